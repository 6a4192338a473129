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
struct VplParams {
    uint width;
    uint height;
    uint lights_per_subset;
    float min_d2_;
    float near_r2_;
    uint subset_shift;
    uint far_groups_at;
    uint near_clusters_at;
    uint near_groups_at;
    uint box_count;
    uint pad0_;
    uint pad1_;
    uvec4 far_grid;
    uvec4 near_grid;
};
struct GpuBox {
    vec3 lo;
    float pad0_;
    vec3 hi;
    float pad1_;
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
const uint BOX_THREADS = 64u;

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

shared WorkgroupBox wg_box;

layout(std140) uniform VplParams_block_0Compute { VplParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_6_block_1Compute { GpuLight _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_4_block_2Compute { float _group_0_binding_2_cs[]; };

layout(std430) readonly buffer type_7_block_3Compute { uint _group_0_binding_3_cs[]; };

layout(std430) buffer type_8_block_4Compute { GpuBox _group_0_binding_4_cs[]; };


float to_f32_(uint u) {
    return float(u);
}

float cull_radius(float r2_) {
    return (sqrt(r2_) * CULL_RADIUS_SCALE);
}

float interleave_flux_scale(uint period) {
    float _e2 = to_f32_((period * period));
    return _e2;
}

float vpl_near_range2_(float r2_1, uint period_1) {
    float _e2 = interleave_flux_scale(period_1);
    return (r2_1 / _e2);
}

float vpl_near_cull_range2_(float r2_2, float near_r2_) {
    return min(r2_2, near_r2_);
}

WorkgroupBox workgroup_bounds(uint li_1, vec3 lo, vec3 hi) {
    uint stride = 32u;
    wg_lo[li_1] = lo;
    wg_hi[li_1] = hi;
    memoryBarrierShared();
    barrier();
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e36 = stride;
            stride = (_e36 / 2u);
        }
        loop_init = false;
        uint _e9 = stride;
        if ((_e9 > 0u)) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if ((li_1 < _e12)) {
                vec3 _e18 = wg_lo[li_1];
                uint _e20 = stride;
                vec3 _e23 = wg_lo[(li_1 + _e20)];
                wg_lo[li_1] = min(_e18, _e23);
                vec3 _e29 = wg_hi[li_1];
                uint _e31 = stride;
                vec3 _e34 = wg_hi[(li_1 + _e31)];
                wg_hi[li_1] = max(_e29, _e34);
            }
            memoryBarrierShared();
            barrier();
        }
    }
    if ((li_1 == 0u)) {
        vec3 _e44 = wg_lo[0];
        vec3 _e47 = wg_hi[0];
        wg_box = WorkgroupBox(_e44, _e47);
    }
    memoryBarrierShared();
    barrier();
    WorkgroupBox _e50 = wg_box;
    memoryBarrierShared();
    barrier();
    return _e50;
}

float near_r2_of(uint slot_1) {
    float _e3 = _group_0_binding_2_cs[slot_1];
    float _e5 = vpl_near_range2_(_e3, P);
    return _e5;
}

float near_cull_r2_of(uint slot_2, float near_r2_1) {
    float _e2 = near_r2_of(slot_2);
    float _e3 = vpl_near_cull_range2_(_e2, near_r2_1);
    return _e3;
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_lo = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_hi = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_box = WorkgroupBox(vec3(0.0), vec3(0.0));
    }
    memoryBarrierShared();
    barrier();
    uvec3 wg = gl_WorkGroupID;
    uvec3 nwg = gl_NumWorkGroups;
    uint li = gl_LocalInvocationIndex;
    uint slot = 0u;
    uint out_ = 0u;
    float r2_cull = 0.0;
    uint c = ((wg.y * nwg.x) + wg.x);
    uint far = _group_0_binding_0_cs.far_groups_at;
    uint _e13 = _group_0_binding_0_cs.near_groups_at;
    uint _e16 = _group_0_binding_0_cs.near_clusters_at;
    uint near = (_e13 - _e16);
    if ((c >= (far + near))) {
        return;
    }
    if ((c < far)) {
        slot = ((c * CLUSTER) + li);
        out_ = c;
        uint _e28 = slot;
        float _e30 = _group_0_binding_2_cs[_e28];
        r2_cull = _e30;
    } else {
        uint _e37 = _group_0_binding_3_cs[(((c - far) * CLUSTER) + li)];
        slot = _e37;
        uint _e40 = _group_0_binding_0_cs.near_clusters_at;
        out_ = ((_e40 + c) - far);
        uint _e43 = slot;
        float _e46 = _group_0_binding_0_cs.near_r2_;
        float _e47 = near_cull_r2_of(_e43, _e46);
        r2_cull = _e47;
    }
    uint _e49 = slot;
    GpuLight l = _group_0_binding_1_cs[_e49];
    bool lit = any(notEqual(l.intensity, vec3(0.0)));
    float _e57 = r2_cull;
    float _e58 = cull_radius(_e57);
    WorkgroupBox _e71 = workgroup_bounds(li, (lit ? (l.p0_ - vec3(_e58)) : vec3(3.4028235e38)), (lit ? (l.p0_ + vec3(_e58)) : vec3(-3.4028235e38)));
    if ((li == 0u)) {
        uint _e75 = out_;
        _group_0_binding_4_cs[_e75] = GpuBox(_e71.lo, 0.0, _e71.hi, 0.0);
        return;
    } else {
        return;
    }
}

