//! Direct light from many lights at arbitrary shading points, the way the
//! GPU's `bsh_reservoir` kernel computes it, so an engine can shade its own
//! G-buffer with either backend and get the same numbers: the lights' BSH
//! refitted to this frame's random ranges, traversal into a k-slot
//! reservoir, then each pick sampled (a point on a triangle), RR-tested at
//! that point with the light's own range, weighted by `1/p` and the
//! reservoir's `n/k` (talk: "Improving tree traversal & shading").
//! Unshadowed: the caller owns visibility.
//!
//! Every random number is the shared hash of the kernel (`pcg_hash`,
//! `xi_for`), so for the same seed and frame the CPU and the GPU pick the
//! same lights and sample the same points.

use glam::Vec3;
use rayon::prelude::*;
use slc_core::bsh::Bsh;
use slc_core::light::{Light, connection_cosine, connection_factor};
use slc_core::range::{RangeParams, random_range2};
use slc_core::reservoir::Reservoir;
use slc_core::xi::{pcg_hash, pick_stream, point_stream, xi_for, xi_from_bits};
use slc_scene::RenderError;
use slc_scene::lights::{DIRECT_K, Direct, LightSet};

/// A light set ready to shade points on the CPU: the set's lights and a
/// BSH of its own that each call refits to its frame's ranges.
pub struct DirectLights {
    lights: Vec<Light>,
    bsh: Bsh,
}

impl DirectLights {
    /// Copies the lights and the BSH of `set`.
    pub fn new(set: &LightSet) -> DirectLights {
        DirectLights { lights: set.lights().to_vec(), bsh: set.bsh().clone() }
    }

    /// Shades `points` with unit `normals` for frame `frame` of `seed`:
    /// ranges from `xi_for(seed, frame, light)`, the BSH refitted to them,
    /// then [`Direct`] per point (zero for a point with a NaN coordinate).
    pub fn shade(
        &mut self,
        points: &[Vec3],
        normals: &[Vec3],
        params: &RangeParams,
        seed: u32,
        frame: u32,
    ) -> Result<Vec<Direct>, RenderError> {
        if points.len() != normals.len() {
            return Err(RenderError::Setting(format!(
                "{} points but {} normals",
                points.len(),
                normals.len()
            )));
        }
        let rt2: Vec<f32> = self.lights.iter().map(|l| params.threshold_range2(l.peak())).collect();
        let r2: Vec<f32> = rt2
            .iter()
            .enumerate()
            .map(|(i, &t)| random_range2(t, xi_for(seed, frame, i as u32)))
            .collect();
        self.bsh.refit(&r2).map_err(|e| RenderError::Setting(e.to_string()))?;
        let this = &*self;
        Ok((0..points.len())
            .into_par_iter()
            .map(|i| {
                this.shade_point(
                    points[i],
                    normals[i],
                    &rt2,
                    &r2,
                    point_stream(seed, i as u32, frame),
                )
            })
            .collect())
    }

    /// One point, with the kernel's random-number stream `seed`.
    fn shade_point(&self, x: Vec3, n: Vec3, rt2: &[f32], r2: &[f32], seed: u32) -> Direct {
        let mut res = Reservoir::<DIRECT_K>::new();
        let mut h = seed;
        self.bsh.for_each_containing(x, |l| {
            h = pcg_hash(h);
            let hi = h;
            h = pcg_hash(h);
            res.push(l, hi, h);
        });
        let w_res = res.weight();
        let mut h = pick_stream(seed);
        let mut e = Vec3::ZERO;
        for &li in res.picks() {
            h = pcg_hash(h);
            let u1 = xi_from_bits(h);
            h = pcg_hash(h);
            let u2 = xi_from_bits(h);
            let l = &self.lights[li as usize];
            let y = match l {
                Light::Triangle(t) => t.sample(u1, u2),
                _ => l.bound().center,
            };
            // Unshadowed, and the shading normal is the surface's (as the
            // GPU kernel passes it).
            let cos_x = connection_cosine(x, y, n, n, r2[li as usize]);
            if cos_x <= 0.0 {
                continue;
            }
            let v = x - y;
            let d2 = v.dot(v);
            e += l.intensity(v / d2.sqrt()) * connection_factor(cos_x, d2, rt2[li as usize], w_res);
        }
        Direct { irradiance: e, in_range: res.seen() }
    }
}
