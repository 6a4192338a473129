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
static const uint P = 8u;
static const uint BOX_THREADS = 64u;

groupshared float3 wg_lo[64];
groupshared float3 wg_hi[64];
groupshared WorkgroupBox wg_box;
cbuffer params : register(b0) { VplParams params; }
ByteAddressBuffer lights : register(t1);
ByteAddressBuffer r2_3 : register(t2);
ByteAddressBuffer near_slots : register(t3);
RWByteAddressBuffer boxes : register(u4);

float to_f32_(uint u)
{
    return float(u);
}

float cull_radius(float r2_)
{
    return (sqrt(r2_) * CULL_RADIUS_SCALE);
}

float interleave_flux_scale(uint period)
{
    const float _e2 = to_f32_((period * period));
    return _e2;
}

float vpl_near_range2_(float r2_1, uint period_1)
{
    const float _e2 = interleave_flux_scale(period_1);
    return (r2_1 / _e2);
}

float vpl_near_cull_range2_(float r2_2, float near_r2_)
{
    return min(r2_2, near_r2_);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

WorkgroupBox ConstructWorkgroupBox(float3 arg0, float3 arg1) {
    WorkgroupBox ret = (WorkgroupBox)0;
    ret.lo = arg0;
    ret.hi = arg1;
    return ret;
}

WorkgroupBox workgroup_bounds(uint li_1, float3 lo, float3 hi)
{
    uint stride = 32u;

    wg_lo[min(uint(li_1), 63u)] = lo;
    wg_hi[min(uint(li_1), 63u)] = hi;
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

float near_r2_of(uint slot_1)
{
    float _e3 = asfloat(r2_3.Load(slot_1*4));
    const float _e5 = vpl_near_range2_(_e3, P);
    return _e5;
}

float near_cull_r2_of(uint slot_2, float near_r2_1)
{
    const float _e2 = near_r2_of(slot_2);
    const float _e3 = vpl_near_cull_range2_(_e2, near_r2_1);
    return _e3;
}

GpuBox ConstructGpuBox(float3 arg0, float arg1, float3 arg2, float arg3) {
    GpuBox ret = (GpuBox)0;
    ret.lo = arg0;
    ret.pad0_ = arg1;
    ret.hi = arg2;
    ret.pad1_ = arg3;
    return ret;
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
void main(uint3 wg : SV_GroupID, uint3 nwg : SV_GroupID, uint li : SV_GroupIndex)
{
    if (li == 0) {
        wg_lo = (float3[64])0;
        wg_hi = (float3[64])0;
        wg_box = (WorkgroupBox)0;
    }
    GroupMemoryBarrierWithGroupSync();
    uint slot = (uint)0;
    uint out_ = (uint)0;
    float r2_cull = (float)0;

    uint c = ((wg.y * nwg.x) + wg.x);
    uint far = params.far_groups_at;
    uint _e13 = params.near_groups_at;
    uint _e16 = params.near_clusters_at;
    uint near = (_e13 - _e16);
    if ((c >= (far + near))) {
        return;
    }
    if ((c < far)) {
        slot = ((c * CLUSTER) + li);
        out_ = c;
        uint _e28 = slot;
        float _e30 = asfloat(r2_3.Load(_e28*4));
        r2_cull = _e30;
    } else {
        uint _e37 = asuint(near_slots.Load((((c - far) * CLUSTER) + li)*4));
        slot = _e37;
        uint _e40 = params.near_clusters_at;
        out_ = ((_e40 + c) - far);
        uint _e43 = slot;
        float _e46 = params.near_r2_;
        const float _e47 = near_cull_r2_of(_e43, _e46);
        r2_cull = _e47;
    }
    uint _e49 = slot;
    GpuLight l = ConstructGpuLight(asfloat(lights.Load3(_e49*64+0)), asuint(lights.Load(_e49*64+12)), asfloat(lights.Load3(_e49*64+16)), asfloat(lights.Load(_e49*64+28)), asfloat(lights.Load3(_e49*64+32)), asfloat(lights.Load(_e49*64+44)), asfloat(lights.Load3(_e49*64+48)), asuint(lights.Load(_e49*64+60)));
    bool lit_ = any((l.intensity != (0.0).xxx));
    float _e57 = r2_cull;
    const float _e58 = cull_radius(_e57);
    const WorkgroupBox _e71 = workgroup_bounds(li, (lit_ ? (l.p0_ - (_e58).xxx) : (3.4028235e38).xxx), (lit_ ? (l.p0_ + (_e58).xxx) : (-3.4028235e38).xxx));
    if ((li == 0u)) {
        uint _e75 = out_;
        {
            GpuBox _value3 = ConstructGpuBox(_e71.lo, 0.0, _e71.hi, 0.0);
            boxes.Store3(_e75*32+0, asuint(_value3.lo));
            boxes.Store(_e75*32+12, asuint(_value3.pad0_));
            boxes.Store3(_e75*32+16, asuint(_value3.hi));
            boxes.Store(_e75*32+28, asuint(_value3.pad1_));
        }
        return;
    } else {
        return;
    }
}
