//! Occluders on the GPU: slc-scene's [`Occluders`] (meshes and instances
//! flattened into one world-space BVH) as the `geo_nodes` and `geo_tris`
//! buffers the kernels' `trace` walks (slc-shared-shaders' `geometry.wgsl`).
//! The path tracer's scene and the direct pass's shadows go through here;
//! slc-scene's module is re-exported whole.

use crate::kernel::storage;
use crate::{GpuContext, GpuError};
use glam::Affine3A;
pub use slc_scene::occluders::*;
use slc_shared_shaders::layout::{GpuGeoNode, GpuTriangle, NO_LIGHT};

/// The flattened tree's nodes as the kernels read them. A tree of no
/// instance becomes one leaf over one zero-area triangle at the origin
/// (a binding cannot be empty; no ray hits it).
pub(crate) fn gpu_nodes(o: &Occluders) -> Vec<GpuGeoNode> {
    if o.nodes().is_empty() {
        let zero = glam::Vec3::ZERO;
        return vec![GpuGeoNode { bmin: zero, first: 0, bmax: zero, count: 1 }];
    }
    nodes_as_gpu(o.nodes())
}

/// Nodes in the kernels' layout.
fn nodes_as_gpu(nodes: &[GeoNode]) -> Vec<GpuGeoNode> {
    nodes
        .iter()
        .map(|n| GpuGeoNode { bmin: n.bmin, first: n.first, bmax: n.bmax, count: n.count })
        .collect()
}

/// The flattened tree's triangles in leaf order, triangle `i` with the
/// material and light `tag(i)` gives (the path tracer's; shadows need
/// neither); one zero-area triangle for a tree of no instance.
pub(crate) fn gpu_triangles(o: &Occluders, tag: impl Fn(usize) -> (u32, u32)) -> Vec<GpuTriangle> {
    if o.triangles().is_empty() {
        let z = glam::Vec3::ZERO;
        return vec![GpuTriangle { v0: z, material: 0, v1: z, light: NO_LIGHT, v2: z, pad: 0 }];
    }
    triangles_as_gpu(o.triangles(), 0, tag)
}

/// Triangles `first ..` in the kernels' layout, tagged by `tag(index)`.
fn triangles_as_gpu(
    tris: &[[glam::Vec3; 3]],
    first: usize,
    tag: impl Fn(usize) -> (u32, u32),
) -> Vec<GpuTriangle> {
    tris.iter()
        .enumerate()
        .map(|(i, t)| {
            let (material, light) = tag(first + i);
            GpuTriangle { v0: t[0], material, v1: t[1], light, v2: t[2], pad: 0 }
        })
        .collect()
}

/// Bytes of the buffers [`gpu_nodes`] and [`gpu_triangles`] fill.
fn buffer_sizes(o: &Occluders) -> (u64, u64) {
    let size = |n: usize, each: usize| n.max(1) as u64 * each as u64;
    (
        size(o.nodes().len(), size_of::<GpuGeoNode>()),
        size(o.triangles().len(), size_of::<GpuTriangle>()),
    )
}

/// Checks the buffers' sizes against the device's binding limit.
pub(crate) fn check_limits(gpu: &GpuContext, o: &Occluders) -> Result<(), GpuError> {
    let max = gpu.limits.max_storage_buffer_binding_size;
    let (nodes, tris) = buffer_sizes(o);
    gpu.require("max_storage_buffer_binding_size (occluder triangles)", tris, max)?;
    gpu.require("max_storage_buffer_binding_size (occluder BVH nodes)", nodes, max)
}

/// Occluders for shadow rays, uploaded: nodes and triangles (no material,
/// no light), with the layout and transforms they hold.
pub(crate) struct GpuOccluders {
    pub(crate) nodes: wgpu::Buffer,
    pub(crate) tris: wgpu::Buffer,
    /// [`Occluders::layout_id`] of the contents.
    layout: u64,
    /// Each instance's transform in the contents.
    transforms: Vec<Affine3A>,
}

impl GpuOccluders {
    /// Uploads `o` after checking the device's limits.
    pub(crate) fn new(gpu: &GpuContext, o: &Occluders) -> Result<Self, GpuError> {
        check_limits(gpu, o)?;
        let (nodes, tris) = (gpu_nodes(o), gpu_triangles(o, |_| (0, NO_LIGHT)));
        let usage = wgpu::BufferUsages::empty();
        Ok(GpuOccluders {
            nodes: storage(gpu, "slc occluder nodes", bytemuck::cast_slice(&nodes), usage),
            tris: storage(gpu, "slc occluder triangles", bytemuck::cast_slice(&tris), usage),
            layout: o.layout_id(),
            transforms: Self::transforms_of(o),
        })
    }

    /// Triangles in the kernels' layout, no material, no light.
    fn untagged(tris: &[[glam::Vec3; 3]]) -> Vec<GpuTriangle> {
        triangles_as_gpu(tris, 0, |_| (0, NO_LIGHT))
    }

    fn transforms_of(o: &Occluders) -> Vec<Affine3A> {
        o.instances().iter().map(|i| i.transform).collect()
    }

    /// Rewrites the buffers in place through the queue when `o` fits them
    /// exactly; `false` when it does not and nothing was written. With the
    /// layout of the contents ([`Occluders::layout_id`]: the same meshes
    /// and instances, moved), only what moving changed is written: the top
    /// level and the moved instances' blocks (an engine's static scene
    /// with a few moving objects uploads a few kilobytes a frame); with
    /// another layout of the same sizes, everything.
    pub(crate) fn rewrite(&mut self, gpu: &GpuContext, o: &Occluders) -> bool {
        if buffer_sizes(o) != (self.nodes.size(), self.tris.size()) {
            return false;
        }
        let node_at = |i: usize| (i * size_of::<GpuGeoNode>()) as u64;
        let tri_at = |i: usize| (i * size_of::<GpuTriangle>()) as u64;
        let transforms = Self::transforms_of(o);
        if o.layout_id() == self.layout && transforms.len() == self.transforms.len() {
            let moved: Vec<usize> =
                (0..transforms.len()).filter(|&i| transforms[i] != self.transforms[i]).collect();
            for &i in &moved {
                let (nodes, tris) = o.instance_blocks(i);
                let gn = nodes_as_gpu(&o.nodes()[nodes.clone()]);
                gpu.queue.write_buffer(
                    &self.nodes,
                    node_at(nodes.start),
                    bytemuck::cast_slice(&gn),
                );
                let gt = Self::untagged(&o.triangles()[tris.clone()]);
                gpu.queue.write_buffer(&self.tris, tri_at(tris.start), bytemuck::cast_slice(&gt));
            }
            if !moved.is_empty() {
                let top = nodes_as_gpu(&o.nodes()[..o.top_level_len()]);
                gpu.queue.write_buffer(&self.nodes, 0, bytemuck::cast_slice(&top));
            }
        } else {
            let tris = gpu_triangles(o, |_| (0, NO_LIGHT));
            gpu.queue.write_buffer(&self.nodes, 0, bytemuck::cast_slice(&gpu_nodes(o)));
            gpu.queue.write_buffer(&self.tris, 0, bytemuck::cast_slice(&tris));
            self.layout = o.layout_id();
        }
        self.transforms = transforms;
        true
    }
}
