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
var<uniform> params: MapParams;
@group(0) @binding(1) 
var<uniform> image: ImageParams;
@group(0) @binding(2) 
var position_tex: texture_2d<f32>;
@group(0) @binding(3) 
var normal_tex: texture_2d<f32>;
@group(0) @binding(4) 
var shadow_map: texture_2d<f32>;
@group(0) @binding(5) 
var<storage, read_write> direct: array<vec4<f32>>;

fn to_f32_(u: u32) -> f32 {
    return f32(u);
}

fn to_u32_(x: f32) -> u32 {
    return u32(x);
}

fn inverse_square(d2_: f32) -> f32 {
    return (1f / max(d2_, MIN_D2_));
}

fn spot_falloff(cos_theta: f32, cos_outer: f32, cos_inner: f32, shape: f32) -> f32 {
    if (cos_inner <= cos_outer) {
        return select(0f, 1f, (cos_theta >= cos_outer));
    }
    let t = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return select(((t * t) * (3f - (2f * t))), (t * t), (shape > 0.5f));
}

fn light_map_texel(a_1: f32, size: u32) -> u32 {
    let _e6 = to_f32_(size);
    let _e9 = to_f32_(size);
    let _e14 = to_u32_(clamp(floor((((a_1 + 1f) * 0.5f) * _e6)), 0f, (_e9 - 1f)));
    return _e14;
}

fn light_map_coord_at(rel: vec3<f32>, dir: vec3<f32>, axis: vec3<f32>, extent: f32, perspective: bool) -> f32 {
    return (dot(rel, dir) / (select(1f, dot(rel, axis), perspective) * extent));
}

fn light_map_depth(rel_1: vec3<f32>, axis_1: vec3<f32>, perspective_1: bool) -> f32 {
    return select(dot(rel_1, axis_1), sqrt(dot(rel_1, rel_1)), perspective_1);
}

fn point_irradiance(intensity: vec3<f32>, n: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    let d2_1 = dot(v, v);
    let cos_x = (dot(n, v) / sqrt(max(d2_1, MIN_D2_)));
    let _e11 = inverse_square(d2_1);
    return (intensity * (max(cos_x, 0f) * _e11));
}

fn directional_irradiance(e_1: vec3<f32>, n_1: vec3<f32>, to_light: vec3<f32>) -> vec3<f32> {
    return (e_1 * max(dot(n_1, to_light), 0f));
}

fn perspective_texel_width(extent_1: f32, d: f32, z: f32, size_1: f32) -> f32 {
    return ((((2f * extent_1) * d) * d) / (size_1 * z));
}

fn ortho_texel_width(extent_2: f32, size_2: f32) -> f32 {
    return ((2f * extent_2) / size_2);
}

fn shadow_bias(texel: f32, cos_light_1: f32) -> f32 {
    let c = clamp(cos_light_1, 0.02f, 1f);
    return (texel * (1.5f + (sqrt((1f - (c * c))) / c)));
}

fn shadow_lit(d_1: f32, d_map: f32, bias: f32) -> bool {
    var local_4: bool;

    if !((d_map <= 0f)) {
        local_4 = (d_1 <= (d_map + bias));
    } else {
        local_4 = true;
    }
    let _e11 = local_4;
    return _e11;
}

fn light_intensity(l: GpuLight, w: vec3<f32>) -> vec3<f32> {
    switch l.kind {
        case 1u: {
            let _e10 = spot_falloff(dot(l.p1_, w), l.a, l.b, l.p2_.x);
            return (l.intensity * _e10);
        }
        default: {
            return vec3(0f);
        }
    }
}

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var local: bool;
    var local_1: bool;
    var e: vec3<f32> = vec3(0f);
    var a: f32 = 0f;
    var b: f32 = 0f;
    var width: f32 = 0f;
    var cos_light: f32 = 0f;
    var local_2: bool;
    var local_3: bool;

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
    let texel_1 = vec2<i32>(i32(gid.x), i32(gid.y));
    let p = textureLoad(position_tex, texel_1, 0i);
    let _e33 = textureLoad(normal_tex, texel_1, 0i);
    let nn = _e33.xyz;
    if !(!((p.w > 0f))) {
        local_1 = (dot(nn, nn) <= 0f);
    } else {
        local_1 = true;
    }
    let _e46 = local_1;
    if _e46 {
        direct[i] = vec4(0f);
        return;
    }
    let x_1 = p.xyz;
    let n_2 = normalize(nn);
    let _e55 = params.size;
    let size_3 = f32(_e55);
    let _e66 = params.origin;
    let rel_2 = (x_1 - _e66);
    let _e70 = params.axis;
    let _e73 = params.mode;
    let _e76 = light_map_depth(rel_2, _e70, (_e73 == MAP_PERSPECTIVE));
    let _e83 = params.mode;
    if (_e83 == MAP_PERSPECTIVE) {
        let v_1 = -(rel_2);
        let _e89 = params.axis;
        let z_1 = dot(rel_2, _e89);
        if !((z_1 <= 0f)) {
            local_2 = (_e76 <= 0f);
        } else {
            local_2 = true;
        }
        let _e99 = local_2;
        if _e99 {
            direct[i] = vec4(0f);
            return;
        }
        let _e106 = params.right;
        let _e109 = params.axis;
        let _e112 = params.extent;
        let _e114 = light_map_coord_at(rel_2, _e106, _e109, _e112, true);
        a = _e114;
        let _e117 = params.up;
        let _e120 = params.axis;
        let _e123 = params.extent;
        let _e125 = light_map_coord_at(rel_2, _e117, _e120, _e123, true);
        b = _e125;
        let _e128 = params.extent;
        let _e129 = perspective_texel_width(_e128, _e76, z_1, size_3);
        width = _e129;
        cos_light = (dot(n_2, v_1) / _e76);
        let _e134 = params.light;
        let _e137 = light_intensity(_e134, (rel_2 / vec3(_e76)));
        let _e138 = point_irradiance(_e137, n_2, v_1);
        e = _e138;
    } else {
        let _e141 = params.right;
        let _e144 = params.axis;
        let _e147 = params.extent;
        let _e149 = light_map_coord_at(rel_2, _e141, _e144, _e147, false);
        a = _e149;
        let _e152 = params.up;
        let _e155 = params.axis;
        let _e158 = params.extent;
        let _e160 = light_map_coord_at(rel_2, _e152, _e155, _e158, false);
        b = _e160;
        let _e163 = params.extent;
        let _e164 = ortho_texel_width(_e163, size_3);
        width = _e164;
        let _e167 = params.axis;
        cos_light = -(dot(n_2, _e167));
        let _e173 = params.light.intensity;
        let _e176 = params.axis;
        let _e178 = directional_irradiance(_e173, n_2, -(_e176));
        e = _e178;
    }
    let _e179 = a;
    if (abs(_e179) <= 1f) {
        let _e185 = b;
        local_3 = (abs(_e185) <= 1f);
    } else {
        local_3 = false;
    }
    let _e190 = local_3;
    if _e190 {
        let _e192 = a;
        let _e195 = params.size;
        let _e196 = light_map_texel(_e192, _e195);
        let _e198 = b;
        let _e201 = params.size;
        let _e202 = light_map_texel(_e198, _e201);
        let _e206 = textureLoad(shadow_map, vec2<i32>(i32(_e196), i32(_e202)), 0i);
        let d_map_1 = _e206.x;
        let _e208 = width;
        let _e209 = cos_light;
        let _e210 = shadow_bias(_e208, _e209);
        let _e211 = shadow_lit(_e76, d_map_1, _e210);
        if !(_e211) {
            e = vec3(0f);
        }
    }
    let _e217 = e;
    direct[i] = vec4<f32>(_e217, 0f);
    return;
}
