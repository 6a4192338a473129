//! Phase 4 of the headless test: slc-bevy's shadow rays against Bevy's own
//! shadow maps.

use super::*;
use bevy::light::{PointLightShadowMap, ShadowFilteringMethod};

/// Phase 4, shadows: the scene's lights replaced by 8 point lights around
/// the boxes (one strong one behind the tall box), the camera closer. (a) Bevy with unbounded ranges and
/// its shadow maps, (u) the same without shadow maps, (b) the mean of
/// `FRAMES` frames of slc-bevy with `SlcCamera::shadows`. Bevy's shadow
/// maps soften and shift edges (PCF, depth and normal biases) where slc's
/// rays are exact, so Bevy's sharpest settings are used (hardware 2×2
/// filtering, 2048² cube faces) and blocks near an edge are left out: a
/// pixel is on an edge where the shadowed fraction `a/u` varies by more
/// than 0.05 within `r` pixels of it (`r` = 1 per 96 of width), and a block
/// is checked only if no edge pixel lies within `2r` of it. Checked blocks: (b) = (a) within the bound of [`compare`](super::compare);
/// at least 16 of them, and at least 8 where the shadows take ≥ 10% of
/// the light (so a missing shadow fails). With `SlcCamera::visibility_reuse`
/// (the scene still), one frame after 16 at most half of one independent
/// frame's luminance RMSE against Bevy's image away from the edges. Then
/// again, without it, after the tall box moves, and after its mesh asset
/// is edited in place.
pub(super) fn shadows(app: &mut App) -> Result<String, String> {
    let world = app.world_mut();
    let old: Vec<Entity> = world.query_filtered::<Entity, With<SceneLight>>().iter(world).collect();
    for e in old {
        world.despawn(e);
    }
    // One strong light behind the tall box (its shadow runs toward the
    // camera) and seven weaker ones around.
    for i in 0..8 {
        let t = i as f32 * std::f32::consts::TAU / 7.0;
        let (p, intensity) = if i == 0 {
            (Vec3::new(-8.0, 7.0, -9.0), 2.5e6)
        } else {
            (
                Vec3::new(-5.0 + 12.0 * t.cos(), 5.0 + (i % 3) as f32 * 2.0, -6.0 + 12.0 * t.sin()),
                1.5e5,
            )
        };
        world.spawn((
            PointLight {
                color: Color::hsl(45.0 * i as f32, 0.5, 0.7),
                intensity,
                shadow_maps_enabled: true,
                ..default()
            },
            Transform::from_translation(p),
            SceneLight,
        ));
    }
    let camera = world.resource::<Target>().1;
    *world.get_mut::<Transform>(camera).expect("camera") =
        Transform::from_xyz(-2.0, 16.0, 16.0).looking_at(Vec3::new(-7.0, 0.0, -1.0), Vec3::Y);
    let mut settings = world.get_mut::<SlcCamera>(camera).expect("camera");
    (settings.accumulate, settings.shadows) = (false, true);
    world.entity_mut(camera).insert(ShadowFilteringMethod::Hardware2x2);
    world.insert_resource(PointLightShadowMap { size: 2048 });
    let first = shadow_compare(app, "")?;
    // The box moves: slc refits its occluders, Bevy renders its shadow maps anew.
    let world = app.world_mut();
    let tall = world.query_filtered::<Entity, With<TallBox>>().single(world).expect("the tall box");
    world.get_mut::<Transform>(tall).expect("box transform").translation +=
        Vec3::new(-1.0, 0.0, -1.0);
    let moved = shadow_compare(app, "-moved")?;
    // The box's mesh asset is edited in place (wider, floating):
    // slc builds its BVH again.
    let world = app.world_mut();
    let id = world.get::<Mesh3d>(tall).expect("box mesh").id();
    let wider: Mesh = Cuboid::new(5.0, 5.0, 5.0).into();
    *world.resource_mut::<Assets<Mesh>>().get_mut(id).expect("box mesh asset") = wider;
    let edited = shadow_compare(app, "-edited")?;
    Ok(format!("{first}\nafter moving the tall box: {moved}\nafter editing its mesh: {edited}"))
}

/// Phase 4's images and checks for the scene as it is (see [`shadows`]).
fn shadow_compare(app: &mut App, suffix: &str) -> Result<String, String> {
    let shadow_maps = |app: &mut App, on: bool| {
        let world = app.world_mut();
        let mut q = world.query_filtered::<&mut PointLight, With<SceneLight>>();
        for mut l in q.iter_mut(world) {
            l.shadow_maps_enabled = on;
        }
    };
    shadow_maps(app, true);
    set_mode(app, Mode::Unbounded);
    let truth = capture(app, 8, 2)[1].clone();
    shadow_maps(app, false);
    let open = capture(app, 8, 2)[1].clone();
    set_mode(app, Mode::Slc);
    let shots = capture(app, 4, FRAMES);
    let slc = mean_image(&shots);
    let name = |s: &str| format!("{s}{suffix}");
    write_images(&[
        (&name("shadows-bevy"), &truth),
        (&name("shadows-slc"), &slc),
        (&name("shadows-bevy-unshadowed"), &open),
    ]);
    let (w, h) = (size().0 as i64, size().1 as i64);
    let frac = |x: i64, y: i64| {
        let i = (y.clamp(0, h - 1) * w + x.clamp(0, w - 1)) as usize;
        let u = luminance(open[i]);
        if u > 1e-6 { luminance(truth[i]) / u } else { 1.0 }
    };
    // Edge pixels: Bevy's shadowed fraction varies by more than 0.05
    // within r pixels (r = 1 per 96 of width); a block is checked when no
    // edge pixel lies within 2r of it.
    let r = (w / 96).max(1);
    let edge: Vec<bool> = (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let (mut lo, mut hi) = (f64::MAX, f64::MIN);
            for dy in -r..=r {
                for dx in -r..=r {
                    let f = frac(x + dx, y + dy);
                    (lo, hi) = (lo.min(f), hi.max(f));
                }
            }
            hi - lo > 0.05
        })
        .collect();
    let b = i64::from(BLOCK);
    let near_edge = |blk: i64| {
        let (bx, by) = (blk % (w / b), blk / (w / b));
        (by * b - 2 * r..(by + 1) * b + 2 * r).any(|y| {
            (bx * b - 2 * r..(bx + 1) * b + 2 * r)
                .any(|x| (0..w).contains(&x) && (0..h).contains(&y) && edge[(y * w + x) as usize])
        })
    };
    let per_frame: Vec<Vec<f64>> = shots.iter().map(|f| blocks(f)).collect();
    let (a, bb, u) = (blocks(&truth), blocks(&slc), blocks(&open));
    let z = gaussian_quantile(0.001 / (2.0 * a.len() as f64));
    let (mut checked, mut shadowed, mut worst) = (0, 0, (0.0f64, 0usize));
    for i in 0..a.len() {
        if near_edge(i as i64) {
            continue;
        }
        checked += 1;
        if a[i] < 0.9 * u[i] {
            shadowed += 1;
        }
        let bound = block_bound(z, &per_frame, i, bb[i], a[i]);
        if (bb[i] - a[i]).abs() / bound > worst.0 {
            worst = ((bb[i] - a[i]).abs() / bound, i);
        }
    }
    let report = format!(
        "{checked} of {} blocks outside the penumbrae, {shadowed} of them with >= 10% of the light shadowed; slc (mean of {FRAMES} frames) against Bevy's shadow maps: worst block at {:.2} of its bound",
        a.len(),
        worst.0
    );
    if worst.0 > 1.0 {
        let i = worst.1;
        return Err(format!(
            "{report}
block {i}: slc {:.5} vs Bevy shadowed {:.5} (unshadowed {:.5})",
            bb[i], a[i], u[i]
        ));
    }
    if checked < 16 || shadowed < 8 {
        return Err(format!(
            "{report}
too few blocks to say much"
        ));
    }
    if !suffix.is_empty() {
        return Ok(report);
    }
    // Visibility reuse (`SlcCamera::visibility_reuse`), the scene still:
    // one frame after 16 against Bevy's shadow maps, away from the edges,
    // at most half of one independent frame's error (the frames above).
    let luminance_rmse = |img: &[[f32; 3]]| {
        let (mut se, mut n) = (0.0f64, 0usize);
        for i in (0..img.len()).filter(|&i| !edge[i]) {
            se += (luminance(img[i]) - luminance(truth[i])).powi(2);
            n += 1;
        }
        (se / n.max(1) as f64).sqrt()
    };
    let single = shots.iter().map(|f| luminance_rmse(f)).sum::<f64>() / shots.len() as f64;
    let set_reuse = |app: &mut App, on: bool| {
        let camera = app.world().resource::<Target>().1;
        let mut c = app.world_mut().get_mut::<SlcCamera>(camera).expect("camera");
        (c.reuse, c.visibility_reuse) = (on, on);
    };
    set_reuse(app, true);
    let reused = capture(app, 16, 1).remove(0);
    set_reuse(app, false);
    write_images(&[("shadows-slc-visibility-reuse-one-frame", &reused)]);
    let er = luminance_rmse(&reused);
    let report = format!(
        "{report}; one frame with visibility reuse after 16: luminance RMSE against Bevy's shadow maps away from the edges {er:.5}, one independent frame's {single:.5} ({:.3})",
        er / single
    );
    if er > 0.5 * single {
        return Err(format!("{report}\nvisibility reuse should halve one frame's error"));
    }
    Ok(report)
}
