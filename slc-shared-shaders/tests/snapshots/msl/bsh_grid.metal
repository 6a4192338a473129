// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size1;
    uint size2;
    uint size3;
    uint size4;
    uint size5;
    uint size6;
};

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
    metal::packed_float3 center;
    float radius;
    uint child;
    uint next;
    uint light;
    float extent;
};
typedef BshNode type_4[1];
typedef uint type_5[1];
struct GridFrame {
    metal::packed_float3 lo;
    uint nx;
    metal::packed_float3 hi;
    uint ny;
    metal::packed_float3 inv;
    uint nz;
};
typedef GridFrame type_6[1];
typedef metal::atomic_uint type_8[1];
struct type_10 {
    uint inner[64];
};
constant uint LIGHT_POINT = 0u;
constant uint LIGHT_SPOT = 1u;
constant uint LIGHT_IES = 2u;
constant uint LIGHT_TRIANGLE = 3u;
constant uint LIGHT_VPL = 4u;
constant uint NO_LIGHT = 4294967295u;
constant uint GRID_HEADER = 32u;
constant uint GRID_LEVELS_MAX = 8u;
constant uint COUNT_TILES = 0u;
constant uint COUNT_GROUP_TESTS = 1u;
constant uint COUNT_CLUSTER_TESTS = 2u;
constant uint COUNT_SPHERE_TESTS = 3u;
constant uint COUNT_TESTED = 4u;
constant uint COUNT_KEPT = 5u;
constant uint COUNT_PIXELS = 6u;
constant uint COUNT_FIELDS = 7u;
constant uint DIRECT_COUNT_PIXELS = 0u;
constant uint DIRECT_COUNT_CANDIDATES = 1u;
constant uint DIRECT_COUNT_EVALUATIONS = 2u;
constant uint DIRECT_COUNT_RAYS = 3u;
constant uint DIRECT_COUNT_NODES = 4u;
constant uint DIRECT_COUNT_FIELDS = 5u;
constant uint MAP_CAMERA = 0u;
constant uint MAP_PERSPECTIVE = 1u;
constant uint MAP_ORTHOGRAPHIC = 2u;
constant float XI_STEP = 0.000000059604645;
constant uint PICK_STREAM = 2654435769u;
constant float TWO_PI = 6.2831855;
constant float UNRANGED = 100000000000000000000000000000000000000.0;
constant float CULL_RADIUS_SCALE = 1.000001;
constant float SPHERE_PAD = 0.00000047683716;
constant float SPHERE_HUGE = 340282350000000000000000000000000000000.0;
constant float SPHERE_PAD_ABS = 0.000000000000000001;
constant uint CLUSTER = 64u;
constant uint GROUP_SIDE = 8u;
constant float INV_PI = 0.31830987;
constant float MIN_D2_ = 0.000000000001;
constant float MAX_INTENSITY = 72057594000000000.0;
constant uint BSH_NONE = 4294967295u;
constant uint BSH_TAIL = 2147483648u;
constant uint BSH_TAIL_BINS = 1024u;
constant uint BSH_TAIL_MAX = 64u;
constant uint RESERVOIR_FULL = 4294967295u;
constant float GGX_ALPHA_MIN = 0.001;
constant float RANGE_SCALE_MAX = 64.0;
constant uint LIGHT_BVH_LEAF = 4294967295u;
constant float ONE_MINUS_EPSILON = 0.99999994;
constant float F32_MAX = 340282350000000000000000000000000000000.0;
constant float DEPTH_NONE = 1000000000000000000000000000000.0;
constant float DEPTH_SIGMA = 0.05;
constant float COVER_WEIGHT = 0.1;
constant uint ROULETTE_DEPTH = 2u;
constant float TEMPORAL_MAX_HISTORY = 32.0;
constant float TEMPORAL_DEPTH_TOLERANCE = 0.01;
constant float TEMPORAL_MOTION_DEPTH_TOLERANCE = 0.05;
constant float TEMPORAL_NORMAL_COS = 0.9;
constant float TEMPORAL_MIN_MOMENTS = 8.0;
constant float TEMPORAL_CHANGED_HISTORY = 1.0;
constant float TEMPORAL_CHANGE_LOW = 4.0;
constant float TEMPORAL_CHANGE_HIGH = 8.0;
constant float TEMPORAL_MIN_WEIGHT = 0.01;
constant uint GRID_ENTRIES_PER_LIGHT = 8u;

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

uint to_u32_(
    float x_1
) {
    return naga_f2u32(x_1);
}

uint add_wrap_u32_(
    uint a,
    uint b
) {
    return a + b;
}

float f32_from_bits(
    uint u
) {
    return as_type<float>(u);
}

float bsh_range_bound(
    BshNode node
) {
    if (node.child == BSH_NONE) {
        return node.radius - node.extent;
    }
    float _e8 = f32_from_bits(node.light);
    return _e8;
}

float bsh_reach_bound(
    BshNode node_1,
    float w
) {
    float _e5 = bsh_range_bound(node_1);
    return node_1.extent + ((w * 1.001) * _e5);
}

uint bsh_grid_budget(
    uint leaves,
    uint cells
) {
    if (leaves > 536870911u) {
        return 4294967295u;
    }
    uint e = leaves * GRID_ENTRIES_PER_LIGHT;
    uint _e7 = add_wrap_u32_(e, cells);
    return (_e7 < e) ? 4294967295u : _e7;
}

float bsh_grid_reach(
    BshNode node_2,
    float w_1
) {
    if (w_1 > 1.0) {
        float _e5 = bsh_reach_bound(node_2, w_1);
        return metal::max(node_2.radius, _e5);
    }
    return node_2.radius;
}

float bsh_grid_pad(
    float reach
) {
    if (reach > 10000000000000000000.0) {
        return 340282350000000000000000000000000000000.0;
    }
    return (reach * 1.00001) + 0.0000000000000000000001;
}

uint bsh_grid_axis(
    float v,
    float lo,
    float inv,
    uint n
) {
    uint _e9 = to_u32_(metal::max(metal::floor((v - lo) * inv), 0.0));
    return metal::min(_e9, n - 1u);
}

uint grid_word(
    uint i,
    device type_8 const& grid,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = metal::atomic_load_explicit(&grid[i], metal::memory_order_relaxed);
    return _e3;
}

GridFrame grid_frame(
    device type_8 const& grid,
    constant _mslBufferSizes& _buffer_sizes
) {
    GridFrame f_1 = {};
    uint _e3 = grid_word(0u, grid, _buffer_sizes);
    uint _e6 = grid_word(1u, grid, _buffer_sizes);
    uint _e9 = grid_word(2u, grid, _buffer_sizes);
    f_1.lo = metal::float3(as_type<float>(_e3), as_type<float>(_e6), as_type<float>(_e9));
    uint _e14 = grid_word(3u, grid, _buffer_sizes);
    f_1.nx = _e14;
    uint _e17 = grid_word(4u, grid, _buffer_sizes);
    uint _e20 = grid_word(5u, grid, _buffer_sizes);
    uint _e23 = grid_word(6u, grid, _buffer_sizes);
    f_1.hi = metal::float3(as_type<float>(_e17), as_type<float>(_e20), as_type<float>(_e23));
    uint _e28 = grid_word(7u, grid, _buffer_sizes);
    f_1.ny = _e28;
    uint _e31 = grid_word(8u, grid, _buffer_sizes);
    uint _e34 = grid_word(9u, grid, _buffer_sizes);
    uint _e37 = grid_word(10u, grid, _buffer_sizes);
    f_1.inv = metal::float3(as_type<float>(_e31), as_type<float>(_e34), as_type<float>(_e37));
    uint _e42 = grid_word(11u, grid, _buffer_sizes);
    f_1.nz = _e42;
    GridFrame _e43 = f_1;
    return _e43;
}

uint grid_leaf(
    uint i_1,
    device type_4 const& bsh_nodes,
    device type_5 const& grid_leaves,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint node_5 = grid_leaves[i_1];
    uint _e7 = bsh_nodes[node_5].light;
    if ((_e7 & BSH_TAIL) != 0u) {
        return BSH_NONE;
    }
    return node_5;
}

metal::uint3 cover_first(
    GridFrame f_2,
    BshNode node_3,
    float r
) {
    metal::float3 c_3 = node_3.center;
    uint _e11 = bsh_grid_axis(node_3.center[0] - r, f_2.lo[0], f_2.inv[0], f_2.nx);
    uint _e19 = bsh_grid_axis(node_3.center[1] - r, f_2.lo[1], f_2.inv[1], f_2.ny);
    uint _e27 = bsh_grid_axis(node_3.center[2] - r, f_2.lo[2], f_2.inv[2], f_2.nz);
    return metal::uint3(_e11, _e19, _e27);
}

metal::uint3 cover_last(
    GridFrame f_3,
    BshNode node_4,
    float r_1
) {
    metal::float3 c_4 = node_4.center;
    uint _e11 = bsh_grid_axis(node_4.center[0] + r_1, f_3.lo[0], f_3.inv[0], f_3.nx);
    uint _e19 = bsh_grid_axis(node_4.center[1] + r_1, f_3.lo[1], f_3.inv[1], f_3.ny);
    uint _e27 = bsh_grid_axis(node_4.center[2] + r_1, f_3.lo[2], f_3.inv[2], f_3.nz);
    return metal::uint3(_e11, _e19, _e27);
}
uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}


struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, uint __local_invocation_index [[thread_index_in_threadgroup]]
, constant GridParams& params [[user(fake0)]]
, device type_4 const& bsh_nodes [[user(fake0)]]
, device type_5 const& grid_leaves [[user(fake0)]]
, device type_6 const& grid_levels [[user(fake0)]]
, device type_8& grid [[user(fake0)]]
, device type_8& grid_fill [[user(fake0)]]
, device type_5& grid_entries [[user(fake0)]]
, threadgroup type_10& wg_sums
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    if (__local_invocation_index == 0u) {
        wg_sums = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint sum = 0u;
    uint c = {};
    uint start = 0u;
    uint j = 0u;
    uint c_1 = {};
    uint l = 0u;
    uint chosen = {};
    uint l_1 = 0u;
    bool local = {};
    bool local_1 = {};
    GridFrame f = {};
    bool local_2 = {};
    uint z = {};
    uint y = {};
    uint x = {};
    uint s = {};
    uint c_2 = {};
    bool local_3 = {};
    uint s_1 = {};
    uint i_2 = gid.x;
    uint _e4 = params.stage;
    if (_e4 == 3u) {
        GridFrame _e7 = grid_frame(grid, _buffer_sizes);
        uint cells_1 = (_e7.nx * _e7.ny) * _e7.nz;
        uint run = naga_div((cells_1 + 64u) - 1u, 64u);
        uint a_1 = metal::min(i_2 * run, cells_1);
        uint b_1 = metal::min(a_1 + run, cells_1);
        c = a_1;
        uint2 loop_bound = uint2(4294967295u);
        bool loop_init = true;
        while(true) {
            if (metal::all(loop_bound == uint2(0u))) { break; }
            loop_bound -= uint2(loop_bound.y == 0u, 1u);
            if (!loop_init) {
                uint _e35 = c;
                c = _e35 + 1u;
            }
            loop_init = false;
            uint _e26 = c;
            if (_e26 < b_1) {
            } else {
                break;
            }
            {
                uint _e28 = sum;
                uint _e30 = c;
                uint _e32 = metal::atomic_load_explicit(&grid_fill[_e30], metal::memory_order_relaxed);
                sum = _e28 + _e32;
            }
        }
        uint _e39 = sum;
        wg_sums.inner[i_2] = _e39;
        metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        uint2 loop_bound_1 = uint2(4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (metal::all(loop_bound_1 == uint2(0u))) { break; }
            loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e53 = j;
                j = _e53 + 1u;
            }
            loop_init_1 = false;
            uint _e44 = j;
            if (_e44 < i_2) {
            } else {
                break;
            }
            {
                uint _e46 = start;
                uint _e48 = j;
                uint _e50 = wg_sums.inner[_e48];
                start = _e46 + _e50;
            }
        }
        c_1 = a_1;
        uint2 loop_bound_2 = uint2(4294967295u);
        bool loop_init_2 = true;
        while(true) {
            if (metal::all(loop_bound_2 == uint2(0u))) { break; }
            loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
            if (!loop_init_2) {
                uint _e75 = c_1;
                c_1 = _e75 + 1u;
            }
            loop_init_2 = false;
            uint _e56 = c_1;
            if (_e56 < b_1) {
            } else {
                break;
            }
            {
                uint _e59 = c_1;
                uint n_1 = metal::atomic_load_explicit(&grid_fill[_e59], metal::memory_order_relaxed);
                uint _e64 = c_1;
                uint _e67 = start;
                metal::atomic_store_explicit(&grid[GRID_HEADER + _e64], _e67, metal::memory_order_relaxed);
                uint _e69 = c_1;
                uint _e71 = start;
                metal::atomic_store_explicit(&grid_fill[_e69], _e71, metal::memory_order_relaxed);
                uint _e72 = start;
                start = _e72 + n_1;
            }
        }
        if ((i_2 + 1u) == 64u) {
            uint _e85 = start;
            metal::atomic_store_explicit(&grid[GRID_HEADER + cells_1], _e85, metal::memory_order_relaxed);
        }
        return;
    }
    uint _e88 = params.stage;
    switch(_e88) {
        case 0u: {
            uint _e91 = params.count;
            if (i_2 >= _e91) {
                return;
            }
            uint _e93 = grid_leaf(i_2, bsh_nodes, grid_leaves, _buffer_sizes);
            if (_e93 == BSH_NONE) {
                return;
            }
            uint _e99 = metal::atomic_fetch_add_explicit(&grid[13], 1u, metal::memory_order_relaxed);
            BshNode leaf = bsh_nodes[_e93];
            float _e105 = params.reach;
            float _e106 = bsh_grid_reach(leaf, _e105);
            float _e107 = bsh_grid_pad(_e106);
            uint2 loop_bound_3 = uint2(4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (metal::all(loop_bound_3 == uint2(0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e151 = l;
                    l = _e151 + 1u;
                }
                loop_init_3 = false;
                uint _e110 = l;
                uint _e113 = params.levels;
                if (_e110 < _e113) {
                } else {
                    break;
                }
                {
                    uint _e116 = l;
                    GridFrame _e118 = grid_levels[_e116];
                    metal::uint3 _e119 = cover_last(_e118, leaf, _e107);
                    uint _e121 = l;
                    GridFrame _e123 = grid_levels[_e121];
                    metal::uint3 _e124 = cover_first(_e123, leaf, _e107);
                    metal::uint3 d = (_e119 - _e124) + metal::uint3(1u);
                    uint n_2 = (d.x * d.y) * d.z;
                    uint _e136 = l;
                    uint at = 16u + (2u * _e136);
                    uint _e141 = metal::atomic_fetch_add_explicit(&grid[at], n_2, metal::memory_order_relaxed);
                    if ((_e141 + n_2) < _e141) {
                        uint _e149 = metal::atomic_fetch_add_explicit(&grid[at + 1u], 1u, metal::memory_order_relaxed);
                    }
                }
            }
            return;
        }
        case 1u: {
            if (i_2 != 0u) {
                return;
            }
            uint leaves_1 = metal::atomic_load_explicit(&grid[13], metal::memory_order_relaxed);
            uint _e160 = params.levels;
            chosen = _e160;
            uint2 loop_bound_4 = uint2(4294967295u);
            bool loop_init_4 = true;
            while(true) {
                if (metal::all(loop_bound_4 == uint2(0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_4) {
                    uint _e233 = l_1;
                    l_1 = _e233 + 1u;
                }
                loop_init_4 = false;
                uint _e164 = l_1;
                uint _e167 = params.levels;
                if (_e164 < _e167) {
                } else {
                    break;
                }
                {
                    uint _e170 = l_1;
                    GridFrame f_4 = grid_levels[_e170];
                    uint cells_2 = (f_4.nx * f_4.ny) * f_4.nz;
                    uint _e178 = bsh_grid_budget(leaves_1, cells_2);
                    uint _e181 = params.capacity;
                    uint budget = metal::min(_e178, _e181);
                    uint _e183 = chosen;
                    uint _e186 = params.levels;
                    if (_e183 == _e186) {
                        uint _e193 = l_1;
                        uint _e197 = metal::atomic_load_explicit(&grid[17u + (2u * _e193)], metal::memory_order_relaxed);
                        local = _e197 == 0u;
                    } else {
                        local = false;
                    }
                    bool _e201 = local;
                    if (_e201) {
                        uint _e207 = l_1;
                        uint _e211 = metal::atomic_load_explicit(&grid[16u + (2u * _e207)], metal::memory_order_relaxed);
                        local_1 = _e211 <= budget;
                    } else {
                        local_1 = false;
                    }
                    bool _e214 = local_1;
                    if (_e214) {
                        uint _e215 = l_1;
                        chosen = _e215;
                    }
                    uint _e219 = l_1;
                    metal::atomic_store_explicit(&grid[16u + (2u * _e219)], 0u, metal::memory_order_relaxed);
                    uint _e227 = l_1;
                    metal::atomic_store_explicit(&grid[17u + (2u * _e227)], 0u, metal::memory_order_relaxed);
                }
            }
            metal::atomic_store_explicit(&grid[13], 0u, metal::memory_order_relaxed);
            uint _e239 = chosen;
            uint _e242 = params.levels;
            if (_e239 < _e242) {
                uint _e245 = chosen;
                GridFrame _e247 = grid_levels[_e245];
                f = _e247;
            }
            float _e252 = f.lo[0];
            metal::atomic_store_explicit(&grid[0], as_type<uint>(_e252), metal::memory_order_relaxed);
            float _e258 = f.lo[1];
            metal::atomic_store_explicit(&grid[1], as_type<uint>(_e258), metal::memory_order_relaxed);
            float _e264 = f.lo[2];
            metal::atomic_store_explicit(&grid[2], as_type<uint>(_e264), metal::memory_order_relaxed);
            uint _e269 = f.nx;
            metal::atomic_store_explicit(&grid[3], _e269, metal::memory_order_relaxed);
            float _e274 = f.hi[0];
            metal::atomic_store_explicit(&grid[4], as_type<uint>(_e274), metal::memory_order_relaxed);
            float _e280 = f.hi[1];
            metal::atomic_store_explicit(&grid[5], as_type<uint>(_e280), metal::memory_order_relaxed);
            float _e286 = f.hi[2];
            metal::atomic_store_explicit(&grid[6], as_type<uint>(_e286), metal::memory_order_relaxed);
            uint _e291 = f.ny;
            metal::atomic_store_explicit(&grid[7], _e291, metal::memory_order_relaxed);
            float _e296 = f.inv[0];
            metal::atomic_store_explicit(&grid[8], as_type<uint>(_e296), metal::memory_order_relaxed);
            float _e302 = f.inv[1];
            metal::atomic_store_explicit(&grid[9], as_type<uint>(_e302), metal::memory_order_relaxed);
            float _e308 = f.inv[2];
            metal::atomic_store_explicit(&grid[10], as_type<uint>(_e308), metal::memory_order_relaxed);
            uint _e313 = f.nz;
            metal::atomic_store_explicit(&grid[11], _e313, metal::memory_order_relaxed);
            float _e318 = params.reach;
            metal::atomic_store_explicit(&grid[12], as_type<uint>(_e318), metal::memory_order_relaxed);
            return;
        }
        case 2u:
        case 4u: {
            uint _e322 = params.count;
            if (i_2 >= _e322) {
                return;
            }
            GridFrame _e324 = grid_frame(grid, _buffer_sizes);
            uint _e325 = grid_leaf(i_2, bsh_nodes, grid_leaves, _buffer_sizes);
            if (!((_e324.nx == 0u))) {
                local_2 = _e325 == BSH_NONE;
            } else {
                local_2 = true;
            }
            bool _e335 = local_2;
            if (_e335) {
                return;
            }
            BshNode leaf_1 = bsh_nodes[_e325];
            float _e341 = params.reach;
            float _e342 = bsh_grid_reach(leaf_1, _e341);
            float _e343 = bsh_grid_pad(_e342);
            metal::uint3 _e344 = cover_first(_e324, leaf_1, _e343);
            metal::uint3 _e345 = cover_last(_e324, leaf_1, _e343);
            z = _e344.z;
            uint2 loop_bound_5 = uint2(4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (metal::all(loop_bound_5 == uint2(0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e388 = z;
                    z = _e388 + 1u;
                }
                loop_init_5 = false;
                uint _e348 = z;
                if (_e348 <= _e345.z) {
                } else {
                    break;
                }
                {
                    y = _e344.y;
                    uint2 loop_bound_6 = uint2(4294967295u);
                    bool loop_init_6 = true;
                    while(true) {
                        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
                        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                        if (!loop_init_6) {
                            uint _e385 = y;
                            y = _e385 + 1u;
                        }
                        loop_init_6 = false;
                        uint _e353 = y;
                        if (_e353 <= _e345.y) {
                        } else {
                            break;
                        }
                        {
                            x = _e344.x;
                            uint2 loop_bound_7 = uint2(4294967295u);
                            bool loop_init_7 = true;
                            while(true) {
                                if (metal::all(loop_bound_7 == uint2(0u))) { break; }
                                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                                if (!loop_init_7) {
                                    uint _e382 = x;
                                    x = _e382 + 1u;
                                }
                                loop_init_7 = false;
                                uint _e358 = x;
                                if (_e358 <= _e345.x) {
                                } else {
                                    break;
                                }
                                {
                                    uint _e361 = z;
                                    uint _e364 = y;
                                    uint _e368 = x;
                                    uint c_5 = (((_e361 * _e324.ny) + _e364) * _e324.nx) + _e368;
                                    uint _e373 = metal::atomic_fetch_add_explicit(&grid_fill[c_5], 1u, metal::memory_order_relaxed);
                                    uint _e376 = params.stage;
                                    if (_e376 == 4u) {
                                        grid_entries[_e373] = i_2;
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
            GridFrame _e390 = grid_frame(grid, _buffer_sizes);
            if (i_2 >= ((_e390.nx * _e390.ny) * _e390.nz)) {
                return;
            }
            metal::atomic_store_explicit(&grid_fill[i_2], 0u, metal::memory_order_relaxed);
            uint a_2 = metal::atomic_load_explicit(&grid[GRID_HEADER + i_2], metal::memory_order_relaxed);
            uint b_2 = metal::atomic_load_explicit(&grid[(GRID_HEADER + i_2) + 1u], metal::memory_order_relaxed);
            s = a_2 + 1u;
            uint2 loop_bound_8 = uint2(4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (metal::all(loop_bound_8 == uint2(0u))) { break; }
                loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e452 = s;
                    s = _e452 + 1u;
                }
                loop_init_8 = false;
                uint _e415 = s;
                if (_e415 < b_2) {
                } else {
                    break;
                }
                {
                    uint _e418 = s;
                    uint v_1 = grid_entries[_e418];
                    uint _e421 = s;
                    c_2 = _e421;
                    uint2 loop_bound_9 = uint2(4294967295u);
                    while(true) {
                        if (metal::all(loop_bound_9 == uint2(0u))) { break; }
                        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                        uint _e423 = c_2;
                        if (_e423 > a_2) {
                            uint _e428 = c_2;
                            uint _e432 = grid_entries[_e428 - 1u];
                            local_3 = _e432 > v_1;
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
                            uint _e444 = grid_entries[_e440 - 1u];
                            grid_entries[_e437] = _e444;
                            uint _e445 = c_2;
                            c_2 = _e445 - 1u;
                        }
                    }
                    uint _e449 = c_2;
                    grid_entries[_e449] = v_1;
                }
            }
            s_1 = a_2;
            uint2 loop_bound_10 = uint2(4294967295u);
            bool loop_init_9 = true;
            while(true) {
                if (metal::all(loop_bound_10 == uint2(0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_9) {
                    uint _e468 = s_1;
                    s_1 = _e468 + 1u;
                }
                loop_init_9 = false;
                uint _e455 = s_1;
                if (_e455 < b_2) {
                } else {
                    break;
                }
                {
                    uint _e458 = s_1;
                    uint _e462 = s_1;
                    uint _e464 = grid_entries[_e462];
                    uint _e466 = grid_leaves[_e464];
                    grid_entries[_e458] = _e466;
                }
            }
            return;
        }
    }
}
