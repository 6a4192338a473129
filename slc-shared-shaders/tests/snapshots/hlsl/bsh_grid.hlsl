struct GridParams {
    uint stage;
    uint count;
    uint levels;
    uint capacity;
    float reach;
    uint cells;
    uint header;
    uint fill;
    uint entries;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};

struct BshNode {
    float3 center_;
    float radius;
    uint child;
    uint next;
    uint light;
    float extent;
};

struct GridFrame {
    float3 lo;
    uint nx;
    float3 hi;
    uint ny;
    float3 inv;
    uint nz;
};

static const uint LIGHT_POINT = 0u;
static const uint LIGHT_SPOT = 1u;
static const uint LIGHT_IES = 2u;
static const uint LIGHT_TRIANGLE = 3u;
static const uint LIGHT_VPL = 4u;
static const uint NO_LIGHT = 4294967295u;
static const uint GRID_HEADER = 32u;
static const uint GRID_LEVELS_MAX = 8u;
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
static const uint GRID_ENTRIES_PER_LIGHT = 8u;

cbuffer params : register(b0) { GridParams params; }
ByteAddressBuffer bsh_nodes : register(t1);
ByteAddressBuffer grid_leaves : register(t2);
ByteAddressBuffer grid_levels : register(t3);
RWByteAddressBuffer grid : register(u4);
RWByteAddressBuffer grid_fill : register(u5);
RWByteAddressBuffer grid_entries : register(u6);
groupshared uint wg_sums[64];

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

uint to_u32_(float x_1)
{
    return naga_f2u32(x_1);
}

uint add_wrap_u32_(uint a, uint b)
{
    return (a + b);
}

float f32_from_bits(uint u)
{
    return asfloat(u);
}

float bsh_range_bound(BshNode node)
{
    if ((node.child == BSH_NONE)) {
        return (node.radius - node.extent);
    }
    const float _e8 = f32_from_bits(node.light);
    return _e8;
}

float bsh_reach_bound(BshNode node_1, float w)
{
    const float _e5 = bsh_range_bound(node_1);
    return (node_1.extent + ((w * 1.001) * _e5));
}

uint bsh_grid_budget(uint leaves, uint cells)
{
    if ((leaves > 536870911u)) {
        return 4294967295u;
    }
    uint e = (leaves * GRID_ENTRIES_PER_LIGHT);
    const uint _e7 = add_wrap_u32_(e, cells);
    return ((_e7 < e) ? 4294967295u : _e7);
}

float bsh_grid_reach(BshNode node_2, float w_1)
{
    if ((w_1 > 1.0)) {
        const float _e5 = bsh_reach_bound(node_2, w_1);
        return max(node_2.radius, _e5);
    }
    return node_2.radius;
}

float bsh_grid_pad(float reach)
{
    if ((reach > 1e19)) {
        return 3.4028235e38;
    }
    return ((reach * 1.00001) + 1e-22);
}

uint bsh_grid_axis(float v, float lo, float inv, uint n)
{
    const uint _e8 = to_u32_(max(((v - lo) * inv), 0.0));
    return min(_e8, (n - 1u));
}

float bsh_grid_radius(BshNode node_3, float w_2)
{
    const float _e2 = bsh_grid_reach(node_3, w_2);
    const float _e3 = bsh_grid_pad(_e2);
    return _e3;
}

uint3 bsh_grid_first(GridFrame f_1, float3 c_3, float r)
{
    const uint _e10 = bsh_grid_axis((c_3.x - r), f_1.lo.x, f_1.inv.x, f_1.nx);
    const uint _e18 = bsh_grid_axis((c_3.y - r), f_1.lo.y, f_1.inv.y, f_1.ny);
    const uint _e26 = bsh_grid_axis((c_3.z - r), f_1.lo.z, f_1.inv.z, f_1.nz);
    return uint3(_e10, _e18, _e26);
}

uint3 bsh_grid_last(GridFrame f_2, float3 c_4, float r_1)
{
    const uint _e10 = bsh_grid_axis((c_4.x + r_1), f_2.lo.x, f_2.inv.x, f_2.nx);
    const uint _e18 = bsh_grid_axis((c_4.y + r_1), f_2.lo.y, f_2.inv.y, f_2.ny);
    const uint _e26 = bsh_grid_axis((c_4.z + r_1), f_2.lo.z, f_2.inv.z, f_2.nz);
    return uint3(_e10, _e18, _e26);
}

uint grid_word(uint i)
{
    uint _e3; grid.InterlockedOr(i*4, 0, _e3);
    return _e3;
}

GridFrame grid_frame(uint h)
{
    GridFrame f_3 = (GridFrame)0;

    const uint _e3 = grid_word(h);
    const uint _e7 = grid_word((h + 1u));
    const uint _e11 = grid_word((h + 2u));
    f_3.lo = float3(asfloat(_e3), asfloat(_e7), asfloat(_e11));
    const uint _e17 = grid_word((h + 3u));
    f_3.nx = _e17;
    const uint _e21 = grid_word((h + 4u));
    const uint _e25 = grid_word((h + 5u));
    const uint _e29 = grid_word((h + 6u));
    f_3.hi = float3(asfloat(_e21), asfloat(_e25), asfloat(_e29));
    const uint _e35 = grid_word((h + 7u));
    f_3.ny = _e35;
    const uint _e39 = grid_word((h + 8u));
    const uint _e43 = grid_word((h + 9u));
    const uint _e47 = grid_word((h + 10u));
    f_3.inv = float3(asfloat(_e39), asfloat(_e43), asfloat(_e47));
    const uint _e53 = grid_word((h + 11u));
    f_3.nz = _e53;
    GridFrame _e54 = f_3;
    const GridFrame gridframe = _e54;
    return gridframe;
}

uint grid_leaf(uint i_1)
{
    uint node_4 = asuint(grid_leaves.Load(i_1*4));
    uint _e7 = asuint(bsh_nodes.Load(24+node_4*32));
    if (((_e7 & BSH_TAIL) != 0u)) {
        return BSH_NONE;
    }
    return node_4;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
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

GridFrame ConstructGridFrame(float3 arg0, uint arg1, float3 arg2, uint arg3, float3 arg4, uint arg5) {
    GridFrame ret = (GridFrame)0;
    ret.lo = arg0;
    ret.nx = arg1;
    ret.hi = arg2;
    ret.ny = arg3;
    ret.inv = arg4;
    ret.nz = arg5;
    return ret;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID, uint local_invocation_index : SV_GroupIndex)
{
    if (local_invocation_index == 0) {
        wg_sums = (uint[64])0;
    }
    GroupMemoryBarrierWithGroupSync();
    uint sum = 0u;
    uint c = (uint)0;
    uint start = (uint)0;
    uint j = 0u;
    uint c_1 = (uint)0;
    uint l = 0u;
    uint chosen = (uint)0;
    uint l_1 = 0u;
    bool local = (bool)0;
    bool local_1 = (bool)0;
    GridFrame f = (GridFrame)0;
    bool local_2 = (bool)0;
    uint z = (uint)0;
    uint y = (uint)0;
    uint x = (uint)0;
    uint s = (uint)0;
    uint c_2 = (uint)0;
    bool local_3 = (bool)0;
    uint s_1 = (uint)0;

    uint i_2 = gid.x;
    uint h_1 = params.header;
    uint starts = (h_1 + GRID_HEADER);
    uint _e9 = params.stage;
    if ((_e9 == 3u)) {
        const GridFrame _e12 = grid_frame(h_1);
        uint cells_1 = ((_e12.nx * _e12.ny) * _e12.nz);
        uint run = naga_div(((cells_1 + 64u) - 1u), 64u);
        uint a_1 = min((i_2 * run), cells_1);
        uint b_1 = min((a_1 + run), cells_1);
        c = a_1;
        uint2 loop_bound = uint2(4294967295u, 4294967295u);
        bool loop_init = true;
        while(true) {
            if (all(loop_bound == uint2(0u, 0u))) { break; }
            loop_bound -= uint2(loop_bound.y == 0u, 1u);
            if (!loop_init) {
                uint _e44 = c;
                c = (_e44 + 1u);
            }
            loop_init = false;
            uint _e31 = c;
            if ((_e31 < b_1)) {
            } else {
                break;
            }
            {
                uint _e33 = sum;
                uint _e37 = params.fill;
                uint _e38 = c;
                uint _e41; grid_fill.InterlockedOr((_e37 + _e38)*4, 0, _e41);
                sum = (_e33 + _e41);
            }
        }
        uint _e48 = sum;
        wg_sums[min(uint(i_2), 63u)] = _e48;
        GroupMemoryBarrierWithGroupSync();
        uint _e51 = params.entries;
        start = _e51;
        uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
            loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e64 = j;
                j = (_e64 + 1u);
            }
            loop_init_1 = false;
            uint _e55 = j;
            if ((_e55 < i_2)) {
            } else {
                break;
            }
            {
                uint _e57 = start;
                uint _e59 = j;
                uint _e61 = wg_sums[min(uint(_e59), 63u)];
                start = (_e57 + _e61);
            }
        }
        c_1 = a_1;
        uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
        bool loop_init_2 = true;
        while(true) {
            if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
            loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
            if (!loop_init_2) {
                uint _e93 = c_1;
                c_1 = (_e93 + 1u);
            }
            loop_init_2 = false;
            uint _e67 = c_1;
            if ((_e67 < b_1)) {
            } else {
                break;
            }
            {
                uint _e72 = params.fill;
                uint _e73 = c_1;
                uint n_1; grid_fill.InterlockedOr((_e72 + _e73)*4, 0, n_1);
                uint _e78 = c_1;
                uint _e81 = start;
                { uint dummy = 0; grid.InterlockedExchange((starts + _e78)*4, _e81, dummy); }
                uint _e85 = params.fill;
                uint _e86 = c_1;
                uint _e89 = start;
                { uint dummy_1 = 0; grid_fill.InterlockedExchange((_e85 + _e86)*4, _e89, dummy_1); }
                uint _e90 = start;
                start = (_e90 + n_1);
            }
        }
        if (((i_2 + 1u) == 64u)) {
            uint _e102 = start;
            { uint dummy_2 = 0; grid.InterlockedExchange((starts + cells_1)*4, _e102, dummy_2); }
        }
        return;
    }
    uint _e105 = params.stage;
    switch(_e105) {
        case 0u: {
            uint _e108 = params.count;
            if ((i_2 >= _e108)) {
                return;
            }
            const uint _e110 = grid_leaf(i_2);
            if ((_e110 == BSH_NONE)) {
                return;
            }
            uint _e118; grid.InterlockedAdd((h_1 + 13u)*4, 1u, _e118);
            BshNode leaf = ConstructBshNode(asfloat(bsh_nodes.Load3(_e110*32+0)), asfloat(bsh_nodes.Load(_e110*32+12)), asuint(bsh_nodes.Load(_e110*32+16)), asuint(bsh_nodes.Load(_e110*32+20)), asuint(bsh_nodes.Load(_e110*32+24)), asfloat(bsh_nodes.Load(_e110*32+28)));
            float _e124 = params.reach;
            const float _e125 = bsh_grid_radius(leaf, _e124);
            uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e172 = l;
                    l = (_e172 + 1u);
                }
                loop_init_3 = false;
                uint _e128 = l;
                uint _e131 = params.levels;
                if ((_e128 < _e131)) {
                } else {
                    break;
                }
                {
                    uint _e134 = l;
                    GridFrame _e136 = ConstructGridFrame(asfloat(grid_levels.Load3(_e134*48+0)), asuint(grid_levels.Load(_e134*48+12)), asfloat(grid_levels.Load3(_e134*48+16)), asuint(grid_levels.Load(_e134*48+28)), asfloat(grid_levels.Load3(_e134*48+32)), asuint(grid_levels.Load(_e134*48+44)));
                    const uint3 _e138 = bsh_grid_last(_e136, leaf.center_, _e125);
                    uint _e140 = l;
                    GridFrame _e142 = ConstructGridFrame(asfloat(grid_levels.Load3(_e140*48+0)), asuint(grid_levels.Load(_e140*48+12)), asfloat(grid_levels.Load3(_e140*48+16)), asuint(grid_levels.Load(_e140*48+28)), asfloat(grid_levels.Load3(_e140*48+32)), asuint(grid_levels.Load(_e140*48+44)));
                    const uint3 _e144 = bsh_grid_first(_e142, leaf.center_, _e125);
                    uint3 d = ((_e138 - _e144) + (1u).xxx);
                    uint n_2 = ((d.x * d.y) * d.z);
                    uint _e157 = l;
                    uint at = ((h_1 + 16u) + (2u * _e157));
                    uint _e162; grid.InterlockedAdd(at*4, n_2, _e162);
                    if (((_e162 + n_2) < _e162)) {
                        uint _e170; grid.InterlockedAdd((at + 1u)*4, 1u, _e170);
                    }
                }
            }
            return;
        }
        case 1u: {
            if ((i_2 != 0u)) {
                return;
            }
            uint leaves_1; grid.InterlockedOr((h_1 + 13u)*4, 0, leaves_1);
            uint _e183 = params.levels;
            chosen = _e183;
            uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
            bool loop_init_4 = true;
            while(true) {
                if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_4) {
                    uint _e246 = l_1;
                    l_1 = (_e246 + 1u);
                }
                loop_init_4 = false;
                uint _e187 = l_1;
                uint _e190 = params.levels;
                if ((_e187 < _e190)) {
                } else {
                    break;
                }
                {
                    uint _e193 = l_1;
                    GridFrame f_4 = ConstructGridFrame(asfloat(grid_levels.Load3(_e193*48+0)), asuint(grid_levels.Load(_e193*48+12)), asfloat(grid_levels.Load3(_e193*48+16)), asuint(grid_levels.Load(_e193*48+28)), asfloat(grid_levels.Load3(_e193*48+32)), asuint(grid_levels.Load(_e193*48+44)));
                    uint cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    const uint _e201 = bsh_grid_budget(leaves_1, cells_2);
                    uint _e204 = params.capacity;
                    uint budget = min(_e201, _e204);
                    uint _e209 = l_1;
                    uint at_1 = ((h_1 + 16u) + (2u * _e209));
                    uint _e212 = chosen;
                    uint _e215 = params.levels;
                    if ((_e212 == _e215)) {
                        uint _e223; grid.InterlockedOr((at_1 + 1u)*4, 0, _e223);
                        local = (_e223 == 0u);
                    } else {
                        local = false;
                    }
                    bool _e227 = local;
                    if (_e227) {
                        uint _e232; grid.InterlockedOr(at_1*4, 0, _e232);
                        local_1 = (_e232 <= budget);
                    } else {
                        local_1 = false;
                    }
                    bool _e235 = local_1;
                    if (_e235) {
                        uint _e236 = l_1;
                        chosen = _e236;
                    }
                    { uint dummy_3 = 0; grid.InterlockedExchange(at_1*4, 0u, dummy_3); }
                    { uint dummy_4 = 0; grid.InterlockedExchange((at_1 + 1u)*4, 0u, dummy_4); }
                }
            }
            { uint dummy_5 = 0; grid.InterlockedExchange((h_1 + 13u)*4, 0u, dummy_5); }
            uint _e254 = chosen;
            uint _e257 = params.levels;
            if ((_e254 < _e257)) {
                uint _e260 = chosen;
                GridFrame _e262 = ConstructGridFrame(asfloat(grid_levels.Load3(_e260*48+0)), asuint(grid_levels.Load(_e260*48+12)), asfloat(grid_levels.Load3(_e260*48+16)), asuint(grid_levels.Load(_e260*48+28)), asfloat(grid_levels.Load3(_e260*48+32)), asuint(grid_levels.Load(_e260*48+44)));
                f = _e262;
            }
            float _e267 = f.lo.x;
            { uint dummy_6 = 0; grid.InterlockedExchange(h_1*4, asuint(_e267), dummy_6); }
            float _e275 = f.lo.y;
            { uint dummy_7 = 0; grid.InterlockedExchange((h_1 + 1u)*4, asuint(_e275), dummy_7); }
            float _e283 = f.lo.z;
            { uint dummy_8 = 0; grid.InterlockedExchange((h_1 + 2u)*4, asuint(_e283), dummy_8); }
            uint _e290 = f.nx;
            { uint dummy_9 = 0; grid.InterlockedExchange((h_1 + 3u)*4, _e290, dummy_9); }
            float _e297 = f.hi.x;
            { uint dummy_10 = 0; grid.InterlockedExchange((h_1 + 4u)*4, asuint(_e297), dummy_10); }
            float _e305 = f.hi.y;
            { uint dummy_11 = 0; grid.InterlockedExchange((h_1 + 5u)*4, asuint(_e305), dummy_11); }
            float _e313 = f.hi.z;
            { uint dummy_12 = 0; grid.InterlockedExchange((h_1 + 6u)*4, asuint(_e313), dummy_12); }
            uint _e320 = f.ny;
            { uint dummy_13 = 0; grid.InterlockedExchange((h_1 + 7u)*4, _e320, dummy_13); }
            float _e327 = f.inv.x;
            { uint dummy_14 = 0; grid.InterlockedExchange((h_1 + 8u)*4, asuint(_e327), dummy_14); }
            float _e335 = f.inv.y;
            { uint dummy_15 = 0; grid.InterlockedExchange((h_1 + 9u)*4, asuint(_e335), dummy_15); }
            float _e343 = f.inv.z;
            { uint dummy_16 = 0; grid.InterlockedExchange((h_1 + 10u)*4, asuint(_e343), dummy_16); }
            uint _e350 = f.nz;
            { uint dummy_17 = 0; grid.InterlockedExchange((h_1 + 11u)*4, _e350, dummy_17); }
            float _e357 = params.reach;
            { uint dummy_18 = 0; grid.InterlockedExchange((h_1 + 12u)*4, asuint(_e357), dummy_18); }
            return;
        }
        case 2u:
        case 4u: {
            uint _e361 = params.count;
            if ((i_2 >= _e361)) {
                return;
            }
            const GridFrame _e363 = grid_frame(h_1);
            const uint _e364 = grid_leaf(i_2);
            if (!((_e363.nx == 0u))) {
                local_2 = (_e364 == BSH_NONE);
            } else {
                local_2 = true;
            }
            bool _e374 = local_2;
            if (_e374) {
                return;
            }
            BshNode leaf_1 = ConstructBshNode(asfloat(bsh_nodes.Load3(_e364*32+0)), asfloat(bsh_nodes.Load(_e364*32+12)), asuint(bsh_nodes.Load(_e364*32+16)), asuint(bsh_nodes.Load(_e364*32+20)), asuint(bsh_nodes.Load(_e364*32+24)), asfloat(bsh_nodes.Load(_e364*32+28)));
            float _e380 = params.reach;
            const float _e381 = bsh_grid_radius(leaf_1, _e380);
            const uint3 _e383 = bsh_grid_first(_e363, leaf_1.center_, _e381);
            const uint3 _e385 = bsh_grid_last(_e363, leaf_1.center_, _e381);
            z = _e383.z;
            uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e432 = z;
                    z = (_e432 + 1u);
                }
                loop_init_5 = false;
                uint _e388 = z;
                if ((_e388 <= _e385.z)) {
                } else {
                    break;
                }
                {
                    y = _e383.y;
                    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
                    bool loop_init_6 = true;
                    while(true) {
                        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
                        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                        if (!loop_init_6) {
                            uint _e429 = y;
                            y = (_e429 + 1u);
                        }
                        loop_init_6 = false;
                        uint _e393 = y;
                        if ((_e393 <= _e385.y)) {
                        } else {
                            break;
                        }
                        {
                            x = _e383.x;
                            uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
                            bool loop_init_7 = true;
                            while(true) {
                                if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
                                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                                if (!loop_init_7) {
                                    uint _e426 = x;
                                    x = (_e426 + 1u);
                                }
                                loop_init_7 = false;
                                uint _e398 = x;
                                if ((_e398 <= _e385.x)) {
                                } else {
                                    break;
                                }
                                {
                                    uint _e401 = z;
                                    uint _e404 = y;
                                    uint _e408 = x;
                                    uint c_5 = ((((_e401 * _e363.ny) + _e404) * _e363.nx) + _e408);
                                    uint _e413 = params.fill;
                                    uint _e417; grid_fill.InterlockedAdd((_e413 + c_5)*4, 1u, _e417);
                                    uint _e420 = params.stage;
                                    if ((_e420 == 4u)) {
                                        grid_entries.Store(_e417*4, asuint(i_2));
                                    }
                                }
                            }
                        }
                    }
                }
            }
            return;
        }
        default: {
            const GridFrame _e434 = grid_frame(h_1);
            if ((i_2 >= ((_e434.nx * _e434.ny) * _e434.nz))) {
                return;
            }
            uint _e444 = params.fill;
            { uint dummy_19 = 0; grid_fill.InterlockedExchange((_e444 + i_2)*4, 0u, dummy_19); }
            uint a_2; grid.InterlockedOr((starts + i_2)*4, 0, a_2);
            uint b_2; grid.InterlockedOr(((starts + i_2) + 1u)*4, 0, b_2);
            s = (a_2 + 1u);
            uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
                loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e498 = s;
                    s = (_e498 + 1u);
                }
                loop_init_8 = false;
                uint _e461 = s;
                if ((_e461 < b_2)) {
                } else {
                    break;
                }
                {
                    uint _e464 = s;
                    uint v_1 = asuint(grid_entries.Load(_e464*4));
                    uint _e467 = s;
                    c_2 = _e467;
                    uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
                    while(true) {
                        if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
                        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                        uint _e469 = c_2;
                        if ((_e469 > a_2)) {
                            uint _e474 = c_2;
                            uint _e478 = asuint(grid_entries.Load((_e474 - 1u)*4));
                            local_3 = (_e478 > v_1);
                        } else {
                            local_3 = false;
                        }
                        bool _e481 = local_3;
                        if (_e481) {
                        } else {
                            break;
                        }
                        {
                            uint _e483 = c_2;
                            uint _e486 = c_2;
                            uint _e490 = asuint(grid_entries.Load((_e486 - 1u)*4));
                            grid_entries.Store(_e483*4, asuint(_e490));
                            uint _e491 = c_2;
                            c_2 = (_e491 - 1u);
                        }
                    }
                    uint _e495 = c_2;
                    grid_entries.Store(_e495*4, asuint(v_1));
                }
            }
            s_1 = a_2;
            uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
            bool loop_init_9 = true;
            while(true) {
                if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_9) {
                    uint _e514 = s_1;
                    s_1 = (_e514 + 1u);
                }
                loop_init_9 = false;
                uint _e501 = s_1;
                if ((_e501 < b_2)) {
                } else {
                    break;
                }
                {
                    uint _e504 = s_1;
                    uint _e508 = s_1;
                    uint _e510 = asuint(grid_entries.Load(_e508*4));
                    uint _e512 = asuint(grid_leaves.Load(_e510*4));
                    grid_entries.Store(_e504*4, asuint(_e512));
                }
            }
            return;
        }
    }
}
