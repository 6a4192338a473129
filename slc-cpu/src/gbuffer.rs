//! The G-buffer: what the camera sees at each pixel.

use crate::geometry::Geometry;
use crate::scene::Scene;
use glam::Vec3;
use rayon::prelude::*;

/// Per-pixel surface attributes (row-major, y down). Pixels that see no
/// surface have `depth = ∞` and zero attributes.
#[derive(Clone, Debug, PartialEq)]
pub struct GBuffer {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// World position of the visible surface.
    pub position: Vec<Vec3>,
    /// Unit normal, flipped to face the camera.
    pub normal: Vec<Vec3>,
    /// Diffuse albedo.
    pub albedo: Vec<Vec3>,
    /// Emitted radiance.
    pub emission: Vec<Vec3>,
    /// Distance from the camera (∞ for background).
    pub depth: Vec<f32>,
}

impl GBuffer {
    /// Casts one primary ray per pixel centre.
    pub fn render(scene: &Scene, geo: &Geometry, width: u32, height: u32) -> GBuffer {
        let n = width as usize * height as usize;
        let px: Vec<(Vec3, Vec3, Vec3, Vec3, f32)> = (0..n)
            .into_par_iter()
            .map(|i| {
                let (x, y) = ((i % width as usize) as f32, (i / width as usize) as f32);
                let dir = scene.camera.ray_dir(x, y, width, height);
                match geo.intersect(scene.camera.position, dir, 0.0, f32::INFINITY) {
                    Some(h) => {
                        let p = scene.camera.position + dir * h.t;
                        let mut nrm = geo.normal(h.triangle);
                        if nrm.dot(dir) > 0.0 {
                            nrm = -nrm;
                        }
                        let m = scene.materials[scene.material_of[h.triangle as usize] as usize];
                        (p, nrm, m.albedo, m.emission, h.t)
                    }
                    None => (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, f32::INFINITY),
                }
            })
            .collect();
        GBuffer {
            width,
            height,
            position: px.iter().map(|p| p.0).collect(),
            normal: px.iter().map(|p| p.1).collect(),
            albedo: px.iter().map(|p| p.2).collect(),
            emission: px.iter().map(|p| p.3).collect(),
            depth: px.iter().map(|p| p.4).collect(),
        }
    }

    /// `true` where the pixel sees a surface.
    pub fn valid(&self, i: usize) -> bool {
        self.depth[i].is_finite()
    }
}
