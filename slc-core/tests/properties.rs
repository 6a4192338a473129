//! Property tests of slc-core: the roulette keeps with probability p, the SLC
//! estimator's expectation is the unculled sum, the BSH equals brute force,
//! spheres are minimal and conservative, reservoirs pick with the right
//! probabilities.

#[macro_use]
mod common;

use proptest::prelude::*;
use slc_core::bsh::Bsh;
use slc_core::estimator::{Seen, clamped_sum, slc_sum, unculled_sum};
use slc_core::glam::Vec3;
use slc_core::light::{Light, LightBound, PointLight, Vpl};
use slc_core::range::{RangeParams, random_range2, rr_probability, slc_keep};
use slc_core::reservoir::{Reservoir, WeightedReservoir};
use slc_core::sphere::{Aabb, Sphere};

/// Fixed case count and seed, so CI runs the same cases every time;
/// `SLC_PROPTEST_SEED=<u64>` explores other seeds locally.
fn cfg(cases: u32) -> ProptestConfig {
    let seed =
        std::env::var("SLC_PROPTEST_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(0x51C_2016);
    ProptestConfig {
        cases,
        failure_persistence: None,
        rng_seed: proptest::test_runner::RngSeed::Fixed(seed),
        ..ProptestConfig::default()
    }
}

/// Strata for the ξ quadrature.
const M: usize = 4096;

fn midpoint(j: usize) -> f32 {
    (j as f32 + 0.5) / M as f32
}

proptest! {
    #![proptest_config(cfg(256))]

    /// P(d² < r_t²/(1−ξ)) over uniform ξ equals p = min(r_t²/d², 1): the
    /// fraction of M stratum midpoints kept is within one stratum of p
    /// (the keep set is the interval ξ > 1 − p, so only one stratum can
    /// straddle its end; a second allows for f32 rounding at the edge).
    #[test]
    fn keep_probability_is_p(rt2 in 1e-6f32..1e6, ratio in 0.0f32..50.0) {
        let d2 = rt2 * ratio;
        let kept = (0..M).filter(|&j| slc_keep(random_range2(rt2, midpoint(j)), d2)).count();
        let p = rr_probability(rt2, d2);
        prop_assert!((kept as f32 / M as f32 - p).abs() <= 2.0 / M as f32, "kept {} p {}", kept, p);
    }
}

/// A random light: point or VPL, intensity from tiny to huge.
fn light_strategy() -> impl Strategy<Value = Light> {
    let pos = prop::array::uniform3(-10.0f32..10.0);
    let log_i = -6.0f32..6.0;
    let rgb = prop::array::uniform3(0.0f32..1.0);
    (pos, log_i, rgb, any::<bool>(), prop::array::uniform3(-1.0f32..1.0)).prop_map(
        |(p, li, c, vpl, n)| {
            let i = Vec3::from(c) * 10f32.powf(li);
            let p = Vec3::from(p);
            let n = Vec3::from(n);
            if vpl && n.length() > 0.1 {
                Light::Vpl(Vpl::new(p, n, i).unwrap())
            } else {
                Light::Point(PointLight::new(p, i).unwrap())
            }
        },
    )
}

proptest! {
    #![proptest_config(cfg(128))]

    /// E_ξ[SLC] = unculled sum, through the real estimator: the expectation
    /// over each light's own ξ is Σᵢ ∫ gᵢ(ξ) dξ, and because the estimator is
    /// a sum of per-light terms, evaluating it with every light's ξ set to the
    /// j-th stratum midpoint and averaging over j is the midpoint rule for
    /// every light at once. gᵢ is fᵢ/pᵢ on an interval ending at 1 and 0
    /// elsewhere, so the rule's error is at most fᵢ/(pᵢ M) per light (two
    /// strata allowed for rounding at the edge), plus f32 summation error.
    #[test]
    fn slc_expectation_equals_unculled_sum(
        lights in prop::collection::vec(light_strategy(), 1..24),
        x in prop::array::uniform3(-12.0f32..12.0),
        log_eps in -4.0f32..0.0,
    ) {
        let x = Vec3::from(x);
        let params = RangeParams::new(10f32.powf(log_eps), 1.0).unwrap();
        let rt2: Vec<f32> = lights.iter().map(|l| params.threshold_range2(l.peak())).collect();
        let f = |i: &usize| lights[*i].contribution_at(x).0;
        let d2 = |i: usize| lights[i].contribution_at(x).1;
        let truth = unculled_sum(0..lights.len(), f).value;
        let mut mean = Vec3::ZERO.as_dvec3();
        for j in 0..M {
            let xi = midpoint(j);
            let e = slc_sum(0..lights.len(), |&i| Seen { d2: d2(i), rt2: rt2[i], r2: random_range2(rt2[i], xi) }, f);
            mean += e.value.as_dvec3() / M as f64;
        }
        let mut tol = Vec3::ZERO.as_dvec3();
        for i in 0..lights.len() {
            let p = rr_probability(rt2[i], d2(i)) as f64;
            if p > 0.0 {
                tol += f(&i).as_dvec3() / p * (2.0 / M as f64);
            }
        }
        tol += truth.as_dvec3() * 1e-5;
        for c in 0..3 {
            prop_assert!((mean[c] - truth.as_dvec3()[c]).abs() <= tol[c],
                "channel {}: E[slc] {} vs sum {} (tol {})", c, mean[c], truth[c], tol[c]);
        }
    }
}

#[test]
fn clamped_ranges_darken() {
    // 1000 VPLs on a line; clamping each at its threshold range loses every
    // light beyond it, so the clamped sum is strictly below the true sum.
    let lights: Vec<Light> = (0..1000)
        .map(|i| {
            Light::Point(
                PointLight::new(Vec3::new(i as f32 * 0.1, 0.0, 0.0), Vec3::splat(0.01)).unwrap(),
            )
        })
        .collect();
    let params = RangeParams::new(0.01, 1.0).unwrap();
    let x = Vec3::new(0.0, 1.0, 0.0);
    let truth = unculled_sum(lights.iter(), |l| l.contribution_at(x).0).value;
    let clamp = clamped_sum(
        lights.iter(),
        |l| (l.contribution_at(x).1, params.threshold_range2(l.peak())),
        |l| l.contribution_at(x).0,
    );
    assert!(clamp.value.x < 0.95 * truth.x, "clamped {} vs {}", clamp.value.x, truth.x);
    assert!(clamp.evaluated < 1000);
}

/// Brute-force sets of lights whose sphere passes a test.
fn brute(spheres: &[Sphere], test: impl Fn(&Sphere) -> bool) -> Vec<u32> {
    (0..spheres.len() as u32).filter(|&i| test(&spheres[i as usize])).collect()
}

fn bounds_strategy() -> impl Strategy<Value = (Vec<LightBound>, Vec<f32>)> {
    let one = (prop::array::uniform3(-100.0f32..100.0), 0.0f32..5.0, -8.0f32..4.0, 0u8..20);
    prop_oneof![
        // General sets, radii from tiny to huge, a few infinite.
        prop::collection::vec(one, 0..300).prop_map(|v| {
            let b = v
                .iter()
                .map(|&(c, e, _, k)| LightBound {
                    center: Vec3::from(c),
                    extent: if k < 5 { 0.0 } else { e },
                })
                .collect();
            let r2 = v
                .iter()
                .map(|&(_, _, lr, k)| if k == 0 { f32::INFINITY } else { 10f32.powf(lr * 2.0) })
                .collect();
            (b, r2)
        }),
        // All lights at one point.
        (1usize..100, prop::array::uniform3(-5.0f32..5.0)).prop_map(|(n, c)| {
            (
                vec![LightBound { center: Vec3::from(c), extent: 0.0 }; n],
                (0..n).map(|i| i as f32 * 0.01).collect(),
            )
        }),
        // Far from the origin (1e5), small ranges.
        prop::collection::vec((prop::array::uniform3(-1.0f32..1.0), 0.0f32..0.5), 1..100).prop_map(
            |v| {
                let b = v
                    .iter()
                    .map(|&(c, _)| LightBound {
                        center: Vec3::splat(1e5) + Vec3::from(c),
                        extent: 0.0,
                    })
                    .collect();
                (b, v.iter().map(|&(_, r)| r * r).collect())
            }
        ),
    ]
}

proptest! {
    #![proptest_config(cfg(96))]

    /// BSH queries return exactly the brute-force sets.
    #[test]
    fn bsh_equals_brute_force(
        (bounds, r2) in bounds_strategy(),
        qs in prop::collection::vec((prop::array::uniform3(-120.0f32..120.0), -6.0f32..3.0, prop::array::uniform3(0.0f32..30.0)), 1..24),
    ) {
        let mut bsh = Bsh::build(&bounds).unwrap();
        bsh.refit(&r2).unwrap();
        let spheres: Vec<Sphere> = bounds.iter().zip(&r2).map(|(b, &r2)| b.range_sphere(r2)).collect();
        for i in 0..spheres.len() {
            prop_assert_eq!(bsh.light_sphere(i), Some(spheres[i]));
        }
        let far = bounds.first().map_or(Vec3::ZERO, |b| if b.center.x > 1e4 { Vec3::splat(1e5) } else { Vec3::ZERO });
        for (q, lr, ext) in qs {
            let x = far + Vec3::from(q) * if far.x > 0.0 { 0.01 } else { 1.0 };
            let mut got = Vec::new();
            bsh.for_each_containing(x, |i| got.push(i));
            got.sort_unstable();
            prop_assert_eq!(&got, &brute(&spheres, |s| s.contains(x)));

            let s = Sphere::new(x, 10f32.powf(lr));
            got.clear();
            bsh.for_each_overlapping_sphere(s, |i| got.push(i));
            got.sort_unstable();
            prop_assert_eq!(&got, &brute(&spheres, |t| t.overlaps_sphere(&s)));

            let b = Aabb { min: x, max: x + Vec3::from(ext) };
            got.clear();
            bsh.for_each_overlapping_aabb(b, |i| got.push(i));
            got.sort_unstable();
            prop_assert_eq!(&got, &brute(&spheres, |t| t.overlaps_aabb(&b)));
        }
    }

    /// Every point either sphere contains (tested in f32) the union contains,
    /// and the radius is the exact (d+r₁+r₂)/2 unless one contains the other.
    #[test]
    fn union_contains_and_is_tight(
        c1 in prop::array::uniform3(-50.0f32..50.0), r1 in 0.0f32..20.0,
        c2 in prop::array::uniform3(-50.0f32..50.0), r2 in 0.0f32..20.0,
        dirs in prop::collection::vec(prop::array::uniform3(-1.0f32..1.0), 8),
    ) {
        let (a, b) = (Sphere::new(Vec3::from(c1), r1), Sphere::new(Vec3::from(c2), r2));
        let u = a.union(&b);
        for s in [a, b] {
            prop_assert!(u.contains(s.center));
            for d in &dirs {
                let d = Vec3::from(*d);
                if d.length() > 1e-3 {
                    // Points at and just inside the boundary, kept only if the
                    // input sphere itself contains them in f32.
                    for f in [1.0, 0.999_999, 0.5] {
                        let p = s.center + d.normalize() * (s.radius * f);
                        if s.contains(p) {
                            prop_assert!(u.contains(p), "union {:?} misses {:?} of {:?}", u, p, s);
                        }
                    }
                }
            }
        }
        let d = (a.center - b.center).length();
        let exact = ((d + r1 + r2) * 0.5).max(r1).max(r2);
        assert_approx_eq!(u.radius, exact, 1e-4 * (exact + 100.0));
    }

    /// The point-set sphere contains every point and is no larger than the
    /// best sphere through any 2, 3 or 4 of them that contains all (the
    /// minimal sphere is one of those).
    #[test]
    fn point_sphere_is_minimal(pts in prop::collection::vec(prop::array::uniform3(-10.0f32..10.0), 1..8)) {
        let pts: Vec<Vec3> = pts.into_iter().map(Vec3::from).collect();
        let s = Sphere::of_points(&pts);
        for &p in &pts {
            prop_assert!(s.contains(p));
        }
        let mut best = f64::INFINITY;
        let n = pts.len();
        let holds = |c: glam::DVec3, r: f64| pts.iter().all(|p| (p.as_dvec3() - c).length() <= r * (1.0 + 1e-9) + 1e-9);
        if n == 1 { best = 0.0; }
        for i in 0..n { for j in i + 1..n {
            let (c, r) = ((pts[i].as_dvec3() + pts[j].as_dvec3()) * 0.5, (pts[i].as_dvec3() - pts[j].as_dvec3()).length() * 0.5);
            if holds(c, r) { best = best.min(r); }
            for k in j + 1..n {
                if let Some((c, r)) = circle3(pts[i].as_dvec3(), pts[j].as_dvec3(), pts[k].as_dvec3())
                    && holds(c, r) { best = best.min(r); }
                for l in k + 1..n {
                    if let Some((c, r)) = sphere4(pts[i].as_dvec3(), pts[j].as_dvec3(), pts[k].as_dvec3(), pts[l].as_dvec3())
                        && holds(c, r) { best = best.min(r); }
                }
            }
        }}
        prop_assert!((s.radius as f64) <= best * (1.0 + 1e-4) + 1e-4, "radius {} best {}", s.radius, best);
    }

    /// The triangle's minimal sphere equals the point-set sphere of its
    /// vertices.
    #[test]
    fn triangle_sphere_is_point_sphere(v in prop::array::uniform3(prop::array::uniform3(-10.0f32..10.0))) {
        let v = v.map(Vec3::from);
        let t = Sphere::of_triangle(v[0], v[1], v[2]);
        let p = Sphere::of_points(&v);
        for x in v { prop_assert!(t.contains(x)); }
        assert_approx_eq!(t.radius, p.radius, 1e-4 * (1.0 + p.radius));
    }
}

fn circle3(a: glam::DVec3, b: glam::DVec3, c: glam::DVec3) -> Option<(glam::DVec3, f64)> {
    let (u, v) = (b - a, c - a);
    let n = u.cross(v);
    if n.length_squared() < 1e-18 {
        return None;
    }
    let center = a
        + (n.cross(u) * v.length_squared() + v.cross(n) * u.length_squared())
            / (2.0 * n.length_squared());
    Some((center, (a - center).length()))
}

fn sphere4(
    a: glam::DVec3,
    b: glam::DVec3,
    c: glam::DVec3,
    d: glam::DVec3,
) -> Option<(glam::DVec3, f64)> {
    let m = glam::DMat3::from_cols(b - a, c - a, d - a).transpose();
    if m.determinant().abs() < 1e-12 {
        return None;
    }
    let x = m.inverse()
        * glam::DVec3::new(
            (b - a).length_squared(),
            (c - a).length_squared(),
            (d - a).length_squared(),
        )
        * 0.5;
    Some((a + x, x.length()))
}

/// 64 random bits that make `uniform_index(i, ·)` return exactly `j`:
/// `x = ⌈j·2⁶⁴ / i⌉`.
fn bits_for(j: u32, i: u32) -> (u32, u32) {
    let x = ((j as u128) << 64).div_ceil(i as u128) as u64;
    ((x >> 32) as u32, x as u32)
}

#[test]
fn algorithm_r_exact_counting() {
    // Enumerate every random draw for n = 7 candidates, k = 3: each item must
    // be held in exactly k/n of the equally likely outcomes.
    const N: u32 = 7;
    const K: usize = 3;
    let mut counts = [0u64; N as usize];
    let mut total = 0u64;
    let draws: Vec<u32> = (K as u32 + 1..=N).collect();
    let outcomes: u64 = draws.iter().map(|&i| i as u64).product();
    for code in 0..outcomes {
        let mut r = Reservoir::<K>::new();
        let mut c = code;
        for item in 0..N {
            let n = item + 1;
            let (hi, lo) = if n as usize > K {
                let j = (c % n as u64) as u32;
                c /= n as u64;
                bits_for(j, n)
            } else {
                (0, 0)
            };
            r.push(item, hi, lo);
        }
        assert_eq!(r.seen(), N);
        for &p in r.picks() {
            counts[p as usize] += 1;
        }
        total += 1;
        assert_eq!(r.weight(), N as f32 / K as f32);
    }
    for (item, &c) in counts.iter().enumerate() {
        assert_eq!(c * N as u64, total * K as u64, "item {item} held {c} of {total}");
    }
}

#[test]
fn weighted_reservoir_probabilities() {
    // Each slot holds item i with probability wᵢ/W. 4 slots × 50,000 trials;
    // per item, |freq − p| < 5σ with σ = sqrt(p(1−p)/trials).
    use rand_core::{RngCore, SeedableRng};
    let w = [1.0f32, 2.0, 0.5, 4.0, 0.25, 8.0, 1.5];
    let total: f32 = w.iter().sum();
    let mut rng = rand_pcg::Pcg32::seed_from_u64(12345);
    let trials = 50_000u32;
    let mut counts = [0u32; 7];
    let mut weight_mean = [0.0f64; 7];
    for _ in 0..trials {
        let mut r = WeightedReservoir::<4>::new();
        for (i, &wi) in w.iter().enumerate() {
            r.push(i as u32, wi, || slc_core::xi::xi_from_bits(rng.next_u32()));
        }
        assert!((r.total_weight() - total).abs() < 1e-5);
        for (i, wt) in r.picks() {
            counts[i as usize] += 1;
            // Estimator of Σ 1 = 7 items: each pick contributes W/(k·wᵢ)·1.
            weight_mean[i as usize] += wt as f64;
        }
    }
    let n = (trials * 4) as f64;
    for i in 0..7 {
        let p = (w[i] / total) as f64;
        let sigma = (p * (1.0 - p) / n).sqrt();
        let f = counts[i] as f64 / n;
        assert!((f - p).abs() < 5.0 * sigma, "item {i}: freq {f} vs p {p} (5σ = {})", 5.0 * sigma);
        // Unbiasedness of the weights: E[Σ picks weight] per trial = number of items.
        let mean_weight = weight_mean[i] / trials as f64;
        assert!(
            (mean_weight - 1.0).abs()
                < 5.0
                    * (total as f64 / w[i] as f64 / 4.0)
                    * (p * (1.0 - p) * 4.0 / trials as f64).sqrt()
                    * 2.0,
            "item {i}: mean weight {mean_weight}"
        );
    }
}

#[test]
fn big_sums_against_f64() {
    // 65,536 and 1M lights: the compensated f32 estimator sum agrees with an
    // f64 sum to a few f32 ulps of the total.
    for n in [65_536usize, 1 << 20] {
        let terms: Vec<Vec3> = (0..n)
            .map(|i| Vec3::splat(1.0 + (i % 977) as f32 * 1e-3) * (1.0 / (1.0 + i as f32)))
            .collect();
        let est = unculled_sum(terms.iter(), |t| **t).value;
        let exact: f64 = terms.iter().map(|t| t.x as f64).sum();
        let rel = ((est.x as f64 - exact) / exact).abs();
        assert!(rel < 4.0 * f32::EPSILON as f64, "n {n}: rel err {rel}");
        let naive: f32 = terms.iter().map(|t| t.x).sum();
        assert!(
            rel <= ((naive as f64 - exact) / exact).abs(),
            "compensation must not be worse than naive"
        );
    }
}
