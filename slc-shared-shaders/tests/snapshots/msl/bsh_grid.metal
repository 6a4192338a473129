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
    uint size7;
};

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
typedef GridParams type_9[1];
struct type_11 {
    uint inner[64];
};
struct type_13 {
    metal::uint2 inner[64];
};
struct type_14 {
    uint inner[1024];
};
constant uint LIGHT_POINT = 0u;
constant uint LIGHT_SPOT = 1u;
constant uint LIGHT_IES = 2u;
constant uint LIGHT_TRIANGLE = 3u;
constant uint LIGHT_VPL = 4u;
constant uint NO_LIGHT = 4294967295u;
constant uint GRID_HEADER = 32u;
constant uint GRID_LEVELS_MAX = 8u;
constant uint GRIDS_MAX = 3u;
constant uint GRID_SORT_MOVES = 1024u;
constant uint GRID_SORT_MAX = 1024u;
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
constant uint XI_ROTATED = 2147483648u;
constant uint XI_BITS_SHIFT = 26u;
constant uint XI_INDEX_MASK = 67108863u;
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
constant float REUSE_TRUST_SCALE = 64.0;
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
constant float LOBE_CONE_PAD = 1.001;

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

uint to_u32_(
    float x
) {
    return naga_f2u32(x);
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
    uint cells,
    uint least
) {
    if (leaves > 536870911u) {
        return 4294967295u;
    }
    uint e_1 = leaves * GRID_ENTRIES_PER_LIGHT;
    uint _e8 = add_wrap_u32_(e_1, cells);
    return metal::max((_e8 < e_1) ? 4294967295u : _e8, least);
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
    uint _e8 = to_u32_(metal::max((v - lo) * inv, 0.0));
    return metal::min(_e8, n - 1u);
}

float bsh_grid_radius(
    BshNode node_3,
    float w_2
) {
    float _e2 = bsh_grid_reach(node_3, w_2);
    float _e3 = bsh_grid_pad(_e2);
    return _e3;
}

metal::uint3 bsh_grid_first(
    GridFrame f,
    metal::float3 c,
    float r
) {
    uint _e10 = bsh_grid_axis(c.x - r, f.lo[0], f.inv[0], f.nx);
    uint _e18 = bsh_grid_axis(c.y - r, f.lo[1], f.inv[1], f.ny);
    uint _e26 = bsh_grid_axis(c.z - r, f.lo[2], f.inv[2], f.nz);
    return metal::uint3(_e10, _e18, _e26);
}

metal::uint3 bsh_grid_last(
    GridFrame f_1,
    metal::float3 c_1,
    float r_1
) {
    uint _e10 = bsh_grid_axis(c_1.x + r_1, f_1.lo[0], f_1.inv[0], f_1.nx);
    uint _e18 = bsh_grid_axis(c_1.y + r_1, f_1.lo[1], f_1.inv[1], f_1.ny);
    uint _e26 = bsh_grid_axis(c_1.z + r_1, f_1.lo[2], f_1.inv[2], f_1.nz);
    return metal::uint3(_e10, _e18, _e26);
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
    uint h,
    device type_8 const& grid,
    constant _mslBufferSizes& _buffer_sizes
) {
    GridFrame f_2 = {};
    uint _e3 = grid_word(h, grid, _buffer_sizes);
    uint _e7 = grid_word(h + 1u, grid, _buffer_sizes);
    uint _e11 = grid_word(h + 2u, grid, _buffer_sizes);
    f_2.lo = metal::float3(as_type<float>(_e3), as_type<float>(_e7), as_type<float>(_e11));
    uint _e17 = grid_word(h + 3u, grid, _buffer_sizes);
    f_2.nx = _e17;
    uint _e21 = grid_word(h + 4u, grid, _buffer_sizes);
    uint _e25 = grid_word(h + 5u, grid, _buffer_sizes);
    uint _e29 = grid_word(h + 6u, grid, _buffer_sizes);
    f_2.hi = metal::float3(as_type<float>(_e21), as_type<float>(_e25), as_type<float>(_e29));
    uint _e35 = grid_word(h + 7u, grid, _buffer_sizes);
    f_2.ny = _e35;
    uint _e39 = grid_word(h + 8u, grid, _buffer_sizes);
    uint _e43 = grid_word(h + 9u, grid, _buffer_sizes);
    uint _e47 = grid_word(h + 10u, grid, _buffer_sizes);
    f_2.inv = metal::float3(as_type<float>(_e39), as_type<float>(_e43), as_type<float>(_e47));
    uint _e53 = grid_word(h + 11u, grid, _buffer_sizes);
    f_2.nz = _e53;
    GridFrame _e54 = f_2;
    return _e54;
}

uint grid_leaf(
    uint i_1,
    device type_4 const& bsh_nodes,
    device type_5 const& grid_leaves,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint node_4 = grid_leaves[i_1];
    uint _e7 = bsh_nodes[node_4].light;
    if ((_e7 & BSH_TAIL) != 0u) {
        return BSH_NONE;
    }
    return node_4;
}

uint cell_key(
    bool big,
    uint a_1,
    uint j,
    device type_5 const& grid_entries,
    threadgroup type_14& wg_cell,
    constant _mslBufferSizes& _buffer_sizes
) {
    if (big) {
        uint _e6 = grid_entries[a_1 + j];
        return _e6;
    }
    uint _e9 = wg_cell.inner[j];
    return _e9;
}

void set_cell_key(
    bool big_1,
    uint a_2,
    uint j_1,
    uint v_1,
    device type_5& grid_entries,
    threadgroup type_14& wg_cell,
    constant _mslBufferSizes& _buffer_sizes
) {
    if (big_1) {
        grid_entries[a_2 + j_1] = v_1;
        return;
    } else {
        wg_cell.inner[j_1] = v_1;
        return;
    }
}

void sort_together(
    uint b_1,
    uint li_1,
    device type_5 const& grid_leaves,
    device type_5& grid_entries,
    threadgroup type_13& wg_big,
    threadgroup type_14& wg_cell,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint j_2 = {};
    uint p = 1u;
    uint k = 2u;
    uint h_1 = {};
    uint t = {};
    uint j_3 = {};
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    metal::uint2 unnamed = wg_big.inner[b_1];
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint a_3 = unnamed.x;
    uint n_1 = unnamed.y - unnamed.x;
    bool big_2 = n_1 > GRID_SORT_MAX;
    if (!(big_2)) {
        j_2 = li_1;
        uint2 loop_bound = uint2(4294967295u);
        bool loop_init = true;
        while(true) {
            if (metal::all(loop_bound == uint2(0u))) { break; }
            loop_bound -= uint2(loop_bound.y == 0u, 1u);
            if (!loop_init) {
                uint _e23 = j_2;
                j_2 = _e23 + 64u;
            }
            loop_init = false;
            uint _e13 = j_2;
            if (_e13 < n_1) {
            } else {
                break;
            }
            {
                uint _e16 = j_2;
                uint _e19 = j_2;
                uint _e22 = grid_entries[a_3 + _e19];
                wg_cell.inner[_e16] = _e22;
            }
        }
    }
    uint2 loop_bound_1 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e28 = p;
        if (_e28 < n_1) {
        } else {
            break;
        }
        {
            uint _e30 = p;
            p = _e30 << 1u;
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint2 loop_bound_2 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e87 = k;
            k = _e87 << 1u;
        }
        loop_init_1 = false;
        uint _e35 = k;
        uint _e36 = p;
        if (_e35 <= _e36) {
        } else {
            break;
        }
        {
            uint _e38 = k;
            h_1 = _e38 >> 1u;
            uint2 loop_bound_3 = uint2(4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (metal::all(loop_bound_3 == uint2(0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e84 = h_1;
                    h_1 = _e84 >> 1u;
                }
                loop_init_2 = false;
                uint _e42 = h_1;
                if (_e42 > 0u) {
                } else {
                    break;
                }
                {
                    t = li_1;
                    uint2 loop_bound_4 = uint2(4294967295u);
                    bool loop_init_3 = true;
                    while(true) {
                        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
                        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                        if (!loop_init_3) {
                            uint _e81 = t;
                            t = _e81 + 64u;
                        }
                        loop_init_3 = false;
                        uint _e46 = t;
                        uint _e47 = p;
                        if (_e46 < (_e47 >> 1u)) {
                        } else {
                            break;
                        }
                        {
                            uint _e51 = t;
                            uint _e52 = h_1;
                            uint _e59 = t;
                            uint _e60 = h_1;
                            uint i_4 = ((_e51 & ~((_e52 - 1u))) << 1u) | (_e59 & (_e60 - 1u));
                            uint _e65 = h_1;
                            uint _e67 = k;
                            uint _e71 = h_1;
                            uint _e72 = k;
                            uint o = (_e71 == (_e72 >> 1u)) ? (i_4 ^ (_e67 - 1u)) : (i_4 | _e65);
                            if (o < n_1) {
                                uint _e78 = cell_key(big_2, a_3, i_4, grid_entries, wg_cell, _buffer_sizes);
                                uint _e79 = cell_key(big_2, a_3, o, grid_entries, wg_cell, _buffer_sizes);
                                if (_e79 < _e78) {
                                    set_cell_key(big_2, a_3, i_4, _e79, grid_entries, wg_cell, _buffer_sizes);
                                    set_cell_key(big_2, a_3, o, _e78, grid_entries, wg_cell, _buffer_sizes);
                                }
                            }
                        }
                    }
                    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
                    metal::threadgroup_barrier(metal::mem_flags::mem_device);
                }
            }
        }
    }
    j_3 = li_1;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e102 = j_3;
            j_3 = _e102 + 64u;
        }
        loop_init_4 = false;
        uint _e91 = j_3;
        if (_e91 < n_1) {
        } else {
            break;
        }
        {
            uint _e94 = j_3;
            uint _e98 = j_3;
            uint _e99 = cell_key(big_2, a_3, _e98, grid_entries, wg_cell, _buffer_sizes);
            uint _e101 = grid_leaves[_e99];
            grid_entries[a_3 + _e94] = _e101;
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return;
}

void sort_cells(
    GridParams g,
    uint first,
    uint li_2,
    constant GridStage& params,
    device type_5 const& grid_leaves,
    device type_8 const& grid,
    device type_8& grid_fill,
    device type_5& grid_entries,
    threadgroup type_13& wg_big,
    threadgroup metal::atomic_uint& wg_bigs,
    threadgroup type_14& wg_cell,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint2 span = metal::uint2(0u);
    uint s = {};
    uint moves = 0u;
    bool local = {};
    uint c_2 = {};
    bool local_1 = {};
    uint e = {};
    uint b_2 = 0u;
    uint starts = g.header + GRID_HEADER;
    GridFrame _e7 = grid_frame(g.header, grid, _buffer_sizes);
    uint cell = first + li_2;
    if (cell < ((_e7.nx * _e7.ny) * _e7.nz)) {
        uint _e21 = metal::atomic_load_explicit(&grid[starts + cell], metal::memory_order_relaxed);
        uint _e27 = metal::atomic_load_explicit(&grid[(starts + cell) + 1u], metal::memory_order_relaxed);
        span = metal::uint2(_e21, _e27);
        metal::atomic_store_explicit(&grid_fill[g.fill + cell], 0u, metal::memory_order_relaxed);
    }
    if (li_2 == 0u) {
        metal::atomic_store_explicit(&wg_bigs, 0u, metal::memory_order_relaxed);
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint _e39 = span.x;
    s = _e39 + 1u;
    uint2 loop_bound_6 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        uint _e45 = s;
        uint _e47 = span.y;
        if (_e45 < _e47) {
            uint _e51 = moves;
            uint _e54 = params.moves;
            local = _e51 < _e54;
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
            uint v_2 = grid_entries[_e59];
            uint _e62 = s;
            c_2 = _e62;
            uint2 loop_bound_7 = uint2(4294967295u);
            while(true) {
                if (metal::all(loop_bound_7 == uint2(0u))) { break; }
                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                uint _e64 = c_2;
                uint _e66 = span.x;
                if (_e64 > _e66) {
                    uint _e71 = c_2;
                    uint _e75 = grid_entries[_e71 - 1u];
                    local_1 = _e75 > v_2;
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
                    uint _e87 = grid_entries[_e83 - 1u];
                    grid_entries[_e80] = _e87;
                    uint _e88 = c_2;
                    c_2 = _e88 - 1u;
                }
            }
            uint _e92 = c_2;
            grid_entries[_e92] = v_2;
            uint _e94 = moves;
            uint _e95 = s;
            uint _e96 = c_2;
            moves = _e94 + (_e95 - _e96);
            uint _e99 = s;
            s = _e99 + 1u;
        }
    }
    uint _e102 = s;
    uint _e104 = span.y;
    if (_e102 < _e104) {
        uint _e109 = metal::atomic_fetch_add_explicit(&wg_bigs, 1u, metal::memory_order_relaxed);
        metal::uint2 _e111 = span;
        wg_big.inner[_e109] = _e111;
    } else {
        uint _e113 = span.x;
        e = _e113;
        uint2 loop_bound_8 = uint2(4294967295u);
        bool loop_init_5 = true;
        while(true) {
            if (metal::all(loop_bound_8 == uint2(0u))) { break; }
            loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
            if (!loop_init_5) {
                uint _e130 = e;
                e = _e130 + 1u;
            }
            loop_init_5 = false;
            uint _e115 = e;
            uint _e117 = span.y;
            if (_e115 < _e117) {
            } else {
                break;
            }
            {
                uint _e120 = e;
                uint _e124 = e;
                uint _e126 = grid_entries[_e124];
                uint _e128 = grid_leaves[_e126];
                grid_entries[_e120] = _e128;
            }
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_device);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_1 = metal::atomic_load_explicit(&wg_bigs, metal::memory_order_relaxed);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint2 loop_bound_9 = uint2(4294967295u);
    bool loop_init_6 = true;
    while(true) {
        if (metal::all(loop_bound_9 == uint2(0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_6) {
            uint _e140 = b_2;
            b_2 = _e140 + 1u;
        }
        loop_init_6 = false;
        uint _e136 = b_2;
        if (_e136 < unnamed_1) {
        } else {
            break;
        }
        {
            uint _e138 = b_2;
            sort_together(_e138, li_2, grid_leaves, grid_entries, wg_big, wg_cell, _buffer_sizes);
        }
    }
    return;
}

void count_levels(
    GridParams g_1,
    uint i_2,
    constant GridStage& params,
    device type_4 const& bsh_nodes,
    device type_5 const& grid_leaves,
    device type_6 const& grid_levels,
    device type_8& grid,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint l = 0u;
    uint _e4 = params.count;
    if (i_2 >= _e4) {
        return;
    }
    uint h_2 = g_1.header;
    uint _e7 = grid_leaf(i_2, bsh_nodes, grid_leaves, _buffer_sizes);
    if (_e7 == BSH_NONE) {
        return;
    }
    uint _e15 = metal::atomic_fetch_add_explicit(&grid[h_2 + 13u], 1u, metal::memory_order_relaxed);
    BshNode leaf = bsh_nodes[_e7];
    float _e20 = bsh_grid_radius(leaf, g_1.reach);
    uint2 loop_bound_10 = uint2(4294967295u);
    bool loop_init_7 = true;
    while(true) {
        if (metal::all(loop_bound_10 == uint2(0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        if (!loop_init_7) {
            uint _e67 = l;
            l = _e67 + 1u;
        }
        loop_init_7 = false;
        uint _e23 = l;
        uint _e26 = params.levels;
        if (_e23 < _e26) {
        } else {
            break;
        }
        {
            uint _e29 = l;
            GridFrame _e31 = grid_levels[_e29];
            metal::uint3 _e33 = bsh_grid_last(_e31, leaf.center, _e20);
            uint _e35 = l;
            GridFrame _e37 = grid_levels[_e35];
            metal::uint3 _e39 = bsh_grid_first(_e37, leaf.center, _e20);
            metal::uint3 d = (_e33 - _e39) + metal::uint3(1u);
            uint n_2 = (d.x * d.y) * d.z;
            uint _e52 = l;
            uint at = (h_2 + 16u) + (2u * _e52);
            uint _e57 = metal::atomic_fetch_add_explicit(&grid[at], n_2, metal::memory_order_relaxed);
            if ((_e57 + n_2) < _e57) {
                uint _e65 = metal::atomic_fetch_add_explicit(&grid[at + 1u], 1u, metal::memory_order_relaxed);
            }
        }
    }
    return;
}

void choose_level(
    GridParams g_2,
    constant GridStage& params,
    device type_6 const& grid_levels,
    device type_8& grid,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint chosen = {};
    uint l_1 = 0u;
    bool local_2 = {};
    bool local_3 = {};
    GridFrame f_3 = {};
    uint h_3 = g_2.header;
    uint leaves_1 = metal::atomic_load_explicit(&grid[h_3 + 13u], metal::memory_order_relaxed);
    uint _e9 = params.levels;
    chosen = _e9;
    uint2 loop_bound_11 = uint2(4294967295u);
    bool loop_init_8 = true;
    while(true) {
        if (metal::all(loop_bound_11 == uint2(0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_8) {
            uint _e71 = l_1;
            l_1 = _e71 + 1u;
        }
        loop_init_8 = false;
        uint _e13 = l_1;
        uint _e16 = params.levels;
        if (_e13 < _e16) {
        } else {
            break;
        }
        {
            uint _e19 = l_1;
            GridFrame f_4 = grid_levels[_e19];
            uint cells_1 = (f_4.nx * f_4.ny) * f_4.nz;
            uint _e28 = bsh_grid_budget(leaves_1, cells_1, g_2.least);
            uint budget = metal::min(_e28, g_2.capacity);
            uint _e34 = l_1;
            uint at_1 = (h_3 + 16u) + (2u * _e34);
            uint _e37 = chosen;
            uint _e40 = params.levels;
            if (_e37 == _e40) {
                uint _e48 = metal::atomic_load_explicit(&grid[at_1 + 1u], metal::memory_order_relaxed);
                local_2 = _e48 == 0u;
            } else {
                local_2 = false;
            }
            bool _e52 = local_2;
            if (_e52) {
                uint _e57 = metal::atomic_load_explicit(&grid[at_1], metal::memory_order_relaxed);
                local_3 = _e57 <= budget;
            } else {
                local_3 = false;
            }
            bool _e60 = local_3;
            if (_e60) {
                uint _e61 = l_1;
                chosen = _e61;
            }
            metal::atomic_store_explicit(&grid[at_1], 0u, metal::memory_order_relaxed);
            metal::atomic_store_explicit(&grid[at_1 + 1u], 0u, metal::memory_order_relaxed);
        }
    }
    metal::atomic_store_explicit(&grid[h_3 + 13u], 0u, metal::memory_order_relaxed);
    uint _e79 = chosen;
    uint _e82 = params.levels;
    if (_e79 < _e82) {
        uint _e85 = chosen;
        GridFrame _e87 = grid_levels[_e85];
        f_3 = _e87;
    }
    float _e92 = f_3.lo[0];
    metal::atomic_store_explicit(&grid[h_3], as_type<uint>(_e92), metal::memory_order_relaxed);
    float _e100 = f_3.lo[1];
    metal::atomic_store_explicit(&grid[h_3 + 1u], as_type<uint>(_e100), metal::memory_order_relaxed);
    float _e108 = f_3.lo[2];
    metal::atomic_store_explicit(&grid[h_3 + 2u], as_type<uint>(_e108), metal::memory_order_relaxed);
    uint _e115 = f_3.nx;
    metal::atomic_store_explicit(&grid[h_3 + 3u], _e115, metal::memory_order_relaxed);
    float _e122 = f_3.hi[0];
    metal::atomic_store_explicit(&grid[h_3 + 4u], as_type<uint>(_e122), metal::memory_order_relaxed);
    float _e130 = f_3.hi[1];
    metal::atomic_store_explicit(&grid[h_3 + 5u], as_type<uint>(_e130), metal::memory_order_relaxed);
    float _e138 = f_3.hi[2];
    metal::atomic_store_explicit(&grid[h_3 + 6u], as_type<uint>(_e138), metal::memory_order_relaxed);
    uint _e145 = f_3.ny;
    metal::atomic_store_explicit(&grid[h_3 + 7u], _e145, metal::memory_order_relaxed);
    float _e152 = f_3.inv[0];
    metal::atomic_store_explicit(&grid[h_3 + 8u], as_type<uint>(_e152), metal::memory_order_relaxed);
    float _e160 = f_3.inv[1];
    metal::atomic_store_explicit(&grid[h_3 + 9u], as_type<uint>(_e160), metal::memory_order_relaxed);
    float _e168 = f_3.inv[2];
    metal::atomic_store_explicit(&grid[h_3 + 10u], as_type<uint>(_e168), metal::memory_order_relaxed);
    uint _e175 = f_3.nz;
    metal::atomic_store_explicit(&grid[h_3 + 11u], _e175, metal::memory_order_relaxed);
    metal::atomic_store_explicit(&grid[h_3 + 12u], as_type<uint>(g_2.reach), metal::memory_order_relaxed);
    return;
}

void fill_cells(
    GridParams g_3,
    uint i_3,
    bool scatter,
    constant GridStage& params,
    device type_4 const& bsh_nodes,
    device type_5 const& grid_leaves,
    device type_8 const& grid,
    device type_8& grid_fill,
    device type_5& grid_entries,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_4 = {};
    uint z = {};
    uint y = {};
    uint x_1 = {};
    uint _e5 = params.count;
    if (i_3 >= _e5) {
        return;
    }
    GridFrame _e8 = grid_frame(g_3.header, grid, _buffer_sizes);
    uint _e9 = grid_leaf(i_3, bsh_nodes, grid_leaves, _buffer_sizes);
    if (!((_e8.nx == 0u))) {
        local_4 = _e9 == BSH_NONE;
    } else {
        local_4 = true;
    }
    bool _e19 = local_4;
    if (_e19) {
        return;
    }
    BshNode leaf_1 = bsh_nodes[_e9];
    float _e24 = bsh_grid_radius(leaf_1, g_3.reach);
    metal::uint3 _e26 = bsh_grid_first(_e8, leaf_1.center, _e24);
    metal::uint3 _e28 = bsh_grid_last(_e8, leaf_1.center, _e24);
    z = _e26.z;
    uint2 loop_bound_12 = uint2(4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (metal::all(loop_bound_12 == uint2(0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e68 = z;
            z = _e68 + 1u;
        }
        loop_init_9 = false;
        uint _e31 = z;
        if (_e31 <= _e28.z) {
        } else {
            break;
        }
        {
            y = _e26.y;
            uint2 loop_bound_13 = uint2(4294967295u);
            bool loop_init_10 = true;
            while(true) {
                if (metal::all(loop_bound_13 == uint2(0u))) { break; }
                loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                if (!loop_init_10) {
                    uint _e65 = y;
                    y = _e65 + 1u;
                }
                loop_init_10 = false;
                uint _e36 = y;
                if (_e36 <= _e28.y) {
                } else {
                    break;
                }
                {
                    x_1 = _e26.x;
                    uint2 loop_bound_14 = uint2(4294967295u);
                    bool loop_init_11 = true;
                    while(true) {
                        if (metal::all(loop_bound_14 == uint2(0u))) { break; }
                        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
                        if (!loop_init_11) {
                            uint _e62 = x_1;
                            x_1 = _e62 + 1u;
                        }
                        loop_init_11 = false;
                        uint _e41 = x_1;
                        if (_e41 <= _e28.x) {
                        } else {
                            break;
                        }
                        {
                            uint _e44 = z;
                            uint _e47 = y;
                            uint _e51 = x_1;
                            uint c_5 = (((_e44 * _e8.ny) + _e47) * _e8.nx) + _e51;
                            uint _e58 = metal::atomic_fetch_add_explicit(&grid_fill[g_3.fill + c_5], 1u, metal::memory_order_relaxed);
                            if (scatter) {
                                grid_entries[_e58] = i_3;
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
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

void scan_starts(
    GridParams g_4,
    uint li_3,
    device type_8& grid,
    device type_8& grid_fill,
    threadgroup type_11& wg_sums,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint sum = 0u;
    uint c_3 = {};
    uint start = {};
    uint j_4 = 0u;
    uint c_4 = {};
    uint starts_1 = g_4.header + GRID_HEADER;
    GridFrame _e6 = grid_frame(g_4.header, grid, _buffer_sizes);
    uint cells_2 = (_e6.nx * _e6.ny) * _e6.nz;
    uint run = naga_div((cells_2 + 64u) - 1u, 64u);
    uint a_4 = metal::min(li_3 * run, cells_2);
    uint b_3 = metal::min(a_4 + run, cells_2);
    c_3 = a_4;
    uint2 loop_bound_15 = uint2(4294967295u);
    bool loop_init_12 = true;
    while(true) {
        if (metal::all(loop_bound_15 == uint2(0u))) { break; }
        loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
        if (!loop_init_12) {
            uint _e36 = c_3;
            c_3 = _e36 + 1u;
        }
        loop_init_12 = false;
        uint _e25 = c_3;
        if (_e25 < b_3) {
        } else {
            break;
        }
        {
            uint _e27 = sum;
            uint _e30 = c_3;
            uint _e33 = metal::atomic_load_explicit(&grid_fill[g_4.fill + _e30], metal::memory_order_relaxed);
            sum = _e27 + _e33;
        }
    }
    uint _e40 = sum;
    wg_sums.inner[li_3] = _e40;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    start = g_4.entries;
    uint2 loop_bound_16 = uint2(4294967295u);
    bool loop_init_13 = true;
    while(true) {
        if (metal::all(loop_bound_16 == uint2(0u))) { break; }
        loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
        if (!loop_init_13) {
            uint _e54 = j_4;
            j_4 = _e54 + 1u;
        }
        loop_init_13 = false;
        uint _e45 = j_4;
        if (_e45 < li_3) {
        } else {
            break;
        }
        {
            uint _e47 = start;
            uint _e49 = j_4;
            uint _e51 = wg_sums.inner[_e49];
            start = _e47 + _e51;
        }
    }
    c_4 = a_4;
    uint2 loop_bound_17 = uint2(4294967295u);
    bool loop_init_14 = true;
    while(true) {
        if (metal::all(loop_bound_17 == uint2(0u))) { break; }
        loop_bound_17 -= uint2(loop_bound_17.y == 0u, 1u);
        if (!loop_init_14) {
            uint _e79 = c_4;
            c_4 = _e79 + 1u;
        }
        loop_init_14 = false;
        uint _e57 = c_4;
        if (_e57 < b_3) {
        } else {
            break;
        }
        {
            uint _e61 = c_4;
            uint n_3 = metal::atomic_load_explicit(&grid_fill[g_4.fill + _e61], metal::memory_order_relaxed);
            uint _e66 = c_4;
            uint _e69 = start;
            metal::atomic_store_explicit(&grid[starts_1 + _e66], _e69, metal::memory_order_relaxed);
            uint _e72 = c_4;
            uint _e75 = start;
            metal::atomic_store_explicit(&grid_fill[g_4.fill + _e72], _e75, metal::memory_order_relaxed);
            uint _e76 = start;
            start = _e76 + n_3;
        }
    }
    if ((li_3 + 1u) == 64u) {
        uint _e88 = start;
        metal::atomic_store_explicit(&grid[starts_1 + cells_2], _e88, metal::memory_order_relaxed);
        return;
    } else {
        return;
    }
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, metal::uint3 wid [[threadgroup_position_in_grid]]
, metal::uint3 groups [[threadgroups_per_grid]]
, uint li [[thread_index_in_threadgroup]]
, constant GridStage& params [[user(fake0)]]
, device type_4 const& bsh_nodes [[user(fake0)]]
, device type_5 const& grid_leaves [[user(fake0)]]
, device type_6 const& grid_levels [[user(fake0)]]
, device type_8& grid [[user(fake0)]]
, device type_8& grid_fill [[user(fake0)]]
, device type_5& grid_entries [[user(fake0)]]
, device type_9 const& grids [[user(fake0)]]
, threadgroup type_11& wg_sums
, threadgroup type_13& wg_big
, threadgroup metal::atomic_uint& wg_bigs
, threadgroup type_14& wg_cell
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    if (li == 0u) {
        wg_sums = {};
        wg_big = {};
        metal::atomic_store_explicit(&wg_bigs, 0, metal::memory_order_relaxed);
        wg_cell = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    GridParams g_5 = grids[wid.z];
    uint _e10 = params.stage;
    switch(_e10) {
        case 0u: {
            count_levels(g_5, gid.x, params, bsh_nodes, grid_leaves, grid_levels, grid, _buffer_sizes);
            return;
        }
        case 1u: {
            if (li == 0u) {
                choose_level(g_5, params, grid_levels, grid, _buffer_sizes);
                return;
            } else {
                return;
            }
            break;
        }
        case 3u: {
            scan_starts(g_5, li, grid, grid_fill, wg_sums, _buffer_sizes);
            return;
        }
        case 5u: {
            sort_cells(g_5, ((wid.y * groups.x) + wid.x) * 64u, li, params, grid_leaves, grid, grid_fill, grid_entries, wg_big, wg_bigs, wg_cell, _buffer_sizes);
            return;
        }
        default: {
            uint _e24 = params.stage;
            fill_cells(g_5, gid.x, _e24 == 4u, params, bsh_nodes, grid_leaves, grid, grid_fill, grid_entries, _buffer_sizes);
            return;
        }
    }
}
