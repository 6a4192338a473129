// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size4;
    uint size5;
    uint size6;
    uint size7;
};

struct GpuLight {
    metal::packed_float3 p0_;
    uint kind;
    metal::packed_float3 p1_;
    float a;
    metal::packed_float3 p2_;
    float b;
    metal::packed_float3 intensity;
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
    metal::uint4 far_grid;
    metal::uint4 near_grid;
};
struct GpuBox {
    metal::packed_float3 lo;
    float pad0_;
    metal::packed_float3 hi;
    float pad1_;
};
typedef float type_4[1];
struct type_5 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
};
typedef GpuLight type_6[1];
typedef uint type_7[1];
typedef GpuBox type_8[1];
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
constant uint P = 8u;
constant uint BOX_THREADS = 64u;

float to_f32_(
    uint u
) {
    return static_cast<float>(u);
}

float cull_radius(
    float r2_
) {
    return metal::sqrt(r2_) * CULL_RADIUS_SCALE;
}

float interleave_flux_scale(
    uint period
) {
    float _e2 = to_f32_(period * period);
    return _e2;
}

float vpl_near_range2_(
    float r2_1,
    uint period_1
) {
    float _e2 = interleave_flux_scale(period_1);
    return r2_1 / _e2;
}

float vpl_near_cull_range2_(
    float r2_2,
    float near_r2_
) {
    return metal::min(r2_2, near_r2_);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

WorkgroupBox workgroup_bounds(
    uint li_1,
    metal::float3 lo,
    metal::float3 hi,
    threadgroup type_5& wg_lo,
    threadgroup type_5& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    uint stride = 32u;
    wg_lo.inner[li_1] = lo;
    wg_hi.inner[li_1] = hi;
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

float near_r2_of(
    uint slot_1,
    device type_4 const& r2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e3 = r2_3[slot_1];
    float _e5 = vpl_near_range2_(_e3, P);
    return _e5;
}

float near_cull_r2_of(
    uint slot_2,
    float near_r2_1,
    device type_4 const& r2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e2 = near_r2_of(slot_2, r2_3, _buffer_sizes);
    float _e3 = vpl_near_cull_range2_(_e2, near_r2_1);
    return _e3;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 wg [[threadgroup_position_in_grid]]
, metal::uint3 nwg [[threadgroups_per_grid]]
, uint li [[thread_index_in_threadgroup]]
, threadgroup type_5& wg_lo
, threadgroup type_5& wg_hi
, threadgroup WorkgroupBox& wg_box
, constant VplParams& params [[user(fake0)]]
, device type_6 const& lights [[user(fake0)]]
, device type_4 const& r2_3 [[user(fake0)]]
, device type_7 const& near_slots [[user(fake0)]]
, device type_8& boxes [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    if (li == 0u) {
        wg_lo = {};
        wg_hi = {};
        wg_box = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint slot = {};
    uint out = {};
    float r2_cull = {};
    uint c = (wg.y * nwg.x) + wg.x;
    uint far = params.far_groups_at;
    uint _e13 = params.near_groups_at;
    uint _e16 = params.near_clusters_at;
    uint near = _e13 - _e16;
    if (c >= (far + near)) {
        return;
    }
    if (c < far) {
        slot = (c * CLUSTER) + li;
        out = c;
        uint _e28 = slot;
        float _e30 = r2_3[_e28];
        r2_cull = _e30;
    } else {
        uint _e37 = near_slots[((c - far) * CLUSTER) + li];
        slot = _e37;
        uint _e40 = params.near_clusters_at;
        out = (_e40 + c) - far;
        uint _e43 = slot;
        float _e46 = params.near_r2_;
        float _e47 = near_cull_r2_of(_e43, _e46, r2_3, _buffer_sizes);
        r2_cull = _e47;
    }
    uint _e49 = slot;
    GpuLight l = lights[_e49];
    bool lit = metal::any(l.intensity != metal::float3(0.0));
    float _e57 = r2_cull;
    float _e58 = cull_radius(_e57);
    WorkgroupBox _e71 = workgroup_bounds(li, lit ? (l.p0_ - metal::float3(_e58)) : metal::float3(340282350000000000000000000000000000000.0), lit ? (l.p0_ + metal::float3(_e58)) : metal::float3(-340282350000000000000000000000000000000.0), wg_lo, wg_hi, wg_box);
    if (li == 0u) {
        uint _e75 = out;
        boxes[_e75] = GpuBox {_e71.lo, 0.0, _e71.hi, 0.0};
        return;
    } else {
        return;
    }
}
