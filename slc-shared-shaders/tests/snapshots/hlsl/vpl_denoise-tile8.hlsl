struct VplParams {
    uint width;
    uint height;
    uint lights_per_subset;
    float min_d2_;
    float near_r2_;
    uint near_blocks;
    uint pad0_;
    uint pad1_;
};

struct Window {
    float3 sum;
    float weight;
    uint covered;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
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
static const uint PERIOD = 8u;

cbuffer params : register(b0) { VplParams params; }
ByteAddressBuffer gb_position : register(t1);
ByteAddressBuffer gb_normal : register(t2);
ByteAddressBuffer irradiance : register(t3);
RWByteAddressBuffer filtered : register(u4);

float inv_sigma_z(float z)
{
    return (1.0 / (DEPTH_SIGMA * z));
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

uint window_start(uint x, uint size)
{
    uint half_ = naga_div(size, 2u);
    return (max(x, half_) - half_);
}

uint window_end(uint x_1, uint size_1, uint extent)
{
    return min(((x_1 + size_1) - naga_div(size_1, 2u)), extent);
}

uint wide_window(uint period)
{
    return (2u * period);
}

bool misses_subset(uint covered, uint period_1)
{
    return (covered < (period_1 * period_1));
}

float3 filtered_irradiance(float3 e, float3 sum, float weight)
{
    if ((weight > 0.0)) {
        return (sum / (weight).xxx);
    }
    return e;
}

float bilateral_weight(float3 n, float3 nj, float z_1, float zj, float inv_sz)
{
    float dn = max(dot(n, nj), 0.0);
    float dn2_ = (dn * dn);
    float dn4_ = (dn2_ * dn2_);
    float dn8_ = (dn4_ * dn4_);
    float d = ((zj - z_1) * inv_sz);
    float t = max((1.0 - (d * d)), 0.0);
    return (((dn8_ * dn8_) * t) * t);
}

float depth_of(uint i)
{
    float _e5 = asfloat(gb_normal.Load(12+i*16));
    float _e9 = asfloat(gb_position.Load(12+i*16));
    return ((_e9 > 0.0) ? _e5 : DEPTH_NONE);
}

Window window_sum(uint x_2, uint y, uint size_2, float3 n_1, float z_2, float inv)
{
    Window win = (Window)0;
    uint yy = (uint)0;
    uint xx = (uint)0;

    uint w = params.width;
    uint h = params.height;
    const uint _e12 = window_start(x_2, size_2);
    const uint _e13 = window_end(x_2, size_2, w);
    const uint _e14 = window_start(y, size_2);
    const uint _e15 = window_end(y, size_2, h);
    win.sum = (0.0).xxx;
    win.weight = 0.0;
    win.covered = 0u;
    yy = _e14;
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e63 = yy;
            yy = (_e63 + 1u);
        }
        loop_init = false;
        uint _e25 = yy;
        if ((_e25 < _e15)) {
        } else {
            break;
        }
        {
            xx = _e12;
            uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
            bool loop_init_1 = true;
            while(true) {
                if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
                loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                if (!loop_init_1) {
                    uint _e60 = xx;
                    xx = (_e60 + 1u);
                }
                loop_init_1 = false;
                uint _e28 = xx;
                if ((_e28 < _e13)) {
                } else {
                    break;
                }
                {
                    uint _e30 = yy;
                    uint _e32 = xx;
                    uint j = ((_e30 * w) + _e32);
                    float4 _e36 = asfloat(gb_normal.Load4(j*16));
                    const float _e38 = depth_of(j);
                    const float _e39 = bilateral_weight(n_1, _e36.xyz, z_2, _e38, inv);
                    float3 _e41 = win.sum;
                    float4 _e44 = asfloat(irradiance.Load4(j*16));
                    win.sum = (_e41 + (_e44.xyz * _e39));
                    float _e49 = win.weight;
                    win.weight = (_e49 + _e39);
                    uint _e52 = win.covered;
                    win.covered = (_e52 + ((_e39 > COVER_WEIGHT) ? 1u : 0u));
                }
            }
        }
    }
    Window _e65 = win;
    const Window window = _e65;
    return window;
}

[numthreads(8, 8, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    bool local = (bool)0;
    Window s = (Window)0;

    uint w_1 = params.width;
    uint h_1 = params.height;
    if (!((gid.x >= w_1))) {
        local = (gid.y >= h_1);
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    uint i_1 = ((gid.y * w_1) + gid.x);
    float4 e_1 = asfloat(irradiance.Load4(i_1*16));
    float _e26 = asfloat(gb_position.Load(12+i_1*16));
    if ((_e26 <= 0.0)) {
        filtered.Store4(i_1*16, asuint(float4(0.0, 0.0, 0.0, e_1.w)));
        return;
    }
    float4 _e38 = asfloat(gb_normal.Load4(i_1*16));
    float3 n_2 = _e38.xyz;
    const float _e40 = depth_of(i_1);
    const float _e41 = inv_sigma_z(_e40);
    const Window _e45 = window_sum(gid.x, gid.y, PERIOD, n_2, _e40, _e41);
    s = _e45;
    uint _e48 = s.covered;
    const bool _e50 = misses_subset(_e48, PERIOD);
    if (_e50) {
        const uint _e54 = wide_window(PERIOD);
        const Window _e55 = window_sum(gid.x, gid.y, _e54, n_2, _e40, _e41);
        s = _e55;
    }
    float3 _e60 = s.sum;
    float _e62 = s.weight;
    const float3 _e63 = filtered_irradiance(e_1.xyz, _e60, _e62);
    filtered.Store4(i_1*16, asuint(float4(_e63, e_1.w)));
    return;
}
