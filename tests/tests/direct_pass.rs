//! The engine-facing many-lights direct pass
//! ([`slc_wgpu::passes::DirectPass`]) against the CPU's twin
//! (`slc_cpu::direct::DirectLights`, the same random numbers with uniform
//! picks), its input checks, live lights, per-record slots and the
//! G-buffer read from depth.
//!
//! The pass gets its G-buffer as textures (the CPU's ray-cast G-buffer of
//! the Cornell box, uploaded as an engine would) and renormalises the
//! normals it reads, so a dot product may differ in its last bit: a light
//! within an ulp of its range is in range on one side only (bounded at
//! 0.5% of the pixels); elsewhere the irradiance agrees to 1e-5 relative.

use glam::{Mat4, Vec3};
use slc_core::light::{Light, PointLight, SpotLight, TriangleLight};
use slc_core::range::RangeParams;
use slc_cpu::direct::DirectLights;
use slc_scene::lights::LightSet;
use slc_scene::scene::Scene;
use slc_tests::engine::{self, texture, upload};
use slc_tests::gpu;
use slc_wgpu::passes::{
    Culling, DirectInputs, DirectPass, DirectPassDesc, DirectSelection, DirectSettings, GBuffer,
    Surface, SurfaceDesc,
};
use slc_wgpu::{GpuContext, GpuError};

const W: u32 = 64;
const H: u32 = 48;

/// 300 lights of three kinds spread through the box (a fixed LCG, so the
/// test is the same every run).
fn lights() -> LightSet {
    let mut state = 12345u32;
    let mut rnd = || {
        state = state.wrapping_mul(1664525).wrapping_add(1013904223);
        (state >> 8) as f32 / (1u32 << 24) as f32
    };
    let mut v = Vec::new();
    for i in 0..300 {
        let p = Vec3::new(0.05 + 0.45 * rnd(), 0.02 + 0.5 * rnd(), 0.05 + 0.45 * rnd());
        let i_rgb = Vec3::new(rnd(), rnd(), rnd()) * 0.02;
        v.push(match i % 3 {
            0 => Light::Point(PointLight::new(p, i_rgb).unwrap()),
            1 => Light::Spot(
                SpotLight::new(
                    p,
                    Vec3::new(rnd() - 0.5, -1.0, rnd() - 0.5).normalize(),
                    i_rgb,
                    0.3,
                    0.9,
                )
                .unwrap(),
            ),
            _ => Light::Triangle(
                TriangleLight::new(
                    p,
                    p + Vec3::new(0.02, 0.0, 0.0),
                    p + Vec3::new(0.0, 0.0, 0.02),
                    i_rgb * 50.0,
                )
                .unwrap(),
            ),
        });
    }
    LightSet::new(v).unwrap()
}

/// The Cornell box's ray-cast G-buffer as position and normal textures.
struct Gb {
    position: wgpu::TextureView,
    normal: wgpu::TextureView,
    points: Vec<Vec3>,
    normals: Vec<Vec3>,
    valid: Vec<bool>,
}

fn gbuffer(gpu: &GpuContext) -> Gb {
    let up = engine::upload_gbuffer(gpu, &Scene::cornell_box(), (W, H));
    let gb = &up.cpu;
    Gb {
        position: up.position,
        normal: up.normal,
        points: (0..gb.position.len())
            .map(|i| if gb.valid(i) { gb.position[i] } else { Vec3::NAN })
            .collect(),
        normals: gb.normal.clone(),
        valid: (0..gb.position.len()).map(|i| gb.valid(i)).collect(),
    }
}

fn position_desc(selection: DirectSelection) -> DirectPassDesc {
    DirectPassDesc {
        surface: SurfaceDesc::Position,
        output_format: wgpu::TextureFormat::Rgba32Float,
        selection,
        ..DirectPassDesc::new(W, H)
    }
}

/// Uniform picks, number for number as the CPU's reservoir; every light in
/// range without culling.
fn pass_matches_the_cpu_twin() {
    let Some(gpu) = gpu() else { return };
    let g = gbuffer(gpu);
    let set = lights();
    let out = engine::output(gpu, (W, H));
    let out_view = out.create_view(&Default::default());
    let mut pass =
        DirectPass::new(gpu, &set, &position_desc(DirectSelection::Uniform { k: 8 })).unwrap();
    let mut cpu = DirectLights::new(&set);
    let inputs = DirectInputs::new(
        GBuffer { surface: Surface::Position(&g.position), normal: &g.normal, eye: Vec3::ZERO },
        &out_view,
    );
    for (eps, frame) in [(0.002, 0), (0.02, 5)] {
        let params = RangeParams::new(eps, 1.0).unwrap();
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        pass.record(
            &mut enc,
            &inputs,
            &DirectSettings { culling: Culling::Stochastic(params), seed: 9, frame },
        )
        .unwrap();
        let got = engine::submit_and_read(gpu, enc, &out);
        let want = cpu.shade(&g.points, &g.normals, &params, 9, frame).unwrap();
        let (mut shaded, mut differs, mut worst) = (0, 0, 0.0f64);
        for i in 0..got.len() {
            let p = got[i];
            if !g.valid[i] {
                assert_eq!(p, [0.0; 4], "pixel {i} without a surface must be zero");
                continue;
            }
            shaded += 1;
            if p[3] as u32 != want[i].in_range {
                differs += 1;
                continue;
            }
            let (a, b) = (Vec3::new(p[0], p[1], p[2]).as_dvec3(), want[i].irradiance.as_dvec3());
            worst = worst.max(
                ((a - b).abs().max_element() - 1e-12).max(0.0) / b.abs().max_element().max(1e-30),
            );
        }
        eprintln!(
            "eps {eps}: {differs} of {shaded} pixels with another in-range count, worst {worst:.2e} elsewhere"
        );
        assert!(shaded > 1000);
        assert!(
            differs * 200 <= shaded,
            "{differs} of {shaded} pixels differ in their in-range counts"
        );
        assert!(worst <= 1e-5, "irradiance differs by {worst:.3e}");
    }
    let mut all = DirectPass::new(gpu, &set, &position_desc(DirectSelection::All)).unwrap();
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    all.record(&mut enc, &inputs, &DirectSettings { culling: Culling::None, seed: 1, frame: 0 })
        .unwrap();
    let got = engine::submit_and_read(gpu, enc, &out);
    for i in (0..got.len()).filter(|&i| g.valid[i]) {
        assert_eq!(got[i][3] as usize, set.len(), "unculled: every light is in range at pixel {i}");
    }
    gpu.take_errors().unwrap();
}

/// Two records of one pass in one submission (different frames, different
/// outputs) equal the same records submitted one by one: each record has
/// its own uniform slot.
fn records_share_a_submission() {
    let Some(gpu) = gpu() else { return };
    let g = gbuffer(gpu);
    let set = lights();
    let mut pass =
        DirectPass::new(gpu, &set, &position_desc(DirectSelection::Weighted { k: 4 })).unwrap();
    let outs = [engine::output(gpu, (W, H)), engine::output(gpu, (W, H))];
    let views: Vec<wgpu::TextureView> =
        outs.iter().map(|t| t.create_view(&Default::default())).collect();
    let gb =
        GBuffer { surface: Surface::Position(&g.position), normal: &g.normal, eye: Vec3::ZERO };
    let settings = |frame, eps| DirectSettings {
        culling: Culling::Stochastic(RangeParams::new(eps, 1.0).unwrap()),
        seed: 3,
        frame,
    };
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    pass.record(&mut enc, &DirectInputs::new(gb, &views[0]), &settings(0, 0.01)).unwrap();
    pass.record(&mut enc, &DirectInputs::new(gb, &views[1]), &settings(1, 0.002)).unwrap();
    gpu.queue.submit([enc.finish()]);
    let together = [
        engine::submit_and_read(
            gpu,
            gpu.device.create_command_encoder(&Default::default()),
            &outs[0],
        ),
        engine::submit_and_read(
            gpu,
            gpu.device.create_command_encoder(&Default::default()),
            &outs[1],
        ),
    ];
    for (k, (frame, eps)) in [(0, 0.01), (1, 0.002)].into_iter().enumerate() {
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        pass.record(&mut enc, &DirectInputs::new(gb, &views[k]), &settings(frame, eps)).unwrap();
        assert_eq!(engine::submit_and_read(gpu, enc, &outs[k]), together[k], "record {k}");
    }
    assert_ne!(together[0], together[1]);
}

/// Moved lights ([`DirectPass::update_lights`]) shade as a pass built with
/// them (the refit moves the leaves; the tree's topology differs, so the
/// traversal order, and with it the reservoir's picks and the points
/// sampled on triangles, may differ: compare with every point and spot
/// light in range, whose sum depends on the order only by rounding); a
/// new count ([`DirectPass::set_lights`]) likewise; a light of a type the
/// pass did not compile is refused.
fn moved_lights_shade_as_a_new_pass() {
    let Some(gpu) = gpu() else { return };
    let g = gbuffer(gpu);
    let set = LightSet::new(
        lights().lights().iter().filter(|l| !matches!(l, Light::Triangle(_))).cloned().collect(),
    )
    .unwrap();
    let desc = position_desc(DirectSelection::All);
    let mut pass = DirectPass::new(gpu, &set, &desc).unwrap();
    let out = engine::output(gpu, (W, H));
    let out_view = out.create_view(&Default::default());
    let inputs = DirectInputs::new(
        GBuffer { surface: Surface::Position(&g.position), normal: &g.normal, eye: Vec3::ZERO },
        &out_view,
    );
    let settings = DirectSettings {
        culling: Culling::Stochastic(RangeParams::new(0.004, 1.0).unwrap()),
        seed: 2,
        frame: 1,
    };
    let moved: Vec<Light> = set
        .lights()
        .iter()
        .map(|l| match l {
            Light::Point(p) => Light::Point(
                PointLight::new(p.position() + Vec3::new(0.05, -0.02, 0.03), l.peak() * 1.5)
                    .unwrap(),
            ),
            other => other.clone(),
        })
        .collect();
    let run = |pass: &mut DirectPass| {
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        pass.record(&mut enc, &inputs, &settings).unwrap();
        engine::submit_and_read(gpu, enc, &out)
    };
    let before = run(&mut pass);
    pass.update_lights(&moved).unwrap();
    let after = run(&mut pass);
    let fresh =
        run(&mut DirectPass::new(gpu, &LightSet::new(moved.clone()).unwrap(), &desc).unwrap());
    let close = |a: &[[f32; 4]], b: &[[f32; 4]]| {
        let bad: Vec<_> = a
            .iter()
            .zip(b)
            .filter(|(p, q)| {
                !(p[3] == q[3]
                    && (0..3).all(|c| (p[c] - q[c]).abs() <= 1e-5 * q[c].abs().max(1e-6)))
            })
            .collect();
        if let Some(first) = bad.first() {
            eprintln!("{} pixels differ, e.g. {:?}", bad.len(), first);
        }
        bad.is_empty()
    };
    assert!(close(&after, &fresh), "moved lights shade as a pass built with them");
    assert!(!close(&before, &after), "moving the lights changed nothing");
    let fewer = LightSet::new(moved[..100].to_vec()).unwrap();
    pass.set_lights(&fewer).unwrap();
    assert_eq!(pass.light_count(), 100);
    assert!(close(&run(&mut pass), &run(&mut DirectPass::new(gpu, &fewer, &desc).unwrap())));
    let vpl = Light::Vpl(slc_core::light::Vpl::new(Vec3::ZERO, Vec3::Y, Vec3::ONE).unwrap());
    let mut bad = moved[..100].to_vec();
    bad[0] = vpl;
    assert!(matches!(pass.update_lights(&bad), Err(GpuError::Setting(_))));
    assert!(
        matches!(pass.update_lights(&moved), Err(GpuError::Setting(_))),
        "a new count needs set_lights"
    );
    gpu.take_errors().unwrap();
}

/// An `R32Float` depth buffer made on the host from the positions (each
/// pixel's depth under a projection) reads back as those positions: the
/// depth pass equals the position pass within the unprojection's
/// rounding (every light in range, so no pick depends on last bits).
fn depth_input_matches_positions() {
    let Some(gpu) = gpu() else { return };
    let scene = Scene::cornell_box();
    let cam = &scene.camera;
    let (_, up, forward) = cam.basis();
    use glam::camera::rh::{proj, view::look_to_mat4};
    let vp = proj::directx::perspective(cam.vfov_deg.to_radians(), W as f32 / H as f32, 0.1, 10.0)
        * look_to_mat4(cam.position, forward, up);
    let inv = vp.inverse();
    let g = gbuffer(gpu);
    // Each valid pixel's position re-made from its depth; the depth of the
    // CPU's point along the pixel's own ray.
    let mut depth = vec![[1.0f32, 0.0, 0.0, 0.0]; (W * H) as usize];
    let mut points = vec![[0.0f32; 4]; (W * H) as usize];
    for i in 0..depth.len() {
        if !g.valid[i] {
            continue;
        }
        let c = vp * g.points[i].extend(1.0);
        let d = c.z / c.w;
        depth[i][0] = d;
        let p = slc_shared_shaders::engine::unproject_pixel(
            inv.x_axis,
            inv.y_axis,
            inv.z_axis,
            inv.w_axis,
            (i as u32 % W) as f32,
            (i as u32 / W) as f32,
            W as f32,
            H as f32,
            d,
        );
        points[i] = p.to_array();
    }
    let r32 = texture(
        gpu,
        "depth",
        (W, H),
        wgpu::TextureFormat::R32Float,
        wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
    );
    let d1: Vec<f32> = depth.iter().map(|d| d[0]).collect();
    gpu.queue.write_texture(
        r32.as_image_copy(),
        bytemuck::cast_slice(&d1),
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(W * 4), rows_per_image: None },
        r32.size(),
    );
    let r32_view = r32.create_view(&Default::default());
    let positions = upload(gpu, "unprojected", (W, H), &points);
    let set = lights();
    let out = engine::output(gpu, (W, H));
    let out_view = out.create_view(&Default::default());
    let settings = DirectSettings {
        culling: Culling::Stochastic(RangeParams::new(0.004, 1.0).unwrap()),
        seed: 4,
        frame: 2,
    };
    let mut by_depth = DirectPass::new(
        gpu,
        &set,
        &DirectPassDesc {
            surface: SurfaceDesc::Depth { format: wgpu::TextureFormat::R32Float },
            ..position_desc(DirectSelection::All)
        },
    )
    .unwrap();
    let mut by_position = DirectPass::new(gpu, &set, &position_desc(DirectSelection::All)).unwrap();
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    let gb = GBuffer {
        surface: Surface::Depth { depth: &r32_view, inv_view_proj: inv },
        normal: &g.normal,
        eye: cam.position,
    };
    by_depth.record(&mut enc, &DirectInputs::new(gb, &out_view), &settings).unwrap();
    let a = engine::submit_and_read(gpu, enc, &out);
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    let gb = GBuffer { surface: Surface::Position(&positions), ..gb };
    by_position.record(&mut enc, &DirectInputs::new(gb, &out_view), &settings).unwrap();
    let b = engine::submit_and_read(gpu, enc, &out);
    let (mut valid, mut far) = (0, 0);
    for i in 0..a.len() {
        assert_eq!(
            a[i][3] == 0.0 && a[i][0] == 0.0,
            b[i][3] == 0.0 && b[i][0] == 0.0,
            "pixel {i}: surface masks differ"
        );
        if g.valid[i] {
            valid += 1;
            let rel = (0..3)
                .map(|c| (a[i][c] - b[i][c]).abs() / b[i][c].abs().max(1e-6))
                .fold(0.0f32, f32::max);
            far += (rel > 1e-3 || a[i][3] != b[i][3]) as usize;
        }
    }
    eprintln!(
        "depth vs positions: {far} of {valid} pixels differ by more than 1e-3 or in their count"
    );
    assert!(far * 100 <= valid, "{far} of {valid}");
    let _ = Mat4::IDENTITY;
}

fn wrong_inputs_are_typed_errors() {
    let Some(gpu) = gpu() else { return };
    let set = lights();
    let desc = DirectPassDesc { surface: SurfaceDesc::Position, ..DirectPassDesc::new(W, H) };
    let mut pass = DirectPass::new(gpu, &set, &desc).unwrap();
    let tex = wgpu::TextureUsages::TEXTURE_BINDING;
    let good = texture(gpu, "gb", (W, H), wgpu::TextureFormat::Rgba32Float, tex)
        .create_view(&Default::default());
    let small = texture(gpu, "small", (W / 2, H), wgpu::TextureFormat::Rgba32Float, tex)
        .create_view(&Default::default());
    let unorm = texture(gpu, "unorm", (W, H), wgpu::TextureFormat::Rgba8Unorm, tex)
        .create_view(&Default::default());
    let out16 = texture(
        gpu,
        "out",
        (W, H),
        wgpu::TextureFormat::Rgba16Float,
        wgpu::TextureUsages::STORAGE_BINDING,
    )
    .create_view(&Default::default());
    let not_storage = texture(gpu, "out", (W, H), wgpu::TextureFormat::Rgba16Float, tex)
        .create_view(&Default::default());
    let settings = DirectSettings { culling: Culling::None, seed: 1, frame: 0 };
    let mut bad = |surface, normal, output, what: &str| {
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        let inputs = DirectInputs::new(GBuffer { surface, normal, eye: Vec3::ZERO }, output);
        let e = pass.record(&mut enc, &inputs, &settings).unwrap_err();
        assert!(matches!(e, GpuError::Binding { .. }), "{what}: {e}");
        eprintln!("{what}: {e}");
    };
    bad(Surface::Position(&small), &good, &out16, "small position");
    bad(Surface::Position(&good), &unorm, &out16, "unorm normal");
    bad(Surface::Position(&good), &good, &not_storage, "output without STORAGE_BINDING");
    bad(Surface::Position(&good), &good, &good, "output of another format");
    bad(
        Surface::Depth { depth: &good, inv_view_proj: Mat4::IDENTITY },
        &good,
        &out16,
        "depth for a position pass",
    );
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    let ok = DirectInputs::new(
        GBuffer { surface: Surface::Position(&good), normal: &good, eye: Vec3::ZERO },
        &out16,
    );
    pass.record(&mut enc, &ok, &settings).unwrap();
    let reference = DirectSettings { culling: Culling::Reference, ..settings };
    assert!(matches!(pass.record(&mut enc, &ok, &reference), Err(GpuError::Setting(_))));
    assert!(DirectPass::new(gpu, &set, &DirectPassDesc { width: 0, ..desc }).is_err());
    assert!(
        DirectPass::new(
            gpu,
            &set,
            &DirectPassDesc { selection: DirectSelection::Weighted { k: 0 }, ..desc }
        )
        .is_err()
    );
    let e = DirectPass::new(
        gpu,
        &set,
        &DirectPassDesc { output_format: wgpu::TextureFormat::Rgba8Unorm, ..desc },
    )
    .err()
    .unwrap();
    assert!(matches!(e, GpuError::Binding { .. }), "{e}");
    let depth16 = SurfaceDesc::Depth { format: wgpu::TextureFormat::Depth16Unorm };
    assert!(matches!(
        DirectPass::new(gpu, &set, &DirectPassDesc { surface: depth16, ..desc }),
        Err(GpuError::Binding { .. })
    ));
    let points_only = slc_shared_shaders::LightTypes { point: true, ..Default::default() };
    assert!(matches!(
        DirectPass::new(gpu, &set, &DirectPassDesc { light_types: points_only, ..desc }),
        Err(GpuError::Setting(_))
    ));
    gpu.take_errors().unwrap();
}

/// The material outputs: with every point and spot light in range and no
/// culling the sum is exact, so each pixel's outgoing radiance
/// (`Radiance`) and specular radiance (`Split`) equal slc-core's glTF BRDF
/// (`brdf_eval`, `specular_brdf`) summed over every light on the CPU, for
/// base colours, metallic and roughness varying by pixel; and Bevy's
/// radiance (`BevyRadiance`, the material's alpha its reflectance) equals
/// slc-core's `bevy_brdf` summed likewise.
fn material_outputs_match_the_brdf() {
    use slc_core::brdf::{bevy_brdf, brdf_eval, ggx_alpha, specular_brdf};
    use slc_core::light::{connection_cosine, connection_factor};
    use slc_wgpu::passes::{Dielectric, DirectOutputs, MaterialInputs};
    let Some(gpu) = gpu() else { return };
    let g = gbuffer(gpu);
    let set = LightSet::new(
        lights().lights().iter().filter(|l| !matches!(l, Light::Triangle(_))).cloned().collect(),
    )
    .unwrap();
    let n = (W * H) as usize;
    let base: Vec<[f32; 4]> = (0..n)
        .map(|i| [0.2 + 0.6 * (i % 7) as f32 / 6.0, 0.5, 0.9 - 0.7 * (i % 5) as f32 / 4.0, 1.0])
        .collect();
    let mr: Vec<[f32; 4]> = (0..n)
        .map(|i| {
            [0.0, 0.05 + 0.9 * (i % 4) as f32 / 3.0, (i % 3) as f32 / 2.0, 0.25 * (i % 5) as f32]
        })
        .collect();
    let (bc, mrv) =
        (upload(gpu, "base colour", (W, H), &base), upload(gpu, "metal rough", (W, H), &mr));
    let eye = Scene::cornell_box().camera.position;
    let dielectric = Dielectric::default();
    let outs = [engine::output(gpu, (W, H)), engine::output(gpu, (W, H))];
    let views: Vec<wgpu::TextureView> =
        outs.iter().map(|t| t.create_view(&Default::default())).collect();
    let settings = DirectSettings { culling: Culling::None, seed: 1, frame: 0 };
    let gb = GBuffer { surface: Surface::Position(&g.position), normal: &g.normal, eye };
    let material = Some(MaterialInputs { base_color: &bc, metallic_roughness: &mrv });
    let run = |outputs, specular: Option<&wgpu::TextureView>| {
        let mut pass = DirectPass::new(
            gpu,
            &set,
            &DirectPassDesc { outputs, ..position_desc(DirectSelection::All) },
        )
        .unwrap();
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        pass.record(
            &mut enc,
            &DirectInputs { material, specular, ..DirectInputs::new(gb, &views[0]) },
            &settings,
        )
        .unwrap();
        gpu.queue.submit([enc.finish()]);
        let a = engine::submit_and_read(
            gpu,
            gpu.device.create_command_encoder(&Default::default()),
            &outs[0],
        );
        let b = engine::submit_and_read(
            gpu,
            gpu.device.create_command_encoder(&Default::default()),
            &outs[1],
        );
        (a, b)
    };
    let (radiance, _) = run(DirectOutputs::Radiance(dielectric), None);
    let (bevy, _) = run(DirectOutputs::BevyRadiance, None);
    let (irradiance, specular) = run(DirectOutputs::Split(dielectric), Some(&views[1]));
    let (mut worst, mut shaded) = (0.0f64, 0);
    for i in (0..n).filter(|&i| g.valid[i]) {
        let (x, nn) = (g.points[i], g.normals[i]);
        let (b, m, alpha) =
            (Vec3::new(base[i][0], base[i][1], base[i][2]), mr[i][2], ggx_alpha(mr[i][1]));
        let v = (eye - x).normalize();
        let (mut l_out, mut e, mut spec, mut l_bevy) =
            (glam::DVec3::ZERO, glam::DVec3::ZERO, glam::DVec3::ZERO, glam::DVec3::ZERO);
        for light in set.lights() {
            let y = light.bound().center;
            let cos = connection_cosine(x, y, nn, nn, f32::INFINITY);
            if cos <= 0.0 {
                continue;
            }
            let w = x - y;
            let d2 = w.dot(w);
            let c = light.intensity(w / d2.sqrt()) * connection_factor(cos, d2, f32::INFINITY, 1.0);
            let l = (y - x).normalize();
            e += c.as_dvec3();
            l_out +=
                (brdf_eval(b, m, dielectric.f0, dielectric.f90, alpha, nn, v, l) * c).as_dvec3();
            spec += (specular_brdf(b, m, dielectric.f0, dielectric.f90, alpha, nn, v, l) * c)
                .as_dvec3();
            l_bevy += (bevy_brdf(b, m, mr[i][1], mr[i][3], nn, v, l) * c).as_dvec3();
        }
        let rel = |got: &[f32; 4], want: glam::DVec3| {
            let g = glam::DVec3::new(got[0] as f64, got[1] as f64, got[2] as f64);
            ((g - want).abs().max_element() - 1e-9).max(0.0) / want.abs().max_element().max(1e-12)
        };
        worst = worst
            .max(rel(&radiance[i], l_out))
            .max(rel(&irradiance[i], e))
            .max(rel(&specular[i], spec))
            .max(rel(&bevy[i], l_bevy));
        shaded += 1;
    }
    eprintln!("material outputs: {shaded} pixels, worst relative difference {worst:.2e}");
    assert!(shaded > 1000);
    assert!(worst <= 1e-4, "{worst:.3e}");
    // Missing material or specular target: typed errors.
    let mut pass = DirectPass::new(
        gpu,
        &set,
        &DirectPassDesc {
            outputs: DirectOutputs::Split(dielectric),
            ..position_desc(DirectSelection::All)
        },
    )
    .unwrap();
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    assert!(matches!(
        pass.record(&mut enc, &DirectInputs::new(gb, &views[0]), &settings),
        Err(GpuError::Binding { .. })
    ));
    assert!(matches!(
        pass.record(
            &mut enc,
            &DirectInputs { material, ..DirectInputs::new(gb, &views[0]) },
            &settings
        ),
        Err(GpuError::Binding { .. })
    ));
    gpu.take_errors().unwrap();
}

slc_tests::harness!(
    Gpu: material_outputs_match_the_brdf,
    Gpu: pass_matches_the_cpu_twin,
    Gpu: records_share_a_submission,
    Gpu: moved_lights_shade_as_a_new_pass,
    Gpu: depth_input_matches_positions,
    Gpu: wrong_inputs_are_typed_errors,
);
