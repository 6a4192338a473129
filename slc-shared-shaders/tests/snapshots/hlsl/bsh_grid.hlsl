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
    uint least;
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
static const uint GRID_SORT_MAX = 1536u;
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
static const float LOBE_CONE_PAD = 1.001;

cbuffer params : register(b0) { GridParams params; }
ByteAddressBuffer bsh_nodes : register(t1);
ByteAddressBuffer grid_leaves : register(t2);
ByteAddressBuffer grid_levels : register(t3);
RWByteAddressBuffer grid : register(u4);
RWByteAddressBuffer grid_fill : register(u5);
RWByteAddressBuffer grid_entries : register(u6);
groupshared uint wg_sums[64];
groupshared uint wg_cell[1536];
groupshared uint2 wg_span;

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

uint bsh_grid_budget(uint leaves, uint cells, uint least)
{
    if ((leaves > 536870911u)) {
        return 4294967295u;
    }
    uint e = (leaves * GRID_ENTRIES_PER_LIGHT);
    const uint _e8 = add_wrap_u32_(e, cells);
    return max(((_e8 < e) ? 4294967295u : _e8), least);
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

uint3 bsh_grid_first(GridFrame f_1, float3 c_2, float r)
{
    const uint _e10 = bsh_grid_axis((c_2.x - r), f_1.lo.x, f_1.inv.x, f_1.nx);
    const uint _e18 = bsh_grid_axis((c_2.y - r), f_1.lo.y, f_1.inv.y, f_1.ny);
    const uint _e26 = bsh_grid_axis((c_2.z - r), f_1.lo.z, f_1.inv.z, f_1.nz);
    return uint3(_e10, _e18, _e26);
}

uint3 bsh_grid_last(GridFrame f_2, float3 c_3, float r_1)
{
    const uint _e10 = bsh_grid_axis((c_3.x + r_1), f_2.lo.x, f_2.inv.x, f_2.nx);
    const uint _e18 = bsh_grid_axis((c_3.y + r_1), f_2.lo.y, f_2.inv.y, f_2.ny);
    const uint _e26 = bsh_grid_axis((c_3.z + r_1), f_2.lo.z, f_2.inv.z, f_2.nz);
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

void sort_cell(uint cell, uint li_1)
{
    uint2 span = (0u).xx;
    uint s = (uint)0;
    uint c_4 = (uint)0;
    bool local_3 = (bool)0;
    uint s_1 = (uint)0;
    uint j_1 = (uint)0;
    uint j_2 = (uint)0;
    uint below = (uint)0;
    uint m = (uint)0;

    uint _e4 = params.header;
    uint starts = (_e4 + GRID_HEADER);
    if ((li_1 == 0u)) {
        uint _e11 = params.header;
        const GridFrame _e12 = grid_frame(_e11);
        if ((cell < ((_e12.nx * _e12.ny) * _e12.nz))) {
            uint _e25; grid.InterlockedOr((starts + cell)*4, 0, _e25);
            uint _e31; grid.InterlockedOr(((starts + cell) + 1u)*4, 0, _e31);
            span = uint2(_e25, _e31);
            uint _e36 = params.fill;
            { uint dummy = 0; grid_fill.InterlockedExchange((_e36 + cell)*4, 0u, dummy); }
        }
        uint2 _e41 = span;
        wg_span = _e41;
    }
    GroupMemoryBarrierWithGroupSync();
    uint2 _e43 = wg_span;
    GroupMemoryBarrierWithGroupSync();
    uint a_1 = _e43.x;
    uint n_1 = (_e43.y - _e43.x);
    if ((n_1 > GRID_SORT_MAX)) {
        if ((li_1 == 0u)) {
            s = (a_1 + 1u);
            uint2 loop_bound = uint2(4294967295u, 4294967295u);
            bool loop_init = true;
            while(true) {
                if (all(loop_bound == uint2(0u, 0u))) { break; }
                loop_bound -= uint2(loop_bound.y == 0u, 1u);
                if (!loop_init) {
                    uint _e93 = s;
                    s = (_e93 + 1u);
                }
                loop_init = false;
                uint _e55 = s;
                if ((_e55 < (a_1 + n_1))) {
                } else {
                    break;
                }
                {
                    uint _e59 = s;
                    uint v_1 = asuint(grid_entries.Load(_e59*4));
                    uint _e62 = s;
                    c_4 = _e62;
                    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
                    while(true) {
                        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
                        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                        uint _e64 = c_4;
                        if ((_e64 > a_1)) {
                            uint _e69 = c_4;
                            uint _e73 = asuint(grid_entries.Load((_e69 - 1u)*4));
                            local_3 = (_e73 > v_1);
                        } else {
                            local_3 = false;
                        }
                        bool _e76 = local_3;
                        if (_e76) {
                        } else {
                            break;
                        }
                        {
                            uint _e78 = c_4;
                            uint _e81 = c_4;
                            uint _e85 = asuint(grid_entries.Load((_e81 - 1u)*4));
                            grid_entries.Store(_e78*4, asuint(_e85));
                            uint _e86 = c_4;
                            c_4 = (_e86 - 1u);
                        }
                    }
                    uint _e90 = c_4;
                    grid_entries.Store(_e90*4, asuint(v_1));
                }
            }
            s_1 = a_1;
            uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
            bool loop_init_1 = true;
            while(true) {
                if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
                loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                if (!loop_init_1) {
                    uint _e110 = s_1;
                    s_1 = (_e110 + 1u);
                }
                loop_init_1 = false;
                uint _e96 = s_1;
                if ((_e96 < (a_1 + n_1))) {
                } else {
                    break;
                }
                {
                    uint _e100 = s_1;
                    uint _e104 = s_1;
                    uint _e106 = asuint(grid_entries.Load(_e104*4));
                    uint _e108 = asuint(grid_leaves.Load(_e106*4));
                    grid_entries.Store(_e100*4, asuint(_e108));
                }
            }
        }
        return;
    }
    j_1 = li_1;
    uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e123 = j_1;
            j_1 = (_e123 + 64u);
        }
        loop_init_2 = false;
        uint _e113 = j_1;
        if ((_e113 < n_1)) {
        } else {
            break;
        }
        {
            uint _e116 = j_1;
            uint _e119 = j_1;
            uint _e122 = asuint(grid_entries.Load((a_1 + _e119)*4));
            wg_cell[min(uint(_e116), 1535u)] = _e122;
        }
    }
    GroupMemoryBarrierWithGroupSync();
    j_2 = li_1;
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e159 = j_2;
            j_2 = (_e159 + 64u);
        }
        loop_init_3 = false;
        uint _e127 = j_2;
        if ((_e127 < n_1)) {
        } else {
            break;
        }
        {
            uint _e130 = j_2;
            uint v_2 = wg_cell[min(uint(_e130), 1535u)];
            below = 0u;
            m = 0u;
            uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
            bool loop_init_4 = true;
            while(true) {
                if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_4) {
                    uint _e150 = m;
                    m = (_e150 + 1u);
                }
                loop_init_4 = false;
                uint _e137 = m;
                if ((_e137 < n_1)) {
                } else {
                    break;
                }
                {
                    uint _e139 = below;
                    uint _e143 = m;
                    uint _e145 = wg_cell[min(uint(_e143), 1535u)];
                    below = (_e139 + ((_e145 < v_2) ? 1u : 0u));
                }
            }
            uint _e153 = below;
            uint _e158 = asuint(grid_leaves.Load(v_2*4));
            grid_entries.Store((a_1 + _e153)*4, asuint(_e158));
        }
    }
    return;
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
void main(uint3 gid : SV_DispatchThreadID, uint3 wid : SV_GroupID, uint3 groups : SV_GroupID, uint li : SV_GroupIndex)
{
    if (li == 0) {
        wg_sums = (uint[64])0;
        wg_cell = (uint[1536])0;
        wg_span = (uint2)0;
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

    uint _e6 = params.stage;
    if ((_e6 == 5u)) {
        sort_cell(((wid.y * groups.x) + wid.x), li);
        return;
    }
    uint i_2 = gid.x;
    uint h_1 = params.header;
    uint starts_1 = (h_1 + GRID_HEADER);
    uint _e22 = params.stage;
    if ((_e22 == 3u)) {
        const GridFrame _e25 = grid_frame(h_1);
        uint cells_1 = ((_e25.nx * _e25.ny) * _e25.nz);
        uint run = naga_div(((cells_1 + 64u) - 1u), 64u);
        uint a_2 = min((i_2 * run), cells_1);
        uint b_1 = min((a_2 + run), cells_1);
        c = a_2;
        uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
        bool loop_init_5 = true;
        while(true) {
            if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
            loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
            if (!loop_init_5) {
                uint _e57 = c;
                c = (_e57 + 1u);
            }
            loop_init_5 = false;
            uint _e44 = c;
            if ((_e44 < b_1)) {
            } else {
                break;
            }
            {
                uint _e46 = sum;
                uint _e50 = params.fill;
                uint _e51 = c;
                uint _e54; grid_fill.InterlockedOr((_e50 + _e51)*4, 0, _e54);
                sum = (_e46 + _e54);
            }
        }
        uint _e61 = sum;
        wg_sums[min(uint(i_2), 63u)] = _e61;
        GroupMemoryBarrierWithGroupSync();
        uint _e64 = params.entries;
        start = _e64;
        uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
        bool loop_init_6 = true;
        while(true) {
            if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
            loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
            if (!loop_init_6) {
                uint _e77 = j;
                j = (_e77 + 1u);
            }
            loop_init_6 = false;
            uint _e68 = j;
            if ((_e68 < i_2)) {
            } else {
                break;
            }
            {
                uint _e70 = start;
                uint _e72 = j;
                uint _e74 = wg_sums[min(uint(_e72), 63u)];
                start = (_e70 + _e74);
            }
        }
        c_1 = a_2;
        uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
        bool loop_init_7 = true;
        while(true) {
            if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
            loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
            if (!loop_init_7) {
                uint _e106 = c_1;
                c_1 = (_e106 + 1u);
            }
            loop_init_7 = false;
            uint _e80 = c_1;
            if ((_e80 < b_1)) {
            } else {
                break;
            }
            {
                uint _e85 = params.fill;
                uint _e86 = c_1;
                uint n_2; grid_fill.InterlockedOr((_e85 + _e86)*4, 0, n_2);
                uint _e91 = c_1;
                uint _e94 = start;
                { uint dummy_1 = 0; grid.InterlockedExchange((starts_1 + _e91)*4, _e94, dummy_1); }
                uint _e98 = params.fill;
                uint _e99 = c_1;
                uint _e102 = start;
                { uint dummy_2 = 0; grid_fill.InterlockedExchange((_e98 + _e99)*4, _e102, dummy_2); }
                uint _e103 = start;
                start = (_e103 + n_2);
            }
        }
        if (((i_2 + 1u) == 64u)) {
            uint _e115 = start;
            { uint dummy_3 = 0; grid.InterlockedExchange((starts_1 + cells_1)*4, _e115, dummy_3); }
        }
        return;
    }
    uint _e118 = params.stage;
    switch(_e118) {
        case 0u: {
            uint _e121 = params.count;
            if ((i_2 >= _e121)) {
                return;
            }
            const uint _e123 = grid_leaf(i_2);
            if ((_e123 == BSH_NONE)) {
                return;
            }
            uint _e131; grid.InterlockedAdd((h_1 + 13u)*4, 1u, _e131);
            BshNode leaf = ConstructBshNode(asfloat(bsh_nodes.Load3(_e123*32+0)), asfloat(bsh_nodes.Load(_e123*32+12)), asuint(bsh_nodes.Load(_e123*32+16)), asuint(bsh_nodes.Load(_e123*32+20)), asuint(bsh_nodes.Load(_e123*32+24)), asfloat(bsh_nodes.Load(_e123*32+28)));
            float _e137 = params.reach;
            const float _e138 = bsh_grid_radius(leaf, _e137);
            uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
                loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e185 = l;
                    l = (_e185 + 1u);
                }
                loop_init_8 = false;
                uint _e141 = l;
                uint _e144 = params.levels;
                if ((_e141 < _e144)) {
                } else {
                    break;
                }
                {
                    uint _e147 = l;
                    GridFrame _e149 = ConstructGridFrame(asfloat(grid_levels.Load3(_e147*48+0)), asuint(grid_levels.Load(_e147*48+12)), asfloat(grid_levels.Load3(_e147*48+16)), asuint(grid_levels.Load(_e147*48+28)), asfloat(grid_levels.Load3(_e147*48+32)), asuint(grid_levels.Load(_e147*48+44)));
                    const uint3 _e151 = bsh_grid_last(_e149, leaf.center_, _e138);
                    uint _e153 = l;
                    GridFrame _e155 = ConstructGridFrame(asfloat(grid_levels.Load3(_e153*48+0)), asuint(grid_levels.Load(_e153*48+12)), asfloat(grid_levels.Load3(_e153*48+16)), asuint(grid_levels.Load(_e153*48+28)), asfloat(grid_levels.Load3(_e153*48+32)), asuint(grid_levels.Load(_e153*48+44)));
                    const uint3 _e157 = bsh_grid_first(_e155, leaf.center_, _e138);
                    uint3 d = ((_e151 - _e157) + (1u).xxx);
                    uint n_3 = ((d.x * d.y) * d.z);
                    uint _e170 = l;
                    uint at = ((h_1 + 16u) + (2u * _e170));
                    uint _e175; grid.InterlockedAdd(at*4, n_3, _e175);
                    if (((_e175 + n_3) < _e175)) {
                        uint _e183; grid.InterlockedAdd((at + 1u)*4, 1u, _e183);
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
            uint _e196 = params.levels;
            chosen = _e196;
            uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
            bool loop_init_9 = true;
            while(true) {
                if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_9) {
                    uint _e262 = l_1;
                    l_1 = (_e262 + 1u);
                }
                loop_init_9 = false;
                uint _e200 = l_1;
                uint _e203 = params.levels;
                if ((_e200 < _e203)) {
                } else {
                    break;
                }
                {
                    uint _e206 = l_1;
                    GridFrame f_4 = ConstructGridFrame(asfloat(grid_levels.Load3(_e206*48+0)), asuint(grid_levels.Load(_e206*48+12)), asfloat(grid_levels.Load3(_e206*48+16)), asuint(grid_levels.Load(_e206*48+28)), asfloat(grid_levels.Load3(_e206*48+32)), asuint(grid_levels.Load(_e206*48+44)));
                    uint cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    uint _e216 = params.least;
                    const uint _e217 = bsh_grid_budget(leaves_1, cells_2, _e216);
                    uint _e220 = params.capacity;
                    uint budget = min(_e217, _e220);
                    uint _e225 = l_1;
                    uint at_1 = ((h_1 + 16u) + (2u * _e225));
                    uint _e228 = chosen;
                    uint _e231 = params.levels;
                    if ((_e228 == _e231)) {
                        uint _e239; grid.InterlockedOr((at_1 + 1u)*4, 0, _e239);
                        local = (_e239 == 0u);
                    } else {
                        local = false;
                    }
                    bool _e243 = local;
                    if (_e243) {
                        uint _e248; grid.InterlockedOr(at_1*4, 0, _e248);
                        local_1 = (_e248 <= budget);
                    } else {
                        local_1 = false;
                    }
                    bool _e251 = local_1;
                    if (_e251) {
                        uint _e252 = l_1;
                        chosen = _e252;
                    }
                    { uint dummy_4 = 0; grid.InterlockedExchange(at_1*4, 0u, dummy_4); }
                    { uint dummy_5 = 0; grid.InterlockedExchange((at_1 + 1u)*4, 0u, dummy_5); }
                }
            }
            { uint dummy_6 = 0; grid.InterlockedExchange((h_1 + 13u)*4, 0u, dummy_6); }
            uint _e270 = chosen;
            uint _e273 = params.levels;
            if ((_e270 < _e273)) {
                uint _e276 = chosen;
                GridFrame _e278 = ConstructGridFrame(asfloat(grid_levels.Load3(_e276*48+0)), asuint(grid_levels.Load(_e276*48+12)), asfloat(grid_levels.Load3(_e276*48+16)), asuint(grid_levels.Load(_e276*48+28)), asfloat(grid_levels.Load3(_e276*48+32)), asuint(grid_levels.Load(_e276*48+44)));
                f = _e278;
            }
            float _e283 = f.lo.x;
            { uint dummy_7 = 0; grid.InterlockedExchange(h_1*4, asuint(_e283), dummy_7); }
            float _e291 = f.lo.y;
            { uint dummy_8 = 0; grid.InterlockedExchange((h_1 + 1u)*4, asuint(_e291), dummy_8); }
            float _e299 = f.lo.z;
            { uint dummy_9 = 0; grid.InterlockedExchange((h_1 + 2u)*4, asuint(_e299), dummy_9); }
            uint _e306 = f.nx;
            { uint dummy_10 = 0; grid.InterlockedExchange((h_1 + 3u)*4, _e306, dummy_10); }
            float _e313 = f.hi.x;
            { uint dummy_11 = 0; grid.InterlockedExchange((h_1 + 4u)*4, asuint(_e313), dummy_11); }
            float _e321 = f.hi.y;
            { uint dummy_12 = 0; grid.InterlockedExchange((h_1 + 5u)*4, asuint(_e321), dummy_12); }
            float _e329 = f.hi.z;
            { uint dummy_13 = 0; grid.InterlockedExchange((h_1 + 6u)*4, asuint(_e329), dummy_13); }
            uint _e336 = f.ny;
            { uint dummy_14 = 0; grid.InterlockedExchange((h_1 + 7u)*4, _e336, dummy_14); }
            float _e343 = f.inv.x;
            { uint dummy_15 = 0; grid.InterlockedExchange((h_1 + 8u)*4, asuint(_e343), dummy_15); }
            float _e351 = f.inv.y;
            { uint dummy_16 = 0; grid.InterlockedExchange((h_1 + 9u)*4, asuint(_e351), dummy_16); }
            float _e359 = f.inv.z;
            { uint dummy_17 = 0; grid.InterlockedExchange((h_1 + 10u)*4, asuint(_e359), dummy_17); }
            uint _e366 = f.nz;
            { uint dummy_18 = 0; grid.InterlockedExchange((h_1 + 11u)*4, _e366, dummy_18); }
            float _e373 = params.reach;
            { uint dummy_19 = 0; grid.InterlockedExchange((h_1 + 12u)*4, asuint(_e373), dummy_19); }
            return;
        }
        case 2u:
        case 4u: {
            uint _e377 = params.count;
            if ((i_2 >= _e377)) {
                return;
            }
            const GridFrame _e379 = grid_frame(h_1);
            const uint _e380 = grid_leaf(i_2);
            if (!((_e379.nx == 0u))) {
                local_2 = (_e380 == BSH_NONE);
            } else {
                local_2 = true;
            }
            bool _e390 = local_2;
            if (_e390) {
                return;
            }
            BshNode leaf_1 = ConstructBshNode(asfloat(bsh_nodes.Load3(_e380*32+0)), asfloat(bsh_nodes.Load(_e380*32+12)), asuint(bsh_nodes.Load(_e380*32+16)), asuint(bsh_nodes.Load(_e380*32+20)), asuint(bsh_nodes.Load(_e380*32+24)), asfloat(bsh_nodes.Load(_e380*32+28)));
            float _e396 = params.reach;
            const float _e397 = bsh_grid_radius(leaf_1, _e396);
            const uint3 _e399 = bsh_grid_first(_e379, leaf_1.center_, _e397);
            const uint3 _e401 = bsh_grid_last(_e379, leaf_1.center_, _e397);
            z = _e399.z;
            uint2 loop_bound_11 = uint2(4294967295u, 4294967295u);
            bool loop_init_10 = true;
            while(true) {
                if (all(loop_bound_11 == uint2(0u, 0u))) { break; }
                loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
                if (!loop_init_10) {
                    uint _e448 = z;
                    z = (_e448 + 1u);
                }
                loop_init_10 = false;
                uint _e404 = z;
                if ((_e404 <= _e401.z)) {
                } else {
                    break;
                }
                {
                    y = _e399.y;
                    uint2 loop_bound_12 = uint2(4294967295u, 4294967295u);
                    bool loop_init_11 = true;
                    while(true) {
                        if (all(loop_bound_12 == uint2(0u, 0u))) { break; }
                        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
                        if (!loop_init_11) {
                            uint _e445 = y;
                            y = (_e445 + 1u);
                        }
                        loop_init_11 = false;
                        uint _e409 = y;
                        if ((_e409 <= _e401.y)) {
                        } else {
                            break;
                        }
                        {
                            x = _e399.x;
                            uint2 loop_bound_13 = uint2(4294967295u, 4294967295u);
                            bool loop_init_12 = true;
                            while(true) {
                                if (all(loop_bound_13 == uint2(0u, 0u))) { break; }
                                loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                                if (!loop_init_12) {
                                    uint _e442 = x;
                                    x = (_e442 + 1u);
                                }
                                loop_init_12 = false;
                                uint _e414 = x;
                                if ((_e414 <= _e401.x)) {
                                } else {
                                    break;
                                }
                                {
                                    uint _e417 = z;
                                    uint _e420 = y;
                                    uint _e424 = x;
                                    uint c_5 = ((((_e417 * _e379.ny) + _e420) * _e379.nx) + _e424);
                                    uint _e429 = params.fill;
                                    uint _e433; grid_fill.InterlockedAdd((_e429 + c_5)*4, 1u, _e433);
                                    uint _e436 = params.stage;
                                    if ((_e436 == 4u)) {
                                        grid_entries.Store(_e433*4, asuint(i_2));
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
            return;
        }
    }
}
