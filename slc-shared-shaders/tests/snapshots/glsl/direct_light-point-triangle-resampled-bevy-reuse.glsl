#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

struct GpuLight {
    vec3 p0_;
    uint kind;
    vec3 p1_;
    float a;
    vec3 p2_;
    float b;
    vec3 intensity;
    uint ies_base;
};
struct GpuLightCone {
    vec3 center;
    float radius;
    vec3 axis;
    float cos_o;
    float phi;
    float cos_e;
    uint bvh_leaf;
    uint pad;
};
struct GpuGeoNode {
    vec3 bmin;
    uint first;
    vec3 bmax;
    uint count;
};
struct GpuTriangle {
    vec3 v0_;
    uint material;
    vec3 v1_;
    uint light;
    vec3 v2_;
    uint pad;
};
struct ReuseParams {
    vec4 c0_;
    vec4 c1_;
    vec4 c2_;
    vec4 c3_;
    vec3 prev_eye;
    float max_confidence;
    uint has_history;
    float radius;
    uint visibility;
    uint parity;
    vec3 moved_min;
    uint moved;
    vec3 moved_max;
    uint pad;
};
struct ReuseSurface {
    vec3 x;
    float m;
    vec3 n;
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
    vec4 c0_;
    vec4 c1_;
    vec4 c2_;
    vec4 c3_;
    vec3 eye;
    uint width;
    uint height;
    float shadow_offset;
    uint seed;
    uint frame;
    vec3 f0_d;
    float f90_d;
};
struct BshNode {
    vec3 center;
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
struct ReusePixel {
    ReuseSurface surface;
    ReuseSlot slots[8];
};
struct Connection {
    vec3 e;
    vec3 y;
    float cos_x;
};
struct WorkgroupBox {
    vec3 lo;
    vec3 hi;
};
struct TileWalk {
    vec3 lo;
    vec3 hi;
    float w;
    uint total;
};
struct Shaded {
    vec3 e;
    vec3 diffuse;
    vec3 specular;
};
struct Material {
    vec3 base;
    float metallic;
    float alpha;
    vec3 v;
    float roughness;
    float reflectance;
};
struct Domain {
    uint pixel;
    vec3 x;
    vec3 n;
    Material m;
    float c;
    bool temporal;
};
const uint LIGHT_POINT = 0u;
const uint LIGHT_SPOT = 1u;
const uint LIGHT_IES = 2u;
const uint LIGHT_TRIANGLE = 3u;
const uint LIGHT_VPL = 4u;
const uint NO_LIGHT = 4294967295u;
const uint GRID_HEADER = 32u;
const uint GRID_LEVELS_MAX = 8u;
const uint GRIDS_MAX = 3u;
const uint GRID_SORT_MOVES = 1024u;
const uint GRID_SORT_MAX = 1024u;
const uint COUNT_TILES = 0u;
const uint COUNT_GROUP_TESTS = 1u;
const uint COUNT_CLUSTER_TESTS = 2u;
const uint COUNT_SPHERE_TESTS = 3u;
const uint COUNT_TESTED = 4u;
const uint COUNT_KEPT = 5u;
const uint COUNT_PIXELS = 6u;
const uint COUNT_FIELDS = 7u;
const uint DIRECT_COUNT_PIXELS = 0u;
const uint DIRECT_COUNT_CANDIDATES = 1u;
const uint DIRECT_COUNT_EVALUATIONS = 2u;
const uint DIRECT_COUNT_RAYS = 3u;
const uint DIRECT_COUNT_NODES = 4u;
const uint DIRECT_COUNT_FIELDS = 5u;
const uint MAP_CAMERA = 0u;
const uint MAP_PERSPECTIVE = 1u;
const uint MAP_ORTHOGRAPHIC = 2u;
const float XI_STEP = 5.9604645e-8;
const uint XI_ROTATED = 2147483648u;
const uint XI_BITS_SHIFT = 26u;
const uint XI_INDEX_MASK = 67108863u;
const uint PICK_STREAM = 2654435769u;
const float TWO_PI = 6.2831855;
const float UNRANGED = 1e38;
const float CULL_RADIUS_SCALE = 1.000001;
const float SPHERE_PAD = 4.7683716e-7;
const float SPHERE_HUGE = 3.4028235e38;
const float SPHERE_PAD_ABS = 1e-18;
const uint CLUSTER = 64u;
const uint GROUP_SIDE = 8u;
const float INV_PI = 0.31830987;
const float MIN_D2_ = 1e-12;
const float MAX_INTENSITY = 7.2057594e16;
const uint BSH_NONE = 4294967295u;
const uint BSH_TAIL = 2147483648u;
const uint BSH_TAIL_BINS = 1024u;
const uint BSH_TAIL_MAX = 64u;
const uint RESERVOIR_FULL = 4294967295u;
const float REUSE_TRUST_SCALE = 64.0;
const float GGX_ALPHA_MIN = 0.001;
const float RANGE_SCALE_MAX = 64.0;
const uint LIGHT_BVH_LEAF = 4294967295u;
const float ONE_MINUS_EPSILON = 0.99999994;
const float F32_MAX = 3.4028235e38;
const float DEPTH_NONE = 1e30;
const float DEPTH_SIGMA = 0.05;
const float COVER_WEIGHT = 0.1;
const uint ROULETTE_DEPTH = 2u;
const float TEMPORAL_MAX_HISTORY = 32.0;
const float TEMPORAL_DEPTH_TOLERANCE = 0.01;
const float TEMPORAL_MOTION_DEPTH_TOLERANCE = 0.05;
const float TEMPORAL_NORMAL_COS = 0.9;
const float TEMPORAL_MIN_MOMENTS = 8.0;
const float TEMPORAL_CHANGED_HISTORY = 1.0;
const float TEMPORAL_CHANGE_LOW = 4.0;
const float TEMPORAL_CHANGE_HIGH = 8.0;
const float TEMPORAL_MIN_WEIGHT = 0.01;
const uint K = 8u;
const uint BSH = 0u;
const uint BSH_TILE_DEPTH = 8u;
const uint BSH_TILE_SUBTREES = 256u;
const uint TILE_THREADS = 64u;
const uint BOX_THREADS = 64u;
const uint TILE_LIST = 1024u;
const uint DOMAINS = 3u;

layout(std430) readonly buffer type_7_block_0Compute { GpuGeoNode _group_1_binding_6_cs[]; };

layout(std430) readonly buffer type_8_block_1Compute { GpuTriangle _group_1_binding_7_cs[]; };

layout(std140) uniform ViewParams_block_2Compute { ViewParams _group_0_binding_0_cs; };

uniform sampler2D _group_0_binding_1_cs;

uniform sampler2D _group_0_binding_2_cs;

layout(rgba16f) writeonly uniform image2D _group_0_binding_3_cs;

uniform sampler2D _group_0_binding_4_cs;

uniform sampler2D _group_0_binding_5_cs;

layout(std430) readonly buffer type_12_block_3Compute { GpuLight _group_1_binding_1_cs[]; };

layout(std430) readonly buffer type_4_block_4Compute { float _group_1_binding_2_cs[]; };

layout(std430) readonly buffer type_4_block_5Compute { float _group_1_binding_3_cs[]; };

layout(std430) readonly buffer type_13_block_6Compute { BshNode _group_1_binding_4_cs[]; };

layout(std430) readonly buffer type_14_block_7Compute { GpuLightCone _group_1_binding_5_cs[]; };

layout(std140) uniform ReuseParams_block_8Compute { ReuseParams _group_0_binding_7_cs; };

layout(std430) readonly buffer type_12_block_9Compute { GpuLight _group_1_binding_8_cs[]; };

layout(std430) buffer type_16_block_10Compute { ReusePixel _group_1_binding_9_cs[]; };

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

shared WorkgroupBox wg_box;

shared uint tile_list[1024];

shared uint subtree_at[256];

shared uint tile_scale;

shared uint tile_total;


float to_f32_(uint u) {
    return float(u);
}

uint mul_lo_u32_(uint a, uint b) {
    return (a * b);
}

uint add_wrap_u32_(uint a_1, uint b_1) {
    return (a_1 + b_1);
}

float f32_from_bits(uint u_1) {
    return uintBitsToFloat(u_1);
}

float xi_from_bits(uint bits) {
    float _e3 = to_f32_((bits >> 8u));
    return (_e3 * XI_STEP);
}

uint pcg_hash(uint x) {
    uint _e2 = mul_lo_u32_(x, 747796405u);
    uint _e4 = add_wrap_u32_(_e2, 2891336453u);
    uint _e12 = mul_lo_u32_(((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4), 277803737u);
    return ((_e12 >> 22u) ^ _e12);
}

uint point_stream(uint seed, uint point, uint frame) {
    uint _e3 = pcg_hash(frame);
    uint _e5 = pcg_hash((point ^ _e3));
    uint _e7 = pcg_hash((seed ^ _e5));
    return _e7;
}

uint pick_stream(uint stream) {
    uint _e3 = pcg_hash((stream ^ PICK_STREAM));
    return _e3;
}

uint reuse_stream(uint stream_1, uint which) {
    uint _e2 = pick_stream(stream_1);
    uint _e6 = pcg_hash(((_e2 + 1u) + which));
    return _e6;
}

float slc_weight(float rt2_, float d2_) {
    if ((d2_ <= rt2_)) {
        return 1.0;
    }
    return (d2_ / rt2_);
}

bool slc_keep(float r2_, float d2_1) {
    return (d2_1 < r2_);
}

bool sphere_contains_point(vec3 c, float r_1, vec3 x_1) {
    vec3 v_5 = (x_1 - c);
    return (dot(v_5, v_5) <= (r_1 * r_1));
}

bool sphere_overlaps_aabb(vec3 c_1, float r_2, vec3 bmin, vec3 bmax) {
    vec3 q_9 = clamp(c_1, bmin, bmax);
    vec3 v_6 = (q_9 - c_1);
    return (dot(v_6, v_6) <= (r_2 * r_2));
}

float inverse_square(float d2_2) {
    return (1.0 / max(d2_2, MIN_D2_));
}

float connection_factor(float cos_x, float d2_3, float rt2_1, float w_1) {
    float _e4 = inverse_square(d2_3);
    float _e6 = slc_weight(rt2_1, d2_3);
    return (((cos_x * _e4) * _e6) * w_1);
}

float connection_cosine(vec3 x_2, vec3 y, vec3 n_1, vec3 ng, float r2_1) {
    bool local_16 = false;
    bool local_17 = false;
    vec3 v_7 = (x_2 - y);
    float d2_6 = dot(v_7, v_7);
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
    vec3 w_12 = (v_7 / vec3(sqrt(d2_6)));
    float cos_x_1 = -(dot(n_1, w_12));
    if (!(!((cos_x_1 > 0.0)))) {
        local_17 = !((dot(ng, w_12) < 0.0));
    } else {
        local_17 = true;
    }
    bool _e34 = local_17;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float triangle_lobe(vec3 n_2, float area, vec3 w_2) {
    return (area * max(dot(n_2, w_2), 0.0));
}

vec3 triangle_sample(vec3 a_2, vec3 b_2, vec3 c_2, float u1_, float u2_) {
    float su = sqrt(u1_);
    float b0_ = (1.0 - su);
    float b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_2 * ((1.0 - b0_) - b1_)));
}

float bsh_scaled_radius(BshNode node, float scale) {
    if ((scale == 1.0)) {
        return node.radius;
    }
    if ((node.child == BSH_NONE)) {
        return (node.extent + (scale * (node.radius - node.extent)));
    }
    return (node.radius * scale);
}

float bsh_range_bound(BshNode node_1) {
    if ((node_1.child == BSH_NONE)) {
        return (node_1.radius - node_1.extent);
    }
    float _e8 = f32_from_bits(node_1.light);
    return _e8;
}

float bsh_reach_bound(BshNode node_2, float w_3) {
    float _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_3 * 1.001) * _e5));
}

bool weighted_replace(float w_4, float w_sum, float u_2) {
    return ((u_2 * w_sum) < w_4);
}

float weighted_threshold(float w_sum_1, float u_3) {
    return (w_sum_1 / (1.0 - u_3));
}

float resample_target(vec3 c_3) {
    return (((c_3.x + c_3.y) + c_3.z) * 0.33333334);
}

float slot_target(vec3 c_4, uint slot, uint k_2) {
    if ((k_2 < 3u)) {
        float _e5 = resample_target(c_4);
        return _e5;
    }
    uint j_7 = (slot % 3u);
    if ((j_7 == 0u)) {
        return c_4.x;
    }
    if ((j_7 == 1u)) {
        return c_4.y;
    }
    return c_4.z;
}

vec3 slot_share(uint slot_1, uint k_3) {
    if ((k_3 < 3u)) {
        float _e4 = to_f32_(k_3);
        float w_13 = (1.0 / _e4);
        return vec3(w_13, w_13, w_13);
    }
    uint j_8 = (slot_1 % 3u);
    float _e15 = to_f32_((((k_3 + 2u) - j_8) / 3u));
    float w_14 = (1.0 / _e15);
    if ((j_8 == 0u)) {
        return vec3(w_14, 0.0, 0.0);
    }
    if ((j_8 == 1u)) {
        return vec3(0.0, w_14, 0.0);
    }
    return vec3(0.0, 0.0, w_14);
}

float grid_coordinate(uint bits_1) {
    float _e3 = to_f32_((bits_1 >> 16u));
    return ((_e3 + 0.5) / 65536.0);
}

uint grid_cells(uint h1_, uint h2_) {
    return ((h1_ & 4294901760u) | (h2_ >> 16u));
}

vec2 disk_offset(float r_3, float u1_1, float u2_1) {
    float a_9 = (TWO_PI * u2_1);
    return (vec2(cos(a_9), sin(a_9)) * (r_3 * sqrt(u1_1)));
}

float gris_weight(float own, float all_, float p_hat, float w_5) {
    if (!((all_ > 0.0))) {
        return 0.0;
    }
    return (((own / all_) * p_hat) * w_5);
}

float reuse_trust(vec3 h_1, vec3 t_1) {
    float d2_7 = dot(h_1, h_1);
    if (!((d2_7 > 0.0))) {
        return 1.0;
    }
    vec3 c_11 = (h_1 - t_1);
    return (d2_7 / (d2_7 + (REUSE_TRUST_SCALE * dot(c_11, c_11))));
}

float gris_contribution_weight(float w_sum_2, float p_hat_1) {
    if (!((p_hat_1 > 0.0))) {
        return 0.0;
    }
    return (w_sum_2 / p_hat_1);
}

float ggx_d(float cos_h, float sin2_h, float alpha) {
    if ((cos_h <= 0.0)) {
        return 0.0;
    }
    float a2_ = (alpha * alpha);
    float t_6 = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t_6 * t_6));
}

float smith_root(float cos_, float alpha_1) {
    float a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1.0 - a2_1)) + a2_1));
}

float smith_visibility(float n_l, float n_v, float alpha_2) {
    bool local_18 = false;
    if (!((n_l <= 0.0))) {
        local_18 = (n_v <= 0.0);
    } else {
        local_18 = true;
    }
    bool _e11 = local_18;
    if (_e11) {
        return 0.0;
    }
    float _e13 = smith_root(n_v, alpha_2);
    float _e15 = smith_root(n_l, alpha_2);
    return (0.5 / ((n_l * _e13) + (n_v * _e15)));
}

vec3 fresnel_schlick(vec3 f0_, float f90_, float v_h) {
    float c_12 = clamp((1.0 - v_h), 0.0, 1.0);
    float c2_1 = (c_12 * c_12);
    return (f0_ + ((vec3(f90_, f90_, f90_) - f0_) * ((c2_1 * c2_1) * c_12)));
}

vec3 specular_fresnel(vec3 base, float metallic, vec3 f0_d, float f90_d, float v_h_1) {
    vec3 _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    vec3 _e10 = fresnel_schlick(base, 1.0, v_h_1);
    return ((_e5 * (1.0 - metallic)) + (_e10 * metallic));
}

bool has_specular(float metallic_1, vec3 f0_d_1, float f90_d_1) {
    bool local_19 = false;
    bool local_20 = false;
    if (!((metallic_1 > 0.0))) {
        local_19 = (f90_d_1 > 0.0);
    } else {
        local_19 = true;
    }
    bool _e11 = local_19;
    if (!(_e11)) {
        local_20 = (max(max(f0_d_1.x, f0_d_1.y), f0_d_1.z) > 0.0);
    } else {
        local_20 = true;
    }
    bool _e23 = local_20;
    return _e23;
}

float channel_mean(vec3 c_5) {
    return (((c_5.x + c_5.y) + c_5.z) * 0.33333334);
}

vec4 receiver_lobe(vec3 base_1, float metallic_2, vec3 f0_d_2, float f90_d_2, float alpha_3, float n_v_1) {
    bool local_21 = false;
    vec3 _e10 = fresnel_schlick(f0_d_2, f90_d_2, n_v_1);
    float _e16 = channel_mean((((vec3(1.0, 1.0, 1.0) - _e10) * base_1) * (1.0 - metallic_2)));
    if (!((n_v_1 <= 0.0))) {
        bool _e22 = has_specular(metallic_2, f0_d_2, f90_d_2);
        local_21 = !(_e22);
    } else {
        local_21 = true;
    }
    bool _e25 = local_21;
    if (_e25) {
        return vec4(_e16, 0.0, alpha_3, n_v_1);
    }
    vec3 _e28 = specular_fresnel(base_1, metallic_2, f0_d_2, f90_d_2, n_v_1);
    float _e29 = channel_mean(_e28);
    return vec4(_e16, _e29, alpha_3, n_v_1);
}

float specular_peak_factor(vec4 lobe_1) {
    float _e6 = smith_root(lobe_1.w, lobe_1.z);
    return ((lobe_1.y * 0.5) / (_e6 + max(lobe_1.w, 0.0)));
}

float receiver_peak(vec4 lobe_2) {
    float _e2 = specular_peak_factor(lobe_2);
    return (lobe_2.x + (_e2 / (lobe_2.z * lobe_2.z)));
}

float range_scale(vec4 lobe_3) {
    if ((lobe_3.y <= 0.0)) {
        return 1.0;
    }
    float _e5 = receiver_peak(lobe_3);
    return clamp(_e5, 1.0, RANGE_SCALE_MAX);
}

vec4 range_lobe(vec4 lobe_4) {
    if ((lobe_4.y <= 0.0)) {
        return vec4(1.0, 0.0, 1.0, 1.0);
    }
    float _e10 = specular_peak_factor(lobe_4);
    float _e14 = range_scale(lobe_4);
    return vec4(lobe_4.x, _e10, (lobe_4.z * lobe_4.z), sqrt(_e14));
}

vec3 mirror_dir(vec3 n_3, vec3 v) {
    return ((n_3 * (2.0 * dot(n_3, v))) - v);
}

float bevy_alpha(float perceptual) {
    float r_11 = clamp(perceptual, 0.089, 1.0);
    return (r_11 * r_11);
}

float bevy_f0_(float reflectance) {
    return ((0.16 * reflectance) * reflectance);
}

float bevy_dfg(float r_4, float n_v_2) {
    float rx = (1.0 - r_4);
    float a004_ = ((min((rx * rx), exp2((-9.28 * n_v_2))) * rx) + (0.0425 - (0.0275 * r_4)));
    float x_18 = max(((1.04 - (0.572 * r_4)) - (1.04 * a004_)), 5e-5);
    float y_1 = max((((0.022 * r_4) - 0.04) + (1.04 * a004_)), 5e-5);
    return (x_18 + y_1);
}

vec3 bevy_brdf(vec3 base_2, float metallic_3, float r_5, float reflectance_1, vec3 n_4, vec3 v_1, vec3 l) {
    float n_l_1 = clamp(dot(n_4, l), 0.0, 1.0);
    if ((n_l_1 <= 0.0)) {
        return vec3(0.0, 0.0, 0.0);
    }
    float _e15 = bevy_alpha(r_5);
    float n_v_3 = max(dot(n_4, v_1), 0.0001);
    vec3 h_4 = normalize((l + v_1));
    float n_h = clamp(dot(n_4, h_4), 0.0, 1.0);
    float l_h = clamp(dot(l, h_4), 0.0, 1.0);
    float f90_d_3 = (0.5 + (((2.0 * _e15) * l_h) * l_h));
    vec3 _e35 = fresnel_schlick(vec3(1.0, 1.0, 1.0), f90_d_3, n_l_1);
    vec3 _e41 = fresnel_schlick(vec3(1.0, 1.0, 1.0), f90_d_3, n_v_3);
    float burley = ((_e35.x * _e41.x) * INV_PI);
    float _e46 = bevy_f0_(reflectance_1);
    vec3 f0_1 = ((vec3(_e46, _e46, _e46) * (1.0 - metallic_3)) + (base_2 * metallic_3));
    float f90_1 = clamp((((f0_1.x + f0_1.y) + f0_1.z) * 16.5), 0.0, 1.0);
    float _e64 = ggx_d(n_h, (1.0 - (n_h * n_h)), _e15);
    float _e65 = smith_visibility(n_l_1, n_v_3, _e15);
    float _e70 = bevy_dfg(r_5, n_v_3);
    vec3 comp = (vec3(1.0, 1.0, 1.0) + (f0_1 * ((1.0 / _e70) - 1.0)));
    vec3 _e77 = fresnel_schlick(f0_1, f90_1, l_h);
    vec3 spec = ((_e77 * comp) * (_e64 * _e65));
    return ((base_2 * ((1.0 - metallic_3) * burley)) + spec);
}

float cone_cos_of(vec3 v_2, float d2_4, float a_3, vec3 d) {
    bool local_22 = false;
    bool local_23 = false;
    float vd = dot(v_2, d);
    float h2_1 = (d2_4 - (a_3 * a_3));
    if (!((h2_1 <= 0.0))) {
        if ((vd >= 0.0)) {
            local_23 = ((vd * vd) >= h2_1);
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
    vec3 c_13 = cross(v_2, d);
    return min((((vd * sqrt(h2_1)) + (sqrt(dot(c_13, c_13)) * a_3)) / d2_4), 1.0);
}

float cone_cos_toward(vec3 center, float radius, vec3 p, vec3 d_1) {
    vec3 v_8 = (center - p);
    float _e6 = cone_cos_of(v_8, dot(v_8, v_8), radius, d_1);
    return _e6;
}

float range_scale_at(vec4 rl, float cos_t) {
    float t_7 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_7 * t_7))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(vec4 rl_1, vec3 center_1, float radius_1, vec3 p_1, vec3 r_6) {
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_6);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

float shadow_margin(float len) {
    return (0.0001 * len);
}

float ray_inverse(float x_3) {
    return (1.0 / ((abs(x_3) < 1e-30) ? 1e-30 : x_3));
}

vec3 ray_inverse3_(vec3 d_2) {
    float _e2 = ray_inverse(d_2.x);
    float _e4 = ray_inverse(d_2.y);
    float _e6 = ray_inverse(d_2.z);
    return vec3(_e2, _e4, _e6);
}

float ray_aabb(vec3 o, vec3 inv_d, vec3 bmin_1, vec3 bmax_1, float t_max) {
    vec3 t0_ = ((bmin_1 - o) * inv_d);
    vec3 t1_ = ((bmax_1 - o) * inv_d);
    vec3 lo_3 = min(t0_, t1_);
    vec3 hi_3 = max(t0_, t1_);
    float t_in = max(max(lo_3.x, lo_3.y), max(lo_3.z, 0.0));
    float t_out = min(min(hi_3.x, hi_3.y), min(hi_3.z, t_max));
    if ((t_in <= t_out)) {
        return t_in;
    }
    return -1.0;
}

vec3 triangle_normal(vec3 a_4, vec3 b_3, vec3 c_6) {
    bool local_24 = false;
    vec3 n_17 = cross((b_3 - a_4), (c_6 - a_4));
    float l2_ = dot(n_17, n_17);
    if (!(!((l2_ > 0.0)))) {
        local_24 = !((l2_ < 3e38));
    } else {
        local_24 = true;
    }
    bool _e17 = local_24;
    if (_e17) {
        return vec3(0.0, 0.0, 0.0);
    }
    return (n_17 / vec3(sqrt(l2_)));
}

float ray_triangle(vec3 o_1, vec3 d_3, vec3 a_5, vec3 b_4, vec3 c_7, float t_min, float t_max_1) {
    bool local_25 = false;
    bool local_26 = false;
    bool local_27 = false;
    vec3 e1_ = (b_4 - a_5);
    vec3 e2_ = (c_7 - a_5);
    vec3 p_8 = cross(d_3, e2_);
    float det = dot(e1_, p_8);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv = (1.0 / det);
    vec3 s_12 = (o_1 - a_5);
    float u_4 = (dot(s_12, p_8) * inv);
    if (!((u_4 < 0.0))) {
        local_25 = (u_4 > 1.0);
    } else {
        local_25 = true;
    }
    bool _e28 = local_25;
    if (_e28) {
        return -1.0;
    }
    vec3 q_10 = cross(s_12, e1_);
    float v_9 = (dot(d_3, q_10) * inv);
    if (!((v_9 < 0.0))) {
        local_26 = ((u_4 + v_9) > 1.0);
    } else {
        local_26 = true;
    }
    bool _e42 = local_26;
    if (_e42) {
        return -1.0;
    }
    float t_8 = (dot(e2_, q_10) * inv);
    if ((t_8 > t_min)) {
        local_27 = (t_8 < t_max_1);
    } else {
        local_27 = false;
    }
    bool _e51 = local_27;
    if (_e51) {
        return t_8;
    }
    return -1.0;
}

vec3 reproject(vec4 c0_, vec4 c1_, vec4 c2_, vec4 c3_, vec3 p_2, float width, float height) {
    vec4 clip = ((((c0_ * p_2.x) + (c1_ * p_2.y)) + (c2_ * p_2.z)) + c3_);
    if ((clip.w <= 0.0)) {
        return vec3(-1.0, -1.0, 0.0);
    }
    float x_19 = (((((clip.x / clip.w) + 1.0) * 0.5) * width) - 0.5);
    float y_2 = ((((1.0 - (clip.y / clip.w)) * 0.5) * height) - 0.5);
    return vec3(x_19, y_2, clip.w);
}

bool history_matches(vec3 n_5, vec3 nh, vec3 p_3, float oh, float d_4) {
    bool local_28 = false;
    if ((abs((dot(nh, p_3) - oh)) <= (TEMPORAL_DEPTH_TOLERANCE * d_4))) {
        local_28 = (dot(n_5, nh) >= TEMPORAL_NORMAL_COS);
    } else {
        local_28 = false;
    }
    bool _e17 = local_28;
    return _e17;
}

vec3 light_intensity(GpuLight l_1, vec3 w_6) {
    switch(l_1.kind) {
        case 0u: {
            return l_1.intensity;
        }
        case 3u: {
            vec3 _e8 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
            float _e10 = triangle_lobe(_e8, l_1.a, w_6);
            return (l_1.intensity * _e10);
        }
        default: {
            return vec3(0.0);
        }
    }
}

vec3 light_point(GpuLight l_2, float u1_2, float u2_2) {
    if ((l_2.kind == LIGHT_TRIANGLE)) {
        vec3 _e9 = triangle_sample(l_2.p0_, l_2.p1_, l_2.p2_, u1_2, u2_2);
        return _e9;
    }
    return l_2.p0_;
}

GeoHit trace(vec3 o_2, vec3 d_5, float t_min_1, float t_max_2, bool any_hit) {
    GeoHit hit = GeoHit(0.0, 0u);
    uint stack[64] = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    uint sp = 0u;
    uint node_3 = 0u;
    uint i = 0u;
    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((uint(_group_1_binding_6_cs.length()) == 0u)) {
        GeoHit _e13 = hit;
        return _e13;
    }
    vec3 _e14 = ray_inverse3_(d_5);
    while(true) {
        uint _e21 = node_3;
        GpuGeoNode n_18 = _group_1_binding_6_cs[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_18.bmin, n_18.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_18.count > 0u)) {
                i = n_18.first;
                bool loop_init = true;
                while(true) {
                    if (!loop_init) {
                        uint _e58 = i;
                        i = (_e58 + 1u);
                    }
                    loop_init = false;
                    uint _e36 = i;
                    if ((_e36 < (n_18.first + n_18.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_9 = _group_1_binding_7_cs[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_5, t_9.v0_, t_9.v1_, t_9.v2_, t_min_1, _e49);
                        if ((_e50 > 0.0)) {
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
                if ((_e60 < 64u)) {
                    uint _e63 = sp;
                    stack[_e63] = (n_18.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_18.first;
                continue;
            }
        }
        uint _e72 = sp;
        if ((_e72 == 0u)) {
            break;
        }
        uint _e75 = sp;
        sp = (_e75 - 1u);
        uint _e78 = sp;
        uint _e80 = stack[_e78];
        node_3 = _e80;
    }
    GeoHit _e81 = hit;
    return _e81;
}

bool occluded(vec3 a_6, vec3 b_5) {
    vec3 dv = (b_5 - a_6);
    float len_1 = length(dv);
    if ((len_1 <= 0.0)) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    GeoHit _e12 = trace(a_6, (dv / vec3(len_1)), _e7, (len_1 - _e7), true);
    return (_e12.tri != NO_LIGHT);
}

BshNode bsh_node(uint nodes, uint i_1) {
    BshNode _e4 = _group_1_binding_4_cs[i_1];
    return _e4;
}

uint bsh_count(uint nodes_1) {
    return uint(_group_1_binding_4_cs.length());
}

uint bsh_first(uint nodes_2) {
    uint _e1 = bsh_count(nodes_2);
    if ((_e1 > 0u)) {
        return 0u;
    }
    return BSH_NONE;
}

float bsh_inner_scale(float a_7, vec3 v_3, float d2_5, vec3 r_7, vec4 rl_2) {
    float _e5 = cone_cos_of(v_3, d2_5, a_7, r_7);
    float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_4, vec3 x_4, vec3 r_8, vec4 rl_3) {
    bool local_29 = false;
    bool local_30 = false;
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_4);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, (node_4.radius * (rl_3.w * 1.0001)), x_4);
        local_29 = !(_e20);
    } else {
        local_29 = true;
    }
    bool _e23 = local_29;
    if (_e23) {
        return false;
    }
    vec3 v_10 = (x_4 - node_4.center);
    float d2_8 = dot(v_10, v_10);
    float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if ((d2_8 > (_e29 * _e29))) {
        return false;
    }
    if ((node_4.child == BSH_NONE)) {
        float _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_4, r_8);
        float _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_4);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_10), d2_8, r_8, rl_3);
    float s_c = (_e45 * 1.001);
    float _e50 = bsh_range_bound(node_4);
    float reach = (node_4.extent + (sqrt(s_c) * _e50));
    if ((d2_8 <= ((node_4.radius * node_4.radius) * s_c))) {
        local_30 = (d2_8 <= (reach * reach));
    } else {
        local_30 = false;
    }
    bool _e63 = local_30;
    return _e63;
}

bool bsh_reaches_box(BshNode node_5, vec3 lo, vec3 hi, float w_7) {
    bool _e13 = sphere_overlaps_aabb(node_5.center, (node_5.radius * (max(1.0, (w_7 * 1.0001)) * 1.0001)), lo, hi);
    return _e13;
}

uint bsh_subtree(uint nodes_3, uint s_1, uint depth) {
    uint i_2 = 0u;
    uint level = 0u;
    bool local_31 = false;
    uint _e3 = bsh_first(nodes_3);
    i_2 = _e3;
    while(true) {
        uint _e7 = level;
        if ((_e7 < depth)) {
            uint _e11 = i_2;
            local_31 = (_e11 != BSH_NONE);
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
            BshNode _e17 = bsh_node(nodes_3, _e16);
            uint _e18 = level;
            uint below = (depth - _e18);
            if ((_e17.child == BSH_NONE)) {
                if (((s_1 << (32u - below)) != 0u)) {
                    return BSH_NONE;
                }
                uint _e29 = i_2;
                return _e29;
            }
            if ((((s_1 >> (below - 1u)) & 1u) == 0u)) {
                i_2 = _e17.child;
            } else {
                BshNode _e39 = bsh_node(nodes_3, _e17.child);
                i_2 = _e39.next;
            }
            uint _e41 = level;
            level = (_e41 + 1u);
        }
    }
    uint _e44 = i_2;
    return _e44;
}

uint bsh_next_leaf_box(uint nodes_4, uint start_1, uint end, vec3 lo_1, vec3 hi_1, float w_8) {
    uint i_3 = 0u;
    i_3 = start_1;
    while(true) {
        uint _e7 = i_3;
        if ((_e7 != end)) {
        } else {
            break;
        }
        {
            uint _e9 = i_3;
            BshNode _e10 = bsh_node(nodes_4, _e9);
            bool _e11 = bsh_reaches_box(_e10, lo_1, hi_1, w_8);
            if (_e11) {
                if ((_e10.child == BSH_NONE)) {
                    if (((_e10.light & BSH_TAIL) == 0u)) {
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

float next_threshold(float sum, inout uint h_2) {
    uint _e2 = h_2;
    uint _e3 = pcg_hash(_e2);
    h_2 = _e3;
    uint _e4 = h_2;
    float _e5 = xi_from_bits(_e4);
    float _e6 = weighted_threshold(sum, _e5);
    return _e6;
}

Connection connect_record(GpuLight l_3, vec3 x_5, vec3 n_6, vec3 ng_1, float r2_2, float rt2_2, float w_res, float u1_3, float u2_3, float eps, bool trace_1) {
    Connection c_8 = Connection(vec3(0.0), vec3(0.0), 0.0);
    bool local_32 = false;
    bool local_33 = false;
    c_8.e = vec3(0.0);
    vec3 _e16 = light_point(l_3, u1_3, u2_3);
    c_8.y = _e16;
    vec3 _e19 = c_8.y;
    float _e20 = connection_cosine(x_5, _e19, n_6, ng_1, r2_2);
    c_8.cos_x = _e20;
    float _e22 = c_8.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            vec3 _e33 = c_8.y;
            bool _e34 = occluded((x_5 + (ng_1 * eps)), _e33);
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
    vec3 _e41 = c_8.y;
    vec3 v_11 = (x_5 - _e41);
    float d2_9 = dot(v_11, v_11);
    vec3 _e48 = light_intensity(l_3, (v_11 / vec3(sqrt(d2_9))));
    float _e50 = c_8.cos_x;
    float _e51 = connection_factor(_e50, d2_9, rt2_2, w_res);
    c_8.e = (_e48 * _e51);
    Connection _e53 = c_8;
    return _e53;
}

Connection connect_traced(uint li, vec3 x_6, vec3 n_7, vec3 ng_2, float s_2, float w_res_1, float u1_4, float u2_4, float eps_1, bool trace_2) {
    GpuLight _e12 = _group_1_binding_1_cs[li];
    float _e15 = _group_1_binding_3_cs[li];
    float _e19 = _group_1_binding_2_cs[li];
    Connection _e21 = connect_record(_e12, x_6, n_7, ng_2, (s_2 * _e15), (s_2 * _e19), w_res_1, u1_4, u2_4, eps_1, trace_2);
    return _e21;
}

float light_range_scale(uint li_1, vec3 x_7, vec3 r_9, vec4 rl_4) {
    GpuLightCone c_14 = _group_1_binding_5_cs[li_1];
    float _e9 = range_scale_toward(rl_4, c_14.center, c_14.radius, x_7, r_9);
    return _e9;
}

vec4 surface_at(ivec2 texel) {
    vec4 p_9 = texelFetch(_group_0_binding_1_cs, texel, 0);
    return ((p_9.w > 0.0) ? vec4(p_9.xyz, 1.0) : vec4(0.0));
}

WorkgroupBox workgroup_bounds(uint li_2, vec3 lo_2, vec3 hi_2) {
    uint stride = 32u;
    wg_lo[li_2] = lo_2;
    wg_hi[li_2] = hi_2;
    memoryBarrierShared();
    barrier();
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e36 = stride;
            stride = (_e36 / 2u);
        }
        loop_init_1 = false;
        uint _e9 = stride;
        if ((_e9 > 0u)) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if ((li_2 < _e12)) {
                vec3 _e18 = wg_lo[li_2];
                uint _e20 = stride;
                vec3 _e23 = wg_lo[(li_2 + _e20)];
                wg_lo[li_2] = min(_e18, _e23);
                vec3 _e29 = wg_hi[li_2];
                uint _e31 = stride;
                vec3 _e34 = wg_hi[(li_2 + _e31)];
                wg_hi[li_2] = max(_e29, _e34);
            }
            memoryBarrierShared();
            barrier();
        }
    }
    if ((li_2 == 0u)) {
        vec3 _e44 = wg_lo[0];
        vec3 _e47 = wg_hi[0];
        wg_box = WorkgroupBox(_e44, _e47);
    }
    memoryBarrierShared();
    barrier();
    WorkgroupBox _e50 = wg_box;
    memoryBarrierShared();
    barrier();
    return _e50;
}

WorkgroupBox point_box(vec3 p_4, bool has) {
    return WorkgroupBox((has ? p_4 : vec3(3.4028235e38)), (has ? p_4 : vec3(-3.4028235e38)));
}

WorkgroupBox workgroup_box(uint li_3, vec3 p_5, bool has_1) {
    WorkgroupBox _e3 = point_box(p_5, has_1);
    WorkgroupBox _e6 = workgroup_bounds(li_3, _e3.lo, _e3.hi);
    return _e6;
}

bool box_is_empty(WorkgroupBox b_6) {
    return (b_6.lo.x > b_6.hi.x);
}

uint tile_subtree(uint s_3, TileWalk t_2, bool list, uint at, uint start_2, uint to) {
    uint p_6 = 0u;
    uint b_7 = 0u;
    bool local_34 = false;
    bool local_35 = false;
    bool local_36 = false;
    uint _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH);
    if ((_e8 == BSH_NONE)) {
        return 0u;
    }
    uint end_1 = _group_1_binding_4_cs[_e8].next;
    p_6 = at;
    uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_2.lo, t_2.hi, t_2.w);
    b_7 = _e21;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e53 = b_7;
            uint _e56 = _group_1_binding_4_cs[_e53].next;
            uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_2.lo, t_2.hi, t_2.w);
            b_7 = _e60;
        }
        loop_init_2 = false;
        uint _e23 = b_7;
        if ((_e23 != end_1)) {
            if (!(!(list))) {
                uint _e31 = p_6;
                local_35 = (_e31 < to);
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
                local_36 = (_e39 >= start_2);
            } else {
                local_36 = false;
            }
            bool _e42 = local_36;
            if (_e42) {
                uint _e44 = p_6;
                uint _e47 = b_7;
                tile_list[(_e44 - start_2)] = _e47;
            }
            uint _e48 = p_6;
            p_6 = (_e48 + 1u);
        }
    }
    uint _e61 = p_6;
    return (_e61 - at);
}

TileWalk tile_walk_begin(uint li_4, vec3 x_8, float w_9, bool has_2) {
    bool local_37 = false;
    TileWalk t_3 = TileWalk(vec3(0.0), vec3(0.0), 0.0, 0u);
    uint s_4 = 0u;
    uint sum_1 = 0u;
    uint s_5 = 0u;
    if (has_2) {
        local_37 = (w_9 >= 0.0);
    } else {
        local_37 = false;
    }
    bool _e12 = local_37;
    uint _e14 = atomicMax(tile_scale, (_e12 ? floatBitsToUint(w_9) : 0u));
    WorkgroupBox _e15 = workgroup_box(li_4, x_8, has_2);
    memoryBarrierShared();
    barrier();
    uint _e19 = tile_scale;
    memoryBarrierShared();
    barrier();
    t_3 = TileWalk(_e15.lo, _e15.hi, uintBitsToFloat(_e19), 0u);
    bool _e24 = box_is_empty(_e15);
    if (_e24) {
        TileWalk _e25 = t_3;
        return _e25;
    }
    s_4 = li_4;
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            uint _e40 = s_4;
            s_4 = (_e40 + TILE_THREADS);
        }
        loop_init_3 = false;
        uint _e27 = s_4;
        if ((_e27 < BSH_TILE_SUBTREES)) {
        } else {
            break;
        }
        {
            uint _e31 = s_4;
            uint _e33 = s_4;
            TileWalk _e34 = t_3;
            uint _e39 = tile_subtree(_e33, _e34, false, 0u, 0u, 0u);
            subtree_at[_e31] = _e39;
        }
    }
    memoryBarrierShared();
    barrier();
    if ((li_4 == 0u)) {
        bool loop_init_4 = true;
        while(true) {
            if (!loop_init_4) {
                uint _e63 = s_5;
                s_5 = (_e63 + 1u);
            }
            loop_init_4 = false;
            uint _e49 = s_5;
            if ((_e49 < BSH_TILE_SUBTREES)) {
            } else {
                break;
            }
            {
                uint _e53 = s_5;
                uint c_15 = subtree_at[_e53];
                uint _e57 = s_5;
                uint _e59 = sum_1;
                subtree_at[_e57] = _e59;
                uint _e60 = sum_1;
                sum_1 = (_e60 + c_15);
            }
        }
        uint _e66 = sum_1;
        tile_total = _e66;
    }
    memoryBarrierShared();
    barrier();
    uint _e69 = tile_total;
    memoryBarrierShared();
    barrier();
    t_3.total = _e69;
    TileWalk _e70 = t_3;
    return _e70;
}

uint tile_walk_fill(uint li_5, TileWalk t_4, uint start_3) {
    uint s_6 = 0u;
    uint past = 0u;
    bool local_38 = false;
    uint to_1 = min(t_4.total, (start_3 + TILE_LIST));
    s_6 = li_5;
    bool loop_init_5 = true;
    while(true) {
        if (!loop_init_5) {
            uint _e38 = s_6;
            s_6 = (_e38 + TILE_THREADS);
        }
        loop_init_5 = false;
        uint _e8 = s_6;
        if ((_e8 < BSH_TILE_SUBTREES)) {
        } else {
            break;
        }
        {
            uint _e12 = s_6;
            uint at_1 = subtree_at[_e12];
            past = t_4.total;
            uint _e17 = s_6;
            if (((_e17 + 1u) < BSH_TILE_SUBTREES)) {
                uint _e23 = s_6;
                uint _e27 = subtree_at[(_e23 + 1u)];
                past = _e27;
            }
            if ((at_1 < to_1)) {
                uint _e31 = past;
                local_38 = (_e31 > start_3);
            } else {
                local_38 = false;
            }
            bool _e34 = local_38;
            if (_e34) {
                uint _e35 = s_6;
                uint _e37 = tile_subtree(_e35, t_4, true, at_1, start_3, to_1);
            }
        }
    }
    memoryBarrierShared();
    barrier();
    return (to_1 - start_3);
}

Shaded shade_connection(Connection c_9, vec3 x_9, vec3 n_8, Material m_1) {
    Shaded s_7 = Shaded(vec3(0.0), vec3(0.0), vec3(0.0));
    s_7.e = c_9.e;
    s_7.diffuse = vec3(0.0);
    s_7.specular = vec3(0.0);
    if ((c_9.cos_x > 0.0)) {
        vec3 _e25 = bevy_brdf(m_1.base, m_1.metallic, m_1.roughness, m_1.reflectance, n_8, m_1.v, normalize((c_9.y - x_9)));
        s_7.diffuse = (_e25 * c_9.e);
    }
    Shaded _e28 = s_7;
    return _e28;
}

Shaded shade_pick_traced(uint li_6, vec3 x_10, vec3 n_9, vec3 r_10, vec4 rl_5, Material m_2, float w_10, float u1_5, float u2_5, float eps_2, bool trace_3) {
    float _e11 = light_range_scale(li_6, x_10, r_10, rl_5);
    Connection _e12 = connect_traced(li_6, x_10, n_9, n_9, _e11, w_10, u1_5, u2_5, eps_2, trace_3);
    Shaded _e13 = shade_connection(_e12, x_10, n_9, m_2);
    return _e13;
}

Material material_of(vec3 base_3, float metallic_4, float roughness, float reflectance_2, vec3 v_4) {
    float _e6 = bevy_alpha(roughness);
    return Material(base_3, clamp(metallic_4, 0.0, 1.0), _e6, v_4, roughness, reflectance_2);
}

Shaded add(Shaded a_8, Shaded b_8) {
    return Shaded((a_8.e + b_8.e), (a_8.diffuse + b_8.diffuse), (a_8.specular + b_8.specular));
}

Shaded scaled(Shaded s_8, vec3 w_11) {
    return Shaded((s_8.e * w_11), (s_8.diffuse * w_11), (s_8.specular * w_11));
}

uint[8] first_holders(uvec2 keys_1[8], bool held_1[8]) {
    uint first[8] = uint[8](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    uint k_4 = 0u;
    uint j_4 = 0u;
    bool local_39 = false;
    bool local_40 = false;
    bool loop_init_6 = true;
    while(true) {
        if (!loop_init_6) {
            uint _e45 = k_4;
            k_4 = (_e45 + 1u);
        }
        loop_init_6 = false;
        uint _e5 = k_4;
        if ((_e5 < K)) {
        } else {
            break;
        }
        {
            uint _e8 = k_4;
            uint _e11 = k_4;
            uint _e12 = k_4;
            first[_e8] = (held_1[_e12] ? _e11 : K);
            j_4 = 0u;
            bool loop_init_7 = true;
            while(true) {
                if (!loop_init_7) {
                    uint _e42 = j_4;
                    j_4 = (_e42 + 1u);
                }
                loop_init_7 = false;
                uint _e17 = j_4;
                uint _e18 = k_4;
                if ((_e17 < _e18)) {
                    uint _e22 = k_4;
                    local_39 = held_1[_e22];
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
                    if (held_1[_e26]) {
                        uint _e30 = j_4;
                        uint _e32 = k_4;
                        local_40 = all(equal(keys_1[_e30], keys_1[_e32]));
                    } else {
                        local_40 = false;
                    }
                    bool _e37 = local_40;
                    if (_e37) {
                        uint _e38 = k_4;
                        uint _e40 = j_4;
                        first[_e38] = _e40;
                        break;
                    }
                }
            }
        }
    }
    uint _e47[8] = first;
    return _e47;
}

vec3 output_of(Shaded s_9) {
    return (s_9.diffuse + s_9.specular);
}

uint previous_index(uint i_4) {
    uint _e4 = _group_0_binding_7_cs.parity;
    uint _e8 = _group_0_binding_0_cs.width;
    uint _e12 = _group_0_binding_0_cs.height;
    return ((((1u - _e4) * _e8) * _e12) + i_4);
}

uint next_index(uint i_5) {
    uint _e3 = _group_0_binding_7_cs.parity;
    uint _e6 = _group_0_binding_0_cs.width;
    uint _e10 = _group_0_binding_0_cs.height;
    return (((_e3 * _e6) * _e10) + i_5);
}

Connection sample_connection(GpuLight l_4, uint cells, vec3 x_11, vec3 n_10, float eps_3, bool trace_4) {
    float _e9 = grid_coordinate(cells);
    float _e12 = grid_coordinate((cells << 16u));
    Connection _e13 = connect_record(l_4, x_11, n_10, n_10, UNRANGED, UNRANGED, 1.0, _e9, _e12, eps_3, trace_4);
    return _e13;
}

float reuse_target(uint q_6, GpuLight l_5, uint cells_1, vec3 x_12, vec3 n_11, Material m_3) {
    Connection _e8 = sample_connection(l_5, cells_1, x_12, n_11, 0.0, false);
    Shaded _e9 = shade_connection(_e8, x_12, n_11, m_3);
    vec3 _e10 = output_of(_e9);
    float _e12 = slot_target(_e10, q_6, K);
    return _e12;
}

ReuseSurface reuse_surface(vec3 x_13, vec3 n_12, Material m_4, float c_10) {
    return ReuseSurface(x_13, c_10, n_12, packUnorm4x8(vec4(m_4.base, m_4.metallic)), packUnorm2x16(vec2(clamp(m_4.roughness, 0.0, 1.0), clamp(m_4.reflectance, 0.0, 1.0))), 0u, 0u, 0u);
}

Material reuse_material(ReuseSurface s_10, vec3 eye) {
    vec4 b_9 = unpackUnorm4x8(s_10.base);
    vec2 r_12 = unpackUnorm2x16(s_10.rough);
    Material _e13 = material_of(b_9.xyz, b_9.w, r_12.x, r_12.y, normalize((eye - s_10.x)));
    return _e13;
}

uvec2 sample_key(uint li_7, uint cells_2) {
    uint _e6 = _group_1_binding_1_cs[li_7].kind;
    return uvec2(li_7, ((_e6 == LIGHT_TRIANGLE) ? cells_2 : 0u));
}

bool sample_reaches(GpuLight l_6, uint cells_3, vec3 x_14, vec3 n_13, float eps_4) {
    Connection _e6 = sample_connection(l_6, cells_3, x_14, n_13, eps_4, true);
    return any(greaterThan(_e6.e, vec3(0.0)));
}

float domain_offset(Domain d_6) {
    float _e3 = _group_0_binding_0_cs.shadow_offset;
    vec3 _e6 = _group_0_binding_7_cs.prev_eye;
    return (_e3 * length((_e6 - d_6.x)));
}

bool history_vouches(uint li_8, uint cells_4, Domain d_7) {
    uint _e5 = _group_0_binding_7_cs.moved;
    if ((_e5 == 0u)) {
        return true;
    }
    uint _e11 = _group_0_binding_7_cs.moved;
    if ((_e11 == 2u)) {
        return false;
    }
    float _e17 = domain_offset(d_7);
    vec3 a_10 = (d_7.x + (d_7.n * _e17));
    GpuLight _e22 = _group_1_binding_8_cs[li_8];
    float _e23 = grid_coordinate(cells_4);
    float _e26 = grid_coordinate((cells_4 << 16u));
    vec3 _e27 = light_point(_e22, _e23, _e26);
    vec3 _e29 = ray_inverse3_((_e27 - a_10));
    vec3 _e32 = _group_0_binding_7_cs.moved_min;
    vec3 _e35 = _group_0_binding_7_cs.moved_max;
    float _e37 = ray_aabb(a_10, _e29, _e32, _e35, 1.0);
    return (_e37 < 0.0);
}

bool reached_before(uint li_9, uint cells_5, Domain d_8, vec3 x_15, vec3 n_14) {
    bool local_41 = false;
    bool local_42 = false;
    bool local_43 = false;
    bool local_44 = false;
    uint q_7 = 0u;
    bool local_45 = false;
    bool local_46 = false;
    bool _e5 = history_vouches(li_9, cells_5, d_8);
    if (!(_e5)) {
        return false;
    }
    GpuLight l_7 = _group_1_binding_1_cs[li_9];
    GpuLight lp = _group_1_binding_8_cs[li_9];
    if (all(equal(d_8.x, x_15))) {
        local_41 = all(equal(d_8.n, n_14));
    } else {
        local_41 = false;
    }
    bool _e23 = local_41;
    if (_e23) {
        local_42 = all(equal(l_7.p0_, lp.p0_));
    } else {
        local_42 = false;
    }
    bool _e31 = local_42;
    if (_e31) {
        local_43 = all(equal(l_7.p1_, lp.p1_));
    } else {
        local_43 = false;
    }
    bool _e39 = local_43;
    if (_e39) {
        local_44 = all(equal(l_7.p2_, lp.p2_));
    } else {
        local_44 = false;
    }
    bool _e47 = local_44;
    if (_e47) {
        return true;
    }
    uvec2 _e49 = sample_key(li_9, cells_5);
    bool loop_init_8 = true;
    while(true) {
        if (!loop_init_8) {
            uint _e85 = q_7;
            q_7 = (_e85 + 1u);
        }
        loop_init_8 = false;
        uint _e52 = q_7;
        if ((_e52 < K)) {
        } else {
            break;
        }
        {
            uint _e57 = previous_index(d_8.pixel);
            uint _e60 = q_7;
            ReuseSlot h_5 = _group_1_binding_9_cs[_e57].slots[_e60];
            if ((h_5.w > 0.0)) {
                local_45 = (h_5.light < uint(_group_1_binding_1_cs.length()));
            } else {
                local_45 = false;
            }
            bool _e73 = local_45;
            if (_e73) {
                uvec2 _e78 = sample_key(h_5.light, h_5.u);
                local_46 = all(equal(_e78, _e49));
            } else {
                local_46 = false;
            }
            bool _e82 = local_46;
            if (_e82) {
                return true;
            }
        }
    }
    float _e89 = domain_offset(d_8);
    bool _e90 = sample_reaches(lp, cells_5, d_8.x, d_8.n, _e89);
    return _e90;
}

uint reuse_domains(vec3 x_16, vec3 n_15, float d_9, uint h_3, inout Domain doms_1[3]) {
    uint nd = 0u;
    uint hr = 0u;
    uint j_5 = 0u;
    vec2 p_7 = vec2(0.0);
    bool local_47 = false;
    bool local_48 = false;
    bool local_49 = false;
    bool seen_1 = false;
    uint k_5 = 0u;
    bool local_50 = false;
    bool local_51 = false;
    bool local_52 = false;
    uint _e9 = _group_0_binding_7_cs.has_history;
    if ((_e9 != 1u)) {
        return 0u;
    }
    vec4 _e15 = _group_0_binding_7_cs.c0_;
    vec4 _e18 = _group_0_binding_7_cs.c1_;
    vec4 _e21 = _group_0_binding_7_cs.c2_;
    vec4 _e24 = _group_0_binding_7_cs.c3_;
    uint _e27 = _group_0_binding_0_cs.width;
    uint _e31 = _group_0_binding_0_cs.height;
    vec3 _e33 = reproject(_e15, _e18, _e21, _e24, x_16, float(_e27), float(_e31));
    if ((_e33.z <= 0.0)) {
        return 0u;
    }
    hr = h_3;
    bool loop_init_9 = true;
    while(true) {
        if (!loop_init_9) {
            uint _e176 = j_5;
            j_5 = (_e176 + 1u);
        }
        loop_init_9 = false;
        uint _e41 = j_5;
        if ((_e41 < DOMAINS)) {
        } else {
            break;
        }
        {
            p_7 = _e33.xy;
            uint _e46 = j_5;
            if ((_e46 > 0u)) {
                uint _e49 = hr;
                uint _e50 = pcg_hash(_e49);
                hr = _e50;
                uint _e51 = hr;
                float _e52 = xi_from_bits(_e51);
                uint _e53 = hr;
                uint _e54 = pcg_hash(_e53);
                hr = _e54;
                vec2 _e55 = p_7;
                float _e58 = _group_0_binding_7_cs.radius;
                uint _e59 = hr;
                float _e60 = xi_from_bits(_e59);
                vec2 _e61 = disk_offset(_e58, _e52, _e60);
                p_7 = (_e55 + _e61);
            }
            vec2 _e63 = p_7;
            ivec2 t_10 = ivec2(roundEven(_e63));
            if (!((t_10.x < 0))) {
                local_47 = (t_10.y < 0);
            } else {
                local_47 = true;
            }
            bool _e76 = local_47;
            if (!(_e76)) {
                uint _e83 = _group_0_binding_0_cs.width;
                local_48 = (t_10.x >= int(_e83));
            } else {
                local_48 = true;
            }
            bool _e87 = local_48;
            if (!(_e87)) {
                uint _e94 = _group_0_binding_0_cs.height;
                local_49 = (t_10.y >= int(_e94));
            } else {
                local_49 = true;
            }
            bool _e98 = local_49;
            if (_e98) {
                continue;
            }
            uint _e103 = _group_0_binding_0_cs.width;
            uint pixel = ((uint(t_10.y) * _e103) + uint(t_10.x));
            seen_1 = false;
            k_5 = 0u;
            bool loop_init_10 = true;
            while(true) {
                if (!loop_init_10) {
                    uint _e127 = k_5;
                    k_5 = (_e127 + 1u);
                }
                loop_init_10 = false;
                uint _e112 = k_5;
                uint _e113 = nd;
                if ((_e112 < _e113)) {
                } else {
                    break;
                }
                {
                    bool _e115 = seen_1;
                    if (!(_e115)) {
                        uint _e119 = k_5;
                        uint _e122 = doms_1[_e119].pixel;
                        local_50 = (_e122 == pixel);
                    } else {
                        local_50 = true;
                    }
                    bool _e125 = local_50;
                    seen_1 = _e125;
                }
            }
            uint _e130 = previous_index(pixel);
            ReuseSurface s_13 = _group_1_binding_9_cs[_e130].surface;
            bool _e134 = seen_1;
            if (!(_e134)) {
                local_51 = !((s_13.m > 0.0));
            } else {
                local_51 = true;
            }
            bool _e143 = local_51;
            if (!(_e143)) {
                bool _e151 = history_matches(n_15, s_13.n, x_16, dot(s_13.n, s_13.x), d_9);
                local_52 = !(_e151);
            } else {
                local_52 = true;
            }
            bool _e154 = local_52;
            if (_e154) {
                continue;
            }
            uint _e155 = nd;
            vec3 _e161 = _group_0_binding_7_cs.prev_eye;
            Material _e162 = reuse_material(s_13, _e161);
            float _e166 = _group_0_binding_7_cs.max_confidence;
            uint _e168 = j_5;
            doms_1[_e155] = Domain(pixel, s_13.x, s_13.n, _e162, min(s_13.m, _e166), (_e168 == 0u));
            uint _e172 = nd;
            nd = (_e172 + 1u);
        }
    }
    uint _e178 = nd;
    return _e178;
}

ReuseSlot gris_combine(uint q_8, ReuseSlot cur, bool cur_ris, float cur_c, bool cur_reached, uint k0_, uint k1_, vec3 x_17, vec3 n_16, Material m_5, inout Domain doms_2[3], inout uint hs_1) {
    float w_sum_3 = 0.0;
    ReuseSlot out_ = ReuseSlot(0u, 0u, 0.0);
    float out_target = 0.0;
    uint j_6 = 0u;
    ReuseSlot s_11 = ReuseSlot(0u, 0u, 0.0);
    bool local_53 = false;
    bool local_54 = false;
    bool local_55 = false;
    float w_in = 0.0;
    bool local_56 = false;
    float own_1 = 0.0;
    float all_1 = 0.0;
    uint k_6 = 0u;
    float t_5 = 0.0;
    bool local_57 = false;
    bool local_58 = false;
    j_6 = k0_;
    bool loop_init_11 = true;
    while(true) {
        if (!loop_init_11) {
            uint _e186 = j_6;
            j_6 = (_e186 + 1u);
        }
        loop_init_11 = false;
        uint _e22 = j_6;
        if ((_e22 <= k1_)) {
        } else {
            break;
        }
        {
            s_11 = cur;
            uint _e25 = j_6;
            if ((_e25 > k0_)) {
                uint _e28 = j_6;
                uint _e33 = doms_2[(_e28 - 1u)].pixel;
                uint _e34 = previous_index(_e33);
                ReuseSlot _e38 = _group_1_binding_9_cs[_e34].slots[q_8];
                s_11 = _e38;
            }
            float _e40 = s_11.w;
            if (!(!((_e40 > 0.0)))) {
                uint _e48 = s_11.light;
                local_53 = (_e48 >= uint(_group_1_binding_1_cs.length()));
            } else {
                local_53 = true;
            }
            bool _e53 = local_53;
            if (_e53) {
                continue;
            }
            uint _e54 = j_6;
            if ((_e54 > k0_)) {
                uint _e60 = _group_0_binding_7_cs.visibility;
                local_54 = (_e60 == 1u);
            } else {
                local_54 = false;
            }
            bool _e64 = local_54;
            if (_e64) {
                uint _e68 = s_11.light;
                uint _e70 = s_11.u;
                uint _e71 = j_6;
                Domain _e75 = doms_2[(_e71 - 1u)];
                bool _e76 = history_vouches(_e68, _e70, _e75);
                local_55 = !(_e76);
            } else {
                local_55 = false;
            }
            bool _e79 = local_55;
            if (_e79) {
                continue;
            }
            uint _e82 = s_11.light;
            GpuLight _e84 = _group_1_binding_1_cs[_e82];
            uint _e86 = s_11.u;
            float _e87 = reuse_target(q_8, _e84, _e86, x_17, n_16, m_5);
            if (!((_e87 > 0.0))) {
                continue;
            }
            float _e92 = s_11.w;
            w_in = _e92;
            uint _e94 = j_6;
            if ((_e94 == k0_)) {
                local_56 = cur_ris;
            } else {
                local_56 = false;
            }
            bool _e99 = local_56;
            if (_e99) {
                float _e101 = s_11.w;
                w_in = (_e101 / _e87);
            }
            own_1 = (cur_c * _e87);
            float _e105 = own_1;
            all_1 = _e105;
            uint _e109 = s_11.light;
            GpuLight _e111 = _group_1_binding_1_cs[_e109];
            uint _e113 = s_11.u;
            float _e114 = grid_coordinate(_e113);
            uint _e116 = s_11.u;
            float _e119 = grid_coordinate((_e116 << 16u));
            vec3 _e120 = light_point(_e111, _e114, _e119);
            k_6 = k0_;
            bool loop_init_12 = true;
            while(true) {
                if (!loop_init_12) {
                    uint _e164 = k_6;
                    k_6 = (_e164 + 1u);
                }
                loop_init_12 = false;
                uint _e122 = k_6;
                if ((_e122 < k1_)) {
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
                        Domain d_10 = doms_2[_e133];
                        float _e140 = reuse_trust((_e120 - x_17), (_e120 - d_10.x));
                        uint _e144 = s_11.light;
                        GpuLight _e146 = _group_1_binding_8_cs[_e144];
                        uint _e148 = s_11.u;
                        float _e152 = reuse_target(q_8, _e146, _e148, d_10.x, d_10.n, d_10.m);
                        t_5 = ((d_10.c * _e140) * _e152);
                    }
                    float _e154 = all_1;
                    float _e155 = t_5;
                    all_1 = (_e154 + _e155);
                    uint _e157 = k_6;
                    uint _e160 = j_6;
                    if (((_e157 + 1u) == _e160)) {
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
            w_sum_3 = (_e170 + _e169);
            uint _e172 = hs_1;
            uint _e173 = pcg_hash(_e172);
            hs_1 = _e173;
            if ((_e169 > 0.0)) {
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
                out_ = _e184;
                out_target = _e87;
            }
        }
    }
    float _e189 = w_sum_3;
    float _e190 = out_target;
    float _e191 = gris_contribution_weight(_e189, _e190);
    out_.w = _e191;
    ReuseSlot _e192 = out_;
    return _e192;
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_lo = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_hi = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_box = WorkgroupBox(vec3(0.0), vec3(0.0));
        tile_list = uint[1024](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
        subtree_at = uint[256](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
        tile_scale = 0u;
        tile_total = 0u;
    }
    memoryBarrierShared();
    barrier();
    uvec3 gid = gl_GlobalInvocationID;
    uint lid = gl_LocalInvocationIndex;
    bool local = false;
    vec4 s = vec4(0.0);
    vec3 nn = vec3(0.0);
    bool local_1 = false;
    bool local_2 = false;
    bool local_3 = false;
    vec3 n = vec3(0.0, 0.0, 1.0);
    Material m = Material(vec3(0.0), 0.0, 0.0, vec3(0.0), 0.0, 0.0);
    vec4 lobe = vec4(1.0, 0.0, 1.0, 1.0);
    vec3 r = vec3(0.0);
    uint h = 0u;
    Shaded t = Shaded(vec3(0.0), vec3(0.0), vec3(0.0));
    uint slot_light[8] = uint[8](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    vec2 slot_u[8] = vec2[8](vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
    float slot_p[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    uint slot_cells[8] = uint[8](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    vec3 total = vec3(0.0);
    uint count = 0u;
    uint hc = 0u;
    float threshold[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    uint start = 0u;
    uint j = 0u;
    bool local_4 = false;
    uint q = 0u;
    bool local_5 = false;
    Domain doms[3] = Domain[3](Domain(0u, vec3(0.0), vec3(0.0), Material(vec3(0.0), 0.0, 0.0, vec3(0.0), 0.0, 0.0), 0.0, false), Domain(0u, vec3(0.0), vec3(0.0), Material(vec3(0.0), 0.0, 0.0, vec3(0.0), 0.0, 0.0), 0.0, false), Domain(0u, vec3(0.0), vec3(0.0), Material(vec3(0.0), 0.0, 0.0, vec3(0.0), 0.0, 0.0), 0.0, false));
    bool local_6 = false;
    uint hs = 0u;
    uvec2 fresh_keys[8] = uvec2[8](uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u));
    bool fresh_held[8] = bool[8](false, false, false, false, false, false, false, false);
    uint q_1 = 0u;
    bool local_7 = false;
    bool fresh_visible[8] = bool[8](false, false, false, false, false, false, false, false);
    uint q_2 = 0u;
    bool fresh_before[8] = bool[8](false, false, false, false, false, false, false, false);
    uint q_3 = 0u;
    bool local_8 = false;
    bool local_9 = false;
    ReuseSlot kept[8] = ReuseSlot[8](ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0));
    ReuseSlot fin[8] = ReuseSlot[8](ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0), ReuseSlot(0u, 0u, 0.0));
    uint q_4 = 0u;
    bool local_10 = false;
    bool local_11 = false;
    uvec2 keys[8] = uvec2[8](uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u));
    bool held[8] = bool[8](false, false, false, false, false, false, false, false);
    uint k = 0u;
    bool visible[8] = bool[8](false, false, false, false, false, false, false, false);
    uint k_1 = 0u;
    vec3 w = vec3(0.0);
    uint j_1 = 0u;
    bool known = false;
    bool seen = false;
    uint j_2 = 0u;
    bool local_12 = false;
    bool local_13 = false;
    Shaded shaded = Shaded(vec3(0.0), vec3(0.0), vec3(0.0));
    bool local_14 = false;
    uint j_3 = 0u;
    uint q_5 = 0u;
    bool local_15 = false;
    uint _e5 = _group_0_binding_0_cs.width;
    if ((gid.x < _e5)) {
        uint _e12 = _group_0_binding_0_cs.height;
        local = (gid.y < _e12);
    } else {
        local = false;
    }
    bool inside = local;
    ivec2 texel_1 = ivec2(int(gid.x), int(gid.y));
    if (inside) {
        vec4 _e27 = surface_at(texel_1);
        s = _e27;
        vec4 _e30 = texelFetch(_group_0_binding_2_cs, texel_1, 0);
        nn = _e30.xyz;
    }
    vec3 _e32 = nn;
    vec3 _e33 = nn;
    float len2_ = dot(_e32, _e33);
    vec4 _e35 = s;
    vec3 x_20 = _e35.xyz;
    if (inside) {
        float _e40 = s.w;
        local_1 = (_e40 > 0.0);
    } else {
        local_1 = false;
    }
    bool _e44 = local_1;
    if (_e44) {
        local_2 = (len2_ > 0.0);
    } else {
        local_2 = false;
    }
    bool _e50 = local_2;
    if (_e50) {
        local_3 = all(lessThanEqual(abs(x_20), vec3(3.4028235e38)));
    } else {
        local_3 = false;
    }
    bool has_3 = local_3;
    if (has_3) {
        vec3 _e65 = nn;
        n = (_e65 / vec3(sqrt(len2_)));
    }
    vec3 _e76 = n;
    r = _e76;
    if (has_3) {
        vec4 mr = texelFetch(_group_0_binding_5_cs, texel_1, 0);
        vec4 _e83 = texelFetch(_group_0_binding_4_cs, texel_1, 0);
        vec3 _e90 = _group_0_binding_0_cs.eye;
        Material _e93 = material_of(_e83.xyz, mr.z, mr.y, mr.w, normalize((_e90 - x_20)));
        m = _e93;
        vec3 _e95 = m.base;
        float _e97 = m.metallic;
        float _e99 = bevy_f0_(mr.w);
        float _e103 = m.alpha;
        vec3 _e104 = n;
        vec3 _e106 = m.v;
        vec4 _e108 = receiver_lobe(_e95, _e97, vec3(_e99), 1.0, _e103, dot(_e104, _e106));
        lobe = _e108;
        vec3 _e109 = n;
        vec3 _e111 = m.v;
        vec3 _e112 = mirror_dir(_e109, _e111);
        r = _e112;
    }
    vec4 _e113 = lobe;
    vec4 _e114 = range_lobe(_e113);
    float _e117 = _group_0_binding_0_cs.shadow_offset;
    vec3 _e120 = _group_0_binding_0_cs.eye;
    float eps_5 = (_e117 * length((_e120 - x_20)));
    uint _e126 = _group_0_binding_0_cs.seed;
    uint _e130 = _group_0_binding_0_cs.width;
    uint _e136 = _group_0_binding_0_cs.frame;
    uint _e137 = point_stream(_e126, ((gid.y * _e130) + gid.x), _e136);
    uint _e138 = pick_stream(_e137);
    h = _e138;
    hc = _e137;
    TileWalk _e160 = tile_walk_begin(lid, x_20, _e114.w, has_3);
    bool loop_init_13 = true;
    while(true) {
        if (!loop_init_13) {
            uint _e259 = start;
            start = (_e259 + TILE_LIST);
        }
        loop_init_13 = false;
        uint _e163 = start;
        if ((_e163 < _e160.total)) {
        } else {
            break;
        }
        {
            uint _e166 = start;
            uint _e167 = tile_walk_fill(lid, _e160, _e166);
            j = 0u;
            bool loop_init_14 = true;
            while(true) {
                if (!loop_init_14) {
                    uint _e257 = j;
                    j = (_e257 + 1u);
                }
                loop_init_14 = false;
                uint _e170 = j;
                if ((_e170 < _e167)) {
                } else {
                    break;
                }
                {
                    uint _e173 = j;
                    uint b_10 = tile_list[_e173];
                    if (!(!(has_3))) {
                        BshNode _e182 = _group_1_binding_4_cs[b_10];
                        vec3 _e183 = r;
                        bool _e184 = bsh_reaches(_e182, x_20, _e183, _e114);
                        local_4 = !(_e184);
                    } else {
                        local_4 = true;
                    }
                    bool _e187 = local_4;
                    if (_e187) {
                        continue;
                    }
                    uint li_10 = _group_1_binding_4_cs[b_10].light;
                    uint _e192 = count;
                    count = (_e192 + 1u);
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
                    vec2 u_5 = vec2(_e202, _e204);
                    vec3 _e206 = n;
                    vec3 _e207 = r;
                    Material _e208 = m;
                    Shaded _e213 = shade_pick_traced(li_10, x_20, _e206, _e207, _e114, _e208, 1.0, u_5.x, u_5.y, eps_5, false);
                    vec3 _e214 = output_of(_e213);
                    float _e215 = resample_target(_e214);
                    if ((_e215 > 0.0)) {
                        vec3 _e218 = total;
                        total = (_e218 + _e214);
                        q = 0u;
                        bool loop_init_15 = true;
                        while(true) {
                            if (!loop_init_15) {
                                uint _e254 = q;
                                q = (_e254 + 1u);
                            }
                            loop_init_15 = false;
                            uint _e222 = q;
                            if ((_e222 < K)) {
                            } else {
                                break;
                            }
                            {
                                uint _e225 = q;
                                float _e227 = slot_target(_e214, _e225, K);
                                vec3 _e228 = total;
                                uint _e229 = q;
                                float _e231 = slot_target(_e228, _e229, K);
                                if ((_e227 > 0.0)) {
                                    uint _e236 = q;
                                    float _e238 = threshold[_e236];
                                    local_5 = (_e231 > _e238);
                                } else {
                                    local_5 = false;
                                }
                                bool _e241 = local_5;
                                if (_e241) {
                                    uint _e242 = q;
                                    slot_light[_e242] = li_10;
                                    uint _e244 = q;
                                    slot_u[_e244] = u_5;
                                    uint _e246 = q;
                                    slot_p[_e246] = _e227;
                                    uint _e248 = q;
                                    slot_cells[_e248] = _e201;
                                    uint _e250 = q;
                                    float _e252 = next_threshold(_e231, hc);
                                    threshold[_e250] = _e252;
                                }
                            }
                        }
                    }
                }
            }
            memoryBarrierShared();
            barrier();
        }
    }
    if (!(has_3)) {
        if (inside) {
            imageStore(_group_0_binding_3_cs, texel_1, vec4(0.0));
            uint _e270 = _group_0_binding_0_cs.width;
            uint _e274 = next_index(((gid.y * _e270) + gid.x));
            _group_1_binding_9_cs[_e274].surface.m = 0.0;
        }
        return;
    }
    uint _e282 = _group_0_binding_0_cs.width;
    uint pixel_1 = ((gid.y * _e282) + gid.x);
    vec3 _e287 = n;
    vec3 _e290 = _group_0_binding_0_cs.eye;
    uint _e294 = reuse_stream(_e137, 0u);
    uint _e295 = reuse_domains(x_20, _e287, length((_e290 - x_20)), _e294, doms);
    if ((_e295 > 0u)) {
        bool _e302 = doms[0].temporal;
        local_6 = _e302;
    } else {
        local_6 = false;
    }
    bool own_history = local_6;
    uint first_1 = (own_history ? 1u : 0u);
    float _e310 = doms[0].c;
    float confidence = (1.0 + (own_history ? _e310 : 0.0));
    uint _e316 = reuse_stream(_e137, 1u);
    hs = _e316;
    bool loop_init_16 = true;
    while(true) {
        if (!loop_init_16) {
            uint _e351 = q_1;
            q_1 = (_e351 + 1u);
        }
        loop_init_16 = false;
        uint _e322 = q_1;
        if ((_e322 < K)) {
        } else {
            break;
        }
        {
            uint _e325 = q_1;
            uint _e327 = q_1;
            uint _e329 = slot_light[_e327];
            uint _e330 = q_1;
            uint _e332 = slot_cells[_e330];
            uvec2 _e333 = sample_key(_e329, _e332);
            fresh_keys[_e325] = _e333;
            uint _e334 = q_1;
            uint _e338 = _group_0_binding_7_cs.visibility;
            if ((_e338 == 1u)) {
                uint _e343 = q_1;
                float _e345 = slot_p[_e343];
                local_7 = (_e345 > 0.0);
            } else {
                local_7 = false;
            }
            bool _e349 = local_7;
            fresh_held[_e334] = _e349;
        }
    }
    uvec2 _e353[8] = fresh_keys;
    bool _e354[8] = fresh_held;
    uint _e355[8] = first_holders(_e353, _e354);
    bool loop_init_17 = true;
    while(true) {
        if (!loop_init_17) {
            uint _e390 = q_2;
            q_2 = (_e390 + 1u);
        }
        loop_init_17 = false;
        uint _e359 = q_2;
        if ((_e359 < K)) {
        } else {
            break;
        }
        {
            uint _e362 = q_2;
            uint _e364 = q_2;
            if ((_e355[_e362] == _e364)) {
                uint _e366 = q_2;
                uint _e369 = q_2;
                uint _e371 = slot_light[_e369];
                GpuLight _e373 = _group_1_binding_1_cs[_e371];
                uint _e374 = q_2;
                uint _e376 = slot_cells[_e374];
                vec3 _e377 = n;
                bool _e378 = sample_reaches(_e373, _e376, x_20, _e377, eps_5);
                fresh_visible[_e366] = _e378;
            } else {
                uint _e379 = q_2;
                if ((_e355[_e379] < K)) {
                    uint _e383 = q_2;
                    uint _e385 = q_2;
                    bool _e388 = fresh_visible[_e355[_e385]];
                    fresh_visible[_e383] = _e388;
                }
            }
        }
    }
    bool loop_init_18 = true;
    while(true) {
        if (!loop_init_18) {
            uint _e439 = q_3;
            q_3 = (_e439 + 1u);
        }
        loop_init_18 = false;
        uint _e395 = q_3;
        if ((_e395 < K)) {
        } else {
            break;
        }
        {
            uint _e398 = q_3;
            fresh_before[_e398] = true;
            uint _e401 = q_3;
            uint _e403 = q_3;
            if ((_e355[_e401] == _e403)) {
                uint _e407 = q_3;
                bool _e409 = fresh_visible[_e407];
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
                uint _e420 = slot_light[_e418];
                uint _e421 = q_3;
                uint _e423 = slot_cells[_e421];
                Domain _e425 = doms[0];
                vec3 _e426 = n;
                bool _e427 = reached_before(_e420, _e423, _e425, x_20, _e426);
                fresh_before[_e416] = _e427;
            } else {
                uint _e428 = q_3;
                if ((_e355[_e428] < K)) {
                    uint _e432 = q_3;
                    uint _e434 = q_3;
                    bool _e437 = fresh_before[_e355[_e434]];
                    fresh_before[_e432] = _e437;
                }
            }
        }
    }
    bool loop_init_19 = true;
    while(true) {
        if (!loop_init_19) {
            uint _e513 = q_4;
            q_4 = (_e513 + 1u);
        }
        loop_init_19 = false;
        uint _e445 = q_4;
        if ((_e445 < K)) {
        } else {
            break;
        }
        {
            uint _e448 = q_4;
            float _e450 = slot_p[_e448];
            if ((_e450 > 0.0)) {
                uint _e457 = _group_0_binding_7_cs.visibility;
                if (!((_e457 == 0u))) {
                    uint _e463 = q_4;
                    bool _e465 = fresh_visible[_e463];
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
            uint _e475 = slot_light[_e473];
            uint _e476 = q_4;
            uint _e478 = slot_cells[_e476];
            vec3 _e479 = total;
            uint _e480 = q_4;
            float _e482 = slot_target(_e479, _e480, K);
            uint _e488 = q_4;
            bool _e490 = fresh_before[_e488];
            vec3 _e492 = n;
            Material _e493 = m;
            ReuseSlot _e494 = gris_combine(_e472, ReuseSlot(_e475, _e478, (fresh ? _e482 : 0.0)), true, 1.0, _e490, 0u, first_1, x_20, _e492, _e493, doms, hs);
            kept[_e470] = _e494;
            uint _e495 = q_4;
            uint _e497 = q_4;
            ReuseSlot _e499 = kept[_e497];
            fin[_e495] = _e499;
            if ((_e295 > first_1)) {
                uint _e501 = q_4;
                uint _e503 = q_4;
                uint _e504 = q_4;
                ReuseSlot _e506 = kept[_e504];
                vec3 _e509 = n;
                Material _e510 = m;
                ReuseSlot _e511 = gris_combine(_e503, _e506, false, confidence, true, first_1, _e295, x_20, _e509, _e510, doms, hs);
                fin[_e501] = _e511;
            }
        }
    }
    bool loop_init_20 = true;
    while(true) {
        if (!loop_init_20) {
            uint _e542 = k;
            k = (_e542 + 1u);
        }
        loop_init_20 = false;
        uint _e519 = k;
        if ((_e519 < K)) {
        } else {
            break;
        }
        {
            uint _e522 = k;
            uint _e524 = k;
            uint _e527 = fin[_e524].light;
            uint _e528 = k;
            uint _e531 = fin[_e528].u;
            uvec2 _e532 = sample_key(_e527, _e531);
            keys[_e522] = _e532;
            uint _e533 = k;
            uint _e535 = k;
            float _e538 = fin[_e535].w;
            held[_e533] = (_e538 > 0.0);
        }
    }
    uvec2 _e544[8] = keys;
    bool _e545[8] = held;
    uint _e546[8] = first_holders(_e544, _e545);
    bool loop_init_21 = true;
    while(true) {
        if (!loop_init_21) {
            uint _e678 = k_1;
            k_1 = (_e678 + 1u);
        }
        loop_init_21 = false;
        uint _e550 = k_1;
        if ((_e550 < K)) {
        } else {
            break;
        }
        {
            uint _e553 = k_1;
            uint _e555 = k_1;
            if ((_e546[_e553] != _e555)) {
                continue;
            }
            w = vec3(0.0);
            uint _e560 = k_1;
            j_1 = _e560;
            bool loop_init_22 = true;
            while(true) {
                if (!loop_init_22) {
                    uint _e580 = j_1;
                    j_1 = (_e580 + 1u);
                }
                loop_init_22 = false;
                uint _e562 = j_1;
                if ((_e562 < K)) {
                } else {
                    break;
                }
                {
                    uint _e565 = j_1;
                    uint _e567 = k_1;
                    if ((_e546[_e565] == _e567)) {
                        vec3 _e569 = w;
                        uint _e570 = j_1;
                        float _e573 = fin[_e570].w;
                        uint _e574 = j_1;
                        vec3 _e576 = slot_share(_e574, K);
                        w = (_e569 + (_e573 * _e576));
                    }
                }
            }
            known = false;
            seen = false;
            j_2 = 0u;
            bool loop_init_23 = true;
            while(true) {
                if (!loop_init_23) {
                    uint _e617 = j_2;
                    j_2 = (_e617 + 1u);
                }
                loop_init_23 = false;
                uint _e588 = j_2;
                if ((_e588 < K)) {
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
                    bool _e599 = fresh_held[_e597];
                    if (_e599) {
                        uint _e602 = j_2;
                        uvec2 _e604 = fresh_keys[_e602];
                        uint _e605 = k_1;
                        uvec2 _e607 = keys[_e605];
                        local_13 = all(equal(_e604, _e607));
                    } else {
                        local_13 = false;
                    }
                    bool _e611 = local_13;
                    if (_e611) {
                        known = true;
                        uint _e613 = j_2;
                        bool _e615 = fresh_visible[_e613];
                        seen = _e615;
                    }
                }
            }
            shaded = Shaded(vec3(0.0), vec3(0.0), vec3(0.0));
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
                uint _e639 = fin[_e636].light;
                GpuLight _e641 = _group_1_binding_1_cs[_e639];
                uint _e642 = k_1;
                uint _e645 = fin[_e642].u;
                vec3 _e646 = n;
                bool _e647 = known;
                Connection _e649 = sample_connection(_e641, _e645, x_20, _e646, eps_5, !(_e647));
                vec3 _e650 = n;
                Material _e651 = m;
                Shaded _e652 = shade_connection(_e649, x_20, _e650, _e651);
                shaded = _e652;
            }
            Shaded _e653 = t;
            Shaded _e654 = shaded;
            vec3 _e655 = w;
            Shaded _e656 = scaled(_e654, _e655);
            Shaded _e657 = add(_e653, _e656);
            t = _e657;
            uint _e658 = k_1;
            j_3 = _e658;
            bool loop_init_24 = true;
            while(true) {
                if (!loop_init_24) {
                    uint _e675 = j_3;
                    j_3 = (_e675 + 1u);
                }
                loop_init_24 = false;
                uint _e660 = j_3;
                if ((_e660 < K)) {
                } else {
                    break;
                }
                {
                    uint _e663 = j_3;
                    uint _e665 = k_1;
                    if ((_e546[_e663] == _e665)) {
                        uint _e667 = j_3;
                        Shaded _e669 = shaded;
                        vec3 _e670 = output_of(_e669);
                        float _e671 = resample_target(_e670);
                        visible[_e667] = (_e671 > 0.0);
                    }
                }
            }
        }
    }
    bool loop_init_25 = true;
    while(true) {
        if (!loop_init_25) {
            uint _e720 = q_5;
            q_5 = (_e720 + 1u);
        }
        loop_init_25 = false;
        uint _e682 = q_5;
        if ((_e682 < K)) {
        } else {
            break;
        }
        {
            uint _e687 = _group_0_binding_7_cs.visibility;
            if (!((_e687 == 0u))) {
                uint _e693 = q_5;
                bool _e695 = visible[_e693];
                local_15 = _e695;
            } else {
                local_15 = true;
            }
            bool keep = local_15;
            uint _e699 = next_index(pixel_1);
            uint _e702 = q_5;
            uint _e704 = q_5;
            uint _e707 = kept[_e704].light;
            uint _e708 = q_5;
            uint _e711 = kept[_e708].u;
            uint _e712 = q_5;
            float _e715 = kept[_e712].w;
            _group_1_binding_9_cs[_e699].slots[_e702] = ReuseSlot(_e707, _e711, (keep ? _e715 : 0.0));
        }
    }
    uint _e723 = next_index(pixel_1);
    vec3 _e726 = n;
    Material _e727 = m;
    float _e730 = _group_0_binding_7_cs.max_confidence;
    ReuseSurface _e732 = reuse_surface(x_20, _e726, _e727, min(confidence, _e730));
    _group_1_binding_9_cs[_e723].surface = _e732;
    vec3 _e735 = t.diffuse;
    vec3 _e737 = t.specular;
    uint _e739 = count;
    imageStore(_group_0_binding_3_cs, texel_1, vec4((_e735 + _e737), float(_e739)));
    return;
}

