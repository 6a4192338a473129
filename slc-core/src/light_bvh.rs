//! Sampling a light BVH (the `lightbvh` baseline; Conty Estevez & Kulla,
//! "Importance Sampling of Many Lights with Adaptive Tree Splitting", HPG
//! 2018, as pbrt-v4's `BVHLightSampler` does it: Pharr, Jakob & Humphreys,
//! *PBR* 4th ed., §12.6.3).
//!
//! The tree is binary, one light per leaf, in preorder: an interior node
//! `i`'s first child is `i + 1` and its second child `second`, so the first
//! child's subtree is the index range `i + 1 .. second`. A sample walks from
//! the root, at each node choosing a child with probability proportional to
//! the [`receiver_importance`](crate::importance::receiver_importance) of its bounds at the shading point
//! (pbrt-v4's importance for a Lambertian receiver; a glossy receiver's
//! lobe weighs it too)
//! ([`bvh_first_prob`]) and reusing the uniform number ([`bvh_remap_u`]);
//! the light's pmf is the product of the choices. The pmf of a given light
//! (for MIS at a BSDF-sampled hit) takes the same walk towards its leaf,
//! choosing the child whose index range holds the leaf.
//!
//! The step functions and the walks ([`walk::light_bvh_sample`],
//! [`walk::light_bvh_pmf`]) are shared with the GPU, over the nodes packed
//! as [`GpuLightBvhNode`]. slc-scene builds the tree.

use crate::importance::LightCone;
use crate::wgsl::*;

crate::shared! {
    /// `second` of a light-BVH leaf; also "no leaf" for a light left out of
    /// the tree (zero power).
    pub const LIGHT_BVH_LEAF: u32 = 4294967295;

    /// A light-BVH node, as both backends' walks read it: its lights'
    /// importance bounds and its links; 48 bytes, the same layout in Rust
    /// and in WGSL storage buffers.
    pub struct GpuLightBvhNode {
        /// Bounding-sphere centre.
        pub center: vec3f,
        /// Bounding-sphere radius.
        pub radius: f32,
        /// Axis of the normal cone.
        pub axis: vec3f,
        /// Cosine of the normal cone's half-angle.
        pub cos_o: f32,
        /// Emitted power (max channel).
        pub phi: f32,
        /// Cosine of the emission spread.
        pub cos_e: f32,
        /// Interior: the second child (the first is the next node); leaf:
        /// `LIGHT_BVH_LEAF`.
        pub second: u32,
        /// Leaf: its light; interior: `LIGHT_BVH_LEAF`.
        pub light: u32,
    }

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

impl GpuLightBvhNode {
    /// A node bounding its lights by `cone` (a sphere, their total power,
    /// the cone of their normals), with its links: `second` the second
    /// child of an interior node (the first is the next node) or
    /// [`LIGHT_BVH_LEAF`], `light` a leaf's light or [`LIGHT_BVH_LEAF`].
    pub fn new(cone: &LightCone, second: u32, light: u32) -> GpuLightBvhNode {
        GpuLightBvhNode {
            center: cone.center,
            radius: cone.radius,
            axis: cone.axis,
            cos_o: cone.cos_o,
            phi: cone.phi,
            cos_e: cone.cos_e,
            second,
            light,
        }
    }
}

/// The nodes as the shared walks read them: a slice on the CPU. On the GPU
/// a kernel that binds its `light_bvh` buffer declares `alias BvhNodes =
/// u32` and the readers [`light_bvh_node`] and [`light_bvh_count`] over it,
/// then includes [`walk`]'s WGSL and [`WALK_WGSL_PRELUDE`].
pub type BvhNodes<'a> = &'a [GpuLightBvhNode];

/// Node `i` of `nodes` (the GPU kernel's reader: `light_bvh[i]`).
#[inline]
pub fn light_bvh_node(nodes: BvhNodes, i: u32) -> GpuLightBvhNode {
    nodes[i as usize]
}

/// The number of nodes (the GPU kernel's reader: `arrayLength(&light_bvh)`).
#[inline]
pub fn light_bvh_count(nodes: BvhNodes) -> u32 {
    nodes.len() as u32
}

/// "No light" ([`walk::BvhPick`] with pmf 0), where a walk finds none. Shared
/// code cannot build a struct (Rust and WGSL spell constructors apart), so
/// each language has this one: WGSL's is in [`WALK_WGSL_PRELUDE`].
#[inline]
pub fn bvh_pick_none() -> walk::BvhPick {
    walk::BvhPick::default()
}

/// The WGSL twin of [`bvh_pick_none`], for kernels that include [`walk`].
pub const WALK_WGSL_PRELUDE: &str = "fn bvh_pick_none() -> BvhPick { return BvhPick(0u, 0.0); }\n";

/// The light BVH's walks, written once for both backends. Not part of
/// [`crate::wgsl::library`]: they read a light-BVH buffer, which only the
/// path tracer's kernels bind (their WGSL is [`walk::WGSL`]).
pub mod walk {
    use super::{
        BvhNodes, GpuLightBvhNode, LIGHT_BVH_LEAF, bvh_first_prob, bvh_pick_none, bvh_remap_u,
        light_bvh_count, light_bvh_node,
    };
    use crate::importance::receiver_importance;
    use crate::wgsl::*;

    crate::shared! {
        /// A light drawn from the light BVH and its pmf (0: none).
        pub struct BvhPick {
            /// The light.
            pub light: u32,
            /// Its probability.
            pub pmf: f32,
        }

        /// Importance of node `i` for the receiver at `x` (normal `n`,
        /// mirror direction `r`, lobe `lobe`;
        /// [`receiver_importance`]).
        pub fn bvh_importance(nodes: BvhNodes, i: u32, x: vec3f, n: vec3f, r: vec3f, lobe: vec4f) -> f32 {
            let b: GpuLightBvhNode = light_bvh_node(nodes, i);
            return receiver_importance(b.center, b.radius, b.phi, b.axis, b.cos_o, b.cos_e, x, n, r, lobe);
        }

        /// First-child probability at interior node `i` for the receiver
        /// `(x, n, r, lobe)`, or −1 where the walk ends: a second child out of the table
        /// or not after the first, or [`bvh_first_prob`] < 0.
        pub fn bvh_first(nodes: BvhNodes, i: u32, x: vec3f, n: vec3f, r: vec3f, lobe: vec4f) -> f32 {
            let j: u32 = light_bvh_node(nodes, i).second;
            if j <= i + 1 || j >= light_bvh_count(nodes) {
                return -1.0;
            }
            return bvh_first_prob(bvh_importance(nodes, i + 1, x, n, r, lobe), bvh_importance(nodes, j, x, n, r, lobe));
        }

        /// Samples one light for the receiver at `x` (normal `n`, mirror
        /// direction `r`, lobe `lobe`) and uniform `u_in ∈ [0, 1)`, walking from the root and choosing each
        /// child by its importance: the light and its pmf, or pmf 0 where no
        /// light can light the point (or the tree is empty). A lone leaf is
        /// sampled only where its importance is positive.
        pub fn light_bvh_sample(nodes: BvhNodes, x: vec3f, n: vec3f, r: vec3f, lobe: vec4f, u_in: f32) -> BvhPick {
            let mut pick: BvhPick = bvh_pick_none();
            let mut u: f32 = u_in;
            let mut i: u32 = 0;
            let mut pmf: f32 = 1.0;
            while i < light_bvh_count(nodes) {
                let node: GpuLightBvhNode = light_bvh_node(nodes, i);
                if node.second == LIGHT_BVH_LEAF {
                    if i > 0 || bvh_importance(nodes, 0, x, n, r, lobe) > 0.0 {
                        pick.light = node.light;
                        pick.pmf = pmf;
                    }
                    return pick;
                }
                let p0: f32 = bvh_first(nodes, i, x, n, r, lobe);
                if p0 < 0.0 {
                    return pick;
                }
                let first: bool = u < p0;
                pmf = pmf * select(1.0 - p0, p0, first);
                u = bvh_remap_u(u, p0, first);
                i = select(node.second, i + 1, first);
            }
            return pick;
        }

        /// Probability that [`light_bvh_sample`] for the receiver `(x, n, r,
        /// lobe)` picks
        /// the light whose leaf is node `leaf` (`LIGHT_BVH_LEAF` or out of
        /// the table: 0): the same walk towards that leaf, choosing the
        /// child whose index range holds it.
        pub fn light_bvh_pmf(nodes: BvhNodes, leaf: u32, x: vec3f, n: vec3f, r: vec3f, lobe: vec4f) -> f32 {
            if leaf >= light_bvh_count(nodes) {
                return 0.0;
            }
            let mut i: u32 = 0;
            let mut pmf: f32 = 1.0;
            while i < light_bvh_count(nodes) {
                let node: GpuLightBvhNode = light_bvh_node(nodes, i);
                if node.second == LIGHT_BVH_LEAF {
                    if i == leaf && (i > 0 || bvh_importance(nodes, 0, x, n, r, lobe) > 0.0) {
                        return pmf;
                    }
                    return 0.0;
                }
                let p0: f32 = bvh_first(nodes, i, x, n, r, lobe);
                if p0 < 0.0 {
                    return 0.0;
                }
                let first: bool = leaf < node.second;
                pmf = pmf * select(1.0 - p0, p0, first);
                i = select(node.second, i + 1, first);
            }
            return 0.0;
        }
    }
}
