//! Sampling a light BVH (the `lightbvh` baseline; Conty Estevez & Kulla,
//! "Importance Sampling of Many Lights with Adaptive Tree Splitting", HPG
//! 2018, as pbrt-v4's `BVHLightSampler` does it: Pharr, Jakob & Humphreys,
//! *PBR* 4th ed., §12.6.3).
//!
//! The tree is binary, one light per leaf, in preorder: an interior node
//! `i`'s first child is `i + 1` and its second child `second`, so the first
//! child's subtree is the index range `i + 1 .. second`. A sample walks from
//! the root, at each node choosing a child with probability proportional to
//! the [`light_importance`](crate::importance::light_importance) of its bounds at the shading point
//! ([`bvh_first_prob`]) and reusing the uniform number ([`bvh_remap_u`]);
//! the light's pmf is the product of the choices. The pmf of a given light
//! (for MIS at a BSDF-sampled hit) takes the same walk towards its leaf,
//! choosing the child whose index range holds the leaf.
//!
//! The step functions are shared with the GPU; [`light_bvh_sample`] and
//! [`light_bvh_pmf`] are the CPU's walks (the GPU's are in
//! slc-shared-shaders' `pt_mis.wgsl`, over the same nodes packed as
//! `GpuLightBvhNode`). slc-scene builds the tree.

use crate::importance::LightCone;
use crate::wgsl::*;
use glam::Vec3;

crate::shared! {
    /// `second` of a light-BVH leaf; also "no leaf" for a light left out of
    /// the tree (zero power).
    pub const LIGHT_BVH_LEAF: u32 = 4294967295;

    /// Largest `f32` below 1 (`1 − 2⁻²⁴`).
    pub const ONE_MINUS_EPSILON: f32 = 0.99999994;

    /// Probability of descending into the first child of an interior node
    /// whose children have importances `c0` and `c1` at the shading point:
    /// `c0 / (c0 + c1)`; or −1 where neither child can light the point
    /// (then there is no sample, as in pbrt-v4).
    pub fn bvh_first_prob(c0: f32, c1: f32) -> f32 {
        let s: f32 = c0 + c1;
        if s > 0.0 {
            return c0 / s;
        }
        return -1.0;
    }

    /// The uniform number `u ∈ [0, 1)` rescaled to `[0, 1)` after it chose
    /// the first child (`first`, `u < p0`) or the second, `p0` the first
    /// child's probability.
    pub fn bvh_remap_u(u: f32, p0: f32, first: bool) -> f32 {
        if first {
            return min(u / p0, ONE_MINUS_EPSILON);
        }
        return clamp((u - p0) / (1.0 - p0), 0.0, ONE_MINUS_EPSILON);
    }
}

/// One node of a light BVH: the bounds of its lights (a sphere, their
/// total power, the cone of their normals) and its links.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightBvhNode {
    /// Bounds of the node's lights.
    pub cone: LightCone,
    /// Interior node: the second child's index (the first is the next
    /// node); leaf: [`LIGHT_BVH_LEAF`].
    pub second: u32,
    /// Leaf: its light's index; interior: [`LIGHT_BVH_LEAF`].
    pub light: u32,
}

impl LightBvhNode {
    /// Whether the node is a leaf.
    pub fn is_leaf(&self) -> bool {
        self.second == LIGHT_BVH_LEAF
    }
}

/// The first-child probability at interior node `i` for shading point `p`
/// with normal `n` (zero: none), or `None` where the walk ends (a child
/// index out of the table or not after `i`, or [`bvh_first_prob`] < 0).
fn first_prob(nodes: &[LightBvhNode], i: usize, p: Vec3, n: Vec3) -> Option<f32> {
    let j = nodes[i].second as usize;
    if j <= i + 1 {
        return None;
    }
    let second = nodes.get(j)?;
    let first = nodes.get(i + 1)?;
    let p0 = bvh_first_prob(first.cone.importance(p, n), second.cone.importance(p, n));
    (p0 >= 0.0).then_some(p0)
}

/// Samples one light of the tree `nodes` for shading point `p` with normal
/// `n` and uniform `u ∈ [0, 1)`: `(light, pmf)`, or `None` where no light
/// can light the point (or the tree is empty). A lone leaf is sampled only
/// where its importance is positive.
pub fn light_bvh_sample(nodes: &[LightBvhNode], p: Vec3, n: Vec3, mut u: f32) -> Option<(u32, f32)> {
    let mut i = 0usize;
    let mut pmf = 1.0f32;
    loop {
        let node = nodes.get(i)?;
        if node.is_leaf() {
            return (i > 0 || node.cone.importance(p, n) > 0.0).then_some((node.light, pmf));
        }
        let p0 = first_prob(nodes, i, p, n)?;
        let first = u < p0;
        pmf *= if first { p0 } else { 1.0 - p0 };
        u = bvh_remap_u(u, p0, first);
        i = if first { i + 1 } else { node.second as usize };
    }
}

/// Probability that [`light_bvh_sample`] at `(p, n)` picks the light whose
/// leaf is node `leaf` ([`LIGHT_BVH_LEAF`]: a light not in the tree, 0).
pub fn light_bvh_pmf(nodes: &[LightBvhNode], leaf: u32, p: Vec3, n: Vec3) -> f32 {
    let mut i = 0usize;
    let mut pmf = 1.0f32;
    if leaf as usize >= nodes.len() {
        return 0.0;
    }
    loop {
        let node = &nodes[i];
        if node.is_leaf() {
            let reaches = i > 0 || node.cone.importance(p, n) > 0.0;
            return if i == leaf as usize && reaches { pmf } else { 0.0 };
        }
        let Some(p0) = first_prob(nodes, i, p, n) else { return 0.0 };
        let first = leaf < node.second;
        pmf *= if first { p0 } else { 1.0 - p0 };
        i = if first { i + 1 } else { node.second as usize };
    }
}
