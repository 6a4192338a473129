#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct TailParams {
    uint stage;
    uint count;
    uint k;
    uint tree;
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
const uint HIST = 0u;
const uint BSH_TAIL_CHUNK = 32u;

layout(std140) uniform TailParams_block_0Compute { TailParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_6_block_1Compute { vec4 _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_4_block_2Compute { float _group_0_binding_2_cs[]; };

layout(std430) buffer type_8_block_3Compute { uint _group_0_binding_3_cs[]; };

layout(std430) buffer type_8_block_4Compute { uint _group_0_binding_4_cs[]; };

layout(std430) buffer type_9_block_5Compute { BshNode _group_0_binding_5_cs[]; };

shared uint wg_bins[1024];

shared uint wg_chunks[32];


uint f32_to_bits(float x) {
    return floatBitsToUint(x);
}

float range_radius(float extent, float r2_) {
    return (extent + sqrt(r2_));
}

uint bsh_tail_key(float radius) {
    uint _e1 = f32_to_bits(radius);
    return ((_e1 & 2147483647u) >> 21u);
}

BshNode bsh_node(uint nodes, uint i) {
    BshNode _e4 = _group_0_binding_5_cs[i];
    return _e4;
}

bool bsh_in_tail(float extent_1, float r2_1, uint cut) {
    float _e3 = range_radius(extent_1, r2_1);
    uint _e4 = bsh_tail_key(_e3);
    return (_e4 >= cut);
}

uint bsh_rightmost_next(uint nodes_1, uint i_1) {
    uint c_2 = 0u;
    BshNode _e2 = bsh_node(nodes_1, i_1);
    if ((_e2.child == BSH_NONE)) {
        return BSH_NONE;
    }
    c_2 = _e2.child;
    while(true) {
        uint _e9 = c_2;
        BshNode _e10 = bsh_node(nodes_1, _e9);
        if ((_e10.next != _e2.next)) {
        } else {
            break;
        }
        {
            uint _e14 = c_2;
            BshNode _e15 = bsh_node(nodes_1, _e14);
            c_2 = _e15.next;
        }
    }
    uint _e17 = c_2;
    return _e17;
}

BshNode bsh_tail_leaf(BshNode slot, vec4 bound, float r2_2, uint li, uint next) {
    BshNode leaf = BshNode(vec3(0.0), 0.0, 0u, 0u, 0u, 0.0);
    leaf = slot;
    leaf.center = vec3(bound.x, bound.y, bound.z);
    float _e13 = range_radius(bound.w, r2_2);
    leaf.radius = _e13;
    leaf.child = BSH_NONE;
    leaf.next = next;
    leaf.light = li;
    leaf.extent = bound.w;
    BshNode _e20 = leaf;
    return _e20;
}

uint bsh_tail_bin(uint hist, uint b_3) {
    uint _e4 = wg_bins[b_3];
    return _e4;
}

uint bsh_tail_chunk(uint hist_1, uint c_3) {
    uint _e4 = wg_chunks[c_3];
    return _e4;
}

uint bsh_tail_cut(uint hist_2, uint k) {
    uint c_4 = 32u;
    uint sum_1 = 0u;
    bool local_2 = false;
    uint b_4 = 0u;
    bool local_3 = false;
    while(true) {
        uint _e6 = c_4;
        if ((_e6 > 0u)) {
            uint _e11 = sum_1;
            uint _e12 = c_4;
            uint _e15 = bsh_tail_chunk(hist_2, (_e12 - 1u));
            local_2 = ((_e11 + _e15) <= k);
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
            uint _e24 = bsh_tail_chunk(hist_2, (_e21 - 1u));
            sum_1 = (_e20 + _e24);
            uint _e26 = c_4;
            c_4 = (_e26 - 1u);
        }
    }
    uint _e29 = c_4;
    b_4 = (_e29 * BSH_TAIL_CHUNK);
    uint _e33 = b_4;
    uint _e34 = b_4;
    uint end = (_e33 - min(_e34, BSH_TAIL_CHUNK));
    while(true) {
        uint _e38 = b_4;
        if ((_e38 > end)) {
            uint _e42 = sum_1;
            uint _e43 = b_4;
            uint _e46 = bsh_tail_bin(hist_2, (_e43 - 1u));
            local_3 = ((_e42 + _e46) <= k);
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
            uint _e55 = bsh_tail_bin(hist_2, (_e52 - 1u));
            sum_1 = (_e51 + _e55);
            uint _e57 = b_4;
            b_4 = (_e57 - 1u);
        }
    }
    uint _e60 = b_4;
    return _e60;
}

uint tail_light(uint s_1) {
    uint _e5 = atomicOr(_group_0_binding_4_cs[(2u + s_1)], 0u);
    return _e5;
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_bins = uint[1024](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
        wg_chunks = uint[32](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    }
    memoryBarrierShared();
    barrier();
    uvec3 gid = gl_GlobalInvocationID;
    uint b = 0u;
    uint c = 0u;
    uint sum = 0u;
    uint b_1 = 0u;
    bool local = false;
    uint b_2 = 0u;
    uint a = 1u;
    uint c_1 = 0u;
    bool local_1 = false;
    uint s = 0u;
    uint n = 0u;
    uint i_2 = gid.x;
    uint _e4 = _group_0_binding_0_cs.stage;
    if ((_e4 == 1u)) {
        b = i_2;
        bool loop_init = true;
        while(true) {
            if (!loop_init) {
                uint _e18 = b;
                b = (_e18 + 64u);
            }
            loop_init = false;
            uint _e8 = b;
            if ((_e8 < BSH_TAIL_BINS)) {
            } else {
                break;
            }
            {
                uint _e12 = b;
                uint _e15 = b;
                uint _e17 = atomicOr(_group_0_binding_3_cs[_e15], 0u);
                wg_bins[_e12] = _e17;
            }
        }
        memoryBarrierShared();
        barrier();
        c = i_2;
        bool loop_init_1 = true;
        while(true) {
            if (!loop_init_1) {
                uint _e49 = c;
                c = (_e49 + 64u);
            }
            loop_init_1 = false;
            uint _e22 = c;
            if ((_e22 < 32u)) {
            } else {
                break;
            }
            {
                sum = 0u;
                b_1 = 0u;
                bool loop_init_2 = true;
                while(true) {
                    if (!loop_init_2) {
                        uint _e43 = b_1;
                        b_1 = (_e43 + 1u);
                    }
                    loop_init_2 = false;
                    uint _e29 = b_1;
                    if ((_e29 < BSH_TAIL_CHUNK)) {
                    } else {
                        break;
                    }
                    {
                        uint _e32 = sum;
                        uint _e34 = c;
                        uint _e37 = b_1;
                        uint _e40 = wg_bins[((_e34 * BSH_TAIL_CHUNK) + _e37)];
                        sum = (_e32 + _e40);
                    }
                }
                uint _e46 = c;
                uint _e48 = sum;
                wg_chunks[_e46] = _e48;
            }
        }
        memoryBarrierShared();
        barrier();
        if ((i_2 == 0u)) {
            uint _e59 = _group_0_binding_0_cs.k;
            uint _e60 = bsh_tail_cut(HIST, _e59);
            atomicExchange(_group_0_binding_4_cs[0], _e60);
            atomicExchange(_group_0_binding_4_cs[1], 0u);
        }
        return;
    }
    uint _e66 = _group_0_binding_0_cs.stage;
    switch(_e66) {
        case 0u: {
            uint _e69 = _group_0_binding_0_cs.count;
            if ((i_2 < _e69)) {
                float _e75 = _group_0_binding_1_cs[i_2].w;
                float _e78 = _group_0_binding_2_cs[i_2];
                float _e79 = range_radius(_e75, _e78);
                uint _e80 = bsh_tail_key(_e79);
                uint _e83 = atomicAdd(_group_0_binding_3_cs[_e80], 1u);
                return;
            } else {
                return;
            }
            break;
        }
        case 2u: {
            uint _e86 = _group_0_binding_0_cs.count;
            if ((i_2 < _e86)) {
                float _e93 = _group_0_binding_1_cs[i_2].w;
                float _e96 = _group_0_binding_2_cs[i_2];
                uint _e99 = atomicOr(_group_0_binding_4_cs[0], 0u);
                bool _e100 = bsh_in_tail(_e93, _e96, _e99);
                local = _e100;
            } else {
                local = false;
            }
            bool _e102 = local;
            if (_e102) {
                uint _e108 = atomicAdd(_group_0_binding_4_cs[1], 1u);
                atomicExchange(_group_0_binding_4_cs[(2u + _e108)], i_2);
                return;
            } else {
                return;
            }
            break;
        }
        default: {
            b_2 = i_2;
            bool loop_init_3 = true;
            while(true) {
                if (!loop_init_3) {
                    uint _e119 = b_2;
                    b_2 = (_e119 + 64u);
                }
                loop_init_3 = false;
                uint _e112 = b_2;
                if ((_e112 < BSH_TAIL_BINS)) {
                } else {
                    break;
                }
                {
                    uint _e116 = b_2;
                    atomicExchange(_group_0_binding_3_cs[_e116], 0u);
                }
            }
            if ((i_2 != 0u)) {
                return;
            }
            uint count = atomicOr(_group_0_binding_4_cs[1], 0u);
            bool loop_init_4 = true;
            while(true) {
                if (!loop_init_4) {
                    uint _e165 = a;
                    a = (_e165 + 1u);
                }
                loop_init_4 = false;
                uint _e129 = a;
                if ((_e129 < count)) {
                } else {
                    break;
                }
                {
                    uint _e131 = a;
                    uint _e132 = tail_light(_e131);
                    uint _e133 = a;
                    c_1 = _e133;
                    while(true) {
                        uint _e135 = c_1;
                        if ((_e135 > 0u)) {
                            uint _e140 = c_1;
                            uint _e143 = tail_light((_e140 - 1u));
                            local_1 = (_e143 > _e132);
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
                            uint _e155 = tail_light((_e152 - 1u));
                            atomicExchange(_group_0_binding_4_cs[(2u + _e149)], _e155);
                            uint _e156 = c_1;
                            c_1 = (_e156 - 1u);
                        }
                    }
                    uint _e161 = c_1;
                    atomicExchange(_group_0_binding_4_cs[(2u + _e161)], _e132);
                }
            }
            bool loop_init_5 = true;
            while(true) {
                if (!loop_init_5) {
                    uint _e199 = s;
                    s = (_e199 + 1u);
                }
                loop_init_5 = false;
                uint _e169 = s;
                if ((_e169 < count)) {
                } else {
                    break;
                }
                {
                    uint _e171 = s;
                    uint _e172 = tail_light(_e171);
                    uint _e175 = _group_0_binding_0_cs.tree;
                    uint _e176 = s;
                    uint at = (_e175 + _e176);
                    uint _e181 = s;
                    uint next_1 = (((_e181 + 1u) == count) ? BSH_NONE : (at + 1u));
                    BshNode _e190 = _group_0_binding_5_cs[at];
                    vec4 _e193 = _group_0_binding_1_cs[_e172];
                    float _e196 = _group_0_binding_2_cs[_e172];
                    BshNode _e197 = bsh_tail_leaf(_e190, _e193, _e196, _e172, next_1);
                    _group_0_binding_5_cs[at] = _e197;
                }
            }
            uint _e203 = _group_0_binding_0_cs.tree;
            uint first = ((count == 0u) ? BSH_NONE : _e203);
            while(true) {
                uint _e210 = n;
                if ((_e210 != BSH_NONE)) {
                } else {
                    break;
                }
                {
                    uint _e214 = n;
                    uint _e215 = bsh_rightmost_next(BSH, _e214);
                    uint _e217 = n;
                    _group_0_binding_5_cs[_e217].next = first;
                    n = _e215;
                }
            }
            return;
        }
    }
}

