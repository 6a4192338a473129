// slc-core shared functions (generated from Rust; do not edit)
alias Table = u32;
fn at(tab: Table, i: u32) -> f32 { return slc_table[i]; }
fn to_f32(u: u32) -> f32 { return f32(u); }
fn to_u32(x: f32) -> u32 { return u32(x); }
fn mul_lo_u32(a: u32, b: u32) -> u32 { return a * b; }
fn add_wrap_u32(a: u32, b: u32) -> u32 { return a + b; }
const XI_STEP: f32 = 0.000000059604644775390625;
fn xi_from_bits(bits: u32) -> f32 {
    return to_f32(bits >> 8) * XI_STEP;
}
fn pcg_hash(x: u32) -> u32 {
    let state: u32 = add_wrap_u32(mul_lo_u32(x, 747796405), 2891336453);
    let word: u32 = mul_lo_u32((state >> ((state >> 28) + 4)) ^ state, 277803737);
    return (word >> 22) ^ word;
}
fn xi_for(seed: u32, frame: u32, light: u32) -> f32 {
    return xi_from_bits(add_wrap_u32(pcg_hash(pcg_hash(pcg_hash(seed)) ^ light), reverse_bits(frame)));
}
fn reverse_bits(x: u32) -> u32 {
    var v: u32 = ((x >> 16) & 65535) | ((x & 65535) << 16);
    v = ((v >> 8) & 16711935) | ((v & 16711935) << 8);
    v = ((v >> 4) & 252645135) | ((v & 252645135) << 4);
    v = ((v >> 2) & 858993459) | ((v & 858993459) << 2);
    v = ((v >> 1) & 1431655765) | ((v & 1431655765) << 1);
    return v;
}
const TWO_PI: f32 = 6.283185307179586;
fn rr_probability(rt2: f32, d2: f32) -> f32 {
    if d2 <= rt2 {
        return 1.0;
    }
    return rt2 / d2;
}
fn slc_weight(rt2: f32, d2: f32) -> f32 {
    if d2 <= rt2 {
        return 1.0;
    }
    return d2 / rt2;
}
fn random_range2(rt2: f32, xi: f32) -> f32 {
    return rt2 / (1.0 - xi);
}
fn slc_keep(r2: f32, d2: f32) -> bool {
    return d2 < r2;
}
fn threshold_range2(intensity: f32, exposure: f32, error_bound: f32) -> f32 {
    if intensity <= 0.0 {
        return 0.0;
    }
    return (exposure / error_bound) * intensity / TWO_PI;
}
fn intensity_measure(rgb: vec3f, mode: u32) -> f32 {
    if mode == 1 {
        return (rgb.x + rgb.y + rgb.z) / 3.0;
    }
    return max(rgb.x, max(rgb.y, rgb.z));
}
const CULL_RADIUS_SCALE: f32 = 1.00000095367431640625;
fn cull_radius(r2: f32) -> f32 {
    return sqrt(r2) * CULL_RADIUS_SCALE;
}
fn windowed_falloff(d2: f32, range2: f32) -> f32 {
    let q: f32 = d2 / range2;
    let w: f32 = saturate(1.0 - q * q);
    return w * w / max(d2, 0.0001);
}
fn sphere_contains_point(c: vec3f, r: f32, x: vec3f) -> bool {
    let v: vec3f = x - c;
    return dot(v, v) <= r * r;
}
fn sphere_overlaps_sphere(c1: vec3f, r1: f32, c2: vec3f, r2: f32) -> bool {
    let v: vec3f = c2 - c1;
    let r: f32 = r1 + r2;
    return dot(v, v) <= r * r;
}
const SPHERE_PAD: f32 = 0.000000476837158203125;
const SPHERE_HUGE: f32 = 340282346638528859811704183484516925440.0;
const SPHERE_PAD_ABS: f32 = 1e-18;
fn sphere_pad(r: f32, c: vec3f) -> f32 {
    return (r + max(abs(c.x), max(abs(c.y), abs(c.z)))) * SPHERE_PAD + SPHERE_PAD_ABS;
}
fn sphere_union(c1: vec3f, r1: f32, c2: vec3f, r2: f32) -> vec4f {
    let v: vec3f = c2 - c1;
    let d: f32 = sqrt(dot(v, v));
    if r1 >= d + r2 + sphere_pad(r1, c1) {
        return vec4f(c1.x, c1.y, c1.z, r1);
    }
    if r2 >= d + r1 + sphere_pad(r2, c2) {
        return vec4f(c2.x, c2.y, c2.z, r2);
    }
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
fn sphere_overlaps_aabb(c: vec3f, r: f32, bmin: vec3f, bmax: vec3f) -> bool {
    let q: vec3f = clamp(c, bmin, bmax);
    let v: vec3f = q - c;
    return dot(v, v) <= r * r;
}
const INV_PI: f32 = 0.3183098861837907;
const MIN_D2: f32 = 0.000000000001;
fn vpl_rt2(flux: vec3f, exposure: f32, error_bound: f32, mode: u32) -> f32 {
    return threshold_range2(intensity_measure(flux * INV_PI, mode), exposure, error_bound);
}
fn range_radius(extent: f32, r2: f32) -> f32 {
    return extent + sqrt(r2);
}
fn inverse_square(d2: f32) -> f32 {
    return 1.0 / max(d2, MIN_D2);
}
fn connection_factor(cos_x: f32, d2: f32, rt2: f32, w: f32) -> f32 {
    return cos_x * inverse_square(d2) * slc_weight(rt2, d2) * w;
}
fn vpl_lobe(n: vec3f, w: vec3f) -> f32 {
    return max(dot(n, w), 0.0) * INV_PI;
}
fn vpl_transfer(n_l: vec3f, n_x: vec3f, v: vec3f, min_d2: f32) -> f32 {
    let m: f32 = max(dot(v, v), min_d2);
    return max(dot(n_l, v), 0.0) * max(-dot(n_x, v), 0.0) * INV_PI / (m * m);
}
fn spot_falloff(cos_theta: f32, cos_outer: f32, cos_inner: f32) -> f32 {
    if cos_inner <= cos_outer {
        return select(0.0, 1.0, cos_theta >= cos_outer);
    }
    let t: f32 = saturate((cos_theta - cos_outer) / (cos_inner - cos_outer));
    return t * t * (3.0 - 2.0 * t);
}
fn triangle_lobe(n: vec3f, area: f32, w: vec3f) -> f32 {
    return area * max(dot(n, w), 0.0);
}
fn triangle_sample(a: vec3f, b: vec3f, c: vec3f, u1: f32, u2: f32) -> vec3f {
    let su: f32 = sqrt(u1);
    let b0: f32 = 1.0 - su;
    let b1: f32 = u2 * su;
    return a * b0 + b * b1 + c * (1.0 - b0 - b1);
}
fn area_to_solid_angle_pdf(pdf_area: f32, d2: f32, cos_light: f32) -> f32 {
    let c: f32 = abs(cos_light);
    if c <= 0.0 {
        return 0.0;
    }
    return pdf_area * d2 / c;
}
fn atan_portable(x: f32) -> f32 {
    let a: f32 = abs(x);
    var base: f32 = 0.0;
    var t: f32 = a;
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
fn atan2_portable(y: f32, x: f32) -> f32 {
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
fn ies_fold_c(c: f32, h_first: f32, h_last: f32) -> f32 {
    var a: f32 = c - 360.0 * floor(c / 360.0);
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
fn ies_segment(tab: Table, start: u32, n: u32, x: f32) -> u32 {
    if n < 2 {
        return 0;
    }
    var lo: u32 = 0;
    var hi: u32 = n - 1;
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
fn ies_lerp_t(a0: f32, a1: f32, x: f32) -> f32 {
    if a1 <= a0 {
        return 0.0;
    }
    return saturate((x - a0) / (a1 - a0));
}
fn ies_candela(tab: Table, base: u32, gamma: f32, c: f32) -> f32 {
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
fn ies_candela_dir(tab: Table, base: u32, wn: f32, wr: f32, ws: f32) -> f32 {
    let gamma: f32 = degrees(atan2_portable(sqrt(wr * wr + ws * ws), wn));
    let on_axis: bool = abs(wr) + abs(ws) <= 0.0;
    let c: f32 = select(degrees(atan2_portable(ws, wr)), 0.0, on_axis);
    return ies_candela(tab, base, gamma, c);
}
const BSH_NONE: u32 = 4294967295;
struct BshNode {
    center: vec3f, radius: f32, child: u32, next: u32, light: u32, pad: u32
}
fn mul_hi_u32(a: u32, b: u32) -> u32 {
    let a_lo: u32 = a & 65535;
    let a_hi: u32 = a >> 16;
    let b_lo: u32 = b & 65535;
    let b_hi: u32 = b >> 16;
    let ll: u32 = a_lo * b_lo;
    let lh: u32 = a_lo * b_hi;
    let hl: u32 = a_hi * b_lo;
    let hh: u32 = a_hi * b_hi;
    let mid: u32 = (ll >> 16) + (lh & 65535) + (hl & 65535);
    return hh + (lh >> 16) + (hl >> 16) + (mid >> 16);
}
fn uniform_index(n: u32, hi: u32, lo: u32) -> u32 {
    let p_lo: u32 = mul_lo_u32(hi, n);
    let p_hi: u32 = mul_hi_u32(hi, n);
    let carry_in: u32 = mul_hi_u32(lo, n);
    if p_lo > 4294967295 - carry_in {
        return p_hi + 1;
    }
    return p_hi;
}
fn reservoir_slot(n: u32, k: u32, hi: u32, lo: u32) -> u32 {
    if n <= k {
        return n - 1;
    }
    let j: u32 = uniform_index(n, hi, lo);
    if j < k {
        return j;
    }
    return k;
}
fn reservoir_weight(n: u32, k: u32) -> f32 {
    return max(to_f32(n) / to_f32(k), 1.0);
}
fn weighted_replace(w: f32, w_sum: f32, u: f32) -> bool {
    return u * w_sum < w;
}
fn weighted_pick_weight(w_sum: f32, w: f32, k: u32) -> f32 {
    return w_sum / (to_f32(k) * w);
}
fn cos_sub_clamped(sin_a: f32, cos_a: f32, sin_b: f32, cos_b: f32) -> f32 {
    if cos_a > cos_b {
        return 1.0;
    }
    return cos_a * cos_b + sin_a * sin_b;
}
fn sin_sub_clamped(sin_a: f32, cos_a: f32, sin_b: f32, cos_b: f32) -> f32 {
    if cos_a > cos_b {
        return 0.0;
    }
    return sin_a * cos_b - cos_a * sin_b;
}
fn safe_sqrt(x: f32) -> f32 {
    return sqrt(max(x, 0.0));
}
fn light_importance(center: vec3f, radius: f32, phi: f32, axis: vec3f, cos_o: f32, cos_e: f32, p: vec3f, n: vec3f) -> f32 {
    let v: vec3f = p - center;
    let dist2: f32 = dot(v, v);
    let r2: f32 = radius * radius;
    let d2: f32 = max(max(dist2, r2), MIN_D2);
    let wi: vec3f = select(vec3f(0.0, 0.0, 0.0), v / sqrt(dist2), dist2 > 0.0);
    let cos_w: f32 = dot(axis, wi);
    let sin_w: f32 = safe_sqrt(1.0 - cos_w * cos_w);
    let cos_b: f32 = select(safe_sqrt(1.0 - r2 / dist2), -1.0, dist2 <= r2);
    let sin_b: f32 = safe_sqrt(1.0 - cos_b * cos_b);
    let sin_o: f32 = safe_sqrt(1.0 - cos_o * cos_o);
    let cos_x: f32 = cos_sub_clamped(sin_w, cos_w, sin_o, cos_o);
    let sin_x: f32 = sin_sub_clamped(sin_w, cos_w, sin_o, cos_o);
    let cos_p: f32 = cos_sub_clamped(sin_x, cos_x, sin_b, cos_b);
    if cos_p <= cos_e {
        return 0.0;
    }
    var imp: f32 = phi * cos_p / d2;
    if dot(n, n) > 0.0 {
        let cos_i: f32 = -dot(wi, n);
        let sin_i: f32 = safe_sqrt(1.0 - cos_i * cos_i);
        imp = imp * max(cos_sub_clamped(sin_i, cos_i, sin_b, cos_b), 0.0);
    }
    return max(imp, 0.0);
}
fn candidate_weight(importance: f32, rt2: f32, d2: f32) -> f32 {
    return importance * slc_weight(rt2, d2);
}
fn cone_weight(center: vec3f, radius: f32, phi: f32, axis: vec3f, cos_o: f32, cos_e: f32, rt2: f32, p: vec3f, n: vec3f) -> f32 {
    let v: vec3f = p - center;
    return candidate_weight(light_importance(center, radius, phi, axis, cos_o, cos_e, p, n) * INV_PI, rt2, dot(v, v));
}
fn weighted_select_pdf(w: f32, w_sum: f32, in_range: bool, k: u32) -> f32 {
    if w <= 0.0 {
        return 0.0;
    }
    let total: f32 = select(w_sum + w, w_sum, in_range);
    return to_f32(k) * w / total;
}
const LIGHT_BVH_LEAF: u32 = 4294967295;
const ONE_MINUS_EPSILON: f32 = 0.99999994;
fn bvh_first_prob(c0: f32, c1: f32) -> f32 {
    let s: f32 = c0 + c1;
    if s > 0.0 {
        return c0 / s;
    }
    return -1.0;
}
fn bvh_remap_u(u: f32, p0: f32, first: bool) -> f32 {
    if first {
        return min(u / p0, ONE_MINUS_EPSILON);
    }
    return clamp((u - p0) / (1.0 - p0), 0.0, ONE_MINUS_EPSILON);
}
fn ray_aabb(o: vec3f, inv_d: vec3f, bmin: vec3f, bmax: vec3f, t_max: f32) -> f32 {
    let t0: vec3f = (bmin - o) * inv_d;
    let t1: vec3f = (bmax - o) * inv_d;
    let lo: vec3f = min(t0, t1);
    let hi: vec3f = max(t0, t1);
    let t_in: f32 = max(max(lo.x, lo.y), max(lo.z, 0.0));
    let t_out: f32 = min(min(hi.x, hi.y), min(hi.z, t_max));
    if t_in <= t_out {
        return t_in;
    }
    return -1.0;
}
fn triangle_normal(a: vec3f, b: vec3f, c: vec3f) -> vec3f {
    let n: vec3f = cross(b - a, c - a);
    let l2: f32 = dot(n, n);
    if !(l2 > 0.0) || !(l2 < 3.0e38) {
        return vec3f(0.0, 0.0, 0.0);
    }
    return n / sqrt(l2);
}
fn face_against(n: vec3f, dir: vec3f) -> vec3f {
    return select(n, -n, dot(n, dir) > 0.0);
}
fn barycentric(p: vec3f, a: vec3f, b: vec3f, c: vec3f) -> vec3f {
    let e1: vec3f = b - a;
    let e2: vec3f = c - a;
    let q: vec3f = p - a;
    let d11: f32 = dot(e1, e1);
    let d12: f32 = dot(e1, e2);
    let d22: f32 = dot(e2, e2);
    let den: f32 = d11 * d22 - d12 * d12;
    if !(abs(den) > 0.0) {
        return vec3f(1.0, 0.0, 0.0);
    }
    let w1: f32 = (d22 * dot(q, e1) - d12 * dot(q, e2)) / den;
    let w2: f32 = (d11 * dot(q, e2) - d12 * dot(q, e1)) / den;
    return vec3f(1.0 - w1 - w2, w1, w2);
}
fn shading_normal(n0: vec3f, n1: vec3f, n2: vec3f, w: vec3f, facing: vec3f) -> vec3f {
    let s: vec3f = n0 * w.x + n1 * w.y + n2 * w.z;
    let l2: f32 = dot(s, s);
    if !(l2 > 1e-12) || !(l2 < 3.0e38) {
        return facing;
    }
    let n: vec3f = s / sqrt(l2);
    return select(n, -n, dot(n, facing) < 0.0);
}
fn ray_triangle(o: vec3f, d: vec3f, a: vec3f, b: vec3f, c: vec3f, t_min: f32, t_max: f32) -> f32 {
    let e1: vec3f = b - a;
    let e2: vec3f = c - a;
    let p: vec3f = cross(d, e2);
    let det: f32 = dot(e1, p);
    if abs(det) <= 0.0 {
        return -1.0;
    }
    let inv: f32 = 1.0 / det;
    let s: vec3f = o - a;
    let u: f32 = dot(s, p) * inv;
    if u < 0.0 || u > 1.0 {
        return -1.0;
    }
    let q: vec3f = cross(s, e1);
    let v: f32 = dot(d, q) * inv;
    if v < 0.0 || u + v > 1.0 {
        return -1.0;
    }
    let t: f32 = dot(e2, q) * inv;
    if t > t_min && t < t_max {
        return t;
    }
    return -1.0;
}
fn mis_balance(pdf_a: f32, pdf_b: f32) -> f32 {
    let s: f32 = pdf_a + pdf_b;
    if s <= 0.0 {
        return 0.0;
    }
    return pdf_a / s;
}
fn mis_power(pdf_a: f32, pdf_b: f32) -> f32 {
    let a2: f32 = pdf_a * pdf_a;
    let s: f32 = a2 + pdf_b * pdf_b;
    if s <= 0.0 {
        return 0.0;
    }
    return a2 / s;
}
fn light_strategy_pdf(select: f32, rt2: f32, d2: f32, area: f32, cos_y: f32) -> f32 {
    if d2 <= 0.0 || area <= 0.0 || cos_y <= 0.0 {
        return 0.0;
    }
    return select * rr_probability(rt2, d2) * area_to_solid_angle_pdf(1.0 / area, d2, cos_y);
}
fn lambert_brdf(rho: vec3f) -> vec3f {
    return rho * INV_PI;
}
fn cosine_pdf(cos_theta: f32) -> f32 {
    return max(cos_theta, 0.0) * INV_PI;
}
fn cosine_direction(n: vec3f, u1: f32, u2: f32) -> vec3f {
    let s: f32 = select(-1.0, 1.0, n.z >= 0.0);
    let a: f32 = -1.0 / (s + n.z);
    let b: f32 = n.x * n.y * a;
    let t: vec3f = vec3f(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    let bt: vec3f = vec3f(b, s + n.y * n.y * a, -n.y);
    let r: f32 = sqrt(u1);
    let phi: f32 = 6.2831855 * u2;
    return normalize(t * (r * cos(phi)) + bt * (r * sin(phi)) + n * sqrt(max(1.0 - u1, 0.0)));
}
const DEPTH_SIGMA: f32 = 0.05;
const COVER_WEIGHT: f32 = 0.1;
fn bilateral_weight(n: vec3f, nj: vec3f, z: f32, zj: f32, inv_sz: f32) -> f32 {
    let dn: f32 = max(dot(n, nj), 0.0);
    let dn2: f32 = dn * dn;
    let dn4: f32 = dn2 * dn2;
    let dn8: f32 = dn4 * dn4;
    let d: f32 = (zj - z) * inv_sz;
    let t: f32 = max(1.0 - d * d, 0.0);
    return dn8 * dn8 * t * t;
}
fn interleave_subset(x: u32, y: u32, period: u32) -> u32 {
    return (y % period) * period + x % period;
}
fn interleave_slot(tx: u32, ty: u32, size: u32, period: u32) -> u32 {
    let side: u32 = size / period;
    return interleave_subset(tx, ty, period) * side * side + (ty / period) * side + tx / period;
}
fn interleave_slot_linear(i: u32, per_subset: u32, period: u32) -> u32 {
    let subsets: u32 = period * period;
    return (i % subsets) * per_subset + i / subsets;
}
const NEAR_BLOCK: u32 = 64;
fn near_block_index(tx: u32, ty: u32, size: u32) -> u32 {
    let side: u32 = size / 8;
    return ((ty / 8) * side + tx / 8) * NEAR_BLOCK + (ty % 8) * 8 + tx % 8;
}
fn near_block_tx(q: u32, size: u32) -> u32 {
    return ((q / NEAR_BLOCK) % (size / 8)) * 8 + q % 8;
}
fn near_block_ty(q: u32, size: u32) -> u32 {
    return ((q / NEAR_BLOCK) / (size / 8)) * 8 + (q % NEAR_BLOCK) / 8;
}
fn vpl_near_weight(d2: f32, near_r2: f32) -> f32 {
    if near_r2 <= 0.0 {
        return 0.0;
    }
    let t: f32 = clamp((near_r2 - d2) / (0.75 * near_r2), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}
fn vpl_far_weight(d2: f32, near_r2: f32) -> f32 {
    return 1.0 - vpl_near_weight(d2, near_r2);
}
fn camera_dir(forward: vec3f, right: vec3f, up: vec3f, px: f32, py: f32, w: f32, h: f32) -> vec3f {
    let sx: f32 = 2.0 * px / w - 1.0;
    let sy: f32 = 1.0 - 2.0 * py / h;
    return normalize(forward + right * sx + up * sy);
}
fn path_survival(beta: vec3f) -> f32 {
    return clamp(max(max(beta.x, beta.y), beta.z), 0.05, 0.95);
}
fn light_map_coord(t: u32, size: u32) -> f32 {
    return 2.0 * (to_f32(t) + 0.5) / to_f32(size) - 1.0;
}
fn light_map_texel(a: f32, size: u32) -> u32 {
    return to_u32(clamp(floor((a + 1.0) * 0.5 * to_f32(size)), 0.0, to_f32(size) - 1.0));
}
fn light_map_depth(rel: vec3f, axis: vec3f, perspective: bool) -> f32 {
    return select(dot(rel, axis), sqrt(dot(rel, rel)), perspective);
}
fn rsm_texel_solid_angle(texel_area: f32, cos_axis: f32) -> f32 {
    return texel_area * cos_axis * cos_axis * cos_axis;
}
fn point_irradiance(intensity: vec3f, n: vec3f, v: vec3f) -> vec3f {
    let d2: f32 = dot(v, v);
    let cos_x: f32 = dot(n, v) / sqrt(max(d2, MIN_D2));
    return intensity * (max(cos_x, 0.0) * inverse_square(d2));
}
fn directional_irradiance(e: vec3f, n: vec3f, to_light: vec3f) -> vec3f {
    return e * max(dot(n, to_light), 0.0);
}
fn shadow_bias(texel: f32, cos_light: f32) -> f32 {
    let c: f32 = clamp(cos_light, 0.02, 1.0);
    return texel * (1.5 + sqrt(1.0 - c * c) / c);
}
fn shadow_lit(d: f32, d_map: f32, bias: f32) -> bool {
    return d_map <= 0.0 || d <= d_map + bias;
}
fn diffuse_radiance(albedo: vec3f, emission: vec3f, e: vec3f) -> vec3f {
    return emission + albedo * INV_PI * e;
}
