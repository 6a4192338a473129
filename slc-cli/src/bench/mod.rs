//! `slc bench`: speed against error. Runs `none`, `slc` over a sweep of
//! error bounds and `clamp` over a sweep of ranges, measures RMSE of each
//! against the (cached) reference, and writes JSON (and optionally CSV).
//!
//! | module | holds |
//! |---|---|
//! | `args` | the command's flags and its progress bar |
//! | `measure` | fastest-of-N timing and one frame's RMSE spread |
//! | `vpl` | the VPL frame's bench, CPU and GPU |
//! | `pt` | path tracing at equal time |
//! | `suite` | the scene suite (`--suite DIR`) |
//! | `flicker` | temporal stability (`--flicker`) |

mod args;
mod flicker;
mod measure;
mod pt;
mod suite;
mod vpl;

use crate::backends::Backend;
use crate::scene_args::App;
use anyhow::anyhow;
pub use args::BenchArgs;

/// The bench flags only the path tracers' bench reads (`--suite` has its
/// own message), by their clap ids.
const PT_ONLY: [&str; 6] =
    ["seconds", "error_bound", "noise", "pairs", "reference_spp", "reference_method"];

/// The bench flags only the VPL frame's bench reads.
const VPL_ONLY: [&str; 8] =
    ["error_bounds", "ranges", "repeat", "flicker", "frames", "warmup", "timed_frames", "simd"];

/// The first of `ids` given on the command line (not defaulted), as its
/// flag: `--error-bounds` for `error_bounds`.
fn given_flag(given: &clap::ArgMatches, ids: &[&str]) -> Option<String> {
    ids.iter()
        .find(|id| given.value_source(id) == Some(clap::parser::ValueSource::CommandLine))
        .map(|id| format!("--{}", id.replace('_', "-")))
}

/// Runs `slc bench` with `a` (`given`: its matches, which say which flags
/// the command line gave): checks the flags, then the study they ask for.
/// A flag the chosen study would ignore is refused.
pub fn run(a: BenchArgs, given: &clap::ArgMatches) -> anyhow::Result<()> {
    let (app, gpu) = (a.scene.app, a.scene.backend == Backend::Gpu);
    if let Some(flag) = given_flag(given, if app == App::Pt { &VPL_ONLY } else { &PT_ONLY }) {
        return Err(match app {
            App::Pt => anyhow!("{flag}: only the VPL frame's bench (--app vpl) takes it"),
            _ => anyhow!("{flag}: only the path tracers' bench (--app pt) takes it"),
        });
    }
    if let Some(flag) = given_flag(given, &["warmup", "timed_frames"]).filter(|_| !gpu) {
        return Err(anyhow!("{flag}: only the GPU bench (--backend gpu) takes it"));
    }
    if let Some(flag) = given_flag(given, &["frames"]).filter(|_| !a.flicker) {
        return Err(anyhow!("{flag}: only the flicker study (--flicker) takes it"));
    }
    if a.repeat == 0 {
        return Err(anyhow!("--repeat 0 must be at least 1"));
    }
    if a.reference_spp == 0 {
        return Err(anyhow!("--reference-spp 0 must be at least 1"));
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
    // The report's files: a bad path fails now, not after the bench.
    for (flag, path) in [("--json", &a.json), ("--csv", &a.csv)] {
        if let Some(path) = path {
            crate::output_folder(flag, path)?;
        }
    }
    if let Some(path) = &a.plot {
        crate::plot::check_path("--plot", path)?;
    }
    if a.scene.app != App::Pt {
        a.scene.pt_only_flags()?;
        a.scene.backend_flags()?;
        if a.suite.is_some() {
            return Err(anyhow!("--suite: only the path tracers' bench (--app pt) runs a suite"));
        }
    } else {
        a.scene.vpl_only_flags()?;
    }
    if a.flicker {
        if a.scene.app == App::Pt {
            return Err(anyhow!("--flicker measures the VPL frame (--app vpl)"));
        }
        return flicker::run(&a, a.frames);
    }
    if a.scene.app == App::Pt {
        if !(a.seconds > 0.0 && a.seconds.is_finite()) {
            return Err(anyhow!("--seconds {} must be finite and > 0", a.seconds));
        }
        if !(1..=1024).contains(&a.pairs) {
            return Err(anyhow!("--pairs {}: from 1 to 1024 seed pairs", a.pairs));
        }
        if a.pairs > 1 && a.noise != args::Noise::Seeds {
            return Err(anyhow!(
                "--pairs {}: seed pairs are the noise of --noise seeds (the reference mode renders one run per method)",
                a.pairs
            ));
        }
        return match &a.suite {
            Some(dir) => suite::run(&a, dir),
            None => pt::run(a),
        };
    }
    if a.scene.backend == Backend::Gpu {
        return vpl::run_gpu(a);
    }
    vpl::run_cpu(a)
}
