#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

struct VplParams {
    uint width;
    uint height;
    uint lights_per_subset;
    float min_d2_;
    float near_r2_;
    uint near_blocks;
    uint pad0_;
    uint pad1_;
};
struct Window {
    vec3 sum;
    float weight;
    uint covered;
};
const uint LIGHT_POINT = 0u;
const uint LIGHT_SPOT = 1u;
const uint LIGHT_IES = 2u;
const uint LIGHT_TRIANGLE = 3u;
const uint LIGHT_VPL = 4u;
const uint NO_LIGHT = 4294967295u;
const uint MAP_CAMERA = 0u;
const uint MAP_PERSPECTIVE = 1u;
const uint MAP_ORTHOGRAPHIC = 2u;
const float XI_STEP = 5.9604645e-8;
const uint PICK_STREAM = 2654435769u;
const float TWO_PI = 6.2831855;
const float CULL_RADIUS_SCALE = 1.000001;
const float SPHERE_PAD = 4.7683716e-7;
const float SPHERE_HUGE = 3.4028235e38;
const float SPHERE_PAD_ABS = 1e-18;
const float INV_PI = 0.31830987;
const float MIN_D2_ = 1e-12;
const uint BSH_NONE = 4294967295u;
const uint RESERVOIR_FULL = 4294967295u;
const float GGX_ALPHA_MIN = 0.001;
const float RANGE_SCALE_MAX = 64.0;
const uint LIGHT_BVH_LEAF = 4294967295u;
const float ONE_MINUS_EPSILON = 0.99999994;
const float F32_MAX = 3.4028235e38;
const float DEPTH_NONE = 1e30;
const float DEPTH_SIGMA = 0.05;
const float COVER_WEIGHT = 0.1;
const uint NEAR_BLOCK = 64u;
const uint ROULETTE_DEPTH = 2u;
const uint PERIOD = 8u;

layout(std140) uniform VplParams_block_0Compute { VplParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_5_block_1Compute { vec4 _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_5_block_2Compute { vec4 _group_0_binding_2_cs[]; };

layout(std430) readonly buffer type_5_block_3Compute { vec4 _group_0_binding_3_cs[]; };

layout(std430) buffer type_5_block_4Compute { vec4 _group_0_binding_4_cs[]; };


float inv_sigma_z(float z) {
    return (1.0 / (DEPTH_SIGMA * z));
}

uint window_start(uint x, uint size) {
    uint half_ = (size / 2u);
    return (max(x, half_) - half_);
}

uint window_end(uint x_1, uint size_1, uint extent) {
    return min(((x_1 + size_1) - (size_1 / 2u)), extent);
}

uint wide_window(uint period) {
    return (2u * period);
}

bool misses_subset(uint covered, uint period_1) {
    return (covered < (period_1 * period_1));
}

vec3 filtered_irradiance(vec3 e, vec3 sum, float weight) {
    if ((weight > 0.0)) {
        return (sum / vec3(weight));
    }
    return e;
}

float bilateral_weight(vec3 n, vec3 nj, float z_1, float zj, float inv_sz) {
    float dn = max(dot(n, nj), 0.0);
    float dn2_ = (dn * dn);
    float dn4_ = (dn2_ * dn2_);
    float dn8_ = (dn4_ * dn4_);
    float d = ((zj - z_1) * inv_sz);
    float t = max((1.0 - (d * d)), 0.0);
    return (((dn8_ * dn8_) * t) * t);
}

float depth_of(uint i) {
    float _e5 = _group_0_binding_2_cs[i].w;
    float _e9 = _group_0_binding_1_cs[i].w;
    return ((_e9 > 0.0) ? _e5 : DEPTH_NONE);
}

Window window_sum(uint x_2, uint y, uint size_2, vec3 n_1, float z_2, float inv) {
    Window win = Window(vec3(0.0), 0.0, 0u);
    uint yy = 0u;
    uint xx = 0u;
    uint w = _group_0_binding_0_cs.width;
    uint h = _group_0_binding_0_cs.height;
    uint _e12 = window_start(x_2, size_2);
    uint _e13 = window_end(x_2, size_2, w);
    uint _e14 = window_start(y, size_2);
    uint _e15 = window_end(y, size_2, h);
    win.sum = vec3(0.0);
    win.weight = 0.0;
    win.covered = 0u;
    yy = _e14;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e63 = yy;
            yy = (_e63 + 1u);
        }
        loop_init = false;
        uint _e25 = yy;
        if ((_e25 < _e15)) {
        } else {
            break;
        }
        {
            xx = _e12;
            bool loop_init_1 = true;
            while(true) {
                if (!loop_init_1) {
                    uint _e60 = xx;
                    xx = (_e60 + 1u);
                }
                loop_init_1 = false;
                uint _e28 = xx;
                if ((_e28 < _e13)) {
                } else {
                    break;
                }
                {
                    uint _e30 = yy;
                    uint _e32 = xx;
                    uint j = ((_e30 * w) + _e32);
                    vec4 _e36 = _group_0_binding_2_cs[j];
                    float _e38 = depth_of(j);
                    float _e39 = bilateral_weight(n_1, _e36.xyz, z_2, _e38, inv);
                    vec3 _e41 = win.sum;
                    vec4 _e44 = _group_0_binding_3_cs[j];
                    win.sum = (_e41 + (_e44.xyz * _e39));
                    float _e49 = win.weight;
                    win.weight = (_e49 + _e39);
                    uint _e52 = win.covered;
                    win.covered = (_e52 + ((_e39 > COVER_WEIGHT) ? 1u : 0u));
                }
            }
        }
    }
    Window _e65 = win;
    return _e65;
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    bool local = false;
    Window s = Window(vec3(0.0), 0.0, 0u);
    uint w_1 = _group_0_binding_0_cs.width;
    uint h_1 = _group_0_binding_0_cs.height;
    if (!((gid.x >= w_1))) {
        local = (gid.y >= h_1);
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    uint i_1 = ((gid.y * w_1) + gid.x);
    vec4 e_1 = _group_0_binding_3_cs[i_1];
    float _e26 = _group_0_binding_1_cs[i_1].w;
    if ((_e26 <= 0.0)) {
        _group_0_binding_4_cs[i_1] = vec4(0.0, 0.0, 0.0, e_1.w);
        return;
    }
    vec4 _e38 = _group_0_binding_2_cs[i_1];
    vec3 n_2 = _e38.xyz;
    float _e40 = depth_of(i_1);
    float _e41 = inv_sigma_z(_e40);
    Window _e45 = window_sum(gid.x, gid.y, PERIOD, n_2, _e40, _e41);
    s = _e45;
    uint _e48 = s.covered;
    bool _e50 = misses_subset(_e48, PERIOD);
    if (_e50) {
        uint _e54 = wide_window(PERIOD);
        Window _e55 = window_sum(gid.x, gid.y, _e54, n_2, _e40, _e41);
        s = _e55;
    }
    vec3 _e60 = s.sum;
    float _e62 = s.weight;
    vec3 _e63 = filtered_irradiance(e_1.xyz, _e60, _e62);
    _group_0_binding_4_cs[i_1] = vec4(_e63, e_1.w);
    return;
}

