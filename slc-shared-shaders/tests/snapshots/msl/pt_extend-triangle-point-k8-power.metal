// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size1;
    uint size2;
    uint size3;
    uint size4;
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
struct GpuLightCone {
    metal::packed_float3 center;
    float radius;
    metal::packed_float3 axis;
    float cos_o;
    float phi;
    float cos_e;
    uint bvh_leaf;
    uint pad;
};
struct GpuGeoNode {
    metal::packed_float3 bmin;
    uint first;
    metal::packed_float3 bmax;
    uint count;
};
struct GpuTriangle {
    metal::packed_float3 v0_;
    uint material;
    metal::packed_float3 v1_;
    uint light;
    metal::packed_float3 v2_;
    uint pad;
};
struct GpuPathVertex {
    metal::packed_float3 position;
    uint alive;
    metal::packed_float3 normal;
    uint material;
    metal::packed_float3 weight;
    float pad1_;
    metal::packed_float3 gnormal;
    float pad2_;
    metal::packed_float3 wo;
    float pad3_;
};
struct GpuPathState {
    metal::packed_float3 origin;
    uint alive;
    metal::packed_float3 dir;
    uint rng;
    metal::packed_float3 beta;
    float pdf_bsdf;
    metal::packed_float3 prev;
    uint pad;
    metal::packed_float3 prev_normal;
    uint pad2_;
    metal::packed_float3 prev_r;
    uint pad3_;
    metal::float4 prev_lobe;
};
struct PtParams {
    metal::packed_float3 cam_pos;
    uint width;
    metal::packed_float3 cam_right;
    uint height;
    metal::packed_float3 cam_up;
    uint depth;
    metal::packed_float3 cam_forward;
    uint seed;
    uint pass_index;
    uint max_depth;
    float eps;
    float t_min;
};
struct GpuMaterial {
    metal::packed_float3 albedo;
    float metallic;
    metal::packed_float3 emission;
    float alpha;
    metal::packed_float3 f0_;
    float f90_;
};
typedef float type_4[1];
struct BshNode {
    metal::packed_float3 center;
    float radius;
    uint child;
    uint next;
    uint light;
    float extent;
};
struct GeoHit {
    float t;
    uint tri;
};
typedef GpuGeoNode type_6[1];
typedef GpuTriangle type_7[1];
struct type_8 {
    uint inner[64];
};
typedef GpuLightCone type_9[1];
typedef uint BvhNodes;
typedef GpuLight type_10[1];
typedef BshNode type_11[1];
typedef uint type_12[1];
typedef GpuMaterial type_13[1];
typedef metal::float4 type_14[1];
typedef GpuPathState type_15[1];
typedef GpuPathVertex type_16[1];
typedef uint BshNodes;
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
constant uint K = 8u;
constant BvhNodes BVH = 0u;
constant BshNodes BSH = 0u;
constant uint BSH_TILE_DEPTH = 8u;
constant uint BSH_TILE_SUBTREES = 256u;

float to_f32_(
    uint u
) {
    return static_cast<float>(u);
}

uint mul_lo_u32_(
    uint a,
    uint b
) {
    return a * b;
}

uint add_wrap_u32_(
    uint a_1,
    uint b_1
) {
    return a_1 + b_1;
}

float f32_from_bits(
    uint u_1
) {
    return as_type<float>(u_1);
}

float xi_from_bits(
    uint bits
) {
    float _e3 = to_f32_(bits >> 8u);
    return _e3 * XI_STEP;
}

uint pcg_hash(
    uint x
) {
    uint _e2 = mul_lo_u32_(x, 747796405u);
    uint _e4 = add_wrap_u32_(_e2, 2891336453u);
    uint _e12 = mul_lo_u32_((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4, 277803737u);
    return (_e12 >> 22u) ^ _e12;
}

uint point_stream(
    uint seed,
    uint point,
    uint frame
) {
    uint _e3 = pcg_hash(frame);
    uint _e5 = pcg_hash(point ^ _e3);
    uint _e7 = pcg_hash(seed ^ _e5);
    return _e7;
}

uint path_stream(
    uint seed_1,
    uint pixel,
    uint pass_index
) {
    uint _e4 = add_wrap_u32_(pass_index, PICK_STREAM);
    uint _e5 = point_stream(seed_1, pixel, _e4);
    return _e5;
}

float rr_probability(
    float rt2_,
    float d2_
) {
    if (d2_ <= rt2_) {
        return 1.0;
    }
    return rt2_ / d2_;
}

bool sphere_contains_point(
    metal::float3 c,
    float r,
    metal::float3 x_1
) {
    metal::float3 v_10 = x_1 - c;
    return metal::dot(v_10, v_10) <= (r * r);
}

float area_to_solid_angle_pdf(
    float pdf_area,
    float d2_1,
    float cos_light
) {
    float c_5 = metal::abs(cos_light);
    if (c_5 <= 0.0) {
        return 0.0;
    }
    return (pdf_area * d2_1) / c_5;
}

float bsh_scaled_radius(
    BshNode node,
    float scale
) {
    if (scale == 1.0) {
        return node.radius;
    }
    if (node.child == BSH_NONE) {
        return node.extent + (scale * (node.radius - node.extent));
    }
    return node.radius * scale;
}

float bsh_range_bound(
    BshNode node_1
) {
    if (node_1.child == BSH_NONE) {
        return node_1.radius - node_1.extent;
    }
    float _e8 = f32_from_bits(node_1.light);
    return _e8;
}

float bsh_reach_bound(
    BshNode node_2,
    float w_1
) {
    float _e5 = bsh_range_bound(node_2);
    return node_2.extent + ((w_1 * 1.001) * _e5);
}

float reservoir_weight(
    uint n,
    uint k
) {
    float _e2 = to_f32_(n);
    float _e3 = to_f32_(k);
    return metal::max(_e2 / _e3, 1.0);
}

float reservoir_select_pdf(
    uint seen,
    bool in_range,
    uint k_1
) {
    uint others = {};
    bool local_3 = {};
    others = seen;
    if (in_range) {
        local_3 = seen > 0u;
    } else {
        local_3 = false;
    }
    bool _e9 = local_3;
    if (_e9) {
        others = seen - 1u;
    }
    uint _e12 = others;
    float _e15 = reservoir_weight(_e12 + 1u, k_1);
    return 1.0 / _e15;
}

float mis_power(
    float pdf_a,
    float pdf_b
) {
    float a2_ = pdf_a * pdf_a;
    float s = a2_ + (pdf_b * pdf_b);
    if (s <= 0.0) {
        return 0.0;
    }
    return a2_ / s;
}

float light_strategy_pdf(
    float select,
    float rt2_1,
    float d2_2,
    float area,
    float cos_y
) {
    bool local_4 = {};
    bool local_5 = {};
    if (!((d2_2 <= 0.0))) {
        local_4 = area <= 0.0;
    } else {
        local_4 = true;
    }
    bool _e13 = local_4;
    if (!(_e13)) {
        local_5 = cos_y <= 0.0;
    } else {
        local_5 = true;
    }
    bool _e20 = local_5;
    if (_e20) {
        return 0.0;
    }
    float _e22 = rr_probability(rt2_1, d2_2);
    float _e26 = area_to_solid_angle_pdf(1.0 / area, d2_2, cos_y);
    return (select * _e22) * _e26;
}

float cosine_pdf(
    float cos_theta
) {
    return metal::max(cos_theta, 0.0) * INV_PI;
}

metal::float3 onb_tangent(
    metal::float3 n_1
) {
    float s_1 = (n_1.z >= 0.0) ? 1.0 : -1.0;
    float a_7 = -1.0 / (s_1 + n_1.z);
    return metal::float3(1.0 + (((s_1 * n_1.x) * n_1.x) * a_7), ((s_1 * n_1.x) * n_1.y) * a_7, -(s_1) * n_1.x);
}

metal::float3 onb_bitangent(
    metal::float3 n_2
) {
    float s_2 = (n_2.z >= 0.0) ? 1.0 : -1.0;
    float a_8 = -1.0 / (s_2 + n_2.z);
    return metal::float3((n_2.x * n_2.y) * a_8, s_2 + ((n_2.y * n_2.y) * a_8), -(n_2.y));
}

metal::float3 onb_to_world(
    metal::float3 n_3,
    metal::float3 d
) {
    metal::float3 _e2 = onb_tangent(n_3);
    metal::float3 _e5 = onb_bitangent(n_3);
    return ((_e2 * d.x) + (_e5 * d.y)) + (n_3 * d.z);
}

metal::float3 onb_to_local(
    metal::float3 n_4,
    metal::float3 w_2
) {
    metal::float3 _e2 = onb_tangent(n_4);
    metal::float3 _e4 = onb_bitangent(n_4);
    return metal::float3(metal::dot(w_2, _e2), metal::dot(w_2, _e4), metal::dot(w_2, n_4));
}

metal::float3 cosine_direction(
    metal::float3 n_5,
    float u1_,
    float u2_
) {
    float r_8 = metal::sqrt(u1_);
    float phi = 6.2831855 * u2_;
    metal::float3 _e16 = onb_to_world(n_5, metal::float3(r_8 * metal::cos(phi), r_8 * metal::sin(phi), metal::sqrt(metal::max(1.0 - u1_, 0.0))));
    return metal::normalize(_e16);
}

float ggx_d(
    float cos_h,
    float sin2_h,
    float alpha
) {
    if (cos_h <= 0.0) {
        return 0.0;
    }
    float a2_1 = alpha * alpha;
    float t_1 = ((cos_h * cos_h) * a2_1) + sin2_h;
    return (a2_1 * INV_PI) / (t_1 * t_1);
}

float smith_root(
    float cos,
    float alpha_1
) {
    float a2_2 = alpha_1 * alpha_1;
    return metal::sqrt(((cos * cos) * (1.0 - a2_2)) + a2_2);
}

float smith_visibility(
    float n_l,
    float n_v,
    float alpha_2
) {
    bool local_6 = {};
    if (!((n_l <= 0.0))) {
        local_6 = n_v <= 0.0;
    } else {
        local_6 = true;
    }
    bool _e11 = local_6;
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
    float c_6 = metal::saturate(1.0 - v_h);
    float c2_ = c_6 * c_6;
    return f0_ + ((metal::float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_6));
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
    metal::float3 n_6,
    metal::float3 v_2,
    metal::float3 l_1
) {
    bool local_7 = {};
    float n_l_1 = metal::dot(n_6, l_1);
    float n_v_2 = metal::dot(n_6, v_2);
    if (!((n_l_1 <= 0.0))) {
        local_7 = n_v_2 <= 0.0;
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
    metal::float3 c_7 = metal::cross(n_6, h_3);
    float _e32 = ggx_d(metal::dot(n_6, h_3), metal::dot(c_7, c_7), alpha_3);
    metal::float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, metal::dot(v_2, h_3));
    float _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return _e34 * (_e32 * _e35);
}

metal::float3 brdf_eval(
    metal::float3 base_3,
    float metallic_3,
    metal::float3 f0_d_3,
    float f90_d_3,
    float alpha_4,
    metal::float3 n_7,
    metal::float3 v_3,
    metal::float3 l_2
) {
    if (metal::dot(n_7, l_2) <= 0.0) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    float _e15 = half_cosine(v_3, l_2);
    metal::float3 _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    metal::float3 _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_7, v_3, l_2);
    return _e16 + _e17;
}

bool has_specular(
    float metallic_4,
    metal::float3 f0_d_4,
    float f90_d_4
) {
    bool local_8 = {};
    bool local_9 = {};
    if (!((metallic_4 > 0.0))) {
        local_8 = f90_d_4 > 0.0;
    } else {
        local_8 = true;
    }
    bool _e11 = local_8;
    if (!(_e11)) {
        local_9 = metal::max(metal::max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0.0;
    } else {
        local_9 = true;
    }
    bool _e23 = local_9;
    return _e23;
}

float channel_mean(
    metal::float3 c_1
) {
    return ((c_1.x + c_1.y) + c_1.z) * 0.33333334;
}

metal::float4 receiver_lobe(
    metal::float3 base_4,
    float metallic_5,
    metal::float3 f0_d_5,
    float f90_d_5,
    float alpha_5,
    float n_v_1
) {
    bool local_10 = {};
    metal::float3 _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    float _e16 = channel_mean(((metal::float3(1.0, 1.0, 1.0) - _e10) * base_4) * (1.0 - metallic_5));
    if (!((n_v_1 <= 0.0))) {
        bool _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_10 = !(_e22);
    } else {
        local_10 = true;
    }
    bool _e25 = local_10;
    if (_e25) {
        return metal::float4(_e16, 0.0, alpha_5, n_v_1);
    }
    metal::float3 _e28 = specular_fresnel(base_4, metallic_5, f0_d_5, f90_d_5, n_v_1);
    float _e29 = channel_mean(_e28);
    return metal::float4(_e16, _e29, alpha_5, n_v_1);
}

float specular_probability(
    metal::float4 lobe
) {
    if (lobe.y <= 0.0) {
        return 0.0;
    }
    if (lobe.x <= 0.0) {
        return 1.0;
    }
    return metal::clamp(lobe.y / (lobe.y + lobe.x), 0.1, 0.9);
}

float specular_peak_factor(
    metal::float4 lobe_1
) {
    float _e6 = smith_root(lobe_1.w, lobe_1.z);
    return (lobe_1.y * 0.5) / (_e6 + metal::max(lobe_1.w, 0.0));
}

float receiver_peak(
    metal::float4 lobe_2
) {
    float _e2 = specular_peak_factor(lobe_2);
    return lobe_2.x + (_e2 / (lobe_2.z * lobe_2.z));
}

float range_scale(
    metal::float4 lobe_3
) {
    if (lobe_3.y <= 0.0) {
        return 1.0;
    }
    float _e5 = receiver_peak(lobe_3);
    return metal::clamp(_e5, 1.0, RANGE_SCALE_MAX);
}

metal::float4 range_lobe(
    metal::float4 lobe_4
) {
    if (lobe_4.y <= 0.0) {
        return metal::float4(1.0, 0.0, 1.0, 1.0);
    }
    float _e10 = specular_peak_factor(lobe_4);
    float _e14 = range_scale(lobe_4);
    return metal::float4(lobe_4.x, _e10, lobe_4.z * lobe_4.z, metal::sqrt(_e14));
}

metal::float3 mirror_dir(
    metal::float3 n_8,
    metal::float3 v_4
) {
    return (n_8 * (2.0 * metal::dot(n_8, v_4))) - v_4;
}

float bounded_vndf_k(
    metal::float3 wi,
    float alpha_6
) {
    float a_9 = metal::saturate(alpha_6);
    float s_3 = 1.0 + metal::sqrt((wi.x * wi.x) + (wi.y * wi.y));
    float a2_3 = a_9 * a_9;
    float s2_ = s_3 * s_3;
    return ((1.0 - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z));
}

metal::float3 ggx_vndf_sample(
    metal::float3 wi_1,
    float alpha_7,
    float u1_1,
    float u2_1
) {
    metal::float3 wi_std = metal::normalize(metal::float3(wi_1.x * alpha_7, wi_1.y * alpha_7, wi_1.z));
    float _e12 = bounded_vndf_k(wi_1, alpha_7);
    float b_5 = (wi_1.z > 0.0) ? (_e12 * wi_std.z) : wi_std.z;
    float phi_1 = 6.2831855 * u1_1;
    float z = ((1.0 - u2_1) * (1.0 + b_5)) - b_5;
    float sin_t = metal::sqrt(metal::saturate(1.0 - (z * z)));
    metal::float3 m_std = wi_std + metal::float3(sin_t * metal::cos(phi_1), sin_t * metal::sin(phi_1), z);
    metal::float3 m = metal::normalize(metal::float3(m_std.x * alpha_7, m_std.y * alpha_7, m_std.z));
    return (m * (2.0 * metal::dot(wi_1, m))) - wi_1;
}

float ggx_vndf_pdf(
    metal::float3 wi_2,
    metal::float3 wo,
    float alpha_8
) {
    bool local_11 = {};
    if (!((wi_2.z <= 0.0))) {
        local_11 = wo.z <= 0.0;
    } else {
        local_11 = true;
    }
    bool _e13 = local_11;
    if (_e13) {
        return 0.0;
    }
    metal::float3 hs_1 = wi_2 + wo;
    metal::float3 m_1 = hs_1 / metal::float3(metal::sqrt(metal::dot(hs_1, hs_1)));
    float _e28 = ggx_d(m_1.z, (m_1.x * m_1.x) + (m_1.y * m_1.y), alpha_8);
    float t_2 = metal::sqrt(((alpha_8 * alpha_8) * ((wi_2.x * wi_2.x) + (wi_2.y * wi_2.y))) + (wi_2.z * wi_2.z));
    float _e43 = bounded_vndf_k(wi_2, alpha_8);
    return _e28 / (2.0 * ((_e43 * wi_2.z) + t_2));
}

metal::float3 bsdf_sample(
    metal::float3 n_9,
    metal::float3 v_5,
    float alpha_9,
    float p_spec,
    float u1_2,
    float u2_2
) {
    if (u1_2 < p_spec) {
        if (metal::dot(n_9, v_5) <= 0.0) {
            return -(n_9);
        }
        metal::float3 _e11 = onb_to_local(n_9, v_5);
        metal::float3 _e13 = ggx_vndf_sample(_e11, alpha_9, u1_2 / p_spec, u2_2);
        metal::float3 _e14 = onb_to_world(n_9, _e13);
        return metal::normalize(_e14);
    }
    metal::float3 _e20 = cosine_direction(n_9, (u1_2 - p_spec) / (1.0 - p_spec), u2_2);
    return _e20;
}

float bsdf_pdf(
    metal::float3 n_10,
    metal::float3 v_6,
    metal::float3 l_3,
    float alpha_10,
    float p_spec_1
) {
    float _e6 = cosine_pdf(metal::dot(n_10, l_3));
    if (p_spec_1 <= 0.0) {
        return _e6;
    }
    metal::float3 _e9 = onb_to_local(n_10, v_6);
    metal::float3 _e10 = onb_to_local(n_10, l_3);
    float _e11 = ggx_vndf_pdf(_e9, _e10, alpha_10);
    return (p_spec_1 * _e11) + ((1.0 - p_spec_1) * _e6);
}

float cone_cos_of(
    metal::float3 v_7,
    float d2_3,
    float a_2,
    metal::float3 d_1
) {
    bool local_12 = {};
    bool local_13 = {};
    float vd = metal::dot(v_7, d_1);
    float h2_ = d2_3 - (a_2 * a_2);
    if (!((h2_ <= 0.0))) {
        if (vd >= 0.0) {
            local_13 = (vd * vd) >= h2_;
        } else {
            local_13 = false;
        }
        bool _e19 = local_13;
        local_12 = _e19;
    } else {
        local_12 = true;
    }
    bool _e21 = local_12;
    if (_e21) {
        return 1.0;
    }
    metal::float3 c_8 = metal::cross(v_7, d_1);
    return metal::min(((vd * metal::sqrt(h2_)) + (metal::sqrt(metal::dot(c_8, c_8)) * a_2)) / d2_3, 1.0);
}

float cone_cos_toward(
    metal::float3 center,
    float radius,
    metal::float3 p,
    metal::float3 d_2
) {
    metal::float3 v_11 = center - p;
    float _e6 = cone_cos_of(v_11, metal::dot(v_11, v_11), radius, d_2);
    return _e6;
}

float range_scale_at(
    metal::float4 rl,
    float cos_t
) {
    float t_3 = ((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0;
    return metal::clamp(rl.x + ((rl.y * rl.z) / (t_3 * t_3)), 1.0, rl.w * rl.w);
}

float range_scale_toward(
    metal::float4 rl_1,
    metal::float3 center_1,
    float radius_1,
    metal::float3 p_1,
    metal::float3 r_1
) {
    if (rl_1.w <= 1.0) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_1);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

bool finite3_(
    metal::float3 v_8
) {
    bool local_14 = {};
    bool local_15 = {};
    if (metal::abs(v_8.x) <= F32_MAX) {
        local_14 = metal::abs(v_8.y) <= F32_MAX;
    } else {
        local_14 = false;
    }
    bool _e12 = local_14;
    if (_e12) {
        local_15 = metal::abs(v_8.z) <= F32_MAX;
    } else {
        local_15 = false;
    }
    bool _e20 = local_15;
    return _e20;
}

float ray_inverse(
    float x_2
) {
    return 1.0 / ((metal::abs(x_2) < 0.000000000000000000000000000001) ? 0.000000000000000000000000000001 : x_2);
}

metal::float3 ray_inverse3_(
    metal::float3 d_3
) {
    float _e2 = ray_inverse(d_3.x);
    float _e4 = ray_inverse(d_3.y);
    float _e6 = ray_inverse(d_3.z);
    return metal::float3(_e2, _e4, _e6);
}

float ray_aabb(
    metal::float3 o,
    metal::float3 inv_d,
    metal::float3 bmin,
    metal::float3 bmax,
    float t_max
) {
    metal::float3 t0_ = (bmin - o) * inv_d;
    metal::float3 t1_ = (bmax - o) * inv_d;
    metal::float3 lo = metal::min(t0_, t1_);
    metal::float3 hi = metal::max(t0_, t1_);
    float t_in = metal::max(metal::max(lo.x, lo.y), metal::max(lo.z, 0.0));
    float t_out = metal::min(metal::min(hi.x, hi.y), metal::min(hi.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1.0;
}

metal::float3 triangle_normal(
    metal::float3 a_3,
    metal::float3 b_2,
    metal::float3 c_2
) {
    bool local_16 = {};
    metal::float3 n_15 = metal::cross(b_2 - a_3, c_2 - a_3);
    float l2_ = metal::dot(n_15, n_15);
    if (!(!((l2_ > 0.0)))) {
        local_16 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_16 = true;
    }
    bool _e17 = local_16;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_15 / metal::float3(metal::sqrt(l2_));
}

metal::float3 face_against(
    metal::float3 n_11,
    metal::float3 dir
) {
    return (metal::dot(n_11, dir) > 0.0) ? -(n_11) : n_11;
}

metal::float3 barycentric(
    metal::float3 p_2,
    metal::float3 a_4,
    metal::float3 b_3,
    metal::float3 c_3
) {
    metal::float3 e1_ = b_3 - a_4;
    metal::float3 e2_ = c_3 - a_4;
    metal::float3 q = p_2 - a_4;
    float d11_ = metal::dot(e1_, e1_);
    float d12_ = metal::dot(e1_, e2_);
    float d22_ = metal::dot(e2_, e2_);
    float den = (d11_ * d22_) - (d12_ * d12_);
    if (!((metal::abs(den) > 0.0))) {
        return metal::float3(1.0, 0.0, 0.0);
    }
    float w1_ = ((d22_ * metal::dot(q, e1_)) - (d12_ * metal::dot(q, e2_))) / den;
    float w2_ = ((d11_ * metal::dot(q, e2_)) - (d12_ * metal::dot(q, e1_))) / den;
    return metal::float3((1.0 - w1_) - w2_, w1_, w2_);
}

metal::float3 shading_normal(
    metal::float3 n0_,
    metal::float3 n1_,
    metal::float3 n2_,
    metal::float3 w_3,
    metal::float3 facing
) {
    bool local_17 = {};
    metal::float3 s_4 = ((n0_ * w_3.x) + (n1_ * w_3.y)) + (n2_ * w_3.z);
    float l2_1 = metal::dot(s_4, s_4);
    if (!(!((l2_1 > 0.000000000001)))) {
        local_17 = !((l2_1 < 300000000000000000000000000000000000000.0));
    } else {
        local_17 = true;
    }
    bool _e24 = local_17;
    if (_e24) {
        return facing;
    }
    metal::float3 n_16 = s_4 / metal::float3(metal::sqrt(l2_1));
    return (metal::dot(n_16, facing) < 0.0) ? -(n_16) : n_16;
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_4,
    metal::float3 a_5,
    metal::float3 b_4,
    metal::float3 c_4,
    float t_min,
    float t_max_1
) {
    bool local_18 = {};
    bool local_19 = {};
    bool local_20 = {};
    metal::float3 e1_1 = b_4 - a_5;
    metal::float3 e2_1 = c_4 - a_5;
    metal::float3 p_3 = metal::cross(d_4, e2_1);
    float det = metal::dot(e1_1, p_3);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv_1 = 1.0 / det;
    metal::float3 s_5 = o_1 - a_5;
    float u_3 = metal::dot(s_5, p_3) * inv_1;
    if (!((u_3 < 0.0))) {
        local_18 = u_3 > 1.0;
    } else {
        local_18 = true;
    }
    bool _e28 = local_18;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q_1 = metal::cross(s_5, e1_1);
    float v_12 = metal::dot(d_4, q_1) * inv_1;
    if (!((v_12 < 0.0))) {
        local_19 = (u_3 + v_12) > 1.0;
    } else {
        local_19 = true;
    }
    bool _e42 = local_19;
    if (_e42) {
        return -1.0;
    }
    float t_4 = metal::dot(e2_1, q_1) * inv_1;
    if (t_4 > t_min) {
        local_20 = t_4 < t_max_1;
    } else {
        local_20 = false;
    }
    bool _e51 = local_20;
    if (_e51) {
        return t_4;
    }
    return -1.0;
}

metal::float3 camera_dir(
    metal::float3 forward,
    metal::float3 right,
    metal::float3 up,
    float px,
    float py,
    float w_4,
    float h_1
) {
    float sx = ((2.0 * px) / w_4) - 1.0;
    float sy = 1.0 - ((2.0 * py) / h_1);
    return metal::normalize((forward + (right * sx)) + (up * sy));
}

float jittered_pixel(
    uint coord,
    float u_2
) {
    float _e2 = to_f32_(coord);
    return _e2 + u_2;
}

bool plays_roulette(
    uint depth
) {
    return depth >= ROULETTE_DEPTH;
}

bool sees_emission(
    metal::float3 gn,
    metal::float3 dir_1
) {
    return metal::dot(gn, dir_1) < 0.0;
}

bool continues_path(
    metal::float3 nd,
    metal::float3 n_12,
    metal::float3 ng
) {
    bool local_21 = {};
    if (metal::dot(nd, n_12) > 0.0) {
        local_21 = metal::dot(nd, ng) > 0.0;
    } else {
        local_21 = false;
    }
    bool _e12 = local_21;
    return _e12;
}

float path_survival(
    metal::float3 beta
) {
    return metal::clamp(metal::max(metal::max(beta.x, beta.y), beta.z), 0.05, 0.95);
}

float light_area(
    GpuLight l_4
) {
    if (l_4.kind == LIGHT_TRIANGLE) {
        return l_4.a;
    }
    return 0.0;
}

metal::float3 light_normal(
    GpuLight l_5
) {
    if (l_5.kind == LIGHT_TRIANGLE) {
        metal::float3 _e7 = triangle_normal(l_5.p0_, l_5.p1_, l_5.p2_);
        return _e7;
    }
    return metal::float3(0.0);
}

GeoHit trace(
    metal::float3 o_2,
    metal::float3 d_5,
    float t_min_1,
    float t_max_2,
    bool any_hit,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    GeoHit hit = {};
    type_8 stack = {};
    uint sp = 0u;
    uint node_3 = 0u;
    uint i = {};
    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((1 + (_buffer_sizes.size0 - 0 - 32) / 32) == 0u) {
        GeoHit _e13 = hit;
        return _e13;
    }
    metal::float3 _e14 = ray_inverse3_(d_5);
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e21 = node_3;
        GpuGeoNode n_17 = geo_nodes[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_17.bmin, n_17.bmax, _e27);
        if (_e28 >= 0.0) {
            if (n_17.count > 0u) {
                i = n_17.first;
                uint2 loop_bound_1 = uint2(4294967295u);
                bool loop_init = true;
                while(true) {
                    if (metal::all(loop_bound_1 == uint2(0u))) { break; }
                    loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                    if (!loop_init) {
                        uint _e58 = i;
                        i = _e58 + 1u;
                    }
                    loop_init = false;
                    uint _e36 = i;
                    if (_e36 < (n_17.first + n_17.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_5 = geo_tris[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_5, t_5.v0_, t_5.v1_, t_5.v2_, t_min_1, _e49);
                        if (_e50 > 0.0) {
                            hit.t = _e50;
                            uint _e55 = i;
                            hit.tri = _e55;
                            if (any_hit) {
                                GeoHit _e56 = hit;
                                return _e56;
                            }
                        }
                    }
                }
            } else {
                uint _e60 = sp;
                if (_e60 < 64u) {
                    uint _e63 = sp;
                    stack.inner[_e63] = n_17.first + 1u;
                    uint _e68 = sp;
                    sp = _e68 + 1u;
                }
                node_3 = n_17.first;
                continue;
            }
        }
        uint _e72 = sp;
        if (_e72 == 0u) {
            break;
        }
        uint _e75 = sp;
        sp = _e75 - 1u;
        uint _e78 = sp;
        uint _e80 = stack.inner[_e78];
        node_3 = _e80;
    }
    GeoHit _e81 = hit;
    return _e81;
}

float mis_weight(
    float pdf_a_1,
    float pdf_b_1
) {
    float _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

float light_range_scale(
    uint li,
    metal::float3 x_3,
    metal::float3 r_2,
    metal::float4 rl_2,
    device type_9 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_9 = light_cones[li];
    float _e9 = range_scale_toward(rl_2, c_9.center, c_9.radius, x_3, r_2);
    return _e9;
}

float select_pdf(
    uint li_1,
    metal::float3 x_4,
    metal::float3 n_13,
    metal::float3 r_3,
    metal::float4 lobe_5,
    metal::float4 rl_3,
    uint nee,
    bool in_range_1
) {
    float _e9 = reservoir_select_pdf(nee, in_range_1, K);
    return _e9;
}

float light_pdf_selected(
    uint li_2,
    metal::float3 x_5,
    metal::float3 r_4,
    metal::float4 rl_4,
    metal::float3 y,
    float sel,
    device type_9 const& light_cones,
    device type_4 const& rt2_2,
    device type_10 const& lights,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight l_6 = lights[li_2];
    metal::float3 v_13 = x_5 - y;
    float d2_5 = metal::dot(v_13, v_13);
    metal::float3 _e11 = light_normal(l_6);
    float cos_y_1 = (d2_5 > 0.0) ? metal::dot(_e11, v_13 / metal::float3(metal::sqrt(d2_5))) : 0.0;
    float _e20 = light_range_scale(li_2, x_5, r_4, rl_4, light_cones, _buffer_sizes);
    float _e23 = rt2_2[li_2];
    float _e25 = light_area(l_6);
    float _e26 = light_strategy_pdf(sel, _e20 * _e23, d2_5, _e25, cos_y_1);
    return _e26;
}

float light_pdf(
    uint li_3,
    metal::float3 x_6,
    metal::float3 n_14,
    metal::float3 r_5,
    metal::float4 lobe_6,
    metal::float4 rl_5,
    metal::float3 y_1,
    uint nee_1,
    bool in_range_2,
    device type_9 const& light_cones,
    device type_4 const& rt2_2,
    device type_10 const& lights,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e9 = select_pdf(li_3, x_6, n_14, r_5, lobe_6, rl_5, nee_1, in_range_2);
    float _e10 = light_pdf_selected(li_3, x_6, r_5, rl_5, y_1, _e9, light_cones, rt2_2, lights, _buffer_sizes);
    return _e10;
}

BshNode bsh_node(
    BshNodes nodes,
    uint i_1,
    device type_11 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshNode _e4 = bsh_nodes[i_1];
    return _e4;
}

float bsh_inner_scale(
    float a_6,
    metal::float3 v_9,
    float d2_4,
    metal::float3 r_6,
    metal::float4 rl_6
) {
    float _e5 = cone_cos_of(v_9, d2_4, a_6, r_6);
    float _e8 = range_scale_at(rl_6, _e5 + 0.000002);
    return _e8;
}

bool bsh_reaches(
    BshNode node_4,
    metal::float3 x_7,
    metal::float3 r_7,
    metal::float4 rl_7
) {
    bool local_22 = {};
    bool local_23 = {};
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_7);
    if (_e6) {
        return true;
    }
    if (!((rl_7.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, node_4.radius * (rl_7.w * 1.0001), x_7);
        local_22 = !(_e20);
    } else {
        local_22 = true;
    }
    bool _e23 = local_22;
    if (_e23) {
        return false;
    }
    metal::float3 v_14 = x_7 - node_4.center;
    float d2_6 = metal::dot(v_14, v_14);
    float _e29 = bsh_reach_bound(node_4, rl_7.w);
    if (d2_6 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        float _e38 = range_scale_toward(rl_7, node_4.center, node_4.extent, x_7, r_7);
        float _e41 = bsh_scaled_radius(node_4, metal::sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_7);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_14), d2_6, r_7, rl_7);
    float s_c = _e45 * 1.001;
    float _e50 = bsh_range_bound(node_4);
    float reach = node_4.extent + (metal::sqrt(s_c) * _e50);
    if (d2_6 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_23 = d2_6 <= (reach * reach);
    } else {
        local_23 = false;
    }
    bool _e63 = local_23;
    return _e63;
}

BshNode bsh_range_leaf(
    BshNodes nodes_1,
    uint i_2,
    device type_11 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint t = {};
    BshNode _e2 = bsh_node(nodes_1, i_2, bsh_nodes, _buffer_sizes);
    if ((_e2.light & BSH_TAIL) == 0u) {
        return _e2;
    }
    uint li_4 = _e2.light & 2147483647u;
    BshNode _e12 = bsh_node(nodes_1, 0u, bsh_nodes, _buffer_sizes);
    t = _e12.next;
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e15 = t;
        if (_e15 != BSH_NONE) {
        } else {
            break;
        }
        {
            uint _e18 = t;
            BshNode _e19 = bsh_node(nodes_1, _e18, bsh_nodes, _buffer_sizes);
            if (_e19.light == li_4) {
                return _e19;
            }
            t = _e19.next;
        }
    }
    return _e2;
}

float next_uniform(
    thread uint& state
) {
    uint _e1 = state;
    uint _e2 = pcg_hash(_e1);
    state = _e2;
    uint _e3 = state;
    float _e4 = xi_from_bits(_e3);
    return _e4;
}
uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}


struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, device type_6 const& geo_nodes [[user(fake0)]]
, device type_7 const& geo_tris [[user(fake0)]]
, device type_9 const& light_cones [[user(fake0)]]
, device type_4 const& rt2_2 [[user(fake0)]]
, device type_10 const& lights [[user(fake0)]]
, constant PtParams& params [[user(fake0)]]
, device type_11 const& bsh_nodes [[user(fake0)]]
, device type_12 const& light_leaf [[user(fake0)]]
, device type_13 const& materials [[user(fake0)]]
, device type_14 const& geo_normals [[user(fake0)]]
, device type_12 const& candidates [[user(fake0)]]
, device type_15& paths [[user(fake0)]]
, device type_16& vertices [[user(fake0)]]
, device type_14& radiance [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    GpuPathState st = {};
    uint h = {};
    GpuPathVertex v = {};
    bool local = {};
    float w = 1.0;
    uint rng = {};
    bool local_1 = {};
    bool local_2 = {};
    uint i_3 = gid.x;
    uint _e4 = params.width;
    uint _e7 = params.height;
    if (i_3 >= (_e4 * _e7)) {
        return;
    }
    uint _e13 = params.depth;
    if (_e13 == 0u) {
        uint _e18 = params.seed;
        uint _e21 = params.pass_index;
        uint _e22 = path_stream(_e18, i_3, _e21);
        h = _e22;
        uint _e26 = params.width;
        float _e28 = next_uniform(h);
        float _e29 = jittered_pixel(naga_mod(i_3, _e26), _e28);
        uint _e32 = params.width;
        float _e34 = next_uniform(h);
        float _e35 = jittered_pixel(naga_div(i_3, _e32), _e34);
        metal::float3 _e39 = params.cam_pos;
        st.origin = _e39;
        metal::float3 _e43 = params.cam_forward;
        metal::float3 _e46 = params.cam_right;
        metal::float3 _e49 = params.cam_up;
        uint _e52 = params.width;
        uint _e56 = params.height;
        metal::float3 _e58 = camera_dir(_e43, _e46, _e49, _e29, _e35, static_cast<float>(_e52), static_cast<float>(_e56));
        st.dir = _e58;
        st.alive = 1u;
        uint _e62 = h;
        st.rng = _e62;
        st.beta = metal::float3(1.0);
        st.pdf_bsdf = 0.0;
        metal::float3 _e71 = params.cam_pos;
        st.prev = _e71;
    } else {
        GpuPathState _e74 = paths[i_3];
        st = _e74;
    }
    v.alive = 0u;
    uint _e79 = st.alive;
    if (_e79 == 0u) {
        GpuPathVertex _e84 = v;
        vertices[i_3] = _e84;
        return;
    }
    metal::float3 _e86 = st.origin;
    metal::float3 _e88 = st.dir;
    float _e91 = params.t_min;
    GeoHit _e94 = trace(_e86, _e88, _e91, F32_MAX, false, geo_nodes, geo_tris, _buffer_sizes);
    if (_e94.tri == NO_LIGHT) {
        st.alive = 0u;
        GpuPathState _e102 = st;
        paths[i_3] = _e102;
        GpuPathVertex _e105 = v;
        vertices[i_3] = _e105;
        return;
    }
    GpuTriangle tri = geo_tris[_e94.tri];
    metal::float3 _e111 = st.origin;
    metal::float3 _e113 = st.dir;
    metal::float3 x_8 = _e111 + (_e113 * _e94.t);
    metal::float3 _e120 = triangle_normal(tri.v0_, tri.v1_, tri.v2_);
    metal::float3 _e122 = st.dir;
    metal::float3 _e123 = face_against(_e120, _e122);
    uint b_6 = _e94.tri * 3u;
    metal::float4 _e129 = geo_normals[b_6];
    metal::float4 _e135 = geo_normals[b_6 + 1u];
    metal::float4 _e141 = geo_normals[b_6 + 2u];
    metal::float3 _e146 = barycentric(x_8, tri.v0_, tri.v1_, tri.v2_);
    metal::float3 _e147 = shading_normal(_e129.xyz, _e135.xyz, _e141.xyz, _e146, _e123);
    if (tri.light != NO_LIGHT) {
        metal::float3 _e154 = st.dir;
        bool _e155 = sees_emission(_e120, _e154);
        local = _e155;
    } else {
        local = false;
    }
    bool _e157 = local;
    if (_e157) {
        float _e161 = st.pdf_bsdf;
        if (_e161 > 0.0) {
            uint _e168 = light_leaf[tri.light];
            BshNode _e169 = bsh_range_leaf(BSH, _e168, bsh_nodes, _buffer_sizes);
            metal::float4 _e171 = st.prev_lobe;
            metal::float4 _e172 = range_lobe(_e171);
            metal::float3 _e174 = st.prev;
            metal::float3 _e176 = st.prev_r;
            bool _e177 = bsh_reaches(_e169, _e174, _e176, _e172);
            float _e179 = st.pdf_bsdf;
            metal::float3 _e182 = st.prev;
            metal::float3 _e184 = st.prev_normal;
            metal::float3 _e186 = st.prev_r;
            metal::float4 _e188 = st.prev_lobe;
            uint _e191 = candidates[i_3];
            float _e192 = light_pdf(tri.light, _e182, _e184, _e186, _e188, _e172, x_8, _e191, _e177, light_cones, rt2_2, lights, _buffer_sizes);
            float _e193 = mis_weight(_e179, _e192);
            w = _e193;
        }
        metal::float3 _e195 = st.beta;
        metal::float3 _e200 = lights[tri.light].intensity;
        float _e202 = w;
        metal::float3 add = (_e195 * _e200) * _e202;
        bool _e204 = finite3_(add);
        if (_e204) {
            metal::float4 _e207 = radiance[i_3];
            radiance[i_3] = _e207 + metal::float4(add, 0.0);
        }
    }
    uint _e213 = params.depth;
    uint _e216 = params.max_depth;
    if (_e213 >= _e216) {
        st.alive = 0u;
        GpuPathState _e222 = st;
        paths[i_3] = _e222;
        GpuPathVertex _e225 = v;
        vertices[i_3] = _e225;
        return;
    }
    GpuMaterial m_2 = materials[tri.material];
    metal::float3 _e231 = st.dir;
    metal::float3 wo_1 = -(_e231);
    metal::float4 _e239 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, metal::dot(_e147, wo_1));
    v.position = x_8;
    v.normal = _e147;
    v.material = tri.material;
    v.gnormal = _e123;
    metal::float3 _e247 = st.beta;
    v.weight = _e247;
    v.wo = wo_1;
    v.alive = 1u;
    GpuPathVertex _e253 = v;
    vertices[i_3] = _e253;
    uint _e255 = st.rng;
    rng = _e255;
    float _e257 = next_uniform(rng);
    float _e258 = next_uniform(rng);
    float _e259 = specular_probability(_e239);
    metal::float3 _e261 = bsdf_sample(_e147, wo_1, m_2.alpha, _e259, _e257, _e258);
    float _e263 = bsdf_pdf(_e147, wo_1, _e261, m_2.alpha, _e259);
    bool _e267 = has_specular(m_2.metallic, m_2.f0_, m_2.f90_);
    if (_e267) {
        metal::float3 _e269 = st.beta;
        metal::float3 _e275 = brdf_eval(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, _e147, wo_1, _e261);
        st.beta = _e269 * (_e275 * (metal::dot(_e261, _e147) / _e263));
    } else {
        metal::float3 _e281 = st.beta;
        st.beta = _e281 * m_2.albedo;
    }
    st.prev = x_8;
    st.prev_normal = _e147;
    metal::float3 _e287 = mirror_dir(_e147, wo_1);
    st.prev_r = _e287;
    st.prev_lobe = _e239;
    st.pdf_bsdf = _e263;
    float _e293 = params.eps;
    st.origin = x_8 + (_e123 * _e293);
    st.dir = _e261;
    bool _e297 = continues_path(_e261, _e147, _e123);
    if (!(!(_e297))) {
        local_1 = !((_e263 > 0.0));
    } else {
        local_1 = true;
    }
    bool _e306 = local_1;
    if (_e306) {
        st.alive = 0u;
    }
    uint _e311 = params.depth;
    bool _e312 = plays_roulette(_e311);
    if (_e312) {
        uint _e316 = st.alive;
        local_2 = _e316 == 1u;
    } else {
        local_2 = false;
    }
    bool _e320 = local_2;
    if (_e320) {
        metal::float3 _e322 = st.beta;
        float _e323 = path_survival(_e322);
        float _e324 = next_uniform(rng);
        if (_e324 >= _e323) {
            st.alive = 0u;
        } else {
            metal::float3 _e329 = st.beta;
            st.beta = _e329 / metal::float3(_e323);
        }
    }
    uint _e333 = rng;
    st.rng = _e333;
    GpuPathState _e336 = st;
    paths[i_3] = _e336;
    return;
}
