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

struct Picks {
    light: array<u32, 8>,
    n: u32,
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

@group(1) @binding(0) 
var<storage> slc_table: array<f32>;
@group(0) @binding(0) 
var<uniform> view: ViewParams;
@group(0) @binding(1) 
var position_tex: texture_2d<f32>;
@group(0) @binding(2) 
var normal_tex: texture_2d<f32>;
@group(0) @binding(3) 
var out_tex: texture_storage_2d<rgba32float,write>;
@group(1) @binding(1) 
var<storage> lights: array<GpuLight>;
@group(1) @binding(2) 
var<storage> rt2_3: array<f32>;
@group(1) @binding(3) 
var<storage> r2_3: array<f32>;
@group(1) @binding(4) 
var<storage> bsh_nodes: array<BshNode>;
var<workgroup> wg_lo: array<vec3<f32>, 64>;
var<workgroup> wg_hi: array<vec3<f32>, 64>;
var<workgroup> wg_box: WorkgroupBox;
var<workgroup> tile_list: array<u32, 1024>;
var<workgroup> subtree_at: array<u32, 256>;
var<workgroup> tile_scale: atomic<u32>;
var<workgroup> tile_total: u32;

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

fn sphere_contains_point(c: vec3<f32>, r_1: f32, x_2: vec3<f32>) -> bool {
    let v_2 = (x_2 - c);
    return (dot(v_2, v_2) <= (r_1 * r_1));
}

fn sphere_overlaps_aabb(c_1: vec3<f32>, r_2: f32, bmin: vec3<f32>, bmax: vec3<f32>) -> bool {
    let q = clamp(c_1, bmin, bmax);
    let v_3 = (q - c_1);
    return (dot(v_3, v_3) <= (r_2 * r_2));
}

fn inverse_square(d2_2: f32) -> f32 {
    return (1f / max(d2_2, MIN_D2_));
}

fn connection_factor(cos_x: f32, d2_3: f32, rt2_1: f32, w: f32) -> f32 {
    let _e4 = inverse_square(d2_3);
    let _e6 = slc_weight(rt2_1, d2_3);
    return (((cos_x * _e4) * _e6) * w);
}

fn connection_cosine(x_3: vec3<f32>, y: vec3<f32>, n_1: vec3<f32>, ng: vec3<f32>, r2_1: f32) -> f32 {
    var local_5: bool;
    var local_6: bool;

    let v_4 = (x_3 - y);
    let d2_6 = dot(v_4, v_4);
    let _e7 = slc_keep(r2_1, d2_6);
    if !(!(_e7)) {
        local_5 = !((d2_6 > 0f));
    } else {
        local_5 = true;
    }
    let _e16 = local_5;
    if _e16 {
        return 0f;
    }
    let w_10 = (v_4 / vec3(sqrt(d2_6)));
    let cos_x_1 = -(dot(n_1, w_10));
    if !(!((cos_x_1 > 0f))) {
        local_6 = !((dot(ng, w_10) < 0f));
    } else {
        local_6 = true;
    }
    let _e34 = local_6;
    if _e34 {
        return 0f;
    }
    return cos_x_1;
}

fn spot_falloff(cos_theta: f32, cos_outer: f32, cos_inner: f32, shape: f32) -> f32 {
    if (cos_inner <= cos_outer) {
        return select(0f, 1f, (cos_theta >= cos_outer));
    }
    let t_5 = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return select(((t_5 * t_5) * (3f - (2f * t_5))), (t_5 * t_5), (shape > 0.5f));
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

fn atan_portable(x_4: f32) -> f32 {
    var base: f32 = 0f;
    var t_1: f32;

    let a_10 = abs(x_4);
    t_1 = a_10;
    if (a_10 > 2.4142137f) {
        base = 1.5707964f;
        t_1 = (-1f / a_10);
    } else {
        if (a_10 > 0.41421357f) {
            base = 0.7853982f;
            t_1 = ((a_10 - 1f) / (a_10 + 1f));
        }
    }
    let _e18 = t_1;
    let _e19 = t_1;
    let z = (_e18 * _e19);
    let _e21 = base;
    let _e33 = t_1;
    let _e35 = t_1;
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

fn ies_fold_c(c_3: f32, h_first: f32, h_last: f32) -> f32 {
    var a_3: f32;

    a_3 = (c_3 - (360f * floor((c_3 / 360f))));
    if (h_last <= 0f) {
        return 0f;
    }
    if (h_last <= 90f) {
        let _e15 = a_3;
        if (_e15 > 180f) {
            let _e18 = a_3;
            a_3 = (360f - _e18);
        }
        let _e21 = a_3;
        if (_e21 > 90f) {
            let _e24 = a_3;
            a_3 = (180f - _e24);
        }
        let _e27 = a_3;
        return _e27;
    }
    if (h_first >= 90f) {
        let _e30 = a_3;
        if (_e30 < 90f) {
            let _e33 = a_3;
            a_3 = (180f - _e33);
        } else {
            let _e36 = a_3;
            if (_e36 > 270f) {
                let _e39 = a_3;
                a_3 = (540f - _e39);
            }
        }
        let _e42 = a_3;
        return _e42;
    }
    if (h_last <= 180f) {
        let _e45 = a_3;
        if (_e45 > 180f) {
            let _e48 = a_3;
            a_3 = (360f - _e48);
        }
        let _e51 = a_3;
        return _e51;
    }
    let _e52 = a_3;
    return _e52;
}

fn ies_segment(tab_1: u32, start_1: u32, n_3: u32, x_6: f32) -> u32 {
    var lo: u32 = 0u;
    var hi: u32;

    if (n_3 < 2u) {
        return 0u;
    }
    hi = (n_3 - 1u);
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
            let _e23 = at(tab_1, (start_1 + mid));
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

fn ies_candela(tab_2: u32, base_1: u32, gamma: f32, c_4: f32) -> f32 {
    var local_7: bool;

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
        local_7 = (gamma > _e22);
    } else {
        local_7 = true;
    }
    let _e25 = local_7;
    if _e25 {
        return 0f;
    }
    let _e27 = at(tab_2, h0_);
    let _e31 = at(tab_2, ((h0_ + _e9) - 1u));
    let _e32 = ies_fold_c(c_4, _e27, _e31);
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
    let a_11 = ((_e58 * (1f - _e49)) + (_e65 * _e49));
    let _e71 = at(tab_2, ((c0_ + (ih1_ * _e5)) + _e33));
    let _e78 = at(tab_2, ((c0_ + (ih1_ * _e5)) + iv1_));
    let b_9 = ((_e71 * (1f - _e49)) + (_e78 * _e49));
    return ((a_11 * (1f - _e54)) + (b_9 * _e54));
}

fn ies_candela_dir(tab_3: u32, base_2: u32, wn: f32, wr: f32, ws: f32) -> f32 {
    let _e9 = atan2_portable(sqrt(((wr * wr) + (ws * ws))), wn);
    let gamma_1 = degrees(_e9);
    let on_axis = ((abs(wr) + abs(ws)) <= 0f);
    let _e16 = atan2_portable(ws, wr);
    let c_8 = select(degrees(_e16), 0f, on_axis);
    let _e20 = ies_candela(tab_3, base_2, gamma_1, c_8);
    return _e20;
}

fn ies_light_candela(tab_4: u32, base_3: u32, nadir: vec3<f32>, reference: vec3<f32>, w_2: vec3<f32>) -> f32 {
    let side = cross(reference, nadir);
    let _e9 = ies_candela_dir(tab_4, base_3, dot(w_2, nadir), dot(w_2, reference), dot(w_2, side));
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

fn bsh_reach_bound(node_2: BshNode, w_3: f32) -> f32 {
    let _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_3 * 1.001f) * _e5));
}

fn mul_hi_u32_(a_4: u32, b_3: u32) -> u32 {
    let a_lo = (a_4 & 65535u);
    let a_hi = (a_4 >> 16u);
    let b_lo = (b_3 & 65535u);
    let b_hi = (b_3 >> 16u);
    let ll = (a_lo * b_lo);
    let lh = (a_lo * b_hi);
    let hl = (a_hi * b_lo);
    let hh = (a_hi * b_hi);
    let mid_1 = (((ll >> 16u) + (lh & 65535u)) + (hl & 65535u));
    return (((hh + (lh >> 16u)) + (hl >> 16u)) + (mid_1 >> 16u));
}

fn uniform_index(n_4: u32, hi_1: u32, lo_1: u32) -> u32 {
    let _e3 = mul_lo_u32_(hi_1, n_4);
    let _e4 = mul_hi_u32_(hi_1, n_4);
    let _e5 = mul_hi_u32_(lo_1, n_4);
    if (_e3 > (4294967295u - _e5)) {
        return (_e4 + 1u);
    }
    return _e4;
}

fn reservoir_slot(n_5: u32, k_1: u32, hi_2: u32, lo_2: u32) -> u32 {
    if (n_5 <= k_1) {
        return (n_5 - 1u);
    }
    let _e7 = uniform_index(n_5, hi_2, lo_2);
    if (_e7 < k_1) {
        return _e7;
    }
    return k_1;
}

fn reservoir_takes(n_6: u32) -> bool {
    return (n_6 < RESERVOIR_FULL);
}

fn reservoir_weight(n_7: u32, k_2: u32) -> f32 {
    let _e2 = to_f32_(n_7);
    let _e3 = to_f32_(k_2);
    return max((_e2 / _e3), 1f);
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

fn cone_cos_of(v: vec3<f32>, d2_4: f32, a_5: f32, d: vec3<f32>) -> f32 {
    var local_8: bool;
    var local_9: bool;

    let vd = dot(v, d);
    let h2_ = (d2_4 - (a_5 * a_5));
    if !((h2_ <= 0f)) {
        if (vd >= 0f) {
            local_9 = ((vd * vd) >= h2_);
        } else {
            local_9 = false;
        }
        let _e19 = local_9;
        local_8 = _e19;
    } else {
        local_8 = true;
    }
    let _e21 = local_8;
    if _e21 {
        return 1f;
    }
    let c_9 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_9, c_9)) * a_5)) / d2_4), 1f);
}

fn cone_cos_toward(center: vec3<f32>, radius: f32, p: vec3<f32>, d_1: vec3<f32>) -> f32 {
    let v_5 = (center - p);
    let _e6 = cone_cos_of(v_5, dot(v_5, v_5), radius, d_1);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_6 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_6 * t_6))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_1: vec3<f32>, radius_1: f32, p_1: vec3<f32>, r_3: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_1, radius_1, p_1, r_3);
    let _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

fn triangle_normal(a_6: vec3<f32>, b_4: vec3<f32>, c_5: vec3<f32>) -> vec3<f32> {
    var local_10: bool;

    let n_13 = cross((b_4 - a_6), (c_5 - a_6));
    let l2_ = dot(n_13, n_13);
    if !(!((l2_ > 0f))) {
        local_10 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_10 = true;
    }
    let _e17 = local_10;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_13 / vec3(sqrt(l2_)));
}

fn light_intensity(l: GpuLight, w_4: vec3<f32>) -> vec3<f32> {
    switch l.kind {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            let _e11 = spot_falloff(dot(l.p1_, w_4), l.a, l.b, l.p2_.x);
            return (l.intensity * _e11);
        }
        case 2u: {
            let _e18 = ies_light_candela(0u, l.ies_base, l.p1_, l.p2_, w_4);
            return (l.intensity * _e18);
        }
        case 3u: {
            let _e24 = triangle_normal(l.p0_, l.p1_, l.p2_);
            let _e26 = triangle_lobe(_e24, l.a, w_4);
            return (l.intensity * _e26);
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

fn occluded(a_7: vec3<f32>, b_5: vec3<f32>) -> bool {
    return false;
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

fn bsh_inner_scale(a_8: f32, v_1: vec3<f32>, d2_5: f32, r_4: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let _e5 = cone_cos_of(v_1, d2_5, a_8, r_4);
    let _e8 = range_scale_at(rl_2, (_e5 + 0.000002f));
    return _e8;
}

fn bsh_reaches(node_3: BshNode, x_8: vec3<f32>, r_5: vec3<f32>, rl_3: vec4<f32>) -> bool {
    var local_11: bool;
    var local_12: bool;

    let _e6 = sphere_contains_point(node_3.center, node_3.radius, x_8);
    if _e6 {
        return true;
    }
    if !((rl_3.w <= 1f)) {
        let _e20 = sphere_contains_point(node_3.center, (node_3.radius * (rl_3.w * 1.0001f)), x_8);
        local_11 = !(_e20);
    } else {
        local_11 = true;
    }
    let _e23 = local_11;
    if _e23 {
        return false;
    }
    let v_6 = (x_8 - node_3.center);
    let d2_7 = dot(v_6, v_6);
    let _e29 = bsh_reach_bound(node_3, rl_3.w);
    if (d2_7 > (_e29 * _e29)) {
        return false;
    }
    if (node_3.child == BSH_NONE) {
        let _e38 = range_scale_toward(rl_3, node_3.center, node_3.extent, x_8, r_5);
        let _e41 = bsh_scaled_radius(node_3, sqrt(_e38));
        let _e42 = sphere_contains_point(node_3.center, _e41, x_8);
        return _e42;
    }
    let _e45 = bsh_inner_scale(node_3.extent, -(v_6), d2_7, r_5, rl_3);
    let s_c = (_e45 * 1.001f);
    let _e50 = bsh_range_bound(node_3);
    let reach = (node_3.extent + (sqrt(s_c) * _e50));
    if (d2_7 <= ((node_3.radius * node_3.radius) * s_c)) {
        local_12 = (d2_7 <= (reach * reach));
    } else {
        local_12 = false;
    }
    let _e63 = local_12;
    return _e63;
}

fn bsh_reaches_box(node_4: BshNode, lo_3: vec3<f32>, hi_3: vec3<f32>, w_5: f32) -> bool {
    let _e13 = sphere_overlaps_aabb(node_4.center, (node_4.radius * (max(1f, (w_5 * 1.0001f)) * 1.0001f)), lo_3, hi_3);
    return _e13;
}

fn bsh_subtree(nodes_3: u32, s_1: u32, depth: u32) -> u32 {
    var i_2: u32;
    var level: u32 = 0u;
    var local_13: bool;

    let _e3 = bsh_first(nodes_3);
    i_2 = _e3;
    loop {
        let _e7 = level;
        if (_e7 < depth) {
            let _e11 = i_2;
            local_13 = (_e11 != BSH_NONE);
        } else {
            local_13 = false;
        }
        let _e15 = local_13;
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

fn bsh_next_leaf_box(nodes_4: u32, start_2: u32, end: u32, lo_4: vec3<f32>, hi_4: vec3<f32>, w_6: f32) -> u32 {
    var i_3: u32;

    i_3 = start_2;
    loop {
        let _e7 = i_3;
        if (_e7 != end) {
        } else {
            break;
        }
        {
            let _e9 = i_3;
            let _e10 = bsh_node(nodes_4, _e9);
            let _e11 = bsh_reaches_box(_e10, lo_4, hi_4, w_6);
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

fn reservoir_offer(picks_1: ptr<function, Picks>, h_1: ptr<function, u32>, light: u32) {
    let _e4 = (*picks_1).n;
    let _e5 = reservoir_takes(_e4);
    if _e5 {
        let _e7 = (*picks_1).n;
        (*picks_1).n = (_e7 + 1u);
        let _e10 = (*h_1);
        let _e11 = pcg_hash(_e10);
        (*h_1) = _e11;
        let hi_6 = (*h_1);
        let _e13 = (*h_1);
        let _e14 = pcg_hash(_e13);
        (*h_1) = _e14;
        let _e16 = (*picks_1).n;
        let _e18 = (*h_1);
        let _e19 = reservoir_slot(_e16, K, hi_6, _e18);
        if (_e19 < K) {
            (*picks_1).light[_e19] = light;
            return;
        } else {
            return;
        }
    } else {
        return;
    }
}

fn connect_record(l_2: GpuLight, x_9: vec3<f32>, n_8: vec3<f32>, ng_1: vec3<f32>, r2_2: f32, rt2_2: f32, w_res: f32, u1_2: f32, u2_2: f32, eps: f32, trace: bool) -> Connection {
    var c_6: Connection;
    var local_14: bool;
    var local_15: bool;

    c_6.e = vec3(0f);
    let _e16 = light_point(l_2, u1_2, u2_2);
    c_6.y = _e16;
    let _e19 = c_6.y;
    let _e20 = connection_cosine(x_9, _e19, n_8, ng_1, r2_2);
    c_6.cos_x = _e20;
    let _e22 = c_6.cos_x;
    if !((_e22 <= 0f)) {
        if trace {
            let _e33 = c_6.y;
            let _e34 = occluded((x_9 + (ng_1 * eps)), _e33);
            local_15 = _e34;
        } else {
            local_15 = false;
        }
        let _e36 = local_15;
        local_14 = _e36;
    } else {
        local_14 = true;
    }
    let _e38 = local_14;
    if _e38 {
        let _e39 = c_6;
        return _e39;
    }
    let _e41 = c_6.y;
    let v_7 = (x_9 - _e41);
    let d2_8 = dot(v_7, v_7);
    let _e48 = light_intensity(l_2, (v_7 / vec3(sqrt(d2_8))));
    let _e50 = c_6.cos_x;
    let _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_6.e = (_e48 * _e51);
    let _e53 = c_6;
    return _e53;
}

fn connect_traced(li: u32, x_10: vec3<f32>, n_9: vec3<f32>, ng_2: vec3<f32>, s_2: f32, w_res_1: f32, u1_3: f32, u2_3: f32, eps_1: f32, trace_1: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_3[li];
    let _e19 = rt2_3[li];
    let _e21 = connect_record(_e12, x_10, n_9, ng_2, (s_2 * _e15), (s_2 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_1);
    return _e21;
}

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p_5 = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p_5.xyz, 1f), (p_5.w > 0f));
}

fn workgroup_bounds(li_1: u32, lo_5: vec3<f32>, hi_5: vec3<f32>) -> WorkgroupBox {
    var stride: u32 = 32u;

    wg_lo[li_1] = lo_5;
    wg_hi[li_1] = hi_5;
    workgroupBarrier();
    loop {
        let _e9 = stride;
        if (_e9 > 0u) {
        } else {
            break;
        }
        {
            let _e12 = stride;
            if (li_1 < _e12) {
                let _e18 = wg_lo[li_1];
                let _e20 = stride;
                let _e23 = wg_lo[(li_1 + _e20)];
                wg_lo[li_1] = min(_e18, _e23);
                let _e29 = wg_hi[li_1];
                let _e31 = stride;
                let _e34 = wg_hi[(li_1 + _e31)];
                wg_hi[li_1] = max(_e29, _e34);
            }
            workgroupBarrier();
        }
        continuing {
            let _e36 = stride;
            stride = (_e36 / 2u);
        }
    }
    if (li_1 == 0u) {
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

fn workgroup_box(li_2: u32, p_3: vec3<f32>, has_1: bool) -> WorkgroupBox {
    let _e3 = point_box(p_3, has_1);
    let _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi);
    return _e6;
}

fn box_is_empty(b_6: WorkgroupBox) -> bool {
    return (b_6.lo.x > b_6.hi.x);
}

fn tile_subtree(s_3: u32, t_2: TileWalk, list: bool, at_1: u32, start_3: u32, to: u32) -> u32 {
    var p_4: u32;
    var b_7: u32;
    var local_16: bool;
    var local_17: bool;
    var local_18: bool;

    let _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH);
    if (_e8 == BSH_NONE) {
        return 0u;
    }
    let end_1 = bsh_nodes[_e8].next;
    p_4 = at_1;
    let _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_2.lo, t_2.hi, t_2.w);
    b_7 = _e21;
    loop {
        let _e23 = b_7;
        if (_e23 != end_1) {
            if !(!(list)) {
                let _e31 = p_4;
                local_17 = (_e31 < to);
            } else {
                local_17 = true;
            }
            let _e34 = local_17;
            local_16 = _e34;
        } else {
            local_16 = false;
        }
        let _e36 = local_16;
        if _e36 {
        } else {
            break;
        }
        {
            if list {
                let _e39 = p_4;
                local_18 = (_e39 >= start_3);
            } else {
                local_18 = false;
            }
            let _e42 = local_18;
            if _e42 {
                let _e44 = p_4;
                let _e47 = b_7;
                tile_list[(_e44 - start_3)] = _e47;
            }
            let _e48 = p_4;
            p_4 = (_e48 + 1u);
        }
        continuing {
            let _e53 = b_7;
            let _e56 = bsh_nodes[_e53].next;
            let _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_2.lo, t_2.hi, t_2.w);
            b_7 = _e60;
        }
    }
    let _e61 = p_4;
    return (_e61 - at_1);
}

fn tile_walk_begin(li_3: u32, x_11: vec3<f32>, w_7: f32, has_2: bool) -> TileWalk {
    var local_19: bool;
    var t_3: TileWalk;
    var s_4: u32;
    var sum: u32 = 0u;
    var s_5: u32 = 0u;

    if has_2 {
        local_19 = (w_7 >= 0f);
    } else {
        local_19 = false;
    }
    let _e12 = local_19;
    let _e14 = atomicMax((&tile_scale), select(0u, bitcast<u32>(w_7), _e12));
    let _e15 = workgroup_box(li_3, x_11, has_2);
    let _e19 = workgroupUniformLoad((&tile_scale));
    t_3 = TileWalk(_e15.lo, _e15.hi, bitcast<f32>(_e19), 0u);
    let _e24 = box_is_empty(_e15);
    if _e24 {
        let _e25 = t_3;
        return _e25;
    }
    s_4 = li_3;
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
    if (li_3 == 0u) {
        loop {
            let _e49 = s_5;
            if (_e49 < BSH_TILE_SUBTREES) {
            } else {
                break;
            }
            {
                let _e53 = s_5;
                let c_10 = subtree_at[_e53];
                let _e57 = s_5;
                let _e59 = sum;
                subtree_at[_e57] = _e59;
                let _e60 = sum;
                sum = (_e60 + c_10);
            }
            continuing {
                let _e63 = s_5;
                s_5 = (_e63 + 1u);
            }
        }
        let _e66 = sum;
        tile_total = _e66;
    }
    let _e69 = workgroupUniformLoad((&tile_total));
    t_3.total = _e69;
    let _e70 = t_3;
    return _e70;
}

fn tile_walk_fill(li_4: u32, t_4: TileWalk, start_4: u32) -> u32 {
    var s_6: u32;
    var past: u32;
    var local_20: bool;

    let to_1 = min(t_4.total, (start_4 + TILE_LIST));
    s_6 = li_4;
    loop {
        let _e8 = s_6;
        if (_e8 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            let _e12 = s_6;
            let at_2 = subtree_at[_e12];
            past = t_4.total;
            let _e17 = s_6;
            if ((_e17 + 1u) < BSH_TILE_SUBTREES) {
                let _e23 = s_6;
                let _e27 = subtree_at[(_e23 + 1u)];
                past = _e27;
            }
            if (at_2 < to_1) {
                let _e31 = past;
                local_20 = (_e31 > start_4);
            } else {
                local_20 = false;
            }
            let _e34 = local_20;
            if _e34 {
                let _e35 = s_6;
                let _e37 = tile_subtree(_e35, t_4, true, at_2, start_4, to_1);
            }
        }
        continuing {
            let _e38 = s_6;
            s_6 = (_e38 + TILE_THREADS);
        }
    }
    workgroupBarrier();
    return (to_1 - start_4);
}

fn shade_connection(c_7: Connection, x_12: vec3<f32>, n_10: vec3<f32>, m_1: Material) -> Shaded {
    var s_7: Shaded;

    s_7.e = c_7.e;
    s_7.diffuse = vec3(0f);
    s_7.specular = vec3(0f);
    let _e13 = s_7;
    return _e13;
}

fn shade_pick_traced(li_5: u32, x_13: vec3<f32>, n_11: vec3<f32>, r_6: vec3<f32>, rl_4: vec4<f32>, m_2: Material, w_8: f32, u1_4: f32, u2_4: f32, eps_2: f32, trace_2: bool) -> Shaded {
    let _e12 = connect_traced(li_5, x_13, n_11, n_11, 1f, w_8, u1_4, u2_4, eps_2, trace_2);
    let _e13 = shade_connection(_e12, x_13, n_11, m_2);
    return _e13;
}

fn shade_pick(li_6: u32, x_14: vec3<f32>, n_12: vec3<f32>, r_7: vec3<f32>, rl_5: vec4<f32>, m_3: Material, w_9: f32, u1_5: f32, u2_5: f32, eps_3: f32) -> Shaded {
    let _e11 = shade_pick_traced(li_6, x_14, n_12, r_7, rl_5, m_3, w_9, u1_5, u2_5, eps_3, true);
    return _e11;
}

fn add(a_9: Shaded, b_8: Shaded) -> Shaded {
    return Shaded((a_9.e + b_8.e), (a_9.diffuse + b_8.diffuse), (a_9.specular + b_8.specular));
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
    var picks: Picks;
    var hr: u32;
    var start: u32 = 0u;
    var j: u32;
    var local_4: bool;
    var k: u32 = 0u;

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
    let x_15 = _e35.xyz;
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
        local_3 = all((abs(x_15) <= vec3(340282350000000000000000000000000000000f)));
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
    let _e78 = lobe;
    let _e79 = range_lobe(_e78);
    let _e82 = view.shadow_offset;
    let _e85 = view.eye;
    let eps_4 = (_e82 * length((_e85 - x_15)));
    let _e91 = view.seed;
    let _e95 = view.width;
    let _e101 = view.frame;
    let _e102 = point_stream(_e91, ((gid.y * _e95) + gid.x), _e101);
    let _e103 = pick_stream(_e102);
    h = _e103;
    picks.n = 0u;
    hr = _e102;
    let _e118 = tile_walk_begin(lid, x_15, _e79.w, has_3);
    loop {
        let _e121 = start;
        if (_e121 < _e118.total) {
        } else {
            break;
        }
        {
            let _e124 = start;
            let _e125 = tile_walk_fill(lid, _e118, _e124);
            j = 0u;
            loop {
                let _e128 = j;
                if (_e128 < _e125) {
                } else {
                    break;
                }
                {
                    let _e131 = j;
                    let b_10 = tile_list[_e131];
                    if !(!(has_3)) {
                        let _e140 = bsh_nodes[b_10];
                        let _e141 = r;
                        let _e142 = bsh_reaches(_e140, x_15, _e141, _e79);
                        local_4 = !(_e142);
                    } else {
                        local_4 = true;
                    }
                    let _e145 = local_4;
                    if _e145 {
                        continue;
                    }
                    let li_7 = bsh_nodes[b_10].light;
                    reservoir_offer((&picks), (&hr), li_7);
                }
                continuing {
                    let _e151 = j;
                    j = (_e151 + 1u);
                }
            }
            workgroupBarrier();
        }
        continuing {
            let _e153 = start;
            start = (_e153 + TILE_LIST);
        }
    }
    if !(has_3) {
        if inside {
            textureStore(out_tex, texel_1, vec4(0f));
        }
        return;
    }
    let _e161 = picks.n;
    let _e163 = reservoir_weight(_e161, K);
    loop {
        let _e166 = k;
        let _e168 = picks.n;
        if (_e166 < min(_e168, K)) {
        } else {
            break;
        }
        {
            let _e172 = h;
            let _e173 = pcg_hash(_e172);
            h = _e173;
            let _e174 = h;
            let _e175 = xi_from_bits(_e174);
            let _e176 = h;
            let _e177 = pcg_hash(_e176);
            h = _e177;
            let _e178 = t;
            let _e180 = k;
            let _e182 = picks.light[_e180];
            let _e183 = n;
            let _e184 = r;
            let _e185 = m;
            let _e186 = h;
            let _e187 = xi_from_bits(_e186);
            let _e188 = shade_pick(_e182, x_15, _e183, _e184, _e79, _e185, _e163, _e175, _e187, eps_4);
            let _e189 = add(_e178, _e188);
            t = _e189;
        }
        continuing {
            let _e191 = k;
            k = (_e191 + 1u);
        }
    }
    let count = picks.n;
    let _e197 = t.e;
    textureStore(out_tex, texel_1, vec4<f32>(_e197, f32(count)));
    return;
}
