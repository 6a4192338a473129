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
static const uint MAX_TILE_LIGHTS = 1024u;

groupshared float3 wg_lo[64];
groupshared float3 wg_hi[64];
groupshared WorkgroupBox wg_box;
cbuffer params : register(b0) { VplParams params; }
cbuffer view : register(b1) { ViewParams view; }
Texture2D<float4> position_tex : register(t2);
Texture2D<float4> normal_tex : register(t3);
ByteAddressBuffer lights : register(t4);
ByteAddressBuffer rt2_2 : register(t5);
ByteAddressBuffer r2_3 : register(t6);
ByteAddressBuffer boxes : register(t7);
RWByteAddressBuffer irradiance : register(u8);
RWByteAddressBuffer guide : register(u9);
static float3 pos = (float3)0;
static float3 nrm = (float3)0;
static float eye_distance = (float)0;
static bool valid = (bool)0;
static float3 e = (float3)0;
static uint kept = (uint)0;
groupshared uint tile_lights[1024];
groupshared uint list_count;
groupshared uint cluster_hits[64];
groupshared uint hit_count;

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
    float3 q = clamp(c, bmin, bmax);
    float3 v_1 = (q - c);
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
    float m = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m * m));
}

uint shifted_subset(uint pixel_class, uint shift, uint period)
{
    return naga_mod((pixel_class + shift), (period * period));
}

float vpl_near_weight(float d2_2, float near_r2_)
{
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t = clamp(((near_r2_ - d2_2) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t * t) * (3.0 - (2.0 * t)));
}

float vpl_far_weight(float d2_3, float near_r2_1)
{
    const float _e2 = vpl_near_weight(d2_3, near_r2_1);
    return (1.0 - _e2);
}

float vpl_far_slc_share(float rt2_1, float r2_2, float d2_4, float near_r2_2)
{
    const float _e4 = vpl_far_weight(d2_4, near_r2_2);
    const float _e5 = slc_weight(rt2_1, d2_4);
    const bool _e7 = slc_keep(r2_2, d2_4);
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
    float4 p_4 = position_tex.Load(int3(texel, int(0)));
    return ((p_4.w > 0.0) ? float4(p_4.xyz, 1.0) : (0.0).xxxx);
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
    float3 n = _e15.xyz;
    float len2_ = dot(n, n);
    if ((_e12.w > 0.0)) {
        local_6 = (len2_ > 0.0);
    } else {
        local_6 = false;
    }
    bool valid_1 = local_6;
    float3 _e30 = view.eye;
    float3 v_2 = (_e12.xyz - _e30);
    float4 position = float4(_e12.xyz, (valid_1 ? 1.0 : 0.0));
    float4 normal = (valid_1 ? float4((n / (sqrt(len2_)).xxx), sqrt(dot(v_2, v_2))) : float4(0.0, 0.0, 0.0, 1e30));
    const GbTexel gbtexel = ConstructGbTexel(position, normal);
    return gbtexel;
}

WorkgroupBox load_receiver(uint li_3, uint pix, bool inside)
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
    float3 _e29 = pos;
    bool _e31 = valid;
    const WorkgroupBox _e32 = workgroup_box(li_3, _e29, _e31);
    const WorkgroupBox workgroupbox_3 = _e32;
    return workgroupbox_3;
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

void shade_light(uint j)
{
    GpuLight l = ConstructGpuLight(asfloat(lights.Load3(j*64+0)), asuint(lights.Load(j*64+12)), asfloat(lights.Load3(j*64+16)), asfloat(lights.Load(j*64+28)), asfloat(lights.Load3(j*64+32)), asfloat(lights.Load(j*64+44)), asfloat(lights.Load3(j*64+48)), asuint(lights.Load(j*64+60)));
    float3 _e5 = pos;
    float3 v_3 = (_e5 - l.p0_);
    float _e10 = asfloat(rt2_2.Load(j*4));
    float _e13 = asfloat(r2_3.Load(j*4));
    float _e17 = params.near_r2_;
    const float _e18 = vpl_far_slc_share(_e10, _e13, dot(v_3, v_3), _e17);
    if ((_e18 > 0.0)) {
        float3 _e23 = nrm;
        float _e26 = params.min_d2_;
        const float _e27 = vpl_transfer(l.p1_, _e23, v_3, _e26);
        float t_1 = (_e27 * _e18);
        float3 _e30 = e;
        e = (_e30 + (l.intensity * t_1));
        uint _e35 = kept;
        kept = (_e35 + 1u);
        return;
    } else {
        return;
    }
}

uint cluster_slot(uint c_1, uint k)
{
    return ((c_1 * CLUSTER) + k);
}

float cull_r2_of(uint slot)
{
    float _e3 = asfloat(r2_3.Load(slot*4));
    return _e3;
}

void shade_list(uint count)
{
    uint k_1 = 0u;

    bool _e2 = valid;
    if (_e2) {
        uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
            loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e12 = k_1;
                k_1 = (_e12 + 1u);
            }
            loop_init_1 = false;
            uint _e5 = k_1;
            if ((_e5 < count)) {
            } else {
                break;
            }
            {
                uint _e8 = k_1;
                uint _e10 = tile_lights[min(uint(_e8), 1023u)];
                shade_light(_e10);
            }
        }
        return;
    } else {
        return;
    }
}

void list_clear(uint li_4)
{
    if ((li_4 == 0u)) {
        { uint dummy = 0; InterlockedExchange(list_count, 0u, dummy); }
        return;
    } else {
        return;
    }
}

bool list_full()
{
    GroupMemoryBarrierWithGroupSync();
    uint _e1 = list_count;
    GroupMemoryBarrierWithGroupSync();
    return ((_e1 + CLUSTER) > MAX_TILE_LIGHTS);
}

void list_add(uint slot_1, float3 p_3, float radius)
{
    uint _e6; InterlockedAdd(list_count, 1u, _e6);
    tile_lights[min(uint(_e6), 1023u)] = slot_1;
    return;
}

void list_shade()
{
    GroupMemoryBarrierWithGroupSync();
    uint _e1 = list_count;
    GroupMemoryBarrierWithGroupSync();
    shade_list(_e1);
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

void cull_tile(uint li_5, float3 lo_1, float3 hi_1, uint4 grid, uint clusters_at, uint groups_at)
{
    uint g_2 = 0u;
    uint h = (uint)0;

    list_clear(li_5);
    const uint _e10 = group_count(grid.x, grid.y, grid.z, grid.w);
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e84 = g_2;
            g_2 = (_e84 + 1u);
        }
        loop_init_2 = false;
        uint _e13 = g_2;
        if ((_e13 < _e10)) {
        } else {
            break;
        }
        {
            uint _e16 = g_2;
            GpuBox gb = ConstructGpuBox(asfloat(boxes.Load3((groups_at + _e16)*32+0)), asfloat(boxes.Load((groups_at + _e16)*32+12)), asfloat(boxes.Load3((groups_at + _e16)*32+16)), asfloat(boxes.Load((groups_at + _e16)*32+28)));
            const bool _e22 = box_overlaps_box(gb.lo, gb.hi, lo_1, hi_1);
            if (!(_e22)) {
                continue;
            }
            uint _e24 = g_2;
            const uint _e29 = group_first(_e24, grid.x, grid.y, grid.z, grid.w);
            uint first = (clusters_at + _e29);
            uint _e31 = g_2;
            const uint _e36 = group_clusters(_e31, grid.x, grid.y, grid.z, grid.w);
            if ((li_5 == 0u)) {
                { uint dummy_1 = 0; InterlockedExchange(hit_count, 0u, dummy_1); }
            }
            GroupMemoryBarrierWithGroupSync();
            if ((li_5 < _e36)) {
                GpuBox cb = ConstructGpuBox(asfloat(boxes.Load3((first + li_5)*32+0)), asfloat(boxes.Load((first + li_5)*32+12)), asfloat(boxes.Load3((first + li_5)*32+16)), asfloat(boxes.Load((first + li_5)*32+28)));
                const bool _e48 = box_overlaps_box(cb.lo, cb.hi, lo_1, hi_1);
                if (_e48) {
                    uint _e52; InterlockedAdd(hit_count, 1u, _e52);
                    cluster_hits[min(uint(_e52), 63u)] = (first + li_5);
                }
            }
            GroupMemoryBarrierWithGroupSync();
            uint _e56 = hit_count;
            GroupMemoryBarrierWithGroupSync();
            h = 0u;
            uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e81 = h;
                    h = (_e81 + 1u);
                }
                loop_init_3 = false;
                uint _e59 = h;
                if ((_e59 < _e56)) {
                } else {
                    break;
                }
                {
                    const bool _e61 = list_full();
                    if (_e61) {
                        list_shade();
                        GroupMemoryBarrierWithGroupSync();
                        list_clear(li_5);
                        GroupMemoryBarrierWithGroupSync();
                    }
                    uint _e63 = h;
                    uint _e65 = cluster_hits[min(uint(_e63), 63u)];
                    const uint _e66 = cluster_slot(_e65, li_5);
                    GpuLight l_1 = ConstructGpuLight(asfloat(lights.Load3(_e66*64+0)), asuint(lights.Load(_e66*64+12)), asfloat(lights.Load3(_e66*64+16)), asfloat(lights.Load(_e66*64+28)), asfloat(lights.Load3(_e66*64+32)), asfloat(lights.Load(_e66*64+44)), asfloat(lights.Load3(_e66*64+48)), asuint(lights.Load(_e66*64+60)));
                    if (any((l_1.intensity != (0.0).xxx))) {
                        const float _e75 = cull_r2_of(_e66);
                        const float _e76 = cull_radius(_e75);
                        const bool _e78 = sphere_overlaps_aabb(l_1.p0_, _e76, lo_1, hi_1);
                        if (_e78) {
                            list_add(_e66, l_1.p0_, _e76);
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
        tile_lights = (uint[1024])0;
        list_count = (uint)0;
        cluster_hits = (uint[64])0;
        hit_count = (uint)0;
    }
    GroupMemoryBarrierWithGroupSync();
    bool local = (bool)0;

    uint sub = wg.z;
    uint px = (naga_mod(sub, P) + (((wg.x * TILE) + lid.x) * P));
    uint py = (naga_div(sub, P) + (((wg.y * TILE) + lid.y) * P));
    uint _e26 = params.width;
    if ((px < _e26)) {
        uint _e32 = params.height;
        local = (py < _e32);
    } else {
        local = false;
    }
    bool inside_1 = local;
    uint _e38 = params.width;
    uint pix_1 = ((py * _e38) + px);
    const WorkgroupBox _e41 = load_receiver(li, pix_1, inside_1);
    uint _e44 = params.subset_shift;
    const uint _e46 = shifted_subset(sub, _e44, P);
    const bool _e47 = box_is_empty(_e41);
    if (!(_e47)) {
        uint4 grid_1 = params.far_grid;
        uint _e56 = params.lights_per_subset;
        uint _e62 = params.far_groups_at;
        const uint _e67 = group_count(grid_1.x, grid_1.y, grid_1.z, grid_1.w);
        cull_tile(li, _e41.lo, _e41.hi, grid_1, (_e46 * naga_div(_e56, CLUSTER)), (_e62 + (_e46 * _e67)));
    }
    if (inside_1) {
        float3 _e73 = e;
        uint _e75 = kept;
        irradiance.Store4(pix_1*16, asuint(float4(_e73, float(_e75))));
        float3 _e81 = nrm;
        float _e83 = eye_distance;
        guide.Store4(pix_1*16, asuint(float4(_e81, _e83)));
        return;
    } else {
        return;
    }
}
