//! Spheres and boxes: light range spheres, their bounds and the culling
//! tests (talk: "Area light bound", "Build Bounding Sphere Hierarchy").
//!
//! Containment is *conservative in f32*: every constructor here returns a
//! sphere that contains its inputs when tested with [`sphere_contains_point`]
//! in f32, not only in exact arithmetic (the result radius is grown by a few
//! ulps of `|centre| + radius`). Culling relies on that: a light whose sphere
//! really contains a point is never culled by a parent's rounding.

use crate::wgsl::*;
use alloc::vec::Vec;
use glam::Vec3;

crate::shared! {
    /// `|x − c|² ≤ r²`: the sphere (c, r) contains x (boundary included;
    /// `r = ∞` contains everything finite).
    pub fn sphere_contains_point(c: vec3f, r: f32, x: vec3f) -> bool {
        let v: vec3f = x - c;
        return dot(v, v) <= r * r;
    }

    /// Two spheres overlap: `|c₁ − c₂|² ≤ (r₁ + r₂)²`.
    pub fn sphere_overlaps_sphere(c1: vec3f, r1: f32, c2: vec3f, r2: f32) -> bool {
        let v: vec3f = c2 - c1;
        let r: f32 = r1 + r2;
        return dot(v, v) <= r * r;
    }

    /// 4 · 2⁻²³: relative padding that makes computed bounds contain their
    /// inputs in f32.
    pub const SPHERE_PAD: f32 = 0.000000476837158203125;

    /// Largest finite f32: the radius of a sphere that holds everything
    /// (its square overflows to ∞ in the containment tests).
    pub const SPHERE_HUGE: f32 = 340282346638528859811704183484516925440.0;

    /// Absolute floor of the padding, 10⁻¹⁸: squares of lengths below
    /// ~10⁻¹⁹ are subnormal or flush to 0 (on GPUs), so relative padding
    /// alone lets a parent miss a point its child holds (fuzz/bsh_vs_brute
    /// found lights 10⁻²³ apart). Its square, 10⁻³⁶, is a normal f32.
    pub const SPHERE_PAD_ABS: f32 = 1e-18;

    /// Padding for a sphere of radius `r` at `c`: a few ulps of `|c|∞ + r`,
    /// and at least [`SPHERE_PAD_ABS`].
    pub fn sphere_pad(r: f32, c: vec3f) -> f32 {
        return (r + max(abs(c.x), max(abs(c.y), abs(c.z)))) * SPHERE_PAD + SPHERE_PAD_ABS;
    }

    /// The smallest sphere holding spheres (c₁, r₁) and (c₂, r₂), as
    /// `(centre, radius)`: radius `(d + r₁ + r₂)/2` on the line between the
    /// centres, or the containing sphere when one holds the other; padded to
    /// be conservative in f32 (unchanged only when nesting has a clear
    /// margin). Infinite radii give an infinite result.
    pub fn sphere_union(c1: vec3f, r1: f32, c2: vec3f, r2: f32) -> vec4f {
        let v: vec3f = c2 - c1;
        let d: f32 = sqrt(dot(v, v));
        if r1 >= d + r2 + sphere_pad(r1, c1) {
            return vec4f(c1.x, c1.y, c1.z, r1);
        }
        if r2 >= d + r1 + sphere_pad(r2, c2) {
            return vec4f(c2.x, c2.y, c2.z, r2);
        }
        // Centres ≳ 1e19 apart overflow d; radii near f32::MAX overflow the
        // sum: fall back to a sphere that holds everything (no NaN centre).
        if d >= SPHERE_HUGE || 0.5 * (d + r1 + r2) >= SPHERE_HUGE {
            return vec4f(c1.x, c1.y, c1.z, SPHERE_HUGE);
        }
        if abs(r1 - r2) >= d {
            if r1 >= r2 {
                let rn: f32 = max(r1, d + r2);
                return vec4f(c1.x, c1.y, c1.z, rn + sphere_pad(rn, c1));
            }
            let rm: f32 = max(r2, d + r1);
            return vec4f(c2.x, c2.y, c2.z, rm + sphere_pad(rm, c2));
        }
        let r0: f32 = 0.5 * (d + r1 + r2);
        let c: vec3f = c1 + v * ((r0 - r1) / d);
        let e1: vec3f = c - c1;
        let e2: vec3f = c - c2;
        let r: f32 = max(r0, max(sqrt(dot(e1, e1)) + r1, sqrt(dot(e2, e2)) + r2));
        return vec4f(c.x, c.y, c.z, r + sphere_pad(r, c));
    }

    /// A sphere overlaps an axis-aligned box (Arvo 1990): the squared distance
    /// from c to the box's closest point is at most r².
    pub fn sphere_overlaps_aabb(c: vec3f, r: f32, bmin: vec3f, bmax: vec3f) -> bool {
        let q: vec3f = clamp(c, bmin, bmax);
        let v: vec3f = q - c;
        return dot(v, v) <= r * r;
    }
}

/// Relative padding that makes computed bounds contain their inputs in f32.
const PAD: f32 = SPHERE_PAD;

/// A sphere with centre and radius (`radius` may be `+∞`).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Sphere {
    /// Centre.
    pub center: Vec3,
    /// Radius, `≥ 0`.
    pub radius: f32,
}

/// An axis-aligned box `[min, max]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Lower corner.
    pub min: Vec3,
    /// Upper corner.
    pub max: Vec3,
}

impl Aabb {
    /// The empty box (union identity).
    pub const EMPTY: Aabb =
        Aabb { min: Vec3::splat(f32::INFINITY), max: Vec3::splat(f32::NEG_INFINITY) };

    /// Grows the box to hold `p`.
    pub fn grow(self, p: Vec3) -> Aabb {
        Aabb { min: self.min.min(p), max: self.max.max(p) }
    }

    /// Smallest box holding every point.
    pub fn of_points(points: &[Vec3]) -> Aabb {
        points.iter().fold(Aabb::EMPTY, |b, &p| b.grow(p))
    }
}

impl Sphere {
    /// A sphere (no validation; see the light constructors for that).
    pub const fn new(center: Vec3, radius: f32) -> Self {
        Self { center, radius }
    }

    /// `false` for a sphere with a NaN centre or a negative or NaN radius:
    /// such a sphere is empty in every test below.
    pub fn is_valid(&self) -> bool {
        !self.center.is_nan() && self.radius >= 0.0
    }

    /// [`sphere_contains_point`] (false for a NaN point or an invalid sphere).
    pub fn contains(&self, x: Vec3) -> bool {
        self.is_valid() && sphere_contains_point(self.center, self.radius, x)
    }

    /// [`sphere_overlaps_sphere`] (false if either sphere is invalid).
    pub fn overlaps_sphere(&self, o: &Sphere) -> bool {
        self.is_valid()
            && o.is_valid()
            && sphere_overlaps_sphere(self.center, self.radius, o.center, o.radius)
    }

    /// [`sphere_overlaps_aabb`]; a box with a NaN corner overlaps nothing.
    pub fn overlaps_aabb(&self, b: &Aabb) -> bool {
        self.is_valid()
            && !b.min.is_nan()
            && !b.max.is_nan()
            && sphere_overlaps_aabb(self.center, self.radius, b.min, b.max)
    }

    /// Radius that makes `center` contain every point of `pts` in f32: the
    /// largest f32 distance, padded by a few ulps of `|c| + r`.
    fn covering(center: Vec3, radius: f32, pts: &[Vec3]) -> Self {
        let mut r = radius;
        for p in pts {
            r = r.max((*p - center).length());
        }
        Self { center, radius: r + sphere_pad(r, center) }
    }

    /// The exact minimal sphere of a triangle: the circumsphere when the
    /// triangle is acute, else the sphere on its longest edge. Degenerate
    /// triangles (repeated vertex, collinear) fall in the second case.
    pub fn of_triangle(a: Vec3, b: Vec3, c: Vec3) -> Self {
        let pts = [a, b, c];
        // An angle ≥ 90° at a vertex ⇒ the opposite edge is a diameter.
        for i in 0..3 {
            let (p, q, r) = (pts[i], pts[(i + 1) % 3], pts[(i + 2) % 3]);
            if (q - p).dot(r - p) <= 0.0 {
                return Self::covering((q + r) * 0.5, 0.5 * (q - r).length(), &pts);
            }
        }
        match circumcenter3(a, b, c) {
            Some(center) => Self::covering(center, 0.0, &pts),
            None => Self::of_points(&pts),
        }
    }

    /// The minimal sphere of a point set (Welzl 1991, iterative form, points
    /// visited in a fixed pseudo-random order: expected O(n)). Empty input
    /// gives a zero sphere at the origin.
    pub fn of_points(points: &[Vec3]) -> Self {
        if points.is_empty() {
            return Self::default();
        }
        let mut p: Vec<Vec3> = points.to_vec();
        // Deterministic shuffle (xorshift) so the expected running time holds.
        let mut s: u32 = 0x9E37_79B9;
        for i in (1..p.len()).rev() {
            s ^= s << 13;
            s ^= s >> 17;
            s ^= s << 5;
            p.swap(i, (s as usize) % (i + 1));
        }
        let inside = |s: &Sphere, x: Vec3| (x - s.center).length() <= s.radius * (1.0 + PAD);
        let mut s = Sphere::new(p[0], 0.0);
        for i in 1..p.len() {
            if inside(&s, p[i]) {
                continue;
            }
            s = Sphere::new(p[i], 0.0);
            for j in 0..i {
                if inside(&s, p[j]) {
                    continue;
                }
                s = sphere2(p[i], p[j]);
                for k in 0..j {
                    if inside(&s, p[k]) {
                        continue;
                    }
                    s = sphere3(p[i], p[j], p[k]);
                    for l in 0..k {
                        if inside(&s, p[l]) {
                            continue;
                        }
                        s = sphere4(p[i], p[j], p[k], p[l]);
                    }
                }
            }
        }
        Self::covering(s.center, s.radius, &p)
    }

    /// The smallest sphere containing both ([`sphere_union`]).
    pub fn union(&self, o: &Sphere) -> Sphere {
        let u = sphere_union(self.center, self.radius, o.center, o.radius);
        Sphere { center: Vec3::new(u.x, u.y, u.z), radius: u.w }
    }
}

fn sphere2(a: Vec3, b: Vec3) -> Sphere {
    Sphere::new((a + b) * 0.5, 0.5 * (a - b).length())
}

/// Centre of the circle through three points, `None` when (nearly) collinear.
fn circumcenter3(a: Vec3, b: Vec3, c: Vec3) -> Option<Vec3> {
    let (u, v) = (b - a, c - a);
    let n = u.cross(v);
    let n2 = n.length_squared();
    if !(n2 > f32::EPSILON * u.length_squared() * v.length_squared()) {
        return None;
    }
    Some(a + (n.cross(u) * v.length_squared() + v.cross(n) * u.length_squared()) / (2.0 * n2))
}

/// Smallest sphere with three points on its boundary (or, when collinear, the
/// sphere of the farthest pair).
fn sphere3(a: Vec3, b: Vec3, c: Vec3) -> Sphere {
    match circumcenter3(a, b, c) {
        Some(center) => Sphere::new(center, (a - center).length()),
        None => {
            let (ab, ac, bc) = (sphere2(a, b), sphere2(a, c), sphere2(b, c));
            [ab, ac, bc].into_iter().fold(ab, |m, s| if s.radius > m.radius { s } else { m })
        }
    }
}

/// Sphere through four points; when they are (nearly) coplanar, the smallest
/// three-point sphere that holds the fourth.
fn sphere4(a: Vec3, b: Vec3, c: Vec3, d: Vec3) -> Sphere {
    let (u, v, w) = (b - a, c - a, d - a);
    let m = glam::Mat3::from_cols(u, v, w).transpose();
    let det = m.determinant();
    let scale = u.length() * v.length() * w.length();
    if det.abs() > 1e-6 * scale {
        let rhs = Vec3::new(u.length_squared(), v.length_squared(), w.length_squared()) * 0.5;
        let x = m.inverse() * rhs;
        let center = a + x;
        return Sphere::new(center, (a - center).length());
    }
    let pts = [a, b, c, d];
    let mut best: Option<Sphere> = None;
    for skip in 0..4 {
        let t: Vec<Vec3> = (0..4).filter(|&i| i != skip).map(|i| pts[i]).collect();
        let s = sphere3(t[0], t[1], t[2]);
        if (pts[skip] - s.center).length() <= s.radius * (1.0 + PAD)
            && best.is_none_or(|b| s.radius < b.radius)
        {
            best = Some(s);
        }
    }
    best.unwrap_or_else(|| {
        let c = (a + b + c + d) * 0.25;
        Sphere::covering(c, 0.0, &pts)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_acute_is_circumsphere() {
        let (a, b, c) =
            (Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 0.0, 1.0));
        let s = Sphere::of_triangle(a, b, c);
        let third = Vec3::splat(1.0 / 3.0);
        assert!((s.center - third).length() < 1e-6);
        assert!((s.radius - (a - third).length()).abs() < 1e-5);
        assert!(s.contains(a) && s.contains(b) && s.contains(c));
    }

    #[test]
    fn triangle_obtuse_is_longest_edge() {
        let s = Sphere::of_triangle(Vec3::ZERO, Vec3::new(4.0, 0.0, 0.0), Vec3::new(2.0, 0.5, 0.0));
        assert!((s.center - Vec3::new(2.0, 0.0, 0.0)).length() < 1e-6);
        assert!((s.radius - 2.0).abs() < 1e-5);
    }

    #[test]
    fn degenerate_triangles() {
        // Repeated vertex, collinear, single point.
        let s = Sphere::of_triangle(Vec3::ZERO, Vec3::ZERO, Vec3::X * 2.0);
        assert!((s.center - Vec3::X).length() < 1e-6 && (s.radius - 1.0).abs() < 1e-5);
        let s = Sphere::of_triangle(Vec3::ZERO, Vec3::X, Vec3::X * 3.0);
        assert!((s.center - Vec3::X * 1.5).length() < 1e-6 && (s.radius - 1.5).abs() < 1e-5);
        let s = Sphere::of_triangle(Vec3::ONE, Vec3::ONE, Vec3::ONE);
        assert!(s.radius < 1e-5 && s.contains(Vec3::ONE));
    }

    #[test]
    fn union_hand_values_and_containment() {
        let a = Sphere::new(Vec3::ZERO, 1.0);
        let b = Sphere::new(Vec3::new(4.0, 0.0, 0.0), 1.0);
        let u = a.union(&b);
        assert!((u.center - Vec3::new(2.0, 0.0, 0.0)).length() < 1e-6);
        assert!((u.radius - 3.0).abs() < 1e-5);
        let inner = Sphere::new(Vec3::new(0.5, 0.0, 0.0), 0.2);
        assert_eq!(a.union(&inner), a);
        assert_eq!(inner.union(&a), a);
        let inf = Sphere::new(Vec3::ONE, f32::INFINITY);
        assert_eq!(a.union(&inf).radius, f32::INFINITY);
        assert_eq!(inf.union(&a).radius, f32::INFINITY);
    }

    #[test]
    fn union_of_far_apart_spheres_has_no_nan() {
        // Regression (fuzz/bsh_vs_brute): centres 2e19 apart overflow |c₁ − c₂|²;
        // the union used to get a NaN centre and contain nothing.
        let a = Sphere::new(Vec3::new(-1e19, 0.0, 0.0), 1.0);
        let b = Sphere::new(Vec3::new(1e19, 0.0, 0.0), 2.0);
        for u in [a.union(&b), b.union(&a)] {
            assert!(!u.center.is_nan() && !u.radius.is_nan());
            assert!(u.contains(a.center) && u.contains(b.center));
        }
        let huge = Sphere::new(Vec3::ZERO, f32::MAX);
        let u = huge.union(&Sphere::new(Vec3::X * 1e30, f32::MAX));
        assert!(!u.center.is_nan() && u.contains(Vec3::X * 1e30));
    }

    #[test]
    fn aabb_and_sphere_tests() {
        let b = Aabb { min: Vec3::ZERO, max: Vec3::ONE };
        assert!(Sphere::new(Vec3::new(2.0, 0.5, 0.5), 1.0).overlaps_aabb(&b));
        assert!(!Sphere::new(Vec3::new(2.0, 0.5, 0.5), 0.99).overlaps_aabb(&b));
        assert!(Sphere::new(Vec3::splat(0.5), 0.01).overlaps_aabb(&b));
        // Corner distance sqrt(3).
        assert!(!Sphere::new(Vec3::splat(2.0), 1.7).overlaps_aabb(&b));
        assert!(Sphere::new(Vec3::splat(2.0), 1.75).overlaps_aabb(&b));
        assert!(Sphere::new(Vec3::ZERO, 1.0).overlaps_sphere(&Sphere::new(Vec3::X * 2.0, 1.0)));
        assert!(!Sphere::new(Vec3::ZERO, 1.0).overlaps_sphere(&Sphere::new(Vec3::X * 2.0, 0.99)));
    }

    #[test]
    fn point_set_sphere_is_minimal_on_known_sets() {
        // Regular tetrahedron's vertices: circumsphere radius sqrt(3).
        let t = [
            Vec3::new(1., 1., 1.),
            Vec3::new(1., -1., -1.),
            Vec3::new(-1., 1., -1.),
            Vec3::new(-1., -1., 1.),
        ];
        let s = Sphere::of_points(&t);
        assert!(s.center.length() < 1e-5 && (s.radius - 3f32.sqrt()).abs() < 1e-4);
        // Cube corners plus interior points.
        let mut pts = Vec::new();
        for i in 0..8 {
            pts.push(Vec3::new((i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32));
        }
        pts.push(Vec3::splat(0.5));
        pts.push(Vec3::new(0.2, 0.7, 0.1));
        let s = Sphere::of_points(&pts);
        assert!((s.center - Vec3::splat(0.5)).length() < 1e-5);
        assert!((s.radius - 0.75f32.sqrt()).abs() < 1e-4);
        assert!(pts.iter().all(|&p| s.contains(p)));
    }
}
