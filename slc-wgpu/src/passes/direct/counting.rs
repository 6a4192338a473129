//! The counting variant of the direct pass's kernel
//! (`Features::counters`): `direct_light` built to count every shaded
//! pixel's lights in range, lights evaluated, shadow rays and occluder BVH
//! nodes into a small buffer read back as [`DirectCounts`]
//! ([`DirectPass::count_work`]). Built at the first count, so a pass that is
//! never counted compiles nothing more, and never part of a timed frame.

use super::{DirectInputs, DirectPass, DirectSettings, Pipe};
use crate::GpuError;
use crate::kernel::{KernelLayout, check_kernels, zeroed};
use crate::passes::ViewCache;
use slc_shared_shaders::layout::{
    DIRECT_COUNT_CANDIDATES, DIRECT_COUNT_EVALUATIONS, DIRECT_COUNT_FIELDS, DIRECT_COUNT_NODES,
    DIRECT_COUNT_PIXELS, DIRECT_COUNT_RAYS,
};
use slc_shared_shaders::{Features, Kernel};

/// The counting variant of `direct_light` (`Features::counters`), shadowed
/// or not as the pass was when it was built, and its counters.
pub(super) struct Counting {
    pub(super) shadows: bool,
    pub(super) pipe: Pipe,
    pub(super) counters: wgpu::Buffer,
    staging: wgpu::Buffer,
    /// Group 1 over the pass's lights (and occluders, reuse): made again
    /// with the pass's own.
    pub(super) lights_group: wgpu::BindGroup,
    /// Group 0 by the engine's views, as the pass's own cache.
    pub(super) cache: ViewCache<Vec<wgpu::TextureView>>,
}

/// The direct pass's work in one record, summed over the shaded pixels
/// ([`DirectPass::count_work`]): what anyone can measure without a GPU.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DirectCounts {
    /// Pixels shaded (with a surface).
    pub pixels: u64,
    /// Lights in range (the candidates the BSH walk found).
    pub candidates: u64,
    /// Lights evaluated without a ray: resampled picks' candidates and
    /// the reuse's targets (0 for weighted, uniform and all picks).
    pub evaluations: u64,
    /// Shadow rays cast (0 unshadowed).
    pub rays: u64,
    /// Occluder BVH nodes the shadow rays visited.
    pub nodes: u64,
}

impl DirectCounts {
    /// `count` per shaded pixel (0 without one).
    pub fn per_pixel(&self, count: u64) -> f64 {
        count as f64 / self.pixels.max(1) as f64
    }
}

impl DirectPass {
    /// Counts the work a record of `inputs` and `settings` does
    /// ([`DirectCounts`]): the counting variant of `direct_light`, built
    /// at the first call (and again when shadows are turned on or off),
    /// recorded, submitted and read back (waits). The image it writes is
    /// the record's; it does not advance the reuse's history (the next
    /// record reuses what the last record left). Never part of a timed
    /// frame.
    pub fn count_work(
        &mut self,
        inputs: &DirectInputs,
        settings: &DirectSettings,
    ) -> Result<DirectCounts, GpuError> {
        let shadows = self.occluders.is_some();
        let bytes = u64::from(DIRECT_COUNT_FIELDS) * 8;
        if self.counting.as_ref().is_none_or(|c| c.shadows != shadows) {
            let f = Features { counters: true, shadows, ..self.features };
            check_kernels(&self.gpu, &[(Kernel::DirectLight, &f, 0)])?;
            let layout = KernelLayout::new(&self.gpu, Kernel::DirectLight, &f)?;
            let pipe = (layout.pipeline(&self.gpu, &f, None)?, layout);
            let rw = wgpu::BufferUsages::STORAGE
                | wgpu::BufferUsages::COPY_SRC
                | wgpu::BufferUsages::COPY_DST;
            let read = wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST;
            let lights_group = self.groups_for(&pipe.1).1;
            self.counting = Some(Counting {
                shadows,
                pipe,
                counters: zeroed(&self.gpu, "slc direct counters", bytes, rw),
                staging: zeroed(&self.gpu, "slc direct counters staging", bytes, read),
                lights_group,
                cache: ViewCache::new(),
            });
        }
        let mut encoder = self.gpu.device.create_command_encoder(&Default::default());
        if let Some(c) = &self.counting {
            encoder.clear_buffer(&c.counters, 0, None);
        }
        self.encode(&mut encoder, inputs, settings, true)?;
        self.gpu.queue.submit([encoder.finish()]);
        let c = self.counting.as_ref().expect("built above");
        let words: Vec<u32> = crate::kernel::read_back(&self.gpu, &c.counters, &c.staging)?;
        self.gpu.take_errors()?;
        let v = |f: u32| words[2 * f as usize] as u64 | (words[2 * f as usize + 1] as u64) << 32;
        Ok(DirectCounts {
            pixels: v(DIRECT_COUNT_PIXELS),
            candidates: v(DIRECT_COUNT_CANDIDATES),
            evaluations: v(DIRECT_COUNT_EVALUATIONS),
            rays: v(DIRECT_COUNT_RAYS),
            nodes: v(DIRECT_COUNT_NODES),
        })
    }
}
