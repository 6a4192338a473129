#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

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
const uint BOX_THREADS = 64u;

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

shared WorkgroupBox wg_box;

layout(std140) uniform VplParams_block_0Compute { VplParams _group_0_binding_0_cs; };

layout(std430) buffer type_5_block_1Compute { GpuBox _group_0_binding_1_cs[]; };


uint groups_across(uint bw, uint gw) {
    return (((bw + gw) - 1u) / gw);
}

uint group_count(uint bw_1, uint bh, uint gw_1, uint gh) {
    uint _e4 = groups_across(bw_1, gw_1);
    uint _e5 = groups_across(bh, gh);
    return (_e4 * _e5);
}

uint group_first(uint g, uint bw_2, uint bh_1, uint gw_2, uint gh_1) {
    uint _e5 = groups_across(bw_2, gw_2);
    uint gx = (g % _e5);
    uint gy = (g / _e5);
    uint h = min(gh_1, (bh_1 - (gh_1 * gy)));
    return (((gy * gh_1) * bw_2) + ((gx * gw_2) * h));
}

uint group_clusters(uint g_1, uint bw_3, uint bh_2, uint gw_3, uint gh_2) {
    uint _e5 = groups_across(bw_3, gw_3);
    uint gx_1 = (g_1 % _e5);
    uint gy_1 = (g_1 / _e5);
    return (min(gw_3, (bw_3 - (gw_3 * gx_1))) * min(gh_2, (bh_2 - (gh_2 * gy_1))));
}

WorkgroupBox workgroup_bounds(uint li_1, vec3 lo_1, vec3 hi_1) {
    uint stride = 32u;
    wg_lo[li_1] = lo_1;
    wg_hi[li_1] = hi_1;
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
    uvec4 grid = uvec4(0u);
    uint k = 0u;
    uint clusters = 0u;
    uint out_ = 0u;
    vec3 lo = vec3(3.4028235e38);
    vec3 hi = vec3(-3.4028235e38);
    uint g_2 = ((wg.y * nwg.x) + wg.x);
    uint _e10 = _group_0_binding_0_cs.near_clusters_at;
    uint _e13 = _group_0_binding_0_cs.far_groups_at;
    uint far = (_e10 - _e13);
    uint _e17 = _group_0_binding_0_cs.box_count;
    uint _e20 = _group_0_binding_0_cs.near_groups_at;
    uint near = (_e17 - _e20);
    if ((g_2 >= (far + near))) {
        return;
    }
    if ((g_2 < far)) {
        uvec4 _e31 = _group_0_binding_0_cs.far_grid;
        grid = _e31;
        uint _e33 = grid.x;
        uint _e35 = grid.y;
        uint _e37 = grid.z;
        uint _e39 = grid.w;
        uint _e40 = group_count(_e33, _e35, _e37, _e39);
        k = (g_2 % _e40);
        uint _e45 = _group_0_binding_0_cs.lights_per_subset;
        clusters = ((g_2 / _e40) * (_e45 / CLUSTER));
        uint _e51 = _group_0_binding_0_cs.far_groups_at;
        out_ = (_e51 + g_2);
    } else {
        uvec4 _e55 = _group_0_binding_0_cs.near_grid;
        grid = _e55;
        k = (g_2 - far);
        uint _e59 = _group_0_binding_0_cs.near_clusters_at;
        clusters = _e59;
        uint _e62 = _group_0_binding_0_cs.near_groups_at;
        uint _e63 = k;
        out_ = (_e62 + _e63);
    }
    uint _e65 = k;
    uint _e67 = grid.x;
    uint _e69 = grid.y;
    uint _e71 = grid.z;
    uint _e73 = grid.w;
    uint _e74 = group_clusters(_e65, _e67, _e69, _e71, _e73);
    if ((li < _e74)) {
        uint _e83 = clusters;
        uint _e84 = k;
        uint _e86 = grid.x;
        uint _e88 = grid.y;
        uint _e90 = grid.z;
        uint _e92 = grid.w;
        uint _e93 = group_first(_e84, _e86, _e88, _e90, _e92);
        GpuBox b = _group_0_binding_1_cs[((_e83 + _e93) + li)];
        lo = b.lo;
        hi = b.hi;
    }
    vec3 _e100 = lo;
    vec3 _e101 = hi;
    WorkgroupBox _e102 = workgroup_bounds(li, _e100, _e101);
    if ((li == 0u)) {
        uint _e106 = out_;
        _group_0_binding_1_cs[_e106] = GpuBox(_e102.lo, 0.0, _e102.hi, 0.0);
        return;
    } else {
        return;
    }
}

