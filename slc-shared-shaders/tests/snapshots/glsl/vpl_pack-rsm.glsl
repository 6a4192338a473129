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
struct GpuNearBox {
    vec3 lo;
    float pad0_;
    vec3 hi;
    float pad1_;
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
const uint BOX_THREADS = 64u;

layout(std140) uniform PackParams_block_0Compute { PackParams _group_0_binding_0_cs; };

uniform sampler2D _group_0_binding_1_cs;

uniform sampler2D _group_0_binding_2_cs;

uniform sampler2D _group_0_binding_3_cs;

layout(std430) buffer type_6_block_1Compute { GpuLight _group_0_binding_4_cs[]; };

layout(std430) buffer type_7_block_2Compute { uint _group_0_binding_5_cs[]; };

layout(std430) buffer type_3_block_3Compute { float _group_0_binding_6_cs[]; };

layout(std430) buffer type_3_block_4Compute { float _group_0_binding_7_cs[]; };

layout(std430) buffer type_7_block_5Compute { uint _group_0_binding_8_cs[]; };

layout(std430) buffer type_8_block_6Compute { GpuNearBox _group_0_binding_9_cs[]; };

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];


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
    bool local_1 = false;
    bool local_2 = false;
    if ((abs(v.x) <= F32_MAX)) {
        local_1 = (abs(v.y) <= F32_MAX);
    } else {
        local_1 = false;
    }
    bool _e12 = local_1;
    if (_e12) {
        local_2 = (abs(v.z) <= F32_MAX);
    } else {
        local_2 = false;
    }
    bool _e20 = local_2;
    return _e20;
}

uint interleave_subset(uint x, uint y, uint period) {
    return (((y % period) * period) + (x % period));
}

bool vpl_record_ok(vec3 position_1, vec3 normal_1, vec3 flux_2) {
    bool local_3 = false;
    bool local_4 = false;
    bool local_5 = false;
    bool local_6 = false;
    bool local_7 = false;
    bool _e3 = finite3_(position_1);
    if (_e3) {
        bool _e6 = finite3_(normal_1);
        local_3 = _e6;
    } else {
        local_3 = false;
    }
    bool _e8 = local_3;
    if (_e8) {
        bool _e11 = finite3_(flux_2);
        local_4 = _e11;
    } else {
        local_4 = false;
    }
    bool _e13 = local_4;
    if (!(_e13)) {
        return false;
    }
    if ((flux_2.x >= 0.0)) {
        local_5 = (flux_2.y >= 0.0);
    } else {
        local_5 = false;
    }
    bool _e25 = local_5;
    if (_e25) {
        local_6 = (flux_2.z >= 0.0);
    } else {
        local_6 = false;
    }
    bool _e32 = local_6;
    if (_e32) {
        local_7 = ((max(max(flux_2.x, flux_2.y), flux_2.z) * INV_PI) <= MAX_INTENSITY);
    } else {
        local_7 = false;
    }
    bool _e45 = local_7;
    return _e45;
}

uint interleave_slot(uint tx, uint ty, uint size, uint period_1) {
    uint side = (size / period_1);
    uint _e5 = interleave_subset(tx, ty, period_1);
    return ((((_e5 * side) * side) + ((ty / period_1) * side)) + (tx / period_1));
}

uint near_block_tx(uint q, uint size_1) {
    return ((((q / NEAR_BLOCK) % (size_1 / 8u)) * 8u) + (q % 8u));
}

uint near_block_ty(uint q_1, uint size_2) {
    return ((((q_1 / NEAR_BLOCK) / (size_2 / 8u)) * 8u) + ((q_1 % NEAR_BLOCK) / 8u));
}

WorkgroupBox workgroup_box(uint li_1, vec3 p_1, bool has) {
    uint stride = 32u;
    wg_lo[li_1] = (has ? p_1 : vec3(3.4028235e38));
    wg_hi[li_1] = (has ? p_1 : vec3(-3.4028235e38));
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
    }
    memoryBarrierShared();
    barrier();
    uvec3 gid = gl_GlobalInvocationID;
    uvec3 wg = gl_WorkGroupID;
    uint li = gl_LocalInvocationIndex;
    vec3 position = vec3(0.0);
    bool lit = false;
    vec3 p = vec3(0.0);
    vec3 normal = vec3(0.0);
    vec3 flux = vec3(0.0);
    bool local = false;
    uint q_2 = gid.x;
    uint _e6 = _group_0_binding_0_cs.count;
    bool inside = (q_2 < _e6);
    if (inside) {
        uint _e15 = _group_0_binding_0_cs.size;
        uint _e16 = near_block_tx(q_2, _e15);
        uint _e19 = _group_0_binding_0_cs.size;
        uint _e20 = near_block_ty(q_2, _e19);
        uint _e23 = _group_0_binding_0_cs.size;
        uint i = ((_e20 * _e23) + _e16);
        ivec2 texel = ivec2(int(_e16), int(_e20));
        vec4 _e31 = texelFetch(_group_0_binding_1_cs, texel, 0);
        p = _e31.xyz;
        vec4 _e36 = texelFetch(_group_0_binding_2_cs, texel, 0);
        normal = _e36.xyz;
        vec4 _e41 = texelFetch(_group_0_binding_3_cs, texel, 0);
        flux = _e41.xyz;
        uint _e46 = _group_0_binding_0_cs.size;
        uint _e48 = interleave_slot(_e16, _e20, _e46, P);
        vec3 _e49 = p;
        vec3 _e50 = normal;
        vec3 _e51 = flux;
        bool _e52 = vpl_record_ok(_e49, _e50, _e51);
        if (!(_e52)) {
            p = vec3(0.0);
            normal = vec3(0.0);
            flux = vec3(0.0);
        }
        vec3 _e60 = p;
        position = _e60;
        vec3 _e61 = flux;
        float _e64 = _group_0_binding_0_cs.scale;
        flux = (_e61 * _e64);
        vec3 _e68 = position;
        vec3 _e70 = normal;
        vec3 _e73 = flux;
        _group_0_binding_4_cs[_e48] = GpuLight(_e68, LIGHT_VPL, _e70, 0.0, vec3(0.0), 0.0, _e73, 0u);
        _group_0_binding_5_cs[_e48] = i;
        uint _e82 = _group_0_binding_0_cs.slc;
        bool slc = (_e82 != 0u);
        vec3 _e87 = flux;
        float _e90 = _group_0_binding_0_cs.exposure;
        float _e93 = _group_0_binding_0_cs.error_bound;
        uint _e96 = _group_0_binding_0_cs.mode;
        float _e97 = vpl_rt2_(_e87, _e90, _e93, _e96);
        _group_0_binding_6_cs[_e48] = (slc ? _e97 : 0.0);
        float _e104 = _group_0_binding_0_cs.fixed_r2_;
        _group_0_binding_7_cs[_e48] = (slc ? 0.0 : _e104);
        _group_0_binding_8_cs[q_2] = _e48;
        vec3 _e109 = flux;
        lit = any(notEqual(_e109, vec3(0.0)));
    }
    vec3 _e114 = position;
    bool _e115 = lit;
    WorkgroupBox _e116 = workgroup_box(li, _e114, _e115);
    if ((li == 0u)) {
        local = inside;
    } else {
        local = false;
    }
    bool _e122 = local;
    if (_e122) {
        _group_0_binding_9_cs[wg.x] = GpuNearBox(_e116.lo, 0.0, _e116.hi, 0.0);
        return;
    } else {
        return;
    }
}

