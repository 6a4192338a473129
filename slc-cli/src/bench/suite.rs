//! `slc bench --app pt --suite [DIR]`: every method at equal time on every
//! scene file of a suite (`slc suite` writes `scenes/suite/`), one table,
//! one JSON, one CSV and one plot for them all.
//!
//! Per scene it reports each method's net RMSE (the reference's own noise
//! taken out; with `--noise seeds`, no reference: the noise σ from two
//! renders of different seeds, at any resolution), its noise per sample `rmse_net · √spp` (what the selection
//! buys, independent of speed) and its time per sample against uniform
//! sampling's (what it costs), and slc-weighted against the best peer
//! (uniform, power, lightbvh; the least net RMSE): its net RMSE over the
//! peer's, split into the two factors it is the product of at equal time,
//! noise per sample over the peer's times the root of time per sample over
//! the peer's ([`AgainstBest`]), so a loss says whether the selection or
//! its cost lost it.

use super::args::BenchArgs;
use super::pt::pt_equal_time;
use crate::report::{PtReport, SuiteRow};
use anyhow::{Context, anyhow};
use rand_core::RngCore;
use rand_pcg::Pcg32;
use serde::Serialize;
use slc_scene::scene_file::SceneFile;
use slc_scene::stats::median;
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
    /// slc-weighted against the best peer, per scene (scenes where a
    /// method is missing left out).
    against_best: Vec<AgainstBest>,
    /// The 90% interval of the median of `against_best`'s ratios over the
    /// seed pairs ([`median_interval`]; none for one pair).
    median_interval: Option<(f64, f64)>,
}

/// slc-weighted against the best peer of one scene, the peer with the
/// least net RMSE at equal time. At equal time `rmse = σ₁/√spp` and
/// `spp = T/t`, so `rmse` over the peer's is `noise_per_sample` over the
/// peer's times `√(time_per_sample over the peer's)`.
#[derive(Serialize, Clone, Debug, PartialEq)]
pub struct AgainstBest {
    pub scene: String,
    /// The best peer's method name.
    pub peer: String,
    /// slc-weighted's net RMSE over the peer's (≤ 1: slc-weighted wins).
    pub rmse: f64,
    /// Its noise per sample (`rmse_net · √spp`) over the peer's: what the
    /// selection buys.
    pub noise_per_sample: f64,
    /// Its time per sample over the peer's: what the selection costs.
    pub time_per_sample: f64,
    /// The standard error of `rmse` from the two methods' seed pairs:
    /// `rmse · ½√(s_w² + s_p²)`, `s` each one's relative standard error
    /// of σ² (NaN for one pair).
    pub rmse_se: f64,
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
            rmse_se: x.rmse_se(),
        })
        .collect()
}

/// slc-weighted against the best peer in `scene`, or `None` where it or
/// every peer is missing or unmeasurable (a NaN net RMSE).
pub fn against_best_peer(rows: &[SuiteRow], scene: &str) -> Option<AgainstBest> {
    let of = |m: &str| rows.iter().find(|r| r.scene == scene && r.method == m);
    let w = of("slc-weighted").filter(|w| w.rmse_net.is_finite())?;
    let best = PEERS
        .iter()
        .filter_map(|m| of(m))
        .filter(|r| r.rmse_net.is_finite())
        .min_by(|a, b| a.rmse_net.total_cmp(&b.rmse_net))?;
    Some(AgainstBest {
        scene: scene.to_string(),
        peer: best.method.clone(),
        rmse: w.rmse_net / best.rmse_net,
        noise_per_sample: w.noise_per_sample / best.noise_per_sample,
        time_per_sample: w.time_per_sample_vs_uniform / best.time_per_sample_vs_uniform,
        // σ's relative error is half σ²'s: se(σ)/σ = s/2.
        rmse_se: w.rmse_net / best.rmse_net
            * ((w.rmse_se / w.rmse_net).powi(2) + (best.rmse_se / best.rmse_net).powi(2)).sqrt(),
    })
}

/// Bootstrap draws of [`median_interval`].
const BOOTSTRAP_DRAWS: usize = 2000;

/// The 5th and 95th percentiles of slc-weighted's median ratio to the best
/// peer over the suite's scenes, by the bootstrap over seed pairs: each
/// draw resamples every method's pairs in every scene (with replacement,
/// as many as it has), takes the root of their mean σ² as its RMSE,
/// re-picks each scene's best peer and takes the median ratio. `None`
/// unless every method of every scene has two or more pairs. A fixed
/// seed: the same report gives the same interval.
pub fn median_interval(scenes: &[PtReport]) -> Option<(f64, f64)> {
    let usable = |s: &PtReport| {
        s.runs.iter().any(|r| r.method == "slc-weighted")
            && s.runs.iter().any(|r| PEERS.contains(&r.method.as_str()))
            && s.runs.iter().all(|r| r.pair_variances.len() >= 2)
    };
    if scenes.is_empty() || !scenes.iter().all(usable) {
        return None;
    }
    let mut rng = Pcg32::new(0xB007_57A9, 48);
    let mut resampled = |v: &[f64]| {
        let n = v.len();
        let sum: f64 = (0..n).map(|_| v[(rng.next_u32() as usize) % n]).sum();
        (sum / n as f64).sqrt()
    };
    let mut medians = Vec::with_capacity(BOOTSTRAP_DRAWS);
    for _ in 0..BOOTSTRAP_DRAWS {
        let mut ratios = Vec::with_capacity(scenes.len());
        for s in scenes {
            let (mut w, mut best) = (f64::NAN, f64::INFINITY);
            for r in &s.runs {
                let rmse = resampled(&r.pair_variances);
                if r.method == "slc-weighted" {
                    w = rmse;
                } else if PEERS.contains(&r.method.as_str()) {
                    best = best.min(rmse);
                }
            }
            ratios.push(w / best);
        }
        medians.push(median(&ratios)?);
    }
    medians.sort_by(f64::total_cmp);
    let at = |q: f64| medians[((q * (medians.len() - 1) as f64).round()) as usize];
    Some((at(0.05), at(0.95)))
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
    let against_best =
        scenes.iter().filter_map(|s| against_best_peer(&all_rows, &s.scene)).collect();
    let report = SuiteReport {
        folder: dir.display().to_string(),
        seconds_per_method: a.seconds,
        noise: match a.noise {
            super::args::Noise::Reference => "reference".into(),
            super::args::Noise::Seeds => "seeds".into(),
        },
        median_interval: median_interval(&scenes),
        scenes,
        rows: all_rows,
        against_best,
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
    println!(" {:>12} {:>8} {:>8} {:>8} {:>10}", "w/best", "best", "nps", "t/spp", "w t/spp");
    let num = |v: f64| if v.is_finite() { format!("{v:.2}") } else { "-".into() };
    let with_se = |v: f64, se: f64| match (v.is_finite(), se.is_finite()) {
        (true, true) => format!("{v:.2}±{se:.2}"),
        _ => num(v),
    };
    for s in &report.scenes {
        print!("{:<24} {:>7}", s.scene, s.lights);
        for m in &methods {
            let r = report.rows.iter().find(|r| r.scene == s.scene && &r.method == m);
            let ratio = r
                .filter(|r| r.rmse_vs_uniform.is_finite())
                .map_or("-".into(), |r| format!("{:.2}", r.rmse_vs_uniform));
            print!(" {:>16}", format!("{ratio} ({})", r.map_or(0, |r| r.spp)));
        }
        let tps = report
            .rows
            .iter()
            .find(|r| r.scene == s.scene && r.method == "slc-weighted")
            .map_or(f64::NAN, |r| r.time_per_sample_vs_uniform);
        match report.against_best.iter().find(|b| b.scene == s.scene) {
            Some(b) => println!(
                " {:>12} {:>8} {:>8} {:>8} {:>10}",
                with_se(b.rmse, b.rmse_se),
                b.peer,
                num(b.noise_per_sample),
                num(b.time_per_sample),
                num(tps)
            ),
            None => println!(" {:>12} {:>8} {:>8} {:>8} {:>10}", "-", "-", "-", "-", num(tps)),
        }
    }
    for s in &report.scenes {
        if let Some(r) = s.runs.iter().find(|r| s.reference_noise > r.rmse_net / 3.0) {
            println!(
                "warning: {}: the reference's own noise {:.5} exceeds a third of {}'s net RMSE {:.5}: its ratios are uncertain (\"-\" where none is left); raise --reference-spp",
                s.scene, s.reference_noise, r.method, r.rmse_net
            );
        }
    }
    let b = &report.against_best;
    let ratios: Vec<f64> = b.iter().map(|b| b.rmse).collect();
    match median(&ratios) {
        None => println!(
            "slc-weighted / best peer (uniform, power, lightbvh): not measurable in any scene (raise --reference-spp)"
        ),
        Some(m) => {
            let wins = ratios.iter().filter(|&&r| r <= 1.0).count();
            let losses: Vec<&AgainstBest> = b.iter().filter(|b| b.rmse > 1.0).collect();
            let by_noise = losses.iter().filter(|b| b.noise_per_sample > 1.0).count();
            println!(
                "slc-weighted / best peer (uniform, power, lightbvh): median {m:.2}{}, at most 1 in {wins} of {} scenes; of the {} losses, {by_noise} with more noise per sample than the peer, {} with less (lost on time per sample alone)",
                report.median_interval.map_or(String::new(), |(lo, hi)| format!(
                    " (90% interval over the seed pairs {lo:.2}–{hi:.2})"
                )),
                ratios.len(),
                losses.len(),
                losses.len() - by_noise
            );
            // Wins and losses the pairs' spread cannot overturn (2 se).
            if b.iter().all(|b| b.rmse_se.is_finite()) {
                let clear_wins = b.iter().filter(|b| b.rmse + 2.0 * b.rmse_se < 1.0).count();
                let clear_losses = b.iter().filter(|b| b.rmse - 2.0 * b.rmse_se > 1.0).count();
                println!(
                    "  beyond 2 standard errors: {clear_wins} wins, {clear_losses} losses; {} scenes within them",
                    b.len() - clear_wins - clear_losses
                );
            }
        }
    }
    println!(
        "(w/best: slc-weighted's net RMSE over the best peer's, = nps · √(t/spp): its noise per sample and time per sample over that peer's; w t/spp: its time per sample over uniform's)"
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(method: &str, rmse_net: f64, spp: u32, tps: f64) -> SuiteRow {
        SuiteRow {
            scene: "s".into(),
            method: method.into(),
            spp,
            rmse_net,
            noise_per_sample: rmse_net * (spp as f64).sqrt(),
            time_per_sample_vs_uniform: tps,
            rmse_vs_uniform: f64::NAN,
            rmse_se: f64::NAN,
        }
    }

    #[test]
    fn against_best_splits_the_ratio_into_noise_and_time_per_sample() {
        // At equal time: uniform 400 spp, power 100 spp (4x the time per
        // sample), slc-weighted 200 spp (2x).
        let rows = [
            row("uniform", 0.05, 400, 1.0),
            row("power", 0.04, 100, 4.0),
            row("lightbvh", f64::NAN, 0, f64::NAN),
            row("slc-weighted", 0.03, 200, 2.0),
        ];
        let b = against_best_peer(&rows, "s").unwrap();
        assert_eq!(b.peer, "power");
        assert!((b.rmse - 0.75).abs() < 1e-12);
        assert!((b.time_per_sample - 0.5).abs() < 1e-12);
        // 0.03·√200 / (0.04·√100)
        assert!((b.noise_per_sample - 0.03 * 200f64.sqrt() / 0.4).abs() < 1e-12);
        assert!((b.noise_per_sample * b.time_per_sample.sqrt() - b.rmse).abs() < 1e-12);
        assert_eq!(against_best_peer(&rows[..3], "s"), None);
    }

    fn run(method: &str, pairs: &[f64]) -> crate::report::PtRun {
        let rmse = (pairs.iter().sum::<f64>() / pairs.len() as f64).sqrt();
        crate::report::PtRun {
            method: method.into(),
            param: None,
            time_ms: 1.0,
            spp: 1,
            rmse,
            rmse_net: rmse,
            series: Vec::new(),
            pair_variances: pairs.to_vec(),
        }
    }

    fn scene(runs: Vec<crate::report::PtRun>) -> PtReport {
        PtReport {
            app: "pt".into(),
            backend: "cpu".into(),
            scene: "s".into(),
            width: 1,
            height: 1,
            lights: 1,
            reference: "none".into(),
            reference_noise: 0.0,
            reference_from_cache: false,
            error_bound_note: String::new(),
            runs,
        }
    }

    /// Pairs that agree give a point interval at the median ratio; pairs
    /// that spread give an interval around it; one pair gives none.
    #[test]
    fn the_median_interval_comes_from_the_seed_pairs() {
        let steady = [
            scene(vec![run("slc-weighted", &[1.0, 1.0]), run("uniform", &[4.0, 4.0])]),
            scene(vec![run("slc-weighted", &[1.0, 1.0, 1.0]), run("power", &[16.0; 3])]),
            scene(vec![run("slc-weighted", &[9.0, 9.0]), run("lightbvh", &[4.0, 4.0])]),
        ];
        // Ratios 0.5, 0.25 and 1.5: median 0.5, exactly in every draw.
        assert_eq!(median_interval(&steady), Some((0.5, 0.5)));
        let spread = [
            scene(vec![run("slc-weighted", &[0.5, 1.5, 1.0, 1.0]), run("uniform", &[4.0; 4])]),
            scene(vec![run("slc-weighted", &[1.0; 2]), run("uniform", &[1.0, 7.0])]),
            scene(vec![run("slc-weighted", &[1.0; 2]), run("uniform", &[0.5, 2.0])]),
        ];
        let (lo, hi) = median_interval(&spread).unwrap();
        assert!(lo < 0.5 && hi > 0.5 && lo > 0.0 && hi < 1.5, "{lo} {hi}");
        let one = [scene(vec![run("slc-weighted", &[1.0]), run("uniform", &[4.0])])];
        assert_eq!(median_interval(&one), None);
        assert_eq!(median_interval(&[]), None);
        // The ratio's standard error: each σ's relative error, in quadrature.
        let w = run("slc-weighted", &[1.0, 3.0]);
        let u = run("uniform", &[4.0, 4.0, 4.0]);
        assert!(u.rmse_se() == 0.0);
        // σ² = 2 ± 1 (sd √2 over √2 pairs): σ = √2, se(σ) = 1/(2√2).
        assert!((w.rmse_se() - 1.0 / (2.0 * 2f64.sqrt())).abs() < 1e-12);
    }
}
