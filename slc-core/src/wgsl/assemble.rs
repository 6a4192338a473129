//! Assembly of the WGSL library: the prelude that maps the helpers of
//! [`builtins`](super::builtins) to WGSL, every module's shared text in
//! dependency order, and the mapping from `stringify!` output to formatted
//! WGSL.

use alloc::string::String;
use alloc::vec::Vec;

// The prelude's pieces, as macros so that `concat!` can join them.
macro_rules! table_reader {
    () => {
        "alias Table = u32;\nfn at(tab: Table, i: u32) -> f32 { return slc_table[i]; }\n"
    };
}
macro_rules! numeric_helpers {
    () => {
        "fn to_f32(u: u32) -> f32 { return f32(u); }
fn to_u32(x: f32) -> u32 { return u32(x); }
fn mul_lo_u32(a: u32, b: u32) -> u32 { return a * b; }
fn add_wrap_u32(a: u32, b: u32) -> u32 { return a + b; }
fn f32_from_bits(u: u32) -> f32 { return bitcast<f32>(u); }
fn f32_to_bits(x: f32) -> u32 { return bitcast<u32>(x); }
"
    };
}
macro_rules! table_binding {
    () => {
        "@group(1) @binding(0) var<storage, read> slc_table: array<f32>;\n"
    };
}
macro_rules! composable_table_binding {
    () => {
        concat!(
            "#ifdef SLC_TABLE_GROUP\n",
            "@group(#{SLC_TABLE_GROUP}) @binding(#{SLC_TABLE_BINDING}) var<storage, read> slc_table: array<f32>;\n",
            "#else\n",
            table_binding!(),
            "#endif\n"
        )
    };
}

/// WGSL definitions of the helpers in [`builtins`](super::builtins) that are
/// not WGSL built-ins. A
/// module that uses [`library`] must also declare the table buffer, e.g.
/// `@group(0) @binding(5) var<storage, read> slc_table: array<f32>;`.
pub const PRELUDE: &str = concat!(table_reader!(), numeric_helpers!());

/// The helpers of [`PRELUDE`] every module may use (not the table reader,
/// which belongs to the IES module).
const NUMERIC_PRELUDE: &str = numeric_helpers!();

/// The IES module's table, as a naga_oil module declares it: at the group
/// and binding of the `SLC_TABLE_GROUP` / `SLC_TABLE_BINDING` shader defs
/// (give both), else at group 1, binding 0; then its reader.
const IES_TABLE: &str = concat!(composable_table_binding!(), table_reader!());

/// Every module's name and shared items, in dependency order, as raw text.
const MODULES: [(&str, &str); 18] = [
    ("xi", crate::xi::WGSL),
    ("range", crate::range::WGSL),
    ("sphere", crate::sphere::WGSL),
    ("cluster", crate::cluster::WGSL),
    ("light", crate::light::WGSL),
    ("ies", crate::ies::lookup::WGSL),
    ("bsh", crate::bsh::WGSL),
    ("reservoir", crate::reservoir::WGSL),
    ("mis", crate::mis::WGSL),
    ("brdf", crate::brdf::WGSL),
    ("importance", crate::importance::WGSL),
    ("light_bvh", crate::light_bvh::WGSL),
    ("ray", crate::ray::WGSL),
    ("denoise", crate::denoise::WGSL),
    ("interleave", crate::interleave::WGSL),
    ("path", crate::path::WGSL),
    ("frame", crate::frame::WGSL),
    ("temporal", crate::temporal::WGSL),
];

/// The whole shared library as WGSL: [`PRELUDE`] followed by every shared
/// item of slc-core, formatted one statement per line. Kernel templates
/// include this text; they never retype a formula.
pub fn library() -> String {
    let mut out = String::from("// slc-core shared functions (generated from Rust; do not edit)\n");
    out.push_str(PRELUDE);
    for (_, part) in MODULES {
        out.push_str(&translate(part));
    }
    out
}

/// One concern of the shared library (a slc-core module) as WGSL that an
/// engine can use alone, with the modules it needs: e.g. `range` (the
/// roulette) needs only `prelude`; only `ies` reads the IES table, so code
/// that imports no IES function declares no table binding.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WgslModule {
    /// Its name; as a naga_oil module its import path is `slc::{name}`.
    pub name: &'static str,
    /// The items it uses from earlier modules: `(module, items)`.
    pub imports: Vec<(&'static str, Vec<String>)>,
    /// Its own items (functions, constants, structs, aliases).
    pub items: Vec<String>,
    /// Its WGSL (the IES module's table binding in naga_oil syntax: the
    /// `SLC_TABLE_GROUP` / `SLC_TABLE_BINDING` shader defs, else group 1,
    /// binding 0; [`modules_wgsl`] gives it as plain WGSL).
    pub wgsl: String,
}

impl WgslModule {
    /// The module as a naga_oil composable module:
    /// `#define_import_path slc::{name}`, an `#import slc::{m}::{items}`
    /// line per module it uses, then its WGSL.
    pub fn composable(&self) -> String {
        let mut out = alloc::format!("#define_import_path slc::{}\n", self.name);
        for (m, items) in &self.imports {
            out.push_str(&alloc::format!("#import slc::{m}::{{{}}}\n", items.join(", ")));
        }
        out.push('\n');
        out.push_str(&self.wgsl);
        out
    }
}

/// The shared library split by concern, in dependency order: `prelude`
/// (the integer and conversion helpers), then one module per slc-core
/// module with shared code. The same text as [`library`], item for item.
pub fn modules() -> Vec<WgslModule> {
    let mut out: Vec<WgslModule> = Vec::new();
    let mut add = |name: &'static str, wgsl: String| {
        let words = identifiers(&wgsl);
        let imports = out
            .iter()
            .filter_map(|m| {
                let used: Vec<String> =
                    m.items.iter().filter(|i| words.iter().any(|w| w == *i)).cloned().collect();
                (!used.is_empty()).then_some((m.name, used))
            })
            .collect();
        let items = wgsl
            .lines()
            .filter_map(|l| {
                let rest = ["fn ", "const ", "struct ", "alias "]
                    .iter()
                    .find_map(|k| l.strip_prefix(k))?;
                let end = rest
                    .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .unwrap_or(rest.len());
                Some(String::from(&rest[..end]))
            })
            .collect();
        out.push(WgslModule { name, imports, items, wgsl });
    };
    add("prelude", String::from(NUMERIC_PRELUDE));
    for (name, part) in MODULES {
        let mut wgsl = String::new();
        if name == "ies" {
            // naga_oil keeps no type aliases (naga's writer substitutes them):
            // the table handle is spelled `u32` in the module.
            wgsl.push_str(
                &IES_TABLE.replace("alias Table = u32;\n", "").replace(": Table", ": u32"),
            );
            wgsl.push_str(&translate(part).replace(": Table", ": u32"));
        } else {
            wgsl.push_str(&translate(part));
        }
        add(name, wgsl);
    }
    out
}

/// Plain WGSL of the modules `names` and of every module they use, in
/// dependency order, for a shader that pastes slc's functions without a
/// composer: e.g. `modules_wgsl(&["xi", "range"])` is the roulette and its
/// random numbers, and needs no binding. With `ies`, the IES table is
/// declared at `@group(1) @binding(0)`. `None` for an unknown name.
pub fn modules_wgsl(names: &[&str]) -> Option<String> {
    let all = modules();
    let mut need = alloc::vec![false; all.len()];
    let mut stack: Vec<usize> = Vec::new();
    for n in names {
        stack.push(all.iter().position(|m| m.name == *n)?);
    }
    while let Some(i) = stack.pop() {
        if !need[i] {
            need[i] = true;
            stack.extend(
                all[i].imports.iter().filter_map(|(d, _)| all.iter().position(|m| m.name == *d)),
            );
        }
    }
    let mut out = String::new();
    for (m, _) in all.iter().zip(&need).filter(|(_, n)| **n) {
        out.push_str(&m.wgsl.replace(composable_table_binding!(), table_binding!()));
    }
    Some(out)
}

/// The identifier tokens of WGSL text.
fn identifiers(s: &str) -> Vec<&str> {
    s.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| w.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_'))
        .collect()
}

/// Maps raw `stringify!` text to formatted WGSL: `let mut` becomes `var`,
/// whitespace is normalised, and statements are laid out one per line with
/// four-space indentation (`} else {` stays on one line).
pub fn translate(raw: &str) -> String {
    // Collapse every whitespace run (stringify! wraps long items) to one space.
    let mut flat = String::with_capacity(raw.len());
    for word in raw.split_whitespace() {
        if !flat.is_empty() {
            flat.push(' ');
        }
        flat.push_str(word);
    }
    let text = tighten_calls(&flat.replace("let mut ", "var ").replace(" : ", ": "));
    let mut out = String::with_capacity(text.len() + text.len() / 4);
    let mut depth = 0usize;
    let mut paren = 0usize;
    let mut line = String::new();
    let flush = |line: &mut String, out: &mut String, depth: usize| {
        let t = line.trim();
        if !t.is_empty() {
            for _ in 0..depth {
                out.push_str("    ");
            }
            out.push_str(t);
            out.push('\n');
        }
        line.clear();
    };
    for (i, ch) in text.char_indices() {
        match ch {
            '(' => {
                paren += 1;
                line.push(ch);
            }
            ')' => {
                paren = paren.saturating_sub(1);
                line.push(ch);
            }
            '{' => {
                line.push('{');
                flush(&mut line, &mut out, depth);
                depth += 1;
            }
            '}' => {
                flush(&mut line, &mut out, depth);
                depth = depth.saturating_sub(1);
                line.push('}');
                if !text[i + 1..].trim_start().starts_with("else") {
                    flush(&mut line, &mut out, depth);
                }
            }
            ';' if paren == 0 => {
                line.push(';');
                flush(&mut line, &mut out, depth);
            }
            ' ' if line.is_empty() => {}
            _ => line.push(ch),
        }
    }
    flush(&mut line, &mut out, depth);
    out
}

/// Drops the space stringify! puts between a function name and its `(`
/// (`f (x)` → `f(x)`), keeping it after keywords and operators.
fn tighten_calls(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let b = s.as_bytes();
    for (i, ch) in s.char_indices() {
        if ch == ' ' && b.get(i + 1) == Some(&b'(') {
            let word_start =
                out.rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).map_or(0, |p| p + 1);
            let word = &out[word_start..];
            let ident = word.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_');
            if ident && !matches!(word, "return" | "if" | "while" | "else") {
                continue;
            }
        }
        out.push(ch);
    }
    out
}
