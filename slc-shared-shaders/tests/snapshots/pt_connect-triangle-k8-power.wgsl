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

struct GpuPathVertex {
    position: vec3<f32>,
    alive: u32,
    normal: vec3<f32>,
    pad: f32,
    weight: vec3<f32>,
    pad1_: f32,
    gnormal: vec3<f32>,
    pad2_: f32,
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
    pad: u32,
}

struct GeoHit {
    t: f32,
    tri: u32,
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

const LIGHT_POINT: u32 = 0u;
const LIGHT_SPOT: u32 = 1u;
const LIGHT_IES: u32 = 2u;
const LIGHT_TRIANGLE: u32 = 3u;
const LIGHT_VPL: u32 = 4u;
const NO_LIGHT: u32 = 4294967295u;
const MAP_CAMERA: u32 = 0u;
const MAP_PERSPECTIVE: u32 = 1u;
const MAP_ORTHOGRAPHIC: u32 = 2u;
const XI_STEP: f32 = 0.000000059604645f;
const PICK_STREAM: u32 = 2654435769u;
const TWO_PI: f32 = 6.2831855f;
const CULL_RADIUS_SCALE: f32 = 1.000001f;
const SPHERE_PAD: f32 = 0.00000047683716f;
const SPHERE_HUGE: f32 = 340282350000000000000000000000000000000f;
const SPHERE_PAD_ABS: f32 = 0.000000000000000001f;
const INV_PI: f32 = 0.31830987f;
const MIN_D2_: f32 = 0.000000000001f;
const BSH_NONE: u32 = 4294967295u;
const RESERVOIR_FULL: u32 = 4294967295u;
const LIGHT_BVH_LEAF: u32 = 4294967295u;
const ONE_MINUS_EPSILON: f32 = 0.99999994f;
const F32_MAX: f32 = 340282350000000000000000000000000000000f;
const GGX_ALPHA_MIN: f32 = 0.001f;
const DEPTH_NONE: f32 = 1000000000000000000000000000000f;
const DEPTH_SIGMA: f32 = 0.05f;
const COVER_WEIGHT: f32 = 0.1f;
const NEAR_BLOCK: u32 = 64u;
const ROULETTE_DEPTH: u32 = 2u;
const K: u32 = 8u;
const BSH: u32 = 0u;
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
var<storage> r2_2: array<f32>;
@group(0) @binding(3) 
var<storage> rt2_4: array<f32>;
@group(0) @binding(0) 
var<uniform> params: ShadeParams;
@group(0) @binding(1) 
var<storage> vertices: array<GpuPathVertex>;
@group(0) @binding(8) 
var<storage, read_write> radiance: array<vec4<f32>>;
@group(0) @binding(9) 
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

fn sphere_contains_point(c: vec3<f32>, r: f32, x_1: vec3<f32>) -> bool {
    let v_1 = (x_1 - c);
    return (dot(v_1, v_1) <= (r * r));
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

    let v_2 = (x_2 - y);
    let d2_7 = dot(v_2, v_2);
    let _e7 = slc_keep(r2_1, d2_7);
    if !(!(_e7)) {
        local = !((d2_7 > 0f));
    } else {
        local = true;
    }
    let _e16 = local;
    if _e16 {
        return 0f;
    }
    let w_4 = (v_2 / vec3(sqrt(d2_7)));
    let cos_x_1 = -(dot(n, w_4));
    if !((cos_x_1 <= 0f)) {
        local_1 = (dot(ng, w_4) >= 0f);
    } else {
        local_1 = true;
    }
    let _e32 = local_1;
    if _e32 {
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
    let c_5 = abs(cos_light);
    if (c_5 <= 0f) {
        return 0f;
    }
    return ((pdf_area * d2_5) / c_5);
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

fn shadow_margin(len: f32) -> f32 {
    return (0.0001f * len);
}

fn ray_inverse(x_3: f32) -> f32 {
    return (1f / select(x_3, 0.000000000000000000000000000001f, (abs(x_3) < 0.000000000000000000000000000001f)));
}

fn ray_inverse3_(d: vec3<f32>) -> vec3<f32> {
    let _e2 = ray_inverse(d.x);
    let _e4 = ray_inverse(d.y);
    let _e6 = ray_inverse(d.z);
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

fn triangle_normal(a_4: vec3<f32>, b_4: vec3<f32>, c_2: vec3<f32>) -> vec3<f32> {
    var local_3: bool;

    let n_10 = cross((b_4 - a_4), (c_2 - a_4));
    let l2_ = dot(n_10, n_10);
    if !(!((l2_ > 0f))) {
        local_3 = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local_3 = true;
    }
    let _e17 = local_3;
    if _e17 {
        return vec3<f32>(0f, 0f, 0f);
    }
    return (n_10 / vec3(sqrt(l2_)));
}

fn ray_triangle(o_1: vec3<f32>, d_1: vec3<f32>, a_5: vec3<f32>, b_5: vec3<f32>, c_3: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_4: bool;
    var local_5: bool;
    var local_6: bool;

    let e1_ = (b_5 - a_5);
    let e2_ = (c_3 - a_5);
    let p = cross(d_1, e2_);
    let det = dot(e1_, p);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv = (1f / det);
    let s_1 = (o_1 - a_5);
    let u_1 = (dot(s_1, p) * inv);
    if !((u_1 < 0f)) {
        local_4 = (u_1 > 1f);
    } else {
        local_4 = true;
    }
    let _e28 = local_4;
    if _e28 {
        return -1f;
    }
    let q = cross(s_1, e1_);
    let v_3 = (dot(d_1, q) * inv);
    if !((v_3 < 0f)) {
        local_5 = ((u_1 + v_3) > 1f);
    } else {
        local_5 = true;
    }
    let _e42 = local_5;
    if _e42 {
        return -1f;
    }
    let t = (dot(e2_, q) * inv);
    if (t > t_min) {
        local_6 = (t < t_max_1);
    } else {
        local_6 = false;
    }
    let _e51 = local_6;
    if _e51 {
        return t;
    }
    return -1f;
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
    var local_7: bool;
    var local_8: bool;

    if !((d2_6 <= 0f)) {
        local_7 = (area_1 <= 0f);
    } else {
        local_7 = true;
    }
    let _e13 = local_7;
    if !(_e13) {
        local_8 = (cos_y <= 0f);
    } else {
        local_8 = true;
    }
    let _e20 = local_8;
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

fn finite3_(v: vec3<f32>) -> bool {
    var local_9: bool;
    var local_10: bool;

    if (abs(v.x) <= F32_MAX) {
        local_9 = (abs(v.y) <= F32_MAX);
    } else {
        local_9 = false;
    }
    let _e12 = local_9;
    if _e12 {
        local_10 = (abs(v.z) <= F32_MAX);
    } else {
        local_10 = false;
    }
    let _e20 = local_10;
    return _e20;
}

fn light_intensity(l: GpuLight, w_2: vec3<f32>) -> vec3<f32> {
    switch l.kind {
        case 3u: {
            let _e7 = triangle_normal(l.p0_, l.p1_, l.p2_);
            let _e9 = triangle_lobe(_e7, l.a, w_2);
            return (l.intensity * _e9);
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

fn light_area(l_2: GpuLight) -> f32 {
    if (l_2.kind == LIGHT_TRIANGLE) {
        return l_2.a;
    }
    return 0f;
}

fn light_normal(l_3: GpuLight) -> vec3<f32> {
    if (l_3.kind == LIGHT_TRIANGLE) {
        let _e7 = triangle_normal(l_3.p0_, l_3.p1_, l_3.p2_);
        return _e7;
    }
    return vec3(0f);
}

fn trace(o_2: vec3<f32>, d_2: vec3<f32>, t_min_1: f32, t_max_2: f32, any_hit: bool) -> GeoHit {
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
    let _e14 = ray_inverse3_(d_2);
    loop {
        let _e21 = node;
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
                        let t_1 = geo_tris[_e42];
                        let _e49 = hit.t;
                        let _e50 = ray_triangle(o_2, d_2, t_1.v0_, t_1.v1_, t_1.v2_, t_min_1, _e49);
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
                node = n_11.first;
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

fn occluded(a_6: vec3<f32>, b_6: vec3<f32>) -> bool {
    let dv = (b_6 - a_6);
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

fn bsh_next_leaf(nodes_3: u32, start: u32, x_4: vec3<f32>) -> u32 {
    var i_2: u32;

    i_2 = start;
    loop {
        let _e4 = i_2;
        if (_e4 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e7 = i_2;
            let _e8 = bsh_node(nodes_3, _e7);
            let _e11 = sphere_contains_point(_e8.center, _e8.radius, x_4);
            if _e11 {
                if (_e8.child == BSH_NONE) {
                    let _e15 = i_2;
                    return _e15;
                }
                i_2 = _e8.child;
            } else {
                i_2 = _e8.next;
            }
        }
    }
    return BSH_NONE;
}

fn bsh_collect(x_5: vec3<f32>, seed_1: u32) -> Picks {
    var picks: Picks;
    var h_1: u32;
    var i_3: u32;

    picks.n = 0u;
    h_1 = seed_1;
    let _e8 = bsh_first(BSH);
    let _e9 = bsh_next_leaf(BSH, _e8, x_5);
    i_3 = _e9;
    loop {
        let _e11 = i_3;
        if (_e11 != BSH_NONE) {
        } else {
            break;
        }
        {
            let _e15 = picks.n;
            let _e16 = reservoir_takes(_e15);
            if _e16 {
                let _e18 = picks.n;
                picks.n = (_e18 + 1u);
                let _e21 = h_1;
                let _e22 = pcg_hash(_e21);
                h_1 = _e22;
                let hi_3 = h_1;
                let _e24 = h_1;
                let _e25 = pcg_hash(_e24);
                h_1 = _e25;
                let _e27 = picks.n;
                let _e29 = h_1;
                let _e30 = reservoir_slot(_e27, K, hi_3, _e29);
                if (_e30 < K) {
                    let _e36 = i_3;
                    let _e39 = bsh_nodes[_e36].light;
                    picks.light[_e30] = _e39;
                }
            }
        }
        continuing {
            let _e42 = i_3;
            let _e45 = bsh_nodes[_e42].next;
            let _e46 = bsh_next_leaf(BSH, _e45, x_5);
            i_3 = _e46;
        }
    }
    let _e47 = picks;
    return _e47;
}

fn connect(li: u32, x_6: vec3<f32>, n_6: vec3<f32>, ng_1: vec3<f32>, w_res: f32, u1_2: f32, u2_2: f32, eps: f32) -> Connection {
    var c_4: Connection;
    var local_11: bool;

    c_4.e = vec3(0f);
    let l_4 = lights[li];
    let _e16 = light_point(l_4, u1_2, u2_2);
    c_4.y = _e16;
    let _e19 = c_4.y;
    let _e22 = r2_2[li];
    let _e23 = connection_cosine(x_6, _e19, n_6, ng_1, _e22);
    c_4.cos_x = _e23;
    let _e25 = c_4.cos_x;
    if !((_e25 <= 0f)) {
        let _e34 = c_4.y;
        let _e35 = occluded((x_6 + (ng_1 * eps)), _e34);
        local_11 = _e35;
    } else {
        local_11 = true;
    }
    let _e37 = local_11;
    if _e37 {
        let _e38 = c_4;
        return _e38;
    }
    let _e40 = c_4.y;
    let v_4 = (x_6 - _e40);
    let d2_8 = dot(v_4, v_4);
    let _e47 = light_intensity(l_4, (v_4 / vec3(sqrt(d2_8))));
    let _e49 = c_4.cos_x;
    let _e52 = rt2_4[li];
    let _e53 = connection_factor(_e49, d2_8, _e52, w_res);
    c_4.e = (_e47 * _e53);
    let _e55 = c_4;
    return _e55;
}

fn mis_weight(pdf_a_1: f32, pdf_b_1: f32) -> f32 {
    let _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

fn select_pdf(li_1: u32, x_7: vec3<f32>, n_7: vec3<f32>, nee: u32, in_range_1: bool) -> f32 {
    let _e6 = reservoir_select_pdf(nee, in_range_1, K);
    return _e6;
}

fn light_pdf(li_2: u32, x_8: vec3<f32>, n_8: vec3<f32>, y_1: vec3<f32>, nee_1: u32, in_range_2: bool) -> f32 {
    let l_5 = lights[li_2];
    let v_5 = (x_8 - y_1);
    let d2_9 = dot(v_5, v_5);
    let _e11 = light_normal(l_5);
    let cos_y_1 = select(0f, dot(_e11, (v_5 / vec3(sqrt(d2_9)))), (d2_9 > 0f));
    let _e20 = select_pdf(li_2, x_8, n_8, nee_1, in_range_2);
    let _e23 = rt2_4[li_2];
    let _e24 = light_area(l_5);
    let _e25 = light_strategy_pdf(_e20, _e23, d2_9, _e24, cos_y_1);
    return _e25;
}

fn shade_pick(li_3: u32, x_9: vec3<f32>, n_9: vec3<f32>, ng_2: vec3<f32>, w_3: f32, nee_2: u32, u1_3: f32, u2_3: f32) -> vec3<f32> {
    var mis: f32 = 1f;
    var local_12: bool;

    let _e10 = params.eps;
    let _e11 = connect(li_3, x_9, n_9, ng_2, w_3, u1_3, u2_3, _e10);
    let _e16 = lights[li_3];
    let _e17 = light_area(_e16);
    if (_e17 > 0f) {
        local_12 = (_e11.cos_x > 0f);
    } else {
        local_12 = false;
    }
    let _e26 = local_12;
    if _e26 {
        let _e29 = light_pdf(li_3, x_9, n_9, _e11.y, nee_2, true);
        let _e31 = cosine_pdf(_e11.cos_x);
        let _e32 = mis_weight(_e29, _e31);
        mis = _e32;
    }
    let _e34 = mis;
    return (_e11.e * _e34);
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
    let x_10 = vtx.position;
    let n_12 = vtx.normal;
    let ng_3 = vtx.gnormal;
    let _e20 = params.seed;
    let _e23 = params.frame;
    let _e24 = point_stream(_e20, i_4, _e23);
    let _e25 = pick_stream(_e24);
    h = _e25;
    let _e30 = bsh_collect(x_10, _e24);
    candidates[i_4] = _e30.n;
    let _e36 = reservoir_weight(_e30.n, K);
    loop {
        let _e39 = s;
        if (_e39 < min(_e30.n, K)) {
        } else {
            break;
        }
        {
            let _e44 = h;
            let _e45 = pcg_hash(_e44);
            h = _e45;
            let _e46 = h;
            let _e47 = xi_from_bits(_e46);
            let _e48 = h;
            let _e49 = pcg_hash(_e48);
            h = _e49;
            let _e50 = sum;
            let _e52 = s;
            let _e55 = h;
            let _e56 = xi_from_bits(_e55);
            let _e57 = shade_pick(_e30.light[_e52], x_10, n_12, ng_3, _e36, _e30.n, _e47, _e56);
            sum = (_e50 + _e57);
        }
        continuing {
            let _e60 = s;
            s = (_e60 + 1u);
        }
    }
    let _e63 = sum;
    let add = (vtx.weight * _e63);
    let _e65 = finite3_(add);
    if _e65 {
        let _e68 = radiance[i_4];
        radiance[i_4] = (_e68 + vec4<f32>(add, 0f));
        return;
    } else {
        return;
    }
}
