//! Ray–box and ray–triangle intersection, written once for the GPU's
//! geometry BVH (the CPU backend casts rays through obvhs), and the surface
//! at a hit: barycentrics and the interpolated shading normal both
//! backends use.

use crate::wgsl::*;

crate::shared! {
    /// The largest finite `f32`: the far end of an unbounded ray, the
    /// bounds of an empty box, and the finiteness test's limit.
    pub const F32_MAX: f32 = 3.4028235e38;

    /// `true` when every component of `v` is finite (NaN compares false):
    /// a contribution that is not is dropped, a point that is not is no
    /// surface.
    pub fn finite3(v: vec3f) -> bool {
        return abs(v.x) <= F32_MAX && abs(v.y) <= F32_MAX && abs(v.z) <= F32_MAX;
    }

    /// How far a ray leaving a surface starts from it, along the geometric
    /// normal facing the ray: `10⁻⁵` of the scene's bounding-box diagonal
    /// (path tracers' bounces and light connections, the VPL reference's and
    /// the RSM's rays).
    pub fn surface_offset(diag: f32) -> f32 {
        return 0.00001 * diag;
    }

    /// The nearest hit a path's ray accepts, `10⁻⁶·diag`.
    pub fn ray_t_min(diag: f32) -> f32 {
        return 0.000001 * diag;
    }

    /// Margin kept free at both ends of a shadow segment of length `len`,
    /// `10⁻⁴·len`, so the end points' own surfaces do not occlude it.
    pub fn shadow_margin(len: f32) -> f32 {
        return 0.0001 * len;
    }

    /// `1/x`, with `|x| < 10⁻³⁰` (zero included) taken as `10⁻³⁰`: a ray
    /// direction's inverse for the slab test, finite for an axis-parallel ray.
    pub fn ray_inverse(x: f32) -> f32 {
        return 1.0 / select(x, 0.000000000000000000000000000001, abs(x) < 0.000000000000000000000000000001);
    }

    /// [`ray_inverse`] of each component of `d`.
    pub fn ray_inverse3(d: vec3f) -> vec3f {
        return vec3f(ray_inverse(d.x), ray_inverse(d.y), ray_inverse(d.z));
    }

    /// Entry distance of a ray `o + t·d` (with `inv_d = 1/d`) into the box
    /// `[bmin, bmax]` within `[0, t_max]`, or `-1` when it misses (slab test,
    /// Kay & Kajiya 1986).
    pub fn ray_aabb(o: vec3f, inv_d: vec3f, bmin: vec3f, bmax: vec3f, t_max: f32) -> f32 {
        let t0: vec3f = (bmin - o) * inv_d;
        let t1: vec3f = (bmax - o) * inv_d;
        let lo: vec3f = min(t0, t1);
        let hi: vec3f = max(t0, t1);
        let t_in: f32 = max(max(lo.x, lo.y), max(lo.z, 0.0));
        let t_out: f32 = min(min(hi.x, hi.y), min(hi.z, t_max));
        if t_in <= t_out {
            return t_in;
        }
        return -1.0;
    }

    /// Unit geometric normal of triangle (a, b, c) from its winding,
    /// `normalize((b − a) × (c − a))`, or zero for a degenerate triangle.
    pub fn triangle_normal(a: vec3f, b: vec3f, c: vec3f) -> vec3f {
        let n: vec3f = cross(b - a, c - a);
        let l2: f32 = dot(n, n);
        if !(l2 > 0.0) || !(l2 < 3.0e38) {
            return vec3f(0.0, 0.0, 0.0);
        }
        return n / sqrt(l2);
    }

    /// `n` turned to face against the ray direction `dir` (toward where the
    /// ray came from): `-n` when `n · dir > 0`.
    pub fn face_against(n: vec3f, dir: vec3f) -> vec3f {
        return select(n, -n, dot(n, dir) > 0.0);
    }

    /// Barycentric coordinates `(w₀, w₁, w₂)` of `p` (projected onto the
    /// plane of triangle (a, b, c)), `p ≈ w₀a + w₁b + w₂c` (Ericson, *Real-Time
    /// Collision Detection*, §3.4); `(1, 0, 0)` for a degenerate triangle.
    pub fn barycentric(p: vec3f, a: vec3f, b: vec3f, c: vec3f) -> vec3f {
        let e1: vec3f = b - a;
        let e2: vec3f = c - a;
        let q: vec3f = p - a;
        let d11: f32 = dot(e1, e1);
        let d12: f32 = dot(e1, e2);
        let d22: f32 = dot(e2, e2);
        let den: f32 = d11 * d22 - d12 * d12;
        if !(abs(den) > 0.0) {
            return vec3f(1.0, 0.0, 0.0);
        }
        let w1: f32 = (d22 * dot(q, e1) - d12 * dot(q, e2)) / den;
        let w2: f32 = (d11 * dot(q, e2) - d12 * dot(q, e1)) / den;
        return vec3f(1.0 - w1 - w2, w1, w2);
    }

    /// Shading normal from unit vertex normals `n0, n1, n2` at barycentrics
    /// `w`: `normalize(w₀n₀ + w₁n₁ + w₂n₂)`, turned to the side of `facing`
    /// (the geometric normal oriented toward the incoming ray), or `facing`
    /// itself where the sum vanishes or is not finite (Phong normal
    /// interpolation; Pharr, Jakob & Humphreys, *PBRT* 4th ed., §6.5.3).
    pub fn shading_normal(n0: vec3f, n1: vec3f, n2: vec3f, w: vec3f, facing: vec3f) -> vec3f {
        let s: vec3f = n0 * w.x + n1 * w.y + n2 * w.z;
        let l2: f32 = dot(s, s);
        if !(l2 > 1e-12) || !(l2 < 3.0e38) {
            return facing;
        }
        let n: vec3f = s / sqrt(l2);
        return select(n, -n, dot(n, facing) < 0.0);
    }

    /// Distance along `o + t·d` to triangle (a, b, c), or `-1` for a miss or
    /// `t ∉ (t_min, t_max)` (Möller & Trumbore 1997, two-sided).
    pub fn ray_triangle(o: vec3f, d: vec3f, a: vec3f, b: vec3f, c: vec3f, t_min: f32, t_max: f32) -> f32 {
        let e1: vec3f = b - a;
        let e2: vec3f = c - a;
        let p: vec3f = cross(d, e2);
        let det: f32 = dot(e1, p);
        if abs(det) <= 0.0 {
            return -1.0;
        }
        let inv: f32 = 1.0 / det;
        let s: vec3f = o - a;
        let u: f32 = dot(s, p) * inv;
        if u < 0.0 || u > 1.0 {
            return -1.0;
        }
        let q: vec3f = cross(s, e1);
        let v: f32 = dot(d, q) * inv;
        if v < 0.0 || u + v > 1.0 {
            return -1.0;
        }
        let t: f32 = dot(e2, q) * inv;
        if t > t_min && t < t_max {
            return t;
        }
        return -1.0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn box_hits_and_misses() {
        let d = Vec3::new(1.0, 0.0, 0.0);
        let inv = Vec3::ONE / d;
        assert_eq!(ray_aabb(Vec3::new(-2.0, 0.5, 0.5), inv, Vec3::ZERO, Vec3::ONE, 10.0), 2.0);
        assert_eq!(ray_aabb(Vec3::new(-2.0, 1.5, 0.5), inv, Vec3::ZERO, Vec3::ONE, 10.0), -1.0);
        assert_eq!(ray_aabb(Vec3::new(-2.0, 0.5, 0.5), inv, Vec3::ZERO, Vec3::ONE, 1.0), -1.0);
        assert_eq!(ray_aabb(Vec3::splat(0.5), inv, Vec3::ZERO, Vec3::ONE, 1.0), 0.0);
    }

    #[test]
    fn barycentrics_and_shading_normals() {
        let (a, b, c) = (Vec3::ZERO, Vec3::X, Vec3::Y);
        let w = barycentric(Vec3::new(0.25, 0.5, 0.0), a, b, c);
        assert!((w - Vec3::new(0.25, 0.25, 0.5)).length() < 1e-6);
        assert_eq!(barycentric(Vec3::ONE, a, a, a), Vec3::X);
        let n1 = Vec3::new(0.6, 0.0, 0.8);
        let s = shading_normal(Vec3::Z, n1, Vec3::Z, Vec3::new(0.5, 0.5, 0.0), Vec3::Z);
        assert!((s - (Vec3::Z + n1).normalize()).length() < 1e-6);
        // Turned to the facing side; opposite normals that cancel give `facing`.
        assert!(shading_normal(-Vec3::Z, -Vec3::Z, -Vec3::Z, w, Vec3::Z).z > 0.99);
        assert_eq!(
            shading_normal(Vec3::Z, -Vec3::Z, Vec3::Z, Vec3::new(0.5, 0.5, 0.0), Vec3::Y),
            Vec3::Y
        );
        assert_eq!(shading_normal(Vec3::NAN, Vec3::Z, Vec3::Z, w, Vec3::Y), Vec3::Y);
        assert_eq!(triangle_normal(a, b, c), Vec3::Z);
        assert_eq!(triangle_normal(a, b, b), Vec3::ZERO);
        assert_eq!(face_against(Vec3::Z, Vec3::Z), -Vec3::Z);
        assert_eq!(face_against(Vec3::Z, -Vec3::Z), Vec3::Z);
    }

    #[test]
    fn triangle_hits_and_misses() {
        let (a, b, c) = (Vec3::ZERO, Vec3::X, Vec3::Y);
        let o = Vec3::new(0.25, 0.25, 1.0);
        assert_eq!(ray_triangle(o, -Vec3::Z, a, b, c, 0.0, 10.0), 1.0);
        assert_eq!(ray_triangle(o, Vec3::Z, a, b, c, 0.0, 10.0), -1.0);
        assert_eq!(ray_triangle(Vec3::new(0.8, 0.8, 1.0), -Vec3::Z, a, b, c, 0.0, 10.0), -1.0);
        assert_eq!(ray_triangle(o, -Vec3::Z, a, b, c, 0.0, 0.5), -1.0);
        assert_eq!(ray_triangle(o, Vec3::X, a, b, c, 0.0, 10.0), -1.0);
    }
}
