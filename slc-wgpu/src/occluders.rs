//! Occluders on the GPU: slc-scene's [`Occluders`] (meshes and instances
//! flattened into one world-space BVH) as the `geo_nodes` and `geo_tris`
//! buffers the kernels' `trace` walks (slc-shared-shaders' `geometry.wgsl`).
//! The path tracer's scene and the direct pass's shadows go through here;
//! slc-scene's module is re-exported whole.

use crate::kernel::storage;
use crate::{GpuContext, GpuError};
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
    o.nodes()
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
    o.triangles()
        .iter()
        .enumerate()
        .map(|(i, t)| {
            let (material, light) = tag(i);
            GpuTriangle { v0: t[0], material, v1: t[1], light, v2: t[2], pad: 0 }
        })
        .collect()
}

/// Checks the buffers' sizes against the device's binding limit.
pub(crate) fn check_limits(gpu: &GpuContext, o: &Occluders) -> Result<(), GpuError> {
    let max = gpu.limits.max_storage_buffer_binding_size;
    let size = |n: usize, each: usize| n.max(1) as u64 * each as u64;
    gpu.require(
        "max_storage_buffer_binding_size (occluder triangles)",
        size(o.triangles().len(), size_of::<GpuTriangle>()),
        max,
    )?;
    gpu.require(
        "max_storage_buffer_binding_size (occluder BVH nodes)",
        size(o.nodes().len(), size_of::<GpuGeoNode>()),
        max,
    )
}

/// Occluders for shadow rays, uploaded: nodes and triangles (no material,
/// no light).
pub(crate) struct GpuOccluders {
    pub(crate) nodes: wgpu::Buffer,
    pub(crate) tris: wgpu::Buffer,
}

impl GpuOccluders {
    /// Uploads `o` after checking the device's limits.
    pub(crate) fn new(gpu: &GpuContext, o: &Occluders) -> Result<Self, GpuError> {
        check_limits(gpu, o)?;
        let (nodes, tris) = Self::contents(o);
        Ok(GpuOccluders {
            nodes: storage(
                gpu,
                "slc occluder nodes",
                bytemuck::cast_slice(&nodes),
                wgpu::BufferUsages::empty(),
            ),
            tris: storage(
                gpu,
                "slc occluder triangles",
                bytemuck::cast_slice(&tris),
                wgpu::BufferUsages::empty(),
            ),
        })
    }

    fn contents(o: &Occluders) -> (Vec<GpuGeoNode>, Vec<GpuTriangle>) {
        (gpu_nodes(o), gpu_triangles(o, |_| (0, NO_LIGHT)))
    }

    /// Rewrites the buffers in place through the queue when `o` fits them
    /// exactly (the same meshes and instances, moved); `false` when it
    /// does not and nothing was written.
    pub(crate) fn rewrite(&self, gpu: &GpuContext, o: &Occluders) -> bool {
        let (nodes, tris) = Self::contents(o);
        let (nb, tb): (&[u8], &[u8]) = (bytemuck::cast_slice(&nodes), bytemuck::cast_slice(&tris));
        if nb.len() as u64 != self.nodes.size() || tb.len() as u64 != self.tris.size() {
            return false;
        }
        gpu.queue.write_buffer(&self.nodes, 0, nb);
        gpu.queue.write_buffer(&self.tris, 0, tb);
        true
    }
}
