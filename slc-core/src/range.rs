//! Russian-roulette light ranges: the heart of stochastic light culling.
//!
//! Notation (docs/architecture.md §1.1, talk slides "Russian roulette", "Random influence
//! range", "Error bound-based light range"): `d2` squared distance from the
//! light to the shading point, `rt2` the squared *threshold* range, `r2` the
//! squared *random* range, `xi` the light's random number in `[0, 1)`.
//!
//! - RR probability `p(d) = min(r_t²/d², 1)` for fall-off `1/d²`.
//! - Random range `r² = r_t² / (1 − ξ)`; the light is kept iff `d² < r²`,
//!   which for uniform ξ happens with probability exactly `p(d)`.
//! - A kept light's contribution is multiplied by `1/p(d)`.
//!
//! Threshold range from an error bound ε on the standard deviation one light
//! may add to a pixel channel, with exposure `E` (Lambertian receiver,
//! `ρ ≤ 1/π`): `r_t² = E · I_max / (2π ε)`. Derivation: the RR variance of one
//! light is `(1/p − 1) f²` with `f = c/d²`, `c = E·I_max/π`; its maximum over
//! `d` is `(c / (2 r_t²))²`, so the standard deviation stays `≤ ε`.
//! The talk's code uses `r_t² = lum(I) / (π α)` with `lum` the channel average:
//! that is the same formula with `α = 2ε/E` and the average in place of the
//! max ([`IntensityMeasure::ChannelAverage`], [`RangeParams::from_alpha`]).
//!
//! **On a glossy receiver** ([`crate::brdf`]) the same derivation with `c =
//! E·I_max·P`, `P` the receiver's `f·cos` toward the light, gives a largest
//! deviation of `π·P·ε`: ε bounds the deviation one light adds to a *white
//! Lambertian* receiver (`P ≤ 1/π`), and a receiver whose `f·cos` peaks at
//! `P` gets up to `π·P` times that — `F/(4α²)` on a GGX metal's mirror
//! direction at normal view (156× at roughness 0.2, 4× at 0.5). slc keeps
//! the range receiver-independent (one sphere per light, so tile, cluster
//! and tree culling work unchanged and the estimate stays unbiased) and
//! keeps this meaning of ε; a renderer that needs the bound on its glossiest
//! surface divides ε by `π·P_max` there, at the cost of culling. The tests
//! check `max σ = π·P·ε` through the roulette itself
//! (`brdf::tests::slc_deviation_on_a_glossy_receiver_is_pi_p_epsilon`);
//! `docs/results/glossy-error-bound.md` measures what it lets through in a
//! rendered image.
//!
//! Defined edge behaviour (tested):
//! - zero intensity ⇒ `r_t² = r² = 0` ⇒ never kept (`d² < 0` is false);
//! - `d² = 0` ⇒ `p = 1`, weight 1 (no `0/0`);
//! - `ξ` = largest `f32` below 1 ⇒ `1 − ξ = 2⁻²⁴` exactly, `r² = 2²⁴ r_t²`;
//! - huge intensity: `r_t²` or `r²` may round to `+∞`, which means "never
//!   culled" and gives `p = 1`, weight 1; a kept light's weight is always in
//!   `[1, 2²⁴]`, so no ∞ or NaN reaches a pixel from the range math;
//! - NaN, ∞ or negative inputs are rejected by the constructors below.

use crate::RangeError;
use crate::wgsl::*;
use glam::Vec3;

crate::shared! {
    /// 2π.
    pub const TWO_PI: f32 = 6.283185307179586;

    /// A squared range no point reaches past: given as both `r²` and
    /// `r_t²`, the keep test keeps every light and its `1/p` is 1 (a
    /// light's whole contribution, as resampling's reused targets weigh
    /// it).
    pub const UNRANGED: f32 = 1e38;

    /// Russian-roulette probability `p = min(r_t²/d², 1)`. Returns exactly 1
    /// when `d² ≤ r_t²` (so `d² = 0` never divides).
    pub fn rr_probability(rt2: f32, d2: f32) -> f32 {
        if d2 <= rt2 {
            return 1.0;
        }
        return rt2 / d2;
    }

    /// The `1/p` weight of a kept light: `max(d²/r_t², 1)`.
    pub fn slc_weight(rt2: f32, d2: f32) -> f32 {
        if d2 <= rt2 {
            return 1.0;
        }
        return d2 / rt2;
    }

    /// Random squared range `r² = r_t² / (1 − ξ)` for `ξ ∈ [0, 1)`.
    pub fn random_range2(rt2: f32, xi: f32) -> f32 {
        return rt2 / (1.0 - xi);
    }

    /// The keep test: the light survives the roulette at this point iff
    /// `d² < r²`. With `r² = r_t²/(1 − ξ)` and uniform ξ this happens with
    /// probability `p(d)`; zero ranges are never kept.
    pub fn slc_keep(r2: f32, d2: f32) -> bool {
        return d2 < r2;
    }

    /// The clamped-range test (the biased baseline, and the near field's
    /// radius): a light counts, at full weight, iff `d² < R²` for its fixed
    /// range `R`; a zero range counts nothing.
    pub fn clamp_keep(range2: f32, d2: f32) -> bool {
        return d2 < range2;
    }

    /// Threshold squared range `r_t² = E · I / (2π ε)` from a scalar peak
    /// intensity `I`, exposure `E` and error bound `ε`, evaluated as
    /// `(E/ε)·I/2π` so that no valid input makes `∞/∞` or `∞·0` (NaN) and
    /// subnormal intensities keep their precision: the result is 0 for
    /// `I = 0` and may be `+∞` ("never culled").
    pub fn threshold_range2(intensity: f32, exposure: f32, error_bound: f32) -> f32 {
        if intensity <= 0.0 {
            return 0.0;
        }
        return (exposure / error_bound) * intensity / TWO_PI;
    }

    /// Scalar measure of an RGB intensity: max channel (`mode` 0) or channel
    /// average (`mode` 1, the talk's `lum`).
    pub fn intensity_measure(rgb: vec3f, mode: u32) -> f32 {
        if mode == 1 {
            return (rgb.x + rgb.y + rgb.z) / 3.0;
        }
        return max(rgb.x, max(rgb.y, rgb.z));
    }

    /// `1 + 2⁻²⁰`: how much [`cull_radius`] rounds `√r²` up.
    pub const CULL_RADIUS_SCALE: f32 = 1.00000095367431640625;

    /// Radius of a light's culling sphere for squared range `r2`: `√r²`
    /// rounded up by 2⁻²⁰ relative, so that `d² < r²` implies `d ≤ radius`
    /// in f32 (tile culling never drops a light the per-point test keeps).
    pub fn cull_radius(r2: f32) -> f32 {
        return sqrt(r2) * CULL_RADIUS_SCALE;
    }

    /// Windowed fall-off of the clamped-range baseline used by Bevy and
    /// others: `saturate(1 − (d²/r²)²)² / max(d², 10⁻⁴)` (biased: it darkens).
    pub fn windowed_falloff(d2: f32, range2: f32) -> f32 {
        let q: f32 = d2 / range2;
        let w: f32 = saturate(1.0 - q * q);
        return w * w / max(d2, 0.0001);
    }
}

/// Which scalar of an RGB peak intensity sets the range.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum IntensityMeasure {
    /// `max(r, g, b)`: the bound `σ ≤ ε` holds for every channel (default).
    #[default]
    MaxChannel,
    /// `(r + g + b) / 3`: the talk's `lum`; the bound holds for the average.
    ChannelAverage,
}

impl IntensityMeasure {
    /// The `mode` argument of [`intensity_measure`].
    pub const fn mode(self) -> u32 {
        match self {
            Self::MaxChannel => 0,
            Self::ChannelAverage => 1,
        }
    }
}

/// Which keep test and weight a light takes, without their parameters:
/// the family a culling setting belongs to (slc-scene's `Culling` carries
/// the parameters). A kernel is specialised per kind, and the CPU's
/// shading loop is monomorphised per kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CullKind {
    /// Stochastic light culling: kept iff `d² < r²` ([`slc_keep`]),
    /// weighted `1/p` ([`slc_weight`]).
    Stochastic,
    /// A clamped range `R`: kept iff `d² < R²` ([`clamp_keep`]), weight 1
    /// (biased: the baseline engines ship).
    Clamped,
    /// Every light, weight 1.
    None,
}

impl CullKind {
    /// Every kind, in the order kernels and reports list them.
    pub const ALL: [CullKind; 3] = [CullKind::Stochastic, CullKind::Clamped, CullKind::None];

    /// The kind's name on the command line, in reports and in kernel
    /// variants: `slc`, `clamp`, `none`.
    pub fn name(self) -> &'static str {
        match self {
            CullKind::Stochastic => "slc",
            CullKind::Clamped => "clamp",
            CullKind::None => "none",
        }
    }
}

/// Settings that turn a light's peak intensity into its threshold range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RangeParams {
    exposure: f32,
    error_bound: f32,
    measure: IntensityMeasure,
}

impl RangeParams {
    /// Error bound `ε > 0` and exposure `E > 0`, both finite; max-channel
    /// measure.
    pub fn new(error_bound: f32, exposure: f32) -> Result<Self, RangeError> {
        if !(error_bound.is_finite() && error_bound > 0.0) {
            return Err(RangeError::ErrorBound(error_bound));
        }
        if !(exposure.is_finite() && exposure > 0.0) {
            return Err(RangeError::Exposure(exposure));
        }
        Ok(Self { exposure, error_bound, measure: IntensityMeasure::MaxChannel })
    }

    /// The talk's parameter α in `r_t² = lum(I)/(π α)`: channel average,
    /// `E = 1`, `ε = α/2`.
    pub fn from_alpha(alpha: f32) -> Result<Self, RangeError> {
        if !(alpha.is_finite() && alpha > 0.0) {
            return Err(RangeError::Alpha(alpha));
        }
        Ok(Self::new(alpha * 0.5, 1.0)?.with_measure(IntensityMeasure::ChannelAverage))
    }

    /// The same settings with another intensity measure.
    pub fn with_measure(self, measure: IntensityMeasure) -> Self {
        Self { measure, ..self }
    }

    /// Error bound ε.
    pub fn error_bound(&self) -> f32 {
        self.error_bound
    }
    /// Exposure E.
    pub fn exposure(&self) -> f32 {
        self.exposure
    }
    /// Intensity measure.
    pub fn measure(&self) -> IntensityMeasure {
        self.measure
    }

    /// `r_t²` of a light with RGB peak intensity `peak` (validated by the
    /// light's constructor: finite, non-negative). May be `+∞` for huge
    /// intensities, meaning "never culled".
    pub fn threshold_range2(&self, peak: Vec3) -> f32 {
        threshold_range2(
            intensity_measure(peak, self.measure.mode()),
            self.exposure,
            self.error_bound,
        )
    }
}

/// A light's random number for one frame or pass, `ξ ∈ [0, 1)`.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd, Default)]
pub struct Xi(f32);

impl Xi {
    /// Largest `f32` below 1.
    pub const MAX: Xi = Xi(1.0 - f32::EPSILON / 2.0);

    /// Checks `0 ≤ ξ < 1`.
    pub fn new(xi: f32) -> Result<Self, RangeError> {
        if (0.0..1.0).contains(&xi) { Ok(Self(xi)) } else { Err(RangeError::Xi(xi)) }
    }

    /// The value.
    pub fn get(self) -> f32 {
        self.0
    }
}

/// Squared random range of a light with threshold `rt2` and random number
/// `xi`: `r² = r_t²/(1 − ξ)` (see [`random_range2`]).
pub fn random_range2_of(rt2: f32, xi: Xi) -> f32 {
    random_range2(rt2, xi.get())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn probability_and_weight_hand_values() {
        assert_eq!(rr_probability(4.0, 16.0), 0.25);
        assert_eq!(slc_weight(4.0, 16.0), 4.0);
        assert_eq!(rr_probability(4.0, 1.0), 1.0);
        assert_eq!(slc_weight(4.0, 4.0), 1.0);
        assert_eq!(random_range2(2.0, 0.5), 4.0);
        assert_eq!(random_range2(2.0, 0.0), 2.0);
    }

    #[test]
    fn threshold_range_hand_value() {
        // E·I/(2πε) with E = 2, I = max(1, 3, 2) = 3, ε = 0.5: 6/π.
        let p = RangeParams::new(0.5, 2.0).unwrap();
        let rt2 = p.threshold_range2(Vec3::new(1.0, 3.0, 2.0));
        assert!((rt2 - 6.0 / core::f32::consts::PI).abs() < 1e-6);
        let avg = p
            .with_measure(IntensityMeasure::ChannelAverage)
            .threshold_range2(Vec3::new(1.0, 3.0, 2.0));
        assert!((avg - 4.0 / core::f32::consts::PI).abs() < 1e-6);
    }

    #[test]
    fn alpha_form_matches_talk() {
        // Talk: r_t² = lum(I)/(π α).
        let alpha = 0.02;
        let i = Vec3::new(0.3, 0.6, 0.9);
        let rt2 = RangeParams::from_alpha(alpha).unwrap().threshold_range2(i);
        let talk = ((i.x + i.y + i.z) / 3.0) / (core::f32::consts::PI * alpha);
        assert!((rt2 - talk).abs() <= 1e-5 * talk);
    }

    #[test]
    fn zero_intensity_is_never_kept() {
        let p = RangeParams::new(0.01, 1.0).unwrap();
        let rt2 = p.threshold_range2(Vec3::ZERO);
        assert_eq!(rt2, 0.0);
        for xi in [0.0, 0.5, Xi::MAX.get()] {
            let r2 = random_range2(rt2, xi);
            assert_eq!(r2, 0.0);
            assert!(!slc_keep(r2, 0.0));
            assert!(!slc_keep(r2, f32::MIN_POSITIVE));
        }
        // p and the weight stay finite even if someone evaluates them.
        assert_eq!(rr_probability(0.0, 0.0), 1.0);
        assert_eq!(slc_weight(0.0, 0.0), 1.0);
        assert_eq!(rr_probability(0.0, 1.0), 0.0);
    }

    #[test]
    fn zero_distance_has_probability_one() {
        for rt2 in [f32::MIN_POSITIVE, 1.0, f32::MAX, f32::INFINITY] {
            assert_eq!(rr_probability(rt2, 0.0), 1.0);
            assert_eq!(slc_weight(rt2, 0.0), 1.0);
            assert!(slc_keep(random_range2(rt2, 0.0), 0.0));
        }
    }

    #[test]
    fn largest_xi_below_one() {
        let xi = Xi::MAX.get();
        assert!(xi < 1.0);
        assert_eq!(1.0 - xi, f32::EPSILON / 2.0);
        assert_eq!(random_range2(1.0, xi), 16_777_216.0);
        // f64 reference of the same formula.
        let r64 = 3.5f64 / (1.0 - xi as f64);
        assert_eq!(random_range2(3.5, xi) as f64, r64);
        assert!(Xi::new(1.0).is_err());
        assert!(Xi::new(-0.0).is_ok());
        assert!(Xi::new(f32::NAN).is_err());
    }

    #[test]
    fn huge_intensity_never_leaks_inf_or_nan() {
        let p = RangeParams::new(1e-6, 1e3).unwrap();
        let rt2 = p.threshold_range2(Vec3::splat(f32::MAX));
        assert_eq!(rt2, f32::INFINITY);
        let r2 = random_range2(rt2, Xi::MAX.get());
        assert_eq!(r2, f32::INFINITY);
        for d2 in [0.0, 1.0, 1e30, f32::MAX] {
            assert!(slc_keep(r2, d2));
            assert_eq!(slc_weight(rt2, d2), 1.0);
            assert_eq!(rr_probability(rt2, d2), 1.0);
        }
        // Finite but enormous rt2: every kept light's weight is ≤ 2^24.
        let rt2 = f32::MAX / 4.0;
        let r2 = random_range2(rt2, Xi::MAX.get());
        assert_eq!(r2, f32::INFINITY);
        let w = slc_weight(rt2, f32::MAX);
        assert!(w.is_finite() && w <= 16_777_216.0);
    }

    #[test]
    fn kept_weight_is_bounded_by_one_over_one_minus_xi() {
        // For any kept light d² < r_t²/(1−ξ) ⇒ d²/r_t² < 1/(1−ξ) ≤ 2^24.
        for rt2 in [1e-45f32, 1e-30, 1.0, 1e30] {
            let r2 = random_range2(rt2, Xi::MAX.get());
            let d2 = r2 * 0.999_999;
            if slc_keep(r2, d2) {
                let w = slc_weight(rt2, d2);
                assert!(w.is_finite() && w <= 16_777_216.0, "rt2 {rt2} w {w}");
            }
        }
    }

    #[test]
    fn extreme_exposure_and_error_bound_give_no_nan() {
        // Regression (fuzz/range_math): E and ε near f32::MAX made E·I and
        // 2πε both overflow, and ∞/∞ = NaN.
        let big = f32::from_bits(2130649599);
        for (e, eps) in [(big, big), (big, 1e-30), (1e-30, big), (f32::MAX, f32::MAX)] {
            let p = RangeParams::new(eps, e).unwrap();
            for i in [0.0, 1e-40, 1.0, f32::MAX] {
                let rt2 = p.threshold_range2(Vec3::splat(i));
                assert!(!rt2.is_nan() && rt2 >= 0.0, "E {e} eps {eps} I {i}: {rt2}");
                assert_eq!(rt2 == 0.0, i == 0.0 || (e / eps) * i / TWO_PI == 0.0);
            }
        }
        let rt2 = threshold_range2(f32::MAX, f32::MAX, f32::MAX);
        let r64 = f32::MAX as f64 / core::f64::consts::TAU;
        assert!((rt2 as f64 - r64).abs() <= 1e-6 * r64);
    }

    #[test]
    fn constructors_reject_bad_input() {
        for bad in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            assert!(RangeParams::new(bad, 1.0).is_err());
            assert!(RangeParams::new(0.1, bad).is_err());
            assert!(RangeParams::from_alpha(bad).is_err());
        }
    }

    #[test]
    fn windowed_falloff_is_zero_outside_and_finite_at_zero() {
        assert_eq!(windowed_falloff(4.0, 4.0), 0.0);
        assert_eq!(windowed_falloff(9.0, 4.0), 0.0);
        assert!(windowed_falloff(0.0, 4.0).is_finite());
        assert!(windowed_falloff(1.0, 4.0) < 1.0);
    }
}
