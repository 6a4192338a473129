//! The indirect-light pass: application A on an engine's G-buffer.
//!
//! SLC shading of VPLs (the paper's first application) on the engine's
//! G-buffer, into a texture the engine owns. Recorded dispatches, in one
//! compute pass: `gbuffer_import` (textures → the shading buffers),
//! `vpl_pack` (RSM texels or VPL records → the light buffer, subset after
//! subset, flux × P², `r_t²`), `light_update` (SLC: `r² = r_t²/(1−ξ)` with
//! `ξ = xi_for(seed, frame, id)`, the CPU's numbers), `vpl_tiled` (tiled
//! culling and shading per 8×8 interleaved sub-image, the far field of the
//! near-field split), `vpl_denoise` (cross-bilateral, when
//! `settings.denoise`), `vpl_near` (the near field: every VPL closer than
//! `R_n` at every pixel, added after the denoise; when `R_n > 0`) and
//! `irradiance_export`.
//!
//! | input | format | size | usage | content |
//! |---|---|---|---|---|
//! | `position` | `Rgba32Float` or `Rgba16Float` | `width × height` | `TEXTURE_BINDING` | world position; `w > 0` where a surface is |
//! | `normal` | `Rgba32Float` or `Rgba16Float` | `width × height` | `TEXTURE_BINDING` | world unit normal facing the camera (`w` unused) |
//! | RSM `position`, `normal`, `flux` | `Rgba32Float` or `Rgba16Float` | `s × s`, `s` a multiple of 8 | `TEXTURE_BINDING` | per texel the surface the light sees, its normal and the flux it reflects (incident × albedo); zero flux where nothing is hit; a texel's flux shrinks as `1/s²`, so prefer `Rgba32Float` for flux (half floats go subnormal below 6·10⁻⁵: at 256² a half-float flux target zeroed 28% of the default box's lit texels) |
//! | VPL buffer | [`GpuVplRecord`] array | `count` records, `count` a multiple of 64 | `STORAGE` | position, normal, flux |
//! | `output` | the `output_format` of the descriptor (`Rgba16Float` or `Rgba32Float`) | `width × height` | `STORAGE_BINDING` | written: irradiance (rgb), lights kept (a); 0 where no surface |
//!
//! Views must show mip level 0 of the whole texture in its own format. A
//! wrong format, size or usage is a [`GpuError::Binding`] before anything is
//! recorded; limits the device lacks are [`GpuError::Limit`]s at
//! [`IndirectPass::new`]. The pass keeps its own intermediate buffers
//! (G-buffer copies, light buffer, ranges, irradiance): one `record` per
//! frame, since a second one in the same submission overwrites them.
//!
//! ```no_run
//! # fn frame(device: wgpu::Device, queue: wgpu::Queue, gb_position: wgpu::TextureView,
//! #          gb_normal: wgpu::TextureView, rsm: [wgpu::TextureView; 3], output: wgpu::TextureView)
//! #          -> Result<(), slc_wgpu::GpuError> {
//! use slc_scene::vpl::VplSettings;
//! use slc_wgpu::GpuContext;
//! use slc_wgpu::passes::{IndirectFrame, IndirectInputs, IndirectPass, IndirectPassDesc, VplInput, VplSourceDesc};
//!
//! let gpu = GpuContext::from_device(device.clone(), queue.clone());
//! let pass = IndirectPass::new(&gpu, &IndirectPassDesc {
//!     width: 1920,
//!     height: 1080,
//!     vpls: VplSourceDesc::Rsm { size: 256 },
//!     output_format: wgpu::TextureFormat::Rgba16Float,
//! })?;
//! let mut encoder = device.create_command_encoder(&Default::default());
//! // ... the engine's G-buffer and RSM passes ...
//! let inputs = IndirectInputs {
//!     position: &gb_position,
//!     normal: &gb_normal,
//!     vpls: VplInput::Rsm { position: &rsm[0], normal: &rsm[1], flux: &rsm[2] },
//!     output: &output,
//! };
//! let frame = IndirectFrame { settings: VplSettings::default(), eye: glam::Vec3::new(0.0, 1.0, 3.5), min_distance: 0.05 };
//! pass.record(&gpu, &mut encoder, &inputs, &frame)?;
//! // ... the engine composes `output` × albedo with its direct light ...
//! queue.submit([encoder.finish()]);
//! # Ok(()) }
//! ```

use super::{Dispatch, FLOAT_INPUTS, check_gbuffer, check_view, output_format};
use crate::kernel::{B, layout, pipeline, storage, zeroed};
use crate::{GpuContext, GpuError};
use glam::Vec3;
use slc_core::interleave::NEAR_BLOCK;
use slc_scene::vpl::{PERIOD, VplMethod, VplSettings};
use slc_shared_shaders::layout::{FrameParams, GpuLight, GpuNearBox, GpuVplRecord, ImageParams, PackParams, VplParams};
use slc_shared_shaders::{CullMethod, Features, Kernel, LightSet, VplSource, generate};
use wgpu::util::DeviceExt;

/// Tile edge of the 2-D kernels, in pixels.
const TILE: u32 = crate::vpl::TILE;
/// Workgroup size of the 1-D kernels.
const WG: u32 = 64;

/// Where the indirect pass gets its VPLs, fixed at creation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VplSourceDesc {
    /// A reflective shadow map of `size × size` texels (`size` a multiple of
    /// 8): one VPL per texel.
    Rsm {
        /// Edge in texels.
        size: u32,
    },
    /// A buffer of `count` [`GpuVplRecord`]s (`count` a multiple of 64).
    Buffer {
        /// Number of VPLs.
        count: u32,
    },
}

impl VplSourceDesc {
    fn count(self) -> u64 {
        match self {
            VplSourceDesc::Rsm { size } => size as u64 * size as u64,
            VplSourceDesc::Buffer { count } => count as u64,
        }
    }
}

/// What an [`IndirectPass`] is built for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IndirectPassDesc {
    /// G-buffer and output width.
    pub width: u32,
    /// G-buffer and output height.
    pub height: u32,
    /// The VPL source.
    pub vpls: VplSourceDesc,
    /// Format of the output storage texture: `Rgba16Float` or `Rgba32Float`.
    pub output_format: wgpu::TextureFormat,
}

/// The VPLs of one frame.
#[derive(Clone, Copy, Debug)]
pub enum VplInput<'a> {
    /// RSM textures (see the module table).
    Rsm {
        /// World position of the texel's surface.
        position: &'a wgpu::TextureView,
        /// Its unit normal.
        normal: &'a wgpu::TextureView,
        /// Reflected flux (rgb).
        flux: &'a wgpu::TextureView,
    },
    /// A storage buffer of [`GpuVplRecord`]s.
    Buffer(&'a wgpu::Buffer),
}

/// The engine's resources for one frame.
#[derive(Clone, Copy, Debug)]
pub struct IndirectInputs<'a> {
    /// G-buffer world positions (`w > 0`: surface).
    pub position: &'a wgpu::TextureView,
    /// G-buffer unit normals facing the camera.
    pub normal: &'a wgpu::TextureView,
    /// The VPLs.
    pub vpls: VplInput<'a>,
    /// Where the irradiance goes.
    pub output: &'a wgpu::TextureView,
}

/// Per-frame settings of the indirect pass.
#[derive(Clone, Debug)]
pub struct IndirectFrame {
    /// Method (`slc`, `clamp`, `none`), ε, exposure, clamp range, seed,
    /// frame number and denoise, as for the CPU backend. `fixed_xi` and the
    /// `reference` method are not offered here (use [`crate::vpl::GpuVpl`]).
    pub settings: VplSettings,
    /// Eye position (the denoise's depth is the distance from it).
    pub eye: Vec3,
    /// Clamp distance of the VPL fall-off `1/max(d², min_distance²)`; the
    /// default near radius is [`slc_scene::vpl::NEAR_FACTOR`] times it
    /// ([`VplSettings::near_radius`]).
    pub min_distance: f32,
}

/// SLC indirect light from VPLs on an engine's G-buffer (see the module
/// docs for the inputs it expects).
pub struct IndirectPass {
    desc: IndirectPassDesc,
    count: u32,
    per_subset: u32,
    gb_position: wgpu::Buffer,
    gb_normal: wgpu::Buffer,
    irradiance: wgpu::Buffer,
    filtered: wgpu::Buffer,
    lights: wgpu::Buffer,
    ids: wgpu::Buffer,
    rt2: wgpu::Buffer,
    r2: wgpu::Buffer,
    near_slots: wgpu::Buffer,
    near_boxes: wgpu::Buffer,
    import: (wgpu::ComputePipeline, wgpu::BindGroupLayout),
    pack: (wgpu::ComputePipeline, wgpu::BindGroupLayout),
    update: (wgpu::ComputePipeline, wgpu::BindGroupLayout),
    tiled: Vec<(VplMethod, wgpu::ComputePipeline)>,
    tiled_layout: wgpu::BindGroupLayout,
    denoise: (wgpu::ComputePipeline, wgpu::BindGroupLayout),
    /// `vpl_near` per culling method, and its layout.
    near: (Vec<(VplMethod, wgpu::ComputePipeline)>, wgpu::BindGroupLayout),
    export: (wgpu::ComputePipeline, wgpu::BindGroupLayout),
}

impl IndirectPass {
    /// Builds the pipelines and intermediate buffers for `desc`. Checks the
    /// sizes (non-zero image, RSM edge or VPL count a multiple of the
    /// interleave period) and the device limits first.
    pub fn new(gpu: &GpuContext, desc: &IndirectPassDesc) -> Result<Self, GpuError> {
        let (w, h) = (desc.width, desc.height);
        if w == 0 || h == 0 {
            return Err(GpuError::Setting(format!("indirect pass: image size {w}×{h} must be non-zero")));
        }
        let subsets = PERIOD * PERIOD;
        let (count, vpl_source) = match desc.vpls {
            VplSourceDesc::Rsm { size } if size == 0 || size % PERIOD != 0 => {
                return Err(GpuError::Setting(format!("indirect pass: RSM size {size} must be a positive multiple of {PERIOD}")));
            }
            VplSourceDesc::Buffer { count } if count == 0 || count % subsets != 0 => {
                return Err(GpuError::Setting(format!("indirect pass: VPL count {count} must be a positive multiple of {subsets}")));
            }
            VplSourceDesc::Rsm { .. } => (desc.vpls.count(), VplSource::Rsm),
            VplSourceDesc::Buffer { .. } => (desc.vpls.count(), VplSource::Buffer),
        };
        let output = output_format(desc.output_format)?;
        let lim = &gpu.limits;
        let max_binding = lim.max_storage_buffer_binding_size;
        gpu.require("max_storage_buffer_binding_size (G-buffer)", w as u64 * h as u64 * 16, max_binding)?;
        gpu.require("max_storage_buffer_binding_size (lights)", count * std::mem::size_of::<GpuLight>() as u64, max_binding)?;
        let groups = lim.max_compute_workgroups_per_dimension as u64;
        gpu.require("max_compute_workgroups_per_dimension", w.div_ceil(TILE).max(h.div_ceil(TILE)) as u64, groups)?;
        gpu.require("max_compute_workgroups_per_dimension (VPLs)", count.div_ceil(WG as u64), groups)?;
        gpu.require("max_storage_buffers_per_shader_stage", 8, lim.max_storage_buffers_per_shader_stage as u64)?;
        gpu.require("max_storage_textures_per_shader_stage", 1, lim.max_storage_textures_per_shader_stage as u64)?;
        let per_subset = (count / subsets as u64) as u32;
        let list = per_subset.clamp(1, crate::vpl::TILE_LIST);
        let wg_bytes = slc_shared_shaders::vpl_tiled_workgroup_bytes(TILE, list);
        gpu.require("max_compute_workgroup_storage_size (tile light list)", wg_bytes, lim.max_compute_workgroup_storage_size as u64)?;

        let vpl = LightSet { vpl: true, ..LightSet::default() };
        let base = Features { lights: vpl, tile_size: TILE, interleave: PERIOD, workgroup_size: WG, max_tile_lights: list, ..Features::default() };
        let kernel = |k: Kernel, f: &Features, l: &wgpu::BindGroupLayout| -> Result<wgpu::ComputePipeline, GpuError> {
            Ok(pipeline(gpu, k.name(), generate(k, f)?, &[l]))
        };
        use B::*;
        let import_layout = layout(gpu, "gbuffer_import", &[(0, Uniform), (1, Texture), (2, Texture), (3, Write), (4, Write), (5, Write)]);
        let pack_inputs: &[(u32, B)] = match vpl_source {
            VplSource::Rsm => &[(1, Texture), (2, Texture), (3, Texture)],
            VplSource::Buffer => &[(1, Read)],
        };
        let mut pack_entries = vec![(0, Uniform)];
        pack_entries.extend_from_slice(pack_inputs);
        pack_entries.extend([(4, Write), (5, Write), (6, Write), (7, Write), (8, Write), (9, Write)]);
        let pack_layout = layout(gpu, "vpl_pack", &pack_entries);
        let update_layout = layout(gpu, "light_update", &[(0, Uniform), (1, Read), (2, Read), (3, Write)]);
        let tiled_layout = layout(gpu, "vpl_tiled", &[(0, Uniform), (1, Read), (2, Read), (3, Read), (4, Read), (5, Read), (6, Write)]);
        let denoise_layout = layout(gpu, "vpl_denoise", &[(0, Uniform), (1, Read), (2, Read), (3, Read), (4, Write)]);
        let near_layout =
            layout(gpu, "vpl_near", &[(0, Uniform), (1, Read), (2, Read), (3, Read), (4, Read), (5, Read), (6, Read), (7, Read), (8, Write)]);
        let export_layout = layout(gpu, "irradiance_export", &[(0, Uniform), (1, Read), (2, Read), (3, Storage(desc.output_format))]);
        let (mut tiled, mut near) = (Vec::new(), Vec::new());
        for (m, cm) in [(VplMethod::Slc, CullMethod::Slc), (VplMethod::Clamp, CullMethod::Clamp), (VplMethod::None, CullMethod::None)] {
            tiled.push((m, kernel(Kernel::VplTiled, &Features { method: cm, ..base }, &tiled_layout)?));
            near.push((m, kernel(Kernel::VplNear, &Features { method: cm, ..base }, &near_layout)?));
        }
        let pixels = w as u64 * h as u64 * 16;
        let rw = wgpu::BufferUsages::STORAGE;
        let s = IndirectPass {
            desc: *desc,
            count: count as u32,
            per_subset,
            gb_position: zeroed(gpu, "slc gb_position", pixels, rw),
            gb_normal: zeroed(gpu, "slc gb_normal", pixels, rw),
            irradiance: zeroed(gpu, "slc irradiance", pixels, rw),
            filtered: zeroed(gpu, "slc filtered", pixels, rw),
            lights: zeroed(gpu, "slc lights", count * std::mem::size_of::<GpuLight>() as u64, rw),
            ids: zeroed(gpu, "slc ids", count * 4, rw),
            rt2: zeroed(gpu, "slc rt2", count * 4, rw),
            r2: zeroed(gpu, "slc r2", count * 4, rw),
            near_slots: zeroed(gpu, "slc near_slots", count * 4, rw),
            near_boxes: zeroed(gpu, "slc near_boxes", count / NEAR_BLOCK as u64 * std::mem::size_of::<GpuNearBox>() as u64, rw),
            import: (kernel(Kernel::GbufferImport, &base, &import_layout)?, import_layout),
            pack: (kernel(Kernel::VplPack, &Features { vpl_source, ..base }, &pack_layout)?, pack_layout),
            update: (kernel(Kernel::LightUpdate, &base, &update_layout)?, update_layout),
            tiled,
            tiled_layout,
            denoise: (kernel(Kernel::VplDenoise, &base, &denoise_layout)?, denoise_layout),
            near: (near, near_layout),
            export: (kernel(Kernel::IrradianceExport, &Features { output_format: output, ..base }, &export_layout)?, export_layout),
        };
        gpu.take_errors()?;
        Ok(s)
    }

    /// The descriptor the pass was built for.
    pub fn desc(&self) -> &IndirectPassDesc {
        &self.desc
    }

    /// Checks `inputs` against the descriptor (formats, sizes, usages).
    pub fn check(&self, inputs: &IndirectInputs) -> Result<(), GpuError> {
        let size = (self.desc.width, self.desc.height);
        let tex = wgpu::TextureUsages::TEXTURE_BINDING;
        check_gbuffer(inputs.position, inputs.normal, size)?;
        check_view("output", inputs.output, size, &[self.desc.output_format], wgpu::TextureUsages::STORAGE_BINDING)?;
        match (inputs.vpls, self.desc.vpls) {
            (VplInput::Rsm { position, normal, flux }, VplSourceDesc::Rsm { size }) => {
                check_view("RSM position", position, (size, size), &FLOAT_INPUTS, tex)?;
                check_view("RSM normal", normal, (size, size), &FLOAT_INPUTS, tex)?;
                check_view("RSM flux", flux, (size, size), &FLOAT_INPUTS, tex)?;
            }
            (VplInput::Buffer(b), VplSourceDesc::Buffer { count }) => {
                let need = count as u64 * std::mem::size_of::<GpuVplRecord>() as u64;
                if b.size() < need || !b.usage().contains(wgpu::BufferUsages::STORAGE) {
                    return Err(GpuError::Binding {
                        name: "VPL buffer",
                        expected: format!("at least {need} bytes ({count} GpuVplRecords) with STORAGE usage"),
                        found: format!("{} bytes, {:?}", b.size(), b.usage()),
                    });
                }
            }
            (VplInput::Rsm { .. }, VplSourceDesc::Buffer { .. }) => {
                return Err(GpuError::Binding {
                    name: "VPLs",
                    expected: "a VPL buffer (the pass was built for one)".into(),
                    found: "RSM textures".into(),
                });
            }
            (VplInput::Buffer(_), VplSourceDesc::Rsm { .. }) => {
                return Err(GpuError::Binding {
                    name: "VPLs",
                    expected: "RSM textures (the pass was built for an RSM)".into(),
                    found: "a buffer".into(),
                });
            }
        }
        Ok(())
    }

    /// Records the frame into `encoder` (one compute pass); checks the
    /// inputs and settings first and records nothing when they are wrong.
    pub fn record(
        &self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        inputs: &IndirectInputs,
        frame: &IndirectFrame,
    ) -> Result<(), GpuError> {
        let dispatches = self.dispatches(gpu, inputs, frame)?;
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("slc indirect"), timestamp_writes: None });
        for d in &dispatches {
            d.record(&mut pass);
        }
        Ok(())
    }

    /// The frame's dispatches in order (only those its settings run), with
    /// their bind groups made; checks the inputs and settings first.
    pub(crate) fn dispatches<'a>(&'a self, gpu: &GpuContext, inputs: &IndirectInputs, frame: &IndirectFrame) -> Result<Vec<Dispatch<'a>>, GpuError> {
        self.check(inputs)?;
        let st = &frame.settings;
        let params = st.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
        if st.fixed_xi.is_some() || st.method == VplMethod::Reference {
            return Err(GpuError::Setting(
                "the indirect pass runs slc, clamp or none with per-frame ξ (fixed ξ and the reference are GpuVpl's)".into(),
            ));
        }
        if !(frame.min_distance.is_finite() && frame.min_distance >= 0.0 && frame.eye.is_finite()) {
            return Err(GpuError::Setting(format!("indirect pass: min distance {} and eye {} must be finite", frame.min_distance, frame.eye)));
        }
        let (w, h) = (self.desc.width, self.desc.height);
        let slc = st.method == VplMethod::Slc;
        let uniform = |label: &str, bytes: &[u8]| {
            gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytes,
                usage: wgpu::BufferUsages::UNIFORM,
            })
        };
        let image = uniform("slc image params", bytemuck::bytes_of(&ImageParams { eye: frame.eye, width: w, height: h, pad0: 0, pad1: 0, pad2: 0 }));
        let (rsm_size, count) = match self.desc.vpls {
            VplSourceDesc::Rsm { size } => (size, self.count),
            VplSourceDesc::Buffer { count } => (0, count),
        };
        let pack = uniform(
            "slc pack params",
            bytemuck::bytes_of(&PackParams {
                count,
                size: rsm_size,
                per_subset: self.per_subset,
                mode: params.measure().mode(),
                exposure: params.exposure(),
                error_bound: params.error_bound(),
                scale: slc_core::interleave::interleave_flux_scale(PERIOD),
                slc: slc as u32,
                fixed_r2: if st.method == VplMethod::Clamp { st.range * st.range } else { f32::MAX },
                pad0: 0,
                pad1: 0,
                pad2: 0,
            }),
        );
        let fp = uniform("slc frame params", bytemuck::bytes_of(&FrameParams { light_count: count, seed: st.seed, frame: st.frame, pad: 0 }));
        let min_d2 = frame.min_distance * frame.min_distance;
        let near_r2 = st.near_r2(min_d2);
        let near_blocks = count / NEAR_BLOCK;
        let vp = uniform(
            "slc vpl params",
            bytemuck::bytes_of(&VplParams {
                width: w,
                height: h,
                lights_per_subset: self.per_subset,
                min_d2,
                near_r2,
                near_blocks,
                pad0: 0,
                pad1: 0,
            }),
        );
        let group = |label: &str, layout: &wgpu::BindGroupLayout, res: &[(u32, wgpu::BindingResource)]| crate::kernel::group(gpu, label, layout, res);
        let buf = crate::kernel::whole;
        let import = group(
            "gbuffer_import",
            &self.import.1,
            &[
                (0, buf(&image)),
                (1, wgpu::BindingResource::TextureView(inputs.position)),
                (2, wgpu::BindingResource::TextureView(inputs.normal)),
                (3, buf(&self.gb_position)),
                (4, buf(&self.gb_normal)),
                (5, buf(&self.irradiance)),
            ],
        );
        let mut pack_res = vec![(0, buf(&pack))];
        match inputs.vpls {
            VplInput::Rsm { position, normal, flux } => pack_res.extend([
                (1, wgpu::BindingResource::TextureView(position)),
                (2, wgpu::BindingResource::TextureView(normal)),
                (3, wgpu::BindingResource::TextureView(flux)),
            ]),
            VplInput::Buffer(b) => pack_res.push((1, buf(b))),
        }
        pack_res.extend([
            (4, buf(&self.lights)),
            (5, buf(&self.ids)),
            (6, buf(&self.rt2)),
            (7, buf(&self.r2)),
            (8, buf(&self.near_slots)),
            (9, buf(&self.near_boxes)),
        ]);
        let pack_bg = group("vpl_pack", &self.pack.1, &pack_res);
        let update_bg = group("light_update", &self.update.1, &[(0, buf(&fp)), (1, buf(&self.ids)), (2, buf(&self.rt2)), (3, buf(&self.r2))]);
        let tiled_bg = group(
            "vpl_tiled",
            &self.tiled_layout,
            &[
                (0, buf(&vp)),
                (1, buf(&self.gb_position)),
                (2, buf(&self.gb_normal)),
                (3, buf(&self.lights)),
                (4, buf(&self.rt2)),
                (5, buf(&self.r2)),
                (6, buf(&self.irradiance)),
            ],
        );
        let result = if st.denoise { &self.filtered } else { &self.irradiance };
        let denoise_bg = group(
            "vpl_denoise",
            &self.denoise.1,
            &[(0, buf(&vp)), (1, buf(&self.gb_position)), (2, buf(&self.gb_normal)), (3, buf(&self.irradiance)), (4, buf(&self.filtered))],
        );
        let near_bg = group(
            "vpl_near",
            &self.near.1,
            &[
                (0, buf(&vp)),
                (1, buf(&self.gb_position)),
                (2, buf(&self.gb_normal)),
                (3, buf(&self.lights)),
                (4, buf(&self.near_slots)),
                (5, buf(&self.near_boxes)),
                (6, buf(&self.rt2)),
                (7, buf(&self.r2)),
                (8, buf(result)),
            ],
        );
        let export_bg = group(
            "irradiance_export",
            &self.export.1,
            &[(0, buf(&image)), (1, buf(&self.gb_position)), (2, buf(result)), (3, wgpu::BindingResource::TextureView(inputs.output))],
        );
        let tiled = &self.tiled.iter().find(|(m, _)| *m == st.method).ok_or(GpuError::Setting("unknown method".into()))?.1;
        let near = &self.near.0.iter().find(|(m, _)| *m == st.method).ok_or(GpuError::Setting("unknown method".into()))?.1;
        let (gx, gy) = (w.div_ceil(TILE), h.div_ceil(TILE));
        let (sub_w, sub_h) = (w.div_ceil(PERIOD), h.div_ceil(PERIOD));
        let d = Dispatch::new;
        let mut out =
            vec![d("G-buffer import", &self.import.0, import, [gx, gy, 1]), d("VPL generation", &self.pack.0, pack_bg, [near_blocks, 1, 1])];
        if slc {
            out.push(d("light update", &self.update.0, update_bg, [count.div_ceil(WG), 1, 1]));
        }
        out.push(d("shading", tiled, tiled_bg, [sub_w.div_ceil(TILE), sub_h.div_ceil(TILE), PERIOD * PERIOD]));
        if st.denoise {
            out.push(d("denoise", &self.denoise.0, denoise_bg, [gx, gy, 1]));
        }
        if near_r2 > 0.0 {
            out.push(d("near field", near, near_bg, [gx, gy, 1]));
        }
        out.push(d("irradiance export", &self.export.0, export_bg, [gx, gy, 1]));
        Ok(out)
    }
}

/// Uploads `data` as a storage buffer of the device (a helper for engines
/// and tests that make VPL records on the host).
pub fn vpl_buffer(gpu: &GpuContext, records: &[GpuVplRecord]) -> wgpu::Buffer {
    storage(gpu, "slc vpl records", bytemuck::cast_slice(records), wgpu::BufferUsages::empty())
}
