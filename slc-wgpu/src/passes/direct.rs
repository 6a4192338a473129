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
//!   docs/results/reused-picks.md): the shadow test 0.088 (visibility
//!   reuse: 0.066) against resampling's 0.115 and weighted picks' 0.237;
//!   the engine-pass scene per channel 0.0083 against weighted picks'
//!   0.074 (0.11), its r + g + b 0.0081 against 0.0378; slc-bevy's
//!   luminance RMSE 0.00022 against 0.086.
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

use super::{
    Culling, GBuffer, SurfaceDesc, ViewCache, check_size, check_view, kernel_form, output_format,
};
use crate::kernel::{KernelLayout, UniformSlots, check_kernels, zeroed};
use crate::lights::{GpuLightSet, WG, check_light_limits};
use crate::occluders::{GpuOccluders, check_accel_limits, check_limits};
use crate::record::Uploads;
use crate::{GpuContext, GpuError};
use glam::{Mat4, Vec3};
use slc_core::light::Light;
use slc_scene::lights::LightSet;
use slc_scene::occluders::Occluders;
use slc_shared_shaders::layout::{
    CullParams, DIRECT_COUNT_CANDIDATES, DIRECT_COUNT_EVALUATIONS, DIRECT_COUNT_FIELDS,
    DIRECT_COUNT_NODES, DIRECT_COUNT_PIXELS, DIRECT_COUNT_RAYS, ReuseParams, ReuseSlot,
    ReuseSurface, ViewParams,
};
use slc_shared_shaders::{DirectOutput, Features, Kernel, LightTypes, Selection};

/// Tile edge of the 2-D kernels, in pixels.
const TILE: u32 = 8;

pub use slc_scene::lights::DirectSelection;

/// The dielectric part of the glTF material: its Fresnel reflectance at
/// normal (`f0`) and grazing (`f90`) incidence; glTF's default (IOR 1.5)
/// is `0.04` and `1`, `KHR_materials_specular` scales and tints them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dielectric {
    /// `F0_d` (RGB).
    pub f0: Vec3,
    /// `F90_d`.
    pub f90: f32,
}

impl Default for Dielectric {
    /// glTF's default: IOR 1.5.
    fn default() -> Self {
        Dielectric { f0: Vec3::splat(0.04), f90: 1.0 }
    }
}

/// What the direct pass writes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DirectOutputs {
    /// Irradiance (rgb) and the lights in range (a); the engine applies
    /// its BRDF.
    Irradiance,
    /// Outgoing radiance toward the eye under the G-buffer's glTF
    /// material ([`MaterialInputs`]), and the lights in range (a).
    Radiance(Dielectric),
    /// Irradiance into the output and the specular lobe's outgoing
    /// radiance into [`DirectInputs::specular`].
    Split(Dielectric),
    /// Outgoing radiance toward the eye under Bevy `StandardMaterial`'s
    /// BRDF (`slc_core::brdf::bevy_brdf`: Burley diffuse, GGX with Bevy's
    /// Fresnel and multiple-scattering compensation), and the lights in
    /// range (a); the metallic-roughness input's alpha holds Bevy's
    /// `reflectance` (dielectric `F0 = 0.16·reflectance²`).
    BevyRadiance,
}

/// The G-buffer's glTF metallic-roughness material (see the module table).
#[derive(Clone, Copy, Debug)]
pub struct MaterialInputs<'a> {
    /// Linear base colour (rgb).
    pub base_color: &'a wgpu::TextureView,
    /// Perceptual roughness (g) and metallic (b), glTF's layout.
    pub metallic_roughness: &'a wgpu::TextureView,
}

/// The formats the material textures are read in.
const MATERIAL_FORMATS: [wgpu::TextureFormat; 4] = [
    wgpu::TextureFormat::Rgba8Unorm,
    wgpu::TextureFormat::Rgba8UnormSrgb,
    wgpu::TextureFormat::Rgba16Float,
    wgpu::TextureFormat::Rgba32Float,
];

/// What a [`DirectPass`] is built for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectPassDesc {
    /// G-buffer and output width.
    pub width: u32,
    /// G-buffer and output height.
    pub height: u32,
    /// Where the G-buffer's surface comes from.
    pub surface: SurfaceDesc,
    /// Format of the output storage texture: `Rgba16Float` or `Rgba32Float`.
    pub output_format: wgpu::TextureFormat,
    /// How lights in range are picked.
    pub selection: DirectSelection,
    /// The light types compiled in: lights given later
    /// ([`DirectPass::update_lights`], [`DirectPass::set_lights`]) must be
    /// of these types.
    pub light_types: LightTypes,
    /// What the pass writes.
    pub outputs: DirectOutputs,
    /// Reuse of the resampled picks across frames and pixels
    /// ([`DirectReuse`]; [`DirectSelection::Resampled`] only), or none.
    pub reuse: Option<DirectReuse>,
    /// How each pixel's lights in range are found ([`DirectWalk`]).
    pub walk: DirectWalk,
}

/// How the direct pass finds each pixel's lights in range. Either way a
/// pixel gets the same lights in the same order, so the same picks and
/// image: only the time differs, and which is faster depends on the
/// adapter (measured in `docs/results/bevy-gpu-h200.md`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DirectWalk {
    /// One walk of the light hierarchy per 8×8 tile, shared by its
    /// invocations, into a list in workgroup memory that each pixel then
    /// tests exactly (the module docs, "One walk per tile").
    #[default]
    Tile,
    /// One walk per pixel: no workgroup memory and no barriers.
    Pixel,
}

/// Reuse of [`DirectSelection::Resampled`]'s picks across frames and
/// pixels (ReSTIR DI, Bitterli et al. 2020, as generalized RIS, Lin et al.
/// 2022). Each of the `k` picks is a reservoir: this record's pick
/// (drawn from the lights in range) is combined with the same reservoir
/// of the previous record's pixel this point reprojects to, where it saw
/// the same surface (the history the next record reuses); for this
/// record's shading only, `neighbours` previous-record pixels in a disk of
/// `radius` pixels around it join. Each enters in proportion to
/// its whole unshadowed contribution here, weighted by the generalized
/// balance heuristic over every reused pixel's target (its surface, the
/// previous record's lights) and confidence (the inputs it stands for, at
/// most `max_confidence`): unbiased, and the culling's noise averages
/// over the frames reused. The picks are then shadowed as before.
///
/// Needs the record's view-projection (a depth surface gives it; a
/// position surface needs [`DirectInputs::view_projection`]), one record
/// per frame, and costs `2 × (48 + 12k)` bytes per pixel (k = 8: 144 B,
/// 597 MB at 1080p) and, per pick, `(1 + d)²` target evaluations for the
/// `d` reused pixels found. Reprojection is by the view alone: a moving
/// object's pixels find no history (the surface test) and start anew.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectReuse {
    /// Previous-record pixels reused besides the reprojected one, `0..=7`,
    /// for the shading only. 0 by default: measured, they raised one
    /// frame's noise (docs/results/reused-picks.md: SLC's candidates are
    /// already every light in range, and a frame's ranges are every
    /// pixel's, so a neighbour brings nothing the pixel lacks).
    pub neighbours: u32,
    /// Radius of the neighbours' disk, in pixels.
    pub radius: f32,
    /// The largest confidence a reservoir keeps, in frames (`≥ 1`): its
    /// weight against this record's pick.
    pub max_confidence: f32,
    /// Visibility reuse: a pick whose shadow ray is blocked keeps no
    /// weight for the next record, so the reservoirs learn which lights
    /// reach the pixel. Unbiased while the camera and the occluders stand
    /// still (the reused pixel is this one, its occluded picks carry no
    /// light here); where they move, the reprojected pixel's surface
    /// point differs slightly and shadow edges come out a little dark
    /// (ReSTIR's biased variant).
    pub visibility: bool,
}

impl Default for DirectReuse {
    /// The pixel's own history only (no neighbours; a disk of 16 pixels
    /// where some are asked for), at most 20 frames' confidence, no
    /// visibility reuse.
    fn default() -> Self {
        DirectReuse { neighbours: 0, radius: 16.0, max_confidence: 20.0, visibility: false }
    }
}

impl DirectReuse {
    fn check(&self) -> Result<(), GpuError> {
        if self.neighbours > 7
            || !(self.radius.is_finite() && self.radius >= 0.0)
            || !(self.max_confidence.is_finite() && self.max_confidence >= 1.0)
        {
            return Err(GpuError::Setting(format!(
                "direct pass reuse: {} neighbours (0..=7), radius {} (finite, ≥ 0) and max confidence {} (finite, ≥ 1)",
                self.neighbours, self.radius, self.max_confidence
            )));
        }
        if self.visibility && self.neighbours > 0 {
            return Err(GpuError::Setting(format!(
                "direct pass reuse: visibility reuse holds for the pixel's own history only, not {} neighbours (a neighbour's occluded picks may light this pixel)",
                self.neighbours
            )));
        }
        Ok(())
    }

    /// Bytes of one pixel's reservoirs and surface for `k` picks (the
    /// kernel's `ReusePixel`).
    fn pixel_bytes(k: u32) -> u64 {
        let surface = std::mem::size_of::<ReuseSurface>() as u64;
        let slot = std::mem::size_of::<ReuseSlot>() as u64;
        (surface + slot * k as u64).next_multiple_of(16)
    }
}

impl DirectPassDesc {
    /// `width × height`, a `Depth32Float` depth buffer, `Rgba16Float`
    /// output, 8 weighted picks ([`DirectSelection::Weighted`]), point,
    /// spot, IES and triangle lights, and [`DirectOutputs::Irradiance`]
    /// (irradiance in rgb, lights in range in a: no material input).
    pub fn new(width: u32, height: u32) -> DirectPassDesc {
        DirectPassDesc {
            width,
            height,
            surface: SurfaceDesc::Depth { format: wgpu::TextureFormat::Depth32Float },
            output_format: wgpu::TextureFormat::Rgba16Float,
            selection: DirectSelection::Weighted { k: 8 },
            light_types: LightTypes {
                point: true,
                spot: true,
                ies: true,
                triangle: true,
                vpl: false,
            },
            outputs: DirectOutputs::Irradiance,
            reuse: None,
            walk: DirectWalk::Tile,
        }
    }
}

/// The engine's resources for one record.
#[derive(Clone, Copy, Debug)]
pub struct DirectInputs<'a> {
    /// The G-buffer.
    pub gbuffer: GBuffer<'a>,
    /// Where the irradiance (or radiance) goes.
    pub output: &'a wgpu::TextureView,
    /// The material, for [`DirectOutputs::Radiance`] and
    /// [`DirectOutputs::Split`].
    pub material: Option<MaterialInputs<'a>>,
    /// The specular radiance's target, for [`DirectOutputs::Split`].
    pub specular: Option<&'a wgpu::TextureView>,
    /// The view-projection the G-buffer was rendered with (world to clip,
    /// wgpu's conventions), for [`DirectReuse`] with a position surface (a
    /// depth surface's is the inverse of its `inv_view_proj`).
    pub view_projection: Option<Mat4>,
}

impl<'a> DirectInputs<'a> {
    /// Inputs for [`DirectOutputs::Irradiance`]: the G-buffer and the output.
    pub fn new(gbuffer: GBuffer<'a>, output: &'a wgpu::TextureView) -> Self {
        DirectInputs { gbuffer, output, material: None, specular: None, view_projection: None }
    }
}

/// Per-record settings of the direct pass: all it honours.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectSettings {
    /// How lights are culled. With [`Culling::None`] every light is a
    /// candidate at every pixel: with weighted picks
    /// ([`DirectSelection::Weighted`]) the picks follow each light's
    /// importance, so one frame is about as noisy as with stochastic
    /// culling (measured by an outside engine program at 3,000 point
    /// lights, k = 8: relative RMSE 0.053 both) at about 2.6× the cost
    /// (every light's importance at every pixel); with uniform picks it is
    /// far noisier. A baseline, not a reference image.
    pub culling: Culling,
    /// Seed of the per-light ξ and the picks' random numbers.
    pub seed: u32,
    /// Frame number (a new ξ set and new picks per frame).
    pub frame: u32,
}

/// Shadow rays for the direct pass's picks ([`DirectPass::set_shadows`]).
#[derive(Clone, Copy, Debug)]
pub struct Shadows<'a> {
    /// What the rays hit, in world space.
    pub occluders: &'a Occluders,
    /// A ray's origin offset along the G-buffer normal, as a fraction of
    /// the pixel's distance to the eye ([`GBuffer::eye`]): large enough to
    /// clear the error of a position reconstructed from depth, small
    /// enough not to let light leak through thin walls or at contacts.
    /// [`Shadows::new`]: `10⁻³` (about a pixel's footprint at 1080p and a
    /// 60° field of view).
    pub normal_offset: f32,
    /// How the rays are cast. [`Shadows::new`]: [`ShadowRays::Software`].
    pub rays: ShadowRays,
}

/// How the direct pass casts its shadow rays (the module docs, "Hardware
/// shadow rays"): the same segments either way.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ShadowRays {
    /// A BVH walk in WGSL: every adapter, lavapipe included.
    #[default]
    Software,
    /// The adapter's ray queries through acceleration structures: needs a
    /// device with wgpu's `EXPERIMENTAL_RAY_QUERY` ([`GpuContext::ray_query`]).
    RayQuery,
}

impl<'a> Shadows<'a> {
    /// Shadows against `occluders` with a normal offset of `10⁻³` × the eye
    /// distance, cast in software.
    pub fn new(occluders: &'a Occluders) -> Self {
        Shadows { occluders, normal_offset: 1e-3, rays: ShadowRays::Software }
    }
}

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
    /// `direct_light`'s group 1, one per parity of the reuse's ping-pong
    /// (one without reuse).
    lights_groups: Vec<wgpu::BindGroup>,
    cull: UniformSlots,
    view: UniformSlots,
    cache: ViewCache<Vec<wgpu::TextureView>>,
    /// The reuse's buffers and history, with [`DirectPassDesc::reuse`].
    reuse: Option<Reuse>,
    /// The counting variant, built at the first [`DirectPass::count_work`].
    counting: Option<Counting>,
}

/// The counting variant of `direct_light` (`Features::counters`), shadowed
/// or not as the pass was when it was built, and its counters.
struct Counting {
    shadows: bool,
    pipe: Pipe,
    counters: wgpu::Buffer,
    staging: wgpu::Buffer,
}

/// The direct pass's work in one record, summed over the shaded pixels
/// ([`DirectPass::count_work`]): what anyone can measure without a GPU.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DirectCounts {
    /// Pixels shaded (with a surface).
    pub pixels: u64,
    /// Lights in range (the candidates the BSH walk found).
    pub candidates: u64,
    /// Lights evaluated without a ray: resampled picks' candidates and
    /// the reuse's targets (0 for weighted, uniform and all picks).
    pub evaluations: u64,
    /// Shadow rays cast (0 unshadowed).
    pub rays: u64,
    /// Occluder BVH nodes the shadow rays visited.
    pub nodes: u64,
}

impl DirectCounts {
    /// `count` per shaded pixel (0 without one).
    pub fn per_pixel(&self, count: u64) -> f64 {
        count as f64 / self.pixels.max(1) as f64
    }
}

/// The reuse's state: its uniforms, the two reservoir buffers (this
/// record writes `pixels[parity]` and reads the other), the previous
/// record's lights, and its view-projection and eye (none: no history).
struct Reuse {
    settings: DirectReuse,
    params: UniformSlots,
    pixels: [wgpu::Buffer; 2],
    lights_prev: wgpu::Buffer,
    parity: usize,
    previous: Option<(Mat4, Vec3)>,
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
        let reuse_bytes = DirectReuse::pixel_bytes(k) * w as u64 * h as u64;
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
            pixels: [0, 1].map(|_| {
                zeroed(gpu, "slc direct reuse reservoirs", reuse_bytes, wgpu::BufferUsages::STORAGE)
            }),
            lights_prev: previous_lights(gpu, &set),
            parity: 0,
            previous: None,
        });
        let (ranges_group, lights_groups) = groups(
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
            lights_groups,
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

    fn remake_groups(&mut self) {
        (self.ranges_group, self.lights_groups) = groups(
            &self.gpu,
            &self.set,
            &self.ranges.1,
            &self.shade.1,
            &self.cull,
            binds_cones(&self.desc),
            self.desc.light_types.ies,
            self.occluders.as_ref().map(|o| &o.0),
            self.reuse.as_ref(),
        );
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
            && o.rewrite(&self.gpu, sh.occluders)
        {
            *offset = sh.normal_offset;
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
        self.gpu.take_errors()
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
        self.check_inputs(inputs, 0, 0).map(|_| ())
    }

    fn check_inputs(
        &self,
        inputs: &DirectInputs,
        seed: u32,
        frame: u32,
    ) -> Result<ViewParams, GpuError> {
        let size = (self.desc.width, self.desc.height);
        let mut view = inputs.gbuffer.check(self.desc.surface, size, seed, frame)?;
        let storage = wgpu::TextureUsages::STORAGE_BINDING;
        check_view("output", inputs.output, size, &[self.desc.output_format], storage)?;
        let missing = |name, what: &str| GpuError::Binding {
            name,
            expected: what.into(),
            found: "none".into(),
        };
        let (material, split) = match self.desc.outputs {
            DirectOutputs::Irradiance => (None, false),
            DirectOutputs::BevyRadiance => (Some(Dielectric::default()), false),
            DirectOutputs::Radiance(d) => (Some(d), false),
            DirectOutputs::Split(d) => (Some(d), true),
        };
        if let Some(d) = material {
            let m = inputs.material.ok_or_else(|| {
                missing("material", "the G-buffer's base colour and metallic-roughness")
            })?;
            let tex = wgpu::TextureUsages::TEXTURE_BINDING;
            check_view("material base colour", m.base_color, size, &MATERIAL_FORMATS, tex)?;
            check_view(
                "material metallic-roughness",
                m.metallic_roughness,
                size,
                &MATERIAL_FORMATS,
                tex,
            )?;
            (view.f0_d, view.f90_d) = (d.f0, d.f90);
        }
        if split {
            let s = inputs
                .specular
                .ok_or_else(|| missing("specular", "a target for the specular radiance"))?;
            check_view("specular", s, size, &[self.desc.output_format], storage)?;
        }
        Ok(view)
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
        }
        Ok(())
    }

    /// Counts the work a record of `inputs` and `settings` does
    /// ([`DirectCounts`]): the counting variant of `direct_light`, built
    /// at the first call (and again when shadows are turned on or off),
    /// recorded, submitted and read back (waits). The image it writes is
    /// the record's; it does not advance the reuse's history (the next
    /// record reuses what the last record left). Never part of a timed
    /// frame.
    pub fn count_work(
        &mut self,
        inputs: &DirectInputs,
        settings: &DirectSettings,
    ) -> Result<DirectCounts, GpuError> {
        let shadows = self.occluders.is_some();
        let bytes = u64::from(DIRECT_COUNT_FIELDS) * 8;
        if self.counting.as_ref().is_none_or(|c| c.shadows != shadows) {
            let f = Features { counters: true, shadows, ..self.features };
            check_kernels(&self.gpu, &[(Kernel::DirectLight, &f, 0)])?;
            let layout = KernelLayout::new(&self.gpu, Kernel::DirectLight, &f)?;
            let pipe = (layout.pipeline(&self.gpu, &f, None)?, layout);
            let rw = wgpu::BufferUsages::STORAGE
                | wgpu::BufferUsages::COPY_SRC
                | wgpu::BufferUsages::COPY_DST;
            let read = wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST;
            self.counting = Some(Counting {
                shadows,
                pipe,
                counters: zeroed(&self.gpu, "slc direct counters", bytes, rw),
                staging: zeroed(&self.gpu, "slc direct counters staging", bytes, read),
            });
        }
        let mut encoder = self.gpu.device.create_command_encoder(&Default::default());
        if let Some(c) = &self.counting {
            encoder.clear_buffer(&c.counters, 0, None);
        }
        self.encode(&mut encoder, inputs, settings, true)?;
        self.gpu.queue.submit([encoder.finish()]);
        let c = self.counting.as_ref().expect("built above");
        let words: Vec<u32> = crate::kernel::read_back(&self.gpu, &c.counters, &c.staging)?;
        self.gpu.take_errors()?;
        let v = |f: u32| words[2 * f as usize] as u64 | (words[2 * f as usize + 1] as u64) << 32;
        Ok(DirectCounts {
            pixels: v(DIRECT_COUNT_PIXELS),
            candidates: v(DIRECT_COUNT_CANDIDATES),
            evaluations: v(DIRECT_COUNT_EVALUATIONS),
            rays: v(DIRECT_COUNT_RAYS),
            nodes: v(DIRECT_COUNT_NODES),
        })
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
        let mut view = self.check_inputs(inputs, settings.seed, settings.frame)?;
        view.shadow_offset = self.occluders.as_ref().map_or(0.0, |o| o.1);
        let view_projection = match self.reuse {
            Some(_) => Some(view_projection(inputs)?),
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
                pad0: 0,
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
        let parity = self.reuse.as_ref().map_or(0, |r| r.parity);
        let (pipeline, group0, group1) = match (&self.counting, counting) {
            (Some(c), true) => {
                let mut res = resources();
                res.push(("counters", crate::kernel::whole(&c.counters)));
                let (_, group1) = groups(
                    gpu,
                    &self.set,
                    &self.ranges.1,
                    &c.pipe.1,
                    &self.cull,
                    binds_cones(&self.desc),
                    self.desc.light_types.ies,
                    self.occluders.as_ref().map(|o| &o.0),
                    self.reuse.as_ref(),
                );
                (&c.pipe.0, c.pipe.1.group(gpu, 0, &res), group1[parity].clone())
            }
            _ => {
                let group0 = self.cache.get(key, || shade.group(gpu, 0, &resources()));
                (&self.shade.0, group0, self.lights_groups[parity].clone())
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
) -> (wgpu::BindGroup, Vec<wgpu::BindGroup>) {
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
    let Some(r) = reuse else {
        return (ranges_group, vec![shade.group(gpu, 1, &lights)]);
    };
    // The record of parity p writes pixels[p] and reads the other.
    let parities = (0..2).map(|p| {
        let mut with = lights.clone();
        with.extend([
            ("lights_prev", res(&r.lights_prev)),
            ("reuse_prev", res(&r.pixels[1 - p])),
            ("reuse_next", res(&r.pixels[p])),
        ]);
        shade.group(gpu, 1, &with)
    });
    (ranges_group, parities.collect())
}

/// A buffer for the previous record's lights, the size of `set`'s.
fn previous_lights(gpu: &GpuContext, set: &GpuLightSet) -> wgpu::Buffer {
    let usage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST;
    zeroed(gpu, "slc direct previous lights", set.lights.size(), usage)
}

/// The record's view-projection, for the reuse: the inverse of a depth
/// surface's `inv_view_proj`, or [`DirectInputs::view_projection`].
fn view_projection(inputs: &DirectInputs) -> Result<Mat4, GpuError> {
    let m = match (inputs.gbuffer.surface, inputs.view_projection) {
        (_, Some(m)) => m,
        (super::Surface::Depth { inv_view_proj, .. }, None) => inv_view_proj.inverse(),
        (super::Surface::Position(_), None) => {
            return Err(GpuError::Binding {
                name: "view_projection",
                expected: "the view-projection (reuse with a position surface)".into(),
                found: "none".into(),
            });
        }
    };
    if !m.is_finite() {
        return Err(GpuError::Setting(format!(
            "direct pass reuse: view-projection {m} must be finite"
        )));
    }
    Ok(m)
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
