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

layout(std430) readonly buffer type_6_block_1Compute { vec4 _group_0_binding_3_cs[]; };

layout(rgba32f) writeonly uniform image2D _group_0_binding_4_cs;


vec4 surface_at(ivec2 texel) {
    vec4 p = texelFetch(_group_0_binding_1_cs, texel, 0);
    return ((p.w > 0.0) ? vec4(p.xyz, 1.0) : vec4(0.0));
}

GbTexel gbuffer_at(uint i) {
    bool local_1 = false;
    uint _e3 = _group_0_binding_0_cs.width;
    uint _e8 = _group_0_binding_0_cs.width;
    ivec2 texel_1 = ivec2(int((i % _e3)), int((i / _e8)));
    vec4 _e12 = surface_at(texel_1);
    vec4 _e15 = texelFetch(_group_0_binding_2_cs, texel_1, 0);
    vec3 n = _e15.xyz;
    float len2_ = dot(n, n);
    if ((_e12.w > 0.0)) {
        local_1 = (len2_ > 0.0);
    } else {
        local_1 = false;
    }
    bool valid = local_1;
    vec3 _e30 = _group_0_binding_0_cs.eye;
    vec3 v = (_e12.xyz - _e30);
    vec4 position = vec4(_e12.xyz, (valid ? 1.0 : 0.0));
    vec4 normal = (valid ? vec4((n / vec3(sqrt(len2_))), sqrt(dot(v, v))) : vec4(0.0, 0.0, 0.0, 1e30));
    return GbTexel(position, normal);
}

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
    uint i_1 = ((gid.y * _e19) + gid.x);
    GbTexel _e23 = gbuffer_at(i_1);
    bool valid_1 = (_e23.position.w > 0.0);
    vec4 _e32 = _group_0_binding_3_cs[i_1];
    vec4 e = (valid_1 ? _e32 : vec4(0.0));
    imageStore(_group_0_binding_4_cs, ivec2(int(gid.x), int(gid.y)), e);
    return;
}

