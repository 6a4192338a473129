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
    uint pad0_;
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
    metal::float3 c_3,
    float r
) {
    uint _e10 = bsh_grid_axis(c_3.x - r, f_1.lo[0], f_1.inv[0], f_1.nx);
    uint _e18 = bsh_grid_axis(c_3.y - r, f_1.lo[1], f_1.inv[1], f_1.ny);
    uint _e26 = bsh_grid_axis(c_3.z - r, f_1.lo[2], f_1.inv[2], f_1.nz);
    return metal::uint3(_e10, _e18, _e26);
}

metal::uint3 bsh_grid_last(
    GridFrame f_2,
    metal::float3 c_4,
    float r_1
) {
    uint _e10 = bsh_grid_axis(c_4.x + r_1, f_2.lo[0], f_2.inv[0], f_2.nx);
    uint _e18 = bsh_grid_axis(c_4.y + r_1, f_2.lo[1], f_2.inv[1], f_2.ny);
    uint _e26 = bsh_grid_axis(c_4.z + r_1, f_2.lo[2], f_2.inv[2], f_2.nz);
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
    uint s = {};
    uint c_2 = {};
    bool local_3 = {};
    uint s_1 = {};
    uint i_2 = gid.x;
    uint h_1 = params.header;
    uint starts = h_1 + GRID_HEADER;
    uint _e9 = params.stage;
    if (_e9 == 3u) {
        GridFrame _e12 = grid_frame(h_1, grid, _buffer_sizes);
        uint cells_1 = (_e12.nx * _e12.ny) * _e12.nz;
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
                uint _e44 = c;
                c = _e44 + 1u;
            }
            loop_init = false;
            uint _e31 = c;
            if (_e31 < b_1) {
            } else {
                break;
            }
            {
                uint _e33 = sum;
                uint _e37 = params.fill;
                uint _e38 = c;
                uint _e41 = metal::atomic_load_explicit(&grid_fill[_e37 + _e38], metal::memory_order_relaxed);
                sum = _e33 + _e41;
            }
        }
        uint _e48 = sum;
        wg_sums.inner[i_2] = _e48;
        metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        uint _e51 = params.entries;
        start = _e51;
        uint2 loop_bound_1 = uint2(4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (metal::all(loop_bound_1 == uint2(0u))) { break; }
            loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e64 = j;
                j = _e64 + 1u;
            }
            loop_init_1 = false;
            uint _e55 = j;
            if (_e55 < i_2) {
            } else {
                break;
            }
            {
                uint _e57 = start;
                uint _e59 = j;
                uint _e61 = wg_sums.inner[_e59];
                start = _e57 + _e61;
            }
        }
        c_1 = a_1;
        uint2 loop_bound_2 = uint2(4294967295u);
        bool loop_init_2 = true;
        while(true) {
            if (metal::all(loop_bound_2 == uint2(0u))) { break; }
            loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
            if (!loop_init_2) {
                uint _e93 = c_1;
                c_1 = _e93 + 1u;
            }
            loop_init_2 = false;
            uint _e67 = c_1;
            if (_e67 < b_1) {
            } else {
                break;
            }
            {
                uint _e72 = params.fill;
                uint _e73 = c_1;
                uint n_1 = metal::atomic_load_explicit(&grid_fill[_e72 + _e73], metal::memory_order_relaxed);
                uint _e78 = c_1;
                uint _e81 = start;
                metal::atomic_store_explicit(&grid[starts + _e78], _e81, metal::memory_order_relaxed);
                uint _e85 = params.fill;
                uint _e86 = c_1;
                uint _e89 = start;
                metal::atomic_store_explicit(&grid_fill[_e85 + _e86], _e89, metal::memory_order_relaxed);
                uint _e90 = start;
                start = _e90 + n_1;
            }
        }
        if ((i_2 + 1u) == 64u) {
            uint _e102 = start;
            metal::atomic_store_explicit(&grid[starts + cells_1], _e102, metal::memory_order_relaxed);
        }
        return;
    }
    uint _e105 = params.stage;
    switch(_e105) {
        case 0u: {
            uint _e108 = params.count;
            if (i_2 >= _e108) {
                return;
            }
            uint _e110 = grid_leaf(i_2, bsh_nodes, grid_leaves, _buffer_sizes);
            if (_e110 == BSH_NONE) {
                return;
            }
            uint _e118 = metal::atomic_fetch_add_explicit(&grid[h_1 + 13u], 1u, metal::memory_order_relaxed);
            BshNode leaf = bsh_nodes[_e110];
            float _e124 = params.reach;
            float _e125 = bsh_grid_radius(leaf, _e124);
            uint2 loop_bound_3 = uint2(4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (metal::all(loop_bound_3 == uint2(0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e172 = l;
                    l = _e172 + 1u;
                }
                loop_init_3 = false;
                uint _e128 = l;
                uint _e131 = params.levels;
                if (_e128 < _e131) {
                } else {
                    break;
                }
                {
                    uint _e134 = l;
                    GridFrame _e136 = grid_levels[_e134];
                    metal::uint3 _e138 = bsh_grid_last(_e136, leaf.center, _e125);
                    uint _e140 = l;
                    GridFrame _e142 = grid_levels[_e140];
                    metal::uint3 _e144 = bsh_grid_first(_e142, leaf.center, _e125);
                    metal::uint3 d = (_e138 - _e144) + metal::uint3(1u);
                    uint n_2 = (d.x * d.y) * d.z;
                    uint _e157 = l;
                    uint at = (h_1 + 16u) + (2u * _e157);
                    uint _e162 = metal::atomic_fetch_add_explicit(&grid[at], n_2, metal::memory_order_relaxed);
                    if ((_e162 + n_2) < _e162) {
                        uint _e170 = metal::atomic_fetch_add_explicit(&grid[at + 1u], 1u, metal::memory_order_relaxed);
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
            uint _e183 = params.levels;
            chosen = _e183;
            uint2 loop_bound_4 = uint2(4294967295u);
            bool loop_init_4 = true;
            while(true) {
                if (metal::all(loop_bound_4 == uint2(0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_4) {
                    uint _e246 = l_1;
                    l_1 = _e246 + 1u;
                }
                loop_init_4 = false;
                uint _e187 = l_1;
                uint _e190 = params.levels;
                if (_e187 < _e190) {
                } else {
                    break;
                }
                {
                    uint _e193 = l_1;
                    GridFrame f_4 = grid_levels[_e193];
                    uint cells_2 = (f_4.nx * f_4.ny) * f_4.nz;
                    uint _e201 = bsh_grid_budget(leaves_1, cells_2);
                    uint _e204 = params.capacity;
                    uint budget = metal::min(_e201, _e204);
                    uint _e209 = l_1;
                    uint at_1 = (h_1 + 16u) + (2u * _e209);
                    uint _e212 = chosen;
                    uint _e215 = params.levels;
                    if (_e212 == _e215) {
                        uint _e223 = metal::atomic_load_explicit(&grid[at_1 + 1u], metal::memory_order_relaxed);
                        local = _e223 == 0u;
                    } else {
                        local = false;
                    }
                    bool _e227 = local;
                    if (_e227) {
                        uint _e232 = metal::atomic_load_explicit(&grid[at_1], metal::memory_order_relaxed);
                        local_1 = _e232 <= budget;
                    } else {
                        local_1 = false;
                    }
                    bool _e235 = local_1;
                    if (_e235) {
                        uint _e236 = l_1;
                        chosen = _e236;
                    }
                    metal::atomic_store_explicit(&grid[at_1], 0u, metal::memory_order_relaxed);
                    metal::atomic_store_explicit(&grid[at_1 + 1u], 0u, metal::memory_order_relaxed);
                }
            }
            metal::atomic_store_explicit(&grid[h_1 + 13u], 0u, metal::memory_order_relaxed);
            uint _e254 = chosen;
            uint _e257 = params.levels;
            if (_e254 < _e257) {
                uint _e260 = chosen;
                GridFrame _e262 = grid_levels[_e260];
                f = _e262;
            }
            float _e267 = f.lo[0];
            metal::atomic_store_explicit(&grid[h_1], as_type<uint>(_e267), metal::memory_order_relaxed);
            float _e275 = f.lo[1];
            metal::atomic_store_explicit(&grid[h_1 + 1u], as_type<uint>(_e275), metal::memory_order_relaxed);
            float _e283 = f.lo[2];
            metal::atomic_store_explicit(&grid[h_1 + 2u], as_type<uint>(_e283), metal::memory_order_relaxed);
            uint _e290 = f.nx;
            metal::atomic_store_explicit(&grid[h_1 + 3u], _e290, metal::memory_order_relaxed);
            float _e297 = f.hi[0];
            metal::atomic_store_explicit(&grid[h_1 + 4u], as_type<uint>(_e297), metal::memory_order_relaxed);
            float _e305 = f.hi[1];
            metal::atomic_store_explicit(&grid[h_1 + 5u], as_type<uint>(_e305), metal::memory_order_relaxed);
            float _e313 = f.hi[2];
            metal::atomic_store_explicit(&grid[h_1 + 6u], as_type<uint>(_e313), metal::memory_order_relaxed);
            uint _e320 = f.ny;
            metal::atomic_store_explicit(&grid[h_1 + 7u], _e320, metal::memory_order_relaxed);
            float _e327 = f.inv[0];
            metal::atomic_store_explicit(&grid[h_1 + 8u], as_type<uint>(_e327), metal::memory_order_relaxed);
            float _e335 = f.inv[1];
            metal::atomic_store_explicit(&grid[h_1 + 9u], as_type<uint>(_e335), metal::memory_order_relaxed);
            float _e343 = f.inv[2];
            metal::atomic_store_explicit(&grid[h_1 + 10u], as_type<uint>(_e343), metal::memory_order_relaxed);
            uint _e350 = f.nz;
            metal::atomic_store_explicit(&grid[h_1 + 11u], _e350, metal::memory_order_relaxed);
            float _e357 = params.reach;
            metal::atomic_store_explicit(&grid[h_1 + 12u], as_type<uint>(_e357), metal::memory_order_relaxed);
            return;
        }
        case 2u:
        case 4u: {
            uint _e361 = params.count;
            if (i_2 >= _e361) {
                return;
            }
            GridFrame _e363 = grid_frame(h_1, grid, _buffer_sizes);
            uint _e364 = grid_leaf(i_2, bsh_nodes, grid_leaves, _buffer_sizes);
            if (!((_e363.nx == 0u))) {
                local_2 = _e364 == BSH_NONE;
            } else {
                local_2 = true;
            }
            bool _e374 = local_2;
            if (_e374) {
                return;
            }
            BshNode leaf_1 = bsh_nodes[_e364];
            float _e380 = params.reach;
            float _e381 = bsh_grid_radius(leaf_1, _e380);
            metal::uint3 _e383 = bsh_grid_first(_e363, leaf_1.center, _e381);
            metal::uint3 _e385 = bsh_grid_last(_e363, leaf_1.center, _e381);
            z = _e383.z;
            uint2 loop_bound_5 = uint2(4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (metal::all(loop_bound_5 == uint2(0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e432 = z;
                    z = _e432 + 1u;
                }
                loop_init_5 = false;
                uint _e388 = z;
                if (_e388 <= _e385.z) {
                } else {
                    break;
                }
                {
                    y = _e383.y;
                    uint2 loop_bound_6 = uint2(4294967295u);
                    bool loop_init_6 = true;
                    while(true) {
                        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
                        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                        if (!loop_init_6) {
                            uint _e429 = y;
                            y = _e429 + 1u;
                        }
                        loop_init_6 = false;
                        uint _e393 = y;
                        if (_e393 <= _e385.y) {
                        } else {
                            break;
                        }
                        {
                            x = _e383.x;
                            uint2 loop_bound_7 = uint2(4294967295u);
                            bool loop_init_7 = true;
                            while(true) {
                                if (metal::all(loop_bound_7 == uint2(0u))) { break; }
                                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                                if (!loop_init_7) {
                                    uint _e426 = x;
                                    x = _e426 + 1u;
                                }
                                loop_init_7 = false;
                                uint _e398 = x;
                                if (_e398 <= _e385.x) {
                                } else {
                                    break;
                                }
                                {
                                    uint _e401 = z;
                                    uint _e404 = y;
                                    uint _e408 = x;
                                    uint c_5 = (((_e401 * _e363.ny) + _e404) * _e363.nx) + _e408;
                                    uint _e413 = params.fill;
                                    uint _e417 = metal::atomic_fetch_add_explicit(&grid_fill[_e413 + c_5], 1u, metal::memory_order_relaxed);
                                    uint _e420 = params.stage;
                                    if (_e420 == 4u) {
                                        grid_entries[_e417] = i_2;
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
            GridFrame _e434 = grid_frame(h_1, grid, _buffer_sizes);
            if (i_2 >= ((_e434.nx * _e434.ny) * _e434.nz)) {
                return;
            }
            uint _e444 = params.fill;
            metal::atomic_store_explicit(&grid_fill[_e444 + i_2], 0u, metal::memory_order_relaxed);
            uint a_2 = metal::atomic_load_explicit(&grid[starts + i_2], metal::memory_order_relaxed);
            uint b_2 = metal::atomic_load_explicit(&grid[(starts + i_2) + 1u], metal::memory_order_relaxed);
            s = a_2 + 1u;
            uint2 loop_bound_8 = uint2(4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (metal::all(loop_bound_8 == uint2(0u))) { break; }
                loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e498 = s;
                    s = _e498 + 1u;
                }
                loop_init_8 = false;
                uint _e461 = s;
                if (_e461 < b_2) {
                } else {
                    break;
                }
                {
                    uint _e464 = s;
                    uint v_1 = grid_entries[_e464];
                    uint _e467 = s;
                    c_2 = _e467;
                    uint2 loop_bound_9 = uint2(4294967295u);
                    while(true) {
                        if (metal::all(loop_bound_9 == uint2(0u))) { break; }
                        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                        uint _e469 = c_2;
                        if (_e469 > a_2) {
                            uint _e474 = c_2;
                            uint _e478 = grid_entries[_e474 - 1u];
                            local_3 = _e478 > v_1;
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
                            uint _e490 = grid_entries[_e486 - 1u];
                            grid_entries[_e483] = _e490;
                            uint _e491 = c_2;
                            c_2 = _e491 - 1u;
                        }
                    }
                    uint _e495 = c_2;
                    grid_entries[_e495] = v_1;
                }
            }
            s_1 = a_2;
            uint2 loop_bound_10 = uint2(4294967295u);
            bool loop_init_9 = true;
            while(true) {
                if (metal::all(loop_bound_10 == uint2(0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_9) {
                    uint _e514 = s_1;
                    s_1 = _e514 + 1u;
                }
                loop_init_9 = false;
                uint _e501 = s_1;
                if (_e501 < b_2) {
                } else {
                    break;
                }
                {
                    uint _e504 = s_1;
                    uint _e508 = s_1;
                    uint _e510 = grid_entries[_e508];
                    uint _e512 = grid_leaves[_e510];
                    grid_entries[_e504] = _e512;
                }
            }
            return;
        }
    }
}
