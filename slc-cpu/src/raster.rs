//! Visibility without a BVH walk per ray, for views whose rays all leave
//! one centre (a pinhole: the camera, a spot light's map) or run parallel
//! (an orthographic map: a directional light's).
//!
//! Triangles are binned by the image box their projected vertices span,
//! grown by one pixel against rounding: a triangle with a vertex at or
//! behind a pinhole's plane is first clipped to the least depth the view's
//! rays reach ([`View::near`]; every bin when that is 0), one wholly nearer
//! goes to none (no ray of the view reaches it). A ray of pixel `(x, y)` can only
//! hit a triangle whose projection covers `(x, y)`, so testing the binned
//! triangles with the ray caster's own test ([`Geometry::hit_t`]) gives the
//! ray caster's answer:
//! - [`closest_hits`]: each pixel's nearest hit, tile by tile (the G-buffer
//!   and the reflective shadow map);
//! - [`Occluders`]: whether a segment running along one of the view's rays
//!   (toward a spot light, or against a directional light) is blocked, from
//!   the single bin its points all project to (the primary light's
//!   shadows).

use crate::geometry::Geometry;
use glam::Vec3;
use obvhs::ray::Ray;
use rayon::prelude::*;
use slc_core::frame::light_map_coord_at;
use slc_core::path::camera_dir;
use slc_scene::scene::{Camera, LightMap};

/// A view of `width × height` pixels: where a point projects, and the ray
/// of a pixel.
pub trait View: Sync {
    /// Image size in pixels.
    fn size(&self) -> (usize, usize);

    /// `(depth, x, y)` of point `p`: image coordinates in pixels (pixel
    /// `i`'s ray through `i`), valid where `depth > 0` (always, for an
    /// orthographic view).
    fn project(&self, p: Vec3) -> (f32, f32, f32);

    /// The `depth` of [`View::project`] alone (an affine function of `p`).
    fn depth(&self, p: Vec3) -> f32;

    /// The ray of pixel `(x, y)`.
    fn ray(&self, x: usize, y: usize) -> Ray;

    /// A depth every point a ray of the view tests reaches (`0` at most):
    /// triangles are clipped to it before binning, so the nearer it is to
    /// the truth, the fewer bins a triangle crossing the view's plane fills.
    fn near(&self) -> f32;
}

/// A pinhole camera: rays from `eye` along
/// [`camera_dir`]`(f, r, u, x + ½, y + ½, w, h)`, from `t = 0`.
pub struct Pinhole {
    /// Eye position.
    pub eye: Vec3,
    /// The camera's scaled basis `(forward, right, up)` (see
    /// [`slc_scene::scene::Camera::scaled_basis`]).
    pub basis: (Vec3, Vec3, Vec3),
    /// Image width and height in pixels.
    pub size: (usize, usize),
}

impl Pinhole {
    /// The view of `cam` for a `w × h` image.
    pub fn of(cam: &Camera, w: u32, h: u32) -> Pinhole {
        Pinhole { eye: cam.position, basis: cam.scaled_basis(w, h), size: (w as usize, h as usize) }
    }

    /// The unit direction of pixel `(x, y)`'s ray (through its centre).
    pub fn dir(&self, x: usize, y: usize) -> Vec3 {
        self.dir_at(x as f32 + 0.5, y as f32 + 0.5)
    }

    /// The unit direction of the ray through image point `(sx, sy)`, in
    /// pixels from the top-left corner ([`camera_dir`]).
    pub fn dir_at(&self, sx: f32, sy: f32) -> Vec3 {
        let (f, r, u) = self.basis;
        camera_dir(f, r, u, sx, sy, self.size.0 as f32, self.size.1 as f32)
    }
}

impl View for Pinhole {
    fn size(&self) -> (usize, usize) {
        self.size
    }

    fn depth(&self, p: Vec3) -> f32 {
        (p - self.eye).dot(self.basis.0)
    }

    fn project(&self, p: Vec3) -> (f32, f32, f32) {
        let (f, r, u) = self.basis;
        let (w, h) = (self.size.0 as f32, self.size.1 as f32);
        let q = p - self.eye;
        let depth = q.dot(f);
        // q = depth·(f + sx·r + sy·u): the image point of camera_dir's inverse.
        let (sx, sy) =
            (q.dot(r) / (r.length_squared() * depth), q.dot(u) / (u.length_squared() * depth));
        (depth, (sx + 1.0) * 0.5 * w - 0.5, (1.0 - sy) * 0.5 * h - 0.5)
    }

    fn ray(&self, x: usize, y: usize) -> Ray {
        Geometry::ray(self.eye, self.dir(x, y), 0.0, f32::INFINITY)
    }

    fn near(&self) -> f32 {
        0.0
    }
}

/// A `size × size` light map ([`LightMap`]): texel `(x, y)`'s ray is
/// [`LightMap::texel_ray`], from `t = t_min`.
pub struct MapView {
    /// The map's frame.
    pub map: LightMap,
    /// Texels per edge.
    pub size: usize,
    /// Where each texel's ray starts.
    pub t_min: f32,
}

impl View for MapView {
    fn size(&self) -> (usize, usize) {
        (self.size, self.size)
    }

    fn depth(&self, p: Vec3) -> f32 {
        match self.map {
            LightMap::Perspective { origin, axis, .. } => (p - origin).dot(axis),
            LightMap::Orthographic { .. } => 1.0,
        }
    }

    fn project(&self, p: Vec3) -> (f32, f32, f32) {
        let (depth, a, b) = match self.map {
            LightMap::Perspective { origin, axis, right, up, tan } => {
                let rel = p - origin;
                (
                    rel.dot(axis),
                    light_map_coord_at(rel, right, axis, tan, true),
                    light_map_coord_at(rel, up, axis, tan, true),
                )
            }
            LightMap::Orthographic { origin, axis, right, up, half } => {
                let rel = p - origin;
                (
                    1.0,
                    light_map_coord_at(rel, right, axis, half, false),
                    light_map_coord_at(rel, up, axis, half, false),
                )
            }
        };
        // The inverse of light_map_coord: texel t's centre at t.
        let n = self.size as f32;
        (depth, (a + 1.0) * 0.5 * n - 0.5, (b + 1.0) * 0.5 * n - 0.5)
    }

    fn ray(&self, x: usize, y: usize) -> Ray {
        let (origin, dir, _) = self.map.texel_ray(x as u32, y as u32, self.size as u32);
        Geometry::ray(origin, dir, self.t_min, f32::INFINITY)
    }

    /// `t_min` times the least cosine of a texel's ray with a perspective
    /// map's axis (its corner, `1/√(1 + 2·tan²)`), halved against rounding;
    /// `0` for an orthographic map (its depth is a constant 1: nothing is
    /// clipped).
    fn near(&self) -> f32 {
        match self.map {
            LightMap::Perspective { tan, .. } => 0.5 * self.t_min / (1.0 + 2.0 * tan * tan).sqrt(),
            LightMap::Orthographic { .. } => 0.0,
        }
    }
}

/// A triangle's pixel box, inclusive: `[x0, x1] × [y0, y1]`.
#[derive(Clone, Copy)]
struct PixelBox {
    x0: usize,
    x1: usize,
    y0: usize,
    y1: usize,
}

/// The pixels whose rays can hit triangle `t` at depth `near` or more: the
/// box of its projected vertices grown by one pixel, clipped to the image.
/// The part of the triangle nearer than `near` is clipped off first (depth
/// is affine in the point for both views, and a convex polygon wholly in
/// front of a pinhole projects inside the box of its vertices' images); a
/// clipped vertex that still projects to no finite point in front (always,
/// for `near = 0`) gives the whole image. `None` when the whole triangle is
/// nearer than `near` or the box misses the image.
fn pixel_box(view: &impl View, t: &[Vec3; 3], near: f32) -> Option<PixelBox> {
    let (w, h) = view.size();
    let depth = t.map(|v| view.depth(v));
    if depth.iter().all(|&d| d < near) {
        return None;
    }
    // Sutherland–Hodgman against the plane `depth = near`: at most 4 vertices.
    let mut poly = [Vec3::ZERO; 4];
    let mut n = 0;
    for k in 0..3 {
        let (p, q, dp, dq) = (t[k], t[(k + 1) % 3], depth[k], depth[(k + 1) % 3]);
        if dp >= near {
            poly[n] = p;
            n += 1;
        }
        if (dp >= near) != (dq >= near) {
            poly[n] = p + (q - p) * ((dp - near) / (dp - dq));
            n += 1;
        }
    }
    let whole = PixelBox { x0: 0, x1: w - 1, y0: 0, y1: h - 1 };
    let (mut lo, mut hi) = ((f32::INFINITY, f32::INFINITY), (f32::NEG_INFINITY, f32::NEG_INFINITY));
    for &v in &poly[..n] {
        let (d, px, py) = view.project(v);
        if !(d > 0.0 && px.is_finite() && py.is_finite()) {
            return Some(whole);
        }
        lo = (lo.0.min(px), lo.1.min(py));
        hi = (hi.0.max(px), hi.1.max(py));
    }
    let (x0, y0) = ((lo.0.floor() - 1.0).max(0.0), (lo.1.floor() - 1.0).max(0.0));
    let (x1, y1) =
        ((hi.0.ceil() + 1.0).min(w as f32 - 1.0), (hi.1.ceil() + 1.0).min(h as f32 - 1.0));
    (x0 <= x1 && y0 <= y1).then_some(PixelBox {
        x0: x0 as usize,
        x1: x1 as usize,
        y0: y0 as usize,
        y1: y1 as usize,
    })
}

/// Triangles binned to the `tile × tile` pixel tiles of a view, in scene
/// order within each bin (a tie at equal distance goes to the first).
struct Bins {
    boxes: Vec<Option<PixelBox>>,
    /// Tiles per row and per column.
    tiles: (usize, usize),
    bins: Vec<Vec<u32>>,
}

impl Bins {
    /// Bins the triangles that can be hit at depth `near` or more.
    fn new(view: &impl View, triangles: &[[Vec3; 3]], tile: usize, near: f32) -> Bins {
        let (w, h) = view.size();
        let boxes: Vec<Option<PixelBox>> =
            triangles.iter().map(|t| pixel_box(view, t, near)).collect();
        let (tw, th) = (w.div_ceil(tile), h.div_ceil(tile));
        let mut bins: Vec<Vec<u32>> = vec![Vec::new(); tw * th];
        for (i, b) in boxes.iter().enumerate() {
            if let Some(b) = b {
                for ty in b.y0 / tile..=b.y1 / tile {
                    for tx in b.x0 / tile..=b.x1 / tile {
                        bins[ty * tw + tx].push(i as u32);
                    }
                }
            }
        }
        Bins { boxes, tiles: (tw, th), bins }
    }
}

/// Edge of a tile of [`closest_hits`], in pixels.
const TILE: usize = 16;

/// A tile's four corner pixels' rays `(o, d)` with the scale `(|d|,
/// |o|·|d|)` of their Plücker sides ([`tile_misses`]), taken once per tile.
type Corners = [(Vec3, Vec3, f32, f32); 4];

fn corners(rays: &[Ray], row: usize) -> Corners {
    [0, row - 1, rays.len() - row, rays.len() - 1].map(|k| {
        let (o, d) = (Vec3::from(rays[k].origin), Vec3::from(rays[k].direction));
        (o, d, d.length(), o.length() * d.length())
    })
}

/// A triangle's three edges `a → b` in Plücker form for [`tile_misses`]:
/// `(b − a, a × b, |b − a|, |a × b|)`, taken once per triangle.
type Edges = [(Vec3, Vec3, f32, f32); 3];

fn edges(t: &[Vec3; 3]) -> Edges {
    [0, 1, 2].map(|k| {
        let (a, b) = (t[k], t[(k + 1) % 3]);
        let (e, m) = (b - a, a.cross(b));
        (e, m, e.length(), m.length())
    })
}

/// `true` when no ray of a tile, whose pixels' rays lie between its four
/// corner pixels' `corners` (a view's ray is affine in the pixel up to a
/// positive scale: a pinhole's or a perspective map's direction from a
/// fixed origin, an orthographic map's origin along a fixed direction),
/// can hit the triangle of `edges` ([`edges`]): by Plücker coordinates, a
/// line meets the triangle only where its side `d·(a × b) + (o × d)·(b − a)`
/// of the three edges `a → b` has one sign, and each side is then linear
/// over the tile,
/// so one edge with every corner strictly on its positive side and another
/// with every corner on its negative side rules the whole tile out (with a
/// relative margin of 10⁻⁴ of the side's magnitude against rounding,
/// far above the ray caster's own).
fn tile_misses(corners: &Corners, edges: &Edges) -> bool {
    let (mut pos, mut neg) = (false, false);
    for &(e, m, el, ml) in edges {
        let (mut all_pos, mut all_neg) = (true, true);
        for &(o, d, dl, odl) in corners {
            let side = d.dot(m) + o.cross(d).dot(e);
            let margin = 1e-4 * (dl * ml + odl * el);
            all_pos &= side > margin;
            all_neg &= side < -margin;
        }
        pos |= all_pos;
        neg |= all_neg;
    }
    pos && neg
}

/// Each pixel's nearest hit `(t, triangle)` of a view (`(∞, u32::MAX)` where
/// the ray hits nothing), stored tile by tile; read it with
/// [`ClosestHits::at`].
pub struct ClosestHits {
    width: usize,
    height: usize,
    tiles_x: usize,
    tiles: Vec<Vec<(f32, u32)>>,
}

impl ClosestHits {
    /// The hit of pixel `(x, y)`.
    pub fn at(&self, x: usize, y: usize) -> (f32, u32) {
        let (x0, y0) = ((x / TILE) * TILE, (y / TILE) * TILE);
        let row = (x0 + TILE).min(self.width) - x0;
        self.tiles[(y / TILE) * self.tiles_x + x / TILE][(y - y0) * row + x - x0]
    }

    /// Image width and height.
    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }
}

/// The nearest hit of every pixel's ray of `view` among `triangles` (the
/// ones `geo` was built from), by binning: the ray caster's closest hit
/// (up to which of two triangles at exactly the same distance wins).
pub fn closest_hits(view: &impl View, geo: &Geometry, triangles: &[[Vec3; 3]]) -> ClosestHits {
    let (w, h) = view.size();
    let bins = Bins::new(view, triangles, TILE, view.near());
    let edges: Vec<Edges> = triangles.par_iter().map(edges).collect();
    let tw = bins.tiles.0;
    let tiles = (0..bins.bins.len())
        .into_par_iter()
        .map(|tile| {
            let (x0, y0) = ((tile % tw) * TILE, (tile / tw) * TILE);
            let (x1, y1) = ((x0 + TILE).min(w), (y0 + TILE).min(h));
            let mut rays = Vec::with_capacity((x1 - x0) * (y1 - y0));
            for y in y0..y1 {
                for x in x0..x1 {
                    rays.push(view.ray(x, y));
                }
            }
            let mut best = vec![(f32::INFINITY, u32::MAX); rays.len()];
            let corners = corners(&rays, x1 - x0);
            for &tri in &bins.bins[tile] {
                if tile_misses(&corners, &edges[tri as usize]) {
                    continue;
                }
                let b = bins.boxes[tri as usize].expect("binned triangles have a box");
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
    ClosestHits { width: w, height: h, tiles_x: tw, tiles }
}

/// The triangles that can block a segment running along one of a view's
/// rays, binned per pixel of the view: every point of such a segment
/// projects to the same image point, so only the triangles binned there
/// can cross it. Before the ray caster's test, a binned triangle is
/// skipped when both ends of the segment lie on one side of its plane by
/// more than a rounding margin (then the open segment cannot reach it; the
/// receiver's own surface and the walls around it go this way).
/// [`Occluders::occluded`] answers as [`Geometry::occluded`] does, and asks
/// it where the point projects outside the view.
pub struct Occluders<'g, V> {
    view: V,
    geo: &'g Geometry,
    bins: Bins,
    /// Each triangle's plane `(n, n·v₀)`, unit `n`.
    planes: Vec<(Vec3, f32)>,
    /// Distance to a plane below which a side is not trusted.
    margin: f32,
}

impl<'g, V: View> Occluders<'g, V> {
    /// Bins `triangles` (the ones `geo` was built from) to the pixels of
    /// `view`.
    pub fn new(view: V, geo: &'g Geometry, triangles: &[[Vec3; 3]]) -> Self {
        let bins = Bins::new(&view, triangles, 1, view.near());
        let plane = |(i, t): (usize, &[Vec3; 3])| {
            let n = geo.normal(i as u32);
            (n, n.dot(t[0]))
        };
        let planes = triangles.iter().enumerate().map(plane).collect();
        let extent = triangles.iter().flatten().fold(0.0f32, |m, v| m.max(v.abs().max_element()));
        Occluders { view, geo, bins, planes, margin: 1e-6 * extent }
    }

    /// `true` when the open segment from `a` to `b` hits a triangle.
    /// Precondition: `b` lies on the view's ray through `a` (a pinhole
    /// view's centre, or `a` moved against an orthographic view's axis);
    /// otherwise the answer is only the bin's. A segment whose tested part
    /// leaves the view, or comes nearer than the view's
    /// [`near`](View::near), is asked of the BVH.
    pub fn occluded(&self, a: Vec3, b: Vec3) -> bool {
        let Some(ray) = Geometry::segment(a, b) else { return false };
        let (w, h) = self.view.size();
        let (depth, px, py) = self.view.project(a);
        let end = self.view.depth(Vec3::from(ray.origin + ray.direction * ray.tmax));
        // Pixel i covers [i − ½, i + ½): truncation is the floor here, as
        // negative coordinates are outside.
        let (x, y) = (px + 0.5, py + 0.5);
        let near = self.view.near();
        if !(depth >= near
            && end >= near
            && depth > 0.0
            && x >= 0.0
            && y >= 0.0
            && x < w as f32
            && y < h as f32)
        {
            return self.geo.occluded(a, b);
        }
        let bin = &self.bins.bins[y as usize * self.bins.tiles.0 + x as usize];
        bin.iter().any(|&tri| {
            let (n, d) = self.planes[tri as usize];
            let (sa, sb) = (n.dot(a) - d, n.dot(b) - d);
            let apart =
                (sa > self.margin && sb > self.margin) || (sa < -self.margin && sb < -self.margin);
            !apart && self.geo.blocks(tri, &ray)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use slc_core::ray::surface_offset;
    use slc_scene::scene::{Camera, PrimaryLight, Scene};

    /// The binned occlusion test answers as the BVH's for segments from
    /// G-buffer-like points toward a spot light and against a directional
    /// one, including points outside the map (the fallback) and points the
    /// box's blocks shadow.
    #[test]
    fn binned_occlusion_equals_ray_casting() {
        let scene = Scene::cornell_box();
        let geo = Geometry::new(&scene.triangles);
        let (lo, hi) = scene.bounds();
        let diag = scene.diagonal();
        let spot_pos = match scene.primary {
            PrimaryLight::Spot { position, .. } => position,
            PrimaryLight::Directional { .. } => unreachable!("the Cornell box has a spot light"),
        };
        let dir_light = PrimaryLight::Directional {
            direction: Vec3::new(0.3, -1.0, 0.2),
            irradiance: Vec3::ONE,
        };
        let t_min = surface_offset(diag);
        let spot = Occluders::new(
            MapView { map: scene.primary.light_map((lo, hi)), size: 64, t_min },
            &geo,
            &scene.triangles,
        );
        let sun = Occluders::new(
            MapView { map: dir_light.light_map((lo, hi)), size: 64, t_min },
            &geo,
            &scene.triangles,
        );
        let wi = Vec3::new(-0.3, 1.0, -0.2).normalize();
        // Points on the surfaces the camera sees, offset off them.
        let cam = scene.camera;
        let (w, h) = (61, 47);
        let (mut blocked, mut total) = (0, 0);
        for y in 0..h {
            for x in 0..w {
                let dir = cam.ray_dir(x as f32, y as f32, w, h);
                let Some(hit) = geo.intersect(cam.position, dir, 0.0, f32::INFINITY) else {
                    continue;
                };
                let gn = slc_core::ray::face_against(geo.normal(hit.triangle), dir);
                let from = cam.position + dir * hit.t + gn * surface_offset(diag);
                for (occ, to) in [
                    (spot.occluded(from, spot_pos), spot_pos),
                    (sun.occluded(from, from + wi * 2.0 * diag), from + wi * 2.0 * diag),
                ] {
                    assert_eq!(occ, geo.occluded(from, to), "pixel ({x}, {y}) toward {to}");
                    blocked += occ as usize;
                    total += 1;
                }
            }
        }
        assert!(
            blocked > total / 20 && blocked < total,
            "{blocked} of {total} segments blocked: the test sees shadows and light"
        );
    }

    /// A pinhole view projects a pixel's ray back onto that pixel, and a
    /// map view a texel's ray onto that texel.
    #[test]
    fn views_project_their_own_rays() {
        fn projects_its_rays(view: &impl View) {
            let (w, h) = view.size();
            for (x, y) in [(0, 0), (w / 3, h / 2), (w - 1, h - 1)] {
                let r = view.ray(x, y);
                let p = Vec3::from(r.origin + r.direction * 2.5);
                let (depth, px, py) = view.project(p);
                assert_eq!(view.depth(p), depth, "depth is project's");
                assert!(
                    depth > 0.0 && (px - x as f32).abs() < 1e-3 && (py - y as f32).abs() < 1e-3,
                    "({x}, {y}) → ({px}, {py})"
                );
            }
        }
        let scene = Scene::cornell_box();
        let cam: Camera = scene.camera;
        projects_its_rays(&Pinhole::of(&cam, 40, 30));
        projects_its_rays(&MapView {
            map: scene.primary.light_map(scene.bounds()),
            size: 32,
            t_min: 0.0,
        });
        let sun = PrimaryLight::Directional {
            direction: Vec3::new(0.3, -1.0, 0.2),
            irradiance: Vec3::ONE,
        };
        projects_its_rays(&MapView { map: sun.light_map(scene.bounds()), size: 32, t_min: 0.0 });
    }
}
