//! The path tracer's grid over the BSH's leaves on the GPU (slc-core's
//! [`BshGrid`](slc_core::bsh::BshGrid), which the CPU path tracer builds):
//! rebuilt every pass after the refit by `bsh_grid`'s six stages, one
//! dispatch each for all of a pass's grids (a counting sort, each cell then
//! put into the walk's order by its own invocation or, past
//! `GRID_SORT_MOVES` moves, by its workgroup), over the frames
//! [`GridFrame::levels`] gives for the scene's box, the first whose entries
//! fit its budget. `pt_connect` then tests a vertex's cell and the range
//! tail instead of walking the tree: the same lights in the same order, so
//! the same image (`tests/pt_parity.rs`). Off unless
//! [`GpuPt::set_grid`](crate::pt::GpuPt::set_grid) turns it on: on
//! lavapipe the build costs more than the lookups save.
//!
//! Three grids share the buffers where the scene has glossy materials, as
//! on the CPU: one for Lambertian receivers, one for range lobes up to
//! [`GLOSSY_REACH`] and one up to [`SHARP_REACH`] (every lobe), allowed at
//! least [`SHARP_GRID_ENTRIES`] entries. A glossy receiver's cell is cut
//! to the lights whose bound meets its lobe's cone (slc-core's
//! `bsh_lobe_admits`) before the walk's leaf test.
//!
//! On lavapipe, whose loops end silently after 65,535 iterations in an
//! invocation, a leaf may cover at most that many cells, and the cells of
//! a workgroup (64) their invocations leave to it hold at most about
//! 30,000 entries in all (a cell of 16,384: its insertion stopped after
//! 1,024 moves plus one more insertion, then 105 bitonic steps of 128
//! pairs an invocation); the tests' scenes stay well below.

use crate::kernel::{KernelLayout, UniformSlots, check_kernels, read_back, storage, whole, zeroed};
use crate::lights::{LightBuffers, WG};
use crate::{GpuContext, GpuError};
use glam::Vec3;
use slc_core::bsh::grid::{GLOSSY_REACH, SHARP_GRID_ENTRIES, SHARP_REACH, walk_leaves};
use slc_core::bsh::{Bsh, GridFrame};
use slc_shared_shaders::layout::{
    GRID_HEADER, GRID_LEVELS_MAX, GRID_SORT_MOVES, GRIDS_MAX, GridParams, GridStage,
};
use slc_shared_shaders::{Features, Kernel};

/// A grid read back: its frame and each cell's leaves (node indices).
pub type GridCells = (GridFrame, Vec<Vec<u32>>);

/// The stages of `bsh_grid` (its module docs).
const STAGES: usize = 6;

/// A pass's grids: their buffers, the build's pipeline and bind group.
pub(crate) struct GpuGrid {
    pipeline: wgpu::ComputePipeline,
    /// The six stages' uniforms (each dispatch builds every grid).
    params: UniformSlots,
    group: wgpu::BindGroup,
    /// Each grid's frame, reach and counts, then each cell's first entry.
    pub(crate) grid: wgpu::Buffer,
    /// The cells' leaves.
    pub(crate) entries: wgpu::Buffer,
    /// Each stage's [`GridStage`], as `params` holds them.
    stages: Vec<GridStage>,
    /// Where each grid's words start in `grid`.
    headers: Vec<u32>,
    /// Leaves in the tree (the per-leaf stages' extent).
    lights: u32,
    /// Cells of the finest frame; 0 without a frame (no grid: the walks
    /// take the tree).
    cells: u32,
    /// Whether passes build them ([`GpuGrid::set_enabled`]).
    enabled: bool,
    /// Stage 5's workgroups, one per `WG` cells of the finest frame, in
    /// rows of at most the device's most along x.
    cell_groups: (u32, u32),
}

impl GpuGrid {
    /// The grids for the light set `set` (its refitted BSH) whose tree is
    /// `bsh`'s, over the scene's box `(lo, hi)`: for Lambertian receivers,
    /// and with `glossy` also for range lobes up to [`GLOSSY_REACH`]. Each
    /// grid's entries are capped by the device's binding size (a coarser
    /// frame, or none, is then taken).
    pub(crate) fn new(
        gpu: &GpuContext,
        set: &LightBuffers,
        bsh: &Bsh,
        (lo, hi): (Vec3, Vec3),
        glossy: bool,
    ) -> Result<GpuGrid, GpuError> {
        let f = Features { workgroup_size: WG, ..Features::default() };
        check_kernels(gpu, &[(Kernel::BshGrid, &f, 0)])?;
        // Each grid's reach and the entries it may take at least.
        let grids: &[(f32, u64)] = if glossy {
            &[(1.0, 0), (GLOSSY_REACH, 0), (SHARP_REACH, SHARP_GRID_ENTRIES)]
        } else {
            &[(1.0, 0)]
        };
        let k = grids.len() as u64;
        debug_assert!(k <= GRIDS_MAX as u64);
        let leaves = walk_leaves(bsh);
        let tree_lights = leaves.len();
        let mut levels = GridFrame::levels(lo, hi, bsh.len());
        levels.truncate(GRID_LEVELS_MAX as usize);
        let lim = &gpu.limits;
        let binding = lim.max_storage_buffer_binding_size.min(lim.max_buffer_size);
        // Each grid's words: the header, one start a cell and the end. No
        // frame where the finest one's would pass the device's limits.
        let words_of = |cells: u64| GRID_HEADER as u64 + cells + 1;
        let most = lim.max_compute_workgroups_per_dimension as u64;
        if levels.first().is_some_and(|l| {
            k * words_of(l.cells()) * 4 > binding
                || l.cells().div_ceil(WG as u64).div_ceil(most) > most
        }) {
            levels.clear();
        }
        let cells = levels.first().map_or(0, |l| l.cells());
        let groups = cells.div_ceil(WG as u64);
        let cell_groups = (groups.min(most) as u32, groups.div_ceil(most) as u32);
        let words = words_of(cells);
        // Each grid's entries: its finest frame's budget (a coarser one's
        // is smaller), within its share of the binding; where they start.
        let capacity: Vec<u64> = grids
            .iter()
            .map(|&(_, least)| {
                levels
                    .first()
                    .map_or(1, |l| l.budget(tree_lights as u64, least))
                    .clamp(1, binding / 4 / k)
            })
            .collect();
        let first: Vec<u64> = capacity
            .iter()
            .scan(0, |at, &c| {
                *at += c;
                Some(*at - c)
            })
            .collect();
        let layout = KernelLayout::new(gpu, Kernel::BshGrid, &f)?;
        let pipeline = layout.pipeline(gpu, &f, None)?;
        // COPY_SRC: read back by the tests.
        let rw = wgpu::BufferUsages::STORAGE
            | wgpu::BufferUsages::COPY_DST
            | wgpu::BufferUsages::COPY_SRC;
        let headers: Vec<u32> = (0..k).map(|g| (g * words) as u32).collect();
        // No frame until the first pass; each grid's word 14 the next's start.
        let mut init = vec![0u32; (k * words) as usize];
        for g in 1..headers.len() {
            init[headers[g - 1] as usize + 14] = headers[g];
        }
        let grid = storage(gpu, "bsh grid", bytemuck::cast_slice(&init), rw);
        let fill = zeroed(gpu, "bsh grid fill", (k * cells).max(1) * 4, rw);
        let entries = zeroed(gpu, "bsh grid entries", capacity.iter().sum::<u64>() * 4, rw);
        let frames = if levels.is_empty() { vec![GridFrame::default()] } else { levels.clone() };
        let none = wgpu::BufferUsages::empty();
        let frames = storage(gpu, "grid levels", bytemuck::cast_slice(&frames), none);
        let leaves = if leaves.is_empty() { vec![0] } else { leaves };
        let leaves = storage(gpu, "grid leaves", bytemuck::cast_slice(&leaves), none);
        let params = UniformSlots::new::<GridStage>(gpu, "grid stages", STAGES as u64);
        let stages: Vec<GridStage> = (0..STAGES as u32)
            .map(|stage| GridStage {
                stage,
                count: tree_lights as u32,
                levels: levels.len() as u32,
                moves: GRID_SORT_MOVES,
            })
            .collect();
        params.write(gpu, &stages);
        let specs: Vec<GridParams> = (0..k as usize)
            .map(|g| GridParams {
                capacity: capacity[g] as u32,
                reach: grids[g].0,
                header: headers[g],
                fill: (g as u64 * cells) as u32,
                entries: first[g] as u32,
                least: grids[g].1 as u32,
            })
            .collect();
        let specs = storage(gpu, "grid specs", bytemuck::cast_slice(&specs), none);
        let group = layout.group(
            gpu,
            0,
            &[
                ("params", params.binding()),
                ("bsh_nodes", whole(&set.bsh)),
                ("grid_leaves", whole(&leaves)),
                ("grid_levels", whole(&frames)),
                ("grid", whole(&grid)),
                ("grid_fill", whole(&fill)),
                ("grid_entries", whole(&entries)),
                ("grids", whole(&specs)),
            ],
        );
        Ok(GpuGrid {
            pipeline,
            params,
            group,
            grid,
            entries,
            stages,
            headers,
            lights: tree_lights as u32,
            cells: cells as u32,
            enabled: false,
            cell_groups,
        })
    }

    /// Builds the grids in passes to come (`true`) or not (the default):
    /// the walks then take the tree (the same lights in the same order).
    pub(crate) fn set_enabled(&mut self, gpu: &GpuContext, on: bool) {
        self.enabled = on;
        if !on {
            // No cells along x: no grid.
            for &h in &self.headers {
                gpu.queue.write_buffer(&self.grid, (h as u64 + 3) * 4, &0u32.to_le_bytes());
            }
        }
    }

    /// Sets the moves each cell's sort by insertion may make in one
    /// invocation before its workgroup sorts it ([`GRID_SORT_MOVES`] by
    /// default; 0: every cell of two or more entries by its workgroup).
    /// The same cells either way.
    pub(crate) fn set_sort_moves(&mut self, gpu: &GpuContext, moves: u32) {
        for s in &mut self.stages {
            s.moves = moves;
        }
        self.params.write(gpu, &self.stages);
    }

    /// The last pass's grid `g` (0: Lambertian, 1: glossy, 2: sharp) read back: its
    /// frame (no cells along x: none) and each cell's leaves (node
    /// indices); `None` where there is no such grid.
    pub(crate) fn read(&self, gpu: &GpuContext, g: usize) -> Result<Option<GridCells>, GpuError> {
        let Some(&h) = self.headers.get(g) else { return Ok(None) };
        let staging = |b: &wgpu::Buffer| {
            gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("grid readback"),
                size: b.size(),
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            })
        };
        let words: Vec<u32> = read_back(gpu, &self.grid, &staging(&self.grid))?;
        let entries: Vec<u32> = read_back(gpu, &self.entries, &staging(&self.entries))?;
        let h = h as usize;
        let frame: GridFrame =
            bytemuck::pod_read_unaligned(bytemuck::cast_slice(&words[h..h + 12]));
        let start = &words[h + GRID_HEADER as usize..];
        let cells = (0..frame.cells() as usize)
            .map(|c| entries[start[c] as usize..start[c + 1] as usize].to_vec())
            .collect();
        Ok(Some((frame, cells)))
    }

    /// Records the grids' build for the refitted BSH into `cp` (nothing
    /// where they are off or the scene has no frame).
    pub(crate) fn encode(&self, cp: &mut wgpu::ComputePass) {
        if !self.enabled || self.cells == 0 {
            return;
        }
        cp.set_pipeline(&self.pipeline);
        let per_light = self.lights.div_ceil(WG);
        // Every grid in its own workgroups along z.
        let grids = self.headers.len() as u32;
        for stage in 0..STAGES {
            cp.set_bind_group(0, &self.group, &[self.params.offset(stage)]);
            let groups = match stage {
                0 | 2 | 4 => (per_light, 1),
                5 => self.cell_groups,
                _ => (1, 1),
            };
            cp.dispatch_workgroups(groups.0, groups.1, grids);
        }
    }
}
