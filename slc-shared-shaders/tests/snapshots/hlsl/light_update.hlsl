struct FrameParams {
    uint light_count;
    uint seed;
    uint frame;
    uint pad;
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

cbuffer params : register(b0) { FrameParams params; }
ByteAddressBuffer ids : register(t1);
ByteAddressBuffer rt2_1 : register(t2);
RWByteAddressBuffer r2_ : register(u3);

float to_f32_(uint u)
{
    return float(u);
}

uint mul_lo_u32_(uint a, uint b)
{
    return (a * b);
}

uint add_wrap_u32_(uint a_1, uint b_1)
{
    return (a_1 + b_1);
}

float xi_from_bits(uint bits)
{
    const float _e3 = to_f32_((bits >> 8u));
    return (_e3 * XI_STEP);
}

uint pcg_hash(uint x)
{
    const uint _e2 = mul_lo_u32_(x, 747796405u);
    const uint _e4 = add_wrap_u32_(_e2, 2891336453u);
    const uint _e12 = mul_lo_u32_(((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4), 277803737u);
    return ((_e12 >> 22u) ^ _e12);
}

uint reverse_bits(uint x_1)
{
    uint v = (uint)0;

    v = (((x_1 >> 16u) & 65535u) | ((x_1 & 65535u) << 16u));
    uint _e11 = v;
    uint _e16 = v;
    v = (((_e11 >> 8u) & 16711935u) | ((_e16 & 16711935u) << 8u));
    uint _e22 = v;
    uint _e27 = v;
    v = (((_e22 >> 4u) & 252645135u) | ((_e27 & 252645135u) << 4u));
    uint _e33 = v;
    uint _e38 = v;
    v = (((_e33 >> 2u) & 858993459u) | ((_e38 & 858993459u) << 2u));
    uint _e44 = v;
    uint _e49 = v;
    v = (((_e44 >> 1u) & 1431655765u) | ((_e49 & 1431655765u) << 1u));
    uint _e55 = v;
    return _e55;
}

float xi_for(uint seed, uint frame, uint light)
{
    const uint _e3 = pcg_hash(seed);
    const uint _e4 = pcg_hash(_e3);
    const uint _e6 = pcg_hash((_e4 ^ light));
    const uint _e7 = reverse_bits(frame);
    const uint _e8 = add_wrap_u32_(_e6, _e7);
    const float _e9 = xi_from_bits(_e8);
    return _e9;
}

float random_range2_(float rt2_, float xi)
{
    return (rt2_ / (1.0 - xi));
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    uint i = gid.x;
    uint _e4 = params.light_count;
    if ((i >= _e4)) {
        return;
    }
    float _e10 = asfloat(rt2_1.Load(i*4));
    uint _e13 = params.seed;
    uint _e16 = params.frame;
    uint _e19 = asuint(ids.Load(i*4));
    const float _e20 = xi_for(_e13, _e16, _e19);
    const float _e21 = random_range2_(_e10, _e20);
    r2_.Store(i*4, asuint(_e21));
    return;
}
