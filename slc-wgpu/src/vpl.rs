//! Application A on the GPU: the VPL pipeline's shading and denoise run in
//! the `light_update`, `vpl_tiled`, `vpl_denoise` and `vpl_near` kernels of
//! slc-shared-shaders, on the G-buffer and VPLs of a
//! [`slc_scene::vpl::VplInputs`] (whoever made them: the CPU backend ray
//! casts them), so both backends shade the same inputs. [`GpuVpl`] is an
//! [`IndirectShader`]; the frame's composition is the caller's.

use crate::kernel::{Timer, bind_layout, pipeline, read_back, storage};
use crate::{GpuContext, GpuError};
use glam::Vec3;
use slc_core::interleave::interleave_slot;
use slc_core::light::vpl_threshold_range2;
use slc_core::range::random_range2;
use slc_scene::backend::IndirectShader;
use slc_scene::vpl::{PERIOD, Shaded, VplInputs, VplMethod, VplSettings};
use slc_shared_shaders::layout::{FrameParams, GpuLight, GpuNearBox, VplParams};
use slc_shared_shaders::{CullMethod, Features, Kernel, LightSet, generate};
use std::time::Instant;
use wgpu::util::DeviceExt;

/// Tile edge of `vpl_tiled` in sub-image pixels.
pub const TILE: u32 = 8;
/// Default capacity of the tile light list (8 KiB of workgroup memory): a
/// subset with more lights is culled and shaded in chunks of this size.
pub const TILE_LIST: u32 = 2048;
/// Workgroup size of `light_update`.
const WG: u32 = 64;

struct Layout {
    period: u32,
    per_subset: u32,
    pipeline: wgpu::ComputePipeline,
}

/// GPU buffers and pipelines for one [`VplInputs`] (one G-buffer and VPL set).
pub struct GpuVpl {
    gpu: GpuContext,
    width: u32,
    height: u32,
    /// Pixels that see a surface.
    valid: Vec<bool>,
    min_d2: f32,
    gb_position: wgpu::Buffer,
    gb_normal: wgpu::Buffer,
    /// Interleaved layout: VPLs subset after subset, flux × P².
    lights: wgpu::Buffer,
    ids: wgpu::Buffer,
    flux: Vec<Vec3>,
    /// Reference layout: one subset holding every VPL, flux × 1.
    lights_all: wgpu::Buffer,
    ids_all: wgpu::Buffer,
    rt2: wgpu::Buffer,
    r2: wgpu::Buffer,
    /// Near-block order → slot in `lights` ([`Vpls::near_order`](slc_scene::vpl::Vpls::near_order)).
    near_slots: wgpu::Buffer,
    near_boxes: wgpu::Buffer,
    near_blocks: u32,
    irradiance: wgpu::Buffer,
    /// Denoised irradiance.
    filtered: wgpu::Buffer,
    readback: wgpu::Buffer,
    denoise: wgpu::ComputePipeline,
    denoise_layout: wgpu::BindGroupLayout,
    /// `vpl_near` per culling method (the near field culled as the far field is).
    near: Vec<(VplMethod, wgpu::ComputePipeline)>,
    near_layout: wgpu::BindGroupLayout,
    update: wgpu::ComputePipeline,
    update_layout: wgpu::BindGroupLayout,
    tiled: Vec<(VplMethod, Layout)>,
    tiled_layout: wgpu::BindGroupLayout,
    /// One frame at a time: a frame writes the shared range, irradiance and
    /// readback buffers, so concurrent `shade` calls would race.
    frame: std::sync::Mutex<()>,
}

impl GpuVpl {
    /// Uploads the G-buffer and VPLs of `inputs` and builds the pipelines.
    /// Checks buffer, dispatch and workgroup-memory limits first. The tile
    /// light list holds up to [`TILE_LIST`] lights; larger subsets stream
    /// through it in chunks.
    pub fn new(gpu: &GpuContext, inputs: &VplInputs) -> Result<Self, GpuError> {
        Self::with_tile_list(gpu, inputs, TILE_LIST)
    }

    /// [`GpuVpl::new`] with a tile light list of `capacity` lights (at
    /// least 1): smaller lists take less workgroup memory and more chunks.
    pub fn with_tile_list(gpu: &GpuContext, inputs: &VplInputs, capacity: u32) -> Result<Self, GpuError> {
        let gb = &inputs.gbuffer;
        let v = &inputs.vpls;
        let (w, h) = (gb.width, gb.height);
        let n = v.len() as u64;
        let subsets = (PERIOD * PERIOD) as usize;
        let per_subset = (n / subsets as u64) as u32;
        let lim = &gpu.limits;
        let max_binding = lim.max_storage_buffer_binding_size;
        gpu.require("max_storage_buffer_binding_size (G-buffer)", w as u64 * h as u64 * 16, max_binding)?;
        gpu.require("max_storage_buffer_binding_size (lights)", n * 64, max_binding)?;
        let sub_w = w.div_ceil(PERIOD);
        gpu.require(
            "max_compute_workgroups_per_dimension",
            sub_w.div_ceil(TILE).max(w.div_ceil(TILE)) as u64,
            lim.max_compute_workgroups_per_dimension as u64,
        )?;
        gpu.require("max_compute_workgroups_per_dimension (light update)", n.div_ceil(WG as u64), lim.max_compute_workgroups_per_dimension as u64)?;
        let list = per_subset.min(capacity).max(1);
        let wg_bytes = slc_shared_shaders::vpl_tiled_workgroup_bytes(TILE, list);
        gpu.require("max_compute_workgroup_storage_size (tile light list)", wg_bytes, lim.max_compute_workgroup_storage_size as u64)?;

        let vpl_only = LightSet { vpl: true, ..LightSet::default() };
        let checked =
            Features { lights: vpl_only, tile_size: TILE, interleave: PERIOD, max_tile_lights: list, workgroup_size: WG, ..Features::default() };
        crate::kernel::check_kernels(gpu, &[Kernel::LightUpdate, Kernel::VplTiled, Kernel::VplDenoise, Kernel::VplNear].map(|k| (k, &checked, 0)))?;

        let pos: Vec<[f32; 4]> = (0..gb.position.len())
            .map(|i| {
                let p = gb.position[i];
                [p.x, p.y, p.z, if gb.valid(i) { 1.0 } else { 0.0 }]
            })
            .collect();
        // w: depth, for the denoise (DEPTH_NONE where there is no surface).
        let nrm: Vec<[f32; 4]> =
            gb.normal.iter().zip(&gb.depth).map(|(n, &d)| [n.x, n.y, n.z, if d.is_finite() { d } else { slc_core::denoise::DEPTH_NONE }]).collect();
        let vpl = |i: usize, scale: f32| GpuLight::vpl(v.position[i], v.normal[i], v.flux[i] * scale);
        let order = inputs.interleaved_order();
        let scale = slc_core::interleave::interleave_flux_scale(PERIOD);
        let lights: Vec<GpuLight> = order.iter().map(|&i| vpl(i, scale)).collect();
        let ids: Vec<u32> = order.iter().map(|&i| i as u32).collect();
        // Where each VPL of near-block order sits in `lights` (vpl_pack's map).
        let near_slots: Vec<u32> = v.near_order().iter().map(|&i| interleave_slot(i as u32 % v.size, i as u32 / v.size, v.size, PERIOD)).collect();
        let near_boxes: Vec<GpuNearBox> = v.near_boxes().iter().map(|&(lo, hi)| GpuNearBox { lo, pad0: 0.0, hi, pad1: 0.0 }).collect();
        let lights_all: Vec<GpuLight> = (0..v.len()).map(|i| vpl(i, 1.0)).collect();
        let ids_all: Vec<u32> = (0..v.len() as u32).collect();
        let zeros = vec![0.0f32; v.len().max(1)];
        let pixels = (w as u64) * (h as u64) * 16;
        let irradiance = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("irradiance"),
            size: pixels,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let filtered = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("filtered"),
            size: pixels,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let readback = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: pixels,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let features = Features { workgroup_size: WG, ..Features::default() };
        let update_layout = bind_layout(gpu, "light_update", 2, 1, false);
        let tiled_layout = bind_layout(gpu, "vpl_tiled", 5, 1, false);
        let update = pipeline(gpu, "light_update", generate(Kernel::LightUpdate, &features)?, &[&update_layout]);
        let denoise_layout = bind_layout(gpu, "vpl_denoise", 3, 1, false);
        let df = Features { lights: LightSet { vpl: true, ..LightSet::default() }, tile_size: TILE, interleave: PERIOD, ..Features::default() };
        let denoise = pipeline(gpu, "vpl_denoise", generate(Kernel::VplDenoise, &df)?, &[&denoise_layout]);
        let near_layout = bind_layout(gpu, "vpl_near", 7, 1, false);
        let mut tiled = Vec::new();
        let mut near = Vec::new();
        for (m, cm) in [(VplMethod::Slc, CullMethod::Slc), (VplMethod::Clamp, CullMethod::Clamp), (VplMethod::None, CullMethod::None)] {
            near.push((m, pipeline(gpu, "vpl_near", generate(Kernel::VplNear, &Features { method: cm, ..df })?, &[&near_layout])));
            let f = Features { lights: vpl_only, tile_size: TILE, interleave: PERIOD, max_tile_lights: list, method: cm, ..Features::default() };
            tiled.push((
                m,
                Layout { period: PERIOD, per_subset, pipeline: pipeline(gpu, "vpl_tiled", generate(Kernel::VplTiled, &f)?, &[&tiled_layout]) },
            ));
        }
        // The reference: one "subset" of every VPL, unculled, no list.
        let f = Features { lights: vpl_only, tile_size: TILE, interleave: 1, max_tile_lights: 1, method: CullMethod::None, ..Features::default() };
        tiled.push((
            VplMethod::Reference,
            Layout {
                period: 1,
                per_subset: v.len() as u32,
                pipeline: pipeline(gpu, "vpl_reference", generate(Kernel::VplTiled, &f)?, &[&tiled_layout]),
            },
        ));
        let s = GpuVpl {
            gpu: gpu.clone(),
            width: w,
            height: h,
            valid: (0..gb.position.len()).map(|i| gb.valid(i)).collect(),
            min_d2: inputs.min_d2,
            gb_position: storage(gpu, "gb_position", bytemuck::cast_slice(&pos), wgpu::BufferUsages::empty()),
            gb_normal: storage(gpu, "gb_normal", bytemuck::cast_slice(&nrm), wgpu::BufferUsages::empty()),
            lights: storage(gpu, "lights", bytemuck::cast_slice(&lights), wgpu::BufferUsages::empty()),
            ids: storage(gpu, "ids", bytemuck::cast_slice(&ids), wgpu::BufferUsages::empty()),
            flux: order.iter().map(|&i| v.flux[i] * scale).collect(),
            lights_all: storage(gpu, "lights_all", bytemuck::cast_slice(&lights_all), wgpu::BufferUsages::empty()),
            ids_all: storage(gpu, "ids_all", bytemuck::cast_slice(&ids_all), wgpu::BufferUsages::empty()),
            rt2: storage(gpu, "rt2", bytemuck::cast_slice(&zeros), wgpu::BufferUsages::empty()),
            r2: storage(gpu, "r2", bytemuck::cast_slice(&zeros), wgpu::BufferUsages::empty()),
            near_slots: storage(gpu, "near_slots", bytemuck::cast_slice(&near_slots), wgpu::BufferUsages::empty()),
            near_boxes: storage(gpu, "near_boxes", bytemuck::cast_slice(&near_boxes), wgpu::BufferUsages::empty()),
            near_blocks: near_boxes.len() as u32,
            irradiance,
            filtered,
            readback,
            denoise,
            denoise_layout,
            near,
            near_layout,
            update,
            update_layout,
            tiled,
            tiled_layout,
            frame: std::sync::Mutex::new(()),
        };
        gpu.wait()?;
        Ok(s)
    }

    /// Indirect irradiance on the GPU for `settings`, denoised on the GPU
    /// when `settings.denoise` (the same filter as the CPU's) (same ξ as the CPU:
    /// `xi_for(seed, frame, VPL index)`); calls from several threads are
    /// serialised, one frame at a time; `fixed_xi` ranges are computed on
    /// the host. `shading_ms` is GPU time from timestamps where the adapter
    /// has them ([`GpuContext::timestamps`]), else the wall time of the
    /// submitted kernels.
    pub fn shade(&self, settings: &VplSettings) -> Result<Shaded, GpuError> {
        let params = settings.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
        let _frame = self.frame.lock().map_err(|_| GpuError::Device("a previous frame panicked".into()))?;
        let gpu = &self.gpu;
        let (_, layout) = self.tiled.iter().find(|(m, _)| *m == settings.method).ok_or(GpuError::Setting("unknown method".into()))?;
        let n = self.flux.len();
        // Threshold ranges on the host with the core's function; r² on the GPU.
        let rt2: Vec<f32> = match settings.method {
            VplMethod::Slc => self.flux.iter().map(|&f| vpl_threshold_range2(&params, f)).collect(),
            _ => vec![0.0; n],
        };
        gpu.queue.write_buffer(&self.rt2, 0, bytemuck::cast_slice(&rt2));
        let host_r2: Option<Vec<f32>> = match (settings.method, settings.fixed_xi) {
            (VplMethod::Slc, Some(x)) => Some(rt2.iter().map(|&t| random_range2(t, x)).collect()),
            (VplMethod::Slc, None) => None,
            (VplMethod::Clamp, _) => Some(vec![settings.range * settings.range; n]),
            _ => Some(vec![f32::INFINITY; n]),
        };
        if let Some(r2) = &host_r2 {
            gpu.queue.write_buffer(&self.r2, 0, bytemuck::cast_slice(r2));
        }
        let reference = settings.method == VplMethod::Reference;
        let (lights, ids) = if reference { (&self.lights_all, &self.ids_all) } else { (&self.lights, &self.ids) };
        let frame = FrameParams { light_count: n as u32, seed: settings.seed, frame: settings.frame, pad: 0 };
        let frame_buf = gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("frame params"),
            contents: bytemuck::bytes_of(&frame),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        // The reference shades every VPL in full: no near-field split.
        let near_r2 = if reference { 0.0 } else { settings.near_r2(self.min_d2) };
        let vp = VplParams {
            width: self.width,
            height: self.height,
            lights_per_subset: layout.per_subset,
            min_d2: self.min_d2,
            near_r2,
            near_blocks: self.near_blocks,
            pad0: 0,
            pad1: 0,
        };
        let vp_buf = gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("vpl params"),
            contents: bytemuck::bytes_of(&vp),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        fn entries<'b>(bufs: &[&'b wgpu::Buffer]) -> Vec<wgpu::BindGroupEntry<'b>> {
            bufs.iter().enumerate().map(|(i, b)| wgpu::BindGroupEntry { binding: i as u32, resource: b.as_entire_binding() }).collect()
        }
        let denoise = settings.denoise && !reference;
        let mut timer = Timer::new(gpu, 3);
        let mut enc = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("slc vpl") });
        {
            let mut pass = enc
                .begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("slc vpl"), timestamp_writes: timer.as_mut().and_then(|t| t.next()) });
            if host_r2.is_none() {
                let bg = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("light_update"),
                    layout: &self.update_layout,
                    entries: &entries(&[&frame_buf, ids, &self.rt2, &self.r2]),
                });
                pass.set_pipeline(&self.update);
                pass.set_bind_group(0, &bg, &[]);
                pass.dispatch_workgroups((n as u32).div_ceil(WG), 1, 1);
            }
            let bg = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("vpl_tiled"),
                layout: &self.tiled_layout,
                entries: &entries(&[&vp_buf, &self.gb_position, &self.gb_normal, lights, &self.rt2, &self.r2, &self.irradiance]),
            });
            pass.set_pipeline(&layout.pipeline);
            pass.set_bind_group(0, &bg, &[]);
            let p = layout.period;
            let (sub_w, sub_h) = (self.width.div_ceil(p), self.height.div_ceil(p));
            pass.dispatch_workgroups(sub_w.div_ceil(TILE), sub_h.div_ceil(TILE), p * p);
        }
        let near = near_r2 > 0.0;
        if let Some(t) = &timer
            && !denoise
            && !near
        {
            t.resolve(&mut enc);
        }
        let t = Instant::now();
        gpu.queue.submit([enc.finish()]);
        gpu.wait()?;
        let mut shading_ms = t.elapsed().as_secs_f64() * 1e3;
        let mut denoised_ms = None;
        if denoise {
            // The cross-bilateral filter as its own timed pass.
            let mut enc = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("slc vpl denoise") });
            {
                let writes = timer.as_mut().and_then(|t| t.next());
                let mut pass = enc.begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("slc vpl denoise"), timestamp_writes: writes });
                let bg = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("vpl_denoise"),
                    layout: &self.denoise_layout,
                    entries: &entries(&[&vp_buf, &self.gb_position, &self.gb_normal, &self.irradiance, &self.filtered]),
                });
                pass.set_pipeline(&self.denoise);
                pass.set_bind_group(0, &bg, &[]);
                pass.dispatch_workgroups(self.width.div_ceil(TILE), self.height.div_ceil(TILE), 1);
            }
            if let Some(t) = &timer
                && !near
            {
                t.resolve(&mut enc);
            }
            let t = Instant::now();
            gpu.queue.submit([enc.finish()]);
            gpu.wait()?;
            denoised_ms = Some(t.elapsed().as_secs_f64() * 1e3);
        }
        let result = if denoise { &self.filtered } else { &self.irradiance };
        if near {
            // The near field, added after the denoise (which filters only the
            // interleaved far field), culled as the far field (the ranges
            // the first pass wrote), as its own timed pass.
            let near_pipeline = &self.near.iter().find(|(m, _)| *m == settings.method).ok_or(GpuError::Setting("unknown method".into()))?.1;
            let mut enc = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("slc vpl near") });
            {
                let writes = timer.as_mut().and_then(|t| t.next());
                let mut pass = enc.begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("slc vpl near"), timestamp_writes: writes });
                let bg = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("vpl_near"),
                    layout: &self.near_layout,
                    entries: &entries(&[
                        &vp_buf,
                        &self.gb_position,
                        &self.gb_normal,
                        &self.lights,
                        &self.near_slots,
                        &self.near_boxes,
                        &self.rt2,
                        &self.r2,
                        result,
                    ]),
                });
                pass.set_pipeline(near_pipeline);
                pass.set_bind_group(0, &bg, &[]);
                pass.dispatch_workgroups(self.width.div_ceil(TILE), self.height.div_ceil(TILE), 1);
            }
            if let Some(t) = &timer {
                t.resolve(&mut enc);
            }
            let t = Instant::now();
            gpu.queue.submit([enc.finish()]);
            gpu.wait()?;
            shading_ms += t.elapsed().as_secs_f64() * 1e3;
        }
        if let Some(timer) = &timer {
            let d = timer.durations_ms(gpu)?;
            shading_ms = d[0] + if near { d[1 + denoise as usize] } else { 0.0 };
            if denoise {
                denoised_ms = d.get(1).copied();
            }
        }

        let data: Vec<[f32; 4]> = read_back(gpu, result, &self.readback)?;
        let mut irradiance = Vec::with_capacity(data.len());
        let mut kept = Vec::with_capacity(data.len());
        let mut evaluations = 0u64;
        for (i, d) in data.iter().enumerate() {
            let valid = self.valid[i];
            irradiance.push(if valid { Vec3::new(d[0], d[1], d[2]) } else { Vec3::ZERO });
            kept.push(if valid { d[3] as u32 } else { 0 });
            evaluations += valid as u64 * d[3] as u64;
        }
        Ok(Shaded { irradiance, near: Vec::new(), kept, evaluations, shading_ms, denoised_ms })
    }
}

impl IndirectShader for GpuVpl {
    type Error = GpuError;

    fn describe(&self) -> String {
        self.gpu.describe()
    }

    fn shade(&self, settings: &VplSettings) -> Result<Shaded, GpuError> {
        GpuVpl::shade(self, settings)
    }
}
