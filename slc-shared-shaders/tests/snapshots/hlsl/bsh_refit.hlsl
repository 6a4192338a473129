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
    float pad;
    float3 weight;
    float pad1_;
    float3 gnormal;
    float pad2_;
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

struct FrameParams {
    uint light_count;
    uint seed;
    uint frame;
    uint pad;
};

struct RefitParams {
    uint first;
    uint count;
    uint pad0_;
    uint pad1_;
};

struct VplParams {
    uint width;
    uint height;
    uint lights_per_subset;
    float min_d2_;
    float near_r2_;
    uint near_blocks;
    uint pad0_;
    uint pad1_;
};

struct GpuNearBox {
    float3 lo;
    float pad0_;
    float3 hi;
    float pad1_;
};

struct GpuVplRecord {
    float3 position;
    float pad0_;
    float3 normal;
    float pad1_;
    float3 flux;
    float pad2_;
};

struct PackParams {
    uint count;
    uint size;
    uint per_subset;
    uint mode;
    float exposure;
    float error_bound;
    float scale;
    uint slc;
    float fixed_r2_;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};

struct ImageParams {
    float3 eye;
    uint width;
    uint height;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};

struct GpuVertex {
    float3 position;
    uint material;
    float3 normal;
    uint pad0_;
    float3 geo_normal;
    uint pad1_;
};

struct GpuMaterial {
    float3 albedo;
    uint pad0_;
    float3 emission;
    uint pad1_;
};

struct MapParams {
    float4 c0_;
    float4 c1_;
    float4 c2_;
    float4 c3_;
    GpuLight light;
    float3 origin;
    uint mode;
    float3 axis;
    uint size;
    float3 right;
    float extent;
    float3 up;
    float texel;
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
    uint pad;
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
static const uint BSH_NONE = 4294967295u;
static const uint RESERVOIR_FULL = 4294967295u;
static const uint LIGHT_BVH_LEAF = 4294967295u;
static const float ONE_MINUS_EPSILON = 0.99999994;
static const float F32_MAX = 3.4028235e38;
static const float DEPTH_NONE = 1e30;
static const float DEPTH_SIGMA = 0.05;
static const float COVER_WEIGHT = 0.1;
static const uint NEAR_BLOCK = 64u;
static const uint ROULETTE_DEPTH = 2u;
static const uint BSH = 0u;

ByteAddressBuffer slc_table : register(t0, space1);
cbuffer params : register(b0) { RefitParams params; }
ByteAddressBuffer order : register(t1);
ByteAddressBuffer extent_5 : register(t2);
ByteAddressBuffer r2_10 : register(t3);
RWByteAddressBuffer bsh_nodes : register(u4);

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

uint reverse_bits(uint x_2)
{
    uint v = (uint)0;

    v = (((x_2 >> 16u) & 65535u) | ((x_2 & 65535u) << 16u));
    uint _e11 = v;
    uint _e16 = v;
    v = (((_e11 >> 8u) & 16711935u) | ((_e16 & 16711935u) << 8u));
    uint _e22 = v;
    uint _e27 = v;
    v = (((_e22 >> 4u) & 252645135u) | ((_e27 & 252645135u) << 4u));
    uint _e33 = v;
    uint _e38 = v;
    v = (((_e33 >> 2u) & 858993459u) | ((_e38 & 858993459u) << 2u));
    uint _e44 = v;
    uint _e49 = v;
    v = (((_e44 >> 1u) & 1431655765u) | ((_e49 & 1431655765u) << 1u));
    uint _e55 = v;
    return _e55;
}

float xi_for(uint seed, uint frame, uint light)
{
    const uint _e3 = pcg_hash(seed);
    const uint _e4 = pcg_hash(_e3);
    const uint _e6 = pcg_hash((_e4 ^ light));
    const uint _e7 = reverse_bits(frame);
    const uint _e8 = add_wrap_u32_(_e6, _e7);
    const float _e9 = xi_from_bits(_e8);
    return _e9;
}

uint point_stream(uint seed_1, uint point_, uint frame_1)
{
    const uint _e3 = pcg_hash(frame_1);
    const uint _e5 = pcg_hash((point_ ^ _e3));
    const uint _e7 = pcg_hash((seed_1 ^ _e5));
    return _e7;
}

uint pick_stream(uint stream)
{
    const uint _e3 = pcg_hash((stream ^ PICK_STREAM));
    return _e3;
}

uint path_stream(uint seed_2, uint pixel, uint pass_index)
{
    const uint _e4 = add_wrap_u32_(pass_index, PICK_STREAM);
    const uint _e5 = point_stream(seed_2, pixel, _e4);
    return _e5;
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

float random_range2_(float rt2_2, float xi)
{
    return (rt2_2 / (1.0 - xi));
}

bool slc_keep(float r2_, float d2_2)
{
    return (d2_2 < r2_);
}

bool clamp_keep(float range2_, float d2_3)
{
    return (d2_3 < range2_);
}

float threshold_range2_(float intensity, float exposure, float error_bound)
{
    if ((intensity <= 0.0)) {
        return 0.0;
    }
    return (((exposure / error_bound) * intensity) / TWO_PI);
}

float intensity_measure(float3 rgb, uint mode)
{
    if ((mode == 1u)) {
        return (((rgb.x + rgb.y) + rgb.z) / 3.0);
    }
    return max(rgb.x, max(rgb.y, rgb.z));
}

float cull_radius(float r2_1)
{
    return (sqrt(r2_1) * CULL_RADIUS_SCALE);
}

float windowed_falloff(float d2_4, float range2_1)
{
    float q_2 = (d2_4 / range2_1);
    float w_9 = saturate((1.0 - (q_2 * q_2)));
    return ((w_9 * w_9) / max(d2_4, 0.0001));
}

bool sphere_contains_point(float3 c, float r, float3 x_3)
{
    float3 v_4 = (x_3 - c);
    return (dot(v_4, v_4) <= (r * r));
}

bool sphere_overlaps_sphere(float3 c1_, float r1_, float3 c2_, float r2_2)
{
    float3 v_5 = (c2_ - c1_);
    float r_3 = (r1_ + r2_2);
    return (dot(v_5, v_5) <= (r_3 * r_3));
}

float sphere_pad(float r_1, float3 c_1)
{
    return (((r_1 + max(abs(c_1.x), max(abs(c_1.y), abs(c_1.z)))) * SPHERE_PAD) + SPHERE_PAD_ABS);
}

float4 sphere_union(float3 c1_1, float r1_1, float3 c2_1, float r2_3)
{
    bool local = (bool)0;

    float3 v_6 = (c2_1 - c1_1);
    float d_4 = sqrt(dot(v_6, v_6));
    const float _e8 = sphere_pad(r1_1, c1_1);
    if ((r1_1 >= ((d_4 + r2_3) + _e8))) {
        return float4(c1_1.x, c1_1.y, c1_1.z, r1_1);
    }
    const float _e16 = sphere_pad(r2_3, c2_1);
    if ((r2_3 >= ((d_4 + r1_1) + _e16))) {
        return float4(c2_1.x, c2_1.y, c2_1.z, r2_3);
    }
    if (!((d_4 >= SPHERE_HUGE))) {
        local = ((0.5 * ((d_4 + r1_1) + r2_3)) >= SPHERE_HUGE);
    } else {
        local = true;
    }
    bool _e35 = local;
    if (_e35) {
        return float4(c1_1.x, c1_1.y, c1_1.z, SPHERE_HUGE);
    }
    if ((abs((r1_1 - r2_3)) >= d_4)) {
        if ((r1_1 >= r2_3)) {
            float rn = max(r1_1, (d_4 + r2_3));
            const float _e50 = sphere_pad(rn, c1_1);
            return float4(c1_1.x, c1_1.y, c1_1.z, (rn + _e50));
        }
        float rm = max(r2_3, (d_4 + r1_1));
        const float _e58 = sphere_pad(rm, c2_1);
        return float4(c2_1.x, c2_1.y, c2_1.z, (rm + _e58));
    }
    float r0_ = (0.5 * ((d_4 + r1_1) + r2_3));
    float3 c_9 = (c1_1 + (v_6 * ((r0_ - r1_1) / d_4)));
    float3 e1_ = (c_9 - c1_1);
    float3 e2_ = (c_9 - c2_1);
    float r_4 = max(r0_, max((sqrt(dot(e1_, e1_)) + r1_1), (sqrt(dot(e2_, e2_)) + r2_3)));
    const float _e82 = sphere_pad(r_4, c_9);
    return float4(c_9.x, c_9.y, c_9.z, (r_4 + _e82));
}

bool sphere_overlaps_aabb(float3 c_2, float r_2, float3 bmin, float3 bmax)
{
    float3 q_3 = clamp(c_2, bmin, bmax);
    float3 v_7 = (q_3 - c_2);
    return (dot(v_7, v_7) <= (r_2 * r_2));
}

float vpl_rt2_(float3 flux, float exposure_1, float error_bound_1, uint mode_1)
{
    const float _e6 = intensity_measure((flux * INV_PI), mode_1);
    const float _e7 = threshold_range2_(_e6, exposure_1, error_bound_1);
    return _e7;
}

float range_radius(float extent, float r2_4)
{
    return (extent + sqrt(r2_4));
}

float inverse_square(float d2_5)
{
    return (1.0 / max(d2_5, MIN_D2_));
}

float connection_factor(float cos_x, float d2_6, float rt2_3, float w)
{
    const float _e4 = inverse_square(d2_6);
    const float _e6 = slc_weight(rt2_3, d2_6);
    return (((cos_x * _e4) * _e6) * w);
}

float connection_cosine(float3 x_4, float3 y, float3 n, float3 ng, float r2_5)
{
    bool local_1 = (bool)0;
    bool local_2 = (bool)0;

    float3 v_8 = (x_4 - y);
    float d2_16 = dot(v_8, v_8);
    const bool _e7 = slc_keep(r2_5, d2_16);
    if (!(!(_e7))) {
        local_1 = !((d2_16 > 0.0));
    } else {
        local_1 = true;
    }
    bool _e16 = local_1;
    if (_e16) {
        return 0.0;
    }
    float3 w_10 = (v_8 / (sqrt(d2_16)).xxx);
    float cos_x_1 = -(dot(n, w_10));
    if (!((cos_x_1 <= 0.0))) {
        local_2 = (dot(ng, w_10) >= 0.0);
    } else {
        local_2 = true;
    }
    bool _e32 = local_2;
    if (_e32) {
        return 0.0;
    }
    return cos_x_1;
}

float vpl_lobe(float3 n_1, float3 w_1)
{
    return (max(dot(n_1, w_1), 0.0) * INV_PI);
}

float vpl_transfer(float3 n_l, float3 n_x, float3 v_1, float min_d2_)
{
    float m = max(dot(v_1, v_1), min_d2_);
    return (((max(dot(n_l, v_1), 0.0) * max(-(dot(n_x, v_1)), 0.0)) * INV_PI) / (m * m));
}

float spot_falloff(float cos_theta, float cos_outer, float cos_inner)
{
    if ((cos_inner <= cos_outer)) {
        return ((cos_theta >= cos_outer) ? 1.0 : 0.0);
    }
    float t_2 = saturate(((cos_theta - cos_outer) / (cos_inner - cos_outer)));
    return ((t_2 * t_2) * (3.0 - (2.0 * t_2)));
}

float triangle_lobe(float3 n_2, float area, float3 w_2)
{
    return (area * max(dot(n_2, w_2), 0.0));
}

float3 triangle_sample(float3 a_2, float3 b_2, float3 c_3, float u1_, float u2_)
{
    float su = sqrt(u1_);
    float b0_ = (1.0 - su);
    float b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_3 * ((1.0 - b0_) - b1_)));
}

float area_to_solid_angle_pdf(float pdf_area, float d2_7, float cos_light)
{
    float c_10 = abs(cos_light);
    if ((c_10 <= 0.0)) {
        return 0.0;
    }
    return ((pdf_area * d2_7) / c_10);
}

float atan_portable(float x_5)
{
    float base = 0.0;
    float t = (float)0;

    float a_9 = abs(x_5);
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
    float z_3 = (_e18 * _e19);
    float _e21 = base;
    float _e33 = t;
    float _e35 = t;
    float r_5 = (_e21 + (((((((((0.080537446 * z_3) - 0.13877685) * z_3) + 0.19977711) * z_3) - 0.3333295) * z_3) * _e33) + _e35));
    return ((x_5 < 0.0) ? -(r_5) : r_5);
}

float atan2_portable(float y_1, float x_6)
{
    if ((x_6 == 0.0)) {
        if ((y_1 > 0.0)) {
            return 1.5707964;
        }
        if ((y_1 < 0.0)) {
            return -1.5707964;
        }
        return 0.0;
    }
    const float _e12 = atan_portable((y_1 / x_6));
    if ((x_6 > 0.0)) {
        return _e12;
    }
    if ((y_1 >= 0.0)) {
        return (_e12 + 3.1415927);
    }
    return (_e12 - 3.1415927);
}

float ies_fold_c(float c_4, float h_first, float h_last)
{
    float a_3 = (float)0;

    a_3 = (c_4 - (360.0 * floor((c_4 / 360.0))));
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

uint ies_segment(uint tab_1, uint start, uint n_3, float x_7)
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
            if ((_e23 <= x_7)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
    uint _e25 = lo;
    return _e25;
}

float ies_lerp_t(float a0_, float a1_, float x_8)
{
    if ((a1_ <= a0_)) {
        return 0.0;
    }
    return saturate(((x_8 - a0_) / (a1_ - a0_)));
}

float ies_candela(uint tab_2, uint base_1, float gamma, float c_5)
{
    bool local_3 = (bool)0;

    const float _e4 = at(tab_2, base_1);
    const uint _e5 = to_u32_(_e4);
    const float _e8 = at(tab_2, (base_1 + 1u));
    const uint _e9 = to_u32_(_e8);
    uint v0_ = (base_1 + 2u);
    uint h0_ = (v0_ + _e5);
    uint c0_1 = (h0_ + _e9);
    const float _e14 = at(tab_2, v0_);
    if (!((gamma < _e14))) {
        const float _e22 = at(tab_2, ((v0_ + _e5) - 1u));
        local_3 = (gamma > _e22);
    } else {
        local_3 = true;
    }
    bool _e25 = local_3;
    if (_e25) {
        return 0.0;
    }
    const float _e27 = at(tab_2, h0_);
    const float _e31 = at(tab_2, ((h0_ + _e9) - 1u));
    const float _e32 = ies_fold_c(c_5, _e27, _e31);
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
    const float _e58 = at(tab_2, ((c0_1 + (_e34 * _e5)) + _e33));
    const float _e65 = at(tab_2, ((c0_1 + (_e34 * _e5)) + iv1_));
    float a_10 = ((_e58 * (1.0 - _e49)) + (_e65 * _e49));
    const float _e71 = at(tab_2, ((c0_1 + (ih1_ * _e5)) + _e33));
    const float _e78 = at(tab_2, ((c0_1 + (ih1_ * _e5)) + iv1_));
    float b_7 = ((_e71 * (1.0 - _e49)) + (_e78 * _e49));
    return ((a_10 * (1.0 - _e54)) + (b_7 * _e54));
}

float ies_candela_dir(uint tab_3, uint base_2, float wn, float wr, float ws)
{
    const float _e9 = atan2_portable(sqrt(((wr * wr) + (ws * ws))), wn);
    float gamma_1 = degrees(_e9);
    bool on_axis = ((abs(wr) + abs(ws)) <= 0.0);
    const float _e16 = atan2_portable(ws, wr);
    float c_11 = (on_axis ? 0.0 : degrees(_e16));
    const float _e20 = ies_candela(tab_3, base_2, gamma_1, c_11);
    return _e20;
}

float ies_light_candela(uint tab_4, uint base_3, float3 nadir, float3 reference, float3 w_3)
{
    float3 side = cross(reference, nadir);
    const float _e9 = ies_candela_dir(tab_4, base_3, dot(w_3, nadir), dot(w_3, reference), dot(w_3, side));
    return _e9;
}

uint mul_hi_u32_(uint a_4, uint b_3)
{
    uint a_lo = (a_4 & 65535u);
    uint a_hi = (a_4 >> 16u);
    uint b_lo = (b_3 & 65535u);
    uint b_hi = (b_3 >> 16u);
    uint ll = (a_lo * b_lo);
    uint lh = (a_lo * b_hi);
    uint hl = (a_hi * b_lo);
    uint hh = (a_hi * b_hi);
    uint mid_1 = (((ll >> 16u) + (lh & 65535u)) + (hl & 65535u));
    return (((hh + (lh >> 16u)) + (hl >> 16u)) + (mid_1 >> 16u));
}

uint uniform_index(uint n_4, uint hi_1, uint lo_1)
{
    const uint _e3 = mul_lo_u32_(hi_1, n_4);
    const uint _e4 = mul_hi_u32_(hi_1, n_4);
    const uint _e5 = mul_hi_u32_(lo_1, n_4);
    if ((_e3 > (4294967295u - _e5))) {
        return (_e4 + 1u);
    }
    return _e4;
}

uint reservoir_slot(uint n_5, uint k, uint hi_2, uint lo_2)
{
    if ((n_5 <= k)) {
        return (n_5 - 1u);
    }
    const uint _e7 = uniform_index(n_5, hi_2, lo_2);
    if ((_e7 < k)) {
        return _e7;
    }
    return k;
}

bool reservoir_takes(uint n_6)
{
    return (n_6 < RESERVOIR_FULL);
}

float reservoir_weight(uint n_7, uint k_1)
{
    const float _e2 = to_f32_(n_7);
    const float _e3 = to_f32_(k_1);
    return max((_e2 / _e3), 1.0);
}

bool weighted_replace(float w_4, float w_sum, float u_1)
{
    return ((u_1 * w_sum) < w_4);
}

float weighted_pick_weight(float w_sum_1, float w_5, uint k_2)
{
    const float _e3 = to_f32_(k_2);
    return (w_sum_1 / (_e3 * w_5));
}

float reservoir_select_pdf(uint seen, bool in_range, uint k_3)
{
    uint others = (uint)0;
    bool local_4 = (bool)0;

    others = seen;
    if (in_range) {
        local_4 = (seen > 0u);
    } else {
        local_4 = false;
    }
    bool _e9 = local_4;
    if (_e9) {
        others = (seen - 1u);
    }
    uint _e12 = others;
    const float _e15 = reservoir_weight((_e12 + 1u), k_3);
    return (1.0 / _e15);
}

uint alias_choice(uint column, uint other, float keep, float u_2)
{
    return ((u_2 < keep) ? column : other);
}

uint uniform_light(float u_3, uint n_8)
{
    const float _e2 = to_f32_(n_8);
    const uint _e4 = to_u32_((u_3 * _e2));
    return min(_e4, (n_8 - 1u));
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

float safe_sqrt(float x_9)
{
    return sqrt(max(x_9, 0.0));
}

float light_importance(float3 center_, float radius, float phi, float3 axis, float cos_o, float cos_e, float3 p, float3 n_9)
{
    float imp = (float)0;

    float3 v_9 = (p - center_);
    float dist2_ = dot(v_9, v_9);
    float r2_11 = (radius * radius);
    float d2_17 = max(max(dist2_, r2_11), MIN_D2_);
    float3 wi = ((dist2_ > 0.0) ? (v_9 / (sqrt(dist2_)).xxx) : float3(0.0, 0.0, 0.0));
    float cos_w = dot(axis, wi);
    const float _e28 = safe_sqrt((1.0 - (cos_w * cos_w)));
    const float _e32 = safe_sqrt((1.0 - (r2_11 / dist2_)));
    float cos_b_2 = ((dist2_ <= r2_11) ? -1.0 : _e32);
    const float _e39 = safe_sqrt((1.0 - (cos_b_2 * cos_b_2)));
    const float _e43 = safe_sqrt((1.0 - (cos_o * cos_o)));
    const float _e44 = cos_sub_clamped(_e28, cos_w, _e43, cos_o);
    const float _e45 = sin_sub_clamped(_e28, cos_w, _e43, cos_o);
    const float _e46 = cos_sub_clamped(_e45, _e44, _e39, cos_b_2);
    if ((_e46 <= cos_e)) {
        return 0.0;
    }
    imp = ((phi * _e46) / d2_17);
    if ((dot(n_9, n_9) > 0.0)) {
        float cos_i = -(dot(wi, n_9));
        const float _e60 = safe_sqrt((1.0 - (cos_i * cos_i)));
        float _e61 = imp;
        const float _e62 = cos_sub_clamped(_e60, cos_i, _e39, cos_b_2);
        imp = (_e61 * max(_e62, 0.0));
    }
    float _e66 = imp;
    return max(_e66, 0.0);
}

float candidate_weight(float importance, float rt2_4, float d2_8)
{
    const float _e3 = slc_weight(rt2_4, d2_8);
    return (importance * _e3);
}

float cone_weight(float3 center_1, float radius_1, float phi_1, float3 axis_1, float cos_o_1, float cos_e_1, float rt2_5, float3 p_1, float3 n_10)
{
    float3 v_10 = (p_1 - center_1);
    const float _e10 = light_importance(center_1, radius_1, phi_1, axis_1, cos_o_1, cos_e_1, p_1, n_10);
    const float _e14 = candidate_weight((_e10 * INV_PI), rt2_5, dot(v_10, v_10));
    return _e14;
}

float weighted_select_pdf(float w_6, float w_sum_2, bool in_range_1, uint k_4)
{
    if ((w_6 <= 0.0)) {
        return 0.0;
    }
    float total = (in_range_1 ? w_sum_2 : (w_sum_2 + w_6));
    const float _e9 = to_f32_(k_4);
    return ((_e9 * w_6) / total);
}

float bvh_first_prob(float c0_, float c1_2)
{
    float s = (c0_ + c1_2);
    if ((s > 0.0)) {
        return (c0_ / s);
    }
    return -1.0;
}

float bvh_remap_u(float u_4, float p0_, bool first)
{
    if (first) {
        return min((u_4 / p0_), ONE_MINUS_EPSILON);
    }
    return clamp(((u_4 - p0_) / (1.0 - p0_)), 0.0, ONE_MINUS_EPSILON);
}

float surface_offset(float diag)
{
    return (1e-5 * diag);
}

float ray_t_min(float diag_1)
{
    return (1e-6 * diag_1);
}

float shadow_margin(float len)
{
    return (0.0001 * len);
}

float ray_inverse(float x_10)
{
    return (1.0 / ((abs(x_10) < 1e-30) ? 1e-30 : x_10));
}

float3 ray_inverse3_(float3 d)
{
    const float _e2 = ray_inverse(d.x);
    const float _e4 = ray_inverse(d.y);
    const float _e6 = ray_inverse(d.z);
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

float3 triangle_normal(float3 a_5, float3 b_4, float3 c_6)
{
    bool local_5 = (bool)0;

    float3 n_17 = cross((b_4 - a_5), (c_6 - a_5));
    float l2_ = dot(n_17, n_17);
    if (!(!((l2_ > 0.0)))) {
        local_5 = !((l2_ < 3e38));
    } else {
        local_5 = true;
    }
    bool _e17 = local_5;
    if (_e17) {
        return float3(0.0, 0.0, 0.0);
    }
    return (n_17 / (sqrt(l2_)).xxx);
}

float3 face_against(float3 n_11, float3 dir)
{
    return ((dot(n_11, dir) > 0.0) ? -(n_11) : n_11);
}

float3 barycentric(float3 p_2, float3 a_6, float3 b_5, float3 c_7)
{
    float3 e1_1 = (b_5 - a_6);
    float3 e2_1 = (c_7 - a_6);
    float3 q_4 = (p_2 - a_6);
    float d11_ = dot(e1_1, e1_1);
    float d12_ = dot(e1_1, e2_1);
    float d22_ = dot(e2_1, e2_1);
    float den = ((d11_ * d22_) - (d12_ * d12_));
    if (!((abs(den) > 0.0))) {
        return float3(1.0, 0.0, 0.0);
    }
    float w1_ = (((d22_ * dot(q_4, e1_1)) - (d12_ * dot(q_4, e2_1))) / den);
    float w2_ = (((d11_ * dot(q_4, e2_1)) - (d12_ * dot(q_4, e1_1))) / den);
    return float3(((1.0 - w1_) - w2_), w1_, w2_);
}

float3 shading_normal(float3 n0_, float3 n1_, float3 n2_, float3 w_7, float3 facing)
{
    bool local_6 = (bool)0;

    float3 s_1 = (((n0_ * w_7.x) + (n1_ * w_7.y)) + (n2_ * w_7.z));
    float l2_1 = dot(s_1, s_1);
    if (!(!((l2_1 > 1e-12)))) {
        local_6 = !((l2_1 < 3e38));
    } else {
        local_6 = true;
    }
    bool _e24 = local_6;
    if (_e24) {
        return facing;
    }
    float3 n_18 = (s_1 / (sqrt(l2_1)).xxx);
    return ((dot(n_18, facing) < 0.0) ? -(n_18) : n_18);
}

float ray_triangle(float3 o_1, float3 d_1, float3 a_7, float3 b_6, float3 c_8, float t_min, float t_max_1)
{
    bool local_7 = (bool)0;
    bool local_8 = (bool)0;
    bool local_9 = (bool)0;

    float3 e1_2 = (b_6 - a_7);
    float3 e2_2 = (c_8 - a_7);
    float3 p_3 = cross(d_1, e2_2);
    float det = dot(e1_2, p_3);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv = (1.0 / det);
    float3 s_2 = (o_1 - a_7);
    float u_6 = (dot(s_2, p_3) * inv);
    if (!((u_6 < 0.0))) {
        local_7 = (u_6 > 1.0);
    } else {
        local_7 = true;
    }
    bool _e28 = local_7;
    if (_e28) {
        return -1.0;
    }
    float3 q_5 = cross(s_2, e1_2);
    float v_11 = (dot(d_1, q_5) * inv);
    if (!((v_11 < 0.0))) {
        local_8 = ((u_6 + v_11) > 1.0);
    } else {
        local_8 = true;
    }
    bool _e42 = local_8;
    if (_e42) {
        return -1.0;
    }
    float t_3 = (dot(e2_2, q_5) * inv);
    if ((t_3 > t_min)) {
        local_9 = (t_3 < t_max_1);
    } else {
        local_9 = false;
    }
    bool _e51 = local_9;
    if (_e51) {
        return t_3;
    }
    return -1.0;
}

float mis_balance(float pdf_a, float pdf_b)
{
    float s_3 = (pdf_a + pdf_b);
    if ((s_3 <= 0.0)) {
        return 0.0;
    }
    return (pdf_a / s_3);
}

float mis_power(float pdf_a_1, float pdf_b_1)
{
    float a2_ = (pdf_a_1 * pdf_a_1);
    float s_4 = (a2_ + (pdf_b_1 * pdf_b_1));
    if ((s_4 <= 0.0)) {
        return 0.0;
    }
    return (a2_ / s_4);
}

float light_strategy_pdf(float select_, float rt2_6, float d2_9, float area_1, float cos_y)
{
    bool local_10 = (bool)0;
    bool local_11 = (bool)0;

    if (!((d2_9 <= 0.0))) {
        local_10 = (area_1 <= 0.0);
    } else {
        local_10 = true;
    }
    bool _e13 = local_10;
    if (!(_e13)) {
        local_11 = (cos_y <= 0.0);
    } else {
        local_11 = true;
    }
    bool _e20 = local_11;
    if (_e20) {
        return 0.0;
    }
    const float _e22 = rr_probability(rt2_6, d2_9);
    const float _e26 = area_to_solid_angle_pdf((1.0 / area_1), d2_9, cos_y);
    return ((select_ * _e22) * _e26);
}

float3 lambert_brdf(float3 rho)
{
    return (rho * INV_PI);
}

float cosine_pdf(float cos_theta_1)
{
    return (max(cos_theta_1, 0.0) * INV_PI);
}

float3 cosine_direction(float3 n_12, float u1_1, float u2_1)
{
    float s_5 = ((n_12.z >= 0.0) ? 1.0 : -1.0);
    float a_11 = (-1.0 / (s_5 + n_12.z));
    float b_8 = ((n_12.x * n_12.y) * a_11);
    float3 t_4 = float3((1.0 + (((s_5 * n_12.x) * n_12.x) * a_11)), (s_5 * b_8), (-(s_5) * n_12.x));
    float3 bt = float3(b_8, (s_5 + ((n_12.y * n_12.y) * a_11)), -(n_12.y));
    float r_6 = sqrt(u1_1);
    float phi_2 = (6.2831855 * u2_1);
    return normalize((((t_4 * (r_6 * cos(phi_2))) + (bt * (r_6 * sin(phi_2)))) + (n_12 * sqrt(max((1.0 - u1_1), 0.0)))));
}

float inv_sigma_z(float z)
{
    return (1.0 / (DEPTH_SIGMA * z));
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

uint window_start(uint x_11, uint size)
{
    uint half_ = naga_div(size, 2u);
    return (max(x_11, half_) - half_);
}

uint window_end(uint x_12, uint size_1, uint extent_1)
{
    return min(((x_12 + size_1) - naga_div(size_1, 2u)), extent_1);
}

uint wide_window(uint period)
{
    return (2u * period);
}

bool misses_subset(uint covered, uint period_1)
{
    return (covered < (period_1 * period_1));
}

float3 filtered_irradiance(float3 e, float3 sum, float weight)
{
    if ((weight > 0.0)) {
        return (sum / (weight).xxx);
    }
    return e;
}

float bilateral_weight(float3 n_13, float3 nj, float z_1, float zj, float inv_sz)
{
    float dn = max(dot(n_13, nj), 0.0);
    float dn2_ = (dn * dn);
    float dn4_ = (dn2_ * dn2_);
    float dn8_ = (dn4_ * dn4_);
    float d_5 = ((zj - z_1) * inv_sz);
    float t_5 = max((1.0 - (d_5 * d_5)), 0.0);
    return (((dn8_ * dn8_) * t_5) * t_5);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint interleave_subset(uint x_13, uint y_2, uint period_2)
{
    return ((naga_mod(y_2, period_2) * period_2) + naga_mod(x_13, period_2));
}

uint interleave_slot(uint tx, uint ty, uint size_2, uint period_3)
{
    uint side_1 = naga_div(size_2, period_3);
    const uint _e5 = interleave_subset(tx, ty, period_3);
    return ((((_e5 * side_1) * side_1) + (naga_div(ty, period_3) * side_1)) + naga_div(tx, period_3));
}

uint interleave_slot_linear(uint i_1, uint per_subset, uint period_4)
{
    uint subsets = (period_4 * period_4);
    return ((naga_mod(i_1, subsets) * per_subset) + naga_div(i_1, subsets));
}

float interleave_flux_scale(uint period_5)
{
    const float _e2 = to_f32_((period_5 * period_5));
    return _e2;
}

uint near_block_index(uint tx_1, uint ty_1, uint size_3)
{
    uint side_2 = naga_div(size_3, 8u);
    return (((((naga_div(ty_1, 8u) * side_2) + naga_div(tx_1, 8u)) * NEAR_BLOCK) + (naga_mod(ty_1, 8u) * 8u)) + naga_mod(tx_1, 8u));
}

uint near_block_tx(uint q, uint size_4)
{
    return ((naga_mod(naga_div(q, NEAR_BLOCK), naga_div(size_4, 8u)) * 8u) + naga_mod(q, 8u));
}

uint near_block_ty(uint q_1, uint size_5)
{
    return ((naga_div(naga_div(q_1, NEAR_BLOCK), naga_div(size_5, 8u)) * 8u) + naga_div(naga_mod(q_1, NEAR_BLOCK), 8u));
}

float vpl_near_weight(float d2_10, float near_r2_)
{
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t_6 = clamp(((near_r2_ - d2_10) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t_6 * t_6) * (3.0 - (2.0 * t_6)));
}

float vpl_far_weight(float d2_11, float near_r2_1)
{
    const float _e2 = vpl_near_weight(d2_11, near_r2_1);
    return (1.0 - _e2);
}

float vpl_far_slc_share(float rt2_7, float r2_6, float d2_12, float near_r2_2)
{
    const float _e4 = vpl_far_weight(d2_12, near_r2_2);
    const float _e5 = slc_weight(rt2_7, d2_12);
    const bool _e7 = slc_keep(r2_6, d2_12);
    return ((_e7 & (_e4 > 0.0)) ? (_e4 * _e5) : 0.0);
}

float vpl_far_fixed_share(float range2_2, float d2_13, float near_r2_3)
{
    const float _e3 = vpl_far_weight(d2_13, near_r2_3);
    const bool _e4 = clamp_keep(range2_2, d2_13);
    return ((_e4 & (_e3 > 0.0)) ? _e3 : 0.0);
}

float vpl_near_range2_(float r2_7, uint period_6)
{
    const float _e2 = interleave_flux_scale(period_6);
    return (r2_7 / _e2);
}

float vpl_near_cull_range2_(float r2_8, float near_r2_4)
{
    return min(r2_8, near_r2_4);
}

float vpl_near_slc_share(float rt2_8, float r2_9, float d2_14, float near_r2_5)
{
    const float _e4 = vpl_near_weight(d2_14, near_r2_5);
    const float _e5 = slc_weight(rt2_8, d2_14);
    const bool _e7 = slc_keep(r2_9, d2_14);
    return ((_e7 & (_e4 > 0.0)) ? (_e4 * _e5) : 0.0);
}

float vpl_near_fixed_share(float range2_3, float d2_15, float near_r2_6)
{
    const float _e3 = vpl_near_weight(d2_15, near_r2_6);
    const bool _e4 = clamp_keep(range2_3, d2_15);
    return ((_e4 & (_e3 > 0.0)) ? _e3 : 0.0);
}

float3 camera_dir(float3 forward, float3 right, float3 up, float px, float py, float w_8, float h)
{
    float sx = (((2.0 * px) / w_8) - 1.0);
    float sy = (1.0 - ((2.0 * py) / h));
    return normalize(((forward + (right * sx)) + (up * sy)));
}

float jittered_pixel(uint coord, float u_5)
{
    const float _e2 = to_f32_(coord);
    return (_e2 + u_5);
}

bool plays_roulette(uint depth)
{
    return (depth >= ROULETTE_DEPTH);
}

bool sees_emission(float3 gn, float3 dir_1)
{
    return (dot(gn, dir_1) < 0.0);
}

bool continues_path(float3 nd, float3 n_14, float3 ng_1)
{
    bool local_12 = (bool)0;

    if ((dot(nd, n_14) > 0.0)) {
        local_12 = (dot(nd, ng_1) > 0.0);
    } else {
        local_12 = false;
    }
    bool _e12 = local_12;
    return _e12;
}

bool finite3_(float3 v_2)
{
    bool local_13 = (bool)0;
    bool local_14 = (bool)0;

    if ((abs(v_2.x) <= F32_MAX)) {
        local_13 = (abs(v_2.y) <= F32_MAX);
    } else {
        local_13 = false;
    }
    bool _e12 = local_13;
    if (_e12) {
        local_14 = (abs(v_2.z) <= F32_MAX);
    } else {
        local_14 = false;
    }
    bool _e20 = local_14;
    return _e20;
}

float path_survival(float3 beta)
{
    return clamp(max(max(beta.x, beta.y), beta.z), 0.05, 0.95);
}

float light_map_coord(uint t_1, uint size_6)
{
    const float _e2 = to_f32_(t_1);
    const float _e7 = to_f32_(size_6);
    return (((2.0 * (_e2 + 0.5)) / _e7) - 1.0);
}

uint light_map_texel(float a_8, uint size_7)
{
    const float _e6 = to_f32_(size_7);
    const float _e9 = to_f32_(size_7);
    const uint _e14 = to_u32_(clamp(floor((((a_8 + 1.0) * 0.5) * _e6)), 0.0, (_e9 - 1.0)));
    return _e14;
}

float light_map_coord_at(float3 rel, float3 dir_2, float3 axis_2, float extent_2, bool perspective)
{
    return (dot(rel, dir_2) / ((perspective ? dot(rel, axis_2) : 1.0) * extent_2));
}

float display_encode(float x_14)
{
    float v_12 = max(x_14, 0.0);
    float t_7 = ((2.0 * v_12) / (1.0 + (2.0 * v_12)));
    return ((t_7 <= 0.0031308) ? (12.92 * t_7) : ((1.055 * pow(t_7, 0.41666666)) - 0.055));
}

float light_map_depth(float3 rel_1, float3 axis_3, bool perspective_1)
{
    return (perspective_1 ? sqrt(dot(rel_1, rel_1)) : dot(rel_1, axis_3));
}

float rsm_texel_solid_angle(float texel_area, float cos_axis)
{
    return (((texel_area * cos_axis) * cos_axis) * cos_axis);
}

float3 point_irradiance(float3 intensity_1, float3 n_15, float3 v_3)
{
    float d2_18 = dot(v_3, v_3);
    float cos_x_2 = (dot(n_15, v_3) / sqrt(max(d2_18, MIN_D2_)));
    const float _e11 = inverse_square(d2_18);
    return (intensity_1 * (max(cos_x_2, 0.0) * _e11));
}

float3 directional_irradiance(float3 e_1, float3 n_16, float3 to_light)
{
    return (e_1 * max(dot(n_16, to_light), 0.0));
}

float perspective_texel_width(float extent_3, float d_2, float z_2, float size_8)
{
    return ((((2.0 * extent_3) * d_2) * d_2) / (size_8 * z_2));
}

float ortho_texel_width(float extent_4, float size_9)
{
    return ((2.0 * extent_4) / size_9);
}

float shadow_bias(float texel, float cos_light_1)
{
    float c_12 = clamp(cos_light_1, 0.02, 1.0);
    return (texel * (1.5 + (sqrt((1.0 - (c_12 * c_12))) / c_12)));
}

bool shadow_lit(float d_3, float d_map, float bias)
{
    bool local_15 = (bool)0;

    if (!((d_map <= 0.0))) {
        local_15 = (d_3 <= (d_map + bias));
    } else {
        local_15 = true;
    }
    bool _e11 = local_15;
    return _e11;
}

float3 diffuse_radiance(float3 albedo, float3 emission, float3 e_2)
{
    return (emission + ((albedo * INV_PI) * e_2));
}

BshNode ConstructBshNode(float3 arg0, float arg1, uint arg2, uint arg3, uint arg4, uint arg5) {
    BshNode ret = (BshNode)0;
    ret.center_ = arg0;
    ret.radius = arg1;
    ret.child = arg2;
    ret.next = arg3;
    ret.light = arg4;
    ret.pad = arg5;
    return ret;
}

BshNode bsh_node(uint nodes, uint i_2)
{
    BshNode _e4 = ConstructBshNode(asfloat(bsh_nodes.Load3(i_2*32+0)), asfloat(bsh_nodes.Load(i_2*32+12)), asuint(bsh_nodes.Load(i_2*32+16)), asuint(bsh_nodes.Load(i_2*32+20)), asuint(bsh_nodes.Load(i_2*32+24)), asuint(bsh_nodes.Load(i_2*32+28)));
    const BshNode bshnode = _e4;
    return bshnode;
}

uint NagaBufferLengthRW(RWByteAddressBuffer buffer)
{
    uint ret;
    buffer.GetDimensions(ret);
    return ret;
}

uint bsh_count(uint nodes_1)
{
    return ((NagaBufferLengthRW(bsh_nodes) - 0) / 32);
}

uint bsh_first(uint nodes_2)
{
    const uint _e1 = bsh_count(nodes_2);
    if ((_e1 > 0u)) {
        return 0u;
    }
    return BSH_NONE;
}

uint bsh_next_leaf(uint nodes_3, uint start_1, float3 x_15)
{
    uint i_3 = (uint)0;

    i_3 = start_1;
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e4 = i_3;
        if ((_e4 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e7 = i_3;
            const BshNode _e8 = bsh_node(nodes_3, _e7);
            const bool _e11 = sphere_contains_point(_e8.center_, _e8.radius, x_15);
            if (_e11) {
                if ((_e8.child == BSH_NONE)) {
                    uint _e15 = i_3;
                    return _e15;
                }
                i_3 = _e8.child;
            } else {
                i_3 = _e8.next;
            }
        }
    }
    return BSH_NONE;
}

float4 bsh_children_sphere(uint nodes_4, uint i_4)
{
    const BshNode _e2 = bsh_node(nodes_4, i_4);
    const BshNode _e4 = bsh_node(nodes_4, _e2.child);
    const BshNode _e6 = bsh_node(nodes_4, _e4.next);
    const float4 _e11 = sphere_union(_e4.center_, _e4.radius, _e6.center_, _e6.radius);
    return _e11;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    uint _e4 = params.count;
    if ((gid.x >= _e4)) {
        return;
    }
    uint _e9 = params.first;
    uint i_5 = asuint(order.Load((_e9 + gid.x)*4));
    BshNode node = ConstructBshNode(asfloat(bsh_nodes.Load3(i_5*32+0)), asfloat(bsh_nodes.Load(i_5*32+12)), asuint(bsh_nodes.Load(i_5*32+16)), asuint(bsh_nodes.Load(i_5*32+20)), asuint(bsh_nodes.Load(i_5*32+24)), asuint(bsh_nodes.Load(i_5*32+28)));
    if ((node.child == BSH_NONE)) {
        float _e26 = asfloat(extent_5.Load(node.light*4));
        float _e30 = asfloat(r2_10.Load(node.light*4));
        const float _e31 = range_radius(_e26, _e30);
        bsh_nodes.Store(12+i_5*32, asuint(_e31));
        return;
    }
    const float4 _e33 = bsh_children_sphere(BSH, i_5);
    bsh_nodes.Store3(0+i_5*32, asuint(_e33.xyz));
    bsh_nodes.Store(12+i_5*32, asuint(_e33.w));
    return;
}
