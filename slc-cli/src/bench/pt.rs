//! Path tracing at equal time: every method for the same wall-clock time,
//! RMSE against a reference.

use super::args::{BenchArgs, Noise};
use crate::backends::{GPU_BATCH, gpu_context_with, path_tracer};
use crate::reference::pt_reference;
use crate::report::{PtReport, PtRun, write_pt_csv};
use anyhow::{Context, anyhow};
use indicatif::{ProgressBar, ProgressStyle};
use slc_cpu::pt::CpuPathTracer;
use slc_scene::pt::{PtMethod, PtRender, PtScene, PtSettings};

pub(super) fn run(a: BenchArgs) -> anyhow::Result<()> {
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
/// the methods taking turns a batch of passes at a time, RMSE against a
/// (cached) CPU reference of `--reference-spp`, or with `--noise seeds`
/// the noise σ from renders of different seeds: the first pair in those
/// turns (each method then takes twice `--seconds`), `--pairs` − 1 more at
/// its passes, one method after another. The time per sample comes from
/// the turns alone.
pub(super) fn pt_equal_time(
    a: &BenchArgs,
    scene: &slc_scene::scene::Scene,
    lights: &[slc_core::light::Light],
    f: &slc_scene::scene_file::RenderSettings,
) -> anyhow::Result<PtReport> {
    let (w, h) =
        (a.scene.width.or(f.width).unwrap_or(128), a.scene.height.or(f.height).unwrap_or(128));
    let pts = PtScene::new(scene, lights)?;
    let (eps, eps_note) =
        crate::methods::pt_error_bound(a.error_bound, f.pt_error_bound, &pts, 1.0)?;
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
    // The reference (image, its own noise, from the cache), or none when
    // the noise comes from seed pairs.
    let reference = match a.noise {
        Noise::Seeds => None,
        Noise::Reference => {
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
            Some(r)
        }
    };
    // The reference stays on the CPU; the methods run on the chosen backend.
    let ctx = gpu_context_with(a.scene.backend, a.scene.ray_query)?;
    let mut tracer = path_tracer(ctx.as_ref(), &pts, (w, h), a.scene.ray_query, a.scene.grid_on())?;
    let batch = if ctx.is_some() { GPU_BATCH } else { 1 };
    let methods = PtMethod::ALL;
    // Each method's time-bounded render (and its seed twin), its settings
    // and its RMSE after each batch.
    struct Track {
        s: PtSettings,
        twin_s: PtSettings,
        acc: PtRender,
        twin: PtRender,
        series: Vec<(f64, u32, f64)>,
    }
    let mut tracks: Vec<Track> = methods
        .iter()
        .map(|&method| {
            let s = PtSettings { method, error_bound: eps, seed: a.seed, ..PtSettings::default() };
            // Seed pairs: the twin renders the same passes with the next seed.
            let twin_s = PtSettings { seed: a.seed.wrapping_add(1), ..s };
            Track {
                s,
                twin_s,
                acc: PtRender::new(w, h),
                twin: PtRender::new(w, h),
                series: Vec::new(),
            }
        })
        .collect();
    // The bar counts tenths of a second of rendering, all methods together.
    let tenths = (a.seconds * 10.0).ceil() as u64;
    bar.set_style(ProgressStyle::with_template("{spinner} [{bar:30}] {msg} (ETA {eta})")?);
    bar.set_length(tenths * methods.len() as u64);
    bar.set_position(0);
    bar.reset_eta();
    bar.set_message(format!("{} methods in turn, {} s each", methods.len(), a.seconds));
    // The methods take turns, a batch each, until each has rendered for
    // --seconds: a drift of the machine's speed (a shared or throttled
    // CPU, a GPU's clock) then touches every method alike, where one
    // method after another would put it into their time per sample.
    let budget = a.seconds * 1e3;
    while tracks.iter().any(|t| t.acc.time_ms < budget) {
        for t in tracks.iter_mut().filter(|t| t.acc.time_ms < budget) {
            tracer.render(&mut t.acc, &t.s, batch).map_err(|e| anyhow!(e))?;
            let error = match &reference {
                Some(r) => t.acc.image().rmse(&r.image),
                None => {
                    tracer.render(&mut t.twin, &t.twin_s, batch).map_err(|e| anyhow!(e))?;
                    t.acc.image().rmse(&t.twin.image()) / std::f64::consts::SQRT_2
                }
            };
            t.series.push((t.acc.time_ms, t.acc.passes, error));
        }
        let done: f64 = tracks.iter().map(|t| t.acc.time_ms.min(budget)).sum();
        bar.set_position((done / 100.0) as u64);
    }
    let mut runs = Vec::new();
    for (k, t) in tracks.into_iter().enumerate() {
        let (s, method) = (t.s, t.s.method);
        let last = *t.series.last().expect("at least one pass");
        let noise = reference.as_ref().map_or(0.0, |r| r.noise);
        // Time per sample from the interleaved renders only: the twin
        // rendered the same passes in the same turns.
        let time_ms = match &reference {
            Some(_) => t.acc.time_ms,
            None => 0.5 * (t.acc.time_ms + t.twin.time_ms),
        };
        // The other seed pairs render the first pair's passes; they give
        // the noise, not the time.
        let mut pair_variances = Vec::new();
        if reference.is_none() {
            pair_variances.push(last.2 * last.2);
            for pair in 1..a.pairs {
                bar.set_message(format!(
                    "{} ({} of {}), seed pair {} of {}",
                    method.name(),
                    k + 1,
                    methods.len(),
                    pair + 1,
                    a.pairs
                ));
                let seed = a.seed.wrapping_add(2 * pair);
                let one = PtSettings { seed, ..s };
                let other = PtSettings { seed: seed.wrapping_add(1), ..s };
                let (mut p, mut q) = (PtRender::new(w, h), PtRender::new(w, h));
                while p.passes < last.1 {
                    tracer.render(&mut p, &one, batch).map_err(|e| anyhow!(e))?;
                    tracer.render(&mut q, &other, batch).map_err(|e| anyhow!(e))?;
                }
                pair_variances.push(p.image().rmse(&q.image()).powi(2) / 2.0);
            }
        }
        let rmse = match pair_variances.len() {
            0 => last.2,
            n => (pair_variances.iter().sum::<f64>() / n as f64).sqrt(),
        };
        runs.push(PtRun {
            method: method.name().into(),
            param: method.culls().then_some(eps),
            time_ms,
            spp: last.1,
            rmse,
            rmse_net: (rmse * rmse - noise * noise).max(0.0).sqrt(),
            series: thin_series(&t.series),
            pair_variances,
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
        } + match a.scene.grid {
            Some(crate::scene_args::Grid::On) => ", grid on",
            Some(crate::scene_args::Grid::Off) => ", grid off",
            None => "",
        },
        scene: scene.name.clone(),
        width: w,
        height: h,
        lights: pts.light_count(),
        reference: match &reference {
            Some(_) => format!("{}, {} spp", a.reference_method.name(), a.reference_spp),
            None if a.pairs == 1 => {
                format!("none: noise from seeds {} and {}", a.seed, a.seed.wrapping_add(1))
            }
            None => format!(
                "none: noise from {} seed pairs, seeds {} to {}",
                a.pairs,
                a.seed,
                a.seed.wrapping_add(2 * a.pairs - 1)
            ),
        },
        reference_noise: reference.as_ref().map_or(0.0, |r| r.noise),
        reference_from_cache: reference.as_ref().is_some_and(|r| r.cached),
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
    let seeds = a.noise == Noise::Seeds;
    let source = if seeds {
        format!("{}: σ = RMSE(one, other)/√2 at equal passes", report.reference)
    } else {
        format!(
            "reference {} {}, its own RMSE about {:.5}",
            report.reference,
            if report.reference_from_cache { "from cache" } else { "rendered" },
            report.reference_noise
        )
    };
    println!(
        "{} {}x{}, {} lights, {:.1} s per method{} ({source})",
        report.scene,
        w,
        h,
        report.lights,
        a.seconds,
        if seeds { " and seed" } else { "" }
    );
    let spread = a.pairs > 1;
    println!(
        "{:<14} {:>8} {:>10} {:>6} {:>10} {:>10}{} {:>16}",
        "method",
        "param",
        "time ms",
        "spp",
        "rmse",
        "rmse net",
        if spread { format!(" {:>9}", "± se") } else { String::new() },
        "uniform/method"
    );
    for r in &report.runs {
        // No ratio where the reference's noise left no net error (warned below).
        let ratio = uniform / r.rmse_net;
        println!(
            "{:<14} {:>8} {:>10.0} {:>6} {:>10.5} {:>10.5}{} {:>16}",
            r.method,
            r.param.map_or("-".into(), |p| p.to_string()),
            r.time_ms,
            r.spp,
            r.rmse,
            r.rmse_net,
            if spread { format!(" {:>9.5}", r.rmse_se()) } else { String::new() },
            if ratio.is_finite() && r.rmse_net > 0.0 { format!("{ratio:.2}") } else { "-".into() }
        );
    }
    if seeds {
        println!(
            "(rmse, rmse net: σ, one render's RMSE against the exact image{}; the ratio uses it)",
            if spread {
                ", the root of the pairs' mean σ²; ± se: its standard error from their spread"
            } else {
                "; one pair: --pairs K for its standard error"
            }
        );
        return;
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
            "warning: the reference's own noise {:.5} exceeds a third of {}'s net RMSE {:.5}: its ratio is uncertain (\"-\" where none is left); raise --reference-spp",
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
