struct VplParams {
    uint width;
    uint height;
    uint lights_per_subset;
    float min_d2_;
    float near_r2_;
    uint subset_shift;
    uint far_groups_at;
    uint near_clusters_at;
    uint near_groups_at;
    uint box_count;
    uint pad0_;
    uint pad1_;
    uint4 far_grid;
    uint4 near_grid;
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
static const uint PERIOD = 8u;

cbuffer params : register(b0) { VplParams params; }
ByteAddressBuffer guide : register(t1);
ByteAddressBuffer irradiance : register(t2);
RWByteAddressBuffer filtered : register(u3);

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
                    float4 g = asfloat(guide.Load4(j*16));
                    const float _e39 = bilateral_weight(n_1, g.xyz, z_2, g.w, inv);
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
    uint i = ((gid.y * w_1) + gid.x);
    float4 e_1 = asfloat(irradiance.Load4(i*16));
    float4 g_1 = asfloat(guide.Load4(i*16));
    if (all((g_1.xyz == (0.0).xxx))) {
        filtered.Store4(i*16, asuint(float4(0.0, 0.0, 0.0, e_1.w)));
        return;
    }
    float3 n_2 = g_1.xyz;
    float z_3 = g_1.w;
    const float _e40 = inv_sigma_z(z_3);
    const Window _e44 = window_sum(gid.x, gid.y, PERIOD, n_2, z_3, _e40);
    s = _e44;
    uint _e47 = s.covered;
    const bool _e49 = misses_subset(_e47, PERIOD);
    if (_e49) {
        const uint _e53 = wide_window(PERIOD);
        const Window _e54 = window_sum(gid.x, gid.y, _e53, n_2, z_3, _e40);
        s = _e54;
    }
    float3 _e59 = s.sum;
    float _e61 = s.weight;
    const float3 _e62 = filtered_irradiance(e_1.xyz, _e59, _e61);
    filtered.Store4(i*16, asuint(float4(_e62, e_1.w)));
    return;
}
