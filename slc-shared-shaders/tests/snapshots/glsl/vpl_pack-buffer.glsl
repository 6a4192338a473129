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
struct GpuVplRecord {
    vec3 position;
    float pad0_;
    vec3 normal;
    float pad1_;
    vec3 flux;
    float pad2_;
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

layout(std430) readonly buffer type_5_block_1Compute { GpuVplRecord _group_0_binding_1_cs[]; };

layout(std430) buffer type_6_block_2Compute { GpuLight _group_0_binding_4_cs[]; };

layout(std430) buffer type_7_block_3Compute { uint _group_0_binding_5_cs[]; };

layout(std430) buffer type_3_block_4Compute { float _group_0_binding_6_cs[]; };

layout(std430) buffer type_3_block_5Compute { float _group_0_binding_7_cs[]; };

layout(std430) buffer type_7_block_6Compute { uint _group_0_binding_8_cs[]; };


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

uint interleave_slot_linear(uint i, uint per_subset, uint period) {
    uint subsets = (period * period);
    return (((i % subsets) * per_subset) + (i / subsets));
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    vec3 p = vec3(0.0);
    vec3 normal = vec3(0.0);
    vec3 flux = vec3(0.0);
    uint i_1 = gid.x;
    uint _e4 = _group_0_binding_0_cs.count;
    if ((i_1 >= _e4)) {
        return;
    }
    GpuVplRecord r = _group_0_binding_1_cs[i_1];
    p = r.position;
    normal = r.normal;
    flux = r.flux;
    uint _e17 = _group_0_binding_0_cs.per_subset;
    uint _e19 = interleave_slot_linear(i_1, _e17, P);
    vec3 _e20 = p;
    vec3 _e21 = normal;
    vec3 _e22 = flux;
    bool _e23 = vpl_record_ok(_e20, _e21, _e22);
    if (!(_e23)) {
        p = vec3(0.0);
        normal = vec3(0.0);
        flux = vec3(0.0);
    }
    vec3 _e31 = flux;
    float _e34 = _group_0_binding_0_cs.scale;
    flux = (_e31 * _e34);
    vec3 _e38 = p;
    vec3 _e40 = normal;
    vec3 _e43 = flux;
    _group_0_binding_4_cs[_e19] = GpuLight(_e38, LIGHT_VPL, _e40, 0.0, vec3(0.0), 0.0, _e43, 0u);
    _group_0_binding_5_cs[_e19] = i_1;
    uint _e52 = _group_0_binding_0_cs.slc;
    bool slc = (_e52 != 0u);
    vec3 _e57 = flux;
    float _e60 = _group_0_binding_0_cs.exposure;
    float _e63 = _group_0_binding_0_cs.error_bound;
    uint _e66 = _group_0_binding_0_cs.mode;
    float _e67 = vpl_rt2_(_e57, _e60, _e63, _e66);
    _group_0_binding_6_cs[_e19] = (slc ? _e67 : 0.0);
    float _e74 = _group_0_binding_0_cs.fixed_r2_;
    _group_0_binding_7_cs[_e19] = (slc ? 0.0 : _e74);
    _group_0_binding_8_cs[i_1] = _e19;
    return;
}

