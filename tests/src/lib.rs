//! # slc-tests
//!
//! Cross-backend tests of slc: the GPU (wgpu, kernels from
//! slc-shared-shaders) against the CPU (rayon), on the same inputs with the
//! same ξ. GPU tests declare their need for an adapter through [`gpu`]:
//! without one they skip with a one-line reason, unless `SLC_REQUIRE_GPU=1`
//! (as in CI, which runs them on Mesa's lavapipe), where they fail.
//!
//! ```
//! // The property the parity tests check on both backends, shown on the CPU:
//! // a light at d² = 1.5 with r_t² = 1 survives for ξ = 0.5 (r² = 2).
//! use slc_core::range::{random_range2, slc_keep};
//! assert!(slc_keep(random_range2(1.0, 0.5), 1.5));
//! ```
#![deny(missing_docs)]

use std::sync::OnceLock;

pub mod engine;

/// The shared GPU context, or `None` (after printing why) when no adapter
/// exists and `SLC_REQUIRE_GPU` is not `1`.
///
/// # Panics
/// When no adapter exists and `SLC_REQUIRE_GPU=1`: a GPU test must not pass
/// silently in CI.
pub fn gpu() -> Option<&'static slc_wgpu::GpuContext> {
    static CTX: OnceLock<Result<slc_wgpu::GpuContext, String>> = OnceLock::new();
    let ctx = CTX.get_or_init(|| {
        let r = slc_wgpu::GpuContext::new().map_err(|e| e.to_string());
        if let Ok(c) = &r {
            eprintln!("GPU tests run on: {}", c.describe());
        }
        r
    });
    match ctx {
        Ok(c) => Some(c),
        Err(e) if std::env::var("SLC_REQUIRE_GPU").as_deref() == Ok("1") => {
            panic!("SLC_REQUIRE_GPU=1 but no GPU adapter: {e}")
        }
        Err(e) => {
            eprintln!("skipping GPU test: {e}");
            None
        }
    }
}

/// A file under `../shared/data` beside the checkout, or `None` (after
/// printing why) when it is missing outside CI.
///
/// # Panics
/// When the file is missing and `CI` is set: CI always has `../shared`.
pub fn shared_data(rel: &str) -> Option<std::path::PathBuf> {
    let p = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/data").join(rel);
    if p.exists() {
        return Some(p);
    }
    if std::env::var_os("CI").is_some() {
        panic!("test data {} is missing (CI must have ../shared beside the checkout)", p.display());
    }
    eprintln!("skipping: test data {} is missing", p.display());
    None
}
