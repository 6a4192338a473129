//! Shows the frame's HDR output on the window: a full-screen triangle
//! reads the output texel under each window pixel (nearest: the frame is
//! rendered at the window's size, stretched only while they differ), scales it by the exposure and encodes it with
//! slc-core's [`display_encode`](slc_core::frame::display_encode), the
//! mapping of the PNG previews, into a non-sRGB view of the swap-chain
//! image (so the encoding happens once).

use wgpu::util::DeviceExt;

/// The template: slc-core's `frame` module (for `display_encode`) is
/// prepended; this part only composes it.
const SHADER: &str = r#"
struct Present {
    frame_size: vec2u,
    target_size: vec2u,
    exposure: f32,
    pad0: f32,
    pad1: f32,
    pad2: f32,
}

@group(0) @binding(0) var hdr: texture_2d<f32>;
@group(0) @binding(1) var<uniform> present: Present;

@vertex
fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4f {
    let uv = vec2f(f32((i << 1u) & 2u), f32(i & 2u));
    return vec4f(uv * 2.0 - 1.0, 0.0, 1.0);
}

@fragment
fn fs_main(@builtin(position) pos: vec4f) -> @location(0) vec4f {
    let scale = vec2f(present.frame_size) / vec2f(present.target_size);
    let texel = min(vec2u(floor(pos.xy * scale)), present.frame_size - 1u);
    let c = textureLoad(hdr, texel, 0).rgb * present.exposure;
    return vec4f(display_encode(c.r), display_encode(c.g), display_encode(c.b), 1.0);
}
"#;

/// The uniform of [`SHADER`].
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct PresentParams {
    frame_size: [u32; 2],
    target_size: [u32; 2],
    exposure: f32,
    pad: [f32; 3],
}

/// The present pass's pipeline and its bindings to one frame's output.
pub struct Present {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    params: wgpu::Buffer,
    group: Option<wgpu::BindGroup>,
}

impl Present {
    /// The pipeline for swap-chain views of `format` (non-sRGB).
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Result<Present, String> {
        let frame_wgsl = slc_core::wgsl::modules_wgsl(&["frame"])
            .ok_or("slc-core has no `frame` WGSL module")?;
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("slc view present"),
            source: wgpu::ShaderSource::Wgsl(format!("{frame_wgsl}\n{SHADER}").into()),
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("slc view present"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("slc view present"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("slc view present"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_main"),
                compilation_options: Default::default(),
                targets: &[Some(format.into())],
            }),
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: Default::default(),
            multiview_mask: None,
            cache: None,
        });
        let params = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("slc view present params"),
            contents: bytemuck::bytes_of(&PresentParams {
                frame_size: [1, 1],
                target_size: [1, 1],
                exposure: 1.0,
                pad: [0.0; 3],
            }),
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
        Ok(Present { pipeline, layout, params, group: None })
    }

    /// Binds the frame's HDR output (call again when the frame is rebuilt).
    pub fn bind(&mut self, device: &wgpu::Device, output: &wgpu::Texture) {
        let view = output.create_view(&Default::default());
        self.group = Some(device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("slc view present"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&view),
                },
                wgpu::BindGroupEntry { binding: 1, resource: self.params.as_entire_binding() },
            ],
        }));
    }

    /// Records the pass drawing the bound output over `target` (cleared),
    /// `frame` and `target_size` in pixels.
    pub fn record(
        &self,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        frame: (u32, u32),
        target_size: (u32, u32),
        exposure: f32,
    ) {
        let params = PresentParams {
            frame_size: [frame.0, frame.1],
            target_size: [target_size.0.max(1), target_size.1.max(1)],
            exposure,
            pad: [0.0; 3],
        };
        queue.write_buffer(&self.params, 0, bytemuck::bytes_of(&params));
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("slc view present"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: target,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        if let Some(group) = &self.group {
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, group, &[]);
            pass.draw(0..3, 0..1);
        }
    }
}
