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
var depth_tex: texture_2d<f32>;
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
var out_tex: texture_storage_2d<rgba16float,write>;
@group(0) @binding(9) 
var next_value: texture_storage_2d<rgba32float,write>;
@group(0) @binding(10) 
var next_noise: texture_storage_2d<rgba32float,write>;
@group(0) @binding(11) 
var next_surface: texture_storage_2d<rgba32float,write>;

fn to_f32_(u: u32) -> f32 {
    return f32(u);
}

fn finite3_(v_1: vec3<f32>) -> bool {
    var local_1: bool;
    var local_2: bool;

    if (abs(v_1.x) <= F32_MAX) {
        local_1 = (abs(v_1.y) <= F32_MAX);
    } else {
        local_1 = false;
    }
    let _e12 = local_1;
    if _e12 {
        local_2 = (abs(v_1.z) <= F32_MAX);
    } else {
        local_2 = false;
    }
    let _e20 = local_2;
    return _e20;
}

fn luminance(c: vec3<f32>) -> f32 {
    return dot(c, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn reproject(c0_: vec4<f32>, c1_: vec4<f32>, c2_: vec4<f32>, c3_: vec4<f32>, p: vec3<f32>, width: f32, height: f32) -> vec3<f32> {
    let clip = ((((c0_ * p.x) + (c1_ * p.y)) + (c2_ * p.z)) + c3_);
    if (clip.w <= 0f) {
        return vec3<f32>(-1f, -1f, 0f);
    }
    let x = (((((clip.x / clip.w) + 1f) * 0.5f) * width) - 0.5f);
    let y = ((((1f - (clip.y / clip.w)) * 0.5f) * height) - 0.5f);
    return vec3<f32>(x, y, clip.w);
}

fn bilinear_weight(fx: f32, fy: f32, dx: u32, dy: u32) -> f32 {
    let wx = select((1f - fx), fx, (dx == 1u));
    let wy = select((1f - fy), fy, (dy == 1u));
    return (wx * wy);
}

fn history_tap(q: vec3<f32>, k_1: u32, width_1: f32, height_1: f32) -> vec4<f32> {
    var local_3: bool;
    var local_4: bool;
    var local_5: bool;
    var local_6: bool;

    let x0_ = floor(q.x);
    let y0_ = floor(q.y);
    let dx_1 = (k_1 % 2u);
    let dy_1 = (k_1 / 2u);
    let _e12 = to_f32_(dx_1);
    let tx = (x0_ + _e12);
    let _e14 = to_f32_(dy_1);
    let ty = (y0_ + _e14);
    if (q.z > 0f) {
        local_3 = (tx >= 0f);
    } else {
        local_3 = false;
    }
    let _e24 = local_3;
    if _e24 {
        local_4 = (ty >= 0f);
    } else {
        local_4 = false;
    }
    let _e30 = local_4;
    if _e30 {
        local_5 = (tx < width_1);
    } else {
        local_5 = false;
    }
    let _e35 = local_5;
    if _e35 {
        local_6 = (ty < height_1);
    } else {
        local_6 = false;
    }
    let inside = local_6;
    let _e45 = bilinear_weight((q.x - x0_), (q.y - y0_), dx_1, dy_1);
    return vec4<f32>(tx, ty, _e45, select(0f, 1f, inside));
}

fn history_mean(sum: vec4<f32>, weight_1: f32) -> vec4<f32> {
    if (weight_1 < TEMPORAL_MIN_WEIGHT) {
        return vec4<f32>(0f, 0f, 0f, 0f);
    }
    return (sum / vec4(weight_1));
}

fn history_matches(n: vec3<f32>, nh: vec3<f32>, p_1: vec3<f32>, oh: f32, d: f32) -> bool {
    var local_7: bool;

    if (abs((dot(nh, p_1) - oh)) <= (TEMPORAL_DEPTH_TOLERANCE * d)) {
        local_7 = (dot(n, nh) >= TEMPORAL_NORMAL_COS);
    } else {
        local_7 = false;
    }
    let _e17 = local_7;
    return _e17;
}

fn temporal_change(l: f32, m1_: f32, noise: f32, n_1: f32) -> f32 {
    if (n_1 < TEMPORAL_MIN_MOMENTS) {
        return 0f;
    }
    let sigma = sqrt((max(noise, 0f) * (1f + (1f / n_1))));
    let t = (abs((l - m1_)) / ((sigma + (0.001f * max(abs(l), abs(m1_)))) + 0.00000000000000000001f));
    return clamp(((t - TEMPORAL_CHANGE_LOW) / 4f), 0f, 1f);
}

fn next_history_length(n_2: f32, lambda: f32, max_history: f32) -> f32 {
    return min((((1f - lambda) * n_2) + 1f), max(max_history, 1f));
}

fn temporal_alpha(n_3: f32) -> f32 {
    return (1f / max(n_3, 1f));
}

fn history_tap_weight(w: f32, n_4: vec3<f32>, nh_1: vec3<f32>, p_2: vec3<f32>, oh_1: f32, d_1: f32, len: f32) -> f32 {
    var local_8: bool;

    if (len > 0f) {
        let _e11 = history_matches(n_4, nh_1, p_2, oh_1, d_1);
        local_8 = _e11;
    } else {
        local_8 = false;
    }
    let _e13 = local_8;
    return select(0f, w, _e13);
}

fn persistent_change(l_1: f32, last: f32, m1_1: f32, noise_1: f32, n_5: f32) -> f32 {
    if (((l_1 - m1_1) * (last - m1_1)) <= 0f) {
        return 0f;
    }
    let _e11 = temporal_change(l_1, m1_1, noise_1, n_5);
    let _e12 = temporal_change(last, m1_1, noise_1, n_5);
    return min(_e11, _e12);
}

fn temporal_color(c_1: vec3<f32>, h: vec4<f32>, noise_2: f32, last_1: f32, max_history_1: f32) -> vec4<f32> {
    let hc = vec3<f32>(h.x, h.y, h.z);
    let _e9 = luminance(c_1);
    let _e10 = luminance(hc);
    let _e12 = persistent_change(_e9, last_1, _e10, noise_2, h.w);
    let _e14 = next_history_length(h.w, _e12, max_history_1);
    let _e15 = temporal_alpha(_e14);
    let v_2 = ((hc * (1f - _e15)) + (c_1 * _e15));
    return vec4<f32>(v_2.x, v_2.y, v_2.z, _e14);
}

fn temporal_moments(c_2: vec3<f32>, last_2: f32, noise_3: f32, prev_len: f32, len_1: f32, depth: f32) -> vec4<f32> {
    var local_9: bool;

    let _e6 = luminance(c_2);
    if (prev_len <= 0f) {
        return vec4<f32>(_e6, 0f, depth, 0f);
    }
    let d_2 = (_e6 - last_2);
    let d2_ = ((0.5f * d_2) * d_2);
    let cap = (16f * noise_3);
    if (prev_len >= TEMPORAL_MIN_MOMENTS) {
        local_9 = (noise_3 > 0f);
    } else {
        local_9 = false;
    }
    let _e26 = local_9;
    let sample = select(d2_, min(d2_, cap), _e26);
    let _e31 = temporal_alpha((len_1 - 1f));
    return vec4<f32>(_e6, (noise_3 + ((sample - noise_3) * _e31)), depth, 0f);
}

fn unproject_pixel(c0_1: vec4<f32>, c1_1: vec4<f32>, c2_1: vec4<f32>, c3_1: vec4<f32>, px: f32, py: f32, width_2: f32, height_2: f32, depth_1: f32) -> vec4<f32> {
    var local_10: bool;
    var local_11: bool;

    if (depth_1 > 0f) {
        local_10 = (depth_1 < 1f);
    } else {
        local_10 = false;
    }
    let _e16 = local_10;
    if !(_e16) {
        return vec4<f32>(0f, 0f, 0f, 0f);
    }
    let x_1 = ((((px + 0.5f) / width_2) * 2f) - 1f);
    let y_1 = (1f - (((py + 0.5f) / height_2) * 2f));
    let p_3 = ((((c0_1 * x_1) + (c1_1 * y_1)) + (c2_1 * depth_1)) + c3_1);
    let q_1 = vec3<f32>((p_3.x / p_3.w), (p_3.y / p_3.w), (p_3.z / p_3.w));
    if (abs(p_3.w) > 0f) {
        let _e59 = finite3_(q_1);
        local_11 = _e59;
    } else {
        local_11 = false;
    }
    let _e61 = local_11;
    if _e61 {
        return vec4<f32>(q_1.x, q_1.y, q_1.z, 1f);
    }
    return vec4<f32>(0f, 0f, 0f, 0f);
}

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let _e3 = textureLoad(depth_tex, texel, 0i);
    let d_3 = _e3.x;
    let _e7 = view.c0_;
    let _e10 = view.c1_;
    let _e13 = view.c2_;
    let _e16 = view.c3_;
    let _e23 = view.width;
    let _e27 = view.height;
    let _e29 = unproject_pixel(_e7, _e10, _e13, _e16, f32(texel.x), f32(texel.y), f32(_e23), f32(_e27), d_3);
    return _e29;
}

fn gbuffer_at(i: u32) -> GbTexel {
    var local_12: bool;

    let _e3 = view.width;
    let _e8 = view.width;
    let texel_1 = vec2<i32>(i32((i % _e3)), i32((i / _e8)));
    let _e12 = surface_at(texel_1);
    let _e15 = textureLoad(normal_tex, texel_1, 0i);
    let n_6 = _e15.xyz;
    let len2_ = dot(n_6, n_6);
    if (_e12.w > 0f) {
        local_12 = (len2_ > 0f);
    } else {
        local_12 = false;
    }
    let valid = local_12;
    let _e30 = view.eye;
    let v_3 = (_e12.xyz - _e30);
    let position = vec4<f32>(_e12.xyz, select(0f, 1f, valid));
    let normal = select(vec4<f32>(0f, 0f, 0f, 1000000000000000000000000000000f), vec4<f32>((n_6 / vec3(sqrt(len2_))), sqrt(dot(v_3, v_3))), valid);
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
    let p_4 = _e28.position.xyz;
    let n_7 = _e28.normal.xyz;
    let _e61 = params.c0_;
    let _e64 = params.c1_;
    let _e67 = params.c2_;
    let _e70 = params.c3_;
    let _e73 = view.width;
    let _e77 = view.height;
    let _e79 = reproject(_e61, _e64, _e67, _e70, p_4, f32(_e73), f32(_e77));
    let _e82 = params.has_history;
    if (_e82 == 1u) {
        let _e87 = params.prev_eye;
        let d_4 = length((p_4 - _e87));
        loop {
            let _e100 = k;
            if (_e100 < 4u) {
            } else {
                break;
            }
            {
                let _e103 = k;
                let _e106 = view.width;
                let _e110 = view.height;
                let _e112 = history_tap(_e79, _e103, f32(_e106), f32(_e110));
                if (_e112.w > 0f) {
                    let t_1 = vec2<i32>(i32(_e112.x), i32(_e112.y));
                    let tv = textureLoad(hist_value, t_1, 0i);
                    let ts = textureLoad(hist_surface, t_1, 0i);
                    let tn = textureLoad(hist_noise, t_1, 0i);
                    let _e134 = history_tap_weight(_e112.z, n_7, ts.xyz, p_4, ts.w, d_4, tv.w);
                    let _e135 = v;
                    v = (_e135 + (tv * _e134));
                    let _e138 = m;
                    m = (_e138 + (tn * _e134));
                    let _e141 = weight;
                    weight = (_e141 + _e134);
                }
            }
            continuing {
                let _e144 = k;
                k = (_e144 + 1u);
            }
        }
        let _e146 = v;
        let _e147 = weight;
        let _e148 = history_mean(_e146, _e147);
        hv = _e148;
        let _e149 = m;
        let _e150 = weight;
        let _e151 = history_mean(_e149, _e150);
        hn = _e151;
    }
    let _e152 = hv;
    let _e154 = hn.y;
    let _e156 = hn.x;
    let _e159 = params.max_history;
    let _e160 = temporal_color(c_3, _e152, _e154, _e156, _e159);
    textureStore(out_tex, texel_2, _e160);
    textureStore(next_value, texel_2, _e160);
    let _e165 = hn.x;
    let _e167 = hn.y;
    let _e169 = hv.w;
    let _e173 = view.eye;
    let _e176 = temporal_moments(c_3, _e165, _e167, _e169, _e160.w, length((p_4 - _e173)));
    textureStore(next_noise, texel_2, _e176);
    textureStore(next_surface, texel_2, vec4<f32>(n_7, dot(n_7, p_4)));
    return;
}
