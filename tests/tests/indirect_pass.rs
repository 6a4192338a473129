//! The engine-facing indirect pass ([`slc_wgpu::passes::IndirectPass`])
//! recorded into an encoder of ours against [`GpuVpl`], and its input
//! checks. `GpuVpl` records the same pass on its own uploads of the CPU's
//! G-buffer and VPLs (its parity with the CPU's shading is
//! `vpl_parity.rs`'s); here the pass gets everything as an engine would:
//! G-buffer and RSM textures (made here from the CPU's G-buffer and VPLs),
//! a storage texture to write, and a command encoder of ours. Tolerances
//! (the bounds of the host-made shading this test once compared with, kept;
//! observed now: the same numbers):
//! - SLC keep decisions may differ for lights within a few ulps of their
//!   range (at most 0.5% of the pixels, at most one light each), and
//!   elsewhere the irradiance agrees to 1e-4 relative (1e-3 after the
//!   denoise, whose weights amplify last-bit differences);
//! - clamp and none draw no ξ: the same decisions everywhere.

use glam::Vec3;
use slc_core::cluster::{map_x, map_y};
use slc_cpu::vpl::VplContext;
use slc_scene::scene::Scene;
use slc_scene::vpl::{Culling, PERIOD, Shaded, VplSettings};
use slc_tests::engine::{self, texture, upload};
use slc_tests::gpu;
use slc_tests::vpl::GpuVpl;
use slc_wgpu::GpuContext;
use slc_wgpu::GpuError;
use slc_wgpu::passes::{
    GBuffer, GpuMaterial, GpuVplRecord, IndirectInputs, IndirectMaterials, IndirectPass,
    IndirectPassDesc, Surface, SurfaceDesc, VplInput, VplSourceDesc, vpl_buffer,
};

const W: u32 = 64;
const H: u32 = 48;
const RSM: u32 = 16;

fn cpu_ctx() -> VplContext {
    VplContext::new(&Scene::cornell_box(), W, H, RSM, None).unwrap()
}

fn v4(v: Vec3, w: f32) -> [f32; 4] {
    [v.x, v.y, v.z, w]
}

/// The engine's resources: G-buffer, RSM and an `Rgba32Float` output with
/// `COPY_SRC` for the read-back.
struct Engine {
    position: wgpu::TextureView,
    normal: wgpu::TextureView,
    rsm: [wgpu::TextureView; 3],
    records: wgpu::Buffer,
    output: wgpu::Texture,
    output_view: wgpu::TextureView,
    eye: Vec3,
    min_distance: f32,
}

impl Engine {
    fn gbuffer(&self) -> GBuffer<'_> {
        GBuffer { surface: Surface::Position(&self.position), normal: &self.normal, eye: self.eye }
    }
}

/// A position-input pass for `vpls`.
fn desc(vpls: VplSourceDesc) -> IndirectPassDesc {
    IndirectPassDesc {
        surface: SurfaceDesc::Position,
        output_format: wgpu::TextureFormat::Rgba32Float,
        ..IndirectPassDesc::new(W, H, vpls)
    }
}

fn engine(gpu: &GpuContext, ctx: &VplContext) -> Engine {
    let inputs = ctx.inputs();
    let gb = &inputs.gbuffer;
    let pos: Vec<[f32; 4]> = (0..gb.position.len())
        .map(|i| v4(gb.position[i], if gb.valid(i) { 1.0 } else { 0.0 }))
        .collect();
    let nrm: Vec<[f32; 4]> = gb.normal.iter().map(|&n| v4(n, 0.0)).collect();
    let v = &inputs.vpls;
    let rsm = [
        upload(
            gpu,
            "rsm position",
            (RSM, RSM),
            &v.position.iter().map(|&p| v4(p, 1.0)).collect::<Vec<_>>(),
        ),
        upload(
            gpu,
            "rsm normal",
            (RSM, RSM),
            &v.normal.iter().map(|&n| v4(n, 0.0)).collect::<Vec<_>>(),
        ),
        upload(
            gpu,
            "rsm flux",
            (RSM, RSM),
            &v.flux.iter().map(|&f| v4(f, 0.0)).collect::<Vec<_>>(),
        ),
    ];
    // Records in the RSM's map order (record q is texel (map_x(q), map_y(q))):
    // record q's subset, q mod P², is its texel's (P = 8: the texel's place
    // in its 8×8 cluster), its entry q / P² its cluster's index, so each
    // subset holds the RSM subset's VPLs in the same order, and each run of
    // 64 records (a near cluster of the buffer) is a near cluster of the RSM.
    let records: Vec<GpuVplRecord> = (0..v.len() as u32)
        .map(|q| {
            let t = (map_y(q, RSM) * RSM + map_x(q, RSM)) as usize;
            GpuVplRecord {
                position: v.position[t],
                normal: v.normal[t],
                flux: v.flux[t],
                ..GpuVplRecord::default()
            }
        })
        .collect();
    let output = engine::output(gpu, (W, H));
    Engine {
        position: upload(gpu, "gb position", (W, H), &pos),
        normal: upload(gpu, "gb normal", (W, H), &nrm),
        rsm,
        records: vpl_buffer(gpu, &records),
        output_view: output.create_view(&Default::default()),
        output,
        eye: Scene::cornell_box().camera.position,
        min_distance: inputs.min_d2.sqrt(),
    }
}

/// Records the pass into an encoder of ours, submits it and reads the
/// output texture back.
fn run(
    gpu: &GpuContext,
    pass: &mut IndirectPass,
    e: &Engine,
    vpls: VplInput,
    settings: &VplSettings,
) -> Vec<[f32; 4]> {
    let inputs =
        IndirectInputs { gbuffer: e.gbuffer(), vpls, output: &e.output_view, materials: None };
    let st = slc_wgpu::frame::indirect_settings(settings, e.min_distance).unwrap();
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    pass.record(&mut enc, &inputs, &st).unwrap();
    engine::submit_and_read(gpu, enc, &e.output)
}

fn settings(culling: Culling, denoise: bool) -> VplSettings {
    VplSettings { culling, denoise, seed: 7, frame: 3, ..VplSettings::default() }
}

/// The culling named `name` at this file's ε (0.004) and clamp range (0.08).
fn culling(name: &str) -> Culling {
    Culling::named(name, 0.004, 1.0, 0.08).unwrap()
}

/// Pixels whose kept count differs, and the worst relative irradiance
/// difference elsewhere.
fn compare(pass: &[[f32; 4]], reference: &Shaded, ctx: &VplContext) -> (usize, usize, f64) {
    let gb = ctx.gbuffer();
    let (mut pixels, mut differs, mut worst) = (0, 0, 0.0f64);
    for (i, p) in pass.iter().enumerate() {
        if !gb.valid(i) {
            assert_eq!(*p, [0.0; 4], "pixel {i} without a surface must be zero");
            continue;
        }
        pixels += 1;
        let dk = (p[3] as u32).abs_diff(reference.kept[i]);
        assert!(dk <= 1, "pixel {i}: kept {} by the pass vs {} by GpuVpl", p[3], reference.kept[i]);
        if dk > 0 {
            differs += 1;
            continue;
        }
        let (a, b) = (Vec3::new(p[0], p[1], p[2]).as_dvec3(), reference.irradiance[i].as_dvec3());
        let rel = ((a - b).abs().max_element() - 1e-9).max(0.0) / b.abs().max_element().max(1e-30);
        worst = worst.max(rel);
    }
    (pixels, differs, worst)
}

fn pass_matches_gpu_vpl_for_every_method() {
    let Some(gpu) = gpu() else { return };
    let ctx = cpu_ctx();
    let e = engine(gpu, &ctx);
    let mut reference = GpuVpl::new(gpu, ctx.inputs()).unwrap();
    let mut pass = IndirectPass::new(gpu, &desc(VplSourceDesc::Rsm { size: RSM })).unwrap();
    let rsm = VplInput::Rsm { position: &e.rsm[0], normal: &e.rsm[1], flux: &e.rsm[2] };
    // Without the near-field split (R_n = 0) and with the default one
    // (NEAR_FACTOR clamp distances).
    // The split moves light between the fields: the kept counts (w) change.
    let mut without_split = Vec::new();
    for method in [culling("slc"), culling("clamp"), Culling::None] {
        for (denoise, near_radius) in
            [false, true].into_iter().flat_map(|d| [(d, Some(0.0)), (d, None)])
        {
            let s = VplSettings { near_radius, ..settings(method, denoise) };
            let got = run(gpu, &mut pass, &e, rsm, &s);
            if near_radius == Some(0.0) {
                without_split = got.clone();
            } else {
                assert!(
                    got.iter().zip(&without_split).any(|(a, b)| a[3] != b[3]),
                    "{}: the near field changed nothing",
                    method.name()
                );
            }
            let want = reference.shade(&s).unwrap();
            let (pixels, differs, worst) = compare(&got, &want, &ctx);
            eprintln!(
                "{} denoise={denoise} near={near_radius:?}: {pixels} pixels, {differs} keep decisions differ, worst relative difference {worst:.2e}",
                method.name()
            );
            assert!(pixels > (W * H / 2) as usize);
            if method != culling("slc") {
                assert_eq!(differs, 0, "{}: no ξ, so every decision must agree", method.name());
            }
            assert!(
                differs as f64 <= 0.005 * pixels as f64,
                "{}: {differs} of {pixels} pixels keep different lights",
                method.name()
            );
            // The denoise's weights (n·n')¹⁶ and (1 − δ²)² amplify the last
            // bits of the renormalised normals and of |p − eye| against the
            // ray distance (observed 1.7e-4); a differing decision spreads
            // into the neighbours it is mixed with.
            let bound = match (denoise, differs > 0) {
                (false, _) => 1e-4,
                (true, false) => 1e-3,
                (true, true) => 1e-2,
            };
            assert!(
                worst <= bound,
                "{} denoise={denoise}: worst relative difference {worst:.2e} > {bound}",
                method.name()
            );
        }
    }
    gpu.take_errors().unwrap();
}

/// The same VPLs from a buffer, ordered into the RSM's subsets: without ξ
/// (clamp, none) the very same image.
fn vpl_buffer_source_gives_the_rsm_image() {
    let Some(gpu) = gpu() else { return };
    let ctx = cpu_ctx();
    let e = engine(gpu, &ctx);
    let mut from_rsm = IndirectPass::new(gpu, &desc(VplSourceDesc::Rsm { size: RSM })).unwrap();
    let mut from_buffer =
        IndirectPass::new(gpu, &desc(VplSourceDesc::Buffer { count: RSM * RSM })).unwrap();
    let rsm = VplInput::Rsm { position: &e.rsm[0], normal: &e.rsm[1], flux: &e.rsm[2] };
    for method in [culling("clamp"), Culling::None] {
        let s = settings(method, true);
        let a = run(gpu, &mut from_rsm, &e, rsm, &s);
        let b = run(gpu, &mut from_buffer, &e, VplInput::Buffer(&e.records), &s);
        assert_eq!(a, b, "{}", method.name());
        assert!(a.iter().any(|p| p[0] > 0.0), "{}: the image is black", method.name());
    }
}

/// Wrong formats, sizes, usages and sources are typed errors before
/// anything is recorded.
fn wrong_inputs_are_typed_errors() {
    let Some(gpu) = gpu() else { return };
    let ctx = cpu_ctx();
    let e = engine(gpu, &ctx);
    let fmt = wgpu::TextureFormat::Rgba32Float;
    let desc = desc(VplSourceDesc::Rsm { size: RSM });
    let mut pass = IndirectPass::new(gpu, &desc).unwrap();
    let rsm = VplInput::Rsm { position: &e.rsm[0], normal: &e.rsm[1], flux: &e.rsm[2] };
    let tex = |size, format, usage| {
        texture(gpu, "bad", size, format, usage).create_view(&Default::default())
    };
    let sampled = wgpu::TextureUsages::TEXTURE_BINDING;
    let bad_format = tex((W, H), wgpu::TextureFormat::Rgba8Unorm, sampled);
    let bad_size = tex((W / 2, H), fmt, sampled);
    let bad_usage = tex((W, H), fmt, wgpu::TextureUsages::COPY_DST);
    let small_rsm = tex((RSM / 2, RSM / 2), fmt, sampled);
    let out16 = tex((W, H), wgpu::TextureFormat::Rgba16Float, wgpu::TextureUsages::STORAGE_BINDING);
    let ok =
        IndirectInputs { gbuffer: e.gbuffer(), vpls: rsm, output: &e.output_view, materials: None };
    assert!(pass.check(&ok).is_ok());
    let with = |surface, normal| GBuffer { surface, normal, eye: e.eye };
    let cases: [(&str, IndirectInputs); 6] = [
        (
            "G-buffer position",
            IndirectInputs { gbuffer: with(Surface::Position(&bad_format), &e.normal), ..ok },
        ),
        (
            "G-buffer normal",
            IndirectInputs { gbuffer: with(Surface::Position(&e.position), &bad_size), ..ok },
        ),
        (
            "G-buffer position",
            IndirectInputs { gbuffer: with(Surface::Position(&bad_usage), &e.normal), ..ok },
        ),
        ("output", IndirectInputs { output: &out16, ..ok }),
        (
            "RSM flux",
            IndirectInputs {
                vpls: VplInput::Rsm { position: &e.rsm[0], normal: &e.rsm[1], flux: &small_rsm },
                ..ok
            },
        ),
        ("VPLs", IndirectInputs { vpls: VplInput::Buffer(&e.records), ..ok }),
    ];
    for (name, inputs) in cases {
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        let st =
            slc_wgpu::frame::indirect_settings(&settings(culling("slc"), false), 0.01).unwrap();
        match pass.record(&mut enc, &inputs, &st) {
            Err(GpuError::Binding { name: n, .. }) => assert_eq!(n, name),
            other => panic!("{name}: expected a binding error, got {:?}", other.err()),
        }
    }
    // Bad descriptors and settings.
    let bad_descs = [
        IndirectPassDesc { vpls: VplSourceDesc::Rsm { size: 12 }, ..desc },
        IndirectPassDesc { vpls: VplSourceDesc::Buffer { count: 100 }, ..desc },
        IndirectPassDesc { width: 0, ..desc },
        IndirectPassDesc { tile_list: 0, ..desc },
    ];
    for d in bad_descs {
        assert!(matches!(IndirectPass::new(gpu, &d), Err(GpuError::Setting(_))), "{d:?}");
    }
    assert!(matches!(
        IndirectPass::new(
            gpu,
            &IndirectPassDesc { output_format: wgpu::TextureFormat::Rgba8Unorm, ..desc }
        ),
        Err(GpuError::Binding { name: "output_format", .. })
    ));
    assert!(
        slc_wgpu::frame::indirect_settings(
            &VplSettings { near_radius: Some(-1.0), ..settings(culling("slc"), false) },
            0.01
        )
        .is_err()
    );
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    let st = slc_wgpu::passes::IndirectSettings {
        min_distance: f32::NAN,
        ..slc_wgpu::passes::IndirectSettings::default()
    };
    assert!(matches!(pass.record(&mut enc, &ok, &st), Err(GpuError::Setting(_))));
    // The material input: required by a glossy pass, refused by a
    // Lambertian one, its table and specular target checked.
    let out_usage = wgpu::TextureUsages::STORAGE_BINDING;
    let specular = tex((W, H), fmt, out_usage);
    let specular16 = tex((W, H), wgpu::TextureFormat::Rgba16Float, out_usage);
    let table = slc_tests::engine::materials(
        gpu,
        &[GpuMaterial::new(Vec3::ONE, Vec3::ZERO, 1.0, 0.2, Vec3::ZERO, 0.0)],
    );
    let uniform = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 48,
        usage: wgpu::BufferUsages::UNIFORM,
        mapped_at_creation: false,
    });
    let mats = |table, specular| Some(IndirectMaterials { table, specular });
    let mut glossy = IndirectPass::new(gpu, &IndirectPassDesc { glossy: true, ..desc }).unwrap();
    let st = slc_wgpu::frame::indirect_settings(&settings(culling("slc"), false), 0.01).unwrap();
    assert!(glossy.check(&IndirectInputs { materials: mats(&table, &specular), ..ok }).is_ok());
    for (on_glossy, inputs, name) in [
        (false, IndirectInputs { materials: mats(&table, &specular), ..ok }, "materials"),
        (true, ok, "materials"),
        (true, IndirectInputs { materials: mats(&table, &specular16), ..ok }, "specular output"),
        (true, IndirectInputs { materials: mats(&table, &bad_size), ..ok }, "specular output"),
        (true, IndirectInputs { materials: mats(&uniform, &specular), ..ok }, "material table"),
    ] {
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        let p = if on_glossy { &mut glossy } else { &mut pass };
        match p.record(&mut enc, &inputs, &st) {
            Err(GpuError::Binding { name: n, .. }) => assert_eq!(n, name),
            other => panic!("{name}: expected a binding error, got {:?}", other.err()),
        }
    }
    gpu.take_errors().unwrap();
}

/// The glossy pass as an engine records it on the glossy box (a material
/// table of the G-buffer's distinct materials, each pixel's index in the
/// normal's w, a specular target) against `GpuVpl` on the same G-buffer:
/// the irradiance within the bounds of
/// [`pass_matches_gpu_vpl_for_every_method`], the specular correction
/// within the same bounds on its scale `|S| + 2·c_diff/π·E` (the sum of
/// its terms' magnitudes, `vpl_parity.rs`), zero where no surface is, and
/// not zero everywhere.
fn glossy_pass_matches_gpu_vpl() {
    let Some(gpu) = gpu() else { return };
    let ctx = VplContext::new(&Scene::cornell_box_glossy(), W, H, RSM, None).unwrap();
    let gb = ctx.gbuffer();
    let mut e = engine(gpu, &ctx);
    let (mut table, mut index) = (Vec::<GpuMaterial>::new(), Vec::new());
    for i in 0..gb.position.len() {
        let s = gb.specular_at(i).unwrap_or_default();
        let m = GpuMaterial::new(gb.albedo[i], Vec3::ZERO, s.metallic, s.roughness, s.f0, s.f90);
        let k = table
            .iter()
            .position(|t| bytemuck::bytes_of(t) == bytemuck::bytes_of(&m))
            .unwrap_or_else(|| {
                table.push(m);
                table.len() - 1
            });
        index.push(k as f32);
    }
    e.normal = upload(
        gpu,
        "gb normal",
        (W, H),
        &gb.normal.iter().zip(&index).map(|(&n, &k)| v4(n, k)).collect::<Vec<_>>(),
    );
    let table = engine::materials(gpu, &table);
    let specular = engine::output(gpu, (W, H));
    let specular_view = specular.create_view(&Default::default());
    let mut reference = GpuVpl::new(gpu, ctx.inputs()).unwrap();
    let mut pass = IndirectPass::new(
        gpu,
        &IndirectPassDesc { glossy: true, ..desc(VplSourceDesc::Rsm { size: RSM }) },
    )
    .unwrap();
    let rsm = VplInput::Rsm { position: &e.rsm[0], normal: &e.rsm[1], flux: &e.rsm[2] };
    for method in [culling("slc"), Culling::None] {
        for denoise in [false, true] {
            let s = settings(method, denoise);
            let inputs = IndirectInputs {
                gbuffer: e.gbuffer(),
                vpls: rsm,
                output: &e.output_view,
                materials: Some(IndirectMaterials { table: &table, specular: &specular_view }),
            };
            let mut enc = gpu.device.create_command_encoder(&Default::default());
            pass.record(
                &mut enc,
                &inputs,
                &slc_wgpu::frame::indirect_settings(&s, e.min_distance).unwrap(),
            )
            .unwrap();
            let got = engine::submit_and_read(gpu, enc, &e.output);
            let got_s = engine::submit_and_read(
                gpu,
                gpu.device.create_command_encoder(&Default::default()),
                &specular,
            );
            let want = reference.shade(&s).unwrap();
            let (pixels, differs, worst) = compare(&got, &want, &ctx);
            let mut worst_s = 0.0f64;
            for i in 0..got_s.len() {
                let a = Vec3::new(got_s[i][0], got_s[i][1], got_s[i][2]).as_dvec3();
                if !gb.valid(i) {
                    assert_eq!(a, glam::DVec3::ZERO, "pixel {i} without a surface must have no S");
                    continue;
                }
                let b = want.specular[i].as_dvec3();
                let c_diff = gb
                    .specular_at(i)
                    .map_or(glam::DVec3::ZERO, |l| l.diffuse_albedo(gb.albedo[i]).as_dvec3());
                let scale =
                    b.abs() + c_diff * (2.0 / std::f64::consts::PI) * want.irradiance[i].as_dvec3();
                let d = ((a - b).abs() - glam::DVec3::splat(1e-9)).max(glam::DVec3::ZERO)
                    / scale.max(glam::DVec3::splat(1e-30));
                worst_s = worst_s.max(d.max_element());
            }
            eprintln!(
                "glossy {} denoise={denoise}: {pixels} pixels, {differs} keep decisions differ, worst relative irradiance {worst:.2e}, specular {worst_s:.2e}",
                method.name()
            );
            assert!(
                got_s.iter().any(|p| p[0].abs() > 0.0),
                "{}: S is zero everywhere",
                method.name()
            );
            let bound = match (denoise, differs > 0) {
                (false, _) => 1e-4,
                (true, false) => 1e-3,
                (true, true) => 1e-2,
            };
            assert!(
                differs as f64 <= 0.005 * pixels as f64,
                "{}: {differs} of {pixels} pixels keep different lights",
                method.name()
            );
            assert!(
                worst <= bound && worst_s <= bound,
                "glossy {} denoise={denoise}: {worst:.2e}, {worst_s:.2e} > {bound}",
                method.name()
            );
        }
    }
    gpu.take_errors().unwrap();
}

/// Writes `depth` (one value per texel, row-major) into a `Depth32Float`
/// texture the way an engine's depth buffer gets its values, by a render
/// pass (depth textures take no copies): a full-screen triangle whose
/// fragments write `frag_depth` from an `R32Float` texture.
fn depth32(gpu: &GpuContext, depth: &[f32]) -> wgpu::TextureView {
    const SHADER: &str = r#"
@group(0) @binding(0) var depth_in: texture_2d<f32>;
@vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4f {
    let uv = vec2f(f32((i << 1u) & 2u), f32(i & 2u));
    return vec4f(uv * 2.0 - 1.0, 0.0, 1.0);
}
struct Out { @builtin(frag_depth) depth: f32 }
@fragment fn fs(@builtin(position) p: vec4f) -> Out {
    return Out(textureLoad(depth_in, vec2i(p.xy), 0).x);
}
"#;
    let src = texture(
        gpu,
        "depth values",
        (W, H),
        wgpu::TextureFormat::R32Float,
        wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
    );
    gpu.queue.write_texture(
        src.as_image_copy(),
        bytemuck::cast_slice(depth),
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(W * 4), rows_per_image: None },
        src.size(),
    );
    let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
    let dst = texture(gpu, "depth buffer", (W, H), wgpu::TextureFormat::Depth32Float, usage);
    let d = &gpu.device;
    let module = d.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("depth writer"),
        source: wgpu::ShaderSource::Wgsl(SHADER.into()),
    });
    let layout = d.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: None,
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: false },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        }],
    });
    let src_view = src.create_view(&Default::default());
    let group = d.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout,
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: wgpu::BindingResource::TextureView(&src_view),
        }],
    });
    let pipeline_layout = d.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let pipeline = d.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("depth writer"),
        layout: Some(&pipeline_layout),
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs"),
            compilation_options: Default::default(),
            targets: &[],
        }),
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: Some(wgpu::DepthStencilState {
            format: wgpu::TextureFormat::Depth32Float,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: Default::default(),
        multiview_mask: None,
        cache: None,
    });
    let view = dst.create_view(&Default::default());
    let mut enc = d.create_command_encoder(&Default::default());
    {
        let mut rp = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("depth writer"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(0.5),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        rp.set_pipeline(&pipeline);
        rp.set_bind_group(0, &group, &[]);
        rp.draw(0..3, 0..1);
    }
    gpu.queue.submit([enc.finish()]);
    view
}

/// The G-buffer's surface from an engine's `Depth32Float` depth buffer,
/// standard (background 1) and reversed Z (background 0), with the
/// camera's inverse view-projection, against world positions unprojected
/// on the host from the standard depth: the same image (SLC with its
/// denoise and near field, which read the distance from the eye): the
/// same surface mask, and at most 1% of the pixels differ by more than
/// 1e-3 relative or in their kept count (a position a few ulps off moves
/// a light across its range).
fn depth_input_matches_positions() {
    let Some(gpu) = gpu() else { return };
    let ctx = cpu_ctx();
    let e = engine(gpu, &ctx);
    let gb = ctx.gbuffer();
    let cam = Scene::cornell_box().camera;
    let (_, up, forward) = cam.basis();
    use glam::camera::rh::{proj, view::look_to_mat4};
    let view = look_to_mat4(cam.position, forward, up);
    let (fov, aspect) = (cam.vfov_deg.to_radians(), W as f32 / H as f32);
    // Reversed Z: near and far swapped, so near maps to 1 and far to 0.
    let (vp, vp_reversed) = (
        proj::directx::perspective(fov, aspect, 0.1, 10.0) * view,
        proj::directx::perspective(fov, aspect, 10.0, 0.1) * view,
    );
    let n = (W * H) as usize;
    let (mut forward_depth, mut reversed_depth, mut points) =
        (vec![1.0f32; n], vec![0.0f32; n], vec![[0.0f32; 4]; n]);
    let inv = vp.inverse();
    for i in 0..n {
        if !gb.valid(i) {
            continue;
        }
        let p = gb.position[i].extend(1.0);
        let (c, r) = (vp * p, vp_reversed * p);
        forward_depth[i] = c.z / c.w;
        reversed_depth[i] = r.z / r.w;
        let (x, y) = ((i as u32 % W) as f32, (i as u32 / W) as f32);
        let q = slc_shared_shaders::engine::unproject_pixel(
            inv.x_axis,
            inv.y_axis,
            inv.z_axis,
            inv.w_axis,
            x,
            y,
            W as f32,
            H as f32,
            forward_depth[i],
        );
        points[i] = q.to_array();
    }
    // Surfaces 1-2 m away: near 1 in standard depth, near 0 reversed.
    assert!(
        (0..n).all(|i| !gb.valid(i) || (forward_depth[i] > 0.5 && reversed_depth[i] < 0.5)),
        "reversed Z must map near to 1"
    );
    let positions = upload(gpu, "unprojected", (W, H), &points);
    let (forward_view, reversed_view) =
        (depth32(gpu, &forward_depth), depth32(gpu, &reversed_depth));
    let rsm = VplInput::Rsm { position: &e.rsm[0], normal: &e.rsm[1], flux: &e.rsm[2] };
    let st = slc_wgpu::frame::indirect_settings(&settings(culling("slc"), true), e.min_distance)
        .unwrap();
    let image = |surface: SurfaceDesc, gbuffer: Surface| {
        let d = IndirectPassDesc { surface, ..desc(VplSourceDesc::Rsm { size: RSM }) };
        let mut pass = IndirectPass::new(gpu, &d).unwrap();
        let inputs = IndirectInputs {
            gbuffer: GBuffer { surface: gbuffer, normal: &e.normal, eye: e.eye },
            vpls: rsm,
            output: &e.output_view,
            materials: None,
        };
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        pass.record(&mut enc, &inputs, &st).unwrap();
        engine::submit_and_read(gpu, enc, &e.output)
    };
    // One descriptor reads both conventions: 0 and 1 are background.
    let depth = SurfaceDesc::Depth { format: wgpu::TextureFormat::Depth32Float };
    let by_positions = image(SurfaceDesc::Position, Surface::Position(&positions));
    let by_depth = image(depth, Surface::Depth { depth: &forward_view, inv_view_proj: inv });
    let by_reversed = image(
        depth,
        Surface::Depth { depth: &reversed_view, inv_view_proj: vp_reversed.inverse() },
    );
    for (what, got) in [("standard depth", &by_depth), ("reversed Z", &by_reversed)] {
        let (mut valid, mut far, mut worst) = (0, 0, 0.0f32);
        for i in 0..n {
            let (a, b) = (got[i], by_positions[i]);
            assert_eq!(
                a == [0.0; 4],
                b == [0.0; 4],
                "{what}, pixel {i}: surface masks differ ({a:?} vs {b:?})"
            );
            if gb.valid(i) {
                valid += 1;
                let rel = (0..3)
                    .map(|c| (a[c] - b[c]).abs() / b[c].abs().max(1e-6))
                    .fold(0.0f32, f32::max);
                worst = worst.max(rel);
                far += (rel > 1e-3 || a[3] != b[3]) as usize;
            }
        }
        eprintln!(
            "{what} vs positions: {far} of {valid} pixels differ by more than 1e-3 or in their count; worst relative {worst:.2e}"
        );
        assert!(valid > n / 2);
        assert!(far * 100 <= valid, "{what}: {far} of {valid} pixels differ");
    }
    gpu.take_errors().unwrap();
}

/// The pass's interleaving is unbiased over frames (its subset map
/// shifted per frame, stratified): the mean of frames `0..P²` of the
/// unculled, undenoised pass, with the near-field split, is the pass's
/// own reference (not interleaved: every VPL at every pixel) at every
/// pixel, to f32 summation error; frame 0 alone is not.
fn interleaving_averages_to_the_reference_over_frames() {
    let Some(gpu) = gpu() else { return };
    let ctx = cpu_ctx();
    let e = engine(gpu, &ctx);
    let rsm = VplInput::Rsm { position: &e.rsm[0], normal: &e.rsm[1], flux: &e.rsm[2] };
    let mut reference_pass = IndirectPass::new(
        gpu,
        &IndirectPassDesc { interleaved: false, ..desc(VplSourceDesc::Rsm { size: RSM }) },
    )
    .unwrap();
    let inputs =
        IndirectInputs { gbuffer: e.gbuffer(), vpls: rsm, output: &e.output_view, materials: None };
    let unculled = slc_wgpu::passes::IndirectSettings {
        culling: slc_wgpu::Culling::None,
        denoise: false,
        near_radius: Some(0.0),
        min_distance: e.min_distance,
        ..Default::default()
    };
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    reference_pass.record(&mut enc, &inputs, &unculled).unwrap();
    let reference = engine::submit_and_read(gpu, enc, &e.output);
    let mut pass = IndirectPass::new(gpu, &desc(VplSourceDesc::Rsm { size: RSM })).unwrap();
    let frames = PERIOD * PERIOD;
    let mut mean = vec![[0.0f64; 3]; reference.len()];
    let mut first = Vec::new();
    for frame in 0..frames {
        let img =
            run(gpu, &mut pass, &e, rsm, &VplSettings { frame, ..settings(Culling::None, false) });
        for (m, p) in mean.iter_mut().zip(&img) {
            for c in 0..3 {
                m[c] += p[c] as f64 / frames as f64;
            }
        }
        if frame == 0 {
            first = img;
        }
    }
    let gb = ctx.gbuffer();
    let worst = |img: &dyn Fn(usize) -> [f64; 3]| {
        (0..reference.len())
            .filter(|&i| gb.valid(i))
            .map(|i| {
                (0..3)
                    .map(|c| {
                        (img(i)[c] - reference[i][c] as f64).abs()
                            / (reference[i][c] as f64).abs().max(1e-9)
                    })
                    .fold(0.0, f64::max)
            })
            .fold(0.0, f64::max)
    };
    let (of_mean, of_first) =
        (worst(&|i| mean[i]), worst(&|i| [0, 1, 2].map(|c| first[i][c] as f64)));
    eprintln!(
        "mean of {frames} frames against the reference: worst relative {of_mean:.2e}; frame 0 alone {of_first:.2e}"
    );
    assert!(
        of_mean <= 1e-4,
        "the mean over {frames} frames differs from the reference by {of_mean:.2e}"
    );
    assert!(
        of_first > 1e-2,
        "frame 0 alone must differ (it shades one subset per pixel): {of_first:.2e}"
    );
    gpu.take_errors().unwrap();
}

slc_tests::harness!(
    Gpu: interleaving_averages_to_the_reference_over_frames,
    Gpu: depth_input_matches_positions,
    Gpu: pass_matches_gpu_vpl_for_every_method,
    Gpu: vpl_buffer_source_gives_the_rsm_image,
    Gpu: wrong_inputs_are_typed_errors,
    Gpu: glossy_pass_matches_gpu_vpl,
);
