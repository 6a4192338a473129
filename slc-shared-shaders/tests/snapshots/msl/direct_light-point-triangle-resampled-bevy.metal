// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size1;
    uint size8;
    uint size9;
    uint size10;
    uint size11;
    uint size12;
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
typedef GpuGeoNode type_7[1];
typedef GpuTriangle type_8[1];
struct type_9 {
    uint inner[64];
};
typedef GpuLight type_12[1];
typedef BshNode type_13[1];
typedef GpuLightCone type_14[1];
struct type_15 {
    uint inner[8];
};
typedef uint BshNodes;
struct Connection {
    metal::float3 e;
    metal::packed_float3 y;
    float cos_x;
};
struct type_18 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
};
struct type_19 {
    uint inner[1024];
};
struct type_20 {
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
struct type_23 {
    metal::uint2 inner[8];
};
struct type_24 {
    bool inner[8];
};
struct type_26 {
    metal::float2 inner[8];
};
struct type_27 {
    float inner[8];
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
    metal::float3 v_5 = x_1 - c;
    return metal::dot(v_5, v_5) <= (r_1 * r_1);
}

bool sphere_overlaps_aabb(
    metal::float3 c_1,
    float r_2,
    metal::float3 bmin,
    metal::float3 bmax
) {
    metal::float3 q_1 = metal::clamp(c_1, bmin, bmax);
    metal::float3 v_6 = q_1 - c_1;
    return metal::dot(v_6, v_6) <= (r_2 * r_2);
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
    float w_1
) {
    float _e4 = inverse_square(d2_3);
    float _e6 = slc_weight(rt2_1, d2_3);
    return ((cos_x * _e4) * _e6) * w_1;
}

float connection_cosine(
    metal::float3 x_2,
    metal::float3 y,
    metal::float3 n_1,
    metal::float3 ng,
    float r2_1
) {
    bool local_7 = {};
    bool local_8 = {};
    metal::float3 v_7 = x_2 - y;
    float d2_6 = metal::dot(v_7, v_7);
    bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local_7 = !((d2_6 > 0.0));
    } else {
        local_7 = true;
    }
    bool _e16 = local_7;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_11 = v_7 / metal::float3(metal::sqrt(d2_6));
    float cos_x_1 = -(metal::dot(n_1, w_11));
    if (!(!((cos_x_1 > 0.0)))) {
        local_8 = !((metal::dot(ng, w_11) < 0.0));
    } else {
        local_8 = true;
    }
    bool _e34 = local_8;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float triangle_lobe(
    metal::float3 n_2,
    float area,
    metal::float3 w_2
) {
    return area * metal::max(metal::dot(n_2, w_2), 0.0);
}

metal::float3 triangle_sample(
    metal::float3 a_2,
    metal::float3 b_2,
    metal::float3 c_2,
    float u1_,
    float u2_
) {
    float su = metal::sqrt(u1_);
    float b0_ = 1.0 - su;
    float b1_ = u2_ * su;
    return ((a_2 * b0_) + (b_2 * b1_)) + (c_2 * ((1.0 - b0_) - b1_));
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
    float w_3
) {
    float _e5 = bsh_range_bound(node_2);
    return node_2.extent + ((w_3 * 1.001) * _e5);
}

float weighted_threshold(
    float w_sum,
    float u_2
) {
    return w_sum / (1.0 - u_2);
}

float resample_target(
    metal::float3 c_3
) {
    return ((c_3.x + c_3.y) + c_3.z) * 0.33333334;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

float slot_target(
    metal::float3 c_4,
    uint slot,
    uint k_2
) {
    if (k_2 < 3u) {
        float _e5 = resample_target(c_4);
        return _e5;
    }
    uint j_3 = naga_mod(slot, 3u);
    if (j_3 == 0u) {
        return c_4.x;
    }
    if (j_3 == 1u) {
        return c_4.y;
    }
    return c_4.z;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

metal::float3 slot_share(
    uint slot_1,
    uint k_3
) {
    if (k_3 < 3u) {
        float _e4 = to_f32_(k_3);
        float w_12 = 1.0 / _e4;
        return metal::float3(w_12, w_12, w_12);
    }
    uint j_4 = naga_mod(slot_1, 3u);
    float _e15 = to_f32_(naga_div((k_3 + 2u) - j_4, 3u));
    float w_13 = 1.0 / _e15;
    if (j_4 == 0u) {
        return metal::float3(w_13, 0.0, 0.0);
    }
    if (j_4 == 1u) {
        return metal::float3(0.0, w_13, 0.0);
    }
    return metal::float3(0.0, 0.0, w_13);
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
    float t_4 = ((cos_h * cos_h) * a2_) + sin2_h;
    return (a2_ * INV_PI) / (t_4 * t_4);
}

float smith_root(
    float cos,
    float alpha_1
) {
    float a2_1 = alpha_1 * alpha_1;
    return metal::sqrt(((cos * cos) * (1.0 - a2_1)) + a2_1);
}

float smith_visibility(
    float n_l,
    float n_v,
    float alpha_2
) {
    bool local_9 = {};
    if (!((n_l <= 0.0))) {
        local_9 = n_v <= 0.0;
    } else {
        local_9 = true;
    }
    bool _e11 = local_9;
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
    float c_10 = metal::saturate(1.0 - v_h);
    float c2_ = c_10 * c_10;
    return f0_ + ((metal::float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_10));
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

bool has_specular(
    float metallic_1,
    metal::float3 f0_d_1,
    float f90_d_1
) {
    bool local_10 = {};
    bool local_11 = {};
    if (!((metallic_1 > 0.0))) {
        local_10 = f90_d_1 > 0.0;
    } else {
        local_10 = true;
    }
    bool _e11 = local_10;
    if (!(_e11)) {
        local_11 = metal::max(metal::max(f0_d_1.x, f0_d_1.y), f0_d_1.z) > 0.0;
    } else {
        local_11 = true;
    }
    bool _e23 = local_11;
    return _e23;
}

float channel_mean(
    metal::float3 c_5
) {
    return ((c_5.x + c_5.y) + c_5.z) * 0.33333334;
}

metal::float4 receiver_lobe(
    metal::float3 base_1,
    float metallic_2,
    metal::float3 f0_d_2,
    float f90_d_2,
    float alpha_3,
    float n_v_1
) {
    bool local_12 = {};
    metal::float3 _e10 = fresnel_schlick(f0_d_2, f90_d_2, n_v_1);
    float _e16 = channel_mean(((metal::float3(1.0, 1.0, 1.0) - _e10) * base_1) * (1.0 - metallic_2));
    if (!((n_v_1 <= 0.0))) {
        bool _e22 = has_specular(metallic_2, f0_d_2, f90_d_2);
        local_12 = !(_e22);
    } else {
        local_12 = true;
    }
    bool _e25 = local_12;
    if (_e25) {
        return metal::float4(_e16, 0.0, alpha_3, n_v_1);
    }
    metal::float3 _e28 = specular_fresnel(base_1, metallic_2, f0_d_2, f90_d_2, n_v_1);
    float _e29 = channel_mean(_e28);
    return metal::float4(_e16, _e29, alpha_3, n_v_1);
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
    metal::float3 n_3,
    metal::float3 v
) {
    return (n_3 * (2.0 * metal::dot(n_3, v))) - v;
}

float bevy_alpha(
    float perceptual
) {
    float r_11 = metal::clamp(perceptual, 0.089, 1.0);
    return r_11 * r_11;
}

float bevy_f0_(
    float reflectance
) {
    return (0.16 * reflectance) * reflectance;
}

float bevy_dfg(
    float r_3,
    float n_v_2
) {
    float rx = 1.0 - r_3;
    float a004_ = (metal::min(rx * rx, metal::exp2(-9.28 * n_v_2)) * rx) + (0.0425 - (0.0275 * r_3));
    float x_12 = metal::max((1.04 - (0.572 * r_3)) - (1.04 * a004_), 0.00005);
    float y_1 = metal::max(((0.022 * r_3) - 0.04) + (1.04 * a004_), 0.00005);
    return x_12 + y_1;
}

metal::float3 bevy_brdf(
    metal::float3 base_2,
    float metallic_3,
    float r_4,
    float reflectance_1,
    metal::float3 n_4,
    metal::float3 v_1,
    metal::float3 l
) {
    float n_l_1 = metal::saturate(metal::dot(n_4, l));
    if (n_l_1 <= 0.0) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    float _e15 = bevy_alpha(r_4);
    float n_v_3 = metal::max(metal::dot(n_4, v_1), 0.0001);
    metal::float3 h_2 = metal::normalize(l + v_1);
    float n_h = metal::saturate(metal::dot(n_4, h_2));
    float l_h = metal::saturate(metal::dot(l, h_2));
    float f90_d_3 = 0.5 + (((2.0 * _e15) * l_h) * l_h);
    metal::float3 _e35 = fresnel_schlick(metal::float3(1.0, 1.0, 1.0), f90_d_3, n_l_1);
    metal::float3 _e41 = fresnel_schlick(metal::float3(1.0, 1.0, 1.0), f90_d_3, n_v_3);
    float burley = (_e35.x * _e41.x) * INV_PI;
    float _e46 = bevy_f0_(reflectance_1);
    metal::float3 f0_1 = (metal::float3(_e46, _e46, _e46) * (1.0 - metallic_3)) + (base_2 * metallic_3);
    float f90_1 = metal::saturate(((f0_1.x + f0_1.y) + f0_1.z) * 16.5);
    float _e64 = ggx_d(n_h, 1.0 - (n_h * n_h), _e15);
    float _e65 = smith_visibility(n_l_1, n_v_3, _e15);
    float _e70 = bevy_dfg(r_4, n_v_3);
    metal::float3 comp = metal::float3(1.0, 1.0, 1.0) + (f0_1 * ((1.0 / _e70) - 1.0));
    metal::float3 _e77 = fresnel_schlick(f0_1, f90_1, l_h);
    metal::float3 spec = (_e77 * comp) * (_e64 * _e65);
    return (base_2 * ((1.0 - metallic_3) * burley)) + spec;
}

float cone_cos_of(
    metal::float3 v_2,
    float d2_4,
    float a_3,
    metal::float3 d
) {
    bool local_13 = {};
    bool local_14 = {};
    float vd = metal::dot(v_2, d);
    float h2_ = d2_4 - (a_3 * a_3);
    if (!((h2_ <= 0.0))) {
        if (vd >= 0.0) {
            local_14 = (vd * vd) >= h2_;
        } else {
            local_14 = false;
        }
        bool _e19 = local_14;
        local_13 = _e19;
    } else {
        local_13 = true;
    }
    bool _e21 = local_13;
    if (_e21) {
        return 1.0;
    }
    metal::float3 c_11 = metal::cross(v_2, d);
    return metal::min(((vd * metal::sqrt(h2_)) + (metal::sqrt(metal::dot(c_11, c_11)) * a_3)) / d2_4, 1.0);
}

float cone_cos_toward(
    metal::float3 center,
    float radius,
    metal::float3 p,
    metal::float3 d_1
) {
    metal::float3 v_8 = center - p;
    float _e6 = cone_cos_of(v_8, metal::dot(v_8, v_8), radius, d_1);
    return _e6;
}

float range_scale_at(
    metal::float4 rl,
    float cos_t
) {
    float t_5 = ((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0;
    return metal::clamp(rl.x + ((rl.y * rl.z) / (t_5 * t_5)), 1.0, rl.w * rl.w);
}

float range_scale_toward(
    metal::float4 rl_1,
    metal::float3 center_1,
    float radius_1,
    metal::float3 p_1,
    metal::float3 r_5
) {
    if (rl_1.w <= 1.0) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_5);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
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

metal::float3 triangle_normal(
    metal::float3 a_4,
    metal::float3 b_3,
    metal::float3 c_6
) {
    bool local_15 = {};
    metal::float3 n_10 = metal::cross(b_3 - a_4, c_6 - a_4);
    float l2_ = metal::dot(n_10, n_10);
    if (!(!((l2_ > 0.0)))) {
        local_15 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_15 = true;
    }
    bool _e17 = local_15;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_10 / metal::float3(metal::sqrt(l2_));
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_3,
    metal::float3 a_5,
    metal::float3 b_4,
    metal::float3 c_7,
    float t_min,
    float t_max_1
) {
    bool local_16 = {};
    bool local_17 = {};
    bool local_18 = {};
    metal::float3 e1_ = b_4 - a_5;
    metal::float3 e2_ = c_7 - a_5;
    metal::float3 p_5 = metal::cross(d_3, e2_);
    float det = metal::dot(e1_, p_5);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv = 1.0 / det;
    metal::float3 s_10 = o_1 - a_5;
    float u_3 = metal::dot(s_10, p_5) * inv;
    if (!((u_3 < 0.0))) {
        local_16 = u_3 > 1.0;
    } else {
        local_16 = true;
    }
    bool _e28 = local_16;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q_2 = metal::cross(s_10, e1_);
    float v_9 = metal::dot(d_3, q_2) * inv;
    if (!((v_9 < 0.0))) {
        local_17 = (u_3 + v_9) > 1.0;
    } else {
        local_17 = true;
    }
    bool _e42 = local_17;
    if (_e42) {
        return -1.0;
    }
    float t_6 = metal::dot(e2_, q_2) * inv;
    if (t_6 > t_min) {
        local_18 = t_6 < t_max_1;
    } else {
        local_18 = false;
    }
    bool _e51 = local_18;
    if (_e51) {
        return t_6;
    }
    return -1.0;
}

metal::float3 light_intensity(
    GpuLight l_1,
    metal::float3 w_4
) {
    switch(l_1.kind) {
        case 0u: {
            return l_1.intensity;
        }
        case 3u: {
            metal::float3 _e8 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
            float _e10 = triangle_lobe(_e8, l_1.a, w_4);
            return l_1.intensity * _e10;
        }
        default: {
            return metal::float3(0.0);
        }
    }
}

metal::float3 light_point(
    GpuLight l_2,
    float u1_1,
    float u2_1
) {
    if (l_2.kind == LIGHT_TRIANGLE) {
        metal::float3 _e9 = triangle_sample(l_2.p0_, l_2.p1_, l_2.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_2.p0_;
}

GeoHit trace(
    metal::float3 o_2,
    metal::float3 d_4,
    float t_min_1,
    float t_max_2,
    bool any_hit,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    GeoHit hit = {};
    type_9 stack = {};
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
                        GpuTriangle t_7 = geo_tris[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_4, t_7.v0_, t_7.v1_, t_7.v2_, t_min_1, _e49);
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
    metal::float3 a_6,
    metal::float3 b_5,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
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

BshNode bsh_node(
    BshNodes nodes,
    uint i_1,
    device type_13 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshNode _e4 = bsh_nodes[i_1];
    return _e4;
}

uint bsh_count(
    BshNodes nodes_1,
    device type_13 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    return 1 + (_buffer_sizes.size11 - 0 - 32) / 32;
}

uint bsh_first(
    BshNodes nodes_2,
    device type_13 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e1 = bsh_count(nodes_2, bsh_nodes, _buffer_sizes);
    if (_e1 > 0u) {
        return 0u;
    }
    return BSH_NONE;
}

float bsh_inner_scale(
    float a_7,
    metal::float3 v_3,
    float d2_5,
    metal::float3 r_6,
    metal::float4 rl_2
) {
    float _e5 = cone_cos_of(v_3, d2_5, a_7, r_6);
    float _e8 = range_scale_at(rl_2, _e5 + 0.000002);
    return _e8;
}

bool bsh_reaches(
    BshNode node_4,
    metal::float3 x_4,
    metal::float3 r_7,
    metal::float4 rl_3
) {
    bool local_19 = {};
    bool local_20 = {};
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_4);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, node_4.radius * (rl_3.w * 1.0001), x_4);
        local_19 = !(_e20);
    } else {
        local_19 = true;
    }
    bool _e23 = local_19;
    if (_e23) {
        return false;
    }
    metal::float3 v_10 = x_4 - node_4.center;
    float d2_7 = metal::dot(v_10, v_10);
    float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_7 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        float _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_4, r_7);
        float _e41 = bsh_scaled_radius(node_4, metal::sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_4);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_10), d2_7, r_7, rl_3);
    float s_c = _e45 * 1.001;
    float _e50 = bsh_range_bound(node_4);
    float reach = node_4.extent + (metal::sqrt(s_c) * _e50);
    if (d2_7 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_20 = d2_7 <= (reach * reach);
    } else {
        local_20 = false;
    }
    bool _e63 = local_20;
    return _e63;
}

bool bsh_reaches_box(
    BshNode node_5,
    metal::float3 lo,
    metal::float3 hi,
    float w_5
) {
    bool _e13 = sphere_overlaps_aabb(node_5.center, node_5.radius * (metal::max(1.0, w_5 * 1.0001) * 1.0001), lo, hi);
    return _e13;
}

uint bsh_subtree(
    BshNodes nodes_3,
    uint s_1,
    uint depth,
    device type_13 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_2 = {};
    uint level = 0u;
    bool local_21 = {};
    uint _e3 = bsh_first(nodes_3, bsh_nodes, _buffer_sizes);
    i_2 = _e3;
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e7 = level;
        if (_e7 < depth) {
            uint _e11 = i_2;
            local_21 = _e11 != BSH_NONE;
        } else {
            local_21 = false;
        }
        bool _e15 = local_21;
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
    float w_6,
    device type_13 const& bsh_nodes,
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
            bool _e11 = bsh_reaches_box(_e10, lo_1, hi_1, w_6);
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
    GpuLight l_3,
    metal::float3 x_5,
    metal::float3 n_5,
    metal::float3 ng_1,
    float r2_2,
    float rt2_2,
    float w_res,
    float u1_2,
    float u2_2,
    float eps,
    bool trace_1,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection c_8 = {};
    bool local_22 = {};
    bool local_23 = {};
    c_8.e = metal::float3(0.0);
    metal::float3 _e16 = light_point(l_3, u1_2, u2_2);
    c_8.y = _e16;
    metal::float3 _e19 = c_8.y;
    float _e20 = connection_cosine(x_5, _e19, n_5, ng_1, r2_2);
    c_8.cos_x = _e20;
    float _e22 = c_8.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            metal::float3 _e33 = c_8.y;
            bool _e34 = occluded(x_5 + (ng_1 * eps), _e33, geo_nodes, geo_tris, _buffer_sizes);
            local_23 = _e34;
        } else {
            local_23 = false;
        }
        bool _e36 = local_23;
        local_22 = _e36;
    } else {
        local_22 = true;
    }
    bool _e38 = local_22;
    if (_e38) {
        Connection _e39 = c_8;
        return _e39;
    }
    metal::float3 _e41 = c_8.y;
    metal::float3 v_11 = x_5 - _e41;
    float d2_8 = metal::dot(v_11, v_11);
    metal::float3 _e48 = light_intensity(l_3, v_11 / metal::float3(metal::sqrt(d2_8)));
    float _e50 = c_8.cos_x;
    float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_8.e = _e48 * _e51;
    Connection _e53 = c_8;
    return _e53;
}

Connection connect_traced(
    uint li,
    metal::float3 x_6,
    metal::float3 n_6,
    metal::float3 ng_2,
    float s_2,
    float w_res_1,
    float u1_3,
    float u2_3,
    float eps_1,
    bool trace_2,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_12 const& lights,
    device type_4 const& rt2_3,
    device type_4 const& r2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight _e12 = lights[li];
    float _e15 = r2_3[li];
    float _e19 = rt2_3[li];
    Connection _e21 = connect_record(_e12, x_6, n_6, ng_2, s_2 * _e15, s_2 * _e19, w_res_1, u1_3, u2_3, eps_1, trace_2, geo_nodes, geo_tris, _buffer_sizes);
    return _e21;
}

float light_range_scale(
    uint li_1,
    metal::float3 x_7,
    metal::float3 r_8,
    metal::float4 rl_4,
    device type_14 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_12 = light_cones[li_1];
    float _e9 = range_scale_toward(rl_4, c_12.center, c_12.radius, x_7, r_8);
    return _e9;
}

metal::float4 surface_at(
    metal::int2 texel,
    metal::texture2d<float, metal::access::sample> position_tex
) {
    metal::float4 p_6 = position_tex.read(metal::uint2(texel), 0);
    return (p_6.w > 0.0) ? metal::float4(p_6.xyz, 1.0) : metal::float4(0.0);
}

WorkgroupBox workgroup_bounds(
    uint li_2,
    metal::float3 lo_2,
    metal::float3 hi_2,
    threadgroup type_18& wg_lo,
    threadgroup type_18& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    uint stride = 32u;
    wg_lo.inner[li_2] = lo_2;
    wg_hi.inner[li_2] = hi_2;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint2 loop_bound_4 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e36 = stride;
            stride = naga_div(_e36, 2u);
        }
        loop_init_1 = false;
        uint _e9 = stride;
        if (_e9 > 0u) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if (li_2 < _e12) {
                metal::float3 _e18 = wg_lo.inner[li_2];
                uint _e20 = stride;
                metal::float3 _e23 = wg_lo.inner[li_2 + _e20];
                wg_lo.inner[li_2] = metal::min(_e18, _e23);
                metal::float3 _e29 = wg_hi.inner[li_2];
                uint _e31 = stride;
                metal::float3 _e34 = wg_hi.inner[li_2 + _e31];
                wg_hi.inner[li_2] = metal::max(_e29, _e34);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (li_2 == 0u) {
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
    metal::float3 p_2,
    bool has
) {
    return WorkgroupBox {has ? p_2 : metal::float3(340282350000000000000000000000000000000.0), has ? p_2 : metal::float3(-340282350000000000000000000000000000000.0)};
}

WorkgroupBox workgroup_box(
    uint li_3,
    metal::float3 p_3,
    bool has_1,
    threadgroup type_18& wg_lo,
    threadgroup type_18& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    WorkgroupBox _e3 = point_box(p_3, has_1);
    WorkgroupBox _e6 = workgroup_bounds(li_3, _e3.lo, _e3.hi, wg_lo, wg_hi, wg_box);
    return _e6;
}

bool box_is_empty(
    WorkgroupBox b_6
) {
    return b_6.lo.x > b_6.hi.x;
}

uint tile_subtree(
    uint s_3,
    TileWalk t_1,
    bool list,
    uint at,
    uint start_2,
    uint to,
    device type_13 const& bsh_nodes,
    threadgroup type_19& tile_list,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint p_4 = {};
    uint b_7 = {};
    bool local_24 = {};
    bool local_25 = {};
    bool local_26 = {};
    uint _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH, bsh_nodes, _buffer_sizes);
    if (_e8 == BSH_NONE) {
        return 0u;
    }
    uint end_1 = bsh_nodes[_e8].next;
    p_4 = at;
    uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_1.lo, t_1.hi, t_1.w, bsh_nodes, _buffer_sizes);
    b_7 = _e21;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e53 = b_7;
            uint _e56 = bsh_nodes[_e53].next;
            uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_1.lo, t_1.hi, t_1.w, bsh_nodes, _buffer_sizes);
            b_7 = _e60;
        }
        loop_init_2 = false;
        uint _e23 = b_7;
        if (_e23 != end_1) {
            if (!(!(list))) {
                uint _e31 = p_4;
                local_25 = _e31 < to;
            } else {
                local_25 = true;
            }
            bool _e34 = local_25;
            local_24 = _e34;
        } else {
            local_24 = false;
        }
        bool _e36 = local_24;
        if (_e36) {
        } else {
            break;
        }
        {
            if (list) {
                uint _e39 = p_4;
                local_26 = _e39 >= start_2;
            } else {
                local_26 = false;
            }
            bool _e42 = local_26;
            if (_e42) {
                uint _e44 = p_4;
                uint _e47 = b_7;
                tile_list.inner[_e44 - start_2] = _e47;
            }
            uint _e48 = p_4;
            p_4 = _e48 + 1u;
        }
    }
    uint _e61 = p_4;
    return _e61 - at;
}

TileWalk tile_walk_begin(
    uint li_4,
    metal::float3 x_8,
    float w_7,
    bool has_2,
    device type_13 const& bsh_nodes,
    threadgroup type_18& wg_lo,
    threadgroup type_18& wg_hi,
    threadgroup WorkgroupBox& wg_box,
    threadgroup type_19& tile_list,
    threadgroup type_20& subtree_at,
    threadgroup metal::atomic_uint& tile_scale,
    threadgroup uint& tile_total,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_27 = {};
    TileWalk t_2 = {};
    uint s_4 = {};
    uint sum_1 = 0u;
    uint s_5 = 0u;
    if (has_2) {
        local_27 = w_7 >= 0.0;
    } else {
        local_27 = false;
    }
    bool _e12 = local_27;
    uint _e14 = metal::atomic_fetch_max_explicit(&tile_scale, _e12 ? as_type<uint>(w_7) : 0u, metal::memory_order_relaxed);
    WorkgroupBox _e15 = workgroup_box(li_4, x_8, has_2, wg_lo, wg_hi, wg_box);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_1 = metal::atomic_load_explicit(&tile_scale, metal::memory_order_relaxed);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    t_2 = TileWalk {_e15.lo, _e15.hi, as_type<float>(unnamed_1), 0u};
    bool _e24 = box_is_empty(_e15);
    if (_e24) {
        TileWalk _e25 = t_2;
        return _e25;
    }
    s_4 = li_4;
    uint2 loop_bound_6 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e40 = s_4;
            s_4 = _e40 + TILE_THREADS;
        }
        loop_init_3 = false;
        uint _e27 = s_4;
        if (_e27 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            uint _e31 = s_4;
            uint _e33 = s_4;
            TileWalk _e34 = t_2;
            uint _e39 = tile_subtree(_e33, _e34, false, 0u, 0u, 0u, bsh_nodes, tile_list, _buffer_sizes);
            subtree_at.inner[_e31] = _e39;
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    if (li_4 == 0u) {
        uint2 loop_bound_7 = uint2(4294967295u);
        bool loop_init_4 = true;
        while(true) {
            if (metal::all(loop_bound_7 == uint2(0u))) { break; }
            loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
            if (!loop_init_4) {
                uint _e63 = s_5;
                s_5 = _e63 + 1u;
            }
            loop_init_4 = false;
            uint _e49 = s_5;
            if (_e49 < BSH_TILE_SUBTREES) {
            } else {
                break;
            }
            {
                uint _e53 = s_5;
                uint c_13 = subtree_at.inner[_e53];
                uint _e57 = s_5;
                uint _e59 = sum_1;
                subtree_at.inner[_e57] = _e59;
                uint _e60 = sum_1;
                sum_1 = _e60 + c_13;
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
    uint li_5,
    TileWalk t_3,
    uint start_3,
    device type_13 const& bsh_nodes,
    threadgroup type_19& tile_list,
    threadgroup type_20& subtree_at,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint s_6 = {};
    uint past = {};
    bool local_28 = {};
    uint to_1 = metal::min(t_3.total, start_3 + TILE_LIST);
    s_6 = li_5;
    uint2 loop_bound_8 = uint2(4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e38 = s_6;
            s_6 = _e38 + TILE_THREADS;
        }
        loop_init_5 = false;
        uint _e8 = s_6;
        if (_e8 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            uint _e12 = s_6;
            uint at_1 = subtree_at.inner[_e12];
            past = t_3.total;
            uint _e17 = s_6;
            if ((_e17 + 1u) < BSH_TILE_SUBTREES) {
                uint _e23 = s_6;
                uint _e27 = subtree_at.inner[_e23 + 1u];
                past = _e27;
            }
            if (at_1 < to_1) {
                uint _e31 = past;
                local_28 = _e31 > start_3;
            } else {
                local_28 = false;
            }
            bool _e34 = local_28;
            if (_e34) {
                uint _e35 = s_6;
                uint _e37 = tile_subtree(_e35, t_3, true, at_1, start_3, to_1, bsh_nodes, tile_list, _buffer_sizes);
            }
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return to_1 - start_3;
}

Shaded shade_connection(
    Connection c_9,
    metal::float3 x_9,
    metal::float3 n_7,
    Material m_1
) {
    Shaded s_7 = {};
    s_7.e = c_9.e;
    s_7.diffuse = metal::float3(0.0);
    s_7.specular = metal::float3(0.0);
    if (c_9.cos_x > 0.0) {
        metal::float3 _e25 = bevy_brdf(m_1.base, m_1.metallic, m_1.roughness, m_1.reflectance, n_7, m_1.v, metal::normalize(c_9.y - x_9));
        s_7.diffuse = _e25 * c_9.e;
    }
    Shaded _e28 = s_7;
    return _e28;
}

Shaded shade_pick_traced(
    uint li_6,
    metal::float3 x_10,
    metal::float3 n_8,
    metal::float3 r_9,
    metal::float4 rl_5,
    Material m_2,
    float w_8,
    float u1_4,
    float u2_4,
    float eps_2,
    bool trace_3,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_12 const& lights,
    device type_4 const& rt2_3,
    device type_4 const& r2_3,
    device type_14 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e11 = light_range_scale(li_6, x_10, r_9, rl_5, light_cones, _buffer_sizes);
    Connection _e12 = connect_traced(li_6, x_10, n_8, n_8, _e11, w_8, u1_4, u2_4, eps_2, trace_3, geo_nodes, geo_tris, lights, rt2_3, r2_3, _buffer_sizes);
    Shaded _e13 = shade_connection(_e12, x_10, n_8, m_2);
    return _e13;
}

Shaded shade_pick(
    uint li_7,
    metal::float3 x_11,
    metal::float3 n_9,
    metal::float3 r_10,
    metal::float4 rl_6,
    Material m_3,
    float w_9,
    float u1_5,
    float u2_5,
    float eps_3,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_12 const& lights,
    device type_4 const& rt2_3,
    device type_4 const& r2_3,
    device type_14 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    Shaded _e11 = shade_pick_traced(li_7, x_11, n_9, r_10, rl_6, m_3, w_9, u1_5, u2_5, eps_3, true, geo_nodes, geo_tris, lights, rt2_3, r2_3, light_cones, _buffer_sizes);
    return _e11;
}

Material material_of(
    metal::float3 base_3,
    float metallic_4,
    float roughness,
    float reflectance_2,
    metal::float3 v_4
) {
    float _e6 = bevy_alpha(roughness);
    return Material {base_3, metal::saturate(metallic_4), _e6, {}, v_4, roughness, reflectance_2};
}

Shaded add(
    Shaded a_8,
    Shaded b_8
) {
    return Shaded {a_8.e + b_8.e, a_8.diffuse + b_8.diffuse, a_8.specular + b_8.specular};
}

Shaded scaled(
    Shaded s_8,
    metal::float3 w_10
) {
    return Shaded {s_8.e * w_10, s_8.diffuse * w_10, s_8.specular * w_10};
}

type_15 first_holders(
    type_23 keys_1,
    type_24 held_1
) {
    type_15 first = {};
    uint k_4 = 0u;
    uint j_2 = {};
    bool local_29 = {};
    bool local_30 = {};
    uint2 loop_bound_9 = uint2(4294967295u);
    bool loop_init_6 = true;
    while(true) {
        if (metal::all(loop_bound_9 == uint2(0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_6) {
            uint _e45 = k_4;
            k_4 = _e45 + 1u;
        }
        loop_init_6 = false;
        uint _e5 = k_4;
        if (_e5 < K) {
        } else {
            break;
        }
        {
            uint _e8 = k_4;
            uint _e11 = k_4;
            uint _e12 = k_4;
            first.inner[_e8] = held_1.inner[_e12] ? _e11 : K;
            j_2 = 0u;
            uint2 loop_bound_10 = uint2(4294967295u);
            bool loop_init_7 = true;
            while(true) {
                if (metal::all(loop_bound_10 == uint2(0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_7) {
                    uint _e42 = j_2;
                    j_2 = _e42 + 1u;
                }
                loop_init_7 = false;
                uint _e17 = j_2;
                uint _e18 = k_4;
                if (_e17 < _e18) {
                    uint _e22 = k_4;
                    local_29 = held_1.inner[_e22];
                } else {
                    local_29 = false;
                }
                bool _e25 = local_29;
                if (_e25) {
                } else {
                    break;
                }
                {
                    uint _e26 = j_2;
                    if (held_1.inner[_e26]) {
                        uint _e30 = j_2;
                        uint _e32 = k_4;
                        local_30 = metal::all(keys_1.inner[_e30] == keys_1.inner[_e32]);
                    } else {
                        local_30 = false;
                    }
                    bool _e37 = local_30;
                    if (_e37) {
                        uint _e38 = k_4;
                        uint _e40 = j_2;
                        first.inner[_e38] = _e40;
                        break;
                    }
                }
            }
        }
    }
    type_15 _e47 = first;
    return _e47;
}

metal::float3 output_of(
    Shaded s_9
) {
    return s_9.diffuse + s_9.specular;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, uint lid [[thread_index_in_threadgroup]]
, device type_7 const& geo_nodes [[user(fake0)]]
, device type_8 const& geo_tris [[user(fake0)]]
, constant ViewParams& view [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::write> out_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> base_color_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> metal_rough_tex [[user(fake0)]]
, device type_12 const& lights [[user(fake0)]]
, device type_4 const& rt2_3 [[user(fake0)]]
, device type_4 const& r2_3 [[user(fake0)]]
, device type_13 const& bsh_nodes [[user(fake0)]]
, device type_14 const& light_cones [[user(fake0)]]
, threadgroup type_18& wg_lo
, threadgroup type_18& wg_hi
, threadgroup WorkgroupBox& wg_box
, threadgroup type_19& tile_list
, threadgroup type_20& subtree_at
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
    type_15 slot_light = {};
    type_26 slot_u = {};
    type_27 slot_p = {};
    metal::float3 total = metal::float3(0.0);
    uint count = 0u;
    uint hc = {};
    type_27 threshold = {};
    uint start = 0u;
    uint j = {};
    bool local_4 = {};
    uint q = {};
    bool local_5 = {};
    type_23 keys = {};
    type_24 held = {};
    uint k = 0u;
    uint k_1 = 0u;
    metal::float3 w = {};
    uint j_1 = {};
    bool local_6 = {};
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
        metal::float4 _e27 = surface_at(texel_1, position_tex);
        s = _e27;
        metal::float4 _e30 = normal_tex.read(metal::uint2(texel_1), 0);
        nn = _e30.xyz;
    }
    metal::float3 _e32 = nn;
    metal::float3 _e33 = nn;
    float len2_ = metal::dot(_e32, _e33);
    metal::float4 _e35 = s;
    metal::float3 x_13 = _e35.xyz;
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
        local_3 = metal::all(metal::abs(x_13) <= metal::float3(340282350000000000000000000000000000000.0));
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
    if (has_3) {
        metal::float4 mr = metal_rough_tex.read(metal::uint2(texel_1), 0);
        metal::float4 _e83 = base_color_tex.read(metal::uint2(texel_1), 0);
        metal::float3 _e90 = view.eye;
        Material _e93 = material_of(_e83.xyz, mr.z, mr.y, mr.w, metal::normalize(_e90 - x_13));
        m = _e93;
        metal::float3 _e95 = m.base;
        float _e97 = m.metallic;
        float _e99 = bevy_f0_(mr.w);
        float _e103 = m.alpha;
        metal::float3 _e104 = n;
        metal::float3 _e106 = m.v;
        metal::float4 _e108 = receiver_lobe(_e95, _e97, metal::float3(_e99), 1.0, _e103, metal::dot(_e104, _e106));
        lobe = _e108;
        metal::float3 _e109 = n;
        metal::float3 _e111 = m.v;
        metal::float3 _e112 = mirror_dir(_e109, _e111);
        r = _e112;
    }
    metal::float4 _e113 = lobe;
    metal::float4 _e114 = range_lobe(_e113);
    float _e117 = view.shadow_offset;
    metal::float3 _e120 = view.eye;
    float eps_4 = _e117 * metal::length(_e120 - x_13);
    uint _e126 = view.seed;
    uint _e130 = view.width;
    uint _e136 = view.frame;
    uint _e137 = point_stream(_e126, (gid.y * _e130) + gid.x, _e136);
    uint _e138 = pick_stream(_e137);
    h = _e138;
    hc = _e137;
    TileWalk _e159 = tile_walk_begin(lid, x_13, _e114.w, has_3, bsh_nodes, wg_lo, wg_hi, wg_box, tile_list, subtree_at, tile_scale, tile_total, _buffer_sizes);
    uint2 loop_bound_11 = uint2(4294967295u);
    bool loop_init_8 = true;
    while(true) {
        if (metal::all(loop_bound_11 == uint2(0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_8) {
            uint _e254 = start;
            start = _e254 + TILE_LIST;
        }
        loop_init_8 = false;
        uint _e162 = start;
        if (_e162 < _e159.total) {
        } else {
            break;
        }
        {
            uint _e165 = start;
            uint _e166 = tile_walk_fill(lid, _e159, _e165, bsh_nodes, tile_list, subtree_at, _buffer_sizes);
            j = 0u;
            uint2 loop_bound_12 = uint2(4294967295u);
            bool loop_init_9 = true;
            while(true) {
                if (metal::all(loop_bound_12 == uint2(0u))) { break; }
                loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
                if (!loop_init_9) {
                    uint _e252 = j;
                    j = _e252 + 1u;
                }
                loop_init_9 = false;
                uint _e169 = j;
                if (_e169 < _e166) {
                } else {
                    break;
                }
                {
                    uint _e172 = j;
                    uint b_9 = tile_list.inner[_e172];
                    if (!(!(has_3))) {
                        BshNode _e181 = bsh_nodes[b_9];
                        metal::float3 _e182 = r;
                        bool _e183 = bsh_reaches(_e181, x_13, _e182, _e114);
                        local_4 = !(_e183);
                    } else {
                        local_4 = true;
                    }
                    bool _e186 = local_4;
                    if (_e186) {
                        continue;
                    }
                    uint li_8 = bsh_nodes[b_9].light;
                    uint _e191 = count;
                    count = _e191 + 1u;
                    uint _e194 = h;
                    uint _e195 = pcg_hash(_e194);
                    h = _e195;
                    uint _e196 = h;
                    float _e197 = xi_from_bits(_e196);
                    uint _e198 = h;
                    uint _e199 = pcg_hash(_e198);
                    h = _e199;
                    uint _e200 = h;
                    float _e201 = xi_from_bits(_e200);
                    metal::float2 u_4 = metal::float2(_e197, _e201);
                    metal::float3 _e203 = n;
                    metal::float3 _e204 = r;
                    Material _e205 = m;
                    Shaded _e210 = shade_pick_traced(li_8, x_13, _e203, _e204, _e114, _e205, 1.0, u_4.x, u_4.y, eps_4, false, geo_nodes, geo_tris, lights, rt2_3, r2_3, light_cones, _buffer_sizes);
                    metal::float3 _e211 = output_of(_e210);
                    float _e212 = resample_target(_e211);
                    if (_e212 > 0.0) {
                        metal::float3 _e215 = total;
                        total = _e215 + _e211;
                        q = 0u;
                        uint2 loop_bound_13 = uint2(4294967295u);
                        bool loop_init_10 = true;
                        while(true) {
                            if (metal::all(loop_bound_13 == uint2(0u))) { break; }
                            loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                            if (!loop_init_10) {
                                uint _e249 = q;
                                q = _e249 + 1u;
                            }
                            loop_init_10 = false;
                            uint _e219 = q;
                            if (_e219 < K) {
                            } else {
                                break;
                            }
                            {
                                uint _e222 = q;
                                float _e224 = slot_target(_e211, _e222, K);
                                metal::float3 _e225 = total;
                                uint _e226 = q;
                                float _e228 = slot_target(_e225, _e226, K);
                                if (_e224 > 0.0) {
                                    uint _e233 = q;
                                    float _e235 = threshold.inner[_e233];
                                    local_5 = _e228 > _e235;
                                } else {
                                    local_5 = false;
                                }
                                bool _e238 = local_5;
                                if (_e238) {
                                    uint _e239 = q;
                                    slot_light.inner[_e239] = li_8;
                                    uint _e241 = q;
                                    slot_u.inner[_e241] = u_4;
                                    uint _e243 = q;
                                    slot_p.inner[_e243] = _e224;
                                    uint _e245 = q;
                                    float _e247 = next_threshold(_e228, hc);
                                    threshold.inner[_e245] = _e247;
                                }
                            }
                        }
                    }
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
    uint2 loop_bound_14 = uint2(4294967295u);
    bool loop_init_11 = true;
    while(true) {
        if (metal::all(loop_bound_14 == uint2(0u))) { break; }
        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
        if (!loop_init_11) {
            uint _e283 = k;
            k = _e283 + 1u;
        }
        loop_init_11 = false;
        uint _e265 = k;
        if (_e265 < K) {
        } else {
            break;
        }
        {
            uint _e268 = k;
            uint _e270 = k;
            uint _e272 = slot_light.inner[_e270];
            keys.inner[_e268] = metal::uint2(_e272, 0u);
            uint _e275 = k;
            uint _e277 = k;
            float _e279 = slot_p.inner[_e277];
            held.inner[_e275] = _e279 > 0.0;
        }
    }
    type_23 _e285 = keys;
    type_24 _e286 = held;
    type_15 _e287 = first_holders(_e285, _e286);
    uint2 loop_bound_15 = uint2(4294967295u);
    bool loop_init_12 = true;
    while(true) {
        if (metal::all(loop_bound_15 == uint2(0u))) { break; }
        loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
        if (!loop_init_12) {
            uint _e351 = k_1;
            k_1 = _e351 + 1u;
        }
        loop_init_12 = false;
        uint _e290 = k_1;
        if (_e290 < K) {
        } else {
            break;
        }
        {
            w = metal::float3(0.0);
            uint _e296 = k_1;
            uint _e298 = k_1;
            bool first_1 = _e287.inner[_e296] == _e298;
            uint _e300 = k_1;
            j_1 = _e300;
            uint2 loop_bound_16 = uint2(4294967295u);
            bool loop_init_13 = true;
            while(true) {
                if (metal::all(loop_bound_16 == uint2(0u))) { break; }
                loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
                if (!loop_init_13) {
                    uint _e328 = j_1;
                    j_1 = _e328 + 1u;
                }
                loop_init_13 = false;
                uint _e302 = j_1;
                if (_e302 < K) {
                    local_6 = first_1;
                } else {
                    local_6 = false;
                }
                bool _e308 = local_6;
                if (_e308) {
                } else {
                    break;
                }
                {
                    uint _e309 = j_1;
                    uint _e311 = k_1;
                    if (_e287.inner[_e309] == _e311) {
                        metal::float3 _e313 = w;
                        metal::float3 _e314 = total;
                        uint _e315 = j_1;
                        float _e317 = slot_target(_e314, _e315, K);
                        uint _e318 = j_1;
                        float _e320 = slot_p.inner[_e318];
                        uint _e322 = j_1;
                        metal::float3 _e324 = slot_share(_e322, K);
                        w = _e313 + ((_e317 / _e320) * _e324);
                    }
                }
            }
            if (first_1) {
                Shaded _e330 = t;
                uint _e331 = k_1;
                uint _e333 = slot_light.inner[_e331];
                metal::float3 _e334 = n;
                metal::float3 _e335 = r;
                Material _e336 = m;
                uint _e338 = k_1;
                float _e341 = slot_u.inner[_e338].x;
                uint _e342 = k_1;
                float _e345 = slot_u.inner[_e342].y;
                Shaded _e346 = shade_pick(_e333, x_13, _e334, _e335, _e114, _e336, 1.0, _e341, _e345, eps_4, geo_nodes, geo_tris, lights, rt2_3, r2_3, light_cones, _buffer_sizes);
                metal::float3 _e347 = w;
                Shaded _e348 = scaled(_e346, _e347);
                Shaded _e349 = add(_e330, _e348);
                t = _e349;
            }
        }
    }
    metal::float3 _e355 = t.diffuse;
    metal::float3 _e357 = t.specular;
    uint _e359 = count;
    out_tex.write(metal::float4(_e355 + _e357, static_cast<float>(_e359)), metal::uint2(texel_1));
    return;
}
