struct GridStage {
    uint stage;
    uint count;
    uint levels;
    uint moves;
};

struct GridParams {
    uint capacity;
    float reach;
    uint header;
    uint fill;
    uint entries;
    uint least;
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
static const uint GRID_ENTRIES_PER_LIGHT = 8u;
static const float LOBE_CONE_PAD = 1.001;

cbuffer params : register(b0) { GridStage params; }
ByteAddressBuffer bsh_nodes : register(t1);
ByteAddressBuffer grid_leaves : register(t2);
ByteAddressBuffer grid_levels : register(t3);
RWByteAddressBuffer grid : register(u4);
RWByteAddressBuffer grid_fill : register(u5);
RWByteAddressBuffer grid_entries : register(u6);
ByteAddressBuffer grids : register(t7);
groupshared uint wg_sums[64];
groupshared uint2 wg_big[64];
groupshared uint wg_bigs;
groupshared uint wg_cell[1024];

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

uint to_u32_(float x)
{
    return naga_f2u32(x);
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

uint bsh_grid_budget(uint leaves, uint cells, uint least)
{
    if ((leaves > 536870911u)) {
        return 4294967295u;
    }
    uint e_1 = (leaves * GRID_ENTRIES_PER_LIGHT);
    const uint _e8 = add_wrap_u32_(e_1, cells);
    return max(((_e8 < e_1) ? 4294967295u : _e8), least);
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

uint3 bsh_grid_first(GridFrame f, float3 c, float r)
{
    const uint _e10 = bsh_grid_axis((c.x - r), f.lo.x, f.inv.x, f.nx);
    const uint _e18 = bsh_grid_axis((c.y - r), f.lo.y, f.inv.y, f.ny);
    const uint _e26 = bsh_grid_axis((c.z - r), f.lo.z, f.inv.z, f.nz);
    return uint3(_e10, _e18, _e26);
}

uint3 bsh_grid_last(GridFrame f_1, float3 c_1, float r_1)
{
    const uint _e10 = bsh_grid_axis((c_1.x + r_1), f_1.lo.x, f_1.inv.x, f_1.nx);
    const uint _e18 = bsh_grid_axis((c_1.y + r_1), f_1.lo.y, f_1.inv.y, f_1.ny);
    const uint _e26 = bsh_grid_axis((c_1.z + r_1), f_1.lo.z, f_1.inv.z, f_1.nz);
    return uint3(_e10, _e18, _e26);
}

uint grid_word(uint i)
{
    uint _e3; grid.InterlockedOr(i*4, 0, _e3);
    return _e3;
}

GridFrame grid_frame(uint h)
{
    GridFrame f_2 = (GridFrame)0;

    const uint _e3 = grid_word(h);
    const uint _e7 = grid_word((h + 1u));
    const uint _e11 = grid_word((h + 2u));
    f_2.lo = float3(asfloat(_e3), asfloat(_e7), asfloat(_e11));
    const uint _e17 = grid_word((h + 3u));
    f_2.nx = _e17;
    const uint _e21 = grid_word((h + 4u));
    const uint _e25 = grid_word((h + 5u));
    const uint _e29 = grid_word((h + 6u));
    f_2.hi = float3(asfloat(_e21), asfloat(_e25), asfloat(_e29));
    const uint _e35 = grid_word((h + 7u));
    f_2.ny = _e35;
    const uint _e39 = grid_word((h + 8u));
    const uint _e43 = grid_word((h + 9u));
    const uint _e47 = grid_word((h + 10u));
    f_2.inv = float3(asfloat(_e39), asfloat(_e43), asfloat(_e47));
    const uint _e53 = grid_word((h + 11u));
    f_2.nz = _e53;
    GridFrame _e54 = f_2;
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

uint cell_key(bool big, uint a_1, uint j)
{
    if (big) {
        uint _e6 = asuint(grid_entries.Load((a_1 + j)*4));
        return _e6;
    }
    uint _e9 = wg_cell[min(uint(j), 1023u)];
    return _e9;
}

void set_cell_key(bool big_1, uint a_2, uint j_1, uint v_1)
{
    if (big_1) {
        grid_entries.Store((a_2 + j_1)*4, asuint(v_1));
        return;
    } else {
        wg_cell[min(uint(j_1), 1023u)] = v_1;
        return;
    }
}

void sort_together(uint b_1, uint li_1)
{
    uint j_2 = (uint)0;
    uint p = 1u;
    uint k = 2u;
    uint h_1 = (uint)0;
    uint t = (uint)0;
    uint j_3 = (uint)0;

    GroupMemoryBarrierWithGroupSync();
    uint2 _e4 = wg_big[min(uint(b_1), 63u)];
    GroupMemoryBarrierWithGroupSync();
    uint a_3 = _e4.x;
    uint n_1 = (_e4.y - _e4.x);
    bool big_2 = (n_1 > GRID_SORT_MAX);
    if (!(big_2)) {
        j_2 = li_1;
        uint2 loop_bound = uint2(4294967295u, 4294967295u);
        bool loop_init = true;
        while(true) {
            if (all(loop_bound == uint2(0u, 0u))) { break; }
            loop_bound -= uint2(loop_bound.y == 0u, 1u);
            if (!loop_init) {
                uint _e23 = j_2;
                j_2 = (_e23 + 64u);
            }
            loop_init = false;
            uint _e13 = j_2;
            if ((_e13 < n_1)) {
            } else {
                break;
            }
            {
                uint _e16 = j_2;
                uint _e19 = j_2;
                uint _e22 = asuint(grid_entries.Load((a_3 + _e19)*4));
                wg_cell[min(uint(_e16), 1023u)] = _e22;
            }
        }
    }
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e28 = p;
        if ((_e28 < n_1)) {
        } else {
            break;
        }
        {
            uint _e30 = p;
            p = (_e30 << 1u);
        }
    }
    GroupMemoryBarrierWithGroupSync();
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e87 = k;
            k = (_e87 << 1u);
        }
        loop_init_1 = false;
        uint _e35 = k;
        uint _e36 = p;
        if ((_e35 <= _e36)) {
        } else {
            break;
        }
        {
            uint _e38 = k;
            h_1 = (_e38 >> 1u);
            uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e84 = h_1;
                    h_1 = (_e84 >> 1u);
                }
                loop_init_2 = false;
                uint _e42 = h_1;
                if ((_e42 > 0u)) {
                } else {
                    break;
                }
                {
                    t = li_1;
                    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
                    bool loop_init_3 = true;
                    while(true) {
                        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
                        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                        if (!loop_init_3) {
                            uint _e81 = t;
                            t = (_e81 + 64u);
                        }
                        loop_init_3 = false;
                        uint _e46 = t;
                        uint _e47 = p;
                        if ((_e46 < (_e47 >> 1u))) {
                        } else {
                            break;
                        }
                        {
                            uint _e51 = t;
                            uint _e52 = h_1;
                            uint _e59 = t;
                            uint _e60 = h_1;
                            uint i_4 = (((_e51 & ~((_e52 - 1u))) << 1u) | (_e59 & (_e60 - 1u)));
                            uint _e65 = h_1;
                            uint _e67 = k;
                            uint _e71 = h_1;
                            uint _e72 = k;
                            uint o = ((_e71 == (_e72 >> 1u)) ? (i_4 ^ (_e67 - 1u)) : (i_4 | _e65));
                            if ((o < n_1)) {
                                const uint _e78 = cell_key(big_2, a_3, i_4);
                                const uint _e79 = cell_key(big_2, a_3, o);
                                if ((_e79 < _e78)) {
                                    set_cell_key(big_2, a_3, i_4, _e79);
                                    set_cell_key(big_2, a_3, o, _e78);
                                }
                            }
                        }
                    }
                    GroupMemoryBarrierWithGroupSync();
                    DeviceMemoryBarrierWithGroupSync();
                }
            }
        }
    }
    j_3 = li_1;
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e102 = j_3;
            j_3 = (_e102 + 64u);
        }
        loop_init_4 = false;
        uint _e91 = j_3;
        if ((_e91 < n_1)) {
        } else {
            break;
        }
        {
            uint _e94 = j_3;
            uint _e98 = j_3;
            const uint _e99 = cell_key(big_2, a_3, _e98);
            uint _e101 = asuint(grid_leaves.Load(_e99*4));
            grid_entries.Store((a_3 + _e94)*4, asuint(_e101));
        }
    }
    GroupMemoryBarrierWithGroupSync();
    return;
}

void sort_cells(GridParams g, uint first, uint li_2)
{
    uint2 span = (0u).xx;
    uint s = (uint)0;
    uint moves = 0u;
    bool local = (bool)0;
    uint c_2 = (uint)0;
    bool local_1 = (bool)0;
    uint e = (uint)0;
    uint b_2 = 0u;

    uint starts = (g.header + GRID_HEADER);
    const GridFrame _e7 = grid_frame(g.header);
    uint cell = (first + li_2);
    if ((cell < ((_e7.nx * _e7.ny) * _e7.nz))) {
        uint _e21; grid.InterlockedOr((starts + cell)*4, 0, _e21);
        uint _e27; grid.InterlockedOr(((starts + cell) + 1u)*4, 0, _e27);
        span = uint2(_e21, _e27);
        { uint dummy = 0; grid_fill.InterlockedExchange((g.fill + cell)*4, 0u, dummy); }
    }
    if ((li_2 == 0u)) {
        { uint dummy_1 = 0; InterlockedExchange(wg_bigs, 0u, dummy_1); }
    }
    GroupMemoryBarrierWithGroupSync();
    uint _e39 = span.x;
    s = (_e39 + 1u);
    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        uint _e45 = s;
        uint _e47 = span.y;
        if ((_e45 < _e47)) {
            uint _e51 = moves;
            uint _e54 = params.moves;
            local = (_e51 < _e54);
        } else {
            local = false;
        }
        bool _e57 = local;
        if (_e57) {
        } else {
            break;
        }
        {
            uint _e59 = s;
            uint v_2 = asuint(grid_entries.Load(_e59*4));
            uint _e62 = s;
            c_2 = _e62;
            uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
            while(true) {
                if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                uint _e64 = c_2;
                uint _e66 = span.x;
                if ((_e64 > _e66)) {
                    uint _e71 = c_2;
                    uint _e75 = asuint(grid_entries.Load((_e71 - 1u)*4));
                    local_1 = (_e75 > v_2);
                } else {
                    local_1 = false;
                }
                bool _e78 = local_1;
                if (_e78) {
                } else {
                    break;
                }
                {
                    uint _e80 = c_2;
                    uint _e83 = c_2;
                    uint _e87 = asuint(grid_entries.Load((_e83 - 1u)*4));
                    grid_entries.Store(_e80*4, asuint(_e87));
                    uint _e88 = c_2;
                    c_2 = (_e88 - 1u);
                }
            }
            uint _e92 = c_2;
            grid_entries.Store(_e92*4, asuint(v_2));
            uint _e94 = moves;
            uint _e95 = s;
            uint _e96 = c_2;
            moves = (_e94 + (_e95 - _e96));
            uint _e99 = s;
            s = (_e99 + 1u);
        }
    }
    uint _e102 = s;
    uint _e104 = span.y;
    if ((_e102 < _e104)) {
        uint _e109; InterlockedAdd(wg_bigs, 1u, _e109);
        uint2 _e111 = span;
        wg_big[min(uint(_e109), 63u)] = _e111;
    } else {
        uint _e113 = span.x;
        e = _e113;
        uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
        bool loop_init_5 = true;
        while(true) {
            if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
            loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
            if (!loop_init_5) {
                uint _e130 = e;
                e = (_e130 + 1u);
            }
            loop_init_5 = false;
            uint _e115 = e;
            uint _e117 = span.y;
            if ((_e115 < _e117)) {
            } else {
                break;
            }
            {
                uint _e120 = e;
                uint _e124 = e;
                uint _e126 = asuint(grid_entries.Load(_e124*4));
                uint _e128 = asuint(grid_leaves.Load(_e126*4));
                grid_entries.Store(_e120*4, asuint(_e128));
            }
        }
    }
    DeviceMemoryBarrierWithGroupSync();
    GroupMemoryBarrierWithGroupSync();
    uint _e133 = wg_bigs;
    GroupMemoryBarrierWithGroupSync();
    uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
    bool loop_init_6 = true;
    while(true) {
        if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_6) {
            uint _e140 = b_2;
            b_2 = (_e140 + 1u);
        }
        loop_init_6 = false;
        uint _e136 = b_2;
        if ((_e136 < _e133)) {
        } else {
            break;
        }
        {
            uint _e138 = b_2;
            sort_together(_e138, li_2);
        }
    }
    return;
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

void count_levels(GridParams g_1, uint i_2)
{
    uint l = 0u;

    uint _e4 = params.count;
    if ((i_2 >= _e4)) {
        return;
    }
    uint h_2 = g_1.header;
    const uint _e7 = grid_leaf(i_2);
    if ((_e7 == BSH_NONE)) {
        return;
    }
    uint _e15; grid.InterlockedAdd((h_2 + 13u)*4, 1u, _e15);
    BshNode leaf = ConstructBshNode(asfloat(bsh_nodes.Load3(_e7*32+0)), asfloat(bsh_nodes.Load(_e7*32+12)), asuint(bsh_nodes.Load(_e7*32+16)), asuint(bsh_nodes.Load(_e7*32+20)), asuint(bsh_nodes.Load(_e7*32+24)), asfloat(bsh_nodes.Load(_e7*32+28)));
    const float _e20 = bsh_grid_radius(leaf, g_1.reach);
    uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
    bool loop_init_7 = true;
    while(true) {
        if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        if (!loop_init_7) {
            uint _e67 = l;
            l = (_e67 + 1u);
        }
        loop_init_7 = false;
        uint _e23 = l;
        uint _e26 = params.levels;
        if ((_e23 < _e26)) {
        } else {
            break;
        }
        {
            uint _e29 = l;
            GridFrame _e31 = ConstructGridFrame(asfloat(grid_levels.Load3(_e29*48+0)), asuint(grid_levels.Load(_e29*48+12)), asfloat(grid_levels.Load3(_e29*48+16)), asuint(grid_levels.Load(_e29*48+28)), asfloat(grid_levels.Load3(_e29*48+32)), asuint(grid_levels.Load(_e29*48+44)));
            const uint3 _e33 = bsh_grid_last(_e31, leaf.center_, _e20);
            uint _e35 = l;
            GridFrame _e37 = ConstructGridFrame(asfloat(grid_levels.Load3(_e35*48+0)), asuint(grid_levels.Load(_e35*48+12)), asfloat(grid_levels.Load3(_e35*48+16)), asuint(grid_levels.Load(_e35*48+28)), asfloat(grid_levels.Load3(_e35*48+32)), asuint(grid_levels.Load(_e35*48+44)));
            const uint3 _e39 = bsh_grid_first(_e37, leaf.center_, _e20);
            uint3 d = ((_e33 - _e39) + (1u).xxx);
            uint n_2 = ((d.x * d.y) * d.z);
            uint _e52 = l;
            uint at = ((h_2 + 16u) + (2u * _e52));
            uint _e57; grid.InterlockedAdd(at*4, n_2, _e57);
            if (((_e57 + n_2) < _e57)) {
                uint _e65; grid.InterlockedAdd((at + 1u)*4, 1u, _e65);
            }
        }
    }
    return;
}

void choose_level(GridParams g_2)
{
    uint chosen = (uint)0;
    uint l_1 = 0u;
    bool local_2 = (bool)0;
    bool local_3 = (bool)0;
    GridFrame f_3 = (GridFrame)0;

    uint h_3 = g_2.header;
    uint leaves_1; grid.InterlockedOr((h_3 + 13u)*4, 0, leaves_1);
    uint _e9 = params.levels;
    chosen = _e9;
    uint2 loop_bound_11 = uint2(4294967295u, 4294967295u);
    bool loop_init_8 = true;
    while(true) {
        if (all(loop_bound_11 == uint2(0u, 0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_8) {
            uint _e71 = l_1;
            l_1 = (_e71 + 1u);
        }
        loop_init_8 = false;
        uint _e13 = l_1;
        uint _e16 = params.levels;
        if ((_e13 < _e16)) {
        } else {
            break;
        }
        {
            uint _e19 = l_1;
            GridFrame f_4 = ConstructGridFrame(asfloat(grid_levels.Load3(_e19*48+0)), asuint(grid_levels.Load(_e19*48+12)), asfloat(grid_levels.Load3(_e19*48+16)), asuint(grid_levels.Load(_e19*48+28)), asfloat(grid_levels.Load3(_e19*48+32)), asuint(grid_levels.Load(_e19*48+44)));
            uint cells_1 = ((f_4.nx * f_4.ny) * f_4.nz);
            const uint _e28 = bsh_grid_budget(leaves_1, cells_1, g_2.least);
            uint budget = min(_e28, g_2.capacity);
            uint _e34 = l_1;
            uint at_1 = ((h_3 + 16u) + (2u * _e34));
            uint _e37 = chosen;
            uint _e40 = params.levels;
            if ((_e37 == _e40)) {
                uint _e48; grid.InterlockedOr((at_1 + 1u)*4, 0, _e48);
                local_2 = (_e48 == 0u);
            } else {
                local_2 = false;
            }
            bool _e52 = local_2;
            if (_e52) {
                uint _e57; grid.InterlockedOr(at_1*4, 0, _e57);
                local_3 = (_e57 <= budget);
            } else {
                local_3 = false;
            }
            bool _e60 = local_3;
            if (_e60) {
                uint _e61 = l_1;
                chosen = _e61;
            }
            { uint dummy_2 = 0; grid.InterlockedExchange(at_1*4, 0u, dummy_2); }
            { uint dummy_3 = 0; grid.InterlockedExchange((at_1 + 1u)*4, 0u, dummy_3); }
        }
    }
    { uint dummy_4 = 0; grid.InterlockedExchange((h_3 + 13u)*4, 0u, dummy_4); }
    uint _e79 = chosen;
    uint _e82 = params.levels;
    if ((_e79 < _e82)) {
        uint _e85 = chosen;
        GridFrame _e87 = ConstructGridFrame(asfloat(grid_levels.Load3(_e85*48+0)), asuint(grid_levels.Load(_e85*48+12)), asfloat(grid_levels.Load3(_e85*48+16)), asuint(grid_levels.Load(_e85*48+28)), asfloat(grid_levels.Load3(_e85*48+32)), asuint(grid_levels.Load(_e85*48+44)));
        f_3 = _e87;
    }
    float _e92 = f_3.lo.x;
    { uint dummy_5 = 0; grid.InterlockedExchange(h_3*4, asuint(_e92), dummy_5); }
    float _e100 = f_3.lo.y;
    { uint dummy_6 = 0; grid.InterlockedExchange((h_3 + 1u)*4, asuint(_e100), dummy_6); }
    float _e108 = f_3.lo.z;
    { uint dummy_7 = 0; grid.InterlockedExchange((h_3 + 2u)*4, asuint(_e108), dummy_7); }
    uint _e115 = f_3.nx;
    { uint dummy_8 = 0; grid.InterlockedExchange((h_3 + 3u)*4, _e115, dummy_8); }
    float _e122 = f_3.hi.x;
    { uint dummy_9 = 0; grid.InterlockedExchange((h_3 + 4u)*4, asuint(_e122), dummy_9); }
    float _e130 = f_3.hi.y;
    { uint dummy_10 = 0; grid.InterlockedExchange((h_3 + 5u)*4, asuint(_e130), dummy_10); }
    float _e138 = f_3.hi.z;
    { uint dummy_11 = 0; grid.InterlockedExchange((h_3 + 6u)*4, asuint(_e138), dummy_11); }
    uint _e145 = f_3.ny;
    { uint dummy_12 = 0; grid.InterlockedExchange((h_3 + 7u)*4, _e145, dummy_12); }
    float _e152 = f_3.inv.x;
    { uint dummy_13 = 0; grid.InterlockedExchange((h_3 + 8u)*4, asuint(_e152), dummy_13); }
    float _e160 = f_3.inv.y;
    { uint dummy_14 = 0; grid.InterlockedExchange((h_3 + 9u)*4, asuint(_e160), dummy_14); }
    float _e168 = f_3.inv.z;
    { uint dummy_15 = 0; grid.InterlockedExchange((h_3 + 10u)*4, asuint(_e168), dummy_15); }
    uint _e175 = f_3.nz;
    { uint dummy_16 = 0; grid.InterlockedExchange((h_3 + 11u)*4, _e175, dummy_16); }
    { uint dummy_17 = 0; grid.InterlockedExchange((h_3 + 12u)*4, asuint(g_2.reach), dummy_17); }
    return;
}

void fill_cells(GridParams g_3, uint i_3, bool scatter)
{
    bool local_4 = (bool)0;
    uint z = (uint)0;
    uint y = (uint)0;
    uint x_1 = (uint)0;

    uint _e5 = params.count;
    if ((i_3 >= _e5)) {
        return;
    }
    const GridFrame _e8 = grid_frame(g_3.header);
    const uint _e9 = grid_leaf(i_3);
    if (!((_e8.nx == 0u))) {
        local_4 = (_e9 == BSH_NONE);
    } else {
        local_4 = true;
    }
    bool _e19 = local_4;
    if (_e19) {
        return;
    }
    BshNode leaf_1 = ConstructBshNode(asfloat(bsh_nodes.Load3(_e9*32+0)), asfloat(bsh_nodes.Load(_e9*32+12)), asuint(bsh_nodes.Load(_e9*32+16)), asuint(bsh_nodes.Load(_e9*32+20)), asuint(bsh_nodes.Load(_e9*32+24)), asfloat(bsh_nodes.Load(_e9*32+28)));
    const float _e24 = bsh_grid_radius(leaf_1, g_3.reach);
    const uint3 _e26 = bsh_grid_first(_e8, leaf_1.center_, _e24);
    const uint3 _e28 = bsh_grid_last(_e8, leaf_1.center_, _e24);
    z = _e26.z;
    uint2 loop_bound_12 = uint2(4294967295u, 4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (all(loop_bound_12 == uint2(0u, 0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e68 = z;
            z = (_e68 + 1u);
        }
        loop_init_9 = false;
        uint _e31 = z;
        if ((_e31 <= _e28.z)) {
        } else {
            break;
        }
        {
            y = _e26.y;
            uint2 loop_bound_13 = uint2(4294967295u, 4294967295u);
            bool loop_init_10 = true;
            while(true) {
                if (all(loop_bound_13 == uint2(0u, 0u))) { break; }
                loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                if (!loop_init_10) {
                    uint _e65 = y;
                    y = (_e65 + 1u);
                }
                loop_init_10 = false;
                uint _e36 = y;
                if ((_e36 <= _e28.y)) {
                } else {
                    break;
                }
                {
                    x_1 = _e26.x;
                    uint2 loop_bound_14 = uint2(4294967295u, 4294967295u);
                    bool loop_init_11 = true;
                    while(true) {
                        if (all(loop_bound_14 == uint2(0u, 0u))) { break; }
                        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
                        if (!loop_init_11) {
                            uint _e62 = x_1;
                            x_1 = (_e62 + 1u);
                        }
                        loop_init_11 = false;
                        uint _e41 = x_1;
                        if ((_e41 <= _e28.x)) {
                        } else {
                            break;
                        }
                        {
                            uint _e44 = z;
                            uint _e47 = y;
                            uint _e51 = x_1;
                            uint c_5 = ((((_e44 * _e8.ny) + _e47) * _e8.nx) + _e51);
                            uint _e58; grid_fill.InterlockedAdd((g_3.fill + c_5)*4, 1u, _e58);
                            if (scatter) {
                                grid_entries.Store(_e58*4, asuint(i_3));
                            }
                        }
                    }
                }
            }
        }
    }
    return;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

void scan_starts(GridParams g_4, uint li_3)
{
    uint sum = 0u;
    uint c_3 = (uint)0;
    uint start = (uint)0;
    uint j_4 = 0u;
    uint c_4 = (uint)0;

    uint starts_1 = (g_4.header + GRID_HEADER);
    const GridFrame _e6 = grid_frame(g_4.header);
    uint cells_2 = ((_e6.nx * _e6.ny) * _e6.nz);
    uint run = naga_div(((cells_2 + 64u) - 1u), 64u);
    uint a_4 = min((li_3 * run), cells_2);
    uint b_3 = min((a_4 + run), cells_2);
    c_3 = a_4;
    uint2 loop_bound_15 = uint2(4294967295u, 4294967295u);
    bool loop_init_12 = true;
    while(true) {
        if (all(loop_bound_15 == uint2(0u, 0u))) { break; }
        loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
        if (!loop_init_12) {
            uint _e36 = c_3;
            c_3 = (_e36 + 1u);
        }
        loop_init_12 = false;
        uint _e25 = c_3;
        if ((_e25 < b_3)) {
        } else {
            break;
        }
        {
            uint _e27 = sum;
            uint _e30 = c_3;
            uint _e33; grid_fill.InterlockedOr((g_4.fill + _e30)*4, 0, _e33);
            sum = (_e27 + _e33);
        }
    }
    uint _e40 = sum;
    wg_sums[min(uint(li_3), 63u)] = _e40;
    GroupMemoryBarrierWithGroupSync();
    start = g_4.entries;
    uint2 loop_bound_16 = uint2(4294967295u, 4294967295u);
    bool loop_init_13 = true;
    while(true) {
        if (all(loop_bound_16 == uint2(0u, 0u))) { break; }
        loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
        if (!loop_init_13) {
            uint _e54 = j_4;
            j_4 = (_e54 + 1u);
        }
        loop_init_13 = false;
        uint _e45 = j_4;
        if ((_e45 < li_3)) {
        } else {
            break;
        }
        {
            uint _e47 = start;
            uint _e49 = j_4;
            uint _e51 = wg_sums[min(uint(_e49), 63u)];
            start = (_e47 + _e51);
        }
    }
    c_4 = a_4;
    uint2 loop_bound_17 = uint2(4294967295u, 4294967295u);
    bool loop_init_14 = true;
    while(true) {
        if (all(loop_bound_17 == uint2(0u, 0u))) { break; }
        loop_bound_17 -= uint2(loop_bound_17.y == 0u, 1u);
        if (!loop_init_14) {
            uint _e79 = c_4;
            c_4 = (_e79 + 1u);
        }
        loop_init_14 = false;
        uint _e57 = c_4;
        if ((_e57 < b_3)) {
        } else {
            break;
        }
        {
            uint _e61 = c_4;
            uint n_3; grid_fill.InterlockedOr((g_4.fill + _e61)*4, 0, n_3);
            uint _e66 = c_4;
            uint _e69 = start;
            { uint dummy_18 = 0; grid.InterlockedExchange((starts_1 + _e66)*4, _e69, dummy_18); }
            uint _e72 = c_4;
            uint _e75 = start;
            { uint dummy_19 = 0; grid_fill.InterlockedExchange((g_4.fill + _e72)*4, _e75, dummy_19); }
            uint _e76 = start;
            start = (_e76 + n_3);
        }
    }
    if (((li_3 + 1u) == 64u)) {
        uint _e88 = start;
        { uint dummy_20 = 0; grid.InterlockedExchange((starts_1 + cells_2)*4, _e88, dummy_20); }
        return;
    } else {
        return;
    }
}

GridParams ConstructGridParams(uint arg0, float arg1, uint arg2, uint arg3, uint arg4, uint arg5) {
    GridParams ret = (GridParams)0;
    ret.capacity = arg0;
    ret.reach = arg1;
    ret.header = arg2;
    ret.fill = arg3;
    ret.entries = arg4;
    ret.least = arg5;
    return ret;
}

[numthreads(64, 1, 1)]
void main(uint3 gid : SV_DispatchThreadID, uint3 wid : SV_GroupID, uint3 groups : SV_GroupID, uint li : SV_GroupIndex)
{
    if (li == 0) {
        wg_sums = (uint[64])0;
        wg_big = (uint2[64])0;
        wg_bigs = (uint)0;
        wg_cell = (uint[1024])0;
    }
    GroupMemoryBarrierWithGroupSync();
    GridParams g_5 = ConstructGridParams(asuint(grids.Load(wid.z*24+0)), asfloat(grids.Load(wid.z*24+4)), asuint(grids.Load(wid.z*24+8)), asuint(grids.Load(wid.z*24+12)), asuint(grids.Load(wid.z*24+16)), asuint(grids.Load(wid.z*24+20)));
    uint _e10 = params.stage;
    switch(_e10) {
        case 0u: {
            count_levels(g_5, gid.x);
            return;
        }
        case 1u: {
            if ((li == 0u)) {
                choose_level(g_5);
                return;
            } else {
                return;
            }
            break;
        }
        case 3u: {
            scan_starts(g_5, li);
            return;
        }
        case 5u: {
            sort_cells(g_5, (((wid.y * groups.x) + wid.x) * 64u), li);
            return;
        }
        default: {
            uint _e24 = params.stage;
            fill_cells(g_5, gid.x, (_e24 == 4u));
            return;
        }
    }
}
