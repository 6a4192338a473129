//! `slc bench --app pt --suite [DIR]`: every method at equal time on every
//! scene file of a suite (`slc suite` writes `scenes/suite/`), one table,
//! one JSON, one CSV and one plot for them all.
//!
//! Per scene it reports each method's net RMSE (the reference's own noise
//! taken out; with `--noise seeds`, no reference: the noise σ from two
//! renders of different seeds, at any resolution), its noise per sample `rmse_net · √spp` (what the selection
//! buys, independent of speed) and its time per sample against uniform
//! sampling's (what it costs), and slc-weighted's net RMSE over the best
//! peer's (uniform, power, lightbvh): the target is ≤ 1 in every
//! scene and ≤ 0.8 in the median one.

use super::args::BenchArgs;
use super::pt::pt_equal_time;
use crate::report::{PtReport, SuiteRow};
use anyhow::{Context, anyhow};
use serde::Serialize;
use slc_scene::scene_file::SceneFile;
use std::path::{Path, PathBuf};

/// The methods slc-weighted is judged against.
const PEERS: [&str; 3] = ["uniform", "power", "lightbvh"];

/// The whole suite run: every scene's equal-time report and the summary rows.
#[derive(Serialize)]
struct SuiteReport {
    folder: String,
    seconds_per_method: f64,
    /// Where the errors come from: `reference` (net RMSE against a CPU
    /// reference) or `seeds` (σ from seed pairs, `--noise seeds`).
    noise: String,
    scenes: Vec<PtReport>,
    rows: Vec<SuiteRow>,
}

/// The scene files of `dir`, sorted by name.
fn scene_files(dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .with_context(|| {
            format!(
                "--suite {}: cannot read the folder (write it with `slc suite --out {0}`)",
                dir.display()
            )
        })?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    if files.is_empty() {
        return Err(anyhow!(
            "--suite {}: no .toml scene files there (write them with `slc suite --out {0}`)",
            dir.display()
        ));
    }
    Ok(files)
}

/// The summary rows of one scene's report.
pub fn rows(scene: &str, r: &PtReport) -> Vec<SuiteRow> {
    let uniform = r.runs.iter().find(|x| x.method == "uniform");
    let (u_rmse, u_tps) =
        uniform.map_or((f64::NAN, f64::NAN), |u| (u.rmse_net, u.time_ms / u.spp.max(1) as f64));
    r.runs
        .iter()
        .map(|x| SuiteRow {
            scene: scene.to_string(),
            method: x.method.clone(),
            spp: x.spp,
            rmse_net: x.rmse_net,
            noise_per_sample: x.rmse_net * (x.spp as f64).sqrt(),
            time_per_sample_vs_uniform: x.time_ms / x.spp.max(1) as f64 / u_tps,
            rmse_vs_uniform: x.rmse_net / u_rmse,
        })
        .collect()
}

/// slc-weighted's net RMSE over the best peer's, per scene (NaN where a
/// method is missing).
pub fn weighted_over_best_peer(rows: &[SuiteRow], scene: &str) -> f64 {
    let of = |m: &str| rows.iter().find(|r| r.scene == scene && r.method == m).map(|r| r.rmse_net);
    let best = PEERS.iter().filter_map(|m| of(m)).fold(f64::INFINITY, f64::min);
    of("slc-weighted").map_or(f64::NAN, |w| w / best)
}

pub fn run(a: &BenchArgs, dir: &Path) -> anyhow::Result<()> {
    let files = scene_files(dir)?;
    let mut scenes = Vec::new();
    let mut all_rows = Vec::new();
    for (i, file) in files.iter().enumerate() {
        let name = file
            .file_stem()
            .map_or_else(|| file.display().to_string(), |s| s.to_string_lossy().into_owned());
        eprintln!("suite: scene {} of {}: {name}", i + 1, files.len());
        let f = SceneFile::load(file).with_context(|| format!("suite scene {}", file.display()))?;
        let mut report = pt_equal_time(a, &f.scene, &f.lights, &f.render)?;
        report.scene = name.clone();
        all_rows.extend(rows(&name, &report));
        scenes.push(report);
    }
    let report = SuiteReport {
        folder: dir.display().to_string(),
        seconds_per_method: a.seconds,
        noise: match a.noise {
            super::args::Noise::Reference => "reference".into(),
            super::args::Noise::Seeds => "seeds".into(),
        },
        scenes,
        rows: all_rows,
    };
    if let Some(path) = &a.json {
        std::fs::write(path, serde_json::to_string_pretty(&report)?)
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    if let Some(path) = &a.csv {
        let mut w = csv::Writer::from_path(path)
            .with_context(|| format!("cannot write {}", path.display()))?;
        for r in &report.rows {
            w.serialize(r)?;
        }
        w.flush()?;
    }
    if let Some(path) = &a.plot {
        crate::plot::suite_vs_uniform(&report.rows, path)?;
    }
    print_summary(&report);
    Ok(())
}

fn print_summary(report: &SuiteReport) {
    let methods: Vec<String> = report
        .scenes
        .first()
        .map_or(Vec::new(), |s| s.runs.iter().map(|r| r.method.clone()).collect());
    println!(
        "suite {}: {} scenes, {} s per method; {} over uniform's (spp)",
        report.folder,
        report.scenes.len(),
        report.seconds_per_method,
        if report.noise == "seeds" { "noise σ (from seed pairs)" } else { "net RMSE" }
    );
    print!("{:<24} {:>7}", "scene", "lights");
    for m in &methods {
        print!(" {:>16}", m);
    }
    println!(" {:>10} {:>10}", "w/best", "w t/spp");
    let mut ratios = Vec::new();
    for s in &report.scenes {
        print!("{:<24} {:>7}", s.scene, s.lights);
        for m in &methods {
            let r = report.rows.iter().find(|r| r.scene == s.scene && &r.method == m);
            let ratio = r
                .filter(|r| r.rmse_vs_uniform.is_finite())
                .map_or("-".into(), |r| format!("{:.2}", r.rmse_vs_uniform));
            print!(" {:>16}", format!("{ratio} ({})", r.map_or(0, |r| r.spp)));
        }
        let ratio = weighted_over_best_peer(&report.rows, &s.scene);
        let tps = report
            .rows
            .iter()
            .find(|r| r.scene == s.scene && r.method == "slc-weighted")
            .map_or(f64::NAN, |r| r.time_per_sample_vs_uniform);
        ratios.push(ratio);
        let num = |v: f64| if v.is_finite() { format!("{v:.2}") } else { "-".into() };
        println!(" {:>10} {:>10}", num(ratio), num(tps));
    }
    for s in &report.scenes {
        if let Some(r) = s.runs.iter().find(|r| s.reference_noise > r.rmse_net / 3.0) {
            println!(
                "warning: {}: the reference's own noise {:.5} exceeds a third of {}'s net RMSE {:.5}: its ratios are uncertain (\"-\" where none is left); raise --reference-spp",
                s.scene, s.reference_noise, r.method, r.rmse_net
            );
        }
    }
    let mut sorted: Vec<f64> = ratios.iter().copied().filter(|r| r.is_finite()).collect();
    sorted.sort_by(f64::total_cmp);
    if sorted.is_empty() {
        println!(
            "slc-weighted / best peer (uniform, power, lightbvh): not measurable in any scene (raise --reference-spp)"
        );
    } else {
        let median = sorted[sorted.len() / 2];
        let wins = sorted.iter().filter(|&&r| r <= 1.0).count();
        println!(
            "slc-weighted / best peer (uniform, power, lightbvh): median {median:.2}, at most 1 in {wins} of {} scenes (targets: <= 1 in every scene, median <= 0.8)",
            sorted.len()
        );
    }
    println!(
        "(w/best: slc-weighted's net RMSE over the best peer's; w t/spp: its time per sample over uniform's)"
    );
}
