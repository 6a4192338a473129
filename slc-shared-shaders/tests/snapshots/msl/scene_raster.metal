// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size1;
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
struct GpuMaterial {
    metal::packed_float3 albedo;
    float metallic;
    metal::packed_float3 emission;
    float alpha;
    metal::packed_float3 f0_;
    float f90_;
};
struct MapParams {
    metal::float4 c0_;
    metal::float4 c1_;
    metal::float4 c2_;
    metal::float4 c3_;
    GpuLight light;
    metal::packed_float3 origin;
    uint mode;
    metal::packed_float3 axis;
    uint size;
    metal::packed_float3 right;
    float extent;
    metal::packed_float3 up;
    float texel;
};
typedef GpuMaterial type_5[1];
struct VsOut {
    metal::float4 clip;
    metal::float3 world;
    metal::float3 normal;
    metal::packed_float3 geo;
    uint material;
};
struct GbufferOut {
    metal::float4 position;
    metal::float4 normal;
};
struct RsmOut {
    metal::float4 position;
    metal::float4 normal;
    metal::float4 flux;
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

float spot_falloff(
    float cos_theta,
    float cos_outer,
    float cos_inner,
    float shape
) {
    if (cos_inner <= cos_outer) {
        return (cos_theta >= cos_outer) ? 1.0 : 0.0;
    }
    float t = metal::saturate((cos_theta - cos_outer) / (cos_inner - cos_outer));
    return (shape > 0.5) ? (t * t) : ((t * t) * (3.0 - (2.0 * t)));
}

metal::float3 face_against(
    metal::float3 n,
    metal::float3 dir_1
) {
    return (metal::dot(n, dir_1) > 0.0) ? -(n) : n;
}

metal::float3 shading_normal(
    metal::float3 n0_,
    metal::float3 n1_,
    metal::float3 n2_,
    metal::float3 w,
    metal::float3 facing
) {
    bool local = {};
    metal::float3 s = ((n0_ * w.x) + (n1_ * w.y)) + (n2_ * w.z);
    float l2_ = metal::dot(s, s);
    if (!(!((l2_ > 0.000000000001)))) {
        local = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local = true;
    }
    bool _e24 = local;
    if (_e24) {
        return facing;
    }
    metal::float3 n_1 = s / metal::float3(metal::sqrt(l2_));
    return (metal::dot(n_1, facing) < 0.0) ? -(n_1) : n_1;
}

float light_map_depth(
    metal::float3 rel,
    metal::float3 axis,
    bool perspective
) {
    return perspective ? metal::sqrt(metal::dot(rel, rel)) : metal::dot(rel, axis);
}

float rsm_texel_solid_angle(
    float texel_area,
    float cos_axis
) {
    return ((texel_area * cos_axis) * cos_axis) * cos_axis;
}

metal::float3 light_intensity(
    GpuLight l,
    metal::float3 w_1
) {
    switch(l.kind) {
        case 1u: {
            float _e10 = spot_falloff(metal::dot(l.p1_, w_1), l.a, l.b, l.p2_[0]);
            return l.intensity * _e10;
        }
        default: {
            return metal::float3(0.0);
        }
    }
}

metal::float3 seen_normal(
    VsOut v_3,
    metal::float3 dir_2
) {
    metal::float3 _e12 = face_against(v_3.geo, dir_2);
    metal::float3 _e13 = shading_normal(v_3.normal, metal::float3(0.0), metal::float3(0.0), metal::float3(1.0, 0.0, 0.0), _e12);
    return _e13;
}

struct vs_mainInput {
    metal::float3 position [[attribute(0)]];
    uint material [[attribute(1)]];
    metal::float3 normal [[attribute(2)]];
    metal::float3 geo [[attribute(3)]];
};
struct vs_mainOutput {
    metal::float4 clip [[position]];
    metal::float3 world [[user(loc0), center_perspective]];
    metal::float3 normal [[user(loc1), center_perspective]];
    metal::float3 geo [[user(loc2), flat]];
    uint material [[user(loc3), flat]];
};
vertex vs_mainOutput vs_main(
  vs_mainInput varyings [[stage_in]]
, constant MapParams& params [[user(fake0)]]
) {
    const auto position = varyings.position;
    const auto material = varyings.material;
    const auto normal = varyings.normal;
    const auto geo = varyings.geo;
    metal::float4 _e6 = params.c0_;
    metal::float4 _e9 = params.c1_;
    metal::float4 _e12 = params.c2_;
    metal::float4 _e15 = params.c3_;
    metal::float4x4 m = metal::float4x4(_e6, _e9, _e12, _e15);
    const auto _tmp = VsOut {m * metal::float4(position, 1.0), position, normal, geo, material};
    return vs_mainOutput { _tmp.clip, _tmp.world, _tmp.normal, _tmp.geo, _tmp.material };
}


struct fs_gbufferInput {
    metal::float3 world [[user(loc0), center_perspective]];
    metal::float3 normal_1 [[user(loc1), center_perspective]];
    metal::float3 geo_1 [[user(loc2), flat]];
    uint material_1 [[user(loc3), flat]];
};
struct fs_gbufferOutput {
    metal::float4 position [[color(0)]];
    metal::float4 normal [[color(1)]];
};
fragment fs_gbufferOutput fs_gbuffer(
  fs_gbufferInput varyings_1 [[stage_in]]
, metal::float4 clip [[position]]
, constant MapParams& params [[user(fake0)]]
) {
    const VsOut v = { clip, varyings_1.world, varyings_1.normal_1, varyings_1.geo_1, varyings_1.material_1 };
    metal::float3 _e4 = params.origin;
    metal::float3 _e6 = seen_normal(v, v.world - _e4);
    const auto _tmp_1 = GbufferOut {metal::float4(v.world, 1.0), metal::float4(_e6, static_cast<float>(v.material))};
    return fs_gbufferOutput { _tmp_1.position, _tmp_1.normal };
}


struct fs_rsmInput {
    metal::float3 world [[user(loc0), center_perspective]];
    metal::float3 normal_1 [[user(loc1), center_perspective]];
    metal::float3 geo_1 [[user(loc2), flat]];
    uint material_1 [[user(loc3), flat]];
};
struct fs_rsmOutput {
    metal::float4 position [[color(0)]];
    metal::float4 normal [[color(1)]];
    metal::float4 flux [[color(2)]];
};
fragment fs_rsmOutput fs_rsm(
  fs_rsmInput varyings_2 [[stage_in]]
, metal::float4 clip_1 [[position]]
, constant MapParams& params [[user(fake0)]]
, device type_5 const& materials [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    const VsOut v_1 = { clip_1, varyings_2.world, varyings_2.normal_1, varyings_2.geo_1, varyings_2.material_1 };
    metal::float3 dir = {};
    metal::float3 incident = {};
    metal::float3 _e3 = params.axis;
    dir = _e3;
    metal::float3 _e8 = params.light.intensity;
    float _e11 = params.texel;
    incident = _e8 * _e11;
    uint _e16 = params.mode;
    if (_e16 == MAP_PERSPECTIVE) {
        metal::float3 _e22 = params.origin;
        dir = metal::normalize(v_1.world - _e22);
        GpuLight _e27 = params.light;
        metal::float3 _e28 = dir;
        metal::float3 _e29 = light_intensity(_e27, _e28);
        float _e32 = params.texel;
        metal::float3 _e33 = dir;
        metal::float3 _e36 = params.axis;
        float _e38 = rsm_texel_solid_angle(_e32, metal::dot(_e33, _e36));
        incident = _e29 * _e38;
    }
    metal::float3 albedo = materials[v_1.material].albedo;
    metal::float3 _e48 = dir;
    metal::float3 _e49 = seen_normal(v_1, _e48);
    metal::float3 _e52 = incident;
    const auto _tmp_2 = RsmOut {metal::float4(v_1.world, 1.0), metal::float4(_e49, 0.0), metal::float4(_e52 * albedo, 0.0)};
    return fs_rsmOutput { _tmp_2.position, _tmp_2.normal, _tmp_2.flux };
}


struct fs_shadowInput {
    metal::float3 world [[user(loc0), center_perspective]];
    metal::float3 normal_1 [[user(loc1), center_perspective]];
    metal::float3 geo_1 [[user(loc2), flat]];
    uint material_1 [[user(loc3), flat]];
};
struct fs_shadowOutput {
    metal::float4 member_3 [[color(0)]];
};
fragment fs_shadowOutput fs_shadow(
  fs_shadowInput varyings_3 [[stage_in]]
, metal::float4 clip_2 [[position]]
, constant MapParams& params [[user(fake0)]]
) {
    const VsOut v_2 = { clip_2, varyings_3.world, varyings_3.normal_1, varyings_3.geo_1, varyings_3.material_1 };
    metal::float3 _e4 = params.origin;
    metal::float3 _e8 = params.axis;
    uint _e11 = params.mode;
    float _e14 = light_map_depth(v_2.world - _e4, _e8, _e11 == MAP_PERSPECTIVE);
    return fs_shadowOutput { metal::float4(_e14, 0.0, 0.0, 0.0) };
}
