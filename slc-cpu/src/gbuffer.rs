//! The G-buffer: what the camera sees at each pixel centre.
//!
//! Visibility is rasterized: each triangle's vertices are projected through
//! the pinhole camera and the triangle is binned to the screen tiles its
//! pixel bounding box (grown by a pixel against rounding) overlaps; a
//! triangle with a vertex at or behind the eye's plane goes to every tile.
//! Per tile, each binned triangle is tested against the primary rays of the
//! pixels inside its box with the ray caster's own ray–triangle test
//! ([`Geometry::hit_t`]), keeping the nearest. A triangle the ray through a
//! pixel centre hits projects over that centre, so the result is the ray
//! caster's closest hit (up to which of two triangles at exactly the same
//! distance wins), at the cost of a rasterizer: no BVH traversal per pixel.

use crate::geometry::Geometry;
use glam::Vec3;
use rayon::prelude::*;
use slc_core::path::camera_dir;
use slc_core::ray::face_against;
use slc_scene::scene::Scene;
use slc_scene::vpl::GBuffer;

/// Edge of a screen tile of the visibility pass, in pixels.
const TILE: usize = 16;

/// A triangle's pixel bounding box, inclusive: `[x0, x1] × [y0, y1]`.
#[derive(Clone, Copy)]
struct PixelBox {
    x0: usize,
    x1: usize,
    y0: usize,
    y1: usize,
}

/// Renders the G-buffer at every pixel centre. Its normal is the shading
/// normal (interpolated vertex normals where the scene has them), flipped to
/// face the camera; the second vector holds each pixel's geometric normal on
/// the same side (for ray offsets).
pub fn render_gbuffer(scene: &Scene, geo: &Geometry, width: u32, height: u32) -> (GBuffer, Vec<Vec3>) {
    let (w, h) = (width as usize, height as usize);
    let cam = &scene.camera;
    let (f, r, u) = cam.scaled_basis(width, height);
    let boxes: Vec<Option<PixelBox>> = scene.triangles.iter().map(|t| pixel_box(t, cam.position, (f, r, u), w, h)).collect();
    // Triangles per tile, in scene order (ties at equal distance go to the
    // first, as a stable order).
    let (tw, th) = (w.div_ceil(TILE), h.div_ceil(TILE));
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); tw * th];
    for (i, b) in boxes.iter().enumerate() {
        if let Some(b) = b {
            for ty in b.y0 / TILE..=b.y1 / TILE {
                for tx in b.x0 / TILE..=b.x1 / TILE {
                    bins[ty * tw + tx].push(i as u32);
                }
            }
        }
    }
    // Nearest (t, triangle) per pixel, tile by tile.
    let tiles: Vec<Vec<(f32, u32)>> = (0..tw * th)
        .into_par_iter()
        .map(|tile| {
            let (x0, y0) = ((tile % tw) * TILE, (tile / tw) * TILE);
            let (x1, y1) = ((x0 + TILE).min(w), (y0 + TILE).min(h));
            let mut rays = Vec::with_capacity((x1 - x0) * (y1 - y0));
            for y in y0..y1 {
                for x in x0..x1 {
                    let dir = camera_dir(f, r, u, x as f32 + 0.5, y as f32 + 0.5, w as f32, h as f32);
                    rays.push(Geometry::ray(cam.position, dir, 0.0, f32::INFINITY));
                }
            }
            let mut best = vec![(f32::INFINITY, u32::MAX); rays.len()];
            for &tri in &bins[tile] {
                let b = boxes[tri as usize].expect("binned triangles have a box");
                for y in b.y0.max(y0)..=b.y1.min(y1 - 1) {
                    for x in b.x0.max(x0)..=b.x1.min(x1 - 1) {
                        let k = (y - y0) * (x1 - x0) + x - x0;
                        let t = geo.hit_t(tri, &rays[k]);
                        if t < best[k].0 {
                            best[k] = (t, tri);
                        }
                    }
                }
            }
            best
        })
        .collect();
    // One parallel pass writes every buffer straight into fresh memory (a
    // zero-filled buffer first would cost as much as the pass).
    type Texel = ((Vec3, Vec3), ((Vec3, Vec3), (f32, Vec3)));
    type Buffers = ((Vec<Vec3>, Vec<Vec3>), ((Vec<Vec3>, Vec<Vec3>), (Vec<f32>, Vec<Vec3>)));
    let ((position, normal), ((albedo, emission), (depth, geometric))): Buffers = (0..w * h)
        .into_par_iter()
        .map(|i| -> Texel {
            let (x, y) = (i % w, i / w);
            let (x0, y0) = ((x / TILE) * TILE, (y / TILE) * TILE);
            let (t, tri) = tiles[(y / TILE) * tw + x / TILE][(y - y0) * ((x0 + TILE).min(w) - x0) + x - x0];
            if tri == u32::MAX {
                return ((Vec3::ZERO, Vec3::ZERO), ((Vec3::ZERO, Vec3::ZERO), (f32::INFINITY, Vec3::ZERO)));
            }
            let dir = camera_dir(f, r, u, x as f32 + 0.5, y as f32 + 0.5, w as f32, h as f32);
            let p = cam.position + dir * t;
            let gn = face_against(geo.normal(tri), dir);
            let m = scene.materials[scene.material_of[tri as usize] as usize];
            ((p, scene.shading_normal(tri as usize, p, gn)), ((m.albedo, m.emission), (t, gn)))
        })
        .unzip();
    (GBuffer { width, height, position, normal, albedo, emission, depth }, geometric)
}

/// The pixels whose centres triangle `t` can cover, seen from `eye` through
/// the camera's scaled basis `(f, r, u)` (see
/// [`slc_core::path::camera_dir`]): the box of its projected vertices grown
/// by one pixel, clipped to the image; the whole image when a vertex is not
/// in front of the eye; `None` when the box misses the image.
fn pixel_box(t: &[Vec3; 3], eye: Vec3, (f, r, u): (Vec3, Vec3, Vec3), w: usize, h: usize) -> Option<PixelBox> {
    let whole = PixelBox { x0: 0, x1: w - 1, y0: 0, y1: h - 1 };
    let (mut lo, mut hi) = ((f32::INFINITY, f32::INFINITY), (f32::NEG_INFINITY, f32::NEG_INFINITY));
    for &v in t {
        let q = v - eye;
        let depth = q.dot(f);
        if !(depth > 0.0) {
            return Some(whole);
        }
        // q = depth·(f + sx·r + sy·u): the image point of camera_dir's inverse.
        let (sx, sy) = (q.dot(r) / (r.length_squared() * depth), q.dot(u) / (u.length_squared() * depth));
        let (px, py) = ((sx + 1.0) * 0.5 * w as f32 - 0.5, (1.0 - sy) * 0.5 * h as f32 - 0.5);
        if !(px.is_finite() && py.is_finite()) {
            return Some(whole);
        }
        lo = (lo.0.min(px), lo.1.min(py));
        hi = (hi.0.max(px), hi.1.max(py));
    }
    let (x0, y0) = ((lo.0.floor() - 1.0).max(0.0), (lo.1.floor() - 1.0).max(0.0));
    let (x1, y1) = ((hi.0.ceil() + 1.0).min(w as f32 - 1.0), (hi.1.ceil() + 1.0).min(h as f32 - 1.0));
    (x0 <= x1 && y0 <= y1).then_some(PixelBox { x0: x0 as usize, x1: x1 as usize, y0: y0 as usize, y1: y1 as usize })
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
                        assert!(gb.valid(i) && (gb.depth[i] - hit.t).abs() <= 1e-6 * hit.t, "pixel {i}: depth {} vs {}", gb.depth[i], hit.t);
                        assert!(geometric[i].dot(face_against(geo.normal(hit.triangle), dir)) > 0.999, "pixel {i}: geometric normal");
                    }
                    None => assert!(!gb.valid(i), "pixel {i}: hit where the ray caster misses"),
                }
            }
            assert!(hits > (w * h) as usize / 2, "the camera sees the box");
        }
    }
}
