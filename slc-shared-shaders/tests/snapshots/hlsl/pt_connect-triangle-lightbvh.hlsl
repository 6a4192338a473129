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

struct GpuLightCone {
    float3 center_;
    float radius;
    float3 axis;
    float cos_o;
    float phi;
    float cos_e;
    uint bvh_leaf;
    uint pad;
};

struct GpuGeoNode {
    float3 bmin;
    uint first;
    float3 bmax;
    uint count;
};

struct GpuTriangle {
    float3 v0_;
    uint material;
    float3 v1_;
    uint light;
    float3 v2_;
    uint pad;
};

struct GpuPathVertex {
    float3 position;
    uint alive;
    float3 normal;
    uint material;
    float3 weight;
    float pad1_;
    float3 gnormal;
    float pad2_;
    float3 wo;
    float pad3_;
};

struct GpuMaterial {
    float3 albedo;
    float metallic;
    float3 emission;
    float alpha;
    float3 f0_;
    float f90_;
};

struct ShadeParams {
    uint point_count;
    uint seed;
    uint frame;
    float eps;
};

struct GpuLightBvhNode {
    float3 center_;
    float radius;
    float3 axis;
    float cos_o;
    float phi;
    float cos_e;
    uint second;
    uint light;
};

struct GeoHit {
    float t;
    uint tri;
};

struct Connection {
    float3 e;
    int _pad1_0;
    float3 y;
    float cos_x;
};

struct BvhPick {
    uint light;
    float pmf;
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
static const uint K = 8u;
static const uint BSH = 0u;
static const uint BSH_TILE_DEPTH = 8u;
static const uint BSH_TILE_SUBTREES = 256u;
static const uint BVH = 0u;

ByteAddressBuffer geo_nodes : register(t6);
ByteAddressBuffer geo_tris : register(t7);
ByteAddressBuffer lights : register(t2);
ByteAddressBuffer r2_4 : register(t4);
ByteAddressBuffer rt2_5 : register(t3);
ByteAddressBuffer light_cones : register(t2, space1);
ByteAddressBuffer light_bvh : register(t3, space1);
cbuffer params : register(b0) { ShadeParams params; }
ByteAddressBuffer vertices_ : register(t1);
ByteAddressBuffer materials : register(t8);
RWByteAddressBuffer radiance : register(u9);
RWByteAddressBuffer candidates : register(u10);

float to_f32_(uint u)
{
    return float(u);
}

uint mul_lo_u32_(uint a, uint b)
{
    return (a * b);
}

uint add_wrap_u32_(uint a_1, uint b_1)
{
    return (a_1 + b_1);
}

float xi_from_bits(uint bits)
{
    const float _e3 = to_f32_((bits >> 8u));
    return (_e3 * XI_STEP);
}

uint pcg_hash(uint x)
{
    const uint _e2 = mul_lo_u32_(x, 747796405u);
    const uint _e4 = add_wrap_u32_(_e2, 2891336453u);
    const uint _e12 = mul_lo_u32_(((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4), 277803737u);
    return ((_e12 >> 22u) ^ _e12);
}

uint point_stream(uint seed, uint point_, uint frame)
{
    const uint _e3 = pcg_hash(frame);
    const uint _e5 = pcg_hash((point_ ^ _e3));
    const uint _e7 = pcg_hash((seed ^ _e5));
    return _e7;
}

uint pick_stream(uint stream)
{
    const uint _e3 = pcg_hash((stream ^ PICK_STREAM));
    return _e3;
}

float rr_probability(float rt2_, float d2_)
{
    if ((d2_ <= rt2_)) {
        return 1.0;
    }
    return (rt2_ / d2_);
}

float slc_weight(float rt2_1, float d2_1)
{
    if ((d2_1 <= rt2_1)) {
        return 1.0;
    }
    return (d2_1 / rt2_1);
}

bool slc_keep(float r2_, float d2_2)
{
    return (d2_2 < r2_);
}

float inverse_square(float d2_3)
{
    return (1.0 / max(d2_3, MIN_D2_));
}

float connection_factor(float cos_x, float d2_4, float rt2_2, float w)
{
    const float _e4 = inverse_square(d2_4);
    const float _e6 = slc_weight(rt2_2, d2_4);
    return (((cos_x * _e4) * _e6) * w);
}

float connection_cosine(float3 x_1, float3 y, float3 n, float3 ng, float r2_1)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;

    float3 v_7 = (x_1 - y);
    float d2_8 = dot(v_7, v_7);
    const bool _e7 = slc_keep(r2_1, d2_8);
    if (!(!(_e7))) {
        local = !((d2_8 > 0.0));
    } else {
        local = true;
    }
    bool _e16 = local;
    if (_e16) {
        return 0.0;
    }
    float3 w_5 = (v_7 / (sqrt(d2_8)).xxx);
    float cos_x_1 = -(dot(n, w_5));
    if (!(!((cos_x_1 > 0.0)))) {
        local_1 = !((dot(ng, w_5) < 0.0));
    } else {
        local_1 = true;
    }
    bool _e34 = local_1;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float triangle_lobe(float3 n_1, float area, float3 w_1)
{
    return (area * max(dot(n_1, w_1), 0.0));
}

float3 triangle_sample(float3 a_2, float3 b_2, float3 c, float u1_, float u2_)
{
    float su = sqrt(u1_);
    float b0_ = (1.0 - su);
    float b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c * ((1.0 - b0_) - b1_)));
}

float area_to_solid_angle_pdf(float pdf_area, float d2_5, float cos_light)
{
    float c_5 = abs(cos_light);
    if ((c_5 <= 0.0)) {
        return 0.0;
    }
    return ((pdf_area * d2_5) / c_5);
}

float mis_power(float pdf_a, float pdf_b)
{
    float a2_ = (pdf_a * pdf_a);
    float s_2 = (a2_ + (pdf_b * pdf_b));
    if ((s_2 <= 0.0)) {
        return 0.0;
    }
    return (a2_ / s_2);
}

float light_strategy_pdf(float select_, float rt2_3, float d2_6, float area_1, float cos_y)
{
    bool local_2 = (bool)0;
    bool local_3 = (bool)0;

    if (!((d2_6 <= 0.0))) {
        local_2 = (area_1 <= 0.0);
    } else {
        local_2 = true;
    }
    bool _e13 = local_2;
    if (!(_e13)) {
        local_3 = (cos_y <= 0.0);
    } else {
        local_3 = true;
    }
    bool _e20 = local_3;
    if (_e20) {
        return 0.0;
    }
    const float _e22 = rr_probability(rt2_3, d2_6);
    const float _e26 = area_to_solid_angle_pdf((1.0 / area_1), d2_6, cos_y);
    return ((select_ * _e22) * _e26);
}

float cosine_pdf(float cos_theta)
{
    return (max(cos_theta, 0.0) * INV_PI);
}

float3 onb_tangent(float3 n_2)
{
    float s_3 = ((n_2.z >= 0.0) ? 1.0 : -1.0);
    float a_7 = (-1.0 / (s_3 + n_2.z));
    return float3((1.0 + (((s_3 * n_2.x) * n_2.x) * a_7)), (((s_3 * n_2.x) * n_2.y) * a_7), (-(s_3) * n_2.x));
}

float3 onb_bitangent(float3 n_3)
{
    float s_4 = ((n_3.z >= 0.0) ? 1.0 : -1.0);
    float a_8 = (-1.0 / (s_4 + n_3.z));
    return float3(((n_3.x * n_3.y) * a_8), (s_4 + ((n_3.y * n_3.y) * a_8)), -(n_3.y));
}

float3 onb_to_local(float3 n_4, float3 w_2)
{
    const float3 _e2 = onb_tangent(n_4);
    const float3 _e4 = onb_bitangent(n_4);
    return float3(dot(w_2, _e2), dot(w_2, _e4), dot(w_2, n_4));
}

float ggx_d(float cos_h, float sin2_h, float alpha)
{
    if ((cos_h <= 0.0)) {
        return 0.0;
    }
    float a2_1 = (alpha * alpha);
    float t = (((cos_h * cos_h) * a2_1) + sin2_h);
    return ((a2_1 * INV_PI) / (t * t));
}

float smith_root(float cos_, float alpha_1)
{
    float a2_2 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1.0 - a2_2)) + a2_2));
}

float smith_visibility(float n_l, float n_v, float alpha_2)
{
    bool local_4 = (bool)0;

    if (!((n_l <= 0.0))) {
        local_4 = (n_v <= 0.0);
    } else {
        local_4 = true;
    }
    bool _e11 = local_4;
    if (_e11) {
        return 0.0;
    }
    const float _e13 = smith_root(n_v, alpha_2);
    const float _e15 = smith_root(n_l, alpha_2);
    return (0.5 / ((n_l * _e13) + (n_v * _e15)));
}

float3 fresnel_schlick(float3 f0_, float f90_, float v_h)
{
    float c_6 = saturate((1.0 - v_h));
    float c2_ = (c_6 * c_6);
    return (f0_ + ((float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_6)));
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

float half_cosine(float3 v, float3 l)
{
    float3 h_1 = (v + l);
    float len2_ = dot(h_1, h_1);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return saturate((dot(v, h_1) / sqrt(len2_)));
}

float3 specular_brdf(float3 base_2, float metallic_2, float3 f0_d_2, float f90_d_2, float alpha_3, float3 n_5, float3 v_1, float3 l_1)
{
    bool local_5 = (bool)0;

    float n_l_1 = dot(n_5, l_1);
    float n_v_2 = dot(n_5, v_1);
    if (!((n_l_1 <= 0.0))) {
        local_5 = (n_v_2 <= 0.0);
    } else {
        local_5 = true;
    }
    bool _e18 = local_5;
    if (_e18) {
        return float3(0.0, 0.0, 0.0);
    }
    float3 hs = (v_1 + l_1);
    float inv = (1.0 / sqrt(dot(hs, hs)));
    float3 h_2 = (hs * inv);
    float3 c_7 = cross(n_5, h_2);
    const float _e32 = ggx_d(dot(n_5, h_2), dot(c_7, c_7), alpha_3);
    const float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_1, h_2));
    const float _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return (_e34 * (_e32 * _e35));
}

float3 brdf_eval(float3 base_3, float metallic_3, float3 f0_d_3, float f90_d_3, float alpha_4, float3 n_6, float3 v_2, float3 l_2)
{
    if ((dot(n_6, l_2) <= 0.0)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float _e15 = half_cosine(v_2, l_2);
    const float3 _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    const float3 _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_6, v_2, l_2);
    return (_e16 + _e17);
}

bool has_specular(float metallic_4, float3 f0_d_4, float f90_d_4)
{
    bool local_6 = (bool)0;
    bool local_7 = (bool)0;

    if (!((metallic_4 > 0.0))) {
        local_6 = (f90_d_4 > 0.0);
    } else {
        local_6 = true;
    }
    bool _e11 = local_6;
    if (!(_e11)) {
        local_7 = (max(max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0.0);
    } else {
        local_7 = true;
    }
    bool _e23 = local_7;
    return _e23;
}

float channel_mean(float3 c_1)
{
    return (((c_1.x + c_1.y) + c_1.z) * 0.33333334);
}

float4 receiver_lobe(float3 base_4, float metallic_5, float3 f0_d_5, float f90_d_5, float alpha_5, float n_v_1)
{
    bool local_8 = (bool)0;

    const float3 _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    const float _e16 = channel_mean((((float3(1.0, 1.0, 1.0) - _e10) * base_4) * (1.0 - metallic_5)));
    if (!((n_v_1 <= 0.0))) {
        const bool _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_8 = !(_e22);
    } else {
        local_8 = true;
    }
    bool _e25 = local_8;
    if (_e25) {
        return float4(_e16, 0.0, alpha_5, n_v_1);
    }
    const float3 _e28 = specular_fresnel(base_4, metallic_5, f0_d_5, f90_d_5, n_v_1);
    const float _e29 = channel_mean(_e28);
    return float4(_e16, _e29, alpha_5, n_v_1);
}

float specular_probability(float4 lobe)
{
    if ((lobe.y <= 0.0)) {
        return 0.0;
    }
    if ((lobe.x <= 0.0)) {
        return 1.0;
    }
    return clamp((lobe.y / (lobe.y + lobe.x)), 0.1, 0.9);
}

float specular_peak_factor(float4 lobe_1)
{
    const float _e6 = smith_root(lobe_1.w, lobe_1.z);
    return ((lobe_1.y * 0.5) / (_e6 + max(lobe_1.w, 0.0)));
}

float receiver_peak(float4 lobe_2)
{
    const float _e2 = specular_peak_factor(lobe_2);
    return (lobe_2.x + (_e2 / (lobe_2.z * lobe_2.z)));
}

float range_scale(float4 lobe_3)
{
    if ((lobe_3.y <= 0.0)) {
        return 1.0;
    }
    const float _e5 = receiver_peak(lobe_3);
    return clamp(_e5, 1.0, RANGE_SCALE_MAX);
}

float4 range_lobe(float4 lobe_4)
{
    if ((lobe_4.y <= 0.0)) {
        return float4(1.0, 0.0, 1.0, 1.0);
    }
    const float _e10 = specular_peak_factor(lobe_4);
    const float _e14 = range_scale(lobe_4);
    return float4(lobe_4.x, _e10, (lobe_4.z * lobe_4.z), sqrt(_e14));
}

float3 mirror_dir(float3 n_7, float3 v_3)
{
    return ((n_7 * (2.0 * dot(n_7, v_3))) - v_3);
}

float bounded_vndf_k(float3 wi, float alpha_6)
{
    float a_9 = saturate(alpha_6);
    float s_5 = (1.0 + sqrt(((wi.x * wi.x) + (wi.y * wi.y))));
    float a2_3 = (a_9 * a_9);
    float s2_ = (s_5 * s_5);
    return (((1.0 - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z)));
}

float ggx_vndf_pdf(float3 wi_1, float3 wo, float alpha_7)
{
    bool local_9 = (bool)0;

    if (!((wi_1.z <= 0.0))) {
        local_9 = (wo.z <= 0.0);
    } else {
        local_9 = true;
    }
    bool _e13 = local_9;
    if (_e13) {
        return 0.0;
    }
    float3 hs_1 = (wi_1 + wo);
    float3 m_1 = (hs_1 / (sqrt(dot(hs_1, hs_1))).xxx);
    const float _e28 = ggx_d(m_1.z, ((m_1.x * m_1.x) + (m_1.y * m_1.y)), alpha_7);
    float t_1 = sqrt((((alpha_7 * alpha_7) * ((wi_1.x * wi_1.x) + (wi_1.y * wi_1.y))) + (wi_1.z * wi_1.z)));
    const float _e43 = bounded_vndf_k(wi_1, alpha_7);
    return (_e28 / (2.0 * ((_e43 * wi_1.z) + t_1)));
}

float bsdf_pdf(float3 n_8, float3 v_4, float3 l_3, float alpha_8, float p_spec)
{
    const float _e6 = cosine_pdf(dot(n_8, l_3));
    if ((p_spec <= 0.0)) {
        return _e6;
    }
    const float3 _e9 = onb_to_local(n_8, v_4);
    const float3 _e10 = onb_to_local(n_8, l_3);
    const float _e11 = ggx_vndf_pdf(_e9, _e10, alpha_8);
    return ((p_spec * _e11) + ((1.0 - p_spec) * _e6));
}

float cos_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b)
{
    if ((cos_a > cos_b)) {
        return 1.0;
    }
    return ((cos_a * cos_b) + (sin_a * sin_b));
}

float sin_sub_clamped(float sin_a_1, float cos_a_1, float sin_b_1, float cos_b_1)
{
    if ((cos_a_1 > cos_b_1)) {
        return 0.0;
    }
    return ((sin_a_1 * cos_b_1) - (cos_a_1 * sin_b_1));
}

float safe_sqrt(float x_2)
{
    return sqrt(max(x_2, 0.0));
}

float subtended_cos(float dist2_, float r2_2)
{
    const float _e5 = safe_sqrt((1.0 - (r2_2 / dist2_)));
    return ((dist2_ <= r2_2) ? -1.0 : _e5);
}

float4 emitter_cone(float3 center_, float radius, float3 axis, float cos_o, float3 p)
{
    bool local_10 = (bool)0;

    float3 v_8 = (p - center_);
    float dist2_1 = dot(v_8, v_8);
    float r2_5 = (radius * radius);
    if ((dist2_1 <= 0.0)) {
        local_10 = (r2_5 <= 0.0);
    } else {
        local_10 = false;
    }
    bool _e15 = local_10;
    if (_e15) {
        return float4(-2.0, 1e-12, -1.0, 0.0);
    }
    float d2_9 = max(max(dist2_1, r2_5), MIN_D2_);
    float3 wi_2 = ((dist2_1 > 0.0) ? (v_8 / (sqrt(dist2_1)).xxx) : float3(0.0, 0.0, 0.0));
    float cos_w = dot(axis, wi_2);
    const float _e38 = safe_sqrt((1.0 - (cos_w * cos_w)));
    const float _e39 = subtended_cos(dist2_1, r2_5);
    const float _e43 = safe_sqrt((1.0 - (_e39 * _e39)));
    const float _e47 = safe_sqrt((1.0 - (cos_o * cos_o)));
    const float _e48 = cos_sub_clamped(_e38, cos_w, _e47, cos_o);
    const float _e49 = sin_sub_clamped(_e38, cos_w, _e47, cos_o);
    const float _e50 = cos_sub_clamped(_e49, _e48, _e43, _e39);
    return float4(_e50, d2_9, _e39, _e43);
}

float emitter_importance(float3 center_1, float radius_1, float phi, float3 axis_1, float cos_o_1, float cos_e, float3 p_1)
{
    const float4 _e7 = emitter_cone(center_1, radius_1, axis_1, cos_o_1, p_1);
    if ((_e7.x <= cos_e)) {
        return 0.0;
    }
    return ((phi * _e7.x) / _e7.y);
}

float cone_cos_of(float3 v_5, float d2_7, float a_3, float3 d)
{
    bool local_11 = (bool)0;
    bool local_12 = (bool)0;

    float vd = dot(v_5, d);
    float h2_ = (d2_7 - (a_3 * a_3));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_12 = ((vd * vd) >= h2_);
        } else {
            local_12 = false;
        }
        bool _e19 = local_12;
        local_11 = _e19;
    } else {
        local_11 = true;
    }
    bool _e21 = local_11;
    if (_e21) {
        return 1.0;
    }
    float3 c_8 = cross(v_5, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_8, c_8)) * a_3)) / d2_7), 1.0);
}

float cone_cos_toward(float3 center_2, float radius_2, float3 p_2, float3 d_1)
{
    float3 v_9 = (center_2 - p_2);
    const float _e6 = cone_cos_of(v_9, dot(v_9, v_9), radius_2, d_1);
    return _e6;
}

float range_scale_at(float4 rl, float cos_t)
{
    float t_2 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_2 * t_2))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(float4 rl_1, float3 center_3, float radius_3, float3 p_3, float3 r)
{
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    const float _e9 = cone_cos_toward(center_3, radius_3, p_3, r);
    const float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

float light_importance(float3 center_4, float radius_4, float phi_1, float3 axis_2, float cos_o_2, float cos_e_1, float3 p_4, float3 n_9)
{
    float imp = (float)0;

    const float4 _e8 = emitter_cone(center_4, radius_4, axis_2, cos_o_2, p_4);
    if ((_e8.x <= cos_e_1)) {
        return 0.0;
    }
    imp = ((phi_1 * _e8.x) / _e8.y);
    if ((dot(n_9, n_9) > 0.0)) {
        float3 v_10 = (center_4 - p_4);
        float dist2_2 = dot(v_10, v_10);
        float cos_i = dot(((dist2_2 > 0.0) ? (v_10 / (sqrt(dist2_2)).xxx) : float3(0.0, 0.0, 0.0)), n_9);
        float _e33 = imp;
        const float _e37 = safe_sqrt((1.0 - (cos_i * cos_i)));
        const float _e40 = cos_sub_clamped(_e37, cos_i, _e8.w, _e8.z);
        imp = (_e33 * max(_e40, 0.0));
    }
    float _e44 = imp;
    return max(_e44, 0.0);
}

float glossy_importance(float3 center_5, float radius_5, float phi_2, float3 axis_3, float cos_o_3, float cos_e_2, float3 p_5, float3 n_10, float3 r_1, float4 lobe_5)
{
    bool local_13 = (bool)0;

    const float _e10 = emitter_importance(center_5, radius_5, phi_2, axis_3, cos_o_3, cos_e_2, p_5);
    const float _e11 = cone_cos_toward(center_5, radius_5, p_5, n_10);
    if (!((_e10 <= 0.0))) {
        local_13 = (_e11 <= 0.0);
    } else {
        local_13 = true;
    }
    bool _e20 = local_13;
    if (_e20) {
        return 0.0;
    }
    const float _e22 = cone_cos_toward(center_5, radius_5, p_5, r_1);
    const float _e27 = safe_sqrt((0.5 + (0.5 * _e22)));
    const float _e33 = ggx_d(_e27, (1.0 - (_e27 * _e27)), lobe_5.z);
    const float _e39 = smith_root(lobe_5.w, lobe_5.z);
    float spec = (((lobe_5.y * _e33) * 0.25) / _e39);
    return (_e10 * (((lobe_5.x * INV_PI) * _e11) + spec));
}

float receiver_importance(float3 center_6, float radius_6, float phi_3, float3 axis_4, float cos_o_4, float cos_e_3, float3 p_6, float3 n_11, float3 r_2, float4 lobe_6)
{
    if ((lobe_6.y <= 0.0)) {
        const float _e13 = light_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_11);
        return _e13;
    }
    const float _e14 = glossy_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_11, r_2, lobe_6);
    return _e14;
}

float bvh_first_prob(float c0_, float c1_)
{
    float s_6 = (c0_ + c1_);
    if ((s_6 > 0.0)) {
        return (c0_ / s_6);
    }
    return -1.0;
}

float bvh_remap_u(float u_1, float p0_, bool first)
{
    if (first) {
        return min((u_1 / p0_), ONE_MINUS_EPSILON);
    }
    return clamp(((u_1 - p0_) / (1.0 - p0_)), 0.0, ONE_MINUS_EPSILON);
}

bool finite3_(float3 v_6)
{
    bool local_14 = (bool)0;
    bool local_15 = (bool)0;

    if ((abs(v_6.x) <= F32_MAX)) {
        local_14 = (abs(v_6.y) <= F32_MAX);
    } else {
        local_14 = false;
    }
    bool _e12 = local_14;
    if (_e12) {
        local_15 = (abs(v_6.z) <= F32_MAX);
    } else {
        local_15 = false;
    }
    bool _e20 = local_15;
    return _e20;
}

float shadow_margin(float len)
{
    return (0.0001 * len);
}

float ray_inverse(float x_3)
{
    return (1.0 / ((abs(x_3) < 1e-30) ? 1e-30 : x_3));
}

float3 ray_inverse3_(float3 d_2)
{
    const float _e2 = ray_inverse(d_2.x);
    const float _e4 = ray_inverse(d_2.y);
    const float _e6 = ray_inverse(d_2.z);
    return float3(_e2, _e4, _e6);
}

float ray_aabb(float3 o, float3 inv_d, float3 bmin, float3 bmax, float t_max)
{
    float3 t0_ = ((bmin - o) * inv_d);
    float3 t1_ = ((bmax - o) * inv_d);
    float3 lo = min(t0_, t1_);
    float3 hi = max(t0_, t1_);
    float t_in = max(max(lo.x, lo.y), max(lo.z, 0.0));
    float t_out = min(min(hi.x, hi.y), min(hi.z, t_max));
    if ((t_in <= t_out)) {
        return t_in;
    }
    return -1.0;
}

float3 triangle_normal(float3 a_4, float3 b_3, float3 c_2)
{
    bool local_16 = (bool)0;

    float3 n_19 = cross((b_3 - a_4), (c_2 - a_4));
    float l2_ = dot(n_19, n_19);
    if (!(!((l2_ > 0.0)))) {
        local_16 = !((l2_ < 3e38));
    } else {
        local_16 = true;
    }
    bool _e17 = local_16;
    if (_e17) {
        return float3(0.0, 0.0, 0.0);
    }
    return (n_19 / (sqrt(l2_)).xxx);
}

float ray_triangle(float3 o_1, float3 d_3, float3 a_5, float3 b_4, float3 c_3, float t_min, float t_max_1)
{
    bool local_17 = (bool)0;
    bool local_18 = (bool)0;
    bool local_19 = (bool)0;

    float3 e1_ = (b_4 - a_5);
    float3 e2_ = (c_3 - a_5);
    float3 p_7 = cross(d_3, e2_);
    float det = dot(e1_, p_7);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv_1 = (1.0 / det);
    float3 s_7 = (o_1 - a_5);
    float u_3 = (dot(s_7, p_7) * inv_1);
    if (!((u_3 < 0.0))) {
        local_17 = (u_3 > 1.0);
    } else {
        local_17 = true;
    }
    bool _e28 = local_17;
    if (_e28) {
        return -1.0;
    }
    float3 q = cross(s_7, e1_);
    float v_11 = (dot(d_3, q) * inv_1);
    if (!((v_11 < 0.0))) {
        local_18 = ((u_3 + v_11) > 1.0);
    } else {
        local_18 = true;
    }
    bool _e42 = local_18;
    if (_e42) {
        return -1.0;
    }
    float t_3 = (dot(e2_, q) * inv_1);
    if ((t_3 > t_min)) {
        local_19 = (t_3 < t_max_1);
    } else {
        local_19 = false;
    }
    bool _e51 = local_19;
    if (_e51) {
        return t_3;
    }
    return -1.0;
}

float3 light_intensity(GpuLight l_4, float3 w_3)
{
    switch(l_4.kind) {
        case 3u: {
            const float3 _e7 = triangle_normal(l_4.p0_, l_4.p1_, l_4.p2_);
            const float _e9 = triangle_lobe(_e7, l_4.a, w_3);
            return (l_4.intensity * _e9);
        }
        default: {
            return (0.0).xxx;
        }
    }
}

float3 light_point(GpuLight l_5, float u1_1, float u2_1)
{
    if ((l_5.kind == LIGHT_TRIANGLE)) {
        const float3 _e9 = triangle_sample(l_5.p0_, l_5.p1_, l_5.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_5.p0_;
}

float light_area(GpuLight l_6)
{
    if ((l_6.kind == LIGHT_TRIANGLE)) {
        return l_6.a;
    }
    return 0.0;
}

float3 light_normal(GpuLight l_7)
{
    if ((l_7.kind == LIGHT_TRIANGLE)) {
        const float3 _e7 = triangle_normal(l_7.p0_, l_7.p1_, l_7.p2_);
        return _e7;
    }
    return (0.0).xxx;
}

uint NagaBufferLength(ByteAddressBuffer buffer)
{
    uint ret;
    buffer.GetDimensions(ret);
    return ret;
}

GpuGeoNode ConstructGpuGeoNode(float3 arg0, uint arg1, float3 arg2, uint arg3) {
    GpuGeoNode ret = (GpuGeoNode)0;
    ret.bmin = arg0;
    ret.first = arg1;
    ret.bmax = arg2;
    ret.count = arg3;
    return ret;
}

GpuTriangle ConstructGpuTriangle(float3 arg0, uint arg1, float3 arg2, uint arg3, float3 arg4, uint arg5) {
    GpuTriangle ret = (GpuTriangle)0;
    ret.v0_ = arg0;
    ret.material = arg1;
    ret.v1_ = arg2;
    ret.light = arg3;
    ret.v2_ = arg4;
    ret.pad = arg5;
    return ret;
}

GeoHit trace(float3 o_2, float3 d_4, float t_min_1, float t_max_2, bool any_hit)
{
    GeoHit hit = (GeoHit)0;
    uint stack[64] = (uint[64])0;
    uint sp = 0u;
    uint node = 0u;
    uint i = (uint)0;

    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((((NagaBufferLength(geo_nodes) - 0) / 32) == 0u)) {
        GeoHit _e13 = hit;
        const GeoHit geohit = _e13;
        return geohit;
    }
    const float3 _e14 = ray_inverse3_(d_4);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e21 = node;
        GpuGeoNode n_20 = ConstructGpuGeoNode(asfloat(geo_nodes.Load3(_e21*32+0)), asuint(geo_nodes.Load(_e21*32+12)), asfloat(geo_nodes.Load3(_e21*32+16)), asuint(geo_nodes.Load(_e21*32+28)));
        float _e27 = hit.t;
        const float _e28 = ray_aabb(o_2, _e14, n_20.bmin, n_20.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_20.count > 0u)) {
                i = n_20.first;
                uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
                bool loop_init = true;
                while(true) {
                    if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
                    loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                    if (!loop_init) {
                        uint _e58 = i;
                        i = (_e58 + 1u);
                    }
                    loop_init = false;
                    uint _e36 = i;
                    if ((_e36 < (n_20.first + n_20.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_4 = ConstructGpuTriangle(asfloat(geo_tris.Load3(_e42*48+0)), asuint(geo_tris.Load(_e42*48+12)), asfloat(geo_tris.Load3(_e42*48+16)), asuint(geo_tris.Load(_e42*48+28)), asfloat(geo_tris.Load3(_e42*48+32)), asuint(geo_tris.Load(_e42*48+44)));
                        float _e49 = hit.t;
                        const float _e50 = ray_triangle(o_2, d_4, t_4.v0_, t_4.v1_, t_4.v2_, t_min_1, _e49);
                        if ((_e50 > 0.0)) {
                            hit.t = _e50;
                            uint _e55 = i;
                            hit.tri = _e55;
                            if (any_hit) {
                                GeoHit _e56 = hit;
                                const GeoHit geohit_1 = _e56;
                                return geohit_1;
                            }
                        }
                    }
                }
            } else {
                uint _e60 = sp;
                if ((_e60 < 64u)) {
                    uint _e63 = sp;
                    stack[min(uint(_e63), 63u)] = (n_20.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node = n_20.first;
                continue;
            }
        }
        uint _e72 = sp;
        if ((_e72 == 0u)) {
            break;
        }
        uint _e75 = sp;
        sp = (_e75 - 1u);
        uint _e78 = sp;
        uint _e80 = stack[min(uint(_e78), 63u)];
        node = _e80;
    }
    GeoHit _e81 = hit;
    const GeoHit geohit_2 = _e81;
    return geohit_2;
}

bool occluded(float3 a_6, float3 b_5)
{
    float3 dv = (b_5 - a_6);
    float len_1 = length(dv);
    if ((len_1 <= 0.0)) {
        return false;
    }
    const float _e7 = shadow_margin(len_1);
    const GeoHit _e12 = trace(a_6, (dv / (len_1).xxx), _e7, (len_1 - _e7), true);
    return (_e12.tri != NO_LIGHT);
}

Connection connect_record(GpuLight l_8, float3 x_4, float3 n_12, float3 ng_1, float r2_3, float rt2_4, float w_res, float u1_2, float u2_2, float eps, bool trace_1)
{
    Connection c_4 = (Connection)0;
    bool local_20 = (bool)0;
    bool local_21 = (bool)0;

    c_4.e = (0.0).xxx;
    const float3 _e16 = light_point(l_8, u1_2, u2_2);
    c_4.y = _e16;
    float3 _e19 = c_4.y;
    const float _e20 = connection_cosine(x_4, _e19, n_12, ng_1, r2_3);
    c_4.cos_x = _e20;
    float _e22 = c_4.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            float3 _e33 = c_4.y;
            const bool _e34 = occluded((x_4 + (ng_1 * eps)), _e33);
            local_21 = _e34;
        } else {
            local_21 = false;
        }
        bool _e36 = local_21;
        local_20 = _e36;
    } else {
        local_20 = true;
    }
    bool _e38 = local_20;
    if (_e38) {
        Connection _e39 = c_4;
        const Connection connection = _e39;
        return connection;
    }
    float3 _e41 = c_4.y;
    float3 v_12 = (x_4 - _e41);
    float d2_10 = dot(v_12, v_12);
    const float3 _e48 = light_intensity(l_8, (v_12 / (sqrt(d2_10)).xxx));
    float _e50 = c_4.cos_x;
    const float _e51 = connection_factor(_e50, d2_10, rt2_4, w_res);
    c_4.e = (_e48 * _e51);
    Connection _e53 = c_4;
    const Connection connection_1 = _e53;
    return connection_1;
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

Connection connect_traced(uint li, float3 x_5, float3 n_13, float3 ng_2, float s, float w_res_1, float u1_3, float u2_3, float eps_1, bool trace_2)
{
    GpuLight _e12 = ConstructGpuLight(asfloat(lights.Load3(li*64+0)), asuint(lights.Load(li*64+12)), asfloat(lights.Load3(li*64+16)), asfloat(lights.Load(li*64+28)), asfloat(lights.Load3(li*64+32)), asfloat(lights.Load(li*64+44)), asfloat(lights.Load3(li*64+48)), asuint(lights.Load(li*64+60)));
    float _e15 = asfloat(r2_4.Load(li*4));
    float _e19 = asfloat(rt2_5.Load(li*4));
    const Connection _e21 = connect_record(_e12, x_5, n_13, ng_2, (s * _e15), (s * _e19), w_res_1, u1_3, u2_3, eps_1, trace_2);
    const Connection connection_2 = _e21;
    return connection_2;
}

Connection connect(uint li_1, float3 x_6, float3 n_14, float3 ng_3, float s_1, float w_res_2, float u1_4, float u2_4, float eps_2)
{
    const Connection _e10 = connect_traced(li_1, x_6, n_14, ng_3, s_1, w_res_2, u1_4, u2_4, eps_2, true);
    const Connection connection_3 = _e10;
    return connection_3;
}

float mis_weight(float pdf_a_1, float pdf_b_1)
{
    const float _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

GpuLightCone ConstructGpuLightCone(float3 arg0, float arg1, float3 arg2, float arg3, float arg4, float arg5, uint arg6, uint arg7) {
    GpuLightCone ret = (GpuLightCone)0;
    ret.center_ = arg0;
    ret.radius = arg1;
    ret.axis = arg2;
    ret.cos_o = arg3;
    ret.phi = arg4;
    ret.cos_e = arg5;
    ret.bvh_leaf = arg6;
    ret.pad = arg7;
    return ret;
}

float light_range_scale(uint li_2, float3 x_7, float3 r_3, float4 rl_2)
{
    GpuLightCone c_9 = ConstructGpuLightCone(asfloat(light_cones.Load3(li_2*48+0)), asfloat(light_cones.Load(li_2*48+12)), asfloat(light_cones.Load3(li_2*48+16)), asfloat(light_cones.Load(li_2*48+28)), asfloat(light_cones.Load(li_2*48+32)), asfloat(light_cones.Load(li_2*48+36)), asuint(light_cones.Load(li_2*48+40)), asuint(light_cones.Load(li_2*48+44)));
    const float _e9 = range_scale_toward(rl_2, c_9.center_, c_9.radius, x_7, r_3);
    return _e9;
}

GpuLightBvhNode ConstructGpuLightBvhNode(float3 arg0, float arg1, float3 arg2, float arg3, float arg4, float arg5, uint arg6, uint arg7) {
    GpuLightBvhNode ret = (GpuLightBvhNode)0;
    ret.center_ = arg0;
    ret.radius = arg1;
    ret.axis = arg2;
    ret.cos_o = arg3;
    ret.phi = arg4;
    ret.cos_e = arg5;
    ret.second = arg6;
    ret.light = arg7;
    return ret;
}

GpuLightBvhNode light_bvh_node(uint nodes, uint i_1)
{
    GpuLightBvhNode _e4 = ConstructGpuLightBvhNode(asfloat(light_bvh.Load3(i_1*48+0)), asfloat(light_bvh.Load(i_1*48+12)), asfloat(light_bvh.Load3(i_1*48+16)), asfloat(light_bvh.Load(i_1*48+28)), asfloat(light_bvh.Load(i_1*48+32)), asfloat(light_bvh.Load(i_1*48+36)), asuint(light_bvh.Load(i_1*48+40)), asuint(light_bvh.Load(i_1*48+44)));
    const GpuLightBvhNode gpulightbvhnode = _e4;
    return gpulightbvhnode;
}

uint light_bvh_count(uint nodes_1)
{
    return ((NagaBufferLength(light_bvh) - 0) / 48);
}

float bvh_importance(uint nodes_2, uint i_2, float3 x_8, float3 n_15, float3 r_4, float4 lobe_7)
{
    const GpuLightBvhNode _e6 = light_bvh_node(nodes_2, i_2);
    const float _e13 = receiver_importance(_e6.center_, _e6.radius, _e6.phi, _e6.axis, _e6.cos_o, _e6.cos_e, x_8, n_15, r_4, lobe_7);
    return _e13;
}

float bvh_first(uint nodes_3, uint i_3, float3 x_9, float3 n_16, float3 r_5, float4 lobe_8)
{
    bool local_22 = (bool)0;

    const GpuLightBvhNode _e6 = light_bvh_node(nodes_3, i_3);
    uint j = _e6.second;
    if (!((j <= (i_3 + 1u)))) {
        const uint _e14 = light_bvh_count(nodes_3);
        local_22 = (j >= _e14);
    } else {
        local_22 = true;
    }
    bool _e17 = local_22;
    if (_e17) {
        return -1.0;
    }
    const float _e21 = bvh_importance(nodes_3, (i_3 + 1u), x_9, n_16, r_5, lobe_8);
    const float _e22 = bvh_importance(nodes_3, j, x_9, n_16, r_5, lobe_8);
    const float _e23 = bvh_first_prob(_e21, _e22);
    return _e23;
}

BvhPick ConstructBvhPick(uint arg0, float arg1) {
    BvhPick ret = (BvhPick)0;
    ret.light = arg0;
    ret.pmf = arg1;
    return ret;
}

BvhPick bvh_pick_none()
{
    const BvhPick bvhpick = ConstructBvhPick(0u, 0.0);
    return bvhpick;
}

BvhPick light_bvh_sample(uint nodes_4, float3 x_10, float3 n_17, float3 r_6, float4 lobe_9, float u_in)
{
    BvhPick pick = (BvhPick)0;
    float u_2 = (float)0;
    uint i_4 = 0u;
    float pmf = 1.0;
    bool local_23 = (bool)0;

    const BvhPick _e6 = bvh_pick_none();
    pick = _e6;
    u_2 = u_in;
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e13 = i_4;
        const uint _e14 = light_bvh_count(nodes_4);
        if ((_e13 < _e14)) {
        } else {
            break;
        }
        {
            uint _e16 = i_4;
            const GpuLightBvhNode _e17 = light_bvh_node(nodes_4, _e16);
            if ((_e17.second == LIGHT_BVH_LEAF)) {
                uint _e21 = i_4;
                if (!((_e21 > 0u))) {
                    const float _e28 = bvh_importance(nodes_4, 0u, x_10, n_17, r_6, lobe_9);
                    local_23 = (_e28 > 0.0);
                } else {
                    local_23 = true;
                }
                bool _e32 = local_23;
                if (_e32) {
                    pick.light = _e17.light;
                    float _e36 = pmf;
                    pick.pmf = _e36;
                }
                BvhPick _e37 = pick;
                const BvhPick bvhpick_1 = _e37;
                return bvhpick_1;
            }
            uint _e38 = i_4;
            const float _e39 = bvh_first(nodes_4, _e38, x_10, n_17, r_6, lobe_9);
            if ((_e39 < 0.0)) {
                BvhPick _e42 = pick;
                const BvhPick bvhpick_2 = _e42;
                return bvhpick_2;
            }
            float _e43 = u_2;
            bool first_1 = (_e43 < _e39);
            float _e45 = pmf;
            pmf = (_e45 * (first_1 ? _e39 : (1.0 - _e39)));
            float _e50 = u_2;
            const float _e51 = bvh_remap_u(_e50, _e39, first_1);
            u_2 = _e51;
            uint _e53 = i_4;
            i_4 = (first_1 ? (_e53 + 1u) : _e17.second);
        }
    }
    BvhPick _e57 = pick;
    const BvhPick bvhpick_3 = _e57;
    return bvhpick_3;
}

float light_pdf_selected(uint li_3, float3 x_11, float3 r_7, float4 rl_3, float3 y_1, float sel)
{
    GpuLight l_9 = ConstructGpuLight(asfloat(lights.Load3(li_3*64+0)), asuint(lights.Load(li_3*64+12)), asfloat(lights.Load3(li_3*64+16)), asfloat(lights.Load(li_3*64+28)), asfloat(lights.Load3(li_3*64+32)), asfloat(lights.Load(li_3*64+44)), asfloat(lights.Load3(li_3*64+48)), asuint(lights.Load(li_3*64+60)));
    float3 v_13 = (x_11 - y_1);
    float d2_11 = dot(v_13, v_13);
    const float3 _e11 = light_normal(l_9);
    float cos_y_1 = ((d2_11 > 0.0) ? dot(_e11, (v_13 / (sqrt(d2_11)).xxx)) : 0.0);
    const float _e20 = light_range_scale(li_3, x_11, r_7, rl_3);
    float _e23 = asfloat(rt2_5.Load(li_3*4));
    const float _e25 = light_area(l_9);
    const float _e26 = light_strategy_pdf(sel, (_e20 * _e23), d2_11, _e25, cos_y_1);
    return _e26;
}

float3 shade_pick(uint li_4, float3 x_12, float3 n_18, float3 ng_4, GpuMaterial m, float3 wo_1, float3 r_8, float4 lobe_10, float4 rl_4, float w_4, uint nee, float u1_5, float u2_5)
{
    float mis = 1.0;

    const float _e13 = light_range_scale(li_4, x_12, r_8, rl_4);
    float _e16 = params.eps;
    const Connection _e17 = connect(li_4, x_12, n_18, ng_4, _e13, w_4, u1_5, u2_5, _e16);
    if ((_e17.cos_x <= 0.0)) {
        return (0.0).xxx;
    }
    float3 l_10 = normalize((_e17.y - x_12));
    GpuLight _e30 = ConstructGpuLight(asfloat(lights.Load3(li_4*64+0)), asuint(lights.Load(li_4*64+12)), asfloat(lights.Load3(li_4*64+16)), asfloat(lights.Load(li_4*64+28)), asfloat(lights.Load3(li_4*64+32)), asfloat(lights.Load(li_4*64+44)), asfloat(lights.Load3(li_4*64+48)), asuint(lights.Load(li_4*64+60)));
    const float _e31 = light_area(_e30);
    if ((_e31 > 0.0)) {
        const float _e37 = light_pdf_selected(li_4, x_12, r_8, rl_4, _e17.y, (1.0 / w_4));
        const float _e39 = specular_probability(lobe_10);
        const float _e40 = bsdf_pdf(n_18, wo_1, l_10, m.alpha, _e39);
        const float _e41 = mis_weight(_e37, _e40);
        mis = _e41;
    }
    const float3 _e47 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, n_18, wo_1, l_10);
    float _e50 = mis;
    return ((_e47 * _e17.e) * _e50);
}

GpuPathVertex ConstructGpuPathVertex(float3 arg0, uint arg1, float3 arg2, uint arg3, float3 arg4, float arg5, float3 arg6, float arg7, float3 arg8, float arg9) {
    GpuPathVertex ret = (GpuPathVertex)0;
    ret.position = arg0;
    ret.alive = arg1;
    ret.normal = arg2;
    ret.material = arg3;
    ret.weight = arg4;
    ret.pad1_ = arg5;
    ret.gnormal = arg6;
    ret.pad2_ = arg7;
    ret.wo = arg8;
    ret.pad3_ = arg9;
    return ret;
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

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    uint h = (uint)0;
    float3 sum = (0.0).xxx;

    uint i_5 = gid.x;
    uint _e4 = params.point_count;
    if ((i_5 >= _e4)) {
        return;
    }
    GpuPathVertex vtx = ConstructGpuPathVertex(asfloat(vertices_.Load3(i_5*80+0)), asuint(vertices_.Load(i_5*80+12)), asfloat(vertices_.Load3(i_5*80+16)), asuint(vertices_.Load(i_5*80+28)), asfloat(vertices_.Load3(i_5*80+32)), asfloat(vertices_.Load(i_5*80+44)), asfloat(vertices_.Load3(i_5*80+48)), asfloat(vertices_.Load(i_5*80+60)), asfloat(vertices_.Load3(i_5*80+64)), asfloat(vertices_.Load(i_5*80+76)));
    if ((vtx.alive == 0u)) {
        candidates.Store(i_5*4, asuint(0u));
        return;
    }
    float3 x_13 = vtx.position;
    float3 n_21 = vtx.normal;
    float3 ng_5 = vtx.gnormal;
    GpuMaterial m_2 = ConstructGpuMaterial(asfloat(materials.Load3(vtx.material*48+0)), asfloat(materials.Load(vtx.material*48+12)), asfloat(materials.Load3(vtx.material*48+16)), asfloat(materials.Load(vtx.material*48+28)), asfloat(materials.Load3(vtx.material*48+32)), asfloat(materials.Load(vtx.material*48+44)));
    float3 wo_2 = vtx.wo;
    const float3 _e23 = mirror_dir(n_21, wo_2);
    const float4 _e30 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, dot(n_21, wo_2));
    const float4 _e31 = range_lobe(_e30);
    uint _e34 = params.seed;
    uint _e37 = params.frame;
    const uint _e38 = point_stream(_e34, i_5, _e37);
    const uint _e39 = pick_stream(_e38);
    h = _e39;
    candidates.Store(i_5*4, asuint(0u));
    uint _e47 = h;
    const uint _e48 = pcg_hash(_e47);
    h = _e48;
    uint _e49 = h;
    const float _e50 = xi_from_bits(_e49);
    const BvhPick _e52 = light_bvh_sample(BVH, x_13, n_21, _e23, _e30, _e50);
    uint li_5 = _e52.light;
    float pmf_1 = _e52.pmf;
    uint _e55 = h;
    const uint _e56 = pcg_hash(_e55);
    h = _e56;
    uint _e57 = h;
    const float _e58 = xi_from_bits(_e57);
    uint _e59 = h;
    const uint _e60 = pcg_hash(_e59);
    h = _e60;
    uint _e61 = h;
    const float _e62 = xi_from_bits(_e61);
    if ((pmf_1 > 0.0)) {
        const float3 _e68 = shade_pick(li_5, x_13, n_21, ng_5, m_2, wo_2, _e23, _e30, _e31, (1.0 / pmf_1), 0u, _e58, _e62);
        sum = _e68;
    }
    float3 _e70 = sum;
    float3 add = (vtx.weight * _e70);
    const bool _e72 = finite3_(add);
    if (_e72) {
        float4 _e75 = asfloat(radiance.Load4(i_5*16));
        radiance.Store4(i_5*16, asuint((_e75 + float4(add, 0.0))));
        return;
    } else {
        return;
    }
}
