//! Reflective shadow map (Dachsbacher & Stamminger 2005): every texel of a
//! map rendered from the primary light becomes a VPL at the surface it sees,
//! with the flux that surface reflects.

use crate::geometry::Geometry;
use crate::raster::{MapView, closest_hits};
use glam::Vec3;
use rayon::prelude::*;
use slc_core::light::Light;
use slc_core::ray::{face_against, surface_offset};
use slc_scene::scene::{PrimaryLight, Scene};
use slc_scene::vpl::Vpls;

/// Renders the `size × size` RSM of the scene's primary light: what the
/// ray of each texel of its [`LightMap`](slc_scene::scene::LightMap) hits
/// (rasterized: [`closest_hits`]), carrying the intensity toward the texel
/// times its solid angle (spot) or the irradiance times its area
/// (directional).
pub fn reflective_shadow_map(scene: &Scene, geo: &Geometry, size: u32) -> Vpls {
    let mut vpls = Vpls { size, ..Vpls::default() };
    reflective_shadow_map_into(scene, geo, &mut vpls);
    vpls
}

/// [`reflective_shadow_map`] at `vpls.size` into `vpls`, reusing its memory
/// when it already holds that many texels, else into new buffers.
pub fn reflective_shadow_map_into(scene: &Scene, geo: &Geometry, vpls: &mut Vpls) {
    let size = vpls.size;
    let n = size as usize * size as usize;
    let map = scene.primary.light_map(scene.bounds());
    let hits = closest_hits(
        &MapView { map, size: size as usize, t_min: surface_offset(scene.diagonal()) },
        geo,
        &scene.triangles,
    );
    let spot = scene.primary.spot().map(Light::Spot);
    let texel = |i: usize| -> (Vec3, (Vec3, Vec3)) {
        let (tx, ty) = (i % size as usize, i / size as usize);
        let (origin, dir, gathered) = map.texel_ray(tx as u32, ty as u32, size);
        let (t, tri) = hits.at(tx, ty);
        if tri == u32::MAX {
            return (origin, (-dir, Vec3::ZERO));
        }
        let incident = match scene.primary {
            // A spot light's parameters are checked when the scene is.
            PrimaryLight::Spot { .. } => {
                spot.as_ref().map_or(Vec3::ZERO, |s| s.intensity(dir)) * gathered
            }
            PrimaryLight::Directional { irradiance, .. } => irradiance * gathered,
        };
        // The VPL: the hit point, its normal toward the light, the
        // incident flux times the surface albedo.
        let gn = face_against(geo.normal(tri), dir);
        let p = origin + dir * t;
        let albedo = scene.materials[scene.material_of[tri as usize] as usize].albedo;
        (p, (scene.shading_normal(tri as usize, p, gn), incident * albedo))
    };
    if [vpls.position.len(), vpls.normal.len(), vpls.flux.len()].iter().all(|&l| l == n) {
        (&mut vpls.position, &mut vpls.normal, &mut vpls.flux)
            .into_par_iter()
            .enumerate()
            .for_each(|(i, (p, nrm, f))| (*p, (*nrm, *f)) = texel(i));
    } else {
        (vpls.position, (vpls.normal, vpls.flux)) = (0..n).into_par_iter().map(texel).unzip();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rasterized RSM is the one BVH ray casting gives, texel by texel,
    /// for the Cornell box's spot light and for a directional light.
    #[test]
    fn rasterized_rsm_equals_ray_casting() {
        let mut scene = Scene::cornell_box();
        let geo = Geometry::new(&scene.triangles);
        let sun = PrimaryLight::Directional {
            direction: Vec3::new(0.3, -1.0, 0.2),
            irradiance: Vec3::splat(2.0),
        };
        for primary in [scene.primary, sun] {
            scene.primary = primary;
            let size = 40;
            let vpls = reflective_shadow_map(&scene, &geo, size);
            let map = scene.primary.light_map(scene.bounds());
            let mut lit = 0;
            for i in 0..(size * size) as usize {
                let (origin, dir, _) = map.texel_ray(i as u32 % size, i as u32 / size, size);
                match geo.intersect(origin, dir, surface_offset(scene.diagonal()), f32::INFINITY) {
                    Some(hit) => {
                        let p = origin + dir * hit.t;
                        assert!(
                            (vpls.position[i] - p).length() <= 1e-5 * hit.t,
                            "texel {i}: {} vs {p}",
                            vpls.position[i]
                        );
                        lit += (vpls.flux[i] != Vec3::ZERO) as usize;
                    }
                    None => assert_eq!(
                        vpls.flux[i],
                        Vec3::ZERO,
                        "texel {i}: flux where the ray caster misses"
                    ),
                }
            }
            assert!(lit > (size * size) as usize / 4, "{primary:?}: {lit} texels lit");
        }
    }
}
