//! Application A's backend-neutral half (the paper's real-time VPL
//! indirect illumination): settings, the G-buffer and VPLs a
//! frame is shaded from, the 8×8 interleaving, and what a backend returns.

use crate::RenderError;
pub use crate::culling::Culling;
use crate::image::Image;
use glam::Vec3;

/// Per-run settings (the scene-dependent part lives in the [`VplInputs`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VplSettings {
    /// How the VPLs are culled, with its parameters ([`Culling::Reference`]:
    /// every VPL at every pixel, the ground truth).
    pub culling: Culling,
    /// Seed of the per-VPL ξ.
    pub seed: u32,
    /// Frame number (a new ξ set and a new shift of the interleaving's
    /// subset map per frame).
    pub frame: u32,
    /// Tile size in sub-image pixels.
    pub tile: u32,
    /// Apply the cross-bilateral filter (interleaved methods).
    pub denoise: bool,
    /// Give every light this ξ instead of the hashed per-light one. Not an
    /// estimator on its own: averaging frames over a grid of ξ values is
    /// quadrature of the expectation over ξ (how the tests prove the
    /// pipeline unbiased). Must lie in `[0, 1)`.
    pub fixed_xi: Option<f32>,
    /// Near-field radius `R_n` (scene units; both backends): every pixel
    /// shades the VPLs closer than `R_n` itself, unscaled and undenoised,
    /// and its interleaved subset takes only the rest, with a smooth
    /// partition between ([`slc_core::interleave::vpl_near_weight`]).
    /// `None` (the default): [`NEAR_FACTOR`] × the clamp distance, which
    /// removes the `P × P` blotches where a surface meets the floor;
    /// `Some(0)`: no split.
    pub near_radius: Option<f32>,
}

/// Near-field radius, in clamp distances, that removes the blotches at the
/// base of the default image's tall block (`--near-radius 0.0285`, 3 × the
/// 9.5 mm clamp): RMSE against the all-VPL reference 0.00125 → 0.00088,
/// and the largest pixel error in the crop of the block's base 0.078 →
/// 0.025, for about 50 ms more CPU shading at 512² (≈ 170 more lights
/// tested per pixel). 2 × leaves faint blobs; 4 × costs more for less.
pub const NEAR_FACTOR: f32 = 3.0;

impl Default for VplSettings {
    /// Stochastic culling at the default error bound
    /// ([`Culling::default`]), seed 1, frame 0, 4×4 tiles, denoised, the
    /// default near field.
    fn default() -> Self {
        VplSettings {
            culling: Culling::default(),
            seed: 1,
            frame: 0,
            tile: 4,
            denoise: true,
            fixed_xi: None,
            near_radius: None,
        }
    }
}

impl VplSettings {
    /// Checks the settings every backend shares (the culling checked its
    /// own parameters when it was made).
    pub fn validate(&self) -> Result<(), RenderError> {
        if let Some(x) = self.fixed_xi {
            slc_core::range::Xi::new(x).map_err(|e| RenderError::Setting(e.to_string()))?;
        }
        if self.tile == 0 {
            return Err(RenderError::Setting("tile size must be > 0".into()));
        }
        if let Some(r) = self.near_radius
            && !(r.is_finite() && r >= 0.0)
        {
            return Err(RenderError::Setting(format!("near radius {r} must be finite and >= 0")));
        }
        Ok(())
    }

    /// `R_n²` of the near-field split ([`VplSettings::near_radius`]) for a
    /// clamp distance `√min_d2`; 0: no split.
    pub fn near_r2(&self, min_d2: f32) -> f32 {
        self.near_radius.map_or(NEAR_FACTOR * NEAR_FACTOR * min_d2, |r| r * r)
    }
}

/// Interleaving period (8×8 subsets, as in the paper).
pub const PERIOD: u32 = 8;

/// The reflective shadow map's side for `vpls` VPLs: `s` with `vpls = s²`,
/// `s` a multiple of [`PERIOD`] up to 4096.
pub fn rsm_side(vpls: u64) -> Result<u32, RenderError> {
    let s = vpls.isqrt();
    if s * s != vpls || s == 0 || !s.is_multiple_of(PERIOD as u64) || s > 4096 {
        return Err(RenderError::VplCount(vpls));
    }
    Ok(s as u32)
}

/// Checks what a VPL frame is built for, as every backend's frame does:
/// the scene, the image size (`1..=16384`), the RSM edge (a positive
/// multiple of [`PERIOD`] up to 4096, `rsm_size²` VPLs), and the clamp
/// distance of the VPL fall-off, which it returns (`None`: 1% of the
/// scene's diagonal; finite and ≥ 0).
pub fn check_frame(
    scene: &crate::scene::Scene,
    width: u32,
    height: u32,
    rsm_size: u32,
    min_distance: Option<f32>,
) -> Result<f32, RenderError> {
    scene.validate()?;
    crate::check_size(width, height)?;
    rsm_side((rsm_size as u64).pow(2))?;
    let min_distance = min_distance.unwrap_or(0.01 * scene.diagonal());
    if !(min_distance.is_finite() && min_distance >= 0.0) {
        return Err(RenderError::Setting(format!(
            "min distance {min_distance} must be finite and >= 0"
        )));
    }
    Ok(min_distance)
}

/// The culling and shading work of one field of a VPL frame (the
/// interleaved far field, or the near field), counted the same way on both
/// backends: per tile with a shaded pixel, the tests its traversal of the
/// lights' box hierarchy made (`slc_core::cluster`: every group box, the
/// cluster boxes of the groups it met, the spheres of the lit lights of the
/// clusters it met), and per shaded pixel the lights its loop tested (the
/// tile's list) and kept. The per-pixel figures divide by the shaded
/// pixels; a tile's tests count for each of its pixels as tests/pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct WorkCounts {
    /// Tiles with a shaded pixel (those that traverse).
    pub tiles: u64,
    /// Group boxes tested.
    pub group_tests: u64,
    /// Cluster boxes tested.
    pub cluster_tests: u64,
    /// Light spheres tested.
    pub sphere_tests: u64,
    /// Lights the shading loops tested, summed over the shaded pixels.
    pub tested: u64,
    /// Lights the shading loops kept, summed over the shaded pixels.
    pub kept: u64,
    /// Pixels shaded.
    pub pixels: u64,
}

impl WorkCounts {
    /// Culling tests of every kind (groups, clusters, spheres).
    pub fn culling_tests(&self) -> u64 {
        self.group_tests + self.cluster_tests + self.sphere_tests
    }

    /// `count` per shaded pixel (0 without one).
    pub fn per_pixel(&self, count: u64) -> f64 {
        count as f64 / self.pixels.max(1) as f64
    }
}

impl std::ops::Add for WorkCounts {
    type Output = WorkCounts;
    fn add(self, o: WorkCounts) -> WorkCounts {
        WorkCounts {
            tiles: self.tiles + o.tiles,
            group_tests: self.group_tests + o.group_tests,
            cluster_tests: self.cluster_tests + o.cluster_tests,
            sphere_tests: self.sphere_tests + o.sphere_tests,
            tested: self.tested + o.tested,
            kept: self.kept + o.kept,
            pixels: self.pixels + o.pixels,
        }
    }
}

impl std::iter::Sum for WorkCounts {
    fn sum<I: Iterator<Item = WorkCounts>>(iter: I) -> WorkCounts {
        iter.fold(WorkCounts::default(), |a, b| a + b)
    }
}

/// Timings (milliseconds) and work counts of one frame.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct VplStats {
    /// G-buffer (shared by all methods; measured once per context).
    pub gbuffer_ms: f64,
    /// Reflective shadow map (once per context).
    pub rsm_ms: f64,
    /// Direct light with shadow rays (once per context).
    pub direct_ms: f64,
    /// Range computation, tile culling and shading.
    pub shading_ms: f64,
    /// Denoise, de-interleave and composition.
    pub denoise_ms: f64,
    /// Sum of the above.
    pub total_ms: f64,
    /// Number of VPLs.
    pub vpls: usize,
    /// Lights in the shaded pixels' tile lists, per shaded pixel (the loop's work).
    pub lights_per_pixel: f64,
    /// Lights that passed the keep test, per shaded pixel.
    pub kept_per_pixel: f64,
    /// Light evaluations in the shading loop.
    pub evaluations: u64,
    /// The far field's work (the interleaved shading).
    pub far_work: WorkCounts,
    /// The near field's work.
    pub near_work: WorkCounts,
}

impl VplStats {
    /// These statistics with the G-buffer, RSM and direct-light times of
    /// `inputs` (a warm re-run of those stages) and the total summed again.
    pub fn with_input_times(mut self, inputs: &VplStats) -> VplStats {
        (self.gbuffer_ms, self.rsm_ms, self.direct_ms) =
            (inputs.gbuffer_ms, inputs.rsm_ms, inputs.direct_ms);
        self.total_ms = self.stage_sum();
        self
    }

    /// The frame's time: G-buffer + RSM + direct + shading + denoise.
    pub fn stage_sum(&self) -> f64 {
        self.gbuffer_ms + self.rsm_ms + self.direct_ms + self.shading_ms + self.denoise_ms
    }
}

/// Indirect irradiance of one frame before denoise and composition (what a
/// backend computes).
#[derive(Clone, Debug)]
pub struct Shaded {
    /// Irradiance per pixel (zero where no surface), the near field of the
    /// split included.
    pub irradiance: Vec<Vec3>,
    /// The near field of the split ([`VplSettings::near_radius`]): the part
    /// of `irradiance` that is exact at every pixel, which the denoise
    /// leaves alone (it filters `irradiance − near`, the interleaved far
    /// field); empty when there is none or `irradiance` is already denoised.
    pub near: Vec<Vec3>,
    /// The specular correction at every pixel with a specular lobe
    /// ([`GBuffer::specular_at`]; zero elsewhere): the same kept VPLs, the
    /// same weights and transfer `T` as `irradiance`, each times
    /// `Φ ⊙ (f(l, v) − c_diff/π)` (slc-core's glTF BRDF less the diffuse
    /// albedo [`Specular::diffuse_albedo`] over π), so the VPL light's
    /// radiance is `c_diff/π · E + S`. Empty when no pixel has a lobe, or
    /// when the backend shades VPL light as Lambertian (`albedo/π · E`).
    pub specular: Vec<Vec3>,
    /// The near field's part of `specular` (as `near` is `irradiance`'s);
    /// empty when `near` is.
    pub specular_near: Vec<Vec3>,
    /// Lights that passed the keep test, per pixel.
    pub kept: Vec<u32>,
    /// Light evaluations of the shading loop.
    pub evaluations: u64,
    /// The far field's work (empty for the reference and where a backend
    /// does not count).
    pub far_work: WorkCounts,
    /// The near field's work (likewise).
    pub near_work: WorkCounts,
    /// Shading time (ms).
    pub shading_ms: f64,
    /// `Some(ms)` when the backend has already denoised `irradiance` (the
    /// GPU does, with the same filter), so the frame's composition does not.
    pub denoised_ms: Option<f64>,
}

/// One rendered frame.
#[derive(Clone, Debug)]
pub struct VplFrame {
    /// Final linear radiance.
    pub image: Image,
    /// Timings and counts.
    pub stats: VplStats,
}

/// Per-pixel surface attributes (row-major, y down). Pixels that see no
/// surface have `depth = ∞` and zero attributes.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct GBuffer {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// World position of the visible surface.
    pub position: Vec<Vec3>,
    /// Unit normal, flipped to face the camera.
    pub normal: Vec<Vec3>,
    /// Diffuse albedo.
    pub albedo: Vec<Vec3>,
    /// Emitted radiance.
    pub emission: Vec<Vec3>,
    /// Distance from the camera (∞ for background).
    pub depth: Vec<f32>,
    /// The camera's position, which `depth` is the distance from (a
    /// backend that recomputes depth from positions, as the GPU's indirect
    /// pass does, needs it), and the view direction of every pixel.
    pub eye: Vec3,
    /// Each pixel's specular lobe (glTF metallic-roughness; `albedo` is its
    /// base colour), or empty: then every pixel is Lambertian and VPL light
    /// is shaded as `albedo/π`, as it is where a pixel's lobe has no
    /// specular part ([`Specular::has_specular`]).
    pub specular: Vec<Specular>,
}

/// The specular part of a pixel's glTF metallic-roughness material
/// ([`crate::scene::Material`] without its base colour and emission, which
/// the G-buffer holds as `albedo` and `emission`). The default (all zero)
/// is Lambertian.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Specular {
    /// Metallic factor in `[0, 1]`.
    pub metallic: f32,
    /// Perceptual roughness in `[0, 1]` (GGX `α = roughness²`).
    pub roughness: f32,
    /// The dielectric's Fresnel reflectance at normal incidence.
    pub f0: Vec3,
    /// The dielectric's Fresnel reflectance at grazing incidence.
    pub f90: f32,
}

impl Specular {
    /// The specular part of `m`.
    pub fn of(m: &crate::scene::Material) -> Specular {
        Specular { metallic: m.metallic, roughness: m.roughness, f0: m.f0, f90: m.f90 }
    }

    /// `true` when the lobe has a specular part ([`slc_core::brdf::has_specular`]).
    pub fn has_specular(&self) -> bool {
        slc_core::brdf::has_specular(self.metallic, self.f0, self.f90)
    }

    /// `c_diff = (1 − m)·b`, the albedo a pixel of base colour `base`
    /// multiplies its Lambertian VPL irradiance by in the composition
    /// ([`Shaded::specular`] holds the rest of its BRDF): the metal has
    /// no diffuse lobe, so its VPL light is all in the correction.
    pub fn diffuse_albedo(&self, base: Vec3) -> Vec3 {
        slc_core::brdf::diffuse_albedo(base, self.metallic)
    }
}

impl GBuffer {
    /// `true` where the pixel sees a surface.
    pub fn valid(&self, i: usize) -> bool {
        self.depth[i].is_finite()
    }

    /// Pixel `i`'s specular lobe where it has one (a surface whose material
    /// is not Lambertian), else `None`.
    pub fn specular_at(&self, i: usize) -> Option<Specular> {
        self.specular.get(i).filter(|s| s.has_specular() && self.valid(i)).copied()
    }

    /// `true` when some pixel has a specular lobe.
    pub fn has_specular(&self) -> bool {
        (0..self.specular.len()).any(|i| self.specular_at(i).is_some())
    }

    /// Pixel `i`'s outgoing radiance in the VPL frame, the composition both
    /// backends' frames make: 0 off the surfaces; from the direct
    /// irradiance `direct` of the primary light `primary`, the VPLs'
    /// irradiance `indirect` and, where the frame has one, their specular
    /// correction `specular`: `L_e + ρ/π·(E_direct + E_indirect)`
    /// ([`slc_core::frame::diffuse_radiance`]) for a Lambertian pixel or
    /// without a correction, else `L_e + f(v, l)·E_direct +
    /// c_diff/π·E_indirect + S` ([`slc_core::frame::glossy_radiance`], `f`
    /// the whole BRDF seen from the eye, `l` toward the light:
    /// [`crate::scene::PrimaryLight::direction_from`]).
    pub fn radiance(
        &self,
        i: usize,
        primary: &crate::scene::PrimaryLight,
        direct: Vec3,
        indirect: Vec3,
        specular: Option<Vec3>,
    ) -> Vec3 {
        use slc_core::brdf::{brdf_eval, ggx_alpha};
        use slc_core::frame::{diffuse_radiance, glossy_radiance};
        if !self.valid(i) {
            return Vec3::ZERO;
        }
        let (base, emission) = (self.albedo[i], self.emission[i]);
        match (self.specular_at(i), specular) {
            (Some(s), Some(spec)) => {
                let (x, n) = (self.position[i], self.normal[i]);
                let v = (self.eye - x).normalize_or_zero();
                let f = brdf_eval(
                    base,
                    s.metallic,
                    s.f0,
                    s.f90,
                    ggx_alpha(s.roughness),
                    n,
                    v,
                    primary.direction_from(x),
                );
                glossy_radiance(base, emission, s.metallic, f, direct, indirect, spec)
            }
            _ => diffuse_radiance(base, emission, direct + indirect),
        }
    }
}

/// VPLs in structure-of-arrays form, one per RSM texel (row-major), so
/// `index = ty · size + tx`. Texels that see nothing, or lie outside the spot
/// cone, are VPLs of zero flux (never kept by SLC, zero contribution).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Vpls {
    /// RSM resolution (`size²` VPLs).
    pub size: u32,
    /// Positions.
    pub position: Vec<Vec3>,
    /// Unit normals (facing the light).
    pub normal: Vec<Vec3>,
    /// Reflected RGB flux Φ (W).
    pub flux: Vec<Vec3>,
}

impl Vpls {
    /// Number of VPLs.
    pub fn len(&self) -> usize {
        self.position.len()
    }
    /// `true` when there are none.
    pub fn is_empty(&self) -> bool {
        self.position.is_empty()
    }
}

/// What shading a VPL frame needs, whoever made it (the CPU backend ray
/// casts it; an engine rasterizes its own): the G-buffer, the VPLs of a
/// `size × size` reflective shadow map, and the squared clamp distance of
/// the VPL fall-off.
#[derive(Clone, Debug, PartialEq)]
pub struct VplInputs {
    /// The G-buffer.
    pub gbuffer: GBuffer,
    /// The VPLs, one per RSM texel.
    pub vpls: Vpls,
    /// Squared clamp distance of the VPL fall-off.
    pub min_d2: f32,
}
