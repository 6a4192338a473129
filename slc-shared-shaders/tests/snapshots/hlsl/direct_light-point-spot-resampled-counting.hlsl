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
static const uint RESERVOIR_FULL = 4294967295u;
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

static uint rays_cast = (uint)0;
static uint nodes_visited = (uint)0;
ByteAddressBuffer geo_nodes : register(t6, space1);
ByteAddressBuffer geo_tris : register(t7, space1);
cbuffer view : register(b0) { ViewParams view; }
Texture2D<float4> position_tex : register(t1);
Texture2D<float4> normal_tex : register(t2);
RWTexture2D<float4> out_tex : register(u3);
ByteAddressBuffer lights : register(t1, space1);
ByteAddressBuffer rt2_3 : register(t2, space1);
ByteAddressBuffer r2_3 : register(t3, space1);
ByteAddressBuffer bsh_nodes : register(t4, space1);
RWByteAddressBuffer counters : register(u8);
static uint evaluations = (uint)0;

float to_f32_(uint u)
{
    return float(u);
}

uint mul_lo_u32_(uint a, uint b_1)
{
    return (a * b_1);
}

uint add_wrap_u32_(uint a_1, uint b_2)
{
    return (a_1 + b_2);
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
    float3 v_2 = (x_1 - c);
    return (dot(v_2, v_2) <= (r_1 * r_1));
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

float connection_cosine(float3 x_2, float3 y, float3 n, float3 ng, float r2_1)
{
    bool local_4 = (bool)0;
    bool local_5 = (bool)0;

    float3 v_3 = (x_2 - y);
    float d2_6 = dot(v_3, v_3);
    const bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local_4 = !((d2_6 > 0.0));
    } else {
        local_4 = true;
    }
    bool _e16 = local_4;
    if (_e16) {
        return 0.0;
    }
    float3 w_6 = (v_3 / (sqrt(d2_6)).xxx);
    float cos_x_1 = -(dot(n, w_6));
    if (!((cos_x_1 <= 0.0))) {
        local_5 = (dot(ng, w_6) >= 0.0);
    } else {
        local_5 = true;
    }
    bool _e32 = local_5;
    if (_e32) {
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

float weighted_threshold(float w_sum, float u_2)
{
    return (w_sum / (1.0 - u_2));
}

float resample_target(float3 c_1)
{
    return (((c_1.x + c_1.y) + c_1.z) * 0.33333334);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

float slot_target(float3 c_2, uint slot, uint k_2)
{
    if ((k_2 < 3u)) {
        const float _e5 = resample_target(c_2);
        return _e5;
    }
    uint j_2 = naga_mod(slot, 3u);
    if ((j_2 == 0u)) {
        return c_2.x;
    }
    if ((j_2 == 1u)) {
        return c_2.y;
    }
    return c_2.z;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

float3 slot_share(uint slot_1, uint k_3)
{
    if ((k_3 < 3u)) {
        const float _e4 = to_f32_(k_3);
        float w_7 = (1.0 / _e4);
        return float3(w_7, w_7, w_7);
    }
    uint j_3 = naga_mod(slot_1, 3u);
    const float _e15 = to_f32_(naga_div(((k_3 + 2u) - j_3), 3u));
    float w_8 = (1.0 / _e15);
    if ((j_3 == 0u)) {
        return float3(w_8, 0.0, 0.0);
    }
    if ((j_3 == 1u)) {
        return float3(0.0, w_8, 0.0);
    }
    return float3(0.0, 0.0, w_8);
}

float smith_root(float cos_, float alpha)
{
    float a2_ = (alpha * alpha);
    return sqrt((((cos_ * cos_) * (1.0 - a2_)) + a2_));
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

float cone_cos_of(float3 v, float d2_4, float a_2, float3 d)
{
    bool local_6 = (bool)0;
    bool local_7 = (bool)0;

    float vd = dot(v, d);
    float h2_ = (d2_4 - (a_2 * a_2));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_7 = ((vd * vd) >= h2_);
        } else {
            local_7 = false;
        }
        bool _e19 = local_7;
        local_6 = _e19;
    } else {
        local_6 = true;
    }
    bool _e21 = local_6;
    if (_e21) {
        return 1.0;
    }
    float3 c_6 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_6, c_6)) * a_2)) / d2_4), 1.0);
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

float range_scale_toward(float4 rl_1, float3 center_1, float radius_1, float3 p_1, float3 r_2)
{
    if ((rl_1.w <= 1.0)) {
        return 1.0;
    }
    const float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_2);
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

float ray_triangle(float3 o_1, float3 d_3, float3 a_3, float3 b_3, float3 c_3, float t_min, float t_max_1)
{
    bool local_8 = (bool)0;
    bool local_9 = (bool)0;
    bool local_10 = (bool)0;

    float3 e1_ = (b_3 - a_3);
    float3 e2_ = (c_3 - a_3);
    float3 p_2 = cross(d_3, e2_);
    float det = dot(e1_, p_2);
    if ((abs(det) <= 0.0)) {
        return -1.0;
    }
    float inv = (1.0 / det);
    float3 s_4 = (o_1 - a_3);
    float u_3 = (dot(s_4, p_2) * inv);
    if (!((u_3 < 0.0))) {
        local_8 = (u_3 > 1.0);
    } else {
        local_8 = true;
    }
    bool _e28 = local_8;
    if (_e28) {
        return -1.0;
    }
    float3 q_1 = cross(s_4, e1_);
    float v_5 = (dot(d_3, q_1) * inv);
    if (!((v_5 < 0.0))) {
        local_9 = ((u_3 + v_5) > 1.0);
    } else {
        local_9 = true;
    }
    bool _e42 = local_9;
    if (_e42) {
        return -1.0;
    }
    float t_3 = (dot(e2_, q_1) * inv);
    if ((t_3 > t_min)) {
        local_10 = (t_3 < t_max_1);
    } else {
        local_10 = false;
    }
    bool _e51 = local_10;
    if (_e51) {
        return t_3;
    }
    return -1.0;
}

float3 light_intensity(GpuLight l, float3 w_2)
{
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            const float _e11 = spot_falloff(dot(l.p1_, w_2), l.a, l.b, l.p2_.x);
            return (l.intensity * _e11);
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
    uint node_2 = 0u;
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
        uint _e21 = node_2;
        GpuGeoNode n_7 = ConstructGpuGeoNode(asfloat(geo_nodes.Load3(_e21*32+0)), asuint(geo_nodes.Load(_e21*32+12)), asfloat(geo_nodes.Load3(_e21*32+16)), asuint(geo_nodes.Load(_e21*32+28)));
        uint _e25 = nodes_visited;
        nodes_visited = (_e25 + 1u);
        float _e31 = hit.t;
        const float _e32 = ray_aabb(o_2, _e14, n_7.bmin, n_7.bmax, _e31);
        if ((_e32 >= 0.0)) {
            if ((n_7.count > 0u)) {
                i = n_7.first;
                uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
                bool loop_init = true;
                while(true) {
                    if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
                    loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                    if (!loop_init) {
                        uint _e62 = i;
                        i = (_e62 + 1u);
                    }
                    loop_init = false;
                    uint _e40 = i;
                    if ((_e40 < (n_7.first + n_7.count))) {
                    } else {
                        break;
                    }
                    {
                        uint _e46 = i;
                        GpuTriangle t_4 = ConstructGpuTriangle(asfloat(geo_tris.Load3(_e46*48+0)), asuint(geo_tris.Load(_e46*48+12)), asfloat(geo_tris.Load3(_e46*48+16)), asuint(geo_tris.Load(_e46*48+28)), asfloat(geo_tris.Load3(_e46*48+32)), asuint(geo_tris.Load(_e46*48+44)));
                        float _e53 = hit.t;
                        const float _e54 = ray_triangle(o_2, d_4, t_4.v0_, t_4.v1_, t_4.v2_, t_min_1, _e53);
                        if ((_e54 > 0.0)) {
                            hit.t = _e54;
                            uint _e59 = i;
                            hit.tri = _e59;
                            if (any_hit) {
                                GeoHit _e60 = hit;
                                const GeoHit geohit_1 = _e60;
                                return geohit_1;
                            }
                        }
                    }
                }
            } else {
                uint _e64 = sp;
                if ((_e64 < 64u)) {
                    uint _e67 = sp;
                    stack[min(uint(_e67), 63u)] = (n_7.first + 1u);
                    uint _e72 = sp;
                    sp = (_e72 + 1u);
                }
                node_2 = n_7.first;
                continue;
            }
        }
        uint _e76 = sp;
        if ((_e76 == 0u)) {
            break;
        }
        uint _e79 = sp;
        sp = (_e79 - 1u);
        uint _e82 = sp;
        uint _e84 = stack[min(uint(_e82), 63u)];
        node_2 = _e84;
    }
    GeoHit _e85 = hit;
    const GeoHit geohit_2 = _e85;
    return geohit_2;
}

bool occluded(float3 a_4, float3 b_4)
{
    float3 dv = (b_4 - a_4);
    float len_1 = length(dv);
    if ((len_1 <= 0.0)) {
        return false;
    }
    const float _e7 = shadow_margin(len_1);
    uint _e9 = rays_cast;
    rays_cast = (_e9 + 1u);
    const GeoHit _e16 = trace(a_4, (dv / (len_1).xxx), _e7, (len_1 - _e7), true);
    return (_e16.tri != NO_LIGHT);
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

float bsh_inner_scale(float a_5, float3 v_1, float d2_5, float3 r_3, float4 rl_2)
{
    const float _e5 = cone_cos_of(v_1, d2_5, a_5, r_3);
    const float _e8 = range_scale_at(rl_2, (_e5 + 2e-6));
    return _e8;
}

bool bsh_reaches(BshNode node_3, float3 x_4, float3 r_4, float4 rl_3)
{
    bool local_11 = (bool)0;
    bool local_12 = (bool)0;

    const bool _e6 = sphere_contains_point(node_3.center_, node_3.radius, x_4);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        const bool _e20 = sphere_contains_point(node_3.center_, (node_3.radius * (rl_3.w * 1.0001)), x_4);
        local_11 = !(_e20);
    } else {
        local_11 = true;
    }
    bool _e23 = local_11;
    if (_e23) {
        return false;
    }
    const float _e25 = bsh_range_bound(node_3);
    float3 v_6 = (x_4 - node_3.center_);
    float d2_7 = dot(v_6, v_6);
    float reach_max = (node_3.extent + ((rl_3.w * 1.001) * _e25));
    if ((d2_7 > (reach_max * reach_max))) {
        return false;
    }
    if ((node_3.child == BSH_NONE)) {
        const float _e43 = range_scale_toward(rl_3, node_3.center_, node_3.extent, x_4, r_4);
        const float _e46 = bsh_scaled_radius(node_3, sqrt(_e43));
        const bool _e47 = sphere_contains_point(node_3.center_, _e46, x_4);
        return _e47;
    }
    const float _e50 = bsh_inner_scale(node_3.extent, -(v_6), d2_7, r_4, rl_3);
    float s_c = (_e50 * 1.001);
    float reach = (node_3.extent + (sqrt(s_c) * _e25));
    if ((d2_7 <= ((node_3.radius * node_3.radius) * s_c))) {
        local_12 = (d2_7 <= (reach * reach));
    } else {
        local_12 = false;
    }
    bool _e67 = local_12;
    return _e67;
}

uint bsh_next_leaf_lobe(uint nodes_3, uint start, float3 x_5, float3 r_5, float4 rl_4)
{
    uint i_2 = (uint)0;

    i_2 = start;
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e6 = i_2;
        if ((_e6 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e9 = i_2;
            const BshNode _e10 = bsh_node(nodes_3, _e9);
            const bool _e11 = bsh_reaches(_e10, x_5, r_5, rl_4);
            if (_e11) {
                if ((_e10.child == BSH_NONE)) {
                    uint _e15 = i_2;
                    return _e15;
                }
                i_2 = _e10.child;
            } else {
                i_2 = _e10.next;
            }
        }
    }
    return BSH_NONE;
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

Connection connect_record(GpuLight l_2, float3 x_6, float3 n_1, float3 ng_1, float r2_2, float rt2_2, float w_res, float u1_1, float u2_1, float eps, bool trace_1)
{
    Connection c_4 = (Connection)0;
    bool local_13 = (bool)0;
    bool local_14 = (bool)0;

    c_4.e = (0.0).xxx;
    const float3 _e16 = light_point(l_2, u1_1, u2_1);
    c_4.y = _e16;
    float3 _e19 = c_4.y;
    const float _e20 = connection_cosine(x_6, _e19, n_1, ng_1, r2_2);
    c_4.cos_x = _e20;
    float _e22 = c_4.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            float3 _e33 = c_4.y;
            const bool _e34 = occluded((x_6 + (ng_1 * eps)), _e33);
            local_14 = _e34;
        } else {
            local_14 = false;
        }
        bool _e36 = local_14;
        local_13 = _e36;
    } else {
        local_13 = true;
    }
    bool _e38 = local_13;
    if (_e38) {
        Connection _e39 = c_4;
        const Connection connection = _e39;
        return connection;
    }
    float3 _e41 = c_4.y;
    float3 v_7 = (x_6 - _e41);
    float d2_8 = dot(v_7, v_7);
    const float3 _e48 = light_intensity(l_2, (v_7 / (sqrt(d2_8)).xxx));
    float _e50 = c_4.cos_x;
    const float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
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

Connection connect_traced(uint li, float3 x_7, float3 n_2, float3 ng_2, float s, float w_res_1, float u1_2, float u2_2, float eps_1, bool trace_2)
{
    GpuLight _e12 = ConstructGpuLight(asfloat(lights.Load3(li*64+0)), asuint(lights.Load(li*64+12)), asfloat(lights.Load3(li*64+16)), asfloat(lights.Load(li*64+28)), asfloat(lights.Load3(li*64+32)), asfloat(lights.Load(li*64+44)), asfloat(lights.Load3(li*64+48)), asuint(lights.Load(li*64+60)));
    float _e15 = asfloat(r2_3.Load(li*4));
    float _e19 = asfloat(rt2_3.Load(li*4));
    const Connection _e21 = connect_record(_e12, x_7, n_2, ng_2, (s * _e15), (s * _e19), w_res_1, u1_2, u2_2, eps_1, trace_2);
    const Connection connection_2 = _e21;
    return connection_2;
}

float4 surface_at(int2 texel)
{
    float4 p_3 = position_tex.Load(int3(texel, int(0)));
    return ((p_3.w > 0.0) ? float4(p_3.xyz, 1.0) : (0.0).xxxx);
}

void counter_add(uint f, uint n_3)
{
    uint _e6; counters.InterlockedAdd((2u * f)*4, n_3, _e6);
    if (((_e6 + n_3) < _e6)) {
        uint _e16; counters.InterlockedAdd(((2u * f) + 1u)*4, 1u, _e16);
        return;
    } else {
        return;
    }
}

Shaded shade_connection(Connection c_5, float3 x_8, float3 n_4, Material m_1)
{
    Shaded s_1 = (Shaded)0;

    s_1.e = c_5.e;
    s_1.diffuse = (0.0).xxx;
    s_1.specular = (0.0).xxx;
    Shaded _e13 = s_1;
    const Shaded shaded = _e13;
    return shaded;
}

Shaded shade_pick_traced(uint li_1, float3 x_9, float3 n_5, float3 r_6, float4 rl_5, Material m_2, float w_3, float u1_3, float u2_3, float eps_2, bool trace_3)
{
    const Connection _e12 = connect_traced(li_1, x_9, n_5, n_5, 1.0, w_3, u1_3, u2_3, eps_2, trace_3);
    const Shaded _e13 = shade_connection(_e12, x_9, n_5, m_2);
    const Shaded shaded_1 = _e13;
    return shaded_1;
}

Shaded shade_pick(uint li_2, float3 x_10, float3 n_6, float3 r_7, float4 rl_6, Material m_3, float w_4, float u1_4, float u2_4, float eps_3)
{
    const Shaded _e11 = shade_pick_traced(li_2, x_10, n_6, r_7, rl_6, m_3, w_4, u1_4, u2_4, eps_3, true);
    const Shaded shaded_2 = _e11;
    return shaded_2;
}

Shaded ConstructShaded(float3 arg0, float3 arg1, float3 arg2) {
    Shaded ret = (Shaded)0;
    ret.e = arg0;
    ret.diffuse = arg1;
    ret.specular = arg2;
    return ret;
}

Shaded add(Shaded a_6, Shaded b_5)
{
    const Shaded shaded_3 = ConstructShaded((a_6.e + b_5.e), (a_6.diffuse + b_5.diffuse), (a_6.specular + b_5.specular));
    return shaded_3;
}

Shaded scaled(Shaded s_2, float3 w_5)
{
    const Shaded shaded_4 = ConstructShaded((s_2.e * w_5), (s_2.diffuse * w_5), (s_2.specular * w_5));
    return shaded_4;
}

typedef uint ret_first_holders[8];
ret_first_holders first_holders(uint2 keys_1[8], bool held_1[8])
{
    uint first[8] = (uint[8])0;
    uint k_4 = 0u;
    uint j_1 = (uint)0;
    bool local_15 = (bool)0;
    bool local_16 = (bool)0;

    uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e45 = k_4;
            k_4 = (_e45 + 1u);
        }
        loop_init_1 = false;
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
            j_1 = 0u;
            uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e42 = j_1;
                    j_1 = (_e42 + 1u);
                }
                loop_init_2 = false;
                uint _e17 = j_1;
                uint _e18 = k_4;
                if ((_e17 < _e18)) {
                    uint _e22 = k_4;
                    local_15 = held_1[min(uint(_e22), 7u)];
                } else {
                    local_15 = false;
                }
                bool _e25 = local_15;
                if (_e25) {
                } else {
                    break;
                }
                {
                    uint _e26 = j_1;
                    if (held_1[min(uint(_e26), 7u)]) {
                        uint _e30 = j_1;
                        uint _e32 = k_4;
                        local_16 = all((keys_1[min(uint(_e30), 7u)] == keys_1[min(uint(_e32), 7u)]));
                    } else {
                        local_16 = false;
                    }
                    bool _e37 = local_16;
                    if (_e37) {
                        uint _e38 = k_4;
                        uint _e40 = j_1;
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

float3 output_of(Shaded s_3)
{
    return s_3.e;
}

[numthreads(8, 8, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;
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
    uint b = (uint)0;
    uint q = (uint)0;
    bool local_2 = (bool)0;
    uint2 keys[8] = (uint2[8])0;
    bool held[8] = (bool[8])0;
    uint k = 0u;
    uint k_1 = 0u;
    float3 w = (float3)0;
    uint j = (uint)0;
    bool local_3 = (bool)0;

    uint _e4 = view.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = view.height;
        local = (gid.y >= _e12);
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    int2 texel_1 = int2(int(gid.x), int(gid.y));
    const float4 _e21 = surface_at(texel_1);
    float4 _e24 = normal_tex.Load(int3(texel_1, int(0)));
    float3 nn = _e24.xyz;
    float len2_ = dot(nn, nn);
    if (!((_e21.w <= 0.0))) {
        local_1 = !((len2_ > 0.0));
    } else {
        local_1 = true;
    }
    bool _e37 = local_1;
    if (_e37) {
        out_tex[texel_1] = (0.0).xxxx;
        return;
    }
    float3 x_11 = _e21.xyz;
    float3 n_8 = (nn / (sqrt(len2_)).xxx);
    r = n_8;
    float4 _e53 = lobe;
    const float4 _e54 = range_lobe(_e53);
    float _e57 = view.shadow_offset;
    float3 _e60 = view.eye;
    float eps_4 = (_e57 * length((_e60 - x_11)));
    uint _e66 = view.seed;
    uint _e70 = view.width;
    uint _e76 = view.frame;
    const uint _e77 = point_stream(_e66, ((gid.y * _e70) + gid.x), _e76);
    const uint _e78 = pick_stream(_e77);
    h = _e78;
    hc = _e77;
    const uint _e100 = bsh_first(BSH);
    float3 _e101 = r;
    const uint _e102 = bsh_next_leaf_lobe(BSH, _e100, x_11, _e101, _e54);
    b = _e102;
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e177 = b;
            uint _e180 = asuint(bsh_nodes.Load(20+_e177*32));
            float3 _e181 = r;
            const uint _e182 = bsh_next_leaf_lobe(BSH, _e180, x_11, _e181, _e54);
            b = _e182;
        }
        loop_init_3 = false;
        uint _e104 = b;
        if ((_e104 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e107 = count;
            count = (_e107 + 1u);
            uint _e111 = b;
            uint li_3 = asuint(bsh_nodes.Load(24+_e111*32));
            uint _e115 = h;
            const uint _e116 = pcg_hash(_e115);
            h = _e116;
            uint _e117 = h;
            const float _e118 = xi_from_bits(_e117);
            uint _e119 = h;
            const uint _e120 = pcg_hash(_e119);
            h = _e120;
            uint _e121 = h;
            const float _e122 = xi_from_bits(_e121);
            float2 u_4 = float2(_e118, _e122);
            float3 _e124 = r;
            Material _e125 = m;
            const Shaded _e130 = shade_pick_traced(li_3, x_11, n_8, _e124, _e54, _e125, 1.0, u_4.x, u_4.y, eps_4, false);
            const float3 _e131 = output_of(_e130);
            uint _e133 = evaluations;
            evaluations = (_e133 + 1u);
            const float _e136 = resample_target(_e131);
            if ((_e136 > 0.0)) {
                float3 _e139 = total;
                total = (_e139 + _e131);
                q = 0u;
                uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
                bool loop_init_4 = true;
                while(true) {
                    if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
                    loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                    if (!loop_init_4) {
                        uint _e173 = q;
                        q = (_e173 + 1u);
                    }
                    loop_init_4 = false;
                    uint _e143 = q;
                    if ((_e143 < K)) {
                    } else {
                        break;
                    }
                    {
                        uint _e146 = q;
                        const float _e148 = slot_target(_e131, _e146, K);
                        float3 _e149 = total;
                        uint _e150 = q;
                        const float _e152 = slot_target(_e149, _e150, K);
                        if ((_e148 > 0.0)) {
                            uint _e157 = q;
                            float _e159 = threshold[min(uint(_e157), 7u)];
                            local_2 = (_e152 > _e159);
                        } else {
                            local_2 = false;
                        }
                        bool _e162 = local_2;
                        if (_e162) {
                            uint _e163 = q;
                            slot_light[min(uint(_e163), 7u)] = li_3;
                            uint _e165 = q;
                            slot_u[min(uint(_e165), 7u)] = u_4;
                            uint _e167 = q;
                            slot_p[min(uint(_e167), 7u)] = _e148;
                            uint _e169 = q;
                            const float _e171 = next_threshold(_e152, hc);
                            threshold[min(uint(_e169), 7u)] = _e171;
                        }
                    }
                }
            }
        }
    }
    uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e205 = k;
            k = (_e205 + 1u);
        }
        loop_init_5 = false;
        uint _e187 = k;
        if ((_e187 < K)) {
        } else {
            break;
        }
        {
            uint _e190 = k;
            uint _e192 = k;
            uint _e194 = slot_light[min(uint(_e192), 7u)];
            keys[min(uint(_e190), 7u)] = uint2(_e194, 0u);
            uint _e197 = k;
            uint _e199 = k;
            float _e201 = slot_p[min(uint(_e199), 7u)];
            held[min(uint(_e197), 7u)] = (_e201 > 0.0);
        }
    }
    uint2 _e207[8] = keys;
    bool _e208[8] = held;
    const uint _e209[8] = first_holders(_e207, _e208);
    uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
    bool loop_init_6 = true;
    while(true) {
        if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_6) {
            uint _e272 = k_1;
            k_1 = (_e272 + 1u);
        }
        loop_init_6 = false;
        uint _e212 = k_1;
        if ((_e212 < K)) {
        } else {
            break;
        }
        {
            w = (0.0).xxx;
            uint _e218 = k_1;
            uint _e220 = k_1;
            bool first_1 = (_e209[min(uint(_e218), 7u)] == _e220);
            uint _e222 = k_1;
            j = _e222;
            uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
            bool loop_init_7 = true;
            while(true) {
                if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
                loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                if (!loop_init_7) {
                    uint _e250 = j;
                    j = (_e250 + 1u);
                }
                loop_init_7 = false;
                uint _e224 = j;
                if ((_e224 < K)) {
                    local_3 = first_1;
                } else {
                    local_3 = false;
                }
                bool _e230 = local_3;
                if (_e230) {
                } else {
                    break;
                }
                {
                    uint _e231 = j;
                    uint _e233 = k_1;
                    if ((_e209[min(uint(_e231), 7u)] == _e233)) {
                        float3 _e235 = w;
                        float3 _e236 = total;
                        uint _e237 = j;
                        const float _e239 = slot_target(_e236, _e237, K);
                        uint _e240 = j;
                        float _e242 = slot_p[min(uint(_e240), 7u)];
                        uint _e244 = j;
                        const float3 _e246 = slot_share(_e244, K);
                        w = (_e235 + ((_e239 / _e242) * _e246));
                    }
                }
            }
            if (first_1) {
                Shaded _e252 = t;
                uint _e253 = k_1;
                uint _e255 = slot_light[min(uint(_e253), 7u)];
                float3 _e256 = r;
                Material _e257 = m;
                uint _e259 = k_1;
                float _e262 = slot_u[min(uint(_e259), 7u)].x;
                uint _e263 = k_1;
                float _e266 = slot_u[min(uint(_e263), 7u)].y;
                const Shaded _e267 = shade_pick(_e255, x_11, n_8, _e256, _e54, _e257, 1.0, _e262, _e266, eps_4);
                float3 _e268 = w;
                const Shaded _e269 = scaled(_e267, _e268);
                const Shaded _e270 = add(_e252, _e269);
                t = _e270;
            }
        }
    }
    float3 _e276 = t.e;
    uint _e277 = count;
    out_tex[texel_1] = float4(_e276, float(_e277));
    counter_add(DIRECT_COUNT_PIXELS, 1u);
    uint _e283 = count;
    counter_add(DIRECT_COUNT_CANDIDATES, _e283);
    uint _e286 = evaluations;
    counter_add(DIRECT_COUNT_EVALUATIONS, _e286);
    uint _e289 = rays_cast;
    counter_add(DIRECT_COUNT_RAYS, _e289);
    uint _e292 = nodes_visited;
    counter_add(DIRECT_COUNT_NODES, _e292);
    return;
}
