//! Clusters and groups: the two-level box hierarchy both backends cull
//! VPLs with, over an ordered list of lights.
//!
//! A **cluster** is [`CLUSTER`] consecutive lights of the list; a
//! **group** is up to `gw × gh` clusters of a `bw × bh` grid of clusters.
//! Where the list comes from a map (an RSM, or one interleaved subset of
//! one), cluster `(bx, by)` holds the 8×8 texels `(8bx + i, 8by + j)`
//! and groups are [`GROUP_SIDE`] × [`GROUP_SIDE`] clusters (64×64 texels):
//! both levels are compact patches of the map, so their boxes are small.
//! A list without a map (an engine's VPL records) is a `clusters × 1` grid
//! with groups of 64 clusters in a row (`gw = 64`, `gh = 1`).
//!
//! Clusters are numbered group by group (groups row-major, the last column
//! and row of groups partial, clusters row-major inside their group), so a
//! group's clusters are consecutive and a cluster's lights are consecutive:
//! the hierarchy is implicit in the order, and each level's boxes are a
//! reduction over a contiguous range ([`box_overlaps_box`] tests them).

use crate::wgsl::*;

crate::shared! {
    /// Lights per cluster: an 8×8 patch of a map's texels, or 64
    /// consecutive lights of a list.
    pub const CLUSTER: u32 = 64;

    /// Clusters per side of a group in a map's layout (8×8 clusters: a
    /// 64×64-texel patch).
    pub const GROUP_SIDE: u32 = 8;

    /// Groups of a grid `bw` clusters wide with groups `gw` wide:
    /// `⌈bw/gw⌉`.
    pub fn groups_across(bw: u32, gw: u32) -> u32 {
        return (bw + gw - 1) / gw;
    }

    /// Groups of a `bw × bh` grid of clusters in groups of `gw × gh`.
    pub fn group_count(bw: u32, bh: u32, gw: u32, gh: u32) -> u32 {
        return groups_across(bw, gw) * groups_across(bh, gh);
    }

    /// The first cluster of group `g` (row-major over the groups) of a
    /// `bw × bh` grid in groups of `gw × gh`: every earlier group row holds
    /// `gh·bw` clusters, every earlier group of its row `gw·h` (`h` the
    /// row's height, `gh` but for the last row).
    pub fn group_first(g: u32, bw: u32, bh: u32, gw: u32, gh: u32) -> u32 {
        let across: u32 = groups_across(bw, gw);
        let gx: u32 = g % across;
        let gy: u32 = g / across;
        let h: u32 = min(gh, bh - gh * gy);
        return gy * gh * bw + gx * gw * h;
    }

    /// The number of clusters of group `g`.
    pub fn group_clusters(g: u32, bw: u32, bh: u32, gw: u32, gh: u32) -> u32 {
        let across: u32 = groups_across(bw, gw);
        let gx: u32 = g % across;
        let gy: u32 = g / across;
        return min(gw, bw - gw * gx) * min(gh, bh - gh * gy);
    }

    /// The index of cluster `(bx, by)` of the grid in that order.
    pub fn cluster_index(bx: u32, by: u32, bw: u32, bh: u32, gw: u32, gh: u32) -> u32 {
        let gx: u32 = bx / gw;
        let gy: u32 = by / gh;
        let w: u32 = min(gw, bw - gw * gx);
        let g: u32 = gy * groups_across(bw, gw) + gx;
        return group_first(g, bw, bh, gw, gh) + (by - gh * gy) * w + (bx - gw * gx);
    }

    /// The column `bx` of cluster index `c` (the inverse of
    /// [`cluster_index`] with [`cluster_y`]).
    pub fn cluster_x(c: u32, bw: u32, bh: u32, gw: u32, gh: u32) -> u32 {
        let gy: u32 = c / (gh * bw);
        let h: u32 = min(gh, bh - gh * gy);
        let rest: u32 = c - gy * gh * bw;
        let gx: u32 = rest / (gw * h);
        let w: u32 = min(gw, bw - gw * gx);
        return gx * gw + (rest - gx * gw * h) % w;
    }

    /// The row `by` of cluster index `c`.
    pub fn cluster_y(c: u32, bw: u32, bh: u32, gw: u32, gh: u32) -> u32 {
        let gy: u32 = c / (gh * bw);
        let h: u32 = min(gh, bh - gh * gy);
        let rest: u32 = c - gy * gh * bw;
        let gx: u32 = rest / (gw * h);
        let w: u32 = min(gw, bw - gw * gx);
        return gy * gh + (rest - gx * gw * h) / w;
    }

    /// The index of texel `(tx, ty)` of a `side × side` map (`side` a
    /// multiple of 8) in map order: its cluster's index
    /// ([`cluster_index`] on the `side/8`-square grid, groups of
    /// [`GROUP_SIDE`]²) times [`CLUSTER`], plus `(ty mod 8)·8 + tx mod 8`.
    pub fn map_index(tx: u32, ty: u32, side: u32) -> u32 {
        let b: u32 = side / 8;
        let c: u32 = cluster_index(tx / 8, ty / 8, b, b, GROUP_SIDE, GROUP_SIDE);
        return c * CLUSTER + (ty % 8) * 8 + tx % 8;
    }

    /// The column of map-order index `q` of a `side × side` map (the
    /// inverse of [`map_index`] with [`map_y`]).
    pub fn map_x(q: u32, side: u32) -> u32 {
        let b: u32 = side / 8;
        return cluster_x(q / CLUSTER, b, b, GROUP_SIDE, GROUP_SIDE) * 8 + q % 8;
    }

    /// The row of map-order index `q` of a `side × side` map.
    pub fn map_y(q: u32, side: u32) -> u32 {
        let b: u32 = side / 8;
        return cluster_y(q / CLUSTER, b, b, GROUP_SIDE, GROUP_SIDE) * 8 + (q % CLUSTER) / 8;
    }

    /// `true` when the boxes `[lo1, hi1]` and `[lo2, hi2]` share a point.
    /// The empty box of a reduction over no point, `[F32_MAX, −F32_MAX]`,
    /// shares none.
    pub fn box_overlaps_box(lo1: vec3f, hi1: vec3f, lo2: vec3f, hi2: vec3f) -> bool {
        return lo1.x <= hi2.x && lo2.x <= hi1.x
            && lo1.y <= hi2.y && lo2.y <= hi1.y
            && lo1.z <= hi2.z && lo2.z <= hi1.z;
    }
}

/// A cluster grid and its groups: `bw × bh` clusters in groups of
/// `gw × gh` (see the module docs), as both backends' hosts describe a
/// list to the culling.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ClusterGrid {
    /// Clusters across.
    pub bw: u32,
    /// Clusters down.
    pub bh: u32,
    /// Clusters across a group.
    pub gw: u32,
    /// Clusters down a group.
    pub gh: u32,
}

impl ClusterGrid {
    /// The grid of a `side × side` map (`side` a multiple of 8): 8×8-texel
    /// clusters in groups of [`GROUP_SIDE`]².
    pub fn map(side: u32) -> ClusterGrid {
        ClusterGrid { bw: side / 8, bh: side / 8, gw: GROUP_SIDE, gh: GROUP_SIDE }
    }

    /// The grid of a list of `lights` lights without a map: clusters of
    /// [`CLUSTER`] consecutive lights (the last one partial), groups of 64
    /// consecutive clusters.
    pub fn list(lights: u32) -> ClusterGrid {
        ClusterGrid { bw: lights.div_ceil(CLUSTER).max(1), bh: 1, gw: 64, gh: 1 }
    }

    /// The number of clusters.
    pub fn clusters(&self) -> u32 {
        self.bw * self.bh
    }

    /// The number of groups.
    pub fn groups(&self) -> u32 {
        group_count(self.bw, self.bh, self.gw, self.gh)
    }

    /// The clusters of group `g`: `first..first + count`.
    pub fn group_range(&self, g: u32) -> core::ops::Range<u32> {
        let first = group_first(g, self.bw, self.bh, self.gw, self.gh);
        first..first + group_clusters(g, self.bw, self.bh, self.gw, self.gh)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    /// Every grid's numbering is a bijection whose inverse is
    /// `cluster_x`/`cluster_y`, each group's clusters are consecutive and
    /// inside the group's rectangle, and the groups cover the clusters in
    /// order.
    #[test]
    fn cluster_numbering_is_a_bijection_grouped() {
        for (bw, bh, gw, gh) in [
            (4, 4, 8, 8),
            (16, 16, 8, 8),
            (13, 7, 8, 8),
            (9, 17, 8, 8),
            (100, 1, 64, 1),
            (1, 1, 8, 8),
        ] {
            let grid = ClusterGrid { bw, bh, gw, gh };
            let mut seen = vec![false; (bw * bh) as usize];
            for by in 0..bh {
                for bx in 0..bw {
                    let c = cluster_index(bx, by, bw, bh, gw, gh);
                    assert!(!seen[c as usize], "{bw}x{bh}: cluster {c} twice");
                    seen[c as usize] = true;
                    assert_eq!(
                        (cluster_x(c, bw, bh, gw, gh), cluster_y(c, bw, bh, gw, gh)),
                        (bx, by)
                    );
                }
            }
            let mut next = 0;
            for g in 0..grid.groups() {
                let r = grid.group_range(g);
                assert_eq!(r.start, next, "{bw}x{bh}: group {g}");
                next = r.end;
                let across = groups_across(bw, gw);
                let (gx, gy) = (g % across, g / across);
                for c in r {
                    let (x, y) = (cluster_x(c, bw, bh, gw, gh), cluster_y(c, bw, bh, gw, gh));
                    assert!(x / gw == gx && y / gh == gy, "cluster {c} outside group {g}");
                }
            }
            assert_eq!(next, bw * bh);
        }
    }

    /// Map order is a permutation of a map's texels whose clusters are 8×8
    /// patches and whose groups are 64×64 patches.
    #[test]
    fn map_order_is_a_permutation_of_patches() {
        for side in [8u32, 64, 72, 200, 256] {
            let mut seen = vec![false; (side * side) as usize];
            for ty in 0..side {
                for tx in 0..side {
                    let q = map_index(tx, ty, side);
                    assert!(!seen[q as usize], "{side}: index {q} twice");
                    seen[q as usize] = true;
                    assert_eq!((map_x(q, side), map_y(q, side)), (tx, ty));
                    let grid = ClusterGrid::map(side);
                    let c = q / CLUSTER;
                    assert_eq!(
                        (
                            cluster_x(c, grid.bw, grid.bh, 8, 8),
                            cluster_y(c, grid.bw, grid.bh, 8, 8)
                        ),
                        (tx / 8, ty / 8)
                    );
                }
            }
        }
        assert!(box_overlaps_box(
            vec3f(0.0, 0.0, 0.0),
            vec3f(1.0, 1.0, 1.0),
            vec3f(1.0, 0.5, 0.5),
            vec3f(2.0, 2.0, 2.0)
        ));
        assert!(!box_overlaps_box(
            vec3f(0.0, 0.0, 0.0),
            vec3f(1.0, 1.0, 1.0),
            vec3f(1.5, 0.5, 0.5),
            vec3f(2.0, 2.0, 2.0)
        ));
        let empty = (
            vec3f(crate::ray::F32_MAX, crate::ray::F32_MAX, crate::ray::F32_MAX),
            -vec3f(crate::ray::F32_MAX, crate::ray::F32_MAX, crate::ray::F32_MAX),
        );
        assert!(!box_overlaps_box(empty.0, empty.1, vec3f(-9.0, -9.0, -9.0), vec3f(9.0, 9.0, 9.0)));
    }
}
