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

struct GpuVplRecord {
    float3 position;
    float pad0_;
    float3 normal;
    float pad1_;
    float3 flux;
    float pad2_;
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
ByteAddressBuffer records : register(t1);
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

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

uint interleave_slot_linear(uint i, uint per_subset, uint period)
{
    uint subsets = (period * period);
    return ((naga_mod(i, subsets) * per_subset) + naga_div(i, subsets));
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

GpuVplRecord ConstructGpuVplRecord(float3 arg0, float arg1, float3 arg2, float arg3, float3 arg4, float arg5) {
    GpuVplRecord ret = (GpuVplRecord)0;
    ret.position = arg0;
    ret.pad0_ = arg1;
    ret.normal = arg2;
    ret.pad1_ = arg3;
    ret.flux = arg4;
    ret.pad2_ = arg5;
    return ret;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    float3 p = (float3)0;
    float3 normal = (float3)0;
    float3 flux = (float3)0;

    uint i_1 = gid.x;
    uint _e4 = params.count;
    if ((i_1 >= _e4)) {
        return;
    }
    GpuVplRecord r = ConstructGpuVplRecord(asfloat(records.Load3(i_1*48+0)), asfloat(records.Load(i_1*48+12)), asfloat(records.Load3(i_1*48+16)), asfloat(records.Load(i_1*48+28)), asfloat(records.Load3(i_1*48+32)), asfloat(records.Load(i_1*48+44)));
    p = r.position;
    normal = r.normal;
    flux = r.flux;
    uint _e17 = params.per_subset;
    const uint _e19 = interleave_slot_linear(i_1, _e17, P);
    float3 _e20 = p;
    float3 _e21 = normal;
    float3 _e22 = flux;
    const bool _e23 = vpl_record_ok(_e20, _e21, _e22);
    if (!(_e23)) {
        p = (0.0).xxx;
        normal = (0.0).xxx;
        flux = (0.0).xxx;
    }
    float3 _e31 = flux;
    float _e34 = params.scale;
    flux = (_e31 * _e34);
    float3 _e38 = p;
    float3 _e40 = normal;
    float3 _e43 = flux;
    {
        GpuLight _value2 = ConstructGpuLight(_e38, LIGHT_VPL, _e40, 0.0, (0.0).xxx, 0.0, _e43, 0u);
        lights.Store3(_e19*64+0, asuint(_value2.p0_));
        lights.Store(_e19*64+12, asuint(_value2.kind));
        lights.Store3(_e19*64+16, asuint(_value2.p1_));
        lights.Store(_e19*64+28, asuint(_value2.a));
        lights.Store3(_e19*64+32, asuint(_value2.p2_));
        lights.Store(_e19*64+44, asuint(_value2.b));
        lights.Store3(_e19*64+48, asuint(_value2.intensity));
        lights.Store(_e19*64+60, asuint(_value2.ies_base));
    }
    ids.Store(_e19*4, asuint(i_1));
    uint _e52 = params.slc;
    bool slc = (_e52 != 0u);
    float3 _e57 = flux;
    float _e60 = params.exposure;
    float _e63 = params.error_bound;
    uint _e66 = params.mode;
    const float _e67 = vpl_rt2_(_e57, _e60, _e63, _e66);
    rt2_.Store(_e19*4, asuint((slc ? _e67 : 0.0)));
    float _e74 = params.fixed_r2_;
    r2_.Store(_e19*4, asuint((slc ? 0.0 : _e74)));
    near_slots.Store(i_1*4, asuint(_e19));
    return;
}
