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
    uint size14;
    uint size15;
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
struct ReuseParams {
    metal::float4 c0_;
    metal::float4 c1_;
    metal::float4 c2_;
    metal::float4 c3_;
    metal::packed_float3 prev_eye;
    float max_confidence;
    uint has_history;
    float radius;
    uint visibility;
    uint parity;
    metal::packed_float3 moved_min;
    uint moved;
    metal::packed_float3 moved_max;
    uint pad;
};
struct ReuseSurface {
    metal::packed_float3 x;
    float m;
    metal::packed_float3 n;
    uint base;
    uint rough;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};
struct ReuseSlot {
    uint light;
    uint u;
    float w;
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
    ReuseSlot inner[8];
};
struct ReusePixel {
    ReuseSurface surface;
    type_15 slots;
};
typedef ReusePixel type_16[1];
struct type_17 {
    uint inner[8];
};
typedef uint BshNodes;
struct Connection {
    metal::float3 e;
    metal::packed_float3 y;
    float cos_x;
};
struct type_20 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
};
struct type_21 {
    uint inner[1024];
};
struct type_22 {
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
struct type_25 {
    metal::uint2 inner[8];
};
struct type_26 {
    bool inner[8];
};
struct Domain {
    uint pixel;
    char _pad1[12];
    metal::float3 x;
    metal::float3 n;
    Material m;
    float c;
    bool temporal;
    char _pad6[11];
};
struct type_27 {
    Domain inner[3];
};
struct type_30 {
    metal::float2 inner[8];
};
struct type_31 {
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
constant uint DOMAINS = 3u;

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

uint reuse_stream(
    uint stream_1,
    uint which
) {
    uint _e2 = pick_stream(stream_1);
    uint _e6 = pcg_hash((_e2 + 1u) + which);
    return _e6;
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
    metal::float3 q_9 = metal::clamp(c_1, bmin, bmax);
    metal::float3 v_6 = q_9 - c_1;
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
    bool local_16 = {};
    bool local_17 = {};
    metal::float3 v_7 = x_2 - y;
    float d2_6 = metal::dot(v_7, v_7);
    bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local_16 = !((d2_6 > 0.0));
    } else {
        local_16 = true;
    }
    bool _e16 = local_16;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_12 = v_7 / metal::float3(metal::sqrt(d2_6));
    float cos_x_1 = -(metal::dot(n_1, w_12));
    if (!(!((cos_x_1 > 0.0)))) {
        local_17 = !((metal::dot(ng, w_12) < 0.0));
    } else {
        local_17 = true;
    }
    bool _e34 = local_17;
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

bool weighted_replace(
    float w_4,
    float w_sum,
    float u_2
) {
    return (u_2 * w_sum) < w_4;
}

float weighted_threshold(
    float w_sum_1,
    float u_3
) {
    return w_sum_1 / (1.0 - u_3);
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
    uint j_7 = naga_mod(slot, 3u);
    if (j_7 == 0u) {
        return c_4.x;
    }
    if (j_7 == 1u) {
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
        float w_13 = 1.0 / _e4;
        return metal::float3(w_13, w_13, w_13);
    }
    uint j_8 = naga_mod(slot_1, 3u);
    float _e15 = to_f32_(naga_div((k_3 + 2u) - j_8, 3u));
    float w_14 = 1.0 / _e15;
    if (j_8 == 0u) {
        return metal::float3(w_14, 0.0, 0.0);
    }
    if (j_8 == 1u) {
        return metal::float3(0.0, w_14, 0.0);
    }
    return metal::float3(0.0, 0.0, w_14);
}

float grid_coordinate(
    uint bits_1
) {
    float _e3 = to_f32_(bits_1 >> 16u);
    return (_e3 + 0.5) / 65536.0;
}

uint grid_cells(
    uint h1_,
    uint h2_
) {
    return (h1_ & 4294901760u) | (h2_ >> 16u);
}

metal::float2 disk_offset(
    float r_3,
    float u1_1,
    float u2_1
) {
    float a_9 = TWO_PI * u2_1;
    return metal::float2(metal::cos(a_9), metal::sin(a_9)) * (r_3 * metal::sqrt(u1_1));
}

float gris_weight(
    float own,
    float all,
    float p_hat,
    float w_5
) {
    if (!((all > 0.0))) {
        return 0.0;
    }
    return ((own / all) * p_hat) * w_5;
}

float reuse_trust(
    metal::float3 h_1,
    metal::float3 t_1
) {
    float d2_7 = metal::dot(h_1, h_1);
    if (!((d2_7 > 0.0))) {
        return 1.0;
    }
    metal::float3 c_11 = h_1 - t_1;
    return d2_7 / (d2_7 + (REUSE_TRUST_SCALE * metal::dot(c_11, c_11)));
}

float gris_contribution_weight(
    float w_sum_2,
    float p_hat_1
) {
    if (!((p_hat_1 > 0.0))) {
        return 0.0;
    }
    return w_sum_2 / p_hat_1;
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
    float t_6 = ((cos_h * cos_h) * a2_) + sin2_h;
    return (a2_ * INV_PI) / (t_6 * t_6);
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
    bool local_18 = {};
    if (!((n_l <= 0.0))) {
        local_18 = n_v <= 0.0;
    } else {
        local_18 = true;
    }
    bool _e11 = local_18;
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
    float c_12 = metal::saturate(1.0 - v_h);
    float c2_1 = c_12 * c_12;
    return f0_ + ((metal::float3(f90_, f90_, f90_) - f0_) * ((c2_1 * c2_1) * c_12));
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
    bool local_19 = {};
    bool local_20 = {};
    if (!((metallic_1 > 0.0))) {
        local_19 = f90_d_1 > 0.0;
    } else {
        local_19 = true;
    }
    bool _e11 = local_19;
    if (!(_e11)) {
        local_20 = metal::max(metal::max(f0_d_1.x, f0_d_1.y), f0_d_1.z) > 0.0;
    } else {
        local_20 = true;
    }
    bool _e23 = local_20;
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
    bool local_21 = {};
    metal::float3 _e10 = fresnel_schlick(f0_d_2, f90_d_2, n_v_1);
    float _e16 = channel_mean(((metal::float3(1.0, 1.0, 1.0) - _e10) * base_1) * (1.0 - metallic_2));
    if (!((n_v_1 <= 0.0))) {
        bool _e22 = has_specular(metallic_2, f0_d_2, f90_d_2);
        local_21 = !(_e22);
    } else {
        local_21 = true;
    }
    bool _e25 = local_21;
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
    float r_4,
    float n_v_2
) {
    float rx = 1.0 - r_4;
    float a004_ = (metal::min(rx * rx, metal::exp2(-9.28 * n_v_2)) * rx) + (0.0425 - (0.0275 * r_4));
    float x_18 = metal::max((1.04 - (0.572 * r_4)) - (1.04 * a004_), 0.00005);
    float y_1 = metal::max(((0.022 * r_4) - 0.04) + (1.04 * a004_), 0.00005);
    return x_18 + y_1;
}

metal::float3 bevy_brdf(
    metal::float3 base_2,
    float metallic_3,
    float r_5,
    float reflectance_1,
    metal::float3 n_4,
    metal::float3 v_1,
    metal::float3 l
) {
    float n_l_1 = metal::saturate(metal::dot(n_4, l));
    if (n_l_1 <= 0.0) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    float _e15 = bevy_alpha(r_5);
    float n_v_3 = metal::max(metal::dot(n_4, v_1), 0.0001);
    metal::float3 h_4 = metal::normalize(l + v_1);
    float n_h = metal::saturate(metal::dot(n_4, h_4));
    float l_h = metal::saturate(metal::dot(l, h_4));
    float f90_d_3 = 0.5 + (((2.0 * _e15) * l_h) * l_h);
    metal::float3 _e35 = fresnel_schlick(metal::float3(1.0, 1.0, 1.0), f90_d_3, n_l_1);
    metal::float3 _e41 = fresnel_schlick(metal::float3(1.0, 1.0, 1.0), f90_d_3, n_v_3);
    float burley = (_e35.x * _e41.x) * INV_PI;
    float _e46 = bevy_f0_(reflectance_1);
    metal::float3 f0_1 = (metal::float3(_e46, _e46, _e46) * (1.0 - metallic_3)) + (base_2 * metallic_3);
    float f90_1 = metal::saturate(((f0_1.x + f0_1.y) + f0_1.z) * 16.5);
    float _e64 = ggx_d(n_h, 1.0 - (n_h * n_h), _e15);
    float _e65 = smith_visibility(n_l_1, n_v_3, _e15);
    float _e70 = bevy_dfg(r_5, n_v_3);
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
    bool local_22 = {};
    bool local_23 = {};
    float vd = metal::dot(v_2, d);
    float h2_1 = d2_4 - (a_3 * a_3);
    if (!((h2_1 <= 0.0))) {
        if (vd >= 0.0) {
            local_23 = (vd * vd) >= h2_1;
        } else {
            local_23 = false;
        }
        bool _e19 = local_23;
        local_22 = _e19;
    } else {
        local_22 = true;
    }
    bool _e21 = local_22;
    if (_e21) {
        return 1.0;
    }
    metal::float3 c_13 = metal::cross(v_2, d);
    return metal::min(((vd * metal::sqrt(h2_1)) + (metal::sqrt(metal::dot(c_13, c_13)) * a_3)) / d2_4, 1.0);
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
    float t_7 = ((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0;
    return metal::clamp(rl.x + ((rl.y * rl.z) / (t_7 * t_7)), 1.0, rl.w * rl.w);
}

float range_scale_toward(
    metal::float4 rl_1,
    metal::float3 center_1,
    float radius_1,
    metal::float3 p_1,
    metal::float3 r_6
) {
    if (rl_1.w <= 1.0) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_6);
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
    bool local_24 = {};
    metal::float3 n_17 = metal::cross(b_3 - a_4, c_6 - a_4);
    float l2_ = metal::dot(n_17, n_17);
    if (!(!((l2_ > 0.0)))) {
        local_24 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_24 = true;
    }
    bool _e17 = local_24;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_17 / metal::float3(metal::sqrt(l2_));
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
    bool local_25 = {};
    bool local_26 = {};
    bool local_27 = {};
    metal::float3 e1_ = b_4 - a_5;
    metal::float3 e2_ = c_7 - a_5;
    metal::float3 p_8 = metal::cross(d_3, e2_);
    float det = metal::dot(e1_, p_8);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv = 1.0 / det;
    metal::float3 s_12 = o_1 - a_5;
    float u_4 = metal::dot(s_12, p_8) * inv;
    if (!((u_4 < 0.0))) {
        local_25 = u_4 > 1.0;
    } else {
        local_25 = true;
    }
    bool _e28 = local_25;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q_10 = metal::cross(s_12, e1_);
    float v_9 = metal::dot(d_3, q_10) * inv;
    if (!((v_9 < 0.0))) {
        local_26 = (u_4 + v_9) > 1.0;
    } else {
        local_26 = true;
    }
    bool _e42 = local_26;
    if (_e42) {
        return -1.0;
    }
    float t_8 = metal::dot(e2_, q_10) * inv;
    if (t_8 > t_min) {
        local_27 = t_8 < t_max_1;
    } else {
        local_27 = false;
    }
    bool _e51 = local_27;
    if (_e51) {
        return t_8;
    }
    return -1.0;
}

metal::float3 reproject(
    metal::float4 c0_,
    metal::float4 c1_,
    metal::float4 c2_,
    metal::float4 c3_,
    metal::float3 p_2,
    float width,
    float height
) {
    metal::float4 clip = (((c0_ * p_2.x) + (c1_ * p_2.y)) + (c2_ * p_2.z)) + c3_;
    if (clip.w <= 0.0) {
        return metal::float3(-1.0, -1.0, 0.0);
    }
    float x_19 = ((((clip.x / clip.w) + 1.0) * 0.5) * width) - 0.5;
    float y_2 = (((1.0 - (clip.y / clip.w)) * 0.5) * height) - 0.5;
    return metal::float3(x_19, y_2, clip.w);
}

bool history_matches(
    metal::float3 n_5,
    metal::float3 nh,
    metal::float3 p_3,
    float oh,
    float d_4
) {
    bool local_28 = {};
    if (metal::abs(metal::dot(nh, p_3) - oh) <= (TEMPORAL_DEPTH_TOLERANCE * d_4)) {
        local_28 = metal::dot(n_5, nh) >= TEMPORAL_NORMAL_COS;
    } else {
        local_28 = false;
    }
    bool _e17 = local_28;
    return _e17;
}

metal::float3 light_intensity(
    GpuLight l_1,
    metal::float3 w_6
) {
    switch(l_1.kind) {
        case 0u: {
            return l_1.intensity;
        }
        case 3u: {
            metal::float3 _e8 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
            float _e10 = triangle_lobe(_e8, l_1.a, w_6);
            return l_1.intensity * _e10;
        }
        default: {
            return metal::float3(0.0);
        }
    }
}

metal::float3 light_point(
    GpuLight l_2,
    float u1_2,
    float u2_2
) {
    if (l_2.kind == LIGHT_TRIANGLE) {
        metal::float3 _e9 = triangle_sample(l_2.p0_, l_2.p1_, l_2.p2_, u1_2, u2_2);
        return _e9;
    }
    return l_2.p0_;
}

GeoHit trace(
    metal::float3 o_2,
    metal::float3 d_5,
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
    metal::float3 _e14 = ray_inverse3_(d_5);
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e21 = node_3;
        GpuGeoNode n_18 = geo_nodes[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_18.bmin, n_18.bmax, _e27);
        if (_e28 >= 0.0) {
            if (n_18.count > 0u) {
                i = n_18.first;
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
                    if (_e36 < (n_18.first + n_18.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_9 = geo_tris[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_5, t_9.v0_, t_9.v1_, t_9.v2_, t_min_1, _e49);
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
                    stack.inner[_e63] = n_18.first + 1u;
                    uint _e68 = sp;
                    sp = _e68 + 1u;
                }
                node_3 = n_18.first;
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
    metal::float3 r_7,
    metal::float4 rl_2
) {
    float _e5 = cone_cos_of(v_3, d2_5, a_7, r_7);
    float _e8 = range_scale_at(rl_2, _e5 + 0.000002);
    return _e8;
}

bool bsh_reaches(
    BshNode node_4,
    metal::float3 x_4,
    metal::float3 r_8,
    metal::float4 rl_3
) {
    bool local_29 = {};
    bool local_30 = {};
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_4);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, node_4.radius * (rl_3.w * 1.0001), x_4);
        local_29 = !(_e20);
    } else {
        local_29 = true;
    }
    bool _e23 = local_29;
    if (_e23) {
        return false;
    }
    metal::float3 v_10 = x_4 - node_4.center;
    float d2_8 = metal::dot(v_10, v_10);
    float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_8 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        float _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_4, r_8);
        float _e41 = bsh_scaled_radius(node_4, metal::sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_4);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_10), d2_8, r_8, rl_3);
    float s_c = _e45 * 1.001;
    float _e50 = bsh_range_bound(node_4);
    float reach = node_4.extent + (metal::sqrt(s_c) * _e50);
    if (d2_8 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_30 = d2_8 <= (reach * reach);
    } else {
        local_30 = false;
    }
    bool _e63 = local_30;
    return _e63;
}

bool bsh_reaches_box(
    BshNode node_5,
    metal::float3 lo,
    metal::float3 hi,
    float w_7
) {
    bool _e13 = sphere_overlaps_aabb(node_5.center, node_5.radius * (metal::max(1.0, w_7 * 1.0001) * 1.0001), lo, hi);
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
    bool local_31 = {};
    uint _e3 = bsh_first(nodes_3, bsh_nodes, _buffer_sizes);
    i_2 = _e3;
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e7 = level;
        if (_e7 < depth) {
            uint _e11 = i_2;
            local_31 = _e11 != BSH_NONE;
        } else {
            local_31 = false;
        }
        bool _e15 = local_31;
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
    float w_8,
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
            bool _e11 = bsh_reaches_box(_e10, lo_1, hi_1, w_8);
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
    thread uint& h_2
) {
    uint _e2 = h_2;
    uint _e3 = pcg_hash(_e2);
    h_2 = _e3;
    uint _e4 = h_2;
    float _e5 = xi_from_bits(_e4);
    float _e6 = weighted_threshold(sum, _e5);
    return _e6;
}

Connection connect_record(
    GpuLight l_3,
    metal::float3 x_5,
    metal::float3 n_6,
    metal::float3 ng_1,
    float r2_2,
    float rt2_2,
    float w_res,
    float u1_3,
    float u2_3,
    float eps,
    bool trace_1,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection c_8 = {};
    bool local_32 = {};
    bool local_33 = {};
    c_8.e = metal::float3(0.0);
    metal::float3 _e16 = light_point(l_3, u1_3, u2_3);
    c_8.y = _e16;
    metal::float3 _e19 = c_8.y;
    float _e20 = connection_cosine(x_5, _e19, n_6, ng_1, r2_2);
    c_8.cos_x = _e20;
    float _e22 = c_8.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            metal::float3 _e33 = c_8.y;
            bool _e34 = occluded(x_5 + (ng_1 * eps), _e33, geo_nodes, geo_tris, _buffer_sizes);
            local_33 = _e34;
        } else {
            local_33 = false;
        }
        bool _e36 = local_33;
        local_32 = _e36;
    } else {
        local_32 = true;
    }
    bool _e38 = local_32;
    if (_e38) {
        Connection _e39 = c_8;
        return _e39;
    }
    metal::float3 _e41 = c_8.y;
    metal::float3 v_11 = x_5 - _e41;
    float d2_9 = metal::dot(v_11, v_11);
    metal::float3 _e48 = light_intensity(l_3, v_11 / metal::float3(metal::sqrt(d2_9)));
    float _e50 = c_8.cos_x;
    float _e51 = connection_factor(_e50, d2_9, rt2_2, w_res);
    c_8.e = _e48 * _e51;
    Connection _e53 = c_8;
    return _e53;
}

Connection connect_traced(
    uint li,
    metal::float3 x_6,
    metal::float3 n_7,
    metal::float3 ng_2,
    float s_2,
    float w_res_1,
    float u1_4,
    float u2_4,
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
    Connection _e21 = connect_record(_e12, x_6, n_7, ng_2, s_2 * _e15, s_2 * _e19, w_res_1, u1_4, u2_4, eps_1, trace_2, geo_nodes, geo_tris, _buffer_sizes);
    return _e21;
}

float light_range_scale(
    uint li_1,
    metal::float3 x_7,
    metal::float3 r_9,
    metal::float4 rl_4,
    device type_14 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_14 = light_cones[li_1];
    float _e9 = range_scale_toward(rl_4, c_14.center, c_14.radius, x_7, r_9);
    return _e9;
}

metal::float4 surface_at(
    metal::int2 texel,
    metal::texture2d<float, metal::access::sample> position_tex
) {
    metal::float4 p_9 = position_tex.read(metal::uint2(texel), 0);
    return (p_9.w > 0.0) ? metal::float4(p_9.xyz, 1.0) : metal::float4(0.0);
}

WorkgroupBox workgroup_bounds(
    uint li_2,
    metal::float3 lo_2,
    metal::float3 hi_2,
    threadgroup type_20& wg_lo,
    threadgroup type_20& wg_hi,
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
    metal::float3 p_4,
    bool has
) {
    return WorkgroupBox {has ? p_4 : metal::float3(340282350000000000000000000000000000000.0), has ? p_4 : metal::float3(-340282350000000000000000000000000000000.0)};
}

WorkgroupBox workgroup_box(
    uint li_3,
    metal::float3 p_5,
    bool has_1,
    threadgroup type_20& wg_lo,
    threadgroup type_20& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    WorkgroupBox _e3 = point_box(p_5, has_1);
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
    TileWalk t_2,
    bool list,
    uint at,
    uint start_2,
    uint to,
    device type_13 const& bsh_nodes,
    threadgroup type_21& tile_list,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint p_6 = {};
    uint b_7 = {};
    bool local_34 = {};
    bool local_35 = {};
    bool local_36 = {};
    uint _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH, bsh_nodes, _buffer_sizes);
    if (_e8 == BSH_NONE) {
        return 0u;
    }
    uint end_1 = bsh_nodes[_e8].next;
    p_6 = at;
    uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_2.lo, t_2.hi, t_2.w, bsh_nodes, _buffer_sizes);
    b_7 = _e21;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e53 = b_7;
            uint _e56 = bsh_nodes[_e53].next;
            uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_2.lo, t_2.hi, t_2.w, bsh_nodes, _buffer_sizes);
            b_7 = _e60;
        }
        loop_init_2 = false;
        uint _e23 = b_7;
        if (_e23 != end_1) {
            if (!(!(list))) {
                uint _e31 = p_6;
                local_35 = _e31 < to;
            } else {
                local_35 = true;
            }
            bool _e34 = local_35;
            local_34 = _e34;
        } else {
            local_34 = false;
        }
        bool _e36 = local_34;
        if (_e36) {
        } else {
            break;
        }
        {
            if (list) {
                uint _e39 = p_6;
                local_36 = _e39 >= start_2;
            } else {
                local_36 = false;
            }
            bool _e42 = local_36;
            if (_e42) {
                uint _e44 = p_6;
                uint _e47 = b_7;
                tile_list.inner[_e44 - start_2] = _e47;
            }
            uint _e48 = p_6;
            p_6 = _e48 + 1u;
        }
    }
    uint _e61 = p_6;
    return _e61 - at;
}

TileWalk tile_walk_begin(
    uint li_4,
    metal::float3 x_8,
    float w_9,
    bool has_2,
    device type_13 const& bsh_nodes,
    threadgroup type_20& wg_lo,
    threadgroup type_20& wg_hi,
    threadgroup WorkgroupBox& wg_box,
    threadgroup type_21& tile_list,
    threadgroup type_22& subtree_at,
    threadgroup metal::atomic_uint& tile_scale,
    threadgroup uint& tile_total,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_37 = {};
    TileWalk t_3 = {};
    uint s_4 = {};
    uint sum_1 = 0u;
    uint s_5 = 0u;
    if (has_2) {
        local_37 = w_9 >= 0.0;
    } else {
        local_37 = false;
    }
    bool _e12 = local_37;
    uint _e14 = metal::atomic_fetch_max_explicit(&tile_scale, _e12 ? as_type<uint>(w_9) : 0u, metal::memory_order_relaxed);
    WorkgroupBox _e15 = workgroup_box(li_4, x_8, has_2, wg_lo, wg_hi, wg_box);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_1 = metal::atomic_load_explicit(&tile_scale, metal::memory_order_relaxed);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    t_3 = TileWalk {_e15.lo, _e15.hi, as_type<float>(unnamed_1), 0u};
    bool _e24 = box_is_empty(_e15);
    if (_e24) {
        TileWalk _e25 = t_3;
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
            TileWalk _e34 = t_3;
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
                uint c_15 = subtree_at.inner[_e53];
                uint _e57 = s_5;
                uint _e59 = sum_1;
                subtree_at.inner[_e57] = _e59;
                uint _e60 = sum_1;
                sum_1 = _e60 + c_15;
            }
        }
        uint _e66 = sum_1;
        tile_total = _e66;
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_2 = tile_total;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    t_3.total = unnamed_2;
    TileWalk _e70 = t_3;
    return _e70;
}

uint tile_walk_fill(
    uint li_5,
    TileWalk t_4,
    uint start_3,
    device type_13 const& bsh_nodes,
    threadgroup type_21& tile_list,
    threadgroup type_22& subtree_at,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint s_6 = {};
    uint past = {};
    bool local_38 = {};
    uint to_1 = metal::min(t_4.total, start_3 + TILE_LIST);
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
            past = t_4.total;
            uint _e17 = s_6;
            if ((_e17 + 1u) < BSH_TILE_SUBTREES) {
                uint _e23 = s_6;
                uint _e27 = subtree_at.inner[_e23 + 1u];
                past = _e27;
            }
            if (at_1 < to_1) {
                uint _e31 = past;
                local_38 = _e31 > start_3;
            } else {
                local_38 = false;
            }
            bool _e34 = local_38;
            if (_e34) {
                uint _e35 = s_6;
                uint _e37 = tile_subtree(_e35, t_4, true, at_1, start_3, to_1, bsh_nodes, tile_list, _buffer_sizes);
            }
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return to_1 - start_3;
}

Shaded shade_connection(
    Connection c_9,
    metal::float3 x_9,
    metal::float3 n_8,
    Material m_1
) {
    Shaded s_7 = {};
    s_7.e = c_9.e;
    s_7.diffuse = metal::float3(0.0);
    s_7.specular = metal::float3(0.0);
    if (c_9.cos_x > 0.0) {
        metal::float3 _e25 = bevy_brdf(m_1.base, m_1.metallic, m_1.roughness, m_1.reflectance, n_8, m_1.v, metal::normalize(c_9.y - x_9));
        s_7.diffuse = _e25 * c_9.e;
    }
    Shaded _e28 = s_7;
    return _e28;
}

Shaded shade_pick_traced(
    uint li_6,
    metal::float3 x_10,
    metal::float3 n_9,
    metal::float3 r_10,
    metal::float4 rl_5,
    Material m_2,
    float w_10,
    float u1_5,
    float u2_5,
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
    float _e11 = light_range_scale(li_6, x_10, r_10, rl_5, light_cones, _buffer_sizes);
    Connection _e12 = connect_traced(li_6, x_10, n_9, n_9, _e11, w_10, u1_5, u2_5, eps_2, trace_3, geo_nodes, geo_tris, lights, rt2_3, r2_3, _buffer_sizes);
    Shaded _e13 = shade_connection(_e12, x_10, n_9, m_2);
    return _e13;
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
    metal::float3 w_11
) {
    return Shaded {s_8.e * w_11, s_8.diffuse * w_11, s_8.specular * w_11};
}

type_17 first_holders(
    type_25 keys_1,
    type_26 held_1
) {
    type_17 first = {};
    uint k_4 = 0u;
    uint j_4 = {};
    bool local_39 = {};
    bool local_40 = {};
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
            j_4 = 0u;
            uint2 loop_bound_10 = uint2(4294967295u);
            bool loop_init_7 = true;
            while(true) {
                if (metal::all(loop_bound_10 == uint2(0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_7) {
                    uint _e42 = j_4;
                    j_4 = _e42 + 1u;
                }
                loop_init_7 = false;
                uint _e17 = j_4;
                uint _e18 = k_4;
                if (_e17 < _e18) {
                    uint _e22 = k_4;
                    local_39 = held_1.inner[_e22];
                } else {
                    local_39 = false;
                }
                bool _e25 = local_39;
                if (_e25) {
                } else {
                    break;
                }
                {
                    uint _e26 = j_4;
                    if (held_1.inner[_e26]) {
                        uint _e30 = j_4;
                        uint _e32 = k_4;
                        local_40 = metal::all(keys_1.inner[_e30] == keys_1.inner[_e32]);
                    } else {
                        local_40 = false;
                    }
                    bool _e37 = local_40;
                    if (_e37) {
                        uint _e38 = k_4;
                        uint _e40 = j_4;
                        first.inner[_e38] = _e40;
                        break;
                    }
                }
            }
        }
    }
    type_17 _e47 = first;
    return _e47;
}

metal::float3 output_of(
    Shaded s_9
) {
    return s_9.diffuse + s_9.specular;
}

uint previous_index(
    uint i_4,
    constant ViewParams& view,
    constant ReuseParams& reuse
) {
    uint _e4 = reuse.parity;
    uint _e8 = view.width;
    uint _e12 = view.height;
    return (((1u - _e4) * _e8) * _e12) + i_4;
}

uint next_index(
    uint i_5,
    constant ViewParams& view,
    constant ReuseParams& reuse
) {
    uint _e3 = reuse.parity;
    uint _e6 = view.width;
    uint _e10 = view.height;
    return ((_e3 * _e6) * _e10) + i_5;
}

Connection sample_connection(
    GpuLight l_4,
    uint cells,
    metal::float3 x_11,
    metal::float3 n_10,
    float eps_3,
    bool trace_4,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e9 = grid_coordinate(cells);
    float _e12 = grid_coordinate(cells << 16u);
    Connection _e13 = connect_record(l_4, x_11, n_10, n_10, UNRANGED, UNRANGED, 1.0, _e9, _e12, eps_3, trace_4, geo_nodes, geo_tris, _buffer_sizes);
    return _e13;
}

float reuse_target(
    uint q_6,
    GpuLight l_5,
    uint cells_1,
    metal::float3 x_12,
    metal::float3 n_11,
    Material m_3,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection _e8 = sample_connection(l_5, cells_1, x_12, n_11, 0.0, false, geo_nodes, geo_tris, _buffer_sizes);
    Shaded _e9 = shade_connection(_e8, x_12, n_11, m_3);
    metal::float3 _e10 = output_of(_e9);
    float _e12 = slot_target(_e10, q_6, K);
    return _e12;
}

ReuseSurface reuse_surface(
    metal::float3 x_13,
    metal::float3 n_12,
    Material m_4,
    float c_10
) {
    return ReuseSurface {x_13, c_10, n_12, metal::pack_float_to_unorm4x8(metal::float4(m_4.base, m_4.metallic)), metal::pack_float_to_unorm2x16(metal::float2(metal::saturate(m_4.roughness), metal::saturate(m_4.reflectance))), 0u, 0u, 0u};
}

Material reuse_material(
    ReuseSurface s_10,
    metal::float3 eye
) {
    metal::float4 b_9 = metal::unpack_unorm4x8_to_float(s_10.base);
    metal::float2 r_12 = metal::unpack_unorm2x16_to_float(s_10.rough);
    Material _e13 = material_of(b_9.xyz, b_9.w, r_12.x, r_12.y, metal::normalize(eye - s_10.x));
    return _e13;
}

metal::uint2 sample_key(
    uint li_7,
    uint cells_2,
    device type_12 const& lights,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e6 = lights[li_7].kind;
    return metal::uint2(li_7, (_e6 == LIGHT_TRIANGLE) ? cells_2 : 0u);
}

bool sample_reaches(
    GpuLight l_6,
    uint cells_3,
    metal::float3 x_14,
    metal::float3 n_13,
    float eps_4,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection _e6 = sample_connection(l_6, cells_3, x_14, n_13, eps_4, true, geo_nodes, geo_tris, _buffer_sizes);
    return metal::any(_e6.e > metal::float3(0.0));
}

float domain_offset(
    Domain d_6,
    constant ViewParams& view,
    constant ReuseParams& reuse
) {
    float _e3 = view.shadow_offset;
    metal::float3 _e6 = reuse.prev_eye;
    return _e3 * metal::length(_e6 - d_6.x);
}

bool history_vouches(
    uint li_8,
    uint cells_4,
    Domain d_7,
    constant ViewParams& view,
    constant ReuseParams& reuse,
    device type_12 const& lights_prev,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = reuse.moved;
    if (_e5 == 0u) {
        return true;
    }
    uint _e11 = reuse.moved;
    if (_e11 == 2u) {
        return false;
    }
    float _e17 = domain_offset(d_7, view, reuse);
    metal::float3 a_10 = d_7.x + (d_7.n * _e17);
    GpuLight _e22 = lights_prev[li_8];
    float _e23 = grid_coordinate(cells_4);
    float _e26 = grid_coordinate(cells_4 << 16u);
    metal::float3 _e27 = light_point(_e22, _e23, _e26);
    metal::float3 _e29 = ray_inverse3_(_e27 - a_10);
    metal::float3 _e32 = reuse.moved_min;
    metal::float3 _e35 = reuse.moved_max;
    float _e37 = ray_aabb(a_10, _e29, _e32, _e35, 1.0);
    return _e37 < 0.0;
}

bool reached_before(
    uint li_9,
    uint cells_5,
    Domain d_8,
    metal::float3 x_15,
    metal::float3 n_14,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant ViewParams& view,
    device type_12 const& lights,
    constant ReuseParams& reuse,
    device type_12 const& lights_prev,
    device type_16 const& reuse_pixels,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_41 = {};
    bool local_42 = {};
    bool local_43 = {};
    bool local_44 = {};
    uint q_7 = 0u;
    bool local_45 = {};
    bool local_46 = {};
    bool _e5 = history_vouches(li_9, cells_5, d_8, view, reuse, lights_prev, _buffer_sizes);
    if (!(_e5)) {
        return false;
    }
    GpuLight l_7 = lights[li_9];
    GpuLight lp = lights_prev[li_9];
    if (metal::all(d_8.x == x_15)) {
        local_41 = metal::all(d_8.n == n_14);
    } else {
        local_41 = false;
    }
    bool _e23 = local_41;
    if (_e23) {
        local_42 = metal::all(l_7.p0_ == lp.p0_);
    } else {
        local_42 = false;
    }
    bool _e31 = local_42;
    if (_e31) {
        local_43 = metal::all(l_7.p1_ == lp.p1_);
    } else {
        local_43 = false;
    }
    bool _e39 = local_43;
    if (_e39) {
        local_44 = metal::all(l_7.p2_ == lp.p2_);
    } else {
        local_44 = false;
    }
    bool _e47 = local_44;
    if (_e47) {
        return true;
    }
    metal::uint2 _e49 = sample_key(li_9, cells_5, lights, _buffer_sizes);
    uint2 loop_bound_11 = uint2(4294967295u);
    bool loop_init_8 = true;
    while(true) {
        if (metal::all(loop_bound_11 == uint2(0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_8) {
            uint _e85 = q_7;
            q_7 = _e85 + 1u;
        }
        loop_init_8 = false;
        uint _e52 = q_7;
        if (_e52 < K) {
        } else {
            break;
        }
        {
            uint _e57 = previous_index(d_8.pixel, view, reuse);
            uint _e60 = q_7;
            ReuseSlot h_5 = reuse_pixels[_e57].slots.inner[_e60];
            if (h_5.w > 0.0) {
                local_45 = h_5.light < (1 + (_buffer_sizes.size8 - 0 - 64) / 64);
            } else {
                local_45 = false;
            }
            bool _e73 = local_45;
            if (_e73) {
                metal::uint2 _e78 = sample_key(h_5.light, h_5.u, lights, _buffer_sizes);
                local_46 = metal::all(_e78 == _e49);
            } else {
                local_46 = false;
            }
            bool _e82 = local_46;
            if (_e82) {
                return true;
            }
        }
    }
    float _e89 = domain_offset(d_8, view, reuse);
    bool _e90 = sample_reaches(lp, cells_5, d_8.x, d_8.n, _e89, geo_nodes, geo_tris, _buffer_sizes);
    return _e90;
}

metal::int2 naga_f2i32(metal::float2 value) {
    return static_cast<metal::int2>(metal::clamp(value, -2147483600.0, 2147483500.0));
}

uint reuse_domains(
    metal::float3 x_16,
    metal::float3 n_15,
    float d_9,
    uint h_3,
    thread type_27& doms_1,
    constant ViewParams& view,
    constant ReuseParams& reuse,
    device type_16 const& reuse_pixels,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint nd = 0u;
    uint hr = {};
    uint j_5 = 0u;
    metal::float2 p_7 = {};
    bool local_47 = {};
    bool local_48 = {};
    bool local_49 = {};
    bool seen_1 = {};
    uint k_5 = {};
    bool local_50 = {};
    bool local_51 = {};
    bool local_52 = {};
    uint _e9 = reuse.has_history;
    if (_e9 != 1u) {
        return 0u;
    }
    metal::float4 _e15 = reuse.c0_;
    metal::float4 _e18 = reuse.c1_;
    metal::float4 _e21 = reuse.c2_;
    metal::float4 _e24 = reuse.c3_;
    uint _e27 = view.width;
    uint _e31 = view.height;
    metal::float3 _e33 = reproject(_e15, _e18, _e21, _e24, x_16, static_cast<float>(_e27), static_cast<float>(_e31));
    if (_e33.z <= 0.0) {
        return 0u;
    }
    hr = h_3;
    uint2 loop_bound_12 = uint2(4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (metal::all(loop_bound_12 == uint2(0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e176 = j_5;
            j_5 = _e176 + 1u;
        }
        loop_init_9 = false;
        uint _e41 = j_5;
        if (_e41 < DOMAINS) {
        } else {
            break;
        }
        {
            p_7 = _e33.xy;
            uint _e46 = j_5;
            if (_e46 > 0u) {
                uint _e49 = hr;
                uint _e50 = pcg_hash(_e49);
                hr = _e50;
                uint _e51 = hr;
                float _e52 = xi_from_bits(_e51);
                uint _e53 = hr;
                uint _e54 = pcg_hash(_e53);
                hr = _e54;
                metal::float2 _e55 = p_7;
                float _e58 = reuse.radius;
                uint _e59 = hr;
                float _e60 = xi_from_bits(_e59);
                metal::float2 _e61 = disk_offset(_e58, _e52, _e60);
                p_7 = _e55 + _e61;
            }
            metal::float2 _e63 = p_7;
            metal::int2 t_10 = naga_f2i32(metal::rint(_e63));
            if (!((t_10.x < 0))) {
                local_47 = t_10.y < 0;
            } else {
                local_47 = true;
            }
            bool _e76 = local_47;
            if (!(_e76)) {
                uint _e83 = view.width;
                local_48 = t_10.x >= static_cast<int>(_e83);
            } else {
                local_48 = true;
            }
            bool _e87 = local_48;
            if (!(_e87)) {
                uint _e94 = view.height;
                local_49 = t_10.y >= static_cast<int>(_e94);
            } else {
                local_49 = true;
            }
            bool _e98 = local_49;
            if (_e98) {
                continue;
            }
            uint _e103 = view.width;
            uint pixel = (static_cast<uint>(t_10.y) * _e103) + static_cast<uint>(t_10.x);
            seen_1 = false;
            k_5 = 0u;
            uint2 loop_bound_13 = uint2(4294967295u);
            bool loop_init_10 = true;
            while(true) {
                if (metal::all(loop_bound_13 == uint2(0u))) { break; }
                loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                if (!loop_init_10) {
                    uint _e127 = k_5;
                    k_5 = _e127 + 1u;
                }
                loop_init_10 = false;
                uint _e112 = k_5;
                uint _e113 = nd;
                if (_e112 < _e113) {
                } else {
                    break;
                }
                {
                    bool _e115 = seen_1;
                    if (!(_e115)) {
                        uint _e119 = k_5;
                        uint _e122 = doms_1.inner[_e119].pixel;
                        local_50 = _e122 == pixel;
                    } else {
                        local_50 = true;
                    }
                    bool _e125 = local_50;
                    seen_1 = _e125;
                }
            }
            uint _e130 = previous_index(pixel, view, reuse);
            ReuseSurface s_13 = reuse_pixels[_e130].surface;
            bool _e134 = seen_1;
            if (!(_e134)) {
                local_51 = !((s_13.m > 0.0));
            } else {
                local_51 = true;
            }
            bool _e143 = local_51;
            if (!(_e143)) {
                bool _e151 = history_matches(n_15, s_13.n, x_16, metal::dot(s_13.n, s_13.x), d_9);
                local_52 = !(_e151);
            } else {
                local_52 = true;
            }
            bool _e154 = local_52;
            if (_e154) {
                continue;
            }
            uint _e155 = nd;
            metal::float3 _e161 = reuse.prev_eye;
            Material _e162 = reuse_material(s_13, _e161);
            float _e166 = reuse.max_confidence;
            uint _e168 = j_5;
            doms_1.inner[_e155] = Domain {pixel, {}, s_13.x, s_13.n, _e162, metal::min(s_13.m, _e166), _e168 == 0u};
            uint _e172 = nd;
            nd = _e172 + 1u;
        }
    }
    uint _e178 = nd;
    return _e178;
}

ReuseSlot gris_combine(
    uint q_8,
    ReuseSlot cur,
    bool cur_ris,
    float cur_c,
    bool cur_reached,
    uint k0_,
    uint k1_,
    metal::float3 x_17,
    metal::float3 n_16,
    Material m_5,
    thread type_27& doms_2,
    thread uint& hs_1,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant ViewParams& view,
    device type_12 const& lights,
    constant ReuseParams& reuse,
    device type_12 const& lights_prev,
    device type_16 const& reuse_pixels,
    constant _mslBufferSizes& _buffer_sizes
) {
    float w_sum_3 = 0.0;
    ReuseSlot out = ReuseSlot {0u, 0u, 0.0};
    float out_target = 0.0;
    uint j_6 = {};
    ReuseSlot s_11 = {};
    bool local_53 = {};
    bool local_54 = {};
    bool local_55 = {};
    float w_in = {};
    bool local_56 = {};
    float own_1 = {};
    float all_1 = {};
    uint k_6 = {};
    float t_5 = {};
    bool local_57 = {};
    bool local_58 = {};
    j_6 = k0_;
    uint2 loop_bound_14 = uint2(4294967295u);
    bool loop_init_11 = true;
    while(true) {
        if (metal::all(loop_bound_14 == uint2(0u))) { break; }
        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
        if (!loop_init_11) {
            uint _e186 = j_6;
            j_6 = _e186 + 1u;
        }
        loop_init_11 = false;
        uint _e22 = j_6;
        if (_e22 <= k1_) {
        } else {
            break;
        }
        {
            s_11 = cur;
            uint _e25 = j_6;
            if (_e25 > k0_) {
                uint _e28 = j_6;
                uint _e33 = doms_2.inner[_e28 - 1u].pixel;
                uint _e34 = previous_index(_e33, view, reuse);
                ReuseSlot _e38 = reuse_pixels[_e34].slots.inner[q_8];
                s_11 = _e38;
            }
            float _e40 = s_11.w;
            if (!(!((_e40 > 0.0)))) {
                uint _e48 = s_11.light;
                local_53 = _e48 >= (1 + (_buffer_sizes.size8 - 0 - 64) / 64);
            } else {
                local_53 = true;
            }
            bool _e53 = local_53;
            if (_e53) {
                continue;
            }
            uint _e54 = j_6;
            if (_e54 > k0_) {
                uint _e60 = reuse.visibility;
                local_54 = _e60 == 1u;
            } else {
                local_54 = false;
            }
            bool _e64 = local_54;
            if (_e64) {
                uint _e68 = s_11.light;
                uint _e70 = s_11.u;
                uint _e71 = j_6;
                Domain _e75 = doms_2.inner[_e71 - 1u];
                bool _e76 = history_vouches(_e68, _e70, _e75, view, reuse, lights_prev, _buffer_sizes);
                local_55 = !(_e76);
            } else {
                local_55 = false;
            }
            bool _e79 = local_55;
            if (_e79) {
                continue;
            }
            uint _e82 = s_11.light;
            GpuLight _e84 = lights[_e82];
            uint _e86 = s_11.u;
            float _e87 = reuse_target(q_8, _e84, _e86, x_17, n_16, m_5, geo_nodes, geo_tris, _buffer_sizes);
            if (!((_e87 > 0.0))) {
                continue;
            }
            float _e92 = s_11.w;
            w_in = _e92;
            uint _e94 = j_6;
            if (_e94 == k0_) {
                local_56 = cur_ris;
            } else {
                local_56 = false;
            }
            bool _e99 = local_56;
            if (_e99) {
                float _e101 = s_11.w;
                w_in = _e101 / _e87;
            }
            own_1 = cur_c * _e87;
            float _e105 = own_1;
            all_1 = _e105;
            uint _e109 = s_11.light;
            GpuLight _e111 = lights[_e109];
            uint _e113 = s_11.u;
            float _e114 = grid_coordinate(_e113);
            uint _e116 = s_11.u;
            float _e119 = grid_coordinate(_e116 << 16u);
            metal::float3 _e120 = light_point(_e111, _e114, _e119);
            k_6 = k0_;
            uint2 loop_bound_15 = uint2(4294967295u);
            bool loop_init_12 = true;
            while(true) {
                if (metal::all(loop_bound_15 == uint2(0u))) { break; }
                loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
                if (!loop_init_12) {
                    uint _e164 = k_6;
                    k_6 = _e164 + 1u;
                }
                loop_init_12 = false;
                uint _e122 = k_6;
                if (_e122 < k1_) {
                } else {
                    break;
                }
                {
                    t_5 = 0.0;
                    uint _e126 = j_6;
                    if (!((_e126 > k0_))) {
                        local_57 = cur_reached;
                    } else {
                        local_57 = true;
                    }
                    bool _e132 = local_57;
                    if (_e132) {
                        uint _e133 = k_6;
                        Domain d_10 = doms_2.inner[_e133];
                        float _e140 = reuse_trust(_e120 - x_17, _e120 - d_10.x);
                        uint _e144 = s_11.light;
                        GpuLight _e146 = lights_prev[_e144];
                        uint _e148 = s_11.u;
                        float _e152 = reuse_target(q_8, _e146, _e148, d_10.x, d_10.n, d_10.m, geo_nodes, geo_tris, _buffer_sizes);
                        t_5 = (d_10.c * _e140) * _e152;
                    }
                    float _e154 = all_1;
                    float _e155 = t_5;
                    all_1 = _e154 + _e155;
                    uint _e157 = k_6;
                    uint _e160 = j_6;
                    if ((_e157 + 1u) == _e160) {
                        float _e162 = t_5;
                        own_1 = _e162;
                    }
                }
            }
            float _e166 = own_1;
            float _e167 = all_1;
            float _e168 = w_in;
            float _e169 = gris_weight(_e166, _e167, _e87, _e168);
            float _e170 = w_sum_3;
            w_sum_3 = _e170 + _e169;
            uint _e172 = hs_1;
            uint _e173 = pcg_hash(_e172);
            hs_1 = _e173;
            if (_e169 > 0.0) {
                float _e178 = w_sum_3;
                uint _e179 = hs_1;
                float _e180 = xi_from_bits(_e179);
                bool _e181 = weighted_replace(_e169, _e178, _e180);
                local_58 = _e181;
            } else {
                local_58 = false;
            }
            bool _e183 = local_58;
            if (_e183) {
                ReuseSlot _e184 = s_11;
                out = _e184;
                out_target = _e87;
            }
        }
    }
    float _e189 = w_sum_3;
    float _e190 = out_target;
    float _e191 = gris_contribution_weight(_e189, _e190);
    out.w = _e191;
    ReuseSlot _e192 = out;
    return _e192;
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
, constant ReuseParams& reuse [[user(fake0)]]
, device type_12 const& lights_prev [[user(fake0)]]
, device type_16& reuse_pixels [[user(fake0)]]
, threadgroup type_20& wg_lo
, threadgroup type_20& wg_hi
, threadgroup WorkgroupBox& wg_box
, threadgroup type_21& tile_list
, threadgroup type_22& subtree_at
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
    type_17 slot_light = {};
    type_30 slot_u = {};
    type_31 slot_p = {};
    type_17 slot_cells = {};
    metal::float3 total = metal::float3(0.0);
    uint count = 0u;
    uint hc = {};
    type_31 threshold = {};
    uint start = 0u;
    uint j = {};
    bool local_4 = {};
    uint q = {};
    bool local_5 = {};
    type_27 doms = {};
    bool local_6 = {};
    uint hs = {};
    type_25 fresh_keys = {};
    type_26 fresh_held = {};
    uint q_1 = 0u;
    bool local_7 = {};
    type_26 fresh_visible = {};
    uint q_2 = 0u;
    type_26 fresh_before = {};
    uint q_3 = 0u;
    bool local_8 = {};
    bool local_9 = {};
    type_15 kept = {};
    type_15 fin = {};
    uint q_4 = 0u;
    bool local_10 = {};
    bool local_11 = {};
    type_25 keys = {};
    type_26 held = {};
    uint k = 0u;
    type_26 visible = {};
    uint k_1 = 0u;
    metal::float3 w = {};
    uint j_1 = {};
    bool known = {};
    bool seen = {};
    uint j_2 = {};
    bool local_12 = {};
    bool local_13 = {};
    Shaded shaded = {};
    bool local_14 = {};
    uint j_3 = {};
    uint q_5 = 0u;
    bool local_15 = {};
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
    metal::float3 x_20 = _e35.xyz;
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
        local_3 = metal::all(metal::abs(x_20) <= metal::float3(340282350000000000000000000000000000000.0));
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
        Material _e93 = material_of(_e83.xyz, mr.z, mr.y, mr.w, metal::normalize(_e90 - x_20));
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
    float eps_5 = _e117 * metal::length(_e120 - x_20);
    uint _e126 = view.seed;
    uint _e130 = view.width;
    uint _e136 = view.frame;
    uint _e137 = point_stream(_e126, (gid.y * _e130) + gid.x, _e136);
    uint _e138 = pick_stream(_e137);
    h = _e138;
    hc = _e137;
    TileWalk _e160 = tile_walk_begin(lid, x_20, _e114.w, has_3, bsh_nodes, wg_lo, wg_hi, wg_box, tile_list, subtree_at, tile_scale, tile_total, _buffer_sizes);
    uint2 loop_bound_16 = uint2(4294967295u);
    bool loop_init_13 = true;
    while(true) {
        if (metal::all(loop_bound_16 == uint2(0u))) { break; }
        loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
        if (!loop_init_13) {
            uint _e259 = start;
            start = _e259 + TILE_LIST;
        }
        loop_init_13 = false;
        uint _e163 = start;
        if (_e163 < _e160.total) {
        } else {
            break;
        }
        {
            uint _e166 = start;
            uint _e167 = tile_walk_fill(lid, _e160, _e166, bsh_nodes, tile_list, subtree_at, _buffer_sizes);
            j = 0u;
            uint2 loop_bound_17 = uint2(4294967295u);
            bool loop_init_14 = true;
            while(true) {
                if (metal::all(loop_bound_17 == uint2(0u))) { break; }
                loop_bound_17 -= uint2(loop_bound_17.y == 0u, 1u);
                if (!loop_init_14) {
                    uint _e257 = j;
                    j = _e257 + 1u;
                }
                loop_init_14 = false;
                uint _e170 = j;
                if (_e170 < _e167) {
                } else {
                    break;
                }
                {
                    uint _e173 = j;
                    uint b_10 = tile_list.inner[_e173];
                    if (!(!(has_3))) {
                        BshNode _e182 = bsh_nodes[b_10];
                        metal::float3 _e183 = r;
                        bool _e184 = bsh_reaches(_e182, x_20, _e183, _e114);
                        local_4 = !(_e184);
                    } else {
                        local_4 = true;
                    }
                    bool _e187 = local_4;
                    if (_e187) {
                        continue;
                    }
                    uint li_10 = bsh_nodes[b_10].light;
                    uint _e192 = count;
                    count = _e192 + 1u;
                    uint _e195 = h;
                    uint _e196 = pcg_hash(_e195);
                    h = _e196;
                    uint h1_1 = h;
                    uint _e198 = h;
                    uint _e199 = pcg_hash(_e198);
                    h = _e199;
                    uint _e200 = h;
                    uint _e201 = grid_cells(h1_1, _e200);
                    float _e202 = grid_coordinate(h1_1);
                    uint _e203 = h;
                    float _e204 = grid_coordinate(_e203);
                    metal::float2 u_5 = metal::float2(_e202, _e204);
                    metal::float3 _e206 = n;
                    metal::float3 _e207 = r;
                    Material _e208 = m;
                    Shaded _e213 = shade_pick_traced(li_10, x_20, _e206, _e207, _e114, _e208, 1.0, u_5.x, u_5.y, eps_5, false, geo_nodes, geo_tris, lights, rt2_3, r2_3, light_cones, _buffer_sizes);
                    metal::float3 _e214 = output_of(_e213);
                    float _e215 = resample_target(_e214);
                    if (_e215 > 0.0) {
                        metal::float3 _e218 = total;
                        total = _e218 + _e214;
                        q = 0u;
                        uint2 loop_bound_18 = uint2(4294967295u);
                        bool loop_init_15 = true;
                        while(true) {
                            if (metal::all(loop_bound_18 == uint2(0u))) { break; }
                            loop_bound_18 -= uint2(loop_bound_18.y == 0u, 1u);
                            if (!loop_init_15) {
                                uint _e254 = q;
                                q = _e254 + 1u;
                            }
                            loop_init_15 = false;
                            uint _e222 = q;
                            if (_e222 < K) {
                            } else {
                                break;
                            }
                            {
                                uint _e225 = q;
                                float _e227 = slot_target(_e214, _e225, K);
                                metal::float3 _e228 = total;
                                uint _e229 = q;
                                float _e231 = slot_target(_e228, _e229, K);
                                if (_e227 > 0.0) {
                                    uint _e236 = q;
                                    float _e238 = threshold.inner[_e236];
                                    local_5 = _e231 > _e238;
                                } else {
                                    local_5 = false;
                                }
                                bool _e241 = local_5;
                                if (_e241) {
                                    uint _e242 = q;
                                    slot_light.inner[_e242] = li_10;
                                    uint _e244 = q;
                                    slot_u.inner[_e244] = u_5;
                                    uint _e246 = q;
                                    slot_p.inner[_e246] = _e227;
                                    uint _e248 = q;
                                    slot_cells.inner[_e248] = _e201;
                                    uint _e250 = q;
                                    float _e252 = next_threshold(_e231, hc);
                                    threshold.inner[_e250] = _e252;
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
            uint _e270 = view.width;
            uint _e274 = next_index((gid.y * _e270) + gid.x, view, reuse);
            reuse_pixels[_e274].surface.m = 0.0;
        }
        return;
    }
    uint _e282 = view.width;
    uint pixel_1 = (gid.y * _e282) + gid.x;
    metal::float3 _e287 = n;
    metal::float3 _e290 = view.eye;
    uint _e294 = reuse_stream(_e137, 0u);
    uint _e295 = reuse_domains(x_20, _e287, metal::length(_e290 - x_20), _e294, doms, view, reuse, reuse_pixels, _buffer_sizes);
    if (_e295 > 0u) {
        bool _e302 = doms.inner[0].temporal;
        local_6 = _e302;
    } else {
        local_6 = false;
    }
    bool own_history = local_6;
    uint first_1 = own_history ? 1u : 0u;
    float _e310 = doms.inner[0].c;
    float confidence = 1.0 + (own_history ? _e310 : 0.0);
    uint _e316 = reuse_stream(_e137, 1u);
    hs = _e316;
    uint2 loop_bound_19 = uint2(4294967295u);
    bool loop_init_16 = true;
    while(true) {
        if (metal::all(loop_bound_19 == uint2(0u))) { break; }
        loop_bound_19 -= uint2(loop_bound_19.y == 0u, 1u);
        if (!loop_init_16) {
            uint _e351 = q_1;
            q_1 = _e351 + 1u;
        }
        loop_init_16 = false;
        uint _e322 = q_1;
        if (_e322 < K) {
        } else {
            break;
        }
        {
            uint _e325 = q_1;
            uint _e327 = q_1;
            uint _e329 = slot_light.inner[_e327];
            uint _e330 = q_1;
            uint _e332 = slot_cells.inner[_e330];
            metal::uint2 _e333 = sample_key(_e329, _e332, lights, _buffer_sizes);
            fresh_keys.inner[_e325] = _e333;
            uint _e334 = q_1;
            uint _e338 = reuse.visibility;
            if (_e338 == 1u) {
                uint _e343 = q_1;
                float _e345 = slot_p.inner[_e343];
                local_7 = _e345 > 0.0;
            } else {
                local_7 = false;
            }
            bool _e349 = local_7;
            fresh_held.inner[_e334] = _e349;
        }
    }
    type_25 _e353 = fresh_keys;
    type_26 _e354 = fresh_held;
    type_17 _e355 = first_holders(_e353, _e354);
    uint2 loop_bound_20 = uint2(4294967295u);
    bool loop_init_17 = true;
    while(true) {
        if (metal::all(loop_bound_20 == uint2(0u))) { break; }
        loop_bound_20 -= uint2(loop_bound_20.y == 0u, 1u);
        if (!loop_init_17) {
            uint _e390 = q_2;
            q_2 = _e390 + 1u;
        }
        loop_init_17 = false;
        uint _e359 = q_2;
        if (_e359 < K) {
        } else {
            break;
        }
        {
            uint _e362 = q_2;
            uint _e364 = q_2;
            if (_e355.inner[_e362] == _e364) {
                uint _e366 = q_2;
                uint _e369 = q_2;
                uint _e371 = slot_light.inner[_e369];
                GpuLight _e373 = lights[_e371];
                uint _e374 = q_2;
                uint _e376 = slot_cells.inner[_e374];
                metal::float3 _e377 = n;
                bool _e378 = sample_reaches(_e373, _e376, x_20, _e377, eps_5, geo_nodes, geo_tris, _buffer_sizes);
                fresh_visible.inner[_e366] = _e378;
            } else {
                uint _e379 = q_2;
                if (_e355.inner[_e379] < K) {
                    uint _e383 = q_2;
                    uint _e385 = q_2;
                    bool _e388 = fresh_visible.inner[_e355.inner[_e385]];
                    fresh_visible.inner[_e383] = _e388;
                }
            }
        }
    }
    uint2 loop_bound_21 = uint2(4294967295u);
    bool loop_init_18 = true;
    while(true) {
        if (metal::all(loop_bound_21 == uint2(0u))) { break; }
        loop_bound_21 -= uint2(loop_bound_21.y == 0u, 1u);
        if (!loop_init_18) {
            uint _e439 = q_3;
            q_3 = _e439 + 1u;
        }
        loop_init_18 = false;
        uint _e395 = q_3;
        if (_e395 < K) {
        } else {
            break;
        }
        {
            uint _e398 = q_3;
            fresh_before.inner[_e398] = true;
            uint _e401 = q_3;
            uint _e403 = q_3;
            if (_e355.inner[_e401] == _e403) {
                uint _e407 = q_3;
                bool _e409 = fresh_visible.inner[_e407];
                local_8 = _e409;
            } else {
                local_8 = false;
            }
            bool _e411 = local_8;
            if (_e411) {
                local_9 = own_history;
            } else {
                local_9 = false;
            }
            bool _e415 = local_9;
            if (_e415) {
                uint _e416 = q_3;
                uint _e418 = q_3;
                uint _e420 = slot_light.inner[_e418];
                uint _e421 = q_3;
                uint _e423 = slot_cells.inner[_e421];
                Domain _e425 = doms.inner[0];
                metal::float3 _e426 = n;
                bool _e427 = reached_before(_e420, _e423, _e425, x_20, _e426, geo_nodes, geo_tris, view, lights, reuse, lights_prev, reuse_pixels, _buffer_sizes);
                fresh_before.inner[_e416] = _e427;
            } else {
                uint _e428 = q_3;
                if (_e355.inner[_e428] < K) {
                    uint _e432 = q_3;
                    uint _e434 = q_3;
                    bool _e437 = fresh_before.inner[_e355.inner[_e434]];
                    fresh_before.inner[_e432] = _e437;
                }
            }
        }
    }
    uint2 loop_bound_22 = uint2(4294967295u);
    bool loop_init_19 = true;
    while(true) {
        if (metal::all(loop_bound_22 == uint2(0u))) { break; }
        loop_bound_22 -= uint2(loop_bound_22.y == 0u, 1u);
        if (!loop_init_19) {
            uint _e513 = q_4;
            q_4 = _e513 + 1u;
        }
        loop_init_19 = false;
        uint _e445 = q_4;
        if (_e445 < K) {
        } else {
            break;
        }
        {
            uint _e448 = q_4;
            float _e450 = slot_p.inner[_e448];
            if (_e450 > 0.0) {
                uint _e457 = reuse.visibility;
                if (!((_e457 == 0u))) {
                    uint _e463 = q_4;
                    bool _e465 = fresh_visible.inner[_e463];
                    local_11 = _e465;
                } else {
                    local_11 = true;
                }
                bool _e467 = local_11;
                local_10 = _e467;
            } else {
                local_10 = false;
            }
            bool fresh = local_10;
            uint _e470 = q_4;
            uint _e472 = q_4;
            uint _e473 = q_4;
            uint _e475 = slot_light.inner[_e473];
            uint _e476 = q_4;
            uint _e478 = slot_cells.inner[_e476];
            metal::float3 _e479 = total;
            uint _e480 = q_4;
            float _e482 = slot_target(_e479, _e480, K);
            uint _e488 = q_4;
            bool _e490 = fresh_before.inner[_e488];
            metal::float3 _e492 = n;
            Material _e493 = m;
            ReuseSlot _e494 = gris_combine(_e472, ReuseSlot {_e475, _e478, fresh ? _e482 : 0.0}, true, 1.0, _e490, 0u, first_1, x_20, _e492, _e493, doms, hs, geo_nodes, geo_tris, view, lights, reuse, lights_prev, reuse_pixels, _buffer_sizes);
            kept.inner[_e470] = _e494;
            uint _e495 = q_4;
            uint _e497 = q_4;
            ReuseSlot _e499 = kept.inner[_e497];
            fin.inner[_e495] = _e499;
            if (_e295 > first_1) {
                uint _e501 = q_4;
                uint _e503 = q_4;
                uint _e504 = q_4;
                ReuseSlot _e506 = kept.inner[_e504];
                metal::float3 _e509 = n;
                Material _e510 = m;
                ReuseSlot _e511 = gris_combine(_e503, _e506, false, confidence, true, first_1, _e295, x_20, _e509, _e510, doms, hs, geo_nodes, geo_tris, view, lights, reuse, lights_prev, reuse_pixels, _buffer_sizes);
                fin.inner[_e501] = _e511;
            }
        }
    }
    uint2 loop_bound_23 = uint2(4294967295u);
    bool loop_init_20 = true;
    while(true) {
        if (metal::all(loop_bound_23 == uint2(0u))) { break; }
        loop_bound_23 -= uint2(loop_bound_23.y == 0u, 1u);
        if (!loop_init_20) {
            uint _e542 = k;
            k = _e542 + 1u;
        }
        loop_init_20 = false;
        uint _e519 = k;
        if (_e519 < K) {
        } else {
            break;
        }
        {
            uint _e522 = k;
            uint _e524 = k;
            uint _e527 = fin.inner[_e524].light;
            uint _e528 = k;
            uint _e531 = fin.inner[_e528].u;
            metal::uint2 _e532 = sample_key(_e527, _e531, lights, _buffer_sizes);
            keys.inner[_e522] = _e532;
            uint _e533 = k;
            uint _e535 = k;
            float _e538 = fin.inner[_e535].w;
            held.inner[_e533] = _e538 > 0.0;
        }
    }
    type_25 _e544 = keys;
    type_26 _e545 = held;
    type_17 _e546 = first_holders(_e544, _e545);
    uint2 loop_bound_24 = uint2(4294967295u);
    bool loop_init_21 = true;
    while(true) {
        if (metal::all(loop_bound_24 == uint2(0u))) { break; }
        loop_bound_24 -= uint2(loop_bound_24.y == 0u, 1u);
        if (!loop_init_21) {
            uint _e678 = k_1;
            k_1 = _e678 + 1u;
        }
        loop_init_21 = false;
        uint _e550 = k_1;
        if (_e550 < K) {
        } else {
            break;
        }
        {
            uint _e553 = k_1;
            uint _e555 = k_1;
            if (_e546.inner[_e553] != _e555) {
                continue;
            }
            w = metal::float3(0.0);
            uint _e560 = k_1;
            j_1 = _e560;
            uint2 loop_bound_25 = uint2(4294967295u);
            bool loop_init_22 = true;
            while(true) {
                if (metal::all(loop_bound_25 == uint2(0u))) { break; }
                loop_bound_25 -= uint2(loop_bound_25.y == 0u, 1u);
                if (!loop_init_22) {
                    uint _e580 = j_1;
                    j_1 = _e580 + 1u;
                }
                loop_init_22 = false;
                uint _e562 = j_1;
                if (_e562 < K) {
                } else {
                    break;
                }
                {
                    uint _e565 = j_1;
                    uint _e567 = k_1;
                    if (_e546.inner[_e565] == _e567) {
                        metal::float3 _e569 = w;
                        uint _e570 = j_1;
                        float _e573 = fin.inner[_e570].w;
                        uint _e574 = j_1;
                        metal::float3 _e576 = slot_share(_e574, K);
                        w = _e569 + (_e573 * _e576);
                    }
                }
            }
            known = false;
            seen = false;
            j_2 = 0u;
            uint2 loop_bound_26 = uint2(4294967295u);
            bool loop_init_23 = true;
            while(true) {
                if (metal::all(loop_bound_26 == uint2(0u))) { break; }
                loop_bound_26 -= uint2(loop_bound_26.y == 0u, 1u);
                if (!loop_init_23) {
                    uint _e617 = j_2;
                    j_2 = _e617 + 1u;
                }
                loop_init_23 = false;
                uint _e588 = j_2;
                if (_e588 < K) {
                    bool _e593 = known;
                    local_12 = !(_e593);
                } else {
                    local_12 = false;
                }
                bool _e596 = local_12;
                if (_e596) {
                } else {
                    break;
                }
                {
                    uint _e597 = j_2;
                    bool _e599 = fresh_held.inner[_e597];
                    if (_e599) {
                        uint _e602 = j_2;
                        metal::uint2 _e604 = fresh_keys.inner[_e602];
                        uint _e605 = k_1;
                        metal::uint2 _e607 = keys.inner[_e605];
                        local_13 = metal::all(_e604 == _e607);
                    } else {
                        local_13 = false;
                    }
                    bool _e611 = local_13;
                    if (_e611) {
                        known = true;
                        uint _e613 = j_2;
                        bool _e615 = fresh_visible.inner[_e613];
                        seen = _e615;
                    }
                }
            }
            shaded = Shaded {metal::float3(0.0), metal::float3(0.0), metal::float3(0.0)};
            bool _e627 = known;
            if (!(!(_e627))) {
                bool _e632 = seen;
                local_14 = _e632;
            } else {
                local_14 = true;
            }
            bool _e634 = local_14;
            if (_e634) {
                uint _e636 = k_1;
                uint _e639 = fin.inner[_e636].light;
                GpuLight _e641 = lights[_e639];
                uint _e642 = k_1;
                uint _e645 = fin.inner[_e642].u;
                metal::float3 _e646 = n;
                bool _e647 = known;
                Connection _e649 = sample_connection(_e641, _e645, x_20, _e646, eps_5, !(_e647), geo_nodes, geo_tris, _buffer_sizes);
                metal::float3 _e650 = n;
                Material _e651 = m;
                Shaded _e652 = shade_connection(_e649, x_20, _e650, _e651);
                shaded = _e652;
            }
            Shaded _e653 = t;
            Shaded _e654 = shaded;
            metal::float3 _e655 = w;
            Shaded _e656 = scaled(_e654, _e655);
            Shaded _e657 = add(_e653, _e656);
            t = _e657;
            uint _e658 = k_1;
            j_3 = _e658;
            uint2 loop_bound_27 = uint2(4294967295u);
            bool loop_init_24 = true;
            while(true) {
                if (metal::all(loop_bound_27 == uint2(0u))) { break; }
                loop_bound_27 -= uint2(loop_bound_27.y == 0u, 1u);
                if (!loop_init_24) {
                    uint _e675 = j_3;
                    j_3 = _e675 + 1u;
                }
                loop_init_24 = false;
                uint _e660 = j_3;
                if (_e660 < K) {
                } else {
                    break;
                }
                {
                    uint _e663 = j_3;
                    uint _e665 = k_1;
                    if (_e546.inner[_e663] == _e665) {
                        uint _e667 = j_3;
                        Shaded _e669 = shaded;
                        metal::float3 _e670 = output_of(_e669);
                        float _e671 = resample_target(_e670);
                        visible.inner[_e667] = _e671 > 0.0;
                    }
                }
            }
        }
    }
    uint2 loop_bound_28 = uint2(4294967295u);
    bool loop_init_25 = true;
    while(true) {
        if (metal::all(loop_bound_28 == uint2(0u))) { break; }
        loop_bound_28 -= uint2(loop_bound_28.y == 0u, 1u);
        if (!loop_init_25) {
            uint _e720 = q_5;
            q_5 = _e720 + 1u;
        }
        loop_init_25 = false;
        uint _e682 = q_5;
        if (_e682 < K) {
        } else {
            break;
        }
        {
            uint _e687 = reuse.visibility;
            if (!((_e687 == 0u))) {
                uint _e693 = q_5;
                bool _e695 = visible.inner[_e693];
                local_15 = _e695;
            } else {
                local_15 = true;
            }
            bool keep = local_15;
            uint _e699 = next_index(pixel_1, view, reuse);
            uint _e702 = q_5;
            uint _e704 = q_5;
            uint _e707 = kept.inner[_e704].light;
            uint _e708 = q_5;
            uint _e711 = kept.inner[_e708].u;
            uint _e712 = q_5;
            float _e715 = kept.inner[_e712].w;
            reuse_pixels[_e699].slots.inner[_e702] = ReuseSlot {_e707, _e711, keep ? _e715 : 0.0};
        }
    }
    uint _e723 = next_index(pixel_1, view, reuse);
    metal::float3 _e726 = n;
    Material _e727 = m;
    float _e730 = reuse.max_confidence;
    ReuseSurface _e732 = reuse_surface(x_20, _e726, _e727, metal::min(confidence, _e730));
    reuse_pixels[_e723].surface = _e732;
    metal::float3 _e735 = t.diffuse;
    metal::float3 _e737 = t.specular;
    uint _e739 = count;
    out_tex.write(metal::float4(_e735 + _e737, static_cast<float>(_e739)), metal::uint2(texel_1));
    return;
}
