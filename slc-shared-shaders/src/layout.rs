//! Buffer structs shared by host and kernels, written once in Rust: the
//! `shared!` block emits `#[repr(C)]` + bytemuck structs and the same
//! declarations as WGSL ([`WGSL`]). A test checks every struct's size and
//! field offsets against naga's layouter, so a `vec3f` alignment slip cannot
//! pass silently.

use slc_core::light::Light;
/// The light-BVH node layout (slc-core's, which both walks read).
pub use slc_core::light_bvh::GpuLightBvhNode;
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
        /// Reference direction or third vertex (a spot: its fall-off shape in x).
        pub p2: vec3f,
        /// Kind-specific scalar (cos inner).
        pub b: f32,
        /// Intensity, radiance, flux or tint (RGB).
        pub intensity: vec3f,
        /// IES profile offset in `slc_table`.
        pub ies_base: u32,
    }

    /// A light's importance bounds (`slc_core::importance::LightCone`), 48
    /// bytes, read by `slc-weighted`'s `cone_weight`, and its leaf in the
    /// light BVH.
    pub struct GpuLightCone {
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
        /// The light's leaf in the light BVH (`LIGHT_BVH_LEAF`: none).
        pub bvh_leaf: u32,
        /// Padding.
        pub pad: u32,
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

    /// A triangle of the geometry BVH, 48 bytes, in the BVH's leaf order.
    pub struct GpuTriangle {
        /// Vertex 0.
        pub v0: vec3f,
        /// Material index (path tracer: its albedo).
        pub material: u32,
        /// Vertex 1.
        pub v1: vec3f,
        /// Light index of an emissive triangle, else `NO_LIGHT`.
        pub light: u32,
        /// Vertex 2.
        pub v2: vec3f,
        /// Padding.
        pub pad: u32,
    }

    /// [`GpuTriangle::light`] of a triangle that does not emit.
    pub const NO_LIGHT: u32 = 4294967295;

    /// A path vertex waiting for its explicit light connection, 80 bytes.
    pub struct GpuPathVertex {
        /// Position.
        pub position: vec3f,
        /// 1 when the path is alive at this vertex, else 0.
        pub alive: u32,
        /// Unit shading normal.
        pub normal: vec3f,
        /// Material index (into the materials buffer).
        pub material: u32,
        /// Path throughput up to this vertex (the BRDF is evaluated per
        /// connection).
        pub weight: vec3f,
        /// Padding.
        pub pad1: f32,
        /// Unit geometric normal on the shading normal's side (ray offsets,
        /// and lights behind the surface itself are not connected).
        pub gnormal: vec3f,
        /// Padding.
        pub pad2: f32,
        /// Unit direction back along the path (toward the previous vertex).
        pub wo: vec3f,
        /// Padding.
        pub pad3: f32,
    }

    /// Per-pixel state of a path between `pt_extend` dispatches, 96 bytes.
    pub struct GpuPathState {
        /// Origin of the next ray.
        pub origin: vec3f,
        /// 1 while the path continues, else 0.
        pub alive: u32,
        /// Unit direction of the next ray.
        pub dir: vec3f,
        /// Random state of the path.
        pub rng: u32,
        /// Path throughput.
        pub beta: vec3f,
        /// Solid-angle pdf of the BSDF sample that made the next ray (0 for
        /// camera rays: no MIS).
        pub pdf_bsdf: f32,
        /// The vertex the next ray leaves from (for the light pdf of MIS).
        pub prev: vec3f,
        /// Padding.
        pub pad: u32,
        /// Shading normal at `prev` (`slc-weighted`'s weights use it).
        pub prev_normal: vec3f,
        /// Padding.
        pub pad2: u32,
        /// Mirror direction of the view at `prev` (a glossy lobe's weights).
        pub prev_r: vec3f,
        /// Padding.
        pub pad3: u32,
        /// The BRDF lobe at `prev` (`slc_core::brdf::receiver_lobe`).
        pub prev_lobe: vec4f,
    }

    /// Uniforms of `pt_extend`: camera, image, pass and depth.
    pub struct PtParams {
        /// Eye position.
        pub cam_pos: vec3f,
        /// Image width.
        pub width: u32,
        /// Camera right vector scaled by `tan(fov/2) · aspect`.
        pub cam_right: vec3f,
        /// Image height.
        pub height: u32,
        /// Camera up vector scaled by `tan(fov/2)`.
        pub cam_up: vec3f,
        /// Bounce this dispatch handles (0: camera rays).
        pub depth: u32,
        /// Unit view direction.
        pub cam_forward: vec3f,
        /// Seed.
        pub seed: u32,
        /// Pass number.
        pub pass_index: u32,
        /// Longest path (vertices after the camera).
        pub max_depth: u32,
        /// Offset of new rays along the normal (scene units).
        pub eps: f32,
        /// Nearest hit distance accepted (scene units).
        pub t_min: f32,
    }

    /// Uniforms of `light_update`.
    pub struct FrameParams {
        /// Number of lights.
        pub light_count: u32,
        /// Seed of ξ.
        pub seed: u32,
        /// Frame or pass number.
        pub frame: u32,
        /// A ξ every light takes instead of its own (`≥ 0`), or a negative
        /// value: none ([`slc_core::xi::frame_xi`]).
        pub fixed_xi: f32,
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

    /// Uniforms of one `bsh_tail` dispatch: its stage (0 the histogram, 1
    /// the cut, 2 the lights at or above it, 3 their leaves after the
    /// tree), the light count, the tail's length limit `k` and the tree's
    /// node count (where the tail's leaves start).
    pub struct TailParams {
        /// Stage.
        pub stage: u32,
        /// Lights.
        pub count: u32,
        /// Length limit of the tail.
        pub k: u32,
        /// Nodes of the tree before the tail.
        pub tree: u32,
    }

    /// Words before the cell starts of a grid in `bsh_grid`'s `grid`
    /// buffer: the chosen frame (slc-core's `GridFrame`, 12 words; no
    /// cells along x: no grid this pass), the reach it serves (word 12, f32
    /// bits), the leaves counted (13), where the next grid's words start
    /// (14; 0: none, written by the host), then each level's entry count
    /// (64-bit: low, high) from word 16. The cell starts follow, one a cell
    /// and the end after them, as positions in `grid_entries`.
    pub const GRID_HEADER: u32 = 32;

    /// Most frames `bsh_grid` tries (slc-core's `GridFrame::levels`: 64
    /// cells down to 4 is five).
    pub const GRID_LEVELS_MAX: u32 = 8;

    /// Most grids a path-tracing pass builds (`bsh_grid`'s `grids`): the
    /// Lambertian one and the glossy lobes' two (slc-core's `GLOSSY_REACH`
    /// and `SHARP_REACH`); `bsh_collect`'s cursor follows at most
    /// `GRIDS_MAX − 1` links of the chain.
    pub const GRIDS_MAX: u32 = 3;

    /// Moves `bsh_grid`'s stage 5 makes at most sorting a cell by insertion
    /// in one invocation, by default (past it, the workgroup sorts the
    /// cell; `GridStage::moves`): every cell of up to 45 entries (at most
    /// 45·44/2 moves), and larger ones that stage 4 filled almost in order.
    pub const GRID_SORT_MOVES: u32 = 1024;

    /// Most entries of a cell `bsh_grid`'s stage 5 sorts in workgroup
    /// memory (4 KiB; a larger cell is sorted in place in `grid_entries`).
    pub const GRID_SORT_MAX: u32 = 1024;

    /// Uniforms of one `bsh_grid` dispatch: its stage (0 each level's
    /// entries counted, 1 the level chosen, 2 each cell's entries counted,
    /// 3 their starts, 4 the leaves scattered, 5 each cell sorted) for
    /// every grid of the pass at once (grid `g` in workgroups of
    /// `workgroup_id.z = g`, [`GridParams`] `grids[g]`), and what the grids
    /// share; 16 bytes.
    pub struct GridStage {
        /// Stage.
        pub stage: u32,
        /// Leaves in the tree.
        pub count: u32,
        /// Frames in `grid_levels`.
        pub levels: u32,
        /// Moves stage 5 may make sorting a cell by insertion before the
        /// workgroup sorts it (`GRID_SORT_MOVES`; 0: every cell by the
        /// workgroup).
        pub moves: u32,
    }

    /// One grid `bsh_grid` builds (an element of its `grids`): the largest
    /// range lobe the grid serves, its least entries, and where its words
    /// (`grid`), counts (`grid_fill`) and entries (`grid_entries`, at most
    /// `capacity`) start; 24 bytes.
    pub struct GridParams {
        /// Entries the grid may take in `grid_entries`.
        pub capacity: u32,
        /// The largest range lobe `rl.w` the grid serves (1: the plain spheres).
        pub reach: f32,
        /// The grid's first word in `grid`.
        pub header: u32,
        /// The grid's first count in `grid_fill`.
        pub fill: u32,
        /// The grid's first entry in `grid_entries`.
        pub entries: u32,
        /// Entries the grid may take at least, whatever its budget (slc-core's
        /// `bsh_grid_budget`: the sharp grid's `SHARP_GRID_ENTRIES`, else 0).
        pub least: u32,
    }

    /// Uniforms of `vpl_tiled`, `vpl_near`, `vpl_denoise`, `vpl_clusters`
    /// and `vpl_groups`, 80 bytes. `boxes` holds the far field's cluster
    /// boxes (subset after subset), its group boxes, the near field's
    /// cluster boxes and its group boxes, in that order
    /// ([`slc_core::cluster`]).
    pub struct VplParams {
        /// Image width.
        pub width: u32,
        /// Image height.
        pub height: u32,
        /// Slots per interleaved subset (stored subset after subset; whole
        /// clusters of 64, the padding holding no VPL).
        pub lights_per_subset: u32,
        /// Squared clamp distance of the VPL fall-off.
        pub min_d2: f32,
        /// `R_n²` of the near-field split (0: none).
        pub near_r2: f32,
        /// The frame's shift of the pixel-to-subset map
        /// ([`slc_core::interleave::interleave_shift`]).
        pub subset_shift: u32,
        /// Index in `boxes` of the far field's first group box (so also
        /// the far field's cluster count).
        pub far_groups_at: u32,
        /// Index in `boxes` of the near field's first cluster box.
        pub near_clusters_at: u32,
        /// Index in `boxes` of the near field's first group box.
        pub near_groups_at: u32,
        /// Boxes in `boxes` (the near field's end; equal to
        /// `near_groups_at` and `near_clusters_at` without a near field).
        pub box_count: u32,
        /// Padding.
        pub pad0: u32,
        /// Padding.
        pub pad1: u32,
        /// One subset's cluster grid: clusters across and down, clusters
        /// across and down a group ([`slc_core::cluster::ClusterGrid`]).
        pub far_grid: vec4u,
        /// The near field's cluster grid.
        pub near_grid: vec4u,
    }

    /// A box of the VPL frame's culling hierarchies (`lo > hi` when it
    /// holds no lit VPL), 32 bytes.
    pub struct GpuBox {
        /// Lower corner.
        pub lo: vec3f,
        /// Padding.
        pub pad0: f32,
        /// Upper corner.
        pub hi: vec3f,
        /// Padding.
        pub pad1: f32,
    }

    /// A VPL as an engine writes it into the VPL buffer of the indirect
    /// pass (`vpl_pack` with a buffer source), 48 bytes.
    pub struct GpuVplRecord {
        /// Position.
        pub position: vec3f,
        /// Padding.
        pub pad0: f32,
        /// Unit normal of the surface the VPL lies on.
        pub normal: vec3f,
        /// Padding.
        pub pad1: f32,
        /// Flux (RGB), unscaled.
        pub flux: vec3f,
        /// Padding.
        pub pad2: f32,
    }

    /// Uniforms of `vpl_pack`.
    pub struct PackParams {
        /// Number of VPLs (`size²` for an RSM).
        pub count: u32,
        /// Edge of the RSM in texels (0 for a VPL buffer).
        pub size: u32,
        /// Slots per interleaved subset of a VPL buffer
        /// ([`slc_core::interleave::subset_slots_linear`]; unused for an RSM).
        pub per_subset: u32,
        /// Intensity measure of `vpl_rt2` (`IntensityMeasure::mode`).
        pub mode: u32,
        /// Exposure `E`.
        pub exposure: f32,
        /// Error bound `ε`.
        pub error_bound: f32,
        /// Flux scale of interleaving (`P²`).
        pub scale: f32,
        /// 1: write `r_t²` (SLC; `light_update` then draws `r²`); 0: write
        /// `r_t² = 0` and `r² = fixed_r2`.
        pub slc: u32,
        /// `r²` of every VPL when `slc = 0` (clamp: `R²`).
        pub fixed_r2: f32,
        /// Padding.
        pub pad0: u32,
        /// Padding.
        pub pad1: u32,
        /// Padding.
        pub pad2: u32,
    }

    /// Uniforms of `temporal`: the previous frame's view-projection (the
    /// history's reprojection) and eye, the history cap, and whether a
    /// history exists (0: the first frame or after a reset), 96 bytes.
    pub struct TemporalParams {
        /// Column 0 of the previous frame's view-projection.
        pub c0: vec4f,
        /// Column 1.
        pub c1: vec4f,
        /// Column 2.
        pub c2: vec4f,
        /// Column 3.
        pub c3: vec4f,
        /// The previous frame's eye.
        pub prev_eye: vec3f,
        /// The longest history (`≥ 1`; this frame's cap).
        pub max_history: f32,
        /// 1 where the previous frame left a history, else 0.
        pub has_history: u32,
        /// Padding.
        pub pad0: u32,
        /// Padding.
        pub pad1: u32,
        /// Padding.
        pub pad2: u32,
    }

    /// Uniforms of `direct_light`'s reuse (its resampled picks reused
    /// across frames and pixels), one slot per record: the previous
    /// frame's view-projection (where a point was) and eye, the cap on a
    /// reservoir's confidence, the spatial neighbours' disk, the visibility
    /// reuse, which half of the reservoirs it writes, where the occluders
    /// moved since the previous record, 128 bytes.
    pub struct ReuseParams {
        /// Column 0 of the previous frame's view-projection.
        pub c0: vec4f,
        /// Column 1.
        pub c1: vec4f,
        /// Column 2.
        pub c2: vec4f,
        /// Column 3.
        pub c3: vec4f,
        /// The previous frame's eye.
        pub prev_eye: vec3f,
        /// The largest confidence `M` a reservoir keeps (in frames).
        pub max_confidence: f32,
        /// 1 where the previous frame left reservoirs, else 0.
        pub has_history: u32,
        /// Radius of the disk the neighbours are drawn in, in pixels.
        pub radius: f32,
        /// 1: visibility reuse (this frame's picks shadowed before they
        /// meet the history, a final pick found occluded keeps no weight
        /// for the next frame), else 0.
        pub visibility: u32,
        /// The half of `reuse_pixels` this frame writes (0 or 1: pixel
        /// `i`'s reservoirs at `parity·w·h + i`); it reads the other.
        pub parity: u32,
        /// Minimum of the box the occluders moved in (`moved` 1).
        pub moved_min: vec3f,
        /// Where the occluders moved since the previous record: 0 nowhere,
        /// 1 inside `moved_min ..= moved_max`, 2 anywhere.
        pub moved: u32,
        /// Maximum of the box the occluders moved in.
        pub moved_max: vec3f,
        /// Padding.
        pub pad: u32,
    }

    /// The surface a pixel's reused reservoirs were drawn for, as the next
    /// frame evaluates their targets at it, 48 bytes: position, confidence
    /// `m` (0: no surface), unit normal, base colour and metallic
    /// (`pack4x8unorm`), perceptual roughness and Bevy's reflectance
    /// (`pack2x16unorm`; glTF materials: roughness only).
    pub struct ReuseSurface {
        /// World position.
        pub x: vec3f,
        /// Confidence (reservoir inputs it stands for, capped).
        pub m: f32,
        /// Unit normal.
        pub n: vec3f,
        /// Base colour (rgb) and metallic (a), 8-bit unorm.
        pub base: u32,
        /// Perceptual roughness (low) and reflectance (high), 16-bit unorm.
        pub rough: u32,
        /// Padding.
        pub pad0: u32,
        /// Padding.
        pub pad1: u32,
        /// Padding.
        pub pad2: u32,
    }

    /// One reused pick, 12 bytes: the light, its sampled point's `(u1, u2)`
    /// as two 16-bit grid cells (the candidates draw them on that grid:
    /// slc-core's `grid_coordinate`) and the unbiased contribution weight
    /// `W` (0: no pick).
    pub struct ReuseSlot {
        /// Light index.
        pub light: u32,
        /// `u1`'s cell in the high 16 bits, `u2`'s in the low.
        pub u: u32,
        /// Unbiased contribution weight.
        pub w: f32,
    }

    /// Uniforms of `primary_direct` and `frame_compose`.
    pub struct ImageParams {
        /// Eye position (depth = distance from it).
        pub eye: vec3f,
        /// Image width.
        pub width: u32,
        /// Image height.
        pub height: u32,
        /// Padding.
        pub pad0: u32,
        /// Padding.
        pub pad1: u32,
        /// Padding.
        pub pad2: u32,
    }

    /// One vertex of the VPL frame's raster passes (`scene_raster`), 48
    /// bytes: attributes at offsets 0 (position), 12 (material), 16
    /// (vertex normal), 32 (the triangle's geometric normal).
    pub struct GpuVertex {
        /// World position.
        pub position: vec3f,
        /// Material index.
        pub material: u32,
        /// Unit vertex normal (the geometric one for flat triangles).
        pub normal: vec3f,
        /// Padding.
        pub pad0: u32,
        /// Unit geometric normal of the triangle.
        pub geo_normal: vec3f,
        /// Padding.
        pub pad1: u32,
    }

    /// A material as the VPL frame's and the path tracer's kernels read it
    /// (`slc_scene::scene::Material`, glTF metallic-roughness), 48 bytes.
    pub struct GpuMaterial {
        /// Base colour (a dielectric's albedo, a metal's `F0`).
        pub albedo: vec3f,
        /// Metallic factor.
        pub metallic: f32,
        /// Emitted radiance.
        pub emission: vec3f,
        /// GGX `α` (`slc_core::brdf::ggx_alpha` of the roughness).
        pub alpha: f32,
        /// The dielectric's Fresnel reflectance at normal incidence.
        pub f0: vec3f,
        /// The dielectric's Fresnel reflectance at grazing incidence.
        pub f90: f32,
    }

    /// The primary light's map (RSM and shadow map) for `scene_raster` and
    /// `primary_direct`: the light (`LIGHT_SPOT` record for a spot; for a
    /// directional light `intensity` holds its irradiance), the map frame
    /// of `slc_scene::scene::LightMap` and the raster pass's matrix.
    pub struct MapParams {
        /// Column 0 of the raster pass's view-projection matrix.
        pub c0: vec4f,
        /// Column 1.
        pub c1: vec4f,
        /// Column 2.
        pub c2: vec4f,
        /// Column 3.
        pub c3: vec4f,
        /// The primary light.
        pub light: GpuLight,
        /// Eye (G-buffer pass) or the map's origin (light position or plane centre).
        pub origin: vec3f,
        /// `MAP_CAMERA`, `MAP_PERSPECTIVE` or `MAP_ORTHOGRAPHIC`.
        pub mode: u32,
        /// Unit axis of the map.
        pub axis: vec3f,
        /// Map edge in texels.
        pub size: u32,
        /// Unit right.
        pub right: vec3f,
        /// `tan` of the half-angle (perspective) or the half edge (orthographic).
        pub extent: f32,
        /// Unit up.
        pub up: vec3f,
        /// What a texel gathers: its area at distance 1 (perspective) or its area.
        pub texel: f32,
    }

    /// Field of the work counters (`work_counters.wgsl`, read back as
    /// slc-scene's `WorkCounts`): tiles.
    pub const COUNT_TILES: u32 = 0;
    /// Work-counter field: group-box tests.
    pub const COUNT_GROUP_TESTS: u32 = 1;
    /// Work-counter field: cluster-box tests.
    pub const COUNT_CLUSTER_TESTS: u32 = 2;
    /// Work-counter field: culling-sphere tests.
    pub const COUNT_SPHERE_TESTS: u32 = 3;
    /// Work-counter field: lights a pixel loops over.
    pub const COUNT_TESTED: u32 = 4;
    /// Work-counter field: lights a pixel keeps.
    pub const COUNT_KEPT: u32 = 5;
    /// Work-counter field: shaded pixels.
    pub const COUNT_PIXELS: u32 = 6;
    /// Number of work-counter fields (each a 64-bit low, high pair).
    pub const COUNT_FIELDS: u32 = 7;

    /// Field of the direct pass's work counters (`direct_light`'s counting
    /// variant, read back as slc-wgpu's `DirectCounts`): shaded pixels.
    pub const DIRECT_COUNT_PIXELS: u32 = 0;
    /// Direct-pass counter: lights in range, summed over the pixels.
    pub const DIRECT_COUNT_CANDIDATES: u32 = 1;
    /// Direct-pass counter: lights evaluated without a ray (resampled
    /// candidates, the reuse's targets).
    pub const DIRECT_COUNT_EVALUATIONS: u32 = 2;
    /// Direct-pass counter: shadow rays cast.
    pub const DIRECT_COUNT_RAYS: u32 = 3;
    /// Direct-pass counter: BVH nodes the shadow rays visited.
    pub const DIRECT_COUNT_NODES: u32 = 4;
    /// Number of direct-pass counter fields (each a 64-bit low, high pair).
    pub const DIRECT_COUNT_FIELDS: u32 = 5;

    /// [`MapParams::mode`] of the camera's G-buffer pass.
    pub const MAP_CAMERA: u32 = 0;
    /// [`MapParams::mode`] of a spot's perspective map.
    pub const MAP_PERSPECTIVE: u32 = 1;
    /// [`MapParams::mode`] of a directional light's orthographic map.
    pub const MAP_ORTHOGRAPHIC: u32 = 2;

    /// Uniforms of the engine passes' G-buffer readers (`direct_light`,
    /// `vpl_tiled`, `vpl_denoise`, `vpl_near`, `irradiance_export`), written per record: the view
    /// that made the depth buffer, the image and the record's random
    /// streams, the dielectric's Fresnel terms, 112 bytes.
    pub struct ViewParams {
        /// Column 0 of the inverse view-projection (depth input).
        pub c0: vec4f,
        /// Column 1.
        pub c1: vec4f,
        /// Column 2.
        pub c2: vec4f,
        /// Column 3.
        pub c3: vec4f,
        /// Eye position.
        pub eye: vec3f,
        /// Image width.
        pub width: u32,
        /// Image height.
        pub height: u32,
        /// Shadow rays' origin offset along the normal, as a fraction of
        /// the distance to the eye (`direct_light`'s shadowed variant).
        pub shadow_offset: f32,
        /// Seed of the record's random streams.
        pub seed: u32,
        /// Frame number.
        pub frame: u32,
        /// The dielectric's Fresnel reflectance at normal incidence `F0_d`
        /// (`direct_light`'s material outputs; glTF: 0.04).
        pub f0_d: vec3f,
        /// The dielectric's Fresnel reflectance at grazing incidence `F90_d`
        /// (glTF: 1).
        pub f90_d: f32,
    }

    /// Uniforms of `light_ranges`, one slot per record: the lights, the
    /// record's ξ and its culling, 48 bytes.
    pub struct CullParams {
        /// Number of lights.
        pub light_count: u32,
        /// Seed of ξ.
        pub seed: u32,
        /// Frame number.
        pub frame: u32,
        /// 1: stochastic culling (`r_t²` from ε and `E`); 0: `r_t² =
        /// unculled` and `r² = fixed_r2`.
        pub slc: u32,
        /// Intensity measure of `r_t²` (`IntensityMeasure::mode`).
        pub mode: u32,
        /// Exposure `E`.
        pub exposure: f32,
        /// Error bound `ε`.
        pub error_bound: f32,
        /// `r²` without stochastic culling: a clamp range `R²`, or +∞.
        pub fixed_r2: f32,
        /// `r_t²` without stochastic culling: +∞ (weight 1).
        pub unculled: f32,
        /// Padding.
        pub pad0: u32,
        /// Padding.
        pub pad1: u32,
        /// Padding.
        pub pad2: u32,
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

/// The importance cones as the kernels read them, each with its light's
impl GpuMaterial {
    /// A glTF metallic-roughness material as the kernels read it: base
    /// colour, emission, metallic, perceptual roughness (stored as GGX `α`,
    /// `slc_core::brdf::ggx_alpha`), and the dielectric's `F0`/`F90`.
    pub fn new(
        albedo: vec3f,
        emission: vec3f,
        metallic: f32,
        roughness: f32,
        f0: vec3f,
        f90: f32,
    ) -> GpuMaterial {
        GpuMaterial {
            albedo,
            metallic,
            emission,
            alpha: slc_core::brdf::ggx_alpha(roughness),
            f0,
            f90,
        }
    }
}

/// leaf in the light BVH (`bvh_leaf[i]`; missing entries: none).
pub fn pack_cones(
    cones: &[slc_core::importance::LightCone],
    bvh_leaf: &[u32],
) -> Vec<GpuLightCone> {
    cones
        .iter()
        .enumerate()
        .map(|(i, c)| GpuLightCone {
            center: c.center,
            radius: c.radius,
            axis: c.axis,
            cos_o: c.cos_o,
            phi: c.phi,
            cos_e: c.cos_e,
            bvh_leaf: bvh_leaf.get(i).copied().unwrap_or(slc_core::light_bvh::LIGHT_BVH_LEAF),
            pad: 0,
        })
        .collect()
}

/// The light BVH as the kernels read it. An empty tree becomes one leaf of
/// zero power (a binding cannot be empty), which samples nothing.
pub fn pack_light_bvh(nodes: &[GpuLightBvhNode]) -> Vec<GpuLightBvhNode> {
    use slc_core::light_bvh::LIGHT_BVH_LEAF;
    if nodes.is_empty() {
        return vec![GpuLightBvhNode {
            second: LIGHT_BVH_LEAF,
            light: 0,
            ..GpuLightBvhNode::default()
        }];
    }
    nodes.to_vec()
}

impl GpuLight {
    /// A VPL at `position` with unit `normal` and `flux` (the layout
    /// `vpl_pack` writes on the GPU): the one place the host encodes it.
    pub fn vpl(position: vec3f, normal: vec3f, flux: vec3f) -> GpuLight {
        GpuLight {
            p0: position,
            kind: LIGHT_VPL,
            p1: normal,
            a: 0.0,
            p2: vec3f(0.0, 0.0, 0.0),
            b: 0.0,
            intensity: flux,
            ies_base: 0,
        }
    }
}

/// The lights as the kernels read them, and the IES table (`slc_table`)
/// holding each distinct profile once (a light's `ies_base` is its offset).
/// The table is never empty (a zero stands in), since a binding cannot be.
pub fn pack_lights(lights: &[Light]) -> (Vec<GpuLight>, Vec<f32>) {
    let mut table: Vec<f32> = Vec::new();
    let mut seen: Vec<(*const slc_core::ies::IesProfile, u32)> = Vec::new();
    let mut out = Vec::with_capacity(lights.len());
    for l in lights {
        let mut g = GpuLight {
            p0: l.bound().center,
            kind: 0,
            p1: vec3f(0.0, 0.0, 0.0),
            a: 0.0,
            p2: vec3f(0.0, 0.0, 0.0),
            b: 0.0,
            intensity: l.peak(),
            ies_base: 0,
        };
        match l {
            Light::Point(_) => g.kind = LIGHT_POINT,
            Light::Vpl(v) => g = GpuLight::vpl(v.position(), v.normal(), v.flux()),
            Light::Spot(s) => {
                let (cos_outer, cos_inner) = s.cone_cosines();
                (g.kind, g.p1, g.a, g.b) = (LIGHT_SPOT, s.direction(), cos_outer, cos_inner);
                // p2.x: the fall-off's shape (slc_core::light::spot_falloff).
                g.p2 = vec3f(s.falloff_shape(), 0.0, 0.0);
            }
            Light::Ies(i) => {
                let key = std::sync::Arc::as_ptr(i.profile_arc());
                let base = match seen.iter().find(|(p, _)| *p == key) {
                    Some(&(_, b)) => b,
                    None => {
                        let b = table.len() as u32;
                        table.extend_from_slice(i.profile().table());
                        seen.push((key, b));
                        b
                    }
                };
                (g.kind, g.p0, g.p1, g.p2, g.intensity, g.ies_base) =
                    (LIGHT_IES, i.position(), i.nadir(), i.reference(), i.tint(), base);
            }
            Light::Triangle(t) => {
                let [a, b, c] = t.vertices();
                (g.kind, g.p0, g.p1, g.p2, g.a, g.intensity) =
                    (LIGHT_TRIANGLE, a, b, c, t.area(), t.radiance());
            }
        }
        out.push(g);
    }
    if table.is_empty() {
        table.push(0.0);
    }
    (out, table)
}
