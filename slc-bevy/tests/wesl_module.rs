//! slc's shared functions as a WESL package
//! ([`slc_shared_shaders::wesl::modules`]), imported by a user's shader
//! the way a Bevy 0.20 shader imports a package (`import
//! slc::range::{…};`), compiled by `wesl` 0.6 (Bevy 0.20's compiler, the
//! one this workspace already builds for Bevy) and run on the GPU against
//! the same Rust functions: 4,096 points, 256 lights, each point's SLC sum
//! (kept count equal, irradiance within 1e-4 relative), and the IES lookup
//! through the package's table binding. A panic fails the test binary.

use slc_core::range::{random_range2, slc_keep, slc_weight};
use slc_core::xi::xi_for;
use slc_wgpu::GpuContext;
use wesl::syntax::{ModulePath, PathOrigin};
use wgpu::util::DeviceExt;

const USER: &str = r#"
import slc::xi::xi_for;
import slc::range::{random_range2, slc_keep, slc_weight};

struct Light { position: vec3f, rt2: f32, intensity: vec3f, pad: f32 }
@group(0) @binding(0) var<storage, read> lights: array<Light>;
@group(0) @binding(1) var<storage, read> points: array<vec4f>;
@group(0) @binding(2) var<storage, read_write> out: array<vec4f>;

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
        if slc_keep(random_range2(l.rt2, xi_for(5u, 2u, j)), d2) {
            e += l.intensity / d2 * slc_weight(l.rt2, d2);
            kept += 1u;
        }
    }
    out[i] = vec4f(e, f32(kept));
}
"#;

const POINTS: usize = 4096;
const LIGHTS: usize = 256;

/// `user` compiled by wesl with slc's package resolved as `slc::{name}`.
fn compile(user: &str) -> String {
    let mut r = wesl::resolver::VirtualResolver::new();
    for m in slc_shared_shaders::wesl::modules() {
        r.add_module(
            ModulePath::new(PathOrigin::Package("slc".into()), vec![m.name.into()]),
            m.source.into(),
        );
    }
    let main = ModulePath::new(PathOrigin::Absolute, vec!["main".into()]);
    r.add_module(main.clone(), user.to_string().into());
    let compiler = wesl::Compiler::new_with_resolver(wesl::CompileOptions::default(), r);
    compiler.compile_module(&main).unwrap_or_else(|e| panic!("wesl: {e}")).to_string()
}

fn wesl_shader_runs_like_the_rust_functions(gpu: &GpuContext) {
    let wgsl = compile(USER);
    assert!(!wgsl.contains("import"), "{wgsl}");
    let params = slc_core::range::RangeParams::new(0.01, 1.0).unwrap();
    let h = |k: u32| slc_core::xi::xi_from_bits(slc_core::xi::pcg_hash(k));
    let lights: Vec<[f32; 8]> = (0..LIGHTS as u32)
        .map(|j| {
            let i = glam::Vec3::new(0.5 + h(3 * j), 0.8, 0.6) * 0.02;
            [h(3 * j + 1), 1.0, h(3 * j + 2), params.threshold_range2(i), i.x, i.y, i.z, 0.0]
        })
        .collect();
    let points: Vec<[f32; 4]> =
        (0..POINTS).map(|i| [(i % 64) as f32 / 63.0, 0.0, (i / 64) as f32 / 63.0, 1.0]).collect();
    let d = &gpu.device;
    let module = d.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("user wesl"),
        source: wgpu::ShaderSource::Wgsl(wgsl.into()),
    });
    let pipeline = d.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: None,
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    let buf = |data: &[u8], usage| {
        d.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents: data,
            usage,
        })
    };
    let lb = buf(bytemuck::cast_slice(&lights), wgpu::BufferUsages::STORAGE);
    let pb = buf(bytemuck::cast_slice(&points), wgpu::BufferUsages::STORAGE);
    let ob =
        buf(&vec![0u8; POINTS * 16], wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC);
    let staging = d.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: (POINTS * 16) as u64,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let group = d.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: lb.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 1, resource: pb.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 2, resource: ob.as_entire_binding() },
        ],
    });
    let mut enc = d.create_command_encoder(&Default::default());
    {
        let mut cp = enc.begin_compute_pass(&Default::default());
        cp.set_pipeline(&pipeline);
        cp.set_bind_group(0, &group, &[]);
        cp.dispatch_workgroups((POINTS as u32).div_ceil(64), 1, 1);
    }
    enc.copy_buffer_to_buffer(&ob, 0, &staging, 0, staging.size());
    gpu.queue.submit([enc.finish()]);
    staging.slice(..).map_async(wgpu::MapMode::Read, |_| {});
    gpu.wait().unwrap();
    let got: Vec<[f32; 4]> =
        bytemuck::cast_slice(&staging.slice(..).get_mapped_range().unwrap()).to_vec();
    let (mut counts, mut worst) = (0, 0.0f32);
    for (p, g) in points.iter().zip(&got) {
        let x = glam::Vec3::new(p[0], p[1], p[2]);
        let (mut e, mut kept) = (glam::Vec3::ZERO, 0u32);
        for (j, l) in lights.iter().enumerate() {
            let v = glam::Vec3::new(l[0], l[1], l[2]) - x;
            let d2 = v.dot(v);
            if slc_keep(random_range2(l[3], xi_for(5, 2, j as u32)), d2) {
                e += glam::Vec3::new(l[4], l[5], l[6]) / d2 * slc_weight(l[3], d2);
                kept += 1;
            }
        }
        if g[3] as u32 != kept {
            counts += 1;
            continue;
        }
        worst = worst.max(
            ((glam::Vec3::new(g[0], g[1], g[2]) - e).abs() / e.abs().max(glam::Vec3::splat(1e-20)))
                .max_element(),
        );
    }
    let kept = got.iter().map(|g| g[3]).sum::<f32>() / POINTS as f32;
    eprintln!(
        "WESL shader: {kept:.1} lights kept per point, {counts} kept counts differ, worst relative difference {worst:.2e}"
    );
    assert!(kept > 5.0 && kept < LIGHTS as f32 * 0.9, "{kept}");
    assert!(counts <= 4, "{counts} points keep other lights than the CPU");
    assert!(worst <= 1e-4, "{worst:.2e}");
}

/// The IES module brings its table binding along (`@group(1) @binding(0)`),
/// and nothing else declares one.
fn wesl_ies_module_declares_the_table() {
    let wgsl = compile(
        "import slc::ies::ies_candela;\n@compute @workgroup_size(1) fn main() { let c = ies_candela(0u, 0u, 0.5, 0.5); }\n",
    );
    assert!(wgsl.contains("@group(1) @binding(0)"), "{wgsl}");
    slc_shared_shaders::validate("wesl ies", &wgsl).unwrap();
}

/// A plain harness (as `headless.rs`'s): libtest's lines, the GPU test
/// ignored with a SKIP line where no adapter exists, a failure instead
/// under `SLC_REQUIRE_GPU=1` (CI).
fn main() {
    let filter: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with('-')).collect();
    let gpu_test = "wesl_shader_runs_like_the_rust_functions";
    let cpu_test = "wesl_ies_module_declares_the_table";
    if std::env::args().any(|a| a == "--list") {
        println!("{gpu_test}: test\n{cpu_test}: test");
        return;
    }
    let selected =
        |name: &str| filter.is_empty() || filter.iter().any(|f| name.contains(f.as_str()));
    let required = std::env::var("SLC_REQUIRE_GPU").is_ok_and(|v| v == "1");
    let (mut passed, mut ignored) = (0, 0);
    println!("\nrunning {} tests", [gpu_test, cpu_test].iter().filter(|n| selected(n)).count());
    if selected(cpu_test) {
        wesl_ies_module_declares_the_table();
        println!("test {cpu_test} ... ok");
        passed += 1;
    }
    if selected(gpu_test) {
        match GpuContext::new() {
            Ok(gpu) => {
                eprintln!("GPU test runs on: {}", gpu.describe());
                wesl_shader_runs_like_the_rust_functions(&gpu);
                println!("test {gpu_test} ... ok");
                passed += 1;
            }
            Err(e) if required => panic!("SLC_REQUIRE_GPU=1 but no GPU adapter: {e}"),
            Err(e) => {
                println!(
                    "SKIP {gpu_test}: no GPU adapter ({e}; SLC_REQUIRE_GPU=1 makes this a failure)"
                );
                println!("test {gpu_test} ... ignored");
                ignored += 1;
            }
        }
    }
    println!("\ntest result: ok. {passed} passed; 0 failed; {ignored} ignored\n");
}
