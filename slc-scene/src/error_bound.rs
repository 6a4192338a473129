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

/// Most expected candidates per point `auto:C` takes: every candidate
/// costs a walk step and a weight, so more than this is no bound at all.
pub const MAX_TARGET_CANDIDATES: f64 = 1e4;

/// The path tracer's ε as a user states it (`--error-bound`, a scene
/// file's `[render] pt_error_bound`): a number, or `auto` / `auto:C`, the
/// ε whose expected candidates per shading point are `C`
/// ([`TARGET_CANDIDATES`] by default; [`auto_error_bound`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BoundArg {
    /// Set from the scene for this many expected candidates per point.
    Auto(f64),
    /// This ε.
    Value(f32),
}

impl core::str::FromStr for BoundArg {
    type Err = String;

    /// A number, `auto`, or `auto:C` (a number C; its range is checked
    /// where the bound is set, [`BoundArg::check_target`]).
    fn from_str(s: &str) -> Result<BoundArg, String> {
        if s == "auto" {
            return Ok(BoundArg::Auto(TARGET_CANDIDATES));
        }
        if let Some(c) = s.strip_prefix("auto:") {
            return c
                .parse::<f64>()
                .map(BoundArg::Auto)
                .map_err(|_| format!("'{c}' in '{s}' is not a number of candidates"));
        }
        s.parse::<f32>()
            .map(BoundArg::Value)
            .map_err(|_| format!("'{s}' is neither a number, auto nor auto:C"))
    }
}

impl BoundArg {
    /// Checks an `auto:C` target: `C` in (0, [`MAX_TARGET_CANDIDATES`]].
    pub fn check_target(c: f64) -> Result<f64, String> {
        if c > 0.0 && c <= MAX_TARGET_CANDIDATES {
            Ok(c)
        } else {
            Err(format!(
                "auto:{c}: the expected candidates per point must be in (0, {MAX_TARGET_CANDIDATES}]"
            ))
        }
    }
}

/// Most shading points the mean is taken over; fewer (down to
/// [`MIN_POINTS`]) where points × lights would pass [`MAX_PAIRS`].
pub const SAMPLE_POINTS: u32 = 256;

/// Fewest shading points the mean is taken over.
pub const MIN_POINTS: u32 = 32;

/// Most (point, light) pairs the model keeps (`4 · MAX_PAIRS` bytes).
pub const MAX_PAIRS: usize = 1 << 23;

/// Each (sample point, light) pair's `b = a_j / d_j²` (`a_j = r_t,j²` at
/// ε = 1, at the model's exposure; +∞ where the point is inside a lit
/// light's bound, 0 for a dark light), so `C(x, ε) = Σ_j min(b / ε, 1)`.
pub struct CandidateModel {
    b: Vec<f32>,
    lights: usize,
    points: usize,
}

impl CandidateModel {
    /// The model of `pts` at `exposure`, over points drawn (seeded,
    /// deterministic) uniformly by area on its non-emissive surfaces:
    /// [`SAMPLE_POINTS`], fewer for many lights (at least [`MIN_POINTS`]);
    /// `None` without such surfaces or lights.
    pub fn new(pts: &PtScene, exposure: f32) -> Option<CandidateModel> {
        let params = RangeParams::new(1.0, exposure).ok()?;
        let lights = pts.lights();
        if lights.is_empty() {
            return None;
        }
        let surfaces = Surfaces::new(pts.scene()).ok()?;
        let n = (MAX_PAIRS / lights.len()).clamp(MIN_POINTS as usize, SAMPLE_POINTS as usize);
        let bounds = pts.light_set().bounds();
        let a: Vec<f32> = lights.iter().map(|l| params.threshold_range2(l.peak())).collect();
        let mut b = Vec::with_capacity(n * lights.len());
        for i in 0..n as u32 {
            let x = surfaces.sample(&mut Stream::new(0xe9_5150, i)).0;
            b.extend(bounds.iter().zip(&a).map(|(bd, &a)| {
                let d = ((x - bd.center).length() - bd.extent).max(0.0);
                // A dark light is never a candidate (not 0/0 inside its bound).
                if a > 0.0 { a / (d * d) } else { 0.0 }
            }));
        }
        Some(CandidateModel { b, lights: lights.len(), points: n })
    }

    /// Lights in the model.
    pub fn lights(&self) -> usize {
        self.lights
    }

    /// Mean expected candidates per point at error bound `eps`.
    pub fn mean_candidates(&self, eps: f32) -> f64 {
        let inv = 1.0 / eps;
        // f32 sums per point in LANES interleaved partial sums (terms ≤ 1,
        // at most MAX_PAIRS / MIN_POINTS = 262,144 a point, so each partial
        // sum holds ≤ 16,384 and its rounding stays below 10⁻³ of it), in a
        // fixed order the compiler vectorises on any SIMD width; f64 across.
        // The bisection takes ~13 of these passes over up to 8.4 M pairs.
        const LANES: usize = 16;
        let row_sum = |row: &[f32]| {
            let mut acc = [0.0f32; LANES];
            let mut chunks = row.chunks_exact(LANES);
            for c in &mut chunks {
                for (a, &b) in acc.iter_mut().zip(c) {
                    *a += (b * inv).min(1.0);
                }
            }
            let rest: f32 = chunks.remainder().iter().map(|&b| (b * inv).min(1.0)).sum();
            acc.iter().map(|&a| a as f64).sum::<f64>() + rest as f64
        };
        self.b.chunks(self.lights).map(row_sum).sum::<f64>() / self.points as f64
    }
}

/// The ε whose mean expected candidates per point are `target` (halved to
/// half the light count when that is less; see the module docs), to 1%,
/// by bisection on `ln ε` over `[10⁻¹², 10¹²]`. `None` when the scene has
/// no lights or no surfaces, or no light reaches a surface (all emit
/// nothing: any ε gives no candidates; the caller keeps its fixed default).
pub fn auto_error_bound(pts: &PtScene, exposure: f32, target: f64) -> Option<f32> {
    let model = CandidateModel::new(pts, exposure)?;
    if model.mean_candidates(1e-12) == 0.0 {
        return None;
    }
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
    use glam::Vec3;
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
                Light::Point(
                    PointLight::new(
                        Vec3::new(0.02 + 0.5 * x, 0.3, 0.02 + 0.5 * z),
                        Vec3::splat(intensity),
                    )
                    .unwrap(),
                )
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
        let model = CandidateModel::new(&pts, 1.0).unwrap();
        let eps = 0.05f32;
        let params = RangeParams::new(1.0, 1.0).unwrap();
        let surfaces = Surfaces::new(pts.scene()).unwrap();
        // The model's first point, drawn again, and one ξ-draw count per frame.
        let x = surfaces.sample(&mut Stream::new(0xe9_5150, 0)).0;
        let want: f64 = model.b[..model.lights].iter().map(|&b| (b / eps).min(1.0) as f64).sum();
        let draws = 4000u32;
        let mut got = 0u64;
        let mut var = 0.0f64;
        for (j, (l, bd)) in pts.lights().iter().zip(pts.light_set().bounds()).enumerate() {
            let rt2 = params.threshold_range2(l.peak()) / eps;
            let dist = (x - bd.center).length();
            let d = (dist - bd.extent).max(0.0);
            let p = (rt2 / (d * d)).min(1.0) as f64;
            var += p * (1.0 - p);
            for k in 0..draws {
                let r2 = slc_core::range::random_range2(rt2, slc_core::xi::xi_for(3, k, j as u32));
                got += (r2.sqrt() + bd.extent >= dist) as u64;
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

    /// Lights that emit nothing are never candidates: no ε is automatic
    /// (the bisection would run to its lower end, 10⁻¹²).
    #[test]
    fn dark_lights_set_no_bound() {
        assert_eq!(auto_error_bound(&scene_with(grid(8, 0.0)), 1.0, 1.5), None);
    }
}
