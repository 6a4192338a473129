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
typedef uint TailHist;
constant uint LIGHT_POINT = 0u;
constant uint LIGHT_SPOT = 1u;
constant uint LIGHT_IES = 2u;
constant uint LIGHT_TRIANGLE = 3u;
constant uint LIGHT_VPL = 4u;
constant uint NO_LIGHT = 4294967295u;
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
constant BshNodes BSH = 0u;
constant uint BSH_TILE_DEPTH = 8u;
constant uint BSH_TILE_SUBTREES = 256u;
constant TailHist HIST = 0u;

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
    BshNode _e2 = bsh_node(nodes_1, i_1, bsh_nodes, _buffer_sizes);
    if (_e2.child == BSH_NONE) {
        return BSH_NONE;
    }
    BshNode _e8 = bsh_node(nodes_1, _e2.child, bsh_nodes, _buffer_sizes);
    return _e8.next;
}

uint bsh_tail_bin(
    TailHist hist,
    uint b_1,
    device type_8 const& tail_hist,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e4 = metal::atomic_load_explicit(&tail_hist[b_1], metal::memory_order_relaxed);
    return _e4;
}

uint bsh_tail_cut(
    TailHist hist_1,
    uint k,
    device type_8 const& tail_hist,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint b_2 = BSH_TAIL_BINS;
    uint sum = 0u;
    bool local_2 = {};
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e6 = b_2;
        if (_e6 > 0u) {
            uint _e11 = sum;
            uint _e12 = b_2;
            uint _e15 = bsh_tail_bin(hist_1, _e12 - 1u, tail_hist, _buffer_sizes);
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
            uint _e20 = sum;
            uint _e21 = b_2;
            uint _e24 = bsh_tail_bin(hist_1, _e21 - 1u, tail_hist, _buffer_sizes);
            sum = _e20 + _e24;
            uint _e26 = b_2;
            b_2 = _e26 - 1u;
        }
    }
    uint _e29 = b_2;
    return _e29;
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
, constant TailParams& params [[user(fake0)]]
, device type_6 const& bounds [[user(fake0)]]
, device type_4 const& r2_2 [[user(fake0)]]
, device type_8& tail_hist [[user(fake0)]]
, device type_8& tail [[user(fake0)]]
, device type_9& bsh_nodes [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    bool local = {};
    uint b = {};
    uint a = 1u;
    uint c = {};
    bool local_1 = {};
    uint s = 0u;
    uint n = 0u;
    uint i_2 = gid.x;
    uint _e4 = params.stage;
    switch(_e4) {
        case 0u: {
            uint _e7 = params.count;
            if (i_2 < _e7) {
                float _e13 = bounds[i_2].w;
                float _e16 = r2_2[i_2];
                float _e17 = range_radius(_e13, _e16);
                uint _e18 = bsh_tail_key(_e17);
                uint _e21 = metal::atomic_fetch_add_explicit(&tail_hist[_e18], 1u, metal::memory_order_relaxed);
                return;
            } else {
                return;
            }
            break;
        }
        case 1u: {
            if (i_2 == 0u) {
                uint _e29 = params.k;
                uint _e30 = bsh_tail_cut(HIST, _e29, tail_hist, _buffer_sizes);
                metal::atomic_store_explicit(&tail[0], _e30, metal::memory_order_relaxed);
                metal::atomic_store_explicit(&tail[1], 0u, metal::memory_order_relaxed);
                return;
            } else {
                return;
            }
            break;
        }
        case 2u: {
            uint _e36 = params.count;
            if (i_2 < _e36) {
                float _e43 = bounds[i_2].w;
                float _e46 = r2_2[i_2];
                uint _e49 = metal::atomic_load_explicit(&tail[0], metal::memory_order_relaxed);
                bool _e50 = bsh_in_tail(_e43, _e46, _e49);
                local = _e50;
            } else {
                local = false;
            }
            bool _e52 = local;
            if (_e52) {
                uint _e58 = metal::atomic_fetch_add_explicit(&tail[1], 1u, metal::memory_order_relaxed);
                metal::atomic_store_explicit(&tail[2u + _e58], i_2, metal::memory_order_relaxed);
                return;
            } else {
                return;
            }
            break;
        }
        default: {
            b = i_2;
            uint2 loop_bound_1 = uint2(4294967295u);
            bool loop_init = true;
            while(true) {
                if (metal::all(loop_bound_1 == uint2(0u))) { break; }
                loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                if (!loop_init) {
                    uint _e69 = b;
                    b = _e69 + 64u;
                }
                loop_init = false;
                uint _e62 = b;
                if (_e62 < BSH_TAIL_BINS) {
                } else {
                    break;
                }
                {
                    uint _e66 = b;
                    metal::atomic_store_explicit(&tail_hist[_e66], 0u, metal::memory_order_relaxed);
                }
            }
            if (i_2 != 0u) {
                return;
            }
            uint count = metal::atomic_load_explicit(&tail[1], metal::memory_order_relaxed);
            uint2 loop_bound_2 = uint2(4294967295u);
            bool loop_init_1 = true;
            while(true) {
                if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                if (!loop_init_1) {
                    uint _e115 = a;
                    a = _e115 + 1u;
                }
                loop_init_1 = false;
                uint _e79 = a;
                if (_e79 < count) {
                } else {
                    break;
                }
                {
                    uint _e81 = a;
                    uint _e82 = tail_light(_e81, tail, _buffer_sizes);
                    uint _e83 = a;
                    c = _e83;
                    uint2 loop_bound_3 = uint2(4294967295u);
                    while(true) {
                        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
                        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                        uint _e85 = c;
                        if (_e85 > 0u) {
                            uint _e90 = c;
                            uint _e93 = tail_light(_e90 - 1u, tail, _buffer_sizes);
                            local_1 = _e93 > _e82;
                        } else {
                            local_1 = false;
                        }
                        bool _e96 = local_1;
                        if (_e96) {
                        } else {
                            break;
                        }
                        {
                            uint _e99 = c;
                            uint _e102 = c;
                            uint _e105 = tail_light(_e102 - 1u, tail, _buffer_sizes);
                            metal::atomic_store_explicit(&tail[2u + _e99], _e105, metal::memory_order_relaxed);
                            uint _e106 = c;
                            c = _e106 - 1u;
                        }
                    }
                    uint _e111 = c;
                    metal::atomic_store_explicit(&tail[2u + _e111], _e82, metal::memory_order_relaxed);
                }
            }
            uint2 loop_bound_4 = uint2(4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (metal::all(loop_bound_4 == uint2(0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e156 = s;
                    s = _e156 + 1u;
                }
                loop_init_2 = false;
                uint _e119 = s;
                if (_e119 < count) {
                } else {
                    break;
                }
                {
                    uint _e121 = s;
                    uint _e122 = tail_light(_e121, tail, _buffer_sizes);
                    metal::float4 b_3 = bounds[_e122];
                    uint _e128 = params.tree;
                    uint _e129 = s;
                    uint _e134 = s;
                    uint next = ((_e134 + 1u) == count) ? BSH_NONE : ((_e128 + _e129) + 1u);
                    uint _e142 = params.tree;
                    uint _e143 = s;
                    float _e150 = r2_2[_e122];
                    float _e151 = range_radius(b_3.w, _e150);
                    bsh_nodes[_e142 + _e143] = BshNode {b_3.xyz, _e151, BSH_NONE, next, _e122, b_3.w};
                }
            }
            uint _e160 = params.tree;
            uint first = (count == 0u) ? BSH_NONE : _e160;
            uint2 loop_bound_5 = uint2(4294967295u);
            bool loop_init_3 = true;
            while(true) {
                if (metal::all(loop_bound_5 == uint2(0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_3) {
                    uint _e175 = n;
                    uint _e176 = bsh_rightmost_next(BSH, _e175, bsh_nodes, _buffer_sizes);
                    n = _e176;
                }
                loop_init_3 = false;
                uint _e167 = n;
                if (_e167 != BSH_NONE) {
                } else {
                    break;
                }
                {
                    uint _e171 = n;
                    bsh_nodes[_e171].next = first;
                }
            }
            return;
        }
    }
}
