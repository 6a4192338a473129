//! The VPL frame's per-pixel formulas outside the shading loop, written
//! once for the CPU's ray-cast frame and the GPU's rasterized one: where a
//! texel of the light's map looks, the solid angle it covers (the flux of
//! its VPL), the primary light's direct term with its shadow-map test, and
//! the composition `L = L_e + ρ/π · E` (Dachsbacher & Stamminger,
//! "Reflective Shadow Maps", I3D 2005; docs/architecture.md §2.1).

use crate::brdf::diffuse_albedo;
use crate::light::{INV_PI, MIN_D2, inverse_square};
use crate::wgsl::*;

crate::shared! {
    /// Map coordinate in `[-1, 1]` of the centre of texel `t` of a map
    /// `size` texels wide: `2(t + ½)/size − 1` (texel 0 at −1).
    pub fn light_map_coord(t: u32, size: u32) -> f32 {
        return 2.0 * (to_f32(t) + 0.5) / to_f32(size) - 1.0;
    }

    /// The texel whose cell holds map coordinate `a` (the inverse of
    /// [`light_map_coord`]), clamped to `[0, size − 1]`.
    pub fn light_map_texel(a: f32, size: u32) -> u32 {
        return to_u32(clamp(floor((a + 1.0) * 0.5 * to_f32(size)), 0.0, to_f32(size) - 1.0));
    }

    /// Map coordinate along the unit map direction `dir` (its right or
    /// up) of a point at offset `rel` from the map's origin: the inverse of
    /// the map's rays, `rel·dir / (z·extent)` with `z = rel·axis` the depth
    /// along the unit `axis` (perspective map, `extent = tan` of the
    /// half-angle; meaningful where `z > 0`), or `rel·dir / extent`
    /// (orthographic map, `extent` its half-edge).
    pub fn light_map_coord_at(rel: vec3f, dir: vec3f, axis: vec3f, extent: f32, perspective: bool) -> f32 {
        return dot(rel, dir) / (select(1.0, dot(rel, axis), perspective) * extent);
    }

    /// A linear channel value `x ≥ 0` (after exposure) as the display
    /// value in `[0, 1]` of slc's previews: the curve `t = 2x/(1 + 2x)`
    /// (½ at `x = ½`, white only at ∞), then the sRGB transfer function
    /// (IEC 61966-2-1: `12.92·t` up to `0.0031308`, else
    /// `1.055·t^(1/2.4) − 0.055`). The PNG writer and the viewer share it.
    pub fn display_encode(x: f32) -> f32 {
        let v: f32 = max(x, 0.0);
        let t: f32 = 2.0 * v / (1.0 + 2.0 * v);
        return select(1.055 * pow(t, 1.0 / 2.4) - 0.055, 12.92 * t, t <= 0.0031308);
    }

    /// Depth a light map stores for a point at offset `rel` from the map's
    /// origin: the distance from the light (perspective map) or the
    /// distance along the unit `axis` from the map's plane (orthographic).
    /// The shadow map is written and read with it.
    pub fn light_map_depth(rel: vec3f, axis: vec3f, perspective: bool) -> f32 {
        return select(dot(rel, axis), sqrt(dot(rel, rel)), perspective);
    }

    /// Solid angle of a texel of a perspective light map whose texels have
    /// area `texel_area` on the image plane at distance 1, seen at cosine
    /// `cos_axis` from the map's axis: `A·cos³θ` (`A / q^{3/2}` with
    /// `q = 1 + s² + t² = 1/cos²θ` for the plane point `(s, t, 1)`).
    pub fn rsm_texel_solid_angle(texel_area: f32, cos_axis: f32) -> f32 {
        return texel_area * cos_axis * cos_axis * cos_axis;
    }

    /// Irradiance at a receiver with unit normal `n` from a point-like
    /// light at offset `v` (receiver → light) whose intensity toward the
    /// receiver is `intensity`: `I · max(n·ŵ, 0) / max(d², MIN_D2)`.
    pub fn point_irradiance(intensity: vec3f, n: vec3f, v: vec3f) -> vec3f {
        let d2: f32 = dot(v, v);
        let cos_x: f32 = dot(n, v) / sqrt(max(d2, MIN_D2));
        return intensity * (max(cos_x, 0.0) * inverse_square(d2));
    }

    /// Irradiance at a receiver with unit normal `n` from a directional
    /// light of irradiance `e` arriving from unit direction `to_light`:
    /// `E · max(n·ω, 0)`.
    pub fn directional_irradiance(e: vec3f, n: vec3f, to_light: vec3f) -> vec3f {
        return e * max(dot(n, to_light), 0.0);
    }

    /// Width at the receiver of one texel of a perspective light map of
    /// `size²` texels and half-extent `extent` (`tan` of the half-angle), for
    /// a receiver at distance `d` from the light and depth `z` along its
    /// axis: `2·extent·d²/(size·z)` (the texel's width `2·extent·z/size` at
    /// depth `z`, widened by `d/z` toward the ray).
    pub fn perspective_texel_width(extent: f32, d: f32, z: f32, size: f32) -> f32 {
        return 2.0 * extent * d * d / (size * z);
    }

    /// Width of one texel of an orthographic light map of `size²` texels
    /// and half-extent `extent`: `2·extent/size`.
    pub fn ortho_texel_width(extent: f32, size: f32) -> f32 {
        return 2.0 * extent / size;
    }

    /// Depth bias of a shadow-map test for texels `texel` wide at the
    /// receiver, lit at cosine `cos_light`: one and a half texels plus the
    /// slope `tan θ` texels (θ clamped below 88.9°), so a lit surface never
    /// shadows itself across the texel it falls in. The bias grows at
    /// grazing light, where the light's contribution (∝ cos θ) vanishes.
    pub fn shadow_bias(texel: f32, cos_light: f32) -> f32 {
        let c: f32 = clamp(cos_light, 0.02, 1.0);
        return texel * (1.5 + sqrt(1.0 - c * c) / c);
    }

    /// Shadow-map test: a receiver at distance `d` from the light along the
    /// map's ray is lit when the map's first surface on that ray lies no
    /// nearer than `d − bias`, or when the map saw nothing there
    /// (`d_map ≤ 0`).
    pub fn shadow_lit(d: f32, d_map: f32, bias: f32) -> bool {
        return d_map <= 0.0 || d <= d_map + bias;
    }

    /// Outgoing radiance of a diffuse surface of albedo `albedo` and
    /// emission `emission` under irradiance `e`: `L_e + ρ/π · E`.
    pub fn diffuse_radiance(albedo: vec3f, emission: vec3f, e: vec3f) -> vec3f {
        return emission + albedo * INV_PI * e;
    }

    /// Unit direction from `x` toward the primary light of the light map
    /// with origin `origin` and unit axis `axis`: toward the spot's position
    /// for a perspective map, against the axis (the direction the light
    /// travels) for a directional light's orthographic map; at the spot's
    /// own position, its axis reversed.
    pub fn primary_light_dir(x: vec3f, origin: vec3f, axis: vec3f, perspective: bool) -> vec3f {
        let v: vec3f = origin - x;
        let d2: f32 = dot(v, v);
        if perspective && d2 > 0.0 {
            return v / sqrt(d2);
        }
        return -axis;
    }

    /// Outgoing radiance of a receiver with a specular lobe in the VPL
    /// frame: base colour `base`, metallic `metallic`, emission
    /// `emission`, the primary light's direct irradiance `direct` (which
    /// arrives from one direction `l`, so it is reflected by the whole BRDF
    /// there, `f_direct = f(v, l)`: [`crate::brdf::brdf_eval`] toward
    /// [`primary_light_dir`]), the VPLs' irradiance `indirect` and their
    /// specular correction `specular` (`Σ Φ ⊙ (f − c_diff/π)·T`,
    /// [`crate::brdf::specular_correction`]):
    /// `L_e + f(v, l)·E_direct + c_diff/π·E_indirect + S`.
    pub fn glossy_radiance(base: vec3f, emission: vec3f, metallic: f32, f_direct: vec3f, direct: vec3f, indirect: vec3f, specular: vec3f) -> vec3f {
        return emission + f_direct * direct + diffuse_albedo(base, metallic) * INV_PI * indirect + specular;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// The direction to the primary light: unit, toward a spot's position,
    /// against a directional light's travel, and finite at the spot itself.
    #[test]
    fn primary_light_direction() {
        let (x, spot) = (Vec3::new(1.0, 0.0, 0.0), Vec3::new(1.0, 2.0, 0.0));
        let axis = Vec3::new(0.0, -1.0, 0.0);
        assert!((primary_light_dir(x, spot, axis, true) - Vec3::Y).length() < 1e-6);
        assert!(
            (primary_light_dir(x, Vec3::new(3.0, 0.0, 4.0), Vec3::ZERO, true)
                - Vec3::new(0.4, 0.0, 0.8).normalize())
            .length()
                < 1e-6
        );
        assert_eq!(primary_light_dir(x, Vec3::ZERO, axis, false), Vec3::Y);
        assert_eq!(primary_light_dir(spot, spot, axis, true), Vec3::Y);
    }

    /// A glossy receiver's composition: `L_e + f·E_direct + c_diff/π·E + S`;
    /// a metal (no diffuse lobe) keeps only the direct term's BRDF and `S`.
    #[test]
    fn glossy_composition() {
        let (base, e) = (Vec3::new(0.8, 0.6, 0.4), Vec3::splat(2.0));
        let f = Vec3::new(0.5, 0.25, 0.125);
        let metal =
            glossy_radiance(base, Vec3::ZERO, 1.0, f, e, Vec3::splat(3.0), Vec3::splat(0.01));
        assert!((metal - (f * e + Vec3::splat(0.01))).length() < 1e-6);
        let dielectric =
            glossy_radiance(base, Vec3::splat(0.1), 0.0, f, e, Vec3::splat(3.0), Vec3::ZERO);
        assert!((dielectric - (Vec3::splat(0.1) + f * e + base * INV_PI * 3.0)).length() < 1e-6);
    }

    #[test]
    fn texel_coordinates_round_trip() {
        for size in [1u32, 8, 64, 512] {
            for t in 0..size {
                assert_eq!(light_map_texel(light_map_coord(t, size), size), t);
            }
            assert_eq!(light_map_texel(-1.5, size), 0);
            assert_eq!(light_map_texel(1.0, size), size - 1);
        }
    }

    /// The texel solid angles of a perspective map sum to the solid angle
    /// of its square pyramid, `4·asin(tan²α / (1 + tan²α))` for half-angle α.
    #[test]
    fn texel_solid_angles_sum_to_the_pyramid() {
        let (size, tan) = (256u32, 0.7f32);
        let area = (2.0 * tan / size as f32).powi(2);
        let mut sum = 0.0f64;
        for ty in 0..size {
            for tx in 0..size {
                let (s, t) = (light_map_coord(tx, size) * tan, light_map_coord(ty, size) * tan);
                let cos = 1.0 / (1.0 + s * s + t * t).sqrt();
                sum += rsm_texel_solid_angle(area, cos) as f64;
            }
        }
        let t2 = (tan * tan) as f64;
        let exact = 4.0 * (t2 / (1.0 + t2)).asin();
        assert!((sum - exact).abs() < 1e-4 * exact, "{sum} vs {exact}");
    }

    #[test]
    fn irradiance_terms() {
        let n = Vec3::Y;
        let e = point_irradiance(Vec3::splat(4.0), n, Vec3::new(0.0, 2.0, 0.0));
        assert!((e - Vec3::ONE).abs().max_element() < 1e-6);
        assert_eq!(point_irradiance(Vec3::ONE, n, Vec3::new(0.0, -1.0, 0.0)), Vec3::ZERO);
        assert!(point_irradiance(Vec3::ONE, n, Vec3::ZERO).is_finite());
        let d = directional_irradiance(
            Vec3::splat(2.0),
            n,
            Vec3::new(0.0, 0.5f32.sqrt(), 0.5f32.sqrt()),
        );
        assert!((d.x - 2.0 * 0.5f32.sqrt()).abs() < 1e-6);
        assert_eq!(directional_irradiance(Vec3::ONE, n, -Vec3::Y), Vec3::ZERO);
    }

    #[test]
    fn map_coord_inverts_the_map_rays() {
        // A perspective ray axis + right·a·tan + up·b·tan at any depth.
        let (axis, right, up, tan) = (Vec3::NEG_Y, Vec3::X, Vec3::Z, 0.5);
        let rel = (axis + right * (0.25 * tan) + up * (-0.75 * tan)) * 3.0;
        assert!((light_map_coord_at(rel, right, axis, tan, true) - 0.25).abs() < 1e-6);
        assert!((light_map_coord_at(rel, up, axis, tan, true) + 0.75).abs() < 1e-6);
        // An orthographic point right·a·half + axis·anything.
        let rel = right * (0.5 * 2.0) + axis * 7.0;
        assert!((light_map_coord_at(rel, right, axis, 2.0, false) - 0.5).abs() < 1e-6);
    }

    #[test]
    fn display_encoding() {
        assert_eq!(display_encode(0.0), 0.0);
        assert_eq!(display_encode(-1.0), 0.0);
        // x = ½ maps to t = ½, sRGB-encoded 0.7354.
        assert!((display_encode(0.5) - 0.735_357).abs() < 1e-5);
        assert!(display_encode(1e30) <= 1.0 && display_encode(1e30) > 0.999);
        let mut last = 0.0;
        for k in 1..1000 {
            let v = display_encode(k as f32 * 1e-3);
            assert!(v > last, "monotone");
            last = v;
        }
    }

    #[test]
    fn map_depth() {
        let rel = Vec3::new(3.0, 4.0, 0.0);
        assert_eq!(light_map_depth(rel, Vec3::Y, true), 5.0);
        assert_eq!(light_map_depth(rel, Vec3::Y, false), 4.0);
    }

    #[test]
    fn shadow_test() {
        assert!(shadow_lit(1.0, 0.0, 0.0), "nothing in the map: lit");
        assert!(shadow_lit(1.0, 1.0, 0.0));
        assert!(!shadow_lit(2.0, 1.0, 0.1));
        assert!(shadow_bias(0.01, 1.0) >= 0.015 && shadow_bias(0.01, 0.0) <= 0.01 * 52.0);
        assert!(shadow_bias(0.01, 0.5) > shadow_bias(0.01, 1.0));
    }

    #[test]
    fn composition() {
        let l = diffuse_radiance(Vec3::splat(0.5), Vec3::X, Vec3::splat(core::f32::consts::PI));
        assert!((l - Vec3::new(1.5, 0.5, 0.5)).abs().max_element() < 1e-6);
    }
}
