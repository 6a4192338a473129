//! Buffers, bind-group layouts and pipelines for the generated kernels,
//! following the binding tables of slc-shared-shaders (binding 0 a uniform,
//! then the read-only storage buffers, then the read-write ones; group 1 the
//! IES table `slc_table`).

use crate::{GpuContext, GpuError};
use slc_shared_shaders::bindings::{Binding, Resource, bindings, counts};
use slc_shared_shaders::{Features, Kernel, generate};
use wgpu::util::DeviceExt;

/// Checks, before anything is created on the device, that each kernel's
/// bindings fit the device's per-stage limits (with `extra` storage
/// buffers in a group the caller adds, the path tracer's tables), and that
/// its workgroup fits.
pub(crate) fn check_kernels(
    gpu: &GpuContext,
    kernels: &[(Kernel, &Features, u32)],
) -> Result<(), GpuError> {
    let lim = &gpu.limits;
    for &(kernel, f, extra) in kernels {
        let c = counts(&bindings(kernel, f));
        let n = |what: &str| format!("{what} ({})", kernel.name());
        gpu.require(
            n("max_storage_buffers_per_shader_stage"),
            (c.storage_buffers + extra) as u64,
            lim.max_storage_buffers_per_shader_stage as u64,
        )?;
        gpu.require(
            n("max_uniform_buffers_per_shader_stage"),
            c.uniform_buffers as u64,
            lim.max_uniform_buffers_per_shader_stage as u64,
        )?;
        gpu.require(
            n("max_dynamic_uniform_buffers_per_pipeline_layout"),
            c.dynamic_uniform_buffers as u64,
            lim.max_dynamic_uniform_buffers_per_pipeline_layout as u64,
        )?;
        gpu.require(
            n("max_sampled_textures_per_shader_stage"),
            c.sampled_textures as u64,
            lim.max_sampled_textures_per_shader_stage as u64,
        )?;
        gpu.require(
            n("max_storage_textures_per_shader_stage"),
            c.storage_textures as u64,
            lim.max_storage_textures_per_shader_stage as u64,
        )?;
        gpu.require(
            n("max_bind_groups"),
            c.bind_groups.max(1 + (extra > 0) as u32) as u64,
            lim.max_bind_groups as u64,
        )?;
        let wg = match kernel {
            Kernel::LightUpdate
            | Kernel::LightRanges
            | Kernel::BshRefit
            | Kernel::BshTail
            | Kernel::BshGrid
            | Kernel::BshReservoir
            | Kernel::PtConnect
            | Kernel::PtExtend => (f.workgroup_size, 1),
            Kernel::VplPack | Kernel::VplClusters | Kernel::VplGroups => {
                (slc_core::cluster::CLUSTER, 1)
            }
            Kernel::SceneRaster => (1, 1),
            _ => (f.tile_size, f.tile_size),
        };
        gpu.require(
            n("max_compute_workgroup_size_x"),
            wg.0 as u64,
            lim.max_compute_workgroup_size_x as u64,
        )?;
        gpu.require(
            n("max_compute_workgroup_size_y"),
            wg.1 as u64,
            lim.max_compute_workgroup_size_y as u64,
        )?;
        gpu.require(
            n("max_compute_invocations_per_workgroup"),
            (wg.0 * wg.1) as u64,
            lim.max_compute_invocations_per_workgroup as u64,
        )?;
    }
    Ok(())
}

/// A kernel's bind-group layouts, made from its binding table
/// ([`slc_shared_shaders::bindings`]): one per group (an empty one for a
/// group without bound entries), and bind groups filled by binding name.
pub(crate) struct KernelLayout {
    kernel: Kernel,
    table: Vec<Binding>,
    groups: Vec<wgpu::BindGroupLayout>,
}

impl KernelLayout {
    /// The layouts of `kernel` for `features`, visible to compute (checks
    /// the kernel's limits first).
    pub(crate) fn new(
        gpu: &GpuContext,
        kernel: Kernel,
        features: &Features,
    ) -> Result<KernelLayout, GpuError> {
        KernelLayout::with_visibility(gpu, kernel, features, wgpu::ShaderStages::COMPUTE)
    }

    /// [`KernelLayout::new`] for the shader stages `visibility`.
    pub(crate) fn with_visibility(
        gpu: &GpuContext,
        kernel: Kernel,
        features: &Features,
        visibility: wgpu::ShaderStages,
    ) -> Result<KernelLayout, GpuError> {
        check_kernels(gpu, &[(kernel, features, 0)])?;
        let table = bindings(kernel, features);
        let n_groups = table.iter().filter(|b| b.bound).map(|b| b.group + 1).max().unwrap_or(0);
        let groups = (0..n_groups)
            .map(|g| {
                let kinds: Vec<(u32, B)> = table
                    .iter()
                    .filter(|b| b.bound && b.group == g)
                    .map(|b| {
                        let kind = match b.resource {
                            Resource::Uniform { dynamic: true, .. } => B::DynamicUniform,
                            Resource::Uniform { dynamic: false, .. } => B::Uniform,
                            Resource::Read(_) => B::Read,
                            Resource::ReadWrite(_) => B::Write,
                            Resource::Texture => B::Texture,
                            Resource::DepthTexture => B::Depth,
                            Resource::StorageTexture(f) => B::Storage(match f {
                                slc_shared_shaders::OutputFormat::Rgba16Float => {
                                    wgpu::TextureFormat::Rgba16Float
                                }
                                slc_shared_shaders::OutputFormat::Rgba32Float => {
                                    wgpu::TextureFormat::Rgba32Float
                                }
                            }),
                            Resource::AccelerationStructure => B::AccelerationStructure,
                        };
                        (b.binding, kind)
                    })
                    .collect();
                layout_for(gpu, &format!("{} group {g}", kernel.name()), &kinds, visibility)
            })
            .collect();
        Ok(KernelLayout { kernel, table, groups })
    }

    /// Whether the kernel binds a resource called `name`.
    pub(crate) fn binds(&self, name: &str) -> bool {
        self.table.iter().any(|b| b.bound && b.name == name)
    }

    /// Group `g`'s layout.
    pub(crate) fn group_layout(&self, g: usize) -> &wgpu::BindGroupLayout {
        &self.groups[g]
    }

    /// The compute pipeline of the kernel generated for `features` over
    /// these layouts; `group1` replaces group 1 (the path tracer's tables).
    pub(crate) fn pipeline(
        &self,
        gpu: &GpuContext,
        features: &Features,
        group1: Option<&wgpu::BindGroupLayout>,
    ) -> Result<wgpu::ComputePipeline, GpuError> {
        let mut layouts: Vec<&wgpu::BindGroupLayout> = self.groups.iter().collect();
        if let Some(g1) = group1 {
            if layouts.len() > 1 {
                layouts[1] = g1;
            } else {
                layouts.push(g1);
            }
        }
        Ok(pipeline(gpu, self.kernel.name(), generate(self.kernel, features)?, &layouts))
    }

    /// A bind group of group `g` with `res` bound by the table's names.
    ///
    /// # Panics
    /// When a name is not one of the group's bound entries or one is
    /// missing: a mismatch between slc-wgpu and the kernel's table (a bug,
    /// never input).
    pub(crate) fn group(
        &self,
        gpu: &GpuContext,
        g: u32,
        res: &[(&str, wgpu::BindingResource)],
    ) -> wgpu::BindGroup {
        let wanted: Vec<&Binding> = self.table.iter().filter(|b| b.bound && b.group == g).collect();
        let entries: Vec<wgpu::BindGroupEntry> = res
            .iter()
            .map(|(name, r)| {
                let b = wanted.iter().find(|b| b.name == *name).unwrap_or_else(|| {
                    panic!("{} group {g} has no bound binding {name}", self.kernel.name())
                });
                wgpu::BindGroupEntry { binding: b.binding, resource: r.clone() }
            })
            .collect();
        assert_eq!(
            entries.len(),
            wanted.len(),
            "{} group {g}: {} of {} bindings given",
            self.kernel.name(),
            entries.len(),
            wanted.len()
        );
        gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(self.kernel.name()),
            layout: &self.groups[g as usize],
            entries: &entries,
        })
    }
}

/// A storage buffer initialised with `bytes` (at least 4 bytes are
/// allocated: a binding cannot be empty).
pub(crate) fn storage(
    gpu: &GpuContext,
    label: &str,
    bytes: &[u8],
    extra: wgpu::BufferUsages,
) -> wgpu::Buffer {
    let zero = [0u8; 4];
    gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some(label),
        contents: if bytes.is_empty() { &zero } else { bytes },
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST | extra,
    })
}

/// A zeroed buffer of `size` bytes (at least 4).
pub(crate) fn zeroed(
    gpu: &GpuContext,
    label: &str,
    size: u64,
    usage: wgpu::BufferUsages,
) -> wgpu::Buffer {
    gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: size.max(4),
        usage,
        mapped_at_creation: false,
    })
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
    /// `texture_depth_2d`.
    Depth,
    /// `texture_storage_2d<format, write>`.
    Storage(wgpu::TextureFormat),
    /// `acceleration_structure` (a TLAS for ray queries).
    AccelerationStructure,
}

/// A bind-group layout with the given `(binding, kind)` entries, visible
/// to the shader stages `visibility`.
pub(crate) fn layout_for(
    gpu: &GpuContext,
    label: &str,
    kinds: &[(u32, B)],
    visibility: wgpu::ShaderStages,
) -> wgpu::BindGroupLayout {
    let entries: Vec<wgpu::BindGroupLayoutEntry> = kinds
        .iter()
        .map(|&(binding, kind)| {
            let buffer = |ty, has_dynamic_offset| wgpu::BindingType::Buffer {
                ty,
                has_dynamic_offset,
                min_binding_size: None,
            };
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
                B::Depth => wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Depth,
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
                B::Storage(format) => wgpu::BindingType::StorageTexture {
                    access: wgpu::StorageTextureAccess::WriteOnly,
                    format,
                    view_dimension: wgpu::TextureViewDimension::D2,
                },
                B::AccelerationStructure => {
                    wgpu::BindingType::AccelerationStructure { vertex_return: false }
                }
            };
            wgpu::BindGroupLayoutEntry { binding, visibility, ty, count: None }
        })
        .collect();
    gpu.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries: &entries,
    })
}

/// A compute pipeline for generated WGSL with the given bind-group layouts.
pub(crate) fn pipeline(
    gpu: &GpuContext,
    label: &str,
    wgsl: String,
    layouts: &[&wgpu::BindGroupLayout],
) -> wgpu::ComputePipeline {
    let module = gpu.device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(wgsl.into()),
    });
    let layouts: Vec<Option<&wgpu::BindGroupLayout>> = layouts.iter().map(|l| Some(*l)).collect();
    let pl = gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(label),
        bind_group_layouts: &layouts,
        immediate_size: 0,
    });
    gpu.device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(label),
        layout: Some(&pl),
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    })
}

/// The whole of `b` as a binding.
pub(crate) fn whole(b: &wgpu::Buffer) -> wgpu::BindingResource<'_> {
    b.as_entire_binding()
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
        let buffer = zeroed(
            gpu,
            label,
            stride * slots.max(1),
            wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        );
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

    /// The slots' buffer as a binding of one slot (bound with a dynamic
    /// offset).
    pub(crate) fn binding(&self) -> wgpu::BindingResource<'_> {
        wgpu::BindingResource::Buffer(wgpu::BufferBinding {
            buffer: &self.buffer,
            offset: 0,
            size: wgpu::BufferSize::new(self.size),
        })
    }
}

/// Reads a whole buffer back through a mappable staging buffer.
pub(crate) fn read_back<T: bytemuck::Pod>(
    gpu: &GpuContext,
    src: &wgpu::Buffer,
    staging: &wgpu::Buffer,
) -> Result<Vec<T>, GpuError> {
    let mut enc = gpu
        .device
        .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("readback") });
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
