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
struct VplParams {
    uint width;
    uint height;
    uint lights_per_subset;
    float min_d2_;
    float near_r2_;
    uint near_blocks;
    uint subset_shift;
    uint pad1_;
};
struct GpuNearBox {
    vec3 lo;
    float pad0_;
    vec3 hi;
    float pad1_;
};
struct GpuMaterial {
    vec3 albedo;
    float metallic;
    vec3 emission;
    float alpha;
    vec3 f0_;
    float f90_;
};
struct ViewParams {
    vec4 c0_;
    vec4 c1_;
    vec4 c2_;
    vec4 c3_;
    vec3 eye;
    uint width;
    uint height;
    uint pad0_;
    uint seed;
    uint frame;
    vec3 f0_d;
    float f90_d;
};
struct WorkgroupBox {
    vec3 lo;
    vec3 hi;
};
struct GbTexel {
    vec4 position;
    vec4 normal;
};
struct Glossy {
    GpuMaterial m;
    vec3 v;
    bool on;
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
const uint NEAR_BLOCK = 64u;
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
const uint P = 8u;
const uint TILE = 8u;
const uint THREADS = 64u;
const uint BOX_THREADS = 64u;
const uint NEAR_CHUNK = 32u;

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

layout(std140) uniform VplParams_block_0Compute { VplParams _group_0_binding_0_cs; };

layout(std140) uniform ViewParams_block_1Compute { ViewParams _group_0_binding_1_cs; };

uniform sampler2D _group_0_binding_2_cs;

uniform sampler2D _group_0_binding_3_cs;

layout(std430) readonly buffer type_8_block_2Compute { GpuLight _group_0_binding_4_cs[]; };

layout(std430) readonly buffer type_9_block_3Compute { uint _group_0_binding_5_cs[]; };

layout(std430) readonly buffer type_10_block_4Compute { GpuNearBox _group_0_binding_6_cs[]; };

layout(std430) readonly buffer type_4_block_5Compute { float _group_0_binding_7_cs[]; };

layout(std430) readonly buffer type_4_block_6Compute { float _group_0_binding_8_cs[]; };

layout(std430) buffer type_11_block_7Compute { vec4 _group_0_binding_9_cs[]; };

layout(std430) readonly buffer type_12_block_8Compute { GpuMaterial _group_0_binding_10_cs[]; };

layout(std430) buffer type_11_block_9Compute { vec4 _group_0_binding_11_cs[]; };

shared uint light_count;

shared uint light_list[2048];


float to_f32_(uint u) {
    return float(u);
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

float cull_radius(float r2_1) {
    return (sqrt(r2_1) * CULL_RADIUS_SCALE);
}

bool sphere_overlaps_aabb(vec3 c, float r, vec3 bmin, vec3 bmax) {
    vec3 q = clamp(c, bmin, bmax);
    vec3 v_6 = (q - c);
    return (dot(v_6, v_6) <= (r * r));
}

float vpl_transfer(vec3 n_l, vec3 n_x, vec3 v, float min_d2_) {
    float m_2 = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m_2 * m_2));
}

float ggx_d(float cos_h, float sin2_h, float alpha) {
    if ((cos_h <= 0.0)) {
        return 0.0;
    }
    float a2_ = (alpha * alpha);
    float t_1 = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t_1 * t_1));
}

float smith_root(float cos_, float alpha_1) {
    float a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1.0 - a2_1)) + a2_1));
}

float smith_visibility(float n_l_1, float n_v, float alpha_2) {
    bool local_5 = false;
    if (!((n_l_1 <= 0.0))) {
        local_5 = (n_v <= 0.0);
    } else {
        local_5 = true;
    }
    bool _e11 = local_5;
    if (_e11) {
        return 0.0;
    }
    float _e13 = smith_root(n_v, alpha_2);
    float _e15 = smith_root(n_l_1, alpha_2);
    return (0.5 / ((n_l_1 * _e13) + (n_v * _e15)));
}

vec3 fresnel_schlick(vec3 f0_, float f90_, float v_h) {
    float c_1 = clamp((1.0 - v_h), 0.0, 1.0);
    float c2_ = (c_1 * c_1);
    return (f0_ + ((vec3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_1)));
}

vec3 specular_fresnel(vec3 base, float metallic, vec3 f0_d, float f90_d, float v_h_1) {
    vec3 _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    vec3 _e10 = fresnel_schlick(base, 1.0, v_h_1);
    return ((_e5 * (1.0 - metallic)) + (_e10 * metallic));
}

vec3 diffuse_brdf(vec3 base_1, float metallic_1, vec3 f0_d_1, float f90_d_1, float v_h_2) {
    vec3 _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return ((((vec3(1.0, 1.0, 1.0) - _e9) * base_1) * (1.0 - metallic_1)) * INV_PI);
}

float half_cosine(vec3 v_1, vec3 l) {
    vec3 h = (v_1 + l);
    float len2_ = dot(h, h);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return clamp((dot(v_1, h) / sqrt(len2_)), 0.0, 1.0);
}

vec3 specular_brdf(vec3 base_2, float metallic_2, vec3 f0_d_2, float f90_d_2, float alpha_3, vec3 n, vec3 v_2, vec3 l_1) {
    bool local_6 = false;
    float n_l_2 = dot(n, l_1);
    float n_v_1 = dot(n, v_2);
    if (!((n_l_2 <= 0.0))) {
        local_6 = (n_v_1 <= 0.0);
    } else {
        local_6 = true;
    }
    bool _e18 = local_6;
    if (_e18) {
        return vec3(0.0, 0.0, 0.0);
    }
    vec3 hs = (v_2 + l_1);
    float inv = (1.0 / sqrt(dot(hs, hs)));
    vec3 h_1 = (hs * inv);
    vec3 c_2 = cross(n, h_1);
    float _e32 = ggx_d(dot(n, h_1), dot(c_2, c_2), alpha_3);
    vec3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_2, h_1));
    float _e35 = smith_visibility(n_l_2, n_v_1, alpha_3);
    return (_e34 * (_e32 * _e35));
}

vec3 brdf_eval(vec3 base_3, float metallic_3, vec3 f0_d_3, float f90_d_3, float alpha_4, vec3 n_1, vec3 v_3, vec3 l_2) {
    if ((dot(n_1, l_2) <= 0.0)) {
        return vec3(0.0, 0.0, 0.0);
    }
    float _e15 = half_cosine(v_3, l_2);
    vec3 _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    vec3 _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_1, v_3, l_2);
    return (_e16 + _e17);
}

vec3 diffuse_albedo(vec3 base_4, float metallic_4) {
    return (base_4 * (1.0 - metallic_4));
}

vec3 specular_correction(vec3 base_5, float metallic_5, vec3 f0_d_4, float f90_d_4, float alpha_5, vec3 n_2, vec3 v_4, vec3 l_3) {
    vec3 _e8 = brdf_eval(base_5, metallic_5, f0_d_4, f90_d_4, alpha_5, n_2, v_4, l_3);
    vec3 _e9 = diffuse_albedo(base_5, metallic_5);
    return (_e8 - (_e9 * INV_PI));
}

bool has_specular(float metallic_6, vec3 f0_d_5, float f90_d_5) {
    bool local_7 = false;
    bool local_8 = false;
    if (!((metallic_6 > 0.0))) {
        local_7 = (f90_d_5 > 0.0);
    } else {
        local_7 = true;
    }
    bool _e11 = local_7;
    if (!(_e11)) {
        local_8 = (max(max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0.0);
    } else {
        local_8 = true;
    }
    bool _e23 = local_8;
    return _e23;
}

float interleave_flux_scale(uint period) {
    float _e2 = to_f32_((period * period));
    return _e2;
}

float vpl_near_weight(float d2_2, float near_r2_) {
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t_2 = clamp(((near_r2_ - d2_2) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t_2 * t_2) * (3.0 - (2.0 * t_2)));
}

float vpl_near_range2_(float r2_2, uint period_1) {
    float _e2 = interleave_flux_scale(period_1);
    return (r2_2 / _e2);
}

float vpl_near_cull_range2_(float r2_3, float near_r2_1) {
    return min(r2_3, near_r2_1);
}

float vpl_near_slc_share(float rt2_1, float r2_4, float d2_3, float near_r2_2) {
    float _e4 = vpl_near_weight(d2_3, near_r2_2);
    float _e5 = slc_weight(rt2_1, d2_3);
    bool _e7 = slc_keep(r2_4, d2_3);
    return ((_e7 && (_e4 > 0.0)) ? (_e4 * _e5) : 0.0);
}

WorkgroupBox workgroup_box(uint li_1, vec3 p, bool has) {
    uint stride = 32u;
    wg_lo[li_1] = (has ? p : vec3(3.4028235e38));
    wg_hi[li_1] = (has ? p : vec3(-3.4028235e38));
    memoryBarrierShared();
    barrier();
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e42 = stride;
            stride = (_e42 / 2u);
        }
        loop_init = false;
        uint _e15 = stride;
        if ((_e15 > 0u)) {
        } else {
            break;
        }
        {
            uint _e18 = stride;
            if ((li_1 < _e18)) {
                vec3 _e24 = wg_lo[li_1];
                uint _e26 = stride;
                vec3 _e29 = wg_lo[(li_1 + _e26)];
                wg_lo[li_1] = min(_e24, _e29);
                vec3 _e35 = wg_hi[li_1];
                uint _e37 = stride;
                vec3 _e40 = wg_hi[(li_1 + _e37)];
                wg_hi[li_1] = max(_e35, _e40);
            }
            memoryBarrierShared();
            barrier();
        }
    }
    vec3 _e47 = wg_lo[0];
    vec3 _e50 = wg_hi[0];
    return WorkgroupBox(_e47, _e50);
}

vec4 surface_at(ivec2 texel) {
    vec4 p_1 = texelFetch(_group_0_binding_2_cs, texel, 0);
    return ((p_1.w > 0.0) ? vec4(p_1.xyz, 1.0) : vec4(0.0));
}

GbTexel gbuffer_at(uint i) {
    bool local_9 = false;
    uint _e3 = _group_0_binding_1_cs.width;
    uint _e8 = _group_0_binding_1_cs.width;
    ivec2 texel_1 = ivec2(int((i % _e3)), int((i / _e8)));
    vec4 _e12 = surface_at(texel_1);
    vec4 _e15 = texelFetch(_group_0_binding_3_cs, texel_1, 0);
    vec3 n_4 = _e15.xyz;
    float len2_1 = dot(n_4, n_4);
    if ((_e12.w > 0.0)) {
        local_9 = (len2_1 > 0.0);
    } else {
        local_9 = false;
    }
    bool valid = local_9;
    vec3 _e30 = _group_0_binding_1_cs.eye;
    vec3 v_7 = (_e12.xyz - _e30);
    vec4 position = vec4(_e12.xyz, (valid ? 1.0 : 0.0));
    vec4 normal = (valid ? vec4((n_4 / vec3(sqrt(len2_1))), sqrt(dot(v_7, v_7))) : vec4(0.0, 0.0, 0.0, 1e30));
    return GbTexel(position, normal);
}

Glossy glossy_at(uint i_1, vec3 x) {
    uint _e4 = _group_0_binding_1_cs.width;
    uint _e9 = _group_0_binding_1_cs.width;
    ivec2 texel_2 = ivec2(int((i_1 % _e4)), int((i_1 / _e9)));
    vec4 _e16 = texelFetch(_group_0_binding_3_cs, texel_2, 0);
    GpuMaterial m_3 = _group_0_binding_10_cs[uint(_e16.w)];
    vec3 _e23 = _group_0_binding_1_cs.eye;
    bool _e29 = has_specular(m_3.metallic, m_3.f0_, m_3.f90_);
    return Glossy(m_3, normalize((_e23 - x)), _e29);
}

vec3 glossy_term(Glossy g_1, GpuLight l_4, vec3 n_3, vec3 v_5, float t) {
    bool local_10 = false;
    if (!(!(g_1.on))) {
        local_10 = (t <= 0.0);
    } else {
        local_10 = true;
    }
    bool _e13 = local_10;
    if (_e13) {
        return vec3(0.0);
    }
    vec3 _e30 = specular_correction(g_1.m.albedo, g_1.m.metallic, g_1.m.f0_, g_1.m.f90_, g_1.m.alpha, n_3, g_1.v, normalize(-(v_5)));
    return ((l_4.intensity * _e30) * t);
}

float near_r2_of(uint slot) {
    float _e3 = _group_0_binding_8_cs[slot];
    float _e5 = vpl_near_range2_(_e3, P);
    return _e5;
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_lo = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_hi = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        light_count = 0u;
        light_list = uint[2048](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    }
    memoryBarrierShared();
    barrier();
    uvec3 wg = gl_WorkGroupID;
    uvec3 lid = gl_LocalInvocationID;
    uint li = gl_LocalInvocationIndex;
    bool local = false;
    vec4 pos = vec4(0.0);
    vec3 nrm = vec3(0.0);
    bool local_1 = false;
    vec3 e = vec3(0.0);
    uint kept = 0u;
    vec3 s = vec3(0.0);
    Glossy g = Glossy(GpuMaterial(vec3(0.0), 0.0, vec3(0.0), 0.0, vec3(0.0), 0.0), vec3(0.0), false);
    uint first = 0u;
    bool local_2 = false;
    bool local_3 = false;
    uint m = 0u;
    bool local_4 = false;
    uint m_1 = 0u;
    uint px = ((wg.x * TILE) + lid.x);
    uint py = ((wg.y * TILE) + lid.y);
    uint _e15 = _group_0_binding_0_cs.width;
    if ((px < _e15)) {
        uint _e21 = _group_0_binding_0_cs.height;
        local = (py < _e21);
    } else {
        local = false;
    }
    bool inside = local;
    uint _e27 = _group_0_binding_0_cs.width;
    uint pix = ((py * _e27) + px);
    if (inside) {
        GbTexel _e36 = gbuffer_at(pix);
        pos = _e36.position;
        nrm = _e36.normal.xyz;
    }
    if (inside) {
        float _e43 = pos.w;
        local_1 = (_e43 > 0.0);
    } else {
        local_1 = false;
    }
    bool valid_1 = local_1;
    vec4 _e48 = pos;
    WorkgroupBox _e50 = workgroup_box(li, _e48.xyz, valid_1);
    vec3 lo = _e50.lo;
    vec3 hi = _e50.hi;
    float _e55 = _group_0_binding_0_cs.near_r2_;
    float _e56 = cull_radius(_e55);
    float _e58 = interleave_flux_scale(P);
    float unscale = (1.0 / _e58);
    if (valid_1) {
        vec4 _e70 = pos;
        Glossy _e72 = glossy_at(pix, _e70.xyz);
        g = _e72;
    }
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e206 = first;
            first = (_e206 + NEAR_CHUNK);
        }
        loop_init_1 = false;
        uint _e75 = first;
        uint _e78 = _group_0_binding_0_cs.near_blocks;
        if ((_e75 < _e78)) {
        } else {
            break;
        }
        {
            if ((li == 0u)) {
                atomicExchange(light_count, 0u);
            }
            memoryBarrierShared();
            barrier();
            uint _e84 = first;
            uint b = (_e84 + li);
            if ((li < NEAR_CHUNK)) {
                uint _e92 = _group_0_binding_0_cs.near_blocks;
                local_2 = (b < _e92);
            } else {
                local_2 = false;
            }
            bool _e95 = local_2;
            if (_e95) {
                GpuNearBox nb = _group_0_binding_6_cs[b];
                if (all(lessThanEqual((nb.lo - vec3(_e56)), hi))) {
                    local_3 = all(lessThanEqual(lo, (nb.hi + vec3(_e56))));
                } else {
                    local_3 = false;
                }
                bool _e112 = local_3;
                if (_e112) {
                    m = 0u;
                    bool loop_init_2 = true;
                    while(true) {
                        if (!loop_init_2) {
                            uint _e151 = m;
                            m = (_e151 + 1u);
                        }
                        loop_init_2 = false;
                        uint _e115 = m;
                        if ((_e115 < NEAR_BLOCK)) {
                        } else {
                            break;
                        }
                        {
                            uint _e121 = m;
                            uint slot_1 = _group_0_binding_5_cs[((b * NEAR_BLOCK) + _e121)];
                            GpuLight l_5 = _group_0_binding_4_cs[slot_1];
                            float _e128 = near_r2_of(slot_1);
                            float _e131 = _group_0_binding_0_cs.near_r2_;
                            float _e132 = vpl_near_cull_range2_(_e128, _e131);
                            float _e133 = cull_radius(_e132);
                            if (any(notEqual(l_5.intensity, vec3(0.0)))) {
                                bool _e142 = sphere_overlaps_aabb(l_5.p0_, _e133, lo, hi);
                                local_4 = _e142;
                            } else {
                                local_4 = false;
                            }
                            bool _e144 = local_4;
                            if (_e144) {
                                uint _e148 = atomicAdd(light_count, 1u);
                                light_list[_e148] = slot_1;
                            }
                        }
                    }
                }
            }
            memoryBarrierShared();
            barrier();
            uint _e154 = light_count;
            memoryBarrierShared();
            barrier();
            if (valid_1) {
                m_1 = 0u;
                bool loop_init_3 = true;
                while(true) {
                    if (!loop_init_3) {
                        uint _e204 = m_1;
                        m_1 = (_e204 + 1u);
                    }
                    loop_init_3 = false;
                    uint _e157 = m_1;
                    if ((_e157 < _e154)) {
                    } else {
                        break;
                    }
                    {
                        uint _e160 = m_1;
                        uint slot_2 = light_list[_e160];
                        GpuLight l_6 = _group_0_binding_4_cs[slot_2];
                        vec4 _e166 = pos;
                        vec3 v_8 = (_e166.xyz - l_6.p0_);
                        float _e172 = _group_0_binding_7_cs[slot_2];
                        float _e174 = vpl_near_range2_(_e172, P);
                        float _e175 = near_r2_of(slot_2);
                        float _e179 = _group_0_binding_0_cs.near_r2_;
                        float _e180 = vpl_near_slc_share(_e174, _e175, dot(v_8, v_8), _e179);
                        if ((_e180 > 0.0)) {
                            vec3 _e184 = nrm;
                            float _e187 = _group_0_binding_0_cs.min_d2_;
                            float _e188 = vpl_transfer(l_6.p1_, _e184, v_8, _e187);
                            float t_3 = ((_e188 * _e180) * unscale);
                            vec3 _e191 = e;
                            e = (_e191 + (l_6.intensity * t_3));
                            vec3 _e195 = s;
                            Glossy _e196 = g;
                            vec3 _e197 = nrm;
                            vec3 _e198 = glossy_term(_e196, l_6, _e197, v_8, t_3);
                            s = (_e195 + _e198);
                            uint _e200 = kept;
                            kept = (_e200 + 1u);
                        }
                    }
                }
            }
            memoryBarrierShared();
            barrier();
        }
    }
    if (valid_1) {
        vec4 old = _group_0_binding_9_cs[pix];
        vec3 _e215 = e;
        uint _e218 = kept;
        _group_0_binding_9_cs[pix] = vec4((old.xyz + _e215), (old.w + float(_e218)));
        vec4 _e226 = _group_0_binding_11_cs[pix];
        vec3 _e228 = s;
        _group_0_binding_11_cs[pix] = vec4((_e226.xyz + _e228), 0.0);
        return;
    } else {
        return;
    }
}

