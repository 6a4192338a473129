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

struct Connection {
    float3 e;
    int _pad1_0;
    float3 y;
    float cos_x;
};

struct WorkgroupBox {
    float3 lo;
    int _pad1_0;
    float3 hi;
    int _end_pad_0;
};

struct TileWalk {
    float3 lo;
    int _pad1_0;
    float3 hi;
    float w;
    uint total;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct Shaded {
    float3 e;
    int _pad1_0;
    float3 diffuse;
    int _pad2_0;
    float3 specular;
    int _end_pad_0;
};

struct Material {
    float3 base;
    float metallic;
    float alpha;
    int _pad3_0;
    int _pad3_1;
    int _pad3_2;
    float3 v;
    float roughness;
    float reflectance;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
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
static const uint TILE_THREADS = 64u;
static const uint BOX_THREADS = 64u;
static const uint TILE_LIST = 1024u;

ByteAddressBuffer geo_nodes : register(t6, space1);
ByteAddressBuffer geo_tris : register(t7, space1);
cbuffer view : register(b0) { ViewParams view; }
Texture2D<float4> position_tex : register(t1);
Texture2D<float4> normal_tex : register(t2);
RWTexture2D<float4> out_tex : register(u3);
Texture2D<float4> base_color_tex : register(t4);
Texture2D<float4> metal_rough_tex : register(t5);
ByteAddressBuffer lights : register(t1, space1);
ByteAddressBuffer rt2_3 : register(t2, space1);
ByteAddressBuffer r2_3 : register(t3, space1);
ByteAddressBuffer bsh_nodes : register(t4, space1);
ByteAddressBuffer light_cones : register(t5, space1);
groupshared float3 wg_lo[64];
groupshared float3 wg_hi[64];
groupshared WorkgroupBox wg_box;
groupshared uint tile_list[1024];
groupshared uint subtree_at[256];
groupshared uint tile_scale;
groupshared uint tile_total;

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

uint pick_stream(uint stream)
{
    const uint _e3 = pcg_hash((stream ^ PICK_STREAM));
    return _e3;
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

bool sphere_contains_point(float3 c, float r_1, float3 x_1)
{
    float3 v_5 = (x_1 - c);
    return (dot(v_5, v_5) <= (r_1 * r_1));
}

bool sphere_overlaps_aabb(float3 c_1, float r_2, float3 bmin, float3 bmax)
{
    float3 q_1 = clamp(c_1, bmin, bmax);
    float3 v_6 = (q_1 - c_1);
    return (dot(v_6, v_6) <= (r_2 * r_2));
}

float inverse_square(float d2_2)
{
    return (1.0 / max(d2_2, MIN_D2_));
}

float connection_factor(float cos_x, float d2_3, float rt2_1, float w_1)
{
    const float _e4 = inverse_square(d2_3);
    const float _e6 = slc_weight(rt2_1, d2_3);
    return (((cos_x * _e4) * _e6) * w_1);
}

float connection_cosine(float3 x_2, float3 y, float3 n_1, float3 ng, float r2_1)
{
    bool local_7 = (bool)0;
    bool local_8 = (bool)0;

    float3 v_7 = (x_2 - y);
    float d2_6 = dot(v_7, v_7);
    const bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local_7 = !((d2_6 > 0.0));
    } else {
        local_7 = true;
    }
    bool _e16 = local_7;
    if (_e16) {
        return 0.0;
    }
    float3 w_11 = (v_7 / (sqrt(d2_6)).xxx);
    float cos_x_1 = -(dot(n_1, w_11));
    if (!(!((cos_x_1 > 0.0)))) {
        local_8 = !((dot(ng, w_11) < 0.0));
    } else {
        local_8 = true;
    }
    bool _e34 = local_8;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float triangle_lobe(float3 n_2, float area, float3 w_2)
{
    return (area * max(dot(n_2, w_2), 0.0));
}

float3 triangle_sample(float3 a_2, float3 b_2, float3 c_2, float u1_, float u2_)
{
    float su = sqrt(u1_);
    float b0_ = (1.0 - su);
    float b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_2 * ((1.0 - b0_) - b1_)));
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

float bsh_reach_bound(BshNode node_2, float w_3)
{
    const float _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_3 * 1.001) * _e5));
}

float weighted_threshold(float w_sum, float u_2)
{
    return (w_sum / (1.0 - u_2));
}

float resample_target(float3 c_3)
{
    return (((c_3.x + c_3.y) + c_3.z) * 0.33333334);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

float slot_target(float3 c_4, uint slot, uint k_2)
{
    if ((k_2 < 3u)) {
        const float _e5 = resample_target(c_4);
        return _e5;
    }
    uint j_3 = naga_mod(slot, 3u);
    if ((j_3 == 0u)) {
        return c_4.x;
    }
    if ((j_3 == 1u)) {
        return c_4.y;
    }
    return c_4.z;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

float3 slot_share(uint slot_1, uint k_3)
{
    if ((k_3 < 3u)) {
        const float _e4 = to_f32_(k_3);
        float w_12 = (1.0 / _e4);
        return float3(w_12, w_12, w_12);
    }
    uint j_4 = naga_mod(slot_1, 3u);
    const float _e15 = to_f32_(naga_div(((k_3 + 2u) - j_4), 3u));
    float w_13 = (1.0 / _e15);
    if ((j_4 == 0u)) {
        return float3(w_13, 0.0, 0.0);
    }
    if ((j_4 == 1u)) {
        return float3(0.0, w_13, 0.0);
    }
    return float3(0.0, 0.0, w_13);
}

float ggx_d(float cos_h, float sin2_h, float alpha)
{
    if ((cos_h <= 0.0)) {
        return 0.0;
    }
    float a2_ = (alpha * alpha);
    float t_4 = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t_4 * t_4));
}

float smith_root(float cos_, float alpha_1)
{
    float a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1.0 - a2_1)) + a2_1));
}

float smith_visibility(float n_l, float n_v, float alpha_2)
{
    bool local_9 = (bool)0;

    if (!((n_l <= 0.0))) {
        local_9 = (n_v <= 0.0);
    } else {
        local_9 = true;
    }
    bool _e11 = local_9;
    if (_e11) {
        return 0.0;
    }
    const float _e13 = smith_root(n_v, alpha_2);
    const float _e15 = smith_root(n_l, alpha_2);
    return (0.5 / ((n_l * _e13) + (n_v * _e15)));
}

float3 fresnel_schlick(float3 f0_, float f90_, float v_h)
{
    float c_10 = saturate((1.0 - v_h));
    float c2_ = (c_10 * c_10);
    return (f0_ + ((float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_10)));
}

float3 specular_fresnel(float3 base, float metallic, float3 f0_d, float f90_d, float v_h_1)
{
    const float3 _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    const float3 _e10 = fresnel_schlick(base, 1.0, v_h_1);
    return ((_e5 * (1.0 - metallic)) + (_e10 * metallic));
}

bool has_specular(float metallic_1, float3 f0_d_1, float f90_d_1)
{
    bool local_10 = (bool)0;
    bool local_11 = (bool)0;

    if (!((metallic_1 > 0.0))) {
        local_10 = (f90_d_1 > 0.0);
    } else {
        local_10 = true;
    }
    bool _e11 = local_10;
    if (!(_e11)) {
        local_11 = (max(max(f0_d_1.x, f0_d_1.y), f0_d_1.z) > 0.0);
    } else {
        local_11 = true;
    }
    bool _e23 = local_11;
    return _e23;
}

float channel_mean(float3 c_5)
{
    return (((c_5.x + c_5.y) + c_5.z) * 0.33333334);
}

float4 receiver_lobe(float3 base_1, float metallic_2, float3 f0_d_2, float f90_d_2, float alpha_3, float n_v_1)
{
    bool local_12 = (bool)0;

    const float3 _e10 = fresnel_schlick(f0_d_2, f90_d_2, n_v_1);
    const float _e16 = channel_mean((((float3(1.0, 1.0, 1.0) - _e10) * base_1) * (1.0 - metallic_2)));
    if (!((n_v_1 <= 0.0))) {
        const bool _e22 = has_specular(metallic_2, f0_d_2, f90_d_2);
        local_12 = !(_e22);
    } else {
        local_12 = true;
    }
    bool _e25 = local_12;
    if (_e25) {
        return float4(_e16, 0.0, alpha_3, n_v_1);
    }
    const float3 _e28 = specular_fresnel(base_1, metallic_2, f0_d_2, f90_d_2, n_v_1);
    const float _e29 = channel_mean(_e28);
    return float4(_e16, _e29, alpha_3, n_v_1);
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

float3 mirror_dir(float3 n_3, float3 v)
{
    return ((n_3 * (2.0 * dot(n_3, v))) - v);
}

float bevy_alpha(float perceptual)
{
    float r_11 = clamp(perceptual, 0.089, 1.0);
    return (r_11 * r_11);
}

float bevy_f0_(float reflectance)
{
    return ((0.16 * reflectance) * reflectance);
}

float bevy_dfg(float r_3, float n_v_2)
{
    float rx = (1.0 - r_3);
    float a004_ = ((min((rx * rx), exp2((-9.28 * n_v_2))) * rx) + (0.0425 - (0.0275 * r_3)));
    float x_12 = max(((1.04 - (0.572 * r_3)) - (1.04 * a004_)), 5e-5);
    float y_1 = max((((0.022 * r_3) - 0.04) + (1.04 * a004_)), 5e-5);
    return (x_12 + y_1);
}

float3 bevy_brdf(float3 base_2, float metallic_3, float r_4, float reflectance_1, float3 n_4, float3 v_1, float3 l)
{
    float n_l_1 = saturate(dot(n_4, l));
    if ((n_l_1 <= 0.0)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float _e15 = bevy_alpha(r_4);
    float n_v_3 = max(dot(n_4, v_1), 0.0001);
    float3 h_2 = normalize((l + v_1));
    float n_h = saturate(dot(n_4, h_2));
    float l_h = saturate(dot(l, h_2));
    float f90_d_3 = (0.5 + (((2.0 * _e15) * l_h) * l_h));
    const float3 _e35 = fresnel_schlick(float3(1.0, 1.0, 1.0), f90_d_3, n_l_1);
    const float3 _e41 = fresnel_schlick(float3(1.0, 1.0, 1.0), f90_d_3, n_v_3);
    float burley = ((_e35.x * _e41.x) * INV_PI);
    const float _e46 = bevy_f0_(reflectance_1);
    float3 f0_1 = ((float3(_e46, _e46, _e46) * (1.0 - metallic_3)) + (base_2 * metallic_3));
    float f90_1 = saturate((((f0_1.x + f0_1.y) + f0_1.z) * 16.5));
    const float _e64 = ggx_d(n_h, (1.0 - (n_h * n_h)), _e15);
    const float _e65 = smith_visibility(n_l_1, n_v_3, _e15);
    const float _e70 = bevy_dfg(r_4, n_v_3);
    float3 comp = (float3(1.0, 1.0, 1.0) + (f0_1 * ((1.0 / _e70) - 1.0)));
    const float3 _e77 = fresnel_schlick(f0_1, f90_1, l_h);
    float3 spec = ((_e77 * comp) * (_e64 * _e65));
    return ((base_2 * ((1.0 - metallic_3) * burley)) + spec);
}

float cone_cos_of(float3 v_2, float d2_4, float a_3, float3 d)
{
    bool local_13 = (bool)0;
    bool local_14 = (bool)0;

    float vd = dot(v_2, d);
    float h2_ = (d2_4 - (a_3 * a_3));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_14 = ((vd * vd) >= h2_);
        } else {
            local_14 = false;
        }
        bool _e19 = local_14;
        local_13 = _e19;
    } else {
        local_13 = true;
    }
    bool _e21 = local_13;
    if (_e21) {
        return 1.0;
    }
    float3 c_11 = cross(v_2, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_11, c_11)) * a_3)) / d2_4), 1.0);
}

float cone_cos_toward(float3 center_, float radius, float3 p, float3 d_1)
{
    float3 v_8 = (center_ - p);
    const float _e6 = cone_cos_of(v_8, dot(v_8, v_8), radius, d_1);
    return _e6;
}

float range_scale_at(float4 rl, float cos_t)
{
    float t_5 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_5 * t_5))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(float4 rl_1, float3 center_1, float radius_1, float3 p_1, float3 r_5)
{
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    const float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_5);
    const float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
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

float ray_aabb(float3 o, float3 inv_d, float3 bmin_1, float3 bmax_1, float t_max)
{
    float3 t0_ = ((bmin_1 - o) * inv_d);
    float3 t1_ = ((bmax_1 - o) * inv_d);
    float3 lo_3 = min(t0_, t1_);
    float3 hi_3 = max(t0_, t1_);
    float t_in = max(max(lo_3.x, lo_3.y), max(lo_3.z, 0.0));
    float t_out = min(min(hi_3.x, hi_3.y), min(hi_3.z, t_max));
    if ((t_in <= t_out)) {
        return t_in;
    }
    return -1.0;
}

float3 triangle_normal(float3 a_4, float3 b_3, float3 c_6)
{
    bool local_15 = (bool)0;

    float3 n_10 = cross((b_3 - a_4), (c_6 - a_4));
    float l2_ = dot(n_10, n_10);
    if (!(!((l2_ > 0.0)))) {
        local_15 = !((l2_ < 3e38));
    } else {
        local_15 = true;
    }
    bool _e17 = local_15;
    if (_e17) {
        return float3(0.0, 0.0, 0.0);
    }
    return (n_10 / (sqrt(l2_)).xxx);
}

float ray_triangle(float3 o_1, float3 d_3, float3 a_5, float3 b_4, float3 c_7, float t_min, float t_max_1)
{
    bool local_16 = (bool)0;
    bool local_17 = (bool)0;
    bool local_18 = (bool)0;

    float3 e1_ = (b_4 - a_5);
    float3 e2_ = (c_7 - a_5);
    float3 p_5 = cross(d_3, e2_);
    float det = dot(e1_, p_5);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv = (1.0 / det);
    float3 s_10 = (o_1 - a_5);
    float u_3 = (dot(s_10, p_5) * inv);
    if (!((u_3 < 0.0))) {
        local_16 = (u_3 > 1.0);
    } else {
        local_16 = true;
    }
    bool _e28 = local_16;
    if (_e28) {
        return -1.0;
    }
    float3 q_2 = cross(s_10, e1_);
    float v_9 = (dot(d_3, q_2) * inv);
    if (!((v_9 < 0.0))) {
        local_17 = ((u_3 + v_9) > 1.0);
    } else {
        local_17 = true;
    }
    bool _e42 = local_17;
    if (_e42) {
        return -1.0;
    }
    float t_6 = (dot(e2_, q_2) * inv);
    if ((t_6 > t_min)) {
        local_18 = (t_6 < t_max_1);
    } else {
        local_18 = false;
    }
    bool _e51 = local_18;
    if (_e51) {
        return t_6;
    }
    return -1.0;
}

float3 light_intensity(GpuLight l_1, float3 w_4)
{
    switch(l_1.kind) {
        case 0u: {
            return l_1.intensity;
        }
        case 3u: {
            const float3 _e8 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
            const float _e10 = triangle_lobe(_e8, l_1.a, w_4);
            return (l_1.intensity * _e10);
        }
        default: {
            return (0.0).xxx;
        }
    }
}

float3 light_point(GpuLight l_2, float u1_1, float u2_1)
{
    if ((l_2.kind == LIGHT_TRIANGLE)) {
        const float3 _e9 = triangle_sample(l_2.p0_, l_2.p1_, l_2.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_2.p0_;
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
    uint node_3 = 0u;
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
        uint _e21 = node_3;
        GpuGeoNode n_11 = ConstructGpuGeoNode(asfloat(geo_nodes.Load3(_e21*32+0)), asuint(geo_nodes.Load(_e21*32+12)), asfloat(geo_nodes.Load3(_e21*32+16)), asuint(geo_nodes.Load(_e21*32+28)));
        float _e27 = hit.t;
        const float _e28 = ray_aabb(o_2, _e14, n_11.bmin, n_11.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_11.count > 0u)) {
                i = n_11.first;
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
                    if ((_e36 < (n_11.first + n_11.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_7 = ConstructGpuTriangle(asfloat(geo_tris.Load3(_e42*48+0)), asuint(geo_tris.Load(_e42*48+12)), asfloat(geo_tris.Load3(_e42*48+16)), asuint(geo_tris.Load(_e42*48+28)), asfloat(geo_tris.Load3(_e42*48+32)), asuint(geo_tris.Load(_e42*48+44)));
                        float _e49 = hit.t;
                        const float _e50 = ray_triangle(o_2, d_4, t_7.v0_, t_7.v1_, t_7.v2_, t_min_1, _e49);
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
                    stack[min(uint(_e63), 63u)] = (n_11.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_11.first;
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

uint bsh_count(uint nodes_1)
{
    return ((NagaBufferLength(bsh_nodes) - 0) / 32);
}

uint bsh_first(uint nodes_2)
{
    const uint _e1 = bsh_count(nodes_2);
    if ((_e1 > 0u)) {
        return 0u;
    }
    return BSH_NONE;
}

float bsh_inner_scale(float a_7, float3 v_3, float d2_5, float3 r_6, float4 rl_2)
{
    const float _e5 = cone_cos_of(v_3, d2_5, a_7, r_6);
    const float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_4, float3 x_4, float3 r_7, float4 rl_3)
{
    bool local_19 = (bool)0;
    bool local_20 = (bool)0;

    const bool _e6 = sphere_contains_point(node_4.center_, node_4.radius, x_4);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        const bool _e20 = sphere_contains_point(node_4.center_, (node_4.radius * (rl_3.w * 1.0001)), x_4);
        local_19 = !(_e20);
    } else {
        local_19 = true;
    }
    bool _e23 = local_19;
    if (_e23) {
        return false;
    }
    float3 v_10 = (x_4 - node_4.center_);
    float d2_7 = dot(v_10, v_10);
    const float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if ((d2_7 > (_e29 * _e29))) {
        return false;
    }
    if ((node_4.child == BSH_NONE)) {
        const float _e38 = range_scale_toward(rl_3, node_4.center_, node_4.extent, x_4, r_7);
        const float _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        const bool _e42 = sphere_contains_point(node_4.center_, _e41, x_4);
        return _e42;
    }
    const float _e45 = bsh_inner_scale(node_4.extent, -(v_10), d2_7, r_7, rl_3);
    float s_c = (_e45 * 1.001);
    const float _e50 = bsh_range_bound(node_4);
    float reach = (node_4.extent + (sqrt(s_c) * _e50));
    if ((d2_7 <= ((node_4.radius * node_4.radius) * s_c))) {
        local_20 = (d2_7 <= (reach * reach));
    } else {
        local_20 = false;
    }
    bool _e63 = local_20;
    return _e63;
}

bool bsh_reaches_box(BshNode node_5, float3 lo, float3 hi, float w_5)
{
    const bool _e13 = sphere_overlaps_aabb(node_5.center_, (node_5.radius * (max(1.0, (w_5 * 1.0001)) * 1.0001)), lo, hi);
    return _e13;
}

uint bsh_subtree(uint nodes_3, uint s_1, uint depth)
{
    uint i_2 = (uint)0;
    uint level = 0u;
    bool local_21 = (bool)0;

    const uint _e3 = bsh_first(nodes_3);
    i_2 = _e3;
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e7 = level;
        if ((_e7 < depth)) {
            uint _e11 = i_2;
            local_21 = (_e11 != BSH_NONE);
        } else {
            local_21 = false;
        }
        bool _e15 = local_21;
        if (_e15) {
        } else {
            break;
        }
        {
            uint _e16 = i_2;
            const BshNode _e17 = bsh_node(nodes_3, _e16);
            uint _e18 = level;
            uint below = (depth - _e18);
            if ((_e17.child == BSH_NONE)) {
                if (((s_1 << (32u - below)) != 0u)) {
                    return BSH_NONE;
                }
                uint _e29 = i_2;
                return _e29;
            }
            if ((((s_1 >> (below - 1u)) & 1u) == 0u)) {
                i_2 = _e17.child;
            } else {
                const BshNode _e39 = bsh_node(nodes_3, _e17.child);
                i_2 = _e39.next;
            }
            uint _e41 = level;
            level = (_e41 + 1u);
        }
    }
    uint _e44 = i_2;
    return _e44;
}

uint bsh_next_leaf_box(uint nodes_4, uint start_1, uint end, float3 lo_1, float3 hi_1, float w_6)
{
    uint i_3 = (uint)0;

    i_3 = start_1;
    uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e7 = i_3;
        if ((_e7 != end)) {
        } else {
            break;
        }
        {
            uint _e9 = i_3;
            const BshNode _e10 = bsh_node(nodes_4, _e9);
            const bool _e11 = bsh_reaches_box(_e10, lo_1, hi_1, w_6);
            if (_e11) {
                if ((_e10.child == BSH_NONE)) {
                    if (((_e10.light & BSH_TAIL) == 0u)) {
                        uint _e20 = i_3;
                        return _e20;
                    }
                    i_3 = _e10.next;
                } else {
                    i_3 = _e10.child;
                }
            } else {
                i_3 = _e10.next;
            }
        }
    }
    return end;
}

float next_threshold(float sum, inout uint h_1)
{
    uint _e2 = h_1;
    const uint _e3 = pcg_hash(_e2);
    h_1 = _e3;
    uint _e4 = h_1;
    const float _e5 = xi_from_bits(_e4);
    const float _e6 = weighted_threshold(sum, _e5);
    return _e6;
}

Connection connect_record(GpuLight l_3, float3 x_5, float3 n_5, float3 ng_1, float r2_2, float rt2_2, float w_res, float u1_2, float u2_2, float eps, bool trace_1)
{
    Connection c_8 = (Connection)0;
    bool local_22 = (bool)0;
    bool local_23 = (bool)0;

    c_8.e = (0.0).xxx;
    const float3 _e16 = light_point(l_3, u1_2, u2_2);
    c_8.y = _e16;
    float3 _e19 = c_8.y;
    const float _e20 = connection_cosine(x_5, _e19, n_5, ng_1, r2_2);
    c_8.cos_x = _e20;
    float _e22 = c_8.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            float3 _e33 = c_8.y;
            const bool _e34 = occluded((x_5 + (ng_1 * eps)), _e33);
            local_23 = _e34;
        } else {
            local_23 = false;
        }
        bool _e36 = local_23;
        local_22 = _e36;
    } else {
        local_22 = true;
    }
    bool _e38 = local_22;
    if (_e38) {
        Connection _e39 = c_8;
        const Connection connection = _e39;
        return connection;
    }
    float3 _e41 = c_8.y;
    float3 v_11 = (x_5 - _e41);
    float d2_8 = dot(v_11, v_11);
    const float3 _e48 = light_intensity(l_3, (v_11 / (sqrt(d2_8)).xxx));
    float _e50 = c_8.cos_x;
    const float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_8.e = (_e48 * _e51);
    Connection _e53 = c_8;
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

Connection connect_traced(uint li, float3 x_6, float3 n_6, float3 ng_2, float s_2, float w_res_1, float u1_3, float u2_3, float eps_1, bool trace_2)
{
    GpuLight _e12 = ConstructGpuLight(asfloat(lights.Load3(li*64+0)), asuint(lights.Load(li*64+12)), asfloat(lights.Load3(li*64+16)), asfloat(lights.Load(li*64+28)), asfloat(lights.Load3(li*64+32)), asfloat(lights.Load(li*64+44)), asfloat(lights.Load3(li*64+48)), asuint(lights.Load(li*64+60)));
    float _e15 = asfloat(r2_3.Load(li*4));
    float _e19 = asfloat(rt2_3.Load(li*4));
    const Connection _e21 = connect_record(_e12, x_6, n_6, ng_2, (s_2 * _e15), (s_2 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_2);
    const Connection connection_2 = _e21;
    return connection_2;
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

float light_range_scale(uint li_1, float3 x_7, float3 r_8, float4 rl_4)
{
    GpuLightCone c_12 = ConstructGpuLightCone(asfloat(light_cones.Load3(li_1*48+0)), asfloat(light_cones.Load(li_1*48+12)), asfloat(light_cones.Load3(li_1*48+16)), asfloat(light_cones.Load(li_1*48+28)), asfloat(light_cones.Load(li_1*48+32)), asfloat(light_cones.Load(li_1*48+36)), asuint(light_cones.Load(li_1*48+40)), asuint(light_cones.Load(li_1*48+44)));
    const float _e9 = range_scale_toward(rl_4, c_12.center_, c_12.radius, x_7, r_8);
    return _e9;
}

float4 surface_at(int2 texel)
{
    float4 p_6 = position_tex.Load(int3(texel, int(0)));
    return ((p_6.w > 0.0) ? float4(p_6.xyz, 1.0) : (0.0).xxxx);
}

WorkgroupBox ConstructWorkgroupBox(float3 arg0, float3 arg1) {
    WorkgroupBox ret = (WorkgroupBox)0;
    ret.lo = arg0;
    ret.hi = arg1;
    return ret;
}

WorkgroupBox workgroup_bounds(uint li_2, float3 lo_2, float3 hi_2)
{
    uint stride = 32u;

    wg_lo[min(uint(li_2), 63u)] = lo_2;
    wg_hi[min(uint(li_2), 63u)] = hi_2;
    GroupMemoryBarrierWithGroupSync();
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e36 = stride;
            stride = naga_div(_e36, 2u);
        }
        loop_init_1 = false;
        uint _e9 = stride;
        if ((_e9 > 0u)) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if ((li_2 < _e12)) {
                float3 _e18 = wg_lo[min(uint(li_2), 63u)];
                uint _e20 = stride;
                float3 _e23 = wg_lo[min(uint((li_2 + _e20)), 63u)];
                wg_lo[min(uint(li_2), 63u)] = min(_e18, _e23);
                float3 _e29 = wg_hi[min(uint(li_2), 63u)];
                uint _e31 = stride;
                float3 _e34 = wg_hi[min(uint((li_2 + _e31)), 63u)];
                wg_hi[min(uint(li_2), 63u)] = max(_e29, _e34);
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    if ((li_2 == 0u)) {
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

WorkgroupBox point_box(float3 p_2, bool has)
{
    const WorkgroupBox workgroupbox_1 = ConstructWorkgroupBox((has ? p_2 : (3.4028235e38).xxx), (has ? p_2 : (-3.4028235e38).xxx));
    return workgroupbox_1;
}

WorkgroupBox workgroup_box(uint li_3, float3 p_3, bool has_1)
{
    const WorkgroupBox _e3 = point_box(p_3, has_1);
    const WorkgroupBox _e6 = workgroup_bounds(li_3, _e3.lo, _e3.hi);
    const WorkgroupBox workgroupbox_2 = _e6;
    return workgroupbox_2;
}

bool box_is_empty(WorkgroupBox b_6)
{
    return (b_6.lo.x > b_6.hi.x);
}

uint tile_subtree(uint s_3, TileWalk t_1, bool list, uint at, uint start_2, uint to)
{
    uint p_4 = (uint)0;
    uint b_7 = (uint)0;
    bool local_24 = (bool)0;
    bool local_25 = (bool)0;
    bool local_26 = (bool)0;

    const uint _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH);
    if ((_e8 == BSH_NONE)) {
        return 0u;
    }
    uint end_1 = asuint(bsh_nodes.Load(20+_e8*32));
    p_4 = at;
    const uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_1.lo, t_1.hi, t_1.w);
    b_7 = _e21;
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e53 = b_7;
            uint _e56 = asuint(bsh_nodes.Load(20+_e53*32));
            const uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_1.lo, t_1.hi, t_1.w);
            b_7 = _e60;
        }
        loop_init_2 = false;
        uint _e23 = b_7;
        if ((_e23 != end_1)) {
            if (!(!(list))) {
                uint _e31 = p_4;
                local_25 = (_e31 < to);
            } else {
                local_25 = true;
            }
            bool _e34 = local_25;
            local_24 = _e34;
        } else {
            local_24 = false;
        }
        bool _e36 = local_24;
        if (_e36) {
        } else {
            break;
        }
        {
            if (list) {
                uint _e39 = p_4;
                local_26 = (_e39 >= start_2);
            } else {
                local_26 = false;
            }
            bool _e42 = local_26;
            if (_e42) {
                uint _e44 = p_4;
                uint _e47 = b_7;
                tile_list[min(uint((_e44 - start_2)), 1023u)] = _e47;
            }
            uint _e48 = p_4;
            p_4 = (_e48 + 1u);
        }
    }
    uint _e61 = p_4;
    return (_e61 - at);
}

TileWalk ConstructTileWalk(float3 arg0, float3 arg1, float arg2, uint arg3) {
    TileWalk ret = (TileWalk)0;
    ret.lo = arg0;
    ret.hi = arg1;
    ret.w = arg2;
    ret.total = arg3;
    return ret;
}

TileWalk tile_walk_begin(uint li_4, float3 x_8, float w_7, bool has_2)
{
    bool local_27 = (bool)0;
    TileWalk t_2 = (TileWalk)0;
    uint s_4 = (uint)0;
    uint sum_1 = 0u;
    uint s_5 = 0u;

    if (has_2) {
        local_27 = (w_7 >= 0.0);
    } else {
        local_27 = false;
    }
    bool _e12 = local_27;
    uint _e14; InterlockedMax(tile_scale, (_e12 ? asuint(w_7) : 0u), _e14);
    const WorkgroupBox _e15 = workgroup_box(li_4, x_8, has_2);
    GroupMemoryBarrierWithGroupSync();
    uint _e19 = tile_scale;
    GroupMemoryBarrierWithGroupSync();
    t_2 = ConstructTileWalk(_e15.lo, _e15.hi, asfloat(_e19), 0u);
    const bool _e24 = box_is_empty(_e15);
    if (_e24) {
        TileWalk _e25 = t_2;
        const TileWalk tilewalk = _e25;
        return tilewalk;
    }
    s_4 = li_4;
    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e40 = s_4;
            s_4 = (_e40 + TILE_THREADS);
        }
        loop_init_3 = false;
        uint _e27 = s_4;
        if ((_e27 < BSH_TILE_SUBTREES)) {
        } else {
            break;
        }
        {
            uint _e31 = s_4;
            uint _e33 = s_4;
            TileWalk _e34 = t_2;
            const uint _e39 = tile_subtree(_e33, _e34, false, 0u, 0u, 0u);
            subtree_at[min(uint(_e31), 255u)] = _e39;
        }
    }
    GroupMemoryBarrierWithGroupSync();
    if ((li_4 == 0u)) {
        uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
        bool loop_init_4 = true;
        while(true) {
            if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
            loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
            if (!loop_init_4) {
                uint _e63 = s_5;
                s_5 = (_e63 + 1u);
            }
            loop_init_4 = false;
            uint _e49 = s_5;
            if ((_e49 < BSH_TILE_SUBTREES)) {
            } else {
                break;
            }
            {
                uint _e53 = s_5;
                uint c_13 = subtree_at[min(uint(_e53), 255u)];
                uint _e57 = s_5;
                uint _e59 = sum_1;
                subtree_at[min(uint(_e57), 255u)] = _e59;
                uint _e60 = sum_1;
                sum_1 = (_e60 + c_13);
            }
        }
        uint _e66 = sum_1;
        tile_total = _e66;
    }
    GroupMemoryBarrierWithGroupSync();
    uint _e69 = tile_total;
    GroupMemoryBarrierWithGroupSync();
    t_2.total = _e69;
    TileWalk _e70 = t_2;
    const TileWalk tilewalk_1 = _e70;
    return tilewalk_1;
}

uint tile_walk_fill(uint li_5, TileWalk t_3, uint start_3)
{
    uint s_6 = (uint)0;
    uint past = (uint)0;
    bool local_28 = (bool)0;

    uint to_1 = min(t_3.total, (start_3 + TILE_LIST));
    s_6 = li_5;
    uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e38 = s_6;
            s_6 = (_e38 + TILE_THREADS);
        }
        loop_init_5 = false;
        uint _e8 = s_6;
        if ((_e8 < BSH_TILE_SUBTREES)) {
        } else {
            break;
        }
        {
            uint _e12 = s_6;
            uint at_1 = subtree_at[min(uint(_e12), 255u)];
            past = t_3.total;
            uint _e17 = s_6;
            if (((_e17 + 1u) < BSH_TILE_SUBTREES)) {
                uint _e23 = s_6;
                uint _e27 = subtree_at[min(uint((_e23 + 1u)), 255u)];
                past = _e27;
            }
            if ((at_1 < to_1)) {
                uint _e31 = past;
                local_28 = (_e31 > start_3);
            } else {
                local_28 = false;
            }
            bool _e34 = local_28;
            if (_e34) {
                uint _e35 = s_6;
                const uint _e37 = tile_subtree(_e35, t_3, true, at_1, start_3, to_1);
            }
        }
    }
    GroupMemoryBarrierWithGroupSync();
    return (to_1 - start_3);
}

Shaded shade_connection(Connection c_9, float3 x_9, float3 n_7, Material m_1)
{
    Shaded s_7 = (Shaded)0;

    s_7.e = c_9.e;
    s_7.diffuse = (0.0).xxx;
    s_7.specular = (0.0).xxx;
    if ((c_9.cos_x > 0.0)) {
        const float3 _e25 = bevy_brdf(m_1.base, m_1.metallic, m_1.roughness, m_1.reflectance, n_7, m_1.v, normalize((c_9.y - x_9)));
        s_7.diffuse = (_e25 * c_9.e);
    }
    Shaded _e28 = s_7;
    const Shaded shaded = _e28;
    return shaded;
}

Shaded shade_pick_traced(uint li_6, float3 x_10, float3 n_8, float3 r_9, float4 rl_5, Material m_2, float w_8, float u1_4, float u2_4, float eps_2, bool trace_3)
{
    const float _e11 = light_range_scale(li_6, x_10, r_9, rl_5);
    const Connection _e12 = connect_traced(li_6, x_10, n_8, n_8, _e11, w_8, u1_4, u2_4, eps_2, trace_3);
    const Shaded _e13 = shade_connection(_e12, x_10, n_8, m_2);
    const Shaded shaded_1 = _e13;
    return shaded_1;
}

Shaded shade_pick(uint li_7, float3 x_11, float3 n_9, float3 r_10, float4 rl_6, Material m_3, float w_9, float u1_5, float u2_5, float eps_3)
{
    const Shaded _e11 = shade_pick_traced(li_7, x_11, n_9, r_10, rl_6, m_3, w_9, u1_5, u2_5, eps_3, true);
    const Shaded shaded_2 = _e11;
    return shaded_2;
}

Material ConstructMaterial(float3 arg0, float arg1, float arg2, float3 arg3, float arg4, float arg5) {
    Material ret = (Material)0;
    ret.base = arg0;
    ret.metallic = arg1;
    ret.alpha = arg2;
    ret.v = arg3;
    ret.roughness = arg4;
    ret.reflectance = arg5;
    return ret;
}

Material material_of(float3 base_3, float metallic_4, float roughness, float reflectance_2, float3 v_4)
{
    const float _e6 = bevy_alpha(roughness);
    const Material material = ConstructMaterial(base_3, saturate(metallic_4), _e6, v_4, roughness, reflectance_2);
    return material;
}

Shaded ConstructShaded(float3 arg0, float3 arg1, float3 arg2) {
    Shaded ret = (Shaded)0;
    ret.e = arg0;
    ret.diffuse = arg1;
    ret.specular = arg2;
    return ret;
}

Shaded add(Shaded a_8, Shaded b_8)
{
    const Shaded shaded_3 = ConstructShaded((a_8.e + b_8.e), (a_8.diffuse + b_8.diffuse), (a_8.specular + b_8.specular));
    return shaded_3;
}

Shaded scaled(Shaded s_8, float3 w_10)
{
    const Shaded shaded_4 = ConstructShaded((s_8.e * w_10), (s_8.diffuse * w_10), (s_8.specular * w_10));
    return shaded_4;
}

typedef uint ret_first_holders[8];
ret_first_holders first_holders(uint2 keys_1[8], bool held_1[8])
{
    uint first[8] = (uint[8])0;
    uint k_4 = 0u;
    uint j_2 = (uint)0;
    bool local_29 = (bool)0;
    bool local_30 = (bool)0;

    uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
    bool loop_init_6 = true;
    while(true) {
        if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_6) {
            uint _e45 = k_4;
            k_4 = (_e45 + 1u);
        }
        loop_init_6 = false;
        uint _e5 = k_4;
        if ((_e5 < K)) {
        } else {
            break;
        }
        {
            uint _e8 = k_4;
            uint _e11 = k_4;
            uint _e12 = k_4;
            first[min(uint(_e8), 7u)] = (held_1[min(uint(_e12), 7u)] ? _e11 : K);
            j_2 = 0u;
            uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
            bool loop_init_7 = true;
            while(true) {
                if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_7) {
                    uint _e42 = j_2;
                    j_2 = (_e42 + 1u);
                }
                loop_init_7 = false;
                uint _e17 = j_2;
                uint _e18 = k_4;
                if ((_e17 < _e18)) {
                    uint _e22 = k_4;
                    local_29 = held_1[min(uint(_e22), 7u)];
                } else {
                    local_29 = false;
                }
                bool _e25 = local_29;
                if (_e25) {
                } else {
                    break;
                }
                {
                    uint _e26 = j_2;
                    if (held_1[min(uint(_e26), 7u)]) {
                        uint _e30 = j_2;
                        uint _e32 = k_4;
                        local_30 = all((keys_1[min(uint(_e30), 7u)] == keys_1[min(uint(_e32), 7u)]));
                    } else {
                        local_30 = false;
                    }
                    bool _e37 = local_30;
                    if (_e37) {
                        uint _e38 = k_4;
                        uint _e40 = j_2;
                        first[min(uint(_e38), 7u)] = _e40;
                        break;
                    }
                }
            }
        }
    }
    uint _e47[8] = first;
    return _e47;
}

float3 output_of(Shaded s_9)
{
    return (s_9.diffuse + s_9.specular);
}

[numthreads(8, 8, 1)]
void main(uint3 gid : SV_DispatchThreadID, uint lid : SV_GroupIndex)
{
    if (lid == 0) {
        wg_lo = (float3[64])0;
        wg_hi = (float3[64])0;
        wg_box = (WorkgroupBox)0;
        tile_list = (uint[1024])0;
        subtree_at = (uint[256])0;
        tile_scale = (uint)0;
        tile_total = (uint)0;
    }
    GroupMemoryBarrierWithGroupSync();
    bool local = (bool)0;
    float4 s = (0.0).xxxx;
    float3 nn = (0.0).xxx;
    bool local_1 = (bool)0;
    bool local_2 = (bool)0;
    bool local_3 = (bool)0;
    float3 n = float3(0.0, 0.0, 1.0);
    Material m = (Material)0;
    float4 lobe = float4(1.0, 0.0, 1.0, 1.0);
    float3 r = (float3)0;
    uint h = (uint)0;
    Shaded t = ConstructShaded((0.0).xxx, (0.0).xxx, (0.0).xxx);
    uint slot_light[8] = (uint[8])0;
    float2 slot_u[8] = (float2[8])0;
    float slot_p[8] = (float[8])0;
    float3 total = (0.0).xxx;
    uint count = 0u;
    uint hc = (uint)0;
    float threshold[8] = (float[8])0;
    uint start = 0u;
    uint j = (uint)0;
    bool local_4 = (bool)0;
    uint q = (uint)0;
    bool local_5 = (bool)0;
    uint2 keys[8] = (uint2[8])0;
    bool held[8] = (bool[8])0;
    uint k = 0u;
    uint k_1 = 0u;
    float3 w = (float3)0;
    uint j_1 = (uint)0;
    bool local_6 = (bool)0;

    uint _e5 = view.width;
    if ((gid.x < _e5)) {
        uint _e12 = view.height;
        local = (gid.y < _e12);
    } else {
        local = false;
    }
    bool inside = local;
    int2 texel_1 = int2(int(gid.x), int(gid.y));
    if (inside) {
        const float4 _e27 = surface_at(texel_1);
        s = _e27;
        float4 _e30 = normal_tex.Load(int3(texel_1, int(0)));
        nn = _e30.xyz;
    }
    float3 _e32 = nn;
    float3 _e33 = nn;
    float len2_ = dot(_e32, _e33);
    float4 _e35 = s;
    float3 x_13 = _e35.xyz;
    if (inside) {
        float _e40 = s.w;
        local_1 = (_e40 > 0.0);
    } else {
        local_1 = false;
    }
    bool _e44 = local_1;
    if (_e44) {
        local_2 = (len2_ > 0.0);
    } else {
        local_2 = false;
    }
    bool _e50 = local_2;
    if (_e50) {
        local_3 = all((abs(x_13) <= (3.4028235e38).xxx));
    } else {
        local_3 = false;
    }
    bool has_3 = local_3;
    if (has_3) {
        float3 _e65 = nn;
        n = (_e65 / (sqrt(len2_)).xxx);
    }
    float3 _e76 = n;
    r = _e76;
    if (has_3) {
        float4 mr = metal_rough_tex.Load(int3(texel_1, int(0)));
        float4 _e83 = base_color_tex.Load(int3(texel_1, int(0)));
        float3 _e90 = view.eye;
        const Material _e93 = material_of(_e83.xyz, mr.z, mr.y, mr.w, normalize((_e90 - x_13)));
        m = _e93;
        float3 _e95 = m.base;
        float _e97 = m.metallic;
        const float _e99 = bevy_f0_(mr.w);
        float _e103 = m.alpha;
        float3 _e104 = n;
        float3 _e106 = m.v;
        const float4 _e108 = receiver_lobe(_e95, _e97, (_e99).xxx, 1.0, _e103, dot(_e104, _e106));
        lobe = _e108;
        float3 _e109 = n;
        float3 _e111 = m.v;
        const float3 _e112 = mirror_dir(_e109, _e111);
        r = _e112;
    }
    float4 _e113 = lobe;
    const float4 _e114 = range_lobe(_e113);
    float _e117 = view.shadow_offset;
    float3 _e120 = view.eye;
    float eps_4 = (_e117 * length((_e120 - x_13)));
    uint _e126 = view.seed;
    uint _e130 = view.width;
    uint _e136 = view.frame;
    const uint _e137 = point_stream(_e126, ((gid.y * _e130) + gid.x), _e136);
    const uint _e138 = pick_stream(_e137);
    h = _e138;
    hc = _e137;
    const TileWalk _e159 = tile_walk_begin(lid, x_13, _e114.w, has_3);
    uint2 loop_bound_11 = uint2(4294967295u, 4294967295u);
    bool loop_init_8 = true;
    while(true) {
        if (all(loop_bound_11 == uint2(0u, 0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_8) {
            uint _e254 = start;
            start = (_e254 + TILE_LIST);
        }
        loop_init_8 = false;
        uint _e162 = start;
        if ((_e162 < _e159.total)) {
        } else {
            break;
        }
        {
            uint _e165 = start;
            const uint _e166 = tile_walk_fill(lid, _e159, _e165);
            j = 0u;
            uint2 loop_bound_12 = uint2(4294967295u, 4294967295u);
            bool loop_init_9 = true;
            while(true) {
                if (all(loop_bound_12 == uint2(0u, 0u))) { break; }
                loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
                if (!loop_init_9) {
                    uint _e252 = j;
                    j = (_e252 + 1u);
                }
                loop_init_9 = false;
                uint _e169 = j;
                if ((_e169 < _e166)) {
                } else {
                    break;
                }
                {
                    uint _e172 = j;
                    uint b_9 = tile_list[min(uint(_e172), 1023u)];
                    if (!(!(has_3))) {
                        BshNode _e181 = ConstructBshNode(asfloat(bsh_nodes.Load3(b_9*32+0)), asfloat(bsh_nodes.Load(b_9*32+12)), asuint(bsh_nodes.Load(b_9*32+16)), asuint(bsh_nodes.Load(b_9*32+20)), asuint(bsh_nodes.Load(b_9*32+24)), asfloat(bsh_nodes.Load(b_9*32+28)));
                        float3 _e182 = r;
                        const bool _e183 = bsh_reaches(_e181, x_13, _e182, _e114);
                        local_4 = !(_e183);
                    } else {
                        local_4 = true;
                    }
                    bool _e186 = local_4;
                    if (_e186) {
                        continue;
                    }
                    uint li_8 = asuint(bsh_nodes.Load(24+b_9*32));
                    uint _e191 = count;
                    count = (_e191 + 1u);
                    uint _e194 = h;
                    const uint _e195 = pcg_hash(_e194);
                    h = _e195;
                    uint _e196 = h;
                    const float _e197 = xi_from_bits(_e196);
                    uint _e198 = h;
                    const uint _e199 = pcg_hash(_e198);
                    h = _e199;
                    uint _e200 = h;
                    const float _e201 = xi_from_bits(_e200);
                    float2 u_4 = float2(_e197, _e201);
                    float3 _e203 = n;
                    float3 _e204 = r;
                    Material _e205 = m;
                    const Shaded _e210 = shade_pick_traced(li_8, x_13, _e203, _e204, _e114, _e205, 1.0, u_4.x, u_4.y, eps_4, false);
                    const float3 _e211 = output_of(_e210);
                    const float _e212 = resample_target(_e211);
                    if ((_e212 > 0.0)) {
                        float3 _e215 = total;
                        total = (_e215 + _e211);
                        q = 0u;
                        uint2 loop_bound_13 = uint2(4294967295u, 4294967295u);
                        bool loop_init_10 = true;
                        while(true) {
                            if (all(loop_bound_13 == uint2(0u, 0u))) { break; }
                            loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                            if (!loop_init_10) {
                                uint _e249 = q;
                                q = (_e249 + 1u);
                            }
                            loop_init_10 = false;
                            uint _e219 = q;
                            if ((_e219 < K)) {
                            } else {
                                break;
                            }
                            {
                                uint _e222 = q;
                                const float _e224 = slot_target(_e211, _e222, K);
                                float3 _e225 = total;
                                uint _e226 = q;
                                const float _e228 = slot_target(_e225, _e226, K);
                                if ((_e224 > 0.0)) {
                                    uint _e233 = q;
                                    float _e235 = threshold[min(uint(_e233), 7u)];
                                    local_5 = (_e228 > _e235);
                                } else {
                                    local_5 = false;
                                }
                                bool _e238 = local_5;
                                if (_e238) {
                                    uint _e239 = q;
                                    slot_light[min(uint(_e239), 7u)] = li_8;
                                    uint _e241 = q;
                                    slot_u[min(uint(_e241), 7u)] = u_4;
                                    uint _e243 = q;
                                    slot_p[min(uint(_e243), 7u)] = _e224;
                                    uint _e245 = q;
                                    const float _e247 = next_threshold(_e228, hc);
                                    threshold[min(uint(_e245), 7u)] = _e247;
                                }
                            }
                        }
                    }
                }
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    if (!(has_3)) {
        if (inside) {
            out_tex[texel_1] = (0.0).xxxx;
        }
        return;
    }
    uint2 loop_bound_14 = uint2(4294967295u, 4294967295u);
    bool loop_init_11 = true;
    while(true) {
        if (all(loop_bound_14 == uint2(0u, 0u))) { break; }
        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
        if (!loop_init_11) {
            uint _e283 = k;
            k = (_e283 + 1u);
        }
        loop_init_11 = false;
        uint _e265 = k;
        if ((_e265 < K)) {
        } else {
            break;
        }
        {
            uint _e268 = k;
            uint _e270 = k;
            uint _e272 = slot_light[min(uint(_e270), 7u)];
            keys[min(uint(_e268), 7u)] = uint2(_e272, 0u);
            uint _e275 = k;
            uint _e277 = k;
            float _e279 = slot_p[min(uint(_e277), 7u)];
            held[min(uint(_e275), 7u)] = (_e279 > 0.0);
        }
    }
    uint2 _e285[8] = keys;
    bool _e286[8] = held;
    const uint _e287[8] = first_holders(_e285, _e286);
    uint2 loop_bound_15 = uint2(4294967295u, 4294967295u);
    bool loop_init_12 = true;
    while(true) {
        if (all(loop_bound_15 == uint2(0u, 0u))) { break; }
        loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
        if (!loop_init_12) {
            uint _e351 = k_1;
            k_1 = (_e351 + 1u);
        }
        loop_init_12 = false;
        uint _e290 = k_1;
        if ((_e290 < K)) {
        } else {
            break;
        }
        {
            w = (0.0).xxx;
            uint _e296 = k_1;
            uint _e298 = k_1;
            bool first_1 = (_e287[min(uint(_e296), 7u)] == _e298);
            uint _e300 = k_1;
            j_1 = _e300;
            uint2 loop_bound_16 = uint2(4294967295u, 4294967295u);
            bool loop_init_13 = true;
            while(true) {
                if (all(loop_bound_16 == uint2(0u, 0u))) { break; }
                loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
                if (!loop_init_13) {
                    uint _e328 = j_1;
                    j_1 = (_e328 + 1u);
                }
                loop_init_13 = false;
                uint _e302 = j_1;
                if ((_e302 < K)) {
                    local_6 = first_1;
                } else {
                    local_6 = false;
                }
                bool _e308 = local_6;
                if (_e308) {
                } else {
                    break;
                }
                {
                    uint _e309 = j_1;
                    uint _e311 = k_1;
                    if ((_e287[min(uint(_e309), 7u)] == _e311)) {
                        float3 _e313 = w;
                        float3 _e314 = total;
                        uint _e315 = j_1;
                        const float _e317 = slot_target(_e314, _e315, K);
                        uint _e318 = j_1;
                        float _e320 = slot_p[min(uint(_e318), 7u)];
                        uint _e322 = j_1;
                        const float3 _e324 = slot_share(_e322, K);
                        w = (_e313 + ((_e317 / _e320) * _e324));
                    }
                }
            }
            if (first_1) {
                Shaded _e330 = t;
                uint _e331 = k_1;
                uint _e333 = slot_light[min(uint(_e331), 7u)];
                float3 _e334 = n;
                float3 _e335 = r;
                Material _e336 = m;
                uint _e338 = k_1;
                float _e341 = slot_u[min(uint(_e338), 7u)].x;
                uint _e342 = k_1;
                float _e345 = slot_u[min(uint(_e342), 7u)].y;
                const Shaded _e346 = shade_pick(_e333, x_13, _e334, _e335, _e114, _e336, 1.0, _e341, _e345, eps_4);
                float3 _e347 = w;
                const Shaded _e348 = scaled(_e346, _e347);
                const Shaded _e349 = add(_e330, _e348);
                t = _e349;
            }
        }
    }
    float3 _e355 = t.diffuse;
    float3 _e357 = t.specular;
    uint _e359 = count;
    out_tex[texel_1] = float4((_e355 + _e357), float(_e359));
    return;
}
