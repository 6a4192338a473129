// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
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
    uint subset_shift;
    uint far_groups_at;
    uint near_clusters_at;
    uint near_groups_at;
    uint box_count;
    uint pad0_;
    uint pad1_;
    metal::uint4 far_grid;
    metal::uint4 near_grid;
};
struct GpuBox {
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
    float shadow_offset;
    uint seed;
    uint frame;
    metal::packed_float3 f0_d;
    float f90_d;
};
typedef float type_5[1];
struct type_7 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
};
typedef GpuLight type_9[1];
typedef GpuBox type_10[1];
typedef metal::float4 type_11[1];
typedef metal::atomic_uint type_13[1];
struct GbTexel {
    metal::float4 position;
    metal::float4 normal;
};
struct type_15 {
    metal::atomic_uint inner[7];
};
struct type_16 {
    uint inner[1024];
};
struct type_17 {
    uint inner[64];
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
    metal::float3 v_1 = q - c;
    return metal::dot(v_1, v_1) <= (r * r);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

uint groups_across(
    uint bw,
    uint gw
) {
    return naga_div((bw + gw) - 1u, gw);
}

uint group_count(
    uint bw_1,
    uint bh,
    uint gw_1,
    uint gh
) {
    uint _e4 = groups_across(bw_1, gw_1);
    uint _e5 = groups_across(bh, gh);
    return _e4 * _e5;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint group_first(
    uint g,
    uint bw_2,
    uint bh_1,
    uint gw_2,
    uint gh_1
) {
    uint _e5 = groups_across(bw_2, gw_2);
    uint gx = naga_mod(g, _e5);
    uint gy = naga_div(g, _e5);
    uint h_1 = metal::min(gh_1, bh_1 - (gh_1 * gy));
    return ((gy * gh_1) * bw_2) + ((gx * gw_2) * h_1);
}

uint group_clusters(
    uint g_1,
    uint bw_3,
    uint bh_2,
    uint gw_3,
    uint gh_2
) {
    uint _e5 = groups_across(bw_3, gw_3);
    uint gx_1 = naga_mod(g_1, _e5);
    uint gy_1 = naga_div(g_1, _e5);
    return metal::min(gw_3, bw_3 - (gw_3 * gx_1)) * metal::min(gh_2, bh_2 - (gh_2 * gy_1));
}

bool box_overlaps_box(
    metal::float3 lo1_,
    metal::float3 hi1_,
    metal::float3 lo2_,
    metal::float3 hi2_
) {
    bool local_1 = {};
    bool local_2 = {};
    bool local_3 = {};
    bool local_4 = {};
    bool local_5 = {};
    if (lo1_.x <= hi2_.x) {
        local_1 = lo2_.x <= hi1_.x;
    } else {
        local_1 = false;
    }
    bool _e13 = local_1;
    if (_e13) {
        local_2 = lo1_.y <= hi2_.y;
    } else {
        local_2 = false;
    }
    bool _e20 = local_2;
    if (_e20) {
        local_3 = lo2_.y <= hi1_.y;
    } else {
        local_3 = false;
    }
    bool _e27 = local_3;
    if (_e27) {
        local_4 = lo1_.z <= hi2_.z;
    } else {
        local_4 = false;
    }
    bool _e34 = local_4;
    if (_e34) {
        local_5 = lo2_.z <= hi1_.z;
    } else {
        local_5 = false;
    }
    bool _e41 = local_5;
    return _e41;
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
    float t = metal::clamp((near_r2_ - d2_2) / (0.75 * near_r2_), 0.0, 1.0);
    return (t * t) * (3.0 - (2.0 * t));
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

WorkgroupBox workgroup_bounds(
    uint li_1,
    metal::float3 lo,
    metal::float3 hi,
    threadgroup type_7& wg_lo,
    threadgroup type_7& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    uint stride = 32u;
    wg_lo.inner[li_1] = lo;
    wg_hi.inner[li_1] = hi;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e36 = stride;
            stride = naga_div(_e36, 2u);
        }
        loop_init = false;
        uint _e9 = stride;
        if (_e9 > 0u) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if (li_1 < _e12) {
                metal::float3 _e18 = wg_lo.inner[li_1];
                uint _e20 = stride;
                metal::float3 _e23 = wg_lo.inner[li_1 + _e20];
                wg_lo.inner[li_1] = metal::min(_e18, _e23);
                metal::float3 _e29 = wg_hi.inner[li_1];
                uint _e31 = stride;
                metal::float3 _e34 = wg_hi.inner[li_1 + _e31];
                wg_hi.inner[li_1] = metal::max(_e29, _e34);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (li_1 == 0u) {
        metal::float3 _e44 = wg_lo.inner[0];
        metal::float3 _e47 = wg_hi.inner[0];
        wg_box = WorkgroupBox {_e44, _e47};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    WorkgroupBox unnamed = wg_box;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return unnamed;
}

WorkgroupBox point_box(
    metal::float3 p,
    bool has
) {
    return WorkgroupBox {has ? p : metal::float3(340282350000000000000000000000000000000.0), has ? p : metal::float3(-340282350000000000000000000000000000000.0)};
}

WorkgroupBox workgroup_box(
    uint li_2,
    metal::float3 p_1,
    bool has_1,
    threadgroup type_7& wg_lo,
    threadgroup type_7& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    WorkgroupBox _e3 = point_box(p_1, has_1);
    WorkgroupBox _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi, wg_lo, wg_hi, wg_box);
    return _e6;
}

bool box_is_empty(
    WorkgroupBox b
) {
    return b.lo.x > b.hi.x;
}

metal::float4 surface_at(
    metal::int2 texel,
    metal::texture2d<float, metal::access::sample> position_tex
) {
    metal::float4 p_4 = position_tex.read(metal::uint2(texel), 0);
    return (p_4.w > 0.0) ? metal::float4(p_4.xyz, 1.0) : metal::float4(0.0);
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
    metal::float3 n_3 = _e15.xyz;
    float len2_ = metal::dot(n_3, n_3);
    if (_e12.w > 0.0) {
        local_6 = len2_ > 0.0;
    } else {
        local_6 = false;
    }
    bool valid_1 = local_6;
    metal::float3 _e30 = view.eye;
    metal::float3 v_2 = _e12.xyz - _e30;
    metal::float4 position = metal::float4(_e12.xyz, valid_1 ? 1.0 : 0.0);
    metal::float4 normal = valid_1 ? metal::float4(n_3 / metal::float3(metal::sqrt(len2_)), metal::sqrt(metal::dot(v_2, v_2))) : metal::float4(0.0, 0.0, 0.0, 1000000000000000000000000000000.0);
    return GbTexel {position, normal};
}

void counter_add(
    uint f,
    uint n,
    device type_13& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e6 = metal::atomic_fetch_add_explicit(&counters[2u * f], n, metal::memory_order_relaxed);
    if ((_e6 + n) < _e6) {
        uint _e16 = metal::atomic_fetch_add_explicit(&counters[(2u * f) + 1u], 1u, metal::memory_order_relaxed);
        return;
    } else {
        return;
    }
}

void counts_begin(
    uint li_3,
    threadgroup type_15& wg_counts
) {
    if (li_3 < COUNT_FIELDS) {
        metal::atomic_store_explicit(&wg_counts.inner[li_3], 0u, metal::memory_order_relaxed);
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return;
}

void count_add(
    uint f_1,
    uint n_1,
    threadgroup type_15& wg_counts
) {
    uint _e4 = metal::atomic_fetch_add_explicit(&wg_counts.inner[f_1], n_1, metal::memory_order_relaxed);
    return;
}

void count_one(
    uint f_2,
    threadgroup type_15& wg_counts
) {
    uint _e4 = metal::atomic_fetch_add_explicit(&wg_counts.inner[f_2], 1u, metal::memory_order_relaxed);
    return;
}

void count_tests(
    uint li_4,
    uint f_3,
    uint n_2,
    threadgroup type_15& wg_counts
) {
    if (li_4 == 0u) {
        uint _e7 = metal::atomic_fetch_add_explicit(&wg_counts.inner[f_3], n_2, metal::memory_order_relaxed);
        return;
    } else {
        return;
    }
}

void counts_end(
    uint li_5,
    device type_13& counters,
    threadgroup type_15& wg_counts,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    if (li_5 < COUNT_FIELDS) {
        uint _e5 = metal::atomic_load_explicit(&wg_counts.inner[li_5], metal::memory_order_relaxed);
        counter_add(li_5, _e5, counters, _buffer_sizes);
        return;
    } else {
        return;
    }
}

WorkgroupBox load_receiver(
    uint li_6,
    uint pix,
    bool inside,
    threadgroup type_7& wg_lo,
    threadgroup type_7& wg_hi,
    threadgroup WorkgroupBox& wg_box,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> position_tex,
    metal::texture2d<float, metal::access::sample> normal_tex,
    threadgroup type_15& wg_counts,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread float& eye_distance,
    thread bool& valid
) {
    metal::float4 p_2 = metal::float4(0.0);
    bool local_7 = {};
    eye_distance = DEPTH_NONE;
    if (inside) {
        GbTexel _e8 = gbuffer_at(pix, view, position_tex, normal_tex);
        p_2 = _e8.position;
        nrm = _e8.normal.xyz;
        eye_distance = _e8.normal.w;
    }
    metal::float4 _e17 = p_2;
    pos = _e17.xyz;
    if (inside) {
        float _e23 = p_2.w;
        local_7 = _e23 > 0.0;
    } else {
        local_7 = false;
    }
    bool _e27 = local_7;
    valid = _e27;
    counts_begin(li_6, wg_counts);
    bool _e29 = valid;
    if (_e29) {
        count_one(COUNT_PIXELS, wg_counts);
    }
    metal::float3 _e32 = pos;
    bool _e34 = valid;
    WorkgroupBox _e35 = workgroup_box(li_6, _e32, _e34, wg_lo, wg_hi, wg_box);
    return _e35;
}

void count_receiver(
    uint li_7,
    device type_13& counters,
    threadgroup type_15& wg_counts,
    thread bool& valid,
    thread uint& kept,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool _e2 = valid;
    if (_e2) {
        uint _e5 = kept;
        count_add(COUNT_KEPT, _e5, wg_counts);
    }
    counts_end(li_7, counters, wg_counts, _buffer_sizes);
    return;
}

void shade_light(
    uint j,
    constant VplParams& params,
    device type_9 const& lights,
    device type_5 const& rt2_2,
    device type_5 const& r2_3,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread metal::float3& e,
    thread uint& kept,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight l = lights[j];
    metal::float3 _e5 = pos;
    metal::float3 v_3 = _e5 - l.p0_;
    float _e10 = rt2_2[j];
    float _e13 = r2_3[j];
    float _e17 = params.near_r2_;
    float _e18 = vpl_far_slc_share(_e10, _e13, metal::dot(v_3, v_3), _e17);
    if (_e18 > 0.0) {
        metal::float3 _e23 = nrm;
        float _e26 = params.min_d2_;
        float _e27 = vpl_transfer(l.p1_, _e23, v_3, _e26);
        float t_1 = _e27 * _e18;
        metal::float3 _e30 = e;
        e = _e30 + (l.intensity * t_1);
        uint _e35 = kept;
        kept = _e35 + 1u;
        return;
    } else {
        return;
    }
}

uint cluster_slot(
    uint c_1,
    uint k
) {
    return (c_1 * CLUSTER) + k;
}

float cull_r2_of(
    uint slot,
    device type_5 const& r2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e3 = r2_3[slot];
    return _e3;
}

void shade_list(
    uint count,
    constant VplParams& params,
    device type_9 const& lights,
    device type_5 const& rt2_2,
    device type_5 const& r2_3,
    threadgroup type_15& wg_counts,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread bool& valid,
    thread metal::float3& e,
    thread uint& kept,
    threadgroup type_16& tile_lights,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint k_1 = 0u;
    bool _e2 = valid;
    if (_e2) {
        uint2 loop_bound_1 = uint2(4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (metal::all(loop_bound_1 == uint2(0u))) { break; }
            loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e12 = k_1;
                k_1 = _e12 + 1u;
            }
            loop_init_1 = false;
            uint _e5 = k_1;
            if (_e5 < count) {
            } else {
                break;
            }
            {
                uint _e8 = k_1;
                uint _e10 = tile_lights.inner[_e8];
                shade_light(_e10, params, lights, rt2_2, r2_3, pos, nrm, e, kept, _buffer_sizes);
            }
        }
        count_add(COUNT_TESTED, count, wg_counts);
        return;
    } else {
        return;
    }
}

void list_clear(
    uint li_8,
    threadgroup metal::atomic_uint& list_count
) {
    if (li_8 == 0u) {
        metal::atomic_store_explicit(&list_count, 0u, metal::memory_order_relaxed);
        return;
    } else {
        return;
    }
}

bool list_full(
    threadgroup metal::atomic_uint& list_count
) {
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_1 = metal::atomic_load_explicit(&list_count, metal::memory_order_relaxed);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return (unnamed_1 + CLUSTER) > MAX_TILE_LIGHTS;
}

void list_add(
    uint slot_1,
    metal::float3 p_3,
    float radius,
    threadgroup type_16& tile_lights,
    threadgroup metal::atomic_uint& list_count
) {
    uint _e6 = metal::atomic_fetch_add_explicit(&list_count, 1u, metal::memory_order_relaxed);
    tile_lights.inner[_e6] = slot_1;
    return;
}

void list_shade(
    constant VplParams& params,
    device type_9 const& lights,
    device type_5 const& rt2_2,
    device type_5 const& r2_3,
    threadgroup type_15& wg_counts,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread bool& valid,
    thread metal::float3& e,
    thread uint& kept,
    threadgroup type_16& tile_lights,
    threadgroup metal::atomic_uint& list_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_2 = metal::atomic_load_explicit(&list_count, metal::memory_order_relaxed);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    shade_list(unnamed_2, params, lights, rt2_2, r2_3, wg_counts, pos, nrm, valid, e, kept, tile_lights, _buffer_sizes);
    return;
}

void cull_tile(
    uint li_9,
    metal::float3 lo_1,
    metal::float3 hi_1,
    metal::uint4 grid,
    uint clusters_at,
    uint groups_at,
    constant VplParams& params,
    device type_9 const& lights,
    device type_5 const& rt2_2,
    device type_5 const& r2_3,
    device type_10 const& boxes,
    threadgroup type_15& wg_counts,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread bool& valid,
    thread metal::float3& e,
    thread uint& kept,
    threadgroup type_16& tile_lights,
    threadgroup metal::atomic_uint& list_count,
    threadgroup type_17& cluster_hits,
    threadgroup metal::atomic_uint& hit_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint g_2 = 0u;
    uint h = {};
    list_clear(li_9, list_count);
    uint _e10 = group_count(grid.x, grid.y, grid.z, grid.w);
    count_tests(li_9, COUNT_GROUP_TESTS, _e10, wg_counts);
    uint2 loop_bound_2 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e87 = g_2;
            g_2 = _e87 + 1u;
        }
        loop_init_2 = false;
        uint _e14 = g_2;
        if (_e14 < _e10) {
        } else {
            break;
        }
        {
            uint _e17 = g_2;
            GpuBox gb = boxes[groups_at + _e17];
            bool _e23 = box_overlaps_box(gb.lo, gb.hi, lo_1, hi_1);
            if (!(_e23)) {
                continue;
            }
            uint _e25 = g_2;
            uint _e30 = group_first(_e25, grid.x, grid.y, grid.z, grid.w);
            uint first = clusters_at + _e30;
            uint _e32 = g_2;
            uint _e37 = group_clusters(_e32, grid.x, grid.y, grid.z, grid.w);
            count_tests(li_9, COUNT_CLUSTER_TESTS, _e37, wg_counts);
            if (li_9 == 0u) {
                metal::atomic_store_explicit(&hit_count, 0u, metal::memory_order_relaxed);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            if (li_9 < _e37) {
                GpuBox cb = boxes[first + li_9];
                bool _e50 = box_overlaps_box(cb.lo, cb.hi, lo_1, hi_1);
                if (_e50) {
                    uint _e54 = metal::atomic_fetch_add_explicit(&hit_count, 1u, metal::memory_order_relaxed);
                    cluster_hits.inner[_e54] = first + li_9;
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint unnamed_3 = metal::atomic_load_explicit(&hit_count, metal::memory_order_relaxed);
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            h = 0u;
            uint2 loop_bound_3 = uint2(4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (metal::all(loop_bound_3 == uint2(0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e84 = h;
                    h = _e84 + 1u;
                }
                loop_init_3 = false;
                uint _e61 = h;
                if (_e61 < unnamed_3) {
                } else {
                    break;
                }
                {
                    bool _e63 = list_full(list_count);
                    if (_e63) {
                        list_shade(params, lights, rt2_2, r2_3, wg_counts, pos, nrm, valid, e, kept, tile_lights, list_count, _buffer_sizes);
                        metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
                        list_clear(li_9, list_count);
                        metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
                    }
                    uint _e65 = h;
                    uint _e67 = cluster_hits.inner[_e65];
                    uint _e68 = cluster_slot(_e67, li_9);
                    GpuLight l_1 = lights[_e68];
                    if (metal::any(l_1.intensity != metal::float3(0.0))) {
                        count_one(COUNT_SPHERE_TESTS, wg_counts);
                        float _e78 = cull_r2_of(_e68, r2_3, _buffer_sizes);
                        float _e79 = cull_radius(_e78);
                        bool _e81 = sphere_overlaps_aabb(l_1.p0_, _e79, lo_1, hi_1);
                        if (_e81) {
                            list_add(_e68, l_1.p0_, _e79, tile_lights, list_count);
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    list_shade(params, lights, rt2_2, r2_3, wg_counts, pos, nrm, valid, e, kept, tile_lights, list_count, _buffer_sizes);
    return;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 wg [[threadgroup_position_in_grid]]
, metal::uint3 lid [[thread_position_in_threadgroup]]
, uint li [[thread_index_in_threadgroup]]
, threadgroup type_7& wg_lo
, threadgroup type_7& wg_hi
, threadgroup WorkgroupBox& wg_box
, constant VplParams& params [[user(fake0)]]
, constant ViewParams& view [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, device type_9 const& lights [[user(fake0)]]
, device type_5 const& rt2_2 [[user(fake0)]]
, device type_5 const& r2_3 [[user(fake0)]]
, device type_10 const& boxes [[user(fake0)]]
, device type_11& irradiance [[user(fake0)]]
, device type_11& guide [[user(fake0)]]
, device type_13& counters [[user(fake0)]]
, threadgroup type_15& wg_counts
, threadgroup type_16& tile_lights
, threadgroup metal::atomic_uint& list_count
, threadgroup type_17& cluster_hits
, threadgroup metal::atomic_uint& hit_count
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    metal::float3 pos = {};
    metal::float3 nrm = {};
    float eye_distance = {};
    bool valid = {};
    metal::float3 e = {};
    uint kept = {};
    if (li == 0u) {
        wg_lo = {};
        wg_hi = {};
        wg_box = {};
        for (int __i0 = 0; __i0 < 7; __i0++) {
            metal::atomic_store_explicit(&wg_counts.inner[__i0], 0, metal::memory_order_relaxed);
        }
        tile_lights = {};
        metal::atomic_store_explicit(&list_count, 0, metal::memory_order_relaxed);
        cluster_hits = {};
        metal::atomic_store_explicit(&hit_count, 0, metal::memory_order_relaxed);
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    bool local = {};
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
    bool inside_1 = local;
    uint _e38 = params.width;
    uint pix_1 = (py * _e38) + px;
    WorkgroupBox _e41 = load_receiver(li, pix_1, inside_1, wg_lo, wg_hi, wg_box, view, position_tex, normal_tex, wg_counts, pos, nrm, eye_distance, valid);
    uint _e44 = params.subset_shift;
    uint _e46 = shifted_subset(sub, _e44, P);
    bool _e47 = box_is_empty(_e41);
    if (!(_e47)) {
        count_tests(li, COUNT_TILES, 1u, wg_counts);
        metal::uint4 grid_1 = params.far_grid;
        uint _e58 = params.lights_per_subset;
        uint _e64 = params.far_groups_at;
        uint _e69 = group_count(grid_1.x, grid_1.y, grid_1.z, grid_1.w);
        cull_tile(li, _e41.lo, _e41.hi, grid_1, _e46 * naga_div(_e58, CLUSTER), _e64 + (_e46 * _e69), params, lights, rt2_2, r2_3, boxes, wg_counts, pos, nrm, valid, e, kept, tile_lights, list_count, cluster_hits, hit_count, _buffer_sizes);
    }
    count_receiver(li, counters, wg_counts, valid, kept, _buffer_sizes);
    if (inside_1) {
        metal::float3 _e75 = e;
        uint _e77 = kept;
        irradiance[pix_1] = metal::float4(_e75, static_cast<float>(_e77));
        metal::float3 _e83 = nrm;
        float _e85 = eye_distance;
        guide[pix_1] = metal::float4(_e83, _e85);
        return;
    } else {
        return;
    }
}
