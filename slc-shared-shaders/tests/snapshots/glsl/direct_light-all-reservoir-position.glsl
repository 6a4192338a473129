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

layout(std430) readonly buffer type_4_block_0Compute { float _group_1_binding_0_cs[]; };

layout(std140) uniform ViewParams_block_1Compute { ViewParams _group_0_binding_0_cs; };

uniform sampler2D _group_0_binding_1_cs;

uniform sampler2D _group_0_binding_2_cs;

layout(rgba32f) writeonly uniform image2D _group_0_binding_3_cs;

layout(std430) readonly buffer type_8_block_2Compute { GpuLight _group_1_binding_1_cs[]; };

layout(std430) readonly buffer type_4_block_3Compute { float _group_1_binding_2_cs[]; };

layout(std430) readonly buffer type_4_block_4Compute { float _group_1_binding_3_cs[]; };

layout(std430) readonly buffer type_9_block_5Compute { BshNode _group_1_binding_4_cs[]; };

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

shared WorkgroupBox wg_box;

shared uint tile_list[1024];

shared uint subtree_at[256];

shared uint tile_scale;

shared uint tile_total;


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

bool sphere_overlaps_aabb(vec3 c_1, float r_2, vec3 bmin, vec3 bmax) {
    vec3 q = clamp(c_1, bmin, bmax);
    vec3 v_3 = (q - c_1);
    return (dot(v_3, v_3) <= (r_2 * r_2));
}

float inverse_square(float d2_2) {
    return (1.0 / max(d2_2, MIN_D2_));
}

float connection_factor(float cos_x, float d2_3, float rt2_1, float w) {
    float _e4 = inverse_square(d2_3);
    float _e6 = slc_weight(rt2_1, d2_3);
    return (((cos_x * _e4) * _e6) * w);
}

float connection_cosine(vec3 x_3, vec3 y, vec3 n_1, vec3 ng, float r2_1) {
    bool local_5 = false;
    bool local_6 = false;
    vec3 v_4 = (x_3 - y);
    float d2_6 = dot(v_4, v_4);
    bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local_5 = !((d2_6 > 0.0));
    } else {
        local_5 = true;
    }
    bool _e16 = local_5;
    if (_e16) {
        return 0.0;
    }
    vec3 w_10 = (v_4 / vec3(sqrt(d2_6)));
    float cos_x_1 = -(dot(n_1, w_10));
    if (!(!((cos_x_1 > 0.0)))) {
        local_6 = !((dot(ng, w_10) < 0.0));
    } else {
        local_6 = true;
    }
    bool _e34 = local_6;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float spot_falloff(float cos_theta, float cos_outer, float cos_inner, float shape) {
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t_5 = clamp(((cos_theta - cos_outer) / (cos_inner - cos_outer)), 0.0, 1.0);
    return ((shape > 0.5) ? (t_5 * t_5) : ((t_5 * t_5) * (3.0 - (2.0 * t_5))));
}

float triangle_lobe(vec3 n_2, float area, vec3 w_1) {
    return (area * max(dot(n_2, w_1), 0.0));
}

vec3 triangle_sample(vec3 a_2, vec3 b_2, vec3 c_2, float u1_, float u2_) {
    float su = sqrt(u1_);
    float b0_ = (1.0 - su);
    float b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_2 * ((1.0 - b0_) - b1_)));
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

float ies_fold_c(float c_3, float h_first, float h_last) {
    float a_3 = 0.0;
    a_3 = (c_3 - (360.0 * floor((c_3 / 360.0))));
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

uint ies_segment(uint tab_1, uint start_1, uint n_3, float x_6) {
    uint lo = 0u;
    uint hi = 0u;
    if ((n_3 < 2u)) {
        return 0u;
    }
    hi = (n_3 - 1u);
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
            float _e23 = at(tab_1, (start_1 + mid));
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

float ies_candela(uint tab_2, uint base_1, float gamma, float c_4) {
    bool local_7 = false;
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
        local_7 = (gamma > _e22);
    } else {
        local_7 = true;
    }
    bool _e25 = local_7;
    if (_e25) {
        return 0.0;
    }
    float _e27 = at(tab_2, h0_);
    float _e31 = at(tab_2, ((h0_ + _e9) - 1u));
    float _e32 = ies_fold_c(c_4, _e27, _e31);
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
    float b_9 = ((_e71 * (1.0 - _e49)) + (_e78 * _e49));
    return ((a_11 * (1.0 - _e54)) + (b_9 * _e54));
}

float ies_candela_dir(uint tab_3, uint base_2, float wn, float wr, float ws) {
    float _e9 = atan2_portable(sqrt(((wr * wr) + (ws * ws))), wn);
    float gamma_1 = degrees(_e9);
    bool on_axis = ((abs(wr) + abs(ws)) <= 0.0);
    float _e16 = atan2_portable(ws, wr);
    float c_8 = (on_axis ? 0.0 : degrees(_e16));
    float _e20 = ies_candela(tab_3, base_2, gamma_1, c_8);
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

float bsh_reach_bound(BshNode node_2, float w_3) {
    float _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_3 * 1.001) * _e5));
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

uint uniform_index(uint n_4, uint hi_1, uint lo_1) {
    uint _e3 = mul_lo_u32_(hi_1, n_4);
    uint _e4 = mul_hi_u32_(hi_1, n_4);
    uint _e5 = mul_hi_u32_(lo_1, n_4);
    if ((_e3 > (4294967295u - _e5))) {
        return (_e4 + 1u);
    }
    return _e4;
}

uint reservoir_slot(uint n_5, uint k_1, uint hi_2, uint lo_2) {
    if ((n_5 <= k_1)) {
        return (n_5 - 1u);
    }
    uint _e7 = uniform_index(n_5, hi_2, lo_2);
    if ((_e7 < k_1)) {
        return _e7;
    }
    return k_1;
}

bool reservoir_takes(uint n_6) {
    return (n_6 < RESERVOIR_FULL);
}

float reservoir_weight(uint n_7, uint k_2) {
    float _e2 = to_f32_(n_7);
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
    bool local_8 = false;
    bool local_9 = false;
    float vd = dot(v, d);
    float h2_ = (d2_4 - (a_5 * a_5));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_9 = ((vd * vd) >= h2_);
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
    vec3 c_9 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_9, c_9)) * a_5)) / d2_4), 1.0);
}

float cone_cos_toward(vec3 center, float radius, vec3 p, vec3 d_1) {
    vec3 v_5 = (center - p);
    float _e6 = cone_cos_of(v_5, dot(v_5, v_5), radius, d_1);
    return _e6;
}

float range_scale_at(vec4 rl, float cos_t) {
    float t_6 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_6 * t_6))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(vec4 rl_1, vec3 center_1, float radius_1, vec3 p_1, vec3 r_3) {
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_3);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

vec3 triangle_normal(vec3 a_6, vec3 b_4, vec3 c_5) {
    bool local_10 = false;
    vec3 n_13 = cross((b_4 - a_6), (c_5 - a_6));
    float l2_ = dot(n_13, n_13);
    if (!(!((l2_ > 0.0)))) {
        local_10 = !((l2_ < 3e38));
    } else {
        local_10 = true;
    }
    bool _e17 = local_10;
    if (_e17) {
        return vec3(0.0, 0.0, 0.0);
    }
    return (n_13 / vec3(sqrt(l2_)));
}

vec3 light_intensity(GpuLight l, vec3 w_4) {
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            float _e11 = spot_falloff(dot(l.p1_, w_4), l.a, l.b, l.p2_.x);
            return (l.intensity * _e11);
        }
        case 2u: {
            float _e18 = ies_light_candela(0u, l.ies_base, l.p1_, l.p2_, w_4);
            return (l.intensity * _e18);
        }
        case 3u: {
            vec3 _e24 = triangle_normal(l.p0_, l.p1_, l.p2_);
            float _e26 = triangle_lobe(_e24, l.a, w_4);
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

float bsh_inner_scale(float a_8, vec3 v_1, float d2_5, vec3 r_4, vec4 rl_2) {
    float _e5 = cone_cos_of(v_1, d2_5, a_8, r_4);
    float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_3, vec3 x_8, vec3 r_5, vec4 rl_3) {
    bool local_11 = false;
    bool local_12 = false;
    bool _e6 = sphere_contains_point(node_3.center, node_3.radius, x_8);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_3.center, (node_3.radius * (rl_3.w * 1.0001)), x_8);
        local_11 = !(_e20);
    } else {
        local_11 = true;
    }
    bool _e23 = local_11;
    if (_e23) {
        return false;
    }
    vec3 v_6 = (x_8 - node_3.center);
    float d2_7 = dot(v_6, v_6);
    float _e29 = bsh_reach_bound(node_3, rl_3.w);
    if ((d2_7 > (_e29 * _e29))) {
        return false;
    }
    if ((node_3.child == BSH_NONE)) {
        float _e38 = range_scale_toward(rl_3, node_3.center, node_3.extent, x_8, r_5);
        float _e41 = bsh_scaled_radius(node_3, sqrt(_e38));
        bool _e42 = sphere_contains_point(node_3.center, _e41, x_8);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_3.extent, -(v_6), d2_7, r_5, rl_3);
    float s_c = (_e45 * 1.001);
    float _e50 = bsh_range_bound(node_3);
    float reach = (node_3.extent + (sqrt(s_c) * _e50));
    if ((d2_7 <= ((node_3.radius * node_3.radius) * s_c))) {
        local_12 = (d2_7 <= (reach * reach));
    } else {
        local_12 = false;
    }
    bool _e63 = local_12;
    return _e63;
}

bool bsh_reaches_box(BshNode node_4, vec3 lo_3, vec3 hi_3, float w_5) {
    bool _e13 = sphere_overlaps_aabb(node_4.center, (node_4.radius * (max(1.0, (w_5 * 1.0001)) * 1.0001)), lo_3, hi_3);
    return _e13;
}

uint bsh_subtree(uint nodes_3, uint s_1, uint depth) {
    uint i_2 = 0u;
    uint level = 0u;
    bool local_13 = false;
    uint _e3 = bsh_first(nodes_3);
    i_2 = _e3;
    while(true) {
        uint _e7 = level;
        if ((_e7 < depth)) {
            uint _e11 = i_2;
            local_13 = (_e11 != BSH_NONE);
        } else {
            local_13 = false;
        }
        bool _e15 = local_13;
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

uint bsh_next_leaf_box(uint nodes_4, uint start_2, uint end, vec3 lo_4, vec3 hi_4, float w_6) {
    uint i_3 = 0u;
    i_3 = start_2;
    while(true) {
        uint _e7 = i_3;
        if ((_e7 != end)) {
        } else {
            break;
        }
        {
            uint _e9 = i_3;
            BshNode _e10 = bsh_node(nodes_4, _e9);
            bool _e11 = bsh_reaches_box(_e10, lo_4, hi_4, w_6);
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

void reservoir_offer(inout Picks picks_1, inout uint h_1, uint light) {
    uint _e4 = picks_1.n;
    bool _e5 = reservoir_takes(_e4);
    if (_e5) {
        uint _e7 = picks_1.n;
        picks_1.n = (_e7 + 1u);
        uint _e10 = h_1;
        uint _e11 = pcg_hash(_e10);
        h_1 = _e11;
        uint hi_6 = h_1;
        uint _e13 = h_1;
        uint _e14 = pcg_hash(_e13);
        h_1 = _e14;
        uint _e16 = picks_1.n;
        uint _e18 = h_1;
        uint _e19 = reservoir_slot(_e16, K, hi_6, _e18);
        if ((_e19 < K)) {
            picks_1.light[_e19] = light;
            return;
        } else {
            return;
        }
    } else {
        return;
    }
}

Connection connect_record(GpuLight l_2, vec3 x_9, vec3 n_8, vec3 ng_1, float r2_2, float rt2_2, float w_res, float u1_2, float u2_2, float eps, bool trace) {
    Connection c_6 = Connection(vec3(0.0), vec3(0.0), 0.0);
    bool local_14 = false;
    bool local_15 = false;
    c_6.e = vec3(0.0);
    vec3 _e16 = light_point(l_2, u1_2, u2_2);
    c_6.y = _e16;
    vec3 _e19 = c_6.y;
    float _e20 = connection_cosine(x_9, _e19, n_8, ng_1, r2_2);
    c_6.cos_x = _e20;
    float _e22 = c_6.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace) {
            vec3 _e33 = c_6.y;
            bool _e34 = occluded((x_9 + (ng_1 * eps)), _e33);
            local_15 = _e34;
        } else {
            local_15 = false;
        }
        bool _e36 = local_15;
        local_14 = _e36;
    } else {
        local_14 = true;
    }
    bool _e38 = local_14;
    if (_e38) {
        Connection _e39 = c_6;
        return _e39;
    }
    vec3 _e41 = c_6.y;
    vec3 v_7 = (x_9 - _e41);
    float d2_8 = dot(v_7, v_7);
    vec3 _e48 = light_intensity(l_2, (v_7 / vec3(sqrt(d2_8))));
    float _e50 = c_6.cos_x;
    float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_6.e = (_e48 * _e51);
    Connection _e53 = c_6;
    return _e53;
}

Connection connect_traced(uint li, vec3 x_10, vec3 n_9, vec3 ng_2, float s_2, float w_res_1, float u1_3, float u2_3, float eps_1, bool trace_1) {
    GpuLight _e12 = _group_1_binding_1_cs[li];
    float _e15 = _group_1_binding_3_cs[li];
    float _e19 = _group_1_binding_2_cs[li];
    Connection _e21 = connect_record(_e12, x_10, n_9, ng_2, (s_2 * _e15), (s_2 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_1);
    return _e21;
}

vec4 surface_at(ivec2 texel) {
    vec4 p_5 = texelFetch(_group_0_binding_1_cs, texel, 0);
    return ((p_5.w > 0.0) ? vec4(p_5.xyz, 1.0) : vec4(0.0));
}

WorkgroupBox workgroup_bounds(uint li_1, vec3 lo_5, vec3 hi_5) {
    uint stride = 32u;
    wg_lo[li_1] = lo_5;
    wg_hi[li_1] = hi_5;
    memoryBarrierShared();
    barrier();
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e36 = stride;
            stride = (_e36 / 2u);
        }
        loop_init = false;
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

bool box_is_empty(WorkgroupBox b_6) {
    return (b_6.lo.x > b_6.hi.x);
}

uint tile_subtree(uint s_3, TileWalk t_2, bool list, uint at_1, uint start_3, uint to) {
    uint p_4 = 0u;
    uint b_7 = 0u;
    bool local_16 = false;
    bool local_17 = false;
    bool local_18 = false;
    uint _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH);
    if ((_e8 == BSH_NONE)) {
        return 0u;
    }
    uint end_1 = _group_1_binding_4_cs[_e8].next;
    p_4 = at_1;
    uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_2.lo, t_2.hi, t_2.w);
    b_7 = _e21;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e53 = b_7;
            uint _e56 = _group_1_binding_4_cs[_e53].next;
            uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_2.lo, t_2.hi, t_2.w);
            b_7 = _e60;
        }
        loop_init_1 = false;
        uint _e23 = b_7;
        if ((_e23 != end_1)) {
            if (!(!(list))) {
                uint _e31 = p_4;
                local_17 = (_e31 < to);
            } else {
                local_17 = true;
            }
            bool _e34 = local_17;
            local_16 = _e34;
        } else {
            local_16 = false;
        }
        bool _e36 = local_16;
        if (_e36) {
        } else {
            break;
        }
        {
            if (list) {
                uint _e39 = p_4;
                local_18 = (_e39 >= start_3);
            } else {
                local_18 = false;
            }
            bool _e42 = local_18;
            if (_e42) {
                uint _e44 = p_4;
                uint _e47 = b_7;
                tile_list[(_e44 - start_3)] = _e47;
            }
            uint _e48 = p_4;
            p_4 = (_e48 + 1u);
        }
    }
    uint _e61 = p_4;
    return (_e61 - at_1);
}

TileWalk tile_walk_begin(uint li_3, vec3 x_11, float w_7, bool has_2) {
    bool local_19 = false;
    TileWalk t_3 = TileWalk(vec3(0.0), vec3(0.0), 0.0, 0u);
    uint s_4 = 0u;
    uint sum = 0u;
    uint s_5 = 0u;
    if (has_2) {
        local_19 = (w_7 >= 0.0);
    } else {
        local_19 = false;
    }
    bool _e12 = local_19;
    uint _e14 = atomicMax(tile_scale, (_e12 ? floatBitsToUint(w_7) : 0u));
    WorkgroupBox _e15 = workgroup_box(li_3, x_11, has_2);
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
    s_4 = li_3;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e40 = s_4;
            s_4 = (_e40 + TILE_THREADS);
        }
        loop_init_2 = false;
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
    if ((li_3 == 0u)) {
        bool loop_init_3 = true;
        while(true) {
            if (!loop_init_3) {
                uint _e63 = s_5;
                s_5 = (_e63 + 1u);
            }
            loop_init_3 = false;
            uint _e49 = s_5;
            if ((_e49 < BSH_TILE_SUBTREES)) {
            } else {
                break;
            }
            {
                uint _e53 = s_5;
                uint c_10 = subtree_at[_e53];
                uint _e57 = s_5;
                uint _e59 = sum;
                subtree_at[_e57] = _e59;
                uint _e60 = sum;
                sum = (_e60 + c_10);
            }
        }
        uint _e66 = sum;
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

uint tile_walk_fill(uint li_4, TileWalk t_4, uint start_4) {
    uint s_6 = 0u;
    uint past = 0u;
    bool local_20 = false;
    uint to_1 = min(t_4.total, (start_4 + TILE_LIST));
    s_6 = li_4;
    bool loop_init_4 = true;
    while(true) {
        if (!loop_init_4) {
            uint _e38 = s_6;
            s_6 = (_e38 + TILE_THREADS);
        }
        loop_init_4 = false;
        uint _e8 = s_6;
        if ((_e8 < BSH_TILE_SUBTREES)) {
        } else {
            break;
        }
        {
            uint _e12 = s_6;
            uint at_2 = subtree_at[_e12];
            past = t_4.total;
            uint _e17 = s_6;
            if (((_e17 + 1u) < BSH_TILE_SUBTREES)) {
                uint _e23 = s_6;
                uint _e27 = subtree_at[(_e23 + 1u)];
                past = _e27;
            }
            if ((at_2 < to_1)) {
                uint _e31 = past;
                local_20 = (_e31 > start_4);
            } else {
                local_20 = false;
            }
            bool _e34 = local_20;
            if (_e34) {
                uint _e35 = s_6;
                uint _e37 = tile_subtree(_e35, t_4, true, at_2, start_4, to_1);
            }
        }
    }
    memoryBarrierShared();
    barrier();
    return (to_1 - start_4);
}

Shaded shade_connection(Connection c_7, vec3 x_12, vec3 n_10, Material m_1) {
    Shaded s_7 = Shaded(vec3(0.0), vec3(0.0), vec3(0.0));
    s_7.e = c_7.e;
    s_7.diffuse = vec3(0.0);
    s_7.specular = vec3(0.0);
    Shaded _e13 = s_7;
    return _e13;
}

Shaded shade_pick_traced(uint li_5, vec3 x_13, vec3 n_11, vec3 r_6, vec4 rl_4, Material m_2, float w_8, float u1_4, float u2_4, float eps_2, bool trace_2) {
    Connection _e12 = connect_traced(li_5, x_13, n_11, n_11, 1.0, w_8, u1_4, u2_4, eps_2, trace_2);
    Shaded _e13 = shade_connection(_e12, x_13, n_11, m_2);
    return _e13;
}

Shaded shade_pick(uint li_6, vec3 x_14, vec3 n_12, vec3 r_7, vec4 rl_5, Material m_3, float w_9, float u1_5, float u2_5, float eps_3) {
    Shaded _e11 = shade_pick_traced(li_6, x_14, n_12, r_7, rl_5, m_3, w_9, u1_5, u2_5, eps_3, true);
    return _e11;
}

Shaded add(Shaded a_9, Shaded b_8) {
    return Shaded((a_9.e + b_8.e), (a_9.diffuse + b_8.diffuse), (a_9.specular + b_8.specular));
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
    Picks picks = Picks(uint[8](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u), 0u);
    uint hr = 0u;
    uint start = 0u;
    uint j = 0u;
    bool local_4 = false;
    uint k = 0u;
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
    vec3 x_15 = _e35.xyz;
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
        local_3 = all(lessThanEqual(abs(x_15), vec3(3.4028235e38)));
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
    float eps_4 = (_e82 * length((_e85 - x_15)));
    uint _e91 = _group_0_binding_0_cs.seed;
    uint _e95 = _group_0_binding_0_cs.width;
    uint _e101 = _group_0_binding_0_cs.frame;
    uint _e102 = point_stream(_e91, ((gid.y * _e95) + gid.x), _e101);
    uint _e103 = pick_stream(_e102);
    h = _e103;
    picks.n = 0u;
    hr = _e102;
    TileWalk _e118 = tile_walk_begin(lid, x_15, _e79.w, has_3);
    bool loop_init_5 = true;
    while(true) {
        if (!loop_init_5) {
            uint _e153 = start;
            start = (_e153 + TILE_LIST);
        }
        loop_init_5 = false;
        uint _e121 = start;
        if ((_e121 < _e118.total)) {
        } else {
            break;
        }
        {
            uint _e124 = start;
            uint _e125 = tile_walk_fill(lid, _e118, _e124);
            j = 0u;
            bool loop_init_6 = true;
            while(true) {
                if (!loop_init_6) {
                    uint _e151 = j;
                    j = (_e151 + 1u);
                }
                loop_init_6 = false;
                uint _e128 = j;
                if ((_e128 < _e125)) {
                } else {
                    break;
                }
                {
                    uint _e131 = j;
                    uint b_10 = tile_list[_e131];
                    if (!(!(has_3))) {
                        BshNode _e140 = _group_1_binding_4_cs[b_10];
                        vec3 _e141 = r;
                        bool _e142 = bsh_reaches(_e140, x_15, _e141, _e79);
                        local_4 = !(_e142);
                    } else {
                        local_4 = true;
                    }
                    bool _e145 = local_4;
                    if (_e145) {
                        continue;
                    }
                    uint li_7 = _group_1_binding_4_cs[b_10].light;
                    reservoir_offer(picks, hr, li_7);
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
    uint _e161 = picks.n;
    float _e163 = reservoir_weight(_e161, K);
    bool loop_init_7 = true;
    while(true) {
        if (!loop_init_7) {
            uint _e191 = k;
            k = (_e191 + 1u);
        }
        loop_init_7 = false;
        uint _e166 = k;
        uint _e168 = picks.n;
        if ((_e166 < min(_e168, K))) {
        } else {
            break;
        }
        {
            uint _e172 = h;
            uint _e173 = pcg_hash(_e172);
            h = _e173;
            uint _e174 = h;
            float _e175 = xi_from_bits(_e174);
            uint _e176 = h;
            uint _e177 = pcg_hash(_e176);
            h = _e177;
            Shaded _e178 = t;
            uint _e180 = k;
            uint _e182 = picks.light[_e180];
            vec3 _e183 = n;
            vec3 _e184 = r;
            Material _e185 = m;
            uint _e186 = h;
            float _e187 = xi_from_bits(_e186);
            Shaded _e188 = shade_pick(_e182, x_15, _e183, _e184, _e79, _e185, _e163, _e175, _e187, eps_4);
            Shaded _e189 = add(_e178, _e188);
            t = _e189;
        }
    }
    uint count = picks.n;
    vec3 _e197 = t.e;
    imageStore(_group_0_binding_3_cs, texel_1, vec4(_e197, float(count)));
    return;
}

