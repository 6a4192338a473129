//! # slc-wgpu
//!
//! The GPU backend of slc (wgpu compute). **Status: filled by the slc-wgpu
//! issue.** It will hold adapter/device setup that works on real GPUs and on
//! the software Vulkan driver, both applications of the paper on the GPU with
//! kernels from `slc-shared-shaders` only, and GPU timestamps for the bench.
//!
//! ```
//! assert_eq!(slc_wgpu::STATUS, "planned");
//! ```
#![deny(missing_docs)]

/// Implementation status of this backend.
pub const STATUS: &str = "planned";
