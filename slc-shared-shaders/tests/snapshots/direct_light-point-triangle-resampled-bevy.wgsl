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

struct ViewParams {
    c0_: vec4<f32>,
    c1_: vec4<f32>,
    c2_: vec4<f32>,
    c3_: vec4<f32>,
    eye: vec3<f32>,
    width: u32,
    height: u32,
    shadow_offset: f32,
    seed: u32,
    frame: u32,
    f0_d: vec3<f32>,
    f90_d: f32,
}

struct BshNode {
    center: vec3<f32>,
    radius: f32,
    child: u32,
    next: u32,
    light: u32,
    extent: f32,
}

struct GeoHit {
    t: f32,
    tri: u32,
}

struct Connection {
    e: vec3<f32>,
    y: vec3<f32>,
    cos_x: f32,
}

struct Shaded {
    e: vec3<f32>,
    diffuse: vec3<f32>,
    specular: vec3<f32>,
}

struct Material {
    base: vec3<f32>,
    metallic: f32,
    alpha: f32,
    v: vec3<f32>,
    roughness: f32,
    reflectance: f32,
}

const LIGHT_POINT: u32 = 0u;
const LIGHT_SPOT: u32 = 1u;
const LIGHT_IES: u32 = 2u;
const LIGHT_TRIANGLE: u32 = 3u;
const LIGHT_VPL: u32 = 4u;
const NO_LIGHT: u32 = 4294967295u;
const COUNT_TILES: u32 = 0u;
const COUNT_GROUP_TESTS: u32 = 1u;
const COUNT_CLUSTER_TESTS: u32 = 2u;
const COUNT_SPHERE_TESTS: u32 = 3u;
const COUNT_TESTED: u32 = 4u;
const COUNT_KEPT: u32 = 5u;
const COUNT_PIXELS: u32 = 6u;
const COUNT_FIELDS: u32 = 7u;
const DIRECT_COUNT_PIXELS: u32 = 0u;
const DIRECT_COUNT_CANDIDATES: u32 = 1u;
const DIRECT_COUNT_EVALUATIONS: u32 = 2u;
const DIRECT_COUNT_RAYS: u32 = 3u;
const DIRECT_COUNT_NODES: u32 = 4u;
const DIRECT_COUNT_FIELDS: u32 = 5u;
const MAP_CAMERA: u32 = 0u;
const MAP_PERSPECTIVE: u32 = 1u;
const MAP_ORTHOGRAPHIC: u32 = 2u;
const XI_STEP: f32 = 0.000000059604645f;
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
const RESERVOIR_FULL: u32 = 4294967295u;
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
const K: u32 = 8u;
const BSH: u32 = 0u;

@group(1) @binding(6) 
var<storage> geo_nodes: array<GpuGeoNode>;
@group(1) @binding(7) 
var<storage> geo_tris: array<GpuTriangle>;
@group(0) @binding(0) 
var<uniform> view: ViewParams;
@group(0) @binding(1) 
var position_tex: texture_2d<f32>;
@group(0) @binding(2) 
var normal_tex: texture_2d<f32>;
@group(0) @binding(3) 
var out_tex: texture_storage_2d<rgba16float,write>;
@group(0) @binding(4) 
var base_color_tex: texture_2d<f32>;
@group(0) @binding(5) 
var metal_rough_tex: texture_2d<f32>;
@group(1) @binding(1) 
var<storage> lights: array<GpuLight>;
@group(1) @binding(2) 
var<storage> rt2_3: array<f32>;
@group(1) @binding(3) 
var<storage> r2_3: array<f32>;
@group(1) @binding(4) 
var<storage> bsh_nodes: array<BshNode>;
@group(1) @binding(5) 
var<storage> light_cones: array<GpuLightCone>;

fn to_f32_(u: u32) -> f32 {
    return f32(u);
}

fn mul_lo_u32_(a: u32, b_1: u32) -> u32 {
    return (a * b_1);
}

fn add_wrap_u32_(a_1: u32, b_2: u32) -> u32 {
    return (a_1 + b_2);
}

fn f32_from_bits(u_1: u32) -> f32 {
    return bitcast<f32>(u_1);
}

fn xi_from_bits(bits: u32) -> f32 {
    let _e3 = to_f32_((bits >> 8u));
    return (_e3 * XI_STEP);
}

fn pcg_hash(x: u32) -> u32 {
    let _e2 = mul_lo_u32_(x, 747796405u);
    let _e4 = add_wrap_u32_(_e2, 2891336453u);
    let _e12 = mul_lo_u32_(((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4), 277803737u);
    return ((_e12 >> 22u) ^ _e12);
}

fn point_stream(seed: u32, point: u32, frame: u32) -> u32 {
    let _e3 = pcg_hash(frame);
    let _e5 = pcg_hash((point ^ _e3));
    let _e7 = pcg_hash((seed ^ _e5));
    return _e7;
}

fn pick_stream(stream: u32) -> u32 {
    let _e3 = pcg_hash((stream ^ PICK_STREAM));
    return _e3;
}

fn slc_weight(rt2_: f32, d2_: f32) -> f32 {
    if (d2_ <= rt2_) {
        return 1f;
    }
    return (d2_ / rt2_);
}

fn slc_keep(r2_: f32, d2_1: f32) -> bool {
    return (d2_1 < r2_);
}

fn sphere_contains_point(c: vec3<f32>, r_1: f32, x_1: vec3<f32>) -> bool {
    let v_5 = (x_1 - c);
    return (dot(v_5, v_5) <= (r_1 * r_1));
}

fn inverse_square(d2_2: f32) -> f32 {
    return (1f / max(d2_2, MIN_D2_));
}

fn connection_factor(cos_x: f32, d2_3: f32, rt2_1: f32, w_1: f32) -> f32 {
    let _e4 = inverse_square(d2_3);
    let _e6 = slc_weight(rt2_1, d2_3);
    return (((cos_x * _e4) * _e6) * w_1);
}

fn connection_cosine(x_2: vec3<f32>, y: vec3<f32>, n: vec3<f32>, ng: vec3<f32>, r2_1: f32) -> f32 {
    var local_4: bool;
    var local_5: bool;

    let v_6 = (x_2 - y);
    let d2_6 = dot(v_6, v_6);
    let _e7 = slc_keep(r2_1, d2_6);
    if !(!(_e7)) {
        local_4 = !((d2_6 > 0f));
    } else {
        local_4 = true;
    }
    let _e16 = local_4;
    if _e16 {
        return 0f;
    }
    let w_7 = (v_6 / vec3(sqrt(d2_6)));
    let cos_x_1 = -(dot(n, w_7));
    if !((cos_x_1 <= 0f)) {
        local_5 = (dot(ng, w_7) >= 0f);
    } else {
        local_5 = true;
    }
    let _e32 = local_5;
    if _e32 {
        return 0f;
    }
    return cos_x_1;
}

fn triangle_lobe(n_1: vec3<f32>, area: f32, w_2: vec3<f32>) -> f32 {
    return (area * max(dot(n_1, w_2), 0f));
}

fn triangle_sample(a_2: vec3<f32>, b_3: vec3<f32>, c_1: vec3<f32>, u1_: f32, u2_: f32) -> vec3<f32> {
    let su = sqrt(u1_);
    let b0_ = (1f - su);
    let b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_3 * b1_)) + (c_1 * ((1f - b0_) - b1_)));
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

fn weighted_threshold(w_sum: f32, u_2: f32) -> f32 {
    return (w_sum / (1f - u_2));
}

fn resample_target(c_2: vec3<f32>) -> f32 {
    return (((c_2.x + c_2.y) + c_2.z) * 0.33333334f);
}

fn slot_target(c_3: vec3<f32>, slot: u32, k_2: u32) -> f32 {
    if (k_2 < 3u) {
        let _e5 = resample_target(c_3);
        return _e5;
    }
    let j_2 = (slot % 3u);
    if (j_2 == 0u) {
        return c_3.x;
    }
    if (j_2 == 1u) {
        return c_3.y;
    }
    return c_3.z;
}

fn slot_share(slot_1: u32, k_3: u32) -> vec3<f32> {
    if (k_3 < 3u) {
        let _e4 = to_f32_(k_3);
        let w_8 = (1f / _e4);
        return vec3<f32>(w_8, w_8, w_8);
    }
    let j_3 = (slot_1 % 3u);
    let _e15 = to_f32_((((k_3 + 2u) - j_3) / 3u));
    let w_9 = (1f / _e15);
    if (j_3 == 0u) {
        return vec3<f32>(w_9, 0f, 0f);
    }
    if (j_3 == 1u) {
        return vec3<f32>(0f, w_9, 0f);
    }
    return vec3<f32>(0f, 0f, w_9);
}

fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
    if (cos_h <= 0f) {
        return 0f;
    }
    let a2_ = (alpha * alpha);
    let t_1 = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t_1 * t_1));
}

fn smith_root(cos_: f32, alpha_1: f32) -> f32 {
    let a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1f - a2_1)) + a2_1));
}

fn smith_visibility(n_l: f32, n_v: f32, alpha_2: f32) -> f32 {
    var local_6: bool;

    if !((n_l <= 0f)) {
        local_6 = (n_v <= 0f);
    } else {
        local_6 = true;
    }
    let _e11 = local_6;
    if _e11 {
        return 0f;
    }
    let _e13 = smith_root(n_v, alpha_2);
    let _e15 = smith_root(n_l, alpha_2);
    return (0.5f / ((n_l * _e13) + (n_v * _e15)));
}

fn fresnel_schlick(f0_: vec3<f32>, f90_: f32, v_h: f32) -> vec3<f32> {
    let c_9 = saturate((1f - v_h));
    let c2_ = (c_9 * c_9);
    return (f0_ + ((vec3<f32>(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_9)));
}

fn specular_fresnel(base: vec3<f32>, metallic: f32, f0_d: vec3<f32>, f90_d: f32, v_h_1: f32) -> vec3<f32> {
    let _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    let _e10 = fresnel_schlick(base, 1f, v_h_1);
    return ((_e5 * (1f - metallic)) + (_e10 * metallic));
}

fn has_specular(metallic_1: f32, f0_d_1: vec3<f32>, f90_d_1: f32) -> bool {
    var local_7: bool;
    var local_8: bool;

    if !((metallic_1 > 0f)) {
        local_7 = (f90_d_1 > 0f);
    } else {
        local_7 = true;
    }
    let _e11 = local_7;
    if !(_e11) {
        local_8 = (max(max(f0_d_1.x, f0_d_1.y), f0_d_1.z) > 0f);
    } else {
        local_8 = true;
    }
    let _e23 = local_8;
    return _e23;
}

fn channel_mean(c_4: vec3<f32>) -> f32 {
    return (((c_4.x + c_4.y) + c_4.z) * 0.33333334f);
}

fn receiver_lobe(base_1: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n_v_1: f32) -> vec4<f32> {
    var local_9: bool;

    let _e10 = fresnel_schlick(f0_d_2, f90_d_2, n_v_1);
    let _e16 = channel_mean((((vec3<f32>(1f, 1f, 1f) - _e10) * base_1) * (1f - metallic_2)));
    if !((n_v_1 <= 0f)) {
        let _e22 = has_specular(metallic_2, f0_d_2, f90_d_2);
        local_9 = !(_e22);
    } else {
        local_9 = true;
    }
    let _e25 = local_9;
    if _e25 {
        return vec4<f32>(_e16, 0f, alpha_3, n_v_1);
    }
    let _e28 = specular_fresnel(base_1, metallic_2, f0_d_2, f90_d_2, n_v_1);
    let _e29 = channel_mean(_e28);
    return vec4<f32>(_e16, _e29, alpha_3, n_v_1);
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

fn mirror_dir(n_2: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    return ((n_2 * (2f * dot(n_2, v))) - v);
}

fn bevy_alpha(perceptual: f32) -> f32 {
    let r_11 = clamp(perceptual, 0.089f, 1f);
    return (r_11 * r_11);
}

fn bevy_f0_(reflectance: f32) -> f32 {
    return ((0.16f * reflectance) * reflectance);
}

fn bevy_dfg(r_2: f32, n_v_2: f32) -> f32 {
    let rx = (1f - r_2);
    let a004_ = ((min((rx * rx), exp2((-9.28f * n_v_2))) * rx) + (0.0425f - (0.0275f * r_2)));
    let x_12 = max(((1.04f - (0.572f * r_2)) - (1.04f * a004_)), 0.00005f);
    let y_1 = max((((0.022f * r_2) - 0.04f) + (1.04f * a004_)), 0.00005f);
    return (x_12 + y_1);
}

fn bevy_brdf(base_2: vec3<f32>, metallic_3: f32, r_3: f32, reflectance_1: f32, n_3: vec3<f32>, v_1: vec3<f32>, l: vec3<f32>) -> vec3<f32> {
    let n_l_1 = saturate(dot(n_3, l));
    if (n_l_1 <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = bevy_alpha(r_3);
    let n_v_3 = max(dot(n_3, v_1), 0.0001f);
    let h_2 = normalize((l + v_1));
    let n_h = saturate(dot(n_3, h_2));
    let l_h = saturate(dot(l, h_2));
    let f90_d_3 = (0.5f + (((2f * _e15) * l_h) * l_h));
    let _e35 = fresnel_schlick(vec3<f32>(1f, 1f, 1f), f90_d_3, n_l_1);
    let _e41 = fresnel_schlick(vec3<f32>(1f, 1f, 1f), f90_d_3, n_v_3);
    let burley = ((_e35.x * _e41.x) * INV_PI);
    let _e46 = bevy_f0_(reflectance_1);
    let f0_1 = ((vec3<f32>(_e46, _e46, _e46) * (1f - metallic_3)) + (base_2 * metallic_3));
    let f90_1 = saturate((((f0_1.x + f0_1.y) + f0_1.z) * 16.5f));
    let _e64 = ggx_d(n_h, (1f - (n_h * n_h)), _e15);
    let _e65 = smith_visibility(n_l_1, n_v_3, _e15);
    let _e70 = bevy_dfg(r_3, n_v_3);
    let comp = (vec3<f32>(1f, 1f, 1f) + (f0_1 * ((1f / _e70) - 1f)));
    let _e77 = fresnel_schlick(f0_1, f90_1, l_h);
    let spec = ((_e77 * comp) * (_e64 * _e65));
    return ((base_2 * ((1f - metallic_3) * burley)) + spec);
}

fn cone_cos_of(v_2: vec3<f32>, d2_4: f32, a_3: f32, d: vec3<f32>) -> f32 {
    var local_10: bool;
    var local_11: bool;

    let vd = dot(v_2, d);
    let h2_ = (d2_4 - (a_3 * a_3));
    if !((h2_ <= 0f)) {
        if (vd >= 0f) {
            local_11 = ((vd * vd) >= h2_);
        } else {
            local_11 = false;
        }
        let _e19 = local_11;
        local_10 = _e19;
    } else {
        local_10 = true;
    }
    let _e21 = local_10;
    if _e21 {
        return 1f;
    }
    let c_10 = cross(v_2, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_10, c_10)) * a_3)) / d2_4), 1f);
}

fn cone_cos_toward(center: vec3<f32>, radius: f32, p: vec3<f32>, d_1: vec3<f32>) -> f32 {
    let v_7 = (center - p);
    let _e6 = cone_cos_of(v_7, dot(v_7, v_7), radius, d_1);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_2 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_2 * t_2))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_1: vec3<f32>, radius_1: f32, p_1: vec3<f32>, r_4: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_1, radius_1, p_1, r_4);
    let _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

fn shadow_margin(len: f32) -> f32 {
    return (0.0001f * len);
}

fn ray_inverse(x_3: f32) -> f32 {
    return (1f / select(x_3, 0.000000000000000000000000000001f, (abs(x_3) < 0.000000000000000000000000000001f)));
}

fn ray_inverse3_(d_2: vec3<f32>) -> vec3<f32> {
    let _e2 = ray_inverse(d_2.x);
    let _e4 = ray_inverse(d_2.y);
    let _e6 = ray_inverse(d_2.z);
    return vec3<f32>(_e2, _e4, _e6);
}

fn ray_aabb(o: vec3<f32>, inv_d: vec3<f32>, bmin: vec3<f32>, bmax: vec3<f32>, t_max: f32) -> f32 {
    let t0_ = ((bmin - o) * inv_d);
    let t1_ = ((bmax - o) * inv_d);
    let lo = min(t0_, t1_);
    let hi = max(t0_, t1_);
    let t_in = max(max(lo.x, lo.y), max(lo.z, 0f));
    let t_out = min(min(hi.x, hi.y), min(hi.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1f;
}

fn triangle_normal(a_4: vec3<f32>, b_4: vec3<f32>, c_5: vec3<f32>) -> vec3<f32> {
    var local_12: bool;

    let n_9 = cross((b_4 - a_4), (c_5 - a_4));
    let l2_ = dot(n_9, n_9);
    if !(!((l2_ > 0f))) {
        local_12 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_12 = true;
    }
    let _e17 = local_12;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_9 / vec3(sqrt(l2_)));
}

fn ray_triangle(o_1: vec3<f32>, d_3: vec3<f32>, a_5: vec3<f32>, b_5: vec3<f32>, c_6: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_13: bool;
    var local_14: bool;
    var local_15: bool;

    let e1_ = (b_5 - a_5);
    let e2_ = (c_6 - a_5);
    let p_2 = cross(d_3, e2_);
    let det = dot(e1_, p_2);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv = (1f / det);
    let s_4 = (o_1 - a_5);
    let u_3 = (dot(s_4, p_2) * inv);
    if !((u_3 < 0f)) {
        local_13 = (u_3 > 1f);
    } else {
        local_13 = true;
    }
    let _e28 = local_13;
    if _e28 {
        return -1f;
    }
    let q_1 = cross(s_4, e1_);
    let v_8 = (dot(d_3, q_1) * inv);
    if !((v_8 < 0f)) {
        local_14 = ((u_3 + v_8) > 1f);
    } else {
        local_14 = true;
    }
    let _e42 = local_14;
    if _e42 {
        return -1f;
    }
    let t_3 = (dot(e2_, q_1) * inv);
    if (t_3 > t_min) {
        local_15 = (t_3 < t_max_1);
    } else {
        local_15 = false;
    }
    let _e51 = local_15;
    if _e51 {
        return t_3;
    }
    return -1f;
}

fn light_intensity(l_1: GpuLight, w_3: vec3<f32>) -> vec3<f32> {
    switch l_1.kind {
        case 0u: {
            return l_1.intensity;
        }
        case 3u: {
            let _e8 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
            let _e10 = triangle_lobe(_e8, l_1.a, w_3);
            return (l_1.intensity * _e10);
        }
        default: {
            return vec3(0f);
        }
    }
}

fn light_point(l_2: GpuLight, u1_1: f32, u2_1: f32) -> vec3<f32> {
    if (l_2.kind == LIGHT_TRIANGLE) {
        let _e9 = triangle_sample(l_2.p0_, l_2.p1_, l_2.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_2.p0_;
}

fn trace(o_2: vec3<f32>, d_4: vec3<f32>, t_min_1: f32, t_max_2: f32, any_hit: bool) -> GeoHit {
    var hit: GeoHit;
    var stack: array<u32, 64>;
    var sp: u32 = 0u;
    var node_2: u32 = 0u;
    var i: u32;

    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if (arrayLength((&geo_nodes)) == 0u) {
        let _e13 = hit;
        return _e13;
    }
    let _e14 = ray_inverse3_(d_4);
    loop {
        let _e21 = node_2;
        let n_10 = geo_nodes[_e21];
        let _e27 = hit.t;
        let _e28 = ray_aabb(o_2, _e14, n_10.bmin, n_10.bmax, _e27);
        if (_e28 >= 0f) {
            if (n_10.count > 0u) {
                i = n_10.first;
                loop {
                    let _e36 = i;
                    if (_e36 < (n_10.first + n_10.count)) {
                    } else {
                        break;
                    }
                    {
                        let _e42 = i;
                        let t_4 = geo_tris[_e42];
                        let _e49 = hit.t;
                        let _e50 = ray_triangle(o_2, d_4, t_4.v0_, t_4.v1_, t_4.v2_, t_min_1, _e49);
                        if (_e50 > 0f) {
                            hit.t = _e50;
                            let _e55 = i;
                            hit.tri = _e55;
                            if any_hit {
                                let _e56 = hit;
                                return _e56;
                            }
                        }
                    }
                    continuing {
                        let _e58 = i;
                        i = (_e58 + 1u);
                    }
                }
            } else {
                let _e60 = sp;
                if (_e60 < 64u) {
                    let _e63 = sp;
                    stack[_e63] = (n_10.first + 1u);
                    let _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_2 = n_10.first;
                continue;
            }
        }
        let _e72 = sp;
        if (_e72 == 0u) {
            break;
        }
        let _e75 = sp;
        sp = (_e75 - 1u);
        let _e78 = sp;
        let _e80 = stack[_e78];
        node_2 = _e80;
    }
    let _e81 = hit;
    return _e81;
}

fn occluded(a_6: vec3<f32>, b_6: vec3<f32>) -> bool {
    let dv = (b_6 - a_6);
    let len_1 = length(dv);
    if (len_1 <= 0f) {
        return false;
    }
    let _e7 = shadow_margin(len_1);
    let _e12 = trace(a_6, (dv / vec3(len_1)), _e7, (len_1 - _e7), true);
    return (_e12.tri != NO_LIGHT);
}

fn bsh_node(nodes: u32, i_1: u32) -> BshNode {
    let _e4 = bsh_nodes[i_1];
    return _e4;
}

fn bsh_count(nodes_1: u32) -> u32 {
    return arrayLength((&bsh_nodes));
}

fn bsh_first(nodes_2: u32) -> u32 {
    let _e1 = bsh_count(nodes_2);
    if (_e1 > 0u) {
        return 0u;
    }
    return BSH_NONE;
}

fn bsh_inner_scale(a_7: f32, v_3: vec3<f32>, d2_5: f32, r_5: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let _e5 = cone_cos_of(v_3, d2_5, a_7, r_5);
    let _e8 = range_scale_at(rl_2, (_e5 + 0.000002f));
    return _e8;
}

fn bsh_reaches(node_3: BshNode, x_4: vec3<f32>, r_6: vec3<f32>, rl_3: vec4<f32>) -> bool {
    var local_16: bool;
    var local_17: bool;

    let _e6 = sphere_contains_point(node_3.center, node_3.radius, x_4);
    if _e6 {
        return true;
    }
    if !((rl_3.w <= 1f)) {
        let _e20 = sphere_contains_point(node_3.center, (node_3.radius * (rl_3.w * 1.0001f)), x_4);
        local_16 = !(_e20);
    } else {
        local_16 = true;
    }
    let _e23 = local_16;
    if _e23 {
        return false;
    }
    let _e25 = bsh_range_bound(node_3);
    let v_9 = (x_4 - node_3.center);
    let d2_7 = dot(v_9, v_9);
    let reach_max = (node_3.extent + ((rl_3.w * 1.001f) * _e25));
    if (d2_7 > (reach_max * reach_max)) {
        return false;
    }
    if (node_3.child == BSH_NONE) {
        let _e43 = range_scale_toward(rl_3, node_3.center, node_3.extent, x_4, r_6);
        let _e46 = bsh_scaled_radius(node_3, sqrt(_e43));
        let _e47 = sphere_contains_point(node_3.center, _e46, x_4);
        return _e47;
    }
    let _e50 = bsh_inner_scale(node_3.extent, -(v_9), d2_7, r_6, rl_3);
    let s_c = (_e50 * 1.001f);
    let reach = (node_3.extent + (sqrt(s_c) * _e25));
    if (d2_7 <= ((node_3.radius * node_3.radius) * s_c)) {
        local_17 = (d2_7 <= (reach * reach));
    } else {
        local_17 = false;
    }
    let _e67 = local_17;
    return _e67;
}

fn bsh_next_leaf_lobe(nodes_3: u32, start: u32, x_5: vec3<f32>, r_7: vec3<f32>, rl_4: vec4<f32>) -> u32 {
    var i_2: u32;

    i_2 = start;
    loop {
        let _e6 = i_2;
        if (_e6 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e9 = i_2;
            let _e10 = bsh_node(nodes_3, _e9);
            let _e11 = bsh_reaches(_e10, x_5, r_7, rl_4);
            if _e11 {
                if (_e10.child == BSH_NONE) {
                    let _e15 = i_2;
                    return _e15;
                }
                i_2 = _e10.child;
            } else {
                i_2 = _e10.next;
            }
        }
    }
    return BSH_NONE;
}

fn next_threshold(sum: f32, h_1: ptr<function, u32>) -> f32 {
    let _e2 = (*h_1);
    let _e3 = pcg_hash(_e2);
    (*h_1) = _e3;
    let _e4 = (*h_1);
    let _e5 = xi_from_bits(_e4);
    let _e6 = weighted_threshold(sum, _e5);
    return _e6;
}

fn connect_record(l_3: GpuLight, x_6: vec3<f32>, n_4: vec3<f32>, ng_1: vec3<f32>, r2_2: f32, rt2_2: f32, w_res: f32, u1_2: f32, u2_2: f32, eps: f32, trace_1: bool) -> Connection {
    var c_7: Connection;
    var local_18: bool;
    var local_19: bool;

    c_7.e = vec3(0f);
    let _e16 = light_point(l_3, u1_2, u2_2);
    c_7.y = _e16;
    let _e19 = c_7.y;
    let _e20 = connection_cosine(x_6, _e19, n_4, ng_1, r2_2);
    c_7.cos_x = _e20;
    let _e22 = c_7.cos_x;
    if !((_e22 <= 0f)) {
        if trace_1 {
            let _e33 = c_7.y;
            let _e34 = occluded((x_6 + (ng_1 * eps)), _e33);
            local_19 = _e34;
        } else {
            local_19 = false;
        }
        let _e36 = local_19;
        local_18 = _e36;
    } else {
        local_18 = true;
    }
    let _e38 = local_18;
    if _e38 {
        let _e39 = c_7;
        return _e39;
    }
    let _e41 = c_7.y;
    let v_10 = (x_6 - _e41);
    let d2_8 = dot(v_10, v_10);
    let _e48 = light_intensity(l_3, (v_10 / vec3(sqrt(d2_8))));
    let _e50 = c_7.cos_x;
    let _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_7.e = (_e48 * _e51);
    let _e53 = c_7;
    return _e53;
}

fn connect_traced(li: u32, x_7: vec3<f32>, n_5: vec3<f32>, ng_2: vec3<f32>, s: f32, w_res_1: f32, u1_3: f32, u2_3: f32, eps_1: f32, trace_2: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_3[li];
    let _e19 = rt2_3[li];
    let _e21 = connect_record(_e12, x_7, n_5, ng_2, (s * _e15), (s * _e19), w_res_1, u1_3, u2_3, eps_1, trace_2);
    return _e21;
}

fn light_range_scale(li_1: u32, x_8: vec3<f32>, r_8: vec3<f32>, rl_5: vec4<f32>) -> f32 {
    let c_11 = light_cones[li_1];
    let _e9 = range_scale_toward(rl_5, c_11.center, c_11.radius, x_8, r_8);
    return _e9;
}

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p_3 = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p_3.xyz, 1f), (p_3.w > 0f));
}

fn shade_connection(c_8: Connection, x_9: vec3<f32>, n_6: vec3<f32>, m_1: Material) -> Shaded {
    var s_1: Shaded;

    s_1.e = c_8.e;
    s_1.diffuse = vec3(0f);
    s_1.specular = vec3(0f);
    if (c_8.cos_x > 0f) {
        let _e25 = bevy_brdf(m_1.base, m_1.metallic, m_1.roughness, m_1.reflectance, n_6, m_1.v, normalize((c_8.y - x_9)));
        s_1.diffuse = (_e25 * c_8.e);
    }
    let _e28 = s_1;
    return _e28;
}

fn shade_pick_traced(li_2: u32, x_10: vec3<f32>, n_7: vec3<f32>, r_9: vec3<f32>, rl_6: vec4<f32>, m_2: Material, w_4: f32, u1_4: f32, u2_4: f32, eps_2: f32, trace_3: bool) -> Shaded {
    let _e11 = light_range_scale(li_2, x_10, r_9, rl_6);
    let _e12 = connect_traced(li_2, x_10, n_7, n_7, _e11, w_4, u1_4, u2_4, eps_2, trace_3);
    let _e13 = shade_connection(_e12, x_10, n_7, m_2);
    return _e13;
}

fn shade_pick(li_3: u32, x_11: vec3<f32>, n_8: vec3<f32>, r_10: vec3<f32>, rl_7: vec4<f32>, m_3: Material, w_5: f32, u1_5: f32, u2_5: f32, eps_3: f32) -> Shaded {
    let _e11 = shade_pick_traced(li_3, x_11, n_8, r_10, rl_7, m_3, w_5, u1_5, u2_5, eps_3, true);
    return _e11;
}

fn material_of(base_3: vec3<f32>, metallic_4: f32, roughness: f32, reflectance_2: f32, v_4: vec3<f32>) -> Material {
    let _e6 = bevy_alpha(roughness);
    return Material(base_3, saturate(metallic_4), _e6, v_4, roughness, reflectance_2);
}

fn add(a_8: Shaded, b_7: Shaded) -> Shaded {
    return Shaded((a_8.e + b_7.e), (a_8.diffuse + b_7.diffuse), (a_8.specular + b_7.specular));
}

fn scaled(s_2: Shaded, w_6: vec3<f32>) -> Shaded {
    return Shaded((s_2.e * w_6), (s_2.diffuse * w_6), (s_2.specular * w_6));
}

fn first_holders(keys_1: array<vec2<u32>, 8>, held_1: array<bool, 8>) -> array<u32, 8> {
    var first: array<u32, 8>;
    var k_4: u32 = 0u;
    var j_1: u32;
    var local_20: bool;
    var local_21: bool;

    loop {
        let _e5 = k_4;
        if (_e5 < K) {
        } else {
            break;
        }
        {
            let _e8 = k_4;
            let _e11 = k_4;
            let _e12 = k_4;
            first[_e8] = select(K, _e11, held_1[_e12]);
            j_1 = 0u;
            loop {
                let _e17 = j_1;
                let _e18 = k_4;
                if (_e17 < _e18) {
                    let _e22 = k_4;
                    local_20 = held_1[_e22];
                } else {
                    local_20 = false;
                }
                let _e25 = local_20;
                if _e25 {
                } else {
                    break;
                }
                {
                    let _e26 = j_1;
                    if held_1[_e26] {
                        let _e30 = j_1;
                        let _e32 = k_4;
                        local_21 = all((keys_1[_e30] == keys_1[_e32]));
                    } else {
                        local_21 = false;
                    }
                    let _e37 = local_21;
                    if _e37 {
                        let _e38 = k_4;
                        let _e40 = j_1;
                        first[_e38] = _e40;
                        break;
                    }
                }
                continuing {
                    let _e42 = j_1;
                    j_1 = (_e42 + 1u);
                }
            }
        }
        continuing {
            let _e45 = k_4;
            k_4 = (_e45 + 1u);
        }
    }
    let _e47 = first;
    return _e47;
}

fn output_of(s_3: Shaded) -> vec3<f32> {
    return (s_3.diffuse + s_3.specular);
}

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var local: bool;
    var local_1: bool;
    var m: Material;
    var lobe: vec4<f32> = vec4<f32>(1f, 0f, 1f, 1f);
    var r: vec3<f32>;
    var h: u32;
    var t: Shaded = Shaded(vec3(0f), vec3(0f), vec3(0f));
    var slot_light: array<u32, 8>;
    var slot_u: array<vec2<f32>, 8>;
    var slot_p: array<f32, 8>;
    var total: vec3<f32> = vec3(0f);
    var count: u32 = 0u;
    var hc: u32;
    var threshold: array<f32, 8>;
    var b: u32;
    var q: u32;
    var local_2: bool;
    var keys: array<vec2<u32>, 8>;
    var held: array<bool, 8>;
    var k: u32 = 0u;
    var k_1: u32 = 0u;
    var w: vec3<f32>;
    var j: u32;
    var local_3: bool;

    let _e4 = view.width;
    if !((gid.x >= _e4)) {
        let _e12 = view.height;
        local = (gid.y >= _e12);
    } else {
        local = true;
    }
    let _e15 = local;
    if _e15 {
        return;
    }
    let texel_1 = vec2<i32>(i32(gid.x), i32(gid.y));
    let _e21 = surface_at(texel_1);
    let _e24 = textureLoad(normal_tex, texel_1, 0i);
    let nn = _e24.xyz;
    let len2_ = dot(nn, nn);
    if !((_e21.w <= 0f)) {
        local_1 = !((len2_ > 0f));
    } else {
        local_1 = true;
    }
    let _e37 = local_1;
    if _e37 {
        textureStore(out_tex, texel_1, vec4(0f));
        return;
    }
    let x_13 = _e21.xyz;
    let n_11 = (nn / vec3(sqrt(len2_)));
    r = n_11;
    let mr = textureLoad(metal_rough_tex, texel_1, 0i);
    let _e58 = textureLoad(base_color_tex, texel_1, 0i);
    let _e65 = view.eye;
    let _e68 = material_of(_e58.xyz, mr.z, mr.y, mr.w, normalize((_e65 - x_13)));
    m = _e68;
    let _e70 = m.base;
    let _e72 = m.metallic;
    let _e74 = bevy_f0_(mr.w);
    let _e78 = m.alpha;
    let _e80 = m.v;
    let _e82 = receiver_lobe(_e70, _e72, vec3(_e74), 1f, _e78, dot(n_11, _e80));
    lobe = _e82;
    let _e84 = m.v;
    let _e85 = mirror_dir(n_11, _e84);
    r = _e85;
    let _e86 = lobe;
    let _e87 = range_lobe(_e86);
    let _e90 = view.shadow_offset;
    let _e93 = view.eye;
    let eps_4 = (_e90 * length((_e93 - x_13)));
    let _e99 = view.seed;
    let _e103 = view.width;
    let _e109 = view.frame;
    let _e110 = point_stream(_e99, ((gid.y * _e103) + gid.x), _e109);
    let _e111 = pick_stream(_e110);
    h = _e111;
    hc = _e110;
    let _e133 = bsh_first(BSH);
    let _e134 = r;
    let _e135 = bsh_next_leaf_lobe(BSH, _e133, x_13, _e134, _e87);
    b = _e135;
    loop {
        let _e137 = b;
        if (_e137 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e140 = count;
            count = (_e140 + 1u);
            let _e144 = b;
            let li_4 = bsh_nodes[_e144].light;
            let _e148 = h;
            let _e149 = pcg_hash(_e148);
            h = _e149;
            let _e150 = h;
            let _e151 = xi_from_bits(_e150);
            let _e152 = h;
            let _e153 = pcg_hash(_e152);
            h = _e153;
            let _e154 = h;
            let _e155 = xi_from_bits(_e154);
            let u_4 = vec2<f32>(_e151, _e155);
            let _e157 = r;
            let _e158 = m;
            let _e163 = shade_pick_traced(li_4, x_13, n_11, _e157, _e87, _e158, 1f, u_4.x, u_4.y, eps_4, false);
            let _e164 = output_of(_e163);
            let _e165 = resample_target(_e164);
            if (_e165 > 0f) {
                let _e168 = total;
                total = (_e168 + _e164);
                q = 0u;
                loop {
                    let _e172 = q;
                    if (_e172 < K) {
                    } else {
                        break;
                    }
                    {
                        let _e175 = q;
                        let _e177 = slot_target(_e164, _e175, K);
                        let _e178 = total;
                        let _e179 = q;
                        let _e181 = slot_target(_e178, _e179, K);
                        if (_e177 > 0f) {
                            let _e186 = q;
                            let _e188 = threshold[_e186];
                            local_2 = (_e181 > _e188);
                        } else {
                            local_2 = false;
                        }
                        let _e191 = local_2;
                        if _e191 {
                            let _e192 = q;
                            slot_light[_e192] = li_4;
                            let _e194 = q;
                            slot_u[_e194] = u_4;
                            let _e196 = q;
                            slot_p[_e196] = _e177;
                            let _e198 = q;
                            let _e200 = next_threshold(_e181, (&hc));
                            threshold[_e198] = _e200;
                        }
                    }
                    continuing {
                        let _e202 = q;
                        q = (_e202 + 1u);
                    }
                }
            }
        }
        continuing {
            let _e206 = b;
            let _e209 = bsh_nodes[_e206].next;
            let _e210 = r;
            let _e211 = bsh_next_leaf_lobe(BSH, _e209, x_13, _e210, _e87);
            b = _e211;
        }
    }
    loop {
        let _e216 = k;
        if (_e216 < K) {
        } else {
            break;
        }
        {
            let _e219 = k;
            let _e221 = k;
            let _e223 = slot_light[_e221];
            keys[_e219] = vec2<u32>(_e223, 0u);
            let _e226 = k;
            let _e228 = k;
            let _e230 = slot_p[_e228];
            held[_e226] = (_e230 > 0f);
        }
        continuing {
            let _e234 = k;
            k = (_e234 + 1u);
        }
    }
    let _e236 = keys;
    let _e237 = held;
    let _e238 = first_holders(_e236, _e237);
    loop {
        let _e241 = k_1;
        if (_e241 < K) {
        } else {
            break;
        }
        {
            w = vec3(0f);
            let _e247 = k_1;
            let _e249 = k_1;
            let first_1 = (_e238[_e247] == _e249);
            let _e251 = k_1;
            j = _e251;
            loop {
                let _e253 = j;
                if (_e253 < K) {
                    local_3 = first_1;
                } else {
                    local_3 = false;
                }
                let _e259 = local_3;
                if _e259 {
                } else {
                    break;
                }
                {
                    let _e260 = j;
                    let _e262 = k_1;
                    if (_e238[_e260] == _e262) {
                        let _e264 = w;
                        let _e265 = total;
                        let _e266 = j;
                        let _e268 = slot_target(_e265, _e266, K);
                        let _e269 = j;
                        let _e271 = slot_p[_e269];
                        let _e273 = j;
                        let _e275 = slot_share(_e273, K);
                        w = (_e264 + ((_e268 / _e271) * _e275));
                    }
                }
                continuing {
                    let _e279 = j;
                    j = (_e279 + 1u);
                }
            }
            if first_1 {
                let _e281 = t;
                let _e282 = k_1;
                let _e284 = slot_light[_e282];
                let _e285 = r;
                let _e286 = m;
                let _e288 = k_1;
                let _e291 = slot_u[_e288].x;
                let _e292 = k_1;
                let _e295 = slot_u[_e292].y;
                let _e296 = shade_pick(_e284, x_13, n_11, _e285, _e87, _e286, 1f, _e291, _e295, eps_4);
                let _e297 = w;
                let _e298 = scaled(_e296, _e297);
                let _e299 = add(_e281, _e298);
                t = _e299;
            }
        }
        continuing {
            let _e301 = k_1;
            k_1 = (_e301 + 1u);
        }
    }
    let _e305 = t.diffuse;
    let _e307 = t.specular;
    let _e309 = count;
    textureStore(out_tex, texel_1, vec4<f32>((_e305 + _e307), f32(_e309)));
    return;
}
