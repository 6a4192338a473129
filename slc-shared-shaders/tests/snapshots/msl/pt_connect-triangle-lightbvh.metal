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
    uint size5;
    uint size6;
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
struct GpuMaterial {
    metal::packed_float3 albedo;
    float metallic;
    metal::packed_float3 emission;
    float alpha;
    metal::packed_float3 f0_;
    float f90_;
};
struct ShadeParams {
    uint point_count;
    uint seed;
    uint frame;
    float eps;
};
typedef float type_4[1];
struct GpuLightBvhNode {
    metal::packed_float3 center;
    float radius;
    metal::packed_float3 axis;
    float cos_o;
    float phi;
    float cos_e;
    uint second;
    uint light;
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
typedef uint BshNodes;
struct Connection {
    metal::float3 e;
    metal::packed_float3 y;
    float cos_x;
};
typedef GpuLight type_9[1];
typedef GpuLightCone type_10[1];
typedef uint BvhNodes;
typedef GpuLightBvhNode type_11[1];
struct BvhPick {
    uint light;
    float pmf;
};
typedef GpuPathVertex type_12[1];
typedef GpuMaterial type_13[1];
typedef metal::float4 type_14[1];
typedef uint type_15[1];
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
constant BshNodes BSH = 0u;
constant uint BSH_TILE_DEPTH = 8u;
constant uint BSH_TILE_SUBTREES = 256u;
constant BvhNodes BVH = 0u;

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

uint pick_stream(
    uint stream
) {
    uint _e3 = pcg_hash(stream ^ PICK_STREAM);
    return _e3;
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

float slc_weight(
    float rt2_1,
    float d2_1
) {
    if (d2_1 <= rt2_1) {
        return 1.0;
    }
    return d2_1 / rt2_1;
}

bool slc_keep(
    float r2_,
    float d2_2
) {
    return d2_2 < r2_;
}

float inverse_square(
    float d2_3
) {
    return 1.0 / metal::max(d2_3, MIN_D2_);
}

float connection_factor(
    float cos_x,
    float d2_4,
    float rt2_2,
    float w
) {
    float _e4 = inverse_square(d2_4);
    float _e6 = slc_weight(rt2_2, d2_4);
    return ((cos_x * _e4) * _e6) * w;
}

float connection_cosine(
    metal::float3 x_1,
    metal::float3 y,
    metal::float3 n,
    metal::float3 ng,
    float r2_1
) {
    bool local = {};
    bool local_1 = {};
    metal::float3 v_7 = x_1 - y;
    float d2_8 = metal::dot(v_7, v_7);
    bool _e7 = slc_keep(r2_1, d2_8);
    if (!(!(_e7))) {
        local = !((d2_8 > 0.0));
    } else {
        local = true;
    }
    bool _e16 = local;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_5 = v_7 / metal::float3(metal::sqrt(d2_8));
    float cos_x_1 = -(metal::dot(n, w_5));
    if (!(!((cos_x_1 > 0.0)))) {
        local_1 = !((metal::dot(ng, w_5) < 0.0));
    } else {
        local_1 = true;
    }
    bool _e34 = local_1;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float triangle_lobe(
    metal::float3 n_1,
    float area,
    metal::float3 w_1
) {
    return area * metal::max(metal::dot(n_1, w_1), 0.0);
}

metal::float3 triangle_sample(
    metal::float3 a_2,
    metal::float3 b_2,
    metal::float3 c,
    float u1_,
    float u2_
) {
    float su = metal::sqrt(u1_);
    float b0_ = 1.0 - su;
    float b1_ = u2_ * su;
    return ((a_2 * b0_) + (b_2 * b1_)) + (c * ((1.0 - b0_) - b1_));
}

float area_to_solid_angle_pdf(
    float pdf_area,
    float d2_5,
    float cos_light
) {
    float c_5 = metal::abs(cos_light);
    if (c_5 <= 0.0) {
        return 0.0;
    }
    return (pdf_area * d2_5) / c_5;
}

float mis_power(
    float pdf_a,
    float pdf_b
) {
    float a2_ = pdf_a * pdf_a;
    float s_2 = a2_ + (pdf_b * pdf_b);
    if (s_2 <= 0.0) {
        return 0.0;
    }
    return a2_ / s_2;
}

float light_strategy_pdf(
    float select,
    float rt2_3,
    float d2_6,
    float area_1,
    float cos_y
) {
    bool local_2 = {};
    bool local_3 = {};
    if (!((d2_6 <= 0.0))) {
        local_2 = area_1 <= 0.0;
    } else {
        local_2 = true;
    }
    bool _e13 = local_2;
    if (!(_e13)) {
        local_3 = cos_y <= 0.0;
    } else {
        local_3 = true;
    }
    bool _e20 = local_3;
    if (_e20) {
        return 0.0;
    }
    float _e22 = rr_probability(rt2_3, d2_6);
    float _e26 = area_to_solid_angle_pdf(1.0 / area_1, d2_6, cos_y);
    return (select * _e22) * _e26;
}

float cosine_pdf(
    float cos_theta
) {
    return metal::max(cos_theta, 0.0) * INV_PI;
}

metal::float3 onb_tangent(
    metal::float3 n_2
) {
    float s_3 = (n_2.z >= 0.0) ? 1.0 : -1.0;
    float a_7 = -1.0 / (s_3 + n_2.z);
    return metal::float3(1.0 + (((s_3 * n_2.x) * n_2.x) * a_7), ((s_3 * n_2.x) * n_2.y) * a_7, -(s_3) * n_2.x);
}

metal::float3 onb_bitangent(
    metal::float3 n_3
) {
    float s_4 = (n_3.z >= 0.0) ? 1.0 : -1.0;
    float a_8 = -1.0 / (s_4 + n_3.z);
    return metal::float3((n_3.x * n_3.y) * a_8, s_4 + ((n_3.y * n_3.y) * a_8), -(n_3.y));
}

metal::float3 onb_to_local(
    metal::float3 n_4,
    metal::float3 w_2
) {
    metal::float3 _e2 = onb_tangent(n_4);
    metal::float3 _e4 = onb_bitangent(n_4);
    return metal::float3(metal::dot(w_2, _e2), metal::dot(w_2, _e4), metal::dot(w_2, n_4));
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
    float t = ((cos_h * cos_h) * a2_1) + sin2_h;
    return (a2_1 * INV_PI) / (t * t);
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
    bool local_4 = {};
    if (!((n_l <= 0.0))) {
        local_4 = n_v <= 0.0;
    } else {
        local_4 = true;
    }
    bool _e11 = local_4;
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
    metal::float3 v,
    metal::float3 l
) {
    metal::float3 h_1 = v + l;
    float len2_ = metal::dot(h_1, h_1);
    if (len2_ <= 0.0) {
        return 0.0;
    }
    return metal::saturate(metal::dot(v, h_1) / metal::sqrt(len2_));
}

metal::float3 specular_brdf(
    metal::float3 base_2,
    float metallic_2,
    metal::float3 f0_d_2,
    float f90_d_2,
    float alpha_3,
    metal::float3 n_5,
    metal::float3 v_1,
    metal::float3 l_1
) {
    bool local_5 = {};
    float n_l_1 = metal::dot(n_5, l_1);
    float n_v_2 = metal::dot(n_5, v_1);
    if (!((n_l_1 <= 0.0))) {
        local_5 = n_v_2 <= 0.0;
    } else {
        local_5 = true;
    }
    bool _e18 = local_5;
    if (_e18) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    metal::float3 hs = v_1 + l_1;
    float inv = 1.0 / metal::sqrt(metal::dot(hs, hs));
    metal::float3 h_2 = hs * inv;
    metal::float3 c_7 = metal::cross(n_5, h_2);
    float _e32 = ggx_d(metal::dot(n_5, h_2), metal::dot(c_7, c_7), alpha_3);
    metal::float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, metal::dot(v_1, h_2));
    float _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return _e34 * (_e32 * _e35);
}

metal::float3 brdf_eval(
    metal::float3 base_3,
    float metallic_3,
    metal::float3 f0_d_3,
    float f90_d_3,
    float alpha_4,
    metal::float3 n_6,
    metal::float3 v_2,
    metal::float3 l_2
) {
    if (metal::dot(n_6, l_2) <= 0.0) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    float _e15 = half_cosine(v_2, l_2);
    metal::float3 _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    metal::float3 _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_6, v_2, l_2);
    return _e16 + _e17;
}

bool has_specular(
    float metallic_4,
    metal::float3 f0_d_4,
    float f90_d_4
) {
    bool local_6 = {};
    bool local_7 = {};
    if (!((metallic_4 > 0.0))) {
        local_6 = f90_d_4 > 0.0;
    } else {
        local_6 = true;
    }
    bool _e11 = local_6;
    if (!(_e11)) {
        local_7 = metal::max(metal::max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0.0;
    } else {
        local_7 = true;
    }
    bool _e23 = local_7;
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
    bool local_8 = {};
    metal::float3 _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    float _e16 = channel_mean(((metal::float3(1.0, 1.0, 1.0) - _e10) * base_4) * (1.0 - metallic_5));
    if (!((n_v_1 <= 0.0))) {
        bool _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_8 = !(_e22);
    } else {
        local_8 = true;
    }
    bool _e25 = local_8;
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
    metal::float3 n_7,
    metal::float3 v_3
) {
    return (n_7 * (2.0 * metal::dot(n_7, v_3))) - v_3;
}

float bounded_vndf_k(
    metal::float3 wi,
    float alpha_6
) {
    float a_9 = metal::saturate(alpha_6);
    float s_5 = 1.0 + metal::sqrt((wi.x * wi.x) + (wi.y * wi.y));
    float a2_3 = a_9 * a_9;
    float s2_ = s_5 * s_5;
    return ((1.0 - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z));
}

float ggx_vndf_pdf(
    metal::float3 wi_1,
    metal::float3 wo,
    float alpha_7
) {
    bool local_9 = {};
    if (!((wi_1.z <= 0.0))) {
        local_9 = wo.z <= 0.0;
    } else {
        local_9 = true;
    }
    bool _e13 = local_9;
    if (_e13) {
        return 0.0;
    }
    metal::float3 hs_1 = wi_1 + wo;
    metal::float3 m_1 = hs_1 / metal::float3(metal::sqrt(metal::dot(hs_1, hs_1)));
    float _e28 = ggx_d(m_1.z, (m_1.x * m_1.x) + (m_1.y * m_1.y), alpha_7);
    float t_1 = metal::sqrt(((alpha_7 * alpha_7) * ((wi_1.x * wi_1.x) + (wi_1.y * wi_1.y))) + (wi_1.z * wi_1.z));
    float _e43 = bounded_vndf_k(wi_1, alpha_7);
    return _e28 / (2.0 * ((_e43 * wi_1.z) + t_1));
}

float bsdf_pdf(
    metal::float3 n_8,
    metal::float3 v_4,
    metal::float3 l_3,
    float alpha_8,
    float p_spec
) {
    float _e6 = cosine_pdf(metal::dot(n_8, l_3));
    if (p_spec <= 0.0) {
        return _e6;
    }
    metal::float3 _e9 = onb_to_local(n_8, v_4);
    metal::float3 _e10 = onb_to_local(n_8, l_3);
    float _e11 = ggx_vndf_pdf(_e9, _e10, alpha_8);
    return (p_spec * _e11) + ((1.0 - p_spec) * _e6);
}

float cos_sub_clamped(
    float sin_a,
    float cos_a,
    float sin_b,
    float cos_b
) {
    if (cos_a > cos_b) {
        return 1.0;
    }
    return (cos_a * cos_b) + (sin_a * sin_b);
}

float sin_sub_clamped(
    float sin_a_1,
    float cos_a_1,
    float sin_b_1,
    float cos_b_1
) {
    if (cos_a_1 > cos_b_1) {
        return 0.0;
    }
    return (sin_a_1 * cos_b_1) - (cos_a_1 * sin_b_1);
}

float safe_sqrt(
    float x_2
) {
    return metal::sqrt(metal::max(x_2, 0.0));
}

float subtended_cos(
    float dist2_,
    float r2_2
) {
    float _e5 = safe_sqrt(1.0 - (r2_2 / dist2_));
    return (dist2_ <= r2_2) ? -1.0 : _e5;
}

metal::float4 emitter_cone(
    metal::float3 center,
    float radius,
    metal::float3 axis,
    float cos_o,
    metal::float3 p
) {
    bool local_10 = {};
    metal::float3 v_8 = p - center;
    float dist2_1 = metal::dot(v_8, v_8);
    float r2_5 = radius * radius;
    if (dist2_1 <= 0.0) {
        local_10 = r2_5 <= 0.0;
    } else {
        local_10 = false;
    }
    bool _e15 = local_10;
    if (_e15) {
        return metal::float4(-2.0, 0.000000000001, -1.0, 0.0);
    }
    float d2_9 = metal::max(metal::max(dist2_1, r2_5), MIN_D2_);
    metal::float3 wi_2 = (dist2_1 > 0.0) ? (v_8 / metal::float3(metal::sqrt(dist2_1))) : metal::float3(0.0, 0.0, 0.0);
    float cos_w = metal::dot(axis, wi_2);
    float _e38 = safe_sqrt(1.0 - (cos_w * cos_w));
    float _e39 = subtended_cos(dist2_1, r2_5);
    float _e43 = safe_sqrt(1.0 - (_e39 * _e39));
    float _e47 = safe_sqrt(1.0 - (cos_o * cos_o));
    float _e48 = cos_sub_clamped(_e38, cos_w, _e47, cos_o);
    float _e49 = sin_sub_clamped(_e38, cos_w, _e47, cos_o);
    float _e50 = cos_sub_clamped(_e49, _e48, _e43, _e39);
    return metal::float4(_e50, d2_9, _e39, _e43);
}

float emitter_importance(
    metal::float3 center_1,
    float radius_1,
    float phi,
    metal::float3 axis_1,
    float cos_o_1,
    float cos_e,
    metal::float3 p_1
) {
    metal::float4 _e7 = emitter_cone(center_1, radius_1, axis_1, cos_o_1, p_1);
    if (_e7.x <= cos_e) {
        return 0.0;
    }
    return (phi * _e7.x) / _e7.y;
}

float cone_cos_of(
    metal::float3 v_5,
    float d2_7,
    float a_3,
    metal::float3 d
) {
    bool local_11 = {};
    bool local_12 = {};
    float vd = metal::dot(v_5, d);
    float h2_ = d2_7 - (a_3 * a_3);
    if (!((h2_ <= 0.0))) {
        if (vd >= 0.0) {
            local_12 = (vd * vd) >= h2_;
        } else {
            local_12 = false;
        }
        bool _e19 = local_12;
        local_11 = _e19;
    } else {
        local_11 = true;
    }
    bool _e21 = local_11;
    if (_e21) {
        return 1.0;
    }
    metal::float3 c_8 = metal::cross(v_5, d);
    return metal::min(((vd * metal::sqrt(h2_)) + (metal::sqrt(metal::dot(c_8, c_8)) * a_3)) / d2_7, 1.0);
}

float cone_cos_toward(
    metal::float3 center_2,
    float radius_2,
    metal::float3 p_2,
    metal::float3 d_1
) {
    metal::float3 v_9 = center_2 - p_2;
    float _e6 = cone_cos_of(v_9, metal::dot(v_9, v_9), radius_2, d_1);
    return _e6;
}

float range_scale_at(
    metal::float4 rl,
    float cos_t
) {
    float t_2 = ((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0;
    return metal::clamp(rl.x + ((rl.y * rl.z) / (t_2 * t_2)), 1.0, rl.w * rl.w);
}

float range_scale_toward(
    metal::float4 rl_1,
    metal::float3 center_3,
    float radius_3,
    metal::float3 p_3,
    metal::float3 r
) {
    if (rl_1.w <= 1.0) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_3, radius_3, p_3, r);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

float light_importance(
    metal::float3 center_4,
    float radius_4,
    float phi_1,
    metal::float3 axis_2,
    float cos_o_2,
    float cos_e_1,
    metal::float3 p_4,
    metal::float3 n_9
) {
    float imp = {};
    metal::float4 _e8 = emitter_cone(center_4, radius_4, axis_2, cos_o_2, p_4);
    if (_e8.x <= cos_e_1) {
        return 0.0;
    }
    imp = (phi_1 * _e8.x) / _e8.y;
    if (metal::dot(n_9, n_9) > 0.0) {
        metal::float3 v_10 = center_4 - p_4;
        float dist2_2 = metal::dot(v_10, v_10);
        float cos_i = metal::dot((dist2_2 > 0.0) ? (v_10 / metal::float3(metal::sqrt(dist2_2))) : metal::float3(0.0, 0.0, 0.0), n_9);
        float _e33 = imp;
        float _e37 = safe_sqrt(1.0 - (cos_i * cos_i));
        float _e40 = cos_sub_clamped(_e37, cos_i, _e8.w, _e8.z);
        imp = _e33 * metal::max(_e40, 0.0);
    }
    float _e44 = imp;
    return metal::max(_e44, 0.0);
}

float glossy_importance(
    metal::float3 center_5,
    float radius_5,
    float phi_2,
    metal::float3 axis_3,
    float cos_o_3,
    float cos_e_2,
    metal::float3 p_5,
    metal::float3 n_10,
    metal::float3 r_1,
    metal::float4 lobe_5
) {
    bool local_13 = {};
    float _e10 = emitter_importance(center_5, radius_5, phi_2, axis_3, cos_o_3, cos_e_2, p_5);
    float _e11 = cone_cos_toward(center_5, radius_5, p_5, n_10);
    if (!((_e10 <= 0.0))) {
        local_13 = _e11 <= 0.0;
    } else {
        local_13 = true;
    }
    bool _e20 = local_13;
    if (_e20) {
        return 0.0;
    }
    float _e22 = cone_cos_toward(center_5, radius_5, p_5, r_1);
    float _e27 = safe_sqrt(0.5 + (0.5 * _e22));
    float _e33 = ggx_d(_e27, 1.0 - (_e27 * _e27), lobe_5.z);
    float _e39 = smith_root(lobe_5.w, lobe_5.z);
    float spec = ((lobe_5.y * _e33) * 0.25) / _e39;
    return _e10 * (((lobe_5.x * INV_PI) * _e11) + spec);
}

float receiver_importance(
    metal::float3 center_6,
    float radius_6,
    float phi_3,
    metal::float3 axis_4,
    float cos_o_4,
    float cos_e_3,
    metal::float3 p_6,
    metal::float3 n_11,
    metal::float3 r_2,
    metal::float4 lobe_6
) {
    if (lobe_6.y <= 0.0) {
        float _e13 = light_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_11);
        return _e13;
    }
    float _e14 = glossy_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_11, r_2, lobe_6);
    return _e14;
}

float bvh_first_prob(
    float c0_,
    float c1_
) {
    float s_6 = c0_ + c1_;
    if (s_6 > 0.0) {
        return c0_ / s_6;
    }
    return -1.0;
}

float bvh_remap_u(
    float u_1,
    float p0_,
    bool first
) {
    if (first) {
        return metal::min(u_1 / p0_, ONE_MINUS_EPSILON);
    }
    return metal::clamp((u_1 - p0_) / (1.0 - p0_), 0.0, ONE_MINUS_EPSILON);
}

bool finite3_(
    metal::float3 v_6
) {
    bool local_14 = {};
    bool local_15 = {};
    if (metal::abs(v_6.x) <= F32_MAX) {
        local_14 = metal::abs(v_6.y) <= F32_MAX;
    } else {
        local_14 = false;
    }
    bool _e12 = local_14;
    if (_e12) {
        local_15 = metal::abs(v_6.z) <= F32_MAX;
    } else {
        local_15 = false;
    }
    bool _e20 = local_15;
    return _e20;
}

float shadow_margin(
    float len
) {
    return 0.0001 * len;
}

float ray_inverse(
    float x_3
) {
    return 1.0 / ((metal::abs(x_3) < 0.000000000000000000000000000001) ? 0.000000000000000000000000000001 : x_3);
}

metal::float3 ray_inverse3_(
    metal::float3 d_2
) {
    float _e2 = ray_inverse(d_2.x);
    float _e4 = ray_inverse(d_2.y);
    float _e6 = ray_inverse(d_2.z);
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
    metal::float3 a_4,
    metal::float3 b_3,
    metal::float3 c_2
) {
    bool local_16 = {};
    metal::float3 n_19 = metal::cross(b_3 - a_4, c_2 - a_4);
    float l2_ = metal::dot(n_19, n_19);
    if (!(!((l2_ > 0.0)))) {
        local_16 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_16 = true;
    }
    bool _e17 = local_16;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_19 / metal::float3(metal::sqrt(l2_));
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_3,
    metal::float3 a_5,
    metal::float3 b_4,
    metal::float3 c_3,
    float t_min,
    float t_max_1
) {
    bool local_17 = {};
    bool local_18 = {};
    bool local_19 = {};
    metal::float3 e1_ = b_4 - a_5;
    metal::float3 e2_ = c_3 - a_5;
    metal::float3 p_7 = metal::cross(d_3, e2_);
    float det = metal::dot(e1_, p_7);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv_1 = 1.0 / det;
    metal::float3 s_7 = o_1 - a_5;
    float u_3 = metal::dot(s_7, p_7) * inv_1;
    if (!((u_3 < 0.0))) {
        local_17 = u_3 > 1.0;
    } else {
        local_17 = true;
    }
    bool _e28 = local_17;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q = metal::cross(s_7, e1_);
    float v_11 = metal::dot(d_3, q) * inv_1;
    if (!((v_11 < 0.0))) {
        local_18 = (u_3 + v_11) > 1.0;
    } else {
        local_18 = true;
    }
    bool _e42 = local_18;
    if (_e42) {
        return -1.0;
    }
    float t_3 = metal::dot(e2_, q) * inv_1;
    if (t_3 > t_min) {
        local_19 = t_3 < t_max_1;
    } else {
        local_19 = false;
    }
    bool _e51 = local_19;
    if (_e51) {
        return t_3;
    }
    return -1.0;
}

metal::float3 light_intensity(
    GpuLight l_4,
    metal::float3 w_3
) {
    switch(l_4.kind) {
        case 3u: {
            metal::float3 _e7 = triangle_normal(l_4.p0_, l_4.p1_, l_4.p2_);
            float _e9 = triangle_lobe(_e7, l_4.a, w_3);
            return l_4.intensity * _e9;
        }
        default: {
            return metal::float3(0.0);
        }
    }
}

metal::float3 light_point(
    GpuLight l_5,
    float u1_1,
    float u2_1
) {
    if (l_5.kind == LIGHT_TRIANGLE) {
        metal::float3 _e9 = triangle_sample(l_5.p0_, l_5.p1_, l_5.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_5.p0_;
}

float light_area(
    GpuLight l_6
) {
    if (l_6.kind == LIGHT_TRIANGLE) {
        return l_6.a;
    }
    return 0.0;
}

metal::float3 light_normal(
    GpuLight l_7
) {
    if (l_7.kind == LIGHT_TRIANGLE) {
        metal::float3 _e7 = triangle_normal(l_7.p0_, l_7.p1_, l_7.p2_);
        return _e7;
    }
    return metal::float3(0.0);
}

GeoHit trace(
    metal::float3 o_2,
    metal::float3 d_4,
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
    uint node = 0u;
    uint i = {};
    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((1 + (_buffer_sizes.size0 - 0 - 32) / 32) == 0u) {
        GeoHit _e13 = hit;
        return _e13;
    }
    metal::float3 _e14 = ray_inverse3_(d_4);
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e21 = node;
        GpuGeoNode n_20 = geo_nodes[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_20.bmin, n_20.bmax, _e27);
        if (_e28 >= 0.0) {
            if (n_20.count > 0u) {
                i = n_20.first;
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
                    if (_e36 < (n_20.first + n_20.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_4 = geo_tris[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_4, t_4.v0_, t_4.v1_, t_4.v2_, t_min_1, _e49);
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
                    stack.inner[_e63] = n_20.first + 1u;
                    uint _e68 = sp;
                    sp = _e68 + 1u;
                }
                node = n_20.first;
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
        node = _e80;
    }
    GeoHit _e81 = hit;
    return _e81;
}

bool occluded(
    metal::float3 a_6,
    metal::float3 b_5,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 dv = b_5 - a_6;
    float len_1 = metal::length(dv);
    if (len_1 <= 0.0) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    GeoHit _e12 = trace(a_6, dv / metal::float3(len_1), _e7, len_1 - _e7, true, geo_nodes, geo_tris, _buffer_sizes);
    return _e12.tri != NO_LIGHT;
}

Connection connect_record(
    GpuLight l_8,
    metal::float3 x_4,
    metal::float3 n_12,
    metal::float3 ng_1,
    float r2_3,
    float rt2_4,
    float w_res,
    float u1_2,
    float u2_2,
    float eps,
    bool trace_1,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection c_4 = {};
    bool local_20 = {};
    bool local_21 = {};
    c_4.e = metal::float3(0.0);
    metal::float3 _e16 = light_point(l_8, u1_2, u2_2);
    c_4.y = _e16;
    metal::float3 _e19 = c_4.y;
    float _e20 = connection_cosine(x_4, _e19, n_12, ng_1, r2_3);
    c_4.cos_x = _e20;
    float _e22 = c_4.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            metal::float3 _e33 = c_4.y;
            bool _e34 = occluded(x_4 + (ng_1 * eps), _e33, geo_nodes, geo_tris, _buffer_sizes);
            local_21 = _e34;
        } else {
            local_21 = false;
        }
        bool _e36 = local_21;
        local_20 = _e36;
    } else {
        local_20 = true;
    }
    bool _e38 = local_20;
    if (_e38) {
        Connection _e39 = c_4;
        return _e39;
    }
    metal::float3 _e41 = c_4.y;
    metal::float3 v_12 = x_4 - _e41;
    float d2_10 = metal::dot(v_12, v_12);
    metal::float3 _e48 = light_intensity(l_8, v_12 / metal::float3(metal::sqrt(d2_10)));
    float _e50 = c_4.cos_x;
    float _e51 = connection_factor(_e50, d2_10, rt2_4, w_res);
    c_4.e = _e48 * _e51;
    Connection _e53 = c_4;
    return _e53;
}

Connection connect_traced(
    uint li,
    metal::float3 x_5,
    metal::float3 n_13,
    metal::float3 ng_2,
    float s,
    float w_res_1,
    float u1_3,
    float u2_3,
    float eps_1,
    bool trace_2,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    device type_9 const& lights,
    device type_4 const& r2_4,
    device type_4 const& rt2_5,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight _e12 = lights[li];
    float _e15 = r2_4[li];
    float _e19 = rt2_5[li];
    Connection _e21 = connect_record(_e12, x_5, n_13, ng_2, s * _e15, s * _e19, w_res_1, u1_3, u2_3, eps_1, trace_2, geo_nodes, geo_tris, _buffer_sizes);
    return _e21;
}

Connection connect(
    uint li_1,
    metal::float3 x_6,
    metal::float3 n_14,
    metal::float3 ng_3,
    float s_1,
    float w_res_2,
    float u1_4,
    float u2_4,
    float eps_2,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    device type_9 const& lights,
    device type_4 const& r2_4,
    device type_4 const& rt2_5,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection _e10 = connect_traced(li_1, x_6, n_14, ng_3, s_1, w_res_2, u1_4, u2_4, eps_2, true, geo_nodes, geo_tris, lights, r2_4, rt2_5, _buffer_sizes);
    return _e10;
}

float mis_weight(
    float pdf_a_1,
    float pdf_b_1
) {
    float _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

float light_range_scale(
    uint li_2,
    metal::float3 x_7,
    metal::float3 r_3,
    metal::float4 rl_2,
    device type_10 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_9 = light_cones[li_2];
    float _e9 = range_scale_toward(rl_2, c_9.center, c_9.radius, x_7, r_3);
    return _e9;
}

GpuLightBvhNode light_bvh_node(
    BvhNodes nodes,
    uint i_1,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightBvhNode _e4 = light_bvh[i_1];
    return _e4;
}

uint light_bvh_count(
    BvhNodes nodes_1,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    return 1 + (_buffer_sizes.size6 - 0 - 48) / 48;
}

float bvh_importance(
    BvhNodes nodes_2,
    uint i_2,
    metal::float3 x_8,
    metal::float3 n_15,
    metal::float3 r_4,
    metal::float4 lobe_7,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightBvhNode _e6 = light_bvh_node(nodes_2, i_2, light_bvh, _buffer_sizes);
    float _e13 = receiver_importance(_e6.center, _e6.radius, _e6.phi, _e6.axis, _e6.cos_o, _e6.cos_e, x_8, n_15, r_4, lobe_7);
    return _e13;
}

float bvh_first(
    BvhNodes nodes_3,
    uint i_3,
    metal::float3 x_9,
    metal::float3 n_16,
    metal::float3 r_5,
    metal::float4 lobe_8,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_22 = {};
    GpuLightBvhNode _e6 = light_bvh_node(nodes_3, i_3, light_bvh, _buffer_sizes);
    uint j = _e6.second;
    if (!((j <= (i_3 + 1u)))) {
        uint _e14 = light_bvh_count(nodes_3, light_bvh, _buffer_sizes);
        local_22 = j >= _e14;
    } else {
        local_22 = true;
    }
    bool _e17 = local_22;
    if (_e17) {
        return -1.0;
    }
    float _e21 = bvh_importance(nodes_3, i_3 + 1u, x_9, n_16, r_5, lobe_8, light_bvh, _buffer_sizes);
    float _e22 = bvh_importance(nodes_3, j, x_9, n_16, r_5, lobe_8, light_bvh, _buffer_sizes);
    float _e23 = bvh_first_prob(_e21, _e22);
    return _e23;
}

BvhPick bvh_pick_none(
) {
    return BvhPick {0u, 0.0};
}

BvhPick light_bvh_sample(
    BvhNodes nodes_4,
    metal::float3 x_10,
    metal::float3 n_17,
    metal::float3 r_6,
    metal::float4 lobe_9,
    float u_in,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    BvhPick pick = {};
    float u_2 = {};
    uint i_4 = 0u;
    float pmf = 1.0;
    bool local_23 = {};
    BvhPick _e6 = bvh_pick_none();
    pick = _e6;
    u_2 = u_in;
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e13 = i_4;
        uint _e14 = light_bvh_count(nodes_4, light_bvh, _buffer_sizes);
        if (_e13 < _e14) {
        } else {
            break;
        }
        {
            uint _e16 = i_4;
            GpuLightBvhNode _e17 = light_bvh_node(nodes_4, _e16, light_bvh, _buffer_sizes);
            if (_e17.second == LIGHT_BVH_LEAF) {
                uint _e21 = i_4;
                if (!((_e21 > 0u))) {
                    float _e28 = bvh_importance(nodes_4, 0u, x_10, n_17, r_6, lobe_9, light_bvh, _buffer_sizes);
                    local_23 = _e28 > 0.0;
                } else {
                    local_23 = true;
                }
                bool _e32 = local_23;
                if (_e32) {
                    pick.light = _e17.light;
                    float _e36 = pmf;
                    pick.pmf = _e36;
                }
                BvhPick _e37 = pick;
                return _e37;
            }
            uint _e38 = i_4;
            float _e39 = bvh_first(nodes_4, _e38, x_10, n_17, r_6, lobe_9, light_bvh, _buffer_sizes);
            if (_e39 < 0.0) {
                BvhPick _e42 = pick;
                return _e42;
            }
            float _e43 = u_2;
            bool first_1 = _e43 < _e39;
            float _e45 = pmf;
            pmf = _e45 * (first_1 ? _e39 : (1.0 - _e39));
            float _e50 = u_2;
            float _e51 = bvh_remap_u(_e50, _e39, first_1);
            u_2 = _e51;
            uint _e53 = i_4;
            i_4 = first_1 ? (_e53 + 1u) : _e17.second;
        }
    }
    BvhPick _e57 = pick;
    return _e57;
}

float light_pdf_selected(
    uint li_3,
    metal::float3 x_11,
    metal::float3 r_7,
    metal::float4 rl_3,
    metal::float3 y_1,
    float sel,
    device type_9 const& lights,
    device type_4 const& rt2_5,
    device type_10 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight l_9 = lights[li_3];
    metal::float3 v_13 = x_11 - y_1;
    float d2_11 = metal::dot(v_13, v_13);
    metal::float3 _e11 = light_normal(l_9);
    float cos_y_1 = (d2_11 > 0.0) ? metal::dot(_e11, v_13 / metal::float3(metal::sqrt(d2_11))) : 0.0;
    float _e20 = light_range_scale(li_3, x_11, r_7, rl_3, light_cones, _buffer_sizes);
    float _e23 = rt2_5[li_3];
    float _e25 = light_area(l_9);
    float _e26 = light_strategy_pdf(sel, _e20 * _e23, d2_11, _e25, cos_y_1);
    return _e26;
}

metal::float3 shade_pick(
    uint li_4,
    metal::float3 x_12,
    metal::float3 n_18,
    metal::float3 ng_4,
    GpuMaterial m,
    metal::float3 wo_1,
    metal::float3 r_8,
    metal::float4 lobe_10,
    metal::float4 rl_4,
    float w_4,
    uint nee,
    float u1_5,
    float u2_5,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    device type_9 const& lights,
    device type_4 const& r2_4,
    device type_4 const& rt2_5,
    device type_10 const& light_cones,
    constant ShadeParams& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    float mis = 1.0;
    float _e13 = light_range_scale(li_4, x_12, r_8, rl_4, light_cones, _buffer_sizes);
    float _e16 = params.eps;
    Connection _e17 = connect(li_4, x_12, n_18, ng_4, _e13, w_4, u1_5, u2_5, _e16, geo_nodes, geo_tris, lights, r2_4, rt2_5, _buffer_sizes);
    if (_e17.cos_x <= 0.0) {
        return metal::float3(0.0);
    }
    metal::float3 l_10 = metal::normalize(_e17.y - x_12);
    GpuLight _e30 = lights[li_4];
    float _e31 = light_area(_e30);
    if (_e31 > 0.0) {
        float _e37 = light_pdf_selected(li_4, x_12, r_8, rl_4, _e17.y, 1.0 / w_4, lights, rt2_5, light_cones, _buffer_sizes);
        float _e39 = specular_probability(lobe_10);
        float _e40 = bsdf_pdf(n_18, wo_1, l_10, m.alpha, _e39);
        float _e41 = mis_weight(_e37, _e40);
        mis = _e41;
    }
    metal::float3 _e47 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, n_18, wo_1, l_10);
    float _e50 = mis;
    return (_e47 * _e17.e) * _e50;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, device type_6 const& geo_nodes [[user(fake0)]]
, device type_7 const& geo_tris [[user(fake0)]]
, device type_9 const& lights [[user(fake0)]]
, device type_4 const& r2_4 [[user(fake0)]]
, device type_4 const& rt2_5 [[user(fake0)]]
, device type_10 const& light_cones [[user(fake0)]]
, device type_11 const& light_bvh [[user(fake0)]]
, constant ShadeParams& params [[user(fake0)]]
, device type_12 const& vertices [[user(fake0)]]
, device type_13 const& materials [[user(fake0)]]
, device type_14& radiance [[user(fake0)]]
, device type_15& candidates [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint h = {};
    metal::float3 sum = metal::float3(0.0);
    uint i_5 = gid.x;
    uint _e4 = params.point_count;
    if (i_5 >= _e4) {
        return;
    }
    GpuPathVertex vtx = vertices[i_5];
    if (vtx.alive == 0u) {
        candidates[i_5] = 0u;
        return;
    }
    metal::float3 x_13 = vtx.position;
    metal::float3 n_21 = vtx.normal;
    metal::float3 ng_5 = vtx.gnormal;
    GpuMaterial m_2 = materials[vtx.material];
    metal::float3 wo_2 = vtx.wo;
    metal::float3 _e23 = mirror_dir(n_21, wo_2);
    metal::float4 _e30 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, metal::dot(n_21, wo_2));
    metal::float4 _e31 = range_lobe(_e30);
    uint _e34 = params.seed;
    uint _e37 = params.frame;
    uint _e38 = point_stream(_e34, i_5, _e37);
    uint _e39 = pick_stream(_e38);
    h = _e39;
    candidates[i_5] = 0u;
    uint _e47 = h;
    uint _e48 = pcg_hash(_e47);
    h = _e48;
    uint _e49 = h;
    float _e50 = xi_from_bits(_e49);
    BvhPick _e52 = light_bvh_sample(BVH, x_13, n_21, _e23, _e30, _e50, light_bvh, _buffer_sizes);
    uint li_5 = _e52.light;
    float pmf_1 = _e52.pmf;
    uint _e55 = h;
    uint _e56 = pcg_hash(_e55);
    h = _e56;
    uint _e57 = h;
    float _e58 = xi_from_bits(_e57);
    uint _e59 = h;
    uint _e60 = pcg_hash(_e59);
    h = _e60;
    uint _e61 = h;
    float _e62 = xi_from_bits(_e61);
    if (pmf_1 > 0.0) {
        metal::float3 _e68 = shade_pick(li_5, x_13, n_21, ng_5, m_2, wo_2, _e23, _e30, _e31, 1.0 / pmf_1, 0u, _e58, _e62, geo_nodes, geo_tris, lights, r2_4, rt2_5, light_cones, params, _buffer_sizes);
        sum = _e68;
    }
    metal::float3 _e70 = sum;
    metal::float3 add = vtx.weight * _e70;
    bool _e72 = finite3_(add);
    if (_e72) {
        metal::float4 _e75 = radiance[i_5];
        radiance[i_5] = _e75 + metal::float4(add, 0.0);
        return;
    } else {
        return;
    }
}
