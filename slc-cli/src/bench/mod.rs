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

/// Runs `slc bench` with `a`: checks the flags, then the study they ask for.
pub fn run(a: BenchArgs) -> anyhow::Result<()> {
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
        if a.suite.is_some() {
            return Err(anyhow!("--suite: only the path tracers' bench (--app pt) runs a suite"));
        }
        if a.pairs != 1 {
            return Err(anyhow!(
                "--pairs: only the path tracers' bench (--app pt) renders seed pairs"
            ));
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
