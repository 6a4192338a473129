#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

struct ViewParams {
    vec4 c0_;
    vec4 c1_;
    vec4 c2_;
    vec4 c3_;
    vec3 eye;
    uint width;
    uint height;
    float background;
    uint seed;
    uint frame;
    vec3 f0_d;
    float f90_d;
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

layout(std140) uniform ViewParams_block_0Compute { ViewParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_5_block_1Compute { vec4 _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_5_block_2Compute { vec4 _group_0_binding_2_cs[]; };

layout(rgba32f) writeonly uniform image2D _group_0_binding_3_cs;


void main() {
    uvec3 gid = gl_GlobalInvocationID;
    bool local = false;
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
    uint _e19 = _group_0_binding_0_cs.width;
    uint i = ((gid.y * _e19) + gid.x);
    vec4 _e27 = _group_0_binding_2_cs[i];
    float _e31 = _group_0_binding_1_cs[i].w;
    vec4 e = ((_e31 > 0.0) ? _e27 : vec4(0.0));
    imageStore(_group_0_binding_3_cs, ivec2(int(gid.x), int(gid.y)), e);
    return;
}

