//! Application A wholly on the GPU: one command encoder per frame records
//! the camera's G-buffer and the primary light's reflective shadow map
//! and shadow map (wgpu render pipelines over the scene's triangles,
//! `scene_raster`), the
//! [`IndirectPass`] on them (VPLs from the RSM, light update with the CPU's
//! ξ, tiled SLC shading per 8×8 interleaved sub-image, cross-bilateral
//! denoise), the primary light's direct term shadowed by the shadow map
//! (`primary_direct`) and the composition `L_e + ρ/π·(E_direct +
//! E_indirect)` into an `Rgba32Float` HDR target (`frame_compose`). A
//! scene with glossy materials (a specular lobe: metals, dielectrics with
//! Fresnel reflectance) builds the pass glossy ([`IndirectPassDesc::glossy`],
//! the frame's material table and the G-buffer's material index): its
//! glossy pixels take `L_e + f(v, l)·E_direct + c_diff/π·E_indirect + S`,
//! the primary light reflected by the whole BRDF toward it and `S` the
//! VPLs' specular correction, as the CPU frame composes them. Pixels
//! come back only when asked for ([`GpuVplFrame::render`]; an engine or a
//! viewer records [`GpuVplFrame::record`] and samples
//! [`GpuVplFrame::output`]).
//!
//! The frame is built from parts, one file each: `raster.rs` (the scene on
//! the device, the three raster views, their uniforms and targets) and
//! `compose.rs` (the direct term and the composition), around the
//! [`IndirectPass`], an optional temporal stage ([`TemporalPass`]es) and
//! the stage timer. Stage times come from GPU timestamps around each
//! stage's pass where the adapter has them; otherwise (and on software
//! adapters such as lavapipe) each stage is submitted alone and timed by
//! the host's clock ([`Timing::Wall`]; [`crate::timing`]).
//!
//! ```no_run
//! use slc_scene::scene::Scene;
//! use slc_scene::vpl::VplSettings;
//! use slc_wgpu::GpuContext;
//! use slc_wgpu::frame::{FrameDesc, GpuVplFrame, indirect_settings};
//! use slc_wgpu::passes::IndirectSettings;
//!
//! let gpu = GpuContext::new()?;
//! let mut frame = GpuVplFrame::new(&gpu, &Scene::cornell_box(), &FrameDesc { width: 512, height: 512, rsm_size: 256, shadow_size: 2048, min_distance: None })?;
//! // The indirect pass's own settings, at the frame's clamp distance ...
//! let out = frame.render(&IndirectSettings { min_distance: frame.min_distance(), ..IndirectSettings::default() })?;
//! // ... or converted from the CPU frame's (refused: its reference and fixed ξ).
//! let out = frame.render(&indirect_settings(&VplSettings::default(), frame.min_distance())?)?;
//! for s in &out.stages {
//!     println!("{:>18} {:.3} ms", s.name, s.ms);
//! }
//! out.image.write_png(std::path::Path::new("frame.png"), 1.0)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod compose;
mod raster;
mod sequence;

pub use sequence::{FrameSequence, StageSpread};

use crate::kernel::check_kernels;
use crate::passes::indirect::TILE;
use crate::passes::{
    Culling, GBuffer, IndirectInputs, IndirectMaterials, IndirectPass, IndirectPassDesc,
    IndirectSettings, Surface, SurfaceDesc, TemporalInputs, TemporalPass, TemporalPassDesc,
    VplInput, VplSourceDesc,
};
use crate::record::{Dispatch, Recording, Uploads};
use crate::texture::{F32, Target, read_texture, target};
/// The stages a frame times and their times ([`crate::timing`]'s).
pub use crate::timing::{Stage, StageTime};
use crate::timing::{TIMED_PASSES, Timer};
use crate::{GpuContext, GpuError};
use compose::Compose;
use glam::Vec3;
use raster::Raster;
use slc_scene::backend::Timing;
use slc_scene::image::Image;
use slc_scene::scene::{Camera, Material, PrimaryLight, Scene};
use slc_scene::temporal::{TemporalSettings, TemporalView};
use slc_scene::vpl::{PERIOD, VplInputs, VplSettings, VplStats, WorkCounts};
use slc_shared_shaders::{Features, Kernel, LightTypes, OutputFormat};
use std::time::Instant;

/// What a [`GpuVplFrame`] is built for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameDesc {
    /// Image width (1..=16384).
    pub width: u32,
    /// Image height (1..=16384).
    pub height: u32,
    /// RSM edge: a positive multiple of 8 up to 4096 (`rsm_size²` VPLs).
    pub rsm_size: u32,
    /// Shadow-map edge (the primary light's map again, depth only, for its
    /// direct term): 1 up to the device's texture limit. The RSM's own
    /// resolution is too coarse for a wide spot's shadows.
    pub shadow_size: u32,
    /// Clamp distance of the VPL fall-off (`None`: 1% of the scene's diagonal).
    pub min_distance: Option<f32>,
}

/// The indirect pass's settings for the CPU frame's VPL settings at clamp
/// distance `min_distance` ([`GpuVplFrame::min_distance`] for a frame):
/// the same culling, seed, frame, fixed ξ, denoise and near field; the
/// reference is refused here ([`GpuVplFrame::render_reference`] renders
/// it), and the CPU's `tile` (its tile size) has no GPU counterpart.
pub fn indirect_settings(
    settings: &VplSettings,
    min_distance: f32,
) -> Result<IndirectSettings, GpuError> {
    settings.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
    if settings.culling == Culling::Reference {
        return Err(GpuError::Setting(
            "the GPU frame runs slc, clamp or none (the reference is render_reference's)".into(),
        ));
    }
    Ok(IndirectSettings {
        culling: settings.culling,
        seed: settings.seed,
        frame: settings.frame,
        fixed_xi: settings.fixed_xi,
        denoise: settings.denoise,
        min_distance,
        near_radius: settings.near_radius,
    })
}

/// A rendered frame read back.
#[derive(Clone, Debug)]
pub struct FrameRender {
    /// Final linear radiance.
    pub image: Image,
    /// Every stage's time, in order.
    pub stages: Vec<StageTime>,
    /// How the stages were timed.
    pub timing: Timing,
    /// The stage times summed into the CPU frame's categories (G-buffer:
    /// raster; RSM: raster and VPL generation; direct: shadow
    /// map and direct; shading: light update and shading; denoise: denoise,
    /// export and composition), the kept lights per shaded pixel and the
    /// VPL count. The GPU does not count loop evaluations (`evaluations`
    /// and `lights_per_pixel` are 0).
    pub stats: VplStats,
}

/// The VPL frame of one scene at one size, wholly on the GPU.
pub struct GpuVplFrame {
    gpu: GpuContext,
    desc: FrameDesc,
    /// The clamp distance the frame was built with.
    min_distance: f32,
    /// The clamp distance of the last recorded frame ([`Self::read_inputs`]).
    recorded_min_distance: f32,
    /// The scene on the device, its raster pipelines, uniforms and targets.
    raster: Raster,
    indirect: IndirectPass,
    /// The same pass built without interleaving, for
    /// [`GpuVplFrame::render_reference`] (built at its first use).
    reference: Option<IndirectPass>,
    /// The indirect pass's irradiance.
    irradiance: Target,
    /// The VPLs' specular correction (a scene with glossy materials).
    specular: Option<Target>,
    /// The direct term and the composition.
    compose: Compose,
    /// Temporal accumulation of the indirect light, when on.
    temporal: Option<FrameTemporal>,
    /// The primary light moved since the last recorded frame (a reported
    /// change for the temporal stage).
    lighting_changed: std::cell::Cell<bool>,
    /// GPU timestamps around the stages, sized for every [`Stage`] (and
    /// the glossy frame's second denoise, `TIMED_PASSES`); `None`
    /// where the frame times by the host's clock.
    timer: Option<Timer>,
    /// The stages the last timestamped recording timed, in order.
    timed_stages: Vec<Stage>,
}

impl GpuVplFrame {
    /// Validates the scene and sizes as the CPU's frame does, checks every
    /// device limit, uploads the triangles and materials, and builds the
    /// pipelines and targets.
    pub fn new(gpu: &GpuContext, scene: &Scene, desc: &FrameDesc) -> Result<Self, GpuError> {
        let min_distance = slc_scene::vpl::check_frame(
            scene,
            desc.width,
            desc.height,
            desc.rsm_size,
            desc.min_distance,
        )
        .map_err(|e| GpuError::Setting(e.to_string()))?;
        let size = (desc.width, desc.height);
        Raster::check(gpu, scene, size, desc.rsm_size, desc.shadow_size)?;
        let features = Features {
            lights: LightTypes { vpl: true, ..LightTypes::default() },
            tile_size: TILE,
            interleave: PERIOD,
            ..Features::default()
        };
        // Glossy materials: the indirect pass's and the composition's glossy kernels.
        let glossy = scene.materials.iter().any(Material::has_specular);
        let compose_features =
            Features { output_format: OutputFormat::Rgba32Float, glossy, ..features };
        check_kernels(
            gpu,
            &[
                (Kernel::SceneRaster, &features, 0),
                (Kernel::PrimaryDirect, &features, 0),
                (Kernel::FrameCompose, &compose_features, 0),
            ],
        )?;
        let indirect_desc = IndirectPassDesc {
            surface: SurfaceDesc::Position,
            output_format: F32,
            glossy,
            ..IndirectPassDesc::new(size.0, size.1, VplSourceDesc::Rsm { size: desc.rsm_size })
        };
        // The indirect pass checks its own limits before it creates
        // anything; built first, so that no raster pipeline precedes them.
        let indirect = IndirectPass::new(gpu, &indirect_desc)?;
        let raster = Raster::new(gpu, scene, size, desc.rsm_size, desc.shadow_size, &features)?;
        let irradiance = indirect_target(gpu, "slc frame irradiance", size);
        let specular = glossy.then(|| indirect_target(gpu, "slc frame specular", size));
        let features = (&features, &compose_features);
        let compose = Compose::new(gpu, &raster, features, &irradiance, specular.as_ref())?;
        let s = GpuVplFrame {
            gpu: gpu.clone(),
            desc: *desc,
            min_distance,
            recorded_min_distance: min_distance,
            raster,
            indirect,
            reference: None,
            irradiance,
            specular,
            compose,
            temporal: None,
            lighting_changed: std::cell::Cell::new(false),
            // A software adapter's timestamps do not bracket the work its
            // worker threads do (lavapipe reports microseconds for
            // 10⁸-evaluation dispatches): time it by the clock instead.
            timer: if gpu.adapter.device_type == wgpu::DeviceType::Cpu {
                None
            } else {
                Timer::new(gpu, TIMED_PASSES)
            },
            timed_stages: Vec::new(),
        };
        gpu.take_errors()?;
        Ok(s)
    }

    /// The descriptor the frame was built for.
    pub fn desc(&self) -> &FrameDesc {
        &self.desc
    }

    /// The clamp distance of the VPL fall-off the frame was built with
    /// ([`FrameDesc::min_distance`], or 1% of the scene's diagonal): the
    /// CPU frame's, for [`IndirectSettings::min_distance`].
    pub fn min_distance(&self) -> f32 {
        self.min_distance
    }

    /// The HDR target (`Rgba32Float`, `TEXTURE_BINDING | STORAGE_BINDING |
    /// COPY_SRC`): radiance, alpha 1, after the recorded frame.
    pub fn output(&self) -> &wgpu::Texture {
        &self.compose.output.texture
    }

    /// Moves or changes the primary light (a viewer animating it, an
    /// engine's sun): rewrites the RSM's and the shadow map's uniforms, so
    /// the next recorded frame renders with it. The light is checked as
    /// the scene's is ([`PrimaryLight::validate`]).
    pub fn set_primary(&self, primary: &PrimaryLight) -> Result<(), GpuError> {
        primary.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
        self.raster.set_primary(&self.gpu, primary);
        self.lighting_changed.set(true);
        Ok(())
    }

    /// Moves the camera (a viewer flying, an engine's view): rewrites the
    /// G-buffer's raster uniforms and the eye, so the next recorded frame
    /// renders from it. The camera is checked as the scene's is
    /// ([`Camera::validate`]).
    pub fn set_camera(&mut self, camera: &Camera) -> Result<(), GpuError> {
        camera.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
        self.raster.set_camera(&self.gpu, camera);
        Ok(())
    }

    /// The camera the next frame renders from.
    pub fn camera(&self) -> &Camera {
        self.raster.camera()
    }

    /// Turns temporal accumulation of the indirect light on (with
    /// `settings`) or off (`None`): the filtered irradiance (and on glossy
    /// pixels the specular correction) goes through a [`TemporalPass`]
    /// before the composition, reprojected with the camera's motion
    /// ([`GpuVplFrame::set_camera`]); a moved primary light
    /// ([`GpuVplFrame::set_primary`]) is a reported change
    /// ([`TemporalSettings::after_change`]). Turning it on builds the
    /// passes and targets (once); the history starts empty.
    pub fn set_temporal(&mut self, settings: Option<TemporalSettings>) -> Result<(), GpuError> {
        let Some(settings) = settings else {
            self.temporal = None;
            return Ok(());
        };
        settings.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
        if let Some(t) = &mut self.temporal {
            t.settings = settings;
            return Ok(());
        }
        let gpu = &self.gpu;
        let (w, h) = (self.desc.width, self.desc.height);
        let desc = TemporalPassDesc { output_format: F32, ..TemporalPassDesc::new(w, h) };
        let irradiance = (
            TemporalPass::new(gpu, &desc)?,
            indirect_target(gpu, "slc frame accumulated irradiance", (w, h)),
        );
        let specular = match self.specular {
            Some(_) => Some((
                TemporalPass::new(gpu, &desc)?,
                indirect_target(gpu, "slc frame accumulated specular", (w, h)),
            )),
            None => None,
        };
        let compose_group =
            self.compose.group(gpu, &self.raster, &irradiance.1, specular.as_ref().map(|s| &s.1));
        self.lighting_changed.set(false);
        self.temporal = Some(FrameTemporal { settings, irradiance, specular, compose_group });
        Ok(())
    }

    /// Forgets the temporal history (a cut); nothing when accumulation is off.
    pub fn reset_temporal(&mut self) {
        if let Some(t) = &mut self.temporal {
            t.irradiance.0.reset();
            if let Some(s) = &mut t.specular {
                s.0.reset();
            }
        }
    }

    /// Whether stages are timed by GPU timestamps. A software adapter's
    /// timestamps do not bracket its worker threads' work, so the frame
    /// times it by the host's clock unless `on` asks for timestamps anyway
    /// (their values then mean little; the test of the timestamp path runs
    /// on lavapipe this way). Returns whether timestamps are now used:
    /// never without the device's `TIMESTAMP_QUERY`.
    pub fn use_timestamps(&mut self, on: bool) -> bool {
        self.timer = if on { Timer::new(&self.gpu, TIMED_PASSES) } else { None };
        self.timed_stages.clear();
        self.timer.is_some()
    }

    /// [`GpuVplFrame::record`] with a GPU timestamp around every stage
    /// where the adapter has usable ones (not on software adapters, unless
    /// [`GpuVplFrame::use_timestamps`]); read them with
    /// [`GpuVplFrame::stage_times`] once the encoder's commands are
    /// submitted. Returns whether the stages are timed.
    pub fn record_timed(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        settings: &IndirectSettings,
    ) -> Result<bool, GpuError> {
        let (uploads, steps) = self.steps(settings, false)?;
        uploads.record(&self.gpu, encoder);
        let mut timer = self.timer.take();
        match timer.as_mut() {
            Some(t) => self.record_with_timestamps(encoder, &steps, t),
            None => {
                for step in &steps {
                    self.record_step(encoder, step, None);
                }
            }
        }
        let timed = timer.is_some();
        self.timer = timer;
        Ok(timed)
    }

    /// Records `steps` with a timestamp pair around each, resolves the
    /// queries and remembers the stages for [`GpuVplFrame::stage_times`].
    fn record_with_timestamps(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        steps: &[Step],
        t: &mut Timer,
    ) {
        t.reset();
        for step in steps {
            self.record_step(encoder, step, Some(t));
        }
        t.resolve(encoder);
        self.timed_stages = steps.iter().map(Step::stage).collect();
    }

    /// Every stage's GPU time of the last frame recorded with timestamps
    /// (waits for it to finish), in order, each stage with its own
    /// duration; `None` where the frame does not use timestamps or no frame
    /// was timed yet.
    pub fn stage_times(&self) -> Result<Option<Vec<StageTime>>, GpuError> {
        let Some(t) = self.timer.as_ref().filter(|_| !self.timed_stages.is_empty()) else {
            return Ok(None);
        };
        let ms = t.durations_ms(&self.gpu)?;
        if ms.len() != self.timed_stages.len() {
            return Err(GpuError::Device(format!(
                "{} timestamp pairs for {} stages",
                ms.len(),
                self.timed_stages.len()
            )));
        }
        Ok(Some(
            self.timed_stages
                .iter()
                .zip(ms)
                .map(|(&stage, ms)| StageTime::new(stage, ms))
                .collect(),
        ))
    }

    /// The frame's uniforms (recorded first) and its steps for `st`, each
    /// recordable on its own; with `reference`, the reference's steps
    /// ([`GpuVplFrame::render_reference`]).
    fn steps(
        &mut self,
        st: &IndirectSettings,
        reference: bool,
    ) -> Result<(Uploads, Vec<Step>), GpuError> {
        let st = &if reference {
            if self.reference.is_none() {
                let desc = IndirectPassDesc { interleaved: false, ..*self.indirect.desc() };
                self.reference = Some(IndirectPass::new(&self.gpu, &desc)?);
            }
            st.reference()
        } else {
            *st
        };
        let pass = match (reference, self.reference.as_mut()) {
            (true, Some(r)) => r,
            _ => &mut self.indirect,
        };
        let inputs = frame_inputs(&self.raster, &self.irradiance, self.specular.as_ref());
        let Recording { mut uploads, dispatches: indirect } =
            pass.dispatches(&inputs, st, false)?;
        self.recorded_min_distance = st.min_distance;
        let mut steps = vec![
            Step::Raster(Stage::GBuffer),
            Step::Raster(Stage::Rsm),
            Step::Raster(Stage::ShadowMap),
        ];
        steps.extend(indirect.into_iter().map(Step::Compute));
        let mut compose = None;
        if let Some(t) = self.temporal.as_mut().filter(|_| !reference) {
            let (camera, (w, h)) = (self.raster.camera(), self.raster.size());
            let view = TemporalView::of_camera(camera, w, h);
            let ts =
                if self.lighting_changed.take() { t.settings.after_change() } else { t.settings };
            let (pass, out) = &mut t.irradiance;
            let signal = TemporalInputs::new(inputs.gbuffer, &self.irradiance.view, &out.view);
            let (up, d) = pass.dispatch(&signal, &view, &ts)?;
            uploads.append(up);
            steps.push(Step::Compute(d));
            if let (Some((pass, out)), Some(sp)) = (&mut t.specular, &self.specular) {
                let signal = TemporalInputs::new(inputs.gbuffer, &sp.view, &out.view);
                let (up, d) = pass.dispatch(&signal, &view, &ts)?;
                uploads.append(up);
                steps.push(Step::Compute(d));
            }
            compose = Some(t.compose_group.clone());
        }
        steps.extend(self.compose.dispatches(compose).map(Step::Compute));
        Ok((uploads, steps))
    }

    /// Records `step` into `encoder`, with a timestamp pair from `timer`.
    fn record_step(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        step: &Step,
        timer: Option<&mut Timer>,
    ) {
        match step {
            Step::Compute(d) => {
                let timestamp_writes = timer.and_then(|t| t.next());
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some(d.stage.name()),
                    timestamp_writes,
                });
                d.record(&mut pass);
            }
            Step::Raster(stage) => {
                self.raster.record(encoder, *stage, timer.and_then(|t| t.next_render()))
            }
        }
    }

    /// Records the whole frame into `encoder` (render and compute passes;
    /// nothing is submitted or read back) with the indirect pass's
    /// `settings` (every one of them honoured).
    pub fn record(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        settings: &IndirectSettings,
    ) -> Result<(), GpuError> {
        let (uploads, steps) = self.steps(settings, false)?;
        uploads.record(&self.gpu, encoder);
        for step in &steps {
            self.record_step(encoder, step, None);
        }
        Ok(())
    }

    /// Renders one frame in one command encoder, reads the image back and
    /// times every stage (GPU timestamps, else each stage submitted alone
    /// under the host clock).
    pub fn render(&mut self, settings: &IndirectSettings) -> Result<FrameRender, GpuError> {
        let (uploads, steps) = self.steps(settings, false)?;
        self.run(uploads, steps)
    }

    /// The frame's reference, rendered as [`GpuVplFrame::render`] renders
    /// a frame: every VPL at every pixel of the frame's own G-buffer and
    /// RSM (an [`IndirectPass`] built with `interleaved: false` at the
    /// first call, recorded unculled, undenoised, without the near-field
    /// split: [`IndirectPassDesc::interleaved`]), composed with the
    /// frame's direct light by its own composition; no temporal stage. Of
    /// `settings` only the clamp distance matters (seed and frame choose
    /// nothing in an unculled, uninterleaved frame); its culling, fixed ξ,
    /// denoise and near radius are the reference's.
    pub fn render_reference(
        &mut self,
        settings: &IndirectSettings,
    ) -> Result<FrameRender, GpuError> {
        let (uploads, steps) = self.steps(settings, true)?;
        self.run(uploads, steps)
    }

    /// Submits `uploads` and `steps`, times every stage and reads the
    /// image back.
    fn run(&mut self, uploads: Uploads, steps: Vec<Step>) -> Result<FrameRender, GpuError> {
        let gpu = self.gpu.clone();
        let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("slc frame uniforms"),
        });
        uploads.record(&gpu, &mut encoder);
        gpu.queue.submit([encoder.finish()]);
        let mut times = Vec::with_capacity(steps.len());
        let mut timer = self.timer.take();
        let timing = match timer.as_mut() {
            Some(t) => {
                let mut encoder =
                    gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                        label: Some("slc frame"),
                    });
                self.record_with_timestamps(&mut encoder, &steps, t);
                gpu.queue.submit([encoder.finish()]);
                gpu.wait()?;
                let ms = t.durations_ms(&gpu)?;
                times.extend(
                    steps.iter().zip(ms).map(|(step, ms)| StageTime::new(step.stage(), ms)),
                );
                Timing::GpuTimestamps
            }
            None => {
                gpu.wait()?;
                for step in &steps {
                    let t0 = Instant::now();
                    let mut encoder =
                        gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                            label: Some(step.stage().name()),
                        });
                    self.record_step(&mut encoder, step, None);
                    gpu.queue.submit([encoder.finish()]);
                    gpu.wait()?;
                    times.push(StageTime::new(step.stage(), t0.elapsed().as_secs_f64() * 1e3));
                }
                Timing::Wall
            }
        };
        self.timer = timer;
        let (w, h) = (self.desc.width, self.desc.height);
        let radiance = read_texture(&gpu, &self.compose.output.texture)?;
        let irradiance = read_texture(&gpu, &self.irradiance.texture)?;
        let positions = read_texture(&gpu, &self.raster.gbuffer.colors[0].texture)?;
        let image = Image {
            width: w,
            height: h,
            data: radiance.iter().map(|p| Vec3::new(p[0], p[1], p[2])).collect(),
        };
        let shaded = positions.iter().filter(|p| p[3] > 0.0).count().max(1) as f64;
        let sum = |stages: &[Stage]| {
            times.iter().filter(|t| stages.contains(&t.stage)).map(|t| t.ms).sum::<f64>()
        };
        let stats = VplStats {
            gbuffer_ms: sum(&[Stage::GBuffer]),
            // The CPU's "direct" includes its shadow rays.
            direct_ms: sum(&[Stage::ShadowMap, Stage::Direct]),
            rsm_ms: sum(&[Stage::Rsm, Stage::VplGeneration]),
            shading_ms: sum(&Stage::SHADING),
            denoise_ms: sum(&[
                Stage::Denoise,
                Stage::IrradianceExport,
                Stage::Temporal,
                Stage::Composition,
            ]),
            total_ms: times.iter().map(|t| t.ms).sum(),
            vpls: (self.desc.rsm_size as usize).pow(2),
            lights_per_pixel: 0.0,
            kept_per_pixel: irradiance
                .iter()
                .zip(&positions)
                .filter(|(_, p)| p[3] > 0.0)
                .map(|(e, _)| e[3] as f64)
                .sum::<f64>()
                / shaded,
            evaluations: 0,
            ..VplStats::default()
        };
        Ok(FrameRender { image, stages: times, timing, stats })
    }

    /// The G-buffer and VPLs the last frame rasterized, read back as the
    /// backend-neutral [`VplInputs`] (to shade them with another backend,
    /// or to compare with the CPU's ray-cast ones), with the last frame's
    /// clamp distance. Depth is the distance from the eye.
    pub fn read_inputs(&self) -> Result<VplInputs, GpuError> {
        self.raster.read_inputs(&self.gpu, self.recorded_min_distance)
    }

    /// The primary light's direct irradiance of the last frame, per pixel.
    pub fn read_direct(&self) -> Result<Vec<Vec3>, GpuError> {
        self.compose.read_direct(&self.gpu)
    }

    /// The culling work of a frame of `settings`, far field then near
    /// field (slc-scene's [`WorkCounts`]): the frame's G-buffer and RSM
    /// rasterized, then its indirect pass recorded with counting kernels
    /// ([`IndirectPass::count_work`]). Never timed; nothing is composed.
    pub fn count_work(
        &mut self,
        settings: &IndirectSettings,
    ) -> Result<(WorkCounts, WorkCounts), GpuError> {
        let mut encoder = self.gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("slc frame inputs"),
        });
        for stage in [Stage::GBuffer, Stage::Rsm] {
            self.raster.record(&mut encoder, stage, None);
        }
        self.gpu.queue.submit([encoder.finish()]);
        let inputs = frame_inputs(&self.raster, &self.irradiance, self.specular.as_ref());
        self.indirect.count_work(&inputs, settings)
    }
}

/// The indirect pass's inputs in a frame: the rasterized G-buffer and RSM,
/// the frame's irradiance target and, in a glossy frame, its material
/// table and specular target.
fn frame_inputs<'a>(
    raster: &'a Raster,
    irradiance: &'a Target,
    specular: Option<&'a Target>,
) -> IndirectInputs<'a> {
    let (gb, rsm) = (&raster.gbuffer.colors, &raster.rsm.colors);
    IndirectInputs {
        gbuffer: GBuffer {
            surface: Surface::Position(&gb[0].view),
            normal: &gb[1].view,
            eye: raster.camera().position,
        },
        vpls: VplInput::Rsm { position: &rsm[0].view, normal: &rsm[1].view, flux: &rsm[2].view },
        output: &irradiance.view,
        materials: specular
            .map(|sp| IndirectMaterials { table: &raster.material_table, specular: &sp.view }),
    }
}

/// The frame's temporal stage: its settings, a pass and an output per
/// accumulated signal (irradiance; the glossy frame's specular
/// correction), and the composition's bind group reading the outputs.
struct FrameTemporal {
    settings: TemporalSettings,
    irradiance: (TemporalPass, Target),
    specular: Option<(TemporalPass, Target)>,
    compose_group: wgpu::BindGroup,
}

/// An `Rgba32Float` target of the indirect light (the indirect pass's or
/// the temporal stage's output), sampled by the composition.
fn indirect_target(gpu: &GpuContext, label: &str, size: (u32, u32)) -> Target {
    let usage = wgpu::TextureUsages::STORAGE_BINDING
        | wgpu::TextureUsages::TEXTURE_BINDING
        | wgpu::TextureUsages::COPY_SRC;
    target(gpu, label, size, F32, usage)
}

/// A step of the frame: a raster pass (G-buffer, RSM or shadow map) or a
/// compute dispatch.
enum Step {
    Raster(Stage),
    Compute(Dispatch),
}

impl Step {
    /// The stage the step belongs to.
    fn stage(&self) -> Stage {
        match self {
            Step::Raster(s) => *s,
            Step::Compute(d) => d.stage,
        }
    }
}
