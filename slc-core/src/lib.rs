//! # slc-core
//!
//! The math of *stochastic light culling* (Tokuyoshi & Harada, "Stochastic
//! Light Culling", JCGT 5(1), 2016), written once: `#![no_std]` + `alloc`,
//! glam with `libm`, `rand_core`. Both slc backends (rayon CPU, wgpu GPU) and
//! engines that embed slc call this crate; the GPU gets the very same
//! functions as WGSL text ([`wgsl::library`]).
//!
//! | module | holds |
//! |---|---|
//! | [`range`] | RR probability `min(r_t²/d², 1)`, error-bound threshold range, random range `r_t²/(1−ξ)`, keep test, `1/p` weight |
//! | [`xi`] | one ξ per light per frame/pass, from a `rand_core::RngCore` or a hash |
//! | [`light`] | point, VPL, spot, IES and triangle lights: peak intensity, intensity toward a direction, range-sphere bound |
//! | [`ies`] | LM-63 parser and bilinear candela lookup with all horizontal symmetries |
//! | [`sphere`] | minimal spheres (triangle, point set), sphere union, sphere–point/sphere/AABB tests |
//! | [`bsh`] | bounding-sphere hierarchy: build, O(n) refit, stackless `child`/`next` traversal |
//! | [`importance`] | pbrt-v4's importance of a bounded set of lights at a point; `slc-weighted`'s candidate weight and selection pdf |
//! | [`light_bvh`] | the light BVH's descent steps, sample and pmf (the `lightbvh` baseline) |
//! | [`reservoir`] | k-slot Algorithm R and a weighted variant |
//! | [`estimator`] | SLC, clamped-range and unculled sums at one shading point |
//! | [`brdf`] | glTF 2.0 metallic-roughness BRDF (Lambert + GGX, height-correlated Smith, Schlick), bounded-VNDF sampling, lobe choice and pdf |
//! | [`mis`] | balance and power heuristics, cosine pdf and cosine-weighted directions (light pdfs include `p_rr`) |
//! | [`ray`] | ray–box and ray–triangle tests for the GPU's geometry BVH |
//! | [`path`] | the camera ray and Russian roulette on path length of both path tracers |
//! | [`interleave`] | the VPL frame's interleaved sampling (subsets, slots, the per-frame shift) and the near-field split |
//! | [`cluster`] | clusters of 64 lights and groups of clusters: the two-level box hierarchy both backends cull VPLs with |
//! | [`frame`] | the VPL frame's direct light and composition |
//! | [`denoise`] | the cross-bilateral filter weight of the VPL denoise |
//! | [`temporal`] | temporal accumulation: reprojection, history matching, change response from luminance moments, the moving average's weight |
//! | [`wgsl`] | the shared-code macro, WGSL built-ins in Rust, the assembled WGSL library |
//!
//! ```
//! use slc_core::range::{RangeParams, random_range2, slc_keep, slc_weight};
//! use glam::Vec3;
//!
//! // A light of peak intensity 10 W/sr, error bound 0.01, exposure 1.
//! let params = RangeParams::new(0.01, 1.0).unwrap();
//! let rt2 = params.threshold_range2(Vec3::splat(10.0));
//! // Its random range for ξ = 0.75 is twice as far as r_t (r² = 4 r_t²).
//! let r2 = random_range2(rt2, 0.75);
//! assert!((r2 / rt2 - 4.0).abs() < 1e-6);
//! // A point at d² = 2 r_t² is kept and weighted by 1/p = d²/r_t² = 2.
//! let d2 = 2.0 * rt2;
//! assert!(slc_keep(r2, d2));
//! assert!((slc_weight(rt2, d2) - 2.0).abs() < 1e-6);
//! ```
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
// `!(x > 0.0)` is how the validators reject NaN along with the bad range.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

extern crate alloc;

#[macro_use]
pub mod wgsl;

pub mod brdf;
pub mod bsh;
pub mod cluster;
pub mod denoise;
pub mod estimator;
pub mod frame;
pub mod ies;
pub mod importance;
pub mod interleave;
pub mod light;
pub mod light_bvh;
pub mod mis;
pub mod path;
pub mod range;
pub mod ray;
pub mod reservoir;
pub mod sphere;
pub mod temporal;
pub mod xi;

pub use glam;

use thiserror::Error;

/// Invalid range settings or random numbers.
#[derive(Clone, Copy, Debug, PartialEq, Error)]
pub enum RangeError {
    /// ε must be finite and `> 0`.
    #[error("error bound must be finite and > 0, got {0}")]
    ErrorBound(f32),
    /// E must be finite and `> 0`.
    #[error("exposure must be finite and > 0, got {0}")]
    Exposure(f32),
    /// α must be finite and `> 0`.
    #[error("alpha must be finite and > 0, got {0}")]
    Alpha(f32),
    /// ξ must lie in `[0, 1)`.
    #[error("xi must lie in [0, 1), got {0}")]
    Xi(f32),
}

/// Invalid light parameters.
#[derive(Clone, Copy, Debug, PartialEq, Error)]
pub enum LightError {
    /// NaN or ±∞ in a field.
    #[error("light {field} is not finite")]
    NonFinite {
        /// The field.
        field: &'static str,
    },
    /// A negative intensity, flux or radiance channel.
    #[error("light {field} has a negative channel")]
    Negative {
        /// The field.
        field: &'static str,
    },
    /// A direction of zero length.
    #[error("light {field} has zero length")]
    ZeroDirection {
        /// The field.
        field: &'static str,
    },
    /// Spot cone half-angles outside `0 ≤ inner ≤ outer ≤ π`.
    #[error(
        "spot cone angles must satisfy 0 <= inner <= outer <= pi, got inner {inner}, outer {outer}"
    )]
    ConeAngles {
        /// Inner half-angle (radians).
        inner: f32,
        /// Outer half-angle (radians).
        outer: f32,
    },
    /// A triangle emitter with zero area (repeated or collinear vertices).
    #[error("triangle light has zero area (repeated or collinear vertices)")]
    DegenerateTriangle,
    /// A peak intensity above [`light::MAX_INTENSITY`]: the light's terms
    /// could overflow `f32` in a pixel.
    #[error(
        "light {field} gives a peak intensity of {peak:e}, above the largest slc shades without overflow ({max:e})"
    )]
    TooBright {
        /// The field (or product of fields) that sets the peak.
        field: &'static str,
        /// The peak intensity's largest channel.
        peak: f32,
        /// [`light::MAX_INTENSITY`].
        max: f32,
    },
    /// An IES profile that is not type C.
    #[error("IES photometric type {0:?} is not supported for lights (type C only)")]
    UnsupportedPhotometry(ies::PhotometricType),
}

/// Invalid input to the bounding-sphere hierarchy.
#[derive(Clone, Copy, Debug, PartialEq, Error)]
pub enum BshError {
    /// Light `i` has a NaN or infinite centre.
    #[error("light {0} has a non-finite centre")]
    NonFiniteCenter(usize),
    /// Light `i` has a negative or non-finite extent.
    #[error("light {0} has an invalid extent {1} (must be finite and >= 0)")]
    BadExtent(usize, f32),
    /// Light `i` has a negative or NaN squared range.
    #[error("light {0} has an invalid squared range {1} (must be >= 0 or +inf)")]
    BadRange(usize, f32),
    /// Refit with the wrong number of ranges.
    #[error("refit needs {expected} ranges, got {got}")]
    RangeCount {
        /// Lights in the tree.
        expected: usize,
        /// Ranges given.
        got: usize,
    },
    /// More lights than 32-bit links can address.
    #[error("{0} lights exceed the hierarchy's 32-bit index space")]
    TooManyLights(usize),
    /// A range tail longer than [`crate::bsh::BSH_TAIL_MAX`].
    #[error("a range tail of {0} lights exceeds the most the walk tests flat ({max})", max = crate::bsh::BSH_TAIL_MAX)]
    TailTooLong(usize),
    /// A tree width outside 2..=[`crate::bsh::BSH_MAX_WIDTH`].
    #[error("a tree {0} children wide is outside 2..={max}", max = crate::bsh::BSH_MAX_WIDTH)]
    BadWidth(u32),
}

/// An LM-63 parse error with the (1-based) line it was found on.
#[derive(Clone, Debug, PartialEq, Error)]
#[error("IES line {line}: {kind}")]
pub struct IesError {
    /// 1-based line number.
    pub line: usize,
    /// What went wrong.
    pub kind: IesErrorKind,
}

/// What went wrong while parsing an LM-63 file.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum IesErrorKind {
    /// No `TILT=` line.
    #[error("no TILT= line")]
    MissingTilt,
    /// The file ended early.
    #[error("file ends before the {expected}")]
    UnexpectedEnd {
        /// What was expected.
        expected: &'static str,
    },
    /// A token that is not a finite number.
    #[error("{field}: '{token}' is not a finite number")]
    BadNumber {
        /// The field.
        field: &'static str,
        /// The token.
        token: alloc::string::String,
    },
    /// A number outside its allowed range.
    #[error("{field}: {value} is out of range")]
    OutOfRange {
        /// The field.
        field: &'static str,
        /// The value.
        value: f32,
    },
    /// Angles not strictly increasing.
    #[error("{field} are not strictly increasing")]
    NotIncreasing {
        /// The field.
        field: &'static str,
    },
    /// A type C horizontal range that matches no LM-63 symmetry.
    #[error(
        "type C horizontal angles {first}..{last} match no LM-63 symmetry (0, 0-90, 0-180, 90-270, 0-360)"
    )]
    HorizontalRange {
        /// First angle.
        first: f32,
        /// Last angle.
        last: f32,
    },
    /// More candela values than [`ies::MAX_VALUES`].
    #[error("{values} candela values exceed the limit")]
    TooLarge {
        /// Values requested.
        values: usize,
    },
}
