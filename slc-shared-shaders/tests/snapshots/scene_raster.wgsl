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

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) @interpolate(flat) geo: vec3<f32>,
    @location(3) @interpolate(flat) material: u32,
}

struct GbufferOut {
    @location(0) position: vec4<f32>,
    @location(1) normal: vec4<f32>,
}

struct RsmOut {
    @location(0) position: vec4<f32>,
    @location(1) normal: vec4<f32>,
    @location(2) flux: vec4<f32>,
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
var<uniform> params: MapParams;
@group(0) @binding(1) 
var<storage> materials: array<GpuMaterial>;

fn spot_falloff(cos_theta: f32, cos_outer: f32, cos_inner: f32, shape: f32) -> f32 {
    if (cos_inner <= cos_outer) {
        return select(0f, 1f, (cos_theta >= cos_outer));
    }
    let t = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return select(((t * t) * (3f - (2f * t))), (t * t), (shape > 0.5f));
}

fn face_against(n: vec3<f32>, dir_1: vec3<f32>) -> vec3<f32> {
    return select(n, -(n), (dot(n, dir_1) > 0f));
}

fn shading_normal(n0_: vec3<f32>, n1_: vec3<f32>, n2_: vec3<f32>, w: vec3<f32>, facing: vec3<f32>) -> vec3<f32> {
    var local: bool;

    let s = (((n0_ * w.x) + (n1_ * w.y)) + (n2_ * w.z));
    let l2_ = dot(s, s);
    if !(!((l2_ > 0.000000000001f))) {
        local = !((l2_ < 300000000000000000000000000000000000000f));
    } else {
        local = true;
    }
    let _e24 = local;
    if _e24 {
        return facing;
    }
    let n_1 = (s / vec3(sqrt(l2_)));
    return select(n_1, -(n_1), (dot(n_1, facing) < 0f));
}

fn light_map_depth(rel: vec3<f32>, axis: vec3<f32>, perspective: bool) -> f32 {
    return select(dot(rel, axis), sqrt(dot(rel, rel)), perspective);
}

fn rsm_texel_solid_angle(texel_area: f32, cos_axis: f32) -> f32 {
    return (((texel_area * cos_axis) * cos_axis) * cos_axis);
}

fn light_intensity(l: GpuLight, w_1: vec3<f32>) -> vec3<f32> {
    switch l.kind {
        case 1u: {
            let _e10 = spot_falloff(dot(l.p1_, w_1), l.a, l.b, l.p2_.x);
            return (l.intensity * _e10);
        }
        default: {
            return vec3(0f);
        }
    }
}

fn seen_normal(v_3: VsOut, dir_2: vec3<f32>) -> vec3<f32> {
    let _e12 = face_against(v_3.geo, dir_2);
    let _e13 = shading_normal(v_3.normal, vec3(0f), vec3(0f), vec3<f32>(1f, 0f, 0f), _e12);
    return _e13;
}

@vertex 
fn vs_main(@location(0) position: vec3<f32>, @location(1) material: u32, @location(2) normal: vec3<f32>, @location(3) geo: vec3<f32>) -> VsOut {
    let _e6 = params.c0_;
    let _e9 = params.c1_;
    let _e12 = params.c2_;
    let _e15 = params.c3_;
    let m = mat4x4<f32>(_e6, _e9, _e12, _e15);
    return VsOut((m * vec4<f32>(position, 1f)), position, normal, geo, material);
}

@fragment 
fn fs_gbuffer(v: VsOut) -> GbufferOut {
    let _e4 = params.origin;
    let _e6 = seen_normal(v, (v.world - _e4));
    return GbufferOut(vec4<f32>(v.world, 1f), vec4<f32>(_e6, f32(v.material)));
}

@fragment 
fn fs_rsm(v_1: VsOut) -> RsmOut {
    var dir: vec3<f32>;
    var incident: vec3<f32>;

    let _e3 = params.axis;
    dir = _e3;
    let _e8 = params.light.intensity;
    let _e11 = params.texel;
    incident = (_e8 * _e11);
    let _e16 = params.mode;
    if (_e16 == MAP_PERSPECTIVE) {
        let _e22 = params.origin;
        dir = normalize((v_1.world - _e22));
        let _e27 = params.light;
        let _e28 = dir;
        let _e29 = light_intensity(_e27, _e28);
        let _e32 = params.texel;
        let _e33 = dir;
        let _e36 = params.axis;
        let _e38 = rsm_texel_solid_angle(_e32, dot(_e33, _e36));
        incident = (_e29 * _e38);
    }
    let albedo = materials[v_1.material].albedo;
    let _e48 = dir;
    let _e49 = seen_normal(v_1, _e48);
    let _e52 = incident;
    return RsmOut(vec4<f32>(v_1.world, 1f), vec4<f32>(_e49, 0f), vec4<f32>((_e52 * albedo), 0f));
}

@fragment 
fn fs_shadow(v_2: VsOut) -> @location(0) vec4<f32> {
    let _e4 = params.origin;
    let _e8 = params.axis;
    let _e11 = params.mode;
    let _e14 = light_map_depth((v_2.world - _e4), _e8, (_e11 == MAP_PERSPECTIVE));
    return vec4<f32>(_e14, 0f, 0f, 0f);
}
