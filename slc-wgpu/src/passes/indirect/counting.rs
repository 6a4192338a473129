//! The counting variant of the indirect pass's culled kernels
//! (`Features::counters`): `vpl_tiled` and `vpl_near` built to count every
//! group, cluster and sphere test, every light a pixel loops over and
//! every light it keeps, per field, into two small buffers read back as
//! slc-scene's [`WorkCounts`] ([`super::IndirectPass::count_work`]). Built
//! at the first count, so a pass that is never counted compiles nothing
//! more, and never part of a timed frame.

use super::Pipe;
use crate::kernel::{KernelLayout, zeroed};
use crate::passes::ViewCache;
use crate::{GpuContext, GpuError};
use slc_scene::vpl::WorkCounts;
use slc_shared_shaders::layout::{
    COUNT_CLUSTER_TESTS, COUNT_FIELDS, COUNT_GROUP_TESTS, COUNT_KEPT, COUNT_PIXELS,
    COUNT_SPHERE_TESTS, COUNT_TESTED, COUNT_TILES,
};
use slc_shared_shaders::{CullKind, Features, Kernel};

/// Fields of `WorkCounts` the kernels count (the layout's `COUNT_*`);
/// each a 64-bit (low, high) pair of `u32`s.
const FIELDS: usize = COUNT_FIELDS as usize;
/// Bytes of one field's counters.
const BYTES: u64 = (FIELDS * 2 * 4) as u64;

/// The counting kernels, their counters and their G-buffer bind groups.
pub(super) struct Counting {
    pub(super) tiled_layout: KernelLayout,
    pub(super) near_layout: KernelLayout,
    /// `vpl_tiled` per culling kind.
    pub(super) tiled: Vec<(CullKind, wgpu::ComputePipeline)>,
    /// `vpl_near` per culling kind.
    pub(super) near: Vec<(CullKind, wgpu::ComputePipeline)>,
    /// The far field's counters, then the near field's.
    pub(super) counters: [wgpu::Buffer; 2],
    /// Both fields' counters, mapped for reading.
    staging: wgpu::Buffer,
    /// `vpl_tiled` and `vpl_near` (raw, denoised) groups, keyed by the
    /// surface and normal views.
    pub(super) groups: ViewCache<(wgpu::TextureView, wgpu::TextureView), CountGroups>,
}

/// The counting kernels' bind groups for one pair of G-buffer views.
#[derive(Clone)]
pub(super) struct CountGroups {
    pub(super) tiled: wgpu::BindGroup,
    /// Adding to the raw irradiance (0) or the denoised one (1).
    pub(super) near: [wgpu::BindGroup; 2],
}

impl Counting {
    /// The counting variants of `base` (the pass's features; counted
    /// Lambertian, as the counts do not depend on the material).
    pub(super) fn new(gpu: &GpuContext, base: &Features) -> Result<Counting, GpuError> {
        let f = Features { counters: true, glossy: false, ..*base };
        let tiled_layout = KernelLayout::new(gpu, Kernel::VplTiled, &f)?;
        let near_layout = KernelLayout::new(gpu, Kernel::VplNear, &f)?;
        let (mut tiled, mut near) = (Vec::new(), Vec::new());
        for m in CullKind::ALL {
            let fm = Features { method: m, ..f };
            tiled.push((m, tiled_layout.pipeline(gpu, &fm, None)?));
            near.push((m, near_layout.pipeline(gpu, &fm, None)?));
        }
        let rw = wgpu::BufferUsages::STORAGE
            | wgpu::BufferUsages::COPY_SRC
            | wgpu::BufferUsages::COPY_DST;
        let counters = [
            zeroed(gpu, "slc far counters", BYTES, rw),
            zeroed(gpu, "slc near counters", BYTES, rw),
        ];
        let staging = zeroed(
            gpu,
            "slc counters staging",
            2 * BYTES,
            wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        );
        gpu.take_errors()?;
        Ok(Counting {
            tiled_layout,
            near_layout,
            tiled,
            near,
            counters,
            staging,
            groups: ViewCache::new(),
        })
    }

    /// Clears both fields' counters (before the counted record).
    pub(super) fn clear(&self, encoder: &mut wgpu::CommandEncoder) {
        for c in &self.counters {
            encoder.clear_buffer(c, 0, None);
        }
    }

    /// Copies the counters for [`Counting::read`] (after the record).
    pub(super) fn copy_out(&self, encoder: &mut wgpu::CommandEncoder) {
        for (k, c) in self.counters.iter().enumerate() {
            encoder.copy_buffer_to_buffer(c, 0, &self.staging, k as u64 * BYTES, BYTES);
        }
    }

    /// The far and near fields' counts of the submitted record (waits).
    pub(super) fn read(&self, gpu: &GpuContext) -> Result<(WorkCounts, WorkCounts), GpuError> {
        let slice = self.staging.slice(..);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        gpu.wait()?;
        let words: Vec<u32> = {
            let view = slice.get_mapped_range().map_err(|e| GpuError::Device(e.to_string()))?;
            bytemuck::cast_slice(&view).to_vec()
        };
        self.staging.unmap();
        let field = |k: usize| -> WorkCounts {
            let v = |f: u32| {
                let at = k * FIELDS * 2 + 2 * f as usize;
                words[at] as u64 | (words[at + 1] as u64) << 32
            };
            WorkCounts {
                tiles: v(COUNT_TILES),
                group_tests: v(COUNT_GROUP_TESTS),
                cluster_tests: v(COUNT_CLUSTER_TESTS),
                sphere_tests: v(COUNT_SPHERE_TESTS),
                tested: v(COUNT_TESTED),
                kept: v(COUNT_KEPT),
                pixels: v(COUNT_PIXELS),
            }
        };
        Ok((field(0), field(1)))
    }
}

impl Pipe {
    /// `vpl_tiled` or `vpl_near` for culling kind `m` out of a list built
    /// per kind.
    pub(super) fn find(
        list: &[(CullKind, wgpu::ComputePipeline)],
        m: CullKind,
    ) -> Result<&wgpu::ComputePipeline, GpuError> {
        list.iter()
            .find(|(k, _)| *k == m)
            .map(|(_, p)| p)
            .ok_or_else(|| GpuError::Setting(format!("no pipeline for culling {m:?}")))
    }
}
