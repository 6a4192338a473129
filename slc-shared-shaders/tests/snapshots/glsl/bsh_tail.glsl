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

layout(std140) uniform TailParams_block_0Compute { TailParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_6_block_1Compute { vec4 _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_4_block_2Compute { float _group_0_binding_2_cs[]; };

layout(std430) buffer type_8_block_3Compute { uint _group_0_binding_3_cs[]; };

layout(std430) buffer type_8_block_4Compute { uint _group_0_binding_4_cs[]; };

layout(std430) buffer type_9_block_5Compute { BshNode _group_0_binding_5_cs[]; };


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
    BshNode _e2 = bsh_node(nodes_1, i_1);
    if ((_e2.child == BSH_NONE)) {
        return BSH_NONE;
    }
    BshNode _e8 = bsh_node(nodes_1, _e2.child);
    return _e8.next;
}

uint bsh_tail_bin(uint hist, uint b_1) {
    uint _e4 = atomicOr(_group_0_binding_3_cs[b_1], 0u);
    return _e4;
}

uint bsh_tail_cut(uint hist_1, uint k) {
    uint b_2 = BSH_TAIL_BINS;
    uint sum = 0u;
    bool local_2 = false;
    while(true) {
        uint _e6 = b_2;
        if ((_e6 > 0u)) {
            uint _e11 = sum;
            uint _e12 = b_2;
            uint _e15 = bsh_tail_bin(hist_1, (_e12 - 1u));
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
            uint _e20 = sum;
            uint _e21 = b_2;
            uint _e24 = bsh_tail_bin(hist_1, (_e21 - 1u));
            sum = (_e20 + _e24);
            uint _e26 = b_2;
            b_2 = (_e26 - 1u);
        }
    }
    uint _e29 = b_2;
    return _e29;
}

uint tail_light(uint s_1) {
    uint _e5 = atomicOr(_group_0_binding_4_cs[(2u + s_1)], 0u);
    return _e5;
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    bool local = false;
    uint b = 0u;
    uint a = 1u;
    uint c = 0u;
    bool local_1 = false;
    uint s = 0u;
    uint n = 0u;
    uint i_2 = gid.x;
    uint _e4 = _group_0_binding_0_cs.stage;
    switch(_e4) {
        case 0u: {
            uint _e7 = _group_0_binding_0_cs.count;
            if ((i_2 < _e7)) {
                float _e13 = _group_0_binding_1_cs[i_2].w;
                float _e16 = _group_0_binding_2_cs[i_2];
                float _e17 = range_radius(_e13, _e16);
                uint _e18 = bsh_tail_key(_e17);
                uint _e21 = atomicAdd(_group_0_binding_3_cs[_e18], 1u);
                return;
            } else {
                return;
            }
            break;
        }
        case 1u: {
            if ((i_2 == 0u)) {
                uint _e29 = _group_0_binding_0_cs.k;
                uint _e30 = bsh_tail_cut(HIST, _e29);
                atomicExchange(_group_0_binding_4_cs[0], _e30);
                atomicExchange(_group_0_binding_4_cs[1], 0u);
                return;
            } else {
                return;
            }
            break;
        }
        case 2u: {
            uint _e36 = _group_0_binding_0_cs.count;
            if ((i_2 < _e36)) {
                float _e43 = _group_0_binding_1_cs[i_2].w;
                float _e46 = _group_0_binding_2_cs[i_2];
                uint _e49 = atomicOr(_group_0_binding_4_cs[0], 0u);
                bool _e50 = bsh_in_tail(_e43, _e46, _e49);
                local = _e50;
            } else {
                local = false;
            }
            bool _e52 = local;
            if (_e52) {
                uint _e58 = atomicAdd(_group_0_binding_4_cs[1], 1u);
                atomicExchange(_group_0_binding_4_cs[(2u + _e58)], i_2);
                return;
            } else {
                return;
            }
            break;
        }
        default: {
            b = i_2;
            bool loop_init = true;
            while(true) {
                if (!loop_init) {
                    uint _e69 = b;
                    b = (_e69 + 64u);
                }
                loop_init = false;
                uint _e62 = b;
                if ((_e62 < BSH_TAIL_BINS)) {
                } else {
                    break;
                }
                {
                    uint _e66 = b;
                    atomicExchange(_group_0_binding_3_cs[_e66], 0u);
                }
            }
            if ((i_2 != 0u)) {
                return;
            }
            uint count = atomicOr(_group_0_binding_4_cs[1], 0u);
            bool loop_init_1 = true;
            while(true) {
                if (!loop_init_1) {
                    uint _e115 = a;
                    a = (_e115 + 1u);
                }
                loop_init_1 = false;
                uint _e79 = a;
                if ((_e79 < count)) {
                } else {
                    break;
                }
                {
                    uint _e81 = a;
                    uint _e82 = tail_light(_e81);
                    uint _e83 = a;
                    c = _e83;
                    while(true) {
                        uint _e85 = c;
                        if ((_e85 > 0u)) {
                            uint _e90 = c;
                            uint _e93 = tail_light((_e90 - 1u));
                            local_1 = (_e93 > _e82);
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
                            uint _e105 = tail_light((_e102 - 1u));
                            atomicExchange(_group_0_binding_4_cs[(2u + _e99)], _e105);
                            uint _e106 = c;
                            c = (_e106 - 1u);
                        }
                    }
                    uint _e111 = c;
                    atomicExchange(_group_0_binding_4_cs[(2u + _e111)], _e82);
                }
            }
            bool loop_init_2 = true;
            while(true) {
                if (!loop_init_2) {
                    uint _e156 = s;
                    s = (_e156 + 1u);
                }
                loop_init_2 = false;
                uint _e119 = s;
                if ((_e119 < count)) {
                } else {
                    break;
                }
                {
                    uint _e121 = s;
                    uint _e122 = tail_light(_e121);
                    vec4 b_3 = _group_0_binding_1_cs[_e122];
                    uint _e128 = _group_0_binding_0_cs.tree;
                    uint _e129 = s;
                    uint _e134 = s;
                    uint next = (((_e134 + 1u) == count) ? BSH_NONE : ((_e128 + _e129) + 1u));
                    uint _e142 = _group_0_binding_0_cs.tree;
                    uint _e143 = s;
                    float _e150 = _group_0_binding_2_cs[_e122];
                    float _e151 = range_radius(b_3.w, _e150);
                    _group_0_binding_5_cs[(_e142 + _e143)] = BshNode(b_3.xyz, _e151, BSH_NONE, next, _e122, b_3.w);
                }
            }
            uint _e160 = _group_0_binding_0_cs.tree;
            uint first = ((count == 0u) ? BSH_NONE : _e160);
            bool loop_init_3 = true;
            while(true) {
                if (!loop_init_3) {
                    uint _e175 = n;
                    uint _e176 = bsh_rightmost_next(BSH, _e175);
                    n = _e176;
                }
                loop_init_3 = false;
                uint _e167 = n;
                if ((_e167 != BSH_NONE)) {
                } else {
                    break;
                }
                {
                    uint _e171 = n;
                    _group_0_binding_5_cs[_e171].next = first;
                }
            }
            return;
        }
    }
}

