//! The path tracer's expected SLC candidates per shading point
//! (`slc_scene::error_bound`) for scene files: the mean over the scene's
//! surfaces at ε = 1 (the fixed default) and the automatic ε with the
//! candidates it gives.
//!
//!     cargo run --release -p slc-scene --example candidates -- SCENE.toml [SCENE.toml ...]

use slc_scene::error_bound::{CandidateModel, TARGET_CANDIDATES, auto_error_bound};
use slc_scene::pt::PtScene;
use slc_scene::scene_file::SceneFile;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!(
        "{:<48} {:>7} {:>10} {:>12} {:>10}",
        "scene", "lights", "C(eps=1)", "auto eps", "C(auto)"
    );
    for path in std::env::args().skip(1) {
        let f = SceneFile::load(std::path::Path::new(&path))?;
        let pts = PtScene::new(&f.scene, &f.lights)?;
        let Some(model) = CandidateModel::new(&pts, 1.0) else {
            println!("{path:<48} no lights or no surfaces");
            continue;
        };
        let eps = auto_error_bound(&pts, 1.0, TARGET_CANDIDATES).ok_or("no automatic bound")?;
        println!(
            "{path:<48} {:>7} {:>10.2} {:>12.4e} {:>10.2}",
            model.lights(),
            model.mean_candidates(1.0),
            eps,
            model.mean_candidates(eps)
        );
    }
    Ok(())
}
