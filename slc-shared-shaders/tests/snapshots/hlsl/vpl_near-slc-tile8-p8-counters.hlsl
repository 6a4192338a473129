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

struct WorkgroupBox {
    float3 lo;
    int _pad1_0;
    float3 hi;
    int _end_pad_0;
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
static const uint P = 8u;
static const uint TILE = 8u;
static const uint THREADS = 64u;
static const uint BOX_THREADS = 64u;
static const uint HALF = 4u;
static const uint QUARTER_LIGHTS = 256u;

groupshared float3 wg_lo[64];
groupshared float3 wg_hi[64];
groupshared WorkgroupBox wg_box;
cbuffer params : register(b0) { VplParams params; }
cbuffer view : register(b1) { ViewParams view; }
Texture2D<float4> position_tex : register(t2);
Texture2D<float4> normal_tex : register(t3);
ByteAddressBuffer lights : register(t4);
ByteAddressBuffer near_slots : register(t5);
ByteAddressBuffer boxes : register(t6);
ByteAddressBuffer rt2_2 : register(t7);
ByteAddressBuffer r2_5 : register(t8);
RWByteAddressBuffer irradiance : register(u9);
RWByteAddressBuffer counters : register(u12);
groupshared uint wg_counts[7];
static float3 pos = (float3)0;
static float3 nrm = (float3)0;
static float eye_distance = (float)0;
static bool valid = (bool)0;
static float3 e = (float3)0;
static uint kept = (uint)0;
groupshared float3 quarter_lo[4];
groupshared float3 quarter_hi[4];
groupshared uint quarter_lights[1024];
groupshared uint quarter_count[4];
groupshared uint fullest;
static uint quarter = (uint)0;
groupshared uint cluster_hits[64];
groupshared uint hit_count;

float to_f32_(uint u)
{
    return float(u);
}

float slc_weight(float rt2_, float d2_)
{
    if ((d2_ <= rt2_)) {
        return 1.0;
    }
    return (d2_ / rt2_);
}

bool slc_keep(float r2_, float d2_1)
{
    return (d2_1 < r2_);
}

float cull_radius(float r2_1)
{
    return (sqrt(r2_1) * CULL_RADIUS_SCALE);
}

bool sphere_overlaps_aabb(float3 c, float r, float3 bmin, float3 bmax)
{
    float3 q_1 = clamp(c, bmin, bmax);
    float3 v_1 = (q_1 - c);
    return (dot(v_1, v_1) <= (r * r));
}

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
    uint h_1 = min(gh_1, (bh_1 - (gh_1 * gy)));
    return (((gy * gh_1) * bw_2) + ((gx * gw_2) * h_1));
}

uint group_clusters(uint g_1, uint bw_3, uint bh_2, uint gw_3, uint gh_2)
{
    const uint _e5 = groups_across(bw_3, gw_3);
    uint gx_1 = naga_mod(g_1, _e5);
    uint gy_1 = naga_div(g_1, _e5);
    return (min(gw_3, (bw_3 - (gw_3 * gx_1))) * min(gh_2, (bh_2 - (gh_2 * gy_1))));
}

bool box_overlaps_box(float3 lo1_, float3 hi1_, float3 lo2_, float3 hi2_)
{
    bool local_1 = (bool)0;
    bool local_2 = (bool)0;
    bool local_3 = (bool)0;
    bool local_4 = (bool)0;
    bool local_5 = (bool)0;

    if ((lo1_.x <= hi2_.x)) {
        local_1 = (lo2_.x <= hi1_.x);
    } else {
        local_1 = false;
    }
    bool _e13 = local_1;
    if (_e13) {
        local_2 = (lo1_.y <= hi2_.y);
    } else {
        local_2 = false;
    }
    bool _e20 = local_2;
    if (_e20) {
        local_3 = (lo2_.y <= hi1_.y);
    } else {
        local_3 = false;
    }
    bool _e27 = local_3;
    if (_e27) {
        local_4 = (lo1_.z <= hi2_.z);
    } else {
        local_4 = false;
    }
    bool _e34 = local_4;
    if (_e34) {
        local_5 = (lo2_.z <= hi1_.z);
    } else {
        local_5 = false;
    }
    bool _e41 = local_5;
    return _e41;
}

float vpl_transfer(float3 n_l, float3 n_x, float3 v, float min_d2_)
{
    float m_1 = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m_1 * m_1));
}

float interleave_flux_scale(uint period)
{
    const float _e2 = to_f32_((period * period));
    return _e2;
}

float vpl_near_weight(float d2_2, float near_r2_)
{
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t = clamp(((near_r2_ - d2_2) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t * t) * (3.0 - (2.0 * t)));
}

float vpl_near_range2_(float r2_2, uint period_1)
{
    const float _e2 = interleave_flux_scale(period_1);
    return (r2_2 / _e2);
}

float vpl_near_cull_range2_(float r2_3, float near_r2_1)
{
    return min(r2_3, near_r2_1);
}

float vpl_near_slc_share(float rt2_1, float r2_4, float d2_3, float near_r2_2)
{
    const float _e4 = vpl_near_weight(d2_3, near_r2_2);
    const float _e5 = slc_weight(rt2_1, d2_3);
    const bool _e7 = slc_keep(r2_4, d2_3);
    return ((_e7 & (_e4 > 0.0)) ? (_e4 * _e5) : 0.0);
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

WorkgroupBox point_box(float3 p, bool has)
{
    const WorkgroupBox workgroupbox_1 = ConstructWorkgroupBox((has ? p : (3.4028235e38).xxx), (has ? p : (-3.4028235e38).xxx));
    return workgroupbox_1;
}

WorkgroupBox workgroup_box(uint li_2, float3 p_1, bool has_1)
{
    const WorkgroupBox _e3 = point_box(p_1, has_1);
    const WorkgroupBox _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi);
    const WorkgroupBox workgroupbox_2 = _e6;
    return workgroupbox_2;
}

bool box_is_empty(WorkgroupBox b)
{
    return (b.lo.x > b.hi.x);
}

float4 surface_at(int2 texel)
{
    float4 p_5 = position_tex.Load(int3(texel, int(0)));
    return ((p_5.w > 0.0) ? float4(p_5.xyz, 1.0) : (0.0).xxxx);
}

GbTexel ConstructGbTexel(float4 arg0, float4 arg1) {
    GbTexel ret = (GbTexel)0;
    ret.position = arg0;
    ret.normal = arg1;
    return ret;
}

GbTexel gbuffer_at(uint i)
{
    bool local_6 = (bool)0;

    uint _e3 = view.width;
    uint _e8 = view.width;
    int2 texel_1 = int2(int(naga_mod(i, _e3)), int(naga_div(i, _e8)));
    const float4 _e12 = surface_at(texel_1);
    float4 _e15 = normal_tex.Load(int3(texel_1, int(0)));
    float3 n_3 = _e15.xyz;
    float len2_ = dot(n_3, n_3);
    if ((_e12.w > 0.0)) {
        local_6 = (len2_ > 0.0);
    } else {
        local_6 = false;
    }
    bool valid_1 = local_6;
    float3 _e30 = view.eye;
    float3 v_2 = (_e12.xyz - _e30);
    float4 position = float4(_e12.xyz, (valid_1 ? 1.0 : 0.0));
    float4 normal = (valid_1 ? float4((n_3 / (sqrt(len2_)).xxx), sqrt(dot(v_2, v_2))) : float4(0.0, 0.0, 0.0, 1e30));
    const GbTexel gbtexel = ConstructGbTexel(position, normal);
    return gbtexel;
}

float near_r2_of(uint slot)
{
    float _e3 = asfloat(r2_5.Load(slot*4));
    const float _e5 = vpl_near_range2_(_e3, P);
    return _e5;
}

float near_cull_r2_of(uint slot_1, float near_r2_3)
{
    const float _e2 = near_r2_of(slot_1);
    const float _e3 = vpl_near_cull_range2_(_e2, near_r2_3);
    return _e3;
}

void counter_add(uint f, uint n)
{
    uint _e6; counters.InterlockedAdd((2u * f)*4, n, _e6);
    if (((_e6 + n) < _e6)) {
        uint _e16; counters.InterlockedAdd(((2u * f) + 1u)*4, 1u, _e16);
        return;
    } else {
        return;
    }
}

void counts_begin(uint li_3)
{
    if ((li_3 < COUNT_FIELDS)) {
        { uint dummy = 0; InterlockedExchange(wg_counts[min(uint(li_3), 6u)], 0u, dummy); }
    }
    GroupMemoryBarrierWithGroupSync();
    return;
}

void count_add(uint f_1, uint n_1)
{
    uint _e4; InterlockedAdd(wg_counts[min(uint(f_1), 6u)], n_1, _e4);
    return;
}

void count_one(uint f_2)
{
    uint _e4; InterlockedAdd(wg_counts[min(uint(f_2), 6u)], 1u, _e4);
    return;
}

void count_tests(uint li_4, uint f_3, uint n_2)
{
    if ((li_4 == 0u)) {
        uint _e7; InterlockedAdd(wg_counts[min(uint(f_3), 6u)], n_2, _e7);
        return;
    } else {
        return;
    }
}

void counts_end(uint li_5)
{
    GroupMemoryBarrierWithGroupSync();
    if ((li_5 < COUNT_FIELDS)) {
        uint _e5; InterlockedOr(wg_counts[min(uint(li_5), 6u)], 0, _e5);
        counter_add(li_5, _e5);
        return;
    } else {
        return;
    }
}

WorkgroupBox load_receiver(uint li_6, uint pix, bool inside)
{
    float4 p_2 = (0.0).xxxx;
    bool local_7 = (bool)0;

    eye_distance = DEPTH_NONE;
    if (inside) {
        const GbTexel _e8 = gbuffer_at(pix);
        p_2 = _e8.position;
        nrm = _e8.normal.xyz;
        eye_distance = _e8.normal.w;
    }
    float4 _e17 = p_2;
    pos = _e17.xyz;
    if (inside) {
        float _e23 = p_2.w;
        local_7 = (_e23 > 0.0);
    } else {
        local_7 = false;
    }
    bool _e27 = local_7;
    valid = _e27;
    counts_begin(li_6);
    bool _e29 = valid;
    if (_e29) {
        count_one(COUNT_PIXELS);
    }
    float3 _e32 = pos;
    bool _e34 = valid;
    const WorkgroupBox _e35 = workgroup_box(li_6, _e32, _e34);
    const WorkgroupBox workgroupbox_3 = _e35;
    return workgroupbox_3;
}

void count_receiver(uint li_7)
{
    bool _e2 = valid;
    if (_e2) {
        uint _e5 = kept;
        count_add(COUNT_KEPT, _e5);
    }
    counts_end(li_7);
    return;
}

uint cluster_slot(uint c_1, uint k)
{
    uint _e5 = params.near_clusters_at;
    uint _e11 = asuint(near_slots.Load((((c_1 - _e5) * CLUSTER) + k)*4));
    return _e11;
}

float cull_r2_of(uint slot_2)
{
    float _e3 = params.near_r2_;
    const float _e4 = near_cull_r2_of(slot_2, _e3);
    return _e4;
}

void quarter_boxes(uint li_8, uint3 lid_1)
{
    float3 lo_1 = (3.4028235e38).xxx;
    float3 hi_1 = (-3.4028235e38).xxx;
    uint y = (uint)0;
    uint x = (uint)0;

    quarter = (((lid_1.x >= HALF) ? 1u : 0u) + ((lid_1.y >= HALF) ? 2u : 0u));
    float3 _e17 = pos;
    bool _e19 = valid;
    const WorkgroupBox _e20 = point_box(_e17, _e19);
    wg_lo[min(uint(li_8), 63u)] = _e20.lo;
    wg_hi[min(uint(li_8), 63u)] = _e20.hi;
    GroupMemoryBarrierWithGroupSync();
    if ((li_8 < 4u)) {
        uint x0_ = (naga_mod(li_8, 2u) * HALF);
        uint y0_ = (naga_div(li_8, 2u) * HALF);
        y = y0_;
        uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
            loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e81 = y;
                y = (_e81 + 1u);
            }
            loop_init_1 = false;
            uint _e44 = y;
            if ((_e44 < min((y0_ + HALF), TILE))) {
            } else {
                break;
            }
            {
                x = x0_;
                uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
                bool loop_init_2 = true;
                while(true) {
                    if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
                    loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                    if (!loop_init_2) {
                        uint _e78 = x;
                        x = (_e78 + 1u);
                    }
                    loop_init_2 = false;
                    uint _e51 = x;
                    if ((_e51 < min((x0_ + HALF), TILE))) {
                    } else {
                        break;
                    }
                    {
                        float3 _e57 = lo_1;
                        uint _e59 = y;
                        uint _e62 = x;
                        float3 _e65 = wg_lo[min(uint(((_e59 * TILE) + _e62)), 63u)];
                        lo_1 = min(_e57, _e65);
                        float3 _e67 = hi_1;
                        uint _e69 = y;
                        uint _e72 = x;
                        float3 _e75 = wg_hi[min(uint(((_e69 * TILE) + _e72)), 63u)];
                        hi_1 = max(_e67, _e75);
                    }
                }
            }
        }
        float3 _e85 = lo_1;
        quarter_lo[min(uint(li_8), 3u)] = _e85;
        float3 _e88 = hi_1;
        quarter_hi[min(uint(li_8), 3u)] = _e88;
    }
    GroupMemoryBarrierWithGroupSync();
    return;
}

void list_clear(uint li_9)
{
    if ((li_9 < 4u)) {
        { uint dummy_1 = 0; InterlockedExchange(quarter_count[min(uint(li_9), 3u)], 0u, dummy_1); }
    }
    if ((li_9 == 0u)) {
        { uint dummy_2 = 0; InterlockedExchange(fullest, 0u, dummy_2); }
        return;
    } else {
        return;
    }
}

bool list_full()
{
    GroupMemoryBarrierWithGroupSync();
    uint _e1 = fullest;
    GroupMemoryBarrierWithGroupSync();
    return ((_e1 + CLUSTER) > QUARTER_LIGHTS);
}

uint quarter_add(uint q, uint slot_3, float3 p_3, float radius)
{
    float3 lo_3 = quarter_lo[min(uint(q), 3u)];
    float3 hi_3 = quarter_hi[min(uint(q), 3u)];
    if ((lo_3.x > hi_3.x)) {
        return 0u;
    }
    count_one(COUNT_SPHERE_TESTS);
    const bool _e15 = sphere_overlaps_aabb(p_3, radius, lo_3, hi_3);
    if (!(_e15)) {
        return 0u;
    }
    uint _e21; InterlockedAdd(quarter_count[min(uint(q), 3u)], 1u, _e21);
    quarter_lights[min(uint(((q * QUARTER_LIGHTS) + _e21)), 1023u)] = slot_3;
    return (_e21 + 1u);
}

void list_add(uint slot_4, float3 p_4, float radius_1)
{
    const uint _e4 = quarter_add(0u, slot_4, p_4, radius_1);
    const uint _e6 = quarter_add(1u, slot_4, p_4, radius_1);
    uint a = max(_e4, _e6);
    const uint _e9 = quarter_add(2u, slot_4, p_4, radius_1);
    const uint _e11 = quarter_add(3u, slot_4, p_4, radius_1);
    uint b_1 = max(_e9, _e11);
    uint _e15; InterlockedMax(fullest, max(a, b_1), _e15);
    return;
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

void shade_list(uint count, uint first)
{
    uint m = 0u;

    bool _e3 = valid;
    if (!(_e3)) {
        return;
    }
    const float _e6 = interleave_flux_scale(P);
    float unscale = (1.0 / _e6);
    uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e57 = m;
            m = (_e57 + 1u);
        }
        loop_init_3 = false;
        uint _e11 = m;
        if ((_e11 < count)) {
        } else {
            break;
        }
        {
            uint _e14 = m;
            uint slot_5 = quarter_lights[min(uint((first + _e14)), 1023u)];
            GpuLight l = ConstructGpuLight(asfloat(lights.Load3(slot_5*64+0)), asuint(lights.Load(slot_5*64+12)), asfloat(lights.Load3(slot_5*64+16)), asfloat(lights.Load(slot_5*64+28)), asfloat(lights.Load3(slot_5*64+32)), asfloat(lights.Load(slot_5*64+44)), asfloat(lights.Load3(slot_5*64+48)), asuint(lights.Load(slot_5*64+60)));
            float3 _e22 = pos;
            float3 v_3 = (_e22 - l.p0_);
            float _e27 = asfloat(rt2_2.Load(slot_5*4));
            const float _e29 = vpl_near_range2_(_e27, P);
            const float _e30 = near_r2_of(slot_5);
            float _e34 = params.near_r2_;
            const float _e35 = vpl_near_slc_share(_e29, _e30, dot(v_3, v_3), _e34);
            if ((_e35 > 0.0)) {
                float3 _e40 = nrm;
                float _e43 = params.min_d2_;
                const float _e44 = vpl_transfer(l.p1_, _e40, v_3, _e43);
                float t_1 = ((_e44 * _e35) * unscale);
                float3 _e48 = e;
                e = (_e48 + (l.intensity * t_1));
                uint _e53 = kept;
                kept = (_e53 + 1u);
            }
        }
    }
    count_add(COUNT_TESTED, count);
    return;
}

void list_shade()
{
    GroupMemoryBarrierWithGroupSync();
    uint _e2 = quarter;
    uint _e4; InterlockedOr(quarter_count[min(uint(_e2), 3u)], 0, _e4);
    uint _e6 = quarter;
    shade_list(_e4, (_e6 * QUARTER_LIGHTS));
    return;
}

GpuBox ConstructGpuBox(float3 arg0, float arg1, float3 arg2, float arg3) {
    GpuBox ret = (GpuBox)0;
    ret.lo = arg0;
    ret.pad0_ = arg1;
    ret.hi = arg2;
    ret.pad1_ = arg3;
    return ret;
}

void cull_tile(uint li_10, float3 lo_2, float3 hi_2, uint4 grid, uint clusters_at, uint groups_at)
{
    uint g_2 = 0u;
    uint h = (uint)0;

    list_clear(li_10);
    const uint _e10 = group_count(grid.x, grid.y, grid.z, grid.w);
    count_tests(li_10, COUNT_GROUP_TESTS, _e10);
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e87 = g_2;
            g_2 = (_e87 + 1u);
        }
        loop_init_4 = false;
        uint _e14 = g_2;
        if ((_e14 < _e10)) {
        } else {
            break;
        }
        {
            uint _e17 = g_2;
            GpuBox gb = ConstructGpuBox(asfloat(boxes.Load3((groups_at + _e17)*32+0)), asfloat(boxes.Load((groups_at + _e17)*32+12)), asfloat(boxes.Load3((groups_at + _e17)*32+16)), asfloat(boxes.Load((groups_at + _e17)*32+28)));
            const bool _e23 = box_overlaps_box(gb.lo, gb.hi, lo_2, hi_2);
            if (!(_e23)) {
                continue;
            }
            uint _e25 = g_2;
            const uint _e30 = group_first(_e25, grid.x, grid.y, grid.z, grid.w);
            uint first_1 = (clusters_at + _e30);
            uint _e32 = g_2;
            const uint _e37 = group_clusters(_e32, grid.x, grid.y, grid.z, grid.w);
            count_tests(li_10, COUNT_CLUSTER_TESTS, _e37);
            if ((li_10 == 0u)) {
                { uint dummy_3 = 0; InterlockedExchange(hit_count, 0u, dummy_3); }
            }
            GroupMemoryBarrierWithGroupSync();
            if ((li_10 < _e37)) {
                GpuBox cb = ConstructGpuBox(asfloat(boxes.Load3((first_1 + li_10)*32+0)), asfloat(boxes.Load((first_1 + li_10)*32+12)), asfloat(boxes.Load3((first_1 + li_10)*32+16)), asfloat(boxes.Load((first_1 + li_10)*32+28)));
                const bool _e50 = box_overlaps_box(cb.lo, cb.hi, lo_2, hi_2);
                if (_e50) {
                    uint _e54; InterlockedAdd(hit_count, 1u, _e54);
                    cluster_hits[min(uint(_e54), 63u)] = (first_1 + li_10);
                }
            }
            GroupMemoryBarrierWithGroupSync();
            uint _e58 = hit_count;
            GroupMemoryBarrierWithGroupSync();
            h = 0u;
            uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e84 = h;
                    h = (_e84 + 1u);
                }
                loop_init_5 = false;
                uint _e61 = h;
                if ((_e61 < _e58)) {
                } else {
                    break;
                }
                {
                    const bool _e63 = list_full();
                    if (_e63) {
                        list_shade();
                        GroupMemoryBarrierWithGroupSync();
                        list_clear(li_10);
                        GroupMemoryBarrierWithGroupSync();
                    }
                    uint _e65 = h;
                    uint _e67 = cluster_hits[min(uint(_e65), 63u)];
                    const uint _e68 = cluster_slot(_e67, li_10);
                    GpuLight l_1 = ConstructGpuLight(asfloat(lights.Load3(_e68*64+0)), asuint(lights.Load(_e68*64+12)), asfloat(lights.Load3(_e68*64+16)), asfloat(lights.Load(_e68*64+28)), asfloat(lights.Load3(_e68*64+32)), asfloat(lights.Load(_e68*64+44)), asfloat(lights.Load3(_e68*64+48)), asuint(lights.Load(_e68*64+60)));
                    if (any((l_1.intensity != (0.0).xxx))) {
                        count_one(COUNT_SPHERE_TESTS);
                        const float _e78 = cull_r2_of(_e68);
                        const float _e79 = cull_radius(_e78);
                        const bool _e81 = sphere_overlaps_aabb(l_1.p0_, _e79, lo_2, hi_2);
                        if (_e81) {
                            list_add(_e68, l_1.p0_, _e79);
                        }
                    }
                }
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    list_shade();
    return;
}

[numthreads(8, 8, 1)]
void main(uint3 wg : SV_GroupID, uint3 lid : SV_GroupThreadID, uint li : SV_GroupIndex)
{
    if (li == 0) {
        wg_lo = (float3[64])0;
        wg_hi = (float3[64])0;
        wg_box = (WorkgroupBox)0;
        wg_counts = (uint[7])0;
        quarter_lo = (float3[4])0;
        quarter_hi = (float3[4])0;
        quarter_lights = (uint[1024])0;
        quarter_count = (uint[4])0;
        fullest = (uint)0;
        cluster_hits = (uint[64])0;
        hit_count = (uint)0;
    }
    GroupMemoryBarrierWithGroupSync();
    bool local = (bool)0;

    uint px = ((wg.x * TILE) + lid.x);
    uint py = ((wg.y * TILE) + lid.y);
    uint _e15 = params.width;
    if ((px < _e15)) {
        uint _e21 = params.height;
        local = (py < _e21);
    } else {
        local = false;
    }
    bool inside_1 = local;
    uint _e27 = params.width;
    uint pix_1 = ((py * _e27) + px);
    const WorkgroupBox _e30 = load_receiver(li, pix_1, inside_1);
    const bool _e31 = box_is_empty(_e30);
    if (!(_e31)) {
        quarter_boxes(li, lid);
        count_tests(li, COUNT_TILES, 1u);
        uint4 _e39 = params.near_grid;
        uint _e42 = params.near_clusters_at;
        uint _e45 = params.near_groups_at;
        cull_tile(li, _e30.lo, _e30.hi, _e39, _e42, _e45);
    }
    count_receiver(li);
    bool _e47 = valid;
    if (_e47) {
        float4 old = asfloat(irradiance.Load4(pix_1*16));
        float3 _e55 = e;
        uint _e59 = kept;
        irradiance.Store4(pix_1*16, asuint(float4((old.xyz + _e55), (old.w + float(_e59)))));
        return;
    } else {
        return;
    }
}
