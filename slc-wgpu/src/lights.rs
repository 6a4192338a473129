//! A light set on the GPU with its bounding-sphere hierarchy: the lights
//! and IES table as the kernels read them, the per-pass random ranges
//! (`light_update`, or the direct pass's `light_ranges`) and the BSH
//! refitted to them level by level (`bsh_refit`, deepest level first, leaf
//! centres read from the lights' bounds so that moved lights refit in
//! place), after its range tail where the BSH has one (`bsh_tail`: the path
//! tracer's). Shared by the path tracer and the direct pass.

use crate::kernel::{KernelLayout, UniformSlots, check_kernels, storage, zeroed};
use crate::{GpuContext, GpuError};
use glam::Vec3;
use slc_core::bsh::{BSH_TAIL_BINS, Bsh};
use slc_core::importance::LightCone;
use slc_core::light::{Light, LightBound};
use slc_core::range::RangeParams;
use slc_core::xi::xi_keys;
use slc_scene::light_bvh::LightBvh;
use slc_shared_shaders::layout::{
    FrameParams, GpuLight, GpuLightCone, RefitParams, TailParams, pack_cones, pack_light_bvh,
    pack_lights,
};
use slc_shared_shaders::{Features, Kernel, LightTypes};

/// Workgroup size of the 1-D kernels.
pub(crate) const WG: u32 = 64;

/// BSH node indices level by level, deepest level first, and each level's
/// `(first, count)` in that list (the tree's nodes; the range tail's slots
/// after it are `bsh_tail`'s).
fn refit_order(bsh: &Bsh) -> (Vec<u32>, Vec<(u32, u32)>) {
    let depth = bsh.depths();
    let deepest = depth.iter().copied().max().unwrap_or(0);
    let mut order = Vec::with_capacity(depth.len());
    let mut levels = Vec::new();
    for d in (0..=deepest).rev() {
        let first = order.len() as u32;
        order.extend((0..depth.len() as u32).filter(|&i| depth[i as usize] == d));
        levels.push((first, order.len() as u32 - first));
    }
    (order, levels)
}

/// Each light's bound as `bsh_refit` reads it: centre (xyz), extent (w).
fn pack_bounds(bounds: &[LightBound]) -> Vec<[f32; 4]> {
    bounds.iter().map(|b| [b.center.x, b.center.y, b.center.z, b.extent]).collect()
}

/// Each light's RGB peak intensity as `light_ranges` reads it.
fn pack_peaks(lights: &[Light]) -> Vec<[f32; 4]> {
    lights.iter().map(|l| l.peak().extend(0.0).to_array()).collect()
}

/// The limits a light set of `n` lights and a light BVH of `bvh_bytes`
/// bytes need.
pub(crate) fn check_light_limits(gpu: &GpuContext, n: u64, bvh_bytes: u64) -> Result<(), GpuError> {
    let lim = &gpu.limits;
    let binding = lim.max_storage_buffer_binding_size.min(lim.max_buffer_size);
    gpu.require(
        "max_storage_buffer_binding_size (lights)",
        n * std::mem::size_of::<GpuLight>() as u64,
        binding,
    )?;
    gpu.require("max_storage_buffer_binding_size (light BVH)", bvh_bytes, binding)?;
    gpu.require(
        "max_compute_workgroups_per_dimension (lights)",
        n.div_ceil(WG as u64),
        lim.max_compute_workgroups_per_dimension as u64,
    )
}

/// A light set's buffers and bind groups (rebuilt when the count changes).
pub(crate) struct LightBuffers {
    pub(crate) n: u32,
    peaks_host: Vec<Vec3>,
    pub(crate) types: LightTypes,
    pub(crate) lights: wgpu::Buffer,
    /// The IES table (`slc_table`).
    pub(crate) table_buf: wgpu::Buffer,
    /// Each light's importance cone (`slc-weighted`).
    pub(crate) cones: wgpu::Buffer,
    /// Each light's RGB peak (`light_ranges`).
    pub(crate) peaks: wgpu::Buffer,
    pub(crate) rt2: wgpu::Buffer,
    pub(crate) r2: wgpu::Buffer,
    /// Each light's ξ key ([`slc_core::xi::xi_keys`]), `light_update`'s
    /// `ids`: the point, spot and IES lights' ξ rotate together, the area
    /// lights draw their own (the direct pass runs no update).
    keys: wgpu::Buffer,
    pub(crate) bsh: wgpu::Buffer,
    /// BSH leaf of each light.
    pub(crate) leaf: wgpu::Buffer,
    bounds: wgpu::Buffer,
    levels: Vec<(u32, u32)>,
    refit_params: UniformSlots,
    /// The range tail's length limit (0: none, `bsh_tail` not run), its
    /// four stages' uniforms and bind group.
    tail_k: u32,
    tail_params: UniformSlots,
    tail_group: wgpu::BindGroup,
    power: wgpu::Buffer,
    bvh: wgpu::Buffer,
    update_group: wgpu::BindGroup,
    refit_group: wgpu::BindGroup,
    pub(crate) table: wgpu::BindGroup,
}

/// Lights, ranges and BSH on the GPU, with the range-update and refit
/// pipelines (kept when the set is rebuilt).
pub(crate) struct GpuLightSet {
    b: LightBuffers,
    frame_params: UniformSlots,
    update: (wgpu::ComputePipeline, KernelLayout),
    refit: (wgpu::ComputePipeline, KernelLayout),
    tail: (wgpu::ComputePipeline, KernelLayout),
    /// Group 1 of the path tracer's kernels: the IES table, the power alias
    /// table, the importance cones and the light BVH.
    pub(crate) table_layout: wgpu::BindGroupLayout,
}

impl std::ops::Deref for GpuLightSet {
    type Target = LightBuffers;
    fn deref(&self) -> &LightBuffers {
        &self.b
    }
}

/// Storage buffers in the path tracer's group 1 (`table_layout`).
pub(crate) const TABLES: u32 = 4;

impl GpuLightSet {
    /// Uploads `lights` (with their `bounds`, the `bsh` built over them and
    /// the path tracer's `power` alias table, importance `cones`
    /// ([`slc_scene::lights::LightSet::cones`]) and light BVH, any of which
    /// may be empty or absent) after checking the buffer, dispatch and
    /// binding limits, and builds the range-update and refit pipelines.
    pub(crate) fn new(
        gpu: &GpuContext,
        lights: &[Light],
        bounds: &[LightBound],
        bsh: &Bsh,
        power: &[[f32; 4]],
        cones: &[LightCone],
        light_bvh: Option<&LightBvh>,
    ) -> Result<GpuLightSet, GpuError> {
        let bvh = pack_light_bvh(light_bvh.map_or(&[], |b| b.nodes()));
        check_light_limits(gpu, lights.len() as u64, std::mem::size_of_val(bvh.as_slice()) as u64)?;
        let features = Features { workgroup_size: WG, ..Features::default() };
        check_kernels(
            gpu,
            &[
                (Kernel::LightUpdate, &features, TABLES),
                (Kernel::BshRefit, &features, 0),
                (Kernel::BshTail, &features, 0),
            ],
        )?;
        let update_layout = KernelLayout::new(gpu, Kernel::LightUpdate, &features)?;
        let refit_layout = KernelLayout::new(gpu, Kernel::BshRefit, &features)?;
        let tail_layout = KernelLayout::new(gpu, Kernel::BshTail, &features)?;
        // Group 1 of the path tracer: four read-only tables.
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
            gpu.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("scene tables"),
                entries: &[e(0), e(1), e(2), e(3)],
            })
        };
        let update = update_layout.pipeline(gpu, &features, Some(&table_layout))?;
        // The refit and the tail read no table: without group 1 they stay
        // within WebGPU's default of 8 storage buffers per stage.
        let refit = refit_layout.pipeline(gpu, &features, None)?;
        let tail = tail_layout.pipeline(gpu, &features, None)?;
        let frame_params = UniformSlots::new::<FrameParams>(gpu, "frame params", 1);
        let b = LightBuffers::new(
            gpu,
            lights,
            bounds,
            bsh,
            power,
            cones,
            &bvh,
            light_bvh,
            [&update_layout, &refit_layout, &tail_layout],
            &table_layout,
            &frame_params,
        )?;
        gpu.take_errors()?;
        Ok(GpuLightSet {
            b,
            frame_params,
            update: (update, update_layout),
            refit: (refit, refit_layout),
            tail: (tail, tail_layout),
            table_layout,
        })
    }

    /// Replaces the set with `set` (any count; new buffers and bind groups,
    /// the BSH as `set` built it, the pipelines kept).
    pub(crate) fn replace(
        &mut self,
        gpu: &GpuContext,
        set: &slc_scene::lights::LightSet,
    ) -> Result<(), GpuError> {
        let layouts = [&self.update.1, &self.refit.1, &self.tail.1];
        self.b = LightBuffers::new(
            gpu,
            set.lights(),
            set.bounds(),
            set.bsh(),
            &[],
            set.cones(),
            &pack_light_bvh(&[]),
            None,
            layouts,
            &self.table_layout,
            &self.frame_params,
        )?;
        Ok(())
    }

    /// Moves, turns or recolours the lights in place: `lights` has the
    /// set's count (light `i` replaces light `i`), so the BSH keeps its
    /// topology and the next refit moves its leaves to the new centres (a
    /// valid hierarchy, looser the further the lights wandered from where
    /// it was built). Writes the lights, their bounds, peaks, cones and
    /// the IES table (a new table buffer only when its size changes).
    /// Returns whether a buffer was replaced (bind groups then need
    /// remaking).
    pub(crate) fn update(&mut self, gpu: &GpuContext, lights: &[Light]) -> Result<bool, GpuError> {
        let b = &mut self.b;
        if lights.len() != b.n as usize {
            return Err(GpuError::Setting(format!(
                "update_lights: {} lights for a set of {} (a new count needs set_lights)",
                lights.len(),
                b.n
            )));
        }
        let (gpu_lights, table) = pack_lights(lights);
        let bounds: Vec<LightBound> = lights.iter().map(Light::bound).collect();
        let powers = slc_core::light::emitted_powers(lights);
        let cones: Vec<LightCone> =
            lights.iter().zip(&powers).map(|(l, &p)| LightCone::of_light(l, p)).collect();
        let q = &gpu.queue;
        q.write_buffer(&b.lights, 0, bytemuck::cast_slice(&gpu_lights));
        q.write_buffer(&b.bounds, 0, bytemuck::cast_slice(&pack_bounds(&bounds)));
        q.write_buffer(&b.peaks, 0, bytemuck::cast_slice(&pack_peaks(lights)));
        q.write_buffer(&b.cones, 0, bytemuck::cast_slice(&pack_cones(&cones, &[])));
        q.write_buffer(&b.keys, 0, bytemuck::cast_slice(&xi_keys(lights)));
        b.peaks_host = lights.iter().map(Light::peak).collect();
        let table_bytes: &[u8] = bytemuck::cast_slice(&table);
        let replaced = table_bytes.len() as u64 != b.table_buf.size();
        if replaced {
            b.table_buf = storage(gpu, "slc_table", table_bytes, wgpu::BufferUsages::COPY_DST);
            b.table =
                table_group(gpu, &self.table_layout, [&b.table_buf, &b.power, &b.cones, &b.bvh]);
        } else {
            q.write_buffer(&b.table_buf, 0, table_bytes);
        }
        b.types = LightTypes::of(lights);
        Ok(replaced)
    }

    /// Threshold ranges `r_t²` for `params` (host, the core's function),
    /// or +∞ for every light (`None`: nothing culled, p = 1).
    pub(crate) fn set_threshold(&self, gpu: &GpuContext, params: Option<&RangeParams>) {
        let rt2: Vec<f32> = self
            .b
            .peaks_host
            .iter()
            .map(|&p| params.map_or(f32::INFINITY, |q| q.threshold_range2(p)))
            .collect();
        gpu.queue.write_buffer(&self.rt2, 0, bytemuck::cast_slice(&rt2));
    }

    /// Seed and frame (pass) of the next [`GpuLightSet::encode`]d update
    /// (staged until the next submit).
    pub(crate) fn set_frame(&self, gpu: &GpuContext, seed: u32, frame: u32) {
        self.frame_params
            .write(gpu, &[FrameParams { light_count: self.b.n, seed, frame, fixed_xi: -1.0 }]);
    }

    /// Records the range update and the BSH refit into `cp` (and binds the
    /// scene tables as group 1).
    pub(crate) fn encode(&self, cp: &mut wgpu::ComputePass) {
        self.encode_update(cp);
        self.encode_refit(cp);
    }

    /// Records the range update alone (and binds the scene tables as group
    /// 1): what a method that culls nothing needs once, its `r²` all +∞
    /// (`set_threshold(None)`), with no BSH to refit.
    pub(crate) fn encode_update(&self, cp: &mut wgpu::ComputePass) {
        self.bind_tables(cp);
        cp.set_pipeline(&self.update.0);
        cp.set_bind_group(0, &self.b.update_group, &[0]);
        cp.dispatch_workgroups(self.n.div_ceil(WG), 1, 1);
    }

    /// Binds the scene tables as group 1 of `cp`.
    pub(crate) fn bind_tables(&self, cp: &mut wgpu::ComputePass) {
        cp.set_bind_group(1, &self.table, &[]);
    }

    /// Records the BSH refit alone (the range tail's four stages where the
    /// BSH has one, then every level, deepest first), for ranges another
    /// kernel wrote (group 1, the scene tables, is left as it was bound).
    pub(crate) fn encode_refit(&self, cp: &mut wgpu::ComputePass) {
        if self.b.tail_k > 0 {
            cp.set_pipeline(&self.tail.0);
            for stage in 0..4 {
                cp.set_bind_group(0, &self.b.tail_group, &[self.b.tail_params.offset(stage)]);
                let per_light = stage == 0 || stage == 2;
                cp.dispatch_workgroups(if per_light { self.n.div_ceil(WG) } else { 1 }, 1, 1);
            }
        }
        cp.set_pipeline(&self.refit.0);
        for (i, &(_, count)) in self.b.levels.iter().enumerate() {
            cp.set_bind_group(0, &self.b.refit_group, &[self.b.refit_params.offset(i)]);
            cp.dispatch_workgroups(count.div_ceil(WG), 1, 1);
        }
    }
}

impl LightBuffers {
    /// Uploads a light set and binds it to the update, refit and table
    /// layouts.
    #[allow(clippy::too_many_arguments)]
    fn new(
        gpu: &GpuContext,
        lights: &[Light],
        bounds: &[LightBound],
        bsh: &Bsh,
        power: &[[f32; 4]],
        cones: &[LightCone],
        bvh: &[slc_shared_shaders::layout::GpuLightBvhNode],
        light_bvh: Option<&LightBvh>,
        [update, refit, tail_layout]: [&KernelLayout; 3],
        table_layout: &wgpu::BindGroupLayout,
        frame_params: &UniformSlots,
    ) -> Result<LightBuffers, GpuError> {
        check_light_limits(gpu, lights.len() as u64, std::mem::size_of_val(bvh) as u64)?;
        let n = lights.len() as u64;
        let (order, levels) = refit_order(bsh);
        let (gpu_lights, table) = pack_lights(lights);
        let dst = wgpu::BufferUsages::COPY_DST;
        let s = |label: &str, bytes: &[u8]| storage(gpu, label, bytes, wgpu::BufferUsages::empty());
        let leaf = s("light leaf", bytemuck::cast_slice(bsh.leaf_indices()));
        let cones = if cones.is_empty() {
            vec![GpuLightCone::default()]
        } else {
            pack_cones(cones, light_bvh.map_or(&[], |b| b.leaf_of_light()))
        };
        let refit_params =
            UniformSlots::new::<RefitParams>(gpu, "refit params", levels.len() as u64);
        let values: Vec<RefitParams> = levels
            .iter()
            .map(|&(first, count)| RefitParams { first, count, pad0: 0, pad1: 0 })
            .collect();
        refit_params.write(gpu, &values);
        let rt2 = zeroed(gpu, "rt2", n * 4, wgpu::BufferUsages::STORAGE | dst);
        let r2 = zeroed(gpu, "r2", n * 4, wgpu::BufferUsages::STORAGE);
        // `light_update`'s ids: each light's ξ key (the CPU path tracer's).
        let keys = storage(gpu, "xi keys", bytemuck::cast_slice(&xi_keys(lights)), dst);
        let order = s("bsh order", bytemuck::cast_slice(&order));
        let bounds = storage(gpu, "light bounds", bytemuck::cast_slice(&pack_bounds(bounds)), dst);
        // The range tail: its cut (none until `bsh_tail` runs: the CPU's
        // as built), length and slots; the histogram, zero between passes.
        let (tail_k, tree) = (bsh.tail_capacity() as u32, bsh.tree_len() as u32);
        // COPY_SRC: read back by the tests that compare it with the CPU's.
        let bsh = storage(
            gpu,
            "bsh nodes",
            bytemuck::cast_slice(bsh.nodes()),
            wgpu::BufferUsages::COPY_SRC,
        );
        let mut tail_init = vec![BSH_TAIL_BINS, 0];
        tail_init.resize(2 + tail_k as usize, 0);
        let tail = s("bsh tail", bytemuck::cast_slice(&tail_init));
        let tail_hist = zeroed(
            gpu,
            "bsh tail histogram",
            BSH_TAIL_BINS as u64 * 4,
            wgpu::BufferUsages::STORAGE,
        );
        let tail_params = UniformSlots::new::<TailParams>(gpu, "tail params", 4);
        let stages: Vec<TailParams> =
            (0..4).map(|stage| TailParams { stage, count: n as u32, k: tail_k, tree }).collect();
        tail_params.write(gpu, &stages);
        let res = crate::kernel::whole;
        let update_group = update.group(
            gpu,
            0,
            &[
                ("params", frame_params.binding()),
                ("ids", res(&keys)),
                ("rt2", res(&rt2)),
                ("r2", res(&r2)),
            ],
        );
        let refit_group = refit.group(
            gpu,
            0,
            &[
                ("params", refit_params.binding()),
                ("order", res(&order)),
                ("bounds", res(&bounds)),
                ("r2", res(&r2)),
                ("bsh_nodes", res(&bsh)),
                ("tail", res(&tail)),
            ],
        );
        let tail_group = tail_layout.group(
            gpu,
            0,
            &[
                ("params", tail_params.binding()),
                ("bounds", res(&bounds)),
                ("r2", res(&r2)),
                ("tail_hist", res(&tail_hist)),
                ("tail", res(&tail)),
                ("bsh_nodes", res(&bsh)),
            ],
        );
        // The path tracer's tables (a binding cannot be empty: a zeroed
        // entry stands in for a missing one).
        let power = s(
            "power_table",
            bytemuck::cast_slice(if power.is_empty() { &[[0.0f32; 4]][..] } else { power }),
        );
        let bvh = s("light_bvh", bytemuck::cast_slice(bvh));
        let table_buf = storage(gpu, "slc_table", bytemuck::cast_slice(&table), dst);
        let cones = storage(gpu, "light_cones", bytemuck::cast_slice(&cones), dst);
        let table = table_group(gpu, table_layout, [&table_buf, &power, &cones, &bvh]);
        Ok(LightBuffers {
            n: n as u32,
            peaks_host: lights.iter().map(Light::peak).collect(),
            types: LightTypes::of(lights),
            // COPY_SRC: the direct pass's reuse keeps the previous record's lights.
            lights: storage(
                gpu,
                "lights",
                bytemuck::cast_slice(&gpu_lights),
                dst | wgpu::BufferUsages::COPY_SRC,
            ),
            table_buf,
            cones,
            peaks: storage(gpu, "light peaks", bytemuck::cast_slice(&pack_peaks(lights)), dst),
            rt2,
            r2,
            keys,
            bsh,
            leaf,
            bounds,
            levels,
            refit_params,
            tail_k,
            tail_params,
            tail_group,
            power,
            bvh,
            update_group,
            refit_group,
            table,
        })
    }
}

/// The path tracer's group 1 over a set's tables: the IES table, the power
/// alias table, the importance cones and the light BVH.
fn table_group(
    gpu: &GpuContext,
    layout: &wgpu::BindGroupLayout,
    bufs: [&wgpu::Buffer; 4],
) -> wgpu::BindGroup {
    let entries: Vec<wgpu::BindGroupEntry> = bufs
        .iter()
        .enumerate()
        .map(|(i, b)| wgpu::BindGroupEntry { binding: i as u32, resource: b.as_entire_binding() })
        .collect();
    gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("scene tables"),
        layout,
        entries: &entries,
    })
}
