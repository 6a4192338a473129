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

cbuffer params : register(b0) { MapParams params; }
cbuffer image : register(b1) { ImageParams image; }
Texture2D<float4> position_tex : register(t2);
Texture2D<float4> normal_tex : register(t3);
Texture2D<float4> shadow_map : register(t4);
RWByteAddressBuffer direct : register(u5);

float to_f32_(uint u)
{
    return float(u);
}

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

uint to_u32_(float x)
{
    return naga_f2u32(x);
}

float inverse_square(float d2_)
{
    return (1.0 / max(d2_, MIN_D2_));
}

float spot_falloff(float cos_theta, float cos_outer, float cos_inner, float shape)
{
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return ((shape > 0.5) ? (t * t) : ((t * t) * (3.0 - (2.0 * t))));
}

uint light_map_texel(float a_1, uint size)
{
    const float _e6 = to_f32_(size);
    const float _e9 = to_f32_(size);
    const uint _e14 = to_u32_(clamp(floor((((a_1 + 1.0) * 0.5) * _e6)), 0.0, (_e9 - 1.0)));
    return _e14;
}

float light_map_coord_at(float3 rel, float3 dir, float3 axis, float extent, bool perspective)
{
    return (dot(rel, dir) / ((perspective ? dot(rel, axis) : 1.0) * extent));
}

float light_map_depth(float3 rel_1, float3 axis_1, bool perspective_1)
{
    return (perspective_1 ? sqrt(dot(rel_1, rel_1)) : dot(rel_1, axis_1));
}

float3 point_irradiance(float3 intensity, float3 n, float3 v)
{
    float d2_1 = dot(v, v);
    float cos_x = (dot(n, v) / sqrt(max(d2_1, MIN_D2_)));
    const float _e11 = inverse_square(d2_1);
    return (intensity * (max(cos_x, 0.0) * _e11));
}

float3 directional_irradiance(float3 e_1, float3 n_1, float3 to_light)
{
    return (e_1 * max(dot(n_1, to_light), 0.0));
}

float perspective_texel_width(float extent_1, float d, float z, float size_1)
{
    return ((((2.0 * extent_1) * d) * d) / (size_1 * z));
}

float ortho_texel_width(float extent_2, float size_2)
{
    return ((2.0 * extent_2) / size_2);
}

float shadow_bias(float texel, float cos_light_1)
{
    float c = clamp(cos_light_1, 0.02, 1.0);
    return (texel * (1.5 + (sqrt((1.0 - (c * c))) / c)));
}

bool shadow_lit(float d_1, float d_map, float bias)
{
    bool local_4 = (bool)0;

    if (!((d_map <= 0.0))) {
        local_4 = (d_1 <= (d_map + bias));
    } else {
        local_4 = true;
    }
    bool _e11 = local_4;
    return _e11;
}

float3 light_intensity(GpuLight l, float3 w)
{
    switch(l.kind) {
        case 1u: {
            const float _e10 = spot_falloff(dot(l.p1_, w), l.a, l.b, l.p2_.x);
            return (l.intensity * _e10);
        }
        default: {
            return (0.0).xxx;
        }
    }
}

[numthreads(8, 8, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;
    float3 e = (0.0).xxx;
    float a = 0.0;
    float b = 0.0;
    float width = 0.0;
    float cos_light = 0.0;
    bool local_2 = (bool)0;
    bool local_3 = (bool)0;

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
    int2 texel_1 = int2(int(gid.x), int(gid.y));
    float4 p = position_tex.Load(int3(texel_1, int(0)));
    float4 _e33 = normal_tex.Load(int3(texel_1, int(0)));
    float3 nn = _e33.xyz;
    if (!(!((p.w > 0.0)))) {
        local_1 = (dot(nn, nn) <= 0.0);
    } else {
        local_1 = true;
    }
    bool _e46 = local_1;
    if (_e46) {
        direct.Store4(i*16, asuint((0.0).xxxx));
        return;
    }
    float3 x_1 = p.xyz;
    float3 n_2 = normalize(nn);
    uint _e55 = params.size;
    float size_3 = float(_e55);
    float3 _e66 = params.origin;
    float3 rel_2 = (x_1 - _e66);
    float3 _e70 = params.axis;
    uint _e73 = params.mode;
    const float _e76 = light_map_depth(rel_2, _e70, (_e73 == MAP_PERSPECTIVE));
    uint _e83 = params.mode;
    if ((_e83 == MAP_PERSPECTIVE)) {
        float3 v_1 = -(rel_2);
        float3 _e89 = params.axis;
        float z_1 = dot(rel_2, _e89);
        if (!((z_1 <= 0.0))) {
            local_2 = (_e76 <= 0.0);
        } else {
            local_2 = true;
        }
        bool _e99 = local_2;
        if (_e99) {
            direct.Store4(i*16, asuint((0.0).xxxx));
            return;
        }
        float3 _e106 = params.right;
        float3 _e109 = params.axis;
        float _e112 = params.extent;
        const float _e114 = light_map_coord_at(rel_2, _e106, _e109, _e112, true);
        a = _e114;
        float3 _e117 = params.up;
        float3 _e120 = params.axis;
        float _e123 = params.extent;
        const float _e125 = light_map_coord_at(rel_2, _e117, _e120, _e123, true);
        b = _e125;
        float _e128 = params.extent;
        const float _e129 = perspective_texel_width(_e128, _e76, z_1, size_3);
        width = _e129;
        cos_light = (dot(n_2, v_1) / _e76);
        GpuLight _e134 = params.light;
        const float3 _e137 = light_intensity(_e134, (rel_2 / (_e76).xxx));
        const float3 _e138 = point_irradiance(_e137, n_2, v_1);
        e = _e138;
    } else {
        float3 _e141 = params.right;
        float3 _e144 = params.axis;
        float _e147 = params.extent;
        const float _e149 = light_map_coord_at(rel_2, _e141, _e144, _e147, false);
        a = _e149;
        float3 _e152 = params.up;
        float3 _e155 = params.axis;
        float _e158 = params.extent;
        const float _e160 = light_map_coord_at(rel_2, _e152, _e155, _e158, false);
        b = _e160;
        float _e163 = params.extent;
        const float _e164 = ortho_texel_width(_e163, size_3);
        width = _e164;
        float3 _e167 = params.axis;
        cos_light = -(dot(n_2, _e167));
        float3 _e173 = params.light.intensity;
        float3 _e176 = params.axis;
        const float3 _e178 = directional_irradiance(_e173, n_2, -(_e176));
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
        uint _e195 = params.size;
        const uint _e196 = light_map_texel(_e192, _e195);
        float _e198 = b;
        uint _e201 = params.size;
        const uint _e202 = light_map_texel(_e198, _e201);
        float4 _e206 = shadow_map.Load(int3(int2(int(_e196), int(_e202)), int(0)));
        float d_map_1 = _e206.x;
        float _e208 = width;
        float _e209 = cos_light;
        const float _e210 = shadow_bias(_e208, _e209);
        const bool _e211 = shadow_lit(_e76, d_map_1, _e210);
        if (!(_e211)) {
            e = (0.0).xxx;
        }
    }
    float3 _e217 = e;
    direct.Store4(i*16, asuint(float4(_e217, 0.0)));
    return;
}
