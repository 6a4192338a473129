//! Application A of the paper: real-time indirect illumination with VPLs.
//!
//! Pipeline (every step a function with a typed input and output):
//! [`render_gbuffer_into`] → [`rsm::reflective_shadow_map_into`] (`size²` VPLs) →
//! 8×8 interleaved sampling (pixels of class `(y mod 8)·8 + x mod 8` shade
//! VPL subset `shifted_subset(class, interleave_shift(seed, frame))`; the
//! subset of RSM texel `(tx, ty)` is its class, each subset's flux scaled
//! by 64; [`slc_core::interleave`]) → tiled shading of each sub-image with the
//! subset's VPL spheres culled per tile ([`shade`]) →
//! [`denoise::cross_bilateral`] → albedo × (indirect + direct) + emission.
//! What the shading and the denoise need from the G-buffer alone (the
//! pixels' tiles with their boxes, the filter's normal and depth planes)
//! is built once with the G-buffer and counted in its time.
//!
//! The settings, G-buffer, VPL and frame types are slc-scene's
//! ([`slc_scene::vpl`]). The culling is the settings'
//! [`Culling`]: stochastic ranges from error bound ε, a clamped range `R`
//! (no reweighting: biased), none (interleaved, unculled), or the
//! reference (every VPL at every pixel, no interleaving, no denoise).

pub mod denoise;
pub mod rsm;
pub mod shade;
mod tiling;

use crate::gbuffer::render_gbuffer_into;
use crate::geometry::Geometry;
use crate::raster::{MapView, Occluders};
use crate::temporal::Temporal;
use denoise::Denoiser;
use glam::Vec3;
use rayon::prelude::*;
use shade::{Cull, Glossy, LightList};
use slc_core::frame::{directional_irradiance, point_irradiance};
use slc_core::interleave::{
    interleave_flux_scale, interleave_shift, shifted_subset, vpl_near_range2,
};
use slc_core::light::{Light, vpl_threshold_range2};
use slc_core::range::{CullKind, random_range2};
use slc_core::ray::surface_offset;
use slc_core::xi::frame_xi;
use slc_scene::RenderError;
use slc_scene::image::Image;
use slc_scene::scene::{Camera, PrimaryLight, Scene};
use slc_scene::temporal::{TemporalSettings, TemporalView};
use slc_scene::vpl::{
    Culling, GBuffer, PERIOD, Shaded, VplFrame, VplInputs, VplSettings, VplStats, Vpls,
};
use std::sync::{Mutex, PoisonError};
use std::time::Instant;
use tiling::{NO_RECEIVER, PartTiles, Tiling};

/// The histories of a VPL frame's accumulated signals (the filtered
/// irradiance and, on glossy pixels, the specular correction), for
/// [`VplContext::render_accumulated`], and the primary light they were lit
/// by: a frame whose primary light differs from the last one's is a
/// reported change ([`TemporalSettings::after_change`]).
pub struct FrameHistory {
    /// The filtered irradiance's.
    pub irradiance: Temporal,
    /// The specular correction's.
    pub specular: Temporal,
    lit_by: Option<PrimaryLight>,
}

impl FrameHistory {
    /// Empty histories for a `width × height` frame.
    pub fn new(width: u32, height: u32) -> Result<FrameHistory, RenderError> {
        Ok(FrameHistory {
            irradiance: Temporal::new(width, height)?,
            specular: Temporal::new(width, height)?,
            lit_by: None,
        })
    }

    /// Forgets both histories.
    pub fn reset(&mut self) {
        self.irradiance.reset();
        self.specular.reset();
        self.lit_by = None;
    }
}

/// Super-tile size in tiles for the first culling level.
pub const SUPER: usize = 2;

/// Everything that does not depend on the method: geometry, G-buffer, VPLs
/// and direct light, computed once.
pub struct VplContext {
    scene: Scene,
    geo: Geometry,
    inputs: VplInputs,
    /// Each pixel's geometric normal (shadow-ray offsets).
    geometric: Vec<Vec3>,
    direct: Vec<Vec3>,
    from_gbuffer: FromGBuffer,
    reuse: Mutex<Reused>,
    base: VplStats,
}

/// A frame's working memory kept for the next frame (its buffers are
/// megabytes: fresh ones cost a page fault per 4 KiB on first touch): the
/// far and near fields' per-receiver results, and the pixel buffers a
/// [`Shaded`] hands to [`VplContext::finish`], returned by it. Frames
/// rendered at once take what is there; one that finds it taken
/// allocates its own.
#[derive(Default)]
struct Reused {
    far: PerReceiver,
    near: PerReceiver,
    /// The near field's light list.
    near_lights: LightList,
    vec3: Vec<Vec<Vec3>>,
    counts: Vec<Vec<u32>>,
}

impl Reused {
    /// Pixel buffers of each type kept at most (a frame's [`Shaded`] holds
    /// four of `Vec3`, one of counts).
    const KEEP: usize = 4;

    /// A pixel buffer of `Vec3` (empty, with the memory of a kept one).
    fn vec3(&mut self) -> Vec<Vec3> {
        take_buffer(&mut self.vec3)
    }

    /// A pixel buffer of counts, as [`Reused::vec3`].
    fn counts(&mut self) -> Vec<u32> {
        take_buffer(&mut self.counts)
    }

    /// Adds `r`'s memory to this one's where this one has none.
    fn absorb(&mut self, r: Reused) {
        if self.far.out.capacity() == 0 {
            self.far = r.far;
        }
        if self.near.out.capacity() == 0 {
            self.near = r.near;
        }
        if self.near_lights.capacity() == 0 {
            self.near_lights = r.near_lights;
        }
        keep_buffers(&mut self.vec3, r.vec3);
        keep_buffers(&mut self.counts, r.counts);
    }
}

/// A buffer of `pool` emptied (a new one where the pool has none).
fn take_buffer<T>(pool: &mut Vec<Vec<T>>) -> Vec<T> {
    let mut v = pool.pop().unwrap_or_default();
    v.clear();
    v
}

/// Adds the buffers of `more` that hold memory to `pool`, up to
/// [`Reused::KEEP`].
fn keep_buffers<T>(pool: &mut Vec<Vec<T>>, more: Vec<Vec<T>>) {
    pool.extend(more.into_iter().filter(|v| v.capacity() > 0));
    pool.truncate(Reused::KEEP);
}

impl VplContext {
    /// The reused memory (none when another frame holds the lock).
    fn take_reused(&self) -> Reused {
        self.reuse.try_lock().map(|mut r| std::mem::take(&mut *r)).unwrap_or_default()
    }

    /// Keeps `r`'s memory for the next frame (drops it when another frame
    /// holds the lock, or where memory is kept already).
    fn keep_reused(&self, r: Reused) {
        if let Ok(mut kept) = self.reuse.try_lock() {
            kept.absorb(r);
        }
    }
}

/// What a frame derives from the G-buffer alone, rebuilt with it: the
/// pixels tiled for the far field (at the default tile size) and the near
/// field, and the denoise with its G-buffer planes (behind a lock so that
/// frames render through `&self`; frames rendered at once take turns at
/// the filter).
#[derive(Default)]
struct FromGBuffer {
    far: Tiling,
    /// The tile size `far` was built for.
    far_tile: usize,
    near: Tiling,
    denoiser: Mutex<Denoiser>,
}

impl FromGBuffer {
    fn build(&mut self, gb: &GBuffer) {
        self.far_tile = VplSettings::default().tile as usize;
        self.far.interleaved_into(gb, PERIOD as usize, self.far_tile, SUPER);
        self.near.regions_into(gb, NEAR_REGION, NEAR_TILE);
        self.denoiser.get_mut().unwrap_or_else(PoisonError::into_inner).set_gbuffer(gb);
    }
}

impl VplContext {
    /// Validates the inputs and computes the shared buffers. `rsm_size` must
    /// be a positive multiple of 8 (`rsm_size²` VPLs); `width`, `height` in
    /// `1..=16384`. `min_distance` is the clamp distance of the VPL fall-off
    /// (`None`: 1% of the scene's diagonal).
    pub fn new(
        scene: &Scene,
        width: u32,
        height: u32,
        rsm_size: u32,
        min_distance: Option<f32>,
    ) -> Result<Self, RenderError> {
        let min_distance =
            slc_scene::vpl::check_frame(scene, width, height, rsm_size, min_distance)?;
        let geo = Geometry::new(&scene.triangles);
        let (gbuffer, vpls) = (
            GBuffer { width, height, ..GBuffer::default() },
            Vpls { size: rsm_size, ..Vpls::default() },
        );
        let mut inputs = VplInputs { gbuffer, vpls, min_d2: min_distance * min_distance };
        let (mut geometric, mut direct, mut from_gbuffer) =
            (Vec::new(), Vec::new(), FromGBuffer::default());
        let base = frame_inputs(
            scene,
            &geo,
            true,
            &mut inputs,
            &mut geometric,
            &mut direct,
            &mut from_gbuffer,
        );
        Ok(VplContext {
            scene: scene.clone(),
            geo,
            inputs,
            geometric,
            direct,
            from_gbuffer,
            reuse: Mutex::default(),
            base,
        })
    }

    /// Renders the G-buffer, the RSM and the direct light again into the
    /// context's buffers, as a frame whose camera and light move does every
    /// frame, and returns their times (the statistics
    /// [`VplContext::render`] reports hold the first, cold run: thread
    /// start-up, first touches of memory). The same scene gives the same
    /// buffers.
    pub fn time_inputs(&mut self) -> VplStats {
        frame_inputs(
            &self.scene,
            &self.geo,
            true,
            &mut self.inputs,
            &mut self.geometric,
            &mut self.direct,
            &mut self.from_gbuffer,
        )
    }

    /// Moves or changes the primary light (the CPU twin of the GPU frame's
    /// `set_primary`): the RSM and the direct light are rendered again into
    /// the context's buffers (the G-buffer stands), and their times are
    /// returned and kept for [`VplContext::render`]'s statistics. The light
    /// is checked as the scene's is; a refused light changes nothing.
    pub fn set_primary(&mut self, primary: PrimaryLight) -> Result<VplStats, RenderError> {
        primary.validate().map_err(|e| RenderError::Setting(e.to_string()))?;
        self.scene.primary = primary;
        let t = frame_inputs(
            &self.scene,
            &self.geo,
            false,
            &mut self.inputs,
            &mut self.geometric,
            &mut self.direct,
            &mut self.from_gbuffer,
        );
        (self.base.rsm_ms, self.base.direct_ms) = (t.rsm_ms, t.direct_ms);
        Ok(t)
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
        settings.validate()?;
        let t = Instant::now();
        let f = match settings.culling {
            Culling::Reference => self.shade_reference(),
            _ => self.shade_interleaved(settings),
        };
        Ok(Shaded {
            irradiance: f.irradiance,
            near: f.near,
            specular: f.specular,
            specular_near: f.specular_near,
            kept: f.kept,
            evaluations: f.evaluations,
            shading_ms: ms(t),
            denoised_ms: None,
        })
    }

    /// Denoise (interleaved methods), albedo × (direct + indirect) +
    /// emission, and the frame's statistics. Where `shaded` has a specular
    /// correction ([`Shaded::specular`]), it is denoised with the same
    /// filter (linear in its input, so this is the filter of the whole VPL
    /// radiance where `c_diff` is constant over the window), and those
    /// pixels take `emission + f(v, l)·direct + c_diff/π · E + S`, the
    /// primary light's direct term reflected by the whole BRDF toward it
    /// ([`GBuffer::radiance`]).
    pub fn finish(&self, shaded: Shaded, settings: &VplSettings) -> VplFrame {
        // Without a history nothing in the frame can fail.
        self.finish_with(shaded, settings, None)
            .unwrap_or_else(|_| unreachable!("a frame without history has no failure"))
    }

    /// Renders one frame with temporal accumulation: [`VplContext::shade`],
    /// the spatial filter, then the filtered irradiance (and the specular
    /// correction) accumulated over the frames in `history`
    /// ([`crate::temporal`]; albedo and the lobes are applied after it),
    /// seen from the context's camera ([`VplContext::set_camera`]). The
    /// accumulation's time counts as denoise.
    pub fn render_accumulated(
        &self,
        settings: &VplSettings,
        history: &mut FrameHistory,
        temporal: &TemporalSettings,
    ) -> Result<VplFrame, RenderError> {
        let shaded = self.shade(settings)?;
        self.finish_accumulated(shaded, settings, history, temporal)
    }

    /// [`VplContext::finish`] with the filtered signals accumulated over
    /// `history` ([`VplContext::render_accumulated`]).
    pub fn finish_accumulated(
        &self,
        shaded: Shaded,
        settings: &VplSettings,
        history: &mut FrameHistory,
        temporal: &TemporalSettings,
    ) -> Result<VplFrame, RenderError> {
        self.finish_with(shaded, settings, Some((history, temporal)))
    }

    /// Moves the camera: the G-buffer, the RSM and the direct light are
    /// rendered again, their times returned and kept for the frame's
    /// statistics. The camera is checked as the scene's is; a refused
    /// camera changes nothing.
    pub fn set_camera(&mut self, camera: Camera) -> Result<VplStats, RenderError> {
        camera.validate().map_err(|e| RenderError::Setting(e.to_string()))?;
        self.scene.camera = camera;
        let t = frame_inputs(
            &self.scene,
            &self.geo,
            true,
            &mut self.inputs,
            &mut self.geometric,
            &mut self.direct,
            &mut self.from_gbuffer,
        );
        (self.base.gbuffer_ms, self.base.rsm_ms, self.base.direct_ms) =
            (t.gbuffer_ms, t.rsm_ms, t.direct_ms);
        Ok(t)
    }

    /// [`VplContext::finish`], accumulating the filtered signals over
    /// `temporal`'s history where given.
    fn finish_with(
        &self,
        shaded: Shaded,
        settings: &VplSettings,
        temporal: Option<(&mut FrameHistory, &TemporalSettings)>,
    ) -> Result<VplFrame, RenderError> {
        let mut stats = self.base;
        stats.shading_ms = shaded.shading_ms;
        let gb = &self.inputs.gbuffer;
        let shaded_px =
            (0..gb.position.len()).into_par_iter().filter(|&i| gb.valid(i)).count().max(1) as f64;
        stats.evaluations = shaded.evaluations;
        stats.lights_per_pixel = shaded.evaluations as f64 / shaded_px;
        stats.kept_per_pixel =
            shaded.kept.par_iter().map(|&k| k as u64).sum::<u64>() as f64 / shaded_px;
        let t = Instant::now();
        let denoise = settings.denoise
            && settings.culling != Culling::Reference
            && shaded.denoised_ms.is_none();
        let filter = |mut e: Vec<Vec3>, near: &[Vec3]| -> Vec<Vec3> {
            if denoise {
                // The near field is exact: only the interleaved far field is filtered.
                self.from_gbuffer
                    .denoiser
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner)
                    .filter_far_in_place(&mut e, near, gb, PERIOD);
            }
            e
        };
        let mut filtered = filter(shaded.irradiance, &shaded.near);
        let mut specular = if shaded.specular.is_empty() {
            Vec::new()
        } else {
            filter(shaded.specular, &shaded.specular_near)
        };
        if let Some((history, ts)) = temporal {
            let view = TemporalView::of_camera(&self.scene.camera, gb.width, gb.height);
            let changed = history.lit_by.is_some_and(|p| p != self.scene.primary);
            history.lit_by = Some(self.scene.primary);
            let ts = &if changed { ts.after_change() } else { *ts };
            filtered = history.irradiance.accumulate(&filtered, gb, &view, ts)?;
            if specular.is_empty() {
                // No glossy pixel this frame: the next glossy frame must not
                // reproject a specular history from frames ago.
                history.specular.reset();
            } else {
                specular = history.specular.accumulate(&specular, gb, &view, ts)?;
            }
        }
        let primary = self.scene.primary;
        let data = (0..filtered.len())
            .into_par_iter()
            .map(|i| {
                gb.radiance(i, &primary, self.direct[i], filtered[i], specular.get(i).copied())
            })
            .collect();
        // The pixel buffers serve the next frame's shading.
        self.keep_reused(Reused {
            vec3: vec![filtered, shaded.near, specular, shaded.specular_near],
            counts: vec![shaded.kept],
            ..Reused::default()
        });
        stats.denoise_ms = ms(t) + shaded.denoised_ms.unwrap_or(0.0);
        stats.total_ms = stats.stage_sum();
        Ok(VplFrame { image: Image { width: gb.width, height: gb.height, data }, stats })
    }

    /// Every VPL at every pixel.
    fn shade_reference(&self) -> Fields {
        let v = &self.inputs.vpls;
        let mut list = LightList::default();
        for i in 0..v.len() {
            list.push(v.position[i], v.normal[i], v.flux[i], f32::INFINITY, f32::INFINITY);
        }
        let gb = &self.inputs.gbuffer;
        let out: Vec<(Vec3, u32)> = (0..gb.position.len())
            .into_par_iter()
            .map(|i| {
                if gb.valid(i) {
                    shade::shade(
                        &list,
                        gb.position[i],
                        gb.normal[i],
                        self.inputs.min_d2,
                        0.0,
                        Cull::far(CullKind::None),
                    )
                } else {
                    (Vec3::ZERO, 0)
                }
            })
            .collect();
        let shaded = (0..out.len()).filter(|&i| gb.valid(i)).count() as u64;
        let specular = self.specular_at_every_glossy_pixel(|g| {
            shade::shade_specular(&list, g, self.inputs.min_d2, 0.0, Cull::far(CullKind::None))
        });
        Fields {
            irradiance: out.iter().map(|o| o.0).collect(),
            near: Vec::new(),
            specular,
            specular_near: Vec::new(),
            kept: out.iter().map(|o| o.1).collect(),
            evaluations: shaded * v.len() as u64,
        }
    }

    /// `shade(g)` at every pixel with a specular lobe, zero elsewhere;
    /// empty when no pixel has one.
    fn specular_at_every_glossy_pixel(&self, shade: impl Fn(&Glossy) -> Vec3 + Sync) -> Vec<Vec3> {
        let gb = &self.inputs.gbuffer;
        if !gb.has_specular() {
            return Vec::new();
        }
        (0..gb.position.len())
            .into_par_iter()
            .map(|i| Glossy::at(gb, i).map_or(Vec3::ZERO, |g| shade(&g)))
            .collect()
    }

    /// Interleaved sampling with tiled culling per sub-image: the far field
    /// plus the near field ([`VplContext::shade_near_in`]), the near field
    /// alone, the same two of the specular correction at the pixels with a
    /// specular lobe, the kept counts and evaluations of both. The tiles are
    /// the context's [`Tiling::interleaved`] (built with the G-buffer) for
    /// the default tile size, built here for another.
    fn shade_interleaved(&self, s: &VplSettings) -> Fields {
        let gb = &self.inputs.gbuffer;
        let p = PERIOD as usize;
        let cull = Cull::far(s.culling.kind());
        let (w, h) = (gb.width as usize, gb.height as usize);
        let near_r2 = s.near_r2(self.inputs.min_d2);
        let owned;
        let tiling = if s.tile as usize == self.from_gbuffer.far_tile {
            &self.from_gbuffer.far
        } else {
            owned = Tiling::interleaved(gb, p, s.tile as usize, SUPER);
            &owned
        };
        let min_d2 = self.inputs.min_d2;
        let mut reused = self.take_reused();
        let ranges = self.ranges(s);
        let shift = interleave_shift(s.seed, s.frame, PERIOD);
        let (mut far, mut near_lights) =
            (std::mem::take(&mut reused.far), std::mem::take(&mut reused.near_lights));
        // The near field's light list is built (one thread) while the far
        // field is shaded (the other, and both once it is built).
        rayon::join(
            || {
                far.shade_parts(tiling, |class, part, out, spec, scratch| {
                    self.subset_lights_into(
                        &mut scratch.all,
                        shifted_subset(class as u32, shift, PERIOD) as usize,
                        &ranges,
                    );
                    shade_part(
                        part,
                        &scratch.all,
                        cull.kind != CullKind::None,
                        cull,
                        min_d2,
                        near_r2,
                        out,
                        spec,
                        &mut scratch.lists,
                    )
                })
            },
            || self.near_lights_into(&mut near_lights, &ranges, near_r2, cull),
        );
        let mut near = std::mem::take(&mut reused.near);
        self.shade_near_in(&mut near, &self.from_gbuffer.near, &near_lights, near_r2, cull);
        // Each pixel adds its far field to its near field, in parallel, in
        // one pass that also writes the near field alone.
        let nt = &self.from_gbuffer.near;
        let (mut irradiance, mut kept, mut near_field) =
            (reused.vec3(), reused.counts(), reused.vec3());
        let sum = |i: usize| {
            let ((f, kf), (n, kn)) = (far.at(tiling, i), near.at(nt, i));
            ((f + n, kf + kn), n)
        };
        if near.out.is_empty() {
            (0..w * h)
                .into_par_iter()
                .map(|i| sum(i).0)
                .unzip_into_vecs(&mut irradiance, &mut kept);
        } else {
            let mut all = ((irradiance, kept), near_field);
            all.par_extend((0..w * h).into_par_iter().map(sum));
            ((irradiance, kept), near_field) = all;
        }
        // A field per pixel, empty where `present` is false.
        let mut pixels = |present: bool, value: &(dyn Fn(usize) -> Vec3 + Sync)| -> Vec<Vec3> {
            let mut out = reused.vec3();
            if present {
                out.par_extend((0..w * h).into_par_iter().map(value));
            }
            out
        };
        let specular =
            pixels(!far.spec.is_empty(), &|i| far.specular_at(tiling, i) + near.specular_at(nt, i));
        let specular_near = pixels(!near.spec.is_empty(), &|i| near.specular_at(nt, i));
        let evaluations = near.evals + far.evals;
        (reused.far, reused.near, reused.near_lights) = (far, near, near_lights);
        self.keep_reused(reused);
        Fields { irradiance, near: near_field, specular, specular_near, kept, evaluations }
    }

    /// Each VPL's interleaved ranges `(r_t², r²)` under the frame's
    /// culling ([`light_ranges`], flux × `P²`), computed once per frame for
    /// the far and the near field.
    fn ranges(&self, s: &VplSettings) -> Vec<(f32, f32)> {
        let v = &self.inputs.vpls;
        let scale = interleave_flux_scale(PERIOD);
        (0..v.len()).into_par_iter().map(|i| light_ranges(s, i, v.flux[i] * scale)).collect()
    }

    /// The far field's lights of VPL subset `sub` (`sy·P + sx`) into `all`
    /// (emptied first): its VPLs at the interleaved flux (each pixel sees
    /// 1/P² of the VPLs, so each counts P²×) with
    /// their interleaved `ranges`, in 4×4 blocks of subset texels, so each
    /// chunk of 16 consecutive lights is a small patch of the RSM
    /// (spatially coherent), and their chunk boxes.
    fn subset_lights_into(&self, all: &mut LightList, sub: usize, ranges: &[(f32, f32)]) {
        let v = &self.inputs.vpls;
        let (p, size) = (PERIOD as usize, v.size as usize);
        let (sx, sy, m) = (sub % p, sub / p, size / p);
        let scale = interleave_flux_scale(PERIOD);
        all.clear();
        for by in (0..m).step_by(4) {
            for bx in (0..m).step_by(4) {
                for (u, w) in
                    (0..16).map(|k| (bx + k % 4, by + k / 4)).filter(|&(u, w)| u < m && w < m)
                {
                    let i = (sy + w * p) * size + sx + u * p;
                    let (rt2, r2) = ranges[i];
                    all.push(v.position[i], v.normal[i], v.flux[i] * scale, rt2, r2);
                }
            }
        }
        all.build_chunks();
    }

    /// The near field's lights into `all` (emptied first): the VPLs of
    /// every subset at their own flux, in near-block order (so chunks are
    /// small RSM patches), with the ranges `cull` gives them (from the
    /// interleaved `ranges`: SLC with each VPL's own ranges and the far
    /// field's ξ, [`slc_core::interleave::vpl_near_range2`]; clamp at its
    /// range; none not at all) and their chunk boxes. Empty when
    /// `near_r2 = 0`.
    fn near_lights_into(
        &self,
        all: &mut LightList,
        ranges: &[(f32, f32)],
        near_r2: f32,
        cull: Cull,
    ) {
        all.clear();
        if near_r2 <= 0.0 {
            return;
        }
        let v = &self.inputs.vpls;
        for i in v.near_order() {
            if v.flux[i] != Vec3::ZERO {
                // The interleaved light's ranges, then the VPL's own.
                let (rt2, r2) = ranges[i];
                let (rt2, r2) = if cull.kind == CullKind::Stochastic {
                    (vpl_near_range2(rt2, PERIOD), vpl_near_range2(r2, PERIOD))
                } else {
                    (rt2, r2)
                };
                all.push_near(v.position[i], v.normal[i], v.flux[i], rt2, r2, near_r2);
            }
        }
        all.build_chunks();
    }

    /// The near field of the split ([`slc_core::interleave::vpl_near_weight`]):
    /// at every receiver of `tiling` (a [`Tiling::regions`]), the near share
    /// of the lights `all` ([`VplContext::near_lights_into`]) closer than
    /// `R_n = √near_r2`, culled as the method culls the far field (`cull`),
    /// into `r`: SLC at each VPL's own ranges
    /// ([`slc_core::interleave::vpl_near_slc_share`]: unbiased), clamp at
    /// its range, none not at all; with the kept counts and loop
    /// evaluations. Empty when `near_r2 = 0`. Culled in two levels, like
    /// the interleaved loop but over full-resolution pixels: regions cull
    /// the lights, tiles cull their region's list, each light's sphere of
    /// radius `min(r, R_n)` ([`slc_core::interleave::vpl_near_cull_range2`])
    /// against the box of the G-buffer positions.
    fn shade_near_in(
        &self,
        r: &mut PerReceiver,
        tiling: &Tiling,
        all: &LightList,
        near_r2: f32,
        cull: Cull,
    ) {
        if near_r2 <= 0.0 {
            r.clear();
            return;
        }
        let near_cull = Cull::near(cull.kind);
        let min_d2 = self.inputs.min_d2;
        r.shade_parts(tiling, |_, part, out, spec, scratch| {
            shade_part(part, all, true, near_cull, min_d2, near_r2, out, spec, &mut scratch.lists)
        });
    }
}

/// Shades the receivers of one part of a tiling with the lights of `all`
/// under `cull` into `out` (`(irradiance, kept)`) and, at its glossy
/// receivers, the specular correction into `spec` (both the part's range
/// of a per-receiver buffer); returns the loop evaluations. With
/// `cull_lists`, each group culls `all` to its box
/// ([`LightList::cull_chunked_into`]) and each tile that list to its own
/// ([`LightList::cull_into`]); without, every tile takes every light.
#[allow(clippy::too_many_arguments)]
fn shade_part(
    part: &PartTiles,
    all: &LightList,
    cull_lists: bool,
    cull: Cull,
    min_d2: f32,
    near_r2: f32,
    out: &mut [(Vec3, u32)],
    spec: &mut [Vec3],
    lists: &mut CullLists,
) -> u64 {
    let CullLists { coarse, fine, hits, shaded } = lists;
    let mut evals = 0u64;
    for group in &part.groups {
        if cull_lists {
            all.cull_chunked_into(group.lo, group.hi, hits, coarse);
        }
        for tile in &part.tiles[group.items.clone()] {
            let lights = if cull_lists {
                coarse.cull_into(tile.lo, tile.hi, hits, fine);
                &*fine
            } else {
                all
            };
            let r = tile.receivers.clone();
            shaded.clear();
            shade::shade_all(lights, &part.points[r.clone()], min_d2, near_r2, cull, shaded);
            out[r.clone()].copy_from_slice(shaded);
            for (k, g) in &part.glossy[tile.glossy.clone()] {
                spec[*k] = shade::shade_specular(lights, g, min_d2, near_r2, cull);
            }
            evals += (lights.len_unpadded() * r.len()) as u64;
        }
    }
    evals
}

/// One worker's reused memory: a part's own light list (the far field's
/// subset) and [`shade_part`]'s lists.
#[derive(Default)]
struct Scratch {
    all: LightList,
    lists: CullLists,
}

/// [`shade_part`]'s culled lists, hit indices and loop results, reused.
#[derive(Default)]
struct CullLists {
    coarse: LightList,
    fine: LightList,
    hits: Vec<u32>,
    shaded: Vec<(Vec3, u32)>,
}

/// A tiling's results per receiver ([`Tiling`]'s order): `(irradiance,
/// kept)`, the specular correction (empty without glossy pixels) and the
/// loop evaluations. Empty: nothing shaded (no near field).
#[derive(Default)]
struct PerReceiver {
    out: Vec<(Vec3, u32)>,
    spec: Vec<Vec3>,
    evals: u64,
}

impl PerReceiver {
    /// Nothing shaded.
    fn clear(&mut self) {
        self.out.clear();
        self.spec.clear();
        self.evals = 0;
    }

    /// Every part `k` of `tiling` shaded by `shade(k, part, out, spec,
    /// scratch)` in parallel (into its range of the per-receiver buffers,
    /// with a worker's reused lists; returning its loop evaluations), into
    /// this one's memory. Every receiver's `out` is written by its part;
    /// `spec` starts at zero where the tiling has glossy receivers and is
    /// empty where it has none.
    fn shade_parts(
        &mut self,
        tiling: &Tiling,
        shade: impl Fn(usize, &PartTiles, &mut [(Vec3, u32)], &mut [Vec3], &mut Scratch) -> u64
        + Sync
        + Send,
    ) {
        // Every receiver's `out` is written below: its old values need no
        // clearing (only a new size is filled).
        let n = tiling.len();
        self.out.resize(n, (Vec3::ZERO, 0));
        self.spec.clear();
        if tiling.has_glossy() {
            self.spec.resize(n, Vec3::ZERO);
        }
        self.evals = tiling
            .parts
            .par_iter()
            .zip(tiling.split(&mut self.out))
            .zip(tiling.split_glossy(&mut self.spec))
            .enumerate()
            .map_init(Scratch::default, |scratch, (k, ((part, out), spec))| {
                shade(k, part, out, spec, scratch)
            })
            .sum();
    }

    /// Pixel `i`'s `(irradiance, kept)`; zero where it has no receiver or
    /// nothing was shaded.
    fn at(&self, tiling: &Tiling, i: usize) -> (Vec3, u32) {
        match tiling.receiver(i) {
            r if r != NO_RECEIVER && !self.out.is_empty() => self.out[r as usize],
            _ => (Vec3::ZERO, 0),
        }
    }

    /// Irradiance and kept count of each of the tiling's pixels (tests).
    #[cfg(test)]
    fn per_pixel(&self, tiling: &Tiling) -> (Vec<Vec3>, Vec<u32>) {
        (0..tiling.pixels()).map(|i| self.at(tiling, i)).unzip()
    }

    /// Pixel `i`'s specular correction, zero as [`PerReceiver::at`].
    fn specular_at(&self, tiling: &Tiling, i: usize) -> Vec3 {
        match tiling.receiver(i) {
            r if r != NO_RECEIVER && !self.spec.is_empty() => self.spec[r as usize],
            _ => Vec3::ZERO,
        }
    }
}

/// The ranges `(r_t², r²)` of VPL `i`'s interleaved light (flux `flux`,
/// already × `P²`) under `s.culling`: stochastic ranges from the error
/// bound and the VPL's ξ (`xi_for(seed, frame, i)`, or `fixed_xi`), the
/// clamp range `(0, R²)`, or `(∞, ∞)` unculled.
fn light_ranges(s: &VplSettings, i: usize, flux: Vec3) -> (f32, f32) {
    match s.culling {
        Culling::Stochastic(params) => {
            let rt2 = vpl_threshold_range2(&params, flux);
            let xi = frame_xi(s.seed, s.frame, i as u32, s.fixed_xi.unwrap_or(-1.0));
            (rt2, random_range2(rt2, xi))
        }
        Culling::Clamped(r) => (0.0, r.get() * r.get()),
        Culling::None | Culling::Reference => (f32::INFINITY, f32::INFINITY),
    }
}

/// The method-independent part of a frame: G-buffer with its tilings and
/// denoise planes (unless `camera_moved` is false), VPLs (RSM) and direct light, rendered
/// into `inputs`, `geometric`, `direct` and `from_gbuffer` (memory reused at the
/// same size), with their times in the returned statistics (G-buffer 0
/// when not rendered; what is derived from it counts as G-buffer).
fn frame_inputs(
    scene: &Scene,
    geo: &Geometry,
    camera_moved: bool,
    inputs: &mut VplInputs,
    geometric: &mut Vec<Vec3>,
    direct: &mut Vec<Vec3>,
    from_gbuffer: &mut FromGBuffer,
) -> VplStats {
    let mut base = VplStats::default();
    if camera_moved {
        let t = Instant::now();
        render_gbuffer_into(scene, geo, &mut inputs.gbuffer, geometric);
        from_gbuffer.build(&inputs.gbuffer);
        base.gbuffer_ms = ms(t);
    }
    let t = Instant::now();
    rsm::reflective_shadow_map_into(scene, geo, &mut inputs.vpls);
    base.rsm_ms = ms(t);
    let t = Instant::now();
    direct_light(scene, geo, &inputs.gbuffer, geometric, direct);
    base.direct_ms = ms(t);
    base.vpls = inputs.vpls.len();
    base
}

/// What the shading of a frame's pixels returns (fields of [`Shaded`]):
/// irradiance (the near field included) and the near field alone, the
/// same two of the specular correction (empty without glossy pixels), the
/// kept counts and the loop evaluations.
#[derive(Default)]
struct Fields {
    irradiance: Vec<Vec3>,
    near: Vec<Vec3>,
    specular: Vec<Vec3>,
    specular_near: Vec<Vec3>,
    kept: Vec<u32>,
    evaluations: u64,
}

/// Region edge (pixels) of the near field's first culling level.
pub const NEAR_REGION: usize = 32;

/// Tile edge (pixels) of the near field's second culling level.
pub const NEAR_TILE: usize = 8;

/// Texels per edge of the light-space grid the primary light's shadow
/// segments are binned to (see [`Occluders`]).
const SHADOW_GRID: usize = 64;

/// Direct irradiance from the primary light into `out` (one value per
/// pixel), with shadow segments offset
/// along the geometric normal `geo_n` (cosines use the G-buffer's shading
/// normal). Every shadow segment runs along a ray of the light's map, so
/// it is tested against the triangles binned to its texel ([`Occluders`],
/// the ray caster's answer without a BVH walk), and only where the light
/// would add something (facing the light, inside a spot's cone).
fn direct_light(scene: &Scene, geo: &Geometry, gb: &GBuffer, geo_n: &[Vec3], out: &mut Vec<Vec3>) {
    let diag = scene.diagonal();
    let spot = scene.primary.spot().map(Light::Spot);
    let map = MapView {
        map: scene.primary.light_map(scene.bounds()),
        size: SHADOW_GRID,
        t_min: surface_offset(diag),
    };
    let occluders = Occluders::new(map, geo, &scene.triangles);
    let pixel = |i: usize| -> Vec3 {
        if !gb.valid(i) {
            return Vec3::ZERO;
        }
        let (x, n) = (gb.position[i], gb.normal[i]);
        let from = x + geo_n[i] * surface_offset(diag);
        match scene.primary {
            PrimaryLight::Spot { position, .. } => {
                let v = position - x;
                // A spot light's parameters are checked when the scene is.
                let Some(spot) = spot.as_ref().filter(|_| n.dot(v) > 0.0) else {
                    return Vec3::ZERO;
                };
                let e = point_irradiance(spot.intensity(-v.normalize()), n, v);
                if e == Vec3::ZERO || occluders.occluded(from, position) { Vec3::ZERO } else { e }
            }
            PrimaryLight::Directional { direction, irradiance } => {
                let wi = -direction.normalize();
                if n.dot(wi) <= 0.0 || occluders.occluded(from, x + wi * 2.0 * diag) {
                    return Vec3::ZERO;
                }
                directional_irradiance(irradiance, n, wi)
            }
        }
    };
    // In place when the buffer has the frame's size (no fresh pages).
    if out.len() == gb.position.len() {
        out.par_iter_mut().enumerate().for_each(|(i, e)| *e = pixel(i));
    } else {
        *out = (0..gb.position.len()).into_par_iter().map(pixel).collect();
    }
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

#[cfg(test)]
mod tests {
    use super::*;
    use slc_core::light::INV_PI;

    /// The near field at `tiling`'s receivers, as a frame shades it.
    fn near_field(ctx: &VplContext, tiling: &Tiling, near_r2: f32, s: &VplSettings) -> PerReceiver {
        let cull = Cull::far(s.culling.kind());
        let mut r = PerReceiver::default();
        let mut all = LightList::default();
        ctx.near_lights_into(&mut all, &ctx.ranges(s), near_r2, cull);
        ctx.shade_near_in(&mut r, tiling, &all, near_r2, cull);
        r
    }

    /// The near field's tile culling drops nothing: for every method (SLC
    /// with its own ranges, clamp, none) it equals every VPL evaluated at
    /// every pixel by the same loop without culling, for any region and
    /// tile size.
    #[test]
    fn near_field_culling_drops_nothing() {
        let ctx = VplContext::new(&Scene::cornell_box(), 16, 16, 512, None).unwrap();
        let near_r2 = 9.0 * ctx.min_d2();
        let v = ctx.vpls();
        let gb = ctx.gbuffer();
        for culling in [
            Culling::stochastic(0.002, 1.0).unwrap(),
            Culling::clamped(0.02).unwrap(),
            Culling::None,
        ] {
            let (cull, near_cull) = (Cull::far(culling.kind()), Cull::near(culling.kind()));
            let s = VplSettings { culling, ..VplSettings::default() };
            let mut all = LightList::default();
            for i in (0..v.len()).filter(|&i| v.flux[i] != Vec3::ZERO) {
                let (rt2, r2) = light_ranges(&s, i, v.flux[i] * interleave_flux_scale(PERIOD));
                let (rt2, r2) = if cull.kind == CullKind::Stochastic {
                    (vpl_near_range2(rt2, PERIOD), vpl_near_range2(r2, PERIOD))
                } else {
                    (rt2, r2)
                };
                all.push(v.position[i], v.normal[i], v.flux[i], rt2, r2);
            }
            let brute: Vec<(Vec3, u32)> = (0..gb.position.len())
                .map(|i| {
                    if gb.valid(i) {
                        shade::shade(
                            &all,
                            gb.position[i],
                            gb.normal[i],
                            ctx.min_d2(),
                            near_r2,
                            near_cull,
                        )
                    } else {
                        (Vec3::ZERO, 0)
                    }
                })
                .collect();
            assert!(
                brute.iter().map(|b| b.1).sum::<u32>() > 1000,
                "{cull:?}: the near field holds lights"
            );
            for (region, tile) in [(64, 8), (32, 8), (32, 4), (16, 16), (7, 3)] {
                let (e, kept) = near_field(&ctx, &Tiling::regions(gb, region, tile), near_r2, &s)
                    .per_pixel(&Tiling::regions(gb, region, tile));
                for i in 0..brute.len() {
                    assert_eq!(
                        kept[i], brute[i].1,
                        "{cull:?}: pixel {i}, region {region}, tile {tile}"
                    );
                    assert!(
                        (e[i] - brute[i].0).abs().max_element()
                            <= 1e-5 * brute[i].0.max_element().max(1e-3),
                        "{cull:?}: pixel {i}: {} vs {}",
                        e[i],
                        brute[i].0
                    );
                }
            }
        }
    }

    /// On the glossy box, the VPL frame shades VPL light with the whole
    /// glTF BRDF: without culling and without denoise its image equals, at
    /// every pixel, `L_e + f(l, v)·direct + Σ_v Φ_v ⊙ f(l_v, v) · T_v`
    /// (`l` toward the primary light; `f = albedo/π` on Lambertian pixels)
    /// summed here in f64 over the VPLs each method gives the pixel
    /// (Reference: all of them; None: its interleaved subset at `P²`× the
    /// flux, with and without the near-field split's share at the VPL's
    /// own flux), each pixel's material found by casting its camera ray,
    /// `f` from `Material::eval` (slc-core's BRDF). Tolerance: f32 sums of
    /// 4,096 terms. The glossy pixels' VPL light must differ from the
    /// Lambertian `albedo/π · E` (else the test would prove nothing).
    #[test]
    fn glossy_vpl_light_is_the_brdf_sum_over_vpls() {
        use slc_core::interleave::{interleave_subset, shifted_subset, vpl_near_weight};
        use slc_core::light::vpl_transfer;
        let scene = Scene::cornell_box_glossy();
        let (w, h) = (24u32, 24u32);
        let ctx = VplContext::new(&scene, w, h, 64, None).unwrap();
        let (gb, v, min_d2) = (ctx.gbuffer(), ctx.vpls(), ctx.min_d2());
        assert!(gb.has_specular());
        let size = v.size as usize;
        let scale = interleave_flux_scale(PERIOD) as f64;
        let default_near = VplSettings::default().near_r2(min_d2);
        for (culling, near_radius, near_r2) in [
            (Culling::Reference, None, 0.0),
            (Culling::None, Some(0.0), 0.0),
            (Culling::None, None, default_near),
        ] {
            let settings =
                VplSettings { culling, denoise: false, near_radius, ..VplSettings::default() };
            let shift =
                slc_core::interleave::interleave_shift(settings.seed, settings.frame, PERIOD);
            let image = ctx.render(&settings).unwrap().image;
            let (mut glossy, mut differs, mut direct_differs) = (0, 0, 0);
            for i in 0..(w * h) as usize {
                let (px, py) = (i % w as usize, i / w as usize);
                let dir = scene.camera.ray_dir(px as f32, py as f32, w, h);
                let Some(hit) = ctx.geo.intersect(scene.camera.position, dir, 0.0, f32::INFINITY)
                else {
                    assert_eq!(image.data[i], Vec3::ZERO, "pixel {i}: background");
                    continue;
                };
                let m = scene.materials[scene.material_of[hit.triangle as usize] as usize];
                let (x, n) = (gb.position[i], gb.normal[i]);
                let view = (scene.camera.position - x).normalize();
                let (mut sum, mut lambert) = (glam::DVec3::ZERO, glam::DVec3::ZERO);
                for k in 0..v.len() {
                    let class = interleave_subset(px as u32, py as u32, PERIOD);
                    let in_subset = interleave_subset((k % size) as u32, (k / size) as u32, PERIOD)
                        == shifted_subset(class, shift, PERIOD);
                    let d = x - v.position[k];
                    let near = vpl_near_weight(d.length_squared(), near_r2) as f64;
                    let share = match culling {
                        Culling::Reference => 1.0,
                        _ => near + (1.0 - near) * if in_subset { scale } else { 0.0 },
                    };
                    if share == 0.0 {
                        continue;
                    }
                    let t = vpl_transfer(v.normal[k], n, d, min_d2) as f64 * share;
                    let f = m.eval(n, view, -d.normalize()).as_dvec3();
                    sum += v.flux[k].as_dvec3() * f * t;
                    lambert += v.flux[k].as_dvec3() * (m.albedo * INV_PI).as_dvec3() * t;
                }
                // The primary light's direct term: the whole BRDF toward it.
                let f_direct = if m.has_specular() {
                    m.eval(n, view, scene.primary.direction_from(x))
                } else {
                    m.albedo * INV_PI
                };
                let base = (gb.emission[i] + f_direct * ctx.direct[i]).as_dvec3();
                let lambert_direct = (m.albedo * INV_PI * ctx.direct[i]).as_dvec3();
                let expect = base + sum;
                let got = image.data[i].as_dvec3();
                assert!(
                    (got - expect).abs().max_element() <= 2e-5 * expect.max_element() + 1e-7,
                    "{culling:?}, R_n² {near_r2}: pixel {i} ({:?}): {got} vs {expect}",
                    m
                );
                if m.has_specular() {
                    glossy += 1;
                    differs +=
                        ((sum - lambert).abs().max_element() > 0.1 * sum.max_element()) as u32;
                    let direct = base - gb.emission[i].as_dvec3();
                    direct_differs += ((direct - lambert_direct).abs().max_element()
                        > 0.1 * direct.max_element()) as u32;
                }
            }
            assert!(
                glossy > 100 && differs > glossy / 4,
                "{culling:?}: {glossy} glossy pixels, {differs} unlike Lambertian"
            );
            // The metal sphere has no diffuse lobe: its direct light is not `albedo/π · E`.
            assert!(
                direct_differs > glossy / 4,
                "{culling:?}: {glossy} glossy pixels, {direct_differs} with a direct term unlike Lambertian"
            );
        }
    }

    /// The specular correction leaves the Lambertian part alone: on the
    /// glossy box, with every method and the denoise, the irradiance, near
    /// field and kept counts are bit for bit those of the same G-buffer
    /// without its lobes (the path a Lambertian scene takes, which gives
    /// main's images byte for byte), and so is every Lambertian pixel of
    /// the image; the glossy pixels change.
    #[test]
    fn specular_correction_leaves_lambertian_pixels_bit_identical() {
        let scene = Scene::cornell_box_glossy();
        let ctx = VplContext::new(&scene, 40, 32, 64, None).unwrap();
        let mut lambert = VplContext::new(&scene, 40, 32, 64, None).unwrap();
        lambert.inputs.gbuffer.specular.clear();
        lambert.from_gbuffer.build(&lambert.inputs.gbuffer);
        let gb = ctx.gbuffer();
        for culling in
            [Culling::default(), Culling::clamped(0.1).unwrap(), Culling::None, Culling::Reference]
        {
            let s = VplSettings { culling, ..VplSettings::default() };
            let (a, b) = (ctx.shade(&s).unwrap(), lambert.shade(&s).unwrap());
            assert!(b.specular.is_empty() && !a.specular.is_empty());
            assert!(
                a.irradiance == b.irradiance && a.near == b.near && a.kept == b.kept,
                "{culling:?}"
            );
            let (ia, ib) = (ctx.finish(a, &s).image, lambert.finish(b, &s).image);
            let mut changed = 0;
            for i in 0..ia.data.len() {
                if gb.specular_at(i).is_none() {
                    assert_eq!(ia.data[i], ib.data[i], "{culling:?}: Lambertian pixel {i}");
                } else {
                    changed += (ia.data[i] != ib.data[i]) as usize;
                }
            }
            assert!(changed > 20, "{culling:?}: {changed} glossy pixels changed");
        }
    }

    /// A frame's memory kept for the next one changes no frame: a frame
    /// rendered after frames of other methods, settings and sizes of its
    /// buffers (near field off, no denoise, a frame whose `Shaded` was
    /// never finished) is bit for bit a frame of a fresh context, on the
    /// glossy box (so the specular buffers are reused too).
    #[test]
    fn reused_frame_memory_changes_no_frame() {
        let scene = Scene::cornell_box_glossy();
        let ctx = VplContext::new(&scene, 40, 32, 64, None).unwrap();
        let settings = [
            VplSettings::default(),
            VplSettings { culling: Culling::None, ..VplSettings::default() },
            VplSettings { near_radius: Some(0.0), frame: 3, ..VplSettings::default() },
            VplSettings {
                culling: Culling::clamped(0.1).unwrap(),
                denoise: false,
                ..VplSettings::default()
            },
            VplSettings { frame: 5, ..VplSettings::default() },
        ];
        let fresh: Vec<Vec<Vec3>> = settings
            .iter()
            .map(|s| {
                VplContext::new(&scene, 40, 32, 64, None).unwrap().render(s).unwrap().image.data
            })
            .collect();
        for round in 0..2 {
            let _unfinished = ctx.shade(&settings[1]).unwrap();
            for (s, expected) in settings.iter().zip(&fresh) {
                assert!(ctx.render(s).unwrap().image.data == *expected, "round {round}: {s:?}");
            }
        }
    }

    /// The culled near field is unbiased: its expectation over ξ equals the
    /// unculled near field at every pixel, by stratified quadrature through
    /// the real code (`shade_near_in` with `fixed_xi` at the midpoints of M
    /// strata). Each light's term is `w·T/p` on the ξ interval where it is
    /// kept (which ends at ξ = 1) and 0 elsewhere, so the midpoint rule
    /// misses each light by at most 2 strata of `w·T/p`: the bound is `2/M`
    /// of the near field with every light kept (ξ → 1), plus f32 summation.
    /// The error bound is chosen so that culling drops most near lights.
    #[test]
    fn culled_near_field_expectation_equals_unculled() {
        let ctx = VplContext::new(&Scene::cornell_box(), 24, 24, 256, None).unwrap();
        let near_r2 = 16.0 * ctx.min_d2();
        let s = VplSettings {
            culling: Culling::stochastic(0.02, 1.0).unwrap(),
            ..VplSettings::default()
        };
        let near = |s: &VplSettings| {
            let f = near_field(&ctx, &ctx.from_gbuffer.near, near_r2, s);
            let (e, kept) = f.per_pixel(&ctx.from_gbuffer.near);
            (e, kept, f.evals)
        };
        let (truth, truth_kept, truth_evals) = near(&VplSettings { culling: Culling::None, ..s });
        let fixed = |x: f32| near(&VplSettings { fixed_xi: Some(x), ..s });
        let all_kept = fixed(slc_core::range::Xi::MAX.get()).0;
        const M: usize = 256;
        let mut mean = vec![glam::DVec3::ZERO; truth.len()];
        let (mut kept, mut listed) = (0u64, 0u64);
        for j in 0..M {
            let (e, k, evals) = fixed((j as f32 + 0.5) / M as f32);
            for (m, v) in mean.iter_mut().zip(&e) {
                *m += v.as_dvec3() / M as f64;
            }
            kept += k.iter().map(|&k| k as u64).sum::<u64>();
            listed += evals;
        }
        let unculled = truth_kept.iter().map(|&k| k as u64).sum::<u64>() * M as u64;
        assert!(
            kept * 4 < unculled && listed < truth_evals * M as u64,
            "culling must bite: kept {kept} of {unculled}, tested {listed} of {}",
            truth_evals * M as u64
        );
        for i in 0..truth.len() {
            let t = truth[i].as_dvec3();
            let bound = all_kept[i].as_dvec3() * (2.0 / M as f64) + t.abs() * 1e-5 + 1e-12;
            for c in 0..3 {
                assert!(
                    (mean[i][c] - t[c]).abs() <= bound[c],
                    "pixel {i} channel {c}: E[culled] {} vs unculled {} (bound {})",
                    mean[i][c],
                    t[c],
                    bound[c]
                );
            }
        }
    }
}
