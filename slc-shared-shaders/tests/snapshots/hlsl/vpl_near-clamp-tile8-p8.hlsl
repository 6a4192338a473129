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

struct GpuNearBox {
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
static const uint NEAR_CHUNK = 32u;

groupshared float3 wg_lo[64];
groupshared float3 wg_hi[64];
cbuffer params : register(b0) { VplParams params; }
cbuffer view : register(b1) { ViewParams view; }
Texture2D<float4> position_tex : register(t2);
Texture2D<float4> normal_tex : register(t3);
ByteAddressBuffer lights : register(t4);
ByteAddressBuffer near_slots : register(t5);
ByteAddressBuffer near_boxes : register(t6);
ByteAddressBuffer r2_2 : register(t8);
RWByteAddressBuffer irradiance : register(u9);
groupshared uint light_count;
groupshared uint light_list[2048];

float to_f32_(uint u)
{
    return float(u);
}

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
    float m_2 = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m_2 * m_2));
}

float interleave_flux_scale(uint period)
{
    const float _e2 = to_f32_((period * period));
    return _e2;
}

float vpl_near_weight(float d2_1, float near_r2_)
{
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t = clamp(((near_r2_ - d2_1) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t * t) * (3.0 - (2.0 * t)));
}

float vpl_near_cull_range2_(float r2_1, float near_r2_1)
{
    return min(r2_1, near_r2_1);
}

float vpl_near_fixed_share(float range2_1, float d2_2, float near_r2_2)
{
    const float _e3 = vpl_near_weight(d2_2, near_r2_2);
    const bool _e4 = clamp_keep(range2_1, d2_2);
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

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

GbTexel ConstructGbTexel(float4 arg0, float4 arg1) {
    GbTexel ret = (GbTexel)0;
    ret.position = arg0;
    ret.normal = arg1;
    return ret;
}

GbTexel gbuffer_at(uint i)
{
    bool local_5 = (bool)0;

    uint _e3 = view.width;
    uint _e8 = view.width;
    int2 texel_1 = int2(int(naga_mod(i, _e3)), int(naga_div(i, _e8)));
    const float4 _e12 = surface_at(texel_1);
    float4 _e15 = normal_tex.Load(int3(texel_1, int(0)));
    float3 n = _e15.xyz;
    float len2_ = dot(n, n);
    if ((_e12.w > 0.0)) {
        local_5 = (len2_ > 0.0);
    } else {
        local_5 = false;
    }
    bool valid = local_5;
    float3 _e30 = view.eye;
    float3 v_2 = (_e12.xyz - _e30);
    float4 position = float4(_e12.xyz, (valid ? 1.0 : 0.0));
    float4 normal = (valid ? float4((n / (sqrt(len2_)).xxx), sqrt(dot(v_2, v_2))) : float4(0.0, 0.0, 0.0, 1e30));
    const GbTexel gbtexel = ConstructGbTexel(position, normal);
    return gbtexel;
}

float near_r2_of(uint slot)
{
    float _e3 = asfloat(r2_2.Load(slot*4));
    return _e3;
}

GpuNearBox ConstructGpuNearBox(float3 arg0, float arg1, float3 arg2, float arg3) {
    GpuNearBox ret = (GpuNearBox)0;
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

[numthreads(8, 8, 1)]
void main(uint3 wg : SV_GroupID, uint3 lid : SV_GroupThreadID, uint li : SV_GroupIndex)
{
    if (li == 0) {
        wg_lo = (float3[64])0;
        wg_hi = (float3[64])0;
        light_count = (uint)0;
        light_list = (uint[2048])0;
    }
    GroupMemoryBarrierWithGroupSync();
    bool local = (bool)0;
    float4 pos = (0.0).xxxx;
    float3 nrm = (0.0).xxx;
    bool local_1 = (bool)0;
    float3 e = (0.0).xxx;
    uint kept = 0u;
    uint first = 0u;
    bool local_2 = (bool)0;
    bool local_3 = (bool)0;
    uint m = (uint)0;
    bool local_4 = (bool)0;
    uint m_1 = (uint)0;

    uint px = ((wg.x * TILE) + lid.x);
    uint py = ((wg.y * TILE) + lid.y);
    uint _e15 = params.width;
    if ((px < _e15)) {
        uint _e21 = params.height;
        local = (py < _e21);
    } else {
        local = false;
    }
    bool inside = local;
    uint _e27 = params.width;
    uint pix = ((py * _e27) + px);
    if (inside) {
        const GbTexel _e36 = gbuffer_at(pix);
        pos = _e36.position;
        nrm = _e36.normal.xyz;
    }
    if (inside) {
        float _e43 = pos.w;
        local_1 = (_e43 > 0.0);
    } else {
        local_1 = false;
    }
    bool valid_1 = local_1;
    float4 _e48 = pos;
    const WorkgroupBox _e50 = workgroup_box(li, _e48.xyz, valid_1);
    float3 lo = _e50.lo;
    float3 hi = _e50.hi;
    float _e55 = params.near_r2_;
    const float _e56 = cull_radius(_e55);
    const float _e58 = interleave_flux_scale(P);
    float unscale = (1.0 / _e58);
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e191 = first;
            first = (_e191 + NEAR_CHUNK);
        }
        loop_init_1 = false;
        uint _e68 = first;
        uint _e71 = params.near_blocks;
        if ((_e68 < _e71)) {
        } else {
            break;
        }
        {
            if ((li == 0u)) {
                { uint dummy = 0; InterlockedExchange(light_count, 0u, dummy); }
            }
            GroupMemoryBarrierWithGroupSync();
            uint _e77 = first;
            uint b = (_e77 + li);
            if ((li < NEAR_CHUNK)) {
                uint _e85 = params.near_blocks;
                local_2 = (b < _e85);
            } else {
                local_2 = false;
            }
            bool _e88 = local_2;
            if (_e88) {
                GpuNearBox nb = ConstructGpuNearBox(asfloat(near_boxes.Load3(b*32+0)), asfloat(near_boxes.Load(b*32+12)), asfloat(near_boxes.Load3(b*32+16)), asfloat(near_boxes.Load(b*32+28)));
                if (all(((nb.lo - (_e56).xxx) <= hi))) {
                    local_3 = all((lo <= (nb.hi + (_e56).xxx)));
                } else {
                    local_3 = false;
                }
                bool _e105 = local_3;
                if (_e105) {
                    m = 0u;
                    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
                    bool loop_init_2 = true;
                    while(true) {
                        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
                        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                        if (!loop_init_2) {
                            uint _e144 = m;
                            m = (_e144 + 1u);
                        }
                        loop_init_2 = false;
                        uint _e108 = m;
                        if ((_e108 < NEAR_BLOCK)) {
                        } else {
                            break;
                        }
                        {
                            uint _e114 = m;
                            uint slot_1 = asuint(near_slots.Load(((b * NEAR_BLOCK) + _e114)*4));
                            GpuLight l = ConstructGpuLight(asfloat(lights.Load3(slot_1*64+0)), asuint(lights.Load(slot_1*64+12)), asfloat(lights.Load3(slot_1*64+16)), asfloat(lights.Load(slot_1*64+28)), asfloat(lights.Load3(slot_1*64+32)), asfloat(lights.Load(slot_1*64+44)), asfloat(lights.Load3(slot_1*64+48)), asuint(lights.Load(slot_1*64+60)));
                            const float _e121 = near_r2_of(slot_1);
                            float _e124 = params.near_r2_;
                            const float _e125 = vpl_near_cull_range2_(_e121, _e124);
                            const float _e126 = cull_radius(_e125);
                            if (any((l.intensity != (0.0).xxx))) {
                                const bool _e135 = sphere_overlaps_aabb(l.p0_, _e126, lo, hi);
                                local_4 = _e135;
                            } else {
                                local_4 = false;
                            }
                            bool _e137 = local_4;
                            if (_e137) {
                                uint _e141; InterlockedAdd(light_count, 1u, _e141);
                                light_list[min(uint(_e141), 2047u)] = slot_1;
                            }
                        }
                    }
                }
            }
            GroupMemoryBarrierWithGroupSync();
            uint _e147 = light_count;
            GroupMemoryBarrierWithGroupSync();
            if (valid_1) {
                m_1 = 0u;
                uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
                bool loop_init_3 = true;
                while(true) {
                    if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
                    loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                    if (!loop_init_3) {
                        uint _e189 = m_1;
                        m_1 = (_e189 + 1u);
                    }
                    loop_init_3 = false;
                    uint _e150 = m_1;
                    if ((_e150 < _e147)) {
                    } else {
                        break;
                    }
                    {
                        uint _e153 = m_1;
                        uint slot_2 = light_list[min(uint(_e153), 2047u)];
                        GpuLight l_1 = ConstructGpuLight(asfloat(lights.Load3(slot_2*64+0)), asuint(lights.Load(slot_2*64+12)), asfloat(lights.Load3(slot_2*64+16)), asfloat(lights.Load(slot_2*64+28)), asfloat(lights.Load3(slot_2*64+32)), asfloat(lights.Load(slot_2*64+44)), asfloat(lights.Load3(slot_2*64+48)), asuint(lights.Load(slot_2*64+60)));
                        float4 _e159 = pos;
                        float3 v_3 = (_e159.xyz - l_1.p0_);
                        float _e165 = asfloat(r2_2.Load(slot_2*4));
                        float _e169 = params.near_r2_;
                        const float _e170 = vpl_near_fixed_share(_e165, dot(v_3, v_3), _e169);
                        if ((_e170 > 0.0)) {
                            float3 _e174 = nrm;
                            float _e177 = params.min_d2_;
                            const float _e178 = vpl_transfer(l_1.p1_, _e174, v_3, _e177);
                            float t_1 = ((_e178 * _e170) * unscale);
                            float3 _e181 = e;
                            e = (_e181 + (l_1.intensity * t_1));
                            uint _e185 = kept;
                            kept = (_e185 + 1u);
                        }
                    }
                }
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    if (valid_1) {
        float4 old = asfloat(irradiance.Load4(pix*16));
        float3 _e200 = e;
        uint _e203 = kept;
        irradiance.Store4(pix*16, asuint(float4((old.xyz + _e200), (old.w + float(_e203)))));
        return;
    } else {
        return;
    }
}
