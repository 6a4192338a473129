//! What shadow rays hit: an engine's meshes (triangles in object space) and
//! their instances (affine transforms), laid out as the one binary BVH in
//! world space that the kernels' `trace` walks (slc-shared-shaders'
//! `geometry.wgsl`, any-hit for shadows, closest-hit for the path tracer).
//!
//! **Layout.** Each mesh gets its own BVH once, in object space (obvhs's
//! PLOC builder, at [`Occluders::new`]). The flattened tree
//! ([`Occluders::nodes`], [`Occluders::triangles`]) starts with a top-level
//! BVH over the instances' world boxes (one instance per leaf); each of its
//! leaves is a copy of its instance's mesh root, whose children lie in that
//! instance's block: a copy of the mesh's nodes with the triangles moved to
//! world space and every box refitted bottom-up. A node with `count > 0` is
//! a leaf over triangles `first .. first + count`; any other node's
//! children are `first` and `first + 1`: the layout the path tracer's
//! scene BVH always had, so one traversal serves both.
//!
//! **Costs.** [`Occluders::new`] and [`Occluders::add_mesh`]: one BVH build
//! per mesh (O(n log n) in its triangles). [`Occluders::set_instances`]:
//! the layout anew, O(the instances' triangles), no mesh rebuilt. [`Occluders::set_transforms`]: the moved instances'
//! triangles transformed and refitted (O(their triangles)), then the
//! top-level tree rebuilt (O(I log I) in the instances); an instance that
//! did not move costs nothing. Memory: every instance holds its own copy
//! of its mesh's triangles (48 B each) and nodes (32 B each), so a mesh
//! instanced a thousand times costs a thousand copies: the price of a
//! traversal without per-instance ray transforms, which stays one loop on
//! every adapter. A rotation loosens a refitted box (the topology was built
//! in object space), which slows rays and never changes a hit.
//!
//! **Bad input** is an [`OccluderError`]: a non-finite vertex or transform,
//! a singular transform, an instance of a mesh that does not exist, a tree
//! deeper than the kernels' 64-entry stack. Zero-area triangles are dropped
//! (no ray hits them; [`Occluders::dropped`] counts them); a mesh left
//! with none is an error.

use glam::{Affine3A, Vec3};
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb;
use obvhs::bvh2::builder::{build_bvh2, build_bvh2_from_tris};
use obvhs::triangle::Triangle;
use std::ops::Range;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;
use thiserror::Error;

/// Deepest tree (top level and mesh together) the kernels' 64-entry
/// traversal stack walks without dropping a subtree.
pub const MAX_DEPTH: u32 = 64;

/// One node of the flattened BVH: a leaf over triangles
/// `first .. first + count` when `count > 0`, else children `first` and
/// `first + 1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GeoNode {
    /// Box minimum.
    pub bmin: Vec3,
    /// First child, or first triangle of a leaf.
    pub first: u32,
    /// Box maximum.
    pub bmax: Vec3,
    /// Triangles of a leaf; 0 for an inner node.
    pub count: u32,
}

/// An instance of a mesh: world position = `transform` × object position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instance {
    /// Index of the mesh in [`Occluders::new`]'s list.
    pub mesh: u32,
    /// Object to world.
    pub transform: Affine3A,
}

/// Geometry that cannot occlude as given.
#[derive(Debug, Error, PartialEq)]
pub enum OccluderError {
    /// A vertex with NaN or ±∞.
    #[error("occluder mesh {mesh}: triangle {triangle} has a non-finite vertex")]
    NonFiniteVertex {
        /// The mesh.
        mesh: usize,
        /// The triangle in it.
        triangle: usize,
    },
    /// No triangle with an area.
    #[error("occluder mesh {mesh} has no triangle with a non-zero area ({triangles} given)")]
    EmptyMesh {
        /// The mesh.
        mesh: usize,
        /// Its triangles, all degenerate.
        triangles: usize,
    },
    /// An instance of a mesh that is not in the list.
    #[error("occluder instance {instance} refers to mesh {mesh}, but there are {meshes} meshes")]
    MeshIndex {
        /// The instance.
        instance: usize,
        /// The mesh it names.
        mesh: u32,
        /// The meshes given.
        meshes: usize,
    },
    /// A transform with NaN, ±∞ or a zero determinant.
    #[error("occluder instance {instance}: the transform is not finite and invertible")]
    Transform {
        /// The instance.
        instance: usize,
    },
    /// Not one transform per instance.
    #[error("{given} transforms for {instances} occluder instances")]
    TransformCount {
        /// Transforms given.
        given: usize,
        /// Instances.
        instances: usize,
    },
    /// Deeper than the kernels' traversal stack.
    #[error("the occluder BVH is {depth} levels deep (top level and mesh), more than {max}")]
    TooDeep {
        /// Its depth.
        depth: u32,
        /// [`MAX_DEPTH`].
        max: u32,
    },
}

/// One mesh's BVH in object space.
#[derive(Clone, Debug)]
struct MeshBvh {
    nodes: Vec<GeoNode>,
    /// Triangles in leaf order.
    tris: Vec<[Vec3; 3]>,
    /// Index in the mesh as given of each of `tris`.
    source: Vec<u32>,
    depth: u32,
}

/// Meshes, their instances and the flattened world-space BVH over them
/// (see the module docs). `Default`: no mesh, no instance (nothing
/// occludes).
#[derive(Clone, Debug, Default)]
pub struct Occluders {
    meshes: Vec<MeshBvh>,
    instances: Vec<Instance>,
    /// First node and first triangle of each instance's block.
    blocks: Vec<(u32, u32)>,
    nodes: Vec<GeoNode>,
    tris: Vec<[Vec3; 3]>,
    dropped: usize,
    depth: u32,
    /// [`Occluders::layout_id`].
    layout: u64,
}

/// The source of [`Occluders::layout_id`]s: every layout in the process
/// gets its own.
static NEXT_LAYOUT: AtomicU64 = AtomicU64::new(1);

fn aabb(n: &GeoNode) -> Aabb {
    Aabb::new(n.bmin.into(), n.bmax.into())
}

fn area2(t: &[Vec3; 3]) -> f32 {
    (t[1] - t[0]).cross(t[2] - t[0]).length_squared()
}

impl MeshBvh {
    fn new(mesh: usize, given: &[[Vec3; 3]]) -> Result<(MeshBvh, usize), OccluderError> {
        let mut kept = Vec::with_capacity(given.len());
        for (i, t) in given.iter().enumerate() {
            if !t.iter().all(|v| v.is_finite()) {
                return Err(OccluderError::NonFiniteVertex { mesh, triangle: i });
            }
            if area2(t) > 0.0 {
                kept.push(i as u32);
            }
        }
        if kept.is_empty() {
            return Err(OccluderError::EmptyMesh { mesh, triangles: given.len() });
        }
        let tris: Vec<Triangle> = kept
            .iter()
            .map(|&i| {
                let t = given[i as usize];
                Triangle { v0: t[0].into(), v1: t[1].into(), v2: t[2].into() }
            })
            .collect();
        let bvh =
            build_bvh2_from_tris(&tris, BvhBuildParams::medium_build(), &mut Duration::default());
        let nodes: Vec<GeoNode> = bvh
            .nodes
            .iter()
            .map(|n| GeoNode {
                bmin: n.aabb.min.into(),
                first: n.first_index,
                bmax: n.aabb.max.into(),
                count: n.prim_count,
            })
            .collect();
        let source: Vec<u32> = bvh.primitive_indices.iter().map(|&p| kept[p as usize]).collect();
        let tris = source.iter().map(|&i| given[i as usize]).collect();
        let depth = tree_depth(&nodes, 0);
        Ok((MeshBvh { nodes, tris, source, depth }, given.len() - kept.len()))
    }
}

/// Levels below and including node `root` (1 for a leaf).
fn tree_depth(nodes: &[GeoNode], root: usize) -> u32 {
    let mut depth = 0;
    let mut stack = vec![(root, 1u32)];
    while let Some((i, d)) = stack.pop() {
        depth = depth.max(d);
        if let Some(n) = nodes.get(i)
            && n.count == 0
        {
            stack.push((n.first as usize, d + 1));
            stack.push((n.first as usize + 1, d + 1));
        }
    }
    depth
}

/// Whether an instance may have transform `m`: finite, with a non-zero
/// determinant (a zero scale, which engines use to hide an object, is
/// not: leave such an instance out).
pub fn placeable(m: &Affine3A) -> bool {
    let det = m.matrix3.determinant();
    m.is_finite() && det.is_finite() && det != 0.0
}

fn check_transform(instance: usize, m: &Affine3A) -> Result<(), OccluderError> {
    if placeable(m) { Ok(()) } else { Err(OccluderError::Transform { instance }) }
}

impl Occluders {
    /// Builds each mesh's BVH and the flattened tree of `instances`.
    /// `meshes[m]` holds mesh `m`'s triangles in object space.
    pub fn new(meshes: &[Vec<[Vec3; 3]>], instances: &[Instance]) -> Result<Self, OccluderError> {
        let mut o = Occluders::default();
        for tris in meshes {
            o.add_mesh(tris)?;
        }
        o.set_instances(instances)?;
        Ok(o)
    }

    /// Builds the BVH of one more mesh (`triangles` in object space) and
    /// returns its index for [`Instance::mesh`]. No instance uses it
    /// until [`Occluders::set_instances`] says so.
    pub fn add_mesh(&mut self, triangles: &[[Vec3; 3]]) -> Result<u32, OccluderError> {
        let (mesh, dropped) = MeshBvh::new(self.meshes.len(), triangles)?;
        self.meshes.push(mesh);
        self.dropped += dropped;
        Ok(self.meshes.len() as u32 - 1)
    }

    /// Replaces the instances (any number, of the meshes added so far) and
    /// lays the flattened tree out anew: O(their triangles), no mesh BVH
    /// rebuilt. On an error nothing changes.
    pub fn set_instances(&mut self, instances: &[Instance]) -> Result<(), OccluderError> {
        for (i, inst) in instances.iter().enumerate() {
            if inst.mesh as usize >= self.meshes.len() {
                return Err(OccluderError::MeshIndex {
                    instance: i,
                    mesh: inst.mesh,
                    meshes: self.meshes.len(),
                });
            }
            check_transform(i, &inst.transform)?;
        }
        let before = std::mem::replace(&mut self.instances, instances.to_vec());
        if let Err(e) = self.lay_out() {
            self.instances = before;
            // The instances before were laid out once: they are again.
            let _ = self.lay_out();
            return Err(e);
        }
        Ok(())
    }

    /// The meshes added.
    pub fn mesh_count(&self) -> usize {
        self.meshes.len()
    }

    /// One mesh, placed as given (the identity transform): a scene's
    /// triangles in world space.
    pub fn from_triangles(triangles: &[[Vec3; 3]]) -> Result<Self, OccluderError> {
        Occluders::new(
            &[triangles.to_vec()],
            &[Instance { mesh: 0, transform: Affine3A::IDENTITY }],
        )
    }

    /// Moves the instances: `transforms[i]` replaces instance `i`'s. Only
    /// the instances whose transform changed are transformed and refitted;
    /// the top-level tree is rebuilt when any did. Returns whether any did.
    /// On an error nothing changes.
    pub fn set_transforms(&mut self, transforms: &[Affine3A]) -> Result<bool, OccluderError> {
        if transforms.len() != self.instances.len() {
            return Err(OccluderError::TransformCount {
                given: transforms.len(),
                instances: self.instances.len(),
            });
        }
        for (i, m) in transforms.iter().enumerate() {
            check_transform(i, m)?;
        }
        let before: Vec<Affine3A> = self.instances.iter().map(|i| i.transform).collect();
        let mut moved = false;
        for (i, m) in transforms.iter().enumerate() {
            if self.instances[i].transform != *m {
                self.instances[i].transform = *m;
                self.place(i);
                moved = true;
            }
        }
        if moved && let Err(e) = self.build_top() {
            // Too deep a top level: back to the transforms before.
            for (i, m) in before.iter().enumerate() {
                if self.instances[i].transform != *m {
                    self.instances[i].transform = *m;
                    self.place(i);
                }
            }
            return Err(e);
        }
        Ok(moved)
    }

    /// The flattened BVH's nodes (node 0 is the root; none without
    /// instances).
    pub fn nodes(&self) -> &[GeoNode] {
        &self.nodes
    }

    /// The world-space triangles in leaf order.
    pub fn triangles(&self) -> &[[Vec3; 3]] {
        &self.tris
    }

    /// The instance and the triangle's index in its mesh (as given) of
    /// flattened triangle `i`.
    pub fn source(&self, i: usize) -> (u32, u32) {
        let inst = self.blocks.partition_point(|b| b.1 as usize <= i) - 1;
        let mesh = &self.meshes[self.instances[inst].mesh as usize];
        (inst as u32, mesh.source[i - self.blocks[inst].1 as usize])
    }

    /// Mesh `m`'s triangles in object space, zero-area ones left out (in
    /// its BVH's leaf order): what an acceleration structure per mesh is
    /// built from (slc-wgpu's ray-query shadows). Empty for a mesh that
    /// does not exist.
    pub fn mesh_triangles(&self, m: usize) -> &[[Vec3; 3]] {
        self.meshes.get(m).map_or(&[], |mesh| &mesh.tris)
    }

    /// The instances with their current transforms.
    pub fn instances(&self) -> &[Instance] {
        &self.instances
    }

    /// Zero-area triangles left out of the meshes.
    pub fn dropped(&self) -> usize {
        self.dropped
    }

    /// Levels of the flattened tree, top level and deepest mesh together.
    pub fn depth(&self) -> u32 {
        self.depth
    }

    /// An id of the flattened tree's layout, new whenever
    /// [`Occluders::set_instances`] lays it out (unique in the process; a
    /// clone keeps it). While it stays the same, every instance keeps its
    /// mesh and its blocks ([`Occluders::instance_blocks`]), and only
    /// [`Occluders::set_transforms`] changes the arrays: the moved
    /// instances' blocks and the top level ([`Occluders::top_level_len`]
    /// nodes). An uploader can then write just those.
    pub fn layout_id(&self) -> u64 {
        self.layout
    }

    /// Instance `i`'s blocks: the ranges of [`Occluders::nodes`] and
    /// [`Occluders::triangles`] that hold its mesh's nodes (its root's copy
    /// is also a top-level leaf) and its world-space triangles.
    pub fn instance_blocks(&self, i: usize) -> (Range<usize>, Range<usize>) {
        let mesh = &self.meshes[self.instances[i].mesh as usize];
        let (n0, t0) = (self.blocks[i].0 as usize, self.blocks[i].1 as usize);
        (n0..n0 + mesh.nodes.len(), t0..t0 + mesh.tris.len())
    }

    /// Nodes of the top level (`2n − 1` for `n` instances), the first in
    /// [`Occluders::nodes`]: rebuilt whenever an instance moves.
    pub fn top_level_len(&self) -> usize {
        (2 * self.instances.len()).saturating_sub(1)
    }

    /// Allots each instance its block (nodes after the top level's,
    /// triangles in order), places every instance and builds the top level.
    fn lay_out(&mut self) -> Result<(), OccluderError> {
        self.layout = NEXT_LAYOUT.fetch_add(1, Ordering::Relaxed);
        let n_inst = self.instances.len() as u32;
        let mut node = (2 * n_inst).saturating_sub(1);
        let mut tri = 0u32;
        self.blocks.clear();
        for inst in &self.instances {
            let mesh = &self.meshes[inst.mesh as usize];
            self.blocks.push((node, tri));
            node += mesh.nodes.len() as u32;
            tri += mesh.tris.len() as u32;
        }
        self.nodes =
            vec![GeoNode { bmin: Vec3::ZERO, first: 0, bmax: Vec3::ZERO, count: 0 }; node as usize];
        self.tris = vec![[Vec3::ZERO; 3]; tri as usize];
        for i in 0..self.instances.len() {
            self.place(i);
        }
        self.build_top()
    }

    /// Instance `i`'s triangles in world space and its block's boxes
    /// refitted to them, children before parents (obvhs puts a node's
    /// children after it, so a reverse sweep is bottom-up).
    fn place(&mut self, i: usize) {
        let inst = self.instances[i];
        let mesh = &self.meshes[inst.mesh as usize];
        let (n0, t0) = (self.blocks[i].0 as usize, self.blocks[i].1 as usize);
        let m = inst.transform;
        let identity = m == Affine3A::IDENTITY;
        for (k, t) in mesh.tris.iter().enumerate() {
            self.tris[t0 + k] = if identity { *t } else { t.map(|v| m.transform_point3(v)) };
        }
        let block = &mut self.nodes[n0..n0 + mesh.nodes.len()];
        for k in (0..mesh.nodes.len()).rev() {
            let src = mesh.nodes[k];
            let (bmin, bmax, first) = if src.count > 0 {
                let tris = &self.tris[t0 + src.first as usize..][..src.count as usize];
                let (lo, hi) = tris
                    .iter()
                    .flatten()
                    .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), v| {
                        (lo.min(*v), hi.max(*v))
                    });
                (lo, hi, src.first + t0 as u32)
            } else {
                let (a, b) = (block[src.first as usize], block[src.first as usize + 1]);
                (a.bmin.min(b.bmin), a.bmax.max(b.bmax), src.first + n0 as u32)
            };
            block[k] = GeoNode { bmin, first, bmax, count: src.count };
        }
    }

    /// The top-level tree over the instances' root boxes, its leaves
    /// replaced by copies of those roots.
    fn build_top(&mut self) -> Result<(), OccluderError> {
        let n = self.instances.len();
        if n == 0 {
            self.depth = 0;
            return Ok(());
        }
        let roots: Vec<GeoNode> = self.blocks.iter().map(|b| self.nodes[b.0 as usize]).collect();
        let boxes: Vec<Aabb> = roots.iter().map(aabb).collect();
        let params = BvhBuildParams { max_prims_per_leaf: 1, ..BvhBuildParams::medium_build() };
        let top = build_bvh2(&boxes, params, &mut Duration::default());
        debug_assert_eq!(top.nodes.len(), 2 * n - 1);
        let mut nodes = vec![roots[0]; top.nodes.len()];
        let mut depth = 0;
        let mut stack = vec![(0usize, 1u32)];
        while let Some((k, d)) = stack.pop() {
            let t = top.nodes[k];
            if t.prim_count > 0 {
                let inst = top.primitive_indices[t.first_index as usize] as usize;
                nodes[k] = roots[inst];
                let mesh = &self.meshes[self.instances[inst].mesh as usize];
                depth = depth.max(d - 1 + mesh.depth);
            } else {
                nodes[k] = GeoNode {
                    bmin: t.aabb.min.into(),
                    first: t.first_index,
                    bmax: t.aabb.max.into(),
                    count: 0,
                };
                stack.push((t.first_index as usize, d + 1));
                stack.push((t.first_index as usize + 1, d + 1));
            }
        }
        if depth > MAX_DEPTH {
            return Err(OccluderError::TooDeep { depth, max: MAX_DEPTH });
        }
        self.nodes[..nodes.len()].copy_from_slice(&nodes);
        self.depth = depth;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Quat;
    use slc_core::ray::{ray_aabb, ray_inverse3, ray_triangle};

    /// A unit square in the z = 0 plane as two triangles, and a degenerate one.
    fn square() -> Vec<[Vec3; 3]> {
        let (a, b, c, d) = (Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y);
        vec![[a, b, c], [a, c, d], [a, a, b]]
    }

    /// Brute force: does the segment hit any of `tris`? (slc-core's
    /// `ray_triangle`, the kernels' test.)
    fn hits(tris: &[[Vec3; 3]], o: Vec3, d: Vec3, t_max: f32) -> bool {
        tris.iter().any(|t| ray_triangle(o, d, t[0], t[1], t[2], 0.0, t_max) > 0.0)
    }

    /// Walks the flattened tree as `geometry.wgsl`'s `trace` does, with
    /// its box and triangle tests.
    fn walk(o: &Occluders, org: Vec3, d: Vec3, t_max: f32) -> bool {
        let (nodes, inv) = (o.nodes(), ray_inverse3(d));
        let mut stack = if nodes.is_empty() { vec![] } else { vec![0usize] };
        while let Some(k) = stack.pop() {
            let n = nodes[k];
            if ray_aabb(org, inv, n.bmin, n.bmax, t_max) < 0.0 {
                continue;
            }
            if n.count > 0 {
                let tris = &o.triangles()[n.first as usize..][..n.count as usize];
                if hits(tris, org, d, t_max) {
                    return true;
                }
            } else {
                stack.extend([n.first as usize, n.first as usize + 1]);
            }
        }
        false
    }

    /// Every triangle of every instance, transformed by brute force.
    fn world(meshes: &[Vec<[Vec3; 3]>], o: &Occluders) -> Vec<[Vec3; 3]> {
        o.instances()
            .iter()
            .flat_map(|i| {
                meshes[i.mesh as usize]
                    .iter()
                    .map(move |t| t.map(|v| i.transform.transform_point3(v)))
            })
            .collect()
    }

    fn rays(seed: u32, count: usize) -> Vec<(Vec3, Vec3)> {
        let mut s = seed;
        let mut rnd = || {
            s = s.wrapping_mul(1664525).wrapping_add(1013904223);
            (s >> 8) as f32 / (1u32 << 24) as f32
        };
        (0..count)
            .map(|_| {
                let o = Vec3::new(rnd(), rnd(), rnd()) * 12.0 - 6.0;
                let d = (Vec3::new(rnd(), rnd(), rnd()) - 0.5).normalize();
                (o, d)
            })
            .collect()
    }

    /// The flattened tree of 50 instances of two meshes, before and after
    /// moving some, finds exactly the brute force's hits.
    #[test]
    fn flattened_tree_hits_what_brute_force_hits() {
        let cube: Vec<[Vec3; 3]> = (0..6)
            .flat_map(|f| {
                let q = Quat::from_rotation_arc(
                    Vec3::Z,
                    [Vec3::X, Vec3::Y, Vec3::Z][f % 3] * if f < 3 { 1.0 } else { -1.0 },
                );
                square()
                    .into_iter()
                    .take(2)
                    .map(move |t| t.map(|v| q * (v - Vec3::new(0.5, 0.5, -0.5))))
            })
            .collect();
        let meshes = vec![square(), cube];
        let mut instances: Vec<Instance> = (0..50)
            .map(|i| Instance {
                mesh: i % 2,
                transform: Affine3A::from_scale_rotation_translation(
                    Vec3::splat(0.3 + 0.02 * i as f32),
                    Quat::from_rotation_y(0.4 * i as f32),
                    Vec3::new((i % 7) as f32 - 3.0, (i % 5) as f32 - 2.0, (i % 3) as f32 - 1.0),
                ),
            })
            .collect();
        let mut o = Occluders::new(&meshes, &instances).unwrap();
        assert_eq!(o.dropped(), 1);
        assert_eq!(o.triangles().len(), 25 * 2 + 25 * 12);
        let check = |o: &Occluders| {
            let w = world(&meshes, o);
            let mut hit = 0;
            for (org, d) in rays(7, 4000) {
                let want = hits(&w, org, d, 20.0);
                assert_eq!(walk(o, org, d, 20.0), want, "ray {org} {d}");
                hit += want as usize;
            }
            assert!(
                hit > 4 * o.instances().len(),
                "only {hit} of 4000 rays hit: the test says little"
            );
        };
        check(&o);
        for (i, inst) in instances.iter_mut().enumerate().filter(|(i, _)| i % 3 == 0) {
            inst.transform =
                Affine3A::from_translation(Vec3::new(0.0, 1.5, 0.1 * i as f32)) * inst.transform;
        }
        let transforms: Vec<Affine3A> = instances.iter().map(|i| i.transform).collect();
        assert!(o.set_transforms(&transforms).unwrap());
        assert!(!o.set_transforms(&transforms).unwrap(), "nothing moved the second time");
        check(&o);
        // Fewer instances, then a third mesh: no mesh BVH rebuilt.
        o.set_instances(&instances[5..20]).unwrap();
        check(&o);
        let tri = vec![[Vec3::ZERO, Vec3::X * 3.0, Vec3::Z * 3.0]];
        assert_eq!(o.add_mesh(&tri).unwrap(), 2);
        let mut more = instances[5..20].to_vec();
        more.push(Instance { mesh: 2, transform: Affine3A::from_translation(Vec3::Y * 0.5) });
        o.set_instances(&more).unwrap();
        let mut all = meshes.clone();
        all.push(tri);
        let w = world(&all, &o);
        for (org, d) in rays(9, 2000) {
            assert_eq!(walk(&o, org, d, 20.0), hits(&w, org, d, 20.0));
        }
        o.set_instances(&instances).unwrap();
        // Every flattened triangle names its source.
        let w = world(&meshes, &o);
        for i in 0..o.triangles().len() {
            let (inst, t) = o.source(i);
            let src = w[(0..inst as usize)
                .map(|k| meshes[instances[k].mesh as usize].len())
                .sum::<usize>()
                + t as usize];
            assert_eq!(src, o.triangles()[i]);
        }
    }

    #[test]
    fn one_mesh_at_identity_keeps_its_vertices() {
        let o = Occluders::from_triangles(&square()).unwrap();
        assert_eq!(o.triangles().len(), 2);
        for (i, t) in o.triangles().iter().enumerate() {
            assert_eq!(*t, square()[o.source(i).1 as usize]);
        }
        assert!(o.depth() >= 1);
    }

    /// Moving keeps the layout id and every block; laying out anew gives a
    /// new id. The blocks tile the arrays after the top level, and moving
    /// one instance changes nothing outside its blocks and the top level.
    #[test]
    fn layout_id_and_blocks_say_what_moving_changes() {
        let cube = |at: Vec3| Affine3A::from_translation(at);
        let meshes = vec![square(), square()];
        let inst = |x: f32| {
            vec![
                Instance { mesh: 0, transform: cube(Vec3::ZERO) },
                Instance { mesh: 1, transform: cube(Vec3::new(x, 0.0, 1.0)) },
                Instance { mesh: 0, transform: cube(Vec3::new(0.0, 2.0, 0.0)) },
            ]
        };
        let mut o = Occluders::new(&meshes, &inst(0.0)).unwrap();
        let id = o.layout_id();
        assert_eq!(o.top_level_len(), 5);
        let mut next = (o.top_level_len(), 0);
        for i in 0..3 {
            let (n, t) = o.instance_blocks(i);
            assert_eq!((n.start, t.start), next, "instance {i}'s blocks follow the previous ones");
            next = (n.end, t.end);
        }
        assert_eq!(next, (o.nodes().len(), o.triangles().len()));
        let (nodes, tris) = (o.nodes().to_vec(), o.triangles().to_vec());
        let transforms: Vec<Affine3A> = inst(0.5).iter().map(|i| i.transform).collect();
        assert!(o.set_transforms(&transforms).unwrap());
        assert_eq!(o.layout_id(), id, "moving keeps the layout");
        let (n1, t1) = o.instance_blocks(1);
        for (k, (a, b)) in nodes.iter().zip(o.nodes()).enumerate() {
            assert!(a == b || k < o.top_level_len() || n1.contains(&k), "node {k} changed");
        }
        for (k, (a, b)) in tris.iter().zip(o.triangles()).enumerate() {
            assert!(a == b || t1.contains(&k), "triangle {k} changed");
        }
        assert!(tris[t1.clone()] != o.triangles()[t1], "the moved instance's triangles moved");
        o.set_instances(&inst(0.0)).unwrap();
        assert_ne!(o.layout_id(), id, "a new layout has a new id");
        assert_eq!((o.nodes(), o.triangles()), (&nodes[..], &tris[..]), "the same tree again");
    }

    #[test]
    fn no_instances_is_an_empty_tree() {
        let o = Occluders::new(&[square()], &[]).unwrap();
        assert!(o.triangles().is_empty() && o.nodes().is_empty());
        assert_eq!(o.depth(), 0);
    }

    #[test]
    fn bad_geometry_is_an_error() {
        let id = Affine3A::IDENTITY;
        let one = |m| [Instance { mesh: m, transform: id }];
        let mut nan = square();
        nan[1][2].y = f32::NAN;
        assert_eq!(
            Occluders::new(&[nan], &one(0)).unwrap_err(),
            OccluderError::NonFiniteVertex { mesh: 0, triangle: 1 }
        );
        assert_eq!(
            Occluders::new(&[vec![[Vec3::X; 3]]], &one(0)).unwrap_err(),
            OccluderError::EmptyMesh { mesh: 0, triangles: 1 }
        );
        assert!(matches!(
            Occluders::new(&[square()], &one(1)).unwrap_err(),
            OccluderError::MeshIndex { instance: 0, mesh: 1, meshes: 1 }
        ));
        let flat = Affine3A::from_scale(Vec3::new(1.0, 0.0, 1.0));
        assert_eq!(
            Occluders::new(&[square()], &[Instance { mesh: 0, transform: flat }]).unwrap_err(),
            OccluderError::Transform { instance: 0 }
        );
        let mut o = Occluders::new(&[square()], &one(0)).unwrap();
        let before = o.triangles().to_vec();
        assert!(matches!(o.set_transforms(&[]), Err(OccluderError::TransformCount { .. })));
        let inf = Affine3A::from_translation(Vec3::new(f32::INFINITY, 0.0, 0.0));
        assert!(matches!(o.set_transforms(&[inf]), Err(OccluderError::Transform { instance: 0 })));
        assert_eq!(o.triangles(), &before[..], "a refused move changes nothing");
    }
}
