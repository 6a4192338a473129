//! The method flags `render`, `bench` and `view` share: method names and
//! the VPL settings built from flags, the scene file and the defaults.

use anyhow::anyhow;
use slc_scene::culling::{DEFAULT_CLAMP_RANGE, DEFAULT_ERROR_BOUND};
use slc_scene::error_bound::{BoundArg, TARGET_CANDIDATES, auto_error_bound};
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

/// Parses `--error-bound`: a number, `auto`, or `auto:C` ([`BoundArg`];
/// [`pt_error_bound`] checks C's range, as the range code checks ε, so bad
/// values get the same one-line error).
pub fn bound_arg(s: &str) -> anyhow::Result<BoundArg> {
    s.parse().map_err(anyhow::Error::msg)
}

/// The path tracer's ε and how it was set: the flag, else the scene file's
/// `[render] pt_error_bound`, else `auto`; a number as given, `auto`/`auto:C`
/// the automatic bound of `pts` (PtSettings' fixed default where no light
/// reaches a surface). The file's `error_bound` is the VPL frame's and is
/// not read here.
pub fn pt_error_bound(
    flag: Option<BoundArg>,
    file: Option<BoundArg>,
    pts: &PtScene,
    exposure: f32,
) -> anyhow::Result<(f32, String)> {
    let (bound, source, note) = match (flag, file) {
        (Some(b), _) => (b, "--error-bound", "given"),
        (None, Some(b)) => (b, "[render] pt_error_bound", "the scene file's"),
        (None, None) => (BoundArg::Auto(TARGET_CANDIDATES), "--error-bound", ""),
    };
    let target = match bound {
        BoundArg::Value(e) => return Ok((e, note.into())),
        BoundArg::Auto(c) => BoundArg::check_target(c).map_err(|e| anyhow!("{source} {e}"))?,
    };
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
