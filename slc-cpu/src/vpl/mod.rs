//! Application A of the paper: real-time indirect illumination with VPLs.
//!
//! Pipeline (every step a function with a typed input and output):
//! [`GBuffer::render`] → [`rsm::reflective_shadow_map`] (`size²` VPLs) →
//! 8×8 interleaved sampling (pixel `(x, y)` uses VPL subset
//! `(y mod 8)·8 + x mod 8`; subset of RSM texel `(tx, ty)` likewise, each
//! subset's flux scaled by 64) → tiled shading of each sub-image with the
//! subset's VPL spheres culled per tile ([`shade`]) →
//! [`denoise::cross_bilateral`] → albedo × (indirect + direct) + emission.
//!
//! Methods: [`VplMethod::Slc`] (stochastic ranges from error bound ε),
//! [`VplMethod::Clamp`] (fixed range R, no reweighting: biased),
//! [`VplMethod::None`] (interleaved, unculled) and [`VplMethod::Reference`]
//! (every VPL at every pixel, no interleaving, no denoise).

pub mod denoise;
pub mod rsm;
pub mod shade;

use crate::RenderError;
use crate::gbuffer::GBuffer;
use crate::geometry::Geometry;
use crate::image::Image;
use crate::scene::{PrimaryLight, Scene};
use glam::Vec3;
use rayon::prelude::*;
use rsm::Vpls;
use shade::{Cull, LightList};
use slc_core::light::{INV_PI, Light, inverse_square};
use slc_core::range::{RangeParams, random_range2};
use slc_core::xi::xi_for;
use std::time::Instant;

/// How the indirect light is computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VplMethod {
    /// Stochastic light culling (error bound ε).
    Slc,
    /// Clamped ranges (range R), no reweighting.
    Clamp,
    /// Interleaved, unculled.
    None,
    /// Every VPL at every pixel: the ground truth.
    Reference,
}

impl VplMethod {
    /// Lower-case name used on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            VplMethod::Slc => "slc",
            VplMethod::Clamp => "clamp",
            VplMethod::None => "none",
            VplMethod::Reference => "reference",
        }
    }
}

/// Per-run settings (the scene-dependent part lives in [`VplContext`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VplSettings {
    /// Method.
    pub method: VplMethod,
    /// SLC error bound ε (radiance units).
    pub error_bound: f32,
    /// Clamp range R (scene units).
    pub range: f32,
    /// Exposure E used by the error bound.
    pub exposure: f32,
    /// Seed of the per-VPL ξ.
    pub seed: u32,
    /// Frame number (a new ξ set per frame).
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
}

impl Default for VplSettings {
    fn default() -> Self {
        VplSettings {
            method: VplMethod::Slc,
            error_bound: 0.008,
            range: 0.1,
            exposure: 1.0,
            seed: 1,
            frame: 0,
            tile: 4,
            denoise: true,
            fixed_xi: None,
        }
    }
}

/// `r_t²` of a VPL of (interleave-scaled) flux `Φ`: its peak intensity is
/// `Φ/π` (cosine lobe), shared by the CPU and GPU backends.
pub fn vpl_threshold_range2(params: &RangeParams, flux: Vec3) -> f32 {
    params.threshold_range2(flux * INV_PI)
}

/// Interleaving period (8×8 subsets, as in the paper).
pub const PERIOD: u32 = 8;

/// Super-tile size in tiles for the first culling level.
pub const SUPER: usize = 2;

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
}

/// Indirect irradiance of one frame before denoise and composition (what a
/// backend computes).
#[derive(Clone, Debug)]
pub struct Shaded {
    /// Irradiance per pixel (zero where no surface).
    pub irradiance: Vec<Vec3>,
    /// Lights that passed the keep test, per pixel.
    pub kept: Vec<u32>,
    /// Light evaluations of the shading loop.
    pub evaluations: u64,
    /// Shading time (ms).
    pub shading_ms: f64,
    /// `Some(ms)` when the backend has already denoised `irradiance` (the
    /// GPU does, with the same filter), so [`VplContext::finish`] does not.
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

/// Everything that does not depend on the method: geometry, G-buffer, VPLs
/// and direct light, computed once.
pub struct VplContext {
    scene: Scene,
    gbuffer: GBuffer,
    vpls: Vpls,
    direct: Vec<Vec3>,
    min_d2: f32,
    base: VplStats,
}

impl VplContext {
    /// Validates the inputs and computes the shared buffers. `rsm_size` must
    /// be a positive multiple of 8 (`rsm_size²` VPLs); `width`, `height` in
    /// `1..=16384`. `min_distance` is the clamp distance of the VPL fall-off
    /// (`None`: 1% of the scene's diagonal).
    pub fn new(scene: &Scene, width: u32, height: u32, rsm_size: u32, min_distance: Option<f32>) -> Result<Self, RenderError> {
        scene.validate()?;
        if !(1..=16384).contains(&width) || !(1..=16384).contains(&height) {
            return Err(RenderError::Size(width, height));
        }
        if rsm_size == 0 || !rsm_size.is_multiple_of(PERIOD) || rsm_size > 4096 {
            return Err(RenderError::VplCount((rsm_size as u64).pow(2)));
        }
        let min_distance = min_distance.unwrap_or(0.01 * scene.diagonal());
        if !(min_distance.is_finite() && min_distance >= 0.0) {
            return Err(RenderError::Setting(format!("min distance {min_distance} must be finite and >= 0")));
        }
        let mut base = VplStats::default();
        let t = Instant::now();
        let geo = Geometry::new(&scene.triangles);
        let gbuffer = GBuffer::render(scene, &geo, width, height);
        base.gbuffer_ms = ms(t);
        let t = Instant::now();
        let vpls = rsm::reflective_shadow_map(scene, &geo, rsm_size);
        base.rsm_ms = ms(t);
        let t = Instant::now();
        let direct = direct_light(scene, &geo, &gbuffer);
        base.direct_ms = ms(t);
        base.vpls = vpls.len();
        Ok(VplContext { scene: scene.clone(), gbuffer, vpls, direct, min_d2: min_distance * min_distance, base })
    }

    /// The G-buffer.
    pub fn gbuffer(&self) -> &GBuffer {
        &self.gbuffer
    }

    /// The VPLs.
    pub fn vpls(&self) -> &Vpls {
        &self.vpls
    }

    /// The scene.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// RSM texel indices of VPL subset `sub` (`0 ≤ sub < PERIOD²`): texels
    /// `(tx, ty)` with `ty mod P = sub / P` and `tx mod P = sub mod P`,
    /// row-major. Pixel `(x, y)` uses subset `(y mod P)·P + x mod P`.
    pub fn subset_members(&self, sub: usize) -> Vec<usize> {
        let (p, size) = (PERIOD as usize, self.vpls.size as usize);
        let (sx, sy) = (sub % p, sub / p);
        (sy..size).step_by(p).flat_map(|ty| (sx..size).step_by(p).map(move |tx| ty * size + tx)).collect()
    }

    /// Squared clamp distance of the VPL fall-off.
    pub fn min_d2(&self) -> f32 {
        self.min_d2
    }

    /// Renders one frame with `settings`: [`VplContext::shade`] then
    /// [`VplContext::finish`].
    pub fn render(&self, settings: &VplSettings) -> Result<VplFrame, RenderError> {
        let shaded = self.shade(settings)?;
        Ok(self.finish(shaded, settings))
    }

    /// Checks settings shared by every backend.
    pub fn check(&self, s: &VplSettings) -> Result<RangeParams, RenderError> {
        let params = RangeParams::new(s.error_bound, s.exposure).map_err(|e| RenderError::Setting(e.to_string()))?;
        if s.method == VplMethod::Clamp && !(s.range.is_finite() && s.range > 0.0) {
            return Err(RenderError::Setting(format!("clamp range {} must be finite and > 0", s.range)));
        }
        if let Some(x) = s.fixed_xi {
            slc_core::range::Xi::new(x).map_err(|e| RenderError::Setting(e.to_string()))?;
        }
        if s.tile == 0 {
            return Err(RenderError::Setting("tile size must be > 0".into()));
        }
        Ok(params)
    }

    /// Indirect irradiance at every pixel (before denoise and albedo), on the
    /// CPU.
    pub fn shade(&self, settings: &VplSettings) -> Result<Shaded, RenderError> {
        let params = self.check(settings)?;
        let t = Instant::now();
        let (irradiance, kept, evaluations) = match settings.method {
            VplMethod::Reference => self.shade_reference(),
            m => self.shade_interleaved(m, &params, settings),
        };
        Ok(Shaded { irradiance, kept, evaluations, shading_ms: ms(t), denoised_ms: None })
    }

    /// Denoise (interleaved methods), albedo × (direct + indirect) +
    /// emission, and the frame's statistics.
    pub fn finish(&self, shaded: Shaded, settings: &VplSettings) -> VplFrame {
        let mut stats = self.base;
        stats.shading_ms = shaded.shading_ms;
        let gb = &self.gbuffer;
        let shaded_px = (0..gb.position.len()).filter(|&i| gb.valid(i)).count().max(1) as f64;
        stats.evaluations = shaded.evaluations;
        stats.lights_per_pixel = shaded.evaluations as f64 / shaded_px;
        stats.kept_per_pixel = shaded.kept.iter().map(|&k| k as f64).sum::<f64>() / shaded_px;
        let t = Instant::now();
        let filtered = if settings.denoise && settings.method != VplMethod::Reference && shaded.denoised_ms.is_none() {
            denoise::cross_bilateral(&shaded.irradiance, gb, PERIOD)
        } else {
            shaded.irradiance
        };
        let data = (0..filtered.len()).map(|i| gb.emission[i] + gb.albedo[i] * INV_PI * (self.direct[i] + filtered[i])).collect();
        stats.denoise_ms = ms(t) + shaded.denoised_ms.unwrap_or(0.0);
        stats.total_ms = stats.gbuffer_ms + stats.rsm_ms + stats.direct_ms + stats.shading_ms + stats.denoise_ms;
        VplFrame { image: Image { width: gb.width, height: gb.height, data }, stats }
    }

    /// Every VPL at every pixel.
    fn shade_reference(&self) -> (Vec<Vec3>, Vec<u32>, u64) {
        let v = &self.vpls;
        let mut list = LightList::default();
        for i in 0..v.len() {
            list.push(v.position[i], v.normal[i], v.flux[i], f32::INFINITY, f32::INFINITY);
        }
        let gb = &self.gbuffer;
        let out: Vec<(Vec3, u32)> = (0..gb.position.len())
            .into_par_iter()
            .map(|i| if gb.valid(i) { shade::shade(&list, gb.position[i], gb.normal[i], self.min_d2, Cull::None) } else { (Vec3::ZERO, 0) })
            .collect();
        let shaded = (0..out.len()).filter(|&i| gb.valid(i)).count() as u64;
        (out.iter().map(|o| o.0).collect(), out.iter().map(|o| o.1).collect(), shaded * v.len() as u64)
    }

    /// Interleaved sampling with tiled culling per sub-image.
    fn shade_interleaved(&self, method: VplMethod, params: &RangeParams, s: &VplSettings) -> (Vec<Vec3>, Vec<u32>, u64) {
        let gb = &self.gbuffer;
        let v = &self.vpls;
        let p = PERIOD as usize;
        let subsets = p * p;
        let size = v.size as usize;
        // Interleaved flux: each pixel sees 1/64 of the VPLs, so each counts 64×.
        let scale = subsets as f32;
        let cull = match method {
            VplMethod::Slc => Cull::Slc,
            VplMethod::Clamp => Cull::Clamp,
            _ => Cull::None,
        };
        let (w, h) = (gb.width as usize, gb.height as usize);
        let tile = s.tile as usize;
        // Per subset: (pixel, irradiance, kept) triples and loop evaluations.
        type SubsetResult = (Vec<(usize, Vec3, u32)>, u64);
        let results: Vec<SubsetResult> = (0..subsets)
            .into_par_iter()
            .map(|sub| {
                let (sx, sy) = (sub % p, sub / p);
                // The subset's VPLs (flux ×64) with their ranges, once per frame.
                let mut all = LightList::default();
                // Subset texels in 4×4 blocks, so each CHUNK of 16 consecutive
                // lights is a small patch of the RSM (spatially coherent).
                let m = size / p;
                for by in (0..m).step_by(4) {
                    for bx in (0..m).step_by(4) {
                        for (u, v_) in (0..16).map(|k| (bx + k % 4, by + k / 4)).filter(|&(u, v_)| u < m && v_ < m) {
                            let i = (sy + v_ * p) * size + sx + u * p;
                            let flux = v.flux[i] * scale;
                            let (rt2, r2) = match cull {
                                Cull::Slc => {
                                    let rt2 = vpl_threshold_range2(params, flux);
                                    (rt2, random_range2(rt2, s.fixed_xi.unwrap_or_else(|| xi_for(s.seed, s.frame, i as u32))))
                                }
                                Cull::Clamp => (0.0, s.range * s.range),
                                Cull::None => (f32::INFINITY, f32::INFINITY),
                            };
                            all.push(v.position[i], v.normal[i], flux, rt2, r2);
                        }
                    }
                }
                all.build_chunks();
                let (sw, sh) = ((w + p - 1 - sx) / p, (h + p - 1 - sy) / p);
                let mut out = Vec::with_capacity(sw * sh);
                let (mut coarse, mut fine) = (LightList::default(), LightList::default());
                let (mut pixels, mut hits) = (Vec::new(), Vec::new());
                let mut evals = 0u64;
                // Pixels of sub-image rectangle [x0, x1) × [y0, y1) that see a surface.
                let gather = |pixels: &mut Vec<usize>, (x0, x1): (usize, usize), (y0, y1): (usize, usize)| {
                    pixels.clear();
                    for j in y0..y1 {
                        for i in x0..x1 {
                            let px = (sy + j * p) * w + sx + i * p;
                            if gb.valid(px) {
                                pixels.push(px);
                            }
                        }
                    }
                };
                let bounds = |pixels: &[usize]| {
                    pixels.iter().fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &i| (lo.min(gb.position[i]), hi.max(gb.position[i])))
                };
                // Two-level tiled culling: super-tiles of SUPER × tile cull the
                // subset; their tiles cull the super-tile's list.
                let big = tile * SUPER;
                for by in (0..sh).step_by(big) {
                    for bx in (0..sw).step_by(big) {
                        let (bx1, by1) = ((bx + big).min(sw), (by + big).min(sh));
                        if cull != Cull::None {
                            gather(&mut pixels, (bx, bx1), (by, by1));
                            if pixels.is_empty() {
                                continue;
                            }
                            let (lo, hi) = bounds(&pixels);
                            all.cull_chunked_into(lo, hi, &mut hits, &mut coarse);
                        }
                        for ty in (by..by1).step_by(tile) {
                            for tx in (bx..bx1).step_by(tile) {
                                gather(&mut pixels, (tx, (tx + tile).min(bx1)), (ty, (ty + tile).min(by1)));
                                if pixels.is_empty() {
                                    continue;
                                }
                                let lights = if cull == Cull::None {
                                    &all
                                } else {
                                    let (lo, hi) = bounds(&pixels);
                                    coarse.cull_into(lo, hi, &mut hits, &mut fine);
                                    &fine
                                };
                                for &i in &pixels {
                                    let (e, k) = shade::shade(lights, gb.position[i], gb.normal[i], self.min_d2, cull);
                                    out.push((i, e, k));
                                }
                                evals += (lights.len_unpadded() * pixels.len()) as u64;
                            }
                        }
                    }
                }
                (out, evals)
            })
            .collect();
        let mut e = vec![Vec3::ZERO; w * h];
        let mut kept = vec![0u32; w * h];
        let mut evals = 0;
        for (out, ev) in results {
            for (i, v, k) in out {
                e[i] = v;
                kept[i] = k;
            }
            evals += ev;
        }
        (e, kept, evals)
    }
}

/// Direct irradiance from the primary light, with shadow rays.
fn direct_light(scene: &Scene, geo: &Geometry, gb: &GBuffer) -> Vec<Vec3> {
    let diag = scene.diagonal();
    (0..gb.position.len())
        .into_par_iter()
        .map(|i| {
            if !gb.valid(i) {
                return Vec3::ZERO;
            }
            let (x, n) = (gb.position[i], gb.normal[i]);
            match scene.primary {
                PrimaryLight::Spot { position, .. } => {
                    let spot = Light::Spot(scene.primary.spot().expect("validated scene"));
                    let v = position - x;
                    let d2 = v.length_squared();
                    let wi = v / d2.sqrt();
                    let cos = n.dot(wi);
                    if cos <= 0.0 || geo.occluded(x + n * 1e-5 * diag, position) {
                        return Vec3::ZERO;
                    }
                    spot.intensity(-wi) * cos * inverse_square(d2)
                }
                PrimaryLight::Directional { direction, irradiance } => {
                    let wi = -direction.normalize();
                    let cos = n.dot(wi);
                    if cos <= 0.0 || geo.occluded(x + n * 1e-5 * diag, x + wi * 2.0 * diag) {
                        return Vec3::ZERO;
                    }
                    irradiance * cos
                }
            }
        })
        .collect()
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}
