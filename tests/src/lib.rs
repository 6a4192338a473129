//! # slc-tests
//!
//! Cross-backend integration tests of slc. **Status: filled by the slc-wgpu
//! issue**; it holds no test yet. It will hold: CPU/GPU parity under
//! proptest (keep/cull decisions equal except within a stated float
//! tolerance of `|d² − r²|`, radiance within a stated relative tolerance),
//! end-to-end image agreement of both applications on both backends, the GPU
//! estimator's expectation against the unculled sum, and the hard numerical
//! cases on the GPU. GPU tests skip with a one-line reason without an
//! adapter, and fail instead when `SLC_REQUIRE_GPU=1` (as in CI).
//!
//! The property the parity tests check on both backends, shown on the CPU:
//! a light at `d² = 1.5` with `r_t² = 1` survives for `ξ = 0.5` (`r² = 2`).
//!
//! ```
//! use slc_core::range::{random_range2, slc_keep};
//! assert!(slc_keep(random_range2(1.0, 0.5), 1.5));
//! ```
#![deny(missing_docs)]
