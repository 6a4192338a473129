//! Application A of the paper: real-time indirect illumination with VPLs.
//!
//! Pipeline (every step a function with a typed input and output):
//! [`render_gbuffer`] → [`rsm::reflective_shadow_map`] (`size²` VPLs) →
//! 8×8 interleaved sampling (pixel `(x, y)` uses VPL subset
//! `(y mod 8)·8 + x mod 8`; subset of RSM texel `(tx, ty)` likewise, each
//! subset's flux scaled by 64) → tiled shading of each sub-image with the
//! subset's VPL spheres culled per tile ([`shade`]) →
//! [`denoise::cross_bilateral`] → albedo × (indirect + direct) + emission.
//!
//! The settings, G-buffer, VPL and frame types are slc-scene's
//! ([`slc_scene::vpl`]); [`VplContext`] is the CPU's
//! [`IndirectShader`].
//!
//! Methods: [`VplMethod::Slc`] (stochastic ranges from error bound ε),
//! [`VplMethod::Clamp`] (fixed range R, no reweighting: biased),
//! [`VplMethod::None`] (interleaved, unculled) and [`VplMethod::Reference`]
//! (every VPL at every pixel, no interleaving, no denoise).

pub mod denoise;
pub mod rsm;
pub mod shade;

use crate::gbuffer::render_gbuffer;
use crate::geometry::Geometry;
use glam::Vec3;
use rayon::prelude::*;
use shade::{Cull, LightList};
use slc_core::frame::{diffuse_radiance, directional_irradiance, point_irradiance};
use slc_core::light::{Light, vpl_threshold_range2};
use slc_core::range::{RangeParams, random_range2};
use slc_core::xi::xi_for;
use slc_scene::RenderError;
use slc_scene::backend::IndirectShader;
use slc_scene::image::Image;
use slc_scene::scene::{PrimaryLight, Scene};
use slc_scene::vpl::{GBuffer, PERIOD, Shaded, VplFrame, VplInputs, VplMethod, VplSettings, VplStats, Vpls};
use std::time::Instant;

/// Super-tile size in tiles for the first culling level.
pub const SUPER: usize = 2;

/// Everything that does not depend on the method: geometry, G-buffer, VPLs
/// and direct light, computed once.
pub struct VplContext {
    scene: Scene,
    inputs: VplInputs,
    direct: Vec<Vec3>,
    base: VplStats,
}

impl VplContext {
    /// Validates the inputs and computes the shared buffers. `rsm_size` must
    /// be a positive multiple of 8 (`rsm_size²` VPLs); `width`, `height` in
    /// `1..=16384`. `min_distance` is the clamp distance of the VPL fall-off
    /// (`None`: 1% of the scene's diagonal).
    pub fn new(scene: &Scene, width: u32, height: u32, rsm_size: u32, min_distance: Option<f32>) -> Result<Self, RenderError> {
        let min_distance = slc_scene::vpl::check_frame(scene, width, height, rsm_size, min_distance)?;
        let mut base = VplStats::default();
        let t = Instant::now();
        let geo = Geometry::new(&scene.triangles);
        let (gbuffer, geometric_normal) = render_gbuffer(scene, &geo, width, height);
        base.gbuffer_ms = ms(t);
        let t = Instant::now();
        let vpls = rsm::reflective_shadow_map(scene, &geo, rsm_size);
        base.rsm_ms = ms(t);
        let t = Instant::now();
        let direct = direct_light(scene, &geo, &gbuffer, &geometric_normal);
        base.direct_ms = ms(t);
        base.vpls = vpls.len();
        let inputs = VplInputs { gbuffer, vpls, min_d2: min_distance * min_distance };
        Ok(VplContext { scene: scene.clone(), inputs, direct, base })
    }

    /// What a backend shades: G-buffer, VPLs, clamp distance.
    pub fn inputs(&self) -> &VplInputs {
        &self.inputs
    }

    /// The G-buffer.
    pub fn gbuffer(&self) -> &GBuffer {
        &self.inputs.gbuffer
    }

    /// The VPLs.
    pub fn vpls(&self) -> &Vpls {
        &self.inputs.vpls
    }

    /// The scene.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Squared clamp distance of the VPL fall-off.
    pub fn min_d2(&self) -> f32 {
        self.inputs.min_d2
    }

    /// Renders one frame with `settings`: [`VplContext::shade`] then
    /// [`VplContext::finish`].
    pub fn render(&self, settings: &VplSettings) -> Result<VplFrame, RenderError> {
        let shaded = self.shade(settings)?;
        Ok(self.finish(shaded, settings))
    }

    /// Indirect irradiance at every pixel (before denoise and albedo), on the
    /// CPU.
    pub fn shade(&self, settings: &VplSettings) -> Result<Shaded, RenderError> {
        let params = settings.validate()?;
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
        let gb = &self.inputs.gbuffer;
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
        let data = (0..filtered.len()).map(|i| diffuse_radiance(gb.albedo[i], gb.emission[i], self.direct[i] + filtered[i])).collect();
        stats.denoise_ms = ms(t) + shaded.denoised_ms.unwrap_or(0.0);
        stats.total_ms = stats.gbuffer_ms + stats.rsm_ms + stats.direct_ms + stats.shading_ms + stats.denoise_ms;
        VplFrame { image: Image { width: gb.width, height: gb.height, data }, stats }
    }

    /// Every VPL at every pixel.
    fn shade_reference(&self) -> (Vec<Vec3>, Vec<u32>, u64) {
        let v = &self.inputs.vpls;
        let mut list = LightList::default();
        for i in 0..v.len() {
            list.push(v.position[i], v.normal[i], v.flux[i], f32::INFINITY, f32::INFINITY);
        }
        let gb = &self.inputs.gbuffer;
        let out: Vec<(Vec3, u32)> = (0..gb.position.len())
            .into_par_iter()
            .map(|i| if gb.valid(i) { shade::shade(&list, gb.position[i], gb.normal[i], self.inputs.min_d2, Cull::None) } else { (Vec3::ZERO, 0) })
            .collect();
        let shaded = (0..out.len()).filter(|&i| gb.valid(i)).count() as u64;
        (out.iter().map(|o| o.0).collect(), out.iter().map(|o| o.1).collect(), shaded * v.len() as u64)
    }

    /// Interleaved sampling with tiled culling per sub-image.
    fn shade_interleaved(&self, method: VplMethod, params: &RangeParams, s: &VplSettings) -> (Vec<Vec3>, Vec<u32>, u64) {
        let gb = &self.inputs.gbuffer;
        let v = &self.inputs.vpls;
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
                                    let (e, k) = shade::shade(lights, gb.position[i], gb.normal[i], self.inputs.min_d2, cull);
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

/// Direct irradiance from the primary light, with shadow rays offset along
/// the geometric normal `geo_n` (cosines use the G-buffer's shading normal).
fn direct_light(scene: &Scene, geo: &Geometry, gb: &GBuffer, geo_n: &[Vec3]) -> Vec<Vec3> {
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
                    if n.dot(v) <= 0.0 || geo.occluded(x + geo_n[i] * 1e-5 * diag, position) {
                        return Vec3::ZERO;
                    }
                    point_irradiance(spot.intensity(-v.normalize()), n, v)
                }
                PrimaryLight::Directional { direction, irradiance } => {
                    let wi = -direction.normalize();
                    if n.dot(wi) <= 0.0 || geo.occluded(x + geo_n[i] * 1e-5 * diag, x + wi * 2.0 * diag) {
                        return Vec3::ZERO;
                    }
                    directional_irradiance(irradiance, n, wi)
                }
            }
        })
        .collect()
}

impl IndirectShader for VplContext {
    type Error = RenderError;

    fn describe(&self) -> String {
        format!("cpu ({} threads)", rayon::current_num_threads())
    }

    fn shade(&self, settings: &VplSettings) -> Result<Shaded, RenderError> {
        VplContext::shade(self, settings)
    }
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}
