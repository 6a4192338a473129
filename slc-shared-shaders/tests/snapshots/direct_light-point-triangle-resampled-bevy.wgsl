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
    let v_5 = (x_1 - c);
    return (dot(v_5, v_5) <= (r_1 * r_1));
}

fn sphere_overlaps_aabb(c_1: vec3<f32>, r_2: f32, bmin: vec3<f32>, bmax: vec3<f32>) -> bool {
    let q_1 = clamp(c_1, bmin, bmax);
    let v_6 = (q_1 - c_1);
    return (dot(v_6, v_6) <= (r_2 * r_2));
}

fn inverse_square(d2_2: f32) -> f32 {
    return (1f / max(d2_2, MIN_D2_));
}

fn connection_factor(cos_x: f32, d2_3: f32, rt2_1: f32, w_1: f32) -> f32 {
    let _e4 = inverse_square(d2_3);
    let _e6 = slc_weight(rt2_1, d2_3);
    return (((cos_x * _e4) * _e6) * w_1);
}

fn connection_cosine(x_2: vec3<f32>, y: vec3<f32>, n_1: vec3<f32>, ng: vec3<f32>, r2_1: f32) -> f32 {
    var local_7: bool;
    var local_8: bool;

    let v_7 = (x_2 - y);
    let d2_6 = dot(v_7, v_7);
    let _e7 = slc_keep(r2_1, d2_6);
    if !(!(_e7)) {
        local_7 = !((d2_6 > 0f));
    } else {
        local_7 = true;
    }
    let _e16 = local_7;
    if _e16 {
        return 0f;
    }
    let w_11 = (v_7 / vec3(sqrt(d2_6)));
    let cos_x_1 = -(dot(n_1, w_11));
    if !(!((cos_x_1 > 0f))) {
        local_8 = !((dot(ng, w_11) < 0f));
    } else {
        local_8 = true;
    }
    let _e34 = local_8;
    if _e34 {
        return 0f;
    }
    return cos_x_1;
}

fn triangle_lobe(n_2: vec3<f32>, area: f32, w_2: vec3<f32>) -> f32 {
    return (area * max(dot(n_2, w_2), 0f));
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

fn bsh_reach_bound(node_2: BshNode, w_3: f32) -> f32 {
    let _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_3 * 1.001f) * _e5));
}

fn weighted_threshold(w_sum: f32, u_2: f32) -> f32 {
    return (w_sum / (1f - u_2));
}

fn resample_target(c_3: vec3<f32>) -> f32 {
    return (((c_3.x + c_3.y) + c_3.z) * 0.33333334f);
}

fn slot_target(c_4: vec3<f32>, slot: u32, k_2: u32) -> f32 {
    if (k_2 < 3u) {
        let _e5 = resample_target(c_4);
        return _e5;
    }
    let j_3 = (slot % 3u);
    if (j_3 == 0u) {
        return c_4.x;
    }
    if (j_3 == 1u) {
        return c_4.y;
    }
    return c_4.z;
}

fn slot_share(slot_1: u32, k_3: u32) -> vec3<f32> {
    if (k_3 < 3u) {
        let _e4 = to_f32_(k_3);
        let w_12 = (1f / _e4);
        return vec3<f32>(w_12, w_12, w_12);
    }
    let j_4 = (slot_1 % 3u);
    let _e15 = to_f32_((((k_3 + 2u) - j_4) / 3u));
    let w_13 = (1f / _e15);
    if (j_4 == 0u) {
        return vec3<f32>(w_13, 0f, 0f);
    }
    if (j_4 == 1u) {
        return vec3<f32>(0f, w_13, 0f);
    }
    return vec3<f32>(0f, 0f, w_13);
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
    var local_9: bool;

    if !((n_l <= 0f)) {
        local_9 = (n_v <= 0f);
    } else {
        local_9 = true;
    }
    let _e11 = local_9;
    if _e11 {
        return 0f;
    }
    let _e13 = smith_root(n_v, alpha_2);
    let _e15 = smith_root(n_l, alpha_2);
    return (0.5f / ((n_l * _e13) + (n_v * _e15)));
}

fn fresnel_schlick(f0_: vec3<f32>, f90_: f32, v_h: f32) -> vec3<f32> {
    let c_10 = saturate((1f - v_h));
    let c2_ = (c_10 * c_10);
    return (f0_ + ((vec3<f32>(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_10)));
}

fn specular_fresnel(base: vec3<f32>, metallic: f32, f0_d: vec3<f32>, f90_d: f32, v_h_1: f32) -> vec3<f32> {
    let _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    let _e10 = fresnel_schlick(base, 1f, v_h_1);
    return ((_e5 * (1f - metallic)) + (_e10 * metallic));
}

fn has_specular(metallic_1: f32, f0_d_1: vec3<f32>, f90_d_1: f32) -> bool {
    var local_10: bool;
    var local_11: bool;

    if !((metallic_1 > 0f)) {
        local_10 = (f90_d_1 > 0f);
    } else {
        local_10 = true;
    }
    let _e11 = local_10;
    if !(_e11) {
        local_11 = (max(max(f0_d_1.x, f0_d_1.y), f0_d_1.z) > 0f);
    } else {
        local_11 = true;
    }
    let _e23 = local_11;
    return _e23;
}

fn channel_mean(c_5: vec3<f32>) -> f32 {
    return (((c_5.x + c_5.y) + c_5.z) * 0.33333334f);
}

fn receiver_lobe(base_1: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n_v_1: f32) -> vec4<f32> {
    var local_12: bool;

    let _e10 = fresnel_schlick(f0_d_2, f90_d_2, n_v_1);
    let _e16 = channel_mean((((vec3<f32>(1f, 1f, 1f) - _e10) * base_1) * (1f - metallic_2)));
    if !((n_v_1 <= 0f)) {
        let _e22 = has_specular(metallic_2, f0_d_2, f90_d_2);
        local_12 = !(_e22);
    } else {
        local_12 = true;
    }
    let _e25 = local_12;
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

fn mirror_dir(n_3: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    return ((n_3 * (2f * dot(n_3, v))) - v);
}

fn bevy_alpha(perceptual: f32) -> f32 {
    let r_11 = clamp(perceptual, 0.089f, 1f);
    return (r_11 * r_11);
}

fn bevy_f0_(reflectance: f32) -> f32 {
    return ((0.16f * reflectance) * reflectance);
}

fn bevy_dfg(r_3: f32, n_v_2: f32) -> f32 {
    let rx = (1f - r_3);
    let a004_ = ((min((rx * rx), exp2((-9.28f * n_v_2))) * rx) + (0.0425f - (0.0275f * r_3)));
    let x_12 = max(((1.04f - (0.572f * r_3)) - (1.04f * a004_)), 0.00005f);
    let y_1 = max((((0.022f * r_3) - 0.04f) + (1.04f * a004_)), 0.00005f);
    return (x_12 + y_1);
}

fn bevy_brdf(base_2: vec3<f32>, metallic_3: f32, r_4: f32, reflectance_1: f32, n_4: vec3<f32>, v_1: vec3<f32>, l: vec3<f32>) -> vec3<f32> {
    let n_l_1 = saturate(dot(n_4, l));
    if (n_l_1 <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = bevy_alpha(r_4);
    let n_v_3 = max(dot(n_4, v_1), 0.0001f);
    let h_2 = normalize((l + v_1));
    let n_h = saturate(dot(n_4, h_2));
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
    let _e70 = bevy_dfg(r_4, n_v_3);
    let comp = (vec3<f32>(1f, 1f, 1f) + (f0_1 * ((1f / _e70) - 1f)));
    let _e77 = fresnel_schlick(f0_1, f90_1, l_h);
    let spec = ((_e77 * comp) * (_e64 * _e65));
    return ((base_2 * ((1f - metallic_3) * burley)) + spec);
}

fn cone_cos_of(v_2: vec3<f32>, d2_4: f32, a_3: f32, d: vec3<f32>) -> f32 {
    var local_13: bool;
    var local_14: bool;

    let vd = dot(v_2, d);
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
    let c_11 = cross(v_2, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_11, c_11)) * a_3)) / d2_4), 1f);
}

fn cone_cos_toward(center: vec3<f32>, radius: f32, p: vec3<f32>, d_1: vec3<f32>) -> f32 {
    let v_8 = (center - p);
    let _e6 = cone_cos_of(v_8, dot(v_8, v_8), radius, d_1);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_5 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_5 * t_5))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_1: vec3<f32>, radius_1: f32, p_1: vec3<f32>, r_5: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_1, radius_1, p_1, r_5);
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

fn triangle_normal(a_4: vec3<f32>, b_3: vec3<f32>, c_6: vec3<f32>) -> vec3<f32> {
    var local_15: bool;

    let n_10 = cross((b_3 - a_4), (c_6 - a_4));
    let l2_ = dot(n_10, n_10);
    if !(!((l2_ > 0f))) {
        local_15 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_15 = true;
    }
    let _e17 = local_15;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_10 / vec3(sqrt(l2_)));
}

fn ray_triangle(o_1: vec3<f32>, d_3: vec3<f32>, a_5: vec3<f32>, b_4: vec3<f32>, c_7: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_16: bool;
    var local_17: bool;
    var local_18: bool;

    let e1_ = (b_4 - a_5);
    let e2_ = (c_7 - a_5);
    let p_5 = cross(d_3, e2_);
    let det = dot(e1_, p_5);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv = (1f / det);
    let s_10 = (o_1 - a_5);
    let u_3 = (dot(s_10, p_5) * inv);
    if !((u_3 < 0f)) {
        local_16 = (u_3 > 1f);
    } else {
        local_16 = true;
    }
    let _e28 = local_16;
    if _e28 {
        return -1f;
    }
    let q_2 = cross(s_10, e1_);
    let v_9 = (dot(d_3, q_2) * inv);
    if !((v_9 < 0f)) {
        local_17 = ((u_3 + v_9) > 1f);
    } else {
        local_17 = true;
    }
    let _e42 = local_17;
    if _e42 {
        return -1f;
    }
    let t_6 = (dot(e2_, q_2) * inv);
    if (t_6 > t_min) {
        local_18 = (t_6 < t_max_1);
    } else {
        local_18 = false;
    }
    let _e51 = local_18;
    if _e51 {
        return t_6;
    }
    return -1f;
}

fn light_intensity(l_1: GpuLight, w_4: vec3<f32>) -> vec3<f32> {
    switch l_1.kind {
        case 0u: {
            return l_1.intensity;
        }
        case 3u: {
            let _e8 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
            let _e10 = triangle_lobe(_e8, l_1.a, w_4);
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
        let n_11 = geo_nodes[_e21];
        let _e27 = hit.t;
        let _e28 = ray_aabb(o_2, _e14, n_11.bmin, n_11.bmax, _e27);
        if (_e28 >= 0f) {
            if (n_11.count > 0u) {
                i = n_11.first;
                loop {
                    let _e36 = i;
                    if (_e36 < (n_11.first + n_11.count)) {
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
                    stack[_e63] = (n_11.first + 1u);
                    let _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_11.first;
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

fn bsh_inner_scale(a_7: f32, v_3: vec3<f32>, d2_5: f32, r_6: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let _e5 = cone_cos_of(v_3, d2_5, a_7, r_6);
    let _e8 = range_scale_at(rl_2, (_e5 + 0.000002f));
    return _e8;
}

fn bsh_reaches(node_4: BshNode, x_4: vec3<f32>, r_7: vec3<f32>, rl_3: vec4<f32>) -> bool {
    var local_19: bool;
    var local_20: bool;

    let _e6 = sphere_contains_point(node_4.center, node_4.radius, x_4);
    if _e6 {
        return true;
    }
    if !((rl_3.w <= 1f)) {
        let _e20 = sphere_contains_point(node_4.center, (node_4.radius * (rl_3.w * 1.0001f)), x_4);
        local_19 = !(_e20);
    } else {
        local_19 = true;
    }
    let _e23 = local_19;
    if _e23 {
        return false;
    }
    let v_10 = (x_4 - node_4.center);
    let d2_7 = dot(v_10, v_10);
    let _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_7 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        let _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_4, r_7);
        let _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        let _e42 = sphere_contains_point(node_4.center, _e41, x_4);
        return _e42;
    }
    let _e45 = bsh_inner_scale(node_4.extent, -(v_10), d2_7, r_7, rl_3);
    let s_c = (_e45 * 1.001f);
    let _e50 = bsh_range_bound(node_4);
    let reach = (node_4.extent + (sqrt(s_c) * _e50));
    if (d2_7 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_20 = (d2_7 <= (reach * reach));
    } else {
        local_20 = false;
    }
    let _e63 = local_20;
    return _e63;
}

fn bsh_reaches_box(node_5: BshNode, lo: vec3<f32>, hi: vec3<f32>, w_5: f32) -> bool {
    let _e13 = sphere_overlaps_aabb(node_5.center, (node_5.radius * (max(1f, (w_5 * 1.0001f)) * 1.0001f)), lo, hi);
    return _e13;
}

fn bsh_subtree(nodes_3: u32, s_1: u32, depth: u32) -> u32 {
    var i_2: u32;
    var level: u32 = 0u;
    var local_21: bool;

    let _e3 = bsh_first(nodes_3);
    i_2 = _e3;
    loop {
        let _e7 = level;
        if (_e7 < depth) {
            let _e11 = i_2;
            local_21 = (_e11 != BSH_NONE);
        } else {
            local_21 = false;
        }
        let _e15 = local_21;
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

fn connect_record(l_3: GpuLight, x_5: vec3<f32>, n_5: vec3<f32>, ng_1: vec3<f32>, r2_2: f32, rt2_2: f32, w_res: f32, u1_2: f32, u2_2: f32, eps: f32, trace_1: bool) -> Connection {
    var c_8: Connection;
    var local_22: bool;
    var local_23: bool;

    c_8.e = vec3(0f);
    let _e16 = light_point(l_3, u1_2, u2_2);
    c_8.y = _e16;
    let _e19 = c_8.y;
    let _e20 = connection_cosine(x_5, _e19, n_5, ng_1, r2_2);
    c_8.cos_x = _e20;
    let _e22 = c_8.cos_x;
    if !((_e22 <= 0f)) {
        if trace_1 {
            let _e33 = c_8.y;
            let _e34 = occluded((x_5 + (ng_1 * eps)), _e33);
            local_23 = _e34;
        } else {
            local_23 = false;
        }
        let _e36 = local_23;
        local_22 = _e36;
    } else {
        local_22 = true;
    }
    let _e38 = local_22;
    if _e38 {
        let _e39 = c_8;
        return _e39;
    }
    let _e41 = c_8.y;
    let v_11 = (x_5 - _e41);
    let d2_8 = dot(v_11, v_11);
    let _e48 = light_intensity(l_3, (v_11 / vec3(sqrt(d2_8))));
    let _e50 = c_8.cos_x;
    let _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_8.e = (_e48 * _e51);
    let _e53 = c_8;
    return _e53;
}

fn connect_traced(li: u32, x_6: vec3<f32>, n_6: vec3<f32>, ng_2: vec3<f32>, s_2: f32, w_res_1: f32, u1_3: f32, u2_3: f32, eps_1: f32, trace_2: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_3[li];
    let _e19 = rt2_3[li];
    let _e21 = connect_record(_e12, x_6, n_6, ng_2, (s_2 * _e15), (s_2 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_2);
    return _e21;
}

fn light_range_scale(li_1: u32, x_7: vec3<f32>, r_8: vec3<f32>, rl_4: vec4<f32>) -> f32 {
    let c_12 = light_cones[li_1];
    let _e9 = range_scale_toward(rl_4, c_12.center, c_12.radius, x_7, r_8);
    return _e9;
}

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p_6 = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p_6.xyz, 1f), (p_6.w > 0f));
}

fn workgroup_bounds(li_2: u32, lo_2: vec3<f32>, hi_2: vec3<f32>) -> WorkgroupBox {
    var stride: u32 = 32u;

    wg_lo[li_2] = lo_2;
    wg_hi[li_2] = hi_2;
    workgroupBarrier();
    loop {
        let _e9 = stride;
        if (_e9 > 0u) {
        } else {
            break;
        }
        {
            let _e12 = stride;
            if (li_2 < _e12) {
                let _e18 = wg_lo[li_2];
                let _e20 = stride;
                let _e23 = wg_lo[(li_2 + _e20)];
                wg_lo[li_2] = min(_e18, _e23);
                let _e29 = wg_hi[li_2];
                let _e31 = stride;
                let _e34 = wg_hi[(li_2 + _e31)];
                wg_hi[li_2] = max(_e29, _e34);
            }
            workgroupBarrier();
        }
        continuing {
            let _e36 = stride;
            stride = (_e36 / 2u);
        }
    }
    if (li_2 == 0u) {
        let _e44 = wg_lo[0];
        let _e47 = wg_hi[0];
        wg_box = WorkgroupBox(_e44, _e47);
    }
    let _e50 = workgroupUniformLoad((&wg_box));
    return _e50;
}

fn point_box(p_2: vec3<f32>, has: bool) -> WorkgroupBox {
    return WorkgroupBox(select(vec3(340282350000000000000000000000000000000f), p_2, has), select(vec3(-340282350000000000000000000000000000000f), p_2, has));
}

fn workgroup_box(li_3: u32, p_3: vec3<f32>, has_1: bool) -> WorkgroupBox {
    let _e3 = point_box(p_3, has_1);
    let _e6 = workgroup_bounds(li_3, _e3.lo, _e3.hi);
    return _e6;
}

fn box_is_empty(b_6: WorkgroupBox) -> bool {
    return (b_6.lo.x > b_6.hi.x);
}

fn tile_subtree(s_3: u32, t_1: TileWalk, list: bool, at: u32, start_2: u32, to: u32) -> u32 {
    var p_4: u32;
    var b_7: u32;
    var local_24: bool;
    var local_25: bool;
    var local_26: bool;

    let _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH);
    if (_e8 == BSH_NONE) {
        return 0u;
    }
    let end_1 = bsh_nodes[_e8].next;
    p_4 = at;
    let _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_1.lo, t_1.hi, t_1.w);
    b_7 = _e21;
    loop {
        let _e23 = b_7;
        if (_e23 != end_1) {
            if !(!(list)) {
                let _e31 = p_4;
                local_25 = (_e31 < to);
            } else {
                local_25 = true;
            }
            let _e34 = local_25;
            local_24 = _e34;
        } else {
            local_24 = false;
        }
        let _e36 = local_24;
        if _e36 {
        } else {
            break;
        }
        {
            if list {
                let _e39 = p_4;
                local_26 = (_e39 >= start_2);
            } else {
                local_26 = false;
            }
            let _e42 = local_26;
            if _e42 {
                let _e44 = p_4;
                let _e47 = b_7;
                tile_list[(_e44 - start_2)] = _e47;
            }
            let _e48 = p_4;
            p_4 = (_e48 + 1u);
        }
        continuing {
            let _e53 = b_7;
            let _e56 = bsh_nodes[_e53].next;
            let _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_1.lo, t_1.hi, t_1.w);
            b_7 = _e60;
        }
    }
    let _e61 = p_4;
    return (_e61 - at);
}

fn tile_walk_begin(li_4: u32, x_8: vec3<f32>, w_7: f32, has_2: bool) -> TileWalk {
    var local_27: bool;
    var t_2: TileWalk;
    var s_4: u32;
    var sum_1: u32 = 0u;
    var s_5: u32 = 0u;

    if has_2 {
        local_27 = (w_7 >= 0f);
    } else {
        local_27 = false;
    }
    let _e12 = local_27;
    let _e14 = atomicMax((&tile_scale), select(0u, bitcast<u32>(w_7), _e12));
    let _e15 = workgroup_box(li_4, x_8, has_2);
    let _e19 = workgroupUniformLoad((&tile_scale));
    t_2 = TileWalk(_e15.lo, _e15.hi, bitcast<f32>(_e19), 0u);
    let _e24 = box_is_empty(_e15);
    if _e24 {
        let _e25 = t_2;
        return _e25;
    }
    s_4 = li_4;
    loop {
        let _e27 = s_4;
        if (_e27 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            let _e31 = s_4;
            let _e33 = s_4;
            let _e34 = t_2;
            let _e39 = tile_subtree(_e33, _e34, false, 0u, 0u, 0u);
            subtree_at[_e31] = _e39;
        }
        continuing {
            let _e40 = s_4;
            s_4 = (_e40 + TILE_THREADS);
        }
    }
    workgroupBarrier();
    if (li_4 == 0u) {
        loop {
            let _e49 = s_5;
            if (_e49 < BSH_TILE_SUBTREES) {
            } else {
                break;
            }
            {
                let _e53 = s_5;
                let c_13 = subtree_at[_e53];
                let _e57 = s_5;
                let _e59 = sum_1;
                subtree_at[_e57] = _e59;
                let _e60 = sum_1;
                sum_1 = (_e60 + c_13);
            }
            continuing {
                let _e63 = s_5;
                s_5 = (_e63 + 1u);
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

fn tile_walk_fill(li_5: u32, t_3: TileWalk, start_3: u32) -> u32 {
    var s_6: u32;
    var past: u32;
    var local_28: bool;

    let to_1 = min(t_3.total, (start_3 + TILE_LIST));
    s_6 = li_5;
    loop {
        let _e8 = s_6;
        if (_e8 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            let _e12 = s_6;
            let at_1 = subtree_at[_e12];
            past = t_3.total;
            let _e17 = s_6;
            if ((_e17 + 1u) < BSH_TILE_SUBTREES) {
                let _e23 = s_6;
                let _e27 = subtree_at[(_e23 + 1u)];
                past = _e27;
            }
            if (at_1 < to_1) {
                let _e31 = past;
                local_28 = (_e31 > start_3);
            } else {
                local_28 = false;
            }
            let _e34 = local_28;
            if _e34 {
                let _e35 = s_6;
                let _e37 = tile_subtree(_e35, t_3, true, at_1, start_3, to_1);
            }
        }
        continuing {
            let _e38 = s_6;
            s_6 = (_e38 + TILE_THREADS);
        }
    }
    workgroupBarrier();
    return (to_1 - start_3);
}

fn shade_connection(c_9: Connection, x_9: vec3<f32>, n_7: vec3<f32>, m_1: Material) -> Shaded {
    var s_7: Shaded;

    s_7.e = c_9.e;
    s_7.diffuse = vec3(0f);
    s_7.specular = vec3(0f);
    if (c_9.cos_x > 0f) {
        let _e25 = bevy_brdf(m_1.base, m_1.metallic, m_1.roughness, m_1.reflectance, n_7, m_1.v, normalize((c_9.y - x_9)));
        s_7.diffuse = (_e25 * c_9.e);
    }
    let _e28 = s_7;
    return _e28;
}

fn shade_pick_traced(li_6: u32, x_10: vec3<f32>, n_8: vec3<f32>, r_9: vec3<f32>, rl_5: vec4<f32>, m_2: Material, w_8: f32, u1_4: f32, u2_4: f32, eps_2: f32, trace_3: bool) -> Shaded {
    let _e11 = light_range_scale(li_6, x_10, r_9, rl_5);
    let _e12 = connect_traced(li_6, x_10, n_8, n_8, _e11, w_8, u1_4, u2_4, eps_2, trace_3);
    let _e13 = shade_connection(_e12, x_10, n_8, m_2);
    return _e13;
}

fn shade_pick(li_7: u32, x_11: vec3<f32>, n_9: vec3<f32>, r_10: vec3<f32>, rl_6: vec4<f32>, m_3: Material, w_9: f32, u1_5: f32, u2_5: f32, eps_3: f32) -> Shaded {
    let _e11 = shade_pick_traced(li_7, x_11, n_9, r_10, rl_6, m_3, w_9, u1_5, u2_5, eps_3, true);
    return _e11;
}

fn material_of(base_3: vec3<f32>, metallic_4: f32, roughness: f32, reflectance_2: f32, v_4: vec3<f32>) -> Material {
    let _e6 = bevy_alpha(roughness);
    return Material(base_3, saturate(metallic_4), _e6, v_4, roughness, reflectance_2);
}

fn add(a_8: Shaded, b_8: Shaded) -> Shaded {
    return Shaded((a_8.e + b_8.e), (a_8.diffuse + b_8.diffuse), (a_8.specular + b_8.specular));
}

fn scaled(s_8: Shaded, w_10: vec3<f32>) -> Shaded {
    return Shaded((s_8.e * w_10), (s_8.diffuse * w_10), (s_8.specular * w_10));
}

fn first_holders(keys_1: array<vec2<u32>, 8>, held_1: array<bool, 8>) -> array<u32, 8> {
    var first: array<u32, 8>;
    var k_4: u32 = 0u;
    var j_2: u32;
    var local_29: bool;
    var local_30: bool;

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
            j_2 = 0u;
            loop {
                let _e17 = j_2;
                let _e18 = k_4;
                if (_e17 < _e18) {
                    let _e22 = k_4;
                    local_29 = held_1[_e22];
                } else {
                    local_29 = false;
                }
                let _e25 = local_29;
                if _e25 {
                } else {
                    break;
                }
                {
                    let _e26 = j_2;
                    if held_1[_e26] {
                        let _e30 = j_2;
                        let _e32 = k_4;
                        local_30 = all((keys_1[_e30] == keys_1[_e32]));
                    } else {
                        local_30 = false;
                    }
                    let _e37 = local_30;
                    if _e37 {
                        let _e38 = k_4;
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
            let _e45 = k_4;
            k_4 = (_e45 + 1u);
        }
    }
    let _e47 = first;
    return _e47;
}

fn output_of(s_9: Shaded) -> vec3<f32> {
    return (s_9.diffuse + s_9.specular);
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
    var slot_light: array<u32, 8>;
    var slot_u: array<vec2<f32>, 8>;
    var slot_p: array<f32, 8>;
    var total: vec3<f32> = vec3(0f);
    var count: u32 = 0u;
    var hc: u32;
    var threshold: array<f32, 8>;
    var start: u32 = 0u;
    var j: u32;
    var local_4: bool;
    var q: u32;
    var local_5: bool;
    var keys: array<vec2<u32>, 8>;
    var held: array<bool, 8>;
    var k: u32 = 0u;
    var k_1: u32 = 0u;
    var w: vec3<f32>;
    var j_1: u32;
    var local_6: bool;

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
    let len2_ = dot(_e32, _e33);
    let _e35 = s;
    let x_13 = _e35.xyz;
    if inside {
        let _e40 = s.w;
        local_1 = (_e40 > 0f);
    } else {
        local_1 = false;
    }
    let _e44 = local_1;
    if _e44 {
        local_2 = (len2_ > 0f);
    } else {
        local_2 = false;
    }
    let _e50 = local_2;
    if _e50 {
        local_3 = all((abs(x_13) <= vec3(340282350000000000000000000000000000000f)));
    } else {
        local_3 = false;
    }
    let has_3 = local_3;
    if has_3 {
        let _e65 = nn;
        n = (_e65 / vec3(sqrt(len2_)));
    }
    let _e76 = n;
    r = _e76;
    if has_3 {
        let mr = textureLoad(metal_rough_tex, texel_1, 0i);
        let _e83 = textureLoad(base_color_tex, texel_1, 0i);
        let _e90 = view.eye;
        let _e93 = material_of(_e83.xyz, mr.z, mr.y, mr.w, normalize((_e90 - x_13)));
        m = _e93;
        let _e95 = m.base;
        let _e97 = m.metallic;
        let _e99 = bevy_f0_(mr.w);
        let _e103 = m.alpha;
        let _e104 = n;
        let _e106 = m.v;
        let _e108 = receiver_lobe(_e95, _e97, vec3(_e99), 1f, _e103, dot(_e104, _e106));
        lobe = _e108;
        let _e109 = n;
        let _e111 = m.v;
        let _e112 = mirror_dir(_e109, _e111);
        r = _e112;
    }
    let _e113 = lobe;
    let _e114 = range_lobe(_e113);
    let _e117 = view.shadow_offset;
    let _e120 = view.eye;
    let eps_4 = (_e117 * length((_e120 - x_13)));
    let _e126 = view.seed;
    let _e130 = view.width;
    let _e136 = view.frame;
    let _e137 = point_stream(_e126, ((gid.y * _e130) + gid.x), _e136);
    let _e138 = pick_stream(_e137);
    h = _e138;
    hc = _e137;
    let _e159 = tile_walk_begin(lid, x_13, _e114.w, has_3);
    loop {
        let _e162 = start;
        if (_e162 < _e159.total) {
        } else {
            break;
        }
        {
            let _e165 = start;
            let _e166 = tile_walk_fill(lid, _e159, _e165);
            j = 0u;
            loop {
                let _e169 = j;
                if (_e169 < _e166) {
                } else {
                    break;
                }
                {
                    let _e172 = j;
                    let b_9 = tile_list[_e172];
                    if !(!(has_3)) {
                        let _e181 = bsh_nodes[b_9];
                        let _e182 = r;
                        let _e183 = bsh_reaches(_e181, x_13, _e182, _e114);
                        local_4 = !(_e183);
                    } else {
                        local_4 = true;
                    }
                    let _e186 = local_4;
                    if _e186 {
                        continue;
                    }
                    let li_8 = bsh_nodes[b_9].light;
                    let _e191 = count;
                    count = (_e191 + 1u);
                    let _e194 = h;
                    let _e195 = pcg_hash(_e194);
                    h = _e195;
                    let _e196 = h;
                    let _e197 = xi_from_bits(_e196);
                    let _e198 = h;
                    let _e199 = pcg_hash(_e198);
                    h = _e199;
                    let _e200 = h;
                    let _e201 = xi_from_bits(_e200);
                    let u_4 = vec2<f32>(_e197, _e201);
                    let _e203 = n;
                    let _e204 = r;
                    let _e205 = m;
                    let _e210 = shade_pick_traced(li_8, x_13, _e203, _e204, _e114, _e205, 1f, u_4.x, u_4.y, eps_4, false);
                    let _e211 = output_of(_e210);
                    let _e212 = resample_target(_e211);
                    if (_e212 > 0f) {
                        let _e215 = total;
                        total = (_e215 + _e211);
                        q = 0u;
                        loop {
                            let _e219 = q;
                            if (_e219 < K) {
                            } else {
                                break;
                            }
                            {
                                let _e222 = q;
                                let _e224 = slot_target(_e211, _e222, K);
                                let _e225 = total;
                                let _e226 = q;
                                let _e228 = slot_target(_e225, _e226, K);
                                if (_e224 > 0f) {
                                    let _e233 = q;
                                    let _e235 = threshold[_e233];
                                    local_5 = (_e228 > _e235);
                                } else {
                                    local_5 = false;
                                }
                                let _e238 = local_5;
                                if _e238 {
                                    let _e239 = q;
                                    slot_light[_e239] = li_8;
                                    let _e241 = q;
                                    slot_u[_e241] = u_4;
                                    let _e243 = q;
                                    slot_p[_e243] = _e224;
                                    let _e245 = q;
                                    let _e247 = next_threshold(_e228, (&hc));
                                    threshold[_e245] = _e247;
                                }
                            }
                            continuing {
                                let _e249 = q;
                                q = (_e249 + 1u);
                            }
                        }
                    }
                }
                continuing {
                    let _e252 = j;
                    j = (_e252 + 1u);
                }
            }
            workgroupBarrier();
        }
        continuing {
            let _e254 = start;
            start = (_e254 + TILE_LIST);
        }
    }
    if !(has_3) {
        if inside {
            textureStore(out_tex, texel_1, vec4(0f));
        }
        return;
    }
    loop {
        let _e265 = k;
        if (_e265 < K) {
        } else {
            break;
        }
        {
            let _e268 = k;
            let _e270 = k;
            let _e272 = slot_light[_e270];
            keys[_e268] = vec2<u32>(_e272, 0u);
            let _e275 = k;
            let _e277 = k;
            let _e279 = slot_p[_e277];
            held[_e275] = (_e279 > 0f);
        }
        continuing {
            let _e283 = k;
            k = (_e283 + 1u);
        }
    }
    let _e285 = keys;
    let _e286 = held;
    let _e287 = first_holders(_e285, _e286);
    loop {
        let _e290 = k_1;
        if (_e290 < K) {
        } else {
            break;
        }
        {
            w = vec3(0f);
            let _e296 = k_1;
            let _e298 = k_1;
            let first_1 = (_e287[_e296] == _e298);
            let _e300 = k_1;
            j_1 = _e300;
            loop {
                let _e302 = j_1;
                if (_e302 < K) {
                    local_6 = first_1;
                } else {
                    local_6 = false;
                }
                let _e308 = local_6;
                if _e308 {
                } else {
                    break;
                }
                {
                    let _e309 = j_1;
                    let _e311 = k_1;
                    if (_e287[_e309] == _e311) {
                        let _e313 = w;
                        let _e314 = total;
                        let _e315 = j_1;
                        let _e317 = slot_target(_e314, _e315, K);
                        let _e318 = j_1;
                        let _e320 = slot_p[_e318];
                        let _e322 = j_1;
                        let _e324 = slot_share(_e322, K);
                        w = (_e313 + ((_e317 / _e320) * _e324));
                    }
                }
                continuing {
                    let _e328 = j_1;
                    j_1 = (_e328 + 1u);
                }
            }
            if first_1 {
                let _e330 = t;
                let _e331 = k_1;
                let _e333 = slot_light[_e331];
                let _e334 = n;
                let _e335 = r;
                let _e336 = m;
                let _e338 = k_1;
                let _e341 = slot_u[_e338].x;
                let _e342 = k_1;
                let _e345 = slot_u[_e342].y;
                let _e346 = shade_pick(_e333, x_13, _e334, _e335, _e114, _e336, 1f, _e341, _e345, eps_4);
                let _e347 = w;
                let _e348 = scaled(_e346, _e347);
                let _e349 = add(_e330, _e348);
                t = _e349;
            }
        }
        continuing {
            let _e351 = k_1;
            k_1 = (_e351 + 1u);
        }
    }
    let _e355 = t.diffuse;
    let _e357 = t.specular;
    let _e359 = count;
    textureStore(out_tex, texel_1, vec4<f32>((_e355 + _e357), f32(_e359)));
    return;
}
