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
    const uint _e9 = to_u32_(max(floor(((v - lo) * inv)), 0.0));
    return min(_e9, (n - 1u));
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
    uint node_3 = asuint(grid_leaves.Load(i_1*4));
    uint _e7 = asuint(bsh_nodes.Load(24+node_3*32));
    if (((_e7 & BSH_TAIL) != 0u)) {
        return BSH_NONE;
    }
    return node_3;
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
            const float _e125 = bsh_grid_reach(leaf, _e124);
            const float _e126 = bsh_grid_pad(_e125);
            uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e173 = l;
                    l = (_e173 + 1u);
                }
                loop_init_3 = false;
                uint _e129 = l;
                uint _e132 = params.levels;
                if ((_e129 < _e132)) {
                } else {
                    break;
                }
                {
                    uint _e135 = l;
                    GridFrame _e137 = ConstructGridFrame(asfloat(grid_levels.Load3(_e135*48+0)), asuint(grid_levels.Load(_e135*48+12)), asfloat(grid_levels.Load3(_e135*48+16)), asuint(grid_levels.Load(_e135*48+28)), asfloat(grid_levels.Load3(_e135*48+32)), asuint(grid_levels.Load(_e135*48+44)));
                    const uint3 _e139 = bsh_grid_last(_e137, leaf.center_, _e126);
                    uint _e141 = l;
                    GridFrame _e143 = ConstructGridFrame(asfloat(grid_levels.Load3(_e141*48+0)), asuint(grid_levels.Load(_e141*48+12)), asfloat(grid_levels.Load3(_e141*48+16)), asuint(grid_levels.Load(_e141*48+28)), asfloat(grid_levels.Load3(_e141*48+32)), asuint(grid_levels.Load(_e141*48+44)));
                    const uint3 _e145 = bsh_grid_first(_e143, leaf.center_, _e126);
                    uint3 d = ((_e139 - _e145) + (1u).xxx);
                    uint n_2 = ((d.x * d.y) * d.z);
                    uint _e158 = l;
                    uint at = ((h_1 + 16u) + (2u * _e158));
                    uint _e163; grid.InterlockedAdd(at*4, n_2, _e163);
                    if (((_e163 + n_2) < _e163)) {
                        uint _e171; grid.InterlockedAdd((at + 1u)*4, 1u, _e171);
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
            uint _e184 = params.levels;
            chosen = _e184;
            uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
            bool loop_init_4 = true;
            while(true) {
                if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_4) {
                    uint _e247 = l_1;
                    l_1 = (_e247 + 1u);
                }
                loop_init_4 = false;
                uint _e188 = l_1;
                uint _e191 = params.levels;
                if ((_e188 < _e191)) {
                } else {
                    break;
                }
                {
                    uint _e194 = l_1;
                    GridFrame f_4 = ConstructGridFrame(asfloat(grid_levels.Load3(_e194*48+0)), asuint(grid_levels.Load(_e194*48+12)), asfloat(grid_levels.Load3(_e194*48+16)), asuint(grid_levels.Load(_e194*48+28)), asfloat(grid_levels.Load3(_e194*48+32)), asuint(grid_levels.Load(_e194*48+44)));
                    uint cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    const uint _e202 = bsh_grid_budget(leaves_1, cells_2);
                    uint _e205 = params.capacity;
                    uint budget = min(_e202, _e205);
                    uint _e210 = l_1;
                    uint at_1 = ((h_1 + 16u) + (2u * _e210));
                    uint _e213 = chosen;
                    uint _e216 = params.levels;
                    if ((_e213 == _e216)) {
                        uint _e224; grid.InterlockedOr((at_1 + 1u)*4, 0, _e224);
                        local = (_e224 == 0u);
                    } else {
                        local = false;
                    }
                    bool _e228 = local;
                    if (_e228) {
                        uint _e233; grid.InterlockedOr(at_1*4, 0, _e233);
                        local_1 = (_e233 <= budget);
                    } else {
                        local_1 = false;
                    }
                    bool _e236 = local_1;
                    if (_e236) {
                        uint _e237 = l_1;
                        chosen = _e237;
                    }
                    { uint dummy_3 = 0; grid.InterlockedExchange(at_1*4, 0u, dummy_3); }
                    { uint dummy_4 = 0; grid.InterlockedExchange((at_1 + 1u)*4, 0u, dummy_4); }
                }
            }
            { uint dummy_5 = 0; grid.InterlockedExchange((h_1 + 13u)*4, 0u, dummy_5); }
            uint _e255 = chosen;
            uint _e258 = params.levels;
            if ((_e255 < _e258)) {
                uint _e261 = chosen;
                GridFrame _e263 = ConstructGridFrame(asfloat(grid_levels.Load3(_e261*48+0)), asuint(grid_levels.Load(_e261*48+12)), asfloat(grid_levels.Load3(_e261*48+16)), asuint(grid_levels.Load(_e261*48+28)), asfloat(grid_levels.Load3(_e261*48+32)), asuint(grid_levels.Load(_e261*48+44)));
                f = _e263;
            }
            float _e268 = f.lo.x;
            { uint dummy_6 = 0; grid.InterlockedExchange(h_1*4, asuint(_e268), dummy_6); }
            float _e276 = f.lo.y;
            { uint dummy_7 = 0; grid.InterlockedExchange((h_1 + 1u)*4, asuint(_e276), dummy_7); }
            float _e284 = f.lo.z;
            { uint dummy_8 = 0; grid.InterlockedExchange((h_1 + 2u)*4, asuint(_e284), dummy_8); }
            uint _e291 = f.nx;
            { uint dummy_9 = 0; grid.InterlockedExchange((h_1 + 3u)*4, _e291, dummy_9); }
            float _e298 = f.hi.x;
            { uint dummy_10 = 0; grid.InterlockedExchange((h_1 + 4u)*4, asuint(_e298), dummy_10); }
            float _e306 = f.hi.y;
            { uint dummy_11 = 0; grid.InterlockedExchange((h_1 + 5u)*4, asuint(_e306), dummy_11); }
            float _e314 = f.hi.z;
            { uint dummy_12 = 0; grid.InterlockedExchange((h_1 + 6u)*4, asuint(_e314), dummy_12); }
            uint _e321 = f.ny;
            { uint dummy_13 = 0; grid.InterlockedExchange((h_1 + 7u)*4, _e321, dummy_13); }
            float _e328 = f.inv.x;
            { uint dummy_14 = 0; grid.InterlockedExchange((h_1 + 8u)*4, asuint(_e328), dummy_14); }
            float _e336 = f.inv.y;
            { uint dummy_15 = 0; grid.InterlockedExchange((h_1 + 9u)*4, asuint(_e336), dummy_15); }
            float _e344 = f.inv.z;
            { uint dummy_16 = 0; grid.InterlockedExchange((h_1 + 10u)*4, asuint(_e344), dummy_16); }
            uint _e351 = f.nz;
            { uint dummy_17 = 0; grid.InterlockedExchange((h_1 + 11u)*4, _e351, dummy_17); }
            float _e358 = params.reach;
            { uint dummy_18 = 0; grid.InterlockedExchange((h_1 + 12u)*4, asuint(_e358), dummy_18); }
            return;
        }
        case 2u:
        case 4u: {
            uint _e362 = params.count;
            if ((i_2 >= _e362)) {
                return;
            }
            const GridFrame _e364 = grid_frame(h_1);
            const uint _e365 = grid_leaf(i_2);
            if (!((_e364.nx == 0u))) {
                local_2 = (_e365 == BSH_NONE);
            } else {
                local_2 = true;
            }
            bool _e375 = local_2;
            if (_e375) {
                return;
            }
            BshNode leaf_1 = ConstructBshNode(asfloat(bsh_nodes.Load3(_e365*32+0)), asfloat(bsh_nodes.Load(_e365*32+12)), asuint(bsh_nodes.Load(_e365*32+16)), asuint(bsh_nodes.Load(_e365*32+20)), asuint(bsh_nodes.Load(_e365*32+24)), asfloat(bsh_nodes.Load(_e365*32+28)));
            float _e381 = params.reach;
            const float _e382 = bsh_grid_reach(leaf_1, _e381);
            const float _e383 = bsh_grid_pad(_e382);
            const uint3 _e385 = bsh_grid_first(_e364, leaf_1.center_, _e383);
            const uint3 _e387 = bsh_grid_last(_e364, leaf_1.center_, _e383);
            z = _e385.z;
            uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e434 = z;
                    z = (_e434 + 1u);
                }
                loop_init_5 = false;
                uint _e390 = z;
                if ((_e390 <= _e387.z)) {
                } else {
                    break;
                }
                {
                    y = _e385.y;
                    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
                    bool loop_init_6 = true;
                    while(true) {
                        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
                        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                        if (!loop_init_6) {
                            uint _e431 = y;
                            y = (_e431 + 1u);
                        }
                        loop_init_6 = false;
                        uint _e395 = y;
                        if ((_e395 <= _e387.y)) {
                        } else {
                            break;
                        }
                        {
                            x = _e385.x;
                            uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
                            bool loop_init_7 = true;
                            while(true) {
                                if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
                                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                                if (!loop_init_7) {
                                    uint _e428 = x;
                                    x = (_e428 + 1u);
                                }
                                loop_init_7 = false;
                                uint _e400 = x;
                                if ((_e400 <= _e387.x)) {
                                } else {
                                    break;
                                }
                                {
                                    uint _e403 = z;
                                    uint _e406 = y;
                                    uint _e410 = x;
                                    uint c_5 = ((((_e403 * _e364.ny) + _e406) * _e364.nx) + _e410);
                                    uint _e415 = params.fill;
                                    uint _e419; grid_fill.InterlockedAdd((_e415 + c_5)*4, 1u, _e419);
                                    uint _e422 = params.stage;
                                    if ((_e422 == 4u)) {
                                        grid_entries.Store(_e419*4, asuint(i_2));
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
            const GridFrame _e436 = grid_frame(h_1);
            if ((i_2 >= ((_e436.nx * _e436.ny) * _e436.nz))) {
                return;
            }
            uint _e446 = params.fill;
            { uint dummy_19 = 0; grid_fill.InterlockedExchange((_e446 + i_2)*4, 0u, dummy_19); }
            uint a_2; grid.InterlockedOr((starts + i_2)*4, 0, a_2);
            uint b_2; grid.InterlockedOr(((starts + i_2) + 1u)*4, 0, b_2);
            s = (a_2 + 1u);
            uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
                loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e500 = s;
                    s = (_e500 + 1u);
                }
                loop_init_8 = false;
                uint _e463 = s;
                if ((_e463 < b_2)) {
                } else {
                    break;
                }
                {
                    uint _e466 = s;
                    uint v_1 = asuint(grid_entries.Load(_e466*4));
                    uint _e469 = s;
                    c_2 = _e469;
                    uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
                    while(true) {
                        if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
                        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                        uint _e471 = c_2;
                        if ((_e471 > a_2)) {
                            uint _e476 = c_2;
                            uint _e480 = asuint(grid_entries.Load((_e476 - 1u)*4));
                            local_3 = (_e480 > v_1);
                        } else {
                            local_3 = false;
                        }
                        bool _e483 = local_3;
                        if (_e483) {
                        } else {
                            break;
                        }
                        {
                            uint _e485 = c_2;
                            uint _e488 = c_2;
                            uint _e492 = asuint(grid_entries.Load((_e488 - 1u)*4));
                            grid_entries.Store(_e485*4, asuint(_e492));
                            uint _e493 = c_2;
                            c_2 = (_e493 - 1u);
                        }
                    }
                    uint _e497 = c_2;
                    grid_entries.Store(_e497*4, asuint(v_1));
                }
            }
            s_1 = a_2;
            uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
            bool loop_init_9 = true;
            while(true) {
                if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_9) {
                    uint _e516 = s_1;
                    s_1 = (_e516 + 1u);
                }
                loop_init_9 = false;
                uint _e503 = s_1;
                if ((_e503 < b_2)) {
                } else {
                    break;
                }
                {
                    uint _e506 = s_1;
                    uint _e510 = s_1;
                    uint _e512 = asuint(grid_entries.Load(_e510*4));
                    uint _e514 = asuint(grid_leaves.Load(_e512*4));
                    grid_entries.Store(_e506*4, asuint(_e514));
                }
            }
            return;
        }
    }
}
