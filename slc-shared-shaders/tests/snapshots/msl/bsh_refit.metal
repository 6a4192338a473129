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

struct RefitParams {
    uint first;
    uint count;
    uint pad0_;
    uint pad1_;
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
typedef uint type_6[1];
typedef metal::float4 type_7[1];
typedef BshNode type_8[1];
typedef uint BshNodes;
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

float f32_from_bits(
    uint u
) {
    return as_type<float>(u);
}

uint f32_to_bits(
    float x
) {
    return as_type<uint>(x);
}

float sphere_pad(
    float r,
    metal::float3 c
) {
    return ((r + metal::max(metal::abs(c.x), metal::max(metal::abs(c.y), metal::abs(c.z)))) * SPHERE_PAD) + SPHERE_PAD_ABS;
}

metal::float4 sphere_union(
    metal::float3 c1_,
    float r1_,
    metal::float3 c2_,
    float r2_
) {
    bool local = {};
    metal::float3 v = c2_ - c1_;
    float d = metal::sqrt(metal::dot(v, v));
    float _e8 = sphere_pad(r1_, c1_);
    if (r1_ >= ((d + r2_) + _e8)) {
        return metal::float4(c1_.x, c1_.y, c1_.z, r1_);
    }
    float _e16 = sphere_pad(r2_, c2_);
    if (r2_ >= ((d + r1_) + _e16)) {
        return metal::float4(c2_.x, c2_.y, c2_.z, r2_);
    }
    if (!((d >= SPHERE_HUGE))) {
        local = (0.5 * ((d + r1_) + r2_)) >= SPHERE_HUGE;
    } else {
        local = true;
    }
    bool _e35 = local;
    if (_e35) {
        return metal::float4(c1_.x, c1_.y, c1_.z, SPHERE_HUGE);
    }
    if (metal::abs(r1_ - r2_) >= d) {
        if (r1_ >= r2_) {
            float rn = metal::max(r1_, d + r2_);
            float _e50 = sphere_pad(rn, c1_);
            return metal::float4(c1_.x, c1_.y, c1_.z, rn + _e50);
        }
        float rm = metal::max(r2_, d + r1_);
        float _e58 = sphere_pad(rm, c2_);
        return metal::float4(c2_.x, c2_.y, c2_.z, rm + _e58);
    }
    float r0_ = 0.5 * ((d + r1_) + r2_);
    metal::float3 c_2 = c1_ + (v * ((r0_ - r1_) / d));
    metal::float3 e1_ = c_2 - c1_;
    metal::float3 e2_ = c_2 - c2_;
    float r_1 = metal::max(r0_, metal::max(metal::sqrt(metal::dot(e1_, e1_)) + r1_, metal::sqrt(metal::dot(e2_, e2_)) + r2_));
    float _e82 = sphere_pad(r_1, c_2);
    return metal::float4(c_2.x, c_2.y, c_2.z, r_1 + _e82);
}

float range_radius(
    float extent,
    float r2_1
) {
    return extent + metal::sqrt(r2_1);
}

uint bsh_tail_key(
    float radius
) {
    uint _e1 = f32_to_bits(radius);
    return (_e1 & 2147483647u) >> 21u;
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

BshNode bsh_node(
    BshNodes nodes,
    uint i,
    device type_8 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshNode _e4 = bsh_nodes[i];
    return _e4;
}

bool bsh_in_tail(
    float extent_1,
    float r2_2,
    uint cut
) {
    float _e3 = range_radius(extent_1, r2_2);
    uint _e4 = bsh_tail_key(_e3);
    return _e4 >= cut;
}

BshNode bsh_leaf_refitted(
    BshNode node_1,
    metal::float4 bound,
    float r2_3,
    uint cut_1
) {
    BshNode leaf = {};
    bool _e5 = bsh_in_tail(bound.w, r2_3, cut_1);
    leaf = node_1;
    leaf.center = metal::float3(bound.x, bound.y, bound.z);
    float _e16 = range_radius(bound.w, _e5 ? 0.0 : r2_3);
    leaf.radius = _e16;
    leaf.extent = bound.w;
    leaf.light = (node_1.light & 2147483647u) | (_e5 ? BSH_TAIL : 0u);
    BshNode _e27 = leaf;
    return _e27;
}

metal::float4 bsh_pair_sphere(
    BshNode left,
    BshNode right
) {
    metal::float4 _e6 = sphere_union(left.center, left.radius, right.center, right.radius);
    return _e6;
}

float bsh_pair_extent(
    BshNode left_1,
    BshNode right_1,
    metal::float3 center
) {
    metal::float3 vl = left_1.center - center;
    metal::float3 vr = right_1.center - center;
    float a = metal::max(metal::sqrt(metal::dot(vl, vl)) + left_1.extent, metal::sqrt(metal::dot(vr, vr)) + right_1.extent);
    float _e16 = sphere_pad(a, center);
    return a + _e16;
}

float bsh_pair_range(
    BshNode left_2,
    BshNode right_2
) {
    float _e2 = bsh_range_bound(left_2);
    float _e3 = bsh_range_bound(right_2);
    return metal::max(_e2, _e3);
}

BshNode bsh_inner_refitted(
    BshNode node_2,
    BshNode left_3,
    BshNode right_3
) {
    BshNode inner = {};
    metal::float4 _e3 = bsh_pair_sphere(left_3, right_3);
    inner = node_2;
    inner.center = metal::float3(_e3.x, _e3.y, _e3.z);
    inner.radius = _e3.w;
    metal::float3 _e14 = inner.center;
    float _e15 = bsh_pair_extent(left_3, right_3, _e14);
    inner.extent = _e15;
    float _e17 = bsh_pair_range(left_3, right_3);
    uint _e18 = f32_to_bits(_e17);
    inner.light = _e18;
    BshNode _e19 = inner;
    return _e19;
}

BshNode bsh_family_refitted(
    BshNodes nodes_1,
    BshNode node_3,
    device type_8 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshNode acc = {};
    uint c_1 = {};
    BshNode _e3 = bsh_node(nodes_1, node_3.child, bsh_nodes, _buffer_sizes);
    BshNode _e5 = bsh_node(nodes_1, _e3.next, bsh_nodes, _buffer_sizes);
    BshNode _e6 = bsh_inner_refitted(node_3, _e3, _e5);
    acc = _e6;
    c_1 = _e5.next;
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e10 = c_1;
        if (_e10 != node_3.next) {
        } else {
            break;
        }
        {
            uint _e13 = c_1;
            BshNode _e14 = bsh_node(nodes_1, _e13, bsh_nodes, _buffer_sizes);
            BshNode _e15 = acc;
            BshNode _e16 = acc;
            BshNode _e17 = bsh_inner_refitted(_e15, _e16, _e14);
            acc = _e17;
            c_1 = _e14.next;
        }
    }
    BshNode _e19 = acc;
    return _e19;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, constant RefitParams& params [[user(fake0)]]
, device type_6 const& order [[user(fake0)]]
, device type_7 const& bounds [[user(fake0)]]
, device type_4 const& r2_4 [[user(fake0)]]
, device type_8& bsh_nodes [[user(fake0)]]
, device type_6 const& tail [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint _e4 = params.count;
    if (gid.x >= _e4) {
        return;
    }
    uint _e9 = params.first;
    uint i_1 = order[_e9 + gid.x];
    BshNode node_4 = bsh_nodes[i_1];
    if (node_4.child == BSH_NONE) {
        uint li = node_4.light & 2147483647u;
        metal::float4 _e27 = bounds[li];
        float _e30 = r2_4[li];
        uint _e33 = tail[0];
        BshNode _e34 = bsh_leaf_refitted(node_4, _e27, _e30, _e33);
        bsh_nodes[i_1] = _e34;
        return;
    }
    BshNode _e38 = bsh_family_refitted(BSH, node_4, bsh_nodes, _buffer_sizes);
    bsh_nodes[i_1] = _e38;
    return;
}
