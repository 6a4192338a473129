//! Snapshot tests in the style of naga's `tests/out`: the generated WGSL of
//! representative variants of every kernel, and its SPIR-V (disassembled),
//! GLSL, HLSL and MSL translations, are committed under `tests/snapshots/`;
//! a change in the core's math, a template or naga's back ends shows up as
//! a readable diff. The WGSL is kept as naga's WGSL writer prints the
//! validated module, so the snapshots do not depend on how rustc's
//! `stringify!` spaces the shared code's tokens, and compacted by naga
//! first ([`Generated::compacted`]), so that a kernel's snapshot holds what
//! it uses rather than the whole shared library.
//! `SLC_BLESS=1 cargo test -p slc-shared-shaders --test snapshots` rewrites
//! them after a deliberate change.

use slc_shared_shaders::*;
use std::path::PathBuf;

fn variants() -> Vec<(&'static str, Kernel, Features)> {
    let vpl = LightTypes { vpl: true, ..LightTypes::default() };
    vec![
        ("light_update", Kernel::LightUpdate, Features::default()),
        ("bsh_refit", Kernel::BshRefit, Features::default()),
        ("bsh_tail", Kernel::BshTail, Features::default()),
        ("bsh_grid", Kernel::BshGrid, Features::default()),
        (
            "vpl_tiled-slc-tile8-p8",
            Kernel::VplTiled,
            Features { lights: vpl, ..Features::default() },
        ),
        (
            "vpl_tiled-clamp-tile8-p8",
            Kernel::VplTiled,
            Features { lights: vpl, method: CullKind::Clamped, ..Features::default() },
        ),
        ("vpl_denoise-tile8", Kernel::VplDenoise, Features { lights: vpl, ..Features::default() }),
        ("vpl_near-slc-tile8-p8", Kernel::VplNear, Features { lights: vpl, ..Features::default() }),
        (
            "vpl_near-clamp-tile8-p8",
            Kernel::VplNear,
            Features { lights: vpl, method: CullKind::Clamped, ..Features::default() },
        ),
        (
            "vpl_near-slc-tile8-p8-counters",
            Kernel::VplNear,
            Features { lights: vpl, counters: true, ..Features::default() },
        ),
        (
            "vpl_tiled-slc-tile8-p8-counters",
            Kernel::VplTiled,
            Features { lights: vpl, counters: true, ..Features::default() },
        ),
        (
            "vpl_clusters-slc-p8",
            Kernel::VplClusters,
            Features { lights: vpl, ..Features::default() },
        ),
        ("vpl_groups", Kernel::VplGroups, Features { lights: vpl, ..Features::default() }),
        (
            "vpl_tiled-slc-tile8-p8-glossy",
            Kernel::VplTiled,
            Features { lights: vpl, glossy: true, ..Features::default() },
        ),
        (
            "vpl_tiled-none-tile8-p1-glossy",
            Kernel::VplTiled,
            Features {
                lights: vpl,
                method: CullKind::None,
                interleave: 1,
                glossy: true,
                ..Features::default()
            },
        ),
        (
            "vpl_near-slc-tile8-p8-glossy",
            Kernel::VplNear,
            Features { lights: vpl, glossy: true, ..Features::default() },
        ),
        (
            "bsh_reservoir-point-spot-ies-k8",
            Kernel::BshReservoir,
            Features {
                lights: LightTypes::parse("point,spot,ies").unwrap(),
                ..Features::default()
            },
        ),
        (
            "bsh_reservoir-point-triangle-unshadowed",
            Kernel::BshReservoir,
            Features {
                lights: LightTypes::parse("point,triangle").unwrap(),
                shadows: false,
                ..Features::default()
            },
        ),
        (
            "pt_connect-triangle-k8-power",
            Kernel::PtConnect,
            Features { lights: LightTypes::parse("triangle").unwrap(), ..Features::default() },
        ),
        (
            "pt_connect-triangle-lightbvh",
            Kernel::PtConnect,
            Features {
                lights: LightTypes::parse("triangle").unwrap(),
                selection: Selection::LightBvh,
                ..Features::default()
            },
        ),
        (
            "pt_connect-weighted-grid",
            Kernel::PtConnect,
            Features { selection: Selection::Weighted, bsh_grid: true, ..Features::default() },
        ),
        (
            "pt_connect-all-k16-balance",
            Kernel::PtConnect,
            Features { reservoir_k: 16, heuristic: Heuristic::Balance, ..Features::default() },
        ),
        (
            "pt_extend-triangle-point-k8-power",
            Kernel::PtExtend,
            Features {
                lights: LightTypes::parse("point,triangle").unwrap(),
                ..Features::default()
            },
        ),
        ("vpl_pack-rsm", Kernel::VplPack, Features { lights: vpl, ..Features::default() }),
        (
            "vpl_pack-buffer",
            Kernel::VplPack,
            Features { lights: vpl, vpl_source: VplSource::Buffer, ..Features::default() },
        ),
        (
            "irradiance_export-rgba32float",
            Kernel::IrradianceExport,
            Features {
                lights: vpl,
                output_format: OutputFormat::Rgba32Float,
                ..Features::default()
            },
        ),
        ("scene_raster", Kernel::SceneRaster, Features { lights: vpl, ..Features::default() }),
        ("primary_direct", Kernel::PrimaryDirect, Features { lights: vpl, ..Features::default() }),
        (
            "frame_compose-rgba16float",
            Kernel::FrameCompose,
            Features { lights: vpl, ..Features::default() },
        ),
        (
            "frame_compose-rgba32float-glossy",
            Kernel::FrameCompose,
            Features {
                lights: vpl,
                output_format: OutputFormat::Rgba32Float,
                glossy: true,
                ..Features::default()
            },
        ),
        (
            "irradiance_export-rgba32float-glossy",
            Kernel::IrradianceExport,
            Features {
                lights: vpl,
                output_format: OutputFormat::Rgba32Float,
                glossy: true,
                ..Features::default()
            },
        ),
        ("light_ranges", Kernel::LightRanges, Features::default()),
        (
            "temporal-position",
            Kernel::Temporal,
            Features {
                lights: vpl,
                output_format: OutputFormat::Rgba32Float,
                ..Features::default()
            },
        ),
        (
            "temporal-motion",
            Kernel::Temporal,
            Features {
                lights: vpl,
                output_format: OutputFormat::Rgba32Float,
                motion_vectors: true,
                ..Features::default()
            },
        ),
        (
            "temporal-r32depth-rgba16float",
            Kernel::Temporal,
            Features { lights: vpl, surface: SurfaceSource::R32Depth, ..Features::default() },
        ),
        (
            "direct_light-point-spot-weighted-r32depth",
            Kernel::DirectLight,
            Features {
                lights: LightTypes::parse("point,spot").unwrap(),
                selection: Selection::Weighted,
                // naga's GLSL writer cannot load from a depth texture.
                surface: SurfaceSource::R32Depth,
                ..Features::default()
            },
        ),
        (
            "direct_light-point-weighted-pixel-walk",
            Kernel::DirectLight,
            Features {
                lights: LightTypes::parse("point").unwrap(),
                selection: Selection::Weighted,
                tile_walk: false,
                ..Features::default()
            },
        ),
        (
            "direct_light-all-reservoir-position",
            Kernel::DirectLight,
            Features {
                lights: LightTypes::parse("point,spot,ies,triangle").unwrap(),
                output_format: OutputFormat::Rgba32Float,
                // The unshadowed variant (the others are shadowed).
                shadows: false,
                ..Features::default()
            },
        ),
        (
            "direct_light-triangle-weighted-split",
            Kernel::DirectLight,
            Features {
                lights: LightTypes::parse("triangle").unwrap(),
                selection: Selection::Weighted,
                direct_output: DirectOutput::Split,
                ..Features::default()
            },
        ),
        (
            "direct_light-point-triangle-resampled-bevy",
            Kernel::DirectLight,
            Features {
                lights: LightTypes::parse("point,triangle").unwrap(),
                selection: Selection::Resampled,
                direct_output: DirectOutput::BevyRadiance,
                ..Features::default()
            },
        ),
        (
            "direct_light-point-triangle-resampled-bevy-reuse",
            Kernel::DirectLight,
            Features {
                lights: LightTypes::parse("point,triangle").unwrap(),
                selection: Selection::Resampled,
                direct_output: DirectOutput::BevyRadiance,
                reuse_domains: 3,
                ..Features::default()
            },
        ),
        (
            "direct_light-point-spot-resampled-counting",
            Kernel::DirectLight,
            Features {
                lights: LightTypes::parse("point,spot").unwrap(),
                selection: Selection::Resampled,
                counters: true,
                ..Features::default()
            },
        ),
    ]
}

/// Compares `got` with the snapshot at `path` (or writes it under
/// `SLC_BLESS`), collecting a readable diff on a mismatch.
fn compare(path: &std::path::Path, got: &str, bless: bool, failures: &mut Vec<String>) {
    if bless {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, got).unwrap();
        return;
    }
    let want = std::fs::read_to_string(path).unwrap_or_else(|_| {
        panic!("missing snapshot {}; run with SLC_BLESS=1 to create it", path.display())
    });
    if got != want {
        let diff = similar::TextDiff::from_lines(want.as_str(), got);
        failures.push(format!(
            "{}:\n{}",
            path.display(),
            diff.unified_diff().context_radius(2).header("snapshot", "generated")
        ));
    }
}

/// naga's WGSL writer's form of a validated module.
fn normalised_wgsl(module: &naga::Module, info: &naga::valid::ModuleInfo) -> String {
    naga::back::wgsl::write_string(module, info, naga::back::wgsl::WriterFlags::empty()).unwrap()
}

/// SPIR-V words as rspirv's disassembly (naga's own tests keep `.spvasm`).
fn spvasm(words: &[u32]) -> String {
    use rspirv::binary::Disassemble;
    rspirv::dr::load_words(words).unwrap().disassemble() + "\n"
}

/// slc-core's shared WGSL library (`library.wgsl`), every variant's WGSL
/// (`tests/snapshots/`) and, as naga's own tests keep them, its
/// translations: `spv/` (disassembled), `glsl/` (one file per entry point),
/// `hlsl/` and `msl/`.
#[test]
fn generated_kernels_match_snapshots() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots");
    let bless = std::env::var_os("SLC_BLESS").is_some();
    let mut failures = Vec::new();
    // The shared library alone: every slc-core function as WGSL.
    let lib = format!(
        "{}\n@group(1) @binding(0) var<storage, read> slc_table: array<f32>;\n",
        slc_core::wgsl::library()
    );
    let (module, info) = validate("library", &lib).unwrap();
    compare(&dir.join("library.wgsl"), &normalised_wgsl(&module, &info), bless, &mut failures);
    for (name, kernel, features) in variants() {
        // Compacted, as naga's snapshot tests are: what the kernel uses.
        let g = generate_module(kernel, &features).unwrap().compacted().unwrap();
        compare(
            &dir.join(format!("{name}.wgsl")),
            &normalised_wgsl(&g.module, &g.info),
            bless,
            &mut failures,
        );
        let t = translate(&g).unwrap();
        compare(
            &dir.join("spv").join(format!("{name}.spvasm")),
            &spvasm(&t.spv),
            bless,
            &mut failures,
        );
        for (entry, src) in &t.glsl_entries {
            let file = if t.glsl_entries.len() > 1 {
                format!("{name}.{entry}.glsl")
            } else {
                format!("{name}.glsl")
            };
            compare(&dir.join("glsl").join(file), src, bless, &mut failures);
        }
        compare(&dir.join("hlsl").join(format!("{name}.hlsl")), &t.hlsl, bless, &mut failures);
        compare(&dir.join("msl").join(format!("{name}.metal")), &t.msl, bless, &mut failures);
    }
    assert!(
        failures.is_empty(),
        "generated kernels changed (SLC_BLESS=1 to accept):\n{}",
        failures.join("\n")
    );
}

/// Every kernel has at least one snapshot variant: a new kernel without
/// one fails here, not in review.
#[test]
fn every_kernel_has_a_snapshot() {
    let covered: Vec<Kernel> = variants().into_iter().map(|(_, k, _)| k).collect();
    let missing: Vec<&str> =
        Kernel::ALL.iter().filter(|k| !covered.contains(k)).map(|k| k.name()).collect();
    assert!(missing.is_empty(), "kernels without a snapshot variant: {}", missing.join(", "));
}
