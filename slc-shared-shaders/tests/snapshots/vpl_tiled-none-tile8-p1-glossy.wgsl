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

struct VplParams {
    width: u32,
    height: u32,
    lights_per_subset: u32,
    min_d2_: f32,
    near_r2_: f32,
    subset_shift: u32,
    far_groups_at: u32,
    near_clusters_at: u32,
    near_groups_at: u32,
    box_count: u32,
    pad0_: u32,
    pad1_: u32,
    far_grid: vec4<u32>,
    near_grid: vec4<u32>,
}

struct GpuMaterial {
    albedo: vec3<f32>,
    metallic: f32,
    emission: vec3<f32>,
    alpha: f32,
    f0_: vec3<f32>,
    f90_: f32,
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

struct WorkgroupBox {
    lo: vec3<f32>,
    hi: vec3<f32>,
}

struct GbTexel {
    position: vec4<f32>,
    normal: vec4<f32>,
}

struct Glossy {
    m: GpuMaterial,
    v: vec3<f32>,
    on: bool,
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
const P: u32 = 1u;
const TILE: u32 = 8u;
const THREADS: u32 = 64u;
const BOX_THREADS: u32 = 64u;
const MAX_TILE_LIGHTS: u32 = 1024u;

var<workgroup> wg_lo: array<vec3<f32>, 64>;
var<workgroup> wg_hi: array<vec3<f32>, 64>;
var<workgroup> wg_box: WorkgroupBox;
@group(0) @binding(0) 
var<uniform> params: VplParams;
@group(0) @binding(1) 
var<uniform> view: ViewParams;
@group(0) @binding(2) 
var position_tex: texture_2d<f32>;
@group(0) @binding(3) 
var normal_tex: texture_2d<f32>;
@group(0) @binding(4) 
var<storage> lights: array<GpuLight>;
@group(0) @binding(8) 
var<storage, read_write> irradiance: array<vec4<f32>>;
@group(0) @binding(9) 
var<storage, read_write> guide: array<vec4<f32>>;
@group(0) @binding(10) 
var<storage> materials: array<GpuMaterial>;
@group(0) @binding(11) 
var<storage, read_write> specular: array<vec4<f32>>;
var<private> pos: vec3<f32>;
var<private> nrm: vec3<f32>;
var<private> eye_distance: f32;
var<private> valid: bool;
var<private> e: vec3<f32>;
var<private> kept: u32;
var<private> s: vec3<f32>;
var<private> g_1: Glossy;

fn vpl_transfer(n_l: vec3<f32>, n_x: vec3<f32>, v: vec3<f32>, min_d2_: f32) -> f32 {
    let m = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0f) * max(-(dot(n_x, v)), 0f)) * INV_PI) / (m * m));
}

fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
    if (cos_h <= 0f) {
        return 0f;
    }
    let a2_ = (alpha * alpha);
    let t_1 = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t_1 * t_1));
}

fn smith_root(cos_: f32, alpha_1: f32) -> f32 {
    let a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1f - a2_1)) + a2_1));
}

fn smith_visibility(n_l_1: f32, n_v: f32, alpha_2: f32) -> f32 {
    var local_1: bool;

    if !((n_l_1 <= 0f)) {
        local_1 = (n_v <= 0f);
    } else {
        local_1 = true;
    }
    let _e11 = local_1;
    if _e11 {
        return 0f;
    }
    let _e13 = smith_root(n_v, alpha_2);
    let _e15 = smith_root(n_l_1, alpha_2);
    return (0.5f / ((n_l_1 * _e13) + (n_v * _e15)));
}

fn fresnel_schlick(f0_: vec3<f32>, f90_: f32, v_h: f32) -> vec3<f32> {
    let c = saturate((1f - v_h));
    let c2_ = (c * c);
    return (f0_ + ((vec3<f32>(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c)));
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
    let h = (v_1 + l);
    let len2_ = dot(h, h);
    if (len2_ <= 0f) {
        return 0f;
    }
    return saturate((dot(v_1, h) / sqrt(len2_)));
}

fn specular_brdf(base_2: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n: vec3<f32>, v_2: vec3<f32>, l_1: vec3<f32>) -> vec3<f32> {
    var local_2: bool;

    let n_l_2 = dot(n, l_1);
    let n_v_1 = dot(n, v_2);
    if !((n_l_2 <= 0f)) {
        local_2 = (n_v_1 <= 0f);
    } else {
        local_2 = true;
    }
    let _e18 = local_2;
    if _e18 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let hs = (v_2 + l_1);
    let inv = (1f / sqrt(dot(hs, hs)));
    let h_1 = (hs * inv);
    let c_1 = cross(n, h_1);
    let _e32 = ggx_d(dot(n, h_1), dot(c_1, c_1), alpha_3);
    let _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_2, h_1));
    let _e35 = smith_visibility(n_l_2, n_v_1, alpha_3);
    return (_e34 * (_e32 * _e35));
}

fn brdf_eval(base_3: vec3<f32>, metallic_3: f32, f0_d_3: vec3<f32>, f90_d_3: f32, alpha_4: f32, n_1: vec3<f32>, v_3: vec3<f32>, l_2: vec3<f32>) -> vec3<f32> {
    if (dot(n_1, l_2) <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = half_cosine(v_3, l_2);
    let _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    let _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_1, v_3, l_2);
    return (_e16 + _e17);
}

fn diffuse_albedo(base_4: vec3<f32>, metallic_4: f32) -> vec3<f32> {
    return (base_4 * (1f - metallic_4));
}

fn specular_correction(base_5: vec3<f32>, metallic_5: f32, f0_d_4: vec3<f32>, f90_d_4: f32, alpha_5: f32, n_2: vec3<f32>, v_4: vec3<f32>, l_3: vec3<f32>) -> vec3<f32> {
    let _e8 = brdf_eval(base_5, metallic_5, f0_d_4, f90_d_4, alpha_5, n_2, v_4, l_3);
    let _e9 = diffuse_albedo(base_5, metallic_5);
    return (_e8 - (_e9 * INV_PI));
}

fn has_specular(metallic_6: f32, f0_d_5: vec3<f32>, f90_d_5: f32) -> bool {
    var local_3: bool;
    var local_4: bool;

    if !((metallic_6 > 0f)) {
        local_3 = (f90_d_5 > 0f);
    } else {
        local_3 = true;
    }
    let _e11 = local_3;
    if !(_e11) {
        local_4 = (max(max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0f);
    } else {
        local_4 = true;
    }
    let _e23 = local_4;
    return _e23;
}

fn shifted_subset(pixel_class: u32, shift: u32, period: u32) -> u32 {
    return ((pixel_class + shift) % (period * period));
}

fn vpl_near_weight(d2_: f32, near_r2_: f32) -> f32 {
    if (near_r2_ <= 0f) {
        return 0f;
    }
    let t_2 = clamp(((near_r2_ - d2_) / (0.75f * near_r2_)), 0f, 1f);
    return ((t_2 * t_2) * (3f - (2f * t_2)));
}

fn vpl_far_weight(d2_1: f32, near_r2_1: f32) -> f32 {
    let _e2 = vpl_near_weight(d2_1, near_r2_1);
    return (1f - _e2);
}

fn workgroup_bounds(li_1: u32, lo: vec3<f32>, hi: vec3<f32>) -> WorkgroupBox {
    var stride: u32 = 32u;

    wg_lo[li_1] = lo;
    wg_hi[li_1] = hi;
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

fn point_box(p: vec3<f32>, has: bool) -> WorkgroupBox {
    return WorkgroupBox(select(vec3(340282350000000000000000000000000000000f), p, has), select(vec3(-340282350000000000000000000000000000000f), p, has));
}

fn workgroup_box(li_2: u32, p_1: vec3<f32>, has_1: bool) -> WorkgroupBox {
    let _e3 = point_box(p_1, has_1);
    let _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi);
    return _e6;
}

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p_3 = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p_3.xyz, 1f), (p_3.w > 0f));
}

fn gbuffer_at(i: u32) -> GbTexel {
    var local_5: bool;

    let _e3 = view.width;
    let _e8 = view.width;
    let texel_1 = vec2<i32>(i32((i % _e3)), i32((i / _e8)));
    let _e12 = surface_at(texel_1);
    let _e15 = textureLoad(normal_tex, texel_1, 0i);
    let n_4 = _e15.xyz;
    let len2_1 = dot(n_4, n_4);
    if (_e12.w > 0f) {
        local_5 = (len2_1 > 0f);
    } else {
        local_5 = false;
    }
    let valid_1 = local_5;
    let _e30 = view.eye;
    let v_6 = (_e12.xyz - _e30);
    let position = vec4<f32>(_e12.xyz, select(0f, 1f, valid_1));
    let normal = select(vec4<f32>(0f, 0f, 0f, 1000000000000000000000000000000f), vec4<f32>((n_4 / vec3(sqrt(len2_1))), sqrt(dot(v_6, v_6))), valid_1);
    return GbTexel(position, normal);
}

fn glossy_at(i_1: u32, x: vec3<f32>) -> Glossy {
    let _e4 = view.width;
    let _e9 = view.width;
    let texel_2 = vec2<i32>(i32((i_1 % _e4)), i32((i_1 / _e9)));
    let _e16 = textureLoad(normal_tex, texel_2, 0i);
    let m_1 = materials[u32(_e16.w)];
    let _e23 = view.eye;
    let _e29 = has_specular(m_1.metallic, m_1.f0_, m_1.f90_);
    return Glossy(m_1, normalize((_e23 - x)), _e29);
}

fn glossy_term(g: Glossy, l_4: GpuLight, n_3: vec3<f32>, v_5: vec3<f32>, t: f32) -> vec3<f32> {
    var local_6: bool;

    if !(!(g.on)) {
        local_6 = (t <= 0f);
    } else {
        local_6 = true;
    }
    let _e13 = local_6;
    if _e13 {
        return vec3(0f);
    }
    let _e30 = specular_correction(g.m.albedo, g.m.metallic, g.m.f0_, g.m.f90_, g.m.alpha, n_3, g.v, normalize(-(v_5)));
    return ((l_4.intensity * _e30) * t);
}

fn load_receiver(li_3: u32, pix: u32, inside: bool) -> WorkgroupBox {
    var p_2: vec4<f32> = vec4(0f);
    var local_7: bool;

    eye_distance = DEPTH_NONE;
    if inside {
        let _e8 = gbuffer_at(pix);
        p_2 = _e8.position;
        nrm = _e8.normal.xyz;
        eye_distance = _e8.normal.w;
    }
    let _e17 = p_2;
    pos = _e17.xyz;
    if inside {
        let _e23 = p_2.w;
        local_7 = (_e23 > 0f);
    } else {
        local_7 = false;
    }
    let _e27 = local_7;
    valid = _e27;
    let _e29 = valid;
    if _e29 {
        let _e32 = pos;
        let _e33 = glossy_at(pix, _e32);
        g_1 = _e33;
    }
    let _e35 = pos;
    let _e37 = valid;
    let _e38 = workgroup_box(li_3, _e35, _e37);
    return _e38;
}

fn shade_light(j_1: u32) {
    let l_5 = lights[j_1];
    let _e5 = pos;
    let v_7 = (_e5 - l_5.p0_);
    let _e11 = params.near_r2_;
    let _e12 = vpl_far_weight(dot(v_7, v_7), _e11);
    if (_e12 > 0f) {
        let _e17 = nrm;
        let _e20 = params.min_d2_;
        let _e21 = vpl_transfer(l_5.p1_, _e17, v_7, _e20);
        let t_3 = (_e21 * _e12);
        let _e24 = e;
        e = (_e24 + (l_5.intensity * t_3));
        let _e29 = s;
        let _e31 = g_1;
        let _e33 = nrm;
        let _e34 = glossy_term(_e31, l_5, _e33, v_7, t_3);
        s = (_e29 + _e34);
        let _e37 = kept;
        kept = (_e37 + 1u);
        return;
    } else {
        return;
    }
}

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    var local: bool;
    var j: u32;

    let sub = wg.z;
    let px = ((sub % P) + (((wg.x * TILE) + lid.x) * P));
    let py = ((sub / P) + (((wg.y * TILE) + lid.y) * P));
    let _e26 = params.width;
    if (px < _e26) {
        let _e32 = params.height;
        local = (py < _e32);
    } else {
        local = false;
    }
    let inside_1 = local;
    let _e38 = params.width;
    let pix_1 = ((py * _e38) + px);
    let _e41 = load_receiver(li, pix_1, inside_1);
    let _e44 = params.subset_shift;
    let _e46 = shifted_subset(sub, _e44, P);
    let _e48 = valid;
    if _e48 {
        let _e51 = params.lights_per_subset;
        let base_6 = (_e46 * _e51);
        j = base_6;
        loop {
            let _e54 = j;
            let _e57 = params.lights_per_subset;
            if (_e54 < (base_6 + _e57)) {
            } else {
                break;
            }
            {
                let _e61 = j;
                let _e64 = lights[_e61].intensity;
                if any((_e64 != vec3(0f))) {
                    let _e69 = j;
                    shade_light(_e69);
                }
            }
            continuing {
                let _e71 = j;
                j = (_e71 + 1u);
            }
        }
    }
    if inside_1 {
        let _e76 = e;
        let _e78 = kept;
        irradiance[pix_1] = vec4<f32>(_e76, f32(_e78));
        let _e84 = nrm;
        let _e86 = eye_distance;
        guide[pix_1] = vec4<f32>(_e84, _e86);
        let _e91 = s;
        specular[pix_1] = vec4<f32>(_e91, 0f);
        return;
    } else {
        return;
    }
}
