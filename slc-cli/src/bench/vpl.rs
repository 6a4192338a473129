//! The VPL frame's bench: `none`, `slc` over error bounds, `clamp` over
//! ranges, each against every VPL at every pixel, on the CPU or the GPU.

use super::args::{BenchArgs, progress};
use super::measure::{Spread, fastest, fastest_frames};
use crate::backends::{Backend, gpu_context};
use crate::reference::vpl_reference;
use crate::report::{Report, Run, StageMs, Work, write_vpl_csv};
use anyhow::Context;
use slc_scene::vpl::{Culling, VplFrame, VplSettings, WorkCounts};

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
                tile: a.scene.tile(),
                near_radius: a.scene.near_radius,
                ..d
            };
            (param, settings)
        })
        .collect())
}

/// One configuration's row of a VPL report (loop evaluations per second are
/// 0 where the backend does not count evaluations).
fn vpl_run(
    settings: &VplSettings,
    param: Option<f32>,
    st: &slc_scene::vpl::VplStats,
    rmse: Spread,
    stages: Vec<StageMs>,
    work: (WorkCounts, WorkCounts),
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
        far_work: Some(Work::of(&work.0)),
        near_work: (work.1.pixels > 0).then(|| Work::of(&work.1)),
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

/// The bench on the CPU backend.
pub(super) fn run_cpu(a: BenchArgs) -> anyhow::Result<()> {
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
        .map(|(name, ms)| StageMs { name: name.into(), ms, min_ms: None, max_ms: None })
        .to_vec();
        runs.push(vpl_run(&settings, param, st, rmse, stages, (st.far_work, st.near_work)));
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
/// configuration. Timed with the GPU's clock held
/// (`GpuVplFrame::time_sequence`: a continuous warm-up of `--warmup`
/// seconds, then `--timed-frames` frames back to back in one submission,
/// their timestamps resolved after the last; each stage's median and
/// spread); where the adapter has no timestamps, the fastest of
/// `--repeat` frames by wall clock, a wait after every stage. The RMSE
/// comes from `--repeat` frames rendered and read back apart (frames 0,
/// 1, …), against every VPL at every pixel of the frame's own rasterized
/// G-buffer and RSM, shaded and composed on the GPU
/// (`GpuVplFrame::render_reference`), so it measures the methods, not
/// rasterization against ray casting. The work counters come from the
/// counting kernels (`GpuVplFrame::count_work`), outside the timed frames.
pub(super) fn run_gpu(a: BenchArgs) -> anyhow::Result<()> {
    use slc_wgpu::frame::Stage;
    if !(a.warmup >= 0.0 && a.warmup.is_finite()) {
        anyhow::bail!("--warmup {} must be finite and >= 0 (seconds)", a.warmup);
    }
    if a.timed_frames == 0 {
        anyhow::bail!("--timed-frames 0 must be at least 1");
    }
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
    let mut held = true;
    for (param, settings) in configs {
        bar.set_message(run_label(&settings, param));
        let st = pass_settings(&settings)?;
        // One frame first: drivers compile a pipeline at its first use.
        frame.render(&st)?;
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
        let work = frame.count_work(&st)?;
        let sequence = frame.time_sequence(
            &st,
            std::time::Duration::from_secs_f64(a.warmup),
            a.timed_frames,
        )?;
        let mut stats = f.stats;
        let stages = match &sequence {
            Some(seq) => {
                timing = slc_scene::backend::Timing::GpuTimestamps;
                stats.shading_ms = seq.spread(&Stage::SHADING).0;
                stats.total_ms = seq.spread(&[]).0;
                seq.stages()
                    .iter()
                    .map(|s| StageMs {
                        name: s.name.to_string(),
                        ms: s.median_ms,
                        min_ms: Some(s.min_ms),
                        max_ms: Some(s.max_ms),
                    })
                    .collect()
            }
            None => {
                held = false;
                timing = f.timing;
                f.stages
                    .iter()
                    .map(|s| StageMs {
                        name: s.name.to_string(),
                        ms: s.ms,
                        min_ms: None,
                        max_ms: None,
                    })
                    .collect()
            }
        };
        runs.push(vpl_run(&settings, param, &stats, rmse, stages, work));
        bar.inc(1);
    }
    bar.finish_and_clear();
    speedups(&mut runs);
    let how = if held {
        format!(
            "GPU timestamps, the clock held: {:.1} s of continuous frames, then {} frames back to back in one submission, each stage's median (min..max in the JSON); shading = light update + culling boxes + shading + near field",
            a.warmup, a.timed_frames
        )
    } else {
        format!(
            "{}; the clock is not held: the fastest of --repeat frames by shading time",
            crate::notes::timing_note(timing)
        )
    };
    let report = Report {
        app: "vpl".into(),
        backend: format!("gpu: {}", gpu.describe()),
        scene: r.scene.name.clone(),
        width: r.width,
        height: r.height,
        lights: (r.rsm_size as usize).pow(2),
        timing: format!("{how}; RMSE: the mean over --repeat frames read back apart (0, 1, …)"),
        threads: std::thread::available_parallelism().map_or(1, |n| n.get()),
        reference_from_cache: false,
        simd: None,
        unculled_loop_evaluations_per_second: None,
        runs,
    };
    println!("adapter: {}", gpu.describe());
    println!("timing: {}", report.timing);
    for run in &report.runs {
        let stages: Vec<String> = run
            .stages
            .iter()
            .map(|s| match (s.min_ms, s.max_ms) {
                (Some(lo), Some(hi)) => format!("{} {:.3} ({lo:.3}..{hi:.3})", s.name, s.ms),
                _ => format!("{} {:.3}", s.name, s.ms),
            })
            .collect();
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
    println!("work per shaded pixel (counted; the same on every machine):");
    for r in &report.runs {
        let label = format!("{} {}", r.method, r.param.map_or("-".into(), |p| p.to_string()));
        if let Some(w) = &r.far_work {
            println!("  {label:<14} far:  {}", w.line());
        }
        if let Some(w) = &r.near_work {
            println!("  {label:<14} near: {}", w.line());
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
