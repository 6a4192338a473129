#version 430 core
#extension GL_ARB_shader_storage_buffer_object : require
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
struct VsOut {
    vec4 clip;
    vec3 world;
    vec3 normal;
    vec3 geo;
    uint material;
};
struct GbufferOut {
    vec4 position;
    vec4 normal;
};
struct RsmOut {
    vec4 position;
    vec4 normal;
    vec4 flux;
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

layout(std140) uniform MapParams_block_0Fragment { MapParams _group_0_binding_0_fs; };

layout(std430) readonly buffer type_5_block_1Fragment { GpuMaterial _group_0_binding_1_fs[]; };

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) flat in vec3 _vs2fs_location2;
layout(location = 3) flat in uint _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;
layout(location = 1) out vec4 _fs2p_location1;
layout(location = 2) out vec4 _fs2p_location2;

float spot_falloff(float cos_theta, float cos_outer, float cos_inner, float shape) {
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t = clamp(((cos_theta - cos_outer) / (cos_inner - cos_outer)), 0.0, 1.0);
    return ((shape > 0.5) ? (t * t) : ((t * t) * (3.0 - (2.0 * t))));
}

vec3 face_against(vec3 n, vec3 dir_1) {
    return ((dot(n, dir_1) > 0.0) ? -(n) : n);
}

vec3 shading_normal(vec3 n0_, vec3 n1_, vec3 n2_, vec3 w, vec3 facing) {
    bool local = false;
    vec3 s = (((n0_ * w.x) + (n1_ * w.y)) + (n2_ * w.z));
    float l2_ = dot(s, s);
    if (!(!((l2_ > 1e-12)))) {
        local = !((l2_ < 3e38));
    } else {
        local = true;
    }
    bool _e24 = local;
    if (_e24) {
        return facing;
    }
    vec3 n_1 = (s / vec3(sqrt(l2_)));
    return ((dot(n_1, facing) < 0.0) ? -(n_1) : n_1);
}

float light_map_depth(vec3 rel, vec3 axis, bool perspective) {
    return (perspective ? sqrt(dot(rel, rel)) : dot(rel, axis));
}

float rsm_texel_solid_angle(float texel_area, float cos_axis) {
    return (((texel_area * cos_axis) * cos_axis) * cos_axis);
}

vec3 light_intensity(GpuLight l, vec3 w_1) {
    switch(l.kind) {
        case 1u: {
            float _e10 = spot_falloff(dot(l.p1_, w_1), l.a, l.b, l.p2_.x);
            return (l.intensity * _e10);
        }
        default: {
            return vec3(0.0);
        }
    }
}

vec3 seen_normal(VsOut v_3, vec3 dir_2) {
    vec3 _e12 = face_against(v_3.geo, dir_2);
    vec3 _e13 = shading_normal(v_3.normal, vec3(0.0), vec3(0.0), vec3(1.0, 0.0, 0.0), _e12);
    return _e13;
}

void main() {
    VsOut v_1 = VsOut(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 dir = vec3(0.0);
    vec3 incident = vec3(0.0);
    vec3 _e3 = _group_0_binding_0_fs.axis;
    dir = _e3;
    vec3 _e8 = _group_0_binding_0_fs.light.intensity;
    float _e11 = _group_0_binding_0_fs.texel;
    incident = (_e8 * _e11);
    uint _e16 = _group_0_binding_0_fs.mode;
    if ((_e16 == MAP_PERSPECTIVE)) {
        vec3 _e22 = _group_0_binding_0_fs.origin;
        dir = normalize((v_1.world - _e22));
        GpuLight _e27 = _group_0_binding_0_fs.light;
        vec3 _e28 = dir;
        vec3 _e29 = light_intensity(_e27, _e28);
        float _e32 = _group_0_binding_0_fs.texel;
        vec3 _e33 = dir;
        vec3 _e36 = _group_0_binding_0_fs.axis;
        float _e38 = rsm_texel_solid_angle(_e32, dot(_e33, _e36));
        incident = (_e29 * _e38);
    }
    vec3 albedo = _group_0_binding_1_fs[v_1.material].albedo;
    vec3 _e48 = dir;
    vec3 _e49 = seen_normal(v_1, _e48);
    vec3 _e52 = incident;
    RsmOut _tmp_return = RsmOut(vec4(v_1.world, 1.0), vec4(_e49, 0.0), vec4((_e52 * albedo), 0.0));
    _fs2p_location0 = _tmp_return.position;
    _fs2p_location1 = _tmp_return.normal;
    _fs2p_location2 = _tmp_return.flux;
    return;
}

