//! The primary light's direct term of the VPL frame, shadowed.

use crate::geometry::Geometry;
use crate::raster::{MapView, Occluders};
use glam::Vec3;
use rayon::prelude::*;
use slc_core::frame::{directional_irradiance, point_irradiance};
use slc_core::light::Light;
use slc_core::ray::surface_offset;
use slc_scene::scene::{PrimaryLight, Scene};
use slc_scene::vpl::GBuffer;

/// Texels per edge of the light-space grid the primary light's shadow
/// segments are binned to (see [`Occluders`]).
const SHADOW_GRID: usize = 64;

/// Direct irradiance from the primary light into `out` (one value per
/// pixel), with shadow segments offset
/// along the geometric normal `geo_n` (cosines use the G-buffer's shading
/// normal). Every shadow segment runs along a ray of the light's map, so
/// it is tested against the triangles binned to its texel ([`Occluders`],
/// the ray caster's answer without a BVH walk), and only where the light
/// would add something (facing the light, inside a spot's cone).
pub(super) fn direct_light(
    scene: &Scene,
    geo: &Geometry,
    gb: &GBuffer,
    geo_n: &[Vec3],
    out: &mut Vec<Vec3>,
) {
    let diag = scene.diagonal();
    let spot = scene.primary.spot().map(Light::Spot);
    let map = MapView {
        map: scene.primary.light_map(scene.bounds()),
        size: SHADOW_GRID,
        t_min: surface_offset(diag),
    };
    let occluders = Occluders::new(map, geo, &scene.triangles);
    let pixel = |i: usize| -> Vec3 {
        if !gb.valid(i) {
            return Vec3::ZERO;
        }
        let (x, n) = (gb.position[i], gb.normal[i]);
        let from = x + geo_n[i] * surface_offset(diag);
        match scene.primary {
            PrimaryLight::Spot { position, .. } => {
                let v = position - x;
                // A spot light's parameters are checked when the scene is.
                let Some(spot) = spot.as_ref().filter(|_| n.dot(v) > 0.0) else {
                    return Vec3::ZERO;
                };
                let e = point_irradiance(spot.intensity(-v.normalize()), n, v);
                if e == Vec3::ZERO || occluders.occluded(from, position) { Vec3::ZERO } else { e }
            }
            PrimaryLight::Directional { direction, irradiance } => {
                let wi = -direction.normalize();
                if n.dot(wi) <= 0.0 || occluders.occluded(from, x + wi * 2.0 * diag) {
                    return Vec3::ZERO;
                }
                directional_irradiance(irradiance, n, wi)
            }
        }
    };
    // In place when the buffer has the frame's size (no fresh pages).
    if out.len() == gb.position.len() {
        out.par_iter_mut().enumerate().for_each(|(i, e)| *e = pixel(i));
    } else {
        *out = (0..gb.position.len()).into_par_iter().map(pixel).collect();
    }
}
