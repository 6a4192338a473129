//! Assembly of the WGSL library: the prelude that maps the helpers of
//! [`builtins`](super::builtins) to WGSL, every module's shared text in
//! dependency order, and the mapping from `stringify!` output to formatted
//! WGSL.

use alloc::string::String;

/// WGSL definitions of the helpers in [`builtins`](super::builtins) that are
/// not WGSL built-ins. A
/// module that uses [`library`] must also declare the table buffer, e.g.
/// `@group(0) @binding(5) var<storage, read> slc_table: array<f32>;`.
pub const PRELUDE: &str = "\
alias Table = u32;
fn at(tab: Table, i: u32) -> f32 { return slc_table[i]; }
fn to_f32(u: u32) -> f32 { return f32(u); }
fn to_u32(x: f32) -> u32 { return u32(x); }
fn mul_lo_u32(a: u32, b: u32) -> u32 { return a * b; }
fn add_wrap_u32(a: u32, b: u32) -> u32 { return a + b; }
";

/// Every module's shared items, in dependency order, as raw text.
const PARTS: [&str; 15] = [
    crate::xi::WGSL,
    crate::range::WGSL,
    crate::sphere::WGSL,
    crate::light::WGSL,
    crate::ies::lookup::WGSL,
    crate::bsh::WGSL,
    crate::reservoir::WGSL,
    crate::importance::WGSL,
    crate::light_bvh::WGSL,
    crate::ray::WGSL,
    crate::mis::WGSL,
    crate::denoise::WGSL,
    crate::interleave::WGSL,
    crate::path::WGSL,
    crate::frame::WGSL,
];

/// The whole shared library as WGSL: [`PRELUDE`] followed by every shared
/// item of slc-core, formatted one statement per line. Kernel templates
/// include this text; they never retype a formula.
pub fn library() -> String {
    let mut out = String::from("// slc-core shared functions (generated from Rust; do not edit)\n");
    out.push_str(PRELUDE);
    for part in PARTS {
        out.push_str(&translate(part));
    }
    out
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
            let word_start = out.rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).map_or(0, |p| p + 1);
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
