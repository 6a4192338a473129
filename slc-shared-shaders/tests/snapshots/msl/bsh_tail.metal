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
};

struct TailParams {
    uint stage;
    uint count;
    uint k;
    uint tree;
};
typedef float type_4[1];
struct BshNode {
    metal::packed_float3 center;
    float radius;
    uint child;
    uint next;
    uint light;
    float extent;
};
typedef metal::float4 type_6[1];
typedef metal::atomic_uint type_8[1];
typedef BshNode type_9[1];
typedef uint BshNodes;
struct type_10 {
    uint inner[1024];
};
struct type_11 {
    uint inner[32];
};
typedef uint TailHist;
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
constant BshNodes BSH = 0u;
constant uint BSH_TILE_DEPTH = 8u;
constant uint BSH_TILE_SUBTREES = 256u;
constant TailHist HIST = 0u;
constant uint BSH_TAIL_CHUNK = 32u;

uint f32_to_bits(
    float x
) {
    return as_type<uint>(x);
}

float range_radius(
    float extent,
    float r2_
) {
    return extent + metal::sqrt(r2_);
}

uint bsh_tail_key(
    float radius
) {
    uint _e1 = f32_to_bits(radius);
    return (_e1 & 2147483647u) >> 21u;
}

BshNode bsh_node(
    BshNodes nodes,
    uint i,
    device type_9 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshNode _e4 = bsh_nodes[i];
    return _e4;
}

bool bsh_in_tail(
    float extent_1,
    float r2_1,
    uint cut
) {
    float _e3 = range_radius(extent_1, r2_1);
    uint _e4 = bsh_tail_key(_e3);
    return _e4 >= cut;
}

uint bsh_rightmost_next(
    BshNodes nodes_1,
    uint i_1,
    device type_9 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint c_2 = {};
    BshNode _e2 = bsh_node(nodes_1, i_1, bsh_nodes, _buffer_sizes);
    if (_e2.child == BSH_NONE) {
        return BSH_NONE;
    }
    c_2 = _e2.child;
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e9 = c_2;
        BshNode _e10 = bsh_node(nodes_1, _e9, bsh_nodes, _buffer_sizes);
        if (_e10.next != _e2.next) {
        } else {
            break;
        }
        {
            uint _e14 = c_2;
            BshNode _e15 = bsh_node(nodes_1, _e14, bsh_nodes, _buffer_sizes);
            c_2 = _e15.next;
        }
    }
    uint _e17 = c_2;
    return _e17;
}

BshNode bsh_tail_leaf(
    BshNode slot,
    metal::float4 bound,
    float r2_2,
    uint li,
    uint next
) {
    BshNode leaf = {};
    leaf = slot;
    leaf.center = metal::float3(bound.x, bound.y, bound.z);
    float _e13 = range_radius(bound.w, r2_2);
    leaf.radius = _e13;
    leaf.child = BSH_NONE;
    leaf.next = next;
    leaf.light = li;
    leaf.extent = bound.w;
    BshNode _e20 = leaf;
    return _e20;
}

uint bsh_tail_bin(
    TailHist hist,
    uint b_3,
    threadgroup type_10& wg_bins
) {
    uint _e4 = wg_bins.inner[b_3];
    return _e4;
}

uint bsh_tail_chunk(
    TailHist hist_1,
    uint c_3,
    threadgroup type_11& wg_chunks
) {
    uint _e4 = wg_chunks.inner[c_3];
    return _e4;
}

uint bsh_tail_cut(
    TailHist hist_2,
    uint k,
    threadgroup type_10& wg_bins,
    threadgroup type_11& wg_chunks
) {
    uint c_4 = 32u;
    uint sum_1 = 0u;
    bool local_2 = {};
    uint b_4 = {};
    bool local_3 = {};
    uint2 loop_bound_1 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e6 = c_4;
        if (_e6 > 0u) {
            uint _e11 = sum_1;
            uint _e12 = c_4;
            uint _e15 = bsh_tail_chunk(hist_2, _e12 - 1u, wg_chunks);
            local_2 = (_e11 + _e15) <= k;
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
            uint _e24 = bsh_tail_chunk(hist_2, _e21 - 1u, wg_chunks);
            sum_1 = _e20 + _e24;
            uint _e26 = c_4;
            c_4 = _e26 - 1u;
        }
    }
    uint _e29 = c_4;
    b_4 = _e29 * BSH_TAIL_CHUNK;
    uint _e33 = b_4;
    uint _e34 = b_4;
    uint end = _e33 - metal::min(_e34, BSH_TAIL_CHUNK);
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e38 = b_4;
        if (_e38 > end) {
            uint _e42 = sum_1;
            uint _e43 = b_4;
            uint _e46 = bsh_tail_bin(hist_2, _e43 - 1u, wg_bins);
            local_3 = (_e42 + _e46) <= k;
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
            uint _e55 = bsh_tail_bin(hist_2, _e52 - 1u, wg_bins);
            sum_1 = _e51 + _e55;
            uint _e57 = b_4;
            b_4 = _e57 - 1u;
        }
    }
    uint _e60 = b_4;
    return _e60;
}

uint tail_light(
    uint s_1,
    device type_8 const& tail,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = metal::atomic_load_explicit(&tail[2u + s_1], metal::memory_order_relaxed);
    return _e5;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, uint __local_invocation_index [[thread_index_in_threadgroup]]
, constant TailParams& params [[user(fake0)]]
, device type_6 const& bounds [[user(fake0)]]
, device type_4 const& r2_3 [[user(fake0)]]
, device type_8& tail_hist [[user(fake0)]]
, device type_8& tail [[user(fake0)]]
, device type_9& bsh_nodes [[user(fake0)]]
, threadgroup type_10& wg_bins
, threadgroup type_11& wg_chunks
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    if (__local_invocation_index == 0u) {
        wg_bins = {};
        wg_chunks = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint b = {};
    uint c = {};
    uint sum = {};
    uint b_1 = {};
    bool local = {};
    uint b_2 = {};
    uint a = 1u;
    uint c_1 = {};
    bool local_1 = {};
    uint s = 0u;
    uint n = 0u;
    uint i_2 = gid.x;
    uint _e4 = params.stage;
    if (_e4 == 1u) {
        b = i_2;
        uint2 loop_bound_3 = uint2(4294967295u);
        bool loop_init = true;
        while(true) {
            if (metal::all(loop_bound_3 == uint2(0u))) { break; }
            loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
            if (!loop_init) {
                uint _e18 = b;
                b = _e18 + 64u;
            }
            loop_init = false;
            uint _e8 = b;
            if (_e8 < BSH_TAIL_BINS) {
            } else {
                break;
            }
            {
                uint _e12 = b;
                uint _e15 = b;
                uint _e17 = metal::atomic_load_explicit(&tail_hist[_e15], metal::memory_order_relaxed);
                wg_bins.inner[_e12] = _e17;
            }
        }
        metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        c = i_2;
        uint2 loop_bound_4 = uint2(4294967295u);
        bool loop_init_1 = true;
        while(true) {
            if (metal::all(loop_bound_4 == uint2(0u))) { break; }
            loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
            if (!loop_init_1) {
                uint _e49 = c;
                c = _e49 + 64u;
            }
            loop_init_1 = false;
            uint _e22 = c;
            if (_e22 < 32u) {
            } else {
                break;
            }
            {
                sum = 0u;
                b_1 = 0u;
                uint2 loop_bound_5 = uint2(4294967295u);
                bool loop_init_2 = true;
                while(true) {
                    if (metal::all(loop_bound_5 == uint2(0u))) { break; }
                    loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                    if (!loop_init_2) {
                        uint _e43 = b_1;
                        b_1 = _e43 + 1u;
                    }
                    loop_init_2 = false;
                    uint _e29 = b_1;
                    if (_e29 < BSH_TAIL_CHUNK) {
                    } else {
                        break;
                    }
                    {
                        uint _e32 = sum;
                        uint _e34 = c;
                        uint _e37 = b_1;
                        uint _e40 = wg_bins.inner[(_e34 * BSH_TAIL_CHUNK) + _e37];
                        sum = _e32 + _e40;
                    }
                }
                uint _e46 = c;
                uint _e48 = sum;
                wg_chunks.inner[_e46] = _e48;
            }
        }
        metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        if (i_2 == 0u) {
            uint _e59 = params.k;
            uint _e60 = bsh_tail_cut(HIST, _e59, wg_bins, wg_chunks);
            metal::atomic_store_explicit(&tail[0], _e60, metal::memory_order_relaxed);
            metal::atomic_store_explicit(&tail[1], 0u, metal::memory_order_relaxed);
        }
        return;
    }
    uint _e66 = params.stage;
    switch(_e66) {
        case 0u: {
            uint _e69 = params.count;
            if (i_2 < _e69) {
                float _e75 = bounds[i_2].w;
                float _e78 = r2_3[i_2];
                float _e79 = range_radius(_e75, _e78);
                uint _e80 = bsh_tail_key(_e79);
                uint _e83 = metal::atomic_fetch_add_explicit(&tail_hist[_e80], 1u, metal::memory_order_relaxed);
                return;
            } else {
                return;
            }
            break;
        }
        case 2u: {
            uint _e86 = params.count;
            if (i_2 < _e86) {
                float _e93 = bounds[i_2].w;
                float _e96 = r2_3[i_2];
                uint _e99 = metal::atomic_load_explicit(&tail[0], metal::memory_order_relaxed);
                bool _e100 = bsh_in_tail(_e93, _e96, _e99);
                local = _e100;
            } else {
                local = false;
            }
            bool _e102 = local;
            if (_e102) {
                uint _e108 = metal::atomic_fetch_add_explicit(&tail[1], 1u, metal::memory_order_relaxed);
                metal::atomic_store_explicit(&tail[2u + _e108], i_2, metal::memory_order_relaxed);
                return;
            } else {
                return;
            }
            break;
        }
        default: {
            b_2 = i_2;
            uint2 loop_bound_6 = uint2(4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (metal::all(loop_bound_6 == uint2(0u))) { break; }
                loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e119 = b_2;
                    b_2 = _e119 + 64u;
                }
                loop_init_3 = false;
                uint _e112 = b_2;
                if (_e112 < BSH_TAIL_BINS) {
                } else {
                    break;
                }
                {
                    uint _e116 = b_2;
                    metal::atomic_store_explicit(&tail_hist[_e116], 0u, metal::memory_order_relaxed);
                }
            }
            if (i_2 != 0u) {
                return;
            }
            uint count = metal::atomic_load_explicit(&tail[1], metal::memory_order_relaxed);
            uint2 loop_bound_7 = uint2(4294967295u);
            bool loop_init_4 = true;
            while(true) {
                if (metal::all(loop_bound_7 == uint2(0u))) { break; }
                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                if (!loop_init_4) {
                    uint _e165 = a;
                    a = _e165 + 1u;
                }
                loop_init_4 = false;
                uint _e129 = a;
                if (_e129 < count) {
                } else {
                    break;
                }
                {
                    uint _e131 = a;
                    uint _e132 = tail_light(_e131, tail, _buffer_sizes);
                    uint _e133 = a;
                    c_1 = _e133;
                    uint2 loop_bound_8 = uint2(4294967295u);
                    while(true) {
                        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
                        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
                        uint _e135 = c_1;
                        if (_e135 > 0u) {
                            uint _e140 = c_1;
                            uint _e143 = tail_light(_e140 - 1u, tail, _buffer_sizes);
                            local_1 = _e143 > _e132;
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
                            uint _e155 = tail_light(_e152 - 1u, tail, _buffer_sizes);
                            metal::atomic_store_explicit(&tail[2u + _e149], _e155, metal::memory_order_relaxed);
                            uint _e156 = c_1;
                            c_1 = _e156 - 1u;
                        }
                    }
                    uint _e161 = c_1;
                    metal::atomic_store_explicit(&tail[2u + _e161], _e132, metal::memory_order_relaxed);
                }
            }
            uint2 loop_bound_9 = uint2(4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (metal::all(loop_bound_9 == uint2(0u))) { break; }
                loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e199 = s;
                    s = _e199 + 1u;
                }
                loop_init_5 = false;
                uint _e169 = s;
                if (_e169 < count) {
                } else {
                    break;
                }
                {
                    uint _e171 = s;
                    uint _e172 = tail_light(_e171, tail, _buffer_sizes);
                    uint _e175 = params.tree;
                    uint _e176 = s;
                    uint at = _e175 + _e176;
                    uint _e181 = s;
                    uint next_1 = ((_e181 + 1u) == count) ? BSH_NONE : (at + 1u);
                    BshNode _e190 = bsh_nodes[at];
                    metal::float4 _e193 = bounds[_e172];
                    float _e196 = r2_3[_e172];
                    BshNode _e197 = bsh_tail_leaf(_e190, _e193, _e196, _e172, next_1);
                    bsh_nodes[at] = _e197;
                }
            }
            uint _e203 = params.tree;
            uint first = (count == 0u) ? BSH_NONE : _e203;
            uint2 loop_bound_10 = uint2(4294967295u);
            while(true) {
                if (metal::all(loop_bound_10 == uint2(0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                uint _e210 = n;
                if (_e210 != BSH_NONE) {
                } else {
                    break;
                }
                {
                    uint _e214 = n;
                    uint _e215 = bsh_rightmost_next(BSH, _e214, bsh_nodes, _buffer_sizes);
                    uint _e217 = n;
                    bsh_nodes[_e217].next = first;
                    n = _e215;
                }
            }
            return;
        }
    }
}
