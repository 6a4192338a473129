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
struct ImageParams {
    vec3 eye;
    uint width;
    uint height;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};
struct GpuMaterial {
    vec3 albedo;
    float metallic;
    vec3 emission;
    float alpha;
    vec3 f0_;
    float f90_;
};
struct MapParams {
    vec4 c0_;
    vec4 c1_;
    vec4 c2_;
    vec4 c3_;
    GpuLight light;
    vec3 origin;
    uint mode;
    vec3 axis;
    uint size;
    vec3 right;
    float extent;
    vec3 up;
    float texel;
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

layout(std140) uniform ImageParams_block_0Compute { ImageParams _group_0_binding_0_cs; };

uniform sampler2D _group_0_binding_1_cs;

uniform sampler2D _group_0_binding_2_cs;

uniform sampler2D _group_0_binding_3_cs;

layout(std430) readonly buffer type_6_block_1Compute { vec4 _group_0_binding_4_cs[]; };

layout(std430) readonly buffer type_7_block_2Compute { GpuMaterial _group_0_binding_5_cs[]; };

layout(rgba32f) writeonly uniform image2D _group_0_binding_6_cs;

uniform sampler2D _group_0_binding_7_cs;

layout(std140) uniform MapParams_block_3Compute { MapParams _group_0_binding_8_cs; };


float ggx_d(float cos_h, float sin2_h, float alpha) {
    if ((cos_h <= 0.0)) {
        return 0.0;
    }
    float a2_ = (alpha * alpha);
    float t = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t * t));
}

float smith_root(float cos_, float alpha_1) {
    float a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1.0 - a2_1)) + a2_1));
}

float smith_visibility(float n_l, float n_v, float alpha_2) {
    bool local_1 = false;
    if (!((n_l <= 0.0))) {
        local_1 = (n_v <= 0.0);
    } else {
        local_1 = true;
    }
    bool _e11 = local_1;
    if (_e11) {
        return 0.0;
    }
    float _e13 = smith_root(n_v, alpha_2);
    float _e15 = smith_root(n_l, alpha_2);
    return (0.5 / ((n_l * _e13) + (n_v * _e15)));
}

vec3 fresnel_schlick(vec3 f0_, float f90_, float v_h) {
    float c = clamp((1.0 - v_h), 0.0, 1.0);
    float c2_ = (c * c);
    return (f0_ + ((vec3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c)));
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

float half_cosine(vec3 v, vec3 l) {
    vec3 h = (v + l);
    float len2_ = dot(h, h);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return clamp((dot(v, h) / sqrt(len2_)), 0.0, 1.0);
}

vec3 specular_brdf(vec3 base_2, float metallic_2, vec3 f0_d_2, float f90_d_2, float alpha_3, vec3 n, vec3 v_1, vec3 l_1) {
    bool local_2 = false;
    float n_l_1 = dot(n, l_1);
    float n_v_1 = dot(n, v_1);
    if (!((n_l_1 <= 0.0))) {
        local_2 = (n_v_1 <= 0.0);
    } else {
        local_2 = true;
    }
    bool _e18 = local_2;
    if (_e18) {
        return vec3(0.0, 0.0, 0.0);
    }
    vec3 hs = (v_1 + l_1);
    float inv = (1.0 / sqrt(dot(hs, hs)));
    vec3 h_1 = (hs * inv);
    vec3 c_1 = cross(n, h_1);
    float _e32 = ggx_d(dot(n, h_1), dot(c_1, c_1), alpha_3);
    vec3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_1, h_1));
    float _e35 = smith_visibility(n_l_1, n_v_1, alpha_3);
    return (_e34 * (_e32 * _e35));
}

vec3 brdf_eval(vec3 base_3, float metallic_3, vec3 f0_d_3, float f90_d_3, float alpha_4, vec3 n_1, vec3 v_2, vec3 l_2) {
    if ((dot(n_1, l_2) <= 0.0)) {
        return vec3(0.0, 0.0, 0.0);
    }
    float _e15 = half_cosine(v_2, l_2);
    vec3 _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    vec3 _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_1, v_2, l_2);
    return (_e16 + _e17);
}

vec3 diffuse_albedo(vec3 base_4, float metallic_4) {
    return (base_4 * (1.0 - metallic_4));
}

bool has_specular(float metallic_5, vec3 f0_d_4, float f90_d_4) {
    bool local_3 = false;
    bool local_4 = false;
    if (!((metallic_5 > 0.0))) {
        local_3 = (f90_d_4 > 0.0);
    } else {
        local_3 = true;
    }
    bool _e11 = local_3;
    if (!(_e11)) {
        local_4 = (max(max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0.0);
    } else {
        local_4 = true;
    }
    bool _e23 = local_4;
    return _e23;
}

vec3 diffuse_radiance(vec3 albedo, vec3 emission, vec3 e) {
    return (emission + ((albedo * INV_PI) * e));
}

vec3 primary_light_dir(vec3 x, vec3 origin, vec3 axis, bool perspective) {
    bool local_5 = false;
    vec3 v_3 = (origin - x);
    float d2_ = dot(v_3, v_3);
    if (perspective) {
        local_5 = (d2_ > 0.0);
    } else {
        local_5 = false;
    }
    bool _e11 = local_5;
    if (_e11) {
        return (v_3 / vec3(sqrt(d2_)));
    }
    return -(axis);
}

vec3 glossy_radiance(vec3 base_5, vec3 emission_1, float metallic_6, vec3 f_direct, vec3 direct, vec3 indirect, vec3 specular) {
    vec3 _e9 = diffuse_albedo(base_5, metallic_6);
    return (((emission_1 + (f_direct * direct)) + ((_e9 * INV_PI) * indirect)) + specular);
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    bool local = false;
    vec3 radiance = vec3(0.0);
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
    uint _e19 = _group_0_binding_0_cs.width;
    uint i = ((gid.y * _e19) + gid.x);
    ivec2 texel = ivec2(int(gid.x), int(gid.y));
    vec4 p = texelFetch(_group_0_binding_1_cs, texel, 0);
    if ((p.w > 0.0)) {
        vec4 nm = texelFetch(_group_0_binding_2_cs, texel, 0);
        GpuMaterial m = _group_0_binding_5_cs[uint(nm.w)];
        vec4 _e47 = texelFetch(_group_0_binding_3_cs, texel, 0);
        vec3 e_1 = _e47.xyz;
        bool _e52 = has_specular(m.metallic, m.f0_, m.f90_);
        if (_e52) {
            vec3 _e56 = _group_0_binding_8_cs.origin;
            vec3 _e59 = _group_0_binding_8_cs.axis;
            uint _e62 = _group_0_binding_8_cs.mode;
            vec3 _e65 = primary_light_dir(p.xyz, _e56, _e59, (_e62 == MAP_PERSPECTIVE));
            vec3 _e75 = _group_0_binding_0_cs.eye;
            vec3 _e79 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, normalize(nm.xyz), normalize((_e75 - p.xyz)), _e65);
            vec4 _e85 = _group_0_binding_4_cs[i];
            vec4 _e89 = texelFetch(_group_0_binding_7_cs, texel, 0);
            vec3 _e91 = glossy_radiance(m.albedo, m.emission, m.metallic, _e79, _e85.xyz, e_1, _e89.xyz);
            radiance = _e91;
        } else {
            vec4 _e96 = _group_0_binding_4_cs[i];
            vec3 _e99 = diffuse_radiance(m.albedo, m.emission, (_e96.xyz + e_1));
            radiance = _e99;
        }
    }
    vec3 _e101 = radiance;
    imageStore(_group_0_binding_6_cs, texel, vec4(_e101, 1.0));
    return;
}

