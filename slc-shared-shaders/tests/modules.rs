//! slc-core's shared WGSL as composable modules (`slc_core::wgsl::modules`),
//! imported by a user shader through naga_oil, the composer Bevy uses.

use naga_oil::compose::{
    ComposableModuleDescriptor, Composer, NagaModuleDescriptor, ShaderDefValue, ShaderLanguage,
};
use std::collections::HashMap;

/// A composer holding every slc module (`slc::prelude`, `slc::xi`, …).
fn composer() -> Composer {
    let mut c = Composer::default();
    for m in slc_core::wgsl::modules() {
        let source = m.composable();
        let path = format!("slc/{}.wgsl", m.name);
        let added = c
            .add_composable_module(ComposableModuleDescriptor {
                source: &source,
                file_path: &path,
                language: ShaderLanguage::Wgsl,
                ..Default::default()
            })
            .map(|_| ())
            .map_err(|e| e.emit_to_string(&c));
        if let Err(e) = added {
            panic!("module slc::{}: {e}", m.name);
        }
    }
    c
}

/// Composes `src` and validates it with naga.
fn compose(c: &mut Composer, src: &str, defs: &[(&str, u32)]) -> naga::Module {
    let shader_defs: HashMap<String, ShaderDefValue> =
        defs.iter().map(|&(k, v)| (k.to_string(), ShaderDefValue::UInt(v))).collect();
    let module = c
        .make_naga_module(NagaModuleDescriptor {
            source: src,
            file_path: "user.wgsl",
            shader_defs,
            ..Default::default()
        })
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(c)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("composed shader does not validate: {e:?}"));
    module
}

/// The modules are the library, split: every item once, dependencies
/// before their users, and only `ies` reads the IES table.
#[test]
fn modules_partition_the_library() {
    let modules = slc_core::wgsl::modules();
    let mut seen: Vec<String> = Vec::new();
    for m in &modules {
        for (dep, items) in &m.imports {
            let d = modules.iter().position(|x| x.name == *dep).unwrap();
            assert!(
                d < modules.iter().position(|x| x.name == m.name).unwrap(),
                "{} imports the later {dep}",
                m.name
            );
            assert!(
                items.iter().all(|i| modules[d].items.contains(i)),
                "{} imports {items:?} from {dep}",
                m.name
            );
        }
        for i in &m.items {
            assert!(!seen.contains(i), "{i} defined twice");
            seen.push(i.clone());
        }
        assert_eq!(m.wgsl.contains("slc_table"), m.name == "ies", "{}", m.name);
    }
    let library = slc_core::wgsl::library();
    for i in &seen {
        assert!(
            library.contains(&format!("fn {i}("))
                || library.contains(&format!("const {i}:"))
                || library.contains(&format!("struct {i} "))
                || library.contains(&format!("alias {i} ")),
            "{i} is not in the library"
        );
    }
    assert!(seen.len() > 100, "{} items", seen.len());
}

/// A compute shader that imports slc's roulette and ξ, as an engine's would:
/// it composes and validates, and declares no IES table (only its own
/// buffer).
#[test]
fn user_shader_imports_slc_modules_without_the_ies_table() {
    let mut c = composer();
    let src = r#"
#import slc::xi::xi_for
#import slc::range::{random_range2, slc_keep, slc_weight}

@group(0) @binding(0) var<storage, read_write> out: array<f32>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u) {
    let r2 = random_range2(1.0, xi_for(7u, 0u, id.x));
    out[id.x] = select(0.0, slc_weight(1.0, 2.0), slc_keep(r2, 2.0));
}
"#;
    let m = compose(&mut c, src, &[]);
    let globals: Vec<_> = m.global_variables.iter().filter_map(|(_, g)| g.binding).collect();
    assert_eq!(
        globals,
        [naga::ResourceBinding { group: 0, binding: 0 }],
        "only the shader's own buffer is bound"
    );
}

/// Importing the IES lookup brings in its table, at the group and binding
/// the engine chooses with the `SLC_TABLE_GROUP` / `SLC_TABLE_BINDING`
/// shader defs (1 and 0 without them).
#[test]
fn ies_module_binds_its_table_where_the_engine_says() {
    let src = r#"
#import slc::ies::ies_candela_dir

@group(0) @binding(0) var<storage, read_write> out: array<f32>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u) {
    out[id.x] = ies_candela_dir(0u, 0u, 1.0, 0.0, 0.0);
}
"#;
    for (defs, want) in
        [(&[][..], (1, 0)), (&[("SLC_TABLE_GROUP", 2), ("SLC_TABLE_BINDING", 5)][..], (2, 5))]
    {
        let mut c = composer();
        let m = compose(&mut c, src, defs);
        let table = m
            .global_variables
            .iter()
            .find(|(_, g)| g.binding.as_ref().is_some_and(|b| b.group != 0))
            .map(|(_, g)| g.binding.unwrap());
        assert_eq!(
            table,
            Some(naga::ResourceBinding { group: want.0, binding: want.1 }),
            "defs {defs:?}"
        );
    }
}
