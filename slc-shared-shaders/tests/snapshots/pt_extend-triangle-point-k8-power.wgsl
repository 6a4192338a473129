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
    prev_r: vec3<f32>,
    pad3_: u32,
    prev_lobe: vec4<f32>,
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

struct GpuMaterial {
    albedo: vec3<f32>,
    metallic: f32,
    emission: vec3<f32>,
    alpha: f32,
    f0_: vec3<f32>,
    f90_: f32,
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
const BVH: u32 = 0u;
const BSH: u32 = 0u;
const BSH_TILE_DEPTH: u32 = 8u;
const BSH_TILE_SUBTREES: u32 = 256u;

@group(0) @binding(5) 
var<storage> geo_nodes: array<GpuGeoNode>;
@group(0) @binding(6) 
var<storage> geo_tris: array<GpuTriangle>;
@group(1) @binding(2) 
var<storage> light_cones: array<GpuLightCone>;
@group(0) @binding(2) 
var<storage> rt2_2: array<f32>;
@group(0) @binding(1) 
var<storage> lights: array<GpuLight>;
@group(0) @binding(0) 
var<uniform> params: PtParams;
@group(0) @binding(3) 
var<storage> bsh_nodes: array<BshNode>;
@group(0) @binding(4) 
var<storage> light_leaf: array<u32>;
@group(0) @binding(7) 
var<storage> materials: array<GpuMaterial>;
@group(0) @binding(8) 
var<storage> geo_normals: array<vec4<f32>>;
@group(0) @binding(9) 
var<storage> candidates: array<u32>;
@group(0) @binding(10) 
var<storage, read_write> paths: array<GpuPathState>;
@group(0) @binding(11) 
var<storage, read_write> vertices: array<GpuPathVertex>;
@group(0) @binding(12) 
var<storage, read_write> radiance: array<vec4<f32>>;

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

fn path_stream(seed_1: u32, pixel: u32, pass_index: u32) -> u32 {
    let _e4 = add_wrap_u32_(pass_index, PICK_STREAM);
    let _e5 = point_stream(seed_1, pixel, _e4);
    return _e5;
}

fn rr_probability(rt2_: f32, d2_: f32) -> f32 {
    if (d2_ <= rt2_) {
        return 1f;
    }
    return (rt2_ / d2_);
}

fn sphere_contains_point(c: vec3<f32>, r: f32, x_1: vec3<f32>) -> bool {
    let v_10 = (x_1 - c);
    return (dot(v_10, v_10) <= (r * r));
}

fn area_to_solid_angle_pdf(pdf_area: f32, d2_1: f32, cos_light: f32) -> f32 {
    let c_5 = abs(cos_light);
    if (c_5 <= 0f) {
        return 0f;
    }
    return ((pdf_area * d2_1) / c_5);
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

fn bsh_reach_bound(node_2: BshNode, w_1: f32) -> f32 {
    let _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_1 * 1.001f) * _e5));
}

fn reservoir_weight(n: u32, k: u32) -> f32 {
    let _e2 = to_f32_(n);
    let _e3 = to_f32_(k);
    return max((_e2 / _e3), 1f);
}

fn reservoir_select_pdf(seen: u32, in_range: bool, k_1: u32) -> f32 {
    var others: u32;
    var local_3: bool;

    others = seen;
    if in_range {
        local_3 = (seen > 0u);
    } else {
        local_3 = false;
    }
    let _e9 = local_3;
    if _e9 {
        others = (seen - 1u);
    }
    let _e12 = others;
    let _e15 = reservoir_weight((_e12 + 1u), k_1);
    return (1f / _e15);
}

fn mis_power(pdf_a: f32, pdf_b: f32) -> f32 {
    let a2_ = (pdf_a * pdf_a);
    let s = (a2_ + (pdf_b * pdf_b));
    if (s <= 0f) {
        return 0f;
    }
    return (a2_ / s);
}

fn light_strategy_pdf(select_: f32, rt2_1: f32, d2_2: f32, area: f32, cos_y: f32) -> f32 {
    var local_4: bool;
    var local_5: bool;

    if !((d2_2 <= 0f)) {
        local_4 = (area <= 0f);
    } else {
        local_4 = true;
    }
    let _e13 = local_4;
    if !(_e13) {
        local_5 = (cos_y <= 0f);
    } else {
        local_5 = true;
    }
    let _e20 = local_5;
    if _e20 {
        return 0f;
    }
    let _e22 = rr_probability(rt2_1, d2_2);
    let _e26 = area_to_solid_angle_pdf((1f / area), d2_2, cos_y);
    return ((select_ * _e22) * _e26);
}

fn cosine_pdf(cos_theta: f32) -> f32 {
    return (max(cos_theta, 0f) * INV_PI);
}

fn onb_tangent(n_1: vec3<f32>) -> vec3<f32> {
    let s_1 = select(-1f, 1f, (n_1.z >= 0f));
    let a_7 = (-1f / (s_1 + n_1.z));
    return vec3<f32>((1f + (((s_1 * n_1.x) * n_1.x) * a_7)), (((s_1 * n_1.x) * n_1.y) * a_7), (-(s_1) * n_1.x));
}

fn onb_bitangent(n_2: vec3<f32>) -> vec3<f32> {
    let s_2 = select(-1f, 1f, (n_2.z >= 0f));
    let a_8 = (-1f / (s_2 + n_2.z));
    return vec3<f32>(((n_2.x * n_2.y) * a_8), (s_2 + ((n_2.y * n_2.y) * a_8)), -(n_2.y));
}

fn onb_to_world(n_3: vec3<f32>, d: vec3<f32>) -> vec3<f32> {
    let _e2 = onb_tangent(n_3);
    let _e5 = onb_bitangent(n_3);
    return (((_e2 * d.x) + (_e5 * d.y)) + (n_3 * d.z));
}

fn onb_to_local(n_4: vec3<f32>, w_2: vec3<f32>) -> vec3<f32> {
    let _e2 = onb_tangent(n_4);
    let _e4 = onb_bitangent(n_4);
    return vec3<f32>(dot(w_2, _e2), dot(w_2, _e4), dot(w_2, n_4));
}

fn cosine_direction(n_5: vec3<f32>, u1_: f32, u2_: f32) -> vec3<f32> {
    let r_8 = sqrt(u1_);
    let phi = (6.2831855f * u2_);
    let _e16 = onb_to_world(n_5, vec3<f32>((r_8 * cos(phi)), (r_8 * sin(phi)), sqrt(max((1f - u1_), 0f))));
    return normalize(_e16);
}

fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
    if (cos_h <= 0f) {
        return 0f;
    }
    let a2_1 = (alpha * alpha);
    let t_1 = (((cos_h * cos_h) * a2_1) + sin2_h);
    return ((a2_1 * INV_PI) / (t_1 * t_1));
}

fn smith_root(cos_: f32, alpha_1: f32) -> f32 {
    let a2_2 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1f - a2_2)) + a2_2));
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
    let c_6 = saturate((1f - v_h));
    let c2_ = (c_6 * c_6);
    return (f0_ + ((vec3<f32>(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_6)));
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

fn half_cosine(v_1: vec3<f32>, l: vec3<f32>) -> f32 {
    let h_2 = (v_1 + l);
    let len2_ = dot(h_2, h_2);
    if (len2_ <= 0f) {
        return 0f;
    }
    return saturate((dot(v_1, h_2) / sqrt(len2_)));
}

fn specular_brdf(base_2: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n_6: vec3<f32>, v_2: vec3<f32>, l_1: vec3<f32>) -> vec3<f32> {
    var local_7: bool;

    let n_l_1 = dot(n_6, l_1);
    let n_v_2 = dot(n_6, v_2);
    if !((n_l_1 <= 0f)) {
        local_7 = (n_v_2 <= 0f);
    } else {
        local_7 = true;
    }
    let _e18 = local_7;
    if _e18 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let hs = (v_2 + l_1);
    let inv = (1f / sqrt(dot(hs, hs)));
    let h_3 = (hs * inv);
    let c_7 = cross(n_6, h_3);
    let _e32 = ggx_d(dot(n_6, h_3), dot(c_7, c_7), alpha_3);
    let _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_2, h_3));
    let _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return (_e34 * (_e32 * _e35));
}

fn brdf_eval(base_3: vec3<f32>, metallic_3: f32, f0_d_3: vec3<f32>, f90_d_3: f32, alpha_4: f32, n_7: vec3<f32>, v_3: vec3<f32>, l_2: vec3<f32>) -> vec3<f32> {
    if (dot(n_7, l_2) <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = half_cosine(v_3, l_2);
    let _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    let _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_7, v_3, l_2);
    return (_e16 + _e17);
}

fn has_specular(metallic_4: f32, f0_d_4: vec3<f32>, f90_d_4: f32) -> bool {
    var local_8: bool;
    var local_9: bool;

    if !((metallic_4 > 0f)) {
        local_8 = (f90_d_4 > 0f);
    } else {
        local_8 = true;
    }
    let _e11 = local_8;
    if !(_e11) {
        local_9 = (max(max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0f);
    } else {
        local_9 = true;
    }
    let _e23 = local_9;
    return _e23;
}

fn channel_mean(c_1: vec3<f32>) -> f32 {
    return (((c_1.x + c_1.y) + c_1.z) * 0.33333334f);
}

fn receiver_lobe(base_4: vec3<f32>, metallic_5: f32, f0_d_5: vec3<f32>, f90_d_5: f32, alpha_5: f32, n_v_1: f32) -> vec4<f32> {
    var local_10: bool;

    let _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    let _e16 = channel_mean((((vec3<f32>(1f, 1f, 1f) - _e10) * base_4) * (1f - metallic_5)));
    if !((n_v_1 <= 0f)) {
        let _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_10 = !(_e22);
    } else {
        local_10 = true;
    }
    let _e25 = local_10;
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

fn mirror_dir(n_8: vec3<f32>, v_4: vec3<f32>) -> vec3<f32> {
    return ((n_8 * (2f * dot(n_8, v_4))) - v_4);
}

fn bounded_vndf_k(wi: vec3<f32>, alpha_6: f32) -> f32 {
    let a_9 = saturate(alpha_6);
    let s_3 = (1f + sqrt(((wi.x * wi.x) + (wi.y * wi.y))));
    let a2_3 = (a_9 * a_9);
    let s2_ = (s_3 * s_3);
    return (((1f - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z)));
}

fn ggx_vndf_sample(wi_1: vec3<f32>, alpha_7: f32, u1_1: f32, u2_1: f32) -> vec3<f32> {
    let wi_std = normalize(vec3<f32>((wi_1.x * alpha_7), (wi_1.y * alpha_7), wi_1.z));
    let _e12 = bounded_vndf_k(wi_1, alpha_7);
    let b_5 = select(wi_std.z, (_e12 * wi_std.z), (wi_1.z > 0f));
    let phi_1 = (6.2831855f * u1_1);
    let z = (((1f - u2_1) * (1f + b_5)) - b_5);
    let sin_t = sqrt(saturate((1f - (z * z))));
    let m_std = (wi_std + vec3<f32>((sin_t * cos(phi_1)), (sin_t * sin(phi_1)), z));
    let m = normalize(vec3<f32>((m_std.x * alpha_7), (m_std.y * alpha_7), m_std.z));
    return ((m * (2f * dot(wi_1, m))) - wi_1);
}

fn ggx_vndf_pdf(wi_2: vec3<f32>, wo: vec3<f32>, alpha_8: f32) -> f32 {
    var local_11: bool;

    if !((wi_2.z <= 0f)) {
        local_11 = (wo.z <= 0f);
    } else {
        local_11 = true;
    }
    let _e13 = local_11;
    if _e13 {
        return 0f;
    }
    let hs_1 = (wi_2 + wo);
    let m_1 = (hs_1 / vec3(sqrt(dot(hs_1, hs_1))));
    let _e28 = ggx_d(m_1.z, ((m_1.x * m_1.x) + (m_1.y * m_1.y)), alpha_8);
    let t_2 = sqrt((((alpha_8 * alpha_8) * ((wi_2.x * wi_2.x) + (wi_2.y * wi_2.y))) + (wi_2.z * wi_2.z)));
    let _e43 = bounded_vndf_k(wi_2, alpha_8);
    return (_e28 / (2f * ((_e43 * wi_2.z) + t_2)));
}

fn bsdf_sample(n_9: vec3<f32>, v_5: vec3<f32>, alpha_9: f32, p_spec: f32, u1_2: f32, u2_2: f32) -> vec3<f32> {
    if (u1_2 < p_spec) {
        if (dot(n_9, v_5) <= 0f) {
            return -(n_9);
        }
        let _e11 = onb_to_local(n_9, v_5);
        let _e13 = ggx_vndf_sample(_e11, alpha_9, (u1_2 / p_spec), u2_2);
        let _e14 = onb_to_world(n_9, _e13);
        return normalize(_e14);
    }
    let _e20 = cosine_direction(n_9, ((u1_2 - p_spec) / (1f - p_spec)), u2_2);
    return _e20;
}

fn bsdf_pdf(n_10: vec3<f32>, v_6: vec3<f32>, l_3: vec3<f32>, alpha_10: f32, p_spec_1: f32) -> f32 {
    let _e6 = cosine_pdf(dot(n_10, l_3));
    if (p_spec_1 <= 0f) {
        return _e6;
    }
    let _e9 = onb_to_local(n_10, v_6);
    let _e10 = onb_to_local(n_10, l_3);
    let _e11 = ggx_vndf_pdf(_e9, _e10, alpha_10);
    return ((p_spec_1 * _e11) + ((1f - p_spec_1) * _e6));
}

fn cone_cos_of(v_7: vec3<f32>, d2_3: f32, a_2: f32, d_1: vec3<f32>) -> f32 {
    var local_12: bool;
    var local_13: bool;

    let vd = dot(v_7, d_1);
    let h2_ = (d2_3 - (a_2 * a_2));
    if !((h2_ <= 0f)) {
        if (vd >= 0f) {
            local_13 = ((vd * vd) >= h2_);
        } else {
            local_13 = false;
        }
        let _e19 = local_13;
        local_12 = _e19;
    } else {
        local_12 = true;
    }
    let _e21 = local_12;
    if _e21 {
        return 1f;
    }
    let c_8 = cross(v_7, d_1);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_8, c_8)) * a_2)) / d2_3), 1f);
}

fn cone_cos_toward(center: vec3<f32>, radius: f32, p: vec3<f32>, d_2: vec3<f32>) -> f32 {
    let v_11 = (center - p);
    let _e6 = cone_cos_of(v_11, dot(v_11, v_11), radius, d_2);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_3 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_3 * t_3))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_1: vec3<f32>, radius_1: f32, p_1: vec3<f32>, r_1: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_1, radius_1, p_1, r_1);
    let _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

fn finite3_(v_8: vec3<f32>) -> bool {
    var local_14: bool;
    var local_15: bool;

    if (abs(v_8.x) <= F32_MAX) {
        local_14 = (abs(v_8.y) <= F32_MAX);
    } else {
        local_14 = false;
    }
    let _e12 = local_14;
    if _e12 {
        local_15 = (abs(v_8.z) <= F32_MAX);
    } else {
        local_15 = false;
    }
    let _e20 = local_15;
    return _e20;
}

fn ray_inverse(x_2: f32) -> f32 {
    return (1f / select(x_2, 0.000000000000000000000000000001f, (abs(x_2) < 0.000000000000000000000000000001f)));
}

fn ray_inverse3_(d_3: vec3<f32>) -> vec3<f32> {
    let _e2 = ray_inverse(d_3.x);
    let _e4 = ray_inverse(d_3.y);
    let _e6 = ray_inverse(d_3.z);
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

fn triangle_normal(a_3: vec3<f32>, b_2: vec3<f32>, c_2: vec3<f32>) -> vec3<f32> {
    var local_16: bool;

    let n_15 = cross((b_2 - a_3), (c_2 - a_3));
    let l2_ = dot(n_15, n_15);
    if !(!((l2_ > 0f))) {
        local_16 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_16 = true;
    }
    let _e17 = local_16;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_15 / vec3(sqrt(l2_)));
}

fn face_against(n_11: vec3<f32>, dir: vec3<f32>) -> vec3<f32> {
    return select(n_11, -(n_11), (dot(n_11, dir) > 0f));
}

fn barycentric(p_2: vec3<f32>, a_4: vec3<f32>, b_3: vec3<f32>, c_3: vec3<f32>) -> vec3<f32> {
    let e1_ = (b_3 - a_4);
    let e2_ = (c_3 - a_4);
    let q = (p_2 - a_4);
    let d11_ = dot(e1_, e1_);
    let d12_ = dot(e1_, e2_);
    let d22_ = dot(e2_, e2_);
    let den = ((d11_ * d22_) - (d12_ * d12_));
    if !((abs(den) > 0f)) {
        return vec3<f32>(1f, 0f, 0f);
    }
    let w1_ = (((d22_ * dot(q, e1_)) - (d12_ * dot(q, e2_))) / den);
    let w2_ = (((d11_ * dot(q, e2_)) - (d12_ * dot(q, e1_))) / den);
    return vec3<f32>(((1f - w1_) - w2_), w1_, w2_);
}

fn shading_normal(n0_: vec3<f32>, n1_: vec3<f32>, n2_: vec3<f32>, w_3: vec3<f32>, facing: vec3<f32>) -> vec3<f32> {
    var local_17: bool;

    let s_4 = (((n0_ * w_3.x) + (n1_ * w_3.y)) + (n2_ * w_3.z));
    let l2_1 = dot(s_4, s_4);
    if !(!((l2_1 > 0.000000000001f))) {
        local_17 = !((l2_1 < 300000000000000000000000000000000000000f));
    } else {
        local_17 = true;
    }
    let _e24 = local_17;
    if _e24 {
        return facing;
    }
    let n_16 = (s_4 / vec3(sqrt(l2_1)));
    return select(n_16, -(n_16), (dot(n_16, facing) < 0f));
}

fn ray_triangle(o_1: vec3<f32>, d_4: vec3<f32>, a_5: vec3<f32>, b_4: vec3<f32>, c_4: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_18: bool;
    var local_19: bool;
    var local_20: bool;

    let e1_1 = (b_4 - a_5);
    let e2_1 = (c_4 - a_5);
    let p_3 = cross(d_4, e2_1);
    let det = dot(e1_1, p_3);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv_1 = (1f / det);
    let s_5 = (o_1 - a_5);
    let u_3 = (dot(s_5, p_3) * inv_1);
    if !((u_3 < 0f)) {
        local_18 = (u_3 > 1f);
    } else {
        local_18 = true;
    }
    let _e28 = local_18;
    if _e28 {
        return -1f;
    }
    let q_1 = cross(s_5, e1_1);
    let v_12 = (dot(d_4, q_1) * inv_1);
    if !((v_12 < 0f)) {
        local_19 = ((u_3 + v_12) > 1f);
    } else {
        local_19 = true;
    }
    let _e42 = local_19;
    if _e42 {
        return -1f;
    }
    let t_4 = (dot(e2_1, q_1) * inv_1);
    if (t_4 > t_min) {
        local_20 = (t_4 < t_max_1);
    } else {
        local_20 = false;
    }
    let _e51 = local_20;
    if _e51 {
        return t_4;
    }
    return -1f;
}

fn camera_dir(forward: vec3<f32>, right: vec3<f32>, up: vec3<f32>, px: f32, py: f32, w_4: f32, h_1: f32) -> vec3<f32> {
    let sx = (((2f * px) / w_4) - 1f);
    let sy = (1f - ((2f * py) / h_1));
    return normalize(((forward + (right * sx)) + (up * sy)));
}

fn jittered_pixel(coord: u32, u_2: f32) -> f32 {
    let _e2 = to_f32_(coord);
    return (_e2 + u_2);
}

fn plays_roulette(depth: u32) -> bool {
    return (depth >= ROULETTE_DEPTH);
}

fn sees_emission(gn: vec3<f32>, dir_1: vec3<f32>) -> bool {
    return (dot(gn, dir_1) < 0f);
}

fn continues_path(nd: vec3<f32>, n_12: vec3<f32>, ng: vec3<f32>) -> bool {
    var local_21: bool;

    if (dot(nd, n_12) > 0f) {
        local_21 = (dot(nd, ng) > 0f);
    } else {
        local_21 = false;
    }
    let _e12 = local_21;
    return _e12;
}

fn path_survival(beta: vec3<f32>) -> f32 {
    return clamp(max(max(beta.x, beta.y), beta.z), 0.05f, 0.95f);
}

fn light_area(l_4: GpuLight) -> f32 {
    if (l_4.kind == LIGHT_TRIANGLE) {
        return l_4.a;
    }
    return 0f;
}

fn light_normal(l_5: GpuLight) -> vec3<f32> {
    if (l_5.kind == LIGHT_TRIANGLE) {
        let _e7 = triangle_normal(l_5.p0_, l_5.p1_, l_5.p2_);
        return _e7;
    }
    return vec3(0f);
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
        let n_17 = geo_nodes[_e21];
        let _e27 = hit.t;
        let _e28 = ray_aabb(o_2, _e14, n_17.bmin, n_17.bmax, _e27);
        if (_e28 >= 0f) {
            if (n_17.count > 0u) {
                i = n_17.first;
                loop {
                    let _e36 = i;
                    if (_e36 < (n_17.first + n_17.count)) {
                    } else {
                        break;
                    }
                    {
                        let _e42 = i;
                        let t_5 = geo_tris[_e42];
                        let _e49 = hit.t;
                        let _e50 = ray_triangle(o_2, d_5, t_5.v0_, t_5.v1_, t_5.v2_, t_min_1, _e49);
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
                    stack[_e63] = (n_17.first + 1u);
                    let _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_17.first;
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

fn mis_weight(pdf_a_1: f32, pdf_b_1: f32) -> f32 {
    let _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

fn light_range_scale(li: u32, x_3: vec3<f32>, r_2: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let c_9 = light_cones[li];
    let _e9 = range_scale_toward(rl_2, c_9.center, c_9.radius, x_3, r_2);
    return _e9;
}

fn select_pdf(li_1: u32, x_4: vec3<f32>, n_13: vec3<f32>, r_3: vec3<f32>, lobe_5: vec4<f32>, rl_3: vec4<f32>, nee: u32, in_range_1: bool) -> f32 {
    let _e9 = reservoir_select_pdf(nee, in_range_1, K);
    return _e9;
}

fn light_pdf_selected(li_2: u32, x_5: vec3<f32>, r_4: vec3<f32>, rl_4: vec4<f32>, y: vec3<f32>, sel: f32) -> f32 {
    let l_6 = lights[li_2];
    let v_13 = (x_5 - y);
    let d2_5 = dot(v_13, v_13);
    let _e11 = light_normal(l_6);
    let cos_y_1 = select(0f, dot(_e11, (v_13 / vec3(sqrt(d2_5)))), (d2_5 > 0f));
    let _e20 = light_range_scale(li_2, x_5, r_4, rl_4);
    let _e23 = rt2_2[li_2];
    let _e25 = light_area(l_6);
    let _e26 = light_strategy_pdf(sel, (_e20 * _e23), d2_5, _e25, cos_y_1);
    return _e26;
}

fn light_pdf(li_3: u32, x_6: vec3<f32>, n_14: vec3<f32>, r_5: vec3<f32>, lobe_6: vec4<f32>, rl_5: vec4<f32>, y_1: vec3<f32>, nee_1: u32, in_range_2: bool) -> f32 {
    let _e9 = select_pdf(li_3, x_6, n_14, r_5, lobe_6, rl_5, nee_1, in_range_2);
    let _e10 = light_pdf_selected(li_3, x_6, r_5, rl_5, y_1, _e9);
    return _e10;
}

fn bsh_node(nodes: u32, i_1: u32) -> BshNode {
    let _e4 = bsh_nodes[i_1];
    return _e4;
}

fn bsh_inner_scale(a_6: f32, v_9: vec3<f32>, d2_4: f32, r_6: vec3<f32>, rl_6: vec4<f32>) -> f32 {
    let _e5 = cone_cos_of(v_9, d2_4, a_6, r_6);
    let _e8 = range_scale_at(rl_6, (_e5 + 0.000002f));
    return _e8;
}

fn bsh_reaches(node_4: BshNode, x_7: vec3<f32>, r_7: vec3<f32>, rl_7: vec4<f32>) -> bool {
    var local_22: bool;
    var local_23: bool;

    let _e6 = sphere_contains_point(node_4.center, node_4.radius, x_7);
    if _e6 {
        return true;
    }
    if !((rl_7.w <= 1f)) {
        let _e20 = sphere_contains_point(node_4.center, (node_4.radius * (rl_7.w * 1.0001f)), x_7);
        local_22 = !(_e20);
    } else {
        local_22 = true;
    }
    let _e23 = local_22;
    if _e23 {
        return false;
    }
    let v_14 = (x_7 - node_4.center);
    let d2_6 = dot(v_14, v_14);
    let _e29 = bsh_reach_bound(node_4, rl_7.w);
    if (d2_6 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        let _e38 = range_scale_toward(rl_7, node_4.center, node_4.extent, x_7, r_7);
        let _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        let _e42 = sphere_contains_point(node_4.center, _e41, x_7);
        return _e42;
    }
    let _e45 = bsh_inner_scale(node_4.extent, -(v_14), d2_6, r_7, rl_7);
    let s_c = (_e45 * 1.001f);
    let _e50 = bsh_range_bound(node_4);
    let reach = (node_4.extent + (sqrt(s_c) * _e50));
    if (d2_6 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_23 = (d2_6 <= (reach * reach));
    } else {
        local_23 = false;
    }
    let _e63 = local_23;
    return _e63;
}

fn bsh_range_leaf(nodes_1: u32, i_2: u32) -> BshNode {
    var t: u32;

    let _e2 = bsh_node(nodes_1, i_2);
    if ((_e2.light & BSH_TAIL) == 0u) {
        return _e2;
    }
    let li_4 = (_e2.light & 2147483647u);
    let _e12 = bsh_node(nodes_1, 0u);
    t = _e12.next;
    loop {
        let _e15 = t;
        if (_e15 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e18 = t;
            let _e19 = bsh_node(nodes_1, _e18);
            if (_e19.light == li_4) {
                return _e19;
            }
            t = _e19.next;
        }
    }
    return _e2;
}

fn next_uniform(state: ptr<function, u32>) -> f32 {
    let _e1 = (*state);
    let _e2 = pcg_hash(_e1);
    (*state) = _e2;
    let _e3 = (*state);
    let _e4 = xi_from_bits(_e3);
    return _e4;
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var st: GpuPathState;
    var h: u32;
    var v: GpuPathVertex;
    var local: bool;
    var w: f32 = 1f;
    var rng: u32;
    var local_1: bool;
    var local_2: bool;

    let i_3 = gid.x;
    let _e4 = params.width;
    let _e7 = params.height;
    if (i_3 >= (_e4 * _e7)) {
        return;
    }
    let _e13 = params.depth;
    if (_e13 == 0u) {
        let _e18 = params.seed;
        let _e21 = params.pass_index;
        let _e22 = path_stream(_e18, i_3, _e21);
        h = _e22;
        let _e26 = params.width;
        let _e28 = next_uniform((&h));
        let _e29 = jittered_pixel((i_3 % _e26), _e28);
        let _e32 = params.width;
        let _e34 = next_uniform((&h));
        let _e35 = jittered_pixel((i_3 / _e32), _e34);
        let _e39 = params.cam_pos;
        st.origin = _e39;
        let _e43 = params.cam_forward;
        let _e46 = params.cam_right;
        let _e49 = params.cam_up;
        let _e52 = params.width;
        let _e56 = params.height;
        let _e58 = camera_dir(_e43, _e46, _e49, _e29, _e35, f32(_e52), f32(_e56));
        st.dir = _e58;
        st.alive = 1u;
        let _e62 = h;
        st.rng = _e62;
        st.beta = vec3(1f);
        st.pdf_bsdf = 0f;
        let _e71 = params.cam_pos;
        st.prev = _e71;
    } else {
        let _e74 = paths[i_3];
        st = _e74;
    }
    v.alive = 0u;
    let _e79 = st.alive;
    if (_e79 == 0u) {
        let _e84 = v;
        vertices[i_3] = _e84;
        return;
    }
    let _e86 = st.origin;
    let _e88 = st.dir;
    let _e91 = params.t_min;
    let _e94 = trace(_e86, _e88, _e91, F32_MAX, false);
    if (_e94.tri == NO_LIGHT) {
        st.alive = 0u;
        let _e102 = st;
        paths[i_3] = _e102;
        let _e105 = v;
        vertices[i_3] = _e105;
        return;
    }
    let tri = geo_tris[_e94.tri];
    let _e111 = st.origin;
    let _e113 = st.dir;
    let x_8 = (_e111 + (_e113 * _e94.t));
    let _e120 = triangle_normal(tri.v0_, tri.v1_, tri.v2_);
    let _e122 = st.dir;
    let _e123 = face_against(_e120, _e122);
    let b_6 = (_e94.tri * 3u);
    let _e129 = geo_normals[b_6];
    let _e135 = geo_normals[(b_6 + 1u)];
    let _e141 = geo_normals[(b_6 + 2u)];
    let _e146 = barycentric(x_8, tri.v0_, tri.v1_, tri.v2_);
    let _e147 = shading_normal(_e129.xyz, _e135.xyz, _e141.xyz, _e146, _e123);
    if (tri.light != NO_LIGHT) {
        let _e154 = st.dir;
        let _e155 = sees_emission(_e120, _e154);
        local = _e155;
    } else {
        local = false;
    }
    let _e157 = local;
    if _e157 {
        let _e161 = st.pdf_bsdf;
        if (_e161 > 0f) {
            let _e168 = light_leaf[tri.light];
            let _e169 = bsh_range_leaf(BSH, _e168);
            let _e171 = st.prev_lobe;
            let _e172 = range_lobe(_e171);
            let _e174 = st.prev;
            let _e176 = st.prev_r;
            let _e177 = bsh_reaches(_e169, _e174, _e176, _e172);
            let _e179 = st.pdf_bsdf;
            let _e182 = st.prev;
            let _e184 = st.prev_normal;
            let _e186 = st.prev_r;
            let _e188 = st.prev_lobe;
            let _e191 = candidates[i_3];
            let _e192 = light_pdf(tri.light, _e182, _e184, _e186, _e188, _e172, x_8, _e191, _e177);
            let _e193 = mis_weight(_e179, _e192);
            w = _e193;
        }
        let _e195 = st.beta;
        let _e200 = lights[tri.light].intensity;
        let _e202 = w;
        let add = ((_e195 * _e200) * _e202);
        let _e204 = finite3_(add);
        if _e204 {
            let _e207 = radiance[i_3];
            radiance[i_3] = (_e207 + vec4<f32>(add, 0f));
        }
    }
    let _e213 = params.depth;
    let _e216 = params.max_depth;
    if (_e213 >= _e216) {
        st.alive = 0u;
        let _e222 = st;
        paths[i_3] = _e222;
        let _e225 = v;
        vertices[i_3] = _e225;
        return;
    }
    let m_2 = materials[tri.material];
    let _e231 = st.dir;
    let wo_1 = -(_e231);
    let _e239 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, dot(_e147, wo_1));
    v.position = x_8;
    v.normal = _e147;
    v.material = tri.material;
    v.gnormal = _e123;
    let _e247 = st.beta;
    v.weight = _e247;
    v.wo = wo_1;
    v.alive = 1u;
    let _e253 = v;
    vertices[i_3] = _e253;
    let _e255 = st.rng;
    rng = _e255;
    let _e257 = next_uniform((&rng));
    let _e258 = next_uniform((&rng));
    let _e259 = specular_probability(_e239);
    let _e261 = bsdf_sample(_e147, wo_1, m_2.alpha, _e259, _e257, _e258);
    let _e263 = bsdf_pdf(_e147, wo_1, _e261, m_2.alpha, _e259);
    let _e267 = has_specular(m_2.metallic, m_2.f0_, m_2.f90_);
    if _e267 {
        let _e269 = st.beta;
        let _e275 = brdf_eval(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, _e147, wo_1, _e261);
        st.beta = (_e269 * (_e275 * (dot(_e261, _e147) / _e263)));
    } else {
        let _e281 = st.beta;
        st.beta = (_e281 * m_2.albedo);
    }
    st.prev = x_8;
    st.prev_normal = _e147;
    let _e287 = mirror_dir(_e147, wo_1);
    st.prev_r = _e287;
    st.prev_lobe = _e239;
    st.pdf_bsdf = _e263;
    let _e293 = params.eps;
    st.origin = (x_8 + (_e123 * _e293));
    st.dir = _e261;
    let _e297 = continues_path(_e261, _e147, _e123);
    if !(!(_e297)) {
        local_1 = !((_e263 > 0f));
    } else {
        local_1 = true;
    }
    let _e306 = local_1;
    if _e306 {
        st.alive = 0u;
    }
    let _e311 = params.depth;
    let _e312 = plays_roulette(_e311);
    if _e312 {
        let _e316 = st.alive;
        local_2 = (_e316 == 1u);
    } else {
        local_2 = false;
    }
    let _e320 = local_2;
    if _e320 {
        let _e322 = st.beta;
        let _e323 = path_survival(_e322);
        let _e324 = next_uniform((&rng));
        if (_e324 >= _e323) {
            st.alive = 0u;
        } else {
            let _e329 = st.beta;
            st.beta = (_e329 / vec3(_e323));
        }
    }
    let _e333 = rng;
    st.rng = _e333;
    let _e336 = st;
    paths[i_3] = _e336;
    return;
}
