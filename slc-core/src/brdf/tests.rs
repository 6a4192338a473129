//! Tests of [`super`]: its properties against brute force and closed forms.

use super::*;
use alloc::vec;

/// Midpoint quadrature over the upper hemisphere in `(s, φ)` with
/// `θ = (π/2)·s²` (cells shrink toward the pole, where sharp lobes at
/// normal view sit), `m × 4m` cells.
fn hemisphere(m: usize, mut f: impl FnMut(Vec3) -> f64) -> f64 {
    use core::f64::consts::PI;
    let mut sum = 0.0;
    for i in 0..m {
        let s = (i as f64 + 0.5) / m as f64;
        let theta = 0.5 * PI * s * s;
        let w = theta.sin() * PI * s / m as f64 * (2.0 * PI / (4 * m) as f64);
        for j in 0..4 * m {
            let phi = 2.0 * PI * (j as f64 + 0.5) / (4 * m) as f64;
            let d = Vec3::new(
                (theta.sin() * phi.cos()) as f32,
                (theta.sin() * phi.sin()) as f32,
                theta.cos() as f32,
            );
            sum += f(d) * w;
        }
    }
    sum
}

/// `∫ f cos dω` by the bounded VNDF's own stratified samples (`k × k`):
/// `mean(f cos / pdf)`, samples below the horizon counting 0.
fn albedo_by_sampling(base: Vec3, metallic: f32, alpha: f32, v: Vec3, k: usize) -> f64 {
    let mut sum = 0.0;
    for i in 0..k {
        for j in 0..k {
            let l =
                ggx_vndf_sample(v, alpha, (i as f32 + 0.5) / k as f32, (j as f32 + 0.5) / k as f32);
            if l.z > 0.0 {
                let f = brdf_eval(base, metallic, Vec3::ZERO, 0.0, alpha, Vec3::Z, v, l);
                sum += (f.x * l.z / ggx_vndf_pdf(v, l, alpha)) as f64;
            }
        }
    }
    sum / (k * k) as f64
}

use glam::Vec3;

fn view(cos: f32) -> Vec3 {
    Vec3::new((1.0 - cos * cos).sqrt(), 0.0, cos)
}

/// Bevy's BRDF at normal incidence (`n = v = l`), worked by hand from
/// bevy_pbr 0.20's `pbr_lighting.wesl`: Burley's factors are 1, so the
/// diffuse lobe is `(1 − m)·b/π`; `D = 1/(πα²)`, `V = ¼`, `F = F0`, and
/// the compensation `1 + F0(1/dfg − 1)` with `dfg(1, 1) = 0.45245`.
#[test]
fn bevy_brdf_at_normal_incidence() {
    let n = Vec3::Z;
    let base = Vec3::new(0.8, 0.5, 0.2);
    let pi = core::f64::consts::PI;
    assert!((bevy_dfg(1.0, 1.0) as f64 - 0.45245).abs() < 1e-6);
    for (m, refl) in [(0.0f32, 0.5f32), (0.0, 1.0), (1.0, 0.5), (0.4, 0.3)] {
        let f = bevy_brdf(base, m, 1.0, refl, n, n, n);
        for c in 0..3 {
            let b = base[c] as f64;
            let f0 = 0.16 * (refl as f64).powi(2) * (1.0 - m as f64) + b * m as f64;
            let want =
                (1.0 - m as f64) * b / pi + f0 * (1.0 + f0 * (1.0 / 0.45245 - 1.0)) / pi * 0.25;
            assert!(
                (f[c] as f64 - want).abs() < 1e-5 * want.max(1e-3),
                "m {m} refl {refl}: {} vs {want}",
                f[c]
            );
        }
    }
    // Perceptual roughness below Bevy's clamp 0.089 renders at 0.089
    // (only the compensation sees the unclamped value, as in Bevy).
    let l = Vec3::new(0.3, 0.0, 1.0).normalize();
    let v = Vec3::new(-0.3, 0.0, 1.0).normalize();
    let (f, g) =
        (bevy_brdf(base, 0.0, 0.0, 0.5, n, v, l), bevy_brdf(base, 0.0, 0.089, 0.5, n, v, l));
    assert!((f - g).abs().max_element() < 1e-2 * g.max_element(), "{f} vs {g}");
}

/// Bevy's BRDF is finite (never NaN) at the edges: smooth and rough,
/// grazing, views below the surface, lights below it (0).
#[test]
fn bevy_brdf_edge_cases_are_finite() {
    let n = Vec3::Z;
    let dirs = [
        Vec3::Z,
        Vec3::new(1.0, 0.0, 1e-6).normalize(),
        Vec3::new(0.0, 1.0, -0.5).normalize(),
        Vec3::new(-1.0, 0.0, 0.0),
    ];
    for r in [0.0, 0.089, 0.5, 1.0] {
        for m in [0.0, 1.0] {
            for &v in &dirs {
                for &l in &dirs {
                    let f = bevy_brdf(Vec3::ONE, m, r, 0.5, n, v, l);
                    assert!(
                        f.is_finite() && f.min_element() >= 0.0,
                        "r {r} m {m} v {v} l {l}: {f}"
                    );
                    if l.z <= 0.0 {
                        assert_eq!(f, Vec3::ZERO);
                    }
                }
            }
        }
    }
}

#[test]
fn lambertian_is_exactly_base_over_pi() {
    let b = Vec3::new(0.725, 0.71, 0.68);
    let n = Vec3::Z;
    for (v, l) in
        [(view(0.9), Vec3::new(0.0, 0.6, 0.8)), (view(0.05), view(0.3)), (-view(0.3), view(0.5))]
    {
        assert_eq!(brdf_eval(b, 0.0, Vec3::ZERO, 0.0, 0.3, n, v, l), b * INV_PI);
        assert_eq!(bsdf_pdf(n, v, l, 0.3, 0.0), cosine_pdf(l.z));
    }
    assert_eq!(specular_probability(receiver_lobe(b, 0.0, Vec3::ZERO, 0.0, 0.3, 0.5)), 0.0);
    for (u1, u2) in [(0.0, 0.0), (0.3, 0.7), (0.999, 0.5)] {
        assert_eq!(bsdf_sample(n, view(0.5), 0.3, 0.0, u1, u2), cosine_direction(n, u1, u2));
    }
}

/// Each sampling pdf integrates to 1 over the sphere of directions, less
/// what the bounded VNDF still sends below the horizon (at most that
/// share, and nothing below at normal view).
#[test]
fn pdfs_integrate_to_one() {
    for alpha in [0.05f32, 0.2, 0.5, 1.0] {
        for cos_v in [1.0f32, 0.7, 0.3, 0.05] {
            let wi = view(cos_v);
            // Finer cells for the sharp lobes.
            let m = if alpha < 0.1 { 1000 } else { 400 };
            let total = hemisphere(m, |wo| ggx_vndf_pdf(wi, wo, alpha) as f64);
            // The share of samples lost below the horizon, by sampling.
            let k = 200;
            let mut below = 0;
            for i in 0..k {
                for j in 0..k {
                    let d = ggx_vndf_sample(
                        wi,
                        alpha,
                        (i as f32 + 0.5) / k as f32,
                        (j as f32 + 0.5) / k as f32,
                    );
                    below += (d.z <= 0.0) as u32;
                }
            }
            let lost = below as f64 / (k * k) as f64;
            assert!(
                (total + lost - 1.0).abs() < 0.01,
                "α {alpha}, cos {cos_v}: ∫pdf {total:.4} + lost {lost:.4}"
            );
            if cos_v == 1.0 {
                assert_eq!(below, 0, "α {alpha}: samples below the horizon at normal view");
            }
        }
    }
    let c = hemisphere(400, |l| cosine_pdf(l.z) as f64);
    assert!((c - 1.0).abs() < 1e-3, "{c}");
    let mix = hemisphere(1000, |l| bsdf_pdf(Vec3::Z, view(0.6), l, 0.1, 0.4) as f64);
    assert!((mix - 1.0).abs() < 0.01, "{mix}");
}

/// The bounded VNDF's samples follow its pdf: a χ² test over 16 × 32
/// cells in `(cos θ, φ)`, 200,000 samples with fixed stratified-free
/// pseudo-random numbers; cells expecting fewer than 5 samples are
/// pooled. Threshold: the χ² 1 − 10⁻⁶ quantile for the degrees of
/// freedom (Wilson–Hilferty), so a correct sampler fails once in a
/// million seeds.
#[test]
fn vndf_samples_follow_the_pdf() {
    let mut state = 0x9e37_79b9u32;
    let mut next = || {
        state = crate::xi::pcg_hash(state);
        crate::xi::xi_from_bits(state)
    };
    let (nt, np) = (16usize, 32usize);
    for (alpha, cos_v) in [(0.1f32, 0.8f32), (0.3, 0.3), (0.6, 0.95), (1.0, 0.2)] {
        let wi = view(cos_v);
        let n = 200_000;
        let mut counts = vec![0f64; nt * np];
        let mut lost = 0.0;
        for _ in 0..n {
            let d = ggx_vndf_sample(wi, alpha, next(), next());
            if d.z <= 0.0 {
                lost += 1.0;
                continue;
            }
            let it = ((d.z * nt as f32) as usize).min(nt - 1);
            let phi = d.y.atan2(d.x).rem_euclid(2.0 * core::f32::consts::PI);
            let ip = ((phi / (2.0 * core::f32::consts::PI) * np as f32) as usize).min(np - 1);
            counts[it * np + ip] += 1.0;
        }
        // Expected counts: the pdf integrated over each cell (8 × 8 midpoints).
        let mut expect = vec![0f64; nt * np];
        let s = 8;
        for it in 0..nt {
            for ip in 0..np {
                let mut acc = 0.0;
                for a in 0..s {
                    let z = (it as f64 + (a as f64 + 0.5) / s as f64) / nt as f64;
                    let r = (1.0 - z * z).sqrt();
                    for b in 0..s {
                        let phi =
                            2.0 * core::f64::consts::PI * (ip as f64 + (b as f64 + 0.5) / s as f64)
                                / np as f64;
                        let wo =
                            Vec3::new((r * phi.cos()) as f32, (r * phi.sin()) as f32, z as f32);
                        acc += ggx_vndf_pdf(wi, wo, alpha) as f64;
                    }
                }
                let cell = 2.0 * core::f64::consts::PI / (nt * np) as f64;
                expect[it * np + ip] = acc / (s * s) as f64 * cell * n as f64;
            }
        }
        let (mut chi2, mut dof, mut pool_o, mut pool_e) = (0.0, 0usize, lost, 0.0);
        let above: f64 = expect.iter().sum();
        pool_e += n as f64 - above;
        for (o, e) in counts.iter().zip(&expect) {
            if *e < 5.0 {
                pool_o += o;
                pool_e += e;
            } else {
                chi2 += (o - e) * (o - e) / e;
                dof += 1;
            }
        }
        if pool_e >= 5.0 {
            chi2 += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
            dof += 1;
        }
        let k = (dof - 1) as f64;
        // Wilson–Hilferty: χ²_q ≈ k (1 − 2/(9k) + z_q √(2/(9k)))³, z = 4.753 for 1 − 10⁻⁶.
        let limit = k * (1.0 - 2.0 / (9.0 * k) + 4.753 * (2.0 / (9.0 * k)).sqrt()).powi(3);
        assert!(
            chi2 < limit,
            "α {alpha}, cos {cos_v}: χ² {chi2:.1} over {dof} cells, limit {limit:.1}"
        );
    }
}

/// Helmholtz reciprocity: `f(v, l) = f(l, v)` for every lobe mix.
#[test]
fn reciprocity() {
    let b = Vec3::new(0.9, 0.5, 0.2);
    for (m, f0, f90) in [
        (0.0, Vec3::splat(0.04), 1.0),
        (1.0, Vec3::ZERO, 0.0),
        (0.4, Vec3::new(0.02, 0.05, 0.08), 0.7),
    ] {
        for alpha in [0.01, 0.2, 0.8] {
            for (v, l) in [
                (view(0.9), Vec3::new(0.1, 0.6, 0.79).normalize()),
                (view(0.2), view(0.7)),
                (Vec3::new(-0.5, 0.5, 0.707), view(0.99)),
            ] {
                let a = brdf_eval(b, m, f0, f90, alpha, Vec3::Z, v, l);
                let c = brdf_eval(b, m, f0, f90, alpha, Vec3::Z, l, v);
                assert!(
                    (a - c).abs().max_element() <= 1e-5 * a.max_element().max(1.0),
                    "{a} vs {c}"
                );
            }
        }
    }
}

/// The white furnace: `∫ f cos dω ≤ 1` for a white metal (the lobe that
/// reflects the most) at every view, with its single-scattering energy
/// at normal view per `α` stated (the Smith model's multiple scattering
/// is not modelled: at `α = 1` only `1 − ln 2 = 0.307` is reflected;
/// NumPy quadrature of the same formula agrees to 1e-4); quadrature agrees with the sampled estimate where
/// the lobe is wide enough for it. The glTF dielectric's gain at
/// oblique views is stated too.
#[test]
fn white_furnace() {
    let expect_normal =
        [(0.001f32, 1.000f64), (0.1, 0.9883), (0.3, 0.8774), (0.5, 0.6878), (1.0, 0.3069)];
    for (alpha, e) in expect_normal {
        let normal = albedo_by_sampling(Vec3::ONE, 1.0, alpha, Vec3::Z, 256);
        assert!((normal - e).abs() < 0.005, "α {alpha}: {normal:.4} (expected {e})");
        for cos_v in [0.6f32, 0.2, 0.02] {
            let energy = albedo_by_sampling(Vec3::ONE, 1.0, alpha, view(cos_v), 256);
            assert!(energy <= 1.0 + 1e-3, "α {alpha}, cos {cos_v}: {energy}");
            if alpha >= 0.1 {
                let quad = hemisphere(600, |l| {
                    (brdf_eval(Vec3::ONE, 1.0, Vec3::ZERO, 0.0, alpha, Vec3::Z, view(cos_v), l).x
                        * l.z) as f64
                });
                assert!(
                    (quad - energy).abs() < 5e-3,
                    "α {alpha}, cos {cos_v}: quadrature {quad:.4}, sampled {energy:.4}"
                );
            }
        }
    }
    // A white dielectric (F0 = 0.04) is not energy-conserving at oblique
    // views: glTF weights the diffuse lobe by `1 − F(v·h)` (about 0.95
    // on average) while the specular lobe grows toward grazing. Measured
    // (NumPy quadrature of the same formula agrees to 1e-4):
    for (alpha, cos_v, e) in [
        (0.1f32, 1.0f32, 0.9995f64),
        (0.1, 0.5, 1.0249),
        (0.1, 0.2, 1.1854),
        (0.3, 1.0, 0.9950),
        (0.3, 0.5, 1.0064),
        (0.3, 0.2, 1.0556),
    ] {
        let diel = hemisphere(800, |l| {
            (brdf_eval(Vec3::ONE, 0.0, Vec3::splat(0.04), 1.0, alpha, Vec3::Z, view(cos_v), l).x
                * l.z) as f64
        });
        assert!(
            (diel - e).abs() < 2e-3,
            "dielectric α {alpha}, cos {cos_v}: {diel:.4}, expected {e}"
        );
    }
}

/// Edge cases give finite, non-negative values: α at its floor and at
/// 1, grazing and below-horizon views and lights, `v = −l`, a sample
/// from `u = 0` and `u → 1`.
#[test]
fn edge_cases_are_finite() {
    let b = Vec3::new(0.5, 0.5, 0.5);
    let dirs = [
        Vec3::Z,
        view(1e-4),
        view(0.0),
        -Vec3::Z,
        view(-0.3),
        Vec3::new(0.0, 1.0, 1e-7).normalize(),
    ];
    let below_one = 1.0 - f32::EPSILON / 2.0;
    for rough in [0.0f32, 1e-6, 0.01, 0.5, 1.0] {
        let alpha = ggx_alpha(rough);
        for &v in &dirs {
            for &l in &dirs {
                let f = brdf_eval(b, 0.5, Vec3::splat(0.04), 1.0, alpha, Vec3::Z, v, l);
                assert!(f.is_finite() && f.min_element() >= 0.0, "r {rough}: f({v}, {l}) = {f}");
                let p = bsdf_pdf(
                    Vec3::Z,
                    v,
                    l,
                    alpha,
                    specular_probability(receiver_lobe(b, 0.5, Vec3::splat(0.04), 1.0, alpha, v.z)),
                );
                assert!(p.is_finite() && p >= 0.0, "r {rough}: pdf({v}, {l}) = {p}");
            }
            for (u1, u2) in [(0.0, 0.0), (below_one, below_one), (0.5, below_one), (0.05, 0.0)] {
                let d = bsdf_sample(Vec3::Z, v, alpha, 0.5, u1, u2);
                assert!(d.is_finite(), "r {rough}: sample from {v} at ({u1}, {u2}) = {d}");
            }
        }
    }
    // The peak at the smallest α stays finite and exact: D(n) = 1/(π α²).
    let a = GGX_ALPHA_MIN;
    assert!((ggx_d(1.0, 0.0, a) * core::f32::consts::PI * a * a - 1.0).abs() < 1e-5);
}

/// The sampled direction's pdf matches [`bsdf_pdf`] and the estimator
/// `f cos / pdf` is bounded for the specular lobe (the VNDF cancels `D`).
#[test]
fn sample_weights_are_bounded() {
    let b = Vec3::splat(0.95);
    let n = Vec3::Z;
    for alpha in [0.002f32, 0.05, 0.3, 1.0] {
        for cos_v in [0.99f32, 0.5, 0.1] {
            let v = view(cos_v);
            let p_s = specular_probability(receiver_lobe(b, 1.0, Vec3::ZERO, 0.0, alpha, v.z));
            assert_eq!(p_s, 1.0);
            for i in 0..50 {
                for j in 0..50 {
                    let l = bsdf_sample(
                        n,
                        v,
                        alpha,
                        p_s,
                        (i as f32 + 0.5) / 50.0,
                        (j as f32 + 0.5) / 50.0,
                    );
                    if l.z <= 0.0 {
                        continue;
                    }
                    let w = brdf_eval(b, 1.0, Vec3::ZERO, 0.0, alpha, n, v, l) * l.z
                        / bsdf_pdf(n, v, l, alpha, p_s);
                    assert!(
                        w.is_finite() && w.max_element() <= 1.0 + 1e-3,
                        "α {alpha}, cos {cos_v}: weight {w}"
                    );
                }
            }
        }
    }
}

/// SLC's error bound on a glossy receiver. The range `r_t² = E·I/(2π ε)`
/// caps one light's roulette deviation `σ(d) = √(1/p − 1) · g(d)` at ε
/// for a receiver whose `f·cos ≤ 1/π` (a white Lambertian one); for a
/// receiver whose `f·cos` toward the light is `P`, `max_d σ(d) = π·P·ε`
/// (at `d² = 2 r_t²`). Checked through the real roulette (`random_range2`,
/// `slc_keep`, `slc_weight`, quadrature over ξ) for a point light on a
/// glossy metal's mirror direction, where `π·P = F/(4α²)` at normal view.
#[test]
fn slc_deviation_on_a_glossy_receiver_is_pi_p_epsilon() {
    use crate::range::{RangeParams, random_range2, slc_keep, slc_weight};
    let params = RangeParams::new(0.01, 1.0).unwrap();
    let intensity = Vec3::splat(2.0);
    let rt2 = params.threshold_range2(intensity);
    let n = Vec3::Z;
    for (base, metallic, rough, f0, f90) in [
        (Vec3::ONE, 0.0, 1.0, Vec3::ZERO, 0.0), // white Lambertian: σ ≤ ε
        (Vec3::ONE, 1.0, 0.5, Vec3::ZERO, 0.0),
        (Vec3::ONE, 1.0, 0.2, Vec3::ZERO, 0.0),
        (Vec3::splat(0.5), 0.0, 0.3, Vec3::splat(0.04), 1.0),
    ] {
        let alpha = ggx_alpha(rough);
        let p = brdf_eval(base, metallic, f0, f90, alpha, n, n, n).x; // f·cos at the mirror direction, cos = 1
        let mut worst = 0.0f64;
        for k in 1..400 {
            let d2 = rt2 * (k as f32 * 0.02);
            let g = (p * intensity.x / d2) as f64;
            // E[X] and E[X²] over ξ by the midpoint rule: X = g·1/p if kept.
            let m = 20_000;
            let (mut s1, mut s2) = (0.0f64, 0.0f64);
            for j in 0..m {
                let xi = (j as f32 + 0.5) / m as f32;
                if slc_keep(random_range2(rt2, xi), d2) {
                    let x = g * slc_weight(rt2, d2) as f64;
                    s1 += x;
                    s2 += x * x;
                }
            }
            let (m1, m2) = (s1 / m as f64, s2 / m as f64);
            assert!((m1 - g).abs() <= 2e-3 * g, "unbiased: {m1} vs {g}");
            worst = worst.max((m2 - m1 * m1).max(0.0).sqrt());
        }
        let bound = core::f64::consts::PI * p as f64 * 0.01;
        assert!(
            (worst - bound).abs() <= 0.01 * bound,
            "P = {p}: max σ {worst:.5} vs π·P·ε {bound:.5}"
        );
        if metallic == 1.0 {
            let peak = 1.0 / (4.0 * alpha as f64 * alpha as f64);
            assert!(
                (core::f64::consts::PI * p as f64 - peak).abs() <= 1e-3 * peak,
                "π·P = F/(4α²)"
            );
        }
    }
}
