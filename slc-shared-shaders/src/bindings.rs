//! Every kernel's bindings as data: one table per kernel and feature set
//! ([`bindings`]), from which the templates' WGSL declarations
//! ([`declarations`]), slc-wgpu's bind-group layouts and bind groups (by
//! name) and the binding tables of the docs ([`markdown`], the crate's
//! `docs/bindings.md`) all come. A test checks every kernel variant's
//! table against the globals of its naga-validated module (group, binding,
//! name, address space, access), so a table cannot drift from the
//! kernel it describes.
//!
//! The tables below are [`docs`]'s output, committed in
//! `docs/bindings.md` (a test regenerates it; `SLC_BLESS=1` accepts a
//! change).
#![doc = include_str!("../docs/bindings.md")]

use crate::{DirectOutput, Features, Kernel, OutputFormat, Selection, SurfaceSource, VplSource};

/// What is bound at one binding.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Resource {
    /// `var<uniform>` of the named struct; `dynamic`: bound with a dynamic
    /// offset (one slot per record or per dispatch).
    Uniform {
        /// WGSL type.
        ty: &'static str,
        /// Bound with a dynamic offset.
        dynamic: bool,
    },
    /// `var<storage, read>` of the WGSL type.
    Read(&'static str),
    /// `var<storage, read_write>` of the WGSL type.
    ReadWrite(&'static str),
    /// `texture_2d<f32>`, read with `textureLoad` (unfilterable float).
    Texture,
    /// `texture_depth_2d`, read with `textureLoad`.
    DepthTexture,
    /// `texture_storage_2d<format, write>`.
    StorageTexture(OutputFormat),
    /// `acceleration_structure`: a top-level acceleration structure for
    /// ray queries ([`Features::ray_query`]).
    AccelerationStructure,
}

/// One binding of a kernel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Binding {
    /// Bind group.
    pub group: u32,
    /// Binding number.
    pub binding: u32,
    /// The WGSL variable's name (bind groups are filled by it).
    pub name: &'static str,
    /// What is bound.
    pub resource: Resource,
    /// `false` for a table the shared library declares but this kernel
    /// never reads (slc-core's IES lookup reads `slc_table`): declared, left
    /// out of the bind-group layout.
    pub bound: bool,
    /// What it holds.
    pub content: &'static str,
    /// Who writes it.
    pub writer: &'static str,
}

const fn b(
    group: u32,
    binding: u32,
    name: &'static str,
    resource: Resource,
    content: &'static str,
    writer: &'static str,
) -> Binding {
    Binding { group, binding, name, resource, bound: true, content, writer }
}

const fn uniform(
    binding: u32,
    name: &'static str,
    ty: &'static str,
    dynamic: bool,
    content: &'static str,
) -> Binding {
    b(0, binding, name, Resource::Uniform { ty, dynamic }, content, "host")
}

const fn read(
    binding: u32,
    name: &'static str,
    ty: &'static str,
    content: &'static str,
    writer: &'static str,
) -> Binding {
    b(0, binding, name, Resource::Read(ty), content, writer)
}

const fn write(
    binding: u32,
    name: &'static str,
    ty: &'static str,
    content: &'static str,
) -> Binding {
    b(0, binding, name, Resource::ReadWrite(ty), content, "this kernel")
}

const fn texture(
    binding: u32,
    name: &'static str,
    content: &'static str,
    writer: &'static str,
) -> Binding {
    b(0, binding, name, Resource::Texture, content, writer)
}

/// The IES table at group 1, binding 0: bound where IES lights are compiled
/// in, else only declared.
fn ies_table(bound: bool) -> Binding {
    Binding {
        bound,
        ..b(
            1,
            0,
            "slc_table",
            Resource::Read("array<f32>"),
            "IES profiles, concatenated (a light's `ies_base` is its offset)",
            "host",
        )
    }
}

/// The G-buffer surface an engine pass reads for `surface`: a depth
/// texture (with the view's inverse view-projection in `view`) or world
/// positions.
fn surface(binding: u32, surface: SurfaceSource) -> Binding {
    match surface {
        SurfaceSource::Position => texture(
            binding,
            "position_tex",
            "world position; `w > 0` where a surface is",
            "engine (G-buffer)",
        ),
        SurfaceSource::Depth => b(
            0,
            binding,
            "depth_tex",
            Resource::DepthTexture,
            "`Depth32Float` depth; exactly 0 or 1 where no surface is",
            "engine (depth pre-pass)",
        ),
        SurfaceSource::R32Depth => texture(
            binding,
            "depth_tex",
            "`R32Float` depth (x); exactly 0 or 1 where no surface is",
            "engine (G-buffer)",
        ),
    }
}

/// The view of an engine pass's G-buffer readers, read in place
/// (`gbuffer_read.wgsl`): the surface's unprojection and the eye.
const fn view_uniform(binding: u32) -> Binding {
    uniform(binding, "view", "ViewParams", true, "inverse view-projection, eye, image size")
}

/// The engine's G-buffer as the indirect pass's kernels read it in place,
/// from binding `first` on: the view, the surface (depth or positions) and
/// the normals.
fn gbuffer_in(first: u32, source: SurfaceSource) -> [Binding; 3] {
    [
        view_uniform(first),
        surface(first + 1, source),
        texture(first + 2, "normal_tex", "world normal (xyz)", "engine (G-buffer)"),
    ]
}

/// The glossy VPL kernels' material table ([`Features::glossy`]).
const fn materials(binding: u32) -> Binding {
    read(
        binding,
        "materials",
        "array<GpuMaterial>",
        "glossy variant: glTF metallic-roughness per material (a pixel's index: its normal's w)",
        "host or engine",
    )
}

/// The counting variant's work counters ([`Features::counters`]).
const fn counters(binding: u32) -> Binding {
    b(
        0,
        binding,
        "counters",
        Resource::ReadWrite("array<atomic<u32>>"),
        "counting variant: the work counters, 64-bit (low, high) per field",
        "this kernel",
    )
}

/// The bindings of `kernel` specialised to `f`, in declaration order.
pub fn bindings(kernel: Kernel, f: &Features) -> Vec<Binding> {
    let ies = f.lights.ies;
    let vec4 = "array<vec4f>";
    let out = |binding, content| {
        b(0, binding, "out_tex", Resource::StorageTexture(f.output_format), content, "this kernel")
    };
    let mut v = match kernel {
        Kernel::LightUpdate => vec![
            uniform(0, "params", "FrameParams", true, "light count, seed, frame"),
            read(1, "ids", "array<u32>", "ξ key of each light (`light_xi`)", "host or `vpl_pack`"),
            read(2, "rt2", "array<f32>", "threshold range² `r_t²`", "host or `vpl_pack`"),
            write(3, "r2", "array<f32>", "random range² `r² = r_t²/(1−ξ)`"),
        ],
        Kernel::LightRanges => vec![
            uniform(0, "params", "CullParams", true, "light count, seed, frame, the record's culling"),
            read(1, "peaks", vec4, "each light's RGB peak intensity (xyz)", "host"),
            write(2, "rt2", "array<f32>", "threshold range² (+∞: never culled)"),
            write(3, "r2", "array<f32>", "random range²"),
        ],
        Kernel::BshRefit => vec![
            uniform(0, "params", "RefitParams", true, "the level's first entry in `order` and node count"),
            read(1, "order", "array<u32>", "node indices level by level, deepest first", "host"),
            read(2, "bounds", vec4, "each light's bound: centre (xyz) and extent `R` (w)", "host"),
            read(3, "r2", "array<f32>", "random range²", "`light_update` or `light_ranges`"),
            b(0, 4, "bsh_nodes", Resource::ReadWrite("array<BshNode>"), "the BSH", "host (build), this kernel (refit)"),
            read(5, "tail", "array<u32>", "the range tail: its histogram cut (1024: no tail), length and lights", "`bsh_tail`"),
        ],
        Kernel::BshTail => vec![
            uniform(0, "params", "TailParams", true, "the stage, light count, the tail's length limit and the tree's node count"),
            read(1, "bounds", vec4, "each light's bound: centre (xyz) and extent `R` (w)", "host"),
            read(2, "r2", "array<f32>", "random range²", "`light_update`"),
            write(3, "tail_hist", "array<atomic<u32>>", "lights per radius bin (zero between passes)"),
            write(4, "tail", "array<atomic<u32>>", "the range tail: its histogram cut, length and lights"),
            b(0, 5, "bsh_nodes", Resource::ReadWrite("array<BshNode>"), "the BSH", "host (build), `bsh_refit`, this kernel (the tail's leaves and links)"),
        ],
        Kernel::BshGrid => vec![
            uniform(0, "params", "GridStage", true, "the stage, and the leaf count, frames tried and insertion moves every grid shares"),
            read(1, "bsh_nodes", "array<BshNode>", "the refitted BSH", "`bsh_refit`"),
            read(2, "grid_leaves", "array<u32>", "the tree's leaves in the walk's order", "host"),
            read(3, "grid_levels", "array<GridFrame>", "the frames tried, finest first (slc-core's `GridFrame::levels`)", "host"),
            write(4, "grid", "array<atomic<u32>>", "the pass's frame and reach, the counts, then each cell's first entry (`GRID_HEADER` on)"),
            write(5, "grid_fill", "array<atomic<u32>>", "each cell's entries counted, then filled (zero between passes)"),
            write(6, "grid_entries", "array<u32>", "the cells' leaves, cell after cell, each in the walk's order"),
            read(7, "grids", "array<GridParams>", "each grid's entries' capacity, reach and where its words start (`workgroup_id.z` the grid)", "host"),
        ],
        Kernel::VplTiled => {
            let mut v = vec![uniform(0, "params", "VplParams", true, "image size, slots per subset, clamp distance, near field, the culling grids")];
            v.extend(gbuffer_in(1, f.surface));
            v.extend([
                read(4, "lights", "array<GpuLight>", "VPLs by subset in map order, flux × period²", "`vpl_pack`"),
                read(5, "rt2", "array<f32>", "threshold range²", "`vpl_pack`"),
                read(6, "r2", "array<f32>", "random range² (clamp: R²)", "`light_update` or `vpl_pack`"),
                read(7, "boxes", "array<GpuBox>", "cluster and group boxes of both fields", "`vpl_clusters`, `vpl_groups`"),
                write(8, "irradiance", vec4, "irradiance (rgb), lights kept (w); 0 where no surface is"),
                write(9, "guide", vec4, "the denoise's guide: unit normal (xyz) and distance from the eye (w); a zero normal and `DEPTH_NONE` where no surface is"),
            ]);
            if f.glossy {
                v.extend([
                    materials(10),
                    write(11, "specular", vec4, "glossy variant: specular correction `S` (rgb); 0 where no surface with a specular lobe is"),
                ]);
            }
            if f.counters {
                v.push(counters(12));
            }
            v
        }
        Kernel::VplDenoise => {
            vec![
                uniform(0, "params", "VplParams", true, "image size"),
                read(1, "guide", vec4, "each pixel's unit normal and distance from the eye", "`vpl_tiled`"),
                read(2, "irradiance", vec4, "interleaved irradiance", "`vpl_tiled`"),
                write(3, "filtered", vec4, "denoised irradiance"),
            ]
        }
        Kernel::VplNear => {
            let mut v = vec![uniform(0, "params", "VplParams", true, "image size, `R_n²`, the near field's grid")];
            v.extend(gbuffer_in(1, f.surface));
            v.extend([
                read(4, "lights", "array<GpuLight>", "VPLs by subset in map order, flux × period²", "`vpl_pack`"),
                read(5, "near_slots", "array<u32>", "slot in `lights` of each VPL in the RSM's map order", "`vpl_pack`"),
                read(6, "boxes", "array<GpuBox>", "cluster and group boxes of both fields", "`vpl_clusters`, `vpl_groups`"),
                read(7, "rt2", "array<f32>", "threshold range² (as `vpl_tiled`'s)", "`vpl_pack`"),
                read(8, "r2", "array<f32>", "range² (as `vpl_tiled`'s)", "`light_update` (SLC) or `vpl_pack`"),
                write(9, "irradiance", vec4, "the (denoised) far field, the near field added"),
            ]);
            if f.glossy {
                v.extend([materials(10), write(11, "specular", vec4, "glossy variant: the (denoised) far field's `S`, the near field's added")]);
            }
            if f.counters {
                v.push(counters(12));
            }
            v
        }
        Kernel::VplClusters => vec![
            uniform(0, "params", "VplParams", true, "`R_n²`, where each field's boxes start"),
            read(1, "lights", "array<GpuLight>", "VPLs by subset in map order, flux × period²", "`vpl_pack`"),
            read(2, "r2", "array<f32>", "range²", "`light_update` (SLC) or `vpl_pack`"),
            read(3, "near_slots", "array<u32>", "slot in `lights` of each VPL in the RSM's map order", "`vpl_pack`"),
            write(4, "boxes", "array<GpuBox>", "each cluster's box of its lit VPLs' culling spheres"),
        ],
        Kernel::VplGroups => vec![
            uniform(0, "params", "VplParams", true, "the culling grids, where each field's boxes start"),
            write(1, "boxes", "array<GpuBox>", "each group's box of its clusters' boxes (reads the cluster boxes)"),
        ],
        Kernel::BshReservoir => {
            let mut v = vec![
                uniform(0, "params", "ShadeParams", false, "point count, seed, frame, shadow-ray offset"),
                read(1, "points", vec4, "shading points (w > 0: valid)", "host"),
                read(2, "normals", vec4, "unit normals", "host"),
                read(3, "lights", "array<GpuLight>", "the lights", "host"),
                read(4, "rt2", "array<f32>", "threshold range²", "host"),
                read(5, "r2", "array<f32>", "random range²", "`light_update`"),
                read(6, "bsh_nodes", "array<BshNode>", "the refitted BSH", "`bsh_refit`"),
            ];
            if f.shadows {
                v.push(read(7, "geo_nodes", "array<GpuGeoNode>", "geometry BVH nodes", "host"));
                v.push(read(8, "geo_tris", "array<GpuTriangle>", "geometry BVH triangles", "host"));
            }
            v.push(write(9, "irradiance", vec4, "irradiance (rgb), in-range lights (w)"));
            v
        }
        Kernel::DirectLight => {
            let mut v = vec![
                uniform(0, "view", "ViewParams", true, "inverse view-projection, eye, image size, seed, frame"),
                surface(1, f.surface),
                texture(2, "normal_tex", "world unit normal (xyz)", "engine (G-buffer)"),
                out(
                    3,
                    match f.direct_output {
                        DirectOutput::Radiance | DirectOutput::BevyRadiance => "outgoing radiance (rgb), in-range lights (a); 0 where no surface is",
                        _ => "irradiance (rgb), in-range lights (a); 0 where no surface is",
                    },
                ),
            ];
            if f.direct_output != DirectOutput::Irradiance {
                v.push(texture(4, "base_color_tex", "linear base colour (rgb)", "engine (G-buffer)"));
                v.push(texture(
                    5,
                    "metal_rough_tex",
                    if f.direct_output == DirectOutput::BevyRadiance {
                        "perceptual roughness (g), metallic (b), Bevy's reflectance (a)"
                    } else {
                        "glTF metallic-roughness: roughness (g), metallic (b)"
                    },
                    "engine (G-buffer)",
                ));
            }
            if f.direct_output == DirectOutput::Split {
                v.push(b(
                    0,
                    6,
                    "specular_tex",
                    Resource::StorageTexture(f.output_format),
                    "specular radiance (rgb); 0 where no surface is",
                    "this kernel",
                ));
            }
            v.push(ies_table(ies));
            v.push(b(1, 1, "lights", Resource::Read("array<GpuLight>"), "the lights", "host"));
            v.push(b(1, 2, "rt2", Resource::Read("array<f32>"), "threshold range²", "`light_ranges`"));
            v.push(b(1, 3, "r2", Resource::Read("array<f32>"), "random range²", "`light_ranges`"));
            v.push(b(1, 4, "bsh_nodes", Resource::Read("array<BshNode>"), "the refitted BSH", "`bsh_refit`"));
            if f.selection == Selection::Weighted || f.direct_output != DirectOutput::Irradiance {
                v.push(b(1, 5, "light_cones", Resource::Read("array<GpuLightCone>"), "each light's bounding sphere and importance cone", "host"));
            }
            if f.shadows && f.ray_query {
                v.push(b(1, 6, "geo_tlas", Resource::AccelerationStructure, "the occluders' instances over one acceleration structure per mesh", "host (slc-scene's `Occluders`)"));
            } else if f.shadows {
                v.push(b(1, 6, "geo_nodes", Resource::Read("array<GpuGeoNode>"), "the occluders' BVH nodes", "host (slc-scene's `Occluders`)"));
                v.push(b(1, 7, "geo_tris", Resource::Read("array<GpuTriangle>"), "the occluders' triangles in leaf order", "host"));
            }
            if f.counters {
                v.push(write(8, "counters", "array<atomic<u32>>", "the counting variant's work counters (64-bit low, high pairs per `DIRECT_COUNT_*` field)"));
            }
            if f.reuse_domains > 0 {
                v.push(uniform(7, "reuse", "ReuseParams", true, "the previous view-projection and eye, the confidence cap, the neighbours' radius"));
                v.push(b(1, 8, "lights_prev", Resource::Read("array<GpuLight>"), "the previous record's lights", "copied from `lights` after each record"));
                v.push(b(1, 9, "reuse_pixels", Resource::ReadWrite("array<ReusePixel>"), "two halves of a pixel each: the previous record's reservoirs and surfaces (read), this record's (written; `ReuseParams::parity`)", "this kernel (the previous record's half: the previous record)"));
            }
            return v;
        }
        Kernel::PtConnect => {
            let mut v = vec![
                uniform(0, "params", "ShadeParams", true, "vertex count, seed, frame, shadow-ray offset"),
                read(1, "vertices", "array<GpuPathVertex>", "path vertices", "`pt_extend`"),
                read(2, "lights", "array<GpuLight>", "the lights", "host"),
                read(3, "rt2", "array<f32>", "threshold range²", "host"),
                read(4, "r2", "array<f32>", "random range²", "`light_update`"),
                read(5, "bsh_nodes", "array<BshNode>", "the refitted BSH", "`bsh_refit`"),
            ];
            if f.ray_query {
                v.push(b(0, 6, "geo_tlas", Resource::AccelerationStructure, "the scene's triangles as one acceleration structure (shadow rays)", "host (slc-scene's `Occluders`)"));
            } else {
                v.push(read(6, "geo_nodes", "array<GpuGeoNode>", "geometry BVH nodes", "host"));
                v.push(read(7, "geo_tris", "array<GpuTriangle>", "geometry BVH triangles", "host"));
            }
            v.extend([
                read(8, "materials", "array<GpuMaterial>", "glTF metallic-roughness per material", "host"),
                write(9, "radiance", vec4, "accumulated radiance"),
                write(10, "candidates", "array<u32>", "what the traversal found per vertex (MIS)"),
            ]);
            if f.bsh_grid {
                v.push(read(11, "grid", "array<u32>", "the pass's grid: frame, reach, each cell's first entry", "`bsh_grid`"));
                v.push(read(12, "grid_entries", "array<u32>", "the cells' leaves in node order", "`bsh_grid`"));
            }
            v.extend(pt_tables(ies));
            return v;
        }
        Kernel::PtExtend => {
            let mut v = vec![
                uniform(0, "params", "PtParams", true, "camera, image, pass, depth"),
                read(1, "lights", "array<GpuLight>", "the lights", "host"),
                read(2, "rt2", "array<f32>", "threshold range²", "host"),
                read(3, "bsh_nodes", "array<BshNode>", "the refitted BSH", "`bsh_refit`"),
                read(4, "light_leaf", "array<u32>", "BSH leaf of each light", "host"),
                read(5, "geo_nodes", "array<GpuGeoNode>", "geometry BVH nodes", "host"),
                read(6, "geo_tris", "array<GpuTriangle>", "geometry BVH triangles (material, light)", "host"),
                read(7, "materials", "array<GpuMaterial>", "glTF metallic-roughness per material", "host"),
                read(8, "geo_normals", vec4, "vertex normals", "host"),
                read(9, "candidates", "array<u32>", "what the last connection's traversal found", "`pt_connect`"),
                write(10, "paths", "array<GpuPathState>", "per-pixel path state"),
                write(11, "vertices", "array<GpuPathVertex>", "the vertex for `pt_connect`"),
                write(12, "radiance", vec4, "accumulated radiance"),
            ];
            v.extend(pt_tables(ies));
            return v;
        }
        Kernel::VplPack => {
            let mut v = vec![uniform(0, "params", "PackParams", true, "count, RSM size, slots per subset, SLC parameters")];
            match f.vpl_source {
                VplSource::Rsm => v.extend([
                    texture(1, "rsm_position", "RSM world position", "engine (RSM)"),
                    texture(2, "rsm_normal", "RSM unit normal", "engine (RSM)"),
                    texture(3, "rsm_flux", "RSM reflected flux", "engine (RSM)"),
                ]),
                VplSource::Buffer => v.push(read(1, "records", "array<GpuVplRecord>", "the engine's VPLs", "engine")),
            }
            v.extend([
                write(4, "lights", "array<GpuLight>", "VPLs by subset, flux × period²"),
                write(5, "ids", "array<u32>", "ξ id of each VPL"),
                write(6, "rt2", "array<f32>", "threshold range² (0 when not SLC)"),
                write(7, "r2", "array<f32>", "the fixed r² when not SLC"),
                write(8, "near_slots", "array<u32>", "slot of each VPL in the RSM's map order (records: record order)"),
            ]);
            v
        }
        Kernel::IrradianceExport => {
            let mut v = gbuffer_in(0, f.surface).to_vec();
            v.extend([
                read(3, "irradiance", vec4, "irradiance (rgb), lights kept (w)", "`vpl_tiled`, `vpl_denoise`, `vpl_near`"),
                out(4, "irradiance (rgb), lights kept (a); 0 where no surface is"),
            ]);
            if f.glossy {
                v.extend([
                    read(5, "specular", vec4, "glossy variant: specular correction `S` (rgb)", "`vpl_tiled`, `vpl_denoise`, `vpl_near`"),
                    b(
                        0,
                        6,
                        "specular_tex",
                        Resource::StorageTexture(f.output_format),
                        "glossy variant: specular correction `S` (rgb); 0 where no surface is",
                        "this kernel",
                    ),
                ]);
            }
            v
        }
        Kernel::SceneRaster => vec![
            uniform(0, "params", "MapParams", false, "view-projection and the map's frame"),
            read(1, "materials", "array<GpuMaterial>", "albedo and emission per material", "host"),
        ],
        Kernel::PrimaryDirect => vec![
            uniform(0, "params", "MapParams", false, "the primary light's shadow map"),
            uniform(1, "image", "ImageParams", false, "eye, image size"),
            texture(2, "position_tex", "G-buffer world position", "`scene_raster`"),
            texture(3, "normal_tex", "G-buffer normal", "`scene_raster`"),
            texture(4, "shadow_map", "distance to the first surface per texel", "`scene_raster`"),
            write(5, "direct", vec4, "the primary light's direct irradiance"),
        ],
        Kernel::FrameCompose => vec![
            uniform(0, "image", "ImageParams", false, "eye, image size"),
            texture(1, "position_tex", "G-buffer world position", "`scene_raster`"),
            texture(2, "normal_tex", "G-buffer normal (w: material)", "`scene_raster`"),
            texture(3, "indirect_tex", "indirect irradiance", "`irradiance_export`"),
            read(4, "direct", vec4, "direct irradiance", "`primary_direct`"),
            read(5, "materials", "array<GpuMaterial>", "albedo and emission per material", "host"),
            out(
                6,
                if f.glossy {
                    "radiance `L_e + ρ/π·(E_direct + E_indirect)`; with a specular lobe `L_e + f(v, l)·E_direct + c_diff/π·E_indirect + S`"
                } else {
                    "radiance `L_e + ρ/π·(E_direct + E_indirect)`"
                },
            ),
        ]
        .into_iter()
        .chain(f.glossy.then(|| texture(7, "specular_tex", "glossy variant: specular correction `S` of the VPLs", "`irradiance_export`")))
        .chain(f.glossy.then(|| {
            uniform(8, "params", "MapParams", false, "glossy variant: the primary light's map (origin, axis, mode: the direction to the light)")
        }))
        .collect(),
        Kernel::Temporal => {
            let history = |binding, name, content| texture(binding, name, content, "`temporal` (the previous frame)");
            let next = |binding, name, content| {
                b(0, binding, name, Resource::StorageTexture(crate::OutputFormat::Rgba32Float), content, "this kernel (the next frame's history)")
            };
            let mut v = gbuffer_in(0, f.surface).to_vec();
            v.extend([
                uniform(3, "params", "TemporalParams", false, "the previous view-projection and eye, the history cap"),
                texture(4, "signal_tex", "this frame's signal (rgb)", "engine (e.g. `irradiance_export`)"),
                history(5, "hist_value", "accumulated value (rgb), history length (a)"),
                history(6, "hist_noise", "last luminance (r), noise variance (g), distance from the eye (b)"),
                history(7, "hist_surface", "normal (rgb), tangent-plane offset `n·p` (a)"),
                out(8, "accumulated value (rgb), history length in frames (a)"),
                next(9, "next_value", "accumulated value (rgb), history length (a)"),
                next(10, "next_noise", "last luminance (r), noise variance (g), distance from the eye (b)"),
                next(11, "next_surface", "normal (rgb), tangent-plane offset (a)"),
            ]);
            if f.motion_vectors {
                v.push(texture(12, "motion_tex", "motion vectors: current minus previous UV (xy)", "engine (prepass)"));
            }
            v
        }
    };
    v.push(ies_table(ies && kernel == Kernel::BshReservoir));
    v
}

/// Group 1 of the path tracer's kernels: the IES table, the power alias
/// table, the importance cones and the light BVH.
fn pt_tables(ies: bool) -> [Binding; 4] {
    [
        Binding { bound: true, ..ies_table(ies) },
        b(
            1,
            1,
            "power_table",
            Resource::Read("array<vec4f>"),
            "alias table `(keep, alias bits, pmf, 0)` per light",
            "host",
        ),
        b(
            1,
            2,
            "light_cones",
            Resource::Read("array<GpuLightCone>"),
            "importance cone and light-BVH leaf per light",
            "host",
        ),
        b(1, 3, "light_bvh", Resource::Read("array<GpuLightBvhNode>"), "the light BVH", "host"),
    ]
}

/// WGSL declarations of `bindings` (one line each).
pub fn declarations(bindings: &[Binding]) -> String {
    let mut s = String::new();
    for b in bindings {
        let ty = match b.resource {
            Resource::Uniform { ty, .. } => format!("var<uniform> {}: {ty}", b.name),
            Resource::Read(ty) => format!("var<storage, read> {}: {ty}", b.name),
            Resource::ReadWrite(ty) => format!("var<storage, read_write> {}: {ty}", b.name),
            Resource::Texture => format!("var {}: texture_2d<f32>", b.name),
            Resource::DepthTexture => format!("var {}: texture_depth_2d", b.name),
            Resource::StorageTexture(f) => {
                format!("var {}: texture_storage_2d<{}, write>", b.name, f.wgsl())
            }
            Resource::AccelerationStructure => format!("var {}: acceleration_structure", b.name),
        };
        s.push_str(&format!("@group({}) @binding({}) {ty};\n", b.group, b.binding));
    }
    s
}

/// The bindings as a Markdown table (`group.binding | type | content |
/// written by`); bindings a kernel only declares are marked so.
pub fn markdown(bindings: &[Binding]) -> String {
    let mut s =
        String::from("| group.binding | type | content | written by |\n|---|---|---|---|\n");
    for b in bindings {
        let ty = match b.resource {
            Resource::Uniform { ty, dynamic: true } => format!("`uniform {ty}` (dynamic offset)"),
            Resource::Uniform { ty, dynamic: false } => format!("`uniform {ty}`"),
            Resource::Read(ty) => format!("`storage<read> {}: {ty}`", b.name),
            Resource::ReadWrite(ty) => format!("`storage<read_write> {}: {ty}`", b.name),
            Resource::Texture => format!("`{}: texture_2d<f32>`", b.name),
            Resource::DepthTexture => format!("`{}: texture_depth_2d`", b.name),
            Resource::StorageTexture(f) => {
                format!("`{}: texture_storage_2d<{}, write>`", b.name, f.wgsl())
            }
            Resource::AccelerationStructure => format!("`{}: acceleration_structure`", b.name),
        };
        let content = if b.bound {
            b.content.to_string()
        } else {
            format!("{} (declared, not read: not bound)", b.content)
        };
        s.push_str(&format!("| {}.{} | {ty} | {content} | {} |\n", b.group, b.binding, b.writer));
    }
    s
}

/// How many of each kind of binding a kernel's bind-group layouts hold
/// (the ones it binds), per shader stage: what device limits it needs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BindingCounts {
    /// Uniform buffers.
    pub uniform_buffers: u32,
    /// Of which bound with dynamic offsets.
    pub dynamic_uniform_buffers: u32,
    /// Storage buffers.
    pub storage_buffers: u32,
    /// Sampled textures.
    pub sampled_textures: u32,
    /// Storage textures.
    pub storage_textures: u32,
    /// Acceleration structures.
    pub acceleration_structures: u32,
    /// Bind groups (highest group + 1).
    pub bind_groups: u32,
}

/// [`BindingCounts`] of the bound entries of `bindings`.
pub fn counts(bindings: &[Binding]) -> BindingCounts {
    let mut c = BindingCounts::default();
    for b in bindings.iter().filter(|b| b.bound) {
        match b.resource {
            Resource::Uniform { dynamic, .. } => {
                c.uniform_buffers += 1;
                c.dynamic_uniform_buffers += dynamic as u32;
            }
            Resource::Read(_) | Resource::ReadWrite(_) => c.storage_buffers += 1,
            Resource::Texture | Resource::DepthTexture => c.sampled_textures += 1,
            Resource::StorageTexture(_) => c.storage_textures += 1,
            Resource::AccelerationStructure => c.acceleration_structures += 1,
        }
        c.bind_groups = c.bind_groups.max(b.group + 1);
    }
    c
}

/// Every kernel's binding table as Markdown, for the feature sets the
/// backends use: the VPL kernels for VPLs (their glossy variant,
/// [`Features::glossy`], whose extra bindings say so), the direct pass's kernel with
/// weighted picks of IES lights from a depth buffer with split outputs,
/// the others with [`Features::default`].
pub fn docs() -> String {
    use crate::LightTypes;
    let vpl = Features {
        lights: LightTypes { vpl: true, ..LightTypes::default() },
        glossy: true,
        ..Features::default()
    };
    let direct = Features {
        selection: Selection::Weighted,
        surface: SurfaceSource::Depth,
        direct_output: DirectOutput::Split,
        shadows: false,
        ..Features::default()
    };
    let mut s = String::new();
    for &k in &Kernel::ALL {
        let f = match k {
            Kernel::DirectLight => direct,
            k if k.is_vpl_frame() => vpl,
            _ => Features::default(),
        };
        s.push_str(&format!("\n### `{}`\n\n", k.name()));
        s.push_str(&markdown(&bindings(k, &f)));
    }
    s
}
