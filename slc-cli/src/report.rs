//! The reports `slc bench` writes and `slc plot` reads (JSON), and their
//! CSV form.

use anyhow::Context;
use serde::{Deserialize, Serialize};
use slc_scene::vpl::WorkCounts;
use std::path::Path;

/// One configuration's measurements.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct Run {
    /// `slc`, `clamp` or `none`.
    pub method: String,
    /// Error bound ε (slc) or range R (clamp).
    pub param: Option<f32>,
    /// Culling and shading time (ms).
    pub shading_ms: f64,
    /// Whole frame (ms): G-buffer, RSM, direct, shading, denoise.
    pub total_ms: f64,
    /// RMSE of the final image against the reference (the mean over the
    /// run's frames).
    pub rmse: f64,
    /// The sample standard deviation of one frame's RMSE over the run's
    /// frames (absent in reports from before it was measured).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rmse_sd: Option<f64>,
    /// Lights in the tile lists per shaded pixel (work of the loop).
    pub lights_per_pixel: f64,
    /// Lights kept by the roulette per shaded pixel.
    pub kept_per_pixel: f64,
    /// Loop evaluations per second of shading time (culling included; 0
    /// where the backend does not count them).
    pub evaluations_per_second: f64,
    /// Every stage's time, in order (G-buffer, RSM, direct light, shading,
    /// denoise on the CPU; the GPU frame's passes on the GPU).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stages: Vec<StageMs>,
    /// The unculled (`none`) run's shading time over this one's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shading_speedup: Option<f64>,
    /// The unculled run's whole frame over this one's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub frame_speedup: Option<f64>,
    /// The far field's culling work per shaded pixel (both backends count
    /// it: the CPU as it shades, the GPU with its counting kernels).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub far_work: Option<Work>,
    /// The near field's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub near_work: Option<Work>,
}

/// One stage's time in a [`Run`].
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct StageMs {
    /// Stage name (`G-buffer`, `RSM`, `shading`, …).
    pub name: String,
    /// Milliseconds: the fastest frame's (CPU, or a GPU without
    /// timestamps), or the median of the frames timed back to back (GPU).
    pub ms: f64,
    /// GPU frames timed back to back: the fastest frame's milliseconds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min_ms: Option<f64>,
    /// The slowest frame's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_ms: Option<f64>,
}

/// The JSON written by `slc bench`.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct Report {
    /// Application (`vpl`).
    pub app: String,
    /// Backend (`cpu`).
    pub backend: String,
    /// Scene name.
    pub scene: String,
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// Number of lights (VPLs).
    pub lights: usize,
    /// How times were taken.
    pub timing: String,
    /// Worker threads.
    pub threads: usize,
    /// Whether the reference came from the cache.
    pub reference_from_cache: bool,
    /// The instruction set of the CPU's hot loops (`avx512`, `avx2`,
    /// `baseline`); absent for the GPU.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub simd: Option<String>,
    /// Light evaluations per second of the unculled loop alone (`none`
    /// without the near field, the shading loop every method shares), so
    /// the number compares across machines and settings; absent for the
    /// GPU, which does not count evaluations.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unculled_loop_evaluations_per_second: Option<f64>,
    /// One entry per configuration.
    pub runs: Vec<Run>,
}

/// One method's equal-time path-tracing run.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct PtRun {
    /// Method.
    pub method: String,
    /// Error bound ε for the SLC methods.
    pub param: Option<f32>,
    /// Time spent (ms) rendering `spp` passes (with `--noise seeds`, the
    /// mean of the first seed pair's two renders, which took turns with
    /// the other methods').
    pub time_ms: f64,
    /// Samples per pixel reached.
    pub spp: u32,
    /// RMSE against the reference at the end (with `--noise seeds`, σ: the
    /// root of the mean of `pair_variances`).
    pub rmse: f64,
    /// That RMSE with the reference's own noise taken out,
    /// `√max(rmse² − noise², 0)` (the two errors are independent).
    #[serde(default)]
    pub rmse_net: f64,
    /// (time ms, spp, RMSE) after each pass: RMSE against time (the first
    /// seed pair's, with `--noise seeds`).
    pub series: Vec<(f64, u32, f64)>,
    /// `--noise seeds`: each seed pair's σ² = RMSE(one, other)²/2 at `spp`
    /// passes; `rmse` is the root of their mean. Empty against a reference.
    #[serde(default)]
    pub pair_variances: Vec<f64>,
}

impl PtRun {
    /// The standard error of `rmse` from the seed pairs' spread: that of
    /// their mean σ², `sd(σ²ₖ)/√K`, over `2σ` (the root's derivative);
    /// NaN for fewer than two pairs.
    pub fn rmse_se(&self) -> f64 {
        mean_se(&self.pair_variances) / (2.0 * self.rmse)
    }
}

/// The standard error of the mean of `v` (`sd/√n`, the sample standard
/// deviation), NaN for fewer than two values.
pub fn mean_se(v: &[f64]) -> f64 {
    let n = v.len();
    if n < 2 {
        return f64::NAN;
    }
    let mean = v.iter().sum::<f64>() / n as f64;
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
    (var / n as f64).sqrt()
}

/// The JSON of `slc bench --app pt`.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct PtReport {
    /// `pt`.
    pub app: String,
    /// `cpu`, or `gpu: ADAPTER (timing source)`.
    pub backend: String,
    /// Scene name.
    pub scene: String,
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// Lights.
    pub lights: usize,
    /// Reference: method and samples per pixel.
    pub reference: String,
    /// Estimated RMSE of the reference itself (half-vs-half / 2).
    pub reference_noise: f64,
    /// Whether the reference came from the cache.
    pub reference_from_cache: bool,
    /// How the SLC methods' ε was set (given, the scene file's, automatic).
    #[serde(default)]
    pub error_bound_note: String,
    /// One entry per method.
    pub runs: Vec<PtRun>,
}

/// One CSV line of a VPL run: [`Run`] without its stages.
#[derive(Serialize)]
struct VplCsvRow<'a> {
    method: &'a str,
    param: Option<f32>,
    shading_ms: f64,
    total_ms: f64,
    rmse: f64,
    rmse_sd: Option<f64>,
    lights_per_pixel: f64,
    kept_per_pixel: f64,
    evaluations_per_second: f64,
}

/// One CSV line of a path-tracing run: [`PtRun`] without its series.
#[derive(Serialize)]
struct PtCsvRow<'a> {
    method: &'a str,
    param: Option<f32>,
    time_ms: f64,
    spp: u32,
    rmse: f64,
    rmse_net: f64,
}

/// Writes `rows` as CSV with a header line (the `csv` crate).
fn write_csv<R: Serialize>(path: &Path, rows: impl IntoIterator<Item = R>) -> anyhow::Result<()> {
    let write = || -> anyhow::Result<()> {
        let mut w = csv::Writer::from_path(path)?;
        for r in rows {
            w.serialize(r)?;
        }
        w.flush()?;
        Ok(())
    };
    write().with_context(|| format!("cannot write {}", path.display()))
}

/// Writes the VPL runs to `path` as CSV, one line per configuration.
pub fn write_vpl_csv(report: &Report, path: &Path) -> anyhow::Result<()> {
    write_csv(
        path,
        report.runs.iter().map(|r| VplCsvRow {
            method: &r.method,
            param: r.param,
            shading_ms: r.shading_ms,
            total_ms: r.total_ms,
            rmse: r.rmse,
            rmse_sd: r.rmse_sd,
            lights_per_pixel: r.lights_per_pixel,
            kept_per_pixel: r.kept_per_pixel,
            evaluations_per_second: r.evaluations_per_second,
        }),
    )
}

/// Writes the path-tracing runs to `path` as CSV, one line per method.
pub fn write_pt_csv(report: &PtReport, path: &Path) -> anyhow::Result<()> {
    write_csv(
        path,
        report.runs.iter().map(|r| PtCsvRow {
            method: &r.method,
            param: r.param,
            time_ms: r.time_ms,
            spp: r.spp,
            rmse: r.rmse,
            rmse_net: r.rmse_net,
        }),
    )
}

/// One method's curve over one sequence.
#[derive(Serialize, Clone, Debug)]
pub struct Curve {
    /// The method's name.
    pub method: String,
    /// RMSE against each frame's reference.
    pub rmse: Vec<f64>,
    /// RMSE against the method's previous frame (none for frame 0).
    pub temporal_rmse: Vec<f64>,
}

/// One sequence's curves.
#[derive(Serialize, Clone, Debug)]
pub struct SequenceReport {
    /// The sequence: `static`, `orbit` or `light`.
    pub sequence: String,
    /// The reference's own change between frames (what moving content
    /// contributes to every method's temporal RMSE).
    pub reference_temporal_rmse: Vec<f64>,
    /// Each method's curves.
    pub curves: Vec<Curve>,
}

/// The whole flicker report.
#[derive(Serialize, Clone, Debug)]
pub struct FlickerReport {
    /// `cpu (SIMD path)` or `gpu: adapter`.
    pub backend: String,
    /// Scene name.
    pub scene: String,
    /// Image size.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// VPL count.
    pub vpls: usize,
    /// Frames per sequence.
    pub frames: u32,
    /// The SLC error bound ε.
    pub error_bound: f32,
    /// The temporal stage's longest history.
    pub max_history: f32,
    /// Milliseconds of one temporal accumulation of the irradiance at this
    /// size on the CPU (fastest of the bench's repeats; none on the GPU).
    pub temporal_ms: Option<f64>,
    /// Every sequence.
    pub sequences: Vec<SequenceReport>,
}

/// A number JSON wrote as `null` (serde_json's NaN and ±∞) read back as NaN.
fn nan_if_null<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
}

/// One method on one suite scene, as the summary reads it (and `slc plot`
/// reads back: its numbers NaN where JSON holds `null`).
#[derive(Serialize, Deserialize, Clone, Debug)]
pub struct SuiteRow {
    /// Scene file stem.
    pub scene: String,
    /// Method.
    pub method: String,
    /// Samples per pixel reached in the time.
    pub spp: u32,
    /// Net RMSE (the reference's noise taken out).
    #[serde(deserialize_with = "nan_if_null")]
    pub rmse_net: f64,
    /// `rmse_net · √spp`: noise per sample.
    #[serde(deserialize_with = "nan_if_null")]
    pub noise_per_sample: f64,
    /// Time per sample over uniform sampling's on the same scene.
    #[serde(deserialize_with = "nan_if_null")]
    pub time_per_sample_vs_uniform: f64,
    /// Net RMSE over uniform sampling's on the same scene.
    #[serde(deserialize_with = "nan_if_null")]
    pub rmse_vs_uniform: f64,
    /// The standard error of `rmse_net` from the seed pairs
    /// ([`PtRun::rmse_se`]; NaN for one pair or against a reference).
    #[serde(deserialize_with = "nan_if_null")]
    pub rmse_se: f64,
}

/// One field's work per shaded pixel (`slc_scene::vpl::WorkCounts` divided
/// by the shaded pixels), as reports write it.
#[derive(Serialize, Deserialize, Clone, Copy, Debug, PartialEq, Default)]
pub struct Work {
    /// Group boxes tested, per pixel (a tile's tests over its pixels).
    pub group_tests: f64,
    /// Cluster boxes tested, per pixel.
    pub cluster_tests: f64,
    /// Light spheres tested, per pixel.
    pub sphere_tests: f64,
    /// Lights the shading loop tested, per pixel.
    pub tested: f64,
    /// Lights it kept, per pixel.
    pub kept: f64,
}

impl Work {
    /// `w` per shaded pixel.
    pub fn of(w: &WorkCounts) -> Work {
        Work {
            group_tests: w.per_pixel(w.group_tests),
            cluster_tests: w.per_pixel(w.cluster_tests),
            sphere_tests: w.per_pixel(w.sphere_tests),
            tested: w.per_pixel(w.tested),
            kept: w.per_pixel(w.kept),
        }
    }

    /// Culling tests of every kind per pixel.
    pub fn culling_tests(&self) -> f64 {
        self.group_tests + self.cluster_tests + self.sphere_tests
    }

    /// One line: tests per pixel by kind, lights tested and kept.
    pub fn line(&self) -> String {
        format!(
            "{:.1} culling tests/px ({:.2} groups, {:.1} clusters, {:.1} spheres), {:.1} lights tested, {:.1} kept",
            self.culling_tests(),
            self.group_tests,
            self.cluster_tests,
            self.sphere_tests,
            self.tested,
            self.kept
        )
    }
}
