//! Ray casting against the scene's triangles through obvhs's compressed
//! wide BVH (CWBVH; works with glam, maintained, fast on the CPU). Used for
//! the G-buffer, the reflective shadow map and shadow rays.

use glam::{Vec3, Vec3A};
use obvhs::BvhBuildParams;
use obvhs::cwbvh::CwBvh;
use obvhs::cwbvh::builder::build_cwbvh_from_tris;
use obvhs::ray::{Ray, RayHit};
use obvhs::triangle::Triangle;
use std::time::Duration;

/// A closest hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Ray parameter (distance for unit directions).
    pub t: f32,
    /// Index of the triangle in the scene.
    pub triangle: u32,
}

/// The scene's triangles in a BVH.
pub struct Geometry {
    tris: Vec<Triangle>,
    normals: Vec<Vec3>,
    bvh: CwBvh,
}

impl Geometry {
    /// Builds the BVH over `triangles`.
    pub fn new(triangles: &[[Vec3; 3]]) -> Self {
        let tris: Vec<Triangle> = triangles
            .iter()
            .map(|t| Triangle { v0: t[0].into(), v1: t[1].into(), v2: t[2].into() })
            .collect();
        let normals =
            triangles.iter().map(|t| slc_core::ray::triangle_normal(t[0], t[1], t[2])).collect();
        let bvh =
            build_cwbvh_from_tris(&tris, BvhBuildParams::medium_build(), &mut Duration::default());
        Geometry { tris, normals, bvh }
    }

    /// Closest hit along `origin + t·dir`, `t ∈ (t_min, t_max)`.
    pub fn intersect(&self, origin: Vec3, dir: Vec3, t_min: f32, t_max: f32) -> Option<Hit> {
        if self.tris.is_empty() {
            return None;
        }
        let ray = Ray::new(Vec3A::from(origin), Vec3A::from(dir), t_min, t_max);
        let mut hit = RayHit::none();
        let idx = &self.bvh.primitive_indices;
        if self.bvh.ray_traverse(ray, &mut hit, |r, id| self.tris[idx[id] as usize].intersect(r)) {
            Some(Hit { t: hit.t, triangle: idx[hit.primitive_id as usize] })
        } else {
            None
        }
    }

    /// The ray `origin + t·dir`, `t ∈ [t_min, t_max]`, for [`Geometry::hit_t`].
    pub fn ray(origin: Vec3, dir: Vec3, t_min: f32, t_max: f32) -> Ray {
        Ray::new(Vec3A::from(origin), Vec3A::from(dir), t_min, t_max)
    }

    /// Distance along `ray` to triangle `tri` (∞ on a miss): the test
    /// [`Geometry::intersect`] runs on each BVH leaf's triangles.
    #[inline]
    pub fn hit_t(&self, tri: u32, ray: &Ray) -> f32 {
        self.tris[tri as usize].intersect(ray)
    }

    /// `true` when the open segment from `a` to `b` hits a triangle (a
    /// relative epsilon keeps the end points' own surfaces out).
    pub fn occluded(&self, a: Vec3, b: Vec3) -> bool {
        if self.tris.is_empty() {
            return false;
        }
        let Some(ray) = Self::segment(a, b) else { return false };
        let idx = &self.bvh.primitive_indices;
        !self.bvh.ray_traverse_miss(ray, |r, id| self.tris[idx[id] as usize].intersect(r))
    }

    /// The ray [`Geometry::occluded`] tests for the segment from `a` to `b`:
    /// unit direction, `t` within [`slc_core::ray::shadow_margin`] of both
    /// ends; `None` for a degenerate segment (nothing blocks it).
    pub fn segment(a: Vec3, b: Vec3) -> Option<Ray> {
        let d = b - a;
        let len = d.length();
        if !(len > 0.0) {
            return None;
        }
        let eps = slc_core::ray::shadow_margin(len);
        Some(Ray::new(Vec3A::from(a), Vec3A::from(d / len), eps, len - eps))
    }

    /// `true` when triangle `tri` blocks the segment `ray` (from
    /// [`Geometry::segment`]): the test [`Geometry::occluded`] runs per leaf.
    #[inline]
    pub fn blocks(&self, tri: u32, ray: &Ray) -> bool {
        self.hit_t(tri, ray) < ray.tmax
    }

    /// Geometric unit normal of triangle `i` (from its winding).
    pub fn normal(&self, i: u32) -> Vec3 {
        self.normals[i as usize]
    }
}
