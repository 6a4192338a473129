//! The indirect pass's culling hierarchies (slc-core's `cluster`): how
//! many slots the light buffer has, the far field's grid of one subset
//! and the near field's grid, and where each level's boxes sit in the one
//! `boxes` buffer `vpl_clusters` and `vpl_groups` fill every frame and
//! `vpl_tiled` and `vpl_near` cull through.

use super::VplSourceDesc;
use slc_core::cluster::{CLUSTER, ClusterGrid};
use slc_core::interleave::{subset_side, subset_slots_linear};
use slc_shared_shaders::layout::VplParams;

/// The two hierarchies of a pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Hierarchy {
    /// Interleaved subsets `P²`.
    subsets: u32,
    /// Slots per subset: whole clusters, padding holding no VPL.
    pub(super) per_subset: u32,
    /// One subset's grid: its image in map order (an RSM), or its VPLs in
    /// runs of 64 (a buffer).
    far: ClusterGrid,
    /// The near field's grid: the whole RSM in map order, or the records
    /// in runs of 64.
    near: ClusterGrid,
}

/// Where each level's boxes start in `boxes`, for one record.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct BoxRanges {
    far_groups_at: u32,
    near_clusters_at: u32,
    near_groups_at: u32,
    box_count: u32,
}

impl Hierarchy {
    /// The hierarchies of `vpls` at period `P = period` (sizes already
    /// checked: an RSM edge a multiple of 8, a count a multiple of 64).
    pub(super) fn new(vpls: VplSourceDesc, period: u32) -> Hierarchy {
        let subsets = period * period;
        match vpls {
            VplSourceDesc::Rsm { size } => {
                let side = subset_side(size, period);
                Hierarchy {
                    subsets,
                    per_subset: side * side,
                    far: ClusterGrid::map(side),
                    near: ClusterGrid::map(size),
                }
            }
            VplSourceDesc::Buffer { count } => Hierarchy {
                subsets,
                per_subset: subset_slots_linear(count, period),
                far: ClusterGrid::list(count / subsets),
                near: ClusterGrid::list(count),
            },
        }
    }

    /// Slots of the light buffer (and its range and id buffers).
    pub(super) fn slots(&self) -> u64 {
        self.subsets as u64 * self.per_subset as u64
    }

    /// The far field's clusters, every subset's.
    fn far_clusters(&self) -> u32 {
        self.subsets * (self.per_subset / CLUSTER)
    }

    /// The far field's groups, every subset's.
    fn far_groups(&self) -> u32 {
        self.subsets * self.far.groups()
    }

    /// Boxes of both hierarchies: the size of `boxes`.
    pub(super) fn boxes(&self) -> u64 {
        (self.far_clusters() + self.far_groups() + self.near.clusters() + self.near.groups()) as u64
    }

    /// Where the levels start, with or without the near field (without,
    /// its ranges are empty and the bounds kernels skip it).
    pub(super) fn ranges(&self, near: bool) -> BoxRanges {
        let far_groups_at = self.far_clusters();
        let near_clusters_at = far_groups_at + self.far_groups();
        let (nc, ng) = if near { (self.near.clusters(), self.near.groups()) } else { (0, 0) };
        BoxRanges {
            far_groups_at,
            near_clusters_at,
            near_groups_at: near_clusters_at + nc,
            box_count: near_clusters_at + nc + ng,
        }
    }

    /// Fills `p`'s culling fields for a record (`near`: with a near field).
    pub(super) fn fill(&self, p: &mut VplParams, near: bool) {
        let r = self.ranges(near);
        p.lights_per_subset = self.per_subset;
        p.far_groups_at = r.far_groups_at;
        p.near_clusters_at = r.near_clusters_at;
        p.near_groups_at = r.near_groups_at;
        p.box_count = r.box_count;
        p.far_grid = grid_vec(self.far);
        p.near_grid = grid_vec(self.near);
    }

    /// `vpl_clusters`' workgroups for a record: one per cluster of both
    /// fields (`near`) or of the far field, over a 2-D dispatch of at most
    /// `max_dim` per dimension.
    pub(super) fn cluster_dispatch(&self, near: bool, max_dim: u32) -> [u32; 3] {
        let r = self.ranges(near);
        dispatch_2d(r.far_groups_at + (r.near_groups_at - r.near_clusters_at), max_dim)
    }

    /// `vpl_groups`' workgroups: one per group of both fields or the far
    /// field.
    pub(super) fn group_dispatch(&self, near: bool, max_dim: u32) -> [u32; 3] {
        let r = self.ranges(near);
        dispatch_2d(
            (r.near_clusters_at - r.far_groups_at) + (r.box_count - r.near_groups_at),
            max_dim,
        )
    }
}

/// A grid as the kernels take it: `(bw, bh, gw, gh)`.
fn grid_vec(g: ClusterGrid) -> glam::UVec4 {
    glam::UVec4::new(g.bw, g.bh, g.gw, g.gh)
}

/// `n` workgroups as a 2-D dispatch of at most `max_dim` per dimension,
/// numbered row-major (the kernels skip those past `n`).
fn dispatch_2d(n: u32, max_dim: u32) -> [u32; 3] {
    let x = n.clamp(1, max_dim.max(1));
    [x, n.div_ceil(x).max(1), 1]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The levels tile `boxes` without gaps; a 1,048,576-VPL RSM's far
    /// field has 16 clusters of 64 per group row, and the dispatches cover
    /// every cluster and group.
    #[test]
    fn boxes_are_laid_out_level_after_level() {
        let h = Hierarchy::new(VplSourceDesc::Rsm { size: 1024 }, 8);
        assert_eq!(h.per_subset, 128 * 128);
        assert_eq!(h.slots(), 1 << 20);
        let r = h.ranges(true);
        assert_eq!(r.far_groups_at, 64 * 256);
        assert_eq!(r.near_clusters_at, r.far_groups_at + 64 * 4);
        assert_eq!(r.near_groups_at, r.near_clusters_at + 16384);
        assert_eq!(r.box_count as u64, h.boxes());
        let d = h.cluster_dispatch(true, 65535);
        assert!(d[0] * d[1] >= 64 * 256 + 16384);
        let r = h.ranges(false);
        assert_eq!(
            (r.near_clusters_at, r.near_groups_at, r.box_count),
            (r.near_clusters_at, r.near_clusters_at, r.near_clusters_at)
        );
        // A padded subset side: 200 / 8 = 25 texels, padded to 32.
        let h = Hierarchy::new(VplSourceDesc::Rsm { size: 200 }, 8);
        assert_eq!(h.per_subset, 32 * 32);
        // Records: 64 × 65 per subset, padded to 128 slots.
        let h = Hierarchy::new(VplSourceDesc::Buffer { count: 64 * 65 }, 8);
        assert_eq!(h.per_subset, 128);
        assert_eq!(dispatch_2d(70000, 65535), [65535, 2, 1]);
        assert_eq!(dispatch_2d(0, 65535), [1, 1, 1]);
    }
}
