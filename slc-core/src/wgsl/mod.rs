//! Code written once for the CPU and the GPU.
//!
//! The functions the GPU needs (range math, light intensities, the IES
//! lookup, sphere tests, the reservoir update) are written in the common
//! subset of Rust and WGSL (docs/architecture.md §4) inside [`shared!`](crate::shared) blocks. The macro
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
//! The Rust definitions of the WGSL built-ins the shared code uses (`min`,
//! `select`, `dot`, ...) have WGSL's semantics.
//!
//! Files: [`builtins`] (Rust definitions of the WGSL built-ins), `shared.rs`
//! (the [`shared!`](crate::shared) macro), [`assemble`] (the prelude, the
//! module list and the Rust → WGSL text mapping).

pub mod assemble;
pub mod builtins;
mod shared;

pub use assemble::{PRELUDE, WgslModule, library, modules, modules_wgsl, translate};
pub use builtins::*;
