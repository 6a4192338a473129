#version 430 core
#extension GL_ARB_compute_shader : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

struct TemporalParams {
    vec4 c0_;
    vec4 c1_;
    vec4 c2_;
    vec4 c3_;
    vec3 prev_eye;
    float max_history;
    uint has_history;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};
struct ViewParams {
    vec4 c0_;
    vec4 c1_;
    vec4 c2_;
    vec4 c3_;
    vec3 eye;
    uint width;
    uint height;
    float shadow_offset;
    uint seed;
    uint frame;
    vec3 f0_d;
    float f90_d;
};
struct GbTexel {
    vec4 position;
    vec4 normal;
};
const uint LIGHT_POINT = 0u;
const uint LIGHT_SPOT = 1u;
const uint LIGHT_IES = 2u;
const uint LIGHT_TRIANGLE = 3u;
const uint LIGHT_VPL = 4u;
const uint NO_LIGHT = 4294967295u;
const uint GRID_HEADER = 32u;
const uint GRID_LEVELS_MAX = 8u;
const uint GRIDS_MAX = 3u;
const uint GRID_SORT_MOVES = 1024u;
const uint GRID_SORT_MAX = 1024u;
const uint COUNT_TILES = 0u;
const uint COUNT_GROUP_TESTS = 1u;
const uint COUNT_CLUSTER_TESTS = 2u;
const uint COUNT_SPHERE_TESTS = 3u;
const uint COUNT_TESTED = 4u;
const uint COUNT_KEPT = 5u;
const uint COUNT_PIXELS = 6u;
const uint COUNT_FIELDS = 7u;
const uint DIRECT_COUNT_PIXELS = 0u;
const uint DIRECT_COUNT_CANDIDATES = 1u;
const uint DIRECT_COUNT_EVALUATIONS = 2u;
const uint DIRECT_COUNT_RAYS = 3u;
const uint DIRECT_COUNT_NODES = 4u;
const uint DIRECT_COUNT_FIELDS = 5u;
const uint MAP_CAMERA = 0u;
const uint MAP_PERSPECTIVE = 1u;
const uint MAP_ORTHOGRAPHIC = 2u;
const float XI_STEP = 5.9604645e-8;
const uint XI_ROTATED = 2147483648u;
const uint XI_BITS_SHIFT = 26u;
const uint XI_INDEX_MASK = 67108863u;
const uint PICK_STREAM = 2654435769u;
const float TWO_PI = 6.2831855;
const float UNRANGED = 1e38;
const float CULL_RADIUS_SCALE = 1.000001;
const float SPHERE_PAD = 4.7683716e-7;
const float SPHERE_HUGE = 3.4028235e38;
const float SPHERE_PAD_ABS = 1e-18;
const uint CLUSTER = 64u;
const uint GROUP_SIDE = 8u;
const float INV_PI = 0.31830987;
const float MIN_D2_ = 1e-12;
const float MAX_INTENSITY = 7.2057594e16;
const uint BSH_NONE = 4294967295u;
const uint BSH_TAIL = 2147483648u;
const uint BSH_TAIL_BINS = 1024u;
const uint BSH_TAIL_MAX = 64u;
const uint RESERVOIR_FULL = 4294967295u;
const float REUSE_TRUST_SCALE = 64.0;
const float GGX_ALPHA_MIN = 0.001;
const float RANGE_SCALE_MAX = 64.0;
const uint LIGHT_BVH_LEAF = 4294967295u;
const float ONE_MINUS_EPSILON = 0.99999994;
const float F32_MAX = 3.4028235e38;
const float DEPTH_NONE = 1e30;
const float DEPTH_SIGMA = 0.05;
const float COVER_WEIGHT = 0.1;
const uint ROULETTE_DEPTH = 2u;
const float TEMPORAL_MAX_HISTORY = 32.0;
const float TEMPORAL_DEPTH_TOLERANCE = 0.01;
const float TEMPORAL_MOTION_DEPTH_TOLERANCE = 0.05;
const float TEMPORAL_NORMAL_COS = 0.9;
const float TEMPORAL_MIN_MOMENTS = 8.0;
const float TEMPORAL_CHANGED_HISTORY = 1.0;
const float TEMPORAL_CHANGE_LOW = 4.0;
const float TEMPORAL_CHANGE_HIGH = 8.0;
const float TEMPORAL_MIN_WEIGHT = 0.01;

layout(std140) uniform ViewParams_block_0Compute { ViewParams _group_0_binding_0_cs; };

uniform sampler2D _group_0_binding_1_cs;

uniform sampler2D _group_0_binding_2_cs;

layout(std140) uniform TemporalParams_block_1Compute { TemporalParams _group_0_binding_3_cs; };

uniform sampler2D _group_0_binding_4_cs;

uniform sampler2D _group_0_binding_5_cs;

uniform sampler2D _group_0_binding_6_cs;

uniform sampler2D _group_0_binding_7_cs;

layout(rgba32f) writeonly uniform image2D _group_0_binding_8_cs;

layout(rgba32f) writeonly uniform image2D _group_0_binding_9_cs;

layout(rgba32f) writeonly uniform image2D _group_0_binding_10_cs;

layout(rgba32f) writeonly uniform image2D _group_0_binding_11_cs;


float to_f32_(uint u) {
    return float(u);
}

float luminance(vec3 c) {
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

vec3 reproject(vec4 c0_, vec4 c1_, vec4 c2_, vec4 c3_, vec3 p, float width, float height) {
    vec4 clip = ((((c0_ * p.x) + (c1_ * p.y)) + (c2_ * p.z)) + c3_);
    if ((clip.w <= 0.0)) {
        return vec3(-1.0, -1.0, 0.0);
    }
    float x = (((((clip.x / clip.w) + 1.0) * 0.5) * width) - 0.5);
    float y = ((((1.0 - (clip.y / clip.w)) * 0.5) * height) - 0.5);
    return vec3(x, y, clip.w);
}

float bilinear_weight(float fx, float fy, uint dx, uint dy) {
    float wx = ((dx == 1u) ? fx : (1.0 - fx));
    float wy = ((dy == 1u) ? fy : (1.0 - fy));
    return (wx * wy);
}

vec4 history_tap(vec3 q, uint k_1, float width_1, float height_1) {
    bool local_1 = false;
    bool local_2 = false;
    bool local_3 = false;
    bool local_4 = false;
    float x0_ = floor(q.x);
    float y0_ = floor(q.y);
    uint dx_1 = (k_1 % 2u);
    uint dy_1 = (k_1 / 2u);
    float _e12 = to_f32_(dx_1);
    float tx = (x0_ + _e12);
    float _e14 = to_f32_(dy_1);
    float ty = (y0_ + _e14);
    if ((q.z > 0.0)) {
        local_1 = (tx >= 0.0);
    } else {
        local_1 = false;
    }
    bool _e24 = local_1;
    if (_e24) {
        local_2 = (ty >= 0.0);
    } else {
        local_2 = false;
    }
    bool _e30 = local_2;
    if (_e30) {
        local_3 = (tx < width_1);
    } else {
        local_3 = false;
    }
    bool _e35 = local_3;
    if (_e35) {
        local_4 = (ty < height_1);
    } else {
        local_4 = false;
    }
    bool inside = local_4;
    float _e45 = bilinear_weight((q.x - x0_), (q.y - y0_), dx_1, dy_1);
    return vec4(tx, ty, _e45, (inside ? 1.0 : 0.0));
}

vec4 history_mean(vec4 sum, float weight_1) {
    if ((weight_1 < TEMPORAL_MIN_WEIGHT)) {
        return vec4(0.0, 0.0, 0.0, 0.0);
    }
    return (sum / vec4(weight_1));
}

bool history_matches(vec3 n, vec3 nh, vec3 p_1, float oh, float d) {
    bool local_5 = false;
    if ((abs((dot(nh, p_1) - oh)) <= (TEMPORAL_DEPTH_TOLERANCE * d))) {
        local_5 = (dot(n, nh) >= TEMPORAL_NORMAL_COS);
    } else {
        local_5 = false;
    }
    bool _e17 = local_5;
    return _e17;
}

float temporal_change(float l, float m1_, float noise, float n_1) {
    if ((n_1 < TEMPORAL_MIN_MOMENTS)) {
        return 0.0;
    }
    float sigma = sqrt((max(noise, 0.0) * (1.0 + (1.0 / n_1))));
    float t = (abs((l - m1_)) / ((sigma + (0.001 * max(abs(l), abs(m1_)))) + 1e-20));
    return clamp(((t - TEMPORAL_CHANGE_LOW) / 4.0), 0.0, 1.0);
}

float next_history_length(float n_2, float lambda, float max_history) {
    return min((((1.0 - lambda) * n_2) + 1.0), max(max_history, 1.0));
}

float temporal_alpha(float n_3) {
    return (1.0 / max(n_3, 1.0));
}

float history_tap_weight(float w, vec3 n_4, vec3 nh_1, vec3 p_2, float oh_1, float d_1, float len) {
    bool local_6 = false;
    if ((len > 0.0)) {
        bool _e11 = history_matches(n_4, nh_1, p_2, oh_1, d_1);
        local_6 = _e11;
    } else {
        local_6 = false;
    }
    bool _e13 = local_6;
    return (_e13 ? w : 0.0);
}

float persistent_change(float l_1, float last, float m1_1, float noise_1, float n_5) {
    if ((((l_1 - m1_1) * (last - m1_1)) <= 0.0)) {
        return 0.0;
    }
    float _e11 = temporal_change(l_1, m1_1, noise_1, n_5);
    float _e12 = temporal_change(last, m1_1, noise_1, n_5);
    return min(_e11, _e12);
}

vec4 temporal_color(vec3 c_1, vec4 h, float noise_2, float last_1, float max_history_1) {
    vec3 hc = vec3(h.x, h.y, h.z);
    float _e9 = luminance(c_1);
    float _e10 = luminance(hc);
    float _e12 = persistent_change(_e9, last_1, _e10, noise_2, h.w);
    float _e14 = next_history_length(h.w, _e12, max_history_1);
    float _e15 = temporal_alpha(_e14);
    vec3 v_1 = ((hc * (1.0 - _e15)) + (c_1 * _e15));
    return vec4(v_1.x, v_1.y, v_1.z, _e14);
}

vec4 temporal_moments(vec3 c_2, float last_2, float noise_3, float prev_len, float len_1, float depth) {
    bool local_7 = false;
    float _e6 = luminance(c_2);
    if ((prev_len <= 0.0)) {
        return vec4(_e6, 0.0, depth, 0.0);
    }
    float d_2 = (_e6 - last_2);
    float d2_ = ((0.5 * d_2) * d_2);
    float cap = (16.0 * noise_3);
    if ((prev_len >= TEMPORAL_MIN_MOMENTS)) {
        local_7 = (noise_3 > 0.0);
    } else {
        local_7 = false;
    }
    bool _e26 = local_7;
    float sample_ = (_e26 ? min(d2_, cap) : d2_);
    float _e31 = temporal_alpha((len_1 - 1.0));
    return vec4(_e6, (noise_3 + ((sample_ - noise_3) * _e31)), depth, 0.0);
}

vec4 surface_at(ivec2 texel) {
    vec4 p_3 = texelFetch(_group_0_binding_1_cs, texel, 0);
    return ((p_3.w > 0.0) ? vec4(p_3.xyz, 1.0) : vec4(0.0));
}

GbTexel gbuffer_at(uint i) {
    bool local_8 = false;
    uint _e3 = _group_0_binding_0_cs.width;
    uint _e8 = _group_0_binding_0_cs.width;
    ivec2 texel_1 = ivec2(int((i % _e3)), int((i / _e8)));
    vec4 _e12 = surface_at(texel_1);
    vec4 _e15 = texelFetch(_group_0_binding_2_cs, texel_1, 0);
    vec3 n_6 = _e15.xyz;
    float len2_ = dot(n_6, n_6);
    if ((_e12.w > 0.0)) {
        local_8 = (len2_ > 0.0);
    } else {
        local_8 = false;
    }
    bool valid = local_8;
    vec3 _e30 = _group_0_binding_0_cs.eye;
    vec3 v_2 = (_e12.xyz - _e30);
    vec4 position = vec4(_e12.xyz, (valid ? 1.0 : 0.0));
    vec4 normal = (valid ? vec4((n_6 / vec3(sqrt(len2_))), sqrt(dot(v_2, v_2))) : vec4(0.0, 0.0, 0.0, 1e30));
    return GbTexel(position, normal);
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    bool local = false;
    vec4 hv = vec4(0.0);
    vec4 hn = vec4(0.0);
    vec4 v = vec4(0.0);
    vec4 m = vec4(0.0);
    float weight = 0.0;
    uint k = 0u;
    uint _e4 = _group_0_binding_0_cs.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = _group_0_binding_0_cs.height;
        local = (gid.y >= _e12);
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    ivec2 texel_2 = ivec2(int(gid.x), int(gid.y));
    uint _e24 = _group_0_binding_0_cs.width;
    GbTexel _e28 = gbuffer_at(((gid.y * _e24) + gid.x));
    vec4 _e31 = texelFetch(_group_0_binding_4_cs, texel_2, 0);
    vec3 c_3 = _e31.xyz;
    if ((_e28.position.w <= 0.0)) {
        imageStore(_group_0_binding_8_cs, texel_2, vec4(c_3, 0.0));
        imageStore(_group_0_binding_9_cs, texel_2, vec4(c_3, 0.0));
        imageStore(_group_0_binding_10_cs, texel_2, vec4(0.0));
        imageStore(_group_0_binding_11_cs, texel_2, vec4(0.0));
        return;
    }
    vec3 p_4 = _e28.position.xyz;
    vec3 n_7 = _e28.normal.xyz;
    vec4 _e61 = _group_0_binding_3_cs.c0_;
    vec4 _e64 = _group_0_binding_3_cs.c1_;
    vec4 _e67 = _group_0_binding_3_cs.c2_;
    vec4 _e70 = _group_0_binding_3_cs.c3_;
    uint _e73 = _group_0_binding_0_cs.width;
    uint _e77 = _group_0_binding_0_cs.height;
    vec3 _e79 = reproject(_e61, _e64, _e67, _e70, p_4, float(_e73), float(_e77));
    uint _e82 = _group_0_binding_3_cs.has_history;
    if ((_e82 == 1u)) {
        vec3 _e87 = _group_0_binding_3_cs.prev_eye;
        float d_3 = length((p_4 - _e87));
        bool loop_init = true;
        while(true) {
            if (!loop_init) {
                uint _e144 = k;
                k = (_e144 + 1u);
            }
            loop_init = false;
            uint _e100 = k;
            if ((_e100 < 4u)) {
            } else {
                break;
            }
            {
                uint _e103 = k;
                uint _e106 = _group_0_binding_0_cs.width;
                uint _e110 = _group_0_binding_0_cs.height;
                vec4 _e112 = history_tap(_e79, _e103, float(_e106), float(_e110));
                if ((_e112.w > 0.0)) {
                    ivec2 t_1 = ivec2(int(_e112.x), int(_e112.y));
                    vec4 tv = texelFetch(_group_0_binding_5_cs, t_1, 0);
                    vec4 ts = texelFetch(_group_0_binding_7_cs, t_1, 0);
                    vec4 tn = texelFetch(_group_0_binding_6_cs, t_1, 0);
                    float _e134 = history_tap_weight(_e112.z, n_7, ts.xyz, p_4, ts.w, d_3, tv.w);
                    vec4 _e135 = v;
                    v = (_e135 + (tv * _e134));
                    vec4 _e138 = m;
                    m = (_e138 + (tn * _e134));
                    float _e141 = weight;
                    weight = (_e141 + _e134);
                }
            }
        }
        vec4 _e146 = v;
        float _e147 = weight;
        vec4 _e148 = history_mean(_e146, _e147);
        hv = _e148;
        vec4 _e149 = m;
        float _e150 = weight;
        vec4 _e151 = history_mean(_e149, _e150);
        hn = _e151;
    }
    vec4 _e152 = hv;
    float _e154 = hn.y;
    float _e156 = hn.x;
    float _e159 = _group_0_binding_3_cs.max_history;
    vec4 _e160 = temporal_color(c_3, _e152, _e154, _e156, _e159);
    imageStore(_group_0_binding_8_cs, texel_2, _e160);
    imageStore(_group_0_binding_9_cs, texel_2, _e160);
    float _e165 = hn.x;
    float _e167 = hn.y;
    float _e169 = hv.w;
    vec3 _e173 = _group_0_binding_0_cs.eye;
    vec4 _e176 = temporal_moments(c_3, _e165, _e167, _e169, _e160.w, length((p_4 - _e173)));
    imageStore(_group_0_binding_10_cs, texel_2, _e176);
    imageStore(_group_0_binding_11_cs, texel_2, vec4(n_7, dot(n_7, p_4)));
    return;
}

