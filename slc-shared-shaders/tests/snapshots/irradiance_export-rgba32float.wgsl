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

struct GbTexel {
    position: vec4<f32>,
    normal: vec4<f32>,
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
var<uniform> view: ViewParams;
@group(0) @binding(1) 
var position_tex: texture_2d<f32>;
@group(0) @binding(2) 
var normal_tex: texture_2d<f32>;
@group(0) @binding(3) 
var<storage> irradiance: array<vec4<f32>>;
@group(0) @binding(4) 
var out_tex: texture_storage_2d<rgba32float,write>;

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p.xyz, 1f), (p.w > 0f));
}

fn gbuffer_at(i: u32) -> GbTexel {
    var local_1: bool;

    let _e3 = view.width;
    let _e8 = view.width;
    let texel_1 = vec2<i32>(i32((i % _e3)), i32((i / _e8)));
    let _e12 = surface_at(texel_1);
    let _e15 = textureLoad(normal_tex, texel_1, 0i);
    let n = _e15.xyz;
    let len2_ = dot(n, n);
    if (_e12.w > 0f) {
        local_1 = (len2_ > 0f);
    } else {
        local_1 = false;
    }
    let valid = local_1;
    let _e30 = view.eye;
    let v = (_e12.xyz - _e30);
    let position = vec4<f32>(_e12.xyz, select(0f, 1f, valid));
    let normal = select(vec4<f32>(0f, 0f, 0f, 1000000000000000000000000000000f), vec4<f32>((n / vec3(sqrt(len2_))), sqrt(dot(v, v))), valid);
    return GbTexel(position, normal);
}

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var local: bool;

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
    let _e19 = view.width;
    let i_1 = ((gid.y * _e19) + gid.x);
    let _e23 = gbuffer_at(i_1);
    let valid_1 = (_e23.position.w > 0f);
    let _e32 = irradiance[i_1];
    let e = select(vec4(0f), _e32, valid_1);
    textureStore(out_tex, vec2<i32>(i32(gid.x), i32(gid.y)), e);
    return;
}
