//! Light sets: the lights, their range bounds, the BSH over them and the
//! `power` baseline's alias table, built once and read by both backends.

use crate::RenderError;
use crate::alias::AliasTable;
use crate::scene::Scene;
use glam::Vec3;
use slc_core::bsh::Bsh;
use slc_core::importance::LightCone;
use slc_core::light::{Light, LightBound, TriangleLight, emitted_powers};

/// Reservoir slots of the direct-light shader (the GPU kernel's `k`).
pub const DIRECT_K: usize = 8;

/// How direct light picks among the lights in range at a point (the GPU's
/// direct pass and the CPU's twin, `slc_cpu::direct::DirectLights`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DirectSelection {
    /// `k` importance-weighted picks (`slc-weighted`), `k` in `1..=64`.
    Weighted {
        /// Picks per point.
        k: u32,
    },
    /// `k` uniform picks (a `k`-slot reservoir), `k` in `1..=64`.
    Uniform {
        /// Picks per point.
        k: u32,
    },
    /// `k` picks resampled from every light in range in proportion to its
    /// exact unshadowed contribution (resampled importance sampling: each
    /// candidate is sampled and evaluated without a shadow ray, the `k`
    /// picks are drawn from them, and only they cast one), `k` in
    /// `1..=64`. The `k` rays go only where light arrives unshadowed. With
    /// `k ≥ 3` each pick is drawn for one colour channel (pick `j` for
    /// channel `j mod 3`, slc-core's `slot_target`) and estimates that
    /// channel, so coloured lights add no colour noise.
    Resampled {
        /// Picks per point.
        k: u32,
    },
    /// Every light in range (exact given ξ).
    All,
}

/// Direct light at one point: irradiance-weighted intensity sum and the
/// number of lights in range (what both backends' direct-light shading
/// returns).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Direct {
    /// `Σ I(w) cos θ_x / d² · 1/p · n/k` over the picks (RGB).
    pub irradiance: Vec3,
    /// Lights whose range sphere contains the point.
    pub in_range: u32,
}

/// Lights with their bounds, BSH (as built, on first use; backends refit
/// their own copy per frame) and power distribution.
#[derive(Clone, Debug)]
pub struct LightSet {
    lights: Vec<Light>,
    bounds: Vec<LightBound>,
    /// The balanced BSH the direct pass refits, built on the first
    /// [`LightSet::bsh`] (the path tracers build their own wide one).
    bsh: std::sync::OnceLock<Bsh>,
    /// Emitted power per light ([`Light::power`]).
    power: Vec<Vec3>,
    alias: AliasTable,
    /// Each light's importance bounds (`slc-weighted`, the light BVH).
    cones: Vec<LightCone>,
}

impl LightSet {
    /// The power table over `lights` (at least one), their bounds checked
    /// for the BSH ([`Bsh::check`]; the tree itself is built on the first
    /// [`LightSet::bsh`]).
    pub fn new(lights: Vec<Light>) -> Result<LightSet, RenderError> {
        if lights.is_empty() {
            return Err(RenderError::Setting("no lights to shade with".into()));
        }
        let bounds: Vec<LightBound> = lights.iter().map(Light::bound).collect();
        Bsh::check(&bounds).map_err(|e| RenderError::Setting(e.to_string()))?;
        let bsh = std::sync::OnceLock::new();
        let power = emitted_powers(&lights);
        let alias =
            AliasTable::new(&power.iter().map(|p| p.max_element() as f64).collect::<Vec<f64>>());
        let cones = lights.iter().zip(&power).map(|(l, &p)| LightCone::of_light(l, p)).collect();
        Ok(LightSet { lights, bounds, bsh, power, alias, cones })
    }

    /// Number of lights.
    pub fn len(&self) -> usize {
        self.lights.len()
    }

    /// Never `true`: a set holds at least one light.
    pub fn is_empty(&self) -> bool {
        self.lights.is_empty()
    }

    /// The lights, in BSH light-index order.
    pub fn lights(&self) -> &[Light] {
        &self.lights
    }

    /// Each light's bound (centre and extent `R` of its range sphere).
    pub fn bounds(&self) -> &[LightBound] {
        &self.bounds
    }

    /// The balanced BSH over the lights ([`Bsh::build`]), as built: on
    /// the first call.
    pub fn bsh(&self) -> &Bsh {
        self.bsh.get_or_init(|| {
            Bsh::build(&self.bounds).expect("LightSet::new checked the bounds (Bsh::check)")
        })
    }

    /// Each light's emitted RGB power, the quantity power sampling weighs
    /// lights by (max channel); the light BVH too, but for spot lights
    /// ([`crate::light_bvh::bvh_cone`]).
    pub fn power(&self) -> &[Vec3] {
        &self.power
    }

    /// The `power` baseline's alias table (weights: max channel of
    /// [`LightSet::power`]).
    pub fn alias(&self) -> &AliasTable {
        &self.alias
    }

    /// Each light's importance bounds ([`LightCone::of_light`] of its
    /// power), read by `slc-weighted` on both backends.
    pub fn cones(&self) -> &[LightCone] {
        &self.cones
    }

    /// The alias table per light as the GPU reads it:
    /// `(keep probability, alias index as f32 bits, pmf, 0)`.
    pub fn power_table(&self) -> Vec<[f32; 4]> {
        self.alias
            .entries()
            .map(|(p, a, pdf)| [p as f32, f32::from_bits(a as u32), pdf as f32, 0.0])
            .collect()
    }
}

/// The scene's emissive triangles as triangle lights, and each triangle's
/// light index (`u32::MAX` when it does not emit). An emissive triangle of
/// zero area is an error.
pub fn emissive_triangles(scene: &Scene) -> Result<(Vec<Light>, Vec<u32>), RenderError> {
    let mut lights = Vec::new();
    let mut light_of_triangle = vec![u32::MAX; scene.triangles.len()];
    for (i, t) in scene.triangles.iter().enumerate() {
        let e = scene.materials[scene.material_of[i] as usize].emission;
        if e.max_element() > 0.0 {
            let l = TriangleLight::new(t[0], t[1], t[2], e)
                .map_err(|err| RenderError::Setting(format!("emissive triangle {i}: {err}")))?;
            light_of_triangle[i] = lights.len() as u32;
            lights.push(Light::Triangle(l));
        }
    }
    Ok((lights, light_of_triangle))
}

#[cfg(test)]
mod tests {
    use super::*;
    use slc_core::ies::IesProfile;
    use slc_core::light::{IesLight, PointLight, SpotLight, Vpl};
    use std::sync::Arc;

    /// `∫ I(ω) dω` over the sphere by a Fibonacci lattice of `n` directions.
    fn integrate(l: &Light, n: usize) -> Vec3 {
        let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
        let mut sum = Vec3::ZERO;
        for i in 0..n {
            let z = 1.0 - (2.0 * i as f64 + 1.0) / n as f64;
            let r = (1.0 - z * z).sqrt();
            let phi = golden * i as f64;
            sum += l.intensity(Vec3::new((r * phi.cos()) as f32, (r * phi.sin()) as f32, z as f32));
        }
        sum * (4.0 * std::f32::consts::PI / n as f32)
    }

    /// Every light type's emitted power is the integral of its intensity,
    /// and the set's power table (which the light BVH also reads) and alias
    /// pmf follow it.
    #[test]
    fn emitted_power_is_the_integral_of_intensity_for_every_type() {
        let ies = "IESNA:LM-63-2002\nTILT=NONE\n1 1000 1 5 1 1 2 0 0 0\n1 1 0\n0 22.5 45 67.5 90\n0\n100 80 50 20 0\n";
        let profile = Arc::new(IesProfile::parse(ies).unwrap());
        let lights = vec![
            Light::Point(PointLight::new(Vec3::ZERO, Vec3::new(1.0, 2.0, 3.0)).unwrap()),
            Light::Spot(SpotLight::new(Vec3::ZERO, -Vec3::Y, Vec3::splat(2.0), 0.3, 0.7).unwrap()),
            Light::Ies(
                IesLight::new(Vec3::ZERO, -Vec3::Y, Vec3::X, Vec3::splat(0.01), profile).unwrap(),
            ),
            Light::Triangle(
                TriangleLight::new(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::splat(3.0)).unwrap(),
            ),
            Light::Vpl(Vpl::new(Vec3::ZERO, Vec3::Z, Vec3::splat(5.0)).unwrap()),
        ];
        let set = LightSet::new(lights.clone()).unwrap();
        let total: f32 = set.power().iter().map(|p| p.max_element()).sum();
        for (i, l) in lights.iter().enumerate() {
            let exact = set.power()[i];
            let numeric = integrate(l, 400_000);
            assert!(
                (exact - numeric).abs().max_element() < 2e-3 * exact.max_element(),
                "light {i}: power {exact} vs ∫I = {numeric}"
            );
            assert_eq!(exact, l.power());
            assert!(
                (set.alias().pdf(i) as f32 - exact.max_element() / total).abs() < 1e-6,
                "light {i} pmf"
            );
        }
    }
}
