#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

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
struct VplParams {
    uint width;
    uint height;
    uint lights_per_subset;
    float min_d2_;
    float near_r2_;
    uint near_blocks;
    uint subset_shift;
    uint pad1_;
};
struct ViewParams {
    vec4 c0_;
    vec4 c1_;
    vec4 c2_;
    vec4 c3_;
    vec3 eye;
    uint width;
    uint height;
    uint pad0_;
    uint seed;
    uint frame;
    vec3 f0_d;
    float f90_d;
};
struct WorkgroupBox {
    vec3 lo;
    vec3 hi;
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
const float MAX_INTENSITY = 7.2057594e16;
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
const uint TILE = 8u;
const uint THREADS = 64u;
const uint BOX_THREADS = 64u;
const uint MAX_TILE_LIGHTS = 1024u;

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

layout(std140) uniform VplParams_block_0Compute { VplParams _group_0_binding_0_cs; };

layout(std140) uniform ViewParams_block_1Compute { ViewParams _group_0_binding_1_cs; };

uniform sampler2D _group_0_binding_2_cs;

uniform sampler2D _group_0_binding_3_cs;

layout(std430) readonly buffer type_8_block_2Compute { GpuLight _group_0_binding_4_cs[]; };

layout(std430) readonly buffer type_4_block_3Compute { float _group_0_binding_6_cs[]; };

layout(std430) buffer type_9_block_4Compute { vec4 _group_0_binding_7_cs[]; };

shared uint tile_count;

shared uint tile_lights[1024];


bool clamp_keep(float range2_, float d2_) {
    return (d2_ < range2_);
}

float cull_radius(float r2_) {
    return (sqrt(r2_) * CULL_RADIUS_SCALE);
}

bool sphere_overlaps_aabb(vec3 c, float r, vec3 bmin, vec3 bmax) {
    vec3 q = clamp(c, bmin, bmax);
    vec3 v_1 = (q - c);
    return (dot(v_1, v_1) <= (r * r));
}

float vpl_transfer(vec3 n_l, vec3 n_x, vec3 v, float min_d2_) {
    float m = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m * m));
}

uint shifted_subset(uint pixel_class, uint shift, uint period) {
    return ((pixel_class + shift) % (period * period));
}

float vpl_near_weight(float d2_1, float near_r2_) {
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t = clamp(((near_r2_ - d2_1) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t * t) * (3.0 - (2.0 * t)));
}

float vpl_far_weight(float d2_2, float near_r2_1) {
    float _e2 = vpl_near_weight(d2_2, near_r2_1);
    return (1.0 - _e2);
}

float vpl_far_fixed_share(float range2_1, float d2_3, float near_r2_2) {
    float _e3 = vpl_far_weight(d2_3, near_r2_2);
    bool _e4 = clamp_keep(range2_1, d2_3);
    return ((_e4 && (_e3 > 0.0)) ? _e3 : 0.0);
}

WorkgroupBox workgroup_box(uint li_1, vec3 p, bool has) {
    uint stride = 32u;
    wg_lo[li_1] = (has ? p : vec3(3.4028235e38));
    wg_hi[li_1] = (has ? p : vec3(-3.4028235e38));
    memoryBarrierShared();
    barrier();
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e42 = stride;
            stride = (_e42 / 2u);
        }
        loop_init = false;
        uint _e15 = stride;
        if ((_e15 > 0u)) {
        } else {
            break;
        }
        {
            uint _e18 = stride;
            if ((li_1 < _e18)) {
                vec3 _e24 = wg_lo[li_1];
                uint _e26 = stride;
                vec3 _e29 = wg_lo[(li_1 + _e26)];
                wg_lo[li_1] = min(_e24, _e29);
                vec3 _e35 = wg_hi[li_1];
                uint _e37 = stride;
                vec3 _e40 = wg_hi[(li_1 + _e37)];
                wg_hi[li_1] = max(_e35, _e40);
            }
            memoryBarrierShared();
            barrier();
        }
    }
    vec3 _e47 = wg_lo[0];
    vec3 _e50 = wg_hi[0];
    return WorkgroupBox(_e47, _e50);
}

vec4 surface_at(ivec2 texel) {
    vec4 p_1 = texelFetch(_group_0_binding_2_cs, texel, 0);
    return ((p_1.w > 0.0) ? vec4(p_1.xyz, 1.0) : vec4(0.0));
}

GbTexel gbuffer_at(uint i) {
    bool local_2 = false;
    uint _e3 = _group_0_binding_1_cs.width;
    uint _e8 = _group_0_binding_1_cs.width;
    ivec2 texel_1 = ivec2(int((i % _e3)), int((i / _e8)));
    vec4 _e12 = surface_at(texel_1);
    vec4 _e15 = texelFetch(_group_0_binding_3_cs, texel_1, 0);
    vec3 n = _e15.xyz;
    float len2_ = dot(n, n);
    if ((_e12.w > 0.0)) {
        local_2 = (len2_ > 0.0);
    } else {
        local_2 = false;
    }
    bool valid = local_2;
    vec3 _e30 = _group_0_binding_1_cs.eye;
    vec3 v_2 = (_e12.xyz - _e30);
    vec4 position = vec4(_e12.xyz, (valid ? 1.0 : 0.0));
    vec4 normal = (valid ? vec4((n / vec3(sqrt(len2_))), sqrt(dot(v_2, v_2))) : vec4(0.0, 0.0, 0.0, 1e30));
    return GbTexel(position, normal);
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_lo = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_hi = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        tile_count = 0u;
        tile_lights = uint[1024](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    }
    memoryBarrierShared();
    barrier();
    uvec3 wg = gl_WorkGroupID;
    uvec3 lid = gl_LocalInvocationID;
    uint li = gl_LocalInvocationIndex;
    bool local = false;
    vec4 pos = vec4(0.0);
    vec3 nrm = vec3(0.0);
    bool local_1 = false;
    vec3 e = vec3(0.0);
    uint kept = 0u;
    uint first = 0u;
    uint j = 0u;
    uint k = 0u;
    uint sub = wg.z;
    uint px = ((sub % P) + (((wg.x * TILE) + lid.x) * P));
    uint py = ((sub / P) + (((wg.y * TILE) + lid.y) * P));
    uint _e26 = _group_0_binding_0_cs.width;
    if ((px < _e26)) {
        uint _e32 = _group_0_binding_0_cs.height;
        local = (py < _e32);
    } else {
        local = false;
    }
    bool inside = local;
    uint _e38 = _group_0_binding_0_cs.width;
    uint pix = ((py * _e38) + px);
    if (inside) {
        GbTexel _e47 = gbuffer_at(pix);
        pos = _e47.position;
        nrm = _e47.normal.xyz;
    }
    if (inside) {
        float _e54 = pos.w;
        local_1 = (_e54 > 0.0);
    } else {
        local_1 = false;
    }
    bool valid_1 = local_1;
    vec4 _e59 = pos;
    WorkgroupBox _e61 = workgroup_box(li, _e59.xyz, valid_1);
    vec3 lo = _e61.lo;
    vec3 hi = _e61.hi;
    uint _e66 = _group_0_binding_0_cs.subset_shift;
    uint _e68 = shifted_subset(sub, _e66, P);
    uint _e71 = _group_0_binding_0_cs.lights_per_subset;
    uint base = (_e68 * _e71);
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e172 = first;
            first = (_e172 + MAX_TILE_LIGHTS);
        }
        loop_init_1 = false;
        uint _e80 = first;
        uint _e83 = _group_0_binding_0_cs.lights_per_subset;
        if ((_e80 < _e83)) {
        } else {
            break;
        }
        {
            uint _e85 = first;
            uint _e90 = _group_0_binding_0_cs.lights_per_subset;
            uint end = min((_e85 + MAX_TILE_LIGHTS), _e90);
            if ((li == 0u)) {
                atomicExchange(tile_count, 0u);
            }
            memoryBarrierShared();
            barrier();
            uint _e96 = first;
            j = (_e96 + li);
            bool loop_init_2 = true;
            while(true) {
                if (!loop_init_2) {
                    uint _e122 = j;
                    j = (_e122 + THREADS);
                }
                loop_init_2 = false;
                uint _e99 = j;
                if ((_e99 < end)) {
                } else {
                    break;
                }
                {
                    uint _e102 = j;
                    vec3 _e106 = _group_0_binding_4_cs[(base + _e102)].p0_;
                    uint _e108 = j;
                    float _e111 = _group_0_binding_6_cs[(base + _e108)];
                    float _e112 = cull_radius(_e111);
                    bool _e113 = sphere_overlaps_aabb(_e106, _e112, lo, hi);
                    if (_e113) {
                        uint _e116 = atomicAdd(tile_count, 1u);
                        if ((_e116 < MAX_TILE_LIGHTS)) {
                            uint _e121 = j;
                            tile_lights[_e116] = _e121;
                        }
                    }
                }
            }
            memoryBarrierShared();
            barrier();
            uint _e126 = tile_count;
            memoryBarrierShared();
            barrier();
            uint count = min(_e126, MAX_TILE_LIGHTS);
            if (valid_1) {
                k = 0u;
                bool loop_init_3 = true;
                while(true) {
                    if (!loop_init_3) {
                        uint _e170 = k;
                        k = (_e170 + 1u);
                    }
                    loop_init_3 = false;
                    uint _e131 = k;
                    if ((_e131 < count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e134 = k;
                        uint _e136 = tile_lights[_e134];
                        uint j_1 = (base + _e136);
                        GpuLight l = _group_0_binding_4_cs[j_1];
                        vec4 _e141 = pos;
                        vec3 v_3 = (_e141.xyz - l.p0_);
                        float _e147 = _group_0_binding_6_cs[j_1];
                        float _e151 = _group_0_binding_0_cs.near_r2_;
                        float _e152 = vpl_far_fixed_share(_e147, dot(v_3, v_3), _e151);
                        if ((_e152 > 0.0)) {
                            vec3 _e156 = nrm;
                            float _e159 = _group_0_binding_0_cs.min_d2_;
                            float _e160 = vpl_transfer(l.p1_, _e156, v_3, _e159);
                            float t_1 = (_e160 * _e152);
                            vec3 _e162 = e;
                            e = (_e162 + (l.intensity * t_1));
                            uint _e166 = kept;
                            kept = (_e166 + 1u);
                        }
                    }
                }
            }
            memoryBarrierShared();
            barrier();
        }
    }
    if (inside) {
        vec3 _e177 = e;
        uint _e178 = kept;
        _group_0_binding_7_cs[pix] = vec4(_e177, float(_e178));
        return;
    } else {
        return;
    }
}

