//! Range math and the SLC estimator on arbitrary f32 bit patterns: inputs
//! the constructors accept never produce NaN; ranges may be +∞ (never
//! culled), but probabilities stay in [0, 1] and the weight of a kept light
//! is finite and in [1, 2²⁴].
#![no_main]

use arbitrary::Arbitrary;
use glam::Vec3;
use libfuzzer_sys::fuzz_target;
use slc_core::estimator::{Seen, slc_sum};
use slc_core::light::{Light, PointLight};
use slc_core::range::{RangeParams, Xi, random_range2, rr_probability, slc_keep, slc_weight};

#[derive(Arbitrary, Debug)]
struct Input {
    eps: u32,
    exposure: u32,
    lights: Vec<([u32; 3], [u32; 3], u32)>,
    x: [u32; 3],
}

fuzz_target!(|input: Input| {
    let f = f32::from_bits;
    let Ok(params) = RangeParams::new(f(input.eps), f(input.exposure)) else { return };
    let x = Vec3::new(f(input.x[0]), f(input.x[1]), f(input.x[2]));
    if !x.is_finite() {
        return;
    }
    let mut lights = Vec::new();
    for &(p, i, xi) in input.lights.iter().take(64) {
        let (Ok(l), Ok(xi)) =
            (PointLight::new(Vec3::from(p.map(f)), Vec3::from(i.map(f))), Xi::new(f(xi)))
        else {
            continue;
        };
        let l = Light::Point(l);
        let rt2 = params.threshold_range2(l.peak());
        let r2 = random_range2(rt2, xi.get());
        assert!(!rt2.is_nan() && rt2 >= 0.0 && !r2.is_nan() && r2 >= rt2, "rt2 {rt2} r2 {r2}");
        let (contribution, d2) = l.contribution_at(x);
        assert!(!d2.is_nan() && !contribution.is_nan(), "d2 {d2} c {contribution}");
        let p = rr_probability(rt2, d2);
        assert!((0.0..=1.0).contains(&p), "p {p}");
        if slc_keep(r2, d2) {
            let w = slc_weight(rt2, d2);
            assert!(
                w.is_finite() && (1.0..=16_777_216.0).contains(&w),
                "w {w} (rt2 {rt2} d2 {d2})"
            );
        }
        lights.push((Seen { d2, rt2, r2 }, contribution));
    }
    let e = slc_sum(lights.iter(), |l| l.0, |l| l.1);
    assert!(!e.value.is_nan(), "estimate {e:?}");
});
