//! The G-buffer by ray casting: what the camera sees at each pixel.

use crate::geometry::Geometry;
use glam::Vec3;
use rayon::prelude::*;
use slc_core::ray::face_against;
use slc_scene::scene::Scene;
use slc_scene::vpl::GBuffer;

/// Casts one primary ray per pixel centre. The G-buffer's normal is the
/// shading normal (interpolated vertex normals where the scene has them),
/// flipped to face the camera; the second vector holds each pixel's
/// geometric normal on the same side (for ray offsets).
pub fn render_gbuffer(scene: &Scene, geo: &Geometry, width: u32, height: u32) -> (GBuffer, Vec<Vec3>) {
    let n = width as usize * height as usize;
    let px: Vec<(Vec3, Vec3, Vec3, Vec3, f32, Vec3)> = (0..n)
        .into_par_iter()
        .map(|i| {
            let (x, y) = ((i % width as usize) as f32, (i / width as usize) as f32);
            let dir = scene.camera.ray_dir(x, y, width, height);
            match geo.intersect(scene.camera.position, dir, 0.0, f32::INFINITY) {
                Some(h) => {
                    let p = scene.camera.position + dir * h.t;
                    let gn = face_against(geo.normal(h.triangle), dir);
                    let sn = scene.shading_normal(h.triangle as usize, p, gn);
                    let m = scene.materials[scene.material_of[h.triangle as usize] as usize];
                    (p, sn, m.albedo, m.emission, h.t, gn)
                }
                None => (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, f32::INFINITY, Vec3::ZERO),
            }
        })
        .collect();
    let gb = GBuffer {
        width,
        height,
        position: px.iter().map(|p| p.0).collect(),
        normal: px.iter().map(|p| p.1).collect(),
        albedo: px.iter().map(|p| p.2).collect(),
        emission: px.iter().map(|p| p.3).collect(),
        depth: px.iter().map(|p| p.4).collect(),
    };
    (gb, px.iter().map(|p| p.5).collect())
}
