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
static const uint HIST = 0u;
static const uint BSH_TAIL_CHUNK = 32u;

cbuffer params : register(b0) { TailParams params; }
ByteAddressBuffer bounds : register(t1);
ByteAddressBuffer r2_3 : register(t2);
RWByteAddressBuffer tail_hist : register(u3);
RWByteAddressBuffer tail : register(u4);
RWByteAddressBuffer bsh_nodes : register(u5);
groupshared uint wg_bins[1024];
groupshared uint wg_chunks[32];

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
    uint c_2 = (uint)0;

    const BshNode _e2 = bsh_node(nodes_1, i_1);
    if ((_e2.child == BSH_NONE)) {
        return BSH_NONE;
    }
    c_2 = _e2.child;
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e9 = c_2;
        const BshNode _e10 = bsh_node(nodes_1, _e9);
        if ((_e10.next != _e2.next)) {
        } else {
            break;
        }
        {
            uint _e14 = c_2;
            const BshNode _e15 = bsh_node(nodes_1, _e14);
            c_2 = _e15.next;
        }
    }
    uint _e17 = c_2;
    return _e17;
}

BshNode bsh_tail_leaf(BshNode slot, float4 bound, float r2_2, uint li, uint next)
{
    BshNode leaf = (BshNode)0;

    leaf = slot;
    leaf.center_ = float3(bound.x, bound.y, bound.z);
    const float _e13 = range_radius(bound.w, r2_2);
    leaf.radius = _e13;
    leaf.child = BSH_NONE;
    leaf.next = next;
    leaf.light = li;
    leaf.extent = bound.w;
    BshNode _e20 = leaf;
    const BshNode bshnode_1 = _e20;
    return bshnode_1;
}

uint bsh_tail_bin(uint hist, uint b_3)
{
    uint _e4 = wg_bins[min(uint(b_3), 1023u)];
    return _e4;
}

uint bsh_tail_chunk(uint hist_1, uint c_3)
{
    uint _e4 = wg_chunks[min(uint(c_3), 31u)];
    return _e4;
}

uint bsh_tail_cut(uint hist_2, uint k)
{
    uint c_4 = 32u;
    uint sum_1 = 0u;
    bool local_2 = (bool)0;
    uint b_4 = (uint)0;
    bool local_3 = (bool)0;

    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e6 = c_4;
        if ((_e6 > 0u)) {
            uint _e11 = sum_1;
            uint _e12 = c_4;
            const uint _e15 = bsh_tail_chunk(hist_2, (_e12 - 1u));
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
            uint _e20 = sum_1;
            uint _e21 = c_4;
            const uint _e24 = bsh_tail_chunk(hist_2, (_e21 - 1u));
            sum_1 = (_e20 + _e24);
            uint _e26 = c_4;
            c_4 = (_e26 - 1u);
        }
    }
    uint _e29 = c_4;
    b_4 = (_e29 * BSH_TAIL_CHUNK);
    uint _e33 = b_4;
    uint _e34 = b_4;
    uint end = (_e33 - min(_e34, BSH_TAIL_CHUNK));
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e38 = b_4;
        if ((_e38 > end)) {
            uint _e42 = sum_1;
            uint _e43 = b_4;
            const uint _e46 = bsh_tail_bin(hist_2, (_e43 - 1u));
            local_3 = ((_e42 + _e46) <= k);
        } else {
            local_3 = false;
        }
        bool _e50 = local_3;
        if (_e50) {
        } else {
            break;
        }
        {
            uint _e51 = sum_1;
            uint _e52 = b_4;
            const uint _e55 = bsh_tail_bin(hist_2, (_e52 - 1u));
            sum_1 = (_e51 + _e55);
            uint _e57 = b_4;
            b_4 = (_e57 - 1u);
        }
    }
    uint _e60 = b_4;
    return _e60;
}

uint tail_light(uint s_1)
{
    uint _e5; tail.InterlockedOr((2u + s_1)*4, 0, _e5);
    return _e5;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID, uint local_invocation_index : SV_GroupIndex)
{
    if (local_invocation_index == 0) {
        wg_bins = (uint[1024])0;
        wg_chunks = (uint[32])0;
    }
    GroupMemoryBarrierWithGroupSync();
    uint b = (uint)0;
    uint c = (uint)0;
    uint sum = (uint)0;
    uint b_1 = (uint)0;
    bool local = (bool)0;
    uint b_2 = (uint)0;
    uint a = 1u;
    uint c_1 = (uint)0;
    bool local_1 = (bool)0;
    uint s = 0u;
    uint n = 0u;

    uint i_2 = gid.x;
    uint _e4 = params.stage;
    if ((_e4 == 1u)) {
        b = i_2;
        uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
        bool loop_init = true;
        while(true) {
            if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
            loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
            if (!loop_init) {
                uint _e18 = b;
                b = (_e18 + 64u);
            }
            loop_init = false;
            uint _e8 = b;
            if ((_e8 < BSH_TAIL_BINS)) {
            } else {
                break;
            }
            {
                uint _e12 = b;
                uint _e15 = b;
                uint _e17; tail_hist.InterlockedOr(_e15*4, 0, _e17);
                wg_bins[min(uint(_e12), 1023u)] = _e17;
            }
        }
        GroupMemoryBarrierWithGroupSync();
        c = i_2;
        uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
            loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e49 = c;
                c = (_e49 + 64u);
            }
            loop_init_1 = false;
            uint _e22 = c;
            if ((_e22 < 32u)) {
            } else {
                break;
            }
            {
                sum = 0u;
                b_1 = 0u;
                uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
                bool loop_init_2 = true;
                while(true) {
                    if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
                    loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                    if (!loop_init_2) {
                        uint _e43 = b_1;
                        b_1 = (_e43 + 1u);
                    }
                    loop_init_2 = false;
                    uint _e29 = b_1;
                    if ((_e29 < BSH_TAIL_CHUNK)) {
                    } else {
                        break;
                    }
                    {
                        uint _e32 = sum;
                        uint _e34 = c;
                        uint _e37 = b_1;
                        uint _e40 = wg_bins[min(uint(((_e34 * BSH_TAIL_CHUNK) + _e37)), 1023u)];
                        sum = (_e32 + _e40);
                    }
                }
                uint _e46 = c;
                uint _e48 = sum;
                wg_chunks[min(uint(_e46), 31u)] = _e48;
            }
        }
        GroupMemoryBarrierWithGroupSync();
        if ((i_2 == 0u)) {
            uint _e59 = params.k;
            const uint _e60 = bsh_tail_cut(HIST, _e59);
            { uint dummy = 0; tail.InterlockedExchange(0, _e60, dummy); }
            { uint dummy_1 = 0; tail.InterlockedExchange(4, 0u, dummy_1); }
        }
        return;
    }
    uint _e66 = params.stage;
    switch(_e66) {
        case 0u: {
            uint _e69 = params.count;
            if ((i_2 < _e69)) {
                float _e75 = asfloat(bounds.Load(12+i_2*16));
                float _e78 = asfloat(r2_3.Load(i_2*4));
                const float _e79 = range_radius(_e75, _e78);
                const uint _e80 = bsh_tail_key(_e79);
                uint _e83; tail_hist.InterlockedAdd(_e80*4, 1u, _e83);
                return;
            } else {
                return;
            }
            break;
        }
        case 2u: {
            uint _e86 = params.count;
            if ((i_2 < _e86)) {
                float _e93 = asfloat(bounds.Load(12+i_2*16));
                float _e96 = asfloat(r2_3.Load(i_2*4));
                uint _e99; tail.InterlockedOr(0, 0, _e99);
                const bool _e100 = bsh_in_tail(_e93, _e96, _e99);
                local = _e100;
            } else {
                local = false;
            }
            bool _e102 = local;
            if (_e102) {
                uint _e108; tail.InterlockedAdd(4, 1u, _e108);
                { uint dummy_2 = 0; tail.InterlockedExchange((2u + _e108)*4, i_2, dummy_2); }
                return;
            } else {
                return;
            }
            break;
        }
        default: {
            b_2 = i_2;
            uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
                loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e119 = b_2;
                    b_2 = (_e119 + 64u);
                }
                loop_init_3 = false;
                uint _e112 = b_2;
                if ((_e112 < BSH_TAIL_BINS)) {
                } else {
                    break;
                }
                {
                    uint _e116 = b_2;
                    { uint dummy_3 = 0; tail_hist.InterlockedExchange(_e116*4, 0u, dummy_3); }
                }
            }
            if ((i_2 != 0u)) {
                return;
            }
            uint count; tail.InterlockedOr(4, 0, count);
            uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
            bool loop_init_4 = true;
            while(true) {
                if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                if (!loop_init_4) {
                    uint _e165 = a;
                    a = (_e165 + 1u);
                }
                loop_init_4 = false;
                uint _e129 = a;
                if ((_e129 < count)) {
                } else {
                    break;
                }
                {
                    uint _e131 = a;
                    const uint _e132 = tail_light(_e131);
                    uint _e133 = a;
                    c_1 = _e133;
                    uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
                    while(true) {
                        if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
                        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
                        uint _e135 = c_1;
                        if ((_e135 > 0u)) {
                            uint _e140 = c_1;
                            const uint _e143 = tail_light((_e140 - 1u));
                            local_1 = (_e143 > _e132);
                        } else {
                            local_1 = false;
                        }
                        bool _e146 = local_1;
                        if (_e146) {
                        } else {
                            break;
                        }
                        {
                            uint _e149 = c_1;
                            uint _e152 = c_1;
                            const uint _e155 = tail_light((_e152 - 1u));
                            { uint dummy_4 = 0; tail.InterlockedExchange((2u + _e149)*4, _e155, dummy_4); }
                            uint _e156 = c_1;
                            c_1 = (_e156 - 1u);
                        }
                    }
                    uint _e161 = c_1;
                    { uint dummy_5 = 0; tail.InterlockedExchange((2u + _e161)*4, _e132, dummy_5); }
                }
            }
            uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
                loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e199 = s;
                    s = (_e199 + 1u);
                }
                loop_init_5 = false;
                uint _e169 = s;
                if ((_e169 < count)) {
                } else {
                    break;
                }
                {
                    uint _e171 = s;
                    const uint _e172 = tail_light(_e171);
                    uint _e175 = params.tree;
                    uint _e176 = s;
                    uint at = (_e175 + _e176);
                    uint _e181 = s;
                    uint next_1 = (((_e181 + 1u) == count) ? BSH_NONE : (at + 1u));
                    BshNode _e190 = ConstructBshNode(asfloat(bsh_nodes.Load3(at*32+0)), asfloat(bsh_nodes.Load(at*32+12)), asuint(bsh_nodes.Load(at*32+16)), asuint(bsh_nodes.Load(at*32+20)), asuint(bsh_nodes.Load(at*32+24)), asfloat(bsh_nodes.Load(at*32+28)));
                    float4 _e193 = asfloat(bounds.Load4(_e172*16));
                    float _e196 = asfloat(r2_3.Load(_e172*4));
                    const BshNode _e197 = bsh_tail_leaf(_e190, _e193, _e196, _e172, next_1);
                    {
                        BshNode _value6 = _e197;
                        bsh_nodes.Store3(at*32+0, asuint(_value6.center_));
                        bsh_nodes.Store(at*32+12, asuint(_value6.radius));
                        bsh_nodes.Store(at*32+16, asuint(_value6.child));
                        bsh_nodes.Store(at*32+20, asuint(_value6.next));
                        bsh_nodes.Store(at*32+24, asuint(_value6.light));
                        bsh_nodes.Store(at*32+28, asuint(_value6.extent));
                    }
                }
            }
            uint _e203 = params.tree;
            uint first = ((count == 0u) ? BSH_NONE : _e203);
            uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
            while(true) {
                if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                uint _e210 = n;
                if ((_e210 != BSH_NONE)) {
                } else {
                    break;
                }
                {
                    uint _e214 = n;
                    const uint _e215 = bsh_rightmost_next(BSH, _e214);
                    uint _e217 = n;
                    bsh_nodes.Store(20+_e217*32, asuint(first));
                    n = _e215;
                }
            }
            return;
        }
    }
}
