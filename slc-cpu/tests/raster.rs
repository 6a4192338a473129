//! The rasterized visibility (`slc_cpu::raster`) against BVH ray casting on
//! a real mesh: the Stanford bunny's 4,968 small, thin triangles inside the
//! Cornell box (`scenes/bunny-in-cornell.toml`, the bunny from
//! `../shared/data`). The G-buffer's depth, the RSM's hit points and every
//! shadow segment toward the spot light must be the ray caster's; the
//! triangle hit may differ only where a ray meets an edge two share (at
//! most 0.1% of the pixels).

use glam::Vec3;
use slc_core::ray::{face_against, surface_offset};
use slc_cpu::gbuffer::render_gbuffer;
use slc_cpu::geometry::Geometry;
use slc_cpu::raster::{MapView, Occluders};
use slc_cpu::vpl::rsm::reflective_shadow_map;
use slc_scene::scene::PrimaryLight;
use slc_scene::scene_file::SceneFile;
use std::path::Path;

#[test]
fn raster_equals_ray_casting_on_the_bunny() {
    let file = SceneFile::load(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/bunny-in-cornell.toml"),
    )
    .expect("the bunny scene (../shared/data)");
    let scene = file.scene;
    assert!(scene.triangles.len() > 4968, "the bunny is in the scene");
    let geo = Geometry::new(&scene.triangles);
    let diag = scene.diagonal();
    // The G-buffer.
    let (w, h) = (160, 120);
    let (gb, geometric) = render_gbuffer(&scene, &geo, w, h);
    let cam = scene.camera;
    let (mut froms, mut ties) = (Vec::new(), 0);
    for i in 0..(w * h) as usize {
        let dir = cam.ray_dir((i % w as usize) as f32, (i / w as usize) as f32, w, h);
        match geo.intersect(cam.position, dir, 0.0, f32::INFINITY) {
            Some(hit) => {
                assert!(
                    gb.valid(i) && (gb.depth[i] - hit.t).abs() <= 1e-6 * hit.t,
                    "pixel {i}: depth {} vs {}",
                    gb.depth[i],
                    hit.t
                );
                // Where a ray meets an edge two triangles share, either is
                // the closest hit (same distance, another normal).
                ties += (geometric[i].dot(face_against(geo.normal(hit.triangle), dir)) < 0.999)
                    as usize;
                froms.push(gb.position[i] + geometric[i] * surface_offset(diag));
            }
            None => assert!(!gb.valid(i), "pixel {i}: a hit where the ray caster misses"),
        }
    }
    assert!(ties <= froms.len() / 1000, "{ties} of {} pixels see another triangle", froms.len());
    // The RSM.
    let size = 96;
    let vpls = reflective_shadow_map(&scene, &geo, size);
    let map = scene.primary.light_map(scene.bounds());
    for t in 0..(size * size) as usize {
        let (origin, dir, _) = map.texel_ray(t as u32 % size, t as u32 / size, size);
        match geo.intersect(origin, dir, surface_offset(diag), f32::INFINITY) {
            Some(hit) => {
                let p = origin + dir * hit.t;
                assert!(
                    (vpls.position[t] - p).length() <= 1e-5 * hit.t,
                    "texel {t}: {} vs {p}",
                    vpls.position[t]
                );
            }
            None => {
                assert_eq!(vpls.flux[t], Vec3::ZERO, "texel {t}: flux where the ray caster misses")
            }
        }
    }
    // Shadow segments from every surface point toward the spot.
    let PrimaryLight::Spot { position, .. } = scene.primary else {
        panic!("the scene has a spot light")
    };
    let occluders = Occluders::new(
        MapView { map, size: 64, t_min: surface_offset(diag) },
        &geo,
        &scene.triangles,
    );
    let blocked = froms.iter().filter(|&&a| {
        let o = occluders.occluded(a, position);
        assert_eq!(o, geo.occluded(a, position), "segment from {a}");
        o
    });
    let n = blocked.count();
    assert!(n > froms.len() / 20 && n < froms.len(), "{n} of {} segments blocked", froms.len());
}
