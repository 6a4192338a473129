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
struct GpuBox {
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
const uint P = 8u;
const uint TILE = 8u;
const uint THREADS = 64u;
const uint BOX_THREADS = 64u;
const uint HALF = 4u;
const uint QUARTER_LIGHTS = 256u;

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

shared WorkgroupBox wg_box;

layout(std140) uniform VplParams_block_0Compute { VplParams _group_0_binding_0_cs; };

layout(std140) uniform ViewParams_block_1Compute { ViewParams _group_0_binding_1_cs; };

uniform sampler2D _group_0_binding_2_cs;

uniform sampler2D _group_0_binding_3_cs;

layout(std430) readonly buffer type_9_block_2Compute { GpuLight _group_0_binding_4_cs[]; };

layout(std430) readonly buffer type_10_block_3Compute { uint _group_0_binding_5_cs[]; };

layout(std430) readonly buffer type_11_block_4Compute { GpuBox _group_0_binding_6_cs[]; };

layout(std430) readonly buffer type_5_block_5Compute { float _group_0_binding_7_cs[]; };

layout(std430) readonly buffer type_5_block_6Compute { float _group_0_binding_8_cs[]; };

layout(std430) buffer type_12_block_7Compute { vec4 _group_0_binding_9_cs[]; };

layout(std430) readonly buffer type_13_block_8Compute { GpuMaterial _group_0_binding_10_cs[]; };

layout(std430) buffer type_12_block_9Compute { vec4 _group_0_binding_11_cs[]; };

vec3 pos = vec3(0.0);

vec3 nrm = vec3(0.0);

float eye_distance = 0.0;

bool valid = false;

vec3 e = vec3(0.0);

uint kept = 0u;

vec3 s = vec3(0.0);

Glossy g_4 = Glossy(GpuMaterial(vec3(0.0), 0.0, vec3(0.0), 0.0, vec3(0.0), 0.0), vec3(0.0), false);

shared vec3 quarter_lo[4];

shared vec3 quarter_hi[4];

shared uint quarter_lights[1024];

shared uint quarter_count[4];

shared uint fullest;

uint quarter = 0u;

shared uint cluster_hits[64];

shared uint hit_count;


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
    vec3 q_1 = clamp(c, bmin, bmax);
    vec3 v_6 = (q_1 - c);
    return (dot(v_6, v_6) <= (r * r));
}

uint groups_across(uint bw, uint gw) {
    return (((bw + gw) - 1u) / gw);
}

uint group_count(uint bw_1, uint bh, uint gw_1, uint gh) {
    uint _e4 = groups_across(bw_1, gw_1);
    uint _e5 = groups_across(bh, gh);
    return (_e4 * _e5);
}

uint group_first(uint g, uint bw_2, uint bh_1, uint gw_2, uint gh_1) {
    uint _e5 = groups_across(bw_2, gw_2);
    uint gx = (g % _e5);
    uint gy = (g / _e5);
    uint h_1 = min(gh_1, (bh_1 - (gh_1 * gy)));
    return (((gy * gh_1) * bw_2) + ((gx * gw_2) * h_1));
}

uint group_clusters(uint g_1, uint bw_3, uint bh_2, uint gw_3, uint gh_2) {
    uint _e5 = groups_across(bw_3, gw_3);
    uint gx_1 = (g_1 % _e5);
    uint gy_1 = (g_1 / _e5);
    return (min(gw_3, (bw_3 - (gw_3 * gx_1))) * min(gh_2, (bh_2 - (gh_2 * gy_1))));
}

bool box_overlaps_box(vec3 lo1_, vec3 hi1_, vec3 lo2_, vec3 hi2_) {
    bool local_1 = false;
    bool local_2 = false;
    bool local_3 = false;
    bool local_4 = false;
    bool local_5 = false;
    if ((lo1_.x <= hi2_.x)) {
        local_1 = (lo2_.x <= hi1_.x);
    } else {
        local_1 = false;
    }
    bool _e13 = local_1;
    if (_e13) {
        local_2 = (lo1_.y <= hi2_.y);
    } else {
        local_2 = false;
    }
    bool _e20 = local_2;
    if (_e20) {
        local_3 = (lo2_.y <= hi1_.y);
    } else {
        local_3 = false;
    }
    bool _e27 = local_3;
    if (_e27) {
        local_4 = (lo1_.z <= hi2_.z);
    } else {
        local_4 = false;
    }
    bool _e34 = local_4;
    if (_e34) {
        local_5 = (lo2_.z <= hi1_.z);
    } else {
        local_5 = false;
    }
    bool _e41 = local_5;
    return _e41;
}

float vpl_transfer(vec3 n_l, vec3 n_x, vec3 v, float min_d2_) {
    float m_1 = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m_1 * m_1));
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
    bool local_6 = false;
    if (!((n_l_1 <= 0.0))) {
        local_6 = (n_v <= 0.0);
    } else {
        local_6 = true;
    }
    bool _e11 = local_6;
    if (_e11) {
        return 0.0;
    }
    float _e13 = smith_root(n_v, alpha_2);
    float _e15 = smith_root(n_l_1, alpha_2);
    return (0.5 / ((n_l_1 * _e13) + (n_v * _e15)));
}

vec3 fresnel_schlick(vec3 f0_, float f90_, float v_h) {
    float c_2 = clamp((1.0 - v_h), 0.0, 1.0);
    float c2_ = (c_2 * c_2);
    return (f0_ + ((vec3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_2)));
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
    vec3 h_2 = (v_1 + l);
    float len2_ = dot(h_2, h_2);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return clamp((dot(v_1, h_2) / sqrt(len2_)), 0.0, 1.0);
}

vec3 specular_brdf(vec3 base_2, float metallic_2, vec3 f0_d_2, float f90_d_2, float alpha_3, vec3 n, vec3 v_2, vec3 l_1) {
    bool local_7 = false;
    float n_l_2 = dot(n, l_1);
    float n_v_1 = dot(n, v_2);
    if (!((n_l_2 <= 0.0))) {
        local_7 = (n_v_1 <= 0.0);
    } else {
        local_7 = true;
    }
    bool _e18 = local_7;
    if (_e18) {
        return vec3(0.0, 0.0, 0.0);
    }
    vec3 hs = (v_2 + l_1);
    float inv = (1.0 / sqrt(dot(hs, hs)));
    vec3 h_3 = (hs * inv);
    vec3 c_3 = cross(n, h_3);
    float _e32 = ggx_d(dot(n, h_3), dot(c_3, c_3), alpha_3);
    vec3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_2, h_3));
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
    bool local_8 = false;
    bool local_9 = false;
    if (!((metallic_6 > 0.0))) {
        local_8 = (f90_d_5 > 0.0);
    } else {
        local_8 = true;
    }
    bool _e11 = local_8;
    if (!(_e11)) {
        local_9 = (max(max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0.0);
    } else {
        local_9 = true;
    }
    bool _e23 = local_9;
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

bool box_is_empty(WorkgroupBox b) {
    return (b.lo.x > b.hi.x);
}

vec4 surface_at(ivec2 texel) {
    vec4 p_5 = texelFetch(_group_0_binding_2_cs, texel, 0);
    return ((p_5.w > 0.0) ? vec4(p_5.xyz, 1.0) : vec4(0.0));
}

GbTexel gbuffer_at(uint i) {
    bool local_10 = false;
    uint _e3 = _group_0_binding_1_cs.width;
    uint _e8 = _group_0_binding_1_cs.width;
    ivec2 texel_1 = ivec2(int((i % _e3)), int((i / _e8)));
    vec4 _e12 = surface_at(texel_1);
    vec4 _e15 = texelFetch(_group_0_binding_3_cs, texel_1, 0);
    vec3 n_4 = _e15.xyz;
    float len2_1 = dot(n_4, n_4);
    if ((_e12.w > 0.0)) {
        local_10 = (len2_1 > 0.0);
    } else {
        local_10 = false;
    }
    bool valid_1 = local_10;
    vec3 _e30 = _group_0_binding_1_cs.eye;
    vec3 v_7 = (_e12.xyz - _e30);
    vec4 position = vec4(_e12.xyz, (valid_1 ? 1.0 : 0.0));
    vec4 normal = (valid_1 ? vec4((n_4 / vec3(sqrt(len2_1))), sqrt(dot(v_7, v_7))) : vec4(0.0, 0.0, 0.0, 1e30));
    return GbTexel(position, normal);
}

Glossy glossy_at(uint i_1, vec3 x) {
    uint _e4 = _group_0_binding_1_cs.width;
    uint _e9 = _group_0_binding_1_cs.width;
    ivec2 texel_2 = ivec2(int((i_1 % _e4)), int((i_1 / _e9)));
    vec4 _e16 = texelFetch(_group_0_binding_3_cs, texel_2, 0);
    GpuMaterial m_2 = _group_0_binding_10_cs[uint(_e16.w)];
    vec3 _e23 = _group_0_binding_1_cs.eye;
    bool _e29 = has_specular(m_2.metallic, m_2.f0_, m_2.f90_);
    return Glossy(m_2, normalize((_e23 - x)), _e29);
}

vec3 glossy_term(Glossy g_2, GpuLight l_4, vec3 n_3, vec3 v_5, float t) {
    bool local_11 = false;
    if (!(!(g_2.on))) {
        local_11 = (t <= 0.0);
    } else {
        local_11 = true;
    }
    bool _e13 = local_11;
    if (_e13) {
        return vec3(0.0);
    }
    vec3 _e30 = specular_correction(g_2.m.albedo, g_2.m.metallic, g_2.m.f0_, g_2.m.f90_, g_2.m.alpha, n_3, g_2.v, normalize(-(v_5)));
    return ((l_4.intensity * _e30) * t);
}

float near_r2_of(uint slot) {
    float _e3 = _group_0_binding_8_cs[slot];
    float _e5 = vpl_near_range2_(_e3, P);
    return _e5;
}

float near_cull_r2_of(uint slot_1, float near_r2_3) {
    float _e2 = near_r2_of(slot_1);
    float _e3 = vpl_near_cull_range2_(_e2, near_r2_3);
    return _e3;
}

WorkgroupBox load_receiver(uint li_3, uint pix, bool inside) {
    vec4 p_2 = vec4(0.0);
    bool local_12 = false;
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
        local_12 = (_e23 > 0.0);
    } else {
        local_12 = false;
    }
    bool _e27 = local_12;
    valid = _e27;
    bool _e29 = valid;
    if (_e29) {
        vec3 _e32 = pos;
        Glossy _e33 = glossy_at(pix, _e32);
        g_4 = _e33;
    }
    vec3 _e35 = pos;
    bool _e37 = valid;
    WorkgroupBox _e38 = workgroup_box(li_3, _e35, _e37);
    return _e38;
}

uint cluster_slot(uint c_1, uint k) {
    uint _e5 = _group_0_binding_0_cs.near_clusters_at;
    uint _e11 = _group_0_binding_5_cs[(((c_1 - _e5) * CLUSTER) + k)];
    return _e11;
}

float cull_r2_of(uint slot_2) {
    float _e3 = _group_0_binding_0_cs.near_r2_;
    float _e4 = near_cull_r2_of(slot_2, _e3);
    return _e4;
}

void quarter_boxes(uint li_4, uvec3 lid_1) {
    vec3 lo_1 = vec3(3.4028235e38);
    vec3 hi_1 = vec3(-3.4028235e38);
    uint y = 0u;
    uint x_1 = 0u;
    quarter = (((lid_1.x >= HALF) ? 1u : 0u) + ((lid_1.y >= HALF) ? 2u : 0u));
    vec3 _e17 = pos;
    bool _e19 = valid;
    WorkgroupBox _e20 = point_box(_e17, _e19);
    wg_lo[li_4] = _e20.lo;
    wg_hi[li_4] = _e20.hi;
    memoryBarrierShared();
    barrier();
    if ((li_4 < 4u)) {
        uint x0_ = ((li_4 % 2u) * HALF);
        uint y0_ = ((li_4 / 2u) * HALF);
        y = y0_;
        bool loop_init_1 = true;
        while(true) {
            if (!loop_init_1) {
                uint _e81 = y;
                y = (_e81 + 1u);
            }
            loop_init_1 = false;
            uint _e44 = y;
            if ((_e44 < min((y0_ + HALF), TILE))) {
            } else {
                break;
            }
            {
                x_1 = x0_;
                bool loop_init_2 = true;
                while(true) {
                    if (!loop_init_2) {
                        uint _e78 = x_1;
                        x_1 = (_e78 + 1u);
                    }
                    loop_init_2 = false;
                    uint _e51 = x_1;
                    if ((_e51 < min((x0_ + HALF), TILE))) {
                    } else {
                        break;
                    }
                    {
                        vec3 _e57 = lo_1;
                        uint _e59 = y;
                        uint _e62 = x_1;
                        vec3 _e65 = wg_lo[((_e59 * TILE) + _e62)];
                        lo_1 = min(_e57, _e65);
                        vec3 _e67 = hi_1;
                        uint _e69 = y;
                        uint _e72 = x_1;
                        vec3 _e75 = wg_hi[((_e69 * TILE) + _e72)];
                        hi_1 = max(_e67, _e75);
                    }
                }
            }
        }
        vec3 _e85 = lo_1;
        quarter_lo[li_4] = _e85;
        vec3 _e88 = hi_1;
        quarter_hi[li_4] = _e88;
    }
    memoryBarrierShared();
    barrier();
    return;
}

void list_clear(uint li_5) {
    if ((li_5 < 4u)) {
        atomicExchange(quarter_count[li_5], 0u);
    }
    if ((li_5 == 0u)) {
        atomicExchange(fullest, 0u);
        return;
    } else {
        return;
    }
}

bool list_full() {
    memoryBarrierShared();
    barrier();
    uint _e1 = fullest;
    memoryBarrierShared();
    barrier();
    return ((_e1 + CLUSTER) > QUARTER_LIGHTS);
}

uint quarter_add(uint q, uint slot_3, vec3 p_3, float radius) {
    vec3 lo_3 = quarter_lo[q];
    vec3 hi_3 = quarter_hi[q];
    if ((lo_3.x > hi_3.x)) {
        return 0u;
    }
    bool _e14 = sphere_overlaps_aabb(p_3, radius, lo_3, hi_3);
    if (!(_e14)) {
        return 0u;
    }
    uint _e20 = atomicAdd(quarter_count[q], 1u);
    quarter_lights[((q * QUARTER_LIGHTS) + _e20)] = slot_3;
    return (_e20 + 1u);
}

void list_add(uint slot_4, vec3 p_4, float radius_1) {
    uint _e4 = quarter_add(0u, slot_4, p_4, radius_1);
    uint _e6 = quarter_add(1u, slot_4, p_4, radius_1);
    uint a = max(_e4, _e6);
    uint _e9 = quarter_add(2u, slot_4, p_4, radius_1);
    uint _e11 = quarter_add(3u, slot_4, p_4, radius_1);
    uint b_1 = max(_e9, _e11);
    uint _e15 = atomicMax(fullest, max(a, b_1));
    return;
}

void shade_list(uint count, uint first) {
    uint m = 0u;
    bool _e3 = valid;
    if (!(_e3)) {
        return;
    }
    float _e6 = interleave_flux_scale(P);
    float unscale = (1.0 / _e6);
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            uint _e65 = m;
            m = (_e65 + 1u);
        }
        loop_init_3 = false;
        uint _e11 = m;
        if ((_e11 < count)) {
        } else {
            break;
        }
        {
            uint _e14 = m;
            uint slot_5 = quarter_lights[(first + _e14)];
            GpuLight l_5 = _group_0_binding_4_cs[slot_5];
            vec3 _e22 = pos;
            vec3 v_8 = (_e22 - l_5.p0_);
            float _e27 = _group_0_binding_7_cs[slot_5];
            float _e29 = vpl_near_range2_(_e27, P);
            float _e30 = near_r2_of(slot_5);
            float _e34 = _group_0_binding_0_cs.near_r2_;
            float _e35 = vpl_near_slc_share(_e29, _e30, dot(v_8, v_8), _e34);
            if ((_e35 > 0.0)) {
                vec3 _e40 = nrm;
                float _e43 = _group_0_binding_0_cs.min_d2_;
                float _e44 = vpl_transfer(l_5.p1_, _e40, v_8, _e43);
                float t_3 = ((_e44 * _e35) * unscale);
                vec3 _e48 = e;
                e = (_e48 + (l_5.intensity * t_3));
                vec3 _e53 = s;
                Glossy _e55 = g_4;
                vec3 _e57 = nrm;
                vec3 _e58 = glossy_term(_e55, l_5, _e57, v_8, t_3);
                s = (_e53 + _e58);
                uint _e61 = kept;
                kept = (_e61 + 1u);
            }
        }
    }
    return;
}

void list_shade() {
    memoryBarrierShared();
    barrier();
    uint _e2 = quarter;
    uint _e4 = atomicOr(quarter_count[_e2], 0u);
    uint _e6 = quarter;
    shade_list(_e4, (_e6 * QUARTER_LIGHTS));
    return;
}

void cull_tile(uint li_6, vec3 lo_2, vec3 hi_2, uvec4 grid, uint clusters_at, uint groups_at) {
    uint g_3 = 0u;
    uint h = 0u;
    list_clear(li_6);
    uint _e10 = group_count(grid.x, grid.y, grid.z, grid.w);
    bool loop_init_4 = true;
    while(true) {
        if (!loop_init_4) {
            uint _e84 = g_3;
            g_3 = (_e84 + 1u);
        }
        loop_init_4 = false;
        uint _e13 = g_3;
        if ((_e13 < _e10)) {
        } else {
            break;
        }
        {
            uint _e16 = g_3;
            GpuBox gb = _group_0_binding_6_cs[(groups_at + _e16)];
            bool _e22 = box_overlaps_box(gb.lo, gb.hi, lo_2, hi_2);
            if (!(_e22)) {
                continue;
            }
            uint _e24 = g_3;
            uint _e29 = group_first(_e24, grid.x, grid.y, grid.z, grid.w);
            uint first_1 = (clusters_at + _e29);
            uint _e31 = g_3;
            uint _e36 = group_clusters(_e31, grid.x, grid.y, grid.z, grid.w);
            if ((li_6 == 0u)) {
                atomicExchange(hit_count, 0u);
            }
            memoryBarrierShared();
            barrier();
            if ((li_6 < _e36)) {
                GpuBox cb = _group_0_binding_6_cs[(first_1 + li_6)];
                bool _e48 = box_overlaps_box(cb.lo, cb.hi, lo_2, hi_2);
                if (_e48) {
                    uint _e52 = atomicAdd(hit_count, 1u);
                    cluster_hits[_e52] = (first_1 + li_6);
                }
            }
            memoryBarrierShared();
            barrier();
            uint _e56 = hit_count;
            memoryBarrierShared();
            barrier();
            h = 0u;
            bool loop_init_5 = true;
            while(true) {
                if (!loop_init_5) {
                    uint _e81 = h;
                    h = (_e81 + 1u);
                }
                loop_init_5 = false;
                uint _e59 = h;
                if ((_e59 < _e56)) {
                } else {
                    break;
                }
                {
                    bool _e61 = list_full();
                    if (_e61) {
                        list_shade();
                        memoryBarrierShared();
                        barrier();
                        list_clear(li_6);
                        memoryBarrierShared();
                        barrier();
                    }
                    uint _e63 = h;
                    uint _e65 = cluster_hits[_e63];
                    uint _e66 = cluster_slot(_e65, li_6);
                    GpuLight l_6 = _group_0_binding_4_cs[_e66];
                    if (any(notEqual(l_6.intensity, vec3(0.0)))) {
                        float _e75 = cull_r2_of(_e66);
                        float _e76 = cull_radius(_e75);
                        bool _e78 = sphere_overlaps_aabb(l_6.p0_, _e76, lo_2, hi_2);
                        if (_e78) {
                            list_add(_e66, l_6.p0_, _e76);
                        }
                    }
                }
            }
            memoryBarrierShared();
            barrier();
        }
    }
    list_shade();
    return;
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_lo = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_hi = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_box = WorkgroupBox(vec3(0.0), vec3(0.0));
        quarter_lo = vec3[4](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        quarter_hi = vec3[4](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        quarter_lights = uint[1024](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
        quarter_count = uint[4](0u, 0u, 0u, 0u);
        fullest = 0u;
        cluster_hits = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
        hit_count = 0u;
    }
    memoryBarrierShared();
    barrier();
    uvec3 wg = gl_WorkGroupID;
    uvec3 lid = gl_LocalInvocationID;
    uint li = gl_LocalInvocationIndex;
    bool local = false;
    uint px = ((wg.x * TILE) + lid.x);
    uint py = ((wg.y * TILE) + lid.y);
    uint _e15 = _group_0_binding_0_cs.width;
    if ((px < _e15)) {
        uint _e21 = _group_0_binding_0_cs.height;
        local = (py < _e21);
    } else {
        local = false;
    }
    bool inside_1 = local;
    uint _e27 = _group_0_binding_0_cs.width;
    uint pix_1 = ((py * _e27) + px);
    WorkgroupBox _e30 = load_receiver(li, pix_1, inside_1);
    bool _e31 = box_is_empty(_e30);
    if (!(_e31)) {
        quarter_boxes(li, lid);
        uvec4 _e37 = _group_0_binding_0_cs.near_grid;
        uint _e40 = _group_0_binding_0_cs.near_clusters_at;
        uint _e43 = _group_0_binding_0_cs.near_groups_at;
        cull_tile(li, _e30.lo, _e30.hi, _e37, _e40, _e43);
    }
    bool _e45 = valid;
    if (_e45) {
        vec4 old = _group_0_binding_9_cs[pix_1];
        vec3 _e53 = e;
        uint _e57 = kept;
        _group_0_binding_9_cs[pix_1] = vec4((old.xyz + _e53), (old.w + float(_e57)));
        vec4 _e65 = _group_0_binding_11_cs[pix_1];
        vec3 _e68 = s;
        _group_0_binding_11_cs[pix_1] = vec4((_e65.xyz + _e68), 0.0);
        return;
    } else {
        return;
    }
}

