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
    uint size14;
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
typedef uint type_10[1];
typedef GpuBox type_11[1];
typedef metal::float4 type_12[1];
typedef GpuMaterial type_13[1];
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
    metal::float3 inner[4];
};
struct type_16 {
    uint inner[1024];
};
struct type_18 {
    metal::atomic_uint inner[4];
};
struct type_20 {
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
constant uint HALF = 4u;
constant uint QUARTER_LIGHTS = 256u;

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
    metal::float3 q_1 = metal::clamp(c, bmin, bmax);
    metal::float3 v_6 = q_1 - c;
    return metal::dot(v_6, v_6) <= (r * r);
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
    float m_1 = metal::max(metal::dot(v, v), metal::max(min_d2_, MIN_D2_));
    return ((metal::max(metal::dot(n_l, v), 0.0) * metal::max(-(metal::dot(n_x, v)), 0.0)) * INV_PI) / (m_1 * m_1);
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
    bool local_6 = {};
    if (!((n_l_1 <= 0.0))) {
        local_6 = n_v <= 0.0;
    } else {
        local_6 = true;
    }
    bool _e11 = local_6;
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
    float c_2 = metal::saturate(1.0 - v_h);
    float c2_ = c_2 * c_2;
    return f0_ + ((metal::float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_2));
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
    metal::float3 h_2 = v_1 + l;
    float len2_ = metal::dot(h_2, h_2);
    if (len2_ <= 0.0) {
        return 0.0;
    }
    return metal::saturate(metal::dot(v_1, h_2) / metal::sqrt(len2_));
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
    bool local_7 = {};
    float n_l_2 = metal::dot(n, l_1);
    float n_v_1 = metal::dot(n, v_2);
    if (!((n_l_2 <= 0.0))) {
        local_7 = n_v_1 <= 0.0;
    } else {
        local_7 = true;
    }
    bool _e18 = local_7;
    if (_e18) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    metal::float3 hs = v_2 + l_1;
    float inv = 1.0 / metal::sqrt(metal::dot(hs, hs));
    metal::float3 h_3 = hs * inv;
    metal::float3 c_3 = metal::cross(n, h_3);
    float _e32 = ggx_d(metal::dot(n, h_3), metal::dot(c_3, c_3), alpha_3);
    metal::float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, metal::dot(v_2, h_3));
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
    bool local_8 = {};
    bool local_9 = {};
    if (!((metallic_6 > 0.0))) {
        local_8 = f90_d_5 > 0.0;
    } else {
        local_8 = true;
    }
    bool _e11 = local_8;
    if (!(_e11)) {
        local_9 = metal::max(metal::max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0.0;
    } else {
        local_9 = true;
    }
    bool _e23 = local_9;
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
    metal::float4 p_5 = position_tex.read(metal::uint2(texel), 0);
    return (p_5.w > 0.0) ? metal::float4(p_5.xyz, 1.0) : metal::float4(0.0);
}

GbTexel gbuffer_at(
    uint i,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> position_tex,
    metal::texture2d<float, metal::access::sample> normal_tex
) {
    bool local_10 = {};
    uint _e3 = view.width;
    uint _e8 = view.width;
    metal::int2 texel_1 = metal::int2(static_cast<int>(naga_mod(i, _e3)), static_cast<int>(naga_div(i, _e8)));
    metal::float4 _e12 = surface_at(texel_1, position_tex);
    metal::float4 _e15 = normal_tex.read(metal::uint2(texel_1), 0);
    metal::float3 n_4 = _e15.xyz;
    float len2_1 = metal::dot(n_4, n_4);
    if (_e12.w > 0.0) {
        local_10 = len2_1 > 0.0;
    } else {
        local_10 = false;
    }
    bool valid_1 = local_10;
    metal::float3 _e30 = view.eye;
    metal::float3 v_7 = _e12.xyz - _e30;
    metal::float4 position = metal::float4(_e12.xyz, valid_1 ? 1.0 : 0.0);
    metal::float4 normal = valid_1 ? metal::float4(n_4 / metal::float3(metal::sqrt(len2_1)), metal::sqrt(metal::dot(v_7, v_7))) : metal::float4(0.0, 0.0, 0.0, 1000000000000000000000000000000.0);
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
    device type_13 const& materials,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e4 = view.width;
    uint _e9 = view.width;
    metal::int2 texel_2 = metal::int2(static_cast<int>(naga_mod(i_1, _e4)), static_cast<int>(naga_div(i_1, _e9)));
    metal::float4 _e16 = normal_tex.read(metal::uint2(texel_2), 0);
    GpuMaterial m_2 = materials[naga_f2u32(_e16.w)];
    metal::float3 _e23 = view.eye;
    bool _e29 = has_specular(m_2.metallic, m_2.f0_, m_2.f90_);
    return Glossy {m_2, metal::normalize(_e23 - x), _e29};
}

metal::float3 glossy_term(
    Glossy g_2,
    GpuLight l_4,
    metal::float3 n_3,
    metal::float3 v_5,
    float t
) {
    bool local_11 = {};
    if (!(!(g_2.on))) {
        local_11 = t <= 0.0;
    } else {
        local_11 = true;
    }
    bool _e13 = local_11;
    if (_e13) {
        return metal::float3(0.0);
    }
    metal::float3 _e30 = specular_correction(g_2.m.albedo, g_2.m.metallic, g_2.m.f0_, g_2.m.f90_, g_2.m.alpha, n_3, g_2.v, metal::normalize(-(v_5)));
    return (l_4.intensity * _e30) * t;
}

float near_r2_of(
    uint slot,
    device type_5 const& r2_5,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e3 = r2_5[slot];
    float _e5 = vpl_near_range2_(_e3, P);
    return _e5;
}

float near_cull_r2_of(
    uint slot_1,
    float near_r2_3,
    device type_5 const& r2_5,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e2 = near_r2_of(slot_1, r2_5, _buffer_sizes);
    float _e3 = vpl_near_cull_range2_(_e2, near_r2_3);
    return _e3;
}

WorkgroupBox load_receiver(
    uint li_3,
    uint pix,
    bool inside,
    threadgroup type_7& wg_lo,
    threadgroup type_7& wg_hi,
    threadgroup WorkgroupBox& wg_box,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> position_tex,
    metal::texture2d<float, metal::access::sample> normal_tex,
    device type_13 const& materials,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread float& eye_distance,
    thread bool& valid,
    thread Glossy& g_4,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float4 p_2 = metal::float4(0.0);
    bool local_12 = {};
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
        local_12 = _e23 > 0.0;
    } else {
        local_12 = false;
    }
    bool _e27 = local_12;
    valid = _e27;
    bool _e29 = valid;
    if (_e29) {
        metal::float3 _e32 = pos;
        Glossy _e33 = glossy_at(pix, _e32, view, normal_tex, materials, _buffer_sizes);
        g_4 = _e33;
    }
    metal::float3 _e35 = pos;
    bool _e37 = valid;
    WorkgroupBox _e38 = workgroup_box(li_3, _e35, _e37, wg_lo, wg_hi, wg_box);
    return _e38;
}

uint cluster_slot(
    uint c_1,
    uint k,
    constant VplParams& params,
    device type_10 const& near_slots,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params.near_clusters_at;
    uint _e11 = near_slots[((c_1 - _e5) * CLUSTER) + k];
    return _e11;
}

float cull_r2_of(
    uint slot_2,
    constant VplParams& params,
    device type_5 const& r2_5,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e3 = params.near_r2_;
    float _e4 = near_cull_r2_of(slot_2, _e3, r2_5, _buffer_sizes);
    return _e4;
}

void quarter_boxes(
    uint li_4,
    metal::uint3 lid_1,
    threadgroup type_7& wg_lo,
    threadgroup type_7& wg_hi,
    thread metal::float3& pos,
    thread bool& valid,
    threadgroup type_15& quarter_lo,
    threadgroup type_15& quarter_hi,
    thread uint& quarter
) {
    metal::float3 lo_1 = metal::float3(340282350000000000000000000000000000000.0);
    metal::float3 hi_1 = metal::float3(-340282350000000000000000000000000000000.0);
    uint y = {};
    uint x_1 = {};
    quarter = ((lid_1.x >= HALF) ? 1u : 0u) + ((lid_1.y >= HALF) ? 2u : 0u);
    metal::float3 _e17 = pos;
    bool _e19 = valid;
    WorkgroupBox _e20 = point_box(_e17, _e19);
    wg_lo.inner[li_4] = _e20.lo;
    wg_hi.inner[li_4] = _e20.hi;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    if (li_4 < 4u) {
        uint x0_ = naga_mod(li_4, 2u) * HALF;
        uint y0_ = naga_div(li_4, 2u) * HALF;
        y = y0_;
        uint2 loop_bound_1 = uint2(4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (metal::all(loop_bound_1 == uint2(0u))) { break; }
            loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e81 = y;
                y = _e81 + 1u;
            }
            loop_init_1 = false;
            uint _e44 = y;
            if (_e44 < metal::min(y0_ + HALF, TILE)) {
            } else {
                break;
            }
            {
                x_1 = x0_;
                uint2 loop_bound_2 = uint2(4294967295u);
                bool loop_init_2 = true;
                while(true) {
                    if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                    loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                    if (!loop_init_2) {
                        uint _e78 = x_1;
                        x_1 = _e78 + 1u;
                    }
                    loop_init_2 = false;
                    uint _e51 = x_1;
                    if (_e51 < metal::min(x0_ + HALF, TILE)) {
                    } else {
                        break;
                    }
                    {
                        metal::float3 _e57 = lo_1;
                        uint _e59 = y;
                        uint _e62 = x_1;
                        metal::float3 _e65 = wg_lo.inner[(_e59 * TILE) + _e62];
                        lo_1 = metal::min(_e57, _e65);
                        metal::float3 _e67 = hi_1;
                        uint _e69 = y;
                        uint _e72 = x_1;
                        metal::float3 _e75 = wg_hi.inner[(_e69 * TILE) + _e72];
                        hi_1 = metal::max(_e67, _e75);
                    }
                }
            }
        }
        metal::float3 _e85 = lo_1;
        quarter_lo.inner[li_4] = _e85;
        metal::float3 _e88 = hi_1;
        quarter_hi.inner[li_4] = _e88;
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return;
}

void list_clear(
    uint li_5,
    threadgroup type_18& quarter_count,
    threadgroup metal::atomic_uint& fullest
) {
    if (li_5 < 4u) {
        metal::atomic_store_explicit(&quarter_count.inner[li_5], 0u, metal::memory_order_relaxed);
    }
    if (li_5 == 0u) {
        metal::atomic_store_explicit(&fullest, 0u, metal::memory_order_relaxed);
        return;
    } else {
        return;
    }
}

bool list_full(
    threadgroup metal::atomic_uint& fullest
) {
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_1 = metal::atomic_load_explicit(&fullest, metal::memory_order_relaxed);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return (unnamed_1 + CLUSTER) > QUARTER_LIGHTS;
}

uint quarter_add(
    uint q,
    uint slot_3,
    metal::float3 p_3,
    float radius,
    threadgroup type_15& quarter_lo,
    threadgroup type_15& quarter_hi,
    threadgroup type_16& quarter_lights,
    threadgroup type_18& quarter_count
) {
    metal::float3 lo_3 = quarter_lo.inner[q];
    metal::float3 hi_3 = quarter_hi.inner[q];
    if (lo_3.x > hi_3.x) {
        return 0u;
    }
    bool _e14 = sphere_overlaps_aabb(p_3, radius, lo_3, hi_3);
    if (!(_e14)) {
        return 0u;
    }
    uint _e20 = metal::atomic_fetch_add_explicit(&quarter_count.inner[q], 1u, metal::memory_order_relaxed);
    quarter_lights.inner[(q * QUARTER_LIGHTS) + _e20] = slot_3;
    return _e20 + 1u;
}

void list_add(
    uint slot_4,
    metal::float3 p_4,
    float radius_1,
    threadgroup type_15& quarter_lo,
    threadgroup type_15& quarter_hi,
    threadgroup type_16& quarter_lights,
    threadgroup type_18& quarter_count,
    threadgroup metal::atomic_uint& fullest
) {
    uint _e4 = quarter_add(0u, slot_4, p_4, radius_1, quarter_lo, quarter_hi, quarter_lights, quarter_count);
    uint _e6 = quarter_add(1u, slot_4, p_4, radius_1, quarter_lo, quarter_hi, quarter_lights, quarter_count);
    uint a = metal::max(_e4, _e6);
    uint _e9 = quarter_add(2u, slot_4, p_4, radius_1, quarter_lo, quarter_hi, quarter_lights, quarter_count);
    uint _e11 = quarter_add(3u, slot_4, p_4, radius_1, quarter_lo, quarter_hi, quarter_lights, quarter_count);
    uint b_1 = metal::max(_e9, _e11);
    uint _e15 = metal::atomic_fetch_max_explicit(&fullest, metal::max(a, b_1), metal::memory_order_relaxed);
    return;
}

void shade_list(
    uint count,
    uint first,
    constant VplParams& params,
    device type_9 const& lights,
    device type_5 const& rt2_2,
    device type_5 const& r2_5,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread bool& valid,
    thread metal::float3& e,
    thread uint& kept,
    thread metal::float3& s,
    thread Glossy& g_4,
    threadgroup type_16& quarter_lights,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint m = 0u;
    bool _e3 = valid;
    if (!(_e3)) {
        return;
    }
    float _e6 = interleave_flux_scale(P);
    float unscale = 1.0 / _e6;
    uint2 loop_bound_3 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e65 = m;
            m = _e65 + 1u;
        }
        loop_init_3 = false;
        uint _e11 = m;
        if (_e11 < count) {
        } else {
            break;
        }
        {
            uint _e14 = m;
            uint slot_5 = quarter_lights.inner[first + _e14];
            GpuLight l_5 = lights[slot_5];
            metal::float3 _e22 = pos;
            metal::float3 v_8 = _e22 - l_5.p0_;
            float _e27 = rt2_2[slot_5];
            float _e29 = vpl_near_range2_(_e27, P);
            float _e30 = near_r2_of(slot_5, r2_5, _buffer_sizes);
            float _e34 = params.near_r2_;
            float _e35 = vpl_near_slc_share(_e29, _e30, metal::dot(v_8, v_8), _e34);
            if (_e35 > 0.0) {
                metal::float3 _e40 = nrm;
                float _e43 = params.min_d2_;
                float _e44 = vpl_transfer(l_5.p1_, _e40, v_8, _e43);
                float t_3 = (_e44 * _e35) * unscale;
                metal::float3 _e48 = e;
                e = _e48 + (l_5.intensity * t_3);
                metal::float3 _e53 = s;
                Glossy _e55 = g_4;
                metal::float3 _e57 = nrm;
                metal::float3 _e58 = glossy_term(_e55, l_5, _e57, v_8, t_3);
                s = _e53 + _e58;
                uint _e61 = kept;
                kept = _e61 + 1u;
            }
        }
    }
    return;
}

void list_shade(
    constant VplParams& params,
    device type_9 const& lights,
    device type_5 const& rt2_2,
    device type_5 const& r2_5,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread bool& valid,
    thread metal::float3& e,
    thread uint& kept,
    thread metal::float3& s,
    thread Glossy& g_4,
    threadgroup type_16& quarter_lights,
    threadgroup type_18& quarter_count,
    thread uint& quarter,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint _e2 = quarter;
    uint _e4 = metal::atomic_load_explicit(&quarter_count.inner[_e2], metal::memory_order_relaxed);
    uint _e6 = quarter;
    shade_list(_e4, _e6 * QUARTER_LIGHTS, params, lights, rt2_2, r2_5, pos, nrm, valid, e, kept, s, g_4, quarter_lights, _buffer_sizes);
    return;
}

void cull_tile(
    uint li_6,
    metal::float3 lo_2,
    metal::float3 hi_2,
    metal::uint4 grid,
    uint clusters_at,
    uint groups_at,
    constant VplParams& params,
    device type_9 const& lights,
    device type_10 const& near_slots,
    device type_11 const& boxes,
    device type_5 const& rt2_2,
    device type_5 const& r2_5,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread bool& valid,
    thread metal::float3& e,
    thread uint& kept,
    thread metal::float3& s,
    thread Glossy& g_4,
    threadgroup type_15& quarter_lo,
    threadgroup type_15& quarter_hi,
    threadgroup type_16& quarter_lights,
    threadgroup type_18& quarter_count,
    threadgroup metal::atomic_uint& fullest,
    thread uint& quarter,
    threadgroup type_20& cluster_hits,
    threadgroup metal::atomic_uint& hit_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint g_3 = 0u;
    uint h = {};
    list_clear(li_6, quarter_count, fullest);
    uint _e10 = group_count(grid.x, grid.y, grid.z, grid.w);
    uint2 loop_bound_4 = uint2(4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e84 = g_3;
            g_3 = _e84 + 1u;
        }
        loop_init_4 = false;
        uint _e13 = g_3;
        if (_e13 < _e10) {
        } else {
            break;
        }
        {
            uint _e16 = g_3;
            GpuBox gb = boxes[groups_at + _e16];
            bool _e22 = box_overlaps_box(gb.lo, gb.hi, lo_2, hi_2);
            if (!(_e22)) {
                continue;
            }
            uint _e24 = g_3;
            uint _e29 = group_first(_e24, grid.x, grid.y, grid.z, grid.w);
            uint first_1 = clusters_at + _e29;
            uint _e31 = g_3;
            uint _e36 = group_clusters(_e31, grid.x, grid.y, grid.z, grid.w);
            if (li_6 == 0u) {
                metal::atomic_store_explicit(&hit_count, 0u, metal::memory_order_relaxed);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            if (li_6 < _e36) {
                GpuBox cb = boxes[first_1 + li_6];
                bool _e48 = box_overlaps_box(cb.lo, cb.hi, lo_2, hi_2);
                if (_e48) {
                    uint _e52 = metal::atomic_fetch_add_explicit(&hit_count, 1u, metal::memory_order_relaxed);
                    cluster_hits.inner[_e52] = first_1 + li_6;
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            uint unnamed_2 = metal::atomic_load_explicit(&hit_count, metal::memory_order_relaxed);
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
            h = 0u;
            uint2 loop_bound_5 = uint2(4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (metal::all(loop_bound_5 == uint2(0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e81 = h;
                    h = _e81 + 1u;
                }
                loop_init_5 = false;
                uint _e59 = h;
                if (_e59 < unnamed_2) {
                } else {
                    break;
                }
                {
                    bool _e61 = list_full(fullest);
                    if (_e61) {
                        list_shade(params, lights, rt2_2, r2_5, pos, nrm, valid, e, kept, s, g_4, quarter_lights, quarter_count, quarter, _buffer_sizes);
                        metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
                        list_clear(li_6, quarter_count, fullest);
                        metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
                    }
                    uint _e63 = h;
                    uint _e65 = cluster_hits.inner[_e63];
                    uint _e66 = cluster_slot(_e65, li_6, params, near_slots, _buffer_sizes);
                    GpuLight l_6 = lights[_e66];
                    if (metal::any(l_6.intensity != metal::float3(0.0))) {
                        float _e75 = cull_r2_of(_e66, params, r2_5, _buffer_sizes);
                        float _e76 = cull_radius(_e75);
                        bool _e78 = sphere_overlaps_aabb(l_6.p0_, _e76, lo_2, hi_2);
                        if (_e78) {
                            list_add(_e66, l_6.p0_, _e76, quarter_lo, quarter_hi, quarter_lights, quarter_count, fullest);
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    list_shade(params, lights, rt2_2, r2_5, pos, nrm, valid, e, kept, s, g_4, quarter_lights, quarter_count, quarter, _buffer_sizes);
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
, device type_10 const& near_slots [[user(fake0)]]
, device type_11 const& boxes [[user(fake0)]]
, device type_5 const& rt2_2 [[user(fake0)]]
, device type_5 const& r2_5 [[user(fake0)]]
, device type_12& irradiance [[user(fake0)]]
, device type_13 const& materials [[user(fake0)]]
, device type_12& specular [[user(fake0)]]
, threadgroup type_15& quarter_lo
, threadgroup type_15& quarter_hi
, threadgroup type_16& quarter_lights
, threadgroup type_18& quarter_count
, threadgroup metal::atomic_uint& fullest
, threadgroup type_20& cluster_hits
, threadgroup metal::atomic_uint& hit_count
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    metal::float3 pos = {};
    metal::float3 nrm = {};
    float eye_distance = {};
    bool valid = {};
    metal::float3 e = {};
    uint kept = {};
    metal::float3 s = {};
    Glossy g_4 = {};
    uint quarter = {};
    if (li == 0u) {
        wg_lo = {};
        wg_hi = {};
        wg_box = {};
        quarter_lo = {};
        quarter_hi = {};
        quarter_lights = {};
        for (int __i0 = 0; __i0 < 4; __i0++) {
            metal::atomic_store_explicit(&quarter_count.inner[__i0], 0, metal::memory_order_relaxed);
        }
        metal::atomic_store_explicit(&fullest, 0, metal::memory_order_relaxed);
        cluster_hits = {};
        metal::atomic_store_explicit(&hit_count, 0, metal::memory_order_relaxed);
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    bool local = {};
    uint px = (wg.x * TILE) + lid.x;
    uint py = (wg.y * TILE) + lid.y;
    uint _e15 = params.width;
    if (px < _e15) {
        uint _e21 = params.height;
        local = py < _e21;
    } else {
        local = false;
    }
    bool inside_1 = local;
    uint _e27 = params.width;
    uint pix_1 = (py * _e27) + px;
    WorkgroupBox _e30 = load_receiver(li, pix_1, inside_1, wg_lo, wg_hi, wg_box, view, position_tex, normal_tex, materials, pos, nrm, eye_distance, valid, g_4, _buffer_sizes);
    bool _e31 = box_is_empty(_e30);
    if (!(_e31)) {
        quarter_boxes(li, lid, wg_lo, wg_hi, pos, valid, quarter_lo, quarter_hi, quarter);
        metal::uint4 _e37 = params.near_grid;
        uint _e40 = params.near_clusters_at;
        uint _e43 = params.near_groups_at;
        cull_tile(li, _e30.lo, _e30.hi, _e37, _e40, _e43, params, lights, near_slots, boxes, rt2_2, r2_5, pos, nrm, valid, e, kept, s, g_4, quarter_lo, quarter_hi, quarter_lights, quarter_count, fullest, quarter, cluster_hits, hit_count, _buffer_sizes);
    }
    bool _e45 = valid;
    if (_e45) {
        metal::float4 old = irradiance[pix_1];
        metal::float3 _e53 = e;
        uint _e57 = kept;
        irradiance[pix_1] = metal::float4(old.xyz + _e53, old.w + static_cast<float>(_e57));
        metal::float4 _e65 = specular[pix_1];
        metal::float3 _e68 = s;
        specular[pix_1] = metal::float4(_e65.xyz + _e68, 0.0);
        return;
    } else {
        return;
    }
}
