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

@group(1) @binding(0) 
var<storage> slc_table: array<f32>;
@group(0) @binding(7) 
var<storage> geo_nodes: array<GpuGeoNode>;
@group(0) @binding(8) 
var<storage> geo_tris: array<GpuTriangle>;
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

fn f32_from_bits(u_1: u32) -> f32 {
    return bitcast<f32>(u_1);
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

fn sphere_contains_point(c: vec3<f32>, r: f32, x_2: vec3<f32>) -> bool {
    let v_2 = (x_2 - c);
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

fn connection_cosine(x_3: vec3<f32>, y: vec3<f32>, n: vec3<f32>, ng: vec3<f32>, r2_1: f32) -> f32 {
    var local: bool;
    var local_1: bool;

    let v_3 = (x_3 - y);
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

fn spot_falloff(cos_theta: f32, cos_outer: f32, cos_inner: f32, shape: f32) -> f32 {
    if (cos_inner <= cos_outer) {
        return select(0f, 1f, (cos_theta >= cos_outer));
    }
    let t_1 = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return select(((t_1 * t_1) * (3f - (2f * t_1))), (t_1 * t_1), (shape > 0.5f));
}

fn atan_portable(x_4: f32) -> f32 {
    var base: f32 = 0f;
    var t: f32;

    let a_8 = abs(x_4);
    t = a_8;
    if (a_8 > 2.4142137f) {
        base = 1.5707964f;
        t = (-1f / a_8);
    } else {
        if (a_8 > 0.41421357f) {
            base = 0.7853982f;
            t = ((a_8 - 1f) / (a_8 + 1f));
        }
    }
    let _e18 = t;
    let _e19 = t;
    let z = (_e18 * _e19);
    let _e21 = base;
    let _e33 = t;
    let _e35 = t;
    let r_8 = (_e21 + (((((((((0.080537446f * z) - 0.13877685f) * z) + 0.19977711f) * z) - 0.3333295f) * z) * _e33) + _e35));
    return select(r_8, -(r_8), (x_4 < 0f));
}

fn atan2_portable(y_1: f32, x_5: f32) -> f32 {
    if (x_5 == 0f) {
        if (y_1 > 0f) {
            return 1.5707964f;
        }
        if (y_1 < 0f) {
            return -1.5707964f;
        }
        return 0f;
    }
    let _e12 = atan_portable((y_1 / x_5));
    if (x_5 > 0f) {
        return _e12;
    }
    if (y_1 >= 0f) {
        return (_e12 + 3.1415927f);
    }
    return (_e12 - 3.1415927f);
}

fn ies_fold_c(c_1: f32, h_first: f32, h_last: f32) -> f32 {
    var a_2: f32;

    a_2 = (c_1 - (360f * floor((c_1 / 360f))));
    if (h_last <= 0f) {
        return 0f;
    }
    if (h_last <= 90f) {
        let _e15 = a_2;
        if (_e15 > 180f) {
            let _e18 = a_2;
            a_2 = (360f - _e18);
        }
        let _e21 = a_2;
        if (_e21 > 90f) {
            let _e24 = a_2;
            a_2 = (180f - _e24);
        }
        let _e27 = a_2;
        return _e27;
    }
    if (h_first >= 90f) {
        let _e30 = a_2;
        if (_e30 < 90f) {
            let _e33 = a_2;
            a_2 = (180f - _e33);
        } else {
            let _e36 = a_2;
            if (_e36 > 270f) {
                let _e39 = a_2;
                a_2 = (540f - _e39);
            }
        }
        let _e42 = a_2;
        return _e42;
    }
    if (h_last <= 180f) {
        let _e45 = a_2;
        if (_e45 > 180f) {
            let _e48 = a_2;
            a_2 = (360f - _e48);
        }
        let _e51 = a_2;
        return _e51;
    }
    let _e52 = a_2;
    return _e52;
}

fn ies_segment(tab_1: u32, start: u32, n_1: u32, x_6: f32) -> u32 {
    var lo: u32 = 0u;
    var hi: u32;

    if (n_1 < 2u) {
        return 0u;
    }
    hi = (n_1 - 1u);
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
            if (_e23 <= x_6) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
    let _e25 = lo;
    return _e25;
}

fn ies_lerp_t(a0_: f32, a1_: f32, x_7: f32) -> f32 {
    if (a1_ <= a0_) {
        return 0f;
    }
    return saturate(((x_7 - a0_) / (a1_ - a0_)));
}

fn ies_candela(tab_2: u32, base_1: u32, gamma: f32, c_2: f32) -> f32 {
    var local_2: bool;

    let _e4 = at(tab_2, base_1);
    let _e5 = to_u32_(_e4);
    let _e8 = at(tab_2, (base_1 + 1u));
    let _e9 = to_u32_(_e8);
    let v0_ = (base_1 + 2u);
    let h0_ = (v0_ + _e5);
    let c0_ = (h0_ + _e9);
    let _e14 = at(tab_2, v0_);
    if !((gamma < _e14)) {
        let _e22 = at(tab_2, ((v0_ + _e5) - 1u));
        local_2 = (gamma > _e22);
    } else {
        local_2 = true;
    }
    let _e25 = local_2;
    if _e25 {
        return 0f;
    }
    let _e27 = at(tab_2, h0_);
    let _e31 = at(tab_2, ((h0_ + _e9) - 1u));
    let _e32 = ies_fold_c(c_2, _e27, _e31);
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
    let _e58 = at(tab_2, ((c0_ + (_e34 * _e5)) + _e33));
    let _e65 = at(tab_2, ((c0_ + (_e34 * _e5)) + iv1_));
    let a_9 = ((_e58 * (1f - _e49)) + (_e65 * _e49));
    let _e71 = at(tab_2, ((c0_ + (ih1_ * _e5)) + _e33));
    let _e78 = at(tab_2, ((c0_ + (ih1_ * _e5)) + iv1_));
    let b_5 = ((_e71 * (1f - _e49)) + (_e78 * _e49));
    return ((a_9 * (1f - _e54)) + (b_5 * _e54));
}

fn ies_candela_dir(tab_3: u32, base_2: u32, wn: f32, wr: f32, ws: f32) -> f32 {
    let _e9 = atan2_portable(sqrt(((wr * wr) + (ws * ws))), wn);
    let gamma_1 = degrees(_e9);
    let on_axis = ((abs(wr) + abs(ws)) <= 0f);
    let _e16 = atan2_portable(ws, wr);
    let c_7 = select(degrees(_e16), 0f, on_axis);
    let _e20 = ies_candela(tab_3, base_2, gamma_1, c_7);
    return _e20;
}

fn ies_light_candela(tab_4: u32, base_3: u32, nadir: vec3<f32>, reference: vec3<f32>, w_1: vec3<f32>) -> f32 {
    let side = cross(reference, nadir);
    let _e9 = ies_candela_dir(tab_4, base_3, dot(w_1, nadir), dot(w_1, reference), dot(w_1, side));
    return _e9;
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

fn mul_hi_u32_(a_3: u32, b_2: u32) -> u32 {
    let a_lo = (a_3 & 65535u);
    let a_hi = (a_3 >> 16u);
    let b_lo = (b_2 & 65535u);
    let b_hi = (b_2 >> 16u);
    let ll = (a_lo * b_lo);
    let lh = (a_lo * b_hi);
    let hl = (a_hi * b_lo);
    let hh = (a_hi * b_hi);
    let mid_1 = (((ll >> 16u) + (lh & 65535u)) + (hl & 65535u));
    return (((hh + (lh >> 16u)) + (hl >> 16u)) + (mid_1 >> 16u));
}

fn uniform_index(n_2: u32, hi_1: u32, lo_1: u32) -> u32 {
    let _e3 = mul_lo_u32_(hi_1, n_2);
    let _e4 = mul_hi_u32_(hi_1, n_2);
    let _e5 = mul_hi_u32_(lo_1, n_2);
    if (_e3 > (4294967295u - _e5)) {
        return (_e4 + 1u);
    }
    return _e4;
}

fn reservoir_slot(n_3: u32, k: u32, hi_2: u32, lo_2: u32) -> u32 {
    if (n_3 <= k) {
        return (n_3 - 1u);
    }
    let _e7 = uniform_index(n_3, hi_2, lo_2);
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
    var local_3: bool;
    var local_4: bool;

    let vd = dot(v, d);
    let h2_ = (d2_4 - (a_4 * a_4));
    if !((h2_ <= 0f)) {
        if (vd >= 0f) {
            local_4 = ((vd * vd) >= h2_);
        } else {
            local_4 = false;
        }
        let _e19 = local_4;
        local_3 = _e19;
    } else {
        local_3 = true;
    }
    let _e21 = local_3;
    if _e21 {
        return 1f;
    }
    let c_8 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_8, c_8)) * a_4)) / d2_4), 1f);
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

fn range_scale_toward(rl_1: vec4<f32>, center_1: vec3<f32>, radius_1: f32, p_1: vec3<f32>, r_1: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_1, radius_1, p_1, r_1);
    let _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

fn shadow_margin(len: f32) -> f32 {
    return (0.0001f * len);
}

fn ray_inverse(x_8: f32) -> f32 {
    return (1f / select(x_8, 0.000000000000000000000000000001f, (abs(x_8) < 0.000000000000000000000000000001f)));
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
    let lo_3 = min(t0_, t1_);
    let hi_3 = max(t0_, t1_);
    let t_in = max(max(lo_3.x, lo_3.y), max(lo_3.z, 0f));
    let t_out = min(min(hi_3.x, hi_3.y), min(hi_3.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1f;
}

fn ray_triangle(o_1: vec3<f32>, d_3: vec3<f32>, a_5: vec3<f32>, b_3: vec3<f32>, c_3: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_5: bool;
    var local_6: bool;
    var local_7: bool;

    let e1_ = (b_3 - a_5);
    let e2_ = (c_3 - a_5);
    let p_2 = cross(d_3, e2_);
    let det = dot(e1_, p_2);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv = (1f / det);
    let s_3 = (o_1 - a_5);
    let u_2 = (dot(s_3, p_2) * inv);
    if !((u_2 < 0f)) {
        local_5 = (u_2 > 1f);
    } else {
        local_5 = true;
    }
    let _e28 = local_5;
    if _e28 {
        return -1f;
    }
    let q = cross(s_3, e1_);
    let v_5 = (dot(d_3, q) * inv);
    if !((v_5 < 0f)) {
        local_6 = ((u_2 + v_5) > 1f);
    } else {
        local_6 = true;
    }
    let _e42 = local_6;
    if _e42 {
        return -1f;
    }
    let t_3 = (dot(e2_, q) * inv);
    if (t_3 > t_min) {
        local_7 = (t_3 < t_max_1);
    } else {
        local_7 = false;
    }
    let _e51 = local_7;
    if _e51 {
        return t_3;
    }
    return -1f;
}

fn light_intensity(l: GpuLight, w_3: vec3<f32>) -> vec3<f32> {
    switch l.kind {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            let _e11 = spot_falloff(dot(l.p1_, w_3), l.a, l.b, l.p2_.x);
            return (l.intensity * _e11);
        }
        case 2u: {
            let _e18 = ies_light_candela(0u, l.ies_base, l.p1_, l.p2_, w_3);
            return (l.intensity * _e18);
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
    var node_3: u32 = 0u;
    var i_1: u32;

    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if (arrayLength((&geo_nodes)) == 0u) {
        let _e13 = hit;
        return _e13;
    }
    let _e14 = ray_inverse3_(d_4);
    loop {
        let _e21 = node_3;
        let n_9 = geo_nodes[_e21];
        let _e27 = hit.t;
        let _e28 = ray_aabb(o_2, _e14, n_9.bmin, n_9.bmax, _e27);
        if (_e28 >= 0f) {
            if (n_9.count > 0u) {
                i_1 = n_9.first;
                loop {
                    let _e36 = i_1;
                    if (_e36 < (n_9.first + n_9.count)) {
                    } else {
                        break;
                    }
                    {
                        let _e42 = i_1;
                        let t_4 = geo_tris[_e42];
                        let _e49 = hit.t;
                        let _e50 = ray_triangle(o_2, d_4, t_4.v0_, t_4.v1_, t_4.v2_, t_min_1, _e49);
                        if (_e50 > 0f) {
                            hit.t = _e50;
                            let _e55 = i_1;
                            hit.tri = _e55;
                            if any_hit {
                                let _e56 = hit;
                                return _e56;
                            }
                        }
                    }
                    continuing {
                        let _e58 = i_1;
                        i_1 = (_e58 + 1u);
                    }
                }
            } else {
                let _e60 = sp;
                if (_e60 < 64u) {
                    let _e63 = sp;
                    stack[_e63] = (n_9.first + 1u);
                    let _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_9.first;
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

fn occluded(a_6: vec3<f32>, b_4: vec3<f32>) -> bool {
    let dv = (b_4 - a_6);
    let len_1 = length(dv);
    if (len_1 <= 0f) {
        return false;
    }
    let _e7 = shadow_margin(len_1);
    let _e12 = trace(a_6, (dv / vec3(len_1)), _e7, (len_1 - _e7), true);
    return (_e12.tri != NO_LIGHT);
}

fn bsh_node(nodes: u32, i_2: u32) -> BshNode {
    let _e4 = bsh_nodes[i_2];
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

fn bsh_reaches(node_4: BshNode, x_9: vec3<f32>, r_3: vec3<f32>, rl_3: vec4<f32>) -> bool {
    var local_8: bool;
    var local_9: bool;

    let _e6 = sphere_contains_point(node_4.center, node_4.radius, x_9);
    if _e6 {
        return true;
    }
    if !((rl_3.w <= 1f)) {
        let _e20 = sphere_contains_point(node_4.center, (node_4.radius * (rl_3.w * 1.0001f)), x_9);
        local_8 = !(_e20);
    } else {
        local_8 = true;
    }
    let _e23 = local_8;
    if _e23 {
        return false;
    }
    let v_6 = (x_9 - node_4.center);
    let d2_7 = dot(v_6, v_6);
    let _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_7 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        let _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_9, r_3);
        let _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        let _e42 = sphere_contains_point(node_4.center, _e41, x_9);
        return _e42;
    }
    let _e45 = bsh_inner_scale(node_4.extent, -(v_6), d2_7, r_3, rl_3);
    let s_c = (_e45 * 1.001f);
    let _e50 = bsh_range_bound(node_4);
    let reach = (node_4.extent + (sqrt(s_c) * _e50));
    if (d2_7 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_9 = (d2_7 <= (reach * reach));
    } else {
        local_9 = false;
    }
    let _e63 = local_9;
    return _e63;
}

fn bsh_next_leaf_lobe(nodes_3: u32, start_1: u32, x_10: vec3<f32>, r_4: vec3<f32>, rl_4: vec4<f32>) -> u32 {
    var i_3: u32;

    i_3 = start_1;
    loop {
        let _e6 = i_3;
        if (_e6 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e9 = i_3;
            let _e10 = bsh_node(nodes_3, _e9);
            let _e11 = bsh_reaches(_e10, x_10, r_4, rl_4);
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
    return BSH_NONE;
}

fn bsh_cursor(x_11: vec3<f32>, r_5: vec3<f32>, rl_5: vec4<f32>) -> BshCursor {
    var c_4: BshCursor;

    c_4.i = 0u;
    c_4.end = 0u;
    let _e10 = bsh_first(BSH);
    c_4.next = _e10;
    c_4.cone = vec2(0f);
    let _e14 = c_4;
    return _e14;
}

fn bsh_cursor_next(c_5: ptr<function, BshCursor>, x_12: vec3<f32>, r_6: vec3<f32>, rl_6: vec4<f32>) -> u32 {
    let _e6 = (*c_5).next;
    let _e7 = bsh_next_leaf_lobe(BSH, _e6, x_12, r_6, rl_6);
    if (_e7 != BSH_NONE) {
        let _e14 = bsh_nodes[_e7].next;
        (*c_5).next = _e14;
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
        let hi_4 = (*h_1);
        let _e13 = (*h_1);
        let _e14 = pcg_hash(_e13);
        (*h_1) = _e14;
        let _e16 = (*picks).n;
        let _e18 = (*h_1);
        let _e19 = reservoir_slot(_e16, K, hi_4, _e18);
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

fn bsh_collect(x_13: vec3<f32>, r_7: vec3<f32>, rl_7: vec4<f32>, seed_1: u32) -> Picks {
    var picks_1: Picks;
    var h_2: u32;
    var cur: BshCursor;
    var i_4: u32;

    picks_1.n = 0u;
    h_2 = seed_1;
    let _e8 = bsh_cursor(x_13, r_7, rl_7);
    cur = _e8;
    let _e10 = bsh_cursor_next((&cur), x_13, r_7, rl_7);
    i_4 = _e10;
    loop {
        let _e12 = i_4;
        if (_e12 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e16 = i_4;
            let _e19 = bsh_nodes[_e16].light;
            reservoir_offer((&picks_1), (&h_2), _e19);
        }
        continuing {
            let _e20 = bsh_cursor_next((&cur), x_13, r_7, rl_7);
            i_4 = _e20;
        }
    }
    let _e21 = picks_1;
    return _e21;
}

fn connect_record(l_2: GpuLight, x_14: vec3<f32>, n_6: vec3<f32>, ng_1: vec3<f32>, r2_2: f32, rt2_2: f32, w_res: f32, u1_1: f32, u2_1: f32, eps: f32, trace_1: bool) -> Connection {
    var c_6: Connection;
    var local_10: bool;
    var local_11: bool;

    c_6.e = vec3(0f);
    let _e16 = light_point(l_2, u1_1, u2_1);
    c_6.y = _e16;
    let _e19 = c_6.y;
    let _e20 = connection_cosine(x_14, _e19, n_6, ng_1, r2_2);
    c_6.cos_x = _e20;
    let _e22 = c_6.cos_x;
    if !((_e22 <= 0f)) {
        if trace_1 {
            let _e33 = c_6.y;
            let _e34 = occluded((x_14 + (ng_1 * eps)), _e33);
            local_11 = _e34;
        } else {
            local_11 = false;
        }
        let _e36 = local_11;
        local_10 = _e36;
    } else {
        local_10 = true;
    }
    let _e38 = local_10;
    if _e38 {
        let _e39 = c_6;
        return _e39;
    }
    let _e41 = c_6.y;
    let v_7 = (x_14 - _e41);
    let d2_8 = dot(v_7, v_7);
    let _e48 = light_intensity(l_2, (v_7 / vec3(sqrt(d2_8))));
    let _e50 = c_6.cos_x;
    let _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_6.e = (_e48 * _e51);
    let _e53 = c_6;
    return _e53;
}

fn connect_traced(li: u32, x_15: vec3<f32>, n_7: vec3<f32>, ng_2: vec3<f32>, s_1: f32, w_res_1: f32, u1_2: f32, u2_2: f32, eps_1: f32, trace_2: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_3[li];
    let _e19 = rt2_3[li];
    let _e21 = connect_record(_e12, x_15, n_7, ng_2, (s_1 * _e15), (s_1 * _e19), w_res_1, u1_2, u2_2, eps_1, trace_2);
    return _e21;
}

fn connect(li_1: u32, x_16: vec3<f32>, n_8: vec3<f32>, ng_3: vec3<f32>, s_2: f32, w_res_2: f32, u1_3: f32, u2_3: f32, eps_2: f32) -> Connection {
    let _e10 = connect_traced(li_1, x_16, n_8, ng_3, s_2, w_res_2, u1_3, u2_3, eps_2, true);
    return _e10;
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var h: u32;
    var e: vec3<f32> = vec3(0f);
    var s: u32 = 0u;

    let i_5 = gid.x;
    let _e4 = params.point_count;
    if (i_5 >= _e4) {
        return;
    }
    let p_3 = points[i_5];
    if (p_3.w <= 0f) {
        irradiance[i_5] = vec4(0f);
        return;
    }
    let x_17 = p_3.xyz;
    let _e19 = normals[i_5];
    let n_10 = _e19.xyz;
    let _e23 = params.seed;
    let _e26 = params.frame;
    let _e27 = point_stream(_e23, i_5, _e26);
    let _e33 = bsh_collect(x_17, x_17, vec4<f32>(1f, 0f, 1f, 1f), _e27);
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
            let _e65 = connect(_e33.light[_e57], x_17, n_10, n_10, 1f, _e36, _e52, _e61, _e64);
            e = (_e55 + _e65.e);
        }
        continuing {
            let _e69 = s;
            s = (_e69 + 1u);
        }
    }
    let _e73 = e;
    irradiance[i_5] = vec4<f32>(_e73, f32(_e33.n));
    return;
}
