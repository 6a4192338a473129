//! Occluders on the GPU: slc-scene's [`Occluders`] (meshes and instances
//! flattened into one world-space BVH) as the `geo_nodes` and `geo_tris`
//! buffers the kernels' `trace` walks (slc-shared-shaders' `geometry.wgsl`).
//! The path tracer's scene and the direct pass's shadows go through here;
//! slc-scene's module is re-exported whole.
//!
//! **Ray queries.** For the direct pass's hardware shadow rays
//! ([`ShadowRays::RayQuery`](crate::passes::direct::ShadowRays)) the same
//! occluders also become the adapter's acceleration structures
//! (`GpuAccel`): one bottom level per mesh, built once from its
//! object-space triangles, and a top level over the instances with their
//! transforms, rebuilt whenever one moves (wgpu 30 builds, it does not
//! refit: O(instances) on the GPU). The builds are recorded into the
//! direct pass's next record, before its dispatches: nothing is submitted
//! here. They add to the flattened BVH's buffers, which stay (the counting
//! variant walks them): a vertex buffer and a bottom level per mesh, a top
//! level per instance.

use crate::kernel::storage;
use crate::{GpuContext, GpuError};
use glam::{Affine3A, Vec3};
pub use slc_scene::occluders::*;
use slc_shared_shaders::layout::{GpuGeoNode, GpuTriangle, NO_LIGHT};
use wgpu::util::DeviceExt;

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

/// Checks the acceleration structures of `o` against the device's limits
/// (and that the device has ray queries at all).
pub(crate) fn check_accel_limits(gpu: &GpuContext, o: &Occluders) -> Result<(), GpuError> {
    if !gpu.ray_query {
        return Err(GpuError::Setting(format!(
            "ray-query shadows need a device with wgpu's EXPERIMENTAL_RAY_QUERY, which {} was not opened with (GpuContext::open_with and GpuOptions::ray_query ask for it where the adapter has it); ShadowRays::Software works everywhere",
            gpu.describe()
        )));
    }
    let lim = &gpu.limits;
    gpu.require(
        "max_tlas_instance_count (occluder instances)",
        o.instances().len() as u64,
        lim.max_tlas_instance_count as u64,
    )?;
    let largest = (0..o.mesh_count()).map(|m| o.mesh_triangles(m).len()).max().unwrap_or(0);
    gpu.require(
        "max_blas_primitive_count (triangles of the largest occluder mesh)",
        largest as u64,
        lim.max_blas_primitive_count as u64,
    )
}

/// Occluders as the adapter's acceleration structures (the module docs,
/// "Ray queries"): a bottom level per mesh and the top level `tlas` the
/// kernels bind as `geo_tlas`, for one layout of the occluders. Nothing is
/// submitted here: the builds wait for [`GpuAccel::record_builds`] (the
/// direct pass's next record, before its dispatches).
pub(crate) struct GpuAccel {
    /// One per mesh of the occluders, in mesh order (kept alive: the top
    /// level refers to them).
    blases: Vec<wgpu::Blas>,
    pub(crate) tlas: wgpu::Tlas,
    /// The bottom levels' sizes and vertex buffers until their build is
    /// recorded.
    unbuilt: Option<(Vec<wgpu::BlasTriangleGeometrySizeDescriptor>, Vec<wgpu::Buffer>)>,
    /// The top level's instances changed since its build was recorded.
    stale: bool,
}

/// `m` as the row-major 3×4 matrix a top-level instance carries.
fn row_major(m: &Affine3A) -> [f32; 12] {
    let (c, t) = (m.matrix3, m.translation);
    [
        c.x_axis.x, c.y_axis.x, c.z_axis.x, t.x, //
        c.x_axis.y, c.y_axis.y, c.z_axis.y, t.y, //
        c.x_axis.z, c.y_axis.z, c.z_axis.z, t.z,
    ]
}

impl GpuAccel {
    /// The bottom level of each of `o`'s meshes and the top level over its
    /// instances, created and uploaded; their builds wait for
    /// [`GpuAccel::record_builds`]. The caller has checked
    /// [`check_accel_limits`] first, before it changed anything (the direct
    /// pass's `set_shadows`, the path tracer's `with_shadow_rays`).
    pub(crate) fn new(gpu: &GpuContext, o: &Occluders) -> Result<Self, GpuError> {
        let sizes: Vec<wgpu::BlasTriangleGeometrySizeDescriptor> = (0..o.mesh_count())
            .map(|m| wgpu::BlasTriangleGeometrySizeDescriptor {
                vertex_format: wgpu::VertexFormat::Float32x3,
                vertex_count: 3 * o.mesh_triangles(m).len() as u32,
                index_format: None,
                index_count: None,
                flags: wgpu::AccelerationStructureGeometryFlags::OPAQUE,
            })
            .collect();
        let vertices: Vec<wgpu::Buffer> = (0..o.mesh_count())
            .map(|m| {
                // Read by the BLAS build alone (once; the meshes never change).
                gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("slc occluder mesh"),
                    contents: bytemuck::cast_slice(o.mesh_triangles(m)),
                    usage: wgpu::BufferUsages::BLAS_INPUT,
                })
            })
            .collect();
        let blases: Vec<wgpu::Blas> = sizes
            .iter()
            .map(|size| {
                gpu.device.create_blas(
                    &wgpu::CreateBlasDescriptor {
                        label: Some("slc occluder mesh"),
                        flags: wgpu::AccelerationStructureFlags::PREFER_FAST_TRACE,
                        update_mode: wgpu::AccelerationStructureUpdateMode::Build,
                    },
                    wgpu::BlasGeometrySizeDescriptors::Triangles {
                        descriptors: vec![size.clone()],
                    },
                )
            })
            .collect();
        let tlas = gpu.device.create_tlas(&wgpu::CreateTlasDescriptor {
            label: Some("slc occluder instances"),
            max_instances: o.instances().len().max(1) as u32,
            flags: wgpu::AccelerationStructureFlags::PREFER_FAST_TRACE,
            update_mode: wgpu::AccelerationStructureUpdateMode::Build,
        });
        let mut accel = GpuAccel { blases, tlas, unbuilt: Some((sizes, vertices)), stale: true };
        accel.place(o);
        Ok(accel)
    }

    /// Sets the top level's instances to `o`'s (the same layout: each
    /// instance keeps its mesh); its build waits for the next
    /// [`GpuAccel::record_builds`].
    pub(crate) fn place(&mut self, o: &Occluders) {
        for (i, inst) in o.instances().iter().enumerate() {
            let blas = &self.blases[inst.mesh as usize];
            self.tlas[i] = Some(wgpu::TlasInstance::new(blas, row_major(&inst.transform), 0, 0xff));
        }
        self.stale = true;
    }

    /// Records into `encoder` the builds that wait: the bottom levels once,
    /// the top level whenever its instances changed (wgpu 30 builds it
    /// anew: O(instances) on the GPU). Nothing when nothing changed.
    pub(crate) fn record_builds(&mut self, encoder: &mut wgpu::CommandEncoder) {
        if !self.stale {
            return;
        }
        let (sizes, vertices) = self.unbuilt.take().unwrap_or_default();
        let entries: Vec<wgpu::BlasBuildEntry> = (0..sizes.len())
            .map(|m| wgpu::BlasBuildEntry {
                blas: &self.blases[m],
                geometry: wgpu::BlasGeometries::TriangleGeometries(vec![
                    wgpu::BlasTriangleGeometry {
                        size: &sizes[m],
                        vertex_buffer: &vertices[m],
                        first_vertex: 0,
                        vertex_stride: 12,
                        index_buffer: None,
                        first_index: None,
                        transform_buffer: None,
                        transform_buffer_offset: None,
                    },
                ]),
            })
            .collect();
        encoder.build_acceleration_structures(&entries, [&self.tlas]);
        self.stale = false;
    }
}

/// Where the occluders changed between two records of a pass: the space
/// in which a ray of the earlier record may have met other triangles than
/// the same ray now (the direct pass's visibility reuse cannot say there
/// what its history saw).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Moved {
    /// Nothing moved.
    Nowhere,
    /// Every change lies in the box `(min, max)`: each moved instance's
    /// triangles before and after.
    Inside(Vec3, Vec3),
    /// Anything may have changed (a new layout, shadows switched).
    Everywhere,
}

impl Moved {
    /// The box of instance `i` of `o`: its root node's, which holds its
    /// world-space triangles; `Nowhere` for an instance of no triangle.
    fn of_instance(o: &Occluders, i: usize) -> Moved {
        let nodes = o.instance_blocks(i).0;
        match o.nodes().get(nodes.start) {
            Some(root) if !nodes.is_empty() => Moved::Inside(root.bmin, root.bmax),
            _ => Moved::Nowhere,
        }
    }

    /// The kernel's encoding (`ReuseParams::moved`, `moved_min`,
    /// `moved_max`): 0 nowhere, 1 inside the box grown by a little more
    /// than a float's rounding at its size (a ray that grazes a moved
    /// triangle meets it), 2 everywhere.
    pub(crate) fn encoded(self) -> (u32, Vec3, Vec3) {
        match self {
            Moved::Nowhere => (0, Vec3::ZERO, Vec3::ZERO),
            Moved::Inside(a, b) => {
                let pad = Vec3::splat(1e-4 * a.abs().max(b.abs()).max_element() + 1e-6);
                (1, a - pad, b + pad)
            }
            Moved::Everywhere => (2, Vec3::ZERO, Vec3::ZERO),
        }
    }

    /// The region holding both changes.
    pub(crate) fn join(self, other: Moved) -> Moved {
        match (self, other) {
            (Moved::Everywhere, _) | (_, Moved::Everywhere) => Moved::Everywhere,
            (Moved::Nowhere, m) | (m, Moved::Nowhere) => m,
            (Moved::Inside(a0, a1), Moved::Inside(b0, b1)) => Moved::Inside(a0.min(b0), a1.max(b1)),
        }
    }
}

/// Occluders for shadow rays, uploaded: nodes and triangles (no material,
/// no light), with the layout, transforms and world boxes they hold, and
/// with ray queries their acceleration structures.
pub(crate) struct GpuOccluders {
    pub(crate) nodes: wgpu::Buffer,
    pub(crate) tris: wgpu::Buffer,
    /// The acceleration structures, for ray-query shadows.
    pub(crate) accel: Option<GpuAccel>,
    /// [`Occluders::layout_id`] of the contents.
    layout: u64,
    /// Each instance's transform in the contents.
    transforms: Vec<Affine3A>,
    /// Each instance's world-space box in the contents.
    boxes: Vec<Moved>,
}

impl GpuOccluders {
    /// Uploads `o`, and with `ray_query` makes its acceleration
    /// structures. The caller (the direct pass's `set_shadows`) has checked
    /// [`check_limits`] and, with `ray_query`, [`check_accel_limits`]
    /// first, before it changed anything.
    pub(crate) fn new(gpu: &GpuContext, o: &Occluders, ray_query: bool) -> Result<Self, GpuError> {
        let accel = if ray_query { Some(GpuAccel::new(gpu, o)?) } else { None };
        let (nodes, tris) = (gpu_nodes(o), gpu_triangles(o, |_| (0, NO_LIGHT)));
        let usage = wgpu::BufferUsages::empty();
        Ok(GpuOccluders {
            nodes: storage(gpu, "slc occluder nodes", bytemuck::cast_slice(&nodes), usage),
            tris: storage(gpu, "slc occluder triangles", bytemuck::cast_slice(&tris), usage),
            accel,
            layout: o.layout_id(),
            transforms: Self::transforms_of(o),
            boxes: Self::boxes_of(o),
        })
    }

    fn boxes_of(o: &Occluders) -> Vec<Moved> {
        (0..o.instances().len()).map(|i| Moved::of_instance(o, i)).collect()
    }

    /// Triangles in the kernels' layout, no material, no light.
    fn untagged(tris: &[[glam::Vec3; 3]]) -> Vec<GpuTriangle> {
        triangles_as_gpu(tris, 0, |_| (0, NO_LIGHT))
    }

    fn transforms_of(o: &Occluders) -> Vec<Affine3A> {
        o.instances().iter().map(|i| i.transform).collect()
    }

    /// Rewrites the buffers in place through the queue when `o` fits them
    /// exactly, and says where the occluders changed; `None` when it does
    /// not fit and nothing was written. With the
    /// layout of the contents ([`Occluders::layout_id`]: the same meshes
    /// and instances, moved), only what moving changed is written: the top
    /// level and the moved instances' blocks (an engine's static scene
    /// with a few moving objects uploads a few kilobytes a frame); with
    /// another layout of the same sizes, everything. The acceleration
    /// structures, where there are, get a new top level for the same
    /// layout; another layout is `None` (it may instance other meshes).
    pub(crate) fn rewrite(&mut self, gpu: &GpuContext, o: &Occluders) -> Option<Moved> {
        if buffer_sizes(o) != (self.nodes.size(), self.tris.size())
            || (self.accel.is_some() && o.layout_id() != self.layout)
        {
            return None;
        }
        let mut changed = Moved::Nowhere;
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
                let now = Moved::of_instance(o, i);
                changed = changed.join(self.boxes[i]).join(now);
                self.boxes[i] = now;
            }
            if !moved.is_empty() {
                let top = nodes_as_gpu(&o.nodes()[..o.top_level_len()]);
                gpu.queue.write_buffer(&self.nodes, 0, bytemuck::cast_slice(&top));
                if let Some(a) = self.accel.as_mut() {
                    a.place(o);
                }
            }
        } else {
            let tris = gpu_triangles(o, |_| (0, NO_LIGHT));
            gpu.queue.write_buffer(&self.nodes, 0, bytemuck::cast_slice(&gpu_nodes(o)));
            gpu.queue.write_buffer(&self.tris, 0, bytemuck::cast_slice(&tris));
            self.layout = o.layout_id();
            self.boxes = Self::boxes_of(o);
            changed = Moved::Everywhere;
        }
        self.transforms = transforms;
        Some(changed)
    }
}
