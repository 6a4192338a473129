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
struct GpuPathVertex {
    vec3 position;
    uint alive;
    vec3 normal;
    float pad;
    vec3 weight;
    float pad1_;
    vec3 gnormal;
    float pad2_;
};
struct GpuPathState {
    vec3 origin;
    uint alive;
    vec3 dir;
    uint rng;
    vec3 beta;
    float pdf_bsdf;
    vec3 prev;
    uint pad;
    vec3 prev_normal;
    uint pad2_;
};
struct PtParams {
    vec3 cam_pos;
    uint width;
    vec3 cam_right;
    uint height;
    vec3 cam_up;
    uint depth;
    vec3 cam_forward;
    uint seed;
    uint pass_index;
    uint max_depth;
    float eps;
    float t_min;
};
struct BshNode {
    vec3 center;
    float radius;
    uint child;
    uint next;
    uint light;
    uint pad;
};
struct GeoHit {
    float t;
    uint tri;
};
const uint LIGHT_POINT = 0u;
const uint LIGHT_SPOT = 1u;
const uint LIGHT_IES = 2u;
const uint LIGHT_TRIANGLE = 3u;
const uint LIGHT_VPL = 4u;
const uint NO_LIGHT = 4294967295u;
const uint MAP_CAMERA = 0u;
const uint MAP_PERSPECTIVE = 1u;
const uint MAP_ORTHOGRAPHIC = 2u;
const float XI_STEP = 5.9604645e-8;
const uint PICK_STREAM = 2654435769u;
const float TWO_PI = 6.2831855;
const float CULL_RADIUS_SCALE = 1.000001;
const float SPHERE_PAD = 4.7683716e-7;
const float SPHERE_HUGE = 3.4028235e38;
const float SPHERE_PAD_ABS = 1e-18;
const float INV_PI = 0.31830987;
const float MIN_D2_ = 1e-12;
const uint BSH_NONE = 4294967295u;
const uint RESERVOIR_FULL = 4294967295u;
const uint LIGHT_BVH_LEAF = 4294967295u;
const float ONE_MINUS_EPSILON = 0.99999994;
const float F32_MAX = 3.4028235e38;
const float GGX_ALPHA_MIN = 0.001;
const float DEPTH_NONE = 1e30;
const float DEPTH_SIGMA = 0.05;
const float COVER_WEIGHT = 0.1;
const uint NEAR_BLOCK = 64u;
const uint ROULETTE_DEPTH = 2u;
const uint K = 8u;
const uint BVH = 0u;

layout(std430) readonly buffer type_6_block_0Compute { GpuGeoNode _group_0_binding_5_cs[]; };

layout(std430) readonly buffer type_7_block_1Compute { GpuTriangle _group_0_binding_6_cs[]; };

layout(std430) readonly buffer type_4_block_2Compute { float _group_0_binding_2_cs[]; };

layout(std430) readonly buffer type_10_block_3Compute { GpuLight _group_0_binding_1_cs[]; };

layout(std140) uniform PtParams_block_4Compute { PtParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_11_block_5Compute { BshNode _group_0_binding_3_cs[]; };

layout(std430) readonly buffer type_12_block_6Compute { uint _group_0_binding_4_cs[]; };

layout(std430) readonly buffer type_9_block_7Compute { vec4 _group_0_binding_7_cs[]; };

layout(std430) readonly buffer type_9_block_8Compute { vec4 _group_0_binding_8_cs[]; };

layout(std430) readonly buffer type_12_block_9Compute { uint _group_0_binding_9_cs[]; };

layout(std430) buffer type_13_block_10Compute { GpuPathState _group_0_binding_10_cs[]; };

layout(std430) buffer type_14_block_11Compute { GpuPathVertex _group_0_binding_11_cs[]; };

layout(std430) buffer type_9_block_12Compute { vec4 _group_0_binding_12_cs[]; };


float to_f32_(uint u) {
    return float(u);
}

uint mul_lo_u32_(uint a, uint b) {
    return (a * b);
}

uint add_wrap_u32_(uint a_1, uint b_1) {
    return (a_1 + b_1);
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

uint path_stream(uint seed_1, uint pixel, uint pass_index) {
    uint _e4 = add_wrap_u32_(pass_index, PICK_STREAM);
    uint _e5 = point_stream(seed_1, pixel, _e4);
    return _e5;
}

float rr_probability(float rt2_, float d2_) {
    if ((d2_ <= rt2_)) {
        return 1.0;
    }
    return (rt2_ / d2_);
}

bool sphere_contains_point(vec3 c, float r, vec3 x_1) {
    vec3 v_2 = (x_1 - c);
    return (dot(v_2, v_2) <= (r * r));
}

float area_to_solid_angle_pdf(float pdf_area, float d2_1, float cos_light) {
    float c_4 = abs(cos_light);
    if ((c_4 <= 0.0)) {
        return 0.0;
    }
    return ((pdf_area * d2_1) / c_4);
}

float reservoir_weight(uint n, uint k) {
    float _e2 = to_f32_(n);
    float _e3 = to_f32_(k);
    return max((_e2 / _e3), 1.0);
}

float reservoir_select_pdf(uint seen, bool in_range, uint k_1) {
    uint others = 0u;
    bool local_3 = false;
    others = seen;
    if (in_range) {
        local_3 = (seen > 0u);
    } else {
        local_3 = false;
    }
    bool _e9 = local_3;
    if (_e9) {
        others = (seen - 1u);
    }
    uint _e12 = others;
    float _e15 = reservoir_weight((_e12 + 1u), k_1);
    return (1.0 / _e15);
}

float ray_inverse(float x_2) {
    return (1.0 / ((abs(x_2) < 1e-30) ? 1e-30 : x_2));
}

vec3 ray_inverse3_(vec3 d) {
    float _e2 = ray_inverse(d.x);
    float _e4 = ray_inverse(d.y);
    float _e6 = ray_inverse(d.z);
    return vec3(_e2, _e4, _e6);
}

float ray_aabb(vec3 o, vec3 inv_d, vec3 bmin, vec3 bmax, float t_max) {
    vec3 t0_ = ((bmin - o) * inv_d);
    vec3 t1_ = ((bmax - o) * inv_d);
    vec3 lo = min(t0_, t1_);
    vec3 hi = max(t0_, t1_);
    float t_in = max(max(lo.x, lo.y), max(lo.z, 0.0));
    float t_out = min(min(hi.x, hi.y), min(hi.z, t_max));
    if ((t_in <= t_out)) {
        return t_in;
    }
    return -1.0;
}

vec3 triangle_normal(vec3 a_2, vec3 b_2, vec3 c_1) {
    bool local_4 = false;
    vec3 n_9 = cross((b_2 - a_2), (c_1 - a_2));
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

vec3 face_against(vec3 n_1, vec3 dir) {
    return ((dot(n_1, dir) > 0.0) ? -(n_1) : n_1);
}

vec3 barycentric(vec3 p, vec3 a_3, vec3 b_3, vec3 c_2) {
    vec3 e1_ = (b_3 - a_3);
    vec3 e2_ = (c_2 - a_3);
    vec3 q = (p - a_3);
    float d11_ = dot(e1_, e1_);
    float d12_ = dot(e1_, e2_);
    float d22_ = dot(e2_, e2_);
    float den = ((d11_ * d22_) - (d12_ * d12_));
    if (!((abs(den) > 0.0))) {
        return vec3(1.0, 0.0, 0.0);
    }
    float w1_ = (((d22_ * dot(q, e1_)) - (d12_ * dot(q, e2_))) / den);
    float w2_ = (((d11_ * dot(q, e2_)) - (d12_ * dot(q, e1_))) / den);
    return vec3(((1.0 - w1_) - w2_), w1_, w2_);
}

vec3 shading_normal(vec3 n0_, vec3 n1_, vec3 n2_, vec3 w_1, vec3 facing) {
    bool local_5 = false;
    vec3 s = (((n0_ * w_1.x) + (n1_ * w_1.y)) + (n2_ * w_1.z));
    float l2_1 = dot(s, s);
    if (!(!((l2_1 > 1e-12)))) {
        local_5 = !((l2_1 < 3e38));
    } else {
        local_5 = true;
    }
    bool _e24 = local_5;
    if (_e24) {
        return facing;
    }
    vec3 n_10 = (s / vec3(sqrt(l2_1)));
    return ((dot(n_10, facing) < 0.0) ? -(n_10) : n_10);
}

float ray_triangle(vec3 o_1, vec3 d_1, vec3 a_4, vec3 b_4, vec3 c_3, float t_min, float t_max_1) {
    bool local_6 = false;
    bool local_7 = false;
    bool local_8 = false;
    vec3 e1_1 = (b_4 - a_4);
    vec3 e2_1 = (c_3 - a_4);
    vec3 p_1 = cross(d_1, e2_1);
    float det = dot(e1_1, p_1);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv = (1.0 / det);
    vec3 s_1 = (o_1 - a_4);
    float u_2 = (dot(s_1, p_1) * inv);
    if (!((u_2 < 0.0))) {
        local_6 = (u_2 > 1.0);
    } else {
        local_6 = true;
    }
    bool _e28 = local_6;
    if (_e28) {
        return -1.0;
    }
    vec3 q_1 = cross(s_1, e1_1);
    float v_3 = (dot(d_1, q_1) * inv);
    if (!((v_3 < 0.0))) {
        local_7 = ((u_2 + v_3) > 1.0);
    } else {
        local_7 = true;
    }
    bool _e42 = local_7;
    if (_e42) {
        return -1.0;
    }
    float t = (dot(e2_1, q_1) * inv);
    if ((t > t_min)) {
        local_8 = (t < t_max_1);
    } else {
        local_8 = false;
    }
    bool _e51 = local_8;
    if (_e51) {
        return t;
    }
    return -1.0;
}

float mis_power(float pdf_a, float pdf_b) {
    float a2_ = (pdf_a * pdf_a);
    float s_2 = (a2_ + (pdf_b * pdf_b));
    if ((s_2 <= 0.0)) {
        return 0.0;
    }
    return (a2_ / s_2);
}

float light_strategy_pdf(float select, float rt2_1, float d2_2, float area, float cos_y) {
    bool local_9 = false;
    bool local_10 = false;
    if (!((d2_2 <= 0.0))) {
        local_9 = (area <= 0.0);
    } else {
        local_9 = true;
    }
    bool _e13 = local_9;
    if (!(_e13)) {
        local_10 = (cos_y <= 0.0);
    } else {
        local_10 = true;
    }
    bool _e20 = local_10;
    if (_e20) {
        return 0.0;
    }
    float _e22 = rr_probability(rt2_1, d2_2);
    float _e26 = area_to_solid_angle_pdf((1.0 / area), d2_2, cos_y);
    return ((select * _e22) * _e26);
}

vec3 lambert_brdf(vec3 rho) {
    return (rho * INV_PI);
}

float cosine_pdf(float cos_theta) {
    return (max(cos_theta, 0.0) * INV_PI);
}

vec3 onb_tangent(vec3 n_2) {
    float s_3 = ((n_2.z >= 0.0) ? 1.0 : -1.0);
    float a_5 = (-1.0 / (s_3 + n_2.z));
    return vec3((1.0 + (((s_3 * n_2.x) * n_2.x) * a_5)), (((s_3 * n_2.x) * n_2.y) * a_5), (-(s_3) * n_2.x));
}

vec3 onb_bitangent(vec3 n_3) {
    float s_4 = ((n_3.z >= 0.0) ? 1.0 : -1.0);
    float a_6 = (-1.0 / (s_4 + n_3.z));
    return vec3(((n_3.x * n_3.y) * a_6), (s_4 + ((n_3.y * n_3.y) * a_6)), -(n_3.y));
}

vec3 onb_to_world(vec3 n_4, vec3 d_2) {
    vec3 _e2 = onb_tangent(n_4);
    vec3 _e5 = onb_bitangent(n_4);
    return (((_e2 * d_2.x) + (_e5 * d_2.y)) + (n_4 * d_2.z));
}

vec3 cosine_direction(vec3 n_5, float u1_, float u2_) {
    float r_1 = sqrt(u1_);
    float phi = (6.2831855 * u2_);
    vec3 _e16 = onb_to_world(n_5, vec3((r_1 * cos(phi)), (r_1 * sin(phi)), sqrt(max((1.0 - u1_), 0.0))));
    return normalize(_e16);
}

vec3 camera_dir(vec3 forward, vec3 right, vec3 up, float px, float py, float w_2, float h_1) {
    float sx = (((2.0 * px) / w_2) - 1.0);
    float sy = (1.0 - ((2.0 * py) / h_1));
    return normalize(((forward + (right * sx)) + (up * sy)));
}

float jittered_pixel(uint coord, float u_1) {
    float _e2 = to_f32_(coord);
    return (_e2 + u_1);
}

bool plays_roulette(uint depth) {
    return (depth >= ROULETTE_DEPTH);
}

bool sees_emission(vec3 gn, vec3 dir_1) {
    return (dot(gn, dir_1) < 0.0);
}

bool continues_path(vec3 nd, vec3 n_6, vec3 ng) {
    bool local_11 = false;
    if ((dot(nd, n_6) > 0.0)) {
        local_11 = (dot(nd, ng) > 0.0);
    } else {
        local_11 = false;
    }
    bool _e12 = local_11;
    return _e12;
}

bool finite3_(vec3 v_1) {
    bool local_12 = false;
    bool local_13 = false;
    if ((abs(v_1.x) <= F32_MAX)) {
        local_12 = (abs(v_1.y) <= F32_MAX);
    } else {
        local_12 = false;
    }
    bool _e12 = local_12;
    if (_e12) {
        local_13 = (abs(v_1.z) <= F32_MAX);
    } else {
        local_13 = false;
    }
    bool _e20 = local_13;
    return _e20;
}

float path_survival(vec3 beta) {
    return clamp(max(max(beta.x, beta.y), beta.z), 0.05, 0.95);
}

float light_area(GpuLight l) {
    if ((l.kind == LIGHT_TRIANGLE)) {
        return l.a;
    }
    return 0.0;
}

vec3 light_normal(GpuLight l_1) {
    if ((l_1.kind == LIGHT_TRIANGLE)) {
        vec3 _e7 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
        return _e7;
    }
    return vec3(0.0);
}

GeoHit trace(vec3 o_2, vec3 d_3, float t_min_1, float t_max_2, bool any_hit) {
    GeoHit hit = GeoHit(0.0, 0u);
    uint stack[64] = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    uint sp = 0u;
    uint node = 0u;
    uint i = 0u;
    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((uint(_group_0_binding_5_cs.length()) == 0u)) {
        GeoHit _e13 = hit;
        return _e13;
    }
    vec3 _e14 = ray_inverse3_(d_3);
    while(true) {
        uint _e21 = node;
        GpuGeoNode n_11 = _group_0_binding_5_cs[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_11.bmin, n_11.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_11.count > 0u)) {
                i = n_11.first;
                bool loop_init = true;
                while(true) {
                    if (!loop_init) {
                        uint _e58 = i;
                        i = (_e58 + 1u);
                    }
                    loop_init = false;
                    uint _e36 = i;
                    if ((_e36 < (n_11.first + n_11.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_1 = _group_0_binding_6_cs[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_3, t_1.v0_, t_1.v1_, t_1.v2_, t_min_1, _e49);
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
                    stack[_e63] = (n_11.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node = n_11.first;
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
        node = _e80;
    }
    GeoHit _e81 = hit;
    return _e81;
}

float mis_weight(float pdf_a_1, float pdf_b_1) {
    float _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

float select_pdf(uint li, vec3 x_3, vec3 n_7, uint nee, bool in_range_1) {
    float _e6 = reservoir_select_pdf(nee, in_range_1, K);
    return _e6;
}

float light_pdf(uint li_1, vec3 x_4, vec3 n_8, vec3 y, uint nee_1, bool in_range_2) {
    GpuLight l_2 = _group_0_binding_1_cs[li_1];
    vec3 v_4 = (x_4 - y);
    float d2_3 = dot(v_4, v_4);
    vec3 _e11 = light_normal(l_2);
    float cos_y_1 = ((d2_3 > 0.0) ? dot(_e11, (v_4 / vec3(sqrt(d2_3)))) : 0.0);
    float _e20 = select_pdf(li_1, x_4, n_8, nee_1, in_range_2);
    float _e23 = _group_0_binding_2_cs[li_1];
    float _e24 = light_area(l_2);
    float _e25 = light_strategy_pdf(_e20, _e23, d2_3, _e24, cos_y_1);
    return _e25;
}

float next_uniform(inout uint state) {
    uint _e1 = state;
    uint _e2 = pcg_hash(_e1);
    state = _e2;
    uint _e3 = state;
    float _e4 = xi_from_bits(_e3);
    return _e4;
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    GpuPathState st = GpuPathState(vec3(0.0), 0u, vec3(0.0), 0u, vec3(0.0), 0.0, vec3(0.0), 0u, vec3(0.0), 0u);
    uint h = 0u;
    GpuPathVertex v = GpuPathVertex(vec3(0.0), 0u, vec3(0.0), 0.0, vec3(0.0), 0.0, vec3(0.0), 0.0);
    bool local = false;
    float w = 1.0;
    uint rng = 0u;
    bool local_1 = false;
    bool local_2 = false;
    uint i_1 = gid.x;
    uint _e4 = _group_0_binding_0_cs.width;
    uint _e7 = _group_0_binding_0_cs.height;
    if ((i_1 >= (_e4 * _e7))) {
        return;
    }
    uint _e13 = _group_0_binding_0_cs.depth;
    if ((_e13 == 0u)) {
        uint _e18 = _group_0_binding_0_cs.seed;
        uint _e21 = _group_0_binding_0_cs.pass_index;
        uint _e22 = path_stream(_e18, i_1, _e21);
        h = _e22;
        uint _e26 = _group_0_binding_0_cs.width;
        float _e28 = next_uniform(h);
        float _e29 = jittered_pixel((i_1 % _e26), _e28);
        uint _e32 = _group_0_binding_0_cs.width;
        float _e34 = next_uniform(h);
        float _e35 = jittered_pixel((i_1 / _e32), _e34);
        vec3 _e39 = _group_0_binding_0_cs.cam_pos;
        st.origin = _e39;
        vec3 _e43 = _group_0_binding_0_cs.cam_forward;
        vec3 _e46 = _group_0_binding_0_cs.cam_right;
        vec3 _e49 = _group_0_binding_0_cs.cam_up;
        uint _e52 = _group_0_binding_0_cs.width;
        uint _e56 = _group_0_binding_0_cs.height;
        vec3 _e58 = camera_dir(_e43, _e46, _e49, _e29, _e35, float(_e52), float(_e56));
        st.dir = _e58;
        st.alive = 1u;
        uint _e62 = h;
        st.rng = _e62;
        st.beta = vec3(1.0);
        st.pdf_bsdf = 0.0;
        vec3 _e71 = _group_0_binding_0_cs.cam_pos;
        st.prev = _e71;
    } else {
        GpuPathState _e74 = _group_0_binding_10_cs[i_1];
        st = _e74;
    }
    v.alive = 0u;
    uint _e79 = st.alive;
    if ((_e79 == 0u)) {
        GpuPathVertex _e84 = v;
        _group_0_binding_11_cs[i_1] = _e84;
        return;
    }
    vec3 _e86 = st.origin;
    vec3 _e88 = st.dir;
    float _e91 = _group_0_binding_0_cs.t_min;
    GeoHit _e94 = trace(_e86, _e88, _e91, F32_MAX, false);
    if ((_e94.tri == NO_LIGHT)) {
        st.alive = 0u;
        GpuPathState _e102 = st;
        _group_0_binding_10_cs[i_1] = _e102;
        GpuPathVertex _e105 = v;
        _group_0_binding_11_cs[i_1] = _e105;
        return;
    }
    GpuTriangle tri = _group_0_binding_6_cs[_e94.tri];
    vec3 _e111 = st.origin;
    vec3 _e113 = st.dir;
    vec3 x_5 = (_e111 + (_e113 * _e94.t));
    vec3 _e120 = triangle_normal(tri.v0_, tri.v1_, tri.v2_);
    vec3 _e122 = st.dir;
    vec3 _e123 = face_against(_e120, _e122);
    uint b_5 = (_e94.tri * 3u);
    vec4 _e129 = _group_0_binding_8_cs[b_5];
    vec4 _e135 = _group_0_binding_8_cs[(b_5 + 1u)];
    vec4 _e141 = _group_0_binding_8_cs[(b_5 + 2u)];
    vec3 _e146 = barycentric(x_5, tri.v0_, tri.v1_, tri.v2_);
    vec3 _e147 = shading_normal(_e129.xyz, _e135.xyz, _e141.xyz, _e146, _e123);
    if ((tri.light != NO_LIGHT)) {
        vec3 _e154 = st.dir;
        bool _e155 = sees_emission(_e120, _e154);
        local = _e155;
    } else {
        local = false;
    }
    bool _e157 = local;
    if (_e157) {
        float _e161 = st.pdf_bsdf;
        if ((_e161 > 0.0)) {
            uint _e168 = _group_0_binding_4_cs[tri.light];
            BshNode leaf = _group_0_binding_3_cs[_e168];
            vec3 _e174 = st.prev;
            bool _e175 = sphere_contains_point(leaf.center, leaf.radius, _e174);
            float _e177 = st.pdf_bsdf;
            vec3 _e180 = st.prev;
            vec3 _e182 = st.prev_normal;
            uint _e185 = _group_0_binding_9_cs[i_1];
            float _e186 = light_pdf(tri.light, _e180, _e182, x_5, _e185, _e175);
            float _e187 = mis_weight(_e177, _e186);
            w = _e187;
        }
        vec3 _e189 = st.beta;
        vec3 _e194 = _group_0_binding_1_cs[tri.light].intensity;
        float _e196 = w;
        vec3 add = ((_e189 * _e194) * _e196);
        bool _e198 = finite3_(add);
        if (_e198) {
            vec4 _e201 = _group_0_binding_12_cs[i_1];
            _group_0_binding_12_cs[i_1] = (_e201 + vec4(add, 0.0));
        }
    }
    vec4 _e208 = _group_0_binding_7_cs[tri.material];
    vec3 rho_1 = _e208.xyz;
    v.position = x_5;
    v.normal = _e147;
    v.gnormal = _e123;
    vec3 _e215 = st.beta;
    vec3 _e216 = lambert_brdf(rho_1);
    v.weight = (_e215 * _e216);
    v.alive = 1u;
    GpuPathVertex _e222 = v;
    _group_0_binding_11_cs[i_1] = _e222;
    uint _e224 = st.rng;
    rng = _e224;
    float _e226 = next_uniform(rng);
    float _e227 = next_uniform(rng);
    vec3 _e228 = cosine_direction(_e147, _e226, _e227);
    float cos_o = dot(_e228, _e147);
    vec3 _e231 = st.beta;
    st.beta = (_e231 * rho_1);
    st.prev = x_5;
    st.prev_normal = _e147;
    float _e236 = cosine_pdf(cos_o);
    st.pdf_bsdf = _e236;
    float _e240 = _group_0_binding_0_cs.eps;
    st.origin = (x_5 + (_e123 * _e240));
    st.dir = _e228;
    bool _e244 = continues_path(_e228, _e147, _e123);
    if (!(!(_e244))) {
        uint _e251 = _group_0_binding_0_cs.depth;
        uint _e256 = _group_0_binding_0_cs.max_depth;
        local_1 = ((_e251 + 1u) >= _e256);
    } else {
        local_1 = true;
    }
    bool _e259 = local_1;
    if (_e259) {
        st.alive = 0u;
    }
    uint _e264 = _group_0_binding_0_cs.depth;
    bool _e265 = plays_roulette(_e264);
    if (_e265) {
        uint _e269 = st.alive;
        local_2 = (_e269 == 1u);
    } else {
        local_2 = false;
    }
    bool _e273 = local_2;
    if (_e273) {
        vec3 _e275 = st.beta;
        float _e276 = path_survival(_e275);
        float _e277 = next_uniform(rng);
        if ((_e277 >= _e276)) {
            st.alive = 0u;
        } else {
            vec3 _e282 = st.beta;
            st.beta = (_e282 / vec3(_e276));
        }
    }
    uint _e286 = rng;
    st.rng = _e286;
    GpuPathState _e289 = st;
    _group_0_binding_10_cs[i_1] = _e289;
    return;
}

