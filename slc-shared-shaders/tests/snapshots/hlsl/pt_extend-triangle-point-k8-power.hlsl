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

struct GpuPathState {
    float3 origin;
    uint alive;
    float3 dir;
    uint rng;
    float3 beta;
    float pdf_bsdf;
    float3 prev;
    uint pad;
    float3 prev_normal;
    uint pad2_;
    float3 prev_r;
    uint pad3_;
    float4 prev_lobe;
};

struct PtParams {
    float3 cam_pos;
    uint width;
    float3 cam_right;
    uint height;
    float3 cam_up;
    uint depth;
    float3 cam_forward;
    uint seed;
    uint pass_index;
    uint max_depth;
    float eps;
    float t_min;
};

struct GpuMaterial {
    float3 albedo;
    float metallic;
    float3 emission;
    float alpha;
    float3 f0_;
    float f90_;
};

struct BshNode {
    float3 center_;
    float radius;
    uint child;
    uint next;
    uint light;
    float extent;
};

struct GeoHit {
    float t;
    uint tri;
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
static const uint BVH = 0u;
static const uint BSH = 0u;
static const uint BSH_TILE_DEPTH = 8u;
static const uint BSH_TILE_SUBTREES = 256u;

ByteAddressBuffer geo_nodes : register(t5);
ByteAddressBuffer geo_tris : register(t6);
ByteAddressBuffer light_cones : register(t2, space1);
ByteAddressBuffer rt2_2 : register(t2);
ByteAddressBuffer lights : register(t1);
cbuffer params : register(b0) { PtParams params; }
ByteAddressBuffer bsh_nodes : register(t3);
ByteAddressBuffer light_leaf : register(t4);
ByteAddressBuffer materials : register(t7);
ByteAddressBuffer geo_normals : register(t8);
ByteAddressBuffer candidates : register(t9);
RWByteAddressBuffer paths : register(u10);
RWByteAddressBuffer vertices_ : register(u11);
RWByteAddressBuffer radiance : register(u12);

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

float f32_from_bits(uint u_1)
{
    return asfloat(u_1);
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

uint path_stream(uint seed_1, uint pixel, uint pass_index)
{
    const uint _e4 = add_wrap_u32_(pass_index, PICK_STREAM);
    const uint _e5 = point_stream(seed_1, pixel, _e4);
    return _e5;
}

float rr_probability(float rt2_, float d2_)
{
    if ((d2_ <= rt2_)) {
        return 1.0;
    }
    return (rt2_ / d2_);
}

bool sphere_contains_point(float3 c, float r, float3 x_1)
{
    float3 v_10 = (x_1 - c);
    return (dot(v_10, v_10) <= (r * r));
}

float area_to_solid_angle_pdf(float pdf_area, float d2_1, float cos_light)
{
    float c_5 = abs(cos_light);
    if ((c_5 <= 0.0)) {
        return 0.0;
    }
    return ((pdf_area * d2_1) / c_5);
}

float bsh_scaled_radius(BshNode node, float scale)
{
    if ((scale == 1.0)) {
        return node.radius;
    }
    if ((node.child == BSH_NONE)) {
        return (node.extent + (scale * (node.radius - node.extent)));
    }
    return (node.radius * scale);
}

float bsh_range_bound(BshNode node_1)
{
    if ((node_1.child == BSH_NONE)) {
        return (node_1.radius - node_1.extent);
    }
    const float _e8 = f32_from_bits(node_1.light);
    return _e8;
}

float bsh_reach_bound(BshNode node_2, float w_1)
{
    const float _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_1 * 1.001) * _e5));
}

float reservoir_weight(uint n, uint k)
{
    const float _e2 = to_f32_(n);
    const float _e3 = to_f32_(k);
    return max((_e2 / _e3), 1.0);
}

float reservoir_select_pdf(uint seen, bool in_range, uint k_1)
{
    uint others = (uint)0;
    bool local_3 = (bool)0;

    others = seen;
    if (in_range) {
        local_3 = (seen > 0u);
    } else {
        local_3 = false;
    }
    bool _e9 = local_3;
    if (_e9) {
        others = (seen - 1u);
    }
    uint _e12 = others;
    const float _e15 = reservoir_weight((_e12 + 1u), k_1);
    return (1.0 / _e15);
}

float mis_power(float pdf_a, float pdf_b)
{
    float a2_ = (pdf_a * pdf_a);
    float s = (a2_ + (pdf_b * pdf_b));
    if ((s <= 0.0)) {
        return 0.0;
    }
    return (a2_ / s);
}

float light_strategy_pdf(float select_, float rt2_1, float d2_2, float area, float cos_y)
{
    bool local_4 = (bool)0;
    bool local_5 = (bool)0;

    if (!((d2_2 <= 0.0))) {
        local_4 = (area <= 0.0);
    } else {
        local_4 = true;
    }
    bool _e13 = local_4;
    if (!(_e13)) {
        local_5 = (cos_y <= 0.0);
    } else {
        local_5 = true;
    }
    bool _e20 = local_5;
    if (_e20) {
        return 0.0;
    }
    const float _e22 = rr_probability(rt2_1, d2_2);
    const float _e26 = area_to_solid_angle_pdf((1.0 / area), d2_2, cos_y);
    return ((select_ * _e22) * _e26);
}

float cosine_pdf(float cos_theta)
{
    return (max(cos_theta, 0.0) * INV_PI);
}

float3 onb_tangent(float3 n_1)
{
    float s_1 = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a_7 = (-1.0 / (s_1 + n_1.z));
    return float3((1.0 + (((s_1 * n_1.x) * n_1.x) * a_7)), (((s_1 * n_1.x) * n_1.y) * a_7), (-(s_1) * n_1.x));
}

float3 onb_bitangent(float3 n_2)
{
    float s_2 = ((n_2.z >= 0.0) ? 1.0 : -1.0);
    float a_8 = (-1.0 / (s_2 + n_2.z));
    return float3(((n_2.x * n_2.y) * a_8), (s_2 + ((n_2.y * n_2.y) * a_8)), -(n_2.y));
}

float3 onb_to_world(float3 n_3, float3 d)
{
    const float3 _e2 = onb_tangent(n_3);
    const float3 _e5 = onb_bitangent(n_3);
    return (((_e2 * d.x) + (_e5 * d.y)) + (n_3 * d.z));
}

float3 onb_to_local(float3 n_4, float3 w_2)
{
    const float3 _e2 = onb_tangent(n_4);
    const float3 _e4 = onb_bitangent(n_4);
    return float3(dot(w_2, _e2), dot(w_2, _e4), dot(w_2, n_4));
}

float3 cosine_direction(float3 n_5, float u1_, float u2_)
{
    float r_8 = sqrt(u1_);
    float phi = (6.2831855 * u2_);
    const float3 _e16 = onb_to_world(n_5, float3((r_8 * cos(phi)), (r_8 * sin(phi)), sqrt(max((1.0 - u1_), 0.0))));
    return normalize(_e16);
}

float ggx_d(float cos_h, float sin2_h, float alpha)
{
    if ((cos_h <= 0.0)) {
        return 0.0;
    }
    float a2_1 = (alpha * alpha);
    float t_1 = (((cos_h * cos_h) * a2_1) + sin2_h);
    return ((a2_1 * INV_PI) / (t_1 * t_1));
}

float smith_root(float cos_, float alpha_1)
{
    float a2_2 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1.0 - a2_2)) + a2_2));
}

float smith_visibility(float n_l, float n_v, float alpha_2)
{
    bool local_6 = (bool)0;

    if (!((n_l <= 0.0))) {
        local_6 = (n_v <= 0.0);
    } else {
        local_6 = true;
    }
    bool _e11 = local_6;
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

float half_cosine(float3 v_1, float3 l)
{
    float3 h_2 = (v_1 + l);
    float len2_ = dot(h_2, h_2);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return saturate((dot(v_1, h_2) / sqrt(len2_)));
}

float3 specular_brdf(float3 base_2, float metallic_2, float3 f0_d_2, float f90_d_2, float alpha_3, float3 n_6, float3 v_2, float3 l_1)
{
    bool local_7 = (bool)0;

    float n_l_1 = dot(n_6, l_1);
    float n_v_2 = dot(n_6, v_2);
    if (!((n_l_1 <= 0.0))) {
        local_7 = (n_v_2 <= 0.0);
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
    float3 c_7 = cross(n_6, h_3);
    const float _e32 = ggx_d(dot(n_6, h_3), dot(c_7, c_7), alpha_3);
    const float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_2, h_3));
    const float _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return (_e34 * (_e32 * _e35));
}

float3 brdf_eval(float3 base_3, float metallic_3, float3 f0_d_3, float f90_d_3, float alpha_4, float3 n_7, float3 v_3, float3 l_2)
{
    if ((dot(n_7, l_2) <= 0.0)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float _e15 = half_cosine(v_3, l_2);
    const float3 _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    const float3 _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_7, v_3, l_2);
    return (_e16 + _e17);
}

bool has_specular(float metallic_4, float3 f0_d_4, float f90_d_4)
{
    bool local_8 = (bool)0;
    bool local_9 = (bool)0;

    if (!((metallic_4 > 0.0))) {
        local_8 = (f90_d_4 > 0.0);
    } else {
        local_8 = true;
    }
    bool _e11 = local_8;
    if (!(_e11)) {
        local_9 = (max(max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0.0);
    } else {
        local_9 = true;
    }
    bool _e23 = local_9;
    return _e23;
}

float channel_mean(float3 c_1)
{
    return (((c_1.x + c_1.y) + c_1.z) * 0.33333334);
}

float4 receiver_lobe(float3 base_4, float metallic_5, float3 f0_d_5, float f90_d_5, float alpha_5, float n_v_1)
{
    bool local_10 = (bool)0;

    const float3 _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    const float _e16 = channel_mean((((float3(1.0, 1.0, 1.0) - _e10) * base_4) * (1.0 - metallic_5)));
    if (!((n_v_1 <= 0.0))) {
        const bool _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_10 = !(_e22);
    } else {
        local_10 = true;
    }
    bool _e25 = local_10;
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

float3 mirror_dir(float3 n_8, float3 v_4)
{
    return ((n_8 * (2.0 * dot(n_8, v_4))) - v_4);
}

float bounded_vndf_k(float3 wi, float alpha_6)
{
    float a_9 = saturate(alpha_6);
    float s_3 = (1.0 + sqrt(((wi.x * wi.x) + (wi.y * wi.y))));
    float a2_3 = (a_9 * a_9);
    float s2_ = (s_3 * s_3);
    return (((1.0 - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z)));
}

float3 ggx_vndf_sample(float3 wi_1, float alpha_7, float u1_1, float u2_1)
{
    float3 wi_std = normalize(float3((wi_1.x * alpha_7), (wi_1.y * alpha_7), wi_1.z));
    const float _e12 = bounded_vndf_k(wi_1, alpha_7);
    float b_5 = ((wi_1.z > 0.0) ? (_e12 * wi_std.z) : wi_std.z);
    float phi_1 = (6.2831855 * u1_1);
    float z = (((1.0 - u2_1) * (1.0 + b_5)) - b_5);
    float sin_t = sqrt(saturate((1.0 - (z * z))));
    float3 m_std = (wi_std + float3((sin_t * cos(phi_1)), (sin_t * sin(phi_1)), z));
    float3 m = normalize(float3((m_std.x * alpha_7), (m_std.y * alpha_7), m_std.z));
    return ((m * (2.0 * dot(wi_1, m))) - wi_1);
}

float ggx_vndf_pdf(float3 wi_2, float3 wo, float alpha_8)
{
    bool local_11 = (bool)0;

    if (!((wi_2.z <= 0.0))) {
        local_11 = (wo.z <= 0.0);
    } else {
        local_11 = true;
    }
    bool _e13 = local_11;
    if (_e13) {
        return 0.0;
    }
    float3 hs_1 = (wi_2 + wo);
    float3 m_1 = (hs_1 / (sqrt(dot(hs_1, hs_1))).xxx);
    const float _e28 = ggx_d(m_1.z, ((m_1.x * m_1.x) + (m_1.y * m_1.y)), alpha_8);
    float t_2 = sqrt((((alpha_8 * alpha_8) * ((wi_2.x * wi_2.x) + (wi_2.y * wi_2.y))) + (wi_2.z * wi_2.z)));
    const float _e43 = bounded_vndf_k(wi_2, alpha_8);
    return (_e28 / (2.0 * ((_e43 * wi_2.z) + t_2)));
}

float3 bsdf_sample(float3 n_9, float3 v_5, float alpha_9, float p_spec, float u1_2, float u2_2)
{
    if ((u1_2 < p_spec)) {
        if ((dot(n_9, v_5) <= 0.0)) {
            return -(n_9);
        }
        const float3 _e11 = onb_to_local(n_9, v_5);
        const float3 _e13 = ggx_vndf_sample(_e11, alpha_9, (u1_2 / p_spec), u2_2);
        const float3 _e14 = onb_to_world(n_9, _e13);
        return normalize(_e14);
    }
    const float3 _e20 = cosine_direction(n_9, ((u1_2 - p_spec) / (1.0 - p_spec)), u2_2);
    return _e20;
}

float bsdf_pdf(float3 n_10, float3 v_6, float3 l_3, float alpha_10, float p_spec_1)
{
    const float _e6 = cosine_pdf(dot(n_10, l_3));
    if ((p_spec_1 <= 0.0)) {
        return _e6;
    }
    const float3 _e9 = onb_to_local(n_10, v_6);
    const float3 _e10 = onb_to_local(n_10, l_3);
    const float _e11 = ggx_vndf_pdf(_e9, _e10, alpha_10);
    return ((p_spec_1 * _e11) + ((1.0 - p_spec_1) * _e6));
}

float cone_cos_of(float3 v_7, float d2_3, float a_2, float3 d_1)
{
    bool local_12 = (bool)0;
    bool local_13 = (bool)0;

    float vd = dot(v_7, d_1);
    float h2_ = (d2_3 - (a_2 * a_2));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_13 = ((vd * vd) >= h2_);
        } else {
            local_13 = false;
        }
        bool _e19 = local_13;
        local_12 = _e19;
    } else {
        local_12 = true;
    }
    bool _e21 = local_12;
    if (_e21) {
        return 1.0;
    }
    float3 c_8 = cross(v_7, d_1);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_8, c_8)) * a_2)) / d2_3), 1.0);
}

float cone_cos_toward(float3 center_, float radius, float3 p, float3 d_2)
{
    float3 v_11 = (center_ - p);
    const float _e6 = cone_cos_of(v_11, dot(v_11, v_11), radius, d_2);
    return _e6;
}

float range_scale_at(float4 rl, float cos_t)
{
    float t_3 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_3 * t_3))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(float4 rl_1, float3 center_1, float radius_1, float3 p_1, float3 r_1)
{
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    const float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_1);
    const float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

bool finite3_(float3 v_8)
{
    bool local_14 = (bool)0;
    bool local_15 = (bool)0;

    if ((abs(v_8.x) <= F32_MAX)) {
        local_14 = (abs(v_8.y) <= F32_MAX);
    } else {
        local_14 = false;
    }
    bool _e12 = local_14;
    if (_e12) {
        local_15 = (abs(v_8.z) <= F32_MAX);
    } else {
        local_15 = false;
    }
    bool _e20 = local_15;
    return _e20;
}

float ray_inverse(float x_2)
{
    return (1.0 / ((abs(x_2) < 1e-30) ? 1e-30 : x_2));
}

float3 ray_inverse3_(float3 d_3)
{
    const float _e2 = ray_inverse(d_3.x);
    const float _e4 = ray_inverse(d_3.y);
    const float _e6 = ray_inverse(d_3.z);
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

float3 triangle_normal(float3 a_3, float3 b_2, float3 c_2)
{
    bool local_16 = (bool)0;

    float3 n_15 = cross((b_2 - a_3), (c_2 - a_3));
    float l2_ = dot(n_15, n_15);
    if (!(!((l2_ > 0.0)))) {
        local_16 = !((l2_ < 3e38));
    } else {
        local_16 = true;
    }
    bool _e17 = local_16;
    if (_e17) {
        return float3(0.0, 0.0, 0.0);
    }
    return (n_15 / (sqrt(l2_)).xxx);
}

float3 face_against(float3 n_11, float3 dir)
{
    return ((dot(n_11, dir) > 0.0) ? -(n_11) : n_11);
}

float3 barycentric(float3 p_2, float3 a_4, float3 b_3, float3 c_3)
{
    float3 e1_ = (b_3 - a_4);
    float3 e2_ = (c_3 - a_4);
    float3 q = (p_2 - a_4);
    float d11_ = dot(e1_, e1_);
    float d12_ = dot(e1_, e2_);
    float d22_ = dot(e2_, e2_);
    float den = ((d11_ * d22_) - (d12_ * d12_));
    if (!((abs(den) > 0.0))) {
        return float3(1.0, 0.0, 0.0);
    }
    float w1_ = (((d22_ * dot(q, e1_)) - (d12_ * dot(q, e2_))) / den);
    float w2_ = (((d11_ * dot(q, e2_)) - (d12_ * dot(q, e1_))) / den);
    return float3(((1.0 - w1_) - w2_), w1_, w2_);
}

float3 shading_normal(float3 n0_, float3 n1_, float3 n2_, float3 w_3, float3 facing)
{
    bool local_17 = (bool)0;

    float3 s_4 = (((n0_ * w_3.x) + (n1_ * w_3.y)) + (n2_ * w_3.z));
    float l2_1 = dot(s_4, s_4);
    if (!(!((l2_1 > 1e-12)))) {
        local_17 = !((l2_1 < 3e38));
    } else {
        local_17 = true;
    }
    bool _e24 = local_17;
    if (_e24) {
        return facing;
    }
    float3 n_16 = (s_4 / (sqrt(l2_1)).xxx);
    return ((dot(n_16, facing) < 0.0) ? -(n_16) : n_16);
}

float ray_triangle(float3 o_1, float3 d_4, float3 a_5, float3 b_4, float3 c_4, float t_min, float t_max_1)
{
    bool local_18 = (bool)0;
    bool local_19 = (bool)0;
    bool local_20 = (bool)0;

    float3 e1_1 = (b_4 - a_5);
    float3 e2_1 = (c_4 - a_5);
    float3 p_3 = cross(d_4, e2_1);
    float det = dot(e1_1, p_3);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv_1 = (1.0 / det);
    float3 s_5 = (o_1 - a_5);
    float u_3 = (dot(s_5, p_3) * inv_1);
    if (!((u_3 < 0.0))) {
        local_18 = (u_3 > 1.0);
    } else {
        local_18 = true;
    }
    bool _e28 = local_18;
    if (_e28) {
        return -1.0;
    }
    float3 q_1 = cross(s_5, e1_1);
    float v_12 = (dot(d_4, q_1) * inv_1);
    if (!((v_12 < 0.0))) {
        local_19 = ((u_3 + v_12) > 1.0);
    } else {
        local_19 = true;
    }
    bool _e42 = local_19;
    if (_e42) {
        return -1.0;
    }
    float t_4 = (dot(e2_1, q_1) * inv_1);
    if ((t_4 > t_min)) {
        local_20 = (t_4 < t_max_1);
    } else {
        local_20 = false;
    }
    bool _e51 = local_20;
    if (_e51) {
        return t_4;
    }
    return -1.0;
}

float3 camera_dir(float3 forward, float3 right, float3 up, float px, float py, float w_4, float h_1)
{
    float sx = (((2.0 * px) / w_4) - 1.0);
    float sy = (1.0 - ((2.0 * py) / h_1));
    return normalize(((forward + (right * sx)) + (up * sy)));
}

float jittered_pixel(uint coord, float u_2)
{
    const float _e2 = to_f32_(coord);
    return (_e2 + u_2);
}

bool plays_roulette(uint depth)
{
    return (depth >= ROULETTE_DEPTH);
}

bool sees_emission(float3 gn, float3 dir_1)
{
    return (dot(gn, dir_1) < 0.0);
}

bool continues_path(float3 nd, float3 n_12, float3 ng)
{
    bool local_21 = (bool)0;

    if ((dot(nd, n_12) > 0.0)) {
        local_21 = (dot(nd, ng) > 0.0);
    } else {
        local_21 = false;
    }
    bool _e12 = local_21;
    return _e12;
}

float path_survival(float3 beta)
{
    return clamp(max(max(beta.x, beta.y), beta.z), 0.05, 0.95);
}

float light_area(GpuLight l_4)
{
    if ((l_4.kind == LIGHT_TRIANGLE)) {
        return l_4.a;
    }
    return 0.0;
}

float3 light_normal(GpuLight l_5)
{
    if ((l_5.kind == LIGHT_TRIANGLE)) {
        const float3 _e7 = triangle_normal(l_5.p0_, l_5.p1_, l_5.p2_);
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

GeoHit trace(float3 o_2, float3 d_5, float t_min_1, float t_max_2, bool any_hit)
{
    GeoHit hit = (GeoHit)0;
    uint stack[64] = (uint[64])0;
    uint sp = 0u;
    uint node_3 = 0u;
    uint i = (uint)0;

    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((((NagaBufferLength(geo_nodes) - 0) / 32) == 0u)) {
        GeoHit _e13 = hit;
        const GeoHit geohit = _e13;
        return geohit;
    }
    const float3 _e14 = ray_inverse3_(d_5);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e21 = node_3;
        GpuGeoNode n_17 = ConstructGpuGeoNode(asfloat(geo_nodes.Load3(_e21*32+0)), asuint(geo_nodes.Load(_e21*32+12)), asfloat(geo_nodes.Load3(_e21*32+16)), asuint(geo_nodes.Load(_e21*32+28)));
        float _e27 = hit.t;
        const float _e28 = ray_aabb(o_2, _e14, n_17.bmin, n_17.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_17.count > 0u)) {
                i = n_17.first;
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
                    if ((_e36 < (n_17.first + n_17.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_5 = ConstructGpuTriangle(asfloat(geo_tris.Load3(_e42*48+0)), asuint(geo_tris.Load(_e42*48+12)), asfloat(geo_tris.Load3(_e42*48+16)), asuint(geo_tris.Load(_e42*48+28)), asfloat(geo_tris.Load3(_e42*48+32)), asuint(geo_tris.Load(_e42*48+44)));
                        float _e49 = hit.t;
                        const float _e50 = ray_triangle(o_2, d_5, t_5.v0_, t_5.v1_, t_5.v2_, t_min_1, _e49);
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
                    stack[min(uint(_e63), 63u)] = (n_17.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_17.first;
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
        node_3 = _e80;
    }
    GeoHit _e81 = hit;
    const GeoHit geohit_2 = _e81;
    return geohit_2;
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

float light_range_scale(uint li, float3 x_3, float3 r_2, float4 rl_2)
{
    GpuLightCone c_9 = ConstructGpuLightCone(asfloat(light_cones.Load3(li*48+0)), asfloat(light_cones.Load(li*48+12)), asfloat(light_cones.Load3(li*48+16)), asfloat(light_cones.Load(li*48+28)), asfloat(light_cones.Load(li*48+32)), asfloat(light_cones.Load(li*48+36)), asuint(light_cones.Load(li*48+40)), asuint(light_cones.Load(li*48+44)));
    const float _e9 = range_scale_toward(rl_2, c_9.center_, c_9.radius, x_3, r_2);
    return _e9;
}

float select_pdf(uint li_1, float3 x_4, float3 n_13, float3 r_3, float4 lobe_5, float4 rl_3, uint nee, bool in_range_1)
{
    const float _e9 = reservoir_select_pdf(nee, in_range_1, K);
    return _e9;
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

float light_pdf_selected(uint li_2, float3 x_5, float3 r_4, float4 rl_4, float3 y, float sel)
{
    GpuLight l_6 = ConstructGpuLight(asfloat(lights.Load3(li_2*64+0)), asuint(lights.Load(li_2*64+12)), asfloat(lights.Load3(li_2*64+16)), asfloat(lights.Load(li_2*64+28)), asfloat(lights.Load3(li_2*64+32)), asfloat(lights.Load(li_2*64+44)), asfloat(lights.Load3(li_2*64+48)), asuint(lights.Load(li_2*64+60)));
    float3 v_13 = (x_5 - y);
    float d2_5 = dot(v_13, v_13);
    const float3 _e11 = light_normal(l_6);
    float cos_y_1 = ((d2_5 > 0.0) ? dot(_e11, (v_13 / (sqrt(d2_5)).xxx)) : 0.0);
    const float _e20 = light_range_scale(li_2, x_5, r_4, rl_4);
    float _e23 = asfloat(rt2_2.Load(li_2*4));
    const float _e25 = light_area(l_6);
    const float _e26 = light_strategy_pdf(sel, (_e20 * _e23), d2_5, _e25, cos_y_1);
    return _e26;
}

float light_pdf(uint li_3, float3 x_6, float3 n_14, float3 r_5, float4 lobe_6, float4 rl_5, float3 y_1, uint nee_1, bool in_range_2)
{
    const float _e9 = select_pdf(li_3, x_6, n_14, r_5, lobe_6, rl_5, nee_1, in_range_2);
    const float _e10 = light_pdf_selected(li_3, x_6, r_5, rl_5, y_1, _e9);
    return _e10;
}

BshNode ConstructBshNode(float3 arg0, float arg1, uint arg2, uint arg3, uint arg4, float arg5) {
    BshNode ret = (BshNode)0;
    ret.center_ = arg0;
    ret.radius = arg1;
    ret.child = arg2;
    ret.next = arg3;
    ret.light = arg4;
    ret.extent = arg5;
    return ret;
}

BshNode bsh_node(uint nodes, uint i_1)
{
    BshNode _e4 = ConstructBshNode(asfloat(bsh_nodes.Load3(i_1*32+0)), asfloat(bsh_nodes.Load(i_1*32+12)), asuint(bsh_nodes.Load(i_1*32+16)), asuint(bsh_nodes.Load(i_1*32+20)), asuint(bsh_nodes.Load(i_1*32+24)), asfloat(bsh_nodes.Load(i_1*32+28)));
    const BshNode bshnode = _e4;
    return bshnode;
}

float bsh_inner_scale(float a_6, float3 v_9, float d2_4, float3 r_6, float4 rl_6)
{
    const float _e5 = cone_cos_of(v_9, d2_4, a_6, r_6);
    const float _e8 = range_scale_at(rl_6, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_4, float3 x_7, float3 r_7, float4 rl_7)
{
    bool local_22 = (bool)0;
    bool local_23 = (bool)0;

    const bool _e6 = sphere_contains_point(node_4.center_, node_4.radius, x_7);
    if (_e6) {
        return true;
    }
    if (!((rl_7.w <= 1.0))) {
        const bool _e20 = sphere_contains_point(node_4.center_, (node_4.radius * (rl_7.w * 1.0001)), x_7);
        local_22 = !(_e20);
    } else {
        local_22 = true;
    }
    bool _e23 = local_22;
    if (_e23) {
        return false;
    }
    float3 v_14 = (x_7 - node_4.center_);
    float d2_6 = dot(v_14, v_14);
    const float _e29 = bsh_reach_bound(node_4, rl_7.w);
    if ((d2_6 > (_e29 * _e29))) {
        return false;
    }
    if ((node_4.child == BSH_NONE)) {
        const float _e38 = range_scale_toward(rl_7, node_4.center_, node_4.extent, x_7, r_7);
        const float _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        const bool _e42 = sphere_contains_point(node_4.center_, _e41, x_7);
        return _e42;
    }
    const float _e45 = bsh_inner_scale(node_4.extent, -(v_14), d2_6, r_7, rl_7);
    float s_c = (_e45 * 1.001);
    const float _e50 = bsh_range_bound(node_4);
    float reach = (node_4.extent + (sqrt(s_c) * _e50));
    if ((d2_6 <= ((node_4.radius * node_4.radius) * s_c))) {
        local_23 = (d2_6 <= (reach * reach));
    } else {
        local_23 = false;
    }
    bool _e63 = local_23;
    return _e63;
}

BshNode bsh_range_leaf(uint nodes_1, uint i_2)
{
    uint t = (uint)0;

    const BshNode _e2 = bsh_node(nodes_1, i_2);
    if (((_e2.light & BSH_TAIL) == 0u)) {
        const BshNode bshnode_1 = _e2;
        return bshnode_1;
    }
    uint li_4 = (_e2.light & 2147483647u);
    const BshNode _e12 = bsh_node(nodes_1, 0u);
    t = _e12.next;
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e15 = t;
        if ((_e15 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e18 = t;
            const BshNode _e19 = bsh_node(nodes_1, _e18);
            if ((_e19.light == li_4)) {
                const BshNode bshnode_2 = _e19;
                return bshnode_2;
            }
            t = _e19.next;
        }
    }
    const BshNode bshnode_3 = _e2;
    return bshnode_3;
}

float next_uniform(inout uint state)
{
    uint _e1 = state;
    const uint _e2 = pcg_hash(_e1);
    state = _e2;
    uint _e3 = state;
    const float _e4 = xi_from_bits(_e3);
    return _e4;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

GpuPathState ConstructGpuPathState(float3 arg0, uint arg1, float3 arg2, uint arg3, float3 arg4, float arg5, float3 arg6, uint arg7, float3 arg8, uint arg9, float3 arg10, uint arg11, float4 arg12) {
    GpuPathState ret = (GpuPathState)0;
    ret.origin = arg0;
    ret.alive = arg1;
    ret.dir = arg2;
    ret.rng = arg3;
    ret.beta = arg4;
    ret.pdf_bsdf = arg5;
    ret.prev = arg6;
    ret.pad = arg7;
    ret.prev_normal = arg8;
    ret.pad2_ = arg9;
    ret.prev_r = arg10;
    ret.pad3_ = arg11;
    ret.prev_lobe = arg12;
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
    GpuPathState st = (GpuPathState)0;
    uint h = (uint)0;
    GpuPathVertex v = (GpuPathVertex)0;
    bool local = (bool)0;
    float w = 1.0;
    uint rng = (uint)0;
    bool local_1 = (bool)0;
    bool local_2 = (bool)0;

    uint i_3 = gid.x;
    uint _e4 = params.width;
    uint _e7 = params.height;
    if ((i_3 >= (_e4 * _e7))) {
        return;
    }
    uint _e13 = params.depth;
    if ((_e13 == 0u)) {
        uint _e18 = params.seed;
        uint _e21 = params.pass_index;
        const uint _e22 = path_stream(_e18, i_3, _e21);
        h = _e22;
        uint _e26 = params.width;
        const float _e28 = next_uniform(h);
        const float _e29 = jittered_pixel(naga_mod(i_3, _e26), _e28);
        uint _e32 = params.width;
        const float _e34 = next_uniform(h);
        const float _e35 = jittered_pixel(naga_div(i_3, _e32), _e34);
        float3 _e39 = params.cam_pos;
        st.origin = _e39;
        float3 _e43 = params.cam_forward;
        float3 _e46 = params.cam_right;
        float3 _e49 = params.cam_up;
        uint _e52 = params.width;
        uint _e56 = params.height;
        const float3 _e58 = camera_dir(_e43, _e46, _e49, _e29, _e35, float(_e52), float(_e56));
        st.dir = _e58;
        st.alive = 1u;
        uint _e62 = h;
        st.rng = _e62;
        st.beta = (1.0).xxx;
        st.pdf_bsdf = 0.0;
        float3 _e71 = params.cam_pos;
        st.prev = _e71;
    } else {
        GpuPathState _e74 = ConstructGpuPathState(asfloat(paths.Load3(i_3*112+0)), asuint(paths.Load(i_3*112+12)), asfloat(paths.Load3(i_3*112+16)), asuint(paths.Load(i_3*112+28)), asfloat(paths.Load3(i_3*112+32)), asfloat(paths.Load(i_3*112+44)), asfloat(paths.Load3(i_3*112+48)), asuint(paths.Load(i_3*112+60)), asfloat(paths.Load3(i_3*112+64)), asuint(paths.Load(i_3*112+76)), asfloat(paths.Load3(i_3*112+80)), asuint(paths.Load(i_3*112+92)), asfloat(paths.Load4(i_3*112+96)));
        st = _e74;
    }
    v.alive = 0u;
    uint _e79 = st.alive;
    if ((_e79 == 0u)) {
        GpuPathVertex _e84 = v;
        {
            GpuPathVertex _value3 = _e84;
            vertices_.Store3(i_3*80+0, asuint(_value3.position));
            vertices_.Store(i_3*80+12, asuint(_value3.alive));
            vertices_.Store3(i_3*80+16, asuint(_value3.normal));
            vertices_.Store(i_3*80+28, asuint(_value3.material));
            vertices_.Store3(i_3*80+32, asuint(_value3.weight));
            vertices_.Store(i_3*80+44, asuint(_value3.pad1_));
            vertices_.Store3(i_3*80+48, asuint(_value3.gnormal));
            vertices_.Store(i_3*80+60, asuint(_value3.pad2_));
            vertices_.Store3(i_3*80+64, asuint(_value3.wo));
            vertices_.Store(i_3*80+76, asuint(_value3.pad3_));
        }
        return;
    }
    float3 _e86 = st.origin;
    float3 _e88 = st.dir;
    float _e91 = params.t_min;
    const GeoHit _e94 = trace(_e86, _e88, _e91, F32_MAX, false);
    if ((_e94.tri == NO_LIGHT)) {
        st.alive = 0u;
        GpuPathState _e102 = st;
        {
            GpuPathState _value3 = _e102;
            paths.Store3(i_3*112+0, asuint(_value3.origin));
            paths.Store(i_3*112+12, asuint(_value3.alive));
            paths.Store3(i_3*112+16, asuint(_value3.dir));
            paths.Store(i_3*112+28, asuint(_value3.rng));
            paths.Store3(i_3*112+32, asuint(_value3.beta));
            paths.Store(i_3*112+44, asuint(_value3.pdf_bsdf));
            paths.Store3(i_3*112+48, asuint(_value3.prev));
            paths.Store(i_3*112+60, asuint(_value3.pad));
            paths.Store3(i_3*112+64, asuint(_value3.prev_normal));
            paths.Store(i_3*112+76, asuint(_value3.pad2_));
            paths.Store3(i_3*112+80, asuint(_value3.prev_r));
            paths.Store(i_3*112+92, asuint(_value3.pad3_));
            paths.Store4(i_3*112+96, asuint(_value3.prev_lobe));
        }
        GpuPathVertex _e105 = v;
        {
            GpuPathVertex _value3 = _e105;
            vertices_.Store3(i_3*80+0, asuint(_value3.position));
            vertices_.Store(i_3*80+12, asuint(_value3.alive));
            vertices_.Store3(i_3*80+16, asuint(_value3.normal));
            vertices_.Store(i_3*80+28, asuint(_value3.material));
            vertices_.Store3(i_3*80+32, asuint(_value3.weight));
            vertices_.Store(i_3*80+44, asuint(_value3.pad1_));
            vertices_.Store3(i_3*80+48, asuint(_value3.gnormal));
            vertices_.Store(i_3*80+60, asuint(_value3.pad2_));
            vertices_.Store3(i_3*80+64, asuint(_value3.wo));
            vertices_.Store(i_3*80+76, asuint(_value3.pad3_));
        }
        return;
    }
    GpuTriangle tri = ConstructGpuTriangle(asfloat(geo_tris.Load3(_e94.tri*48+0)), asuint(geo_tris.Load(_e94.tri*48+12)), asfloat(geo_tris.Load3(_e94.tri*48+16)), asuint(geo_tris.Load(_e94.tri*48+28)), asfloat(geo_tris.Load3(_e94.tri*48+32)), asuint(geo_tris.Load(_e94.tri*48+44)));
    float3 _e111 = st.origin;
    float3 _e113 = st.dir;
    float3 x_8 = (_e111 + (_e113 * _e94.t));
    const float3 _e120 = triangle_normal(tri.v0_, tri.v1_, tri.v2_);
    float3 _e122 = st.dir;
    const float3 _e123 = face_against(_e120, _e122);
    uint b_6 = (_e94.tri * 3u);
    float4 _e129 = asfloat(geo_normals.Load4(b_6*16));
    float4 _e135 = asfloat(geo_normals.Load4((b_6 + 1u)*16));
    float4 _e141 = asfloat(geo_normals.Load4((b_6 + 2u)*16));
    const float3 _e146 = barycentric(x_8, tri.v0_, tri.v1_, tri.v2_);
    const float3 _e147 = shading_normal(_e129.xyz, _e135.xyz, _e141.xyz, _e146, _e123);
    if ((tri.light != NO_LIGHT)) {
        float3 _e154 = st.dir;
        const bool _e155 = sees_emission(_e120, _e154);
        local = _e155;
    } else {
        local = false;
    }
    bool _e157 = local;
    if (_e157) {
        float _e161 = st.pdf_bsdf;
        if ((_e161 > 0.0)) {
            uint _e168 = asuint(light_leaf.Load(tri.light*4));
            const BshNode _e169 = bsh_range_leaf(BSH, _e168);
            float4 _e171 = st.prev_lobe;
            const float4 _e172 = range_lobe(_e171);
            float3 _e174 = st.prev;
            float3 _e176 = st.prev_r;
            const bool _e177 = bsh_reaches(_e169, _e174, _e176, _e172);
            float _e179 = st.pdf_bsdf;
            float3 _e182 = st.prev;
            float3 _e184 = st.prev_normal;
            float3 _e186 = st.prev_r;
            float4 _e188 = st.prev_lobe;
            uint _e191 = asuint(candidates.Load(i_3*4));
            const float _e192 = light_pdf(tri.light, _e182, _e184, _e186, _e188, _e172, x_8, _e191, _e177);
            const float _e193 = mis_weight(_e179, _e192);
            w = _e193;
        }
        float3 _e195 = st.beta;
        float3 _e200 = asfloat(lights.Load3(48+tri.light*64));
        float _e202 = w;
        float3 add = ((_e195 * _e200) * _e202);
        const bool _e204 = finite3_(add);
        if (_e204) {
            float4 _e207 = asfloat(radiance.Load4(i_3*16));
            radiance.Store4(i_3*16, asuint((_e207 + float4(add, 0.0))));
        }
    }
    uint _e213 = params.depth;
    uint _e216 = params.max_depth;
    if ((_e213 >= _e216)) {
        st.alive = 0u;
        GpuPathState _e222 = st;
        {
            GpuPathState _value3 = _e222;
            paths.Store3(i_3*112+0, asuint(_value3.origin));
            paths.Store(i_3*112+12, asuint(_value3.alive));
            paths.Store3(i_3*112+16, asuint(_value3.dir));
            paths.Store(i_3*112+28, asuint(_value3.rng));
            paths.Store3(i_3*112+32, asuint(_value3.beta));
            paths.Store(i_3*112+44, asuint(_value3.pdf_bsdf));
            paths.Store3(i_3*112+48, asuint(_value3.prev));
            paths.Store(i_3*112+60, asuint(_value3.pad));
            paths.Store3(i_3*112+64, asuint(_value3.prev_normal));
            paths.Store(i_3*112+76, asuint(_value3.pad2_));
            paths.Store3(i_3*112+80, asuint(_value3.prev_r));
            paths.Store(i_3*112+92, asuint(_value3.pad3_));
            paths.Store4(i_3*112+96, asuint(_value3.prev_lobe));
        }
        GpuPathVertex _e225 = v;
        {
            GpuPathVertex _value3 = _e225;
            vertices_.Store3(i_3*80+0, asuint(_value3.position));
            vertices_.Store(i_3*80+12, asuint(_value3.alive));
            vertices_.Store3(i_3*80+16, asuint(_value3.normal));
            vertices_.Store(i_3*80+28, asuint(_value3.material));
            vertices_.Store3(i_3*80+32, asuint(_value3.weight));
            vertices_.Store(i_3*80+44, asuint(_value3.pad1_));
            vertices_.Store3(i_3*80+48, asuint(_value3.gnormal));
            vertices_.Store(i_3*80+60, asuint(_value3.pad2_));
            vertices_.Store3(i_3*80+64, asuint(_value3.wo));
            vertices_.Store(i_3*80+76, asuint(_value3.pad3_));
        }
        return;
    }
    GpuMaterial m_2 = ConstructGpuMaterial(asfloat(materials.Load3(tri.material*48+0)), asfloat(materials.Load(tri.material*48+12)), asfloat(materials.Load3(tri.material*48+16)), asfloat(materials.Load(tri.material*48+28)), asfloat(materials.Load3(tri.material*48+32)), asfloat(materials.Load(tri.material*48+44)));
    float3 _e231 = st.dir;
    float3 wo_1 = -(_e231);
    const float4 _e239 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, dot(_e147, wo_1));
    v.position = x_8;
    v.normal = _e147;
    v.material = tri.material;
    v.gnormal = _e123;
    float3 _e247 = st.beta;
    v.weight = _e247;
    v.wo = wo_1;
    v.alive = 1u;
    GpuPathVertex _e253 = v;
    {
        GpuPathVertex _value2 = _e253;
        vertices_.Store3(i_3*80+0, asuint(_value2.position));
        vertices_.Store(i_3*80+12, asuint(_value2.alive));
        vertices_.Store3(i_3*80+16, asuint(_value2.normal));
        vertices_.Store(i_3*80+28, asuint(_value2.material));
        vertices_.Store3(i_3*80+32, asuint(_value2.weight));
        vertices_.Store(i_3*80+44, asuint(_value2.pad1_));
        vertices_.Store3(i_3*80+48, asuint(_value2.gnormal));
        vertices_.Store(i_3*80+60, asuint(_value2.pad2_));
        vertices_.Store3(i_3*80+64, asuint(_value2.wo));
        vertices_.Store(i_3*80+76, asuint(_value2.pad3_));
    }
    uint _e255 = st.rng;
    rng = _e255;
    const float _e257 = next_uniform(rng);
    const float _e258 = next_uniform(rng);
    const float _e259 = specular_probability(_e239);
    const float3 _e261 = bsdf_sample(_e147, wo_1, m_2.alpha, _e259, _e257, _e258);
    const float _e263 = bsdf_pdf(_e147, wo_1, _e261, m_2.alpha, _e259);
    const bool _e267 = has_specular(m_2.metallic, m_2.f0_, m_2.f90_);
    if (_e267) {
        float3 _e269 = st.beta;
        const float3 _e275 = brdf_eval(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, _e147, wo_1, _e261);
        st.beta = (_e269 * (_e275 * (dot(_e261, _e147) / _e263)));
    } else {
        float3 _e281 = st.beta;
        st.beta = (_e281 * m_2.albedo);
    }
    st.prev = x_8;
    st.prev_normal = _e147;
    const float3 _e287 = mirror_dir(_e147, wo_1);
    st.prev_r = _e287;
    st.prev_lobe = _e239;
    st.pdf_bsdf = _e263;
    float _e293 = params.eps;
    st.origin = (x_8 + (_e123 * _e293));
    st.dir = _e261;
    const bool _e297 = continues_path(_e261, _e147, _e123);
    if (!(!(_e297))) {
        local_1 = !((_e263 > 0.0));
    } else {
        local_1 = true;
    }
    bool _e306 = local_1;
    if (_e306) {
        st.alive = 0u;
    }
    uint _e311 = params.depth;
    const bool _e312 = plays_roulette(_e311);
    if (_e312) {
        uint _e316 = st.alive;
        local_2 = (_e316 == 1u);
    } else {
        local_2 = false;
    }
    bool _e320 = local_2;
    if (_e320) {
        float3 _e322 = st.beta;
        const float _e323 = path_survival(_e322);
        const float _e324 = next_uniform(rng);
        if ((_e324 >= _e323)) {
            st.alive = 0u;
        } else {
            float3 _e329 = st.beta;
            st.beta = (_e329 / (_e323).xxx);
        }
    }
    uint _e333 = rng;
    st.rng = _e333;
    GpuPathState _e336 = st;
    {
        GpuPathState _value2 = _e336;
        paths.Store3(i_3*112+0, asuint(_value2.origin));
        paths.Store(i_3*112+12, asuint(_value2.alive));
        paths.Store3(i_3*112+16, asuint(_value2.dir));
        paths.Store(i_3*112+28, asuint(_value2.rng));
        paths.Store3(i_3*112+32, asuint(_value2.beta));
        paths.Store(i_3*112+44, asuint(_value2.pdf_bsdf));
        paths.Store3(i_3*112+48, asuint(_value2.prev));
        paths.Store(i_3*112+60, asuint(_value2.pad));
        paths.Store3(i_3*112+64, asuint(_value2.prev_normal));
        paths.Store(i_3*112+76, asuint(_value2.pad2_));
        paths.Store3(i_3*112+80, asuint(_value2.prev_r));
        paths.Store(i_3*112+92, asuint(_value2.pad3_));
        paths.Store4(i_3*112+96, asuint(_value2.prev_lobe));
    }
    return;
}
