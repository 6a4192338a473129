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

struct GpuBox {
    float3 lo;
    float pad0_;
    float3 hi;
    float pad1_;
};

struct WorkgroupBox {
    float3 lo;
    int _pad1_0;
    float3 hi;
    int _end_pad_0;
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
static const uint BOX_THREADS = 64u;

groupshared float3 wg_lo[64];
groupshared float3 wg_hi[64];
groupshared WorkgroupBox wg_box;
cbuffer params : register(b0) { VplParams params; }
RWByteAddressBuffer boxes : register(u1);

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

uint groups_across(uint bw, uint gw)
{
    return naga_div(((bw + gw) - 1u), gw);
}

uint group_count(uint bw_1, uint bh, uint gw_1, uint gh)
{
    const uint _e4 = groups_across(bw_1, gw_1);
    const uint _e5 = groups_across(bh, gh);
    return (_e4 * _e5);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint group_first(uint g, uint bw_2, uint bh_1, uint gw_2, uint gh_1)
{
    const uint _e5 = groups_across(bw_2, gw_2);
    uint gx = naga_mod(g, _e5);
    uint gy = naga_div(g, _e5);
    uint h = min(gh_1, (bh_1 - (gh_1 * gy)));
    return (((gy * gh_1) * bw_2) + ((gx * gw_2) * h));
}

uint group_clusters(uint g_1, uint bw_3, uint bh_2, uint gw_3, uint gh_2)
{
    const uint _e5 = groups_across(bw_3, gw_3);
    uint gx_1 = naga_mod(g_1, _e5);
    uint gy_1 = naga_div(g_1, _e5);
    return (min(gw_3, (bw_3 - (gw_3 * gx_1))) * min(gh_2, (bh_2 - (gh_2 * gy_1))));
}

WorkgroupBox ConstructWorkgroupBox(float3 arg0, float3 arg1) {
    WorkgroupBox ret = (WorkgroupBox)0;
    ret.lo = arg0;
    ret.hi = arg1;
    return ret;
}

WorkgroupBox workgroup_bounds(uint li_1, float3 lo_1, float3 hi_1)
{
    uint stride = 32u;

    wg_lo[min(uint(li_1), 63u)] = lo_1;
    wg_hi[min(uint(li_1), 63u)] = hi_1;
    GroupMemoryBarrierWithGroupSync();
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e36 = stride;
            stride = naga_div(_e36, 2u);
        }
        loop_init = false;
        uint _e9 = stride;
        if ((_e9 > 0u)) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if ((li_1 < _e12)) {
                float3 _e18 = wg_lo[min(uint(li_1), 63u)];
                uint _e20 = stride;
                float3 _e23 = wg_lo[min(uint((li_1 + _e20)), 63u)];
                wg_lo[min(uint(li_1), 63u)] = min(_e18, _e23);
                float3 _e29 = wg_hi[min(uint(li_1), 63u)];
                uint _e31 = stride;
                float3 _e34 = wg_hi[min(uint((li_1 + _e31)), 63u)];
                wg_hi[min(uint(li_1), 63u)] = max(_e29, _e34);
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    if ((li_1 == 0u)) {
        float3 _e44 = wg_lo[0];
        float3 _e47 = wg_hi[0];
        wg_box = ConstructWorkgroupBox(_e44, _e47);
    }
    GroupMemoryBarrierWithGroupSync();
    WorkgroupBox _e50 = wg_box;
    GroupMemoryBarrierWithGroupSync();
    const WorkgroupBox workgroupbox = _e50;
    return workgroupbox;
}

GpuBox ConstructGpuBox(float3 arg0, float arg1, float3 arg2, float arg3) {
    GpuBox ret = (GpuBox)0;
    ret.lo = arg0;
    ret.pad0_ = arg1;
    ret.hi = arg2;
    ret.pad1_ = arg3;
    return ret;
}

[numthreads(64, 1, 1)]
void main(uint3 wg : SV_GroupID, uint3 nwg : SV_GroupID, uint li : SV_GroupIndex)
{
    if (li == 0) {
        wg_lo = (float3[64])0;
        wg_hi = (float3[64])0;
        wg_box = (WorkgroupBox)0;
    }
    GroupMemoryBarrierWithGroupSync();
    uint4 grid = (uint4)0;
    uint k = (uint)0;
    uint clusters = (uint)0;
    uint out_ = (uint)0;
    float3 lo = (3.4028235e38).xxx;
    float3 hi = (-3.4028235e38).xxx;

    uint g_2 = ((wg.y * nwg.x) + wg.x);
    uint _e10 = params.near_clusters_at;
    uint _e13 = params.far_groups_at;
    uint far = (_e10 - _e13);
    uint _e17 = params.box_count;
    uint _e20 = params.near_groups_at;
    uint near = (_e17 - _e20);
    if ((g_2 >= (far + near))) {
        return;
    }
    if ((g_2 < far)) {
        uint4 _e31 = params.far_grid;
        grid = _e31;
        uint _e33 = grid.x;
        uint _e35 = grid.y;
        uint _e37 = grid.z;
        uint _e39 = grid.w;
        const uint _e40 = group_count(_e33, _e35, _e37, _e39);
        k = naga_mod(g_2, _e40);
        uint _e45 = params.lights_per_subset;
        clusters = (naga_div(g_2, _e40) * naga_div(_e45, CLUSTER));
        uint _e51 = params.far_groups_at;
        out_ = (_e51 + g_2);
    } else {
        uint4 _e55 = params.near_grid;
        grid = _e55;
        k = (g_2 - far);
        uint _e59 = params.near_clusters_at;
        clusters = _e59;
        uint _e62 = params.near_groups_at;
        uint _e63 = k;
        out_ = (_e62 + _e63);
    }
    uint _e65 = k;
    uint _e67 = grid.x;
    uint _e69 = grid.y;
    uint _e71 = grid.z;
    uint _e73 = grid.w;
    const uint _e74 = group_clusters(_e65, _e67, _e69, _e71, _e73);
    if ((li < _e74)) {
        uint _e83 = clusters;
        uint _e84 = k;
        uint _e86 = grid.x;
        uint _e88 = grid.y;
        uint _e90 = grid.z;
        uint _e92 = grid.w;
        const uint _e93 = group_first(_e84, _e86, _e88, _e90, _e92);
        GpuBox b = ConstructGpuBox(asfloat(boxes.Load3(((_e83 + _e93) + li)*32+0)), asfloat(boxes.Load(((_e83 + _e93) + li)*32+12)), asfloat(boxes.Load3(((_e83 + _e93) + li)*32+16)), asfloat(boxes.Load(((_e83 + _e93) + li)*32+28)));
        lo = b.lo;
        hi = b.hi;
    }
    float3 _e100 = lo;
    float3 _e101 = hi;
    const WorkgroupBox _e102 = workgroup_bounds(li, _e100, _e101);
    if ((li == 0u)) {
        uint _e106 = out_;
        {
            GpuBox _value3 = ConstructGpuBox(_e102.lo, 0.0, _e102.hi, 0.0);
            boxes.Store3(_e106*32+0, asuint(_value3.lo));
            boxes.Store(_e106*32+12, asuint(_value3.pad0_));
            boxes.Store3(_e106*32+16, asuint(_value3.hi));
            boxes.Store(_e106*32+28, asuint(_value3.pad1_));
        }
        return;
    } else {
        return;
    }
}
