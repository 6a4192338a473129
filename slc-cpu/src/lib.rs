//! # slc-cpu
//!
//! The CPU backend of slc (rayon): the paper's applications on the CPU,
//! over the scene and settings of [`slc_scene`], implementing its
//! [`slc_scene::backend`] contract.
//!
//! - [`vpl`]: real-time indirect illumination with VPLs (reflective shadow
//!   map, 8×8 interleaved sampling, tiled stochastic light culling,
//!   cross-bilateral denoise), with the clamped-range and unculled baselines
//!   and the all-VPL reference ([`vpl::VplContext`]).
//! - [`geometry`], [`gbuffer`]: BVH ray casting (obvhs) and the G-buffer.
//! - [`pt`]: progressive path tracing with many triangle, point, spot and
//!   IES lights: SLC over the BSH (all candidates or a k-slot reservoir),
//!   MIS whose light pdf includes the RR probability, and the uniform,
//!   power and light-BVH baselines on the same renderer;
//!   [`pt::CpuPathTracer`] is a [`slc_scene::backend::PathTracer`].
//! - [`temporal`]: temporal accumulation of a per-pixel signal (reprojection,
//!   disocclusion, change response, moving average), the VPL frame's
//!   [`vpl::VplContext::render_accumulated`].
//! - [`direct`]: unshadowed direct light at arbitrary shading points through
//!   the BSH and a k-slot reservoir, number for number as the GPU kernel.
//!
//! ```
//! use slc_cpu::vpl::VplContext;
//! use slc_scene::scene::Scene;
//! use slc_scene::vpl::{Culling, VplSettings};
//!
//! let ctx = VplContext::new(&Scene::cornell_box(), 64, 64, 32, None).unwrap();
//! let culling = Culling::stochastic(0.004, 1.0).unwrap();
//! let frame = ctx.render(&VplSettings { culling, ..Default::default() }).unwrap();
//! assert!(frame.image.is_finite() && frame.image.mean() > 0.0);
//! ```
#![forbid(unsafe_code)]
#![deny(missing_docs)]
// `!(x > 0.0)` is how the validators reject NaN along with the bad range.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod direct;
pub mod gbuffer;
pub mod geometry;
pub mod pt;
pub mod raster;
pub mod simd;
pub mod temporal;
pub mod vpl;
