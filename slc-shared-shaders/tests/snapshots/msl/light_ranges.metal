// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size1;
    uint size2;
    uint size3;
};

struct CullParams {
    uint light_count;
    uint seed;
    uint frame;
    uint slc;
    uint mode;
    float exposure;
    float error_bound;
    float fixed_r2_;
    float unculled;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};
typedef float type_4[1];
typedef metal::float4 type_5[1];
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

float to_f32_(
    uint u
) {
    return static_cast<float>(u);
}

uint mul_lo_u32_(
    uint a,
    uint b
) {
    return a * b;
}

uint add_wrap_u32_(
    uint a_1,
    uint b_1
) {
    return a_1 + b_1;
}

float xi_from_bits(
    uint bits
) {
    float _e3 = to_f32_(bits >> 8u);
    return _e3 * XI_STEP;
}

uint pcg_hash(
    uint x
) {
    uint _e2 = mul_lo_u32_(x, 747796405u);
    uint _e4 = add_wrap_u32_(_e2, 2891336453u);
    uint _e12 = mul_lo_u32_((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4, 277803737u);
    return (_e12 >> 22u) ^ _e12;
}

uint laine_karras(
    uint x_1,
    uint seed
) {
    uint v = {};
    uint _e2 = add_wrap_u32_(x_1, seed);
    v = _e2;
    uint _e4 = v;
    uint _e5 = v;
    uint _e7 = mul_lo_u32_(_e5, 1817228412u);
    v = _e4 ^ _e7;
    uint _e9 = v;
    uint _e10 = v;
    uint _e12 = mul_lo_u32_(_e10, 3090095698u);
    v = _e9 ^ _e12;
    uint _e14 = v;
    uint _e15 = v;
    uint _e17 = mul_lo_u32_(_e15, 3350193720u);
    v = _e14 ^ _e17;
    uint _e19 = v;
    uint _e20 = v;
    uint _e22 = mul_lo_u32_(_e20, 2367878886u);
    v = _e19 ^ _e22;
    uint _e24 = v;
    return _e24;
}

uint reverse_bits(
    uint x_2
) {
    uint v_1 = {};
    v_1 = ((x_2 >> 16u) & 65535u) | ((x_2 & 65535u) << 16u);
    uint _e11 = v_1;
    uint _e16 = v_1;
    v_1 = ((_e11 >> 8u) & 16711935u) | ((_e16 & 16711935u) << 8u);
    uint _e22 = v_1;
    uint _e27 = v_1;
    v_1 = ((_e22 >> 4u) & 252645135u) | ((_e27 & 252645135u) << 4u);
    uint _e33 = v_1;
    uint _e38 = v_1;
    v_1 = ((_e33 >> 2u) & 858993459u) | ((_e38 & 858993459u) << 2u);
    uint _e44 = v_1;
    uint _e49 = v_1;
    v_1 = ((_e44 >> 1u) & 1431655765u) | ((_e49 & 1431655765u) << 1u);
    uint _e55 = v_1;
    return _e55;
}

float xi_for(
    uint seed_1,
    uint frame,
    uint light
) {
    uint _e3 = pcg_hash(seed_1);
    uint _e4 = pcg_hash(_e3);
    uint _e6 = pcg_hash(_e4 ^ light);
    uint _e7 = pcg_hash(_e6);
    uint _e8 = reverse_bits(frame);
    uint _e9 = laine_karras(_e8, _e7);
    uint _e11 = laine_karras(0u, _e7);
    uint _e13 = add_wrap_u32_(_e6, _e9 ^ _e11);
    float _e14 = xi_from_bits(_e13);
    return _e14;
}

float random_range2_(
    float rt2_,
    float xi
) {
    return rt2_ / (1.0 - xi);
}

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

float record_rt2_(
    metal::float3 peak,
    uint slc,
    uint mode_1,
    float exposure_1,
    float error_bound_1,
    float unculled
) {
    if (slc == 1u) {
        float _e8 = intensity_measure(peak, mode_1);
        float _e9 = threshold_range2_(_e8, exposure_1, error_bound_1);
        return _e9;
    }
    return unculled;
}

float record_r2_(
    float rt2_1,
    uint slc_1,
    float fixed_r2_,
    float xi_1
) {
    if (slc_1 == 1u) {
        float _e6 = random_range2_(rt2_1, xi_1);
        return _e6;
    }
    return fixed_r2_;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, constant CullParams& params [[user(fake0)]]
, device type_5 const& peaks [[user(fake0)]]
, device type_4& rt2_2 [[user(fake0)]]
, device type_4& r2_ [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint i = gid.x;
    uint _e4 = params.light_count;
    if (i >= _e4) {
        return;
    }
    metal::float4 _e8 = peaks[i];
    uint _e12 = params.slc;
    uint _e15 = params.mode;
    float _e18 = params.exposure;
    float _e21 = params.error_bound;
    float _e24 = params.unculled;
    float _e25 = record_rt2_(_e8.xyz, _e12, _e15, _e18, _e21, _e24);
    rt2_2[i] = _e25;
    uint _e32 = params.slc;
    float _e35 = params.fixed_r2_;
    uint _e38 = params.seed;
    uint _e41 = params.frame;
    float _e42 = xi_for(_e38, _e41, i);
    float _e43 = record_r2_(_e25, _e32, _e35, _e42);
    r2_[i] = _e43;
    return;
}
