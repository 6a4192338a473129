//! Reflective shadow map (Dachsbacher & Stamminger 2005): every texel of a
//! map rendered from the primary light becomes a VPL at the surface it sees,
//! with the flux that surface reflects.

use crate::geometry::Geometry;
use glam::Vec3;
use rayon::prelude::*;
use slc_core::light::Light;
use slc_core::ray::{face_against, surface_offset};
use slc_scene::scene::{PrimaryLight, Scene};
use slc_scene::vpl::Vpls;

/// Renders the `size × size` RSM of the scene's primary light: one ray per
/// texel of its [`LightMap`](slc_scene::scene::LightMap), carrying the
/// intensity toward the texel times its solid angle (spot) or the
/// irradiance times its area (directional).
pub fn reflective_shadow_map(scene: &Scene, geo: &Geometry, size: u32) -> Vpls {
    let n = size as usize * size as usize;
    let diag = scene.diagonal();
    let map = scene.primary.light_map(scene.bounds());
    let spot = scene.primary.spot().map(Light::Spot);
    let texels: Vec<(Vec3, Vec3, Vec3)> = (0..n)
        .into_par_iter()
        .map(|i| {
            let (tx, ty) = ((i % size as usize) as u32, (i / size as usize) as u32);
            let (origin, dir, gathered) = map.texel_ray(tx, ty, size);
            let incident = match scene.primary {
                // A spot light's parameters are checked when the scene is.
                PrimaryLight::Spot { .. } => spot.as_ref().map_or(Vec3::ZERO, |s| s.intensity(dir)) * gathered,
                PrimaryLight::Directional { irradiance, .. } => irradiance * gathered,
            };
            hit_texel(scene, geo, origin, dir, incident, diag)
        })
        .collect();
    Vpls {
        size,
        position: texels.iter().map(|t| t.0).collect(),
        normal: texels.iter().map(|t| t.1).collect(),
        flux: texels.iter().map(|t| t.2).collect(),
    }
}

/// The VPL a texel makes: its hit point, normal toward the light, and the
/// incident flux times the surface albedo.
fn hit_texel(scene: &Scene, geo: &Geometry, origin: Vec3, dir: Vec3, incident: Vec3, diag: f32) -> (Vec3, Vec3, Vec3) {
    match geo.intersect(origin, dir, surface_offset(diag), f32::INFINITY) {
        Some(h) => {
            let gn = face_against(geo.normal(h.triangle), dir);
            let p = origin + dir * h.t;
            let albedo = scene.materials[scene.material_of[h.triangle as usize] as usize].albedo;
            (p, scene.shading_normal(h.triangle as usize, p, gn), incident * albedo)
        }
        None => (origin, -dir, Vec3::ZERO),
    }
}
