//! What the pass tests play the engine with: textures made, filled and
//! read back through the engine's own device calls.

use slc_wgpu::GpuContext;

/// A single-sampled 2-D texture of `w × h`.
pub fn texture(
    gpu: &GpuContext,
    label: &str,
    (w, h): (u32, u32),
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    gpu.device.create_texture(&wgpu::TextureDescriptor {
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

/// A view of an `Rgba32Float` texture holding `texels` (row-major).
pub fn upload(
    gpu: &GpuContext,
    label: &str,
    size: (u32, u32),
    texels: &[[f32; 4]],
) -> wgpu::TextureView {
    let t = texture(
        gpu,
        label,
        size,
        wgpu::TextureFormat::Rgba32Float,
        wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
    );
    gpu.queue.write_texture(
        t.as_image_copy(),
        bytemuck::cast_slice(texels),
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(size.0 * 16),
            rows_per_image: None,
        },
        wgpu::Extent3d { width: size.0, height: size.1, depth_or_array_layers: 1 },
    );
    t.create_view(&Default::default())
}

/// An `Rgba32Float` storage texture with `COPY_SRC`, for a pass's output.
pub fn output(gpu: &GpuContext, size: (u32, u32)) -> wgpu::Texture {
    texture(
        gpu,
        "output",
        size,
        wgpu::TextureFormat::Rgba32Float,
        wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
    )
}

/// Appends the copy of `Rgba32Float` texture `t` (width a multiple of 16
/// texels) to `enc`, submits it and reads the texels back.
pub fn submit_and_read(
    gpu: &GpuContext,
    mut enc: wgpu::CommandEncoder,
    t: &wgpu::Texture,
) -> Vec<[f32; 4]> {
    let (w, h) = (t.width(), t.height());
    assert_eq!(
        (w * 16) % wgpu::COPY_BYTES_PER_ROW_ALIGNMENT,
        0,
        "read-back rows must be 256-byte aligned"
    );
    let staging = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("staging"),
        size: (w * h * 16) as u64,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
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
    gpu.queue.submit([enc.finish()]);
    let slice = staging.slice(..);
    slice.map_async(wgpu::MapMode::Read, |_| {});
    gpu.wait().expect("device");
    let data: Vec<[f32; 4]> =
        bytemuck::cast_slice(&slice.get_mapped_range().expect("mapped")).to_vec();
    data
}

/// A storage buffer holding `materials` (a glossy indirect pass's table).
pub fn materials(gpu: &GpuContext, materials: &[slc_wgpu::passes::GpuMaterial]) -> wgpu::Buffer {
    use wgpu::util::DeviceExt;
    gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("materials"),
        contents: bytemuck::cast_slice(materials),
        usage: wgpu::BufferUsages::STORAGE,
    })
}

/// Bytes per padded row of a read-back of `Rgba32Float` texture `t`.
fn padded_row(t: &wgpu::Texture) -> u32 {
    (t.width() * 16).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
}

/// A mappable buffer for [`read_via`] of `Rgba32Float` texture `t` (any
/// width: rows padded to the copy alignment).
pub fn staging(gpu: &GpuContext, t: &wgpu::Texture) -> wgpu::Buffer {
    gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("staging"),
        size: padded_row(t) as u64 * t.height() as u64,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

/// Reads `Rgba32Float` texture `t` back through `staging` (a [`staging`]
/// buffer of `t`, kept by a caller that reads back every frame), once the
/// work submitted before has run.
pub fn read_via(
    gpu: &GpuContext,
    t: &wgpu::Texture,
    staging: &wgpu::Buffer,
) -> Result<Vec<[f32; 4]>, slc_wgpu::GpuError> {
    let (w, h, row) = (t.width() as usize, t.height(), padded_row(t));
    let mut enc = gpu
        .device
        .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("read back") });
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
    let bytes =
        slice.get_mapped_range().map_err(|e| slc_wgpu::GpuError::Device(e.to_string()))?.to_vec();
    staging.unmap();
    Ok(bytes
        .chunks_exact(row as usize)
        .flat_map(|r| bytemuck::pod_collect_to_vec::<u8, [f32; 4]>(&r[..w * 16]))
        .take(w * h as usize)
        .collect())
}

/// [`read_via`] through a buffer made for the call.
pub fn read(gpu: &GpuContext, t: &wgpu::Texture) -> Result<Vec<[f32; 4]>, slc_wgpu::GpuError> {
    read_via(gpu, t, &staging(gpu, t))
}

/// A scene's ray-cast G-buffer (slc-cpu's) uploaded as an engine's
/// position and normal textures (`Rgba32Float`; position `w` = 1 where a
/// surface is), with the CPU copy the tests compare against.
pub struct UploadedGBuffer {
    /// World positions.
    pub position: wgpu::TextureView,
    /// World unit normals.
    pub normal: wgpu::TextureView,
    /// The CPU's G-buffer.
    pub cpu: slc_scene::vpl::GBuffer,
}

/// [`UploadedGBuffer`] of `scene` at `w × h` (its own camera).
pub fn upload_gbuffer(
    gpu: &GpuContext,
    scene: &slc_scene::scene::Scene,
    (w, h): (u32, u32),
) -> UploadedGBuffer {
    let ctx = slc_cpu::vpl::VplContext::new(scene, w, h, 8, None).expect("a valid scene");
    let gb = ctx.gbuffer();
    let pos: Vec<[f32; 4]> = (0..gb.position.len())
        .map(|i| gb.position[i].extend(if gb.valid(i) { 1.0 } else { 0.0 }).to_array())
        .collect();
    let nrm: Vec<[f32; 4]> = gb.normal.iter().map(|n| n.extend(0.0).to_array()).collect();
    UploadedGBuffer {
        position: upload(gpu, "gb position", (w, h), &pos),
        normal: upload(gpu, "gb normal", (w, h), &nrm),
        cpu: gb.clone(),
    }
}
