//! # slc-cpu
//!
//! The CPU backend of slc (rayon). **Status: filled by the VPL and
//! path-tracing issues.** It will hold both applications of the paper on the
//! CPU: real-time indirect illumination with 65,536 VPLs (reflective shadow
//! map, 8×8 interleaved sampling, tiled culling, bilateral denoise) and
//! progressive path tracing with thousands of point/spot/IES/triangle lights
//! (bounding-sphere hierarchy, MIS), with EXR output.
//!
//! Today it offers the parallel building block both need: SLC sums at many
//! shading points at once, using slc-core's estimator.
//!
//! ```
//! use slc_core::glam::Vec3;
//! use slc_core::light::{Light, PointLight};
//! use slc_core::range::RangeParams;
//!
//! let lights = vec![Light::Point(PointLight::new(Vec3::ZERO, Vec3::ONE).unwrap())];
//! let points = vec![Vec3::new(0.0, 0.0, 1.0)];
//! let params = RangeParams::new(0.01, 1.0).unwrap();
//! let out = slc_cpu::shade_points(&lights, &[0.5], &params, &points);
//! assert!((out[0].value.x - 1.0).abs() < 1e-6);
//! ```
#![deny(missing_docs)]

use slc_core::estimator::{Estimate, Seen, slc_sum};
use slc_core::glam::Vec3;
use slc_core::light::Light;
use slc_core::range::{RangeParams, random_range2};

/// SLC estimate of `Σ I(w)/d²` at every point in `points`, one ξ per light
/// (`xi[i]` for `lights[i]`), in parallel over points.
pub fn shade_points(lights: &[Light], xi: &[f32], params: &RangeParams, points: &[Vec3]) -> Vec<Estimate> {
    let rt2: Vec<f32> = lights.iter().map(|l| params.threshold_range2(l.peak())).collect();
    let r2: Vec<f32> = rt2.iter().zip(xi).map(|(&rt2, &xi)| random_range2(rt2, xi)).collect();
    points
        .iter()
        .map(|&x| {
            slc_sum(
                0..lights.len(),
                |&i| Seen { d2: (x - lights[i].bound().center).length_squared(), rt2: rt2[i], r2: r2[i] },
                |&i| lights[i].contribution_at(x).0,
            )
        })
        .collect()
}
