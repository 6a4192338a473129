//! Direct light from many lights at arbitrary shading points, the way the
//! GPU's direct pass (slc-wgpu's `DirectPass`, its `direct_light` kernel)
//! computes it, so an engine can shade its own G-buffer with either
//! backend and get the same numbers: the lights' BSH refitted to this
//! frame's random ranges, the lights in range picked as a
//! [`DirectSelection`] says (`k` importance-weighted picks, `k` uniform
//! picks through a `k`-slot reservoir, `k` picks resampled in proportion to
//! the candidates' unshadowed contributions, or every one), each pick sampled (a
//! point on a triangle), RR-tested at that point with the light's own
//! range and weighted by `1/p` and its selection weight (talk: "Improving
//! tree traversal & shading"). Unshadowed unless given occluders
//! ([`DirectLights::set_shadows`]): then each pick casts one shadow ray, as
//! the GPU pass's `set_shadows` does.
//!
//! Every random number is the shared hash of the kernel (`pcg_hash`,
//! `xi_for`), so for the same seed and frame the CPU and the GPU pick the
//! same lights and sample the same points. (The GPU shades a light without
//! area picked `m` times once with `m` times the weight; the CPU shades
//! each pick: the same sum up to rounding.)

use crate::geometry::Geometry;
use glam::Vec3;
use rayon::prelude::*;
use slc_core::bsh::Bsh;
use slc_core::importance::{LightCone, Receiver};
use slc_core::light::{Light, connection_cosine, connection_factor};
use slc_core::range::{RangeParams, random_range2};
use slc_core::reservoir::{
    resample_target, reservoir_slot, reservoir_takes, reservoir_weight, slot_share, slot_target,
    threshold_takes, weighted_pick_weight,
};
use slc_core::xi::{pcg_hash, pick_stream, point_stream, xi_for, xi_from_bits};
use slc_scene::RenderError;
use slc_scene::lights::{DIRECT_K, Direct, DirectSelection, LightSet};
use slc_scene::occluders::Occluders;

/// Shadow rays for the CPU twin's picks, as the GPU pass's `Shadows`: what
/// they hit, and how far each leaves its surface.
#[derive(Clone, Copy, Debug)]
pub struct CpuShadows<'a> {
    /// What the rays hit, in world space.
    pub occluders: &'a Occluders,
    /// A ray's origin offset along the point's normal, as a fraction of its
    /// distance to `eye` (the GPU pass's `Shadows::normal_offset`, `10⁻³`
    /// there by default).
    pub normal_offset: f32,
    /// The eye the offset is relative to (the G-buffer's).
    pub eye: Vec3,
}

/// The occluders' world-space triangles in slc-cpu's BVH and the offset.
struct ShadowRays {
    geometry: Geometry,
    normal_offset: f32,
    eye: Vec3,
}

/// A light set ready to shade points on the CPU: the set's lights, their
/// importance bounds, a BSH of its own that each call refits to its
/// frame's ranges, and the occluders, if any.
pub struct DirectLights {
    lights: Vec<Light>,
    cones: Vec<LightCone>,
    bsh: Bsh,
    shadows: Option<ShadowRays>,
}

impl DirectLights {
    /// Copies the lights, their bounds and the BSH of `set`; unshadowed.
    pub fn new(set: &LightSet) -> DirectLights {
        DirectLights {
            lights: set.lights().to_vec(),
            cones: set.cones().to_vec(),
            bsh: set.bsh().clone(),
            shadows: None,
        }
    }

    /// Shadows every pick against `shadows`' occluders (their triangles as
    /// they are now: call again after they move), or turns shadows off
    /// (`None`). A negative or non-finite offset is an error and changes
    /// nothing.
    pub fn set_shadows(&mut self, shadows: Option<CpuShadows>) -> Result<(), RenderError> {
        let Some(s) = shadows else {
            self.shadows = None;
            return Ok(());
        };
        if !(s.normal_offset.is_finite() && s.normal_offset >= 0.0 && s.eye.is_finite()) {
            return Err(RenderError::Setting(format!(
                "shadow normal offset {} must be finite and non-negative, the eye {} finite",
                s.normal_offset, s.eye
            )));
        }
        self.shadows = Some(ShadowRays {
            geometry: Geometry::new(s.occluders.triangles()),
            normal_offset: s.normal_offset,
            eye: s.eye,
        });
        Ok(())
    }

    /// Shades `points` with unit `normals` for frame `frame` of `seed` with
    /// the reservoir's [`DIRECT_K`] uniform picks
    /// ([`DirectLights::shade_selected`]).
    pub fn shade(
        &mut self,
        points: &[Vec3],
        normals: &[Vec3],
        params: &RangeParams,
        seed: u32,
        frame: u32,
    ) -> Result<Vec<Direct>, RenderError> {
        let uniform = DirectSelection::Uniform { k: DIRECT_K as u32 };
        self.shade_selected(points, normals, params, seed, frame, uniform)
    }

    /// Shades `points` with unit `normals` for frame `frame` of `seed`:
    /// ranges from `xi_for(seed, frame, light)`, the BSH refitted to them,
    /// then the picks `selection` makes per point ([`Direct`]; zero for a
    /// point with a NaN coordinate or normal).
    pub fn shade_selected(
        &mut self,
        points: &[Vec3],
        normals: &[Vec3],
        params: &RangeParams,
        seed: u32,
        frame: u32,
        selection: DirectSelection,
    ) -> Result<Vec<Direct>, RenderError> {
        if points.len() != normals.len() {
            return Err(RenderError::Setting(format!(
                "{} points but {} normals",
                points.len(),
                normals.len()
            )));
        }
        if let DirectSelection::Weighted { k }
        | DirectSelection::Uniform { k }
        | DirectSelection::Resampled { k } = selection
            && !(1..=64).contains(&k)
        {
            return Err(RenderError::Setting(format!("k = {k} picks must be in 1..=64")));
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
                let at = Point { x: points[i], n: normals[i], rt2: &rt2, r2: &r2 };
                this.shade_point(&at, point_stream(seed, i as u32, frame), selection)
            })
            .collect())
    }

    /// One point, with the kernel's random-number stream `seed`.
    fn shade_point(&self, at: &Point, seed: u32, selection: DirectSelection) -> Direct {
        // The picks: (light, weight) each.
        let mut picks: Vec<(u32, f32)> = Vec::new();
        let mut seen = 0u32;
        let mut h = seed;
        match selection {
            DirectSelection::Weighted { k } => {
                // K one-slot weighted reservoirs (the kernel's
                // bsh_weighted_collect, one stream for all slots).
                let rc = Receiver::lambertian(at.x, at.n);
                let mut slots = vec![(0u32, 0.0f32); k as usize];
                let mut thresholds = vec![0.0f32; k as usize];
                let mut w_sum = 0.0f32;
                self.bsh.for_each_containing(at.x, |l| {
                    seen += 1;
                    let w = self.cones[l as usize].weight(&rc, at.rt2[l as usize]);
                    if w > 0.0 {
                        w_sum += w;
                        offer(&mut slots, &mut thresholds, |_| (l, w), |_| (w, w_sum), &mut h);
                    }
                });
                if w_sum > 0.0 {
                    picks = slots
                        .iter()
                        .map(|&(l, w)| (l, weighted_pick_weight(w_sum, w, k)))
                        .collect();
                }
            }
            DirectSelection::Uniform { k } => {
                // Algorithm R (the kernel's bsh_collect).
                let mut slots = vec![0u32; k as usize];
                self.bsh.for_each_containing(at.x, |l| {
                    if reservoir_takes(seen) {
                        seen += 1;
                        h = pcg_hash(h);
                        let hi = h;
                        h = pcg_hash(h);
                        let s = reservoir_slot(seen, k, hi, h);
                        if s < k {
                            slots[s as usize] = l;
                        }
                    }
                });
                let w = reservoir_weight(seen, k);
                picks = slots[..(seen.min(k)) as usize].iter().map(|&l| (l, w)).collect();
            }
            DirectSelection::All => {
                self.bsh.for_each_containing(at.x, |l| {
                    seen += 1;
                    picks.push((l, 1.0));
                });
            }
            DirectSelection::Resampled { k } => return self.resampled(at, seed, k),
        }
        let mut h = pick_stream(seed);
        let mut e = Vec3::ZERO;
        for &(li, w) in &picks {
            h = pcg_hash(h);
            let u1 = xi_from_bits(h);
            h = pcg_hash(h);
            e += self.connect(at, li as usize, w, u1, xi_from_bits(h), true);
        }
        Direct { irradiance: e, in_range: seen }
    }

    /// [`DirectSelection::Resampled`] (the kernel's): every light in range
    /// sampled (its point from the pick stream) and evaluated unshadowed,
    /// `k` one-slot weighted reservoirs (the seed's stream), slot `q` over
    /// its [`slot_target`]s, each kept candidate shadowed and weighted
    /// `P_q/p_q` times its [`slot_share`], `P_q` the slot's target sum.
    fn resampled(&self, at: &Point, seed: u32, k: u32) -> Direct {
        let mut slots = vec![(0u32, 0.0f32, 0.0f32, 0.0f32); k as usize];
        let mut thresholds = vec![0.0f32; k as usize];
        let (mut total, mut seen) = (Vec3::ZERO, 0u32);
        let (mut h, mut hc) = (pick_stream(seed), seed);
        self.bsh.for_each_containing(at.x, |l| {
            seen += 1;
            h = pcg_hash(h);
            let u1 = xi_from_bits(h);
            h = pcg_hash(h);
            let u2 = xi_from_bits(h);
            let c = self.connect(at, l as usize, 1.0, u1, u2, false);
            if resample_target(c) > 0.0 {
                total += c;
                let of = |q: usize, v: Vec3| slot_target(v, q as u32, k);
                let item = |q| (l, u1, u2, of(q, c));
                offer(&mut slots, &mut thresholds, item, |q| (of(q, c), of(q, total)), &mut hc);
            }
        });
        let mut e = Vec3::ZERO;
        for (q, &(l, u1, u2, p)) in slots.iter().enumerate() {
            if p > 0.0 {
                let w = slot_target(total, q as u32, k) / p;
                e += self.connect(at, l as usize, 1.0, u1, u2, true) * w * slot_share(q as u32, k);
            }
        }
        Direct { irradiance: e, in_range: seen }
    }

    /// Pick `li` of weight `w` sampled at `(u1, u2)` (the kernel's
    /// `connect_traced`): the RR test at the sampled point, with `trace`
    /// the shadow ray (along the point's normal, which the kernel takes as
    /// the geometric one), `1/p` and `w`.
    fn connect(&self, at: &Point, li: usize, w: f32, u1: f32, u2: f32, trace: bool) -> Vec3 {
        let (x, n) = (at.x, at.n);
        let l = &self.lights[li];
        let y = match l {
            Light::Triangle(t) => t.sample(u1, u2),
            _ => l.bound().center,
        };
        let cos_x = connection_cosine(x, y, n, n, at.r2[li]);
        if cos_x <= 0.0 {
            return Vec3::ZERO;
        }
        if let Some(s) = self.shadows.as_ref().filter(|_| trace) {
            let eps = s.normal_offset * (s.eye - x).length();
            if s.geometry.occluded(x + n * eps, y) {
                return Vec3::ZERO;
            }
        }
        let v = x - y;
        let d2 = v.dot(v);
        l.intensity(v / d2.sqrt()) * connection_factor(cos_x, d2, at.rt2[li], w)
    }
}

/// Offers a candidate to one-slot weighted reservoirs `slots` (the
/// kernels' loops in `bsh_weighted_collect` and the resampled picks): slot
/// `q`, whose candidates so far weigh `total` including this one's `w`
/// (`weights(q) = (w, total)`), takes `item(q)` with probability `w/total`
/// where `w > 0`, in the threshold form ([`threshold_takes`]): where
/// `total` passes the slot's threshold, one hash of `h` sets the next.
fn offer<T>(
    slots: &mut [T],
    thresholds: &mut [f32],
    item: impl Fn(usize) -> T,
    weights: impl Fn(usize) -> (f32, f32),
    h: &mut u32,
) {
    for (q, (s, threshold)) in slots.iter_mut().zip(thresholds.iter_mut()).enumerate() {
        let (w, total) = weights(q);
        if w > 0.0
            && threshold_takes(total, threshold, || {
                *h = pcg_hash(*h);
                xi_from_bits(*h)
            })
        {
            *s = item(q);
        }
    }
}

/// A shading point and the frame's ranges.
struct Point<'a> {
    x: Vec3,
    n: Vec3,
    rt2: &'a [f32],
    r2: &'a [f32],
}
