//! Deterministic random placement on a scene: the random stream of one
//! placed item, and points drawn uniformly by area on the scene's
//! non-emissive surfaces. Used by the scene file's `[[scatter_lights]]` and
//! `[[light_cloud]]`, so a seed places the same lights on every machine.

use crate::scene::Scene;
use glam::Vec3;
use slc_core::xi::{pcg_hash, xi_from_bits};

/// The random numbers of item `index` placed with `seed`:
/// `h(h(h(seed ⊕ h(index))))…`, `h` = [`pcg_hash`], each mapped to
/// `[0, 1)` by [`xi_from_bits`].
pub struct Stream(u32);

impl Stream {
    /// The stream of item `index` for `seed`.
    pub fn new(seed: u32, index: u32) -> Self {
        Stream(pcg_hash(seed ^ pcg_hash(index)))
    }

    /// The next number in `[0, 1)`.
    pub fn uniform(&mut self) -> f32 {
        self.0 = pcg_hash(self.0);
        xi_from_bits(self.0)
    }

    /// A standard normal deviate (Box–Muller on two of the stream's numbers).
    pub fn normal(&mut self) -> f32 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * (1.0 - u).ln()).sqrt() * (std::f32::consts::TAU * v).cos()
    }

    /// A direction uniform on the unit sphere.
    pub fn direction(&mut self) -> Vec3 {
        let (u, v) = (self.uniform(), self.uniform());
        let z = 1.0 - 2.0 * u;
        let r = (1.0 - z * z).max(0.0).sqrt();
        let phi = std::f32::consts::TAU * v;
        Vec3::new(r * phi.cos(), r * phi.sin(), z)
    }
}

/// The non-emissive triangles of a scene with their cumulative areas: a
/// point drawn from it is uniform by area over those surfaces.
pub struct Surfaces<'a> {
    scene: &'a Scene,
    triangles: Vec<usize>,
    cdf: Vec<f64>,
}

impl<'a> Surfaces<'a> {
    /// The non-emissive surfaces of `scene`; an error when they have no area.
    pub fn new(scene: &'a Scene) -> Result<Self, String> {
        let triangles: Vec<usize> = (0..scene.triangles.len())
            .filter(|&t| scene.materials[scene.material_of[t] as usize].emission == Vec3::ZERO)
            .collect();
        let area = |t: &[Vec3; 3]| 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).length();
        let mut cdf = Vec::with_capacity(triangles.len());
        let mut total = 0.0f64;
        for &t in &triangles {
            total += area(&scene.triangles[t]) as f64;
            cdf.push(total);
        }
        if !(total > 0.0) {
            return Err("no non-emissive surface of positive area to place lights over (list [[geometry]] first)".into());
        }
        Ok(Surfaces { scene, triangles, cdf })
    }

    /// A point uniform by area and its triangle's front normal (its
    /// winding's), from three numbers of `s`.
    pub fn sample(&self, s: &mut Stream) -> (Vec3, Vec3) {
        let total = self.cdf.last().copied().unwrap_or(0.0);
        let (pick, u, v) = (s.uniform() as f64 * total, s.uniform(), s.uniform());
        let i = self.cdf.partition_point(|&c| c <= pick).min(self.triangles.len() - 1);
        let [a, b, c] = self.scene.triangles[self.triangles[i]];
        let su = u.sqrt();
        let p = a * (1.0 - su) + b * (su * (1.0 - v)) + c * (su * v);
        (p, (b - a).cross(c - a).normalize_or_zero())
    }
}
