// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size6;
    uint size7;
    uint size8;
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
struct GbTexel {
    metal::float4 position;
    metal::float4 normal;
};
struct type_12 {
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
    float m = metal::max(metal::dot(v, v), metal::max(min_d2_, MIN_D2_));
    return ((metal::max(metal::dot(n_l, v), 0.0) * metal::max(-(metal::dot(n_x, v)), 0.0)) * INV_PI) / (m * m);
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
    float d2_1,
    float near_r2_
) {
    if (near_r2_ <= 0.0) {
        return 0.0;
    }
    float t = metal::clamp((near_r2_ - d2_1) / (0.75 * near_r2_), 0.0, 1.0);
    return (t * t) * (3.0 - (2.0 * t));
}

float vpl_far_weight(
    float d2_2,
    float near_r2_1
) {
    float _e2 = vpl_near_weight(d2_2, near_r2_1);
    return 1.0 - _e2;
}

float vpl_far_fixed_share(
    float range2_1,
    float d2_3,
    float near_r2_2
) {
    float _e3 = vpl_far_weight(d2_3, near_r2_2);
    bool _e4 = clamp_keep(range2_1, d2_3);
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

GbTexel gbuffer_at(
    uint i,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> position_tex,
    metal::texture2d<float, metal::access::sample> normal_tex
) {
    bool local_2 = {};
    uint _e3 = view.width;
    uint _e8 = view.width;
    metal::int2 texel_1 = metal::int2(static_cast<int>(naga_mod(i, _e3)), static_cast<int>(naga_div(i, _e8)));
    metal::float4 _e12 = surface_at(texel_1, position_tex);
    metal::float4 _e15 = normal_tex.read(metal::uint2(texel_1), 0);
    metal::float3 n = _e15.xyz;
    float len2_ = metal::dot(n, n);
    if (_e12.w > 0.0) {
        local_2 = len2_ > 0.0;
    } else {
        local_2 = false;
    }
    bool valid = local_2;
    metal::float3 _e30 = view.eye;
    metal::float3 v_2 = _e12.xyz - _e30;
    metal::float4 position = metal::float4(_e12.xyz, valid ? 1.0 : 0.0);
    metal::float4 normal = valid ? metal::float4(n / metal::float3(metal::sqrt(len2_)), metal::sqrt(metal::dot(v_2, v_2))) : metal::float4(0.0, 0.0, 0.0, 1000000000000000000000000000000.0);
    return GbTexel {position, normal};
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
, device type_4 const& r2_1 [[user(fake0)]]
, device type_9& irradiance [[user(fake0)]]
, threadgroup metal::atomic_uint& tile_count
, threadgroup type_12& tile_lights
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
    uint base = _e68 * _e71;
    uint2 loop_bound_1 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e172 = first;
            first = _e172 + MAX_TILE_LIGHTS;
        }
        loop_init_1 = false;
        uint _e80 = first;
        uint _e83 = params.lights_per_subset;
        if (_e80 < _e83) {
        } else {
            break;
        }
        {
            uint _e85 = first;
            uint _e90 = params.lights_per_subset;
            uint end = metal::min(_e85 + MAX_TILE_LIGHTS, _e90);
            if (li == 0u) {
                metal::atomic_store_explicit(&tile_count, 0u, metal::memory_order_relaxed);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint _e96 = first;
            j = _e96 + li;
            uint2 loop_bound_2 = uint2(4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e122 = j;
                    j = _e122 + THREADS;
                }
                loop_init_2 = false;
                uint _e99 = j;
                if (_e99 < end) {
                } else {
                    break;
                }
                {
                    uint _e102 = j;
                    metal::float3 _e106 = lights[base + _e102].p0_;
                    uint _e108 = j;
                    float _e111 = r2_1[base + _e108];
                    float _e112 = cull_radius(_e111);
                    bool _e113 = sphere_overlaps_aabb(_e106, _e112, lo, hi);
                    if (_e113) {
                        uint _e116 = metal::atomic_fetch_add_explicit(&tile_count, 1u, metal::memory_order_relaxed);
                        if (_e116 < MAX_TILE_LIGHTS) {
                            uint _e121 = j;
                            tile_lights.inner[_e116] = _e121;
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
                        uint _e170 = k;
                        k = _e170 + 1u;
                    }
                    loop_init_3 = false;
                    uint _e131 = k;
                    if (_e131 < count) {
                    } else {
                        break;
                    }
                    {
                        uint _e134 = k;
                        uint _e136 = tile_lights.inner[_e134];
                        uint j_1 = base + _e136;
                        GpuLight l = lights[j_1];
                        metal::float4 _e141 = pos;
                        metal::float3 v_3 = _e141.xyz - l.p0_;
                        float _e147 = r2_1[j_1];
                        float _e151 = params.near_r2_;
                        float _e152 = vpl_far_fixed_share(_e147, metal::dot(v_3, v_3), _e151);
                        if (_e152 > 0.0) {
                            metal::float3 _e156 = nrm;
                            float _e159 = params.min_d2_;
                            float _e160 = vpl_transfer(l.p1_, _e156, v_3, _e159);
                            float t_1 = _e160 * _e152;
                            metal::float3 _e162 = e;
                            e = _e162 + (l.intensity * t_1);
                            uint _e166 = kept;
                            kept = _e166 + 1u;
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (inside) {
        metal::float3 _e177 = e;
        uint _e178 = kept;
        irradiance[pix] = metal::float4(_e177, static_cast<float>(_e178));
        return;
    } else {
        return;
    }
}
