// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size1;
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
typedef GpuLight type_11[1];
typedef BshNode type_12[1];
typedef GpuLightCone type_13[1];
struct type_14 {
    uint inner[8];
};
typedef uint BshNodes;
struct Connection {
    metal::float3 e;
    metal::packed_float3 y;
    float cos_x;
};
struct type_16 {
    float inner[8];
};
struct WeightedPicks {
    type_14 light;
    type_16 w;
    type_16 threshold;
    float w_sum;
    uint n;
    uint h;
};
struct type_19 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
};
struct type_20 {
    uint inner[1024];
};
struct type_21 {
    uint inner[256];
};
struct TileWalk {
    metal::float3 lo;
    metal::packed_float3 hi;
    float w;
    uint total;
    char _pad4[12];
};
struct Shaded {
    metal::float3 e;
    metal::float3 diffuse;
    metal::float3 specular;
};
struct Material {
    metal::packed_float3 base;
    float metallic;
    float alpha;
    char _pad3[12];
    metal::packed_float3 v;
    float roughness;
    float reflectance;
    char _pad6[12];
};
struct type_24 {
    metal::uint2 inner[8];
};
struct type_25 {
    bool inner[8];
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
constant uint K = 8u;
constant BshNodes BSH = 0u;
constant uint BSH_TILE_DEPTH = 8u;
constant uint BSH_TILE_SUBTREES = 256u;
constant uint TILE_THREADS = 64u;
constant uint BOX_THREADS = 64u;
constant uint TILE_LIST = 1024u;

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

uint pick_stream(
    uint stream
) {
    uint _e3 = pcg_hash(stream ^ PICK_STREAM);
    return _e3;
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

bool sphere_contains_point(
    metal::float3 c,
    float r_1,
    metal::float3 x_1
) {
    metal::float3 v_3 = x_1 - c;
    return metal::dot(v_3, v_3) <= (r_1 * r_1);
}

bool sphere_overlaps_aabb(
    metal::float3 c_1,
    float r_2,
    metal::float3 bmin,
    metal::float3 bmax
) {
    metal::float3 q = metal::clamp(c_1, bmin, bmax);
    metal::float3 v_4 = q - c_1;
    return metal::dot(v_4, v_4) <= (r_2 * r_2);
}

float inverse_square(
    float d2_2
) {
    return 1.0 / metal::max(d2_2, MIN_D2_);
}

float connection_factor(
    float cos_x,
    float d2_3,
    float rt2_1,
    float w
) {
    float _e4 = inverse_square(d2_3);
    float _e6 = slc_weight(rt2_1, d2_3);
    return ((cos_x * _e4) * _e6) * w;
}

float connection_cosine(
    metal::float3 x_2,
    metal::float3 y,
    metal::float3 n_1,
    metal::float3 ng,
    float r2_1
) {
    bool local_5 = {};
    bool local_6 = {};
    metal::float3 v_5 = x_2 - y;
    float d2_7 = metal::dot(v_5, v_5);
    bool _e7 = slc_keep(r2_1, d2_7);
    if (!(!(_e7))) {
        local_5 = !((d2_7 > 0.0));
    } else {
        local_5 = true;
    }
    bool _e16 = local_5;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_10 = v_5 / metal::float3(metal::sqrt(d2_7));
    float cos_x_1 = -(metal::dot(n_1, w_10));
    if (!(!((cos_x_1 > 0.0)))) {
        local_6 = !((metal::dot(ng, w_10) < 0.0));
    } else {
        local_6 = true;
    }
    bool _e34 = local_6;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float spot_falloff(
    float cos_theta,
    float cos_outer,
    float cos_inner,
    float shape
) {
    if (cos_inner <= cos_outer) {
        return (cos_theta >= cos_outer) ? 1.0 : 0.0;
    }
    float t_4 = metal::saturate((cos_theta - cos_outer) / (cos_inner - cos_outer));
    return (shape > 0.5) ? (t_4 * t_4) : ((t_4 * t_4) * (3.0 - (2.0 * t_4)));
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

float weighted_threshold(
    float w_sum,
    float u_2
) {
    return w_sum / (1.0 - u_2);
}

float weighted_pick_weight(
    float w_sum_1,
    float w_2,
    uint k_2
) {
    float _e3 = to_f32_(k_2);
    return w_sum_1 / (_e3 * w_2);
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
    float t_5 = ((cos_h * cos_h) * a2_) + sin2_h;
    return (a2_ * INV_PI) / (t_5 * t_5);
}

float smith_root(
    float cos,
    float alpha_1
) {
    float a2_1 = alpha_1 * alpha_1;
    return metal::sqrt(((cos * cos) * (1.0 - a2_1)) + a2_1);
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
    float x_3
) {
    return metal::sqrt(metal::max(x_3, 0.0));
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
    bool local_7 = {};
    metal::float3 v_6 = p - center;
    float dist2_1 = metal::dot(v_6, v_6);
    float r2_5 = radius * radius;
    if (dist2_1 <= 0.0) {
        local_7 = r2_5 <= 0.0;
    } else {
        local_7 = false;
    }
    bool _e15 = local_7;
    if (_e15) {
        return metal::float4(-2.0, 0.000000000001, -1.0, 0.0);
    }
    float d2_8 = metal::max(metal::max(dist2_1, r2_5), MIN_D2_);
    metal::float3 wi = (dist2_1 > 0.0) ? (v_6 / metal::float3(metal::sqrt(dist2_1))) : metal::float3(0.0, 0.0, 0.0);
    float cos_w = metal::dot(axis, wi);
    float _e38 = safe_sqrt(1.0 - (cos_w * cos_w));
    float _e39 = subtended_cos(dist2_1, r2_5);
    float _e43 = safe_sqrt(1.0 - (_e39 * _e39));
    float _e47 = safe_sqrt(1.0 - (cos_o * cos_o));
    float _e48 = cos_sub_clamped(_e38, cos_w, _e47, cos_o);
    float _e49 = sin_sub_clamped(_e38, cos_w, _e47, cos_o);
    float _e50 = cos_sub_clamped(_e49, _e48, _e43, _e39);
    return metal::float4(_e50, d2_8, _e39, _e43);
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
    metal::float3 v,
    float d2_4,
    float a_2,
    metal::float3 d
) {
    bool local_8 = {};
    bool local_9 = {};
    float vd = metal::dot(v, d);
    float h2_ = d2_4 - (a_2 * a_2);
    if (!((h2_ <= 0.0))) {
        if (vd >= 0.0) {
            local_9 = (vd * vd) >= h2_;
        } else {
            local_9 = false;
        }
        bool _e19 = local_9;
        local_8 = _e19;
    } else {
        local_8 = true;
    }
    bool _e21 = local_8;
    if (_e21) {
        return 1.0;
    }
    metal::float3 c_5 = metal::cross(v, d);
    return metal::min(((vd * metal::sqrt(h2_)) + (metal::sqrt(metal::dot(c_5, c_5)) * a_2)) / d2_4, 1.0);
}

float cone_cos_toward(
    metal::float3 center_2,
    float radius_2,
    metal::float3 p_2,
    metal::float3 d_1
) {
    metal::float3 v_7 = center_2 - p_2;
    float _e6 = cone_cos_of(v_7, metal::dot(v_7, v_7), radius_2, d_1);
    return _e6;
}

float range_scale_at(
    metal::float4 rl,
    float cos_t
) {
    float t_6 = ((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0;
    return metal::clamp(rl.x + ((rl.y * rl.z) / (t_6 * t_6)), 1.0, rl.w * rl.w);
}

float range_scale_toward(
    metal::float4 rl_1,
    metal::float3 center_3,
    float radius_3,
    metal::float3 p_3,
    metal::float3 r_3
) {
    if (rl_1.w <= 1.0) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_3, radius_3, p_3, r_3);
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
    metal::float3 n_2
) {
    float imp = {};
    metal::float4 _e8 = emitter_cone(center_4, radius_4, axis_2, cos_o_2, p_4);
    if (_e8.x <= cos_e_1) {
        return 0.0;
    }
    imp = (phi_1 * _e8.x) / _e8.y;
    if (metal::dot(n_2, n_2) > 0.0) {
        metal::float3 v_8 = center_4 - p_4;
        float dist2_2 = metal::dot(v_8, v_8);
        float cos_i = metal::dot((dist2_2 > 0.0) ? (v_8 / metal::float3(metal::sqrt(dist2_2))) : metal::float3(0.0, 0.0, 0.0), n_2);
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
    metal::float3 n_3,
    metal::float3 r_4,
    metal::float4 lobe_5
) {
    bool local_10 = {};
    float _e10 = emitter_importance(center_5, radius_5, phi_2, axis_3, cos_o_3, cos_e_2, p_5);
    float _e11 = cone_cos_toward(center_5, radius_5, p_5, n_3);
    if (!((_e10 <= 0.0))) {
        local_10 = _e11 <= 0.0;
    } else {
        local_10 = true;
    }
    bool _e20 = local_10;
    if (_e20) {
        return 0.0;
    }
    float _e22 = cone_cos_toward(center_5, radius_5, p_5, r_4);
    float _e27 = safe_sqrt(0.5 + (0.5 * _e22));
    float _e33 = ggx_d(_e27, 1.0 - (_e27 * _e27), lobe_5.z);
    float _e39 = smith_root(lobe_5.w, lobe_5.z);
    float spec = ((lobe_5.y * _e33) * 0.25) / _e39;
    return _e10 * (((lobe_5.x * INV_PI) * _e11) + spec);
}

float candidate_weight(
    float importance,
    float rt2_2,
    float d2_5
) {
    float _e3 = slc_weight(rt2_2, d2_5);
    return importance * _e3;
}

float cone_weight(
    metal::float3 center_6,
    float radius_6,
    float phi_3,
    metal::float3 axis_4,
    float cos_o_4,
    float cos_e_3,
    float rt2_3,
    metal::float3 p_6,
    metal::float3 n_4,
    metal::float3 r_5,
    metal::float4 lobe_6
) {
    metal::float3 v_9 = p_6 - center_6;
    if (lobe_6.y <= 0.0) {
        float _e15 = light_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_4);
        float _e19 = candidate_weight(_e15 * INV_PI, rt2_3, metal::dot(v_9, v_9));
        return _e19;
    }
    float _e20 = glossy_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_4, r_5, lobe_6);
    float _e22 = candidate_weight(_e20, rt2_3, metal::dot(v_9, v_9));
    return _e22;
}

bool finite3_(
    metal::float3 v_1
) {
    bool local_11 = {};
    bool local_12 = {};
    if (metal::abs(v_1.x) <= F32_MAX) {
        local_11 = metal::abs(v_1.y) <= F32_MAX;
    } else {
        local_11 = false;
    }
    bool _e12 = local_11;
    if (_e12) {
        local_12 = metal::abs(v_1.z) <= F32_MAX;
    } else {
        local_12 = false;
    }
    bool _e20 = local_12;
    return _e20;
}

float shadow_margin(
    float len
) {
    return 0.0001 * len;
}

float ray_inverse(
    float x_4
) {
    return 1.0 / ((metal::abs(x_4) < 0.000000000000000000000000000001) ? 0.000000000000000000000000000001 : x_4);
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
    metal::float3 bmin_1,
    metal::float3 bmax_1,
    float t_max
) {
    metal::float3 t0_ = (bmin_1 - o) * inv_d;
    metal::float3 t1_ = (bmax_1 - o) * inv_d;
    metal::float3 lo_3 = metal::min(t0_, t1_);
    metal::float3 hi_3 = metal::max(t0_, t1_);
    float t_in = metal::max(metal::max(lo_3.x, lo_3.y), metal::max(lo_3.z, 0.0));
    float t_out = metal::min(metal::min(hi_3.x, hi_3.y), metal::min(hi_3.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1.0;
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_3,
    metal::float3 a_3,
    metal::float3 b_2,
    metal::float3 c_2,
    float t_min,
    float t_max_1
) {
    bool local_13 = {};
    bool local_14 = {};
    bool local_15 = {};
    metal::float3 e1_ = b_2 - a_3;
    metal::float3 e2_ = c_2 - a_3;
    metal::float3 p_10 = metal::cross(d_3, e2_);
    float det = metal::dot(e1_, p_10);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv = 1.0 / det;
    metal::float3 s_9 = o_1 - a_3;
    float u_3 = metal::dot(s_9, p_10) * inv;
    if (!((u_3 < 0.0))) {
        local_13 = u_3 > 1.0;
    } else {
        local_13 = true;
    }
    bool _e28 = local_13;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q_1 = metal::cross(s_9, e1_);
    float v_10 = metal::dot(d_3, q_1) * inv;
    if (!((v_10 < 0.0))) {
        local_14 = (u_3 + v_10) > 1.0;
    } else {
        local_14 = true;
    }
    bool _e42 = local_14;
    if (_e42) {
        return -1.0;
    }
    float t_7 = metal::dot(e2_, q_1) * inv;
    if (t_7 > t_min) {
        local_15 = t_7 < t_max_1;
    } else {
        local_15 = false;
    }
    bool _e51 = local_15;
    if (_e51) {
        return t_7;
    }
    return -1.0;
}

metal::float3 light_intensity(
    GpuLight l,
    metal::float3 w_3
) {
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            float _e11 = spot_falloff(metal::dot(l.p1_, w_3), l.a, l.b, l.p2_[0]);
            return l.intensity * _e11;
        }
        default: {
            return metal::float3(0.0);
        }
    }
}

metal::float3 light_point(
    GpuLight l_1,
    float u1_,
    float u2_
) {
    return l_1.p0_;
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
    uint node_3 = 0u;
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
        uint _e21 = node_3;
        GpuGeoNode n_11 = geo_nodes[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_11.bmin, n_11.bmax, _e27);
        if (_e28 >= 0.0) {
            if (n_11.count > 0u) {
                i = n_11.first;
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
                    if (_e36 < (n_11.first + n_11.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_8 = geo_tris[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_4, t_8.v0_, t_8.v1_, t_8.v2_, t_min_1, _e49);
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
                    stack.inner[_e63] = n_11.first + 1u;
                    uint _e68 = sp;
                    sp = _e68 + 1u;
                }
                node_3 = n_11.first;
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

bool occluded(
    metal::float3 a_4,
    metal::float3 b_3,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 dv = b_3 - a_4;
    float len_1 = metal::length(dv);
    if (len_1 <= 0.0) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    GeoHit _e12 = trace(a_4, dv / metal::float3(len_1), _e7, len_1 - _e7, true, geo_nodes, geo_tris, _buffer_sizes);
    return _e12.tri != NO_LIGHT;
}

BshNode bsh_node(
    BshNodes nodes,
    uint i_1,
    device type_12 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshNode _e4 = bsh_nodes[i_1];
    return _e4;
}

uint bsh_count(
    BshNodes nodes_1,
    device type_12 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    return 1 + (_buffer_sizes.size9 - 0 - 32) / 32;
}

uint bsh_first(
    BshNodes nodes_2,
    device type_12 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e1 = bsh_count(nodes_2, bsh_nodes, _buffer_sizes);
    if (_e1 > 0u) {
        return 0u;
    }
    return BSH_NONE;
}

float bsh_inner_scale(
    float a_5,
    metal::float3 v_2,
    float d2_6,
    metal::float3 r_6,
    metal::float4 rl_2
) {
    float _e5 = cone_cos_of(v_2, d2_6, a_5, r_6);
    float _e8 = range_scale_at(rl_2, _e5 + 0.000002);
    return _e8;
}

bool bsh_reaches(
    BshNode node_4,
    metal::float3 x_5,
    metal::float3 r_7,
    metal::float4 rl_3
) {
    bool local_16 = {};
    bool local_17 = {};
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_5);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, node_4.radius * (rl_3.w * 1.0001), x_5);
        local_16 = !(_e20);
    } else {
        local_16 = true;
    }
    bool _e23 = local_16;
    if (_e23) {
        return false;
    }
    metal::float3 v_11 = x_5 - node_4.center;
    float d2_9 = metal::dot(v_11, v_11);
    float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_9 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        float _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_5, r_7);
        float _e41 = bsh_scaled_radius(node_4, metal::sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_5);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_11), d2_9, r_7, rl_3);
    float s_c = _e45 * 1.001;
    float _e50 = bsh_range_bound(node_4);
    float reach = node_4.extent + (metal::sqrt(s_c) * _e50);
    if (d2_9 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_17 = d2_9 <= (reach * reach);
    } else {
        local_17 = false;
    }
    bool _e63 = local_17;
    return _e63;
}

bool bsh_reaches_box(
    BshNode node_5,
    metal::float3 lo,
    metal::float3 hi,
    float w_4
) {
    bool _e13 = sphere_overlaps_aabb(node_5.center, node_5.radius * (metal::max(1.0, w_4 * 1.0001) * 1.0001), lo, hi);
    return _e13;
}

uint bsh_subtree(
    BshNodes nodes_3,
    uint s_1,
    uint depth,
    device type_12 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_2 = {};
    uint level = 0u;
    bool local_18 = {};
    uint _e3 = bsh_first(nodes_3, bsh_nodes, _buffer_sizes);
    i_2 = _e3;
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e7 = level;
        if (_e7 < depth) {
            uint _e11 = i_2;
            local_18 = _e11 != BSH_NONE;
        } else {
            local_18 = false;
        }
        bool _e15 = local_18;
        if (_e15) {
        } else {
            break;
        }
        {
            uint _e16 = i_2;
            BshNode _e17 = bsh_node(nodes_3, _e16, bsh_nodes, _buffer_sizes);
            uint _e18 = level;
            uint below = depth - _e18;
            if (_e17.child == BSH_NONE) {
                if ((s_1 << (32u - below)) != 0u) {
                    return BSH_NONE;
                }
                uint _e29 = i_2;
                return _e29;
            }
            if (((s_1 >> (below - 1u)) & 1u) == 0u) {
                i_2 = _e17.child;
            } else {
                BshNode _e39 = bsh_node(nodes_3, _e17.child, bsh_nodes, _buffer_sizes);
                i_2 = _e39.next;
            }
            uint _e41 = level;
            level = _e41 + 1u;
        }
    }
    uint _e44 = i_2;
    return _e44;
}

uint bsh_next_leaf_box(
    BshNodes nodes_4,
    uint start_1,
    uint end,
    metal::float3 lo_1,
    metal::float3 hi_1,
    float w_5,
    device type_12 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_3 = {};
    i_3 = start_1;
    uint2 loop_bound_3 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e7 = i_3;
        if (_e7 != end) {
        } else {
            break;
        }
        {
            uint _e9 = i_3;
            BshNode _e10 = bsh_node(nodes_4, _e9, bsh_nodes, _buffer_sizes);
            bool _e11 = bsh_reaches_box(_e10, lo_1, hi_1, w_5);
            if (_e11) {
                if (_e10.child == BSH_NONE) {
                    if ((_e10.light & BSH_TAIL) == 0u) {
                        uint _e20 = i_3;
                        return _e20;
                    }
                    i_3 = _e10.next;
                } else {
                    i_3 = _e10.child;
                }
            } else {
                i_3 = _e10.next;
            }
        }
    }
    return end;
}

float next_threshold(
    float sum,
    thread uint& h_1
) {
    uint _e2 = h_1;
    uint _e3 = pcg_hash(_e2);
    h_1 = _e3;
    uint _e4 = h_1;
    float _e5 = xi_from_bits(_e4);
    float _e6 = weighted_threshold(sum, _e5);
    return _e6;
}

Connection connect_record(
    GpuLight l_2,
    metal::float3 x_6,
    metal::float3 n_5,
    metal::float3 ng_1,
    float r2_3,
    float rt2_4,
    float w_res,
    float u1_1,
    float u2_1,
    float eps,
    bool trace_1,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection c_3 = {};
    bool local_19 = {};
    bool local_20 = {};
    c_3.e = metal::float3(0.0);
    metal::float3 _e16 = light_point(l_2, u1_1, u2_1);
    c_3.y = _e16;
    metal::float3 _e19 = c_3.y;
    float _e20 = connection_cosine(x_6, _e19, n_5, ng_1, r2_3);
    c_3.cos_x = _e20;
    float _e22 = c_3.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            metal::float3 _e33 = c_3.y;
            bool _e34 = occluded(x_6 + (ng_1 * eps), _e33, geo_nodes, geo_tris, _buffer_sizes);
            local_20 = _e34;
        } else {
            local_20 = false;
        }
        bool _e36 = local_20;
        local_19 = _e36;
    } else {
        local_19 = true;
    }
    bool _e38 = local_19;
    if (_e38) {
        Connection _e39 = c_3;
        return _e39;
    }
    metal::float3 _e41 = c_3.y;
    metal::float3 v_12 = x_6 - _e41;
    float d2_10 = metal::dot(v_12, v_12);
    metal::float3 _e48 = light_intensity(l_2, v_12 / metal::float3(metal::sqrt(d2_10)));
    float _e50 = c_3.cos_x;
    float _e51 = connection_factor(_e50, d2_10, rt2_4, w_res);
    c_3.e = _e48 * _e51;
    Connection _e53 = c_3;
    return _e53;
}

Connection connect_traced(
    uint li,
    metal::float3 x_7,
    metal::float3 n_6,
    metal::float3 ng_2,
    float s_2,
    float w_res_1,
    float u1_2,
    float u2_2,
    float eps_1,
    bool trace_2,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    device type_11 const& lights,
    device type_4 const& rt2_5,
    device type_4 const& r2_4,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight _e12 = lights[li];
    float _e15 = r2_4[li];
    float _e19 = rt2_5[li];
    Connection _e21 = connect_record(_e12, x_7, n_6, ng_2, s_2 * _e15, s_2 * _e19, w_res_1, u1_2, u2_2, eps_1, trace_2, geo_nodes, geo_tris, _buffer_sizes);
    return _e21;
}

float light_range_scale(
    uint li_1,
    metal::float3 x_8,
    metal::float3 r_8,
    metal::float4 rl_4,
    device type_13 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_6 = light_cones[li_1];
    float _e9 = range_scale_toward(rl_4, c_6.center, c_6.radius, x_8, r_8);
    return _e9;
}

float light_weight(
    uint li_2,
    metal::float3 x_9,
    metal::float3 n_7,
    metal::float3 r_9,
    metal::float4 lobe_7,
    metal::float4 rl_5,
    device type_4 const& rt2_5,
    device type_13 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_7 = light_cones[li_2];
    float _e15 = light_range_scale(li_2, x_9, r_9, rl_5, light_cones, _buffer_sizes);
    float _e18 = rt2_5[li_2];
    float _e20 = cone_weight(c_7.center, c_7.radius, c_7.phi, c_7.axis, c_7.cos_o, c_7.cos_e, _e15 * _e18, x_9, n_7, r_9, lobe_7);
    return _e20;
}

WeightedPicks weighted_picks(
    uint h_2
) {
    WeightedPicks picks_1 = {};
    picks_1.w_sum = 0.0;
    picks_1.n = 0u;
    picks_1.h = h_2;
    WeightedPicks _e7 = picks_1;
    return _e7;
}

void weighted_offer(
    thread WeightedPicks& picks_2,
    uint li_3,
    float w_6
) {
    uint h_3 = {};
    uint s_3 = 0u;
    uint _e4 = picks_2.n;
    picks_2.n = _e4 + 1u;
    if (w_6 > 0.0) {
        float _e10 = picks_2.w_sum;
        picks_2.w_sum = _e10 + w_6;
        uint _e13 = picks_2.h;
        h_3 = _e13;
        uint2 loop_bound_4 = uint2(4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (metal::all(loop_bound_4 == uint2(0u))) { break; }
            loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e40 = s_3;
                s_3 = _e40 + 1u;
            }
            loop_init_1 = false;
            uint _e17 = s_3;
            if (_e17 < K) {
            } else {
                break;
            }
            {
                float _e21 = picks_2.w_sum;
                uint _e23 = s_3;
                float _e25 = picks_2.threshold.inner[_e23];
                if (_e21 > _e25) {
                    uint _e28 = s_3;
                    picks_2.light.inner[_e28] = li_3;
                    uint _e31 = s_3;
                    picks_2.w.inner[_e31] = w_6;
                    uint _e34 = s_3;
                    float _e37 = picks_2.w_sum;
                    float _e38 = next_threshold(_e37, h_3);
                    picks_2.threshold.inner[_e34] = _e38;
                }
            }
        }
        uint _e43 = h_3;
        picks_2.h = _e43;
        return;
    } else {
        return;
    }
}

metal::float4 unproject_pixel(
    metal::float4 c0_,
    metal::float4 c1_,
    metal::float4 c2_,
    metal::float4 c3_,
    float px,
    float py,
    float width,
    float height,
    float depth_1
) {
    bool local_21 = {};
    bool local_22 = {};
    if (depth_1 > 0.0) {
        local_21 = depth_1 < 1.0;
    } else {
        local_21 = false;
    }
    bool _e16 = local_21;
    if (!(_e16)) {
        return metal::float4(0.0, 0.0, 0.0, 0.0);
    }
    float x_14 = (((px + 0.5) / width) * 2.0) - 1.0;
    float y_1 = 1.0 - (((py + 0.5) / height) * 2.0);
    metal::float4 p_11 = (((c0_ * x_14) + (c1_ * y_1)) + (c2_ * depth_1)) + c3_;
    metal::float3 q_2 = metal::float3(p_11.x / p_11.w, p_11.y / p_11.w, p_11.z / p_11.w);
    if (metal::abs(p_11.w) > 0.0) {
        bool _e59 = finite3_(q_2);
        local_22 = _e59;
    } else {
        local_22 = false;
    }
    bool _e61 = local_22;
    if (_e61) {
        return metal::float4(q_2.x, q_2.y, q_2.z, 1.0);
    }
    return metal::float4(0.0, 0.0, 0.0, 0.0);
}

metal::float4 surface_at(
    metal::int2 texel,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> depth_tex
) {
    metal::float4 _e3 = depth_tex.read(metal::uint2(texel), 0);
    float d_5 = _e3.x;
    metal::float4 _e7 = view.c0_;
    metal::float4 _e10 = view.c1_;
    metal::float4 _e13 = view.c2_;
    metal::float4 _e16 = view.c3_;
    uint _e23 = view.width;
    uint _e27 = view.height;
    metal::float4 _e29 = unproject_pixel(_e7, _e10, _e13, _e16, static_cast<float>(texel.x), static_cast<float>(texel.y), static_cast<float>(_e23), static_cast<float>(_e27), d_5);
    return _e29;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

WorkgroupBox workgroup_bounds(
    uint li_4,
    metal::float3 lo_2,
    metal::float3 hi_2,
    threadgroup type_19& wg_lo,
    threadgroup type_19& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    uint stride = 32u;
    wg_lo.inner[li_4] = lo_2;
    wg_hi.inner[li_4] = hi_2;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e36 = stride;
            stride = naga_div(_e36, 2u);
        }
        loop_init_2 = false;
        uint _e9 = stride;
        if (_e9 > 0u) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if (li_4 < _e12) {
                metal::float3 _e18 = wg_lo.inner[li_4];
                uint _e20 = stride;
                metal::float3 _e23 = wg_lo.inner[li_4 + _e20];
                wg_lo.inner[li_4] = metal::min(_e18, _e23);
                metal::float3 _e29 = wg_hi.inner[li_4];
                uint _e31 = stride;
                metal::float3 _e34 = wg_hi.inner[li_4 + _e31];
                wg_hi.inner[li_4] = metal::max(_e29, _e34);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (li_4 == 0u) {
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
    metal::float3 p_7,
    bool has
) {
    return WorkgroupBox {has ? p_7 : metal::float3(340282350000000000000000000000000000000.0), has ? p_7 : metal::float3(-340282350000000000000000000000000000000.0)};
}

WorkgroupBox workgroup_box(
    uint li_5,
    metal::float3 p_8,
    bool has_1,
    threadgroup type_19& wg_lo,
    threadgroup type_19& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    WorkgroupBox _e3 = point_box(p_8, has_1);
    WorkgroupBox _e6 = workgroup_bounds(li_5, _e3.lo, _e3.hi, wg_lo, wg_hi, wg_box);
    return _e6;
}

bool box_is_empty(
    WorkgroupBox b_4
) {
    return b_4.lo.x > b_4.hi.x;
}

uint tile_subtree(
    uint s_4,
    TileWalk t_1,
    bool list,
    uint at,
    uint start_2,
    uint to,
    device type_12 const& bsh_nodes,
    threadgroup type_20& tile_list,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint p_9 = {};
    uint b_5 = {};
    bool local_23 = {};
    bool local_24 = {};
    bool local_25 = {};
    uint _e8 = bsh_subtree(BSH, s_4, BSH_TILE_DEPTH, bsh_nodes, _buffer_sizes);
    if (_e8 == BSH_NONE) {
        return 0u;
    }
    uint end_1 = bsh_nodes[_e8].next;
    p_9 = at;
    uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_1.lo, t_1.hi, t_1.w, bsh_nodes, _buffer_sizes);
    b_5 = _e21;
    uint2 loop_bound_6 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e53 = b_5;
            uint _e56 = bsh_nodes[_e53].next;
            uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_1.lo, t_1.hi, t_1.w, bsh_nodes, _buffer_sizes);
            b_5 = _e60;
        }
        loop_init_3 = false;
        uint _e23 = b_5;
        if (_e23 != end_1) {
            if (!(!(list))) {
                uint _e31 = p_9;
                local_24 = _e31 < to;
            } else {
                local_24 = true;
            }
            bool _e34 = local_24;
            local_23 = _e34;
        } else {
            local_23 = false;
        }
        bool _e36 = local_23;
        if (_e36) {
        } else {
            break;
        }
        {
            if (list) {
                uint _e39 = p_9;
                local_25 = _e39 >= start_2;
            } else {
                local_25 = false;
            }
            bool _e42 = local_25;
            if (_e42) {
                uint _e44 = p_9;
                uint _e47 = b_5;
                tile_list.inner[_e44 - start_2] = _e47;
            }
            uint _e48 = p_9;
            p_9 = _e48 + 1u;
        }
    }
    uint _e61 = p_9;
    return _e61 - at;
}

TileWalk tile_walk_begin(
    uint li_6,
    metal::float3 x_10,
    float w_7,
    bool has_2,
    device type_12 const& bsh_nodes,
    threadgroup type_19& wg_lo,
    threadgroup type_19& wg_hi,
    threadgroup WorkgroupBox& wg_box,
    threadgroup type_20& tile_list,
    threadgroup type_21& subtree_at,
    threadgroup metal::atomic_uint& tile_scale,
    threadgroup uint& tile_total,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_26 = {};
    TileWalk t_2 = {};
    uint s_5 = {};
    uint sum_1 = 0u;
    uint s_6 = 0u;
    if (has_2) {
        local_26 = w_7 >= 0.0;
    } else {
        local_26 = false;
    }
    bool _e12 = local_26;
    uint _e14 = metal::atomic_fetch_max_explicit(&tile_scale, _e12 ? as_type<uint>(w_7) : 0u, metal::memory_order_relaxed);
    WorkgroupBox _e15 = workgroup_box(li_6, x_10, has_2, wg_lo, wg_hi, wg_box);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_1 = metal::atomic_load_explicit(&tile_scale, metal::memory_order_relaxed);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    t_2 = TileWalk {_e15.lo, _e15.hi, as_type<float>(unnamed_1), 0u};
    bool _e24 = box_is_empty(_e15);
    if (_e24) {
        TileWalk _e25 = t_2;
        return _e25;
    }
    s_5 = li_6;
    uint2 loop_bound_7 = uint2(4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (metal::all(loop_bound_7 == uint2(0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e40 = s_5;
            s_5 = _e40 + TILE_THREADS;
        }
        loop_init_4 = false;
        uint _e27 = s_5;
        if (_e27 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            uint _e31 = s_5;
            uint _e33 = s_5;
            TileWalk _e34 = t_2;
            uint _e39 = tile_subtree(_e33, _e34, false, 0u, 0u, 0u, bsh_nodes, tile_list, _buffer_sizes);
            subtree_at.inner[_e31] = _e39;
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    if (li_6 == 0u) {
        uint2 loop_bound_8 = uint2(4294967295u);
        bool loop_init_5 = true;
        while(true) {
            if (metal::all(loop_bound_8 == uint2(0u))) { break; }
            loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
            if (!loop_init_5) {
                uint _e63 = s_6;
                s_6 = _e63 + 1u;
            }
            loop_init_5 = false;
            uint _e49 = s_6;
            if (_e49 < BSH_TILE_SUBTREES) {
            } else {
                break;
            }
            {
                uint _e53 = s_6;
                uint c_8 = subtree_at.inner[_e53];
                uint _e57 = s_6;
                uint _e59 = sum_1;
                subtree_at.inner[_e57] = _e59;
                uint _e60 = sum_1;
                sum_1 = _e60 + c_8;
            }
        }
        uint _e66 = sum_1;
        tile_total = _e66;
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_2 = tile_total;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    t_2.total = unnamed_2;
    TileWalk _e70 = t_2;
    return _e70;
}

uint tile_walk_fill(
    uint li_7,
    TileWalk t_3,
    uint start_3,
    device type_12 const& bsh_nodes,
    threadgroup type_20& tile_list,
    threadgroup type_21& subtree_at,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint s_7 = {};
    uint past = {};
    bool local_27 = {};
    uint to_1 = metal::min(t_3.total, start_3 + TILE_LIST);
    s_7 = li_7;
    uint2 loop_bound_9 = uint2(4294967295u);
    bool loop_init_6 = true;
    while(true) {
        if (metal::all(loop_bound_9 == uint2(0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_6) {
            uint _e38 = s_7;
            s_7 = _e38 + TILE_THREADS;
        }
        loop_init_6 = false;
        uint _e8 = s_7;
        if (_e8 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            uint _e12 = s_7;
            uint at_1 = subtree_at.inner[_e12];
            past = t_3.total;
            uint _e17 = s_7;
            if ((_e17 + 1u) < BSH_TILE_SUBTREES) {
                uint _e23 = s_7;
                uint _e27 = subtree_at.inner[_e23 + 1u];
                past = _e27;
            }
            if (at_1 < to_1) {
                uint _e31 = past;
                local_27 = _e31 > start_3;
            } else {
                local_27 = false;
            }
            bool _e34 = local_27;
            if (_e34) {
                uint _e35 = s_7;
                uint _e37 = tile_subtree(_e35, t_3, true, at_1, start_3, to_1, bsh_nodes, tile_list, _buffer_sizes);
            }
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return to_1 - start_3;
}

Shaded shade_connection(
    Connection c_4,
    metal::float3 x_11,
    metal::float3 n_8,
    Material m_1
) {
    Shaded s_8 = {};
    s_8.e = c_4.e;
    s_8.diffuse = metal::float3(0.0);
    s_8.specular = metal::float3(0.0);
    Shaded _e13 = s_8;
    return _e13;
}

Shaded shade_pick_traced(
    uint li_8,
    metal::float3 x_12,
    metal::float3 n_9,
    metal::float3 r_10,
    metal::float4 rl_6,
    Material m_2,
    float w_8,
    float u1_3,
    float u2_3,
    float eps_2,
    bool trace_3,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    device type_11 const& lights,
    device type_4 const& rt2_5,
    device type_4 const& r2_4,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection _e12 = connect_traced(li_8, x_12, n_9, n_9, 1.0, w_8, u1_3, u2_3, eps_2, trace_3, geo_nodes, geo_tris, lights, rt2_5, r2_4, _buffer_sizes);
    Shaded _e13 = shade_connection(_e12, x_12, n_9, m_2);
    return _e13;
}

Shaded shade_pick(
    uint li_9,
    metal::float3 x_13,
    metal::float3 n_10,
    metal::float3 r_11,
    metal::float4 rl_7,
    Material m_3,
    float w_9,
    float u1_4,
    float u2_4,
    float eps_3,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    device type_11 const& lights,
    device type_4 const& rt2_5,
    device type_4 const& r2_4,
    constant _mslBufferSizes& _buffer_sizes
) {
    Shaded _e11 = shade_pick_traced(li_9, x_13, n_10, r_11, rl_7, m_3, w_9, u1_4, u2_4, eps_3, true, geo_nodes, geo_tris, lights, rt2_5, r2_4, _buffer_sizes);
    return _e11;
}

Shaded add(
    Shaded a_6,
    Shaded b_6
) {
    return Shaded {a_6.e + b_6.e, a_6.diffuse + b_6.diffuse, a_6.specular + b_6.specular};
}

type_14 first_holders(
    type_24 keys_1,
    type_25 held_1
) {
    type_14 first = {};
    uint k_3 = 0u;
    uint j_2 = {};
    bool local_28 = {};
    bool local_29 = {};
    uint2 loop_bound_10 = uint2(4294967295u);
    bool loop_init_7 = true;
    while(true) {
        if (metal::all(loop_bound_10 == uint2(0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        if (!loop_init_7) {
            uint _e45 = k_3;
            k_3 = _e45 + 1u;
        }
        loop_init_7 = false;
        uint _e5 = k_3;
        if (_e5 < K) {
        } else {
            break;
        }
        {
            uint _e8 = k_3;
            uint _e11 = k_3;
            uint _e12 = k_3;
            first.inner[_e8] = held_1.inner[_e12] ? _e11 : K;
            j_2 = 0u;
            uint2 loop_bound_11 = uint2(4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (metal::all(loop_bound_11 == uint2(0u))) { break; }
                loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e42 = j_2;
                    j_2 = _e42 + 1u;
                }
                loop_init_8 = false;
                uint _e17 = j_2;
                uint _e18 = k_3;
                if (_e17 < _e18) {
                    uint _e22 = k_3;
                    local_28 = held_1.inner[_e22];
                } else {
                    local_28 = false;
                }
                bool _e25 = local_28;
                if (_e25) {
                } else {
                    break;
                }
                {
                    uint _e26 = j_2;
                    if (held_1.inner[_e26]) {
                        uint _e30 = j_2;
                        uint _e32 = k_3;
                        local_29 = metal::all(keys_1.inner[_e30] == keys_1.inner[_e32]);
                    } else {
                        local_29 = false;
                    }
                    bool _e37 = local_29;
                    if (_e37) {
                        uint _e38 = k_3;
                        uint _e40 = j_2;
                        first.inner[_e38] = _e40;
                        break;
                    }
                }
            }
        }
    }
    type_14 _e47 = first;
    return _e47;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, uint lid [[thread_index_in_threadgroup]]
, device type_6 const& geo_nodes [[user(fake0)]]
, device type_7 const& geo_tris [[user(fake0)]]
, constant ViewParams& view [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> depth_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::write> out_tex [[user(fake0)]]
, device type_11 const& lights [[user(fake0)]]
, device type_4 const& rt2_5 [[user(fake0)]]
, device type_4 const& r2_4 [[user(fake0)]]
, device type_12 const& bsh_nodes [[user(fake0)]]
, device type_13 const& light_cones [[user(fake0)]]
, threadgroup type_19& wg_lo
, threadgroup type_19& wg_hi
, threadgroup WorkgroupBox& wg_box
, threadgroup type_20& tile_list
, threadgroup type_21& subtree_at
, threadgroup metal::atomic_uint& tile_scale
, threadgroup uint& tile_total
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    if (lid == 0u) {
        wg_lo = {};
        wg_hi = {};
        wg_box = {};
        tile_list = {};
        subtree_at = {};
        metal::atomic_store_explicit(&tile_scale, 0, metal::memory_order_relaxed);
        tile_total = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    bool local = {};
    metal::float4 s = metal::float4(0.0);
    metal::float3 nn = metal::float3(0.0);
    bool local_1 = {};
    bool local_2 = {};
    bool local_3 = {};
    metal::float3 n = metal::float3(0.0, 0.0, 1.0);
    Material m = {};
    metal::float4 lobe = metal::float4(1.0, 0.0, 1.0, 1.0);
    metal::float3 r = {};
    uint h = {};
    Shaded t = Shaded {metal::float3(0.0), metal::float3(0.0), metal::float3(0.0)};
    WeightedPicks picks = {};
    uint start = 0u;
    uint j = {};
    bool local_4 = {};
    type_24 keys = {};
    type_25 held = {};
    uint k = 0u;
    uint k_1 = 0u;
    uint copies = {};
    uint j_1 = {};
    uint _e5 = view.width;
    if (gid.x < _e5) {
        uint _e12 = view.height;
        local = gid.y < _e12;
    } else {
        local = false;
    }
    bool inside = local;
    metal::int2 texel_1 = metal::int2(static_cast<int>(gid.x), static_cast<int>(gid.y));
    if (inside) {
        metal::float4 _e27 = surface_at(texel_1, view, depth_tex);
        s = _e27;
        metal::float4 _e30 = normal_tex.read(metal::uint2(texel_1), 0);
        nn = _e30.xyz;
    }
    metal::float3 _e32 = nn;
    metal::float3 _e33 = nn;
    float len2_ = metal::dot(_e32, _e33);
    metal::float4 _e35 = s;
    metal::float3 x_15 = _e35.xyz;
    if (inside) {
        float _e40 = s.w;
        local_1 = _e40 > 0.0;
    } else {
        local_1 = false;
    }
    bool _e44 = local_1;
    if (_e44) {
        local_2 = len2_ > 0.0;
    } else {
        local_2 = false;
    }
    bool _e50 = local_2;
    if (_e50) {
        local_3 = metal::all(metal::abs(x_15) <= metal::float3(340282350000000000000000000000000000000.0));
    } else {
        local_3 = false;
    }
    bool has_3 = local_3;
    if (has_3) {
        metal::float3 _e65 = nn;
        n = _e65 / metal::float3(metal::sqrt(len2_));
    }
    metal::float3 _e76 = n;
    r = _e76;
    metal::float4 _e78 = lobe;
    metal::float4 _e79 = range_lobe(_e78);
    float _e82 = view.shadow_offset;
    metal::float3 _e85 = view.eye;
    float eps_4 = _e82 * metal::length(_e85 - x_15);
    uint _e91 = view.seed;
    uint _e95 = view.width;
    uint _e101 = view.frame;
    uint _e102 = point_stream(_e91, (gid.y * _e95) + gid.x, _e101);
    uint _e103 = pick_stream(_e102);
    h = _e103;
    WeightedPicks _e113 = weighted_picks(_e102);
    picks = _e113;
    TileWalk _e116 = tile_walk_begin(lid, x_15, _e79.w, has_3, bsh_nodes, wg_lo, wg_hi, wg_box, tile_list, subtree_at, tile_scale, tile_total, _buffer_sizes);
    uint2 loop_bound_12 = uint2(4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (metal::all(loop_bound_12 == uint2(0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e155 = start;
            start = _e155 + TILE_LIST;
        }
        loop_init_9 = false;
        uint _e119 = start;
        if (_e119 < _e116.total) {
        } else {
            break;
        }
        {
            uint _e122 = start;
            uint _e123 = tile_walk_fill(lid, _e116, _e122, bsh_nodes, tile_list, subtree_at, _buffer_sizes);
            j = 0u;
            uint2 loop_bound_13 = uint2(4294967295u);
            bool loop_init_10 = true;
            while(true) {
                if (metal::all(loop_bound_13 == uint2(0u))) { break; }
                loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                if (!loop_init_10) {
                    uint _e153 = j;
                    j = _e153 + 1u;
                }
                loop_init_10 = false;
                uint _e126 = j;
                if (_e126 < _e123) {
                } else {
                    break;
                }
                {
                    uint _e129 = j;
                    uint b_7 = tile_list.inner[_e129];
                    if (!(!(has_3))) {
                        BshNode _e138 = bsh_nodes[b_7];
                        metal::float3 _e139 = r;
                        bool _e140 = bsh_reaches(_e138, x_15, _e139, _e79);
                        local_4 = !(_e140);
                    } else {
                        local_4 = true;
                    }
                    bool _e143 = local_4;
                    if (_e143) {
                        continue;
                    }
                    uint li_10 = bsh_nodes[b_7].light;
                    metal::float3 _e148 = n;
                    metal::float3 _e149 = r;
                    metal::float4 _e150 = lobe;
                    float _e151 = light_weight(li_10, x_15, _e148, _e149, _e150, _e79, rt2_5, light_cones, _buffer_sizes);
                    weighted_offer(picks, li_10, _e151);
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (!(has_3)) {
        if (inside) {
            out_tex.write(metal::float4(0.0), metal::uint2(texel_1));
        }
        return;
    }
    float _e163 = picks.w_sum;
    if (_e163 > 0.0) {
        uint2 loop_bound_14 = uint2(4294967295u);
        bool loop_init_11 = true;
        while(true) {
            if (metal::all(loop_bound_14 == uint2(0u))) { break; }
            loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
            if (!loop_init_11) {
                uint _e199 = k;
                k = _e199 + 1u;
            }
            loop_init_11 = false;
            uint _e170 = k;
            if (_e170 < K) {
            } else {
                break;
            }
            {
                uint _e174 = k;
                uint _e179 = k;
                uint _e181 = picks.light.inner[_e179];
                uint _e184 = lights[_e181].kind;
                uint own = (_e184 == LIGHT_TRIANGLE) ? (_e174 + 1u) : 0u;
                uint _e188 = k;
                uint _e191 = k;
                uint _e193 = picks.light.inner[_e191];
                keys.inner[_e188] = metal::uint2(_e193, own);
                uint _e195 = k;
                held.inner[_e195] = true;
            }
        }
        type_24 _e201 = keys;
        type_25 _e202 = held;
        type_14 _e203 = first_holders(_e201, _e202);
        uint2 loop_bound_15 = uint2(4294967295u);
        bool loop_init_12 = true;
        while(true) {
            if (metal::all(loop_bound_15 == uint2(0u))) { break; }
            loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
            if (!loop_init_12) {
                uint _e261 = k_1;
                k_1 = _e261 + 1u;
            }
            loop_init_12 = false;
            uint _e206 = k_1;
            if (_e206 < K) {
            } else {
                break;
            }
            {
                uint _e209 = h;
                uint _e210 = pcg_hash(_e209);
                h = _e210;
                uint _e211 = h;
                float _e212 = xi_from_bits(_e211);
                uint _e213 = h;
                uint _e214 = pcg_hash(_e213);
                h = _e214;
                uint _e215 = h;
                float _e216 = xi_from_bits(_e215);
                uint _e218 = k_1;
                uint li_11 = picks.light.inner[_e218];
                copies = 0u;
                uint _e223 = k_1;
                j_1 = _e223;
                uint2 loop_bound_16 = uint2(4294967295u);
                bool loop_init_13 = true;
                while(true) {
                    if (metal::all(loop_bound_16 == uint2(0u))) { break; }
                    loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
                    if (!loop_init_13) {
                        uint _e238 = j_1;
                        j_1 = _e238 + 1u;
                    }
                    loop_init_13 = false;
                    uint _e225 = j_1;
                    if (_e225 < K) {
                    } else {
                        break;
                    }
                    {
                        uint _e228 = copies;
                        uint _e231 = j_1;
                        uint _e233 = k_1;
                        copies = _e228 + ((_e203.inner[_e231] == _e233) ? 1u : 0u);
                    }
                }
                uint _e240 = copies;
                if (_e240 > 0u) {
                    Shaded _e243 = t;
                    metal::float3 _e244 = n;
                    metal::float3 _e245 = r;
                    Material _e246 = m;
                    float _e248 = picks.w_sum;
                    uint _e250 = k_1;
                    float _e252 = picks.w.inner[_e250];
                    float _e254 = weighted_pick_weight(_e248, _e252, K);
                    uint _e255 = copies;
                    Shaded _e258 = shade_pick(li_11, x_15, _e244, _e245, _e79, _e246, _e254 * static_cast<float>(_e255), _e212, _e216, eps_4, geo_nodes, geo_tris, lights, rt2_5, r2_4, _buffer_sizes);
                    Shaded _e259 = add(_e243, _e258);
                    t = _e259;
                }
            }
        }
    }
    uint count = picks.n;
    metal::float3 _e267 = t.e;
    out_tex.write(metal::float4(_e267, static_cast<float>(count)), metal::uint2(texel_1));
    return;
}
