// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size1;
    uint size2;
    uint size3;
    uint size4;
    uint size5;
    uint size6;
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
struct GpuVplRecord {
    metal::packed_float3 position;
    float pad0_;
    metal::packed_float3 normal;
    float pad1_;
    metal::packed_float3 flux;
    float pad2_;
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
typedef float type_3[1];
typedef GpuVplRecord type_5[1];
typedef GpuLight type_6[1];
typedef uint type_7[1];
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

float threshold_range2_(
    float intensity,
    float exposure,
    float error_bound
) {
    if (intensity <= 0.0) {
        return 0.0;
    }
    return ((exposure / error_bound) * intensity) / TWO_PI;
}

float intensity_measure(
    metal::float3 rgb,
    uint mode
) {
    if (mode == 1u) {
        return ((rgb.x + rgb.y) + rgb.z) / 3.0;
    }
    return metal::max(rgb.x, metal::max(rgb.y, rgb.z));
}

float vpl_rt2_(
    metal::float3 flux_1,
    float exposure_1,
    float error_bound_1,
    uint mode_1
) {
    float _e6 = intensity_measure(flux_1 * INV_PI, mode_1);
    float _e7 = threshold_range2_(_e6, exposure_1, error_bound_1);
    return _e7;
}

bool finite3_(
    metal::float3 v
) {
    bool local = {};
    bool local_1 = {};
    if (metal::abs(v.x) <= F32_MAX) {
        local = metal::abs(v.y) <= F32_MAX;
    } else {
        local = false;
    }
    bool _e12 = local;
    if (_e12) {
        local_1 = metal::abs(v.z) <= F32_MAX;
    } else {
        local_1 = false;
    }
    bool _e20 = local_1;
    return _e20;
}

bool vpl_record_ok(
    metal::float3 position,
    metal::float3 normal_1,
    metal::float3 flux_2
) {
    bool local_2 = {};
    bool local_3 = {};
    bool local_4 = {};
    bool local_5 = {};
    bool local_6 = {};
    bool _e3 = finite3_(position);
    if (_e3) {
        bool _e6 = finite3_(normal_1);
        local_2 = _e6;
    } else {
        local_2 = false;
    }
    bool _e8 = local_2;
    if (_e8) {
        bool _e11 = finite3_(flux_2);
        local_3 = _e11;
    } else {
        local_3 = false;
    }
    bool _e13 = local_3;
    if (!(_e13)) {
        return false;
    }
    if (flux_2.x >= 0.0) {
        local_4 = flux_2.y >= 0.0;
    } else {
        local_4 = false;
    }
    bool _e25 = local_4;
    if (_e25) {
        local_5 = flux_2.z >= 0.0;
    } else {
        local_5 = false;
    }
    bool _e32 = local_5;
    if (_e32) {
        local_6 = (metal::max(metal::max(flux_2.x, flux_2.y), flux_2.z) * INV_PI) <= MAX_INTENSITY;
    } else {
        local_6 = false;
    }
    bool _e45 = local_6;
    return _e45;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

uint interleave_slot_linear(
    uint i,
    uint per_subset,
    uint period
) {
    uint subsets = period * period;
    return (naga_mod(i, subsets) * per_subset) + naga_div(i, subsets);
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, constant PackParams& params [[user(fake0)]]
, device type_5 const& records [[user(fake0)]]
, device type_6& lights [[user(fake0)]]
, device type_7& ids [[user(fake0)]]
, device type_3& rt2_ [[user(fake0)]]
, device type_3& r2_ [[user(fake0)]]
, device type_7& near_slots [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    metal::float3 p = {};
    metal::float3 normal = {};
    metal::float3 flux = {};
    uint i_1 = gid.x;
    uint _e4 = params.count;
    if (i_1 >= _e4) {
        return;
    }
    GpuVplRecord r = records[i_1];
    p = r.position;
    normal = r.normal;
    flux = r.flux;
    uint _e17 = params.per_subset;
    uint _e19 = interleave_slot_linear(i_1, _e17, P);
    metal::float3 _e20 = p;
    metal::float3 _e21 = normal;
    metal::float3 _e22 = flux;
    bool _e23 = vpl_record_ok(_e20, _e21, _e22);
    if (!(_e23)) {
        p = metal::float3(0.0);
        normal = metal::float3(0.0);
        flux = metal::float3(0.0);
    }
    metal::float3 _e31 = flux;
    float _e34 = params.scale;
    flux = _e31 * _e34;
    metal::float3 _e38 = p;
    metal::float3 _e40 = normal;
    metal::float3 _e43 = flux;
    lights[_e19] = GpuLight {_e38, LIGHT_VPL, _e40, 0.0, metal::float3(0.0), 0.0, _e43, 0u};
    ids[_e19] = i_1;
    uint _e52 = params.slc;
    bool slc = _e52 != 0u;
    metal::float3 _e57 = flux;
    float _e60 = params.exposure;
    float _e63 = params.error_bound;
    uint _e66 = params.mode;
    float _e67 = vpl_rt2_(_e57, _e60, _e63, _e66);
    rt2_[_e19] = slc ? _e67 : 0.0;
    float _e74 = params.fixed_r2_;
    r2_[_e19] = slc ? 0.0 : _e74;
    near_slots[i_1] = _e19;
    return;
}
