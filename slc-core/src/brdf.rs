//! The glTF 2.0 metallic-roughness BRDF (glTF 2.0 specification, Appendix
//! B, "BRDF Implementation"), its importance sampling and its pdf, written
//! once for the CPU and the GPU.
//!
//! A material is a base colour `b`, a metallic factor `m ∈ [0, 1]`, a GGX
//! roughness `α` (glTF's perceptual roughness squared, [`ggx_alpha`]) and
//! the dielectric's Fresnel reflectance at normal and grazing incidence,
//! `F0_d` (RGB) and `F90_d` (glTF: `F0_d = ((ior − 1)/(ior + 1))² = 0.04`
//! for the default IOR 1.5 and `F90_d = 1`; `KHR_materials_specular` scales
//! both by its specular factor and tints `F0_d` by its colour). The BRDF is
//! glTF's normative mix of a dielectric and a metal:
//!
//! ```text
//! f = mix(dielectric, metal, m)
//!   dielectric = (1 − F_d)·b/π + F_d·D·V      F_d = Schlick(F0_d, F90_d, v·h)
//!   metal      = F_b·D·V                      F_b = Schlick(b, 1, v·h)
//! ```
//!
//! with `D` the GGX / Trowbridge-Reitz distribution ([`ggx_d`]), `V` the
//! height-correlated Smith visibility `G₂/(4 n·l n·v)` ([`smith_visibility`];
//! Heitz 2014) and Schlick's Fresnel ([`fresnel_schlick`]). At `m = 0` or
//! `1` this equals the specification's implementation form (`c_diff =
//! lerp(b, 0, m)`, `F0 = lerp(0.04, b, m)`, `f = (1 − F)·c_diff/π + F·D·V`);
//! for fractional `m` the normative mix is taken. A **Lambertian** material
//! is `m = 0, F0_d = 0, F90_d = 0`: then `F_d ≡ 0` and `f = b/π` exactly.
//!
//! Where Bevy's `StandardMaterial` differs (its `pbr_lighting.wgsl`): Bevy's
//! diffuse lobe is Burley's (Disney) instead of Lambert and is not weighted
//! by `1 − F`; its specular lobe has a multiple-scattering energy
//! compensation; its dielectric `F0 = 0.16·reflectance²` (0.04 at the
//! default reflectance 0.5) with `F90` from `F0`; its perceptual roughness
//! is clamped to at least 0.089. That BRDF is here too, as Bevy writes it
//! ([`bevy_brdf`], [`bevy_alpha`], [`bevy_f0`], [`bevy_dfg`]), for an
//! engine plugin that must shade exactly as Bevy does (slc-bevy).
//!
//! Sampling ([`bsdf_sample`], [`bsdf_pdf`]): the specular lobe by the
//! bounded visible-normal distribution (Eto & Tokuyoshi, "Bounded VNDF
//! Sampling for Smith–GGX Reflections", SIGGRAPH Asia 2023 Technical
//! Communications; Heitz 2018's VNDF sampling with the spherical cap
//! shrunk to the directions that reflect above the horizon), the diffuse
//! lobe by the cosine, one of them chosen with probability
//! [`specular_probability`]; the pdf is the mixture of both, so MIS against
//! light sampling is exact whichever lobe drew the direction.
//!
//! Single scattering loses energy at high roughness (the Smith model's
//! multiply scattered light is not modelled, as in the glTF reference):
//! the white furnace `∫ f cos dω` of a white metal at normal view is 1.000,
//! 0.988, 0.877, 0.688 and 0.307 at `α` = 0.001, 0.1, 0.3, 0.5 and 1. The
//! reference's dielectric is not energy-conserving at oblique views (its
//! diffuse lobe is weighted by `1 − F(v·h)`): a white one reflects 1.025 at
//! `n·v = 0.5` and 1.19 at 0.2 for `α = 0.1`.

// Shared (WGSL) functions take material parameters as scalars and vectors.
#![allow(clippy::too_many_arguments)]

use crate::light::INV_PI;
use crate::mis::{cosine_direction, cosine_pdf, onb_to_local, onb_to_world};
use crate::wgsl::*;

crate::shared! {
    /// Smallest GGX `α` (perceptual roughness 0.0316): a smoother surface
    /// is rendered at this `α`, so that `D`'s peak `1/(π α²)` stays finite
    /// and sampled and evaluated directions agree in `f32`.
    pub const GGX_ALPHA_MIN: f32 = 0.001;

    /// GGX `α` of glTF's perceptual roughness `r ∈ [0, 1]`: `α = r²`
    /// (glTF 2.0 Appendix B), at least [`GGX_ALPHA_MIN`].
    pub fn ggx_alpha(roughness: f32) -> f32 {
        return max(roughness * roughness, GGX_ALPHA_MIN);
    }

    /// GGX / Trowbridge-Reitz normal distribution (Walter et al. 2007) of
    /// a microfacet normal `h` with `cos = n·h` and `sin2 = |n × h|²`:
    /// `D = α² / (π (cos²·α² + sin²)²)` for `cos > 0`, else 0. Taking the
    /// sine separately keeps the peak accurate in `f32` at small `α`
    /// (`1 − cos²` cancels there).
    pub fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
        if cos_h <= 0.0 {
            return 0.0;
        }
        let a2: f32 = alpha * alpha;
        let t: f32 = cos_h * cos_h * a2 + sin2_h;
        return a2 * INV_PI / (t * t);
    }

    /// `√(cos²(1 − α²) + α²)`, the Smith term of a direction at cosine
    /// `cos` to the normal (`2 cos / (cos + this)` is its `G₁`).
    pub fn smith_root(cos: f32, alpha: f32) -> f32 {
        let a2: f32 = alpha * alpha;
        return sqrt(cos * cos * (1.0 - a2) + a2);
    }

    /// Height-correlated Smith visibility `V = G₂ / (4 n·l n·v) =
    /// ½ / (n·l·√(n·v²(1−α²)+α²) + n·v·√(n·l²(1−α²)+α²))` (glTF 2.0
    /// Appendix B; Heitz, "Understanding the Masking-Shadowing Function",
    /// JCGT 2014); 0 unless both cosines are positive.
    pub fn smith_visibility(n_l: f32, n_v: f32, alpha: f32) -> f32 {
        if n_l <= 0.0 || n_v <= 0.0 {
            return 0.0;
        }
        return 0.5 / (n_l * smith_root(n_v, alpha) + n_v * smith_root(n_l, alpha));
    }

    /// Schlick's Fresnel `F0 + (F90 − F0)(1 − v·h)⁵`.
    pub fn fresnel_schlick(f0: vec3f, f90: f32, v_h: f32) -> vec3f {
        let c: f32 = saturate(1.0 - v_h);
        let c2: f32 = c * c;
        return f0 + (vec3f(f90, f90, f90) - f0) * (c2 * c2 * c);
    }

    /// The Fresnel weight of the specular lobe, `(1 − m)·F_d + m·F_b`
    /// (the metal's `F0` is the base colour, its `F90` 1).
    pub fn specular_fresnel(base: vec3f, metallic: f32, f0_d: vec3f, f90_d: f32, v_h: f32) -> vec3f {
        return fresnel_schlick(f0_d, f90_d, v_h) * (1.0 - metallic) + fresnel_schlick(base, 1.0, v_h) * metallic;
    }

    /// The diffuse lobe's BRDF `(1 − m)·(1 − F_d)·b/π` at `v·h`
    /// (`b/π` exactly for a Lambertian material).
    pub fn diffuse_brdf(base: vec3f, metallic: f32, f0_d: vec3f, f90_d: f32, v_h: f32) -> vec3f {
        return (vec3f(1.0, 1.0, 1.0) - fresnel_schlick(f0_d, f90_d, v_h)) * base * (1.0 - metallic) * INV_PI;
    }

    /// `v·h` of the unit view `v` and light `l` directions (0 when
    /// `v = −l`, where the half vector is undefined).
    pub fn half_cosine(v: vec3f, l: vec3f) -> f32 {
        let h: vec3f = v + l;
        let len2: f32 = dot(h, h);
        if len2 <= 0.0 {
            return 0.0;
        }
        return saturate(dot(v, h) / sqrt(len2));
    }

    /// The specular lobe's BRDF `F·D·V` at unit normal `n`, view `v` and
    /// light `l` (0 unless both lie above `n`).
    pub fn specular_brdf(base: vec3f, metallic: f32, f0_d: vec3f, f90_d: f32, alpha: f32, n: vec3f, v: vec3f, l: vec3f) -> vec3f {
        let n_l: f32 = dot(n, l);
        let n_v: f32 = dot(n, v);
        if n_l <= 0.0 || n_v <= 0.0 {
            return vec3f(0.0, 0.0, 0.0);
        }
        let hs: vec3f = v + l;
        let inv: f32 = 1.0 / sqrt(dot(hs, hs));
        let h: vec3f = hs * inv;
        let c: vec3f = cross(n, h);
        let d: f32 = ggx_d(dot(n, h), dot(c, c), alpha);
        return specular_fresnel(base, metallic, f0_d, f90_d, dot(v, h)) * (d * smith_visibility(n_l, n_v, alpha));
    }

    /// The whole BRDF `f(v, l)` at unit shading normal `n` (both unit
    /// directions point away from the surface): [`diffuse_brdf`] plus
    /// [`specular_brdf`]; 0 when `l` is below `n`. A view below `n` (smooth
    /// shading seen near its silhouette) keeps the diffuse lobe only.
    pub fn brdf_eval(base: vec3f, metallic: f32, f0_d: vec3f, f90_d: f32, alpha: f32, n: vec3f, v: vec3f, l: vec3f) -> vec3f {
        if dot(n, l) <= 0.0 {
            return vec3f(0.0, 0.0, 0.0);
        }
        let v_h: f32 = half_cosine(v, l);
        return diffuse_brdf(base, metallic, f0_d, f90_d, v_h) + specular_brdf(base, metallic, f0_d, f90_d, alpha, n, v, l);
    }

    /// `c_diff = (1 − m)·b`, the part of base colour `b` that the
    /// diffuse lobe of glTF's implementation form reflects (a metal has
    /// none): the albedo a receiver's Lambertian VPL irradiance is
    /// composed with ([`specular_correction`] holds the rest of its BRDF).
    pub fn diffuse_albedo(base: vec3f, metallic: f32) -> vec3f {
        return base * (1.0 - metallic);
    }

    /// The VPL application's specular correction of a receiver toward the
    /// unit light direction `l` (unit normal `n`, unit view `v`): the whole
    /// BRDF less the Lambertian part its irradiance is already composed
    /// with, `f(v, l) − c_diff/π` ([`brdf_eval`], [`diffuse_albedo`]), so
    /// that `c_diff/π · E + Σ Φ ⊙ (f − c_diff/π)·T` over the same lights,
    /// weights and transfer `T` is the BRDF's outgoing radiance.
    pub fn specular_correction(base: vec3f, metallic: f32, f0_d: vec3f, f90_d: f32, alpha: f32, n: vec3f, v: vec3f, l: vec3f) -> vec3f {
        return brdf_eval(base, metallic, f0_d, f90_d, alpha, n, v, l) - diffuse_albedo(base, metallic) * INV_PI;
    }

    /// `true` when the material has a specular lobe (a metal, or a
    /// dielectric with Fresnel reflectance); a Lambertian material has none
    /// and every function here reduces to `b/π` and cosine sampling.
    pub fn has_specular(metallic: f32, f0_d: vec3f, f90_d: f32) -> bool {
        return metallic > 0.0 || f90_d > 0.0 || max(max(f0_d.x, f0_d.y), f0_d.z) > 0.0;
    }

    /// Mean of the channels.
    pub fn channel_mean(c: vec3f) -> f32 {
        return (c.x + c.y + c.z) * 0.33333334;
    }

    /// The lobes of a receiver seen at `n·v`, as light selection and lobe
    /// sampling use them: `(k_d, k_s, α, n·v)` with `k_d` the diffuse and
    /// `k_s` the specular albedo estimated with the Fresnel at `n·v`
    /// (channel means of `(1 − m)(1 − F_d)·b` and `F_s`); `k_s = 0` without
    /// a specular lobe or for a view below `n` (only the diffuse lobe is
    /// seen there).
    pub fn receiver_lobe(base: vec3f, metallic: f32, f0_d: vec3f, f90_d: f32, alpha: f32, n_v: f32) -> vec4f {
        let d: f32 = channel_mean((vec3f(1.0, 1.0, 1.0) - fresnel_schlick(f0_d, f90_d, n_v)) * base * (1.0 - metallic));
        if n_v <= 0.0 || !has_specular(metallic, f0_d, f90_d) {
            return vec4f(d, 0.0, alpha, n_v);
        }
        return vec4f(d, channel_mean(specular_fresnel(base, metallic, f0_d, f90_d, n_v)), alpha, n_v);
    }

    /// Probability of sampling the specular lobe of a receiver with lobe
    /// `lobe` ([`receiver_lobe`]): its share `k_s/(k_s + k_d)` of the two
    /// albedos, kept in `[0.1, 0.9]` when both lobes exist so neither is
    /// starved; 0 without a specular lobe, 1 without a diffuse one.
    pub fn specular_probability(lobe: vec4f) -> f32 {
        if lobe.y <= 0.0 {
            return 0.0;
        }
        if lobe.x <= 0.0 {
            return 1.0;
        }
        return clamp(lobe.y / (lobe.y + lobe.x), 0.1, 0.9);
    }

    /// `π` times a receiver's largest `f·cos`, estimated from its lobe
    /// `lobe` ([`receiver_lobe`]): `k_d + k_s / (2α² (√(n·v²(1−α²)+α²) + n·v))`,
    /// the diffuse lobe's `k_d/π` plus the specular lobe's `F·D·V·n·l` with
    /// `D` at its peak `1/(πα²)` and `V·n·l` at its largest over every light
    /// direction, `½/(√(n·v²(1−α²)+α²) + n·v)` (the height-correlated `V`
    /// with `√(n·l²(1−α²)+α²) ≥ n·l`): the mirror direction's
    /// `¼/√(n·v²(1−α²)+α²)` at normal incidence, up to twice it at grazing
    /// views, whose lobe peaks off the mirror direction. 1 for a white
    /// Lambertian receiver.
    pub fn receiver_peak(lobe: vec4f) -> f32 {
        return lobe.x + specular_peak_factor(lobe) / (lobe.z * lobe.z);
    }

    /// `k_s` times the largest `V·n·l` over every light direction for a
    /// receiver with lobe `lobe`: `k_s · ½/(√(n·v²(1−α²)+α²) + n·v)`
    /// ([`receiver_peak`]).
    pub fn specular_peak_factor(lobe: vec4f) -> f32 {
        return lobe.y * 0.5 / (smith_root(lobe.w, lobe.z) + max(lobe.w, 0.0));
    }

    /// Largest factor by which a receiver scales SLC's range² ([`range_scale`]).
    pub const RANGE_SCALE_MAX: f32 = 64.0;

    /// The largest factor `s` by which a receiver with lobe `lobe` scales a
    /// light's threshold and random range² (same ξ, so the estimate stays
    /// unbiased and the spheres stay one per light): `s = π·P`, the
    /// receiver's [`receiver_peak`], which keeps one light's roulette
    /// deviation at the receiver within ε (it is `π·P·ε` unscaled, see
    /// `crate::range`); at least 1, at most [`RANGE_SCALE_MAX`] (a
    /// sharper lobe keeps `π·P/64` times ε: its range grows 8× already);
    /// exactly 1 without a specular lobe. Each light gets the lobe's peak
    /// toward it, at most this (`crate::importance::range_scale_toward`).
    pub fn range_scale(lobe: vec4f) -> f32 {
        if lobe.y <= 0.0 {
            return 1.0;
        }
        return clamp(receiver_peak(lobe), 1.0, RANGE_SCALE_MAX);
    }

    /// What a receiver with lobe `lobe` ([`receiver_lobe`]) needs to scale
    /// each light's range² by the lobe's peak *toward that light*
    /// (`crate::importance::range_scale_toward`): `(k_d, c_s, α², √s_max)`
    /// with `c_s` the [`specular_peak_factor`], so that `π·f·cos` on a
    /// direction whose half vector makes the angle `θ_h` with `n` is at most
    /// about `k_d + c_s·α²/(cos²θ_h (α²−1) + 1)²` (the GGX `π·D` times the
    /// specular lobe's largest factor, as [`receiver_peak`] at `θ_h = 0`), and
    /// `s_max` is [`range_scale`]. `(1, 0, 1, 1)` without a specular lobe:
    /// every light's scale is then 1.
    pub fn range_lobe(lobe: vec4f) -> vec4f {
        if lobe.y <= 0.0 {
            return vec4f(1.0, 0.0, 1.0, 1.0);
        }
        return vec4f(lobe.x, specular_peak_factor(lobe), lobe.z * lobe.z, sqrt(range_scale(lobe)));
    }

    /// The view direction `v` mirrored about the unit normal `n`: `2(n·v)n − v`.
    pub fn mirror_dir(n: vec3f, v: vec3f) -> vec3f {
        return n * (2.0 * dot(n, v)) - v;
    }

    /// `k` of the bounded VNDF (Eto & Tokuyoshi 2023, eq. 5) for a local
    /// view `wi` (`z` along the normal, `wi.z > 0`): the spherical cap of
    /// Heitz 2018's VNDF sampling shrinks to `z ≥ −k·wi_std.z`, which drops
    /// only microfacets that would reflect below the horizon.
    pub fn bounded_vndf_k(wi: vec3f, alpha: f32) -> f32 {
        let a: f32 = saturate(alpha);
        let s: f32 = 1.0 + sqrt(wi.x * wi.x + wi.y * wi.y);
        let a2: f32 = a * a;
        let s2: f32 = s * s;
        return (1.0 - a2) * s2 / (s2 + a2 * wi.z * wi.z);
    }

    /// Reflected local direction sampled from the GGX lobe of `α` seen from
    /// the local view `wi` (`z` along the normal) by the bounded VNDF
    /// (Eto & Tokuyoshi 2023, Listing 1) for `u1, u2 ∈ [0, 1)`; it may lie
    /// below the horizon (the sample is then lost). Its pdf is
    /// [`ggx_vndf_pdf`].
    pub fn ggx_vndf_sample(wi: vec3f, alpha: f32, u1: f32, u2: f32) -> vec3f {
        let wi_std: vec3f = normalize(vec3f(wi.x * alpha, wi.y * alpha, wi.z));
        let b: f32 = select(wi_std.z, bounded_vndf_k(wi, alpha) * wi_std.z, wi.z > 0.0);
        let phi: f32 = 6.2831855 * u1;
        let z: f32 = (1.0 - u2) * (1.0 + b) - b;
        let sin_t: f32 = sqrt(saturate(1.0 - z * z));
        let m_std: vec3f = wi_std + vec3f(sin_t * cos(phi), sin_t * sin(phi), z);
        let m: vec3f = normalize(vec3f(m_std.x * alpha, m_std.y * alpha, m_std.z));
        return m * (2.0 * dot(wi, m)) - wi;
    }

    /// Solid-angle pdf of [`ggx_vndf_sample`] drawing the local direction
    /// `wo` from `wi`: `D(m) / (2 (k·wi.z + t))` with `m` the half vector
    /// and `t = |(α wi.x, α wi.y, wi.z)|` (Eto & Tokuyoshi 2023, eq. 6; with
    /// `k = 1` it is Heitz 2018's `D_wi(m)/(4 wi·m)`); 0 for `wo` below the
    /// horizon or `wi` not above it.
    pub fn ggx_vndf_pdf(wi: vec3f, wo: vec3f, alpha: f32) -> f32 {
        if wi.z <= 0.0 || wo.z <= 0.0 {
            return 0.0;
        }
        let hs: vec3f = wi + wo;
        let m: vec3f = hs / sqrt(dot(hs, hs));
        let d: f32 = ggx_d(m.z, m.x * m.x + m.y * m.y, alpha);
        let t: f32 = sqrt(alpha * alpha * (wi.x * wi.x + wi.y * wi.y) + wi.z * wi.z);
        return d / (2.0 * (bounded_vndf_k(wi, alpha) * wi.z + t));
    }

    /// A direction sampled from the BSDF at unit shading normal `n` seen
    /// along unit `v` (toward the viewer), for `u1, u2 ∈ [0, 1)`: the
    /// specular lobe ([`ggx_vndf_sample`]) when `u1 < p_spec`, else the
    /// cosine lobe ([`cosine_direction`]); `u1` is rescaled to `[0, 1)`
    /// within the chosen lobe, so with `p_spec = 0` the draw is the cosine
    /// sample of `(u1, u2)` itself. Its pdf is [`bsdf_pdf`]; it may lie
    /// below the surface (always, for a specular draw seen from below `n`:
    /// take `p_spec` from [`specular_probability`], which is 0 there).
    pub fn bsdf_sample(n: vec3f, v: vec3f, alpha: f32, p_spec: f32, u1: f32, u2: f32) -> vec3f {
        if u1 < p_spec {
            if dot(n, v) <= 0.0 {
                return -n;
            }
            let wo: vec3f = ggx_vndf_sample(onb_to_local(n, v), alpha, u1 / p_spec, u2);
            return normalize(onb_to_world(n, wo));
        }
        return cosine_direction(n, (u1 - p_spec) / (1.0 - p_spec), u2);
    }

    /// Solid-angle pdf of [`bsdf_sample`] drawing unit `l`: `p_spec ·
    /// pdf_vndf + (1 − p_spec) · cos/π`; the cosine pdf alone when
    /// `p_spec = 0`.
    pub fn bsdf_pdf(n: vec3f, v: vec3f, l: vec3f, alpha: f32, p_spec: f32) -> f32 {
        let pd: f32 = cosine_pdf(dot(n, l));
        if p_spec <= 0.0 {
            return pd;
        }
        return p_spec * ggx_vndf_pdf(onb_to_local(n, v), onb_to_local(n, l), alpha) + (1.0 - p_spec) * pd;
    }

    /// Bevy's GGX `α` of a perceptual roughness (`perceptualRoughnessToRoughness`
    /// in bevy_pbr 0.20's `pbr_lighting.wesl`): clamped to `[0.089, 1]`, squared.
    pub fn bevy_alpha(perceptual: f32) -> f32 {
        let r: f32 = clamp(perceptual, 0.089, 1.0);
        return r * r;
    }

    /// Bevy's dielectric `F0 = 0.16·reflectance²` (`calculate_F0_dielectric`
    /// in bevy_pbr 0.20's `pbr_functions.wesl`; 0.04 at its default
    /// reflectance 0.5).
    pub fn bevy_f0(reflectance: f32) -> f32 {
        return 0.16 * reflectance * reflectance;
    }

    /// `F_ab.x + F_ab.y` of Bevy's analytic split-sum environment BRDF
    /// (`F_AB` without `DFG_LUT`: Karis 2014's polynomial fit, "Physically
    /// Based Shading on Mobile") at perceptual roughness `r` and `n·v`: the
    /// specular lobe's directional albedo for `F0 = 1`, which Bevy's
    /// multiple-scattering compensation divides by.
    pub fn bevy_dfg(r: f32, n_v: f32) -> f32 {
        let rx: f32 = 1.0 - r;
        let a004: f32 = min(rx * rx, exp2(-9.28 * n_v)) * rx + (0.0425 - 0.0275 * r);
        let x: f32 = max(1.04 - 0.572 * r - 1.04 * a004, 0.00005);
        let y: f32 = max(0.022 * r - 0.04 + 1.04 * a004, 0.00005);
        return x + y;
    }

    /// Bevy `StandardMaterial`'s BRDF `f(v, l)` for a point light of
    /// radius 0 (bevy_pbr 0.20's `point_light` in
    /// `pbr_lighting.wesl`, the Filament model): Burley's diffuse
    /// `(1 − m)·b/π · S(n·l) S(n·v)` with `S(c) = 1 + (F90 − 1)(1 − c)⁵`,
    /// `F90 = ½ + 2α(l·h)²`, plus GGX `D·V·F` with Bevy's Fresnel
    /// (`F0 = mix(0.16·reflectance², b, m)`, `F90 = saturate(50·0.33·ΣF0)`)
    /// and its multiple-scattering compensation `1 + F0(1/dfg − 1)`
    /// ([`bevy_dfg`]). `r` is the perceptual roughness as Bevy stores it
    /// (clamped here as Bevy does), `n·v` is clamped to `10⁻⁴` as Bevy does;
    /// 0 for `l` below `n`. Bevy's deferred renderer reads `dfg` from a
    /// lookup table instead of the fit (a difference of well under 1% of
    /// the specular lobe at `F0 = 0.04`).
    pub fn bevy_brdf(base: vec3f, metallic: f32, r: f32, reflectance: f32, n: vec3f, v: vec3f, l: vec3f) -> vec3f {
        let n_l: f32 = saturate(dot(n, l));
        if n_l <= 0.0 {
            return vec3f(0.0, 0.0, 0.0);
        }
        let alpha: f32 = bevy_alpha(r);
        let n_v: f32 = max(dot(n, v), 0.0001);
        let h: vec3f = normalize(l + v);
        let n_h: f32 = saturate(dot(n, h));
        let l_h: f32 = saturate(dot(l, h));
        let f90_d: f32 = 0.5 + 2.0 * alpha * l_h * l_h;
        let burley: f32 = fresnel_schlick(vec3f(1.0, 1.0, 1.0), f90_d, n_l).x * fresnel_schlick(vec3f(1.0, 1.0, 1.0), f90_d, n_v).x * INV_PI;
        let f0_d: f32 = bevy_f0(reflectance);
        let f0: vec3f = vec3f(f0_d, f0_d, f0_d) * (1.0 - metallic) + base * metallic;
        let f90: f32 = saturate((f0.x + f0.y + f0.z) * 16.5);
        let d: f32 = ggx_d(n_h, 1.0 - n_h * n_h, alpha);
        let vis: f32 = smith_visibility(n_l, n_v, alpha);
        let comp: vec3f = vec3f(1.0, 1.0, 1.0) + f0 * (1.0 / bevy_dfg(r, n_v) - 1.0);
        let spec: vec3f = fresnel_schlick(f0, f90, l_h) * comp * (d * vis);
        return base * ((1.0 - metallic) * burley) + spec;
    }
}

#[cfg(test)]
mod tests;
