//! The method flags `render`, `bench` and `view` share: method names and
//! the VPL settings built from flags, the scene file and the defaults.

use anyhow::anyhow;
use slc_scene::culling::{DEFAULT_CLAMP_RANGE, DEFAULT_ERROR_BOUND};
use slc_scene::error_bound::{TARGET_CANDIDATES, auto_error_bound};
use slc_scene::pt::{PtMethod, PtScene, PtSettings};
use slc_scene::vpl::{Culling, VplSettings};

/// A path-tracing method name.
pub fn pt_method(name: &str) -> anyhow::Result<PtMethod> {
    PtMethod::ALL.into_iter().find(|m| m.name() == name).ok_or_else(|| {
        let names: Vec<&str> = PtMethod::ALL.iter().map(|m| m.name()).collect();
        anyhow!("method '{name}' is not one of {} (--app pt)", names.join(", "))
    })
}

/// The flags that choose a VPL method and its parameters (`render` and `view`).
pub struct MethodFlags<'a> {
    pub method: Option<&'a str>,
    pub error_bound: Option<BoundArg>,
    pub range: Option<f32>,
    pub seed: Option<u32>,
    pub no_denoise: bool,
    pub tile: u32,
    pub near_radius: Option<f32>,
}

/// The VPL settings of a run: flags, else the scene file's, else the defaults.
pub fn vpl_settings(
    m: &MethodFlags,
    f: &slc_scene::scene_file::RenderSettings,
    exposure: f32,
) -> anyhow::Result<VplSettings> {
    let d = VplSettings::default();
    let error_bound = match m.error_bound {
        Some(BoundArg::Value(e)) => e,
        Some(BoundArg::Auto(_)) => {
            return Err(anyhow!(
                "--error-bound auto applies to path tracing (--app pt); give the VPL application a number"
            ));
        }
        None => f.error_bound.unwrap_or(DEFAULT_ERROR_BOUND),
    };
    let name = m.method.or(f.method.as_deref()).unwrap_or("slc");
    let range = m.range.or(f.range).unwrap_or(DEFAULT_CLAMP_RANGE);
    Ok(VplSettings {
        culling: Culling::named(name, error_bound, exposure, range)
            .map_err(|e| anyhow!("{e} (--app vpl)"))?,
        seed: m.seed.or(f.seed).unwrap_or(d.seed),
        denoise: !m.no_denoise,
        tile: m.tile,
        near_radius: m.near_radius,
        ..d
    })
}

/// `--error-bound`: a number, or `auto` / `auto:C` (path tracing: the ε
/// whose expected SLC candidates per shading point are `C`, by default
/// [`TARGET_CANDIDATES`]; `slc_scene::error_bound`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BoundArg {
    /// Set from the scene for this many expected candidates per point.
    Auto(f64),
    /// This ε.
    Value(f32),
}

/// Most expected candidates per point `auto:C` takes: every candidate
/// costs a walk step and a weight, so more than this is no bound at all.
pub const MAX_TARGET_CANDIDATES: f64 = 1e4;

/// Parses `--error-bound`: a number, `auto`, or `auto:C` (a number C;
/// [`pt_error_bound`] checks its range, as the range code checks ε, so bad
/// values get the same one-line error).
pub fn bound_arg(s: &str) -> anyhow::Result<BoundArg> {
    if s == "auto" {
        return Ok(BoundArg::Auto(TARGET_CANDIDATES));
    }
    if let Some(c) = s.strip_prefix("auto:") {
        return c
            .parse::<f64>()
            .map(BoundArg::Auto)
            .map_err(|_| anyhow!("'{c}' in '{s}' is not a number of candidates"));
    }
    s.parse::<f32>()
        .map(BoundArg::Value)
        .map_err(|_| anyhow!("'{s}' is neither a number, auto nor auto:C"))
}

/// The path tracer's ε and how it was set: the flag's number, else the
/// scene file's, else (or with `auto`/`auto:C`) the automatic bound of `pts`
/// (PtSettings' fixed default where no light reaches a surface).
pub fn pt_error_bound(
    flag: Option<BoundArg>,
    file: Option<f32>,
    pts: &PtScene,
    exposure: f32,
) -> anyhow::Result<(f32, String)> {
    let target = match (flag, file) {
        (Some(BoundArg::Value(e)), _) => return Ok((e, "given".into())),
        (None, Some(e)) => return Ok((e, "the scene file's".into())),
        (Some(BoundArg::Auto(c)), _) => c,
        (None, None) => TARGET_CANDIDATES,
    };
    if !(target > 0.0 && target <= MAX_TARGET_CANDIDATES) {
        return Err(anyhow!(
            "--error-bound auto:{target}: the expected candidates per point must be in (0, {MAX_TARGET_CANDIDATES}]"
        ));
    }
    Ok(match auto_error_bound(pts, exposure, target) {
        Some(e) => (e, format!("automatic: {target} expected candidates per surface point")),
        None => (
            PtSettings::default().error_bound,
            "the fixed default: no light reaches a surface to set it from".into(),
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn error_bound_flag_parses_numbers_auto_and_candidate_targets() {
        assert_eq!(bound_arg("0.25").unwrap(), BoundArg::Value(0.25));
        assert_eq!(bound_arg("auto").unwrap(), BoundArg::Auto(TARGET_CANDIDATES));
        assert_eq!(bound_arg("auto:3").unwrap(), BoundArg::Auto(3.0));
        for bad in ["auto:", "auto:x", "automatic", "x"] {
            assert!(bound_arg(bad).is_err(), "{bad} was accepted");
        }
    }
}
