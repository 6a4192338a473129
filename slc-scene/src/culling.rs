//! How lights are culled: one vocabulary for the CPU frame, the GPU
//! passes, the command line and slc-bevy. Each variant carries its own
//! parameters, checked when it is made, so a `Culling` in hand is valid:
//! no caller pairs a method with a loose parameter, and none checks again.

use crate::RenderError;
use slc_core::range::{CullKind, RangeParams};

/// The error bound ε of stochastic culling unless a caller asks for
/// another: the VPL frame's mean RMSE against every VPL at every pixel
/// falls from 0.00102 (ε = 0.008, one frame's standard deviation 0.00018:
/// occasional far VPLs with large `1/p`) to 0.00079 (±0.00004) for about
/// 2 ms more shading at 512² (`docs/results/default-frame.md`).
pub const DEFAULT_ERROR_BOUND: f32 = 0.004;

/// The clamp range `R` of the clamped baseline unless a caller asks for
/// another (scene units: a tenth of the Cornell box).
pub const DEFAULT_CLAMP_RANGE: f32 = 0.1;

/// How lights are culled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Culling {
    /// Stochastic light culling (the paper): each light's range
    /// `r² = r_t²/(1 − ξ)` from the error bound ε and exposure `E`
    /// (`r_t² = E·I/(2π ε)`), a kept light weighted `1/p`. Unbiased; each
    /// light adds at most ε to a Lambertian pixel's standard deviation.
    Stochastic(RangeParams),
    /// Clamped ranges, the baseline engines ship: lights beyond `R` are
    /// dropped and none is reweighted, so the image darkens.
    Clamped(ClampRange),
    /// Every light everywhere (`r² = ∞`): the exact sum the culling
    /// estimates (for the VPL frame, still interleaved and denoised).
    None,
    /// The ground truth of the VPL frame: every VPL at every pixel, no
    /// interleaving, no near-field split, no denoise. The engine passes do
    /// not take it (the indirect pass's reference is a pass built with
    /// `interleaved: false` under [`Culling::None`]).
    Reference,
}

impl Default for Culling {
    /// Stochastic culling at [`DEFAULT_ERROR_BOUND`], exposure 1.
    fn default() -> Self {
        Culling::Stochastic(RangeParams::new(DEFAULT_ERROR_BOUND, 1.0).expect("valid defaults"))
    }
}

impl Culling {
    /// Stochastic culling with error bound ε and exposure `E` (both finite
    /// and positive).
    pub fn stochastic(error_bound: f32, exposure: f32) -> Result<Culling, RenderError> {
        RangeParams::new(error_bound, exposure)
            .map(Culling::Stochastic)
            .map_err(|e| RenderError::Setting(e.to_string()))
    }

    /// Clamped ranges at `R` (finite and positive).
    pub fn clamped(range: f32) -> Result<Culling, RenderError> {
        ClampRange::new(range).map(Culling::Clamped)
    }

    /// The culling named `name` (`slc`, `clamp`, `none`, `reference`), with
    /// the error bound and exposure of `slc` and the range of `clamp` (the
    /// others ignore them).
    pub fn named(
        name: &str,
        error_bound: f32,
        exposure: f32,
        range: f32,
    ) -> Result<Culling, RenderError> {
        match name {
            "slc" => Culling::stochastic(error_bound, exposure),
            "clamp" => Culling::clamped(range),
            "none" => Ok(Culling::None),
            "reference" => Ok(Culling::Reference),
            m => Err(RenderError::Setting(format!(
                "culling '{m}' is not one of slc, clamp, none, reference"
            ))),
        }
    }

    /// The name on the command line and in reports: `slc`, `clamp`,
    /// `none` or `reference`.
    pub fn name(&self) -> &'static str {
        match self {
            Culling::Reference => "reference",
            c => c.kind().name(),
        }
    }

    /// The keep test and weight it takes ([`CullKind`]); the reference
    /// culls nothing.
    pub fn kind(&self) -> CullKind {
        match self {
            Culling::Stochastic(_) => CullKind::Stochastic,
            Culling::Clamped(_) => CullKind::Clamped,
            Culling::None | Culling::Reference => CullKind::None,
        }
    }

    /// The stochastic parameters, when it is [`Culling::Stochastic`].
    pub fn range_params(&self) -> Option<RangeParams> {
        match self {
            Culling::Stochastic(p) => Some(*p),
            _ => None,
        }
    }

    /// The error bound ε of stochastic culling (`None` for the others).
    pub fn error_bound(&self) -> Option<f32> {
        self.range_params().map(|p| p.error_bound())
    }

    /// The same culling with error bound `error_bound` where it is
    /// stochastic (the others are returned unchanged).
    pub fn with_error_bound(self, error_bound: f32) -> Result<Culling, RenderError> {
        match self {
            Culling::Stochastic(p) => {
                Culling::stochastic(error_bound, p.exposure()).map(|c| match c {
                    Culling::Stochastic(q) => Culling::Stochastic(q.with_measure(p.measure())),
                    c => c,
                })
            }
            c => Ok(c),
        }
    }

    /// The squared range of a light that the culling gives every light
    /// alike: `R²` when clamped, `+∞` without culling; `None` when it is
    /// stochastic (each light's own `r²`).
    pub fn fixed_range2(&self) -> Option<f32> {
        match self {
            Culling::Stochastic(_) => None,
            Culling::Clamped(r) => Some(r.get() * r.get()),
            Culling::None | Culling::Reference => Some(f32::INFINITY),
        }
    }
}

/// A clamped range `R`: finite and positive (checked when made).
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct ClampRange(f32);

impl ClampRange {
    /// The range `R` (scene units), or a typed error when it is not finite
    /// and positive.
    pub fn new(range: f32) -> Result<ClampRange, RenderError> {
        if range.is_finite() && range > 0.0 {
            Ok(ClampRange(range))
        } else {
            Err(RenderError::Setting(format!("clamp range {range} must be finite and > 0")))
        }
    }

    /// `R`.
    pub fn get(self) -> f32 {
        self.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn variants_check_their_parameters_once() {
        for bad in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            assert!(Culling::stochastic(bad, 1.0).is_err());
            assert!(Culling::stochastic(0.01, bad).is_err());
            assert!(Culling::clamped(bad).is_err());
        }
        let c = Culling::named("slc", 0.02, 2.0, f32::NAN).unwrap();
        assert_eq!(
            (c.name(), c.kind(), c.error_bound()),
            ("slc", CullKind::Stochastic, Some(0.02))
        );
        assert_eq!(c.fixed_range2(), None);
        let c = Culling::named("clamp", f32::NAN, f32::NAN, 0.5).unwrap();
        assert_eq!((c.name(), c.fixed_range2()), ("clamp", Some(0.25)));
        assert_eq!(
            Culling::named("none", 0.0, 0.0, 0.0).unwrap().fixed_range2(),
            Some(f32::INFINITY)
        );
        assert_eq!(Culling::Reference.kind(), CullKind::None);
        assert!(Culling::named("laser", 0.01, 1.0, 1.0).is_err());
        assert_eq!(Culling::default().error_bound(), Some(DEFAULT_ERROR_BOUND));
        let halved = Culling::default().with_error_bound(0.002).unwrap();
        assert_eq!(halved.error_bound(), Some(0.002));
        assert_eq!(Culling::None.with_error_bound(0.002).unwrap(), Culling::None);
    }
}
