//! Application B of the paper: progressive path tracing with many lights.
//!
//! Lambertian and GGX surfaces; at every vertex next-event estimation (NEE)
//! by the chosen light-selection method, combined with BSDF sampling (cosine
//! for the diffuse lobe, GGX visible normals for the specular one) by
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
//! - `slc-weighted`: the same candidates, each with weight `wᵢ = ĝᵢ/pᵢ`
//!   (its importance at `x` over its roulette probability,
//!   [`slc_core::importance`]), streamed through `k` independent one-slot
//!   weighted reservoirs; a pick is weighted `W/(k·wᵢ)`, `W = Σ wᵢ`: exact
//!   discrete importance sampling of the SLC sum over the candidates.
//! - `uniform`: one light chosen uniformly; `power`: one light chosen in
//!   proportion to its emitted power (alias table).
//! - `lightbvh`: one light chosen by light-BVH importance sampling
//!   (Conty & Kulla 2018, pbrt-v4's `BVHLightSampler`; the scene's
//!   [`slc_scene::light_bvh`], sampled by [`slc_core::light_bvh`]).
//!
//! MIS: the light strategy's solid-angle pdf of `y` is
//! `pdf(select) · p_rr(|x−y|) · pdf_area(y) · d²/|cos θ_y|` (talk: "Multiple
//! importance sampling"), with `p_rr = 1` for the baselines and
//! `pdf(select)` = 1 (slc), `min(k/n, 1)` (reservoir), `k·w/(W₋ⱼ + w)`
//! (weighted, `W₋ⱼ` the other candidates' weight), `1/N` (uniform),
//! `Φᵢ/ΣΦ` (power), the tree's pmf at `(x, n)` (lightbvh). These pdfs must not depend on the light's own ξ: a
//! weight that is 0 when this pass's sphere misses `x` makes the two
//! strategies' weights sum to more than one in expectation (the test against
//! uniform sampling caught a 40% bias from exactly that). Point-like lights
//! are delta lights (weight 1).

use crate::geometry::Geometry;
use crate::raster::Pinhole;
use glam::{Vec3, Vec4};
use rand_core::RngCore;
use rand_pcg::Pcg32;
use rayon::prelude::*;
use slc_core::brdf::{bsdf_pdf, bsdf_sample, specular_probability};
use slc_core::bsh::grid::SHARP_GRID_ENTRIES;
use slc_core::bsh::{Bsh, BshGrid, walk::bsh_reaches};
use slc_core::importance::Receiver;
use slc_core::importance::weighted_select_pdf;
use slc_core::light::{Light, connection_cosine, connection_factor};
use slc_core::mis::{light_strategy_pdf, mis_power};
use slc_core::path::{
    continues_path, jittered_pixel, path_survival, plays_roulette, sees_emission,
};
use slc_core::range::{RangeParams, random_range2};
use slc_core::ray::{face_against, ray_t_min, surface_offset};
use slc_core::reservoir::{Reservoir, WeightedReservoir, reservoir_select_pdf, uniform_light};
use slc_core::xi::{light_xi, xi_from_bits, xi_keys};
use slc_scene::RenderError;
use slc_scene::backend::{PathTracer, Timing};
use slc_scene::pt::{PtMethod, PtRender, PtScene, PtSettings, RESERVOIR_K, WEIGHTED_K};
use slc_scene::scene::Material;
use std::sync::Arc;
use std::sync::OnceLock;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// The largest range lobe a pass's glossy grid holds (slc-core's, shared
/// with the GPU path tracer).
pub use slc_core::bsh::grid::GLOSSY_REACH;
/// The largest range lobe a pass's sharp grid holds: every receiver's.
pub use slc_core::bsh::grid::SHARP_REACH;

/// The CPU path tracer over a [`PtScene`]: the scene's geometry in a BVH,
/// and a BSH of its own that each pass refits to that pass's ranges.
pub struct CpuPathTracer {
    pts: PtScene,
    geo: Geometry,
    bsh: Bsh,
    /// Each light's `r_t²` and the range parameters it was computed for
    /// (shared with each pass's [`Pass`]).
    rt2: Option<(RangeParams, Arc<[f32]>)>,
    /// Each light's ξ key ([`slc_core::xi::xi_keys`]): the point, spot and
    /// IES lights' ξ rotate together, the area lights draw their own.
    xi_keys: Vec<u32>,
    /// The scene's bounding-box diagonal (ray offsets scale with it).
    diag: f32,
    /// The scene's bounding box (each pass's [`BshGrid`] covers it).
    bounds: (Vec3, Vec3),
    /// Whether passes look in their grids ([`CpuPathTracer::set_grid`]).
    grid: bool,
}

impl CpuPathTracer {
    /// Builds the geometry BVH of `pts`.
    pub fn new(pts: &PtScene) -> CpuPathTracer {
        let scene = pts.scene();
        CpuPathTracer {
            geo: Geometry::new(&scene.triangles),
            bsh: pts.bsh().clone(),
            rt2: None,
            xi_keys: xi_keys(pts.lights()),
            diag: scene.diagonal(),
            bounds: scene.bounds(),
            pts: pts.clone(),
            grid: true,
        }
    }

    /// Whether the SLC methods find a vertex's lights in the pass's grids
    /// (`true`, the default: [`BshGrid`]s for Lambertian vertices and
    /// glossy ones within [`GLOSSY_REACH`]) or by walking the tree at
    /// every vertex. The same lights in the same order either way, so the
    /// same image: a switch for measurements.
    pub fn set_grid(&mut self, on: bool) {
        self.grid = on;
    }

    /// The prepared scene.
    pub fn scene(&self) -> &PtScene {
        &self.pts
    }

    /// Number of lights.
    pub fn light_count(&self) -> usize {
        self.pts.light_count()
    }

    fn lights(&self) -> &[Light] {
        self.pts.lights()
    }
}

/// What next-event estimation at a vertex leaves for MIS at the next
/// implicit hit: the number of in-range lights (`slc-reservoir`) and their
/// total weight `W` (`slc-weighted`).
#[derive(Clone, Copy, Debug, Default)]
struct NeeState {
    seen: u32,
    w_sum: f32,
}

/// Subtrees of at most this many nodes are refitted on one thread.
const REFIT_GRAIN: usize = 4096;

/// Per-pass light state of the SLC methods: ξ-dependent ranges (the BSH
/// itself is refitted in place). The baselines (uniform, power, light BVH)
/// have none: they cull nothing, so a pass costs them no ranges and no
/// refit, as their authors built them.
#[derive(Default)]
struct Pass {
    rt2: Arc<[f32]>,
    r2: Vec<f32>,
    /// The refitted tree's leaves in a grid over the scene's box
    /// ([`BshGrid`]): where a Lambertian receiver finds its candidates.
    grid: LazyGrid,
    /// The same for glossy receivers whose range lobe reaches at most
    /// [`GLOSSY_REACH`] ([`BshGrid::build_reaching`]).
    glossy: LazyGrid,
    /// The same for sharper lobes, up to [`SHARP_REACH`]
    /// ([`BshGrid::build_reaching_within`]).
    sharp: LazyGrid,
}

/// A pass's grid, built by the first receiver that asks for it while the
/// other threads go on walking the tree: the grid gives the walk's lights
/// in the walk's order, so which one a receiver takes changes nothing in
/// the image, and no thread waits for the serial build.
#[derive(Default)]
struct LazyGrid {
    claimed: AtomicBool,
    /// `None` inside: no grid this pass (ranges too large for one).
    grid: OnceLock<Option<BshGrid>>,
}

impl LazyGrid {
    /// The grid once built; `None` while another thread builds it, or
    /// where the pass has none. The first caller builds it with `build`.
    fn get(&self, build: impl FnOnce() -> Option<BshGrid>) -> Option<&BshGrid> {
        if let Some(g) = self.grid.get() {
            return g.as_ref();
        }
        if self.claimed.swap(true, Ordering::AcqRel) {
            return None;
        }
        self.grid.get_or_init(build).as_ref()
    }

    /// Whether the grid has been built (a grid or none).
    #[cfg(test)]
    fn built(&self) -> Option<bool> {
        self.grid.get().map(Option::is_some)
    }
}

impl CpuPathTracer {
    /// Whether light `l`'s range sphere, scaled for the receiver `rc`
    /// (range lobe `rl`; [`bsh_reaches`]), holds it this pass: it is one
    /// of the receiver's candidates.
    fn in_range(&self, l: usize, rc: &Receiver, rl: Vec4) -> bool {
        bsh_reaches(self.bsh.leaf(l), rc.p, rc.r, rl)
    }

    /// The SLC methods' state for pass `pass`: new ξ for every light,
    /// their ranges (`r_t²`, which depends only on the error bound, kept
    /// from the last pass), and the BSH refitted to them in O(n), its
    /// subtrees in parallel ([`Bsh::refit_split`]). Empty for the
    /// baselines.
    fn pass_state(
        &mut self,
        method: PtMethod,
        params: &RangeParams,
        seed: u32,
        pass: u32,
    ) -> Result<Pass, RenderError> {
        if !method.culls() {
            return Ok(Pass::default());
        }
        if self.rt2.as_ref().is_none_or(|(p, _)| p != params) {
            let rt2 = self.lights().par_iter().map(|l| params.threshold_range2(l.peak())).collect();
            self.rt2 = Some((*params, rt2));
        }
        let rt2 = self.rt2.as_ref().map(|(_, rt2)| Arc::clone(rt2)).unwrap_or_default();
        let r2: Vec<f32> = rt2
            .par_iter()
            .enumerate()
            .map(|(i, &t)| random_range2(t, light_xi(seed, pass, self.xi_keys[i])))
            .collect();
        self.bsh
            .refit_split(&r2, REFIT_GRAIN, &|a, b| _ = rayon::join(a, b))
            .map_err(|e| RenderError::Setting(e.to_string()))?;
        Ok(Pass { rt2, r2, ..Pass::default() })
    }

    /// The lights whose range sphere, scaled for the receiver at `x`
    /// (mirror direction `r`, range lobe `rl`), reaches it, in the walk's
    /// order ([`Bsh::for_each_reaching`]): from one of the pass's grids
    /// for a receiver inside the scene's box (the plain grid without a
    /// range lobe, `rl.w ≤ 1`; the glossy one up to [`GLOSSY_REACH`]; the
    /// sharp one up to [`SHARP_REACH`]), the same lights in the same order;
    /// else, and while another thread builds that grid ([`LazyGrid`]), by
    /// the walk.
    fn for_each_candidate(
        &self,
        st: &Pass,
        x: Vec3,
        r: Vec3,
        rl: Vec4,
        mut visit: impl FnMut(u32),
    ) {
        let (lo, hi) = self.bounds;
        if self.grid {
            let bsh = &self.bsh;
            let grid = if rl.w <= 1.0 {
                st.grid.get(|| BshGrid::build(bsh, lo, hi))
            } else if rl.w <= GLOSSY_REACH {
                st.glossy.get(|| BshGrid::build_reaching(bsh, lo, hi, GLOSSY_REACH))
            } else if rl.w <= SHARP_REACH {
                st.sharp.get(|| {
                    BshGrid::build_reaching_within(bsh, lo, hi, SHARP_REACH, SHARP_GRID_ENTRIES)
                })
            } else {
                None
            };
            if grid.is_some_and(|g| g.for_each_reaching(x, r, rl, &mut visit)) {
                return;
            }
        }
        self.bsh.for_each_reaching(x, r, rl, visit);
    }

    /// Renders `passes` more passes of one sample per pixel into `acc`
    /// (also [`PathTracer::render`]).
    pub fn render(
        &mut self,
        acc: &mut PtRender,
        s: &PtSettings,
        passes: u32,
    ) -> Result<(), RenderError> {
        let (w, h) = acc.size();
        slc_scene::check_size(w, h)?;
        let params = RangeParams::new(s.error_bound, s.exposure)
            .map_err(|e| RenderError::Setting(e.to_string()))?;
        if !(1..=64).contains(&s.max_depth) {
            return Err(RenderError::Setting(format!(
                "max depth {} must be in 1..=64",
                s.max_depth
            )));
        }
        // The light BVH is the lightbvh method's set-up (as the BSH is the
        // SLC methods'): built here, on its first render, outside the
        // passes' time.
        if s.method == PtMethod::LightBvh {
            self.pts.light_bvh();
        }
        for _ in 0..passes {
            let t = Instant::now();
            let pass = acc.passes;
            let state = self.pass_state(s.method, &params, s.seed, pass)?;
            let st = &state;
            let this = &*self;
            // The camera's basis once a pass, not once a path.
            let view = &Pinhole::of(&self.pts.scene().camera, w, h);
            let image: Vec<Vec3> = (0..w * h)
                .into_par_iter()
                .map(|px| {
                    let mut rng = Pcg32::new(((s.seed as u64) << 32) | pass as u64, px as u64);
                    this.trace(px % w, px / w, view, s, st, &mut rng)
                })
                .collect();
            acc.accumulate(&image, 1, t.elapsed().as_secs_f64() * 1e3);
        }
        Ok(())
    }

    /// Light-strategy solid-angle pdf of reaching point `y` on triangle
    /// light `l` from `x`, as MIS needs it: independent of the light's own ξ
    /// (else the two strategies' weights would not sum to one in
    /// expectation and the result would be biased). For SLC that is
    /// `p_rr(|x−y|) · pdf_area`, the probability over ξ; the reservoir also
    /// selects with `min(k/n, 1)`, `n` = the other in-range lights at `x`
    /// plus this one (`seen` counts in-range lights at `x`; `in_nee` says
    /// the light is known to be one of them). The weighted picks select with
    /// `k·w/(W₋ⱼ + w)`, `W₋ⱼ` the weight of the others (`W` from `nee`).
    /// `rc` is the receiver at `x` (its normal and lobe weigh the lights).
    /// `picked`: the selection probability when the caller already knows
    /// it, as the one-light methods' next-event estimate does (the pmf its
    /// sample returned): the light BVH's MIS weight then takes it, as
    /// pbrt-v4's `SampleLd` takes `sampledLight->p`, instead of walking the
    /// tree a second time.
    #[allow(clippy::too_many_arguments)]
    fn light_pdf(
        &self,
        s: &PtSettings,
        st: &Pass,
        l: usize,
        rc: &Receiver,
        y: Vec3,
        nee: NeeState,
        in_nee: bool,
        picked: Option<f32>,
    ) -> f32 {
        let Light::Triangle(t) = &self.lights()[l] else { return 0.0 };
        let x = rc.p;
        // The receiver's range scale s toward this light (1 for a Lambertian one).
        let rl = rc.range_lobe();
        let rs = rc.range_scale_to(rl, &self.pts.light_set().cones()[l]);
        let in_range = || in_nee || self.in_range(l, rc, rl);
        let v = x - y;
        let d2 = v.length_squared();
        let cos_y = if d2 > 0.0 { t.normal().dot(v / d2.sqrt()) } else { 0.0 };
        // (selection probability, r_t² of the RR test; +∞ for the baselines)
        let (select, rt2) = match s.method {
            PtMethod::Slc => (1.0, rs * st.rt2[l]),
            PtMethod::SlcReservoir => {
                (reservoir_select_pdf(nee.seen, in_range(), RESERVOIR_K as u32), rs * st.rt2[l])
            }
            PtMethod::SlcWeighted => {
                let w = self.pts.light_set().cones()[l].weight(rc, rs * st.rt2[l]);
                (weighted_select_pdf(w, nee.w_sum, in_range(), WEIGHTED_K as u32), rs * st.rt2[l])
            }
            PtMethod::Uniform => (1.0 / self.lights().len() as f32, f32::INFINITY),
            PtMethod::Power => (self.pts.light_set().alias().pdf(l) as f32, f32::INFINITY),
            PtMethod::LightBvh => {
                (picked.unwrap_or_else(|| self.pts.light_bvh().pmf(rc, l)), f32::INFINITY)
            }
        };
        light_strategy_pdf(select, rt2, d2, t.area(), cos_y)
    }

    /// Contribution of light `l` at the vertex `vx` (its BRDF seen from
    /// `wo`) through a sampled point, weighted by `extra` (the reservoir
    /// weight, or 1/the selection probability of the one-light methods)
    /// and, when `rr`, by the RR weight `1/p`, with the MIS weight against
    /// BSDF sampling for area lights.
    #[allow(clippy::too_many_arguments)]
    fn connect(
        &self,
        s: &PtSettings,
        st: &Pass,
        l: usize,
        vx: &Vertex,
        rng: &mut Pcg32,
        nee: NeeState,
        rr: bool,
        extra: f32,
    ) -> Option<Vec3> {
        let (x, n, ng) = (vx.rc.p, vx.rc.n, vx.ng);
        let light = &self.lights()[l];
        let (u1, u2) = (xi_from_bits(rng.next_u32()), xi_from_bits(rng.next_u32()));
        let y = match light {
            Light::Triangle(t) => t.sample(u1, u2),
            _ => light.bound().center,
        };
        // The receiver's range scale toward this light (SLC's methods only).
        let rs =
            if rr { vx.rc.range_scale_to(vx.rl, &self.pts.light_set().cones()[l]) } else { 1.0 };
        // The baselines cull nothing: r² = +∞ keeps every light.
        let cos_x = connection_cosine(x, y, n, ng, if rr { rs * st.r2[l] } else { f32::INFINITY });
        if cos_x <= 0.0 {
            return None;
        }
        let v = x - y;
        let d2 = v.length_squared();
        let wdir = v / d2.sqrt();
        let diag = self.diag;
        if self.geo.occluded(x + ng * surface_offset(diag), y) {
            return None;
        }
        let i = light.intensity(wdir);
        if i.max_element() <= 0.0 {
            return None;
        }
        // The baselines cull nothing: r_t² = +∞ makes 1/p = 1.
        let rt2 = if rr { rs * st.rt2[l] } else { f32::INFINITY };
        let to_light = -wdir;
        let mis = match light {
            // The one-light methods (no RR) pass `extra = 1/pmf` of their pick.
            Light::Triangle(_) => mis_power(
                self.light_pdf(s, st, l, &vx.rc, y, nee, true, (!rr).then(|| 1.0 / extra)),
                vx.bsdf_pdf(to_light),
            ),
            _ => 1.0,
        };
        Some(vx.mat.eval(n, vx.wo, to_light) * i * connection_factor(cos_x, d2, rt2, extra * mis))
    }

    /// Next-event estimate at the vertex `vx`; returns the radiance and
    /// what MIS at the next hit needs of it.
    fn nee(&self, s: &PtSettings, st: &Pass, vx: &Vertex, rng: &mut Pcg32) -> (Vec3, NeeState) {
        let x = vx.rc.p;
        let mut sum = Vec3::ZERO;
        match s.method {
            PtMethod::Slc => {
                let mut cand = Vec::new();
                self.for_each_candidate(st, x, vx.rc.r, vx.rl, |l| cand.push(l));
                let nee = NeeState { seen: cand.len() as u32, w_sum: 0.0 };
                for l in cand {
                    if let Some(c) = self.connect(s, st, l as usize, vx, rng, nee, true, 1.0) {
                        sum += c;
                    }
                }
                (sum, nee)
            }
            PtMethod::SlcReservoir => {
                let mut res = Reservoir::<RESERVOIR_K>::new();
                self.for_each_candidate(st, x, vx.rc.r, vx.rl, |l| {
                    res.push(l, rng.next_u32(), rng.next_u32())
                });
                let (nee, w) = (NeeState { seen: res.seen(), w_sum: 0.0 }, res.weight());
                for &l in res.picks() {
                    if let Some(c) = self.connect(s, st, l as usize, vx, rng, nee, true, w) {
                        sum += c;
                    }
                }
                (sum, nee)
            }
            PtMethod::SlcWeighted => {
                let (res, seen) = self.weighted_picks(st, &vx.rc, rng);
                let nee = NeeState { seen, w_sum: res.total_weight() };
                for (l, w) in res.picks() {
                    if let Some(c) = self.connect(s, st, l as usize, vx, rng, nee, true, w) {
                        sum += c;
                    }
                }
                (sum, nee)
            }
            PtMethod::Uniform | PtMethod::Power | PtMethod::LightBvh => {
                let u = xi_from_bits(rng.next_u32());
                let picked = match s.method {
                    PtMethod::Uniform => {
                        let n = self.lights().len() as u32;
                        Some((uniform_light(u, n) as usize, 1.0 / n as f32))
                    }
                    PtMethod::Power => {
                        let alias = self.pts.light_set().alias();
                        let l = alias.sample(u, xi_from_bits(rng.next_u32()));
                        Some((l, alias.pdf(l) as f32))
                    }
                    _ => self.pts.light_bvh().sample(&vx.rc, u),
                };
                if let Some((l, select)) = picked.filter(|&(_, p)| p > 0.0)
                    && let Some(c) =
                        self.connect(s, st, l, vx, rng, NeeState::default(), false, 1.0 / select)
                {
                    sum += c;
                }
                // The one-light methods' MIS needs nothing of the traversal.
                (sum, NeeState::default())
            }
        }
    }

    /// `slc-weighted`'s traversal for the receiver `rc`: every in-range
    /// candidate offered to [`WEIGHTED_K`] one-slot weighted reservoirs
    /// with its weight ([`slc_core::importance::LightCone::weight`]); also
    /// the number of candidates.
    fn weighted_picks(
        &self,
        st: &Pass,
        rc: &Receiver,
        rng: &mut Pcg32,
    ) -> (WeightedReservoir<WEIGHTED_K>, u32) {
        let mut res = WeightedReservoir::<WEIGHTED_K>::new();
        let cones = self.pts.light_set().cones();
        let mut seen = 0;
        let rl = rc.range_lobe();
        self.for_each_candidate(st, rc.p, rc.r, rl, |l| {
            seen += 1;
            let c = &cones[l as usize];
            let w = c.weight(rc, rc.range_scale_to(rl, c) * st.rt2[l as usize]);
            // Zero weight: never picked (and its MIS pdf is 0), so no draws.
            res.push(l, w, || xi_from_bits(rng.next_u32()));
        });
        (res, seen)
    }

    /// One path through pixel `(px, py)` of the image `view` shows.
    fn trace(
        &self,
        px: u32,
        py: u32,
        view: &Pinhole,
        s: &PtSettings,
        st: &Pass,
        rng: &mut Pcg32,
    ) -> Vec3 {
        let scene = self.pts.scene();
        let sx = jittered_pixel(px, xi_from_bits(rng.next_u32()));
        let sy = jittered_pixel(py, xi_from_bits(rng.next_u32()));
        let mut dir = view.dir_at(sx, sy);
        let mut org = view.eye;
        let mut beta = Vec3::ONE;
        let mut radiance = Vec3::ZERO;
        let diag = self.diag;
        // Previous vertex for MIS at implicit hits: its receiver, its NEE,
        // the pdf of the BSDF sample that left it.
        let mut prev: Option<(Receiver, NeeState, f32)> = None;
        // `max_depth` vertices with next-event estimation, then the emission
        // the last one's BSDF sample finds (MIS's other share of it).
        for depth in 0..=s.max_depth {
            let Some(hit) = self.geo.intersect(org, dir, ray_t_min(diag), f32::INFINITY) else {
                break;
            };
            let x = org + dir * hit.t;
            let tri = hit.triangle as usize;
            let geo_n = self.geo.normal(hit.triangle);
            let ng = face_against(geo_n, dir);
            let n = scene.shading_normal(tri, x, ng);
            let mat = scene.materials[scene.material_of[tri] as usize];
            // Emission seen directly or by BSDF sampling (one-sided, like the light).
            let l = self.pts.light_of_triangle()[tri];
            if l != u32::MAX && sees_emission(geo_n, dir) {
                let le = mat.emission;
                match &prev {
                    None => radiance += beta * le,
                    Some((rc, nee, pdf_bsdf)) => {
                        let pdf_light = self.light_pdf(s, st, l as usize, rc, x, *nee, false, None);
                        radiance += beta * le * mis_power(*pdf_bsdf, pdf_light);
                    }
                }
            }
            if depth == s.max_depth {
                break;
            }
            let vx = Vertex::new(mat, x, n, ng, -dir);
            let (direct, nee) = self.nee(s, st, &vx, rng);
            radiance += beta * direct;
            // A BSDF sample about the shading normal (cosine, or the GGX
            // lobe's visible normals); a direction below the surface itself
            // ends the path.
            let (u1, u2) = (xi_from_bits(rng.next_u32()), xi_from_bits(rng.next_u32()));
            let nd = bsdf_sample(n, vx.wo, vx.alpha, vx.p_spec, u1, u2);
            if !continues_path(nd, n, ng) {
                break;
            }
            let pdf = vx.bsdf_pdf(nd);
            if !(pdf > 0.0) {
                break;
            }
            // f·cos/pdf; for a Lambertian surface exactly its albedo.
            beta *= if mat.has_specular() {
                mat.eval(n, vx.wo, nd) * (nd.dot(n) / pdf)
            } else {
                mat.albedo
            };
            prev = Some((vx.rc, nee, pdf));
            org = x + ng * surface_offset(diag);
            dir = nd;
            // Russian roulette on path length from the third bounce.
            if plays_roulette(depth) {
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

/// A path vertex as next-event estimation and BSDF sampling see it: the
/// receiver (position, shading normal, mirror direction, lobe), the
/// geometric normal on the shading normal's side, the material, the unit
/// direction `wo` back along the path, and the material's `α` and
/// specular-lobe probability there.
struct Vertex {
    rc: Receiver,
    ng: Vec3,
    mat: Material,
    wo: Vec3,
    alpha: f32,
    p_spec: f32,
    /// The receiver's range lobe ([`Receiver::range_lobe`]): what scales
    /// each light's ranges².
    rl: Vec4,
}

impl Vertex {
    fn new(mat: Material, x: Vec3, n: Vec3, ng: Vec3, wo: Vec3) -> Vertex {
        let rc = mat.receiver(x, n, wo);
        Vertex {
            rc,
            ng,
            mat,
            wo,
            alpha: mat.alpha(),
            p_spec: specular_probability(rc.lobe),
            rl: rc.range_lobe(),
        }
    }

    /// The BSDF sampling pdf of the unit direction `l` ([`bsdf_pdf`]).
    fn bsdf_pdf(&self, l: Vec3) -> f32 {
        bsdf_pdf(self.rc.n, self.wo, l, self.alpha, self.p_spec)
    }
}

impl PathTracer for CpuPathTracer {
    type Error = RenderError;

    fn describe(&self) -> String {
        format!("cpu ({} threads)", rayon::current_num_threads())
    }

    fn render(
        &mut self,
        acc: &mut PtRender,
        settings: &PtSettings,
        passes: u32,
    ) -> Result<Timing, RenderError> {
        CpuPathTracer::render(self, acc, settings, passes)?;
        Ok(Timing::Wall)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use slc_core::bsh::bsh_scaled_radius;
    use slc_core::sphere::sphere_contains_point;
    use slc_scene::scene::Scene;

    /// For a triangle light reachable by both strategies, the light
    /// strategy's MIS weight (as `connect` computes it) and the BSDF
    /// strategy's (as an implicit hit computes it) sum to one, for every
    /// method: both use the same ξ-independent light pdf. For a light
    /// outside this pass's range at `x` (NEE cannot pick it this pass) the
    /// pdf an implicit hit uses is still positive, with `W₋ⱼ = W` (the
    /// weighted picks) or the count of the others (the reservoir): what NEE
    /// would use in a pass whose ξ put the light in range with the same
    /// other candidates. For a Lambertian and a glossy receiver.
    #[test]
    fn mis_weights_sum_to_one() {
        let mut pts =
            CpuPathTracer::new(&PtScene::new(&Scene::cornell_box_split_light(4), &[]).unwrap());
        let (x, n) = (Vec3::new(0.3, 0.0, 0.3), Vec3::Y);
        let params = RangeParams::new(0.005, 1.0).unwrap();
        let st = pts.pass_state(PtMethod::SlcWeighted, &params, 7, 0).unwrap();
        let wo = Vec3::new(0.3, 0.8, -0.2).normalize();
        let (mut inside, mut outside) = (0, 0);
        for (mat, method) in [
            Material::lambertian(Vec3::splat(0.5), Vec3::ZERO),
            Material::gltf(Vec3::splat(0.9), 1.0, 0.4),
        ]
        .into_iter()
        .flat_map(|m| PtMethod::ALL.map(|method| (m, method)))
        {
            let vx = Vertex::new(mat, x, n, n, wo);
            let rc = vx.rc;
            let mut nee = NeeState::default();
            let rl = rc.range_lobe();
            let cones = pts.pts.light_set().cones();
            pts.bsh.for_each_reaching(x, rc.r, rl, |l| {
                nee.seen += 1;
                let c = &cones[l as usize];
                nee.w_sum += c.weight(&rc, rc.range_scale_to(rl, c) * st.rt2[l as usize]);
            });
            let s = PtSettings { method, error_bound: 0.005, ..PtSettings::default() };
            for l in 0..pts.light_count() {
                let Light::Triangle(t) = &pts.lights()[l] else { continue };
                let in_range = pts.in_range(l, &rc, rl);
                let rs = rc.range_scale_to(rl, &cones[l]);
                for (u1, u2) in [(0.1, 0.2), (0.5, 0.5), (0.9, 0.05)] {
                    let y = t.sample(u1, u2);
                    let cos_x = n.dot((y - x).normalize());
                    let p_light_hit = pts.light_pdf(&s, &st, l, &rc, y, nee, false, None);
                    assert!(p_light_hit > 0.0 && cos_x > 0.0, "{}", method.name());
                    if !in_range {
                        outside += 1;
                        if method == PtMethod::SlcWeighted {
                            let w = pts.pts.light_set().cones()[l].weight(&rc, rs * st.rt2[l]);
                            let select =
                                weighted_select_pdf(w, nee.w_sum + w, true, WEIGHTED_K as u32);
                            let expect = light_strategy_pdf(
                                select,
                                rs * st.rt2[l],
                                (x - y).length_squared(),
                                t.area(),
                                t.normal().dot((x - y).normalize()),
                            );
                            assert!(
                                (p_light_hit - expect).abs() <= 1e-5 * expect,
                                "{p_light_hit} vs {expect}"
                            );
                        }
                        continue;
                    }
                    // The one-light methods' NEE passes its pick's pmf
                    // (`connect` gets it as `extra = 1/pmf`): the pmf the
                    // sampler returned, which is the walk's.
                    let picked = match method {
                        PtMethod::Uniform => Some(1.0 / pts.light_count() as f32),
                        PtMethod::Power => Some(pts.pts.light_set().alias().pdf(l) as f32),
                        PtMethod::LightBvh => Some(pts.pts.light_bvh().pmf(&rc, l)),
                        _ => None,
                    };
                    let p_light_nee = pts.light_pdf(
                        &s,
                        &st,
                        l,
                        &rc,
                        y,
                        nee,
                        true,
                        picked.map(|p| 1.0 / (1.0 / p)),
                    );
                    assert!(
                        (p_light_nee - p_light_hit).abs() <= 1e-6 * p_light_hit,
                        "{}: {p_light_nee} vs {p_light_hit}",
                        method.name()
                    );
                    let p_bsdf = vx.bsdf_pdf((y - x).normalize());
                    assert!(p_bsdf > 0.0);
                    let w_light = mis_power(p_light_nee, p_bsdf);
                    let w_bsdf = mis_power(p_bsdf, p_light_hit);
                    assert!(
                        (w_light + w_bsdf - 1.0).abs() < 1e-6,
                        "{}: {w_light} + {w_bsdf}",
                        method.name()
                    );
                    inside += 1;
                }
            }
        }
        assert!(
            inside >= 4 * PtMethod::ALL.len() * 3 && outside >= 4 * PtMethod::ALL.len() * 3,
            "{inside} in range, {outside} outside"
        );
    }

    /// The candidates a vertex gets (`for_each_candidate`: the pass's
    /// grids for a receiver in the scene's box whose lobe they hold) are
    /// the walk's, in its order, at points on and off the surfaces,
    /// outside the box and NaN, for Lambertian receivers and glossy ones
    /// within and beyond [`GLOSSY_REACH`] (the sharp grid's, whose scan
    /// cuts its cells to the lobe's cone); and the pass built all three
    /// grids.
    #[test]
    fn candidates_are_the_walks_in_its_order() {
        let mut pt =
            CpuPathTracer::new(&PtScene::new(&Scene::cornell_box_split_light(256), &[]).unwrap());
        let st = pt
            .pass_state(PtMethod::SlcWeighted, &RangeParams::new(0.3, 1.0).unwrap(), 5, 1)
            .unwrap();
        assert!(st.grid.built().is_none() && st.glossy.built().is_none(), "built before asked");
        let (lo, hi) = pt.pts.scene().bounds();
        let mut rng = Pcg32::new(17, 3);
        let (mut found, mut points) = (0, 0);
        let mut reach = [0; 3];
        for k in 0..4_000 {
            let u = Vec3::new(
                xi_from_bits(rng.next_u32()),
                xi_from_bits(rng.next_u32()),
                xi_from_bits(rng.next_u32()),
            );
            let x = match k % 8 {
                0 => lo + (hi - lo) * (u * 1.4 - 0.2),
                1 => Vec3::NAN,
                _ => lo + (hi - lo) * u,
            };
            let n = Vec3::new(u.y - 0.5, 1.0, u.x - 0.5).normalize();
            let v = (n + Vec3::new(u.z - 0.5, 0.0, 0.3)).normalize();
            for mat in [
                Material::lambertian(Vec3::splat(0.5), Vec3::ZERO),
                Material::gltf(Vec3::splat(0.9), 1.0, 0.3),
                Material::gltf(Vec3::splat(0.7), 0.0, 0.3),
                Material::gltf(Vec3::new(1.0, 0.78, 0.34), 1.0, 0.4),
                Material::gltf(Vec3::splat(0.97), 1.0, 0.15),
                Material::gltf(Vec3::splat(0.8), 0.0, 0.15),
            ] {
                let rc = mat.receiver(x, n, v);
                let rl = rc.range_lobe();
                reach[(rl.w > 1.0) as usize + (rl.w > GLOSSY_REACH) as usize] += 1;
                let (mut walk, mut got) = (Vec::new(), Vec::new());
                pt.bsh.for_each_reaching(x, rc.r, rl, |l| walk.push(l));
                pt.for_each_candidate(&st, x, rc.r, rl, |l| got.push(l));
                assert_eq!(got, walk, "at {x}");
                found += walk.len();
                points += 1;
            }
        }
        assert!(found > points, "{found} candidates at {points} points");
        assert!(reach.iter().all(|&k| k > 2_000), "Lambertian, held, beyond: {reach:?}");
        assert_eq!(
            (st.grid.built(), st.glossy.built(), st.sharp.built()),
            (Some(true), Some(true), Some(true))
        );
    }

    /// A pass's grid is built once, by the first receiver that asks; one
    /// that asks while it is being built gets none (and walks the tree).
    #[test]
    fn a_grid_being_built_is_walked_around() {
        let mut t =
            Bsh::build(&[slc_core::light::LightBound { center: Vec3::splat(0.5), extent: 0.0 }; 4])
                .unwrap();
        t.refit(&[0.01; 4]).unwrap();
        let lazy = LazyGrid::default();
        let mut builds = 0;
        let got = lazy.get(|| {
            builds += 1;
            assert!(
                lazy.get(|| unreachable!("built twice")).is_none(),
                "a grid before it is built"
            );
            BshGrid::build(&t, Vec3::ZERO, Vec3::ONE)
        });
        assert!(got.is_some() && builds == 1);
        assert!(lazy.get(|| unreachable!("built twice")).is_some());
        assert_eq!(lazy.built(), Some(true));
    }

    /// `slc-weighted` against brute-force enumeration of the candidates:
    /// the traversal's `W` is the sum of the weights of exactly the lights
    /// whose range sphere holds `x` (every light tested), and over 40,000
    /// traversals each light is picked `k·w/W` times per traversal on
    /// average (within 5σ of the binomial count, per slot `w/W`); for a
    /// glossy receiver, whose lobe weighs the candidates.
    #[test]
    fn weighted_picks_match_brute_force_enumeration() {
        let pts = {
            let mut p =
                CpuPathTracer::new(&PtScene::new(&Scene::cornell_box_split_light(8), &[]).unwrap());
            let st = p
                .pass_state(PtMethod::SlcWeighted, &RangeParams::new(0.016, 1.0).unwrap(), 3, 0)
                .unwrap();
            (p, st)
        };
        let (pts, st) = (&pts.0, &pts.1);
        let (x, n) = (Vec3::new(0.3, 0.0, 0.3), Vec3::Y);
        // The view mirrors a point near the light's edge: its lobe covers
        // part of the split light.
        let cones = pts.pts.light_set().cones();
        let aim = cones.iter().map(|c| c.center).sum::<Vec3>() / cones.len() as f32
            + Vec3::new(0.12, 0.0, 0.0);
        let to = (aim - x).normalize();
        let rc =
            Material::gltf(Vec3::splat(0.9), 1.0, 0.45).receiver(x, n, n * (2.0 * n.dot(to)) - to);
        let (rs, rl) = (rc.range_scale(), rc.range_lobe());
        assert!(rc.lobe.y > 0.0 && rs > 1.0, "a glossy receiver scales its ranges: {rs}");
        // Each light's own scale toward it, and its leaf's sphere so scaled
        // (the walk's inner nodes are not consulted).
        let scale: Vec<f32> = cones.iter().map(|c| rc.range_scale_to(rl, c)).collect();
        assert!(
            scale.iter().any(|&s| s < 0.5 * rs) && scale.iter().any(|&s| s > 0.8 * rs),
            "scales toward the lights {scale:?}, peak {rs}"
        );
        let holds = |l: usize| {
            sphere_contains_point(
                pts.bsh.leaf(l).center,
                bsh_scaled_radius(pts.bsh.leaf(l), scale[l].sqrt()),
                x,
            )
        };
        let brute: Vec<(usize, f64)> = (0..pts.light_count())
            .filter(|&l| holds(l))
            .map(|l| (l, cones[l].weight(&rc, scale[l] * st.rt2[l]) as f64))
            .collect();
        let w_brute: f64 = brute.iter().map(|&(_, w)| w).sum();
        assert!(brute.len() >= 10 && brute.len() < pts.light_count(), "{} candidates", brute.len());
        let mut rng = Pcg32::new(11, 5);
        let trials = 40_000;
        let mut count = vec![0u32; pts.light_count()];
        for _ in 0..trials {
            let (res, seen) = pts.weighted_picks(st, &rc, &mut rng);
            assert_eq!(seen as usize, brute.len());
            assert!(
                (res.total_weight() as f64 - w_brute).abs() <= 1e-5 * w_brute,
                "W {} vs {w_brute}",
                res.total_weight()
            );
            for (l, _) in res.picks() {
                count[l as usize] += 1;
            }
        }
        let slots = (trials * WEIGHTED_K) as f64;
        for &(l, w) in &brute {
            let p = w / w_brute;
            let (expect, sd) = (slots * p, (slots * p * (1.0 - p)).sqrt());
            assert!(
                (count[l] as f64 - expect).abs() <= 5.0 * sd + 1.0,
                "light {l}: {} picks, expected {expect:.0} ± {sd:.0}",
                count[l]
            );
        }
        assert_eq!(
            count.iter().sum::<u32>() as f64,
            slots,
            "a light outside the candidates was picked"
        );
    }
}
