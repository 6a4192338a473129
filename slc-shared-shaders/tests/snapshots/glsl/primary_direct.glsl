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

layout(std140) uniform MapParams_block_0Compute { MapParams _group_0_binding_0_cs; };

layout(std140) uniform ImageParams_block_1Compute { ImageParams _group_0_binding_1_cs; };

uniform sampler2D _group_0_binding_2_cs;

uniform sampler2D _group_0_binding_3_cs;

uniform sampler2D _group_0_binding_4_cs;

layout(std430) buffer type_6_block_2Compute { vec4 _group_0_binding_5_cs[]; };


float to_f32_(uint u) {
    return float(u);
}

uint to_u32_(float x) {
    return uint(x);
}

float inverse_square(float d2_) {
    return (1.0 / max(d2_, MIN_D2_));
}

float spot_falloff(float cos_theta, float cos_outer, float cos_inner, float shape) {
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t = clamp(((cos_theta - cos_outer) / (cos_inner - cos_outer)), 0.0, 1.0);
    return ((shape > 0.5) ? (t * t) : ((t * t) * (3.0 - (2.0 * t))));
}

uint light_map_texel(float a_1, uint size) {
    float _e6 = to_f32_(size);
    float _e9 = to_f32_(size);
    uint _e14 = to_u32_(clamp(floor((((a_1 + 1.0) * 0.5) * _e6)), 0.0, (_e9 - 1.0)));
    return _e14;
}

float light_map_coord_at(vec3 rel, vec3 dir, vec3 axis, float extent, bool perspective) {
    return (dot(rel, dir) / ((perspective ? dot(rel, axis) : 1.0) * extent));
}

float light_map_depth(vec3 rel_1, vec3 axis_1, bool perspective_1) {
    return (perspective_1 ? sqrt(dot(rel_1, rel_1)) : dot(rel_1, axis_1));
}

vec3 point_irradiance(vec3 intensity, vec3 n, vec3 v) {
    float d2_1 = dot(v, v);
    float cos_x = (dot(n, v) / sqrt(max(d2_1, MIN_D2_)));
    float _e11 = inverse_square(d2_1);
    return (intensity * (max(cos_x, 0.0) * _e11));
}

vec3 directional_irradiance(vec3 e_1, vec3 n_1, vec3 to_light) {
    return (e_1 * max(dot(n_1, to_light), 0.0));
}

float perspective_texel_width(float extent_1, float d, float z, float size_1) {
    return ((((2.0 * extent_1) * d) * d) / (size_1 * z));
}

float ortho_texel_width(float extent_2, float size_2) {
    return ((2.0 * extent_2) / size_2);
}

float shadow_bias(float texel, float cos_light_1) {
    float c = clamp(cos_light_1, 0.02, 1.0);
    return (texel * (1.5 + (sqrt((1.0 - (c * c))) / c)));
}

bool shadow_lit(float d_1, float d_map, float bias) {
    bool local_4 = false;
    if (!((d_map <= 0.0))) {
        local_4 = (d_1 <= (d_map + bias));
    } else {
        local_4 = true;
    }
    bool _e11 = local_4;
    return _e11;
}

vec3 light_intensity(GpuLight l, vec3 w) {
    switch(l.kind) {
        case 1u: {
            float _e10 = spot_falloff(dot(l.p1_, w), l.a, l.b, l.p2_.x);
            return (l.intensity * _e10);
        }
        default: {
            return vec3(0.0);
        }
    }
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    bool local = false;
    bool local_1 = false;
    vec3 e = vec3(0.0);
    float a = 0.0;
    float b = 0.0;
    float width = 0.0;
    float cos_light = 0.0;
    bool local_2 = false;
    bool local_3 = false;
    uint _e4 = _group_0_binding_1_cs.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = _group_0_binding_1_cs.height;
        local = (gid.y >= _e12);
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    uint _e19 = _group_0_binding_1_cs.width;
    uint i = ((gid.y * _e19) + gid.x);
    ivec2 texel_1 = ivec2(int(gid.x), int(gid.y));
    vec4 p = texelFetch(_group_0_binding_2_cs, texel_1, 0);
    vec4 _e33 = texelFetch(_group_0_binding_3_cs, texel_1, 0);
    vec3 nn = _e33.xyz;
    if (!(!((p.w > 0.0)))) {
        local_1 = (dot(nn, nn) <= 0.0);
    } else {
        local_1 = true;
    }
    bool _e46 = local_1;
    if (_e46) {
        _group_0_binding_5_cs[i] = vec4(0.0);
        return;
    }
    vec3 x_1 = p.xyz;
    vec3 n_2 = normalize(nn);
    uint _e55 = _group_0_binding_0_cs.size;
    float size_3 = float(_e55);
    vec3 _e66 = _group_0_binding_0_cs.origin;
    vec3 rel_2 = (x_1 - _e66);
    vec3 _e70 = _group_0_binding_0_cs.axis;
    uint _e73 = _group_0_binding_0_cs.mode;
    float _e76 = light_map_depth(rel_2, _e70, (_e73 == MAP_PERSPECTIVE));
    uint _e83 = _group_0_binding_0_cs.mode;
    if ((_e83 == MAP_PERSPECTIVE)) {
        vec3 v_1 = -(rel_2);
        vec3 _e89 = _group_0_binding_0_cs.axis;
        float z_1 = dot(rel_2, _e89);
        if (!((z_1 <= 0.0))) {
            local_2 = (_e76 <= 0.0);
        } else {
            local_2 = true;
        }
        bool _e99 = local_2;
        if (_e99) {
            _group_0_binding_5_cs[i] = vec4(0.0);
            return;
        }
        vec3 _e106 = _group_0_binding_0_cs.right;
        vec3 _e109 = _group_0_binding_0_cs.axis;
        float _e112 = _group_0_binding_0_cs.extent;
        float _e114 = light_map_coord_at(rel_2, _e106, _e109, _e112, true);
        a = _e114;
        vec3 _e117 = _group_0_binding_0_cs.up;
        vec3 _e120 = _group_0_binding_0_cs.axis;
        float _e123 = _group_0_binding_0_cs.extent;
        float _e125 = light_map_coord_at(rel_2, _e117, _e120, _e123, true);
        b = _e125;
        float _e128 = _group_0_binding_0_cs.extent;
        float _e129 = perspective_texel_width(_e128, _e76, z_1, size_3);
        width = _e129;
        cos_light = (dot(n_2, v_1) / _e76);
        GpuLight _e134 = _group_0_binding_0_cs.light;
        vec3 _e137 = light_intensity(_e134, (rel_2 / vec3(_e76)));
        vec3 _e138 = point_irradiance(_e137, n_2, v_1);
        e = _e138;
    } else {
        vec3 _e141 = _group_0_binding_0_cs.right;
        vec3 _e144 = _group_0_binding_0_cs.axis;
        float _e147 = _group_0_binding_0_cs.extent;
        float _e149 = light_map_coord_at(rel_2, _e141, _e144, _e147, false);
        a = _e149;
        vec3 _e152 = _group_0_binding_0_cs.up;
        vec3 _e155 = _group_0_binding_0_cs.axis;
        float _e158 = _group_0_binding_0_cs.extent;
        float _e160 = light_map_coord_at(rel_2, _e152, _e155, _e158, false);
        b = _e160;
        float _e163 = _group_0_binding_0_cs.extent;
        float _e164 = ortho_texel_width(_e163, size_3);
        width = _e164;
        vec3 _e167 = _group_0_binding_0_cs.axis;
        cos_light = -(dot(n_2, _e167));
        vec3 _e173 = _group_0_binding_0_cs.light.intensity;
        vec3 _e176 = _group_0_binding_0_cs.axis;
        vec3 _e178 = directional_irradiance(_e173, n_2, -(_e176));
        e = _e178;
    }
    float _e179 = a;
    if ((abs(_e179) <= 1.0)) {
        float _e185 = b;
        local_3 = (abs(_e185) <= 1.0);
    } else {
        local_3 = false;
    }
    bool _e190 = local_3;
    if (_e190) {
        float _e192 = a;
        uint _e195 = _group_0_binding_0_cs.size;
        uint _e196 = light_map_texel(_e192, _e195);
        float _e198 = b;
        uint _e201 = _group_0_binding_0_cs.size;
        uint _e202 = light_map_texel(_e198, _e201);
        vec4 _e206 = texelFetch(_group_0_binding_4_cs, ivec2(int(_e196), int(_e202)), 0);
        float d_map_1 = _e206.x;
        float _e208 = width;
        float _e209 = cos_light;
        float _e210 = shadow_bias(_e208, _e209);
        bool _e211 = shadow_lit(_e76, d_map_1, _e210);
        if (!(_e211)) {
            e = vec3(0.0);
        }
    }
    vec3 _e217 = e;
    _group_0_binding_5_cs[i] = vec4(_e217, 0.0);
    return;
}

