//! The light BVH of the `lightbvh` baseline (Conty Estevez & Kulla,
//! "Importance Sampling of Many Lights with Adaptive Tree Splitting", HPG
//! 2018; pbrt-v4's `BVHLightSampler`, Pharr, Jakob & Humphreys, *PBR* 4th
//! ed., §12.6.3), the peer a user would pick instead of stochastic light
//! culling: built here, sampled on both backends by slc-core's
//! [`light_bvh`](slc_core::light_bvh) (the GPU reads the same nodes).
//!
//! Every node bounds its lights by a [`LightBounds`]: an AABB, the power
//! `φ`, and an orientation cone `(w, θ_o)` of emitter normals plus the
//! emission spread `θ_e`. A node ([`GpuLightBvhNode`]) holds them as the
//! [`LightCone`] fields that slc-core's importance reads: the AABB's bounding
//! sphere for interior nodes, the light's own (tighter) cone for leaves.
//! Built top-down by the surface-area-orientation heuristic over 12 buckets
//! per axis, one light per leaf, in preorder.

use glam::Vec3;
use slc_core::importance::Receiver;
#[cfg(doc)]
use slc_core::importance::light_importance;
use slc_core::importance::{LightCone, safe_sqrt};
use slc_core::light::Light;
use slc_core::light_bvh::walk::{light_bvh_pmf, light_bvh_sample};
use slc_core::light_bvh::{GpuLightBvhNode, LIGHT_BVH_LEAF};
use std::f32::consts::PI;

/// Bounds of a set of lights (pbrt-v4 `LightBounds`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightBounds {
    /// AABB corner.
    pub min: Vec3,
    /// AABB corner.
    pub max: Vec3,
    /// Emitted power (max channel).
    pub phi: f32,
    /// Axis of the cone of emitter normals.
    pub w: Vec3,
    /// Cosine of the normal cone's half-angle `θ_o`.
    pub cos_o: f32,
    /// Cosine of the emission spread `θ_e` around each normal.
    pub cos_e: f32,
}

impl LightBounds {
    /// Bounds of one light whose importance cone is `c`
    /// ([`LightCone::of_light`] of its [`Light::power`]), as pbrt-v4's
    /// `Light::Bounds()`: a triangle's AABB and normal (`θ_o = 0`,
    /// `θ_e = π/2`, `φ = π A L`); a point light over the whole sphere
    /// (`θ_o = π`, `φ = 4π I`), an IES light too with its emitted power
    /// (pbrt-v4's goniometric `φ = 4π I · mean(image)`); a spot light
    /// around its axis (`θ_o = θ_inner`, `θ_e = θ_outer − θ_inner`) with
    /// `φ = 4π I₀`, the power of a point light of its peak intensity
    /// ([`bvh_cone`]), so that inside its beam it weighs as much as a point
    /// light of that intensity. `φ` is the max channel.
    pub fn of_light(l: &Light, c: &LightCone) -> LightBounds {
        let (min, max) = match l {
            Light::Triangle(t) => {
                let [a, b, c] = t.vertices();
                (a.min(b).min(c), a.max(b).max(c))
            }
            _ => (c.center, c.center),
        };
        let c = bvh_cone(l, c);
        LightBounds { min, max, phi: c.phi, w: c.axis, cos_o: c.cos_o, cos_e: c.cos_e }
    }

    fn centroid(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }

    /// The bounds as [`light_importance`] reads them: the box's bounding
    /// sphere with the power and cones (pbrt-v4 `LightBounds::Importance`
    /// clamps the distance with `max(d², |diagonal|/2)`, a squared distance
    /// against a length; slc clamps with the squared radius). The receiver
    /// is one-sided, where pbrt-v4 takes `|cos θ_i|` for transmissive
    /// surfaces: slc's surfaces only reflect, so the baseline gets that
    /// advantage too.
    pub fn cone(&self) -> LightCone {
        LightCone {
            center: self.centroid(),
            radius: 0.5 * (self.max - self.min).length(),
            phi: self.phi,
            axis: self.w,
            cos_o: self.cos_o,
            cos_e: self.cos_e,
        }
    }

    /// Union: AABB union, summed power, the smallest cone around both
    /// normal cones (pbrt-v4 `Union(DirectionCone, DirectionCone)`), the
    /// wider emission spread.
    pub fn union(&self, o: &LightBounds) -> LightBounds {
        if self.phi == 0.0 {
            return *o;
        }
        if o.phi == 0.0 {
            return *self;
        }
        let (w, cos_o) = cone_union(self.w, self.cos_o, o.w, o.cos_o);
        LightBounds {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
            phi: self.phi + o.phi,
            w,
            cos_o,
            cos_e: self.cos_e.min(o.cos_e),
        }
    }

    /// pbrt-v4's `EvaluateCost`: `φ · M_Ω · K_r · area`, with the
    /// orientation measure `M_Ω` of the cone and `K_r` penalising thin
    /// splits along axis `dim` of the parent box.
    fn cost(&self, parent_diag: Vec3, dim: usize) -> f32 {
        let theta_o = self.cos_o.clamp(-1.0, 1.0).acos();
        let theta_e = self.cos_e.clamp(-1.0, 1.0).acos();
        let theta_w = (theta_o + theta_e).min(PI);
        let sin_o = safe_sqrt(1.0 - self.cos_o * self.cos_o);
        let m_omega = 2.0 * PI * (1.0 - self.cos_o)
            + PI / 2.0
                * (2.0 * theta_w * sin_o - (theta_o - 2.0 * theta_w).cos() - 2.0 * theta_o * sin_o
                    + self.cos_o);
        let kr = parent_diag.max_element() / parent_diag[dim].max(f32::MIN_POSITIVE);
        let d = self.max - self.min;
        let area = 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
        self.phi * m_omega * kr * area
    }
}

/// The importance cone the light BVH gives light `l` of cone `c`
/// ([`LightCone::of_light`], which `slc-weighted` reads): `c`, but a spot
/// light's `φ` is pbrt-v4's `4π I₀` (its peak intensity over the whole
/// sphere) instead of its emitted power.
pub fn bvh_cone(l: &Light, c: &LightCone) -> LightCone {
    match l {
        Light::Spot(s) => {
            LightCone { phi: 4.0 * PI * l.intensity(s.direction()).max_element(), ..*c }
        }
        _ => *c,
    }
}

/// Smallest cone containing cones `(a, cos_a)` and `(b, cos_b)`.
fn cone_union(a: Vec3, cos_a: f32, b: Vec3, cos_b: f32) -> (Vec3, f32) {
    let theta_a = cos_a.clamp(-1.0, 1.0).acos();
    let theta_b = cos_b.clamp(-1.0, 1.0).acos();
    let theta_d = a.dot(b).clamp(-1.0, 1.0).acos();
    if (theta_d + theta_b).min(PI) <= theta_a {
        return (a, cos_a);
    }
    if (theta_d + theta_a).min(PI) <= theta_b {
        return (b, cos_b);
    }
    let theta_o = 0.5 * (theta_a + theta_d + theta_b);
    if theta_o >= PI {
        return (Vec3::Z, -1.0);
    }
    let axis = a.cross(b);
    if axis.length_squared() == 0.0 {
        return (Vec3::Z, -1.0);
    }
    let w = glam::Quat::from_axis_angle(axis.normalize(), theta_o - theta_a) * a;
    (w.normalize(), theta_o.cos())
}

/// A binary BVH over lights, one light per leaf, in preorder
/// ([`slc_core::light_bvh`] samples it).
#[derive(Clone, Debug)]
pub struct LightBvh {
    nodes: Vec<GpuLightBvhNode>,
    leaf_of_light: Vec<u32>,
}

const BUCKETS: usize = 12;

impl LightBvh {
    /// Builds the tree over `lights` with their importance `cones`
    /// ([`crate::lights::LightSet::cones`]) top-down by the
    /// surface-area-orientation heuristic; an explicit stack keeps deep
    /// trees off the call stack. Lights of zero power are left out (they
    /// are never sampled and their pmf is 0); with none left the tree is
    /// empty.
    pub fn new(lights: &[Light], cones: &[LightCone]) -> LightBvh {
        let mut items: Vec<(u32, LightBounds)> = lights
            .iter()
            .zip(cones)
            .enumerate()
            .map(|(i, (l, c))| (i as u32, LightBounds::of_light(l, c)))
            .filter(|(_, b)| b.phi > 0.0)
            .collect();
        let mut nodes: Vec<GpuLightBvhNode> = Vec::with_capacity(2 * items.len());
        let mut leaf_of_light = vec![LIGHT_BVH_LEAF; lights.len()];
        // (start, end, parent node, whether this is the parent's second child)
        let mut stack = vec![(0usize, items.len(), usize::MAX, false)];
        while let Some((start, end, par, second)) = stack.pop() {
            if start == end {
                continue;
            }
            let me = nodes.len() as u32;
            if second {
                nodes[par].second = me;
            }
            let set = &mut items[start..end];
            let bounds = set.iter().skip(1).fold(set[0].1, |acc, (_, b)| acc.union(b));
            if set.len() == 1 {
                let light = set[0].0;
                leaf_of_light[light as usize] = me;
                nodes.push(GpuLightBvhNode::new(
                    &bvh_cone(&lights[light as usize], &cones[light as usize]),
                    LIGHT_BVH_LEAF,
                    light,
                ));
                continue;
            }
            let mid = start + split(set, &bounds);
            nodes.push(GpuLightBvhNode::new(&bounds.cone(), LIGHT_BVH_LEAF, LIGHT_BVH_LEAF));
            // Second child pushed first, so the first child is next in preorder.
            stack.push((mid, end, me as usize, true));
            stack.push((start, mid, me as usize, false));
        }
        LightBvh { nodes, leaf_of_light }
    }

    /// The nodes, in preorder (empty when no light has power).
    pub fn nodes(&self) -> &[GpuLightBvhNode] {
        &self.nodes
    }

    /// Each light's leaf ([`LIGHT_BVH_LEAF`] for a light left out).
    pub fn leaf_of_light(&self) -> &[u32] {
        &self.leaf_of_light
    }

    /// Samples one light for the receiver `rc` and uniform `u ∈ [0, 1)`:
    /// `(light, pmf)`, or `None` where every light has zero importance
    /// ([`light_bvh_sample`], the walk the GPU takes).
    pub fn sample(&self, rc: &Receiver, u: f32) -> Option<(usize, f32)> {
        let pick = light_bvh_sample(&self.nodes, rc.p, rc.n, rc.r, rc.lobe, u);
        (pick.pmf > 0.0).then_some((pick.light as usize, pick.pmf))
    }

    /// Probability that [`LightBvh::sample`] for `rc` picks `light`
    /// ([`light_bvh_pmf`]).
    pub fn pmf(&self, rc: &Receiver, light: usize) -> f32 {
        self.leaf_of_light
            .get(light)
            .map_or(0.0, |&leaf| light_bvh_pmf(&self.nodes, leaf, rc.p, rc.n, rc.r, rc.lobe))
    }
}

/// Reorders `set` and returns the split index (in `1..len`): the cheapest
/// bucket boundary over the three axes, or the middle when no axis splits.
fn split(set: &mut [(u32, LightBounds)], bounds: &LightBounds) -> usize {
    let (cmin, cmax) = set.iter().fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), (_, b)| {
        (lo.min(b.centroid()), hi.max(b.centroid()))
    });
    let diag = bounds.max - bounds.min;
    let bucket = |c: Vec3, dim: usize| -> usize {
        let t = (c[dim] - cmin[dim]) / (cmax[dim] - cmin[dim]);
        ((BUCKETS as f32 * t) as usize).min(BUCKETS - 1)
    };
    let mut best: Option<(f32, usize, usize)> = None;
    for dim in 0..3 {
        if !(cmax[dim] > cmin[dim]) {
            continue;
        }
        let mut b: [Option<LightBounds>; BUCKETS] = [None; BUCKETS];
        for (_, lb) in set.iter() {
            let k = bucket(lb.centroid(), dim);
            b[k] = Some(b[k].map_or(*lb, |x| x.union(lb)));
        }
        let join = |r: &[Option<LightBounds>]| {
            r.iter()
                .flatten()
                .fold(None, |acc: Option<LightBounds>, x| Some(acc.map_or(*x, |a| a.union(x))))
        };
        for i in 0..BUCKETS - 1 {
            let (Some(lo), Some(hi)) = (join(&b[..=i]), join(&b[i + 1..])) else { continue };
            let cost = lo.cost(diag, dim) + hi.cost(diag, dim);
            if cost.is_finite() && best.is_none_or(|(c, _, _)| cost < c) {
                best = Some((cost, dim, i));
            }
        }
    }
    let half = set.len() / 2;
    let Some((_, dim, i)) = best else { return half };
    let mut mid = 0;
    for j in 0..set.len() {
        if bucket(set[j].1.centroid(), dim) <= i {
            set.swap(j, mid);
            mid += 1;
        }
    }
    if mid == 0 || mid == set.len() { half } else { mid }
}

#[cfg(test)]
mod tests {
    use super::*;
    use slc_core::light::{PointLight, SpotLight, TriangleLight};

    fn cones(ls: &[Light]) -> Vec<LightCone> {
        ls.iter().map(|l| LightCone::of_light(l, l.power())).collect()
    }

    fn lights() -> Vec<Light> {
        let mut v = Vec::new();
        let mut s = 12345u32;
        let mut r = || {
            s = s.wrapping_mul(1664525).wrapping_add(1013904223);
            (s >> 8) as f32 / (1u32 << 24) as f32
        };
        for _ in 0..200 {
            let a = Vec3::new(r(), r(), r()) * 4.0;
            let t = TriangleLight::new(
                a,
                a + Vec3::new(r(), r(), 0.1) * 0.3,
                a + Vec3::new(0.1, r(), r()) * 0.3,
                Vec3::splat(1.0 + 5.0 * r()),
            );
            v.push(Light::Triangle(t.unwrap()));
        }
        for _ in 0..20 {
            v.push(Light::Point(
                PointLight::new(Vec3::new(r(), r(), r()) * 4.0, Vec3::splat(r())).unwrap(),
            ));
        }
        v.push(Light::Spot(
            SpotLight::new(Vec3::splat(2.0), Vec3::NEG_Y, Vec3::ONE, 0.3, 0.6).unwrap(),
        ));
        v
    }

    /// The pmf of every light equals its sampling frequency under
    /// stratified `u`; Σ pmf ≤ 1 with the rest the probability that
    /// sampling fails (a node whose children both have zero importance,
    /// which only holds lights that cannot reach the point); and every light
    /// that does reach the point has pmf > 0 (the bounds are conservative).
    /// For Lambertian receivers and for a glossy metal's, whose lobe weighs
    /// the nodes.
    #[test]
    fn pmf_matches_sampling_and_covers_every_contributing_light() {
        let ls = lights();
        let bvh = LightBvh::new(&ls, &cones(&ls));
        let metal = crate::scene::Material::gltf(Vec3::splat(0.9), 1.0, 0.3);
        let view = Vec3::new(0.3, 0.9, 0.2).normalize();
        for rc in [
            Receiver::lambertian(Vec3::splat(2.0), Vec3::Y),
            Receiver::lambertian(Vec3::new(-1.0, 0.5, 3.0), Vec3::X),
            Receiver::lambertian(Vec3::splat(2.0), Vec3::ZERO),
            Receiver::lambertian(Vec3::new(2.0, 5.0, 2.0), Vec3::NEG_Y),
            metal.receiver(Vec3::splat(2.0), Vec3::Y, view),
            metal.receiver(Vec3::new(2.0, 5.0, 2.0), Vec3::NEG_Y, -view),
        ] {
            let (p, n) = (rc.p, rc.n);
            let pmfs: Vec<f32> = (0..ls.len()).map(|l| bvh.pmf(&rc, l)).collect();
            let total: f64 = pmfs.iter().map(|&x| x as f64).sum();
            assert!(total <= 1.0 + 1e-4 && total > 0.1, "Σ pmf = {total}");
            let m = 200_000;
            let mut count = vec![0u32; ls.len()];
            let mut failed = 0;
            for k in 0..m {
                let Some((l, pmf)) = bvh.sample(&rc, (k as f32 + 0.5) / m as f32) else {
                    failed += 1;
                    continue;
                };
                assert!(
                    (pmf - pmfs[l]).abs() <= 1e-5 * pmfs[l].max(1e-3),
                    "sample pmf {pmf} vs pmf() {}",
                    pmfs[l]
                );
                count[l] += 1;
            }
            let tol = 2.0 * 64.0 / m as f32 + 1e-4;
            for l in 0..ls.len() {
                let f = count[l] as f32 / m as f32;
                assert!((f - pmfs[l]).abs() < tol, "light {l}: {f} vs {}", pmfs[l]);
                let (c, d2) = ls[l].contribution_at(p);
                let w = (ls[l].bound().center - p).normalize();
                let reaches =
                    c.max_element() > 0.0 && d2 > 0.0 && (n == Vec3::ZERO || n.dot(w) > 0.0);
                if reaches {
                    assert!(pmfs[l] > 0.0, "light {l} reaches {p} but has pmf 0");
                }
            }
            assert!(
                (failed as f64 / m as f64 - (1.0 - total)).abs() < 1e-3,
                "failed {failed} vs 1 − Σ = {}",
                1.0 - total
            );
        }
    }

    #[test]
    fn importance_prefers_near_and_facing_lights() {
        let t = |z: f32, up: bool| {
            let (b, c) = if up { (Vec3::X, Vec3::Y) } else { (Vec3::Y, Vec3::X) };
            let l = Light::Triangle(
                TriangleLight::new(
                    Vec3::new(0.0, 0.0, z),
                    Vec3::new(0.0, 0.0, z) + b * 0.1,
                    Vec3::new(0.0, 0.0, z) + c * 0.1,
                    Vec3::ONE,
                )
                .unwrap(),
            );
            LightBounds::of_light(&l, &LightCone::of_light(&l, l.power()))
        };
        let p = Vec3::new(0.05, 0.05, 5.0);
        assert!(
            t(1.0, true).cone().importance(p, Vec3::NEG_Z)
                < t(4.0, true).cone().importance(p, Vec3::NEG_Z)
        );
        // Facing away (normal −z, p above): zero importance.
        assert_eq!(t(1.0, false).cone().importance(p, Vec3::NEG_Z), 0.0);
    }

    /// A spot light and a point light of the same peak intensity, at the
    /// same distance from a point inside the beam, light it alike and are
    /// sampled alike (pbrt-v4's spot `φ = 4π I₀`); the spot's emitted power
    /// (a 0.2–0.3-radian beam: 1.6% of the point light's) made it 62 times
    /// less likely.
    #[test]
    fn spot_weighs_as_a_point_light_of_its_peak_intensity_in_its_beam() {
        let ls = vec![
            Light::Spot(
                SpotLight::new(Vec3::new(0.0, 2.0, 0.0), Vec3::NEG_Y, Vec3::ONE, 0.2, 0.3).unwrap(),
            ),
            Light::Point(PointLight::new(Vec3::new(0.0, -2.0, 0.0), Vec3::ONE).unwrap()),
        ];
        let bvh = LightBvh::new(&ls, &cones(&ls));
        let rc = Receiver::lambertian(Vec3::ZERO, Vec3::ZERO);
        let (p0, p1) = (bvh.pmf(&rc, 0), bvh.pmf(&rc, 1));
        assert!((p0 - p1).abs() < 1e-5 && (p0 + p1 - 1.0).abs() < 1e-5, "{p0} {p1}");
    }

    #[test]
    fn cone_union_contains_both_cones() {
        let (w, c) = cone_union(Vec3::X, 1.0, Vec3::Y, 1.0);
        assert!((c - (PI / 4.0).cos()).abs() < 1e-5);
        assert!(w.dot(Vec3::X) >= c - 1e-5 && w.dot(Vec3::Y) >= c - 1e-5);
        assert_eq!(cone_union(Vec3::X, 1.0, Vec3::NEG_X, 1.0).1, -1.0);
    }

    #[test]
    fn degenerate_sets_build_balanced_trees() {
        // 4,096 coincident point lights: no axis splits, so halves.
        let ls: Vec<Light> = (0..4096)
            .map(|_| Light::Point(PointLight::new(Vec3::ONE, Vec3::ONE).unwrap()))
            .collect();
        let bvh = LightBvh::new(&ls, &cones(&ls));
        let total: f32 =
            (0..ls.len()).map(|l| bvh.pmf(&Receiver::lambertian(Vec3::ZERO, Vec3::ZERO), l)).sum();
        assert!((total - 1.0).abs() < 1e-3);
        assert!(
            (bvh.pmf(&Receiver::lambertian(Vec3::ZERO, Vec3::ZERO), 7) - 1.0 / 4096.0).abs() < 1e-7
        );
    }
}
