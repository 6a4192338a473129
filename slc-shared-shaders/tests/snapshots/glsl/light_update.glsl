#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct FrameParams {
    uint light_count;
    uint seed;
    uint frame;
    float fixed_xi;
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

layout(std140) uniform FrameParams_block_0Compute { FrameParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_3_block_1Compute { uint _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_2_block_2Compute { float _group_0_binding_2_cs[]; };

layout(std430) buffer type_2_block_3Compute { float _group_0_binding_3_cs[]; };


float to_f32_(uint u) {
    return float(u);
}

uint mul_lo_u32_(uint a, uint b) {
    return (a * b);
}

uint add_wrap_u32_(uint a_1, uint b_1) {
    return (a_1 + b_1);
}

float xi_from_bits(uint bits) {
    float _e3 = to_f32_((bits >> 8u));
    return (_e3 * XI_STEP);
}

uint pcg_hash(uint x) {
    uint _e2 = mul_lo_u32_(x, 747796405u);
    uint _e4 = add_wrap_u32_(_e2, 2891336453u);
    uint _e12 = mul_lo_u32_(((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4), 277803737u);
    return ((_e12 >> 22u) ^ _e12);
}

uint laine_karras(uint x_1, uint seed) {
    uint v = 0u;
    uint _e2 = add_wrap_u32_(x_1, seed);
    v = _e2;
    uint _e4 = v;
    uint _e5 = v;
    uint _e7 = mul_lo_u32_(_e5, 1817228412u);
    v = (_e4 ^ _e7);
    uint _e9 = v;
    uint _e10 = v;
    uint _e12 = mul_lo_u32_(_e10, 3090095698u);
    v = (_e9 ^ _e12);
    uint _e14 = v;
    uint _e15 = v;
    uint _e17 = mul_lo_u32_(_e15, 3350193720u);
    v = (_e14 ^ _e17);
    uint _e19 = v;
    uint _e20 = v;
    uint _e22 = mul_lo_u32_(_e20, 2367878886u);
    v = (_e19 ^ _e22);
    uint _e24 = v;
    return _e24;
}

uint reverse_bits(uint x_2) {
    uint v_1 = 0u;
    v_1 = (((x_2 >> 16u) & 65535u) | ((x_2 & 65535u) << 16u));
    uint _e11 = v_1;
    uint _e16 = v_1;
    v_1 = (((_e11 >> 8u) & 16711935u) | ((_e16 & 16711935u) << 8u));
    uint _e22 = v_1;
    uint _e27 = v_1;
    v_1 = (((_e22 >> 4u) & 252645135u) | ((_e27 & 252645135u) << 4u));
    uint _e33 = v_1;
    uint _e38 = v_1;
    v_1 = (((_e33 >> 2u) & 858993459u) | ((_e38 & 858993459u) << 2u));
    uint _e44 = v_1;
    uint _e49 = v_1;
    v_1 = (((_e44 >> 1u) & 1431655765u) | ((_e49 & 1431655765u) << 1u));
    uint _e55 = v_1;
    return _e55;
}

float xi_for(uint seed_1, uint frame, uint light) {
    uint _e3 = pcg_hash(seed_1);
    uint _e4 = pcg_hash(_e3);
    uint _e6 = pcg_hash((_e4 ^ light));
    uint _e7 = pcg_hash(_e6);
    uint _e8 = reverse_bits(frame);
    uint _e9 = laine_karras(_e8, _e7);
    uint _e11 = laine_karras(0u, _e7);
    uint _e13 = add_wrap_u32_(_e6, (_e9 ^ _e11));
    float _e14 = xi_from_bits(_e13);
    return _e14;
}

float xi_rotated(uint seed_2, uint frame_1, uint light_1, uint bits_1) {
    uint _e4 = pcg_hash(seed_2);
    uint _e7 = pcg_hash((_e4 ^ 1013904223u));
    uint _e8 = laine_karras(light_1, _e7);
    uint _e13 = pcg_hash((_e7 ^ light_1));
    uint o = ((_e8 << (32u - bits_1)) | (_e13 >> bits_1));
    uint _e16 = pcg_hash(_e7);
    uint _e17 = reverse_bits(frame_1);
    uint _e18 = laine_karras(_e17, _e16);
    uint _e20 = laine_karras(0u, _e16);
    uint t = (_e18 ^ _e20);
    uint _e22 = add_wrap_u32_(o, t);
    float _e23 = xi_from_bits(_e22);
    return _e23;
}

float light_xi(uint seed_3, uint frame_2, uint key) {
    if ((key >= XI_ROTATED)) {
        float _e13 = xi_rotated(seed_3, frame_2, (key & XI_INDEX_MASK), max(((key >> XI_BITS_SHIFT) & 31u), 1u));
        return _e13;
    }
    float _e14 = xi_for(seed_3, frame_2, key);
    return _e14;
}

float frame_xi(uint seed_4, uint frame_3, uint key_1, float fixed_) {
    if ((fixed_ >= 0.0)) {
        return fixed_;
    }
    float _e6 = light_xi(seed_4, frame_3, key_1);
    return _e6;
}

float random_range2_(float rt2_, float xi) {
    return (rt2_ / (1.0 - xi));
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    uint i = gid.x;
    uint _e4 = _group_0_binding_0_cs.light_count;
    if ((i >= _e4)) {
        return;
    }
    float _e10 = _group_0_binding_2_cs[i];
    uint _e13 = _group_0_binding_0_cs.seed;
    uint _e16 = _group_0_binding_0_cs.frame;
    uint _e19 = _group_0_binding_1_cs[i];
    float _e22 = _group_0_binding_0_cs.fixed_xi;
    float _e23 = frame_xi(_e13, _e16, _e19, _e22);
    float _e24 = random_range2_(_e10, _e23);
    _group_0_binding_3_cs[i] = _e24;
    return;
}

