//! slc-core's shared functions as a WESL package (the shader language Bevy
//! 0.20 composes with `wesl` 0.6): one module per concern, the same split
//! and the same text as the naga_oil modules
//! ([`slc_core::wgsl::modules`]), each importing what it uses from the
//! others (`import super::prelude::{…};`), every item `public`. A user's shader imports them by
//! path, e.g. `import slc::range::{random_range2, slc_keep, slc_weight};`,
//! once the modules are mounted under the package name `slc` (with `wesl`:
//! a resolver that maps the module path `slc::{name}` to
//! [`WeslModule::source`]; `slc shaders --out DIR` writes them as
//! `DIR/wesl/slc/{name}.wesl`). Only `ies` declares a binding, the IES
//! table at `@group(1) @binding(0)`. slc itself does not depend on the
//! `wesl` crate (0.6 needs a newer Rust than slc's); slc-bevy's test
//! (`slc-bevy/tests/wesl_module.rs`, beside Bevy's own wesl) compiles a
//! user shader with it and runs it on the GPU.

/// One module of the `slc` WESL package.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WeslModule {
    /// Its name: the module path is `slc::{name}`.
    pub name: &'static str,
    /// Its WESL source.
    pub source: String,
}

/// The package's modules, in dependency order.
pub fn modules() -> Vec<WeslModule> {
    slc_core::wgsl::modules()
        .into_iter()
        .map(|m| {
            let mut source = format!("// slc::{}: generated from slc-core's shared code by slc-shared-shaders; do not edit.\n", m.name);
            for (dep, items) in &m.imports {
                source.push_str(&format!("import super::{dep}::{{{}}};\n", items.join(", ")));
            }
            source.push('\n');
            source.push_str(&public(&plain_table_binding(&m.wgsl)));
            WeslModule { name: m.name, source }
        })
        .collect()
}

/// `wgsl` with every top-level function, constant, struct and alias
/// declared `public` (WESL keeps a package's declarations to itself
/// otherwise).
fn public(wgsl: &str) -> String {
    let mut out = String::new();
    for line in wgsl.lines() {
        if ["fn ", "const ", "struct ", "alias "].iter().any(|k| line.starts_with(k)) {
            out.push_str("public ");
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

/// `wgsl` with naga_oil's `#ifdef SLC_TABLE_GROUP … #else … #endif` table
/// binding replaced by its `#else` branch (WESL has no shader defs).
fn plain_table_binding(wgsl: &str) -> String {
    let mut out = String::new();
    let mut state = 0; // 0 outside, 1 in the #ifdef branch, 2 in the #else branch
    for line in wgsl.lines() {
        match (state, line.trim()) {
            (0, l) if l.starts_with("#ifdef SLC_TABLE_GROUP") => state = 1,
            (1, "#else") => state = 2,
            (1 | 2, "#endif") => state = 0,
            (1, _) => {}
            _ => {
                out.push_str(line);
                out.push('\n');
            }
        }
    }
    out
}

#[cfg(test)]
fn range_has_public(m: &[WeslModule]) -> bool {
    m.iter().any(|m| m.name == "range" && m.source.contains("public fn random_range2("))
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn modules_are_plain_wesl() {
        let m = super::modules();
        let ies = m.iter().find(|m| m.name == "ies").unwrap();
        assert!(
            ies.source.contains("@group(1) @binding(0) var<storage, read> slc_table: array<f32>;"),
            "{}",
            ies.source
        );
        assert!(m.iter().all(|m| !m.source.contains('#')), "no naga_oil directives");
        assert!(
            m.iter().filter(|m| m.source.contains("\nimport super::")).count() > 5,
            "the modules import each other"
        );
        assert!(range_has_public(&m), "items are public");
    }
}
