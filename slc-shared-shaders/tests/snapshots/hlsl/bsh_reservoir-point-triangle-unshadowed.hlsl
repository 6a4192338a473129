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

ByteAddressBuffer bsh_nodes : register(t6);
ByteAddressBuffer lights : register(t3);
ByteAddressBuffer r2_3 : register(t5);
ByteAddressBuffer rt2_3 : register(t4);
cbuffer params : register(b0) { ShadeParams params; }
ByteAddressBuffer points : register(t1);
ByteAddressBuffer normals : register(t2);
RWByteAddressBuffer irradiance : register(u9);

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

bool sphere_contains_point(float3 c, float r, float3 x_1)
{
    float3 v_2 = (x_1 - c);
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

float connection_cosine(float3 x_2, float3 y, float3 n, float3 ng, float r2_1)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;

    float3 v_3 = (x_2 - y);
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

float triangle_lobe(float3 n_1, float area, float3 w_1)
{
    return (area * max(dot(n_1, w_1), 0.0));
}

float3 triangle_sample(float3 a_2, float3 b_2, float3 c_1, float u1_, float u2_)
{
    float su = sqrt(u1_);
    float b0_ = (1.0 - su);
    float b1_ = (u2_ * su);
    return (((a_2 * b0_) + (b_2 * b1_)) + (c_1 * ((1.0 - b0_) - b1_)));
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

uint mul_hi_u32_(uint a_3, uint b_3)
{
    uint a_lo = (a_3 & 65535u);
    uint a_hi = (a_3 >> 16u);
    uint b_lo = (b_3 & 65535u);
    uint b_hi = (b_3 >> 16u);
    uint ll = (a_lo * b_lo);
    uint lh = (a_lo * b_hi);
    uint hl = (a_hi * b_lo);
    uint hh = (a_hi * b_hi);
    uint mid = (((ll >> 16u) + (lh & 65535u)) + (hl & 65535u));
    return (((hh + (lh >> 16u)) + (hl >> 16u)) + (mid >> 16u));
}

uint uniform_index(uint n_2, uint hi, uint lo)
{
    const uint _e3 = mul_lo_u32_(hi, n_2);
    const uint _e4 = mul_hi_u32_(hi, n_2);
    const uint _e5 = mul_hi_u32_(lo, n_2);
    if ((_e3 > (4294967295u - _e5))) {
        return (_e4 + 1u);
    }
    return _e4;
}

uint reservoir_slot(uint n_3, uint k, uint hi_1, uint lo_1)
{
    if ((n_3 <= k)) {
        return (n_3 - 1u);
    }
    const uint _e7 = uniform_index(n_3, hi_1, lo_1);
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
    bool local_2 = (bool)0;
    bool local_3 = (bool)0;

    float vd = dot(v, d);
    float h2_ = (d2_4 - (a_4 * a_4));
    if (!((h2_ <= 0.0))) {
        if ((vd >= 0.0)) {
            local_3 = ((vd * vd) >= h2_);
        } else {
            local_3 = false;
        }
        bool _e19 = local_3;
        local_2 = _e19;
    } else {
        local_2 = true;
    }
    bool _e21 = local_2;
    if (_e21) {
        return 1.0;
    }
    float3 c_6 = cross(v, d);
    return min((((vd * sqrt(h2_)) + (sqrt(dot(c_6, c_6)) * a_4)) / d2_4), 1.0);
}

float cone_cos_toward(float3 center_, float radius, float3 p, float3 d_1)
{
    float3 v_4 = (center_ - p);
    const float _e6 = cone_cos_of(v_4, dot(v_4, v_4), radius, d_1);
    return _e6;
}

float range_scale_at(float4 rl, float cos_t)
{
    float t = (((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0);
    return clamp((rl.x + ((rl.y * rl.z) / (t * t))), 1.0, (rl.w * rl.w));
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

float3 triangle_normal(float3 a_5, float3 b_4, float3 c_2)
{
    bool local_4 = (bool)0;

    float3 n_9 = cross((b_4 - a_5), (c_2 - a_5));
    float l2_ = dot(n_9, n_9);
    if (!(!((l2_ > 0.0)))) {
        local_4 = !((l2_ < 3e38));
    } else {
        local_4 = true;
    }
    bool _e17 = local_4;
    if (_e17) {
        return float3(0.0, 0.0, 0.0);
    }
    return (n_9 / (sqrt(l2_)).xxx);
}

float3 light_intensity(GpuLight l, float3 w_3)
{
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 3u: {
            const float3 _e8 = triangle_normal(l.p0_, l.p1_, l.p2_);
            const float _e10 = triangle_lobe(_e8, l.a, w_3);
            return (l.intensity * _e10);
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

bool occluded(float3 a_6, float3 b_5)
{
    return false;
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

BshNode bsh_node(uint nodes, uint i)
{
    BshNode _e4 = ConstructBshNode(asfloat(bsh_nodes.Load3(i*32+0)), asfloat(bsh_nodes.Load(i*32+12)), asuint(bsh_nodes.Load(i*32+16)), asuint(bsh_nodes.Load(i*32+20)), asuint(bsh_nodes.Load(i*32+24)), asfloat(bsh_nodes.Load(i*32+28)));
    const BshNode bshnode = _e4;
    return bshnode;
}

uint NagaBufferLength(ByteAddressBuffer buffer)
{
    uint ret;
    buffer.GetDimensions(ret);
    return ret;
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

bool bsh_reaches(BshNode node_3, float3 x_3, float3 r_3, float4 rl_3)
{
    bool local_5 = (bool)0;
    bool local_6 = (bool)0;

    const bool _e6 = sphere_contains_point(node_3.center_, node_3.radius, x_3);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        const bool _e20 = sphere_contains_point(node_3.center_, (node_3.radius * (rl_3.w * 1.0001)), x_3);
        local_5 = !(_e20);
    } else {
        local_5 = true;
    }
    bool _e23 = local_5;
    if (_e23) {
        return false;
    }
    float3 v_5 = (x_3 - node_3.center_);
    float d2_7 = dot(v_5, v_5);
    const float _e29 = bsh_reach_bound(node_3, rl_3.w);
    if ((d2_7 > (_e29 * _e29))) {
        return false;
    }
    if ((node_3.child == BSH_NONE)) {
        const float _e38 = range_scale_toward(rl_3, node_3.center_, node_3.extent, x_3, r_3);
        const float _e41 = bsh_scaled_radius(node_3, sqrt(_e38));
        const bool _e42 = sphere_contains_point(node_3.center_, _e41, x_3);
        return _e42;
    }
    const float _e45 = bsh_inner_scale(node_3.extent, -(v_5), d2_7, r_3, rl_3);
    float s_c = (_e45 * 1.001);
    const float _e50 = bsh_range_bound(node_3);
    float reach = (node_3.extent + (sqrt(s_c) * _e50));
    if ((d2_7 <= ((node_3.radius * node_3.radius) * s_c))) {
        local_6 = (d2_7 <= (reach * reach));
    } else {
        local_6 = false;
    }
    bool _e63 = local_6;
    return _e63;
}

uint bsh_next_leaf_lobe(uint nodes_3, uint start, float3 x_4, float3 r_4, float4 rl_4)
{
    uint i_1 = (uint)0;

    i_1 = start;
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e6 = i_1;
        if ((_e6 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e9 = i_1;
            const BshNode _e10 = bsh_node(nodes_3, _e9);
            const bool _e11 = bsh_reaches(_e10, x_4, r_4, rl_4);
            if (_e11) {
                if ((_e10.child == BSH_NONE)) {
                    if (((_e10.light & BSH_TAIL) == 0u)) {
                        uint _e20 = i_1;
                        return _e20;
                    }
                    i_1 = _e10.next;
                } else {
                    i_1 = _e10.child;
                }
            } else {
                i_1 = _e10.next;
            }
        }
    }
    return BSH_NONE;
}

BshCursor bsh_cursor(float3 x_5, float3 r_5, float4 rl_5)
{
    BshCursor c_3 = (BshCursor)0;

    c_3.i = 0u;
    c_3.end = 0u;
    const uint _e10 = bsh_first(BSH);
    c_3.next = _e10;
    c_3.cone = (0.0).xx;
    BshCursor _e14 = c_3;
    const BshCursor bshcursor = _e14;
    return bshcursor;
}

uint bsh_cursor_next(inout BshCursor c_4, float3 x_6, float3 r_6, float4 rl_6)
{
    uint _e6 = c_4.next;
    const uint _e7 = bsh_next_leaf_lobe(BSH, _e6, x_6, r_6, rl_6);
    if ((_e7 != BSH_NONE)) {
        uint _e14 = asuint(bsh_nodes.Load(20+_e7*32));
        c_4.next = _e14;
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
        uint hi_2 = h_1;
        uint _e13 = h_1;
        const uint _e14 = pcg_hash(_e13);
        h_1 = _e14;
        uint _e16 = picks.n;
        uint _e18 = h_1;
        const uint _e19 = reservoir_slot(_e16, K, hi_2, _e18);
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

Picks bsh_collect(float3 x_7, float3 r_7, float4 rl_7, uint seed_1)
{
    Picks picks_1 = (Picks)0;
    uint h_2 = (uint)0;
    BshCursor cur = (BshCursor)0;
    uint i_2 = (uint)0;

    picks_1.n = 0u;
    h_2 = seed_1;
    const BshCursor _e8 = bsh_cursor(x_7, r_7, rl_7);
    cur = _e8;
    const uint _e10 = bsh_cursor_next(cur, x_7, r_7, rl_7);
    i_2 = _e10;
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init) {
            const uint _e20 = bsh_cursor_next(cur, x_7, r_7, rl_7);
            i_2 = _e20;
        }
        loop_init = false;
        uint _e12 = i_2;
        if ((_e12 != BSH_NONE)) {
        } else {
            break;
        }
        {
            uint _e16 = i_2;
            uint _e19 = asuint(bsh_nodes.Load(24+_e16*32));
            reservoir_offer(picks_1, h_2, _e19);
        }
    }
    Picks _e21 = picks_1;
    const Picks picks_2 = _e21;
    return picks_2;
}

Connection connect_record(GpuLight l_2, float3 x_8, float3 n_6, float3 ng_1, float r2_2, float rt2_2, float w_res, float u1_2, float u2_2, float eps, bool trace)
{
    Connection c_5 = (Connection)0;
    bool local_7 = (bool)0;
    bool local_8 = (bool)0;

    c_5.e = (0.0).xxx;
    const float3 _e16 = light_point(l_2, u1_2, u2_2);
    c_5.y = _e16;
    float3 _e19 = c_5.y;
    const float _e20 = connection_cosine(x_8, _e19, n_6, ng_1, r2_2);
    c_5.cos_x = _e20;
    float _e22 = c_5.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace) {
            float3 _e33 = c_5.y;
            const bool _e34 = occluded((x_8 + (ng_1 * eps)), _e33);
            local_8 = _e34;
        } else {
            local_8 = false;
        }
        bool _e36 = local_8;
        local_7 = _e36;
    } else {
        local_7 = true;
    }
    bool _e38 = local_7;
    if (_e38) {
        Connection _e39 = c_5;
        const Connection connection = _e39;
        return connection;
    }
    float3 _e41 = c_5.y;
    float3 v_6 = (x_8 - _e41);
    float d2_8 = dot(v_6, v_6);
    const float3 _e48 = light_intensity(l_2, (v_6 / (sqrt(d2_8)).xxx));
    float _e50 = c_5.cos_x;
    const float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_5.e = (_e48 * _e51);
    Connection _e53 = c_5;
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

Connection connect_traced(uint li, float3 x_9, float3 n_7, float3 ng_2, float s_1, float w_res_1, float u1_3, float u2_3, float eps_1, bool trace_1)
{
    GpuLight _e12 = ConstructGpuLight(asfloat(lights.Load3(li*64+0)), asuint(lights.Load(li*64+12)), asfloat(lights.Load3(li*64+16)), asfloat(lights.Load(li*64+28)), asfloat(lights.Load3(li*64+32)), asfloat(lights.Load(li*64+44)), asfloat(lights.Load3(li*64+48)), asuint(lights.Load(li*64+60)));
    float _e15 = asfloat(r2_3.Load(li*4));
    float _e19 = asfloat(rt2_3.Load(li*4));
    const Connection _e21 = connect_record(_e12, x_9, n_7, ng_2, (s_1 * _e15), (s_1 * _e19), w_res_1, u1_3, u2_3, eps_1, trace_1);
    const Connection connection_2 = _e21;
    return connection_2;
}

Connection connect(uint li_1, float3 x_10, float3 n_8, float3 ng_3, float s_2, float w_res_2, float u1_4, float u2_4, float eps_2)
{
    const Connection _e10 = connect_traced(li_1, x_10, n_8, ng_3, s_2, w_res_2, u1_4, u2_4, eps_2, true);
    const Connection connection_3 = _e10;
    return connection_3;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    uint h = (uint)0;
    float3 e = (0.0).xxx;
    uint s = 0u;

    uint i_3 = gid.x;
    uint _e4 = params.point_count;
    if ((i_3 >= _e4)) {
        return;
    }
    float4 p_2 = asfloat(points.Load4(i_3*16));
    if ((p_2.w <= 0.0)) {
        irradiance.Store4(i_3*16, asuint((0.0).xxxx));
        return;
    }
    float3 x_11 = p_2.xyz;
    float4 _e19 = asfloat(normals.Load4(i_3*16));
    float3 n_10 = _e19.xyz;
    uint _e23 = params.seed;
    uint _e26 = params.frame;
    const uint _e27 = point_stream(_e23, i_3, _e26);
    const Picks _e33 = bsh_collect(x_11, x_11, float4(1.0, 0.0, 1.0, 1.0), _e27);
    const float _e36 = reservoir_weight(_e33.n, K);
    const uint _e37 = pick_stream(_e27);
    h = _e37;
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e69 = s;
            s = (_e69 + 1u);
        }
        loop_init_1 = false;
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
            const Connection _e65 = connect(_e33.light[min(uint(_e57), 7u)], x_11, n_10, n_10, 1.0, _e36, _e52, _e61, _e64);
            e = (_e55 + _e65.e);
        }
    }
    float3 _e73 = e;
    irradiance.Store4(i_3*16, asuint(float4(_e73, float(_e33.n))));
    return;
}
