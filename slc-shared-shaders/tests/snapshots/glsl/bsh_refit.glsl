#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct RefitParams {
    uint first;
    uint count;
    uint pad0_;
    uint pad1_;
};
struct BshNode {
    vec3 center;
    float radius;
    uint child;
    uint next;
    uint light;
    float extent;
};
const uint LIGHT_POINT = 0u;
const uint LIGHT_SPOT = 1u;
const uint LIGHT_IES = 2u;
const uint LIGHT_TRIANGLE = 3u;
const uint LIGHT_VPL = 4u;
const uint NO_LIGHT = 4294967295u;
const uint GRID_HEADER = 32u;
const uint GRID_LEVELS_MAX = 8u;
const uint GRIDS_MAX = 3u;
const uint GRID_SORT_MOVES = 1024u;
const uint GRID_SORT_MAX = 1024u;
const uint COUNT_TILES = 0u;
const uint COUNT_GROUP_TESTS = 1u;
const uint COUNT_CLUSTER_TESTS = 2u;
const uint COUNT_SPHERE_TESTS = 3u;
const uint COUNT_TESTED = 4u;
const uint COUNT_KEPT = 5u;
const uint COUNT_PIXELS = 6u;
const uint COUNT_FIELDS = 7u;
const uint DIRECT_COUNT_PIXELS = 0u;
const uint DIRECT_COUNT_CANDIDATES = 1u;
const uint DIRECT_COUNT_EVALUATIONS = 2u;
const uint DIRECT_COUNT_RAYS = 3u;
const uint DIRECT_COUNT_NODES = 4u;
const uint DIRECT_COUNT_FIELDS = 5u;
const uint MAP_CAMERA = 0u;
const uint MAP_PERSPECTIVE = 1u;
const uint MAP_ORTHOGRAPHIC = 2u;
const float XI_STEP = 5.9604645e-8;
const uint XI_ROTATED = 2147483648u;
const uint XI_BITS_SHIFT = 26u;
const uint XI_INDEX_MASK = 67108863u;
const uint PICK_STREAM = 2654435769u;
const float TWO_PI = 6.2831855;
const float UNRANGED = 1e38;
const float CULL_RADIUS_SCALE = 1.000001;
const float SPHERE_PAD = 4.7683716e-7;
const float SPHERE_HUGE = 3.4028235e38;
const float SPHERE_PAD_ABS = 1e-18;
const uint CLUSTER = 64u;
const uint GROUP_SIDE = 8u;
const float INV_PI = 0.31830987;
const float MIN_D2_ = 1e-12;
const float MAX_INTENSITY = 7.2057594e16;
const uint BSH_NONE = 4294967295u;
const uint BSH_TAIL = 2147483648u;
const uint BSH_TAIL_BINS = 1024u;
const uint BSH_TAIL_MAX = 64u;
const uint RESERVOIR_FULL = 4294967295u;
const float REUSE_TRUST_SCALE = 64.0;
const float GGX_ALPHA_MIN = 0.001;
const float RANGE_SCALE_MAX = 64.0;
const uint LIGHT_BVH_LEAF = 4294967295u;
const float ONE_MINUS_EPSILON = 0.99999994;
const float F32_MAX = 3.4028235e38;
const float DEPTH_NONE = 1e30;
const float DEPTH_SIGMA = 0.05;
const float COVER_WEIGHT = 0.1;
const uint ROULETTE_DEPTH = 2u;
const float TEMPORAL_MAX_HISTORY = 32.0;
const float TEMPORAL_DEPTH_TOLERANCE = 0.01;
const float TEMPORAL_MOTION_DEPTH_TOLERANCE = 0.05;
const float TEMPORAL_NORMAL_COS = 0.9;
const float TEMPORAL_MIN_MOMENTS = 8.0;
const float TEMPORAL_CHANGED_HISTORY = 1.0;
const float TEMPORAL_CHANGE_LOW = 4.0;
const float TEMPORAL_CHANGE_HIGH = 8.0;
const float TEMPORAL_MIN_WEIGHT = 0.01;
const uint BSH = 0u;
const uint BSH_TILE_DEPTH = 8u;
const uint BSH_TILE_SUBTREES = 256u;

layout(std140) uniform RefitParams_block_0Compute { RefitParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_6_block_1Compute { uint _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_7_block_2Compute { vec4 _group_0_binding_2_cs[]; };

layout(std430) readonly buffer type_4_block_3Compute { float _group_0_binding_3_cs[]; };

layout(std430) buffer type_8_block_4Compute { BshNode _group_0_binding_4_cs[]; };

layout(std430) readonly buffer type_6_block_5Compute { uint _group_0_binding_5_cs[]; };


float f32_from_bits(uint u) {
    return uintBitsToFloat(u);
}

uint f32_to_bits(float x) {
    return floatBitsToUint(x);
}

float sphere_pad(float r, vec3 c) {
    return (((r + max(abs(c.x), max(abs(c.y), abs(c.z)))) * SPHERE_PAD) + SPHERE_PAD_ABS);
}

vec4 sphere_union(vec3 c1_, float r1_, vec3 c2_, float r2_) {
    bool local = false;
    vec3 v = (c2_ - c1_);
    float d = sqrt(dot(v, v));
    float _e8 = sphere_pad(r1_, c1_);
    if ((r1_ >= ((d + r2_) + _e8))) {
        return vec4(c1_.x, c1_.y, c1_.z, r1_);
    }
    float _e16 = sphere_pad(r2_, c2_);
    if ((r2_ >= ((d + r1_) + _e16))) {
        return vec4(c2_.x, c2_.y, c2_.z, r2_);
    }
    if (!((d >= SPHERE_HUGE))) {
        local = ((0.5 * ((d + r1_) + r2_)) >= SPHERE_HUGE);
    } else {
        local = true;
    }
    bool _e35 = local;
    if (_e35) {
        return vec4(c1_.x, c1_.y, c1_.z, SPHERE_HUGE);
    }
    if ((abs((r1_ - r2_)) >= d)) {
        if ((r1_ >= r2_)) {
            float rn = max(r1_, (d + r2_));
            float _e50 = sphere_pad(rn, c1_);
            return vec4(c1_.x, c1_.y, c1_.z, (rn + _e50));
        }
        float rm = max(r2_, (d + r1_));
        float _e58 = sphere_pad(rm, c2_);
        return vec4(c2_.x, c2_.y, c2_.z, (rm + _e58));
    }
    float r0_ = (0.5 * ((d + r1_) + r2_));
    vec3 c_2 = (c1_ + (v * ((r0_ - r1_) / d)));
    vec3 e1_ = (c_2 - c1_);
    vec3 e2_ = (c_2 - c2_);
    float r_1 = max(r0_, max((sqrt(dot(e1_, e1_)) + r1_), (sqrt(dot(e2_, e2_)) + r2_)));
    float _e82 = sphere_pad(r_1, c_2);
    return vec4(c_2.x, c_2.y, c_2.z, (r_1 + _e82));
}

float range_radius(float extent, float r2_1) {
    return (extent + sqrt(r2_1));
}

uint bsh_tail_key(float radius) {
    uint _e1 = f32_to_bits(radius);
    return ((_e1 & 2147483647u) >> 21u);
}

float bsh_range_bound(BshNode node) {
    if ((node.child == BSH_NONE)) {
        return (node.radius - node.extent);
    }
    float _e8 = f32_from_bits(node.light);
    return _e8;
}

BshNode bsh_node(uint nodes, uint i) {
    BshNode _e4 = _group_0_binding_4_cs[i];
    return _e4;
}

bool bsh_in_tail(float extent_1, float r2_2, uint cut) {
    float _e3 = range_radius(extent_1, r2_2);
    uint _e4 = bsh_tail_key(_e3);
    return (_e4 >= cut);
}

BshNode bsh_leaf_refitted(BshNode node_1, vec4 bound, float r2_3, uint cut_1) {
    BshNode leaf = BshNode(vec3(0.0), 0.0, 0u, 0u, 0u, 0.0);
    bool _e5 = bsh_in_tail(bound.w, r2_3, cut_1);
    leaf = node_1;
    leaf.center = vec3(bound.x, bound.y, bound.z);
    float _e16 = range_radius(bound.w, (_e5 ? 0.0 : r2_3));
    leaf.radius = _e16;
    leaf.extent = bound.w;
    leaf.light = ((node_1.light & 2147483647u) | (_e5 ? BSH_TAIL : 0u));
    BshNode _e27 = leaf;
    return _e27;
}

vec4 bsh_pair_sphere(BshNode left, BshNode right) {
    vec4 _e6 = sphere_union(left.center, left.radius, right.center, right.radius);
    return _e6;
}

float bsh_pair_extent(BshNode left_1, BshNode right_1, vec3 center) {
    vec3 vl = (left_1.center - center);
    vec3 vr = (right_1.center - center);
    float a = max((sqrt(dot(vl, vl)) + left_1.extent), (sqrt(dot(vr, vr)) + right_1.extent));
    float _e16 = sphere_pad(a, center);
    return (a + _e16);
}

float bsh_pair_range(BshNode left_2, BshNode right_2) {
    float _e2 = bsh_range_bound(left_2);
    float _e3 = bsh_range_bound(right_2);
    return max(_e2, _e3);
}

BshNode bsh_inner_refitted(BshNode node_2, BshNode left_3, BshNode right_3) {
    BshNode inner = BshNode(vec3(0.0), 0.0, 0u, 0u, 0u, 0.0);
    vec4 _e3 = bsh_pair_sphere(left_3, right_3);
    inner = node_2;
    inner.center = vec3(_e3.x, _e3.y, _e3.z);
    inner.radius = _e3.w;
    vec3 _e14 = inner.center;
    float _e15 = bsh_pair_extent(left_3, right_3, _e14);
    inner.extent = _e15;
    float _e17 = bsh_pair_range(left_3, right_3);
    uint _e18 = f32_to_bits(_e17);
    inner.light = _e18;
    BshNode _e19 = inner;
    return _e19;
}

BshNode bsh_family_refitted(uint nodes_1, BshNode node_3) {
    BshNode acc = BshNode(vec3(0.0), 0.0, 0u, 0u, 0u, 0.0);
    uint c_1 = 0u;
    BshNode _e3 = bsh_node(nodes_1, node_3.child);
    BshNode _e5 = bsh_node(nodes_1, _e3.next);
    BshNode _e6 = bsh_inner_refitted(node_3, _e3, _e5);
    acc = _e6;
    c_1 = _e5.next;
    while(true) {
        uint _e10 = c_1;
        if ((_e10 != node_3.next)) {
        } else {
            break;
        }
        {
            uint _e13 = c_1;
            BshNode _e14 = bsh_node(nodes_1, _e13);
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

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    uint _e4 = _group_0_binding_0_cs.count;
    if ((gid.x >= _e4)) {
        return;
    }
    uint _e9 = _group_0_binding_0_cs.first;
    uint i_1 = _group_0_binding_1_cs[(_e9 + gid.x)];
    BshNode node_4 = _group_0_binding_4_cs[i_1];
    if ((node_4.child == BSH_NONE)) {
        uint li = (node_4.light & 2147483647u);
        vec4 _e27 = _group_0_binding_2_cs[li];
        float _e30 = _group_0_binding_3_cs[li];
        uint _e33 = _group_0_binding_5_cs[0];
        BshNode _e34 = bsh_leaf_refitted(node_4, _e27, _e30, _e33);
        _group_0_binding_4_cs[i_1] = _e34;
        return;
    }
    BshNode _e38 = bsh_family_refitted(BSH, node_4);
    _group_0_binding_4_cs[i_1] = _e38;
    return;
}

