//! `slc bench --flicker`: how stable the VPL frame is over time. Three
//! scripted sequences (static camera and light; the camera orbiting; the
//! primary light moving through the middle third and resting before and
//! after), and per frame, for each method: the RMSE against that frame's
//! reference (every VPL at every pixel) and the temporal RMSE against the
//! method's previous frame. Methods: `slc` with the spatial filter only,
//! `slc` with temporal accumulation (the frame index walks each light's
//! stratified ξ sequence, `xi_for`), the same accumulation over
//! independent ξ (a new seed per frame: what the stratification buys),
//! and the unculled interleaved frame.
//!
//! `--backend gpu` runs the same sequences on slc-wgpu's whole frame
//! (`GpuVplFrame`, its `set_temporal` and `set_camera`), the reference
//! every VPL at every pixel of the frame's own rasterized G-buffer (as
//! `slc bench --backend gpu` does): on lavapipe a check of correctness,
//! not of speed (default 128×128, 4,096 VPLs: the reference's loop stays
//! under lavapipe's 65,535 iterations).

use super::args::{BenchArgs, progress};
use crate::backends::Backend;
use crate::report::{Curve, FlickerReport, SequenceReport};
use anyhow::{Context, anyhow};
use glam::{Quat, Vec3};
use slc_cpu::temporal::Temporal;
use slc_cpu::vpl::FrameHistory;
use slc_scene::image::Image;
use slc_scene::scene::{Camera, PrimaryLight};
use slc_scene::temporal::{TemporalSettings, TemporalView};
use slc_scene::vpl::{Culling, VplSettings};
use std::time::Instant;

/// A scripted sequence.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sequence {
    /// Nothing moves.
    Static,
    /// The camera swings ±20° about the vertical through its target.
    Orbit,
    /// The primary light moves during the middle third of the frames.
    Light,
}

impl Sequence {
    const ALL: [Sequence; 3] = [Sequence::Static, Sequence::Orbit, Sequence::Light];

    fn name(self) -> &'static str {
        match self {
            Sequence::Static => "static",
            Sequence::Orbit => "orbit",
            Sequence::Light => "light",
        }
    }

    /// The camera of frame `f` of `n`.
    fn camera(self, base: &Camera, f: u32, n: u32) -> Camera {
        if self != Sequence::Orbit {
            return *base;
        }
        let angle = 20f32.to_radians() * (std::f32::consts::TAU * f as f32 / n as f32).sin();
        let rot = Quat::from_axis_angle(Vec3::Y, angle);
        Camera {
            position: base.target + rot * (base.position - base.target),
            up: rot * base.up,
            ..*base
        }
    }

    /// Where the light is along its path in frame `f` of `n`: 0 before the
    /// middle third, 1 after it, linear in between.
    fn light_travel(self, f: u32, n: u32) -> f32 {
        if self != Sequence::Light {
            return 0.0;
        }
        let (start, end) = (n / 3, 2 * n / 3);
        ((f as f32 - start as f32) / (end - start).max(1) as f32).clamp(0.0, 1.0)
    }

    /// The primary light of frame `f` of `n`: a spot moves a fifth of the
    /// scene's diagonal sideways (its axis kept), a directional light turns
    /// by 20°.
    fn primary(self, base: &PrimaryLight, diagonal: f32, f: u32, n: u32) -> PrimaryLight {
        let t = self.light_travel(f, n);
        match *base {
            PrimaryLight::Spot { position, direction, intensity, inner, outer } => {
                let side = direction.any_orthonormal_vector();
                PrimaryLight::Spot {
                    position: position + side * (0.2 * diagonal * t),
                    direction,
                    intensity,
                    inner,
                    outer,
                }
            }
            PrimaryLight::Directional { direction, irradiance } => {
                let axis = direction.any_orthonormal_vector();
                PrimaryLight::Directional {
                    direction: Quat::from_axis_angle(axis, 20f32.to_radians() * t) * direction,
                    irradiance,
                }
            }
        }
    }
}

const SPATIAL: &str = "slc, spatial filter";
const TEMPORAL: &str = "slc, temporal";
const INDEPENDENT: &str = "slc, temporal, independent xi";
const UNCULLED: &str = "unculled, spatial filter";

/// One backend's frames for the flicker sequences: the camera and light
/// of the frame, then each method's image and the frame's reference.
trait Frames {
    /// Moves the camera and the light (only what changed: a moved light is
    /// a reported change for the temporal stage).
    fn pose(&mut self, camera: &Camera, light: &PrimaryLight) -> anyhow::Result<()>;
    /// Every VPL at every pixel.
    fn reference(&mut self) -> anyhow::Result<Image>;
    /// [spatial filter only, temporal, temporal over independent ξ,
    /// unculled] for frame `f` of SLC settings `slc` (the independent ones
    /// `fresh`).
    fn methods(&mut self, slc: &VplSettings, fresh: &VplSettings) -> anyhow::Result<Vec<Image>>;
    /// Forgets the accumulated histories (a new sequence).
    fn reset(&mut self);
    /// Milliseconds of one accumulation of a frame's irradiance at the
    /// scene's own pose (fastest of `repeat`), where the backend's clock
    /// means something (the CPU's).
    fn accumulation_ms(
        &mut self,
        camera: &Camera,
        light: &PrimaryLight,
        repeat: u32,
    ) -> anyhow::Result<Option<f64>>;
}

/// The CPU's: one context, histories per accumulated method.
struct CpuFrames {
    ctx: slc_cpu::vpl::VplContext,
    history: FrameHistory,
    independent: FrameHistory,
    ts: TemporalSettings,
}

impl Frames for CpuFrames {
    fn pose(&mut self, camera: &Camera, light: &PrimaryLight) -> anyhow::Result<()> {
        if self.ctx.scene().camera != *camera {
            self.ctx.set_camera(*camera)?;
        }
        if self.ctx.scene().primary != *light {
            self.ctx.set_primary(*light)?;
        }
        Ok(())
    }

    fn reference(&mut self) -> anyhow::Result<Image> {
        let s = VplSettings { culling: Culling::Reference, ..VplSettings::default() };
        Ok(self.ctx.render(&s)?.image)
    }

    fn methods(&mut self, slc: &VplSettings, fresh: &VplSettings) -> anyhow::Result<Vec<Image>> {
        let shaded = self.ctx.shade(slc)?;
        let spatial = self.ctx.finish(shaded.clone(), slc);
        let temporal = self.ctx.finish_accumulated(shaded, slc, &mut self.history, &self.ts)?;
        let indep = self.ctx.render_accumulated(fresh, &mut self.independent, &self.ts)?;
        let unculled = self.ctx.render(&VplSettings { culling: Culling::None, ..*slc })?;
        Ok(vec![spatial.image, temporal.image, indep.image, unculled.image])
    }

    fn reset(&mut self) {
        self.history.reset();
        self.independent.reset();
    }

    fn accumulation_ms(
        &mut self,
        camera: &Camera,
        light: &PrimaryLight,
        repeat: u32,
    ) -> anyhow::Result<Option<f64>> {
        self.pose(camera, light)?;
        let s = VplSettings::default();
        let e = self.ctx.shade(&s)?.irradiance;
        let gb = &self.ctx.inputs().gbuffer;
        let view = TemporalView::of_camera(camera, gb.width, gb.height);
        let mut t = Temporal::new(gb.width, gb.height)?;
        let mut best = f64::MAX;
        for _ in 0..repeat.max(3) {
            let t0 = Instant::now();
            t.accumulate(&e, gb, &view, &self.ts)?;
            best = best.min(t0.elapsed().as_secs_f64() * 1e3);
        }
        Ok(Some(best))
    }
}

/// The GPU's: a plain frame (spatial filter, unculled, and the reference:
/// `GpuVplFrame::render_reference`) and two accumulating ones.
struct GpuFrames {
    plain: slc_wgpu::frame::GpuVplFrame,
    accumulated: slc_wgpu::frame::GpuVplFrame,
    independent: slc_wgpu::frame::GpuVplFrame,
    pose: Option<(Camera, PrimaryLight)>,
}

impl Frames for GpuFrames {
    fn pose(&mut self, camera: &Camera, light: &PrimaryLight) -> anyhow::Result<()> {
        let (old_camera, old_light) = self.pose.map_or((None, None), |(c, l)| (Some(c), Some(l)));
        for f in [&mut self.plain, &mut self.accumulated, &mut self.independent] {
            if old_camera != Some(*camera) {
                f.set_camera(camera)?;
            }
            if old_light != Some(*light) {
                f.set_primary(light)?;
            }
        }
        self.pose = Some((*camera, *light));
        Ok(())
    }

    fn reference(&mut self) -> anyhow::Result<Image> {
        let min_distance = self.plain.min_distance();
        let all = slc_wgpu::passes::IndirectSettings { min_distance, ..Default::default() };
        Ok(self.plain.render_reference(&all)?.image)
    }

    fn methods(&mut self, slc: &VplSettings, fresh: &VplSettings) -> anyhow::Result<Vec<Image>> {
        let on = |f: &slc_wgpu::frame::GpuVplFrame, s: &VplSettings| {
            slc_wgpu::frame::indirect_settings(s, f.min_distance())
        };
        let spatial = self.plain.render(&on(&self.plain, slc)?)?.image;
        let temporal = self.accumulated.render(&on(&self.accumulated, slc)?)?.image;
        let indep = self.independent.render(&on(&self.independent, fresh)?)?.image;
        let unculled = self
            .plain
            .render(&on(&self.plain, &VplSettings { culling: Culling::None, ..*slc })?)?
            .image;
        Ok(vec![spatial, temporal, indep, unculled])
    }

    fn reset(&mut self) {
        self.accumulated.reset_temporal();
        self.independent.reset_temporal();
    }

    fn accumulation_ms(
        &mut self,
        _: &Camera,
        _: &PrimaryLight,
        _: u32,
    ) -> anyhow::Result<Option<f64>> {
        Ok(None)
    }
}

/// Runs the three sequences on the chosen backend and prints, writes and
/// plots the report.
pub fn run(a: &BenchArgs, frames: u32) -> anyhow::Result<()> {
    if frames < 2 {
        return Err(anyhow!("--frames {frames}: a flicker sequence needs at least 2 frames"));
    }
    let gpu = a.scene.backend == Backend::Gpu;
    let mut args = a.scene.clone();
    // The reference shades every VPL at every pixel every frame: a smaller
    // default image than the frame bench's (on lavapipe smaller still, and
    // few enough VPLs for its loop limit).
    let (side, vpls) = if gpu { (128, 4096) } else { (256, 65536) };
    args.width = args.width.or(Some(side));
    args.height = args.height.or(Some(side));
    args.vpls = args.vpls.or(Some(vpls));
    let r = args.resolve()?;
    let (base_camera, base_primary, diagonal) =
        (r.scene.camera, r.scene.primary, r.scene.diagonal());
    let culling = Culling::stochastic(slc_scene::culling::DEFAULT_ERROR_BOUND, r.exposure)?;
    let slc = VplSettings { culling, seed: a.seed, ..VplSettings::default() };
    let ts = TemporalSettings::default();
    let (mut runner, backend): (Box<dyn Frames>, String) = if gpu {
        let g = crate::backends::gpu_context(Backend::Gpu)?.context("no GPU context")?;
        let make = |temporal: bool| -> anyhow::Result<slc_wgpu::frame::GpuVplFrame> {
            let mut f = args.gpu_frame(&g, &r)?;
            f.set_temporal(temporal.then_some(ts))?;
            Ok(f)
        };
        let (plain, accumulated, independent) = (make(false)?, make(true)?, make(true)?);
        let backend = format!("gpu: {}", g.describe());
        (Box::new(GpuFrames { plain, accumulated, independent, pose: None }), backend)
    } else {
        let ctx = slc_cpu::vpl::VplContext::new(
            &r.scene,
            r.width,
            r.height,
            r.rsm_size,
            args.min_distance,
        )?;
        let (history, independent) =
            (FrameHistory::new(r.width, r.height)?, FrameHistory::new(r.width, r.height)?);
        let backend = format!("cpu ({} loops)", slc_cpu::simd::SimdPath::best().name());
        (Box::new(CpuFrames { ctx, history, independent, ts }), backend)
    };
    let bar = progress(Sequence::ALL.len() * frames as usize)?;
    let mut sequences = Vec::new();
    for seq in Sequence::ALL {
        runner.reset();
        let names = [SPATIAL, TEMPORAL, INDEPENDENT, UNCULLED];
        let mut curves: Vec<Curve> = names
            .iter()
            .map(|m| Curve { method: m.to_string(), rmse: Vec::new(), temporal_rmse: Vec::new() })
            .collect();
        let mut previous: Option<(Image, Vec<Image>)> = None;
        let mut reference_temporal = Vec::new();
        for f in 0..frames {
            bar.set_message(format!("{} frame {f}", seq.name()));
            runner.pose(
                &seq.camera(&base_camera, f, frames),
                &seq.primary(&base_primary, diagonal, f, frames),
            )?;
            let reference = runner.reference()?;
            let this = VplSettings { frame: f, ..slc };
            let fresh = VplSettings {
                seed: a.seed.wrapping_add(f.wrapping_mul(0x9e37_79b9)),
                frame: 0,
                ..slc
            };
            let images = runner.methods(&this, &fresh)?;
            for (c, img) in curves.iter_mut().zip(&images) {
                c.rmse.push(img.rmse(&reference));
            }
            if let Some((prev_ref, prev)) = &previous {
                reference_temporal.push(reference.rmse(prev_ref));
                for ((c, img), p) in curves.iter_mut().zip(&images).zip(prev) {
                    c.temporal_rmse.push(img.rmse(p));
                }
            }
            previous = Some((reference, images));
            bar.inc(1);
        }
        sequences.push(SequenceReport {
            sequence: seq.name().to_string(),
            reference_temporal_rmse: reference_temporal,
            curves,
        });
    }
    bar.finish_and_clear();
    // The temporal stage's own cost at this size, on the CPU.
    let temporal_ms = runner.accumulation_ms(&base_camera, &base_primary, a.repeat)?;
    let report = FlickerReport {
        backend,
        scene: r.scene.name.clone(),
        width: r.width,
        height: r.height,
        vpls: (r.rsm_size as usize).pow(2),
        frames,
        error_bound: slc_scene::culling::DEFAULT_ERROR_BOUND,
        max_history: ts.max_history,
        temporal_ms,
        sequences,
    };
    print_report(&report);
    if let Some(path) = &a.json {
        std::fs::write(path, serde_json::to_string_pretty(&report)?)
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    if let Some(plot) = &a.plot {
        crate::plot::flicker(&report, plot)?;
    }
    Ok(())
}

fn curve<'a>(s: &'a SequenceReport, method: &str) -> &'a Curve {
    s.curves.iter().find(|c| c.method == method).unwrap_or(&s.curves[0])
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

/// The summary the targets are stated in, then every curve's mean.
fn print_report(r: &FlickerReport) {
    let cost = r
        .temporal_ms
        .map_or("lavapipe and other software adapters check correctness, not speed".into(), |ms| {
            format!("temporal stage {ms:.2} ms")
        });
    println!(
        "{} {}x{}, {} VPLs, {} frames per sequence, slc eps = {}, history <= {} frames, {}; {cost}",
        r.scene, r.width, r.height, r.vpls, r.frames, r.error_bound, r.max_history, r.backend
    );
    println!(
        "{:<8} {:<32} {:>12} {:>12} {:>12}",
        "sequence", "method", "mean rmse", "last rmse", "temporal rmse"
    );
    for s in &r.sequences {
        for c in &s.curves {
            let last = c.rmse.last().copied().unwrap_or(0.0);
            println!(
                "{:<8} {:<32} {:>12.6} {:>12.6} {:>12.6}",
                s.sequence,
                c.method,
                mean(&c.rmse),
                last,
                mean(&c.temporal_rmse)
            );
        }
    }
    for s in &r.sequences {
        let (sp, te, un) = (curve(s, SPATIAL), curve(s, TEMPORAL), curve(s, UNCULLED));
        match s.sequence.as_str() {
            "static" => {
                let k = (r.frames as usize).min(32) - 1;
                println!(
                    "static: temporal RMSE {:.2}x lower with accumulation (target >= 5); error at frame {} {:.6} against the unculled frame's {:.6} (target <=), {:.6} with independent xi",
                    mean(&sp.temporal_rmse) / mean(&te.temporal_rmse).max(1e-30),
                    k + 1,
                    te.rmse[k],
                    un.rmse[k],
                    curve(s, INDEPENDENT).rmse[k]
                );
            }
            _ => {
                let worst =
                    te.rmse.iter().zip(&sp.rmse).map(|(t, s)| t / s.max(1e-30)).fold(0.0, f64::max);
                let mut line = format!(
                    "{}: accumulated error at most {worst:.2}x the spatial-only frame's (target <= 1.2)",
                    s.sequence
                );
                if s.sequence == Sequence::Light.name() {
                    let stop = (2 * r.frames / 3) as usize;
                    let back =
                        (stop..te.rmse.len()).find(|&f| te.rmse[f] <= sp.rmse[f]).map(|f| f - stop);
                    line += &match back {
                        Some(k) => format!(
                            "; below it again {k} frames after the light stops (target <= 8)"
                        ),
                        None => "; not below it again before the sequence ends".into(),
                    };
                }
                println!("{line}");
            }
        }
    }
}
