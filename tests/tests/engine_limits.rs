//! What an engine's device can rely on:
//! - on a device with `Limits::downlevel_defaults()` (4 storage buffers per
//!   stage), every constructor returns a typed [`GpuError::Limit`] and the
//!   device raises no validation error first (a handler counts them);
//! - a soak of 10,000 records (5,000 of each pass, into alternating
//!   outputs, submitted 10 at a time, the direct pass's lights moved with
//!   `update_lights` before each of its records) leaves wgpu's internal
//!   resource counters (`Device::get_internal_counters`, wgpu's `counters`
//!   feature) where the first records left them: recording and moving
//!   lights create no buffer, bind group, view or pipeline;
//! - the same of `GpuVpl`'s shades (every method, fixed ξ, the reference)
//!   once each has run, Lambertian and glossy;
//! - on a device with less workgroup memory than the direct pass's tile
//!   list needs, the tile walk is a typed [`GpuError::Limit`] with no
//!   validation error, and the walk per pixel (no workgroup memory) builds
//!   and shades the same image as the tile walk on a full device;
//! - on a device with WebGPU's default limits (8 storage buffers per
//!   stage), the indirect pass builds and records with its material input
//!   (glossy: `vpl_near` then binds 8), as does the glossy `GpuVpl`, with
//!   no validation error (`GpuVplFrame`, whose RSM needs 40 color bytes per
//!   sample, is a typed error there); so does the temporal pass (4 storage
//!   textures), and the shadowed direct pass, also with resampled picks
//!   reused across frames for point lights (8 storage buffers; every light
//!   type's IES table makes 9, a typed error).
//!
//! The counters hold what is alive now: they catch what accumulates, not
//! an object made and dropped within one record (that none is made is by
//! construction: bind groups cached by the views, buffers kept).

use glam::Vec3;
use slc_core::light::{Light, PointLight};
use slc_scene::scene::Scene;
use slc_scene::vpl::VplSettings;
use slc_tests::engine::{self, upload};
use slc_tests::gpu;
use slc_wgpu::passes::{
    Culling, DirectInputs, DirectPass, DirectPassDesc, DirectReuse, DirectSelection,
    DirectSettings, DirectWalk, GBuffer, IndirectInputs, IndirectPass, IndirectPassDesc,
    IndirectSettings, Shadows, Surface, SurfaceDesc, TemporalInputs, TemporalPass,
    TemporalPassDesc, VplInput, VplSourceDesc,
};
use slc_wgpu::{GpuContext, GpuError, LightSet, LightTypes, Occluders, RangeParams};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

fn point_lights(n: usize) -> LightSet {
    LightSet::new(moved_lights(n, 0)).unwrap()
}

/// `n` point lights on a grid, shifted and recoloured for record `r`.
fn moved_lights(n: usize, r: u32) -> Vec<Light> {
    let t = r as f32 * 0.01;
    (0..n)
        .map(|i| {
            let p = Vec3::new(
                (i % 8) as f32 * 0.1 + 0.05 * t.sin(),
                0.4,
                (i / 8) as f32 * 0.1 + 0.05 * t.cos(),
            );
            Light::Point(PointLight::new(p, Vec3::splat(0.01 * (1.5 + t.sin()))).unwrap())
        })
        .collect()
}

/// A constructor under test.
type Constructor<'a> = Box<dyn Fn() -> Result<(), GpuError> + 'a>;

/// A device of the test adapter (the harness runs this file's tests only
/// where there is one) with `limits`, and a count of the validation errors
/// it raises.
fn device_with(limits: wgpu::Limits) -> (wgpu::Device, wgpu::Queue, Arc<AtomicUsize>) {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter =
        pollster::block_on(wgpu::util::initialize_adapter_from_env_or_default(&instance, None))
            .expect("an adapter");
    let (device, queue) =
        pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            required_limits: limits,
            ..Default::default()
        }))
        .expect("a device with the asked limits");
    let errors = Arc::new(AtomicUsize::new(0));
    let seen = errors.clone();
    device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
        eprintln!("validation error: {e:?}");
        seen.fetch_add(1, Ordering::SeqCst);
    }));
    (device, queue, errors)
}

fn downlevel_constructors_are_typed_errors() {
    let (device, queue, errors) = device_with(wgpu::Limits::downlevel_defaults());
    let gpu = GpuContext::from_device(device.clone(), queue);
    let set = point_lights(64);
    let scene = Scene::cornell_box();
    let cpu = slc_cpu::vpl::VplContext::new(&scene, 16, 16, 8, None).unwrap();
    let pts = slc_scene::pt::PtScene::new(&scene, &[]).unwrap();
    let constructors: Vec<(&str, Constructor)> = vec![
        (
            "DirectPass",
            Box::new(|| DirectPass::new(&gpu, &set, &DirectPassDesc::new(64, 64)).map(|_| ())),
        ),
        (
            "IndirectPass (RSM)",
            Box::new(|| {
                IndirectPass::new(
                    &gpu,
                    &IndirectPassDesc::new(64, 64, VplSourceDesc::Rsm { size: 16 }),
                )
                .map(|_| ())
            }),
        ),
        (
            "IndirectPass (buffer)",
            Box::new(|| {
                IndirectPass::new(
                    &gpu,
                    &IndirectPassDesc::new(64, 64, VplSourceDesc::Buffer { count: 256 }),
                )
                .map(|_| ())
            }),
        ),
        (
            "GpuVplFrame",
            Box::new(|| {
                let desc = slc_wgpu::frame::FrameDesc {
                    width: 32,
                    height: 32,
                    rsm_size: 16,
                    shadow_size: 64,
                    min_distance: None,
                };
                slc_wgpu::frame::GpuVplFrame::new(&gpu, &scene, &desc).map(|_| ())
            }),
        ),
        ("GpuVpl", Box::new(|| slc_tests::vpl::GpuVpl::new(&gpu, cpu.inputs()).map(|_| ()))),
        (
            "IndirectPass (RSM, glossy)",
            Box::new(|| {
                let desc = IndirectPassDesc {
                    glossy: true,
                    ..IndirectPassDesc::new(64, 64, VplSourceDesc::Rsm { size: 16 })
                };
                IndirectPass::new(&gpu, &desc).map(|_| ())
            }),
        ),
        (
            "GpuDirect",
            Box::new(|| {
                let mut d = slc_tests::direct::GpuDirect::new(&gpu, &set)?;
                d.shade(&[Vec3::ZERO], &[Vec3::Y], &RangeParams::new(0.01, 1.0).unwrap(), 1, 0)
                    .map(|_| ())
            }),
        ),
        ("GpuPt", Box::new(|| slc_wgpu::pt::GpuPt::new(&gpu, &pts, 16, 16).map(|_| ()))),
    ];
    let mut failures = Vec::new();
    for (name, make) in constructors {
        let before = errors.load(Ordering::SeqCst);
        let r = make();
        device.poll(wgpu::PollType::wait_indefinitely()).unwrap();
        let raised = errors.load(Ordering::SeqCst) - before;
        match r {
            Err(GpuError::Limit { name: limit, need, have }) if raised == 0 => {
                eprintln!("{name}: typed error, needs {limit} >= {need}, has {have}")
            }
            Err(e) => failures.push(format!("{name}: {e} after {raised} validation errors")),
            Ok(()) => failures
                .push(format!("{name}: built on a downlevel device ({raised} validation errors)")),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn ten_thousand_records_allocate_nothing() {
    let Some(gpu) = gpu() else { return };
    let (w, h) = (16, 16);
    let ctx = slc_cpu::vpl::VplContext::new(&Scene::cornell_box(), w, h, 8, None).unwrap();
    let inputs = ctx.inputs();
    let gb = &inputs.gbuffer;
    let v4 = |v: Vec3, w: f32| [v.x, v.y, v.z, w];
    let position = upload(
        gpu,
        "p",
        (w, h),
        &(0..gb.position.len())
            .map(|i| v4(gb.position[i], gb.valid(i) as u32 as f32))
            .collect::<Vec<_>>(),
    );
    let normal =
        upload(gpu, "n", (w, h), &gb.normal.iter().map(|&n| v4(n, 0.0)).collect::<Vec<_>>());
    let vp = &inputs.vpls;
    let rsm = [
        upload(gpu, "rp", (8, 8), &vp.position.iter().map(|&p| v4(p, 1.0)).collect::<Vec<_>>()),
        upload(gpu, "rn", (8, 8), &vp.normal.iter().map(|&n| v4(n, 0.0)).collect::<Vec<_>>()),
        upload(gpu, "rf", (8, 8), &vp.flux.iter().map(|&f| v4(f, 0.0)).collect::<Vec<_>>()),
    ];
    let outs = [engine::output(gpu, (w, h)), engine::output(gpu, (w, h))];
    let views: Vec<wgpu::TextureView> =
        outs.iter().map(|t| t.create_view(&Default::default())).collect();
    let f32out = wgpu::TextureFormat::Rgba32Float;
    let mut direct = DirectPass::new(
        gpu,
        &point_lights(64),
        &DirectPassDesc {
            surface: SurfaceDesc::Position,
            output_format: f32out,
            ..DirectPassDesc::new(w, h)
        },
    )
    .unwrap();
    let mut indirect = IndirectPass::new(
        gpu,
        &IndirectPassDesc {
            surface: SurfaceDesc::Position,
            output_format: f32out,
            ..IndirectPassDesc::new(w, h, VplSourceDesc::Rsm { size: 8 })
        },
    )
    .unwrap();
    let gbuffer = GBuffer {
        surface: Surface::Position(&position),
        normal: &normal,
        eye: Scene::cornell_box().camera.position,
    };
    let culling = Culling::Stochastic(RangeParams::new(0.01, 1.0).unwrap());
    let mut run = |from: u32, to: u32| {
        for batch in (from..to).step_by(10) {
            let mut enc = gpu.device.create_command_encoder(&Default::default());
            for r in batch..batch + 10 {
                let output = &views[(r / 2 % 2) as usize];
                if r % 2 == 0 {
                    direct.update_lights(&moved_lights(64, r)).unwrap();
                    direct
                        .record(
                            &mut enc,
                            &DirectInputs::new(gbuffer, output),
                            &DirectSettings { culling, seed: 1, frame: r },
                        )
                        .unwrap();
                } else {
                    let vpls = VplInput::Rsm { position: &rsm[0], normal: &rsm[1], flux: &rsm[2] };
                    let st = IndirectSettings {
                        culling,
                        frame: r,
                        min_distance: 0.01,
                        ..IndirectSettings::default()
                    };
                    indirect
                        .record(
                            &mut enc,
                            &IndirectInputs { gbuffer, vpls, output, materials: None },
                            &st,
                        )
                        .unwrap();
                }
            }
            gpu.queue.submit([enc.finish()]);
            if batch % 500 == 0 {
                gpu.wait().unwrap();
            }
        }
        gpu.wait().unwrap();
    };
    let counters = || {
        let c = gpu.device.get_internal_counters().hal;
        [
            ("buffers", c.buffers.read()),
            ("textures", c.textures.read()),
            ("texture views", c.texture_views.read()),
            ("bind groups", c.bind_groups.read()),
            ("bind group layouts", c.bind_group_layouts.read()),
            ("compute pipelines", c.compute_pipelines.read()),
            ("pipeline layouts", c.pipeline_layouts.read()),
            ("shader modules", c.shader_modules.read()),
            ("buffer memory", c.buffer_memory.read()),
            ("texture memory", c.texture_memory.read()),
        ]
    };
    run(0, 100);
    let before = counters();
    assert!(
        before[0].1 > 0 && before[3].1 > 0,
        "wgpu's counters read zero: build wgpu with its `counters` feature ({before:?})"
    );
    run(100, 10_000);
    let after = counters();
    eprintln!("counters after 100 records: {before:?}\ncounters after 10,000 records: {after:?}");
    assert_eq!(before, after, "records allocated GPU objects");
    gpu.take_errors().unwrap();
    // The counting variant: its first count builds it; 20 more, the lights
    // moved before each, keep nothing more (and count the same pixels).
    let mut count = |frame: u32| {
        direct.update_lights(&moved_lights(64, frame)).unwrap();
        let settings = DirectSettings { culling, seed: 1, frame };
        direct.count_work(&DirectInputs::new(gbuffer, &views[0]), &settings).unwrap()
    };
    let first = count(0);
    let before = counters();
    for frame in 1..=20 {
        assert_eq!(count(frame).pixels, first.pixels, "frame {frame}");
    }
    assert_eq!(before, counters(), "count_work allocated GPU objects");
    gpu.take_errors().unwrap();
    // The counters are the device's: the harness runs tests at once, so
    // GpuVpl's check runs here, after the soak, not as a test of its own.
    gpu_vpl_shades_allocate_nothing(gpu, &Scene::cornell_box());
    gpu_vpl_shades_allocate_nothing(gpu, &Scene::cornell_box_glossy());
}

/// `GpuVpl` records the indirect pass on inputs it uploaded once: after
/// a first shade of each kind (the reference builds its pass then), 50
/// more of every kind leave wgpu's counters where they were (views, bind
/// groups, pipelines, buffers and their memory: nothing accumulates).
fn gpu_vpl_shades_allocate_nothing(gpu: &GpuContext, scene: &Scene) {
    let ctx = slc_cpu::vpl::VplContext::new(scene, 16, 16, 8, None).unwrap();
    let mut gv = slc_tests::vpl::GpuVpl::new(gpu, ctx.inputs()).unwrap();
    let base =
        VplSettings { culling: Culling::stochastic(0.01, 1.0).unwrap(), ..VplSettings::default() };
    let kinds = [
        base,
        VplSettings { denoise: false, fixed_xi: Some(0.5), ..base },
        VplSettings { culling: Culling::clamped(0.1).unwrap(), ..base },
        VplSettings { culling: Culling::None, near_radius: Some(0.0), ..base },
        VplSettings { culling: Culling::Reference, ..base },
    ];
    let mut shade_all = |frame: u32| {
        for s in &kinds {
            let out = gv.shade(&VplSettings { frame, ..*s }).unwrap();
            assert!(
                out.irradiance.iter().any(|e| e.max_element() > 0.0),
                "{:?}: a black image",
                s.culling
            );
        }
        gpu.wait().unwrap();
    };
    shade_all(0);
    let counters = || {
        let c = gpu.device.get_internal_counters().hal;
        [
            c.buffers.read(),
            c.textures.read(),
            c.texture_views.read(),
            c.bind_groups.read(),
            c.compute_pipelines.read(),
            c.buffer_memory.read(),
        ]
    };
    let before = counters();
    for frame in 1..=50 {
        shade_all(frame);
    }
    let after = counters();
    eprintln!(
        "GpuVpl ({}): counters (buffers, textures, views, bind groups, pipelines, buffer memory) {before:?} after the first shades, {after:?} after 250 more",
        scene.name
    );
    assert_eq!(before, after, "shades allocated GPU objects");
    gpu.take_errors().unwrap();
}

/// WebGPU's default limits (8 storage buffers per stage, 4 storage
/// textures): the glossy indirect pass (its `vpl_near` binds 8 storage
/// buffers, its export 2 storage textures) under the glossy `GpuVpl`
/// builds, records and shades with no validation error; the frame asks
/// for more than the defaults' 32 color bytes per sample (its RSM's 40):
/// a typed error.
fn glossy_pass_fits_webgpu_default_limits() {
    let (device, queue, errors) = device_with(wgpu::Limits::default());
    assert_eq!(device.limits().max_storage_buffers_per_shader_stage, 8);
    let gpu = GpuContext::from_device(device.clone(), queue);
    let scene = Scene::cornell_box_glossy();
    let ctx = slc_cpu::vpl::VplContext::new(&scene, 16, 16, 8, None).unwrap();
    let mut gv = slc_tests::vpl::GpuVpl::new(&gpu, ctx.inputs()).unwrap();
    let culling = Culling::stochastic(0.01, 1.0).unwrap();
    let shaded = gv.shade(&VplSettings { culling, ..VplSettings::default() }).unwrap();
    assert!(shaded.specular.iter().any(|s| s.abs().max_element() > 0.0), "no specular correction");
    // The frame's RSM writes 40 bytes per sample (WebGPU's default: 32): a
    // typed error, before any pipeline (it was a validation error).
    let desc = slc_wgpu::frame::FrameDesc {
        width: 16,
        height: 16,
        rsm_size: 8,
        shadow_size: 64,
        min_distance: None,
    };
    match slc_wgpu::frame::GpuVplFrame::new(&gpu, &scene, &desc) {
        Err(GpuError::Limit { name, need: 40, have: 32 })
            if name.starts_with("max_color_attachment_bytes_per_sample") => {}
        Err(e) => panic!("GpuVplFrame: {e}"),
        Ok(_) => panic!("GpuVplFrame built with 32 bytes per sample"),
    }
    // The temporal pass binds 4 storage textures, the default limit: it
    // builds and records on the glossy G-buffer's irradiance.
    let gb = &ctx.inputs().gbuffer;
    let texels = |v: &dyn Fn(usize) -> [f32; 4]| (0..gb.position.len()).map(v).collect::<Vec<_>>();
    let position = upload(
        &gpu,
        "position",
        (16, 16),
        &texels(&|i| {
            [gb.position[i].x, gb.position[i].y, gb.position[i].z, gb.valid(i) as u32 as f32]
        }),
    );
    let normal =
        upload(&gpu, "normal", (16, 16), &texels(&|i| gb.normal[i].extend(0.0).to_array()));
    let signal =
        upload(&gpu, "signal", (16, 16), &texels(&|i| shaded.irradiance[i].extend(0.0).to_array()));
    let out = engine::output(&gpu, (16, 16));
    let out_view = out.create_view(&Default::default());
    let desc = TemporalPassDesc {
        output_format: wgpu::TextureFormat::Rgba32Float,
        ..TemporalPassDesc::new(16, 16)
    };
    let mut temporal = TemporalPass::new(&gpu, &desc).unwrap();
    let gbuffer = GBuffer { surface: Surface::Position(&position), normal: &normal, eye: gb.eye };
    let view = slc_wgpu::TemporalView::of_camera(&scene.camera, 16, 16);
    let mut enc = device.create_command_encoder(&Default::default());
    for _ in 0..2 {
        temporal
            .record(
                &mut enc,
                &TemporalInputs::new(gbuffer, &signal, &out_view),
                &view,
                &Default::default(),
            )
            .unwrap();
    }
    gpu.queue.submit([enc.finish()]);
    device.poll(wgpu::PollType::wait_indefinitely()).unwrap();
    gpu.take_errors().unwrap();
    assert_eq!(errors.load(Ordering::SeqCst), 0, "validation errors");
}

/// WebGPU's default limits: the shadowed direct pass with the default
/// descriptor (weighted picks, every light type: its `direct_light` binds
/// 8 storage buffers, the occluders' two included) builds, records and
/// shades the Cornell box with no validation error, and its shadows
/// darken the image.
fn shadowed_direct_pass_fits_webgpu_default_limits() {
    let (device, queue, errors) = device_with(wgpu::Limits::default());
    let gpu = GpuContext::from_device(device.clone(), queue);
    let scene = Scene::cornell_box();
    let g = engine::upload_gbuffer(&gpu, &scene, (16, 16));
    let desc = DirectPassDesc {
        surface: SurfaceDesc::Position,
        output_format: wgpu::TextureFormat::Rgba32Float,
        ..DirectPassDesc::new(16, 16)
    };
    let mut pass = DirectPass::new(&gpu, &point_lights(32), &desc).unwrap();
    let out = engine::output(&gpu, (16, 16));
    let out_view = out.create_view(&Default::default());
    let gbuffer =
        GBuffer { surface: Surface::Position(&g.position), normal: &g.normal, eye: g.cpu.eye };
    let mean = |pass: &mut DirectPass| {
        let mut enc = device.create_command_encoder(&Default::default());
        let settings = DirectSettings { culling: Culling::None, seed: 1, frame: 0 };
        // The camera's view-projection: the reuse reprojects with it.
        let inputs = DirectInputs {
            view_projection: Some(scene.camera.view_projection(16, 16, 0.01, 100.0)),
            ..DirectInputs::new(gbuffer, &out_view)
        };
        pass.record(&mut enc, &inputs, &settings).unwrap();
        let img = engine::submit_and_read(&gpu, enc, &out);
        img.iter().map(|p| (p[0] + p[1] + p[2]) as f64).sum::<f64>()
    };
    let open = mean(&mut pass);
    let occluders = Occluders::from_triangles(&scene.triangles).unwrap();
    pass.set_shadows(Some(Shadows::new(&occluders))).unwrap();
    let shadowed = mean(&mut pass);
    assert!(shadowed < 0.95 * open, "shadows: {shadowed} against {open} unshadowed");
    // Resampled picks reused across frames, with visibility reuse: the
    // previous lights and the reservoirs' two halves bind two more storage
    // buffers, 8 in all for point lights (irradiance, no IES table)...
    let reused = DirectPassDesc {
        selection: DirectSelection::Resampled { k: 4 },
        reuse: Some(DirectReuse::default()),
        light_types: LightTypes { point: true, ..LightTypes::default() },
        ..desc
    };
    let mut pass = DirectPass::new(&gpu, &point_lights(32), &reused).unwrap();
    pass.set_shadows(Some(Shadows::new(&occluders))).unwrap();
    let shadowed_reused = mean(&mut pass);
    assert!(
        shadowed_reused < 0.95 * open,
        "reused shadows: {shadowed_reused} against {open} unshadowed"
    );
    // ...and with the IES table of every light type one more: its shadows
    // are a typed error that changes nothing.
    let every_type =
        DirectPassDesc { light_types: DirectPassDesc::new(16, 16).light_types, ..reused };
    let mut pass = DirectPass::new(&gpu, &point_lights(32), &every_type).unwrap();
    match pass.set_shadows(Some(Shadows::new(&occluders))) {
        Err(GpuError::Limit { name, need: 9, have: 8 }) => {
            assert!(name.contains("max_storage_buffers_per_shader_stage"), "{name}")
        }
        Err(e) => panic!("another error: {e}"),
        Ok(_) => panic!("every light type's reused pass shadowed within 8 storage buffers"),
    }
    assert!(pass.shadow_rays().is_none(), "the refused shadows were kept");
    gpu.take_errors().unwrap();
    assert_eq!(errors.load(Ordering::SeqCst), 0, "validation errors");
}

fn tile_walk_needs_its_workgroup_memory() {
    let need = slc_shared_shaders::direct_workgroup_bytes(&slc_shared_shaders::Features {
        selection: slc_shared_shaders::Selection::Weighted,
        ..slc_shared_shaders::Features::default()
    }) as u32;
    assert!(need > 2048, "the default tile list needs only {need} bytes");
    let small = wgpu::Limits { max_compute_workgroup_storage_size: need - 1, ..Default::default() };
    let (device, queue, errors) = device_with(small);
    let gpu = GpuContext::from_device(device.clone(), queue);
    let scene = Scene::cornell_box();
    let desc = DirectPassDesc {
        surface: SurfaceDesc::Position,
        output_format: wgpu::TextureFormat::Rgba32Float,
        ..DirectPassDesc::new(16, 16)
    };
    let r = DirectPass::new(&gpu, &point_lights(32), &desc);
    match r {
        Err(GpuError::Limit { name, need: n, have }) => {
            assert!(name.contains("max_compute_workgroup_storage_size"), "{name}");
            assert_eq!((n, have), (need as u64, need as u64 - 1));
        }
        Err(e) => panic!("another error: {e}"),
        Ok(_) => panic!("the tile walk built with {} bytes of workgroup memory", need - 1),
    }
    // The walk per pixel needs none, and finds the same lights.
    let image = |gpu: &GpuContext, desc: &DirectPassDesc| {
        let g = engine::upload_gbuffer(gpu, &scene, (16, 16));
        let mut pass = DirectPass::new(gpu, &point_lights(32), desc).unwrap();
        let out = engine::output(gpu, (16, 16));
        let view = out.create_view(&Default::default());
        let gbuffer =
            GBuffer { surface: Surface::Position(&g.position), normal: &g.normal, eye: g.cpu.eye };
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        let culling = Culling::Stochastic(RangeParams::new(0.01, 1.0).unwrap());
        let settings = DirectSettings { culling, seed: 1, frame: 0 };
        pass.record(&mut enc, &DirectInputs::new(gbuffer, &view), &settings).unwrap();
        engine::submit_and_read(gpu, enc, &out)
    };
    let pixel = image(&gpu, &DirectPassDesc { walk: DirectWalk::Pixel, ..desc });
    let Some(full) = slc_tests::gpu() else { return };
    let tile = image(full, &desc);
    let lit = tile.iter().filter(|p| p[0] + p[1] + p[2] > 0.0).count();
    assert!(lit > 100, "only {lit} lit pixels");
    for (a, b) in pixel.iter().zip(&tile) {
        for c in 0..4 {
            assert!((a[c] - b[c]).abs() <= 1e-5 * a[c].abs().max(b[c].abs()) + 1e-9, "{a:?} {b:?}");
        }
    }
    gpu.take_errors().unwrap();
    assert_eq!(errors.load(Ordering::SeqCst), 0, "validation errors");
}

slc_tests::harness!(
    Gpu: tile_walk_needs_its_workgroup_memory,
    Gpu: glossy_pass_fits_webgpu_default_limits,
    Gpu: shadowed_direct_pass_fits_webgpu_default_limits,
    Gpu: downlevel_constructors_are_typed_errors,
    Gpu: ten_thousand_records_allocate_nothing,
);
