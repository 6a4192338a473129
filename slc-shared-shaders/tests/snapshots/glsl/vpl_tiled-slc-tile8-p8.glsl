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
    uint pad0_;
    uint pad1_;
};
struct WorkgroupBox {
    vec3 lo;
    vec3 hi;
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
const uint P = 8u;
const uint TILE = 8u;
const uint THREADS = 64u;
const uint BOX_THREADS = 64u;
const uint MAX_TILE_LIGHTS = 1024u;

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

layout(std140) uniform VplParams_block_0Compute { VplParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_7_block_1Compute { vec4 _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_7_block_2Compute { vec4 _group_0_binding_2_cs[]; };

layout(std430) readonly buffer type_8_block_3Compute { GpuLight _group_0_binding_3_cs[]; };

layout(std430) readonly buffer type_4_block_4Compute { float _group_0_binding_4_cs[]; };

layout(std430) readonly buffer type_4_block_5Compute { float _group_0_binding_5_cs[]; };

layout(std430) buffer type_7_block_6Compute { vec4 _group_0_binding_6_cs[]; };

shared uint tile_count;

shared uint tile_lights[1024];


float slc_weight(float rt2_, float d2_) {
    if ((d2_ <= rt2_)) {
        return 1.0;
    }
    return (d2_ / rt2_);
}

bool slc_keep(float r2_, float d2_1) {
    return (d2_1 < r2_);
}

float cull_radius(float r2_1) {
    return (sqrt(r2_1) * CULL_RADIUS_SCALE);
}

bool sphere_overlaps_aabb(vec3 c, float r, vec3 bmin, vec3 bmax) {
    vec3 q = clamp(c, bmin, bmax);
    vec3 v_1 = (q - c);
    return (dot(v_1, v_1) <= (r * r));
}

float vpl_transfer(vec3 n_l, vec3 n_x, vec3 v, float min_d2_) {
    float m = max(dot(v, v), min_d2_);
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m * m));
}

float vpl_near_weight(float d2_2, float near_r2_) {
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t = clamp(((near_r2_ - d2_2) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t * t) * (3.0 - (2.0 * t)));
}

float vpl_far_weight(float d2_3, float near_r2_1) {
    float _e2 = vpl_near_weight(d2_3, near_r2_1);
    return (1.0 - _e2);
}

float vpl_far_slc_share(float rt2_1, float r2_2, float d2_4, float near_r2_2) {
    float _e4 = vpl_far_weight(d2_4, near_r2_2);
    float _e5 = slc_weight(rt2_1, d2_4);
    bool _e7 = slc_keep(r2_2, d2_4);
    return ((_e7 && (_e4 > 0.0)) ? (_e4 * _e5) : 0.0);
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
        vec4 _e49 = _group_0_binding_1_cs[pix];
        pos = _e49;
        vec4 _e52 = _group_0_binding_2_cs[pix];
        nrm = _e52.xyz;
    }
    if (inside) {
        float _e57 = pos.w;
        local_1 = (_e57 > 0.0);
    } else {
        local_1 = false;
    }
    bool valid = local_1;
    vec4 _e62 = pos;
    WorkgroupBox _e64 = workgroup_box(li, _e62.xyz, valid);
    vec3 lo = _e64.lo;
    vec3 hi = _e64.hi;
    uint _e69 = _group_0_binding_0_cs.lights_per_subset;
    uint base = (sub * _e69);
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e173 = first;
            first = (_e173 + MAX_TILE_LIGHTS);
        }
        loop_init_1 = false;
        uint _e78 = first;
        uint _e81 = _group_0_binding_0_cs.lights_per_subset;
        if ((_e78 < _e81)) {
        } else {
            break;
        }
        {
            uint _e83 = first;
            uint _e88 = _group_0_binding_0_cs.lights_per_subset;
            uint end = min((_e83 + MAX_TILE_LIGHTS), _e88);
            if ((li == 0u)) {
                atomicExchange(tile_count, 0u);
            }
            memoryBarrierShared();
            barrier();
            uint _e94 = first;
            j = (_e94 + li);
            bool loop_init_2 = true;
            while(true) {
                if (!loop_init_2) {
                    uint _e120 = j;
                    j = (_e120 + THREADS);
                }
                loop_init_2 = false;
                uint _e97 = j;
                if ((_e97 < end)) {
                } else {
                    break;
                }
                {
                    uint _e100 = j;
                    vec3 _e104 = _group_0_binding_3_cs[(base + _e100)].p0_;
                    uint _e106 = j;
                    float _e109 = _group_0_binding_5_cs[(base + _e106)];
                    float _e110 = cull_radius(_e109);
                    bool _e111 = sphere_overlaps_aabb(_e104, _e110, lo, hi);
                    if (_e111) {
                        uint _e114 = atomicAdd(tile_count, 1u);
                        if ((_e114 < MAX_TILE_LIGHTS)) {
                            uint _e119 = j;
                            tile_lights[_e114] = _e119;
                        }
                    }
                }
            }
            memoryBarrierShared();
            barrier();
            uint _e124 = tile_count;
            memoryBarrierShared();
            barrier();
            uint count = min(_e124, MAX_TILE_LIGHTS);
            if (valid) {
                k = 0u;
                bool loop_init_3 = true;
                while(true) {
                    if (!loop_init_3) {
                        uint _e171 = k;
                        k = (_e171 + 1u);
                    }
                    loop_init_3 = false;
                    uint _e129 = k;
                    if ((_e129 < count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e132 = k;
                        uint _e134 = tile_lights[_e132];
                        uint j_1 = (base + _e134);
                        GpuLight l = _group_0_binding_3_cs[j_1];
                        vec4 _e139 = pos;
                        vec3 v_2 = (_e139.xyz - l.p0_);
                        float _e145 = _group_0_binding_4_cs[j_1];
                        float _e148 = _group_0_binding_5_cs[j_1];
                        float _e152 = _group_0_binding_0_cs.near_r2_;
                        float _e153 = vpl_far_slc_share(_e145, _e148, dot(v_2, v_2), _e152);
                        if ((_e153 > 0.0)) {
                            vec3 _e156 = e;
                            vec3 _e159 = nrm;
                            float _e162 = _group_0_binding_0_cs.min_d2_;
                            float _e163 = vpl_transfer(l.p1_, _e159, v_2, _e162);
                            e = (_e156 + (l.intensity * (_e163 * _e153)));
                            uint _e167 = kept;
                            kept = (_e167 + 1u);
                        }
                    }
                }
            }
            memoryBarrierShared();
            barrier();
        }
    }
    if (valid) {
        vec3 _e178 = e;
        uint _e179 = kept;
        _group_0_binding_6_cs[pix] = vec4(_e178, float(_e179));
        return;
    } else {
        return;
    }
}

