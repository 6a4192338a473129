//! `slc bench`'s flags and its progress bar.

use crate::scene_args::SceneArgs;
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use slc_scene::pt::PtMethod;
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
    /// Path tracing: the SLC error bound ε, `auto` or `auto:C` [default:
    /// auto: set from each scene so that a shading point expects a fixed
    /// number of candidate lights, or C of them; `slc_scene::error_bound`].
    #[arg(long, value_parser = crate::methods::bound_arg)]
    pub error_bound: Option<slc_scene::error_bound::BoundArg>,
    /// Path tracing: seconds per method (equal time).
    #[arg(long, default_value_t = 10.0)]
    pub seconds: f64,
    /// Path tracing: where each method's error comes from. `reference`: its
    /// RMSE against a CPU reference of `--reference-spp` samples, the
    /// reference's own noise taken out. `seeds`: no reference (any
    /// resolution, any backend): each method renders twice, seeds `--seed`
    /// and `--seed + 1`, pass for pass, and its noise is σ = RMSE(one,
    /// other)/√2, the RMSE of one render against the exact image (every
    /// method is unbiased: the tests check it).
    #[arg(long, value_enum, default_value_t = Noise::Reference)]
    pub noise: Noise,
    /// Path tracing, `--noise seeds`: independent seed pairs per method
    /// (seeds `--seed + 2k` and `+ 2k + 1`), each rendering the passes the
    /// first pair reached in `--seconds`; σ² is their mean, and with two or
    /// more its standard error comes from their spread (the table's `±`;
    /// the suite also gives its median's interval). One pair's σ can be off
    /// by 2× or more where rare bright paths (point lights near surfaces)
    /// decide the error: docs/results/pt-noise-from-seeds.md.
    #[arg(long, default_value_t = 1)]
    pub pairs: u32,
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
    /// `--backend gpu`: seconds of continuous frames before each
    /// configuration's timed frames, so the GPU's clock rises and settles.
    #[arg(long, default_value_t = 0.5)]
    pub warmup: f64,
    /// `--backend gpu`: frames timed back to back per configuration, in
    /// one submission (each stage's median and spread over them).
    #[arg(long, default_value_t = 32)]
    pub timed_frames: u32,
    /// CPU: run the hot loops on this instruction set instead of the best
    /// one the CPU has (avx512, avx2 or baseline), to measure a lower one.
    #[arg(long, value_parser = simd_path)]
    pub simd: Option<slc_cpu::simd::SimdPath>,
}

/// `--noise`: against a reference, or from pairs of seeds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Noise {
    /// RMSE against a CPU reference, its own noise taken out.
    Reference,
    /// σ from two renders with different seeds: RMSE(one, other)/√2.
    Seeds,
}

/// `--simd`'s value: a [`slc_cpu::simd::SimdPath`] by its name.
fn simd_path(name: &str) -> Result<slc_cpu::simd::SimdPath, String> {
    slc_cpu::simd::SimdPath::from_name(name)
        .ok_or_else(|| format!("{name}: one of avx512, avx2, baseline"))
}

/// A progress bar of `len + 1` steps (the reference is the first).
pub fn progress(len: usize) -> anyhow::Result<ProgressBar> {
    let bar = ProgressBar::new(len as u64 + 1);
    bar.set_style(ProgressStyle::with_template(
        "{spinner} [{bar:30}] {pos}/{len} {msg} ({elapsed})",
    )?);
    Ok(bar)
}
