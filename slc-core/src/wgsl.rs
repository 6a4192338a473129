//! Code written once for the CPU and the GPU.
//!
//! The functions the GPU needs (range math, light intensities, the IES
//! lookup, sphere tests, the reservoir update) are written in the common
//! subset of Rust and WGSL (DESIGN.md §3) inside [`shared!`](crate::shared) blocks. The macro
//! emits each item as ordinary Rust and also `stringify!`s the same tokens into
//! the module's `WGSL` constant. [`library`] assembles every module's text,
//! maps the few spellings that differ (`let mut` → `var`), and lays it out one
//! statement per line.
//!
//! Rules for code inside `shared!` (checked by naga in the tests):
//! - explicit `return`; no casts, no method calls, no closures, no `for`;
//! - every `let mut` has an explicit type (WGSL would infer `i32` for `0`);
//! - integer arithmetic that may wrap goes through [`mul_lo_u32`] /
//!   [`add_wrap_u32`];
//! - conversions go through [`to_f32`] / [`to_u32`]; table reads through [`at`].
//!
//! This module also holds the Rust definitions of the WGSL built-ins the shared
//! code uses (`min`, `select`, `dot`, ...), with WGSL's semantics.

use alloc::string::String;
use glam::Vec3;

/// Rust spelling of WGSL's `vec3f`.
#[allow(non_camel_case_types)]
pub type vec3f = Vec3;

/// WGSL's `vec3f(x, y, z)` constructor.
#[inline]
pub fn vec3f(x: f32, y: f32, z: f32) -> Vec3 {
    Vec3::new(x, y, z)
}

/// Rust spelling of WGSL's `vec4f`.
#[allow(non_camel_case_types)]
pub type vec4f = glam::Vec4;

/// WGSL's `vec4f(x, y, z, w)` constructor.
#[inline]
pub fn vec4f(x: f32, y: f32, z: f32, w: f32) -> glam::Vec4 {
    glam::Vec4::new(x, y, z, w)
}

/// A read-only table of `f32` indexed with `u32`: a slice on the CPU. In WGSL
/// the same parameter is a dummy `u32` and [`at`] reads the module-scope
/// storage buffer `slc_table` (see [`PRELUDE`]).
pub type Table<'a> = &'a [f32];

/// `tab[i]`, or `0.0` outside the table (WGSL's robust-access behaviour is
/// also a clamped or zero read, never a fault).
#[inline]
pub fn at(tab: Table, i: u32) -> f32 {
    match tab.get(i as usize) {
        Some(v) => *v,
        None => 0.0,
    }
}

/// WGSL's `f32(u)`.
#[inline]
pub fn to_f32(u: u32) -> f32 {
    u as f32
}

/// WGSL's `u32(x)` for `x` in `[0, 2³²)`; saturates outside (Rust `as` and
/// WGSL's conversion agree on that range, which is all shared code uses).
#[inline]
pub fn to_u32(x: f32) -> u32 {
    x as u32
}

/// Low 32 bits of `a · b` (WGSL's `u32` multiply wraps).
#[inline]
pub fn mul_lo_u32(a: u32, b: u32) -> u32 {
    a.wrapping_mul(b)
}

/// `a + b` modulo 2³² (WGSL's `u32` add wraps).
#[inline]
pub fn add_wrap_u32(a: u32, b: u32) -> u32 {
    a.wrapping_add(b)
}

/// Types WGSL's `min`/`max`/`clamp`/`select` accept in shared code.
pub trait WgslScalar: Copy {
    /// WGSL `min`.
    fn wmin(self, o: Self) -> Self;
    /// WGSL `max`.
    fn wmax(self, o: Self) -> Self;
}
impl WgslScalar for f32 {
    #[inline]
    fn wmin(self, o: Self) -> Self {
        f32::min(self, o)
    }
    #[inline]
    fn wmax(self, o: Self) -> Self {
        f32::max(self, o)
    }
}
impl WgslScalar for u32 {
    #[inline]
    fn wmin(self, o: Self) -> Self {
        if self < o { self } else { o }
    }
    #[inline]
    fn wmax(self, o: Self) -> Self {
        if self > o { self } else { o }
    }
}
impl WgslScalar for Vec3 {
    #[inline]
    fn wmin(self, o: Self) -> Self {
        vec3f(self.x.wmin(o.x), self.y.wmin(o.y), self.z.wmin(o.z))
    }
    #[inline]
    fn wmax(self, o: Self) -> Self {
        vec3f(self.x.wmax(o.x), self.y.wmax(o.y), self.z.wmax(o.z))
    }
}

/// WGSL `min` (component-wise on vectors).
#[inline]
pub fn min<T: WgslScalar>(a: T, b: T) -> T {
    a.wmin(b)
}
/// WGSL `max` (component-wise on vectors).
#[inline]
pub fn max<T: WgslScalar>(a: T, b: T) -> T {
    a.wmax(b)
}
/// WGSL `clamp(e, lo, hi) = min(max(e, lo), hi)`; never panics for `lo > hi`.
#[inline]
pub fn clamp<T: WgslScalar>(e: T, lo: T, hi: T) -> T {
    e.wmax(lo).wmin(hi)
}
/// WGSL `select(f, t, cond)`.
#[inline]
pub fn select<T>(f: T, t: T, cond: bool) -> T {
    if cond { t } else { f }
}
/// WGSL `dot`.
#[inline]
pub fn dot(a: Vec3, b: Vec3) -> f32 {
    a.x * b.x + a.y * b.y + a.z * b.z
}
/// WGSL `cross`.
#[inline]
pub fn cross(a: Vec3, b: Vec3) -> Vec3 {
    a.cross(b)
}
/// WGSL `normalize`.
#[inline]
pub fn normalize(v: Vec3) -> Vec3 {
    v / sqrt(dot(v, v))
}
/// WGSL `sqrt`.
#[inline]
pub fn sqrt(x: f32) -> f32 {
    libm::sqrtf(x)
}
/// WGSL `floor`.
#[inline]
pub fn floor(x: f32) -> f32 {
    libm::floorf(x)
}
/// WGSL `abs`.
#[inline]
pub fn abs(x: f32) -> f32 {
    libm::fabsf(x)
}
/// WGSL `acos`.
#[inline]
pub fn acos(x: f32) -> f32 {
    libm::acosf(x)
}
/// WGSL `atan2(y, x)`.
#[inline]
pub fn atan2(y: f32, x: f32) -> f32 {
    libm::atan2f(y, x)
}
/// WGSL `cos`.
#[inline]
pub fn cos(x: f32) -> f32 {
    libm::cosf(x)
}
/// WGSL `sin`.
#[inline]
pub fn sin(x: f32) -> f32 {
    libm::sinf(x)
}
/// WGSL `degrees`.
#[inline]
pub fn degrees(rad: f32) -> f32 {
    rad * (180.0 / core::f32::consts::PI)
}
/// WGSL `saturate`.
#[inline]
pub fn saturate(x: f32) -> f32 {
    clamp(x, 0.0, 1.0)
}

/// WGSL definitions of the helpers above that are not WGSL built-ins. A
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

/// Emits a block of items as Rust and collects their tokens as WGSL text in a
/// `pub const WGSL: &str` beside them. Accepts `pub const`, `pub fn` and
/// `pub struct` items with doc comments (see the module docs for the rules).
#[macro_export]
#[doc(hidden)]
macro_rules! shared {
    (@acc [$($w:expr),*]) => {
        /// This module's shared items as WGSL source (raw `stringify!` text;
        /// `slc_core::wgsl::translate` formats it).
        pub const WGSL: &str = concat!($($w, "\n"),*);
    };
    (@acc [$($w:expr),*]
        $(#[$m:meta])* pub const $name:ident : $ty:ty = $val:expr ; $($rest:tt)*) => {
        // WGSL has no `core::f32::consts`: constants are written as literals.
        $(#[$m])*
        #[allow(clippy::approx_constant, clippy::excessive_precision)]
        pub const $name: $ty = $val;
        $crate::shared!(@acc [$($w,)* stringify!(const $name: $ty = $val;)] $($rest)*);
    };
    (@acc [$($w:expr),*]
        $(#[$m:meta])* pub fn $name:ident ( $($arg:ident : $aty:ty),* $(,)? ) -> $ret:ty $body:block
        $($rest:tt)*) => {
        $(#[$m])*
        #[inline]
        #[allow(clippy::needless_return, unused_mut, clippy::collapsible_else_if, clippy::assign_op_pattern, clippy::manual_range_contains)]
        pub fn $name($($arg: $aty),*) -> $ret $body
        $crate::shared!(@acc [$($w,)* stringify!(fn $name($($arg: $aty),*) -> $ret $body)] $($rest)*);
    };
    (@acc [$($w:expr),*]
        $(#[$m:meta])* pub struct $name:ident { $($(#[$fm:meta])* pub $f:ident : $fty:ty),* $(,)? }
        $($rest:tt)*) => {
        $(#[$m])*
        #[repr(C)]
        #[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
        pub struct $name { $($(#[$fm])* pub $f: $fty),* }
        $crate::shared!(@acc [$($w,)* stringify!(struct $name { $($f: $fty),* })] $($rest)*);
    };
    ($($items:tt)*) => { $crate::shared!(@acc [] $($items)*); };
}

/// Every module's shared items, in dependency order, as raw text.
const PARTS: [&str; 11] = [
    crate::xi::WGSL,
    crate::range::WGSL,
    crate::sphere::WGSL,
    crate::light::WGSL,
    crate::ies::WGSL,
    crate::bsh::WGSL,
    crate::reservoir::WGSL,
    crate::ray::WGSL,
    crate::mis::WGSL,
    crate::denoise::WGSL,
    crate::path::WGSL,
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
