struct TailParams {
    uint stage;
    uint count;
    uint k;
    uint tree;
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
static const uint BSH_TAIL = 2147483648u;
static const uint BSH_TAIL_BINS = 1024u;
static const uint BSH_TAIL_MAX = 64u;
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
static const uint BSH = 0u;
static const uint BSH_TILE_DEPTH = 8u;
static const uint BSH_TILE_SUBTREES = 256u;
static const uint HIST = 0u;

cbuffer params : register(b0) { TailParams params; }
ByteAddressBuffer bounds : register(t1);
ByteAddressBuffer r2_2 : register(t2);
RWByteAddressBuffer tail_hist : register(u3);
RWByteAddressBuffer tail : register(u4);
RWByteAddressBuffer bsh_nodes : register(u5);

uint f32_to_bits(float x)
{
    return asuint(x);
}

float range_radius(float extent, float r2_)
{
    return (extent + sqrt(r2_));
}

uint bsh_tail_key(float radius)
{
    const uint _e1 = f32_to_bits(radius);
    return ((_e1 & 2147483647u) >> 21u);
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

bool bsh_in_tail(float extent_1, float r2_1, uint cut)
{
    const float _e3 = range_radius(extent_1, r2_1);
    const uint _e4 = bsh_tail_key(_e3);
    return (_e4 >= cut);
}

uint bsh_rightmost_next(uint nodes_1, uint i_1)
{
    const BshNode _e2 = bsh_node(nodes_1, i_1);
    if ((_e2.child == BSH_NONE)) {
        return BSH_NONE;
    }
    const BshNode _e8 = bsh_node(nodes_1, _e2.child);
    return _e8.next;
}

uint bsh_tail_bin(uint hist, uint b_1)
{
    uint _e4; tail_hist.InterlockedOr(b_1*4, 0, _e4);
    return _e4;
}

uint bsh_tail_cut(uint hist_1, uint k)
{
    uint b_2 = BSH_TAIL_BINS;
    uint sum = 0u;
    bool local_2 = (bool)0;

    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e6 = b_2;
        if ((_e6 > 0u)) {
            uint _e11 = sum;
            uint _e12 = b_2;
            const uint _e15 = bsh_tail_bin(hist_1, (_e12 - 1u));
            local_2 = ((_e11 + _e15) <= k);
        } else {
            local_2 = false;
        }
        bool _e19 = local_2;
        if (_e19) {
        } else {
            break;
        }
        {
            uint _e20 = sum;
            uint _e21 = b_2;
            const uint _e24 = bsh_tail_bin(hist_1, (_e21 - 1u));
            sum = (_e20 + _e24);
            uint _e26 = b_2;
            b_2 = (_e26 - 1u);
        }
    }
    uint _e29 = b_2;
    return _e29;
}

uint tail_light(uint s_1)
{
    uint _e5; tail.InterlockedOr((2u + s_1)*4, 0, _e5);
    return _e5;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    bool local = (bool)0;
    uint b = (uint)0;
    uint a = 1u;
    uint c = (uint)0;
    bool local_1 = (bool)0;
    uint s = 0u;
    uint n = 0u;

    uint i_2 = gid.x;
    uint _e4 = params.stage;
    switch(_e4) {
        case 0u: {
            uint _e7 = params.count;
            if ((i_2 < _e7)) {
                float _e13 = asfloat(bounds.Load(12+i_2*16));
                float _e16 = asfloat(r2_2.Load(i_2*4));
                const float _e17 = range_radius(_e13, _e16);
                const uint _e18 = bsh_tail_key(_e17);
                uint _e21; tail_hist.InterlockedAdd(_e18*4, 1u, _e21);
                return;
            } else {
                return;
            }
            break;
        }
        case 1u: {
            if ((i_2 == 0u)) {
                uint _e29 = params.k;
                const uint _e30 = bsh_tail_cut(HIST, _e29);
                { uint dummy = 0; tail.InterlockedExchange(0, _e30, dummy); }
                { uint dummy_1 = 0; tail.InterlockedExchange(4, 0u, dummy_1); }
                return;
            } else {
                return;
            }
            break;
        }
        case 2u: {
            uint _e36 = params.count;
            if ((i_2 < _e36)) {
                float _e43 = asfloat(bounds.Load(12+i_2*16));
                float _e46 = asfloat(r2_2.Load(i_2*4));
                uint _e49; tail.InterlockedOr(0, 0, _e49);
                const bool _e50 = bsh_in_tail(_e43, _e46, _e49);
                local = _e50;
            } else {
                local = false;
            }
            bool _e52 = local;
            if (_e52) {
                uint _e58; tail.InterlockedAdd(4, 1u, _e58);
                { uint dummy_2 = 0; tail.InterlockedExchange((2u + _e58)*4, i_2, dummy_2); }
                return;
            } else {
                return;
            }
            break;
        }
        default: {
            b = i_2;
            uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
            bool loop_init = true;
            while(true) {
                if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
                loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                if (!loop_init) {
                    uint _e69 = b;
                    b = (_e69 + 64u);
                }
                loop_init = false;
                uint _e62 = b;
                if ((_e62 < BSH_TAIL_BINS)) {
                } else {
                    break;
                }
                {
                    uint _e66 = b;
                    { uint dummy_3 = 0; tail_hist.InterlockedExchange(_e66*4, 0u, dummy_3); }
                }
            }
            if ((i_2 != 0u)) {
                return;
            }
            uint count; tail.InterlockedOr(4, 0, count);
            uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
            bool loop_init_1 = true;
            while(true) {
                if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
                loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                if (!loop_init_1) {
                    uint _e115 = a;
                    a = (_e115 + 1u);
                }
                loop_init_1 = false;
                uint _e79 = a;
                if ((_e79 < count)) {
                } else {
                    break;
                }
                {
                    uint _e81 = a;
                    const uint _e82 = tail_light(_e81);
                    uint _e83 = a;
                    c = _e83;
                    uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
                    while(true) {
                        if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
                        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                        uint _e85 = c;
                        if ((_e85 > 0u)) {
                            uint _e90 = c;
                            const uint _e93 = tail_light((_e90 - 1u));
                            local_1 = (_e93 > _e82);
                        } else {
                            local_1 = false;
                        }
                        bool _e96 = local_1;
                        if (_e96) {
                        } else {
                            break;
                        }
                        {
                            uint _e99 = c;
                            uint _e102 = c;
                            const uint _e105 = tail_light((_e102 - 1u));
                            { uint dummy_4 = 0; tail.InterlockedExchange((2u + _e99)*4, _e105, dummy_4); }
                            uint _e106 = c;
                            c = (_e106 - 1u);
                        }
                    }
                    uint _e111 = c;
                    { uint dummy_5 = 0; tail.InterlockedExchange((2u + _e111)*4, _e82, dummy_5); }
                }
            }
            uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e156 = s;
                    s = (_e156 + 1u);
                }
                loop_init_2 = false;
                uint _e119 = s;
                if ((_e119 < count)) {
                } else {
                    break;
                }
                {
                    uint _e121 = s;
                    const uint _e122 = tail_light(_e121);
                    float4 b_3 = asfloat(bounds.Load4(_e122*16));
                    uint _e128 = params.tree;
                    uint _e129 = s;
                    uint _e134 = s;
                    uint next = (((_e134 + 1u) == count) ? BSH_NONE : ((_e128 + _e129) + 1u));
                    uint _e142 = params.tree;
                    uint _e143 = s;
                    float _e150 = asfloat(r2_2.Load(_e122*4));
                    const float _e151 = range_radius(b_3.w, _e150);
                    {
                        BshNode _value6 = ConstructBshNode(b_3.xyz, _e151, BSH_NONE, next, _e122, b_3.w);
                        bsh_nodes.Store3((_e142 + _e143)*32+0, asuint(_value6.center_));
                        bsh_nodes.Store((_e142 + _e143)*32+12, asuint(_value6.radius));
                        bsh_nodes.Store((_e142 + _e143)*32+16, asuint(_value6.child));
                        bsh_nodes.Store((_e142 + _e143)*32+20, asuint(_value6.next));
                        bsh_nodes.Store((_e142 + _e143)*32+24, asuint(_value6.light));
                        bsh_nodes.Store((_e142 + _e143)*32+28, asuint(_value6.extent));
                    }
                }
            }
            uint _e160 = params.tree;
            uint first = ((count == 0u) ? BSH_NONE : _e160);
            uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e175 = n;
                    const uint _e176 = bsh_rightmost_next(BSH, _e175);
                    n = _e176;
                }
                loop_init_3 = false;
                uint _e167 = n;
                if ((_e167 != BSH_NONE)) {
                } else {
                    break;
                }
                {
                    uint _e171 = n;
                    bsh_nodes.Store(20+_e171*32, asuint(first));
                }
            }
            return;
        }
    }
}
