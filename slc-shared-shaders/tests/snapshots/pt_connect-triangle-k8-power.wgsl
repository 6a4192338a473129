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
    material: u32,
    weight: vec3<f32>,
    pad1_: f32,
    gnormal: vec3<f32>,
    pad2_: f32,
    wo: vec3<f32>,
    pad3_: f32,
}

struct GpuMaterial {
    albedo: vec3<f32>,
    metallic: f32,
    emission: vec3<f32>,
    alpha: f32,
    f0_: vec3<f32>,
    f90_: f32,
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
    extent: f32,
}

struct GeoHit {
    t: f32,
    tri: u32,
}

struct Picks {
    light: array<u32, 8>,
    n: u32,
}

struct BshCursor {
    i: u32,
    end: u32,
    next: u32,
    cone: vec2<f32>,
}

struct Connection {
    e: vec3<f32>,
    y: vec3<f32>,
    cos_x: f32,
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
const BVH: u32 = 0u;

@group(0) @binding(6) 
var<storage> geo_nodes: array<GpuGeoNode>;
@group(0) @binding(7) 
var<storage> geo_tris: array<GpuTriangle>;
@group(0) @binding(5) 
var<storage> bsh_nodes: array<BshNode>;
@group(0) @binding(2) 
var<storage> lights: array<GpuLight>;
@group(0) @binding(4) 
var<storage> r2_3: array<f32>;
@group(0) @binding(3) 
var<storage> rt2_5: array<f32>;
@group(1) @binding(2) 
var<storage> light_cones: array<GpuLightCone>;
@group(0) @binding(0) 
var<uniform> params: ShadeParams;
@group(0) @binding(1) 
var<storage> vertices: array<GpuPathVertex>;
@group(0) @binding(8) 
var<storage> materials: array<GpuMaterial>;
@group(0) @binding(9) 
var<storage, read_write> radiance: array<vec4<f32>>;
@group(0) @binding(10) 
var<storage, read_write> candidates: array<u32>;

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

fn slc_keep(r2_: f32, d2_2: f32) -> bool {
    return (d2_2 < r2_);
}

fn sphere_contains_point(c: vec3<f32>, r: f32, x_1: vec3<f32>) -> bool {
    let v_8 = (x_1 - c);
    return (dot(v_8, v_8) <= (r * r));
}

fn inverse_square(d2_3: f32) -> f32 {
    return (1f / max(d2_3, MIN_D2_));
}

fn connection_factor(cos_x: f32, d2_4: f32, rt2_2: f32, w: f32) -> f32 {
    let _e4 = inverse_square(d2_4);
    let _e6 = slc_weight(rt2_2, d2_4);
    return (((cos_x * _e4) * _e6) * w);
}

fn connection_cosine(x_2: vec3<f32>, y: vec3<f32>, n: vec3<f32>, ng: vec3<f32>, r2_1: f32) -> f32 {
    var local: bool;
    var local_1: bool;

    let v_9 = (x_2 - y);
    let d2_9 = dot(v_9, v_9);
    let _e7 = slc_keep(r2_1, d2_9);
    if !(!(_e7)) {
        local = !((d2_9 > 0f));
    } else {
        local = true;
    }
    let _e16 = local;
    if _e16 {
        return 0f;
    }
    let w_6 = (v_9 / vec3(sqrt(d2_9)));
    let cos_x_1 = -(dot(n, w_6));
    if !(!((cos_x_1 > 0f))) {
        local_1 = !((dot(ng, w_6) < 0f));
    } else {
        local_1 = true;
    }
    let _e34 = local_1;
    if _e34 {
        return 0f;
    }
    return cos_x_1;
}

fn triangle_lobe(n_1: vec3<f32>, area: f32, w_1: vec3<f32>) -> f32 {
    return (area * max(dot(n_1, w_1), 0f));
}

fn triangle_sample(a_2: vec3<f32>, b_2: vec3<f32>, c_1: vec3<f32>, u1_: f32, u2_: f32) -> vec3<f32> {
    let su = sqrt(u1_);
    let b0_ = (1f - su);
    let b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_1 * ((1f - b0_) - b1_)));
}

fn area_to_solid_angle_pdf(pdf_area: f32, d2_5: f32, cos_light: f32) -> f32 {
    let c_8 = abs(cos_light);
    if (c_8 <= 0f) {
        return 0f;
    }
    return ((pdf_area * d2_5) / c_8);
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

fn mul_hi_u32_(a_3: u32, b_3: u32) -> u32 {
    let a_lo = (a_3 & 65535u);
    let a_hi = (a_3 >> 16u);
    let b_lo = (b_3 & 65535u);
    let b_hi = (b_3 >> 16u);
    let ll = (a_lo * b_lo);
    let lh = (a_lo * b_hi);
    let hl = (a_hi * b_lo);
    let hh = (a_hi * b_hi);
    let mid = (((ll >> 16u) + (lh & 65535u)) + (hl & 65535u));
    return (((hh + (lh >> 16u)) + (hl >> 16u)) + (mid >> 16u));
}

fn uniform_index(n_2: u32, hi: u32, lo: u32) -> u32 {
    let _e3 = mul_lo_u32_(hi, n_2);
    let _e4 = mul_hi_u32_(hi, n_2);
    let _e5 = mul_hi_u32_(lo, n_2);
    if (_e3 > (4294967295u - _e5)) {
        return (_e4 + 1u);
    }
    return _e4;
}

fn reservoir_slot(n_3: u32, k: u32, hi_1: u32, lo_1: u32) -> u32 {
    if (n_3 <= k) {
        return (n_3 - 1u);
    }
    let _e7 = uniform_index(n_3, hi_1, lo_1);
    if (_e7 < k) {
        return _e7;
    }
    return k;
}

fn reservoir_takes(n_4: u32) -> bool {
    return (n_4 < RESERVOIR_FULL);
}

fn reservoir_weight(n_5: u32, k_1: u32) -> f32 {
    let _e2 = to_f32_(n_5);
    let _e3 = to_f32_(k_1);
    return max((_e2 / _e3), 1f);
}

fn reservoir_select_pdf(seen: u32, in_range: bool, k_2: u32) -> f32 {
    var others: u32;
    var local_2: bool;

    others = seen;
    if in_range {
        local_2 = (seen > 0u);
    } else {
        local_2 = false;
    }
    let _e9 = local_2;
    if _e9 {
        others = (seen - 1u);
    }
    let _e12 = others;
    let _e15 = reservoir_weight((_e12 + 1u), k_2);
    return (1f / _e15);
}

fn mis_power(pdf_a: f32, pdf_b: f32) -> f32 {
    let a2_ = (pdf_a * pdf_a);
    let s_3 = (a2_ + (pdf_b * pdf_b));
    if (s_3 <= 0f) {
        return 0f;
    }
    return (a2_ / s_3);
}

fn light_strategy_pdf(select_: f32, rt2_3: f32, d2_6: f32, area_1: f32, cos_y: f32) -> f32 {
    var local_3: bool;
    var local_4: bool;

    if !((d2_6 <= 0f)) {
        local_3 = (area_1 <= 0f);
    } else {
        local_3 = true;
    }
    let _e13 = local_3;
    if !(_e13) {
        local_4 = (cos_y <= 0f);
    } else {
        local_4 = true;
    }
    let _e20 = local_4;
    if _e20 {
        return 0f;
    }
    let _e22 = rr_probability(rt2_3, d2_6);
    let _e26 = area_to_solid_angle_pdf((1f / area_1), d2_6, cos_y);
    return ((select_ * _e22) * _e26);
}

fn cosine_pdf(cos_theta: f32) -> f32 {
    return (max(cos_theta, 0f) * INV_PI);
}

fn onb_tangent(n_6: vec3<f32>) -> vec3<f32> {
    let s_4 = select(-1f, 1f, (n_6.z >= 0f));
    let a_9 = (-1f / (s_4 + n_6.z));
    return vec3<f32>((1f + (((s_4 * n_6.x) * n_6.x) * a_9)), (((s_4 * n_6.x) * n_6.y) * a_9), (-(s_4) * n_6.x));
}

fn onb_bitangent(n_7: vec3<f32>) -> vec3<f32> {
    let s_5 = select(-1f, 1f, (n_7.z >= 0f));
    let a_10 = (-1f / (s_5 + n_7.z));
    return vec3<f32>(((n_7.x * n_7.y) * a_10), (s_5 + ((n_7.y * n_7.y) * a_10)), -(n_7.y));
}

fn onb_to_local(n_8: vec3<f32>, w_3: vec3<f32>) -> vec3<f32> {
    let _e2 = onb_tangent(n_8);
    let _e4 = onb_bitangent(n_8);
    return vec3<f32>(dot(w_3, _e2), dot(w_3, _e4), dot(w_3, n_8));
}

fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
    if (cos_h <= 0f) {
        return 0f;
    }
    let a2_1 = (alpha * alpha);
    let t = (((cos_h * cos_h) * a2_1) + sin2_h);
    return ((a2_1 * INV_PI) / (t * t));
}

fn smith_root(cos_: f32, alpha_1: f32) -> f32 {
    let a2_2 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1f - a2_2)) + a2_2));
}

fn smith_visibility(n_l: f32, n_v: f32, alpha_2: f32) -> f32 {
    var local_5: bool;

    if !((n_l <= 0f)) {
        local_5 = (n_v <= 0f);
    } else {
        local_5 = true;
    }
    let _e11 = local_5;
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

fn diffuse_brdf(base_1: vec3<f32>, metallic_1: f32, f0_d_1: vec3<f32>, f90_d_1: f32, v_h_2: f32) -> vec3<f32> {
    let _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return ((((vec3<f32>(1f, 1f, 1f) - _e9) * base_1) * (1f - metallic_1)) * INV_PI);
}

fn half_cosine(v: vec3<f32>, l: vec3<f32>) -> f32 {
    let h_3 = (v + l);
    let len2_ = dot(h_3, h_3);
    if (len2_ <= 0f) {
        return 0f;
    }
    return saturate((dot(v, h_3) / sqrt(len2_)));
}

fn specular_brdf(base_2: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n_9: vec3<f32>, v_1: vec3<f32>, l_1: vec3<f32>) -> vec3<f32> {
    var local_6: bool;

    let n_l_1 = dot(n_9, l_1);
    let n_v_2 = dot(n_9, v_1);
    if !((n_l_1 <= 0f)) {
        local_6 = (n_v_2 <= 0f);
    } else {
        local_6 = true;
    }
    let _e18 = local_6;
    if _e18 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let hs = (v_1 + l_1);
    let inv = (1f / sqrt(dot(hs, hs)));
    let h_4 = (hs * inv);
    let c_10 = cross(n_9, h_4);
    let _e32 = ggx_d(dot(n_9, h_4), dot(c_10, c_10), alpha_3);
    let _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_1, h_4));
    let _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return (_e34 * (_e32 * _e35));
}

fn brdf_eval(base_3: vec3<f32>, metallic_3: f32, f0_d_3: vec3<f32>, f90_d_3: f32, alpha_4: f32, n_10: vec3<f32>, v_2: vec3<f32>, l_2: vec3<f32>) -> vec3<f32> {
    if (dot(n_10, l_2) <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = half_cosine(v_2, l_2);
    let _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    let _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_10, v_2, l_2);
    return (_e16 + _e17);
}

fn has_specular(metallic_4: f32, f0_d_4: vec3<f32>, f90_d_4: f32) -> bool {
    var local_7: bool;
    var local_8: bool;

    if !((metallic_4 > 0f)) {
        local_7 = (f90_d_4 > 0f);
    } else {
        local_7 = true;
    }
    let _e11 = local_7;
    if !(_e11) {
        local_8 = (max(max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0f);
    } else {
        local_8 = true;
    }
    let _e23 = local_8;
    return _e23;
}

fn channel_mean(c_2: vec3<f32>) -> f32 {
    return (((c_2.x + c_2.y) + c_2.z) * 0.33333334f);
}

fn receiver_lobe(base_4: vec3<f32>, metallic_5: f32, f0_d_5: vec3<f32>, f90_d_5: f32, alpha_5: f32, n_v_1: f32) -> vec4<f32> {
    var local_9: bool;

    let _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    let _e16 = channel_mean((((vec3<f32>(1f, 1f, 1f) - _e10) * base_4) * (1f - metallic_5)));
    if !((n_v_1 <= 0f)) {
        let _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_9 = !(_e22);
    } else {
        local_9 = true;
    }
    let _e25 = local_9;
    if _e25 {
        return vec4<f32>(_e16, 0f, alpha_5, n_v_1);
    }
    let _e28 = specular_fresnel(base_4, metallic_5, f0_d_5, f90_d_5, n_v_1);
    let _e29 = channel_mean(_e28);
    return vec4<f32>(_e16, _e29, alpha_5, n_v_1);
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

fn mirror_dir(n_11: vec3<f32>, v_3: vec3<f32>) -> vec3<f32> {
    return ((n_11 * (2f * dot(n_11, v_3))) - v_3);
}

fn bounded_vndf_k(wi: vec3<f32>, alpha_6: f32) -> f32 {
    let a_11 = saturate(alpha_6);
    let s_6 = (1f + sqrt(((wi.x * wi.x) + (wi.y * wi.y))));
    let a2_3 = (a_11 * a_11);
    let s2_ = (s_6 * s_6);
    return (((1f - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z)));
}

fn ggx_vndf_pdf(wi_1: vec3<f32>, wo: vec3<f32>, alpha_7: f32) -> f32 {
    var local_10: bool;

    if !((wi_1.z <= 0f)) {
        local_10 = (wo.z <= 0f);
    } else {
        local_10 = true;
    }
    let _e13 = local_10;
    if _e13 {
        return 0f;
    }
    let hs_1 = (wi_1 + wo);
    let m_1 = (hs_1 / vec3(sqrt(dot(hs_1, hs_1))));
    let _e28 = ggx_d(m_1.z, ((m_1.x * m_1.x) + (m_1.y * m_1.y)), alpha_7);
    let t_1 = sqrt((((alpha_7 * alpha_7) * ((wi_1.x * wi_1.x) + (wi_1.y * wi_1.y))) + (wi_1.z * wi_1.z)));
    let _e43 = bounded_vndf_k(wi_1, alpha_7);
    return (_e28 / (2f * ((_e43 * wi_1.z) + t_1)));
}

fn bsdf_pdf(n_12: vec3<f32>, v_4: vec3<f32>, l_3: vec3<f32>, alpha_8: f32, p_spec: f32) -> f32 {
    let _e6 = cosine_pdf(dot(n_12, l_3));
    if (p_spec <= 0f) {
        return _e6;
    }
    let _e9 = onb_to_local(n_12, v_4);
    let _e10 = onb_to_local(n_12, l_3);
    let _e11 = ggx_vndf_pdf(_e9, _e10, alpha_8);
    return ((p_spec * _e11) + ((1f - p_spec) * _e6));
}

fn cone_cos_of(v_5: vec3<f32>, d2_7: f32, a_4: f32, d: vec3<f32>) -> f32 {
    var local_11: bool;
    var local_12: bool;

    let vd = dot(v_5, d);
    let h2_ = (d2_7 - (a_4 * a_4));
    if !((h2_ <= 0f)) {
        if (vd >= 0f) {
            local_12 = ((vd * vd) >= h2_);
        } else {
            local_12 = false;
        }
        let _e19 = local_12;
        local_11 = _e19;
    } else {
        local_11 = true;
    }
    let _e21 = local_11;
    if _e21 {
        return 1f;
    }
    let c_11 = cross(v_5, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_11, c_11)) * a_4)) / d2_7), 1f);
}

fn cone_cos_toward(center: vec3<f32>, radius: f32, p: vec3<f32>, d_1: vec3<f32>) -> f32 {
    let v_10 = (center - p);
    let _e6 = cone_cos_of(v_10, dot(v_10, v_10), radius, d_1);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_2 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_2 * t_2))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_1: vec3<f32>, radius_1: f32, p_1: vec3<f32>, r_1: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_1, radius_1, p_1, r_1);
    let _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

fn finite3_(v_6: vec3<f32>) -> bool {
    var local_13: bool;
    var local_14: bool;

    if (abs(v_6.x) <= F32_MAX) {
        local_13 = (abs(v_6.y) <= F32_MAX);
    } else {
        local_13 = false;
    }
    let _e12 = local_13;
    if _e12 {
        local_14 = (abs(v_6.z) <= F32_MAX);
    } else {
        local_14 = false;
    }
    let _e20 = local_14;
    return _e20;
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
    let lo_2 = min(t0_, t1_);
    let hi_2 = max(t0_, t1_);
    let t_in = max(max(lo_2.x, lo_2.y), max(lo_2.z, 0f));
    let t_out = min(min(hi_2.x, hi_2.y), min(hi_2.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1f;
}

fn triangle_normal(a_5: vec3<f32>, b_4: vec3<f32>, c_3: vec3<f32>) -> vec3<f32> {
    var local_15: bool;

    let n_19 = cross((b_4 - a_5), (c_3 - a_5));
    let l2_ = dot(n_19, n_19);
    if !(!((l2_ > 0f))) {
        local_15 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_15 = true;
    }
    let _e17 = local_15;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_19 / vec3(sqrt(l2_)));
}

fn ray_triangle(o_1: vec3<f32>, d_3: vec3<f32>, a_6: vec3<f32>, b_5: vec3<f32>, c_4: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_16: bool;
    var local_17: bool;
    var local_18: bool;

    let e1_ = (b_5 - a_6);
    let e2_ = (c_4 - a_6);
    let p_2 = cross(d_3, e2_);
    let det = dot(e1_, p_2);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv_1 = (1f / det);
    let s_7 = (o_1 - a_6);
    let u_2 = (dot(s_7, p_2) * inv_1);
    if !((u_2 < 0f)) {
        local_16 = (u_2 > 1f);
    } else {
        local_16 = true;
    }
    let _e28 = local_16;
    if _e28 {
        return -1f;
    }
    let q = cross(s_7, e1_);
    let v_11 = (dot(d_3, q) * inv_1);
    if !((v_11 < 0f)) {
        local_17 = ((u_2 + v_11) > 1f);
    } else {
        local_17 = true;
    }
    let _e42 = local_17;
    if _e42 {
        return -1f;
    }
    let t_3 = (dot(e2_, q) * inv_1);
    if (t_3 > t_min) {
        local_18 = (t_3 < t_max_1);
    } else {
        local_18 = false;
    }
    let _e51 = local_18;
    if _e51 {
        return t_3;
    }
    return -1f;
}

fn light_intensity(l_4: GpuLight, w_4: vec3<f32>) -> vec3<f32> {
    switch l_4.kind {
        case 3u: {
            let _e7 = triangle_normal(l_4.p0_, l_4.p1_, l_4.p2_);
            let _e9 = triangle_lobe(_e7, l_4.a, w_4);
            return (l_4.intensity * _e9);
        }
        default: {
            return vec3(0f);
        }
    }
}

fn light_point(l_5: GpuLight, u1_1: f32, u2_1: f32) -> vec3<f32> {
    if (l_5.kind == LIGHT_TRIANGLE) {
        let _e9 = triangle_sample(l_5.p0_, l_5.p1_, l_5.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_5.p0_;
}

fn light_area(l_6: GpuLight) -> f32 {
    if (l_6.kind == LIGHT_TRIANGLE) {
        return l_6.a;
    }
    return 0f;
}

fn light_normal(l_7: GpuLight) -> vec3<f32> {
    if (l_7.kind == LIGHT_TRIANGLE) {
        let _e7 = triangle_normal(l_7.p0_, l_7.p1_, l_7.p2_);
        return _e7;
    }
    return vec3(0f);
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
        let n_20 = geo_nodes[_e21];
        let _e27 = hit.t;
        let _e28 = ray_aabb(o_2, _e14, n_20.bmin, n_20.bmax, _e27);
        if (_e28 >= 0f) {
            if (n_20.count > 0u) {
                i = n_20.first;
                loop {
                    let _e36 = i;
                    if (_e36 < (n_20.first + n_20.count)) {
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
                    stack[_e63] = (n_20.first + 1u);
                    let _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_20.first;
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

fn occluded(a_7: vec3<f32>, b_6: vec3<f32>) -> bool {
    let dv = (b_6 - a_7);
    let len_1 = length(dv);
    if (len_1 <= 0f) {
        return false;
    }
    let _e7 = shadow_margin(len_1);
    let _e12 = trace(a_7, (dv / vec3(len_1)), _e7, (len_1 - _e7), true);
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

fn bsh_inner_scale(a_8: f32, v_7: vec3<f32>, d2_8: f32, r_2: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let _e5 = cone_cos_of(v_7, d2_8, a_8, r_2);
    let _e8 = range_scale_at(rl_2, (_e5 + 0.000002f));
    return _e8;
}

fn bsh_reaches(node_4: BshNode, x_4: vec3<f32>, r_3: vec3<f32>, rl_3: vec4<f32>) -> bool {
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
    let v_12 = (x_4 - node_4.center);
    let d2_10 = dot(v_12, v_12);
    let _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_10 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        let _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_4, r_3);
        let _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        let _e42 = sphere_contains_point(node_4.center, _e41, x_4);
        return _e42;
    }
    let _e45 = bsh_inner_scale(node_4.extent, -(v_12), d2_10, r_3, rl_3);
    let s_c = (_e45 * 1.001f);
    let _e50 = bsh_range_bound(node_4);
    let reach = (node_4.extent + (sqrt(s_c) * _e50));
    if (d2_10 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_20 = (d2_10 <= (reach * reach));
    } else {
        local_20 = false;
    }
    let _e63 = local_20;
    return _e63;
}

fn bsh_next_leaf_lobe(nodes_3: u32, start: u32, x_5: vec3<f32>, r_4: vec3<f32>, rl_4: vec4<f32>) -> u32 {
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
            let _e11 = bsh_reaches(_e10, x_5, r_4, rl_4);
            if _e11 {
                if (_e10.child == BSH_NONE) {
                    if ((_e10.light & BSH_TAIL) == 0u) {
                        let _e20 = i_2;
                        return _e20;
                    }
                    i_2 = _e10.next;
                } else {
                    i_2 = _e10.child;
                }
            } else {
                i_2 = _e10.next;
            }
        }
    }
    return BSH_NONE;
}

fn bsh_cursor(x_6: vec3<f32>, r_5: vec3<f32>, rl_5: vec4<f32>) -> BshCursor {
    var c_5: BshCursor;

    c_5.i = 0u;
    c_5.end = 0u;
    let _e10 = bsh_first(BSH);
    c_5.next = _e10;
    c_5.cone = vec2(0f);
    let _e14 = c_5;
    return _e14;
}

fn bsh_cursor_next(c_6: ptr<function, BshCursor>, x_7: vec3<f32>, r_6: vec3<f32>, rl_6: vec4<f32>) -> u32 {
    let _e6 = (*c_6).next;
    let _e7 = bsh_next_leaf_lobe(BSH, _e6, x_7, r_6, rl_6);
    if (_e7 != BSH_NONE) {
        let _e14 = bsh_nodes[_e7].next;
        (*c_6).next = _e14;
    }
    return _e7;
}

fn reservoir_offer(picks: ptr<function, Picks>, h_1: ptr<function, u32>, light: u32) {
    let _e4 = (*picks).n;
    let _e5 = reservoir_takes(_e4);
    if _e5 {
        let _e7 = (*picks).n;
        (*picks).n = (_e7 + 1u);
        let _e10 = (*h_1);
        let _e11 = pcg_hash(_e10);
        (*h_1) = _e11;
        let hi_3 = (*h_1);
        let _e13 = (*h_1);
        let _e14 = pcg_hash(_e13);
        (*h_1) = _e14;
        let _e16 = (*picks).n;
        let _e18 = (*h_1);
        let _e19 = reservoir_slot(_e16, K, hi_3, _e18);
        if (_e19 < K) {
            (*picks).light[_e19] = light;
            return;
        } else {
            return;
        }
    } else {
        return;
    }
}

fn bsh_collect(x_8: vec3<f32>, r_7: vec3<f32>, rl_7: vec4<f32>, seed_1: u32) -> Picks {
    var picks_1: Picks;
    var h_2: u32;
    var cur: BshCursor;
    var i_3: u32;

    picks_1.n = 0u;
    h_2 = seed_1;
    let _e8 = bsh_cursor(x_8, r_7, rl_7);
    cur = _e8;
    let _e10 = bsh_cursor_next((&cur), x_8, r_7, rl_7);
    i_3 = _e10;
    loop {
        let _e12 = i_3;
        if (_e12 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e16 = i_3;
            let _e19 = bsh_nodes[_e16].light;
            reservoir_offer((&picks_1), (&h_2), _e19);
        }
        continuing {
            let _e20 = bsh_cursor_next((&cur), x_8, r_7, rl_7);
            i_3 = _e20;
        }
    }
    let _e21 = picks_1;
    return _e21;
}

fn connect_record(l_8: GpuLight, x_9: vec3<f32>, n_13: vec3<f32>, ng_1: vec3<f32>, r2_2: f32, rt2_4: f32, w_res: f32, u1_2: f32, u2_2: f32, eps: f32, trace_1: bool) -> Connection {
    var c_7: Connection;
    var local_21: bool;
    var local_22: bool;

    c_7.e = vec3(0f);
    let _e16 = light_point(l_8, u1_2, u2_2);
    c_7.y = _e16;
    let _e19 = c_7.y;
    let _e20 = connection_cosine(x_9, _e19, n_13, ng_1, r2_2);
    c_7.cos_x = _e20;
    let _e22 = c_7.cos_x;
    if !((_e22 <= 0f)) {
        if trace_1 {
            let _e33 = c_7.y;
            let _e34 = occluded((x_9 + (ng_1 * eps)), _e33);
            local_22 = _e34;
        } else {
            local_22 = false;
        }
        let _e36 = local_22;
        local_21 = _e36;
    } else {
        local_21 = true;
    }
    let _e38 = local_21;
    if _e38 {
        let _e39 = c_7;
        return _e39;
    }
    let _e41 = c_7.y;
    let v_13 = (x_9 - _e41);
    let d2_11 = dot(v_13, v_13);
    let _e48 = light_intensity(l_8, (v_13 / vec3(sqrt(d2_11))));
    let _e50 = c_7.cos_x;
    let _e51 = connection_factor(_e50, d2_11, rt2_4, w_res);
    c_7.e = (_e48 * _e51);
    let _e53 = c_7;
    return _e53;
}

fn connect_traced(li: u32, x_10: vec3<f32>, n_14: vec3<f32>, ng_2: vec3<f32>, s_1: f32, w_res_1: f32, u1_3: f32, u2_3: f32, eps_1: f32, trace_2: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_3[li];
    let _e19 = rt2_5[li];
    let _e21 = connect_record(_e12, x_10, n_14, ng_2, (s_1 * _e15), (s_1 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_2);
    return _e21;
}

fn connect(li_1: u32, x_11: vec3<f32>, n_15: vec3<f32>, ng_3: vec3<f32>, s_2: f32, w_res_2: f32, u1_4: f32, u2_4: f32, eps_2: f32) -> Connection {
    let _e10 = connect_traced(li_1, x_11, n_15, ng_3, s_2, w_res_2, u1_4, u2_4, eps_2, true);
    return _e10;
}

fn mis_weight(pdf_a_1: f32, pdf_b_1: f32) -> f32 {
    let _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

fn light_range_scale(li_2: u32, x_12: vec3<f32>, r_8: vec3<f32>, rl_8: vec4<f32>) -> f32 {
    let c_12 = light_cones[li_2];
    let _e9 = range_scale_toward(rl_8, c_12.center, c_12.radius, x_12, r_8);
    return _e9;
}

fn select_pdf(li_3: u32, x_13: vec3<f32>, n_16: vec3<f32>, r_9: vec3<f32>, lobe_5: vec4<f32>, rl_9: vec4<f32>, nee: u32, in_range_1: bool) -> f32 {
    let _e9 = reservoir_select_pdf(nee, in_range_1, K);
    return _e9;
}

fn light_pdf_selected(li_4: u32, x_14: vec3<f32>, r_10: vec3<f32>, rl_10: vec4<f32>, y_1: vec3<f32>, sel: f32) -> f32 {
    let l_9 = lights[li_4];
    let v_14 = (x_14 - y_1);
    let d2_12 = dot(v_14, v_14);
    let _e11 = light_normal(l_9);
    let cos_y_1 = select(0f, dot(_e11, (v_14 / vec3(sqrt(d2_12)))), (d2_12 > 0f));
    let _e20 = light_range_scale(li_4, x_14, r_10, rl_10);
    let _e23 = rt2_5[li_4];
    let _e25 = light_area(l_9);
    let _e26 = light_strategy_pdf(sel, (_e20 * _e23), d2_12, _e25, cos_y_1);
    return _e26;
}

fn light_pdf(li_5: u32, x_15: vec3<f32>, n_17: vec3<f32>, r_11: vec3<f32>, lobe_6: vec4<f32>, rl_11: vec4<f32>, y_2: vec3<f32>, nee_1: u32, in_range_2: bool) -> f32 {
    let _e9 = select_pdf(li_5, x_15, n_17, r_11, lobe_6, rl_11, nee_1, in_range_2);
    let _e10 = light_pdf_selected(li_5, x_15, r_11, rl_11, y_2, _e9);
    return _e10;
}

fn shade_pick(li_6: u32, x_16: vec3<f32>, n_18: vec3<f32>, ng_4: vec3<f32>, m: GpuMaterial, wo_1: vec3<f32>, r_12: vec3<f32>, lobe_7: vec4<f32>, rl_12: vec4<f32>, w_5: f32, nee_2: u32, u1_5: f32, u2_5: f32) -> vec3<f32> {
    var mis: f32 = 1f;

    let _e13 = light_range_scale(li_6, x_16, r_12, rl_12);
    let _e16 = params.eps;
    let _e17 = connect(li_6, x_16, n_18, ng_4, _e13, w_5, u1_5, u2_5, _e16);
    if (_e17.cos_x <= 0f) {
        return vec3(0f);
    }
    let l_10 = normalize((_e17.y - x_16));
    let _e30 = lights[li_6];
    let _e31 = light_area(_e30);
    if (_e31 > 0f) {
        let _e36 = light_pdf(li_6, x_16, n_18, r_12, lobe_7, rl_12, _e17.y, nee_2, true);
        let _e38 = specular_probability(lobe_7);
        let _e39 = bsdf_pdf(n_18, wo_1, l_10, m.alpha, _e38);
        let _e40 = mis_weight(_e36, _e39);
        mis = _e40;
    }
    let _e46 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, n_18, wo_1, l_10);
    let _e49 = mis;
    return ((_e46 * _e17.e) * _e49);
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var h: u32;
    var sum: vec3<f32> = vec3(0f);
    var s: u32 = 0u;

    let i_4 = gid.x;
    let _e4 = params.point_count;
    if (i_4 >= _e4) {
        return;
    }
    let vtx = vertices[i_4];
    if (vtx.alive == 0u) {
        candidates[i_4] = 0u;
        return;
    }
    let x_17 = vtx.position;
    let n_21 = vtx.normal;
    let ng_5 = vtx.gnormal;
    let m_2 = materials[vtx.material];
    let wo_2 = vtx.wo;
    let _e23 = mirror_dir(n_21, wo_2);
    let _e30 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, dot(n_21, wo_2));
    let _e31 = range_lobe(_e30);
    let _e34 = params.seed;
    let _e37 = params.frame;
    let _e38 = point_stream(_e34, i_4, _e37);
    let _e39 = pick_stream(_e38);
    h = _e39;
    let _e44 = bsh_collect(x_17, _e23, _e31, _e38);
    candidates[i_4] = _e44.n;
    let _e50 = reservoir_weight(_e44.n, K);
    loop {
        let _e53 = s;
        if (_e53 < min(_e44.n, K)) {
        } else {
            break;
        }
        {
            let _e58 = h;
            let _e59 = pcg_hash(_e58);
            h = _e59;
            let _e60 = h;
            let _e61 = xi_from_bits(_e60);
            let _e62 = h;
            let _e63 = pcg_hash(_e62);
            h = _e63;
            let _e64 = sum;
            let _e66 = s;
            let _e69 = h;
            let _e70 = xi_from_bits(_e69);
            let _e71 = shade_pick(_e44.light[_e66], x_17, n_21, ng_5, m_2, wo_2, _e23, _e30, _e31, _e50, _e44.n, _e61, _e70);
            sum = (_e64 + _e71);
        }
        continuing {
            let _e74 = s;
            s = (_e74 + 1u);
        }
    }
    let _e77 = sum;
    let add = (vtx.weight * _e77);
    let _e79 = finite3_(add);
    if _e79 {
        let _e82 = radiance[i_4];
        radiance[i_4] = (_e82 + vec4<f32>(add, 0f));
        return;
    } else {
        return;
    }
}
