//! # slc-cpu
//!
//! The CPU backend of slc (rayon): the paper's applications on the CPU.
//!
//! - [`vpl`]: real-time indirect illumination with VPLs (reflective shadow
//!   map, 8×8 interleaved sampling, tiled stochastic light culling,
//!   cross-bilateral denoise), with the clamped-range and unculled baselines
//!   and the all-VPL reference.
//! - [`scene`], [`geometry`], [`gbuffer`], [`image`]: scenes (OBJ+MTL or the
//!   built-in Cornell box), BVH ray casting, G-buffer, EXR/PNG output.
//!
//! - [`pt`]: progressive path tracing with many triangle, point, spot and
//!   IES lights: SLC over the BSH (all candidates or a k-slot reservoir),
//!   MIS whose light pdf includes the RR probability, and the uniform,
//!   power and light-BVH baselines on the same renderer.
//! - [`mod@reference`]: cached references for both applications.
//! - [`direct`]: unshadowed direct light at arbitrary shading points through
//!   the BSH and a k-slot reservoir, number for number as the GPU kernel.
//!
//! ```
//! use slc_cpu::scene::Scene;
//! use slc_cpu::vpl::{VplContext, VplMethod, VplSettings};
//!
//! let ctx = VplContext::new(&Scene::cornell_box(), 64, 64, 32, None).unwrap();
//! let frame = ctx.render(&VplSettings { method: VplMethod::Slc, ..Default::default() }).unwrap();
//! assert!(frame.image.is_finite() && frame.image.mean() > 0.0);
//! ```
#![deny(missing_docs)]
// `!(x > 0.0)` is how the validators reject NaN along with the bad range.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod direct;
pub mod gbuffer;
pub mod geometry;
pub mod image;
pub mod pt;
pub mod reference;
pub mod scene;
pub mod scene_file;
pub mod vpl;

use thiserror::Error;

/// A scene that cannot be loaded or used.
#[derive(Debug, Error, PartialEq)]
pub enum SceneError {
    /// The file could not be read.
    #[error("cannot read {0}: {1}")]
    Io(String, String),
    /// The OBJ/MTL could not be parsed.
    #[error("invalid OBJ/MTL {0}: {1}")]
    Obj(String, String),
    /// No triangles.
    #[error("the scene has no triangles")]
    Empty,
    /// A vertex with NaN or ±∞.
    #[error("triangle {0} has a non-finite vertex")]
    NonFiniteVertex(usize),
    /// Another invalid value.
    #[error("invalid scene: {0}")]
    Invalid(String),
    /// A scene file that does not parse or holds a bad value.
    #[error("scene file {0}: {1}")]
    File(String, String),
}

/// Invalid render settings.
#[derive(Debug, Error, PartialEq)]
pub enum RenderError {
    /// Scene problem.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// Image size out of range.
    #[error("image size {0}x{1} must be within 1..=16384 on each side")]
    Size(u32, u32),
    /// VPL count that is not the square of a multiple of 8.
    #[error("{0} VPLs: the count must be s*s for s a multiple of 8 up to 4096 (e.g. 4096, 16384, 65536, 262144)")]
    VplCount(u64),
    /// Another bad setting.
    #[error("invalid setting: {0}")]
    Setting(String),
}

/// An image that could not be written or read.
#[derive(Debug, Error, PartialEq)]
#[error("cannot write or read image {0}: {1}")]
pub struct OutputError(pub String, pub String);
