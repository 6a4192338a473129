//! How slc-wgpu times its work: the frame's [`Stage`]s, a [`StageTime`]
//! per stage, and the crate's GPU timestamp timer (`Timer`, the frame's and
//! the path tracer's).
//!
//! **Contract**: a rendered frame (`GpuVplFrame::render`, or
//! `GpuVplFrame::stage_times` after a timed record) reports one
//! [`StageTime`] per stage it ran, in the order it ran them: a subset of
//! [`Stage::ALL`] (`light update` with SLC only, `denoise`, `near field`
//! and `temporal` when asked for), the glossy frame's second denoise and
//! temporal accumulation (the specular correction's) each with a time of
//! its own. Each time is the stage's own duration, never a running total.
//!
//! **How**: where the adapter has usable GPU timestamps, a timestamp pair
//! brackets each stage's render or compute pass
//! ([`Timing::GpuTimestamps`](slc_scene::backend::Timing::GpuTimestamps)).
//! Elsewhere, and on software adapters such as lavapipe (whose timestamps
//! do not bracket the work of their worker threads), each stage is
//! submitted alone and timed by the host's wall clock
//! ([`Timing::Wall`](slc_scene::backend::Timing::Wall)).

use crate::kernel::{read_back, zeroed};
use crate::{GpuContext, GpuError};

/// The frame's stages, in the order a frame runs them (a frame runs a
/// subset: `light update` with SLC only, `denoise` and `near field` when
/// asked for).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    /// The camera's G-buffer (raster).
    GBuffer,
    /// The primary light's reflective shadow map (raster).
    Rsm,
    /// The primary light's shadow map (raster).
    ShadowMap,
    /// VPLs from the RSM.
    VplGeneration,
    /// Random ranges from ξ.
    LightUpdate,
    /// The boxes of the VPL culling hierarchies (`vpl_clusters`,
    /// `vpl_groups`), from the frame's ranges.
    Bounds,
    /// Tiled SLC shading of the interleaved sub-images.
    Shading,
    /// The cross-bilateral filter (twice in a glossy frame: the
    /// irradiance, then the specular correction).
    Denoise,
    /// The near field of the VPL split.
    NearField,
    /// The irradiance into the frame's texture.
    IrradianceExport,
    /// Temporal accumulation of the irradiance (when asked for).
    Temporal,
    /// The primary light's shadowed direct term.
    Direct,
    /// Direct plus indirect light into the HDR target.
    Composition,
}

impl Stage {
    /// Every stage, in order: the timer holds a timestamp pair for each.
    pub const ALL: [Stage; 13] = [
        Stage::GBuffer,
        Stage::Rsm,
        Stage::ShadowMap,
        Stage::VplGeneration,
        Stage::LightUpdate,
        Stage::Bounds,
        Stage::Shading,
        Stage::Denoise,
        Stage::NearField,
        Stage::IrradianceExport,
        Stage::Temporal,
        Stage::Direct,
        Stage::Composition,
    ];

    /// The stages a frame's VPL shading time sums (`VplStats::shading_ms`):
    /// the light update, the culling boxes, the far and the near field.
    pub const SHADING: [Stage; 4] =
        [Stage::LightUpdate, Stage::Bounds, Stage::Shading, Stage::NearField];

    /// The stage's name as reports print it.
    pub fn name(self) -> &'static str {
        match self {
            Stage::GBuffer => "G-buffer",
            Stage::Rsm => "RSM",
            Stage::ShadowMap => "shadow map",
            Stage::VplGeneration => "VPL generation",
            Stage::LightUpdate => "light update",
            Stage::Bounds => "culling boxes",
            Stage::Shading => "shading",
            Stage::Denoise => "denoise",
            Stage::NearField => "near field",
            Stage::IrradianceExport => "irradiance export",
            Stage::Temporal => "temporal",
            Stage::Direct => "direct",
            Stage::Composition => "composition",
        }
    }
}

/// Timestamp pairs a frame's timer holds: one per stage, one more for the
/// culling boxes' second dispatch (`vpl_groups` after `vpl_clusters`), and
/// two more for the glossy frame's second denoise and second temporal
/// accumulation (the specular correction's).
pub(crate) const TIMED_PASSES: u32 = Stage::ALL.len() as u32 + 3;

/// One stage's time.
#[derive(Clone, Debug, PartialEq)]
pub struct StageTime {
    /// The stage.
    pub stage: Stage,
    /// Its name ([`Stage::name`]).
    pub name: &'static str,
    /// Milliseconds.
    pub ms: f64,
}

impl StageTime {
    /// `ms` milliseconds of `stage`.
    pub(crate) fn new(stage: Stage, ms: f64) -> StageTime {
        StageTime { stage, name: stage.name(), ms }
    }
}

/// GPU timestamps around compute and render passes, where the adapter
/// supports them: a timestamp pair per timed pass.
pub(crate) struct Timer {
    queries: wgpu::QuerySet,
    resolve: wgpu::Buffer,
    staging: wgpu::Buffer,
    capacity: u32,
    used: u32,
}

impl Timer {
    /// Room for `passes` timed passes (two queries each); `None` without
    /// timestamp support.
    pub(crate) fn new(gpu: &GpuContext, passes: u32) -> Option<Timer> {
        if !gpu.timestamps {
            return None;
        }
        let capacity = passes.clamp(1, 2048);
        let queries = gpu.device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("slc timer"),
            ty: wgpu::QueryType::Timestamp,
            count: 2 * capacity,
        });
        let size = 16 * capacity as u64;
        let resolve = zeroed(
            gpu,
            "timer resolve",
            size,
            wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
        );
        let staging = zeroed(
            gpu,
            "timer staging",
            size,
            wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        );
        Some(Timer { queries, resolve, staging, capacity, used: 0 })
    }

    /// Timestamp writes for the next pass (none once full).
    pub(crate) fn next(&mut self) -> Option<wgpu::ComputePassTimestampWrites<'_>> {
        if self.used >= self.capacity {
            return None;
        }
        let i = self.used;
        self.used += 1;
        Some(wgpu::ComputePassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(2 * i),
            end_of_pass_write_index: Some(2 * i + 1),
        })
    }

    /// Timestamp writes for the next render pass (none once full).
    pub(crate) fn next_render(&mut self) -> Option<wgpu::RenderPassTimestampWrites<'_>> {
        let w = self.next()?;
        Some(wgpu::RenderPassTimestampWrites {
            query_set: w.query_set,
            beginning_of_pass_write_index: w.beginning_of_pass_write_index,
            end_of_pass_write_index: w.end_of_pass_write_index,
        })
    }

    /// Starts over at the first query (the next frame).
    pub(crate) fn reset(&mut self) {
        self.used = 0;
    }

    /// Resolves the queries written so far into the resolve buffer.
    pub(crate) fn resolve(&self, enc: &mut wgpu::CommandEncoder) {
        if self.used > 0 {
            enc.resolve_query_set(&self.queries, 0..2 * self.used, &self.resolve, 0);
        }
    }

    /// Each timed pass's GPU duration in ms (after [`Timer::resolve`] was
    /// submitted).
    pub(crate) fn durations_ms(&self, gpu: &GpuContext) -> Result<Vec<f64>, GpuError> {
        let ticks: Vec<u64> = read_back(gpu, &self.resolve, &self.staging)?;
        let period = gpu.queue.get_timestamp_period() as f64;
        Ok(ticks
            .chunks(2)
            .take(self.used as usize)
            .map(|p| p[1].saturating_sub(p[0]) as f64 * period * 1e-6)
            .collect())
    }

    /// Sum of the timed passes' GPU durations in ms.
    pub(crate) fn total_ms(&self, gpu: &GpuContext) -> Result<f64, GpuError> {
        Ok(self.durations_ms(gpu)?.iter().sum())
    }
}
