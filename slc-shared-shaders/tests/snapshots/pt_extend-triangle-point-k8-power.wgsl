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
const BVH: u32 = 0u;

@group(0) @binding(5) 
var<storage> geo_nodes: array<GpuGeoNode>;
@group(0) @binding(6) 
var<storage> geo_tris: array<GpuTriangle>;
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
var<storage> albedo: array<vec4<f32>>;
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
    let v_2 = (x_1 - c);
    return (dot(v_2, v_2) <= (r * r));
}

fn area_to_solid_angle_pdf(pdf_area: f32, d2_1: f32, cos_light: f32) -> f32 {
    let c_4 = abs(cos_light);
    if (c_4 <= 0f) {
        return 0f;
    }
    return ((pdf_area * d2_1) / c_4);
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

fn ray_inverse(x_2: f32) -> f32 {
    return (1f / select(x_2, 0.000000000000000000000000000001f, (abs(x_2) < 0.000000000000000000000000000001f)));
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
    let lo = min(t0_, t1_);
    let hi = max(t0_, t1_);
    let t_in = max(max(lo.x, lo.y), max(lo.z, 0f));
    let t_out = min(min(hi.x, hi.y), min(hi.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1f;
}

fn triangle_normal(a_2: vec3<f32>, b_2: vec3<f32>, c_1: vec3<f32>) -> vec3<f32> {
    var local_4: bool;

    let n_9 = cross((b_2 - a_2), (c_1 - a_2));
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

fn face_against(n_1: vec3<f32>, dir: vec3<f32>) -> vec3<f32> {
    return select(n_1, -(n_1), (dot(n_1, dir) > 0f));
}

fn barycentric(p: vec3<f32>, a_3: vec3<f32>, b_3: vec3<f32>, c_2: vec3<f32>) -> vec3<f32> {
    let e1_ = (b_3 - a_3);
    let e2_ = (c_2 - a_3);
    let q = (p - a_3);
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

fn shading_normal(n0_: vec3<f32>, n1_: vec3<f32>, n2_: vec3<f32>, w_1: vec3<f32>, facing: vec3<f32>) -> vec3<f32> {
    var local_5: bool;

    let s = (((n0_ * w_1.x) + (n1_ * w_1.y)) + (n2_ * w_1.z));
    let l2_1 = dot(s, s);
    if !(!((l2_1 > 0.000000000001f))) {
        local_5 = !((l2_1 < 300000000000000000000000000000000000000f));
    } else {
        local_5 = true;
    }
    let _e24 = local_5;
    if _e24 {
        return facing;
    }
    let n_10 = (s / vec3(sqrt(l2_1)));
    return select(n_10, -(n_10), (dot(n_10, facing) < 0f));
}

fn ray_triangle(o_1: vec3<f32>, d_1: vec3<f32>, a_4: vec3<f32>, b_4: vec3<f32>, c_3: vec3<f32>, t_min: f32, t_max_1: f32) -> f32 {
    var local_6: bool;
    var local_7: bool;
    var local_8: bool;

    let e1_1 = (b_4 - a_4);
    let e2_1 = (c_3 - a_4);
    let p_1 = cross(d_1, e2_1);
    let det = dot(e1_1, p_1);
    if (abs(det) <= 0f) {
        return -1f;
    }
    let inv = (1f / det);
    let s_1 = (o_1 - a_4);
    let u_2 = (dot(s_1, p_1) * inv);
    if !((u_2 < 0f)) {
        local_6 = (u_2 > 1f);
    } else {
        local_6 = true;
    }
    let _e28 = local_6;
    if _e28 {
        return -1f;
    }
    let q_1 = cross(s_1, e1_1);
    let v_3 = (dot(d_1, q_1) * inv);
    if !((v_3 < 0f)) {
        local_7 = ((u_2 + v_3) > 1f);
    } else {
        local_7 = true;
    }
    let _e42 = local_7;
    if _e42 {
        return -1f;
    }
    let t = (dot(e2_1, q_1) * inv);
    if (t > t_min) {
        local_8 = (t < t_max_1);
    } else {
        local_8 = false;
    }
    let _e51 = local_8;
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

fn light_strategy_pdf(select_: f32, rt2_1: f32, d2_2: f32, area: f32, cos_y: f32) -> f32 {
    var local_9: bool;
    var local_10: bool;

    if !((d2_2 <= 0f)) {
        local_9 = (area <= 0f);
    } else {
        local_9 = true;
    }
    let _e13 = local_9;
    if !(_e13) {
        local_10 = (cos_y <= 0f);
    } else {
        local_10 = true;
    }
    let _e20 = local_10;
    if _e20 {
        return 0f;
    }
    let _e22 = rr_probability(rt2_1, d2_2);
    let _e26 = area_to_solid_angle_pdf((1f / area), d2_2, cos_y);
    return ((select_ * _e22) * _e26);
}

fn lambert_brdf(rho: vec3<f32>) -> vec3<f32> {
    return (rho * INV_PI);
}

fn cosine_pdf(cos_theta: f32) -> f32 {
    return (max(cos_theta, 0f) * INV_PI);
}

fn onb_tangent(n_2: vec3<f32>) -> vec3<f32> {
    let s_3 = select(-1f, 1f, (n_2.z >= 0f));
    let a_5 = (-1f / (s_3 + n_2.z));
    return vec3<f32>((1f + (((s_3 * n_2.x) * n_2.x) * a_5)), (((s_3 * n_2.x) * n_2.y) * a_5), (-(s_3) * n_2.x));
}

fn onb_bitangent(n_3: vec3<f32>) -> vec3<f32> {
    let s_4 = select(-1f, 1f, (n_3.z >= 0f));
    let a_6 = (-1f / (s_4 + n_3.z));
    return vec3<f32>(((n_3.x * n_3.y) * a_6), (s_4 + ((n_3.y * n_3.y) * a_6)), -(n_3.y));
}

fn onb_to_world(n_4: vec3<f32>, d_2: vec3<f32>) -> vec3<f32> {
    let _e2 = onb_tangent(n_4);
    let _e5 = onb_bitangent(n_4);
    return (((_e2 * d_2.x) + (_e5 * d_2.y)) + (n_4 * d_2.z));
}

fn cosine_direction(n_5: vec3<f32>, u1_: f32, u2_: f32) -> vec3<f32> {
    let r_1 = sqrt(u1_);
    let phi = (6.2831855f * u2_);
    let _e16 = onb_to_world(n_5, vec3<f32>((r_1 * cos(phi)), (r_1 * sin(phi)), sqrt(max((1f - u1_), 0f))));
    return normalize(_e16);
}

fn camera_dir(forward: vec3<f32>, right: vec3<f32>, up: vec3<f32>, px: f32, py: f32, w_2: f32, h_1: f32) -> vec3<f32> {
    let sx = (((2f * px) / w_2) - 1f);
    let sy = (1f - ((2f * py) / h_1));
    return normalize(((forward + (right * sx)) + (up * sy)));
}

fn jittered_pixel(coord: u32, u_1: f32) -> f32 {
    let _e2 = to_f32_(coord);
    return (_e2 + u_1);
}

fn plays_roulette(depth: u32) -> bool {
    return (depth >= ROULETTE_DEPTH);
}

fn sees_emission(gn: vec3<f32>, dir_1: vec3<f32>) -> bool {
    return (dot(gn, dir_1) < 0f);
}

fn continues_path(nd: vec3<f32>, n_6: vec3<f32>, ng: vec3<f32>) -> bool {
    var local_11: bool;

    if (dot(nd, n_6) > 0f) {
        local_11 = (dot(nd, ng) > 0f);
    } else {
        local_11 = false;
    }
    let _e12 = local_11;
    return _e12;
}

fn finite3_(v_1: vec3<f32>) -> bool {
    var local_12: bool;
    var local_13: bool;

    if (abs(v_1.x) <= F32_MAX) {
        local_12 = (abs(v_1.y) <= F32_MAX);
    } else {
        local_12 = false;
    }
    let _e12 = local_12;
    if _e12 {
        local_13 = (abs(v_1.z) <= F32_MAX);
    } else {
        local_13 = false;
    }
    let _e20 = local_13;
    return _e20;
}

fn path_survival(beta: vec3<f32>) -> f32 {
    return clamp(max(max(beta.x, beta.y), beta.z), 0.05f, 0.95f);
}

fn light_area(l: GpuLight) -> f32 {
    if (l.kind == LIGHT_TRIANGLE) {
        return l.a;
    }
    return 0f;
}

fn light_normal(l_1: GpuLight) -> vec3<f32> {
    if (l_1.kind == LIGHT_TRIANGLE) {
        let _e7 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
        return _e7;
    }
    return vec3(0f);
}

fn trace(o_2: vec3<f32>, d_3: vec3<f32>, t_min_1: f32, t_max_2: f32, any_hit: bool) -> GeoHit {
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
    let _e14 = ray_inverse3_(d_3);
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
                        let _e50 = ray_triangle(o_2, d_3, t_1.v0_, t_1.v1_, t_1.v2_, t_min_1, _e49);
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

fn mis_weight(pdf_a_1: f32, pdf_b_1: f32) -> f32 {
    let _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

fn select_pdf(li: u32, x_3: vec3<f32>, n_7: vec3<f32>, nee: u32, in_range_1: bool) -> f32 {
    let _e6 = reservoir_select_pdf(nee, in_range_1, K);
    return _e6;
}

fn light_pdf(li_1: u32, x_4: vec3<f32>, n_8: vec3<f32>, y: vec3<f32>, nee_1: u32, in_range_2: bool) -> f32 {
    let l_2 = lights[li_1];
    let v_4 = (x_4 - y);
    let d2_3 = dot(v_4, v_4);
    let _e11 = light_normal(l_2);
    let cos_y_1 = select(0f, dot(_e11, (v_4 / vec3(sqrt(d2_3)))), (d2_3 > 0f));
    let _e20 = select_pdf(li_1, x_4, n_8, nee_1, in_range_2);
    let _e23 = rt2_2[li_1];
    let _e24 = light_area(l_2);
    let _e25 = light_strategy_pdf(_e20, _e23, d2_3, _e24, cos_y_1);
    return _e25;
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

    let i_1 = gid.x;
    let _e4 = params.width;
    let _e7 = params.height;
    if (i_1 >= (_e4 * _e7)) {
        return;
    }
    let _e13 = params.depth;
    if (_e13 == 0u) {
        let _e18 = params.seed;
        let _e21 = params.pass_index;
        let _e22 = path_stream(_e18, i_1, _e21);
        h = _e22;
        let _e26 = params.width;
        let _e28 = next_uniform((&h));
        let _e29 = jittered_pixel((i_1 % _e26), _e28);
        let _e32 = params.width;
        let _e34 = next_uniform((&h));
        let _e35 = jittered_pixel((i_1 / _e32), _e34);
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
        let _e74 = paths[i_1];
        st = _e74;
    }
    v.alive = 0u;
    let _e79 = st.alive;
    if (_e79 == 0u) {
        let _e84 = v;
        vertices[i_1] = _e84;
        return;
    }
    let _e86 = st.origin;
    let _e88 = st.dir;
    let _e91 = params.t_min;
    let _e94 = trace(_e86, _e88, _e91, F32_MAX, false);
    if (_e94.tri == NO_LIGHT) {
        st.alive = 0u;
        let _e102 = st;
        paths[i_1] = _e102;
        let _e105 = v;
        vertices[i_1] = _e105;
        return;
    }
    let tri = geo_tris[_e94.tri];
    let _e111 = st.origin;
    let _e113 = st.dir;
    let x_5 = (_e111 + (_e113 * _e94.t));
    let _e120 = triangle_normal(tri.v0_, tri.v1_, tri.v2_);
    let _e122 = st.dir;
    let _e123 = face_against(_e120, _e122);
    let b_5 = (_e94.tri * 3u);
    let _e129 = geo_normals[b_5];
    let _e135 = geo_normals[(b_5 + 1u)];
    let _e141 = geo_normals[(b_5 + 2u)];
    let _e146 = barycentric(x_5, tri.v0_, tri.v1_, tri.v2_);
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
            let leaf = bsh_nodes[_e168];
            let _e174 = st.prev;
            let _e175 = sphere_contains_point(leaf.center, leaf.radius, _e174);
            let _e177 = st.pdf_bsdf;
            let _e180 = st.prev;
            let _e182 = st.prev_normal;
            let _e185 = candidates[i_1];
            let _e186 = light_pdf(tri.light, _e180, _e182, x_5, _e185, _e175);
            let _e187 = mis_weight(_e177, _e186);
            w = _e187;
        }
        let _e189 = st.beta;
        let _e194 = lights[tri.light].intensity;
        let _e196 = w;
        let add = ((_e189 * _e194) * _e196);
        let _e198 = finite3_(add);
        if _e198 {
            let _e201 = radiance[i_1];
            radiance[i_1] = (_e201 + vec4<f32>(add, 0f));
        }
    }
    let _e208 = albedo[tri.material];
    let rho_1 = _e208.xyz;
    v.position = x_5;
    v.normal = _e147;
    v.gnormal = _e123;
    let _e215 = st.beta;
    let _e216 = lambert_brdf(rho_1);
    v.weight = (_e215 * _e216);
    v.alive = 1u;
    let _e222 = v;
    vertices[i_1] = _e222;
    let _e224 = st.rng;
    rng = _e224;
    let _e226 = next_uniform((&rng));
    let _e227 = next_uniform((&rng));
    let _e228 = cosine_direction(_e147, _e226, _e227);
    let cos_o = dot(_e228, _e147);
    let _e231 = st.beta;
    st.beta = (_e231 * rho_1);
    st.prev = x_5;
    st.prev_normal = _e147;
    let _e236 = cosine_pdf(cos_o);
    st.pdf_bsdf = _e236;
    let _e240 = params.eps;
    st.origin = (x_5 + (_e123 * _e240));
    st.dir = _e228;
    let _e244 = continues_path(_e228, _e147, _e123);
    if !(!(_e244)) {
        let _e251 = params.depth;
        let _e256 = params.max_depth;
        local_1 = ((_e251 + 1u) >= _e256);
    } else {
        local_1 = true;
    }
    let _e259 = local_1;
    if _e259 {
        st.alive = 0u;
    }
    let _e264 = params.depth;
    let _e265 = plays_roulette(_e264);
    if _e265 {
        let _e269 = st.alive;
        local_2 = (_e269 == 1u);
    } else {
        local_2 = false;
    }
    let _e273 = local_2;
    if _e273 {
        let _e275 = st.beta;
        let _e276 = path_survival(_e275);
        let _e277 = next_uniform((&rng));
        if (_e277 >= _e276) {
            st.alive = 0u;
        } else {
            let _e282 = st.beta;
            st.beta = (_e282 / vec3(_e276));
        }
    }
    let _e286 = rng;
    st.rng = _e286;
    let _e289 = st;
    paths[i_1] = _e289;
    return;
}
