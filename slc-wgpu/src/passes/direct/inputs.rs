//! What an engine gives the [`DirectPass`]: what the pass is built for
//! ([`DirectPassDesc`]: how lights are picked, what it writes, the reuse,
//! the walk), each record's resources ([`DirectInputs`],
//! [`MaterialInputs`]) and settings ([`DirectSettings`]), the shadows'
//! occluders ([`Shadows`], [`ShadowRays`]), and the checks of the
//! resources against the descriptor.

#[cfg(doc)]
use super::DirectPass;
#[cfg(doc)]
use crate::GpuContext;
use crate::GpuError;
use crate::passes::{Culling, GBuffer, Surface, SurfaceDesc, check_view};
use glam::{Mat4, Vec3};
use slc_scene::occluders::Occluders;
use slc_shared_shaders::LightTypes;
use slc_shared_shaders::layout::{ReuseSlot, ReuseSurface, ViewParams};

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
    /// pixel's, so a neighbour brings nothing the pixel lacks). Visibility
    /// reuse, the default, takes none: set `visibility: false` with them.
    pub neighbours: u32,
    /// Radius of the neighbours' disk, in pixels.
    pub radius: f32,
    /// The largest confidence a reservoir keeps, in frames (`≥ 1`): its
    /// weight against this record's pick.
    pub max_confidence: f32,
    /// Visibility reuse (ReSTIR DI's): each record's own picks are
    /// shadowed before they are combined with the history, and an occluded
    /// one enters with no weight; a final pick whose ray is blocked keeps
    /// no weight for the next record. A reservoir then holds only picks
    /// that reach its pixel, and its weight averages over the records it
    /// stands for how much of the light arrives. A final pick that is one
    /// of the record's own is not traced again, so a slot casts one ray
    /// where its own pick wins and two where the history's does.
    ///
    /// Unbiased where things move too (ReSTIR DI's unbiased form): a
    /// record's pick shares its weight with the history only where it
    /// reached the reprojected surface in the previous record, so where
    /// the camera or the pick's light moved, a pick that reaches the pixel
    /// and the history does not hold casts one more ray, from the previous
    /// surface to where its light stood (8 picks in the shadow test, every
    /// light moving: 15.2 rays per pixel against 10.0 still). Where
    /// occluders moved ([`DirectPass::set_shadows`] with moved instances),
    /// the history has no share of a pick whose previous ray crosses the
    /// box they moved in: the pixels behind a moving object lose some
    /// history, not their mean.
    pub visibility: bool,
}

impl Default for DirectReuse {
    /// The pixel's own history only (no neighbours; a disk of 16 pixels
    /// where some are asked for), at most 20 frames' confidence, visibility
    /// reuse (issue 47's noise target: with 3 picks, one frame of a still
    /// view at a fifth of 8 weighted picks' error at fewer rays; plain
    /// reuse, `visibility: false`, barely lowers it where shadows are the
    /// noise; docs/results/reused-picks.md).
    fn default() -> Self {
        DirectReuse { neighbours: 0, radius: 16.0, max_confidence: 20.0, visibility: true }
    }
}

impl DirectReuse {
    pub(super) fn check(&self) -> Result<(), GpuError> {
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
    pub(super) fn pixel_bytes(k: u32) -> u64 {
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

/// `inputs` checked against `desc` (formats, sizes, usages): the record's
/// view uniforms for `seed` and `frame`, the material's dielectric set.
pub(super) fn checked_view(
    desc: &DirectPassDesc,
    inputs: &DirectInputs,
    seed: u32,
    frame: u32,
) -> Result<ViewParams, GpuError> {
    let size = (desc.width, desc.height);
    let mut view = inputs.gbuffer.check(desc.surface, size, seed, frame)?;
    let storage = wgpu::TextureUsages::STORAGE_BINDING;
    check_view("output", inputs.output, size, &[desc.output_format], storage)?;
    let missing =
        |name, what: &str| GpuError::Binding { name, expected: what.into(), found: "none".into() };
    let (material, split) = match desc.outputs {
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
        check_view("specular", s, size, &[desc.output_format], storage)?;
    }
    Ok(view)
}

/// The record's view-projection, for the reuse: the inverse of a depth
/// surface's `inv_view_proj`, or [`DirectInputs::view_projection`].
pub(super) fn view_projection(inputs: &DirectInputs) -> Result<Mat4, GpuError> {
    let m = match (inputs.gbuffer.surface, inputs.view_projection) {
        (_, Some(m)) => m,
        (Surface::Depth { inv_view_proj, .. }, None) => inv_view_proj.inverse(),
        (Surface::Position(_), None) => {
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
