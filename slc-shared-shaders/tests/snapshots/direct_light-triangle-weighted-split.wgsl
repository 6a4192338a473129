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

struct WeightedPicks {
    light: array<u32, 8>,
    w: array<f32, 8>,
    threshold: array<f32, 8>,
    w_sum: f32,
    n: u32,
    h: u32,
}

struct WorkgroupBox {
    lo: vec3<f32>,
    hi: vec3<f32>,
}

struct TileWalk {
    lo: vec3<f32>,
    hi: vec3<f32>,
    w: f32,
    total: u32,
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
const GRID_HEADER: u32 = 32u;
const GRID_LEVELS_MAX: u32 = 8u;
const GRIDS_MAX: u32 = 3u;
const GRID_SORT_MOVES: u32 = 1024u;
const GRID_SORT_MAX: u32 = 1024u;
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
const K: u32 = 8u;
const BSH: u32 = 0u;
const BSH_TILE_DEPTH: u32 = 8u;
const BSH_TILE_SUBTREES: u32 = 256u;
const TILE_THREADS: u32 = 64u;
const BOX_THREADS: u32 = 64u;
const TILE_LIST: u32 = 1024u;

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
@group(0) @binding(6) 
var specular_tex: texture_storage_2d<rgba16float,write>;
@group(1) @binding(1) 
var<storage> lights: array<GpuLight>;
@group(1) @binding(2) 
var<storage> rt2_5: array<f32>;
@group(1) @binding(3) 
var<storage> r2_4: array<f32>;
@group(1) @binding(4) 
var<storage> bsh_nodes: array<BshNode>;
@group(1) @binding(5) 
var<storage> light_cones: array<GpuLightCone>;
var<workgroup> wg_lo: array<vec3<f32>, 64>;
var<workgroup> wg_hi: array<vec3<f32>, 64>;
var<workgroup> wg_box: WorkgroupBox;
var<workgroup> tile_list: array<u32, 1024>;
var<workgroup> subtree_at: array<u32, 256>;
var<workgroup> tile_scale: atomic<u32>;
var<workgroup> tile_total: u32;

fn to_f32_(u: u32) -> f32 {
    return f32(u);
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
    let v_6 = (x_1 - c);
    return (dot(v_6, v_6) <= (r_1 * r_1));
}

fn sphere_overlaps_aabb(c_1: vec3<f32>, r_2: f32, bmin: vec3<f32>, bmax: vec3<f32>) -> bool {
    let q = clamp(c_1, bmin, bmax);
    let v_7 = (q - c_1);
    return (dot(v_7, v_7) <= (r_2 * r_2));
}

fn inverse_square(d2_2: f32) -> f32 {
    return (1f / max(d2_2, MIN_D2_));
}

fn connection_factor(cos_x: f32, d2_3: f32, rt2_1: f32, w: f32) -> f32 {
    let _e4 = inverse_square(d2_3);
    let _e6 = slc_weight(rt2_1, d2_3);
    return (((cos_x * _e4) * _e6) * w);
}

fn connection_cosine(x_2: vec3<f32>, y: vec3<f32>, n_1: vec3<f32>, ng: vec3<f32>, r2_1: f32) -> f32 {
    var local_5: bool;
    var local_6: bool;

    let v_8 = (x_2 - y);
    let d2_7 = dot(v_8, v_8);
    let _e7 = slc_keep(r2_1, d2_7);
    if !(!(_e7)) {
        local_5 = !((d2_7 > 0f));
    } else {
        local_5 = true;
    }
    let _e16 = local_5;
    if _e16 {
        return 0f;
    }
    let w_11 = (v_8 / vec3(sqrt(d2_7)));
    let cos_x_1 = -(dot(n_1, w_11));
    if !(!((cos_x_1 > 0f))) {
        local_6 = !((dot(ng, w_11) < 0f));
    } else {
        local_6 = true;
    }
    let _e34 = local_6;
    if _e34 {
        return 0f;
    }
    return cos_x_1;
}

fn triangle_lobe(n_2: vec3<f32>, area: f32, w_1: vec3<f32>) -> f32 {
    return (area * max(dot(n_2, w_1), 0f));
}

fn triangle_sample(a_2: vec3<f32>, b_2: vec3<f32>, c_2: vec3<f32>, u1_: f32, u2_: f32) -> vec3<f32> {
    let su = sqrt(u1_);
    let b0_ = (1f - su);
    let b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_2 * ((1f - b0_) - b1_)));
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

fn bsh_reach_bound(node_2: BshNode, w_2: f32) -> f32 {
    let _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_2 * 1.001f) * _e5));
}

fn weighted_threshold(w_sum: f32, u_2: f32) -> f32 {
    return (w_sum / (1f - u_2));
}

fn weighted_pick_weight(w_sum_1: f32, w_3: f32, k_2: u32) -> f32 {
    let _e3 = to_f32_(k_2);
    return (w_sum_1 / (_e3 * w_3));
}

fn ggx_alpha(roughness: f32) -> f32 {
    return max((roughness * roughness), GGX_ALPHA_MIN);
}

fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
    if (cos_h <= 0f) {
        return 0f;
    }
    let a2_ = (alpha * alpha);
    let t_4 = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t_4 * t_4));
}

fn smith_root(cos_: f32, alpha_1: f32) -> f32 {
    let a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1f - a2_1)) + a2_1));
}

fn smith_visibility(n_l: f32, n_v: f32, alpha_2: f32) -> f32 {
    var local_7: bool;

    if !((n_l <= 0f)) {
        local_7 = (n_v <= 0f);
    } else {
        local_7 = true;
    }
    let _e11 = local_7;
    if _e11 {
        return 0f;
    }
    let _e13 = smith_root(n_v, alpha_2);
    let _e15 = smith_root(n_l, alpha_2);
    return (0.5f / ((n_l * _e13) + (n_v * _e15)));
}

fn fresnel_schlick(f0_: vec3<f32>, f90_: f32, v_h: f32) -> vec3<f32> {
    let c_8 = saturate((1f - v_h));
    let c2_ = (c_8 * c_8);
    return (f0_ + ((vec3<f32>(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_8)));
}

fn specular_fresnel(base: vec3<f32>, metallic: f32, f0_d: vec3<f32>, f90_d: f32, v_h_1: f32) -> vec3<f32> {
    let _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    let _e10 = fresnel_schlick(base, 1f, v_h_1);
    return ((_e5 * (1f - metallic)) + (_e10 * metallic));
}

fn diffuse_brdf(base_1: vec3<f32>, metallic_1: f32, f0_d_1: vec3<f32>, f90_d_1: f32, v_h_2: f32) -> vec3<f32> {
    let _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return ((((vec3<f32>(1f, 1f, 1f) - _e9) * base_1) * (1f - metallic_1)) * INV_PI);
}

fn half_cosine(v: vec3<f32>, l: vec3<f32>) -> f32 {
    let h_4 = (v + l);
    let len2_ = dot(h_4, h_4);
    if (len2_ <= 0f) {
        return 0f;
    }
    return saturate((dot(v, h_4) / sqrt(len2_)));
}

fn specular_brdf(base_2: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n_3: vec3<f32>, v_1: vec3<f32>, l_1: vec3<f32>) -> vec3<f32> {
    var local_8: bool;

    let n_l_1 = dot(n_3, l_1);
    let n_v_2 = dot(n_3, v_1);
    if !((n_l_1 <= 0f)) {
        local_8 = (n_v_2 <= 0f);
    } else {
        local_8 = true;
    }
    let _e18 = local_8;
    if _e18 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let hs = (v_1 + l_1);
    let inv = (1f / sqrt(dot(hs, hs)));
    let h_5 = (hs * inv);
    let c_9 = cross(n_3, h_5);
    let _e32 = ggx_d(dot(n_3, h_5), dot(c_9, c_9), alpha_3);
    let _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_1, h_5));
    let _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return (_e34 * (_e32 * _e35));
}

fn has_specular(metallic_3: f32, f0_d_3: vec3<f32>, f90_d_3: f32) -> bool {
    var local_9: bool;
    var local_10: bool;

    if !((metallic_3 > 0f)) {
        local_9 = (f90_d_3 > 0f);
    } else {
        local_9 = true;
    }
    let _e11 = local_9;
    if !(_e11) {
        local_10 = (max(max(f0_d_3.x, f0_d_3.y), f0_d_3.z) > 0f);
    } else {
        local_10 = true;
    }
    let _e23 = local_10;
    return _e23;
}

fn channel_mean(c_3: vec3<f32>) -> f32 {
    return (((c_3.x + c_3.y) + c_3.z) * 0.33333334f);
}

fn receiver_lobe(base_3: vec3<f32>, metallic_4: f32, f0_d_4: vec3<f32>, f90_d_4: f32, alpha_4: f32, n_v_1: f32) -> vec4<f32> {
    var local_11: bool;

    let _e10 = fresnel_schlick(f0_d_4, f90_d_4, n_v_1);
    let _e16 = channel_mean((((vec3<f32>(1f, 1f, 1f) - _e10) * base_3) * (1f - metallic_4)));
    if !((n_v_1 <= 0f)) {
        let _e22 = has_specular(metallic_4, f0_d_4, f90_d_4);
        local_11 = !(_e22);
    } else {
        local_11 = true;
    }
    let _e25 = local_11;
    if _e25 {
        return vec4<f32>(_e16, 0f, alpha_4, n_v_1);
    }
    let _e28 = specular_fresnel(base_3, metallic_4, f0_d_4, f90_d_4, n_v_1);
    let _e29 = channel_mean(_e28);
    return vec4<f32>(_e16, _e29, alpha_4, n_v_1);
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

fn mirror_dir(n_4: vec3<f32>, v_2: vec3<f32>) -> vec3<f32> {
    return ((n_4 * (2f * dot(n_4, v_2))) - v_2);
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

fn safe_sqrt(x_3: f32) -> f32 {
    return sqrt(max(x_3, 0f));
}

fn subtended_cos(dist2_: f32, r2_2: f32) -> f32 {
    let _e5 = safe_sqrt((1f - (r2_2 / dist2_)));
    return select(_e5, -1f, (dist2_ <= r2_2));
}

fn emitter_cone(center: vec3<f32>, radius: f32, axis: vec3<f32>, cos_o: f32, p: vec3<f32>) -> vec4<f32> {
    var local_12: bool;

    let v_9 = (p - center);
    let dist2_1 = dot(v_9, v_9);
    let r2_5 = (radius * radius);
    if (dist2_1 <= 0f) {
        local_12 = (r2_5 <= 0f);
    } else {
        local_12 = false;
    }
    let _e15 = local_12;
    if _e15 {
        return vec4<f32>(-2f, 0.000000000001f, -1f, 0f);
    }
    let d2_8 = max(max(dist2_1, r2_5), MIN_D2_);
    let wi = select(vec3<f32>(0f, 0f, 0f), (v_9 / vec3(sqrt(dist2_1))), (dist2_1 > 0f));
    let cos_w = dot(axis, wi);
    let _e38 = safe_sqrt((1f - (cos_w * cos_w)));
    let _e39 = subtended_cos(dist2_1, r2_5);
    let _e43 = safe_sqrt((1f - (_e39 * _e39)));
    let _e47 = safe_sqrt((1f - (cos_o * cos_o)));
    let _e48 = cos_sub_clamped(_e38, cos_w, _e47, cos_o);
    let _e49 = sin_sub_clamped(_e38, cos_w, _e47, cos_o);
    let _e50 = cos_sub_clamped(_e49, _e48, _e43, _e39);
    return vec4<f32>(_e50, d2_8, _e39, _e43);
}

fn emitter_importance(center_1: vec3<f32>, radius_1: f32, phi: f32, axis_1: vec3<f32>, cos_o_1: f32, cos_e: f32, p_1: vec3<f32>) -> f32 {
    let _e7 = emitter_cone(center_1, radius_1, axis_1, cos_o_1, p_1);
    if (_e7.x <= cos_e) {
        return 0f;
    }
    return ((phi * _e7.x) / _e7.y);
}

fn cone_cos_of(v_3: vec3<f32>, d2_4: f32, a_3: f32, d: vec3<f32>) -> f32 {
    var local_13: bool;
    var local_14: bool;

    let vd = dot(v_3, d);
    let h2_ = (d2_4 - (a_3 * a_3));
    if !((h2_ <= 0f)) {
        if (vd >= 0f) {
            local_14 = ((vd * vd) >= h2_);
        } else {
            local_14 = false;
        }
        let _e19 = local_14;
        local_13 = _e19;
    } else {
        local_13 = true;
    }
    let _e21 = local_13;
    if _e21 {
        return 1f;
    }
    let c_10 = cross(v_3, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_10, c_10)) * a_3)) / d2_4), 1f);
}

fn cone_cos_toward(center_2: vec3<f32>, radius_2: f32, p_2: vec3<f32>, d_1: vec3<f32>) -> f32 {
    let v_10 = (center_2 - p_2);
    let _e6 = cone_cos_of(v_10, dot(v_10, v_10), radius_2, d_1);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_5 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_5 * t_5))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_3: vec3<f32>, radius_3: f32, p_3: vec3<f32>, r_3: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_3, radius_3, p_3, r_3);
    let _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

fn light_importance(center_4: vec3<f32>, radius_4: f32, phi_1: f32, axis_2: vec3<f32>, cos_o_2: f32, cos_e_1: f32, p_4: vec3<f32>, n_5: vec3<f32>) -> f32 {
    var imp: f32;

    let _e8 = emitter_cone(center_4, radius_4, axis_2, cos_o_2, p_4);
    if (_e8.x <= cos_e_1) {
        return 0f;
    }
    imp = ((phi_1 * _e8.x) / _e8.y);
    if (dot(n_5, n_5) > 0f) {
        let v_11 = (center_4 - p_4);
        let dist2_2 = dot(v_11, v_11);
        let cos_i = dot(select(vec3<f32>(0f, 0f, 0f), (v_11 / vec3(sqrt(dist2_2))), (dist2_2 > 0f)), n_5);
        let _e33 = imp;
        let _e37 = safe_sqrt((1f - (cos_i * cos_i)));
        let _e40 = cos_sub_clamped(_e37, cos_i, _e8.w, _e8.z);
        imp = (_e33 * max(_e40, 0f));
    }
    let _e44 = imp;
    return max(_e44, 0f);
}

fn glossy_importance(center_5: vec3<f32>, radius_5: f32, phi_2: f32, axis_3: vec3<f32>, cos_o_3: f32, cos_e_2: f32, p_5: vec3<f32>, n_6: vec3<f32>, r_4: vec3<f32>, lobe_5: vec4<f32>) -> f32 {
    var local_15: bool;

    let _e10 = emitter_importance(center_5, radius_5, phi_2, axis_3, cos_o_3, cos_e_2, p_5);
    let _e11 = cone_cos_toward(center_5, radius_5, p_5, n_6);
    if !((_e10 <= 0f)) {
        local_15 = (_e11 <= 0f);
    } else {
        local_15 = true;
    }
    let _e20 = local_15;
    if _e20 {
        return 0f;
    }
    let _e22 = cone_cos_toward(center_5, radius_5, p_5, r_4);
    let _e27 = safe_sqrt((0.5f + (0.5f * _e22)));
    let _e33 = ggx_d(_e27, (1f - (_e27 * _e27)), lobe_5.z);
    let _e39 = smith_root(lobe_5.w, lobe_5.z);
    let spec = (((lobe_5.y * _e33) * 0.25f) / _e39);
    return (_e10 * (((lobe_5.x * INV_PI) * _e11) + spec));
}

fn candidate_weight(importance: f32, rt2_2: f32, d2_5: f32) -> f32 {
    let _e3 = slc_weight(rt2_2, d2_5);
    return (importance * _e3);
}

fn cone_weight(center_6: vec3<f32>, radius_6: f32, phi_3: f32, axis_4: vec3<f32>, cos_o_4: f32, cos_e_3: f32, rt2_3: f32, p_6: vec3<f32>, n_7: vec3<f32>, r_5: vec3<f32>, lobe_6: vec4<f32>) -> f32 {
    let v_12 = (p_6 - center_6);
    if (lobe_6.y <= 0f) {
        let _e15 = light_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_7);
        let _e19 = candidate_weight((_e15 * INV_PI), rt2_3, dot(v_12, v_12));
        return _e19;
    }
    let _e20 = glossy_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_7, r_5, lobe_6);
    let _e22 = candidate_weight(_e20, rt2_3, dot(v_12, v_12));
    return _e22;
}

fn shadow_margin(len: f32) -> f32 {
    return (0.0001f * len);
}

fn ray_inverse(x_4: f32) -> f32 {
    return (1f / select(x_4, 0.000000000000000000000000000001f, (abs(x_4) < 0.000000000000000000000000000001f)));
}

fn ray_inverse3_(d_2: vec3<f32>) -> vec3<f32> {
    let _e2 = ray_inverse(d_2.x);
    let _e4 = ray_inverse(d_2.y);
    let _e6 = ray_inverse(d_2.z);
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

fn triangle_normal(a_4: vec3<f32>, b_3: vec3<f32>, c_4: vec3<f32>) -> vec3<f32> {
    var local_16: bool;

    let n_14 = cross((b_3 - a_4), (c_4 - a_4));
    let l2_ = dot(n_14, n_14);
    if !(!((l2_ > 0f))) {
        local_16 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_16 = true;
    }
    let _e17 = local_16;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_14 / vec3(sqrt(l2_)));
}

fn ray_triangle(o_1: vec3<f32>, d_3: vec3<f32>, a_5: vec3<f32>, b_4: vec3<f32>, c_5: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_17: bool;
    var local_18: bool;
    var local_19: bool;

    let e1_ = (b_4 - a_5);
    let e2_ = (c_5 - a_5);
    let p_10 = cross(d_3, e2_);
    let det = dot(e1_, p_10);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv_1 = (1f / det);
    let s_9 = (o_1 - a_5);
    let u_3 = (dot(s_9, p_10) * inv_1);
    if !((u_3 < 0f)) {
        local_17 = (u_3 > 1f);
    } else {
        local_17 = true;
    }
    let _e28 = local_17;
    if _e28 {
        return -1f;
    }
    let q_1 = cross(s_9, e1_);
    let v_13 = (dot(d_3, q_1) * inv_1);
    if !((v_13 < 0f)) {
        local_18 = ((u_3 + v_13) > 1f);
    } else {
        local_18 = true;
    }
    let _e42 = local_18;
    if _e42 {
        return -1f;
    }
    let t_6 = (dot(e2_, q_1) * inv_1);
    if (t_6 > t_min) {
        local_19 = (t_6 < t_max_1);
    } else {
        local_19 = false;
    }
    let _e51 = local_19;
    if _e51 {
        return t_6;
    }
    return -1f;
}

fn light_intensity(l_2: GpuLight, w_4: vec3<f32>) -> vec3<f32> {
    switch l_2.kind {
        case 3u: {
            let _e7 = triangle_normal(l_2.p0_, l_2.p1_, l_2.p2_);
            let _e9 = triangle_lobe(_e7, l_2.a, w_4);
            return (l_2.intensity * _e9);
        }
        default: {
            return vec3(0f);
        }
    }
}

fn light_point(l_3: GpuLight, u1_1: f32, u2_1: f32) -> vec3<f32> {
    if (l_3.kind == LIGHT_TRIANGLE) {
        let _e9 = triangle_sample(l_3.p0_, l_3.p1_, l_3.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_3.p0_;
}

fn trace(o_2: vec3<f32>, d_4: vec3<f32>, t_min_1: f32, t_max_2: f32, any_hit: bool) -> GeoHit {
    var hit: GeoHit;
    var stack: array<u32, 64>;
    var sp: u32 = 0u;
    var node_3: u32 = 0u;
    var i: u32;

    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if (arrayLength((&geo_nodes)) == 0u) {
        let _e13 = hit;
        return _e13;
    }
    let _e14 = ray_inverse3_(d_4);
    loop {
        let _e21 = node_3;
        let n_15 = geo_nodes[_e21];
        let _e27 = hit.t;
        let _e28 = ray_aabb(o_2, _e14, n_15.bmin, n_15.bmax, _e27);
        if (_e28 >= 0f) {
            if (n_15.count > 0u) {
                i = n_15.first;
                loop {
                    let _e36 = i;
                    if (_e36 < (n_15.first + n_15.count)) {
                    } else {
                        break;
                    }
                    {
                        let _e42 = i;
                        let t_7 = geo_tris[_e42];
                        let _e49 = hit.t;
                        let _e50 = ray_triangle(o_2, d_4, t_7.v0_, t_7.v1_, t_7.v2_, t_min_1, _e49);
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
                    stack[_e63] = (n_15.first + 1u);
                    let _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_15.first;
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
        node_3 = _e80;
    }
    let _e81 = hit;
    return _e81;
}

fn occluded(a_6: vec3<f32>, b_5: vec3<f32>) -> bool {
    let dv = (b_5 - a_6);
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

fn bsh_inner_scale(a_7: f32, v_4: vec3<f32>, d2_6: f32, r_6: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let _e5 = cone_cos_of(v_4, d2_6, a_7, r_6);
    let _e8 = range_scale_at(rl_2, (_e5 + 0.000002f));
    return _e8;
}

fn bsh_reaches(node_4: BshNode, x_5: vec3<f32>, r_7: vec3<f32>, rl_3: vec4<f32>) -> bool {
    var local_20: bool;
    var local_21: bool;

    let _e6 = sphere_contains_point(node_4.center, node_4.radius, x_5);
    if _e6 {
        return true;
    }
    if !((rl_3.w <= 1f)) {
        let _e20 = sphere_contains_point(node_4.center, (node_4.radius * (rl_3.w * 1.0001f)), x_5);
        local_20 = !(_e20);
    } else {
        local_20 = true;
    }
    let _e23 = local_20;
    if _e23 {
        return false;
    }
    let v_14 = (x_5 - node_4.center);
    let d2_9 = dot(v_14, v_14);
    let _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_9 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        let _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_5, r_7);
        let _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        let _e42 = sphere_contains_point(node_4.center, _e41, x_5);
        return _e42;
    }
    let _e45 = bsh_inner_scale(node_4.extent, -(v_14), d2_9, r_7, rl_3);
    let s_c = (_e45 * 1.001f);
    let _e50 = bsh_range_bound(node_4);
    let reach = (node_4.extent + (sqrt(s_c) * _e50));
    if (d2_9 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_21 = (d2_9 <= (reach * reach));
    } else {
        local_21 = false;
    }
    let _e63 = local_21;
    return _e63;
}

fn bsh_reaches_box(node_5: BshNode, lo: vec3<f32>, hi: vec3<f32>, w_5: f32) -> bool {
    let _e13 = sphere_overlaps_aabb(node_5.center, (node_5.radius * (max(1f, (w_5 * 1.0001f)) * 1.0001f)), lo, hi);
    return _e13;
}

fn bsh_subtree(nodes_3: u32, s_1: u32, depth: u32) -> u32 {
    var i_2: u32;
    var level: u32 = 0u;
    var local_22: bool;

    let _e3 = bsh_first(nodes_3);
    i_2 = _e3;
    loop {
        let _e7 = level;
        if (_e7 < depth) {
            let _e11 = i_2;
            local_22 = (_e11 != BSH_NONE);
        } else {
            local_22 = false;
        }
        let _e15 = local_22;
        if _e15 {
        } else {
            break;
        }
        {
            let _e16 = i_2;
            let _e17 = bsh_node(nodes_3, _e16);
            let _e18 = level;
            let below = (depth - _e18);
            if (_e17.child == BSH_NONE) {
                if ((s_1 << (32u - below)) != 0u) {
                    return BSH_NONE;
                }
                let _e29 = i_2;
                return _e29;
            }
            if (((s_1 >> (below - 1u)) & 1u) == 0u) {
                i_2 = _e17.child;
            } else {
                let _e39 = bsh_node(nodes_3, _e17.child);
                i_2 = _e39.next;
            }
            let _e41 = level;
            level = (_e41 + 1u);
        }
    }
    let _e44 = i_2;
    return _e44;
}

fn bsh_next_leaf_box(nodes_4: u32, start_1: u32, end: u32, lo_1: vec3<f32>, hi_1: vec3<f32>, w_6: f32) -> u32 {
    var i_3: u32;

    i_3 = start_1;
    loop {
        let _e7 = i_3;
        if (_e7 != end) {
        } else {
            break;
        }
        {
            let _e9 = i_3;
            let _e10 = bsh_node(nodes_4, _e9);
            let _e11 = bsh_reaches_box(_e10, lo_1, hi_1, w_6);
            if _e11 {
                if (_e10.child == BSH_NONE) {
                    if ((_e10.light & BSH_TAIL) == 0u) {
                        let _e20 = i_3;
                        return _e20;
                    }
                    i_3 = _e10.next;
                } else {
                    i_3 = _e10.child;
                }
            } else {
                i_3 = _e10.next;
            }
        }
    }
    return end;
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

fn connect_record(l_4: GpuLight, x_6: vec3<f32>, n_8: vec3<f32>, ng_1: vec3<f32>, r2_3: f32, rt2_4: f32, w_res: f32, u1_2: f32, u2_2: f32, eps: f32, trace_1: bool) -> Connection {
    var c_6: Connection;
    var local_23: bool;
    var local_24: bool;

    c_6.e = vec3(0f);
    let _e16 = light_point(l_4, u1_2, u2_2);
    c_6.y = _e16;
    let _e19 = c_6.y;
    let _e20 = connection_cosine(x_6, _e19, n_8, ng_1, r2_3);
    c_6.cos_x = _e20;
    let _e22 = c_6.cos_x;
    if !((_e22 <= 0f)) {
        if trace_1 {
            let _e33 = c_6.y;
            let _e34 = occluded((x_6 + (ng_1 * eps)), _e33);
            local_24 = _e34;
        } else {
            local_24 = false;
        }
        let _e36 = local_24;
        local_23 = _e36;
    } else {
        local_23 = true;
    }
    let _e38 = local_23;
    if _e38 {
        let _e39 = c_6;
        return _e39;
    }
    let _e41 = c_6.y;
    let v_15 = (x_6 - _e41);
    let d2_10 = dot(v_15, v_15);
    let _e48 = light_intensity(l_4, (v_15 / vec3(sqrt(d2_10))));
    let _e50 = c_6.cos_x;
    let _e51 = connection_factor(_e50, d2_10, rt2_4, w_res);
    c_6.e = (_e48 * _e51);
    let _e53 = c_6;
    return _e53;
}

fn connect_traced(li: u32, x_7: vec3<f32>, n_9: vec3<f32>, ng_2: vec3<f32>, s_2: f32, w_res_1: f32, u1_3: f32, u2_3: f32, eps_1: f32, trace_2: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_4[li];
    let _e19 = rt2_5[li];
    let _e21 = connect_record(_e12, x_7, n_9, ng_2, (s_2 * _e15), (s_2 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_2);
    return _e21;
}

fn light_range_scale(li_1: u32, x_8: vec3<f32>, r_8: vec3<f32>, rl_4: vec4<f32>) -> f32 {
    let c_11 = light_cones[li_1];
    let _e9 = range_scale_toward(rl_4, c_11.center, c_11.radius, x_8, r_8);
    return _e9;
}

fn light_weight(li_2: u32, x_9: vec3<f32>, n_10: vec3<f32>, r_9: vec3<f32>, lobe_7: vec4<f32>, rl_5: vec4<f32>) -> f32 {
    let c_12 = light_cones[li_2];
    let _e15 = light_range_scale(li_2, x_9, r_9, rl_5);
    let _e18 = rt2_5[li_2];
    let _e20 = cone_weight(c_12.center, c_12.radius, c_12.phi, c_12.axis, c_12.cos_o, c_12.cos_e, (_e15 * _e18), x_9, n_10, r_9, lobe_7);
    return _e20;
}

fn weighted_picks(h_2: u32) -> WeightedPicks {
    var picks_1: WeightedPicks;

    picks_1.w_sum = 0f;
    picks_1.n = 0u;
    picks_1.h = h_2;
    let _e7 = picks_1;
    return _e7;
}

fn weighted_offer(picks_2: ptr<function, WeightedPicks>, li_3: u32, w_7: f32) {
    var h_3: u32;
    var s_3: u32 = 0u;

    let _e4 = (*picks_2).n;
    (*picks_2).n = (_e4 + 1u);
    if (w_7 > 0f) {
        let _e10 = (*picks_2).w_sum;
        (*picks_2).w_sum = (_e10 + w_7);
        let _e13 = (*picks_2).h;
        h_3 = _e13;
        loop {
            let _e17 = s_3;
            if (_e17 < K) {
            } else {
                break;
            }
            {
                let _e21 = (*picks_2).w_sum;
                let _e23 = s_3;
                let _e25 = (*picks_2).threshold[_e23];
                if (_e21 > _e25) {
                    let _e28 = s_3;
                    (*picks_2).light[_e28] = li_3;
                    let _e31 = s_3;
                    (*picks_2).w[_e31] = w_7;
                    let _e34 = s_3;
                    let _e37 = (*picks_2).w_sum;
                    let _e38 = next_threshold(_e37, (&h_3));
                    (*picks_2).threshold[_e34] = _e38;
                }
            }
            continuing {
                let _e40 = s_3;
                s_3 = (_e40 + 1u);
            }
        }
        let _e43 = h_3;
        (*picks_2).h = _e43;
        return;
    } else {
        return;
    }
}

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p_11 = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p_11.xyz, 1f), (p_11.w > 0f));
}

fn workgroup_bounds(li_4: u32, lo_2: vec3<f32>, hi_2: vec3<f32>) -> WorkgroupBox {
    var stride: u32 = 32u;

    wg_lo[li_4] = lo_2;
    wg_hi[li_4] = hi_2;
    workgroupBarrier();
    loop {
        let _e9 = stride;
        if (_e9 > 0u) {
        } else {
            break;
        }
        {
            let _e12 = stride;
            if (li_4 < _e12) {
                let _e18 = wg_lo[li_4];
                let _e20 = stride;
                let _e23 = wg_lo[(li_4 + _e20)];
                wg_lo[li_4] = min(_e18, _e23);
                let _e29 = wg_hi[li_4];
                let _e31 = stride;
                let _e34 = wg_hi[(li_4 + _e31)];
                wg_hi[li_4] = max(_e29, _e34);
            }
            workgroupBarrier();
        }
        continuing {
            let _e36 = stride;
            stride = (_e36 / 2u);
        }
    }
    if (li_4 == 0u) {
        let _e44 = wg_lo[0];
        let _e47 = wg_hi[0];
        wg_box = WorkgroupBox(_e44, _e47);
    }
    let _e50 = workgroupUniformLoad((&wg_box));
    return _e50;
}

fn point_box(p_7: vec3<f32>, has: bool) -> WorkgroupBox {
    return WorkgroupBox(select(vec3(340282350000000000000000000000000000000f), p_7, has), select(vec3(-340282350000000000000000000000000000000f), p_7, has));
}

fn workgroup_box(li_5: u32, p_8: vec3<f32>, has_1: bool) -> WorkgroupBox {
    let _e3 = point_box(p_8, has_1);
    let _e6 = workgroup_bounds(li_5, _e3.lo, _e3.hi);
    return _e6;
}

fn box_is_empty(b_6: WorkgroupBox) -> bool {
    return (b_6.lo.x > b_6.hi.x);
}

fn tile_subtree(s_4: u32, t_1: TileWalk, list: bool, at: u32, start_2: u32, to: u32) -> u32 {
    var p_9: u32;
    var b_7: u32;
    var local_25: bool;
    var local_26: bool;
    var local_27: bool;

    let _e8 = bsh_subtree(BSH, s_4, BSH_TILE_DEPTH);
    if (_e8 == BSH_NONE) {
        return 0u;
    }
    let end_1 = bsh_nodes[_e8].next;
    p_9 = at;
    let _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_1.lo, t_1.hi, t_1.w);
    b_7 = _e21;
    loop {
        let _e23 = b_7;
        if (_e23 != end_1) {
            if !(!(list)) {
                let _e31 = p_9;
                local_26 = (_e31 < to);
            } else {
                local_26 = true;
            }
            let _e34 = local_26;
            local_25 = _e34;
        } else {
            local_25 = false;
        }
        let _e36 = local_25;
        if _e36 {
        } else {
            break;
        }
        {
            if list {
                let _e39 = p_9;
                local_27 = (_e39 >= start_2);
            } else {
                local_27 = false;
            }
            let _e42 = local_27;
            if _e42 {
                let _e44 = p_9;
                let _e47 = b_7;
                tile_list[(_e44 - start_2)] = _e47;
            }
            let _e48 = p_9;
            p_9 = (_e48 + 1u);
        }
        continuing {
            let _e53 = b_7;
            let _e56 = bsh_nodes[_e53].next;
            let _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_1.lo, t_1.hi, t_1.w);
            b_7 = _e60;
        }
    }
    let _e61 = p_9;
    return (_e61 - at);
}

fn tile_walk_begin(li_6: u32, x_10: vec3<f32>, w_8: f32, has_2: bool) -> TileWalk {
    var local_28: bool;
    var t_2: TileWalk;
    var s_5: u32;
    var sum_1: u32 = 0u;
    var s_6: u32 = 0u;

    if has_2 {
        local_28 = (w_8 >= 0f);
    } else {
        local_28 = false;
    }
    let _e12 = local_28;
    let _e14 = atomicMax((&tile_scale), select(0u, bitcast<u32>(w_8), _e12));
    let _e15 = workgroup_box(li_6, x_10, has_2);
    let _e19 = workgroupUniformLoad((&tile_scale));
    t_2 = TileWalk(_e15.lo, _e15.hi, bitcast<f32>(_e19), 0u);
    let _e24 = box_is_empty(_e15);
    if _e24 {
        let _e25 = t_2;
        return _e25;
    }
    s_5 = li_6;
    loop {
        let _e27 = s_5;
        if (_e27 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            let _e31 = s_5;
            let _e33 = s_5;
            let _e34 = t_2;
            let _e39 = tile_subtree(_e33, _e34, false, 0u, 0u, 0u);
            subtree_at[_e31] = _e39;
        }
        continuing {
            let _e40 = s_5;
            s_5 = (_e40 + TILE_THREADS);
        }
    }
    workgroupBarrier();
    if (li_6 == 0u) {
        loop {
            let _e49 = s_6;
            if (_e49 < BSH_TILE_SUBTREES) {
            } else {
                break;
            }
            {
                let _e53 = s_6;
                let c_13 = subtree_at[_e53];
                let _e57 = s_6;
                let _e59 = sum_1;
                subtree_at[_e57] = _e59;
                let _e60 = sum_1;
                sum_1 = (_e60 + c_13);
            }
            continuing {
                let _e63 = s_6;
                s_6 = (_e63 + 1u);
            }
        }
        let _e66 = sum_1;
        tile_total = _e66;
    }
    let _e69 = workgroupUniformLoad((&tile_total));
    t_2.total = _e69;
    let _e70 = t_2;
    return _e70;
}

fn tile_walk_fill(li_7: u32, t_3: TileWalk, start_3: u32) -> u32 {
    var s_7: u32;
    var past: u32;
    var local_29: bool;

    let to_1 = min(t_3.total, (start_3 + TILE_LIST));
    s_7 = li_7;
    loop {
        let _e8 = s_7;
        if (_e8 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            let _e12 = s_7;
            let at_1 = subtree_at[_e12];
            past = t_3.total;
            let _e17 = s_7;
            if ((_e17 + 1u) < BSH_TILE_SUBTREES) {
                let _e23 = s_7;
                let _e27 = subtree_at[(_e23 + 1u)];
                past = _e27;
            }
            if (at_1 < to_1) {
                let _e31 = past;
                local_29 = (_e31 > start_3);
            } else {
                local_29 = false;
            }
            let _e34 = local_29;
            if _e34 {
                let _e35 = s_7;
                let _e37 = tile_subtree(_e35, t_3, true, at_1, start_3, to_1);
            }
        }
        continuing {
            let _e38 = s_7;
            s_7 = (_e38 + TILE_THREADS);
        }
    }
    workgroupBarrier();
    return (to_1 - start_3);
}

fn shade_connection(c_7: Connection, x_11: vec3<f32>, n_11: vec3<f32>, m_1: Material) -> Shaded {
    var s_8: Shaded;

    s_8.e = c_7.e;
    s_8.diffuse = vec3(0f);
    s_8.specular = vec3(0f);
    if (c_7.cos_x > 0f) {
        let l_5 = normalize((c_7.y - x_11));
        let _e24 = view.f0_d;
        let _e27 = view.f90_d;
        let _e29 = half_cosine(m_1.v, l_5);
        let _e30 = diffuse_brdf(m_1.base, m_1.metallic, _e24, _e27, _e29);
        s_8.diffuse = (_e30 * c_7.e);
        let _e38 = view.f0_d;
        let _e41 = view.f90_d;
        let _e44 = specular_brdf(m_1.base, m_1.metallic, _e38, _e41, m_1.alpha, n_11, m_1.v, l_5);
        s_8.specular = (_e44 * c_7.e);
    }
    let _e47 = s_8;
    return _e47;
}

fn shade_pick_traced(li_8: u32, x_12: vec3<f32>, n_12: vec3<f32>, r_10: vec3<f32>, rl_6: vec4<f32>, m_2: Material, w_9: f32, u1_4: f32, u2_4: f32, eps_2: f32, trace_3: bool) -> Shaded {
    let _e11 = light_range_scale(li_8, x_12, r_10, rl_6);
    let _e12 = connect_traced(li_8, x_12, n_12, n_12, _e11, w_9, u1_4, u2_4, eps_2, trace_3);
    let _e13 = shade_connection(_e12, x_12, n_12, m_2);
    return _e13;
}

fn shade_pick(li_9: u32, x_13: vec3<f32>, n_13: vec3<f32>, r_11: vec3<f32>, rl_7: vec4<f32>, m_3: Material, w_10: f32, u1_5: f32, u2_5: f32, eps_3: f32) -> Shaded {
    let _e11 = shade_pick_traced(li_9, x_13, n_13, r_11, rl_7, m_3, w_10, u1_5, u2_5, eps_3, true);
    return _e11;
}

fn material_of(base_4: vec3<f32>, metallic_5: f32, roughness_1: f32, reflectance: f32, v_5: vec3<f32>) -> Material {
    let _e7 = ggx_alpha(saturate(roughness_1));
    return Material(base_4, saturate(metallic_5), _e7, v_5, roughness_1, 0f);
}

fn add(a_8: Shaded, b_8: Shaded) -> Shaded {
    return Shaded((a_8.e + b_8.e), (a_8.diffuse + b_8.diffuse), (a_8.specular + b_8.specular));
}

fn first_holders(keys_1: array<vec2<u32>, 8>, held_1: array<bool, 8>) -> array<u32, 8> {
    var first: array<u32, 8>;
    var k_3: u32 = 0u;
    var j_2: u32;
    var local_30: bool;
    var local_31: bool;

    loop {
        let _e5 = k_3;
        if (_e5 < K) {
        } else {
            break;
        }
        {
            let _e8 = k_3;
            let _e11 = k_3;
            let _e12 = k_3;
            first[_e8] = select(K, _e11, held_1[_e12]);
            j_2 = 0u;
            loop {
                let _e17 = j_2;
                let _e18 = k_3;
                if (_e17 < _e18) {
                    let _e22 = k_3;
                    local_30 = held_1[_e22];
                } else {
                    local_30 = false;
                }
                let _e25 = local_30;
                if _e25 {
                } else {
                    break;
                }
                {
                    let _e26 = j_2;
                    if held_1[_e26] {
                        let _e30 = j_2;
                        let _e32 = k_3;
                        local_31 = all((keys_1[_e30] == keys_1[_e32]));
                    } else {
                        local_31 = false;
                    }
                    let _e37 = local_31;
                    if _e37 {
                        let _e38 = k_3;
                        let _e40 = j_2;
                        first[_e38] = _e40;
                        break;
                    }
                }
                continuing {
                    let _e42 = j_2;
                    j_2 = (_e42 + 1u);
                }
            }
        }
        continuing {
            let _e45 = k_3;
            k_3 = (_e45 + 1u);
        }
    }
    let _e47 = first;
    return _e47;
}

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
    var local: bool;
    var s: vec4<f32> = vec4(0f);
    var nn: vec3<f32> = vec3(0f);
    var local_1: bool;
    var local_2: bool;
    var local_3: bool;
    var n: vec3<f32> = vec3<f32>(0f, 0f, 1f);
    var m: Material;
    var lobe: vec4<f32> = vec4<f32>(1f, 0f, 1f, 1f);
    var r: vec3<f32>;
    var h: u32;
    var t: Shaded = Shaded(vec3(0f), vec3(0f), vec3(0f));
    var picks: WeightedPicks;
    var start: u32 = 0u;
    var j: u32;
    var local_4: bool;
    var keys: array<vec2<u32>, 8>;
    var held: array<bool, 8>;
    var k: u32 = 0u;
    var k_1: u32 = 0u;
    var copies: u32;
    var j_1: u32;

    let _e5 = view.width;
    if (gid.x < _e5) {
        let _e12 = view.height;
        local = (gid.y < _e12);
    } else {
        local = false;
    }
    let inside = local;
    let texel_1 = vec2<i32>(i32(gid.x), i32(gid.y));
    if inside {
        let _e27 = surface_at(texel_1);
        s = _e27;
        let _e30 = textureLoad(normal_tex, texel_1, 0i);
        nn = _e30.xyz;
    }
    let _e32 = nn;
    let _e33 = nn;
    let len2_1 = dot(_e32, _e33);
    let _e35 = s;
    let x_14 = _e35.xyz;
    if inside {
        let _e40 = s.w;
        local_1 = (_e40 > 0f);
    } else {
        local_1 = false;
    }
    let _e44 = local_1;
    if _e44 {
        local_2 = (len2_1 > 0f);
    } else {
        local_2 = false;
    }
    let _e50 = local_2;
    if _e50 {
        local_3 = all((abs(x_14) <= vec3(340282350000000000000000000000000000000f)));
    } else {
        local_3 = false;
    }
    let has_3 = local_3;
    if has_3 {
        let _e65 = nn;
        n = (_e65 / vec3(sqrt(len2_1)));
    }
    let _e76 = n;
    r = _e76;
    if has_3 {
        let mr = textureLoad(metal_rough_tex, texel_1, 0i);
        let _e83 = textureLoad(base_color_tex, texel_1, 0i);
        let _e90 = view.eye;
        let _e93 = material_of(_e83.xyz, mr.z, mr.y, mr.w, normalize((_e90 - x_14)));
        m = _e93;
        let _e95 = m.base;
        let _e97 = m.metallic;
        let _e100 = view.f0_d;
        let _e103 = view.f90_d;
        let _e105 = m.alpha;
        let _e106 = n;
        let _e108 = m.v;
        let _e110 = receiver_lobe(_e95, _e97, _e100, _e103, _e105, dot(_e106, _e108));
        lobe = _e110;
        let _e111 = n;
        let _e113 = m.v;
        let _e114 = mirror_dir(_e111, _e113);
        r = _e114;
    }
    let _e115 = lobe;
    let _e116 = range_lobe(_e115);
    let _e119 = view.shadow_offset;
    let _e122 = view.eye;
    let eps_4 = (_e119 * length((_e122 - x_14)));
    let _e128 = view.seed;
    let _e132 = view.width;
    let _e138 = view.frame;
    let _e139 = point_stream(_e128, ((gid.y * _e132) + gid.x), _e138);
    let _e140 = pick_stream(_e139);
    h = _e140;
    let _e150 = weighted_picks(_e139);
    picks = _e150;
    let _e153 = tile_walk_begin(lid, x_14, _e116.w, has_3);
    loop {
        let _e156 = start;
        if (_e156 < _e153.total) {
        } else {
            break;
        }
        {
            let _e159 = start;
            let _e160 = tile_walk_fill(lid, _e153, _e159);
            j = 0u;
            loop {
                let _e163 = j;
                if (_e163 < _e160) {
                } else {
                    break;
                }
                {
                    let _e166 = j;
                    let b_9 = tile_list[_e166];
                    if !(!(has_3)) {
                        let _e175 = bsh_nodes[b_9];
                        let _e176 = r;
                        let _e177 = bsh_reaches(_e175, x_14, _e176, _e116);
                        local_4 = !(_e177);
                    } else {
                        local_4 = true;
                    }
                    let _e180 = local_4;
                    if _e180 {
                        continue;
                    }
                    let li_10 = bsh_nodes[b_9].light;
                    let _e185 = n;
                    let _e186 = r;
                    let _e187 = lobe;
                    let _e188 = light_weight(li_10, x_14, _e185, _e186, _e187, _e116);
                    weighted_offer((&picks), li_10, _e188);
                }
                continuing {
                    let _e190 = j;
                    j = (_e190 + 1u);
                }
            }
            workgroupBarrier();
        }
        continuing {
            let _e192 = start;
            start = (_e192 + TILE_LIST);
        }
    }
    if !(has_3) {
        if inside {
            textureStore(out_tex, texel_1, vec4(0f));
            textureStore(specular_tex, texel_1, vec4(0f));
        }
        return;
    }
    let _e203 = picks.w_sum;
    if (_e203 > 0f) {
        loop {
            let _e210 = k;
            if (_e210 < K) {
            } else {
                break;
            }
            {
                let _e214 = k;
                let _e219 = k;
                let _e221 = picks.light[_e219];
                let _e224 = lights[_e221].kind;
                let own = select(0u, (_e214 + 1u), (_e224 == LIGHT_TRIANGLE));
                let _e228 = k;
                let _e231 = k;
                let _e233 = picks.light[_e231];
                keys[_e228] = vec2<u32>(_e233, own);
                let _e235 = k;
                held[_e235] = true;
            }
            continuing {
                let _e239 = k;
                k = (_e239 + 1u);
            }
        }
        let _e241 = keys;
        let _e242 = held;
        let _e243 = first_holders(_e241, _e242);
        loop {
            let _e246 = k_1;
            if (_e246 < K) {
            } else {
                break;
            }
            {
                let _e249 = h;
                let _e250 = pcg_hash(_e249);
                h = _e250;
                let _e251 = h;
                let _e252 = xi_from_bits(_e251);
                let _e253 = h;
                let _e254 = pcg_hash(_e253);
                h = _e254;
                let _e255 = h;
                let _e256 = xi_from_bits(_e255);
                let _e258 = k_1;
                let li_11 = picks.light[_e258];
                copies = 0u;
                let _e263 = k_1;
                j_1 = _e263;
                loop {
                    let _e265 = j_1;
                    if (_e265 < K) {
                    } else {
                        break;
                    }
                    {
                        let _e268 = copies;
                        let _e271 = j_1;
                        let _e273 = k_1;
                        copies = (_e268 + select(0u, 1u, (_e243[_e271] == _e273)));
                    }
                    continuing {
                        let _e278 = j_1;
                        j_1 = (_e278 + 1u);
                    }
                }
                let _e280 = copies;
                if (_e280 > 0u) {
                    let _e283 = t;
                    let _e284 = n;
                    let _e285 = r;
                    let _e286 = m;
                    let _e288 = picks.w_sum;
                    let _e290 = k_1;
                    let _e292 = picks.w[_e290];
                    let _e294 = weighted_pick_weight(_e288, _e292, K);
                    let _e295 = copies;
                    let _e298 = shade_pick(li_11, x_14, _e284, _e285, _e116, _e286, (_e294 * f32(_e295)), _e252, _e256, eps_4);
                    let _e299 = add(_e283, _e298);
                    t = _e299;
                }
            }
            continuing {
                let _e301 = k_1;
                k_1 = (_e301 + 1u);
            }
        }
    }
    let count = picks.n;
    let _e307 = t.e;
    textureStore(out_tex, texel_1, vec4<f32>(_e307, f32(count)));
    let _e312 = t.specular;
    textureStore(specular_tex, texel_1, vec4<f32>(_e312, 0f));
    return;
}
