//! A light set on the GPU with its bounding-sphere hierarchy: the lights
//! and IES table as the kernels read them, the per-pass random ranges
//! (`light_update`) and the BSH refitted to them level by level
//! (`bsh_refit`, deepest level first). Shared by the path tracer and the
//! direct-light shader.

use crate::kernel::{UniformSlots, bind_group, bind_layout, pipeline, storage, zeroed};
use crate::{GpuContext, GpuError};
use glam::Vec3;
use slc_core::bsh::{BSH_NONE, Bsh};
use slc_core::importance::LightCone;
use slc_core::light::{Light, LightBound};
use slc_core::range::RangeParams;
use slc_scene::light_bvh::LightBvh;
use slc_shared_shaders::layout::{FrameParams, GpuLightCone, RefitParams, pack_cones, pack_light_bvh, pack_lights};
use slc_shared_shaders::{Features, Kernel, LightSet, generate};

/// Workgroup size of the 1-D kernels.
pub(crate) const WG: u32 = 64;

/// The light types present in `lights`.
pub(crate) fn light_set(lights: &[Light]) -> LightSet {
    let has = |f: fn(&Light) -> bool| lights.iter().any(f);
    LightSet {
        point: has(|l| matches!(l, Light::Point(_))),
        spot: has(|l| matches!(l, Light::Spot(_))),
        ies: has(|l| matches!(l, Light::Ies(_))),
        triangle: has(|l| matches!(l, Light::Triangle(_))),
        vpl: has(|l| matches!(l, Light::Vpl(_))),
    }
}

/// BSH node indices level by level, deepest level first, and each level's
/// `(first, count)` in that list; plus each light's leaf.
fn refit_order(bsh: &Bsh, n_lights: usize) -> (Vec<u32>, Vec<(u32, u32)>, Vec<u32>) {
    let nodes = bsh.nodes();
    let mut depth = vec![0u32; nodes.len()];
    let mut leaf = vec![0u32; n_lights];
    for i in 0..nodes.len() {
        let n = &nodes[i];
        if n.child == BSH_NONE {
            leaf[n.light as usize] = i as u32;
        } else {
            let left = n.child as usize;
            depth[left] = depth[i] + 1;
            depth[nodes[left].next as usize] = depth[i] + 1;
        }
    }
    let deepest = depth.iter().copied().max().unwrap_or(0);
    let mut order = Vec::with_capacity(nodes.len());
    let mut levels = Vec::new();
    for d in (0..=deepest).rev() {
        let first = order.len() as u32;
        order.extend((0..nodes.len() as u32).filter(|&i| depth[i as usize] == d));
        levels.push((first, order.len() as u32 - first));
    }
    (order, levels, leaf)
}

/// Lights, ranges and BSH on the GPU.
pub(crate) struct GpuLightSet {
    pub(crate) n: u32,
    peaks: Vec<Vec3>,
    pub(crate) types: LightSet,
    pub(crate) lights: wgpu::Buffer,
    pub(crate) rt2: wgpu::Buffer,
    pub(crate) r2: wgpu::Buffer,
    pub(crate) bsh: wgpu::Buffer,
    /// BSH leaf of each light.
    pub(crate) leaf: wgpu::Buffer,
    levels: Vec<(u32, u32)>,
    frame_params: wgpu::Buffer,
    refit_params: UniformSlots,
    update: (wgpu::ComputePipeline, wgpu::BindGroup),
    refit: (wgpu::ComputePipeline, wgpu::BindGroup),
    /// Group 1 of every kernel: the IES table, the power alias table, the
    /// importance cones and the light BVH.
    pub(crate) table_layout: wgpu::BindGroupLayout,
    /// Group 1 with the IES table only (binding 0), for `bsh_reservoir`.
    pub(crate) ies_layout: wgpu::BindGroupLayout,
    /// Its bind group.
    pub(crate) ies_table: wgpu::BindGroup,
    pub(crate) table: wgpu::BindGroup,
}

impl GpuLightSet {
    /// Uploads `lights` (with their `bounds`, the `bsh` built over them and
    /// the path tracer's `power` alias table, importance `cones`
    /// ([`slc_scene::lights::LightSet::cones`]) and light BVH, any of which
    /// may be empty or absent) after checking the buffer and dispatch
    /// limits.
    pub(crate) fn new(
        gpu: &GpuContext,
        lights: &[Light],
        bounds: &[LightBound],
        bsh: &Bsh,
        power: &[[f32; 4]],
        cones: &[LightCone],
        light_bvh: Option<&LightBvh>,
    ) -> Result<GpuLightSet, GpuError> {
        let n = lights.len() as u64;
        let lim = &gpu.limits;
        gpu.require("max_storage_buffer_binding_size (lights)", n * 64, lim.max_storage_buffer_binding_size)?;
        gpu.require("max_compute_workgroups_per_dimension (lights)", n.div_ceil(WG as u64), lim.max_compute_workgroups_per_dimension as u64)?;
        let (order, levels, leaf) = refit_order(bsh, lights.len());
        let (gpu_lights, table) = pack_lights(lights);
        let s = |label: &str, bytes: &[u8]| storage(gpu, label, bytes, wgpu::BufferUsages::empty());
        let ids: Vec<u32> = (0..n as u32).collect();
        let extent: Vec<f32> = bounds.iter().map(|b| b.extent).collect();
        let lights_buf = s("lights", bytemuck::cast_slice(&gpu_lights));
        let table_buf = s("slc_table", bytemuck::cast_slice(&table));
        // A binding cannot be empty: a zeroed entry stands in.
        let power_buf = s("power_table", bytemuck::cast_slice(if power.is_empty() { &[[0.0f32; 4]][..] } else { power }));
        let cones = if cones.is_empty() { vec![GpuLightCone::default()] } else { pack_cones(cones, light_bvh.map_or(&[], |b| b.leaf_of_light())) };
        let cones_buf = s("light_cones", bytemuck::cast_slice(&cones));
        let bvh = pack_light_bvh(light_bvh.map_or(&[], |b| b.nodes()));
        gpu.require(
            "max_storage_buffer_binding_size (light BVH)",
            std::mem::size_of_val(bvh.as_slice()) as u64,
            lim.max_storage_buffer_binding_size,
        )?;
        let bvh_buf = s("light_bvh", bytemuck::cast_slice(&bvh));
        let ids_buf = s("ids", bytemuck::cast_slice(&ids));
        let extent_buf = s("extent", bytemuck::cast_slice(&extent));
        let rt2 = zeroed(gpu, "rt2", n * 4, wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST);
        let r2 = zeroed(gpu, "r2", n * 4, wgpu::BufferUsages::STORAGE);
        let order_buf = s("bsh order", bytemuck::cast_slice(&order));
        let bsh_buf = s("bsh nodes", bytemuck::cast_slice(bsh.nodes()));
        let leaf_buf = s("light leaf", bytemuck::cast_slice(&leaf));
        let frame_params = zeroed(gpu, "frame params", 16, wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST);
        let refit_params = UniformSlots::new::<RefitParams>(gpu, "refit params", levels.len() as u64);
        let table_layout = {
            let e = |binding| wgpu::BindGroupLayoutEntry {
                binding,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Storage { read_only: true },
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            };
            gpu.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: Some("scene tables"), entries: &[e(0), e(1), e(2), e(3)] })
        };
        // The IES table alone, for kernels that do not read the power table
        // (one storage binding fewer, within WebGPU's default 8 per stage).
        let ies_layout = gpu.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("ies table"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Storage { read_only: true },
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            }],
        });
        let ies_table = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("ies table"),
            layout: &ies_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: table_buf.as_entire_binding() }],
        });
        let table_bg = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("scene tables"),
            layout: &table_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: table_buf.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: power_buf.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 2, resource: cones_buf.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 3, resource: bvh_buf.as_entire_binding() },
            ],
        });
        let features = Features { workgroup_size: WG, ..Features::default() };
        let update_layout = bind_layout(gpu, "light_update", 2, 1, false);
        let update = (
            pipeline(gpu, "light_update", generate(Kernel::LightUpdate, &features)?, &[&update_layout, &table_layout]),
            bind_group(gpu, "light_update", &update_layout, &[&frame_params, &ids_buf, &rt2, &r2], None),
        );
        let refit_layout = bind_layout(gpu, "bsh_refit", 3, 1, true);
        let refit = (
            pipeline(gpu, "bsh_refit", generate(Kernel::BshRefit, &features)?, &[&refit_layout, &table_layout]),
            bind_group(gpu, "bsh_refit", &refit_layout, &[&refit_params.buffer, &order_buf, &extent_buf, &r2, &bsh_buf], Some(refit_params.size)),
        );
        let values: Vec<RefitParams> = levels.iter().map(|&(first, count)| RefitParams { first, count, pad0: 0, pad1: 0 }).collect();
        refit_params.write(gpu, &values);
        Ok(GpuLightSet {
            n: n as u32,
            peaks: lights.iter().map(Light::peak).collect(),
            types: light_set(lights),
            lights: lights_buf,
            rt2,
            r2,
            bsh: bsh_buf,
            leaf: leaf_buf,
            levels,
            frame_params,
            refit_params,
            update,
            refit,
            table_layout,
            ies_layout,
            ies_table,
            table: table_bg,
        })
    }

    /// Threshold ranges `r_t²` for `params` (host, the core's function),
    /// or +∞ for every light (`None`: nothing culled, p = 1).
    pub(crate) fn set_threshold(&self, gpu: &GpuContext, params: Option<&RangeParams>) {
        let rt2: Vec<f32> = self.peaks.iter().map(|&p| params.map_or(f32::INFINITY, |q| q.threshold_range2(p))).collect();
        gpu.queue.write_buffer(&self.rt2, 0, bytemuck::cast_slice(&rt2));
    }

    /// Seed and frame (pass) of the next [`GpuLightSet::encode`]d update
    /// (staged until the next submit).
    pub(crate) fn set_frame(&self, gpu: &GpuContext, seed: u32, frame: u32) {
        let f = FrameParams { light_count: self.n, seed, frame, pad: 0 };
        gpu.queue.write_buffer(&self.frame_params, 0, bytemuck::bytes_of(&f));
    }

    /// Records the range update and the BSH refit into `cp` (and binds the
    /// IES table as group 1).
    pub(crate) fn encode(&self, cp: &mut wgpu::ComputePass) {
        cp.set_bind_group(1, &self.table, &[]);
        cp.set_pipeline(&self.update.0);
        cp.set_bind_group(0, &self.update.1, &[]);
        cp.dispatch_workgroups(self.n.div_ceil(WG), 1, 1);
        cp.set_pipeline(&self.refit.0);
        for (i, &(_, count)) in self.levels.iter().enumerate() {
            cp.set_bind_group(0, &self.refit.1, &[self.refit_params.offset(i)]);
            cp.dispatch_workgroups(count.div_ceil(WG), 1, 1);
        }
    }
}
