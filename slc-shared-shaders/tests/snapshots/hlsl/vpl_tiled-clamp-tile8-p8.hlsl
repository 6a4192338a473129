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
    uint subset_shift;
    uint pad1_;
};

struct ViewParams {
    float4 c0_;
    float4 c1_;
    float4 c2_;
    float4 c3_;
    float3 eye;
    uint width;
    uint height;
    uint pad0_;
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
static const float MAX_INTENSITY = 7.2057594e16;
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
cbuffer params : register(b0) { VplParams params; }
cbuffer view : register(b1) { ViewParams view; }
Texture2D<float4> position_tex : register(t2);
Texture2D<float4> normal_tex : register(t3);
ByteAddressBuffer lights : register(t4);
ByteAddressBuffer r2_1 : register(t6);
RWByteAddressBuffer irradiance : register(u7);
groupshared uint tile_count;
groupshared uint tile_lights[1024];

bool clamp_keep(float range2_, float d2_)
{
    return (d2_ < range2_);
}

float cull_radius(float r2_)
{
    return (sqrt(r2_) * CULL_RADIUS_SCALE);
}

bool sphere_overlaps_aabb(float3 c, float r, float3 bmin, float3 bmax)
{
    float3 q = clamp(c, bmin, bmax);
    float3 v_1 = (q - c);
    return (dot(v_1, v_1) <= (r * r));
}

float vpl_transfer(float3 n_l, float3 n_x, float3 v, float min_d2_)
{
    float m = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m * m));
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint shifted_subset(uint pixel_class, uint shift, uint period)
{
    return naga_mod((pixel_class + shift), (period * period));
}

float vpl_near_weight(float d2_1, float near_r2_)
{
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t = clamp(((near_r2_ - d2_1) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t * t) * (3.0 - (2.0 * t)));
}

float vpl_far_weight(float d2_2, float near_r2_1)
{
    const float _e2 = vpl_near_weight(d2_2, near_r2_1);
    return (1.0 - _e2);
}

float vpl_far_fixed_share(float range2_1, float d2_3, float near_r2_2)
{
    const float _e3 = vpl_far_weight(d2_3, near_r2_2);
    const bool _e4 = clamp_keep(range2_1, d2_3);
    return ((_e4 & (_e3 > 0.0)) ? _e3 : 0.0);
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

float4 surface_at(int2 texel)
{
    float4 p_1 = position_tex.Load(int3(texel, int(0)));
    return ((p_1.w > 0.0) ? float4(p_1.xyz, 1.0) : (0.0).xxxx);
}

GbTexel ConstructGbTexel(float4 arg0, float4 arg1) {
    GbTexel ret = (GbTexel)0;
    ret.position = arg0;
    ret.normal = arg1;
    return ret;
}

GbTexel gbuffer_at(uint i)
{
    bool local_2 = (bool)0;

    uint _e3 = view.width;
    uint _e8 = view.width;
    int2 texel_1 = int2(int(naga_mod(i, _e3)), int(naga_div(i, _e8)));
    const float4 _e12 = surface_at(texel_1);
    float4 _e15 = normal_tex.Load(int3(texel_1, int(0)));
    float3 n = _e15.xyz;
    float len2_ = dot(n, n);
    if ((_e12.w > 0.0)) {
        local_2 = (len2_ > 0.0);
    } else {
        local_2 = false;
    }
    bool valid = local_2;
    float3 _e30 = view.eye;
    float3 v_2 = (_e12.xyz - _e30);
    float4 position = float4(_e12.xyz, (valid ? 1.0 : 0.0));
    float4 normal = (valid ? float4((n / (sqrt(len2_)).xxx), sqrt(dot(v_2, v_2))) : float4(0.0, 0.0, 0.0, 1e30));
    const GbTexel gbtexel = ConstructGbTexel(position, normal);
    return gbtexel;
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
        const GbTexel _e47 = gbuffer_at(pix);
        pos = _e47.position;
        nrm = _e47.normal.xyz;
    }
    if (inside) {
        float _e54 = pos.w;
        local_1 = (_e54 > 0.0);
    } else {
        local_1 = false;
    }
    bool valid_1 = local_1;
    float4 _e59 = pos;
    const WorkgroupBox _e61 = workgroup_box(li, _e59.xyz, valid_1);
    float3 lo = _e61.lo;
    float3 hi = _e61.hi;
    uint _e66 = params.subset_shift;
    const uint _e68 = shifted_subset(sub, _e66, P);
    uint _e71 = params.lights_per_subset;
    uint base = (_e68 * _e71);
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e172 = first;
            first = (_e172 + MAX_TILE_LIGHTS);
        }
        loop_init_1 = false;
        uint _e80 = first;
        uint _e83 = params.lights_per_subset;
        if ((_e80 < _e83)) {
        } else {
            break;
        }
        {
            uint _e85 = first;
            uint _e90 = params.lights_per_subset;
            uint end = min((_e85 + MAX_TILE_LIGHTS), _e90);
            if ((li == 0u)) {
                { uint dummy = 0; InterlockedExchange(tile_count, 0u, dummy); }
            }
            GroupMemoryBarrierWithGroupSync();
            uint _e96 = first;
            j = (_e96 + li);
            uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
                loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e122 = j;
                    j = (_e122 + THREADS);
                }
                loop_init_2 = false;
                uint _e99 = j;
                if ((_e99 < end)) {
                } else {
                    break;
                }
                {
                    uint _e102 = j;
                    float3 _e106 = asfloat(lights.Load3(0+(base + _e102)*64));
                    uint _e108 = j;
                    float _e111 = asfloat(r2_1.Load((base + _e108)*4));
                    const float _e112 = cull_radius(_e111);
                    const bool _e113 = sphere_overlaps_aabb(_e106, _e112, lo, hi);
                    if (_e113) {
                        uint _e116; InterlockedAdd(tile_count, 1u, _e116);
                        if ((_e116 < MAX_TILE_LIGHTS)) {
                            uint _e121 = j;
                            tile_lights[min(uint(_e116), 1023u)] = _e121;
                        }
                    }
                }
            }
            GroupMemoryBarrierWithGroupSync();
            uint _e126 = tile_count;
            GroupMemoryBarrierWithGroupSync();
            uint count = min(_e126, MAX_TILE_LIGHTS);
            if (valid_1) {
                k = 0u;
                uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
                bool loop_init_3 = true;
                while(true) {
                    if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
                    loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                    if (!loop_init_3) {
                        uint _e170 = k;
                        k = (_e170 + 1u);
                    }
                    loop_init_3 = false;
                    uint _e131 = k;
                    if ((_e131 < count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e134 = k;
                        uint _e136 = tile_lights[min(uint(_e134), 1023u)];
                        uint j_1 = (base + _e136);
                        GpuLight l = ConstructGpuLight(asfloat(lights.Load3(j_1*64+0)), asuint(lights.Load(j_1*64+12)), asfloat(lights.Load3(j_1*64+16)), asfloat(lights.Load(j_1*64+28)), asfloat(lights.Load3(j_1*64+32)), asfloat(lights.Load(j_1*64+44)), asfloat(lights.Load3(j_1*64+48)), asuint(lights.Load(j_1*64+60)));
                        float4 _e141 = pos;
                        float3 v_3 = (_e141.xyz - l.p0_);
                        float _e147 = asfloat(r2_1.Load(j_1*4));
                        float _e151 = params.near_r2_;
                        const float _e152 = vpl_far_fixed_share(_e147, dot(v_3, v_3), _e151);
                        if ((_e152 > 0.0)) {
                            float3 _e156 = nrm;
                            float _e159 = params.min_d2_;
                            const float _e160 = vpl_transfer(l.p1_, _e156, v_3, _e159);
                            float t_1 = (_e160 * _e152);
                            float3 _e162 = e;
                            e = (_e162 + (l.intensity * t_1));
                            uint _e166 = kept;
                            kept = (_e166 + 1u);
                        }
                    }
                }
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    if (inside) {
        float3 _e177 = e;
        uint _e178 = kept;
        irradiance.Store4(pix*16, asuint(float4(_e177, float(_e178))));
        return;
    } else {
        return;
    }
}
