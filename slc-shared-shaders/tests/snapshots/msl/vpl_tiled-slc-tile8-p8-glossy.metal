// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size6;
    uint size7;
    uint size8;
    uint size9;
    uint size10;
    uint size11;
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
    uint near_blocks;
    uint subset_shift;
    uint pad1_;
};
struct GpuMaterial {
    metal::packed_float3 albedo;
    float metallic;
    metal::packed_float3 emission;
    float alpha;
    metal::packed_float3 f0_;
    float f90_;
};
struct ViewParams {
    metal::float4 c0_;
    metal::float4 c1_;
    metal::float4 c2_;
    metal::float4 c3_;
    metal::packed_float3 eye;
    uint width;
    uint height;
    uint pad0_;
    uint seed;
    uint frame;
    metal::packed_float3 f0_d;
    float f90_d;
};
typedef float type_4[1];
struct type_6 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
};
typedef GpuLight type_8[1];
typedef metal::float4 type_9[1];
typedef GpuMaterial type_10[1];
struct GbTexel {
    metal::float4 position;
    metal::float4 normal;
};
struct Glossy {
    GpuMaterial m;
    metal::packed_float3 v;
    bool on;
    char _pad3[3];
};
struct type_13 {
    uint inner[1024];
};
constant uint LIGHT_POINT = 0u;
constant uint LIGHT_SPOT = 1u;
constant uint LIGHT_IES = 2u;
constant uint LIGHT_TRIANGLE = 3u;
constant uint LIGHT_VPL = 4u;
constant uint NO_LIGHT = 4294967295u;
constant uint MAP_CAMERA = 0u;
constant uint MAP_PERSPECTIVE = 1u;
constant uint MAP_ORTHOGRAPHIC = 2u;
constant float XI_STEP = 0.000000059604645;
constant uint PICK_STREAM = 2654435769u;
constant float TWO_PI = 6.2831855;
constant float CULL_RADIUS_SCALE = 1.000001;
constant float SPHERE_PAD = 0.00000047683716;
constant float SPHERE_HUGE = 340282350000000000000000000000000000000.0;
constant float SPHERE_PAD_ABS = 0.000000000000000001;
constant float INV_PI = 0.31830987;
constant float MIN_D2_ = 0.000000000001;
constant float MAX_INTENSITY = 72057594000000000.0;
constant uint BSH_NONE = 4294967295u;
constant uint RESERVOIR_FULL = 4294967295u;
constant float GGX_ALPHA_MIN = 0.001;
constant float RANGE_SCALE_MAX = 64.0;
constant uint LIGHT_BVH_LEAF = 4294967295u;
constant float ONE_MINUS_EPSILON = 0.99999994;
constant float F32_MAX = 340282350000000000000000000000000000000.0;
constant float DEPTH_NONE = 1000000000000000000000000000000.0;
constant float DEPTH_SIGMA = 0.05;
constant float COVER_WEIGHT = 0.1;
constant uint NEAR_BLOCK = 64u;
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
constant uint TILE = 8u;
constant uint THREADS = 64u;
constant uint BOX_THREADS = 64u;
constant uint MAX_TILE_LIGHTS = 1024u;

float slc_weight(
    float rt2_,
    float d2_
) {
    if (d2_ <= rt2_) {
        return 1.0;
    }
    return d2_ / rt2_;
}

bool slc_keep(
    float r2_,
    float d2_1
) {
    return d2_1 < r2_;
}

float cull_radius(
    float r2_1
) {
    return metal::sqrt(r2_1) * CULL_RADIUS_SCALE;
}

bool sphere_overlaps_aabb(
    metal::float3 c,
    float r,
    metal::float3 bmin,
    metal::float3 bmax
) {
    metal::float3 q = metal::clamp(c, bmin, bmax);
    metal::float3 v_6 = q - c;
    return metal::dot(v_6, v_6) <= (r * r);
}

float vpl_transfer(
    metal::float3 n_l,
    metal::float3 n_x,
    metal::float3 v,
    float min_d2_
) {
    float m = metal::max(metal::dot(v, v), metal::max(min_d2_, MIN_D2_));
    return ((metal::max(metal::dot(n_l, v), 0.0) * metal::max(-(metal::dot(n_x, v)), 0.0)) * INV_PI) / (m * m);
}

float ggx_d(
    float cos_h,
    float sin2_h,
    float alpha
) {
    if (cos_h <= 0.0) {
        return 0.0;
    }
    float a2_ = alpha * alpha;
    float t_1 = ((cos_h * cos_h) * a2_) + sin2_h;
    return (a2_ * INV_PI) / (t_1 * t_1);
}

float smith_root(
    float cos,
    float alpha_1
) {
    float a2_1 = alpha_1 * alpha_1;
    return metal::sqrt(((cos * cos) * (1.0 - a2_1)) + a2_1);
}

float smith_visibility(
    float n_l_1,
    float n_v,
    float alpha_2
) {
    bool local_2 = {};
    if (!((n_l_1 <= 0.0))) {
        local_2 = n_v <= 0.0;
    } else {
        local_2 = true;
    }
    bool _e11 = local_2;
    if (_e11) {
        return 0.0;
    }
    float _e13 = smith_root(n_v, alpha_2);
    float _e15 = smith_root(n_l_1, alpha_2);
    return 0.5 / ((n_l_1 * _e13) + (n_v * _e15));
}

metal::float3 fresnel_schlick(
    metal::float3 f0_,
    float f90_,
    float v_h
) {
    float c_1 = metal::saturate(1.0 - v_h);
    float c2_ = c_1 * c_1;
    return f0_ + ((metal::float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_1));
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
    metal::float3 v_1,
    metal::float3 l
) {
    metal::float3 h = v_1 + l;
    float len2_ = metal::dot(h, h);
    if (len2_ <= 0.0) {
        return 0.0;
    }
    return metal::saturate(metal::dot(v_1, h) / metal::sqrt(len2_));
}

metal::float3 specular_brdf(
    metal::float3 base_2,
    float metallic_2,
    metal::float3 f0_d_2,
    float f90_d_2,
    float alpha_3,
    metal::float3 n,
    metal::float3 v_2,
    metal::float3 l_1
) {
    bool local_3 = {};
    float n_l_2 = metal::dot(n, l_1);
    float n_v_1 = metal::dot(n, v_2);
    if (!((n_l_2 <= 0.0))) {
        local_3 = n_v_1 <= 0.0;
    } else {
        local_3 = true;
    }
    bool _e18 = local_3;
    if (_e18) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    metal::float3 hs = v_2 + l_1;
    float inv = 1.0 / metal::sqrt(metal::dot(hs, hs));
    metal::float3 h_1 = hs * inv;
    metal::float3 c_2 = metal::cross(n, h_1);
    float _e32 = ggx_d(metal::dot(n, h_1), metal::dot(c_2, c_2), alpha_3);
    metal::float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, metal::dot(v_2, h_1));
    float _e35 = smith_visibility(n_l_2, n_v_1, alpha_3);
    return _e34 * (_e32 * _e35);
}

metal::float3 brdf_eval(
    metal::float3 base_3,
    float metallic_3,
    metal::float3 f0_d_3,
    float f90_d_3,
    float alpha_4,
    metal::float3 n_1,
    metal::float3 v_3,
    metal::float3 l_2
) {
    if (metal::dot(n_1, l_2) <= 0.0) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    float _e15 = half_cosine(v_3, l_2);
    metal::float3 _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    metal::float3 _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_1, v_3, l_2);
    return _e16 + _e17;
}

metal::float3 diffuse_albedo(
    metal::float3 base_4,
    float metallic_4
) {
    return base_4 * (1.0 - metallic_4);
}

metal::float3 specular_correction(
    metal::float3 base_5,
    float metallic_5,
    metal::float3 f0_d_4,
    float f90_d_4,
    float alpha_5,
    metal::float3 n_2,
    metal::float3 v_4,
    metal::float3 l_3
) {
    metal::float3 _e8 = brdf_eval(base_5, metallic_5, f0_d_4, f90_d_4, alpha_5, n_2, v_4, l_3);
    metal::float3 _e9 = diffuse_albedo(base_5, metallic_5);
    return _e8 - (_e9 * INV_PI);
}

bool has_specular(
    float metallic_6,
    metal::float3 f0_d_5,
    float f90_d_5
) {
    bool local_4 = {};
    bool local_5 = {};
    if (!((metallic_6 > 0.0))) {
        local_4 = f90_d_5 > 0.0;
    } else {
        local_4 = true;
    }
    bool _e11 = local_4;
    if (!(_e11)) {
        local_5 = metal::max(metal::max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0.0;
    } else {
        local_5 = true;
    }
    bool _e23 = local_5;
    return _e23;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint shifted_subset(
    uint pixel_class,
    uint shift,
    uint period
) {
    return naga_mod(pixel_class + shift, period * period);
}

float vpl_near_weight(
    float d2_2,
    float near_r2_
) {
    if (near_r2_ <= 0.0) {
        return 0.0;
    }
    float t_2 = metal::clamp((near_r2_ - d2_2) / (0.75 * near_r2_), 0.0, 1.0);
    return (t_2 * t_2) * (3.0 - (2.0 * t_2));
}

float vpl_far_weight(
    float d2_3,
    float near_r2_1
) {
    float _e2 = vpl_near_weight(d2_3, near_r2_1);
    return 1.0 - _e2;
}

float vpl_far_slc_share(
    float rt2_1,
    float r2_2,
    float d2_4,
    float near_r2_2
) {
    float _e4 = vpl_far_weight(d2_4, near_r2_2);
    float _e5 = slc_weight(rt2_1, d2_4);
    bool _e7 = slc_keep(r2_2, d2_4);
    return (_e7 & (_e4 > 0.0)) ? (_e4 * _e5) : 0.0;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

WorkgroupBox workgroup_box(
    uint li_1,
    metal::float3 p,
    bool has,
    threadgroup type_6& wg_lo,
    threadgroup type_6& wg_hi
) {
    uint stride = 32u;
    wg_lo.inner[li_1] = has ? p : metal::float3(340282350000000000000000000000000000000.0);
    wg_hi.inner[li_1] = has ? p : metal::float3(-340282350000000000000000000000000000000.0);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e42 = stride;
            stride = naga_div(_e42, 2u);
        }
        loop_init = false;
        uint _e15 = stride;
        if (_e15 > 0u) {
        } else {
            break;
        }
        {
            uint _e18 = stride;
            if (li_1 < _e18) {
                metal::float3 _e24 = wg_lo.inner[li_1];
                uint _e26 = stride;
                metal::float3 _e29 = wg_lo.inner[li_1 + _e26];
                wg_lo.inner[li_1] = metal::min(_e24, _e29);
                metal::float3 _e35 = wg_hi.inner[li_1];
                uint _e37 = stride;
                metal::float3 _e40 = wg_hi.inner[li_1 + _e37];
                wg_hi.inner[li_1] = metal::max(_e35, _e40);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    metal::float3 _e47 = wg_lo.inner[0];
    metal::float3 _e50 = wg_hi.inner[0];
    return WorkgroupBox {_e47, _e50};
}

metal::float4 surface_at(
    metal::int2 texel,
    metal::texture2d<float, metal::access::sample> position_tex
) {
    metal::float4 p_1 = position_tex.read(metal::uint2(texel), 0);
    return (p_1.w > 0.0) ? metal::float4(p_1.xyz, 1.0) : metal::float4(0.0);
}

GbTexel gbuffer_at(
    uint i,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> position_tex,
    metal::texture2d<float, metal::access::sample> normal_tex
) {
    bool local_6 = {};
    uint _e3 = view.width;
    uint _e8 = view.width;
    metal::int2 texel_1 = metal::int2(static_cast<int>(naga_mod(i, _e3)), static_cast<int>(naga_div(i, _e8)));
    metal::float4 _e12 = surface_at(texel_1, position_tex);
    metal::float4 _e15 = normal_tex.read(metal::uint2(texel_1), 0);
    metal::float3 n_4 = _e15.xyz;
    float len2_1 = metal::dot(n_4, n_4);
    if (_e12.w > 0.0) {
        local_6 = len2_1 > 0.0;
    } else {
        local_6 = false;
    }
    bool valid = local_6;
    metal::float3 _e30 = view.eye;
    metal::float3 v_7 = _e12.xyz - _e30;
    metal::float4 position = metal::float4(_e12.xyz, valid ? 1.0 : 0.0);
    metal::float4 normal = valid ? metal::float4(n_4 / metal::float3(metal::sqrt(len2_1)), metal::sqrt(metal::dot(v_7, v_7))) : metal::float4(0.0, 0.0, 0.0, 1000000000000000000000000000000.0);
    return GbTexel {position, normal};
}

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

Glossy glossy_at(
    uint i_1,
    metal::float3 x,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> normal_tex,
    device type_10 const& materials,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e4 = view.width;
    uint _e9 = view.width;
    metal::int2 texel_2 = metal::int2(static_cast<int>(naga_mod(i_1, _e4)), static_cast<int>(naga_div(i_1, _e9)));
    metal::float4 _e16 = normal_tex.read(metal::uint2(texel_2), 0);
    GpuMaterial m_1 = materials[naga_f2u32(_e16.w)];
    metal::float3 _e23 = view.eye;
    bool _e29 = has_specular(m_1.metallic, m_1.f0_, m_1.f90_);
    return Glossy {m_1, metal::normalize(_e23 - x), _e29};
}

metal::float3 glossy_term(
    Glossy g_1,
    GpuLight l_4,
    metal::float3 n_3,
    metal::float3 v_5,
    float t
) {
    bool local_7 = {};
    if (!(!(g_1.on))) {
        local_7 = t <= 0.0;
    } else {
        local_7 = true;
    }
    bool _e13 = local_7;
    if (_e13) {
        return metal::float3(0.0);
    }
    metal::float3 _e30 = specular_correction(g_1.m.albedo, g_1.m.metallic, g_1.m.f0_, g_1.m.f90_, g_1.m.alpha, n_3, g_1.v, metal::normalize(-(v_5)));
    return (l_4.intensity * _e30) * t;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 wg [[threadgroup_position_in_grid]]
, metal::uint3 lid [[thread_position_in_threadgroup]]
, uint li [[thread_index_in_threadgroup]]
, threadgroup type_6& wg_lo
, threadgroup type_6& wg_hi
, constant VplParams& params [[user(fake0)]]
, constant ViewParams& view [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, device type_8 const& lights [[user(fake0)]]
, device type_4 const& rt2_2 [[user(fake0)]]
, device type_4 const& r2_3 [[user(fake0)]]
, device type_9& irradiance [[user(fake0)]]
, device type_10 const& materials [[user(fake0)]]
, device type_9& specular [[user(fake0)]]
, threadgroup metal::atomic_uint& tile_count
, threadgroup type_13& tile_lights
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    if (li == 0u) {
        wg_lo = {};
        wg_hi = {};
        metal::atomic_store_explicit(&tile_count, 0, metal::memory_order_relaxed);
        tile_lights = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    bool local = {};
    metal::float4 pos = metal::float4(0.0);
    metal::float3 nrm = metal::float3(0.0);
    bool local_1 = {};
    metal::float3 e = metal::float3(0.0);
    uint kept = 0u;
    metal::float3 s = metal::float3(0.0);
    Glossy g = {};
    uint first = 0u;
    uint j = {};
    uint k = {};
    uint sub = wg.z;
    uint px = naga_mod(sub, P) + (((wg.x * TILE) + lid.x) * P);
    uint py = naga_div(sub, P) + (((wg.y * TILE) + lid.y) * P);
    uint _e26 = params.width;
    if (px < _e26) {
        uint _e32 = params.height;
        local = py < _e32;
    } else {
        local = false;
    }
    bool inside = local;
    uint _e38 = params.width;
    uint pix = (py * _e38) + px;
    if (inside) {
        GbTexel _e47 = gbuffer_at(pix, view, position_tex, normal_tex);
        pos = _e47.position;
        nrm = _e47.normal.xyz;
    }
    if (inside) {
        float _e54 = pos.w;
        local_1 = _e54 > 0.0;
    } else {
        local_1 = false;
    }
    bool valid_1 = local_1;
    metal::float4 _e59 = pos;
    WorkgroupBox _e61 = workgroup_box(li, _e59.xyz, valid_1, wg_lo, wg_hi);
    metal::float3 lo = _e61.lo;
    metal::float3 hi = _e61.hi;
    uint _e66 = params.subset_shift;
    uint _e68 = shifted_subset(sub, _e66, P);
    uint _e71 = params.lights_per_subset;
    uint base_6 = _e68 * _e71;
    if (valid_1) {
        metal::float4 _e82 = pos;
        Glossy _e84 = glossy_at(pix, _e82.xyz, view, normal_tex, materials, _buffer_sizes);
        g = _e84;
    }
    uint2 loop_bound_1 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e187 = first;
            first = _e187 + MAX_TILE_LIGHTS;
        }
        loop_init_1 = false;
        uint _e87 = first;
        uint _e90 = params.lights_per_subset;
        if (_e87 < _e90) {
        } else {
            break;
        }
        {
            uint _e92 = first;
            uint _e97 = params.lights_per_subset;
            uint end = metal::min(_e92 + MAX_TILE_LIGHTS, _e97);
            if (li == 0u) {
                metal::atomic_store_explicit(&tile_count, 0u, metal::memory_order_relaxed);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint _e103 = first;
            j = _e103 + li;
            uint2 loop_bound_2 = uint2(4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e129 = j;
                    j = _e129 + THREADS;
                }
                loop_init_2 = false;
                uint _e106 = j;
                if (_e106 < end) {
                } else {
                    break;
                }
                {
                    uint _e109 = j;
                    metal::float3 _e113 = lights[base_6 + _e109].p0_;
                    uint _e115 = j;
                    float _e118 = r2_3[base_6 + _e115];
                    float _e119 = cull_radius(_e118);
                    bool _e120 = sphere_overlaps_aabb(_e113, _e119, lo, hi);
                    if (_e120) {
                        uint _e123 = metal::atomic_fetch_add_explicit(&tile_count, 1u, metal::memory_order_relaxed);
                        if (_e123 < MAX_TILE_LIGHTS) {
                            uint _e128 = j;
                            tile_lights.inner[_e123] = _e128;
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint unnamed = metal::atomic_load_explicit(&tile_count, metal::memory_order_relaxed);
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint count = metal::min(unnamed, MAX_TILE_LIGHTS);
            if (valid_1) {
                k = 0u;
                uint2 loop_bound_3 = uint2(4294967295u);
                bool loop_init_3 = true;
                while(true) {
                    if (metal::all(loop_bound_3 == uint2(0u))) { break; }
                    loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                    if (!loop_init_3) {
                        uint _e185 = k;
                        k = _e185 + 1u;
                    }
                    loop_init_3 = false;
                    uint _e138 = k;
                    if (_e138 < count) {
                    } else {
                        break;
                    }
                    {
                        uint _e141 = k;
                        uint _e143 = tile_lights.inner[_e141];
                        uint j_1 = base_6 + _e143;
                        GpuLight l_5 = lights[j_1];
                        metal::float4 _e148 = pos;
                        metal::float3 v_8 = _e148.xyz - l_5.p0_;
                        float _e154 = rt2_2[j_1];
                        float _e157 = r2_3[j_1];
                        float _e161 = params.near_r2_;
                        float _e162 = vpl_far_slc_share(_e154, _e157, metal::dot(v_8, v_8), _e161);
                        if (_e162 > 0.0) {
                            metal::float3 _e166 = nrm;
                            float _e169 = params.min_d2_;
                            float _e170 = vpl_transfer(l_5.p1_, _e166, v_8, _e169);
                            float t_3 = _e170 * _e162;
                            metal::float3 _e172 = e;
                            e = _e172 + (l_5.intensity * t_3);
                            metal::float3 _e176 = s;
                            Glossy _e177 = g;
                            metal::float3 _e178 = nrm;
                            metal::float3 _e179 = glossy_term(_e177, l_5, _e178, v_8, t_3);
                            s = _e176 + _e179;
                            uint _e181 = kept;
                            kept = _e181 + 1u;
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (inside) {
        metal::float3 _e192 = e;
        uint _e193 = kept;
        irradiance[pix] = metal::float4(_e192, static_cast<float>(_e193));
        metal::float3 _e198 = s;
        specular[pix] = metal::float4(_e198, 0.0);
        return;
    } else {
        return;
    }
}
