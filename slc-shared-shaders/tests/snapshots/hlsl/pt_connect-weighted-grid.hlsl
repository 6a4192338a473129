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

struct GridFrame {
    float3 lo;
    uint nx;
    float3 hi;
    uint ny;
    float3 inv;
    uint nz;
};

struct BshCursor {
    uint i;
    uint end;
    uint next;
    int _pad3_0;
    float2 cone;
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
static const uint GRID_ENTRIES_PER_LIGHT = 8u;
static const float LOBE_CONE_PAD = 1.001;
static const uint BVH = 0u;

ByteAddressBuffer slc_table : register(t0, space1);
ByteAddressBuffer geo_nodes : register(t6);
ByteAddressBuffer geo_tris : register(t7);
ByteAddressBuffer bsh_nodes : register(t5);
ByteAddressBuffer grid : register(t11);
ByteAddressBuffer grid_entries : register(t12);
ByteAddressBuffer lights : register(t2);
ByteAddressBuffer r2_4 : register(t4);
ByteAddressBuffer rt2_7 : register(t3);
ByteAddressBuffer light_cones : register(t2, space1);
cbuffer params : register(b0) { ShadeParams params; }
ByteAddressBuffer vertices_ : register(t1);
ByteAddressBuffer materials : register(t8);
RWByteAddressBuffer radiance : register(u9);
RWByteAddressBuffer candidates : register(u10);

float at(uint tab, uint i)
{
    float _e4 = asfloat(slc_table.Load(i*4));
    return _e4;
}

float to_f32_(uint u)
{
    return float(u);
}

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

uint to_u32_(float x)
{
    return naga_f2u32(x);
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

uint pcg_hash(uint x_1)
{
    const uint _e2 = mul_lo_u32_(x_1, 747796405u);
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

bool sphere_contains_point(float3 c, float r, float3 x_2)
{
    float3 v_10 = (x_2 - c);
    return (dot(v_10, v_10) <= (r * r));
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

float connection_cosine(float3 x_3, float3 y, float3 n, float3 ng, float r2_1)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;

    float3 v_11 = (x_3 - y);
    float d2_11 = dot(v_11, v_11);
    const bool _e7 = slc_keep(r2_1, d2_11);
    if (!(!(_e7))) {
        local = !((d2_11 > 0.0));
    } else {
        local = true;
    }
    bool _e16 = local;
    if (_e16) {
        return 0.0;
    }
    float3 w_12 = (v_11 / (sqrt(d2_11)).xxx);
    float cos_x_1 = -(dot(n, w_12));
    if (!(!((cos_x_1 > 0.0)))) {
        local_1 = !((dot(ng, w_12) < 0.0));
    } else {
        local_1 = true;
    }
    bool _e34 = local_1;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float vpl_lobe(float3 n_1, float3 w_1)
{
    return (max(dot(n_1, w_1), 0.0) * INV_PI);
}

float spot_falloff(float cos_theta, float cos_outer, float cos_inner, float shape)
{
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t_1 = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return ((shape > 0.5) ? (t_1 * t_1) : ((t_1 * t_1) * (3.0 - (2.0 * t_1))));
}

float triangle_lobe(float3 n_2, float area, float3 w_2)
{
    return (area * max(dot(n_2, w_2), 0.0));
}

float3 triangle_sample(float3 a_2, float3 b_2, float3 c_1, float u1_, float u2_)
{
    float su = sqrt(u1_);
    float b0_ = (1.0 - su);
    float b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_1 * ((1.0 - b0_) - b1_)));
}

float area_to_solid_angle_pdf(float pdf_area, float d2_5, float cos_light)
{
    float c_12 = abs(cos_light);
    if ((c_12 <= 0.0)) {
        return 0.0;
    }
    return ((pdf_area * d2_5) / c_12);
}

float atan_portable(float x_4)
{
    float base = 0.0;
    float t = (float)0;

    float a_9 = abs(x_4);
    t = a_9;
    if ((a_9 > 2.4142137)) {
        base = 1.5707964;
        t = (-1.0 / a_9);
    } else {
        if ((a_9 > 0.41421357)) {
            base = 0.7853982;
            t = ((a_9 - 1.0) / (a_9 + 1.0));
        }
    }
    float _e18 = t;
    float _e19 = t;
    float z = (_e18 * _e19);
    float _e21 = base;
    float _e33 = t;
    float _e35 = t;
    float r_17 = (_e21 + (((((((((0.080537446 * z) - 0.13877685) * z) + 0.19977711) * z) - 0.3333295) * z) * _e33) + _e35));
    return ((x_4 < 0.0) ? -(r_17) : r_17);
}

float atan2_portable(float y_1, float x_5)
{
    if ((x_5 == 0.0)) {
        if ((y_1 > 0.0)) {
            return 1.5707964;
        }
        if ((y_1 < 0.0)) {
            return -1.5707964;
        }
        return 0.0;
    }
    const float _e12 = atan_portable((y_1 / x_5));
    if ((x_5 > 0.0)) {
        return _e12;
    }
    if ((y_1 >= 0.0)) {
        return (_e12 + 3.1415927);
    }
    return (_e12 - 3.1415927);
}

float ies_fold_c(float c_2, float h_first, float h_last)
{
    float a_3 = (float)0;

    a_3 = (c_2 - (360.0 * floor((c_2 / 360.0))));
    if ((h_last <= 0.0)) {
        return 0.0;
    }
    if ((h_last <= 90.0)) {
        float _e15 = a_3;
        if ((_e15 > 180.0)) {
            float _e18 = a_3;
            a_3 = (360.0 - _e18);
        }
        float _e21 = a_3;
        if ((_e21 > 90.0)) {
            float _e24 = a_3;
            a_3 = (180.0 - _e24);
        }
        float _e27 = a_3;
        return _e27;
    }
    if ((h_first >= 90.0)) {
        float _e30 = a_3;
        if ((_e30 < 90.0)) {
            float _e33 = a_3;
            a_3 = (180.0 - _e33);
        } else {
            float _e36 = a_3;
            if ((_e36 > 270.0)) {
                float _e39 = a_3;
                a_3 = (540.0 - _e39);
            }
        }
        float _e42 = a_3;
        return _e42;
    }
    if ((h_last <= 180.0)) {
        float _e45 = a_3;
        if ((_e45 > 180.0)) {
            float _e48 = a_3;
            a_3 = (360.0 - _e48);
        }
        float _e51 = a_3;
        return _e51;
    }
    float _e52 = a_3;
    return _e52;
}

uint ies_segment(uint tab_1, uint start, uint n_3, float x_6)
{
    uint lo = 0u;
    uint hi = (uint)0;

    if ((n_3 < 2u)) {
        return 0u;
    }
    hi = (n_3 - 1u);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e12 = hi;
        uint _e13 = lo;
        if (((_e12 - _e13) > 1u)) {
        } else {
            break;
        }
        {
            uint _e17 = lo;
            uint _e18 = hi;
            uint mid = ((_e17 + _e18) >> 1u);
            const float _e23 = at(tab_1, (start + mid));
            if ((_e23 <= x_6)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
    uint _e25 = lo;
    return _e25;
}

float ies_lerp_t(float a0_, float a1_, float x_7)
{
    if ((a1_ <= a0_)) {
        return 0.0;
    }
    return saturate(((x_7 - a0_) / (a1_ - a0_)));
}

float ies_candela(uint tab_2, uint base_1, float gamma, float c_3)
{
    bool local_2 = (bool)0;

    const float _e4 = at(tab_2, base_1);
    const uint _e5 = to_u32_(_e4);
    const float _e8 = at(tab_2, (base_1 + 1u));
    const uint _e9 = to_u32_(_e8);
    uint v0_ = (base_1 + 2u);
    uint h0_1 = (v0_ + _e5);
    uint c0_ = (h0_1 + _e9);
    const float _e14 = at(tab_2, v0_);
    if (!((gamma < _e14))) {
        const float _e22 = at(tab_2, ((v0_ + _e5) - 1u));
        local_2 = (gamma > _e22);
    } else {
        local_2 = true;
    }
    bool _e25 = local_2;
    if (_e25) {
        return 0.0;
    }
    const float _e27 = at(tab_2, h0_1);
    const float _e31 = at(tab_2, ((h0_1 + _e9) - 1u));
    const float _e32 = ies_fold_c(c_3, _e27, _e31);
    const uint _e33 = ies_segment(tab_2, v0_, _e5, gamma);
    const uint _e34 = ies_segment(tab_2, h0_1, _e9, _e32);
    uint iv1_ = min((_e33 + 1u), (_e5 - 1u));
    uint ih1_ = min((_e34 + 1u), (_e9 - 1u));
    const float _e46 = at(tab_2, (v0_ + _e33));
    const float _e48 = at(tab_2, (v0_ + iv1_));
    const float _e49 = ies_lerp_t(_e46, _e48, gamma);
    const float _e51 = at(tab_2, (h0_1 + _e34));
    const float _e53 = at(tab_2, (h0_1 + ih1_));
    const float _e54 = ies_lerp_t(_e51, _e53, _e32);
    const float _e58 = at(tab_2, ((c0_ + (_e34 * _e5)) + _e33));
    const float _e65 = at(tab_2, ((c0_ + (_e34 * _e5)) + iv1_));
    float a_10 = ((_e58 * (1.0 - _e49)) + (_e65 * _e49));
    const float _e71 = at(tab_2, ((c0_ + (ih1_ * _e5)) + _e33));
    const float _e78 = at(tab_2, ((c0_ + (ih1_ * _e5)) + iv1_));
    float b_7 = ((_e71 * (1.0 - _e49)) + (_e78 * _e49));
    return ((a_10 * (1.0 - _e54)) + (b_7 * _e54));
}

float ies_candela_dir(uint tab_3, uint base_2, float wn, float wr, float ws)
{
    const float _e9 = atan2_portable(sqrt(((wr * wr) + (ws * ws))), wn);
    float gamma_1 = degrees(_e9);
    bool on_axis = ((abs(wr) + abs(ws)) <= 0.0);
    const float _e16 = atan2_portable(ws, wr);
    float c_13 = (on_axis ? 0.0 : degrees(_e16));
    const float _e20 = ies_candela(tab_3, base_2, gamma_1, c_13);
    return _e20;
}

float ies_light_candela(uint tab_4, uint base_3, float3 nadir, float3 reference, float3 w_3)
{
    float3 side = cross(reference, nadir);
    const float _e9 = ies_candela_dir(tab_4, base_3, dot(w_3, nadir), dot(w_3, reference), dot(w_3, side));
    return _e9;
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

float bsh_reach_bound(BshNode node_2, float w_4)
{
    const float _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_4 * 1.001) * _e5));
}

float weighted_threshold(float w_sum, float u_2)
{
    return (w_sum / (1.0 - u_2));
}

float weighted_pick_weight(float w_sum_1, float w_5, uint k)
{
    const float _e3 = to_f32_(k);
    return (w_sum_1 / (_e3 * w_5));
}

float mis_power(float pdf_a, float pdf_b)
{
    float a2_ = (pdf_a * pdf_a);
    float s_4 = (a2_ + (pdf_b * pdf_b));
    if ((s_4 <= 0.0)) {
        return 0.0;
    }
    return (a2_ / s_4);
}

float light_strategy_pdf(float select_, float rt2_3, float d2_6, float area_1, float cos_y)
{
    bool local_3 = (bool)0;
    bool local_4 = (bool)0;

    if (!((d2_6 <= 0.0))) {
        local_3 = (area_1 <= 0.0);
    } else {
        local_3 = true;
    }
    bool _e13 = local_3;
    if (!(_e13)) {
        local_4 = (cos_y <= 0.0);
    } else {
        local_4 = true;
    }
    bool _e20 = local_4;
    if (_e20) {
        return 0.0;
    }
    const float _e22 = rr_probability(rt2_3, d2_6);
    const float _e26 = area_to_solid_angle_pdf((1.0 / area_1), d2_6, cos_y);
    return ((select_ * _e22) * _e26);
}

float cosine_pdf(float cos_theta_1)
{
    return (max(cos_theta_1, 0.0) * INV_PI);
}

float3 onb_tangent(float3 n_4)
{
    float s_5 = ((n_4.z >= 0.0) ? 1.0 : -1.0);
    float a_11 = (-1.0 / (s_5 + n_4.z));
    return float3((1.0 + (((s_5 * n_4.x) * n_4.x) * a_11)), (((s_5 * n_4.x) * n_4.y) * a_11), (-(s_5) * n_4.x));
}

float3 onb_bitangent(float3 n_5)
{
    float s_6 = ((n_5.z >= 0.0) ? 1.0 : -1.0);
    float a_12 = (-1.0 / (s_6 + n_5.z));
    return float3(((n_5.x * n_5.y) * a_12), (s_6 + ((n_5.y * n_5.y) * a_12)), -(n_5.y));
}

float3 onb_to_local(float3 n_6, float3 w_6)
{
    const float3 _e2 = onb_tangent(n_6);
    const float3 _e4 = onb_bitangent(n_6);
    return float3(dot(w_6, _e2), dot(w_6, _e4), dot(w_6, n_6));
}

float ggx_d(float cos_h, float sin2_h, float alpha)
{
    if ((cos_h <= 0.0)) {
        return 0.0;
    }
    float a2_1 = (alpha * alpha);
    float t_2 = (((cos_h * cos_h) * a2_1) + sin2_h);
    return ((a2_1 * INV_PI) / (t_2 * t_2));
}

float smith_root(float cos_, float alpha_1)
{
    float a2_2 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1.0 - a2_2)) + a2_2));
}

float smith_visibility(float n_l, float n_v, float alpha_2)
{
    bool local_5 = (bool)0;

    if (!((n_l <= 0.0))) {
        local_5 = (n_v <= 0.0);
    } else {
        local_5 = true;
    }
    bool _e11 = local_5;
    if (_e11) {
        return 0.0;
    }
    const float _e13 = smith_root(n_v, alpha_2);
    const float _e15 = smith_root(n_l, alpha_2);
    return (0.5 / ((n_l * _e13) + (n_v * _e15)));
}

float3 fresnel_schlick(float3 f0_, float f90_, float v_h)
{
    float c_14 = saturate((1.0 - v_h));
    float c2_ = (c_14 * c_14);
    return (f0_ + ((float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_14)));
}

float3 specular_fresnel(float3 base_4, float metallic, float3 f0_d, float f90_d, float v_h_1)
{
    const float3 _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    const float3 _e10 = fresnel_schlick(base_4, 1.0, v_h_1);
    return ((_e5 * (1.0 - metallic)) + (_e10 * metallic));
}

float3 diffuse_brdf(float3 base_5, float metallic_1, float3 f0_d_1, float f90_d_1, float v_h_2)
{
    const float3 _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return ((((float3(1.0, 1.0, 1.0) - _e9) * base_5) * (1.0 - metallic_1)) * INV_PI);
}

float half_cosine(float3 v, float3 l)
{
    float3 h_7 = (v + l);
    float len2_ = dot(h_7, h_7);
    if ((len2_ <= 0.0)) {
        return 0.0;
    }
    return saturate((dot(v, h_7) / sqrt(len2_)));
}

float3 specular_brdf(float3 base_6, float metallic_2, float3 f0_d_2, float f90_d_2, float alpha_3, float3 n_7, float3 v_1, float3 l_1)
{
    bool local_6 = (bool)0;

    float n_l_1 = dot(n_7, l_1);
    float n_v_2 = dot(n_7, v_1);
    if (!((n_l_1 <= 0.0))) {
        local_6 = (n_v_2 <= 0.0);
    } else {
        local_6 = true;
    }
    bool _e18 = local_6;
    if (_e18) {
        return float3(0.0, 0.0, 0.0);
    }
    float3 hs = (v_1 + l_1);
    float inv_1 = (1.0 / sqrt(dot(hs, hs)));
    float3 h_8 = (hs * inv_1);
    float3 c_15 = cross(n_7, h_8);
    const float _e32 = ggx_d(dot(n_7, h_8), dot(c_15, c_15), alpha_3);
    const float3 _e34 = specular_fresnel(base_6, metallic_2, f0_d_2, f90_d_2, dot(v_1, h_8));
    const float _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return (_e34 * (_e32 * _e35));
}

float3 brdf_eval(float3 base_7, float metallic_3, float3 f0_d_3, float f90_d_3, float alpha_4, float3 n_8, float3 v_2, float3 l_2)
{
    if ((dot(n_8, l_2) <= 0.0)) {
        return float3(0.0, 0.0, 0.0);
    }
    const float _e15 = half_cosine(v_2, l_2);
    const float3 _e16 = diffuse_brdf(base_7, metallic_3, f0_d_3, f90_d_3, _e15);
    const float3 _e17 = specular_brdf(base_7, metallic_3, f0_d_3, f90_d_3, alpha_4, n_8, v_2, l_2);
    return (_e16 + _e17);
}

bool has_specular(float metallic_4, float3 f0_d_4, float f90_d_4)
{
    bool local_7 = (bool)0;
    bool local_8 = (bool)0;

    if (!((metallic_4 > 0.0))) {
        local_7 = (f90_d_4 > 0.0);
    } else {
        local_7 = true;
    }
    bool _e11 = local_7;
    if (!(_e11)) {
        local_8 = (max(max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0.0);
    } else {
        local_8 = true;
    }
    bool _e23 = local_8;
    return _e23;
}

float channel_mean(float3 c_4)
{
    return (((c_4.x + c_4.y) + c_4.z) * 0.33333334);
}

float4 receiver_lobe(float3 base_8, float metallic_5, float3 f0_d_5, float f90_d_5, float alpha_5, float n_v_1)
{
    bool local_9 = (bool)0;

    const float3 _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    const float _e16 = channel_mean((((float3(1.0, 1.0, 1.0) - _e10) * base_8) * (1.0 - metallic_5)));
    if (!((n_v_1 <= 0.0))) {
        const bool _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_9 = !(_e22);
    } else {
        local_9 = true;
    }
    bool _e25 = local_9;
    if (_e25) {
        return float4(_e16, 0.0, alpha_5, n_v_1);
    }
    const float3 _e28 = specular_fresnel(base_8, metallic_5, f0_d_5, f90_d_5, n_v_1);
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

float3 mirror_dir(float3 n_9, float3 v_3)
{
    return ((n_9 * (2.0 * dot(n_9, v_3))) - v_3);
}

float bounded_vndf_k(float3 wi, float alpha_6)
{
    float a_13 = saturate(alpha_6);
    float s_7 = (1.0 + sqrt(((wi.x * wi.x) + (wi.y * wi.y))));
    float a2_3 = (a_13 * a_13);
    float s2_ = (s_7 * s_7);
    return (((1.0 - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z)));
}

float ggx_vndf_pdf(float3 wi_1, float3 wo, float alpha_7)
{
    bool local_10 = (bool)0;

    if (!((wi_1.z <= 0.0))) {
        local_10 = (wo.z <= 0.0);
    } else {
        local_10 = true;
    }
    bool _e13 = local_10;
    if (_e13) {
        return 0.0;
    }
    float3 hs_1 = (wi_1 + wo);
    float3 m_1 = (hs_1 / (sqrt(dot(hs_1, hs_1))).xxx);
    const float _e28 = ggx_d(m_1.z, ((m_1.x * m_1.x) + (m_1.y * m_1.y)), alpha_7);
    float t_3 = sqrt((((alpha_7 * alpha_7) * ((wi_1.x * wi_1.x) + (wi_1.y * wi_1.y))) + (wi_1.z * wi_1.z)));
    const float _e43 = bounded_vndf_k(wi_1, alpha_7);
    return (_e28 / (2.0 * ((_e43 * wi_1.z) + t_3)));
}

float bsdf_pdf(float3 n_10, float3 v_4, float3 l_3, float alpha_8, float p_spec)
{
    const float _e6 = cosine_pdf(dot(n_10, l_3));
    if ((p_spec <= 0.0)) {
        return _e6;
    }
    const float3 _e9 = onb_to_local(n_10, v_4);
    const float3 _e10 = onb_to_local(n_10, l_3);
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

float safe_sqrt(float x_8)
{
    return sqrt(max(x_8, 0.0));
}

float subtended_cos(float dist2_, float r2_2)
{
    const float _e5 = safe_sqrt((1.0 - (r2_2 / dist2_)));
    return ((dist2_ <= r2_2) ? -1.0 : _e5);
}

float4 emitter_cone(float3 center_, float radius, float3 axis, float cos_o, float3 p)
{
    bool local_11 = (bool)0;

    float3 v_12 = (p - center_);
    float dist2_1 = dot(v_12, v_12);
    float r2_5 = (radius * radius);
    if ((dist2_1 <= 0.0)) {
        local_11 = (r2_5 <= 0.0);
    } else {
        local_11 = false;
    }
    bool _e15 = local_11;
    if (_e15) {
        return float4(-2.0, 1e-12, -1.0, 0.0);
    }
    float d2_12 = max(max(dist2_1, r2_5), MIN_D2_);
    float3 wi_2 = ((dist2_1 > 0.0) ? (v_12 / (sqrt(dist2_1)).xxx) : float3(0.0, 0.0, 0.0));
    float cos_w = dot(axis, wi_2);
    const float _e38 = safe_sqrt((1.0 - (cos_w * cos_w)));
    const float _e39 = subtended_cos(dist2_1, r2_5);
    const float _e43 = safe_sqrt((1.0 - (_e39 * _e39)));
    const float _e47 = safe_sqrt((1.0 - (cos_o * cos_o)));
    const float _e48 = cos_sub_clamped(_e38, cos_w, _e47, cos_o);
    const float _e49 = sin_sub_clamped(_e38, cos_w, _e47, cos_o);
    const float _e50 = cos_sub_clamped(_e49, _e48, _e43, _e39);
    return float4(_e50, d2_12, _e39, _e43);
}

float emitter_importance(float3 center_1, float radius_1, float phi, float3 axis_1, float cos_o_1, float cos_e, float3 p_1)
{
    const float4 _e7 = emitter_cone(center_1, radius_1, axis_1, cos_o_1, p_1);
    if ((_e7.x <= cos_e)) {
        return 0.0;
    }
    return ((phi * _e7.x) / _e7.y);
}

float cone_cos_of(float3 v_5, float d2_7, float a_4, float3 d)
{
    bool local_12 = (bool)0;
    bool local_13 = (bool)0;

    float vd = dot(v_5, d);
    float h2_ = (d2_7 - (a_4 * a_4));
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
    float3 c_16 = cross(v_5, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_16, c_16)) * a_4)) / d2_7), 1.0);
}

float cone_cos_toward(float3 center_2, float radius_2, float3 p_2, float3 d_1)
{
    float3 v_13 = (center_2 - p_2);
    const float _e6 = cone_cos_of(v_13, dot(v_13, v_13), radius_2, d_1);
    return _e6;
}

float range_scale_at(float4 rl, float cos_t)
{
    float t_4 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_4 * t_4))), 1.0, (rl.w * rl.w));
}

float range_scale_toward(float4 rl_1, float3 center_3, float radius_3, float3 p_3, float3 r_1)
{
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    const float _e9 = cone_cos_toward(center_3, radius_3, p_3, r_1);
    const float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

float light_importance(float3 center_4, float radius_4, float phi_1, float3 axis_2, float cos_o_2, float cos_e_1, float3 p_4, float3 n_11)
{
    float imp = (float)0;

    const float4 _e8 = emitter_cone(center_4, radius_4, axis_2, cos_o_2, p_4);
    if ((_e8.x <= cos_e_1)) {
        return 0.0;
    }
    imp = ((phi_1 * _e8.x) / _e8.y);
    if ((dot(n_11, n_11) > 0.0)) {
        float3 v_14 = (center_4 - p_4);
        float dist2_2 = dot(v_14, v_14);
        float cos_i = dot(((dist2_2 > 0.0) ? (v_14 / (sqrt(dist2_2)).xxx) : float3(0.0, 0.0, 0.0)), n_11);
        float _e33 = imp;
        const float _e37 = safe_sqrt((1.0 - (cos_i * cos_i)));
        const float _e40 = cos_sub_clamped(_e37, cos_i, _e8.w, _e8.z);
        imp = (_e33 * max(_e40, 0.0));
    }
    float _e44 = imp;
    return max(_e44, 0.0);
}

float glossy_importance(float3 center_5, float radius_5, float phi_2, float3 axis_3, float cos_o_3, float cos_e_2, float3 p_5, float3 n_12, float3 r_2, float4 lobe_5)
{
    bool local_14 = (bool)0;

    const float _e10 = emitter_importance(center_5, radius_5, phi_2, axis_3, cos_o_3, cos_e_2, p_5);
    const float _e11 = cone_cos_toward(center_5, radius_5, p_5, n_12);
    if (!((_e10 <= 0.0))) {
        local_14 = (_e11 <= 0.0);
    } else {
        local_14 = true;
    }
    bool _e20 = local_14;
    if (_e20) {
        return 0.0;
    }
    const float _e22 = cone_cos_toward(center_5, radius_5, p_5, r_2);
    const float _e27 = safe_sqrt((0.5 + (0.5 * _e22)));
    const float _e33 = ggx_d(_e27, (1.0 - (_e27 * _e27)), lobe_5.z);
    const float _e39 = smith_root(lobe_5.w, lobe_5.z);
    float spec = (((lobe_5.y * _e33) * 0.25) / _e39);
    return (_e10 * (((lobe_5.x * INV_PI) * _e11) + spec));
}

float candidate_weight(float importance, float rt2_4, float d2_8)
{
    const float _e3 = slc_weight(rt2_4, d2_8);
    return (importance * _e3);
}

float cone_weight(float3 center_6, float radius_6, float phi_3, float3 axis_4, float cos_o_4, float cos_e_3, float rt2_5, float3 p_6, float3 n_13, float3 r_3, float4 lobe_6)
{
    float3 v_15 = (p_6 - center_6);
    if ((lobe_6.y <= 0.0)) {
        const float _e15 = light_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_13);
        const float _e19 = candidate_weight((_e15 * INV_PI), rt2_5, dot(v_15, v_15));
        return _e19;
    }
    const float _e20 = glossy_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_13, r_3, lobe_6);
    const float _e22 = candidate_weight(_e20, rt2_5, dot(v_15, v_15));
    return _e22;
}

float weighted_select_pdf(float w_7, float w_sum_2, bool in_range, uint k_1)
{
    if ((w_7 <= 0.0)) {
        return 0.0;
    }
    float total = (in_range ? w_sum_2 : (w_sum_2 + w_7));
    const float _e9 = to_f32_(k_1);
    return ((_e9 * w_7) / total);
}

bool finite3_(float3 v_6)
{
    bool local_15 = (bool)0;
    bool local_16 = (bool)0;

    if ((abs(v_6.x) <= F32_MAX)) {
        local_15 = (abs(v_6.y) <= F32_MAX);
    } else {
        local_15 = false;
    }
    bool _e12 = local_15;
    if (_e12) {
        local_16 = (abs(v_6.z) <= F32_MAX);
    } else {
        local_16 = false;
    }
    bool _e20 = local_16;
    return _e20;
}

float shadow_margin(float len)
{
    return (0.0001 * len);
}

float ray_inverse(float x_9)
{
    return (1.0 / ((abs(x_9) < 1e-30) ? 1e-30 : x_9));
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
    float3 lo_2 = min(t0_, t1_);
    float3 hi_1 = max(t0_, t1_);
    float t_in = max(max(lo_2.x, lo_2.y), max(lo_2.z, 0.0));
    float t_out = min(min(hi_1.x, hi_1.y), min(hi_1.z, t_max));
    if ((t_in <= t_out)) {
        return t_in;
    }
    return -1.0;
}

float3 triangle_normal(float3 a_5, float3 b_3, float3 c_5)
{
    bool local_17 = (bool)0;

    float3 n_23 = cross((b_3 - a_5), (c_5 - a_5));
    float l2_ = dot(n_23, n_23);
    if (!(!((l2_ > 0.0)))) {
        local_17 = !((l2_ < 3e38));
    } else {
        local_17 = true;
    }
    bool _e17 = local_17;
    if (_e17) {
        return float3(0.0, 0.0, 0.0);
    }
    return (n_23 / (sqrt(l2_)).xxx);
}

float ray_triangle(float3 o_1, float3 d_3, float3 a_6, float3 b_4, float3 c_6, float t_min, float t_max_1)
{
    bool local_18 = (bool)0;
    bool local_19 = (bool)0;
    bool local_20 = (bool)0;

    float3 e1_ = (b_4 - a_6);
    float3 e2_ = (c_6 - a_6);
    float3 p_7 = cross(d_3, e2_);
    float det = dot(e1_, p_7);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv_2 = (1.0 / det);
    float3 s_8 = (o_1 - a_6);
    float u_3 = (dot(s_8, p_7) * inv_2);
    if (!((u_3 < 0.0))) {
        local_18 = (u_3 > 1.0);
    } else {
        local_18 = true;
    }
    bool _e28 = local_18;
    if (_e28) {
        return -1.0;
    }
    float3 q = cross(s_8, e1_);
    float v_16 = (dot(d_3, q) * inv_2);
    if (!((v_16 < 0.0))) {
        local_19 = ((u_3 + v_16) > 1.0);
    } else {
        local_19 = true;
    }
    bool _e42 = local_19;
    if (_e42) {
        return -1.0;
    }
    float t_5 = (dot(e2_, q) * inv_2);
    if ((t_5 > t_min)) {
        local_20 = (t_5 < t_max_1);
    } else {
        local_20 = false;
    }
    bool _e51 = local_20;
    if (_e51) {
        return t_5;
    }
    return -1.0;
}

float3 light_intensity(GpuLight l_4, float3 w_8)
{
    switch(l_4.kind) {
        case 0u: {
            return l_4.intensity;
        }
        case 1u: {
            const float _e11 = spot_falloff(dot(l_4.p1_, w_8), l_4.a, l_4.b, l_4.p2_.x);
            return (l_4.intensity * _e11);
        }
        case 2u: {
            const float _e18 = ies_light_candela(0u, l_4.ies_base, l_4.p1_, l_4.p2_, w_8);
            return (l_4.intensity * _e18);
        }
        case 3u: {
            const float3 _e24 = triangle_normal(l_4.p0_, l_4.p1_, l_4.p2_);
            const float _e26 = triangle_lobe(_e24, l_4.a, w_8);
            return (l_4.intensity * _e26);
        }
        case 4u: {
            const float _e30 = vpl_lobe(l_4.p1_, w_8);
            return (l_4.intensity * _e30);
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
    uint node_3 = 0u;
    uint i_1 = (uint)0;

    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((((NagaBufferLength(geo_nodes) - 0) / 32) == 0u)) {
        GeoHit _e13 = hit;
        const GeoHit geohit = _e13;
        return geohit;
    }
    const float3 _e14 = ray_inverse3_(d_4);
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e21 = node_3;
        GpuGeoNode n_24 = ConstructGpuGeoNode(asfloat(geo_nodes.Load3(_e21*32+0)), asuint(geo_nodes.Load(_e21*32+12)), asfloat(geo_nodes.Load3(_e21*32+16)), asuint(geo_nodes.Load(_e21*32+28)));
        float _e27 = hit.t;
        const float _e28 = ray_aabb(o_2, _e14, n_24.bmin, n_24.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_24.count > 0u)) {
                i_1 = n_24.first;
                uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
                bool loop_init = true;
                while(true) {
                    if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
                    loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                    if (!loop_init) {
                        uint _e58 = i_1;
                        i_1 = (_e58 + 1u);
                    }
                    loop_init = false;
                    uint _e36 = i_1;
                    if ((_e36 < (n_24.first + n_24.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i_1;
                        GpuTriangle t_6 = ConstructGpuTriangle(asfloat(geo_tris.Load3(_e42*48+0)), asuint(geo_tris.Load(_e42*48+12)), asfloat(geo_tris.Load3(_e42*48+16)), asuint(geo_tris.Load(_e42*48+28)), asfloat(geo_tris.Load3(_e42*48+32)), asuint(geo_tris.Load(_e42*48+44)));
                        float _e49 = hit.t;
                        const float _e50 = ray_triangle(o_2, d_4, t_6.v0_, t_6.v1_, t_6.v2_, t_min_1, _e49);
                        if ((_e50 > 0.0)) {
                            hit.t = _e50;
                            uint _e55 = i_1;
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
                    stack[min(uint(_e63), 63u)] = (n_24.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_24.first;
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

bool occluded(float3 a_7, float3 b_5)
{
    float3 dv = (b_5 - a_7);
    float len_1 = length(dv);
    if ((len_1 <= 0.0)) {
        return false;
    }
    const float _e7 = shadow_margin(len_1);
    const GeoHit _e12 = trace(a_7, (dv / (len_1).xxx), _e7, (len_1 - _e7), true);
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

BshNode bsh_node(uint nodes, uint i_2)
{
    BshNode _e4 = ConstructBshNode(asfloat(bsh_nodes.Load3(i_2*32+0)), asfloat(bsh_nodes.Load(i_2*32+12)), asuint(bsh_nodes.Load(i_2*32+16)), asuint(bsh_nodes.Load(i_2*32+20)), asuint(bsh_nodes.Load(i_2*32+24)), asfloat(bsh_nodes.Load(i_2*32+28)));
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

float bsh_inner_scale(float a_8, float3 v_7, float d2_9, float3 r_4, float4 rl_2)
{
    const float _e5 = cone_cos_of(v_7, d2_9, a_8, r_4);
    const float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_4, float3 x_10, float3 r_5, float4 rl_3)
{
    bool local_21 = (bool)0;
    bool local_22 = (bool)0;

    const bool _e6 = sphere_contains_point(node_4.center_, node_4.radius, x_10);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        const bool _e20 = sphere_contains_point(node_4.center_, (node_4.radius * (rl_3.w * 1.0001)), x_10);
        local_21 = !(_e20);
    } else {
        local_21 = true;
    }
    bool _e23 = local_21;
    if (_e23) {
        return false;
    }
    float3 v_17 = (x_10 - node_4.center_);
    float d2_13 = dot(v_17, v_17);
    const float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if ((d2_13 > (_e29 * _e29))) {
        return false;
    }
    if ((node_4.child == BSH_NONE)) {
        const float _e38 = range_scale_toward(rl_3, node_4.center_, node_4.extent, x_10, r_5);
        const float _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        const bool _e42 = sphere_contains_point(node_4.center_, _e41, x_10);
        return _e42;
    }
    const float _e45 = bsh_inner_scale(node_4.extent, -(v_17), d2_13, r_5, rl_3);
    float s_c = (_e45 * 1.001);
    const float _e50 = bsh_range_bound(node_4);
    float reach = (node_4.extent + (sqrt(s_c) * _e50));
    if ((d2_13 <= ((node_4.radius * node_4.radius) * s_c))) {
        local_22 = (d2_13 <= (reach * reach));
    } else {
        local_22 = false;
    }
    bool _e63 = local_22;
    return _e63;
}

uint bsh_next_leaf_lobe(uint nodes_3, uint start_1, float3 x_11, float3 r_6, float4 rl_4)
{
    uint i_3 = (uint)0;

    i_3 = start_1;
    uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e6 = i_3;
        if ((_e6 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e9 = i_3;
            const BshNode _e10 = bsh_node(nodes_3, _e9);
            const bool _e11 = bsh_reaches(_e10, x_11, r_6, rl_4);
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
    return BSH_NONE;
}

uint bsh_grid_axis(float v_8, float lo_1, float inv, uint n_14)
{
    const uint _e8 = to_u32_(max(((v_8 - lo_1) * inv), 0.0));
    return min(_e8, (n_14 - 1u));
}

uint bsh_grid_cell(GridFrame f, float3 x_12)
{
    bool local_23 = (bool)0;
    bool local_24 = (bool)0;
    bool local_25 = (bool)0;
    bool local_26 = (bool)0;
    bool local_27 = (bool)0;

    if ((x_12.x >= f.lo.x)) {
        local_23 = (x_12.y >= f.lo.y);
    } else {
        local_23 = false;
    }
    bool _e13 = local_23;
    if (_e13) {
        local_24 = (x_12.z >= f.lo.z);
    } else {
        local_24 = false;
    }
    bool _e21 = local_24;
    if (_e21) {
        local_25 = (x_12.x <= f.hi.x);
    } else {
        local_25 = false;
    }
    bool _e29 = local_25;
    if (_e29) {
        local_26 = (x_12.y <= f.hi.y);
    } else {
        local_26 = false;
    }
    bool _e37 = local_26;
    if (_e37) {
        local_27 = (x_12.z <= f.hi.z);
    } else {
        local_27 = false;
    }
    bool inside = local_27;
    if (!(inside)) {
        return BSH_NONE;
    }
    const uint _e54 = bsh_grid_axis(x_12.x, f.lo.x, f.inv.x, f.nx);
    const uint _e61 = bsh_grid_axis(x_12.y, f.lo.y, f.inv.y, f.ny);
    const uint _e68 = bsh_grid_axis(x_12.z, f.lo.z, f.inv.z, f.nz);
    return ((((_e68 * f.ny) + _e61) * f.nx) + _e54);
}

float2 lobe_cone(float3 r_7, float4 rl_5)
{
    bool local_28 = (bool)0;
    bool local_29 = (bool)0;
    bool local_30 = (bool)0;
    bool local_31 = (bool)0;
    float c_7 = (float)0;
    uint tries = 0u;

    const bool _e2 = finite3_(r_7);
    if (_e2) {
        local_28 = (rl_5.x < 1.0);
    } else {
        local_28 = false;
    }
    bool _e9 = local_28;
    if (_e9) {
        local_29 = (rl_5.y >= 0.0);
    } else {
        local_29 = false;
    }
    bool _e16 = local_29;
    if (_e16) {
        local_30 = (rl_5.z > 0.0);
    } else {
        local_30 = false;
    }
    bool _e23 = local_30;
    if (_e23) {
        local_31 = (rl_5.z < 1.0);
    } else {
        local_31 = false;
    }
    bool _e30 = local_31;
    if (!(_e30)) {
        return float2(0.0, 0.0);
    }
    float t1_1 = sqrt(((rl_5.y * rl_5.z) / (1.0 - rl_5.x)));
    c_7 = (((2.0 * (1.0 - t1_1)) / (1.0 - rl_5.z)) - 1.0);
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        float _e56 = c_7;
        const float _e57 = range_scale_at(rl_5, _e56);
        if (!((_e57 <= 1.0))) {
        } else {
            break;
        }
        {
            float _e61 = c_7;
            c_7 = (_e61 - 0.0001);
            uint _e64 = tries;
            tries = (_e64 + 1u);
            uint _e67 = tries;
            if ((_e67 > 16u)) {
                return float2(0.0, 0.0);
            }
        }
    }
    float _e73 = c_7;
    float w_13 = min((min(_e73, 1.0) - 0.001), 0.9999);
    if (!((w_13 > 0.0))) {
        return float2(0.0, 0.0);
    }
    return float2((w_13 * w_13), (1.0 / sqrt((1.0 - (w_13 * w_13)))));
}

bool lobe_cone_meets(float3 v_9, float d2_10, float extent, float3 axis_5, float2 cone)
{
    bool local_32 = (bool)0;

    float k_2 = (((extent * LOBE_CONE_PAD) + 1e-30) * cone.y);
    float vd_1 = -(dot(v_9, axis_5));
    float a_14 = (vd_1 + k_2);
    float b_8 = (d2_10 + (k_2 * ((2.0 * vd_1) + k_2)));
    if ((a_14 >= 0.0)) {
        local_32 = ((a_14 * a_14) >= (b_8 * cone.x));
    } else {
        local_32 = false;
    }
    bool _e28 = local_32;
    return _e28;
}

bool bsh_lobe_admits(float3 c_8, float radius_7, float extent_1, float3 x_13, float w_9, float3 axis_6, float2 cone_1)
{
    bool local_33 = (bool)0;
    bool local_34 = (bool)0;
    bool local_35 = (bool)0;

    float3 v_18 = (x_13 - c_8);
    float d2_14 = dot(v_18, v_18);
    float f_2 = (radius_7 * (w_9 * 1.0001));
    if ((d2_14 <= (f_2 * f_2))) {
        if (!((cone_1.y == 0.0))) {
            local_34 = (d2_14 <= (radius_7 * radius_7));
        } else {
            local_34 = true;
        }
        bool _e25 = local_34;
        if (!(_e25)) {
            const bool _e29 = lobe_cone_meets(v_18, d2_14, extent_1, axis_6, cone_1);
            local_35 = _e29;
        } else {
            local_35 = true;
        }
        bool _e31 = local_35;
        local_33 = _e31;
    } else {
        local_33 = false;
    }
    bool _e33 = local_33;
    return _e33;
}

uint grid_word(uint i_4)
{
    uint _e3 = asuint(grid.Load(i_4*4));
    return _e3;
}

GridFrame grid_frame(uint h_1)
{
    GridFrame f_1 = (GridFrame)0;

    const uint _e3 = grid_word(h_1);
    const uint _e7 = grid_word((h_1 + 1u));
    const uint _e11 = grid_word((h_1 + 2u));
    f_1.lo = float3(asfloat(_e3), asfloat(_e7), asfloat(_e11));
    const uint _e17 = grid_word((h_1 + 3u));
    f_1.nx = _e17;
    const uint _e21 = grid_word((h_1 + 4u));
    const uint _e25 = grid_word((h_1 + 5u));
    const uint _e29 = grid_word((h_1 + 6u));
    f_1.hi = float3(asfloat(_e21), asfloat(_e25), asfloat(_e29));
    const uint _e35 = grid_word((h_1 + 7u));
    f_1.ny = _e35;
    const uint _e39 = grid_word((h_1 + 8u));
    const uint _e43 = grid_word((h_1 + 9u));
    const uint _e47 = grid_word((h_1 + 10u));
    f_1.inv = float3(asfloat(_e39), asfloat(_e43), asfloat(_e47));
    const uint _e53 = grid_word((h_1 + 11u));
    f_1.nz = _e53;
    GridFrame _e54 = f_1;
    const GridFrame gridframe = _e54;
    return gridframe;
}

float grid_reach(uint h_2)
{
    const uint _e3 = grid_word((h_2 + 12u));
    return asfloat(_e3);
}

BshCursor bsh_cursor(float3 x_14, float3 r_8, float4 rl_6)
{
    BshCursor c_9 = (BshCursor)0;
    uint h_3 = 0u;
    uint g = 1u;
    bool local_36 = (bool)0;
    bool local_37 = (bool)0;
    bool local_38 = (bool)0;

    c_9.i = 0u;
    c_9.end = 0u;
    const uint _e10 = bsh_first(BSH);
    c_9.next = _e10;
    c_9.cone = (0.0).xx;
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e34 = g;
            g = (_e34 + 1u);
        }
        loop_init_1 = false;
        uint _e18 = g;
        if ((_e18 < GRIDS_MAX)) {
            uint _e24 = h_3;
            const float _e25 = grid_reach(_e24);
            local_36 = (rl_6.w > _e25);
        } else {
            local_36 = false;
        }
        bool _e28 = local_36;
        if (_e28) {
        } else {
            break;
        }
        {
            uint _e29 = h_3;
            const uint _e32 = grid_word((_e29 + 14u));
            h_3 = _e32;
        }
    }
    uint _e36 = h_3;
    const GridFrame _e37 = grid_frame(_e36);
    uint _e39 = c_9.next;
    if ((_e39 != BSH_NONE)) {
        local_37 = (_e37.nx > 0u);
    } else {
        local_37 = false;
    }
    bool _e48 = local_37;
    if (_e48) {
        uint _e52 = h_3;
        const float _e53 = grid_reach(_e52);
        local_38 = (rl_6.w <= _e53);
    } else {
        local_38 = false;
    }
    bool _e56 = local_38;
    if (_e56) {
        const uint _e57 = bsh_grid_cell(_e37, x_14);
        if ((_e57 != BSH_NONE)) {
            uint _e62 = h_3;
            uint _e67 = asuint(grid.Load(((_e62 + GRID_HEADER) + _e57)*4));
            c_9.i = _e67;
            uint _e70 = h_3;
            uint _e77 = asuint(grid.Load((((_e70 + GRID_HEADER) + _e57) + 1u)*4));
            c_9.end = _e77;
            uint _e82 = asuint(bsh_nodes.Load(20+0));
            c_9.next = _e82;
            const float2 _e84 = lobe_cone(r_8, rl_6);
            c_9.cone = _e84;
        }
    }
    BshCursor _e85 = c_9;
    const BshCursor bshcursor = _e85;
    return bshcursor;
}

uint bsh_cursor_next(inout BshCursor c_10, float3 x_15, float3 r_9, float4 rl_7)
{
    bool local_39 = (bool)0;
    bool local_40 = (bool)0;

    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        uint _e5 = c_10.i;
        uint _e7 = c_10.end;
        if ((_e5 < _e7)) {
        } else {
            break;
        }
        {
            uint _e11 = c_10.i;
            uint b_9 = asuint(grid_entries.Load(_e11*4));
            uint _e15 = c_10.i;
            c_10.i = (_e15 + 1u);
            BshNode n_25 = ConstructBshNode(asfloat(bsh_nodes.Load3(b_9*32+0)), asfloat(bsh_nodes.Load(b_9*32+12)), asuint(bsh_nodes.Load(b_9*32+16)), asuint(bsh_nodes.Load(b_9*32+20)), asuint(bsh_nodes.Load(b_9*32+24)), asfloat(bsh_nodes.Load(b_9*32+28)));
            if (!((rl_7.w <= 1.0))) {
                float2 _e32 = c_10.cone;
                const bool _e33 = bsh_lobe_admits(n_25.center_, n_25.radius, n_25.extent, x_15, rl_7.w, r_9, _e32);
                local_39 = _e33;
            } else {
                local_39 = true;
            }
            bool _e35 = local_39;
            if (_e35) {
                const bool _e38 = bsh_reaches(n_25, x_15, r_9, rl_7);
                local_40 = _e38;
            } else {
                local_40 = false;
            }
            bool _e40 = local_40;
            if (_e40) {
                return b_9;
            }
        }
    }
    uint _e43 = c_10.next;
    const uint _e44 = bsh_next_leaf_lobe(BSH, _e43, x_15, r_9, rl_7);
    if ((_e44 != BSH_NONE)) {
        uint _e51 = asuint(bsh_nodes.Load(20+_e44*32));
        c_10.next = _e51;
    }
    return _e44;
}

float next_threshold(float sum_1, inout uint h_4)
{
    uint _e2 = h_4;
    const uint _e3 = pcg_hash(_e2);
    h_4 = _e3;
    uint _e4 = h_4;
    const float _e5 = xi_from_bits(_e4);
    const float _e6 = weighted_threshold(sum_1, _e5);
    return _e6;
}

Connection connect_record(GpuLight l_8, float3 x_16, float3 n_15, float3 ng_1, float r2_3, float rt2_6, float w_res, float u1_2, float u2_2, float eps, bool trace_1)
{
    Connection c_11 = (Connection)0;
    bool local_41 = (bool)0;
    bool local_42 = (bool)0;

    c_11.e = (0.0).xxx;
    const float3 _e16 = light_point(l_8, u1_2, u2_2);
    c_11.y = _e16;
    float3 _e19 = c_11.y;
    const float _e20 = connection_cosine(x_16, _e19, n_15, ng_1, r2_3);
    c_11.cos_x = _e20;
    float _e22 = c_11.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            float3 _e33 = c_11.y;
            const bool _e34 = occluded((x_16 + (ng_1 * eps)), _e33);
            local_42 = _e34;
        } else {
            local_42 = false;
        }
        bool _e36 = local_42;
        local_41 = _e36;
    } else {
        local_41 = true;
    }
    bool _e38 = local_41;
    if (_e38) {
        Connection _e39 = c_11;
        const Connection connection = _e39;
        return connection;
    }
    float3 _e41 = c_11.y;
    float3 v_19 = (x_16 - _e41);
    float d2_15 = dot(v_19, v_19);
    const float3 _e48 = light_intensity(l_8, (v_19 / (sqrt(d2_15)).xxx));
    float _e50 = c_11.cos_x;
    const float _e51 = connection_factor(_e50, d2_15, rt2_6, w_res);
    c_11.e = (_e48 * _e51);
    Connection _e53 = c_11;
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

Connection connect_traced(uint li, float3 x_17, float3 n_16, float3 ng_2, float s_1, float w_res_1, float u1_3, float u2_3, float eps_1, bool trace_2)
{
    GpuLight _e12 = ConstructGpuLight(asfloat(lights.Load3(li*64+0)), asuint(lights.Load(li*64+12)), asfloat(lights.Load3(li*64+16)), asfloat(lights.Load(li*64+28)), asfloat(lights.Load3(li*64+32)), asfloat(lights.Load(li*64+44)), asfloat(lights.Load3(li*64+48)), asuint(lights.Load(li*64+60)));
    float _e15 = asfloat(r2_4.Load(li*4));
    float _e19 = asfloat(rt2_7.Load(li*4));
    const Connection _e21 = connect_record(_e12, x_17, n_16, ng_2, (s_1 * _e15), (s_1 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_2);
    const Connection connection_2 = _e21;
    return connection_2;
}

Connection connect(uint li_1, float3 x_18, float3 n_17, float3 ng_3, float s_2, float w_res_2, float u1_4, float u2_4, float eps_2)
{
    const Connection _e10 = connect_traced(li_1, x_18, n_17, ng_3, s_2, w_res_2, u1_4, u2_4, eps_2, true);
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

float light_range_scale(uint li_2, float3 x_19, float3 r_10, float4 rl_8)
{
    GpuLightCone c_17 = ConstructGpuLightCone(asfloat(light_cones.Load3(li_2*48+0)), asfloat(light_cones.Load(li_2*48+12)), asfloat(light_cones.Load3(li_2*48+16)), asfloat(light_cones.Load(li_2*48+28)), asfloat(light_cones.Load(li_2*48+32)), asfloat(light_cones.Load(li_2*48+36)), asuint(light_cones.Load(li_2*48+40)), asuint(light_cones.Load(li_2*48+44)));
    const float _e9 = range_scale_toward(rl_8, c_17.center_, c_17.radius, x_19, r_10);
    return _e9;
}

float light_weight(uint li_3, float3 x_20, float3 n_18, float3 r_11, float4 lobe_7, float4 rl_9)
{
    GpuLightCone c_18 = ConstructGpuLightCone(asfloat(light_cones.Load3(li_3*48+0)), asfloat(light_cones.Load(li_3*48+12)), asfloat(light_cones.Load3(li_3*48+16)), asfloat(light_cones.Load(li_3*48+28)), asfloat(light_cones.Load(li_3*48+32)), asfloat(light_cones.Load(li_3*48+36)), asuint(light_cones.Load(li_3*48+40)), asuint(light_cones.Load(li_3*48+44)));
    const float _e15 = light_range_scale(li_3, x_20, r_11, rl_9);
    float _e18 = asfloat(rt2_7.Load(li_3*4));
    const float _e20 = cone_weight(c_18.center_, c_18.radius, c_18.phi, c_18.axis, c_18.cos_o, c_18.cos_e, (_e15 * _e18), x_20, n_18, r_11, lobe_7);
    return _e20;
}

float select_pdf(uint li_4, float3 x_21, float3 n_19, float3 r_12, float4 lobe_8, float4 rl_10, uint nee, bool in_range_1)
{
    const float _e8 = light_weight(li_4, x_21, n_19, r_12, lobe_8, rl_10);
    const float _e11 = weighted_select_pdf(_e8, asfloat(nee), in_range_1, K);
    return _e11;
}

float light_pdf_selected(uint li_5, float3 x_22, float3 r_13, float4 rl_11, float3 y_2, float sel)
{
    GpuLight l_9 = ConstructGpuLight(asfloat(lights.Load3(li_5*64+0)), asuint(lights.Load(li_5*64+12)), asfloat(lights.Load3(li_5*64+16)), asfloat(lights.Load(li_5*64+28)), asfloat(lights.Load3(li_5*64+32)), asfloat(lights.Load(li_5*64+44)), asfloat(lights.Load3(li_5*64+48)), asuint(lights.Load(li_5*64+60)));
    float3 v_20 = (x_22 - y_2);
    float d2_16 = dot(v_20, v_20);
    const float3 _e11 = light_normal(l_9);
    float cos_y_1 = ((d2_16 > 0.0) ? dot(_e11, (v_20 / (sqrt(d2_16)).xxx)) : 0.0);
    const float _e20 = light_range_scale(li_5, x_22, r_13, rl_11);
    float _e23 = asfloat(rt2_7.Load(li_5*4));
    const float _e25 = light_area(l_9);
    const float _e26 = light_strategy_pdf(sel, (_e20 * _e23), d2_16, _e25, cos_y_1);
    return _e26;
}

float light_pdf(uint li_6, float3 x_23, float3 n_20, float3 r_14, float4 lobe_9, float4 rl_12, float3 y_3, uint nee_1, bool in_range_2)
{
    const float _e9 = select_pdf(li_6, x_23, n_20, r_14, lobe_9, rl_12, nee_1, in_range_2);
    const float _e10 = light_pdf_selected(li_6, x_23, r_14, rl_12, y_3, _e9);
    return _e10;
}

WeightedPicks weighted_picks(uint h_5)
{
    WeightedPicks picks = (WeightedPicks)0;

    picks.w_sum = 0.0;
    picks.n = 0u;
    picks.h = h_5;
    WeightedPicks _e7 = picks;
    const WeightedPicks weightedpicks = _e7;
    return weightedpicks;
}

void weighted_offer(inout WeightedPicks picks_1, uint li_7, float w_10)
{
    uint h_6 = (uint)0;
    uint s_3 = 0u;

    uint _e4 = picks_1.n;
    picks_1.n = (_e4 + 1u);
    if ((w_10 > 0.0)) {
        float _e10 = picks_1.w_sum;
        picks_1.w_sum = (_e10 + w_10);
        uint _e13 = picks_1.h;
        h_6 = _e13;
        uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
        bool loop_init_2 = true;
        while(true) {
            if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
            loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
            if (!loop_init_2) {
                uint _e40 = s_3;
                s_3 = (_e40 + 1u);
            }
            loop_init_2 = false;
            uint _e17 = s_3;
            if ((_e17 < K)) {
            } else {
                break;
            }
            {
                float _e21 = picks_1.w_sum;
                uint _e23 = s_3;
                float _e25 = picks_1.threshold[min(uint(_e23), 7u)];
                if ((_e21 > _e25)) {
                    uint _e28 = s_3;
                    picks_1.light[min(uint(_e28), 7u)] = li_7;
                    uint _e31 = s_3;
                    picks_1.w[min(uint(_e31), 7u)] = w_10;
                    uint _e34 = s_3;
                    float _e37 = picks_1.w_sum;
                    const float _e38 = next_threshold(_e37, h_6);
                    picks_1.threshold[min(uint(_e34), 7u)] = _e38;
                }
            }
        }
        uint _e43 = h_6;
        picks_1.h = _e43;
        return;
    } else {
        return;
    }
}

WeightedPicks bsh_weighted_collect(float3 x_24, float3 n_21, float3 r_15, float4 lobe_10, float4 rl_13, uint h0_)
{
    WeightedPicks picks_2 = (WeightedPicks)0;
    BshCursor cur = (BshCursor)0;
    uint b_6 = (uint)0;

    const WeightedPicks _e6 = weighted_picks(h0_);
    picks_2 = _e6;
    const BshCursor _e8 = bsh_cursor(x_24, r_15, rl_13);
    cur = _e8;
    const uint _e10 = bsh_cursor_next(cur, x_24, r_15, rl_13);
    b_6 = _e10;
    uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_3) {
            const uint _e21 = bsh_cursor_next(cur, x_24, r_15, rl_13);
            b_6 = _e21;
        }
        loop_init_3 = false;
        uint _e12 = b_6;
        if ((_e12 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e16 = b_6;
            uint li_9 = asuint(bsh_nodes.Load(24+_e16*32));
            const float _e20 = light_weight(li_9, x_24, n_21, r_15, lobe_10, rl_13);
            weighted_offer(picks_2, li_9, _e20);
        }
    }
    WeightedPicks _e22 = picks_2;
    const WeightedPicks weightedpicks_1 = _e22;
    return weightedpicks_1;
}

float3 shade_pick(uint li_8, float3 x_25, float3 n_22, float3 ng_4, GpuMaterial m, float3 wo_1, float3 r_16, float4 lobe_11, float4 rl_14, float w_11, uint nee_2, float u1_5, float u2_5)
{
    float mis = 1.0;

    const float _e13 = light_range_scale(li_8, x_25, r_16, rl_14);
    float _e16 = params.eps;
    const Connection _e17 = connect(li_8, x_25, n_22, ng_4, _e13, w_11, u1_5, u2_5, _e16);
    if ((_e17.cos_x <= 0.0)) {
        return (0.0).xxx;
    }
    float3 l_10 = normalize((_e17.y - x_25));
    GpuLight _e30 = ConstructGpuLight(asfloat(lights.Load3(li_8*64+0)), asuint(lights.Load(li_8*64+12)), asfloat(lights.Load3(li_8*64+16)), asfloat(lights.Load(li_8*64+28)), asfloat(lights.Load3(li_8*64+32)), asfloat(lights.Load(li_8*64+44)), asfloat(lights.Load3(li_8*64+48)), asuint(lights.Load(li_8*64+60)));
    const float _e31 = light_area(_e30);
    if ((_e31 > 0.0)) {
        const float _e36 = light_pdf(li_8, x_25, n_22, r_16, lobe_11, rl_14, _e17.y, nee_2, true);
        const float _e38 = specular_probability(lobe_11);
        const float _e39 = bsdf_pdf(n_22, wo_1, l_10, m.alpha, _e38);
        const float _e40 = mis_weight(_e36, _e39);
        mis = _e40;
    }
    const float3 _e46 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, n_22, wo_1, l_10);
    float _e49 = mis;
    return ((_e46 * _e17.e) * _e49);
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
    uint s = 0u;

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
    float3 x_26 = vtx.position;
    float3 n_26 = vtx.normal;
    float3 ng_5 = vtx.gnormal;
    GpuMaterial m_2 = ConstructGpuMaterial(asfloat(materials.Load3(vtx.material*48+0)), asfloat(materials.Load(vtx.material*48+12)), asfloat(materials.Load3(vtx.material*48+16)), asfloat(materials.Load(vtx.material*48+28)), asfloat(materials.Load3(vtx.material*48+32)), asfloat(materials.Load(vtx.material*48+44)));
    float3 wo_2 = vtx.wo;
    const float3 _e23 = mirror_dir(n_26, wo_2);
    const float4 _e30 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, dot(n_26, wo_2));
    const float4 _e31 = range_lobe(_e30);
    uint _e34 = params.seed;
    uint _e37 = params.frame;
    const uint _e38 = point_stream(_e34, i_5, _e37);
    const uint _e39 = pick_stream(_e38);
    h = _e39;
    uint _e44 = h;
    const WeightedPicks _e45 = bsh_weighted_collect(x_26, n_26, _e23, _e30, _e31, _e44);
    h = _e45.h;
    float w_sum_3 = _e45.w_sum;
    candidates.Store(i_5*4, asuint(asuint(w_sum_3)));
    if ((w_sum_3 > 0.0)) {
        uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
        bool loop_init_4 = true;
        while(true) {
            if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
            loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
            if (!loop_init_4) {
                uint _e79 = s;
                s = (_e79 + 1u);
            }
            loop_init_4 = false;
            uint _e55 = s;
            if ((_e55 < K)) {
            } else {
                break;
            }
            {
                uint _e58 = h;
                const uint _e59 = pcg_hash(_e58);
                h = _e59;
                uint _e60 = h;
                const float _e61 = xi_from_bits(_e60);
                uint _e62 = h;
                const uint _e63 = pcg_hash(_e62);
                h = _e63;
                float3 _e64 = sum;
                uint _e66 = s;
                uint _e69 = s;
                const float _e72 = weighted_pick_weight(w_sum_3, _e45.w[min(uint(_e69), 7u)], K);
                uint _e74 = h;
                const float _e75 = xi_from_bits(_e74);
                const float3 _e76 = shade_pick(_e45.light[min(uint(_e66), 7u)], x_26, n_26, ng_5, m_2, wo_2, _e23, _e30, _e31, _e72, asuint(w_sum_3), _e61, _e75);
                sum = (_e64 + _e76);
            }
        }
    }
    float3 _e82 = sum;
    float3 add = (vtx.weight * _e82);
    const bool _e84 = finite3_(add);
    if (_e84) {
        float4 _e87 = asfloat(radiance.Load4(i_5*16));
        radiance.Store4(i_5*16, asuint((_e87 + float4(add, 0.0))));
        return;
    } else {
        return;
    }
}
