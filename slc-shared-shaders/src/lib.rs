//! # slc-shared-shaders
//!
//! The single place where slc's GPU code is assembled. Kernel templates
//! (WGSL with minijinja blocks, in `src/templates/`) include slc-core's
//! shared functions ([`slc_core::wgsl::library`]) and this crate's buffer
//! structs ([`layout`]), both generated from Rust: no template retypes a
//! formula of the core. [`generate`] specialises a kernel to a scene's
//! [`Features`] (only the light types present are compiled in), and
//! validates the result with naga, reporting naga's message with the
//! offending source line. [`translate`] turns a kernel into SPIR-V, GLSL,
//! HLSL and MSL for engines that are not on wgpu (`slc shaders --out DIR`).
//!
//! ## Kernels and bindings
//!
//! Each kernel's bindings are data ([`bindings::bindings`]): the templates'
//! declarations, slc-wgpu's bind-group layouts and bind groups, and the
//! tables in [`bindings`]'s docs all come from them, and a test checks them
//! against every variant's naga module. Every kernel declares
//! `@group(1) @binding(0) slc_table: array<f32>` (read), the IES profiles
//! ([`slc_core::ies::IesProfile::table`], concatenated; a light's
//! `ies_base` is its offset), bound where IES lights are compiled in; the
//! path-tracing kernels' group 1 also holds the power alias table, the
//! importance cones and the light BVH ([`Selection`]). A pass of the path
//! tracer: `light_update`, `bsh_tail`, `bsh_refit` (every level), then `pt_extend` and
//! `pt_connect` once per depth (slc-wgpu's `pt`); the engine's direct
//! pass: `light_ranges`, `bsh_refit`, `direct_light`.
//!
//! ## Embedding one kernel in your own wgpu pass
//!
//! ```
//! use slc_shared_shaders::{generate, Features, Kernel, LightTypes};
//!
//! let features = Features { lights: LightTypes::parse("point,spot").unwrap(), ..Features::default() };
//! let wgsl = generate(Kernel::LightUpdate, &features).unwrap();
//! assert!(wgsl.contains("fn main"));
//! // let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
//! //     label: Some("slc light_update"),
//! //     source: wgpu::ShaderSource::Wgsl(wgsl.into()),
//! // });
//! // let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
//! //     module: &module, entry_point: Some("main"), layout: None, ..
//! // });
//! // Bind FrameParams, ids, rt2 and r2 as in the table above and dispatch
//! // ceil(light_count / workgroup_size) workgroups.
//! ```
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod bindings;
pub mod engine;
pub mod layout;
mod translate;
pub mod wesl;

pub use translate::{Translations, translate};

use minijinja::{Environment, context};
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};
use slc_core::cluster::CLUSTER;
use thiserror::Error;

/// What went wrong while generating or translating a kernel.
#[derive(Debug, Error, PartialEq)]
pub enum ShaderError {
    /// A feature combination the kernels do not support.
    #[error("unsupported kernel features: {0}")]
    Unsupported(String),
    /// The template failed to render (a bug in a template).
    #[error("template {kernel}: {message}")]
    Template {
        /// Kernel name.
        kernel: &'static str,
        /// minijinja's message.
        message: String,
    },
    /// naga rejected the generated WGSL; the message quotes the source line.
    #[error("generated WGSL of {kernel} is invalid:\n{message}")]
    Naga {
        /// Kernel name.
        kernel: &'static str,
        /// naga's message with the offending line.
        message: String,
    },
    /// A naga backend failed.
    #[error("{kernel}: translation to {backend} failed: {message}")]
    Translate {
        /// Kernel name.
        kernel: &'static str,
        /// `spv`, `glsl`, `hlsl` or `msl`.
        backend: &'static str,
        /// naga's message.
        message: String,
    },
}

/// Which light types a scene has; only these are compiled into a kernel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct LightTypes {
    /// Point lights.
    pub point: bool,
    /// Spot lights.
    pub spot: bool,
    /// IES lights.
    pub ies: bool,
    /// Triangle emitters.
    pub triangle: bool,
    /// VPLs.
    pub vpl: bool,
}

impl LightTypes {
    /// Names in the order `point, spot, ies, triangle, vpl`.
    pub const NAMES: [&'static str; 5] = ["point", "spot", "ies", "triangle", "vpl"];

    /// Every light type.
    pub const ALL: LightTypes =
        LightTypes { point: true, spot: true, ies: true, triangle: true, vpl: true };

    /// Parses a comma-separated list such as `point,spot,ies`.
    pub fn parse(list: &str) -> Result<LightTypes, ShaderError> {
        let mut s = LightTypes::default();
        for name in list.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            match name {
                "point" => s.point = true,
                "spot" => s.spot = true,
                "ies" => s.ies = true,
                "triangle" => s.triangle = true,
                "vpl" => s.vpl = true,
                other => {
                    return Err(ShaderError::Unsupported(format!(
                        "unknown light type '{other}' (known: point, spot, ies, triangle, vpl)"
                    )));
                }
            }
        }
        Ok(s)
    }

    /// The set with bit `i` of `bits` standing for `NAMES[i]`.
    pub fn from_bits(bits: u32) -> LightTypes {
        LightTypes {
            point: bits & 1 != 0,
            spot: bits & 2 != 0,
            ies: bits & 4 != 0,
            triangle: bits & 8 != 0,
            vpl: bits & 16 != 0,
        }
    }

    fn flags(&self) -> [bool; 5] {
        [self.point, self.spot, self.ies, self.triangle, self.vpl]
    }

    /// Names of the types in the set.
    pub fn names(&self) -> Vec<&'static str> {
        Self::NAMES.iter().zip(self.flags()).filter(|(_, f)| *f).map(|(n, _)| *n).collect()
    }

    /// `true` when no type is in the set.
    pub fn is_empty(&self) -> bool {
        !self.flags().iter().any(|f| *f)
    }

    /// The types present in `lights`.
    pub fn of(lights: &[slc_core::light::Light]) -> LightTypes {
        use slc_core::light::Light;
        let has = |f: fn(&Light) -> bool| lights.iter().any(f);
        LightTypes {
            point: has(|l| matches!(l, Light::Point(_))),
            spot: has(|l| matches!(l, Light::Spot(_))),
            ies: has(|l| matches!(l, Light::Ies(_))),
            triangle: has(|l| matches!(l, Light::Triangle(_))),
            vpl: has(|l| matches!(l, Light::Vpl(_))),
        }
    }

    /// `true` when every type of this set is in `outer` (a pass compiled
    /// for `outer` shades these lights).
    pub fn within(&self, outer: LightTypes) -> bool {
        self.flags().into_iter().zip(outer.flags()).all(|(a, b)| !a || b)
    }
}

/// The GPU kernels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kernel {
    /// Random ranges from ξ, per frame.
    LightUpdate,
    /// BSH refit, one level per dispatch.
    BshRefit,
    /// The BSH's range tail for the pass's ranges (slc-core's
    /// `bsh::tail`), before the refit: a histogram of the range spheres'
    /// radii, its cut, the lights above it and their leaves after the
    /// tree.
    BshTail,
    /// A uniform grid over the refitted BSH's leaves for the pass (slc-core's
    /// `BshGrid`), by a counting sort in six stages: what `pt_connect`
    /// tests instead of walking the tree where [`Features::bsh_grid`].
    BshGrid,
    /// Tiled culling + VPL shading per interleaved sub-image.
    VplTiled,
    /// BSH traversal into a k-slot reservoir + shading with shadow rays.
    BshReservoir,
    /// Path-tracing light connection with MIS.
    PtConnect,
    /// Path-tracing bounce: camera/BSDF ray, closest hit, emission with MIS.
    PtExtend,
    /// Cross-bilateral denoise of the VPL irradiance.
    VplDenoise,
    /// The near field of the VPL split, per full-resolution tile, added to
    /// the (denoised) interleaved irradiance.
    VplNear,
    /// VPLs (from an RSM or a VPL buffer) into the interleaved light buffer.
    VplPack,
    /// The cluster boxes of the VPL frame's culling hierarchies, every
    /// frame once the ranges are drawn.
    VplClusters,
    /// The group boxes of the VPL frame's culling hierarchies, from the
    /// cluster boxes.
    VplGroups,
    /// The irradiance into an engine's storage texture.
    IrradianceExport,
    /// The VPL frame's raster passes (vertex `vs_main`, fragments
    /// `fs_gbuffer`, `fs_rsm` and `fs_shadow`): G-buffer, reflective shadow
    /// map and shadow map.
    SceneRaster,
    /// The primary light's direct irradiance, shadowed by its shadow map.
    PrimaryDirect,
    /// Direct plus indirect light into the frame's HDR target.
    FrameCompose,
    /// The direct pass's per-record ranges: `r_t²` from each light's peak
    /// and the record's culling, then `r²`.
    LightRanges,
    /// The direct pass's shading: an engine's G-buffer read in place, the
    /// BSH traversed, the picks (weighted, uniform or every light in range)
    /// connected, irradiance into the engine's storage texture.
    DirectLight,
    /// Temporal accumulation of a per-pixel signal over an engine's
    /// G-buffer (slc-core's `temporal`): the history reprojected, matched
    /// and blended into the engine's output and the next history.
    Temporal,
}

impl Kernel {
    /// All kernels.
    pub const ALL: [Kernel; 20] = [
        Kernel::LightUpdate,
        Kernel::BshRefit,
        Kernel::BshTail,
        Kernel::BshGrid,
        Kernel::VplTiled,
        Kernel::VplDenoise,
        Kernel::VplNear,
        Kernel::BshReservoir,
        Kernel::PtConnect,
        Kernel::PtExtend,
        Kernel::VplPack,
        Kernel::VplClusters,
        Kernel::VplGroups,
        Kernel::IrradianceExport,
        Kernel::SceneRaster,
        Kernel::PrimaryDirect,
        Kernel::FrameCompose,
        Kernel::LightRanges,
        Kernel::DirectLight,
        Kernel::Temporal,
    ];

    /// File stem / name.
    pub fn name(self) -> &'static str {
        match self {
            Kernel::LightUpdate => "light_update",
            Kernel::BshRefit => "bsh_refit",
            Kernel::BshTail => "bsh_tail",
            Kernel::BshGrid => "bsh_grid",
            Kernel::VplTiled => "vpl_tiled",
            Kernel::BshReservoir => "bsh_reservoir",
            Kernel::PtConnect => "pt_connect",
            Kernel::PtExtend => "pt_extend",
            Kernel::VplDenoise => "vpl_denoise",
            Kernel::VplNear => "vpl_near",
            Kernel::VplPack => "vpl_pack",
            Kernel::VplClusters => "vpl_clusters",
            Kernel::VplGroups => "vpl_groups",
            Kernel::IrradianceExport => "irradiance_export",
            Kernel::SceneRaster => "scene_raster",
            Kernel::PrimaryDirect => "primary_direct",
            Kernel::FrameCompose => "frame_compose",
            Kernel::LightRanges => "light_ranges",
            Kernel::DirectLight => "direct_light",
            Kernel::Temporal => "temporal",
        }
    }

    /// The VPL application's kernels, generated for a VPL-only light set
    /// (the frame kernels compile the primary light's spot case whatever
    /// the set says).
    pub fn is_vpl_frame(self) -> bool {
        matches!(
            self,
            Kernel::VplTiled
                | Kernel::VplDenoise
                | Kernel::VplNear
                | Kernel::VplPack
                | Kernel::VplClusters
                | Kernel::VplGroups
                | Kernel::IrradianceExport
                | Kernel::SceneRaster
                | Kernel::PrimaryDirect
                | Kernel::FrameCompose
        )
    }

    /// Entry points and their stages: `main` for compute kernels; the
    /// raster kernel's vertex and fragment entry points.
    pub fn entry_points(self) -> &'static [(&'static str, naga::ShaderStage)] {
        match self {
            Kernel::SceneRaster => &[
                ("vs_main", naga::ShaderStage::Vertex),
                ("fs_gbuffer", naga::ShaderStage::Fragment),
                ("fs_rsm", naga::ShaderStage::Fragment),
                ("fs_shadow", naga::ShaderStage::Fragment),
            ],
            _ => &[("main", naga::ShaderStage::Compute)],
        }
    }
}

/// The culling kind of `vpl_tiled` and `vpl_near` (slc-core's).
pub use slc_core::range::CullKind;

/// MIS heuristic of `pt_connect`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Heuristic {
    /// `a/(a+b)`.
    Balance,
    /// `a²/(a²+b²)`.
    Power,
}

/// How the path tracer's light connection picks lights.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Selection {
    /// Stochastic light culling: BSH traversal into a k-slot reservoir.
    Reservoir,
    /// Stochastic light culling: every in-range light, connected during the
    /// traversal.
    All,
    /// One light, uniformly (baseline; ranges are +∞, nothing culled).
    Uniform,
    /// One light in proportion to its power, from the alias table in
    /// `power_table` (baseline).
    Power,
    /// Stochastic light culling: `k` independent weighted picks among the
    /// in-range lights, each candidate weighted by its importance over its
    /// roulette probability (`slc-weighted`; cones in `light_cones`).
    Weighted,
    /// One light by light-BVH importance sampling (baseline; the tree in
    /// `light_bvh`, each light's leaf in `light_cones`).
    LightBvh,
    /// Stochastic light culling, `direct_light` only: `k` picks resampled
    /// from every in-range light in proportion to its unshadowed
    /// contribution, each evaluated without a ray; only the picks are
    /// shadowed.
    Resampled,
}

/// Where `vpl_pack` reads its VPLs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VplSource {
    /// A reflective shadow map: position, normal and flux textures, one VPL
    /// per texel.
    Rsm,
    /// A storage buffer of `GpuVplRecord`s.
    Buffer,
}

/// Texel format of the storage texture `irradiance_export` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OutputFormat {
    /// `rgba16float`.
    Rgba16Float,
    /// `rgba32float`.
    Rgba32Float,
}

impl OutputFormat {
    /// The WGSL texel format name.
    pub fn wgsl(self) -> &'static str {
        match self {
            OutputFormat::Rgba16Float => "rgba16float",
            OutputFormat::Rgba32Float => "rgba32float",
        }
    }
}

/// Where the engine passes' kernels (`direct_light` and the indirect
/// pass's `vpl_tiled`, `vpl_denoise`, `vpl_near`, `irradiance_export`)
/// read the G-buffer's surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SurfaceSource {
    /// A world-position texture (`texture_2d<f32>`, `w > 0` where a
    /// surface is).
    Position,
    /// A `Depth32Float` depth texture (`texture_depth_2d`) and the view's
    /// inverse view-projection.
    Depth,
    /// An `R32Float` depth texture (`texture_2d<f32>`, depth in x) and the
    /// view's inverse view-projection.
    R32Depth,
}

/// What `direct_light` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DirectOutput {
    /// Irradiance (rgb) and the lights in range (a).
    Irradiance,
    /// Outgoing radiance toward the eye under the glTF metallic-roughness
    /// BRDF (slc-core's `brdf`) of the G-buffer's material (rgb), and the
    /// lights in range (a).
    Radiance,
    /// Irradiance (rgb, a: lights in range) and, in a second target, the
    /// specular lobe's outgoing radiance (rgb).
    Split,
    /// Outgoing radiance toward the eye under Bevy `StandardMaterial`'s
    /// BRDF (slc-core's `brdf::bevy_brdf`; the material's alpha channel is
    /// its `reflectance`), and the lights in range (a).
    BevyRadiance,
}

/// What a kernel is specialised to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Features {
    /// Light types compiled in.
    pub lights: LightTypes,
    /// Reservoir slots `k` (1..=64).
    pub reservoir_k: u32,
    /// Workgroup size of the 1-D kernels (1..=256).
    pub workgroup_size: u32,
    /// Tile edge of `vpl_tiled` in sub-image pixels (1..=16).
    pub tile_size: u32,
    /// Interleave period `P` (P×P subsets, 1..=16).
    pub interleave: u32,
    /// Capacity of a tile's light list (at least the lights per subset).
    pub max_tile_lights: u32,
    /// Culling kind of `vpl_tiled` and `vpl_near`.
    pub method: CullKind,
    /// MIS heuristic of `pt_connect`.
    pub heuristic: Heuristic,
    /// Light selection of `pt_connect` and `pt_extend`.
    pub selection: Selection,
    /// VPL source of `vpl_pack`.
    pub vpl_source: VplSource,
    /// Storage-texture format of `irradiance_export`.
    pub output_format: OutputFormat,
    /// Shadow rays in `bsh_reservoir` (bindings 0.7 `geo_nodes` and 0.8
    /// `geo_tris`) and `direct_light` (1.6 and 1.7); without them the
    /// kernel is unshadowed and declares neither (`bsh_reservoir`: 8
    /// storage buffers per stage instead of 10, WebGPU's default limit).
    pub shadows: bool,
    /// Where the engine passes' G-buffer readers (`direct_light`,
    /// `vpl_tiled`, `vpl_denoise`, `vpl_near`, `irradiance_export`) read
    /// the surface.
    pub surface: SurfaceSource,
    /// What `direct_light` writes (with a material input unless
    /// `Irradiance`).
    pub direct_output: DirectOutput,
    /// The VPL kernels' glossy variant (the glTF BRDF at glossy
    /// receivers): `vpl_tiled` and `vpl_near` read each pixel's material
    /// from `materials` (its index in the normal texture's w) and, where it
    /// has a specular lobe, add the specular correction `S = Σ Φ ⊙
    /// (f − c_diff/π)·T·share` (slc-core's `specular_correction`) over
    /// the same kept VPLs to `specular`; `irradiance_export` also writes
    /// `S` to `specular_tex`; `frame_compose` adds it
    /// (`glossy_radiance`). `vpl_denoise` is the same kernel for `S`.
    /// `false`: Lambertian kernels (`ρ/π·E`), unchanged.
    pub glossy: bool,
    /// The counting variant of `vpl_tiled` and `vpl_near`: every culling
    /// test, light tested and light kept is counted into `counters`
    /// (slc-scene's `WorkCounts`, 64-bit per field). Lambertian only (the
    /// counts do not depend on the material); never in a timed frame.
    pub counters: bool,
    /// `temporal` reprojects by the engine's motion vectors (`motion_tex`,
    /// current minus previous UV in xy) instead of the previous
    /// view-projection.
    pub motion_vectors: bool,
    /// `direct_light`'s reuse (resampled picks only): the previous-frame
    /// pixels each pixel combines its reservoirs with, the reprojected one
    /// and `reuse_domains − 1` neighbours (1..=8); 0: no reuse. Binds the
    /// `reuse` uniform (0.7), `lights_prev` and `reuse_pixels` (1.8,
    /// 1.9).
    pub reuse_domains: u32,
    /// `direct_light` walks the light hierarchy once per tile, shared by
    /// its invocations (`bsh_tile.wgsl`; the default), rather than once
    /// per pixel: the same lights in the same order either way.
    pub tile_walk: bool,
    /// `direct_light`'s shadow rays are the adapter's ray queries through
    /// an acceleration structure (binding 1.6 `geo_tlas`, wgpu's
    /// experimental ray query, native adapters only) instead of the WGSL
    /// BVH walk over `geo_nodes` and `geo_tris`: the same segments, the
    /// same end margins. Needs `shadows`; not with `counters` (a ray
    /// query counts no node).
    pub ray_query: bool,
    /// `pt_connect` finds a vertex's candidates in the pass's grid
    /// (`bsh_grid`; bindings 0.11 `grid` and 0.12 `grid_entries`) where it
    /// has one and the vertex's range lobe is within the grid's reach,
    /// else by the walk: the same lights in the same order. Other kernels
    /// ignore it.
    pub bsh_grid: bool,
}

impl Default for Features {
    fn default() -> Self {
        Features {
            lights: LightTypes::ALL,
            reservoir_k: 8,
            workgroup_size: 64,
            tile_size: 8,
            interleave: 8,
            max_tile_lights: 1024,
            method: CullKind::Stochastic,
            heuristic: Heuristic::Power,
            selection: Selection::Reservoir,
            vpl_source: VplSource::Rsm,
            output_format: OutputFormat::Rgba16Float,
            shadows: true,
            surface: SurfaceSource::Position,
            direct_output: DirectOutput::Irradiance,
            glossy: false,
            counters: false,
            motion_vectors: false,
            reuse_domains: 0,
            tile_walk: true,
            ray_query: false,
            bsh_grid: false,
        }
    }
}

const TEMPLATES: [(&str, &str); 40] = [
    ("header.wgsl", include_str!("templates/header.wgsl")),
    ("workgroup_box.wgsl", include_str!("templates/workgroup_box.wgsl")),
    ("lights.wgsl", include_str!("templates/lights.wgsl")),
    ("geometry.wgsl", include_str!("templates/geometry.wgsl")),
    ("bsh_walk.wgsl", include_str!("templates/bsh_walk.wgsl")),
    ("bsh_collect.wgsl", include_str!("templates/bsh_collect.wgsl")),
    ("bsh_tile.wgsl", include_str!("templates/bsh_tile.wgsl")),
    ("light_update", include_str!("templates/light_update.wgsl")),
    ("bsh_refit", include_str!("templates/bsh_refit.wgsl")),
    ("bsh_tail", include_str!("templates/bsh_tail.wgsl")),
    ("bsh_grid", include_str!("templates/bsh_grid.wgsl")),
    ("bsh_grid_frame.wgsl", include_str!("templates/bsh_grid_frame.wgsl")),
    ("vpl_tiled", include_str!("templates/vpl_tiled.wgsl")),
    ("vpl_denoise", include_str!("templates/vpl_denoise.wgsl")),
    ("vpl_near", include_str!("templates/vpl_near.wgsl")),
    ("bsh_reservoir", include_str!("templates/bsh_reservoir.wgsl")),
    ("pt_connect", include_str!("templates/pt_connect.wgsl")),
    ("pt_mis.wgsl", include_str!("templates/pt_mis.wgsl")),
    ("pt_extend", include_str!("templates/pt_extend.wgsl")),
    ("vpl_pack", include_str!("templates/vpl_pack.wgsl")),
    ("vpl_clusters", include_str!("templates/vpl_clusters.wgsl")),
    ("vpl_groups", include_str!("templates/vpl_groups.wgsl")),
    ("vpl_ranges.wgsl", include_str!("templates/vpl_ranges.wgsl")),
    ("cluster_cull.wgsl", include_str!("templates/cluster_cull.wgsl")),
    ("tile_list.wgsl", include_str!("templates/tile_list.wgsl")),
    ("work_counters.wgsl", include_str!("templates/work_counters.wgsl")),
    ("counter64.wgsl", include_str!("templates/counter64.wgsl")),
    ("vpl_receiver.wgsl", include_str!("templates/vpl_receiver.wgsl")),
    ("irradiance_export", include_str!("templates/irradiance_export.wgsl")),
    ("scene_raster", include_str!("templates/scene_raster.wgsl")),
    ("primary_direct", include_str!("templates/primary_direct.wgsl")),
    ("frame_compose", include_str!("templates/frame_compose.wgsl")),
    ("gbuffer_read.wgsl", include_str!("templates/gbuffer_read.wgsl")),
    ("vpl_glossy.wgsl", include_str!("templates/vpl_glossy.wgsl")),
    ("bsh_weighted.wgsl", include_str!("templates/bsh_weighted.wgsl")),
    ("light_weight.wgsl", include_str!("templates/light_weight.wgsl")),
    ("light_ranges", include_str!("templates/light_ranges.wgsl")),
    ("direct_light", include_str!("templates/direct_light.wgsl")),
    ("temporal", include_str!("templates/temporal.wgsl")),
    ("layout", ""),
];

/// The template sources, for inspection (e.g. the test that no template
/// retypes a core formula).
pub fn templates() -> impl Iterator<Item = (&'static str, &'static str)> {
    TEMPLATES.iter().copied().filter(|(n, _)| *n != "layout")
}

/// Workgroup memory in bytes of `vpl_tiled` or `vpl_near` (0 for any
/// other kernel) specialised to `f`: two `vec3f` (16 bytes each) per
/// invocation and the box for the tile's box; with culling (always in
/// `vpl_near`) the hits of a group's clusters and their counter, and the
/// light list: `vpl_tiled`'s of `max_tile_lights` slots and its counter,
/// `vpl_near`'s four quarter lists of [`near_quarter_lights`] slots, their
/// four counters and the longest's, and the four quarters' boxes (two
/// `vec3f` each); the counting variant's 7 counts (checked against naga's
/// layout of the generated kernels in the tests).
pub fn vpl_workgroup_bytes(kernel: Kernel, f: &Features) -> u64 {
    let threads = f.tile_size as u64 * f.tile_size as u64;
    let culled = kernel == Kernel::VplNear || f.method != CullKind::None;
    let hits = if culled { 4 * CLUSTER as u64 + 4 } else { 0 };
    let counts = if f.counters { 4 * 7 } else { 0 };
    match kernel {
        Kernel::VplTiled => {
            let list = if culled { 4 * f.max_tile_lights as u64 + 4 } else { 0 };
            32 * threads + 32 + hits + list + counts
        }
        Kernel::VplNear => {
            let lists = 4 * 4 * near_quarter_lights(f) as u64 + 4 * 4 + 4;
            32 * threads + 32 + hits + lists + counts + 4 * 32
        }
        _ => 0,
    }
}

/// Capacity of each of `vpl_near`'s four quarter lists: a quarter of the
/// tile list (`max_tile_lights`), and at least a cluster, which the
/// culling adds at once.
pub fn near_quarter_lights(f: &Features) -> u32 {
    (f.max_tile_lights / 4).max(CLUSTER)
}

/// Workgroup memory in bytes of `direct_light` specialised to `f`: with
/// the tile walk, its box reduction (two `vec3f` per invocation and the
/// box), the list of `max_tile_lights` entries, the 256 subtrees'
/// positions and two scalars; none without (checked against naga's
/// layout in the tests).
pub fn direct_workgroup_bytes(f: &Features) -> u64 {
    let threads = f.tile_size as u64 * f.tile_size as u64;
    if !f.tile_walk {
        return 0;
    }
    32 * threads + 32 + 4 * f.max_tile_lights as u64 + 4 * 256 + 8
}

/// Checks the feature ranges and the combinations a kernel supports.
pub fn check(kernel: Kernel, f: &Features) -> Result<(), ShaderError> {
    let bad = |m: String| Err(ShaderError::Unsupported(m));
    if !(1..=64).contains(&f.reservoir_k) {
        return bad(format!("reservoir k = {} must be in 1..=64", f.reservoir_k));
    }
    if !(1..=256).contains(&f.workgroup_size) {
        return bad(format!("workgroup size {} must be in 1..=256", f.workgroup_size));
    }
    if f.ray_query && !matches!(kernel, Kernel::DirectLight | Kernel::PtConnect) {
        return bad(format!(
            "{}: only direct_light and pt_connect cast their shadow rays as ray queries",
            kernel.name()
        ));
    }
    match kernel {
        Kernel::VplDenoise
        | Kernel::VplPack
        | Kernel::IrradianceExport
        | Kernel::PrimaryDirect
        | Kernel::FrameCompose
        | Kernel::Temporal
            if !(1..=16).contains(&f.tile_size) || !(1..=16).contains(&f.interleave) =>
        {
            return bad(format!(
                "{}: tile {} and period {} must be in 1..=16",
                kernel.name(),
                f.tile_size,
                f.interleave
            ));
        }
        Kernel::VplTiled | Kernel::VplNear => {
            let name = kernel.name();
            if f.lights != (LightTypes { vpl: true, ..LightTypes::default() }) {
                return bad(format!(
                    "{name} shades VPLs only; the scene asks for [{}]",
                    f.lights.names().join(", ")
                ));
            }
            // One invocation per light of a cluster (cluster_cull.wgsl).
            if f.tile_size * f.tile_size != CLUSTER {
                return bad(format!(
                    "{name}: tile size {} must be 8 (one invocation per light of a {CLUSTER}-light cluster)",
                    f.tile_size
                ));
            }
            if !(1..=16).contains(&f.interleave) {
                return bad(format!(
                    "{name}: interleave period {} must be in 1..=16",
                    f.interleave
                ));
            }
            if f.max_tile_lights < CLUSTER {
                return bad(format!(
                    "{name}: the tile light list must hold a cluster's {CLUSTER} lights, not {}",
                    f.max_tile_lights
                ));
            }
            if f.counters && f.glossy {
                return bad(format!(
                    "{name}: the counting variant is Lambertian (the counts do not depend on the material)"
                ));
            }
            let bytes = vpl_workgroup_bytes(kernel, f);
            if bytes > 16384 {
                return bad(format!(
                    "{name}: {0} list slots need {bytes} bytes of workgroup memory (WebGPU guarantees 16384)",
                    f.max_tile_lights
                ));
            }
        }
        Kernel::VplClusters | Kernel::VplGroups if !(1..=16).contains(&f.interleave) => {
            return bad(format!("{}: period {} must be in 1..=16", kernel.name(), f.interleave));
        }
        Kernel::DirectLight => {
            if f.lights.is_empty() {
                return bad("direct_light needs at least one light type".into());
            }
            if f.ray_query && !f.shadows {
                return bad("direct_light: ray queries are shadow rays: they need shadows".into());
            }
            if f.ray_query && f.counters {
                return bad(
                    "direct_light: the counting variant walks the WGSL BVH (a ray query counts no node)"
                        .into(),
                );
            }
            if !matches!(
                f.selection,
                Selection::Reservoir | Selection::Weighted | Selection::Resampled | Selection::All
            ) {
                return bad(format!(
                    "direct_light picks lights by reservoir, weighted, resampled or all, not {:?}",
                    f.selection
                ));
            }
            if !(1..=16).contains(&f.tile_size) {
                return bad(format!("direct_light: tile {} must be in 1..=16", f.tile_size));
            }
            if f.tile_walk && !f.tile_size.is_power_of_two() {
                return bad(format!(
                    "direct_light: tile {} must be 1, 2, 4, 8 or 16 for the tile walk (it reduces over a power of two)",
                    f.tile_size
                ));
            }
            if f.tile_walk && f.max_tile_lights == 0 {
                return bad(
                    "direct_light: the tile walk's list must hold at least one light".into()
                );
            }
            let bytes = direct_workgroup_bytes(f);
            if bytes > 16384 {
                return bad(format!(
                    "direct_light: a {0}-entry tile list needs {bytes} bytes of workgroup memory (WebGPU guarantees 16384)",
                    f.max_tile_lights
                ));
            }
            if f.reuse_domains > 0 && f.selection != Selection::Resampled {
                return bad(format!(
                    "direct_light reuses resampled picks only, not {:?} picks",
                    f.selection
                ));
            }
            if f.reuse_domains > 8 {
                return bad(format!("direct_light: {} reused pixels, at most 8", f.reuse_domains));
            }
        }
        Kernel::BshReservoir | Kernel::PtConnect | Kernel::PtExtend if f.lights.is_empty() => {
            return bad(format!("{} needs at least one light type", kernel.name()));
        }
        _ => {}
    }
    Ok(())
}

/// A generated, validated kernel.
#[derive(Debug)]
pub struct Generated {
    /// The kernel.
    pub kernel: Kernel,
    /// WGSL source.
    pub source: String,
    /// naga's module.
    pub module: naga::Module,
    /// naga's validation info.
    pub info: ModuleInfo,
}

/// Renders `kernel` for `features` and validates it with naga.
pub fn generate_module(kernel: Kernel, features: &Features) -> Result<Generated, ShaderError> {
    check(kernel, features)?;
    let mut env = Environment::new();
    env.set_trim_blocks(true);
    env.set_lstrip_blocks(true);
    env.set_keep_trailing_newline(true);
    for (name, src) in TEMPLATES {
        env.add_template(name, src)
            .map_err(|e| ShaderError::Template { kernel: kernel.name(), message: e.to_string() })?;
    }
    // The frame kernels light the scene with the primary light (a spot, or
    // a directional light, which needs no light type).
    let l = if matches!(kernel, Kernel::SceneRaster | Kernel::PrimaryDirect) {
        LightTypes { spot: true, ..LightTypes::default() }
    } else {
        features.lights
    };
    let method = features.method.name();
    let heuristic = match features.heuristic {
        Heuristic::Balance => "balance",
        Heuristic::Power => "power",
    };
    let selection = match features.selection {
        Selection::Reservoir => "reservoir",
        Selection::All => "all",
        Selection::Uniform => "uniform",
        Selection::Power => "power",
        Selection::Weighted => "weighted",
        Selection::LightBvh => "lightbvh",
        Selection::Resampled => "resampled",
    };
    let ctx = context! {
        kernel => kernel.name(),
        core => slc_core::wgsl::library(),
        bsh_walk => slc_core::wgsl::translate(slc_core::bsh::walk::WGSL),
        bsh_tail => slc_core::wgsl::translate(slc_core::bsh::tail::WGSL),
        bsh_grid => slc_core::wgsl::translate(slc_core::bsh::grid::WGSL),
        grid => features.bsh_grid && kernel == Kernel::PtConnect,
        bvh_walk => slc_core::wgsl::translate(slc_core::light_bvh::walk::WGSL) + slc_core::light_bvh::WALK_WGSL_PRELUDE,
        layout => slc_core::wgsl::translate(layout::WGSL),
        light_names => l.names().join(", "),
        point => l.point, spot => l.spot, ies => l.ies, triangle => l.triangle, vpl => l.vpl,
        k => features.reservoir_k,
        wg => features.workgroup_size,
        tile => features.tile_size,
        period => features.interleave,
        max_tile_lights => features.max_tile_lights,
        quarter_lights => near_quarter_lights(features),
        quarter_list => 4 * near_quarter_lights(features),
        method => method,
        heuristic => heuristic,
        selection => selection,
        source => match features.vpl_source { VplSource::Rsm => "rsm", VplSource::Buffer => "buffer" },
        out_format => features.output_format.wgsl(),
        shadows => features.shadows,
        glossy => features.glossy,
        counters => features.counters,
        tile_walk => features.tile_walk,
        ray_query => features.ray_query,
        motion => features.motion_vectors,
        reuse => features.reuse_domains > 0,
        reuse_domains => features.reuse_domains,
        pbr => match features.direct_output { DirectOutput::Irradiance => "none", DirectOutput::Radiance => "radiance", DirectOutput::Split => "split", DirectOutput::BevyRadiance => "bevy" },
        surface => match features.surface { SurfaceSource::Position => "position", SurfaceSource::Depth => "depth", SurfaceSource::R32Depth => "r32" },
        bindings => bindings::declarations(&bindings::bindings(kernel, features)),
        engine => slc_core::wgsl::translate(engine::WGSL),
    };
    let source = env
        .get_template(kernel.name())
        .and_then(|t| t.render(ctx))
        .map_err(|e| ShaderError::Template { kernel: kernel.name(), message: e.to_string() })?;
    let (module, info) = validate(kernel.name(), &source)?;
    Ok(Generated { kernel, source, module, info })
}

impl Generated {
    /// The kernel as naga's compaction leaves it (as naga's own snapshot
    /// tests keep their outputs): only what the entry points use, so a
    /// kernel's snapshot and translations hold that kernel, not the whole
    /// shared library; validated again.
    pub fn compacted(&self) -> Result<Generated, ShaderError> {
        let mut module = self.module.clone();
        naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
        let info = Validator::new(ValidationFlags::all(), capabilities(&module))
            .validate(&module)
            .map_err(|e| ShaderError::Naga {
                kernel: self.kernel.name(),
                message: format!("after compaction: {e}"),
            })?;
        Ok(Generated { kernel: self.kernel, source: self.source.clone(), module, info })
    }
}

/// [`generate_module`]'s WGSL source.
pub fn generate(kernel: Kernel, features: &Features) -> Result<String, ShaderError> {
    generate_module(kernel, features).map(|g| g.source)
}

/// Parses and validates WGSL with naga: WebGPU's baseline capabilities,
/// and ray queries where the module declares an acceleration structure
/// ([`Features::ray_query`]).
pub fn validate(
    kernel: &'static str,
    source: &str,
) -> Result<(naga::Module, ModuleInfo), ShaderError> {
    let module = naga::front::wgsl::parse_str(source)
        .map_err(|e| ShaderError::Naga { kernel, message: e.emit_to_string(source) })?;
    let info = Validator::new(ValidationFlags::all(), capabilities(&module))
        .validate(&module)
        .map_err(|e| ShaderError::Naga { kernel, message: e.emit_to_string(source) })?;
    Ok((module, info))
}

/// WebGPU's baseline capabilities, with [`Capabilities::RAY_QUERY`] where
/// `module` declares an acceleration structure.
fn capabilities(module: &naga::Module) -> Capabilities {
    let rq = module.global_variables.iter().any(|(_, v)| {
        matches!(module.types[v.ty].inner, naga::TypeInner::AccelerationStructure { .. })
    });
    if rq { Capabilities::default() | Capabilities::RAY_QUERY } else { Capabilities::default() }
}

/// Every kernel that applies to the features, generated and validated:
/// the VPL application's kernels (`vpl_tiled`, `vpl_denoise` and the
/// engine-pass kernels) only for a VPL-only light set, the others always.
pub fn all_kernels(features: &Features) -> Result<Vec<Generated>, ShaderError> {
    Kernel::ALL
        .iter()
        .filter(|&&k| {
            !k.is_vpl_frame()
                || features.lights == LightTypes { vpl: true, ..LightTypes::default() }
        })
        .filter(|&&k| {
            k != Kernel::DirectLight
                || matches!(
                    features.selection,
                    Selection::Reservoir
                        | Selection::Weighted
                        | Selection::Resampled
                        | Selection::All
                )
        })
        .map(|&k| generate_module(k, features))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::LightTypes;
    use slc_core::light::{Light, PointLight, TriangleLight};
    use slc_core::wgsl::vec3f;

    /// `within` is inclusion of sets, over all 32 × 32 pairs; `of` finds
    /// exactly the types present.
    #[test]
    fn light_type_sets() {
        for a in 0..32 {
            for b in 0..32 {
                let (ta, tb) = (LightTypes::from_bits(a), LightTypes::from_bits(b));
                assert_eq!(ta.within(tb), a & !b == 0, "{:?} within {:?}", ta.names(), tb.names());
            }
        }
        let p = Light::Point(PointLight::new(vec3f(0.0, 1.0, 0.0), vec3f(1.0, 1.0, 1.0)).unwrap());
        let t = Light::Triangle(
            TriangleLight::new(
                vec3f(0.0, 0.0, 0.0),
                vec3f(1.0, 0.0, 0.0),
                vec3f(0.0, 1.0, 0.0),
                vec3f(1.0, 1.0, 1.0),
            )
            .unwrap(),
        );
        assert_eq!(LightTypes::of(&[p.clone(), t, p]), LightTypes::from_bits(1 | 8));
        assert!(LightTypes::of(&[]).is_empty());
    }
}
