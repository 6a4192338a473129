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

struct GridFrame {
    lo: vec3<f32>,
    nx: u32,
    hi: vec3<f32>,
    ny: u32,
    inv: vec3<f32>,
    nz: u32,
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

struct WeightedPicks {
    light: array<u32, 8>,
    w: array<f32, 8>,
    threshold: array<f32, 8>,
    w_sum: f32,
    n: u32,
    h: u32,
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
const GRID_ENTRIES_PER_LIGHT: u32 = 8u;
const LOBE_CONE_PAD: f32 = 1.001f;
const BVH: u32 = 0u;

@group(1) @binding(0) 
var<storage> slc_table: array<f32>;
@group(0) @binding(6) 
var<storage> geo_nodes: array<GpuGeoNode>;
@group(0) @binding(7) 
var<storage> geo_tris: array<GpuTriangle>;
@group(0) @binding(5) 
var<storage> bsh_nodes: array<BshNode>;
@group(0) @binding(11) 
var<storage> grid: array<u32>;
@group(0) @binding(12) 
var<storage> grid_entries: array<u32>;
@group(0) @binding(2) 
var<storage> lights: array<GpuLight>;
@group(0) @binding(4) 
var<storage> r2_4: array<f32>;
@group(0) @binding(3) 
var<storage> rt2_7: array<f32>;
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

fn sphere_contains_point(c: vec3<f32>, r: f32, x_2: vec3<f32>) -> bool {
    let v_10 = (x_2 - c);
    return (dot(v_10, v_10) <= (r * r));
}

fn inverse_square(d2_3: f32) -> f32 {
    return (1f / max(d2_3, MIN_D2_));
}

fn connection_factor(cos_x: f32, d2_4: f32, rt2_2: f32, w: f32) -> f32 {
    let _e4 = inverse_square(d2_4);
    let _e6 = slc_weight(rt2_2, d2_4);
    return (((cos_x * _e4) * _e6) * w);
}

fn connection_cosine(x_3: vec3<f32>, y: vec3<f32>, n: vec3<f32>, ng: vec3<f32>, r2_1: f32) -> f32 {
    var local: bool;
    var local_1: bool;

    let v_11 = (x_3 - y);
    let d2_11 = dot(v_11, v_11);
    let _e7 = slc_keep(r2_1, d2_11);
    if !(!(_e7)) {
        local = !((d2_11 > 0f));
    } else {
        local = true;
    }
    let _e16 = local;
    if _e16 {
        return 0f;
    }
    let w_12 = (v_11 / vec3(sqrt(d2_11)));
    let cos_x_1 = -(dot(n, w_12));
    if !(!((cos_x_1 > 0f))) {
        local_1 = !((dot(ng, w_12) < 0f));
    } else {
        local_1 = true;
    }
    let _e34 = local_1;
    if _e34 {
        return 0f;
    }
    return cos_x_1;
}

fn vpl_lobe(n_1: vec3<f32>, w_1: vec3<f32>) -> f32 {
    return (max(dot(n_1, w_1), 0f) * INV_PI);
}

fn spot_falloff(cos_theta: f32, cos_outer: f32, cos_inner: f32, shape: f32) -> f32 {
    if (cos_inner <= cos_outer) {
        return select(0f, 1f, (cos_theta >= cos_outer));
    }
    let t_1 = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return select(((t_1 * t_1) * (3f - (2f * t_1))), (t_1 * t_1), (shape > 0.5f));
}

fn triangle_lobe(n_2: vec3<f32>, area: f32, w_2: vec3<f32>) -> f32 {
    return (area * max(dot(n_2, w_2), 0f));
}

fn triangle_sample(a_2: vec3<f32>, b_2: vec3<f32>, c_1: vec3<f32>, u1_: f32, u2_: f32) -> vec3<f32> {
    let su = sqrt(u1_);
    let b0_ = (1f - su);
    let b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_1 * ((1f - b0_) - b1_)));
}

fn area_to_solid_angle_pdf(pdf_area: f32, d2_5: f32, cos_light: f32) -> f32 {
    let c_12 = abs(cos_light);
    if (c_12 <= 0f) {
        return 0f;
    }
    return ((pdf_area * d2_5) / c_12);
}

fn atan_portable(x_4: f32) -> f32 {
    var base: f32 = 0f;
    var t: f32;

    let a_9 = abs(x_4);
    t = a_9;
    if (a_9 > 2.4142137f) {
        base = 1.5707964f;
        t = (-1f / a_9);
    } else {
        if (a_9 > 0.41421357f) {
            base = 0.7853982f;
            t = ((a_9 - 1f) / (a_9 + 1f));
        }
    }
    let _e18 = t;
    let _e19 = t;
    let z = (_e18 * _e19);
    let _e21 = base;
    let _e33 = t;
    let _e35 = t;
    let r_17 = (_e21 + (((((((((0.080537446f * z) - 0.13877685f) * z) + 0.19977711f) * z) - 0.3333295f) * z) * _e33) + _e35));
    return select(r_17, -(r_17), (x_4 < 0f));
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

fn ies_fold_c(c_2: f32, h_first: f32, h_last: f32) -> f32 {
    var a_3: f32;

    a_3 = (c_2 - (360f * floor((c_2 / 360f))));
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

fn ies_segment(tab_1: u32, start: u32, n_3: u32, x_6: f32) -> u32 {
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

fn ies_candela(tab_2: u32, base_1: u32, gamma: f32, c_3: f32) -> f32 {
    var local_2: bool;

    let _e4 = at(tab_2, base_1);
    let _e5 = to_u32_(_e4);
    let _e8 = at(tab_2, (base_1 + 1u));
    let _e9 = to_u32_(_e8);
    let v0_ = (base_1 + 2u);
    let h0_1 = (v0_ + _e5);
    let c0_ = (h0_1 + _e9);
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
    let _e27 = at(tab_2, h0_1);
    let _e31 = at(tab_2, ((h0_1 + _e9) - 1u));
    let _e32 = ies_fold_c(c_3, _e27, _e31);
    let _e33 = ies_segment(tab_2, v0_, _e5, gamma);
    let _e34 = ies_segment(tab_2, h0_1, _e9, _e32);
    let iv1_ = min((_e33 + 1u), (_e5 - 1u));
    let ih1_ = min((_e34 + 1u), (_e9 - 1u));
    let _e46 = at(tab_2, (v0_ + _e33));
    let _e48 = at(tab_2, (v0_ + iv1_));
    let _e49 = ies_lerp_t(_e46, _e48, gamma);
    let _e51 = at(tab_2, (h0_1 + _e34));
    let _e53 = at(tab_2, (h0_1 + ih1_));
    let _e54 = ies_lerp_t(_e51, _e53, _e32);
    let _e58 = at(tab_2, ((c0_ + (_e34 * _e5)) + _e33));
    let _e65 = at(tab_2, ((c0_ + (_e34 * _e5)) + iv1_));
    let a_10 = ((_e58 * (1f - _e49)) + (_e65 * _e49));
    let _e71 = at(tab_2, ((c0_ + (ih1_ * _e5)) + _e33));
    let _e78 = at(tab_2, ((c0_ + (ih1_ * _e5)) + iv1_));
    let b_7 = ((_e71 * (1f - _e49)) + (_e78 * _e49));
    return ((a_10 * (1f - _e54)) + (b_7 * _e54));
}

fn ies_candela_dir(tab_3: u32, base_2: u32, wn: f32, wr: f32, ws: f32) -> f32 {
    let _e9 = atan2_portable(sqrt(((wr * wr) + (ws * ws))), wn);
    let gamma_1 = degrees(_e9);
    let on_axis = ((abs(wr) + abs(ws)) <= 0f);
    let _e16 = atan2_portable(ws, wr);
    let c_13 = select(degrees(_e16), 0f, on_axis);
    let _e20 = ies_candela(tab_3, base_2, gamma_1, c_13);
    return _e20;
}

fn ies_light_candela(tab_4: u32, base_3: u32, nadir: vec3<f32>, reference: vec3<f32>, w_3: vec3<f32>) -> f32 {
    let side = cross(reference, nadir);
    let _e9 = ies_candela_dir(tab_4, base_3, dot(w_3, nadir), dot(w_3, reference), dot(w_3, side));
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

fn bsh_reach_bound(node_2: BshNode, w_4: f32) -> f32 {
    let _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_4 * 1.001f) * _e5));
}

fn weighted_threshold(w_sum: f32, u_2: f32) -> f32 {
    return (w_sum / (1f - u_2));
}

fn weighted_pick_weight(w_sum_1: f32, w_5: f32, k: u32) -> f32 {
    let _e3 = to_f32_(k);
    return (w_sum_1 / (_e3 * w_5));
}

fn mis_power(pdf_a: f32, pdf_b: f32) -> f32 {
    let a2_ = (pdf_a * pdf_a);
    let s_4 = (a2_ + (pdf_b * pdf_b));
    if (s_4 <= 0f) {
        return 0f;
    }
    return (a2_ / s_4);
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

fn cosine_pdf(cos_theta_1: f32) -> f32 {
    return (max(cos_theta_1, 0f) * INV_PI);
}

fn onb_tangent(n_4: vec3<f32>) -> vec3<f32> {
    let s_5 = select(-1f, 1f, (n_4.z >= 0f));
    let a_11 = (-1f / (s_5 + n_4.z));
    return vec3<f32>((1f + (((s_5 * n_4.x) * n_4.x) * a_11)), (((s_5 * n_4.x) * n_4.y) * a_11), (-(s_5) * n_4.x));
}

fn onb_bitangent(n_5: vec3<f32>) -> vec3<f32> {
    let s_6 = select(-1f, 1f, (n_5.z >= 0f));
    let a_12 = (-1f / (s_6 + n_5.z));
    return vec3<f32>(((n_5.x * n_5.y) * a_12), (s_6 + ((n_5.y * n_5.y) * a_12)), -(n_5.y));
}

fn onb_to_local(n_6: vec3<f32>, w_6: vec3<f32>) -> vec3<f32> {
    let _e2 = onb_tangent(n_6);
    let _e4 = onb_bitangent(n_6);
    return vec3<f32>(dot(w_6, _e2), dot(w_6, _e4), dot(w_6, n_6));
}

fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
    if (cos_h <= 0f) {
        return 0f;
    }
    let a2_1 = (alpha * alpha);
    let t_2 = (((cos_h * cos_h) * a2_1) + sin2_h);
    return ((a2_1 * INV_PI) / (t_2 * t_2));
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
    let c_14 = saturate((1f - v_h));
    let c2_ = (c_14 * c_14);
    return (f0_ + ((vec3<f32>(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_14)));
}

fn specular_fresnel(base_4: vec3<f32>, metallic: f32, f0_d: vec3<f32>, f90_d: f32, v_h_1: f32) -> vec3<f32> {
    let _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    let _e10 = fresnel_schlick(base_4, 1f, v_h_1);
    return ((_e5 * (1f - metallic)) + (_e10 * metallic));
}

fn diffuse_brdf(base_5: vec3<f32>, metallic_1: f32, f0_d_1: vec3<f32>, f90_d_1: f32, v_h_2: f32) -> vec3<f32> {
    let _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return ((((vec3<f32>(1f, 1f, 1f) - _e9) * base_5) * (1f - metallic_1)) * INV_PI);
}

fn half_cosine(v: vec3<f32>, l: vec3<f32>) -> f32 {
    let h_7 = (v + l);
    let len2_ = dot(h_7, h_7);
    if (len2_ <= 0f) {
        return 0f;
    }
    return saturate((dot(v, h_7) / sqrt(len2_)));
}

fn specular_brdf(base_6: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n_7: vec3<f32>, v_1: vec3<f32>, l_1: vec3<f32>) -> vec3<f32> {
    var local_6: bool;

    let n_l_1 = dot(n_7, l_1);
    let n_v_2 = dot(n_7, v_1);
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
    let inv_1 = (1f / sqrt(dot(hs, hs)));
    let h_8 = (hs * inv_1);
    let c_15 = cross(n_7, h_8);
    let _e32 = ggx_d(dot(n_7, h_8), dot(c_15, c_15), alpha_3);
    let _e34 = specular_fresnel(base_6, metallic_2, f0_d_2, f90_d_2, dot(v_1, h_8));
    let _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return (_e34 * (_e32 * _e35));
}

fn brdf_eval(base_7: vec3<f32>, metallic_3: f32, f0_d_3: vec3<f32>, f90_d_3: f32, alpha_4: f32, n_8: vec3<f32>, v_2: vec3<f32>, l_2: vec3<f32>) -> vec3<f32> {
    if (dot(n_8, l_2) <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = half_cosine(v_2, l_2);
    let _e16 = diffuse_brdf(base_7, metallic_3, f0_d_3, f90_d_3, _e15);
    let _e17 = specular_brdf(base_7, metallic_3, f0_d_3, f90_d_3, alpha_4, n_8, v_2, l_2);
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

fn channel_mean(c_4: vec3<f32>) -> f32 {
    return (((c_4.x + c_4.y) + c_4.z) * 0.33333334f);
}

fn receiver_lobe(base_8: vec3<f32>, metallic_5: f32, f0_d_5: vec3<f32>, f90_d_5: f32, alpha_5: f32, n_v_1: f32) -> vec4<f32> {
    var local_9: bool;

    let _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    let _e16 = channel_mean((((vec3<f32>(1f, 1f, 1f) - _e10) * base_8) * (1f - metallic_5)));
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
    let _e28 = specular_fresnel(base_8, metallic_5, f0_d_5, f90_d_5, n_v_1);
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

fn mirror_dir(n_9: vec3<f32>, v_3: vec3<f32>) -> vec3<f32> {
    return ((n_9 * (2f * dot(n_9, v_3))) - v_3);
}

fn bounded_vndf_k(wi: vec3<f32>, alpha_6: f32) -> f32 {
    let a_13 = saturate(alpha_6);
    let s_7 = (1f + sqrt(((wi.x * wi.x) + (wi.y * wi.y))));
    let a2_3 = (a_13 * a_13);
    let s2_ = (s_7 * s_7);
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
    let t_3 = sqrt((((alpha_7 * alpha_7) * ((wi_1.x * wi_1.x) + (wi_1.y * wi_1.y))) + (wi_1.z * wi_1.z)));
    let _e43 = bounded_vndf_k(wi_1, alpha_7);
    return (_e28 / (2f * ((_e43 * wi_1.z) + t_3)));
}

fn bsdf_pdf(n_10: vec3<f32>, v_4: vec3<f32>, l_3: vec3<f32>, alpha_8: f32, p_spec: f32) -> f32 {
    let _e6 = cosine_pdf(dot(n_10, l_3));
    if (p_spec <= 0f) {
        return _e6;
    }
    let _e9 = onb_to_local(n_10, v_4);
    let _e10 = onb_to_local(n_10, l_3);
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

fn safe_sqrt(x_8: f32) -> f32 {
    return sqrt(max(x_8, 0f));
}

fn subtended_cos(dist2_: f32, r2_2: f32) -> f32 {
    let _e5 = safe_sqrt((1f - (r2_2 / dist2_)));
    return select(_e5, -1f, (dist2_ <= r2_2));
}

fn emitter_cone(center: vec3<f32>, radius: f32, axis: vec3<f32>, cos_o: f32, p: vec3<f32>) -> vec4<f32> {
    var local_11: bool;

    let v_12 = (p - center);
    let dist2_1 = dot(v_12, v_12);
    let r2_5 = (radius * radius);
    if (dist2_1 <= 0f) {
        local_11 = (r2_5 <= 0f);
    } else {
        local_11 = false;
    }
    let _e15 = local_11;
    if _e15 {
        return vec4<f32>(-2f, 0.000000000001f, -1f, 0f);
    }
    let d2_12 = max(max(dist2_1, r2_5), MIN_D2_);
    let wi_2 = select(vec3<f32>(0f, 0f, 0f), (v_12 / vec3(sqrt(dist2_1))), (dist2_1 > 0f));
    let cos_w = dot(axis, wi_2);
    let _e38 = safe_sqrt((1f - (cos_w * cos_w)));
    let _e39 = subtended_cos(dist2_1, r2_5);
    let _e43 = safe_sqrt((1f - (_e39 * _e39)));
    let _e47 = safe_sqrt((1f - (cos_o * cos_o)));
    let _e48 = cos_sub_clamped(_e38, cos_w, _e47, cos_o);
    let _e49 = sin_sub_clamped(_e38, cos_w, _e47, cos_o);
    let _e50 = cos_sub_clamped(_e49, _e48, _e43, _e39);
    return vec4<f32>(_e50, d2_12, _e39, _e43);
}

fn emitter_importance(center_1: vec3<f32>, radius_1: f32, phi: f32, axis_1: vec3<f32>, cos_o_1: f32, cos_e: f32, p_1: vec3<f32>) -> f32 {
    let _e7 = emitter_cone(center_1, radius_1, axis_1, cos_o_1, p_1);
    if (_e7.x <= cos_e) {
        return 0f;
    }
    return ((phi * _e7.x) / _e7.y);
}

fn cone_cos_of(v_5: vec3<f32>, d2_7: f32, a_4: f32, d: vec3<f32>) -> f32 {
    var local_12: bool;
    var local_13: bool;

    let vd = dot(v_5, d);
    let h2_ = (d2_7 - (a_4 * a_4));
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
    let c_16 = cross(v_5, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_16, c_16)) * a_4)) / d2_7), 1f);
}

fn cone_cos_toward(center_2: vec3<f32>, radius_2: f32, p_2: vec3<f32>, d_1: vec3<f32>) -> f32 {
    let v_13 = (center_2 - p_2);
    let _e6 = cone_cos_of(v_13, dot(v_13, v_13), radius_2, d_1);
    return _e6;
}

fn range_scale_at(rl: vec4<f32>, cos_t: f32) -> f32 {
    let t_4 = (((0.5f + (0.5f * cos_t)) * (rl.z - 1f)) + 1f);
    return clamp((rl.x + ((rl.y * rl.z) / (t_4 * t_4))), 1f, (rl.w * rl.w));
}

fn range_scale_toward(rl_1: vec4<f32>, center_3: vec3<f32>, radius_3: f32, p_3: vec3<f32>, r_1: vec3<f32>) -> f32 {
    if (rl_1.w <= 1f) {
        return 1f;
    }
    let _e9 = cone_cos_toward(center_3, radius_3, p_3, r_1);
    let _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

fn light_importance(center_4: vec3<f32>, radius_4: f32, phi_1: f32, axis_2: vec3<f32>, cos_o_2: f32, cos_e_1: f32, p_4: vec3<f32>, n_11: vec3<f32>) -> f32 {
    var imp: f32;

    let _e8 = emitter_cone(center_4, radius_4, axis_2, cos_o_2, p_4);
    if (_e8.x <= cos_e_1) {
        return 0f;
    }
    imp = ((phi_1 * _e8.x) / _e8.y);
    if (dot(n_11, n_11) > 0f) {
        let v_14 = (center_4 - p_4);
        let dist2_2 = dot(v_14, v_14);
        let cos_i = dot(select(vec3<f32>(0f, 0f, 0f), (v_14 / vec3(sqrt(dist2_2))), (dist2_2 > 0f)), n_11);
        let _e33 = imp;
        let _e37 = safe_sqrt((1f - (cos_i * cos_i)));
        let _e40 = cos_sub_clamped(_e37, cos_i, _e8.w, _e8.z);
        imp = (_e33 * max(_e40, 0f));
    }
    let _e44 = imp;
    return max(_e44, 0f);
}

fn glossy_importance(center_5: vec3<f32>, radius_5: f32, phi_2: f32, axis_3: vec3<f32>, cos_o_3: f32, cos_e_2: f32, p_5: vec3<f32>, n_12: vec3<f32>, r_2: vec3<f32>, lobe_5: vec4<f32>) -> f32 {
    var local_14: bool;

    let _e10 = emitter_importance(center_5, radius_5, phi_2, axis_3, cos_o_3, cos_e_2, p_5);
    let _e11 = cone_cos_toward(center_5, radius_5, p_5, n_12);
    if !((_e10 <= 0f)) {
        local_14 = (_e11 <= 0f);
    } else {
        local_14 = true;
    }
    let _e20 = local_14;
    if _e20 {
        return 0f;
    }
    let _e22 = cone_cos_toward(center_5, radius_5, p_5, r_2);
    let _e27 = safe_sqrt((0.5f + (0.5f * _e22)));
    let _e33 = ggx_d(_e27, (1f - (_e27 * _e27)), lobe_5.z);
    let _e39 = smith_root(lobe_5.w, lobe_5.z);
    let spec = (((lobe_5.y * _e33) * 0.25f) / _e39);
    return (_e10 * (((lobe_5.x * INV_PI) * _e11) + spec));
}

fn candidate_weight(importance: f32, rt2_4: f32, d2_8: f32) -> f32 {
    let _e3 = slc_weight(rt2_4, d2_8);
    return (importance * _e3);
}

fn cone_weight(center_6: vec3<f32>, radius_6: f32, phi_3: f32, axis_4: vec3<f32>, cos_o_4: f32, cos_e_3: f32, rt2_5: f32, p_6: vec3<f32>, n_13: vec3<f32>, r_3: vec3<f32>, lobe_6: vec4<f32>) -> f32 {
    let v_15 = (p_6 - center_6);
    if (lobe_6.y <= 0f) {
        let _e15 = light_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_13);
        let _e19 = candidate_weight((_e15 * INV_PI), rt2_5, dot(v_15, v_15));
        return _e19;
    }
    let _e20 = glossy_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_13, r_3, lobe_6);
    let _e22 = candidate_weight(_e20, rt2_5, dot(v_15, v_15));
    return _e22;
}

fn weighted_select_pdf(w_7: f32, w_sum_2: f32, in_range: bool, k_1: u32) -> f32 {
    if (w_7 <= 0f) {
        return 0f;
    }
    let total = select((w_sum_2 + w_7), w_sum_2, in_range);
    let _e9 = to_f32_(k_1);
    return ((_e9 * w_7) / total);
}

fn finite3_(v_6: vec3<f32>) -> bool {
    var local_15: bool;
    var local_16: bool;

    if (abs(v_6.x) <= F32_MAX) {
        local_15 = (abs(v_6.y) <= F32_MAX);
    } else {
        local_15 = false;
    }
    let _e12 = local_15;
    if _e12 {
        local_16 = (abs(v_6.z) <= F32_MAX);
    } else {
        local_16 = false;
    }
    let _e20 = local_16;
    return _e20;
}

fn shadow_margin(len: f32) -> f32 {
    return (0.0001f * len);
}

fn ray_inverse(x_9: f32) -> f32 {
    return (1f / select(x_9, 0.000000000000000000000000000001f, (abs(x_9) < 0.000000000000000000000000000001f)));
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
    let hi_1 = max(t0_, t1_);
    let t_in = max(max(lo_2.x, lo_2.y), max(lo_2.z, 0f));
    let t_out = min(min(hi_1.x, hi_1.y), min(hi_1.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1f;
}

fn triangle_normal(a_5: vec3<f32>, b_3: vec3<f32>, c_5: vec3<f32>) -> vec3<f32> {
    var local_17: bool;

    let n_23 = cross((b_3 - a_5), (c_5 - a_5));
    let l2_ = dot(n_23, n_23);
    if !(!((l2_ > 0f))) {
        local_17 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_17 = true;
    }
    let _e17 = local_17;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_23 / vec3(sqrt(l2_)));
}

fn ray_triangle(o_1: vec3<f32>, d_3: vec3<f32>, a_6: vec3<f32>, b_4: vec3<f32>, c_6: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_18: bool;
    var local_19: bool;
    var local_20: bool;

    let e1_ = (b_4 - a_6);
    let e2_ = (c_6 - a_6);
    let p_7 = cross(d_3, e2_);
    let det = dot(e1_, p_7);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv_2 = (1f / det);
    let s_8 = (o_1 - a_6);
    let u_3 = (dot(s_8, p_7) * inv_2);
    if !((u_3 < 0f)) {
        local_18 = (u_3 > 1f);
    } else {
        local_18 = true;
    }
    let _e28 = local_18;
    if _e28 {
        return -1f;
    }
    let q = cross(s_8, e1_);
    let v_16 = (dot(d_3, q) * inv_2);
    if !((v_16 < 0f)) {
        local_19 = ((u_3 + v_16) > 1f);
    } else {
        local_19 = true;
    }
    let _e42 = local_19;
    if _e42 {
        return -1f;
    }
    let t_5 = (dot(e2_, q) * inv_2);
    if (t_5 > t_min) {
        local_20 = (t_5 < t_max_1);
    } else {
        local_20 = false;
    }
    let _e51 = local_20;
    if _e51 {
        return t_5;
    }
    return -1f;
}

fn light_intensity(l_4: GpuLight, w_8: vec3<f32>) -> vec3<f32> {
    switch l_4.kind {
        case 0u: {
            return l_4.intensity;
        }
        case 1u: {
            let _e11 = spot_falloff(dot(l_4.p1_, w_8), l_4.a, l_4.b, l_4.p2_.x);
            return (l_4.intensity * _e11);
        }
        case 2u: {
            let _e18 = ies_light_candela(0u, l_4.ies_base, l_4.p1_, l_4.p2_, w_8);
            return (l_4.intensity * _e18);
        }
        case 3u: {
            let _e24 = triangle_normal(l_4.p0_, l_4.p1_, l_4.p2_);
            let _e26 = triangle_lobe(_e24, l_4.a, w_8);
            return (l_4.intensity * _e26);
        }
        case 4u: {
            let _e30 = vpl_lobe(l_4.p1_, w_8);
            return (l_4.intensity * _e30);
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
        let n_24 = geo_nodes[_e21];
        let _e27 = hit.t;
        let _e28 = ray_aabb(o_2, _e14, n_24.bmin, n_24.bmax, _e27);
        if (_e28 >= 0f) {
            if (n_24.count > 0u) {
                i_1 = n_24.first;
                loop {
                    let _e36 = i_1;
                    if (_e36 < (n_24.first + n_24.count)) {
                    } else {
                        break;
                    }
                    {
                        let _e42 = i_1;
                        let t_6 = geo_tris[_e42];
                        let _e49 = hit.t;
                        let _e50 = ray_triangle(o_2, d_4, t_6.v0_, t_6.v1_, t_6.v2_, t_min_1, _e49);
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
                    stack[_e63] = (n_24.first + 1u);
                    let _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_24.first;
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

fn occluded(a_7: vec3<f32>, b_5: vec3<f32>) -> bool {
    let dv = (b_5 - a_7);
    let len_1 = length(dv);
    if (len_1 <= 0f) {
        return false;
    }
    let _e7 = shadow_margin(len_1);
    let _e12 = trace(a_7, (dv / vec3(len_1)), _e7, (len_1 - _e7), true);
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

fn bsh_inner_scale(a_8: f32, v_7: vec3<f32>, d2_9: f32, r_4: vec3<f32>, rl_2: vec4<f32>) -> f32 {
    let _e5 = cone_cos_of(v_7, d2_9, a_8, r_4);
    let _e8 = range_scale_at(rl_2, (_e5 + 0.000002f));
    return _e8;
}

fn bsh_reaches(node_4: BshNode, x_10: vec3<f32>, r_5: vec3<f32>, rl_3: vec4<f32>) -> bool {
    var local_21: bool;
    var local_22: bool;

    let _e6 = sphere_contains_point(node_4.center, node_4.radius, x_10);
    if _e6 {
        return true;
    }
    if !((rl_3.w <= 1f)) {
        let _e20 = sphere_contains_point(node_4.center, (node_4.radius * (rl_3.w * 1.0001f)), x_10);
        local_21 = !(_e20);
    } else {
        local_21 = true;
    }
    let _e23 = local_21;
    if _e23 {
        return false;
    }
    let v_17 = (x_10 - node_4.center);
    let d2_13 = dot(v_17, v_17);
    let _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_13 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        let _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_10, r_5);
        let _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        let _e42 = sphere_contains_point(node_4.center, _e41, x_10);
        return _e42;
    }
    let _e45 = bsh_inner_scale(node_4.extent, -(v_17), d2_13, r_5, rl_3);
    let s_c = (_e45 * 1.001f);
    let _e50 = bsh_range_bound(node_4);
    let reach = (node_4.extent + (sqrt(s_c) * _e50));
    if (d2_13 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_22 = (d2_13 <= (reach * reach));
    } else {
        local_22 = false;
    }
    let _e63 = local_22;
    return _e63;
}

fn bsh_next_leaf_lobe(nodes_3: u32, start_1: u32, x_11: vec3<f32>, r_6: vec3<f32>, rl_4: vec4<f32>) -> u32 {
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
            let _e11 = bsh_reaches(_e10, x_11, r_6, rl_4);
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

fn bsh_grid_axis(v_8: f32, lo_1: f32, inv: f32, n_14: u32) -> u32 {
    let _e8 = to_u32_(max(((v_8 - lo_1) * inv), 0f));
    return min(_e8, (n_14 - 1u));
}

fn bsh_grid_cell(f: GridFrame, x_12: vec3<f32>) -> u32 {
    var local_23: bool;
    var local_24: bool;
    var local_25: bool;
    var local_26: bool;
    var local_27: bool;

    if (x_12.x >= f.lo.x) {
        local_23 = (x_12.y >= f.lo.y);
    } else {
        local_23 = false;
    }
    let _e13 = local_23;
    if _e13 {
        local_24 = (x_12.z >= f.lo.z);
    } else {
        local_24 = false;
    }
    let _e21 = local_24;
    if _e21 {
        local_25 = (x_12.x <= f.hi.x);
    } else {
        local_25 = false;
    }
    let _e29 = local_25;
    if _e29 {
        local_26 = (x_12.y <= f.hi.y);
    } else {
        local_26 = false;
    }
    let _e37 = local_26;
    if _e37 {
        local_27 = (x_12.z <= f.hi.z);
    } else {
        local_27 = false;
    }
    let inside = local_27;
    if !(inside) {
        return BSH_NONE;
    }
    let _e54 = bsh_grid_axis(x_12.x, f.lo.x, f.inv.x, f.nx);
    let _e61 = bsh_grid_axis(x_12.y, f.lo.y, f.inv.y, f.ny);
    let _e68 = bsh_grid_axis(x_12.z, f.lo.z, f.inv.z, f.nz);
    return ((((_e68 * f.ny) + _e61) * f.nx) + _e54);
}

fn lobe_cone(r_7: vec3<f32>, rl_5: vec4<f32>) -> vec2<f32> {
    var local_28: bool;
    var local_29: bool;
    var local_30: bool;
    var local_31: bool;
    var c_7: f32;
    var tries: u32 = 0u;

    let _e2 = finite3_(r_7);
    if _e2 {
        local_28 = (rl_5.x < 1f);
    } else {
        local_28 = false;
    }
    let _e9 = local_28;
    if _e9 {
        local_29 = (rl_5.y >= 0f);
    } else {
        local_29 = false;
    }
    let _e16 = local_29;
    if _e16 {
        local_30 = (rl_5.z > 0f);
    } else {
        local_30 = false;
    }
    let _e23 = local_30;
    if _e23 {
        local_31 = (rl_5.z < 1f);
    } else {
        local_31 = false;
    }
    let _e30 = local_31;
    if !(_e30) {
        return vec2<f32>(0f, 0f);
    }
    let t1_1 = sqrt(((rl_5.y * rl_5.z) / (1f - rl_5.x)));
    c_7 = (((2f * (1f - t1_1)) / (1f - rl_5.z)) - 1f);
    loop {
        let _e56 = c_7;
        let _e57 = range_scale_at(rl_5, _e56);
        if !((_e57 <= 1f)) {
        } else {
            break;
        }
        {
            let _e61 = c_7;
            c_7 = (_e61 - 0.0001f);
            let _e64 = tries;
            tries = (_e64 + 1u);
            let _e67 = tries;
            if (_e67 > 16u) {
                return vec2<f32>(0f, 0f);
            }
        }
    }
    let _e73 = c_7;
    let w_13 = min((min(_e73, 1f) - 0.001f), 0.9999f);
    if !((w_13 > 0f)) {
        return vec2<f32>(0f, 0f);
    }
    return vec2<f32>((w_13 * w_13), (1f / sqrt((1f - (w_13 * w_13)))));
}

fn lobe_cone_meets(v_9: vec3<f32>, d2_10: f32, extent: f32, axis_5: vec3<f32>, cone: vec2<f32>) -> bool {
    var local_32: bool;

    let k_2 = (((extent * LOBE_CONE_PAD) + 0.000000000000000000000000000001f) * cone.y);
    let vd_1 = -(dot(v_9, axis_5));
    let a_14 = (vd_1 + k_2);
    let b_8 = (d2_10 + (k_2 * ((2f * vd_1) + k_2)));
    if (a_14 >= 0f) {
        local_32 = ((a_14 * a_14) >= (b_8 * cone.x));
    } else {
        local_32 = false;
    }
    let _e28 = local_32;
    return _e28;
}

fn bsh_lobe_admits(c_8: vec3<f32>, radius_7: f32, extent_1: f32, x_13: vec3<f32>, w_9: f32, axis_6: vec3<f32>, cone_1: vec2<f32>) -> bool {
    var local_33: bool;
    var local_34: bool;
    var local_35: bool;

    let v_18 = (x_13 - c_8);
    let d2_14 = dot(v_18, v_18);
    let f_2 = (radius_7 * (w_9 * 1.0001f));
    if (d2_14 <= (f_2 * f_2)) {
        if !((cone_1.y == 0f)) {
            local_34 = (d2_14 <= (radius_7 * radius_7));
        } else {
            local_34 = true;
        }
        let _e25 = local_34;
        if !(_e25) {
            let _e29 = lobe_cone_meets(v_18, d2_14, extent_1, axis_6, cone_1);
            local_35 = _e29;
        } else {
            local_35 = true;
        }
        let _e31 = local_35;
        local_33 = _e31;
    } else {
        local_33 = false;
    }
    let _e33 = local_33;
    return _e33;
}

fn grid_word(i_4: u32) -> u32 {
    let _e3 = grid[i_4];
    return _e3;
}

fn grid_frame(h_1: u32) -> GridFrame {
    var f_1: GridFrame;

    let _e3 = grid_word(h_1);
    let _e7 = grid_word((h_1 + 1u));
    let _e11 = grid_word((h_1 + 2u));
    f_1.lo = vec3<f32>(bitcast<f32>(_e3), bitcast<f32>(_e7), bitcast<f32>(_e11));
    let _e17 = grid_word((h_1 + 3u));
    f_1.nx = _e17;
    let _e21 = grid_word((h_1 + 4u));
    let _e25 = grid_word((h_1 + 5u));
    let _e29 = grid_word((h_1 + 6u));
    f_1.hi = vec3<f32>(bitcast<f32>(_e21), bitcast<f32>(_e25), bitcast<f32>(_e29));
    let _e35 = grid_word((h_1 + 7u));
    f_1.ny = _e35;
    let _e39 = grid_word((h_1 + 8u));
    let _e43 = grid_word((h_1 + 9u));
    let _e47 = grid_word((h_1 + 10u));
    f_1.inv = vec3<f32>(bitcast<f32>(_e39), bitcast<f32>(_e43), bitcast<f32>(_e47));
    let _e53 = grid_word((h_1 + 11u));
    f_1.nz = _e53;
    let _e54 = f_1;
    return _e54;
}

fn grid_reach(h_2: u32) -> f32 {
    let _e3 = grid_word((h_2 + 12u));
    return bitcast<f32>(_e3);
}

fn bsh_cursor(x_14: vec3<f32>, r_8: vec3<f32>, rl_6: vec4<f32>) -> BshCursor {
    var c_9: BshCursor;
    var h_3: u32 = 0u;
    var g: u32 = 1u;
    var local_36: bool;
    var local_37: bool;
    var local_38: bool;

    c_9.i = 0u;
    c_9.end = 0u;
    let _e10 = bsh_first(BSH);
    c_9.next = _e10;
    c_9.cone = vec2(0f);
    loop {
        let _e18 = g;
        if (_e18 < GRIDS_MAX) {
            let _e24 = h_3;
            let _e25 = grid_reach(_e24);
            local_36 = (rl_6.w > _e25);
        } else {
            local_36 = false;
        }
        let _e28 = local_36;
        if _e28 {
        } else {
            break;
        }
        {
            let _e29 = h_3;
            let _e32 = grid_word((_e29 + 14u));
            h_3 = _e32;
        }
        continuing {
            let _e34 = g;
            g = (_e34 + 1u);
        }
    }
    let _e36 = h_3;
    let _e37 = grid_frame(_e36);
    let _e39 = c_9.next;
    if (_e39 != BSH_NONE) {
        local_37 = (_e37.nx > 0u);
    } else {
        local_37 = false;
    }
    let _e48 = local_37;
    if _e48 {
        let _e52 = h_3;
        let _e53 = grid_reach(_e52);
        local_38 = (rl_6.w <= _e53);
    } else {
        local_38 = false;
    }
    let _e56 = local_38;
    if _e56 {
        let _e57 = bsh_grid_cell(_e37, x_14);
        if (_e57 != BSH_NONE) {
            let _e62 = h_3;
            let _e67 = grid[((_e62 + GRID_HEADER) + _e57)];
            c_9.i = _e67;
            let _e70 = h_3;
            let _e77 = grid[(((_e70 + GRID_HEADER) + _e57) + 1u)];
            c_9.end = _e77;
            let _e82 = bsh_nodes[0].next;
            c_9.next = _e82;
            let _e84 = lobe_cone(r_8, rl_6);
            c_9.cone = _e84;
        }
    }
    let _e85 = c_9;
    return _e85;
}

fn bsh_cursor_next(c_10: ptr<function, BshCursor>, x_15: vec3<f32>, r_9: vec3<f32>, rl_7: vec4<f32>) -> u32 {
    var local_39: bool;
    var local_40: bool;

    loop {
        let _e5 = (*c_10).i;
        let _e7 = (*c_10).end;
        if (_e5 < _e7) {
        } else {
            break;
        }
        {
            let _e11 = (*c_10).i;
            let b_9 = grid_entries[_e11];
            let _e15 = (*c_10).i;
            (*c_10).i = (_e15 + 1u);
            let n_25 = bsh_nodes[b_9];
            if !((rl_7.w <= 1f)) {
                let _e32 = (*c_10).cone;
                let _e33 = bsh_lobe_admits(n_25.center, n_25.radius, n_25.extent, x_15, rl_7.w, r_9, _e32);
                local_39 = _e33;
            } else {
                local_39 = true;
            }
            let _e35 = local_39;
            if _e35 {
                let _e38 = bsh_reaches(n_25, x_15, r_9, rl_7);
                local_40 = _e38;
            } else {
                local_40 = false;
            }
            let _e40 = local_40;
            if _e40 {
                return b_9;
            }
        }
    }
    let _e43 = (*c_10).next;
    let _e44 = bsh_next_leaf_lobe(BSH, _e43, x_15, r_9, rl_7);
    if (_e44 != BSH_NONE) {
        let _e51 = bsh_nodes[_e44].next;
        (*c_10).next = _e51;
    }
    return _e44;
}

fn next_threshold(sum_1: f32, h_4: ptr<function, u32>) -> f32 {
    let _e2 = (*h_4);
    let _e3 = pcg_hash(_e2);
    (*h_4) = _e3;
    let _e4 = (*h_4);
    let _e5 = xi_from_bits(_e4);
    let _e6 = weighted_threshold(sum_1, _e5);
    return _e6;
}

fn connect_record(l_8: GpuLight, x_16: vec3<f32>, n_15: vec3<f32>, ng_1: vec3<f32>, r2_3: f32, rt2_6: f32, w_res: f32, u1_2: f32, u2_2: f32, eps: f32, trace_1: bool) -> Connection {
    var c_11: Connection;
    var local_41: bool;
    var local_42: bool;

    c_11.e = vec3(0f);
    let _e16 = light_point(l_8, u1_2, u2_2);
    c_11.y = _e16;
    let _e19 = c_11.y;
    let _e20 = connection_cosine(x_16, _e19, n_15, ng_1, r2_3);
    c_11.cos_x = _e20;
    let _e22 = c_11.cos_x;
    if !((_e22 <= 0f)) {
        if trace_1 {
            let _e33 = c_11.y;
            let _e34 = occluded((x_16 + (ng_1 * eps)), _e33);
            local_42 = _e34;
        } else {
            local_42 = false;
        }
        let _e36 = local_42;
        local_41 = _e36;
    } else {
        local_41 = true;
    }
    let _e38 = local_41;
    if _e38 {
        let _e39 = c_11;
        return _e39;
    }
    let _e41 = c_11.y;
    let v_19 = (x_16 - _e41);
    let d2_15 = dot(v_19, v_19);
    let _e48 = light_intensity(l_8, (v_19 / vec3(sqrt(d2_15))));
    let _e50 = c_11.cos_x;
    let _e51 = connection_factor(_e50, d2_15, rt2_6, w_res);
    c_11.e = (_e48 * _e51);
    let _e53 = c_11;
    return _e53;
}

fn connect_traced(li: u32, x_17: vec3<f32>, n_16: vec3<f32>, ng_2: vec3<f32>, s_1: f32, w_res_1: f32, u1_3: f32, u2_3: f32, eps_1: f32, trace_2: bool) -> Connection {
    let _e12 = lights[li];
    let _e15 = r2_4[li];
    let _e19 = rt2_7[li];
    let _e21 = connect_record(_e12, x_17, n_16, ng_2, (s_1 * _e15), (s_1 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_2);
    return _e21;
}

fn connect(li_1: u32, x_18: vec3<f32>, n_17: vec3<f32>, ng_3: vec3<f32>, s_2: f32, w_res_2: f32, u1_4: f32, u2_4: f32, eps_2: f32) -> Connection {
    let _e10 = connect_traced(li_1, x_18, n_17, ng_3, s_2, w_res_2, u1_4, u2_4, eps_2, true);
    return _e10;
}

fn mis_weight(pdf_a_1: f32, pdf_b_1: f32) -> f32 {
    let _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

fn light_range_scale(li_2: u32, x_19: vec3<f32>, r_10: vec3<f32>, rl_8: vec4<f32>) -> f32 {
    let c_17 = light_cones[li_2];
    let _e9 = range_scale_toward(rl_8, c_17.center, c_17.radius, x_19, r_10);
    return _e9;
}

fn light_weight(li_3: u32, x_20: vec3<f32>, n_18: vec3<f32>, r_11: vec3<f32>, lobe_7: vec4<f32>, rl_9: vec4<f32>) -> f32 {
    let c_18 = light_cones[li_3];
    let _e15 = light_range_scale(li_3, x_20, r_11, rl_9);
    let _e18 = rt2_7[li_3];
    let _e20 = cone_weight(c_18.center, c_18.radius, c_18.phi, c_18.axis, c_18.cos_o, c_18.cos_e, (_e15 * _e18), x_20, n_18, r_11, lobe_7);
    return _e20;
}

fn select_pdf(li_4: u32, x_21: vec3<f32>, n_19: vec3<f32>, r_12: vec3<f32>, lobe_8: vec4<f32>, rl_10: vec4<f32>, nee: u32, in_range_1: bool) -> f32 {
    let _e8 = light_weight(li_4, x_21, n_19, r_12, lobe_8, rl_10);
    let _e11 = weighted_select_pdf(_e8, bitcast<f32>(nee), in_range_1, K);
    return _e11;
}

fn light_pdf_selected(li_5: u32, x_22: vec3<f32>, r_13: vec3<f32>, rl_11: vec4<f32>, y_2: vec3<f32>, sel: f32) -> f32 {
    let l_9 = lights[li_5];
    let v_20 = (x_22 - y_2);
    let d2_16 = dot(v_20, v_20);
    let _e11 = light_normal(l_9);
    let cos_y_1 = select(0f, dot(_e11, (v_20 / vec3(sqrt(d2_16)))), (d2_16 > 0f));
    let _e20 = light_range_scale(li_5, x_22, r_13, rl_11);
    let _e23 = rt2_7[li_5];
    let _e25 = light_area(l_9);
    let _e26 = light_strategy_pdf(sel, (_e20 * _e23), d2_16, _e25, cos_y_1);
    return _e26;
}

fn light_pdf(li_6: u32, x_23: vec3<f32>, n_20: vec3<f32>, r_14: vec3<f32>, lobe_9: vec4<f32>, rl_12: vec4<f32>, y_3: vec3<f32>, nee_1: u32, in_range_2: bool) -> f32 {
    let _e9 = select_pdf(li_6, x_23, n_20, r_14, lobe_9, rl_12, nee_1, in_range_2);
    let _e10 = light_pdf_selected(li_6, x_23, r_14, rl_12, y_3, _e9);
    return _e10;
}

fn weighted_picks(h_5: u32) -> WeightedPicks {
    var picks: WeightedPicks;

    picks.w_sum = 0f;
    picks.n = 0u;
    picks.h = h_5;
    let _e7 = picks;
    return _e7;
}

fn weighted_offer(picks_1: ptr<function, WeightedPicks>, li_7: u32, w_10: f32) {
    var h_6: u32;
    var s_3: u32 = 0u;

    let _e4 = (*picks_1).n;
    (*picks_1).n = (_e4 + 1u);
    if (w_10 > 0f) {
        let _e10 = (*picks_1).w_sum;
        (*picks_1).w_sum = (_e10 + w_10);
        let _e13 = (*picks_1).h;
        h_6 = _e13;
        loop {
            let _e17 = s_3;
            if (_e17 < K) {
            } else {
                break;
            }
            {
                let _e21 = (*picks_1).w_sum;
                let _e23 = s_3;
                let _e25 = (*picks_1).threshold[_e23];
                if (_e21 > _e25) {
                    let _e28 = s_3;
                    (*picks_1).light[_e28] = li_7;
                    let _e31 = s_3;
                    (*picks_1).w[_e31] = w_10;
                    let _e34 = s_3;
                    let _e37 = (*picks_1).w_sum;
                    let _e38 = next_threshold(_e37, (&h_6));
                    (*picks_1).threshold[_e34] = _e38;
                }
            }
            continuing {
                let _e40 = s_3;
                s_3 = (_e40 + 1u);
            }
        }
        let _e43 = h_6;
        (*picks_1).h = _e43;
        return;
    } else {
        return;
    }
}

fn bsh_weighted_collect(x_24: vec3<f32>, n_21: vec3<f32>, r_15: vec3<f32>, lobe_10: vec4<f32>, rl_13: vec4<f32>, h0_: u32) -> WeightedPicks {
    var picks_2: WeightedPicks;
    var cur: BshCursor;
    var b_6: u32;

    let _e6 = weighted_picks(h0_);
    picks_2 = _e6;
    let _e8 = bsh_cursor(x_24, r_15, rl_13);
    cur = _e8;
    let _e10 = bsh_cursor_next((&cur), x_24, r_15, rl_13);
    b_6 = _e10;
    loop {
        let _e12 = b_6;
        if (_e12 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e16 = b_6;
            let li_9 = bsh_nodes[_e16].light;
            let _e20 = light_weight(li_9, x_24, n_21, r_15, lobe_10, rl_13);
            weighted_offer((&picks_2), li_9, _e20);
        }
        continuing {
            let _e21 = bsh_cursor_next((&cur), x_24, r_15, rl_13);
            b_6 = _e21;
        }
    }
    let _e22 = picks_2;
    return _e22;
}

fn shade_pick(li_8: u32, x_25: vec3<f32>, n_22: vec3<f32>, ng_4: vec3<f32>, m: GpuMaterial, wo_1: vec3<f32>, r_16: vec3<f32>, lobe_11: vec4<f32>, rl_14: vec4<f32>, w_11: f32, nee_2: u32, u1_5: f32, u2_5: f32) -> vec3<f32> {
    var mis: f32 = 1f;

    let _e13 = light_range_scale(li_8, x_25, r_16, rl_14);
    let _e16 = params.eps;
    let _e17 = connect(li_8, x_25, n_22, ng_4, _e13, w_11, u1_5, u2_5, _e16);
    if (_e17.cos_x <= 0f) {
        return vec3(0f);
    }
    let l_10 = normalize((_e17.y - x_25));
    let _e30 = lights[li_8];
    let _e31 = light_area(_e30);
    if (_e31 > 0f) {
        let _e36 = light_pdf(li_8, x_25, n_22, r_16, lobe_11, rl_14, _e17.y, nee_2, true);
        let _e38 = specular_probability(lobe_11);
        let _e39 = bsdf_pdf(n_22, wo_1, l_10, m.alpha, _e38);
        let _e40 = mis_weight(_e36, _e39);
        mis = _e40;
    }
    let _e46 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, n_22, wo_1, l_10);
    let _e49 = mis;
    return ((_e46 * _e17.e) * _e49);
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var h: u32;
    var sum: vec3<f32> = vec3(0f);
    var s: u32 = 0u;

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
    let x_26 = vtx.position;
    let n_26 = vtx.normal;
    let ng_5 = vtx.gnormal;
    let m_2 = materials[vtx.material];
    let wo_2 = vtx.wo;
    let _e23 = mirror_dir(n_26, wo_2);
    let _e30 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, dot(n_26, wo_2));
    let _e31 = range_lobe(_e30);
    let _e34 = params.seed;
    let _e37 = params.frame;
    let _e38 = point_stream(_e34, i_5, _e37);
    let _e39 = pick_stream(_e38);
    h = _e39;
    let _e44 = h;
    let _e45 = bsh_weighted_collect(x_26, n_26, _e23, _e30, _e31, _e44);
    h = _e45.h;
    let w_sum_3 = _e45.w_sum;
    candidates[i_5] = bitcast<u32>(w_sum_3);
    if (w_sum_3 > 0f) {
        loop {
            let _e55 = s;
            if (_e55 < K) {
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
                let _e69 = s;
                let _e72 = weighted_pick_weight(w_sum_3, _e45.w[_e69], K);
                let _e74 = h;
                let _e75 = xi_from_bits(_e74);
                let _e76 = shade_pick(_e45.light[_e66], x_26, n_26, ng_5, m_2, wo_2, _e23, _e30, _e31, _e72, bitcast<u32>(w_sum_3), _e61, _e75);
                sum = (_e64 + _e76);
            }
            continuing {
                let _e79 = s;
                s = (_e79 + 1u);
            }
        }
    }
    let _e82 = sum;
    let add = (vtx.weight * _e82);
    let _e84 = finite3_(add);
    if _e84 {
        let _e87 = radiance[i_5];
        radiance[i_5] = (_e87 + vec4<f32>(add, 0f));
        return;
    } else {
        return;
    }
}
