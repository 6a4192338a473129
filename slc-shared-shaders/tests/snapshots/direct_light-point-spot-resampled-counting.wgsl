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

var<private> rays_cast: u32;
var<private> nodes_visited: u32;
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
@group(1) @binding(1) 
var<storage> lights: array<GpuLight>;
@group(1) @binding(2) 
var<storage> rt2_3: array<f32>;
@group(1) @binding(3) 
var<storage> r2_3: array<f32>;
@group(1) @binding(4) 
var<storage> bsh_nodes: array<BshNode>;
@group(0) @binding(8) 
var<storage, read_write> counters: array<atomic<u32>>;
var<private> evaluations: u32;

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
    let v_2 = (x_1 - c);
    return (dot(v_2, v_2) <= (r_1 * r_1));
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

    let v_3 = (x_2 - y);
    let d2_6 = dot(v_3, v_3);
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
    let w_6 = (v_3 / vec3(sqrt(d2_6)));
    let cos_x_1 = -(dot(n, w_6));
    if !((cos_x_1 <= 0f)) {
        local_5 = (dot(ng, w_6) >= 0f);
    } else {
        local_5 = true;
    }
    let _e32 = local_5;
    if _e32 {
        return 0f;
    }
    return cos_x_1;
}

fn spot_falloff(cos_theta: f32, cos_outer: f32, cos_inner: f32, shape: f32) -> f32 {
    if (cos_inner <= cos_outer) {
        return select(0f, 1f, (cos_theta >= cos_outer));
    }
    let t_1 = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return select(((t_1 * t_1) * (3f - (2f * t_1))), (t_1 * t_1), (shape > 0.5f));
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

fn resample_target(c_1: vec3<f32>) -> f32 {
    return (((c_1.x + c_1.y) + c_1.z) * 0.33333334f);
}

fn slot_target(c_2: vec3<f32>, slot: u32, k_2: u32) -> f32 {
    if (k_2 < 3u) {
        let _e5 = resample_target(c_2);
        return _e5;
    }
    let j_2 = (slot % 3u);
    if (j_2 == 0u) {
        return c_2.x;
    }
    if (j_2 == 1u) {
        return c_2.y;
    }
    return c_2.z;
}

fn slot_share(slot_1: u32, k_3: u32) -> vec3<f32> {
    if (k_3 < 3u) {
        let _e4 = to_f32_(k_3);
        let w_7 = (1f / _e4);
        return vec3<f32>(w_7, w_7, w_7);
    }
    let j_3 = (slot_1 % 3u);
    let _e15 = to_f32_((((k_3 + 2u) - j_3) / 3u));
    let w_8 = (1f / _e15);
    if (j_3 == 0u) {
        return vec3<f32>(w_8, 0f, 0f);
    }
    if (j_3 == 1u) {
        return vec3<f32>(0f, w_8, 0f);
    }
    return vec3<f32>(0f, 0f, w_8);
}

fn smith_root(cos_: f32, alpha: f32) -> f32 {
    let a2_ = (alpha * alpha);
    return sqrt((((cos_ * cos_) * (1f - a2_)) + a2_));
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

fn cone_cos_of(v: vec3<f32>, d2_4: f32, a_2: f32, d: vec3<f32>) -> f32 {
    var local_6: bool;
    var local_7: bool;

    let vd = dot(v, d);
    let h2_ = (d2_4 - (a_2 * a_2));
    if !((h2_ <= 0f)) {
        if (vd >= 0f) {
            local_7 = ((vd * vd) >= h2_);
        } else {
            local_7 = false;
        }
        let _e19 = local_7;
        local_6 = _e19;
    } else {
        local_6 = true;
    }
    let _e21 = local_6;
    if _e21 {
        return 1f;
    }
    let c_6 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_6, c_6)) * a_2)) / d2_4), 1f);
}

fn cone_cos_toward(center: vec3<f32>, radius: f32, p: vec3<f32>, d_1: vec3<f32>) -> f32 {
    let v_4 = (center - p);
    let _e6 = cone_cos_of(v_4, dot(v_4, v_4), radius, d_1);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_2 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_2 * t_2))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_1: vec3<f32>, radius_1: f32, p_1: vec3<f32>, r_2: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_1, radius_1, p_1, r_2);
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

fn ray_triangle(o_1: vec3<f32>, d_3: vec3<f32>, a_3: vec3<f32>, b_3: vec3<f32>, c_3: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_8: bool;
    var local_9: bool;
    var local_10: bool;

    let e1_ = (b_3 - a_3);
    let e2_ = (c_3 - a_3);
    let p_2 = cross(d_3, e2_);
    let det = dot(e1_, p_2);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv = (1f / det);
    let s_4 = (o_1 - a_3);
    let u_3 = (dot(s_4, p_2) * inv);
    if !((u_3 < 0f)) {
        local_8 = (u_3 > 1f);
    } else {
        local_8 = true;
    }
    let _e28 = local_8;
    if _e28 {
        return -1f;
    }
    let q_1 = cross(s_4, e1_);
    let v_5 = (dot(d_3, q_1) * inv);
    if !((v_5 < 0f)) {
        local_9 = ((u_3 + v_5) > 1f);
    } else {
        local_9 = true;
    }
    let _e42 = local_9;
    if _e42 {
        return -1f;
    }
    let t_3 = (dot(e2_, q_1) * inv);
    if (t_3 > t_min) {
        local_10 = (t_3 < t_max_1);
    } else {
        local_10 = false;
    }
    let _e51 = local_10;
    if _e51 {
        return t_3;
    }
    return -1f;
}

fn light_intensity(l: GpuLight, w_2: vec3<f32>) -> vec3<f32> {
    switch l.kind {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            let _e11 = spot_falloff(dot(l.p1_, w_2), l.a, l.b, l.p2_.x);
            return (l.intensity * _e11);
        }
        default: {
            return vec3(0f);
        }
    }
}

fn light_point(l_1: GpuLight, u1_: f32, u2_: f32) -> vec3<f32> {
    return l_1.p0_;
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
        let n_7 = geo_nodes[_e21];
        let _e25 = nodes_visited;
        nodes_visited = (_e25 + 1u);
        let _e31 = hit.t;
        let _e32 = ray_aabb(o_2, _e14, n_7.bmin, n_7.bmax, _e31);
        if (_e32 >= 0f) {
            if (n_7.count > 0u) {
                i = n_7.first;
                loop {
                    let _e40 = i;
                    if (_e40 < (n_7.first + n_7.count)) {
                    } else {
                        break;
                    }
                    {
                        let _e46 = i;
                        let t_4 = geo_tris[_e46];
                        let _e53 = hit.t;
                        let _e54 = ray_triangle(o_2, d_4, t_4.v0_, t_4.v1_, t_4.v2_, t_min_1, _e53);
                        if (_e54 > 0f) {
                            hit.t = _e54;
                            let _e59 = i;
                            hit.tri = _e59;
                            if any_hit {
                                let _e60 = hit;
                                return _e60;
                            }
                        }
                    }
                    continuing {
                        let _e62 = i;
                        i = (_e62 + 1u);
                    }
                }
            } else {
                let _e64 = sp;
                if (_e64 < 64u) {
                    let _e67 = sp;
                    stack[_e67] = (n_7.first + 1u);
                    let _e72 = sp;
                    sp = (_e72 + 1u);
                }
                node_2 = n_7.first;
                continue;
            }
        }
        let _e76 = sp;
        if (_e76 == 0u) {
            break;
        }
        let _e79 = sp;
        sp = (_e79 - 1u);
        let _e82 = sp;
        let _e84 = stack[_e82];
        node_2 = _e84;
    }
    let _e85 = hit;
    return _e85;
}

fn occluded(a_4: vec3<f32>, b_4: vec3<f32>) -> bool {
    let dv = (b_4 - a_4);
    let len_1 = length(dv);
    if (len_1 <= 0f) {
        return false;
    }
    let _e7 = shadow_margin(len_1);
    let _e9 = rays_cast;
    rays_cast = (_e9 + 1u);
    let _e16 = trace(a_4, (dv / vec3(len_1)), _e7, (len_1 - _e7), true);
    return (_e16.tri != NO_LIGHT);
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

fn bsh_inner_scale(a_5: f32, v_1: vec3<f32>, d2_5: f32, r_3: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let _e5 = cone_cos_of(v_1, d2_5, a_5, r_3);
    let _e8 = range_scale_at(rl_2, (_e5 + 0.000002f));
    return _e8;
}

fn bsh_reaches(node_3: BshNode, x_4: vec3<f32>, r_4: vec3<f32>, rl_3: vec4<f32>) -> bool {
    var local_11: bool;
    var local_12: bool;

    let _e6 = sphere_contains_point(node_3.center, node_3.radius, x_4);
    if _e6 {
        return true;
    }
    if !((rl_3.w <= 1f)) {
        let _e20 = sphere_contains_point(node_3.center, (node_3.radius * (rl_3.w * 1.0001f)), x_4);
        local_11 = !(_e20);
    } else {
        local_11 = true;
    }
    let _e23 = local_11;
    if _e23 {
        return false;
    }
    let _e25 = bsh_range_bound(node_3);
    let v_6 = (x_4 - node_3.center);
    let d2_7 = dot(v_6, v_6);
    let reach_max = (node_3.extent + ((rl_3.w * 1.001f) * _e25));
    if (d2_7 > (reach_max * reach_max)) {
        return false;
    }
    if (node_3.child == BSH_NONE) {
        let _e43 = range_scale_toward(rl_3, node_3.center, node_3.extent, x_4, r_4);
        let _e46 = bsh_scaled_radius(node_3, sqrt(_e43));
        let _e47 = sphere_contains_point(node_3.center, _e46, x_4);
        return _e47;
    }
    let _e50 = bsh_inner_scale(node_3.extent, -(v_6), d2_7, r_4, rl_3);
    let s_c = (_e50 * 1.001f);
    let reach = (node_3.extent + (sqrt(s_c) * _e25));
    if (d2_7 <= ((node_3.radius * node_3.radius) * s_c)) {
        local_12 = (d2_7 <= (reach * reach));
    } else {
        local_12 = false;
    }
    let _e67 = local_12;
    return _e67;
}

fn bsh_next_leaf_lobe(nodes_3: u32, start: u32, x_5: vec3<f32>, r_5: vec3<f32>, rl_4: vec4<f32>) -> u32 {
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
            let _e11 = bsh_reaches(_e10, x_5, r_5, rl_4);
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

fn connect_record(l_2: GpuLight, x_6: vec3<f32>, n_1: vec3<f32>, ng_1: vec3<f32>, r2_2: f32, rt2_2: f32, w_res: f32, u1_1: f32, u2_1: f32, eps: f32, trace_1: bool) -> Connection {
    var c_4: Connection;
    var local_13: bool;
    var local_14: bool;

    c_4.e = vec3(0f);
    let _e16 = light_point(l_2, u1_1, u2_1);
    c_4.y = _e16;
    let _e19 = c_4.y;
    let _e20 = connection_cosine(x_6, _e19, n_1, ng_1, r2_2);
    c_4.cos_x = _e20;
    let _e22 = c_4.cos_x;
    if !((_e22 <= 0f)) {
        if trace_1 {
            let _e33 = c_4.y;
            let _e34 = occluded((x_6 + (ng_1 * eps)), _e33);
            local_14 = _e34;
        } else {
            local_14 = false;
        }
        let _e36 = local_14;
        local_13 = _e36;
    } else {
        local_13 = true;
    }
    let _e38 = local_13;
    if _e38 {
        let _e39 = c_4;
        return _e39;
    }
    let _e41 = c_4.y;
    let v_7 = (x_6 - _e41);
    let d2_8 = dot(v_7, v_7);
    let _e48 = light_intensity(l_2, (v_7 / vec3(sqrt(d2_8))));
    let _e50 = c_4.cos_x;
    let _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_4.e = (_e48 * _e51);
    let _e53 = c_4;
    return _e53;
}

fn connect_traced(li: u32, x_7: vec3<f32>, n_2: vec3<f32>, ng_2: vec3<f32>, s: f32, w_res_1: f32, u1_2: f32, u2_2: f32, eps_1: f32, trace_2: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_3[li];
    let _e19 = rt2_3[li];
    let _e21 = connect_record(_e12, x_7, n_2, ng_2, (s * _e15), (s * _e19), w_res_1, u1_2, u2_2, eps_1, trace_2);
    return _e21;
}

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p_3 = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p_3.xyz, 1f), (p_3.w > 0f));
}

fn counter_add(f: u32, n_3: u32) {
    let _e6 = atomicAdd((&counters[(2u * f)]), n_3);
    if ((_e6 + n_3) < _e6) {
        let _e16 = atomicAdd((&counters[((2u * f) + 1u)]), 1u);
        return;
    } else {
        return;
    }
}

fn shade_connection(c_5: Connection, x_8: vec3<f32>, n_4: vec3<f32>, m_1: Material) -> Shaded {
    var s_1: Shaded;

    s_1.e = c_5.e;
    s_1.diffuse = vec3(0f);
    s_1.specular = vec3(0f);
    let _e13 = s_1;
    return _e13;
}

fn shade_pick_traced(li_1: u32, x_9: vec3<f32>, n_5: vec3<f32>, r_6: vec3<f32>, rl_5: vec4<f32>, m_2: Material, w_3: f32, u1_3: f32, u2_3: f32, eps_2: f32, trace_3: bool) -> Shaded {
    let _e12 = connect_traced(li_1, x_9, n_5, n_5, 1f, w_3, u1_3, u2_3, eps_2, trace_3);
    let _e13 = shade_connection(_e12, x_9, n_5, m_2);
    return _e13;
}

fn shade_pick(li_2: u32, x_10: vec3<f32>, n_6: vec3<f32>, r_7: vec3<f32>, rl_6: vec4<f32>, m_3: Material, w_4: f32, u1_4: f32, u2_4: f32, eps_3: f32) -> Shaded {
    let _e11 = shade_pick_traced(li_2, x_10, n_6, r_7, rl_6, m_3, w_4, u1_4, u2_4, eps_3, true);
    return _e11;
}

fn add(a_6: Shaded, b_5: Shaded) -> Shaded {
    return Shaded((a_6.e + b_5.e), (a_6.diffuse + b_5.diffuse), (a_6.specular + b_5.specular));
}

fn scaled(s_2: Shaded, w_5: vec3<f32>) -> Shaded {
    return Shaded((s_2.e * w_5), (s_2.diffuse * w_5), (s_2.specular * w_5));
}

fn first_holders(keys_1: array<vec2<u32>, 8>, held_1: array<bool, 8>) -> array<u32, 8> {
    var first: array<u32, 8>;
    var k_4: u32 = 0u;
    var j_1: u32;
    var local_15: bool;
    var local_16: bool;

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
                    local_15 = held_1[_e22];
                } else {
                    local_15 = false;
                }
                let _e25 = local_15;
                if _e25 {
                } else {
                    break;
                }
                {
                    let _e26 = j_1;
                    if held_1[_e26] {
                        let _e30 = j_1;
                        let _e32 = k_4;
                        local_16 = all((keys_1[_e30] == keys_1[_e32]));
                    } else {
                        local_16 = false;
                    }
                    let _e37 = local_16;
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
    return s_3.e;
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
    let x_11 = _e21.xyz;
    let n_8 = (nn / vec3(sqrt(len2_)));
    r = n_8;
    let _e53 = lobe;
    let _e54 = range_lobe(_e53);
    let _e57 = view.shadow_offset;
    let _e60 = view.eye;
    let eps_4 = (_e57 * length((_e60 - x_11)));
    let _e66 = view.seed;
    let _e70 = view.width;
    let _e76 = view.frame;
    let _e77 = point_stream(_e66, ((gid.y * _e70) + gid.x), _e76);
    let _e78 = pick_stream(_e77);
    h = _e78;
    hc = _e77;
    let _e100 = bsh_first(BSH);
    let _e101 = r;
    let _e102 = bsh_next_leaf_lobe(BSH, _e100, x_11, _e101, _e54);
    b = _e102;
    loop {
        let _e104 = b;
        if (_e104 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e107 = count;
            count = (_e107 + 1u);
            let _e111 = b;
            let li_3 = bsh_nodes[_e111].light;
            let _e115 = h;
            let _e116 = pcg_hash(_e115);
            h = _e116;
            let _e117 = h;
            let _e118 = xi_from_bits(_e117);
            let _e119 = h;
            let _e120 = pcg_hash(_e119);
            h = _e120;
            let _e121 = h;
            let _e122 = xi_from_bits(_e121);
            let u_4 = vec2<f32>(_e118, _e122);
            let _e124 = r;
            let _e125 = m;
            let _e130 = shade_pick_traced(li_3, x_11, n_8, _e124, _e54, _e125, 1f, u_4.x, u_4.y, eps_4, false);
            let _e131 = output_of(_e130);
            let _e133 = evaluations;
            evaluations = (_e133 + 1u);
            let _e136 = resample_target(_e131);
            if (_e136 > 0f) {
                let _e139 = total;
                total = (_e139 + _e131);
                q = 0u;
                loop {
                    let _e143 = q;
                    if (_e143 < K) {
                    } else {
                        break;
                    }
                    {
                        let _e146 = q;
                        let _e148 = slot_target(_e131, _e146, K);
                        let _e149 = total;
                        let _e150 = q;
                        let _e152 = slot_target(_e149, _e150, K);
                        if (_e148 > 0f) {
                            let _e157 = q;
                            let _e159 = threshold[_e157];
                            local_2 = (_e152 > _e159);
                        } else {
                            local_2 = false;
                        }
                        let _e162 = local_2;
                        if _e162 {
                            let _e163 = q;
                            slot_light[_e163] = li_3;
                            let _e165 = q;
                            slot_u[_e165] = u_4;
                            let _e167 = q;
                            slot_p[_e167] = _e148;
                            let _e169 = q;
                            let _e171 = next_threshold(_e152, (&hc));
                            threshold[_e169] = _e171;
                        }
                    }
                    continuing {
                        let _e173 = q;
                        q = (_e173 + 1u);
                    }
                }
            }
        }
        continuing {
            let _e177 = b;
            let _e180 = bsh_nodes[_e177].next;
            let _e181 = r;
            let _e182 = bsh_next_leaf_lobe(BSH, _e180, x_11, _e181, _e54);
            b = _e182;
        }
    }
    loop {
        let _e187 = k;
        if (_e187 < K) {
        } else {
            break;
        }
        {
            let _e190 = k;
            let _e192 = k;
            let _e194 = slot_light[_e192];
            keys[_e190] = vec2<u32>(_e194, 0u);
            let _e197 = k;
            let _e199 = k;
            let _e201 = slot_p[_e199];
            held[_e197] = (_e201 > 0f);
        }
        continuing {
            let _e205 = k;
            k = (_e205 + 1u);
        }
    }
    let _e207 = keys;
    let _e208 = held;
    let _e209 = first_holders(_e207, _e208);
    loop {
        let _e212 = k_1;
        if (_e212 < K) {
        } else {
            break;
        }
        {
            w = vec3(0f);
            let _e218 = k_1;
            let _e220 = k_1;
            let first_1 = (_e209[_e218] == _e220);
            let _e222 = k_1;
            j = _e222;
            loop {
                let _e224 = j;
                if (_e224 < K) {
                    local_3 = first_1;
                } else {
                    local_3 = false;
                }
                let _e230 = local_3;
                if _e230 {
                } else {
                    break;
                }
                {
                    let _e231 = j;
                    let _e233 = k_1;
                    if (_e209[_e231] == _e233) {
                        let _e235 = w;
                        let _e236 = total;
                        let _e237 = j;
                        let _e239 = slot_target(_e236, _e237, K);
                        let _e240 = j;
                        let _e242 = slot_p[_e240];
                        let _e244 = j;
                        let _e246 = slot_share(_e244, K);
                        w = (_e235 + ((_e239 / _e242) * _e246));
                    }
                }
                continuing {
                    let _e250 = j;
                    j = (_e250 + 1u);
                }
            }
            if first_1 {
                let _e252 = t;
                let _e253 = k_1;
                let _e255 = slot_light[_e253];
                let _e256 = r;
                let _e257 = m;
                let _e259 = k_1;
                let _e262 = slot_u[_e259].x;
                let _e263 = k_1;
                let _e266 = slot_u[_e263].y;
                let _e267 = shade_pick(_e255, x_11, n_8, _e256, _e54, _e257, 1f, _e262, _e266, eps_4);
                let _e268 = w;
                let _e269 = scaled(_e267, _e268);
                let _e270 = add(_e252, _e269);
                t = _e270;
            }
        }
        continuing {
            let _e272 = k_1;
            k_1 = (_e272 + 1u);
        }
    }
    let _e276 = t.e;
    let _e277 = count;
    textureStore(out_tex, texel_1, vec4<f32>(_e276, f32(_e277)));
    counter_add(DIRECT_COUNT_PIXELS, 1u);
    let _e283 = count;
    counter_add(DIRECT_COUNT_CANDIDATES, _e283);
    let _e286 = evaluations;
    counter_add(DIRECT_COUNT_EVALUATIONS, _e286);
    let _e289 = rays_cast;
    counter_add(DIRECT_COUNT_RAYS, _e289);
    let _e292 = nodes_visited;
    counter_add(DIRECT_COUNT_NODES, _e292);
    return;
}
