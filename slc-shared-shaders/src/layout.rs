//! Buffer structs shared by host and kernels, written once in Rust: the
//! `shared!` block emits `#[repr(C)]` + bytemuck structs and the same
//! declarations as WGSL ([`WGSL`]). A test checks every struct's size and
//! field offsets against naga's layouter, so a `vec3f` alignment slip cannot
//! pass silently.

use slc_core::wgsl::*;

slc_core::shared! {
    /// [`GpuLight::kind`] of a point light.
    pub const LIGHT_POINT: u32 = 0;
    /// [`GpuLight::kind`] of a spot light.
    pub const LIGHT_SPOT: u32 = 1;
    /// [`GpuLight::kind`] of an IES light.
    pub const LIGHT_IES: u32 = 2;
    /// [`GpuLight::kind`] of a triangle emitter.
    pub const LIGHT_TRIANGLE: u32 = 3;
    /// [`GpuLight::kind`] of a VPL.
    pub const LIGHT_VPL: u32 = 4;

    /// One light, 64 bytes. Fields by kind:
    /// point `p0` position, `intensity`;
    /// spot `p0` position, `p1` unit axis, `a` cos outer, `b` cos inner, `intensity`;
    /// IES `p0` position, `p1` nadir, `p2` reference (⟂ nadir), `intensity` tint,
    /// `ies_base` offset of its profile in `slc_table`;
    /// triangle `p0 p1 p2` vertices (CCW from the emitting side), `a` area, `intensity` radiance;
    /// VPL `p0` position, `p1` unit normal, `intensity` flux.
    pub struct GpuLight {
        /// Position or first vertex.
        pub p0: vec3f,
        /// `LIGHT_*` kind.
        pub kind: u32,
        /// Axis, nadir, normal or second vertex.
        pub p1: vec3f,
        /// Kind-specific scalar (cos outer, area).
        pub a: f32,
        /// Reference direction or third vertex.
        pub p2: vec3f,
        /// Kind-specific scalar (cos inner).
        pub b: f32,
        /// Intensity, radiance, flux or tint (RGB).
        pub intensity: vec3f,
        /// IES profile offset in `slc_table`.
        pub ies_base: u32,
    }

    /// Node of the geometry BVH used for shadow rays, 32 bytes: a leaf when
    /// `count > 0` (triangles `first .. first + count`), else an inner node
    /// with children `first` and `first + 1`.
    pub struct GpuGeoNode {
        /// Box minimum.
        pub bmin: vec3f,
        /// First child or first triangle.
        pub first: u32,
        /// Box maximum.
        pub bmax: vec3f,
        /// Triangle count (0 for inner nodes).
        pub count: u32,
    }

    /// A triangle of the geometry BVH, 48 bytes.
    pub struct GpuTriangle {
        /// Vertex 0.
        pub v0: vec3f,
        /// Padding.
        pub pad0: f32,
        /// Vertex 1.
        pub v1: vec3f,
        /// Padding.
        pub pad1: f32,
        /// Vertex 2.
        pub v2: vec3f,
        /// Padding.
        pub pad2: f32,
    }

    /// A path vertex waiting for its explicit light connection, 48 bytes.
    pub struct GpuPathVertex {
        /// Position.
        pub position: vec3f,
        /// 1 when the path is alive at this vertex, else 0.
        pub alive: u32,
        /// Unit shading normal.
        pub normal: vec3f,
        /// Padding.
        pub pad: f32,
        /// Path throughput times the diffuse BRDF `ρ/π`.
        pub weight: vec3f,
        /// Padding.
        pub pad1: f32,
    }

    /// Uniforms of `light_update`.
    pub struct FrameParams {
        /// Number of lights.
        pub light_count: u32,
        /// Seed of ξ.
        pub seed: u32,
        /// Frame or pass number.
        pub frame: u32,
        /// Padding.
        pub pad: u32,
    }

    /// Uniforms of one `bsh_refit` level dispatch.
    pub struct RefitParams {
        /// First entry of the level in `order`.
        pub first: u32,
        /// Nodes in the level.
        pub count: u32,
        /// Padding.
        pub pad0: u32,
        /// Padding.
        pub pad1: u32,
    }

    /// Uniforms of `vpl_tiled`.
    pub struct VplParams {
        /// Image width.
        pub width: u32,
        /// Image height.
        pub height: u32,
        /// VPLs per interleaved subset (stored subset after subset).
        pub lights_per_subset: u32,
        /// Squared clamp distance of the VPL fall-off.
        pub min_d2: f32,
    }

    /// Uniforms of `bsh_reservoir` and `pt_connect`.
    pub struct ShadeParams {
        /// Shading points (or path vertices).
        pub point_count: u32,
        /// Seed.
        pub seed: u32,
        /// Frame or pass number.
        pub frame: u32,
        /// Shadow-ray offset along the normal (scene units).
        pub eps: f32,
    }
}
