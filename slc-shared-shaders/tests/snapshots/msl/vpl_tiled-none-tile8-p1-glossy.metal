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
constant uint P = 1u;
constant uint TILE = 8u;
constant uint THREADS = 64u;
constant uint BOX_THREADS = 64u;
constant uint MAX_TILE_LIGHTS = 1024u;

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
    bool local_1 = {};
    if (!((n_l_1 <= 0.0))) {
        local_1 = n_v <= 0.0;
    } else {
        local_1 = true;
    }
    bool _e11 = local_1;
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
    bool local_2 = {};
    float n_l_2 = metal::dot(n, l_1);
    float n_v_1 = metal::dot(n, v_2);
    if (!((n_l_2 <= 0.0))) {
        local_2 = n_v_1 <= 0.0;
    } else {
        local_2 = true;
    }
    bool _e18 = local_2;
    if (_e18) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    metal::float3 hs = v_2 + l_1;
    float inv = 1.0 / metal::sqrt(metal::dot(hs, hs));
    metal::float3 h_1 = hs * inv;
    metal::float3 c_1 = metal::cross(n, h_1);
    float _e32 = ggx_d(metal::dot(n, h_1), metal::dot(c_1, c_1), alpha_3);
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
    bool local_3 = {};
    bool local_4 = {};
    if (!((metallic_6 > 0.0))) {
        local_3 = f90_d_5 > 0.0;
    } else {
        local_3 = true;
    }
    bool _e11 = local_3;
    if (!(_e11)) {
        local_4 = metal::max(metal::max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0.0;
    } else {
        local_4 = true;
    }
    bool _e23 = local_4;
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
    float d2_,
    float near_r2_
) {
    if (near_r2_ <= 0.0) {
        return 0.0;
    }
    float t_2 = metal::clamp((near_r2_ - d2_) / (0.75 * near_r2_), 0.0, 1.0);
    return (t_2 * t_2) * (3.0 - (2.0 * t_2));
}

float vpl_far_weight(
    float d2_1,
    float near_r2_1
) {
    float _e2 = vpl_near_weight(d2_1, near_r2_1);
    return 1.0 - _e2;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

WorkgroupBox workgroup_bounds(
    uint li_1,
    metal::float3 lo,
    metal::float3 hi,
    threadgroup type_6& wg_lo,
    threadgroup type_6& wg_hi,
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
    threadgroup type_6& wg_lo,
    threadgroup type_6& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    WorkgroupBox _e3 = point_box(p_1, has_1);
    WorkgroupBox _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi, wg_lo, wg_hi, wg_box);
    return _e6;
}

metal::float4 surface_at(
    metal::int2 texel,
    metal::texture2d<float, metal::access::sample> position_tex
) {
    metal::float4 p_3 = position_tex.read(metal::uint2(texel), 0);
    return (p_3.w > 0.0) ? metal::float4(p_3.xyz, 1.0) : metal::float4(0.0);
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
    metal::float3 n_4 = _e15.xyz;
    float len2_1 = metal::dot(n_4, n_4);
    if (_e12.w > 0.0) {
        local_5 = len2_1 > 0.0;
    } else {
        local_5 = false;
    }
    bool valid_1 = local_5;
    metal::float3 _e30 = view.eye;
    metal::float3 v_6 = _e12.xyz - _e30;
    metal::float4 position = metal::float4(_e12.xyz, valid_1 ? 1.0 : 0.0);
    metal::float4 normal = valid_1 ? metal::float4(n_4 / metal::float3(metal::sqrt(len2_1)), metal::sqrt(metal::dot(v_6, v_6))) : metal::float4(0.0, 0.0, 0.0, 1000000000000000000000000000000.0);
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
    Glossy g,
    GpuLight l_4,
    metal::float3 n_3,
    metal::float3 v_5,
    float t
) {
    bool local_6 = {};
    if (!(!(g.on))) {
        local_6 = t <= 0.0;
    } else {
        local_6 = true;
    }
    bool _e13 = local_6;
    if (_e13) {
        return metal::float3(0.0);
    }
    metal::float3 _e30 = specular_correction(g.m.albedo, g.m.metallic, g.m.f0_, g.m.f90_, g.m.alpha, n_3, g.v, metal::normalize(-(v_5)));
    return (l_4.intensity * _e30) * t;
}

WorkgroupBox load_receiver(
    uint li_3,
    uint pix,
    bool inside,
    threadgroup type_6& wg_lo,
    threadgroup type_6& wg_hi,
    threadgroup WorkgroupBox& wg_box,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> position_tex,
    metal::texture2d<float, metal::access::sample> normal_tex,
    device type_10 const& materials,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread float& eye_distance,
    thread bool& valid,
    thread Glossy& g_1,
    constant _mslBufferSizes& _buffer_sizes
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
    bool _e29 = valid;
    if (_e29) {
        metal::float3 _e32 = pos;
        Glossy _e33 = glossy_at(pix, _e32, view, normal_tex, materials, _buffer_sizes);
        g_1 = _e33;
    }
    metal::float3 _e35 = pos;
    bool _e37 = valid;
    WorkgroupBox _e38 = workgroup_box(li_3, _e35, _e37, wg_lo, wg_hi, wg_box);
    return _e38;
}

void shade_light(
    uint j_1,
    constant VplParams& params,
    device type_8 const& lights,
    thread metal::float3& pos,
    thread metal::float3& nrm,
    thread metal::float3& e,
    thread uint& kept,
    thread metal::float3& s,
    thread Glossy& g_1,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight l_5 = lights[j_1];
    metal::float3 _e5 = pos;
    metal::float3 v_7 = _e5 - l_5.p0_;
    float _e11 = params.near_r2_;
    float _e12 = vpl_far_weight(metal::dot(v_7, v_7), _e11);
    if (_e12 > 0.0) {
        metal::float3 _e17 = nrm;
        float _e20 = params.min_d2_;
        float _e21 = vpl_transfer(l_5.p1_, _e17, v_7, _e20);
        float t_3 = _e21 * _e12;
        metal::float3 _e24 = e;
        e = _e24 + (l_5.intensity * t_3);
        metal::float3 _e29 = s;
        Glossy _e31 = g_1;
        metal::float3 _e33 = nrm;
        metal::float3 _e34 = glossy_term(_e31, l_5, _e33, v_7, t_3);
        s = _e29 + _e34;
        uint _e37 = kept;
        kept = _e37 + 1u;
        return;
    } else {
        return;
    }
}

struct main_Input {
};
kernel void main_(
  metal::uint3 wg [[threadgroup_position_in_grid]]
, metal::uint3 lid [[thread_position_in_threadgroup]]
, uint li [[thread_index_in_threadgroup]]
, threadgroup type_6& wg_lo
, threadgroup type_6& wg_hi
, threadgroup WorkgroupBox& wg_box
, constant VplParams& params [[user(fake0)]]
, constant ViewParams& view [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, device type_8 const& lights [[user(fake0)]]
, device type_9& irradiance [[user(fake0)]]
, device type_9& guide [[user(fake0)]]
, device type_10 const& materials [[user(fake0)]]
, device type_9& specular [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    metal::float3 pos = {};
    metal::float3 nrm = {};
    float eye_distance = {};
    bool valid = {};
    metal::float3 e = {};
    uint kept = {};
    metal::float3 s = {};
    Glossy g_1 = {};
    if (li == 0u) {
        wg_lo = {};
        wg_hi = {};
        wg_box = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    bool local = {};
    uint j = {};
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
    WorkgroupBox _e41 = load_receiver(li, pix_1, inside_1, wg_lo, wg_hi, wg_box, view, position_tex, normal_tex, materials, pos, nrm, eye_distance, valid, g_1, _buffer_sizes);
    uint _e44 = params.subset_shift;
    uint _e46 = shifted_subset(sub, _e44, P);
    bool _e48 = valid;
    if (_e48) {
        uint _e51 = params.lights_per_subset;
        uint base_6 = _e46 * _e51;
        j = base_6;
        uint2 loop_bound_1 = uint2(4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (metal::all(loop_bound_1 == uint2(0u))) { break; }
            loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e71 = j;
                j = _e71 + 1u;
            }
            loop_init_1 = false;
            uint _e54 = j;
            uint _e57 = params.lights_per_subset;
            if (_e54 < (base_6 + _e57)) {
            } else {
                break;
            }
            {
                uint _e61 = j;
                metal::float3 _e64 = lights[_e61].intensity;
                if (metal::any(_e64 != metal::float3(0.0))) {
                    uint _e69 = j;
                    shade_light(_e69, params, lights, pos, nrm, e, kept, s, g_1, _buffer_sizes);
                }
            }
        }
    }
    if (inside_1) {
        metal::float3 _e76 = e;
        uint _e78 = kept;
        irradiance[pix_1] = metal::float4(_e76, static_cast<float>(_e78));
        metal::float3 _e84 = nrm;
        float _e86 = eye_distance;
        guide[pix_1] = metal::float4(_e84, _e86);
        metal::float3 _e91 = s;
        specular[pix_1] = metal::float4(_e91, 0.0);
        return;
    } else {
        return;
    }
}
