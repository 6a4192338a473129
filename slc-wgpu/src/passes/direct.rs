//! The many-lights direct pass: SLC shading of point, spot, IES and
//! triangle lights on an engine's G-buffer (the deferred many-lights case
//! that clustered renderers solve with hard, biased light ranges), into a
//! texture the engine owns.
//!
//! Recorded dispatches, in one compute pass: `gbuffer_import` (textures →
//! shading points), `light_update` (`r² = r_t²/(1−ξ)` with
//! `ξ = xi_for(seed, frame, light)`), `bsh_refit` (every level, deepest
//! first), `bsh_reservoir` (BSH traversal into a k-slot reservoir, the
//! picks RR-tested at their sampled points and weighted by `1/p · n/k`) and
//! `irradiance_export`. The numbers are those of `slc_cpu::direct` and
//! [`crate::direct::GpuDirect`] for the same seed and frame. **Unshadowed**:
//! the engine owns visibility (its shadow maps, or a ray query of its own).
//!
//! | input | format | size | usage | content |
//! |---|---|---|---|---|
//! | `position` | `Rgba32Float` or `Rgba16Float` | `width × height` | `TEXTURE_BINDING` | world position; `w > 0` where a surface is |
//! | `normal` | `Rgba32Float` or `Rgba16Float` | `width × height` | `TEXTURE_BINDING` | world unit normal facing the camera (`w` unused) |
//! | `output` | the descriptor's `output_format` (`Rgba16Float` or `Rgba32Float`) | `width × height` | `STORAGE_BINDING` | written: irradiance (rgb), lights in range (a); 0 where no surface |
//!
//! The engine multiplies the irradiance by `albedo/π` (a diffuse surface).
//!
//! ```no_run
//! # fn frame(device: wgpu::Device, queue: wgpu::Queue, gb_position: wgpu::TextureView,
//! #          gb_normal: wgpu::TextureView, output: wgpu::TextureView)
//! #          -> Result<(), Box<dyn std::error::Error>> {
//! use glam::Vec3;
//! use slc_core::light::{Light, PointLight};
//! use slc_core::range::RangeParams;
//! use slc_scene::lights::LightSet;
//! use slc_wgpu::GpuContext;
//! use slc_wgpu::passes::{DirectFrame, DirectInputs, DirectPass, DirectPassDesc};
//!
//! let gpu = GpuContext::from_device(device.clone(), queue.clone());
//! // The engine's lights (here 10,000 points on a grid).
//! let lights: Vec<Light> = (0..10_000)
//!     .map(|i| Light::Point(PointLight::new(Vec3::new((i % 100) as f32, 3.0, (i / 100) as f32), Vec3::splat(5.0)).unwrap()))
//!     .collect();
//! let set = LightSet::new(lights)?;
//! let pass = DirectPass::new(&gpu, &set, &DirectPassDesc { width: 1920, height: 1080, output_format: wgpu::TextureFormat::Rgba16Float })?;
//! let mut encoder = device.create_command_encoder(&Default::default());
//! // ... the engine's G-buffer pass ...
//! let frame = DirectFrame { culling: Some(RangeParams::new(0.008, 1.0)?), seed: 1, frame: 0 };
//! pass.record(&gpu, &mut encoder, &DirectInputs { position: &gb_position, normal: &gb_normal, output: &output }, &frame)?;
//! queue.submit([encoder.finish()]);
//! # Ok(()) }
//! ```

use super::{check_gbuffer, check_view, output_format};
use crate::direct::reservoir_pipeline;
use crate::kernel::{B, layout, pipeline, zeroed};
use crate::lights::{GpuLightSet, WG};
use crate::{GpuContext, GpuError};
use glam::Vec3;
use slc_core::range::RangeParams;
use slc_scene::lights::LightSet;
use slc_shared_shaders::layout::{ImageParams, ShadeParams};
use slc_shared_shaders::{Features, Kernel, generate};
use wgpu::util::DeviceExt;

/// Tile edge of the 2-D kernels, in pixels.
const TILE: u32 = crate::vpl::TILE;

/// What a [`DirectPass`] is built for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DirectPassDesc {
    /// G-buffer and output width.
    pub width: u32,
    /// G-buffer and output height.
    pub height: u32,
    /// Format of the output storage texture: `Rgba16Float` or `Rgba32Float`.
    pub output_format: wgpu::TextureFormat,
}

/// The engine's resources for one frame.
#[derive(Clone, Copy, Debug)]
pub struct DirectInputs<'a> {
    /// G-buffer world positions (`w > 0`: surface).
    pub position: &'a wgpu::TextureView,
    /// G-buffer unit normals facing the camera.
    pub normal: &'a wgpu::TextureView,
    /// Where the irradiance goes.
    pub output: &'a wgpu::TextureView,
}

/// Per-frame settings of the direct pass.
#[derive(Clone, Copy, Debug)]
pub struct DirectFrame {
    /// SLC's error bound and exposure (`r_t²` per light); `None` keeps
    /// every light in range (`r_t² = ∞`: unculled, the reference).
    pub culling: Option<RangeParams>,
    /// Seed of the per-light ξ and the reservoir's random numbers.
    pub seed: u32,
    /// Frame number (a new ξ set per frame).
    pub frame: u32,
}

/// SLC direct light from a [`LightSet`] on an engine's G-buffer (see the
/// module docs for the inputs it expects).
pub struct DirectPass {
    desc: DirectPassDesc,
    set: GpuLightSet,
    image: wgpu::Buffer,
    shade_params: wgpu::Buffer,
    points: wgpu::Buffer,
    irradiance: wgpu::Buffer,
    import: (wgpu::ComputePipeline, wgpu::BindGroupLayout),
    reservoir: wgpu::ComputePipeline,
    reservoir_group: wgpu::BindGroup,
    export: (wgpu::ComputePipeline, wgpu::BindGroupLayout),
    normals: wgpu::Buffer,
}

impl DirectPass {
    /// Uploads the lights and their BSH and builds the pipelines and
    /// intermediate buffers for `desc`; checks the sizes and device limits
    /// first.
    pub fn new(gpu: &GpuContext, lights: &LightSet, desc: &DirectPassDesc) -> Result<Self, GpuError> {
        let (w, h) = (desc.width, desc.height);
        if w == 0 || h == 0 {
            return Err(GpuError::Setting(format!("direct pass: image size {w}×{h} must be non-zero")));
        }
        let output = output_format(desc.output_format)?;
        let pixels = w as u64 * h as u64;
        let lim = &gpu.limits;
        gpu.require("max_storage_buffer_binding_size (G-buffer)", pixels * 16, lim.max_storage_buffer_binding_size)?;
        let groups = lim.max_compute_workgroups_per_dimension as u64;
        gpu.require("max_compute_workgroups_per_dimension", w.div_ceil(TILE).max(h.div_ceil(TILE)) as u64, groups)?;
        gpu.require("max_compute_workgroups_per_dimension (pixels)", pixels.div_ceil(WG as u64), groups)?;
        gpu.require("max_storage_textures_per_shader_stage", 1, lim.max_storage_textures_per_shader_stage as u64)?;
        let set = GpuLightSet::new(gpu, lights.lights(), lights.bounds(), lights.bsh(), &[], &[], None)?;
        let (reservoir, reservoir_layout) = reservoir_pipeline(gpu, &set)?;
        let base = Features { tile_size: TILE, workgroup_size: WG, output_format: output, ..Features::default() };
        let kernel = |k: Kernel, l: &wgpu::BindGroupLayout| -> Result<wgpu::ComputePipeline, GpuError> {
            Ok(pipeline(gpu, k.name(), generate(k, &base)?, &[l]))
        };
        use B::*;
        let import_layout = layout(gpu, "gbuffer_import", &[(0, Uniform), (1, Texture), (2, Texture), (3, Write), (4, Write), (5, Write)]);
        let export_layout = layout(gpu, "irradiance_export", &[(0, Uniform), (1, Read), (2, Read), (3, Storage(desc.output_format))]);
        let rw = wgpu::BufferUsages::STORAGE;
        let points = zeroed(gpu, "slc direct points", pixels * 16, rw);
        let normals = zeroed(gpu, "slc direct normals", pixels * 16, rw);
        let irradiance = zeroed(gpu, "slc direct irradiance", pixels * 16, rw);
        let uniform = |label: &str, bytes: &[u8]| {
            gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytes,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            })
        };
        let image = uniform("slc direct image", bytemuck::bytes_of(&ImageParams { eye: Vec3::ZERO, width: w, height: h, pad0: 0, pad1: 0, pad2: 0 }));
        let shade_params =
            uniform("slc direct shade params", bytemuck::bytes_of(&ShadeParams { point_count: (pixels) as u32, seed: 0, frame: 0, eps: 0.0 }));
        let b = crate::kernel::whole;
        let reservoir_group = crate::kernel::group(
            gpu,
            "bsh_reservoir",
            &reservoir_layout,
            &[
                (0, b(&shade_params)),
                (1, b(&points)),
                (2, b(&normals)),
                (3, b(&set.lights)),
                (4, b(&set.rt2)),
                (5, b(&set.r2)),
                (6, b(&set.bsh)),
                (9, b(&irradiance)),
            ],
        );
        let s = DirectPass {
            desc: *desc,
            import: (kernel(Kernel::GbufferImport, &import_layout)?, import_layout),
            export: (kernel(Kernel::IrradianceExport, &export_layout)?, export_layout),
            set,
            image,
            shade_params,
            points,
            normals,
            irradiance,
            reservoir,
            reservoir_group,
        };
        gpu.take_errors()?;
        Ok(s)
    }

    /// The descriptor the pass was built for.
    pub fn desc(&self) -> &DirectPassDesc {
        &self.desc
    }

    /// Checks `inputs` against the descriptor (formats, sizes, usages).
    pub fn check(&self, inputs: &DirectInputs) -> Result<(), GpuError> {
        let size = (self.desc.width, self.desc.height);
        check_gbuffer(inputs.position, inputs.normal, size)?;
        check_view("output", inputs.output, size, &[self.desc.output_format], wgpu::TextureUsages::STORAGE_BINDING)
    }

    /// Records the frame into `encoder` (one compute pass) and stages its
    /// uniforms (seed, frame, `r_t²`) for the next submission; checks the
    /// inputs first and records nothing when they are wrong.
    pub fn record(&self, gpu: &GpuContext, encoder: &mut wgpu::CommandEncoder, inputs: &DirectInputs, frame: &DirectFrame) -> Result<(), GpuError> {
        self.check(inputs)?;
        let (w, h) = (self.desc.width, self.desc.height);
        let sp = ShadeParams { point_count: w * h, seed: frame.seed, frame: frame.frame, eps: 0.0 };
        gpu.queue.write_buffer(&self.shade_params, 0, bytemuck::bytes_of(&sp));
        self.set.set_threshold(gpu, frame.culling.as_ref());
        self.set.set_frame(gpu, frame.seed, frame.frame);
        let group = |label: &str, layout: &wgpu::BindGroupLayout, res: &[(u32, wgpu::BindingResource)]| crate::kernel::group(gpu, label, layout, res);
        let import = group(
            "gbuffer_import",
            &self.import.1,
            &[
                (0, self.image.as_entire_binding()),
                (1, wgpu::BindingResource::TextureView(inputs.position)),
                (2, wgpu::BindingResource::TextureView(inputs.normal)),
                (3, self.points.as_entire_binding()),
                (4, self.normals.as_entire_binding()),
                (5, self.irradiance.as_entire_binding()),
            ],
        );
        let export = group(
            "irradiance_export",
            &self.export.1,
            &[
                (0, self.image.as_entire_binding()),
                (1, self.points.as_entire_binding()),
                (2, self.irradiance.as_entire_binding()),
                (3, wgpu::BindingResource::TextureView(inputs.output)),
            ],
        );
        let (gx, gy) = (w.div_ceil(TILE), h.div_ceil(TILE));
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("slc direct"), timestamp_writes: None });
        pass.set_pipeline(&self.import.0);
        pass.set_bind_group(0, &import, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
        self.set.encode(&mut pass);
        pass.set_pipeline(&self.reservoir);
        pass.set_bind_group(0, &self.reservoir_group, &[]);
        pass.set_bind_group(1, &self.set.ies_table, &[]);
        pass.dispatch_workgroups((w * h).div_ceil(WG), 1, 1);
        pass.set_pipeline(&self.export.0);
        pass.set_bind_group(0, &export, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
        Ok(())
    }
}
