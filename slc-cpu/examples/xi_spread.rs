//! The spread of a progressive render's image mean from seed to seed: how
//! fast SLC's image-wide error (one ξ per light per pass, shared by every
//! pixel) falls with passes.
//!
//! ```text
//! cargo run --release -p slc-cpu --example xi_spread -- SCENE.toml [METHOD] [PASSES] [SEEDS] [SIZE] [EPS]
//! ```
//! Renders `SEEDS` (16) runs of `PASSES` (1024) passes at `SIZE`² (32)
//! pixels with `METHOD` (`slc-reservoir`) at error bound `EPS` (a number,
//! or `auto`: the automatic ε; `PtSettings`' default when not given) and
//! prints each channel's mean over seeds and the relative standard
//! deviation of the image mean.

use slc_cpu::pt::CpuPathTracer;
use slc_scene::pt::{PtMethod, PtRender, PtScene, PtSettings};
use slc_scene::scene_file::SceneFile;
use std::path::Path;

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let scene =
        args.first().ok_or("usage: xi_spread SCENE.toml [METHOD] [PASSES] [SEEDS] [SIZE] [EPS]")?;
    let method = args.get(1).map_or("slc-reservoir", |s| s.as_str());
    let method = PtMethod::ALL
        .into_iter()
        .find(|m| m.name() == method)
        .ok_or(format!("unknown method {method}"))?;
    let num = |i: usize, d: u32| {
        args.get(i).map_or(Ok(d), |s| s.parse::<u32>().map_err(|e| format!("argument {i}: {e}")))
    };
    let (passes, seeds, size) = (num(2, 1024)?, num(3, 16)?, num(4, 32)?);
    let f = SceneFile::load(Path::new(scene)).map_err(|e| e.to_string())?;
    let pts = PtScene::new(&f.scene, &f.lights).map_err(|e| e.to_string())?;
    let error_bound = match args.get(5).map(String::as_str) {
        None => PtSettings::default().error_bound,
        Some("auto") => slc_scene::error_bound::auto_error_bound(
            &pts,
            1.0,
            slc_scene::error_bound::TARGET_CANDIDATES,
        )
        .ok_or("no light reaches a surface")?,
        Some(e) => e.parse::<f32>().map_err(|e| format!("argument 5: {e}"))?,
    };
    let mut tracer = CpuPathTracer::new(&pts);
    let mut means = Vec::new();
    for seed in 0..seeds {
        let mut acc = PtRender::new(size, size);
        tracer
            .render(
                &mut acc,
                &PtSettings { method, error_bound, seed: 1000 + seed, ..PtSettings::default() },
                passes,
            )
            .map_err(|e| e.to_string())?;
        let img = acc.image();
        let m = img
            .data
            .iter()
            .fold([0.0f64; 3], |a, v| [a[0] + v.x as f64, a[1] + v.y as f64, a[2] + v.z as f64]);
        means.push(m.map(|c| c / img.data.len() as f64));
    }
    let n = means.len() as f64;
    println!(
        "{} {}, {} passes at {size}x{size}, {seeds} seeds, ε = {error_bound}",
        f.scene.name,
        method.name(),
        passes
    );
    for c in 0..3 {
        let mean = means.iter().map(|m| m[c]).sum::<f64>() / n;
        let sd = (means.iter().map(|m| (m[c] - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        println!(
            "channel {c}: mean {mean:.6}, seed-to-seed sd {sd:.6} ({:.3}%)",
            100.0 * sd / mean
        );
    }
    Ok(())
}
