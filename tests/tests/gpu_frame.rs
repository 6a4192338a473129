//! The whole VPL frame on the GPU ([`slc_wgpu::frame::GpuVplFrame`]:
//! rasterized G-buffer and RSM, GPU-made VPLs, shadow-mapped direct light,
//! composition) against the CPU's ray-cast frame of the same scene, size,
//! RSM and settings.
//!
//! Rasterization and ray casting see different surfaces at silhouettes,
//! half floats round the RSM's normal and flux, and the GPU's shadow map
//! differs from the CPU's shadow rays within a texel or two of shadow
//! edges. The bounds say so: the image mean within 1%, the median pixel
//! within 1%, at most 2% of the pixels seeing another surface (valid mask)
//! and at most 3% of them differing by more than 10% (silhouettes, shadow
//! edges). The VPLs are compared as sets: the same count, total flux
//! within 0.5%.

use glam::Vec3;
use slc_cpu::vpl::VplContext;
use slc_scene::backend::Timing;
use slc_scene::scene::{Camera, PrimaryLight, Scene};
use slc_scene::temporal::TemporalSettings;
use slc_scene::vpl::{Culling, VplSettings};
use slc_tests::gpu;
use slc_tests::vpl::GpuVpl;
use slc_wgpu::frame::{FrameDesc, GpuVplFrame, Stage, indirect_settings};
use slc_wgpu::passes::IndirectSettings;

const W: u32 = 128;
const H: u32 = 96;
const RSM: u32 = 32;

fn settings(culling: Culling, denoise: bool) -> VplSettings {
    VplSettings { culling, denoise, ..VplSettings::default() }
}

/// The culling named `name` at this file's ε (0.008) and clamp range (0.1).
fn culling(name: &str) -> Culling {
    Culling::named(name, 0.008, 1.0, 0.1).unwrap()
}

/// The frame's own settings for the CPU frame's `s`, at the frame's clamp
/// distance (what the CLI does).
fn on(frame: &GpuVplFrame, s: &VplSettings) -> IndirectSettings {
    indirect_settings(s, frame.min_distance()).unwrap()
}

/// Relative image statistics of `gpu` against `cpu` over the pixels both
/// see a surface in: (largest channel's relative image-mean difference,
/// median pixel difference, share of
/// pixels whose masks differ, share of pixels differing by > 10%).
fn compare(
    gpu: &[Vec3],
    cpu: &[Vec3],
    cpu_valid: &dyn Fn(usize) -> bool,
    gpu_valid: &dyn Fn(usize) -> bool,
) -> (f64, f64, f64, f64) {
    let (mut masks, mut rel, mut sum_g, mut sum_c) =
        (0usize, Vec::new(), glam::DVec3::ZERO, glam::DVec3::ZERO);
    for i in 0..cpu.len() {
        sum_g += gpu[i].as_dvec3();
        sum_c += cpu[i].as_dvec3();
        if cpu_valid(i) != gpu_valid(i) {
            masks += 1;
        } else if cpu_valid(i) {
            rel.push(
                ((gpu[i] - cpu[i]).abs().element_sum() / cpu[i].element_sum().max(1e-6)) as f64,
            );
        }
    }
    rel.sort_by(f64::total_cmp);
    let far = rel.iter().filter(|&&r| r > 0.1).count() as f64 / rel.len().max(1) as f64;
    // The image means' difference: the worst channel's, relative.
    (
        ((sum_g - sum_c).abs() / sum_c).max_element(),
        rel[rel.len() / 2],
        masks as f64 / cpu.len() as f64,
        far,
    )
}

fn check_frame(scene: &Scene, what: &str) {
    let Some(gpu) = gpu() else { return };
    let mut frame = GpuVplFrame::new(
        gpu,
        scene,
        &FrameDesc { width: W, height: H, rsm_size: RSM, shadow_size: 1024, min_distance: None },
    )
    .unwrap();
    let ctx = VplContext::new(scene, W, H, RSM, None).unwrap();
    for (method, denoise) in [(Culling::None, false), (culling("slc"), true)] {
        let s = settings(method, denoise);
        let out = frame.render(&on(&frame, &s)).unwrap();
        assert!(out.image.is_finite(), "{what}: non-finite pixels");
        let cpu = ctx.render(&s).unwrap();
        let inputs = frame.read_inputs().unwrap();
        let (mean, median, masks, far) =
            compare(&out.image.data, &cpu.image.data, &|i| ctx.gbuffer().valid(i), &|i| {
                inputs.gbuffer.valid(i)
            });
        eprintln!(
            "{what} {}: mean {mean:.2e}, median pixel {median:.2e}, {:.2}% masks differ, {:.2}% pixels > 10% off",
            method.name(),
            100.0 * masks,
            100.0 * far
        );
        // SLC draws ξ per VPL: the same ξ on both backends, but a VPL's
        // range differs where its flux does (half floats), so its image
        // noise differs; allow the mean 2%.
        let mean_bound = if method == culling("slc") { 0.02 } else { 0.01 };
        assert!(mean <= mean_bound, "{what} {}: image mean differs by {mean:.3e}", method.name());
        assert!(median <= 0.01, "{what} {}: median pixel differs by {median:.3e}", method.name());
        assert!(masks <= 0.02, "{what}: {:.2}% of the pixels see another surface", 100.0 * masks);
        assert!(
            far <= 0.03,
            "{what} {}: {:.2}% of the pixels differ by more than 10%",
            method.name(),
            100.0 * far
        );
    }
}

fn spot_frame_matches_the_cpu_frame() {
    check_frame(&Scene::cornell_box(), "cornell spot");
}

/// The glossy box: the GPU frame shades glossy pixels with the glTF BRDF
/// (the glossy indirect pass and composition), as the CPU frame does,
/// within the same bounds.
fn glossy_frame_matches_the_cpu_frame() {
    check_frame(&Scene::cornell_box_glossy(), "cornell glossy");
}

/// The glossy box's GPU frame against the same box made matte (every
/// material Lambertian with its base colour and emission), same settings:
/// the Lambertian pixels are the same (their shading is unchanged, within
/// 1e-6 relative), the glossy ones differ (mean relative difference over
/// 10%: before the glossy pass the GPU frame rendered them matte).
fn glossy_frame_differs_from_matte_on_glossy_pixels() {
    let Some(gpu) = gpu() else { return };
    let glossy = Scene::cornell_box_glossy();
    let mut matte = glossy.clone();
    for m in &mut matte.materials {
        *m = slc_scene::scene::Material::lambertian(m.albedo, m.emission);
    }
    let desc =
        FrameDesc { width: W, height: H, rsm_size: RSM, shadow_size: 1024, min_distance: None };
    let s = settings(culling("slc"), true);
    let render = |scene: &Scene| {
        let mut frame = GpuVplFrame::new(gpu, scene, &desc).unwrap();
        let image = frame.render(&on(&frame, &s)).unwrap().image;
        (image, frame.read_inputs().unwrap())
    };
    let (a, inputs) = render(&glossy);
    let (b, _) = render(&matte);
    let gb = &inputs.gbuffer;
    let rel = |i: usize| {
        ((a.data[i] - b.data[i]).abs().element_sum() / b.data[i].element_sum().max(1e-6)) as f64
    };
    let (mut lambert_worst, mut glossy_sum, mut glossy_n) = (0.0f64, 0.0, 0);
    for i in (0..a.data.len()).filter(|&i| gb.valid(i)) {
        if gb.specular_at(i).is_some() {
            glossy_sum += rel(i);
            glossy_n += 1;
        } else {
            lambert_worst = lambert_worst.max(rel(i));
        }
    }
    let glossy_mean = glossy_sum / glossy_n.max(1) as f64;
    eprintln!(
        "glossy vs matte GPU frame: {glossy_n} glossy pixels differ by {glossy_mean:.3} on average; Lambertian pixels at most {lambert_worst:.2e}"
    );
    assert!(glossy_n * 10 >= a.data.len(), "{glossy_n} glossy pixels");
    assert!(
        glossy_mean > 0.1,
        "the glossy pixels look matte: mean relative difference {glossy_mean}"
    );
    assert!(lambert_worst <= 1e-6, "Lambertian pixels changed: {lambert_worst}");
}

fn directional_frame_matches_the_cpu_frame() {
    let mut scene = Scene::cornell_box();
    scene.primary = PrimaryLight::Directional {
        direction: Vec3::new(0.3, -1.0, -0.4).normalize(),
        irradiance: Vec3::splat(2.0),
    };
    check_frame(&scene, "cornell directional");
}

/// The glossy box under a directional primary light: the composition's
/// direction to the light is the light's reversed travel (an orthographic
/// map), on the GPU as on the CPU.
fn glossy_directional_frame_matches_the_cpu_frame() {
    let mut scene = Scene::cornell_box_glossy();
    scene.primary = PrimaryLight::Directional {
        direction: Vec3::new(0.3, -1.0, -0.4).normalize(),
        irradiance: Vec3::splat(2.0),
    };
    check_frame(&scene, "cornell glossy directional");
}

/// The GPU-made VPLs (RSM rasterized, flux from the shared texel solid
/// angle) against the CPU's ray-cast ones at the default 65,536: the same
/// count, the same texels without flux (a half-float flux target once
/// flushed 28% of the lit ones to zero), the same total flux within 1e-5,
/// and texel for texel (those carrying more than 1e-4 of the largest
/// texel's flux, at most 1% excepted: texels on an edge hit different
/// faces) the same position within 0.1% of the scene and flux within 0.1%
/// (grazing texels differ by ~1.3e-4: the rasterizer's and the ray
/// caster's hit points differ in their last bits).
fn gpu_vpls_match_cpu_vpls() {
    let Some(gpu) = gpu() else { return };
    let scene = Scene::cornell_box();
    let mut frame = GpuVplFrame::new(
        gpu,
        &scene,
        &FrameDesc { width: W, height: H, rsm_size: 256, shadow_size: 256, min_distance: None },
    )
    .unwrap();
    frame.render(&on(&frame, &settings(culling("slc"), false))).unwrap();
    let g = frame.read_inputs().unwrap().vpls;
    let ctx = VplContext::new(&scene, W, H, 256, None).unwrap();
    let c = ctx.vpls();
    assert_eq!(g.len(), c.len());
    let total = |f: &[Vec3]| f.iter().fold(Vec3::ZERO, |a, &b| a + b);
    let (tg, tc) = (total(&g.flux), total(&c.flux));
    let rel = ((tg - tc).abs() / tc).max_element();
    eprintln!("VPL flux: GPU {tg}, CPU {tc}, {rel:.2e} relative");
    assert!(rel <= 1e-5, "total VPL flux differs by {rel:.3e}: GPU {tg} vs CPU {tc}");
    let dark = |f: &[Vec3]| f.iter().filter(|f| **f == Vec3::ZERO).count();
    assert_eq!(dark(&g.flux), dark(&c.flux), "texels without flux");
    let peak = c.flux.iter().map(|f| f.max_element()).fold(0.0f32, f32::max);
    let (mut lit, mut off) = (0, 0);
    for t in 0..c.len() {
        if c.flux[t].max_element() > 1e-4 * peak {
            lit += 1;
            let dp = (g.position[t] - c.position[t]).length() / scene.diagonal();
            let df = ((g.flux[t] - c.flux[t]).abs() - c.flux[t] * 1e-3).max_element();
            if dp > 1e-3 || df > 0.0 {
                off += 1;
                eprintln!(
                    "texel {t}: CPU {} {}, GPU {} {}",
                    c.position[t], c.flux[t], g.position[t], g.flux[t]
                );
            }
        }
    }
    assert!(lit > c.len() / 3, "only {lit} lit texels");
    assert!(off <= lit / 100, "{off} of {lit} lit texels differ");
}

/// Every stage is timed, by GPU timestamps where a hardware adapter has
/// them.
fn every_stage_is_timed() {
    let Some(gpu) = gpu() else { return };
    let mut frame = GpuVplFrame::new(
        gpu,
        &Scene::cornell_box(),
        &FrameDesc { width: 64, height: 64, rsm_size: 16, shadow_size: 64, min_distance: None },
    )
    .unwrap();
    let out = frame.render(&on(&frame, &settings(culling("slc"), true))).unwrap();
    let names: Vec<&str> = out.stages.iter().map(|s| s.name).collect();
    assert_eq!(
        names,
        [
            "G-buffer",
            "RSM",
            "shadow map",
            "VPL generation",
            "light update",
            "culling boxes",
            "culling boxes",
            "shading",
            "denoise",
            "near field",
            "irradiance export",
            "direct",
            "composition"
        ]
    );
    assert!(out.stages.iter().all(|s| s.ms.is_finite() && s.ms >= 0.0));
    let software = gpu.adapter.device_type == wgpu::DeviceType::Cpu;
    assert_eq!(out.timing == Timing::GpuTimestamps, gpu.timestamps && !software);
    assert!(out.stats.total_ms > 0.0 && out.stats.kept_per_pixel > 0.0);
    let none = frame.render(&on(&frame, &settings(Culling::None, false))).unwrap();
    assert!(!none.stages.iter().any(|s| s.name == "light update" || s.name == "denoise"));
}

/// A 64×48 frame of the Cornell box for the moving tests: its descriptor,
/// scene, frame, SLC settings and first image.
fn small_box(
    gpu: &slc_wgpu::GpuContext,
) -> (FrameDesc, Scene, GpuVplFrame, IndirectSettings, slc_scene::image::Image) {
    let desc =
        FrameDesc { width: 64, height: 48, rsm_size: 16, shadow_size: 128, min_distance: None };
    let scene = Scene::cornell_box();
    let mut frame = GpuVplFrame::new(gpu, &scene, &desc).unwrap();
    let s = on(&frame, &settings(culling("slc"), true));
    let before = frame.render(&s).unwrap().image;
    (desc, scene, frame, s, before)
}

/// Moving the primary light with [`GpuVplFrame::set_primary`] renders the
/// image of a frame built with the moved light (the same uniforms: equal
/// bit for bit) and not the old one; an invalid light is refused and
/// leaves the frame as it was. Recording with timestamps
/// ([`GpuVplFrame::record_timed`]) times every stage where the adapter
/// has usable timestamps, and says so otherwise.
fn moved_light_renders_as_a_new_frame() {
    let Some(gpu) = gpu() else { return };
    let (desc, mut scene, mut frame, s, before) = small_box(gpu);
    let PrimaryLight::Spot { position, direction, intensity, inner, outer } = scene.primary else {
        unreachable!("a spot")
    };
    scene.primary = PrimaryLight::Spot {
        position: position + Vec3::new(0.15, -0.05, 0.1),
        direction: direction + Vec3::new(0.2, 0.0, 0.0),
        intensity,
        inner,
        outer,
    };
    frame.set_primary(&scene.primary).unwrap();
    let moved = frame.render(&s).unwrap().image;
    let fresh = GpuVplFrame::new(gpu, &scene, &desc).unwrap().render(&s).unwrap().image;
    assert_eq!(moved.data, fresh.data, "the moved light renders as a frame built with it");
    let changed = moved
        .data
        .iter()
        .zip(&before.data)
        .filter(|(a, b)| (**a - **b).abs().max_element() > 1e-3)
        .count();
    assert!(changed > moved.data.len() / 10, "only {changed} pixels changed");
    let bad = PrimaryLight::Spot { position, direction: Vec3::ZERO, intensity, inner, outer };
    assert!(frame.set_primary(&bad).is_err());
    assert_eq!(frame.render(&s).unwrap().image.data, moved.data, "a refused light changes nothing");
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    let timed = frame.record_timed(&mut enc, &s).unwrap();
    gpu.queue.submit([enc.finish()]);
    gpu.wait().unwrap();
    let software = gpu.adapter.device_type == wgpu::DeviceType::Cpu;
    assert_eq!(timed, gpu.timestamps && !software);
    match frame.stage_times().unwrap() {
        Some(times) => assert!(
            times.len() == 11 && times.iter().all(|t| t.ms.is_finite() && t.ms >= 0.0),
            "{times:?}"
        ),
        None => assert!(!timed),
    }
}

/// Moving the camera with [`GpuVplFrame::set_camera`] renders the image
/// of a frame built with the moved camera (equal bit for bit); a bad
/// camera is refused and changes nothing.
fn moved_camera_renders_as_a_new_frame() {
    let Some(gpu) = gpu() else { return };
    let (desc, mut scene, mut frame, s, before) = small_box(gpu);
    let step = Vec3::X * (0.08 * scene.diagonal());
    scene.camera = Camera {
        position: scene.camera.position + step,
        target: scene.camera.target + step * 0.5,
        ..scene.camera
    };
    frame.set_camera(&scene.camera).unwrap();
    let moved = frame.render(&s).unwrap().image;
    let fresh = GpuVplFrame::new(gpu, &scene, &desc).unwrap().render(&s).unwrap().image;
    assert_eq!(moved.data, fresh.data, "the moved camera renders as a frame built with it");
    assert_ne!(moved.data, before.data);
    assert!(frame.set_camera(&Camera { vfov_deg: 0.0, ..scene.camera }).is_err());
    assert!(frame.set_camera(&Camera { target: scene.camera.position, ..scene.camera }).is_err());
    assert_eq!(frame.camera(), &scene.camera, "a refused camera changes nothing");
    assert_eq!(frame.render(&s).unwrap().image.data, moved.data);
}

/// With temporal accumulation on and nothing moving, frame `n` (below the
/// history cap, where no change test runs yet) is the plain mean of the
/// `n` frames the frame renders without it: the composition is linear in
/// the accumulated irradiance and specular correction (glossy box), so
/// the images agree to float rounding (1e-4 relative). Consecutive frames
/// then differ far less than without accumulation (observed below), and
/// a moved light (a reported change) drops the history.
fn temporal_frame_is_the_mean_of_its_frames() {
    let Some(gpu) = gpu() else { return };
    let desc =
        FrameDesc { width: 64, height: 48, rsm_size: 16, shadow_size: 128, min_distance: None };
    let scene = Scene::cornell_box_glossy();
    let mut frame = GpuVplFrame::new(gpu, &scene, &desc).unwrap();
    let n = 6;
    let base = on(&frame, &settings(culling("slc"), true));
    let mut mean = vec![Vec3::ZERO; (desc.width * desc.height) as usize];
    let mut single = Vec::new();
    for f in 0..n {
        let img = frame.render(&IndirectSettings { frame: f, ..base }).unwrap().image;
        mean.iter_mut().zip(&img.data).for_each(|(m, x)| *m += *x / n as f32);
        single.push(img);
    }
    frame.set_temporal(Some(TemporalSettings::default())).unwrap();
    let mut acc = Vec::new();
    for f in 0..n {
        acc.push(frame.render(&IndirectSettings { frame: f, ..base }).unwrap().image);
    }
    let last = acc.last().unwrap();
    // A rasterized surface point reprojects to its own pixel centre within
    // ~1e-3 pixel, so a neighbour on the same plane may take a bilinear
    // weight of that order: at a strong gradient (a shadow edge) that is
    // above 1e-4 relative: 2% of the pixels may (observed: 40 of 3,072),
    // none by more than 1% (observed: 1.1e-3).
    let rel: Vec<f32> = last
        .data
        .iter()
        .zip(&mean)
        .map(|(a, m)| (*a - *m).abs().max_element() / (m.max_element() + 1e-6))
        .collect();
    let off = rel.iter().filter(|&&r| r > 1e-4).count();
    let worst = rel.iter().copied().fold(0.0, f32::max);
    eprintln!(
        "accumulated frame vs the mean of its frames: {off} pixels beyond 1e-4, worst {worst:.2e}"
    );
    assert!(
        off * 50 <= rel.len() && worst < 1e-2,
        "{off} pixels of the accumulated frame differ from the mean of the frames (worst {worst})"
    );
    let flicker = |v: &[slc_scene::image::Image]| {
        v.windows(2).map(|w| w[1].rmse(&w[0])).sum::<f64>() / (v.len() - 1) as f64
    };
    let (without, with) = (flicker(&single), flicker(&acc));
    eprintln!(
        "consecutive-frame RMSE over {n} frames: {without:.3e} without accumulation, {with:.3e} with"
    );
    assert!(with * 2.0 < without, "accumulation must steady the image");
    frame.set_primary(&scene.primary).unwrap();
    let changed = frame.render(&IndirectSettings { frame: n, ..base }).unwrap().image;
    frame.set_temporal(None).unwrap();
    assert_eq!(
        frame.render(&IndirectSettings { frame: 0, ..base }).unwrap().image.data,
        single[0].data,
        "off again: the plain frame"
    );
    let plain = frame.render(&IndirectSettings { frame: n, ..base }).unwrap().image;
    let worst = changed
        .data
        .iter()
        .zip(&plain.data)
        .map(|(a, b)| (*a - *b).abs().max_element() / (b.max_element() + 1e-6))
        .fold(0.0, f32::max);
    assert!(
        worst < 1e-5,
        "after a reported change the frame is the plain frame (worst {worst:.1e})"
    );
    assert!(frame.set_temporal(Some(TemporalSettings { max_history: f32::NAN })).is_err());
}

/// Bad sizes and settings are typed errors, not panics.
fn bad_frames_are_errors() {
    let Some(gpu) = gpu() else { return };
    let scene = Scene::cornell_box();
    for desc in [
        FrameDesc { width: 0, height: 8, rsm_size: 16, shadow_size: 64, min_distance: None },
        FrameDesc { width: 8, height: 8, rsm_size: 12, shadow_size: 64, min_distance: None },
        FrameDesc { width: 8, height: 8, rsm_size: 16, shadow_size: 0, min_distance: None },
        FrameDesc {
            width: 8,
            height: 8,
            rsm_size: 16,
            shadow_size: 64,
            min_distance: Some(f32::NAN),
        },
    ] {
        assert!(GpuVplFrame::new(gpu, &scene, &desc).is_err(), "{desc:?}");
    }
    let mut frame = GpuVplFrame::new(
        gpu,
        &scene,
        &FrameDesc { width: 16, height: 16, rsm_size: 16, shadow_size: 64, min_distance: None },
    )
    .unwrap();
    // The CPU frame's settings the frame has no counterpart for are
    // refused when converted (the reference); the pass's own are checked
    // at the record; a bad culling cannot be made at all.
    assert!(indirect_settings(&settings(Culling::Reference, false), frame.min_distance()).is_err());
    assert!(
        indirect_settings(
            &VplSettings { fixed_xi: Some(1.0), ..VplSettings::default() },
            frame.min_distance()
        )
        .is_err()
    );
    assert!(
        frame
            .render(&IndirectSettings { min_distance: f32::NAN, ..IndirectSettings::default() })
            .is_err()
    );
    assert!(
        frame
            .render(&IndirectSettings {
                culling: Culling::Reference,
                ..IndirectSettings::default()
            })
            .is_err()
    );
    assert!(Culling::clamped(-1.0).is_err() && Culling::stochastic(-1.0, 1.0).is_err());
    assert!(frame.render(&IndirectSettings::default()).is_ok());
}

/// The timestamp path, forced on whatever adapter runs the tests (lavapipe
/// has timestamps, though their values do not bracket its threads' work):
/// with the near field on, the frame has every stage (the culling boxes in
/// two passes), the timer holds a pair for each pass (it once held one
/// fewer, and the composition got none while names and times were zipped
/// out of step), and every pass gets its own duration, in order, from
/// `render`, `record_timed` and, frame after frame, `time_sequence`.
fn timestamp_path_times_every_stage() {
    let Some(gpu) = gpu() else { return };
    if !gpu.timestamps {
        panic!(
            "the test adapter ({}) has no TIMESTAMP_QUERY: the timestamp path cannot be tested",
            gpu.describe()
        );
    }
    let mut frame = GpuVplFrame::new(
        gpu,
        &Scene::cornell_box(),
        &FrameDesc { width: 32, height: 32, rsm_size: 16, shadow_size: 64, min_distance: None },
    )
    .unwrap();
    assert!(frame.use_timestamps(true));
    let s = on(&frame, &settings(culling("slc"), true));
    let out = frame.render(&s).unwrap();
    assert_eq!(out.timing, Timing::GpuTimestamps);
    // Every stage but the temporal accumulation (off unless asked for), the
    // culling boxes twice (clusters, then groups).
    let twice = |st: Stage, dup: &[Stage]| if dup.contains(&st) { vec![st, st] } else { vec![st] };
    let all: Vec<Stage> = Stage::ALL
        .iter()
        .copied()
        .filter(|&st| st != Stage::Temporal)
        .flat_map(|st| twice(st, &[Stage::Bounds]))
        .collect();
    assert_eq!(
        out.stages.iter().map(|t| t.stage).collect::<Vec<_>>(),
        all,
        "every stage, in order"
    );
    assert!(
        out.stages.iter().all(|t| t.ms.is_finite() && t.ms >= 0.0 && t.name == t.stage.name()),
        "{:?}",
        out.stages
    );
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    assert!(frame.record_timed(&mut enc, &s).unwrap());
    gpu.queue.submit([enc.finish()]);
    let times = frame.stage_times().unwrap().expect("timed");
    assert_eq!(times.iter().map(|t| t.stage).collect::<Vec<_>>(), all);
    // Without denoise and near field: fewer stages, still in step.
    let s = IndirectSettings { denoise: false, near_radius: Some(0.0), ..s };
    let out = frame.render(&s).unwrap();
    let want: Vec<Stage> =
        all.iter().copied().filter(|st| !matches!(st, Stage::Denoise | Stage::NearField)).collect();
    assert_eq!(out.stages.iter().map(|t| t.stage).collect::<Vec<_>>(), want);
    // Frames timed back to back after a warm-up: each frame holds the
    // frame's passes in order, and every stage's spread is ordered.
    let seq =
        frame.time_sequence(&s, std::time::Duration::from_millis(30), 5).unwrap().expect("timed");
    assert_eq!(seq.frames.len(), 5);
    assert!(seq.warmup_frames >= 4, "{} warm-up frames", seq.warmup_frames);
    for f in &seq.frames {
        assert_eq!(f.iter().map(|t| t.stage).collect::<Vec<_>>(), want);
    }
    let spreads = seq.stages();
    assert_eq!(spreads.len(), want.iter().filter(|&&st| st != Stage::Bounds).count() + 1);
    for st in &spreads {
        assert!(
            0.0 <= st.min_ms && st.min_ms <= st.median_ms && st.median_ms <= st.max_ms,
            "{st:?}"
        );
    }
    let (median, lo, hi) = seq.spread(&[]);
    assert!(lo <= median && median <= hi && hi.is_finite(), "{lo} {median} {hi}");
    assert!(!frame.use_timestamps(false));
    assert_eq!(frame.time_sequence(&s, std::time::Duration::ZERO, 5).unwrap(), None);
    assert_eq!(frame.stage_times().unwrap(), None);
    // The glossy frame with temporal accumulation denoises and accumulates
    // twice (irradiance, then the specular correction): every stage of
    // Stage::ALL, the denoise and the accumulation twice, each timed.
    let desc =
        FrameDesc { width: 32, height: 32, rsm_size: 16, shadow_size: 64, min_distance: None };
    let mut frame = GpuVplFrame::new(gpu, &Scene::cornell_box_glossy(), &desc).unwrap();
    assert!(frame.use_timestamps(true));
    frame.set_temporal(Some(TemporalSettings::default())).unwrap();
    let s = on(&frame, &settings(culling("slc"), true));
    let out = frame.render(&s).unwrap();
    let want: Vec<Stage> = Stage::ALL
        .iter()
        .flat_map(|&st| twice(st, &[Stage::Denoise, Stage::Temporal, Stage::Bounds]))
        .collect();
    assert_eq!(
        out.stages.iter().map(|t| t.stage).collect::<Vec<_>>(),
        want,
        "every stage, the culling boxes, the denoise and the accumulation twice"
    );
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    assert!(frame.record_timed(&mut enc, &s).unwrap());
    gpu.queue.submit([enc.finish()]);
    assert_eq!(frame.stage_times().unwrap().expect("timed").len(), want.len());
}

/// [`GpuVplFrame::render_reference`] (every VPL at every pixel of the
/// frame's own G-buffer and RSM, composed on the GPU) is what the CLI
/// composed on the host before it: the frame's inputs read back
/// ([`GpuVplFrame::read_inputs`]), shaded by `GpuVpl`'s reference and
/// composed with the frame's direct light ([`GpuVplFrame::read_direct`],
/// `GBuffer::radiance`), pixel for pixel within 1e-4 relative (the
/// GPU's composition and BRDF round differently), Lambertian and glossy.
/// The reference has no culling, denoise, near field or temporal stage,
/// and leaves the frame's own frames as they were.
fn reference_matches_the_host_composition() {
    let Some(gpu) = gpu() else { return };
    let desc =
        FrameDesc { width: W, height: H, rsm_size: RSM, shadow_size: 1024, min_distance: None };
    for scene in [Scene::cornell_box(), Scene::cornell_box_glossy()] {
        let mut frame = GpuVplFrame::new(gpu, &scene, &desc).unwrap();
        frame.set_temporal(Some(TemporalSettings::default())).unwrap();
        let st = on(&frame, &settings(culling("slc"), true));
        let out = frame.render_reference(&st).unwrap();
        let stages: Vec<Stage> = out.stages.iter().map(|t| t.stage).collect();
        for absent in [Stage::LightUpdate, Stage::Denoise, Stage::NearField, Stage::Temporal] {
            assert!(!stages.contains(&absent), "{}: the reference ran {absent:?}", scene.name);
        }
        let inputs = frame.read_inputs().unwrap();
        let direct = frame.read_direct().unwrap();
        let s = settings(Culling::Reference, false);
        let shaded = GpuVpl::new(gpu, &inputs).unwrap().shade(&s).unwrap();
        let glossy = scene.materials.iter().any(|m| m.has_specular());
        assert_eq!(shaded.specular.is_empty(), !glossy, "{}: specular correction", scene.name);
        let gb = &inputs.gbuffer;
        let (mut worst, mut lit) = (0.0f32, 0);
        for i in 0..direct.len() {
            let sp = shaded.specular.get(i).copied();
            let host = gb.radiance(i, &scene.primary, direct[i], shaded.irradiance[i], sp);
            let d = (out.image.data[i] - host).abs().max_element();
            worst = worst.max(d / host.max_element().max(1e-6));
            lit += (host.max_element() > 0.0) as usize;
        }
        eprintln!("{} reference vs host composition: worst relative {worst:.2e}", scene.name);
        assert!(lit * 2 > direct.len(), "{}: {lit} lit pixels", scene.name);
        assert!(worst <= 1e-4, "{}: reference differs by {worst:.3e}", scene.name);
        // The frame's own frames are unchanged by a reference in between.
        frame.set_temporal(None).unwrap();
        let a = frame.render(&st).unwrap().image;
        frame.render_reference(&st).unwrap();
        assert_eq!(frame.render(&st).unwrap().image.data, a.data, "{}", scene.name);
    }
}

slc_tests::harness!(
    Gpu: timestamp_path_times_every_stage,
    Gpu: spot_frame_matches_the_cpu_frame,
    Gpu: directional_frame_matches_the_cpu_frame,
    Gpu: glossy_directional_frame_matches_the_cpu_frame,
    Gpu: glossy_frame_matches_the_cpu_frame,
    Gpu: glossy_frame_differs_from_matte_on_glossy_pixels,
    Gpu: gpu_vpls_match_cpu_vpls,
    Gpu: every_stage_is_timed,
    Gpu: bad_frames_are_errors,
    Gpu: moved_light_renders_as_a_new_frame,
    Gpu: moved_camera_renders_as_a_new_frame,
    Gpu: temporal_frame_is_the_mean_of_its_frames,
    Gpu: reference_matches_the_host_composition,
);
