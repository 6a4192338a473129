//! Multiple importance sampling weights (Veach & Guibas 1995). With SLC the
//! light strategy's pdf includes the Russian-roulette probability (talk:
//! "Multiple importance sampling"): `pdf_light = pdf(select) · p_rr(d) ·
//! pdf_area(y)`, converted to solid angle
//! ([`crate::light::area_to_solid_angle_pdf`]).

// Shared code is also WGSL, which has no `core::f32::consts`: π and its
// fractions are written as literals.
#![allow(clippy::approx_constant)]

use crate::light::{INV_PI, area_to_solid_angle_pdf};
use crate::range::rr_probability;
use crate::wgsl::*;

crate::shared! {
    /// Balance heuristic weight of strategy `a` against `b`: `a / (a + b)`
    /// (0 when both pdfs are 0).
    pub fn mis_balance(pdf_a: f32, pdf_b: f32) -> f32 {
        let s: f32 = pdf_a + pdf_b;
        if s <= 0.0 {
            return 0.0;
        }
        return pdf_a / s;
    }

    /// Power heuristic (β = 2) weight of strategy `a` against `b`:
    /// `a² / (a² + b²)` (0 when both pdfs are 0).
    pub fn mis_power(pdf_a: f32, pdf_b: f32) -> f32 {
        let a2: f32 = pdf_a * pdf_a;
        let s: f32 = a2 + pdf_b * pdf_b;
        if s <= 0.0 {
            return 0.0;
        }
        return a2 / s;
    }

    /// Solid-angle pdf with which the light strategy produces a point at
    /// distance² `d2` on a one-sided area light of `area`, seen under cosine
    /// `cos_y` from the shading point, when it selects the light with
    /// probability `select` and the RR test keeps it with `p_rr(r_t², d²)`
    /// (talk: "Multiple importance sampling"): `select · p_rr · d²/(area ·
    /// cos_y)`; 0 behind the light, at `d² = 0` or for no area. Baselines
    /// pass `rt2 = +∞` (p_rr = 1). The pdf must not depend on the light's own
    /// ξ, or the MIS weights do not sum to one in expectation.
    pub fn light_strategy_pdf(select: f32, rt2: f32, d2: f32, area: f32, cos_y: f32) -> f32 {
        if d2 <= 0.0 || area <= 0.0 || cos_y <= 0.0 {
            return 0.0;
        }
        return select * rr_probability(rt2, d2) * area_to_solid_angle_pdf(1.0 / area, d2, cos_y);
    }

    /// Lambertian BRDF of albedo `rho`: `ρ/π`.
    pub fn lambert_brdf(rho: vec3f) -> vec3f {
        return rho * INV_PI;
    }

    /// Cosine-weighted hemisphere pdf of a diffuse BSDF sample: `max(cos θ, 0)/π`.
    pub fn cosine_pdf(cos_theta: f32) -> f32 {
        return max(cos_theta, 0.0) * INV_PI;
    }

    /// Tangent of the branchless orthonormal basis about the unit normal
    /// `n` (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT
    /// 2017): with [`onb_bitangent`] and `n` a right-handed frame.
    pub fn onb_tangent(n: vec3f) -> vec3f {
        let s: f32 = select(-1.0, 1.0, n.z >= 0.0);
        let a: f32 = -1.0 / (s + n.z);
        return vec3f(1.0 + s * n.x * n.x * a, s * n.x * n.y * a, -s * n.x);
    }

    /// Bitangent of the basis of [`onb_tangent`].
    pub fn onb_bitangent(n: vec3f) -> vec3f {
        let s: f32 = select(-1.0, 1.0, n.z >= 0.0);
        let a: f32 = -1.0 / (s + n.z);
        return vec3f(n.x * n.y * a, s + n.y * n.y * a, -n.y);
    }

    /// World direction of the local direction `d` (`z` along `n`) in the
    /// basis of [`onb_tangent`].
    pub fn onb_to_world(n: vec3f, d: vec3f) -> vec3f {
        return onb_tangent(n) * d.x + onb_bitangent(n) * d.y + n * d.z;
    }

    /// Local coordinates (`z` along `n`) of the world direction `w` in the
    /// basis of [`onb_tangent`].
    pub fn onb_to_local(n: vec3f, w: vec3f) -> vec3f {
        return vec3f(dot(w, onb_tangent(n)), dot(w, onb_bitangent(n)), dot(w, n));
    }

    /// Cosine-weighted direction about the unit normal `n` for `u1, u2 ∈
    /// [0, 1)` (Malley's method: a uniform disk point `(√u1, 2πu2)` lifted
    /// to the hemisphere) in the basis of [`onb_tangent`]. Its pdf is
    /// [`cosine_pdf`] of the cosine with `n`.
    pub fn cosine_direction(n: vec3f, u1: f32, u2: f32) -> vec3f {
        let r: f32 = sqrt(u1);
        let phi: f32 = 6.2831855 * u2;
        return normalize(onb_to_world(n, vec3f(r * cos(phi), r * sin(phi), sqrt(max(1.0 - u1, 0.0)))));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_sum_to_one() {
        for (a, b) in [(1.0f32, 3.0f32), (0.5, 0.5), (1e-20, 1.0), (7.0, 0.0)] {
            assert!((mis_balance(a, b) + mis_balance(b, a) - 1.0).abs() < 1e-6);
            assert!((mis_power(a, b) + mis_power(b, a) - 1.0).abs() < 1e-6);
        }
        assert_eq!(mis_balance(0.0, 0.0), 0.0);
        assert_eq!(mis_power(0.0, 0.0), 0.0);
    }

    /// Unit length, in the hemisphere of `n`, and cosine-distributed: the
    /// stratified mean of cos θ is E[cos θ] = ∫cos²θ/π dω = 2/3.
    #[test]
    fn cosine_direction_is_cosine_distributed() {
        for n in [
            vec3f(0.0, 0.0, 1.0),
            vec3f(0.0, 0.0, -1.0),
            normalize(vec3f(1.0, -2.0, 0.5)),
            vec3f(1.0, 0.0, 0.0),
        ] {
            let m = 200;
            let mut sum = 0.0f64;
            for i in 0..m {
                for j in 0..m {
                    let d = cosine_direction(
                        n,
                        (i as f32 + 0.5) / m as f32,
                        (j as f32 + 0.5) / m as f32,
                    );
                    assert!((dot(d, d) - 1.0).abs() < 1e-5 && dot(d, n) >= 0.0);
                    sum += dot(d, n) as f64;
                }
            }
            assert!(
                (sum / (m * m) as f64 - 2.0 / 3.0).abs() < 1e-4,
                "{n}: {}",
                sum / (m * m) as f64
            );
        }
    }
}
