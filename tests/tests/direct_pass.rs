//! The engine-facing many-lights direct pass
//! ([`slc_wgpu::passes::DirectPass`]) against [`GpuDirect`], which shades
//! the same points from host buffers with the same kernel and random
//! numbers, and its input checks.
//!
//! The pass gets its G-buffer as textures (the CPU's ray-cast G-buffer of
//! the Cornell box, uploaded as an engine would) and renormalises the
//! normals it reads, so a dot product may differ in its last bit: a light
//! within an ulp of its range is in range on one side only (bounded at
//! 0.5% of the pixels); elsewhere the irradiance agrees to 1e-5 relative.

use glam::Vec3;
use slc_core::light::{Light, PointLight, SpotLight, TriangleLight};
use slc_core::range::RangeParams;
use slc_cpu::vpl::VplContext;
use slc_scene::lights::LightSet;
use slc_scene::scene::Scene;
use slc_tests::engine::{self, texture, upload};
use slc_tests::gpu;
use slc_wgpu::GpuError;
use slc_wgpu::direct::GpuDirect;
use slc_wgpu::passes::{DirectFrame, DirectInputs, DirectPass, DirectPassDesc};

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
            1 => Light::Spot(SpotLight::new(p, Vec3::new(rnd() - 0.5, -1.0, rnd() - 0.5).normalize(), i_rgb, 0.3, 0.9).unwrap()),
            _ => Light::Triangle(TriangleLight::new(p, p + Vec3::new(0.02, 0.0, 0.0), p + Vec3::new(0.0, 0.0, 0.02), i_rgb * 50.0).unwrap()),
        });
    }
    LightSet::new(v).unwrap()
}

fn pass_matches_gpu_direct() {
    let Some(gpu) = gpu() else { return };
    let ctx = VplContext::new(&Scene::cornell_box(), W, H, 8, None).unwrap();
    let gb = ctx.gbuffer();
    let set = lights();
    let pos: Vec<[f32; 4]> = (0..gb.position.len()).map(|i| gb.position[i].extend(if gb.valid(i) { 1.0 } else { 0.0 }).to_array()).collect();
    let nrm: Vec<[f32; 4]> = gb.normal.iter().map(|n| n.extend(0.0).to_array()).collect();
    let (position, normal) = (upload(gpu, "gb position", (W, H), &pos), upload(gpu, "gb normal", (W, H), &nrm));
    let out = engine::output(gpu, (W, H));
    let out_view = out.create_view(&Default::default());
    let pass = DirectPass::new(gpu, &set, &DirectPassDesc { width: W, height: H, output_format: wgpu::TextureFormat::Rgba32Float }).unwrap();
    let reference = GpuDirect::new(gpu, &set).unwrap();
    let points: Vec<Vec3> = (0..gb.position.len()).map(|i| if gb.valid(i) { gb.position[i] } else { Vec3::NAN }).collect();
    let inputs = DirectInputs { position: &position, normal: &normal, output: &out_view };
    for (culling, frame) in [(Some(RangeParams::new(0.002, 1.0).unwrap()), 0), (Some(RangeParams::new(0.02, 1.0).unwrap()), 5), (None, 1)] {
        let f = DirectFrame { culling, seed: 9, frame };
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        pass.record(gpu, &mut enc, &inputs, &f).unwrap();
        let got = engine::submit_and_read(gpu, enc, &out);
        let want = match &culling {
            Some(params) => reference.shade(&points, &gb.normal, params, 9, frame).unwrap(),
            None => Vec::new(),
        };
        let (mut shaded, mut differs, mut worst) = (0, 0, 0.0f64);
        for i in 0..got.len() {
            let g = got[i];
            if !gb.valid(i) {
                assert_eq!(g, [0.0; 4], "pixel {i} without a surface must be zero");
                continue;
            }
            shaded += 1;
            if culling.is_none() {
                assert_eq!(g[3] as usize, set.len(), "unculled: every light is in range at pixel {i}");
                continue;
            }
            let w = &want[i];
            if g[3] as u32 != w.in_range {
                differs += 1;
                continue;
            }
            let (a, b) = (Vec3::new(g[0], g[1], g[2]).as_dvec3(), w.irradiance.as_dvec3());
            worst = worst.max(((a - b).abs().max_element() - 1e-12).max(0.0) / b.abs().max_element().max(1e-30));
        }
        eprintln!(
            "culling {:?}: {differs} of {shaded} pixels with another in-range count, worst {worst:.2e} elsewhere",
            culling.map(|c| c.error_bound())
        );
        assert!(shaded > 1000);
        assert!(differs * 200 <= shaded, "{differs} of {shaded} pixels differ in their in-range counts");
        assert!(worst <= 1e-5, "irradiance differs by {worst:.3e}");
    }
}

fn wrong_inputs_are_typed_errors() {
    let Some(gpu) = gpu() else { return };
    let set = lights();
    let desc = DirectPassDesc { width: W, height: H, output_format: wgpu::TextureFormat::Rgba16Float };
    let pass = DirectPass::new(gpu, &set, &desc).unwrap();
    let tex = wgpu::TextureUsages::TEXTURE_BINDING;
    let good = texture(gpu, "gb", (W, H), wgpu::TextureFormat::Rgba32Float, tex).create_view(&Default::default());
    let small = texture(gpu, "small", (W / 2, H), wgpu::TextureFormat::Rgba32Float, tex).create_view(&Default::default());
    let unorm = texture(gpu, "unorm", (W, H), wgpu::TextureFormat::Rgba8Unorm, tex).create_view(&Default::default());
    let out16 = texture(gpu, "out", (W, H), wgpu::TextureFormat::Rgba16Float, wgpu::TextureUsages::STORAGE_BINDING).create_view(&Default::default());
    let not_storage = texture(gpu, "out", (W, H), wgpu::TextureFormat::Rgba16Float, tex).create_view(&Default::default());
    let frame = DirectFrame { culling: None, seed: 1, frame: 0 };
    let bad = |position, normal, output, what: &str| {
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        let e = pass.record(gpu, &mut enc, &DirectInputs { position, normal, output }, &frame).unwrap_err();
        assert!(matches!(e, GpuError::Binding { .. }), "{what}: {e}");
        eprintln!("{what}: {e}");
    };
    bad(&small, &good, &out16, "small position");
    bad(&good, &unorm, &out16, "unorm normal");
    bad(&good, &good, &not_storage, "output without STORAGE_BINDING");
    bad(&good, &good, &good, "output of another format");
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    pass.record(gpu, &mut enc, &DirectInputs { position: &good, normal: &good, output: &out16 }, &frame).unwrap();
    assert!(DirectPass::new(gpu, &set, &DirectPassDesc { width: 0, ..desc }).is_err());
    let e = DirectPass::new(gpu, &set, &DirectPassDesc { output_format: wgpu::TextureFormat::Rgba8Unorm, ..desc }).err().unwrap();
    assert!(matches!(e, GpuError::Binding { .. }), "{e}");
}

slc_tests::harness!(
    Gpu: pass_matches_gpu_direct,
    Gpu: wrong_inputs_are_typed_errors,
);
