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
    uint header;
    uint fill;
    uint entries;
    uint least;
    uint pad1_;
    uint pad2_;
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
struct type_11 {
    uint inner[1536];
};
constant uint LIGHT_POINT = 0u;
constant uint LIGHT_SPOT = 1u;
constant uint LIGHT_IES = 2u;
constant uint LIGHT_TRIANGLE = 3u;
constant uint LIGHT_VPL = 4u;
constant uint NO_LIGHT = 4294967295u;
constant uint GRID_HEADER = 32u;
constant uint GRID_LEVELS_MAX = 8u;
constant uint GRID_SORT_MAX = 1536u;
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
    uint cells,
    uint least
) {
    if (leaves > 536870911u) {
        return 4294967295u;
    }
    uint e = leaves * GRID_ENTRIES_PER_LIGHT;
    uint _e8 = add_wrap_u32_(e, cells);
    return metal::max((_e8 < e) ? 4294967295u : _e8, least);
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
    GridFrame f_1,
    metal::float3 c_2,
    float r
) {
    uint _e10 = bsh_grid_axis(c_2.x - r, f_1.lo[0], f_1.inv[0], f_1.nx);
    uint _e18 = bsh_grid_axis(c_2.y - r, f_1.lo[1], f_1.inv[1], f_1.ny);
    uint _e26 = bsh_grid_axis(c_2.z - r, f_1.lo[2], f_1.inv[2], f_1.nz);
    return metal::uint3(_e10, _e18, _e26);
}

metal::uint3 bsh_grid_last(
    GridFrame f_2,
    metal::float3 c_3,
    float r_1
) {
    uint _e10 = bsh_grid_axis(c_3.x + r_1, f_2.lo[0], f_2.inv[0], f_2.nx);
    uint _e18 = bsh_grid_axis(c_3.y + r_1, f_2.lo[1], f_2.inv[1], f_2.ny);
    uint _e26 = bsh_grid_axis(c_3.z + r_1, f_2.lo[2], f_2.inv[2], f_2.nz);
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
    GridFrame f_3 = {};
    uint _e3 = grid_word(h, grid, _buffer_sizes);
    uint _e7 = grid_word(h + 1u, grid, _buffer_sizes);
    uint _e11 = grid_word(h + 2u, grid, _buffer_sizes);
    f_3.lo = metal::float3(as_type<float>(_e3), as_type<float>(_e7), as_type<float>(_e11));
    uint _e17 = grid_word(h + 3u, grid, _buffer_sizes);
    f_3.nx = _e17;
    uint _e21 = grid_word(h + 4u, grid, _buffer_sizes);
    uint _e25 = grid_word(h + 5u, grid, _buffer_sizes);
    uint _e29 = grid_word(h + 6u, grid, _buffer_sizes);
    f_3.hi = metal::float3(as_type<float>(_e21), as_type<float>(_e25), as_type<float>(_e29));
    uint _e35 = grid_word(h + 7u, grid, _buffer_sizes);
    f_3.ny = _e35;
    uint _e39 = grid_word(h + 8u, grid, _buffer_sizes);
    uint _e43 = grid_word(h + 9u, grid, _buffer_sizes);
    uint _e47 = grid_word(h + 10u, grid, _buffer_sizes);
    f_3.inv = metal::float3(as_type<float>(_e39), as_type<float>(_e43), as_type<float>(_e47));
    uint _e53 = grid_word(h + 11u, grid, _buffer_sizes);
    f_3.nz = _e53;
    GridFrame _e54 = f_3;
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

void sort_cell(
    uint cell,
    uint li_1,
    constant GridParams& params,
    device type_5 const& grid_leaves,
    device type_8 const& grid,
    device type_8& grid_fill,
    device type_5& grid_entries,
    threadgroup type_11& wg_cell,
    threadgroup metal::uint2& wg_span,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint2 span = metal::uint2(0u);
    uint s = {};
    uint c_4 = {};
    bool local_3 = {};
    uint s_1 = {};
    uint j_1 = {};
    uint j_2 = {};
    uint below = {};
    uint m = {};
    uint _e4 = params.header;
    uint starts = _e4 + GRID_HEADER;
    if (li_1 == 0u) {
        uint _e11 = params.header;
        GridFrame _e12 = grid_frame(_e11, grid, _buffer_sizes);
        if (cell < ((_e12.nx * _e12.ny) * _e12.nz)) {
            uint _e25 = metal::atomic_load_explicit(&grid[starts + cell], metal::memory_order_relaxed);
            uint _e31 = metal::atomic_load_explicit(&grid[(starts + cell) + 1u], metal::memory_order_relaxed);
            span = metal::uint2(_e25, _e31);
            uint _e36 = params.fill;
            metal::atomic_store_explicit(&grid_fill[_e36 + cell], 0u, metal::memory_order_relaxed);
        }
        metal::uint2 _e41 = span;
        wg_span = _e41;
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    metal::uint2 unnamed = wg_span;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint a_1 = unnamed.x;
    uint n_1 = unnamed.y - unnamed.x;
    if (n_1 > GRID_SORT_MAX) {
        if (li_1 == 0u) {
            s = a_1 + 1u;
            uint2 loop_bound = uint2(4294967295u);
            bool loop_init = true;
            while(true) {
                if (metal::all(loop_bound == uint2(0u))) { break; }
                loop_bound -= uint2(loop_bound.y == 0u, 1u);
                if (!loop_init) {
                    uint _e93 = s;
                    s = _e93 + 1u;
                }
                loop_init = false;
                uint _e55 = s;
                if (_e55 < (a_1 + n_1)) {
                } else {
                    break;
                }
                {
                    uint _e59 = s;
                    uint v_1 = grid_entries[_e59];
                    uint _e62 = s;
                    c_4 = _e62;
                    uint2 loop_bound_1 = uint2(4294967295u);
                    while(true) {
                        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
                        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                        uint _e64 = c_4;
                        if (_e64 > a_1) {
                            uint _e69 = c_4;
                            uint _e73 = grid_entries[_e69 - 1u];
                            local_3 = _e73 > v_1;
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
                            uint _e85 = grid_entries[_e81 - 1u];
                            grid_entries[_e78] = _e85;
                            uint _e86 = c_4;
                            c_4 = _e86 - 1u;
                        }
                    }
                    uint _e90 = c_4;
                    grid_entries[_e90] = v_1;
                }
            }
            s_1 = a_1;
            uint2 loop_bound_2 = uint2(4294967295u);
            bool loop_init_1 = true;
            while(true) {
                if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                if (!loop_init_1) {
                    uint _e110 = s_1;
                    s_1 = _e110 + 1u;
                }
                loop_init_1 = false;
                uint _e96 = s_1;
                if (_e96 < (a_1 + n_1)) {
                } else {
                    break;
                }
                {
                    uint _e100 = s_1;
                    uint _e104 = s_1;
                    uint _e106 = grid_entries[_e104];
                    uint _e108 = grid_leaves[_e106];
                    grid_entries[_e100] = _e108;
                }
            }
        }
        return;
    }
    j_1 = li_1;
    uint2 loop_bound_3 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e123 = j_1;
            j_1 = _e123 + 64u;
        }
        loop_init_2 = false;
        uint _e113 = j_1;
        if (_e113 < n_1) {
        } else {
            break;
        }
        {
            uint _e116 = j_1;
            uint _e119 = j_1;
            uint _e122 = grid_entries[a_1 + _e119];
            wg_cell.inner[_e116] = _e122;
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    j_2 = li_1;
    uint2 loop_bound_4 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e159 = j_2;
            j_2 = _e159 + 64u;
        }
        loop_init_3 = false;
        uint _e127 = j_2;
        if (_e127 < n_1) {
        } else {
            break;
        }
        {
            uint _e130 = j_2;
            uint v_2 = wg_cell.inner[_e130];
            below = 0u;
            m = 0u;
            uint2 loop_bound_5 = uint2(4294967295u);
            bool loop_init_4 = true;
            while(true) {
                if (metal::all(loop_bound_5 == uint2(0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_4) {
                    uint _e150 = m;
                    m = _e150 + 1u;
                }
                loop_init_4 = false;
                uint _e137 = m;
                if (_e137 < n_1) {
                } else {
                    break;
                }
                {
                    uint _e139 = below;
                    uint _e143 = m;
                    uint _e145 = wg_cell.inner[_e143];
                    below = _e139 + ((_e145 < v_2) ? 1u : 0u);
                }
            }
            uint _e153 = below;
            uint _e158 = grid_leaves[v_2];
            grid_entries[a_1 + _e153] = _e158;
        }
    }
    return;
}
uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}


struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, metal::uint3 wid [[threadgroup_position_in_grid]]
, metal::uint3 groups [[threadgroups_per_grid]]
, uint li [[thread_index_in_threadgroup]]
, constant GridParams& params [[user(fake0)]]
, device type_4 const& bsh_nodes [[user(fake0)]]
, device type_5 const& grid_leaves [[user(fake0)]]
, device type_6 const& grid_levels [[user(fake0)]]
, device type_8& grid [[user(fake0)]]
, device type_8& grid_fill [[user(fake0)]]
, device type_5& grid_entries [[user(fake0)]]
, threadgroup type_10& wg_sums
, threadgroup type_11& wg_cell
, threadgroup metal::uint2& wg_span
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    if (li == 0u) {
        wg_sums = {};
        wg_cell = {};
        wg_span = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint sum = 0u;
    uint c = {};
    uint start = {};
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
    uint _e6 = params.stage;
    if (_e6 == 5u) {
        sort_cell((wid.y * groups.x) + wid.x, li, params, grid_leaves, grid, grid_fill, grid_entries, wg_cell, wg_span, _buffer_sizes);
        return;
    }
    uint i_2 = gid.x;
    uint h_1 = params.header;
    uint starts_1 = h_1 + GRID_HEADER;
    uint _e22 = params.stage;
    if (_e22 == 3u) {
        GridFrame _e25 = grid_frame(h_1, grid, _buffer_sizes);
        uint cells_1 = (_e25.nx * _e25.ny) * _e25.nz;
        uint run = naga_div((cells_1 + 64u) - 1u, 64u);
        uint a_2 = metal::min(i_2 * run, cells_1);
        uint b_1 = metal::min(a_2 + run, cells_1);
        c = a_2;
        uint2 loop_bound_6 = uint2(4294967295u);
        bool loop_init_5 = true;
        while(true) {
            if (metal::all(loop_bound_6 == uint2(0u))) { break; }
            loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
            if (!loop_init_5) {
                uint _e57 = c;
                c = _e57 + 1u;
            }
            loop_init_5 = false;
            uint _e44 = c;
            if (_e44 < b_1) {
            } else {
                break;
            }
            {
                uint _e46 = sum;
                uint _e50 = params.fill;
                uint _e51 = c;
                uint _e54 = metal::atomic_load_explicit(&grid_fill[_e50 + _e51], metal::memory_order_relaxed);
                sum = _e46 + _e54;
            }
        }
        uint _e61 = sum;
        wg_sums.inner[i_2] = _e61;
        metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        uint _e64 = params.entries;
        start = _e64;
        uint2 loop_bound_7 = uint2(4294967295u);
        bool loop_init_6 = true;
        while(true) {
            if (metal::all(loop_bound_7 == uint2(0u))) { break; }
            loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
            if (!loop_init_6) {
                uint _e77 = j;
                j = _e77 + 1u;
            }
            loop_init_6 = false;
            uint _e68 = j;
            if (_e68 < i_2) {
            } else {
                break;
            }
            {
                uint _e70 = start;
                uint _e72 = j;
                uint _e74 = wg_sums.inner[_e72];
                start = _e70 + _e74;
            }
        }
        c_1 = a_2;
        uint2 loop_bound_8 = uint2(4294967295u);
        bool loop_init_7 = true;
        while(true) {
            if (metal::all(loop_bound_8 == uint2(0u))) { break; }
            loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
            if (!loop_init_7) {
                uint _e106 = c_1;
                c_1 = _e106 + 1u;
            }
            loop_init_7 = false;
            uint _e80 = c_1;
            if (_e80 < b_1) {
            } else {
                break;
            }
            {
                uint _e85 = params.fill;
                uint _e86 = c_1;
                uint n_2 = metal::atomic_load_explicit(&grid_fill[_e85 + _e86], metal::memory_order_relaxed);
                uint _e91 = c_1;
                uint _e94 = start;
                metal::atomic_store_explicit(&grid[starts_1 + _e91], _e94, metal::memory_order_relaxed);
                uint _e98 = params.fill;
                uint _e99 = c_1;
                uint _e102 = start;
                metal::atomic_store_explicit(&grid_fill[_e98 + _e99], _e102, metal::memory_order_relaxed);
                uint _e103 = start;
                start = _e103 + n_2;
            }
        }
        if ((i_2 + 1u) == 64u) {
            uint _e115 = start;
            metal::atomic_store_explicit(&grid[starts_1 + cells_1], _e115, metal::memory_order_relaxed);
        }
        return;
    }
    uint _e118 = params.stage;
    switch(_e118) {
        case 0u: {
            uint _e121 = params.count;
            if (i_2 >= _e121) {
                return;
            }
            uint _e123 = grid_leaf(i_2, bsh_nodes, grid_leaves, _buffer_sizes);
            if (_e123 == BSH_NONE) {
                return;
            }
            uint _e131 = metal::atomic_fetch_add_explicit(&grid[h_1 + 13u], 1u, metal::memory_order_relaxed);
            BshNode leaf = bsh_nodes[_e123];
            float _e137 = params.reach;
            float _e138 = bsh_grid_radius(leaf, _e137);
            uint2 loop_bound_9 = uint2(4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (metal::all(loop_bound_9 == uint2(0u))) { break; }
                loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e185 = l;
                    l = _e185 + 1u;
                }
                loop_init_8 = false;
                uint _e141 = l;
                uint _e144 = params.levels;
                if (_e141 < _e144) {
                } else {
                    break;
                }
                {
                    uint _e147 = l;
                    GridFrame _e149 = grid_levels[_e147];
                    metal::uint3 _e151 = bsh_grid_last(_e149, leaf.center, _e138);
                    uint _e153 = l;
                    GridFrame _e155 = grid_levels[_e153];
                    metal::uint3 _e157 = bsh_grid_first(_e155, leaf.center, _e138);
                    metal::uint3 d = (_e151 - _e157) + metal::uint3(1u);
                    uint n_3 = (d.x * d.y) * d.z;
                    uint _e170 = l;
                    uint at = (h_1 + 16u) + (2u * _e170);
                    uint _e175 = metal::atomic_fetch_add_explicit(&grid[at], n_3, metal::memory_order_relaxed);
                    if ((_e175 + n_3) < _e175) {
                        uint _e183 = metal::atomic_fetch_add_explicit(&grid[at + 1u], 1u, metal::memory_order_relaxed);
                    }
                }
            }
            return;
        }
        case 1u: {
            if (i_2 != 0u) {
                return;
            }
            uint leaves_1 = metal::atomic_load_explicit(&grid[h_1 + 13u], metal::memory_order_relaxed);
            uint _e196 = params.levels;
            chosen = _e196;
            uint2 loop_bound_10 = uint2(4294967295u);
            bool loop_init_9 = true;
            while(true) {
                if (metal::all(loop_bound_10 == uint2(0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_9) {
                    uint _e262 = l_1;
                    l_1 = _e262 + 1u;
                }
                loop_init_9 = false;
                uint _e200 = l_1;
                uint _e203 = params.levels;
                if (_e200 < _e203) {
                } else {
                    break;
                }
                {
                    uint _e206 = l_1;
                    GridFrame f_4 = grid_levels[_e206];
                    uint cells_2 = (f_4.nx * f_4.ny) * f_4.nz;
                    uint _e216 = params.least;
                    uint _e217 = bsh_grid_budget(leaves_1, cells_2, _e216);
                    uint _e220 = params.capacity;
                    uint budget = metal::min(_e217, _e220);
                    uint _e225 = l_1;
                    uint at_1 = (h_1 + 16u) + (2u * _e225);
                    uint _e228 = chosen;
                    uint _e231 = params.levels;
                    if (_e228 == _e231) {
                        uint _e239 = metal::atomic_load_explicit(&grid[at_1 + 1u], metal::memory_order_relaxed);
                        local = _e239 == 0u;
                    } else {
                        local = false;
                    }
                    bool _e243 = local;
                    if (_e243) {
                        uint _e248 = metal::atomic_load_explicit(&grid[at_1], metal::memory_order_relaxed);
                        local_1 = _e248 <= budget;
                    } else {
                        local_1 = false;
                    }
                    bool _e251 = local_1;
                    if (_e251) {
                        uint _e252 = l_1;
                        chosen = _e252;
                    }
                    metal::atomic_store_explicit(&grid[at_1], 0u, metal::memory_order_relaxed);
                    metal::atomic_store_explicit(&grid[at_1 + 1u], 0u, metal::memory_order_relaxed);
                }
            }
            metal::atomic_store_explicit(&grid[h_1 + 13u], 0u, metal::memory_order_relaxed);
            uint _e270 = chosen;
            uint _e273 = params.levels;
            if (_e270 < _e273) {
                uint _e276 = chosen;
                GridFrame _e278 = grid_levels[_e276];
                f = _e278;
            }
            float _e283 = f.lo[0];
            metal::atomic_store_explicit(&grid[h_1], as_type<uint>(_e283), metal::memory_order_relaxed);
            float _e291 = f.lo[1];
            metal::atomic_store_explicit(&grid[h_1 + 1u], as_type<uint>(_e291), metal::memory_order_relaxed);
            float _e299 = f.lo[2];
            metal::atomic_store_explicit(&grid[h_1 + 2u], as_type<uint>(_e299), metal::memory_order_relaxed);
            uint _e306 = f.nx;
            metal::atomic_store_explicit(&grid[h_1 + 3u], _e306, metal::memory_order_relaxed);
            float _e313 = f.hi[0];
            metal::atomic_store_explicit(&grid[h_1 + 4u], as_type<uint>(_e313), metal::memory_order_relaxed);
            float _e321 = f.hi[1];
            metal::atomic_store_explicit(&grid[h_1 + 5u], as_type<uint>(_e321), metal::memory_order_relaxed);
            float _e329 = f.hi[2];
            metal::atomic_store_explicit(&grid[h_1 + 6u], as_type<uint>(_e329), metal::memory_order_relaxed);
            uint _e336 = f.ny;
            metal::atomic_store_explicit(&grid[h_1 + 7u], _e336, metal::memory_order_relaxed);
            float _e343 = f.inv[0];
            metal::atomic_store_explicit(&grid[h_1 + 8u], as_type<uint>(_e343), metal::memory_order_relaxed);
            float _e351 = f.inv[1];
            metal::atomic_store_explicit(&grid[h_1 + 9u], as_type<uint>(_e351), metal::memory_order_relaxed);
            float _e359 = f.inv[2];
            metal::atomic_store_explicit(&grid[h_1 + 10u], as_type<uint>(_e359), metal::memory_order_relaxed);
            uint _e366 = f.nz;
            metal::atomic_store_explicit(&grid[h_1 + 11u], _e366, metal::memory_order_relaxed);
            float _e373 = params.reach;
            metal::atomic_store_explicit(&grid[h_1 + 12u], as_type<uint>(_e373), metal::memory_order_relaxed);
            return;
        }
        case 2u:
        case 4u: {
            uint _e377 = params.count;
            if (i_2 >= _e377) {
                return;
            }
            GridFrame _e379 = grid_frame(h_1, grid, _buffer_sizes);
            uint _e380 = grid_leaf(i_2, bsh_nodes, grid_leaves, _buffer_sizes);
            if (!((_e379.nx == 0u))) {
                local_2 = _e380 == BSH_NONE;
            } else {
                local_2 = true;
            }
            bool _e390 = local_2;
            if (_e390) {
                return;
            }
            BshNode leaf_1 = bsh_nodes[_e380];
            float _e396 = params.reach;
            float _e397 = bsh_grid_radius(leaf_1, _e396);
            metal::uint3 _e399 = bsh_grid_first(_e379, leaf_1.center, _e397);
            metal::uint3 _e401 = bsh_grid_last(_e379, leaf_1.center, _e397);
            z = _e399.z;
            uint2 loop_bound_11 = uint2(4294967295u);
            bool loop_init_10 = true;
            while(true) {
                if (metal::all(loop_bound_11 == uint2(0u))) { break; }
                loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
                if (!loop_init_10) {
                    uint _e448 = z;
                    z = _e448 + 1u;
                }
                loop_init_10 = false;
                uint _e404 = z;
                if (_e404 <= _e401.z) {
                } else {
                    break;
                }
                {
                    y = _e399.y;
                    uint2 loop_bound_12 = uint2(4294967295u);
                    bool loop_init_11 = true;
                    while(true) {
                        if (metal::all(loop_bound_12 == uint2(0u))) { break; }
                        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
                        if (!loop_init_11) {
                            uint _e445 = y;
                            y = _e445 + 1u;
                        }
                        loop_init_11 = false;
                        uint _e409 = y;
                        if (_e409 <= _e401.y) {
                        } else {
                            break;
                        }
                        {
                            x = _e399.x;
                            uint2 loop_bound_13 = uint2(4294967295u);
                            bool loop_init_12 = true;
                            while(true) {
                                if (metal::all(loop_bound_13 == uint2(0u))) { break; }
                                loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                                if (!loop_init_12) {
                                    uint _e442 = x;
                                    x = _e442 + 1u;
                                }
                                loop_init_12 = false;
                                uint _e414 = x;
                                if (_e414 <= _e401.x) {
                                } else {
                                    break;
                                }
                                {
                                    uint _e417 = z;
                                    uint _e420 = y;
                                    uint _e424 = x;
                                    uint c_5 = (((_e417 * _e379.ny) + _e420) * _e379.nx) + _e424;
                                    uint _e429 = params.fill;
                                    uint _e433 = metal::atomic_fetch_add_explicit(&grid_fill[_e429 + c_5], 1u, metal::memory_order_relaxed);
                                    uint _e436 = params.stage;
                                    if (_e436 == 4u) {
                                        grid_entries[_e433] = i_2;
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
