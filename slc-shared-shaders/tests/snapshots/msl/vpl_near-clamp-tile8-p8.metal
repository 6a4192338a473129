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
struct GbTexel {
    metal::float4 position;
    metal::float4 normal;
};
struct type_14 {
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

bool clamp_keep(
    float range2_,
    float d2_
) {
    return d2_ < range2_;
}

float cull_radius(
    float r2_
) {
    return metal::sqrt(r2_) * CULL_RADIUS_SCALE;
}

bool sphere_overlaps_aabb(
    metal::float3 c,
    float r,
    metal::float3 bmin,
    metal::float3 bmax
) {
    metal::float3 q = metal::clamp(c, bmin, bmax);
    metal::float3 v_1 = q - c;
    return metal::dot(v_1, v_1) <= (r * r);
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

float interleave_flux_scale(
    uint period
) {
    float _e2 = to_f32_(period * period);
    return _e2;
}

float vpl_near_weight(
    float d2_1,
    float near_r2_
) {
    if (near_r2_ <= 0.0) {
        return 0.0;
    }
    float t = metal::clamp((near_r2_ - d2_1) / (0.75 * near_r2_), 0.0, 1.0);
    return (t * t) * (3.0 - (2.0 * t));
}

float vpl_near_cull_range2_(
    float r2_1,
    float near_r2_1
) {
    return metal::min(r2_1, near_r2_1);
}

float vpl_near_fixed_share(
    float range2_1,
    float d2_2,
    float near_r2_2
) {
    float _e3 = vpl_near_weight(d2_2, near_r2_2);
    bool _e4 = clamp_keep(range2_1, d2_2);
    return (_e4 & (_e3 > 0.0)) ? _e3 : 0.0;
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
    bool local_5 = {};
    uint _e3 = view.width;
    uint _e8 = view.width;
    metal::int2 texel_1 = metal::int2(static_cast<int>(naga_mod(i, _e3)), static_cast<int>(naga_div(i, _e8)));
    metal::float4 _e12 = surface_at(texel_1, position_tex);
    metal::float4 _e15 = normal_tex.read(metal::uint2(texel_1), 0);
    metal::float3 n = _e15.xyz;
    float len2_ = metal::dot(n, n);
    if (_e12.w > 0.0) {
        local_5 = len2_ > 0.0;
    } else {
        local_5 = false;
    }
    bool valid = local_5;
    metal::float3 _e30 = view.eye;
    metal::float3 v_2 = _e12.xyz - _e30;
    metal::float4 position = metal::float4(_e12.xyz, valid ? 1.0 : 0.0);
    metal::float4 normal = valid ? metal::float4(n / metal::float3(metal::sqrt(len2_)), metal::sqrt(metal::dot(v_2, v_2))) : metal::float4(0.0, 0.0, 0.0, 1000000000000000000000000000000.0);
    return GbTexel {position, normal};
}

float near_r2_of(
    uint slot,
    device type_4 const& r2_2,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e3 = r2_2[slot];
    return _e3;
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
, device type_4 const& r2_2 [[user(fake0)]]
, device type_11& irradiance [[user(fake0)]]
, threadgroup metal::atomic_uint& light_count
, threadgroup type_14& light_list
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
    uint2 loop_bound_1 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e191 = first;
            first = _e191 + NEAR_CHUNK;
        }
        loop_init_1 = false;
        uint _e68 = first;
        uint _e71 = params.near_blocks;
        if (_e68 < _e71) {
        } else {
            break;
        }
        {
            if (li == 0u) {
                metal::atomic_store_explicit(&light_count, 0u, metal::memory_order_relaxed);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint _e77 = first;
            uint b = _e77 + li;
            if (li < NEAR_CHUNK) {
                uint _e85 = params.near_blocks;
                local_2 = b < _e85;
            } else {
                local_2 = false;
            }
            bool _e88 = local_2;
            if (_e88) {
                GpuNearBox nb = near_boxes[b];
                if (metal::all((nb.lo - metal::float3(_e56)) <= hi)) {
                    local_3 = metal::all(lo <= (nb.hi + metal::float3(_e56)));
                } else {
                    local_3 = false;
                }
                bool _e105 = local_3;
                if (_e105) {
                    m = 0u;
                    uint2 loop_bound_2 = uint2(4294967295u);
                    bool loop_init_2 = true;
                    while(true) {
                        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                        if (!loop_init_2) {
                            uint _e144 = m;
                            m = _e144 + 1u;
                        }
                        loop_init_2 = false;
                        uint _e108 = m;
                        if (_e108 < NEAR_BLOCK) {
                        } else {
                            break;
                        }
                        {
                            uint _e114 = m;
                            uint slot_1 = near_slots[(b * NEAR_BLOCK) + _e114];
                            GpuLight l = lights[slot_1];
                            float _e121 = near_r2_of(slot_1, r2_2, _buffer_sizes);
                            float _e124 = params.near_r2_;
                            float _e125 = vpl_near_cull_range2_(_e121, _e124);
                            float _e126 = cull_radius(_e125);
                            if (metal::any(l.intensity != metal::float3(0.0))) {
                                bool _e135 = sphere_overlaps_aabb(l.p0_, _e126, lo, hi);
                                local_4 = _e135;
                            } else {
                                local_4 = false;
                            }
                            bool _e137 = local_4;
                            if (_e137) {
                                uint _e141 = metal::atomic_fetch_add_explicit(&light_count, 1u, metal::memory_order_relaxed);
                                light_list.inner[_e141] = slot_1;
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
                        uint _e189 = m_1;
                        m_1 = _e189 + 1u;
                    }
                    loop_init_3 = false;
                    uint _e150 = m_1;
                    if (_e150 < unnamed) {
                    } else {
                        break;
                    }
                    {
                        uint _e153 = m_1;
                        uint slot_2 = light_list.inner[_e153];
                        GpuLight l_1 = lights[slot_2];
                        metal::float4 _e159 = pos;
                        metal::float3 v_3 = _e159.xyz - l_1.p0_;
                        float _e165 = r2_2[slot_2];
                        float _e169 = params.near_r2_;
                        float _e170 = vpl_near_fixed_share(_e165, metal::dot(v_3, v_3), _e169);
                        if (_e170 > 0.0) {
                            metal::float3 _e174 = nrm;
                            float _e177 = params.min_d2_;
                            float _e178 = vpl_transfer(l_1.p1_, _e174, v_3, _e177);
                            float t_1 = (_e178 * _e170) * unscale;
                            metal::float3 _e181 = e;
                            e = _e181 + (l_1.intensity * t_1);
                            uint _e185 = kept;
                            kept = _e185 + 1u;
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (valid_1) {
        metal::float4 old = irradiance[pix];
        metal::float3 _e200 = e;
        uint _e203 = kept;
        irradiance[pix] = metal::float4(old.xyz + _e200, old.w + static_cast<float>(_e203));
        return;
    } else {
        return;
    }
}
