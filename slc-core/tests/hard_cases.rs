//! Hard numerical cases, each against an f64 evaluation of the same
//! formula. (Others live beside the code: ξ = largest f32 below 1 and
//! f32::MAX intensity in `range`, reservoir counts near u32::MAX in
//! `reservoir`, degenerate triangles in `sphere` and `light`, 65,536- and
//! 1M-light sums in `properties`, IES tables in `ies`.)

#[macro_use]
mod common;

use slc_core::glam::Vec3;
use slc_core::light::{Light, PointLight, inverse_square};
use slc_core::range::{
    RangeParams, Xi, random_range2, rr_probability, slc_keep, slc_weight, threshold_range2,
};

const TWO_PI: f64 = std::f64::consts::TAU;

#[test]
fn threshold_range_at_f32_max_intensity() {
    for (e, eps) in [(1.0f32, 1.0f32), (1.0, 10.0), (0.5, 1e6)] {
        let rt2 = threshold_range2(f32::MAX, e, eps);
        let r64 = e as f64 * f32::MAX as f64 / (TWO_PI * eps as f64);
        if r64 > f32::MAX as f64 {
            assert_eq!(rt2, f32::INFINITY);
        } else {
            assert_approx_eq!(rt2, r64, r64 * 4.0 * f32::EPSILON as f64);
        }
    }
}

#[test]
fn denormal_intensity() {
    // 1e-40 is subnormal: the range is tiny but exact to the subnormal ulp.
    let i = 1e-40f32;
    assert!(i > 0.0 && i < f32::MIN_POSITIVE);
    let rt2 = threshold_range2(i, 1.0, 1e-3);
    let r64 = i as f64 / (TWO_PI * 1e-3f32 as f64);
    assert_approx_eq!(rt2, r64, r64 * 8.0 * f32::EPSILON as f64 + f32::from_bits(1) as f64);
    let r2 = random_range2(rt2, 0.5);
    assert!(r2 > 0.0 && r2.is_finite());
    assert!(slc_keep(r2, 0.0));
    assert!(!slc_keep(r2, 1e-30));
    // A subnormal intensity still gives a zero-free, finite weight.
    assert_eq!(slc_weight(rt2, 0.0), 1.0);
}

#[test]
fn distance_below_min_positive() {
    for d2 in [f32::MIN_POSITIVE / 2.0, f32::from_bits(1), 0.0] {
        for rt2 in [f32::from_bits(1), 1e-40, 1e-3, 1.0] {
            let p = rr_probability(rt2, d2);
            let p64 = (rt2 as f64 / d2 as f64).min(1.0);
            assert!(
                p == 1.0 || (p as f64 - p64).abs() <= 1e-6 * p64 + 1e-45,
                "rt2 {rt2} d2 {d2}: {p} vs {p64}"
            );
            let w = slc_weight(rt2, d2);
            assert!(w.is_finite() && w >= 1.0);
        }
    }
    // The 1/d² fall-off is capped, never infinite.
    assert!(inverse_square(f32::from_bits(1)).is_finite());
}

#[test]
fn largest_xi_below_one_against_f64() {
    let xi = Xi::MAX.get();
    for rt2 in [1e-30f32, 1e-3, 1.0, 1e30] {
        let r2 = random_range2(rt2, xi);
        let r64 = rt2 as f64 / (1.0 - xi as f64);
        if r64 > f32::MAX as f64 {
            assert_eq!(r2, f32::INFINITY);
        } else {
            assert_approx_eq!(r2, r64, r64 * f32::EPSILON as f64);
        }
    }
}

/// Scenes 1e5 from the origin: f32 positions there are quantised to
/// ulp(1e5) = 2⁻⁷ ≈ 7.8 mm, so a squared distance of lights d apart carries
/// an absolute error up to about 2·√3·d·ulp. slc keeps that precision (the
/// keep test and weight are exact functions of the f32 d²); renderers that
/// need better should pass camera-relative positions.
#[test]
fn far_from_origin_precision_is_as_documented() {
    let ulp = 1e5f32.next_up() - 1e5f32;
    assert_eq!(ulp, 2f32.powi(-7));
    let params = RangeParams::new(0.01, 1.0).unwrap();
    for k in 0..50 {
        let off =
            Vec3::splat(1e5) + Vec3::new(0.137 * k as f32, -0.071 * k as f32, 0.013 * k as f32);
        let light = Light::Point(PointLight::new(off, Vec3::splat(2.0)).unwrap());
        let x = off + Vec3::new(0.9, 0.3 - 0.01 * k as f32, 0.5);
        let (_, d2) = light.contribution_at(x);
        let d64 = (x.as_dvec3() - off.as_dvec3()).length_squared();
        let bound = 2.0 * 3f64.sqrt() * d64.sqrt() * ulp as f64 + ulp as f64 * ulp as f64;
        assert!((d2 as f64 - d64).abs() <= bound, "d2 {d2} vs {d64} (bound {bound})");
        let rt2 = params.threshold_range2(light.peak());
        let p = rr_probability(rt2, d2) as f64;
        assert!((p - (rt2 as f64 / d64).min(1.0)).abs() <= bound / d64 + 1e-6);
    }
}
