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
struct Picks {
    uint light[8];
    uint n;
};
struct Connection {
    vec3 e;
    vec3 y;
    float cos_x;
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
const uint RESERVOIR_FULL = 4294967295u;
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

layout(std430) readonly buffer type_4_block_0Compute { float _group_1_binding_0_cs[]; };

layout(std140) uniform ViewParams_block_1Compute { ViewParams _group_0_binding_0_cs; };

uniform sampler2D _group_0_binding_1_cs;

uniform sampler2D _group_0_binding_2_cs;

layout(rgba32f) writeonly uniform image2D _group_0_binding_3_cs;

layout(std430) readonly buffer type_8_block_2Compute { GpuLight _group_1_binding_1_cs[]; };

layout(std430) readonly buffer type_4_block_3Compute { float _group_1_binding_2_cs[]; };

layout(std430) readonly buffer type_4_block_4Compute { float _group_1_binding_3_cs[]; };

layout(std430) readonly buffer type_9_block_5Compute { BshNode _group_1_binding_4_cs[]; };


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

bool sphere_contains_point(vec3 c, float r_1, vec3 x_2) {
    vec3 v_2 = (x_2 - c);
    return (dot(v_2, v_2) <= (r_1 * r_1));
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
    bool local_2 = false;
    bool local_3 = false;
    vec3 v_3 = (x_3 - y);
    float d2_6 = dot(v_3, v_3);
    bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local_2 = !((d2_6 > 0.0));
    } else {
        local_2 = true;
    }
    bool _e16 = local_2;
    if (_e16) {
        return 0.0;
    }
    vec3 w_6 = (v_3 / vec3(sqrt(d2_6)));
    float cos_x_1 = -(dot(n, w_6));
    if (!((cos_x_1 <= 0.0))) {
        local_3 = (dot(ng, w_6) >= 0.0);
    } else {
        local_3 = true;
    }
    bool _e32 = local_3;
    if (_e32) {
        return 0.0;
    }
    return cos_x_1;
}

float spot_falloff(float cos_theta, float cos_outer, float cos_inner, float shape) {
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t_2 = clamp(((cos_theta - cos_outer) / (cos_inner - cos_outer)), 0.0, 1.0);
    return ((shape > 0.5) ? (t_2 * t_2) : ((t_2 * t_2) * (3.0 - (2.0 * t_2))));
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

float atan_portable(float x_4) {
    float base = 0.0;
    float t_1 = 0.0;
    float a_10 = abs(x_4);
    t_1 = a_10;
    if ((a_10 > 2.4142137)) {
        base = 1.5707964;
        t_1 = (-1.0 / a_10);
    } else {
        if ((a_10 > 0.41421357)) {
            base = 0.7853982;
            t_1 = ((a_10 - 1.0) / (a_10 + 1.0));
        }
    }
    float _e18 = t_1;
    float _e19 = t_1;
    float z = (_e18 * _e19);
    float _e21 = base;
    float _e33 = t_1;
    float _e35 = t_1;
    float r_9 = (_e21 + (((((((((0.080537446 * z) - 0.13877685) * z) + 0.19977711) * z) - 0.3333295) * z) * _e33) + _e35));
    return ((x_4 < 0.0) ? -(r_9) : r_9);
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

float ies_fold_c(float c_2, float h_first, float h_last) {
    float a_3 = 0.0;
    a_3 = (c_2 - (360.0 * floor((c_2 / 360.0))));
    if ((h_last <= 0.0)) {
        return 0.0;
    }
    if ((h_last <= 90.0)) {
        float _e15 = a_3;
        if ((_e15 > 180.0)) {
            float _e18 = a_3;
            a_3 = (360.0 - _e18);
        }
        float _e21 = a_3;
        if ((_e21 > 90.0)) {
            float _e24 = a_3;
            a_3 = (180.0 - _e24);
        }
        float _e27 = a_3;
        return _e27;
    }
    if ((h_first >= 90.0)) {
        float _e30 = a_3;
        if ((_e30 < 90.0)) {
            float _e33 = a_3;
            a_3 = (180.0 - _e33);
        } else {
            float _e36 = a_3;
            if ((_e36 > 270.0)) {
                float _e39 = a_3;
                a_3 = (540.0 - _e39);
            }
        }
        float _e42 = a_3;
        return _e42;
    }
    if ((h_last <= 180.0)) {
        float _e45 = a_3;
        if ((_e45 > 180.0)) {
            float _e48 = a_3;
            a_3 = (360.0 - _e48);
        }
        float _e51 = a_3;
        return _e51;
    }
    float _e52 = a_3;
    return _e52;
}

uint ies_segment(uint tab_1, uint start, uint n_2, float x_6) {
    uint lo = 0u;
    uint hi = 0u;
    if ((n_2 < 2u)) {
        return 0u;
    }
    hi = (n_2 - 1u);
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

float ies_candela(uint tab_2, uint base_1, float gamma, float c_3) {
    bool local_4 = false;
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
        local_4 = (gamma > _e22);
    } else {
        local_4 = true;
    }
    bool _e25 = local_4;
    if (_e25) {
        return 0.0;
    }
    float _e27 = at(tab_2, h0_);
    float _e31 = at(tab_2, ((h0_ + _e9) - 1u));
    float _e32 = ies_fold_c(c_3, _e27, _e31);
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
    float a_11 = ((_e58 * (1.0 - _e49)) + (_e65 * _e49));
    float _e71 = at(tab_2, ((c0_ + (ih1_ * _e5)) + _e33));
    float _e78 = at(tab_2, ((c0_ + (ih1_ * _e5)) + iv1_));
    float b_7 = ((_e71 * (1.0 - _e49)) + (_e78 * _e49));
    return ((a_11 * (1.0 - _e54)) + (b_7 * _e54));
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

float ies_light_candela(uint tab_4, uint base_3, vec3 nadir, vec3 reference, vec3 w_2) {
    vec3 side = cross(reference, nadir);
    float _e9 = ies_candela_dir(tab_4, base_3, dot(w_2, nadir), dot(w_2, reference), dot(w_2, side));
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

uint mul_hi_u32_(uint a_4, uint b_3) {
    uint a_lo = (a_4 & 65535u);
    uint a_hi = (a_4 >> 16u);
    uint b_lo = (b_3 & 65535u);
    uint b_hi = (b_3 >> 16u);
    uint ll = (a_lo * b_lo);
    uint lh = (a_lo * b_hi);
    uint hl = (a_hi * b_lo);
    uint hh = (a_hi * b_hi);
    uint mid_1 = (((ll >> 16u) + (lh & 65535u)) + (hl & 65535u));
    return (((hh + (lh >> 16u)) + (hl >> 16u)) + (mid_1 >> 16u));
}

uint uniform_index(uint n_3, uint hi_1, uint lo_1) {
    uint _e3 = mul_lo_u32_(hi_1, n_3);
    uint _e4 = mul_hi_u32_(hi_1, n_3);
    uint _e5 = mul_hi_u32_(lo_1, n_3);
    if ((_e3 > (4294967295u - _e5))) {
        return (_e4 + 1u);
    }
    return _e4;
}

uint reservoir_slot(uint n_4, uint k_1, uint hi_2, uint lo_2) {
    if ((n_4 <= k_1)) {
        return (n_4 - 1u);
    }
    uint _e7 = uniform_index(n_4, hi_2, lo_2);
    if ((_e7 < k_1)) {
        return _e7;
    }
    return k_1;
}

bool reservoir_takes(uint n_5) {
    return (n_5 < RESERVOIR_FULL);
}

float reservoir_weight(uint n_6, uint k_2) {
    float _e2 = to_f32_(n_6);
    float _e3 = to_f32_(k_2);
    return max((_e2 / _e3), 1.0);
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

float cone_cos_of(vec3 v, float d2_4, float a_5, vec3 d) {
    bool local_5 = false;
    bool local_6 = false;
    float vd = dot(v, d);
    float h2_ = (d2_4 - (a_5 * a_5));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_6 = ((vd * vd) >= h2_);
        } else {
            local_6 = false;
        }
        bool _e19 = local_6;
        local_5 = _e19;
    } else {
        local_5 = true;
    }
    bool _e21 = local_5;
    if (_e21) {
        return 1.0;
    }
    vec3 c_8 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_8, c_8)) * a_5)) / d2_4), 1.0);
}

float cone_cos_toward(vec3 center, float radius, vec3 p, vec3 d_1) {
    vec3 v_4 = (center - p);
    float _e6 = cone_cos_of(v_4, dot(v_4, v_4), radius, d_1);
    return _e6;
}

float range_scale_at(vec4 rl, float cos_t) {
    float t_3 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_3 * t_3))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(vec4 rl_1, vec3 center_1, float radius_1, vec3 p_1, vec3 r_2) {
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_2);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

vec3 triangle_normal(vec3 a_6, vec3 b_4, vec3 c_4) {
    bool local_7 = false;
    vec3 n_12 = cross((b_4 - a_6), (c_4 - a_6));
    float l2_ = dot(n_12, n_12);
    if (!(!((l2_ > 0.0)))) {
        local_7 = !((l2_ < 3e38));
    } else {
        local_7 = true;
    }
    bool _e17 = local_7;
    if (_e17) {
        return vec3(0.0, 0.0, 0.0);
    }
    return (n_12 / vec3(sqrt(l2_)));
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
        case 3u: {
            vec3 _e24 = triangle_normal(l.p0_, l.p1_, l.p2_);
            float _e26 = triangle_lobe(_e24, l.a, w_3);
            return (l.intensity * _e26);
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

bool occluded(vec3 a_7, vec3 b_5) {
    return false;
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

float bsh_inner_scale(float a_8, vec3 v_1, float d2_5, vec3 r_3, vec4 rl_2) {
    float _e5 = cone_cos_of(v_1, d2_5, a_8, r_3);
    float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_2, vec3 x_8, vec3 r_4, vec4 rl_3) {
    bool local_8 = false;
    bool local_9 = false;
    bool _e6 = sphere_contains_point(node_2.center, node_2.radius, x_8);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_2.center, (node_2.radius * (rl_3.w * 1.0001)), x_8);
        local_8 = !(_e20);
    } else {
        local_8 = true;
    }
    bool _e23 = local_8;
    if (_e23) {
        return false;
    }
    float _e25 = bsh_range_bound(node_2);
    vec3 v_5 = (x_8 - node_2.center);
    float d2_7 = dot(v_5, v_5);
    float reach_max = (node_2.extent + ((rl_3.w * 1.001) * _e25));
    if ((d2_7 > (reach_max * reach_max))) {
        return false;
    }
    if ((node_2.child == BSH_NONE)) {
        float _e43 = range_scale_toward(rl_3, node_2.center, node_2.extent, x_8, r_4);
        float _e46 = bsh_scaled_radius(node_2, sqrt(_e43));
        bool _e47 = sphere_contains_point(node_2.center, _e46, x_8);
        return _e47;
    }
    float _e50 = bsh_inner_scale(node_2.extent, -(v_5), d2_7, r_4, rl_3);
    float s_c = (_e50 * 1.001);
    float reach = (node_2.extent + (sqrt(s_c) * _e25));
    if ((d2_7 <= ((node_2.radius * node_2.radius) * s_c))) {
        local_9 = (d2_7 <= (reach * reach));
    } else {
        local_9 = false;
    }
    bool _e67 = local_9;
    return _e67;
}

uint bsh_next_leaf_lobe(uint nodes_3, uint start_1, vec3 x_9, vec3 r_5, vec4 rl_4) {
    uint i_2 = 0u;
    i_2 = start_1;
    while(true) {
        uint _e6 = i_2;
        if ((_e6 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e9 = i_2;
            BshNode _e10 = bsh_node(nodes_3, _e9);
            bool _e11 = bsh_reaches(_e10, x_9, r_5, rl_4);
            if (_e11) {
                if ((_e10.child == BSH_NONE)) {
                    uint _e15 = i_2;
                    return _e15;
                }
                i_2 = _e10.child;
            } else {
                i_2 = _e10.next;
            }
        }
    }
    return BSH_NONE;
}

Picks bsh_collect(vec3 x_10, vec3 r_6, vec4 rl_5, uint seed_1) {
    Picks picks = Picks(uint[8](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u), 0u);
    uint h_1 = 0u;
    uint i_3 = 0u;
    picks.n = 0u;
    h_1 = seed_1;
    uint _e10 = bsh_first(BSH);
    uint _e11 = bsh_next_leaf_lobe(BSH, _e10, x_10, r_6, rl_5);
    i_3 = _e11;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e44 = i_3;
            uint _e47 = _group_1_binding_4_cs[_e44].next;
            uint _e48 = bsh_next_leaf_lobe(BSH, _e47, x_10, r_6, rl_5);
            i_3 = _e48;
        }
        loop_init = false;
        uint _e13 = i_3;
        if ((_e13 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e17 = picks.n;
            bool _e18 = reservoir_takes(_e17);
            if (_e18) {
                uint _e20 = picks.n;
                picks.n = (_e20 + 1u);
                uint _e23 = h_1;
                uint _e24 = pcg_hash(_e23);
                h_1 = _e24;
                uint hi_3 = h_1;
                uint _e26 = h_1;
                uint _e27 = pcg_hash(_e26);
                h_1 = _e27;
                uint _e29 = picks.n;
                uint _e31 = h_1;
                uint _e32 = reservoir_slot(_e29, K, hi_3, _e31);
                if ((_e32 < K)) {
                    uint _e38 = i_3;
                    uint _e41 = _group_1_binding_4_cs[_e38].light;
                    picks.light[_e32] = _e41;
                }
            }
        }
    }
    Picks _e49 = picks;
    return _e49;
}

Connection connect_record(GpuLight l_2, vec3 x_11, vec3 n_7, vec3 ng_1, float r2_2, float rt2_2, float w_res, float u1_2, float u2_2, float eps, bool trace) {
    Connection c_5 = Connection(vec3(0.0), vec3(0.0), 0.0);
    bool local_10 = false;
    bool local_11 = false;
    c_5.e = vec3(0.0);
    vec3 _e16 = light_point(l_2, u1_2, u2_2);
    c_5.y = _e16;
    vec3 _e19 = c_5.y;
    float _e20 = connection_cosine(x_11, _e19, n_7, ng_1, r2_2);
    c_5.cos_x = _e20;
    float _e22 = c_5.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace) {
            vec3 _e33 = c_5.y;
            bool _e34 = occluded((x_11 + (ng_1 * eps)), _e33);
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
        Connection _e39 = c_5;
        return _e39;
    }
    vec3 _e41 = c_5.y;
    vec3 v_6 = (x_11 - _e41);
    float d2_8 = dot(v_6, v_6);
    vec3 _e48 = light_intensity(l_2, (v_6 / vec3(sqrt(d2_8))));
    float _e50 = c_5.cos_x;
    float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_5.e = (_e48 * _e51);
    Connection _e53 = c_5;
    return _e53;
}

Connection connect_traced(uint li, vec3 x_12, vec3 n_8, vec3 ng_2, float s, float w_res_1, float u1_3, float u2_3, float eps_1, bool trace_1) {
    GpuLight _e12 = _group_1_binding_1_cs[li];
    float _e15 = _group_1_binding_3_cs[li];
    float _e19 = _group_1_binding_2_cs[li];
    Connection _e21 = connect_record(_e12, x_12, n_8, ng_2, (s * _e15), (s * _e19), w_res_1, u1_3, u2_3, eps_1, trace_1);
    return _e21;
}

vec4 surface_at(ivec2 texel) {
    vec4 p_2 = texelFetch(_group_0_binding_1_cs, texel, 0);
    return ((p_2.w > 0.0) ? vec4(p_2.xyz, 1.0) : vec4(0.0));
}

Shaded shade_connection(Connection c_6, vec3 x_13, vec3 n_9, Material m_1) {
    Shaded s_1 = Shaded(vec3(0.0), vec3(0.0), vec3(0.0));
    s_1.e = c_6.e;
    s_1.diffuse = vec3(0.0);
    s_1.specular = vec3(0.0);
    Shaded _e13 = s_1;
    return _e13;
}

Shaded shade_pick_traced(uint li_1, vec3 x_14, vec3 n_10, vec3 r_7, vec4 rl_6, Material m_2, float w_4, float u1_4, float u2_4, float eps_2, bool trace_2) {
    Connection _e12 = connect_traced(li_1, x_14, n_10, n_10, 1.0, w_4, u1_4, u2_4, eps_2, trace_2);
    Shaded _e13 = shade_connection(_e12, x_14, n_10, m_2);
    return _e13;
}

Shaded shade_pick(uint li_2, vec3 x_15, vec3 n_11, vec3 r_8, vec4 rl_7, Material m_3, float w_5, float u1_5, float u2_5, float eps_3) {
    Shaded _e11 = shade_pick_traced(li_2, x_15, n_11, r_8, rl_7, m_3, w_5, u1_5, u2_5, eps_3, true);
    return _e11;
}

Shaded add(Shaded a_9, Shaded b_6) {
    return Shaded((a_9.e + b_6.e), (a_9.diffuse + b_6.diffuse), (a_9.specular + b_6.specular));
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    bool local = false;
    bool local_1 = false;
    Material m = Material(vec3(0.0), 0.0, 0.0, vec3(0.0), 0.0, 0.0);
    vec4 lobe = vec4(1.0, 0.0, 1.0, 1.0);
    vec3 r = vec3(0.0);
    uint h = 0u;
    Shaded t = Shaded(vec3(0.0), vec3(0.0), vec3(0.0));
    uint k = 0u;
    uint _e4 = _group_0_binding_0_cs.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = _group_0_binding_0_cs.height;
        local = (gid.y >= _e12);
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    ivec2 texel_1 = ivec2(int(gid.x), int(gid.y));
    vec4 _e21 = surface_at(texel_1);
    vec4 _e24 = texelFetch(_group_0_binding_2_cs, texel_1, 0);
    vec3 nn = _e24.xyz;
    float len2_ = dot(nn, nn);
    if (!((_e21.w <= 0.0))) {
        local_1 = !((len2_ > 0.0));
    } else {
        local_1 = true;
    }
    bool _e37 = local_1;
    if (_e37) {
        imageStore(_group_0_binding_3_cs, texel_1, vec4(0.0));
        return;
    }
    vec3 x_16 = _e21.xyz;
    vec3 n_13 = (nn / vec3(sqrt(len2_)));
    r = n_13;
    vec4 _e53 = lobe;
    vec4 _e54 = range_lobe(_e53);
    float _e57 = _group_0_binding_0_cs.shadow_offset;
    vec3 _e60 = _group_0_binding_0_cs.eye;
    float eps_4 = (_e57 * length((_e60 - x_16)));
    uint _e66 = _group_0_binding_0_cs.seed;
    uint _e70 = _group_0_binding_0_cs.width;
    uint _e76 = _group_0_binding_0_cs.frame;
    uint _e77 = point_stream(_e66, ((gid.y * _e70) + gid.x), _e76);
    uint _e78 = pick_stream(_e77);
    h = _e78;
    vec3 _e88 = r;
    Picks _e89 = bsh_collect(x_16, _e88, _e54, _e77);
    float _e92 = reservoir_weight(_e89.n, K);
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e117 = k;
            k = (_e117 + 1u);
        }
        loop_init_1 = false;
        uint _e95 = k;
        if ((_e95 < min(_e89.n, K))) {
        } else {
            break;
        }
        {
            uint _e100 = h;
            uint _e101 = pcg_hash(_e100);
            h = _e101;
            uint _e102 = h;
            float _e103 = xi_from_bits(_e102);
            uint _e104 = h;
            uint _e105 = pcg_hash(_e104);
            h = _e105;
            Shaded _e106 = t;
            uint _e108 = k;
            vec3 _e110 = r;
            Material _e111 = m;
            uint _e112 = h;
            float _e113 = xi_from_bits(_e112);
            Shaded _e114 = shade_pick(_e89.light[_e108], x_16, n_13, _e110, _e54, _e111, _e92, _e103, _e113, eps_4);
            Shaded _e115 = add(_e106, _e114);
            t = _e115;
        }
    }
    uint count = _e89.n;
    vec3 _e122 = t.e;
    imageStore(_group_0_binding_3_cs, texel_1, vec4(_e122, float(count)));
    return;
}

