// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size4;
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
    metal::uint4 far_grid;
    metal::uint4 near_grid;
};
struct GpuBox {
    metal::packed_float3 lo;
    float pad0_;
    metal::packed_float3 hi;
    float pad1_;
};
struct type_4 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
};
typedef GpuBox type_5[1];
constant uint LIGHT_POINT = 0u;
constant uint LIGHT_SPOT = 1u;
constant uint LIGHT_IES = 2u;
constant uint LIGHT_TRIANGLE = 3u;
constant uint LIGHT_VPL = 4u;
constant uint NO_LIGHT = 4294967295u;
constant uint GRID_HEADER = 32u;
constant uint GRID_LEVELS_MAX = 8u;
constant uint GRIDS_MAX = 3u;
constant uint GRID_SORT_MOVES = 1024u;
constant uint GRID_SORT_MAX = 1024u;
constant uint COUNT_TILES = 0u;
constant uint COUNT_GROUP_TESTS = 1u;
constant uint COUNT_CLUSTER_TESTS = 2u;
constant uint COUNT_SPHERE_TESTS = 3u;
constant uint COUNT_TESTED = 4u;
constant uint COUNT_KEPT = 5u;
constant uint COUNT_PIXELS = 6u;
constant uint COUNT_FIELDS = 7u;
constant uint DIRECT_COUNT_PIXELS = 0u;
constant uint DIRECT_COUNT_CANDIDATES = 1u;
constant uint DIRECT_COUNT_EVALUATIONS = 2u;
constant uint DIRECT_COUNT_RAYS = 3u;
constant uint DIRECT_COUNT_NODES = 4u;
constant uint DIRECT_COUNT_FIELDS = 5u;
constant uint MAP_CAMERA = 0u;
constant uint MAP_PERSPECTIVE = 1u;
constant uint MAP_ORTHOGRAPHIC = 2u;
constant float XI_STEP = 0.000000059604645;
constant uint XI_ROTATED = 2147483648u;
constant uint XI_BITS_SHIFT = 26u;
constant uint XI_INDEX_MASK = 67108863u;
constant uint PICK_STREAM = 2654435769u;
constant float TWO_PI = 6.2831855;
constant float UNRANGED = 100000000000000000000000000000000000000.0;
constant float CULL_RADIUS_SCALE = 1.000001;
constant float SPHERE_PAD = 0.00000047683716;
constant float SPHERE_HUGE = 340282350000000000000000000000000000000.0;
constant float SPHERE_PAD_ABS = 0.000000000000000001;
constant uint CLUSTER = 64u;
constant uint GROUP_SIDE = 8u;
constant float INV_PI = 0.31830987;
constant float MIN_D2_ = 0.000000000001;
constant float MAX_INTENSITY = 72057594000000000.0;
constant uint BSH_NONE = 4294967295u;
constant uint BSH_TAIL = 2147483648u;
constant uint BSH_TAIL_BINS = 1024u;
constant uint BSH_TAIL_MAX = 64u;
constant uint RESERVOIR_FULL = 4294967295u;
constant float REUSE_TRUST_SCALE = 64.0;
constant float GGX_ALPHA_MIN = 0.001;
constant float RANGE_SCALE_MAX = 64.0;
constant uint LIGHT_BVH_LEAF = 4294967295u;
constant float ONE_MINUS_EPSILON = 0.99999994;
constant float F32_MAX = 340282350000000000000000000000000000000.0;
constant float DEPTH_NONE = 1000000000000000000000000000000.0;
constant float DEPTH_SIGMA = 0.05;
constant float COVER_WEIGHT = 0.1;
constant uint ROULETTE_DEPTH = 2u;
constant float TEMPORAL_MAX_HISTORY = 32.0;
constant float TEMPORAL_DEPTH_TOLERANCE = 0.01;
constant float TEMPORAL_MOTION_DEPTH_TOLERANCE = 0.05;
constant float TEMPORAL_NORMAL_COS = 0.9;
constant float TEMPORAL_MIN_MOMENTS = 8.0;
constant float TEMPORAL_CHANGED_HISTORY = 1.0;
constant float TEMPORAL_CHANGE_LOW = 4.0;
constant float TEMPORAL_CHANGE_HIGH = 8.0;
constant float TEMPORAL_MIN_WEIGHT = 0.01;
constant uint BOX_THREADS = 64u;

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

uint groups_across(
    uint bw,
    uint gw
) {
    return naga_div((bw + gw) - 1u, gw);
}

uint group_count(
    uint bw_1,
    uint bh,
    uint gw_1,
    uint gh
) {
    uint _e4 = groups_across(bw_1, gw_1);
    uint _e5 = groups_across(bh, gh);
    return _e4 * _e5;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint group_first(
    uint g,
    uint bw_2,
    uint bh_1,
    uint gw_2,
    uint gh_1
) {
    uint _e5 = groups_across(bw_2, gw_2);
    uint gx = naga_mod(g, _e5);
    uint gy = naga_div(g, _e5);
    uint h = metal::min(gh_1, bh_1 - (gh_1 * gy));
    return ((gy * gh_1) * bw_2) + ((gx * gw_2) * h);
}

uint group_clusters(
    uint g_1,
    uint bw_3,
    uint bh_2,
    uint gw_3,
    uint gh_2
) {
    uint _e5 = groups_across(bw_3, gw_3);
    uint gx_1 = naga_mod(g_1, _e5);
    uint gy_1 = naga_div(g_1, _e5);
    return metal::min(gw_3, bw_3 - (gw_3 * gx_1)) * metal::min(gh_2, bh_2 - (gh_2 * gy_1));
}

WorkgroupBox workgroup_bounds(
    uint li_1,
    metal::float3 lo_1,
    metal::float3 hi_1,
    threadgroup type_4& wg_lo,
    threadgroup type_4& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    uint stride = 32u;
    wg_lo.inner[li_1] = lo_1;
    wg_hi.inner[li_1] = hi_1;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e36 = stride;
            stride = naga_div(_e36, 2u);
        }
        loop_init = false;
        uint _e9 = stride;
        if (_e9 > 0u) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if (li_1 < _e12) {
                metal::float3 _e18 = wg_lo.inner[li_1];
                uint _e20 = stride;
                metal::float3 _e23 = wg_lo.inner[li_1 + _e20];
                wg_lo.inner[li_1] = metal::min(_e18, _e23);
                metal::float3 _e29 = wg_hi.inner[li_1];
                uint _e31 = stride;
                metal::float3 _e34 = wg_hi.inner[li_1 + _e31];
                wg_hi.inner[li_1] = metal::max(_e29, _e34);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (li_1 == 0u) {
        metal::float3 _e44 = wg_lo.inner[0];
        metal::float3 _e47 = wg_hi.inner[0];
        wg_box = WorkgroupBox {_e44, _e47};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    WorkgroupBox unnamed = wg_box;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return unnamed;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 wg [[threadgroup_position_in_grid]]
, metal::uint3 nwg [[threadgroups_per_grid]]
, uint li [[thread_index_in_threadgroup]]
, threadgroup type_4& wg_lo
, threadgroup type_4& wg_hi
, threadgroup WorkgroupBox& wg_box
, constant VplParams& params [[user(fake0)]]
, device type_5& boxes [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    if (li == 0u) {
        wg_lo = {};
        wg_hi = {};
        wg_box = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    metal::uint4 grid = {};
    uint k = {};
    uint clusters = {};
    uint out = {};
    metal::float3 lo = metal::float3(340282350000000000000000000000000000000.0);
    metal::float3 hi = metal::float3(-340282350000000000000000000000000000000.0);
    uint g_2 = (wg.y * nwg.x) + wg.x;
    uint _e10 = params.near_clusters_at;
    uint _e13 = params.far_groups_at;
    uint far = _e10 - _e13;
    uint _e17 = params.box_count;
    uint _e20 = params.near_groups_at;
    uint near = _e17 - _e20;
    if (g_2 >= (far + near)) {
        return;
    }
    if (g_2 < far) {
        metal::uint4 _e31 = params.far_grid;
        grid = _e31;
        uint _e33 = grid.x;
        uint _e35 = grid.y;
        uint _e37 = grid.z;
        uint _e39 = grid.w;
        uint _e40 = group_count(_e33, _e35, _e37, _e39);
        k = naga_mod(g_2, _e40);
        uint _e45 = params.lights_per_subset;
        clusters = naga_div(g_2, _e40) * naga_div(_e45, CLUSTER);
        uint _e51 = params.far_groups_at;
        out = _e51 + g_2;
    } else {
        metal::uint4 _e55 = params.near_grid;
        grid = _e55;
        k = g_2 - far;
        uint _e59 = params.near_clusters_at;
        clusters = _e59;
        uint _e62 = params.near_groups_at;
        uint _e63 = k;
        out = _e62 + _e63;
    }
    uint _e65 = k;
    uint _e67 = grid.x;
    uint _e69 = grid.y;
    uint _e71 = grid.z;
    uint _e73 = grid.w;
    uint _e74 = group_clusters(_e65, _e67, _e69, _e71, _e73);
    if (li < _e74) {
        uint _e83 = clusters;
        uint _e84 = k;
        uint _e86 = grid.x;
        uint _e88 = grid.y;
        uint _e90 = grid.z;
        uint _e92 = grid.w;
        uint _e93 = group_first(_e84, _e86, _e88, _e90, _e92);
        GpuBox b = boxes[(_e83 + _e93) + li];
        lo = b.lo;
        hi = b.hi;
    }
    metal::float3 _e100 = lo;
    metal::float3 _e101 = hi;
    WorkgroupBox _e102 = workgroup_bounds(li, _e100, _e101, wg_lo, wg_hi, wg_box);
    if (li == 0u) {
        uint _e106 = out;
        boxes[_e106] = GpuBox {_e102.lo, 0.0, _e102.hi, 0.0};
        return;
    } else {
        return;
    }
}
