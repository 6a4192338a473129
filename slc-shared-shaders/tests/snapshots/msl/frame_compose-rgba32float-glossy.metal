// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size4;
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
typedef metal::float4 type_6[1];
typedef GpuMaterial type_7[1];
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

float ggx_d(
    float cos_h,
    float sin2_h,
    float alpha
) {
    if (cos_h <= 0.0) {
        return 0.0;
    }
    float a2_ = alpha * alpha;
    float t = ((cos_h * cos_h) * a2_) + sin2_h;
    return (a2_ * INV_PI) / (t * t);
}

float smith_root(
    float cos,
    float alpha_1
) {
    float a2_1 = alpha_1 * alpha_1;
    return metal::sqrt(((cos * cos) * (1.0 - a2_1)) + a2_1);
}

float smith_visibility(
    float n_l,
    float n_v,
    float alpha_2
) {
    bool local_1 = {};
    if (!((n_l <= 0.0))) {
        local_1 = n_v <= 0.0;
    } else {
        local_1 = true;
    }
    bool _e11 = local_1;
    if (_e11) {
        return 0.0;
    }
    float _e13 = smith_root(n_v, alpha_2);
    float _e15 = smith_root(n_l, alpha_2);
    return 0.5 / ((n_l * _e13) + (n_v * _e15));
}

metal::float3 fresnel_schlick(
    metal::float3 f0_,
    float f90_,
    float v_h
) {
    float c = metal::saturate(1.0 - v_h);
    float c2_ = c * c;
    return f0_ + ((metal::float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c));
}

metal::float3 specular_fresnel(
    metal::float3 base,
    float metallic,
    metal::float3 f0_d,
    float f90_d,
    float v_h_1
) {
    metal::float3 _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    metal::float3 _e10 = fresnel_schlick(base, 1.0, v_h_1);
    return (_e5 * (1.0 - metallic)) + (_e10 * metallic);
}

metal::float3 diffuse_brdf(
    metal::float3 base_1,
    float metallic_1,
    metal::float3 f0_d_1,
    float f90_d_1,
    float v_h_2
) {
    metal::float3 _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return (((metal::float3(1.0, 1.0, 1.0) - _e9) * base_1) * (1.0 - metallic_1)) * INV_PI;
}

float half_cosine(
    metal::float3 v,
    metal::float3 l
) {
    metal::float3 h = v + l;
    float len2_ = metal::dot(h, h);
    if (len2_ <= 0.0) {
        return 0.0;
    }
    return metal::saturate(metal::dot(v, h) / metal::sqrt(len2_));
}

metal::float3 specular_brdf(
    metal::float3 base_2,
    float metallic_2,
    metal::float3 f0_d_2,
    float f90_d_2,
    float alpha_3,
    metal::float3 n,
    metal::float3 v_1,
    metal::float3 l_1
) {
    bool local_2 = {};
    float n_l_1 = metal::dot(n, l_1);
    float n_v_1 = metal::dot(n, v_1);
    if (!((n_l_1 <= 0.0))) {
        local_2 = n_v_1 <= 0.0;
    } else {
        local_2 = true;
    }
    bool _e18 = local_2;
    if (_e18) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    metal::float3 hs = v_1 + l_1;
    float inv = 1.0 / metal::sqrt(metal::dot(hs, hs));
    metal::float3 h_1 = hs * inv;
    metal::float3 c_1 = metal::cross(n, h_1);
    float _e32 = ggx_d(metal::dot(n, h_1), metal::dot(c_1, c_1), alpha_3);
    metal::float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, metal::dot(v_1, h_1));
    float _e35 = smith_visibility(n_l_1, n_v_1, alpha_3);
    return _e34 * (_e32 * _e35);
}

metal::float3 brdf_eval(
    metal::float3 base_3,
    float metallic_3,
    metal::float3 f0_d_3,
    float f90_d_3,
    float alpha_4,
    metal::float3 n_1,
    metal::float3 v_2,
    metal::float3 l_2
) {
    if (metal::dot(n_1, l_2) <= 0.0) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    float _e15 = half_cosine(v_2, l_2);
    metal::float3 _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    metal::float3 _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_1, v_2, l_2);
    return _e16 + _e17;
}

metal::float3 diffuse_albedo(
    metal::float3 base_4,
    float metallic_4
) {
    return base_4 * (1.0 - metallic_4);
}

bool has_specular(
    float metallic_5,
    metal::float3 f0_d_4,
    float f90_d_4
) {
    bool local_3 = {};
    bool local_4 = {};
    if (!((metallic_5 > 0.0))) {
        local_3 = f90_d_4 > 0.0;
    } else {
        local_3 = true;
    }
    bool _e11 = local_3;
    if (!(_e11)) {
        local_4 = metal::max(metal::max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0.0;
    } else {
        local_4 = true;
    }
    bool _e23 = local_4;
    return _e23;
}

metal::float3 diffuse_radiance(
    metal::float3 albedo,
    metal::float3 emission,
    metal::float3 e
) {
    return emission + ((albedo * INV_PI) * e);
}

metal::float3 primary_light_dir(
    metal::float3 x,
    metal::float3 origin,
    metal::float3 axis,
    bool perspective
) {
    bool local_5 = {};
    metal::float3 v_3 = origin - x;
    float d2_ = metal::dot(v_3, v_3);
    if (perspective) {
        local_5 = d2_ > 0.0;
    } else {
        local_5 = false;
    }
    bool _e11 = local_5;
    if (_e11) {
        return v_3 / metal::float3(metal::sqrt(d2_));
    }
    return -(axis);
}

metal::float3 glossy_radiance(
    metal::float3 base_5,
    metal::float3 emission_1,
    float metallic_6,
    metal::float3 f_direct,
    metal::float3 direct,
    metal::float3 indirect,
    metal::float3 specular
) {
    metal::float3 _e9 = diffuse_albedo(base_5, metallic_6);
    return ((emission_1 + (f_direct * direct)) + ((_e9 * INV_PI) * indirect)) + specular;
}
uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}


struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, constant ImageParams& image [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> indirect_tex [[user(fake0)]]
, device type_6 const& direct_1 [[user(fake0)]]
, device type_7 const& materials [[user(fake0)]]
, metal::texture2d<float, metal::access::write> out_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> specular_tex [[user(fake0)]]
, constant MapParams& params [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    bool local = {};
    metal::float3 radiance = metal::float3(0.0);
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
    metal::int2 texel = metal::int2(static_cast<int>(gid.x), static_cast<int>(gid.y));
    metal::float4 p = position_tex.read(metal::uint2(texel), 0);
    if (p.w > 0.0) {
        metal::float4 nm = normal_tex.read(metal::uint2(texel), 0);
        GpuMaterial m = materials[naga_f2u32(nm.w)];
        metal::float4 _e47 = indirect_tex.read(metal::uint2(texel), 0);
        metal::float3 e_1 = _e47.xyz;
        bool _e52 = has_specular(m.metallic, m.f0_, m.f90_);
        if (_e52) {
            metal::float3 _e56 = params.origin;
            metal::float3 _e59 = params.axis;
            uint _e62 = params.mode;
            metal::float3 _e65 = primary_light_dir(p.xyz, _e56, _e59, _e62 == MAP_PERSPECTIVE);
            metal::float3 _e75 = image.eye;
            metal::float3 _e79 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, metal::normalize(nm.xyz), metal::normalize(_e75 - p.xyz), _e65);
            metal::float4 _e85 = direct_1[i];
            metal::float4 _e89 = specular_tex.read(metal::uint2(texel), 0);
            metal::float3 _e91 = glossy_radiance(m.albedo, m.emission, m.metallic, _e79, _e85.xyz, e_1, _e89.xyz);
            radiance = _e91;
        } else {
            metal::float4 _e96 = direct_1[i];
            metal::float3 _e99 = diffuse_radiance(m.albedo, m.emission, _e96.xyz + e_1);
            radiance = _e99;
        }
    }
    metal::float3 _e101 = radiance;
    out_tex.write(metal::float4(_e101, 1.0), metal::uint2(texel));
    return;
}
