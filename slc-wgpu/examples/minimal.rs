//! The smallest embedding of slc's shared functions: your own wgpu device
//! and your own compute shader, with slc's roulette and random numbers
//! pasted in as plain WGSL (`slc_core::wgsl::modules_wgsl(&["xi",
//! "range"])`: no binding of slc's own, no composer). For 4,096 points and
//! 512 point lights it sums each point's irradiance with stochastic light
//! culling (one ξ per light, `r² = r_t²/(1−ξ)`, kept lights weighted by
//! `1/p`), and the CPU computes the same with the same Rust functions.
//!
//! ```text
//! cargo run --release -p slc-wgpu --example minimal
//! ```
//!
//! `cargo test` runs it as a GPU test (`tests/tests/minimal_example.rs`).
//! (With naga_oil, the composer Bevy uses, the same functions are modules:
//! `#import slc::range::{random_range2, slc_keep, slc_weight}`; see
//! docs/embedding.md.)

use glam::Vec3;
use slc_core::range::{RangeParams, random_range2, slc_keep, slc_weight};
use slc_core::xi::xi_for;
use wgpu::util::DeviceExt;

/// Points and lights of the example.
pub const POINTS: usize = 4096;
/// Point lights.
pub const LIGHTS: usize = 512;
/// The frame's seed (every light's ξ comes from it).
pub const SEED: u32 = 7;

/// The shader: slc's functions, then the program's own code.
fn shader() -> String {
    let slc = slc_core::wgsl::modules_wgsl(&["xi", "range"]).expect("known modules");
    slc + r#"
struct Light { position: vec3f, rt2: f32, intensity: vec3f, pad: f32 }
@group(0) @binding(0) var<storage, read> lights: array<Light>;
@group(0) @binding(1) var<storage, read> points: array<vec4f>;
@group(0) @binding(2) var<storage, read_write> out: array<vec4f>;
@group(0) @binding(3) var<uniform> seed: vec4u;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u) {
    let i = id.x;
    if i >= arrayLength(&points) { return; }
    let x = points[i].xyz;
    var e = vec3f(0.0);
    var kept = 0u;
    for (var j = 0u; j < arrayLength(&lights); j++) {
        let l = lights[j];
        let v = l.position - x;
        let d2 = dot(v, v);
        if slc_keep(random_range2(l.rt2, xi_for(seed.x, 0u, j)), d2) {
            e += l.intensity / d2 * slc_weight(l.rt2, d2);
            kept += 1u;
        }
    }
    out[i] = vec4f(e, f32(kept));
}
"#
}

/// The example's lights: positions on a 1 m plane, their intensities and
/// `r_t²` for error bound 0.01 (slc-core's threshold range).
pub fn lights() -> Vec<[f32; 8]> {
    let params = RangeParams::new(0.01, 1.0).expect("valid settings");
    (0..LIGHTS)
        .map(|j| {
            let h = |k: u32| slc_core::xi::xi_from_bits(slc_core::xi::pcg_hash(j as u32 * 3 + k));
            let p = Vec3::new(h(0), 1.0, h(1));
            let i = Vec3::new(0.5 + h(2), 0.8, 0.6) * 0.02;
            let rt2 = params.threshold_range2(i);
            [p.x, p.y, p.z, rt2, i.x, i.y, i.z, 0.0]
        })
        .collect()
}

/// The example's shading points: a 64 × 64 grid on the floor below the lights.
pub fn points() -> Vec<[f32; 4]> {
    (0..POINTS).map(|i| [(i % 64) as f32 / 63.0, 0.0, (i / 64) as f32 / 63.0, 1.0]).collect()
}

/// The CPU's result per point: irradiance (rgb) and the kept count, with
/// the same Rust functions the shader's WGSL was generated from.
pub fn cpu() -> Vec<[f32; 4]> {
    let lights = lights();
    points()
        .iter()
        .map(|p| {
            let x = Vec3::new(p[0], p[1], p[2]);
            let (mut e, mut kept) = (Vec3::ZERO, 0u32);
            for (j, l) in lights.iter().enumerate() {
                let v = Vec3::new(l[0], l[1], l[2]) - x;
                let d2 = v.dot(v);
                if slc_keep(random_range2(l[3], xi_for(SEED, 0, j as u32)), d2) {
                    e += Vec3::new(l[4], l[5], l[6]) / d2 * slc_weight(l[3], d2);
                    kept += 1;
                }
            }
            [e.x, e.y, e.z, kept as f32]
        })
        .collect()
}

/// Runs the shader on the default adapter: per point, irradiance (rgb) and
/// the number of lights kept.
pub fn gpu() -> Result<Vec<[f32; 4]>, Box<dyn std::error::Error>> {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter =
        pollster::block_on(wgpu::util::initialize_adapter_from_env_or_default(&instance, None))?;
    let (device, queue) =
        pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default()))?;
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("minimal"),
        source: wgpu::ShaderSource::Wgsl(shader().into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("minimal"),
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    let init = |label: &str, contents: &[u8], usage: wgpu::BufferUsages| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents,
            usage,
        })
    };
    let lights = init("lights", bytemuck::cast_slice(&lights()), wgpu::BufferUsages::STORAGE);
    let points = init("points", bytemuck::cast_slice(&points()), wgpu::BufferUsages::STORAGE);
    let seed = init("seed", bytemuck::cast_slice(&[SEED, 0, 0, 0]), wgpu::BufferUsages::UNIFORM);
    let size = (POINTS * 16) as u64;
    let out = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("out"),
        size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let staging = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("staging"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: lights.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 1, resource: points.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 2, resource: out.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 3, resource: seed.as_entire_binding() },
        ],
    });
    let mut enc = device.create_command_encoder(&Default::default());
    {
        let mut pass = enc.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups((POINTS as u32).div_ceil(64), 1, 1);
    }
    enc.copy_buffer_to_buffer(&out, 0, &staging, 0, size);
    queue.submit([enc.finish()]);
    staging.slice(..).map_async(wgpu::MapMode::Read, |_| {});
    device.poll(wgpu::PollType::wait_indefinitely())?;
    let data = staging.slice(..).get_mapped_range().expect("mapped");
    Ok(bytemuck::cast_slice(&data).to_vec())
}

/// GPU against CPU: the worst relative irradiance difference over the
/// points that kept the same number of lights, and the number of points
/// that did not.
pub fn compare(gpu: &[[f32; 4]], cpu: &[[f32; 4]]) -> (f32, usize) {
    let mut worst = 0.0f32;
    let mut counts = 0;
    for (g, c) in gpu.iter().zip(cpu) {
        if g[3] != c[3] {
            counts += 1;
            continue;
        }
        for k in 0..3 {
            worst = worst.max((g[k] - c[k]).abs() / c[k].abs().max(1e-12));
        }
    }
    (worst, counts)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let (g, c) = (gpu()?, cpu());
    let (worst, counts) = compare(&g, &c);
    let kept: f32 = c.iter().map(|p| p[3]).sum::<f32>() / POINTS as f32;
    println!(
        "{POINTS} points x {LIGHTS} lights, {kept:.1} kept per point: GPU against CPU, worst relative irradiance difference {worst:.2e} (same kept lights), {counts} points with another kept count"
    );
    Ok(())
}
