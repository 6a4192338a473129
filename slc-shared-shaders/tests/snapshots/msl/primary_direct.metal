// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size5;
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
struct ImageParams {
    metal::packed_float3 eye;
    uint width;
    uint height;
    uint pad0_;
    uint pad1_;
    uint pad2_;
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
typedef metal::float4 type_6[1];
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

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

uint to_u32_(
    float x
) {
    return naga_f2u32(x);
}

float inverse_square(
    float d2_
) {
    return 1.0 / metal::max(d2_, MIN_D2_);
}

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

uint light_map_texel(
    float a_1,
    uint size
) {
    float _e6 = to_f32_(size);
    float _e9 = to_f32_(size);
    uint _e14 = to_u32_(metal::clamp(metal::floor(((a_1 + 1.0) * 0.5) * _e6), 0.0, _e9 - 1.0));
    return _e14;
}

float light_map_coord_at(
    metal::float3 rel,
    metal::float3 dir,
    metal::float3 axis,
    float extent,
    bool perspective
) {
    return metal::dot(rel, dir) / ((perspective ? metal::dot(rel, axis) : 1.0) * extent);
}

float light_map_depth(
    metal::float3 rel_1,
    metal::float3 axis_1,
    bool perspective_1
) {
    return perspective_1 ? metal::sqrt(metal::dot(rel_1, rel_1)) : metal::dot(rel_1, axis_1);
}

metal::float3 point_irradiance(
    metal::float3 intensity,
    metal::float3 n,
    metal::float3 v
) {
    float d2_1 = metal::dot(v, v);
    float cos_x = metal::dot(n, v) / metal::sqrt(metal::max(d2_1, MIN_D2_));
    float _e11 = inverse_square(d2_1);
    return intensity * (metal::max(cos_x, 0.0) * _e11);
}

metal::float3 directional_irradiance(
    metal::float3 e_1,
    metal::float3 n_1,
    metal::float3 to_light
) {
    return e_1 * metal::max(metal::dot(n_1, to_light), 0.0);
}

float perspective_texel_width(
    float extent_1,
    float d,
    float z,
    float size_1
) {
    return (((2.0 * extent_1) * d) * d) / (size_1 * z);
}

float ortho_texel_width(
    float extent_2,
    float size_2
) {
    return (2.0 * extent_2) / size_2;
}

float shadow_bias(
    float texel,
    float cos_light_1
) {
    float c = metal::clamp(cos_light_1, 0.02, 1.0);
    return texel * (1.5 + (metal::sqrt(1.0 - (c * c)) / c));
}

bool shadow_lit(
    float d_1,
    float d_map,
    float bias
) {
    bool local_4 = {};
    if (!((d_map <= 0.0))) {
        local_4 = d_1 <= (d_map + bias);
    } else {
        local_4 = true;
    }
    bool _e11 = local_4;
    return _e11;
}

metal::float3 light_intensity(
    GpuLight l,
    metal::float3 w
) {
    switch(l.kind) {
        case 1u: {
            float _e10 = spot_falloff(metal::dot(l.p1_, w), l.a, l.b, l.p2_[0]);
            return l.intensity * _e10;
        }
        default: {
            return metal::float3(0.0);
        }
    }
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, constant MapParams& params [[user(fake0)]]
, constant ImageParams& image [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> shadow_map [[user(fake0)]]
, device type_6& direct [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    bool local = {};
    bool local_1 = {};
    metal::float3 e = metal::float3(0.0);
    float a = 0.0;
    float b = 0.0;
    float width = 0.0;
    float cos_light = 0.0;
    bool local_2 = {};
    bool local_3 = {};
    uint _e4 = image.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = image.height;
        local = gid.y >= _e12;
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    uint _e19 = image.width;
    uint i = (gid.y * _e19) + gid.x;
    metal::int2 texel_1 = metal::int2(static_cast<int>(gid.x), static_cast<int>(gid.y));
    metal::float4 p = position_tex.read(metal::uint2(texel_1), 0);
    metal::float4 _e33 = normal_tex.read(metal::uint2(texel_1), 0);
    metal::float3 nn = _e33.xyz;
    if (!(!((p.w > 0.0)))) {
        local_1 = metal::dot(nn, nn) <= 0.0;
    } else {
        local_1 = true;
    }
    bool _e46 = local_1;
    if (_e46) {
        direct[i] = metal::float4(0.0);
        return;
    }
    metal::float3 x_1 = p.xyz;
    metal::float3 n_2 = metal::normalize(nn);
    uint _e55 = params.size;
    float size_3 = static_cast<float>(_e55);
    metal::float3 _e66 = params.origin;
    metal::float3 rel_2 = x_1 - _e66;
    metal::float3 _e70 = params.axis;
    uint _e73 = params.mode;
    float _e76 = light_map_depth(rel_2, _e70, _e73 == MAP_PERSPECTIVE);
    uint _e83 = params.mode;
    if (_e83 == MAP_PERSPECTIVE) {
        metal::float3 v_1 = -(rel_2);
        metal::float3 _e89 = params.axis;
        float z_1 = metal::dot(rel_2, _e89);
        if (!((z_1 <= 0.0))) {
            local_2 = _e76 <= 0.0;
        } else {
            local_2 = true;
        }
        bool _e99 = local_2;
        if (_e99) {
            direct[i] = metal::float4(0.0);
            return;
        }
        metal::float3 _e106 = params.right;
        metal::float3 _e109 = params.axis;
        float _e112 = params.extent;
        float _e114 = light_map_coord_at(rel_2, _e106, _e109, _e112, true);
        a = _e114;
        metal::float3 _e117 = params.up;
        metal::float3 _e120 = params.axis;
        float _e123 = params.extent;
        float _e125 = light_map_coord_at(rel_2, _e117, _e120, _e123, true);
        b = _e125;
        float _e128 = params.extent;
        float _e129 = perspective_texel_width(_e128, _e76, z_1, size_3);
        width = _e129;
        cos_light = metal::dot(n_2, v_1) / _e76;
        GpuLight _e134 = params.light;
        metal::float3 _e137 = light_intensity(_e134, rel_2 / metal::float3(_e76));
        metal::float3 _e138 = point_irradiance(_e137, n_2, v_1);
        e = _e138;
    } else {
        metal::float3 _e141 = params.right;
        metal::float3 _e144 = params.axis;
        float _e147 = params.extent;
        float _e149 = light_map_coord_at(rel_2, _e141, _e144, _e147, false);
        a = _e149;
        metal::float3 _e152 = params.up;
        metal::float3 _e155 = params.axis;
        float _e158 = params.extent;
        float _e160 = light_map_coord_at(rel_2, _e152, _e155, _e158, false);
        b = _e160;
        float _e163 = params.extent;
        float _e164 = ortho_texel_width(_e163, size_3);
        width = _e164;
        metal::float3 _e167 = params.axis;
        cos_light = -(metal::dot(n_2, _e167));
        metal::float3 _e173 = params.light.intensity;
        metal::float3 _e176 = params.axis;
        metal::float3 _e178 = directional_irradiance(_e173, n_2, -(_e176));
        e = _e178;
    }
    float _e179 = a;
    if (metal::abs(_e179) <= 1.0) {
        float _e185 = b;
        local_3 = metal::abs(_e185) <= 1.0;
    } else {
        local_3 = false;
    }
    bool _e190 = local_3;
    if (_e190) {
        float _e192 = a;
        uint _e195 = params.size;
        uint _e196 = light_map_texel(_e192, _e195);
        float _e198 = b;
        uint _e201 = params.size;
        uint _e202 = light_map_texel(_e198, _e201);
        metal::float4 _e206 = shadow_map.read(metal::uint2(metal::int2(static_cast<int>(_e196), static_cast<int>(_e202))), 0);
        float d_map_1 = _e206.x;
        float _e208 = width;
        float _e209 = cos_light;
        float _e210 = shadow_bias(_e208, _e209);
        bool _e211 = shadow_lit(_e76, d_map_1, _e210);
        if (!(_e211)) {
            e = metal::float3(0.0);
        }
    }
    metal::float3 _e217 = e;
    direct[i] = metal::float4(_e217, 0.0);
    return;
}
