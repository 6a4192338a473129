//! Device objects every slc camera shares: slc's context on Bevy's render
//! device, and the plugin's own kernels (the G-buffer unpack and the
//! composite into the view target), WESL through Bevy's pipeline cache.

use bevy::core_pipeline::FullscreenShader;
use bevy::prelude::*;
use bevy::render::render_resource::binding_types::{texture_2d, texture_storage_2d};
use bevy::render::render_resource::{
    BindGroupLayoutDescriptor, BindGroupLayoutEntries, BlendComponent, BlendFactor, BlendOperation,
    BlendState, CachedComputePipelineId, CachedRenderPipelineId, ColorTargetState, ColorWrites,
    ComputePipelineDescriptor, FragmentState, PipelineCache, RenderPipelineDescriptor,
    ShaderStages, StorageTextureAccess, TextureSampleType,
};
use bevy::render::renderer::{RenderDevice, RenderQueue};
use slc_wgpu::GpuContext;

/// The textures a view's G-buffer is unpacked into, and slc's output.
pub(crate) const GBUFFER_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// The main texture of an `Hdr` camera.
pub(crate) const HDR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// Device objects shared by every view: slc's context on Bevy's device,
/// and the plugin's two kernels, WESL through Bevy's pipeline cache.
#[derive(Resource)]
pub(crate) struct Gpu {
    pub(crate) ctx: GpuContext,
    pub(crate) unpack_layout: BindGroupLayoutDescriptor,
    pub(crate) unpack: CachedComputePipelineId,
    pub(crate) composite_layout: BindGroupLayoutDescriptor,
    pub(crate) composite: CachedRenderPipelineId,
}

/// The plugin's WESL shaders and slc's WESL package, held so they stay
/// loaded.
#[derive(Resource, Clone)]
pub(crate) struct Shaders {
    unpack: Handle<Shader>,
    composite: Handle<Shader>,
    /// slc's package: held, never read.
    _slc: Vec<Handle<Shader>>,
}

/// Adds slc's WESL package (`slc_shared_shaders::wesl::modules()`, the
/// module path `slc::{name}`: e.g. `import slc::range::{random_range2,
/// slc_keep, slc_weight};`) and the plugin's own shaders to Bevy's shader
/// assets, so that any Bevy shader can import slc's functions.
pub(crate) fn add_shaders(app: &mut App) -> Shaders {
    let mut shaders = app.world_mut().resource_mut::<Assets<Shader>>();
    let slc = slc_shared_shaders::wesl::modules()
        .into_iter()
        .map(|m| {
            shaders.add(Shader::from_wesl(m.source, format!("embedded://slc/{}.wesl", m.name)))
        })
        .collect();
    let unpack = shaders
        .add(Shader::from_wesl(include_str!("unpack.wesl"), "embedded://slc_bevy/unpack.wesl"));
    let composite = shaders.add(Shader::from_wesl(
        include_str!("composite.wesl"),
        "embedded://slc_bevy/composite.wesl",
    ));
    Shaders { unpack, composite, _slc: slc }
}

pub(crate) fn init_gpu(
    mut commands: Commands,
    device: Res<RenderDevice>,
    queue: Res<RenderQueue>,
    cache: Res<PipelineCache>,
    shaders: Res<Shaders>,
    fullscreen: Res<FullscreenShader>,
) {
    let device: wgpu::Device = device.wgpu_device().clone();
    let queue: wgpu::Queue = (**queue).clone();
    let storage = || texture_storage_2d(GBUFFER_FORMAT, StorageTextureAccess::WriteOnly);
    let unpack_layout = BindGroupLayoutDescriptor::new(
        "slc-bevy unpack",
        &BindGroupLayoutEntries::sequential(
            ShaderStages::COMPUTE,
            (texture_2d(TextureSampleType::Uint), storage(), storage(), storage()),
        ),
    );
    let unpack = cache.queue_compute_pipeline(ComputePipelineDescriptor {
        label: Some("slc-bevy unpack".into()),
        layout: vec![unpack_layout.clone()],
        shader: shaders.unpack.clone(),
        entry_point: Some("unpack".into()),
        ..default()
    });
    let composite_layout = BindGroupLayoutDescriptor::new(
        "slc-bevy composite",
        &BindGroupLayoutEntries::single(
            ShaderStages::FRAGMENT,
            texture_2d(TextureSampleType::Float { filterable: false }),
        ),
    );
    let add = BlendComponent {
        src_factor: BlendFactor::One,
        dst_factor: BlendFactor::One,
        operation: BlendOperation::Add,
    };
    let keep = BlendComponent {
        src_factor: BlendFactor::Zero,
        dst_factor: BlendFactor::One,
        operation: BlendOperation::Add,
    };
    let composite = cache.queue_render_pipeline(RenderPipelineDescriptor {
        label: Some("slc-bevy composite".into()),
        layout: vec![composite_layout.clone()],
        vertex: fullscreen.to_vertex_state(),
        fragment: Some(FragmentState {
            shader: shaders.composite.clone(),
            entry_point: Some("composite".into()),
            targets: vec![Some(ColorTargetState {
                format: HDR_FORMAT,
                blend: Some(BlendState { color: add, alpha: keep }),
                write_mask: ColorWrites::ALL,
            })],
            ..default()
        }),
        ..default()
    });
    commands.insert_resource(Gpu {
        ctx: GpuContext::from_device(device, queue),
        unpack_layout,
        unpack,
        composite_layout,
        composite,
    });
}

pub(crate) fn texture(
    device: &wgpu::Device,
    (w, h): (u32, u32),
    label: &str,
    usage: wgpu::TextureUsages,
) -> wgpu::TextureView {
    device
        .create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: GBUFFER_FORMAT,
            usage,
            view_formats: &[],
        })
        .create_view(&Default::default())
}
