//! The indirect-light pass: application A on an engine's G-buffer.
//!
//! SLC shading of VPLs (the paper's first application) on the engine's
//! G-buffer, into a texture the engine owns. Recorded dispatches, in one
//! compute pass: `vpl_pack` (RSM texels or VPL records → the light
//! buffer, subset after subset, each subset's image in map order, flux ×
//! P², `r_t²`), `light_update` (SLC: `r² = r_t²/(1−ξ)` with `ξ =
//! xi_for(seed, frame, id)`, the CPU's numbers), `vpl_clusters` and
//! `vpl_groups` (the boxes of the two culling hierarchies, slc-core's
//! `cluster`: each subset's clusters of 8×8 texels and groups of 8×8
//! clusters for the far field, the whole RSM's for the near field),
//! `vpl_tiled` (per 8×8 tile of an interleaved sub-image, the subset's
//! hierarchy culled into the tile's light list and shaded: the far field
//! of the near-field split; it also writes zero where no surface is),
//! `vpl_denoise` (cross-bilateral, when `settings.denoise`), `vpl_near`
//! (the near field: every VPL closer than `R_n`, culled through the
//! RSM's hierarchy per 8×8 tile, added after the denoise; when `R_n > 0`)
//! and `irradiance_export`. [`IndirectPass::count_work`] runs a record
//! with counting kernels and returns the culling work both fields did.
//!
//! | input | format | size | usage | content |
//! |---|---|---|---|---|
//! | `gbuffer.surface` | `Depth32Float` or `R32Float` (depth), or `Rgba32Float`/`Rgba16Float` (positions) as the descriptor's [`SurfaceDesc`] says | `width × height` | `TEXTURE_BINDING` | depth with the view's inverse view-projection, or world position (`w > 0` where a surface is) |
//! | `gbuffer.normal` | `Rgba32Float` or `Rgba16Float` | `width × height` | `TEXTURE_BINDING` | world normal facing the camera (xyz); `w`: the material index (glossy pass), else unused |
//! | RSM `position`, `normal`, `flux` | `Rgba32Float` or `Rgba16Float` | `s × s`, `s` a multiple of 8 | `TEXTURE_BINDING` | per texel the surface the light sees, its normal and the flux it reflects (incident × albedo); zero flux where nothing is hit; a texel's flux shrinks as `1/s²`, so prefer `Rgba32Float` for flux (half floats go subnormal below 6·10⁻⁵: at 256² a half-float flux target zeroed 28% of the default box's lit texels) |
//! | VPL buffer | [`GpuVplRecord`] array | `count` records, `count` a multiple of 64 | `STORAGE` | position, normal, flux |
//! | `output` | the `output_format` of the descriptor (`Rgba16Float` or `Rgba32Float`) | `width × height` | `STORAGE_BINDING` | written: irradiance (rgb), lights kept (a); 0 where no surface |
//! | `materials.table` (glossy pass only) | [`GpuMaterial`] array | at least one entry | `STORAGE` | glTF metallic-roughness per material; a pixel's entry is the index in `gbuffer.normal`'s `w` |
//! | `materials.specular` (glossy pass only) | the `output_format` | `width × height` | `STORAGE_BINDING` | written: the specular correction `S` (rgb); 0 where no surface |
//!
//! **Materials** (optional, [`IndirectPassDesc::glossy`]): without them
//! the pass is Lambertian, as the paper's: the engine composes `ρ/π · E`.
//! A pass built glossy takes [`IndirectInputs::materials`] every record:
//! a table of [`GpuMaterial`]s (glTF metallic-roughness; the path tracer's
//! and the frame's) and, in the normal texture's `w`, each pixel's index
//! into it (an `Rgba16Float` normal holds indices up to 2048 exactly). At
//! a pixel whose material has a specular lobe, every kept VPL adds its term
//! of the specular correction `S = Σ Φ ⊙ (f(l, v) − c_diff/π)·T·share`
//! (slc-core's `specular_correction`, `v` toward the G-buffer's `eye`):
//! the same lights, ξ, `1/p` weights, near and far shares and transfer
//! `T` as `E`, denoised by the same filter (a second `vpl_denoise`), the
//! near field added after it. The engine composes `c_diff/π · E + S`
//! with `c_diff = (1 − m)·b` (slc-core's `glossy_radiance`; a material
//! without a specular lobe keeps `ρ/π · E`, and `S` is 0 there).
//!
//! **What a frame estimates.** Each stage's expectation over frames (a new
//! `frame` every frame), against every VPL at every pixel:
//! - *interleaving* is unbiased per pixel: each frame shifts which subset
//!   a pixel's class shades ([`slc_core::interleave::interleave_shift`],
//!   stratified: frames `0..64` give every pixel every subset once), so the
//!   mean of 64 consecutive unculled frames is the reference to f32
//!   rounding (`tests/tests/indirect_pass.rs`). A fixed map would be a
//!   structured subsampling with an offset no number of frames removes
//!   (−0.30% of the Cornell box's mean irradiance at 256²);
//! - the *near field* split changes no expectation (a partition of each
//!   VPL's transfer), nor does *stochastic culling* (over ξ);
//! - the *denoise* is a smoothing: each pixel's normalised cross-bilateral
//!   average over a window an edge cuts to one side does not keep the
//!   image's sum. Its expectation is the filter of the true far field plus
//!   the near field; measured on the Cornell box (65,536 VPLs, defaults,
//!   64 frames; `cargo run --release -p slc-cpu --example indirect_offset --
//!   512 256 64`, the CPU backend running the same filter), the image mean
//!   of the irradiance is +0.000% (interleave), +0.000% (+ near field) and
//!   **+0.35%** (+ denoise) off the reference at 512², +0.48% at 256²
//!   (`… -- 256 256 64`); with SLC at ε = 0.004, +0.04 ± 0.14% and +0.39 ±
//!   0.14% (one frame's image mean moves by 1.1%). Turn `denoise` off, or
//!   accumulate with a temporal filter that does not denoise, where the
//!   image mean must be exact.
//!
//! Views must show mip level 0 of the whole texture in its own format. A
//! wrong format, size or usage is a [`GpuError::Binding`] before anything is
//! recorded; limits the device lacks are [`GpuError::Limit`]s at
//! [`IndirectPass::new`]. The pass keeps its own intermediate buffers
//! (light buffer, ranges, irradiance), reused by every record: records run
//! in order, each with its own uniforms (copied into place by its own
//! encoder), so any number may share a submission.
//!
//! The G-buffer is read in place, as the [`DirectPass`](super::DirectPass)
//! reads it: `vpl_tiled`, `vpl_near` and `irradiance_export` load the
//! surface (unprojecting depth with the view's inverse view-projection)
//! and the normal from the engine's textures once per pixel; `vpl_tiled`
//! also writes each pixel's unit normal and distance from the eye (the
//! denoise's depth) into the pass's guide buffer, which `vpl_denoise`
//! reads for every neighbour in its window (one texel a tap, not an
//! unprojection). Depth input, standard and reversed Z, gives the
//! positions' image (`tests/tests/indirect_pass.rs`).
//!
//! ```no_run
//! # fn frame(device: wgpu::Device, queue: wgpu::Queue, gb_position: wgpu::TextureView,
//! #          gb_normal: wgpu::TextureView, rsm: [wgpu::TextureView; 3], output: wgpu::TextureView)
//! #          -> Result<(), Box<dyn std::error::Error>> {
//! use slc_wgpu::{GpuContext, RangeParams};
//! use slc_wgpu::passes::{Culling, GBuffer, IndirectInputs, IndirectPass, IndirectPassDesc, IndirectSettings, Surface, VplInput, VplSourceDesc};
//!
//! let gpu = GpuContext::from_device(device.clone(), queue.clone());
//! let mut pass = IndirectPass::new(&gpu, &IndirectPassDesc::new(1920, 1080, VplSourceDesc::Rsm { size: 256 }))?;
//! let mut encoder = device.create_command_encoder(&Default::default());
//! // ... the engine's G-buffer and RSM passes ...
//! let inputs = IndirectInputs {
//!     gbuffer: GBuffer { surface: Surface::Position(&gb_position), normal: &gb_normal, eye: slc_wgpu::glam::Vec3::new(0.0, 1.0, 3.5) },
//!     vpls: VplInput::Rsm { position: &rsm[0], normal: &rsm[1], flux: &rsm[2] },
//!     output: &output,
//!     // A pass built with `glossy: true` takes the material table and a specular target here.
//!     materials: None,
//! };
//! let settings = IndirectSettings { culling: Culling::Stochastic(RangeParams::new(0.008, 1.0)?), ..IndirectSettings::default() };
//! pass.record(&mut encoder, &inputs, &settings)?;
//! // ... the engine composes `output` × albedo with its direct light ...
//! queue.submit([encoder.finish()]);
//! # Ok(()) }
//! ```

mod counting;
mod dispatches;
mod hierarchy;
mod inputs;

#[cfg(doc)]
use super::SurfaceDesc;
use super::{Culling, ViewCache, check_size, kernel_form, output_format};
use crate::kernel::{KernelLayout, UniformSlots, check_kernels, zeroed};
use crate::record::{Dispatch, Recording, Uploads};
use crate::timing::Stage;
use crate::{GpuContext, GpuError};
use counting::{CountGroups, Counting};
use hierarchy::Hierarchy;
pub use inputs::{
    IndirectInputs, IndirectMaterials, IndirectPassDesc, IndirectSettings, TILE_LIST, VplInput,
    VplSourceDesc, vpl_buffer,
};
use slc_core::cluster::CLUSTER;
use slc_core::interleave::interleave_shift;
use slc_scene::vpl::{PERIOD, WorkCounts};
use slc_shared_shaders::layout::{
    FrameParams, GpuBox, GpuLight, PackParams, ViewParams, VplParams,
};
#[cfg(doc)]
use slc_shared_shaders::layout::{GpuMaterial, GpuVplRecord};
use slc_shared_shaders::{CullKind, Features, Kernel, LightTypes, VplSource};

/// Tile edge of the 2-D kernels (`vpl_tiled`'s in sub-image pixels), in
/// pixels.
pub const TILE: u32 = 8;
/// Workgroup size of the 1-D kernels.
const WG: u32 = 64;

/// The bind groups of the kernels that read the engine's G-buffer in place
/// (besides the export, whose group also binds the output), for one pair
/// of surface and normal views.
#[derive(Clone)]
struct GbufferGroups {
    tiled: wgpu::BindGroup,
    /// `vpl_near` adding to the raw irradiance (0) or the denoised one (1).
    near: [wgpu::BindGroup; 2],
}

/// A kernel's layout and pipeline.
struct Pipe {
    layout: KernelLayout,
    pipeline: wgpu::ComputePipeline,
}

impl Pipe {
    fn new(gpu: &GpuContext, kernel: Kernel, f: &Features) -> Result<Pipe, GpuError> {
        let layout = KernelLayout::new(gpu, kernel, f)?;
        Ok(Pipe { pipeline: layout.pipeline(gpu, f, None)?, layout })
    }
}

/// SLC indirect light from VPLs on an engine's G-buffer (see the module
/// docs for the inputs it expects).
pub struct IndirectPass {
    gpu: GpuContext,
    desc: IndirectPassDesc,
    /// The light buffer's slots and the culling hierarchies' boxes.
    hierarchy: Hierarchy,
    /// The pass's features (the counting kernels' base).
    features: Features,
    pack: Pipe,
    update: Pipe,
    /// `vpl_clusters` per culling kind (the near field's radii) and its
    /// bind group.
    clusters: Vec<(CullKind, wgpu::ComputePipeline)>,
    clusters_group: wgpu::BindGroup,
    /// `vpl_groups` and its bind group.
    groups: Pipe,
    groups_group: wgpu::BindGroup,
    /// The counting kernels, built at the first [`IndirectPass::count_work`].
    counting: Option<Counting>,
    tiled_layout: KernelLayout,
    tiled: Vec<(CullKind, wgpu::ComputePipeline)>,
    denoise: Pipe,
    /// The denoise's groups: of the irradiance, then (glossy pass) of the
    /// specular correction, each into its filtered buffer, guided by the
    /// guide buffer (none of them binds the engine's G-buffer).
    denoise_groups: Vec<wgpu::BindGroup>,
    near_layout: KernelLayout,
    /// `vpl_near` per culling method (its ranges culled as the far field's).
    near: Vec<(CullKind, wgpu::ComputePipeline)>,
    export: Pipe,
    view: UniformSlots,
    pack_params: UniformSlots,
    frame_params: UniformSlots,
    vpl_params: UniformSlots,
    update_group: wgpu::BindGroup,
    /// Keyed by the surface and normal views and the material table.
    gbuffer_cache:
        ViewCache<(wgpu::TextureView, wgpu::TextureView, Option<wgpu::Buffer>), GbufferGroups>,
    pack_cache: ViewCache<PackKey>,
    /// Keyed by the surface, normal, output and specular views and the denoise.
    export_cache: ViewCache<(
        wgpu::TextureView,
        wgpu::TextureView,
        wgpu::TextureView,
        Option<wgpu::TextureView>,
        bool,
    )>,
    irradiance: wgpu::Buffer,
    filtered: wgpu::Buffer,
    /// The denoise's guide (each pixel's normal and eye distance), written
    /// by `vpl_tiled`.
    guide: wgpu::Buffer,
    /// The specular correction, raw and denoised (glossy pass).
    specular: Option<[wgpu::Buffer; 2]>,
    pack_outputs: [wgpu::Buffer; 5],
    /// Both hierarchies' cluster and group boxes.
    boxes: wgpu::Buffer,
}

/// What `vpl_pack`'s cached bind group binds: RSM views or a buffer.
#[derive(PartialEq)]
enum PackKey {
    Rsm(Box<[wgpu::TextureView; 3]>),
    Buffer(wgpu::Buffer),
}

impl IndirectPass {
    /// Builds the pipelines and intermediate buffers for `desc`. Checks the
    /// sizes (non-zero image, RSM edge or VPL count a multiple of the
    /// interleave period) and every device limit first, before anything is
    /// created on the device.
    pub fn new(gpu: &GpuContext, desc: &IndirectPassDesc) -> Result<Self, GpuError> {
        let (w, h) = (desc.width, desc.height);
        check_size(gpu, "indirect pass", (w, h), TILE)?;
        // Near clusters are 8×8 texels or 64 records, interleaved or not.
        let subsets = PERIOD * PERIOD;
        let period = desc.period();
        if desc.tile_list < CLUSTER {
            return Err(GpuError::Setting(format!(
                "indirect pass: the tile light list must hold a cluster's {CLUSTER} lights, not {}",
                desc.tile_list
            )));
        }
        let (count, vpl_source) = match desc.vpls {
            VplSourceDesc::Rsm { size } if size == 0 || size % PERIOD != 0 => {
                return Err(GpuError::Setting(format!(
                    "indirect pass: RSM size {size} must be a positive multiple of {PERIOD}"
                )));
            }
            VplSourceDesc::Buffer { count } if count == 0 || count % subsets != 0 => {
                return Err(GpuError::Setting(format!(
                    "indirect pass: VPL count {count} must be a positive multiple of {subsets}"
                )));
            }
            VplSourceDesc::Rsm { .. } => (desc.vpls.count(), VplSource::Rsm),
            VplSourceDesc::Buffer { .. } => (desc.vpls.count(), VplSource::Buffer),
        };
        let output = output_format(desc.output_format)?;
        let surface = desc.surface.source()?;
        let lim = &gpu.limits;
        let max_binding = lim.max_storage_buffer_binding_size.min(lim.max_buffer_size);
        gpu.require(
            "max_storage_buffer_binding_size (irradiance)",
            w as u64 * h as u64 * 16,
            max_binding,
        )?;
        let hierarchy = Hierarchy::new(desc.vpls, period);
        let slots = hierarchy.slots();
        gpu.require(
            "max_storage_buffer_binding_size (lights)",
            slots * std::mem::size_of::<GpuLight>() as u64,
            max_binding,
        )?;
        gpu.require(
            "max_compute_workgroups_per_dimension (VPLs)",
            count.div_ceil(WG as u64),
            lim.max_compute_workgroups_per_dimension as u64,
        )?;
        gpu.require(
            "max_compute_workgroups_per_dimension (light update)",
            slots.div_ceil(WG as u64),
            lim.max_compute_workgroups_per_dimension as u64,
        )?;
        let list = desc.tile_list;

        let vpl = LightTypes { vpl: true, ..LightTypes::default() };
        let base = Features {
            lights: vpl,
            tile_size: TILE,
            interleave: period,
            workgroup_size: WG,
            max_tile_lights: list,
            surface,
            output_format: output,
            vpl_source,
            glossy: desc.glossy,
            ..Features::default()
        };
        for kernel in [Kernel::VplTiled, Kernel::VplNear] {
            gpu.require(
                "max_compute_workgroup_storage_size (tile light list)",
                slc_shared_shaders::vpl_workgroup_bytes(kernel, &base),
                lim.max_compute_workgroup_storage_size as u64,
            )?;
        }
        let kernels = [
            Kernel::VplPack,
            Kernel::LightUpdate,
            Kernel::VplClusters,
            Kernel::VplGroups,
            Kernel::VplTiled,
            Kernel::VplDenoise,
            Kernel::VplNear,
            Kernel::IrradianceExport,
        ];
        check_kernels(gpu, &kernels.map(|k| (k, &base, 0)))?;
        let mut tiled = Vec::new();
        let tiled_layout = KernelLayout::new(gpu, Kernel::VplTiled, &base)?;
        let near_layout = KernelLayout::new(gpu, Kernel::VplNear, &base)?;
        let clusters_layout = KernelLayout::new(gpu, Kernel::VplClusters, &base)?;
        let (mut near, mut clusters) = (Vec::new(), Vec::new());
        for m in CullKind::ALL {
            let fm = Features { method: m, ..base };
            tiled.push((m, tiled_layout.pipeline(gpu, &fm, None)?));
            near.push((m, near_layout.pipeline(gpu, &fm, None)?));
            clusters.push((m, clusters_layout.pipeline(gpu, &fm, None)?));
        }
        let pixels = w as u64 * h as u64 * 16;
        let rw = wgpu::BufferUsages::STORAGE;
        let view = UniformSlots::new::<ViewParams>(gpu, "slc indirect view", 1);
        let pack_params = UniformSlots::new::<PackParams>(gpu, "slc pack params", 1);
        let frame_params = UniformSlots::new::<FrameParams>(gpu, "slc frame params", 1);
        let vpl_params = UniformSlots::new::<VplParams>(gpu, "slc vpl params", 1);
        let irradiance = zeroed(gpu, "slc irradiance", pixels, rw);
        let filtered = zeroed(gpu, "slc filtered", pixels, rw);
        let guide = zeroed(gpu, "slc denoise guide", pixels, rw);
        let specular = desc.glossy.then(|| {
            [
                zeroed(gpu, "slc specular", pixels, rw),
                zeroed(gpu, "slc specular filtered", pixels, rw),
            ]
        });
        // Slots no VPL fills (a subset's padding) keep these zeros: no flux.
        let lights = zeroed(gpu, "slc lights", slots * std::mem::size_of::<GpuLight>() as u64, rw);
        let ids = zeroed(gpu, "slc ids", slots * 4, rw);
        let rt2 = zeroed(gpu, "slc rt2", slots * 4, rw);
        let r2 = zeroed(gpu, "slc r2", slots * 4, rw);
        let near_slots = zeroed(gpu, "slc near_slots", count * 4, rw);
        let boxes =
            zeroed(gpu, "slc boxes", hierarchy.boxes() * std::mem::size_of::<GpuBox>() as u64, rw);
        let pack = Pipe::new(gpu, Kernel::VplPack, &base)?;
        let update = Pipe::new(gpu, Kernel::LightUpdate, &base)?;
        let denoise = Pipe::new(gpu, Kernel::VplDenoise, &base)?;
        let export = Pipe::new(gpu, Kernel::IrradianceExport, &base)?;
        let groups = Pipe::new(gpu, Kernel::VplGroups, &base)?;
        let b = crate::kernel::whole;
        let clusters_group = clusters_layout.group(
            gpu,
            0,
            &[
                ("params", vpl_params.binding()),
                ("lights", b(&lights)),
                ("r2", b(&r2)),
                ("near_slots", b(&near_slots)),
                ("boxes", b(&boxes)),
            ],
        );
        let groups_group =
            groups.layout.group(gpu, 0, &[("params", vpl_params.binding()), ("boxes", b(&boxes))]);
        let denoise_of = |from: &wgpu::Buffer, to: &wgpu::Buffer| {
            denoise.layout.group(
                gpu,
                0,
                &[
                    ("params", vpl_params.binding()),
                    ("guide", b(&guide)),
                    ("irradiance", b(from)),
                    ("filtered", b(to)),
                ],
            )
        };
        let mut denoise_groups = vec![denoise_of(&irradiance, &filtered)];
        denoise_groups.extend(specular.as_ref().map(|[raw, done]| denoise_of(raw, done)));
        let update_group = update.layout.group(
            gpu,
            0,
            &[
                ("params", frame_params.binding()),
                ("ids", b(&ids)),
                ("rt2", b(&rt2)),
                ("r2", b(&r2)),
            ],
        );
        let s = IndirectPass {
            gpu: gpu.clone(),
            desc: *desc,
            hierarchy,
            features: base,
            pack,
            update,
            clusters,
            clusters_group,
            groups,
            groups_group,
            counting: None,
            tiled_layout,
            tiled,
            denoise,
            denoise_groups,
            near_layout,
            near,
            export,
            view,
            pack_params,
            frame_params,
            vpl_params,
            update_group,
            gbuffer_cache: ViewCache::new(),
            pack_cache: ViewCache::new(),
            export_cache: ViewCache::new(),
            pack_outputs: [lights, ids, rt2, r2, near_slots],
            boxes,
            irradiance,
            filtered,
            guide,
            specular,
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
        inputs.check(&self.desc, 0, 0).map(|_| ())
    }

    /// Records the frame into `encoder`: its uniforms' copy, then one
    /// compute pass. Checks the inputs and settings first and records
    /// nothing when they are wrong. Any number of records may share a
    /// submission, each with its own settings ([`passes`](super) docs).
    /// Creates no bind group when the views are those of a recent record.
    pub fn record(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        inputs: &IndirectInputs,
        settings: &IndirectSettings,
    ) -> Result<(), GpuError> {
        self.dispatches(inputs, settings, false)?.record(&self.gpu, encoder, "slc indirect");
        Ok(())
    }

    /// The culling work of one record of `settings` on `inputs`, far field
    /// then near field (slc-scene's [`WorkCounts`]; the near field's is
    /// zero without one, the far field's culling tests zero when it is
    /// unculled): records it with counting kernels (built at the first
    /// call), submits it and waits. The engine's inputs must be ready (their
    /// passes submitted); the output is written as by [`IndirectPass::record`]
    /// (Lambertian: a glossy pass's specular target is left alone). Never
    /// part of a timed frame: counting costs atomics in every loop.
    pub fn count_work(
        &mut self,
        inputs: &IndirectInputs,
        settings: &IndirectSettings,
    ) -> Result<(WorkCounts, WorkCounts), GpuError> {
        if self.counting.is_none() {
            self.counting = Some(Counting::new(&self.gpu, &self.features)?);
        }
        let recording = self.dispatches(inputs, settings, true)?;
        let gpu = self.gpu.clone();
        let counting = self.counting.as_ref().expect("built above");
        let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("slc indirect counted"),
        });
        counting.clear(&mut encoder);
        recording.record(&gpu, &mut encoder, "slc indirect counted");
        counting.copy_out(&mut encoder);
        gpu.queue.submit([encoder.finish()]);
        counting.read(&gpu)
    }
}
