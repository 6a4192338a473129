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

struct ReuseParams {
    c0_: vec4<f32>,
    c1_: vec4<f32>,
    c2_: vec4<f32>,
    c3_: vec4<f32>,
    prev_eye: vec3<f32>,
    max_confidence: f32,
    has_history: u32,
    radius: f32,
    visibility: u32,
    parity: u32,
    moved_min: vec3<f32>,
    moved: u32,
    moved_max: vec3<f32>,
    pad: u32,
}

struct ReuseSurface {
    x: vec3<f32>,
    m: f32,
    n: vec3<f32>,
    base: u32,
    rough: u32,
    pad0_: u32,
    pad1_: u32,
    pad2_: u32,
}

struct ReuseSlot {
    light: u32,
    u: u32,
    w: f32,
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

struct ReusePixel {
    surface: ReuseSurface,
    slots: array<ReuseSlot, 8>,
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

struct Domain {
    pixel: u32,
    x: vec3<f32>,
    n: vec3<f32>,
    m: Material,
    c: f32,
    temporal: bool,
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
const DOMAINS: u32 = 3u;

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
@group(0) @binding(7) 
var<uniform> reuse: ReuseParams;
@group(1) @binding(8) 
var<storage> lights_prev: array<GpuLight>;
@group(1) @binding(9) 
var<storage, read_write> reuse_pixels: array<ReusePixel>;
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

fn reuse_stream(stream_1: u32, which: u32) -> u32 {
    let _e2 = pick_stream(stream_1);
    let _e6 = pcg_hash(((_e2 + 1u) + which));
    return _e6;
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
    let q_9 = clamp(c_1, bmin, bmax);
    let v_6 = (q_9 - c_1);
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
    var local_16: bool;
    var local_17: bool;

    let v_7 = (x_2 - y);
    let d2_6 = dot(v_7, v_7);
    let _e7 = slc_keep(r2_1, d2_6);
    if !(!(_e7)) {
        local_16 = !((d2_6 > 0f));
    } else {
        local_16 = true;
    }
    let _e16 = local_16;
    if _e16 {
        return 0f;
    }
    let w_12 = (v_7 / vec3(sqrt(d2_6)));
    let cos_x_1 = -(dot(n_1, w_12));
    if !(!((cos_x_1 > 0f))) {
        local_17 = !((dot(ng, w_12) < 0f));
    } else {
        local_17 = true;
    }
    let _e34 = local_17;
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

fn weighted_replace(w_4: f32, w_sum: f32, u_2: f32) -> bool {
    return ((u_2 * w_sum) < w_4);
}

fn weighted_threshold(w_sum_1: f32, u_3: f32) -> f32 {
    return (w_sum_1 / (1f - u_3));
}

fn resample_target(c_3: vec3<f32>) -> f32 {
    return (((c_3.x + c_3.y) + c_3.z) * 0.33333334f);
}

fn slot_target(c_4: vec3<f32>, slot: u32, k_2: u32) -> f32 {
    if (k_2 < 3u) {
        let _e5 = resample_target(c_4);
        return _e5;
    }
    let j_7 = (slot % 3u);
    if (j_7 == 0u) {
        return c_4.x;
    }
    if (j_7 == 1u) {
        return c_4.y;
    }
    return c_4.z;
}

fn slot_share(slot_1: u32, k_3: u32) -> vec3<f32> {
    if (k_3 < 3u) {
        let _e4 = to_f32_(k_3);
        let w_13 = (1f / _e4);
        return vec3<f32>(w_13, w_13, w_13);
    }
    let j_8 = (slot_1 % 3u);
    let _e15 = to_f32_((((k_3 + 2u) - j_8) / 3u));
    let w_14 = (1f / _e15);
    if (j_8 == 0u) {
        return vec3<f32>(w_14, 0f, 0f);
    }
    if (j_8 == 1u) {
        return vec3<f32>(0f, w_14, 0f);
    }
    return vec3<f32>(0f, 0f, w_14);
}

fn grid_coordinate(bits_1: u32) -> f32 {
    let _e3 = to_f32_((bits_1 >> 16u));
    return ((_e3 + 0.5f) / 65536f);
}

fn grid_cells(h1_: u32, h2_: u32) -> u32 {
    return ((h1_ & 4294901760u) | (h2_ >> 16u));
}

fn disk_offset(r_3: f32, u1_1: f32, u2_1: f32) -> vec2<f32> {
    let a_9 = (TWO_PI * u2_1);
    return (vec2<f32>(cos(a_9), sin(a_9)) * (r_3 * sqrt(u1_1)));
}

fn gris_weight(own: f32, all_: f32, p_hat: f32, w_5: f32) -> f32 {
    if !((all_ > 0f)) {
        return 0f;
    }
    return (((own / all_) * p_hat) * w_5);
}

fn reuse_trust(h_1: vec3<f32>, t_1: vec3<f32>) -> f32 {
    let d2_7 = dot(h_1, h_1);
    if !((d2_7 > 0f)) {
        return 1f;
    }
    let c_11 = (h_1 - t_1);
    return (d2_7 / (d2_7 + (REUSE_TRUST_SCALE * dot(c_11, c_11))));
}

fn gris_contribution_weight(w_sum_2: f32, p_hat_1: f32) -> f32 {
    if !((p_hat_1 > 0f)) {
        return 0f;
    }
    return (w_sum_2 / p_hat_1);
}

fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
    if (cos_h <= 0f) {
        return 0f;
    }
    let a2_ = (alpha * alpha);
    let t_6 = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t_6 * t_6));
}

fn smith_root(cos_: f32, alpha_1: f32) -> f32 {
    let a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1f - a2_1)) + a2_1));
}

fn smith_visibility(n_l: f32, n_v: f32, alpha_2: f32) -> f32 {
    var local_18: bool;

    if !((n_l <= 0f)) {
        local_18 = (n_v <= 0f);
    } else {
        local_18 = true;
    }
    let _e11 = local_18;
    if _e11 {
        return 0f;
    }
    let _e13 = smith_root(n_v, alpha_2);
    let _e15 = smith_root(n_l, alpha_2);
    return (0.5f / ((n_l * _e13) + (n_v * _e15)));
}

fn fresnel_schlick(f0_: vec3<f32>, f90_: f32, v_h: f32) -> vec3<f32> {
    let c_12 = saturate((1f - v_h));
    let c2_1 = (c_12 * c_12);
    return (f0_ + ((vec3<f32>(f90_, f90_, f90_) - f0_) * ((c2_1 * c2_1) * c_12)));
}

fn specular_fresnel(base: vec3<f32>, metallic: f32, f0_d: vec3<f32>, f90_d: f32, v_h_1: f32) -> vec3<f32> {
    let _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    let _e10 = fresnel_schlick(base, 1f, v_h_1);
    return ((_e5 * (1f - metallic)) + (_e10 * metallic));
}

fn has_specular(metallic_1: f32, f0_d_1: vec3<f32>, f90_d_1: f32) -> bool {
    var local_19: bool;
    var local_20: bool;

    if !((metallic_1 > 0f)) {
        local_19 = (f90_d_1 > 0f);
    } else {
        local_19 = true;
    }
    let _e11 = local_19;
    if !(_e11) {
        local_20 = (max(max(f0_d_1.x, f0_d_1.y), f0_d_1.z) > 0f);
    } else {
        local_20 = true;
    }
    let _e23 = local_20;
    return _e23;
}

fn channel_mean(c_5: vec3<f32>) -> f32 {
    return (((c_5.x + c_5.y) + c_5.z) * 0.33333334f);
}

fn receiver_lobe(base_1: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n_v_1: f32) -> vec4<f32> {
    var local_21: bool;

    let _e10 = fresnel_schlick(f0_d_2, f90_d_2, n_v_1);
    let _e16 = channel_mean((((vec3<f32>(1f, 1f, 1f) - _e10) * base_1) * (1f - metallic_2)));
    if !((n_v_1 <= 0f)) {
        let _e22 = has_specular(metallic_2, f0_d_2, f90_d_2);
        local_21 = !(_e22);
    } else {
        local_21 = true;
    }
    let _e25 = local_21;
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

fn bevy_dfg(r_4: f32, n_v_2: f32) -> f32 {
    let rx = (1f - r_4);
    let a004_ = ((min((rx * rx), exp2((-9.28f * n_v_2))) * rx) + (0.0425f - (0.0275f * r_4)));
    let x_18 = max(((1.04f - (0.572f * r_4)) - (1.04f * a004_)), 0.00005f);
    let y_1 = max((((0.022f * r_4) - 0.04f) + (1.04f * a004_)), 0.00005f);
    return (x_18 + y_1);
}

fn bevy_brdf(base_2: vec3<f32>, metallic_3: f32, r_5: f32, reflectance_1: f32, n_4: vec3<f32>, v_1: vec3<f32>, l: vec3<f32>) -> vec3<f32> {
    let n_l_1 = saturate(dot(n_4, l));
    if (n_l_1 <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = bevy_alpha(r_5);
    let n_v_3 = max(dot(n_4, v_1), 0.0001f);
    let h_4 = normalize((l + v_1));
    let n_h = saturate(dot(n_4, h_4));
    let l_h = saturate(dot(l, h_4));
    let f90_d_3 = (0.5f + (((2f * _e15) * l_h) * l_h));
    let _e35 = fresnel_schlick(vec3<f32>(1f, 1f, 1f), f90_d_3, n_l_1);
    let _e41 = fresnel_schlick(vec3<f32>(1f, 1f, 1f), f90_d_3, n_v_3);
    let burley = ((_e35.x * _e41.x) * INV_PI);
    let _e46 = bevy_f0_(reflectance_1);
    let f0_1 = ((vec3<f32>(_e46, _e46, _e46) * (1f - metallic_3)) + (base_2 * metallic_3));
    let f90_1 = saturate((((f0_1.x + f0_1.y) + f0_1.z) * 16.5f));
    let _e64 = ggx_d(n_h, (1f - (n_h * n_h)), _e15);
    let _e65 = smith_visibility(n_l_1, n_v_3, _e15);
    let _e70 = bevy_dfg(r_5, n_v_3);
    let comp = (vec3<f32>(1f, 1f, 1f) + (f0_1 * ((1f / _e70) - 1f)));
    let _e77 = fresnel_schlick(f0_1, f90_1, l_h);
    let spec = ((_e77 * comp) * (_e64 * _e65));
    return ((base_2 * ((1f - metallic_3) * burley)) + spec);
}

fn cone_cos_of(v_2: vec3<f32>, d2_4: f32, a_3: f32, d: vec3<f32>) -> f32 {
    var local_22: bool;
    var local_23: bool;

    let vd = dot(v_2, d);
    let h2_1 = (d2_4 - (a_3 * a_3));
    if !((h2_1 <= 0f)) {
        if (vd >= 0f) {
            local_23 = ((vd * vd) >= h2_1);
        } else {
            local_23 = false;
        }
        let _e19 = local_23;
        local_22 = _e19;
    } else {
        local_22 = true;
    }
    let _e21 = local_22;
    if _e21 {
        return 1f;
    }
    let c_13 = cross(v_2, d);
    return min((((vd * sqrt(h2_1)) + (sqrt(dot(c_13, c_13)) * a_3)) / d2_4), 1f);
}

fn cone_cos_toward(center: vec3<f32>, radius: f32, p: vec3<f32>, d_1: vec3<f32>) -> f32 {
    let v_8 = (center - p);
    let _e6 = cone_cos_of(v_8, dot(v_8, v_8), radius, d_1);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_7 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_7 * t_7))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_1: vec3<f32>, radius_1: f32, p_1: vec3<f32>, r_6: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_1, radius_1, p_1, r_6);
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
    var local_24: bool;

    let n_17 = cross((b_3 - a_4), (c_6 - a_4));
    let l2_ = dot(n_17, n_17);
    if !(!((l2_ > 0f))) {
        local_24 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_24 = true;
    }
    let _e17 = local_24;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_17 / vec3(sqrt(l2_)));
}

fn ray_triangle(o_1: vec3<f32>, d_3: vec3<f32>, a_5: vec3<f32>, b_4: vec3<f32>, c_7: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_25: bool;
    var local_26: bool;
    var local_27: bool;

    let e1_ = (b_4 - a_5);
    let e2_ = (c_7 - a_5);
    let p_8 = cross(d_3, e2_);
    let det = dot(e1_, p_8);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv = (1f / det);
    let s_12 = (o_1 - a_5);
    let u_4 = (dot(s_12, p_8) * inv);
    if !((u_4 < 0f)) {
        local_25 = (u_4 > 1f);
    } else {
        local_25 = true;
    }
    let _e28 = local_25;
    if _e28 {
        return -1f;
    }
    let q_10 = cross(s_12, e1_);
    let v_9 = (dot(d_3, q_10) * inv);
    if !((v_9 < 0f)) {
        local_26 = ((u_4 + v_9) > 1f);
    } else {
        local_26 = true;
    }
    let _e42 = local_26;
    if _e42 {
        return -1f;
    }
    let t_8 = (dot(e2_, q_10) * inv);
    if (t_8 > t_min) {
        local_27 = (t_8 < t_max_1);
    } else {
        local_27 = false;
    }
    let _e51 = local_27;
    if _e51 {
        return t_8;
    }
    return -1f;
}

fn reproject(c0_: vec4<f32>, c1_: vec4<f32>, c2_: vec4<f32>, c3_: vec4<f32>, p_2: vec3<f32>, width: f32, height: f32) -> vec3<f32> {
    let clip = ((((c0_ * p_2.x) + (c1_ * p_2.y)) + (c2_ * p_2.z)) + c3_);
    if (clip.w <= 0f) {
        return vec3<f32>(-1f, -1f, 0f);
    }
    let x_19 = (((((clip.x / clip.w) + 1f) * 0.5f) * width) - 0.5f);
    let y_2 = ((((1f - (clip.y / clip.w)) * 0.5f) * height) - 0.5f);
    return vec3<f32>(x_19, y_2, clip.w);
}

fn history_matches(n_5: vec3<f32>, nh: vec3<f32>, p_3: vec3<f32>, oh: f32, d_4: f32) -> bool {
    var local_28: bool;

    if (abs((dot(nh, p_3) - oh)) <= (TEMPORAL_DEPTH_TOLERANCE * d_4)) {
        local_28 = (dot(n_5, nh) >= TEMPORAL_NORMAL_COS);
    } else {
        local_28 = false;
    }
    let _e17 = local_28;
    return _e17;
}

fn light_intensity(l_1: GpuLight, w_6: vec3<f32>) -> vec3<f32> {
    switch l_1.kind {
        case 0u: {
            return l_1.intensity;
        }
        case 3u: {
            let _e8 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
            let _e10 = triangle_lobe(_e8, l_1.a, w_6);
            return (l_1.intensity * _e10);
        }
        default: {
            return vec3(0f);
        }
    }
}

fn light_point(l_2: GpuLight, u1_2: f32, u2_2: f32) -> vec3<f32> {
    if (l_2.kind == LIGHT_TRIANGLE) {
        let _e9 = triangle_sample(l_2.p0_, l_2.p1_, l_2.p2_, u1_2, u2_2);
        return _e9;
    }
    return l_2.p0_;
}

fn trace(o_2: vec3<f32>, d_5: vec3<f32>, t_min_1: f32, t_max_2: f32, any_hit: bool) -> GeoHit {
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
    let _e14 = ray_inverse3_(d_5);
    loop {
        let _e21 = node_3;
        let n_18 = geo_nodes[_e21];
        let _e27 = hit.t;
        let _e28 = ray_aabb(o_2, _e14, n_18.bmin, n_18.bmax, _e27);
        if (_e28 >= 0f) {
            if (n_18.count > 0u) {
                i = n_18.first;
                loop {
                    let _e36 = i;
                    if (_e36 < (n_18.first + n_18.count)) {
                    } else {
                        break;
                    }
                    {
                        let _e42 = i;
                        let t_9 = geo_tris[_e42];
                        let _e49 = hit.t;
                        let _e50 = ray_triangle(o_2, d_5, t_9.v0_, t_9.v1_, t_9.v2_, t_min_1, _e49);
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
                    stack[_e63] = (n_18.first + 1u);
                    let _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_18.first;
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

fn bsh_inner_scale(a_7: f32, v_3: vec3<f32>, d2_5: f32, r_7: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let _e5 = cone_cos_of(v_3, d2_5, a_7, r_7);
    let _e8 = range_scale_at(rl_2, (_e5 + 0.000002f));
    return _e8;
}

fn bsh_reaches(node_4: BshNode, x_4: vec3<f32>, r_8: vec3<f32>, rl_3: vec4<f32>) -> bool {
    var local_29: bool;
    var local_30: bool;

    let _e6 = sphere_contains_point(node_4.center, node_4.radius, x_4);
    if _e6 {
        return true;
    }
    if !((rl_3.w <= 1f)) {
        let _e20 = sphere_contains_point(node_4.center, (node_4.radius * (rl_3.w * 1.0001f)), x_4);
        local_29 = !(_e20);
    } else {
        local_29 = true;
    }
    let _e23 = local_29;
    if _e23 {
        return false;
    }
    let v_10 = (x_4 - node_4.center);
    let d2_8 = dot(v_10, v_10);
    let _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_8 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        let _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_4, r_8);
        let _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        let _e42 = sphere_contains_point(node_4.center, _e41, x_4);
        return _e42;
    }
    let _e45 = bsh_inner_scale(node_4.extent, -(v_10), d2_8, r_8, rl_3);
    let s_c = (_e45 * 1.001f);
    let _e50 = bsh_range_bound(node_4);
    let reach = (node_4.extent + (sqrt(s_c) * _e50));
    if (d2_8 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_30 = (d2_8 <= (reach * reach));
    } else {
        local_30 = false;
    }
    let _e63 = local_30;
    return _e63;
}

fn bsh_reaches_box(node_5: BshNode, lo: vec3<f32>, hi: vec3<f32>, w_7: f32) -> bool {
    let _e13 = sphere_overlaps_aabb(node_5.center, (node_5.radius * (max(1f, (w_7 * 1.0001f)) * 1.0001f)), lo, hi);
    return _e13;
}

fn bsh_subtree(nodes_3: u32, s_1: u32, depth: u32) -> u32 {
    var i_2: u32;
    var level: u32 = 0u;
    var local_31: bool;

    let _e3 = bsh_first(nodes_3);
    i_2 = _e3;
    loop {
        let _e7 = level;
        if (_e7 < depth) {
            let _e11 = i_2;
            local_31 = (_e11 != BSH_NONE);
        } else {
            local_31 = false;
        }
        let _e15 = local_31;
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

fn bsh_next_leaf_box(nodes_4: u32, start_1: u32, end: u32, lo_1: vec3<f32>, hi_1: vec3<f32>, w_8: f32) -> u32 {
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
            let _e11 = bsh_reaches_box(_e10, lo_1, hi_1, w_8);
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

fn next_threshold(sum: f32, h_2: ptr<function, u32>) -> f32 {
    let _e2 = (*h_2);
    let _e3 = pcg_hash(_e2);
    (*h_2) = _e3;
    let _e4 = (*h_2);
    let _e5 = xi_from_bits(_e4);
    let _e6 = weighted_threshold(sum, _e5);
    return _e6;
}

fn connect_record(l_3: GpuLight, x_5: vec3<f32>, n_6: vec3<f32>, ng_1: vec3<f32>, r2_2: f32, rt2_2: f32, w_res: f32, u1_3: f32, u2_3: f32, eps: f32, trace_1: bool) -> Connection {
    var c_8: Connection;
    var local_32: bool;
    var local_33: bool;

    c_8.e = vec3(0f);
    let _e16 = light_point(l_3, u1_3, u2_3);
    c_8.y = _e16;
    let _e19 = c_8.y;
    let _e20 = connection_cosine(x_5, _e19, n_6, ng_1, r2_2);
    c_8.cos_x = _e20;
    let _e22 = c_8.cos_x;
    if !((_e22 <= 0f)) {
        if trace_1 {
            let _e33 = c_8.y;
            let _e34 = occluded((x_5 + (ng_1 * eps)), _e33);
            local_33 = _e34;
        } else {
            local_33 = false;
        }
        let _e36 = local_33;
        local_32 = _e36;
    } else {
        local_32 = true;
    }
    let _e38 = local_32;
    if _e38 {
        let _e39 = c_8;
        return _e39;
    }
    let _e41 = c_8.y;
    let v_11 = (x_5 - _e41);
    let d2_9 = dot(v_11, v_11);
    let _e48 = light_intensity(l_3, (v_11 / vec3(sqrt(d2_9))));
    let _e50 = c_8.cos_x;
    let _e51 = connection_factor(_e50, d2_9, rt2_2, w_res);
    c_8.e = (_e48 * _e51);
    let _e53 = c_8;
    return _e53;
}

fn connect_traced(li: u32, x_6: vec3<f32>, n_7: vec3<f32>, ng_2: vec3<f32>, s_2: f32, w_res_1: f32, u1_4: f32, u2_4: f32, eps_1: f32, trace_2: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_3[li];
    let _e19 = rt2_3[li];
    let _e21 = connect_record(_e12, x_6, n_7, ng_2, (s_2 * _e15), (s_2 * _e19), w_res_1, u1_4, u2_4, eps_1, trace_2);
    return _e21;
}

fn light_range_scale(li_1: u32, x_7: vec3<f32>, r_9: vec3<f32>, rl_4: vec4<f32>) -> f32 {
    let c_14 = light_cones[li_1];
    let _e9 = range_scale_toward(rl_4, c_14.center, c_14.radius, x_7, r_9);
    return _e9;
}

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p_9 = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p_9.xyz, 1f), (p_9.w > 0f));
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

fn point_box(p_4: vec3<f32>, has: bool) -> WorkgroupBox {
    return WorkgroupBox(select(vec3(340282350000000000000000000000000000000f), p_4, has), select(vec3(-340282350000000000000000000000000000000f), p_4, has));
}

fn workgroup_box(li_3: u32, p_5: vec3<f32>, has_1: bool) -> WorkgroupBox {
    let _e3 = point_box(p_5, has_1);
    let _e6 = workgroup_bounds(li_3, _e3.lo, _e3.hi);
    return _e6;
}

fn box_is_empty(b_6: WorkgroupBox) -> bool {
    return (b_6.lo.x > b_6.hi.x);
}

fn tile_subtree(s_3: u32, t_2: TileWalk, list: bool, at: u32, start_2: u32, to: u32) -> u32 {
    var p_6: u32;
    var b_7: u32;
    var local_34: bool;
    var local_35: bool;
    var local_36: bool;

    let _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH);
    if (_e8 == BSH_NONE) {
        return 0u;
    }
    let end_1 = bsh_nodes[_e8].next;
    p_6 = at;
    let _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_2.lo, t_2.hi, t_2.w);
    b_7 = _e21;
    loop {
        let _e23 = b_7;
        if (_e23 != end_1) {
            if !(!(list)) {
                let _e31 = p_6;
                local_35 = (_e31 < to);
            } else {
                local_35 = true;
            }
            let _e34 = local_35;
            local_34 = _e34;
        } else {
            local_34 = false;
        }
        let _e36 = local_34;
        if _e36 {
        } else {
            break;
        }
        {
            if list {
                let _e39 = p_6;
                local_36 = (_e39 >= start_2);
            } else {
                local_36 = false;
            }
            let _e42 = local_36;
            if _e42 {
                let _e44 = p_6;
                let _e47 = b_7;
                tile_list[(_e44 - start_2)] = _e47;
            }
            let _e48 = p_6;
            p_6 = (_e48 + 1u);
        }
        continuing {
            let _e53 = b_7;
            let _e56 = bsh_nodes[_e53].next;
            let _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_2.lo, t_2.hi, t_2.w);
            b_7 = _e60;
        }
    }
    let _e61 = p_6;
    return (_e61 - at);
}

fn tile_walk_begin(li_4: u32, x_8: vec3<f32>, w_9: f32, has_2: bool) -> TileWalk {
    var local_37: bool;
    var t_3: TileWalk;
    var s_4: u32;
    var sum_1: u32 = 0u;
    var s_5: u32 = 0u;

    if has_2 {
        local_37 = (w_9 >= 0f);
    } else {
        local_37 = false;
    }
    let _e12 = local_37;
    let _e14 = atomicMax((&tile_scale), select(0u, bitcast<u32>(w_9), _e12));
    let _e15 = workgroup_box(li_4, x_8, has_2);
    let _e19 = workgroupUniformLoad((&tile_scale));
    t_3 = TileWalk(_e15.lo, _e15.hi, bitcast<f32>(_e19), 0u);
    let _e24 = box_is_empty(_e15);
    if _e24 {
        let _e25 = t_3;
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
            let _e34 = t_3;
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
                let c_15 = subtree_at[_e53];
                let _e57 = s_5;
                let _e59 = sum_1;
                subtree_at[_e57] = _e59;
                let _e60 = sum_1;
                sum_1 = (_e60 + c_15);
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
    t_3.total = _e69;
    let _e70 = t_3;
    return _e70;
}

fn tile_walk_fill(li_5: u32, t_4: TileWalk, start_3: u32) -> u32 {
    var s_6: u32;
    var past: u32;
    var local_38: bool;

    let to_1 = min(t_4.total, (start_3 + TILE_LIST));
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
            past = t_4.total;
            let _e17 = s_6;
            if ((_e17 + 1u) < BSH_TILE_SUBTREES) {
                let _e23 = s_6;
                let _e27 = subtree_at[(_e23 + 1u)];
                past = _e27;
            }
            if (at_1 < to_1) {
                let _e31 = past;
                local_38 = (_e31 > start_3);
            } else {
                local_38 = false;
            }
            let _e34 = local_38;
            if _e34 {
                let _e35 = s_6;
                let _e37 = tile_subtree(_e35, t_4, true, at_1, start_3, to_1);
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

fn shade_connection(c_9: Connection, x_9: vec3<f32>, n_8: vec3<f32>, m_1: Material) -> Shaded {
    var s_7: Shaded;

    s_7.e = c_9.e;
    s_7.diffuse = vec3(0f);
    s_7.specular = vec3(0f);
    if (c_9.cos_x > 0f) {
        let _e25 = bevy_brdf(m_1.base, m_1.metallic, m_1.roughness, m_1.reflectance, n_8, m_1.v, normalize((c_9.y - x_9)));
        s_7.diffuse = (_e25 * c_9.e);
    }
    let _e28 = s_7;
    return _e28;
}

fn shade_pick_traced(li_6: u32, x_10: vec3<f32>, n_9: vec3<f32>, r_10: vec3<f32>, rl_5: vec4<f32>, m_2: Material, w_10: f32, u1_5: f32, u2_5: f32, eps_2: f32, trace_3: bool) -> Shaded {
    let _e11 = light_range_scale(li_6, x_10, r_10, rl_5);
    let _e12 = connect_traced(li_6, x_10, n_9, n_9, _e11, w_10, u1_5, u2_5, eps_2, trace_3);
    let _e13 = shade_connection(_e12, x_10, n_9, m_2);
    return _e13;
}

fn material_of(base_3: vec3<f32>, metallic_4: f32, roughness: f32, reflectance_2: f32, v_4: vec3<f32>) -> Material {
    let _e6 = bevy_alpha(roughness);
    return Material(base_3, saturate(metallic_4), _e6, v_4, roughness, reflectance_2);
}

fn add(a_8: Shaded, b_8: Shaded) -> Shaded {
    return Shaded((a_8.e + b_8.e), (a_8.diffuse + b_8.diffuse), (a_8.specular + b_8.specular));
}

fn scaled(s_8: Shaded, w_11: vec3<f32>) -> Shaded {
    return Shaded((s_8.e * w_11), (s_8.diffuse * w_11), (s_8.specular * w_11));
}

fn first_holders(keys_1: array<vec2<u32>, 8>, held_1: array<bool, 8>) -> array<u32, 8> {
    var first: array<u32, 8>;
    var k_4: u32 = 0u;
    var j_4: u32;
    var local_39: bool;
    var local_40: bool;

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
            j_4 = 0u;
            loop {
                let _e17 = j_4;
                let _e18 = k_4;
                if (_e17 < _e18) {
                    let _e22 = k_4;
                    local_39 = held_1[_e22];
                } else {
                    local_39 = false;
                }
                let _e25 = local_39;
                if _e25 {
                } else {
                    break;
                }
                {
                    let _e26 = j_4;
                    if held_1[_e26] {
                        let _e30 = j_4;
                        let _e32 = k_4;
                        local_40 = all((keys_1[_e30] == keys_1[_e32]));
                    } else {
                        local_40 = false;
                    }
                    let _e37 = local_40;
                    if _e37 {
                        let _e38 = k_4;
                        let _e40 = j_4;
                        first[_e38] = _e40;
                        break;
                    }
                }
                continuing {
                    let _e42 = j_4;
                    j_4 = (_e42 + 1u);
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

fn previous_index(i_4: u32) -> u32 {
    let _e4 = reuse.parity;
    let _e8 = view.width;
    let _e12 = view.height;
    return ((((1u - _e4) * _e8) * _e12) + i_4);
}

fn next_index(i_5: u32) -> u32 {
    let _e3 = reuse.parity;
    let _e6 = view.width;
    let _e10 = view.height;
    return (((_e3 * _e6) * _e10) + i_5);
}

fn sample_connection(l_4: GpuLight, cells: u32, x_11: vec3<f32>, n_10: vec3<f32>, eps_3: f32, trace_4: bool) -> Connection {
    let _e9 = grid_coordinate(cells);
    let _e12 = grid_coordinate((cells << 16u));
    let _e13 = connect_record(l_4, x_11, n_10, n_10, UNRANGED, UNRANGED, 1f, _e9, _e12, eps_3, trace_4);
    return _e13;
}

fn reuse_target(q_6: u32, l_5: GpuLight, cells_1: u32, x_12: vec3<f32>, n_11: vec3<f32>, m_3: Material) -> f32 {
    let _e8 = sample_connection(l_5, cells_1, x_12, n_11, 0f, false);
    let _e9 = shade_connection(_e8, x_12, n_11, m_3);
    let _e10 = output_of(_e9);
    let _e12 = slot_target(_e10, q_6, K);
    return _e12;
}

fn reuse_surface(x_13: vec3<f32>, n_12: vec3<f32>, m_4: Material, c_10: f32) -> ReuseSurface {
    return ReuseSurface(x_13, c_10, n_12, pack4x8unorm(vec4<f32>(m_4.base, m_4.metallic)), pack2x16unorm(vec2<f32>(saturate(m_4.roughness), saturate(m_4.reflectance))), 0u, 0u, 0u);
}

fn reuse_material(s_10: ReuseSurface, eye: vec3<f32>) -> Material {
    let b_9 = unpack4x8unorm(s_10.base);
    let r_12 = unpack2x16unorm(s_10.rough);
    let _e13 = material_of(b_9.xyz, b_9.w, r_12.x, r_12.y, normalize((eye - s_10.x)));
    return _e13;
}

fn sample_key(li_7: u32, cells_2: u32) -> vec2<u32> {
    let _e6 = lights[li_7].kind;
    return vec2<u32>(li_7, select(0u, cells_2, (_e6 == LIGHT_TRIANGLE)));
}

fn sample_reaches(l_6: GpuLight, cells_3: u32, x_14: vec3<f32>, n_13: vec3<f32>, eps_4: f32) -> bool {
    let _e6 = sample_connection(l_6, cells_3, x_14, n_13, eps_4, true);
    return any((_e6.e > vec3(0f)));
}

fn domain_offset(d_6: Domain) -> f32 {
    let _e3 = view.shadow_offset;
    let _e6 = reuse.prev_eye;
    return (_e3 * length((_e6 - d_6.x)));
}

fn history_vouches(li_8: u32, cells_4: u32, d_7: Domain) -> bool {
    let _e5 = reuse.moved;
    if (_e5 == 0u) {
        return true;
    }
    let _e11 = reuse.moved;
    if (_e11 == 2u) {
        return false;
    }
    let _e17 = domain_offset(d_7);
    let a_10 = (d_7.x + (d_7.n * _e17));
    let _e22 = lights_prev[li_8];
    let _e23 = grid_coordinate(cells_4);
    let _e26 = grid_coordinate((cells_4 << 16u));
    let _e27 = light_point(_e22, _e23, _e26);
    let _e29 = ray_inverse3_((_e27 - a_10));
    let _e32 = reuse.moved_min;
    let _e35 = reuse.moved_max;
    let _e37 = ray_aabb(a_10, _e29, _e32, _e35, 1f);
    return (_e37 < 0f);
}

fn reached_before(li_9: u32, cells_5: u32, d_8: Domain, x_15: vec3<f32>, n_14: vec3<f32>) -> bool {
    var local_41: bool;
    var local_42: bool;
    var local_43: bool;
    var local_44: bool;
    var q_7: u32 = 0u;
    var local_45: bool;
    var local_46: bool;

    let _e5 = history_vouches(li_9, cells_5, d_8);
    if !(_e5) {
        return false;
    }
    let l_7 = lights[li_9];
    let lp = lights_prev[li_9];
    if all((d_8.x == x_15)) {
        local_41 = all((d_8.n == n_14));
    } else {
        local_41 = false;
    }
    let _e23 = local_41;
    if _e23 {
        local_42 = all((l_7.p0_ == lp.p0_));
    } else {
        local_42 = false;
    }
    let _e31 = local_42;
    if _e31 {
        local_43 = all((l_7.p1_ == lp.p1_));
    } else {
        local_43 = false;
    }
    let _e39 = local_43;
    if _e39 {
        local_44 = all((l_7.p2_ == lp.p2_));
    } else {
        local_44 = false;
    }
    let _e47 = local_44;
    if _e47 {
        return true;
    }
    let _e49 = sample_key(li_9, cells_5);
    loop {
        let _e52 = q_7;
        if (_e52 < K) {
        } else {
            break;
        }
        {
            let _e57 = previous_index(d_8.pixel);
            let _e60 = q_7;
            let h_5 = reuse_pixels[_e57].slots[_e60];
            if (h_5.w > 0f) {
                local_45 = (h_5.light < arrayLength((&lights)));
            } else {
                local_45 = false;
            }
            let _e73 = local_45;
            if _e73 {
                let _e78 = sample_key(h_5.light, h_5.u);
                local_46 = all((_e78 == _e49));
            } else {
                local_46 = false;
            }
            let _e82 = local_46;
            if _e82 {
                return true;
            }
        }
        continuing {
            let _e85 = q_7;
            q_7 = (_e85 + 1u);
        }
    }
    let _e89 = domain_offset(d_8);
    let _e90 = sample_reaches(lp, cells_5, d_8.x, d_8.n, _e89);
    return _e90;
}

fn reuse_domains(x_16: vec3<f32>, n_15: vec3<f32>, d_9: f32, h_3: u32, doms_1: ptr<function, array<Domain, 3>>) -> u32 {
    var nd: u32 = 0u;
    var hr: u32;
    var j_5: u32 = 0u;
    var p_7: vec2<f32>;
    var local_47: bool;
    var local_48: bool;
    var local_49: bool;
    var seen_1: bool;
    var k_5: u32;
    var local_50: bool;
    var local_51: bool;
    var local_52: bool;

    let _e9 = reuse.has_history;
    if (_e9 != 1u) {
        return 0u;
    }
    let _e15 = reuse.c0_;
    let _e18 = reuse.c1_;
    let _e21 = reuse.c2_;
    let _e24 = reuse.c3_;
    let _e27 = view.width;
    let _e31 = view.height;
    let _e33 = reproject(_e15, _e18, _e21, _e24, x_16, f32(_e27), f32(_e31));
    if (_e33.z <= 0f) {
        return 0u;
    }
    hr = h_3;
    loop {
        let _e41 = j_5;
        if (_e41 < DOMAINS) {
        } else {
            break;
        }
        {
            p_7 = _e33.xy;
            let _e46 = j_5;
            if (_e46 > 0u) {
                let _e49 = hr;
                let _e50 = pcg_hash(_e49);
                hr = _e50;
                let _e51 = hr;
                let _e52 = xi_from_bits(_e51);
                let _e53 = hr;
                let _e54 = pcg_hash(_e53);
                hr = _e54;
                let _e55 = p_7;
                let _e58 = reuse.radius;
                let _e59 = hr;
                let _e60 = xi_from_bits(_e59);
                let _e61 = disk_offset(_e58, _e52, _e60);
                p_7 = (_e55 + _e61);
            }
            let _e63 = p_7;
            let t_10 = vec2<i32>(round(_e63));
            if !((t_10.x < 0i)) {
                local_47 = (t_10.y < 0i);
            } else {
                local_47 = true;
            }
            let _e76 = local_47;
            if !(_e76) {
                let _e83 = view.width;
                local_48 = (t_10.x >= i32(_e83));
            } else {
                local_48 = true;
            }
            let _e87 = local_48;
            if !(_e87) {
                let _e94 = view.height;
                local_49 = (t_10.y >= i32(_e94));
            } else {
                local_49 = true;
            }
            let _e98 = local_49;
            if _e98 {
                continue;
            }
            let _e103 = view.width;
            let pixel = ((u32(t_10.y) * _e103) + u32(t_10.x));
            seen_1 = false;
            k_5 = 0u;
            loop {
                let _e112 = k_5;
                let _e113 = nd;
                if (_e112 < _e113) {
                } else {
                    break;
                }
                {
                    let _e115 = seen_1;
                    if !(_e115) {
                        let _e119 = k_5;
                        let _e122 = (*doms_1)[_e119].pixel;
                        local_50 = (_e122 == pixel);
                    } else {
                        local_50 = true;
                    }
                    let _e125 = local_50;
                    seen_1 = _e125;
                }
                continuing {
                    let _e127 = k_5;
                    k_5 = (_e127 + 1u);
                }
            }
            let _e130 = previous_index(pixel);
            let s_13 = reuse_pixels[_e130].surface;
            let _e134 = seen_1;
            if !(_e134) {
                local_51 = !((s_13.m > 0f));
            } else {
                local_51 = true;
            }
            let _e143 = local_51;
            if !(_e143) {
                let _e151 = history_matches(n_15, s_13.n, x_16, dot(s_13.n, s_13.x), d_9);
                local_52 = !(_e151);
            } else {
                local_52 = true;
            }
            let _e154 = local_52;
            if _e154 {
                continue;
            }
            let _e155 = nd;
            let _e161 = reuse.prev_eye;
            let _e162 = reuse_material(s_13, _e161);
            let _e166 = reuse.max_confidence;
            let _e168 = j_5;
            (*doms_1)[_e155] = Domain(pixel, s_13.x, s_13.n, _e162, min(s_13.m, _e166), (_e168 == 0u));
            let _e172 = nd;
            nd = (_e172 + 1u);
        }
        continuing {
            let _e176 = j_5;
            j_5 = (_e176 + 1u);
        }
    }
    let _e178 = nd;
    return _e178;
}

fn gris_combine(q_8: u32, cur: ReuseSlot, cur_ris: bool, cur_c: f32, cur_reached: bool, k0_: u32, k1_: u32, x_17: vec3<f32>, n_16: vec3<f32>, m_5: Material, doms_2: ptr<function, array<Domain, 3>>, hs_1: ptr<function, u32>) -> ReuseSlot {
    var w_sum_3: f32 = 0f;
    var out: ReuseSlot = ReuseSlot(0u, 0u, 0f);
    var out_target: f32 = 0f;
    var j_6: u32;
    var s_11: ReuseSlot;
    var local_53: bool;
    var local_54: bool;
    var local_55: bool;
    var w_in: f32;
    var local_56: bool;
    var own_1: f32;
    var all_1: f32;
    var k_6: u32;
    var t_5: f32;
    var local_57: bool;
    var local_58: bool;

    j_6 = k0_;
    loop {
        let _e22 = j_6;
        if (_e22 <= k1_) {
        } else {
            break;
        }
        {
            s_11 = cur;
            let _e25 = j_6;
            if (_e25 > k0_) {
                let _e28 = j_6;
                let _e33 = (*doms_2)[(_e28 - 1u)].pixel;
                let _e34 = previous_index(_e33);
                let _e38 = reuse_pixels[_e34].slots[q_8];
                s_11 = _e38;
            }
            let _e40 = s_11.w;
            if !(!((_e40 > 0f))) {
                let _e48 = s_11.light;
                local_53 = (_e48 >= arrayLength((&lights)));
            } else {
                local_53 = true;
            }
            let _e53 = local_53;
            if _e53 {
                continue;
            }
            let _e54 = j_6;
            if (_e54 > k0_) {
                let _e60 = reuse.visibility;
                local_54 = (_e60 == 1u);
            } else {
                local_54 = false;
            }
            let _e64 = local_54;
            if _e64 {
                let _e68 = s_11.light;
                let _e70 = s_11.u;
                let _e71 = j_6;
                let _e75 = (*doms_2)[(_e71 - 1u)];
                let _e76 = history_vouches(_e68, _e70, _e75);
                local_55 = !(_e76);
            } else {
                local_55 = false;
            }
            let _e79 = local_55;
            if _e79 {
                continue;
            }
            let _e82 = s_11.light;
            let _e84 = lights[_e82];
            let _e86 = s_11.u;
            let _e87 = reuse_target(q_8, _e84, _e86, x_17, n_16, m_5);
            if !((_e87 > 0f)) {
                continue;
            }
            let _e92 = s_11.w;
            w_in = _e92;
            let _e94 = j_6;
            if (_e94 == k0_) {
                local_56 = cur_ris;
            } else {
                local_56 = false;
            }
            let _e99 = local_56;
            if _e99 {
                let _e101 = s_11.w;
                w_in = (_e101 / _e87);
            }
            own_1 = (cur_c * _e87);
            let _e105 = own_1;
            all_1 = _e105;
            let _e109 = s_11.light;
            let _e111 = lights[_e109];
            let _e113 = s_11.u;
            let _e114 = grid_coordinate(_e113);
            let _e116 = s_11.u;
            let _e119 = grid_coordinate((_e116 << 16u));
            let _e120 = light_point(_e111, _e114, _e119);
            k_6 = k0_;
            loop {
                let _e122 = k_6;
                if (_e122 < k1_) {
                } else {
                    break;
                }
                {
                    t_5 = 0f;
                    let _e126 = j_6;
                    if !((_e126 > k0_)) {
                        local_57 = cur_reached;
                    } else {
                        local_57 = true;
                    }
                    let _e132 = local_57;
                    if _e132 {
                        let _e133 = k_6;
                        let d_10 = (*doms_2)[_e133];
                        let _e140 = reuse_trust((_e120 - x_17), (_e120 - d_10.x));
                        let _e144 = s_11.light;
                        let _e146 = lights_prev[_e144];
                        let _e148 = s_11.u;
                        let _e152 = reuse_target(q_8, _e146, _e148, d_10.x, d_10.n, d_10.m);
                        t_5 = ((d_10.c * _e140) * _e152);
                    }
                    let _e154 = all_1;
                    let _e155 = t_5;
                    all_1 = (_e154 + _e155);
                    let _e157 = k_6;
                    let _e160 = j_6;
                    if ((_e157 + 1u) == _e160) {
                        let _e162 = t_5;
                        own_1 = _e162;
                    }
                }
                continuing {
                    let _e164 = k_6;
                    k_6 = (_e164 + 1u);
                }
            }
            let _e166 = own_1;
            let _e167 = all_1;
            let _e168 = w_in;
            let _e169 = gris_weight(_e166, _e167, _e87, _e168);
            let _e170 = w_sum_3;
            w_sum_3 = (_e170 + _e169);
            let _e172 = (*hs_1);
            let _e173 = pcg_hash(_e172);
            (*hs_1) = _e173;
            if (_e169 > 0f) {
                let _e178 = w_sum_3;
                let _e179 = (*hs_1);
                let _e180 = xi_from_bits(_e179);
                let _e181 = weighted_replace(_e169, _e178, _e180);
                local_58 = _e181;
            } else {
                local_58 = false;
            }
            let _e183 = local_58;
            if _e183 {
                let _e184 = s_11;
                out = _e184;
                out_target = _e87;
            }
        }
        continuing {
            let _e186 = j_6;
            j_6 = (_e186 + 1u);
        }
    }
    let _e189 = w_sum_3;
    let _e190 = out_target;
    let _e191 = gris_contribution_weight(_e189, _e190);
    out.w = _e191;
    let _e192 = out;
    return _e192;
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
    var slot_cells: array<u32, 8>;
    var total: vec3<f32> = vec3(0f);
    var count: u32 = 0u;
    var hc: u32;
    var threshold: array<f32, 8>;
    var start: u32 = 0u;
    var j: u32;
    var local_4: bool;
    var q: u32;
    var local_5: bool;
    var doms: array<Domain, 3>;
    var local_6: bool;
    var hs: u32;
    var fresh_keys: array<vec2<u32>, 8>;
    var fresh_held: array<bool, 8>;
    var q_1: u32 = 0u;
    var local_7: bool;
    var fresh_visible: array<bool, 8>;
    var q_2: u32 = 0u;
    var fresh_before: array<bool, 8>;
    var q_3: u32 = 0u;
    var local_8: bool;
    var local_9: bool;
    var kept: array<ReuseSlot, 8>;
    var fin: array<ReuseSlot, 8>;
    var q_4: u32 = 0u;
    var local_10: bool;
    var local_11: bool;
    var keys: array<vec2<u32>, 8>;
    var held: array<bool, 8>;
    var k: u32 = 0u;
    var visible: array<bool, 8>;
    var k_1: u32 = 0u;
    var w: vec3<f32>;
    var j_1: u32;
    var known: bool;
    var seen: bool;
    var j_2: u32;
    var local_12: bool;
    var local_13: bool;
    var shaded: Shaded;
    var local_14: bool;
    var j_3: u32;
    var q_5: u32 = 0u;
    var local_15: bool;

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
    let x_20 = _e35.xyz;
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
        local_3 = all((abs(x_20) <= vec3(340282350000000000000000000000000000000f)));
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
        let _e93 = material_of(_e83.xyz, mr.z, mr.y, mr.w, normalize((_e90 - x_20)));
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
    let eps_5 = (_e117 * length((_e120 - x_20)));
    let _e126 = view.seed;
    let _e130 = view.width;
    let _e136 = view.frame;
    let _e137 = point_stream(_e126, ((gid.y * _e130) + gid.x), _e136);
    let _e138 = pick_stream(_e137);
    h = _e138;
    hc = _e137;
    let _e160 = tile_walk_begin(lid, x_20, _e114.w, has_3);
    loop {
        let _e163 = start;
        if (_e163 < _e160.total) {
        } else {
            break;
        }
        {
            let _e166 = start;
            let _e167 = tile_walk_fill(lid, _e160, _e166);
            j = 0u;
            loop {
                let _e170 = j;
                if (_e170 < _e167) {
                } else {
                    break;
                }
                {
                    let _e173 = j;
                    let b_10 = tile_list[_e173];
                    if !(!(has_3)) {
                        let _e182 = bsh_nodes[b_10];
                        let _e183 = r;
                        let _e184 = bsh_reaches(_e182, x_20, _e183, _e114);
                        local_4 = !(_e184);
                    } else {
                        local_4 = true;
                    }
                    let _e187 = local_4;
                    if _e187 {
                        continue;
                    }
                    let li_10 = bsh_nodes[b_10].light;
                    let _e192 = count;
                    count = (_e192 + 1u);
                    let _e195 = h;
                    let _e196 = pcg_hash(_e195);
                    h = _e196;
                    let h1_1 = h;
                    let _e198 = h;
                    let _e199 = pcg_hash(_e198);
                    h = _e199;
                    let _e200 = h;
                    let _e201 = grid_cells(h1_1, _e200);
                    let _e202 = grid_coordinate(h1_1);
                    let _e203 = h;
                    let _e204 = grid_coordinate(_e203);
                    let u_5 = vec2<f32>(_e202, _e204);
                    let _e206 = n;
                    let _e207 = r;
                    let _e208 = m;
                    let _e213 = shade_pick_traced(li_10, x_20, _e206, _e207, _e114, _e208, 1f, u_5.x, u_5.y, eps_5, false);
                    let _e214 = output_of(_e213);
                    let _e215 = resample_target(_e214);
                    if (_e215 > 0f) {
                        let _e218 = total;
                        total = (_e218 + _e214);
                        q = 0u;
                        loop {
                            let _e222 = q;
                            if (_e222 < K) {
                            } else {
                                break;
                            }
                            {
                                let _e225 = q;
                                let _e227 = slot_target(_e214, _e225, K);
                                let _e228 = total;
                                let _e229 = q;
                                let _e231 = slot_target(_e228, _e229, K);
                                if (_e227 > 0f) {
                                    let _e236 = q;
                                    let _e238 = threshold[_e236];
                                    local_5 = (_e231 > _e238);
                                } else {
                                    local_5 = false;
                                }
                                let _e241 = local_5;
                                if _e241 {
                                    let _e242 = q;
                                    slot_light[_e242] = li_10;
                                    let _e244 = q;
                                    slot_u[_e244] = u_5;
                                    let _e246 = q;
                                    slot_p[_e246] = _e227;
                                    let _e248 = q;
                                    slot_cells[_e248] = _e201;
                                    let _e250 = q;
                                    let _e252 = next_threshold(_e231, (&hc));
                                    threshold[_e250] = _e252;
                                }
                            }
                            continuing {
                                let _e254 = q;
                                q = (_e254 + 1u);
                            }
                        }
                    }
                }
                continuing {
                    let _e257 = j;
                    j = (_e257 + 1u);
                }
            }
            workgroupBarrier();
        }
        continuing {
            let _e259 = start;
            start = (_e259 + TILE_LIST);
        }
    }
    if !(has_3) {
        if inside {
            textureStore(out_tex, texel_1, vec4(0f));
            let _e270 = view.width;
            let _e274 = next_index(((gid.y * _e270) + gid.x));
            reuse_pixels[_e274].surface.m = 0f;
        }
        return;
    }
    let _e282 = view.width;
    let pixel_1 = ((gid.y * _e282) + gid.x);
    let _e287 = n;
    let _e290 = view.eye;
    let _e294 = reuse_stream(_e137, 0u);
    let _e295 = reuse_domains(x_20, _e287, length((_e290 - x_20)), _e294, (&doms));
    if (_e295 > 0u) {
        let _e302 = doms[0].temporal;
        local_6 = _e302;
    } else {
        local_6 = false;
    }
    let own_history = local_6;
    let first_1 = select(0u, 1u, own_history);
    let _e310 = doms[0].c;
    let confidence = (1f + select(0f, _e310, own_history));
    let _e316 = reuse_stream(_e137, 1u);
    hs = _e316;
    loop {
        let _e322 = q_1;
        if (_e322 < K) {
        } else {
            break;
        }
        {
            let _e325 = q_1;
            let _e327 = q_1;
            let _e329 = slot_light[_e327];
            let _e330 = q_1;
            let _e332 = slot_cells[_e330];
            let _e333 = sample_key(_e329, _e332);
            fresh_keys[_e325] = _e333;
            let _e334 = q_1;
            let _e338 = reuse.visibility;
            if (_e338 == 1u) {
                let _e343 = q_1;
                let _e345 = slot_p[_e343];
                local_7 = (_e345 > 0f);
            } else {
                local_7 = false;
            }
            let _e349 = local_7;
            fresh_held[_e334] = _e349;
        }
        continuing {
            let _e351 = q_1;
            q_1 = (_e351 + 1u);
        }
    }
    let _e353 = fresh_keys;
    let _e354 = fresh_held;
    let _e355 = first_holders(_e353, _e354);
    loop {
        let _e359 = q_2;
        if (_e359 < K) {
        } else {
            break;
        }
        {
            let _e362 = q_2;
            let _e364 = q_2;
            if (_e355[_e362] == _e364) {
                let _e366 = q_2;
                let _e369 = q_2;
                let _e371 = slot_light[_e369];
                let _e373 = lights[_e371];
                let _e374 = q_2;
                let _e376 = slot_cells[_e374];
                let _e377 = n;
                let _e378 = sample_reaches(_e373, _e376, x_20, _e377, eps_5);
                fresh_visible[_e366] = _e378;
            } else {
                let _e379 = q_2;
                if (_e355[_e379] < K) {
                    let _e383 = q_2;
                    let _e385 = q_2;
                    let _e388 = fresh_visible[_e355[_e385]];
                    fresh_visible[_e383] = _e388;
                }
            }
        }
        continuing {
            let _e390 = q_2;
            q_2 = (_e390 + 1u);
        }
    }
    loop {
        let _e395 = q_3;
        if (_e395 < K) {
        } else {
            break;
        }
        {
            let _e398 = q_3;
            fresh_before[_e398] = true;
            let _e401 = q_3;
            let _e403 = q_3;
            if (_e355[_e401] == _e403) {
                let _e407 = q_3;
                let _e409 = fresh_visible[_e407];
                local_8 = _e409;
            } else {
                local_8 = false;
            }
            let _e411 = local_8;
            if _e411 {
                local_9 = own_history;
            } else {
                local_9 = false;
            }
            let _e415 = local_9;
            if _e415 {
                let _e416 = q_3;
                let _e418 = q_3;
                let _e420 = slot_light[_e418];
                let _e421 = q_3;
                let _e423 = slot_cells[_e421];
                let _e425 = doms[0];
                let _e426 = n;
                let _e427 = reached_before(_e420, _e423, _e425, x_20, _e426);
                fresh_before[_e416] = _e427;
            } else {
                let _e428 = q_3;
                if (_e355[_e428] < K) {
                    let _e432 = q_3;
                    let _e434 = q_3;
                    let _e437 = fresh_before[_e355[_e434]];
                    fresh_before[_e432] = _e437;
                }
            }
        }
        continuing {
            let _e439 = q_3;
            q_3 = (_e439 + 1u);
        }
    }
    loop {
        let _e445 = q_4;
        if (_e445 < K) {
        } else {
            break;
        }
        {
            let _e448 = q_4;
            let _e450 = slot_p[_e448];
            if (_e450 > 0f) {
                let _e457 = reuse.visibility;
                if !((_e457 == 0u)) {
                    let _e463 = q_4;
                    let _e465 = fresh_visible[_e463];
                    local_11 = _e465;
                } else {
                    local_11 = true;
                }
                let _e467 = local_11;
                local_10 = _e467;
            } else {
                local_10 = false;
            }
            let fresh = local_10;
            let _e470 = q_4;
            let _e472 = q_4;
            let _e473 = q_4;
            let _e475 = slot_light[_e473];
            let _e476 = q_4;
            let _e478 = slot_cells[_e476];
            let _e479 = total;
            let _e480 = q_4;
            let _e482 = slot_target(_e479, _e480, K);
            let _e488 = q_4;
            let _e490 = fresh_before[_e488];
            let _e492 = n;
            let _e493 = m;
            let _e494 = gris_combine(_e472, ReuseSlot(_e475, _e478, select(0f, _e482, fresh)), true, 1f, _e490, 0u, first_1, x_20, _e492, _e493, (&doms), (&hs));
            kept[_e470] = _e494;
            let _e495 = q_4;
            let _e497 = q_4;
            let _e499 = kept[_e497];
            fin[_e495] = _e499;
            if (_e295 > first_1) {
                let _e501 = q_4;
                let _e503 = q_4;
                let _e504 = q_4;
                let _e506 = kept[_e504];
                let _e509 = n;
                let _e510 = m;
                let _e511 = gris_combine(_e503, _e506, false, confidence, true, first_1, _e295, x_20, _e509, _e510, (&doms), (&hs));
                fin[_e501] = _e511;
            }
        }
        continuing {
            let _e513 = q_4;
            q_4 = (_e513 + 1u);
        }
    }
    loop {
        let _e519 = k;
        if (_e519 < K) {
        } else {
            break;
        }
        {
            let _e522 = k;
            let _e524 = k;
            let _e527 = fin[_e524].light;
            let _e528 = k;
            let _e531 = fin[_e528].u;
            let _e532 = sample_key(_e527, _e531);
            keys[_e522] = _e532;
            let _e533 = k;
            let _e535 = k;
            let _e538 = fin[_e535].w;
            held[_e533] = (_e538 > 0f);
        }
        continuing {
            let _e542 = k;
            k = (_e542 + 1u);
        }
    }
    let _e544 = keys;
    let _e545 = held;
    let _e546 = first_holders(_e544, _e545);
    loop {
        let _e550 = k_1;
        if (_e550 < K) {
        } else {
            break;
        }
        {
            let _e553 = k_1;
            let _e555 = k_1;
            if (_e546[_e553] != _e555) {
                continue;
            }
            w = vec3(0f);
            let _e560 = k_1;
            j_1 = _e560;
            loop {
                let _e562 = j_1;
                if (_e562 < K) {
                } else {
                    break;
                }
                {
                    let _e565 = j_1;
                    let _e567 = k_1;
                    if (_e546[_e565] == _e567) {
                        let _e569 = w;
                        let _e570 = j_1;
                        let _e573 = fin[_e570].w;
                        let _e574 = j_1;
                        let _e576 = slot_share(_e574, K);
                        w = (_e569 + (_e573 * _e576));
                    }
                }
                continuing {
                    let _e580 = j_1;
                    j_1 = (_e580 + 1u);
                }
            }
            known = false;
            seen = false;
            j_2 = 0u;
            loop {
                let _e588 = j_2;
                if (_e588 < K) {
                    let _e593 = known;
                    local_12 = !(_e593);
                } else {
                    local_12 = false;
                }
                let _e596 = local_12;
                if _e596 {
                } else {
                    break;
                }
                {
                    let _e597 = j_2;
                    let _e599 = fresh_held[_e597];
                    if _e599 {
                        let _e602 = j_2;
                        let _e604 = fresh_keys[_e602];
                        let _e605 = k_1;
                        let _e607 = keys[_e605];
                        local_13 = all((_e604 == _e607));
                    } else {
                        local_13 = false;
                    }
                    let _e611 = local_13;
                    if _e611 {
                        known = true;
                        let _e613 = j_2;
                        let _e615 = fresh_visible[_e613];
                        seen = _e615;
                    }
                }
                continuing {
                    let _e617 = j_2;
                    j_2 = (_e617 + 1u);
                }
            }
            shaded = Shaded(vec3(0f), vec3(0f), vec3(0f));
            let _e627 = known;
            if !(!(_e627)) {
                let _e632 = seen;
                local_14 = _e632;
            } else {
                local_14 = true;
            }
            let _e634 = local_14;
            if _e634 {
                let _e636 = k_1;
                let _e639 = fin[_e636].light;
                let _e641 = lights[_e639];
                let _e642 = k_1;
                let _e645 = fin[_e642].u;
                let _e646 = n;
                let _e647 = known;
                let _e649 = sample_connection(_e641, _e645, x_20, _e646, eps_5, !(_e647));
                let _e650 = n;
                let _e651 = m;
                let _e652 = shade_connection(_e649, x_20, _e650, _e651);
                shaded = _e652;
            }
            let _e653 = t;
            let _e654 = shaded;
            let _e655 = w;
            let _e656 = scaled(_e654, _e655);
            let _e657 = add(_e653, _e656);
            t = _e657;
            let _e658 = k_1;
            j_3 = _e658;
            loop {
                let _e660 = j_3;
                if (_e660 < K) {
                } else {
                    break;
                }
                {
                    let _e663 = j_3;
                    let _e665 = k_1;
                    if (_e546[_e663] == _e665) {
                        let _e667 = j_3;
                        let _e669 = shaded;
                        let _e670 = output_of(_e669);
                        let _e671 = resample_target(_e670);
                        visible[_e667] = (_e671 > 0f);
                    }
                }
                continuing {
                    let _e675 = j_3;
                    j_3 = (_e675 + 1u);
                }
            }
        }
        continuing {
            let _e678 = k_1;
            k_1 = (_e678 + 1u);
        }
    }
    loop {
        let _e682 = q_5;
        if (_e682 < K) {
        } else {
            break;
        }
        {
            let _e687 = reuse.visibility;
            if !((_e687 == 0u)) {
                let _e693 = q_5;
                let _e695 = visible[_e693];
                local_15 = _e695;
            } else {
                local_15 = true;
            }
            let keep = local_15;
            let _e699 = next_index(pixel_1);
            let _e702 = q_5;
            let _e704 = q_5;
            let _e707 = kept[_e704].light;
            let _e708 = q_5;
            let _e711 = kept[_e708].u;
            let _e712 = q_5;
            let _e715 = kept[_e712].w;
            reuse_pixels[_e699].slots[_e702] = ReuseSlot(_e707, _e711, select(0f, _e715, keep));
        }
        continuing {
            let _e720 = q_5;
            q_5 = (_e720 + 1u);
        }
    }
    let _e723 = next_index(pixel_1);
    let _e726 = n;
    let _e727 = m;
    let _e730 = reuse.max_confidence;
    let _e732 = reuse_surface(x_20, _e726, _e727, min(confidence, _e730));
    reuse_pixels[_e723].surface = _e732;
    let _e735 = t.diffuse;
    let _e737 = t.specular;
    let _e739 = count;
    textureStore(out_tex, texel_1, vec4<f32>((_e735 + _e737), f32(_e739)));
    return;
}
