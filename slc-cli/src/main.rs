//! `slc`: render, benchmark and inspect with stochastic light culling.
//!
//! With no arguments it renders the built-in Cornell box with VPL indirect
//! light using SLC on the CPU, writes `slc-out.exr` and `slc-out.png`, and
//! prints time, VPL count, lights per pixel and RMSE against the unculled
//! interleaved image.

use anyhow::{Context, anyhow};
mod backends;
mod bench;
mod diff;
mod methods;
mod notes;
mod plot;
mod reference;
mod report;
mod scene_args;
mod suite;
mod view;

use backends::{Backend, GPU_BATCH, gpu_context, gpu_context_with, path_tracer};
use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand};
use methods::{MethodFlags, pt_method, vpl_settings};
use notes::{PT_LIGHTS_NOTE, timing_note};
use scene_args::{App, SceneArgs};
use slc_scene::image::Image;
use slc_scene::pt::{PtRender, PtScene, PtSettings};
use slc_scene::vpl::{Culling, VplSettings};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[derive(Parser)]
#[command(
    name = "slc",
    version,
    about = "Stochastic light culling (Tokuyoshi & Harada 2016): render, bench, inspect"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Render an image (EXR, with a PNG preview beside it).
    #[command(allow_negative_numbers = true)]
    Render(RenderArgs),
    /// Speed against error: every method and parameter against the reference.
    #[command(allow_negative_numbers = true)]
    Bench(bench::BenchArgs),
    /// The GPU VPL frame in a real-time window: move the light, switch
    /// slc / clamp / none, change ε and the VPL count, see each pass's GPU time.
    #[command(allow_negative_numbers = true)]
    View(view::ViewArgs),
    /// Inspect an IES (LM-63) photometric file.
    Ies {
        /// The .ies file.
        file: PathBuf,
        /// Write a polar candela plot (.svg or .png).
        #[arg(long)]
        plot: Option<PathBuf>,
    },
    /// Compare two EXR images: RMSE, relative RMSE, max difference, NaN/inf.
    #[command(allow_negative_numbers = true)]
    Diff(diff::DiffArgs),
    /// Export every GPU kernel as WGSL, SPIR-V, GLSL, HLSL and MSL.
    Shaders {
        /// Output folder.
        #[arg(long)]
        out: PathBuf,
        /// Light types to compile into the BSH kernels (comma-separated).
        #[arg(long, default_value = "point,spot,ies,triangle,vpl")]
        lights: String,
        /// Reservoir slots k of the BSH kernels.
        #[arg(long, default_value_t = 8)]
        reservoir_k: u32,
    },
    /// Write the scene suite (many-light families in the Cornell box, each
    /// at every light count) as scene files.
    Suite {
        /// Output folder.
        #[arg(long, default_value = "scenes/suite")]
        out: PathBuf,
        /// Light counts per family (comma- or space-separated).
        #[arg(long, value_delimiter = ',', num_args = 1.., default_values_t = suite::DEFAULT_COUNTS)]
        counts: Vec<u32>,
        /// The IES profile of the mixed family, written as given (relative
        /// to the scene files, or absolute).
        #[arg(long, default_value = suite::DEFAULT_IES)]
        ies: String,
    },
    /// Plot a `slc bench` JSON report again (.svg or .png): a VPL report as
    /// speed against error, a path-tracing one as RMSE over time, a suite's
    /// as each scene's error over uniform sampling's.
    Plot {
        /// The JSON written by `slc bench --json`.
        json: PathBuf,
        /// Output plot.
        #[arg(long)]
        out: PathBuf,
    },
}

#[derive(Args)]
struct RenderArgs {
    #[command(flatten)]
    scene: SceneArgs,
    /// Method: slc | clamp | none | reference (vpl, both backends; the
    /// reference is every VPL at every pixel); slc | slc-reservoir |
    /// slc-weighted | uniform | power | lightbvh (pt, both backends)
    /// [default: slc].
    #[arg(long)]
    method: Option<String>,
    /// Path tracing: samples per pixel [default: 16].
    #[arg(long)]
    spp: Option<u32>,
    /// Path tracing: render for this many seconds instead of --spp.
    #[arg(long)]
    seconds: Option<f64>,
    /// SLC error bound ε, the largest standard deviation one light may add
    /// to a pixel [default: 0.004 (vpl); auto (pt): set from the scene so
    /// that a shading point expects a fixed number of candidate lights;
    /// auto:C for C of them].
    #[arg(long, value_parser = methods::bound_arg)]
    error_bound: Option<slc_scene::error_bound::BoundArg>,
    /// Clamp range R (scene units) for --method clamp [default: 0.1].
    #[arg(long)]
    range: Option<f32>,
    /// Seed of the per-light random numbers [default: 1].
    #[arg(long)]
    seed: Option<u32>,
    /// Skip the cross-bilateral filter.
    #[arg(long)]
    no_denoise: bool,
    /// Output EXR (a PNG preview is written beside it).
    #[arg(long, default_value = "slc-out.exr")]
    out: PathBuf,
}

/// Outside a desktop session (no `XDG_RUNTIME_DIR` and no
/// `WAYLAND_DISPLAY`: a container, ssh, `xvfb-run`), Mesa's Vulkan
/// device-select layer tries to reach a Wayland compositor to rank the GPUs,
/// and libwayland prints `error: XDG_RUNTIME_DIR is invalid or not set`
/// twice, though nothing is wrong. There is no compositor to rank by (an
/// X display ranks only the GPU driving it first, which matters only where
/// `DRI_PRIME` picks another), so the layer is turned off
/// (`NODEVICE_SELECT=1`, Mesa's switch) unless the user chose a device
/// (`MESA_VK_DEVICE_SELECT`, `DRI_PRIME`) or set the switch. Engines that
/// embed slc-wgpu can set the same variable.
fn quiet_headless_vulkan() {
    let unset = |k: &str| std::env::var_os(k).is_none();
    if [
        "XDG_RUNTIME_DIR",
        "WAYLAND_DISPLAY",
        "MESA_VK_DEVICE_SELECT",
        "DRI_PRIME",
        "NODEVICE_SELECT",
    ]
    .iter()
    .all(|k| unset(k))
    {
        // SAFETY: called first thing in `main`, before any thread exists,
        // so nothing reads the environment concurrently.
        #[allow(unsafe_code)]
        unsafe {
            std::env::set_var("NODEVICE_SELECT", "1");
        }
    }
}

fn main() -> ExitCode {
    quiet_headless_vulkan();
    // No subcommand: the main job, `slc render` with its defaults.
    // The matches say which flags were given, not defaulted (`slc bench`
    // refuses the other application's).
    let matches = Cli::command().get_matches();
    let cli = Cli::from_arg_matches(&matches).unwrap_or_else(|e| e.exit());
    let command = cli.command.or_else(|| Cli::parse_from(["slc", "render"]).command);
    let result = match command {
        None => Err(anyhow!("no command")),
        Some(Command::Render(a)) => render(a),
        Some(Command::Bench(a)) => match matches.subcommand_matches("bench") {
            Some(given) => bench::run(a, given),
            None => Err(anyhow!("bench without its flags")),
        },
        Some(Command::View(a)) => view::run(a),
        Some(Command::Ies { file, plot }) => ies(&file, plot.as_deref()),
        Some(Command::Diff(a)) => diff::run(a),
        Some(Command::Plot { json, out }) => replot(&json, &out),
        Some(Command::Shaders { out, lights, reservoir_k }) => shaders(&out, &lights, reservoir_k),
        Some(Command::Suite { out, counts, ies }) => {
            suite::write(&out, &counts, &ies).map(|paths| {
                println!("slc suite: wrote {} scene files to {}", paths.len(), out.display());
            })
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // Library errors name no flags; the CLI says which one helps.
            let gpu_limit = e.chain().any(|c| {
                matches!(
                    c.downcast_ref::<slc_wgpu::GpuError>(),
                    Some(slc_wgpu::GpuError::NoAdapter(_) | slc_wgpu::GpuError::Limit { .. })
                )
            });
            let hint = if gpu_limit { " (--backend cpu renders on the CPU)" } else { "" };
            eprintln!("error: {e:#}{hint}");
            ExitCode::FAILURE
        }
    }
}

impl RenderArgs {
    /// The VPL method flags of this render.
    fn method_flags(&self) -> MethodFlags<'_> {
        MethodFlags {
            method: self.method.as_deref(),
            error_bound: self.error_bound,
            range: self.range,
            seed: self.seed,
            no_denoise: self.no_denoise,
            tile: self.scene.tile(),
            near_radius: self.scene.near_radius,
        }
    }
}

fn render(a: RenderArgs) -> anyhow::Result<()> {
    // A bad --out fails now, not after the render.
    output_paths(&a.out)?;
    if a.scene.app == App::Pt {
        a.scene.vpl_only_flags()?;
        if a.range.is_some() || a.no_denoise {
            anyhow::bail!(
                "{}: only the VPL application (--app vpl) takes it",
                if a.no_denoise { "--no-denoise" } else { "--range" }
            );
        }
        return render_pt(a);
    }
    a.scene.pt_only_flags()?;
    a.scene.backend_flags()?;
    if a.spp.is_some() || a.seconds.is_some() {
        anyhow::bail!(
            "{}: only the path tracers (--app pt) take it",
            if a.spp.is_some() { "--spp" } else { "--seconds" }
        );
    }
    if a.scene.backend == Backend::Gpu {
        return render_vpl_gpu(a);
    }
    let t0 = Instant::now();
    let spinner = spinner("scene, G-buffer, reflective shadow map, direct light");
    let loaded = a.scene.load()?;
    let (ctx, f) = (&loaded.ctx, &loaded.file);
    let settings = vpl_settings(&a.method_flags(), f, loaded.exposure)?;
    spinner.set_message(format!("shading ({}, cpu)", settings.culling.name()));
    let frame = ctx.render(&settings)?;
    spinner.set_message("writing images");
    let written = write_outputs(&frame.image, &a.out, loaded.exposure)?;
    let st = frame.stats;
    let versus_none = if settings.culling != Culling::None && settings.culling != Culling::Reference
    {
        spinner.set_message("unculled interleaved image for the RMSE");
        let none = ctx.render(&VplSettings { culling: Culling::None, ..settings })?;
        Some((frame.image.rmse(&none.image), none.stats.shading_ms))
    } else {
        None
    };
    spinner.finish_and_clear();
    println!(
        "slc render: {} {}x{}, {} VPLs, method {}",
        ctx.scene().name,
        loaded.width,
        loaded.height,
        st.vpls,
        settings.culling.name()
    );
    println!(
        "  time        {:.1} ms total, {:.1} ms shading (G-buffer {:.1}, RSM {:.1}, direct {:.1}, denoise {:.1})",
        st.total_ms, st.shading_ms, st.gbuffer_ms, st.rsm_ms, st.direct_ms, st.denoise_ms
    );
    println!("  lights/px   {:.1} tested, {:.1} kept", st.lights_per_pixel, st.kept_per_pixel);
    print_work(&st);
    if let Some((rmse, none_ms)) = versus_none {
        println!(
            "  RMSE        {rmse:.5} against the unculled interleaved image ({none_ms:.1} ms shading, {})",
            speed_vs_none(none_ms, st.shading_ms)
        );
    }
    print_written(&written, &frame.image, t0);
    Ok(())
}

/// The far and near fields' work per pixel, where the frame counted it.
fn print_work(st: &slc_scene::vpl::VplStats) {
    for (name, w) in [("far field", &st.far_work), ("near field", &st.near_work)] {
        if w.pixels > 0 {
            println!("  {name:<11} {}", report::Work::of(w).line());
        }
    }
}

/// `slc render --backend gpu`: the whole VPL frame on the GPU, every stage timed.
fn render_vpl_gpu(a: RenderArgs) -> anyhow::Result<()> {
    let t0 = Instant::now();
    let spinner = spinner("scene and GPU pipelines");
    let r = a.scene.resolve()?;
    let settings = vpl_settings(&a.method_flags(), &r.file, r.exposure)?;
    let gpu = gpu_context(Backend::Gpu)?.context("no GPU context")?;
    let mut frame = a.scene.gpu_frame(&gpu, &r)?;
    spinner.set_message(format!("frame on the GPU ({})", settings.culling.name()));
    // The reference (every VPL at every pixel) is the frame's own
    // uninterleaved, unculled render; of its settings only the clamp
    // distance matters.
    let reference = settings.culling == Culling::Reference;
    let st = if reference {
        slc_wgpu::passes::IndirectSettings {
            min_distance: frame.min_distance(),
            ..Default::default()
        }
    } else {
        slc_wgpu::frame::indirect_settings(&settings, frame.min_distance())?
    };
    let render = |frame: &mut slc_wgpu::frame::GpuVplFrame| {
        if reference { frame.render_reference(&st) } else { frame.render(&st) }
    };
    // The first frame pays for the driver's pipeline compilation: measure the second.
    render(&mut frame)?;
    let out = render(&mut frame)?;
    let written = write_outputs(&out.image, &a.out, r.exposure)?;
    let versus_none = if settings.culling != Culling::None && !reference {
        spinner.set_message("unculled interleaved frame for the RMSE");
        let none = frame.render(&slc_wgpu::passes::IndirectSettings {
            culling: slc_wgpu::Culling::None,
            ..st
        })?;
        Some((out.image.rmse(&none.image), none.stats.shading_ms))
    } else {
        None
    };
    spinner.finish_and_clear();
    let st = out.stats;
    println!(
        "slc render: {} {}x{}, {} VPLs, method {}, whole frame on the GPU",
        r.scene.name,
        r.width,
        r.height,
        st.vpls,
        settings.culling.name()
    );
    println!("  GPU         {}", gpu.describe());
    println!("  timing      {}", timing_note(out.timing));
    let stages: Vec<String> =
        out.stages.iter().map(|s| format!("{} {:.3}", s.name, s.ms)).collect();
    println!("  stages (ms) {}", stages.join(", "));
    println!(
        "  time        {:.3} ms frame, {:.3} ms shading (light update + shading)",
        st.total_ms, st.shading_ms
    );
    println!("  lights/px   {:.1} kept", st.kept_per_pixel);
    if let Some((rmse, none_ms)) = versus_none {
        println!(
            "  RMSE        {rmse:.5} against the unculled interleaved frame ({none_ms:.3} ms shading, {})",
            speed_vs_none(none_ms, st.shading_ms)
        );
    }
    print_written(&written, &out.image, t0);
    Ok(())
}

/// The unculled shading time against the method's, in words: "10.2x
/// slower" or, where culling costs more than it saves, "1.3x faster".
fn speed_vs_none(none_ms: f64, method_ms: f64) -> String {
    let r = none_ms / method_ms.max(1e-9);
    if r >= 1.0 {
        format!("{r:.1}x slower")
    } else {
        format!("{:.1}x faster: culling costs more than it saves here", 1.0 / r)
    }
}

/// `slc render --app pt`: progressive path tracing on the chosen backend.
fn render_pt(a: RenderArgs) -> anyhow::Result<()> {
    let t0 = Instant::now();
    let (scene, lights, f) = a.scene.scene()?;
    let (w, h) =
        (a.scene.width.or(f.width).unwrap_or(512), a.scene.height.or(f.height).unwrap_or(512));
    slc_scene::check_size(w, h)?;
    let pts = PtScene::new(&scene, &lights)?;
    let d = PtSettings::default();
    let on_gpu = a.scene.backend == Backend::Gpu;
    let exposure = a.scene.exposure_of(&f)?;
    let method = pt_method(a.method.as_deref().or(f.method.as_deref()).unwrap_or("slc"))?;
    // A method that culls nothing has no use for ε: the automatic one (a
    // bisection over the scene's surfaces) is not computed for it.
    let (eps, eps_note) = if method.culls() || a.error_bound.is_some() {
        methods::pt_error_bound(a.error_bound, f.pt_error_bound, &pts, exposure)?
    } else {
        (d.error_bound, "unused".into())
    };
    let settings = PtSettings {
        method,
        error_bound: eps,
        exposure,
        seed: a.seed.or(f.seed).unwrap_or(d.seed),
        ..d
    };
    let ctx = gpu_context_with(a.scene.backend, a.scene.ray_query)?;
    let mut tracer = path_tracer(ctx.as_ref(), &pts, (w, h), a.scene.ray_query, a.scene.grid_on())?;
    let batch = if on_gpu { GPU_BATCH } else { 1 };
    let mut acc = PtRender::new(w, h);
    let bar = indicatif::ProgressBar::new(0);
    match a.seconds {
        Some(secs) if secs > 0.0 && secs.is_finite() => {
            bar.set_length((secs * 10.0) as u64);
            while acc.time_ms < secs * 1e3 {
                tracer.render(&mut acc, &settings, batch).map_err(|e| anyhow!(e))?;
                bar.set_position((acc.time_ms / 100.0) as u64);
            }
        }
        Some(secs) => return Err(anyhow!("--seconds {secs} must be finite and > 0")),
        None => {
            let spp = a.spp.unwrap_or(16);
            if spp == 0 {
                return Err(anyhow!("--spp 0: give at least one sample per pixel"));
            }
            bar.set_length(spp as u64);
            while acc.passes < spp {
                let n = batch.min(spp - acc.passes);
                tracer.render(&mut acc, &settings, n).map_err(|e| anyhow!(e))?;
                bar.inc(n as u64);
            }
        }
    }
    bar.finish_and_clear();
    let image = acc.image();
    let exposure = settings.exposure;
    let written = write_outputs(&image, &a.out, exposure)?;
    println!(
        "slc render: {} {}x{}, path tracing, {} lights, method {}",
        scene.name,
        w,
        h,
        pts.light_count(),
        settings.method.name()
    );
    println!("  lights      {}", PT_LIGHTS_NOTE);
    if settings.method.culls() {
        println!("  error bound ε = {:.4} ({eps_note})", settings.error_bound);
    }
    if let Some(c) = &ctx {
        let timing =
            if c.timestamps { "GPU timestamps" } else { "wall clock, no timestamp queries" };
        println!("  backend     GPU {} ({timing})", c.describe());
    }
    println!(
        "  time        {:.1} ms for {} samples per pixel ({:.2} spp/s)",
        acc.time_ms,
        acc.passes,
        acc.passes as f64 / (acc.time_ms * 1e-3)
    );
    print_written(&written, &image, t0);
    Ok(())
}

/// A step indicator on stderr (hidden when stderr is not a terminal). It
/// redraws only when the step changes: a ticking thread would steal time
/// from the renderer being measured.
pub fn spinner(msg: &'static str) -> indicatif::ProgressBar {
    let s = indicatif::ProgressBar::new_spinner();
    s.set_message(msg);
    s.tick();
    s
}

/// Checks that the path `flag` names is a `.png` (what it writes), before
/// any work.
pub fn png_only(flag: &str, path: &Path) -> anyhow::Result<()> {
    output_folder(flag, path)?;
    match path.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("png") => Ok(()),
        _ => Err(anyhow!("{flag} {}: give a .png path (it writes a PNG)", path.display())),
    }
}

/// Checks, before any work, that the folder `flag`'s file goes into exists
/// (a long bench would otherwise fail at its end).
pub fn output_folder(flag: &str, path: &Path) -> anyhow::Result<()> {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    if dir.is_dir() {
        Ok(())
    } else {
        Err(anyhow!("{flag} {}: folder {} does not exist", path.display(), dir.display()))
    }
}

/// The EXR and PNG paths of `--out`: `x.exr` gives `x.exr` and `x.png`,
/// and so does `x.png` (the path given is kept as written, `X.EXR`
/// included); any other extension or a missing folder is an error.
pub fn output_paths(out: &Path) -> anyhow::Result<(PathBuf, PathBuf)> {
    output_folder("--out", out)?;
    match out.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
        Some("exr") => Ok((out.to_path_buf(), out.with_extension("png"))),
        Some("png") => Ok((out.with_extension("exr"), out.to_path_buf())),
        _ => Err(anyhow!(
            "--out {}: give a .exr path (the PNG preview is written beside it) or a .png one (the EXR is written beside it)",
            out.display()
        )),
    }
}

/// Prints the paths [`write_outputs`] wrote and the time since `t0`, and
/// says so when the image is black (a scene whose lights emit nothing, or
/// none that reaches the camera: not an error, but rarely meant).
fn print_written(written: &(PathBuf, PathBuf), img: &Image, t0: Instant) {
    println!(
        "  wrote       {} and {} ({:.1} s)",
        written.0.display(),
        written.1.display(),
        t0.elapsed().as_secs_f64()
    );
    if img.data.iter().all(|p| *p == glam::Vec3::ZERO) {
        println!("  note        the image is black: no light the scene emits reaches the camera");
    }
}

/// Writes the linear EXR and its tone-mapped PNG preview; returns their paths.
pub fn write_outputs(img: &Image, out: &Path, exposure: f32) -> anyhow::Result<(PathBuf, PathBuf)> {
    let (exr, png) = output_paths(out)?;
    img.write_exr(&exr)?;
    img.write_png(&png, exposure)?;
    Ok((exr, png))
}

/// Writes `name.{wgsl,spv,glsl,hlsl,metal}` for every kernel: the BSH,
/// path-tracing and update kernels for `lights` (and `pt_connect_grid`,
/// the light connection that looks up `bsh_grid`'s grids), the direct pass's
/// `light_ranges` and `direct_light` for `lights` (as `DirectPassDesc::new`
/// builds them, weighted picks of `reservoir_k`, irradiance out, but the
/// depth in an `R32Float` texture: naga's GLSL backend cannot load from a
/// depth texture), `vpl_tiled_{slc,clamp,none}` and the VPL frame's
/// kernels (the raster kernel's GLSL as one file per entry point,
/// `scene_raster.vs_main.glsl` …), and the glossy variants of the VPL
/// kernels that have one (`vpl_tiled_{slc,clamp,none}_glossy`,
/// `vpl_near_glossy`, `irradiance_export_glossy`, `frame_compose_glossy`),
/// and the temporal pass (`temporal`, `temporal_motion`).
fn shaders(out: &Path, lights: &str, reservoir_k: u32) -> anyhow::Result<()> {
    use slc_shared_shaders::{
        CullKind, Features, Kernel, LightTypes, OutputFormat, Selection, SurfaceSource,
        generate_module, translate,
    };
    let lights = LightTypes::parse(lights)?;
    let base = Features { lights, reservoir_k, ..Features::default() };
    let vpl = LightTypes { vpl: true, ..LightTypes::default() };
    let mut jobs: Vec<(String, Kernel, Features)> = [
        Kernel::LightUpdate,
        Kernel::BshRefit,
        Kernel::BshTail,
        Kernel::BshGrid,
        Kernel::BshReservoir,
        Kernel::PtConnect,
        Kernel::PtExtend,
    ]
    .into_iter()
    .map(|k| (k.name().to_string(), k, base))
    .collect();
    jobs.push(("pt_connect_grid".into(), Kernel::PtConnect, Features { bsh_grid: true, ..base }));
    let direct = Features {
        selection: Selection::Weighted,
        surface: SurfaceSource::R32Depth,
        shadows: false,
        ..base
    };
    for k in [Kernel::LightRanges, Kernel::DirectLight] {
        jobs.push((k.name().to_string(), k, direct));
    }
    for m in CullKind::ALL {
        jobs.push((
            format!("vpl_tiled_{}", m.name()),
            Kernel::VplTiled,
            Features { lights: vpl, method: m, ..base },
        ));
    }
    for k in [
        Kernel::VplDenoise,
        Kernel::VplNear,
        Kernel::VplPack,
        Kernel::VplClusters,
        Kernel::VplGroups,
        Kernel::IrradianceExport,
        Kernel::SceneRaster,
        Kernel::PrimaryDirect,
        Kernel::FrameCompose,
    ] {
        jobs.push((k.name().to_string(), k, Features { lights: vpl, ..base }));
    }
    // The glossy variants (Features::glossy): the glTF BRDF at glossy
    // receivers, the specular correction beside the irradiance.
    let glossy = Features { lights: vpl, glossy: true, ..base };
    for m in CullKind::ALL {
        jobs.push((
            format!("vpl_tiled_{}_glossy", m.name()),
            Kernel::VplTiled,
            Features { method: m, ..glossy },
        ));
    }
    for k in [Kernel::VplNear, Kernel::IrradianceExport, Kernel::FrameCompose] {
        jobs.push((format!("{}_glossy", k.name()), k, glossy));
    }
    // The temporal pass: reprojection by the camera (world positions in, as
    // the frame's kernels) and by the engine's motion vectors.
    let temporal = Features { lights: vpl, output_format: OutputFormat::Rgba32Float, ..base };
    jobs.push(("temporal".into(), Kernel::Temporal, temporal));
    jobs.push((
        "temporal_motion".into(),
        Kernel::Temporal,
        Features { motion_vectors: true, ..temporal },
    ));
    // Every kernel generated and translated before any file is written: a
    // light set some kernel refuses writes nothing.
    let built = jobs
        .iter()
        .map(|(name, kernel, features)| {
            let g = generate_module(*kernel, features).with_context(|| format!("kernel {name}"))?;
            let t = translate(&g)?;
            Ok((name, g, t))
        })
        .collect::<anyhow::Result<Vec<_>>>()?;
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let write = |name: &str, ext: &str, bytes: &[u8]| {
        let p = out.join(format!("{name}.{ext}"));
        std::fs::write(&p, bytes).with_context(|| format!("cannot write {}", p.display()))
    };
    for (name, g, t) in &built {
        write(name, "wgsl", g.source.as_bytes())?;
        write(name, "spv", &t.spv.iter().flat_map(|w| w.to_le_bytes()).collect::<Vec<u8>>())?;
        // GLSL holds one shader per file: the raster kernel's entry points apart.
        if t.glsl_entries.len() > 1 {
            for (entry, src) in &t.glsl_entries {
                write(&format!("{name}.{entry}"), "glsl", src.as_bytes())?;
            }
        } else {
            write(name, "glsl", t.glsl.as_bytes())?;
        }
        write(name, "hlsl", t.hlsl.as_bytes())?;
        write(name, "metal", t.msl.as_bytes())?;
        println!("  {name}: wgsl spv glsl hlsl metal");
    }
    // slc-core's functions as naga_oil modules (`#import slc::range::...`).
    let modules = slc_core::wgsl::modules();
    let dir = out.join("slc");
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    for m in &modules {
        let p = dir.join(format!("{}.wgsl", m.name));
        std::fs::write(&p, m.composable())
            .with_context(|| format!("cannot write {}", p.display()))?;
    }
    // The same as a WESL package (`import slc::range::{...};`).
    let wesl = slc_shared_shaders::wesl::modules();
    let wesl_dir = out.join("wesl").join("slc");
    std::fs::create_dir_all(&wesl_dir)
        .with_context(|| format!("cannot create {}", wesl_dir.display()))?;
    for m in &wesl {
        let p = wesl_dir.join(format!("{}.wesl", m.name));
        std::fs::write(&p, &m.source).with_context(|| format!("cannot write {}", p.display()))?;
    }
    println!(
        "wrote {} kernels to {} (lights: {})",
        jobs.len(),
        out.display(),
        lights.names().join(", ")
    );
    println!(
        "wrote {} naga_oil modules to {} (#import slc::<module>::<item>)",
        modules.len(),
        dir.display()
    );
    println!(
        "wrote {} WESL modules to {} (import slc::<module>::{{<items>}};)",
        wesl.len(),
        wesl_dir.display()
    );
    Ok(())
}

/// Plots a bench report again: a VPL report as speed against error, a
/// path-tracing one as RMSE over time (told apart by its `app`), a suite's
/// (`bench --app pt --suite`, its `rows`) as each scene's error over
/// uniform sampling's, as `bench --plot` draws it.
fn replot(json: &Path, out: &Path) -> anyhow::Result<()> {
    let text =
        std::fs::read_to_string(json).with_context(|| format!("cannot read {}", json.display()))?;
    let mut value: serde_json::Value =
        serde_json::from_str(&text).with_context(|| format!("{}", json.display()))?;
    match value.get("app").and_then(|a| a.as_str()) {
        // A suite's report has no `app` of its own: its scenes do.
        None if value.get("rows").is_some() => {
            let rows: Vec<report::SuiteRow> = serde_json::from_value(value["rows"].take())
                .with_context(|| format!("{} (a suite report's rows)", json.display()))?;
            plot::suite_vs_uniform(&rows, out)?;
        }
        Some("pt") => {
            let report: report::PtReport = serde_json::from_value(value)
                .with_context(|| format!("{} (a path-tracing report)", json.display()))?;
            plot::rmse_over_time(&report, out)?;
        }
        Some("vpl") => {
            let report: report::Report = serde_json::from_value(value)
                .with_context(|| format!("{} (a VPL report)", json.display()))?;
            plot::speed_vs_error(&report, out)?;
        }
        other => {
            return Err(anyhow!(
                "{}: not a slc bench report (its \"app\" is {other:?}, expected \"vpl\" or \"pt\")",
                json.display()
            ));
        }
    }
    println!("wrote {}", out.display());
    Ok(())
}

fn ies(path: &Path, plot_path: Option<&Path>) -> anyhow::Result<()> {
    let bytes = std::fs::read(path).with_context(|| format!("cannot read {}", path.display()))?;
    let p = slc_core::ies::IesProfile::parse_bytes(&bytes)
        .with_context(|| format!("{}", path.display()))?;
    println!("{}", path.display());
    println!("  format              {:?}", p.format);
    println!("  photometric type    {:?}", p.photometric_type);
    println!(
        "  tilt                {}",
        match &p.tilt {
            slc_core::ies::Tilt::None => "NONE".to_string(),
            slc_core::ies::Tilt::Include { angles, .. } =>
                format!("INCLUDE ({} angles, not applied)", angles.len()),
            slc_core::ies::Tilt::File(f) => format!("file {f} (not applied)"),
        }
    );
    println!("  lamps               {}", p.lamps);
    println!(
        "  lumens per lamp     {}",
        if p.lumens_per_lamp < 0.0 {
            "-1 (absolute photometry)".to_string()
        } else {
            p.lumens_per_lamp.to_string()
        }
    );
    println!("  candela multiplier  {}", p.multiplier);
    println!("  ballast factor      {}", p.ballast_factor);
    println!(
        "  vertical angles     {} from {} to {}",
        p.vertical.len(),
        p.vertical[0],
        p.vertical[p.vertical.len() - 1]
    );
    println!(
        "  horizontal angles   {} from {} to {}",
        p.horizontal.len(),
        p.horizontal[0],
        p.horizontal[p.horizontal.len() - 1]
    );
    println!("  peak candela        {:.1} cd", p.max_candela());
    println!("  total flux          {:.1} lm (integrated from the table)", p.total_flux());
    if let Some(out) = plot_path {
        let name = path.file_name().map_or(String::new(), |n| n.to_string_lossy().into_owned());
        plot::ies_polar(&p, &format!("{name}: candela, peak {:.0} cd", p.max_candela()), out)?;
        println!("  plot                {}", out.display());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn speed_against_none_reads_right() {
        assert_eq!(speed_vs_none(100.0, 10.0), "10.0x slower");
        assert!(speed_vs_none(8.0, 10.0).starts_with("1.2x faster"));
    }

    #[test]
    fn out_paths_pair_exr_and_png() {
        let dir = std::env::temp_dir();
        let (e, p) = output_paths(&dir.join("x.png")).unwrap();
        assert_eq!((e, p), (dir.join("x.exr"), dir.join("x.png")));
        // The name given is kept as written.
        assert_eq!(
            output_paths(&dir.join("x.EXR")).unwrap(),
            (dir.join("x.EXR"), dir.join("x.png"))
        );
        assert!(output_paths(Path::new("x.jpg")).is_err() && output_paths(Path::new("x")).is_err());
        assert!(output_paths(&dir.join("no-such-folder-of-slc").join("x.exr")).is_err());
    }
}
