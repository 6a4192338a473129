struct ViewParams {
    float4 c0_;
    float4 c1_;
    float4 c2_;
    float4 c3_;
    float3 eye;
    uint width;
    uint height;
    float shadow_offset;
    uint seed;
    uint frame;
    float3 f0_d;
    float f90_d;
};

struct GbTexel {
    float4 position;
    float4 normal;
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

cbuffer view : register(b0) { ViewParams view; }
Texture2D<float4> position_tex : register(t1);
Texture2D<float4> normal_tex : register(t2);
ByteAddressBuffer irradiance : register(t3);
RWTexture2D<float4> out_tex : register(u4);

float4 surface_at(int2 texel)
{
    float4 p = position_tex.Load(int3(texel, int(0)));
    return ((p.w > 0.0) ? float4(p.xyz, 1.0) : (0.0).xxxx);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

GbTexel ConstructGbTexel(float4 arg0, float4 arg1) {
    GbTexel ret = (GbTexel)0;
    ret.position = arg0;
    ret.normal = arg1;
    return ret;
}

GbTexel gbuffer_at(uint i)
{
    bool local_1 = (bool)0;

    uint _e3 = view.width;
    uint _e8 = view.width;
    int2 texel_1 = int2(int(naga_mod(i, _e3)), int(naga_div(i, _e8)));
    const float4 _e12 = surface_at(texel_1);
    float4 _e15 = normal_tex.Load(int3(texel_1, int(0)));
    float3 n = _e15.xyz;
    float len2_ = dot(n, n);
    if ((_e12.w > 0.0)) {
        local_1 = (len2_ > 0.0);
    } else {
        local_1 = false;
    }
    bool valid = local_1;
    float3 _e30 = view.eye;
    float3 v = (_e12.xyz - _e30);
    float4 position = float4(_e12.xyz, (valid ? 1.0 : 0.0));
    float4 normal = (valid ? float4((n / (sqrt(len2_)).xxx), sqrt(dot(v, v))) : float4(0.0, 0.0, 0.0, 1e30));
    const GbTexel gbtexel = ConstructGbTexel(position, normal);
    return gbtexel;
}

[numthreads(8, 8, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    bool local = (bool)0;

    uint _e4 = view.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = view.height;
        local = (gid.y >= _e12);
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    uint _e19 = view.width;
    uint i_1 = ((gid.y * _e19) + gid.x);
    const GbTexel _e23 = gbuffer_at(i_1);
    bool valid_1 = (_e23.position.w > 0.0);
    float4 _e32 = asfloat(irradiance.Load4(i_1*16));
    float4 e = (valid_1 ? _e32 : (0.0).xxxx);
    out_tex[int2(int(gid.x), int(gid.y))] = e;
    return;
}
