//! Light types and their bounds (docs/architecture.md §1.3; talk: "Variety
//! of light types", "Area light bound").
//!
//! Every light gives its RGB peak radiant intensity `I_max` (what sets its
//! threshold range), its RGB intensity toward a unit direction `w` (pointing
//! from the light to the receiver), and its [`LightBound`]: a centre and an
//! extent `R` such that the light's range sphere for random range `r` is
//! centred there with radius `R + r` (points: `R = 0`; triangles: `R` is the
//! radius of the triangle's minimal sphere).

use crate::LightError;
use crate::ies::IesProfile;
use crate::range::{intensity_measure, slc_keep, slc_weight, threshold_range2};
use crate::sphere::Sphere;
use crate::wgsl::*;
use alloc::sync::Arc;
use alloc::vec::Vec;
use glam::Vec3;

crate::shared! {
    /// 1/π.
    pub const INV_PI: f32 = 0.3183098861837907;

    /// Smallest squared distance used in the `1/d²` fall-off (1 µm² in scene
    /// metres): the point-light singularity at `d = 0` gives a large finite
    /// value instead of ∞ on both backends.
    pub const MIN_D2: f32 = 0.000000000001;

    /// Largest peak radiant intensity `I_max` a light may have, per
    /// channel: 2⁵⁶ ≈ 7.2·10¹⁶ (W/sr, or the engine's unit). Above it a
    /// pixel's sum could overflow `f32`: one light's term is at most
    /// `I_max/MIN_D2` (≤ 2⁹⁶), and a sum of 2²⁴ such terms with the
    /// interleaving's flux scale (64) and the weighted picks' `W/(k·w)`
    /// stays below 2¹²⁷. Every constructor refuses more
    /// ([`LightError::TooBright`]), and the GPU's VPL packing skips such a
    /// VPL ([`crate::interleave::vpl_record_ok`]), so no light writes ∞
    /// into an image.
    pub const MAX_INTENSITY: f32 = 72057594037927936.0;

    /// `r_t²` of a VPL of flux `flux`: the threshold range of its peak
    /// intensity `Φ/π` (cosine lobe) for exposure `E`, error bound `ε` and
    /// intensity measure `mode` ([`crate::range::intensity_measure`]).
    pub fn vpl_rt2(flux: vec3f, exposure: f32, error_bound: f32, mode: u32) -> f32 {
        return threshold_range2(intensity_measure(flux * INV_PI, mode), exposure, error_bound);
    }

    /// Radius `R + √r²` of the range sphere of a light with extent `R`
    /// (0 for points, the minimal-sphere radius for triangles; talk: "Area
    /// light bound") and squared random range `r²`.
    pub fn range_radius(extent: f32, r2: f32) -> f32 {
        return extent + sqrt(r2);
    }

    /// Inverse-square fall-off `1 / max(d², MIN_D2)`.
    pub fn inverse_square(d2: f32) -> f32 {
        return 1.0 / max(d2, MIN_D2);
    }

    /// Factor of a kept connection to a point at distance² `d2` seen under
    /// cosine `cos_x` at the shading point: `cos_x / d² · 1/p · w`, with the
    /// RR weight `1/p = max(d²/r_t², 1)` (1 for `rt2 = +∞`, nothing culled)
    /// and `w` the selection weight (the reservoir's n/k, 1/pmf, MIS).
    /// Multiplies the light's intensity toward the point.
    pub fn connection_factor(cos_x: f32, d2: f32, rt2: f32, w: f32) -> f32 {
        return cos_x * inverse_square(d2) * slc_weight(rt2, d2) * w;
    }

    /// Cosine at shading point `x` of the connection to point `y` sampled on
    /// a light with squared random range `r2`, or 0 where it carries no
    /// light: the roulette drops it (`slc_keep(r2, d²)` fails; `r2 = +∞`
    /// keeps all), `y = x`, or the light arrives from below the shading
    /// normal `n` or the surface itself (geometric normal `ng`, on `n`'s
    /// side), or either normal is not a number (the comparisons are written
    /// so that NaN fails them). Both backends' next-event estimation test a
    /// pick with it.
    pub fn connection_cosine(x: vec3f, y: vec3f, n: vec3f, ng: vec3f, r2: f32) -> f32 {
        let v: vec3f = x - y;
        let d2: f32 = dot(v, v);
        if !slc_keep(r2, d2) || !(d2 > 0.0) {
            return 0.0;
        }
        let w: vec3f = v / sqrt(d2);
        let cos_x: f32 = -dot(n, w);
        if !(cos_x > 0.0) || !(dot(ng, w) < 0.0) {
            return 0.0;
        }
        return cos_x;
    }

    /// VPL cosine lobe per unit flux: `I(w)/Φ = max(n·w, 0)/π`, so
    /// `I_max = Φ/π` (Keller 1997; docs/architecture.md §1.3).
    pub fn vpl_lobe(n: vec3f, w: vec3f) -> f32 {
        return max(dot(n, w), 0.0) * INV_PI;
    }

    /// VPL transfer per unit flux: the irradiance at a receiver with unit
    /// normal `n_x` from a VPL with unit normal `n_l`, `v = x − p` the vector
    /// from the VPL to the receiver:
    /// `E/Φ = max(n_l·v, 0) · max(−n_x·v, 0) / (π · m²)`, `m = max(|v|², d²_min)`,
    /// i.e. `(1/π) cos θ_l cos θ_x / d²` for `d² ≥ d²_min` (no square root),
    /// smoothly reduced to 0 inside the clamp distance (no singularity;
    /// the clamp is at least [`MIN_D2`], so a VPL on the receiver gives 0,
    /// not 0/0, at a clamp distance of 0).
    pub fn vpl_transfer(n_l: vec3f, n_x: vec3f, v: vec3f, min_d2: f32) -> f32 {
        let m: f32 = max(dot(v, v), max(min_d2, MIN_D2));
        return max(dot(n_l, v), 0.0) * max(-dot(n_x, v), 0.0) * INV_PI / (m * m);
    }

    /// Spot fall-off of `t = saturate((cos θ − cos_outer)/(cos_inner −
    /// cos_outer))`: `smoothstep`, `t²(3 − 2t)`, for `shape = 0` (pbrt-v4's
    /// `SpotLight`); `t²` for `shape = 1` (Bevy's and Filament's spot, whose
    /// `saturate(cos θ·scale + offset)²` is this `t²`); a hard edge when the
    /// two cones coincide.
    pub fn spot_falloff(cos_theta: f32, cos_outer: f32, cos_inner: f32, shape: f32) -> f32 {
        if cos_inner <= cos_outer {
            return select(0.0, 1.0, cos_theta >= cos_outer);
        }
        let t: f32 = saturate((cos_theta - cos_outer) / (cos_inner - cos_outer));
        return select(t * t * (3.0 - 2.0 * t), t * t, shape > 0.5);
    }

    /// Lambertian emitter per unit radiance: `I(w)/L = A · max(n·w, 0)`, so
    /// `I_max = L·A`.
    pub fn triangle_lobe(n: vec3f, area: f32, w: vec3f) -> f32 {
        return area * max(dot(n, w), 0.0);
    }

    /// Uniform point on triangle (a, b, c) from `u1, u2 ∈ [0, 1)`:
    /// barycentrics `(1 − √u₁, u₂√u₁)` (pbrt-v3 §13.6.5); pdf = 1/area.
    pub fn triangle_sample(a: vec3f, b: vec3f, c: vec3f, u1: f32, u2: f32) -> vec3f {
        let su: f32 = sqrt(u1);
        let b0: f32 = 1.0 - su;
        let b1: f32 = u2 * su;
        return a * b0 + b * b1 + c * (1.0 - b0 - b1);
    }

    /// Converts an area pdf at `y` to a solid-angle pdf at `x`:
    /// `pdf_ω = pdf_A · d² / |cos θ_y|` (0 when the emitter is seen edge-on).
    pub fn area_to_solid_angle_pdf(pdf_area: f32, d2: f32, cos_light: f32) -> f32 {
        let c: f32 = abs(cos_light);
        if c <= 0.0 {
            return 0.0;
        }
        return pdf_area * d2 / c;
    }
}

/// Centre and extent of a light: its range sphere for random range `r` is
/// `(center, extent + r)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightBound {
    /// Sphere centre.
    pub center: Vec3,
    /// `R ≥ 0`: 0 for point-like lights, the minimal-sphere radius for
    /// triangles.
    pub extent: f32,
}

impl LightBound {
    /// The range sphere `(c, R + √r²)` for squared random range `r2`.
    pub fn range_sphere(&self, r2: f32) -> Sphere {
        Sphere::new(self.center, range_radius(self.extent, r2))
    }
}

fn check_point(field: &'static str, v: Vec3) -> Result<Vec3, LightError> {
    if v.is_finite() { Ok(v) } else { Err(LightError::NonFinite { field }) }
}

fn check_rgb(field: &'static str, v: Vec3) -> Result<Vec3, LightError> {
    if !v.is_finite() {
        return Err(LightError::NonFinite { field });
    }
    if v.min_element() < 0.0 {
        return Err(LightError::Negative { field });
    }
    Ok(v)
}

/// `light` when its peak intensity `I_max` ([`Light::peak`]) is within
/// [`MAX_INTENSITY`], else [`LightError::TooBright`] naming `field`.
fn check_peak<T>(field: &'static str, peak: Vec3, light: T) -> Result<T, LightError> {
    let peak = peak.max_element();
    if peak > MAX_INTENSITY {
        return Err(LightError::TooBright { field, peak, max: MAX_INTENSITY });
    }
    Ok(light)
}

fn check_dir(field: &'static str, v: Vec3) -> Result<Vec3, LightError> {
    check_point(field, v)?;
    let len = v.length();
    if !(len > 0.0 && len.is_finite()) {
        return Err(LightError::ZeroDirection { field });
    }
    Ok(v / len)
}

/// Isotropic point light: `I(w) = I`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    position: Vec3,
    intensity: Vec3,
}

impl PointLight {
    /// Position (finite) and RGB intensity (finite, ≥ 0, at most
    /// [`MAX_INTENSITY`]).
    pub fn new(position: Vec3, intensity: Vec3) -> Result<Self, LightError> {
        let intensity = check_rgb("intensity", intensity)?;
        check_peak(
            "intensity",
            intensity,
            Self { position: check_point("position", position)?, intensity },
        )
    }
    /// Position.
    pub fn position(&self) -> Vec3 {
        self.position
    }
}

/// Virtual point light: `I(w) = (Φ/π) max(n·w, 0)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vpl {
    position: Vec3,
    normal: Vec3,
    flux: Vec3,
}

impl Vpl {
    /// Position, surface normal (normalised here) and RGB flux Φ (finite,
    /// ≥ 0, its peak `Φ/π` at most [`MAX_INTENSITY`]).
    pub fn new(position: Vec3, normal: Vec3, flux: Vec3) -> Result<Self, LightError> {
        let flux = check_rgb("flux", flux)?;
        let vpl = Self {
            position: check_point("position", position)?,
            normal: check_dir("normal", normal)?,
            flux,
        };
        check_peak("flux", flux * INV_PI, vpl)
    }
    /// Position.
    pub fn position(&self) -> Vec3 {
        self.position
    }
    /// Unit normal.
    pub fn normal(&self) -> Vec3 {
        self.normal
    }
    /// RGB flux.
    pub fn flux(&self) -> Vec3 {
        self.flux
    }
}

/// Spot light: `I(w) = I₀ · smoothstep(cos θ_outer, cos θ_inner, d·w)`,
/// or with [`SpotLight::with_quadratic_falloff`] Bevy's `t²`
/// ([`spot_falloff`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpotLight {
    position: Vec3,
    direction: Vec3,
    intensity: Vec3,
    cos_outer: f32,
    cos_inner: f32,
    quadratic: bool,
}

impl SpotLight {
    /// Position, axis direction (normalised here), RGB peak intensity `I₀`,
    /// and the half-angles in radians of the full-intensity cone `inner` and
    /// of the cut-off cone `outer`, with `0 ≤ inner ≤ outer ≤ π`.
    pub fn new(
        position: Vec3,
        direction: Vec3,
        intensity: Vec3,
        inner: f32,
        outer: f32,
    ) -> Result<Self, LightError> {
        if !(inner.is_finite()
            && outer.is_finite()
            && 0.0 <= inner
            && inner <= outer
            && outer <= core::f32::consts::PI)
        {
            return Err(LightError::ConeAngles { inner, outer });
        }
        let intensity = check_rgb("intensity", intensity)?;
        let spot = Self {
            position: check_point("position", position)?,
            direction: check_dir("direction", direction)?,
            intensity,
            cos_outer: libm::cosf(outer),
            cos_inner: libm::cosf(inner),
            quadratic: false,
        };
        check_peak("intensity", intensity, spot)
    }
    /// The same spot with Bevy's (and Filament's) fall-off `t²` between
    /// the cones instead of the smoothstep ([`spot_falloff`]'s `shape` 1).
    pub fn with_quadratic_falloff(self) -> Self {
        Self { quadratic: true, ..self }
    }
    /// [`spot_falloff`]'s `shape`: 0 (smoothstep) or 1 (quadratic).
    pub fn falloff_shape(&self) -> f32 {
        if self.quadratic { 1.0 } else { 0.0 }
    }
    /// Position.
    pub fn position(&self) -> Vec3 {
        self.position
    }
    /// Unit axis direction.
    pub fn direction(&self) -> Vec3 {
        self.direction
    }
    /// Cosines of the cut-off and full-intensity half-angles `(cos θ_outer, cos θ_inner)`.
    pub fn cone_cosines(&self) -> (f32, f32) {
        (self.cos_outer, self.cos_inner)
    }
}

/// IES (LM-63) light: tabulated candela, bilinear lookup (see [`crate::ies`]).
///
/// Frame: photometric vertical angle γ = 0 points along `nadir`; the
/// horizontal angle C = 0 lies along `reference` (made perpendicular to
/// `nadir` here) and C grows counter-clockwise seen from above, i.e. towards
/// `reference × nadir`.
#[derive(Clone, Debug, PartialEq)]
pub struct IesLight {
    position: Vec3,
    nadir: Vec3,
    reference: Vec3,
    tint: Vec3,
    profile: Arc<IesProfile>,
}

impl IesLight {
    /// Position, nadir and reference directions, an RGB `tint` that scales
    /// the candela values (colour and units), and a parsed profile (type C).
    pub fn new(
        position: Vec3,
        nadir: Vec3,
        reference: Vec3,
        tint: Vec3,
        profile: Arc<IesProfile>,
    ) -> Result<Self, LightError> {
        let nadir = check_dir("nadir", nadir)?;
        let reference = check_dir("reference", reference - nadir * nadir.dot(reference))
            .map_err(|_| LightError::ZeroDirection { field: "reference (parallel to nadir)" })?;
        if !profile.is_type_c() {
            return Err(LightError::UnsupportedPhotometry(profile.photometric_type()));
        }
        let tint = check_rgb("tint", tint)?;
        let peak = tint * profile.max_candela();
        check_peak(
            "tint × candela",
            peak,
            Self { position: check_point("position", position)?, nadir, reference, tint, profile },
        )
    }
    /// Position.
    pub fn position(&self) -> Vec3 {
        self.position
    }
    /// The profile.
    pub fn profile(&self) -> &IesProfile {
        &self.profile
    }
    /// The shared profile (for deduplicating uploads).
    pub fn profile_arc(&self) -> &Arc<IesProfile> {
        &self.profile
    }
    /// Unit nadir (γ = 0).
    pub fn nadir(&self) -> Vec3 {
        self.nadir
    }
    /// Unit reference direction (C = 0), perpendicular to the nadir.
    pub fn reference(&self) -> Vec3 {
        self.reference
    }
    /// RGB tint.
    pub fn tint(&self) -> Vec3 {
        self.tint
    }
    /// Candela toward unit direction `w` (no tint).
    pub fn candela(&self, w: Vec3) -> f32 {
        crate::ies::ies_light_candela(self.profile.table(), 0, self.nadir, self.reference, w)
    }
}

/// One-sided Lambertian triangle emitter with radiance `L`: `I(w) = L·A·max(n·w, 0)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleLight {
    v: [Vec3; 3],
    radiance: Vec3,
    normal: Vec3,
    area: f32,
    bound: LightBound,
}

impl TriangleLight {
    /// Vertices (counter-clockwise seen from the emitting side) and RGB
    /// radiance. Zero-area triangles (repeated or collinear vertices) are
    /// rejected: they emit nothing and have no normal.
    pub fn new(a: Vec3, b: Vec3, c: Vec3, radiance: Vec3) -> Result<Self, LightError> {
        for (f, p) in [("vertex 0", a), ("vertex 1", b), ("vertex 2", c)] {
            check_point(f, p)?;
        }
        let radiance = check_rgb("radiance", radiance)?;
        let n = (b - a).cross(c - a);
        let len = n.length();
        let area = 0.5 * len;
        if !(area > 0.0 && area.is_finite()) {
            return Err(LightError::DegenerateTriangle);
        }
        let s = Sphere::of_triangle(a, b, c);
        let light = Self {
            v: [a, b, c],
            radiance,
            normal: n / len,
            area,
            bound: LightBound { center: s.center, extent: s.radius },
        };
        check_peak("radiance × area", radiance * area, light)
    }
    /// Vertices.
    pub fn vertices(&self) -> [Vec3; 3] {
        self.v
    }
    /// Unit normal.
    pub fn normal(&self) -> Vec3 {
        self.normal
    }
    /// Area.
    pub fn area(&self) -> f32 {
        self.area
    }
    /// RGB radiance.
    pub fn radiance(&self) -> Vec3 {
        self.radiance
    }
    /// Uniform point on the triangle ([`triangle_sample`]); its area pdf is `1/area`.
    pub fn sample(&self, u1: f32, u2: f32) -> Vec3 {
        triangle_sample(self.v[0], self.v[1], self.v[2], u1, u2)
    }
}

/// [`Light::power`] of every light, integrating each distinct IES profile
/// (by identity of its shared `Arc`) once.
pub fn emitted_powers(lights: &[Light]) -> Vec<Vec3> {
    let mut flux: Vec<(*const IesProfile, f32)> = Vec::new();
    lights
        .iter()
        .map(|l| match l {
            Light::Ies(ies) => {
                let key = Arc::as_ptr(&ies.profile);
                let f = match flux.iter().find(|(k, _)| *k == key) {
                    Some(&(_, f)) => f,
                    None => {
                        let f = ies.profile.total_flux() as f32;
                        flux.push((key, f));
                        f
                    }
                };
                ies.tint * f
            }
            _ => l.power(),
        })
        .collect()
}

/// `r_t²` of a VPL of flux `Φ` (interleave-scaled where it applies): its
/// peak intensity is `Φ/π` (cosine lobe), shared by the CPU and GPU
/// backends ([`vpl_rt2`] is the same formula in shared code).
pub fn vpl_threshold_range2(params: &crate::range::RangeParams, flux: Vec3) -> f32 {
    vpl_rt2(flux, params.exposure(), params.error_bound(), params.measure().mode())
}

/// Any light slc culls.
#[derive(Clone, Debug, PartialEq)]
pub enum Light {
    /// Point light.
    Point(PointLight),
    /// Virtual point light.
    Vpl(Vpl),
    /// Spot light.
    Spot(SpotLight),
    /// IES light.
    Ies(IesLight),
    /// Triangle emitter.
    Triangle(TriangleLight),
}

impl Light {
    /// The light with every point `p` of it moved to `p·scale + offset`
    /// (`scale > 0`; directions, intensities and radiance unchanged), as a
    /// scene file places the geometry that holds it.
    pub fn placed(&self, scale: f32, offset: Vec3) -> Result<Light, LightError> {
        let at = |p: Vec3| p * scale + offset;
        Ok(match self {
            Light::Point(l) => Light::Point(PointLight::new(at(l.position), l.intensity)?),
            Light::Vpl(l) => Light::Vpl(Vpl::new(at(l.position), l.normal, l.flux)?),
            Light::Spot(l) => Light::Spot(SpotLight { position: at(l.position), ..*l }),
            Light::Ies(l) => Light::Ies(IesLight { position: at(l.position), ..l.clone() }),
            Light::Triangle(l) => {
                let [a, b, c] = l.v;
                Light::Triangle(TriangleLight::new(at(a), at(b), at(c), l.radiance)?)
            }
        })
    }

    /// RGB peak radiant intensity `I_max` per channel: point `I`, VPL `Φ/π`,
    /// spot `I₀`, IES max candela × tint, triangle `L·A`.
    pub fn peak(&self) -> Vec3 {
        match self {
            Light::Point(l) => l.intensity,
            Light::Vpl(l) => l.flux * INV_PI,
            Light::Spot(l) => l.intensity,
            Light::Ies(l) => l.tint * l.profile.max_candela(),
            Light::Triangle(l) => l.radiance * l.area,
        }
    }

    /// RGB emitted power Φ (W), the one formula both power sampling and
    /// the light BVH use: point `4π I`; VPL `Φ` (its cosine lobe `Φ/π · cos`
    /// integrates to Φ); spot `2π I₀ ((1 − cos θ_i) + k (cos θ_i − cos θ_o))`,
    /// the exact integral of its fall-off (`k = 1/2` for the smoothstep,
    /// pbrt-v4's `SpotLight::Phi`; `1/3` for the quadratic); IES `tint ×` the profile's flux integrated from its
    /// table; one-sided Lambertian triangle `π L A`. For IES lights this
    /// integrates the table (0.5° grid): use [`emitted_powers`] for many
    /// lights sharing profiles.
    pub fn power(&self) -> Vec3 {
        let pi = core::f32::consts::PI;
        match self {
            Light::Point(l) => l.intensity * (4.0 * pi),
            Light::Vpl(l) => l.flux,
            Light::Spot(l) => {
                let k = if l.quadratic { 1.0 / 3.0 } else { 0.5 };
                l.intensity * (2.0 * pi * ((1.0 - l.cos_inner) + k * (l.cos_inner - l.cos_outer)))
            }
            Light::Ies(l) => l.tint * l.profile.total_flux() as f32,
            Light::Triangle(l) => l.radiance * (pi * l.area),
        }
    }

    /// RGB radiant intensity toward unit direction `w` (from the light).
    pub fn intensity(&self, w: Vec3) -> Vec3 {
        match self {
            Light::Point(l) => l.intensity,
            Light::Vpl(l) => l.flux * vpl_lobe(l.normal, w),
            Light::Spot(l) => {
                l.intensity
                    * spot_falloff(dot(l.direction, w), l.cos_outer, l.cos_inner, l.falloff_shape())
            }
            Light::Ies(l) => l.tint * l.candela(w),
            Light::Triangle(l) => l.radiance * triangle_lobe(l.normal, l.area, w),
        }
    }

    /// Centre and extent of the range sphere.
    pub fn bound(&self) -> LightBound {
        let point = |p: Vec3| LightBound { center: p, extent: 0.0 };
        match self {
            Light::Point(l) => point(l.position),
            Light::Vpl(l) => point(l.position),
            Light::Spot(l) => point(l.position),
            Light::Ies(l) => point(l.position),
            Light::Triangle(l) => l.bound,
        }
    }

    /// Irradiance-like point contribution `I(w)/d²` at `x` for point-like
    /// lights, with `w` and `d²` measured from the light's position (the
    /// triangle's bound centre for triangles; path tracers sample a point
    /// instead). Returns `(contribution, d²)`; at `d = 0` the direction is
    /// taken as zero (no NaN) and the fall-off is capped by [`MIN_D2`].
    pub fn contribution_at(&self, x: Vec3) -> (Vec3, f32) {
        let v = x - self.bound().center;
        let d2 = dot(v, v);
        let w = if d2 > 0.0 { v / sqrt(d2) } else { Vec3::ZERO };
        (self.intensity(w) * inverse_square(d2), d2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vpl_peak_and_lobe() {
        let l = Light::Vpl(Vpl::new(Vec3::ZERO, Vec3::Z * 2.0, Vec3::new(3.0, 6.0, 9.0)).unwrap());
        assert!((l.peak() - Vec3::new(3.0, 6.0, 9.0) / core::f32::consts::PI).length() < 1e-6);
        assert!((l.intensity(Vec3::Z) - l.peak()).length() < 1e-6);
        let w = Vec3::new(1.0, 0.0, 1.0).normalize();
        assert!((l.intensity(w) - l.peak() * w.z).length() < 1e-6);
        assert_eq!(l.intensity(-Vec3::Z), Vec3::ZERO);
    }

    #[test]
    fn spot_falloff_shape() {
        let (inner, outer) = (0.2f32, 0.5f32);
        let s = SpotLight::new(Vec3::ZERO, -Vec3::Y, Vec3::ONE, inner, outer).unwrap();
        let l = Light::Spot(s);
        assert_eq!(l.intensity(-Vec3::Y), Vec3::ONE);
        let at = |a: f32| l.intensity(Vec3::new(libm::sinf(a), -libm::cosf(a), 0.0)).x;
        assert_eq!(at(0.19), 1.0);
        assert_eq!(at(0.51), 0.0);
        let mid = at(0.35);
        assert!(mid > 0.0 && mid < 1.0);
        assert!(at(0.3) > at(0.4));
        assert!(SpotLight::new(Vec3::ZERO, Vec3::Y, Vec3::ONE, 0.6, 0.5).is_err());
        assert!(SpotLight::new(Vec3::ZERO, Vec3::ZERO, Vec3::ONE, 0.1, 0.5).is_err());
    }

    /// The quadratic fall-off is Bevy's spot (`bevy_pbr` 0.20's
    /// `spot_light`: `saturate(cos θ·scale + offset)²`, `scale = 1/(cos_i −
    /// cos_o)`, `offset = −cos_o·scale`), and both shapes' [`Light::power`]
    /// is the integral of the intensity over the sphere (midpoint rule).
    #[test]
    fn spot_falloff_quadratic_is_bevys_and_powers_integrate() {
        let (inner, outer) = (0.2f32, 0.7f32);
        let (ci, co) = (libm::cosf(inner) as f64, libm::cosf(outer) as f64);
        let smooth = SpotLight::new(Vec3::ZERO, -Vec3::Y, Vec3::ONE, inner, outer).unwrap();
        for (s, quadratic) in [(smooth, false), (smooth.with_quadratic_falloff(), true)] {
            let l = Light::Spot(s);
            let at = |a: f64| {
                l.intensity(Vec3::new(libm::sin(a) as f32, -libm::cos(a) as f32, 0.0)).x as f64
            };
            if quadratic {
                let scale = 1.0 / (ci - co);
                for a in [0.1, 0.25, 0.4, 0.55, 0.69, 0.8] {
                    let bevy = (libm::cos(a) * scale - co * scale).clamp(0.0, 1.0).powi(2);
                    assert!((at(a) - bevy).abs() < 1e-5, "{a}: {} vs Bevy {bevy}", at(a));
                }
            }
            let m = 20_000;
            let integral: f64 = (0..m)
                .map(|i| {
                    let a = core::f64::consts::PI * (i as f64 + 0.5) / m as f64;
                    at(a) * 2.0 * core::f64::consts::PI * libm::sin(a) * core::f64::consts::PI
                        / m as f64
                })
                .sum();
            let p = l.power().x as f64;
            assert!(
                (p - integral).abs() < 1e-4 * p,
                "quadratic {quadratic}: power {p} vs integral {integral}"
            );
        }
    }

    #[test]
    fn triangle_peak_bound_and_lobe() {
        let t =
            TriangleLight::new(Vec3::ZERO, Vec3::X * 2.0, Vec3::Y * 2.0, Vec3::new(1.0, 2.0, 3.0))
                .unwrap();
        assert_eq!(t.area(), 2.0);
        assert_eq!(t.normal(), Vec3::Z);
        let l = Light::Triangle(t);
        assert_eq!(l.peak(), Vec3::new(2.0, 4.0, 6.0));
        assert_eq!(l.intensity(-Vec3::Z), Vec3::ZERO);
        // Right triangle: minimal sphere on the hypotenuse.
        let b = l.bound();
        assert!((b.center - Vec3::new(1.0, 1.0, 0.0)).length() < 1e-6);
        assert!((b.extent - 2f32.sqrt()).abs() < 1e-5);
        // Talk: radius R + r.
        let s = b.range_sphere(9.0);
        assert!((s.radius - (2f32.sqrt() + 3.0)).abs() < 1e-5);
    }

    #[test]
    fn triangle_samples_lie_on_triangle() {
        let t = TriangleLight::new(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::ONE).unwrap();
        for i in 0..16 {
            for j in 0..16 {
                let p = t.sample(i as f32 / 16.0, j as f32 / 16.0);
                assert!(p.x >= -1e-6 && p.y >= -1e-6 && p.x + p.y <= 1.0 + 1e-6 && p.z == 0.0);
            }
        }
    }

    #[test]
    fn degenerate_triangles_are_errors() {
        let e = Vec3::ONE;
        assert_eq!(
            TriangleLight::new(Vec3::ZERO, Vec3::ZERO, Vec3::X, e),
            Err(LightError::DegenerateTriangle)
        );
        assert_eq!(
            TriangleLight::new(Vec3::ZERO, Vec3::X, Vec3::X * 2.0, e),
            Err(LightError::DegenerateTriangle)
        );
        assert!(TriangleLight::new(Vec3::ZERO, Vec3::X, Vec3::Y, -e).is_err());
        assert!(TriangleLight::new(Vec3::NAN, Vec3::X, Vec3::Y, e).is_err());
    }

    #[test]
    fn bad_inputs_are_typed_errors() {
        assert!(PointLight::new(Vec3::new(f32::NAN, 0.0, 0.0), Vec3::ONE).is_err());
        assert!(PointLight::new(Vec3::ZERO, Vec3::new(-1.0, 0.0, 0.0)).is_err());
        assert!(PointLight::new(Vec3::ZERO, Vec3::splat(f32::INFINITY)).is_err());
        assert!(Vpl::new(Vec3::ZERO, Vec3::ZERO, Vec3::ONE).is_err());
        assert!(PointLight::new(Vec3::ZERO, Vec3::splat(MAX_INTENSITY)).is_ok());
        for bright in [f32::MAX, MAX_INTENSITY * 2.0] {
            let e = LightError::TooBright { field: "intensity", peak: bright, max: MAX_INTENSITY };
            assert_eq!(PointLight::new(Vec3::ZERO, Vec3::new(0.0, bright, 0.0)), Err(e));
            assert!(SpotLight::new(Vec3::ZERO, Vec3::Y, Vec3::splat(bright), 0.1, 0.2).is_err());
            assert!(Vpl::new(Vec3::ZERO, Vec3::Y, Vec3::splat(bright * 4.0)).is_err());
            assert!(
                TriangleLight::new(Vec3::ZERO, Vec3::X * 2.0, Vec3::Y * 2.0, Vec3::splat(bright))
                    .is_err()
            );
        }
        // A VPL's peak is Φ/π: its flux may reach π × the limit.
        assert!(Vpl::new(Vec3::ZERO, Vec3::Y, Vec3::splat(MAX_INTENSITY * 3.0)).is_ok());
    }

    #[test]
    fn vpl_transfer_on_the_receiver_is_zero_without_a_clamp() {
        assert_eq!(vpl_transfer(Vec3::Z, -Vec3::Z, Vec3::ZERO, 0.0), 0.0);
        let t = vpl_transfer(Vec3::Z, -Vec3::Z, Vec3::Z * 1e-7, 0.0);
        assert!(t.is_finite() && t >= 0.0, "{t}");
    }

    #[test]
    fn contribution_at_zero_distance_is_finite() {
        let l = Light::Vpl(Vpl::new(Vec3::ZERO, Vec3::Z, Vec3::ONE).unwrap());
        let (c, d2) = l.contribution_at(Vec3::ZERO);
        assert_eq!(d2, 0.0);
        assert!(c.is_finite());
        let p = Light::Point(PointLight::new(Vec3::ZERO, Vec3::ONE).unwrap());
        let (c, _) = p.contribution_at(Vec3::ZERO);
        assert!(c.is_finite() && c.x == 1.0 / MIN_D2);
    }

    #[test]
    fn vpl_transfer_matches_cosines_over_d2() {
        let nl = Vec3::Y;
        let nx = -Vec3::Y;
        let v = Vec3::new(0.3, 2.0, 0.0);
        let d2 = v.length_squared();
        let w = v / d2.sqrt();
        let expect = w.y * w.y / (core::f32::consts::PI * d2);
        assert!((vpl_transfer(nl, nx, v, 1e-4) - expect).abs() < 1e-7);
        assert_eq!(vpl_transfer(nl, nx, Vec3::ZERO, 1e-4), 0.0);
        assert_eq!(vpl_transfer(nl, nx, -v, 1e-4), 0.0);
        assert!(vpl_transfer(nl, nx, Vec3::Y * 1e-3, 1e-4).is_finite());
    }

    #[test]
    fn solid_angle_pdf() {
        assert_eq!(area_to_solid_angle_pdf(0.5, 4.0, -0.5), 4.0);
        assert_eq!(area_to_solid_angle_pdf(0.5, 4.0, 0.0), 0.0);
    }
}
