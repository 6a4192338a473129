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

struct Picks {
    uint light[8];
    uint n;
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

ByteAddressBuffer slc_table : register(t0, space1);
ByteAddressBuffer geo_nodes : register(t7);
ByteAddressBuffer geo_tris : register(t8);
ByteAddressBuffer bsh_nodes : register(t6);
ByteAddressBuffer lights : register(t3);
ByteAddressBuffer r2_3 : register(t5);
ByteAddressBuffer rt2_3 : register(t4);
cbuffer params : register(b0) { ShadeParams params; }
ByteAddressBuffer points : register(t1);
ByteAddressBuffer normals : register(t2);
RWByteAddressBuffer irradiance : register(u9);

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

bool sphere_contains_point(float3 c, float r, float3 x_2)
{
    float3 v_2 = (x_2 - c);
    return (dot(v_2, v_2) <= (r * r));
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

float connection_cosine(float3 x_3, float3 y, float3 n, float3 ng, float r2_1)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;

    float3 v_3 = (x_3 - y);
    float d2_6 = dot(v_3, v_3);
    const bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local = !((d2_6 > 0.0));
    } else {
        local = true;
    }
    bool _e16 = local;
    if (_e16) {
        return 0.0;
    }
    float3 w_4 = (v_3 / (sqrt(d2_6)).xxx);
    float cos_x_1 = -(dot(n, w_4));
    if (!(!((cos_x_1 > 0.0)))) {
        local_1 = !((dot(ng, w_4) < 0.0));
    } else {
        local_1 = true;
    }
    bool _e34 = local_1;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float spot_falloff(float cos_theta, float cos_outer, float cos_inner, float shape)
{
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t_1 = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return ((shape > 0.5) ? (t_1 * t_1) : ((t_1 * t_1) * (3.0 - (2.0 * t_1))));
}

float atan_portable(float x_4)
{
    float base = 0.0;
    float t = (float)0;

    float a_8 = abs(x_4);
    t = a_8;
    if ((a_8 > 2.4142137)) {
        base = 1.5707964;
        t = (-1.0 / a_8);
    } else {
        if ((a_8 > 0.41421357)) {
            base = 0.7853982;
            t = ((a_8 - 1.0) / (a_8 + 1.0));
        }
    }
    float _e18 = t;
    float _e19 = t;
    float z = (_e18 * _e19);
    float _e21 = base;
    float _e33 = t;
    float _e35 = t;
    float r_8 = (_e21 + (((((((((0.080537446 * z) - 0.13877685) * z) + 0.19977711) * z) - 0.3333295) * z) * _e33) + _e35));
    return ((x_4 < 0.0) ? -(r_8) : r_8);
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

float ies_fold_c(float c_1, float h_first, float h_last)
{
    float a_2 = (float)0;

    a_2 = (c_1 - (360.0 * floor((c_1 / 360.0))));
    if ((h_last <= 0.0)) {
        return 0.0;
    }
    if ((h_last <= 90.0)) {
        float _e15 = a_2;
        if ((_e15 > 180.0)) {
            float _e18 = a_2;
            a_2 = (360.0 - _e18);
        }
        float _e21 = a_2;
        if ((_e21 > 90.0)) {
            float _e24 = a_2;
            a_2 = (180.0 - _e24);
        }
        float _e27 = a_2;
        return _e27;
    }
    if ((h_first >= 90.0)) {
        float _e30 = a_2;
        if ((_e30 < 90.0)) {
            float _e33 = a_2;
            a_2 = (180.0 - _e33);
        } else {
            float _e36 = a_2;
            if ((_e36 > 270.0)) {
                float _e39 = a_2;
                a_2 = (540.0 - _e39);
            }
        }
        float _e42 = a_2;
        return _e42;
    }
    if ((h_last <= 180.0)) {
        float _e45 = a_2;
        if ((_e45 > 180.0)) {
            float _e48 = a_2;
            a_2 = (360.0 - _e48);
        }
        float _e51 = a_2;
        return _e51;
    }
    float _e52 = a_2;
    return _e52;
}

uint ies_segment(uint tab_1, uint start, uint n_1, float x_6)
{
    uint lo = 0u;
    uint hi = (uint)0;

    if ((n_1 < 2u)) {
        return 0u;
    }
    hi = (n_1 - 1u);
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

float ies_candela(uint tab_2, uint base_1, float gamma, float c_2)
{
    bool local_2 = (bool)0;

    const float _e4 = at(tab_2, base_1);
    const uint _e5 = to_u32_(_e4);
    const float _e8 = at(tab_2, (base_1 + 1u));
    const uint _e9 = to_u32_(_e8);
    uint v0_ = (base_1 + 2u);
    uint h0_ = (v0_ + _e5);
    uint c0_ = (h0_ + _e9);
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
    const float _e27 = at(tab_2, h0_);
    const float _e31 = at(tab_2, ((h0_ + _e9) - 1u));
    const float _e32 = ies_fold_c(c_2, _e27, _e31);
    const uint _e33 = ies_segment(tab_2, v0_, _e5, gamma);
    const uint _e34 = ies_segment(tab_2, h0_, _e9, _e32);
    uint iv1_ = min((_e33 + 1u), (_e5 - 1u));
    uint ih1_ = min((_e34 + 1u), (_e9 - 1u));
    const float _e46 = at(tab_2, (v0_ + _e33));
    const float _e48 = at(tab_2, (v0_ + iv1_));
    const float _e49 = ies_lerp_t(_e46, _e48, gamma);
    const float _e51 = at(tab_2, (h0_ + _e34));
    const float _e53 = at(tab_2, (h0_ + ih1_));
    const float _e54 = ies_lerp_t(_e51, _e53, _e32);
    const float _e58 = at(tab_2, ((c0_ + (_e34 * _e5)) + _e33));
    const float _e65 = at(tab_2, ((c0_ + (_e34 * _e5)) + iv1_));
    float a_9 = ((_e58 * (1.0 - _e49)) + (_e65 * _e49));
    const float _e71 = at(tab_2, ((c0_ + (ih1_ * _e5)) + _e33));
    const float _e78 = at(tab_2, ((c0_ + (ih1_ * _e5)) + iv1_));
    float b_5 = ((_e71 * (1.0 - _e49)) + (_e78 * _e49));
    return ((a_9 * (1.0 - _e54)) + (b_5 * _e54));
}

float ies_candela_dir(uint tab_3, uint base_2, float wn, float wr, float ws)
{
    const float _e9 = atan2_portable(sqrt(((wr * wr) + (ws * ws))), wn);
    float gamma_1 = degrees(_e9);
    bool on_axis = ((abs(wr) + abs(ws)) <= 0.0);
    const float _e16 = atan2_portable(ws, wr);
    float c_7 = (on_axis ? 0.0 : degrees(_e16));
    const float _e20 = ies_candela(tab_3, base_2, gamma_1, c_7);
    return _e20;
}

float ies_light_candela(uint tab_4, uint base_3, float3 nadir, float3 reference, float3 w_1)
{
    float3 side = cross(reference, nadir);
    const float _e9 = ies_candela_dir(tab_4, base_3, dot(w_1, nadir), dot(w_1, reference), dot(w_1, side));
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

float bsh_reach_bound(BshNode node_2, float w_2)
{
    const float _e5 = bsh_range_bound(node_2);
    return (node_2.extent + ((w_2 * 1.001) * _e5));
}

uint mul_hi_u32_(uint a_3, uint b_2)
{
    uint a_lo = (a_3 & 65535u);
    uint a_hi = (a_3 >> 16u);
    uint b_lo = (b_2 & 65535u);
    uint b_hi = (b_2 >> 16u);
    uint ll = (a_lo * b_lo);
    uint lh = (a_lo * b_hi);
    uint hl = (a_hi * b_lo);
    uint hh = (a_hi * b_hi);
    uint mid_1 = (((ll >> 16u) + (lh & 65535u)) + (hl & 65535u));
    return (((hh + (lh >> 16u)) + (hl >> 16u)) + (mid_1 >> 16u));
}

uint uniform_index(uint n_2, uint hi_1, uint lo_1)
{
    const uint _e3 = mul_lo_u32_(hi_1, n_2);
    const uint _e4 = mul_hi_u32_(hi_1, n_2);
    const uint _e5 = mul_hi_u32_(lo_1, n_2);
    if ((_e3 > (4294967295u - _e5))) {
        return (_e4 + 1u);
    }
    return _e4;
}

uint reservoir_slot(uint n_3, uint k, uint hi_2, uint lo_2)
{
    if ((n_3 <= k)) {
        return (n_3 - 1u);
    }
    const uint _e7 = uniform_index(n_3, hi_2, lo_2);
    if ((_e7 < k)) {
        return _e7;
    }
    return k;
}

bool reservoir_takes(uint n_4)
{
    return (n_4 < RESERVOIR_FULL);
}

float reservoir_weight(uint n_5, uint k_1)
{
    const float _e2 = to_f32_(n_5);
    const float _e3 = to_f32_(k_1);
    return max((_e2 / _e3), 1.0);
}

float cone_cos_of(float3 v, float d2_4, float a_4, float3 d)
{
    bool local_3 = (bool)0;
    bool local_4 = (bool)0;

    float vd = dot(v, d);
    float h2_ = (d2_4 - (a_4 * a_4));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_4 = ((vd * vd) >= h2_);
        } else {
            local_4 = false;
        }
        bool _e19 = local_4;
        local_3 = _e19;
    } else {
        local_3 = true;
    }
    bool _e21 = local_3;
    if (_e21) {
        return 1.0;
    }
    float3 c_8 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_8, c_8)) * a_4)) / d2_4), 1.0);
}

float cone_cos_toward(float3 center_, float radius, float3 p, float3 d_1)
{
    float3 v_4 = (center_ - p);
    const float _e6 = cone_cos_of(v_4, dot(v_4, v_4), radius, d_1);
    return _e6;
}

float range_scale_at(float4 rl, float cos_t)
{
    float t_2 = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t_2 * t_2))), 1.0, (rl.w * rl.w));
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

float shadow_margin(float len)
{
    return (0.0001 * len);
}

float ray_inverse(float x_8)
{
    return (1.0 / ((abs(x_8) < 1e-30) ? 1e-30 : x_8));
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
    float3 lo_3 = min(t0_, t1_);
    float3 hi_3 = max(t0_, t1_);
    float t_in = max(max(lo_3.x, lo_3.y), max(lo_3.z, 0.0));
    float t_out = min(min(hi_3.x, hi_3.y), min(hi_3.z, t_max));
    if ((t_in <= t_out)) {
        return t_in;
    }
    return -1.0;
}

float ray_triangle(float3 o_1, float3 d_3, float3 a_5, float3 b_3, float3 c_3, float t_min, float t_max_1)
{
    bool local_5 = (bool)0;
    bool local_6 = (bool)0;
    bool local_7 = (bool)0;

    float3 e1_ = (b_3 - a_5);
    float3 e2_ = (c_3 - a_5);
    float3 p_2 = cross(d_3, e2_);
    float det = dot(e1_, p_2);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv = (1.0 / det);
    float3 s_3 = (o_1 - a_5);
    float u_2 = (dot(s_3, p_2) * inv);
    if (!((u_2 < 0.0))) {
        local_5 = (u_2 > 1.0);
    } else {
        local_5 = true;
    }
    bool _e28 = local_5;
    if (_e28) {
        return -1.0;
    }
    float3 q = cross(s_3, e1_);
    float v_5 = (dot(d_3, q) * inv);
    if (!((v_5 < 0.0))) {
        local_6 = ((u_2 + v_5) > 1.0);
    } else {
        local_6 = true;
    }
    bool _e42 = local_6;
    if (_e42) {
        return -1.0;
    }
    float t_3 = (dot(e2_, q) * inv);
    if ((t_3 > t_min)) {
        local_7 = (t_3 < t_max_1);
    } else {
        local_7 = false;
    }
    bool _e51 = local_7;
    if (_e51) {
        return t_3;
    }
    return -1.0;
}

float3 light_intensity(GpuLight l, float3 w_3)
{
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            const float _e11 = spot_falloff(dot(l.p1_, w_3), l.a, l.b, l.p2_.x);
            return (l.intensity * _e11);
        }
        case 2u: {
            const float _e18 = ies_light_candela(0u, l.ies_base, l.p1_, l.p2_, w_3);
            return (l.intensity * _e18);
        }
        default: {
            return (0.0).xxx;
        }
    }
}

float3 light_point(GpuLight l_1, float u1_, float u2_)
{
    return l_1.p0_;
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
        GpuGeoNode n_9 = ConstructGpuGeoNode(asfloat(geo_nodes.Load3(_e21*32+0)), asuint(geo_nodes.Load(_e21*32+12)), asfloat(geo_nodes.Load3(_e21*32+16)), asuint(geo_nodes.Load(_e21*32+28)));
        float _e27 = hit.t;
        const float _e28 = ray_aabb(o_2, _e14, n_9.bmin, n_9.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_9.count > 0u)) {
                i_1 = n_9.first;
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
                    if ((_e36 < (n_9.first + n_9.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i_1;
                        GpuTriangle t_4 = ConstructGpuTriangle(asfloat(geo_tris.Load3(_e42*48+0)), asuint(geo_tris.Load(_e42*48+12)), asfloat(geo_tris.Load3(_e42*48+16)), asuint(geo_tris.Load(_e42*48+28)), asfloat(geo_tris.Load3(_e42*48+32)), asuint(geo_tris.Load(_e42*48+44)));
                        float _e49 = hit.t;
                        const float _e50 = ray_triangle(o_2, d_4, t_4.v0_, t_4.v1_, t_4.v2_, t_min_1, _e49);
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
                    stack[min(uint(_e63), 63u)] = (n_9.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node_3 = n_9.first;
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

bool occluded(float3 a_6, float3 b_4)
{
    float3 dv = (b_4 - a_6);
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

float bsh_inner_scale(float a_7, float3 v_1, float d2_5, float3 r_2, float4 rl_2)
{
    const float _e5 = cone_cos_of(v_1, d2_5, a_7, r_2);
    const float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_4, float3 x_9, float3 r_3, float4 rl_3)
{
    bool local_8 = (bool)0;
    bool local_9 = (bool)0;

    const bool _e6 = sphere_contains_point(node_4.center_, node_4.radius, x_9);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        const bool _e20 = sphere_contains_point(node_4.center_, (node_4.radius * (rl_3.w * 1.0001)), x_9);
        local_8 = !(_e20);
    } else {
        local_8 = true;
    }
    bool _e23 = local_8;
    if (_e23) {
        return false;
    }
    float3 v_6 = (x_9 - node_4.center_);
    float d2_7 = dot(v_6, v_6);
    const float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if ((d2_7 > (_e29 * _e29))) {
        return false;
    }
    if ((node_4.child == BSH_NONE)) {
        const float _e38 = range_scale_toward(rl_3, node_4.center_, node_4.extent, x_9, r_3);
        const float _e41 = bsh_scaled_radius(node_4, sqrt(_e38));
        const bool _e42 = sphere_contains_point(node_4.center_, _e41, x_9);
        return _e42;
    }
    const float _e45 = bsh_inner_scale(node_4.extent, -(v_6), d2_7, r_3, rl_3);
    float s_c = (_e45 * 1.001);
    const float _e50 = bsh_range_bound(node_4);
    float reach = (node_4.extent + (sqrt(s_c) * _e50));
    if ((d2_7 <= ((node_4.radius * node_4.radius) * s_c))) {
        local_9 = (d2_7 <= (reach * reach));
    } else {
        local_9 = false;
    }
    bool _e63 = local_9;
    return _e63;
}

uint bsh_next_leaf_lobe(uint nodes_3, uint start_1, float3 x_10, float3 r_4, float4 rl_4)
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
            const bool _e11 = bsh_reaches(_e10, x_10, r_4, rl_4);
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

BshCursor bsh_cursor(float3 x_11, float3 r_5, float4 rl_5)
{
    BshCursor c_4 = (BshCursor)0;

    c_4.i = 0u;
    c_4.end = 0u;
    const uint _e10 = bsh_first(BSH);
    c_4.next = _e10;
    c_4.cone = (0.0).xx;
    BshCursor _e14 = c_4;
    const BshCursor bshcursor = _e14;
    return bshcursor;
}

uint bsh_cursor_next(inout BshCursor c_5, float3 x_12, float3 r_6, float4 rl_6)
{
    uint _e6 = c_5.next;
    const uint _e7 = bsh_next_leaf_lobe(BSH, _e6, x_12, r_6, rl_6);
    if ((_e7 != BSH_NONE)) {
        uint _e14 = asuint(bsh_nodes.Load(20+_e7*32));
        c_5.next = _e14;
    }
    return _e7;
}

void reservoir_offer(inout Picks picks, inout uint h_1, uint light)
{
    uint _e4 = picks.n;
    const bool _e5 = reservoir_takes(_e4);
    if (_e5) {
        uint _e7 = picks.n;
        picks.n = (_e7 + 1u);
        uint _e10 = h_1;
        const uint _e11 = pcg_hash(_e10);
        h_1 = _e11;
        uint hi_4 = h_1;
        uint _e13 = h_1;
        const uint _e14 = pcg_hash(_e13);
        h_1 = _e14;
        uint _e16 = picks.n;
        uint _e18 = h_1;
        const uint _e19 = reservoir_slot(_e16, K, hi_4, _e18);
        if ((_e19 < K)) {
            picks.light[min(uint(_e19), 7u)] = light;
            return;
        } else {
            return;
        }
    } else {
        return;
    }
}

Picks bsh_collect(float3 x_13, float3 r_7, float4 rl_7, uint seed_1)
{
    Picks picks_1 = (Picks)0;
    uint h_2 = (uint)0;
    BshCursor cur = (BshCursor)0;
    uint i_4 = (uint)0;

    picks_1.n = 0u;
    h_2 = seed_1;
    const BshCursor _e8 = bsh_cursor(x_13, r_7, rl_7);
    cur = _e8;
    const uint _e10 = bsh_cursor_next(cur, x_13, r_7, rl_7);
    i_4 = _e10;
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_1) {
            const uint _e20 = bsh_cursor_next(cur, x_13, r_7, rl_7);
            i_4 = _e20;
        }
        loop_init_1 = false;
        uint _e12 = i_4;
        if ((_e12 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e16 = i_4;
            uint _e19 = asuint(bsh_nodes.Load(24+_e16*32));
            reservoir_offer(picks_1, h_2, _e19);
        }
    }
    Picks _e21 = picks_1;
    const Picks picks_2 = _e21;
    return picks_2;
}

Connection connect_record(GpuLight l_2, float3 x_14, float3 n_6, float3 ng_1, float r2_2, float rt2_2, float w_res, float u1_1, float u2_1, float eps, bool trace_1)
{
    Connection c_6 = (Connection)0;
    bool local_10 = (bool)0;
    bool local_11 = (bool)0;

    c_6.e = (0.0).xxx;
    const float3 _e16 = light_point(l_2, u1_1, u2_1);
    c_6.y = _e16;
    float3 _e19 = c_6.y;
    const float _e20 = connection_cosine(x_14, _e19, n_6, ng_1, r2_2);
    c_6.cos_x = _e20;
    float _e22 = c_6.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            float3 _e33 = c_6.y;
            const bool _e34 = occluded((x_14 + (ng_1 * eps)), _e33);
            local_11 = _e34;
        } else {
            local_11 = false;
        }
        bool _e36 = local_11;
        local_10 = _e36;
    } else {
        local_10 = true;
    }
    bool _e38 = local_10;
    if (_e38) {
        Connection _e39 = c_6;
        const Connection connection = _e39;
        return connection;
    }
    float3 _e41 = c_6.y;
    float3 v_7 = (x_14 - _e41);
    float d2_8 = dot(v_7, v_7);
    const float3 _e48 = light_intensity(l_2, (v_7 / (sqrt(d2_8)).xxx));
    float _e50 = c_6.cos_x;
    const float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
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

Connection connect_traced(uint li, float3 x_15, float3 n_7, float3 ng_2, float s_1, float w_res_1, float u1_2, float u2_2, float eps_1, bool trace_2)
{
    GpuLight _e12 = ConstructGpuLight(asfloat(lights.Load3(li*64+0)), asuint(lights.Load(li*64+12)), asfloat(lights.Load3(li*64+16)), asfloat(lights.Load(li*64+28)), asfloat(lights.Load3(li*64+32)), asfloat(lights.Load(li*64+44)), asfloat(lights.Load3(li*64+48)), asuint(lights.Load(li*64+60)));
    float _e15 = asfloat(r2_3.Load(li*4));
    float _e19 = asfloat(rt2_3.Load(li*4));
    const Connection _e21 = connect_record(_e12, x_15, n_7, ng_2, (s_1 * _e15), (s_1 * _e19), w_res_1, u1_2, u2_2, eps_1, trace_2);
    const Connection connection_2 = _e21;
    return connection_2;
}

Connection connect(uint li_1, float3 x_16, float3 n_8, float3 ng_3, float s_2, float w_res_2, float u1_3, float u2_3, float eps_2)
{
    const Connection _e10 = connect_traced(li_1, x_16, n_8, ng_3, s_2, w_res_2, u1_3, u2_3, eps_2, true);
    const Connection connection_3 = _e10;
    return connection_3;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    uint h = (uint)0;
    float3 e = (0.0).xxx;
    uint s = 0u;

    uint i_5 = gid.x;
    uint _e4 = params.point_count;
    if ((i_5 >= _e4)) {
        return;
    }
    float4 p_3 = asfloat(points.Load4(i_5*16));
    if ((p_3.w <= 0.0)) {
        irradiance.Store4(i_5*16, asuint((0.0).xxxx));
        return;
    }
    float3 x_17 = p_3.xyz;
    float4 _e19 = asfloat(normals.Load4(i_5*16));
    float3 n_10 = _e19.xyz;
    uint _e23 = params.seed;
    uint _e26 = params.frame;
    const uint _e27 = point_stream(_e23, i_5, _e26);
    const Picks _e33 = bsh_collect(x_17, x_17, float4(1.0, 0.0, 1.0, 1.0), _e27);
    const float _e36 = reservoir_weight(_e33.n, K);
    const uint _e37 = pick_stream(_e27);
    h = _e37;
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e69 = s;
            s = (_e69 + 1u);
        }
        loop_init_2 = false;
        uint _e44 = s;
        if ((_e44 < min(_e33.n, K))) {
        } else {
            break;
        }
        {
            uint _e49 = h;
            const uint _e50 = pcg_hash(_e49);
            h = _e50;
            uint _e51 = h;
            const float _e52 = xi_from_bits(_e51);
            uint _e53 = h;
            const uint _e54 = pcg_hash(_e53);
            h = _e54;
            float3 _e55 = e;
            uint _e57 = s;
            uint _e60 = h;
            const float _e61 = xi_from_bits(_e60);
            float _e64 = params.eps;
            const Connection _e65 = connect(_e33.light[min(uint(_e57), 7u)], x_17, n_10, n_10, 1.0, _e36, _e52, _e61, _e64);
            e = (_e55 + _e65.e);
        }
    }
    float3 _e73 = e;
    irradiance.Store4(i_5*16, asuint(float4(_e73, float(_e33.n))));
    return;
}
