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
static const uint P = 1u;
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
RWByteAddressBuffer irradiance : register(u8);
RWByteAddressBuffer guide : register(u9);
ByteAddressBuffer materials : register(t10);
RWByteAddressBuffer specular : register(u11);
static float3 pos = (float3)0;
static float3 nrm = (float3)0;
static float eye_distance = (float)0;
static bool valid = (bool)0;
static float3 e = (float3)0;
static uint kept = (uint)0;
static float3 s = (float3)0;
static Glossy g_1 = (Glossy)0;

float vpl_transfer(float3 n_l, float3 n_x, float3 v, float min_d2_)
{
    float m = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m * m));
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
    bool local_1 = (bool)0;

    if (!((n_l_1 <= 0.0))) {
        local_1 = (n_v <= 0.0);
    } else {
        local_1 = true;
    }
    bool _e11 = local_1;
    if (_e11) {
        return 0.0;
    }
    const float _e13 = smith_root(n_v, alpha_2);
    const float _e15 = smith_root(n_l_1, alpha_2);
    return (0.5 / ((n_l_1 * _e13) + (n_v * _e15)));
}

float3 fresnel_schlick(float3 f0_, float f90_, float v_h)
{
    float c = saturate((1.0 - v_h));
    float c2_ = (c * c);
    return (f0_ + ((float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c)));
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
    float3 h = (v_1 + l);
    float len2_ = dot(h, h);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return saturate((dot(v_1, h) / sqrt(len2_)));
}

float3 specular_brdf(float3 base_2, float metallic_2, float3 f0_d_2, float f90_d_2, float alpha_3, float3 n, float3 v_2, float3 l_1)
{
    bool local_2 = (bool)0;

    float n_l_2 = dot(n, l_1);
    float n_v_1 = dot(n, v_2);
    if (!((n_l_2 <= 0.0))) {
        local_2 = (n_v_1 <= 0.0);
    } else {
        local_2 = true;
    }
    bool _e18 = local_2;
    if (_e18) {
        return float3(0.0, 0.0, 0.0);
    }
    float3 hs = (v_2 + l_1);
    float inv = (1.0 / sqrt(dot(hs, hs)));
    float3 h_1 = (hs * inv);
    float3 c_1 = cross(n, h_1);
    const float _e32 = ggx_d(dot(n, h_1), dot(c_1, c_1), alpha_3);
    const float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_2, h_1));
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
    bool local_3 = (bool)0;
    bool local_4 = (bool)0;

    if (!((metallic_6 > 0.0))) {
        local_3 = (f90_d_5 > 0.0);
    } else {
        local_3 = true;
    }
    bool _e11 = local_3;
    if (!(_e11)) {
        local_4 = (max(max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0.0);
    } else {
        local_4 = true;
    }
    bool _e23 = local_4;
    return _e23;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint shifted_subset(uint pixel_class, uint shift, uint period)
{
    return naga_mod((pixel_class + shift), (period * period));
}

float vpl_near_weight(float d2_, float near_r2_)
{
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t_2 = clamp(((near_r2_ - d2_) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t_2 * t_2) * (3.0 - (2.0 * t_2)));
}

float vpl_far_weight(float d2_1, float near_r2_1)
{
    const float _e2 = vpl_near_weight(d2_1, near_r2_1);
    return (1.0 - _e2);
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

float4 surface_at(int2 texel)
{
    float4 p_3 = position_tex.Load(int3(texel, int(0)));
    return ((p_3.w > 0.0) ? float4(p_3.xyz, 1.0) : (0.0).xxxx);
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
    float3 n_4 = _e15.xyz;
    float len2_1 = dot(n_4, n_4);
    if ((_e12.w > 0.0)) {
        local_5 = (len2_1 > 0.0);
    } else {
        local_5 = false;
    }
    bool valid_1 = local_5;
    float3 _e30 = view.eye;
    float3 v_6 = (_e12.xyz - _e30);
    float4 position = float4(_e12.xyz, (valid_1 ? 1.0 : 0.0));
    float4 normal = (valid_1 ? float4((n_4 / (sqrt(len2_1)).xxx), sqrt(dot(v_6, v_6))) : float4(0.0, 0.0, 0.0, 1e30));
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
    GpuMaterial m_1 = ConstructGpuMaterial(asfloat(materials.Load3(naga_f2u32(_e16.w)*48+0)), asfloat(materials.Load(naga_f2u32(_e16.w)*48+12)), asfloat(materials.Load3(naga_f2u32(_e16.w)*48+16)), asfloat(materials.Load(naga_f2u32(_e16.w)*48+28)), asfloat(materials.Load3(naga_f2u32(_e16.w)*48+32)), asfloat(materials.Load(naga_f2u32(_e16.w)*48+44)));
    float3 _e23 = view.eye;
    const bool _e29 = has_specular(m_1.metallic, m_1.f0_, m_1.f90_);
    const Glossy glossy = ConstructGlossy(m_1, normalize((_e23 - x)), _e29);
    return glossy;
}

float3 glossy_term(Glossy g, GpuLight l_4, float3 n_3, float3 v_5, float t)
{
    bool local_6 = (bool)0;

    if (!(!(g.on))) {
        local_6 = (t <= 0.0);
    } else {
        local_6 = true;
    }
    bool _e13 = local_6;
    if (_e13) {
        return (0.0).xxx;
    }
    const float3 _e30 = specular_correction(g.m.albedo, g.m.metallic, g.m.f0_, g.m.f90_, g.m.alpha, n_3, g.v, normalize(-(v_5)));
    return ((l_4.intensity * _e30) * t);
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
    bool _e29 = valid;
    if (_e29) {
        float3 _e32 = pos;
        const Glossy _e33 = glossy_at(pix, _e32);
        g_1 = _e33;
    }
    float3 _e35 = pos;
    bool _e37 = valid;
    const WorkgroupBox _e38 = workgroup_box(li_3, _e35, _e37);
    const WorkgroupBox workgroupbox_3 = _e38;
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

void shade_light(uint j_1)
{
    GpuLight l_5 = ConstructGpuLight(asfloat(lights.Load3(j_1*64+0)), asuint(lights.Load(j_1*64+12)), asfloat(lights.Load3(j_1*64+16)), asfloat(lights.Load(j_1*64+28)), asfloat(lights.Load3(j_1*64+32)), asfloat(lights.Load(j_1*64+44)), asfloat(lights.Load3(j_1*64+48)), asuint(lights.Load(j_1*64+60)));
    float3 _e5 = pos;
    float3 v_7 = (_e5 - l_5.p0_);
    float _e11 = params.near_r2_;
    const float _e12 = vpl_far_weight(dot(v_7, v_7), _e11);
    if ((_e12 > 0.0)) {
        float3 _e17 = nrm;
        float _e20 = params.min_d2_;
        const float _e21 = vpl_transfer(l_5.p1_, _e17, v_7, _e20);
        float t_3 = (_e21 * _e12);
        float3 _e24 = e;
        e = (_e24 + (l_5.intensity * t_3));
        float3 _e29 = s;
        Glossy _e31 = g_1;
        float3 _e33 = nrm;
        const float3 _e34 = glossy_term(_e31, l_5, _e33, v_7, t_3);
        s = (_e29 + _e34);
        uint _e37 = kept;
        kept = (_e37 + 1u);
        return;
    } else {
        return;
    }
}

[numthreads(8, 8, 1)]
void main(uint3 wg : SV_GroupID, uint3 lid : SV_GroupThreadID, uint li : SV_GroupIndex)
{
    if (li == 0) {
        wg_lo = (float3[64])0;
        wg_hi = (float3[64])0;
        wg_box = (WorkgroupBox)0;
    }
    GroupMemoryBarrierWithGroupSync();
    bool local = (bool)0;
    uint j = (uint)0;

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
    bool _e48 = valid;
    if (_e48) {
        uint _e51 = params.lights_per_subset;
        uint base_6 = (_e46 * _e51);
        j = base_6;
        uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
            loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e71 = j;
                j = (_e71 + 1u);
            }
            loop_init_1 = false;
            uint _e54 = j;
            uint _e57 = params.lights_per_subset;
            if ((_e54 < (base_6 + _e57))) {
            } else {
                break;
            }
            {
                uint _e61 = j;
                float3 _e64 = asfloat(lights.Load3(48+_e61*64));
                if (any((_e64 != (0.0).xxx))) {
                    uint _e69 = j;
                    shade_light(_e69);
                }
            }
        }
    }
    if (inside_1) {
        float3 _e76 = e;
        uint _e78 = kept;
        irradiance.Store4(pix_1*16, asuint(float4(_e76, float(_e78))));
        float3 _e84 = nrm;
        float _e86 = eye_distance;
        guide.Store4(pix_1*16, asuint(float4(_e84, _e86)));
        float3 _e91 = s;
        specular.Store4(pix_1*16, asuint(float4(_e91, 0.0)));
        return;
    } else {
        return;
    }
}
