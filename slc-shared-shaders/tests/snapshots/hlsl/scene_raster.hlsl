struct GpuLight {
    float3 p0_;
    uint kind;
    float3 p1_;
    float a;
    float3 p2_;
    float b;
    float3 intensity;
    uint ies_base;
};

struct GpuMaterial {
    float3 albedo;
    float metallic;
    float3 emission;
    float alpha;
    float3 f0_;
    float f90_;
};

struct MapParams {
    float4 c0_;
    float4 c1_;
    float4 c2_;
    float4 c3_;
    GpuLight light;
    float3 origin;
    uint mode;
    float3 axis;
    uint size;
    float3 right;
    float extent;
    float3 up;
    float texel;
};

struct VsOut {
    float4 clip_ : SV_Position;
    float3 world : LOC0;
    float3 normal : LOC1;
    nointerpolation float3 geo : LOC2;
    nointerpolation uint material : LOC3;
};

struct GbufferOut {
    float4 position : SV_Target0;
    float4 normal : SV_Target1;
};

struct RsmOut {
    float4 position : SV_Target0;
    float4 normal : SV_Target1;
    float4 flux : SV_Target2;
};

static const uint LIGHT_POINT = 0u;
static const uint LIGHT_SPOT = 1u;
static const uint LIGHT_IES = 2u;
static const uint LIGHT_TRIANGLE = 3u;
static const uint LIGHT_VPL = 4u;
static const uint NO_LIGHT = 4294967295u;
static const uint GRID_HEADER = 32u;
static const uint GRID_LEVELS_MAX = 8u;
static const uint GRIDS_MAX = 3u;
static const uint GRID_SORT_MOVES = 1024u;
static const uint GRID_SORT_MAX = 1024u;
static const uint COUNT_TILES = 0u;
static const uint COUNT_GROUP_TESTS = 1u;
static const uint COUNT_CLUSTER_TESTS = 2u;
static const uint COUNT_SPHERE_TESTS = 3u;
static const uint COUNT_TESTED = 4u;
static const uint COUNT_KEPT = 5u;
static const uint COUNT_PIXELS = 6u;
static const uint COUNT_FIELDS = 7u;
static const uint DIRECT_COUNT_PIXELS = 0u;
static const uint DIRECT_COUNT_CANDIDATES = 1u;
static const uint DIRECT_COUNT_EVALUATIONS = 2u;
static const uint DIRECT_COUNT_RAYS = 3u;
static const uint DIRECT_COUNT_NODES = 4u;
static const uint DIRECT_COUNT_FIELDS = 5u;
static const uint MAP_CAMERA = 0u;
static const uint MAP_PERSPECTIVE = 1u;
static const uint MAP_ORTHOGRAPHIC = 2u;
static const float XI_STEP = 5.9604645e-8;
static const uint XI_ROTATED = 2147483648u;
static const uint XI_BITS_SHIFT = 26u;
static const uint XI_INDEX_MASK = 67108863u;
static const uint PICK_STREAM = 2654435769u;
static const float TWO_PI = 6.2831855;
static const float UNRANGED = 1e38;
static const float CULL_RADIUS_SCALE = 1.000001;
static const float SPHERE_PAD = 4.7683716e-7;
static const float SPHERE_HUGE = 3.4028235e38;
static const float SPHERE_PAD_ABS = 1e-18;
static const uint CLUSTER = 64u;
static const uint GROUP_SIDE = 8u;
static const float INV_PI = 0.31830987;
static const float MIN_D2_ = 1e-12;
static const float MAX_INTENSITY = 7.2057594e16;
static const uint BSH_NONE = 4294967295u;
static const uint BSH_TAIL = 2147483648u;
static const uint BSH_TAIL_BINS = 1024u;
static const uint BSH_TAIL_MAX = 64u;
static const uint RESERVOIR_FULL = 4294967295u;
static const float REUSE_TRUST_SCALE = 64.0;
static const float GGX_ALPHA_MIN = 0.001;
static const float RANGE_SCALE_MAX = 64.0;
static const uint LIGHT_BVH_LEAF = 4294967295u;
static const float ONE_MINUS_EPSILON = 0.99999994;
static const float F32_MAX = 3.4028235e38;
static const float DEPTH_NONE = 1e30;
static const float DEPTH_SIGMA = 0.05;
static const float COVER_WEIGHT = 0.1;
static const uint ROULETTE_DEPTH = 2u;
static const float TEMPORAL_MAX_HISTORY = 32.0;
static const float TEMPORAL_DEPTH_TOLERANCE = 0.01;
static const float TEMPORAL_MOTION_DEPTH_TOLERANCE = 0.05;
static const float TEMPORAL_NORMAL_COS = 0.9;
static const float TEMPORAL_MIN_MOMENTS = 8.0;
static const float TEMPORAL_CHANGED_HISTORY = 1.0;
static const float TEMPORAL_CHANGE_LOW = 4.0;
static const float TEMPORAL_CHANGE_HIGH = 8.0;
static const float TEMPORAL_MIN_WEIGHT = 0.01;

cbuffer params : register(b0) { MapParams params; }
ByteAddressBuffer materials : register(t1);

struct VertexOutput_vs_main {
    float3 world : LOC0;
    float3 normal_1 : LOC1;
    nointerpolation float3 geo_1 : LOC2;
    nointerpolation uint material_1 : LOC3;
    float4 clip_ : SV_Position;
};

struct FragmentInput_fs_gbuffer {
    float3 world_1 : LOC0;
    float3 normal_2 : LOC1;
    nointerpolation float3 geo_2 : LOC2;
    nointerpolation uint material_2 : LOC3;
    float4 clip_1 : SV_Position;
};

struct FragmentInput_fs_rsm {
    float3 world_2 : LOC0;
    float3 normal_3 : LOC1;
    nointerpolation float3 geo_3 : LOC2;
    nointerpolation uint material_3 : LOC3;
    float4 clip_2 : SV_Position;
};

struct FragmentInput_fs_shadow {
    float3 world_3 : LOC0;
    float3 normal_4 : LOC1;
    nointerpolation float3 geo_4 : LOC2;
    nointerpolation uint material_4 : LOC3;
    float4 clip_3 : SV_Position;
};

float spot_falloff(float cos_theta, float cos_outer, float cos_inner, float shape)
{
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return ((shape > 0.5) ? (t * t) : ((t * t) * (3.0 - (2.0 * t))));
}

float3 face_against(float3 n, float3 dir_1)
{
    return ((dot(n, dir_1) > 0.0) ? -(n) : n);
}

float3 shading_normal(float3 n0_, float3 n1_, float3 n2_, float3 w, float3 facing)
{
    bool local = (bool)0;

    float3 s = (((n0_ * w.x) + (n1_ * w.y)) + (n2_ * w.z));
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
    float3 n_1 = (s / (sqrt(l2_)).xxx);
    return ((dot(n_1, facing) < 0.0) ? -(n_1) : n_1);
}

float light_map_depth(float3 rel, float3 axis, bool perspective)
{
    return (perspective ? sqrt(dot(rel, rel)) : dot(rel, axis));
}

float rsm_texel_solid_angle(float texel_area, float cos_axis)
{
    return (((texel_area * cos_axis) * cos_axis) * cos_axis);
}

float3 light_intensity(GpuLight l, float3 w_1)
{
    switch(l.kind) {
        case 1u: {
            const float _e10 = spot_falloff(dot(l.p1_, w_1), l.a, l.b, l.p2_.x);
            return (l.intensity * _e10);
        }
        default: {
            return (0.0).xxx;
        }
    }
}

float3 seen_normal(VsOut v_3, float3 dir_2)
{
    const float3 _e12 = face_against(v_3.geo, dir_2);
    const float3 _e13 = shading_normal(v_3.normal, (0.0).xxx, (0.0).xxx, float3(1.0, 0.0, 0.0), _e12);
    return _e13;
}

VsOut ConstructVsOut(float4 arg0, float3 arg1, float3 arg2, float3 arg3, uint arg4) {
    VsOut ret = (VsOut)0;
    ret.clip_ = arg0;
    ret.world = arg1;
    ret.normal = arg2;
    ret.geo = arg3;
    ret.material = arg4;
    return ret;
}

VertexOutput_vs_main vs_main(float3 position : LOC0, uint material : LOC1, float3 normal : LOC2, float3 geo : LOC3)
{
    float4 _e6 = params.c0_;
    float4 _e9 = params.c1_;
    float4 _e12 = params.c2_;
    float4 _e15 = params.c3_;
    float4x4 m = float4x4(_e6, _e9, _e12, _e15);
    const VsOut vsout = ConstructVsOut(mul(float4(position, 1.0), m), position, normal, geo, material);
    const VertexOutput_vs_main vsout_1 = { vsout.world, vsout.normal, vsout.geo, vsout.material, vsout.clip_ };
    return vsout_1;
}

GbufferOut ConstructGbufferOut(float4 arg0, float4 arg1) {
    GbufferOut ret = (GbufferOut)0;
    ret.position = arg0;
    ret.normal = arg1;
    return ret;
}

GbufferOut fs_gbuffer(FragmentInput_fs_gbuffer fragmentinput_fs_gbuffer)
{
    VsOut v = { fragmentinput_fs_gbuffer.clip_1, fragmentinput_fs_gbuffer.world_1, fragmentinput_fs_gbuffer.normal_2, fragmentinput_fs_gbuffer.geo_2, fragmentinput_fs_gbuffer.material_2 };
    float3 _e4 = params.origin;
    const float3 _e6 = seen_normal(v, (v.world - _e4));
    const GbufferOut gbufferout = ConstructGbufferOut(float4(v.world, 1.0), float4(_e6, float(v.material)));
    return gbufferout;
}

RsmOut ConstructRsmOut(float4 arg0, float4 arg1, float4 arg2) {
    RsmOut ret = (RsmOut)0;
    ret.position = arg0;
    ret.normal = arg1;
    ret.flux = arg2;
    return ret;
}

RsmOut fs_rsm(FragmentInput_fs_rsm fragmentinput_fs_rsm)
{
    VsOut v_1 = { fragmentinput_fs_rsm.clip_2, fragmentinput_fs_rsm.world_2, fragmentinput_fs_rsm.normal_3, fragmentinput_fs_rsm.geo_3, fragmentinput_fs_rsm.material_3 };
    float3 dir = (float3)0;
    float3 incident = (float3)0;

    float3 _e3 = params.axis;
    dir = _e3;
    float3 _e8 = params.light.intensity;
    float _e11 = params.texel;
    incident = (_e8 * _e11);
    uint _e16 = params.mode;
    if ((_e16 == MAP_PERSPECTIVE)) {
        float3 _e22 = params.origin;
        dir = normalize((v_1.world - _e22));
        GpuLight _e27 = params.light;
        float3 _e28 = dir;
        const float3 _e29 = light_intensity(_e27, _e28);
        float _e32 = params.texel;
        float3 _e33 = dir;
        float3 _e36 = params.axis;
        const float _e38 = rsm_texel_solid_angle(_e32, dot(_e33, _e36));
        incident = (_e29 * _e38);
    }
    float3 albedo = asfloat(materials.Load3(0+v_1.material*48));
    float3 _e48 = dir;
    const float3 _e49 = seen_normal(v_1, _e48);
    float3 _e52 = incident;
    const RsmOut rsmout = ConstructRsmOut(float4(v_1.world, 1.0), float4(_e49, 0.0), float4((_e52 * albedo), 0.0));
    return rsmout;
}

float4 fs_shadow(FragmentInput_fs_shadow fragmentinput_fs_shadow) : SV_Target0
{
    VsOut v_2 = { fragmentinput_fs_shadow.clip_3, fragmentinput_fs_shadow.world_3, fragmentinput_fs_shadow.normal_4, fragmentinput_fs_shadow.geo_4, fragmentinput_fs_shadow.material_4 };
    float3 _e4 = params.origin;
    float3 _e8 = params.axis;
    uint _e11 = params.mode;
    const float _e14 = light_map_depth((v_2.world - _e4), _e8, (_e11 == MAP_PERSPECTIVE));
    return float4(_e14, 0.0, 0.0, 0.0);
}
