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
static const float GGX_ALPHA_MIN = 0.001;
static const float DEPTH_NONE = 1e30;
static const float DEPTH_SIGMA = 0.05;
static const float COVER_WEIGHT = 0.1;
static const uint NEAR_BLOCK = 64u;
static const uint ROULETTE_DEPTH = 2u;
static const uint K = 8u;
static const uint BSH = 0u;
static const uint BVH = 0u;

ByteAddressBuffer geo_nodes : register(t6);
ByteAddressBuffer geo_tris : register(t7);
ByteAddressBuffer lights : register(t2);
ByteAddressBuffer r2_2 : register(t4);
ByteAddressBuffer rt2_4 : register(t3);
ByteAddressBuffer light_cones : register(t2, space1);
ByteAddressBuffer light_bvh : register(t3, space1);
cbuffer params : register(b0) { ShadeParams params; }
ByteAddressBuffer vertices_ : register(t1);
RWByteAddressBuffer radiance : register(u8);
RWByteAddressBuffer candidates : register(u9);

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

    float3 v_1 = (x_1 - y);
    float d2_7 = dot(v_1, v_1);
    const bool _e7 = slc_keep(r2_1, d2_7);
    if (!(!(_e7))) {
        local = !((d2_7 > 0.0));
    } else {
        local = true;
    }
    bool _e16 = local;
    if (_e16) {
        return 0.0;
    }
    float3 w_4 = (v_1 / (sqrt(d2_7)).xxx);
    float cos_x_1 = -(dot(n, w_4));
    if (!((cos_x_1 <= 0.0))) {
        local_1 = (dot(ng, w_4) >= 0.0);
    } else {
        local_1 = true;
    }
    bool _e32 = local_1;
    if (_e32) {
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
    float c_4 = abs(cos_light);
    if ((c_4 <= 0.0)) {
        return 0.0;
    }
    return ((pdf_area * d2_5) / c_4);
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

float light_importance(float3 center_, float radius, float phi, float3 axis, float cos_o, float cos_e, float3 p, float3 n_2)
{
    float imp = (float)0;

    float3 v_2 = (p - center_);
    float dist2_ = dot(v_2, v_2);
    float r2_3 = (radius * radius);
    float d2_8 = max(max(dist2_, r2_3), MIN_D2_);
    float3 wi = ((dist2_ > 0.0) ? (v_2 / (sqrt(dist2_)).xxx) : float3(0.0, 0.0, 0.0));
    float cos_w = dot(axis, wi);
    const float _e28 = safe_sqrt((1.0 - (cos_w * cos_w)));
    const float _e32 = safe_sqrt((1.0 - (r2_3 / dist2_)));
    float cos_b_2 = ((dist2_ <= r2_3) ? -1.0 : _e32);
    const float _e39 = safe_sqrt((1.0 - (cos_b_2 * cos_b_2)));
    const float _e43 = safe_sqrt((1.0 - (cos_o * cos_o)));
    const float _e44 = cos_sub_clamped(_e28, cos_w, _e43, cos_o);
    const float _e45 = sin_sub_clamped(_e28, cos_w, _e43, cos_o);
    const float _e46 = cos_sub_clamped(_e45, _e44, _e39, cos_b_2);
    if ((_e46 <= cos_e)) {
        return 0.0;
    }
    imp = ((phi * _e46) / d2_8);
    if ((dot(n_2, n_2) > 0.0)) {
        float cos_i = -(dot(wi, n_2));
        const float _e60 = safe_sqrt((1.0 - (cos_i * cos_i)));
        float _e61 = imp;
        const float _e62 = cos_sub_clamped(_e60, cos_i, _e39, cos_b_2);
        imp = (_e61 * max(_e62, 0.0));
    }
    float _e66 = imp;
    return max(_e66, 0.0);
}

float bvh_first_prob(float c0_, float c1_)
{
    float s = (c0_ + c1_);
    if ((s > 0.0)) {
        return (c0_ / s);
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

float shadow_margin(float len)
{
    return (0.0001 * len);
}

float ray_inverse(float x_3)
{
    return (1.0 / ((abs(x_3) < 1e-30) ? 1e-30 : x_3));
}

float3 ray_inverse3_(float3 d)
{
    const float _e2 = ray_inverse(d.x);
    const float _e4 = ray_inverse(d.y);
    const float _e6 = ray_inverse(d.z);
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

float3 triangle_normal(float3 a_3, float3 b_3, float3 c_1)
{
    bool local_2 = (bool)0;

    float3 n_11 = cross((b_3 - a_3), (c_1 - a_3));
    float l2_ = dot(n_11, n_11);
    if (!(!((l2_ > 0.0)))) {
        local_2 = !((l2_ < 3e38));
    } else {
        local_2 = true;
    }
    bool _e17 = local_2;
    if (_e17) {
        return float3(0.0, 0.0, 0.0);
    }
    return (n_11 / (sqrt(l2_)).xxx);
}

float ray_triangle(float3 o_1, float3 d_1, float3 a_4, float3 b_4, float3 c_2, float t_min, float t_max_1)
{
    bool local_3 = (bool)0;
    bool local_4 = (bool)0;
    bool local_5 = (bool)0;

    float3 e1_ = (b_4 - a_4);
    float3 e2_ = (c_2 - a_4);
    float3 p_1 = cross(d_1, e2_);
    float det = dot(e1_, p_1);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv = (1.0 / det);
    float3 s_1 = (o_1 - a_4);
    float u_3 = (dot(s_1, p_1) * inv);
    if (!((u_3 < 0.0))) {
        local_3 = (u_3 > 1.0);
    } else {
        local_3 = true;
    }
    bool _e28 = local_3;
    if (_e28) {
        return -1.0;
    }
    float3 q = cross(s_1, e1_);
    float v_3 = (dot(d_1, q) * inv);
    if (!((v_3 < 0.0))) {
        local_4 = ((u_3 + v_3) > 1.0);
    } else {
        local_4 = true;
    }
    bool _e42 = local_4;
    if (_e42) {
        return -1.0;
    }
    float t = (dot(e2_, q) * inv);
    if ((t > t_min)) {
        local_5 = (t < t_max_1);
    } else {
        local_5 = false;
    }
    bool _e51 = local_5;
    if (_e51) {
        return t;
    }
    return -1.0;
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
    bool local_6 = (bool)0;
    bool local_7 = (bool)0;

    if (!((d2_6 <= 0.0))) {
        local_6 = (area_1 <= 0.0);
    } else {
        local_6 = true;
    }
    bool _e13 = local_6;
    if (!(_e13)) {
        local_7 = (cos_y <= 0.0);
    } else {
        local_7 = true;
    }
    bool _e20 = local_7;
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

bool finite3_(float3 v)
{
    bool local_8 = (bool)0;
    bool local_9 = (bool)0;

    if ((abs(v.x) <= F32_MAX)) {
        local_8 = (abs(v.y) <= F32_MAX);
    } else {
        local_8 = false;
    }
    bool _e12 = local_8;
    if (_e12) {
        local_9 = (abs(v.z) <= F32_MAX);
    } else {
        local_9 = false;
    }
    bool _e20 = local_9;
    return _e20;
}

float3 light_intensity(GpuLight l, float3 w_2)
{
    switch(l.kind) {
        case 3u: {
            const float3 _e7 = triangle_normal(l.p0_, l.p1_, l.p2_);
            const float _e9 = triangle_lobe(_e7, l.a, w_2);
            return (l.intensity * _e9);
        }
        default: {
            return (0.0).xxx;
        }
    }
}

float3 light_point(GpuLight l_1, float u1_1, float u2_1)
{
    if ((l_1.kind == LIGHT_TRIANGLE)) {
        const float3 _e9 = triangle_sample(l_1.p0_, l_1.p1_, l_1.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_1.p0_;
}

float light_area(GpuLight l_2)
{
    if ((l_2.kind == LIGHT_TRIANGLE)) {
        return l_2.a;
    }
    return 0.0;
}

float3 light_normal(GpuLight l_3)
{
    if ((l_3.kind == LIGHT_TRIANGLE)) {
        const float3 _e7 = triangle_normal(l_3.p0_, l_3.p1_, l_3.p2_);
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

GeoHit trace(float3 o_2, float3 d_2, float t_min_1, float t_max_2, bool any_hit)
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
    const float3 _e14 = ray_inverse3_(d_2);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e21 = node;
        GpuGeoNode n_12 = ConstructGpuGeoNode(asfloat(geo_nodes.Load3(_e21*32+0)), asuint(geo_nodes.Load(_e21*32+12)), asfloat(geo_nodes.Load3(_e21*32+16)), asuint(geo_nodes.Load(_e21*32+28)));
        float _e27 = hit.t;
        const float _e28 = ray_aabb(o_2, _e14, n_12.bmin, n_12.bmax, _e27);
        if ((_e28 >= 0.0)) {
            if ((n_12.count > 0u)) {
                i = n_12.first;
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
                    if ((_e36 < (n_12.first + n_12.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_1 = ConstructGpuTriangle(asfloat(geo_tris.Load3(_e42*48+0)), asuint(geo_tris.Load(_e42*48+12)), asfloat(geo_tris.Load3(_e42*48+16)), asuint(geo_tris.Load(_e42*48+28)), asfloat(geo_tris.Load3(_e42*48+32)), asuint(geo_tris.Load(_e42*48+44)));
                        float _e49 = hit.t;
                        const float _e50 = ray_triangle(o_2, d_2, t_1.v0_, t_1.v1_, t_1.v2_, t_min_1, _e49);
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
                    stack[min(uint(_e63), 63u)] = (n_12.first + 1u);
                    uint _e68 = sp;
                    sp = (_e68 + 1u);
                }
                node = n_12.first;
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

bool occluded(float3 a_5, float3 b_5)
{
    float3 dv = (b_5 - a_5);
    float len_1 = length(dv);
    if ((len_1 <= 0.0)) {
        return false;
    }
    const float _e7 = shadow_margin(len_1);
    const GeoHit _e12 = trace(a_5, (dv / (len_1).xxx), _e7, (len_1 - _e7), true);
    return (_e12.tri != NO_LIGHT);
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

Connection connect(uint li, float3 x_4, float3 n_3, float3 ng_1, float w_res, float u1_2, float u2_2, float eps)
{
    Connection c_3 = (Connection)0;
    bool local_10 = (bool)0;

    c_3.e = (0.0).xxx;
    GpuLight l_4 = ConstructGpuLight(asfloat(lights.Load3(li*64+0)), asuint(lights.Load(li*64+12)), asfloat(lights.Load3(li*64+16)), asfloat(lights.Load(li*64+28)), asfloat(lights.Load3(li*64+32)), asfloat(lights.Load(li*64+44)), asfloat(lights.Load3(li*64+48)), asuint(lights.Load(li*64+60)));
    const float3 _e16 = light_point(l_4, u1_2, u2_2);
    c_3.y = _e16;
    float3 _e19 = c_3.y;
    float _e22 = asfloat(r2_2.Load(li*4));
    const float _e23 = connection_cosine(x_4, _e19, n_3, ng_1, _e22);
    c_3.cos_x = _e23;
    float _e25 = c_3.cos_x;
    if (!((_e25 <= 0.0))) {
        float3 _e34 = c_3.y;
        const bool _e35 = occluded((x_4 + (ng_1 * eps)), _e34);
        local_10 = _e35;
    } else {
        local_10 = true;
    }
    bool _e37 = local_10;
    if (_e37) {
        Connection _e38 = c_3;
        const Connection connection = _e38;
        return connection;
    }
    float3 _e40 = c_3.y;
    float3 v_4 = (x_4 - _e40);
    float d2_9 = dot(v_4, v_4);
    const float3 _e47 = light_intensity(l_4, (v_4 / (sqrt(d2_9)).xxx));
    float _e49 = c_3.cos_x;
    float _e52 = asfloat(rt2_4.Load(li*4));
    const float _e53 = connection_factor(_e49, d2_9, _e52, w_res);
    c_3.e = (_e47 * _e53);
    Connection _e55 = c_3;
    const Connection connection_1 = _e55;
    return connection_1;
}

float mis_weight(float pdf_a_1, float pdf_b_1)
{
    const float _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
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

float bvh_importance(uint nodes_2, uint i_2, float3 x_5, float3 n_4)
{
    const GpuLightBvhNode _e4 = light_bvh_node(nodes_2, i_2);
    const float _e11 = light_importance(_e4.center_, _e4.radius, _e4.phi, _e4.axis, _e4.cos_o, _e4.cos_e, x_5, n_4);
    return _e11;
}

float bvh_first(uint nodes_3, uint i_3, float3 x_6, float3 n_5)
{
    bool local_11 = (bool)0;

    const GpuLightBvhNode _e4 = light_bvh_node(nodes_3, i_3);
    uint j = _e4.second;
    if (!((j <= (i_3 + 1u)))) {
        const uint _e12 = light_bvh_count(nodes_3);
        local_11 = (j >= _e12);
    } else {
        local_11 = true;
    }
    bool _e15 = local_11;
    if (_e15) {
        return -1.0;
    }
    const float _e19 = bvh_importance(nodes_3, (i_3 + 1u), x_6, n_5);
    const float _e20 = bvh_importance(nodes_3, j, x_6, n_5);
    const float _e21 = bvh_first_prob(_e19, _e20);
    return _e21;
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

BvhPick light_bvh_sample(uint nodes_4, float3 x_7, float3 n_6, float u_in)
{
    BvhPick pick = (BvhPick)0;
    float u_2 = (float)0;
    uint i_4 = 0u;
    float pmf = 1.0;
    bool local_12 = (bool)0;

    const BvhPick _e4 = bvh_pick_none();
    pick = _e4;
    u_2 = u_in;
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e11 = i_4;
        const uint _e12 = light_bvh_count(nodes_4);
        if ((_e11 < _e12)) {
        } else {
            break;
        }
        {
            uint _e14 = i_4;
            const GpuLightBvhNode _e15 = light_bvh_node(nodes_4, _e14);
            if ((_e15.second == LIGHT_BVH_LEAF)) {
                uint _e19 = i_4;
                if (!((_e19 > 0u))) {
                    const float _e26 = bvh_importance(nodes_4, 0u, x_7, n_6);
                    local_12 = (_e26 > 0.0);
                } else {
                    local_12 = true;
                }
                bool _e30 = local_12;
                if (_e30) {
                    pick.light = _e15.light;
                    float _e34 = pmf;
                    pick.pmf = _e34;
                }
                BvhPick _e35 = pick;
                const BvhPick bvhpick_1 = _e35;
                return bvhpick_1;
            }
            uint _e36 = i_4;
            const float _e37 = bvh_first(nodes_4, _e36, x_7, n_6);
            if ((_e37 < 0.0)) {
                BvhPick _e40 = pick;
                const BvhPick bvhpick_2 = _e40;
                return bvhpick_2;
            }
            float _e41 = u_2;
            bool first_1 = (_e41 < _e37);
            float _e43 = pmf;
            pmf = (_e43 * (first_1 ? _e37 : (1.0 - _e37)));
            float _e48 = u_2;
            const float _e49 = bvh_remap_u(_e48, _e37, first_1);
            u_2 = _e49;
            uint _e51 = i_4;
            i_4 = (first_1 ? (_e51 + 1u) : _e15.second);
        }
    }
    BvhPick _e55 = pick;
    const BvhPick bvhpick_3 = _e55;
    return bvhpick_3;
}

float light_bvh_pmf(uint nodes_5, uint leaf, float3 x_8, float3 n_7)
{
    uint i_5 = 0u;
    float pmf_1 = 1.0;
    bool local_13 = (bool)0;
    bool local_14 = (bool)0;

    const uint _e4 = light_bvh_count(nodes_5);
    if ((leaf >= _e4)) {
        return 0.0;
    }
    uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e11 = i_5;
        const uint _e12 = light_bvh_count(nodes_5);
        if ((_e11 < _e12)) {
        } else {
            break;
        }
        {
            uint _e14 = i_5;
            const GpuLightBvhNode _e15 = light_bvh_node(nodes_5, _e14);
            if ((_e15.second == LIGHT_BVH_LEAF)) {
                uint _e19 = i_5;
                if ((_e19 == leaf)) {
                    uint _e23 = i_5;
                    if (!((_e23 > 0u))) {
                        const float _e30 = bvh_importance(nodes_5, 0u, x_8, n_7);
                        local_14 = (_e30 > 0.0);
                    } else {
                        local_14 = true;
                    }
                    bool _e34 = local_14;
                    local_13 = _e34;
                } else {
                    local_13 = false;
                }
                bool _e36 = local_13;
                if (_e36) {
                    float _e37 = pmf_1;
                    return _e37;
                }
                return 0.0;
            }
            uint _e39 = i_5;
            const float _e40 = bvh_first(nodes_5, _e39, x_8, n_7);
            if ((_e40 < 0.0)) {
                return 0.0;
            }
            bool first_2 = (leaf < _e15.second);
            float _e46 = pmf_1;
            pmf_1 = (_e46 * (first_2 ? _e40 : (1.0 - _e40)));
            uint _e52 = i_5;
            i_5 = (first_2 ? (_e52 + 1u) : _e15.second);
        }
    }
    return 0.0;
}

float select_pdf(uint li_1, float3 x_9, float3 n_8, uint nee, bool in_range)
{
    uint _e9 = asuint(light_cones.Load(40+li_1*48));
    const float _e10 = light_bvh_pmf(BVH, _e9, x_9, n_8);
    return _e10;
}

float light_pdf(uint li_2, float3 x_10, float3 n_9, float3 y_1, uint nee_1, bool in_range_1)
{
    GpuLight l_5 = ConstructGpuLight(asfloat(lights.Load3(li_2*64+0)), asuint(lights.Load(li_2*64+12)), asfloat(lights.Load3(li_2*64+16)), asfloat(lights.Load(li_2*64+28)), asfloat(lights.Load3(li_2*64+32)), asfloat(lights.Load(li_2*64+44)), asfloat(lights.Load3(li_2*64+48)), asuint(lights.Load(li_2*64+60)));
    float3 v_5 = (x_10 - y_1);
    float d2_10 = dot(v_5, v_5);
    const float3 _e11 = light_normal(l_5);
    float cos_y_1 = ((d2_10 > 0.0) ? dot(_e11, (v_5 / (sqrt(d2_10)).xxx)) : 0.0);
    const float _e20 = select_pdf(li_2, x_10, n_9, nee_1, in_range_1);
    float _e23 = asfloat(rt2_4.Load(li_2*4));
    const float _e24 = light_area(l_5);
    const float _e25 = light_strategy_pdf(_e20, _e23, d2_10, _e24, cos_y_1);
    return _e25;
}

float3 shade_pick(uint li_3, float3 x_11, float3 n_10, float3 ng_2, float w_3, uint nee_2, float u1_3, float u2_3)
{
    float mis = 1.0;
    bool local_15 = (bool)0;

    float _e10 = params.eps;
    const Connection _e11 = connect(li_3, x_11, n_10, ng_2, w_3, u1_3, u2_3, _e10);
    GpuLight _e16 = ConstructGpuLight(asfloat(lights.Load3(li_3*64+0)), asuint(lights.Load(li_3*64+12)), asfloat(lights.Load3(li_3*64+16)), asfloat(lights.Load(li_3*64+28)), asfloat(lights.Load3(li_3*64+32)), asfloat(lights.Load(li_3*64+44)), asfloat(lights.Load3(li_3*64+48)), asuint(lights.Load(li_3*64+60)));
    const float _e17 = light_area(_e16);
    if ((_e17 > 0.0)) {
        local_15 = (_e11.cos_x > 0.0);
    } else {
        local_15 = false;
    }
    bool _e26 = local_15;
    if (_e26) {
        const float _e29 = light_pdf(li_3, x_11, n_10, _e11.y, nee_2, true);
        const float _e31 = cosine_pdf(_e11.cos_x);
        const float _e32 = mis_weight(_e29, _e31);
        mis = _e32;
    }
    float _e34 = mis;
    return (_e11.e * _e34);
}

GpuPathVertex ConstructGpuPathVertex(float3 arg0, uint arg1, float3 arg2, float arg3, float3 arg4, float arg5, float3 arg6, float arg7) {
    GpuPathVertex ret = (GpuPathVertex)0;
    ret.position = arg0;
    ret.alive = arg1;
    ret.normal = arg2;
    ret.pad = arg3;
    ret.weight = arg4;
    ret.pad1_ = arg5;
    ret.gnormal = arg6;
    ret.pad2_ = arg7;
    return ret;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    uint h = (uint)0;
    float3 sum = (0.0).xxx;

    uint i_6 = gid.x;
    uint _e4 = params.point_count;
    if ((i_6 >= _e4)) {
        return;
    }
    GpuPathVertex vtx = ConstructGpuPathVertex(asfloat(vertices_.Load3(i_6*64+0)), asuint(vertices_.Load(i_6*64+12)), asfloat(vertices_.Load3(i_6*64+16)), asfloat(vertices_.Load(i_6*64+28)), asfloat(vertices_.Load3(i_6*64+32)), asfloat(vertices_.Load(i_6*64+44)), asfloat(vertices_.Load3(i_6*64+48)), asfloat(vertices_.Load(i_6*64+60)));
    if ((vtx.alive == 0u)) {
        candidates.Store(i_6*4, asuint(0u));
        return;
    }
    float3 x_12 = vtx.position;
    float3 n_13 = vtx.normal;
    float3 ng_3 = vtx.gnormal;
    uint _e20 = params.seed;
    uint _e23 = params.frame;
    const uint _e24 = point_stream(_e20, i_6, _e23);
    const uint _e25 = pick_stream(_e24);
    h = _e25;
    candidates.Store(i_6*4, asuint(0u));
    uint _e33 = h;
    const uint _e34 = pcg_hash(_e33);
    h = _e34;
    uint _e35 = h;
    const float _e36 = xi_from_bits(_e35);
    const BvhPick _e38 = light_bvh_sample(BVH, x_12, n_13, _e36);
    uint li_4 = _e38.light;
    float pmf_2 = _e38.pmf;
    uint _e41 = h;
    const uint _e42 = pcg_hash(_e41);
    h = _e42;
    uint _e43 = h;
    const float _e44 = xi_from_bits(_e43);
    uint _e45 = h;
    const uint _e46 = pcg_hash(_e45);
    h = _e46;
    uint _e47 = h;
    const float _e48 = xi_from_bits(_e47);
    if ((pmf_2 > 0.0)) {
        const float3 _e54 = shade_pick(li_4, x_12, n_13, ng_3, (1.0 / pmf_2), 0u, _e44, _e48);
        sum = _e54;
    }
    float3 _e56 = sum;
    float3 add = (vtx.weight * _e56);
    const bool _e58 = finite3_(add);
    if (_e58) {
        float4 _e61 = asfloat(radiance.Load4(i_6*16));
        radiance.Store4(i_6*16, asuint((_e61 + float4(add, 0.0))));
        return;
    } else {
        return;
    }
}
