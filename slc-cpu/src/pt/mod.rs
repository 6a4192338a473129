//! Application B of the paper: progressive path tracing with many lights.
//!
//! Diffuse surfaces; at every vertex next-event estimation (NEE) by the
//! chosen light-selection method, combined with cosine BSDF sampling by
//! multiple importance sampling (power heuristic); Russian roulette on path
//! length; one ξ per light per pass (progressive); tile-parallel with rayon;
//! deterministic for a seed.
//!
//! NEE methods ([`PtMethod`]):
//! - `slc`: every light whose BSH range sphere contains the shading point `x`
//!   is a candidate; a point `y` is sampled on it, the RR test uses the
//!   light's ξ at `|x − y|`, and a kept light is weighted by `1/p`.
//! - `slc-reservoir`: the same candidates streamed through a k-slot
//!   reservoir (weight `n/k`), exactly as the GPU kernel does.
//! - `uniform`: one light chosen uniformly; `power`: one light chosen in
//!   proportion to its emitted power (alias table).
//! - `lightbvh`: one light chosen by light-BVH importance sampling
//!   (Conty & Kulla 2018, pbrt-v4's `BVHLightSampler`; [`lightbvh`]).
//!
//! MIS: the light strategy's solid-angle pdf of `y` is
//! `pdf(select) · p_rr(|x−y|) · pdf_area(y) · d²/|cos θ_y|` (talk: "Multiple
//! importance sampling"), with `p_rr = 1` for the baselines and
//! `pdf(select)` = 1 (slc), `min(k/n, 1)` (reservoir), `1/N` (uniform),
//! `Φᵢ/ΣΦ` (power), the tree's pmf at `(x, n)` (lightbvh). These pdfs must not depend on the light's own ξ: a
//! weight that is 0 when this pass's sphere misses `x` makes the two
//! strategies' weights sum to more than one in expectation (the test against
//! uniform sampling caught a 40% bias from exactly that). Point-like lights
//! are delta lights (weight 1).

pub mod lightbvh;
pub mod sampler;

use crate::RenderError;
use crate::geometry::Geometry;
use crate::image::Image;
use crate::scene::Scene;
use glam::Vec3;
use lightbvh::LightBvh;
use rand_core::RngCore;
use rand_pcg::Pcg32;
use rayon::prelude::*;
use sampler::AliasTable;
use slc_core::bsh::Bsh;
use slc_core::light::{Light, LightBound, TriangleLight, connection_factor};
use slc_core::mis::{cosine_direction, cosine_pdf, lambert_brdf, light_strategy_pdf, mis_power};
use slc_core::path::path_survival;
use slc_core::range::{RangeParams, random_range2, slc_keep};
use slc_core::reservoir::{Reservoir, reservoir_weight};
use slc_core::sphere::Sphere;
use slc_core::xi::{xi_for, xi_from_bits};
use std::time::Instant;

/// Reservoir slots of `slc-reservoir`.
pub const RESERVOIR_K: usize = 8;

/// Light selection for next-event estimation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PtMethod {
    /// Stochastic light culling over the BSH, every candidate evaluated.
    Slc,
    /// Stochastic light culling with a k-slot reservoir over the candidates.
    SlcReservoir,
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
            PtMethod::Uniform => "uniform",
            PtMethod::Power => "power",
            PtMethod::LightBvh => "lightbvh",
        }
    }

    /// Every method, in report order.
    pub const ALL: [PtMethod; 5] = [PtMethod::Slc, PtMethod::SlcReservoir, PtMethod::Uniform, PtMethod::Power, PtMethod::LightBvh];
}

/// Settings of a path-traced render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PtSettings {
    /// NEE method.
    pub method: PtMethod,
    /// SLC error bound ε.
    pub error_bound: f32,
    /// Exposure E (error bound).
    pub exposure: f32,
    /// Seed.
    pub seed: u32,
    /// Longest path (vertices after the camera).
    pub max_depth: u32,
}

impl Default for PtSettings {
    fn default() -> Self {
        // ε = 0.3: each in-range light costs a shadow ray, so a larger bound
        // (fewer, more heavily weighted candidates) wins at equal time. In the
        // bunny scenes (docs/pt-bench-*.json) slc-reservoir's equal-time RMSE
        // was 0.035 at ε = 0.03, 0.026 at 0.1, 0.022 at 0.3 and 1.0.
        PtSettings { method: PtMethod::Slc, error_bound: 0.3, exposure: 1.0, seed: 1, max_depth: 8 }
    }
}

/// A scene ready to path trace: geometry, lights, the BSH over them.
pub struct PtScene {
    scene: Scene,
    geo: Geometry,
    lights: Vec<Light>,
    bounds: Vec<LightBound>,
    /// Light index of each emissive triangle (u32::MAX for others).
    light_of_triangle: Vec<u32>,
    power: AliasTable,
    light_bvh: LightBvh,
    bsh: Bsh,
    /// The scene's bounding-box diagonal (ray offsets scale with it).
    diag: f32,
}

impl PtScene {
    /// Emissive triangles become triangle lights; `extra` lights (point,
    /// spot, IES) join them in one BSH. An emissive triangle of zero area is
    /// an error.
    pub fn new(scene: &Scene, extra: &[Light]) -> Result<PtScene, RenderError> {
        scene.validate()?;
        let mut lights = Vec::new();
        let mut light_of_triangle = vec![u32::MAX; scene.triangles.len()];
        for (i, t) in scene.triangles.iter().enumerate() {
            let e = scene.materials[scene.material_of[i] as usize].emission;
            if e.max_element() > 0.0 {
                let l = TriangleLight::new(t[0], t[1], t[2], e).map_err(|err| RenderError::Setting(format!("emissive triangle {i}: {err}")))?;
                light_of_triangle[i] = lights.len() as u32;
                lights.push(Light::Triangle(l));
            }
        }
        lights.extend(extra.iter().cloned());
        if lights.is_empty() {
            return Err(RenderError::Setting("the scene has no light (no emissive triangle, no point/spot/IES light)".into()));
        }
        let bounds: Vec<LightBound> = lights.iter().map(Light::bound).collect();
        let bsh = Bsh::build(&bounds).map_err(|e| RenderError::Setting(e.to_string()))?;
        let power = AliasTable::new(&lights.iter().map(light_power).collect::<Vec<f64>>());
        let light_bvh = LightBvh::new(&lights);
        Ok(PtScene {
            scene: scene.clone(),
            geo: Geometry::new(&scene.triangles),
            lights,
            bounds,
            light_of_triangle,
            power,
            light_bvh,
            bsh,
            diag: scene.diagonal(),
        })
    }

    /// Number of lights.
    pub fn light_count(&self) -> usize {
        self.lights.len()
    }

    /// The scene.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The lights, as text (for cache keys).
    pub fn lights_debug(&self) -> String {
        format!("{:?}", self.lights)
    }

    /// The lights, in BSH light-index order.
    pub fn lights(&self) -> &[Light] {
        &self.lights
    }

    /// Each light's bound (centre and extent `R` of its range sphere).
    pub fn bounds(&self) -> &[LightBound] {
        &self.bounds
    }

    /// The BSH over the lights (as built; `render` refits it per pass).
    pub fn bsh(&self) -> &Bsh {
        &self.bsh
    }

    /// The `power` baseline's alias table per light, as the GPU reads it:
    /// `(keep probability, alias index as f32 bits, pmf, 0)`.
    pub fn power_table(&self) -> Vec<[f32; 4]> {
        self.power.entries().map(|(p, a, pdf)| [p as f32, f32::from_bits(a as u32), pdf as f32, 0.0]).collect()
    }

    /// Light index of each scene triangle (`u32::MAX` when it does not emit).
    pub fn light_of_triangle(&self) -> &[u32] {
        &self.light_of_triangle
    }
}

/// Emitted power used by the `power` method (max channel): triangle `π L A`,
/// point `4π I`, spot and IES by their peak over a hemisphere `2π I_max`.
fn light_power(l: &Light) -> f64 {
    let peak = l.peak().max_element() as f64;
    match l {
        Light::Triangle(_) => std::f64::consts::PI * peak,
        Light::Point(_) => 4.0 * std::f64::consts::PI * peak,
        _ => 2.0 * std::f64::consts::PI * peak,
    }
}

/// Per-pass light state: ξ-dependent ranges and each light's range sphere
/// (the BSH itself is refitted in place).
struct Pass {
    rt2: Vec<f32>,
    r2: Vec<f32>,
    spheres: Vec<Sphere>,
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
    /// An empty accumulation.
    pub fn new(width: u32, height: u32) -> Self {
        PtRender { sum: vec![Vec3::ZERO; width as usize * height as usize], passes: 0, time_ms: 0.0, width, height }
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
        Image { width: self.width, height: self.height, data: self.sum.iter().map(|s| *s / n).collect() }
    }
}

impl PtScene {
    /// New ξ for every light (one per pass), their ranges, and the BSH
    /// refitted to them in O(n).
    fn pass_state(&mut self, params: &RangeParams, seed: u32, pass: u32) -> Result<Pass, RenderError> {
        let rt2: Vec<f32> = self.lights.iter().map(|l| params.threshold_range2(l.peak())).collect();
        let r2: Vec<f32> = rt2.iter().enumerate().map(|(i, &t)| random_range2(t, xi_for(seed, pass, i as u32))).collect();
        let spheres = self.bounds.iter().zip(&r2).map(|(b, &r)| b.range_sphere(r)).collect();
        self.bsh.refit(&r2).map_err(|e| RenderError::Setting(e.to_string()))?;
        Ok(Pass { rt2, r2, spheres })
    }

    /// Renders `passes` more passes of one sample per pixel into `acc`.
    pub fn render(&mut self, acc: &mut PtRender, s: &PtSettings, passes: u32) -> Result<(), RenderError> {
        let params = RangeParams::new(s.error_bound, s.exposure).map_err(|e| RenderError::Setting(e.to_string()))?;
        if !(1..=64).contains(&s.max_depth) {
            return Err(RenderError::Setting(format!("max depth {} must be in 1..=64", s.max_depth)));
        }
        let t = Instant::now();
        let (w, h) = (acc.width, acc.height);
        for _ in 0..passes {
            let pass = acc.passes;
            let state = self.pass_state(&params, s.seed, pass)?;
            let st = &state;
            let this = &*self;
            let rows: Vec<Vec<Vec3>> = (0..h)
                .into_par_iter()
                .map(|y| {
                    (0..w)
                        .map(|x| {
                            let px = y * w + x;
                            let mut rng = Pcg32::new(((s.seed as u64) << 32) | pass as u64, px as u64);
                            this.trace(x, y, w, h, s, st, &mut rng)
                        })
                        .collect()
                })
                .collect();
            for (y, row) in rows.into_iter().enumerate() {
                for (x, v) in row.into_iter().enumerate() {
                    acc.sum[y * w as usize + x] += if v.is_finite() { v } else { Vec3::ZERO };
                }
            }
            acc.passes += 1;
        }
        acc.time_ms += t.elapsed().as_secs_f64() * 1e3;
        Ok(())
    }

    /// Light-strategy solid-angle pdf of reaching point `y` on triangle
    /// light `l` from `x`, as MIS needs it: independent of the light's own ξ
    /// (else the two strategies' weights would not sum to one in
    /// expectation and the result would be biased). For SLC that is
    /// `p_rr(|x−y|) · pdf_area`, the probability over ξ; the reservoir also
    /// selects with `min(k/n, 1)`, `n` = the other in-range lights at `x`
    /// plus this one (`seen` counts in-range lights at `x`; `in_nee` says
    /// the light is known to be one of them). `n` is the normal at `x`
    /// (the light BVH's importance uses it).
    #[allow(clippy::too_many_arguments)]
    fn light_pdf(&self, s: &PtSettings, st: &Pass, l: usize, x: Vec3, n: Vec3, y: Vec3, seen: u32, in_nee: bool) -> f32 {
        let Light::Triangle(t) = &self.lights[l] else { return 0.0 };
        let v = x - y;
        let d2 = v.length_squared();
        let cos_y = if d2 > 0.0 { t.normal().dot(v / d2.sqrt()) } else { 0.0 };
        // (selection probability, r_t² of the RR test; +∞ for the baselines)
        let (select, rt2) = match s.method {
            PtMethod::Slc => (1.0, st.rt2[l]),
            PtMethod::SlcReservoir => {
                let others = seen - (in_nee || st.spheres[l].contains(x)) as u32;
                (1.0 / reservoir_weight(others + 1, RESERVOIR_K as u32), st.rt2[l])
            }
            PtMethod::Uniform => (1.0 / self.lights.len() as f32, f32::INFINITY),
            PtMethod::Power => (self.power.pdf(l) as f32, f32::INFINITY),
            PtMethod::LightBvh => (self.light_bvh.pmf(x, n, l), f32::INFINITY),
        };
        light_strategy_pdf(select, rt2, d2, t.area(), cos_y)
    }

    /// Contribution of light `l` at `x` (normal `n`, albedo `rho`) through a
    /// sampled point, weighted by `extra` (the reservoir weight, or 1/the
    /// selection probability of the one-light methods) and, when `rr`, by
    /// the RR weight `1/p`, with the MIS weight against BSDF sampling for
    /// area lights.
    #[allow(clippy::too_many_arguments)]
    fn connect(
        &self,
        s: &PtSettings,
        st: &Pass,
        l: usize,
        x: Vec3,
        n: Vec3,
        rho: Vec3,
        rng: &mut Pcg32,
        seen: u32,
        rr: bool,
        extra: f32,
    ) -> Option<Vec3> {
        let light = &self.lights[l];
        let (u1, u2) = (xi_from_bits(rng.next_u32()), xi_from_bits(rng.next_u32()));
        let y = match light {
            Light::Triangle(t) => t.sample(u1, u2),
            _ => light.bound().center,
        };
        let v = x - y;
        let d2 = v.length_squared();
        if rr && !slc_keep(st.r2[l], d2) {
            return None;
        }
        if d2 <= 0.0 {
            return None;
        }
        let wdir = v / d2.sqrt();
        let cos_x = -n.dot(wdir);
        if cos_x <= 0.0 {
            return None;
        }
        let diag = self.diag;
        if self.geo.occluded(x + n * 1e-5 * diag, y) {
            return None;
        }
        let i = light.intensity(wdir);
        if i.max_element() <= 0.0 {
            return None;
        }
        // The baselines cull nothing: r_t² = +∞ makes 1/p = 1.
        let rt2 = if rr { st.rt2[l] } else { f32::INFINITY };
        let mis = match light {
            Light::Triangle(_) => mis_power(self.light_pdf(s, st, l, x, n, y, seen, true), cosine_pdf(cos_x)),
            _ => 1.0,
        };
        Some(lambert_brdf(rho) * i * connection_factor(cos_x, d2, rt2, extra * mis))
    }

    /// Next-event estimate at `x`; returns the radiance and the number of
    /// in-range lights seen (for the reservoir's MIS at the next hit).
    fn nee(&self, s: &PtSettings, st: &Pass, x: Vec3, n: Vec3, rho: Vec3, rng: &mut Pcg32) -> (Vec3, u32) {
        let mut sum = Vec3::ZERO;
        match s.method {
            PtMethod::Slc => {
                let mut cand = Vec::new();
                self.bsh.for_each_containing(x, |l| cand.push(l));
                let seen = cand.len() as u32;
                for l in cand {
                    if let Some(c) = self.connect(s, st, l as usize, x, n, rho, rng, seen, true, 1.0) {
                        sum += c;
                    }
                }
                (sum, seen)
            }
            PtMethod::SlcReservoir => {
                let mut res = Reservoir::<RESERVOIR_K>::new();
                self.bsh.for_each_containing(x, |l| res.push(l, rng.next_u32(), rng.next_u32()));
                let (seen, w) = (res.seen(), res.weight());
                for &l in res.picks() {
                    if let Some(c) = self.connect(s, st, l as usize, x, n, rho, rng, seen, true, w) {
                        sum += c;
                    }
                }
                (sum, seen)
            }
            PtMethod::Uniform | PtMethod::Power | PtMethod::LightBvh => {
                let u = xi_from_bits(rng.next_u32());
                let picked = match s.method {
                    PtMethod::Uniform => {
                        let n = self.lights.len();
                        Some(((u * n as f32) as usize).min(n - 1)).map(|l| (l, 1.0 / n as f32))
                    }
                    PtMethod::Power => {
                        let l = self.power.sample(u as f64, xi_from_bits(rng.next_u32()) as f64);
                        Some((l, self.power.pdf(l) as f32))
                    }
                    _ => self.light_bvh.sample(x, n, u),
                };
                if let Some((l, select)) = picked.filter(|&(_, p)| p > 0.0)
                    && let Some(c) = self.connect(s, st, l, x, n, rho, rng, 0, false, 1.0 / select)
                {
                    sum += c;
                }
                (sum, self.lights.len() as u32)
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn trace(&self, px: u32, py: u32, w: u32, h: u32, s: &PtSettings, st: &Pass, rng: &mut Pcg32) -> Vec3 {
        let cam = &self.scene.camera;
        let jx = xi_from_bits(rng.next_u32()) - 0.5;
        let jy = xi_from_bits(rng.next_u32()) - 0.5;
        let mut dir = cam.ray_dir(px as f32 + jx, py as f32 + jy, w, h);
        let mut org = cam.position;
        let mut beta = Vec3::ONE;
        let mut radiance = Vec3::ZERO;
        let diag = self.diag;
        // Previous vertex for MIS at implicit hits: (x, n, in-range lights, bsdf pdf).
        let mut prev: Option<(Vec3, Vec3, u32, f32)> = None;
        for depth in 0..s.max_depth {
            let Some(hit) = self.geo.intersect(org, dir, 1e-6 * diag, f32::INFINITY) else { break };
            let x = org + dir * hit.t;
            let tri = hit.triangle as usize;
            let geo_n = self.geo.normal(hit.triangle);
            let n = if geo_n.dot(dir) > 0.0 { -geo_n } else { geo_n };
            let mat = self.scene.materials[self.scene.material_of[tri] as usize];
            // Emission seen directly or by BSDF sampling (one-sided, like the light).
            let l = self.light_of_triangle[tri];
            if l != u32::MAX && geo_n.dot(dir) < 0.0 {
                let le = mat.emission;
                match prev {
                    None => radiance += beta * le,
                    Some((xp, np, seen, pdf_bsdf)) => {
                        let pdf_light = self.light_pdf(s, st, l as usize, xp, np, x, seen, false);
                        radiance += beta * le * mis_power(pdf_bsdf, pdf_light);
                    }
                }
            }
            let (direct, seen) = self.nee(s, st, x, n, mat.albedo, rng);
            radiance += beta * direct;
            // Cosine-weighted BSDF sample: f·cos/pdf = ρ.
            let (u1, u2) = (xi_from_bits(rng.next_u32()), xi_from_bits(rng.next_u32()));
            let nd = cosine_direction(n, u1, u2);
            let cos = nd.dot(n);
            if cos <= 0.0 {
                break;
            }
            beta *= mat.albedo;
            prev = Some((x, n, seen, cosine_pdf(cos)));
            org = x + n * 1e-5 * diag;
            dir = nd;
            // Russian roulette on path length from the third bounce.
            if depth >= 2 {
                let q = path_survival(beta);
                if xi_from_bits(rng.next_u32()) >= q {
                    break;
                }
                beta /= q;
            }
        }
        radiance
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// For a triangle light reachable by both strategies, the light
    /// strategy's MIS weight (as `connect` computes it) and the BSDF
    /// strategy's (as an implicit hit computes it) sum to one, for every
    /// method: both use the same ξ-independent light pdf.
    #[test]
    fn mis_weights_sum_to_one() {
        let mut pts = PtScene::new(&Scene::cornell_box(), &[]).unwrap();
        let (x, n) = (Vec3::new(0.3, 0.0, 0.3), Vec3::Y);
        let params = RangeParams::new(0.05, 1.0).unwrap();
        let st = pts.pass_state(&params, 7, 0).unwrap();
        let mut checked = 0;
        for method in PtMethod::ALL {
            let s = PtSettings { method, error_bound: 0.05, ..PtSettings::default() };
            for l in 0..pts.light_count() {
                let Light::Triangle(t) = &pts.lights[l] else { continue };
                if !st.spheres[l].contains(x) {
                    continue; // the reservoir's per-sample identity needs the light in range
                }
                let mut seen = 0;
                pts.bsh.for_each_containing(x, |_| seen += 1);
                for (u1, u2) in [(0.1, 0.2), (0.5, 0.5), (0.9, 0.05)] {
                    let y = t.sample(u1, u2);
                    let cos_x = n.dot((y - x).normalize());
                    let p_light_nee = pts.light_pdf(&s, &st, l, x, n, y, seen, true);
                    let p_light_hit = pts.light_pdf(&s, &st, l, x, n, y, seen, false);
                    assert!(p_light_nee > 0.0 && cos_x > 0.0, "{}", method.name());
                    let w_light = mis_power(p_light_nee, cosine_pdf(cos_x));
                    let w_bsdf = mis_power(cosine_pdf(cos_x), p_light_hit);
                    assert!((w_light + w_bsdf - 1.0).abs() < 1e-6, "{}: {w_light} + {w_bsdf}", method.name());
                    checked += 1;
                }
            }
        }
        assert!(checked >= 2 * PtMethod::ALL.len() * 3, "{checked} cases");
    }
}
