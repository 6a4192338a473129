//! `slc view`: the GPU VPL frame in a window ([`slc_view`]).

use crate::backends::Backend;
use crate::scene_args::{App, SceneArgs};
use anyhow::anyhow;
use clap::Args;
use slc_scene::vpl::{Culling, VplSettings};
use std::path::PathBuf;

/// Options of `slc view`.
#[derive(Args, Debug)]
pub struct ViewArgs {
    /// `cornell` (built in), an OBJ file (with its MTL), or a TOML scene file.
    #[arg(long, default_value = "cornell")]
    scene: String,
    /// Frame width (and the window's first width) [default: 512].
    #[arg(long)]
    width: Option<u32>,
    /// Frame height [default: 512].
    #[arg(long)]
    height: Option<u32>,
    /// Number of VPLs: s·s with s a multiple of 8; `v` cycles 4,096 … 262,144 [default: 65536].
    #[arg(long)]
    vpls: Option<u64>,
    /// Exposure E, used by the error bound and the display [default: 1].
    #[arg(long)]
    exposure: Option<f32>,
    /// Clamp distance of the VPL fall-off (default: 1% of the scene diagonal).
    #[arg(long)]
    min_distance: Option<f32>,
    /// Near-field radius; 0 turns the split off [default: 3 × the min distance].
    #[arg(long)]
    near_radius: Option<f32>,
    /// Edge of the primary light's shadow map.
    #[arg(long, default_value_t = crate::scene_args::DEFAULT_SHADOW_SIZE)]
    shadow_size: u32,
    /// Method at start: slc | clamp | none (keys 1, 2, 3) [default: slc].
    #[arg(long)]
    method: Option<String>,
    /// SLC error bound ε at start (keys + and -) [default: 0.004].
    #[arg(long)]
    error_bound: Option<f32>,
    /// Clamp range R at start [default: 0.1].
    #[arg(long)]
    range: Option<f32>,
    /// Start without the cross-bilateral filter (key d).
    #[arg(long)]
    no_denoise: bool,
    /// Start with the light moving on a circle (space).
    #[arg(long)]
    animate: bool,
    /// Start without temporal accumulation of the indirect light (key t).
    #[arg(long)]
    no_temporal: bool,
    /// Start with the camera swinging about its target (key o).
    #[arg(long)]
    orbit: bool,
    /// Render this many frames, then exit (the light moves 1/60 s per frame).
    #[arg(long)]
    frames: Option<u32>,
    /// With --frames: save the last frame as this PNG.
    #[arg(long)]
    screenshot: Option<PathBuf>,
}

/// Opens the window; prints what ran when it closes.
pub fn run(a: ViewArgs) -> anyhow::Result<()> {
    if let Some(path) = &a.screenshot {
        crate::png_only("--screenshot", path)?;
    }
    let scene_args = SceneArgs {
        app: App::Vpl,
        backend: Backend::Gpu,
        scene: a.scene.clone(),
        width: a.width,
        height: a.height,
        vpls: a.vpls,
        exposure: a.exposure,
        min_distance: a.min_distance,
        near_radius: a.near_radius,
        tile: None,
        shadow_size: Some(a.shadow_size),
        ray_query: false,
        grid: None,
    };
    let r = scene_args.resolve()?;
    let flags = crate::methods::MethodFlags {
        method: a.method.as_deref(),
        error_bound: a.error_bound.map(slc_scene::error_bound::BoundArg::Value),
        range: a.range,
        seed: None,
        no_denoise: a.no_denoise,
        tile: VplSettings::default().tile,
        near_radius: a.near_radius,
    };
    let settings = crate::methods::vpl_settings(&flags, &r.file, r.exposure)?;
    if settings.culling == Culling::Reference {
        return Err(anyhow!(
            "--method reference (every VPL at every pixel) is not a real-time method; use slc, clamp or none"
        ));
    }
    let opts = slc_view::ViewOptions {
        scene: r.scene,
        width: r.width,
        height: r.height,
        rsm_size: r.rsm_size,
        shadow_size: a.shadow_size,
        min_distance: a.min_distance,
        settings,
        exposure: r.exposure,
        animate: a.animate,
        temporal: !a.no_temporal,
        orbit: a.orbit,
        frames: a.frames,
        screenshot: a.screenshot.clone(),
    };
    let summary = slc_view::run(opts)?;
    println!("slc view: {} frames on {}", summary.frames, summary.adapter);
    if let Some(times) = &summary.last_stage_times {
        let line: Vec<String> = times.iter().map(|t| format!("{} {:.3}", t.name, t.ms)).collect();
        println!("  last frame (GPU ms): {}", line.join(", "));
    }
    if let Some(path) = &a.screenshot {
        println!("  wrote       {}", path.display());
    }
    Ok(())
}
