// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size1;
    uint size2;
    uint size3;
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
typedef metal::float4 type_6[1];
struct Window {
    metal::packed_float3 sum;
    float weight;
    uint covered;
    char _pad3[12];
};
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
constant uint PERIOD = 8u;

float inv_sigma_z(
    float z
) {
    return 1.0 / (DEPTH_SIGMA * z);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

uint window_start(
    uint x,
    uint size
) {
    uint half_ = naga_div(size, 2u);
    return metal::max(x, half_) - half_;
}

uint window_end(
    uint x_1,
    uint size_1,
    uint extent
) {
    return metal::min((x_1 + size_1) - naga_div(size_1, 2u), extent);
}

uint wide_window(
    uint period
) {
    return 2u * period;
}

bool misses_subset(
    uint covered,
    uint period_1
) {
    return covered < (period_1 * period_1);
}

metal::float3 filtered_irradiance(
    metal::float3 e,
    metal::float3 sum,
    float weight
) {
    if (weight > 0.0) {
        return sum / metal::float3(weight);
    }
    return e;
}

float bilateral_weight(
    metal::float3 n,
    metal::float3 nj,
    float z_1,
    float zj,
    float inv_sz
) {
    float dn = metal::max(metal::dot(n, nj), 0.0);
    float dn2_ = dn * dn;
    float dn4_ = dn2_ * dn2_;
    float dn8_ = dn4_ * dn4_;
    float d = (zj - z_1) * inv_sz;
    float t = metal::max(1.0 - (d * d), 0.0);
    return ((dn8_ * dn8_) * t) * t;
}

Window window_sum(
    uint x_2,
    uint y,
    uint size_2,
    metal::float3 n_1,
    float z_2,
    float inv,
    constant VplParams& params,
    device type_6 const& guide,
    device type_6 const& irradiance,
    constant _mslBufferSizes& _buffer_sizes
) {
    Window win = {};
    uint yy = {};
    uint xx = {};
    uint w = params.width;
    uint h = params.height;
    uint _e12 = window_start(x_2, size_2);
    uint _e13 = window_end(x_2, size_2, w);
    uint _e14 = window_start(y, size_2);
    uint _e15 = window_end(y, size_2, h);
    win.sum = metal::float3(0.0);
    win.weight = 0.0;
    win.covered = 0u;
    yy = _e14;
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e63 = yy;
            yy = _e63 + 1u;
        }
        loop_init = false;
        uint _e25 = yy;
        if (_e25 < _e15) {
        } else {
            break;
        }
        {
            xx = _e12;
            uint2 loop_bound_1 = uint2(4294967295u);
            bool loop_init_1 = true;
            while(true) {
                if (metal::all(loop_bound_1 == uint2(0u))) { break; }
                loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                if (!loop_init_1) {
                    uint _e60 = xx;
                    xx = _e60 + 1u;
                }
                loop_init_1 = false;
                uint _e28 = xx;
                if (_e28 < _e13) {
                } else {
                    break;
                }
                {
                    uint _e30 = yy;
                    uint _e32 = xx;
                    uint j = (_e30 * w) + _e32;
                    metal::float4 g = guide[j];
                    float _e39 = bilateral_weight(n_1, g.xyz, z_2, g.w, inv);
                    metal::float3 _e41 = win.sum;
                    metal::float4 _e44 = irradiance[j];
                    win.sum = _e41 + (_e44.xyz * _e39);
                    float _e49 = win.weight;
                    win.weight = _e49 + _e39;
                    uint _e52 = win.covered;
                    win.covered = _e52 + ((_e39 > COVER_WEIGHT) ? 1u : 0u);
                }
            }
        }
    }
    Window _e65 = win;
    return _e65;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, constant VplParams& params [[user(fake0)]]
, device type_6 const& guide [[user(fake0)]]
, device type_6 const& irradiance [[user(fake0)]]
, device type_6& filtered [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    bool local = {};
    Window s = {};
    uint w_1 = params.width;
    uint h_1 = params.height;
    if (!((gid.x >= w_1))) {
        local = gid.y >= h_1;
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    uint i = (gid.y * w_1) + gid.x;
    metal::float4 e_1 = irradiance[i];
    metal::float4 g_1 = guide[i];
    if (metal::all(g_1.xyz == metal::float3(0.0))) {
        filtered[i] = metal::float4(0.0, 0.0, 0.0, e_1.w);
        return;
    }
    metal::float3 n_2 = g_1.xyz;
    float z_3 = g_1.w;
    float _e40 = inv_sigma_z(z_3);
    Window _e44 = window_sum(gid.x, gid.y, PERIOD, n_2, z_3, _e40, params, guide, irradiance, _buffer_sizes);
    s = _e44;
    uint _e47 = s.covered;
    bool _e49 = misses_subset(_e47, PERIOD);
    if (_e49) {
        uint _e53 = wide_window(PERIOD);
        Window _e54 = window_sum(gid.x, gid.y, _e53, n_2, z_3, _e40, params, guide, irradiance, _buffer_sizes);
        s = _e54;
    }
    metal::float3 _e59 = s.sum;
    float _e61 = s.weight;
    metal::float3 _e62 = filtered_irradiance(e_1.xyz, _e59, _e61);
    filtered[i] = metal::float4(_e62, e_1.w);
    return;
}
