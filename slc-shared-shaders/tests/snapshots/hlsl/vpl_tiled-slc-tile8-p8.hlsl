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
    uint near_blocks;
    uint pad0_;
    uint pad1_;
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
static const uint P = 8u;
static const uint TILE = 8u;
static const uint THREADS = 64u;
static const uint BOX_THREADS = 64u;
static const uint MAX_TILE_LIGHTS = 1024u;

groupshared float3 wg_lo[64];
groupshared float3 wg_hi[64];
cbuffer params : register(b0) { VplParams params; }
ByteAddressBuffer gb_position : register(t1);
ByteAddressBuffer gb_normal : register(t2);
ByteAddressBuffer lights : register(t3);
ByteAddressBuffer rt2_2 : register(t4);
ByteAddressBuffer r2_3 : register(t5);
RWByteAddressBuffer irradiance : register(u6);
groupshared uint tile_count;
groupshared uint tile_lights[1024];

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

float vpl_transfer(float3 n_l, float3 n_x, float3 v, float min_d2_)
{
    float m = max(dot(v, v), min_d2_);
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m * m));
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

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

WorkgroupBox ConstructWorkgroupBox(float3 arg0, float3 arg1) {
    WorkgroupBox ret = (WorkgroupBox)0;
    ret.lo = arg0;
    ret.hi = arg1;
    return ret;
}

WorkgroupBox workgroup_box(uint li_1, float3 p, bool has)
{
    uint stride = 32u;

    wg_lo[min(uint(li_1), 63u)] = (has ? p : (3.4028235e38).xxx);
    wg_hi[min(uint(li_1), 63u)] = (has ? p : (-3.4028235e38).xxx);
    GroupMemoryBarrierWithGroupSync();
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e42 = stride;
            stride = naga_div(_e42, 2u);
        }
        loop_init = false;
        uint _e15 = stride;
        if ((_e15 > 0u)) {
        } else {
            break;
        }
        {
            uint _e18 = stride;
            if ((li_1 < _e18)) {
                float3 _e24 = wg_lo[min(uint(li_1), 63u)];
                uint _e26 = stride;
                float3 _e29 = wg_lo[min(uint((li_1 + _e26)), 63u)];
                wg_lo[min(uint(li_1), 63u)] = min(_e24, _e29);
                float3 _e35 = wg_hi[min(uint(li_1), 63u)];
                uint _e37 = stride;
                float3 _e40 = wg_hi[min(uint((li_1 + _e37)), 63u)];
                wg_hi[min(uint(li_1), 63u)] = max(_e35, _e40);
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    float3 _e47 = wg_lo[0];
    float3 _e50 = wg_hi[0];
    const WorkgroupBox workgroupbox = ConstructWorkgroupBox(_e47, _e50);
    return workgroupbox;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
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

[numthreads(8, 8, 1)]
void main(uint3 wg : SV_GroupID, uint3 lid : SV_GroupThreadID, uint li : SV_GroupIndex)
{
    if (li == 0) {
        wg_lo = (float3[64])0;
        wg_hi = (float3[64])0;
        tile_count = (uint)0;
        tile_lights = (uint[1024])0;
    }
    GroupMemoryBarrierWithGroupSync();
    bool local = (bool)0;
    float4 pos = (0.0).xxxx;
    float3 nrm = (0.0).xxx;
    bool local_1 = (bool)0;
    float3 e = (0.0).xxx;
    uint kept = 0u;
    uint first = 0u;
    uint j = (uint)0;
    uint k = (uint)0;

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
    bool inside = local;
    uint _e38 = params.width;
    uint pix = ((py * _e38) + px);
    if (inside) {
        float4 _e49 = asfloat(gb_position.Load4(pix*16));
        pos = _e49;
        float4 _e52 = asfloat(gb_normal.Load4(pix*16));
        nrm = _e52.xyz;
    }
    if (inside) {
        float _e57 = pos.w;
        local_1 = (_e57 > 0.0);
    } else {
        local_1 = false;
    }
    bool valid = local_1;
    float4 _e62 = pos;
    const WorkgroupBox _e64 = workgroup_box(li, _e62.xyz, valid);
    float3 lo = _e64.lo;
    float3 hi = _e64.hi;
    uint _e69 = params.lights_per_subset;
    uint base = (sub * _e69);
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e173 = first;
            first = (_e173 + MAX_TILE_LIGHTS);
        }
        loop_init_1 = false;
        uint _e78 = first;
        uint _e81 = params.lights_per_subset;
        if ((_e78 < _e81)) {
        } else {
            break;
        }
        {
            uint _e83 = first;
            uint _e88 = params.lights_per_subset;
            uint end = min((_e83 + MAX_TILE_LIGHTS), _e88);
            if ((li == 0u)) {
                { uint dummy = 0; InterlockedExchange(tile_count, 0u, dummy); }
            }
            GroupMemoryBarrierWithGroupSync();
            uint _e94 = first;
            j = (_e94 + li);
            uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
                loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e120 = j;
                    j = (_e120 + THREADS);
                }
                loop_init_2 = false;
                uint _e97 = j;
                if ((_e97 < end)) {
                } else {
                    break;
                }
                {
                    uint _e100 = j;
                    float3 _e104 = asfloat(lights.Load3(0+(base + _e100)*64));
                    uint _e106 = j;
                    float _e109 = asfloat(r2_3.Load((base + _e106)*4));
                    const float _e110 = cull_radius(_e109);
                    const bool _e111 = sphere_overlaps_aabb(_e104, _e110, lo, hi);
                    if (_e111) {
                        uint _e114; InterlockedAdd(tile_count, 1u, _e114);
                        if ((_e114 < MAX_TILE_LIGHTS)) {
                            uint _e119 = j;
                            tile_lights[min(uint(_e114), 1023u)] = _e119;
                        }
                    }
                }
            }
            GroupMemoryBarrierWithGroupSync();
            uint _e124 = tile_count;
            GroupMemoryBarrierWithGroupSync();
            uint count = min(_e124, MAX_TILE_LIGHTS);
            if (valid) {
                k = 0u;
                uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
                bool loop_init_3 = true;
                while(true) {
                    if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
                    loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                    if (!loop_init_3) {
                        uint _e171 = k;
                        k = (_e171 + 1u);
                    }
                    loop_init_3 = false;
                    uint _e129 = k;
                    if ((_e129 < count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e132 = k;
                        uint _e134 = tile_lights[min(uint(_e132), 1023u)];
                        uint j_1 = (base + _e134);
                        GpuLight l = ConstructGpuLight(asfloat(lights.Load3(j_1*64+0)), asuint(lights.Load(j_1*64+12)), asfloat(lights.Load3(j_1*64+16)), asfloat(lights.Load(j_1*64+28)), asfloat(lights.Load3(j_1*64+32)), asfloat(lights.Load(j_1*64+44)), asfloat(lights.Load3(j_1*64+48)), asuint(lights.Load(j_1*64+60)));
                        float4 _e139 = pos;
                        float3 v_2 = (_e139.xyz - l.p0_);
                        float _e145 = asfloat(rt2_2.Load(j_1*4));
                        float _e148 = asfloat(r2_3.Load(j_1*4));
                        float _e152 = params.near_r2_;
                        const float _e153 = vpl_far_slc_share(_e145, _e148, dot(v_2, v_2), _e152);
                        if ((_e153 > 0.0)) {
                            float3 _e156 = e;
                            float3 _e159 = nrm;
                            float _e162 = params.min_d2_;
                            const float _e163 = vpl_transfer(l.p1_, _e159, v_2, _e162);
                            e = (_e156 + (l.intensity * (_e163 * _e153)));
                            uint _e167 = kept;
                            kept = (_e167 + 1u);
                        }
                    }
                }
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    if (valid) {
        float3 _e178 = e;
        uint _e179 = kept;
        irradiance.Store4(pix*16, asuint(float4(_e178, float(_e179))));
        return;
    } else {
        return;
    }
}
