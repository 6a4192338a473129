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

struct ImageParams {
    eye: vec3<f32>,
    width: u32,
    height: u32,
    pad0_: u32,
    pad1_: u32,
    pad2_: u32,
}

struct GpuMaterial {
    albedo: vec3<f32>,
    metallic: f32,
    emission: vec3<f32>,
    alpha: f32,
    f0_: vec3<f32>,
    f90_: f32,
}

struct MapParams {
    c0_: vec4<f32>,
    c1_: vec4<f32>,
    c2_: vec4<f32>,
    c3_: vec4<f32>,
    light: GpuLight,
    origin: vec3<f32>,
    mode: u32,
    axis: vec3<f32>,
    size: u32,
    right: vec3<f32>,
    extent: f32,
    up: vec3<f32>,
    texel: f32,
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

@group(0) @binding(0) 
var<uniform> image: ImageParams;
@group(0) @binding(1) 
var position_tex: texture_2d<f32>;
@group(0) @binding(2) 
var normal_tex: texture_2d<f32>;
@group(0) @binding(3) 
var indirect_tex: texture_2d<f32>;
@group(0) @binding(4) 
var<storage> direct_1: array<vec4<f32>>;
@group(0) @binding(5) 
var<storage> materials: array<GpuMaterial>;
@group(0) @binding(6) 
var out_tex: texture_storage_2d<rgba32float,write>;
@group(0) @binding(7) 
var specular_tex: texture_2d<f32>;
@group(0) @binding(8) 
var<uniform> params: MapParams;

fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
    if (cos_h <= 0f) {
        return 0f;
    }
    let a2_ = (alpha * alpha);
    let t = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t * t));
}

fn smith_root(cos_: f32, alpha_1: f32) -> f32 {
    let a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1f - a2_1)) + a2_1));
}

fn smith_visibility(n_l: f32, n_v: f32, alpha_2: f32) -> f32 {
    var local_1: bool;

    if !((n_l <= 0f)) {
        local_1 = (n_v <= 0f);
    } else {
        local_1 = true;
    }
    let _e11 = local_1;
    if _e11 {
        return 0f;
    }
    let _e13 = smith_root(n_v, alpha_2);
    let _e15 = smith_root(n_l, alpha_2);
    return (0.5f / ((n_l * _e13) + (n_v * _e15)));
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

fn half_cosine(v: vec3<f32>, l: vec3<f32>) -> f32 {
    let h = (v + l);
    let len2_ = dot(h, h);
    if (len2_ <= 0f) {
        return 0f;
    }
    return saturate((dot(v, h) / sqrt(len2_)));
}

fn specular_brdf(base_2: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n: vec3<f32>, v_1: vec3<f32>, l_1: vec3<f32>) -> vec3<f32> {
    var local_2: bool;

    let n_l_1 = dot(n, l_1);
    let n_v_1 = dot(n, v_1);
    if !((n_l_1 <= 0f)) {
        local_2 = (n_v_1 <= 0f);
    } else {
        local_2 = true;
    }
    let _e18 = local_2;
    if _e18 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let hs = (v_1 + l_1);
    let inv = (1f / sqrt(dot(hs, hs)));
    let h_1 = (hs * inv);
    let c_1 = cross(n, h_1);
    let _e32 = ggx_d(dot(n, h_1), dot(c_1, c_1), alpha_3);
    let _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_1, h_1));
    let _e35 = smith_visibility(n_l_1, n_v_1, alpha_3);
    return (_e34 * (_e32 * _e35));
}

fn brdf_eval(base_3: vec3<f32>, metallic_3: f32, f0_d_3: vec3<f32>, f90_d_3: f32, alpha_4: f32, n_1: vec3<f32>, v_2: vec3<f32>, l_2: vec3<f32>) -> vec3<f32> {
    if (dot(n_1, l_2) <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = half_cosine(v_2, l_2);
    let _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    let _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_1, v_2, l_2);
    return (_e16 + _e17);
}

fn diffuse_albedo(base_4: vec3<f32>, metallic_4: f32) -> vec3<f32> {
    return (base_4 * (1f - metallic_4));
}

fn has_specular(metallic_5: f32, f0_d_4: vec3<f32>, f90_d_4: f32) -> bool {
    var local_3: bool;
    var local_4: bool;

    if !((metallic_5 > 0f)) {
        local_3 = (f90_d_4 > 0f);
    } else {
        local_3 = true;
    }
    let _e11 = local_3;
    if !(_e11) {
        local_4 = (max(max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0f);
    } else {
        local_4 = true;
    }
    let _e23 = local_4;
    return _e23;
}

fn diffuse_radiance(albedo: vec3<f32>, emission: vec3<f32>, e: vec3<f32>) -> vec3<f32> {
    return (emission + ((albedo * INV_PI) * e));
}

fn primary_light_dir(x: vec3<f32>, origin: vec3<f32>, axis: vec3<f32>, perspective: bool) -> vec3<f32> {
    var local_5: bool;

    let v_3 = (origin - x);
    let d2_ = dot(v_3, v_3);
    if perspective {
        local_5 = (d2_ > 0f);
    } else {
        local_5 = false;
    }
    let _e11 = local_5;
    if _e11 {
        return (v_3 / vec3(sqrt(d2_)));
    }
    return -(axis);
}

fn glossy_radiance(base_5: vec3<f32>, emission_1: vec3<f32>, metallic_6: f32, f_direct: vec3<f32>, direct: vec3<f32>, indirect: vec3<f32>, specular: vec3<f32>) -> vec3<f32> {
    let _e9 = diffuse_albedo(base_5, metallic_6);
    return (((emission_1 + (f_direct * direct)) + ((_e9 * INV_PI) * indirect)) + specular);
}

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var local: bool;
    var radiance: vec3<f32> = vec3(0f);

    let _e4 = image.width;
    if !((gid.x >= _e4)) {
        let _e12 = image.height;
        local = (gid.y >= _e12);
    } else {
        local = true;
    }
    let _e15 = local;
    if _e15 {
        return;
    }
    let _e19 = image.width;
    let i = ((gid.y * _e19) + gid.x);
    let texel = vec2<i32>(i32(gid.x), i32(gid.y));
    let p = textureLoad(position_tex, texel, 0i);
    if (p.w > 0f) {
        let nm = textureLoad(normal_tex, texel, 0i);
        let m = materials[u32(nm.w)];
        let _e47 = textureLoad(indirect_tex, texel, 0i);
        let e_1 = _e47.xyz;
        let _e52 = has_specular(m.metallic, m.f0_, m.f90_);
        if _e52 {
            let _e56 = params.origin;
            let _e59 = params.axis;
            let _e62 = params.mode;
            let _e65 = primary_light_dir(p.xyz, _e56, _e59, (_e62 == MAP_PERSPECTIVE));
            let _e75 = image.eye;
            let _e79 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, normalize(nm.xyz), normalize((_e75 - p.xyz)), _e65);
            let _e85 = direct_1[i];
            let _e89 = textureLoad(specular_tex, texel, 0i);
            let _e91 = glossy_radiance(m.albedo, m.emission, m.metallic, _e79, _e85.xyz, e_1, _e89.xyz);
            radiance = _e91;
        } else {
            let _e96 = direct_1[i];
            let _e99 = diffuse_radiance(m.albedo, m.emission, (_e96.xyz + e_1));
            radiance = _e99;
        }
    }
    let _e101 = radiance;
    textureStore(out_tex, texel, vec4<f32>(_e101, 1f));
    return;
}
