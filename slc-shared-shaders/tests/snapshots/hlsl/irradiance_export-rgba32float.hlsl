struct ViewParams {
    float4 c0_;
    float4 c1_;
    float4 c2_;
    float4 c3_;
    float3 eye;
    uint width;
    uint height;
    float background;
    uint seed;
    uint frame;
    float3 f0_d;
    float f90_d;
};

static const uint LIGHT_POINT = 0u;
static const uint LIGHT_SPOT = 1u;
static const uint LIGHT_IES = 2u;
static const uint LIGHT_TRIANGLE = 3u;
static const uint LIGHT_VPL = 4u;
static const uint NO_LIGHT = 4294967295u;
static const uint MAP_CAMERA = 0u;
static const uint MAP_PERSPECTIVE = 1u;
static const uint MAP_ORTHOGRAPHIC = 2u;
static const float XI_STEP = 5.9604645e-8;
static const uint PICK_STREAM = 2654435769u;
static const float TWO_PI = 6.2831855;
static const float CULL_RADIUS_SCALE = 1.000001;
static const float SPHERE_PAD = 4.7683716e-7;
static const float SPHERE_HUGE = 3.4028235e38;
static const float SPHERE_PAD_ABS = 1e-18;
static const float INV_PI = 0.31830987;
static const float MIN_D2_ = 1e-12;
static const uint BSH_NONE = 4294967295u;
static const uint RESERVOIR_FULL = 4294967295u;
static const float GGX_ALPHA_MIN = 0.001;
static const float RANGE_SCALE_MAX = 64.0;
static const uint LIGHT_BVH_LEAF = 4294967295u;
static const float ONE_MINUS_EPSILON = 0.99999994;
static const float F32_MAX = 3.4028235e38;
static const float DEPTH_NONE = 1e30;
static const float DEPTH_SIGMA = 0.05;
static const float COVER_WEIGHT = 0.1;
static const uint NEAR_BLOCK = 64u;
static const uint ROULETTE_DEPTH = 2u;

cbuffer view : register(b0) { ViewParams view; }
ByteAddressBuffer gb_position : register(t1);
ByteAddressBuffer irradiance : register(t2);
RWTexture2D<float4> out_tex : register(u3);

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
    uint i = ((gid.y * _e19) + gid.x);
    float4 _e27 = asfloat(irradiance.Load4(i*16));
    float _e31 = asfloat(gb_position.Load(12+i*16));
    float4 e = ((_e31 > 0.0) ? _e27 : (0.0).xxxx);
    out_tex[int2(int(gid.x), int(gid.y))] = e;
    return;
}
