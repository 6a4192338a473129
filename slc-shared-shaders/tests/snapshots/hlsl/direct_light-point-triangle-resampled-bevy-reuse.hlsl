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

struct ReuseParams {
    float4 c0_;
    float4 c1_;
    float4 c2_;
    float4 c3_;
    float3 prev_eye;
    float max_confidence;
    uint has_history;
    float radius;
    uint visibility;
    uint parity;
    float3 moved_min;
    uint moved;
    float3 moved_max;
    uint pad;
};

struct ReuseSurface {
    float3 x;
    float m;
    float3 n;
    uint base;
    uint rough;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};

struct ReuseSlot {
    uint light;
    uint u;
    float w;
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

struct ReusePixel {
    ReuseSurface surface;
    ReuseSlot slots[8];
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

struct Domain {
    uint pixel;
    int _pad1_0;
    int _pad1_1;
    int _pad1_2;
    float3 x;
    int _pad2_0;
    float3 n;
    int _pad3_0;
    Material m;
    float c;
    bool temporal;
    int _end_pad_0;
    int _end_pad_1;
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
static const uint DOMAINS = 3u;

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
cbuffer reuse : register(b7) { ReuseParams reuse; }
ByteAddressBuffer lights_prev : register(t8, space1);
RWByteAddressBuffer reuse_pixels : register(u9, space1);
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

uint reuse_stream(uint stream_1, uint which)
{
    const uint _e2 = pick_stream(stream_1);
    const uint _e6 = pcg_hash(((_e2 + 1u) + which));
    return _e6;
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
    float3 q_9 = clamp(c_1, bmin, bmax);
    float3 v_6 = (q_9 - c_1);
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
    bool local_16 = (bool)0;
    bool local_17 = (bool)0;

    float3 v_7 = (x_2 - y);
    float d2_6 = dot(v_7, v_7);
    const bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local_16 = !((d2_6 > 0.0));
    } else {
        local_16 = true;
    }
    bool _e16 = local_16;
    if (_e16) {
        return 0.0;
    }
    float3 w_12 = (v_7 / (sqrt(d2_6)).xxx);
    float cos_x_1 = -(dot(n_1, w_12));
    if (!(!((cos_x_1 > 0.0)))) {
        local_17 = !((dot(ng, w_12) < 0.0));
    } else {
        local_17 = true;
    }
    bool _e34 = local_17;
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

bool weighted_replace(float w_4, float w_sum, float u_2)
{
    return ((u_2 * w_sum) < w_4);
}

float weighted_threshold(float w_sum_1, float u_3)
{
    return (w_sum_1 / (1.0 - u_3));
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
    uint j_7 = naga_mod(slot, 3u);
    if ((j_7 == 0u)) {
        return c_4.x;
    }
    if ((j_7 == 1u)) {
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
        float w_13 = (1.0 / _e4);
        return float3(w_13, w_13, w_13);
    }
    uint j_8 = naga_mod(slot_1, 3u);
    const float _e15 = to_f32_(naga_div(((k_3 + 2u) - j_8), 3u));
    float w_14 = (1.0 / _e15);
    if ((j_8 == 0u)) {
        return float3(w_14, 0.0, 0.0);
    }
    if ((j_8 == 1u)) {
        return float3(0.0, w_14, 0.0);
    }
    return float3(0.0, 0.0, w_14);
}

float grid_coordinate(uint bits_1)
{
    const float _e3 = to_f32_((bits_1 >> 16u));
    return ((_e3 + 0.5) / 65536.0);
}

uint grid_cells(uint h1_, uint h2_)
{
    return ((h1_ & 4294901760u) | (h2_ >> 16u));
}

float2 disk_offset(float r_3, float u1_1, float u2_1)
{
    float a_9 = (TWO_PI * u2_1);
    return (float2(cos(a_9), sin(a_9)) * (r_3 * sqrt(u1_1)));
}

float gris_weight(float own, float all_, float p_hat, float w_5)
{
    if (!((all_ > 0.0))) {
        return 0.0;
    }
    return (((own / all_) * p_hat) * w_5);
}

float reuse_trust(float3 h_1, float3 t_1)
{
    float d2_7 = dot(h_1, h_1);
    if (!((d2_7 > 0.0))) {
        return 1.0;
    }
    float3 c_11 = (h_1 - t_1);
    return (d2_7 / (d2_7 + (REUSE_TRUST_SCALE * dot(c_11, c_11))));
}

float gris_contribution_weight(float w_sum_2, float p_hat_1)
{
    if (!((p_hat_1 > 0.0))) {
        return 0.0;
    }
    return (w_sum_2 / p_hat_1);
}

float ggx_d(float cos_h, float sin2_h, float alpha)
{
    if ((cos_h <= 0.0)) {
        return 0.0;
    }
    float a2_ = (alpha * alpha);
    float t_6 = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t_6 * t_6));
}

float smith_root(float cos_, float alpha_1)
{
    float a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1.0 - a2_1)) + a2_1));
}

float smith_visibility(float n_l, float n_v, float alpha_2)
{
    bool local_18 = (bool)0;

    if (!((n_l <= 0.0))) {
        local_18 = (n_v <= 0.0);
    } else {
        local_18 = true;
    }
    bool _e11 = local_18;
    if (_e11) {
        return 0.0;
    }
    const float _e13 = smith_root(n_v, alpha_2);
    const float _e15 = smith_root(n_l, alpha_2);
    return (0.5 / ((n_l * _e13) + (n_v * _e15)));
}

float3 fresnel_schlick(float3 f0_, float f90_, float v_h)
{
    float c_12 = saturate((1.0 - v_h));
    float c2_1 = (c_12 * c_12);
    return (f0_ + ((float3(f90_, f90_, f90_) - f0_) * ((c2_1 * c2_1) * c_12)));
}

float3 specular_fresnel(float3 base, float metallic, float3 f0_d, float f90_d, float v_h_1)
{
    const float3 _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    const float3 _e10 = fresnel_schlick(base, 1.0, v_h_1);
    return ((_e5 * (1.0 - metallic)) + (_e10 * metallic));
}

bool has_specular(float metallic_1, float3 f0_d_1, float f90_d_1)
{
    bool local_19 = (bool)0;
    bool local_20 = (bool)0;

    if (!((metallic_1 > 0.0))) {
        local_19 = (f90_d_1 > 0.0);
    } else {
        local_19 = true;
    }
    bool _e11 = local_19;
    if (!(_e11)) {
        local_20 = (max(max(f0_d_1.x, f0_d_1.y), f0_d_1.z) > 0.0);
    } else {
        local_20 = true;
    }
    bool _e23 = local_20;
    return _e23;
}

float channel_mean(float3 c_5)
{
    return (((c_5.x + c_5.y) + c_5.z) * 0.33333334);
}

float4 receiver_lobe(float3 base_1, float metallic_2, float3 f0_d_2, float f90_d_2, float alpha_3, float n_v_1)
{
    bool local_21 = (bool)0;

    const float3 _e10 = fresnel_schlick(f0_d_2, f90_d_2, n_v_1);
    const float _e16 = channel_mean((((float3(1.0, 1.0, 1.0) - _e10) * base_1) * (1.0 - metallic_2)));
    if (!((n_v_1 <= 0.0))) {
        const bool _e22 = has_specular(metallic_2, f0_d_2, f90_d_2);
        local_21 = !(_e22);
    } else {
        local_21 = true;
    }
    bool _e25 = local_21;
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

float bevy_dfg(float r_4, float n_v_2)
{
    float rx = (1.0 - r_4);
    float a004_ = ((min((rx * rx), exp2((-9.28 * n_v_2))) * rx) + (0.0425 - (0.0275 * r_4)));
    float x_18 = max(((1.04 - (0.572 * r_4)) - (1.04 * a004_)), 5e-5);
    float y_1 = max((((0.022 * r_4) - 0.04) + (1.04 * a004_)), 5e-5);
    return (x_18 + y_1);
}

float3 bevy_brdf(float3 base_2, float metallic_3, float r_5, float reflectance_1, float3 n_4, float3 v_1, float3 l)
{
    float n_l_1 = saturate(dot(n_4, l));
    if ((n_l_1 <= 0.0)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float _e15 = bevy_alpha(r_5);
    float n_v_3 = max(dot(n_4, v_1), 0.0001);
    float3 h_4 = normalize((l + v_1));
    float n_h = saturate(dot(n_4, h_4));
    float l_h = saturate(dot(l, h_4));
    float f90_d_3 = (0.5 + (((2.0 * _e15) * l_h) * l_h));
    const float3 _e35 = fresnel_schlick(float3(1.0, 1.0, 1.0), f90_d_3, n_l_1);
    const float3 _e41 = fresnel_schlick(float3(1.0, 1.0, 1.0), f90_d_3, n_v_3);
    float burley = ((_e35.x * _e41.x) * INV_PI);
    const float _e46 = bevy_f0_(reflectance_1);
    float3 f0_1 = ((float3(_e46, _e46, _e46) * (1.0 - metallic_3)) + (base_2 * metallic_3));
    float f90_1 = saturate((((f0_1.x + f0_1.y) + f0_1.z) * 16.5));
    const float _e64 = ggx_d(n_h, (1.0 - (n_h * n_h)), _e15);
    const float _e65 = smith_visibility(n_l_1, n_v_3, _e15);
    const float _e70 = bevy_dfg(r_5, n_v_3);
    float3 comp = (float3(1.0, 1.0, 1.0) + (f0_1 * ((1.0 / _e70) - 1.0)));
    const float3 _e77 = fresnel_schlick(f0_1, f90_1, l_h);
    float3 spec = ((_e77 * comp) * (_e64 * _e65));
    return ((base_2 * ((1.0 - metallic_3) * burley)) + spec);
}

float cone_cos_of(float3 v_2, float d2_4, float a_3, float3 d)
{
    bool local_22 = (bool)0;
    bool local_23 = (bool)0;

    float vd = dot(v_2, d);
    float h2_1 = (d2_4 - (a_3 * a_3));
    if (!((h2_1 <= 0.0))) {
        if ((vd >= 0.0)) {
            local_23 = ((vd * vd) >= h2_1);
        } else {
            local_23 = false;
        }
        bool _e19 = local_23;
        local_22 = _e19;
    } else {
        local_22 = true;
    }
    bool _e21 = local_22;
    if (_e21) {
        return 1.0;
    }
    float3 c_13 = cross(v_2, d);
    return min((((vd * sqrt(h2_1)) + (sqrt(dot(c_13, c_13)) * a_3)) / d2_4), 1.0);
}

float cone_cos_toward(float3 center_, float radius, float3 p, float3 d_1)
{
    float3 v_8 = (center_ - p);
    const float _e6 = cone_cos_of(v_8, dot(v_8, v_8), radius, d_1);
    return _e6;
}

float range_scale_at(float4 rl, float cos_t)
{
    float t_7 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_7 * t_7))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(float4 rl_1, float3 center_1, float radius_1, float3 p_1, float3 r_6)
{
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    const float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_6);
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
    bool local_24 = (bool)0;

    float3 n_17 = cross((b_3 - a_4), (c_6 - a_4));
    float l2_ = dot(n_17, n_17);
    if (!(!((l2_ > 0.0)))) {
        local_24 = !((l2_ < 3e38));
    } else {
        local_24 = true;
    }
    bool _e17 = local_24;
    if (_e17) {
        return float3(0.0, 0.0, 0.0);
    }
    return (n_17 / (sqrt(l2_)).xxx);
}

float ray_triangle(float3 o_1, float3 d_3, float3 a_5, float3 b_4, float3 c_7, float t_min, float t_max_1)
{
    bool local_25 = (bool)0;
    bool local_26 = (bool)0;
    bool local_27 = (bool)0;

    float3 e1_ = (b_4 - a_5);
    float3 e2_ = (c_7 - a_5);
    float3 p_8 = cross(d_3, e2_);
    float det = dot(e1_, p_8);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv = (1.0 / det);
    float3 s_12 = (o_1 - a_5);
    float u_4 = (dot(s_12, p_8) * inv);
    if (!((u_4 < 0.0))) {
        local_25 = (u_4 > 1.0);
    } else {
        local_25 = true;
    }
    bool _e28 = local_25;
    if (_e28) {
        return -1.0;
    }
    float3 q_10 = cross(s_12, e1_);
    float v_9 = (dot(d_3, q_10) * inv);
    if (!((v_9 < 0.0))) {
        local_26 = ((u_4 + v_9) > 1.0);
    } else {
        local_26 = true;
    }
    bool _e42 = local_26;
    if (_e42) {
        return -1.0;
    }
    float t_8 = (dot(e2_, q_10) * inv);
    if ((t_8 > t_min)) {
        local_27 = (t_8 < t_max_1);
    } else {
        local_27 = false;
    }
    bool _e51 = local_27;
    if (_e51) {
        return t_8;
    }
    return -1.0;
}

float3 reproject(float4 c0_, float4 c1_, float4 c2_, float4 c3_, float3 p_2, float width, float height)
{
    float4 clip_ = ((((c0_ * p_2.x) + (c1_ * p_2.y)) + (c2_ * p_2.z)) + c3_);
    if ((clip_.w <= 0.0)) {
        return float3(-1.0, -1.0, 0.0);
    }
    float x_19 = (((((clip_.x / clip_.w) + 1.0) * 0.5) * width) - 0.5);
    float y_2 = ((((1.0 - (clip_.y / clip_.w)) * 0.5) * height) - 0.5);
    return float3(x_19, y_2, clip_.w);
}

bool history_matches(float3 n_5, float3 nh, float3 p_3, float oh, float d_4)
{
    bool local_28 = (bool)0;

    if ((abs((dot(nh, p_3) - oh)) <= (TEMPORAL_DEPTH_TOLERANCE * d_4))) {
        local_28 = (dot(n_5, nh) >= TEMPORAL_NORMAL_COS);
    } else {
        local_28 = false;
    }
    bool _e17 = local_28;
    return _e17;
}

float3 light_intensity(GpuLight l_1, float3 w_6)
{
    switch(l_1.kind) {
        case 0u: {
            return l_1.intensity;
        }
        case 3u: {
            const float3 _e8 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
            const float _e10 = triangle_lobe(_e8, l_1.a, w_6);
            return (l_1.intensity * _e10);
        }
        default: {
            return (0.0).xxx;
        }
    }
}

float3 light_point(GpuLight l_2, float u1_2, float u2_2)
{
    if ((l_2.kind == LIGHT_TRIANGLE)) {
        const float3 _e9 = triangle_sample(l_2.p0_, l_2.p1_, l_2.p2_, u1_2, u2_2);
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
        GpuGeoNode n_18 = ConstructGpuGeoNode(asfloat(geo_nodes.Load3(_e21*32+0)), asuint(geo_nodes.Load(_e21*32+12)), asfloat(geo_nodes.Load3(_e21*32+16)), asuint(geo_nodes.Load(_e21*32+28)));
        float _e27 = hit.t;
        const float _e28 = ray_aabb(o_2, _e14, n_18.bmin, n_18.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_18.count > 0u)) {
                i = n_18.first;
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
                    if ((_e36 < (n_18.first + n_18.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_9 = ConstructGpuTriangle(asfloat(geo_tris.Load3(_e42*48+0)), asuint(geo_tris.Load(_e42*48+12)), asfloat(geo_tris.Load3(_e42*48+16)), asuint(geo_tris.Load(_e42*48+28)), asfloat(geo_tris.Load3(_e42*48+32)), asuint(geo_tris.Load(_e42*48+44)));
                        float _e49 = hit.t;
                        const float _e50 = ray_triangle(o_2, d_5, t_9.v0_, t_9.v1_, t_9.v2_, t_min_1, _e49);
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
                    stack[min(uint(_e63), 63u)] = (n_18.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_18.first;
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

float bsh_inner_scale(float a_7, float3 v_3, float d2_5, float3 r_7, float4 rl_2)
{
    const float _e5 = cone_cos_of(v_3, d2_5, a_7, r_7);
    const float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_4, float3 x_4, float3 r_8, float4 rl_3)
{
    bool local_29 = (bool)0;
    bool local_30 = (bool)0;

    const bool _e6 = sphere_contains_point(node_4.center_, node_4.radius, x_4);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        const bool _e20 = sphere_contains_point(node_4.center_, (node_4.radius * (rl_3.w * 1.0001)), x_4);
        local_29 = !(_e20);
    } else {
        local_29 = true;
    }
    bool _e23 = local_29;
    if (_e23) {
        return false;
    }
    float3 v_10 = (x_4 - node_4.center_);
    float d2_8 = dot(v_10, v_10);
    const float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if ((d2_8 > (_e29 * _e29))) {
        return false;
    }
    if ((node_4.child == BSH_NONE)) {
        const float _e38 = range_scale_toward(rl_3, node_4.center_, node_4.extent, x_4, r_8);
        const float _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        const bool _e42 = sphere_contains_point(node_4.center_, _e41, x_4);
        return _e42;
    }
    const float _e45 = bsh_inner_scale(node_4.extent, -(v_10), d2_8, r_8, rl_3);
    float s_c = (_e45 * 1.001);
    const float _e50 = bsh_range_bound(node_4);
    float reach = (node_4.extent + (sqrt(s_c) * _e50));
    if ((d2_8 <= ((node_4.radius * node_4.radius) * s_c))) {
        local_30 = (d2_8 <= (reach * reach));
    } else {
        local_30 = false;
    }
    bool _e63 = local_30;
    return _e63;
}

bool bsh_reaches_box(BshNode node_5, float3 lo, float3 hi, float w_7)
{
    const bool _e13 = sphere_overlaps_aabb(node_5.center_, (node_5.radius * (max(1.0, (w_7 * 1.0001)) * 1.0001)), lo, hi);
    return _e13;
}

uint bsh_subtree(uint nodes_3, uint s_1, uint depth)
{
    uint i_2 = (uint)0;
    uint level = 0u;
    bool local_31 = (bool)0;

    const uint _e3 = bsh_first(nodes_3);
    i_2 = _e3;
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e7 = level;
        if ((_e7 < depth)) {
            uint _e11 = i_2;
            local_31 = (_e11 != BSH_NONE);
        } else {
            local_31 = false;
        }
        bool _e15 = local_31;
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

uint bsh_next_leaf_box(uint nodes_4, uint start_1, uint end, float3 lo_1, float3 hi_1, float w_8)
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
            const bool _e11 = bsh_reaches_box(_e10, lo_1, hi_1, w_8);
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

float next_threshold(float sum, inout uint h_2)
{
    uint _e2 = h_2;
    const uint _e3 = pcg_hash(_e2);
    h_2 = _e3;
    uint _e4 = h_2;
    const float _e5 = xi_from_bits(_e4);
    const float _e6 = weighted_threshold(sum, _e5);
    return _e6;
}

Connection connect_record(GpuLight l_3, float3 x_5, float3 n_6, float3 ng_1, float r2_2, float rt2_2, float w_res, float u1_3, float u2_3, float eps, bool trace_1)
{
    Connection c_8 = (Connection)0;
    bool local_32 = (bool)0;
    bool local_33 = (bool)0;

    c_8.e = (0.0).xxx;
    const float3 _e16 = light_point(l_3, u1_3, u2_3);
    c_8.y = _e16;
    float3 _e19 = c_8.y;
    const float _e20 = connection_cosine(x_5, _e19, n_6, ng_1, r2_2);
    c_8.cos_x = _e20;
    float _e22 = c_8.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            float3 _e33 = c_8.y;
            const bool _e34 = occluded((x_5 + (ng_1 * eps)), _e33);
            local_33 = _e34;
        } else {
            local_33 = false;
        }
        bool _e36 = local_33;
        local_32 = _e36;
    } else {
        local_32 = true;
    }
    bool _e38 = local_32;
    if (_e38) {
        Connection _e39 = c_8;
        const Connection connection = _e39;
        return connection;
    }
    float3 _e41 = c_8.y;
    float3 v_11 = (x_5 - _e41);
    float d2_9 = dot(v_11, v_11);
    const float3 _e48 = light_intensity(l_3, (v_11 / (sqrt(d2_9)).xxx));
    float _e50 = c_8.cos_x;
    const float _e51 = connection_factor(_e50, d2_9, rt2_2, w_res);
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

Connection connect_traced(uint li, float3 x_6, float3 n_7, float3 ng_2, float s_2, float w_res_1, float u1_4, float u2_4, float eps_1, bool trace_2)
{
    GpuLight _e12 = ConstructGpuLight(asfloat(lights.Load3(li*64+0)), asuint(lights.Load(li*64+12)), asfloat(lights.Load3(li*64+16)), asfloat(lights.Load(li*64+28)), asfloat(lights.Load3(li*64+32)), asfloat(lights.Load(li*64+44)), asfloat(lights.Load3(li*64+48)), asuint(lights.Load(li*64+60)));
    float _e15 = asfloat(r2_3.Load(li*4));
    float _e19 = asfloat(rt2_3.Load(li*4));
    const Connection _e21 = connect_record(_e12, x_6, n_7, ng_2, (s_2 * _e15), (s_2 * _e19), w_res_1, u1_4, u2_4, eps_1, trace_2);
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

float light_range_scale(uint li_1, float3 x_7, float3 r_9, float4 rl_4)
{
    GpuLightCone c_14 = ConstructGpuLightCone(asfloat(light_cones.Load3(li_1*48+0)), asfloat(light_cones.Load(li_1*48+12)), asfloat(light_cones.Load3(li_1*48+16)), asfloat(light_cones.Load(li_1*48+28)), asfloat(light_cones.Load(li_1*48+32)), asfloat(light_cones.Load(li_1*48+36)), asuint(light_cones.Load(li_1*48+40)), asuint(light_cones.Load(li_1*48+44)));
    const float _e9 = range_scale_toward(rl_4, c_14.center_, c_14.radius, x_7, r_9);
    return _e9;
}

float4 surface_at(int2 texel)
{
    float4 p_9 = position_tex.Load(int3(texel, int(0)));
    return ((p_9.w > 0.0) ? float4(p_9.xyz, 1.0) : (0.0).xxxx);
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

WorkgroupBox point_box(float3 p_4, bool has)
{
    const WorkgroupBox workgroupbox_1 = ConstructWorkgroupBox((has ? p_4 : (3.4028235e38).xxx), (has ? p_4 : (-3.4028235e38).xxx));
    return workgroupbox_1;
}

WorkgroupBox workgroup_box(uint li_3, float3 p_5, bool has_1)
{
    const WorkgroupBox _e3 = point_box(p_5, has_1);
    const WorkgroupBox _e6 = workgroup_bounds(li_3, _e3.lo, _e3.hi);
    const WorkgroupBox workgroupbox_2 = _e6;
    return workgroupbox_2;
}

bool box_is_empty(WorkgroupBox b_6)
{
    return (b_6.lo.x > b_6.hi.x);
}

uint tile_subtree(uint s_3, TileWalk t_2, bool list, uint at, uint start_2, uint to)
{
    uint p_6 = (uint)0;
    uint b_7 = (uint)0;
    bool local_34 = (bool)0;
    bool local_35 = (bool)0;
    bool local_36 = (bool)0;

    const uint _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH);
    if ((_e8 == BSH_NONE)) {
        return 0u;
    }
    uint end_1 = asuint(bsh_nodes.Load(20+_e8*32));
    p_6 = at;
    const uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_2.lo, t_2.hi, t_2.w);
    b_7 = _e21;
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e53 = b_7;
            uint _e56 = asuint(bsh_nodes.Load(20+_e53*32));
            const uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_2.lo, t_2.hi, t_2.w);
            b_7 = _e60;
        }
        loop_init_2 = false;
        uint _e23 = b_7;
        if ((_e23 != end_1)) {
            if (!(!(list))) {
                uint _e31 = p_6;
                local_35 = (_e31 < to);
            } else {
                local_35 = true;
            }
            bool _e34 = local_35;
            local_34 = _e34;
        } else {
            local_34 = false;
        }
        bool _e36 = local_34;
        if (_e36) {
        } else {
            break;
        }
        {
            if (list) {
                uint _e39 = p_6;
                local_36 = (_e39 >= start_2);
            } else {
                local_36 = false;
            }
            bool _e42 = local_36;
            if (_e42) {
                uint _e44 = p_6;
                uint _e47 = b_7;
                tile_list[min(uint((_e44 - start_2)), 1023u)] = _e47;
            }
            uint _e48 = p_6;
            p_6 = (_e48 + 1u);
        }
    }
    uint _e61 = p_6;
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

TileWalk tile_walk_begin(uint li_4, float3 x_8, float w_9, bool has_2)
{
    bool local_37 = (bool)0;
    TileWalk t_3 = (TileWalk)0;
    uint s_4 = (uint)0;
    uint sum_1 = 0u;
    uint s_5 = 0u;

    if (has_2) {
        local_37 = (w_9 >= 0.0);
    } else {
        local_37 = false;
    }
    bool _e12 = local_37;
    uint _e14; InterlockedMax(tile_scale, (_e12 ? asuint(w_9) : 0u), _e14);
    const WorkgroupBox _e15 = workgroup_box(li_4, x_8, has_2);
    GroupMemoryBarrierWithGroupSync();
    uint _e19 = tile_scale;
    GroupMemoryBarrierWithGroupSync();
    t_3 = ConstructTileWalk(_e15.lo, _e15.hi, asfloat(_e19), 0u);
    const bool _e24 = box_is_empty(_e15);
    if (_e24) {
        TileWalk _e25 = t_3;
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
            TileWalk _e34 = t_3;
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
                uint c_15 = subtree_at[min(uint(_e53), 255u)];
                uint _e57 = s_5;
                uint _e59 = sum_1;
                subtree_at[min(uint(_e57), 255u)] = _e59;
                uint _e60 = sum_1;
                sum_1 = (_e60 + c_15);
            }
        }
        uint _e66 = sum_1;
        tile_total = _e66;
    }
    GroupMemoryBarrierWithGroupSync();
    uint _e69 = tile_total;
    GroupMemoryBarrierWithGroupSync();
    t_3.total = _e69;
    TileWalk _e70 = t_3;
    const TileWalk tilewalk_1 = _e70;
    return tilewalk_1;
}

uint tile_walk_fill(uint li_5, TileWalk t_4, uint start_3)
{
    uint s_6 = (uint)0;
    uint past = (uint)0;
    bool local_38 = (bool)0;

    uint to_1 = min(t_4.total, (start_3 + TILE_LIST));
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
            past = t_4.total;
            uint _e17 = s_6;
            if (((_e17 + 1u) < BSH_TILE_SUBTREES)) {
                uint _e23 = s_6;
                uint _e27 = subtree_at[min(uint((_e23 + 1u)), 255u)];
                past = _e27;
            }
            if ((at_1 < to_1)) {
                uint _e31 = past;
                local_38 = (_e31 > start_3);
            } else {
                local_38 = false;
            }
            bool _e34 = local_38;
            if (_e34) {
                uint _e35 = s_6;
                const uint _e37 = tile_subtree(_e35, t_4, true, at_1, start_3, to_1);
            }
        }
    }
    GroupMemoryBarrierWithGroupSync();
    return (to_1 - start_3);
}

Shaded shade_connection(Connection c_9, float3 x_9, float3 n_8, Material m_1)
{
    Shaded s_7 = (Shaded)0;

    s_7.e = c_9.e;
    s_7.diffuse = (0.0).xxx;
    s_7.specular = (0.0).xxx;
    if ((c_9.cos_x > 0.0)) {
        const float3 _e25 = bevy_brdf(m_1.base, m_1.metallic, m_1.roughness, m_1.reflectance, n_8, m_1.v, normalize((c_9.y - x_9)));
        s_7.diffuse = (_e25 * c_9.e);
    }
    Shaded _e28 = s_7;
    const Shaded shaded_1 = _e28;
    return shaded_1;
}

Shaded shade_pick_traced(uint li_6, float3 x_10, float3 n_9, float3 r_10, float4 rl_5, Material m_2, float w_10, float u1_5, float u2_5, float eps_2, bool trace_3)
{
    const float _e11 = light_range_scale(li_6, x_10, r_10, rl_5);
    const Connection _e12 = connect_traced(li_6, x_10, n_9, n_9, _e11, w_10, u1_5, u2_5, eps_2, trace_3);
    const Shaded _e13 = shade_connection(_e12, x_10, n_9, m_2);
    const Shaded shaded_2 = _e13;
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

Shaded scaled(Shaded s_8, float3 w_11)
{
    const Shaded shaded_4 = ConstructShaded((s_8.e * w_11), (s_8.diffuse * w_11), (s_8.specular * w_11));
    return shaded_4;
}

typedef uint ret_first_holders[8];
ret_first_holders first_holders(uint2 keys_1[8], bool held_1[8])
{
    uint first[8] = (uint[8])0;
    uint k_4 = 0u;
    uint j_4 = (uint)0;
    bool local_39 = (bool)0;
    bool local_40 = (bool)0;

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
            j_4 = 0u;
            uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
            bool loop_init_7 = true;
            while(true) {
                if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_7) {
                    uint _e42 = j_4;
                    j_4 = (_e42 + 1u);
                }
                loop_init_7 = false;
                uint _e17 = j_4;
                uint _e18 = k_4;
                if ((_e17 < _e18)) {
                    uint _e22 = k_4;
                    local_39 = held_1[min(uint(_e22), 7u)];
                } else {
                    local_39 = false;
                }
                bool _e25 = local_39;
                if (_e25) {
                } else {
                    break;
                }
                {
                    uint _e26 = j_4;
                    if (held_1[min(uint(_e26), 7u)]) {
                        uint _e30 = j_4;
                        uint _e32 = k_4;
                        local_40 = all((keys_1[min(uint(_e30), 7u)] == keys_1[min(uint(_e32), 7u)]));
                    } else {
                        local_40 = false;
                    }
                    bool _e37 = local_40;
                    if (_e37) {
                        uint _e38 = k_4;
                        uint _e40 = j_4;
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

uint previous_index(uint i_4)
{
    uint _e4 = reuse.parity;
    uint _e8 = view.width;
    uint _e12 = view.height;
    return ((((1u - _e4) * _e8) * _e12) + i_4);
}

uint next_index(uint i_5)
{
    uint _e3 = reuse.parity;
    uint _e6 = view.width;
    uint _e10 = view.height;
    return (((_e3 * _e6) * _e10) + i_5);
}

Connection sample_connection(GpuLight l_4, uint cells, float3 x_11, float3 n_10, float eps_3, bool trace_4)
{
    const float _e9 = grid_coordinate(cells);
    const float _e12 = grid_coordinate((cells << 16u));
    const Connection _e13 = connect_record(l_4, x_11, n_10, n_10, UNRANGED, UNRANGED, 1.0, _e9, _e12, eps_3, trace_4);
    const Connection connection_3 = _e13;
    return connection_3;
}

float reuse_target(uint q_6, GpuLight l_5, uint cells_1, float3 x_12, float3 n_11, Material m_3)
{
    const Connection _e8 = sample_connection(l_5, cells_1, x_12, n_11, 0.0, false);
    const Shaded _e9 = shade_connection(_e8, x_12, n_11, m_3);
    const float3 _e10 = output_of(_e9);
    const float _e12 = slot_target(_e10, q_6, K);
    return _e12;
}

ReuseSurface ConstructReuseSurface(float3 arg0, float arg1, float3 arg2, uint arg3, uint arg4, uint arg5, uint arg6, uint arg7) {
    ReuseSurface ret = (ReuseSurface)0;
    ret.x = arg0;
    ret.m = arg1;
    ret.n = arg2;
    ret.base = arg3;
    ret.rough = arg4;
    ret.pad0_ = arg5;
    ret.pad1_ = arg6;
    ret.pad2_ = arg7;
    return ret;
}

ReuseSurface reuse_surface(float3 x_13, float3 n_12, Material m_4, float c_10)
{
    float4 _e6 = float4(m_4.base, m_4.metallic);
    float2 _e12 = float2(saturate(m_4.roughness), saturate(m_4.reflectance));
    const ReuseSurface reusesurface = ConstructReuseSurface(x_13, c_10, n_12, (uint(round(clamp(_e6[0], 0.0, 1.0) * 255.0)) | uint(round(clamp(_e6[1], 0.0, 1.0) * 255.0)) << 8 | uint(round(clamp(_e6[2], 0.0, 1.0) * 255.0)) << 16 | uint(round(clamp(_e6[3], 0.0, 1.0) * 255.0)) << 24), (uint(round(clamp(_e12[0], 0.0, 1.0) * 65535.0)) | uint(round(clamp(_e12[1], 0.0, 1.0) * 65535.0)) << 16), 0u, 0u, 0u);
    return reusesurface;
}

Material reuse_material(ReuseSurface s_10, float3 eye)
{
    uint _e2 = s_10.base;
    float4 b_9 = (float4(_e2 & 0xFF, _e2 >> 8 & 0xFF, _e2 >> 16 & 0xFF, _e2 >> 24) / 255.0);
    uint _e4 = s_10.rough;
    float2 r_12 = (float2(_e4 & 0xFFFF, _e4 >> 16) / 65535.0);
    const Material _e13 = material_of(b_9.xyz, b_9.w, r_12.x, r_12.y, normalize((eye - s_10.x)));
    const Material material_1 = _e13;
    return material_1;
}

uint2 sample_key(uint li_7, uint cells_2)
{
    uint _e6 = asuint(lights.Load(12+li_7*64));
    return uint2(li_7, ((_e6 == LIGHT_TRIANGLE) ? cells_2 : 0u));
}

bool sample_reaches(GpuLight l_6, uint cells_3, float3 x_14, float3 n_13, float eps_4)
{
    const Connection _e6 = sample_connection(l_6, cells_3, x_14, n_13, eps_4, true);
    return any((_e6.e > (0.0).xxx));
}

float domain_offset(Domain d_6)
{
    float _e3 = view.shadow_offset;
    float3 _e6 = reuse.prev_eye;
    return (_e3 * length((_e6 - d_6.x)));
}

bool history_vouches(uint li_8, uint cells_4, Domain d_7)
{
    uint _e5 = reuse.moved;
    if ((_e5 == 0u)) {
        return true;
    }
    uint _e11 = reuse.moved;
    if ((_e11 == 2u)) {
        return false;
    }
    const float _e17 = domain_offset(d_7);
    float3 a_10 = (d_7.x + (d_7.n * _e17));
    GpuLight _e22 = ConstructGpuLight(asfloat(lights_prev.Load3(li_8*64+0)), asuint(lights_prev.Load(li_8*64+12)), asfloat(lights_prev.Load3(li_8*64+16)), asfloat(lights_prev.Load(li_8*64+28)), asfloat(lights_prev.Load3(li_8*64+32)), asfloat(lights_prev.Load(li_8*64+44)), asfloat(lights_prev.Load3(li_8*64+48)), asuint(lights_prev.Load(li_8*64+60)));
    const float _e23 = grid_coordinate(cells_4);
    const float _e26 = grid_coordinate((cells_4 << 16u));
    const float3 _e27 = light_point(_e22, _e23, _e26);
    const float3 _e29 = ray_inverse3_((_e27 - a_10));
    float3 _e32 = reuse.moved_min;
    float3 _e35 = reuse.moved_max;
    const float _e37 = ray_aabb(a_10, _e29, _e32, _e35, 1.0);
    return (_e37 < 0.0);
}

ReuseSlot ConstructReuseSlot(uint arg0, uint arg1, float arg2) {
    ReuseSlot ret = (ReuseSlot)0;
    ret.light = arg0;
    ret.u = arg1;
    ret.w = arg2;
    return ret;
}

bool reached_before(uint li_9, uint cells_5, Domain d_8, float3 x_15, float3 n_14)
{
    bool local_41 = (bool)0;
    bool local_42 = (bool)0;
    bool local_43 = (bool)0;
    bool local_44 = (bool)0;
    uint q_7 = 0u;
    bool local_45 = (bool)0;
    bool local_46 = (bool)0;

    const bool _e5 = history_vouches(li_9, cells_5, d_8);
    if (!(_e5)) {
        return false;
    }
    GpuLight l_7 = ConstructGpuLight(asfloat(lights.Load3(li_9*64+0)), asuint(lights.Load(li_9*64+12)), asfloat(lights.Load3(li_9*64+16)), asfloat(lights.Load(li_9*64+28)), asfloat(lights.Load3(li_9*64+32)), asfloat(lights.Load(li_9*64+44)), asfloat(lights.Load3(li_9*64+48)), asuint(lights.Load(li_9*64+60)));
    GpuLight lp = ConstructGpuLight(asfloat(lights_prev.Load3(li_9*64+0)), asuint(lights_prev.Load(li_9*64+12)), asfloat(lights_prev.Load3(li_9*64+16)), asfloat(lights_prev.Load(li_9*64+28)), asfloat(lights_prev.Load3(li_9*64+32)), asfloat(lights_prev.Load(li_9*64+44)), asfloat(lights_prev.Load3(li_9*64+48)), asuint(lights_prev.Load(li_9*64+60)));
    if (all((d_8.x == x_15))) {
        local_41 = all((d_8.n == n_14));
    } else {
        local_41 = false;
    }
    bool _e23 = local_41;
    if (_e23) {
        local_42 = all((l_7.p0_ == lp.p0_));
    } else {
        local_42 = false;
    }
    bool _e31 = local_42;
    if (_e31) {
        local_43 = all((l_7.p1_ == lp.p1_));
    } else {
        local_43 = false;
    }
    bool _e39 = local_43;
    if (_e39) {
        local_44 = all((l_7.p2_ == lp.p2_));
    } else {
        local_44 = false;
    }
    bool _e47 = local_44;
    if (_e47) {
        return true;
    }
    const uint2 _e49 = sample_key(li_9, cells_5);
    uint2 loop_bound_11 = uint2(4294967295u, 4294967295u);
    bool loop_init_8 = true;
    while(true) {
        if (all(loop_bound_11 == uint2(0u, 0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_8) {
            uint _e85 = q_7;
            q_7 = (_e85 + 1u);
        }
        loop_init_8 = false;
        uint _e52 = q_7;
        if ((_e52 < K)) {
        } else {
            break;
        }
        {
            const uint _e57 = previous_index(d_8.pixel);
            uint _e60 = q_7;
            ReuseSlot h_5 = ConstructReuseSlot(asuint(reuse_pixels.Load(_e60*12+48+_e57*144+0)), asuint(reuse_pixels.Load(_e60*12+48+_e57*144+4)), asfloat(reuse_pixels.Load(_e60*12+48+_e57*144+8)));
            if ((h_5.w > 0.0)) {
                local_45 = (h_5.light < ((NagaBufferLength(lights) - 0) / 64));
            } else {
                local_45 = false;
            }
            bool _e73 = local_45;
            if (_e73) {
                const uint2 _e78 = sample_key(h_5.light, h_5.u);
                local_46 = all((_e78 == _e49));
            } else {
                local_46 = false;
            }
            bool _e82 = local_46;
            if (_e82) {
                return true;
            }
        }
    }
    const float _e89 = domain_offset(d_8);
    const bool _e90 = sample_reaches(lp, cells_5, d_8.x, d_8.n, _e89);
    return _e90;
}

Domain ConstructDomain(uint arg0, float3 arg1, float3 arg2, Material arg3, float arg4, bool arg5) {
    Domain ret = (Domain)0;
    ret.pixel = arg0;
    ret.x = arg1;
    ret.n = arg2;
    ret.m = arg3;
    ret.c = arg4;
    ret.temporal = arg5;
    return ret;
}

int2 naga_f2i32(float2 value) {
    return int2(clamp(value, -2147483600.0, 2147483500.0));
}

uint reuse_domains(float3 x_16, float3 n_15, float d_9, uint h_3, inout Domain doms_1[3])
{
    uint nd = 0u;
    uint hr = (uint)0;
    uint j_5 = 0u;
    float2 p_7 = (float2)0;
    bool local_47 = (bool)0;
    bool local_48 = (bool)0;
    bool local_49 = (bool)0;
    bool seen_1 = (bool)0;
    uint k_5 = (uint)0;
    bool local_50 = (bool)0;
    bool local_51 = (bool)0;
    bool local_52 = (bool)0;

    uint _e9 = reuse.has_history;
    if ((_e9 != 1u)) {
        return 0u;
    }
    float4 _e15 = reuse.c0_;
    float4 _e18 = reuse.c1_;
    float4 _e21 = reuse.c2_;
    float4 _e24 = reuse.c3_;
    uint _e27 = view.width;
    uint _e31 = view.height;
    const float3 _e33 = reproject(_e15, _e18, _e21, _e24, x_16, float(_e27), float(_e31));
    if ((_e33.z <= 0.0)) {
        return 0u;
    }
    hr = h_3;
    uint2 loop_bound_12 = uint2(4294967295u, 4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (all(loop_bound_12 == uint2(0u, 0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e176 = j_5;
            j_5 = (_e176 + 1u);
        }
        loop_init_9 = false;
        uint _e41 = j_5;
        if ((_e41 < DOMAINS)) {
        } else {
            break;
        }
        {
            p_7 = _e33.xy;
            uint _e46 = j_5;
            if ((_e46 > 0u)) {
                uint _e49 = hr;
                const uint _e50 = pcg_hash(_e49);
                hr = _e50;
                uint _e51 = hr;
                const float _e52 = xi_from_bits(_e51);
                uint _e53 = hr;
                const uint _e54 = pcg_hash(_e53);
                hr = _e54;
                float2 _e55 = p_7;
                float _e58 = reuse.radius;
                uint _e59 = hr;
                const float _e60 = xi_from_bits(_e59);
                const float2 _e61 = disk_offset(_e58, _e52, _e60);
                p_7 = (_e55 + _e61);
            }
            float2 _e63 = p_7;
            int2 t_10 = naga_f2i32(round(_e63));
            if (!((t_10.x < int(0)))) {
                local_47 = (t_10.y < int(0));
            } else {
                local_47 = true;
            }
            bool _e76 = local_47;
            if (!(_e76)) {
                uint _e83 = view.width;
                local_48 = (t_10.x >= int(_e83));
            } else {
                local_48 = true;
            }
            bool _e87 = local_48;
            if (!(_e87)) {
                uint _e94 = view.height;
                local_49 = (t_10.y >= int(_e94));
            } else {
                local_49 = true;
            }
            bool _e98 = local_49;
            if (_e98) {
                continue;
            }
            uint _e103 = view.width;
            uint pixel = ((uint(t_10.y) * _e103) + uint(t_10.x));
            seen_1 = false;
            k_5 = 0u;
            uint2 loop_bound_13 = uint2(4294967295u, 4294967295u);
            bool loop_init_10 = true;
            while(true) {
                if (all(loop_bound_13 == uint2(0u, 0u))) { break; }
                loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                if (!loop_init_10) {
                    uint _e127 = k_5;
                    k_5 = (_e127 + 1u);
                }
                loop_init_10 = false;
                uint _e112 = k_5;
                uint _e113 = nd;
                if ((_e112 < _e113)) {
                } else {
                    break;
                }
                {
                    bool _e115 = seen_1;
                    if (!(_e115)) {
                        uint _e119 = k_5;
                        uint _e122 = doms_1[min(uint(_e119), 2u)].pixel;
                        local_50 = (_e122 == pixel);
                    } else {
                        local_50 = true;
                    }
                    bool _e125 = local_50;
                    seen_1 = _e125;
                }
            }
            const uint _e130 = previous_index(pixel);
            ReuseSurface s_13 = ConstructReuseSurface(asfloat(reuse_pixels.Load3(0+_e130*144+0)), asfloat(reuse_pixels.Load(0+_e130*144+12)), asfloat(reuse_pixels.Load3(0+_e130*144+16)), asuint(reuse_pixels.Load(0+_e130*144+28)), asuint(reuse_pixels.Load(0+_e130*144+32)), asuint(reuse_pixels.Load(0+_e130*144+36)), asuint(reuse_pixels.Load(0+_e130*144+40)), asuint(reuse_pixels.Load(0+_e130*144+44)));
            bool _e134 = seen_1;
            if (!(_e134)) {
                local_51 = !((s_13.m > 0.0));
            } else {
                local_51 = true;
            }
            bool _e143 = local_51;
            if (!(_e143)) {
                const bool _e151 = history_matches(n_15, s_13.n, x_16, dot(s_13.n, s_13.x), d_9);
                local_52 = !(_e151);
            } else {
                local_52 = true;
            }
            bool _e154 = local_52;
            if (_e154) {
                continue;
            }
            uint _e155 = nd;
            float3 _e161 = reuse.prev_eye;
            const Material _e162 = reuse_material(s_13, _e161);
            float _e166 = reuse.max_confidence;
            uint _e168 = j_5;
            doms_1[min(uint(_e155), 2u)] = ConstructDomain(pixel, s_13.x, s_13.n, _e162, min(s_13.m, _e166), (_e168 == 0u));
            uint _e172 = nd;
            nd = (_e172 + 1u);
        }
    }
    uint _e178 = nd;
    return _e178;
}

ReuseSlot gris_combine(uint q_8, ReuseSlot cur, bool cur_ris, float cur_c, bool cur_reached, uint k0_, uint k1_, float3 x_17, float3 n_16, Material m_5, inout Domain doms_2[3], inout uint hs_1)
{
    float w_sum_3 = 0.0;
    ReuseSlot out_ = ConstructReuseSlot(0u, 0u, 0.0);
    float out_target = 0.0;
    uint j_6 = (uint)0;
    ReuseSlot s_11 = (ReuseSlot)0;
    bool local_53 = (bool)0;
    bool local_54 = (bool)0;
    bool local_55 = (bool)0;
    float w_in = (float)0;
    bool local_56 = (bool)0;
    float own_1 = (float)0;
    float all_1 = (float)0;
    uint k_6 = (uint)0;
    float t_5 = (float)0;
    bool local_57 = (bool)0;
    bool local_58 = (bool)0;

    j_6 = k0_;
    uint2 loop_bound_14 = uint2(4294967295u, 4294967295u);
    bool loop_init_11 = true;
    while(true) {
        if (all(loop_bound_14 == uint2(0u, 0u))) { break; }
        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
        if (!loop_init_11) {
            uint _e186 = j_6;
            j_6 = (_e186 + 1u);
        }
        loop_init_11 = false;
        uint _e22 = j_6;
        if ((_e22 <= k1_)) {
        } else {
            break;
        }
        {
            s_11 = cur;
            uint _e25 = j_6;
            if ((_e25 > k0_)) {
                uint _e28 = j_6;
                uint _e33 = doms_2[min(uint((_e28 - 1u)), 2u)].pixel;
                const uint _e34 = previous_index(_e33);
                ReuseSlot _e38 = ConstructReuseSlot(asuint(reuse_pixels.Load(q_8*12+48+_e34*144+0)), asuint(reuse_pixels.Load(q_8*12+48+_e34*144+4)), asfloat(reuse_pixels.Load(q_8*12+48+_e34*144+8)));
                s_11 = _e38;
            }
            float _e40 = s_11.w;
            if (!(!((_e40 > 0.0)))) {
                uint _e48 = s_11.light;
                local_53 = (_e48 >= ((NagaBufferLength(lights) - 0) / 64));
            } else {
                local_53 = true;
            }
            bool _e53 = local_53;
            if (_e53) {
                continue;
            }
            uint _e54 = j_6;
            if ((_e54 > k0_)) {
                uint _e60 = reuse.visibility;
                local_54 = (_e60 == 1u);
            } else {
                local_54 = false;
            }
            bool _e64 = local_54;
            if (_e64) {
                uint _e68 = s_11.light;
                uint _e70 = s_11.u;
                uint _e71 = j_6;
                Domain _e75 = doms_2[min(uint((_e71 - 1u)), 2u)];
                const bool _e76 = history_vouches(_e68, _e70, _e75);
                local_55 = !(_e76);
            } else {
                local_55 = false;
            }
            bool _e79 = local_55;
            if (_e79) {
                continue;
            }
            uint _e82 = s_11.light;
            GpuLight _e84 = ConstructGpuLight(asfloat(lights.Load3(_e82*64+0)), asuint(lights.Load(_e82*64+12)), asfloat(lights.Load3(_e82*64+16)), asfloat(lights.Load(_e82*64+28)), asfloat(lights.Load3(_e82*64+32)), asfloat(lights.Load(_e82*64+44)), asfloat(lights.Load3(_e82*64+48)), asuint(lights.Load(_e82*64+60)));
            uint _e86 = s_11.u;
            const float _e87 = reuse_target(q_8, _e84, _e86, x_17, n_16, m_5);
            if (!((_e87 > 0.0))) {
                continue;
            }
            float _e92 = s_11.w;
            w_in = _e92;
            uint _e94 = j_6;
            if ((_e94 == k0_)) {
                local_56 = cur_ris;
            } else {
                local_56 = false;
            }
            bool _e99 = local_56;
            if (_e99) {
                float _e101 = s_11.w;
                w_in = (_e101 / _e87);
            }
            own_1 = (cur_c * _e87);
            float _e105 = own_1;
            all_1 = _e105;
            uint _e109 = s_11.light;
            GpuLight _e111 = ConstructGpuLight(asfloat(lights.Load3(_e109*64+0)), asuint(lights.Load(_e109*64+12)), asfloat(lights.Load3(_e109*64+16)), asfloat(lights.Load(_e109*64+28)), asfloat(lights.Load3(_e109*64+32)), asfloat(lights.Load(_e109*64+44)), asfloat(lights.Load3(_e109*64+48)), asuint(lights.Load(_e109*64+60)));
            uint _e113 = s_11.u;
            const float _e114 = grid_coordinate(_e113);
            uint _e116 = s_11.u;
            const float _e119 = grid_coordinate((_e116 << 16u));
            const float3 _e120 = light_point(_e111, _e114, _e119);
            k_6 = k0_;
            uint2 loop_bound_15 = uint2(4294967295u, 4294967295u);
            bool loop_init_12 = true;
            while(true) {
                if (all(loop_bound_15 == uint2(0u, 0u))) { break; }
                loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
                if (!loop_init_12) {
                    uint _e164 = k_6;
                    k_6 = (_e164 + 1u);
                }
                loop_init_12 = false;
                uint _e122 = k_6;
                if ((_e122 < k1_)) {
                } else {
                    break;
                }
                {
                    t_5 = 0.0;
                    uint _e126 = j_6;
                    if (!((_e126 > k0_))) {
                        local_57 = cur_reached;
                    } else {
                        local_57 = true;
                    }
                    bool _e132 = local_57;
                    if (_e132) {
                        uint _e133 = k_6;
                        Domain d_10 = doms_2[min(uint(_e133), 2u)];
                        const float _e140 = reuse_trust((_e120 - x_17), (_e120 - d_10.x));
                        uint _e144 = s_11.light;
                        GpuLight _e146 = ConstructGpuLight(asfloat(lights_prev.Load3(_e144*64+0)), asuint(lights_prev.Load(_e144*64+12)), asfloat(lights_prev.Load3(_e144*64+16)), asfloat(lights_prev.Load(_e144*64+28)), asfloat(lights_prev.Load3(_e144*64+32)), asfloat(lights_prev.Load(_e144*64+44)), asfloat(lights_prev.Load3(_e144*64+48)), asuint(lights_prev.Load(_e144*64+60)));
                        uint _e148 = s_11.u;
                        const float _e152 = reuse_target(q_8, _e146, _e148, d_10.x, d_10.n, d_10.m);
                        t_5 = ((d_10.c * _e140) * _e152);
                    }
                    float _e154 = all_1;
                    float _e155 = t_5;
                    all_1 = (_e154 + _e155);
                    uint _e157 = k_6;
                    uint _e160 = j_6;
                    if (((_e157 + 1u) == _e160)) {
                        float _e162 = t_5;
                        own_1 = _e162;
                    }
                }
            }
            float _e166 = own_1;
            float _e167 = all_1;
            float _e168 = w_in;
            const float _e169 = gris_weight(_e166, _e167, _e87, _e168);
            float _e170 = w_sum_3;
            w_sum_3 = (_e170 + _e169);
            uint _e172 = hs_1;
            const uint _e173 = pcg_hash(_e172);
            hs_1 = _e173;
            if ((_e169 > 0.0)) {
                float _e178 = w_sum_3;
                uint _e179 = hs_1;
                const float _e180 = xi_from_bits(_e179);
                const bool _e181 = weighted_replace(_e169, _e178, _e180);
                local_58 = _e181;
            } else {
                local_58 = false;
            }
            bool _e183 = local_58;
            if (_e183) {
                ReuseSlot _e184 = s_11;
                out_ = _e184;
                out_target = _e87;
            }
        }
    }
    float _e189 = w_sum_3;
    float _e190 = out_target;
    const float _e191 = gris_contribution_weight(_e189, _e190);
    out_.w = _e191;
    ReuseSlot _e192 = out_;
    const ReuseSlot reuseslot = _e192;
    return reuseslot;
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
    uint slot_cells[8] = (uint[8])0;
    float3 total = (0.0).xxx;
    uint count = 0u;
    uint hc = (uint)0;
    float threshold[8] = (float[8])0;
    uint start = 0u;
    uint j = (uint)0;
    bool local_4 = (bool)0;
    uint q = (uint)0;
    bool local_5 = (bool)0;
    Domain doms[3] = (Domain[3])0;
    bool local_6 = (bool)0;
    uint hs = (uint)0;
    uint2 fresh_keys[8] = (uint2[8])0;
    bool fresh_held[8] = (bool[8])0;
    uint q_1 = 0u;
    bool local_7 = (bool)0;
    bool fresh_visible[8] = (bool[8])0;
    uint q_2 = 0u;
    bool fresh_before[8] = (bool[8])0;
    uint q_3 = 0u;
    bool local_8 = (bool)0;
    bool local_9 = (bool)0;
    ReuseSlot kept[8] = (ReuseSlot[8])0;
    ReuseSlot fin[8] = (ReuseSlot[8])0;
    uint q_4 = 0u;
    bool local_10 = (bool)0;
    bool local_11 = (bool)0;
    uint2 keys[8] = (uint2[8])0;
    bool held[8] = (bool[8])0;
    uint k = 0u;
    bool visible[8] = (bool[8])0;
    uint k_1 = 0u;
    float3 w = (float3)0;
    uint j_1 = (uint)0;
    bool known = (bool)0;
    bool seen = (bool)0;
    uint j_2 = (uint)0;
    bool local_12 = (bool)0;
    bool local_13 = (bool)0;
    Shaded shaded = (Shaded)0;
    bool local_14 = (bool)0;
    uint j_3 = (uint)0;
    uint q_5 = 0u;
    bool local_15 = (bool)0;

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
    float3 x_20 = _e35.xyz;
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
        local_3 = all((abs(x_20) <= (3.4028235e38).xxx));
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
        const Material _e93 = material_of(_e83.xyz, mr.z, mr.y, mr.w, normalize((_e90 - x_20)));
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
    float eps_5 = (_e117 * length((_e120 - x_20)));
    uint _e126 = view.seed;
    uint _e130 = view.width;
    uint _e136 = view.frame;
    const uint _e137 = point_stream(_e126, ((gid.y * _e130) + gid.x), _e136);
    const uint _e138 = pick_stream(_e137);
    h = _e138;
    hc = _e137;
    const TileWalk _e160 = tile_walk_begin(lid, x_20, _e114.w, has_3);
    uint2 loop_bound_16 = uint2(4294967295u, 4294967295u);
    bool loop_init_13 = true;
    while(true) {
        if (all(loop_bound_16 == uint2(0u, 0u))) { break; }
        loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
        if (!loop_init_13) {
            uint _e259 = start;
            start = (_e259 + TILE_LIST);
        }
        loop_init_13 = false;
        uint _e163 = start;
        if ((_e163 < _e160.total)) {
        } else {
            break;
        }
        {
            uint _e166 = start;
            const uint _e167 = tile_walk_fill(lid, _e160, _e166);
            j = 0u;
            uint2 loop_bound_17 = uint2(4294967295u, 4294967295u);
            bool loop_init_14 = true;
            while(true) {
                if (all(loop_bound_17 == uint2(0u, 0u))) { break; }
                loop_bound_17 -= uint2(loop_bound_17.y == 0u, 1u);
                if (!loop_init_14) {
                    uint _e257 = j;
                    j = (_e257 + 1u);
                }
                loop_init_14 = false;
                uint _e170 = j;
                if ((_e170 < _e167)) {
                } else {
                    break;
                }
                {
                    uint _e173 = j;
                    uint b_10 = tile_list[min(uint(_e173), 1023u)];
                    if (!(!(has_3))) {
                        BshNode _e182 = ConstructBshNode(asfloat(bsh_nodes.Load3(b_10*32+0)), asfloat(bsh_nodes.Load(b_10*32+12)), asuint(bsh_nodes.Load(b_10*32+16)), asuint(bsh_nodes.Load(b_10*32+20)), asuint(bsh_nodes.Load(b_10*32+24)), asfloat(bsh_nodes.Load(b_10*32+28)));
                        float3 _e183 = r;
                        const bool _e184 = bsh_reaches(_e182, x_20, _e183, _e114);
                        local_4 = !(_e184);
                    } else {
                        local_4 = true;
                    }
                    bool _e187 = local_4;
                    if (_e187) {
                        continue;
                    }
                    uint li_10 = asuint(bsh_nodes.Load(24+b_10*32));
                    uint _e192 = count;
                    count = (_e192 + 1u);
                    uint _e195 = h;
                    const uint _e196 = pcg_hash(_e195);
                    h = _e196;
                    uint h1_1 = h;
                    uint _e198 = h;
                    const uint _e199 = pcg_hash(_e198);
                    h = _e199;
                    uint _e200 = h;
                    const uint _e201 = grid_cells(h1_1, _e200);
                    const float _e202 = grid_coordinate(h1_1);
                    uint _e203 = h;
                    const float _e204 = grid_coordinate(_e203);
                    float2 u_5 = float2(_e202, _e204);
                    float3 _e206 = n;
                    float3 _e207 = r;
                    Material _e208 = m;
                    const Shaded _e213 = shade_pick_traced(li_10, x_20, _e206, _e207, _e114, _e208, 1.0, u_5.x, u_5.y, eps_5, false);
                    const float3 _e214 = output_of(_e213);
                    const float _e215 = resample_target(_e214);
                    if ((_e215 > 0.0)) {
                        float3 _e218 = total;
                        total = (_e218 + _e214);
                        q = 0u;
                        uint2 loop_bound_18 = uint2(4294967295u, 4294967295u);
                        bool loop_init_15 = true;
                        while(true) {
                            if (all(loop_bound_18 == uint2(0u, 0u))) { break; }
                            loop_bound_18 -= uint2(loop_bound_18.y == 0u, 1u);
                            if (!loop_init_15) {
                                uint _e254 = q;
                                q = (_e254 + 1u);
                            }
                            loop_init_15 = false;
                            uint _e222 = q;
                            if ((_e222 < K)) {
                            } else {
                                break;
                            }
                            {
                                uint _e225 = q;
                                const float _e227 = slot_target(_e214, _e225, K);
                                float3 _e228 = total;
                                uint _e229 = q;
                                const float _e231 = slot_target(_e228, _e229, K);
                                if ((_e227 > 0.0)) {
                                    uint _e236 = q;
                                    float _e238 = threshold[min(uint(_e236), 7u)];
                                    local_5 = (_e231 > _e238);
                                } else {
                                    local_5 = false;
                                }
                                bool _e241 = local_5;
                                if (_e241) {
                                    uint _e242 = q;
                                    slot_light[min(uint(_e242), 7u)] = li_10;
                                    uint _e244 = q;
                                    slot_u[min(uint(_e244), 7u)] = u_5;
                                    uint _e246 = q;
                                    slot_p[min(uint(_e246), 7u)] = _e227;
                                    uint _e248 = q;
                                    slot_cells[min(uint(_e248), 7u)] = _e201;
                                    uint _e250 = q;
                                    const float _e252 = next_threshold(_e231, hc);
                                    threshold[min(uint(_e250), 7u)] = _e252;
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
            uint _e270 = view.width;
            const uint _e274 = next_index(((gid.y * _e270) + gid.x));
            reuse_pixels.Store(12+0+_e274*144, asuint(0.0));
        }
        return;
    }
    uint _e282 = view.width;
    uint pixel_1 = ((gid.y * _e282) + gid.x);
    float3 _e287 = n;
    float3 _e290 = view.eye;
    const uint _e294 = reuse_stream(_e137, 0u);
    const uint _e295 = reuse_domains(x_20, _e287, length((_e290 - x_20)), _e294, doms);
    if ((_e295 > 0u)) {
        bool _e302 = doms[0].temporal;
        local_6 = _e302;
    } else {
        local_6 = false;
    }
    bool own_history = local_6;
    uint first_1 = (own_history ? 1u : 0u);
    float _e310 = doms[0].c;
    float confidence = (1.0 + (own_history ? _e310 : 0.0));
    const uint _e316 = reuse_stream(_e137, 1u);
    hs = _e316;
    uint2 loop_bound_19 = uint2(4294967295u, 4294967295u);
    bool loop_init_16 = true;
    while(true) {
        if (all(loop_bound_19 == uint2(0u, 0u))) { break; }
        loop_bound_19 -= uint2(loop_bound_19.y == 0u, 1u);
        if (!loop_init_16) {
            uint _e351 = q_1;
            q_1 = (_e351 + 1u);
        }
        loop_init_16 = false;
        uint _e322 = q_1;
        if ((_e322 < K)) {
        } else {
            break;
        }
        {
            uint _e325 = q_1;
            uint _e327 = q_1;
            uint _e329 = slot_light[min(uint(_e327), 7u)];
            uint _e330 = q_1;
            uint _e332 = slot_cells[min(uint(_e330), 7u)];
            const uint2 _e333 = sample_key(_e329, _e332);
            fresh_keys[min(uint(_e325), 7u)] = _e333;
            uint _e334 = q_1;
            uint _e338 = reuse.visibility;
            if ((_e338 == 1u)) {
                uint _e343 = q_1;
                float _e345 = slot_p[min(uint(_e343), 7u)];
                local_7 = (_e345 > 0.0);
            } else {
                local_7 = false;
            }
            bool _e349 = local_7;
            fresh_held[min(uint(_e334), 7u)] = _e349;
        }
    }
    uint2 _e353[8] = fresh_keys;
    bool _e354[8] = fresh_held;
    const uint _e355[8] = first_holders(_e353, _e354);
    uint2 loop_bound_20 = uint2(4294967295u, 4294967295u);
    bool loop_init_17 = true;
    while(true) {
        if (all(loop_bound_20 == uint2(0u, 0u))) { break; }
        loop_bound_20 -= uint2(loop_bound_20.y == 0u, 1u);
        if (!loop_init_17) {
            uint _e390 = q_2;
            q_2 = (_e390 + 1u);
        }
        loop_init_17 = false;
        uint _e359 = q_2;
        if ((_e359 < K)) {
        } else {
            break;
        }
        {
            uint _e362 = q_2;
            uint _e364 = q_2;
            if ((_e355[min(uint(_e362), 7u)] == _e364)) {
                uint _e366 = q_2;
                uint _e369 = q_2;
                uint _e371 = slot_light[min(uint(_e369), 7u)];
                GpuLight _e373 = ConstructGpuLight(asfloat(lights.Load3(_e371*64+0)), asuint(lights.Load(_e371*64+12)), asfloat(lights.Load3(_e371*64+16)), asfloat(lights.Load(_e371*64+28)), asfloat(lights.Load3(_e371*64+32)), asfloat(lights.Load(_e371*64+44)), asfloat(lights.Load3(_e371*64+48)), asuint(lights.Load(_e371*64+60)));
                uint _e374 = q_2;
                uint _e376 = slot_cells[min(uint(_e374), 7u)];
                float3 _e377 = n;
                const bool _e378 = sample_reaches(_e373, _e376, x_20, _e377, eps_5);
                fresh_visible[min(uint(_e366), 7u)] = _e378;
            } else {
                uint _e379 = q_2;
                if ((_e355[min(uint(_e379), 7u)] < K)) {
                    uint _e383 = q_2;
                    uint _e385 = q_2;
                    bool _e388 = fresh_visible[min(uint(_e355[min(uint(_e385), 7u)]), 7u)];
                    fresh_visible[min(uint(_e383), 7u)] = _e388;
                }
            }
        }
    }
    uint2 loop_bound_21 = uint2(4294967295u, 4294967295u);
    bool loop_init_18 = true;
    while(true) {
        if (all(loop_bound_21 == uint2(0u, 0u))) { break; }
        loop_bound_21 -= uint2(loop_bound_21.y == 0u, 1u);
        if (!loop_init_18) {
            uint _e439 = q_3;
            q_3 = (_e439 + 1u);
        }
        loop_init_18 = false;
        uint _e395 = q_3;
        if ((_e395 < K)) {
        } else {
            break;
        }
        {
            uint _e398 = q_3;
            fresh_before[min(uint(_e398), 7u)] = true;
            uint _e401 = q_3;
            uint _e403 = q_3;
            if ((_e355[min(uint(_e401), 7u)] == _e403)) {
                uint _e407 = q_3;
                bool _e409 = fresh_visible[min(uint(_e407), 7u)];
                local_8 = _e409;
            } else {
                local_8 = false;
            }
            bool _e411 = local_8;
            if (_e411) {
                local_9 = own_history;
            } else {
                local_9 = false;
            }
            bool _e415 = local_9;
            if (_e415) {
                uint _e416 = q_3;
                uint _e418 = q_3;
                uint _e420 = slot_light[min(uint(_e418), 7u)];
                uint _e421 = q_3;
                uint _e423 = slot_cells[min(uint(_e421), 7u)];
                Domain _e425 = doms[0];
                float3 _e426 = n;
                const bool _e427 = reached_before(_e420, _e423, _e425, x_20, _e426);
                fresh_before[min(uint(_e416), 7u)] = _e427;
            } else {
                uint _e428 = q_3;
                if ((_e355[min(uint(_e428), 7u)] < K)) {
                    uint _e432 = q_3;
                    uint _e434 = q_3;
                    bool _e437 = fresh_before[min(uint(_e355[min(uint(_e434), 7u)]), 7u)];
                    fresh_before[min(uint(_e432), 7u)] = _e437;
                }
            }
        }
    }
    uint2 loop_bound_22 = uint2(4294967295u, 4294967295u);
    bool loop_init_19 = true;
    while(true) {
        if (all(loop_bound_22 == uint2(0u, 0u))) { break; }
        loop_bound_22 -= uint2(loop_bound_22.y == 0u, 1u);
        if (!loop_init_19) {
            uint _e513 = q_4;
            q_4 = (_e513 + 1u);
        }
        loop_init_19 = false;
        uint _e445 = q_4;
        if ((_e445 < K)) {
        } else {
            break;
        }
        {
            uint _e448 = q_4;
            float _e450 = slot_p[min(uint(_e448), 7u)];
            if ((_e450 > 0.0)) {
                uint _e457 = reuse.visibility;
                if (!((_e457 == 0u))) {
                    uint _e463 = q_4;
                    bool _e465 = fresh_visible[min(uint(_e463), 7u)];
                    local_11 = _e465;
                } else {
                    local_11 = true;
                }
                bool _e467 = local_11;
                local_10 = _e467;
            } else {
                local_10 = false;
            }
            bool fresh = local_10;
            uint _e470 = q_4;
            uint _e472 = q_4;
            uint _e473 = q_4;
            uint _e475 = slot_light[min(uint(_e473), 7u)];
            uint _e476 = q_4;
            uint _e478 = slot_cells[min(uint(_e476), 7u)];
            float3 _e479 = total;
            uint _e480 = q_4;
            const float _e482 = slot_target(_e479, _e480, K);
            uint _e488 = q_4;
            bool _e490 = fresh_before[min(uint(_e488), 7u)];
            float3 _e492 = n;
            Material _e493 = m;
            const ReuseSlot _e494 = gris_combine(_e472, ConstructReuseSlot(_e475, _e478, (fresh ? _e482 : 0.0)), true, 1.0, _e490, 0u, first_1, x_20, _e492, _e493, doms, hs);
            kept[min(uint(_e470), 7u)] = _e494;
            uint _e495 = q_4;
            uint _e497 = q_4;
            ReuseSlot _e499 = kept[min(uint(_e497), 7u)];
            fin[min(uint(_e495), 7u)] = _e499;
            if ((_e295 > first_1)) {
                uint _e501 = q_4;
                uint _e503 = q_4;
                uint _e504 = q_4;
                ReuseSlot _e506 = kept[min(uint(_e504), 7u)];
                float3 _e509 = n;
                Material _e510 = m;
                const ReuseSlot _e511 = gris_combine(_e503, _e506, false, confidence, true, first_1, _e295, x_20, _e509, _e510, doms, hs);
                fin[min(uint(_e501), 7u)] = _e511;
            }
        }
    }
    uint2 loop_bound_23 = uint2(4294967295u, 4294967295u);
    bool loop_init_20 = true;
    while(true) {
        if (all(loop_bound_23 == uint2(0u, 0u))) { break; }
        loop_bound_23 -= uint2(loop_bound_23.y == 0u, 1u);
        if (!loop_init_20) {
            uint _e542 = k;
            k = (_e542 + 1u);
        }
        loop_init_20 = false;
        uint _e519 = k;
        if ((_e519 < K)) {
        } else {
            break;
        }
        {
            uint _e522 = k;
            uint _e524 = k;
            uint _e527 = fin[min(uint(_e524), 7u)].light;
            uint _e528 = k;
            uint _e531 = fin[min(uint(_e528), 7u)].u;
            const uint2 _e532 = sample_key(_e527, _e531);
            keys[min(uint(_e522), 7u)] = _e532;
            uint _e533 = k;
            uint _e535 = k;
            float _e538 = fin[min(uint(_e535), 7u)].w;
            held[min(uint(_e533), 7u)] = (_e538 > 0.0);
        }
    }
    uint2 _e544[8] = keys;
    bool _e545[8] = held;
    const uint _e546[8] = first_holders(_e544, _e545);
    uint2 loop_bound_24 = uint2(4294967295u, 4294967295u);
    bool loop_init_21 = true;
    while(true) {
        if (all(loop_bound_24 == uint2(0u, 0u))) { break; }
        loop_bound_24 -= uint2(loop_bound_24.y == 0u, 1u);
        if (!loop_init_21) {
            uint _e678 = k_1;
            k_1 = (_e678 + 1u);
        }
        loop_init_21 = false;
        uint _e550 = k_1;
        if ((_e550 < K)) {
        } else {
            break;
        }
        {
            uint _e553 = k_1;
            uint _e555 = k_1;
            if ((_e546[min(uint(_e553), 7u)] != _e555)) {
                continue;
            }
            w = (0.0).xxx;
            uint _e560 = k_1;
            j_1 = _e560;
            uint2 loop_bound_25 = uint2(4294967295u, 4294967295u);
            bool loop_init_22 = true;
            while(true) {
                if (all(loop_bound_25 == uint2(0u, 0u))) { break; }
                loop_bound_25 -= uint2(loop_bound_25.y == 0u, 1u);
                if (!loop_init_22) {
                    uint _e580 = j_1;
                    j_1 = (_e580 + 1u);
                }
                loop_init_22 = false;
                uint _e562 = j_1;
                if ((_e562 < K)) {
                } else {
                    break;
                }
                {
                    uint _e565 = j_1;
                    uint _e567 = k_1;
                    if ((_e546[min(uint(_e565), 7u)] == _e567)) {
                        float3 _e569 = w;
                        uint _e570 = j_1;
                        float _e573 = fin[min(uint(_e570), 7u)].w;
                        uint _e574 = j_1;
                        const float3 _e576 = slot_share(_e574, K);
                        w = (_e569 + (_e573 * _e576));
                    }
                }
            }
            known = false;
            seen = false;
            j_2 = 0u;
            uint2 loop_bound_26 = uint2(4294967295u, 4294967295u);
            bool loop_init_23 = true;
            while(true) {
                if (all(loop_bound_26 == uint2(0u, 0u))) { break; }
                loop_bound_26 -= uint2(loop_bound_26.y == 0u, 1u);
                if (!loop_init_23) {
                    uint _e617 = j_2;
                    j_2 = (_e617 + 1u);
                }
                loop_init_23 = false;
                uint _e588 = j_2;
                if ((_e588 < K)) {
                    bool _e593 = known;
                    local_12 = !(_e593);
                } else {
                    local_12 = false;
                }
                bool _e596 = local_12;
                if (_e596) {
                } else {
                    break;
                }
                {
                    uint _e597 = j_2;
                    bool _e599 = fresh_held[min(uint(_e597), 7u)];
                    if (_e599) {
                        uint _e602 = j_2;
                        uint2 _e604 = fresh_keys[min(uint(_e602), 7u)];
                        uint _e605 = k_1;
                        uint2 _e607 = keys[min(uint(_e605), 7u)];
                        local_13 = all((_e604 == _e607));
                    } else {
                        local_13 = false;
                    }
                    bool _e611 = local_13;
                    if (_e611) {
                        known = true;
                        uint _e613 = j_2;
                        bool _e615 = fresh_visible[min(uint(_e613), 7u)];
                        seen = _e615;
                    }
                }
            }
            shaded = ConstructShaded((0.0).xxx, (0.0).xxx, (0.0).xxx);
            bool _e627 = known;
            if (!(!(_e627))) {
                bool _e632 = seen;
                local_14 = _e632;
            } else {
                local_14 = true;
            }
            bool _e634 = local_14;
            if (_e634) {
                uint _e636 = k_1;
                uint _e639 = fin[min(uint(_e636), 7u)].light;
                GpuLight _e641 = ConstructGpuLight(asfloat(lights.Load3(_e639*64+0)), asuint(lights.Load(_e639*64+12)), asfloat(lights.Load3(_e639*64+16)), asfloat(lights.Load(_e639*64+28)), asfloat(lights.Load3(_e639*64+32)), asfloat(lights.Load(_e639*64+44)), asfloat(lights.Load3(_e639*64+48)), asuint(lights.Load(_e639*64+60)));
                uint _e642 = k_1;
                uint _e645 = fin[min(uint(_e642), 7u)].u;
                float3 _e646 = n;
                bool _e647 = known;
                const Connection _e649 = sample_connection(_e641, _e645, x_20, _e646, eps_5, !(_e647));
                float3 _e650 = n;
                Material _e651 = m;
                const Shaded _e652 = shade_connection(_e649, x_20, _e650, _e651);
                shaded = _e652;
            }
            Shaded _e653 = t;
            Shaded _e654 = shaded;
            float3 _e655 = w;
            const Shaded _e656 = scaled(_e654, _e655);
            const Shaded _e657 = add(_e653, _e656);
            t = _e657;
            uint _e658 = k_1;
            j_3 = _e658;
            uint2 loop_bound_27 = uint2(4294967295u, 4294967295u);
            bool loop_init_24 = true;
            while(true) {
                if (all(loop_bound_27 == uint2(0u, 0u))) { break; }
                loop_bound_27 -= uint2(loop_bound_27.y == 0u, 1u);
                if (!loop_init_24) {
                    uint _e675 = j_3;
                    j_3 = (_e675 + 1u);
                }
                loop_init_24 = false;
                uint _e660 = j_3;
                if ((_e660 < K)) {
                } else {
                    break;
                }
                {
                    uint _e663 = j_3;
                    uint _e665 = k_1;
                    if ((_e546[min(uint(_e663), 7u)] == _e665)) {
                        uint _e667 = j_3;
                        Shaded _e669 = shaded;
                        const float3 _e670 = output_of(_e669);
                        const float _e671 = resample_target(_e670);
                        visible[min(uint(_e667), 7u)] = (_e671 > 0.0);
                    }
                }
            }
        }
    }
    uint2 loop_bound_28 = uint2(4294967295u, 4294967295u);
    bool loop_init_25 = true;
    while(true) {
        if (all(loop_bound_28 == uint2(0u, 0u))) { break; }
        loop_bound_28 -= uint2(loop_bound_28.y == 0u, 1u);
        if (!loop_init_25) {
            uint _e720 = q_5;
            q_5 = (_e720 + 1u);
        }
        loop_init_25 = false;
        uint _e682 = q_5;
        if ((_e682 < K)) {
        } else {
            break;
        }
        {
            uint _e687 = reuse.visibility;
            if (!((_e687 == 0u))) {
                uint _e693 = q_5;
                bool _e695 = visible[min(uint(_e693), 7u)];
                local_15 = _e695;
            } else {
                local_15 = true;
            }
            bool keep = local_15;
            const uint _e699 = next_index(pixel_1);
            uint _e702 = q_5;
            uint _e704 = q_5;
            uint _e707 = kept[min(uint(_e704), 7u)].light;
            uint _e708 = q_5;
            uint _e711 = kept[min(uint(_e708), 7u)].u;
            uint _e712 = q_5;
            float _e715 = kept[min(uint(_e712), 7u)].w;
            {
                ReuseSlot _value4 = ConstructReuseSlot(_e707, _e711, (keep ? _e715 : 0.0));
                reuse_pixels.Store(_e702*12+48+_e699*144+0, asuint(_value4.light));
                reuse_pixels.Store(_e702*12+48+_e699*144+4, asuint(_value4.u));
                reuse_pixels.Store(_e702*12+48+_e699*144+8, asuint(_value4.w));
            }
        }
    }
    const uint _e723 = next_index(pixel_1);
    float3 _e726 = n;
    Material _e727 = m;
    float _e730 = reuse.max_confidence;
    const ReuseSurface _e732 = reuse_surface(x_20, _e726, _e727, min(confidence, _e730));
    {
        ReuseSurface _value2 = _e732;
        reuse_pixels.Store3(0+_e723*144+0, asuint(_value2.x));
        reuse_pixels.Store(0+_e723*144+12, asuint(_value2.m));
        reuse_pixels.Store3(0+_e723*144+16, asuint(_value2.n));
        reuse_pixels.Store(0+_e723*144+28, asuint(_value2.base));
        reuse_pixels.Store(0+_e723*144+32, asuint(_value2.rough));
        reuse_pixels.Store(0+_e723*144+36, asuint(_value2.pad0_));
        reuse_pixels.Store(0+_e723*144+40, asuint(_value2.pad1_));
        reuse_pixels.Store(0+_e723*144+44, asuint(_value2.pad2_));
    }
    float3 _e735 = t.diffuse;
    float3 _e737 = t.specular;
    uint _e739 = count;
    out_tex[texel_1] = float4((_e735 + _e737), float(_e739));
    return;
}
