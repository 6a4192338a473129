#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

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
struct ShadeParams {
    uint point_count;
    uint seed;
    uint frame;
    float eps;
};
struct BshNode {
    vec3 center;
    float radius;
    uint child;
    uint next;
    uint light;
    float extent;
};
struct Picks {
    uint light[8];
    uint n;
};
struct BshCursor {
    uint i;
    uint end;
    uint next;
    vec2 cone;
};
struct Connection {
    vec3 e;
    vec3 y;
    float cos_x;
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

layout(std430) readonly buffer type_8_block_0Compute { BshNode _group_0_binding_6_cs[]; };

layout(std430) readonly buffer type_12_block_1Compute { GpuLight _group_0_binding_3_cs[]; };

layout(std430) readonly buffer type_4_block_2Compute { float _group_0_binding_5_cs[]; };

layout(std430) readonly buffer type_4_block_3Compute { float _group_0_binding_4_cs[]; };

layout(std140) uniform ShadeParams_block_4Compute { ShadeParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_13_block_5Compute { vec4 _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_13_block_6Compute { vec4 _group_0_binding_2_cs[]; };

layout(std430) buffer type_13_block_7Compute { vec4 _group_0_binding_9_cs[]; };


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

bool sphere_contains_point(vec3 c, float r, vec3 x_1) {
    vec3 v_2 = (x_1 - c);
    return (dot(v_2, v_2) <= (r * r));
}

float inverse_square(float d2_2) {
    return (1.0 / max(d2_2, MIN_D2_));
}

float connection_factor(float cos_x, float d2_3, float rt2_1, float w) {
    float _e4 = inverse_square(d2_3);
    float _e6 = slc_weight(rt2_1, d2_3);
    return (((cos_x * _e4) * _e6) * w);
}

float connection_cosine(vec3 x_2, vec3 y, vec3 n, vec3 ng, float r2_1) {
    bool local = false;
    bool local_1 = false;
    vec3 v_3 = (x_2 - y);
    float d2_6 = dot(v_3, v_3);
    bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local = !((d2_6 > 0.0));
    } else {
        local = true;
    }
    bool _e16 = local;
    if (_e16) {
        return 0.0;
    }
    vec3 w_4 = (v_3 / vec3(sqrt(d2_6)));
    float cos_x_1 = -(dot(n, w_4));
    if (!(!((cos_x_1 > 0.0)))) {
        local_1 = !((dot(ng, w_4) < 0.0));
    } else {
        local_1 = true;
    }
    bool _e34 = local_1;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float triangle_lobe(vec3 n_1, float area, vec3 w_1) {
    return (area * max(dot(n_1, w_1), 0.0));
}

vec3 triangle_sample(vec3 a_2, vec3 b_2, vec3 c_1, float u1_, float u2_) {
    float su = sqrt(u1_);
    float b0_ = (1.0 - su);
    float b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_1 * ((1.0 - b0_) - b1_)));
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

uint mul_hi_u32_(uint a_3, uint b_3) {
    uint a_lo = (a_3 & 65535u);
    uint a_hi = (a_3 >> 16u);
    uint b_lo = (b_3 & 65535u);
    uint b_hi = (b_3 >> 16u);
    uint ll = (a_lo * b_lo);
    uint lh = (a_lo * b_hi);
    uint hl = (a_hi * b_lo);
    uint hh = (a_hi * b_hi);
    uint mid = (((ll >> 16u) + (lh & 65535u)) + (hl & 65535u));
    return (((hh + (lh >> 16u)) + (hl >> 16u)) + (mid >> 16u));
}

uint uniform_index(uint n_2, uint hi, uint lo) {
    uint _e3 = mul_lo_u32_(hi, n_2);
    uint _e4 = mul_hi_u32_(hi, n_2);
    uint _e5 = mul_hi_u32_(lo, n_2);
    if ((_e3 > (4294967295u - _e5))) {
        return (_e4 + 1u);
    }
    return _e4;
}

uint reservoir_slot(uint n_3, uint k, uint hi_1, uint lo_1) {
    if ((n_3 <= k)) {
        return (n_3 - 1u);
    }
    uint _e7 = uniform_index(n_3, hi_1, lo_1);
    if ((_e7 < k)) {
        return _e7;
    }
    return k;
}

bool reservoir_takes(uint n_4) {
    return (n_4 < RESERVOIR_FULL);
}

float reservoir_weight(uint n_5, uint k_1) {
    float _e2 = to_f32_(n_5);
    float _e3 = to_f32_(k_1);
    return max((_e2 / _e3), 1.0);
}

float cone_cos_of(vec3 v, float d2_4, float a_4, vec3 d) {
    bool local_2 = false;
    bool local_3 = false;
    float vd = dot(v, d);
    float h2_ = (d2_4 - (a_4 * a_4));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_3 = ((vd * vd) >= h2_);
        } else {
            local_3 = false;
        }
        bool _e19 = local_3;
        local_2 = _e19;
    } else {
        local_2 = true;
    }
    bool _e21 = local_2;
    if (_e21) {
        return 1.0;
    }
    vec3 c_6 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_6, c_6)) * a_4)) / d2_4), 1.0);
}

float cone_cos_toward(vec3 center, float radius, vec3 p, vec3 d_1) {
    vec3 v_4 = (center - p);
    float _e6 = cone_cos_of(v_4, dot(v_4, v_4), radius, d_1);
    return _e6;
}

float range_scale_at(vec4 rl, float cos_t) {
    float t = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t * t))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(vec4 rl_1, vec3 center_1, float radius_1, vec3 p_1, vec3 r_1) {
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_1);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

vec3 triangle_normal(vec3 a_5, vec3 b_4, vec3 c_2) {
    bool local_4 = false;
    vec3 n_9 = cross((b_4 - a_5), (c_2 - a_5));
    float l2_ = dot(n_9, n_9);
    if (!(!((l2_ > 0.0)))) {
        local_4 = !((l2_ < 3e38));
    } else {
        local_4 = true;
    }
    bool _e17 = local_4;
    if (_e17) {
        return vec3(0.0, 0.0, 0.0);
    }
    return (n_9 / vec3(sqrt(l2_)));
}

vec3 light_intensity(GpuLight l, vec3 w_3) {
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 3u: {
            vec3 _e8 = triangle_normal(l.p0_, l.p1_, l.p2_);
            float _e10 = triangle_lobe(_e8, l.a, w_3);
            return (l.intensity * _e10);
        }
        default: {
            return vec3(0.0);
        }
    }
}

vec3 light_point(GpuLight l_1, float u1_1, float u2_1) {
    if ((l_1.kind == LIGHT_TRIANGLE)) {
        vec3 _e9 = triangle_sample(l_1.p0_, l_1.p1_, l_1.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_1.p0_;
}

bool occluded(vec3 a_6, vec3 b_5) {
    return false;
}

BshNode bsh_node(uint nodes, uint i) {
    BshNode _e4 = _group_0_binding_6_cs[i];
    return _e4;
}

uint bsh_count(uint nodes_1) {
    return uint(_group_0_binding_6_cs.length());
}

uint bsh_first(uint nodes_2) {
    uint _e1 = bsh_count(nodes_2);
    if ((_e1 > 0u)) {
        return 0u;
    }
    return BSH_NONE;
}

float bsh_inner_scale(float a_7, vec3 v_1, float d2_5, vec3 r_2, vec4 rl_2) {
    float _e5 = cone_cos_of(v_1, d2_5, a_7, r_2);
    float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_3, vec3 x_3, vec3 r_3, vec4 rl_3) {
    bool local_5 = false;
    bool local_6 = false;
    bool _e6 = sphere_contains_point(node_3.center, node_3.radius, x_3);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_3.center, (node_3.radius * (rl_3.w * 1.0001)), x_3);
        local_5 = !(_e20);
    } else {
        local_5 = true;
    }
    bool _e23 = local_5;
    if (_e23) {
        return false;
    }
    vec3 v_5 = (x_3 - node_3.center);
    float d2_7 = dot(v_5, v_5);
    float _e29 = bsh_reach_bound(node_3, rl_3.w);
    if ((d2_7 > (_e29 * _e29))) {
        return false;
    }
    if ((node_3.child == BSH_NONE)) {
        float _e38 = range_scale_toward(rl_3, node_3.center, node_3.extent, x_3, r_3);
        float _e41 = bsh_scaled_radius(node_3, sqrt(_e38));
        bool _e42 = sphere_contains_point(node_3.center, _e41, x_3);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_3.extent, -(v_5), d2_7, r_3, rl_3);
    float s_c = (_e45 * 1.001);
    float _e50 = bsh_range_bound(node_3);
    float reach = (node_3.extent + (sqrt(s_c) * _e50));
    if ((d2_7 <= ((node_3.radius * node_3.radius) * s_c))) {
        local_6 = (d2_7 <= (reach * reach));
    } else {
        local_6 = false;
    }
    bool _e63 = local_6;
    return _e63;
}

uint bsh_next_leaf_lobe(uint nodes_3, uint start, vec3 x_4, vec3 r_4, vec4 rl_4) {
    uint i_1 = 0u;
    i_1 = start;
    while(true) {
        uint _e6 = i_1;
        if ((_e6 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e9 = i_1;
            BshNode _e10 = bsh_node(nodes_3, _e9);
            bool _e11 = bsh_reaches(_e10, x_4, r_4, rl_4);
            if (_e11) {
                if ((_e10.child == BSH_NONE)) {
                    if (((_e10.light & BSH_TAIL) == 0u)) {
                        uint _e20 = i_1;
                        return _e20;
                    }
                    i_1 = _e10.next;
                } else {
                    i_1 = _e10.child;
                }
            } else {
                i_1 = _e10.next;
            }
        }
    }
    return BSH_NONE;
}

BshCursor bsh_cursor(vec3 x_5, vec3 r_5, vec4 rl_5) {
    BshCursor c_3 = BshCursor(0u, 0u, 0u, vec2(0.0));
    c_3.i = 0u;
    c_3.end = 0u;
    uint _e10 = bsh_first(BSH);
    c_3.next = _e10;
    c_3.cone = vec2(0.0);
    BshCursor _e14 = c_3;
    return _e14;
}

uint bsh_cursor_next(inout BshCursor c_4, vec3 x_6, vec3 r_6, vec4 rl_6) {
    uint _e6 = c_4.next;
    uint _e7 = bsh_next_leaf_lobe(BSH, _e6, x_6, r_6, rl_6);
    if ((_e7 != BSH_NONE)) {
        uint _e14 = _group_0_binding_6_cs[_e7].next;
        c_4.next = _e14;
    }
    return _e7;
}

void reservoir_offer(inout Picks picks, inout uint h_1, uint light) {
    uint _e4 = picks.n;
    bool _e5 = reservoir_takes(_e4);
    if (_e5) {
        uint _e7 = picks.n;
        picks.n = (_e7 + 1u);
        uint _e10 = h_1;
        uint _e11 = pcg_hash(_e10);
        h_1 = _e11;
        uint hi_2 = h_1;
        uint _e13 = h_1;
        uint _e14 = pcg_hash(_e13);
        h_1 = _e14;
        uint _e16 = picks.n;
        uint _e18 = h_1;
        uint _e19 = reservoir_slot(_e16, K, hi_2, _e18);
        if ((_e19 < K)) {
            picks.light[_e19] = light;
            return;
        } else {
            return;
        }
    } else {
        return;
    }
}

Picks bsh_collect(vec3 x_7, vec3 r_7, vec4 rl_7, uint seed_1) {
    Picks picks_1 = Picks(uint[8](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u), 0u);
    uint h_2 = 0u;
    BshCursor cur = BshCursor(0u, 0u, 0u, vec2(0.0));
    uint i_2 = 0u;
    picks_1.n = 0u;
    h_2 = seed_1;
    BshCursor _e8 = bsh_cursor(x_7, r_7, rl_7);
    cur = _e8;
    uint _e10 = bsh_cursor_next(cur, x_7, r_7, rl_7);
    i_2 = _e10;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e20 = bsh_cursor_next(cur, x_7, r_7, rl_7);
            i_2 = _e20;
        }
        loop_init = false;
        uint _e12 = i_2;
        if ((_e12 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e16 = i_2;
            uint _e19 = _group_0_binding_6_cs[_e16].light;
            reservoir_offer(picks_1, h_2, _e19);
        }
    }
    Picks _e21 = picks_1;
    return _e21;
}

Connection connect_record(GpuLight l_2, vec3 x_8, vec3 n_6, vec3 ng_1, float r2_2, float rt2_2, float w_res, float u1_2, float u2_2, float eps, bool trace) {
    Connection c_5 = Connection(vec3(0.0), vec3(0.0), 0.0);
    bool local_7 = false;
    bool local_8 = false;
    c_5.e = vec3(0.0);
    vec3 _e16 = light_point(l_2, u1_2, u2_2);
    c_5.y = _e16;
    vec3 _e19 = c_5.y;
    float _e20 = connection_cosine(x_8, _e19, n_6, ng_1, r2_2);
    c_5.cos_x = _e20;
    float _e22 = c_5.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace) {
            vec3 _e33 = c_5.y;
            bool _e34 = occluded((x_8 + (ng_1 * eps)), _e33);
            local_8 = _e34;
        } else {
            local_8 = false;
        }
        bool _e36 = local_8;
        local_7 = _e36;
    } else {
        local_7 = true;
    }
    bool _e38 = local_7;
    if (_e38) {
        Connection _e39 = c_5;
        return _e39;
    }
    vec3 _e41 = c_5.y;
    vec3 v_6 = (x_8 - _e41);
    float d2_8 = dot(v_6, v_6);
    vec3 _e48 = light_intensity(l_2, (v_6 / vec3(sqrt(d2_8))));
    float _e50 = c_5.cos_x;
    float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_5.e = (_e48 * _e51);
    Connection _e53 = c_5;
    return _e53;
}

Connection connect_traced(uint li, vec3 x_9, vec3 n_7, vec3 ng_2, float s_1, float w_res_1, float u1_3, float u2_3, float eps_1, bool trace_1) {
    GpuLight _e12 = _group_0_binding_3_cs[li];
    float _e15 = _group_0_binding_5_cs[li];
    float _e19 = _group_0_binding_4_cs[li];
    Connection _e21 = connect_record(_e12, x_9, n_7, ng_2, (s_1 * _e15), (s_1 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_1);
    return _e21;
}

Connection connect(uint li_1, vec3 x_10, vec3 n_8, vec3 ng_3, float s_2, float w_res_2, float u1_4, float u2_4, float eps_2) {
    Connection _e10 = connect_traced(li_1, x_10, n_8, ng_3, s_2, w_res_2, u1_4, u2_4, eps_2, true);
    return _e10;
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    uint h = 0u;
    vec3 e = vec3(0.0);
    uint s = 0u;
    uint i_3 = gid.x;
    uint _e4 = _group_0_binding_0_cs.point_count;
    if ((i_3 >= _e4)) {
        return;
    }
    vec4 p_2 = _group_0_binding_1_cs[i_3];
    if ((p_2.w <= 0.0)) {
        _group_0_binding_9_cs[i_3] = vec4(0.0);
        return;
    }
    vec3 x_11 = p_2.xyz;
    vec4 _e19 = _group_0_binding_2_cs[i_3];
    vec3 n_10 = _e19.xyz;
    uint _e23 = _group_0_binding_0_cs.seed;
    uint _e26 = _group_0_binding_0_cs.frame;
    uint _e27 = point_stream(_e23, i_3, _e26);
    Picks _e33 = bsh_collect(x_11, x_11, vec4(1.0, 0.0, 1.0, 1.0), _e27);
    float _e36 = reservoir_weight(_e33.n, K);
    uint _e37 = pick_stream(_e27);
    h = _e37;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e69 = s;
            s = (_e69 + 1u);
        }
        loop_init_1 = false;
        uint _e44 = s;
        if ((_e44 < min(_e33.n, K))) {
        } else {
            break;
        }
        {
            uint _e49 = h;
            uint _e50 = pcg_hash(_e49);
            h = _e50;
            uint _e51 = h;
            float _e52 = xi_from_bits(_e51);
            uint _e53 = h;
            uint _e54 = pcg_hash(_e53);
            h = _e54;
            vec3 _e55 = e;
            uint _e57 = s;
            uint _e60 = h;
            float _e61 = xi_from_bits(_e60);
            float _e64 = _group_0_binding_0_cs.eps;
            Connection _e65 = connect(_e33.light[_e57], x_11, n_10, n_10, 1.0, _e36, _e52, _e61, _e64);
            e = (_e55 + _e65.e);
        }
    }
    vec3 _e73 = e;
    _group_0_binding_9_cs[i_3] = vec4(_e73, float(_e33.n));
    return;
}

