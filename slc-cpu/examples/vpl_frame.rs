//! Renders frames of the built-in Cornell box with one method and prints the
//! timings: `cargo run --release -p slc-cpu --example vpl_frame -- slc 512 10`;
//! a fourth argument `inputs` renders the G-buffer, RSM and direct light
//! again before each frame, as `slc bench` does (a frame whose camera or
//! light moves).

use slc_cpu::vpl::VplContext;
use slc_scene::culling::{DEFAULT_CLAMP_RANGE, DEFAULT_ERROR_BOUND};
use slc_scene::scene::Scene;
use slc_scene::vpl::{Culling, VplSettings};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let name = args.get(1).map_or("slc", String::as_str);
    let culling = Culling::named(name, DEFAULT_ERROR_BOUND, 1.0, DEFAULT_CLAMP_RANGE)
        .expect("a culling: slc, clamp, none or reference");
    let size: u32 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(512);
    let frames: u32 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(5);
    let inputs = args.get(4).is_some_and(|a| a == "inputs");
    let mut ctx =
        VplContext::new(&Scene::cornell_box(), size, size, 256, None).expect("valid scene");
    for frame in 0..frames {
        let t = inputs.then(|| ctx.time_inputs());
        let f = ctx
            .render(&VplSettings { culling, frame, ..Default::default() })
            .expect("valid settings");
        if let Some(t) = t {
            print!(
                "G-buffer {:.2} ms, RSM {:.2} ms, direct {:.2} ms, ",
                t.gbuffer_ms, t.rsm_ms, t.direct_ms
            );
        }
        println!(
            "frame {frame}: shading {:.2} ms, denoise {:.2} ms, {:.1} lights/px, {:.1} kept/px",
            f.stats.shading_ms,
            f.stats.denoise_ms,
            f.stats.lights_per_pixel,
            f.stats.kept_per_pixel
        );
    }
}
