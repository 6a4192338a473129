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

struct ImageParams {
    float3 eye;
    uint width;
    uint height;
    uint pad0_;
    uint pad1_;
    uint pad2_;
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

cbuffer image : register(b0) { ImageParams image; }
Texture2D<float4> position_tex : register(t1);
Texture2D<float4> normal_tex : register(t2);
Texture2D<float4> indirect_tex : register(t3);
ByteAddressBuffer direct_1 : register(t4);
ByteAddressBuffer materials : register(t5);
RWTexture2D<float4> out_tex : register(u6);
Texture2D<float4> specular_tex : register(t7);
cbuffer params : register(b8) { MapParams params; }

float ggx_d(float cos_h, float sin2_h, float alpha)
{
    if ((cos_h <= 0.0)) {
        return 0.0;
    }
    float a2_ = (alpha * alpha);
    float t = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t * t));
}

float smith_root(float cos_, float alpha_1)
{
    float a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1.0 - a2_1)) + a2_1));
}

float smith_visibility(float n_l, float n_v, float alpha_2)
{
    bool local_1 = (bool)0;

    if (!((n_l <= 0.0))) {
        local_1 = (n_v <= 0.0);
    } else {
        local_1 = true;
    }
    bool _e11 = local_1;
    if (_e11) {
        return 0.0;
    }
    const float _e13 = smith_root(n_v, alpha_2);
    const float _e15 = smith_root(n_l, alpha_2);
    return (0.5 / ((n_l * _e13) + (n_v * _e15)));
}

float3 fresnel_schlick(float3 f0_, float f90_, float v_h)
{
    float c = saturate((1.0 - v_h));
    float c2_ = (c * c);
    return (f0_ + ((float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c)));
}

float3 specular_fresnel(float3 base, float metallic, float3 f0_d, float f90_d, float v_h_1)
{
    const float3 _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    const float3 _e10 = fresnel_schlick(base, 1.0, v_h_1);
    return ((_e5 * (1.0 - metallic)) + (_e10 * metallic));
}

float3 diffuse_brdf(float3 base_1, float metallic_1, float3 f0_d_1, float f90_d_1, float v_h_2)
{
    const float3 _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return ((((float3(1.0, 1.0, 1.0) - _e9) * base_1) * (1.0 - metallic_1)) * INV_PI);
}

float half_cosine(float3 v, float3 l)
{
    float3 h = (v + l);
    float len2_ = dot(h, h);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return saturate((dot(v, h) / sqrt(len2_)));
}

float3 specular_brdf(float3 base_2, float metallic_2, float3 f0_d_2, float f90_d_2, float alpha_3, float3 n, float3 v_1, float3 l_1)
{
    bool local_2 = (bool)0;

    float n_l_1 = dot(n, l_1);
    float n_v_1 = dot(n, v_1);
    if (!((n_l_1 <= 0.0))) {
        local_2 = (n_v_1 <= 0.0);
    } else {
        local_2 = true;
    }
    bool _e18 = local_2;
    if (_e18) {
        return float3(0.0, 0.0, 0.0);
    }
    float3 hs = (v_1 + l_1);
    float inv = (1.0 / sqrt(dot(hs, hs)));
    float3 h_1 = (hs * inv);
    float3 c_1 = cross(n, h_1);
    const float _e32 = ggx_d(dot(n, h_1), dot(c_1, c_1), alpha_3);
    const float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_1, h_1));
    const float _e35 = smith_visibility(n_l_1, n_v_1, alpha_3);
    return (_e34 * (_e32 * _e35));
}

float3 brdf_eval(float3 base_3, float metallic_3, float3 f0_d_3, float f90_d_3, float alpha_4, float3 n_1, float3 v_2, float3 l_2)
{
    if ((dot(n_1, l_2) <= 0.0)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float _e15 = half_cosine(v_2, l_2);
    const float3 _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    const float3 _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_1, v_2, l_2);
    return (_e16 + _e17);
}

float3 diffuse_albedo(float3 base_4, float metallic_4)
{
    return (base_4 * (1.0 - metallic_4));
}

bool has_specular(float metallic_5, float3 f0_d_4, float f90_d_4)
{
    bool local_3 = (bool)0;
    bool local_4 = (bool)0;

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

float3 diffuse_radiance(float3 albedo, float3 emission, float3 e)
{
    return (emission + ((albedo * INV_PI) * e));
}

float3 primary_light_dir(float3 x, float3 origin, float3 axis, bool perspective)
{
    bool local_5 = (bool)0;

    float3 v_3 = (origin - x);
    float d2_ = dot(v_3, v_3);
    if (perspective) {
        local_5 = (d2_ > 0.0);
    } else {
        local_5 = false;
    }
    bool _e11 = local_5;
    if (_e11) {
        return (v_3 / (sqrt(d2_)).xxx);
    }
    return -(axis);
}

float3 glossy_radiance(float3 base_5, float3 emission_1, float metallic_6, float3 f_direct, float3 direct, float3 indirect, float3 specular)
{
    const float3 _e9 = diffuse_albedo(base_5, metallic_6);
    return (((emission_1 + (f_direct * direct)) + ((_e9 * INV_PI) * indirect)) + specular);
}

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

GpuMaterial ConstructGpuMaterial(float3 arg0, float arg1, float3 arg2, float arg3, float3 arg4, float arg5) {
    GpuMaterial ret = (GpuMaterial)0;
    ret.albedo = arg0;
    ret.metallic = arg1;
    ret.emission = arg2;
    ret.alpha = arg3;
    ret.f0_ = arg4;
    ret.f90_ = arg5;
    return ret;
}

[numthreads(8, 8, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    bool local = (bool)0;
    float3 radiance = (0.0).xxx;

    uint _e4 = image.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = image.height;
        local = (gid.y >= _e12);
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    uint _e19 = image.width;
    uint i = ((gid.y * _e19) + gid.x);
    int2 texel = int2(int(gid.x), int(gid.y));
    float4 p = position_tex.Load(int3(texel, int(0)));
    if ((p.w > 0.0)) {
        float4 nm = normal_tex.Load(int3(texel, int(0)));
        GpuMaterial m = ConstructGpuMaterial(asfloat(materials.Load3(naga_f2u32(nm.w)*48+0)), asfloat(materials.Load(naga_f2u32(nm.w)*48+12)), asfloat(materials.Load3(naga_f2u32(nm.w)*48+16)), asfloat(materials.Load(naga_f2u32(nm.w)*48+28)), asfloat(materials.Load3(naga_f2u32(nm.w)*48+32)), asfloat(materials.Load(naga_f2u32(nm.w)*48+44)));
        float4 _e47 = indirect_tex.Load(int3(texel, int(0)));
        float3 e_1 = _e47.xyz;
        const bool _e52 = has_specular(m.metallic, m.f0_, m.f90_);
        if (_e52) {
            float3 _e56 = params.origin;
            float3 _e59 = params.axis;
            uint _e62 = params.mode;
            const float3 _e65 = primary_light_dir(p.xyz, _e56, _e59, (_e62 == MAP_PERSPECTIVE));
            float3 _e75 = image.eye;
            const float3 _e79 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, normalize(nm.xyz), normalize((_e75 - p.xyz)), _e65);
            float4 _e85 = asfloat(direct_1.Load4(i*16));
            float4 _e89 = specular_tex.Load(int3(texel, int(0)));
            const float3 _e91 = glossy_radiance(m.albedo, m.emission, m.metallic, _e79, _e85.xyz, e_1, _e89.xyz);
            radiance = _e91;
        } else {
            float4 _e96 = asfloat(direct_1.Load4(i*16));
            const float3 _e99 = diffuse_radiance(m.albedo, m.emission, (_e96.xyz + e_1));
            radiance = _e99;
        }
    }
    float3 _e101 = radiance;
    out_tex[texel] = float4(_e101, 1.0);
    return;
}
