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
struct ViewParams {
    vec4 c0_;
    vec4 c1_;
    vec4 c2_;
    vec4 c3_;
    vec3 eye;
    uint width;
    uint height;
    float background;
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
    uint pad;
};
struct Connection {
    vec3 e;
    vec3 y;
    float cos_x;
};
struct WeightedPicks {
    uint light[8];
    float w[8];
    float w_sum;
    uint n;
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
const uint BSH = 0u;

layout(std140) uniform ViewParams_block_0Compute { ViewParams _group_0_binding_0_cs; };

uniform sampler2D _group_0_binding_1_cs;

uniform sampler2D _group_0_binding_2_cs;

layout(rgba16f) writeonly uniform image2D _group_0_binding_3_cs;

layout(std430) readonly buffer type_8_block_1Compute { GpuLight _group_1_binding_1_cs[]; };

layout(std430) readonly buffer type_4_block_2Compute { float _group_1_binding_2_cs[]; };

layout(std430) readonly buffer type_4_block_3Compute { float _group_1_binding_3_cs[]; };

layout(std430) readonly buffer type_9_block_4Compute { BshNode _group_1_binding_4_cs[]; };

layout(std430) readonly buffer type_10_block_5Compute { GpuLightCone _group_1_binding_5_cs[]; };


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
    vec3 v = (x_1 - c);
    return (dot(v, v) <= (r * r));
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
    bool local_2 = false;
    bool local_3 = false;
    vec3 v_1 = (x_2 - y);
    float d2_5 = dot(v_1, v_1);
    bool _e7 = slc_keep(r2_1, d2_5);
    if (!(!(_e7))) {
        local_2 = !((d2_5 > 0.0));
    } else {
        local_2 = true;
    }
    bool _e16 = local_2;
    if (_e16) {
        return 0.0;
    }
    vec3 w_5 = (v_1 / vec3(sqrt(d2_5)));
    float cos_x_1 = -(dot(n, w_5));
    if (!((cos_x_1 <= 0.0))) {
        local_3 = (dot(ng, w_5) >= 0.0);
    } else {
        local_3 = true;
    }
    bool _e32 = local_3;
    if (_e32) {
        return 0.0;
    }
    return cos_x_1;
}

float spot_falloff(float cos_theta, float cos_outer, float cos_inner) {
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t_1 = clamp(((cos_theta - cos_outer) / (cos_inner - cos_outer)), 0.0, 1.0);
    return ((t_1 * t_1) * (3.0 - (2.0 * t_1)));
}

bool weighted_replace(float w_1, float w_sum, float u_1) {
    return ((u_1 * w_sum) < w_1);
}

float weighted_pick_weight(float w_sum_1, float w_2, uint k_1) {
    float _e3 = to_f32_(k_1);
    return (w_sum_1 / (_e3 * w_2));
}

float cos_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    if ((cos_a > cos_b)) {
        return 1.0;
    }
    return ((cos_a * cos_b) + (sin_a * sin_b));
}

float sin_sub_clamped(float sin_a_1, float cos_a_1, float sin_b_1, float cos_b_1) {
    if ((cos_a_1 > cos_b_1)) {
        return 0.0;
    }
    return ((sin_a_1 * cos_b_1) - (cos_a_1 * sin_b_1));
}

float safe_sqrt(float x_3) {
    return sqrt(max(x_3, 0.0));
}

float light_importance(vec3 center, float radius, float phi, vec3 axis, float cos_o, float cos_e, vec3 p, vec3 n_1) {
    float imp = 0.0;
    vec3 v_2 = (p - center);
    float dist2_ = dot(v_2, v_2);
    float r2_3 = (radius * radius);
    float d2_6 = max(max(dist2_, r2_3), MIN_D2_);
    vec3 wi = ((dist2_ > 0.0) ? (v_2 / vec3(sqrt(dist2_))) : vec3(0.0, 0.0, 0.0));
    float cos_w = dot(axis, wi);
    float _e28 = safe_sqrt((1.0 - (cos_w * cos_w)));
    float _e32 = safe_sqrt((1.0 - (r2_3 / dist2_)));
    float cos_b_2 = ((dist2_ <= r2_3) ? -1.0 : _e32);
    float _e39 = safe_sqrt((1.0 - (cos_b_2 * cos_b_2)));
    float _e43 = safe_sqrt((1.0 - (cos_o * cos_o)));
    float _e44 = cos_sub_clamped(_e28, cos_w, _e43, cos_o);
    float _e45 = sin_sub_clamped(_e28, cos_w, _e43, cos_o);
    float _e46 = cos_sub_clamped(_e45, _e44, _e39, cos_b_2);
    if ((_e46 <= cos_e)) {
        return 0.0;
    }
    imp = ((phi * _e46) / d2_6);
    if ((dot(n_1, n_1) > 0.0)) {
        float cos_i = -(dot(wi, n_1));
        float _e60 = safe_sqrt((1.0 - (cos_i * cos_i)));
        float _e61 = imp;
        float _e62 = cos_sub_clamped(_e60, cos_i, _e39, cos_b_2);
        imp = (_e61 * max(_e62, 0.0));
    }
    float _e66 = imp;
    return max(_e66, 0.0);
}

float candidate_weight(float importance, float rt2_2, float d2_4) {
    float _e3 = slc_weight(rt2_2, d2_4);
    return (importance * _e3);
}

float cone_weight(vec3 center_1, float radius_1, float phi_1, vec3 axis_1, float cos_o_1, float cos_e_1, float rt2_3, vec3 p_1, vec3 n_2) {
    vec3 v_3 = (p_1 - center_1);
    float _e10 = light_importance(center_1, radius_1, phi_1, axis_1, cos_o_1, cos_e_1, p_1, n_2);
    float _e14 = candidate_weight((_e10 * INV_PI), rt2_3, dot(v_3, v_3));
    return _e14;
}

vec3 light_intensity(GpuLight l, vec3 w_3) {
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            float _e9 = spot_falloff(dot(l.p1_, w_3), l.a, l.b);
            return (l.intensity * _e9);
        }
        default: {
            return vec3(0.0);
        }
    }
}

vec3 light_point(GpuLight l_1, float u1_, float u2_) {
    return l_1.p0_;
}

bool occluded(vec3 a_2, vec3 b_2) {
    return false;
}

BshNode bsh_node(uint nodes, uint i) {
    BshNode _e4 = _group_1_binding_4_cs[i];
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

uint bsh_next_leaf(uint nodes_3, uint start, vec3 x_4) {
    uint i_1 = 0u;
    i_1 = start;
    while(true) {
        uint _e4 = i_1;
        if ((_e4 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e7 = i_1;
            BshNode _e8 = bsh_node(nodes_3, _e7);
            bool _e11 = sphere_contains_point(_e8.center, _e8.radius, x_4);
            if (_e11) {
                if ((_e8.child == BSH_NONE)) {
                    uint _e15 = i_1;
                    return _e15;
                }
                i_1 = _e8.child;
            } else {
                i_1 = _e8.next;
            }
        }
    }
    return BSH_NONE;
}

Connection connect(uint li, vec3 x_5, vec3 n_3, vec3 ng_1, float w_res, float u1_1, float u2_1, float eps) {
    Connection c_1 = Connection(vec3(0.0), vec3(0.0), 0.0);
    bool local_4 = false;
    c_1.e = vec3(0.0);
    GpuLight l_2 = _group_1_binding_1_cs[li];
    vec3 _e16 = light_point(l_2, u1_1, u2_1);
    c_1.y = _e16;
    vec3 _e19 = c_1.y;
    float _e22 = _group_1_binding_3_cs[li];
    float _e23 = connection_cosine(x_5, _e19, n_3, ng_1, _e22);
    c_1.cos_x = _e23;
    float _e25 = c_1.cos_x;
    if (!((_e25 <= 0.0))) {
        vec3 _e34 = c_1.y;
        bool _e35 = occluded((x_5 + (ng_1 * eps)), _e34);
        local_4 = _e35;
    } else {
        local_4 = true;
    }
    bool _e37 = local_4;
    if (_e37) {
        Connection _e38 = c_1;
        return _e38;
    }
    vec3 _e40 = c_1.y;
    vec3 v_4 = (x_5 - _e40);
    float d2_7 = dot(v_4, v_4);
    vec3 _e47 = light_intensity(l_2, (v_4 / vec3(sqrt(d2_7))));
    float _e49 = c_1.cos_x;
    float _e52 = _group_1_binding_2_cs[li];
    float _e53 = connection_factor(_e49, d2_7, _e52, w_res);
    c_1.e = (_e47 * _e53);
    Connection _e55 = c_1;
    return _e55;
}

float light_weight(uint li_1, vec3 x_6, vec3 n_4) {
    GpuLightCone c_2 = _group_1_binding_5_cs[li_1];
    float _e14 = _group_1_binding_2_cs[li_1];
    float _e15 = cone_weight(c_2.center, c_2.radius, c_2.phi, c_2.axis, c_2.cos_o, c_2.cos_e, _e14, x_6, n_4);
    return _e15;
}

WeightedPicks bsh_weighted_collect(vec3 x_7, vec3 n_5, uint seed_1) {
    WeightedPicks picks = WeightedPicks(uint[8](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u), float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), 0.0, 0u);
    uint h_1 = 0u;
    uint b_3 = 0u;
    uint s = 0u;
    picks.w_sum = 0.0;
    picks.n = 0u;
    h_1 = seed_1;
    uint _e11 = bsh_first(BSH);
    uint _e12 = bsh_next_leaf(BSH, _e11, x_7);
    b_3 = _e12;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e55 = b_3;
            uint _e58 = _group_1_binding_4_cs[_e55].next;
            uint _e59 = bsh_next_leaf(BSH, _e58, x_7);
            b_3 = _e59;
        }
        loop_init = false;
        uint _e14 = b_3;
        if ((_e14 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e18 = picks.n;
            picks.n = (_e18 + 1u);
            uint _e22 = b_3;
            uint li_3 = _group_1_binding_4_cs[_e22].light;
            float _e26 = light_weight(li_3, x_7, n_5);
            if ((_e26 > 0.0)) {
                float _e30 = picks.w_sum;
                picks.w_sum = (_e30 + _e26);
                s = 0u;
                bool loop_init_1 = true;
                while(true) {
                    if (!loop_init_1) {
                        uint _e51 = s;
                        s = (_e51 + 1u);
                    }
                    loop_init_1 = false;
                    uint _e34 = s;
                    if ((_e34 < K)) {
                    } else {
                        break;
                    }
                    {
                        uint _e37 = h_1;
                        uint _e38 = pcg_hash(_e37);
                        h_1 = _e38;
                        float _e40 = picks.w_sum;
                        uint _e41 = h_1;
                        float _e42 = xi_from_bits(_e41);
                        bool _e43 = weighted_replace(_e26, _e40, _e42);
                        if (_e43) {
                            uint _e45 = s;
                            picks.light[_e45] = li_3;
                            uint _e48 = s;
                            picks.w[_e48] = _e26;
                        }
                    }
                }
            }
        }
    }
    WeightedPicks _e60 = picks;
    return _e60;
}

vec4 unproject_pixel(vec4 c0_, vec4 c1_, vec4 c2_, vec4 c3_, float px, float py, float width, float height, float depth, float background) {
    if ((depth == background)) {
        return vec4(0.0, 0.0, 0.0, 0.0);
    }
    float x_9 = ((((px + 0.5) / width) * 2.0) - 1.0);
    float y_1 = (1.0 - (((py + 0.5) / height) * 2.0));
    vec4 p_2 = ((((c0_ * x_9) + (c1_ * y_1)) + (c2_ * depth)) + c3_);
    if ((abs(p_2.w) > 0.0)) {
        return vec4((p_2.x / p_2.w), (p_2.y / p_2.w), (p_2.z / p_2.w), 1.0);
    }
    return vec4(0.0, 0.0, 0.0, 0.0);
}

vec4 surface_at(ivec2 texel) {
    vec4 _e3 = texelFetch(_group_0_binding_1_cs, texel, 0);
    float d = _e3.x;
    vec4 _e7 = _group_0_binding_0_cs.c0_;
    vec4 _e10 = _group_0_binding_0_cs.c1_;
    vec4 _e13 = _group_0_binding_0_cs.c2_;
    vec4 _e16 = _group_0_binding_0_cs.c3_;
    uint _e23 = _group_0_binding_0_cs.width;
    uint _e27 = _group_0_binding_0_cs.height;
    float _e31 = _group_0_binding_0_cs.background;
    vec4 _e32 = unproject_pixel(_e7, _e10, _e13, _e16, float(texel.x), float(texel.y), float(_e23), float(_e27), d, _e31);
    return _e32;
}

Shaded shade_pick(uint li_2, vec3 x_8, vec3 n_6, Material m_1, float w_4, float u1_2, float u2_2) {
    Shaded s_1 = Shaded(vec3(0.0), vec3(0.0), vec3(0.0));
    Connection _e9 = connect(li_2, x_8, n_6, n_6, w_4, u1_2, u2_2, 0.0);
    s_1.e = _e9.e;
    s_1.diffuse = vec3(0.0);
    s_1.specular = vec3(0.0);
    Shaded _e18 = s_1;
    return _e18;
}

Shaded add(Shaded a_3, Shaded b_4) {
    return Shaded((a_3.e + b_4.e), (a_3.diffuse + b_4.diffuse), (a_3.specular + b_4.specular));
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    bool local = false;
    bool local_1 = false;
    Material m = Material(vec3(0.0), 0.0, 0.0, vec3(0.0));
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
    vec3 x_10 = _e21.xyz;
    vec3 n_7 = (nn / vec3(sqrt(len2_)));
    uint _e48 = _group_0_binding_0_cs.seed;
    uint _e52 = _group_0_binding_0_cs.width;
    uint _e58 = _group_0_binding_0_cs.frame;
    uint _e59 = point_stream(_e48, ((gid.y * _e52) + gid.x), _e58);
    uint _e60 = pick_stream(_e59);
    h = _e60;
    WeightedPicks _e70 = bsh_weighted_collect(x_10, n_7, _e59);
    if ((_e70.w_sum > 0.0)) {
        bool loop_init_2 = true;
        while(true) {
            if (!loop_init_2) {
                uint _e101 = k;
                k = (_e101 + 1u);
            }
            loop_init_2 = false;
            uint _e76 = k;
            if ((_e76 < K)) {
            } else {
                break;
            }
            {
                uint _e79 = h;
                uint _e80 = pcg_hash(_e79);
                h = _e80;
                uint _e81 = h;
                float _e82 = xi_from_bits(_e81);
                uint _e83 = h;
                uint _e84 = pcg_hash(_e83);
                h = _e84;
                Shaded _e85 = t;
                uint _e87 = k;
                Material _e89 = m;
                uint _e92 = k;
                float _e95 = weighted_pick_weight(_e70.w_sum, _e70.w[_e92], K);
                uint _e96 = h;
                float _e97 = xi_from_bits(_e96);
                Shaded _e98 = shade_pick(_e70.light[_e87], x_10, n_7, _e89, _e95, _e82, _e97);
                Shaded _e99 = add(_e85, _e98);
                t = _e99;
            }
        }
    }
    uint count = _e70.n;
    vec3 _e106 = t.e;
    imageStore(_group_0_binding_3_cs, texel_1, vec4(_e106, float(count)));
    return;
}

