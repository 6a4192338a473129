//! Passes an engine records into its own command encoder.
//!
//! The engine owns the device, the queue, the frame graph and the G-buffer.
//! It wraps its device once ([`GpuContext::from_device`]: no adapter is
//! requested, no error handler is installed), builds the passes it needs
//! for its image size, and each frame calls their `record` with its own
//! `CommandEncoder`: a pass records compute work only, submits nothing and
//! reads nothing back.
//!
//! - [`IndirectPass`] ([`indirect`]): SLC indirect light from VPLs (an RSM
//!   or a VPL buffer) on the engine's G-buffer.
//! - [`DirectPass`] ([`direct`]): SLC direct light from many point, spot,
//!   IES and triangle lights on the engine's G-buffer.
//!
//! Each pass documents the textures it expects; a wrong format, size or
//! usage is a [`GpuError::Binding`] before anything is recorded, and a limit
//! the device lacks a [`GpuError::Limit`] when the pass is built. A pass
//! keeps its intermediate buffers and writes its per-frame uniforms through
//! the queue: record it once per submission.

pub mod direct;
pub mod indirect;

pub use direct::{DirectFrame, DirectInputs, DirectPass, DirectPassDesc};
pub use indirect::{IndirectFrame, IndirectInputs, IndirectPass, IndirectPassDesc, VplInput, VplSourceDesc, vpl_buffer};
pub use slc_shared_shaders::layout::GpuVplRecord;

#[cfg(doc)]
use crate::GpuContext;
use crate::GpuError;

/// The float formats the passes read G-buffer and RSM textures in.
pub(crate) const FLOAT_INPUTS: [wgpu::TextureFormat; 2] = [wgpu::TextureFormat::Rgba32Float, wgpu::TextureFormat::Rgba16Float];

/// Checks that `view` shows a `w × h` 2-D texture of an accepted format with
/// `usage`.
pub(crate) fn check_view(
    name: &'static str,
    view: &wgpu::TextureView,
    (w, h): (u32, u32),
    formats: &[wgpu::TextureFormat],
    usage: wgpu::TextureUsages,
) -> Result<(), GpuError> {
    let t = view.texture();
    let bad = |expected: String, found: String| Err(GpuError::Binding { name, expected, found });
    if !formats.contains(&t.format()) {
        return bad(format!("format {}", formats.iter().map(|f| format!("{f:?}")).collect::<Vec<_>>().join(" or ")), format!("{:?}", t.format()));
    }
    if t.dimension() != wgpu::TextureDimension::D2 || t.width() != w || t.height() != h || t.depth_or_array_layers() != 1 || t.sample_count() != 1 {
        return bad(
            format!("a single-sampled 2-D texture of {w}×{h}"),
            format!("{:?} {}×{}×{}, {} samples", t.dimension(), t.width(), t.height(), t.depth_or_array_layers(), t.sample_count()),
        );
    }
    if !t.usage().contains(usage) {
        return bad(format!("usage including {usage:?}"), format!("{:?}", t.usage()));
    }
    Ok(())
}

/// Checks an engine's G-buffer views: position and normal, `size`, a float
/// format, `TEXTURE_BINDING`.
pub(crate) fn check_gbuffer(position: &wgpu::TextureView, normal: &wgpu::TextureView, size: (u32, u32)) -> Result<(), GpuError> {
    let tex = wgpu::TextureUsages::TEXTURE_BINDING;
    check_view("G-buffer position", position, size, &FLOAT_INPUTS, tex)?;
    check_view("G-buffer normal", normal, size, &FLOAT_INPUTS, tex)
}

/// The kernels' output format for a pass's `output_format`:
/// `Rgba16Float` or `Rgba32Float`, else a [`GpuError::Binding`].
pub(crate) fn output_format(f: wgpu::TextureFormat) -> Result<slc_shared_shaders::OutputFormat, GpuError> {
    match f {
        wgpu::TextureFormat::Rgba16Float => Ok(slc_shared_shaders::OutputFormat::Rgba16Float),
        wgpu::TextureFormat::Rgba32Float => Ok(slc_shared_shaders::OutputFormat::Rgba32Float),
        f => Err(GpuError::Binding { name: "output_format", expected: "Rgba16Float or Rgba32Float".into(), found: format!("{f:?}") }),
    }
}

/// One recorded dispatch of a pass: its stage name, pipeline, bind group
/// (group 0) and workgroup counts.
pub(crate) struct Dispatch<'a> {
    pub(crate) stage: &'static str,
    pipeline: &'a wgpu::ComputePipeline,
    group: wgpu::BindGroup,
    groups: [u32; 3],
}

impl<'a> Dispatch<'a> {
    /// Records the dispatch into `pass`.
    pub(crate) fn record(&self, pass: &mut wgpu::ComputePass) {
        pass.set_pipeline(self.pipeline);
        pass.set_bind_group(0, &self.group, &[]);
        pass.dispatch_workgroups(self.groups[0], self.groups[1], self.groups[2]);
    }

    /// A dispatch of `pipeline` with `group` over `groups` workgroups.
    pub(crate) fn new(stage: &'static str, pipeline: &'a wgpu::ComputePipeline, group: wgpu::BindGroup, groups: [u32; 3]) -> Self {
        Dispatch { stage, pipeline, group, groups }
    }
}
