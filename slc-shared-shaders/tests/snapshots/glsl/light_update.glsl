#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct FrameParams {
    uint light_count;
    uint seed;
    uint frame;
    uint pad;
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

uint reverse_bits(uint x_1) {
    uint v = 0u;
    v = (((x_1 >> 16u) & 65535u) | ((x_1 & 65535u) << 16u));
    uint _e11 = v;
    uint _e16 = v;
    v = (((_e11 >> 8u) & 16711935u) | ((_e16 & 16711935u) << 8u));
    uint _e22 = v;
    uint _e27 = v;
    v = (((_e22 >> 4u) & 252645135u) | ((_e27 & 252645135u) << 4u));
    uint _e33 = v;
    uint _e38 = v;
    v = (((_e33 >> 2u) & 858993459u) | ((_e38 & 858993459u) << 2u));
    uint _e44 = v;
    uint _e49 = v;
    v = (((_e44 >> 1u) & 1431655765u) | ((_e49 & 1431655765u) << 1u));
    uint _e55 = v;
    return _e55;
}

float xi_for(uint seed, uint frame, uint light) {
    uint _e3 = pcg_hash(seed);
    uint _e4 = pcg_hash(_e3);
    uint _e6 = pcg_hash((_e4 ^ light));
    uint _e7 = reverse_bits(frame);
    uint _e8 = add_wrap_u32_(_e6, _e7);
    float _e9 = xi_from_bits(_e8);
    return _e9;
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
    float _e20 = xi_for(_e13, _e16, _e19);
    float _e21 = random_range2_(_e10, _e20);
    _group_0_binding_3_cs[i] = _e21;
    return;
}

