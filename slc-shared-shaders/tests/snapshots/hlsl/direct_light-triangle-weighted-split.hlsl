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

struct WeightedPicks {
    uint light[8];
    float w[8];
    float threshold[8];
    float w_sum;
    uint n;
    uint h;
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
RWTexture2D<float4> specular_tex : register(u6);
ByteAddressBuffer lights : register(t1, space1);
ByteAddressBuffer rt2_5 : register(t2, space1);
ByteAddressBuffer r2_4 : register(t3, space1);
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
    float3 v_6 = (x_1 - c);
    return (dot(v_6, v_6) <= (r_1 * r_1));
}

bool sphere_overlaps_aabb(float3 c_1, float r_2, float3 bmin, float3 bmax)
{
    float3 q = clamp(c_1, bmin, bmax);
    float3 v_7 = (q - c_1);
    return (dot(v_7, v_7) <= (r_2 * r_2));
}

float inverse_square(float d2_2)
{
    return (1.0 / max(d2_2, MIN_D2_));
}

float connection_factor(float cos_x, float d2_3, float rt2_1, float w)
{
    const float _e4 = inverse_square(d2_3);
    const float _e6 = slc_weight(rt2_1, d2_3);
    return (((cos_x * _e4) * _e6) * w);
}

float connection_cosine(float3 x_2, float3 y, float3 n_1, float3 ng, float r2_1)
{
    bool local_5 = (bool)0;
    bool local_6 = (bool)0;

    float3 v_8 = (x_2 - y);
    float d2_7 = dot(v_8, v_8);
    const bool _e7 = slc_keep(r2_1, d2_7);
    if (!(!(_e7))) {
        local_5 = !((d2_7 > 0.0));
    } else {
        local_5 = true;
    }
    bool _e16 = local_5;
    if (_e16) {
        return 0.0;
    }
    float3 w_11 = (v_8 / (sqrt(d2_7)).xxx);
    float cos_x_1 = -(dot(n_1, w_11));
    if (!(!((cos_x_1 > 0.0)))) {
        local_6 = !((dot(ng, w_11) < 0.0));
    } else {
        local_6 = true;
    }
    bool _e34 = local_6;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float triangle_lobe(float3 n_2, float area, float3 w_1)
{
    return (area * max(dot(n_2, w_1), 0.0));
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

float bsh_reach_bound(BshNode node_2, float w_2)
{
    const float _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_2 * 1.001) * _e5));
}

float weighted_threshold(float w_sum, float u_2)
{
    return (w_sum / (1.0 - u_2));
}

float weighted_pick_weight(float w_sum_1, float w_3, uint k_2)
{
    const float _e3 = to_f32_(k_2);
    return (w_sum_1 / (_e3 * w_3));
}

float ggx_alpha(float roughness)
{
    return max((roughness * roughness), GGX_ALPHA_MIN);
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
    bool local_7 = (bool)0;

    if (!((n_l <= 0.0))) {
        local_7 = (n_v <= 0.0);
    } else {
        local_7 = true;
    }
    bool _e11 = local_7;
    if (_e11) {
        return 0.0;
    }
    const float _e13 = smith_root(n_v, alpha_2);
    const float _e15 = smith_root(n_l, alpha_2);
    return (0.5 / ((n_l * _e13) + (n_v * _e15)));
}

float3 fresnel_schlick(float3 f0_, float f90_, float v_h)
{
    float c_8 = saturate((1.0 - v_h));
    float c2_ = (c_8 * c_8);
    return (f0_ + ((float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_8)));
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
    float3 h_4 = (v + l);
    float len2_ = dot(h_4, h_4);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return saturate((dot(v, h_4) / sqrt(len2_)));
}

float3 specular_brdf(float3 base_2, float metallic_2, float3 f0_d_2, float f90_d_2, float alpha_3, float3 n_3, float3 v_1, float3 l_1)
{
    bool local_8 = (bool)0;

    float n_l_1 = dot(n_3, l_1);
    float n_v_2 = dot(n_3, v_1);
    if (!((n_l_1 <= 0.0))) {
        local_8 = (n_v_2 <= 0.0);
    } else {
        local_8 = true;
    }
    bool _e18 = local_8;
    if (_e18) {
        return float3(0.0, 0.0, 0.0);
    }
    float3 hs = (v_1 + l_1);
    float inv = (1.0 / sqrt(dot(hs, hs)));
    float3 h_5 = (hs * inv);
    float3 c_9 = cross(n_3, h_5);
    const float _e32 = ggx_d(dot(n_3, h_5), dot(c_9, c_9), alpha_3);
    const float3 _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_1, h_5));
    const float _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return (_e34 * (_e32 * _e35));
}

bool has_specular(float metallic_3, float3 f0_d_3, float f90_d_3)
{
    bool local_9 = (bool)0;
    bool local_10 = (bool)0;

    if (!((metallic_3 > 0.0))) {
        local_9 = (f90_d_3 > 0.0);
    } else {
        local_9 = true;
    }
    bool _e11 = local_9;
    if (!(_e11)) {
        local_10 = (max(max(f0_d_3.x, f0_d_3.y), f0_d_3.z) > 0.0);
    } else {
        local_10 = true;
    }
    bool _e23 = local_10;
    return _e23;
}

float channel_mean(float3 c_3)
{
    return (((c_3.x + c_3.y) + c_3.z) * 0.33333334);
}

float4 receiver_lobe(float3 base_3, float metallic_4, float3 f0_d_4, float f90_d_4, float alpha_4, float n_v_1)
{
    bool local_11 = (bool)0;

    const float3 _e10 = fresnel_schlick(f0_d_4, f90_d_4, n_v_1);
    const float _e16 = channel_mean((((float3(1.0, 1.0, 1.0) - _e10) * base_3) * (1.0 - metallic_4)));
    if (!((n_v_1 <= 0.0))) {
        const bool _e22 = has_specular(metallic_4, f0_d_4, f90_d_4);
        local_11 = !(_e22);
    } else {
        local_11 = true;
    }
    bool _e25 = local_11;
    if (_e25) {
        return float4(_e16, 0.0, alpha_4, n_v_1);
    }
    const float3 _e28 = specular_fresnel(base_3, metallic_4, f0_d_4, f90_d_4, n_v_1);
    const float _e29 = channel_mean(_e28);
    return float4(_e16, _e29, alpha_4, n_v_1);
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

float3 mirror_dir(float3 n_4, float3 v_2)
{
    return ((n_4 * (2.0 * dot(n_4, v_2))) - v_2);
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

float safe_sqrt(float x_3)
{
    return sqrt(max(x_3, 0.0));
}

float subtended_cos(float dist2_, float r2_2)
{
    const float _e5 = safe_sqrt((1.0 - (r2_2 / dist2_)));
    return ((dist2_ <= r2_2) ? -1.0 : _e5);
}

float4 emitter_cone(float3 center_, float radius, float3 axis, float cos_o, float3 p)
{
    bool local_12 = (bool)0;

    float3 v_9 = (p - center_);
    float dist2_1 = dot(v_9, v_9);
    float r2_5 = (radius * radius);
    if ((dist2_1 <= 0.0)) {
        local_12 = (r2_5 <= 0.0);
    } else {
        local_12 = false;
    }
    bool _e15 = local_12;
    if (_e15) {
        return float4(-2.0, 1e-12, -1.0, 0.0);
    }
    float d2_8 = max(max(dist2_1, r2_5), MIN_D2_);
    float3 wi = ((dist2_1 > 0.0) ? (v_9 / (sqrt(dist2_1)).xxx) : float3(0.0, 0.0, 0.0));
    float cos_w = dot(axis, wi);
    const float _e38 = safe_sqrt((1.0 - (cos_w * cos_w)));
    const float _e39 = subtended_cos(dist2_1, r2_5);
    const float _e43 = safe_sqrt((1.0 - (_e39 * _e39)));
    const float _e47 = safe_sqrt((1.0 - (cos_o * cos_o)));
    const float _e48 = cos_sub_clamped(_e38, cos_w, _e47, cos_o);
    const float _e49 = sin_sub_clamped(_e38, cos_w, _e47, cos_o);
    const float _e50 = cos_sub_clamped(_e49, _e48, _e43, _e39);
    return float4(_e50, d2_8, _e39, _e43);
}

float emitter_importance(float3 center_1, float radius_1, float phi, float3 axis_1, float cos_o_1, float cos_e, float3 p_1)
{
    const float4 _e7 = emitter_cone(center_1, radius_1, axis_1, cos_o_1, p_1);
    if ((_e7.x <= cos_e)) {
        return 0.0;
    }
    return ((phi * _e7.x) / _e7.y);
}

float cone_cos_of(float3 v_3, float d2_4, float a_3, float3 d)
{
    bool local_13 = (bool)0;
    bool local_14 = (bool)0;

    float vd = dot(v_3, d);
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
    float3 c_10 = cross(v_3, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_10, c_10)) * a_3)) / d2_4), 1.0);
}

float cone_cos_toward(float3 center_2, float radius_2, float3 p_2, float3 d_1)
{
    float3 v_10 = (center_2 - p_2);
    const float _e6 = cone_cos_of(v_10, dot(v_10, v_10), radius_2, d_1);
    return _e6;
}

float range_scale_at(float4 rl, float cos_t)
{
    float t_5 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_5 * t_5))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(float4 rl_1, float3 center_3, float radius_3, float3 p_3, float3 r_3)
{
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    const float _e9 = cone_cos_toward(center_3, radius_3, p_3, r_3);
    const float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

float light_importance(float3 center_4, float radius_4, float phi_1, float3 axis_2, float cos_o_2, float cos_e_1, float3 p_4, float3 n_5)
{
    float imp = (float)0;

    const float4 _e8 = emitter_cone(center_4, radius_4, axis_2, cos_o_2, p_4);
    if ((_e8.x <= cos_e_1)) {
        return 0.0;
    }
    imp = ((phi_1 * _e8.x) / _e8.y);
    if ((dot(n_5, n_5) > 0.0)) {
        float3 v_11 = (center_4 - p_4);
        float dist2_2 = dot(v_11, v_11);
        float cos_i = dot(((dist2_2 > 0.0) ? (v_11 / (sqrt(dist2_2)).xxx) : float3(0.0, 0.0, 0.0)), n_5);
        float _e33 = imp;
        const float _e37 = safe_sqrt((1.0 - (cos_i * cos_i)));
        const float _e40 = cos_sub_clamped(_e37, cos_i, _e8.w, _e8.z);
        imp = (_e33 * max(_e40, 0.0));
    }
    float _e44 = imp;
    return max(_e44, 0.0);
}

float glossy_importance(float3 center_5, float radius_5, float phi_2, float3 axis_3, float cos_o_3, float cos_e_2, float3 p_5, float3 n_6, float3 r_4, float4 lobe_5)
{
    bool local_15 = (bool)0;

    const float _e10 = emitter_importance(center_5, radius_5, phi_2, axis_3, cos_o_3, cos_e_2, p_5);
    const float _e11 = cone_cos_toward(center_5, radius_5, p_5, n_6);
    if (!((_e10 <= 0.0))) {
        local_15 = (_e11 <= 0.0);
    } else {
        local_15 = true;
    }
    bool _e20 = local_15;
    if (_e20) {
        return 0.0;
    }
    const float _e22 = cone_cos_toward(center_5, radius_5, p_5, r_4);
    const float _e27 = safe_sqrt((0.5 + (0.5 * _e22)));
    const float _e33 = ggx_d(_e27, (1.0 - (_e27 * _e27)), lobe_5.z);
    const float _e39 = smith_root(lobe_5.w, lobe_5.z);
    float spec = (((lobe_5.y * _e33) * 0.25) / _e39);
    return (_e10 * (((lobe_5.x * INV_PI) * _e11) + spec));
}

float candidate_weight(float importance, float rt2_2, float d2_5)
{
    const float _e3 = slc_weight(rt2_2, d2_5);
    return (importance * _e3);
}

float cone_weight(float3 center_6, float radius_6, float phi_3, float3 axis_4, float cos_o_4, float cos_e_3, float rt2_3, float3 p_6, float3 n_7, float3 r_5, float4 lobe_6)
{
    float3 v_12 = (p_6 - center_6);
    if ((lobe_6.y <= 0.0)) {
        const float _e15 = light_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_7);
        const float _e19 = candidate_weight((_e15 * INV_PI), rt2_3, dot(v_12, v_12));
        return _e19;
    }
    const float _e20 = glossy_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_7, r_5, lobe_6);
    const float _e22 = candidate_weight(_e20, rt2_3, dot(v_12, v_12));
    return _e22;
}

float shadow_margin(float len)
{
    return (0.0001 * len);
}

float ray_inverse(float x_4)
{
    return (1.0 / ((abs(x_4) < 1e-30) ? 1e-30 : x_4));
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

float3 triangle_normal(float3 a_4, float3 b_3, float3 c_4)
{
    bool local_16 = (bool)0;

    float3 n_14 = cross((b_3 - a_4), (c_4 - a_4));
    float l2_ = dot(n_14, n_14);
    if (!(!((l2_ > 0.0)))) {
        local_16 = !((l2_ < 3e38));
    } else {
        local_16 = true;
    }
    bool _e17 = local_16;
    if (_e17) {
        return float3(0.0, 0.0, 0.0);
    }
    return (n_14 / (sqrt(l2_)).xxx);
}

float ray_triangle(float3 o_1, float3 d_3, float3 a_5, float3 b_4, float3 c_5, float t_min, float t_max_1)
{
    bool local_17 = (bool)0;
    bool local_18 = (bool)0;
    bool local_19 = (bool)0;

    float3 e1_ = (b_4 - a_5);
    float3 e2_ = (c_5 - a_5);
    float3 p_10 = cross(d_3, e2_);
    float det = dot(e1_, p_10);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv_1 = (1.0 / det);
    float3 s_9 = (o_1 - a_5);
    float u_3 = (dot(s_9, p_10) * inv_1);
    if (!((u_3 < 0.0))) {
        local_17 = (u_3 > 1.0);
    } else {
        local_17 = true;
    }
    bool _e28 = local_17;
    if (_e28) {
        return -1.0;
    }
    float3 q_1 = cross(s_9, e1_);
    float v_13 = (dot(d_3, q_1) * inv_1);
    if (!((v_13 < 0.0))) {
        local_18 = ((u_3 + v_13) > 1.0);
    } else {
        local_18 = true;
    }
    bool _e42 = local_18;
    if (_e42) {
        return -1.0;
    }
    float t_6 = (dot(e2_, q_1) * inv_1);
    if ((t_6 > t_min)) {
        local_19 = (t_6 < t_max_1);
    } else {
        local_19 = false;
    }
    bool _e51 = local_19;
    if (_e51) {
        return t_6;
    }
    return -1.0;
}

float3 light_intensity(GpuLight l_2, float3 w_4)
{
    switch(l_2.kind) {
        case 3u: {
            const float3 _e7 = triangle_normal(l_2.p0_, l_2.p1_, l_2.p2_);
            const float _e9 = triangle_lobe(_e7, l_2.a, w_4);
            return (l_2.intensity * _e9);
        }
        default: {
            return (0.0).xxx;
        }
    }
}

float3 light_point(GpuLight l_3, float u1_1, float u2_1)
{
    if ((l_3.kind == LIGHT_TRIANGLE)) {
        const float3 _e9 = triangle_sample(l_3.p0_, l_3.p1_, l_3.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_3.p0_;
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
        GpuGeoNode n_15 = ConstructGpuGeoNode(asfloat(geo_nodes.Load3(_e21*32+0)), asuint(geo_nodes.Load(_e21*32+12)), asfloat(geo_nodes.Load3(_e21*32+16)), asuint(geo_nodes.Load(_e21*32+28)));
        float _e27 = hit.t;
        const float _e28 = ray_aabb(o_2, _e14, n_15.bmin, n_15.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_15.count > 0u)) {
                i = n_15.first;
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
                    if ((_e36 < (n_15.first + n_15.count))) {
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
                    stack[min(uint(_e63), 63u)] = (n_15.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_15.first;
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

float bsh_inner_scale(float a_7, float3 v_4, float d2_6, float3 r_6, float4 rl_2)
{
    const float _e5 = cone_cos_of(v_4, d2_6, a_7, r_6);
    const float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_4, float3 x_5, float3 r_7, float4 rl_3)
{
    bool local_20 = (bool)0;
    bool local_21 = (bool)0;

    const bool _e6 = sphere_contains_point(node_4.center_, node_4.radius, x_5);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        const bool _e20 = sphere_contains_point(node_4.center_, (node_4.radius * (rl_3.w * 1.0001)), x_5);
        local_20 = !(_e20);
    } else {
        local_20 = true;
    }
    bool _e23 = local_20;
    if (_e23) {
        return false;
    }
    float3 v_14 = (x_5 - node_4.center_);
    float d2_9 = dot(v_14, v_14);
    const float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if ((d2_9 > (_e29 * _e29))) {
        return false;
    }
    if ((node_4.child == BSH_NONE)) {
        const float _e38 = range_scale_toward(rl_3, node_4.center_, node_4.extent, x_5, r_7);
        const float _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        const bool _e42 = sphere_contains_point(node_4.center_, _e41, x_5);
        return _e42;
    }
    const float _e45 = bsh_inner_scale(node_4.extent, -(v_14), d2_9, r_7, rl_3);
    float s_c = (_e45 * 1.001);
    const float _e50 = bsh_range_bound(node_4);
    float reach = (node_4.extent + (sqrt(s_c) * _e50));
    if ((d2_9 <= ((node_4.radius * node_4.radius) * s_c))) {
        local_21 = (d2_9 <= (reach * reach));
    } else {
        local_21 = false;
    }
    bool _e63 = local_21;
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
    bool local_22 = (bool)0;

    const uint _e3 = bsh_first(nodes_3);
    i_2 = _e3;
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e7 = level;
        if ((_e7 < depth)) {
            uint _e11 = i_2;
            local_22 = (_e11 != BSH_NONE);
        } else {
            local_22 = false;
        }
        bool _e15 = local_22;
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

Connection connect_record(GpuLight l_4, float3 x_6, float3 n_8, float3 ng_1, float r2_3, float rt2_4, float w_res, float u1_2, float u2_2, float eps, bool trace_1)
{
    Connection c_6 = (Connection)0;
    bool local_23 = (bool)0;
    bool local_24 = (bool)0;

    c_6.e = (0.0).xxx;
    const float3 _e16 = light_point(l_4, u1_2, u2_2);
    c_6.y = _e16;
    float3 _e19 = c_6.y;
    const float _e20 = connection_cosine(x_6, _e19, n_8, ng_1, r2_3);
    c_6.cos_x = _e20;
    float _e22 = c_6.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            float3 _e33 = c_6.y;
            const bool _e34 = occluded((x_6 + (ng_1 * eps)), _e33);
            local_24 = _e34;
        } else {
            local_24 = false;
        }
        bool _e36 = local_24;
        local_23 = _e36;
    } else {
        local_23 = true;
    }
    bool _e38 = local_23;
    if (_e38) {
        Connection _e39 = c_6;
        const Connection connection = _e39;
        return connection;
    }
    float3 _e41 = c_6.y;
    float3 v_15 = (x_6 - _e41);
    float d2_10 = dot(v_15, v_15);
    const float3 _e48 = light_intensity(l_4, (v_15 / (sqrt(d2_10)).xxx));
    float _e50 = c_6.cos_x;
    const float _e51 = connection_factor(_e50, d2_10, rt2_4, w_res);
    c_6.e = (_e48 * _e51);
    Connection _e53 = c_6;
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

Connection connect_traced(uint li, float3 x_7, float3 n_9, float3 ng_2, float s_2, float w_res_1, float u1_3, float u2_3, float eps_1, bool trace_2)
{
    GpuLight _e12 = ConstructGpuLight(asfloat(lights.Load3(li*64+0)), asuint(lights.Load(li*64+12)), asfloat(lights.Load3(li*64+16)), asfloat(lights.Load(li*64+28)), asfloat(lights.Load3(li*64+32)), asfloat(lights.Load(li*64+44)), asfloat(lights.Load3(li*64+48)), asuint(lights.Load(li*64+60)));
    float _e15 = asfloat(r2_4.Load(li*4));
    float _e19 = asfloat(rt2_5.Load(li*4));
    const Connection _e21 = connect_record(_e12, x_7, n_9, ng_2, (s_2 * _e15), (s_2 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_2);
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

float light_range_scale(uint li_1, float3 x_8, float3 r_8, float4 rl_4)
{
    GpuLightCone c_11 = ConstructGpuLightCone(asfloat(light_cones.Load3(li_1*48+0)), asfloat(light_cones.Load(li_1*48+12)), asfloat(light_cones.Load3(li_1*48+16)), asfloat(light_cones.Load(li_1*48+28)), asfloat(light_cones.Load(li_1*48+32)), asfloat(light_cones.Load(li_1*48+36)), asuint(light_cones.Load(li_1*48+40)), asuint(light_cones.Load(li_1*48+44)));
    const float _e9 = range_scale_toward(rl_4, c_11.center_, c_11.radius, x_8, r_8);
    return _e9;
}

float light_weight(uint li_2, float3 x_9, float3 n_10, float3 r_9, float4 lobe_7, float4 rl_5)
{
    GpuLightCone c_12 = ConstructGpuLightCone(asfloat(light_cones.Load3(li_2*48+0)), asfloat(light_cones.Load(li_2*48+12)), asfloat(light_cones.Load3(li_2*48+16)), asfloat(light_cones.Load(li_2*48+28)), asfloat(light_cones.Load(li_2*48+32)), asfloat(light_cones.Load(li_2*48+36)), asuint(light_cones.Load(li_2*48+40)), asuint(light_cones.Load(li_2*48+44)));
    const float _e15 = light_range_scale(li_2, x_9, r_9, rl_5);
    float _e18 = asfloat(rt2_5.Load(li_2*4));
    const float _e20 = cone_weight(c_12.center_, c_12.radius, c_12.phi, c_12.axis, c_12.cos_o, c_12.cos_e, (_e15 * _e18), x_9, n_10, r_9, lobe_7);
    return _e20;
}

WeightedPicks weighted_picks(uint h_2)
{
    WeightedPicks picks_1 = (WeightedPicks)0;

    picks_1.w_sum = 0.0;
    picks_1.n = 0u;
    picks_1.h = h_2;
    WeightedPicks _e7 = picks_1;
    const WeightedPicks weightedpicks = _e7;
    return weightedpicks;
}

void weighted_offer(inout WeightedPicks picks_2, uint li_3, float w_7)
{
    uint h_3 = (uint)0;
    uint s_3 = 0u;

    uint _e4 = picks_2.n;
    picks_2.n = (_e4 + 1u);
    if ((w_7 > 0.0)) {
        float _e10 = picks_2.w_sum;
        picks_2.w_sum = (_e10 + w_7);
        uint _e13 = picks_2.h;
        h_3 = _e13;
        uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
            loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e40 = s_3;
                s_3 = (_e40 + 1u);
            }
            loop_init_1 = false;
            uint _e17 = s_3;
            if ((_e17 < K)) {
            } else {
                break;
            }
            {
                float _e21 = picks_2.w_sum;
                uint _e23 = s_3;
                float _e25 = picks_2.threshold[min(uint(_e23), 7u)];
                if ((_e21 > _e25)) {
                    uint _e28 = s_3;
                    picks_2.light[min(uint(_e28), 7u)] = li_3;
                    uint _e31 = s_3;
                    picks_2.w[min(uint(_e31), 7u)] = w_7;
                    uint _e34 = s_3;
                    float _e37 = picks_2.w_sum;
                    const float _e38 = next_threshold(_e37, h_3);
                    picks_2.threshold[min(uint(_e34), 7u)] = _e38;
                }
            }
        }
        uint _e43 = h_3;
        picks_2.h = _e43;
        return;
    } else {
        return;
    }
}

float4 surface_at(int2 texel)
{
    float4 p_11 = position_tex.Load(int3(texel, int(0)));
    return ((p_11.w > 0.0) ? float4(p_11.xyz, 1.0) : (0.0).xxxx);
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

WorkgroupBox workgroup_bounds(uint li_4, float3 lo_2, float3 hi_2)
{
    uint stride = 32u;

    wg_lo[min(uint(li_4), 63u)] = lo_2;
    wg_hi[min(uint(li_4), 63u)] = hi_2;
    GroupMemoryBarrierWithGroupSync();
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e36 = stride;
            stride = naga_div(_e36, 2u);
        }
        loop_init_2 = false;
        uint _e9 = stride;
        if ((_e9 > 0u)) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if ((li_4 < _e12)) {
                float3 _e18 = wg_lo[min(uint(li_4), 63u)];
                uint _e20 = stride;
                float3 _e23 = wg_lo[min(uint((li_4 + _e20)), 63u)];
                wg_lo[min(uint(li_4), 63u)] = min(_e18, _e23);
                float3 _e29 = wg_hi[min(uint(li_4), 63u)];
                uint _e31 = stride;
                float3 _e34 = wg_hi[min(uint((li_4 + _e31)), 63u)];
                wg_hi[min(uint(li_4), 63u)] = max(_e29, _e34);
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    if ((li_4 == 0u)) {
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

WorkgroupBox point_box(float3 p_7, bool has)
{
    const WorkgroupBox workgroupbox_1 = ConstructWorkgroupBox((has ? p_7 : (3.4028235e38).xxx), (has ? p_7 : (-3.4028235e38).xxx));
    return workgroupbox_1;
}

WorkgroupBox workgroup_box(uint li_5, float3 p_8, bool has_1)
{
    const WorkgroupBox _e3 = point_box(p_8, has_1);
    const WorkgroupBox _e6 = workgroup_bounds(li_5, _e3.lo, _e3.hi);
    const WorkgroupBox workgroupbox_2 = _e6;
    return workgroupbox_2;
}

bool box_is_empty(WorkgroupBox b_6)
{
    return (b_6.lo.x > b_6.hi.x);
}

uint tile_subtree(uint s_4, TileWalk t_1, bool list, uint at, uint start_2, uint to)
{
    uint p_9 = (uint)0;
    uint b_7 = (uint)0;
    bool local_25 = (bool)0;
    bool local_26 = (bool)0;
    bool local_27 = (bool)0;

    const uint _e8 = bsh_subtree(BSH, s_4, BSH_TILE_DEPTH);
    if ((_e8 == BSH_NONE)) {
        return 0u;
    }
    uint end_1 = asuint(bsh_nodes.Load(20+_e8*32));
    p_9 = at;
    const uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_1.lo, t_1.hi, t_1.w);
    b_7 = _e21;
    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e53 = b_7;
            uint _e56 = asuint(bsh_nodes.Load(20+_e53*32));
            const uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_1.lo, t_1.hi, t_1.w);
            b_7 = _e60;
        }
        loop_init_3 = false;
        uint _e23 = b_7;
        if ((_e23 != end_1)) {
            if (!(!(list))) {
                uint _e31 = p_9;
                local_26 = (_e31 < to);
            } else {
                local_26 = true;
            }
            bool _e34 = local_26;
            local_25 = _e34;
        } else {
            local_25 = false;
        }
        bool _e36 = local_25;
        if (_e36) {
        } else {
            break;
        }
        {
            if (list) {
                uint _e39 = p_9;
                local_27 = (_e39 >= start_2);
            } else {
                local_27 = false;
            }
            bool _e42 = local_27;
            if (_e42) {
                uint _e44 = p_9;
                uint _e47 = b_7;
                tile_list[min(uint((_e44 - start_2)), 1023u)] = _e47;
            }
            uint _e48 = p_9;
            p_9 = (_e48 + 1u);
        }
    }
    uint _e61 = p_9;
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

TileWalk tile_walk_begin(uint li_6, float3 x_10, float w_8, bool has_2)
{
    bool local_28 = (bool)0;
    TileWalk t_2 = (TileWalk)0;
    uint s_5 = (uint)0;
    uint sum_1 = 0u;
    uint s_6 = 0u;

    if (has_2) {
        local_28 = (w_8 >= 0.0);
    } else {
        local_28 = false;
    }
    bool _e12 = local_28;
    uint _e14; InterlockedMax(tile_scale, (_e12 ? asuint(w_8) : 0u), _e14);
    const WorkgroupBox _e15 = workgroup_box(li_6, x_10, has_2);
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
    s_5 = li_6;
    uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e40 = s_5;
            s_5 = (_e40 + TILE_THREADS);
        }
        loop_init_4 = false;
        uint _e27 = s_5;
        if ((_e27 < BSH_TILE_SUBTREES)) {
        } else {
            break;
        }
        {
            uint _e31 = s_5;
            uint _e33 = s_5;
            TileWalk _e34 = t_2;
            const uint _e39 = tile_subtree(_e33, _e34, false, 0u, 0u, 0u);
            subtree_at[min(uint(_e31), 255u)] = _e39;
        }
    }
    GroupMemoryBarrierWithGroupSync();
    if ((li_6 == 0u)) {
        uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
        bool loop_init_5 = true;
        while(true) {
            if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
            loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
            if (!loop_init_5) {
                uint _e63 = s_6;
                s_6 = (_e63 + 1u);
            }
            loop_init_5 = false;
            uint _e49 = s_6;
            if ((_e49 < BSH_TILE_SUBTREES)) {
            } else {
                break;
            }
            {
                uint _e53 = s_6;
                uint c_13 = subtree_at[min(uint(_e53), 255u)];
                uint _e57 = s_6;
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

uint tile_walk_fill(uint li_7, TileWalk t_3, uint start_3)
{
    uint s_7 = (uint)0;
    uint past = (uint)0;
    bool local_29 = (bool)0;

    uint to_1 = min(t_3.total, (start_3 + TILE_LIST));
    s_7 = li_7;
    uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
    bool loop_init_6 = true;
    while(true) {
        if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_6) {
            uint _e38 = s_7;
            s_7 = (_e38 + TILE_THREADS);
        }
        loop_init_6 = false;
        uint _e8 = s_7;
        if ((_e8 < BSH_TILE_SUBTREES)) {
        } else {
            break;
        }
        {
            uint _e12 = s_7;
            uint at_1 = subtree_at[min(uint(_e12), 255u)];
            past = t_3.total;
            uint _e17 = s_7;
            if (((_e17 + 1u) < BSH_TILE_SUBTREES)) {
                uint _e23 = s_7;
                uint _e27 = subtree_at[min(uint((_e23 + 1u)), 255u)];
                past = _e27;
            }
            if ((at_1 < to_1)) {
                uint _e31 = past;
                local_29 = (_e31 > start_3);
            } else {
                local_29 = false;
            }
            bool _e34 = local_29;
            if (_e34) {
                uint _e35 = s_7;
                const uint _e37 = tile_subtree(_e35, t_3, true, at_1, start_3, to_1);
            }
        }
    }
    GroupMemoryBarrierWithGroupSync();
    return (to_1 - start_3);
}

Shaded shade_connection(Connection c_7, float3 x_11, float3 n_11, Material m_1)
{
    Shaded s_8 = (Shaded)0;

    s_8.e = c_7.e;
    s_8.diffuse = (0.0).xxx;
    s_8.specular = (0.0).xxx;
    if ((c_7.cos_x > 0.0)) {
        float3 l_5 = normalize((c_7.y - x_11));
        float3 _e24 = view.f0_d;
        float _e27 = view.f90_d;
        const float _e29 = half_cosine(m_1.v, l_5);
        const float3 _e30 = diffuse_brdf(m_1.base, m_1.metallic, _e24, _e27, _e29);
        s_8.diffuse = (_e30 * c_7.e);
        float3 _e38 = view.f0_d;
        float _e41 = view.f90_d;
        const float3 _e44 = specular_brdf(m_1.base, m_1.metallic, _e38, _e41, m_1.alpha, n_11, m_1.v, l_5);
        s_8.specular = (_e44 * c_7.e);
    }
    Shaded _e47 = s_8;
    const Shaded shaded = _e47;
    return shaded;
}

Shaded shade_pick_traced(uint li_8, float3 x_12, float3 n_12, float3 r_10, float4 rl_6, Material m_2, float w_9, float u1_4, float u2_4, float eps_2, bool trace_3)
{
    const float _e11 = light_range_scale(li_8, x_12, r_10, rl_6);
    const Connection _e12 = connect_traced(li_8, x_12, n_12, n_12, _e11, w_9, u1_4, u2_4, eps_2, trace_3);
    const Shaded _e13 = shade_connection(_e12, x_12, n_12, m_2);
    const Shaded shaded_1 = _e13;
    return shaded_1;
}

Shaded shade_pick(uint li_9, float3 x_13, float3 n_13, float3 r_11, float4 rl_7, Material m_3, float w_10, float u1_5, float u2_5, float eps_3)
{
    const Shaded _e11 = shade_pick_traced(li_9, x_13, n_13, r_11, rl_7, m_3, w_10, u1_5, u2_5, eps_3, true);
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

Material material_of(float3 base_4, float metallic_5, float roughness_1, float reflectance, float3 v_5)
{
    const float _e7 = ggx_alpha(saturate(roughness_1));
    const Material material = ConstructMaterial(base_4, saturate(metallic_5), _e7, v_5, roughness_1, 0.0);
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

typedef uint ret_first_holders[8];
ret_first_holders first_holders(uint2 keys_1[8], bool held_1[8])
{
    uint first[8] = (uint[8])0;
    uint k_3 = 0u;
    uint j_2 = (uint)0;
    bool local_30 = (bool)0;
    bool local_31 = (bool)0;

    uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
    bool loop_init_7 = true;
    while(true) {
        if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        if (!loop_init_7) {
            uint _e45 = k_3;
            k_3 = (_e45 + 1u);
        }
        loop_init_7 = false;
        uint _e5 = k_3;
        if ((_e5 < K)) {
        } else {
            break;
        }
        {
            uint _e8 = k_3;
            uint _e11 = k_3;
            uint _e12 = k_3;
            first[min(uint(_e8), 7u)] = (held_1[min(uint(_e12), 7u)] ? _e11 : K);
            j_2 = 0u;
            uint2 loop_bound_11 = uint2(4294967295u, 4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (all(loop_bound_11 == uint2(0u, 0u))) { break; }
                loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e42 = j_2;
                    j_2 = (_e42 + 1u);
                }
                loop_init_8 = false;
                uint _e17 = j_2;
                uint _e18 = k_3;
                if ((_e17 < _e18)) {
                    uint _e22 = k_3;
                    local_30 = held_1[min(uint(_e22), 7u)];
                } else {
                    local_30 = false;
                }
                bool _e25 = local_30;
                if (_e25) {
                } else {
                    break;
                }
                {
                    uint _e26 = j_2;
                    if (held_1[min(uint(_e26), 7u)]) {
                        uint _e30 = j_2;
                        uint _e32 = k_3;
                        local_31 = all((keys_1[min(uint(_e30), 7u)] == keys_1[min(uint(_e32), 7u)]));
                    } else {
                        local_31 = false;
                    }
                    bool _e37 = local_31;
                    if (_e37) {
                        uint _e38 = k_3;
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
    WeightedPicks picks = (WeightedPicks)0;
    uint start = 0u;
    uint j = (uint)0;
    bool local_4 = (bool)0;
    uint2 keys[8] = (uint2[8])0;
    bool held[8] = (bool[8])0;
    uint k = 0u;
    uint k_1 = 0u;
    uint copies = (uint)0;
    uint j_1 = (uint)0;

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
    float len2_1 = dot(_e32, _e33);
    float4 _e35 = s;
    float3 x_14 = _e35.xyz;
    if (inside) {
        float _e40 = s.w;
        local_1 = (_e40 > 0.0);
    } else {
        local_1 = false;
    }
    bool _e44 = local_1;
    if (_e44) {
        local_2 = (len2_1 > 0.0);
    } else {
        local_2 = false;
    }
    bool _e50 = local_2;
    if (_e50) {
        local_3 = all((abs(x_14) <= (3.4028235e38).xxx));
    } else {
        local_3 = false;
    }
    bool has_3 = local_3;
    if (has_3) {
        float3 _e65 = nn;
        n = (_e65 / (sqrt(len2_1)).xxx);
    }
    float3 _e76 = n;
    r = _e76;
    if (has_3) {
        float4 mr = metal_rough_tex.Load(int3(texel_1, int(0)));
        float4 _e83 = base_color_tex.Load(int3(texel_1, int(0)));
        float3 _e90 = view.eye;
        const Material _e93 = material_of(_e83.xyz, mr.z, mr.y, mr.w, normalize((_e90 - x_14)));
        m = _e93;
        float3 _e95 = m.base;
        float _e97 = m.metallic;
        float3 _e100 = view.f0_d;
        float _e103 = view.f90_d;
        float _e105 = m.alpha;
        float3 _e106 = n;
        float3 _e108 = m.v;
        const float4 _e110 = receiver_lobe(_e95, _e97, _e100, _e103, _e105, dot(_e106, _e108));
        lobe = _e110;
        float3 _e111 = n;
        float3 _e113 = m.v;
        const float3 _e114 = mirror_dir(_e111, _e113);
        r = _e114;
    }
    float4 _e115 = lobe;
    const float4 _e116 = range_lobe(_e115);
    float _e119 = view.shadow_offset;
    float3 _e122 = view.eye;
    float eps_4 = (_e119 * length((_e122 - x_14)));
    uint _e128 = view.seed;
    uint _e132 = view.width;
    uint _e138 = view.frame;
    const uint _e139 = point_stream(_e128, ((gid.y * _e132) + gid.x), _e138);
    const uint _e140 = pick_stream(_e139);
    h = _e140;
    const WeightedPicks _e150 = weighted_picks(_e139);
    picks = _e150;
    const TileWalk _e153 = tile_walk_begin(lid, x_14, _e116.w, has_3);
    uint2 loop_bound_12 = uint2(4294967295u, 4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (all(loop_bound_12 == uint2(0u, 0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e192 = start;
            start = (_e192 + TILE_LIST);
        }
        loop_init_9 = false;
        uint _e156 = start;
        if ((_e156 < _e153.total)) {
        } else {
            break;
        }
        {
            uint _e159 = start;
            const uint _e160 = tile_walk_fill(lid, _e153, _e159);
            j = 0u;
            uint2 loop_bound_13 = uint2(4294967295u, 4294967295u);
            bool loop_init_10 = true;
            while(true) {
                if (all(loop_bound_13 == uint2(0u, 0u))) { break; }
                loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                if (!loop_init_10) {
                    uint _e190 = j;
                    j = (_e190 + 1u);
                }
                loop_init_10 = false;
                uint _e163 = j;
                if ((_e163 < _e160)) {
                } else {
                    break;
                }
                {
                    uint _e166 = j;
                    uint b_9 = tile_list[min(uint(_e166), 1023u)];
                    if (!(!(has_3))) {
                        BshNode _e175 = ConstructBshNode(asfloat(bsh_nodes.Load3(b_9*32+0)), asfloat(bsh_nodes.Load(b_9*32+12)), asuint(bsh_nodes.Load(b_9*32+16)), asuint(bsh_nodes.Load(b_9*32+20)), asuint(bsh_nodes.Load(b_9*32+24)), asfloat(bsh_nodes.Load(b_9*32+28)));
                        float3 _e176 = r;
                        const bool _e177 = bsh_reaches(_e175, x_14, _e176, _e116);
                        local_4 = !(_e177);
                    } else {
                        local_4 = true;
                    }
                    bool _e180 = local_4;
                    if (_e180) {
                        continue;
                    }
                    uint li_10 = asuint(bsh_nodes.Load(24+b_9*32));
                    float3 _e185 = n;
                    float3 _e186 = r;
                    float4 _e187 = lobe;
                    const float _e188 = light_weight(li_10, x_14, _e185, _e186, _e187, _e116);
                    weighted_offer(picks, li_10, _e188);
                }
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    if (!(has_3)) {
        if (inside) {
            out_tex[texel_1] = (0.0).xxxx;
            specular_tex[texel_1] = (0.0).xxxx;
        }
        return;
    }
    float _e203 = picks.w_sum;
    if ((_e203 > 0.0)) {
        uint2 loop_bound_14 = uint2(4294967295u, 4294967295u);
        bool loop_init_11 = true;
        while(true) {
            if (all(loop_bound_14 == uint2(0u, 0u))) { break; }
            loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
            if (!loop_init_11) {
                uint _e239 = k;
                k = (_e239 + 1u);
            }
            loop_init_11 = false;
            uint _e210 = k;
            if ((_e210 < K)) {
            } else {
                break;
            }
            {
                uint _e214 = k;
                uint _e219 = k;
                uint _e221 = picks.light[min(uint(_e219), 7u)];
                uint _e224 = asuint(lights.Load(12+_e221*64));
                uint own = ((_e224 == LIGHT_TRIANGLE) ? (_e214 + 1u) : 0u);
                uint _e228 = k;
                uint _e231 = k;
                uint _e233 = picks.light[min(uint(_e231), 7u)];
                keys[min(uint(_e228), 7u)] = uint2(_e233, own);
                uint _e235 = k;
                held[min(uint(_e235), 7u)] = true;
            }
        }
        uint2 _e241[8] = keys;
        bool _e242[8] = held;
        const uint _e243[8] = first_holders(_e241, _e242);
        uint2 loop_bound_15 = uint2(4294967295u, 4294967295u);
        bool loop_init_12 = true;
        while(true) {
            if (all(loop_bound_15 == uint2(0u, 0u))) { break; }
            loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
            if (!loop_init_12) {
                uint _e301 = k_1;
                k_1 = (_e301 + 1u);
            }
            loop_init_12 = false;
            uint _e246 = k_1;
            if ((_e246 < K)) {
            } else {
                break;
            }
            {
                uint _e249 = h;
                const uint _e250 = pcg_hash(_e249);
                h = _e250;
                uint _e251 = h;
                const float _e252 = xi_from_bits(_e251);
                uint _e253 = h;
                const uint _e254 = pcg_hash(_e253);
                h = _e254;
                uint _e255 = h;
                const float _e256 = xi_from_bits(_e255);
                uint _e258 = k_1;
                uint li_11 = picks.light[min(uint(_e258), 7u)];
                copies = 0u;
                uint _e263 = k_1;
                j_1 = _e263;
                uint2 loop_bound_16 = uint2(4294967295u, 4294967295u);
                bool loop_init_13 = true;
                while(true) {
                    if (all(loop_bound_16 == uint2(0u, 0u))) { break; }
                    loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
                    if (!loop_init_13) {
                        uint _e278 = j_1;
                        j_1 = (_e278 + 1u);
                    }
                    loop_init_13 = false;
                    uint _e265 = j_1;
                    if ((_e265 < K)) {
                    } else {
                        break;
                    }
                    {
                        uint _e268 = copies;
                        uint _e271 = j_1;
                        uint _e273 = k_1;
                        copies = (_e268 + ((_e243[min(uint(_e271), 7u)] == _e273) ? 1u : 0u));
                    }
                }
                uint _e280 = copies;
                if ((_e280 > 0u)) {
                    Shaded _e283 = t;
                    float3 _e284 = n;
                    float3 _e285 = r;
                    Material _e286 = m;
                    float _e288 = picks.w_sum;
                    uint _e290 = k_1;
                    float _e292 = picks.w[min(uint(_e290), 7u)];
                    const float _e294 = weighted_pick_weight(_e288, _e292, K);
                    uint _e295 = copies;
                    const Shaded _e298 = shade_pick(li_11, x_14, _e284, _e285, _e116, _e286, (_e294 * float(_e295)), _e252, _e256, eps_4);
                    const Shaded _e299 = add(_e283, _e298);
                    t = _e299;
                }
            }
        }
    }
    uint count = picks.n;
    float3 _e307 = t.e;
    out_tex[texel_1] = float4(_e307, float(count));
    float3 _e312 = t.specular;
    specular_tex[texel_1] = float4(_e312, 0.0);
    return;
}
