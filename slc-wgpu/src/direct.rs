//! Direct light from many lights at arbitrary shading points on the GPU:
//! `light_update`, `bsh_refit` per level, then `bsh_reservoir` (BSH
//! traversal into a k-slot reservoir, the picks RR-tested at their sampled
//! points and weighted by `1/p · n/k`). Unshadowed, the counterpart of
//! the CPU backend's `slc_cpu::direct::DirectLights`, which draws the same
//! random numbers.

use crate::kernel::{B, group, layout, pipeline, read_back, storage, zeroed};
use crate::lights::{GpuLightSet, WG};
use crate::{GpuContext, GpuError};
use glam::Vec3;
use slc_core::range::RangeParams;
use slc_scene::lights::{DIRECT_K, Direct, LightSet};
use slc_shared_shaders::layout::ShadeParams;
use slc_shared_shaders::{Features, Kernel, generate};
use wgpu::util::DeviceExt;

/// The lights of a [`LightSet`] on the GPU and the shading pipeline.
pub struct GpuDirect<'a> {
    gpu: &'a GpuContext,
    set: GpuLightSet,
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    busy: std::sync::Mutex<()>,
}

impl<'a> GpuDirect<'a> {
    /// Uploads the lights and their BSH.
    pub fn new(gpu: &'a GpuContext, lights: &LightSet) -> Result<Self, GpuError> {
        let set = GpuLightSet::new(gpu, lights.lights(), lights.bounds(), lights.bsh(), &[], &[], None)?;
        let (pipeline, layout) = reservoir_pipeline(gpu, &set)?;
        Ok(GpuDirect { gpu, set, pipeline, layout, busy: std::sync::Mutex::new(()) })
    }

    /// Direct light at `points` (unit `normals`) for frame `frame` of
    /// `seed`, number for number as the CPU's `DirectLights::shade`.
    pub fn shade(&self, points: &[Vec3], normals: &[Vec3], params: &RangeParams, seed: u32, frame: u32) -> Result<Vec<Direct>, GpuError> {
        if points.len() != normals.len() {
            return Err(GpuError::Setting(format!("{} points but {} normals", points.len(), normals.len())));
        }
        if points.is_empty() {
            return Ok(Vec::new());
        }
        let gpu = self.gpu;
        let n = points.len() as u64;
        gpu.require("max_storage_buffer_binding_size (points)", n * 16, gpu.limits.max_storage_buffer_binding_size)?;
        gpu.require("max_compute_workgroups_per_dimension (points)", n.div_ceil(WG as u64), gpu.limits.max_compute_workgroups_per_dimension as u64)?;
        let _busy = self.busy.lock().map_err(|_| GpuError::Device("a previous call panicked".into()))?;
        // w = 1 marks a valid point; NaN coordinates are shaded as nothing, as on the CPU.
        let p4: Vec<[f32; 4]> = points.iter().map(|p| [p.x, p.y, p.z, if p.is_nan() { 0.0 } else { 1.0 }]).collect();
        let n4: Vec<[f32; 4]> = normals.iter().map(|v| [v.x, v.y, v.z, 0.0]).collect();
        let none = wgpu::BufferUsages::empty();
        let pts = storage(gpu, "points", bytemuck::cast_slice(&p4), none);
        let nrm = storage(gpu, "normals", bytemuck::cast_slice(&n4), none);
        let out = zeroed(gpu, "direct", n * 16, wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC);
        let staging = zeroed(gpu, "direct readback", n * 16, wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST);
        let sp = ShadeParams { point_count: n as u32, seed, frame, eps: 0.0 };
        let uniform = gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("shade params"),
            contents: bytemuck::bytes_of(&sp),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let s = &self.set;
        let b = crate::kernel::whole;
        let bg = group(
            gpu,
            "bsh_reservoir",
            &self.layout,
            &[(0, b(&uniform)), (1, b(&pts)), (2, b(&nrm)), (3, b(&s.lights)), (4, b(&s.rt2)), (5, b(&s.r2)), (6, b(&s.bsh)), (9, b(&out))],
        );
        s.set_threshold(gpu, Some(params));
        s.set_frame(gpu, seed, frame);
        let mut enc = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("slc direct") });
        {
            let mut cp = enc.begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("slc direct"), timestamp_writes: None });
            s.encode(&mut cp);
            cp.set_pipeline(&self.pipeline);
            cp.set_bind_group(0, &bg, &[]);
            cp.set_bind_group(1, &s.ies_table, &[]);
            cp.dispatch_workgroups((n as u32).div_ceil(WG), 1, 1);
        }
        gpu.queue.submit([enc.finish()]);
        gpu.wait()?;
        let data: Vec<[f32; 4]> = read_back(gpu, &out, &staging)?;
        Ok(data.iter().map(|d| Direct { irradiance: Vec3::new(d[0], d[1], d[2]), in_range: d[3] as u32 }).collect())
    }
}

/// The unshadowed `bsh_reservoir` pipeline for `set`'s light types with
/// [`DIRECT_K`] reservoir slots, and its group-0 layout (no occluder
/// bindings: seven storage buffers, and the IES table alone in group 1).
pub(crate) fn reservoir_pipeline(gpu: &GpuContext, set: &GpuLightSet) -> Result<(wgpu::ComputePipeline, wgpu::BindGroupLayout), GpuError> {
    gpu.require("max_storage_buffers_per_shader_stage (bsh_reservoir)", 8, gpu.limits.max_storage_buffers_per_shader_stage as u64)?;
    let features = Features { lights: set.types, reservoir_k: DIRECT_K as u32, workgroup_size: WG, shadows: false, ..Features::default() };
    let mut kinds: Vec<(u32, B)> = vec![(0, B::Uniform)];
    kinds.extend((1..=6).map(|b| (b, B::Read)));
    kinds.push((9, B::Write));
    let layout = layout(gpu, "bsh_reservoir", &kinds);
    let pipeline = pipeline(gpu, "bsh_reservoir", generate(Kernel::BshReservoir, &features)?, &[&layout, &set.ies_layout]);
    Ok((pipeline, layout))
}
