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
    uint subset_shift;
    uint far_groups_at;
    uint near_clusters_at;
    uint near_groups_at;
    uint box_count;
    uint pad0_;
    uint pad1_;
    uvec4 far_grid;
    uvec4 near_grid;
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
    float shadow_offset;
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
const uint P = 1u;
const uint TILE = 8u;
const uint THREADS = 64u;
const uint BOX_THREADS = 64u;
const uint MAX_TILE_LIGHTS = 1024u;

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

shared WorkgroupBox wg_box;

layout(std140) uniform VplParams_block_0Compute { VplParams _group_0_binding_0_cs; };

layout(std140) uniform ViewParams_block_1Compute { ViewParams _group_0_binding_1_cs; };

uniform sampler2D _group_0_binding_2_cs;

uniform sampler2D _group_0_binding_3_cs;

layout(std430) readonly buffer type_8_block_2Compute { GpuLight _group_0_binding_4_cs[]; };

layout(std430) buffer type_9_block_3Compute { vec4 _group_0_binding_8_cs[]; };

layout(std430) buffer type_9_block_4Compute { vec4 _group_0_binding_9_cs[]; };

layout(std430) readonly buffer type_10_block_5Compute { GpuMaterial _group_0_binding_10_cs[]; };

layout(std430) buffer type_9_block_6Compute { vec4 _group_0_binding_11_cs[]; };

vec3 pos = vec3(0.0);

vec3 nrm = vec3(0.0);

float eye_distance = 0.0;

bool valid = false;

vec3 e = vec3(0.0);

uint kept = 0u;

vec3 s = vec3(0.0);

Glossy g_1 = Glossy(GpuMaterial(vec3(0.0), 0.0, vec3(0.0), 0.0, vec3(0.0), 0.0), vec3(0.0), false);


float vpl_transfer(vec3 n_l, vec3 n_x, vec3 v, float min_d2_) {
    float m = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m * m));
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
    bool local_1 = false;
    if (!((n_l_1 <= 0.0))) {
        local_1 = (n_v <= 0.0);
    } else {
        local_1 = true;
    }
    bool _e11 = local_1;
    if (_e11) {
        return 0.0;
    }
    float _e13 = smith_root(n_v, alpha_2);
    float _e15 = smith_root(n_l_1, alpha_2);
    return (0.5 / ((n_l_1 * _e13) + (n_v * _e15)));
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

float half_cosine(vec3 v_1, vec3 l) {
    vec3 h = (v_1 + l);
    float len2_ = dot(h, h);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return clamp((dot(v_1, h) / sqrt(len2_)), 0.0, 1.0);
}

vec3 specular_brdf(vec3 base_2, float metallic_2, vec3 f0_d_2, float f90_d_2, float alpha_3, vec3 n, vec3 v_2, vec3 l_1) {
    bool local_2 = false;
    float n_l_2 = dot(n, l_1);
    float n_v_1 = dot(n, v_2);
    if (!((n_l_2 <= 0.0))) {
        local_2 = (n_v_1 <= 0.0);
    } else {
        local_2 = true;
    }
    bool _e18 = local_2;
    if (_e18) {
        return vec3(0.0, 0.0, 0.0);
    }
    vec3 hs = (v_2 + l_1);
    float inv = (1.0 / sqrt(dot(hs, hs)));
    vec3 h_1 = (hs * inv);
    vec3 c_1 = cross(n, h_1);
    float _e32 = ggx_d(dot(n, h_1), dot(c_1, c_1), alpha_3);
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
    bool local_3 = false;
    bool local_4 = false;
    if (!((metallic_6 > 0.0))) {
        local_3 = (f90_d_5 > 0.0);
    } else {
        local_3 = true;
    }
    bool _e11 = local_3;
    if (!(_e11)) {
        local_4 = (max(max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0.0);
    } else {
        local_4 = true;
    }
    bool _e23 = local_4;
    return _e23;
}

uint shifted_subset(uint pixel_class, uint shift, uint period) {
    return ((pixel_class + shift) % (period * period));
}

float vpl_near_weight(float d2_, float near_r2_) {
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t_2 = clamp(((near_r2_ - d2_) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t_2 * t_2) * (3.0 - (2.0 * t_2)));
}

float vpl_far_weight(float d2_1, float near_r2_1) {
    float _e2 = vpl_near_weight(d2_1, near_r2_1);
    return (1.0 - _e2);
}

WorkgroupBox workgroup_bounds(uint li_1, vec3 lo, vec3 hi) {
    uint stride = 32u;
    wg_lo[li_1] = lo;
    wg_hi[li_1] = hi;
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

WorkgroupBox point_box(vec3 p, bool has) {
    return WorkgroupBox((has ? p : vec3(3.4028235e38)), (has ? p : vec3(-3.4028235e38)));
}

WorkgroupBox workgroup_box(uint li_2, vec3 p_1, bool has_1) {
    WorkgroupBox _e3 = point_box(p_1, has_1);
    WorkgroupBox _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi);
    return _e6;
}

vec4 surface_at(ivec2 texel) {
    vec4 p_3 = texelFetch(_group_0_binding_2_cs, texel, 0);
    return ((p_3.w > 0.0) ? vec4(p_3.xyz, 1.0) : vec4(0.0));
}

GbTexel gbuffer_at(uint i) {
    bool local_5 = false;
    uint _e3 = _group_0_binding_1_cs.width;
    uint _e8 = _group_0_binding_1_cs.width;
    ivec2 texel_1 = ivec2(int((i % _e3)), int((i / _e8)));
    vec4 _e12 = surface_at(texel_1);
    vec4 _e15 = texelFetch(_group_0_binding_3_cs, texel_1, 0);
    vec3 n_4 = _e15.xyz;
    float len2_1 = dot(n_4, n_4);
    if ((_e12.w > 0.0)) {
        local_5 = (len2_1 > 0.0);
    } else {
        local_5 = false;
    }
    bool valid_1 = local_5;
    vec3 _e30 = _group_0_binding_1_cs.eye;
    vec3 v_6 = (_e12.xyz - _e30);
    vec4 position = vec4(_e12.xyz, (valid_1 ? 1.0 : 0.0));
    vec4 normal = (valid_1 ? vec4((n_4 / vec3(sqrt(len2_1))), sqrt(dot(v_6, v_6))) : vec4(0.0, 0.0, 0.0, 1e30));
    return GbTexel(position, normal);
}

Glossy glossy_at(uint i_1, vec3 x) {
    uint _e4 = _group_0_binding_1_cs.width;
    uint _e9 = _group_0_binding_1_cs.width;
    ivec2 texel_2 = ivec2(int((i_1 % _e4)), int((i_1 / _e9)));
    vec4 _e16 = texelFetch(_group_0_binding_3_cs, texel_2, 0);
    GpuMaterial m_1 = _group_0_binding_10_cs[uint(_e16.w)];
    vec3 _e23 = _group_0_binding_1_cs.eye;
    bool _e29 = has_specular(m_1.metallic, m_1.f0_, m_1.f90_);
    return Glossy(m_1, normalize((_e23 - x)), _e29);
}

vec3 glossy_term(Glossy g, GpuLight l_4, vec3 n_3, vec3 v_5, float t) {
    bool local_6 = false;
    if (!(!(g.on))) {
        local_6 = (t <= 0.0);
    } else {
        local_6 = true;
    }
    bool _e13 = local_6;
    if (_e13) {
        return vec3(0.0);
    }
    vec3 _e30 = specular_correction(g.m.albedo, g.m.metallic, g.m.f0_, g.m.f90_, g.m.alpha, n_3, g.v, normalize(-(v_5)));
    return ((l_4.intensity * _e30) * t);
}

WorkgroupBox load_receiver(uint li_3, uint pix, bool inside) {
    vec4 p_2 = vec4(0.0);
    bool local_7 = false;
    eye_distance = DEPTH_NONE;
    if (inside) {
        GbTexel _e8 = gbuffer_at(pix);
        p_2 = _e8.position;
        nrm = _e8.normal.xyz;
        eye_distance = _e8.normal.w;
    }
    vec4 _e17 = p_2;
    pos = _e17.xyz;
    if (inside) {
        float _e23 = p_2.w;
        local_7 = (_e23 > 0.0);
    } else {
        local_7 = false;
    }
    bool _e27 = local_7;
    valid = _e27;
    bool _e29 = valid;
    if (_e29) {
        vec3 _e32 = pos;
        Glossy _e33 = glossy_at(pix, _e32);
        g_1 = _e33;
    }
    vec3 _e35 = pos;
    bool _e37 = valid;
    WorkgroupBox _e38 = workgroup_box(li_3, _e35, _e37);
    return _e38;
}

void shade_light(uint j_1) {
    GpuLight l_5 = _group_0_binding_4_cs[j_1];
    vec3 _e5 = pos;
    vec3 v_7 = (_e5 - l_5.p0_);
    float _e11 = _group_0_binding_0_cs.near_r2_;
    float _e12 = vpl_far_weight(dot(v_7, v_7), _e11);
    if ((_e12 > 0.0)) {
        vec3 _e17 = nrm;
        float _e20 = _group_0_binding_0_cs.min_d2_;
        float _e21 = vpl_transfer(l_5.p1_, _e17, v_7, _e20);
        float t_3 = (_e21 * _e12);
        vec3 _e24 = e;
        e = (_e24 + (l_5.intensity * t_3));
        vec3 _e29 = s;
        Glossy _e31 = g_1;
        vec3 _e33 = nrm;
        vec3 _e34 = glossy_term(_e31, l_5, _e33, v_7, t_3);
        s = (_e29 + _e34);
        uint _e37 = kept;
        kept = (_e37 + 1u);
        return;
    } else {
        return;
    }
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_lo = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_hi = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_box = WorkgroupBox(vec3(0.0), vec3(0.0));
    }
    memoryBarrierShared();
    barrier();
    uvec3 wg = gl_WorkGroupID;
    uvec3 lid = gl_LocalInvocationID;
    uint li = gl_LocalInvocationIndex;
    bool local = false;
    uint j = 0u;
    uint sub = wg.z;
    uint px = ((sub % P) + (((wg.x * TILE) + lid.x) * P));
    uint py = ((sub / P) + (((wg.y * TILE) + lid.y) * P));
    uint _e26 = _group_0_binding_0_cs.width;
    if ((px < _e26)) {
        uint _e32 = _group_0_binding_0_cs.height;
        local = (py < _e32);
    } else {
        local = false;
    }
    bool inside_1 = local;
    uint _e38 = _group_0_binding_0_cs.width;
    uint pix_1 = ((py * _e38) + px);
    WorkgroupBox _e41 = load_receiver(li, pix_1, inside_1);
    uint _e44 = _group_0_binding_0_cs.subset_shift;
    uint _e46 = shifted_subset(sub, _e44, P);
    bool _e48 = valid;
    if (_e48) {
        uint _e51 = _group_0_binding_0_cs.lights_per_subset;
        uint base_6 = (_e46 * _e51);
        j = base_6;
        bool loop_init_1 = true;
        while(true) {
            if (!loop_init_1) {
                uint _e71 = j;
                j = (_e71 + 1u);
            }
            loop_init_1 = false;
            uint _e54 = j;
            uint _e57 = _group_0_binding_0_cs.lights_per_subset;
            if ((_e54 < (base_6 + _e57))) {
            } else {
                break;
            }
            {
                uint _e61 = j;
                vec3 _e64 = _group_0_binding_4_cs[_e61].intensity;
                if (any(notEqual(_e64, vec3(0.0)))) {
                    uint _e69 = j;
                    shade_light(_e69);
                }
            }
        }
    }
    if (inside_1) {
        vec3 _e76 = e;
        uint _e78 = kept;
        _group_0_binding_8_cs[pix_1] = vec4(_e76, float(_e78));
        vec3 _e84 = nrm;
        float _e86 = eye_distance;
        _group_0_binding_9_cs[pix_1] = vec4(_e84, _e86);
        vec3 _e91 = s;
        _group_0_binding_11_cs[pix_1] = vec4(_e91, 0.0);
        return;
    } else {
        return;
    }
}

