//! Importance of a light, or a set of lights, at a shading point: a cheap,
//! conservative estimate of its unshadowed contribution, and the weighted
//! selection built on it (beyond the paper).
//!
//! - [`light_importance`]: pbrt-v4's `LightBounds::Importance` (Pharr, Jakob
//!   & Humphreys, *PBR* 4th ed., §12.6.3; Conty Estevez & Kulla, HPG 2018)
//!   over a bounding sphere: `φ · cos θ' / max(d², R²)` times the receiver's
//!   widened `cos θ'_i`, zero only where no point of the bound can light the
//!   point (outside the emission cone, or wholly below the receiver's
//!   horizon). The light BVH weighs its nodes with it; `slc-weighted`
//!   weighs each in-range candidate with it.
//! - [`candidate_weight`]: `slc-weighted`'s weight `wᵢ = ĝᵢ / pᵢ` of an
//!   in-range candidate: its importance over its roulette probability at the
//!   bound's centre, since a kept candidate's term carries `1/p`.
//! - [`weighted_select_pdf`]: the expected number of picks of a light by
//!   `k` independent one-slot weighted reservoirs, `k · w_j / (W₋ⱼ + w_j)`,
//!   with `W₋ⱼ` the weight of the *other* candidates: independent of the
//!   light's own ξ, as MIS needs (the light is a candidate when its own
//!   range reaches the point; then `W₋ⱼ + w_j = W`).

// Shared (WGSL) functions take their bounds as scalars and vectors.
#![allow(clippy::too_many_arguments)]

use crate::brdf::{ggx_d, smith_root};
use crate::light::{INV_PI, Light, MIN_D2};
use crate::range::slc_weight;
use crate::wgsl::*;
use glam::Vec3;

crate::shared! {
    /// `cos(a − b)`, or 1 when `a < b` (pbrt-v4 `CosSubClamped`), from the
    /// sines and cosines of angles `a, b ∈ [0, π]`.
    pub fn cos_sub_clamped(sin_a: f32, cos_a: f32, sin_b: f32, cos_b: f32) -> f32 {
        if cos_a > cos_b {
            return 1.0;
        }
        return cos_a * cos_b + sin_a * sin_b;
    }

    /// `sin(a − b)`, or 0 when `a < b` (pbrt-v4 `SinSubClamped`).
    pub fn sin_sub_clamped(sin_a: f32, cos_a: f32, sin_b: f32, cos_b: f32) -> f32 {
        if cos_a > cos_b {
            return 0.0;
        }
        return sin_a * cos_b - cos_a * sin_b;
    }

    /// `√max(x, 0)`.
    pub fn safe_sqrt(x: f32) -> f32 {
        return sqrt(max(x, 0.0));
    }

    /// `cos` of the half-angle the sphere of radius² `r2` subtends at
    /// distance² `dist2` from its centre (−1 from inside it).
    pub fn subtended_cos(dist2: f32, r2: f32) -> f32 {
        return select(safe_sqrt(1.0 - r2 / dist2), -1.0, dist2 <= r2);
    }

    /// The emitter's geometry seen from `p`, for [`emitter_importance`] and
    /// [`light_importance`] (computed once for both halves):
    /// `(cos θ', max(d², R², MIN_D2), cos θ_b, sin θ_b)` with `θ'` the angle
    /// from the direction to `p` to the normal cone `(axis, cos_o)` less
    /// the angle `θ_b` the sphere `(center, radius)` subtends at `p`. A
    /// point bound (`radius = 0`) at `p` itself gets `cos θ' = −2`, outside
    /// every emission cone: a light at the receiver lights nothing there
    /// (`crate::light::connection_cosine`), so it weighs nothing.
    pub fn emitter_cone(center: vec3f, radius: f32, axis: vec3f, cos_o: f32, p: vec3f) -> vec4f {
        let v: vec3f = p - center;
        let dist2: f32 = dot(v, v);
        let r2: f32 = radius * radius;
        if dist2 <= 0.0 && r2 <= 0.0 {
            return vec4f(-2.0, MIN_D2, -1.0, 0.0);
        }
        let d2: f32 = max(max(dist2, r2), MIN_D2);
        let wi: vec3f = select(vec3f(0.0, 0.0, 0.0), v / sqrt(dist2), dist2 > 0.0);
        let cos_w: f32 = dot(axis, wi);
        let sin_w: f32 = safe_sqrt(1.0 - cos_w * cos_w);
        let cos_b: f32 = subtended_cos(dist2, r2);
        let sin_b: f32 = safe_sqrt(1.0 - cos_b * cos_b);
        let sin_o: f32 = safe_sqrt(1.0 - cos_o * cos_o);
        let cos_x: f32 = cos_sub_clamped(sin_w, cos_w, sin_o, cos_o);
        let sin_x: f32 = sin_sub_clamped(sin_w, cos_w, sin_o, cos_o);
        return vec4f(cos_sub_clamped(sin_x, cos_x, sin_b, cos_b), d2, cos_b, sin_b);
    }

    /// The emitter's half of [`light_importance`] at `p`: `φ · cos θ' /
    /// max(d², R², MIN_D2)`, 0 where `θ' ≥ θ_e` ([`emitter_cone`]).
    pub fn emitter_importance(center: vec3f, radius: f32, phi: f32, axis: vec3f, cos_o: f32, cos_e: f32, p: vec3f) -> f32 {
        let c: vec4f = emitter_cone(center, radius, axis, cos_o, p);
        if c.x <= cos_e {
            return 0.0;
        }
        return phi * c.x / c.y;
    }

    /// The largest cosine between the unit direction `d` at `p` and a
    /// direction from `p` into the sphere `(center, radius)`: `cos(θ − θ_b)`
    /// with `θ` the angle to the centre and `θ_b` the half-angle the sphere
    /// subtends (1 inside it or within `θ_b`). With the receiver's normal it
    /// is pbrt-v4's widened `cos θ'_i`; with a glossy receiver's mirror
    /// direction, how near the sphere comes to the lobe's peak.
    ///
    /// Computed by [`cone_cos_of`] with `v = center − p`.
    pub fn cone_cos_toward(center: vec3f, radius: f32, p: vec3f, d: vec3f) -> f32 {
        let v: vec3f = center - p;
        return cone_cos_of(v, dot(v, v), radius, d);
    }

    /// [`cone_cos_toward`] of the sphere of radius `a` whose centre lies at
    /// `v` from the point (`d2 = |v|²`), over one denominator:
    /// `cos(θ − θ_b) = (v·d·√(d2 − a²) + |v × d|·a)/d2`, and 1 without a
    /// root where the point is inside the sphere (`d2 ≤ a²`) or `d` points
    /// into it (`v·d ≥ 0`, `(v·d)² ≥ d2 − a²`). The sines come from
    /// `|v × d|` and `a`, not from `√(1 − cos²)`, which loses half the
    /// digits near 0 (a small sphere near `d`): a glossy receiver's range
    /// scale ([`range_scale_toward`]) amplifies an error in this cosine by
    /// up to `1/α²`, and the BSH's walk bounds it with a fixed margin
    /// (`crate::bsh::walk::bsh_inner_scale`, which calls this with the
    /// `d2` it has).
    pub fn cone_cos_of(v: vec3f, d2: f32, a: f32, d: vec3f) -> f32 {
        let vd: f32 = dot(v, d);
        let h2: f32 = d2 - a * a;
        if h2 <= 0.0 || (vd >= 0.0 && vd * vd >= h2) {
            return 1.0;
        }
        let c: vec3f = cross(v, d);
        return min((vd * sqrt(h2) + sqrt(dot(c, c)) * a) / d2, 1.0);
    }

    /// The factor `s` by which a receiver at `p` with mirror direction `r`
    /// and range lobe `rl` ([`crate::brdf::range_lobe`]) scales the
    /// threshold and random range² of a light bounded by the sphere
    /// `(center, radius)`: the lobe's `π·f·cos` peak over the directions
    /// into the sphere, `k_d + c_s·α²/t²` with `t = cos²θ_h (α²−1) + 1` and
    /// `cos²θ_h = (1 + cos θ)/2`, `θ` the smallest angle between `r` and the
    /// sphere ([`cone_cos_toward`]; the half vector's angle taken as half
    /// the angle to the mirror direction, as [`glossy_importance`] does),
    /// kept in `[1, s_max]` ([`crate::brdf::range_scale`]). A light near the
    /// mirror direction gets the receiver's full scale, one far off its lobe
    /// about `max(k_d, 1)`: the ranges grow only toward the lobe. Monotone in
    /// the sphere (a sphere holding another gets at least its scale), which
    /// the BSH's walk relies on. 1 for `rl.w ≤ 1` (no specular lobe).
    /// The estimate stays unbiased for any such `s` (the roulette uses the
    /// same `s` in its test and its probability); `s` keeps one light's
    /// roulette deviation at the receiver near ε (`crate::range`), exactly so
    /// in the plane of incidence.
    pub fn range_scale_toward(rl: vec4f, center: vec3f, radius: f32, p: vec3f, r: vec3f) -> f32 {
        if rl.w <= 1.0 {
            return 1.0;
        }
        return range_scale_at(rl, cone_cos_toward(center, radius, p, r));
    }

    /// [`range_scale_toward`] of a sphere whose directions come within
    /// angle `θ` of the mirror direction, `cos_t = cos θ` (non-decreasing in
    /// `cos_t`).
    pub fn range_scale_at(rl: vec4f, cos_t: f32) -> f32 {
        let t: f32 = (0.5 + 0.5 * cos_t) * (rl.z - 1.0) + 1.0;
        return clamp(rl.x + rl.y * rl.z / (t * t), 1.0, rl.w * rl.w);
    }

    /// Importance at point `p` (receiver normal `n`, or zero for none) of
    /// lights inside the sphere `(center, radius)` emitting power `phi`
    /// with normals in the cone `(axis, cos_o)` and emission spread `cos_e`
    /// around each normal: [`emitter_importance`] (`φ · cos θ' / max(d²,
    /// R², MIN_D2)`, `θ'` the angle from the direction to `p` to the normal
    /// cone, less the angle the sphere subtends; 0 when `θ' ≥ θ_e`) times
    /// `max(cos θ'_i, 0)`, `θ'_i` the receiver's angle to the sphere's
    /// centre less the same subtended angle ([`cone_cos_toward`]). The
    /// receiver is one-sided (reflection only; pbrt-v4 takes `|cos|` for
    /// transmission), so only lights wholly below its horizon get 0.
    ///
    /// [`emitter_cone`] once for both halves rather than
    /// [`emitter_importance`] times [`cone_cos_toward`] (the same values):
    /// the subtended angle is computed once, and the receiver's term not at
    /// all where the emitter's is 0, as pbrt-v4 does; the light BVH's walk
    /// calls this twice per level.
    pub fn light_importance(center: vec3f, radius: f32, phi: f32, axis: vec3f, cos_o: f32, cos_e: f32, p: vec3f, n: vec3f) -> f32 {
        let c: vec4f = emitter_cone(center, radius, axis, cos_o, p);
        if c.x <= cos_e {
            return 0.0;
        }
        let mut imp: f32 = phi * c.x / c.y;
        if dot(n, n) > 0.0 {
            // The direction from p to the centre.
            let v: vec3f = center - p;
            let dist2: f32 = dot(v, v);
            let cos_i: f32 = dot(select(vec3f(0.0, 0.0, 0.0), v / sqrt(dist2), dist2 > 0.0), n);
            imp = imp * max(cos_sub_clamped(safe_sqrt(1.0 - cos_i * cos_i), cos_i, c.w, c.z), 0.0);
        }
        return max(imp, 0.0);
    }

    /// [`light_importance`] for a glossy receiver at `p` with normal `n`,
    /// mirror direction `r` (the view reflected about `n`) and lobe `lobe`
    /// ([`crate::brdf::receiver_lobe`]: diffuse and specular albedo, `α`,
    /// `n·v`): [`emitter_importance`] times a bound of `f cos` toward the
    /// sphere, `k_d/π · cos θ'_i + k_s · D(cos θ'_h) / (4 √(n·v²(1−α²)+α²))`
    /// with `θ'_h` half the angle from `r` to the sphere
    /// ([`cone_cos_toward`]; the half vector turns by half as much as the
    /// light for a view along the normal) and the lobe's `V · n·l` at the
    /// mirror direction; 0 only where the light is wholly below the horizon
    /// or outside its emission cone (GGX's `D` is positive wherever the
    /// half vector is above the surface). Beyond pbrt-v4, whose bound is
    /// the cosine alone; in the spirit of Tokuyoshi et al., "Hierarchical
    /// Light Sampling with Accurate Spherical Gaussian Lighting" (SIGGRAPH
    /// Asia 2024), whose receivers weigh lights by their BRDF lobe.
    pub fn glossy_importance(center: vec3f, radius: f32, phi: f32, axis: vec3f, cos_o: f32, cos_e: f32, p: vec3f, n: vec3f, r: vec3f, lobe: vec4f) -> f32 {
        let e: f32 = emitter_importance(center, radius, phi, axis, cos_o, cos_e, p);
        let ci: f32 = cone_cos_toward(center, radius, p, n);
        if e <= 0.0 || ci <= 0.0 {
            return 0.0;
        }
        let cos_h: f32 = safe_sqrt(0.5 + 0.5 * cone_cos_toward(center, radius, p, r));
        let spec: f32 = lobe.y * ggx_d(cos_h, 1.0 - cos_h * cos_h, lobe.z) * 0.25 / smith_root(lobe.w, lobe.z);
        return e * (lobe.x * INV_PI * ci + spec);
    }

    /// The importance a receiver with lobe `lobe` gives the bounded lights
    /// at `p` (normal `n`, mirror direction `r`): [`light_importance`] for
    /// a receiver without a specular lobe (`lobe.y = 0`: Lambertian, or
    /// seen from below), else [`glossy_importance`].
    pub fn receiver_importance(center: vec3f, radius: f32, phi: f32, axis: vec3f, cos_o: f32, cos_e: f32, p: vec3f, n: vec3f, r: vec3f, lobe: vec4f) -> f32 {
        if lobe.y <= 0.0 {
            return light_importance(center, radius, phi, axis, cos_o, cos_e, p, n);
        }
        return glossy_importance(center, radius, phi, axis, cos_o, cos_e, p, n, r, lobe);
    }

    /// `slc-weighted`'s weight of an in-range candidate of importance
    /// `importance`, threshold range² `rt2` and squared distance `d2` from
    /// the point to its bound's centre: `ĝ / p = ĝ · max(d²/r_t², 1)`.
    pub fn candidate_weight(importance: f32, rt2: f32, d2: f32) -> f32 {
        return importance * slc_weight(rt2, d2);
    }

    /// [`candidate_weight`] of a light bounded by the cone `(center,
    /// radius, phi, axis, cos_o, cos_e)` at `p` (normal `n`, mirror
    /// direction `r`, lobe `lobe`) for threshold range² `rt2`: its
    /// importance over its roulette probability at the centre. A receiver
    /// without a specular lobe weighs [`light_importance`] by the
    /// Lambertian `1/π` (the same for every candidate; it keeps `W` on the
    /// radiance's scale); a glossy one by [`glossy_importance`], which
    /// holds its lobes' albedos.
    pub fn cone_weight(center: vec3f, radius: f32, phi: f32, axis: vec3f, cos_o: f32, cos_e: f32, rt2: f32, p: vec3f, n: vec3f, r: vec3f, lobe: vec4f) -> f32 {
        let v: vec3f = p - center;
        if lobe.y <= 0.0 {
            return candidate_weight(light_importance(center, radius, phi, axis, cos_o, cos_e, p, n) * INV_PI, rt2, dot(v, v));
        }
        return candidate_weight(glossy_importance(center, radius, phi, axis, cos_o, cos_e, p, n, r, lobe), rt2, dot(v, v));
    }

    /// Expected number of times `k` independent one-slot weighted
    /// reservoirs pick a light of weight `w` at a point whose candidates
    /// weigh `w_sum` in all (this light included iff `in_range`):
    /// `k · w / (W₋ⱼ + w)`; 0 for `w ≤ 0` (never picked).
    pub fn weighted_select_pdf(w: f32, w_sum: f32, in_range: bool, k: u32) -> f32 {
        if w <= 0.0 {
            return 0.0;
        }
        let total: f32 = select(w_sum + w, w_sum, in_range);
        return to_f32(k) * w / total;
    }
}

/// Bounds of one light for [`light_importance`]: a sphere holding it, its
/// power `φ` (the max channel of [`Light::power`]), the cone of its emitter
/// normals `(axis, cos θ_o)` and the spread `cos θ_e` of emission around
/// each normal, as pbrt-v4 bounds lights: a triangle `θ_o = 0, θ_e = π/2`
/// (one-sided); a VPL the same about its normal; a spot light
/// `θ_o = θ_inner, θ_e = θ_outer − θ_inner` (at least 2.6°); point and IES lights the whole
/// sphere (`θ_o = π`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightCone {
    /// Bounding-sphere centre.
    pub center: Vec3,
    /// Bounding-sphere radius.
    pub radius: f32,
    /// Emitted power (max channel).
    pub phi: f32,
    /// Axis of the normal cone.
    pub axis: Vec3,
    /// Cosine of the normal cone's half-angle.
    pub cos_o: f32,
    /// Cosine of the emission spread around each normal.
    pub cos_e: f32,
}

impl LightCone {
    /// The cone of `l` emitting `power` (its [`Light::power`]), inside its
    /// range-sphere bound ([`Light::bound`]: a triangle's minimal sphere).
    pub fn of_light(l: &Light, power: Vec3) -> LightCone {
        let b = l.bound();
        let phi = power.max_element();
        let cone = |axis: Vec3, cos_o: f32, cos_e: f32| LightCone {
            center: b.center,
            radius: b.extent,
            phi,
            axis,
            cos_o,
            cos_e,
        };
        match l {
            Light::Triangle(t) => cone(t.normal(), 1.0, 0.0),
            Light::Vpl(v) => cone(v.normal(), 1.0, 0.0),
            Light::Spot(s) => {
                let (cos_outer, cos_inner) = s.cone_cosines();
                let (co, ci) = (cos_outer.clamp(-1.0, 1.0), cos_inner.clamp(-1.0, 1.0));
                // cos(θ_outer − θ_inner) without trigonometry, at most
                // 0.999 (θ_e ≥ 2.6°): a hard-edged spot (θ_e = 0) rounds
                // to 1 and would get importance 0 inside its beam, where
                // cos θ' = 1 ≤ cos θ_e (pbrt-v4 allows the same slop).
                let cos_e =
                    (co * ci + safe_sqrt(1.0 - co * co) * safe_sqrt(1.0 - ci * ci)).min(0.999);
                cone(s.direction(), ci, cos_e)
            }
            Light::Point(_) | Light::Ies(_) => cone(Vec3::Z, -1.0, 0.0),
        }
    }

    /// [`light_importance`] of this light at `p` with receiver normal `n`.
    pub fn importance(&self, p: Vec3, n: Vec3) -> f32 {
        light_importance(
            self.center,
            self.radius,
            self.phi,
            self.axis,
            self.cos_o,
            self.cos_e,
            p,
            n,
        )
    }

    /// `slc-weighted`'s [`cone_weight`] of this light for the receiver `rc`
    /// and threshold range² `rt2`.
    pub fn weight(&self, rc: &Receiver, rt2: f32) -> f32 {
        cone_weight(
            self.center,
            self.radius,
            self.phi,
            self.axis,
            self.cos_o,
            self.cos_e,
            rt2,
            rc.p,
            rc.n,
            rc.r,
            rc.lobe,
        )
    }
}

/// A shading point as light selection sees it: position `p`, unit shading
/// normal `n`, mirror direction `r` of the view and the BRDF lobe
/// ([`crate::brdf::receiver_lobe`]). The shared functions take the four
/// fields one by one; this keeps them together on the CPU.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Receiver {
    /// Position.
    pub p: Vec3,
    /// Unit shading normal (zero: no receiver normal, as pbrt-v4 allows).
    pub n: Vec3,
    /// The view direction mirrored about `n` (unused for a Lambertian lobe).
    pub r: Vec3,
    /// `(k_d, k_s, α, n·v)`; `k_s = 0` for a Lambertian receiver.
    pub lobe: glam::Vec4,
}

impl Receiver {
    /// A Lambertian receiver at `p` with normal `n`.
    pub fn lambertian(p: Vec3, n: Vec3) -> Receiver {
        Receiver { p, n, r: n, lobe: glam::Vec4::new(1.0, 0.0, 1.0, 1.0) }
    }

    /// The largest factor by which this receiver scales SLC's ranges²
    /// ([`crate::brdf::range_scale`]; 1 for a Lambertian receiver).
    pub fn range_scale(&self) -> f32 {
        crate::brdf::range_scale(self.lobe)
    }

    /// This receiver's [`crate::brdf::range_lobe`].
    pub fn range_lobe(&self) -> glam::Vec4 {
        crate::brdf::range_lobe(self.lobe)
    }

    /// The factor by which this receiver scales the ranges² of the light
    /// bounded by `cone` ([`range_scale_toward`] over its bounding sphere,
    /// with `rl` this receiver's [`Receiver::range_lobe`]).
    pub fn range_scale_to(&self, rl: glam::Vec4, cone: &LightCone) -> f32 {
        range_scale_toward(rl, cone.center, cone.radius, self.p, self.r)
    }

    /// [`receiver_importance`] of the light bounded by `cone`.
    pub fn importance(&self, cone: &LightCone) -> f32 {
        receiver_importance(
            cone.center,
            cone.radius,
            cone.phi,
            cone.axis,
            cone.cos_o,
            cone.cos_e,
            self.p,
            self.n,
            self.r,
            self.lobe,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::light::{PointLight, TriangleLight};

    #[test]
    fn importance_is_zero_only_where_nothing_can_arrive() {
        let t = Light::Triangle(
            TriangleLight::new(Vec3::ZERO, Vec3::X * 0.1, Vec3::Z * 0.1, Vec3::ONE).unwrap(),
        );
        let c = LightCone::of_light(&t, t.power());
        let up = if c.axis.y > 0.0 { 1.0 } else { -1.0 };
        // In front of the emitter, facing it: positive; nearer is larger.
        let near = c.importance(Vec3::new(0.0, up, 0.0), Vec3::new(0.0, -up, 0.0));
        let far = c.importance(Vec3::new(0.0, 3.0 * up, 0.0), Vec3::new(0.0, -up, 0.0));
        assert!(near > far && far > 0.0, "{near} {far}");
        // Behind the one-sided emitter: 0; receiver facing away: 0.
        assert_eq!(c.importance(Vec3::new(0.0, -up, 0.0), Vec3::new(0.0, up, 0.0)), 0.0);
        assert_eq!(c.importance(Vec3::new(0.0, up, 0.0), Vec3::new(0.0, up, 0.0)), 0.0);
        // A point in the emitter's plane, its normal on the emitting side:
        // the centre lies on both horizons, yet the subtended angle widens
        // both cosines, so the (near) light keeps a positive importance.
        assert!(c.importance(Vec3::new(0.3, 0.0, 0.05), Vec3::new(0.0, up, 0.0)) > 0.0);
        // A point light at the receiver itself: finite.
        let p = Light::Point(PointLight::new(Vec3::ONE, Vec3::ONE).unwrap());
        let pc = LightCone::of_light(&p, p.power());
        assert!(pc.importance(Vec3::ONE, Vec3::Y).is_finite());
    }

    /// [`light_importance`] written out equals [`emitter_importance`] times
    /// the receiver's widened cosine ([`cone_cos_toward`]) up to the
    /// rounding of the receiver's sine (`√(1 − cos²)` in the former, as
    /// pbrt-v4 computes it, `|v × n|/|v|` in the latter).
    #[test]
    fn light_importance_is_the_product_of_its_halves() {
        let mut worst = 0.0f32;
        let mut s = 99u32;
        let mut r = || {
            s = s.wrapping_mul(1664525).wrapping_add(1013904223);
            (s >> 8) as f32 / (1u32 << 24) as f32
        };
        for k in 0..20_000 {
            let center = Vec3::new(r(), r(), r()) * 2.0;
            let radius = if k % 5 == 0 { 0.0 } else { r() * r() };
            let axis = Vec3::new(r() - 0.5, r() - 0.5, r() - 0.5).normalize_or(Vec3::Y);
            let (cos_o, cos_e) = (2.0 * r() - 1.0, if k % 3 == 0 { 0.0 } else { r() });
            let p = if k % 7 == 0 { center } else { Vec3::new(r(), r(), r()) * 2.0 };
            let n = if k % 11 == 0 {
                Vec3::ZERO
            } else {
                Vec3::new(r() - 0.5, r() - 0.5, r() - 0.5).normalize_or(Vec3::X)
            };
            let phi = 0.1 + r();
            let mut want = emitter_importance(center, radius, phi, axis, cos_o, cos_e, p);
            if n != Vec3::ZERO {
                want *= cone_cos_toward(center, radius, p, n).max(0.0);
            }
            let got = light_importance(center, radius, phi, axis, cos_o, cos_e, p, n);
            worst = worst.max((got - want.max(0.0)).abs() / want.abs().max(1e-30));
        }
        // √(1 − cos²) (pbrt-v4's `SafeSqrt`) keeps half the digits where the
        // centre lies near the normal: 0.4% here.
        assert!(worst < 1e-2, "relative difference up to {worst}");
    }

    /// A spot light of equal inner and outer angles (a hard-edged beam,
    /// `θ_e = 0`) keeps a positive importance inside its beam, where it
    /// lights the point: `cos θ_e` rounded to 1 would make `cos θ' ≤ cos θ_e`
    /// everywhere (pbrt-v4 gives such a spot `cos θ_e = 0.999` when its
    /// angles differ, and 1, that is never sampled, when they are equal).
    #[test]
    fn hard_edged_spot_lights_its_beam() {
        use crate::light::SpotLight;
        for a in [0.01f32, 0.2, 0.5, 0.8, 1.0, 1.3] {
            for (inner, outer) in [(a, a), (a, a + 1e-6), (a * 0.999, a)] {
                let s = Light::Spot(
                    SpotLight::new(Vec3::ZERO, Vec3::NEG_Y, Vec3::ONE, inner, outer).unwrap(),
                );
                let c = LightCone::of_light(&s, s.power());
                let p = Vec3::new(0.0, -2.0, 0.0);
                assert!(s.contribution_at(p).0.max_element() > 0.0);
                assert!(c.importance(p, Vec3::Y) > 0.0, "spot {inner} {outer}: cos_e {}", c.cos_e);
            }
        }
    }

    #[test]
    fn select_pdf_is_that_of_the_other_candidates() {
        // In range: the light is part of W; out of range: added to it.
        assert_eq!(weighted_select_pdf(1.0, 4.0, true, 2), 0.5);
        assert_eq!(weighted_select_pdf(1.0, 3.0, false, 2), 0.5);
        assert_eq!(weighted_select_pdf(0.0, 3.0, false, 2), 0.0);
        // Alone and out of range: certain per slot.
        assert_eq!(weighted_select_pdf(2.0, 0.0, false, 1), 1.0);
    }
}
