//! Estimators at one shading point over a set of lights: stochastic light
//! culling, clamped ranges (the biased baseline) and the unculled sum.
//! Generic over the light's contribution so both backends and the tests
//! share them.
//!
//! SLC (docs/architecture.md §1.1; talk code `SlcImpl`):
//! `L̂ = Σᵢ [d²ᵢ < r²ᵢ] · fᵢ / p(dᵢ)`, `r²ᵢ = r_t,ᵢ²/(1 − ξᵢ)`,
//! `p = min(r_t²/d², 1)`; `E_ξ[L̂] = Σᵢ fᵢ`.
//! Clamped: `Σᵢ [d²ᵢ < R²ᵢ] · fᵢ` (no reweighting; biased low).
//!
//! Sums are compensated (Neumaier), so 65,536- and 1M-light sums keep about
//! f32 precision of the total instead of losing `log₂ n` bits.

use crate::range::{slc_keep, slc_weight};
use glam::Vec3;

/// One light as seen from one shading point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seen {
    /// Squared distance from the light (or its sampled point) to the point.
    pub d2: f32,
    /// Squared threshold range `r_t²`.
    pub rt2: f32,
    /// Squared random range `r² = r_t²/(1 − ξ)`.
    pub r2: f32,
}

/// A sum at one point and how many light contributions it evaluated.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Estimate {
    /// The estimate (RGB).
    pub value: Vec3,
    /// Lights whose contribution was evaluated.
    pub evaluated: u32,
}

/// Neumaier-compensated RGB sum.
#[derive(Clone, Copy, Debug, Default)]
pub struct CompensatedSum {
    sum: Vec3,
    comp: Vec3,
}

impl CompensatedSum {
    /// Adds `x`. Once a channel overflows to ±∞ its compensation stops
    /// (`∞ − ∞` would make it NaN), so an overflowing sum is ±∞, never NaN.
    #[inline]
    pub fn add(&mut self, x: Vec3) {
        let t = self.sum + x;
        let big = self.sum.abs().cmpge(x.abs());
        let c = Vec3::select(big, (self.sum - t) + x, (x - t) + self.sum);
        self.comp += Vec3::select(t.is_finite_mask(), c, Vec3::ZERO);
        self.sum = t;
    }
    /// The compensated total.
    #[inline]
    pub fn total(&self) -> Vec3 {
        self.sum + self.comp
    }
}

/// SLC estimate: evaluates `contribution` only for lights that survive the
/// roulette and weights them by `1/p`.
pub fn slc_sum<L>(
    lights: impl IntoIterator<Item = L>,
    seen: impl Fn(&L) -> Seen,
    contribution: impl Fn(&L) -> Vec3,
) -> Estimate {
    let mut sum = CompensatedSum::default();
    let mut evaluated = 0;
    for l in lights {
        let s = seen(&l);
        if slc_keep(s.r2, s.d2) {
            sum.add(contribution(&l) * slc_weight(s.rt2, s.d2));
            evaluated += 1;
        }
    }
    Estimate { value: sum.total(), evaluated }
}

/// Clamped-range estimate: lights with `d² < range²` count at full weight,
/// the rest are dropped. `d2_range2` gives `(d², range²)` per light.
pub fn clamped_sum<L>(
    lights: impl IntoIterator<Item = L>,
    d2_range2: impl Fn(&L) -> (f32, f32),
    contribution: impl Fn(&L) -> Vec3,
) -> Estimate {
    let mut sum = CompensatedSum::default();
    let mut evaluated = 0;
    for l in lights {
        let (d2, range2) = d2_range2(&l);
        if crate::range::clamp_keep(range2, d2) {
            sum.add(contribution(&l));
            evaluated += 1;
        }
    }
    Estimate { value: sum.total(), evaluated }
}

/// The unculled sum `Σᵢ fᵢ` (the ground truth SLC is unbiased for).
pub fn unculled_sum<L>(
    lights: impl IntoIterator<Item = L>,
    contribution: impl Fn(&L) -> Vec3,
) -> Estimate {
    let mut sum = CompensatedSum::default();
    let mut evaluated = 0;
    for l in lights {
        sum.add(contribution(&l));
        evaluated += 1;
    }
    Estimate { value: sum.total(), evaluated }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slc_hand_example() {
        // Two lights: one inside r_t (p = 1), one at d² = 4 r_t² (p = 1/4).
        let seen = [Seen { d2: 1.0, rt2: 2.0, r2: 4.0 }, Seen { d2: 8.0, rt2: 2.0, r2: 10.0 }];
        let e = slc_sum(seen.iter(), |s| **s, |_| Vec3::ONE);
        assert_eq!(e.evaluated, 2);
        assert_eq!(e.value, Vec3::splat(1.0 + 4.0));
        let seen = [Seen { d2: 8.0, rt2: 2.0, r2: 7.9 }];
        assert_eq!(slc_sum(seen.iter(), |s| **s, |_| Vec3::ONE), Estimate::default());
    }

    #[test]
    fn overflowing_sum_is_infinite_not_nan() {
        // Regression (fuzz/range_math): an infinite term made the
        // compensation ∞ − ∞ = NaN.
        let mut s = CompensatedSum::default();
        s.add(Vec3::new(1.0, f32::INFINITY, f32::MAX));
        s.add(Vec3::new(2.0, 1.0, f32::MAX));
        let t = s.total();
        assert_eq!(t, Vec3::new(3.0, f32::INFINITY, f32::INFINITY));
    }

    #[test]
    fn compensated_sum_of_many_small_terms() {
        // 1 + 2^20 · 2^-24 = 1.0625 exactly; a naive f32 sum stays at 1.0.
        let mut s = CompensatedSum::default();
        s.add(Vec3::ONE);
        for _ in 0..(1 << 20) {
            s.add(Vec3::splat(2f32.powi(-24)));
        }
        assert_eq!(s.total(), Vec3::splat(1.0625));
    }
}
