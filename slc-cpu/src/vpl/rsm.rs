//! Reflective shadow map (Dachsbacher & Stamminger 2005): every texel of a
//! map rendered from the primary light becomes a VPL at the surface it sees,
//! with the flux that surface reflects.

use crate::geometry::Geometry;
use glam::Vec3;
use rayon::prelude::*;
use slc_core::light::Light;
use slc_core::ray::face_against;
use slc_scene::scene::{PrimaryLight, Scene};
use slc_scene::vpl::Vpls;

/// Renders the `size × size` RSM of the scene's primary light.
pub fn reflective_shadow_map(scene: &Scene, geo: &Geometry, size: u32) -> Vpls {
    let n = size as usize * size as usize;
    let res = size as f32;
    let diag = scene.diagonal();
    let texels: Vec<(Vec3, Vec3, Vec3)> = match scene.primary {
        PrimaryLight::Spot { position, direction, outer, .. } => {
            let spot = Light::Spot(scene.primary.spot().expect("validated scene"));
            let helper = if direction.y.abs() < 0.9 { Vec3::Y } else { Vec3::X };
            let r = direction.cross(helper).normalize();
            let u = r.cross(direction);
            let tan = outer.tan();
            let texel_area = (2.0 * tan / res).powi(2);
            (0..n)
                .into_par_iter()
                .map(|i| {
                    let (tx, ty) = ((i % size as usize) as f32, (i / size as usize) as f32);
                    let s = (2.0 * (tx + 0.5) / res - 1.0) * tan;
                    let t = (2.0 * (ty + 0.5) / res - 1.0) * tan;
                    let q = 1.0 + s * s + t * t;
                    let dir = (direction + r * s + u * t) / q.sqrt();
                    // Solid angle of the texel on the image plane at distance 1.
                    let d_omega = texel_area / (q * q.sqrt());
                    hit_texel(scene, geo, position, dir, spot.intensity(dir) * d_omega, diag)
                })
                .collect()
        }
        PrimaryLight::Directional { direction, irradiance } => {
            let d = direction.normalize();
            let helper = if d.y.abs() < 0.9 { Vec3::Y } else { Vec3::X };
            let r = d.cross(helper).normalize();
            let u = r.cross(d);
            let (lo, hi) = scene.bounds();
            let c = (lo + hi) * 0.5;
            let half = 0.5 * (hi - lo).length();
            let texel = 2.0 * half / res;
            (0..n)
                .into_par_iter()
                .map(|i| {
                    let (tx, ty) = ((i % size as usize) as f32, (i / size as usize) as f32);
                    let o = c + r * ((tx + 0.5) * texel - half) + u * ((ty + 0.5) * texel - half) - d * (2.0 * half);
                    hit_texel(scene, geo, o, d, irradiance * texel * texel, diag)
                })
                .collect()
        }
    };
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
    match geo.intersect(origin, dir, 1e-5 * diag, f32::INFINITY) {
        Some(h) => {
            let gn = face_against(geo.normal(h.triangle), dir);
            let p = origin + dir * h.t;
            let albedo = scene.materials[scene.material_of[h.triangle as usize] as usize].albedo;
            (p, scene.shading_normal(h.triangle as usize, p, gn), incident * albedo)
        }
        None => (origin, -dir, Vec3::ZERO),
    }
}
