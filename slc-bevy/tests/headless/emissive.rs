//! Phase 5 of the headless test: an emissive mesh lights the floor through
//! slc-bevy, against the integral of its light on the CPU.

use super::*;
use bevy::camera::Exposure;
use slc_bevy::NotSlcLight;

/// Radiance of the emissive quad, cd/m² (Bevy's `emissive`).
const NITS: [f32; 3] = [3000.0, 2700.0, 2400.0];
/// The quad: centre, half side (in x and z), facing down.
const CENTRE: Vec3 = Vec3::new(-20.0, 4.0, 10.0);
const HALF: f32 = 1.5;

/// Every light but the three bad ones gone, a 3×3 m quad with an emissive
/// material hangs 4 m above the floor facing down, and the camera looks
/// straight down at it from 14 m (it sees the quad's back, culled, and the
/// floor under it), a twin quad with `NotSlcLight` beside it. Bevy has no
/// light left, so the image is slc's alone: the first quad's two
/// triangles as triangle lights. Expected, per
/// floor pixel: `∫ f(v, l) L cos θ cos θ' / d² dA` over the quad (a
/// 32×32 midpoint rule; `f` slc-core's `bevy_brdf`, which the unshadowed
/// phases hold to Bevy's own shading) times the camera's exposure. Each
/// 8×8 block on the floor: the mean of `FRAMES` frames within the bound
/// of [`compare`](super::compare); at least 48 blocks. An emitter facing
/// the wrong way, or in other units, fails. Then the quad's mesh asset is
/// edited to 10⁻⁴ of its area: the floor keeps at most 10⁻³ of its light.
pub(super) fn emissive(app: &mut App) -> Result<String, String> {
    let world = app.world_mut();
    let old: Vec<Entity> = world.query_filtered::<Entity, With<SceneLight>>().iter(world).collect();
    for e in old {
        world.despawn(e);
    }
    let quad: Mesh = Plane3d::new(-Vec3::Y, Vec2::splat(HALF)).into();
    let quad = world.resource_mut::<Assets<Mesh>>().add(quad);
    let glow = StandardMaterial {
        base_color: Color::BLACK,
        emissive: LinearRgba::rgb(NITS[0], NITS[1], NITS[2]),
        ..default()
    };
    let glow = world.resource_mut::<Assets<StandardMaterial>>().add(glow);
    let glow_id = glow.id();
    world.spawn((
        Mesh3d(quad.clone()),
        MeshMaterial3d(glow.clone()),
        Transform::from_translation(CENTRE),
    ));
    let edit = quad.clone();
    // The same quad beside it with `NotSlcLight`: shown only, it must
    // light nothing (the integral below has the first quad alone).
    world.spawn((
        Mesh3d(quad),
        MeshMaterial3d(glow),
        Transform::from_translation(CENTRE + Vec3::new(5.0, 0.0, 0.0)),
        NotSlcLight,
    ));
    let camera = world.resource::<Target>().1;
    let view = Transform::from_xyz(CENTRE.x, 14.0, CENTRE.z)
        .looking_at(Vec3::new(CENTRE.x, 0.0, CENTRE.z), Vec3::Z);
    *world.get_mut::<Transform>(camera).expect("camera") = view;
    set_mode(app, Mode::Slc);
    let shots = capture(app, 4, FRAMES);
    let slc = mean_image(&shots);

    // The floor pixels and their expected radiance.
    let (w, h) = size();
    let tan = (PerspectiveProjection::default().fov * 0.5).tan();
    let aspect = w as f32 / h as f32;
    let floor = LinearRgba::from(Color::srgb(0.7, 0.7, 0.7));
    let base = glam::Vec3::new(floor.red, floor.green, floor.blue);
    let nits = glam::Vec3::from(NITS) * Exposure::default().exposure();
    const N: usize = 32;
    let cell = 2.0 * HALF / N as f32;
    let expected: Vec<Option<[f32; 3]>> = (0..w * h)
        .map(|i| {
            let (x, y) = ((i % w) as f32 + 0.5, (i / w) as f32 + 0.5);
            let local = Vec3::new(
                (2.0 * x / w as f32 - 1.0) * tan * aspect,
                (1.0 - 2.0 * y / h as f32) * tan,
                -1.0,
            );
            let dir = view.rotation * local;
            let t = -view.translation.y / dir.y;
            let p = view.translation + dir * t;
            if !(t > 0.0 && p.x.abs() < 30.0 && p.z.abs() < 30.0) {
                return None;
            }
            let p = glam::Vec3::new(p.x, p.y, p.z);
            let v = (glam::Vec3::new(view.translation.x, view.translation.y, view.translation.z)
                - p)
                .normalize();
            let mut sum = glam::Vec3::ZERO;
            for a in 0..N {
                for b in 0..N {
                    let q = glam::Vec3::new(
                        CENTRE.x - HALF + (a as f32 + 0.5) * cell,
                        CENTRE.y,
                        CENTRE.z - HALF + (b as f32 + 0.5) * cell,
                    );
                    let d = q - p;
                    let d2 = d.length_squared();
                    let l = d / d2.sqrt();
                    // cos θ at the floor (n = +Y) and at the quad (n = −Y): both l.y.
                    let f = slc_core::brdf::bevy_brdf(base, 0.0, 0.9, 0.5, glam::Vec3::Y, v, l);
                    sum += f * nits * (l.y * l.y / d2);
                }
            }
            Some((sum * cell * cell).to_array())
        })
        .collect();
    write_images(&[
        ("emissive-slc", &slc),
        ("emissive-expected", &expected.iter().map(|e| e.unwrap_or_default()).collect::<Vec<_>>()),
    ]);

    // Per block on the floor: the frames' mean against the integral.
    let bw = w / BLOCK;
    let on_floor = |blk: u32| {
        let (bx, by) = (blk % bw, blk / bw);
        (by * BLOCK..(by + 1) * BLOCK).all(|y| {
            (bx * BLOCK..(bx + 1) * BLOCK).all(|x| expected[(y * w + x) as usize].is_some())
        })
    };
    let b = blocks(&slc);
    let a = blocks(&expected.iter().map(|e| e.unwrap_or_default()).collect::<Vec<_>>());
    let (checked, worst) = floor_blocks(&shots, &expected, &on_floor, [1.0; 3]);
    let report = format!(
        "an emissive 3x3 m quad (2 triangle lights) over {checked} floor blocks against its integral: worst block at {:.2} of its bound; brightest block {:.4}",
        worst.0,
        a.iter().cloned().fold(0.0, f64::max)
    );
    if worst.0 > 1.0 {
        let i = worst.1;
        return Err(format!("{report}\nblock {i}: slc {:.5} vs the integral {:.5}", b[i], a[i]));
    }
    if checked < 48 {
        return Err(format!("{report}\ntoo few floor blocks"));
    }

    // The same quad with an emissive texture of one colour: each triangle
    // emits `emissive` times the texture's mean over its UVs, here that
    // colour (sRGB-decoded), so every floor block matches the integral
    // scaled per channel.
    let tint = LinearRgba::from(Color::srgb_u8(255, 153, 77));
    let texture = Image::new_fill(
        bevy::render::render_resource::Extent3d { width: 4, height: 4, depth_or_array_layers: 1 },
        bevy::render::render_resource::TextureDimension::D2,
        &[255, 153, 77, 255],
        TextureFormat::Rgba8UnormSrgb,
        RenderAssetUsages::default(),
    );
    let world = app.world_mut();
    let texture = world.resource_mut::<Assets<Image>>().add(texture);
    world
        .resource_mut::<Assets<StandardMaterial>>()
        .get_mut(glow_id)
        .expect("the glow")
        .emissive_texture = Some(texture);
    let tinted = capture(app, 4, FRAMES);
    let scale = [tint.red, tint.green, tint.blue];
    let (checked, tinted_worst) = floor_blocks(&tinted, &expected, &on_floor, scale);
    let report = format!(
        "{report}; with a uniform emissive texture {scale:.3?} (linear), {checked} blocks, worst at {:.2} of its bound",
        tinted_worst.0
    );
    if tinted_worst.0 > 1.0 {
        return Err(format!("{report}\nthe textured quad's block {} is off", tinted_worst.1));
    }
    // The quad's material without its texture again.
    let mut materials = app.world_mut().resource_mut::<Assets<StandardMaterial>>();
    materials.get_mut(glow_id).expect("the glow").emissive_texture = None;

    // The quad's mesh asset edited to a 100× smaller side (10⁻⁴ of the
    // area): its triangles are read again and the floor gets next to
    // nothing (read once and kept, they would still light it fully).
    let small: Mesh = Plane3d::new(-Vec3::Y, Vec2::splat(HALF * 0.01)).into();
    *app.world_mut().resource_mut::<Assets<Mesh>>().get_mut(&edit).expect("the quad") = small;
    let after = mean_image(&capture(app, 4, 4));
    let lit = (0..a.len()).filter(|&i| on_floor(i as u32)).map(|i| b[i]).sum::<f64>();
    let left = blocks(&after);
    let left = (0..a.len()).filter(|&i| on_floor(i as u32)).map(|i| left[i]).sum::<f64>();
    if left.is_nan() || left > 1e-3 * lit {
        return Err(format!(
            "{report}\nthe quad's mesh edited to 10⁻⁴ of its area still lights the floor: {left:.5} of {lit:.5}"
        ));
    }
    Ok(format!(
        "{report}; edited to 1e-4 of its area, the floor keeps {:.1e} of its light",
        left / lit
    ))
}

/// The floor blocks (`on_floor`) of the frames' mean against the integral
/// `expected` scaled per channel by `scale`, each within the bound of
/// [`compare`](super::compare): how many were checked and the worst one's
/// error over its bound and index.
fn floor_blocks(
    shots: &[Vec<[f32; 3]>],
    expected: &[Option<[f32; 3]>],
    on_floor: &dyn Fn(u32) -> bool,
    scale: [f32; 3],
) -> (usize, (f64, usize)) {
    let scaled: Vec<[f32; 3]> = expected
        .iter()
        .map(|e| {
            let e = e.unwrap_or_default();
            [e[0] * scale[0], e[1] * scale[1], e[2] * scale[2]]
        })
        .collect();
    let a = blocks(&scaled);
    let b = blocks(&mean_image(shots));
    let per_frame: Vec<Vec<f64>> = shots.iter().map(|f| blocks(f)).collect();
    let z = gaussian_quantile(0.001 / (2.0 * a.len() as f64));
    let (mut checked, mut worst) = (0, (0.0f64, 0usize));
    for i in 0..a.len() {
        if !on_floor(i as u32) {
            continue;
        }
        checked += 1;
        let bound = block_bound(z, &per_frame, i, b[i], a[i]);
        if (b[i] - a[i]).abs() / bound > worst.0 {
            worst = ((b[i] - a[i]).abs() / bound, i);
        }
    }
    (checked, worst)
}
