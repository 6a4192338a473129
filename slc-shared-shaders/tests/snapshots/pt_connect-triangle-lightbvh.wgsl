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

struct GeoHit {
    t: f32,
    tri: u32,
}

struct Connection {
    e: vec3<f32>,
    y: vec3<f32>,
    cos_x: f32,
}

struct BvhPick {
    light: u32,
    pmf: f32,
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
@group(0) @binding(2) 
var<storage> lights: array<GpuLight>;
@group(0) @binding(4) 
var<storage> r2_4: array<f32>;
@group(0) @binding(3) 
var<storage> rt2_5: array<f32>;
@group(1) @binding(2) 
var<storage> light_cones: array<GpuLightCone>;
@group(1) @binding(3) 
var<storage> light_bvh: array<GpuLightBvhNode>;
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

fn inverse_square(d2_3: f32) -> f32 {
    return (1f / max(d2_3, MIN_D2_));
}

fn connection_factor(cos_x: f32, d2_4: f32, rt2_2: f32, w: f32) -> f32 {
    let _e4 = inverse_square(d2_4);
    let _e6 = slc_weight(rt2_2, d2_4);
    return (((cos_x * _e4) * _e6) * w);
}

fn connection_cosine(x_1: vec3<f32>, y: vec3<f32>, n: vec3<f32>, ng: vec3<f32>, r2_1: f32) -> f32 {
    var local: bool;
    var local_1: bool;

    let v_7 = (x_1 - y);
    let d2_8 = dot(v_7, v_7);
    let _e7 = slc_keep(r2_1, d2_8);
    if !(!(_e7)) {
        local = !((d2_8 > 0f));
    } else {
        local = true;
    }
    let _e16 = local;
    if _e16 {
        return 0f;
    }
    let w_5 = (v_7 / vec3(sqrt(d2_8)));
    let cos_x_1 = -(dot(n, w_5));
    if !(!((cos_x_1 > 0f))) {
        local_1 = !((dot(ng, w_5) < 0f));
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

fn triangle_sample(a_2: vec3<f32>, b_2: vec3<f32>, c: vec3<f32>, u1_: f32, u2_: f32) -> vec3<f32> {
    let su = sqrt(u1_);
    let b0_ = (1f - su);
    let b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c * ((1f - b0_) - b1_)));
}

fn area_to_solid_angle_pdf(pdf_area: f32, d2_5: f32, cos_light: f32) -> f32 {
    let c_5 = abs(cos_light);
    if (c_5 <= 0f) {
        return 0f;
    }
    return ((pdf_area * d2_5) / c_5);
}

fn mis_power(pdf_a: f32, pdf_b: f32) -> f32 {
    let a2_ = (pdf_a * pdf_a);
    let s_2 = (a2_ + (pdf_b * pdf_b));
    if (s_2 <= 0f) {
        return 0f;
    }
    return (a2_ / s_2);
}

fn light_strategy_pdf(select_: f32, rt2_3: f32, d2_6: f32, area_1: f32, cos_y: f32) -> f32 {
    var local_2: bool;
    var local_3: bool;

    if !((d2_6 <= 0f)) {
        local_2 = (area_1 <= 0f);
    } else {
        local_2 = true;
    }
    let _e13 = local_2;
    if !(_e13) {
        local_3 = (cos_y <= 0f);
    } else {
        local_3 = true;
    }
    let _e20 = local_3;
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

fn onb_tangent(n_2: vec3<f32>) -> vec3<f32> {
    let s_3 = select(-1f, 1f, (n_2.z >= 0f));
    let a_7 = (-1f / (s_3 + n_2.z));
    return vec3<f32>((1f + (((s_3 * n_2.x) * n_2.x) * a_7)), (((s_3 * n_2.x) * n_2.y) * a_7), (-(s_3) * n_2.x));
}

fn onb_bitangent(n_3: vec3<f32>) -> vec3<f32> {
    let s_4 = select(-1f, 1f, (n_3.z >= 0f));
    let a_8 = (-1f / (s_4 + n_3.z));
    return vec3<f32>(((n_3.x * n_3.y) * a_8), (s_4 + ((n_3.y * n_3.y) * a_8)), -(n_3.y));
}

fn onb_to_local(n_4: vec3<f32>, w_2: vec3<f32>) -> vec3<f32> {
    let _e2 = onb_tangent(n_4);
    let _e4 = onb_bitangent(n_4);
    return vec3<f32>(dot(w_2, _e2), dot(w_2, _e4), dot(w_2, n_4));
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
    var local_4: bool;

    if !((n_l <= 0f)) {
        local_4 = (n_v <= 0f);
    } else {
        local_4 = true;
    }
    let _e11 = local_4;
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

fn half_cosine(v: vec3<f32>, l: vec3<f32>) -> f32 {
    let h_1 = (v + l);
    let len2_ = dot(h_1, h_1);
    if (len2_ <= 0f) {
        return 0f;
    }
    return saturate((dot(v, h_1) / sqrt(len2_)));
}

fn specular_brdf(base_2: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n_5: vec3<f32>, v_1: vec3<f32>, l_1: vec3<f32>) -> vec3<f32> {
    var local_5: bool;

    let n_l_1 = dot(n_5, l_1);
    let n_v_2 = dot(n_5, v_1);
    if !((n_l_1 <= 0f)) {
        local_5 = (n_v_2 <= 0f);
    } else {
        local_5 = true;
    }
    let _e18 = local_5;
    if _e18 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let hs = (v_1 + l_1);
    let inv = (1f / sqrt(dot(hs, hs)));
    let h_2 = (hs * inv);
    let c_7 = cross(n_5, h_2);
    let _e32 = ggx_d(dot(n_5, h_2), dot(c_7, c_7), alpha_3);
    let _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_1, h_2));
    let _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return (_e34 * (_e32 * _e35));
}

fn brdf_eval(base_3: vec3<f32>, metallic_3: f32, f0_d_3: vec3<f32>, f90_d_3: f32, alpha_4: f32, n_6: vec3<f32>, v_2: vec3<f32>, l_2: vec3<f32>) -> vec3<f32> {
    if (dot(n_6, l_2) <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = half_cosine(v_2, l_2);
    let _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    let _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_6, v_2, l_2);
    return (_e16 + _e17);
}

fn has_specular(metallic_4: f32, f0_d_4: vec3<f32>, f90_d_4: f32) -> bool {
    var local_6: bool;
    var local_7: bool;

    if !((metallic_4 > 0f)) {
        local_6 = (f90_d_4 > 0f);
    } else {
        local_6 = true;
    }
    let _e11 = local_6;
    if !(_e11) {
        local_7 = (max(max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0f);
    } else {
        local_7 = true;
    }
    let _e23 = local_7;
    return _e23;
}

fn channel_mean(c_1: vec3<f32>) -> f32 {
    return (((c_1.x + c_1.y) + c_1.z) * 0.33333334f);
}

fn receiver_lobe(base_4: vec3<f32>, metallic_5: f32, f0_d_5: vec3<f32>, f90_d_5: f32, alpha_5: f32, n_v_1: f32) -> vec4<f32> {
    var local_8: bool;

    let _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    let _e16 = channel_mean((((vec3<f32>(1f, 1f, 1f) - _e10) * base_4) * (1f - metallic_5)));
    if !((n_v_1 <= 0f)) {
        let _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_8 = !(_e22);
    } else {
        local_8 = true;
    }
    let _e25 = local_8;
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

fn mirror_dir(n_7: vec3<f32>, v_3: vec3<f32>) -> vec3<f32> {
    return ((n_7 * (2f * dot(n_7, v_3))) - v_3);
}

fn bounded_vndf_k(wi: vec3<f32>, alpha_6: f32) -> f32 {
    let a_9 = saturate(alpha_6);
    let s_5 = (1f + sqrt(((wi.x * wi.x) + (wi.y * wi.y))));
    let a2_3 = (a_9 * a_9);
    let s2_ = (s_5 * s_5);
    return (((1f - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z)));
}

fn ggx_vndf_pdf(wi_1: vec3<f32>, wo: vec3<f32>, alpha_7: f32) -> f32 {
    var local_9: bool;

    if !((wi_1.z <= 0f)) {
        local_9 = (wo.z <= 0f);
    } else {
        local_9 = true;
    }
    let _e13 = local_9;
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

fn bsdf_pdf(n_8: vec3<f32>, v_4: vec3<f32>, l_3: vec3<f32>, alpha_8: f32, p_spec: f32) -> f32 {
    let _e6 = cosine_pdf(dot(n_8, l_3));
    if (p_spec <= 0f) {
        return _e6;
    }
    let _e9 = onb_to_local(n_8, v_4);
    let _e10 = onb_to_local(n_8, l_3);
    let _e11 = ggx_vndf_pdf(_e9, _e10, alpha_8);
    return ((p_spec * _e11) + ((1f - p_spec) * _e6));
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

fn safe_sqrt(x_2: f32) -> f32 {
    return sqrt(max(x_2, 0f));
}

fn subtended_cos(dist2_: f32, r2_2: f32) -> f32 {
    let _e5 = safe_sqrt((1f - (r2_2 / dist2_)));
    return select(_e5, -1f, (dist2_ <= r2_2));
}

fn emitter_cone(center: vec3<f32>, radius: f32, axis: vec3<f32>, cos_o: f32, p: vec3<f32>) -> vec4<f32> {
    var local_10: bool;

    let v_8 = (p - center);
    let dist2_1 = dot(v_8, v_8);
    let r2_5 = (radius * radius);
    if (dist2_1 <= 0f) {
        local_10 = (r2_5 <= 0f);
    } else {
        local_10 = false;
    }
    let _e15 = local_10;
    if _e15 {
        return vec4<f32>(-2f, 0.000000000001f, -1f, 0f);
    }
    let d2_9 = max(max(dist2_1, r2_5), MIN_D2_);
    let wi_2 = select(vec3<f32>(0f, 0f, 0f), (v_8 / vec3(sqrt(dist2_1))), (dist2_1 > 0f));
    let cos_w = dot(axis, wi_2);
    let _e38 = safe_sqrt((1f - (cos_w * cos_w)));
    let _e39 = subtended_cos(dist2_1, r2_5);
    let _e43 = safe_sqrt((1f - (_e39 * _e39)));
    let _e47 = safe_sqrt((1f - (cos_o * cos_o)));
    let _e48 = cos_sub_clamped(_e38, cos_w, _e47, cos_o);
    let _e49 = sin_sub_clamped(_e38, cos_w, _e47, cos_o);
    let _e50 = cos_sub_clamped(_e49, _e48, _e43, _e39);
    return vec4<f32>(_e50, d2_9, _e39, _e43);
}

fn emitter_importance(center_1: vec3<f32>, radius_1: f32, phi: f32, axis_1: vec3<f32>, cos_o_1: f32, cos_e: f32, p_1: vec3<f32>) -> f32 {
    let _e7 = emitter_cone(center_1, radius_1, axis_1, cos_o_1, p_1);
    if (_e7.x <= cos_e) {
        return 0f;
    }
    return ((phi * _e7.x) / _e7.y);
}

fn cone_cos_of(v_5: vec3<f32>, d2_7: f32, a_3: f32, d: vec3<f32>) -> f32 {
    var local_11: bool;
    var local_12: bool;

    let vd = dot(v_5, d);
    let h2_ = (d2_7 - (a_3 * a_3));
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
    let c_8 = cross(v_5, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_8, c_8)) * a_3)) / d2_7), 1f);
}

fn cone_cos_toward(center_2: vec3<f32>, radius_2: f32, p_2: vec3<f32>, d_1: vec3<f32>) -> f32 {
    let v_9 = (center_2 - p_2);
    let _e6 = cone_cos_of(v_9, dot(v_9, v_9), radius_2, d_1);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_2 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_2 * t_2))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_3: vec3<f32>, radius_3: f32, p_3: vec3<f32>, r: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_3, radius_3, p_3, r);
    let _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

fn light_importance(center_4: vec3<f32>, radius_4: f32, phi_1: f32, axis_2: vec3<f32>, cos_o_2: f32, cos_e_1: f32, p_4: vec3<f32>, n_9: vec3<f32>) -> f32 {
    var imp: f32;

    let _e8 = emitter_cone(center_4, radius_4, axis_2, cos_o_2, p_4);
    if (_e8.x <= cos_e_1) {
        return 0f;
    }
    imp = ((phi_1 * _e8.x) / _e8.y);
    if (dot(n_9, n_9) > 0f) {
        let v_10 = (center_4 - p_4);
        let dist2_2 = dot(v_10, v_10);
        let cos_i = dot(select(vec3<f32>(0f, 0f, 0f), (v_10 / vec3(sqrt(dist2_2))), (dist2_2 > 0f)), n_9);
        let _e33 = imp;
        let _e37 = safe_sqrt((1f - (cos_i * cos_i)));
        let _e40 = cos_sub_clamped(_e37, cos_i, _e8.w, _e8.z);
        imp = (_e33 * max(_e40, 0f));
    }
    let _e44 = imp;
    return max(_e44, 0f);
}

fn glossy_importance(center_5: vec3<f32>, radius_5: f32, phi_2: f32, axis_3: vec3<f32>, cos_o_3: f32, cos_e_2: f32, p_5: vec3<f32>, n_10: vec3<f32>, r_1: vec3<f32>, lobe_5: vec4<f32>) -> f32 {
    var local_13: bool;

    let _e10 = emitter_importance(center_5, radius_5, phi_2, axis_3, cos_o_3, cos_e_2, p_5);
    let _e11 = cone_cos_toward(center_5, radius_5, p_5, n_10);
    if !((_e10 <= 0f)) {
        local_13 = (_e11 <= 0f);
    } else {
        local_13 = true;
    }
    let _e20 = local_13;
    if _e20 {
        return 0f;
    }
    let _e22 = cone_cos_toward(center_5, radius_5, p_5, r_1);
    let _e27 = safe_sqrt((0.5f + (0.5f * _e22)));
    let _e33 = ggx_d(_e27, (1f - (_e27 * _e27)), lobe_5.z);
    let _e39 = smith_root(lobe_5.w, lobe_5.z);
    let spec = (((lobe_5.y * _e33) * 0.25f) / _e39);
    return (_e10 * (((lobe_5.x * INV_PI) * _e11) + spec));
}

fn receiver_importance(center_6: vec3<f32>, radius_6: f32, phi_3: f32, axis_4: vec3<f32>, cos_o_4: f32, cos_e_3: f32, p_6: vec3<f32>, n_11: vec3<f32>, r_2: vec3<f32>, lobe_6: vec4<f32>) -> f32 {
    if (lobe_6.y <= 0f) {
        let _e13 = light_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_11);
        return _e13;
    }
    let _e14 = glossy_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_11, r_2, lobe_6);
    return _e14;
}

fn bvh_first_prob(c0_: f32, c1_: f32) -> f32 {
    let s_6 = (c0_ + c1_);
    if (s_6 > 0f) {
        return (c0_ / s_6);
    }
    return -1f;
}

fn bvh_remap_u(u_1: f32, p0_: f32, first: bool) -> f32 {
    if first {
        return min((u_1 / p0_), ONE_MINUS_EPSILON);
    }
    return clamp(((u_1 - p0_) / (1f - p0_)), 0f, ONE_MINUS_EPSILON);
}

fn finite3_(v_6: vec3<f32>) -> bool {
    var local_14: bool;
    var local_15: bool;

    if (abs(v_6.x) <= F32_MAX) {
        local_14 = (abs(v_6.y) <= F32_MAX);
    } else {
        local_14 = false;
    }
    let _e12 = local_14;
    if _e12 {
        local_15 = (abs(v_6.z) <= F32_MAX);
    } else {
        local_15 = false;
    }
    let _e20 = local_15;
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
    let lo = min(t0_, t1_);
    let hi = max(t0_, t1_);
    let t_in = max(max(lo.x, lo.y), max(lo.z, 0f));
    let t_out = min(min(hi.x, hi.y), min(hi.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1f;
}

fn triangle_normal(a_4: vec3<f32>, b_3: vec3<f32>, c_2: vec3<f32>) -> vec3<f32> {
    var local_16: bool;

    let n_19 = cross((b_3 - a_4), (c_2 - a_4));
    let l2_ = dot(n_19, n_19);
    if !(!((l2_ > 0f))) {
        local_16 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_16 = true;
    }
    let _e17 = local_16;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_19 / vec3(sqrt(l2_)));
}

fn ray_triangle(o_1: vec3<f32>, d_3: vec3<f32>, a_5: vec3<f32>, b_4: vec3<f32>, c_3: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_17: bool;
    var local_18: bool;
    var local_19: bool;

    let e1_ = (b_4 - a_5);
    let e2_ = (c_3 - a_5);
    let p_7 = cross(d_3, e2_);
    let det = dot(e1_, p_7);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv_1 = (1f / det);
    let s_7 = (o_1 - a_5);
    let u_3 = (dot(s_7, p_7) * inv_1);
    if !((u_3 < 0f)) {
        local_17 = (u_3 > 1f);
    } else {
        local_17 = true;
    }
    let _e28 = local_17;
    if _e28 {
        return -1f;
    }
    let q = cross(s_7, e1_);
    let v_11 = (dot(d_3, q) * inv_1);
    if !((v_11 < 0f)) {
        local_18 = ((u_3 + v_11) > 1f);
    } else {
        local_18 = true;
    }
    let _e42 = local_18;
    if _e42 {
        return -1f;
    }
    let t_3 = (dot(e2_, q) * inv_1);
    if (t_3 > t_min) {
        local_19 = (t_3 < t_max_1);
    } else {
        local_19 = false;
    }
    let _e51 = local_19;
    if _e51 {
        return t_3;
    }
    return -1f;
}

fn light_intensity(l_4: GpuLight, w_3: vec3<f32>) -> vec3<f32> {
    switch l_4.kind {
        case 3u: {
            let _e7 = triangle_normal(l_4.p0_, l_4.p1_, l_4.p2_);
            let _e9 = triangle_lobe(_e7, l_4.a, w_3);
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
    var node: u32 = 0u;
    var i: u32;

    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if (arrayLength((&geo_nodes)) == 0u) {
        let _e13 = hit;
        return _e13;
    }
    let _e14 = ray_inverse3_(d_4);
    loop {
        let _e21 = node;
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
                node = n_20.first;
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
        node = _e80;
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

fn connect_record(l_8: GpuLight, x_4: vec3<f32>, n_12: vec3<f32>, ng_1: vec3<f32>, r2_3: f32, rt2_4: f32, w_res: f32, u1_2: f32, u2_2: f32, eps: f32, trace_1: bool) -> Connection {
    var c_4: Connection;
    var local_20: bool;
    var local_21: bool;

    c_4.e = vec3(0f);
    let _e16 = light_point(l_8, u1_2, u2_2);
    c_4.y = _e16;
    let _e19 = c_4.y;
    let _e20 = connection_cosine(x_4, _e19, n_12, ng_1, r2_3);
    c_4.cos_x = _e20;
    let _e22 = c_4.cos_x;
    if !((_e22 <= 0f)) {
        if trace_1 {
            let _e33 = c_4.y;
            let _e34 = occluded((x_4 + (ng_1 * eps)), _e33);
            local_21 = _e34;
        } else {
            local_21 = false;
        }
        let _e36 = local_21;
        local_20 = _e36;
    } else {
        local_20 = true;
    }
    let _e38 = local_20;
    if _e38 {
        let _e39 = c_4;
        return _e39;
    }
    let _e41 = c_4.y;
    let v_12 = (x_4 - _e41);
    let d2_10 = dot(v_12, v_12);
    let _e48 = light_intensity(l_8, (v_12 / vec3(sqrt(d2_10))));
    let _e50 = c_4.cos_x;
    let _e51 = connection_factor(_e50, d2_10, rt2_4, w_res);
    c_4.e = (_e48 * _e51);
    let _e53 = c_4;
    return _e53;
}

fn connect_traced(li: u32, x_5: vec3<f32>, n_13: vec3<f32>, ng_2: vec3<f32>, s: f32, w_res_1: f32, u1_3: f32, u2_3: f32, eps_1: f32, trace_2: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_4[li];
    let _e19 = rt2_5[li];
    let _e21 = connect_record(_e12, x_5, n_13, ng_2, (s * _e15), (s * _e19), w_res_1, u1_3, u2_3, eps_1, trace_2);
    return _e21;
}

fn connect(li_1: u32, x_6: vec3<f32>, n_14: vec3<f32>, ng_3: vec3<f32>, s_1: f32, w_res_2: f32, u1_4: f32, u2_4: f32, eps_2: f32) -> Connection {
    let _e10 = connect_traced(li_1, x_6, n_14, ng_3, s_1, w_res_2, u1_4, u2_4, eps_2, true);
    return _e10;
}

fn mis_weight(pdf_a_1: f32, pdf_b_1: f32) -> f32 {
    let _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

fn light_range_scale(li_2: u32, x_7: vec3<f32>, r_3: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let c_9 = light_cones[li_2];
    let _e9 = range_scale_toward(rl_2, c_9.center, c_9.radius, x_7, r_3);
    return _e9;
}

fn light_bvh_node(nodes: u32, i_1: u32) -> GpuLightBvhNode {
    let _e4 = light_bvh[i_1];
    return _e4;
}

fn light_bvh_count(nodes_1: u32) -> u32 {
    return arrayLength((&light_bvh));
}

fn bvh_importance(nodes_2: u32, i_2: u32, x_8: vec3<f32>, n_15: vec3<f32>, r_4: vec3<f32>, lobe_7: vec4<f32>) -> f32 {
    let _e6 = light_bvh_node(nodes_2, i_2);
    let _e13 = receiver_importance(_e6.center, _e6.radius, _e6.phi, _e6.axis, _e6.cos_o, _e6.cos_e, x_8, n_15, r_4, lobe_7);
    return _e13;
}

fn bvh_first(nodes_3: u32, i_3: u32, x_9: vec3<f32>, n_16: vec3<f32>, r_5: vec3<f32>, lobe_8: vec4<f32>) -> f32 {
    var local_22: bool;

    let _e6 = light_bvh_node(nodes_3, i_3);
    let j = _e6.second;
    if !((j <= (i_3 + 1u))) {
        let _e14 = light_bvh_count(nodes_3);
        local_22 = (j >= _e14);
    } else {
        local_22 = true;
    }
    let _e17 = local_22;
    if _e17 {
        return -1f;
    }
    let _e21 = bvh_importance(nodes_3, (i_3 + 1u), x_9, n_16, r_5, lobe_8);
    let _e22 = bvh_importance(nodes_3, j, x_9, n_16, r_5, lobe_8);
    let _e23 = bvh_first_prob(_e21, _e22);
    return _e23;
}

fn bvh_pick_none() -> BvhPick {
    return BvhPick(0u, 0f);
}

fn light_bvh_sample(nodes_4: u32, x_10: vec3<f32>, n_17: vec3<f32>, r_6: vec3<f32>, lobe_9: vec4<f32>, u_in: f32) -> BvhPick {
    var pick: BvhPick;
    var u_2: f32;
    var i_4: u32 = 0u;
    var pmf: f32 = 1f;
    var local_23: bool;

    let _e6 = bvh_pick_none();
    pick = _e6;
    u_2 = u_in;
    loop {
        let _e13 = i_4;
        let _e14 = light_bvh_count(nodes_4);
        if (_e13 < _e14) {
        } else {
            break;
        }
        {
            let _e16 = i_4;
            let _e17 = light_bvh_node(nodes_4, _e16);
            if (_e17.second == LIGHT_BVH_LEAF) {
                let _e21 = i_4;
                if !((_e21 > 0u)) {
                    let _e28 = bvh_importance(nodes_4, 0u, x_10, n_17, r_6, lobe_9);
                    local_23 = (_e28 > 0f);
                } else {
                    local_23 = true;
                }
                let _e32 = local_23;
                if _e32 {
                    pick.light = _e17.light;
                    let _e36 = pmf;
                    pick.pmf = _e36;
                }
                let _e37 = pick;
                return _e37;
            }
            let _e38 = i_4;
            let _e39 = bvh_first(nodes_4, _e38, x_10, n_17, r_6, lobe_9);
            if (_e39 < 0f) {
                let _e42 = pick;
                return _e42;
            }
            let _e43 = u_2;
            let first_1 = (_e43 < _e39);
            let _e45 = pmf;
            pmf = (_e45 * select((1f - _e39), _e39, first_1));
            let _e50 = u_2;
            let _e51 = bvh_remap_u(_e50, _e39, first_1);
            u_2 = _e51;
            let _e53 = i_4;
            i_4 = select(_e17.second, (_e53 + 1u), first_1);
        }
    }
    let _e57 = pick;
    return _e57;
}

fn light_pdf_selected(li_3: u32, x_11: vec3<f32>, r_7: vec3<f32>, rl_3: vec4<f32>, y_1: vec3<f32>, sel: f32) -> f32 {
    let l_9 = lights[li_3];
    let v_13 = (x_11 - y_1);
    let d2_11 = dot(v_13, v_13);
    let _e11 = light_normal(l_9);
    let cos_y_1 = select(0f, dot(_e11, (v_13 / vec3(sqrt(d2_11)))), (d2_11 > 0f));
    let _e20 = light_range_scale(li_3, x_11, r_7, rl_3);
    let _e23 = rt2_5[li_3];
    let _e25 = light_area(l_9);
    let _e26 = light_strategy_pdf(sel, (_e20 * _e23), d2_11, _e25, cos_y_1);
    return _e26;
}

fn shade_pick(li_4: u32, x_12: vec3<f32>, n_18: vec3<f32>, ng_4: vec3<f32>, m: GpuMaterial, wo_1: vec3<f32>, r_8: vec3<f32>, lobe_10: vec4<f32>, rl_4: vec4<f32>, w_4: f32, nee: u32, u1_5: f32, u2_5: f32) -> vec3<f32> {
    var mis: f32 = 1f;

    let _e13 = light_range_scale(li_4, x_12, r_8, rl_4);
    let _e16 = params.eps;
    let _e17 = connect(li_4, x_12, n_18, ng_4, _e13, w_4, u1_5, u2_5, _e16);
    if (_e17.cos_x <= 0f) {
        return vec3(0f);
    }
    let l_10 = normalize((_e17.y - x_12));
    let _e30 = lights[li_4];
    let _e31 = light_area(_e30);
    if (_e31 > 0f) {
        let _e37 = light_pdf_selected(li_4, x_12, r_8, rl_4, _e17.y, (1f / w_4));
        let _e39 = specular_probability(lobe_10);
        let _e40 = bsdf_pdf(n_18, wo_1, l_10, m.alpha, _e39);
        let _e41 = mis_weight(_e37, _e40);
        mis = _e41;
    }
    let _e47 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, n_18, wo_1, l_10);
    let _e50 = mis;
    return ((_e47 * _e17.e) * _e50);
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var h: u32;
    var sum: vec3<f32> = vec3(0f);

    let i_5 = gid.x;
    let _e4 = params.point_count;
    if (i_5 >= _e4) {
        return;
    }
    let vtx = vertices[i_5];
    if (vtx.alive == 0u) {
        candidates[i_5] = 0u;
        return;
    }
    let x_13 = vtx.position;
    let n_21 = vtx.normal;
    let ng_5 = vtx.gnormal;
    let m_2 = materials[vtx.material];
    let wo_2 = vtx.wo;
    let _e23 = mirror_dir(n_21, wo_2);
    let _e30 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, dot(n_21, wo_2));
    let _e31 = range_lobe(_e30);
    let _e34 = params.seed;
    let _e37 = params.frame;
    let _e38 = point_stream(_e34, i_5, _e37);
    let _e39 = pick_stream(_e38);
    h = _e39;
    candidates[i_5] = 0u;
    let _e47 = h;
    let _e48 = pcg_hash(_e47);
    h = _e48;
    let _e49 = h;
    let _e50 = xi_from_bits(_e49);
    let _e52 = light_bvh_sample(BVH, x_13, n_21, _e23, _e30, _e50);
    let li_5 = _e52.light;
    let pmf_1 = _e52.pmf;
    let _e55 = h;
    let _e56 = pcg_hash(_e55);
    h = _e56;
    let _e57 = h;
    let _e58 = xi_from_bits(_e57);
    let _e59 = h;
    let _e60 = pcg_hash(_e59);
    h = _e60;
    let _e61 = h;
    let _e62 = xi_from_bits(_e61);
    if (pmf_1 > 0f) {
        let _e68 = shade_pick(li_5, x_13, n_21, ng_5, m_2, wo_2, _e23, _e30, _e31, (1f / pmf_1), 0u, _e58, _e62);
        sum = _e68;
    }
    let _e70 = sum;
    let add = (vtx.weight * _e70);
    let _e72 = finite3_(add);
    if _e72 {
        let _e75 = radiance[i_5];
        radiance[i_5] = (_e75 + vec4<f32>(add, 0f));
        return;
    } else {
        return;
    }
}
