//! Bounding-sphere hierarchy (BSH) over light range spheres (talk: "Build
//! Bounding Sphere Hierarchy", "Improving tree traversal & shading").
//!
//! - **Build** once over [`LightBound`]s, top-down, one light per leaf,
//!   each node's lights split in two by a [`BshSplit`]: at the *median* of
//!   their centres along the longest axis of the centres' box (a balanced
//!   tree, depth `⌈log₂ n⌉`: the direct pass's lights), or by the
//!   *sphere-area heuristic* (the path tracers' lights: fewer visits per
//!   walk, depth at most [`BSH_MAX_DEPTH`]), then laid out
//!   ([`BshShape`]). The lights' bounds, not their random ranges, decide
//!   the tree, so it stays valid when the ranges change.
//! - **Refit** every frame/pass for new random ranges in O(n): leaves become
//!   `(c, R + r)`; each inner node the (f32-conservative) union of its two
//!   children, and the radius about its centre that holds its lights'
//!   bounds without their ranges (what a glossy receiver's walk takes its
//!   range scale over; a wider node's: [`walk::bsh_family_refitted`]),
//!   visited children before parents.
//! - **Layout**: a flat array, the binary tree in depth-first pre-order, or
//!   regrouped 3–8 wide with each node's children side by side
//!   ([`BshShape`]: the path tracers' tree is 4 wide). Each [`BshNode`] has
//!   `child` (its first child, [`BSH_NONE`] for leaves) and `next` (the node
//!   after its subtree, [`BSH_NONE`] at the end), so traversal is the talk's
//!   stackless loop in either:
//!   `i = 0; while i != NONE { if hit(i) { if leaf { visit; i = next } else { i = child } } else { i = next } }`.
//! - **Queries** return exactly the lights whose own range sphere passes the
//!   test (leaf test = brute-force test), because every inner sphere
//!   contains its children in f32 (see [`crate::sphere`]).
//! - **Range tail** (optional, [`Bsh::with_tail`]; issue 30's measurement:
//!   the few largest random ranges inflate every sphere above them): each
//!   refit leaves the lights whose range sphere falls in the top bins of a
//!   histogram of radii ([`bsh_tail_key`], at most `k` lights:
//!   [`tail::bsh_tail_cut`]) out of the tree (their leaves refit with range
//!   0 and marked [`BSH_TAIL`], skipped by the walks) and writes them, in
//!   light order, as leaves after the tree, chained from the nodes whose
//!   `next` ended the walk: every walk then tests them flat after the tree.
//!   The same lights are found; only the inner spheres shrink.

use crate::BshError;
use crate::light::LightBound;
use crate::sphere::{Aabb, Sphere};
use crate::wgsl::*;
use alloc::vec::Vec;
use glam::Vec3;

crate::shared! {
    /// "No node" / "no light" marker in [`BshNode`] links.
    pub const BSH_NONE: u32 = 4294967295;

    /// Bit of a leaf's `light` that marks it as in the range tail this
    /// refit: its range is left out of the tree (its radius is its extent)
    /// and the walks skip it; its copy after the tree holds its range.
    /// Light indices stay below it ([`crate::BshError::TooManyLights`]).
    pub const BSH_TAIL: u32 = 2147483648;

    /// Bins of the range tail's histogram ([`bsh_tail_key`]).
    pub const BSH_TAIL_BINS: u32 = 1024;

    /// The longest range tail: what the GPU's one-invocation sort of the
    /// tail takes (`k²` steps) and what a walk tests flat.
    pub const BSH_TAIL_MAX: u32 = 64;

    /// The range tail's histogram bin of a range-sphere radius `ρ`: the top
    /// ten bits of `|ρ|`'s f32 (its exponent and two mantissa bits: bins
    /// 19% wide), monotone in `ρ ≥ 0`; +∞ falls in bin 1020.
    pub fn bsh_tail_key(radius: f32) -> u32 {
        return (f32_to_bits(radius) & 2147483647) >> 21;
    }

    /// One node of the flat hierarchy; 32 bytes, the same layout in Rust
    /// (`#[repr(C)]`) and WGSL storage buffers.
    pub struct BshNode {
        /// Bounding-sphere centre.
        pub center: vec3f,
        /// Bounding-sphere radius (may be +∞).
        pub radius: f32,
        /// First child, or `BSH_NONE` for a leaf (in a binary tree
        /// `self + 1`; in a wide one the first of its children side by
        /// side, each one's `next` the following one: [`BshShape`]).
        pub child: u32,
        /// Next node after this subtree in pre-order, or `BSH_NONE`.
        pub next: u32,
        /// Light index for a leaf; for an inner node the bits of the
        /// largest random range `r` below it (f32; [`bsh_range_bound`]),
        /// which a glossy receiver's walk needs.
        pub light: u32,
        /// A leaf's light extent `R` (its radius is `R + r`); an inner
        /// node's radius about its centre holding every light bound
        /// `(c, R)` below it, ranges left out
        /// ([`walk::bsh_pair_extent`]): the cone a glossy receiver's
        /// range scale is taken over ([`walk::bsh_reaches`]).
        pub extent: f32,
    }

    /// Radius within which node `node` holds the points a receiver that
    /// scales SLC's range² by `s` (`scale = √s ≥ 1`; [`crate::brdf::range_scale`])
    /// can reach: a leaf's `R + √s·r`, an inner node's radius times `√s`
    /// (which holds its children's scaled spheres: `|C − c| + √s·r_c ≤
    /// √s·(|C − c| + r_c) ≤ √s·R_C`); the radius itself for `scale = 1`.
    pub fn bsh_scaled_radius(node: BshNode, scale: f32) -> f32 {
        if scale == 1.0 {
            return node.radius;
        }
        if node.child == BSH_NONE {
            return node.extent + scale * (node.radius - node.extent);
        }
        return node.radius * scale;
    }

    /// The largest random range `r` of the lights below node `node`: a
    /// leaf's `radius − extent`, an inner node's stored bound (the bits in
    /// its `light` field, written by the refit:
    /// `walk::bsh_pair_range`).
    pub fn bsh_range_bound(node: BshNode) -> f32 {
        if node.child == BSH_NONE {
            return node.radius - node.extent;
        }
        return f32_from_bits(node.light);
    }

    /// The farthest from node `node`'s centre that its lights' ranges,
    /// scaled by at most `w` (a range lobe's `rl.w`), can reach:
    /// `A + 1.001·w·b`, `A` its light extent and `b` its
    /// [`bsh_range_bound`] (a little above the exact reach, for rounding).
    /// [`walk::bsh_reaches`]'s cut for a glossy receiver, and what a
    /// [`BshGrid`] built for a reach `w` covers.
    pub fn bsh_reach_bound(node: BshNode, w: f32) -> f32 {
        return node.extent + w * 1.001 * bsh_range_bound(node);
    }
}

/// The nodes as the shared traversal step reads them: a slice on the CPU.
/// On the GPU a kernel that binds its `bsh_nodes` buffer declares
/// `alias BshNodes = u32` and the two readers [`bsh_node`] and
/// [`bsh_count`] over it, then includes [`walk`]'s WGSL.
pub type BshNodes<'a> = &'a [BshNode];

/// Node `i` of `nodes` (the GPU kernel's reader: `bsh_nodes[i]`).
#[inline]
pub fn bsh_node(nodes: BshNodes, i: u32) -> BshNode {
    nodes[i as usize]
}

/// The number of nodes (the GPU kernel's reader: `arrayLength(&bsh_nodes)`).
#[inline]
pub fn bsh_count(nodes: BshNodes) -> u32 {
    nodes.len() as u32
}

/// The stackless traversal's steps, written once for both backends. Not
/// part of [`crate::wgsl::library`]: they read a BSH buffer, which only the
/// kernels that bind one declare (their WGSL is [`walk::WGSL`]).
pub mod walk {
    use super::{
        BSH_NONE, BshNode, BshNodes, bsh_count, bsh_node, bsh_range_bound, bsh_reach_bound,
        bsh_scaled_radius,
    };
    use super::{BSH_TAIL, bsh_tail_key};
    use crate::importance::{cone_cos_of, range_scale_at, range_scale_toward};
    use crate::light::range_radius;
    use crate::sphere::{sphere_contains_point, sphere_overlaps_aabb, sphere_pad, sphere_union};
    use crate::wgsl::*;

    crate::shared! {
        /// The root, or `BSH_NONE` for an empty hierarchy: where a
        /// traversal starts.
        pub fn bsh_first(nodes: BshNodes) -> u32 {
            if bsh_count(nodes) > 0 {
                return 0;
            }
            return BSH_NONE;
        }

        /// The first leaf at or after node `start` in traversal order
        /// whose range sphere contains `x`, or `BSH_NONE`: one step of the
        /// talk's stackless traversal. Start at [`bsh_first`] and continue
        /// from the found leaf's `next`.
        pub fn bsh_next_leaf(nodes: BshNodes, start: u32, x: vec3f) -> u32 {
            return bsh_next_leaf_lobe(nodes, start, x, x, vec4f(1.0, 0.0, 1.0, 1.0));
        }

        #[inline(always)]
        /// Whether node `node` reaches a receiver at `x` with mirror
        /// direction `r` and range lobe `rl` ([`crate::brdf::range_lobe`]),
        /// which scales each light's range² by its own
        /// `s = range_scale_toward(rl, c, R, x, r)`
        /// ([`crate::importance::range_scale_toward`]): a leaf when its
        /// light's scaled sphere `(c, R + √s·r)` ([`bsh_scaled_radius`])
        /// contains `x`; an inner node `(C, ρ)` when `x` lies within both
        /// `√s_C·ρ` and `A + √s_C·B` of `C`, `s_C` the scale toward the
        /// sphere `(C, A)` of its light bounds (its `extent`, ranges left
        /// out: a far narrower cone than `ρ`'s; it holds every light's bound
        /// below it, so `s_C ≥ s` for each of them, with a relative margin
        /// of 1e-3 against rounding) and `B` the largest range below it
        /// ([`bsh_range_bound`]): a light `j` below reaches `x` only within
        /// `|C − c_j| + R_j + √s_j·r_j` of `C`, at most both bounds (the
        /// first by [`bsh_scaled_radius`]'s argument). Nodes out of reach even at
        /// the receiver's largest scale `rl.w²` are rejected first (also
        /// beyond `A + rl.w·B`, before the scale's four square roots; a
        /// leaf's `A` and `B` are `R` and `r`); for `rl.w ≤ 1` (no specular
        /// lobe) this is the plain sphere test.
        pub fn bsh_reaches(node: BshNode, x: vec3f, r: vec3f, rl: vec4f) -> bool {
            if sphere_contains_point(node.center, node.radius, x) {
                return true;
            }
            if rl.w <= 1.0 || !sphere_contains_point(node.center, node.radius * (rl.w * 1.0001), x) {
                return false;
            }
            let v: vec3f = x - node.center;
            let d2: f32 = dot(v, v);
            let reach_max: f32 = bsh_reach_bound(node, rl.w);
            if d2 > reach_max * reach_max {
                return false;
            }
            if node.child == BSH_NONE {
                let s: f32 = range_scale_toward(rl, node.center, node.extent, x, r);
                return sphere_contains_point(node.center, bsh_scaled_radius(node, sqrt(s)), x);
            }
            let s_c: f32 = bsh_inner_scale(node.extent, -v, d2, r, rl) * 1.001;
            let reach: f32 = node.extent + sqrt(s_c) * bsh_range_bound(node);
            return d2 <= node.radius * node.radius * s_c && d2 <= reach * reach;
        }

        /// An inner node's range scale for [`bsh_reaches`]: at least
        /// [`range_scale_toward`] of its light bounds `(C, A)` for a receiver
        /// at `x = C − v` (`d2 = |v|²`) with mirror direction `r`:
        /// [`crate::importance::range_scale_at`] of
        /// [`crate::importance::cone_cos_of`] (no root where `r` points into
        /// the sphere) raised by 2e-6. The cosine is accurate to about 1e-7,
        /// so a node's scale is never below that of a light beneath it (the
        /// walk finds exactly the leaves' lights).
        pub fn bsh_inner_scale(a: f32, v: vec3f, d2: f32, r: vec3f, rl: vec4f) -> f32 {
            return range_scale_at(rl, cone_cos_of(v, d2, a, r) + 2e-6);
        }

        /// [`bsh_next_leaf`] for a receiver at `x` with mirror direction `r`
        /// and range lobe `rl`: the next leaf that [`bsh_reaches`] `x`.
        pub fn bsh_next_leaf_lobe(nodes: BshNodes, start: u32, x: vec3f, r: vec3f, rl: vec4f) -> u32 {
            let mut i: u32 = start;
            while i != BSH_NONE {
                let node: BshNode = bsh_node(nodes, i);
                if bsh_reaches(node, x, r, rl) {
                    if node.child == BSH_NONE {
                        if (node.light & BSH_TAIL) == 0 {
                            return i;
                        }
                        i = node.next;
                    } else {
                        i = node.child;
                    }
                } else {
                    i = node.next;
                }
            }
            return BSH_NONE;
        }

        /// Whether a light of extent `R` and squared random range `r2`
        /// belongs to the range tail of a refit whose histogram cut is `cut`
        /// ([`super::tail::bsh_tail_cut`]; [`super::BSH_TAIL_BINS`] for none): its range
        /// sphere's radius falls in a bin at or above the cut.
        pub fn bsh_in_tail(extent: f32, r2: f32, cut: u32) -> bool {
            return bsh_tail_key(range_radius(extent, r2)) >= cut;
        }

        /// The node after `i` on the tree's rightmost path (its last
        /// child: the one whose `next` is `i`'s), or `BSH_NONE` at its
        /// leaf: the nodes whose `next` ends a walk of the tree, which the
        /// refit points at the range tail. Read it before rewriting `i`'s
        /// `next`.
        pub fn bsh_rightmost_next(nodes: BshNodes, i: u32) -> u32 {
            let node: BshNode = bsh_node(nodes, i);
            if node.child == BSH_NONE {
                return BSH_NONE;
            }
            let mut c: u32 = node.child;
            while bsh_node(nodes, c).next != node.next {
                c = bsh_node(nodes, c).next;
            }
            return c;
        }

        /// Leaf `node` refitted for its light's bound `bound` (centre,
        /// extent `R`) and squared random range `r2` under the range
        /// tail's cut `cut`: the sphere `(c, R + √r2)`, or for a light in
        /// the tail ([`bsh_in_tail`]) `(c, R)` with the [`BSH_TAIL`] mark
        /// on its light index; its links kept. What both refits write.
        pub fn bsh_leaf_refitted(node: BshNode, bound: vec4f, r2: f32, cut: u32) -> BshNode {
            let in_tail: bool = bsh_in_tail(bound.w, r2, cut);
            let mut leaf: BshNode = node;
            leaf.center = vec3f(bound.x, bound.y, bound.z);
            leaf.radius = range_radius(bound.w, select(r2, 0.0, in_tail));
            leaf.extent = bound.w;
            leaf.light = (node.light & (BSH_TAIL - 1)) | select(0, BSH_TAIL, in_tail);
            return leaf;
        }

        /// Inner node `node` refitted from all its children (`child`, then
        /// each one's `next` up to `node`'s own): [`bsh_inner_refitted`]
        /// over the first two, then the result with each further child.
        /// For a binary node it is [`bsh_inner_refitted`]'s result, bit
        /// for bit. What the GPU's refit writes, and the CPU's for a wide
        /// tree.
        pub fn bsh_family_refitted(nodes: BshNodes, node: BshNode) -> BshNode {
            let first: BshNode = bsh_node(nodes, node.child);
            let second: BshNode = bsh_node(nodes, first.next);
            let mut acc: BshNode = bsh_inner_refitted(node, first, second);
            let mut c: u32 = second.next;
            while c != node.next {
                let n: BshNode = bsh_node(nodes, c);
                acc = bsh_inner_refitted(acc, acc, n);
                c = n.next;
            }
            return acc;
        }

        /// Light `li`'s copy in the range tail, linked to `next`: a leaf
        /// holding its bound `bound` with its squared range `r2`, which
        /// the walks test flat after the tree. Every field is written
        /// (`slot` only gives the struct: shared code cannot construct
        /// one). What both refits write after the tree.
        pub fn bsh_tail_leaf(slot: BshNode, bound: vec4f, r2: f32, li: u32, next: u32) -> BshNode {
            let mut leaf: BshNode = slot;
            leaf.center = vec3f(bound.x, bound.y, bound.z);
            leaf.radius = range_radius(bound.w, r2);
            leaf.child = BSH_NONE;
            leaf.next = next;
            leaf.light = li;
            leaf.extent = bound.w;
            return leaf;
        }

        /// Light `li`'s leaf `i` as a walk would test it: the leaf itself,
        /// or, where the refit put its light in the range tail
        /// ([`BSH_TAIL`]), its copy after the tree, which holds its range
        /// (found on the chain from the root's `next`).
        pub fn bsh_range_leaf(nodes: BshNodes, i: u32) -> BshNode {
            let leaf: BshNode = bsh_node(nodes, i);
            if (leaf.light & BSH_TAIL) == 0 {
                return leaf;
            }
            let li: u32 = leaf.light & (BSH_TAIL - 1);
            let mut t: u32 = bsh_node(nodes, 0).next;
            while t != BSH_NONE {
                let copy: BshNode = bsh_node(nodes, t);
                if copy.light == li {
                    return copy;
                }
                t = copy.next;
            }
            return leaf;
        }

        /// Depth of the subtrees the direct pass's tile walk deals out
        /// among a tile's invocations ([`bsh_subtree`]).
        pub const BSH_TILE_DEPTH: u32 = 8;

        /// Their number, `2^BSH_TILE_DEPTH`.
        pub const BSH_TILE_SUBTREES: u32 = 256;

        /// Whether node `node` may reach some receiver in the box
        /// `[lo, hi]` whose range lobes' largest scale `rl.w` is at most
        /// `w`: [`bsh_reaches`]'s outer bound (`node.radius · max(1,
        /// 1.0001·w)`, past which it rejects every point) tested against
        /// the box, padded by another 1e-4 so that a point's test rounded
        /// differently elsewhere never accepts a node this rejects. A
        /// superset of [`bsh_reaches`] for every point of the box: the
        /// direct pass's tile walk (one walk per tile, then each pixel's
        /// exact test in the same order).
        pub fn bsh_reaches_box(node: BshNode, lo: vec3f, hi: vec3f, w: f32) -> bool {
            return sphere_overlaps_aabb(node.center, node.radius * (max(1.0, w * 1.0001) * 1.0001), lo, hi);
        }

        /// The root of subtree `s` of the `2^depth` at depth `depth`
        /// (bit `depth − 1 − j` of `s` picks the child at level `j`: 0 the
        /// first, 1 the second), or `BSH_NONE` where the tree has no node
        /// there. A leaf above depth `depth` (1..=31) is the subtree of its
        /// leftmost index (the one whose lower bits are 0); the others are
        /// empty.
        /// The subtrees in index order hold the leaves in traversal order,
        /// each leaf once. Binary trees only (the direct pass's:
        /// [`super::BshShape::BALANCED`]).
        pub fn bsh_subtree(nodes: BshNodes, s: u32, depth: u32) -> u32 {
            let mut i: u32 = bsh_first(nodes);
            let mut level: u32 = 0;
            while level < depth && i != BSH_NONE {
                let node: BshNode = bsh_node(nodes, i);
                let below: u32 = depth - level;
                if node.child == BSH_NONE {
                    if (s << (32 - below)) != 0 {
                        return BSH_NONE;
                    }
                    return i;
                }
                if ((s >> (below - 1)) & 1) == 0 {
                    i = node.child;
                } else {
                    i = bsh_node(nodes, node.child).next;
                }
                level += 1;
            }
            return i;
        }

        /// The first leaf at or after node `start`, before node `end`
        /// (the node after the subtree being walked; `BSH_NONE` for the
        /// whole tree), that [`bsh_reaches_box`] the box `[lo, hi]` at
        /// scale `w`, or `end`.
        pub fn bsh_next_leaf_box(nodes: BshNodes, start: u32, end: u32, lo: vec3f, hi: vec3f, w: f32) -> u32 {
            let mut i: u32 = start;
            while i != end {
                let node: BshNode = bsh_node(nodes, i);
                if bsh_reaches_box(node, lo, hi, w) {
                    if node.child == BSH_NONE {
                        if (node.light & BSH_TAIL) == 0 {
                            return i;
                        }
                        i = node.next;
                    } else {
                        i = node.child;
                    }
                } else {
                    i = node.next;
                }
            }
            return end;
        }

        /// Inner node `node` refitted from its children `left` and
        /// `right`: the union of their spheres ([`bsh_pair_sphere`]), the
        /// radius about its new centre holding their light bounds
        /// ([`bsh_pair_extent`]) and, as the bits of `light`, the largest
        /// range below it ([`bsh_pair_range`]); its links kept. What both
        /// refits write.
        pub fn bsh_inner_refitted(node: BshNode, left: BshNode, right: BshNode) -> BshNode {
            let u: vec4f = bsh_pair_sphere(left, right);
            let mut inner: BshNode = node;
            inner.center = vec3f(u.x, u.y, u.z);
            inner.radius = u.w;
            inner.extent = bsh_pair_extent(left, right, inner.center);
            inner.light = f32_to_bits(bsh_pair_range(left, right));
            return inner;
        }

        /// The union of an inner node's two children's spheres, `(centre,
        /// radius)`.
        pub fn bsh_pair_sphere(left: BshNode, right: BshNode) -> vec4f {
            return sphere_union(left.center, left.radius, right.center, right.radius);
        }

        /// An inner node's light-bound radius about its new centre
        /// `center`: `max(|center − c_k| + A_k)` over its two children `k`
        /// (a leaf's `A` is its light's extent `R`), padded like a sphere
        /// union.
        pub fn bsh_pair_extent(left: BshNode, right: BshNode, center: vec3f) -> f32 {
            let vl: vec3f = left.center - center;
            let vr: vec3f = right.center - center;
            let a: f32 = max(sqrt(dot(vl, vl)) + left.extent, sqrt(dot(vr, vr)) + right.extent);
            return a + sphere_pad(a, center);
        }

        /// An inner node's largest range below it: the larger of its two
        /// children's [`bsh_range_bound`].
        pub fn bsh_pair_range(left: BshNode, right: BshNode) -> f32 {
            return max(bsh_range_bound(left), bsh_range_bound(right));
        }
    }
}

/// The range tail's histogram as the shared cut reads it: a slice of
/// [`BSH_TAIL_BINS`] counts on the CPU; the GPU's `bsh_tail` kernel
/// declares `alias TailHist = u32` and the readers [`bsh_tail_bin`] and
/// [`bsh_tail_chunk`] over a copy in workgroup memory, then includes
/// [`tail`]'s WGSL.
pub type TailHist<'a> = &'a [u32];

/// Bin `b` of `hist`.
#[inline]
pub fn bsh_tail_bin(hist: TailHist, b: u32) -> u32 {
    hist[b as usize]
}

/// The lights in chunk `c` of `hist`: bins `c·32 .. c·32 + 32`
/// ([`tail::BSH_TAIL_CHUNK`]; the GPU kernel sums them in parallel).
#[inline]
pub fn bsh_tail_chunk(hist: TailHist, c: u32) -> u32 {
    let w = tail::BSH_TAIL_CHUNK as usize;
    hist[c as usize * w..][..w].iter().sum()
}

/// The range tail's selection, written once for both backends (its WGSL
/// is [`tail::WGSL`], which only the GPU's `bsh_tail` kernel includes).
pub mod tail {
    use super::{BSH_TAIL_BINS, TailHist, bsh_tail_bin, bsh_tail_chunk};
    use crate::wgsl::*;

    crate::shared! {
        /// Bins per chunk of the cut's first, coarse scan (32 chunks).
        pub const BSH_TAIL_CHUNK: u32 = 32;

        /// The range tail's cut: the lowest bin `b` such that the bins from
        /// `b` up hold at most `k` lights of the histogram `hist` (read
        /// through `bsh_tail_chunk` and `bsh_tail_bin`); [`BSH_TAIL_BINS`]
        /// when the top bin alone holds more. The lights at or above it are
        /// the tail: the `k` largest spheres or fewer (a bin is all in or
        /// all out), the same on both backends. Whole chunks from the top
        /// first, then the bins of the chunk that does not fit: at most 64
        /// steps.
        pub fn bsh_tail_cut(hist: TailHist, k: u32) -> u32 {
            let mut c: u32 = BSH_TAIL_BINS / BSH_TAIL_CHUNK;
            let mut sum: u32 = 0;
            while c > 0 && sum + bsh_tail_chunk(hist, c - 1) <= k {
                sum += bsh_tail_chunk(hist, c - 1);
                c -= 1;
            }
            let mut b: u32 = c * BSH_TAIL_CHUNK;
            let end: u32 = b - min(b, BSH_TAIL_CHUNK);
            while b > end && sum + bsh_tail_bin(hist, b - 1) <= k {
                sum += bsh_tail_bin(hist, b - 1);
                b -= 1;
            }
            return b;
        }

    }
}

/// Bounding-sphere hierarchy; see the module docs.
#[derive(Clone, Debug, PartialEq)]
pub struct Bsh {
    nodes: Vec<BshNode>,
    bounds: Vec<LightBound>,
    /// Each light's leaf (node index).
    leaves: Vec<u32>,
    /// The range tail's length limit `k` (0: no tail); its `k` slots follow
    /// the tree in `nodes`.
    tail: usize,
    /// Nodes of the tree proper (the tail's slots follow them).
    tree: usize,
    /// Children per inner node ([`BshShape::width`]).
    width: u32,
}

/// The empty tree ([`Bsh::build`] over no lights).
impl Default for Bsh {
    fn default() -> Self {
        Bsh {
            nodes: Vec::new(),
            bounds: Vec::new(),
            leaves: Vec::new(),
            tail: 0,
            tree: 0,
            width: 2,
        }
    }
}

impl Bsh {
    /// Builds the tree over `bounds` (one per light, in light order). Every
    /// centre must be finite and every extent finite and `≥ 0`; such input is
    /// rejected here, before it can reach the tree. Leaf radii start at the
    /// extents (random range 0) until [`Bsh::refit`].
    pub fn build(bounds: &[LightBound]) -> Result<Self, BshError> {
        Self::build_with(bounds, BshShape::BALANCED)
    }

    /// Whether [`Bsh::build`] takes `bounds`: fewer lights than 32-bit links
    /// address, every centre finite, every extent finite and `≥ 0`; the
    /// first bound that is not, as the build's error.
    pub fn check(bounds: &[LightBound]) -> Result<(), BshError> {
        if bounds.len() >= BSH_NONE as usize / 2 {
            return Err(BshError::TooManyLights(bounds.len()));
        }
        for (i, b) in bounds.iter().enumerate() {
            if !b.center.is_finite() {
                return Err(BshError::NonFiniteCenter(i));
            }
            if !(b.extent.is_finite() && b.extent >= 0.0) {
                return Err(BshError::BadExtent(i, b.extent));
            }
        }
        Ok(())
    }

    /// [`Bsh::build`] in the shape `shape` ([`BshShape`]: the split rule and
    /// the children per node).
    pub fn build_with(bounds: &[LightBound], shape: BshShape) -> Result<Self, BshError> {
        if !(2..=BSH_MAX_WIDTH).contains(&shape.width) {
            return Err(BshError::BadWidth(shape.width));
        }
        Self::check(bounds)?;
        let mut bsh = Bsh {
            nodes: Vec::with_capacity(2 * bounds.len()),
            bounds: bounds.to_vec(),
            leaves: Vec::new(),
            tail: 0,
            tree: 0,
            width: 2,
        };
        if !bounds.is_empty() {
            let mut idx: Vec<u32> = (0..bounds.len() as u32).collect();
            bsh.emit(&mut idx, BSH_NONE, shape.split, 0);
        }
        bsh.tree = bsh.nodes.len();
        bsh.index_leaves();
        let zero = alloc::vec![0.0; bounds.len()];
        bsh.refit(&zero)?;
        bsh.width = shape.width;
        if shape.width > 2 && bsh.tree > 1 {
            bsh.nodes = layout::regroup(&bsh.nodes, shape.width as usize);
            bsh.tree = bsh.nodes.len();
            bsh.index_leaves();
            bsh.refit(&zero)?;
        }
        Ok(bsh)
    }

    /// Each light's leaf, from the tree's leaves.
    fn index_leaves(&mut self) {
        self.leaves = alloc::vec![BSH_NONE; self.bounds.len()];
        for (i, n) in self.nodes.iter().enumerate().filter(|(_, n)| n.child == BSH_NONE) {
            self.leaves[(n.light & (BSH_TAIL - 1)) as usize] = i as u32;
        }
    }

    /// Children per inner node ([`BshShape::width`]).
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Each tree node's depth (the root's is 0), in node order: what the
    /// GPU's refit orders its levels by. A node's children follow it in
    /// the array, in either layout.
    pub fn depths(&self) -> Vec<u32> {
        let mut depth = alloc::vec![0u32; self.tree];
        for i in 0..self.tree {
            let n = self.nodes[i];
            let mut c = n.child;
            while c != BSH_NONE && c != n.next {
                depth[c as usize] = depth[i] + 1;
                c = self.nodes[c as usize].next;
            }
        }
        depth
    }

    /// Emits the subtree over `idx` in pre-order, its root at `depth`;
    /// `next` is the link to store in the subtree's root.
    fn emit(&mut self, idx: &mut [u32], next: u32, rule: BshSplit, depth: u32) {
        let me = self.nodes.len() as u32;
        if idx.len() == 1 {
            let c = self.bounds[idx[0] as usize].center;
            self.nodes.push(BshNode {
                center: c,
                radius: 0.0,
                child: BSH_NONE,
                next,
                light: idx[0],
                extent: self.bounds[idx[0] as usize].extent,
            });
            return;
        }
        self.nodes.push(BshNode {
            center: Vec3::ZERO,
            radius: 0.0,
            child: me + 1,
            next,
            light: BSH_NONE,
            extent: 0.0,
        });
        let mid = split::split(&self.bounds, idx, rule, depth);
        let (left, right) = idx.split_at_mut(mid);
        // The right child's index is known only after the left subtree:
        // a subtree over m lights has 2m − 1 nodes.
        let right_root = me + 1 + (2 * left.len() as u32 - 1);
        self.emit(left, right_root, rule, depth + 1);
        self.emit(right, next, rule, depth + 1);
    }

    /// The tree with a range tail of at most `k` lights (module docs): from
    /// the next refit on, the lights whose range spheres fall in the
    /// histogram's top bins, at most `k` ([`tail::bsh_tail_cut`]), are
    /// tested flat after the tree. Walks find the same lights; `k = 0`
    /// takes the tail away. At most [`BSH_TAIL_MAX`]. The ranges start at 0
    /// again (as after [`Bsh::build`]) until the next refit.
    pub fn with_tail(mut self, k: usize) -> Result<Bsh, BshError> {
        if k > BSH_TAIL_MAX as usize {
            return Err(BshError::TailTooLong(k));
        }
        let tree = self.tree_len();
        self.nodes.truncate(tree);
        self.tail = k;
        let mut i = if tree == 0 { BSH_NONE } else { 0 };
        while i != BSH_NONE {
            let last = walk::bsh_rightmost_next(&self.nodes, i);
            self.nodes[i as usize].next = BSH_NONE;
            i = last;
        }
        if !self.nodes.is_empty() {
            let slot = BshNode { child: BSH_NONE, next: BSH_NONE, ..self.nodes[0] };
            self.nodes.resize(tree + k, slot);
            self.refit(&alloc::vec![0.0; self.bounds.len()])?;
        }
        Ok(self)
    }

    /// The range tail's length limit (0: none; [`Bsh::with_tail`]).
    pub fn tail_capacity(&self) -> usize {
        self.tail
    }

    /// Nodes of the tree proper: the range tail's slots follow them.
    pub fn tree_len(&self) -> usize {
        self.tree
    }

    /// Refits every sphere for new squared random ranges, one per light
    /// (`r2[i]` for light `i`, as from [`crate::range::random_range2`]).
    /// O(n). `r2` must have one finite-or-+∞, non-negative value per light.
    pub fn refit(&mut self, r2: &[f32]) -> Result<(), BshError> {
        self.refit_split(r2, usize::MAX, &serial_join)
    }

    /// [`Bsh::refit`] with the two subtrees of every node whose subtree
    /// has more than `grain` nodes refitted by `join(left, right)`, which
    /// may run the two at once (the CPU path tracer passes rayon's
    /// `join`): the same nodes, bit for bit (each node is a function of its
    /// children alone, and a subtree is a contiguous run of the pre-order
    /// array). A wide tree ([`BshShape::width`] > 2), whose subtrees are
    /// not contiguous, refits serially.
    pub fn refit_split(&mut self, r2: &[f32], grain: usize, join: &Join) -> Result<(), BshError> {
        self.check_ranges(r2)?;
        if self.nodes.is_empty() {
            return Ok(());
        }
        let cut = self.tail_cut(r2);
        let tree = self.tree_len();
        let leaf = LeafRefit { bounds: &self.bounds, r2, cut };
        if self.width == 2 {
            refit_subtree(&mut self.nodes[..tree], 0, &leaf, grain.max(1), join);
        } else {
            refit_wide(&mut self.nodes[..tree], &leaf);
        }
        if self.tail > 0 {
            self.link_tail(r2, cut);
        }
        Ok(())
    }

    /// The range tail's cut for ranges `r2`: the histogram of the lights'
    /// range-sphere bins ([`bsh_tail_key`]) cut at the tail's length
    /// ([`tail::bsh_tail_cut`]); [`BSH_TAIL_BINS`] (nothing) without a tail.
    fn tail_cut(&self, r2: &[f32]) -> u32 {
        if self.tail == 0 {
            return BSH_TAIL_BINS;
        }
        let mut hist = alloc::vec![0u32; BSH_TAIL_BINS as usize];
        for (b, &r) in self.bounds.iter().zip(r2) {
            hist[bsh_tail_key(crate::light::range_radius(b.extent, r)) as usize] += 1;
        }
        tail::bsh_tail_cut(&hist, self.tail as u32)
    }

    /// Writes the tail's lights (those at or above `cut`, in light order)
    /// as leaves after the tree, chained, and points the tree's rightmost
    /// path at the first (`BSH_NONE` when the tail is empty): what the
    /// GPU's `bsh_tail` kernel writes.
    fn link_tail(&mut self, r2: &[f32], cut: u32) {
        let tree = self.tree_len();
        let mut count = 0;
        for (li, (b, &r)) in self.bounds.iter().zip(r2).enumerate() {
            if walk::bsh_in_tail(b.extent, r, cut) {
                let at = tree + count;
                let bound = b.center.extend(b.extent);
                self.nodes[at] =
                    walk::bsh_tail_leaf(self.nodes[at], bound, r, li as u32, at as u32 + 1);
                count += 1;
            }
        }
        let first = if count == 0 {
            BSH_NONE
        } else {
            self.nodes[tree + count - 1].next = BSH_NONE;
            tree as u32
        };
        let mut i = 0;
        while i != BSH_NONE {
            let last = walk::bsh_rightmost_next(&self.nodes, i);
            self.nodes[i as usize].next = first;
            i = last;
        }
    }

    /// `r2` has one finite-or-+∞, non-negative value per light.
    fn check_ranges(&self, r2: &[f32]) -> Result<(), BshError> {
        if r2.len() != self.bounds.len() {
            return Err(BshError::RangeCount { expected: self.bounds.len(), got: r2.len() });
        }
        if let Some(i) = r2.iter().position(|r| !(*r >= 0.0)) {
            return Err(BshError::BadRange(i, r2[i]));
        }
        Ok(())
    }

    /// Light `i`'s leaf as the last refit left it, with its range: for a
    /// light in the range tail, its copy after the tree
    /// ([`walk::bsh_range_leaf`]).
    pub fn leaf(&self, i: usize) -> BshNode {
        walk::bsh_range_leaf(&self.nodes, self.leaves[i])
    }

    /// Each light's leaf: its node index in the tree (in light order).
    pub fn leaf_indices(&self) -> &[u32] {
        &self.leaves
    }

    /// The flat node array (upload as-is to the GPU).
    pub fn nodes(&self) -> &[BshNode] {
        &self.nodes
    }

    /// Number of lights.
    pub fn len(&self) -> usize {
        self.bounds.len()
    }

    /// `true` when built over no light.
    pub fn is_empty(&self) -> bool {
        self.bounds.is_empty()
    }

    /// The current range sphere of light `i` (as its leaf holds it).
    pub fn light_sphere(&self, i: usize) -> Option<Sphere> {
        (i < self.leaves.len()).then(|| {
            let l = self.leaf(i);
            Sphere::new(l.center, l.radius)
        })
    }

    /// The talk's stackless traversal: calls `visit(light)` for every leaf
    /// whose sphere passes `hit`, testing inner nodes with the same `hit`
    /// (which must be monotone: a sphere containing one that passes, passes).
    pub fn traverse(&self, mut hit: impl FnMut(Vec3, f32) -> bool, mut visit: impl FnMut(u32)) {
        let mut i = if self.nodes.is_empty() { BSH_NONE } else { 0 };
        while i != BSH_NONE {
            let n = &self.nodes[i as usize];
            if hit(n.center, n.radius) {
                if n.child == BSH_NONE {
                    if n.light & BSH_TAIL == 0 {
                        visit(n.light);
                    }
                    i = n.next;
                } else {
                    i = n.child;
                }
            } else {
                i = n.next;
            }
        }
    }

    /// Lights whose range sphere contains `x` (none for a NaN point), by
    /// the shared traversal steps ([`walk`]) the GPU kernels take.
    pub fn for_each_containing(&self, x: Vec3, visit: impl FnMut(u32)) {
        self.for_each_reaching(x, x, glam::Vec4::new(1.0, 0.0, 1.0, 1.0), visit);
    }

    /// Lights whose range sphere, scaled for a receiver at `x` with mirror
    /// direction `r` and range lobe `rl` ([`walk::bsh_reaches`]), contains
    /// `x` (none for a NaN point).
    pub fn for_each_reaching(&self, x: Vec3, r: Vec3, rl: glam::Vec4, mut visit: impl FnMut(u32)) {
        if x.is_nan() {
            return;
        }
        let nodes = &self.nodes[..];
        let mut i = walk::bsh_next_leaf_lobe(nodes, walk::bsh_first(nodes), x, r, rl);
        while i != BSH_NONE {
            let leaf = bsh_node(nodes, i);
            visit(leaf.light);
            i = walk::bsh_next_leaf_lobe(nodes, leaf.next, x, r, rl);
        }
    }

    /// Lights whose range sphere overlaps sphere `s` (none when `s` is not
    /// [`Sphere::is_valid`]: NaN, or a negative radius).
    pub fn for_each_overlapping_sphere(&self, s: Sphere, visit: impl FnMut(u32)) {
        if !s.is_valid() {
            return;
        }
        self.traverse(
            |c, r| crate::sphere::sphere_overlaps_sphere(c, r, s.center, s.radius),
            visit,
        );
    }

    /// Lights whose range sphere overlaps box `b` (none when `b` has NaN).
    pub fn for_each_overlapping_aabb(&self, b: Aabb, visit: impl FnMut(u32)) {
        if b.min.is_nan() || b.max.is_nan() {
            return;
        }
        self.traverse(|c, r| crate::sphere::sphere_overlaps_aabb(c, r, b.min, b.max), visit);
    }
}

/// How [`Bsh::refit_split`] runs two subtrees' refits: both, in any
/// order or at once.
pub type Join = dyn Fn(&mut (dyn FnMut() + Send), &mut (dyn FnMut() + Send)) + Sync;

/// [`Join`] on one thread: the first, then the second.
fn serial_join(a: &mut (dyn FnMut() + Send), b: &mut (dyn FnMut() + Send)) {
    a();
    b();
}

/// What a leaf's refit reads: the lights' bounds, their squared ranges
/// and the range tail's cut.
struct LeafRefit<'a> {
    bounds: &'a [LightBound],
    r2: &'a [f32],
    cut: u32,
}

impl LeafRefit<'_> {
    /// A leaf refitted: its light's range sphere `(c, R + r)`, or for a
    /// light in the range tail ([`walk::bsh_in_tail`]) `(c, R)`, marked
    /// [`BSH_TAIL`].
    fn leaf(&self, n: BshNode) -> BshNode {
        let li = (n.light & (BSH_TAIL - 1)) as usize;
        let b = &self.bounds[li];
        walk::bsh_leaf_refitted(n, b.center.extend(b.extent), self.r2[li], self.cut)
    }
}

/// Refits the subtree that is all of `nodes`, its root `nodes[0]` at index
/// `base` of the whole array (links are absolute): subtrees above `grain`
/// nodes split in two through `join`, smaller ones in reverse pre-order.
fn refit_subtree(nodes: &mut [BshNode], base: u32, leaf: &LeafRefit, grain: usize, join: &Join) {
    // A leaf is a subtree of one node (`grain ≥ 1`).
    if nodes.len() <= grain {
        for k in (0..nodes.len()).rev() {
            let n = nodes[k];
            nodes[k] = if n.child == BSH_NONE {
                leaf.leaf(n)
            } else {
                let left = nodes[(n.child - base) as usize];
                walk::bsh_inner_refitted(n, left, nodes[(left.next - base) as usize])
            };
        }
        return;
    }
    // The left child's subtree runs up to the right child.
    let right_at = (nodes[1].next - base) as usize;
    let (head, rest) = nodes.split_at_mut(1);
    let (left, right) = rest.split_at_mut(right_at - 1);
    join(&mut || refit_subtree(left, base + 1, leaf, grain, join), &mut || {
        refit_subtree(right, base + right_at as u32, leaf, grain, join)
    });
    head[0] = walk::bsh_inner_refitted(head[0], left[0], right[0]);
}

/// Refits a wide tree ([`BshShape::width`] > 2) serially, children before
/// parents (its subtrees are not contiguous runs to split).
fn refit_wide(nodes: &mut [BshNode], leaf: &LeafRefit) {
    for k in (0..nodes.len()).rev() {
        let n = nodes[k];
        nodes[k] =
            if n.child == BSH_NONE { leaf.leaf(n) } else { walk::bsh_family_refitted(&*nodes, n) };
    }
}

pub mod grid;
mod layout;
mod split;
pub use grid::{
    BshGrid, GRID_ENTRIES_PER_LIGHT, GRID_RES_LIMIT, GRID_RES_MAX, GRID_RES_MIN, GridFrame,
};
pub use layout::{BSH_MAX_WIDTH, BshShape};
pub use split::{BSH_MAX_DEPTH, BshSplit};

#[cfg(test)]
mod tests;
