//! How a built tree sits in the node array: the binary tree in pre-order,
//! or regrouped into a wider tree whose every node's children sit side by
//! side ([`BshShape::width`]). The talk's stackless `child`/`next` walk
//! runs on either unchanged.

use super::{BSH_NONE, BshNode, BshSplit};
use alloc::vec;
use alloc::vec::Vec;

/// The widest tree [`BshShape::width`] allows.
pub const BSH_MAX_WIDTH: u32 = 8;

/// How [`Bsh::build_with`](super::Bsh::build_with) shapes the tree.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BshShape {
    /// How each node's lights split in two.
    pub split: BshSplit,
    /// Children per inner node, 2 to [`BSH_MAX_WIDTH`]. 2: the binary tree
    /// in depth-first pre-order, each subtree a contiguous run (what the
    /// direct pass's tile walk, which deals out subtrees by depth, and the
    /// parallel refit need). Wider: the binary tree's nodes regrouped,
    /// each node taking its children and, while it has fewer than `width`,
    /// opening the inner one of largest sphere (the bounds' spheres, ranges
    /// 0) into its two; a node's children sit side by side (`child` the
    /// first, each one's `next` the following sibling, the last one's its
    /// parent's `next`), families laid out depth first. The walk's step
    /// then mostly reads the cache line it read before: on the path
    /// tracers' trees 4 wide walks in about 0.6 of the binary walk's time
    /// (docs/results/bsh-walk-visits.md).
    pub width: u32,
}

impl BshShape {
    /// Median splits, binary ([`Bsh::build`](super::Bsh::build)): the
    /// direct pass's light hierarchy.
    pub const BALANCED: BshShape = BshShape { split: BshSplit::Median, width: 2 };

    /// Sphere-area splits, 4 wide: the path tracers' light hierarchy.
    pub const WIDE: BshShape = BshShape { split: BshSplit::SphereArea, width: 4 };
}

/// `binary` (a built binary tree in pre-order, refitted) regrouped as
/// [`BshShape::width`] describes, `width` > 2.
pub(super) fn regroup(binary: &[BshNode], width: usize) -> Vec<BshNode> {
    let mut out = vec![BshNode { next: BSH_NONE, ..binary[0] }];
    out.reserve(binary.len());
    place(binary, width, &mut out, 0, 0);
    out
}

/// The children node `i` of `binary` takes: its two, the inner one of
/// largest sphere opened while fewer than `width`.
fn family(binary: &[BshNode], i: u32, width: usize) -> Vec<u32> {
    let two = |j: u32| {
        let c = binary[j as usize].child;
        [c, binary[c as usize].next]
    };
    let mut slots = two(i).to_vec();
    while slots.len() < width {
        let mut open = None;
        for (k, &j) in slots.iter().enumerate() {
            let n = &binary[j as usize];
            if n.child != BSH_NONE
                && open.is_none_or(|(_, r): (usize, f32)| n.radius.total_cmp(&r).is_gt())
            {
                open = Some((k, n.radius));
            }
        }
        let Some((k, _)) = open else { break };
        let [a, b] = two(slots[k]);
        slots[k] = a;
        slots.insert(k + 1, b);
    }
    slots
}

/// Lays out the children of binary node `i`, already placed at `out[at]`,
/// side by side at the end of `out`, then each one's descendants.
fn place(binary: &[BshNode], width: usize, out: &mut Vec<BshNode>, at: usize, i: u32) {
    if binary[i as usize].child == BSH_NONE {
        return;
    }
    let f = family(binary, i, width);
    let first = out.len();
    out[at].child = first as u32;
    let after = out[at].next;
    for (k, &j) in f.iter().enumerate() {
        let next = if k + 1 < f.len() { (first + k + 1) as u32 } else { after };
        out.push(BshNode { next, ..binary[j as usize] });
    }
    for (k, &j) in f.iter().enumerate() {
        place(binary, width, out, first + k, j);
    }
}
