//! Timing a run of frames with the GPU's clock held
//! ([`GpuVplFrame::time_sequence`]): a GPU lowers its clock as soon as it
//! idles (an H100 fell from 1980 to 345 MHz between frames that waited for
//! a read-back, and every stage read 5.7× slower), so frames are timed
//! only after a continuous warm-up, back to back in one submission, and
//! their timestamps are resolved after the last one.

use super::{GpuVplFrame, Stage, StageTime};
use crate::GpuError;
use crate::passes::IndirectSettings;
use crate::timing::Timer;
use std::time::{Duration, Instant};

/// Frames a warm-up batch records before it waits for the batch before it
/// (at most two batches in flight, so the queue never runs dry).
const WARMUP_BATCH: u32 = 4;

/// A run of frames timed back to back.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameSequence {
    /// Each timed frame's passes, in order (a stage of two passes, such as
    /// the culling boxes, appears twice).
    pub frames: Vec<Vec<StageTime>>,
    /// Frames rendered in the warm-up before them.
    pub warmup_frames: u32,
    /// The warm-up's wall-clock seconds.
    pub warmup_s: f64,
}

/// One stage's time over a [`FrameSequence`]: the median, fastest and
/// slowest over its frames of the frame's total for that stage.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StageSpread {
    /// The stage.
    pub stage: Stage,
    /// Its name ([`Stage::name`]).
    pub name: &'static str,
    /// Median over the frames (ms).
    pub median_ms: f64,
    /// Fastest frame (ms).
    pub min_ms: f64,
    /// Slowest frame (ms).
    pub max_ms: f64,
}

impl FrameSequence {
    /// Every stage's spread, in the order the stages first appear.
    pub fn stages(&self) -> Vec<StageSpread> {
        let mut order: Vec<Stage> = Vec::new();
        for t in self.frames.iter().flatten() {
            if !order.contains(&t.stage) {
                order.push(t.stage);
            }
        }
        order
            .into_iter()
            .map(|stage| {
                let (median_ms, min_ms, max_ms) = self.spread(&[stage]);
                StageSpread { stage, name: stage.name(), median_ms, min_ms, max_ms }
            })
            .collect()
    }

    /// Median, fastest and slowest over the frames of each frame's summed
    /// time of `stages` (ms); every stage when `stages` is empty.
    pub fn spread(&self, stages: &[Stage]) -> (f64, f64, f64) {
        let per_frame: Vec<f64> = self
            .frames
            .iter()
            .map(|f| {
                f.iter()
                    .filter(|t| stages.is_empty() || stages.contains(&t.stage))
                    .map(|t| t.ms)
                    .sum()
            })
            .collect();
        let Some(median) = slc_scene::stats::median(&per_frame) else {
            return (0.0, 0.0, 0.0);
        };
        let (min, max) = per_frame
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| (a.min(t), b.max(t)));
        (median, min, max)
    }
}

impl GpuVplFrame {
    /// Times `frames` frames of `settings` with the GPU's clock held:
    /// frames `settings.frame`, `+1`, … are rendered continuously for at
    /// least `warmup` (batches of four, at most two in flight: the GPU
    /// never idles), then `frames` more are recorded back to back into one
    /// submission with a timestamp pair around every pass, and the
    /// timestamps are resolved and read after the last. Nothing is read
    /// back between frames: take images (the RMSE) from frames rendered
    /// apart ([`GpuVplFrame::render`]). At most `2048 / passes per frame`
    /// frames are timed (the query set's room). `None` where the frame has
    /// no timestamps (the adapter lacks them, or it is a software one and
    /// [`GpuVplFrame::use_timestamps`] was not asked).
    pub fn time_sequence(
        &mut self,
        settings: &IndirectSettings,
        warmup: Duration,
        frames: u32,
    ) -> Result<Option<FrameSequence>, GpuError> {
        if self.timer.is_none() {
            return Ok(None);
        }
        let gpu = self.gpu.clone();
        let at = |k: u32| IndirectSettings { frame: settings.frame.wrapping_add(k), ..*settings };
        let start = Instant::now();
        let (mut k, mut in_flight) = (0u32, None);
        while k == 0 || start.elapsed() < warmup {
            let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("slc warm-up"),
            });
            for _ in 0..WARMUP_BATCH {
                self.record(&mut encoder, &at(k))?;
                k += 1;
            }
            let index = gpu.queue.submit([encoder.finish()]);
            if let Some(previous) = in_flight.replace(index) {
                gpu.device
                    .poll(wgpu::PollType::Wait { submission_index: Some(previous), timeout: None })
                    .map_err(|e| GpuError::Device(e.to_string()))?;
            }
        }
        let (warmup_frames, warmup_s) = (k, start.elapsed().as_secs_f64());
        // The first timed frame, built once (building a frame advances the
        // temporal history): its passes size the query set.
        let mut first = Some(self.steps(&at(k), false)?);
        let passes = first.as_ref().map_or(0, |(_, steps)| steps.len()) as u32;
        let frames = frames.clamp(1, (2048 / passes.max(1)).max(1));
        let Some(mut timer) = Timer::new(&gpu, frames * passes) else {
            return Ok(None);
        };
        let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("slc timed frames"),
        });
        let mut stages = Vec::with_capacity(frames as usize);
        for f in 0..frames {
            let (uploads, steps) = match first.take() {
                Some(built) => built,
                None => self.steps(&at(k + f), false)?,
            };
            uploads.record(&gpu, &mut encoder);
            for step in &steps {
                self.record_step(&mut encoder, step, Some(&mut timer));
            }
            stages.push(steps.iter().map(|s| s.stage()).collect::<Vec<_>>());
        }
        timer.resolve(&mut encoder);
        gpu.queue.submit([encoder.finish()]);
        let mut ms = timer.durations_ms(&gpu)?.into_iter();
        let frames = stages
            .into_iter()
            .map(|f| {
                f.into_iter().map(|stage| StageTime::new(stage, ms.next().unwrap_or(0.0))).collect()
            })
            .collect();
        Ok(Some(FrameSequence { frames, warmup_frames, warmup_s }))
    }
}
