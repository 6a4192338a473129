//! Each kernel's binding table ([`slc_shared_shaders::bindings`]) is what
//! its validated module declares: the same globals at the same
//! group and binding, of the same kind and access, for a spread of feature
//! sets of every kernel; and a table's bound entries are those the entry
//! points use (a `bound = false` entry is declared for the library only).

use naga::{AddressSpace, ImageClass, StorageAccess, TypeInner};
use slc_shared_shaders::bindings::{Resource, bindings};
use slc_shared_shaders::*;

fn feature_sets() -> Vec<Features> {
    let vpl = LightTypes { vpl: true, ..LightTypes::default() };
    let mut v = Vec::new();
    for lights in [
        LightTypes::ALL,
        vpl,
        LightTypes::parse("point,ies").unwrap(),
        LightTypes::parse("triangle").unwrap(),
    ] {
        for (selection, surface) in [
            (Selection::Reservoir, SurfaceSource::Position),
            (Selection::Weighted, SurfaceSource::Depth),
            (Selection::All, SurfaceSource::R32Depth),
        ] {
            for (shadows, vpl_source, direct_output) in [
                (true, VplSource::Rsm, DirectOutput::Irradiance),
                (false, VplSource::Buffer, DirectOutput::Split),
                (true, VplSource::Rsm, DirectOutput::Radiance),
            ] {
                // The glossy VPL kernels with the split direct output.
                let glossy = direct_output == DirectOutput::Split;
                v.push(Features {
                    lights,
                    selection,
                    surface,
                    shadows,
                    vpl_source,
                    direct_output,
                    glossy,
                    ..Features::default()
                });
            }
        }
    }
    // Shadow rays as ray queries (direct_light and pt_connect only).
    v.push(Features { ray_query: true, ..Features::default() });
    v.push(Features {
        ray_query: true,
        selection: Selection::Weighted,
        surface: SurfaceSource::Depth,
        ..Features::default()
    });
    v
}

#[test]
fn tables_match_the_modules() {
    let mut checked = 0;
    for f in feature_sets() {
        for &kernel in &Kernel::ALL {
            if f.ray_query && !matches!(kernel, Kernel::DirectLight | Kernel::PtConnect) {
                continue;
            }
            if kernel.is_vpl_frame()
                && f.lights != (LightTypes { vpl: true, ..LightTypes::default() })
            {
                continue;
            }
            let g = generate_module(kernel, &f)
                .unwrap_or_else(|e| panic!("{} {f:?}: {e}", kernel.name()));
            let mut table = bindings(kernel, &f);
            table.sort_by_key(|b| (b.group, b.binding));
            // naga orders globals by use, not by declaration: compare by slot.
            let mut globals: Vec<_> =
                g.module.global_variables.iter().filter(|(_, v)| v.binding.is_some()).collect();
            globals.sort_by_key(|(_, v)| v.binding.as_ref().map(|b| (b.group, b.binding)));
            assert_eq!(
                globals.len(),
                table.len(),
                "{}: {} globals, {} table entries",
                kernel.name(),
                globals.len(),
                table.len()
            );
            for ((handle, var), b) in globals.into_iter().zip(&table) {
                let rb = var.binding.as_ref().unwrap();
                let what = format!("{} {}", kernel.name(), b.name);
                assert_eq!((rb.group, rb.binding), (b.group, b.binding), "{what}");
                assert_eq!(var.name.as_deref(), Some(b.name), "{what}");
                let inner = &g.module.types[var.ty].inner;
                match b.resource {
                    Resource::Uniform { .. } => {
                        assert_eq!(var.space, AddressSpace::Uniform, "{what}")
                    }
                    Resource::Read(_) => {
                        assert_eq!(
                            var.space,
                            AddressSpace::Storage { access: StorageAccess::LOAD },
                            "{what}"
                        )
                    }
                    Resource::ReadWrite(_) => {
                        assert_eq!(
                            var.space,
                            AddressSpace::Storage {
                                access: StorageAccess::LOAD | StorageAccess::STORE
                            },
                            "{what}"
                        )
                    }
                    Resource::Texture => {
                        assert!(
                            matches!(
                                inner,
                                TypeInner::Image { class: ImageClass::Sampled { .. }, .. }
                            ),
                            "{what}: {inner:?}"
                        )
                    }
                    Resource::DepthTexture => assert!(
                        matches!(inner, TypeInner::Image { class: ImageClass::Depth { .. }, .. }),
                        "{what}"
                    ),
                    Resource::StorageTexture(_) => assert!(
                        matches!(inner, TypeInner::Image { class: ImageClass::Storage { .. }, .. }),
                        "{what}"
                    ),
                    Resource::AccelerationStructure => {
                        assert!(matches!(inner, TypeInner::AccelerationStructure { .. }), "{what}")
                    }
                }
                // A bound entry is used by an entry point; an unbound one by none.
                let used = g.info.get_entry_point(0)[handle] != naga::valid::GlobalUse::empty()
                    || (0..g.module.entry_points.len()).any(|e| {
                        g.info.get_entry_point(e)[handle] != naga::valid::GlobalUse::empty()
                    });
                if !b.bound {
                    assert!(!used, "{what}: marked unbound but used");
                }
                checked += 1;
            }
        }
    }
    assert!(checked > 1000, "{checked}");
}

/// The declarations the templates receive are the table's, line for line.
#[test]
fn declarations_are_the_tables() {
    let f = Features {
        selection: Selection::Weighted,
        surface: SurfaceSource::Depth,
        ..Features::default()
    };
    let decl = bindings::declarations(&bindings(Kernel::DirectLight, &f));
    let src = generate(Kernel::DirectLight, &f).unwrap();
    for line in decl.lines() {
        assert!(src.contains(line), "{line}");
    }
    assert!(decl.contains("@group(0) @binding(1) var depth_tex: texture_depth_2d;"), "{decl}");
}

/// `docs/bindings.md` (the binding tables in the crate docs) is the
/// tables' current form; `SLC_BLESS=1` rewrites it.
#[test]
fn binding_docs_are_current() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/bindings.md");
    let want = bindings::docs();
    if std::env::var_os("SLC_BLESS").is_some() {
        std::fs::write(&path, &want).unwrap();
    }
    let have = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        have == want,
        "docs/bindings.md is stale: run SLC_BLESS=1 cargo test -p slc-shared-shaders --test bindings"
    );
}
