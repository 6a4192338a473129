//! How [`Bsh::build_with`](super::Bsh::build_with) splits a node's lights
//! in two: at the median (a balanced tree) or by the sphere-area
//! heuristic (fewer nodes per walk).

use crate::light::LightBound;
use crate::sphere::Aabb;

/// The deepest a [`BshSplit::SphereArea`] tree grows (the root at depth
/// 0): a node splits by the heuristic only while the deeper side could
/// still be finished by median splits within it, so the tree never holds
/// more levels than this (the GPU refits one level per dispatch) and every
/// recursion over it stays shallow.
pub const BSH_MAX_DEPTH: u32 = 48;

/// Bins of the sphere-area heuristic.
const BINS: usize = 32;

/// The rule that splits each node's lights in two.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BshSplit {
    /// At the median of the centres along the longest axis of their box:
    /// a balanced tree, depth `⌈log₂ n⌉`, whose subtrees at one depth hold
    /// equal shares of the lights (what the direct pass's tile walk deals
    /// out to its invocations).
    #[default]
    Median,
    /// The sphere-area heuristic: of 32 bins along the longest axis of the
    /// centres' box (as the median's; all three axes found the same visits
    /// within 2% and took three times as long), the split that minimises `n_L·d_L² + n_R·d_R²`, `n` a side's
    /// lights and `d` the diagonal of the box of their bounds `c ± R`. A
    /// walk visits a node's children when the shading point lies in the
    /// node's sphere; a point on a surface does so with a chance that
    /// grows with the sphere's radius squared (a plane cuts a sphere of
    /// radius `ρ` in a disc of area at most `πρ²`), and half a box's
    /// diagonal bounds the sphere of what it holds. This is the surface
    /// area heuristic of ray tracing (Goldsmith & Salmon 1987; MacDonald &
    /// Booth 1990) with that disc in place of a box's surface. The random
    /// ranges, redrawn every pass, are left out: they grow every sphere
    /// alike. Falls back to the median where every centre falls in one
    /// bin, where no split has a finite cost, and near
    /// [`BSH_MAX_DEPTH`]. Issue 48: 17% fewer visits per walk on the
    /// suite's triangle lights (docs/results/bsh-walk-visits.md).
    SphereArea,
}

/// `⌈log₂ m⌉` for `m ≥ 1`: the levels below a balanced subtree's root.
fn levels(m: usize) -> u32 {
    usize::BITS - (m - 1).leading_zeros()
}

/// Reorders `idx` (at least two lights) so that `idx[..mid]` is the left
/// child's and `idx[mid..]` the right child's, `0 < mid < idx.len()`, and
/// returns `mid`. `depth` is the node's depth (the root's is 0).
pub(super) fn split(bounds: &[LightBound], idx: &mut [u32], rule: BshSplit, depth: u32) -> usize {
    let centres = idx.iter().fold(Aabb::EMPTY, |b, &i| b.grow(bounds[i as usize].center));
    let axis = longest_axis(centres);
    let by_area = match rule {
        BshSplit::SphereArea => sphere_area(bounds, idx, centres, axis, depth),
        BshSplit::Median => None,
    };
    by_area.unwrap_or_else(|| median(bounds, idx, axis))
}

/// The longest axis of box `b` (x before y before z on ties).
fn longest_axis(b: Aabb) -> usize {
    let ext = b.max - b.min;
    if ext.x >= ext.y && ext.x >= ext.z {
        0
    } else if ext.y >= ext.z {
        1
    } else {
        2
    }
}

/// The median split along `axis` (the longest of the centres' box).
fn median(bounds: &[LightBound], idx: &mut [u32], axis: usize) -> usize {
    let mid = idx.len() / 2;
    idx.select_nth_unstable_by(mid, |&a, &b| {
        bounds[a as usize].center[axis].total_cmp(&bounds[b as usize].center[axis])
    });
    mid
}

/// Bins along one axis of the centres' box (in f64: a box spanning most
/// of f32's range has an infinite f32 width).
struct Binning {
    axis: usize,
    lo: f64,
    scale: f64,
}

impl Binning {
    fn bin(&self, b: &LightBound) -> usize {
        // `as` saturates (and takes NaN to 0): always a bin.
        (((b.center[self.axis] as f64 - self.lo) * self.scale) as usize).min(BINS - 1)
    }
}

/// A side's lights and the box of their bounds, in f64.
#[derive(Clone, Copy)]
struct Side {
    count: usize,
    lo: [f64; 3],
    hi: [f64; 3],
}

impl Side {
    const EMPTY: Side = Side { count: 0, lo: [f64::INFINITY; 3], hi: [f64::NEG_INFINITY; 3] };

    /// One light's bound `c ± R`.
    fn of(b: &LightBound) -> Side {
        let (c, r) = (b.center.to_array().map(f64::from), b.extent as f64);
        Side { count: 1, lo: c.map(|c| c - r), hi: c.map(|c| c + r) }
    }

    fn add(self, o: Side) -> Side {
        Side {
            count: self.count + o.count,
            lo: core::array::from_fn(|a| self.lo[a].min(o.lo[a])),
            hi: core::array::from_fn(|a| self.hi[a].max(o.hi[a])),
        }
    }

    /// `n·d²`.
    fn cost(self) -> f64 {
        let d2: f64 = (0..3).map(|a| (self.hi[a] - self.lo[a]) * (self.hi[a] - self.lo[a])).sum();
        self.count as f64 * d2
    }
}

/// The sphere-area split ([`BshSplit::SphereArea`]), or `None` for the
/// median.
fn sphere_area(
    bounds: &[LightBound],
    idx: &mut [u32],
    centres: Aabb,
    axis: usize,
    depth: u32,
) -> Option<usize> {
    let (lo, hi) = (centres.min[axis] as f64, centres.max[axis] as f64);
    if hi <= lo {
        return None;
    }
    let binning = Binning { axis, lo, scale: BINS as f64 / (hi - lo) };
    let mut bins = [Side::EMPTY; BINS];
    for &i in idx.iter() {
        let b = &bounds[i as usize];
        let k = binning.bin(b);
        bins[k] = bins[k].add(Side::of(b));
    }
    let mut right = [Side::EMPTY; BINS];
    let mut acc = Side::EMPTY;
    for k in (1..BINS).rev() {
        acc = acc.add(bins[k]);
        right[k] = acc;
    }
    // The last bin on the left side of the cheapest split.
    let mut best: Option<(f64, usize)> = None;
    let mut left = Side::EMPTY;
    for k in 0..BINS - 1 {
        left = left.add(bins[k]);
        let r = right[k + 1];
        if left.count == 0 || r.count == 0 {
            continue;
        }
        // The deeper side must still fit within BSH_MAX_DEPTH when median
        // splits finish it.
        if depth + 1 + levels(left.count.max(r.count)) > BSH_MAX_DEPTH {
            continue;
        }
        let cost = left.cost() + r.cost();
        if cost.is_finite() && best.is_none_or(|b| cost < b.0) {
            best = Some((cost, k));
        }
    }
    let (_, k) = best?;
    let mut mid = 0;
    for j in 0..idx.len() {
        if binning.bin(&bounds[idx[j] as usize]) <= k {
            idx.swap(j, mid);
            mid += 1;
        }
    }
    Some(mid)
}
