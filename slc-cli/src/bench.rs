//! `slc bench`: speed against error. Runs `none`, `slc` over a sweep of
//! error bounds and `clamp` over a sweep of ranges, measures RMSE of each
//! against the (cached) reference, and writes JSON (and optionally CSV).

use crate::backends::{Backend, GPU_BATCH, gpu_context, path_tracer};
use crate::reference::{pt_reference, vpl_reference};
use crate::report::{PtReport, PtRun, Report, Run, StageMs, write_pt_csv, write_vpl_csv};
use crate::scene_args::{App, SceneArgs};
use anyhow::{Context, anyhow};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use slc_cpu::pt::CpuPathTracer;
use slc_scene::pt::{PtMethod, PtRender, PtScene, PtSettings};
use slc_scene::vpl::{Culling, VplFrame, VplSettings};
use std::path::PathBuf;

#[derive(Args)]
pub struct BenchArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Error bounds ε swept for `slc`.
    #[arg(long, value_delimiter = ',', default_values_t = [0.0005f32, 0.001, 0.002, 0.004, 0.008, 0.016])]
    pub error_bounds: Vec<f32>,
    /// Ranges R swept for `clamp` (scene units).
    #[arg(long, value_delimiter = ',', default_values_t = [0.025f32, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3])]
    pub ranges: Vec<f32>,
    /// Runs per configuration: the fastest time is reported; the VPL
    /// frame's runs are its frames 0, 1, … (a new ξ set each), and its
    /// RMSE is their mean (with their standard deviation).
    #[arg(long, default_value_t = 3)]
    pub repeat: u32,
    /// Seed of the per-light random numbers.
    #[arg(long, default_value_t = 1)]
    pub seed: u32,
    /// Where reference images are cached.
    #[arg(long, default_value = ".slc-cache")]
    pub cache_dir: PathBuf,
    /// Also write the report as JSON (re-plot it with `slc plot`).
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Also write the runs as CSV.
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Also plot RMSE against shading time (.svg or .png).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Path tracing: run every method on every scene file (`*.toml`) of this
    /// folder (`scenes/suite` when given without a value; `slc suite`
    /// writes it) and report them together.
    #[arg(long, num_args = 0..=1, default_missing_value = "scenes/suite")]
    pub suite: Option<PathBuf>,
    /// Path tracing: the SLC error bound ε, or `auto` [default: auto: set
    /// from each scene so that a shading point expects a fixed number of
    /// candidate lights; `slc_scene::error_bound`].
    #[arg(long, value_parser = crate::methods::bound_arg)]
    pub error_bound: Option<crate::methods::BoundArg>,
    /// Path tracing: seconds per method (equal time).
    #[arg(long, default_value_t = 10.0)]
    pub seconds: f64,
    /// Path tracing: samples per pixel of the reference.
    #[arg(long, default_value_t = 1024)]
    pub reference_spp: u32,
    /// Path tracing: the reference's method (any of them is unbiased; its
    /// own seed makes it independent of the runs; the one with the least
    /// noise per second makes the cheapest good reference).
    #[arg(long, default_value = "power", value_parser = crate::methods::pt_method)]
    pub reference_method: PtMethod,
    /// VPL frame: measure flicker instead of speed, over three scripted
    /// sequences (static, camera orbit, moving light): per frame the RMSE
    /// against that frame's reference and against the previous frame, for
    /// slc with the spatial filter only, with temporal accumulation (and
    /// over independent ξ), and the unculled frame [size default: 256x256,
    /// 65,536 VPLs; --backend gpu: 128x128, 4,096 VPLs].
    #[arg(long)]
    pub flicker: bool,
    /// Frames per flicker sequence.
    #[arg(long, default_value_t = 48)]
    pub frames: u32,
    /// CPU: run the hot loops on this instruction set instead of the best
    /// one the CPU has (avx512, avx2 or baseline), to measure a lower one.
    #[arg(long, value_parser = simd_path)]
    pub simd: Option<slc_cpu::simd::SimdPath>,
}

/// The configurations of a VPL bench: `none`, then `slc` per error bound,
/// then `clamp` per range, with their settings and parameter (ε or `R`).
fn vpl_configs(a: &BenchArgs, exposure: f32) -> anyhow::Result<Vec<(Option<f32>, VplSettings)>> {
    let mut cullings = vec![(None, Culling::None)];
    for &e in &a.error_bounds {
        cullings.push((Some(e), Culling::stochastic(e, exposure)?));
    }
    for &r in &a.ranges {
        cullings.push((Some(r), Culling::clamped(r)?));
    }
    let d = VplSettings::default();
    Ok(cullings
        .into_iter()
        .map(|(param, culling)| {
            let settings = VplSettings {
                culling,
                seed: a.seed,
                tile: a.scene.tile,
                near_radius: a.scene.near_radius,
                ..d
            };
            (param, settings)
        })
        .collect())
}

/// `--simd`'s value: a [`slc_cpu::simd::SimdPath`] by its name.
fn simd_path(name: &str) -> Result<slc_cpu::simd::SimdPath, String> {
    slc_cpu::simd::SimdPath::from_name(name)
        .ok_or_else(|| format!("{name}: one of avx512, avx2, baseline"))
}

pub fn progress(len: usize) -> anyhow::Result<ProgressBar> {
    let bar = ProgressBar::new(len as u64 + 1);
    bar.set_style(ProgressStyle::with_template(
        "{spinner} [{bar:30}] {pos}/{len} {msg} ({elapsed})",
    )?);
    Ok(bar)
}

/// The run with the smallest `key` of `repeat` calls of `render`.
fn fastest<T>(
    repeat: u32,
    mut render: impl FnMut() -> anyhow::Result<T>,
    key: impl Fn(&T) -> f64,
) -> anyhow::Result<T> {
    let mut best: Option<T> = None;
    for _ in 0..repeat {
        let f = render()?;
        if best.as_ref().is_none_or(|b| key(&f) < key(b)) {
            best = Some(f);
        }
    }
    best.ok_or_else(|| anyhow!("--repeat must be at least 1"))
}

/// Frames `0..repeat` of a configuration rendered by `render(frame)` (a
/// new ξ set each, as a user's frames have): the fastest by `key`, and the
/// mean and sample standard deviation of `rmse` over them all (one frame's
/// RMSE is one draw of a random error: ε decides its distribution).
fn fastest_frames<T>(
    repeat: u32,
    mut render: impl FnMut(u32) -> anyhow::Result<T>,
    key: impl Fn(&T) -> f64,
    rmse: impl Fn(&T) -> f64,
) -> anyhow::Result<(T, Spread)> {
    let mut errors = Vec::new();
    let best = fastest(
        repeat,
        || {
            let f = render(errors.len() as u32)?;
            errors.push(rmse(&f));
            Ok(f)
        },
        key,
    )?;
    Ok((best, Spread::of(&errors)))
}

/// Mean and sample standard deviation (0 for one value).
#[derive(Clone, Copy, Debug)]
struct Spread {
    mean: f64,
    sd: f64,
}

impl Spread {
    fn of(x: &[f64]) -> Spread {
        let n = x.len().max(1) as f64;
        let mean = x.iter().sum::<f64>() / n;
        let var = if x.len() > 1 {
            x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)
        } else {
            0.0
        };
        Spread { mean, sd: var.sqrt() }
    }
}

/// One configuration's row of a VPL report (loop evaluations per second are
/// 0 where the backend does not count evaluations).
fn vpl_run(
    settings: &VplSettings,
    param: Option<f32>,
    st: &slc_scene::vpl::VplStats,
    rmse: Spread,
    stages: Vec<StageMs>,
) -> Run {
    Run {
        method: settings.culling.name().to_string(),
        param,
        shading_ms: st.shading_ms,
        total_ms: st.total_ms,
        rmse: rmse.mean,
        rmse_sd: Some(rmse.sd),
        lights_per_pixel: st.lights_per_pixel,
        kept_per_pixel: st.kept_per_pixel,
        evaluations_per_second: st.evaluations as f64 / (st.shading_ms * 1e-3).max(1e-12),
        stages,
        shading_speedup: None,
        frame_speedup: None,
    }
}

/// Fills each run's speed-ups over the unculled (`none`) run, if there is one.
fn speedups(runs: &mut [Run]) {
    let Some((shading, frame)) =
        runs.iter().find(|r| r.method == "none").map(|r| (r.shading_ms, r.total_ms))
    else {
        return;
    };
    for r in runs {
        r.shading_speedup = Some(shading / r.shading_ms.max(1e-12));
        r.frame_speedup = Some(frame / r.total_ms.max(1e-12));
    }
}

fn run_label(s: &VplSettings, param: Option<f32>) -> String {
    format!("{} {}", s.culling.name(), param.map_or(String::new(), |p| p.to_string()))
}

pub fn run(a: BenchArgs) -> anyhow::Result<()> {
    if a.repeat == 0 || a.reference_spp == 0 {
        return Err(anyhow!(
            "--repeat {} and --reference-spp {} must be at least 1",
            a.repeat,
            a.reference_spp
        ));
    }
    if let Some(want) = a.simd
        && slc_cpu::simd::SimdPath::prefer(want) != want
    {
        return Err(anyhow!(
            "--simd {}: this CPU cannot run it (it has {})",
            want.name(),
            slc_cpu::simd::SimdPath::best().name()
        ));
    }
    if a.flicker {
        if a.scene.app == App::Pt {
            return Err(anyhow!("--flicker measures the VPL frame (--app vpl)"));
        }
        return crate::flicker::run(&a, a.frames);
    }
    if a.scene.app == App::Pt {
        return run_pt(a);
    }
    if a.scene.backend == Backend::Gpu {
        return run_vpl_gpu(a);
    }
    let mut loaded = a.scene.load()?;
    let configs = vpl_configs(&a, loaded.exposure)?;
    let ctx = &mut loaded.ctx;
    let bar = progress(configs.len() + 1)?;
    bar.set_message("reference (all VPLs at every pixel; cached for the next run)");
    // The reference is one long call and is not timed: let the bar tick on
    // its own meanwhile (never during the measured runs).
    bar.enable_steady_tick(std::time::Duration::from_millis(250));
    let (reference, cached) = vpl_reference(ctx, Some(&a.cache_dir))?;
    bar.disable_steady_tick();
    bar.inc(1);
    // One untimed frame first, so the first method measured does not pay
    // the cold start (the allocator growing, caches, thread wake-up).
    if let Some((_, first)) = configs.first() {
        ctx.time_inputs();
        ctx.render(first)?;
    }
    let mut runs = Vec::new();
    for (param, settings) in configs {
        bar.set_message(run_label(&settings, param));
        // Each run renders the method-independent stages again (warm), as
        // a frame whose light or camera moves must.
        let timed = |k: u32| -> anyhow::Result<VplFrame> {
            let inputs = ctx.time_inputs();
            let mut f = ctx.render(&VplSettings { frame: settings.frame + k, ..settings })?;
            f.stats = f.stats.with_input_times(&inputs);
            Ok(f)
        };
        let (f, rmse) = fastest_frames(
            a.repeat,
            timed,
            |f: &VplFrame| f.stats.total_ms,
            |f: &VplFrame| f.image.rmse(&reference),
        )?;
        let st = &f.stats;
        let stages = [
            ("G-buffer", st.gbuffer_ms),
            ("RSM", st.rsm_ms),
            ("direct", st.direct_ms),
            ("shading", st.shading_ms),
            ("denoise", st.denoise_ms),
        ]
        .map(|(name, ms)| StageMs { name: name.into(), ms })
        .to_vec();
        runs.push(vpl_run(&settings, param, st, rmse, stages));
        bar.inc(1);
    }
    // The unculled loop's own speed: `none` without the near field, whose
    // evaluations are the far field's light loop alone.
    bar.set_message("unculled loop without the near field (evaluations per second)");
    let loop_only = VplSettings {
        culling: Culling::None,
        near_radius: Some(0.0),
        seed: a.seed,
        ..VplSettings::default()
    };
    let f = fastest(
        a.repeat,
        || ctx.render(&loop_only).map_err(anyhow::Error::from),
        |f: &VplFrame| f.stats.shading_ms,
    )?;
    let loop_speed = f.stats.evaluations as f64 / (f.stats.shading_ms * 1e-3).max(1e-12);
    bar.finish_and_clear();
    speedups(&mut runs);
    let report = Report {
        app: "vpl".into(),
        backend: "cpu".into(),
        scene: ctx.scene().name.clone(),
        width: loaded.width,
        height: loaded.height,
        lights: ctx.vpls().len(),
        timing: "wall clock, fastest of --repeat whole frames (every stage re-run, warm; frames 0, 1, …: RMSE their mean)".into(),
        threads: std::thread::available_parallelism().map_or(1, |n| n.get()),
        reference_from_cache: cached,
        simd: Some(slc_cpu::simd::SimdPath::best().name().into()),
        unculled_loop_evaluations_per_second: Some(loop_speed),
        runs,
    };
    write_report(&a, &report)
}

/// `slc bench --backend gpu`: the whole VPL frame on the GPU per
/// configuration, every stage timed; the reference is every VPL at every
/// pixel of the frame's own rasterized G-buffer and RSM, shaded and
/// composed on the GPU (`GpuVplFrame::render_reference`), so the RMSE
/// measures the methods, not rasterization against ray casting.
fn run_vpl_gpu(a: BenchArgs) -> anyhow::Result<()> {
    let r = a.scene.resolve()?;
    let gpu = gpu_context(Backend::Gpu)?.context("no GPU context")?;
    let mut frame = a.scene.gpu_frame(&gpu, &r)?;
    let configs = vpl_configs(&a, r.exposure)?;
    let bar = progress(configs.len())?;
    bar.set_message("reference (all VPLs at every pixel, on the GPU)");
    // The CLI's settings into the frame's own (its indirect pass's).
    let min_distance = frame.min_distance();
    let pass_settings = |s: &VplSettings| slc_wgpu::frame::indirect_settings(s, min_distance);
    let all = slc_wgpu::passes::IndirectSettings { min_distance, ..Default::default() };
    let reference = frame.render_reference(&all)?.image;
    bar.inc(1);
    let mut runs = Vec::new();
    let mut timing = slc_scene::backend::Timing::Wall;
    for (param, settings) in configs {
        bar.set_message(run_label(&settings, param));
        // One untimed frame first: drivers compile a pipeline at its first use.
        frame.render(&pass_settings(&settings)?)?;
        let (f, rmse) = fastest_frames(
            a.repeat,
            |k| {
                frame
                    .render(&pass_settings(&VplSettings { frame: settings.frame + k, ..settings })?)
                    .map_err(anyhow::Error::from)
            },
            |f: &slc_wgpu::frame::FrameRender| f.stats.shading_ms,
            |f: &slc_wgpu::frame::FrameRender| f.image.rmse(&reference),
        )?;
        timing = f.timing;
        let stages =
            f.stages.iter().map(|s| StageMs { name: s.name.to_string(), ms: s.ms }).collect();
        runs.push(vpl_run(&settings, param, &f.stats, rmse, stages));
        bar.inc(1);
    }
    bar.finish_and_clear();
    speedups(&mut runs);
    let report = Report {
        app: "vpl".into(),
        backend: format!("gpu: {}", gpu.describe()),
        scene: r.scene.name.clone(),
        width: r.width,
        height: r.height,
        lights: (r.rsm_size as usize).pow(2),
        timing: format!(
            "{}; the whole frame on the GPU; fastest of --repeat frames (0, 1, …: RMSE their mean) by shading time",
            crate::notes::timing_note(timing)
        ),
        threads: std::thread::available_parallelism().map_or(1, |n| n.get()),
        reference_from_cache: false,
        simd: None,
        unculled_loop_evaluations_per_second: None,
        runs,
    };
    for run in &report.runs {
        let stages: Vec<String> =
            run.stages.iter().map(|s| format!("{} {:.3}", s.name, s.ms)).collect();
        println!(
            "{:>6} {:>8}: RMSE {:.5}, frame {:.3} ms ({})",
            run.method,
            run.param.map_or(String::new(), |p| p.to_string()),
            run.rmse,
            run.total_ms,
            stages.join(", ")
        );
    }
    write_report(&a, &report)
}

fn write_report(a: &BenchArgs, report: &Report) -> anyhow::Result<()> {
    let json = serde_json::to_string_pretty(report)?;
    if let Some(path) = &a.json {
        std::fs::write(path, json).with_context(|| format!("cannot write {}", path.display()))?;
    }
    if let Some(csv) = &a.csv {
        write_vpl_csv(report, csv)?;
    }
    if let Some(plot) = &a.plot {
        crate::plot::speed_vs_error(report, plot)?;
    }
    println!(
        "{} {}x{}, {} VPLs, {} threads{} (reference {})",
        report.scene,
        report.width,
        report.height,
        report.lights,
        report.threads,
        report.simd.as_ref().map_or(String::new(), |s| format!(", {s} loops")),
        if report.reference_from_cache { "from cache" } else { "rendered" }
    );
    println!(
        "{:<8} {:>8} {:>11} {:>10} {:>9} {:>9} {:>9} {:>9} {:>10} {:>8} {:>8}",
        "method",
        "param",
        "shading ms",
        "total ms",
        "rmse",
        "rmse sd",
        "lights/px",
        "kept/px",
        "evals/s",
        "shade x",
        "frame x"
    );
    let speedup = |x: Option<f64>| x.map_or("-".into(), |x| format!("{x:.2}"));
    for r in &report.runs {
        // The GPU frame does not count loop evaluations: "-".
        let counted = r.evaluations_per_second > 0.0;
        println!(
            "{:<8} {:>8} {:>11.2} {:>10.2} {:>9.5} {:>9} {:>9} {:>9.1} {:>10} {:>8} {:>8}",
            r.method,
            r.param.map_or("-".into(), |p| p.to_string()),
            r.shading_ms,
            r.total_ms,
            r.rmse,
            r.rmse_sd.map_or("-".into(), |sd| format!("{sd:.5}")),
            if counted { format!("{:.1}", r.lights_per_pixel) } else { "-".into() },
            r.kept_per_pixel,
            if counted { format!("{:.3e}", r.evaluations_per_second) } else { "-".into() },
            speedup(r.shading_speedup),
            speedup(r.frame_speedup),
        );
    }
    if report.backend == "cpu" {
        println!(
            "stages (ms): {}",
            report.runs.first().map_or(String::new(), |r| r
                .stages
                .iter()
                .map(|s| s.name.as_str())
                .collect::<Vec<_>>()
                .join(", "))
        );
        for r in &report.runs {
            let ms: Vec<String> = r.stages.iter().map(|s| format!("{:.1}", s.ms)).collect();
            println!(
                "  {:<8} {:>8}: {}",
                r.method,
                r.param.map_or("-".into(), |p| p.to_string()),
                ms.join(", ")
            );
        }
    }
    if let Some(speed) = report.unculled_loop_evaluations_per_second {
        println!(
            "unculled loop: {speed:.3e} light evaluations/s (method none without the near field, {} threads, {} loops)",
            report.threads,
            report.simd.as_deref().unwrap_or("?")
        );
    }
    Ok(())
}

fn run_pt(a: BenchArgs) -> anyhow::Result<()> {
    if !(a.seconds > 0.0 && a.seconds.is_finite()) {
        return Err(anyhow!("--seconds {} must be finite and > 0", a.seconds));
    }
    if let Some(dir) = &a.suite {
        return crate::suite_bench::run(&a, dir);
    }
    let (scene, lights, f) = a.scene.scene()?;
    let report = pt_equal_time(&a, &scene, &lights, &f)?;
    let json = serde_json::to_string_pretty(&report)?;
    if let Some(path) = &a.json {
        std::fs::write(path, json).with_context(|| format!("cannot write {}", path.display()))?;
    }
    if let Some(csv) = &a.csv {
        write_pt_csv(&report, csv)?;
    }
    if let Some(plot) = &a.plot {
        crate::plot::rmse_over_time(&report, plot)?;
    }
    print_pt_report(&a, &report);
    Ok(())
}

/// Every method on one scene for `--seconds` each on the chosen backend,
/// RMSE against a (cached) CPU reference of `--reference-spp`.
pub fn pt_equal_time(
    a: &BenchArgs,
    scene: &slc_scene::scene::Scene,
    lights: &[slc_core::light::Light],
    f: &slc_scene::scene_file::RenderSettings,
) -> anyhow::Result<PtReport> {
    let (w, h) =
        (a.scene.width.or(f.width).unwrap_or(128), a.scene.height.or(f.height).unwrap_or(128));
    let pts = PtScene::new(scene, lights)?;
    let (eps, eps_note) = crate::methods::pt_error_bound(a.error_bound, f.error_bound, &pts, 1.0);
    // A reference that culls nothing does not depend on ε: keyed without
    // it, its cache serves every --error-bound.
    let ref_eps = if a.reference_method.culls() { eps } else { PtSettings::default().error_bound };
    let ref_settings = PtSettings {
        method: a.reference_method,
        error_bound: ref_eps,
        seed: 0x5EED,
        ..PtSettings::default()
    };
    let bar = ProgressBar::new(a.reference_spp as u64);
    bar.set_style(ProgressStyle::with_template(
        "{spinner} [{bar:30}] {pos}/{len} spp, {msg} (ETA {eta})",
    )?);
    bar.set_message(format!("reference: {}", a.reference_method.name()));
    let mut progress = |done: u32, total: u32| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    let r = pt_reference(
        &mut CpuPathTracer::new(&pts),
        w,
        h,
        &ref_settings,
        a.reference_spp,
        Some(&a.cache_dir),
        &mut progress,
    )?;
    let (reference, cached) = (r.image, r.cached);
    // The reference stays on the CPU; the methods run on the chosen backend.
    let ctx = gpu_context(a.scene.backend)?;
    let mut tracer = path_tracer(ctx.as_ref(), &pts, w, h)?;
    let batch = if ctx.is_some() { GPU_BATCH } else { 1 };
    let methods = PtMethod::ALL;
    let mut runs = Vec::new();
    // Methods: the bar counts tenths of a second of rendering, all methods together.
    let tenths = (a.seconds * 10.0).ceil() as u64;
    bar.set_style(ProgressStyle::with_template("{spinner} [{bar:30}] {msg} (ETA {eta})")?);
    bar.set_length(tenths * methods.len() as u64);
    bar.set_position(0);
    bar.reset_eta();
    for (k, method) in methods.into_iter().enumerate() {
        bar.set_message(format!(
            "{} ({} of {}), {} s each",
            method.name(),
            k + 1,
            bar.length().unwrap_or(0) / tenths.max(1),
            a.seconds
        ));
        let s = PtSettings { method, error_bound: eps, seed: a.seed, ..PtSettings::default() };
        let mut acc = PtRender::new(w, h);
        let mut series = Vec::new();
        while acc.time_ms < a.seconds * 1e3 {
            tracer.render(&mut acc, &s, batch).map_err(|e| anyhow!(e))?;
            series.push((acc.time_ms, acc.passes, acc.image().rmse(&reference)));
            bar.set_position(k as u64 * tenths + ((acc.time_ms / 100.0) as u64).min(tenths));
        }
        let last = *series.last().expect("at least one pass");
        runs.push(PtRun {
            method: method.name().into(),
            param: method.culls().then_some(eps),
            time_ms: last.0,
            spp: last.1,
            rmse: last.2,
            rmse_net: (last.2 * last.2 - r.noise * r.noise).max(0.0).sqrt(),
            series: thin_series(&series),
        });
    }
    bar.finish_and_clear();
    let report = PtReport {
        app: "pt".into(),
        backend: match &ctx {
            None => "cpu".into(),
            Some(c) => format!(
                "gpu: {} ({})",
                c.describe(),
                if c.timestamps { "GPU timestamps" } else { "wall clock" }
            ),
        },
        scene: scene.name.clone(),
        width: w,
        height: h,
        lights: pts.light_count(),
        reference: format!("{}, {} spp", a.reference_method.name(), a.reference_spp),
        reference_noise: r.noise,
        reference_from_cache: cached,
        error_bound_note: eps_note,
        runs,
    };
    Ok(report)
}

/// Prints one equal-time report as a table, with warnings where the
/// reference limits what it can tell.
fn print_pt_report(a: &BenchArgs, report: &PtReport) {
    let (w, h) = (report.width, report.height);
    let uniform =
        report.runs.iter().find(|r| r.method == "uniform").map_or(f64::NAN, |r| r.rmse_net);
    println!("backend {}", report.backend);
    if let Some(eps) = report.runs.iter().find_map(|r| r.param) {
        println!("eps     {eps:.4} ({})", report.error_bound_note);
    }
    println!("lights  {}", crate::notes::PT_LIGHTS_NOTE);
    println!(
        "{} {}x{}, {} lights, {:.1} s per method (reference {} {}, its own RMSE about {:.5})",
        report.scene,
        w,
        h,
        report.lights,
        a.seconds,
        report.reference,
        if report.reference_from_cache { "from cache" } else { "rendered" },
        report.reference_noise
    );
    println!(
        "{:<14} {:>8} {:>10} {:>6} {:>10} {:>10} {:>16}",
        "method", "param", "time ms", "spp", "rmse", "rmse net", "uniform/method"
    );
    for r in &report.runs {
        println!(
            "{:<14} {:>8} {:>10.0} {:>6} {:>10.5} {:>10.5} {:>16.2}",
            r.method,
            r.param.map_or("-".into(), |p| p.to_string()),
            r.time_ms,
            r.spp,
            r.rmse,
            r.rmse_net,
            uniform / r.rmse_net
        );
    }
    println!(
        "(rmse net: the reference's own noise taken out, √(rmse² − {:.5}²); the ratio uses it)",
        report.reference_noise
    );
    let most = report.runs.iter().map(|r| r.spp).max().unwrap_or(0);
    if (a.reference_spp as u64) < 16 * most as u64 {
        println!(
            "warning: the reference has {} spp, less than 16 × the {most} spp of the fastest method: raise --reference-spp",
            a.reference_spp
        );
    }
    for r in report.runs.iter().filter(|r| report.reference_noise > r.rmse_net / 3.0) {
        println!(
            "warning: the reference's own noise {:.5} exceeds a third of {}'s net RMSE {:.5}: its ratio is uncertain; raise --reference-spp",
            report.reference_noise, r.method, r.rmse_net
        );
    }
}

/// A run's `(time ms, passes, RMSE)` series as the JSON keeps it: every
/// point up to 64 passes, then one per 5% more passes, and the last (a
/// 2,000-pass run keeps about 140 points; the plots are log-scaled).
fn thin_series(series: &[(f64, u32, f64)]) -> Vec<(f64, u32, f64)> {
    let mut out = Vec::new();
    let mut next = 0u32;
    for (k, &p) in series.iter().enumerate() {
        if p.1 <= 64 || p.1 >= next || k + 1 == series.len() {
            out.push(p);
            next = (p.1 as f64 * 1.05).ceil() as u32;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::thin_series;

    /// Every point up to 64 passes, each kept point at least 5% more passes
    /// than the one before past that, the last point always, and about 140
    /// points for 2,000 passes.
    #[test]
    fn series_are_thinned_on_a_log_scale() {
        let series: Vec<(f64, u32, f64)> =
            (1..=2000).map(|p| (p as f64, p, 1.0 / p as f64)).collect();
        let thin = thin_series(&series);
        assert_eq!(&thin[..64], &series[..64]);
        assert_eq!(thin.last(), series.last());
        for w in thin[63..thin.len() - 1].windows(2) {
            assert!(w[1].1 as f64 >= 1.05 * w[0].1 as f64, "{:?}", w);
        }
        assert!((120..=160).contains(&thin.len()), "{} points", thin.len());
        assert_eq!(thin_series(&series[..10]), series[..10].to_vec());
    }
}
