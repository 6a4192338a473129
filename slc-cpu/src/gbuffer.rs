//! The G-buffer: what the camera sees at each pixel centre.
//!
//! Visibility is rasterized ([`crate::raster::closest_hits`] through the
//! camera's pinhole): triangles binned to screen tiles, each tested with
//! the ray caster's own ray–triangle test against the primary rays of the
//! pixels its projection covers, the nearest kept. The result is the ray
//! caster's closest hit at the cost of a rasterizer: no BVH traversal per
//! pixel.

use crate::geometry::Geometry;
use crate::raster::{Pinhole, closest_hits};
use glam::Vec3;
use rayon::prelude::*;
use slc_core::ray::face_against;
use slc_scene::scene::Scene;
use slc_scene::vpl::{GBuffer, Specular};

/// Renders the G-buffer at every pixel centre. Its normal is the shading
/// normal (interpolated vertex normals where the scene has them), flipped to
/// face the camera; the second vector holds each pixel's geometric normal on
/// the same side (for ray offsets). Its specular lobes are filled only when
/// some material of the scene has one.
pub fn render_gbuffer(
    scene: &Scene,
    geo: &Geometry,
    width: u32,
    height: u32,
) -> (GBuffer, Vec<Vec3>) {
    let mut gb = GBuffer { width, height, ..GBuffer::default() };
    let mut geometric = Vec::new();
    render_gbuffer_into(scene, geo, &mut gb, &mut geometric);
    (gb, geometric)
}

/// [`render_gbuffer`] at `gb`'s size into `gb` and `geometric`, reusing
/// their memory when they already hold that many pixels (a frame loop's
/// case: no fresh pages for the kernel to fault in), else into new
/// buffers.
pub fn render_gbuffer_into(
    scene: &Scene,
    geo: &Geometry,
    gb: &mut GBuffer,
    geometric: &mut Vec<Vec3>,
) {
    let (w, h) = (gb.width as usize, gb.height as usize);
    let cam = &scene.camera;
    gb.eye = cam.position;
    let view = Pinhole::of(cam, gb.width, gb.height);
    let hits = closest_hits(&view, geo, &scene.triangles);
    type Texel = ((Vec3, Vec3), ((Vec3, Vec3), (f32, Vec3)));
    let texel = |x: usize, y: usize| -> Texel {
        let (t, tri) = hits.at(x, y);
        if tri == u32::MAX {
            return (
                (Vec3::ZERO, Vec3::ZERO),
                ((Vec3::ZERO, Vec3::ZERO), (f32::INFINITY, Vec3::ZERO)),
            );
        }
        let dir = view.dir(x, y);
        let p = cam.position + dir * t;
        let gn = face_against(geo.normal(tri), dir);
        let m = scene.materials[scene.material_of[tri as usize] as usize];
        ((p, scene.shading_normal(tri as usize, p, gn)), ((m.albedo, m.emission), (t, gn)))
    };
    let n = w * h;
    let sized = [
        gb.position.len(),
        gb.normal.len(),
        gb.albedo.len(),
        gb.emission.len(),
        gb.depth.len(),
        geometric.len(),
    ]
    .iter()
    .all(|&l| l == n);
    if sized && w > 0 {
        // Row by row: a pixel's coordinates without a division.
        (
            gb.position.par_chunks_mut(w),
            gb.normal.par_chunks_mut(w),
            gb.albedo.par_chunks_mut(w),
            gb.emission.par_chunks_mut(w),
            gb.depth.par_chunks_mut(w),
            geometric.par_chunks_mut(w),
        )
            .into_par_iter()
            .enumerate()
            .for_each(|(y, (p, nrm, a, e, d, g))| {
                for x in 0..w {
                    ((p[x], nrm[x]), ((a[x], e[x]), (d[x], g[x]))) = texel(x, y);
                }
            });
    } else {
        // One parallel pass writes every buffer straight into fresh memory
        // (a zero-filled buffer first would cost as much as the pass).
        type Buffers = ((Vec<Vec3>, Vec<Vec3>), ((Vec<Vec3>, Vec<Vec3>), (Vec<f32>, Vec<Vec3>)));
        let ((position, normal), ((albedo, emission), (depth, geo_n))): Buffers =
            (0..n).into_par_iter().map(|i| texel(i % w, i / w)).unzip();
        (gb.position, gb.normal, gb.albedo, gb.emission, gb.depth, *geometric) =
            (position, normal, albedo, emission, depth, geo_n);
    }
    // Each pixel's specular lobe, only where the scene has one (a
    // Lambertian scene's G-buffer holds none).
    if scene.materials.iter().any(|m| m.has_specular()) {
        let lobe = |i: usize| match hits.at(i % w, i / w).1 {
            u32::MAX => Specular::default(),
            tri => Specular::of(&scene.materials[scene.material_of[tri as usize] as usize]),
        };
        if gb.specular.len() == n {
            gb.specular.par_iter_mut().enumerate().for_each(|(i, s)| *s = lobe(i));
        } else {
            gb.specular = (0..n).into_par_iter().map(lobe).collect();
        }
    } else {
        gb.specular.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use slc_scene::scene::Camera;

    /// The rasterized visibility finds the BVH ray caster's closest hit at
    /// every pixel: same depth and normals, the same pixels empty. With the
    /// camera outside the open box, and inside it, where the walls cross
    /// the eye's plane (triangles binned to every tile).
    #[test]
    fn rasterized_visibility_equals_ray_casting() {
        let mut scene = Scene::cornell_box();
        let outside = scene.camera;
        let (lo, hi) = scene.bounds();
        let inside = Camera { position: (lo + hi) * 0.5, target: lo, ..outside };
        let geo = Geometry::new(&scene.triangles);
        for (camera, (w, h)) in [(outside, (67, 45)), (inside, (40, 64))] {
            scene.camera = camera;
            let (gb, geometric) = render_gbuffer(&scene, &geo, w, h);
            let mut hits = 0;
            for i in 0..(w * h) as usize {
                let (x, y) = ((i % w as usize) as f32, (i / w as usize) as f32);
                let dir = camera.ray_dir(x, y, w, h);
                match geo.intersect(camera.position, dir, 0.0, f32::INFINITY) {
                    Some(hit) => {
                        hits += 1;
                        assert!(
                            gb.valid(i) && (gb.depth[i] - hit.t).abs() <= 1e-6 * hit.t,
                            "pixel {i}: depth {} vs {}",
                            gb.depth[i],
                            hit.t
                        );
                        assert!(
                            geometric[i].dot(face_against(geo.normal(hit.triangle), dir)) > 0.999,
                            "pixel {i}: geometric normal"
                        );
                    }
                    None => assert!(!gb.valid(i), "pixel {i}: hit where the ray caster misses"),
                }
            }
            assert!(hits > (w * h) as usize / 2, "the camera sees the box");
        }
    }
}
