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
struct GeoHit {
    float t;
    uint tri;
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

layout(std430) readonly buffer type_4_block_0Compute { float _group_1_binding_0_cs[]; };

layout(std430) readonly buffer type_7_block_1Compute { GpuGeoNode _group_0_binding_7_cs[]; };

layout(std430) readonly buffer type_8_block_2Compute { GpuTriangle _group_0_binding_8_cs[]; };

layout(std430) readonly buffer type_11_block_3Compute { BshNode _group_0_binding_6_cs[]; };

layout(std430) readonly buffer type_15_block_4Compute { GpuLight _group_0_binding_3_cs[]; };

layout(std430) readonly buffer type_4_block_5Compute { float _group_0_binding_5_cs[]; };

layout(std430) readonly buffer type_4_block_6Compute { float _group_0_binding_4_cs[]; };

layout(std140) uniform ShadeParams_block_7Compute { ShadeParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_16_block_8Compute { vec4 _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_16_block_9Compute { vec4 _group_0_binding_2_cs[]; };

layout(std430) buffer type_16_block_10Compute { vec4 _group_0_binding_9_cs[]; };


float at(uint tab, uint i) {
    float _e4 = _group_1_binding_0_cs[i];
    return _e4;
}

float to_f32_(uint u) {
    return float(u);
}

uint to_u32_(float x) {
    return uint(x);
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

uint pcg_hash(uint x_1) {
    uint _e2 = mul_lo_u32_(x_1, 747796405u);
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

bool sphere_contains_point(vec3 c, float r, vec3 x_2) {
    vec3 v_2 = (x_2 - c);
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

float connection_cosine(vec3 x_3, vec3 y, vec3 n, vec3 ng, float r2_1) {
    bool local = false;
    bool local_1 = false;
    vec3 v_3 = (x_3 - y);
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

float spot_falloff(float cos_theta, float cos_outer, float cos_inner, float shape) {
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t_1 = clamp(((cos_theta - cos_outer) / (cos_inner - cos_outer)), 0.0, 1.0);
    return ((shape > 0.5) ? (t_1 * t_1) : ((t_1 * t_1) * (3.0 - (2.0 * t_1))));
}

float atan_portable(float x_4) {
    float base = 0.0;
    float t = 0.0;
    float a_8 = abs(x_4);
    t = a_8;
    if ((a_8 > 2.4142137)) {
        base = 1.5707964;
        t = (-1.0 / a_8);
    } else {
        if ((a_8 > 0.41421357)) {
            base = 0.7853982;
            t = ((a_8 - 1.0) / (a_8 + 1.0));
        }
    }
    float _e18 = t;
    float _e19 = t;
    float z = (_e18 * _e19);
    float _e21 = base;
    float _e33 = t;
    float _e35 = t;
    float r_8 = (_e21 + (((((((((0.080537446 * z) - 0.13877685) * z) + 0.19977711) * z) - 0.3333295) * z) * _e33) + _e35));
    return ((x_4 < 0.0) ? -(r_8) : r_8);
}

float atan2_portable(float y_1, float x_5) {
    if ((x_5 == 0.0)) {
        if ((y_1 > 0.0)) {
            return 1.5707964;
        }
        if ((y_1 < 0.0)) {
            return -1.5707964;
        }
        return 0.0;
    }
    float _e12 = atan_portable((y_1 / x_5));
    if ((x_5 > 0.0)) {
        return _e12;
    }
    if ((y_1 >= 0.0)) {
        return (_e12 + 3.1415927);
    }
    return (_e12 - 3.1415927);
}

float ies_fold_c(float c_1, float h_first, float h_last) {
    float a_2 = 0.0;
    a_2 = (c_1 - (360.0 * floor((c_1 / 360.0))));
    if ((h_last <= 0.0)) {
        return 0.0;
    }
    if ((h_last <= 90.0)) {
        float _e15 = a_2;
        if ((_e15 > 180.0)) {
            float _e18 = a_2;
            a_2 = (360.0 - _e18);
        }
        float _e21 = a_2;
        if ((_e21 > 90.0)) {
            float _e24 = a_2;
            a_2 = (180.0 - _e24);
        }
        float _e27 = a_2;
        return _e27;
    }
    if ((h_first >= 90.0)) {
        float _e30 = a_2;
        if ((_e30 < 90.0)) {
            float _e33 = a_2;
            a_2 = (180.0 - _e33);
        } else {
            float _e36 = a_2;
            if ((_e36 > 270.0)) {
                float _e39 = a_2;
                a_2 = (540.0 - _e39);
            }
        }
        float _e42 = a_2;
        return _e42;
    }
    if ((h_last <= 180.0)) {
        float _e45 = a_2;
        if ((_e45 > 180.0)) {
            float _e48 = a_2;
            a_2 = (360.0 - _e48);
        }
        float _e51 = a_2;
        return _e51;
    }
    float _e52 = a_2;
    return _e52;
}

uint ies_segment(uint tab_1, uint start, uint n_1, float x_6) {
    uint lo = 0u;
    uint hi = 0u;
    if ((n_1 < 2u)) {
        return 0u;
    }
    hi = (n_1 - 1u);
    while(true) {
        uint _e12 = hi;
        uint _e13 = lo;
        if (((_e12 - _e13) > 1u)) {
        } else {
            break;
        }
        {
            uint _e17 = lo;
            uint _e18 = hi;
            uint mid = ((_e17 + _e18) >> 1u);
            float _e23 = at(tab_1, (start + mid));
            if ((_e23 <= x_6)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
    uint _e25 = lo;
    return _e25;
}

float ies_lerp_t(float a0_, float a1_, float x_7) {
    if ((a1_ <= a0_)) {
        return 0.0;
    }
    return clamp(((x_7 - a0_) / (a1_ - a0_)), 0.0, 1.0);
}

float ies_candela(uint tab_2, uint base_1, float gamma, float c_2) {
    bool local_2 = false;
    float _e4 = at(tab_2, base_1);
    uint _e5 = to_u32_(_e4);
    float _e8 = at(tab_2, (base_1 + 1u));
    uint _e9 = to_u32_(_e8);
    uint v0_ = (base_1 + 2u);
    uint h0_ = (v0_ + _e5);
    uint c0_ = (h0_ + _e9);
    float _e14 = at(tab_2, v0_);
    if (!((gamma < _e14))) {
        float _e22 = at(tab_2, ((v0_ + _e5) - 1u));
        local_2 = (gamma > _e22);
    } else {
        local_2 = true;
    }
    bool _e25 = local_2;
    if (_e25) {
        return 0.0;
    }
    float _e27 = at(tab_2, h0_);
    float _e31 = at(tab_2, ((h0_ + _e9) - 1u));
    float _e32 = ies_fold_c(c_2, _e27, _e31);
    uint _e33 = ies_segment(tab_2, v0_, _e5, gamma);
    uint _e34 = ies_segment(tab_2, h0_, _e9, _e32);
    uint iv1_ = min((_e33 + 1u), (_e5 - 1u));
    uint ih1_ = min((_e34 + 1u), (_e9 - 1u));
    float _e46 = at(tab_2, (v0_ + _e33));
    float _e48 = at(tab_2, (v0_ + iv1_));
    float _e49 = ies_lerp_t(_e46, _e48, gamma);
    float _e51 = at(tab_2, (h0_ + _e34));
    float _e53 = at(tab_2, (h0_ + ih1_));
    float _e54 = ies_lerp_t(_e51, _e53, _e32);
    float _e58 = at(tab_2, ((c0_ + (_e34 * _e5)) + _e33));
    float _e65 = at(tab_2, ((c0_ + (_e34 * _e5)) + iv1_));
    float a_9 = ((_e58 * (1.0 - _e49)) + (_e65 * _e49));
    float _e71 = at(tab_2, ((c0_ + (ih1_ * _e5)) + _e33));
    float _e78 = at(tab_2, ((c0_ + (ih1_ * _e5)) + iv1_));
    float b_5 = ((_e71 * (1.0 - _e49)) + (_e78 * _e49));
    return ((a_9 * (1.0 - _e54)) + (b_5 * _e54));
}

float ies_candela_dir(uint tab_3, uint base_2, float wn, float wr, float ws) {
    float _e9 = atan2_portable(sqrt(((wr * wr) + (ws * ws))), wn);
    float gamma_1 = degrees(_e9);
    bool on_axis = ((abs(wr) + abs(ws)) <= 0.0);
    float _e16 = atan2_portable(ws, wr);
    float c_7 = (on_axis ? 0.0 : degrees(_e16));
    float _e20 = ies_candela(tab_3, base_2, gamma_1, c_7);
    return _e20;
}

float ies_light_candela(uint tab_4, uint base_3, vec3 nadir, vec3 reference, vec3 w_1) {
    vec3 side = cross(reference, nadir);
    float _e9 = ies_candela_dir(tab_4, base_3, dot(w_1, nadir), dot(w_1, reference), dot(w_1, side));
    return _e9;
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

uint mul_hi_u32_(uint a_3, uint b_2) {
    uint a_lo = (a_3 & 65535u);
    uint a_hi = (a_3 >> 16u);
    uint b_lo = (b_2 & 65535u);
    uint b_hi = (b_2 >> 16u);
    uint ll = (a_lo * b_lo);
    uint lh = (a_lo * b_hi);
    uint hl = (a_hi * b_lo);
    uint hh = (a_hi * b_hi);
    uint mid_1 = (((ll >> 16u) + (lh & 65535u)) + (hl & 65535u));
    return (((hh + (lh >> 16u)) + (hl >> 16u)) + (mid_1 >> 16u));
}

uint uniform_index(uint n_2, uint hi_1, uint lo_1) {
    uint _e3 = mul_lo_u32_(hi_1, n_2);
    uint _e4 = mul_hi_u32_(hi_1, n_2);
    uint _e5 = mul_hi_u32_(lo_1, n_2);
    if ((_e3 > (4294967295u - _e5))) {
        return (_e4 + 1u);
    }
    return _e4;
}

uint reservoir_slot(uint n_3, uint k, uint hi_2, uint lo_2) {
    if ((n_3 <= k)) {
        return (n_3 - 1u);
    }
    uint _e7 = uniform_index(n_3, hi_2, lo_2);
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
    bool local_3 = false;
    bool local_4 = false;
    float vd = dot(v, d);
    float h2_ = (d2_4 - (a_4 * a_4));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_4 = ((vd * vd) >= h2_);
        } else {
            local_4 = false;
        }
        bool _e19 = local_4;
        local_3 = _e19;
    } else {
        local_3 = true;
    }
    bool _e21 = local_3;
    if (_e21) {
        return 1.0;
    }
    vec3 c_8 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_8, c_8)) * a_4)) / d2_4), 1.0);
}

float cone_cos_toward(vec3 center, float radius, vec3 p, vec3 d_1) {
    vec3 v_4 = (center - p);
    float _e6 = cone_cos_of(v_4, dot(v_4, v_4), radius, d_1);
    return _e6;
}

float range_scale_at(vec4 rl, float cos_t) {
    float t_2 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_2 * t_2))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(vec4 rl_1, vec3 center_1, float radius_1, vec3 p_1, vec3 r_1) {
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_1);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

float shadow_margin(float len) {
    return (0.0001 * len);
}

float ray_inverse(float x_8) {
    return (1.0 / ((abs(x_8) < 1e-30) ? 1e-30 : x_8));
}

vec3 ray_inverse3_(vec3 d_2) {
    float _e2 = ray_inverse(d_2.x);
    float _e4 = ray_inverse(d_2.y);
    float _e6 = ray_inverse(d_2.z);
    return vec3(_e2, _e4, _e6);
}

float ray_aabb(vec3 o, vec3 inv_d, vec3 bmin, vec3 bmax, float t_max) {
    vec3 t0_ = ((bmin - o) * inv_d);
    vec3 t1_ = ((bmax - o) * inv_d);
    vec3 lo_3 = min(t0_, t1_);
    vec3 hi_3 = max(t0_, t1_);
    float t_in = max(max(lo_3.x, lo_3.y), max(lo_3.z, 0.0));
    float t_out = min(min(hi_3.x, hi_3.y), min(hi_3.z, t_max));
    if ((t_in <= t_out)) {
        return t_in;
    }
    return -1.0;
}

float ray_triangle(vec3 o_1, vec3 d_3, vec3 a_5, vec3 b_3, vec3 c_3, float t_min, float t_max_1) {
    bool local_5 = false;
    bool local_6 = false;
    bool local_7 = false;
    vec3 e1_ = (b_3 - a_5);
    vec3 e2_ = (c_3 - a_5);
    vec3 p_2 = cross(d_3, e2_);
    float det = dot(e1_, p_2);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv = (1.0 / det);
    vec3 s_3 = (o_1 - a_5);
    float u_2 = (dot(s_3, p_2) * inv);
    if (!((u_2 < 0.0))) {
        local_5 = (u_2 > 1.0);
    } else {
        local_5 = true;
    }
    bool _e28 = local_5;
    if (_e28) {
        return -1.0;
    }
    vec3 q = cross(s_3, e1_);
    float v_5 = (dot(d_3, q) * inv);
    if (!((v_5 < 0.0))) {
        local_6 = ((u_2 + v_5) > 1.0);
    } else {
        local_6 = true;
    }
    bool _e42 = local_6;
    if (_e42) {
        return -1.0;
    }
    float t_3 = (dot(e2_, q) * inv);
    if ((t_3 > t_min)) {
        local_7 = (t_3 < t_max_1);
    } else {
        local_7 = false;
    }
    bool _e51 = local_7;
    if (_e51) {
        return t_3;
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
        case 2u: {
            float _e18 = ies_light_candela(0u, l.ies_base, l.p1_, l.p2_, w_3);
            return (l.intensity * _e18);
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
    uint i_1 = 0u;
    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((uint(_group_0_binding_7_cs.length()) == 0u)) {
        GeoHit _e13 = hit;
        return _e13;
    }
    vec3 _e14 = ray_inverse3_(d_4);
    while(true) {
        uint _e21 = node_3;
        GpuGeoNode n_9 = _group_0_binding_7_cs[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_9.bmin, n_9.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_9.count > 0u)) {
                i_1 = n_9.first;
                bool loop_init = true;
                while(true) {
                    if (!loop_init) {
                        uint _e58 = i_1;
                        i_1 = (_e58 + 1u);
                    }
                    loop_init = false;
                    uint _e36 = i_1;
                    if ((_e36 < (n_9.first + n_9.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i_1;
                        GpuTriangle t_4 = _group_0_binding_8_cs[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_4, t_4.v0_, t_4.v1_, t_4.v2_, t_min_1, _e49);
                        if ((_e50 > 0.0)) {
                            hit.t = _e50;
                            uint _e55 = i_1;
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
                    stack[_e63] = (n_9.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_9.first;
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

bool occluded(vec3 a_6, vec3 b_4) {
    vec3 dv = (b_4 - a_6);
    float len_1 = length(dv);
    if ((len_1 <= 0.0)) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    GeoHit _e12 = trace(a_6, (dv / vec3(len_1)), _e7, (len_1 - _e7), true);
    return (_e12.tri != NO_LIGHT);
}

BshNode bsh_node(uint nodes, uint i_2) {
    BshNode _e4 = _group_0_binding_6_cs[i_2];
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

bool bsh_reaches(BshNode node_4, vec3 x_9, vec3 r_3, vec4 rl_3) {
    bool local_8 = false;
    bool local_9 = false;
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_9);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, (node_4.radius * (rl_3.w * 1.0001)), x_9);
        local_8 = !(_e20);
    } else {
        local_8 = true;
    }
    bool _e23 = local_8;
    if (_e23) {
        return false;
    }
    vec3 v_6 = (x_9 - node_4.center);
    float d2_7 = dot(v_6, v_6);
    float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if ((d2_7 > (_e29 * _e29))) {
        return false;
    }
    if ((node_4.child == BSH_NONE)) {
        float _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_9, r_3);
        float _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_9);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_6), d2_7, r_3, rl_3);
    float s_c = (_e45 * 1.001);
    float _e50 = bsh_range_bound(node_4);
    float reach = (node_4.extent + (sqrt(s_c) * _e50));
    if ((d2_7 <= ((node_4.radius * node_4.radius) * s_c))) {
        local_9 = (d2_7 <= (reach * reach));
    } else {
        local_9 = false;
    }
    bool _e63 = local_9;
    return _e63;
}

uint bsh_next_leaf_lobe(uint nodes_3, uint start_1, vec3 x_10, vec3 r_4, vec4 rl_4) {
    uint i_3 = 0u;
    i_3 = start_1;
    while(true) {
        uint _e6 = i_3;
        if ((_e6 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e9 = i_3;
            BshNode _e10 = bsh_node(nodes_3, _e9);
            bool _e11 = bsh_reaches(_e10, x_10, r_4, rl_4);
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
    return BSH_NONE;
}

BshCursor bsh_cursor(vec3 x_11, vec3 r_5, vec4 rl_5) {
    BshCursor c_4 = BshCursor(0u, 0u, 0u, vec2(0.0));
    c_4.i = 0u;
    c_4.end = 0u;
    uint _e10 = bsh_first(BSH);
    c_4.next = _e10;
    c_4.cone = vec2(0.0);
    BshCursor _e14 = c_4;
    return _e14;
}

uint bsh_cursor_next(inout BshCursor c_5, vec3 x_12, vec3 r_6, vec4 rl_6) {
    uint _e6 = c_5.next;
    uint _e7 = bsh_next_leaf_lobe(BSH, _e6, x_12, r_6, rl_6);
    if ((_e7 != BSH_NONE)) {
        uint _e14 = _group_0_binding_6_cs[_e7].next;
        c_5.next = _e14;
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
        uint hi_4 = h_1;
        uint _e13 = h_1;
        uint _e14 = pcg_hash(_e13);
        h_1 = _e14;
        uint _e16 = picks.n;
        uint _e18 = h_1;
        uint _e19 = reservoir_slot(_e16, K, hi_4, _e18);
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

Picks bsh_collect(vec3 x_13, vec3 r_7, vec4 rl_7, uint seed_1) {
    Picks picks_1 = Picks(uint[8](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u), 0u);
    uint h_2 = 0u;
    BshCursor cur = BshCursor(0u, 0u, 0u, vec2(0.0));
    uint i_4 = 0u;
    picks_1.n = 0u;
    h_2 = seed_1;
    BshCursor _e8 = bsh_cursor(x_13, r_7, rl_7);
    cur = _e8;
    uint _e10 = bsh_cursor_next(cur, x_13, r_7, rl_7);
    i_4 = _e10;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e20 = bsh_cursor_next(cur, x_13, r_7, rl_7);
            i_4 = _e20;
        }
        loop_init_1 = false;
        uint _e12 = i_4;
        if ((_e12 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e16 = i_4;
            uint _e19 = _group_0_binding_6_cs[_e16].light;
            reservoir_offer(picks_1, h_2, _e19);
        }
    }
    Picks _e21 = picks_1;
    return _e21;
}

Connection connect_record(GpuLight l_2, vec3 x_14, vec3 n_6, vec3 ng_1, float r2_2, float rt2_2, float w_res, float u1_1, float u2_1, float eps, bool trace_1) {
    Connection c_6 = Connection(vec3(0.0), vec3(0.0), 0.0);
    bool local_10 = false;
    bool local_11 = false;
    c_6.e = vec3(0.0);
    vec3 _e16 = light_point(l_2, u1_1, u2_1);
    c_6.y = _e16;
    vec3 _e19 = c_6.y;
    float _e20 = connection_cosine(x_14, _e19, n_6, ng_1, r2_2);
    c_6.cos_x = _e20;
    float _e22 = c_6.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            vec3 _e33 = c_6.y;
            bool _e34 = occluded((x_14 + (ng_1 * eps)), _e33);
            local_11 = _e34;
        } else {
            local_11 = false;
        }
        bool _e36 = local_11;
        local_10 = _e36;
    } else {
        local_10 = true;
    }
    bool _e38 = local_10;
    if (_e38) {
        Connection _e39 = c_6;
        return _e39;
    }
    vec3 _e41 = c_6.y;
    vec3 v_7 = (x_14 - _e41);
    float d2_8 = dot(v_7, v_7);
    vec3 _e48 = light_intensity(l_2, (v_7 / vec3(sqrt(d2_8))));
    float _e50 = c_6.cos_x;
    float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_6.e = (_e48 * _e51);
    Connection _e53 = c_6;
    return _e53;
}

Connection connect_traced(uint li, vec3 x_15, vec3 n_7, vec3 ng_2, float s_1, float w_res_1, float u1_2, float u2_2, float eps_1, bool trace_2) {
    GpuLight _e12 = _group_0_binding_3_cs[li];
    float _e15 = _group_0_binding_5_cs[li];
    float _e19 = _group_0_binding_4_cs[li];
    Connection _e21 = connect_record(_e12, x_15, n_7, ng_2, (s_1 * _e15), (s_1 * _e19), w_res_1, u1_2, u2_2, eps_1, trace_2);
    return _e21;
}

Connection connect(uint li_1, vec3 x_16, vec3 n_8, vec3 ng_3, float s_2, float w_res_2, float u1_3, float u2_3, float eps_2) {
    Connection _e10 = connect_traced(li_1, x_16, n_8, ng_3, s_2, w_res_2, u1_3, u2_3, eps_2, true);
    return _e10;
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    uint h = 0u;
    vec3 e = vec3(0.0);
    uint s = 0u;
    uint i_5 = gid.x;
    uint _e4 = _group_0_binding_0_cs.point_count;
    if ((i_5 >= _e4)) {
        return;
    }
    vec4 p_3 = _group_0_binding_1_cs[i_5];
    if ((p_3.w <= 0.0)) {
        _group_0_binding_9_cs[i_5] = vec4(0.0);
        return;
    }
    vec3 x_17 = p_3.xyz;
    vec4 _e19 = _group_0_binding_2_cs[i_5];
    vec3 n_10 = _e19.xyz;
    uint _e23 = _group_0_binding_0_cs.seed;
    uint _e26 = _group_0_binding_0_cs.frame;
    uint _e27 = point_stream(_e23, i_5, _e26);
    Picks _e33 = bsh_collect(x_17, x_17, vec4(1.0, 0.0, 1.0, 1.0), _e27);
    float _e36 = reservoir_weight(_e33.n, K);
    uint _e37 = pick_stream(_e27);
    h = _e37;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e69 = s;
            s = (_e69 + 1u);
        }
        loop_init_2 = false;
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
            Connection _e65 = connect(_e33.light[_e57], x_17, n_10, n_10, 1.0, _e36, _e52, _e61, _e64);
            e = (_e55 + _e65.e);
        }
    }
    vec3 _e73 = e;
    _group_0_binding_9_cs[i_5] = vec4(_e73, float(_e33.n));
    return;
}

