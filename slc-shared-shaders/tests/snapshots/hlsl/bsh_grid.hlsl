struct GridParams {
    uint stage;
    uint count;
    uint levels;
    uint capacity;
    float reach;
    uint cells;
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

uint grid_word(uint i)
{
    uint _e3; grid.InterlockedOr(i*4, 0, _e3);
    return _e3;
}

GridFrame grid_frame()
{
    GridFrame f_1 = (GridFrame)0;

    const uint _e3 = grid_word(0u);
    const uint _e6 = grid_word(1u);
    const uint _e9 = grid_word(2u);
    f_1.lo = float3(asfloat(_e3), asfloat(_e6), asfloat(_e9));
    const uint _e14 = grid_word(3u);
    f_1.nx = _e14;
    const uint _e17 = grid_word(4u);
    const uint _e20 = grid_word(5u);
    const uint _e23 = grid_word(6u);
    f_1.hi = float3(asfloat(_e17), asfloat(_e20), asfloat(_e23));
    const uint _e28 = grid_word(7u);
    f_1.ny = _e28;
    const uint _e31 = grid_word(8u);
    const uint _e34 = grid_word(9u);
    const uint _e37 = grid_word(10u);
    f_1.inv = float3(asfloat(_e31), asfloat(_e34), asfloat(_e37));
    const uint _e42 = grid_word(11u);
    f_1.nz = _e42;
    GridFrame _e43 = f_1;
    const GridFrame gridframe = _e43;
    return gridframe;
}

uint grid_leaf(uint i_1)
{
    uint node_5 = asuint(grid_leaves.Load(i_1*4));
    uint _e7 = asuint(bsh_nodes.Load(24+node_5*32));
    if (((_e7 & BSH_TAIL) != 0u)) {
        return BSH_NONE;
    }
    return node_5;
}

uint3 cover_first(GridFrame f_2, BshNode node_3, float r)
{
    float3 c_3 = node_3.center_;
    const uint _e11 = bsh_grid_axis((c_3.x - r), f_2.lo.x, f_2.inv.x, f_2.nx);
    const uint _e19 = bsh_grid_axis((c_3.y - r), f_2.lo.y, f_2.inv.y, f_2.ny);
    const uint _e27 = bsh_grid_axis((c_3.z - r), f_2.lo.z, f_2.inv.z, f_2.nz);
    return uint3(_e11, _e19, _e27);
}

uint3 cover_last(GridFrame f_3, BshNode node_4, float r_1)
{
    float3 c_4 = node_4.center_;
    const uint _e11 = bsh_grid_axis((c_4.x + r_1), f_3.lo.x, f_3.inv.x, f_3.nx);
    const uint _e19 = bsh_grid_axis((c_4.y + r_1), f_3.lo.y, f_3.inv.y, f_3.ny);
    const uint _e27 = bsh_grid_axis((c_4.z + r_1), f_3.lo.z, f_3.inv.z, f_3.nz);
    return uint3(_e11, _e19, _e27);
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
    uint start = 0u;
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
    uint _e4 = params.stage;
    if ((_e4 == 3u)) {
        const GridFrame _e7 = grid_frame();
        uint cells_1 = ((_e7.nx * _e7.ny) * _e7.nz);
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
                uint _e35 = c;
                c = (_e35 + 1u);
            }
            loop_init = false;
            uint _e26 = c;
            if ((_e26 < b_1)) {
            } else {
                break;
            }
            {
                uint _e28 = sum;
                uint _e30 = c;
                uint _e32; grid_fill.InterlockedOr(_e30*4, 0, _e32);
                sum = (_e28 + _e32);
            }
        }
        uint _e39 = sum;
        wg_sums[min(uint(i_2), 63u)] = _e39;
        GroupMemoryBarrierWithGroupSync();
        uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
            loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e53 = j;
                j = (_e53 + 1u);
            }
            loop_init_1 = false;
            uint _e44 = j;
            if ((_e44 < i_2)) {
            } else {
                break;
            }
            {
                uint _e46 = start;
                uint _e48 = j;
                uint _e50 = wg_sums[min(uint(_e48), 63u)];
                start = (_e46 + _e50);
            }
        }
        c_1 = a_1;
        uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
        bool loop_init_2 = true;
        while(true) {
            if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
            loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
            if (!loop_init_2) {
                uint _e75 = c_1;
                c_1 = (_e75 + 1u);
            }
            loop_init_2 = false;
            uint _e56 = c_1;
            if ((_e56 < b_1)) {
            } else {
                break;
            }
            {
                uint _e59 = c_1;
                uint n_1; grid_fill.InterlockedOr(_e59*4, 0, n_1);
                uint _e64 = c_1;
                uint _e67 = start;
                { uint dummy = 0; grid.InterlockedExchange((GRID_HEADER + _e64)*4, _e67, dummy); }
                uint _e69 = c_1;
                uint _e71 = start;
                { uint dummy_1 = 0; grid_fill.InterlockedExchange(_e69*4, _e71, dummy_1); }
                uint _e72 = start;
                start = (_e72 + n_1);
            }
        }
        if (((i_2 + 1u) == 64u)) {
            uint _e85 = start;
            { uint dummy_2 = 0; grid.InterlockedExchange((GRID_HEADER + cells_1)*4, _e85, dummy_2); }
        }
        return;
    }
    uint _e88 = params.stage;
    switch(_e88) {
        case 0u: {
            uint _e91 = params.count;
            if ((i_2 >= _e91)) {
                return;
            }
            const uint _e93 = grid_leaf(i_2);
            if ((_e93 == BSH_NONE)) {
                return;
            }
            uint _e99; grid.InterlockedAdd(52, 1u, _e99);
            BshNode leaf = ConstructBshNode(asfloat(bsh_nodes.Load3(_e93*32+0)), asfloat(bsh_nodes.Load(_e93*32+12)), asuint(bsh_nodes.Load(_e93*32+16)), asuint(bsh_nodes.Load(_e93*32+20)), asuint(bsh_nodes.Load(_e93*32+24)), asfloat(bsh_nodes.Load(_e93*32+28)));
            float _e105 = params.reach;
            const float _e106 = bsh_grid_reach(leaf, _e105);
            const float _e107 = bsh_grid_pad(_e106);
            uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e151 = l;
                    l = (_e151 + 1u);
                }
                loop_init_3 = false;
                uint _e110 = l;
                uint _e113 = params.levels;
                if ((_e110 < _e113)) {
                } else {
                    break;
                }
                {
                    uint _e116 = l;
                    GridFrame _e118 = ConstructGridFrame(asfloat(grid_levels.Load3(_e116*48+0)), asuint(grid_levels.Load(_e116*48+12)), asfloat(grid_levels.Load3(_e116*48+16)), asuint(grid_levels.Load(_e116*48+28)), asfloat(grid_levels.Load3(_e116*48+32)), asuint(grid_levels.Load(_e116*48+44)));
                    const uint3 _e119 = cover_last(_e118, leaf, _e107);
                    uint _e121 = l;
                    GridFrame _e123 = ConstructGridFrame(asfloat(grid_levels.Load3(_e121*48+0)), asuint(grid_levels.Load(_e121*48+12)), asfloat(grid_levels.Load3(_e121*48+16)), asuint(grid_levels.Load(_e121*48+28)), asfloat(grid_levels.Load3(_e121*48+32)), asuint(grid_levels.Load(_e121*48+44)));
                    const uint3 _e124 = cover_first(_e123, leaf, _e107);
                    uint3 d = ((_e119 - _e124) + (1u).xxx);
                    uint n_2 = ((d.x * d.y) * d.z);
                    uint _e136 = l;
                    uint at = (16u + (2u * _e136));
                    uint _e141; grid.InterlockedAdd(at*4, n_2, _e141);
                    if (((_e141 + n_2) < _e141)) {
                        uint _e149; grid.InterlockedAdd((at + 1u)*4, 1u, _e149);
                    }
                }
            }
            return;
        }
        case 1u: {
            if ((i_2 != 0u)) {
                return;
            }
            uint leaves_1; grid.InterlockedOr(52, 0, leaves_1);
            uint _e160 = params.levels;
            chosen = _e160;
            uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
            bool loop_init_4 = true;
            while(true) {
                if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_4) {
                    uint _e233 = l_1;
                    l_1 = (_e233 + 1u);
                }
                loop_init_4 = false;
                uint _e164 = l_1;
                uint _e167 = params.levels;
                if ((_e164 < _e167)) {
                } else {
                    break;
                }
                {
                    uint _e170 = l_1;
                    GridFrame f_4 = ConstructGridFrame(asfloat(grid_levels.Load3(_e170*48+0)), asuint(grid_levels.Load(_e170*48+12)), asfloat(grid_levels.Load3(_e170*48+16)), asuint(grid_levels.Load(_e170*48+28)), asfloat(grid_levels.Load3(_e170*48+32)), asuint(grid_levels.Load(_e170*48+44)));
                    uint cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    const uint _e178 = bsh_grid_budget(leaves_1, cells_2);
                    uint _e181 = params.capacity;
                    uint budget = min(_e178, _e181);
                    uint _e183 = chosen;
                    uint _e186 = params.levels;
                    if ((_e183 == _e186)) {
                        uint _e193 = l_1;
                        uint _e197; grid.InterlockedOr((17u + (2u * _e193))*4, 0, _e197);
                        local = (_e197 == 0u);
                    } else {
                        local = false;
                    }
                    bool _e201 = local;
                    if (_e201) {
                        uint _e207 = l_1;
                        uint _e211; grid.InterlockedOr((16u + (2u * _e207))*4, 0, _e211);
                        local_1 = (_e211 <= budget);
                    } else {
                        local_1 = false;
                    }
                    bool _e214 = local_1;
                    if (_e214) {
                        uint _e215 = l_1;
                        chosen = _e215;
                    }
                    uint _e219 = l_1;
                    { uint dummy_3 = 0; grid.InterlockedExchange((16u + (2u * _e219))*4, 0u, dummy_3); }
                    uint _e227 = l_1;
                    { uint dummy_4 = 0; grid.InterlockedExchange((17u + (2u * _e227))*4, 0u, dummy_4); }
                }
            }
            { uint dummy_5 = 0; grid.InterlockedExchange(52, 0u, dummy_5); }
            uint _e239 = chosen;
            uint _e242 = params.levels;
            if ((_e239 < _e242)) {
                uint _e245 = chosen;
                GridFrame _e247 = ConstructGridFrame(asfloat(grid_levels.Load3(_e245*48+0)), asuint(grid_levels.Load(_e245*48+12)), asfloat(grid_levels.Load3(_e245*48+16)), asuint(grid_levels.Load(_e245*48+28)), asfloat(grid_levels.Load3(_e245*48+32)), asuint(grid_levels.Load(_e245*48+44)));
                f = _e247;
            }
            float _e252 = f.lo.x;
            { uint dummy_6 = 0; grid.InterlockedExchange(0, asuint(_e252), dummy_6); }
            float _e258 = f.lo.y;
            { uint dummy_7 = 0; grid.InterlockedExchange(4, asuint(_e258), dummy_7); }
            float _e264 = f.lo.z;
            { uint dummy_8 = 0; grid.InterlockedExchange(8, asuint(_e264), dummy_8); }
            uint _e269 = f.nx;
            { uint dummy_9 = 0; grid.InterlockedExchange(12, _e269, dummy_9); }
            float _e274 = f.hi.x;
            { uint dummy_10 = 0; grid.InterlockedExchange(16, asuint(_e274), dummy_10); }
            float _e280 = f.hi.y;
            { uint dummy_11 = 0; grid.InterlockedExchange(20, asuint(_e280), dummy_11); }
            float _e286 = f.hi.z;
            { uint dummy_12 = 0; grid.InterlockedExchange(24, asuint(_e286), dummy_12); }
            uint _e291 = f.ny;
            { uint dummy_13 = 0; grid.InterlockedExchange(28, _e291, dummy_13); }
            float _e296 = f.inv.x;
            { uint dummy_14 = 0; grid.InterlockedExchange(32, asuint(_e296), dummy_14); }
            float _e302 = f.inv.y;
            { uint dummy_15 = 0; grid.InterlockedExchange(36, asuint(_e302), dummy_15); }
            float _e308 = f.inv.z;
            { uint dummy_16 = 0; grid.InterlockedExchange(40, asuint(_e308), dummy_16); }
            uint _e313 = f.nz;
            { uint dummy_17 = 0; grid.InterlockedExchange(44, _e313, dummy_17); }
            float _e318 = params.reach;
            { uint dummy_18 = 0; grid.InterlockedExchange(48, asuint(_e318), dummy_18); }
            return;
        }
        case 2u:
        case 4u: {
            uint _e322 = params.count;
            if ((i_2 >= _e322)) {
                return;
            }
            const GridFrame _e324 = grid_frame();
            const uint _e325 = grid_leaf(i_2);
            if (!((_e324.nx == 0u))) {
                local_2 = (_e325 == BSH_NONE);
            } else {
                local_2 = true;
            }
            bool _e335 = local_2;
            if (_e335) {
                return;
            }
            BshNode leaf_1 = ConstructBshNode(asfloat(bsh_nodes.Load3(_e325*32+0)), asfloat(bsh_nodes.Load(_e325*32+12)), asuint(bsh_nodes.Load(_e325*32+16)), asuint(bsh_nodes.Load(_e325*32+20)), asuint(bsh_nodes.Load(_e325*32+24)), asfloat(bsh_nodes.Load(_e325*32+28)));
            float _e341 = params.reach;
            const float _e342 = bsh_grid_reach(leaf_1, _e341);
            const float _e343 = bsh_grid_pad(_e342);
            const uint3 _e344 = cover_first(_e324, leaf_1, _e343);
            const uint3 _e345 = cover_last(_e324, leaf_1, _e343);
            z = _e344.z;
            uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e388 = z;
                    z = (_e388 + 1u);
                }
                loop_init_5 = false;
                uint _e348 = z;
                if ((_e348 <= _e345.z)) {
                } else {
                    break;
                }
                {
                    y = _e344.y;
                    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
                    bool loop_init_6 = true;
                    while(true) {
                        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
                        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                        if (!loop_init_6) {
                            uint _e385 = y;
                            y = (_e385 + 1u);
                        }
                        loop_init_6 = false;
                        uint _e353 = y;
                        if ((_e353 <= _e345.y)) {
                        } else {
                            break;
                        }
                        {
                            x = _e344.x;
                            uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
                            bool loop_init_7 = true;
                            while(true) {
                                if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
                                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                                if (!loop_init_7) {
                                    uint _e382 = x;
                                    x = (_e382 + 1u);
                                }
                                loop_init_7 = false;
                                uint _e358 = x;
                                if ((_e358 <= _e345.x)) {
                                } else {
                                    break;
                                }
                                {
                                    uint _e361 = z;
                                    uint _e364 = y;
                                    uint _e368 = x;
                                    uint c_5 = ((((_e361 * _e324.ny) + _e364) * _e324.nx) + _e368);
                                    uint _e373; grid_fill.InterlockedAdd(c_5*4, 1u, _e373);
                                    uint _e376 = params.stage;
                                    if ((_e376 == 4u)) {
                                        grid_entries.Store(_e373*4, asuint(i_2));
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
            const GridFrame _e390 = grid_frame();
            if ((i_2 >= ((_e390.nx * _e390.ny) * _e390.nz))) {
                return;
            }
            { uint dummy_19 = 0; grid_fill.InterlockedExchange(i_2*4, 0u, dummy_19); }
            uint a_2; grid.InterlockedOr((GRID_HEADER + i_2)*4, 0, a_2);
            uint b_2; grid.InterlockedOr(((GRID_HEADER + i_2) + 1u)*4, 0, b_2);
            s = (a_2 + 1u);
            uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
                loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e452 = s;
                    s = (_e452 + 1u);
                }
                loop_init_8 = false;
                uint _e415 = s;
                if ((_e415 < b_2)) {
                } else {
                    break;
                }
                {
                    uint _e418 = s;
                    uint v_1 = asuint(grid_entries.Load(_e418*4));
                    uint _e421 = s;
                    c_2 = _e421;
                    uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
                    while(true) {
                        if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
                        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                        uint _e423 = c_2;
                        if ((_e423 > a_2)) {
                            uint _e428 = c_2;
                            uint _e432 = asuint(grid_entries.Load((_e428 - 1u)*4));
                            local_3 = (_e432 > v_1);
                        } else {
                            local_3 = false;
                        }
                        bool _e435 = local_3;
                        if (_e435) {
                        } else {
                            break;
                        }
                        {
                            uint _e437 = c_2;
                            uint _e440 = c_2;
                            uint _e444 = asuint(grid_entries.Load((_e440 - 1u)*4));
                            grid_entries.Store(_e437*4, asuint(_e444));
                            uint _e445 = c_2;
                            c_2 = (_e445 - 1u);
                        }
                    }
                    uint _e449 = c_2;
                    grid_entries.Store(_e449*4, asuint(v_1));
                }
            }
            s_1 = a_2;
            uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
            bool loop_init_9 = true;
            while(true) {
                if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_9) {
                    uint _e468 = s_1;
                    s_1 = (_e468 + 1u);
                }
                loop_init_9 = false;
                uint _e455 = s_1;
                if ((_e455 < b_2)) {
                } else {
                    break;
                }
                {
                    uint _e458 = s_1;
                    uint _e462 = s_1;
                    uint _e464 = asuint(grid_entries.Load(_e462*4));
                    uint _e466 = asuint(grid_leaves.Load(_e464*4));
                    grid_entries.Store(_e458*4, asuint(_e466));
                }
            }
            return;
        }
    }
}
