#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct GpuLight {
    vec3 p0_;
    uint kind;
    vec3 p1_;
    float a;
    vec3 p2_;
    float b;
    vec3 intensity;
    uint ies_base;
};
struct PackParams {
    uint count;
    uint size;
    uint per_subset;
    uint mode;
    float exposure;
    float error_bound;
    float scale;
    uint slc;
    float fixed_r2_;
    uint pad0_;
    uint pad1_;
    uint pad2_;
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
const uint P = 8u;

layout(std140) uniform PackParams_block_0Compute { PackParams _group_0_binding_0_cs; };

uniform sampler2D _group_0_binding_1_cs;

uniform sampler2D _group_0_binding_2_cs;

uniform sampler2D _group_0_binding_3_cs;

layout(std430) buffer type_6_block_1Compute { GpuLight _group_0_binding_4_cs[]; };

layout(std430) buffer type_7_block_2Compute { uint _group_0_binding_5_cs[]; };

layout(std430) buffer type_3_block_3Compute { float _group_0_binding_6_cs[]; };

layout(std430) buffer type_3_block_4Compute { float _group_0_binding_7_cs[]; };

layout(std430) buffer type_7_block_5Compute { uint _group_0_binding_8_cs[]; };


float threshold_range2_(float intensity, float exposure, float error_bound) {
    if ((intensity <= 0.0)) {
        return 0.0;
    }
    return (((exposure / error_bound) * intensity) / TWO_PI);
}

float intensity_measure(vec3 rgb, uint mode) {
    if ((mode == 1u)) {
        return (((rgb.x + rgb.y) + rgb.z) / 3.0);
    }
    return max(rgb.x, max(rgb.y, rgb.z));
}

uint groups_across(uint bw, uint gw) {
    return (((bw + gw) - 1u) / gw);
}

uint group_first(uint g, uint bw_1, uint bh, uint gw_1, uint gh) {
    uint _e5 = groups_across(bw_1, gw_1);
    uint gx = (g % _e5);
    uint gy = (g / _e5);
    uint h = min(gh, (bh - (gh * gy)));
    return (((gy * gh) * bw_1) + ((gx * gw_1) * h));
}

uint cluster_index(uint bx, uint by, uint bw_2, uint bh_1, uint gw_2, uint gh_1) {
    uint gx_1 = (bx / gw_2);
    uint gy_1 = (by / gh_1);
    uint w = min(gw_2, (bw_2 - (gw_2 * gx_1)));
    uint _e11 = groups_across(bw_2, gw_2);
    uint g_1 = ((gy_1 * _e11) + gx_1);
    uint _e14 = group_first(g_1, bw_2, bh_1, gw_2, gh_1);
    return ((_e14 + ((by - (gh_1 * gy_1)) * w)) + (bx - (gw_2 * gx_1)));
}

uint cluster_x(uint c, uint bw_3, uint bh_2, uint gw_3, uint gh_2) {
    uint gy_2 = (c / (gh_2 * bw_3));
    uint h_1 = min(gh_2, (bh_2 - (gh_2 * gy_2)));
    uint rest = (c - ((gy_2 * gh_2) * bw_3));
    uint gx_2 = (rest / (gw_3 * h_1));
    uint w_1 = min(gw_3, (bw_3 - (gw_3 * gx_2)));
    return ((gx_2 * gw_3) + ((rest - ((gx_2 * gw_3) * h_1)) % w_1));
}

uint cluster_y(uint c_1, uint bw_4, uint bh_3, uint gw_4, uint gh_3) {
    uint gy_3 = (c_1 / (gh_3 * bw_4));
    uint h_2 = min(gh_3, (bh_3 - (gh_3 * gy_3)));
    uint rest_1 = (c_1 - ((gy_3 * gh_3) * bw_4));
    uint gx_3 = (rest_1 / (gw_4 * h_2));
    uint w_2 = min(gw_4, (bw_4 - (gw_4 * gx_3)));
    return ((gy_3 * gh_3) + ((rest_1 - ((gx_3 * gw_4) * h_2)) / w_2));
}

uint map_index(uint tx, uint ty, uint side) {
    uint b = (side / 8u);
    uint _e11 = cluster_index((tx / 8u), (ty / 8u), b, b, GROUP_SIDE, GROUP_SIDE);
    return (((_e11 * CLUSTER) + ((ty % 8u) * 8u)) + (tx % 8u));
}

uint map_x(uint q, uint side_1) {
    uint b_1 = (side_1 / 8u);
    uint _e8 = cluster_x((q / CLUSTER), b_1, b_1, GROUP_SIDE, GROUP_SIDE);
    return ((_e8 * 8u) + (q % 8u));
}

uint map_y(uint q_1, uint side_2) {
    uint b_2 = (side_2 / 8u);
    uint _e8 = cluster_y((q_1 / CLUSTER), b_2, b_2, GROUP_SIDE, GROUP_SIDE);
    return ((_e8 * 8u) + ((q_1 % CLUSTER) / 8u));
}

float vpl_rt2_(vec3 flux_1, float exposure_1, float error_bound_1, uint mode_1) {
    float _e6 = intensity_measure((flux_1 * INV_PI), mode_1);
    float _e7 = threshold_range2_(_e6, exposure_1, error_bound_1);
    return _e7;
}

bool finite3_(vec3 v) {
    bool local = false;
    bool local_1 = false;
    if ((abs(v.x) <= F32_MAX)) {
        local = (abs(v.y) <= F32_MAX);
    } else {
        local = false;
    }
    bool _e12 = local;
    if (_e12) {
        local_1 = (abs(v.z) <= F32_MAX);
    } else {
        local_1 = false;
    }
    bool _e20 = local_1;
    return _e20;
}

uint interleave_subset(uint x, uint y, uint period) {
    return (((y % period) * period) + (x % period));
}

bool vpl_record_ok(vec3 position, vec3 normal_1, vec3 flux_2) {
    bool local_2 = false;
    bool local_3 = false;
    bool local_4 = false;
    bool local_5 = false;
    bool local_6 = false;
    bool _e3 = finite3_(position);
    if (_e3) {
        bool _e6 = finite3_(normal_1);
        local_2 = _e6;
    } else {
        local_2 = false;
    }
    bool _e8 = local_2;
    if (_e8) {
        bool _e11 = finite3_(flux_2);
        local_3 = _e11;
    } else {
        local_3 = false;
    }
    bool _e13 = local_3;
    if (!(_e13)) {
        return false;
    }
    if ((flux_2.x >= 0.0)) {
        local_4 = (flux_2.y >= 0.0);
    } else {
        local_4 = false;
    }
    bool _e25 = local_4;
    if (_e25) {
        local_5 = (flux_2.z >= 0.0);
    } else {
        local_5 = false;
    }
    bool _e32 = local_5;
    if (_e32) {
        local_6 = ((max(max(flux_2.x, flux_2.y), flux_2.z) * INV_PI) <= MAX_INTENSITY);
    } else {
        local_6 = false;
    }
    bool _e45 = local_6;
    return _e45;
}

uint subset_side(uint size, uint period_1) {
    return ((((size / period_1) + 7u) / 8u) * 8u);
}

uint interleave_slot(uint tx_1, uint ty_1, uint size_1, uint period_2) {
    uint _e4 = subset_side(size_1, period_2);
    uint _e5 = interleave_subset(tx_1, ty_1, period_2);
    uint _e10 = map_index((tx_1 / period_2), (ty_1 / period_2), _e4);
    return (((_e5 * _e4) * _e4) + _e10);
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    vec3 p = vec3(0.0);
    vec3 normal = vec3(0.0);
    vec3 flux = vec3(0.0);
    uint q_2 = gid.x;
    uint _e4 = _group_0_binding_0_cs.count;
    if ((q_2 >= _e4)) {
        return;
    }
    uint _e8 = _group_0_binding_0_cs.size;
    uint _e9 = map_x(q_2, _e8);
    uint _e12 = _group_0_binding_0_cs.size;
    uint _e13 = map_y(q_2, _e12);
    uint _e16 = _group_0_binding_0_cs.size;
    uint i = ((_e13 * _e16) + _e9);
    ivec2 texel = ivec2(int(_e9), int(_e13));
    vec4 _e24 = texelFetch(_group_0_binding_1_cs, texel, 0);
    p = _e24.xyz;
    vec4 _e29 = texelFetch(_group_0_binding_2_cs, texel, 0);
    normal = _e29.xyz;
    vec4 _e34 = texelFetch(_group_0_binding_3_cs, texel, 0);
    flux = _e34.xyz;
    uint _e39 = _group_0_binding_0_cs.size;
    uint _e41 = interleave_slot(_e9, _e13, _e39, P);
    vec3 _e42 = p;
    vec3 _e43 = normal;
    vec3 _e44 = flux;
    bool _e45 = vpl_record_ok(_e42, _e43, _e44);
    if (!(_e45)) {
        p = vec3(0.0);
        normal = vec3(0.0);
        flux = vec3(0.0);
    }
    vec3 _e53 = flux;
    float _e56 = _group_0_binding_0_cs.scale;
    flux = (_e53 * _e56);
    vec3 _e60 = p;
    vec3 _e62 = normal;
    vec3 _e65 = flux;
    _group_0_binding_4_cs[_e41] = GpuLight(_e60, LIGHT_VPL, _e62, 0.0, vec3(0.0), 0.0, _e65, 0u);
    _group_0_binding_5_cs[_e41] = i;
    uint _e74 = _group_0_binding_0_cs.slc;
    bool slc = (_e74 != 0u);
    vec3 _e79 = flux;
    float _e82 = _group_0_binding_0_cs.exposure;
    float _e85 = _group_0_binding_0_cs.error_bound;
    uint _e88 = _group_0_binding_0_cs.mode;
    float _e89 = vpl_rt2_(_e79, _e82, _e85, _e88);
    _group_0_binding_6_cs[_e41] = (slc ? _e89 : 0.0);
    float _e96 = _group_0_binding_0_cs.fixed_r2_;
    _group_0_binding_7_cs[_e41] = (slc ? 0.0 : _e96);
    _group_0_binding_8_cs[q_2] = _e41;
    return;
}

