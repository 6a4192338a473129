struct GpuLight {
    p0_: vec3<f32>,
    kind: u32,
    p1_: vec3<f32>,
    a: f32,
    p2_: vec3<f32>,
    b: f32,
    intensity: vec3<f32>,
    ies_base: u32,
}

struct GpuLightCone {
    center: vec3<f32>,
    radius: f32,
    axis: vec3<f32>,
    cos_o: f32,
    phi: f32,
    cos_e: f32,
    bvh_leaf: u32,
    pad: u32,
}

struct GpuGeoNode {
    bmin: vec3<f32>,
    first: u32,
    bmax: vec3<f32>,
    count: u32,
}

struct GpuTriangle {
    v0_: vec3<f32>,
    material: u32,
    v1_: vec3<f32>,
    light: u32,
    v2_: vec3<f32>,
    pad: u32,
}

struct GpuPathVertex {
    position: vec3<f32>,
    alive: u32,
    normal: vec3<f32>,
    pad: f32,
    weight: vec3<f32>,
    pad1_: f32,
    gnormal: vec3<f32>,
    pad2_: f32,
}

struct GpuPathState {
    origin: vec3<f32>,
    alive: u32,
    dir: vec3<f32>,
    rng: u32,
    beta: vec3<f32>,
    pdf_bsdf: f32,
    prev: vec3<f32>,
    pad: u32,
    prev_normal: vec3<f32>,
    pad2_: u32,
}

struct PtParams {
    cam_pos: vec3<f32>,
    width: u32,
    cam_right: vec3<f32>,
    height: u32,
    cam_up: vec3<f32>,
    depth: u32,
    cam_forward: vec3<f32>,
    seed: u32,
    pass_index: u32,
    max_depth: u32,
    eps: f32,
    t_min: f32,
}

struct FrameParams {
    light_count: u32,
    seed: u32,
    frame: u32,
    pad: u32,
}

struct RefitParams {
    first: u32,
    count: u32,
    pad0_: u32,
    pad1_: u32,
}

struct VplParams {
    width: u32,
    height: u32,
    lights_per_subset: u32,
    min_d2_: f32,
    near_r2_: f32,
    near_blocks: u32,
    pad0_: u32,
    pad1_: u32,
}

struct GpuNearBox {
    lo: vec3<f32>,
    pad0_: f32,
    hi: vec3<f32>,
    pad1_: f32,
}

struct GpuVplRecord {
    position: vec3<f32>,
    pad0_: f32,
    normal: vec3<f32>,
    pad1_: f32,
    flux: vec3<f32>,
    pad2_: f32,
}

struct PackParams {
    count: u32,
    size: u32,
    per_subset: u32,
    mode: u32,
    exposure: f32,
    error_bound: f32,
    scale: f32,
    slc: u32,
    fixed_r2_: f32,
    pad0_: u32,
    pad1_: u32,
    pad2_: u32,
}

struct ImageParams {
    eye: vec3<f32>,
    width: u32,
    height: u32,
    pad0_: u32,
    pad1_: u32,
    pad2_: u32,
}

struct GpuVertex {
    position: vec3<f32>,
    material: u32,
    normal: vec3<f32>,
    pad0_: u32,
    geo_normal: vec3<f32>,
    pad1_: u32,
}

struct GpuMaterial {
    albedo: vec3<f32>,
    pad0_: u32,
    emission: vec3<f32>,
    pad1_: u32,
}

struct MapParams {
    c0_: vec4<f32>,
    c1_: vec4<f32>,
    c2_: vec4<f32>,
    c3_: vec4<f32>,
    light: GpuLight,
    origin: vec3<f32>,
    mode: u32,
    axis: vec3<f32>,
    size: u32,
    right: vec3<f32>,
    extent: f32,
    up: vec3<f32>,
    texel: f32,
}

struct ShadeParams {
    point_count: u32,
    seed: u32,
    frame: u32,
    eps: f32,
}

struct BshNode {
    center: vec3<f32>,
    radius: f32,
    child: u32,
    next: u32,
    light: u32,
    pad: u32,
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

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) @interpolate(flat) geo: vec3<f32>,
    @location(3) @interpolate(flat) material: u32,
}

struct GbufferOut {
    @location(0) position: vec4<f32>,
    @location(1) normal: vec4<f32>,
}

struct RsmOut {
    @location(0) position: vec4<f32>,
    @location(1) normal: vec4<f32>,
    @location(2) flux: vec4<f32>,
}

const LIGHT_POINT: u32 = 0u;
const LIGHT_SPOT: u32 = 1u;
const LIGHT_IES: u32 = 2u;
const LIGHT_TRIANGLE: u32 = 3u;
const LIGHT_VPL: u32 = 4u;
const NO_LIGHT: u32 = 4294967295u;
const MAP_CAMERA: u32 = 0u;
const MAP_PERSPECTIVE: u32 = 1u;
const MAP_ORTHOGRAPHIC: u32 = 2u;
const XI_STEP: f32 = 0.000000059604645f;
const PICK_STREAM: u32 = 2654435769u;
const TWO_PI: f32 = 6.2831855f;
const CULL_RADIUS_SCALE: f32 = 1.000001f;
const SPHERE_PAD: f32 = 0.00000047683716f;
const SPHERE_HUGE: f32 = 340282350000000000000000000000000000000f;
const SPHERE_PAD_ABS: f32 = 0.000000000000000001f;
const INV_PI: f32 = 0.31830987f;
const MIN_D2_: f32 = 0.000000000001f;
const BSH_NONE: u32 = 4294967295u;
const RESERVOIR_FULL: u32 = 4294967295u;
const LIGHT_BVH_LEAF: u32 = 4294967295u;
const ONE_MINUS_EPSILON: f32 = 0.99999994f;
const F32_MAX: f32 = 340282350000000000000000000000000000000f;
const DEPTH_NONE: f32 = 1000000000000000000000000000000f;
const DEPTH_SIGMA: f32 = 0.05f;
const COVER_WEIGHT: f32 = 0.1f;
const NEAR_BLOCK: u32 = 64u;
const ROULETTE_DEPTH: u32 = 2u;

@group(1) @binding(0) 
var<storage> slc_table: array<f32>;
@group(0) @binding(0) 
var<uniform> params: MapParams;
@group(0) @binding(1) 
var<storage> materials: array<GpuMaterial>;

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

fn xi_from_bits(bits: u32) -> f32 {
    let _e3 = to_f32_((bits >> 8u));
    return (_e3 * XI_STEP);
}

fn pcg_hash(x_1: u32) -> u32 {
    let _e2 = mul_lo_u32_(x_1, 747796405u);
    let _e4 = add_wrap_u32_(_e2, 2891336453u);
    let _e12 = mul_lo_u32_(((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4), 277803737u);
    return ((_e12 >> 22u) ^ _e12);
}

fn reverse_bits(x_2: u32) -> u32 {
    var v_3: u32;

    v_3 = (((x_2 >> 16u) & 65535u) | ((x_2 & 65535u) << 16u));
    let _e11 = v_3;
    let _e16 = v_3;
    v_3 = (((_e11 >> 8u) & 16711935u) | ((_e16 & 16711935u) << 8u));
    let _e22 = v_3;
    let _e27 = v_3;
    v_3 = (((_e22 >> 4u) & 252645135u) | ((_e27 & 252645135u) << 4u));
    let _e33 = v_3;
    let _e38 = v_3;
    v_3 = (((_e33 >> 2u) & 858993459u) | ((_e38 & 858993459u) << 2u));
    let _e44 = v_3;
    let _e49 = v_3;
    v_3 = (((_e44 >> 1u) & 1431655765u) | ((_e49 & 1431655765u) << 1u));
    let _e55 = v_3;
    return _e55;
}

fn xi_for(seed: u32, frame: u32, light: u32) -> f32 {
    let _e3 = pcg_hash(seed);
    let _e4 = pcg_hash(_e3);
    let _e6 = pcg_hash((_e4 ^ light));
    let _e7 = reverse_bits(frame);
    let _e8 = add_wrap_u32_(_e6, _e7);
    let _e9 = xi_from_bits(_e8);
    return _e9;
}

fn point_stream(seed_1: u32, point: u32, frame_1: u32) -> u32 {
    let _e3 = pcg_hash(frame_1);
    let _e5 = pcg_hash((point ^ _e3));
    let _e7 = pcg_hash((seed_1 ^ _e5));
    return _e7;
}

fn pick_stream(stream: u32) -> u32 {
    let _e3 = pcg_hash((stream ^ PICK_STREAM));
    return _e3;
}

fn path_stream(seed_2: u32, pixel: u32, pass_index: u32) -> u32 {
    let _e4 = add_wrap_u32_(pass_index, PICK_STREAM);
    let _e5 = point_stream(seed_2, pixel, _e4);
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
    let q_2 = (d2_4 / range2_1);
    let w_10 = saturate((1f - (q_2 * q_2)));
    return ((w_10 * w_10) / max(d2_4, 0.0001f));
}

fn sphere_contains_point(c: vec3<f32>, r: f32, x_3: vec3<f32>) -> bool {
    let v_8 = (x_3 - c);
    return (dot(v_8, v_8) <= (r * r));
}

fn sphere_overlaps_sphere(c1_: vec3<f32>, r1_: f32, c2_: vec3<f32>, r2_2: f32) -> bool {
    let v_9 = (c2_ - c1_);
    let r_3 = (r1_ + r2_2);
    return (dot(v_9, v_9) <= (r_3 * r_3));
}

fn sphere_pad(r_1: f32, c_1: vec3<f32>) -> f32 {
    return (((r_1 + max(abs(c_1.x), max(abs(c_1.y), abs(c_1.z)))) * SPHERE_PAD) + SPHERE_PAD_ABS);
}

fn sphere_union(c1_1: vec3<f32>, r1_1: f32, c2_1: vec3<f32>, r2_3: f32) -> vec4<f32> {
    var local: bool;

    let v_10 = (c2_1 - c1_1);
    let d_4 = sqrt(dot(v_10, v_10));
    let _e8 = sphere_pad(r1_1, c1_1);
    if (r1_1 >= ((d_4 + r2_3) + _e8)) {
        return vec4<f32>(c1_1.x, c1_1.y, c1_1.z, r1_1);
    }
    let _e16 = sphere_pad(r2_3, c2_1);
    if (r2_3 >= ((d_4 + r1_1) + _e16)) {
        return vec4<f32>(c2_1.x, c2_1.y, c2_1.z, r2_3);
    }
    if !((d_4 >= SPHERE_HUGE)) {
        local = ((0.5f * ((d_4 + r1_1) + r2_3)) >= SPHERE_HUGE);
    } else {
        local = true;
    }
    let _e35 = local;
    if _e35 {
        return vec4<f32>(c1_1.x, c1_1.y, c1_1.z, SPHERE_HUGE);
    }
    if (abs((r1_1 - r2_3)) >= d_4) {
        if (r1_1 >= r2_3) {
            let rn = max(r1_1, (d_4 + r2_3));
            let _e50 = sphere_pad(rn, c1_1);
            return vec4<f32>(c1_1.x, c1_1.y, c1_1.z, (rn + _e50));
        }
        let rm = max(r2_3, (d_4 + r1_1));
        let _e58 = sphere_pad(rm, c2_1);
        return vec4<f32>(c2_1.x, c2_1.y, c2_1.z, (rm + _e58));
    }
    let r0_ = (0.5f * ((d_4 + r1_1) + r2_3));
    let c_9 = (c1_1 + (v_10 * ((r0_ - r1_1) / d_4)));
    let e1_ = (c_9 - c1_1);
    let e2_ = (c_9 - c2_1);
    let r_4 = max(r0_, max((sqrt(dot(e1_, e1_)) + r1_1), (sqrt(dot(e2_, e2_)) + r2_3)));
    let _e82 = sphere_pad(r_4, c_9);
    return vec4<f32>(c_9.x, c_9.y, c_9.z, (r_4 + _e82));
}

fn sphere_overlaps_aabb(c_2: vec3<f32>, r_2: f32, bmin: vec3<f32>, bmax: vec3<f32>) -> bool {
    let q_3 = clamp(c_2, bmin, bmax);
    let v_11 = (q_3 - c_2);
    return (dot(v_11, v_11) <= (r_2 * r_2));
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

fn connection_cosine(x_4: vec3<f32>, y: vec3<f32>, n: vec3<f32>, ng: vec3<f32>, r2_5: f32) -> f32 {
    var local_1: bool;
    var local_2: bool;

    let v_12 = (x_4 - y);
    let d2_16 = dot(v_12, v_12);
    let _e7 = slc_keep(r2_5, d2_16);
    if !(!(_e7)) {
        local_1 = !((d2_16 > 0f));
    } else {
        local_1 = true;
    }
    let _e16 = local_1;
    if _e16 {
        return 0f;
    }
    let w_11 = (v_12 / vec3(sqrt(d2_16)));
    let cos_x_1 = -(dot(n, w_11));
    if !((cos_x_1 <= 0f)) {
        local_2 = (dot(ng, w_11) >= 0f);
    } else {
        local_2 = true;
    }
    let _e32 = local_2;
    if _e32 {
        return 0f;
    }
    return cos_x_1;
}

fn vpl_lobe(n_1: vec3<f32>, w_1: vec3<f32>) -> f32 {
    return (max(dot(n_1, w_1), 0f) * INV_PI);
}

fn vpl_transfer(n_l: vec3<f32>, n_x: vec3<f32>, v_4: vec3<f32>, min_d2_: f32) -> f32 {
    let m = max(dot(v_4, v_4), min_d2_);
    return (((max(dot(n_l, v_4), 0f) * max(-(dot(n_x, v_4)), 0f)) * INV_PI) / (m * m));
}

fn spot_falloff(cos_theta: f32, cos_outer: f32, cos_inner: f32) -> f32 {
    if (cos_inner <= cos_outer) {
        return select(0f, 1f, (cos_theta >= cos_outer));
    }
    let t_2 = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return ((t_2 * t_2) * (3f - (2f * t_2)));
}

fn triangle_lobe(n_2: vec3<f32>, area: f32, w_2: vec3<f32>) -> f32 {
    return (area * max(dot(n_2, w_2), 0f));
}

fn triangle_sample(a_2: vec3<f32>, b_2: vec3<f32>, c_3: vec3<f32>, u1_: f32, u2_: f32) -> vec3<f32> {
    let su = sqrt(u1_);
    let b0_ = (1f - su);
    let b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_3 * ((1f - b0_) - b1_)));
}

fn area_to_solid_angle_pdf(pdf_area: f32, d2_7: f32, cos_light: f32) -> f32 {
    let c_10 = abs(cos_light);
    if (c_10 <= 0f) {
        return 0f;
    }
    return ((pdf_area * d2_7) / c_10);
}

fn atan_portable(x_5: f32) -> f32 {
    var base: f32 = 0f;
    var t: f32;

    let a_9 = abs(x_5);
    t = a_9;
    if (a_9 > 2.4142137f) {
        base = 1.5707964f;
        t = (-1f / a_9);
    } else {
        if (a_9 > 0.41421357f) {
            base = 0.7853982f;
            t = ((a_9 - 1f) / (a_9 + 1f));
        }
    }
    let _e18 = t;
    let _e19 = t;
    let z_3 = (_e18 * _e19);
    let _e21 = base;
    let _e33 = t;
    let _e35 = t;
    let r_5 = (_e21 + (((((((((0.080537446f * z_3) - 0.13877685f) * z_3) + 0.19977711f) * z_3) - 0.3333295f) * z_3) * _e33) + _e35));
    return select(r_5, -(r_5), (x_5 < 0f));
}

fn atan2_portable(y_1: f32, x_6: f32) -> f32 {
    if (x_6 == 0f) {
        if (y_1 > 0f) {
            return 1.5707964f;
        }
        if (y_1 < 0f) {
            return -1.5707964f;
        }
        return 0f;
    }
    let _e12 = atan_portable((y_1 / x_6));
    if (x_6 > 0f) {
        return _e12;
    }
    if (y_1 >= 0f) {
        return (_e12 + 3.1415927f);
    }
    return (_e12 - 3.1415927f);
}

fn ies_fold_c(c_4: f32, h_first: f32, h_last: f32) -> f32 {
    var a_3: f32;

    a_3 = (c_4 - (360f * floor((c_4 / 360f))));
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

fn ies_segment(tab_1: u32, start: u32, n_3: u32, x_7: f32) -> u32 {
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
            if (_e23 <= x_7) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
    let _e25 = lo;
    return _e25;
}

fn ies_lerp_t(a0_: f32, a1_: f32, x_8: f32) -> f32 {
    if (a1_ <= a0_) {
        return 0f;
    }
    return saturate(((x_8 - a0_) / (a1_ - a0_)));
}

fn ies_candela(tab_2: u32, base_1: u32, gamma: f32, c_5: f32) -> f32 {
    var local_3: bool;

    let _e4 = at(tab_2, base_1);
    let _e5 = to_u32_(_e4);
    let _e8 = at(tab_2, (base_1 + 1u));
    let _e9 = to_u32_(_e8);
    let v0_ = (base_1 + 2u);
    let h0_ = (v0_ + _e5);
    let c0_1 = (h0_ + _e9);
    let _e14 = at(tab_2, v0_);
    if !((gamma < _e14)) {
        let _e22 = at(tab_2, ((v0_ + _e5) - 1u));
        local_3 = (gamma > _e22);
    } else {
        local_3 = true;
    }
    let _e25 = local_3;
    if _e25 {
        return 0f;
    }
    let _e27 = at(tab_2, h0_);
    let _e31 = at(tab_2, ((h0_ + _e9) - 1u));
    let _e32 = ies_fold_c(c_5, _e27, _e31);
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
    let _e58 = at(tab_2, ((c0_1 + (_e34 * _e5)) + _e33));
    let _e65 = at(tab_2, ((c0_1 + (_e34 * _e5)) + iv1_));
    let a_10 = ((_e58 * (1f - _e49)) + (_e65 * _e49));
    let _e71 = at(tab_2, ((c0_1 + (ih1_ * _e5)) + _e33));
    let _e78 = at(tab_2, ((c0_1 + (ih1_ * _e5)) + iv1_));
    let b_7 = ((_e71 * (1f - _e49)) + (_e78 * _e49));
    return ((a_10 * (1f - _e54)) + (b_7 * _e54));
}

fn ies_candela_dir(tab_3: u32, base_2: u32, wn: f32, wr: f32, ws: f32) -> f32 {
    let _e9 = atan2_portable(sqrt(((wr * wr) + (ws * ws))), wn);
    let gamma_1 = degrees(_e9);
    let on_axis = ((abs(wr) + abs(ws)) <= 0f);
    let _e16 = atan2_portable(ws, wr);
    let c_11 = select(degrees(_e16), 0f, on_axis);
    let _e20 = ies_candela(tab_3, base_2, gamma_1, c_11);
    return _e20;
}

fn ies_light_candela(tab_4: u32, base_3: u32, nadir: vec3<f32>, reference: vec3<f32>, w_3: vec3<f32>) -> f32 {
    let side = cross(reference, nadir);
    let _e9 = ies_candela_dir(tab_4, base_3, dot(w_3, nadir), dot(w_3, reference), dot(w_3, side));
    return _e9;
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

fn weighted_replace(w_4: f32, w_sum: f32, u_1: f32) -> bool {
    return ((u_1 * w_sum) < w_4);
}

fn weighted_pick_weight(w_sum_1: f32, w_5: f32, k_2: u32) -> f32 {
    let _e3 = to_f32_(k_2);
    return (w_sum_1 / (_e3 * w_5));
}

fn reservoir_select_pdf(seen: u32, in_range: bool, k_3: u32) -> f32 {
    var others: u32;
    var local_4: bool;

    others = seen;
    if in_range {
        local_4 = (seen > 0u);
    } else {
        local_4 = false;
    }
    let _e9 = local_4;
    if _e9 {
        others = (seen - 1u);
    }
    let _e12 = others;
    let _e15 = reservoir_weight((_e12 + 1u), k_3);
    return (1f / _e15);
}

fn alias_choice(column: u32, other: u32, keep: f32, u_2: f32) -> u32 {
    return select(other, column, (u_2 < keep));
}

fn uniform_light(u_3: f32, n_8: u32) -> u32 {
    let _e2 = to_f32_(n_8);
    let _e4 = to_u32_((u_3 * _e2));
    return min(_e4, (n_8 - 1u));
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

fn safe_sqrt(x_9: f32) -> f32 {
    return sqrt(max(x_9, 0f));
}

fn light_importance(center: vec3<f32>, radius: f32, phi: f32, axis: vec3<f32>, cos_o: f32, cos_e: f32, p: vec3<f32>, n_9: vec3<f32>) -> f32 {
    var imp: f32;

    let v_13 = (p - center);
    let dist2_ = dot(v_13, v_13);
    let r2_10 = (radius * radius);
    let d2_17 = max(max(dist2_, r2_10), MIN_D2_);
    let wi = select(vec3<f32>(0f, 0f, 0f), (v_13 / vec3(sqrt(dist2_))), (dist2_ > 0f));
    let cos_w = dot(axis, wi);
    let _e28 = safe_sqrt((1f - (cos_w * cos_w)));
    let _e32 = safe_sqrt((1f - (r2_10 / dist2_)));
    let cos_b_2 = select(_e32, -1f, (dist2_ <= r2_10));
    let _e39 = safe_sqrt((1f - (cos_b_2 * cos_b_2)));
    let _e43 = safe_sqrt((1f - (cos_o * cos_o)));
    let _e44 = cos_sub_clamped(_e28, cos_w, _e43, cos_o);
    let _e45 = sin_sub_clamped(_e28, cos_w, _e43, cos_o);
    let _e46 = cos_sub_clamped(_e45, _e44, _e39, cos_b_2);
    if (_e46 <= cos_e) {
        return 0f;
    }
    imp = ((phi * _e46) / d2_17);
    if (dot(n_9, n_9) > 0f) {
        let cos_i = -(dot(wi, n_9));
        let _e60 = safe_sqrt((1f - (cos_i * cos_i)));
        let _e61 = imp;
        let _e62 = cos_sub_clamped(_e60, cos_i, _e39, cos_b_2);
        imp = (_e61 * max(_e62, 0f));
    }
    let _e66 = imp;
    return max(_e66, 0f);
}

fn candidate_weight(importance: f32, rt2_4: f32, d2_8: f32) -> f32 {
    let _e3 = slc_weight(rt2_4, d2_8);
    return (importance * _e3);
}

fn cone_weight(center_1: vec3<f32>, radius_1: f32, phi_1: f32, axis_1: vec3<f32>, cos_o_1: f32, cos_e_1: f32, rt2_5: f32, p_1: vec3<f32>, n_10: vec3<f32>) -> f32 {
    let v_14 = (p_1 - center_1);
    let _e10 = light_importance(center_1, radius_1, phi_1, axis_1, cos_o_1, cos_e_1, p_1, n_10);
    let _e14 = candidate_weight((_e10 * INV_PI), rt2_5, dot(v_14, v_14));
    return _e14;
}

fn weighted_select_pdf(w_6: f32, w_sum_2: f32, in_range_1: bool, k_4: u32) -> f32 {
    if (w_6 <= 0f) {
        return 0f;
    }
    let total = select((w_sum_2 + w_6), w_sum_2, in_range_1);
    let _e9 = to_f32_(k_4);
    return ((_e9 * w_6) / total);
}

fn bvh_first_prob(c0_: f32, c1_2: f32) -> f32 {
    let s = (c0_ + c1_2);
    if (s > 0f) {
        return (c0_ / s);
    }
    return -1f;
}

fn bvh_remap_u(u_4: f32, p0_: f32, first: bool) -> f32 {
    if first {
        return min((u_4 / p0_), ONE_MINUS_EPSILON);
    }
    return clamp(((u_4 - p0_) / (1f - p0_)), 0f, ONE_MINUS_EPSILON);
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

fn ray_inverse(x_10: f32) -> f32 {
    return (1f / select(x_10, 0.000000000000000000000000000001f, (abs(x_10) < 0.000000000000000000000000000001f)));
}

fn ray_inverse3_(d: vec3<f32>) -> vec3<f32> {
    let _e2 = ray_inverse(d.x);
    let _e4 = ray_inverse(d.y);
    let _e6 = ray_inverse(d.z);
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

fn triangle_normal(a_5: vec3<f32>, b_4: vec3<f32>, c_6: vec3<f32>) -> vec3<f32> {
    var local_5: bool;

    let n_17 = cross((b_4 - a_5), (c_6 - a_5));
    let l2_ = dot(n_17, n_17);
    if !(!((l2_ > 0f))) {
        local_5 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_5 = true;
    }
    let _e17 = local_5;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_17 / vec3(sqrt(l2_)));
}

fn face_against(n_11: vec3<f32>, dir_1: vec3<f32>) -> vec3<f32> {
    return select(n_11, -(n_11), (dot(n_11, dir_1) > 0f));
}

fn barycentric(p_2: vec3<f32>, a_6: vec3<f32>, b_5: vec3<f32>, c_7: vec3<f32>) -> vec3<f32> {
    let e1_1 = (b_5 - a_6);
    let e2_1 = (c_7 - a_6);
    let q_4 = (p_2 - a_6);
    let d11_ = dot(e1_1, e1_1);
    let d12_ = dot(e1_1, e2_1);
    let d22_ = dot(e2_1, e2_1);
    let den = ((d11_ * d22_) - (d12_ * d12_));
    if !((abs(den) > 0f)) {
        return vec3<f32>(1f, 0f, 0f);
    }
    let w1_ = (((d22_ * dot(q_4, e1_1)) - (d12_ * dot(q_4, e2_1))) / den);
    let w2_ = (((d11_ * dot(q_4, e2_1)) - (d12_ * dot(q_4, e1_1))) / den);
    return vec3<f32>(((1f - w1_) - w2_), w1_, w2_);
}

fn shading_normal(n0_: vec3<f32>, n1_: vec3<f32>, n2_: vec3<f32>, w_7: vec3<f32>, facing: vec3<f32>) -> vec3<f32> {
    var local_6: bool;

    let s_1 = (((n0_ * w_7.x) + (n1_ * w_7.y)) + (n2_ * w_7.z));
    let l2_1 = dot(s_1, s_1);
    if !(!((l2_1 > 0.000000000001f))) {
        local_6 = !((l2_1 < 300000000000000000000000000000000000000f));
    } else {
        local_6 = true;
    }
    let _e24 = local_6;
    if _e24 {
        return facing;
    }
    let n_18 = (s_1 / vec3(sqrt(l2_1)));
    return select(n_18, -(n_18), (dot(n_18, facing) < 0f));
}

fn ray_triangle(o_1: vec3<f32>, d_1: vec3<f32>, a_7: vec3<f32>, b_6: vec3<f32>, c_8: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_7: bool;
    var local_8: bool;
    var local_9: bool;

    let e1_2 = (b_6 - a_7);
    let e2_2 = (c_8 - a_7);
    let p_3 = cross(d_1, e2_2);
    let det = dot(e1_2, p_3);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv = (1f / det);
    let s_2 = (o_1 - a_7);
    let u_6 = (dot(s_2, p_3) * inv);
    if !((u_6 < 0f)) {
        local_7 = (u_6 > 1f);
    } else {
        local_7 = true;
    }
    let _e28 = local_7;
    if _e28 {
        return -1f;
    }
    let q_5 = cross(s_2, e1_2);
    let v_15 = (dot(d_1, q_5) * inv);
    if !((v_15 < 0f)) {
        local_8 = ((u_6 + v_15) > 1f);
    } else {
        local_8 = true;
    }
    let _e42 = local_8;
    if _e42 {
        return -1f;
    }
    let t_3 = (dot(e2_2, q_5) * inv);
    if (t_3 > t_min) {
        local_9 = (t_3 < t_max_1);
    } else {
        local_9 = false;
    }
    let _e51 = local_9;
    if _e51 {
        return t_3;
    }
    return -1f;
}

fn mis_balance(pdf_a: f32, pdf_b: f32) -> f32 {
    let s_3 = (pdf_a + pdf_b);
    if (s_3 <= 0f) {
        return 0f;
    }
    return (pdf_a / s_3);
}

fn mis_power(pdf_a_1: f32, pdf_b_1: f32) -> f32 {
    let a2_ = (pdf_a_1 * pdf_a_1);
    let s_4 = (a2_ + (pdf_b_1 * pdf_b_1));
    if (s_4 <= 0f) {
        return 0f;
    }
    return (a2_ / s_4);
}

fn light_strategy_pdf(select_: f32, rt2_6: f32, d2_9: f32, area_1: f32, cos_y: f32) -> f32 {
    var local_10: bool;
    var local_11: bool;

    if !((d2_9 <= 0f)) {
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
    let _e22 = rr_probability(rt2_6, d2_9);
    let _e26 = area_to_solid_angle_pdf((1f / area_1), d2_9, cos_y);
    return ((select_ * _e22) * _e26);
}

fn lambert_brdf(rho: vec3<f32>) -> vec3<f32> {
    return (rho * INV_PI);
}

fn cosine_pdf(cos_theta_1: f32) -> f32 {
    return (max(cos_theta_1, 0f) * INV_PI);
}

fn cosine_direction(n_12: vec3<f32>, u1_1: f32, u2_1: f32) -> vec3<f32> {
    let s_5 = select(-1f, 1f, (n_12.z >= 0f));
    let a_11 = (-1f / (s_5 + n_12.z));
    let b_8 = ((n_12.x * n_12.y) * a_11);
    let t_4 = vec3<f32>((1f + (((s_5 * n_12.x) * n_12.x) * a_11)), (s_5 * b_8), (-(s_5) * n_12.x));
    let bt = vec3<f32>(b_8, (s_5 + ((n_12.y * n_12.y) * a_11)), -(n_12.y));
    let r_6 = sqrt(u1_1);
    let phi_2 = (6.2831855f * u2_1);
    return normalize((((t_4 * (r_6 * cos(phi_2))) + (bt * (r_6 * sin(phi_2)))) + (n_12 * sqrt(max((1f - u1_1), 0f)))));
}

fn inv_sigma_z(z: f32) -> f32 {
    return (1f / (DEPTH_SIGMA * z));
}

fn window_start(x_11: u32, size: u32) -> u32 {
    let half = (size / 2u);
    return (max(x_11, half) - half);
}

fn window_end(x_12: u32, size_1: u32, extent_1: u32) -> u32 {
    return min(((x_12 + size_1) - (size_1 / 2u)), extent_1);
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

fn bilateral_weight(n_13: vec3<f32>, nj: vec3<f32>, z_1: f32, zj: f32, inv_sz: f32) -> f32 {
    let dn = max(dot(n_13, nj), 0f);
    let dn2_ = (dn * dn);
    let dn4_ = (dn2_ * dn2_);
    let dn8_ = (dn4_ * dn4_);
    let d_5 = ((zj - z_1) * inv_sz);
    let t_5 = max((1f - (d_5 * d_5)), 0f);
    return (((dn8_ * dn8_) * t_5) * t_5);
}

fn interleave_subset(x_13: u32, y_2: u32, period_2: u32) -> u32 {
    return (((y_2 % period_2) * period_2) + (x_13 % period_2));
}

fn interleave_slot(tx: u32, ty: u32, size_2: u32, period_3: u32) -> u32 {
    let side_1 = (size_2 / period_3);
    let _e5 = interleave_subset(tx, ty, period_3);
    return ((((_e5 * side_1) * side_1) + ((ty / period_3) * side_1)) + (tx / period_3));
}

fn interleave_slot_linear(i_1: u32, per_subset: u32, period_4: u32) -> u32 {
    let subsets = (period_4 * period_4);
    return (((i_1 % subsets) * per_subset) + (i_1 / subsets));
}

fn interleave_flux_scale(period_5: u32) -> f32 {
    let _e2 = to_f32_((period_5 * period_5));
    return _e2;
}

fn near_block_index(tx_1: u32, ty_1: u32, size_3: u32) -> u32 {
    let side_2 = (size_3 / 8u);
    return ((((((ty_1 / 8u) * side_2) + (tx_1 / 8u)) * NEAR_BLOCK) + ((ty_1 % 8u) * 8u)) + (tx_1 % 8u));
}

fn near_block_tx(q: u32, size_4: u32) -> u32 {
    return ((((q / NEAR_BLOCK) % (size_4 / 8u)) * 8u) + (q % 8u));
}

fn near_block_ty(q_1: u32, size_5: u32) -> u32 {
    return ((((q_1 / NEAR_BLOCK) / (size_5 / 8u)) * 8u) + ((q_1 % NEAR_BLOCK) / 8u));
}

fn vpl_near_weight(d2_10: f32, near_r2_: f32) -> f32 {
    if (near_r2_ <= 0f) {
        return 0f;
    }
    let t_6 = clamp(((near_r2_ - d2_10) / (0.75f * near_r2_)), 0f, 1f);
    return ((t_6 * t_6) * (3f - (2f * t_6)));
}

fn vpl_far_weight(d2_11: f32, near_r2_1: f32) -> f32 {
    let _e2 = vpl_near_weight(d2_11, near_r2_1);
    return (1f - _e2);
}

fn vpl_far_slc_share(rt2_7: f32, r2_6: f32, d2_12: f32, near_r2_2: f32) -> f32 {
    let _e4 = vpl_far_weight(d2_12, near_r2_2);
    let _e5 = slc_weight(rt2_7, d2_12);
    let _e7 = slc_keep(r2_6, d2_12);
    return select(0f, (_e4 * _e5), (_e7 & (_e4 > 0f)));
}

fn vpl_far_fixed_share(range2_2: f32, d2_13: f32, near_r2_3: f32) -> f32 {
    let _e3 = vpl_far_weight(d2_13, near_r2_3);
    let _e4 = clamp_keep(range2_2, d2_13);
    return select(0f, _e3, (_e4 & (_e3 > 0f)));
}

fn vpl_near_range2_(r2_7: f32, period_6: u32) -> f32 {
    let _e2 = interleave_flux_scale(period_6);
    return (r2_7 / _e2);
}

fn vpl_near_cull_range2_(r2_8: f32, near_r2_4: f32) -> f32 {
    return min(r2_8, near_r2_4);
}

fn vpl_near_slc_share(rt2_8: f32, r2_9: f32, d2_14: f32, near_r2_5: f32) -> f32 {
    let _e4 = vpl_near_weight(d2_14, near_r2_5);
    let _e5 = slc_weight(rt2_8, d2_14);
    let _e7 = slc_keep(r2_9, d2_14);
    return select(0f, (_e4 * _e5), (_e7 & (_e4 > 0f)));
}

fn vpl_near_fixed_share(range2_3: f32, d2_15: f32, near_r2_6: f32) -> f32 {
    let _e3 = vpl_near_weight(d2_15, near_r2_6);
    let _e4 = clamp_keep(range2_3, d2_15);
    return select(0f, _e3, (_e4 & (_e3 > 0f)));
}

fn camera_dir(forward: vec3<f32>, right: vec3<f32>, up: vec3<f32>, px: f32, py: f32, w_8: f32, h: f32) -> vec3<f32> {
    let sx = (((2f * px) / w_8) - 1f);
    let sy = (1f - ((2f * py) / h));
    return normalize(((forward + (right * sx)) + (up * sy)));
}

fn jittered_pixel(coord: u32, u_5: f32) -> f32 {
    let _e2 = to_f32_(coord);
    return (_e2 + u_5);
}

fn plays_roulette(depth: u32) -> bool {
    return (depth >= ROULETTE_DEPTH);
}

fn sees_emission(gn: vec3<f32>, dir_2: vec3<f32>) -> bool {
    return (dot(gn, dir_2) < 0f);
}

fn continues_path(nd: vec3<f32>, n_14: vec3<f32>, ng_1: vec3<f32>) -> bool {
    var local_12: bool;

    if (dot(nd, n_14) > 0f) {
        local_12 = (dot(nd, ng_1) > 0f);
    } else {
        local_12 = false;
    }
    let _e12 = local_12;
    return _e12;
}

fn finite3_(v_5: vec3<f32>) -> bool {
    var local_13: bool;
    var local_14: bool;

    if (abs(v_5.x) <= F32_MAX) {
        local_13 = (abs(v_5.y) <= F32_MAX);
    } else {
        local_13 = false;
    }
    let _e12 = local_13;
    if _e12 {
        local_14 = (abs(v_5.z) <= F32_MAX);
    } else {
        local_14 = false;
    }
    let _e20 = local_14;
    return _e20;
}

fn path_survival(beta: vec3<f32>) -> f32 {
    return clamp(max(max(beta.x, beta.y), beta.z), 0.05f, 0.95f);
}

fn light_map_coord(t_1: u32, size_6: u32) -> f32 {
    let _e2 = to_f32_(t_1);
    let _e7 = to_f32_(size_6);
    return (((2f * (_e2 + 0.5f)) / _e7) - 1f);
}

fn light_map_texel(a_8: f32, size_7: u32) -> u32 {
    let _e6 = to_f32_(size_7);
    let _e9 = to_f32_(size_7);
    let _e14 = to_u32_(clamp(floor((((a_8 + 1f) * 0.5f) * _e6)), 0f, (_e9 - 1f)));
    return _e14;
}

fn light_map_coord_at(rel: vec3<f32>, dir_3: vec3<f32>, axis_2: vec3<f32>, extent_2: f32, perspective: bool) -> f32 {
    return (dot(rel, dir_3) / (select(1f, dot(rel, axis_2), perspective) * extent_2));
}

fn display_encode(x_14: f32) -> f32 {
    let v_16 = max(x_14, 0f);
    let t_7 = ((2f * v_16) / (1f + (2f * v_16)));
    return select(((1.055f * pow(t_7, 0.41666666f)) - 0.055f), (12.92f * t_7), (t_7 <= 0.0031308f));
}

fn light_map_depth(rel_1: vec3<f32>, axis_3: vec3<f32>, perspective_1: bool) -> f32 {
    return select(dot(rel_1, axis_3), sqrt(dot(rel_1, rel_1)), perspective_1);
}

fn rsm_texel_solid_angle(texel_area: f32, cos_axis: f32) -> f32 {
    return (((texel_area * cos_axis) * cos_axis) * cos_axis);
}

fn point_irradiance(intensity_1: vec3<f32>, n_15: vec3<f32>, v_6: vec3<f32>) -> vec3<f32> {
    let d2_18 = dot(v_6, v_6);
    let cos_x_2 = (dot(n_15, v_6) / sqrt(max(d2_18, MIN_D2_)));
    let _e11 = inverse_square(d2_18);
    return (intensity_1 * (max(cos_x_2, 0f) * _e11));
}

fn directional_irradiance(e_1: vec3<f32>, n_16: vec3<f32>, to_light: vec3<f32>) -> vec3<f32> {
    return (e_1 * max(dot(n_16, to_light), 0f));
}

fn perspective_texel_width(extent_3: f32, d_2: f32, z_2: f32, size_8: f32) -> f32 {
    return ((((2f * extent_3) * d_2) * d_2) / (size_8 * z_2));
}

fn ortho_texel_width(extent_4: f32, size_9: f32) -> f32 {
    return ((2f * extent_4) / size_9);
}

fn shadow_bias(texel: f32, cos_light_1: f32) -> f32 {
    let c_12 = clamp(cos_light_1, 0.02f, 1f);
    return (texel * (1.5f + (sqrt((1f - (c_12 * c_12))) / c_12)));
}

fn shadow_lit(d_3: f32, d_map: f32, bias: f32) -> bool {
    var local_15: bool;

    if !((d_map <= 0f)) {
        local_15 = (d_3 <= (d_map + bias));
    } else {
        local_15 = true;
    }
    let _e11 = local_15;
    return _e11;
}

fn diffuse_radiance(albedo: vec3<f32>, emission: vec3<f32>, e_2: vec3<f32>) -> vec3<f32> {
    return (emission + ((albedo * INV_PI) * e_2));
}

fn light_intensity(l: GpuLight, w_9: vec3<f32>) -> vec3<f32> {
    switch l.kind {
        case 1u: {
            let _e8 = spot_falloff(dot(l.p1_, w_9), l.a, l.b);
            return (l.intensity * _e8);
        }
        default: {
            return vec3(0f);
        }
    }
}

fn light_point(l_1: GpuLight, u1_2: f32, u2_2: f32) -> vec3<f32> {
    return l_1.p0_;
}

fn light_area(l_2: GpuLight) -> f32 {
    return 0f;
}

fn light_normal(l_3: GpuLight) -> vec3<f32> {
    return vec3(0f);
}

fn seen_normal(v_7: VsOut, dir_4: vec3<f32>) -> vec3<f32> {
    let _e12 = face_against(v_7.geo, dir_4);
    let _e13 = shading_normal(v_7.normal, vec3(0f), vec3(0f), vec3<f32>(1f, 0f, 0f), _e12);
    return _e13;
}

@vertex 
fn vs_main(@location(0) position: vec3<f32>, @location(1) material: u32, @location(2) normal: vec3<f32>, @location(3) geo: vec3<f32>) -> VsOut {
    let _e6 = params.c0_;
    let _e9 = params.c1_;
    let _e12 = params.c2_;
    let _e15 = params.c3_;
    let m_1 = mat4x4<f32>(_e6, _e9, _e12, _e15);
    return VsOut((m_1 * vec4<f32>(position, 1f)), position, normal, geo, material);
}

@fragment 
fn fs_gbuffer(v: VsOut) -> GbufferOut {
    let _e4 = params.origin;
    let _e6 = seen_normal(v, (v.world - _e4));
    return GbufferOut(vec4<f32>(v.world, 1f), vec4<f32>(_e6, f32(v.material)));
}

@fragment 
fn fs_rsm(v_1: VsOut) -> RsmOut {
    var dir: vec3<f32>;
    var incident: vec3<f32>;

    let _e3 = params.axis;
    dir = _e3;
    let _e8 = params.light.intensity;
    let _e11 = params.texel;
    incident = (_e8 * _e11);
    let _e16 = params.mode;
    if (_e16 == MAP_PERSPECTIVE) {
        let _e22 = params.origin;
        dir = normalize((v_1.world - _e22));
        let _e27 = params.light;
        let _e28 = dir;
        let _e29 = light_intensity(_e27, _e28);
        let _e32 = params.texel;
        let _e33 = dir;
        let _e36 = params.axis;
        let _e38 = rsm_texel_solid_angle(_e32, dot(_e33, _e36));
        incident = (_e29 * _e38);
    }
    let albedo_1 = materials[v_1.material].albedo;
    let _e48 = dir;
    let _e49 = seen_normal(v_1, _e48);
    let _e52 = incident;
    return RsmOut(vec4<f32>(v_1.world, 1f), vec4<f32>(_e49, 0f), vec4<f32>((_e52 * albedo_1), 0f));
}

@fragment 
fn fs_shadow(v_2: VsOut) -> @location(0) vec4<f32> {
    let _e4 = params.origin;
    let _e8 = params.axis;
    let _e11 = params.mode;
    let _e14 = light_map_depth((v_2.world - _e4), _e8, (_e11 == MAP_PERSPECTIVE));
    return vec4<f32>(_e14, 0f, 0f, 0f);
}
