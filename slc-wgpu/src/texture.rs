//! Textures the crate makes, binds and reads back: a [`Target`] (texture and
//! view), `Rgba32Float` uploads, and read-backs of `Rgba32Float` and
//! `Rgba16Float` textures with rows padded to the copy alignment.

use crate::kernel::zeroed;
use crate::{GpuContext, GpuError};

/// HDR colour targets and read-backs.
pub(crate) const F32: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;
/// The RSM's normals.
pub(crate) const F16: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;
/// The shadow map's depth.
pub(crate) const R32: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;
/// Depth attachments.
pub(crate) const DEPTH: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// A texture and its whole view.
pub(crate) struct Target {
    /// The texture.
    pub(crate) texture: wgpu::Texture,
    /// Its view (mip 0, every layer, its own format).
    pub(crate) view: wgpu::TextureView,
}

/// A single-sampled 2-D texture of `w × h` and its view.
pub(crate) fn target(
    gpu: &GpuContext,
    label: &str,
    (w, h): (u32, u32),
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> Target {
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    });
    let view = texture.create_view(&Default::default());
    Target { texture, view }
}

/// `t`'s view as a binding.
pub(crate) fn tex(t: &Target) -> wgpu::BindingResource<'_> {
    wgpu::BindingResource::TextureView(&t.view)
}

/// Bytes per texel and per padded row of a read-back of `t`
/// (`Rgba32Float` or `Rgba16Float`).
pub(crate) fn readback_rows(t: &wgpu::Texture) -> Result<(u32, u32), GpuError> {
    let texel = match t.format() {
        F32 => 16,
        F16 => 8,
        f => return Err(GpuError::Setting(format!("cannot read back {f:?}"))),
    };
    let row = (t.width() * texel).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
        * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
    Ok((texel, row))
}

/// A mappable buffer for [`read_texture_via`] of `t` (an `Rgba32Float` or
/// `Rgba16Float` texture; rows padded to the copy alignment).
pub(crate) fn texture_staging(gpu: &GpuContext, t: &wgpu::Texture) -> wgpu::Buffer {
    let row = readback_rows(t).map_or(16 * t.width(), |(_, row)| row);
    zeroed(
        gpu,
        "slc texture readback",
        row as u64 * t.height() as u64,
        wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
    )
}

/// Reads an `Rgba32Float` or `Rgba16Float` texture back as `[f32; 4]` per
/// texel (rows padded to the copy alignment on the GPU side).
pub(crate) fn read_texture(gpu: &GpuContext, t: &wgpu::Texture) -> Result<Vec<[f32; 4]>, GpuError> {
    read_texture_via(gpu, t, &texture_staging(gpu, t))
}

/// [`read_texture`] through `staging`, a [`texture_staging`] buffer of `t`
/// (kept by a caller that reads back every frame).
pub(crate) fn read_texture_via(
    gpu: &GpuContext,
    t: &wgpu::Texture,
    staging: &wgpu::Buffer,
) -> Result<Vec<[f32; 4]>, GpuError> {
    let (w, h) = (t.width(), t.height());
    let (texel, row) = readback_rows(t)?;
    if staging.size() < row as u64 * h as u64 {
        return Err(GpuError::Setting(format!(
            "a read-back buffer of {} bytes for {} rows of {row}",
            staging.size(),
            h
        )));
    }
    let mut enc = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("slc texture readback"),
    });
    enc.copy_texture_to_buffer(
        t.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: staging,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(row),
                rows_per_image: None,
            },
        },
        t.size(),
    );
    gpu.queue.submit([enc.finish()]);
    let slice = staging.slice(..);
    slice.map_async(wgpu::MapMode::Read, |_| {});
    gpu.wait()?;
    let bytes = slice.get_mapped_range().map_err(|e| GpuError::Device(e.to_string()))?.to_vec();
    staging.unmap();
    let mut out = Vec::with_capacity((w * h) as usize);
    for y in 0..h as usize {
        let r = &bytes[y * row as usize..y * row as usize + (w * texel) as usize];
        if texel == 16 {
            out.extend(bytemuck::pod_collect_to_vec::<u8, [f32; 4]>(r));
        } else {
            let halves: Vec<u16> = bytemuck::pod_collect_to_vec(r);
            out.extend(
                halves
                    .chunks_exact(4)
                    .map(|c| [0, 1, 2, 3].map(|k| half::f16::from_bits(c[k]).to_f32())),
            );
        }
    }
    Ok(out)
}
