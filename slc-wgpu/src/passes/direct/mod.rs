//! The many-lights direct pass: SLC shading of point, spot, IES and
//! triangle lights on an engine's G-buffer (the deferred many-lights case
//! that clustered renderers solve with hard, biased light ranges), into a
//! texture the engine owns, with the lights movable every frame.
//!
//! Recorded dispatches, in one compute pass: `light_ranges` (this record's
//! `r_t²` from each light's peak and the settings' culling, then
//! `r² = r_t²/(1−ξ)` with `ξ = xi_for(seed, frame, light)`), `bsh_refit`
//! (every level, deepest first, leaves moved to their lights' centres) and
//! `direct_light`, which reads the G-buffer in place (depth unprojected, or
//! positions) and writes the output texture: no G-buffer copy, no
//! intermediate image.
//!
//! **One walk per tile.** An 8×8 tile's invocations walk the light
//! hierarchy together, once: its 256 depth-8 subtrees dealt out among them,
//! each tested against the tile's box of positions at its pixels' largest
//! range-lobe scale (`slc_core::bsh::walk::bsh_reaches_box`), into a list
//! in workgroup memory (1,024 leaves at a time; a longer list in rounds).
//! Each pixel tests the listed leaves exactly (`bsh_reaches`): the lights
//! its own walk would find, in the same order, so the CPU twin
//! (`slc_cpu::direct`), which walks per pixel, draws the same picks.
//!
//! **Shadows.** Unshadowed by default: the engine owns visibility (its
//! shadow maps, or a ray query of its own). Given occluders
//! ([`DirectPass::set_shadows`]: slc-scene's [`Occluders`], the engine's
//! meshes and their instances), each pick casts one shadow ray through
//! their BVH in `direct_light` itself (the path tracer's `trace`, any-hit,
//! in plain WGSL: every adapter, lavapipe included), so the expectation is
//! the shadowed sum `Σᵢ Iᵢ(ω) cos θ V / d²`. The ray leaves the G-buffer's
//! surface along its normal by [`Shadows::normal_offset`] × the eye
//! distance (a reconstructed depth is only that precise), and ends at the
//! sampled point on the light, a relative `10⁻⁴` of its length short of
//! both ends. Moving instances: [`Occluders::set_transforms`], then
//! `set_shadows` again, which rewrites in place, through the queue, only
//! what moving changed: the moved instances' triangles (48 B each) and
//! nodes (32 B each) and the top level over the instances (no bind group
//! or pipeline rebuilt). Cost per pixel: at most `k` rays (the picks), each
//! a BVH walk; a light without area (point, spot, IES) picked more than
//! once casts one ray for all its picks.
//!
//! **Hardware shadow rays.** On a device with wgpu's experimental ray
//! queries ([`GpuContext::open_with`] with
//! [`GpuOptions::ray_query`](crate::GpuOptions)), [`Shadows::rays`] =
//! [`ShadowRays::RayQuery`] casts the same segments, with the same end
//! margins, as the adapter's ray queries through acceleration structures
//! built from the same occluders (a bottom level per mesh, a top level
//! over the instances, rebuilt when one moves: `crate::occluders`). A ray
//! may decide an edge-grazing hit differently (the adapter's triangle
//! test against `geometry.wgsl`'s), nothing else: `tests/tests/direct_shadows.rs`
//! compares both on a ray-query adapter (Mesa 25's lavapipe in CI). The
//! builds are recorded into the next record's encoder, before its
//! dispatches (the pass submits nothing); the flattened BVH's buffers stay
//! beside the acceleration structures, and [`DirectPass::count_work`]
//! counts the software walk's rays and nodes. [`DirectPass::shadow_rays`]
//! says which rays a pass casts.
//!
//! | input | format | size | usage | content |
//! |---|---|---|---|---|
//! | `gbuffer.surface` | `Depth32Float` or `R32Float` (depth), or `Rgba32Float`/`Rgba16Float` (positions) as the descriptor's [`SurfaceDesc`] says | `width × height` | `TEXTURE_BINDING` | depth with the view's inverse view-projection, or world position (`w > 0` where a surface is) |
//! | `gbuffer.normal` | `Rgba32Float` or `Rgba16Float` | `width × height` | `TEXTURE_BINDING` | world normal facing the camera (xyz; `w` unused) |
//! | `output` | the descriptor's `output_format` (`Rgba16Float` or `Rgba32Float`) | `width × height` | `STORAGE_BINDING` | written: irradiance (rgb), lights in range (a); 0 where no surface is |
//!
//! The engine multiplies the irradiance by `albedo/π` (a diffuse surface),
//! or asks for more ([`DirectOutputs`]) and gives the G-buffer's glTF
//! metallic-roughness material ([`MaterialInputs`]):
//!
//! | input | format | size | usage | content |
//! |---|---|---|---|---|
//! | `material.base_color` | `Rgba8Unorm`, `Rgba8UnormSrgb`, `Rgba16Float` or `Rgba32Float` | `width × height` | `TEXTURE_BINDING` | linear base colour (rgb) |
//! | `material.metallic_roughness` | the same formats | `width × height` | `TEXTURE_BINDING` | glTF's layout: perceptual roughness (g), metallic (b) |
//! | `specular` (`Split` only) | the output format | `width × height` | `STORAGE_BINDING` | written: the specular lobe's outgoing radiance (rgb) |
//!
//! `Radiance` writes the outgoing radiance toward the eye `Σ f(v, l) I cos θ / d²`
//! with slc-core's `brdf` (the glTF 2.0 reference BRDF: Lambert diffuse
//! weighted by `1 − F`, GGX with height-correlated Smith visibility,
//! Schlick Fresnel, the metal/dielectric mix); `Split` writes the
//! irradiance (the engine applies its own diffuse lobe) and, to a second
//! target, the specular radiance. On a glossy receiver the error bound ε no
//! longer caps one light's deviation (its derivation assumes `ρ ≤ 1/π`):
//! a sharp highlight of a light just inside its range is weighted by `1/p`
//! like any other pick, unbiased but noisier.
//!
//! **The estimator.** At a pixel `x`, the lights whose random range
//! reaches it are the candidates (the BSH finds them). The pass shades `k`
//! of them ([`DirectSelection`]) and weights each so that the expectation
//! over ξ and the picks is the unculled sum `Σᵢ Iᵢ(ω) cos θ / d²`:
//! - `Weighted { k }` (the default, `slc-weighted`): each candidate gets
//!   `wᵢ = ĝᵢ/pᵢ` (its importance bound over its roulette probability), `k`
//!   independent picks with probability `wᵢ/W`, each weighted `W/(k·wᵢ)`
//!   and `1/p`. Its noise is smallest where one light dominates.
//! - `Resampled { k }`: resampled importance sampling over the candidates.
//!   Each is sampled (a point on a triangle) and evaluated without a
//!   shadow ray, `cᵢ` (the `1/p` of its roulette included); pick `j` of
//!   `k` (an independent one-slot reservoir) takes candidate `i` with
//!   probability `pᵢ/P`, `pᵢ` one colour channel of `cᵢ` (channel
//!   `j mod 3`; the channel mean for `k < 3`: slc-core's `slot_target`)
//!   and `P` their sum, and adds that channel of its contribution,
//!   shadowed, weighted `P/pᵢ` over the `⌊(k + 2 − c)/3⌋` picks of channel
//!   `c` (`slot_share`). The rays go only where light arrives unshadowed,
//!   in proportion to it: what the bound misses (a spot's cone, an IES
//!   profile, the BRDF, the roulette at the sampled point) adds no noise,
//!   and neither do the lights' colours (a target shared by the channels
//!   picks a red light as often for blue as for red). Each candidate costs
//!   a full evaluation instead of a bound. Measured on lavapipe, one
//!   frame's relative error at k = 8 (docs/results/reused-picks.md): 200
//!   point and spot lights among shadowing boxes
//!   (`tests/tests/direct_shadows.rs`) 0.115 against weighted picks' 0.237,
//!   both at most 8 rays per pixel; 3,000 unshadowed coloured point
//!   lights, 222 in range per pixel (`tests/tests/engine_direct.rs`), 0.022
//!   per channel against 0.074; slc-bevy's headless scene (coloured point
//!   and spot lights, Bevy's BRDF) 0.0017 against 0.086 (luminance RMSE).
//!   slc-bevy picks this way by default. GPU timing pending.
//!
//!   **Reuse** ([`DirectPassDesc::reuse`], [`DirectReuse`]): each of the
//!   `k` resampled picks is a reservoir with an unbiased contribution
//!   weight, combined every record with the same reservoir of the previous
//!   record's pixel this point reprojects to (generalized RIS with the
//!   balance heuristic over whole, unranged, unshadowed targets; the
//!   previous pixel's target with the previous lights), so a pick stands
//!   for up to `max_confidence` frames of candidates and the culling's
//!   noise averages over them; still unbiased. Measured on lavapipe, the
//!   8th frame (`tests/tests/direct_shadows.rs`, `engine_direct.rs`,
//!   docs/results/reused-picks.md): the shadow test 0.089 against
//!   resampling's 0.115 and weighted picks' 0.237; the unshadowed
//!   engine-pass scene per channel 0.0083 against weighted picks' 0.074
//!   (0.11), its r + g + b 0.0081 against 0.0378; slc-bevy's luminance
//!   RMSE 0.00022 against 0.086. Where shadows are the noise, plain reuse
//!   barely helps (the engine-pass scene shadowed by its boxes: per
//!   channel 0.99 of weighted picks'); [`DirectReuse::visibility`] shadows
//!   each record's own picks before they meet the history: 4 picks reach
//!   0.23 of 8 weighted picks' relative RMSE there after 32 still frames,
//!   at no more rays (7.2 per pixel against 7.4), and the shadow test's 8
//!   picks 0.032 after 8 (unbiased where things move too, at one more
//!   ray per pick where the camera or its light moved: see its docs). It
//!   is [`DirectReuse::default`]'s: 3 picks of it cast fewer rays than 8
//!   of plain reuse in a still view at 0.58 of their error, and as many
//!   while the camera pans.
//! - `Uniform { k }`: `k` picks uniform among the `n` candidates (Algorithm
//!   R), weighted `n/k` and `1/p`: the paper's reservoir.
//! - `All`: every candidate, weighted `1/p` (exact given ξ): for small
//!   ranges; its cost grows with the number in range.
//!
//! **Work counters** ([`DirectPass::count_work`], [`DirectCounts`]): a
//! counting variant of `direct_light` sums per record the shaded pixels,
//! the lights in range, the lights evaluated without a ray, the shadow
//! rays and the occluder BVH nodes they visit: the pass's work measured
//! on any adapter (lavapipe: the shadow test's 200 lights, resampled
//! picks, 82 candidates, 82 evaluations, 7.0 rays and 92 nodes per pixel;
//! reused, 114 evaluations, 7.2 rays, 96 nodes; `tests/tests/direct_shadows.rs`
//! checks the rays and nodes against a CPU walk of the same tree).
//!
//! With stochastic culling each light adds at most ε to a pixel's standard
//! deviation (Lambertian receiver) and the picks add their own noise: a
//! single frame is noisy by design. Vary `frame` every frame and
//! accumulate (a temporal filter, or a denoiser): the mean over frames
//! converges to the unculled light. [`Culling::None`] makes every light a
//! candidate everywhere, so the `k` picks are spread over all of them:
//! exact in expectation and the noisiest setting, not a reference image.
//!
//! ```no_run
//! # fn frame(device: wgpu::Device, queue: wgpu::Queue, depth: wgpu::TextureView,
//! #          normal: wgpu::TextureView, output: wgpu::TextureView, inv_view_proj: slc_wgpu::glam::Mat4)
//! #          -> Result<(), Box<dyn std::error::Error>> {
//! use slc_wgpu::glam::Vec3;
//! use slc_wgpu::{GpuContext, Light, LightSet, PointLight, RangeParams};
//! use slc_wgpu::passes::{Culling, DirectInputs, DirectPass, DirectPassDesc, DirectSettings, GBuffer, Surface};
//!
//! let gpu = GpuContext::from_device(device.clone(), queue.clone());
//! // The engine's lights (here 10,000 points on a grid).
//! let mut lights: Vec<Light> = (0..10_000)
//!     .map(|i| Light::Point(PointLight::new(Vec3::new((i % 100) as f32, 3.0, (i / 100) as f32), Vec3::splat(5.0)).unwrap()))
//!     .collect();
//! let mut pass = DirectPass::new(&gpu, &LightSet::new(lights.clone())?, &DirectPassDesc::new(1920, 1080))?;
//! for frame in 0..3 {
//!     // The lights move: rewritten in place, no pipeline rebuilt.
//!     lights[0] = Light::Point(PointLight::new(Vec3::new(frame as f32, 3.0, 0.0), Vec3::splat(5.0))?);
//!     pass.update_lights(&lights)?;
//!     let mut encoder = device.create_command_encoder(&Default::default());
//!     // ... the engine's depth and normal passes ...
//!     let gbuffer = GBuffer { surface: Surface::Depth { depth: &depth, inv_view_proj }, normal: &normal, eye: Vec3::new(0.0, 1.7, 5.0) };
//!     let settings = DirectSettings { culling: Culling::Stochastic(RangeParams::new(0.008, 1.0)?), seed: 1, frame };
//!     pass.record(&mut encoder, &DirectInputs::new(gbuffer, &output), &settings)?;
//!     queue.submit([encoder.finish()]);
//! }
//! # Ok(()) }
//! ```

mod counting;
mod inputs;

pub use counting::DirectCounts;
pub use inputs::{
    Dielectric, DirectInputs, DirectOutputs, DirectPassDesc, DirectReuse, DirectSelection,
    DirectSettings, DirectWalk, MaterialInputs, ShadowRays, Shadows,
};

#[cfg(doc)]
use super::SurfaceDesc;
use super::{Culling, ViewCache, check_size, kernel_form, output_format};
use crate::kernel::{KernelLayout, UniformSlots, check_kernels, zeroed};
use crate::lights::{GpuLightSet, WG, check_light_limits};
use crate::occluders::{GpuOccluders, Moved, check_accel_limits, check_limits};
use crate::record::Uploads;
use crate::{GpuContext, GpuError};
use counting::Counting;
use glam::{Mat4, Vec3};
use slc_core::light::Light;
use slc_scene::lights::LightSet;
#[cfg(doc)]
use slc_scene::occluders::Occluders;
use slc_shared_shaders::layout::{CullParams, ReuseParams, ViewParams};
use slc_shared_shaders::{DirectOutput, Features, Kernel, LightTypes, Selection};

/// Tile edge of the 2-D kernels, in pixels.
const TILE: u32 = 8;

/// A kernel's pipeline and layout.
type Pipe = (wgpu::ComputePipeline, KernelLayout);

/// SLC direct light from a light set on an engine's G-buffer (see the
/// module docs for the inputs it expects).
pub struct DirectPass {
    gpu: GpuContext,
    desc: DirectPassDesc,
    /// The unshadowed kernel's features (the shadowed one sets `shadows`,
    /// and `ray_query` for [`ShadowRays::RayQuery`]).
    features: Features,
    set: GpuLightSet,
    ranges: Pipe,
    ranges_group: wgpu::BindGroup,
    /// `direct_light`, shadowed when `occluders` is set.
    shade: Pipe,
    /// The features of `shade`.
    shade_features: Features,
    /// The variant of `direct_light` active before, once built, and its
    /// features.
    other: Option<(Features, Pipe)>,
    /// The occluders' buffers and the normal offset.
    occluders: Option<(GpuOccluders, f32)>,
    /// `direct_light`'s group 1.
    lights_group: wgpu::BindGroup,
    cull: UniformSlots,
    view: UniformSlots,
    cache: ViewCache<Vec<wgpu::TextureView>>,
    /// The reuse's buffers and history, with [`DirectPassDesc::reuse`].
    reuse: Option<Reuse>,
    /// The counting variant, built at the first [`DirectPass::count_work`].
    counting: Option<Counting>,
}

/// The reuse's state: its uniforms, the reservoir buffer (two halves of
/// one entry per pixel: this record writes half `parity` and reads the
/// other), the previous record's lights, and its view-projection and eye
/// (none: no history), and where the occluders changed since it.
struct Reuse {
    settings: DirectReuse,
    params: UniformSlots,
    pixels: wgpu::Buffer,
    lights_prev: wgpu::Buffer,
    parity: usize,
    previous: Option<(Mat4, Vec3)>,
    moved: Moved,
}

impl DirectPass {
    /// Uploads the lights and their BSH and builds the pipelines for
    /// `desc`; checks the sizes, the light types and every device limit
    /// first, before anything is created on the device.
    pub fn new(
        gpu: &GpuContext,
        lights: &LightSet,
        desc: &DirectPassDesc,
    ) -> Result<Self, GpuError> {
        let (w, h) = (desc.width, desc.height);
        check_size(gpu, "direct pass", (w, h), TILE)?;
        let output = output_format(desc.output_format)?;
        let surface = desc.surface.source()?;
        let (selection, k) = match desc.selection {
            DirectSelection::Weighted { k } => (Selection::Weighted, k),
            DirectSelection::Resampled { k } => (Selection::Resampled, k),
            DirectSelection::Uniform { k } => (Selection::Reservoir, k),
            DirectSelection::All => (Selection::All, 1),
        };
        if !(1..=64).contains(&k) {
            return Err(GpuError::Setting(format!("direct pass: k = {k} picks must be in 1..=64")));
        }
        if desc.light_types.is_empty() {
            return Err(GpuError::Setting(
                "direct pass: DirectPassDesc::light_types compiles no light type".into(),
            ));
        }
        check_types(lights.lights(), desc.light_types)?;
        let direct_output = match desc.outputs {
            DirectOutputs::Irradiance => DirectOutput::Irradiance,
            DirectOutputs::BevyRadiance => DirectOutput::BevyRadiance,
            DirectOutputs::Radiance(d) | DirectOutputs::Split(d) => {
                if !(d.f0.is_finite()
                    && d.f0.min_element() >= 0.0
                    && d.f90.is_finite()
                    && d.f90 >= 0.0)
                {
                    return Err(GpuError::Setting(format!(
                        "direct pass: dielectric F0 {} and F90 {} must be finite and non-negative",
                        d.f0, d.f90
                    )));
                }
                if matches!(desc.outputs, DirectOutputs::Radiance(_)) {
                    DirectOutput::Radiance
                } else {
                    DirectOutput::Split
                }
            }
        };
        let reuse_domains = match desc.reuse {
            None => 0,
            Some(r) => {
                r.check()?;
                if selection != Selection::Resampled {
                    return Err(GpuError::Setting(format!(
                        "direct pass: reuse needs DirectSelection::Resampled picks, not {:?}",
                        desc.selection
                    )));
                }
                r.neighbours + 1
            }
        };
        let features = Features {
            reuse_domains,
            direct_output,
            lights: desc.light_types,
            reservoir_k: k,
            selection,
            surface,
            output_format: output,
            tile_size: TILE,
            workgroup_size: WG,
            shadows: false,
            tile_walk: desc.walk == DirectWalk::Tile,
            ..Features::default()
        };
        gpu.require(
            "max_compute_workgroup_storage_size (direct pass tile list)",
            slc_shared_shaders::direct_workgroup_bytes(&features),
            gpu.limits.max_compute_workgroup_storage_size as u64,
        )?;
        check_kernels(
            gpu,
            &[(Kernel::LightRanges, &features, 0), (Kernel::DirectLight, &features, 0)],
        )?;
        // The light set's own kernels and buffers: checked by
        // `GpuLightSet::new` before it touches the device.
        // Two halves: the previous record's reservoirs and this record's.
        let reuse_bytes = 2 * DirectReuse::pixel_bytes(k) * w as u64 * h as u64;
        if desc.reuse.is_some() {
            let lim = &gpu.limits;
            gpu.require(
                "max_storage_buffer_binding_size (direct pass reuse)",
                reuse_bytes,
                lim.max_storage_buffer_binding_size.min(lim.max_buffer_size),
            )?;
        }
        let set = GpuLightSet::new(
            gpu,
            lights.lights(),
            lights.bounds(),
            lights.bsh(),
            &[],
            lights.cones(),
            None,
        )?;
        let ranges_layout = KernelLayout::new(gpu, Kernel::LightRanges, &features)?;
        let shade_layout = KernelLayout::new(gpu, Kernel::DirectLight, &features)?;
        let ranges = (ranges_layout.pipeline(gpu, &features, None)?, ranges_layout);
        let shade = (shade_layout.pipeline(gpu, &features, None)?, shade_layout);
        let cull = UniformSlots::new::<CullParams>(gpu, "slc direct cull", 1);
        let view = UniformSlots::new::<ViewParams>(gpu, "slc direct view", 1);
        let reuse = desc.reuse.map(|settings| Reuse {
            settings,
            params: UniformSlots::new::<ReuseParams>(gpu, "slc direct reuse", 1),
            pixels: zeroed(
                gpu,
                "slc direct reuse reservoirs",
                reuse_bytes,
                wgpu::BufferUsages::STORAGE,
            ),
            lights_prev: previous_lights(gpu, &set),
            parity: 0,
            previous: None,
            moved: Moved::Nowhere,
        });
        let (ranges_group, lights_group) = groups(
            gpu,
            &set,
            &ranges.1,
            &shade.1,
            &cull,
            binds_cones(desc),
            desc.light_types.ies,
            None,
            reuse.as_ref(),
        );
        let s = DirectPass {
            gpu: gpu.clone(),
            desc: *desc,
            features,
            set,
            ranges,
            ranges_group,
            shade,
            shade_features: features,
            other: None,
            occluders: None,
            lights_group,
            cull,
            view,
            cache: ViewCache::new(),
            reuse,
            counting: None,
        };
        gpu.take_errors()?;
        Ok(s)
    }

    /// The descriptor the pass was built for.
    pub fn desc(&self) -> &DirectPassDesc {
        &self.desc
    }

    /// Number of lights.
    pub fn light_count(&self) -> u32 {
        self.set.n
    }

    /// Moves, turns or recolours the lights: `lights` holds as many lights
    /// as the pass has (light `i` replaces light `i`), of the compiled-in
    /// types. Their records, bounds and importance cones are rewritten in
    /// place through the queue, so they take effect at the next submission
    /// (every record of the pass in that submission shades the lights of
    /// the last update before it), and every record refits the BSH to them
    /// on the GPU; no pipeline or bind group is rebuilt. The
    /// tree keeps the topology it was built with, so lights that wander far
    /// make it looser (slower, never wrong): [`DirectPass::set_lights`]
    /// builds it anew.
    pub fn update_lights(&mut self, lights: &[Light]) -> Result<(), GpuError> {
        check_types(lights, self.desc.light_types)?;
        if self.set.update(&self.gpu, lights)? {
            self.remake_groups();
        }
        Ok(())
    }

    /// Replaces the lights with `lights` (any count): new light buffers and
    /// BSH (built on the CPU by [`LightSet::new`]), new bind groups, the
    /// same pipelines.
    pub fn set_lights(&mut self, lights: &LightSet) -> Result<(), GpuError> {
        check_types(lights.lights(), self.desc.light_types)?;
        check_light_limits(&self.gpu, lights.len() as u64, 0)?;
        self.set.replace(&self.gpu, lights)?;
        if let Some(r) = self.reuse.as_mut() {
            r.lights_prev = previous_lights(&self.gpu, &self.set);
            r.previous = None;
        }
        self.remake_groups();
        Ok(())
    }

    /// Starts the reuse's history anew (a camera cut): the next record
    /// reuses nothing. [`DirectPass::set_lights`] does it too.
    pub fn reset_reuse(&mut self) {
        if let Some(r) = self.reuse.as_mut() {
            r.previous = None;
        }
    }

    /// Makes the bind groups over the lights (and occluders, reuse) again,
    /// the counting variant's too where it still fits (one built with
    /// shadows on or off as they are now; else the next count builds it).
    fn remake_groups(&mut self) {
        (self.ranges_group, self.lights_group) = self.groups_for(&self.shade.1);
        if let Some(c) = &self.counting
            && c.shadows == self.occluders.is_some()
        {
            let lights_group = self.groups_for(&c.pipe.1).1;
            let c = self.counting.as_mut().expect("checked above");
            (c.lights_group, c.cache) = (lights_group, ViewCache::new());
        }
    }

    /// `light_ranges`' group 0 and, for the `direct_light` variant laid out
    /// as `shade`, its group 1 ([`groups`]).
    fn groups_for(&self, shade: &KernelLayout) -> (wgpu::BindGroup, wgpu::BindGroup) {
        groups(
            &self.gpu,
            &self.set,
            &self.ranges.1,
            shade,
            &self.cull,
            binds_cones(&self.desc),
            self.desc.light_types.ies,
            self.occluders.as_ref().map(|o| &o.0),
            self.reuse.as_ref(),
        )
    }

    /// Shadows every pick against `shadows`' occluders from the next
    /// record on, or turns shadows off (`None`). The first call builds the
    /// shadowed kernel (the device's limits checked first: it binds two
    /// more storage buffers); a call with the same meshes and instances,
    /// moved ([`Occluders::set_transforms`]), rewrites in place through the
    /// queue the moved instances' parts of the buffers and the top level,
    /// and nothing else. [`ShadowRays::RayQuery`] (a device with ray
    /// queries, else a typed error: its limits `max_tlas_instance_count`
    /// and `max_blas_primitive_count`, the largest mesh, are checked too)
    /// also makes the acceleration structures, whose builds the next
    /// record records before its dispatches: every mesh's bottom level for
    /// a new layout, the top level when instances moved. Switching between
    /// the two kinds of rays builds the other kernel once. On an error
    /// nothing changes. Takes effect at the next submission, as
    /// [`DirectPass::update_lights`] does.
    pub fn set_shadows(&mut self, shadows: Option<Shadows>) -> Result<(), GpuError> {
        let Some(sh) = shadows else {
            if self.occluders.is_some() {
                self.swap_kernel(self.features)?;
                self.occluders = None;
                self.remake_groups();
                self.occluders_moved(Moved::Everywhere);
            }
            return Ok(());
        };
        if !(sh.normal_offset.is_finite() && sh.normal_offset >= 0.0) {
            return Err(GpuError::Setting(format!(
                "direct pass: shadow normal offset {} must be finite and non-negative",
                sh.normal_offset
            )));
        }
        let ray_query = sh.rays == ShadowRays::RayQuery;
        check_limits(&self.gpu, sh.occluders)?;
        if ray_query {
            check_accel_limits(&self.gpu, sh.occluders)?;
        }
        let shadowed = Features { shadows: true, ray_query, ..self.features };
        if let Some((o, offset)) = self.occluders.as_mut()
            && o.accel.is_some() == ray_query
            && let Some(moved) = o.rewrite(&self.gpu, sh.occluders)
        {
            let moved = if *offset == sh.normal_offset { moved } else { Moved::Everywhere };
            *offset = sh.normal_offset;
            self.occluders_moved(moved);
            return Ok(());
        }
        check_kernels(&self.gpu, &[(Kernel::DirectLight, &shadowed, 0)])?;
        // The kernel first: where it cannot be built, nothing changes.
        let swapped = self.swap_kernel(shadowed)?;
        let gpu_occ = match GpuOccluders::new(&self.gpu, sh.occluders, ray_query) {
            Ok(o) => o,
            Err(e) => {
                if swapped {
                    self.swap_back();
                }
                return Err(e);
            }
        };
        self.occluders = Some((gpu_occ, sh.normal_offset));
        self.remake_groups();
        self.occluders_moved(Moved::Everywhere);
        self.gpu.take_errors()
    }

    /// Notes for the reuse's next record that the occluders changed in
    /// `m` since the last one.
    fn occluders_moved(&mut self, m: Moved) {
        if let Some(r) = self.reuse.as_mut() {
            r.moved = r.moved.join(m);
        }
    }

    /// How the pass casts its shadow rays, or `None` when it is
    /// unshadowed.
    pub fn shadow_rays(&self) -> Option<ShadowRays> {
        self.occluders.as_ref().map(|(o, _)| {
            if o.accel.is_some() { ShadowRays::RayQuery } else { ShadowRays::Software }
        })
    }

    /// Makes the variant of `direct_light` for `f` the active one (the
    /// one active before stays built for a swap back), building it unless
    /// it is active or was before; returns whether it changed. On an
    /// error nothing changes.
    fn swap_kernel(&mut self, f: Features) -> Result<bool, GpuError> {
        if self.shade_features == f {
            return Ok(false);
        }
        let pipe = match self.other.take() {
            Some((of, p)) if of == f => p,
            kept => {
                self.other = kept;
                let layout = KernelLayout::new(&self.gpu, Kernel::DirectLight, &f)?;
                (layout.pipeline(&self.gpu, &f, None)?, layout)
            }
        };
        self.activate(f, pipe);
        Ok(true)
    }

    /// Undoes the last [`DirectPass::swap_kernel`] that changed the
    /// variant.
    fn swap_back(&mut self) {
        if let Some((f, p)) = self.other.take() {
            self.activate(f, p);
        }
    }

    /// Makes `pipe` (the variant for `f`) the active one, keeping the one
    /// it replaces as `other`.
    fn activate(&mut self, f: Features, pipe: Pipe) {
        let before = std::mem::replace(&mut self.shade, pipe);
        self.other = Some((std::mem::replace(&mut self.shade_features, f), before));
        self.cache = ViewCache::new();
    }

    /// Checks `inputs` against the descriptor (formats, sizes, usages).
    pub fn check(&self, inputs: &DirectInputs) -> Result<(), GpuError> {
        inputs::checked_view(&self.desc, inputs, 0, 0).map(|_| ())
    }

    /// Records the frame into `encoder`: its uniforms' copy, then one
    /// compute pass. Checks the inputs and settings first and records
    /// nothing when they are wrong. Any number of records may share a
    /// submission, each with its own settings: the record's uniforms go
    /// into place in command order ([`passes`](super) docs). Creates no
    /// bind group when the views are those of a recent record.
    pub fn record(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        inputs: &DirectInputs,
        settings: &DirectSettings,
    ) -> Result<(), GpuError> {
        let view_projection = self.encode(encoder, inputs, settings, false)?;
        if let Some(r) = self.reuse.as_mut() {
            // The next record's previous lights are this record's.
            encoder.copy_buffer_to_buffer(
                &self.set.lights,
                0,
                &r.lights_prev,
                0,
                r.lights_prev.size(),
            );
            r.previous = view_projection.map(|m| (m, inputs.gbuffer.eye));
            r.parity ^= 1;
            r.moved = Moved::Nowhere;
        }
        Ok(())
    }

    /// Records a frame's uniforms and dispatches, with the shading kernel
    /// or its counting variant; returns the record's view-projection for
    /// the reuse.
    fn encode(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        inputs: &DirectInputs,
        settings: &DirectSettings,
        counting: bool,
    ) -> Result<Option<Mat4>, GpuError> {
        let mut view = inputs::checked_view(&self.desc, inputs, settings.seed, settings.frame)?;
        view.shadow_offset = self.occluders.as_ref().map_or(0.0, |o| o.1);
        let view_projection = match self.reuse {
            Some(_) => Some(inputs::view_projection(inputs)?),
            None => None,
        };
        let (slc, fixed_r2) = kernel_form(&settings.culling)?;
        let (mode, exposure, error_bound) = match settings.culling {
            Culling::Stochastic(p) => (p.measure().mode(), p.exposure(), p.error_bound()),
            _ => (0, 1.0, 1.0),
        };
        let cull = CullParams {
            light_count: self.set.n,
            seed: settings.seed,
            frame: settings.frame,
            slc: slc as u32,
            mode,
            exposure,
            error_bound,
            fixed_r2,
            unculled: f32::INFINITY,
            pad0: 0,
            pad1: 0,
            pad2: 0,
        };
        let mut uploads = Uploads::default();
        uploads.push(&self.cull, &cull);
        uploads.push(&self.view, &view);
        if let Some(r) = &self.reuse {
            let (m, prev_eye) = r.previous.unwrap_or((Mat4::ZERO, Vec3::ZERO));
            let (moved, moved_min, moved_max) = r.moved.encoded();
            let params = ReuseParams {
                c0: m.x_axis,
                c1: m.y_axis,
                c2: m.z_axis,
                c3: m.w_axis,
                prev_eye,
                max_confidence: r.settings.max_confidence,
                has_history: r.previous.is_some() as u32,
                radius: r.settings.radius,
                visibility: r.settings.visibility as u32,
                parity: r.parity as u32,
                moved_min,
                moved,
                moved_max,
                pad: 0,
            };
            uploads.push(&r.params, &params);
        }
        uploads.record(&self.gpu, encoder);
        // Acceleration structures made or moved since the last record.
        if let Some((o, _)) = self.occluders.as_mut()
            && let Some(a) = o.accel.as_mut()
        {
            a.record_builds(encoder);
        }
        let g = inputs.gbuffer;
        let tex = wgpu::BindingResource::TextureView;
        let mut views = vec![
            ("view", None),
            ("reuse", None),
            (g.surface_name(), Some(g.surface_view())),
            ("normal_tex", Some(g.normal)),
            ("out_tex", Some(inputs.output)),
        ];
        if self.desc.outputs != DirectOutputs::Irradiance
            && let Some(m) = inputs.material
        {
            views.extend([
                ("base_color_tex", Some(m.base_color)),
                ("metal_rough_tex", Some(m.metallic_roughness)),
            ]);
        }
        if matches!(self.desc.outputs, DirectOutputs::Split(_))
            && let Some(s) = inputs.specular
        {
            views.push(("specular_tex", Some(s)));
        }
        if self.reuse.is_none() {
            views.retain(|(name, _)| *name != "reuse");
        }
        let key: Vec<wgpu::TextureView> = views.iter().filter_map(|(_, v)| v.cloned()).collect();
        let (gpu, shade, view_slots) = (&self.gpu, &self.shade.1, &self.view);
        let reuse_slots = self.reuse.as_ref().map(|r| &r.params);
        let resources = || -> Vec<(&str, wgpu::BindingResource)> {
            views
                .iter()
                .map(|&(name, v)| {
                    let uniform = match reuse_slots {
                        Some(r) if name == "reuse" => r.binding(),
                        _ => view_slots.binding(),
                    };
                    (name, v.map_or(uniform, tex))
                })
                .collect()
        };
        let (pipeline, group0, group1) = match (&mut self.counting, counting) {
            (Some(c), true) => {
                let group0 = c.cache.get(key, || {
                    let mut res = resources();
                    res.push(("counters", crate::kernel::whole(&c.counters)));
                    c.pipe.1.group(gpu, 0, &res)
                });
                (&c.pipe.0, group0, c.lights_group.clone())
            }
            _ => {
                let group0 = self.cache.get(key, || shade.group(gpu, 0, &resources()));
                (&self.shade.0, group0, self.lights_group.clone())
            }
        };
        let (w, h) = (self.desc.width, self.desc.height);
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("slc direct"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&self.ranges.0);
        pass.set_bind_group(0, &self.ranges_group, &[0]);
        pass.dispatch_workgroups(self.set.n.div_ceil(WG), 1, 1);
        self.set.encode_refit(&mut pass);
        pass.set_pipeline(pipeline);
        let offsets: &[u32] = if self.reuse.is_some() { &[0, 0] } else { &[0] };
        pass.set_bind_group(0, &group0, offsets);
        pass.set_bind_group(1, &group1, &[]);
        pass.dispatch_workgroups(w.div_ceil(TILE), h.div_ceil(TILE), 1);
        Ok(view_projection)
    }
}

/// Whether `direct_light` binds the lights' cones: the weighted picks weigh
/// the lights by them, and a material's lobe scales each light's range by
/// its bounding sphere.
fn binds_cones(desc: &DirectPassDesc) -> bool {
    matches!(desc.selection, DirectSelection::Weighted { .. })
        || desc.outputs != DirectOutputs::Irradiance
}

/// `light_ranges`' group 0 and `direct_light`'s group 1 over `set` (and
/// the occluders of the shadowed variant).
#[allow(clippy::too_many_arguments)]
fn groups(
    gpu: &GpuContext,
    set: &GpuLightSet,
    ranges: &KernelLayout,
    shade: &KernelLayout,
    cull: &UniformSlots,
    cones: bool,
    ies: bool,
    occluders: Option<&GpuOccluders>,
    reuse: Option<&Reuse>,
) -> (wgpu::BindGroup, wgpu::BindGroup) {
    let res = crate::kernel::whole;
    let ranges_group = ranges.group(
        gpu,
        0,
        &[
            ("params", cull.binding()),
            ("peaks", res(&set.peaks)),
            ("rt2", res(&set.rt2)),
            ("r2", res(&set.r2)),
        ],
    );
    let mut lights = vec![
        ("lights", res(&set.lights)),
        ("rt2", res(&set.rt2)),
        ("r2", res(&set.r2)),
        ("bsh_nodes", res(&set.bsh)),
    ];
    if cones {
        lights.push(("light_cones", res(&set.cones)));
    }
    if ies {
        lights.push(("slc_table", res(&set.table_buf)));
    }
    match occluders {
        Some(GpuOccluders { accel: Some(a), .. }) if shade.binds("geo_tlas") => {
            lights.push(("geo_tlas", wgpu::BindingResource::AccelerationStructure(&a.tlas)));
        }
        Some(o) => lights.extend([("geo_nodes", res(&o.nodes)), ("geo_tris", res(&o.tris))]),
        None => {}
    }
    if let Some(r) = reuse {
        lights.extend([("lights_prev", res(&r.lights_prev)), ("reuse_pixels", res(&r.pixels))]);
    }
    (ranges_group, shade.group(gpu, 1, &lights))
}

/// A buffer for the previous record's lights, the size of `set`'s.
fn previous_lights(gpu: &GpuContext, set: &GpuLightSet) -> wgpu::Buffer {
    let usage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST;
    zeroed(gpu, "slc direct previous lights", set.lights.size(), usage)
}

/// A typed error unless the pass's compiled light types `compiled` hold
/// every type of `lights` (what `DirectPass::new`, `set_lights` and
/// `update_lights` check).
fn check_types(lights: &[Light], compiled: LightTypes) -> Result<(), GpuError> {
    let types = LightTypes::of(lights);
    if !types.within(compiled) {
        return Err(GpuError::Setting(format!(
            "direct pass: lights of types [{}], the pass compiles [{}] (DirectPassDesc::light_types)",
            types.names().join(", "),
            compiled.names().join(", ")
        )));
    }
    Ok(())
}
