// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size4;
    uint size5;
    uint size6;
    uint size7;
    uint size8;
    uint size9;
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
struct GpuNearBox {
    metal::packed_float3 lo;
    float pad0_;
    metal::packed_float3 hi;
    float pad1_;
};
struct PackParams {
    uint count;
    uint size;
    uint per_subset;
    uint mode;
    float exposure;
    float error_bound;
    float scale;
    uint slc;
    float fixed_r2_;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};
typedef float type_3[1];
typedef GpuLight type_6[1];
typedef uint type_7[1];
typedef GpuNearBox type_8[1];
struct type_9 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
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
constant uint BOX_THREADS = 64u;

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

float vpl_rt2_(
    metal::float3 flux_1,
    float exposure_1,
    float error_bound_1,
    uint mode_1
) {
    float _e6 = intensity_measure(flux_1 * INV_PI, mode_1);
    float _e7 = threshold_range2_(_e6, exposure_1, error_bound_1);
    return _e7;
}

bool finite3_(
    metal::float3 v
) {
    bool local_1 = {};
    bool local_2 = {};
    if (metal::abs(v.x) <= F32_MAX) {
        local_1 = metal::abs(v.y) <= F32_MAX;
    } else {
        local_1 = false;
    }
    bool _e12 = local_1;
    if (_e12) {
        local_2 = metal::abs(v.z) <= F32_MAX;
    } else {
        local_2 = false;
    }
    bool _e20 = local_2;
    return _e20;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint interleave_subset(
    uint x,
    uint y,
    uint period
) {
    return (naga_mod(y, period) * period) + naga_mod(x, period);
}

bool vpl_record_ok(
    metal::float3 position_1,
    metal::float3 normal_1,
    metal::float3 flux_2
) {
    bool local_3 = {};
    bool local_4 = {};
    bool local_5 = {};
    bool local_6 = {};
    bool local_7 = {};
    bool _e3 = finite3_(position_1);
    if (_e3) {
        bool _e6 = finite3_(normal_1);
        local_3 = _e6;
    } else {
        local_3 = false;
    }
    bool _e8 = local_3;
    if (_e8) {
        bool _e11 = finite3_(flux_2);
        local_4 = _e11;
    } else {
        local_4 = false;
    }
    bool _e13 = local_4;
    if (!(_e13)) {
        return false;
    }
    if (flux_2.x >= 0.0) {
        local_5 = flux_2.y >= 0.0;
    } else {
        local_5 = false;
    }
    bool _e25 = local_5;
    if (_e25) {
        local_6 = flux_2.z >= 0.0;
    } else {
        local_6 = false;
    }
    bool _e32 = local_6;
    if (_e32) {
        local_7 = (metal::max(metal::max(flux_2.x, flux_2.y), flux_2.z) * INV_PI) <= MAX_INTENSITY;
    } else {
        local_7 = false;
    }
    bool _e45 = local_7;
    return _e45;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

uint interleave_slot(
    uint tx,
    uint ty,
    uint size,
    uint period_1
) {
    uint side = naga_div(size, period_1);
    uint _e5 = interleave_subset(tx, ty, period_1);
    return (((_e5 * side) * side) + (naga_div(ty, period_1) * side)) + naga_div(tx, period_1);
}

uint near_block_tx(
    uint q,
    uint size_1
) {
    return (naga_mod(naga_div(q, NEAR_BLOCK), naga_div(size_1, 8u)) * 8u) + naga_mod(q, 8u);
}

uint near_block_ty(
    uint q_1,
    uint size_2
) {
    return (naga_div(naga_div(q_1, NEAR_BLOCK), naga_div(size_2, 8u)) * 8u) + naga_div(naga_mod(q_1, NEAR_BLOCK), 8u);
}

WorkgroupBox workgroup_box(
    uint li_1,
    metal::float3 p_1,
    bool has,
    threadgroup type_9& wg_lo,
    threadgroup type_9& wg_hi
) {
    uint stride = 32u;
    wg_lo.inner[li_1] = has ? p_1 : metal::float3(340282350000000000000000000000000000000.0);
    wg_hi.inner[li_1] = has ? p_1 : metal::float3(-340282350000000000000000000000000000000.0);
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

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, metal::uint3 wg [[threadgroup_position_in_grid]]
, uint li [[thread_index_in_threadgroup]]
, constant PackParams& params [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> rsm_position [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> rsm_normal [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> rsm_flux [[user(fake0)]]
, device type_6& lights [[user(fake0)]]
, device type_7& ids [[user(fake0)]]
, device type_3& rt2_ [[user(fake0)]]
, device type_3& r2_ [[user(fake0)]]
, device type_7& near_slots [[user(fake0)]]
, device type_8& near_boxes [[user(fake0)]]
, threadgroup type_9& wg_lo
, threadgroup type_9& wg_hi
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    if (li == 0u) {
        wg_lo = {};
        wg_hi = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    metal::float3 position = metal::float3(0.0);
    bool lit = false;
    metal::float3 p = {};
    metal::float3 normal = {};
    metal::float3 flux = {};
    bool local = {};
    uint q_2 = gid.x;
    uint _e6 = params.count;
    bool inside = q_2 < _e6;
    if (inside) {
        uint _e15 = params.size;
        uint _e16 = near_block_tx(q_2, _e15);
        uint _e19 = params.size;
        uint _e20 = near_block_ty(q_2, _e19);
        uint _e23 = params.size;
        uint i = (_e20 * _e23) + _e16;
        metal::int2 texel = metal::int2(static_cast<int>(_e16), static_cast<int>(_e20));
        metal::float4 _e31 = rsm_position.read(metal::uint2(texel), 0);
        p = _e31.xyz;
        metal::float4 _e36 = rsm_normal.read(metal::uint2(texel), 0);
        normal = _e36.xyz;
        metal::float4 _e41 = rsm_flux.read(metal::uint2(texel), 0);
        flux = _e41.xyz;
        uint _e46 = params.size;
        uint _e48 = interleave_slot(_e16, _e20, _e46, P);
        metal::float3 _e49 = p;
        metal::float3 _e50 = normal;
        metal::float3 _e51 = flux;
        bool _e52 = vpl_record_ok(_e49, _e50, _e51);
        if (!(_e52)) {
            p = metal::float3(0.0);
            normal = metal::float3(0.0);
            flux = metal::float3(0.0);
        }
        metal::float3 _e60 = p;
        position = _e60;
        metal::float3 _e61 = flux;
        float _e64 = params.scale;
        flux = _e61 * _e64;
        metal::float3 _e68 = position;
        metal::float3 _e70 = normal;
        metal::float3 _e73 = flux;
        lights[_e48] = GpuLight {_e68, LIGHT_VPL, _e70, 0.0, metal::float3(0.0), 0.0, _e73, 0u};
        ids[_e48] = i;
        uint _e82 = params.slc;
        bool slc = _e82 != 0u;
        metal::float3 _e87 = flux;
        float _e90 = params.exposure;
        float _e93 = params.error_bound;
        uint _e96 = params.mode;
        float _e97 = vpl_rt2_(_e87, _e90, _e93, _e96);
        rt2_[_e48] = slc ? _e97 : 0.0;
        float _e104 = params.fixed_r2_;
        r2_[_e48] = slc ? 0.0 : _e104;
        near_slots[q_2] = _e48;
        metal::float3 _e109 = flux;
        lit = metal::any(_e109 != metal::float3(0.0));
    }
    metal::float3 _e114 = position;
    bool _e115 = lit;
    WorkgroupBox _e116 = workgroup_box(li, _e114, _e115, wg_lo, wg_hi);
    if (li == 0u) {
        local = inside;
    } else {
        local = false;
    }
    bool _e122 = local;
    if (_e122) {
        near_boxes[wg.x] = GpuNearBox {_e116.lo, 0.0, _e116.hi, 0.0};
        return;
    } else {
        return;
    }
}
