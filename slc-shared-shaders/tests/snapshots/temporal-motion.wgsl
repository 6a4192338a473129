struct TemporalParams {
    c0_: vec4<f32>,
    c1_: vec4<f32>,
    c2_: vec4<f32>,
    c3_: vec4<f32>,
    prev_eye: vec3<f32>,
    max_history: f32,
    has_history: u32,
    pad0_: u32,
    pad1_: u32,
    pad2_: u32,
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
var<uniform> params: TemporalParams;
@group(0) @binding(4) 
var signal_tex: texture_2d<f32>;
@group(0) @binding(5) 
var hist_value: texture_2d<f32>;
@group(0) @binding(6) 
var hist_noise: texture_2d<f32>;
@group(0) @binding(7) 
var hist_surface: texture_2d<f32>;
@group(0) @binding(8) 
var out_tex: texture_storage_2d<rgba32float,write>;
@group(0) @binding(9) 
var next_value: texture_storage_2d<rgba32float,write>;
@group(0) @binding(10) 
var next_noise: texture_storage_2d<rgba32float,write>;
@group(0) @binding(11) 
var next_surface: texture_storage_2d<rgba32float,write>;
@group(0) @binding(12) 
var motion_tex: texture_2d<f32>;

fn to_f32_(u: u32) -> f32 {
    return f32(u);
}

fn luminance(c: vec3<f32>) -> f32 {
    return dot(c, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn reproject_motion(px: f32, py: f32, mx: f32, my: f32, width: f32, height: f32) -> vec3<f32> {
    return vec3<f32>((px - (mx * width)), (py - (my * height)), 1f);
}

fn bilinear_weight(fx: f32, fy: f32, dx: u32, dy: u32) -> f32 {
    let wx = select((1f - fx), fx, (dx == 1u));
    let wy = select((1f - fy), fy, (dy == 1u));
    return (wx * wy);
}

fn history_tap(q: vec3<f32>, k_1: u32, width_1: f32, height_1: f32) -> vec4<f32> {
    var local_1: bool;
    var local_2: bool;
    var local_3: bool;
    var local_4: bool;

    let x0_ = floor(q.x);
    let y0_ = floor(q.y);
    let dx_1 = (k_1 % 2u);
    let dy_1 = (k_1 / 2u);
    let _e12 = to_f32_(dx_1);
    let tx = (x0_ + _e12);
    let _e14 = to_f32_(dy_1);
    let ty = (y0_ + _e14);
    if (q.z > 0f) {
        local_1 = (tx >= 0f);
    } else {
        local_1 = false;
    }
    let _e24 = local_1;
    if _e24 {
        local_2 = (ty >= 0f);
    } else {
        local_2 = false;
    }
    let _e30 = local_2;
    if _e30 {
        local_3 = (tx < width_1);
    } else {
        local_3 = false;
    }
    let _e35 = local_3;
    if _e35 {
        local_4 = (ty < height_1);
    } else {
        local_4 = false;
    }
    let inside = local_4;
    let _e45 = bilinear_weight((q.x - x0_), (q.y - y0_), dx_1, dy_1);
    return vec4<f32>(tx, ty, _e45, select(0f, 1f, inside));
}

fn history_mean(sum: vec4<f32>, weight_1: f32) -> vec4<f32> {
    if (weight_1 < TEMPORAL_MIN_WEIGHT) {
        return vec4<f32>(0f, 0f, 0f, 0f);
    }
    return (sum / vec4(weight_1));
}

fn temporal_change(l: f32, m1_: f32, noise: f32, n: f32) -> f32 {
    if (n < TEMPORAL_MIN_MOMENTS) {
        return 0f;
    }
    let sigma = sqrt((max(noise, 0f) * (1f + (1f / n))));
    let t = (abs((l - m1_)) / ((sigma + (0.001f * max(abs(l), abs(m1_)))) + 0.00000000000000000001f));
    return clamp(((t - TEMPORAL_CHANGE_LOW) / 4f), 0f, 1f);
}

fn next_history_length(n_1: f32, lambda: f32, max_history: f32) -> f32 {
    return min((((1f - lambda) * n_1) + 1f), max(max_history, 1f));
}

fn temporal_alpha(n_2: f32) -> f32 {
    return (1f / max(n_2, 1f));
}

fn history_tap_weight_motion(w: f32, n_3: vec3<f32>, nh: vec3<f32>, d: f32, dh: f32, len: f32) -> f32 {
    var local_5: bool;
    var local_6: bool;

    if (len > 0f) {
        local_5 = (abs((dh - d)) <= (TEMPORAL_MOTION_DEPTH_TOLERANCE * d));
    } else {
        local_5 = false;
    }
    let _e16 = local_5;
    if _e16 {
        local_6 = (dot(n_3, nh) >= TEMPORAL_NORMAL_COS);
    } else {
        local_6 = false;
    }
    let _e23 = local_6;
    return select(0f, w, _e23);
}

fn persistent_change(l_1: f32, last: f32, m1_1: f32, noise_1: f32, n_4: f32) -> f32 {
    if (((l_1 - m1_1) * (last - m1_1)) <= 0f) {
        return 0f;
    }
    let _e11 = temporal_change(l_1, m1_1, noise_1, n_4);
    let _e12 = temporal_change(last, m1_1, noise_1, n_4);
    return min(_e11, _e12);
}

fn temporal_color(c_1: vec3<f32>, h: vec4<f32>, noise_2: f32, last_1: f32, max_history_1: f32) -> vec4<f32> {
    let hc = vec3<f32>(h.x, h.y, h.z);
    let _e9 = luminance(c_1);
    let _e10 = luminance(hc);
    let _e12 = persistent_change(_e9, last_1, _e10, noise_2, h.w);
    let _e14 = next_history_length(h.w, _e12, max_history_1);
    let _e15 = temporal_alpha(_e14);
    let v_1 = ((hc * (1f - _e15)) + (c_1 * _e15));
    return vec4<f32>(v_1.x, v_1.y, v_1.z, _e14);
}

fn temporal_moments(c_2: vec3<f32>, last_2: f32, noise_3: f32, prev_len: f32, len_1: f32, depth: f32) -> vec4<f32> {
    var local_7: bool;

    let _e6 = luminance(c_2);
    if (prev_len <= 0f) {
        return vec4<f32>(_e6, 0f, depth, 0f);
    }
    let d_1 = (_e6 - last_2);
    let d2_ = ((0.5f * d_1) * d_1);
    let cap = (16f * noise_3);
    if (prev_len >= TEMPORAL_MIN_MOMENTS) {
        local_7 = (noise_3 > 0f);
    } else {
        local_7 = false;
    }
    let _e26 = local_7;
    let sample = select(d2_, min(d2_, cap), _e26);
    let _e31 = temporal_alpha((len_1 - 1f));
    return vec4<f32>(_e6, (noise_3 + ((sample - noise_3) * _e31)), depth, 0f);
}

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p.xyz, 1f), (p.w > 0f));
}

fn gbuffer_at(i: u32) -> GbTexel {
    var local_8: bool;

    let _e3 = view.width;
    let _e8 = view.width;
    let texel_1 = vec2<i32>(i32((i % _e3)), i32((i / _e8)));
    let _e12 = surface_at(texel_1);
    let _e15 = textureLoad(normal_tex, texel_1, 0i);
    let n_5 = _e15.xyz;
    let len2_ = dot(n_5, n_5);
    if (_e12.w > 0f) {
        local_8 = (len2_ > 0f);
    } else {
        local_8 = false;
    }
    let valid = local_8;
    let _e30 = view.eye;
    let v_2 = (_e12.xyz - _e30);
    let position = vec4<f32>(_e12.xyz, select(0f, 1f, valid));
    let normal = select(vec4<f32>(0f, 0f, 0f, 1000000000000000000000000000000f), vec4<f32>((n_5 / vec3(sqrt(len2_))), sqrt(dot(v_2, v_2))), valid);
    return GbTexel(position, normal);
}

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var local: bool;
    var hv: vec4<f32> = vec4(0f);
    var hn: vec4<f32> = vec4(0f);
    var v: vec4<f32> = vec4(0f);
    var m: vec4<f32> = vec4(0f);
    var weight: f32 = 0f;
    var k: u32 = 0u;

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
    let texel_2 = vec2<i32>(i32(gid.x), i32(gid.y));
    let _e24 = view.width;
    let _e28 = gbuffer_at(((gid.y * _e24) + gid.x));
    let _e31 = textureLoad(signal_tex, texel_2, 0i);
    let c_3 = _e31.xyz;
    if (_e28.position.w <= 0f) {
        textureStore(out_tex, texel_2, vec4<f32>(c_3, 0f));
        textureStore(next_value, texel_2, vec4<f32>(c_3, 0f));
        textureStore(next_noise, texel_2, vec4(0f));
        textureStore(next_surface, texel_2, vec4(0f));
        return;
    }
    let p_1 = _e28.position.xyz;
    let n_6 = _e28.normal.xyz;
    let _e61 = textureLoad(motion_tex, texel_2, 0i);
    let motion = _e61.xy;
    let _e71 = view.width;
    let _e75 = view.height;
    let _e77 = reproject_motion(f32(gid.x), f32(gid.y), motion.x, motion.y, f32(_e71), f32(_e75));
    let _e80 = params.has_history;
    if (_e80 == 1u) {
        let _e85 = view.eye;
        let d_2 = length((p_1 - _e85));
        loop {
            let _e98 = k;
            if (_e98 < 4u) {
            } else {
                break;
            }
            {
                let _e101 = k;
                let _e104 = view.width;
                let _e108 = view.height;
                let _e110 = history_tap(_e77, _e101, f32(_e104), f32(_e108));
                if (_e110.w > 0f) {
                    let t_1 = vec2<i32>(i32(_e110.x), i32(_e110.y));
                    let tv = textureLoad(hist_value, t_1, 0i);
                    let ts = textureLoad(hist_surface, t_1, 0i);
                    let tn = textureLoad(hist_noise, t_1, 0i);
                    let _e132 = history_tap_weight_motion(_e110.z, n_6, ts.xyz, d_2, tn.z, tv.w);
                    let _e133 = v;
                    v = (_e133 + (tv * _e132));
                    let _e136 = m;
                    m = (_e136 + (tn * _e132));
                    let _e139 = weight;
                    weight = (_e139 + _e132);
                }
            }
            continuing {
                let _e142 = k;
                k = (_e142 + 1u);
            }
        }
        let _e144 = v;
        let _e145 = weight;
        let _e146 = history_mean(_e144, _e145);
        hv = _e146;
        let _e147 = m;
        let _e148 = weight;
        let _e149 = history_mean(_e147, _e148);
        hn = _e149;
    }
    let _e150 = hv;
    let _e152 = hn.y;
    let _e154 = hn.x;
    let _e157 = params.max_history;
    let _e158 = temporal_color(c_3, _e150, _e152, _e154, _e157);
    textureStore(out_tex, texel_2, _e158);
    textureStore(next_value, texel_2, _e158);
    let _e163 = hn.x;
    let _e165 = hn.y;
    let _e167 = hv.w;
    let _e171 = view.eye;
    let _e174 = temporal_moments(c_3, _e163, _e165, _e167, _e158.w, length((p_1 - _e171)));
    textureStore(next_noise, texel_2, _e174);
    textureStore(next_surface, texel_2, vec4<f32>(n_6, dot(n_6, p_1)));
    return;
}
