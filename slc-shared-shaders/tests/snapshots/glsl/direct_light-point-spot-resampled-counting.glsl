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

uint rays_cast = 0u;

uint nodes_visited = 0u;

layout(std430) readonly buffer type_7_block_0Compute { GpuGeoNode _group_1_binding_6_cs[]; };

layout(std430) readonly buffer type_8_block_1Compute { GpuTriangle _group_1_binding_7_cs[]; };

layout(std140) uniform ViewParams_block_2Compute { ViewParams _group_0_binding_0_cs; };

uniform sampler2D _group_0_binding_1_cs;

uniform sampler2D _group_0_binding_2_cs;

layout(rgba16f) writeonly uniform image2D _group_0_binding_3_cs;

layout(std430) readonly buffer type_12_block_3Compute { GpuLight _group_1_binding_1_cs[]; };

layout(std430) readonly buffer type_4_block_4Compute { float _group_1_binding_2_cs[]; };

layout(std430) readonly buffer type_4_block_5Compute { float _group_1_binding_3_cs[]; };

layout(std430) readonly buffer type_13_block_6Compute { BshNode _group_1_binding_4_cs[]; };

layout(std430) buffer type_15_block_7Compute { uint _group_0_binding_8_cs[]; };

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

shared WorkgroupBox wg_box;

shared uint tile_list[1024];

shared uint subtree_at[256];

shared uint tile_scale;

shared uint tile_total;

uint evaluations = 0u;


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
    vec3 v_2 = (x_1 - c);
    return (dot(v_2, v_2) <= (r_1 * r_1));
}

bool sphere_overlaps_aabb(vec3 c_1, float r_2, vec3 bmin, vec3 bmax) {
    vec3 q_1 = clamp(c_1, bmin, bmax);
    vec3 v_3 = (q_1 - c_1);
    return (dot(v_3, v_3) <= (r_2 * r_2));
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
    bool local_7 = false;
    bool local_8 = false;
    vec3 v_4 = (x_2 - y);
    float d2_6 = dot(v_4, v_4);
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
    vec3 w_10 = (v_4 / vec3(sqrt(d2_6)));
    float cos_x_1 = -(dot(n_1, w_10));
    if (!(!((cos_x_1 > 0.0)))) {
        local_8 = !((dot(ng, w_10) < 0.0));
    } else {
        local_8 = true;
    }
    bool _e34 = local_8;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float spot_falloff(float cos_theta, float cos_outer, float cos_inner, float shape) {
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t_4 = clamp(((cos_theta - cos_outer) / (cos_inner - cos_outer)), 0.0, 1.0);
    return ((shape > 0.5) ? (t_4 * t_4) : ((t_4 * t_4) * (3.0 - (2.0 * t_4))));
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

float bsh_reach_bound(BshNode node_2, float w_2) {
    float _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_2 * 1.001) * _e5));
}

float weighted_threshold(float w_sum, float u_2) {
    return (w_sum / (1.0 - u_2));
}

float resample_target(vec3 c_2) {
    return (((c_2.x + c_2.y) + c_2.z) * 0.33333334);
}

float slot_target(vec3 c_3, uint slot, uint k_2) {
    if ((k_2 < 3u)) {
        float _e5 = resample_target(c_3);
        return _e5;
    }
    uint j_3 = (slot % 3u);
    if ((j_3 == 0u)) {
        return c_3.x;
    }
    if ((j_3 == 1u)) {
        return c_3.y;
    }
    return c_3.z;
}

vec3 slot_share(uint slot_1, uint k_3) {
    if ((k_3 < 3u)) {
        float _e4 = to_f32_(k_3);
        float w_11 = (1.0 / _e4);
        return vec3(w_11, w_11, w_11);
    }
    uint j_4 = (slot_1 % 3u);
    float _e15 = to_f32_((((k_3 + 2u) - j_4) / 3u));
    float w_12 = (1.0 / _e15);
    if ((j_4 == 0u)) {
        return vec3(w_12, 0.0, 0.0);
    }
    if ((j_4 == 1u)) {
        return vec3(0.0, w_12, 0.0);
    }
    return vec3(0.0, 0.0, w_12);
}

float smith_root(float cos_, float alpha) {
    float a2_ = (alpha * alpha);
    return sqrt((((cos_ * cos_) * (1.0 - a2_)) + a2_));
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

float cone_cos_of(vec3 v, float d2_4, float a_2, vec3 d) {
    bool local_9 = false;
    bool local_10 = false;
    float vd = dot(v, d);
    float h2_ = (d2_4 - (a_2 * a_2));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_10 = ((vd * vd) >= h2_);
        } else {
            local_10 = false;
        }
        bool _e19 = local_10;
        local_9 = _e19;
    } else {
        local_9 = true;
    }
    bool _e21 = local_9;
    if (_e21) {
        return 1.0;
    }
    vec3 c_7 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_7, c_7)) * a_2)) / d2_4), 1.0);
}

float cone_cos_toward(vec3 center, float radius, vec3 p, vec3 d_1) {
    vec3 v_5 = (center - p);
    float _e6 = cone_cos_of(v_5, dot(v_5, v_5), radius, d_1);
    return _e6;
}

float range_scale_at(vec4 rl, float cos_t) {
    float t_5 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_5 * t_5))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(vec4 rl_1, vec3 center_1, float radius_1, vec3 p_1, vec3 r_3) {
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_3);
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

float ray_triangle(vec3 o_1, vec3 d_3, vec3 a_3, vec3 b_2, vec3 c_4, float t_min, float t_max_1) {
    bool local_11 = false;
    bool local_12 = false;
    bool local_13 = false;
    vec3 e1_ = (b_2 - a_3);
    vec3 e2_ = (c_4 - a_3);
    vec3 p_5 = cross(d_3, e2_);
    float det = dot(e1_, p_5);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv = (1.0 / det);
    vec3 s_10 = (o_1 - a_3);
    float u_3 = (dot(s_10, p_5) * inv);
    if (!((u_3 < 0.0))) {
        local_11 = (u_3 > 1.0);
    } else {
        local_11 = true;
    }
    bool _e28 = local_11;
    if (_e28) {
        return -1.0;
    }
    vec3 q_2 = cross(s_10, e1_);
    float v_6 = (dot(d_3, q_2) * inv);
    if (!((v_6 < 0.0))) {
        local_12 = ((u_3 + v_6) > 1.0);
    } else {
        local_12 = true;
    }
    bool _e42 = local_12;
    if (_e42) {
        return -1.0;
    }
    float t_6 = (dot(e2_, q_2) * inv);
    if ((t_6 > t_min)) {
        local_13 = (t_6 < t_max_1);
    } else {
        local_13 = false;
    }
    bool _e51 = local_13;
    if (_e51) {
        return t_6;
    }
    return -1.0;
}

vec3 light_intensity(GpuLight l, vec3 w_3) {
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            float _e11 = spot_falloff(dot(l.p1_, w_3), l.a, l.b, l.p2_.x);
            return (l.intensity * _e11);
        }
        default: {
            return vec3(0.0);
        }
    }
}

vec3 light_point(GpuLight l_1, float u1_, float u2_) {
    return l_1.p0_;
}

GeoHit trace(vec3 o_2, vec3 d_4, float t_min_1, float t_max_2, bool any_hit) {
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
    vec3 _e14 = ray_inverse3_(d_4);
    while(true) {
        uint _e21 = node_3;
        GpuGeoNode n_8 = _group_1_binding_6_cs[_e21];
        uint _e25 = nodes_visited;
        nodes_visited = (_e25 + 1u);
        float _e31 = hit.t;
        float _e32 = ray_aabb(o_2, _e14, n_8.bmin, n_8.bmax, _e31);
        if ((_e32 >= 0.0)) {
            if ((n_8.count > 0u)) {
                i = n_8.first;
                bool loop_init = true;
                while(true) {
                    if (!loop_init) {
                        uint _e62 = i;
                        i = (_e62 + 1u);
                    }
                    loop_init = false;
                    uint _e40 = i;
                    if ((_e40 < (n_8.first + n_8.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e46 = i;
                        GpuTriangle t_7 = _group_1_binding_7_cs[_e46];
                        float _e53 = hit.t;
                        float _e54 = ray_triangle(o_2, d_4, t_7.v0_, t_7.v1_, t_7.v2_, t_min_1, _e53);
                        if ((_e54 > 0.0)) {
                            hit.t = _e54;
                            uint _e59 = i;
                            hit.tri = _e59;
                            if (any_hit) {
                                GeoHit _e60 = hit;
                                return _e60;
                            }
                        }
                    }
                }
            } else {
                uint _e64 = sp;
                if ((_e64 < 64u)) {
                    uint _e67 = sp;
                    stack[_e67] = (n_8.first + 1u);
                    uint _e72 = sp;
                    sp = (_e72 + 1u);
                }
                node_3 = n_8.first;
                continue;
            }
        }
        uint _e76 = sp;
        if ((_e76 == 0u)) {
            break;
        }
        uint _e79 = sp;
        sp = (_e79 - 1u);
        uint _e82 = sp;
        uint _e84 = stack[_e82];
        node_3 = _e84;
    }
    GeoHit _e85 = hit;
    return _e85;
}

bool occluded(vec3 a_4, vec3 b_3) {
    vec3 dv = (b_3 - a_4);
    float len_1 = length(dv);
    if ((len_1 <= 0.0)) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    uint _e9 = rays_cast;
    rays_cast = (_e9 + 1u);
    GeoHit _e16 = trace(a_4, (dv / vec3(len_1)), _e7, (len_1 - _e7), true);
    return (_e16.tri != NO_LIGHT);
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

float bsh_inner_scale(float a_5, vec3 v_1, float d2_5, vec3 r_4, vec4 rl_2) {
    float _e5 = cone_cos_of(v_1, d2_5, a_5, r_4);
    float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_4, vec3 x_4, vec3 r_5, vec4 rl_3) {
    bool local_14 = false;
    bool local_15 = false;
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_4);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, (node_4.radius * (rl_3.w * 1.0001)), x_4);
        local_14 = !(_e20);
    } else {
        local_14 = true;
    }
    bool _e23 = local_14;
    if (_e23) {
        return false;
    }
    vec3 v_7 = (x_4 - node_4.center);
    float d2_7 = dot(v_7, v_7);
    float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if ((d2_7 > (_e29 * _e29))) {
        return false;
    }
    if ((node_4.child == BSH_NONE)) {
        float _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_4, r_5);
        float _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_4);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_7), d2_7, r_5, rl_3);
    float s_c = (_e45 * 1.001);
    float _e50 = bsh_range_bound(node_4);
    float reach = (node_4.extent + (sqrt(s_c) * _e50));
    if ((d2_7 <= ((node_4.radius * node_4.radius) * s_c))) {
        local_15 = (d2_7 <= (reach * reach));
    } else {
        local_15 = false;
    }
    bool _e63 = local_15;
    return _e63;
}

bool bsh_reaches_box(BshNode node_5, vec3 lo, vec3 hi, float w_4) {
    bool _e13 = sphere_overlaps_aabb(node_5.center, (node_5.radius * (max(1.0, (w_4 * 1.0001)) * 1.0001)), lo, hi);
    return _e13;
}

uint bsh_subtree(uint nodes_3, uint s_1, uint depth) {
    uint i_2 = 0u;
    uint level = 0u;
    bool local_16 = false;
    uint _e3 = bsh_first(nodes_3);
    i_2 = _e3;
    while(true) {
        uint _e7 = level;
        if ((_e7 < depth)) {
            uint _e11 = i_2;
            local_16 = (_e11 != BSH_NONE);
        } else {
            local_16 = false;
        }
        bool _e15 = local_16;
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

uint bsh_next_leaf_box(uint nodes_4, uint start_1, uint end, vec3 lo_1, vec3 hi_1, float w_5) {
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
            bool _e11 = bsh_reaches_box(_e10, lo_1, hi_1, w_5);
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

float next_threshold(float sum, inout uint h_1) {
    uint _e2 = h_1;
    uint _e3 = pcg_hash(_e2);
    h_1 = _e3;
    uint _e4 = h_1;
    float _e5 = xi_from_bits(_e4);
    float _e6 = weighted_threshold(sum, _e5);
    return _e6;
}

Connection connect_record(GpuLight l_2, vec3 x_5, vec3 n_2, vec3 ng_1, float r2_2, float rt2_2, float w_res, float u1_1, float u2_1, float eps, bool trace_1) {
    Connection c_5 = Connection(vec3(0.0), vec3(0.0), 0.0);
    bool local_17 = false;
    bool local_18 = false;
    c_5.e = vec3(0.0);
    vec3 _e16 = light_point(l_2, u1_1, u2_1);
    c_5.y = _e16;
    vec3 _e19 = c_5.y;
    float _e20 = connection_cosine(x_5, _e19, n_2, ng_1, r2_2);
    c_5.cos_x = _e20;
    float _e22 = c_5.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            vec3 _e33 = c_5.y;
            bool _e34 = occluded((x_5 + (ng_1 * eps)), _e33);
            local_18 = _e34;
        } else {
            local_18 = false;
        }
        bool _e36 = local_18;
        local_17 = _e36;
    } else {
        local_17 = true;
    }
    bool _e38 = local_17;
    if (_e38) {
        Connection _e39 = c_5;
        return _e39;
    }
    vec3 _e41 = c_5.y;
    vec3 v_8 = (x_5 - _e41);
    float d2_8 = dot(v_8, v_8);
    vec3 _e48 = light_intensity(l_2, (v_8 / vec3(sqrt(d2_8))));
    float _e50 = c_5.cos_x;
    float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_5.e = (_e48 * _e51);
    Connection _e53 = c_5;
    return _e53;
}

Connection connect_traced(uint li, vec3 x_6, vec3 n_3, vec3 ng_2, float s_2, float w_res_1, float u1_2, float u2_2, float eps_1, bool trace_2) {
    GpuLight _e12 = _group_1_binding_1_cs[li];
    float _e15 = _group_1_binding_3_cs[li];
    float _e19 = _group_1_binding_2_cs[li];
    Connection _e21 = connect_record(_e12, x_6, n_3, ng_2, (s_2 * _e15), (s_2 * _e19), w_res_1, u1_2, u2_2, eps_1, trace_2);
    return _e21;
}

vec4 surface_at(ivec2 texel) {
    vec4 p_6 = texelFetch(_group_0_binding_1_cs, texel, 0);
    return ((p_6.w > 0.0) ? vec4(p_6.xyz, 1.0) : vec4(0.0));
}

WorkgroupBox workgroup_bounds(uint li_1, vec3 lo_2, vec3 hi_2) {
    uint stride = 32u;
    wg_lo[li_1] = lo_2;
    wg_hi[li_1] = hi_2;
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
            if ((li_1 < _e12)) {
                vec3 _e18 = wg_lo[li_1];
                uint _e20 = stride;
                vec3 _e23 = wg_lo[(li_1 + _e20)];
                wg_lo[li_1] = min(_e18, _e23);
                vec3 _e29 = wg_hi[li_1];
                uint _e31 = stride;
                vec3 _e34 = wg_hi[(li_1 + _e31)];
                wg_hi[li_1] = max(_e29, _e34);
            }
            memoryBarrierShared();
            barrier();
        }
    }
    if ((li_1 == 0u)) {
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

WorkgroupBox point_box(vec3 p_2, bool has) {
    return WorkgroupBox((has ? p_2 : vec3(3.4028235e38)), (has ? p_2 : vec3(-3.4028235e38)));
}

WorkgroupBox workgroup_box(uint li_2, vec3 p_3, bool has_1) {
    WorkgroupBox _e3 = point_box(p_3, has_1);
    WorkgroupBox _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi);
    return _e6;
}

bool box_is_empty(WorkgroupBox b_4) {
    return (b_4.lo.x > b_4.hi.x);
}

uint tile_subtree(uint s_3, TileWalk t_1, bool list, uint at, uint start_2, uint to) {
    uint p_4 = 0u;
    uint b_5 = 0u;
    bool local_19 = false;
    bool local_20 = false;
    bool local_21 = false;
    uint _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH);
    if ((_e8 == BSH_NONE)) {
        return 0u;
    }
    uint end_1 = _group_1_binding_4_cs[_e8].next;
    p_4 = at;
    uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_1.lo, t_1.hi, t_1.w);
    b_5 = _e21;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e53 = b_5;
            uint _e56 = _group_1_binding_4_cs[_e53].next;
            uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_1.lo, t_1.hi, t_1.w);
            b_5 = _e60;
        }
        loop_init_2 = false;
        uint _e23 = b_5;
        if ((_e23 != end_1)) {
            if (!(!(list))) {
                uint _e31 = p_4;
                local_20 = (_e31 < to);
            } else {
                local_20 = true;
            }
            bool _e34 = local_20;
            local_19 = _e34;
        } else {
            local_19 = false;
        }
        bool _e36 = local_19;
        if (_e36) {
        } else {
            break;
        }
        {
            if (list) {
                uint _e39 = p_4;
                local_21 = (_e39 >= start_2);
            } else {
                local_21 = false;
            }
            bool _e42 = local_21;
            if (_e42) {
                uint _e44 = p_4;
                uint _e47 = b_5;
                tile_list[(_e44 - start_2)] = _e47;
            }
            uint _e48 = p_4;
            p_4 = (_e48 + 1u);
        }
    }
    uint _e61 = p_4;
    return (_e61 - at);
}

TileWalk tile_walk_begin(uint li_3, vec3 x_7, float w_6, bool has_2) {
    bool local_22 = false;
    TileWalk t_2 = TileWalk(vec3(0.0), vec3(0.0), 0.0, 0u);
    uint s_4 = 0u;
    uint sum_1 = 0u;
    uint s_5 = 0u;
    if (has_2) {
        local_22 = (w_6 >= 0.0);
    } else {
        local_22 = false;
    }
    bool _e12 = local_22;
    uint _e14 = atomicMax(tile_scale, (_e12 ? floatBitsToUint(w_6) : 0u));
    WorkgroupBox _e15 = workgroup_box(li_3, x_7, has_2);
    memoryBarrierShared();
    barrier();
    uint _e19 = tile_scale;
    memoryBarrierShared();
    barrier();
    t_2 = TileWalk(_e15.lo, _e15.hi, uintBitsToFloat(_e19), 0u);
    bool _e24 = box_is_empty(_e15);
    if (_e24) {
        TileWalk _e25 = t_2;
        return _e25;
    }
    s_4 = li_3;
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
            TileWalk _e34 = t_2;
            uint _e39 = tile_subtree(_e33, _e34, false, 0u, 0u, 0u);
            subtree_at[_e31] = _e39;
        }
    }
    memoryBarrierShared();
    barrier();
    if ((li_3 == 0u)) {
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
                uint c_8 = subtree_at[_e53];
                uint _e57 = s_5;
                uint _e59 = sum_1;
                subtree_at[_e57] = _e59;
                uint _e60 = sum_1;
                sum_1 = (_e60 + c_8);
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
    t_2.total = _e69;
    TileWalk _e70 = t_2;
    return _e70;
}

uint tile_walk_fill(uint li_4, TileWalk t_3, uint start_3) {
    uint s_6 = 0u;
    uint past = 0u;
    bool local_23 = false;
    uint to_1 = min(t_3.total, (start_3 + TILE_LIST));
    s_6 = li_4;
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
            past = t_3.total;
            uint _e17 = s_6;
            if (((_e17 + 1u) < BSH_TILE_SUBTREES)) {
                uint _e23 = s_6;
                uint _e27 = subtree_at[(_e23 + 1u)];
                past = _e27;
            }
            if ((at_1 < to_1)) {
                uint _e31 = past;
                local_23 = (_e31 > start_3);
            } else {
                local_23 = false;
            }
            bool _e34 = local_23;
            if (_e34) {
                uint _e35 = s_6;
                uint _e37 = tile_subtree(_e35, t_3, true, at_1, start_3, to_1);
            }
        }
    }
    memoryBarrierShared();
    barrier();
    return (to_1 - start_3);
}

void counter_add(uint f, uint n_4) {
    uint _e6 = atomicAdd(_group_0_binding_8_cs[(2u * f)], n_4);
    if (((_e6 + n_4) < _e6)) {
        uint _e16 = atomicAdd(_group_0_binding_8_cs[((2u * f) + 1u)], 1u);
        return;
    } else {
        return;
    }
}

Shaded shade_connection(Connection c_6, vec3 x_8, vec3 n_5, Material m_1) {
    Shaded s_7 = Shaded(vec3(0.0), vec3(0.0), vec3(0.0));
    s_7.e = c_6.e;
    s_7.diffuse = vec3(0.0);
    s_7.specular = vec3(0.0);
    Shaded _e13 = s_7;
    return _e13;
}

Shaded shade_pick_traced(uint li_5, vec3 x_9, vec3 n_6, vec3 r_6, vec4 rl_4, Material m_2, float w_7, float u1_3, float u2_3, float eps_2, bool trace_3) {
    Connection _e12 = connect_traced(li_5, x_9, n_6, n_6, 1.0, w_7, u1_3, u2_3, eps_2, trace_3);
    Shaded _e13 = shade_connection(_e12, x_9, n_6, m_2);
    return _e13;
}

Shaded shade_pick(uint li_6, vec3 x_10, vec3 n_7, vec3 r_7, vec4 rl_5, Material m_3, float w_8, float u1_4, float u2_4, float eps_3) {
    Shaded _e11 = shade_pick_traced(li_6, x_10, n_7, r_7, rl_5, m_3, w_8, u1_4, u2_4, eps_3, true);
    return _e11;
}

Shaded add(Shaded a_6, Shaded b_6) {
    return Shaded((a_6.e + b_6.e), (a_6.diffuse + b_6.diffuse), (a_6.specular + b_6.specular));
}

Shaded scaled(Shaded s_8, vec3 w_9) {
    return Shaded((s_8.e * w_9), (s_8.diffuse * w_9), (s_8.specular * w_9));
}

uint[8] first_holders(uvec2 keys_1[8], bool held_1[8]) {
    uint first[8] = uint[8](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    uint k_4 = 0u;
    uint j_2 = 0u;
    bool local_24 = false;
    bool local_25 = false;
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
            j_2 = 0u;
            bool loop_init_7 = true;
            while(true) {
                if (!loop_init_7) {
                    uint _e42 = j_2;
                    j_2 = (_e42 + 1u);
                }
                loop_init_7 = false;
                uint _e17 = j_2;
                uint _e18 = k_4;
                if ((_e17 < _e18)) {
                    uint _e22 = k_4;
                    local_24 = held_1[_e22];
                } else {
                    local_24 = false;
                }
                bool _e25 = local_24;
                if (_e25) {
                } else {
                    break;
                }
                {
                    uint _e26 = j_2;
                    if (held_1[_e26]) {
                        uint _e30 = j_2;
                        uint _e32 = k_4;
                        local_25 = all(equal(keys_1[_e30], keys_1[_e32]));
                    } else {
                        local_25 = false;
                    }
                    bool _e37 = local_25;
                    if (_e37) {
                        uint _e38 = k_4;
                        uint _e40 = j_2;
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
    return s_9.e;
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
    vec3 total = vec3(0.0);
    uint count = 0u;
    uint hc = 0u;
    float threshold[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    uint start = 0u;
    uint j = 0u;
    bool local_4 = false;
    uint q = 0u;
    bool local_5 = false;
    uvec2 keys[8] = uvec2[8](uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u));
    bool held[8] = bool[8](false, false, false, false, false, false, false, false);
    uint k = 0u;
    uint k_1 = 0u;
    vec3 w = vec3(0.0);
    uint j_1 = 0u;
    bool local_6 = false;
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
    vec3 x_11 = _e35.xyz;
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
        local_3 = all(lessThanEqual(abs(x_11), vec3(3.4028235e38)));
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
    vec4 _e78 = lobe;
    vec4 _e79 = range_lobe(_e78);
    float _e82 = _group_0_binding_0_cs.shadow_offset;
    vec3 _e85 = _group_0_binding_0_cs.eye;
    float eps_4 = (_e82 * length((_e85 - x_11)));
    uint _e91 = _group_0_binding_0_cs.seed;
    uint _e95 = _group_0_binding_0_cs.width;
    uint _e101 = _group_0_binding_0_cs.frame;
    uint _e102 = point_stream(_e91, ((gid.y * _e95) + gid.x), _e101);
    uint _e103 = pick_stream(_e102);
    h = _e103;
    hc = _e102;
    TileWalk _e124 = tile_walk_begin(lid, x_11, _e79.w, has_3);
    bool loop_init_8 = true;
    while(true) {
        if (!loop_init_8) {
            uint _e223 = start;
            start = (_e223 + TILE_LIST);
        }
        loop_init_8 = false;
        uint _e127 = start;
        if ((_e127 < _e124.total)) {
        } else {
            break;
        }
        {
            uint _e130 = start;
            uint _e131 = tile_walk_fill(lid, _e124, _e130);
            j = 0u;
            bool loop_init_9 = true;
            while(true) {
                if (!loop_init_9) {
                    uint _e221 = j;
                    j = (_e221 + 1u);
                }
                loop_init_9 = false;
                uint _e134 = j;
                if ((_e134 < _e131)) {
                } else {
                    break;
                }
                {
                    uint _e137 = j;
                    uint b_7 = tile_list[_e137];
                    if (!(!(has_3))) {
                        BshNode _e146 = _group_1_binding_4_cs[b_7];
                        vec3 _e147 = r;
                        bool _e148 = bsh_reaches(_e146, x_11, _e147, _e79);
                        local_4 = !(_e148);
                    } else {
                        local_4 = true;
                    }
                    bool _e151 = local_4;
                    if (_e151) {
                        continue;
                    }
                    uint li_7 = _group_1_binding_4_cs[b_7].light;
                    uint _e156 = count;
                    count = (_e156 + 1u);
                    uint _e159 = h;
                    uint _e160 = pcg_hash(_e159);
                    h = _e160;
                    uint _e161 = h;
                    float _e162 = xi_from_bits(_e161);
                    uint _e163 = h;
                    uint _e164 = pcg_hash(_e163);
                    h = _e164;
                    uint _e165 = h;
                    float _e166 = xi_from_bits(_e165);
                    vec2 u_4 = vec2(_e162, _e166);
                    vec3 _e168 = n;
                    vec3 _e169 = r;
                    Material _e170 = m;
                    Shaded _e175 = shade_pick_traced(li_7, x_11, _e168, _e169, _e79, _e170, 1.0, u_4.x, u_4.y, eps_4, false);
                    vec3 _e176 = output_of(_e175);
                    uint _e178 = evaluations;
                    evaluations = (_e178 + 1u);
                    float _e181 = resample_target(_e176);
                    if ((_e181 > 0.0)) {
                        vec3 _e184 = total;
                        total = (_e184 + _e176);
                        q = 0u;
                        bool loop_init_10 = true;
                        while(true) {
                            if (!loop_init_10) {
                                uint _e218 = q;
                                q = (_e218 + 1u);
                            }
                            loop_init_10 = false;
                            uint _e188 = q;
                            if ((_e188 < K)) {
                            } else {
                                break;
                            }
                            {
                                uint _e191 = q;
                                float _e193 = slot_target(_e176, _e191, K);
                                vec3 _e194 = total;
                                uint _e195 = q;
                                float _e197 = slot_target(_e194, _e195, K);
                                if ((_e193 > 0.0)) {
                                    uint _e202 = q;
                                    float _e204 = threshold[_e202];
                                    local_5 = (_e197 > _e204);
                                } else {
                                    local_5 = false;
                                }
                                bool _e207 = local_5;
                                if (_e207) {
                                    uint _e208 = q;
                                    slot_light[_e208] = li_7;
                                    uint _e210 = q;
                                    slot_u[_e210] = u_4;
                                    uint _e212 = q;
                                    slot_p[_e212] = _e193;
                                    uint _e214 = q;
                                    float _e216 = next_threshold(_e197, hc);
                                    threshold[_e214] = _e216;
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
        }
        return;
    }
    bool loop_init_11 = true;
    while(true) {
        if (!loop_init_11) {
            uint _e252 = k;
            k = (_e252 + 1u);
        }
        loop_init_11 = false;
        uint _e234 = k;
        if ((_e234 < K)) {
        } else {
            break;
        }
        {
            uint _e237 = k;
            uint _e239 = k;
            uint _e241 = slot_light[_e239];
            keys[_e237] = uvec2(_e241, 0u);
            uint _e244 = k;
            uint _e246 = k;
            float _e248 = slot_p[_e246];
            held[_e244] = (_e248 > 0.0);
        }
    }
    uvec2 _e254[8] = keys;
    bool _e255[8] = held;
    uint _e256[8] = first_holders(_e254, _e255);
    bool loop_init_12 = true;
    while(true) {
        if (!loop_init_12) {
            uint _e320 = k_1;
            k_1 = (_e320 + 1u);
        }
        loop_init_12 = false;
        uint _e259 = k_1;
        if ((_e259 < K)) {
        } else {
            break;
        }
        {
            w = vec3(0.0);
            uint _e265 = k_1;
            uint _e267 = k_1;
            bool first_1 = (_e256[_e265] == _e267);
            uint _e269 = k_1;
            j_1 = _e269;
            bool loop_init_13 = true;
            while(true) {
                if (!loop_init_13) {
                    uint _e297 = j_1;
                    j_1 = (_e297 + 1u);
                }
                loop_init_13 = false;
                uint _e271 = j_1;
                if ((_e271 < K)) {
                    local_6 = first_1;
                } else {
                    local_6 = false;
                }
                bool _e277 = local_6;
                if (_e277) {
                } else {
                    break;
                }
                {
                    uint _e278 = j_1;
                    uint _e280 = k_1;
                    if ((_e256[_e278] == _e280)) {
                        vec3 _e282 = w;
                        vec3 _e283 = total;
                        uint _e284 = j_1;
                        float _e286 = slot_target(_e283, _e284, K);
                        uint _e287 = j_1;
                        float _e289 = slot_p[_e287];
                        uint _e291 = j_1;
                        vec3 _e293 = slot_share(_e291, K);
                        w = (_e282 + ((_e286 / _e289) * _e293));
                    }
                }
            }
            if (first_1) {
                Shaded _e299 = t;
                uint _e300 = k_1;
                uint _e302 = slot_light[_e300];
                vec3 _e303 = n;
                vec3 _e304 = r;
                Material _e305 = m;
                uint _e307 = k_1;
                float _e310 = slot_u[_e307].x;
                uint _e311 = k_1;
                float _e314 = slot_u[_e311].y;
                Shaded _e315 = shade_pick(_e302, x_11, _e303, _e304, _e79, _e305, 1.0, _e310, _e314, eps_4);
                vec3 _e316 = w;
                Shaded _e317 = scaled(_e315, _e316);
                Shaded _e318 = add(_e299, _e317);
                t = _e318;
            }
        }
    }
    vec3 _e324 = t.e;
    uint _e325 = count;
    imageStore(_group_0_binding_3_cs, texel_1, vec4(_e324, float(_e325)));
    counter_add(DIRECT_COUNT_PIXELS, 1u);
    uint _e331 = count;
    counter_add(DIRECT_COUNT_CANDIDATES, _e331);
    uint _e334 = evaluations;
    counter_add(DIRECT_COUNT_EVALUATIONS, _e334);
    uint _e337 = rays_cast;
    counter_add(DIRECT_COUNT_RAYS, _e337);
    uint _e340 = nodes_visited;
    counter_add(DIRECT_COUNT_NODES, _e340);
    return;
}

