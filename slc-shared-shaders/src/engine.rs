//! The engine passes' own shared functions (written once in Rust, emitted
//! as WGSL into their kernels): world positions from an engine's depth
//! buffer, and a record's ranges for its culling mode.

// Shared (WGSL) functions take their inputs as scalars and vectors.
#![allow(clippy::too_many_arguments)]

use slc_core::range::{intensity_measure, random_range2, threshold_range2};
use slc_core::ray::finite3;
use slc_core::wgsl::*;

slc_core::shared! {
    /// World position of pixel `(px, py)` (integer coordinates, row 0 at
    /// the top) of a `width × height` depth target holding `depth`, for the
    /// inverse view-projection with columns `c0..c3`: the pixel centre's
    /// normalised device coordinates `x = 2(px + ½)/w − 1`,
    /// `y = 1 − 2(py + ½)/h` (wgpu: y up, depth in `[0, 1]`), `p = M·(x, y,
    /// depth, 1)`, world `p.xyz / p.w`, and `w = 1`. Returns zero (`w = 0`:
    /// no surface) where `depth` is exactly 0 or 1, either convention's
    /// clear value (standard depth clears to 1, reversed Z to 0; the other
    /// value is the near plane, where the rasterizer leaves no visible
    /// surface), or where `p` is not a finite point (`p.w` = 0: a point at
    /// infinity).
    pub fn unproject_pixel(c0: vec4f, c1: vec4f, c2: vec4f, c3: vec4f, px: f32, py: f32, width: f32, height: f32, depth: f32) -> vec4f {
        if !(depth > 0.0 && depth < 1.0) {
            return vec4f(0.0, 0.0, 0.0, 0.0);
        }
        let x: f32 = (px + 0.5) / width * 2.0 - 1.0;
        let y: f32 = 1.0 - (py + 0.5) / height * 2.0;
        let p: vec4f = c0 * x + c1 * y + c2 * depth + c3;
        let q: vec3f = vec3f(p.x / p.w, p.y / p.w, p.z / p.w);
        if abs(p.w) > 0.0 && finite3(q) {
            return vec4f(q.x, q.y, q.z, 1.0);
        }
        return vec4f(0.0, 0.0, 0.0, 0.0);
    }

    /// A record's threshold range² of a light with RGB peak intensity
    /// `peak`: with stochastic culling (`slc` = 1) `r_t² = E·I/(2π ε)` of
    /// the `mode` intensity measure; otherwise `unculled` (the host writes
    /// +∞, which WGSL cannot spell: the roulette weight `1/p` is then 1).
    pub fn record_rt2(peak: vec3f, slc: u32, mode: u32, exposure: f32, error_bound: f32, unculled: f32) -> f32 {
        if slc == 1 {
            return threshold_range2(intensity_measure(peak, mode), exposure, error_bound);
        }
        return unculled;
    }

    /// A record's random range²: with stochastic culling (`slc` = 1)
    /// `r² = r_t²/(1 − ξ)`; otherwise `fixed_r2` (a clamped range `R²`, or
    /// +∞: every light everywhere).
    pub fn record_r2(rt2: f32, slc: u32, fixed_r2: f32, xi: f32) -> f32 {
        if slc == 1 {
            return random_range2(rt2, xi);
        }
        return fixed_r2;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use slc_core::glam::{Mat4, Vec3, Vec4};

    #[test]
    fn unprojection_inverts_the_projection() {
        use slc_core::glam::camera::rh::{proj, view::look_to_mat4};
        let (w, h) = (64.0, 48.0);
        let vp = proj::directx::perspective(1.0, w / h, 0.1, 50.0)
            * look_to_mat4(Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.2, -0.3, -1.0), Vec3::Y);
        let inv = vp.inverse();
        let p = Vec3::new(0.7, 1.2, -1.5);
        let clip = vp * p.extend(1.0);
        let ndc = clip.truncate() / clip.w;
        let (px, py) = ((ndc.x + 1.0) * 0.5 * w - 0.5, (1.0 - ndc.y) * 0.5 * h - 0.5);
        let q =
            unproject_pixel(inv.x_axis, inv.y_axis, inv.z_axis, inv.w_axis, px, py, w, h, ndc.z);
        assert!((q.truncate() - p).length() < 1e-4 && q.w == 1.0, "{q} vs {p}");
        // Either convention's clear value is background.
        for clear in [0.0, 1.0] {
            assert_eq!(
                unproject_pixel(
                    inv.x_axis, inv.y_axis, inv.z_axis, inv.w_axis, px, py, w, h, clear
                ),
                Vec4::ZERO
            );
        }
        let zero = Mat4::ZERO;
        assert_eq!(
            unproject_pixel(zero.x_axis, zero.y_axis, zero.z_axis, zero.w_axis, px, py, w, h, 0.5),
            Vec4::ZERO
        );
    }

    /// The unprojection is at pixel centres, as a rasterizer samples: the
    /// depth a rasterizer writes at pixel `(x, y)` of a tilted plane is
    /// that of the ray through `(x + ½, y + ½)`, and unprojecting it gives
    /// a point on the plane; the same depth placed at the pixel's corner
    /// (the convention an engine might assume) misses the plane.
    #[test]
    fn unprojection_is_at_pixel_centres() {
        use slc_core::glam::camera::rh::{proj, view::look_to_mat4};
        let (w, h) = (32.0, 24.0);
        let vp = proj::directx::perspective(0.9, w / h, 0.1, 20.0)
            * look_to_mat4(Vec3::ZERO, -Vec3::Z, Vec3::Y);
        let inv = vp.inverse();
        // The plane n·p = d, tilted against the view direction.
        let (n, d) = (Vec3::new(0.3, 0.5, 1.0).normalize(), -3.0);
        let hit = |ndc_x: f32, ndc_y: f32| {
            let (a, b) = (
                inv.project_point3(Vec3::new(ndc_x, ndc_y, 0.0)),
                inv.project_point3(Vec3::new(ndc_x, ndc_y, 1.0)),
            );
            a + (b - a) * ((d - n.dot(a)) / n.dot(b - a))
        };
        let (mut centre, mut corner) = (0.0f32, f32::INFINITY);
        for (px, py) in [(0.0, 0.0), (5.0, 17.0), (31.0, 23.0), (16.0, 12.0)] {
            let ndc = |x: f32, y: f32| (2.0 * x / w - 1.0, 1.0 - 2.0 * y / h);
            let (cx, cy) = ndc(px + 0.5, py + 0.5);
            let depth = vp.project_point3(hit(cx, cy)).z;
            let p = unproject_pixel(
                inv.x_axis, inv.y_axis, inv.z_axis, inv.w_axis, px, py, w, h, depth,
            )
            .truncate();
            centre = centre.max((n.dot(p) - d).abs());
            // The corner's ray at the centre's depth.
            let (kx, ky) = ndc(px, py);
            let q = inv.project_point3(Vec3::new(kx, ky, depth));
            corner = corner.min((n.dot(q) - d).abs());
        }
        assert!(centre < 1e-4, "centre unprojection off the plane by {centre}");
        assert!(
            corner > 1e-3,
            "a corner unprojection lands on the plane ({corner}): the test cannot tell the conventions apart"
        );
    }

    #[test]
    fn record_ranges_follow_the_culling() {
        let peak = Vec3::new(1.0, 2.0, 0.5);
        let rt2 = record_rt2(peak, 1, 0, 1.0, 0.01, f32::INFINITY);
        assert_eq!(
            rt2,
            slc_core::range::RangeParams::new(0.01, 1.0).unwrap().threshold_range2(peak)
        );
        assert_eq!(record_r2(rt2, 1, 0.0, 0.5), 2.0 * rt2);
        assert_eq!(record_rt2(peak, 0, 0, 1.0, 0.01, f32::INFINITY), f32::INFINITY);
        assert_eq!(record_r2(f32::INFINITY, 0, 0.25, 0.5), 0.25);
    }
}
