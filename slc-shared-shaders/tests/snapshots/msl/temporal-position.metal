// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct TemporalParams {
    metal::float4 c0_;
    metal::float4 c1_;
    metal::float4 c2_;
    metal::float4 c3_;
    metal::packed_float3 prev_eye;
    float max_history;
    uint has_history;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};
struct ViewParams {
    metal::float4 c0_;
    metal::float4 c1_;
    metal::float4 c2_;
    metal::float4 c3_;
    metal::packed_float3 eye;
    uint width;
    uint height;
    float shadow_offset;
    uint seed;
    uint frame;
    metal::packed_float3 f0_d;
    float f90_d;
};
struct GbTexel {
    metal::float4 position;
    metal::float4 normal;
};
constant uint LIGHT_POINT = 0u;
constant uint LIGHT_SPOT = 1u;
constant uint LIGHT_IES = 2u;
constant uint LIGHT_TRIANGLE = 3u;
constant uint LIGHT_VPL = 4u;
constant uint NO_LIGHT = 4294967295u;
constant uint GRID_HEADER = 32u;
constant uint GRID_LEVELS_MAX = 8u;
constant uint GRIDS_MAX = 3u;
constant uint GRID_SORT_MOVES = 1024u;
constant uint GRID_SORT_MAX = 1024u;
constant uint COUNT_TILES = 0u;
constant uint COUNT_GROUP_TESTS = 1u;
constant uint COUNT_CLUSTER_TESTS = 2u;
constant uint COUNT_SPHERE_TESTS = 3u;
constant uint COUNT_TESTED = 4u;
constant uint COUNT_KEPT = 5u;
constant uint COUNT_PIXELS = 6u;
constant uint COUNT_FIELDS = 7u;
constant uint DIRECT_COUNT_PIXELS = 0u;
constant uint DIRECT_COUNT_CANDIDATES = 1u;
constant uint DIRECT_COUNT_EVALUATIONS = 2u;
constant uint DIRECT_COUNT_RAYS = 3u;
constant uint DIRECT_COUNT_NODES = 4u;
constant uint DIRECT_COUNT_FIELDS = 5u;
constant uint MAP_CAMERA = 0u;
constant uint MAP_PERSPECTIVE = 1u;
constant uint MAP_ORTHOGRAPHIC = 2u;
constant float XI_STEP = 0.000000059604645;
constant uint XI_ROTATED = 2147483648u;
constant uint XI_BITS_SHIFT = 26u;
constant uint XI_INDEX_MASK = 67108863u;
constant uint PICK_STREAM = 2654435769u;
constant float TWO_PI = 6.2831855;
constant float UNRANGED = 100000000000000000000000000000000000000.0;
constant float CULL_RADIUS_SCALE = 1.000001;
constant float SPHERE_PAD = 0.00000047683716;
constant float SPHERE_HUGE = 340282350000000000000000000000000000000.0;
constant float SPHERE_PAD_ABS = 0.000000000000000001;
constant uint CLUSTER = 64u;
constant uint GROUP_SIDE = 8u;
constant float INV_PI = 0.31830987;
constant float MIN_D2_ = 0.000000000001;
constant float MAX_INTENSITY = 72057594000000000.0;
constant uint BSH_NONE = 4294967295u;
constant uint BSH_TAIL = 2147483648u;
constant uint BSH_TAIL_BINS = 1024u;
constant uint BSH_TAIL_MAX = 64u;
constant uint RESERVOIR_FULL = 4294967295u;
constant float REUSE_TRUST_SCALE = 64.0;
constant float GGX_ALPHA_MIN = 0.001;
constant float RANGE_SCALE_MAX = 64.0;
constant uint LIGHT_BVH_LEAF = 4294967295u;
constant float ONE_MINUS_EPSILON = 0.99999994;
constant float F32_MAX = 340282350000000000000000000000000000000.0;
constant float DEPTH_NONE = 1000000000000000000000000000000.0;
constant float DEPTH_SIGMA = 0.05;
constant float COVER_WEIGHT = 0.1;
constant uint ROULETTE_DEPTH = 2u;
constant float TEMPORAL_MAX_HISTORY = 32.0;
constant float TEMPORAL_DEPTH_TOLERANCE = 0.01;
constant float TEMPORAL_MOTION_DEPTH_TOLERANCE = 0.05;
constant float TEMPORAL_NORMAL_COS = 0.9;
constant float TEMPORAL_MIN_MOMENTS = 8.0;
constant float TEMPORAL_CHANGED_HISTORY = 1.0;
constant float TEMPORAL_CHANGE_LOW = 4.0;
constant float TEMPORAL_CHANGE_HIGH = 8.0;
constant float TEMPORAL_MIN_WEIGHT = 0.01;

float to_f32_(
    uint u
) {
    return static_cast<float>(u);
}

float luminance(
    metal::float3 c
) {
    return metal::dot(c, metal::float3(0.2126, 0.7152, 0.0722));
}

metal::float3 reproject(
    metal::float4 c0_,
    metal::float4 c1_,
    metal::float4 c2_,
    metal::float4 c3_,
    metal::float3 p,
    float width,
    float height
) {
    metal::float4 clip = (((c0_ * p.x) + (c1_ * p.y)) + (c2_ * p.z)) + c3_;
    if (clip.w <= 0.0) {
        return metal::float3(-1.0, -1.0, 0.0);
    }
    float x = ((((clip.x / clip.w) + 1.0) * 0.5) * width) - 0.5;
    float y = (((1.0 - (clip.y / clip.w)) * 0.5) * height) - 0.5;
    return metal::float3(x, y, clip.w);
}

float bilinear_weight(
    float fx,
    float fy,
    uint dx,
    uint dy
) {
    float wx = (dx == 1u) ? fx : (1.0 - fx);
    float wy = (dy == 1u) ? fy : (1.0 - fy);
    return wx * wy;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

metal::float4 history_tap(
    metal::float3 q,
    uint k_1,
    float width_1,
    float height_1
) {
    bool local_1 = {};
    bool local_2 = {};
    bool local_3 = {};
    bool local_4 = {};
    float x0_ = metal::floor(q.x);
    float y0_ = metal::floor(q.y);
    uint dx_1 = naga_mod(k_1, 2u);
    uint dy_1 = naga_div(k_1, 2u);
    float _e12 = to_f32_(dx_1);
    float tx = x0_ + _e12;
    float _e14 = to_f32_(dy_1);
    float ty = y0_ + _e14;
    if (q.z > 0.0) {
        local_1 = tx >= 0.0;
    } else {
        local_1 = false;
    }
    bool _e24 = local_1;
    if (_e24) {
        local_2 = ty >= 0.0;
    } else {
        local_2 = false;
    }
    bool _e30 = local_2;
    if (_e30) {
        local_3 = tx < width_1;
    } else {
        local_3 = false;
    }
    bool _e35 = local_3;
    if (_e35) {
        local_4 = ty < height_1;
    } else {
        local_4 = false;
    }
    bool inside = local_4;
    float _e45 = bilinear_weight(q.x - x0_, q.y - y0_, dx_1, dy_1);
    return metal::float4(tx, ty, _e45, inside ? 1.0 : 0.0);
}

metal::float4 history_mean(
    metal::float4 sum,
    float weight_1
) {
    if (weight_1 < TEMPORAL_MIN_WEIGHT) {
        return metal::float4(0.0, 0.0, 0.0, 0.0);
    }
    return sum / metal::float4(weight_1);
}

bool history_matches(
    metal::float3 n,
    metal::float3 nh,
    metal::float3 p_1,
    float oh,
    float d
) {
    bool local_5 = {};
    if (metal::abs(metal::dot(nh, p_1) - oh) <= (TEMPORAL_DEPTH_TOLERANCE * d)) {
        local_5 = metal::dot(n, nh) >= TEMPORAL_NORMAL_COS;
    } else {
        local_5 = false;
    }
    bool _e17 = local_5;
    return _e17;
}

float temporal_change(
    float l,
    float m1_,
    float noise,
    float n_1
) {
    if (n_1 < TEMPORAL_MIN_MOMENTS) {
        return 0.0;
    }
    float sigma = metal::sqrt(metal::max(noise, 0.0) * (1.0 + (1.0 / n_1)));
    float t = metal::abs(l - m1_) / ((sigma + (0.001 * metal::max(metal::abs(l), metal::abs(m1_)))) + 0.00000000000000000001);
    return metal::clamp((t - TEMPORAL_CHANGE_LOW) / 4.0, 0.0, 1.0);
}

float next_history_length(
    float n_2,
    float lambda,
    float max_history
) {
    return metal::min(((1.0 - lambda) * n_2) + 1.0, metal::max(max_history, 1.0));
}

float temporal_alpha(
    float n_3
) {
    return 1.0 / metal::max(n_3, 1.0);
}

float history_tap_weight(
    float w,
    metal::float3 n_4,
    metal::float3 nh_1,
    metal::float3 p_2,
    float oh_1,
    float d_1,
    float len
) {
    bool local_6 = {};
    if (len > 0.0) {
        bool _e11 = history_matches(n_4, nh_1, p_2, oh_1, d_1);
        local_6 = _e11;
    } else {
        local_6 = false;
    }
    bool _e13 = local_6;
    return _e13 ? w : 0.0;
}

float persistent_change(
    float l_1,
    float last,
    float m1_1,
    float noise_1,
    float n_5
) {
    if (((l_1 - m1_1) * (last - m1_1)) <= 0.0) {
        return 0.0;
    }
    float _e11 = temporal_change(l_1, m1_1, noise_1, n_5);
    float _e12 = temporal_change(last, m1_1, noise_1, n_5);
    return metal::min(_e11, _e12);
}

metal::float4 temporal_color(
    metal::float3 c_1,
    metal::float4 h,
    float noise_2,
    float last_1,
    float max_history_1
) {
    metal::float3 hc = metal::float3(h.x, h.y, h.z);
    float _e9 = luminance(c_1);
    float _e10 = luminance(hc);
    float _e12 = persistent_change(_e9, last_1, _e10, noise_2, h.w);
    float _e14 = next_history_length(h.w, _e12, max_history_1);
    float _e15 = temporal_alpha(_e14);
    metal::float3 v_1 = (hc * (1.0 - _e15)) + (c_1 * _e15);
    return metal::float4(v_1.x, v_1.y, v_1.z, _e14);
}

metal::float4 temporal_moments(
    metal::float3 c_2,
    float last_2,
    float noise_3,
    float prev_len,
    float len_1,
    float depth
) {
    bool local_7 = {};
    float _e6 = luminance(c_2);
    if (prev_len <= 0.0) {
        return metal::float4(_e6, 0.0, depth, 0.0);
    }
    float d_2 = _e6 - last_2;
    float d2_ = (0.5 * d_2) * d_2;
    float cap = 16.0 * noise_3;
    if (prev_len >= TEMPORAL_MIN_MOMENTS) {
        local_7 = noise_3 > 0.0;
    } else {
        local_7 = false;
    }
    bool _e26 = local_7;
    float sample = _e26 ? metal::min(d2_, cap) : d2_;
    float _e31 = temporal_alpha(len_1 - 1.0);
    return metal::float4(_e6, noise_3 + ((sample - noise_3) * _e31), depth, 0.0);
}

metal::float4 surface_at(
    metal::int2 texel,
    metal::texture2d<float, metal::access::sample> position_tex
) {
    metal::float4 p_3 = position_tex.read(metal::uint2(texel), 0);
    return (p_3.w > 0.0) ? metal::float4(p_3.xyz, 1.0) : metal::float4(0.0);
}

GbTexel gbuffer_at(
    uint i,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> position_tex,
    metal::texture2d<float, metal::access::sample> normal_tex
) {
    bool local_8 = {};
    uint _e3 = view.width;
    uint _e8 = view.width;
    metal::int2 texel_1 = metal::int2(static_cast<int>(naga_mod(i, _e3)), static_cast<int>(naga_div(i, _e8)));
    metal::float4 _e12 = surface_at(texel_1, position_tex);
    metal::float4 _e15 = normal_tex.read(metal::uint2(texel_1), 0);
    metal::float3 n_6 = _e15.xyz;
    float len2_ = metal::dot(n_6, n_6);
    if (_e12.w > 0.0) {
        local_8 = len2_ > 0.0;
    } else {
        local_8 = false;
    }
    bool valid = local_8;
    metal::float3 _e30 = view.eye;
    metal::float3 v_2 = _e12.xyz - _e30;
    metal::float4 position = metal::float4(_e12.xyz, valid ? 1.0 : 0.0);
    metal::float4 normal = valid ? metal::float4(n_6 / metal::float3(metal::sqrt(len2_)), metal::sqrt(metal::dot(v_2, v_2))) : metal::float4(0.0, 0.0, 0.0, 1000000000000000000000000000000.0);
    return GbTexel {position, normal};
}
int naga_f2i32(float value) {
    return static_cast<int>(metal::clamp(value, -2147483600.0, 2147483500.0));
}


struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, constant ViewParams& view [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, constant TemporalParams& params [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> signal_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> hist_value [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> hist_noise [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> hist_surface [[user(fake0)]]
, metal::texture2d<float, metal::access::write> out_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::write> next_value [[user(fake0)]]
, metal::texture2d<float, metal::access::write> next_noise [[user(fake0)]]
, metal::texture2d<float, metal::access::write> next_surface [[user(fake0)]]
) {
    bool local = {};
    metal::float4 hv = metal::float4(0.0);
    metal::float4 hn = metal::float4(0.0);
    metal::float4 v = metal::float4(0.0);
    metal::float4 m = metal::float4(0.0);
    float weight = 0.0;
    uint k = 0u;
    uint _e4 = view.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = view.height;
        local = gid.y >= _e12;
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    metal::int2 texel_2 = metal::int2(static_cast<int>(gid.x), static_cast<int>(gid.y));
    uint _e24 = view.width;
    GbTexel _e28 = gbuffer_at((gid.y * _e24) + gid.x, view, position_tex, normal_tex);
    metal::float4 _e31 = signal_tex.read(metal::uint2(texel_2), 0);
    metal::float3 c_3 = _e31.xyz;
    if (_e28.position.w <= 0.0) {
        out_tex.write(metal::float4(c_3, 0.0), metal::uint2(texel_2));
        next_value.write(metal::float4(c_3, 0.0), metal::uint2(texel_2));
        next_noise.write(metal::float4(0.0), metal::uint2(texel_2));
        next_surface.write(metal::float4(0.0), metal::uint2(texel_2));
        return;
    }
    metal::float3 p_4 = _e28.position.xyz;
    metal::float3 n_7 = _e28.normal.xyz;
    metal::float4 _e61 = params.c0_;
    metal::float4 _e64 = params.c1_;
    metal::float4 _e67 = params.c2_;
    metal::float4 _e70 = params.c3_;
    uint _e73 = view.width;
    uint _e77 = view.height;
    metal::float3 _e79 = reproject(_e61, _e64, _e67, _e70, p_4, static_cast<float>(_e73), static_cast<float>(_e77));
    uint _e82 = params.has_history;
    if (_e82 == 1u) {
        metal::float3 _e87 = params.prev_eye;
        float d_3 = metal::length(p_4 - _e87);
        uint2 loop_bound = uint2(4294967295u);
        bool loop_init = true;
        while(true) {
            if (metal::all(loop_bound == uint2(0u))) { break; }
            loop_bound -= uint2(loop_bound.y == 0u, 1u);
            if (!loop_init) {
                uint _e144 = k;
                k = _e144 + 1u;
            }
            loop_init = false;
            uint _e100 = k;
            if (_e100 < 4u) {
            } else {
                break;
            }
            {
                uint _e103 = k;
                uint _e106 = view.width;
                uint _e110 = view.height;
                metal::float4 _e112 = history_tap(_e79, _e103, static_cast<float>(_e106), static_cast<float>(_e110));
                if (_e112.w > 0.0) {
                    metal::int2 t_1 = metal::int2(naga_f2i32(_e112.x), naga_f2i32(_e112.y));
                    metal::float4 tv = hist_value.read(metal::uint2(t_1), 0);
                    metal::float4 ts = hist_surface.read(metal::uint2(t_1), 0);
                    metal::float4 tn = hist_noise.read(metal::uint2(t_1), 0);
                    float _e134 = history_tap_weight(_e112.z, n_7, ts.xyz, p_4, ts.w, d_3, tv.w);
                    metal::float4 _e135 = v;
                    v = _e135 + (tv * _e134);
                    metal::float4 _e138 = m;
                    m = _e138 + (tn * _e134);
                    float _e141 = weight;
                    weight = _e141 + _e134;
                }
            }
        }
        metal::float4 _e146 = v;
        float _e147 = weight;
        metal::float4 _e148 = history_mean(_e146, _e147);
        hv = _e148;
        metal::float4 _e149 = m;
        float _e150 = weight;
        metal::float4 _e151 = history_mean(_e149, _e150);
        hn = _e151;
    }
    metal::float4 _e152 = hv;
    float _e154 = hn.y;
    float _e156 = hn.x;
    float _e159 = params.max_history;
    metal::float4 _e160 = temporal_color(c_3, _e152, _e154, _e156, _e159);
    out_tex.write(_e160, metal::uint2(texel_2));
    next_value.write(_e160, metal::uint2(texel_2));
    float _e165 = hn.x;
    float _e167 = hn.y;
    float _e169 = hv.w;
    metal::float3 _e173 = view.eye;
    metal::float4 _e176 = temporal_moments(c_3, _e165, _e167, _e169, _e160.w, metal::length(p_4 - _e173));
    next_noise.write(_e176, metal::uint2(texel_2));
    next_surface.write(metal::float4(n_7, metal::dot(n_7, p_4)), metal::uint2(texel_2));
    return;
}
