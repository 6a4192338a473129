// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size3;
    uint size4;
    uint size5;
    uint size6;
    uint size7;
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
    uint pad0_;
    uint pad1_;
};
typedef float type_4[1];
struct type_6 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
};
typedef metal::float4 type_7[1];
typedef GpuLight type_8[1];
struct type_10 {
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
    float m = metal::max(metal::dot(v, v), min_d2_);
    return ((metal::max(metal::dot(n_l, v), 0.0) * metal::max(-(metal::dot(n_x, v)), 0.0)) * INV_PI) / (m * m);
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
uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
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
, device type_7 const& gb_position [[user(fake0)]]
, device type_7 const& gb_normal [[user(fake0)]]
, device type_8 const& lights [[user(fake0)]]
, device type_4 const& r2_1 [[user(fake0)]]
, device type_7& irradiance [[user(fake0)]]
, threadgroup metal::atomic_uint& tile_count
, threadgroup type_10& tile_lights
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
        metal::float4 _e49 = gb_position[pix];
        pos = _e49;
        metal::float4 _e52 = gb_normal[pix];
        nrm = _e52.xyz;
    }
    if (inside) {
        float _e57 = pos.w;
        local_1 = _e57 > 0.0;
    } else {
        local_1 = false;
    }
    bool valid = local_1;
    metal::float4 _e62 = pos;
    WorkgroupBox _e64 = workgroup_box(li, _e62.xyz, valid, wg_lo, wg_hi);
    metal::float3 lo = _e64.lo;
    metal::float3 hi = _e64.hi;
    uint _e69 = params.lights_per_subset;
    uint base = sub * _e69;
    uint2 loop_bound_1 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e170 = first;
            first = _e170 + MAX_TILE_LIGHTS;
        }
        loop_init_1 = false;
        uint _e78 = first;
        uint _e81 = params.lights_per_subset;
        if (_e78 < _e81) {
        } else {
            break;
        }
        {
            uint _e83 = first;
            uint _e88 = params.lights_per_subset;
            uint end = metal::min(_e83 + MAX_TILE_LIGHTS, _e88);
            if (li == 0u) {
                metal::atomic_store_explicit(&tile_count, 0u, metal::memory_order_relaxed);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint _e94 = first;
            j = _e94 + li;
            uint2 loop_bound_2 = uint2(4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e120 = j;
                    j = _e120 + THREADS;
                }
                loop_init_2 = false;
                uint _e97 = j;
                if (_e97 < end) {
                } else {
                    break;
                }
                {
                    uint _e100 = j;
                    metal::float3 _e104 = lights[base + _e100].p0_;
                    uint _e106 = j;
                    float _e109 = r2_1[base + _e106];
                    float _e110 = cull_radius(_e109);
                    bool _e111 = sphere_overlaps_aabb(_e104, _e110, lo, hi);
                    if (_e111) {
                        uint _e114 = metal::atomic_fetch_add_explicit(&tile_count, 1u, metal::memory_order_relaxed);
                        if (_e114 < MAX_TILE_LIGHTS) {
                            uint _e119 = j;
                            tile_lights.inner[_e114] = _e119;
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint unnamed = metal::atomic_load_explicit(&tile_count, metal::memory_order_relaxed);
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint count = metal::min(unnamed, MAX_TILE_LIGHTS);
            if (valid) {
                k = 0u;
                uint2 loop_bound_3 = uint2(4294967295u);
                bool loop_init_3 = true;
                while(true) {
                    if (metal::all(loop_bound_3 == uint2(0u))) { break; }
                    loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                    if (!loop_init_3) {
                        uint _e168 = k;
                        k = _e168 + 1u;
                    }
                    loop_init_3 = false;
                    uint _e129 = k;
                    if (_e129 < count) {
                    } else {
                        break;
                    }
                    {
                        uint _e132 = k;
                        uint _e134 = tile_lights.inner[_e132];
                        uint j_1 = base + _e134;
                        GpuLight l = lights[j_1];
                        metal::float4 _e139 = pos;
                        metal::float3 v_2 = _e139.xyz - l.p0_;
                        float _e145 = r2_1[j_1];
                        float _e149 = params.near_r2_;
                        float _e150 = vpl_far_fixed_share(_e145, metal::dot(v_2, v_2), _e149);
                        if (_e150 > 0.0) {
                            metal::float3 _e153 = e;
                            metal::float3 _e156 = nrm;
                            float _e159 = params.min_d2_;
                            float _e160 = vpl_transfer(l.p1_, _e156, v_2, _e159);
                            e = _e153 + (l.intensity * (_e160 * _e150));
                            uint _e164 = kept;
                            kept = _e164 + 1u;
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (valid) {
        metal::float3 _e175 = e;
        uint _e176 = kept;
        irradiance[pix] = metal::float4(_e175, static_cast<float>(_e176));
        return;
    } else {
        return;
    }
}
