//! # slc-tests
//!
//! Cross-backend integration tests (CPU/GPU parity under proptest,
//! unbiasedness of the GPU estimator, hard cases on both backends). **Status:
//! filled by the slc-wgpu issue.** Today its tests check that the CPU
//! backend's SLC sums are unbiased against the unculled sum.
#![deny(missing_docs)]
