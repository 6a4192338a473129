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

@group(0) @binding(6) 
var<storage> bsh_nodes: array<BshNode>;
@group(0) @binding(3) 
var<storage> lights: array<GpuLight>;
@group(0) @binding(5) 
var<storage> r2_3: array<f32>;
@group(0) @binding(4) 
var<storage> rt2_3: array<f32>;
@group(0) @binding(0) 
var<uniform> params: ShadeParams;
@group(0) @binding(1) 
var<storage> points: array<vec4<f32>>;
@group(0) @binding(2) 
var<storage> normals: array<vec4<f32>>;
@group(0) @binding(9) 
var<storage, read_write> irradiance: array<vec4<f32>>;

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

fn sphere_contains_point(c: vec3<f32>, r: f32, x_1: vec3<f32>) -> bool {
    let v_2 = (x_1 - c);
    return (dot(v_2, v_2) <= (r * r));
}

fn inverse_square(d2_2: f32) -> f32 {
    return (1f / max(d2_2, MIN_D2_));
}

fn connection_factor(cos_x: f32, d2_3: f32, rt2_1: f32, w: f32) -> f32 {
    let _e4 = inverse_square(d2_3);
    let _e6 = slc_weight(rt2_1, d2_3);
    return (((cos_x * _e4) * _e6) * w);
}

fn connection_cosine(x_2: vec3<f32>, y: vec3<f32>, n: vec3<f32>, ng: vec3<f32>, r2_1: f32) -> f32 {
    var local: bool;
    var local_1: bool;

    let v_3 = (x_2 - y);
    let d2_6 = dot(v_3, v_3);
    let _e7 = slc_keep(r2_1, d2_6);
    if !(!(_e7)) {
        local = !((d2_6 > 0f));
    } else {
        local = true;
    }
    let _e16 = local;
    if _e16 {
        return 0f;
    }
    let w_4 = (v_3 / vec3(sqrt(d2_6)));
    let cos_x_1 = -(dot(n, w_4));
    if !(!((cos_x_1 > 0f))) {
        local_1 = !((dot(ng, w_4) < 0f));
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

fn cone_cos_of(v: vec3<f32>, d2_4: f32, a_4: f32, d: vec3<f32>) -> f32 {
    var local_2: bool;
    var local_3: bool;

    let vd = dot(v, d);
    let h2_ = (d2_4 - (a_4 * a_4));
    if !((h2_ <= 0f)) {
        if (vd >= 0f) {
            local_3 = ((vd * vd) >= h2_);
        } else {
            local_3 = false;
        }
        let _e19 = local_3;
        local_2 = _e19;
    } else {
        local_2 = true;
    }
    let _e21 = local_2;
    if _e21 {
        return 1f;
    }
    let c_6 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_6, c_6)) * a_4)) / d2_4), 1f);
}

fn cone_cos_toward(center: vec3<f32>, radius: f32, p: vec3<f32>, d_1: vec3<f32>) -> f32 {
    let v_4 = (center - p);
    let _e6 = cone_cos_of(v_4, dot(v_4, v_4), radius, d_1);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t * t))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_1: vec3<f32>, radius_1: f32, p_1: vec3<f32>, r_1: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_1, radius_1, p_1, r_1);
    let _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

fn triangle_normal(a_5: vec3<f32>, b_4: vec3<f32>, c_2: vec3<f32>) -> vec3<f32> {
    var local_4: bool;

    let n_9 = cross((b_4 - a_5), (c_2 - a_5));
    let l2_ = dot(n_9, n_9);
    if !(!((l2_ > 0f))) {
        local_4 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_4 = true;
    }
    let _e17 = local_4;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_9 / vec3(sqrt(l2_)));
}

fn light_intensity(l: GpuLight, w_3: vec3<f32>) -> vec3<f32> {
    switch l.kind {
        case 0u: {
            return l.intensity;
        }
        case 3u: {
            let _e8 = triangle_normal(l.p0_, l.p1_, l.p2_);
            let _e10 = triangle_lobe(_e8, l.a, w_3);
            return (l.intensity * _e10);
        }
        default: {
            return vec3(0f);
        }
    }
}

fn light_point(l_1: GpuLight, u1_1: f32, u2_1: f32) -> vec3<f32> {
    if (l_1.kind == LIGHT_TRIANGLE) {
        let _e9 = triangle_sample(l_1.p0_, l_1.p1_, l_1.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_1.p0_;
}

fn occluded(a_6: vec3<f32>, b_5: vec3<f32>) -> bool {
    return false;
}

fn bsh_node(nodes: u32, i: u32) -> BshNode {
    let _e4 = bsh_nodes[i];
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

fn bsh_inner_scale(a_7: f32, v_1: vec3<f32>, d2_5: f32, r_2: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let _e5 = cone_cos_of(v_1, d2_5, a_7, r_2);
    let _e8 = range_scale_at(rl_2, (_e5 + 0.000002f));
    return _e8;
}

fn bsh_reaches(node_3: BshNode, x_3: vec3<f32>, r_3: vec3<f32>, rl_3: vec4<f32>) -> bool {
    var local_5: bool;
    var local_6: bool;

    let _e6 = sphere_contains_point(node_3.center, node_3.radius, x_3);
    if _e6 {
        return true;
    }
    if !((rl_3.w <= 1f)) {
        let _e20 = sphere_contains_point(node_3.center, (node_3.radius * (rl_3.w * 1.0001f)), x_3);
        local_5 = !(_e20);
    } else {
        local_5 = true;
    }
    let _e23 = local_5;
    if _e23 {
        return false;
    }
    let v_5 = (x_3 - node_3.center);
    let d2_7 = dot(v_5, v_5);
    let _e29 = bsh_reach_bound(node_3, rl_3.w);
    if (d2_7 > (_e29 * _e29)) {
        return false;
    }
    if (node_3.child == BSH_NONE) {
        let _e38 = range_scale_toward(rl_3, node_3.center, node_3.extent, x_3, r_3);
        let _e41 = bsh_scaled_radius(node_3, sqrt(_e38));
        let _e42 = sphere_contains_point(node_3.center, _e41, x_3);
        return _e42;
    }
    let _e45 = bsh_inner_scale(node_3.extent, -(v_5), d2_7, r_3, rl_3);
    let s_c = (_e45 * 1.001f);
    let _e50 = bsh_range_bound(node_3);
    let reach = (node_3.extent + (sqrt(s_c) * _e50));
    if (d2_7 <= ((node_3.radius * node_3.radius) * s_c)) {
        local_6 = (d2_7 <= (reach * reach));
    } else {
        local_6 = false;
    }
    let _e63 = local_6;
    return _e63;
}

fn bsh_next_leaf_lobe(nodes_3: u32, start: u32, x_4: vec3<f32>, r_4: vec3<f32>, rl_4: vec4<f32>) -> u32 {
    var i_1: u32;

    i_1 = start;
    loop {
        let _e6 = i_1;
        if (_e6 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e9 = i_1;
            let _e10 = bsh_node(nodes_3, _e9);
            let _e11 = bsh_reaches(_e10, x_4, r_4, rl_4);
            if _e11 {
                if (_e10.child == BSH_NONE) {
                    if ((_e10.light & BSH_TAIL) == 0u) {
                        let _e20 = i_1;
                        return _e20;
                    }
                    i_1 = _e10.next;
                } else {
                    i_1 = _e10.child;
                }
            } else {
                i_1 = _e10.next;
            }
        }
    }
    return BSH_NONE;
}

fn bsh_cursor(x_5: vec3<f32>, r_5: vec3<f32>, rl_5: vec4<f32>) -> BshCursor {
    var c_3: BshCursor;

    c_3.i = 0u;
    c_3.end = 0u;
    let _e10 = bsh_first(BSH);
    c_3.next = _e10;
    c_3.cone = vec2(0f);
    let _e14 = c_3;
    return _e14;
}

fn bsh_cursor_next(c_4: ptr<function, BshCursor>, x_6: vec3<f32>, r_6: vec3<f32>, rl_6: vec4<f32>) -> u32 {
    let _e6 = (*c_4).next;
    let _e7 = bsh_next_leaf_lobe(BSH, _e6, x_6, r_6, rl_6);
    if (_e7 != BSH_NONE) {
        let _e14 = bsh_nodes[_e7].next;
        (*c_4).next = _e14;
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
        let hi_2 = (*h_1);
        let _e13 = (*h_1);
        let _e14 = pcg_hash(_e13);
        (*h_1) = _e14;
        let _e16 = (*picks).n;
        let _e18 = (*h_1);
        let _e19 = reservoir_slot(_e16, K, hi_2, _e18);
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

fn bsh_collect(x_7: vec3<f32>, r_7: vec3<f32>, rl_7: vec4<f32>, seed_1: u32) -> Picks {
    var picks_1: Picks;
    var h_2: u32;
    var cur: BshCursor;
    var i_2: u32;

    picks_1.n = 0u;
    h_2 = seed_1;
    let _e8 = bsh_cursor(x_7, r_7, rl_7);
    cur = _e8;
    let _e10 = bsh_cursor_next((&cur), x_7, r_7, rl_7);
    i_2 = _e10;
    loop {
        let _e12 = i_2;
        if (_e12 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e16 = i_2;
            let _e19 = bsh_nodes[_e16].light;
            reservoir_offer((&picks_1), (&h_2), _e19);
        }
        continuing {
            let _e20 = bsh_cursor_next((&cur), x_7, r_7, rl_7);
            i_2 = _e20;
        }
    }
    let _e21 = picks_1;
    return _e21;
}

fn connect_record(l_2: GpuLight, x_8: vec3<f32>, n_6: vec3<f32>, ng_1: vec3<f32>, r2_2: f32, rt2_2: f32, w_res: f32, u1_2: f32, u2_2: f32, eps: f32, trace: bool) -> Connection {
    var c_5: Connection;
    var local_7: bool;
    var local_8: bool;

    c_5.e = vec3(0f);
    let _e16 = light_point(l_2, u1_2, u2_2);
    c_5.y = _e16;
    let _e19 = c_5.y;
    let _e20 = connection_cosine(x_8, _e19, n_6, ng_1, r2_2);
    c_5.cos_x = _e20;
    let _e22 = c_5.cos_x;
    if !((_e22 <= 0f)) {
        if trace {
            let _e33 = c_5.y;
            let _e34 = occluded((x_8 + (ng_1 * eps)), _e33);
            local_8 = _e34;
        } else {
            local_8 = false;
        }
        let _e36 = local_8;
        local_7 = _e36;
    } else {
        local_7 = true;
    }
    let _e38 = local_7;
    if _e38 {
        let _e39 = c_5;
        return _e39;
    }
    let _e41 = c_5.y;
    let v_6 = (x_8 - _e41);
    let d2_8 = dot(v_6, v_6);
    let _e48 = light_intensity(l_2, (v_6 / vec3(sqrt(d2_8))));
    let _e50 = c_5.cos_x;
    let _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_5.e = (_e48 * _e51);
    let _e53 = c_5;
    return _e53;
}

fn connect_traced(li: u32, x_9: vec3<f32>, n_7: vec3<f32>, ng_2: vec3<f32>, s_1: f32, w_res_1: f32, u1_3: f32, u2_3: f32, eps_1: f32, trace_1: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_3[li];
    let _e19 = rt2_3[li];
    let _e21 = connect_record(_e12, x_9, n_7, ng_2, (s_1 * _e15), (s_1 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_1);
    return _e21;
}

fn connect(li_1: u32, x_10: vec3<f32>, n_8: vec3<f32>, ng_3: vec3<f32>, s_2: f32, w_res_2: f32, u1_4: f32, u2_4: f32, eps_2: f32) -> Connection {
    let _e10 = connect_traced(li_1, x_10, n_8, ng_3, s_2, w_res_2, u1_4, u2_4, eps_2, true);
    return _e10;
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var h: u32;
    var e: vec3<f32> = vec3(0f);
    var s: u32 = 0u;

    let i_3 = gid.x;
    let _e4 = params.point_count;
    if (i_3 >= _e4) {
        return;
    }
    let p_2 = points[i_3];
    if (p_2.w <= 0f) {
        irradiance[i_3] = vec4(0f);
        return;
    }
    let x_11 = p_2.xyz;
    let _e19 = normals[i_3];
    let n_10 = _e19.xyz;
    let _e23 = params.seed;
    let _e26 = params.frame;
    let _e27 = point_stream(_e23, i_3, _e26);
    let _e33 = bsh_collect(x_11, x_11, vec4<f32>(1f, 0f, 1f, 1f), _e27);
    let _e36 = reservoir_weight(_e33.n, K);
    let _e37 = pick_stream(_e27);
    h = _e37;
    loop {
        let _e44 = s;
        if (_e44 < min(_e33.n, K)) {
        } else {
            break;
        }
        {
            let _e49 = h;
            let _e50 = pcg_hash(_e49);
            h = _e50;
            let _e51 = h;
            let _e52 = xi_from_bits(_e51);
            let _e53 = h;
            let _e54 = pcg_hash(_e53);
            h = _e54;
            let _e55 = e;
            let _e57 = s;
            let _e60 = h;
            let _e61 = xi_from_bits(_e60);
            let _e64 = params.eps;
            let _e65 = connect(_e33.light[_e57], x_11, n_10, n_10, 1f, _e36, _e52, _e61, _e64);
            e = (_e55 + _e65.e);
        }
        continuing {
            let _e69 = s;
            s = (_e69 + 1u);
        }
    }
    let _e73 = e;
    irradiance[i_3] = vec4<f32>(_e73, f32(_e33.n));
    return;
}
