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

struct GpuMaterial {
    float3 albedo;
    float metallic;
    float3 emission;
    float alpha;
    float3 f0_;
    float f90_;
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

struct Glossy {
    GpuMaterial m;
    float3 v;
    bool on;
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
ByteAddressBuffer materials : register(t10);
RWByteAddressBuffer specular : register(u11);
static float3 pos = (float3)0;
static float3 nrm = (float3)0;
static float eye_distance = (float)0;
static bool valid = (bool)0;
static float3 e = (float3)0;
static uint kept = (uint)0;
static float3 s = (float3)0;
static Glossy g_4 = (Glossy)0;
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
    float3 v_6 = (q_1 - c);
    return (dot(v_6, v_6) <= (r * r));
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

float ggx_d(float cos_h, float sin2_h, float alpha)
{
    if ((cos_h <= 0.0)) {
        return 0.0;
    }
    float a2_ = (alpha * alpha);
    float t_1 = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t_1 * t_1));
}

float smith_root(float cos_, float alpha_1)
{
    float a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1.0 - a2_1)) + a2_1));
}

float smith_visibility(float n_l_1, float n_v, float alpha_2)
{
    bool local_6 = (bool)0;

    if (!((n_l_1 <= 0.0))) {
        local_6 = (n_v <= 0.0);
    } else {
        local_6 = true;
    }
    bool _e11 = local_6;
    if (_e11) {
        return 0.0;
    }
    const float _e13 = smith_root(n_v, alpha_2);
    const float _e15 = smith_root(n_l_1, alpha_2);
    return (0.5 / ((n_l_1 * _e13) + (n_v * _e15)));
}

float3 fresnel_schlick(float3 f0_, float f90_, float v_h)
{
    float c_2 = saturate((1.0 - v_h));
    float c2_ = (c_2 * c_2);
    return (f0_ + ((float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_2)));
}

float3 specular_fresnel(float3 base, float metallic, float3 f0_d, float f90_d, float v_h_1)
{
    const float3 _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    const float3 _e10 = fresnel_schlick(base, 1.0, v_h_1);
    return ((_e5 * (1.0 - metallic)) + (_e10 * metallic));
}

float3 diffuse_brdf(float3 base_1, float metallic_1, float3 f0_d_1, float f90_d_1, float v_h_2)
{
    const float3 _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return ((((float3(1.0, 1.0, 1.0) - _e9) * base_1) * (1.0 - metallic_1)) * INV_PI);
}

float half_cosine(float3 v_1, float3 l)
{
    float3 h_2 = (v_1 + l);
    float len2_ = dot(h_2, h_2);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return saturate((dot(v_1, h_2) / sqrt(len2_)));
}

float3 specular_brdf(float3 base_2, float metallic_2, float3 f0_d_2, float f90_d_2, float alpha_3, float3 n, float3 v_2, float3 l_1)
{
    bool local_7 = (bool)0;

    float n_l_2 = dot(n, l_1);
    float n_v_1 = dot(n, v_2);
    if (!((n_l_2 <= 0.0))) {
        local_7 = (n_v_1 <= 0.0);
    } else {
        local_7 = true;
    }
    bool _e18 = local_7;
    if (_e18) {
        return float3(0.0, 0.0, 0.0);
    }
    float3 hs = (v_2 + l_1);
    float inv = (1.0 / sqrt(dot(hs, hs)));
    float3 h_3 = (hs * inv);
    float3 c_3 = cross(n, h_3);
    const float _e32 = ggx_d(dot(n, h_3), dot(c_3, c_3), alpha_3);
    const float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_2, h_3));
    const float _e35 = smith_visibility(n_l_2, n_v_1, alpha_3);
    return (_e34 * (_e32 * _e35));
}

float3 brdf_eval(float3 base_3, float metallic_3, float3 f0_d_3, float f90_d_3, float alpha_4, float3 n_1, float3 v_3, float3 l_2)
{
    if ((dot(n_1, l_2) <= 0.0)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float _e15 = half_cosine(v_3, l_2);
    const float3 _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    const float3 _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_1, v_3, l_2);
    return (_e16 + _e17);
}

float3 diffuse_albedo(float3 base_4, float metallic_4)
{
    return (base_4 * (1.0 - metallic_4));
}

float3 specular_correction(float3 base_5, float metallic_5, float3 f0_d_4, float f90_d_4, float alpha_5, float3 n_2, float3 v_4, float3 l_3)
{
    const float3 _e8 = brdf_eval(base_5, metallic_5, f0_d_4, f90_d_4, alpha_5, n_2, v_4, l_3);
    const float3 _e9 = diffuse_albedo(base_5, metallic_5);
    return (_e8 - (_e9 * INV_PI));
}

bool has_specular(float metallic_6, float3 f0_d_5, float f90_d_5)
{
    bool local_8 = (bool)0;
    bool local_9 = (bool)0;

    if (!((metallic_6 > 0.0))) {
        local_8 = (f90_d_5 > 0.0);
    } else {
        local_8 = true;
    }
    bool _e11 = local_8;
    if (!(_e11)) {
        local_9 = (max(max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0.0);
    } else {
        local_9 = true;
    }
    bool _e23 = local_9;
    return _e23;
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
    float t_2 = clamp(((near_r2_ - d2_2) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t_2 * t_2) * (3.0 - (2.0 * t_2)));
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
    bool local_10 = (bool)0;

    uint _e3 = view.width;
    uint _e8 = view.width;
    int2 texel_1 = int2(int(naga_mod(i, _e3)), int(naga_div(i, _e8)));
    const float4 _e12 = surface_at(texel_1);
    float4 _e15 = normal_tex.Load(int3(texel_1, int(0)));
    float3 n_4 = _e15.xyz;
    float len2_1 = dot(n_4, n_4);
    if ((_e12.w > 0.0)) {
        local_10 = (len2_1 > 0.0);
    } else {
        local_10 = false;
    }
    bool valid_1 = local_10;
    float3 _e30 = view.eye;
    float3 v_7 = (_e12.xyz - _e30);
    float4 position = float4(_e12.xyz, (valid_1 ? 1.0 : 0.0));
    float4 normal = (valid_1 ? float4((n_4 / (sqrt(len2_1)).xxx), sqrt(dot(v_7, v_7))) : float4(0.0, 0.0, 0.0, 1e30));
    const GbTexel gbtexel = ConstructGbTexel(position, normal);
    return gbtexel;
}

Glossy ConstructGlossy(GpuMaterial arg0, float3 arg1, bool arg2) {
    Glossy ret = (Glossy)0;
    ret.m = arg0;
    ret.v = arg1;
    ret.on = arg2;
    return ret;
}

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

GpuMaterial ConstructGpuMaterial(float3 arg0, float arg1, float3 arg2, float arg3, float3 arg4, float arg5) {
    GpuMaterial ret = (GpuMaterial)0;
    ret.albedo = arg0;
    ret.metallic = arg1;
    ret.emission = arg2;
    ret.alpha = arg3;
    ret.f0_ = arg4;
    ret.f90_ = arg5;
    return ret;
}

Glossy glossy_at(uint i_1, float3 x)
{
    uint _e4 = view.width;
    uint _e9 = view.width;
    int2 texel_2 = int2(int(naga_mod(i_1, _e4)), int(naga_div(i_1, _e9)));
    float4 _e16 = normal_tex.Load(int3(texel_2, int(0)));
    GpuMaterial m_2 = ConstructGpuMaterial(asfloat(materials.Load3(naga_f2u32(_e16.w)*48+0)), asfloat(materials.Load(naga_f2u32(_e16.w)*48+12)), asfloat(materials.Load3(naga_f2u32(_e16.w)*48+16)), asfloat(materials.Load(naga_f2u32(_e16.w)*48+28)), asfloat(materials.Load3(naga_f2u32(_e16.w)*48+32)), asfloat(materials.Load(naga_f2u32(_e16.w)*48+44)));
    float3 _e23 = view.eye;
    const bool _e29 = has_specular(m_2.metallic, m_2.f0_, m_2.f90_);
    const Glossy glossy = ConstructGlossy(m_2, normalize((_e23 - x)), _e29);
    return glossy;
}

float3 glossy_term(Glossy g_2, GpuLight l_4, float3 n_3, float3 v_5, float t)
{
    bool local_11 = (bool)0;

    if (!(!(g_2.on))) {
        local_11 = (t <= 0.0);
    } else {
        local_11 = true;
    }
    bool _e13 = local_11;
    if (_e13) {
        return (0.0).xxx;
    }
    const float3 _e30 = specular_correction(g_2.m.albedo, g_2.m.metallic, g_2.m.f0_, g_2.m.f90_, g_2.m.alpha, n_3, g_2.v, normalize(-(v_5)));
    return ((l_4.intensity * _e30) * t);
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

WorkgroupBox load_receiver(uint li_3, uint pix, bool inside)
{
    float4 p_2 = (0.0).xxxx;
    bool local_12 = (bool)0;

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
        local_12 = (_e23 > 0.0);
    } else {
        local_12 = false;
    }
    bool _e27 = local_12;
    valid = _e27;
    bool _e29 = valid;
    if (_e29) {
        float3 _e32 = pos;
        const Glossy _e33 = glossy_at(pix, _e32);
        g_4 = _e33;
    }
    float3 _e35 = pos;
    bool _e37 = valid;
    const WorkgroupBox _e38 = workgroup_box(li_3, _e35, _e37);
    const WorkgroupBox workgroupbox_3 = _e38;
    return workgroupbox_3;
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

void quarter_boxes(uint li_4, uint3 lid_1)
{
    float3 lo_1 = (3.4028235e38).xxx;
    float3 hi_1 = (-3.4028235e38).xxx;
    uint y = (uint)0;
    uint x_1 = (uint)0;

    quarter = (((lid_1.x >= HALF) ? 1u : 0u) + ((lid_1.y >= HALF) ? 2u : 0u));
    float3 _e17 = pos;
    bool _e19 = valid;
    const WorkgroupBox _e20 = point_box(_e17, _e19);
    wg_lo[min(uint(li_4), 63u)] = _e20.lo;
    wg_hi[min(uint(li_4), 63u)] = _e20.hi;
    GroupMemoryBarrierWithGroupSync();
    if ((li_4 < 4u)) {
        uint x0_ = (naga_mod(li_4, 2u) * HALF);
        uint y0_ = (naga_div(li_4, 2u) * HALF);
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
                x_1 = x0_;
                uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
                bool loop_init_2 = true;
                while(true) {
                    if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
                    loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                    if (!loop_init_2) {
                        uint _e78 = x_1;
                        x_1 = (_e78 + 1u);
                    }
                    loop_init_2 = false;
                    uint _e51 = x_1;
                    if ((_e51 < min((x0_ + HALF), TILE))) {
                    } else {
                        break;
                    }
                    {
                        float3 _e57 = lo_1;
                        uint _e59 = y;
                        uint _e62 = x_1;
                        float3 _e65 = wg_lo[min(uint(((_e59 * TILE) + _e62)), 63u)];
                        lo_1 = min(_e57, _e65);
                        float3 _e67 = hi_1;
                        uint _e69 = y;
                        uint _e72 = x_1;
                        float3 _e75 = wg_hi[min(uint(((_e69 * TILE) + _e72)), 63u)];
                        hi_1 = max(_e67, _e75);
                    }
                }
            }
        }
        float3 _e85 = lo_1;
        quarter_lo[min(uint(li_4), 3u)] = _e85;
        float3 _e88 = hi_1;
        quarter_hi[min(uint(li_4), 3u)] = _e88;
    }
    GroupMemoryBarrierWithGroupSync();
    return;
}

void list_clear(uint li_5)
{
    if ((li_5 < 4u)) {
        { uint dummy = 0; InterlockedExchange(quarter_count[min(uint(li_5), 3u)], 0u, dummy); }
    }
    if ((li_5 == 0u)) {
        { uint dummy_1 = 0; InterlockedExchange(fullest, 0u, dummy_1); }
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
    const bool _e14 = sphere_overlaps_aabb(p_3, radius, lo_3, hi_3);
    if (!(_e14)) {
        return 0u;
    }
    uint _e20; InterlockedAdd(quarter_count[min(uint(q), 3u)], 1u, _e20);
    quarter_lights[min(uint(((q * QUARTER_LIGHTS) + _e20)), 1023u)] = slot_3;
    return (_e20 + 1u);
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
            uint _e65 = m;
            m = (_e65 + 1u);
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
            GpuLight l_5 = ConstructGpuLight(asfloat(lights.Load3(slot_5*64+0)), asuint(lights.Load(slot_5*64+12)), asfloat(lights.Load3(slot_5*64+16)), asfloat(lights.Load(slot_5*64+28)), asfloat(lights.Load3(slot_5*64+32)), asfloat(lights.Load(slot_5*64+44)), asfloat(lights.Load3(slot_5*64+48)), asuint(lights.Load(slot_5*64+60)));
            float3 _e22 = pos;
            float3 v_8 = (_e22 - l_5.p0_);
            float _e27 = asfloat(rt2_2.Load(slot_5*4));
            const float _e29 = vpl_near_range2_(_e27, P);
            const float _e30 = near_r2_of(slot_5);
            float _e34 = params.near_r2_;
            const float _e35 = vpl_near_slc_share(_e29, _e30, dot(v_8, v_8), _e34);
            if ((_e35 > 0.0)) {
                float3 _e40 = nrm;
                float _e43 = params.min_d2_;
                const float _e44 = vpl_transfer(l_5.p1_, _e40, v_8, _e43);
                float t_3 = ((_e44 * _e35) * unscale);
                float3 _e48 = e;
                e = (_e48 + (l_5.intensity * t_3));
                float3 _e53 = s;
                Glossy _e55 = g_4;
                float3 _e57 = nrm;
                const float3 _e58 = glossy_term(_e55, l_5, _e57, v_8, t_3);
                s = (_e53 + _e58);
                uint _e61 = kept;
                kept = (_e61 + 1u);
            }
        }
    }
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

void cull_tile(uint li_6, float3 lo_2, float3 hi_2, uint4 grid, uint clusters_at, uint groups_at)
{
    uint g_3 = 0u;
    uint h = (uint)0;

    list_clear(li_6);
    const uint _e10 = group_count(grid.x, grid.y, grid.z, grid.w);
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e84 = g_3;
            g_3 = (_e84 + 1u);
        }
        loop_init_4 = false;
        uint _e13 = g_3;
        if ((_e13 < _e10)) {
        } else {
            break;
        }
        {
            uint _e16 = g_3;
            GpuBox gb = ConstructGpuBox(asfloat(boxes.Load3((groups_at + _e16)*32+0)), asfloat(boxes.Load((groups_at + _e16)*32+12)), asfloat(boxes.Load3((groups_at + _e16)*32+16)), asfloat(boxes.Load((groups_at + _e16)*32+28)));
            const bool _e22 = box_overlaps_box(gb.lo, gb.hi, lo_2, hi_2);
            if (!(_e22)) {
                continue;
            }
            uint _e24 = g_3;
            const uint _e29 = group_first(_e24, grid.x, grid.y, grid.z, grid.w);
            uint first_1 = (clusters_at + _e29);
            uint _e31 = g_3;
            const uint _e36 = group_clusters(_e31, grid.x, grid.y, grid.z, grid.w);
            if ((li_6 == 0u)) {
                { uint dummy_2 = 0; InterlockedExchange(hit_count, 0u, dummy_2); }
            }
            GroupMemoryBarrierWithGroupSync();
            if ((li_6 < _e36)) {
                GpuBox cb = ConstructGpuBox(asfloat(boxes.Load3((first_1 + li_6)*32+0)), asfloat(boxes.Load((first_1 + li_6)*32+12)), asfloat(boxes.Load3((first_1 + li_6)*32+16)), asfloat(boxes.Load((first_1 + li_6)*32+28)));
                const bool _e48 = box_overlaps_box(cb.lo, cb.hi, lo_2, hi_2);
                if (_e48) {
                    uint _e52; InterlockedAdd(hit_count, 1u, _e52);
                    cluster_hits[min(uint(_e52), 63u)] = (first_1 + li_6);
                }
            }
            GroupMemoryBarrierWithGroupSync();
            uint _e56 = hit_count;
            GroupMemoryBarrierWithGroupSync();
            h = 0u;
            uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e81 = h;
                    h = (_e81 + 1u);
                }
                loop_init_5 = false;
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
                        list_clear(li_6);
                        GroupMemoryBarrierWithGroupSync();
                    }
                    uint _e63 = h;
                    uint _e65 = cluster_hits[min(uint(_e63), 63u)];
                    const uint _e66 = cluster_slot(_e65, li_6);
                    GpuLight l_6 = ConstructGpuLight(asfloat(lights.Load3(_e66*64+0)), asuint(lights.Load(_e66*64+12)), asfloat(lights.Load3(_e66*64+16)), asfloat(lights.Load(_e66*64+28)), asfloat(lights.Load3(_e66*64+32)), asfloat(lights.Load(_e66*64+44)), asfloat(lights.Load3(_e66*64+48)), asuint(lights.Load(_e66*64+60)));
                    if (any((l_6.intensity != (0.0).xxx))) {
                        const float _e75 = cull_r2_of(_e66);
                        const float _e76 = cull_radius(_e75);
                        const bool _e78 = sphere_overlaps_aabb(l_6.p0_, _e76, lo_2, hi_2);
                        if (_e78) {
                            list_add(_e66, l_6.p0_, _e76);
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
        uint4 _e37 = params.near_grid;
        uint _e40 = params.near_clusters_at;
        uint _e43 = params.near_groups_at;
        cull_tile(li, _e30.lo, _e30.hi, _e37, _e40, _e43);
    }
    bool _e45 = valid;
    if (_e45) {
        float4 old = asfloat(irradiance.Load4(pix_1*16));
        float3 _e53 = e;
        uint _e57 = kept;
        irradiance.Store4(pix_1*16, asuint(float4((old.xyz + _e53), (old.w + float(_e57)))));
        float4 _e65 = asfloat(specular.Load4(pix_1*16));
        float3 _e68 = s;
        specular.Store4(pix_1*16, asuint(float4((_e65.xyz + _e68), 0.0)));
        return;
    } else {
        return;
    }
}
