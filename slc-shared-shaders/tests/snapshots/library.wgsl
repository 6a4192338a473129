struct BshNode {
    center: vec3<f32>,
    radius: f32,
    child: u32,
    next: u32,
    light: u32,
    extent: f32,
}

struct GpuLightBvhNode {
    center: vec3<f32>,
    radius: f32,
    axis: vec3<f32>,
    cos_o: f32,
    phi: f32,
    cos_e: f32,
    second: u32,
    light: u32,
}

const XI_STEP: f32 = 0.000000059604645f;
const XI_ROTATED: u32 = 2147483648u;
const XI_BITS_SHIFT: u32 = 26u;
const XI_INDEX_MASK: u32 = 67108863u;
const PICK_STREAM: u32 = 2654435769u;
const TWO_PI: f32 = 6.2831855f;
const UNRANGED: f32 = 100000000000000000000000000000000000000f;
const CULL_RADIUS_SCALE: f32 = 1.000001f;
const SPHERE_PAD: f32 = 0.00000047683716f;
const SPHERE_HUGE: f32 = 340282350000000000000000000000000000000f;
const SPHERE_PAD_ABS: f32 = 0.000000000000000001f;
const CLUSTER: u32 = 64u;
const GROUP_SIDE: u32 = 8u;
const INV_PI: f32 = 0.31830987f;
const MIN_D2_: f32 = 0.000000000001f;
const MAX_INTENSITY: f32 = 72057594000000000f;
const BSH_NONE: u32 = 4294967295u;
const BSH_TAIL: u32 = 2147483648u;
const BSH_TAIL_BINS: u32 = 1024u;
const BSH_TAIL_MAX: u32 = 64u;
const RESERVOIR_FULL: u32 = 4294967295u;
const REUSE_TRUST_SCALE: f32 = 64f;
const GGX_ALPHA_MIN: f32 = 0.001f;
const RANGE_SCALE_MAX: f32 = 64f;
const LIGHT_BVH_LEAF: u32 = 4294967295u;
const ONE_MINUS_EPSILON: f32 = 0.99999994f;
const F32_MAX: f32 = 340282350000000000000000000000000000000f;
const DEPTH_NONE: f32 = 1000000000000000000000000000000f;
const DEPTH_SIGMA: f32 = 0.05f;
const COVER_WEIGHT: f32 = 0.1f;
const ROULETTE_DEPTH: u32 = 2u;
const TEMPORAL_MAX_HISTORY: f32 = 32f;
const TEMPORAL_DEPTH_TOLERANCE: f32 = 0.01f;
const TEMPORAL_MOTION_DEPTH_TOLERANCE: f32 = 0.05f;
const TEMPORAL_NORMAL_COS: f32 = 0.9f;
const TEMPORAL_MIN_MOMENTS: f32 = 8f;
const TEMPORAL_CHANGED_HISTORY: f32 = 1f;
const TEMPORAL_CHANGE_LOW: f32 = 4f;
const TEMPORAL_CHANGE_HIGH: f32 = 8f;
const TEMPORAL_MIN_WEIGHT: f32 = 0.01f;

@group(1) @binding(0) 
var<storage> slc_table: array<f32>;

fn at(tab: u32, i: u32) -> f32 {
    let _e4 = slc_table[i];
    return _e4;
}

fn to_f32_(u: u32) -> f32 {
    return f32(u);
}

fn to_u32_(x: f32) -> u32 {
    return u32(x);
}

fn mul_lo_u32_(a: u32, b: u32) -> u32 {
    return (a * b);
}

fn add_wrap_u32_(a_1: u32, b_1: u32) -> u32 {
    return (a_1 + b_1);
}

fn f32_from_bits(u_1: u32) -> f32 {
    return bitcast<f32>(u_1);
}

fn f32_to_bits(x_1: f32) -> u32 {
    return bitcast<u32>(x_1);
}

fn xi_from_bits(bits: u32) -> f32 {
    let _e3 = to_f32_((bits >> 8u));
    return (_e3 * XI_STEP);
}

fn pcg_hash(x_2: u32) -> u32 {
    let _e2 = mul_lo_u32_(x_2, 747796405u);
    let _e4 = add_wrap_u32_(_e2, 2891336453u);
    let _e12 = mul_lo_u32_(((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4), 277803737u);
    return ((_e12 >> 22u) ^ _e12);
}

fn laine_karras(x_3: u32, seed: u32) -> u32 {
    var v: u32;

    let _e2 = add_wrap_u32_(x_3, seed);
    v = _e2;
    let _e4 = v;
    let _e5 = v;
    let _e7 = mul_lo_u32_(_e5, 1817228412u);
    v = (_e4 ^ _e7);
    let _e9 = v;
    let _e10 = v;
    let _e12 = mul_lo_u32_(_e10, 3090095698u);
    v = (_e9 ^ _e12);
    let _e14 = v;
    let _e15 = v;
    let _e17 = mul_lo_u32_(_e15, 3350193720u);
    v = (_e14 ^ _e17);
    let _e19 = v;
    let _e20 = v;
    let _e22 = mul_lo_u32_(_e20, 2367878886u);
    v = (_e19 ^ _e22);
    let _e24 = v;
    return _e24;
}

fn reverse_bits(x_4: u32) -> u32 {
    var v_1: u32;

    v_1 = (((x_4 >> 16u) & 65535u) | ((x_4 & 65535u) << 16u));
    let _e11 = v_1;
    let _e16 = v_1;
    v_1 = (((_e11 >> 8u) & 16711935u) | ((_e16 & 16711935u) << 8u));
    let _e22 = v_1;
    let _e27 = v_1;
    v_1 = (((_e22 >> 4u) & 252645135u) | ((_e27 & 252645135u) << 4u));
    let _e33 = v_1;
    let _e38 = v_1;
    v_1 = (((_e33 >> 2u) & 858993459u) | ((_e38 & 858993459u) << 2u));
    let _e44 = v_1;
    let _e49 = v_1;
    v_1 = (((_e44 >> 1u) & 1431655765u) | ((_e49 & 1431655765u) << 1u));
    let _e55 = v_1;
    return _e55;
}

fn xi_for(seed_1: u32, frame: u32, light: u32) -> f32 {
    let _e3 = pcg_hash(seed_1);
    let _e4 = pcg_hash(_e3);
    let _e6 = pcg_hash((_e4 ^ light));
    let _e7 = pcg_hash(_e6);
    let _e8 = reverse_bits(frame);
    let _e9 = laine_karras(_e8, _e7);
    let _e11 = laine_karras(0u, _e7);
    let _e13 = add_wrap_u32_(_e6, (_e9 ^ _e11));
    let _e14 = xi_from_bits(_e13);
    return _e14;
}

fn xi_rotated(seed_2: u32, frame_1: u32, light_1: u32, bits_1: u32) -> f32 {
    let _e4 = pcg_hash(seed_2);
    let _e7 = pcg_hash((_e4 ^ 1013904223u));
    let _e8 = laine_karras(light_1, _e7);
    let _e13 = pcg_hash((_e7 ^ light_1));
    let o_2 = ((_e8 << (32u - bits_1)) | (_e13 >> bits_1));
    let _e16 = pcg_hash(_e7);
    let _e17 = reverse_bits(frame_1);
    let _e18 = laine_karras(_e17, _e16);
    let _e20 = laine_karras(0u, _e16);
    let t_3 = (_e18 ^ _e20);
    let _e22 = add_wrap_u32_(o_2, t_3);
    let _e23 = xi_from_bits(_e22);
    return _e23;
}

fn light_xi(seed_3: u32, frame_2: u32, key: u32) -> f32 {
    if (key >= XI_ROTATED) {
        let _e13 = xi_rotated(seed_3, frame_2, (key & XI_INDEX_MASK), max(((key >> XI_BITS_SHIFT) & 31u), 1u));
        return _e13;
    }
    let _e14 = xi_for(seed_3, frame_2, key);
    return _e14;
}

fn frame_xi(seed_4: u32, frame_3: u32, key_1: u32, fixed: f32) -> f32 {
    if (fixed >= 0f) {
        return fixed;
    }
    let _e6 = light_xi(seed_4, frame_3, key_1);
    return _e6;
}

fn point_stream(seed_5: u32, point: u32, frame_4: u32) -> u32 {
    let _e3 = pcg_hash(frame_4);
    let _e5 = pcg_hash((point ^ _e3));
    let _e7 = pcg_hash((seed_5 ^ _e5));
    return _e7;
}

fn pick_stream(stream: u32) -> u32 {
    let _e3 = pcg_hash((stream ^ PICK_STREAM));
    return _e3;
}

fn reuse_stream(stream_1: u32, which: u32) -> u32 {
    let _e2 = pick_stream(stream_1);
    let _e6 = pcg_hash(((_e2 + 1u) + which));
    return _e6;
}

fn path_stream(seed_6: u32, pixel: u32, pass_index: u32) -> u32 {
    let _e4 = add_wrap_u32_(pass_index, PICK_STREAM);
    let _e5 = point_stream(seed_6, pixel, _e4);
    return _e5;
}

fn rr_probability(rt2_: f32, d2_: f32) -> f32 {
    if (d2_ <= rt2_) {
        return 1f;
    }
    return (rt2_ / d2_);
}

fn slc_weight(rt2_1: f32, d2_1: f32) -> f32 {
    if (d2_1 <= rt2_1) {
        return 1f;
    }
    return (d2_1 / rt2_1);
}

fn random_range2_(rt2_2: f32, xi: f32) -> f32 {
    return (rt2_2 / (1f - xi));
}

fn slc_keep(r2_: f32, d2_2: f32) -> bool {
    return (d2_2 < r2_);
}

fn clamp_keep(range2_: f32, d2_3: f32) -> bool {
    return (d2_3 < range2_);
}

fn threshold_range2_(intensity: f32, exposure: f32, error_bound: f32) -> f32 {
    if (intensity <= 0f) {
        return 0f;
    }
    return (((exposure / error_bound) * intensity) / TWO_PI);
}

fn intensity_measure(rgb: vec3<f32>, mode: u32) -> f32 {
    if (mode == 1u) {
        return (((rgb.x + rgb.y) + rgb.z) / 3f);
    }
    return max(rgb.x, max(rgb.y, rgb.z));
}

fn cull_radius(r2_1: f32) -> f32 {
    return (sqrt(r2_1) * CULL_RADIUS_SCALE);
}

fn windowed_falloff(d2_4: f32, range2_1: f32) -> f32 {
    let q_3 = (d2_4 / range2_1);
    let w_14 = saturate((1f - (q_3 * q_3)));
    return ((w_14 * w_14) / max(d2_4, 0.0001f));
}

fn sphere_contains_point(c: vec3<f32>, r: f32, x_5: vec3<f32>) -> bool {
    let v_14 = (x_5 - c);
    return (dot(v_14, v_14) <= (r * r));
}

fn sphere_overlaps_sphere(c1_: vec3<f32>, r1_: f32, c2_: vec3<f32>, r2_2: f32) -> bool {
    let v_15 = (c2_ - c1_);
    let r_10 = (r1_ + r2_2);
    return (dot(v_15, v_15) <= (r_10 * r_10));
}

fn sphere_pad(r_1: f32, c_1: vec3<f32>) -> f32 {
    return (((r_1 + max(abs(c_1.x), max(abs(c_1.y), abs(c_1.z)))) * SPHERE_PAD) + SPHERE_PAD_ABS);
}

fn sphere_union(c1_1: vec3<f32>, r1_1: f32, c2_1: vec3<f32>, r2_3: f32) -> vec4<f32> {
    var local: bool;

    let v_16 = (c2_1 - c1_1);
    let d_10 = sqrt(dot(v_16, v_16));
    let _e8 = sphere_pad(r1_1, c1_1);
    if (r1_1 >= ((d_10 + r2_3) + _e8)) {
        return vec4<f32>(c1_1.x, c1_1.y, c1_1.z, r1_1);
    }
    let _e16 = sphere_pad(r2_3, c2_1);
    if (r2_3 >= ((d_10 + r1_1) + _e16)) {
        return vec4<f32>(c2_1.x, c2_1.y, c2_1.z, r2_3);
    }
    if !((d_10 >= SPHERE_HUGE)) {
        local = ((0.5f * ((d_10 + r1_1) + r2_3)) >= SPHERE_HUGE);
    } else {
        local = true;
    }
    let _e35 = local;
    if _e35 {
        return vec4<f32>(c1_1.x, c1_1.y, c1_1.z, SPHERE_HUGE);
    }
    if (abs((r1_1 - r2_3)) >= d_10) {
        if (r1_1 >= r2_3) {
            let rn = max(r1_1, (d_10 + r2_3));
            let _e50 = sphere_pad(rn, c1_1);
            return vec4<f32>(c1_1.x, c1_1.y, c1_1.z, (rn + _e50));
        }
        let rm = max(r2_3, (d_10 + r1_1));
        let _e58 = sphere_pad(rm, c2_1);
        return vec4<f32>(c2_1.x, c2_1.y, c2_1.z, (rm + _e58));
    }
    let r0_ = (0.5f * ((d_10 + r1_1) + r2_3));
    let c_17 = (c1_1 + (v_16 * ((r0_ - r1_1) / d_10)));
    let e1_ = (c_17 - c1_1);
    let e2_ = (c_17 - c2_1);
    let r_11 = max(r0_, max((sqrt(dot(e1_, e1_)) + r1_1), (sqrt(dot(e2_, e2_)) + r2_3)));
    let _e82 = sphere_pad(r_11, c_17);
    return vec4<f32>(c_17.x, c_17.y, c_17.z, (r_11 + _e82));
}

fn sphere_overlaps_aabb(c_2: vec3<f32>, r_2: f32, bmin: vec3<f32>, bmax: vec3<f32>) -> bool {
    let q_4 = clamp(c_2, bmin, bmax);
    let v_17 = (q_4 - c_2);
    return (dot(v_17, v_17) <= (r_2 * r_2));
}

fn groups_across(bw: u32, gw: u32) -> u32 {
    return (((bw + gw) - 1u) / gw);
}

fn group_count(bw_1: u32, bh: u32, gw_1: u32, gh: u32) -> u32 {
    let _e4 = groups_across(bw_1, gw_1);
    let _e5 = groups_across(bh, gh);
    return (_e4 * _e5);
}

fn group_first(g: u32, bw_2: u32, bh_1: u32, gw_2: u32, gh_1: u32) -> u32 {
    let _e5 = groups_across(bw_2, gw_2);
    let gx = (g % _e5);
    let gy = (g / _e5);
    let h_3 = min(gh_1, (bh_1 - (gh_1 * gy)));
    return (((gy * gh_1) * bw_2) + ((gx * gw_2) * h_3));
}

fn group_clusters(g_1: u32, bw_3: u32, bh_2: u32, gw_3: u32, gh_2: u32) -> u32 {
    let _e5 = groups_across(bw_3, gw_3);
    let gx_1 = (g_1 % _e5);
    let gy_1 = (g_1 / _e5);
    return (min(gw_3, (bw_3 - (gw_3 * gx_1))) * min(gh_2, (bh_2 - (gh_2 * gy_1))));
}

fn cluster_index(bx: u32, by: u32, bw_4: u32, bh_3: u32, gw_4: u32, gh_3: u32) -> u32 {
    let gx_2 = (bx / gw_4);
    let gy_2 = (by / gh_3);
    let w_15 = min(gw_4, (bw_4 - (gw_4 * gx_2)));
    let _e11 = groups_across(bw_4, gw_4);
    let g_2 = ((gy_2 * _e11) + gx_2);
    let _e14 = group_first(g_2, bw_4, bh_3, gw_4, gh_3);
    return ((_e14 + ((by - (gh_3 * gy_2)) * w_15)) + (bx - (gw_4 * gx_2)));
}

fn cluster_x(c_3: u32, bw_5: u32, bh_4: u32, gw_5: u32, gh_4: u32) -> u32 {
    let gy_3 = (c_3 / (gh_4 * bw_5));
    let h_4 = min(gh_4, (bh_4 - (gh_4 * gy_3)));
    let rest = (c_3 - ((gy_3 * gh_4) * bw_5));
    let gx_3 = (rest / (gw_5 * h_4));
    let w_16 = min(gw_5, (bw_5 - (gw_5 * gx_3)));
    return ((gx_3 * gw_5) + ((rest - ((gx_3 * gw_5) * h_4)) % w_16));
}

fn cluster_y(c_4: u32, bw_6: u32, bh_5: u32, gw_6: u32, gh_5: u32) -> u32 {
    let gy_4 = (c_4 / (gh_5 * bw_6));
    let h_5 = min(gh_5, (bh_5 - (gh_5 * gy_4)));
    let rest_1 = (c_4 - ((gy_4 * gh_5) * bw_6));
    let gx_4 = (rest_1 / (gw_6 * h_5));
    let w_17 = min(gw_6, (bw_6 - (gw_6 * gx_4)));
    return ((gy_4 * gh_5) + ((rest_1 - ((gx_4 * gw_6) * h_5)) / w_17));
}

fn map_index(tx: u32, ty: u32, side: u32) -> u32 {
    let b_7 = (side / 8u);
    let _e11 = cluster_index((tx / 8u), (ty / 8u), b_7, b_7, GROUP_SIDE, GROUP_SIDE);
    return (((_e11 * CLUSTER) + ((ty % 8u) * 8u)) + (tx % 8u));
}

fn map_x(q: u32, side_1: u32) -> u32 {
    let b_8 = (side_1 / 8u);
    let _e8 = cluster_x((q / CLUSTER), b_8, b_8, GROUP_SIDE, GROUP_SIDE);
    return ((_e8 * 8u) + (q % 8u));
}

fn map_y(q_1: u32, side_2: u32) -> u32 {
    let b_9 = (side_2 / 8u);
    let _e8 = cluster_y((q_1 / CLUSTER), b_9, b_9, GROUP_SIDE, GROUP_SIDE);
    return ((_e8 * 8u) + ((q_1 % CLUSTER) / 8u));
}

fn box_overlaps_box(lo1_: vec3<f32>, hi1_: vec3<f32>, lo2_: vec3<f32>, hi2_: vec3<f32>) -> bool {
    var local_1: bool;
    var local_2: bool;
    var local_3: bool;
    var local_4: bool;
    var local_5: bool;

    if (lo1_.x <= hi2_.x) {
        local_1 = (lo2_.x <= hi1_.x);
    } else {
        local_1 = false;
    }
    let _e13 = local_1;
    if _e13 {
        local_2 = (lo1_.y <= hi2_.y);
    } else {
        local_2 = false;
    }
    let _e20 = local_2;
    if _e20 {
        local_3 = (lo2_.y <= hi1_.y);
    } else {
        local_3 = false;
    }
    let _e27 = local_3;
    if _e27 {
        local_4 = (lo1_.z <= hi2_.z);
    } else {
        local_4 = false;
    }
    let _e34 = local_4;
    if _e34 {
        local_5 = (lo2_.z <= hi1_.z);
    } else {
        local_5 = false;
    }
    let _e41 = local_5;
    return _e41;
}

fn vpl_rt2_(flux: vec3<f32>, exposure_1: f32, error_bound_1: f32, mode_1: u32) -> f32 {
    let _e6 = intensity_measure((flux * INV_PI), mode_1);
    let _e7 = threshold_range2_(_e6, exposure_1, error_bound_1);
    return _e7;
}

fn range_radius(extent: f32, r2_4: f32) -> f32 {
    return (extent + sqrt(r2_4));
}

fn inverse_square(d2_5: f32) -> f32 {
    return (1f / max(d2_5, MIN_D2_));
}

fn connection_factor(cos_x: f32, d2_6: f32, rt2_3: f32, w: f32) -> f32 {
    let _e4 = inverse_square(d2_6);
    let _e6 = slc_weight(rt2_3, d2_6);
    return (((cos_x * _e4) * _e6) * w);
}

fn connection_cosine(x_6: vec3<f32>, y: vec3<f32>, n: vec3<f32>, ng: vec3<f32>, r2_5: f32) -> f32 {
    var local_6: bool;
    var local_7: bool;

    let v_18 = (x_6 - y);
    let d2_17 = dot(v_18, v_18);
    let _e7 = slc_keep(r2_5, d2_17);
    if !(!(_e7)) {
        local_6 = !((d2_17 > 0f));
    } else {
        local_6 = true;
    }
    let _e16 = local_6;
    if _e16 {
        return 0f;
    }
    let w_18 = (v_18 / vec3(sqrt(d2_17)));
    let cos_x_1 = -(dot(n, w_18));
    if !(!((cos_x_1 > 0f))) {
        local_7 = !((dot(ng, w_18) < 0f));
    } else {
        local_7 = true;
    }
    let _e34 = local_7;
    if _e34 {
        return 0f;
    }
    return cos_x_1;
}

fn vpl_lobe(n_1: vec3<f32>, w_1: vec3<f32>) -> f32 {
    return (max(dot(n_1, w_1), 0f) * INV_PI);
}

fn vpl_transfer(n_l: vec3<f32>, n_x: vec3<f32>, v_2: vec3<f32>, min_d2_: f32) -> f32 {
    let m = max(dot(v_2, v_2), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v_2), 0f) * max(-(dot(n_x, v_2)), 0f)) * INV_PI) / (m * m));
}

fn spot_falloff(cos_theta: f32, cos_outer: f32, cos_inner: f32, shape: f32) -> f32 {
    if (cos_inner <= cos_outer) {
        return select(0f, 1f, (cos_theta >= cos_outer));
    }
    let t_4 = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return select(((t_4 * t_4) * (3f - (2f * t_4))), (t_4 * t_4), (shape > 0.5f));
}

fn triangle_lobe(n_2: vec3<f32>, area: f32, w_2: vec3<f32>) -> f32 {
    return (area * max(dot(n_2, w_2), 0f));
}

fn triangle_sample(a_2: vec3<f32>, b_2: vec3<f32>, c_5: vec3<f32>, u1_: f32, u2_: f32) -> vec3<f32> {
    let su = sqrt(u1_);
    let b0_ = (1f - su);
    let b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_5 * ((1f - b0_) - b1_)));
}

fn area_to_solid_angle_pdf(pdf_area: f32, d2_7: f32, cos_light: f32) -> f32 {
    let c_18 = abs(cos_light);
    if (c_18 <= 0f) {
        return 0f;
    }
    return ((pdf_area * d2_7) / c_18);
}

fn atan_portable(x_7: f32) -> f32 {
    var base: f32 = 0f;
    var t: f32;

    let a_10 = abs(x_7);
    t = a_10;
    if (a_10 > 2.4142137f) {
        base = 1.5707964f;
        t = (-1f / a_10);
    } else {
        if (a_10 > 0.41421357f) {
            base = 0.7853982f;
            t = ((a_10 - 1f) / (a_10 + 1f));
        }
    }
    let _e18 = t;
    let _e19 = t;
    let z_3 = (_e18 * _e19);
    let _e21 = base;
    let _e33 = t;
    let _e35 = t;
    let r_12 = (_e21 + (((((((((0.080537446f * z_3) - 0.13877685f) * z_3) + 0.19977711f) * z_3) - 0.3333295f) * z_3) * _e33) + _e35));
    return select(r_12, -(r_12), (x_7 < 0f));
}

fn atan2_portable(y_1: f32, x_8: f32) -> f32 {
    if (x_8 == 0f) {
        if (y_1 > 0f) {
            return 1.5707964f;
        }
        if (y_1 < 0f) {
            return -1.5707964f;
        }
        return 0f;
    }
    let _e12 = atan_portable((y_1 / x_8));
    if (x_8 > 0f) {
        return _e12;
    }
    if (y_1 >= 0f) {
        return (_e12 + 3.1415927f);
    }
    return (_e12 - 3.1415927f);
}

fn ies_fold_c(c_6: f32, h_first: f32, h_last: f32) -> f32 {
    var a_3: f32;

    a_3 = (c_6 - (360f * floor((c_6 / 360f))));
    if (h_last <= 0f) {
        return 0f;
    }
    if (h_last <= 90f) {
        let _e15 = a_3;
        if (_e15 > 180f) {
            let _e18 = a_3;
            a_3 = (360f - _e18);
        }
        let _e21 = a_3;
        if (_e21 > 90f) {
            let _e24 = a_3;
            a_3 = (180f - _e24);
        }
        let _e27 = a_3;
        return _e27;
    }
    if (h_first >= 90f) {
        let _e30 = a_3;
        if (_e30 < 90f) {
            let _e33 = a_3;
            a_3 = (180f - _e33);
        } else {
            let _e36 = a_3;
            if (_e36 > 270f) {
                let _e39 = a_3;
                a_3 = (540f - _e39);
            }
        }
        let _e42 = a_3;
        return _e42;
    }
    if (h_last <= 180f) {
        let _e45 = a_3;
        if (_e45 > 180f) {
            let _e48 = a_3;
            a_3 = (360f - _e48);
        }
        let _e51 = a_3;
        return _e51;
    }
    let _e52 = a_3;
    return _e52;
}

fn ies_segment(tab_1: u32, start: u32, n_3: u32, x_9: f32) -> u32 {
    var lo: u32 = 0u;
    var hi: u32;

    if (n_3 < 2u) {
        return 0u;
    }
    hi = (n_3 - 1u);
    loop {
        let _e12 = hi;
        let _e13 = lo;
        if ((_e12 - _e13) > 1u) {
        } else {
            break;
        }
        {
            let _e17 = lo;
            let _e18 = hi;
            let mid = ((_e17 + _e18) >> 1u);
            let _e23 = at(tab_1, (start + mid));
            if (_e23 <= x_9) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
    let _e25 = lo;
    return _e25;
}

fn ies_lerp_t(a0_: f32, a1_: f32, x_10: f32) -> f32 {
    if (a1_ <= a0_) {
        return 0f;
    }
    return saturate(((x_10 - a0_) / (a1_ - a0_)));
}

fn ies_candela(tab_2: u32, base_1: u32, gamma: f32, c_7: f32) -> f32 {
    var local_8: bool;

    let _e4 = at(tab_2, base_1);
    let _e5 = to_u32_(_e4);
    let _e8 = at(tab_2, (base_1 + 1u));
    let _e9 = to_u32_(_e8);
    let v0_ = (base_1 + 2u);
    let h0_ = (v0_ + _e5);
    let c0_2 = (h0_ + _e9);
    let _e14 = at(tab_2, v0_);
    if !((gamma < _e14)) {
        let _e22 = at(tab_2, ((v0_ + _e5) - 1u));
        local_8 = (gamma > _e22);
    } else {
        local_8 = true;
    }
    let _e25 = local_8;
    if _e25 {
        return 0f;
    }
    let _e27 = at(tab_2, h0_);
    let _e31 = at(tab_2, ((h0_ + _e9) - 1u));
    let _e32 = ies_fold_c(c_7, _e27, _e31);
    let _e33 = ies_segment(tab_2, v0_, _e5, gamma);
    let _e34 = ies_segment(tab_2, h0_, _e9, _e32);
    let iv1_ = min((_e33 + 1u), (_e5 - 1u));
    let ih1_ = min((_e34 + 1u), (_e9 - 1u));
    let _e46 = at(tab_2, (v0_ + _e33));
    let _e48 = at(tab_2, (v0_ + iv1_));
    let _e49 = ies_lerp_t(_e46, _e48, gamma);
    let _e51 = at(tab_2, (h0_ + _e34));
    let _e53 = at(tab_2, (h0_ + ih1_));
    let _e54 = ies_lerp_t(_e51, _e53, _e32);
    let _e58 = at(tab_2, ((c0_2 + (_e34 * _e5)) + _e33));
    let _e65 = at(tab_2, ((c0_2 + (_e34 * _e5)) + iv1_));
    let a_11 = ((_e58 * (1f - _e49)) + (_e65 * _e49));
    let _e71 = at(tab_2, ((c0_2 + (ih1_ * _e5)) + _e33));
    let _e78 = at(tab_2, ((c0_2 + (ih1_ * _e5)) + iv1_));
    let b_10 = ((_e71 * (1f - _e49)) + (_e78 * _e49));
    return ((a_11 * (1f - _e54)) + (b_10 * _e54));
}

fn ies_candela_dir(tab_3: u32, base_2: u32, wn: f32, wr: f32, ws: f32) -> f32 {
    let _e9 = atan2_portable(sqrt(((wr * wr) + (ws * ws))), wn);
    let gamma_1 = degrees(_e9);
    let on_axis = ((abs(wr) + abs(ws)) <= 0f);
    let _e16 = atan2_portable(ws, wr);
    let c_19 = select(degrees(_e16), 0f, on_axis);
    let _e20 = ies_candela(tab_3, base_2, gamma_1, c_19);
    return _e20;
}

fn ies_light_candela(tab_4: u32, base_3: u32, nadir: vec3<f32>, reference: vec3<f32>, w_3: vec3<f32>) -> f32 {
    let side_3 = cross(reference, nadir);
    let _e9 = ies_candela_dir(tab_4, base_3, dot(w_3, nadir), dot(w_3, reference), dot(w_3, side_3));
    return _e9;
}

fn bsh_tail_key(radius: f32) -> u32 {
    let _e1 = f32_to_bits(radius);
    return ((_e1 & 2147483647u) >> 21u);
}

fn bsh_scaled_radius(node: BshNode, scale: f32) -> f32 {
    if (scale == 1f) {
        return node.radius;
    }
    if (node.child == BSH_NONE) {
        return (node.extent + (scale * (node.radius - node.extent)));
    }
    return (node.radius * scale);
}

fn bsh_range_bound(node_1: BshNode) -> f32 {
    if (node_1.child == BSH_NONE) {
        return (node_1.radius - node_1.extent);
    }
    let _e8 = f32_from_bits(node_1.light);
    return _e8;
}

fn bsh_reach_bound(node_2: BshNode, w_4: f32) -> f32 {
    let _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_4 * 1.001f) * _e5));
}

fn mul_hi_u32_(a_4: u32, b_3: u32) -> u32 {
    let a_lo = (a_4 & 65535u);
    let a_hi = (a_4 >> 16u);
    let b_lo = (b_3 & 65535u);
    let b_hi = (b_3 >> 16u);
    let ll = (a_lo * b_lo);
    let lh = (a_lo * b_hi);
    let hl = (a_hi * b_lo);
    let hh = (a_hi * b_hi);
    let mid_1 = (((ll >> 16u) + (lh & 65535u)) + (hl & 65535u));
    return (((hh + (lh >> 16u)) + (hl >> 16u)) + (mid_1 >> 16u));
}

fn uniform_index(n_4: u32, hi_1: u32, lo_1: u32) -> u32 {
    let _e3 = mul_lo_u32_(hi_1, n_4);
    let _e4 = mul_hi_u32_(hi_1, n_4);
    let _e5 = mul_hi_u32_(lo_1, n_4);
    if (_e3 > (4294967295u - _e5)) {
        return (_e4 + 1u);
    }
    return _e4;
}

fn reservoir_slot(n_5: u32, k: u32, hi_2: u32, lo_2: u32) -> u32 {
    if (n_5 <= k) {
        return (n_5 - 1u);
    }
    let _e7 = uniform_index(n_5, hi_2, lo_2);
    if (_e7 < k) {
        return _e7;
    }
    return k;
}

fn reservoir_takes(n_6: u32) -> bool {
    return (n_6 < RESERVOIR_FULL);
}

fn reservoir_weight(n_7: u32, k_1: u32) -> f32 {
    let _e2 = to_f32_(n_7);
    let _e3 = to_f32_(k_1);
    return max((_e2 / _e3), 1f);
}

fn weighted_replace(w_5: f32, w_sum: f32, u_2: f32) -> bool {
    return ((u_2 * w_sum) < w_5);
}

fn weighted_threshold(w_sum_1: f32, u_3: f32) -> f32 {
    return (w_sum_1 / (1f - u_3));
}

fn weighted_pick_weight(w_sum_2: f32, w_6: f32, k_2: u32) -> f32 {
    let _e3 = to_f32_(k_2);
    return (w_sum_2 / (_e3 * w_6));
}

fn reservoir_select_pdf(seen: u32, in_range: bool, k_3: u32) -> f32 {
    var others: u32;
    var local_9: bool;

    others = seen;
    if in_range {
        local_9 = (seen > 0u);
    } else {
        local_9 = false;
    }
    let _e9 = local_9;
    if _e9 {
        others = (seen - 1u);
    }
    let _e12 = others;
    let _e15 = reservoir_weight((_e12 + 1u), k_3);
    return (1f / _e15);
}

fn resample_target(c_8: vec3<f32>) -> f32 {
    return (((c_8.x + c_8.y) + c_8.z) * 0.33333334f);
}

fn slot_target(c_9: vec3<f32>, slot: u32, k_4: u32) -> f32 {
    if (k_4 < 3u) {
        let _e5 = resample_target(c_9);
        return _e5;
    }
    let j = (slot % 3u);
    if (j == 0u) {
        return c_9.x;
    }
    if (j == 1u) {
        return c_9.y;
    }
    return c_9.z;
}

fn slot_share(slot_1: u32, k_5: u32) -> vec3<f32> {
    if (k_5 < 3u) {
        let _e4 = to_f32_(k_5);
        let w_19 = (1f / _e4);
        return vec3<f32>(w_19, w_19, w_19);
    }
    let j_1 = (slot_1 % 3u);
    let _e15 = to_f32_((((k_5 + 2u) - j_1) / 3u));
    let w_20 = (1f / _e15);
    if (j_1 == 0u) {
        return vec3<f32>(w_20, 0f, 0f);
    }
    if (j_1 == 1u) {
        return vec3<f32>(0f, w_20, 0f);
    }
    return vec3<f32>(0f, 0f, w_20);
}

fn grid_coordinate(bits_2: u32) -> f32 {
    let _e3 = to_f32_((bits_2 >> 16u));
    return ((_e3 + 0.5f) / 65536f);
}

fn grid_cells(h1_: u32, h2_: u32) -> u32 {
    return ((h1_ & 4294901760u) | (h2_ >> 16u));
}

fn disk_offset(r_3: f32, u1_1: f32, u2_1: f32) -> vec2<f32> {
    let a_12 = (TWO_PI * u2_1);
    return (vec2<f32>(cos(a_12), sin(a_12)) * (r_3 * sqrt(u1_1)));
}

fn gris_weight(own: f32, all_: f32, p_hat: f32, w_7: f32) -> f32 {
    if !((all_ > 0f)) {
        return 0f;
    }
    return (((own / all_) * p_hat) * w_7);
}

fn reuse_trust(h: vec3<f32>, t_1: vec3<f32>) -> f32 {
    let d2_18 = dot(h, h);
    if !((d2_18 > 0f)) {
        return 1f;
    }
    let c_20 = (h - t_1);
    return (d2_18 / (d2_18 + (REUSE_TRUST_SCALE * dot(c_20, c_20))));
}

fn gris_contribution_weight(w_sum_3: f32, p_hat_1: f32) -> f32 {
    if !((p_hat_1 > 0f)) {
        return 0f;
    }
    return (w_sum_3 / p_hat_1);
}

fn alias_choice(column: u32, other: u32, keep: f32, u_4: f32) -> u32 {
    return select(other, column, (u_4 < keep));
}

fn uniform_light(u_5: f32, n_8: u32) -> u32 {
    let _e2 = to_f32_(n_8);
    let _e4 = to_u32_((u_5 * _e2));
    return min(_e4, (n_8 - 1u));
}

fn mis_balance(pdf_a: f32, pdf_b: f32) -> f32 {
    let s = (pdf_a + pdf_b);
    if (s <= 0f) {
        return 0f;
    }
    return (pdf_a / s);
}

fn mis_power(pdf_a_1: f32, pdf_b_1: f32) -> f32 {
    let a2_ = (pdf_a_1 * pdf_a_1);
    let s_1 = (a2_ + (pdf_b_1 * pdf_b_1));
    if (s_1 <= 0f) {
        return 0f;
    }
    return (a2_ / s_1);
}

fn light_strategy_pdf(select_: f32, rt2_4: f32, d2_8: f32, area_1: f32, cos_y: f32) -> f32 {
    var local_10: bool;
    var local_11: bool;

    if !((d2_8 <= 0f)) {
        local_10 = (area_1 <= 0f);
    } else {
        local_10 = true;
    }
    let _e13 = local_10;
    if !(_e13) {
        local_11 = (cos_y <= 0f);
    } else {
        local_11 = true;
    }
    let _e20 = local_11;
    if _e20 {
        return 0f;
    }
    let _e22 = rr_probability(rt2_4, d2_8);
    let _e26 = area_to_solid_angle_pdf((1f / area_1), d2_8, cos_y);
    return ((select_ * _e22) * _e26);
}

fn lambert_brdf(rho: vec3<f32>) -> vec3<f32> {
    return (rho * INV_PI);
}

fn cosine_pdf(cos_theta_1: f32) -> f32 {
    return (max(cos_theta_1, 0f) * INV_PI);
}

fn onb_tangent(n_9: vec3<f32>) -> vec3<f32> {
    let s_2 = select(-1f, 1f, (n_9.z >= 0f));
    let a_13 = (-1f / (s_2 + n_9.z));
    return vec3<f32>((1f + (((s_2 * n_9.x) * n_9.x) * a_13)), (((s_2 * n_9.x) * n_9.y) * a_13), (-(s_2) * n_9.x));
}

fn onb_bitangent(n_10: vec3<f32>) -> vec3<f32> {
    let s_3 = select(-1f, 1f, (n_10.z >= 0f));
    let a_14 = (-1f / (s_3 + n_10.z));
    return vec3<f32>(((n_10.x * n_10.y) * a_14), (s_3 + ((n_10.y * n_10.y) * a_14)), -(n_10.y));
}

fn onb_to_world(n_11: vec3<f32>, d: vec3<f32>) -> vec3<f32> {
    let _e2 = onb_tangent(n_11);
    let _e5 = onb_bitangent(n_11);
    return (((_e2 * d.x) + (_e5 * d.y)) + (n_11 * d.z));
}

fn onb_to_local(n_12: vec3<f32>, w_8: vec3<f32>) -> vec3<f32> {
    let _e2 = onb_tangent(n_12);
    let _e4 = onb_bitangent(n_12);
    return vec3<f32>(dot(w_8, _e2), dot(w_8, _e4), dot(w_8, n_12));
}

fn cosine_direction(n_13: vec3<f32>, u1_2: f32, u2_2: f32) -> vec3<f32> {
    let r_13 = sqrt(u1_2);
    let phi_5 = (6.2831855f * u2_2);
    let _e16 = onb_to_world(n_13, vec3<f32>((r_13 * cos(phi_5)), (r_13 * sin(phi_5)), sqrt(max((1f - u1_2), 0f))));
    return normalize(_e16);
}

fn ggx_alpha(roughness: f32) -> f32 {
    return max((roughness * roughness), GGX_ALPHA_MIN);
}

fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
    if (cos_h <= 0f) {
        return 0f;
    }
    let a2_1 = (alpha * alpha);
    let t_5 = (((cos_h * cos_h) * a2_1) + sin2_h);
    return ((a2_1 * INV_PI) / (t_5 * t_5));
}

fn smith_root(cos_: f32, alpha_1: f32) -> f32 {
    let a2_2 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1f - a2_2)) + a2_2));
}

fn smith_visibility(n_l_1: f32, n_v: f32, alpha_2: f32) -> f32 {
    var local_12: bool;

    if !((n_l_1 <= 0f)) {
        local_12 = (n_v <= 0f);
    } else {
        local_12 = true;
    }
    let _e11 = local_12;
    if _e11 {
        return 0f;
    }
    let _e13 = smith_root(n_v, alpha_2);
    let _e15 = smith_root(n_l_1, alpha_2);
    return (0.5f / ((n_l_1 * _e13) + (n_v * _e15)));
}

fn fresnel_schlick(f0_: vec3<f32>, f90_: f32, v_h: f32) -> vec3<f32> {
    let c_21 = saturate((1f - v_h));
    let c2_3 = (c_21 * c_21);
    return (f0_ + ((vec3<f32>(f90_, f90_, f90_) - f0_) * ((c2_3 * c2_3) * c_21)));
}

fn specular_fresnel(base_4: vec3<f32>, metallic: f32, f0_d: vec3<f32>, f90_d: f32, v_h_1: f32) -> vec3<f32> {
    let _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    let _e10 = fresnel_schlick(base_4, 1f, v_h_1);
    return ((_e5 * (1f - metallic)) + (_e10 * metallic));
}

fn diffuse_brdf(base_5: vec3<f32>, metallic_1: f32, f0_d_1: vec3<f32>, f90_d_1: f32, v_h_2: f32) -> vec3<f32> {
    let _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return ((((vec3<f32>(1f, 1f, 1f) - _e9) * base_5) * (1f - metallic_1)) * INV_PI);
}

fn half_cosine(v_3: vec3<f32>, l: vec3<f32>) -> f32 {
    let h_6 = (v_3 + l);
    let len2_ = dot(h_6, h_6);
    if (len2_ <= 0f) {
        return 0f;
    }
    return saturate((dot(v_3, h_6) / sqrt(len2_)));
}

fn specular_brdf(base_6: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n_14: vec3<f32>, v_4: vec3<f32>, l_1: vec3<f32>) -> vec3<f32> {
    var local_13: bool;

    let n_l_2 = dot(n_14, l_1);
    let n_v_3 = dot(n_14, v_4);
    if !((n_l_2 <= 0f)) {
        local_13 = (n_v_3 <= 0f);
    } else {
        local_13 = true;
    }
    let _e18 = local_13;
    if _e18 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let hs = (v_4 + l_1);
    let inv = (1f / sqrt(dot(hs, hs)));
    let h_7 = (hs * inv);
    let c_22 = cross(n_14, h_7);
    let _e32 = ggx_d(dot(n_14, h_7), dot(c_22, c_22), alpha_3);
    let _e34 = specular_fresnel(base_6, metallic_2, f0_d_2, f90_d_2, dot(v_4, h_7));
    let _e35 = smith_visibility(n_l_2, n_v_3, alpha_3);
    return (_e34 * (_e32 * _e35));
}

fn brdf_eval(base_7: vec3<f32>, metallic_3: f32, f0_d_3: vec3<f32>, f90_d_3: f32, alpha_4: f32, n_15: vec3<f32>, v_5: vec3<f32>, l_2: vec3<f32>) -> vec3<f32> {
    if (dot(n_15, l_2) <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = half_cosine(v_5, l_2);
    let _e16 = diffuse_brdf(base_7, metallic_3, f0_d_3, f90_d_3, _e15);
    let _e17 = specular_brdf(base_7, metallic_3, f0_d_3, f90_d_3, alpha_4, n_15, v_5, l_2);
    return (_e16 + _e17);
}

fn diffuse_albedo(base_8: vec3<f32>, metallic_4: f32) -> vec3<f32> {
    return (base_8 * (1f - metallic_4));
}

fn specular_correction(base_9: vec3<f32>, metallic_5: f32, f0_d_4: vec3<f32>, f90_d_4: f32, alpha_5: f32, n_16: vec3<f32>, v_6: vec3<f32>, l_3: vec3<f32>) -> vec3<f32> {
    let _e8 = brdf_eval(base_9, metallic_5, f0_d_4, f90_d_4, alpha_5, n_16, v_6, l_3);
    let _e9 = diffuse_albedo(base_9, metallic_5);
    return (_e8 - (_e9 * INV_PI));
}

fn has_specular(metallic_6: f32, f0_d_5: vec3<f32>, f90_d_5: f32) -> bool {
    var local_14: bool;
    var local_15: bool;

    if !((metallic_6 > 0f)) {
        local_14 = (f90_d_5 > 0f);
    } else {
        local_14 = true;
    }
    let _e11 = local_14;
    if !(_e11) {
        local_15 = (max(max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0f);
    } else {
        local_15 = true;
    }
    let _e23 = local_15;
    return _e23;
}

fn channel_mean(c_10: vec3<f32>) -> f32 {
    return (((c_10.x + c_10.y) + c_10.z) * 0.33333334f);
}

fn receiver_lobe(base_10: vec3<f32>, metallic_7: f32, f0_d_6: vec3<f32>, f90_d_6: f32, alpha_6: f32, n_v_1: f32) -> vec4<f32> {
    var local_16: bool;

    let _e10 = fresnel_schlick(f0_d_6, f90_d_6, n_v_1);
    let _e16 = channel_mean((((vec3<f32>(1f, 1f, 1f) - _e10) * base_10) * (1f - metallic_7)));
    if !((n_v_1 <= 0f)) {
        let _e22 = has_specular(metallic_7, f0_d_6, f90_d_6);
        local_16 = !(_e22);
    } else {
        local_16 = true;
    }
    let _e25 = local_16;
    if _e25 {
        return vec4<f32>(_e16, 0f, alpha_6, n_v_1);
    }
    let _e28 = specular_fresnel(base_10, metallic_7, f0_d_6, f90_d_6, n_v_1);
    let _e29 = channel_mean(_e28);
    return vec4<f32>(_e16, _e29, alpha_6, n_v_1);
}

fn specular_probability(lobe: vec4<f32>) -> f32 {
    if (lobe.y <= 0f) {
        return 0f;
    }
    if (lobe.x <= 0f) {
        return 1f;
    }
    return clamp((lobe.y / (lobe.y + lobe.x)), 0.1f, 0.9f);
}

fn specular_peak_factor(lobe_1: vec4<f32>) -> f32 {
    let _e6 = smith_root(lobe_1.w, lobe_1.z);
    return ((lobe_1.y * 0.5f) / (_e6 + max(lobe_1.w, 0f)));
}

fn receiver_peak(lobe_2: vec4<f32>) -> f32 {
    let _e2 = specular_peak_factor(lobe_2);
    return (lobe_2.x + (_e2 / (lobe_2.z * lobe_2.z)));
}

fn range_scale(lobe_3: vec4<f32>) -> f32 {
    if (lobe_3.y <= 0f) {
        return 1f;
    }
    let _e5 = receiver_peak(lobe_3);
    return clamp(_e5, 1f, RANGE_SCALE_MAX);
}

fn range_lobe(lobe_4: vec4<f32>) -> vec4<f32> {
    if (lobe_4.y <= 0f) {
        return vec4<f32>(1f, 0f, 1f, 1f);
    }
    let _e10 = specular_peak_factor(lobe_4);
    let _e14 = range_scale(lobe_4);
    return vec4<f32>(lobe_4.x, _e10, (lobe_4.z * lobe_4.z), sqrt(_e14));
}

fn mirror_dir(n_17: vec3<f32>, v_7: vec3<f32>) -> vec3<f32> {
    return ((n_17 * (2f * dot(n_17, v_7))) - v_7);
}

fn bounded_vndf_k(wi: vec3<f32>, alpha_7: f32) -> f32 {
    let a_15 = saturate(alpha_7);
    let s_4 = (1f + sqrt(((wi.x * wi.x) + (wi.y * wi.y))));
    let a2_3 = (a_15 * a_15);
    let s2_ = (s_4 * s_4);
    return (((1f - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z)));
}

fn ggx_vndf_sample(wi_1: vec3<f32>, alpha_8: f32, u1_3: f32, u2_3: f32) -> vec3<f32> {
    let wi_std = normalize(vec3<f32>((wi_1.x * alpha_8), (wi_1.y * alpha_8), wi_1.z));
    let _e12 = bounded_vndf_k(wi_1, alpha_8);
    let b_11 = select(wi_std.z, (_e12 * wi_std.z), (wi_1.z > 0f));
    let phi_6 = (6.2831855f * u1_3);
    let z_4 = (((1f - u2_3) * (1f + b_11)) - b_11);
    let sin_t = sqrt(saturate((1f - (z_4 * z_4))));
    let m_std = (wi_std + vec3<f32>((sin_t * cos(phi_6)), (sin_t * sin(phi_6)), z_4));
    let m_1 = normalize(vec3<f32>((m_std.x * alpha_8), (m_std.y * alpha_8), m_std.z));
    return ((m_1 * (2f * dot(wi_1, m_1))) - wi_1);
}

fn ggx_vndf_pdf(wi_2: vec3<f32>, wo: vec3<f32>, alpha_9: f32) -> f32 {
    var local_17: bool;

    if !((wi_2.z <= 0f)) {
        local_17 = (wo.z <= 0f);
    } else {
        local_17 = true;
    }
    let _e13 = local_17;
    if _e13 {
        return 0f;
    }
    let hs_1 = (wi_2 + wo);
    let m_2 = (hs_1 / vec3(sqrt(dot(hs_1, hs_1))));
    let _e28 = ggx_d(m_2.z, ((m_2.x * m_2.x) + (m_2.y * m_2.y)), alpha_9);
    let t_6 = sqrt((((alpha_9 * alpha_9) * ((wi_2.x * wi_2.x) + (wi_2.y * wi_2.y))) + (wi_2.z * wi_2.z)));
    let _e43 = bounded_vndf_k(wi_2, alpha_9);
    return (_e28 / (2f * ((_e43 * wi_2.z) + t_6)));
}

fn bsdf_sample(n_18: vec3<f32>, v_8: vec3<f32>, alpha_10: f32, p_spec: f32, u1_4: f32, u2_4: f32) -> vec3<f32> {
    if (u1_4 < p_spec) {
        if (dot(n_18, v_8) <= 0f) {
            return -(n_18);
        }
        let _e11 = onb_to_local(n_18, v_8);
        let _e13 = ggx_vndf_sample(_e11, alpha_10, (u1_4 / p_spec), u2_4);
        let _e14 = onb_to_world(n_18, _e13);
        return normalize(_e14);
    }
    let _e20 = cosine_direction(n_18, ((u1_4 - p_spec) / (1f - p_spec)), u2_4);
    return _e20;
}

fn bsdf_pdf(n_19: vec3<f32>, v_9: vec3<f32>, l_4: vec3<f32>, alpha_11: f32, p_spec_1: f32) -> f32 {
    let _e6 = cosine_pdf(dot(n_19, l_4));
    if (p_spec_1 <= 0f) {
        return _e6;
    }
    let _e9 = onb_to_local(n_19, v_9);
    let _e10 = onb_to_local(n_19, l_4);
    let _e11 = ggx_vndf_pdf(_e9, _e10, alpha_11);
    return ((p_spec_1 * _e11) + ((1f - p_spec_1) * _e6));
}

fn bevy_alpha(perceptual: f32) -> f32 {
    let r_14 = clamp(perceptual, 0.089f, 1f);
    return (r_14 * r_14);
}

fn bevy_f0_(reflectance: f32) -> f32 {
    return ((0.16f * reflectance) * reflectance);
}

fn bevy_dfg(r_4: f32, n_v_2: f32) -> f32 {
    let rx = (1f - r_4);
    let a004_ = ((min((rx * rx), exp2((-9.28f * n_v_2))) * rx) + (0.0425f - (0.0275f * r_4)));
    let x_18 = max(((1.04f - (0.572f * r_4)) - (1.04f * a004_)), 0.00005f);
    let y_3 = max((((0.022f * r_4) - 0.04f) + (1.04f * a004_)), 0.00005f);
    return (x_18 + y_3);
}

fn bevy_brdf(base_11: vec3<f32>, metallic_8: f32, r_5: f32, reflectance_1: f32, n_20: vec3<f32>, v_10: vec3<f32>, l_5: vec3<f32>) -> vec3<f32> {
    let n_l_3 = saturate(dot(n_20, l_5));
    if (n_l_3 <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = bevy_alpha(r_5);
    let n_v_4 = max(dot(n_20, v_10), 0.0001f);
    let h_8 = normalize((l_5 + v_10));
    let n_h = saturate(dot(n_20, h_8));
    let l_h = saturate(dot(l_5, h_8));
    let f90_d_7 = (0.5f + (((2f * _e15) * l_h) * l_h));
    let _e35 = fresnel_schlick(vec3<f32>(1f, 1f, 1f), f90_d_7, n_l_3);
    let _e41 = fresnel_schlick(vec3<f32>(1f, 1f, 1f), f90_d_7, n_v_4);
    let burley = ((_e35.x * _e41.x) * INV_PI);
    let _e46 = bevy_f0_(reflectance_1);
    let f0_1 = ((vec3<f32>(_e46, _e46, _e46) * (1f - metallic_8)) + (base_11 * metallic_8));
    let f90_1 = saturate((((f0_1.x + f0_1.y) + f0_1.z) * 16.5f));
    let _e64 = ggx_d(n_h, (1f - (n_h * n_h)), _e15);
    let _e65 = smith_visibility(n_l_3, n_v_4, _e15);
    let _e70 = bevy_dfg(r_5, n_v_4);
    let comp = (vec3<f32>(1f, 1f, 1f) + (f0_1 * ((1f / _e70) - 1f)));
    let _e77 = fresnel_schlick(f0_1, f90_1, l_h);
    let spec = ((_e77 * comp) * (_e64 * _e65));
    return ((base_11 * ((1f - metallic_8) * burley)) + spec);
}

fn cos_sub_clamped(sin_a: f32, cos_a: f32, sin_b: f32, cos_b: f32) -> f32 {
    if (cos_a > cos_b) {
        return 1f;
    }
    return ((cos_a * cos_b) + (sin_a * sin_b));
}

fn sin_sub_clamped(sin_a_1: f32, cos_a_1: f32, sin_b_1: f32, cos_b_1: f32) -> f32 {
    if (cos_a_1 > cos_b_1) {
        return 0f;
    }
    return ((sin_a_1 * cos_b_1) - (cos_a_1 * sin_b_1));
}

fn safe_sqrt(x_11: f32) -> f32 {
    return sqrt(max(x_11, 0f));
}

fn subtended_cos(dist2_: f32, r2_6: f32) -> f32 {
    let _e5 = safe_sqrt((1f - (r2_6 / dist2_)));
    return select(_e5, -1f, (dist2_ <= r2_6));
}

fn emitter_cone(center: vec3<f32>, radius_1: f32, axis: vec3<f32>, cos_o: f32, p: vec3<f32>) -> vec4<f32> {
    var local_18: bool;

    let v_19 = (p - center);
    let dist2_1 = dot(v_19, v_19);
    let r2_11 = (radius_1 * radius_1);
    if (dist2_1 <= 0f) {
        local_18 = (r2_11 <= 0f);
    } else {
        local_18 = false;
    }
    let _e15 = local_18;
    if _e15 {
        return vec4<f32>(-2f, 0.000000000001f, -1f, 0f);
    }
    let d2_19 = max(max(dist2_1, r2_11), MIN_D2_);
    let wi_3 = select(vec3<f32>(0f, 0f, 0f), (v_19 / vec3(sqrt(dist2_1))), (dist2_1 > 0f));
    let cos_w = dot(axis, wi_3);
    let _e38 = safe_sqrt((1f - (cos_w * cos_w)));
    let _e39 = subtended_cos(dist2_1, r2_11);
    let _e43 = safe_sqrt((1f - (_e39 * _e39)));
    let _e47 = safe_sqrt((1f - (cos_o * cos_o)));
    let _e48 = cos_sub_clamped(_e38, cos_w, _e47, cos_o);
    let _e49 = sin_sub_clamped(_e38, cos_w, _e47, cos_o);
    let _e50 = cos_sub_clamped(_e49, _e48, _e43, _e39);
    return vec4<f32>(_e50, d2_19, _e39, _e43);
}

fn emitter_importance(center_1: vec3<f32>, radius_2: f32, phi: f32, axis_1: vec3<f32>, cos_o_1: f32, cos_e: f32, p_1: vec3<f32>) -> f32 {
    let _e7 = emitter_cone(center_1, radius_2, axis_1, cos_o_1, p_1);
    if (_e7.x <= cos_e) {
        return 0f;
    }
    return ((phi * _e7.x) / _e7.y);
}

fn cone_cos_of(v_11: vec3<f32>, d2_9: f32, a_5: f32, d_1: vec3<f32>) -> f32 {
    var local_19: bool;
    var local_20: bool;

    let vd = dot(v_11, d_1);
    let h2_1 = (d2_9 - (a_5 * a_5));
    if !((h2_1 <= 0f)) {
        if (vd >= 0f) {
            local_20 = ((vd * vd) >= h2_1);
        } else {
            local_20 = false;
        }
        let _e19 = local_20;
        local_19 = _e19;
    } else {
        local_19 = true;
    }
    let _e21 = local_19;
    if _e21 {
        return 1f;
    }
    let c_23 = cross(v_11, d_1);
    return min((((vd * sqrt(h2_1)) + (sqrt(dot(c_23, c_23)) * a_5)) / d2_9), 1f);
}

fn cone_cos_toward(center_2: vec3<f32>, radius_3: f32, p_2: vec3<f32>, d_2: vec3<f32>) -> f32 {
    let v_20 = (center_2 - p_2);
    let _e6 = cone_cos_of(v_20, dot(v_20, v_20), radius_3, d_2);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_7 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_7 * t_7))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_3: vec3<f32>, radius_4: f32, p_3: vec3<f32>, r_6: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_3, radius_4, p_3, r_6);
    let _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

fn light_importance(center_4: vec3<f32>, radius_5: f32, phi_1: f32, axis_2: vec3<f32>, cos_o_2: f32, cos_e_1: f32, p_4: vec3<f32>, n_21: vec3<f32>) -> f32 {
    var imp: f32;

    let _e8 = emitter_cone(center_4, radius_5, axis_2, cos_o_2, p_4);
    if (_e8.x <= cos_e_1) {
        return 0f;
    }
    imp = ((phi_1 * _e8.x) / _e8.y);
    if (dot(n_21, n_21) > 0f) {
        let v_21 = (center_4 - p_4);
        let dist2_2 = dot(v_21, v_21);
        let cos_i = dot(select(vec3<f32>(0f, 0f, 0f), (v_21 / vec3(sqrt(dist2_2))), (dist2_2 > 0f)), n_21);
        let _e33 = imp;
        let _e37 = safe_sqrt((1f - (cos_i * cos_i)));
        let _e40 = cos_sub_clamped(_e37, cos_i, _e8.w, _e8.z);
        imp = (_e33 * max(_e40, 0f));
    }
    let _e44 = imp;
    return max(_e44, 0f);
}

fn glossy_importance(center_5: vec3<f32>, radius_6: f32, phi_2: f32, axis_3: vec3<f32>, cos_o_3: f32, cos_e_2: f32, p_5: vec3<f32>, n_22: vec3<f32>, r_7: vec3<f32>, lobe_5: vec4<f32>) -> f32 {
    var local_21: bool;

    let _e10 = emitter_importance(center_5, radius_6, phi_2, axis_3, cos_o_3, cos_e_2, p_5);
    let _e11 = cone_cos_toward(center_5, radius_6, p_5, n_22);
    if !((_e10 <= 0f)) {
        local_21 = (_e11 <= 0f);
    } else {
        local_21 = true;
    }
    let _e20 = local_21;
    if _e20 {
        return 0f;
    }
    let _e22 = cone_cos_toward(center_5, radius_6, p_5, r_7);
    let _e27 = safe_sqrt((0.5f + (0.5f * _e22)));
    let _e33 = ggx_d(_e27, (1f - (_e27 * _e27)), lobe_5.z);
    let _e39 = smith_root(lobe_5.w, lobe_5.z);
    let spec_1 = (((lobe_5.y * _e33) * 0.25f) / _e39);
    return (_e10 * (((lobe_5.x * INV_PI) * _e11) + spec_1));
}

fn receiver_importance(center_6: vec3<f32>, radius_7: f32, phi_3: f32, axis_4: vec3<f32>, cos_o_4: f32, cos_e_3: f32, p_6: vec3<f32>, n_23: vec3<f32>, r_8: vec3<f32>, lobe_6: vec4<f32>) -> f32 {
    if (lobe_6.y <= 0f) {
        let _e13 = light_importance(center_6, radius_7, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_23);
        return _e13;
    }
    let _e14 = glossy_importance(center_6, radius_7, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_23, r_8, lobe_6);
    return _e14;
}

fn candidate_weight(importance: f32, rt2_5: f32, d2_10: f32) -> f32 {
    let _e3 = slc_weight(rt2_5, d2_10);
    return (importance * _e3);
}

fn cone_weight(center_7: vec3<f32>, radius_8: f32, phi_4: f32, axis_5: vec3<f32>, cos_o_5: f32, cos_e_4: f32, rt2_6: f32, p_7: vec3<f32>, n_24: vec3<f32>, r_9: vec3<f32>, lobe_7: vec4<f32>) -> f32 {
    let v_22 = (p_7 - center_7);
    if (lobe_7.y <= 0f) {
        let _e15 = light_importance(center_7, radius_8, phi_4, axis_5, cos_o_5, cos_e_4, p_7, n_24);
        let _e19 = candidate_weight((_e15 * INV_PI), rt2_6, dot(v_22, v_22));
        return _e19;
    }
    let _e20 = glossy_importance(center_7, radius_8, phi_4, axis_5, cos_o_5, cos_e_4, p_7, n_24, r_9, lobe_7);
    let _e22 = candidate_weight(_e20, rt2_6, dot(v_22, v_22));
    return _e22;
}

fn weighted_select_pdf(w_9: f32, w_sum_4: f32, in_range_1: bool, k_6: u32) -> f32 {
    if (w_9 <= 0f) {
        return 0f;
    }
    let total = select((w_sum_4 + w_9), w_sum_4, in_range_1);
    let _e9 = to_f32_(k_6);
    return ((_e9 * w_9) / total);
}

fn bvh_first_prob(c0_: f32, c1_2: f32) -> f32 {
    let s_5 = (c0_ + c1_2);
    if (s_5 > 0f) {
        return (c0_ / s_5);
    }
    return -1f;
}

fn bvh_remap_u(u_6: f32, p0_: f32, first: bool) -> f32 {
    if first {
        return min((u_6 / p0_), ONE_MINUS_EPSILON);
    }
    return clamp(((u_6 - p0_) / (1f - p0_)), 0f, ONE_MINUS_EPSILON);
}

fn finite3_(v_12: vec3<f32>) -> bool {
    var local_22: bool;
    var local_23: bool;

    if (abs(v_12.x) <= F32_MAX) {
        local_22 = (abs(v_12.y) <= F32_MAX);
    } else {
        local_22 = false;
    }
    let _e12 = local_22;
    if _e12 {
        local_23 = (abs(v_12.z) <= F32_MAX);
    } else {
        local_23 = false;
    }
    let _e20 = local_23;
    return _e20;
}

fn surface_offset(diag: f32) -> f32 {
    return (0.00001f * diag);
}

fn ray_t_min(diag_1: f32) -> f32 {
    return (0.000001f * diag_1);
}

fn shadow_margin(len: f32) -> f32 {
    return (0.0001f * len);
}

fn ray_inverse(x_12: f32) -> f32 {
    return (1f / select(x_12, 0.000000000000000000000000000001f, (abs(x_12) < 0.000000000000000000000000000001f)));
}

fn ray_inverse3_(d_3: vec3<f32>) -> vec3<f32> {
    let _e2 = ray_inverse(d_3.x);
    let _e4 = ray_inverse(d_3.y);
    let _e6 = ray_inverse(d_3.z);
    return vec3<f32>(_e2, _e4, _e6);
}

fn ray_aabb(o: vec3<f32>, inv_d: vec3<f32>, bmin_1: vec3<f32>, bmax_1: vec3<f32>, t_max: f32) -> f32 {
    let t0_ = ((bmin_1 - o) * inv_d);
    let t1_ = ((bmax_1 - o) * inv_d);
    let lo_3 = min(t0_, t1_);
    let hi_3 = max(t0_, t1_);
    let t_in = max(max(lo_3.x, lo_3.y), max(lo_3.z, 0f));
    let t_out = min(min(hi_3.x, hi_3.y), min(hi_3.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1f;
}

fn triangle_normal(a_6: vec3<f32>, b_4: vec3<f32>, c_11: vec3<f32>) -> vec3<f32> {
    var local_24: bool;

    let n_37 = cross((b_4 - a_6), (c_11 - a_6));
    let l2_ = dot(n_37, n_37);
    if !(!((l2_ > 0f))) {
        local_24 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_24 = true;
    }
    let _e17 = local_24;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_37 / vec3(sqrt(l2_)));
}

fn face_against(n_25: vec3<f32>, dir: vec3<f32>) -> vec3<f32> {
    return select(n_25, -(n_25), (dot(n_25, dir) > 0f));
}

fn barycentric(p_8: vec3<f32>, a_7: vec3<f32>, b_5: vec3<f32>, c_12: vec3<f32>) -> vec3<f32> {
    let e1_1 = (b_5 - a_7);
    let e2_1 = (c_12 - a_7);
    let q_5 = (p_8 - a_7);
    let d11_ = dot(e1_1, e1_1);
    let d12_ = dot(e1_1, e2_1);
    let d22_ = dot(e2_1, e2_1);
    let den = ((d11_ * d22_) - (d12_ * d12_));
    if !((abs(den) > 0f)) {
        return vec3<f32>(1f, 0f, 0f);
    }
    let w1_ = (((d22_ * dot(q_5, e1_1)) - (d12_ * dot(q_5, e2_1))) / den);
    let w2_ = (((d11_ * dot(q_5, e2_1)) - (d12_ * dot(q_5, e1_1))) / den);
    return vec3<f32>(((1f - w1_) - w2_), w1_, w2_);
}

fn shading_normal(n0_: vec3<f32>, n1_: vec3<f32>, n2_: vec3<f32>, w_10: vec3<f32>, facing: vec3<f32>) -> vec3<f32> {
    var local_25: bool;

    let s_6 = (((n0_ * w_10.x) + (n1_ * w_10.y)) + (n2_ * w_10.z));
    let l2_1 = dot(s_6, s_6);
    if !(!((l2_1 > 0.000000000001f))) {
        local_25 = !((l2_1 < 300000000000000000000000000000000000000f));
    } else {
        local_25 = true;
    }
    let _e24 = local_25;
    if _e24 {
        return facing;
    }
    let n_38 = (s_6 / vec3(sqrt(l2_1)));
    return select(n_38, -(n_38), (dot(n_38, facing) < 0f));
}

fn ray_triangle(o_1: vec3<f32>, d_4: vec3<f32>, a_8: vec3<f32>, b_6: vec3<f32>, c_13: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_26: bool;
    var local_27: bool;
    var local_28: bool;

    let e1_2 = (b_6 - a_8);
    let e2_2 = (c_13 - a_8);
    let p_12 = cross(d_4, e2_2);
    let det = dot(e1_2, p_12);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv_1 = (1f / det);
    let s_7 = (o_1 - a_8);
    let u_8 = (dot(s_7, p_12) * inv_1);
    if !((u_8 < 0f)) {
        local_26 = (u_8 > 1f);
    } else {
        local_26 = true;
    }
    let _e28 = local_26;
    if _e28 {
        return -1f;
    }
    let q_6 = cross(s_7, e1_2);
    let v_23 = (dot(d_4, q_6) * inv_1);
    if !((v_23 < 0f)) {
        local_27 = ((u_8 + v_23) > 1f);
    } else {
        local_27 = true;
    }
    let _e42 = local_27;
    if _e42 {
        return -1f;
    }
    let t_8 = (dot(e2_2, q_6) * inv_1);
    if (t_8 > t_min) {
        local_28 = (t_8 < t_max_1);
    } else {
        local_28 = false;
    }
    let _e51 = local_28;
    if _e51 {
        return t_8;
    }
    return -1f;
}

fn inv_sigma_z(z: f32) -> f32 {
    return (1f / (DEPTH_SIGMA * z));
}

fn window_start(x_13: u32, size: u32) -> u32 {
    let half = (size / 2u);
    return (max(x_13, half) - half);
}

fn window_end(x_14: u32, size_1: u32, extent_1: u32) -> u32 {
    return min(((x_14 + size_1) - (size_1 / 2u)), extent_1);
}

fn wide_window(period: u32) -> u32 {
    return (2u * period);
}

fn misses_subset(covered: u32, period_1: u32) -> bool {
    return (covered < (period_1 * period_1));
}

fn filtered_irradiance(e: vec3<f32>, sum: vec3<f32>, weight: f32) -> vec3<f32> {
    if (weight > 0f) {
        return (sum / vec3(weight));
    }
    return e;
}

fn bilateral_weight(n_26: vec3<f32>, nj: vec3<f32>, z_1: f32, zj: f32, inv_sz: f32) -> f32 {
    let dn = max(dot(n_26, nj), 0f);
    let dn2_ = (dn * dn);
    let dn4_ = (dn2_ * dn2_);
    let dn8_ = (dn4_ * dn4_);
    let d_11 = ((zj - z_1) * inv_sz);
    let t_9 = max((1f - (d_11 * d_11)), 0f);
    return (((dn8_ * dn8_) * t_9) * t_9);
}

fn interleave_subset(x_15: u32, y_2: u32, period_2: u32) -> u32 {
    return (((y_2 % period_2) * period_2) + (x_15 % period_2));
}

fn shifted_subset(pixel_class: u32, shift: u32, period_3: u32) -> u32 {
    return ((pixel_class + shift) % (period_3 * period_3));
}

fn vpl_record_ok(position: vec3<f32>, normal: vec3<f32>, flux_1: vec3<f32>) -> bool {
    var local_29: bool;
    var local_30: bool;
    var local_31: bool;
    var local_32: bool;
    var local_33: bool;

    let _e3 = finite3_(position);
    if _e3 {
        let _e6 = finite3_(normal);
        local_29 = _e6;
    } else {
        local_29 = false;
    }
    let _e8 = local_29;
    if _e8 {
        let _e11 = finite3_(flux_1);
        local_30 = _e11;
    } else {
        local_30 = false;
    }
    let _e13 = local_30;
    if !(_e13) {
        return false;
    }
    if (flux_1.x >= 0f) {
        local_31 = (flux_1.y >= 0f);
    } else {
        local_31 = false;
    }
    let _e25 = local_31;
    if _e25 {
        local_32 = (flux_1.z >= 0f);
    } else {
        local_32 = false;
    }
    let _e32 = local_32;
    if _e32 {
        local_33 = ((max(max(flux_1.x, flux_1.y), flux_1.z) * INV_PI) <= MAX_INTENSITY);
    } else {
        local_33 = false;
    }
    let _e45 = local_33;
    return _e45;
}

fn subset_side(size_2: u32, period_4: u32) -> u32 {
    return ((((size_2 / period_4) + 7u) / 8u) * 8u);
}

fn interleave_slot(tx_1: u32, ty_1: u32, size_3: u32, period_5: u32) -> u32 {
    let _e4 = subset_side(size_3, period_5);
    let _e5 = interleave_subset(tx_1, ty_1, period_5);
    let _e10 = map_index((tx_1 / period_5), (ty_1 / period_5), _e4);
    return (((_e5 * _e4) * _e4) + _e10);
}

fn subset_slots_linear(count: u32, period_6: u32) -> u32 {
    let per = (count / (period_6 * period_6));
    return ((((per + CLUSTER) - 1u) / CLUSTER) * CLUSTER);
}

fn interleave_slot_linear(i_1: u32, per_subset: u32, period_7: u32) -> u32 {
    let subsets = (period_7 * period_7);
    return (((i_1 % subsets) * per_subset) + (i_1 / subsets));
}

fn interleave_flux_scale(period_8: u32) -> f32 {
    let _e2 = to_f32_((period_8 * period_8));
    return _e2;
}

fn vpl_near_weight(d2_11: f32, near_r2_: f32) -> f32 {
    if (near_r2_ <= 0f) {
        return 0f;
    }
    let t_10 = clamp(((near_r2_ - d2_11) / (0.75f * near_r2_)), 0f, 1f);
    return ((t_10 * t_10) * (3f - (2f * t_10)));
}

fn vpl_far_weight(d2_12: f32, near_r2_1: f32) -> f32 {
    let _e2 = vpl_near_weight(d2_12, near_r2_1);
    return (1f - _e2);
}

fn vpl_far_slc_share(rt2_7: f32, r2_7: f32, d2_13: f32, near_r2_2: f32) -> f32 {
    let _e4 = vpl_far_weight(d2_13, near_r2_2);
    let _e5 = slc_weight(rt2_7, d2_13);
    let _e7 = slc_keep(r2_7, d2_13);
    return select(0f, (_e4 * _e5), (_e7 & (_e4 > 0f)));
}

fn vpl_far_fixed_share(range2_2: f32, d2_14: f32, near_r2_3: f32) -> f32 {
    let _e3 = vpl_far_weight(d2_14, near_r2_3);
    let _e4 = clamp_keep(range2_2, d2_14);
    return select(0f, _e3, (_e4 & (_e3 > 0f)));
}

fn vpl_near_range2_(r2_8: f32, period_9: u32) -> f32 {
    let _e2 = interleave_flux_scale(period_9);
    return (r2_8 / _e2);
}

fn vpl_near_cull_range2_(r2_9: f32, near_r2_4: f32) -> f32 {
    return min(r2_9, near_r2_4);
}

fn vpl_near_slc_share(rt2_8: f32, r2_10: f32, d2_15: f32, near_r2_5: f32) -> f32 {
    let _e4 = vpl_near_weight(d2_15, near_r2_5);
    let _e5 = slc_weight(rt2_8, d2_15);
    let _e7 = slc_keep(r2_10, d2_15);
    return select(0f, (_e4 * _e5), (_e7 & (_e4 > 0f)));
}

fn vpl_near_fixed_share(range2_3: f32, d2_16: f32, near_r2_6: f32) -> f32 {
    let _e3 = vpl_near_weight(d2_16, near_r2_6);
    let _e4 = clamp_keep(range2_3, d2_16);
    return select(0f, _e3, (_e4 & (_e3 > 0f)));
}

fn camera_dir(forward: vec3<f32>, right: vec3<f32>, up: vec3<f32>, px: f32, py: f32, w_11: f32, h_1: f32) -> vec3<f32> {
    let sx = (((2f * px) / w_11) - 1f);
    let sy = (1f - ((2f * py) / h_1));
    return normalize(((forward + (right * sx)) + (up * sy)));
}

fn jittered_pixel(coord: u32, u_7: f32) -> f32 {
    let _e2 = to_f32_(coord);
    return (_e2 + u_7);
}

fn plays_roulette(depth: u32) -> bool {
    return (depth >= ROULETTE_DEPTH);
}

fn sees_emission(gn: vec3<f32>, dir_1: vec3<f32>) -> bool {
    return (dot(gn, dir_1) < 0f);
}

fn continues_path(nd: vec3<f32>, n_27: vec3<f32>, ng_1: vec3<f32>) -> bool {
    var local_34: bool;

    if (dot(nd, n_27) > 0f) {
        local_34 = (dot(nd, ng_1) > 0f);
    } else {
        local_34 = false;
    }
    let _e12 = local_34;
    return _e12;
}

fn path_survival(beta: vec3<f32>) -> f32 {
    return clamp(max(max(beta.x, beta.y), beta.z), 0.05f, 0.95f);
}

fn light_map_coord(t_2: u32, size_4: u32) -> f32 {
    let _e2 = to_f32_(t_2);
    let _e7 = to_f32_(size_4);
    return (((2f * (_e2 + 0.5f)) / _e7) - 1f);
}

fn light_map_texel(a_9: f32, size_5: u32) -> u32 {
    let _e6 = to_f32_(size_5);
    let _e9 = to_f32_(size_5);
    let _e14 = to_u32_(clamp(floor((((a_9 + 1f) * 0.5f) * _e6)), 0f, (_e9 - 1f)));
    return _e14;
}

fn light_map_coord_at(rel: vec3<f32>, dir_2: vec3<f32>, axis_6: vec3<f32>, extent_2: f32, perspective: bool) -> f32 {
    return (dot(rel, dir_2) / (select(1f, dot(rel, axis_6), perspective) * extent_2));
}

fn display_encode(x_16: f32) -> f32 {
    let v_24 = max(x_16, 0f);
    let t_11 = ((2f * v_24) / (1f + (2f * v_24)));
    return select(((1.055f * pow(t_11, 0.41666666f)) - 0.055f), (12.92f * t_11), (t_11 <= 0.0031308f));
}

fn light_map_depth(rel_1: vec3<f32>, axis_7: vec3<f32>, perspective_1: bool) -> f32 {
    return select(dot(rel_1, axis_7), sqrt(dot(rel_1, rel_1)), perspective_1);
}

fn rsm_texel_solid_angle(texel_area: f32, cos_axis: f32) -> f32 {
    return (((texel_area * cos_axis) * cos_axis) * cos_axis);
}

fn point_irradiance(intensity_1: vec3<f32>, n_28: vec3<f32>, v_13: vec3<f32>) -> vec3<f32> {
    let d2_20 = dot(v_13, v_13);
    let cos_x_2 = (dot(n_28, v_13) / sqrt(max(d2_20, MIN_D2_)));
    let _e11 = inverse_square(d2_20);
    return (intensity_1 * (max(cos_x_2, 0f) * _e11));
}

fn directional_irradiance(e_1: vec3<f32>, n_29: vec3<f32>, to_light: vec3<f32>) -> vec3<f32> {
    return (e_1 * max(dot(n_29, to_light), 0f));
}

fn perspective_texel_width(extent_3: f32, d_5: f32, z_2: f32, size_6: f32) -> f32 {
    return ((((2f * extent_3) * d_5) * d_5) / (size_6 * z_2));
}

fn ortho_texel_width(extent_4: f32, size_7: f32) -> f32 {
    return ((2f * extent_4) / size_7);
}

fn shadow_bias(texel: f32, cos_light_1: f32) -> f32 {
    let c_24 = clamp(cos_light_1, 0.02f, 1f);
    return (texel * (1.5f + (sqrt((1f - (c_24 * c_24))) / c_24)));
}

fn shadow_lit(d_6: f32, d_map: f32, bias: f32) -> bool {
    var local_35: bool;

    if !((d_map <= 0f)) {
        local_35 = (d_6 <= (d_map + bias));
    } else {
        local_35 = true;
    }
    let _e11 = local_35;
    return _e11;
}

fn diffuse_radiance(albedo: vec3<f32>, emission: vec3<f32>, e_2: vec3<f32>) -> vec3<f32> {
    return (emission + ((albedo * INV_PI) * e_2));
}

fn primary_light_dir(x_17: vec3<f32>, origin: vec3<f32>, axis_8: vec3<f32>, perspective_2: bool) -> vec3<f32> {
    var local_36: bool;

    let v_25 = (origin - x_17);
    let d2_21 = dot(v_25, v_25);
    if perspective_2 {
        local_36 = (d2_21 > 0f);
    } else {
        local_36 = false;
    }
    let _e11 = local_36;
    if _e11 {
        return (v_25 / vec3(sqrt(d2_21)));
    }
    return -(axis_8);
}

fn glossy_radiance(base_12: vec3<f32>, emission_1: vec3<f32>, metallic_9: f32, f_direct: vec3<f32>, direct: vec3<f32>, indirect: vec3<f32>, specular: vec3<f32>) -> vec3<f32> {
    let _e9 = diffuse_albedo(base_12, metallic_9);
    return (((emission_1 + (f_direct * direct)) + ((_e9 * INV_PI) * indirect)) + specular);
}

fn luminance(c_14: vec3<f32>) -> f32 {
    return dot(c_14, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn reproject(c0_1: vec4<f32>, c1_3: vec4<f32>, c2_2: vec4<f32>, c3_: vec4<f32>, p_9: vec3<f32>, width: f32, height: f32) -> vec3<f32> {
    let clip = ((((c0_1 * p_9.x) + (c1_3 * p_9.y)) + (c2_2 * p_9.z)) + c3_);
    if (clip.w <= 0f) {
        return vec3<f32>(-1f, -1f, 0f);
    }
    let x_19 = (((((clip.x / clip.w) + 1f) * 0.5f) * width) - 0.5f);
    let y_4 = ((((1f - (clip.y / clip.w)) * 0.5f) * height) - 0.5f);
    return vec3<f32>(x_19, y_4, clip.w);
}

fn reproject_motion(px_1: f32, py_1: f32, mx: f32, my: f32, width_1: f32, height_1: f32) -> vec3<f32> {
    return vec3<f32>((px_1 - (mx * width_1)), (py_1 - (my * height_1)), 1f);
}

fn bilinear_weight(fx: f32, fy: f32, dx: u32, dy: u32) -> f32 {
    let wx = select((1f - fx), fx, (dx == 1u));
    let wy = select((1f - fy), fy, (dy == 1u));
    return (wx * wy);
}

fn history_tap(q_2: vec3<f32>, k_7: u32, width_2: f32, height_2: f32) -> vec4<f32> {
    var local_37: bool;
    var local_38: bool;
    var local_39: bool;
    var local_40: bool;

    let x0_ = floor(q_2.x);
    let y0_ = floor(q_2.y);
    let dx_1 = (k_7 % 2u);
    let dy_1 = (k_7 / 2u);
    let _e12 = to_f32_(dx_1);
    let tx_2 = (x0_ + _e12);
    let _e14 = to_f32_(dy_1);
    let ty_2 = (y0_ + _e14);
    if (q_2.z > 0f) {
        local_37 = (tx_2 >= 0f);
    } else {
        local_37 = false;
    }
    let _e24 = local_37;
    if _e24 {
        local_38 = (ty_2 >= 0f);
    } else {
        local_38 = false;
    }
    let _e30 = local_38;
    if _e30 {
        local_39 = (tx_2 < width_2);
    } else {
        local_39 = false;
    }
    let _e35 = local_39;
    if _e35 {
        local_40 = (ty_2 < height_2);
    } else {
        local_40 = false;
    }
    let inside = local_40;
    let _e45 = bilinear_weight((q_2.x - x0_), (q_2.y - y0_), dx_1, dy_1);
    return vec4<f32>(tx_2, ty_2, _e45, select(0f, 1f, inside));
}

fn history_mean(sum_1: vec4<f32>, weight_1: f32) -> vec4<f32> {
    if (weight_1 < TEMPORAL_MIN_WEIGHT) {
        return vec4<f32>(0f, 0f, 0f, 0f);
    }
    return (sum_1 / vec4(weight_1));
}

fn history_matches(n_30: vec3<f32>, nh: vec3<f32>, p_10: vec3<f32>, oh: f32, d_7: f32) -> bool {
    var local_41: bool;

    if (abs((dot(nh, p_10) - oh)) <= (TEMPORAL_DEPTH_TOLERANCE * d_7)) {
        local_41 = (dot(n_30, nh) >= TEMPORAL_NORMAL_COS);
    } else {
        local_41 = false;
    }
    let _e17 = local_41;
    return _e17;
}

fn temporal_change(l_6: f32, m1_: f32, noise: f32, n_31: f32) -> f32 {
    if (n_31 < TEMPORAL_MIN_MOMENTS) {
        return 0f;
    }
    let sigma = sqrt((max(noise, 0f) * (1f + (1f / n_31))));
    let t_12 = (abs((l_6 - m1_)) / ((sigma + (0.001f * max(abs(l_6), abs(m1_)))) + 0.00000000000000000001f));
    return clamp(((t_12 - TEMPORAL_CHANGE_LOW) / 4f), 0f, 1f);
}

fn next_history_length(n_32: f32, lambda: f32, max_history: f32) -> f32 {
    return min((((1f - lambda) * n_32) + 1f), max(max_history, 1f));
}

fn temporal_alpha(n_33: f32) -> f32 {
    return (1f / max(n_33, 1f));
}

fn history_tap_weight(w_12: f32, n_34: vec3<f32>, nh_1: vec3<f32>, p_11: vec3<f32>, oh_1: f32, d_8: f32, len_1: f32) -> f32 {
    var local_42: bool;

    if (len_1 > 0f) {
        let _e11 = history_matches(n_34, nh_1, p_11, oh_1, d_8);
        local_42 = _e11;
    } else {
        local_42 = false;
    }
    let _e13 = local_42;
    return select(0f, w_12, _e13);
}

fn history_tap_weight_motion(w_13: f32, n_35: vec3<f32>, nh_2: vec3<f32>, d_9: f32, dh: f32, len_2: f32) -> f32 {
    var local_43: bool;
    var local_44: bool;

    if (len_2 > 0f) {
        local_43 = (abs((dh - d_9)) <= (TEMPORAL_MOTION_DEPTH_TOLERANCE * d_9));
    } else {
        local_43 = false;
    }
    let _e16 = local_43;
    if _e16 {
        local_44 = (dot(n_35, nh_2) >= TEMPORAL_NORMAL_COS);
    } else {
        local_44 = false;
    }
    let _e23 = local_44;
    return select(0f, w_13, _e23);
}

fn persistent_change(l_7: f32, last: f32, m1_1: f32, noise_1: f32, n_36: f32) -> f32 {
    if (((l_7 - m1_1) * (last - m1_1)) <= 0f) {
        return 0f;
    }
    let _e11 = temporal_change(l_7, m1_1, noise_1, n_36);
    let _e12 = temporal_change(last, m1_1, noise_1, n_36);
    return min(_e11, _e12);
}

fn temporal_color(c_15: vec3<f32>, h_2: vec4<f32>, noise_2: f32, last_1: f32, max_history_1: f32) -> vec4<f32> {
    let hc = vec3<f32>(h_2.x, h_2.y, h_2.z);
    let _e9 = luminance(c_15);
    let _e10 = luminance(hc);
    let _e12 = persistent_change(_e9, last_1, _e10, noise_2, h_2.w);
    let _e14 = next_history_length(h_2.w, _e12, max_history_1);
    let _e15 = temporal_alpha(_e14);
    let v_26 = ((hc * (1f - _e15)) + (c_15 * _e15));
    return vec4<f32>(v_26.x, v_26.y, v_26.z, _e14);
}

fn temporal_moments(c_16: vec3<f32>, last_2: f32, noise_3: f32, prev_len: f32, len_3: f32, depth_1: f32) -> vec4<f32> {
    var local_45: bool;

    let _e6 = luminance(c_16);
    if (prev_len <= 0f) {
        return vec4<f32>(_e6, 0f, depth_1, 0f);
    }
    let d_12 = (_e6 - last_2);
    let d2_22 = ((0.5f * d_12) * d_12);
    let cap = (16f * noise_3);
    if (prev_len >= TEMPORAL_MIN_MOMENTS) {
        local_45 = (noise_3 > 0f);
    } else {
        local_45 = false;
    }
    let _e26 = local_45;
    let sample = select(d2_22, min(d2_22, cap), _e26);
    let _e31 = temporal_alpha((len_3 - 1f));
    return vec4<f32>(_e6, (noise_3 + ((sample - noise_3) * _e31)), depth_1, 0f);
}

