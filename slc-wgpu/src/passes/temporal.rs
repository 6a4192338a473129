//! Temporal accumulation of a per-pixel signal as an engine pass: the
//! `temporal` kernel (slc-core's [`slc_core::temporal`], as slc-cpu's
//! `Temporal` runs it) over the engine's G-buffer, read in place. Each
//! record reprojects the pass's own history with the previous record's
//! view-projection, keeps the taps that saw the same surface (disocclusion
//! otherwise), tests for change against the frame-to-frame noise, blends
//! with the `1/n` moving average (at most [`TemporalSettings::max_history`]
//! frames) and writes the accumulated value (rgb) and the history length
//! in frames (a) into the engine's output; the history ping-pongs between
//! two sets of three `Rgba32Float` textures the pass owns.
//!
//! Use it on irradiance, not radiance (albedo applied after it), for the
//! indirect pass's output or the direct pass's irradiance. A frame whose
//! lighting the engine knows changed (a light moved) passes
//! [`TemporalSettings::after_change`]; a cut calls [`TemporalPass::reset`].
//! Each record advances the history, so record once per frame and submit
//! what was recorded.
//!
//! ```no_run
//! # fn demo(gpu: &slc_wgpu::GpuContext, encoder: &mut wgpu::CommandEncoder, gbuffer: slc_wgpu::passes::GBuffer,
//! #         irradiance: &wgpu::TextureView, accumulated: &wgpu::TextureView, view_projection: slc_wgpu::glam::Mat4) -> Result<(), slc_wgpu::GpuError> {
//! use slc_wgpu::{TemporalSettings, TemporalView};
//! use slc_wgpu::passes::{TemporalInputs, TemporalPass, TemporalPassDesc};
//!
//! let mut temporal = TemporalPass::new(gpu, &TemporalPassDesc::new(1920, 1080))?;
//! // Every frame, after the pass that wrote `irradiance`:
//! let view = TemporalView { view_projection, eye: gbuffer.eye };
//! temporal.record(encoder, &TemporalInputs::new(gbuffer, irradiance, accumulated), &view, &TemporalSettings::default())?;
//! # Ok(()) }
//! ```

use super::{
    FLOAT_INPUTS, GBuffer, SurfaceDesc, ViewCache, check_optional, check_size, check_view,
    output_format,
};
use crate::kernel::{KernelLayout, UniformSlots, check_kernels, zeroed};
use crate::record::{Dispatch, Uploads};
use crate::timing::Stage;
use crate::{GpuContext, GpuError};
use slc_scene::temporal::{TemporalSettings, TemporalView};
use slc_shared_shaders::layout::{TemporalParams, ViewParams};
use slc_shared_shaders::{Features, Kernel, LightTypes};

/// Workgroup edge of the kernel.
const TILE: u32 = 8;
const HISTORY: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;

/// What a [`TemporalPass`] is built for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TemporalPassDesc {
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// Where the G-buffer's surface is read.
    pub surface: SurfaceDesc,
    /// The output's format (`Rgba16Float` or `Rgba32Float`).
    pub output_format: wgpu::TextureFormat,
    /// Reproject by the engine's motion vectors ([`TemporalInputs::motion`])
    /// instead of the previous view-projection: moving objects keep their
    /// history.
    pub motion_vectors: bool,
}

impl TemporalPassDesc {
    /// A pass for `width × height` reading world positions, writing `Rgba16Float`.
    pub fn new(width: u32, height: u32) -> TemporalPassDesc {
        TemporalPassDesc {
            width,
            height,
            surface: SurfaceDesc::Position,
            output_format: wgpu::TextureFormat::Rgba16Float,
            motion_vectors: false,
        }
    }
}

/// One record's inputs.
#[derive(Clone, Copy, Debug)]
pub struct TemporalInputs<'a> {
    /// The frame's G-buffer (surface and normals; the eye).
    pub gbuffer: GBuffer<'a>,
    /// This frame's signal (rgb; `Rgba32Float` or `Rgba16Float`,
    /// `TEXTURE_BINDING`), e.g. the indirect pass's output.
    pub signal: &'a wgpu::TextureView,
    /// Where the accumulated signal goes (rgb; a: history length in
    /// frames), the pass's output format, `STORAGE_BINDING`.
    pub output: &'a wgpu::TextureView,
    /// The engine's motion vectors, for a pass built with
    /// [`TemporalPassDesc::motion_vectors`]: current minus previous UV
    /// (x right, y down, `[0, 1]` across the image; Bevy's convention) in
    /// xy of an `Rg16Float`, `Rg32Float`, `Rgba16Float` or `Rgba32Float`
    /// texture with `TEXTURE_BINDING`.
    pub motion: Option<&'a wgpu::TextureView>,
}

impl<'a> TemporalInputs<'a> {
    /// Inputs without motion vectors.
    pub fn new(
        gbuffer: GBuffer<'a>,
        signal: &'a wgpu::TextureView,
        output: &'a wgpu::TextureView,
    ) -> TemporalInputs<'a> {
        TemporalInputs { gbuffer, signal, output, motion: None }
    }
}

/// The two history sets' textures and views.
struct History {
    views: [wgpu::TextureView; 3],
}

impl History {
    fn new(gpu: &GpuContext, (w, h): (u32, u32), k: usize) -> History {
        let textures = ["value", "noise", "surface"].map(|name| {
            gpu.device.create_texture(&wgpu::TextureDescriptor {
                label: Some(&format!("slc temporal history {k} {name}")),
                size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: HISTORY,
                usage: wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            })
        });
        History { views: textures.map(|t| t.create_view(&Default::default())) }
    }
}

type GroupKey = (
    wgpu::TextureView,
    wgpu::TextureView,
    wgpu::TextureView,
    wgpu::TextureView,
    Option<wgpu::TextureView>,
    usize,
);

/// The formats motion vectors are read in (xy).
const MOTION_FORMATS: [wgpu::TextureFormat; 4] = [
    wgpu::TextureFormat::Rg16Float,
    wgpu::TextureFormat::Rg32Float,
    wgpu::TextureFormat::Rgba16Float,
    wgpu::TextureFormat::Rgba32Float,
];

/// Temporal accumulation on an engine's G-buffer (see the module docs).
pub struct TemporalPass {
    gpu: GpuContext,
    desc: TemporalPassDesc,
    layout: KernelLayout,
    pipeline: wgpu::ComputePipeline,
    view: UniformSlots,
    params: wgpu::Buffer,
    history: [History; 2],
    /// The history set this record reads (it writes the other).
    current: usize,
    previous: Option<TemporalView>,
    cache: ViewCache<GroupKey>,
}

impl TemporalPass {
    /// Checks the sizes and the device's limits (four storage textures per
    /// stage), then builds the pipeline and the history textures.
    pub fn new(gpu: &GpuContext, desc: &TemporalPassDesc) -> Result<TemporalPass, GpuError> {
        let size = (desc.width, desc.height);
        check_size(gpu, "temporal pass", size, TILE)?;
        let features = Features {
            lights: LightTypes { vpl: true, ..LightTypes::default() },
            tile_size: TILE,
            surface: desc.surface.source()?,
            output_format: output_format(desc.output_format)?,
            motion_vectors: desc.motion_vectors,
            ..Features::default()
        };
        gpu.require(
            "max_storage_textures_per_shader_stage",
            4,
            gpu.limits.max_storage_textures_per_shader_stage as u64,
        )?;
        check_kernels(gpu, &[(Kernel::Temporal, &features, 0)])?;
        let layout = KernelLayout::new(gpu, Kernel::Temporal, &features)?;
        let pipeline = layout.pipeline(gpu, &features, None)?;
        let view = UniformSlots::new::<ViewParams>(gpu, "slc temporal view", 1);
        let params = zeroed(
            gpu,
            "slc temporal params",
            std::mem::size_of::<TemporalParams>() as u64,
            wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        );
        let history = [History::new(gpu, size, 0), History::new(gpu, size, 1)];
        let s = TemporalPass {
            gpu: gpu.clone(),
            desc: *desc,
            layout,
            pipeline,
            view,
            params,
            history,
            current: 0,
            previous: None,
            cache: ViewCache::new(),
        };
        gpu.take_errors()?;
        Ok(s)
    }

    /// The descriptor the pass was built for.
    pub fn desc(&self) -> &TemporalPassDesc {
        &self.desc
    }

    /// Forgets the history (a cut): the next record starts afresh.
    pub fn reset(&mut self) {
        self.previous = None;
    }

    /// Records the accumulation into `encoder` (one compute pass); checks
    /// the inputs, view and settings first and records nothing (and keeps
    /// the history) when they are wrong. `view` is this frame's camera
    /// (the G-buffer's); the history advances to this frame.
    pub fn record(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        inputs: &TemporalInputs,
        view: &TemporalView,
        settings: &TemporalSettings,
    ) -> Result<(), GpuError> {
        let (uploads, d) = self.dispatch(inputs, view, settings)?;
        uploads.record(&self.gpu, encoder);
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("slc temporal"),
            timestamp_writes: None,
        });
        d.record(&mut pass);
        Ok(())
    }

    /// The record's uniforms and dispatch; checks first.
    pub(crate) fn dispatch(
        &mut self,
        inputs: &TemporalInputs,
        view: &TemporalView,
        settings: &TemporalSettings,
    ) -> Result<(Uploads, Dispatch), GpuError> {
        let setting = |e: slc_scene::RenderError| GpuError::Setting(format!("temporal pass: {e}"));
        settings.validate().map_err(setting)?;
        view.validate().map_err(setting)?;
        let size = (self.desc.width, self.desc.height);
        let view_params = inputs.gbuffer.check(self.desc.surface, size, 0, 0)?;
        check_view(
            "temporal signal",
            inputs.signal,
            size,
            &FLOAT_INPUTS,
            wgpu::TextureUsages::TEXTURE_BINDING,
        )?;
        check_view(
            "temporal output",
            inputs.output,
            size,
            &[self.desc.output_format],
            wgpu::TextureUsages::STORAGE_BINDING,
        )?;
        check_optional(
            "motion vectors",
            inputs.motion.is_some(),
            self.desc.motion_vectors,
            "a motion-vector texture",
            "TemporalPassDesc::motion_vectors",
        )?;
        if let Some(m) = inputs.motion {
            check_view(
                "motion vectors",
                m,
                size,
                &MOTION_FORMATS,
                wgpu::TextureUsages::TEXTURE_BINDING,
            )?;
        }
        let gpu = &self.gpu;
        let mut uploads = Uploads::default();
        uploads.push(&self.view, &view_params);
        let (m, prev_eye) = self
            .previous
            .map_or((glam::Mat4::ZERO, glam::Vec3::ZERO), |p| (p.view_projection, p.eye));
        let params = TemporalParams {
            c0: m.x_axis,
            c1: m.y_axis,
            c2: m.z_axis,
            c3: m.w_axis,
            prev_eye,
            max_history: settings.max_history,
            has_history: self.previous.is_some() as u32,
            pad0: 0,
            pad1: 0,
            pad2: 0,
        };
        uploads.push_to(&self.params, &params);
        let (read, write) = (self.current, 1 - self.current);
        let g = &inputs.gbuffer;
        let key = (
            g.surface_view().clone(),
            g.normal.clone(),
            inputs.signal.clone(),
            inputs.output.clone(),
            inputs.motion.cloned(),
            read,
        );
        let (layout, history, slots, params_buf) =
            (&self.layout, &self.history, &self.view, &self.params);
        let group = self.cache.get(key, || {
            let tex = wgpu::BindingResource::TextureView;
            let (r, w) = (&history[read].views, &history[write].views);
            let mut res = vec![
                ("view", slots.binding()),
                (g.surface_name(), tex(g.surface_view())),
                ("normal_tex", tex(g.normal)),
                ("params", params_buf.as_entire_binding()),
                ("signal_tex", tex(inputs.signal)),
                ("hist_value", tex(&r[0])),
                ("hist_noise", tex(&r[1])),
                ("hist_surface", tex(&r[2])),
                ("out_tex", tex(inputs.output)),
                ("next_value", tex(&w[0])),
                ("next_noise", tex(&w[1])),
                ("next_surface", tex(&w[2])),
            ];
            if let Some(m) = inputs.motion {
                res.push(("motion_tex", tex(m)));
            }
            layout.group(gpu, 0, &res)
        });
        self.previous = Some(*view);
        self.current = write;
        let groups = [self.desc.width.div_ceil(TILE), self.desc.height.div_ceil(TILE), 1];
        Ok((uploads, Dispatch::new(Stage::Temporal, &self.pipeline, group, Some(0), groups)))
    }
}
