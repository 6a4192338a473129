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

struct PackParams {
    uint count;
    uint size;
    uint per_subset;
    uint mode;
    float exposure;
    float error_bound;
    float scale;
    uint slc;
    float fixed_r2_;
    uint pad0_;
    uint pad1_;
    uint pad2_;
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
static const uint P = 8u;

cbuffer params : register(b0) { PackParams params; }
Texture2D<float4> rsm_position : register(t1);
Texture2D<float4> rsm_normal : register(t2);
Texture2D<float4> rsm_flux : register(t3);
RWByteAddressBuffer lights : register(u4);
RWByteAddressBuffer ids : register(u5);
RWByteAddressBuffer rt2_ : register(u6);
RWByteAddressBuffer r2_ : register(u7);
RWByteAddressBuffer near_slots : register(u8);

float threshold_range2_(float intensity, float exposure, float error_bound)
{
    if ((intensity <= 0.0)) {
        return 0.0;
    }
    return (((exposure / error_bound) * intensity) / TWO_PI);
}

float intensity_measure(float3 rgb, uint mode)
{
    if ((mode == 1u)) {
        return (((rgb.x + rgb.y) + rgb.z) / 3.0);
    }
    return max(rgb.x, max(rgb.y, rgb.z));
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

uint groups_across(uint bw, uint gw)
{
    return naga_div(((bw + gw) - 1u), gw);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint group_first(uint g, uint bw_1, uint bh, uint gw_1, uint gh)
{
    const uint _e5 = groups_across(bw_1, gw_1);
    uint gx = naga_mod(g, _e5);
    uint gy = naga_div(g, _e5);
    uint h = min(gh, (bh - (gh * gy)));
    return (((gy * gh) * bw_1) + ((gx * gw_1) * h));
}

uint cluster_index(uint bx, uint by, uint bw_2, uint bh_1, uint gw_2, uint gh_1)
{
    uint gx_1 = naga_div(bx, gw_2);
    uint gy_1 = naga_div(by, gh_1);
    uint w = min(gw_2, (bw_2 - (gw_2 * gx_1)));
    const uint _e11 = groups_across(bw_2, gw_2);
    uint g_1 = ((gy_1 * _e11) + gx_1);
    const uint _e14 = group_first(g_1, bw_2, bh_1, gw_2, gh_1);
    return ((_e14 + ((by - (gh_1 * gy_1)) * w)) + (bx - (gw_2 * gx_1)));
}

uint cluster_x(uint c, uint bw_3, uint bh_2, uint gw_3, uint gh_2)
{
    uint gy_2 = naga_div(c, (gh_2 * bw_3));
    uint h_1 = min(gh_2, (bh_2 - (gh_2 * gy_2)));
    uint rest = (c - ((gy_2 * gh_2) * bw_3));
    uint gx_2 = naga_div(rest, (gw_3 * h_1));
    uint w_1 = min(gw_3, (bw_3 - (gw_3 * gx_2)));
    return ((gx_2 * gw_3) + naga_mod((rest - ((gx_2 * gw_3) * h_1)), w_1));
}

uint cluster_y(uint c_1, uint bw_4, uint bh_3, uint gw_4, uint gh_3)
{
    uint gy_3 = naga_div(c_1, (gh_3 * bw_4));
    uint h_2 = min(gh_3, (bh_3 - (gh_3 * gy_3)));
    uint rest_1 = (c_1 - ((gy_3 * gh_3) * bw_4));
    uint gx_3 = naga_div(rest_1, (gw_4 * h_2));
    uint w_2 = min(gw_4, (bw_4 - (gw_4 * gx_3)));
    return ((gy_3 * gh_3) + naga_div((rest_1 - ((gx_3 * gw_4) * h_2)), w_2));
}

uint map_index(uint tx, uint ty, uint side)
{
    uint b = naga_div(side, 8u);
    const uint _e11 = cluster_index(naga_div(tx, 8u), naga_div(ty, 8u), b, b, GROUP_SIDE, GROUP_SIDE);
    return (((_e11 * CLUSTER) + (naga_mod(ty, 8u) * 8u)) + naga_mod(tx, 8u));
}

uint map_x(uint q, uint side_1)
{
    uint b_1 = naga_div(side_1, 8u);
    const uint _e8 = cluster_x(naga_div(q, CLUSTER), b_1, b_1, GROUP_SIDE, GROUP_SIDE);
    return ((_e8 * 8u) + naga_mod(q, 8u));
}

uint map_y(uint q_1, uint side_2)
{
    uint b_2 = naga_div(side_2, 8u);
    const uint _e8 = cluster_y(naga_div(q_1, CLUSTER), b_2, b_2, GROUP_SIDE, GROUP_SIDE);
    return ((_e8 * 8u) + naga_div(naga_mod(q_1, CLUSTER), 8u));
}

float vpl_rt2_(float3 flux_1, float exposure_1, float error_bound_1, uint mode_1)
{
    const float _e6 = intensity_measure((flux_1 * INV_PI), mode_1);
    const float _e7 = threshold_range2_(_e6, exposure_1, error_bound_1);
    return _e7;
}

bool finite3_(float3 v)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;

    if ((abs(v.x) <= F32_MAX)) {
        local = (abs(v.y) <= F32_MAX);
    } else {
        local = false;
    }
    bool _e12 = local;
    if (_e12) {
        local_1 = (abs(v.z) <= F32_MAX);
    } else {
        local_1 = false;
    }
    bool _e20 = local_1;
    return _e20;
}

uint interleave_subset(uint x, uint y, uint period)
{
    return ((naga_mod(y, period) * period) + naga_mod(x, period));
}

bool vpl_record_ok(float3 position, float3 normal_1, float3 flux_2)
{
    bool local_2 = (bool)0;
    bool local_3 = (bool)0;
    bool local_4 = (bool)0;
    bool local_5 = (bool)0;
    bool local_6 = (bool)0;

    const bool _e3 = finite3_(position);
    if (_e3) {
        const bool _e6 = finite3_(normal_1);
        local_2 = _e6;
    } else {
        local_2 = false;
    }
    bool _e8 = local_2;
    if (_e8) {
        const bool _e11 = finite3_(flux_2);
        local_3 = _e11;
    } else {
        local_3 = false;
    }
    bool _e13 = local_3;
    if (!(_e13)) {
        return false;
    }
    if ((flux_2.x >= 0.0)) {
        local_4 = (flux_2.y >= 0.0);
    } else {
        local_4 = false;
    }
    bool _e25 = local_4;
    if (_e25) {
        local_5 = (flux_2.z >= 0.0);
    } else {
        local_5 = false;
    }
    bool _e32 = local_5;
    if (_e32) {
        local_6 = ((max(max(flux_2.x, flux_2.y), flux_2.z) * INV_PI) <= MAX_INTENSITY);
    } else {
        local_6 = false;
    }
    bool _e45 = local_6;
    return _e45;
}

uint subset_side(uint size, uint period_1)
{
    return (naga_div((naga_div(size, period_1) + 7u), 8u) * 8u);
}

uint interleave_slot(uint tx_1, uint ty_1, uint size_1, uint period_2)
{
    const uint _e4 = subset_side(size_1, period_2);
    const uint _e5 = interleave_subset(tx_1, ty_1, period_2);
    const uint _e10 = map_index(naga_div(tx_1, period_2), naga_div(ty_1, period_2), _e4);
    return (((_e5 * _e4) * _e4) + _e10);
}

GpuLight ConstructGpuLight(float3 arg0, uint arg1, float3 arg2, float arg3, float3 arg4, float arg5, float3 arg6, uint arg7) {
    GpuLight ret = (GpuLight)0;
    ret.p0_ = arg0;
    ret.kind = arg1;
    ret.p1_ = arg2;
    ret.a = arg3;
    ret.p2_ = arg4;
    ret.b = arg5;
    ret.intensity = arg6;
    ret.ies_base = arg7;
    return ret;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    float3 p = (float3)0;
    float3 normal = (float3)0;
    float3 flux = (float3)0;

    uint q_2 = gid.x;
    uint _e4 = params.count;
    if ((q_2 >= _e4)) {
        return;
    }
    uint _e8 = params.size;
    const uint _e9 = map_x(q_2, _e8);
    uint _e12 = params.size;
    const uint _e13 = map_y(q_2, _e12);
    uint _e16 = params.size;
    uint i = ((_e13 * _e16) + _e9);
    int2 texel = int2(int(_e9), int(_e13));
    float4 _e24 = rsm_position.Load(int3(texel, int(0)));
    p = _e24.xyz;
    float4 _e29 = rsm_normal.Load(int3(texel, int(0)));
    normal = _e29.xyz;
    float4 _e34 = rsm_flux.Load(int3(texel, int(0)));
    flux = _e34.xyz;
    uint _e39 = params.size;
    const uint _e41 = interleave_slot(_e9, _e13, _e39, P);
    float3 _e42 = p;
    float3 _e43 = normal;
    float3 _e44 = flux;
    const bool _e45 = vpl_record_ok(_e42, _e43, _e44);
    if (!(_e45)) {
        p = (0.0).xxx;
        normal = (0.0).xxx;
        flux = (0.0).xxx;
    }
    float3 _e53 = flux;
    float _e56 = params.scale;
    flux = (_e53 * _e56);
    float3 _e60 = p;
    float3 _e62 = normal;
    float3 _e65 = flux;
    {
        GpuLight _value2 = ConstructGpuLight(_e60, LIGHT_VPL, _e62, 0.0, (0.0).xxx, 0.0, _e65, 0u);
        lights.Store3(_e41*64+0, asuint(_value2.p0_));
        lights.Store(_e41*64+12, asuint(_value2.kind));
        lights.Store3(_e41*64+16, asuint(_value2.p1_));
        lights.Store(_e41*64+28, asuint(_value2.a));
        lights.Store3(_e41*64+32, asuint(_value2.p2_));
        lights.Store(_e41*64+44, asuint(_value2.b));
        lights.Store3(_e41*64+48, asuint(_value2.intensity));
        lights.Store(_e41*64+60, asuint(_value2.ies_base));
    }
    ids.Store(_e41*4, asuint(i));
    uint _e74 = params.slc;
    bool slc = (_e74 != 0u);
    float3 _e79 = flux;
    float _e82 = params.exposure;
    float _e85 = params.error_bound;
    uint _e88 = params.mode;
    const float _e89 = vpl_rt2_(_e79, _e82, _e85, _e88);
    rt2_.Store(_e41*4, asuint((slc ? _e89 : 0.0)));
    float _e96 = params.fixed_r2_;
    r2_.Store(_e41*4, asuint((slc ? 0.0 : _e96)));
    near_slots.Store(q_2*4, asuint(_e41));
    return;
}
