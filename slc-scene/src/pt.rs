//! Application B's backend-neutral half: the light-selection methods and
//! settings, the scene prepared for path tracing (lights from emissive
//! triangles plus point/spot/IES lights, one BSH and power table), and the
//! progressive accumulation both backends add their passes to.

use crate::RenderError;
use crate::image::Image;
use crate::light_bvh::LightBvh;
use crate::lights::{LightSet, emissive_triangles};
use crate::scene::Scene;
use glam::Vec3;
use slc_core::bsh::{Bsh, BshShape};
use slc_core::light::Light;

/// Reservoir slots of `slc-reservoir`.
pub const RESERVOIR_K: usize = 8;

/// Independent weighted picks of `slc-weighted` (one shadow ray each).
/// One pick wins at equal time: on `scenes/bunny-in-cornell.toml` (64×64,
/// 5 s, ε = 0.3) k = 2 drew 778 spp for a net RMSE of 0.0147, k = 1 895
/// spp for 0.0137; the noise per sample (RMSE·√spp, 0.41) was the same, so
/// the second pick, among the same candidates, bought nothing. Many small
/// lights and lights-only: equal within the runs' noise.
pub const WEIGHTED_K: usize = 1;

/// Light selection for next-event estimation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PtMethod {
    /// Stochastic light culling over the BSH, every candidate evaluated.
    Slc,
    /// Stochastic light culling with a k-slot reservoir over the candidates.
    SlcReservoir,
    /// Stochastic light culling with [`WEIGHTED_K`] picks among the
    /// candidates, each in proportion to its importance over its roulette
    /// probability (`slc_core::importance`; beyond the paper).
    SlcWeighted,
    /// One light, uniformly.
    Uniform,
    /// One light, in proportion to its power.
    Power,
    /// One light, by light-BVH importance sampling.
    LightBvh,
}

impl PtMethod {
    /// Name on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            PtMethod::Slc => "slc",
            PtMethod::SlcReservoir => "slc-reservoir",
            PtMethod::SlcWeighted => "slc-weighted",
            PtMethod::Uniform => "uniform",
            PtMethod::Power => "power",
            PtMethod::LightBvh => "lightbvh",
        }
    }

    /// Every method, in report order.
    pub const ALL: [PtMethod; 6] = [
        PtMethod::Slc,
        PtMethod::SlcReservoir,
        PtMethod::SlcWeighted,
        PtMethod::Uniform,
        PtMethod::Power,
        PtMethod::LightBvh,
    ];

    /// The method's position in [`PtMethod::ALL`] (its declaration order).
    pub fn index(self) -> usize {
        self as usize
    }

    /// Whether the method culls by stochastic ranges (and so has ε).
    pub fn culls(self) -> bool {
        matches!(self, PtMethod::Slc | PtMethod::SlcReservoir | PtMethod::SlcWeighted)
    }
}

/// Settings of a path-traced render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PtSettings {
    /// NEE method.
    pub method: PtMethod,
    /// SLC error bound ε (see [`crate::error_bound::auto_error_bound`] for
    /// one set from the scene).
    pub error_bound: f32,
    /// Exposure E (error bound).
    pub exposure: f32,
    /// Seed.
    pub seed: u32,
    /// Longest path: the surface vertices after the camera that estimate
    /// next-event light, plus the emission the last one's BSDF sample
    /// finds (so 1 is the whole direct light; Mitsuba's `max_depth` is this
    /// plus one).
    pub max_depth: u32,
}

impl Default for PtSettings {
    fn default() -> Self {
        // ε = 1, the fixed fallback: `slc` (render and bench) sets ε per
        // scene with `error_bound::auto_error_bound` unless told otherwise,
        // so that a shading point expects the candidates this ε gave on the
        // scenes it was tuned on. Every in-range candidate costs a traversal step and an
        // importance (and, for slc, a shadow ray), so a larger bound (fewer,
        // more heavily weighted candidates) wins at equal time, up to the
        // point where the roulette's own noise dominates. slc-weighted's
        // equal-time net RMSE (64×64, 5 s, `slc bench --app pt
        // --error-bound E`): bunny-in-cornell 0.0169 / 0.0137 / 0.0127 /
        // 0.0157 at ε = 0.1 / 0.3 / 1 / 3; many-small-lights 0.0273 / 0.0254
        // / 0.0306 at ε = 0.3 / 1 / 3; bunny-lights-only 0.0076 / 0.0069 at
        // ε = 0.3 / 1.
        PtSettings { method: PtMethod::Slc, error_bound: 1.0, exposure: 1.0, seed: 1, max_depth: 8 }
    }
}

/// A scene ready to path trace on either backend: the scene, its lights
/// (emissive triangles first, in triangle order, then the extra lights)
/// with their BSH, power table and light BVH, and each triangle's light
/// index.
#[derive(Clone, Debug)]
pub struct PtScene {
    scene: Scene,
    lights: LightSet,
    /// The `lightbvh` baseline's tree over the lights, built on first use
    /// (the other methods never read it: 0.14 s of `slc render`'s start-up
    /// at 49,152 lights on a 2-core EPYC).
    light_bvh: std::sync::OnceLock<LightBvh>,
    /// Light index of each emissive triangle (u32::MAX for others).
    light_of_triangle: Vec<u32>,
    /// The BSH both path tracers refit and walk: over the light set's
    /// bounds, split by the sphere-area heuristic and 4 wide
    /// ([`BshShape::WIDE`]: a faster walk than the light set's balanced
    /// binary tree, which the direct pass deals out to tiles), with a range
    /// tail of [`RANGE_TAIL`].
    bsh: Bsh,
}

/// The path tracers' range tail ([`Bsh::with_tail`]): the 16 largest range
/// spheres of a pass, tested flat after the tree. Issue 30's measurement
/// (`slc-scene/examples/walk_visits.rs`, docs/results/bsh-walk-visits.md):
/// 16 take 2–94% of the walk's visits away on the scene suite (most in
/// clustered lights, whose few largest ranges bound every fixture's
/// subtree), and 64 or 256 little more.
pub const RANGE_TAIL: usize = 16;

impl PtScene {
    /// Emissive triangles become triangle lights; `extra` lights (point,
    /// spot, IES) join them in one BSH. An emissive triangle of zero area is
    /// an error, and so is a scene with no light. The scene's primary light
    /// (the VPL application's) is neither used nor checked
    /// ([`Scene::validate_surfaces`]).
    pub fn new(scene: &Scene, extra: &[Light]) -> Result<PtScene, RenderError> {
        scene.validate_surfaces()?;
        let (mut lights, light_of_triangle) = emissive_triangles(scene)?;
        lights.extend(extra.iter().cloned());
        if lights.is_empty() {
            return Err(RenderError::Setting(
                "the scene has no light (no emissive triangle, no point/spot/IES light)".into(),
            ));
        }
        let lights = LightSet::new(lights)?;
        let light_bvh = std::sync::OnceLock::new();
        let bsh = Bsh::build_with(lights.bounds(), BshShape::WIDE)
            .and_then(|t| t.with_tail(RANGE_TAIL))
            .map_err(|e| RenderError::Setting(e.to_string()))?;
        Ok(PtScene { scene: scene.clone(), lights, light_bvh, light_of_triangle, bsh })
    }

    /// Number of lights.
    pub fn light_count(&self) -> usize {
        self.lights.len()
    }

    /// The scene.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The lights with their BSH and power table.
    pub fn light_set(&self) -> &LightSet {
        &self.lights
    }

    /// The BSH the path tracers refit every pass and walk, as built:
    /// [`BshShape::WIDE`], with a range tail of [`RANGE_TAIL`].
    pub fn bsh(&self) -> &Bsh {
        &self.bsh
    }

    /// The light BVH of the `lightbvh` baseline (built on the first call).
    pub fn light_bvh(&self) -> &LightBvh {
        self.light_bvh.get_or_init(|| LightBvh::new(self.lights.lights(), self.lights.cones()))
    }

    /// The lights, in BSH light-index order.
    pub fn lights(&self) -> &[Light] {
        self.lights.lights()
    }

    /// The lights, as text (for cache keys).
    pub fn lights_debug(&self) -> String {
        format!("{:?}", self.lights.lights())
    }

    /// Light index of each scene triangle (`u32::MAX` when it does not emit).
    pub fn light_of_triangle(&self) -> &[u32] {
        &self.light_of_triangle
    }
}

/// Accumulated progressive render.
pub struct PtRender {
    /// Sum of per-pass radiance.
    sum: Vec<Vec3>,
    /// Passes done.
    pub passes: u32,
    /// Time spent (ms).
    pub time_ms: f64,
    width: u32,
    height: u32,
}

impl PtRender {
    /// An empty accumulation (the path tracers' `render` refuses a size
    /// outside `1..=16384` on either side, [`crate::check_size`]).
    pub fn new(width: u32, height: u32) -> Self {
        PtRender {
            sum: vec![Vec3::ZERO; width as usize * height as usize],
            passes: 0,
            time_ms: 0.0,
            width,
            height,
        }
    }

    /// Adds `passes` passes rendered elsewhere (e.g. on the GPU): their
    /// per-pixel sum, with non-finite pixels dropped, and their time.
    pub fn accumulate(&mut self, sum: &[Vec3], passes: u32, time_ms: f64) {
        for (a, v) in self.sum.iter_mut().zip(sum) {
            *a += if v.is_finite() { *v } else { Vec3::ZERO };
        }
        self.passes += passes;
        self.time_ms += time_ms;
    }

    /// Image width and height.
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// The mean image so far.
    pub fn image(&self) -> Image {
        let n = self.passes.max(1) as f32;
        Image {
            width: self.width,
            height: self.height,
            data: self.sum.iter().map(|s| *s / n).collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The path tracers never read the primary light, so a scene of one's
    /// own needs none that works; its surfaces are still checked.
    #[test]
    fn the_primary_light_is_not_the_path_tracers_business() {
        use crate::scene::PrimaryLight;
        let mut scene = Scene::cornell_box();
        scene.primary = PrimaryLight::Directional { direction: Vec3::ZERO, irradiance: Vec3::ONE };
        assert!(scene.validate().is_err());
        assert!(PtScene::new(&scene, &[]).is_ok());
        scene.triangles[0][1].x = f32::NAN;
        assert!(PtScene::new(&scene, &[]).is_err());
    }

    #[test]
    fn index_is_the_position_in_all() {
        for (i, m) in PtMethod::ALL.into_iter().enumerate() {
            assert_eq!(m.index(), i, "{}", m.name());
        }
    }
}
