//! The path tracer's SLC error bound ε set from the scene itself.
//!
//! What ε decides in path tracing is how many lights a shading point meets
//! as candidates: a light `j` whose bound has centre `c_j` and extent `R_j`
//! is a candidate at `x` when its random range reaches it,
//! `√r_j² + R_j ≥ |x − c_j|`, and with `r_j² = r_t,j²/(1 − ξ)` and
//! `r_t,j² = E·I_max,j/(2π ε)` (Tokuyoshi & Harada 2016, eq. 5) that happens
//! with probability `min(r_t,j²/d_j², 1)`, `d_j = max(|x − c_j| − R_j, 0)`.
//! So the expected candidates at `x` are
//!
//! `C(x, ε) = Σ_j min(a_j / (ε d_j²), 1)`,  `a_j = r_t,j²(ε = 1)`,
//!
//! decreasing in ε. Every candidate costs a traversal step and an
//! importance evaluation; more candidates give the weighted pick more
//! lights to choose from. The time a sample costs and what its selection
//! buys both follow `C`, not ε: the same ε gives 24× the candidates when
//! the same power is split among 24× fewer, brighter lights, or when the
//! scene is 5× smaller. [`auto_error_bound`] therefore picks the ε whose
//! mean `C` over the scene's surfaces (points uniform by area on the
//! non-emissive triangles) is a target count, [`TARGET_CANDIDATES`]: the
//! rule depends on the light count (through `C`'s sum), the power
//! distribution (the `a_j`) and the scene's extent (the `d_j`) and nothing
//! else. Where the scene has fewer lights than twice the target, every
//! light is at most half-likely a candidate: the target is half the count.

use crate::placement::{Stream, Surfaces};
use crate::pt::PtScene;
use glam::Vec3;
use slc_core::range::RangeParams;

/// Candidates per shading point the automatic ε aims at.
///
/// Measured on the three scenes the fixed ε = 1 was chosen on by
/// equal-time sweeps ([`crate::pt::PtSettings`]'s default): there ε = 1
/// gives a mean `C` of 1.45 (bunny-in-cornell), 2.51 (many-small-lights)
/// and 0.56 (bunny-lights-only), and each sweep's best ε lies within a
/// factor 3 of 1, so the best `C` lies between about 0.5 and 2.5 in every
/// one; 1.5 is their middle (`cargo run --release -p slc-scene --example
/// candidates -- SCENE.toml …` prints `C` at ε = 1 and the automatic ε).
/// One number for every scene: the rule carries the tuned cost per sample
/// to scenes nobody tuned it on, instead of the tuned ε.
pub const TARGET_CANDIDATES: f64 = 1.5;

/// Shading points the mean is taken over.
pub const SAMPLE_POINTS: u32 = 256;

/// Each light's `a_j = r_t,j²` at ε = 1 (at `exposure`), its centre and
/// extent, and the sample points.
pub struct CandidateModel {
    a: Vec<f32>,
    centre: Vec<Vec3>,
    extent: Vec<f32>,
    points: Vec<Vec3>,
}

impl CandidateModel {
    /// The model of `pts` at `exposure`, over [`SAMPLE_POINTS`] points drawn
    /// (seeded, deterministic) uniformly by area on its non-emissive
    /// surfaces; `None` without such surfaces or lights.
    pub fn new(pts: &PtScene, exposure: f32) -> Option<CandidateModel> {
        let params = RangeParams::new(1.0, exposure).ok()?;
        let lights = pts.lights();
        if lights.is_empty() {
            return None;
        }
        let surfaces = Surfaces::new(pts.scene()).ok()?;
        let points = (0..SAMPLE_POINTS).map(|i| surfaces.sample(&mut Stream::new(0xe9_5150, i)).0).collect();
        let bounds = pts.light_set().bounds();
        Some(CandidateModel {
            a: lights.iter().map(|l| params.threshold_range2(l.peak())).collect(),
            centre: bounds.iter().map(|b| b.center).collect(),
            extent: bounds.iter().map(|b| b.extent).collect(),
            points,
        })
    }

    /// Lights in the model.
    pub fn lights(&self) -> usize {
        self.a.len()
    }

    /// Mean expected candidates per point at error bound `eps`.
    pub fn mean_candidates(&self, eps: f32) -> f64 {
        let mut sum = 0.0f64;
        for &x in &self.points {
            for j in 0..self.a.len() {
                let d = ((x - self.centre[j]).length() - self.extent[j]).max(0.0);
                let p = if d * d * eps <= self.a[j] { 1.0 } else { self.a[j] / (eps * d * d) };
                sum += p as f64;
            }
        }
        sum / self.points.len() as f64
    }
}

/// The ε whose mean expected candidates per point are `target` (halved to
/// half the light count when that is less; see the module docs), to 1%,
/// by bisection on `ln ε` over `[10⁻¹², 10¹²]`. `None` when the scene has
/// no lights or no surfaces (the caller keeps its fixed default).
pub fn auto_error_bound(pts: &PtScene, exposure: f32, target: f64) -> Option<f32> {
    let model = CandidateModel::new(pts, exposure)?;
    let target = target.min(0.5 * model.lights() as f64);
    let (mut lo, mut hi) = ((1e-12f64).ln(), (1e12f64).ln());
    // C falls as ε grows: move the bracket toward the target.
    while hi - lo > 0.01 {
        let mid = 0.5 * (lo + hi);
        if model.mean_candidates(mid.exp() as f32) > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some((0.5 * (lo + hi)).exp() as f32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;
    use slc_core::light::{Light, PointLight};

    fn scene_with(lights: Vec<Light>) -> PtScene {
        let mut s = Scene::cornell_box();
        // Its ceiling light off: the point lights alone.
        for m in &mut s.materials {
            m.emission = Vec3::ZERO;
        }
        PtScene::new(&s, &lights).unwrap()
    }

    fn grid(n: u32, intensity: f32) -> Vec<Light> {
        (0..n)
            .map(|i| {
                let (x, z) = ((i % 32) as f32 / 32.0, (i / 32) as f32 / 32.0);
                Light::Point(PointLight::new(Vec3::new(0.02 + 0.5 * x, 0.3, 0.02 + 0.5 * z), Vec3::splat(intensity)).unwrap())
            })
            .collect()
    }

    /// The automatic ε meets its target, and scales as the rule says: the
    /// same lights 10× brighter need 10× the ε for the same candidates.
    #[test]
    fn auto_bound_meets_its_target_and_scales_with_power() {
        let dim = scene_with(grid(512, 0.01));
        let bright = scene_with(grid(512, 0.1));
        let e_dim = auto_error_bound(&dim, 1.0, 8.0).unwrap();
        let e_bright = auto_error_bound(&bright, 1.0, 8.0).unwrap();
        let c = CandidateModel::new(&dim, 1.0).unwrap().mean_candidates(e_dim);
        assert!((c / 8.0 - 1.0).abs() < 0.02, "mean candidates {c}");
        assert!((e_bright / e_dim / 10.0 - 1.0).abs() < 0.03, "{e_dim} {e_bright}");
    }

    /// `mean_candidates` is the expectation it claims: over many ξ draws the
    /// lights whose random range reaches a point average to it (one point,
    /// 4,000 draws of every light's ξ, within 5σ of the binomial spread).
    #[test]
    fn mean_candidates_is_the_expected_count() {
        let pts = scene_with(grid(256, 0.02));
        let mut model = CandidateModel::new(&pts, 1.0).unwrap();
        model.points.truncate(1);
        let x = model.points[0];
        let eps = 0.05f32;
        let want = model.mean_candidates(eps);
        let draws = 4000u32;
        let mut got = 0u64;
        let mut var = 0.0f64;
        for j in 0..model.lights() {
            let d = ((x - model.centre[j]).length() - model.extent[j]).max(0.0);
            let rt2 = model.a[j] / eps;
            let p = (rt2 / (d * d)).min(1.0) as f64;
            var += p * (1.0 - p);
            for k in 0..draws {
                let xi = slc_core::xi::xi_for(3, k, j as u32);
                let r2 = slc_core::range::random_range2(rt2, xi);
                got += (r2.sqrt() + model.extent[j] >= (x - model.centre[j]).length()) as u64;
            }
        }
        let mean = got as f64 / draws as f64;
        let sd = (var / draws as f64).sqrt();
        assert!((mean - want).abs() < 5.0 * sd + 1e-3, "sampled {mean}, model {want}, sd {sd}");
    }

    /// Fewer lights than twice the target: half of them.
    #[test]
    fn few_lights_aim_at_half_of_them() {
        let pts = scene_with(grid(6, 0.05));
        let eps = auto_error_bound(&pts, 1.0, 8.0).unwrap();
        let c = CandidateModel::new(&pts, 1.0).unwrap().mean_candidates(eps);
        assert!((c - 3.0).abs() < 0.06, "{c}");
    }
}
