//! Plays the engine: its own device, its own render pipelines rasterizing
//! the Cornell box's G-buffer (a `Depth32Float` depth buffer and normals)
//! and the spot light's reflective shadow map, then slc's two passes
//! recorded into its own command encoder, both reading the depth buffer
//! with the camera's inverse view-projection — the [`IndirectPass`] (the
//! spot's one-bounce light through 16,384 VPLs) and the [`DirectPass`] (48
//! small coloured lights under the ceiling, culled stochastically, moved
//! and dimmed every frame with [`DirectPass::update_lights`]) — and its own
//! composition `emission + albedo/π · (E_indirect + E_direct)`. (The
//! spot's own direct light, which needs the engine's shadow map, is left
//! out.)
//!
//! ```text
//! cargo run --release -p slc-wgpu --example embed -- embed.png
//! ```
//!
//! `cargo test` runs it as a GPU test (`tests/tests/embed_example.rs`,
//! through slc-tests' harness): the image is compared with the CPU
//! backend's ray-cast frame of the same scene.

use slc_scene::image::Image;
use slc_scene::scene::{LightMap, PrimaryLight, Scene};
use slc_scene::vpl::{Culling, VplSettings};
use slc_wgpu::glam::Vec3;
use slc_wgpu::passes::{
    DirectInputs, DirectPass, DirectPassDesc, DirectSelection, DirectSettings, IndirectInputs,
    IndirectPass, IndirectPassDesc, VplInput, VplSourceDesc,
};
use slc_wgpu::{GBuffer, GpuContext, Light, LightSet, PointLight, Surface};
use wgpu::util::DeviceExt;

/// One vertex of the engine's mesh.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Vertex {
    position: [f32; 3],
    normal: [f32; 3],
    albedo: [f32; 3],
    material: f32,
}

/// Uniforms of the engine's two raster passes.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Uniforms {
    view_proj: [[f32; 4]; 4],
    eye: [f32; 4],
    /// Spot axis (xyz), texel solid angle at the axis (w).
    axis: [f32; 4],
    /// Spot intensity (rgb), cos outer (w).
    intensity: [f32; 4],
    /// cos inner (x).
    cone: [f32; 4],
}

/// The engine's shaders. The RSM's flux uses slc-core's spot fall-off and
/// texel solid angle (`spot_falloff`, `rsm_texel_solid_angle`, from
/// `slc_core::wgsl::library()`), so the engine and the CPU reference light
/// the scene alike.
const SHADER: &str = r#"
@group(1) @binding(0) var<storage, read> slc_table: array<f32>;
struct Uniforms { view_proj: mat4x4f, eye: vec4f, axis: vec4f, intensity: vec4f, cone: vec4f }
@group(0) @binding(0) var<uniform> u: Uniforms;
struct VsOut { @builtin(position) clip: vec4f, @location(0) world: vec3f, @location(1) normal: vec3f,
               @location(2) albedo: vec3f, @location(3) @interpolate(flat) material: f32 }
@vertex fn vs(@location(0) p: vec3f, @location(1) n: vec3f, @location(2) a: vec3f, @location(3) m: f32) -> VsOut {
    return VsOut(u.view_proj * vec4f(p, 1.0), p, n, a, m);
}
fn facing(n: vec3f, p: vec3f) -> vec3f {
    let m = normalize(n);
    return select(-m, m, dot(m, u.eye.xyz - p) >= 0.0);
}
@fragment fn gbuffer(v: VsOut) -> @location(0) vec4f {
    return vec4f(facing(v.normal, v.world), v.material);
}
struct ROut { @location(0) position: vec4f, @location(1) normal: vec4f, @location(2) flux: vec4f }
@fragment fn rsm(v: VsOut) -> ROut {
    let d = normalize(v.world - u.eye.xyz);
    let c = dot(d, u.axis.xyz);
    let d_omega = rsm_texel_solid_angle(u.axis.w, c);
    let flux = u.intensity.xyz * spot_falloff(c, u.intensity.w, u.cone.x, 0.0) * d_omega * v.albedo;
    return ROut(vec4f(v.world, 1.0), vec4f(facing(v.normal, v.world), 0.0), vec4f(flux, 0.0));
}
"#;

/// Image size and RSM edge.
pub const W: u32 = 256;
pub const H: u32 = 256;
pub const RSM: u32 = 128;
/// Frames averaged for the written image (an engine's temporal accumulation).
const FRAMES: u32 = 16;

fn target(
    device: &wgpu::Device,
    label: &str,
    (w, h): (u32, u32),
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    })
}

/// Reads an `Rgba32Float` texture back (rows of `w · 16` bytes, a multiple
/// of 256 for the sizes used here).
fn read_rgba32(device: &wgpu::Device, queue: &wgpu::Queue, t: &wgpu::Texture) -> Vec<[f32; 4]> {
    let (w, h) = (t.width(), t.height());
    let staging = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("staging"),
        size: (w * h * 16) as u64,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut enc = device.create_command_encoder(&Default::default());
    enc.copy_texture_to_buffer(
        t.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &staging,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(w * 16),
                rows_per_image: None,
            },
        },
        t.size(),
    );
    queue.submit([enc.finish()]);
    staging.slice(..).map_async(wgpu::MapMode::Read, |_| {});
    device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    bytemuck::cast_slice(&staging.slice(..).get_mapped_range().expect("mapped")).to_vec()
}

/// What the example computes: the composed image, the raw indirect
/// irradiance (rgb, lights kept) and the small lights' direct irradiance
/// (rgb, lights in range) per pixel.
pub struct Frame {
    pub image: Image,
    pub irradiance: Vec<[f32; 4]>,
    pub direct: Vec<[f32; 4]>,
}

/// The engine's small lights at frame `frame`: 48 coloured points in a
/// 8 × 6 grid 2 mm under the ceiling, swaying front to back by up to 3 cm
/// and pulsing between 0.5 and 1.5 times their intensity (frame 0: in
/// place, at 1×).
pub fn small_lights_at(frame: u32) -> Vec<Light> {
    let colours = [Vec3::new(1.0, 0.3, 0.2), Vec3::new(0.2, 1.0, 0.3), Vec3::new(0.3, 0.4, 1.0)];
    let t = frame as f32;
    (0..48)
        .map(|i| {
            let p = Vec3::new(
                0.05 + 0.065 * (i % 8) as f32,
                0.498,
                0.06 + 0.085 * (i / 8) as f32 + 0.03 * (0.7 * t).sin(),
            );
            Light::Point(
                PointLight::new(p, colours[i % 3] * (0.004 * (1.0 + 0.5 * (0.9 * t).sin())))
                    .expect("valid light"),
            )
        })
        .collect()
}

/// The small lights as the direct pass is built with (frame 0's).
pub fn small_lights() -> LightSet {
    LightSet::new(small_lights_at(0)).expect("non-empty")
}

/// Renders `frames` frames (a new ξ set each, as an engine's frames draw
/// them, the small lights at [`small_lights_at`] the frame number) and
/// averages them, as an engine's temporal accumulation would.
pub fn render(
    scene: &Scene,
    settings: &VplSettings,
    min_distance: f32,
    frames: u32,
) -> Result<Frame, Box<dyn std::error::Error>> {
    // The engine's device.
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter =
        pollster::block_on(wgpu::util::initialize_adapter_from_env_or_default(&instance, None))?;
    let (device, queue) =
        pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default()))?;

    // The engine's mesh: every triangle's corners with their normals.
    let mut vertices = Vec::with_capacity(scene.triangles.len() * 3);
    for (i, tri) in scene.triangles.iter().enumerate() {
        let m = scene.material_of[i];
        let geo = (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalize();
        for (k, p) in tri.iter().enumerate() {
            let n = if scene.normals.is_empty() { geo } else { scene.normals[i][k] };
            let albedo = scene.materials[m as usize].albedo;
            vertices.push(Vertex {
                position: p.to_array(),
                normal: n.to_array(),
                albedo: albedo.to_array(),
                material: m as f32,
            });
        }
    }
    let vbuf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("mesh"),
        contents: bytemuck::cast_slice(&vertices),
        usage: wgpu::BufferUsages::VERTEX,
    });

    // Camera and spot light as view-projection matrices.
    // (glam's camera module: right-handed, depth in [0, 1].)
    use slc_wgpu::glam::camera::rh::{proj, view::look_to_mat4};
    let cam = &scene.camera;
    let (_, cam_up, cam_forward) = cam.basis();
    // Near and far planes around the box: a 32-bit depth then unprojects
    // to ~2⁻²⁴·d²/near, a few micrometres here.
    let camera_view_proj =
        proj::directx::perspective(cam.vfov_deg.to_radians(), W as f32 / H as f32, 0.1, 10.0)
            * look_to_mat4(cam.position, cam_forward, cam_up);
    let camera = Uniforms {
        view_proj: camera_view_proj.to_cols_array_2d(),
        eye: cam.position.extend(1.0).to_array(),
        axis: [0.0; 4],
        intensity: [0.0; 4],
        cone: [0.0; 4],
    };
    let PrimaryLight::Spot { position, direction, intensity, inner, outer } = scene.primary else {
        return Err("this example's RSM is a spot light's".into());
    };
    // The RSM's frame and texel order are slc's LightMap (row 0 toward
    // −up, so both backends make the same interleaved subsets): the
    // Y-down (Vulkan-convention) projection puts it there.
    let LightMap::Perspective { up, .. } = scene.primary.light_map(scene.bounds()) else {
        return Err("a spot light's map is perspective".into());
    };
    let light_proj = proj::vulkan::perspective(2.0 * outer, 1.0, 0.01, 100.0);
    let tan = outer.tan();
    let light = Uniforms {
        view_proj: (light_proj * look_to_mat4(position, direction, up)).to_cols_array_2d(),
        eye: position.extend(1.0).to_array(),
        axis: direction.extend((2.0 * tan / RSM as f32).powi(2)).to_array(),
        intensity: intensity.extend(outer.cos()).to_array(),
        cone: [inner.cos(), 0.0, 0.0, 0.0],
    };

    // The engine's pipelines: G-buffer (depth, normal + material id) and
    // RSM (position, normal, flux), each with a depth buffer.
    let source = format!("{}\n{SHADER}", slc_core::wgsl::library());
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("engine"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let attributes =
        wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3, 3 => Float32];
    let layout = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<Vertex>() as u64,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &attributes,
    };
    let raster = |entry: &str, formats: &[wgpu::TextureFormat]| {
        let targets: Vec<Option<wgpu::ColorTargetState>> =
            formats.iter().map(|&f| Some(f.into())).collect();
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(entry),
            layout: None,
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs"),
                compilation_options: Default::default(),
                buffers: &[Some(layout.clone())],
            },
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some(entry),
                compilation_options: Default::default(),
                targets: &targets,
            }),
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: Some(wgpu::DepthStencilState {
                format: wgpu::TextureFormat::Depth32Float,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: Default::default(),
            multiview_mask: None,
            cache: None,
        })
    };
    use wgpu::TextureFormat::{Rgba16Float, Rgba32Float};
    let gbuffer_pipeline = raster("gbuffer", &[Rgba32Float]);
    let rsm_pipeline = raster("rsm", &[Rgba32Float, Rgba16Float, Rgba16Float]);

    let rt = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
    let gb_normal =
        target(&device, "gb normal", (W, H), Rgba32Float, rt | wgpu::TextureUsages::COPY_SRC);
    // slc reads the depth buffer: TEXTURE_BINDING as well.
    let gb_depth = target(&device, "gb depth", (W, H), wgpu::TextureFormat::Depth32Float, rt);
    let rsm = [
        target(&device, "rsm position", (RSM, RSM), Rgba32Float, rt),
        target(&device, "rsm normal", (RSM, RSM), Rgba16Float, rt),
        target(&device, "rsm flux", (RSM, RSM), Rgba16Float, rt),
    ];
    let rsm_depth = target(
        &device,
        "rsm depth",
        (RSM, RSM),
        wgpu::TextureFormat::Depth32Float,
        wgpu::TextureUsages::RENDER_ATTACHMENT,
    );
    let output = target(
        &device,
        "indirect",
        (W, H),
        Rgba32Float,
        wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
    );
    let direct_target = target(
        &device,
        "direct",
        (W, H),
        Rgba32Float,
        wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
    );
    let view = |t: &wgpu::Texture| t.create_view(&Default::default());
    let (gb_views, rsm_views) =
        ([view(&gb_depth), view(&gb_normal)], [view(&rsm[0]), view(&rsm[1]), view(&rsm[2])]);
    let (output_view, direct_view) = (view(&output), view(&direct_target));

    // slc's passes, on the engine's device, reading its (standard-Z)
    // Depth32Float depth buffer: the descriptors' default surface.
    let gpu = GpuContext::from_device(device.clone(), queue.clone());
    let mut pass = IndirectPass::new(
        &gpu,
        &IndirectPassDesc {
            output_format: Rgba32Float,
            ..IndirectPassDesc::new(W, H, VplSourceDesc::Rsm { size: RSM })
        },
    )?;
    // The small lights with uniform picks: the CPU's twin (slc_cpu::direct)
    // draws the same numbers.
    let direct_desc = DirectPassDesc {
        output_format: Rgba32Float,
        selection: DirectSelection::Uniform { k: 8 },
        ..DirectPassDesc::new(W, H)
    };
    let mut direct_pass = DirectPass::new(&gpu, &small_lights(), &direct_desc)?;

    let draw = |encoder: &mut wgpu::CommandEncoder,
                pipeline: &wgpu::RenderPipeline,
                uniforms: &Uniforms,
                colors: &[wgpu::TextureView],
                depth: &wgpu::TextureView| {
        let ubuf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("uniforms"),
            contents: bytemuck::bytes_of(uniforms),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: ubuf.as_entire_binding() }],
        });
        let attachments: Vec<Option<wgpu::RenderPassColorAttachment>> = colors
            .iter()
            .map(|v| {
                Some(wgpu::RenderPassColorAttachment {
                    view: v,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                        store: wgpu::StoreOp::Store,
                    },
                })
            })
            .collect();
        let mut rp = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &attachments,
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: depth,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        rp.set_pipeline(pipeline);
        rp.set_bind_group(0, &bind, &[]);
        rp.set_vertex_buffer(0, vbuf.slice(..));
        rp.draw(0..vertices.len() as u32, 0..1);
    };
    let n = (W * H) as usize;
    let (mut irradiance, mut direct) = (vec![[0.0f32; 4]; n], vec![[0.0f32; 4]; n]);
    let rsm_depth = view(&rsm_depth);
    let inv_view_proj = camera_view_proj.inverse();
    for f in 0..frames {
        let settings = VplSettings { frame: settings.frame + f, ..*settings };
        // The small lights move: rewritten in place, the BSH refitted on the GPU.
        direct_pass.update_lights(&small_lights_at(settings.frame))?;
        // One frame: one encoder with the engine's raster passes and slc's passes.
        let mut encoder =
            device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame") });
        draw(&mut encoder, &gbuffer_pipeline, &camera, &gb_views[1..], &gb_views[0]);
        draw(&mut encoder, &rsm_pipeline, &light, &rsm_views, &rsm_depth);
        let gbuffer = GBuffer {
            surface: Surface::Depth { depth: &gb_views[0], inv_view_proj },
            normal: &gb_views[1],
            eye: cam.position,
        };
        let inputs = IndirectInputs {
            gbuffer,
            vpls: VplInput::Rsm {
                position: &rsm_views[0],
                normal: &rsm_views[1],
                flux: &rsm_views[2],
            },
            output: &output_view,
            materials: None,
        };
        pass.record(
            &mut encoder,
            &inputs,
            &slc_wgpu::frame::indirect_settings(&settings, min_distance)?,
        )?;
        let culling = settings.culling;
        direct_pass.record(
            &mut encoder,
            &DirectInputs::new(gbuffer, &direct_view),
            &DirectSettings { culling, seed: settings.seed, frame: settings.frame },
        )?;
        queue.submit([encoder.finish()]);
        // The engine's accumulation (here on the host, from the read-backs).
        for (sum, new) in [
            (&mut irradiance, read_rgba32(&device, &queue, &output)),
            (&mut direct, read_rgba32(&device, &queue, &direct_target)),
        ] {
            for (a, b) in sum.iter_mut().zip(new) {
                for k in 0..4 {
                    a[k] += b[k] / frames as f32;
                }
            }
        }
    }

    // The engine's composition, with the G-buffer's material ids (flat
    // attributes: an interpolated id can round to the neighbour's).
    let normals = read_rgba32(&device, &queue, &gb_normal);
    let mut image = Image::new(W, H);
    for (i, n) in normals.iter().enumerate() {
        if n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0 {
            continue;
        }
        let m = scene.materials[n[3] as usize];
        let (e, d) = (irradiance[i], direct[i]);
        image.data[i] = slc_core::frame::diffuse_radiance(
            m.albedo,
            m.emission,
            Vec3::new(e[0] + d[0], e[1] + d[1], e[2] + d[2]),
        );
    }
    Ok(Frame { image, irradiance, direct })
}

pub fn settings() -> VplSettings {
    VplSettings {
        culling: Culling::stochastic(0.008, 1.0).expect("valid"),
        ..VplSettings::default()
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args().nth(1).unwrap_or_else(|| "embed.png".into());
    let frame = render(&Scene::cornell_box(), &settings(), 0.05, FRAMES)?;
    frame.image.write_png(std::path::Path::new(&out), 1.0)?;
    println!(
        "wrote {out}: the Cornell box, {W}×{H}, indirect light from {} VPLs and direct light from 48 small lights, on the GPU, {FRAMES} frames averaged",
        RSM * RSM
    );
    Ok(())
}
