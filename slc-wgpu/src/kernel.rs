//! Buffers, bind-group layouts and pipelines for the generated kernels,
//! following the binding tables of slc-shared-shaders (binding 0 a uniform,
//! then the read-only storage buffers, then the read-write ones; group 1 the
//! IES table `slc_table`).

use crate::GpuContext;
use wgpu::util::DeviceExt;

/// A storage buffer initialised with `bytes` (at least 4 bytes are
/// allocated: a binding cannot be empty).
pub(crate) fn storage(gpu: &GpuContext, label: &str, bytes: &[u8], extra: wgpu::BufferUsages) -> wgpu::Buffer {
    let zero = [0u8; 4];
    gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some(label),
        contents: if bytes.is_empty() { &zero } else { bytes },
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST | extra,
    })
}

/// A zeroed buffer of `size` bytes (at least 4).
pub(crate) fn zeroed(gpu: &GpuContext, label: &str, size: u64, usage: wgpu::BufferUsages) -> wgpu::Buffer {
    gpu.device.create_buffer(&wgpu::BufferDescriptor { label: Some(label), size: size.max(4), usage, mapped_at_creation: false })
}

/// Bind-group layout of a kernel from its binding table: binding 0 a
/// uniform (with a dynamic offset when `dynamic`), then `reads` read-only
/// storage buffers, then `writes` read-write ones. Explicit, because an
/// automatic layout drops the bindings a variant does not use.
pub(crate) fn bind_layout(gpu: &GpuContext, label: &str, reads: u32, writes: u32, dynamic: bool) -> wgpu::BindGroupLayout {
    let mut kinds = vec![(0, if dynamic { B::DynamicUniform } else { B::Uniform })];
    kinds.extend((1..=reads).map(|b| (b, B::Read)));
    kinds.extend((reads + 1..=reads + writes).map(|b| (b, B::Write)));
    layout(gpu, label, &kinds)
}

/// A binding of a kernel's bind-group layout.
#[derive(Clone, Copy)]
pub(crate) enum B {
    /// `var<uniform>`.
    Uniform,
    /// `var<uniform>` bound with a dynamic offset.
    DynamicUniform,
    /// `var<storage, read>`.
    Read,
    /// `var<storage, read_write>`.
    Write,
    /// `texture_2d<f32>` (unfilterable float).
    Texture,
    /// `texture_storage_2d<format, write>`.
    Storage(wgpu::TextureFormat),
}

/// A compute bind-group layout with the given `(binding, kind)` entries.
pub(crate) fn layout(gpu: &GpuContext, label: &str, kinds: &[(u32, B)]) -> wgpu::BindGroupLayout {
    layout_for(gpu, label, kinds, wgpu::ShaderStages::COMPUTE)
}

/// [`layout`] for the shader stages `visibility` (raster passes).
pub(crate) fn layout_for(gpu: &GpuContext, label: &str, kinds: &[(u32, B)], visibility: wgpu::ShaderStages) -> wgpu::BindGroupLayout {
    let entries: Vec<wgpu::BindGroupLayoutEntry> = kinds
        .iter()
        .map(|&(binding, kind)| {
            let buffer = |ty, has_dynamic_offset| wgpu::BindingType::Buffer { ty, has_dynamic_offset, min_binding_size: None };
            let ty = match kind {
                B::Uniform => buffer(wgpu::BufferBindingType::Uniform, false),
                B::DynamicUniform => buffer(wgpu::BufferBindingType::Uniform, true),
                B::Read => buffer(wgpu::BufferBindingType::Storage { read_only: true }, false),
                B::Write => buffer(wgpu::BufferBindingType::Storage { read_only: false }, false),
                B::Texture => wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: false },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
                B::Storage(format) => wgpu::BindingType::StorageTexture {
                    access: wgpu::StorageTextureAccess::WriteOnly,
                    format,
                    view_dimension: wgpu::TextureViewDimension::D2,
                },
            };
            wgpu::BindGroupLayoutEntry { binding, visibility, ty, count: None }
        })
        .collect();
    gpu.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: Some(label), entries: &entries })
}

/// A compute pipeline for generated WGSL with the given bind-group layouts.
pub(crate) fn pipeline(gpu: &GpuContext, label: &str, wgsl: String, layouts: &[&wgpu::BindGroupLayout]) -> wgpu::ComputePipeline {
    let module = gpu.device.create_shader_module(wgpu::ShaderModuleDescriptor { label: Some(label), source: wgpu::ShaderSource::Wgsl(wgsl.into()) });
    let layouts: Vec<Option<&wgpu::BindGroupLayout>> = layouts.iter().map(|l| Some(*l)).collect();
    let pl =
        gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor { label: Some(label), bind_group_layouts: &layouts, immediate_size: 0 });
    gpu.device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(label),
        layout: Some(&pl),
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    })
}

/// A bind group binding `bufs` in order; the first (the uniform) is bound
/// as a `uniform_size`-byte window when given (dynamic offsets), else whole.
pub(crate) fn bind_group(
    gpu: &GpuContext,
    label: &str,
    layout: &wgpu::BindGroupLayout,
    bufs: &[&wgpu::Buffer],
    uniform_size: Option<u64>,
) -> wgpu::BindGroup {
    let entries: Vec<wgpu::BindGroupEntry> = bufs
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let resource = match (i, uniform_size) {
                (0, Some(size)) => wgpu::BindingResource::Buffer(wgpu::BufferBinding { buffer: b, offset: 0, size: wgpu::BufferSize::new(size) }),
                _ => b.as_entire_binding(),
            };
            wgpu::BindGroupEntry { binding: i as u32, resource }
        })
        .collect();
    gpu.device.create_bind_group(&wgpu::BindGroupDescriptor { label: Some(label), layout, entries: &entries })
}

/// The whole of `b` as a binding.
pub(crate) fn whole(b: &wgpu::Buffer) -> wgpu::BindingResource<'_> {
    b.as_entire_binding()
}

/// A bind group with the given `(binding, resource)` entries.
pub(crate) fn group(gpu: &GpuContext, label: &str, layout: &wgpu::BindGroupLayout, res: &[(u32, wgpu::BindingResource)]) -> wgpu::BindGroup {
    let entries: Vec<wgpu::BindGroupEntry> = res.iter().map(|(binding, r)| wgpu::BindGroupEntry { binding: *binding, resource: r.clone() }).collect();
    gpu.device.create_bind_group(&wgpu::BindGroupDescriptor { label: Some(label), layout, entries: &entries })
}

/// Uniform slots at the device's dynamic-offset alignment: slot `i` of a
/// `T` lives at `i · stride`.
pub(crate) struct UniformSlots {
    pub(crate) buffer: wgpu::Buffer,
    pub(crate) stride: u64,
    pub(crate) size: u64,
}

impl UniformSlots {
    pub(crate) fn new<T: bytemuck::Pod>(gpu: &GpuContext, label: &str, slots: u64) -> UniformSlots {
        let size = std::mem::size_of::<T>() as u64;
        let align = gpu.limits.min_uniform_buffer_offset_alignment.max(1) as u64;
        let stride = size.div_ceil(align) * align;
        let buffer = zeroed(gpu, label, stride * slots.max(1), wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST);
        UniformSlots { buffer, stride, size }
    }

    /// Writes `values` into slots 0, 1, … (staged until the next submit).
    pub(crate) fn write<T: bytemuck::Pod>(&self, gpu: &GpuContext, values: &[T]) {
        let mut bytes = vec![0u8; (self.stride * values.len() as u64) as usize];
        for (i, v) in values.iter().enumerate() {
            let at = i * self.stride as usize;
            bytes[at..at + self.size as usize].copy_from_slice(bytemuck::bytes_of(v));
        }
        gpu.queue.write_buffer(&self.buffer, 0, &bytes);
    }

    /// Dynamic offset of slot `i`.
    pub(crate) fn offset(&self, i: usize) -> u32 {
        (i as u64 * self.stride) as u32
    }
}

/// Reads a whole buffer back through a mappable staging buffer.
pub(crate) fn read_back<T: bytemuck::Pod>(gpu: &GpuContext, src: &wgpu::Buffer, staging: &wgpu::Buffer) -> Result<Vec<T>, crate::GpuError> {
    let mut enc = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("readback") });
    enc.copy_buffer_to_buffer(src, 0, staging, 0, staging.size());
    gpu.queue.submit([enc.finish()]);
    let slice = staging.slice(..);
    slice.map_async(wgpu::MapMode::Read, |_| {});
    gpu.wait()?;
    let data: Vec<T> = {
        let view = slice.get_mapped_range().map_err(|e| crate::GpuError::Device(e.to_string()))?;
        bytemuck::cast_slice(&view).to_vec()
    };
    staging.unmap();
    Ok(data)
}

/// GPU timestamps around compute passes, where the adapter supports them.
pub(crate) struct Timer {
    queries: wgpu::QuerySet,
    resolve: wgpu::Buffer,
    staging: wgpu::Buffer,
    capacity: u32,
    used: u32,
}

impl Timer {
    /// Room for `passes` timed passes (two queries each); `None` without
    /// timestamp support.
    pub(crate) fn new(gpu: &GpuContext, passes: u32) -> Option<Timer> {
        if !gpu.timestamps {
            return None;
        }
        let capacity = passes.clamp(1, 2048);
        let queries =
            gpu.device.create_query_set(&wgpu::QuerySetDescriptor { label: Some("slc timer"), ty: wgpu::QueryType::Timestamp, count: 2 * capacity });
        let size = 16 * capacity as u64;
        let resolve = zeroed(gpu, "timer resolve", size, wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC);
        let staging = zeroed(gpu, "timer staging", size, wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST);
        Some(Timer { queries, resolve, staging, capacity, used: 0 })
    }

    /// Timestamp writes for the next pass (none once full).
    pub(crate) fn next(&mut self) -> Option<wgpu::ComputePassTimestampWrites<'_>> {
        if self.used >= self.capacity {
            return None;
        }
        let i = self.used;
        self.used += 1;
        Some(wgpu::ComputePassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(2 * i),
            end_of_pass_write_index: Some(2 * i + 1),
        })
    }

    /// Timestamp writes for the next render pass (none once full).
    pub(crate) fn next_render(&mut self) -> Option<wgpu::RenderPassTimestampWrites<'_>> {
        let w = self.next()?;
        Some(wgpu::RenderPassTimestampWrites {
            query_set: w.query_set,
            beginning_of_pass_write_index: w.beginning_of_pass_write_index,
            end_of_pass_write_index: w.end_of_pass_write_index,
        })
    }

    /// Starts over at the first query (the next frame).
    pub(crate) fn reset(&mut self) {
        self.used = 0;
    }

    /// Resolves the queries written so far into the resolve buffer.
    pub(crate) fn resolve(&self, enc: &mut wgpu::CommandEncoder) {
        if self.used > 0 {
            enc.resolve_query_set(&self.queries, 0..2 * self.used, &self.resolve, 0);
        }
    }

    /// Each timed pass's GPU duration in ms (after [`Timer::resolve`] was
    /// submitted).
    pub(crate) fn durations_ms(&self, gpu: &GpuContext) -> Result<Vec<f64>, crate::GpuError> {
        let ticks: Vec<u64> = read_back(gpu, &self.resolve, &self.staging)?;
        let period = gpu.queue.get_timestamp_period() as f64;
        Ok(ticks.chunks(2).take(self.used as usize).map(|p| p[1].saturating_sub(p[0]) as f64 * period * 1e-6).collect())
    }

    /// Sum of the timed passes' GPU durations in ms.
    pub(crate) fn total_ms(&self, gpu: &GpuContext) -> Result<f64, crate::GpuError> {
        Ok(self.durations_ms(gpu)?.iter().sum())
    }
}
