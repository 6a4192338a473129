//! Ray–box and ray–triangle intersection, written once for the GPU's
//! geometry BVH (the CPU backend casts rays through obvhs).

use crate::wgsl::*;

crate::shared! {
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
