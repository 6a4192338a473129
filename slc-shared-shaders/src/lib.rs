//! # slc-shared-shaders
//!
//! The single place where slc's GPU code is assembled. **Status: this crate
//! is filled by the slc-shared-shaders issue**; today it re-exports the
//! shared WGSL library of slc-core so engines can already include the range
//! math, light intensities, IES lookup, sphere tests and reservoir update in
//! their own WGSL.
//!
//! It will hold: WGSL kernel templates (per-frame light update and BSH refit,
//! tiled culling per 8×8 interleaved sub-image, VPL shading, BSH traversal
//! into a k-slot reservoir, path-tracing light connection with MIS), a
//! generator that specialises them to a scene's light types, naga validation
//! of every variant, snapshot tests, and export to SPIR-V/GLSL/HLSL/MSL.
//!
//! ```
//! let wgsl = slc_shared_shaders::core_library();
//! assert!(wgsl.contains("fn rr_probability"));
//! ```
#![deny(missing_docs)]

/// slc-core's shared functions as one WGSL source text (see
/// [`slc_core::wgsl::library`] for what a module including it must declare).
pub fn core_library() -> String {
    slc_core::wgsl::library()
}
