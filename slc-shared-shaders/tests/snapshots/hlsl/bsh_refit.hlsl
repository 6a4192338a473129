struct RefitParams {
    uint first;
    uint count;
    uint pad0_;
    uint pad1_;
};

struct BshNode {
    float3 center_;
    float radius;
    uint child;
    uint next;
    uint light;
    float extent;
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
static const uint BSH = 0u;
static const uint BSH_TILE_DEPTH = 8u;
static const uint BSH_TILE_SUBTREES = 256u;

cbuffer params : register(b0) { RefitParams params; }
ByteAddressBuffer order : register(t1);
ByteAddressBuffer bounds : register(t2);
ByteAddressBuffer r2_4 : register(t3);
RWByteAddressBuffer bsh_nodes : register(u4);
ByteAddressBuffer tail : register(t5);

float f32_from_bits(uint u)
{
    return asfloat(u);
}

uint f32_to_bits(float x)
{
    return asuint(x);
}

float sphere_pad(float r, float3 c)
{
    return (((r + max(abs(c.x), max(abs(c.y), abs(c.z)))) * SPHERE_PAD) + SPHERE_PAD_ABS);
}

float4 sphere_union(float3 c1_, float r1_, float3 c2_, float r2_)
{
    bool local = (bool)0;

    float3 v = (c2_ - c1_);
    float d = sqrt(dot(v, v));
    const float _e8 = sphere_pad(r1_, c1_);
    if ((r1_ >= ((d + r2_) + _e8))) {
        return float4(c1_.x, c1_.y, c1_.z, r1_);
    }
    const float _e16 = sphere_pad(r2_, c2_);
    if ((r2_ >= ((d + r1_) + _e16))) {
        return float4(c2_.x, c2_.y, c2_.z, r2_);
    }
    if (!((d >= SPHERE_HUGE))) {
        local = ((0.5 * ((d + r1_) + r2_)) >= SPHERE_HUGE);
    } else {
        local = true;
    }
    bool _e35 = local;
    if (_e35) {
        return float4(c1_.x, c1_.y, c1_.z, SPHERE_HUGE);
    }
    if ((abs((r1_ - r2_)) >= d)) {
        if ((r1_ >= r2_)) {
            float rn = max(r1_, (d + r2_));
            const float _e50 = sphere_pad(rn, c1_);
            return float4(c1_.x, c1_.y, c1_.z, (rn + _e50));
        }
        float rm = max(r2_, (d + r1_));
        const float _e58 = sphere_pad(rm, c2_);
        return float4(c2_.x, c2_.y, c2_.z, (rm + _e58));
    }
    float r0_ = (0.5 * ((d + r1_) + r2_));
    float3 c_2 = (c1_ + (v * ((r0_ - r1_) / d)));
    float3 e1_ = (c_2 - c1_);
    float3 e2_ = (c_2 - c2_);
    float r_1 = max(r0_, max((sqrt(dot(e1_, e1_)) + r1_), (sqrt(dot(e2_, e2_)) + r2_)));
    const float _e82 = sphere_pad(r_1, c_2);
    return float4(c_2.x, c_2.y, c_2.z, (r_1 + _e82));
}

float range_radius(float extent, float r2_1)
{
    return (extent + sqrt(r2_1));
}

uint bsh_tail_key(float radius)
{
    const uint _e1 = f32_to_bits(radius);
    return ((_e1 & 2147483647u) >> 21u);
}

float bsh_range_bound(BshNode node)
{
    if ((node.child == BSH_NONE)) {
        return (node.radius - node.extent);
    }
    const float _e8 = f32_from_bits(node.light);
    return _e8;
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

bool bsh_in_tail(float extent_1, float r2_2, uint cut)
{
    const float _e3 = range_radius(extent_1, r2_2);
    const uint _e4 = bsh_tail_key(_e3);
    return (_e4 >= cut);
}

BshNode bsh_leaf_refitted(BshNode node_1, float4 bound, float r2_3, uint cut_1)
{
    BshNode leaf = (BshNode)0;

    const bool _e5 = bsh_in_tail(bound.w, r2_3, cut_1);
    leaf = node_1;
    leaf.center_ = float3(bound.x, bound.y, bound.z);
    const float _e16 = range_radius(bound.w, (_e5 ? 0.0 : r2_3));
    leaf.radius = _e16;
    leaf.extent = bound.w;
    leaf.light = ((node_1.light & 2147483647u) | (_e5 ? BSH_TAIL : 0u));
    BshNode _e27 = leaf;
    const BshNode bshnode_1 = _e27;
    return bshnode_1;
}

float4 bsh_pair_sphere(BshNode left, BshNode right)
{
    const float4 _e6 = sphere_union(left.center_, left.radius, right.center_, right.radius);
    return _e6;
}

float bsh_pair_extent(BshNode left_1, BshNode right_1, float3 center_)
{
    float3 vl = (left_1.center_ - center_);
    float3 vr = (right_1.center_ - center_);
    float a = max((sqrt(dot(vl, vl)) + left_1.extent), (sqrt(dot(vr, vr)) + right_1.extent));
    const float _e16 = sphere_pad(a, center_);
    return (a + _e16);
}

float bsh_pair_range(BshNode left_2, BshNode right_2)
{
    const float _e2 = bsh_range_bound(left_2);
    const float _e3 = bsh_range_bound(right_2);
    return max(_e2, _e3);
}

BshNode bsh_inner_refitted(BshNode node_2, BshNode left_3, BshNode right_3)
{
    BshNode inner = (BshNode)0;

    const float4 _e3 = bsh_pair_sphere(left_3, right_3);
    inner = node_2;
    inner.center_ = float3(_e3.x, _e3.y, _e3.z);
    inner.radius = _e3.w;
    float3 _e14 = inner.center_;
    const float _e15 = bsh_pair_extent(left_3, right_3, _e14);
    inner.extent = _e15;
    const float _e17 = bsh_pair_range(left_3, right_3);
    const uint _e18 = f32_to_bits(_e17);
    inner.light = _e18;
    BshNode _e19 = inner;
    const BshNode bshnode_2 = _e19;
    return bshnode_2;
}

BshNode bsh_family_refitted(uint nodes_1, BshNode node_3)
{
    BshNode acc = (BshNode)0;
    uint c_1 = (uint)0;

    const BshNode _e3 = bsh_node(nodes_1, node_3.child);
    const BshNode _e5 = bsh_node(nodes_1, _e3.next);
    const BshNode _e6 = bsh_inner_refitted(node_3, _e3, _e5);
    acc = _e6;
    c_1 = _e5.next;
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e10 = c_1;
        if ((_e10 != node_3.next)) {
        } else {
            break;
        }
        {
            uint _e13 = c_1;
            const BshNode _e14 = bsh_node(nodes_1, _e13);
            BshNode _e15 = acc;
            BshNode _e16 = acc;
            const BshNode _e17 = bsh_inner_refitted(_e15, _e16, _e14);
            acc = _e17;
            c_1 = _e14.next;
        }
    }
    BshNode _e19 = acc;
    const BshNode bshnode_3 = _e19;
    return bshnode_3;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    uint _e4 = params.count;
    if ((gid.x >= _e4)) {
        return;
    }
    uint _e9 = params.first;
    uint i_1 = asuint(order.Load((_e9 + gid.x)*4));
    BshNode node_4 = ConstructBshNode(asfloat(bsh_nodes.Load3(i_1*32+0)), asfloat(bsh_nodes.Load(i_1*32+12)), asuint(bsh_nodes.Load(i_1*32+16)), asuint(bsh_nodes.Load(i_1*32+20)), asuint(bsh_nodes.Load(i_1*32+24)), asfloat(bsh_nodes.Load(i_1*32+28)));
    if ((node_4.child == BSH_NONE)) {
        uint li = (node_4.light & 2147483647u);
        float4 _e27 = asfloat(bounds.Load4(li*16));
        float _e30 = asfloat(r2_4.Load(li*4));
        uint _e33 = asuint(tail.Load(0));
        const BshNode _e34 = bsh_leaf_refitted(node_4, _e27, _e30, _e33);
        {
            BshNode _value3 = _e34;
            bsh_nodes.Store3(i_1*32+0, asuint(_value3.center_));
            bsh_nodes.Store(i_1*32+12, asuint(_value3.radius));
            bsh_nodes.Store(i_1*32+16, asuint(_value3.child));
            bsh_nodes.Store(i_1*32+20, asuint(_value3.next));
            bsh_nodes.Store(i_1*32+24, asuint(_value3.light));
            bsh_nodes.Store(i_1*32+28, asuint(_value3.extent));
        }
        return;
    }
    const BshNode _e38 = bsh_family_refitted(BSH, node_4);
    {
        BshNode _value2 = _e38;
        bsh_nodes.Store3(i_1*32+0, asuint(_value2.center_));
        bsh_nodes.Store(i_1*32+12, asuint(_value2.radius));
        bsh_nodes.Store(i_1*32+16, asuint(_value2.child));
        bsh_nodes.Store(i_1*32+20, asuint(_value2.next));
        bsh_nodes.Store(i_1*32+24, asuint(_value2.light));
        bsh_nodes.Store(i_1*32+28, asuint(_value2.extent));
    }
    return;
}
