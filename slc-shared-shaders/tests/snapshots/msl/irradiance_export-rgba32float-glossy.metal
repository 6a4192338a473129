// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size3;
    uint size5;
};

struct ViewParams {
    metal::float4 c0_;
    metal::float4 c1_;
    metal::float4 c2_;
    metal::float4 c3_;
    metal::packed_float3 eye;
    uint width;
    uint height;
    float shadow_offset;
    uint seed;
    uint frame;
    metal::packed_float3 f0_d;
    float f90_d;
};
typedef metal::float4 type_6[1];
struct GbTexel {
    metal::float4 position;
    metal::float4 normal;
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

metal::float4 surface_at(
    metal::int2 texel,
    metal::texture2d<float, metal::access::sample> position_tex
) {
    metal::float4 p = position_tex.read(metal::uint2(texel), 0);
    return (p.w > 0.0) ? metal::float4(p.xyz, 1.0) : metal::float4(0.0);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

GbTexel gbuffer_at(
    uint i,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> position_tex,
    metal::texture2d<float, metal::access::sample> normal_tex
) {
    bool local_1 = {};
    uint _e3 = view.width;
    uint _e8 = view.width;
    metal::int2 texel_1 = metal::int2(static_cast<int>(naga_mod(i, _e3)), static_cast<int>(naga_div(i, _e8)));
    metal::float4 _e12 = surface_at(texel_1, position_tex);
    metal::float4 _e15 = normal_tex.read(metal::uint2(texel_1), 0);
    metal::float3 n = _e15.xyz;
    float len2_ = metal::dot(n, n);
    if (_e12.w > 0.0) {
        local_1 = len2_ > 0.0;
    } else {
        local_1 = false;
    }
    bool valid = local_1;
    metal::float3 _e30 = view.eye;
    metal::float3 v = _e12.xyz - _e30;
    metal::float4 position = metal::float4(_e12.xyz, valid ? 1.0 : 0.0);
    metal::float4 normal = valid ? metal::float4(n / metal::float3(metal::sqrt(len2_)), metal::sqrt(metal::dot(v, v))) : metal::float4(0.0, 0.0, 0.0, 1000000000000000000000000000000.0);
    return GbTexel {position, normal};
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, constant ViewParams& view [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, device type_6 const& irradiance [[user(fake0)]]
, metal::texture2d<float, metal::access::write> out_tex [[user(fake0)]]
, device type_6 const& specular [[user(fake0)]]
, metal::texture2d<float, metal::access::write> specular_tex [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    bool local = {};
    uint _e4 = view.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = view.height;
        local = gid.y >= _e12;
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    uint _e19 = view.width;
    uint i_1 = (gid.y * _e19) + gid.x;
    GbTexel _e23 = gbuffer_at(i_1, view, position_tex, normal_tex);
    bool valid_1 = _e23.position.w > 0.0;
    metal::float4 _e32 = irradiance[i_1];
    metal::float4 e = valid_1 ? _e32 : metal::float4(0.0);
    out_tex.write(e, metal::uint2(metal::int2(static_cast<int>(gid.x), static_cast<int>(gid.y))));
    metal::float4 _e44 = specular[i_1];
    metal::float4 s = valid_1 ? _e44 : metal::float4(0.0);
    specular_tex.write(metal::float4(s.xyz, 0.0), metal::uint2(metal::int2(static_cast<int>(gid.x), static_cast<int>(gid.y))));
    return;
}
