//! The candela lookup of a flattened LM-63 table (type C symmetries,
//! bilinear in (γ, C)) and the portable arctangent it uses: shared code, so
//! the GPU runs the same arithmetic over the same table.

// Shared code is also WGSL, which has no `core::f32::consts`: π and its
// fractions are written as literals.
#![allow(clippy::approx_constant)]

use crate::wgsl::*;

crate::shared! {
    /// Arctangent with the same arithmetic on the CPU and the GPU (WGSL's
    /// `atan`/`atan2`/`acos` may be off by thousands of ulps, which moved
    /// IES lookups by up to 0.03° on lavapipe): Cephes `atanf`, reduction to
    /// `|t| ≤ tan(π/8)` then a degree-9 odd polynomial, about 2e-7 relative.
    pub fn atan_portable(x: f32) -> f32 {
        let a: f32 = abs(x);
        let mut base: f32 = 0.0;
        let mut t: f32 = a;
        if a > 2.4142137 {
            base = 1.5707964;
            t = -1.0 / a;
        } else if a > 0.41421357 {
            base = 0.7853982;
            t = (a - 1.0) / (a + 1.0);
        }
        let z: f32 = t * t;
        let r: f32 = base + ((((0.080537446 * z - 0.13877685) * z + 0.19977711) * z - 0.3333295) * z * t + t);
        return select(r, -r, x < 0.0);
    }

    /// `atan2(y, x)` in `(−π, π]` from [`atan_portable`]; 0 for `(0, 0)`.
    pub fn atan2_portable(y: f32, x: f32) -> f32 {
        if x == 0.0 {
            if y > 0.0 {
                return 1.5707964;
            }
            if y < 0.0 {
                return -1.5707964;
            }
            return 0.0;
        }
        let a: f32 = atan_portable(y / x);
        if x > 0.0 {
            return a;
        }
        if y >= 0.0 {
            return a + 3.1415927;
        }
        return a - 3.1415927;
    }

    /// Folds a horizontal angle `c` (degrees, any value) into the table's
    /// range `[h_first, h_last]` by the LM-63 symmetry that range implies.
    pub fn ies_fold_c(c: f32, h_first: f32, h_last: f32) -> f32 {
        let mut a: f32 = c - 360.0 * floor(c / 360.0);
        if h_last <= 0.0 {
            return 0.0;
        }
        if h_last <= 90.0 {
            if a > 180.0 {
                a = 360.0 - a;
            }
            if a > 90.0 {
                a = 180.0 - a;
            }
            return a;
        }
        if h_first >= 90.0 {
            if a < 90.0 {
                a = 180.0 - a;
            } else if a > 270.0 {
                a = 540.0 - a;
            }
            return a;
        }
        if h_last <= 180.0 {
            if a > 180.0 {
                a = 360.0 - a;
            }
            return a;
        }
        return a;
    }

    /// Index `i ≤ n − 2` of the segment `[t[i], t[i+1]]` of the increasing
    /// angles `t[start..start+n]` that holds `x` (binary search; the end
    /// segments when `x` is outside; 0 when `n < 2`).
    pub fn ies_segment(tab: Table, start: u32, n: u32, x: f32) -> u32 {
        if n < 2 {
            return 0;
        }
        let mut lo: u32 = 0;
        let mut hi: u32 = n - 1;
        while hi - lo > 1 {
            let mid: u32 = (lo + hi) >> 1;
            if at(tab, start + mid) <= x {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    /// Interpolation parameter of `x` in `[a0, a1]`, clamped to `[0, 1]`
    /// (0 for an empty segment).
    pub fn ies_lerp_t(a0: f32, a1: f32, x: f32) -> f32 {
        if a1 <= a0 {
            return 0.0;
        }
        return saturate((x - a0) / (a1 - a0));
    }

    /// Candela at vertical angle `gamma` and horizontal angle `c` (degrees)
    /// from the flattened profile at `tab[base..]`:
    /// `[n_v, n_h, v angles…, h angles…, candela (h-major)…]`.
    pub fn ies_candela(tab: Table, base: u32, gamma: f32, c: f32) -> f32 {
        let nv: u32 = to_u32(at(tab, base));
        let nh: u32 = to_u32(at(tab, base + 1));
        let v0: u32 = base + 2;
        let h0: u32 = v0 + nv;
        let c0: u32 = h0 + nh;
        if gamma < at(tab, v0) || gamma > at(tab, v0 + nv - 1) {
            return 0.0;
        }
        let hc: f32 = ies_fold_c(c, at(tab, h0), at(tab, h0 + nh - 1));
        let iv: u32 = ies_segment(tab, v0, nv, gamma);
        let ih: u32 = ies_segment(tab, h0, nh, hc);
        let iv1: u32 = min(iv + 1, nv - 1);
        let ih1: u32 = min(ih + 1, nh - 1);
        let tv: f32 = ies_lerp_t(at(tab, v0 + iv), at(tab, v0 + iv1), gamma);
        let th: f32 = ies_lerp_t(at(tab, h0 + ih), at(tab, h0 + ih1), hc);
        let a: f32 = at(tab, c0 + ih * nv + iv) * (1.0 - tv) + at(tab, c0 + ih * nv + iv1) * tv;
        let b: f32 = at(tab, c0 + ih1 * nv + iv) * (1.0 - tv) + at(tab, c0 + ih1 * nv + iv1) * tv;
        return a * (1.0 - th) + b * th;
    }

    /// Candela toward a unit direction given by its components along the
    /// light's nadir (`wn`), reference (`wr`, C = 0°) and side (`ws`,
    /// C = 90°) axes.
    pub fn ies_candela_dir(tab: Table, base: u32, wn: f32, wr: f32, ws: f32) -> f32 {
        let gamma: f32 = degrees(atan2_portable(sqrt(wr * wr + ws * ws), wn));
        let on_axis: bool = abs(wr) + abs(ws) <= 0.0;
        let c: f32 = select(degrees(atan2_portable(ws, wr)), 0.0, on_axis);
        return ies_candela(tab, base, gamma, c);
    }

    /// Candela of an IES light with unit `nadir` and `reference` (C = 0°,
    /// ⟂ nadir) axes toward unit `w`: the side axis (C = 90°) is
    /// `reference × nadir`, and [`ies_candela_dir`] takes `w`'s components.
    pub fn ies_light_candela(tab: Table, base: u32, nadir: vec3f, reference: vec3f, w: vec3f) -> f32 {
        let side: vec3f = cross(reference, nadir);
        return ies_candela_dir(tab, base, dot(w, nadir), dot(w, reference), dot(w, side));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The portable arctangent against libm's over a sweep that covers the
    /// reduction branches, all quadrants, zeros and infinities.
    #[test]
    fn portable_atan_matches_libm() {
        let mut worst = 0.0f32;
        for i in -4000..=4000 {
            let x = libm::sinhf(i as f32 / 400.0);
            worst = worst.max((atan_portable(x) - libm::atanf(x)).abs());
            for y in [-3.0f32, -0.5, 0.0, 1e-20, 0.7, 12.0] {
                let (p, l) = (atan2_portable(y, x), libm::atan2f(y, x));
                assert!((p - l).abs() <= 4e-7, "atan2({y}, {x}): {p} vs {l}");
            }
        }
        assert!(worst <= 3e-7, "worst |atan error| {worst}");
        assert_eq!(atan_portable(f32::INFINITY), core::f32::consts::FRAC_PI_2);
        assert_eq!(atan2_portable(0.0, 0.0), 0.0);
        assert!((atan2_portable(0.0, -1.0) - core::f32::consts::PI).abs() < 1e-6);
    }
}
