//! Application A of the paper: real-time indirect illumination with VPLs.
//!
//! Pipeline (every step a function with a typed input and output):
//! [`render_gbuffer_into`](crate::gbuffer::render_gbuffer_into) →
//! [`rsm::reflective_shadow_map_into`] (`size²` VPLs) →
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
//!
//! | module | holds |
//! |---|---|
//! | this one | [`VplContext`]: a scene's frame, its settings in, its image and statistics out |
//! | `inputs` | the method-independent part: G-buffer (with its tilings and filter planes), RSM, direct light |
//! | `direct` | the primary light's shadowed direct term |
//! | `fields` | the shading: the reference, the interleaved far field and the near field, culled per tile |
//! | [`shade`] | the SIMD shading loop over a light list |
//! | `tiling` | the pixels' tiles and their boxes |
//! | [`denoise`] | the cross-bilateral filter |
//! | [`rsm`] | the reflective shadow map's VPLs |
//! | `reuse` | a frame's working memory kept for the next |

pub mod denoise;
mod direct;
mod fields;
mod inputs;
mod reuse;
pub mod rsm;
pub mod shade;
mod tiling;

use crate::geometry::Geometry;
use crate::temporal::Temporal;
use glam::Vec3;
use inputs::{FromGBuffer, frame_inputs};
use rayon::prelude::*;
use reuse::Reused;
use slc_scene::RenderError;
use slc_scene::image::Image;
use slc_scene::scene::{Camera, PrimaryLight, Scene};
use slc_scene::temporal::{TemporalSettings, TemporalView};
use slc_scene::vpl::{
    Culling, GBuffer, PERIOD, Shaded, VplFrame, VplInputs, VplSettings, VplStats, Vpls,
};
use std::sync::{Mutex, PoisonError};
use std::time::Instant;

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
            far_work: f.far_work,
            near_work: f.near_work,
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
        (stats.far_work, stats.near_work) = (shaded.far_work, shaded.near_work);
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
}

/// Region edge (pixels) of the near field's first culling level.
pub const NEAR_REGION: usize = 32;

/// Tile edge (pixels) of the near field's second culling level.
pub const NEAR_TILE: usize = 8;

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

#[cfg(test)]
mod tests;
