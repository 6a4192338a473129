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
    uint size12;
    uint size13;
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
struct GpuNearBox {
    metal::packed_float3 lo;
    float pad0_;
    metal::packed_float3 hi;
    float pad1_;
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
typedef uint type_9[1];
typedef GpuNearBox type_10[1];
typedef metal::float4 type_11[1];
typedef GpuMaterial type_12[1];
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
struct type_15 {
    uint inner[2048];
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
constant uint NEAR_CHUNK = 32u;

float to_f32_(
    uint u
) {
    return static_cast<float>(u);
}

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
    float m_2 = metal::max(metal::dot(v, v), metal::max(min_d2_, MIN_D2_));
    return ((metal::max(metal::dot(n_l, v), 0.0) * metal::max(-(metal::dot(n_x, v)), 0.0)) * INV_PI) / (m_2 * m_2);
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
    bool local_5 = {};
    if (!((n_l_1 <= 0.0))) {
        local_5 = n_v <= 0.0;
    } else {
        local_5 = true;
    }
    bool _e11 = local_5;
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
    bool local_6 = {};
    float n_l_2 = metal::dot(n, l_1);
    float n_v_1 = metal::dot(n, v_2);
    if (!((n_l_2 <= 0.0))) {
        local_6 = n_v_1 <= 0.0;
    } else {
        local_6 = true;
    }
    bool _e18 = local_6;
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
    bool local_7 = {};
    bool local_8 = {};
    if (!((metallic_6 > 0.0))) {
        local_7 = f90_d_5 > 0.0;
    } else {
        local_7 = true;
    }
    bool _e11 = local_7;
    if (!(_e11)) {
        local_8 = metal::max(metal::max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0.0;
    } else {
        local_8 = true;
    }
    bool _e23 = local_8;
    return _e23;
}

float interleave_flux_scale(
    uint period
) {
    float _e2 = to_f32_(period * period);
    return _e2;
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

float vpl_near_range2_(
    float r2_2,
    uint period_1
) {
    float _e2 = interleave_flux_scale(period_1);
    return r2_2 / _e2;
}

float vpl_near_cull_range2_(
    float r2_3,
    float near_r2_1
) {
    return metal::min(r2_3, near_r2_1);
}

float vpl_near_slc_share(
    float rt2_1,
    float r2_4,
    float d2_3,
    float near_r2_2
) {
    float _e4 = vpl_near_weight(d2_3, near_r2_2);
    float _e5 = slc_weight(rt2_1, d2_3);
    bool _e7 = slc_keep(r2_4, d2_3);
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

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

GbTexel gbuffer_at(
    uint i,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> position_tex,
    metal::texture2d<float, metal::access::sample> normal_tex
) {
    bool local_9 = {};
    uint _e3 = view.width;
    uint _e8 = view.width;
    metal::int2 texel_1 = metal::int2(static_cast<int>(naga_mod(i, _e3)), static_cast<int>(naga_div(i, _e8)));
    metal::float4 _e12 = surface_at(texel_1, position_tex);
    metal::float4 _e15 = normal_tex.read(metal::uint2(texel_1), 0);
    metal::float3 n_4 = _e15.xyz;
    float len2_1 = metal::dot(n_4, n_4);
    if (_e12.w > 0.0) {
        local_9 = len2_1 > 0.0;
    } else {
        local_9 = false;
    }
    bool valid = local_9;
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
    device type_12 const& materials,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e4 = view.width;
    uint _e9 = view.width;
    metal::int2 texel_2 = metal::int2(static_cast<int>(naga_mod(i_1, _e4)), static_cast<int>(naga_div(i_1, _e9)));
    metal::float4 _e16 = normal_tex.read(metal::uint2(texel_2), 0);
    GpuMaterial m_3 = materials[naga_f2u32(_e16.w)];
    metal::float3 _e23 = view.eye;
    bool _e29 = has_specular(m_3.metallic, m_3.f0_, m_3.f90_);
    return Glossy {m_3, metal::normalize(_e23 - x), _e29};
}

metal::float3 glossy_term(
    Glossy g_1,
    GpuLight l_4,
    metal::float3 n_3,
    metal::float3 v_5,
    float t
) {
    bool local_10 = {};
    if (!(!(g_1.on))) {
        local_10 = t <= 0.0;
    } else {
        local_10 = true;
    }
    bool _e13 = local_10;
    if (_e13) {
        return metal::float3(0.0);
    }
    metal::float3 _e30 = specular_correction(g_1.m.albedo, g_1.m.metallic, g_1.m.f0_, g_1.m.f90_, g_1.m.alpha, n_3, g_1.v, metal::normalize(-(v_5)));
    return (l_4.intensity * _e30) * t;
}

float near_r2_of(
    uint slot,
    device type_4 const& r2_5,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e3 = r2_5[slot];
    float _e5 = vpl_near_range2_(_e3, P);
    return _e5;
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
, device type_9 const& near_slots [[user(fake0)]]
, device type_10 const& near_boxes [[user(fake0)]]
, device type_4 const& rt2_2 [[user(fake0)]]
, device type_4 const& r2_5 [[user(fake0)]]
, device type_11& irradiance [[user(fake0)]]
, device type_12 const& materials [[user(fake0)]]
, device type_11& specular [[user(fake0)]]
, threadgroup metal::atomic_uint& light_count
, threadgroup type_15& light_list
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    if (li == 0u) {
        wg_lo = {};
        wg_hi = {};
        metal::atomic_store_explicit(&light_count, 0, metal::memory_order_relaxed);
        light_list = {};
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
    bool local_2 = {};
    bool local_3 = {};
    uint m = {};
    bool local_4 = {};
    uint m_1 = {};
    uint px = (wg.x * TILE) + lid.x;
    uint py = (wg.y * TILE) + lid.y;
    uint _e15 = params.width;
    if (px < _e15) {
        uint _e21 = params.height;
        local = py < _e21;
    } else {
        local = false;
    }
    bool inside = local;
    uint _e27 = params.width;
    uint pix = (py * _e27) + px;
    if (inside) {
        GbTexel _e36 = gbuffer_at(pix, view, position_tex, normal_tex);
        pos = _e36.position;
        nrm = _e36.normal.xyz;
    }
    if (inside) {
        float _e43 = pos.w;
        local_1 = _e43 > 0.0;
    } else {
        local_1 = false;
    }
    bool valid_1 = local_1;
    metal::float4 _e48 = pos;
    WorkgroupBox _e50 = workgroup_box(li, _e48.xyz, valid_1, wg_lo, wg_hi);
    metal::float3 lo = _e50.lo;
    metal::float3 hi = _e50.hi;
    float _e55 = params.near_r2_;
    float _e56 = cull_radius(_e55);
    float _e58 = interleave_flux_scale(P);
    float unscale = 1.0 / _e58;
    if (valid_1) {
        metal::float4 _e70 = pos;
        Glossy _e72 = glossy_at(pix, _e70.xyz, view, normal_tex, materials, _buffer_sizes);
        g = _e72;
    }
    uint2 loop_bound_1 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e206 = first;
            first = _e206 + NEAR_CHUNK;
        }
        loop_init_1 = false;
        uint _e75 = first;
        uint _e78 = params.near_blocks;
        if (_e75 < _e78) {
        } else {
            break;
        }
        {
            if (li == 0u) {
                metal::atomic_store_explicit(&light_count, 0u, metal::memory_order_relaxed);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint _e84 = first;
            uint b = _e84 + li;
            if (li < NEAR_CHUNK) {
                uint _e92 = params.near_blocks;
                local_2 = b < _e92;
            } else {
                local_2 = false;
            }
            bool _e95 = local_2;
            if (_e95) {
                GpuNearBox nb = near_boxes[b];
                if (metal::all((nb.lo - metal::float3(_e56)) <= hi)) {
                    local_3 = metal::all(lo <= (nb.hi + metal::float3(_e56)));
                } else {
                    local_3 = false;
                }
                bool _e112 = local_3;
                if (_e112) {
                    m = 0u;
                    uint2 loop_bound_2 = uint2(4294967295u);
                    bool loop_init_2 = true;
                    while(true) {
                        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                        if (!loop_init_2) {
                            uint _e151 = m;
                            m = _e151 + 1u;
                        }
                        loop_init_2 = false;
                        uint _e115 = m;
                        if (_e115 < NEAR_BLOCK) {
                        } else {
                            break;
                        }
                        {
                            uint _e121 = m;
                            uint slot_1 = near_slots[(b * NEAR_BLOCK) + _e121];
                            GpuLight l_5 = lights[slot_1];
                            float _e128 = near_r2_of(slot_1, r2_5, _buffer_sizes);
                            float _e131 = params.near_r2_;
                            float _e132 = vpl_near_cull_range2_(_e128, _e131);
                            float _e133 = cull_radius(_e132);
                            if (metal::any(l_5.intensity != metal::float3(0.0))) {
                                bool _e142 = sphere_overlaps_aabb(l_5.p0_, _e133, lo, hi);
                                local_4 = _e142;
                            } else {
                                local_4 = false;
                            }
                            bool _e144 = local_4;
                            if (_e144) {
                                uint _e148 = metal::atomic_fetch_add_explicit(&light_count, 1u, metal::memory_order_relaxed);
                                light_list.inner[_e148] = slot_1;
                            }
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint unnamed = metal::atomic_load_explicit(&light_count, metal::memory_order_relaxed);
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            if (valid_1) {
                m_1 = 0u;
                uint2 loop_bound_3 = uint2(4294967295u);
                bool loop_init_3 = true;
                while(true) {
                    if (metal::all(loop_bound_3 == uint2(0u))) { break; }
                    loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                    if (!loop_init_3) {
                        uint _e204 = m_1;
                        m_1 = _e204 + 1u;
                    }
                    loop_init_3 = false;
                    uint _e157 = m_1;
                    if (_e157 < unnamed) {
                    } else {
                        break;
                    }
                    {
                        uint _e160 = m_1;
                        uint slot_2 = light_list.inner[_e160];
                        GpuLight l_6 = lights[slot_2];
                        metal::float4 _e166 = pos;
                        metal::float3 v_8 = _e166.xyz - l_6.p0_;
                        float _e172 = rt2_2[slot_2];
                        float _e174 = vpl_near_range2_(_e172, P);
                        float _e175 = near_r2_of(slot_2, r2_5, _buffer_sizes);
                        float _e179 = params.near_r2_;
                        float _e180 = vpl_near_slc_share(_e174, _e175, metal::dot(v_8, v_8), _e179);
                        if (_e180 > 0.0) {
                            metal::float3 _e184 = nrm;
                            float _e187 = params.min_d2_;
                            float _e188 = vpl_transfer(l_6.p1_, _e184, v_8, _e187);
                            float t_3 = (_e188 * _e180) * unscale;
                            metal::float3 _e191 = e;
                            e = _e191 + (l_6.intensity * t_3);
                            metal::float3 _e195 = s;
                            Glossy _e196 = g;
                            metal::float3 _e197 = nrm;
                            metal::float3 _e198 = glossy_term(_e196, l_6, _e197, v_8, t_3);
                            s = _e195 + _e198;
                            uint _e200 = kept;
                            kept = _e200 + 1u;
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (valid_1) {
        metal::float4 old = irradiance[pix];
        metal::float3 _e215 = e;
        uint _e218 = kept;
        irradiance[pix] = metal::float4(old.xyz + _e215, old.w + static_cast<float>(_e218));
        metal::float4 _e226 = specular[pix];
        metal::float3 _e228 = s;
        specular[pix] = metal::float4(_e226.xyz + _e228, 0.0);
        return;
    } else {
        return;
    }
}
