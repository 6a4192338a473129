#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

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
    vec3 center;
    float radius;
    uint child;
    uint next;
    uint light;
    float extent;
};
struct GridFrame {
    vec3 lo;
    uint nx;
    vec3 hi;
    uint ny;
    vec3 inv;
    uint nz;
};
const uint LIGHT_POINT = 0u;
const uint LIGHT_SPOT = 1u;
const uint LIGHT_IES = 2u;
const uint LIGHT_TRIANGLE = 3u;
const uint LIGHT_VPL = 4u;
const uint NO_LIGHT = 4294967295u;
const uint GRID_HEADER = 32u;
const uint GRID_LEVELS_MAX = 8u;
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
const uint GRID_ENTRIES_PER_LIGHT = 8u;

layout(std140) uniform GridParams_block_0Compute { GridParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_4_block_1Compute { BshNode _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_5_block_2Compute { uint _group_0_binding_2_cs[]; };

layout(std430) readonly buffer type_6_block_3Compute { GridFrame _group_0_binding_3_cs[]; };

layout(std430) buffer type_8_block_4Compute { uint _group_0_binding_4_cs[]; };

layout(std430) buffer type_8_block_5Compute { uint _group_0_binding_5_cs[]; };

layout(std430) buffer type_5_block_6Compute { uint _group_0_binding_6_cs[]; };

shared uint wg_sums[64];


uint to_u32_(float x_1) {
    return uint(x_1);
}

uint add_wrap_u32_(uint a, uint b) {
    return (a + b);
}

float f32_from_bits(uint u) {
    return uintBitsToFloat(u);
}

float bsh_range_bound(BshNode node) {
    if ((node.child == BSH_NONE)) {
        return (node.radius - node.extent);
    }
    float _e8 = f32_from_bits(node.light);
    return _e8;
}

float bsh_reach_bound(BshNode node_1, float w) {
    float _e5 = bsh_range_bound(node_1);
    return (node_1.extent + ((w * 1.001) * _e5));
}

uint bsh_grid_budget(uint leaves, uint cells) {
    if ((leaves > 536870911u)) {
        return 4294967295u;
    }
    uint e = (leaves * GRID_ENTRIES_PER_LIGHT);
    uint _e7 = add_wrap_u32_(e, cells);
    return ((_e7 < e) ? 4294967295u : _e7);
}

float bsh_grid_reach(BshNode node_2, float w_1) {
    if ((w_1 > 1.0)) {
        float _e5 = bsh_reach_bound(node_2, w_1);
        return max(node_2.radius, _e5);
    }
    return node_2.radius;
}

float bsh_grid_pad(float reach) {
    if ((reach > 1e19)) {
        return 3.4028235e38;
    }
    return ((reach * 1.00001) + 1e-22);
}

uint bsh_grid_axis(float v, float lo, float inv, uint n) {
    uint _e8 = to_u32_(max(((v - lo) * inv), 0.0));
    return min(_e8, (n - 1u));
}

float bsh_grid_radius(BshNode node_3, float w_2) {
    float _e2 = bsh_grid_reach(node_3, w_2);
    float _e3 = bsh_grid_pad(_e2);
    return _e3;
}

uvec3 bsh_grid_first(GridFrame f_1, vec3 c_3, float r) {
    uint _e10 = bsh_grid_axis((c_3.x - r), f_1.lo.x, f_1.inv.x, f_1.nx);
    uint _e18 = bsh_grid_axis((c_3.y - r), f_1.lo.y, f_1.inv.y, f_1.ny);
    uint _e26 = bsh_grid_axis((c_3.z - r), f_1.lo.z, f_1.inv.z, f_1.nz);
    return uvec3(_e10, _e18, _e26);
}

uvec3 bsh_grid_last(GridFrame f_2, vec3 c_4, float r_1) {
    uint _e10 = bsh_grid_axis((c_4.x + r_1), f_2.lo.x, f_2.inv.x, f_2.nx);
    uint _e18 = bsh_grid_axis((c_4.y + r_1), f_2.lo.y, f_2.inv.y, f_2.ny);
    uint _e26 = bsh_grid_axis((c_4.z + r_1), f_2.lo.z, f_2.inv.z, f_2.nz);
    return uvec3(_e10, _e18, _e26);
}

uint grid_word(uint i) {
    uint _e3 = atomicOr(_group_0_binding_4_cs[i], 0u);
    return _e3;
}

GridFrame grid_frame(uint h) {
    GridFrame f_3 = GridFrame(vec3(0.0), 0u, vec3(0.0), 0u, vec3(0.0), 0u);
    uint _e3 = grid_word(h);
    uint _e7 = grid_word((h + 1u));
    uint _e11 = grid_word((h + 2u));
    f_3.lo = vec3(uintBitsToFloat(_e3), uintBitsToFloat(_e7), uintBitsToFloat(_e11));
    uint _e17 = grid_word((h + 3u));
    f_3.nx = _e17;
    uint _e21 = grid_word((h + 4u));
    uint _e25 = grid_word((h + 5u));
    uint _e29 = grid_word((h + 6u));
    f_3.hi = vec3(uintBitsToFloat(_e21), uintBitsToFloat(_e25), uintBitsToFloat(_e29));
    uint _e35 = grid_word((h + 7u));
    f_3.ny = _e35;
    uint _e39 = grid_word((h + 8u));
    uint _e43 = grid_word((h + 9u));
    uint _e47 = grid_word((h + 10u));
    f_3.inv = vec3(uintBitsToFloat(_e39), uintBitsToFloat(_e43), uintBitsToFloat(_e47));
    uint _e53 = grid_word((h + 11u));
    f_3.nz = _e53;
    GridFrame _e54 = f_3;
    return _e54;
}

uint grid_leaf(uint i_1) {
    uint node_4 = _group_0_binding_2_cs[i_1];
    uint _e7 = _group_0_binding_1_cs[node_4].light;
    if (((_e7 & BSH_TAIL) != 0u)) {
        return BSH_NONE;
    }
    return node_4;
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_sums = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    }
    memoryBarrierShared();
    barrier();
    uvec3 gid = gl_GlobalInvocationID;
    uint sum = 0u;
    uint c = 0u;
    uint start = 0u;
    uint j = 0u;
    uint c_1 = 0u;
    uint l = 0u;
    uint chosen = 0u;
    uint l_1 = 0u;
    bool local = false;
    bool local_1 = false;
    GridFrame f = GridFrame(vec3(0.0), 0u, vec3(0.0), 0u, vec3(0.0), 0u);
    bool local_2 = false;
    uint z = 0u;
    uint y = 0u;
    uint x = 0u;
    uint s = 0u;
    uint c_2 = 0u;
    bool local_3 = false;
    uint s_1 = 0u;
    uint i_2 = gid.x;
    uint h_1 = _group_0_binding_0_cs.header;
    uint starts = (h_1 + GRID_HEADER);
    uint _e9 = _group_0_binding_0_cs.stage;
    if ((_e9 == 3u)) {
        GridFrame _e12 = grid_frame(h_1);
        uint cells_1 = ((_e12.nx * _e12.ny) * _e12.nz);
        uint run = (((cells_1 + 64u) - 1u) / 64u);
        uint a_1 = min((i_2 * run), cells_1);
        uint b_1 = min((a_1 + run), cells_1);
        c = a_1;
        bool loop_init = true;
        while(true) {
            if (!loop_init) {
                uint _e44 = c;
                c = (_e44 + 1u);
            }
            loop_init = false;
            uint _e31 = c;
            if ((_e31 < b_1)) {
            } else {
                break;
            }
            {
                uint _e33 = sum;
                uint _e37 = _group_0_binding_0_cs.fill;
                uint _e38 = c;
                uint _e41 = atomicOr(_group_0_binding_5_cs[(_e37 + _e38)], 0u);
                sum = (_e33 + _e41);
            }
        }
        uint _e48 = sum;
        wg_sums[i_2] = _e48;
        memoryBarrierShared();
        barrier();
        uint _e51 = _group_0_binding_0_cs.entries;
        start = _e51;
        bool loop_init_1 = true;
        while(true) {
            if (!loop_init_1) {
                uint _e64 = j;
                j = (_e64 + 1u);
            }
            loop_init_1 = false;
            uint _e55 = j;
            if ((_e55 < i_2)) {
            } else {
                break;
            }
            {
                uint _e57 = start;
                uint _e59 = j;
                uint _e61 = wg_sums[_e59];
                start = (_e57 + _e61);
            }
        }
        c_1 = a_1;
        bool loop_init_2 = true;
        while(true) {
            if (!loop_init_2) {
                uint _e93 = c_1;
                c_1 = (_e93 + 1u);
            }
            loop_init_2 = false;
            uint _e67 = c_1;
            if ((_e67 < b_1)) {
            } else {
                break;
            }
            {
                uint _e72 = _group_0_binding_0_cs.fill;
                uint _e73 = c_1;
                uint n_1 = atomicOr(_group_0_binding_5_cs[(_e72 + _e73)], 0u);
                uint _e78 = c_1;
                uint _e81 = start;
                atomicExchange(_group_0_binding_4_cs[(starts + _e78)], _e81);
                uint _e85 = _group_0_binding_0_cs.fill;
                uint _e86 = c_1;
                uint _e89 = start;
                atomicExchange(_group_0_binding_5_cs[(_e85 + _e86)], _e89);
                uint _e90 = start;
                start = (_e90 + n_1);
            }
        }
        if (((i_2 + 1u) == 64u)) {
            uint _e102 = start;
            atomicExchange(_group_0_binding_4_cs[(starts + cells_1)], _e102);
        }
        return;
    }
    uint _e105 = _group_0_binding_0_cs.stage;
    switch(_e105) {
        case 0u: {
            uint _e108 = _group_0_binding_0_cs.count;
            if ((i_2 >= _e108)) {
                return;
            }
            uint _e110 = grid_leaf(i_2);
            if ((_e110 == BSH_NONE)) {
                return;
            }
            uint _e118 = atomicAdd(_group_0_binding_4_cs[(h_1 + 13u)], 1u);
            BshNode leaf = _group_0_binding_1_cs[_e110];
            float _e124 = _group_0_binding_0_cs.reach;
            float _e125 = bsh_grid_radius(leaf, _e124);
            bool loop_init_3 = true;
            while(true) {
                if (!loop_init_3) {
                    uint _e172 = l;
                    l = (_e172 + 1u);
                }
                loop_init_3 = false;
                uint _e128 = l;
                uint _e131 = _group_0_binding_0_cs.levels;
                if ((_e128 < _e131)) {
                } else {
                    break;
                }
                {
                    uint _e134 = l;
                    GridFrame _e136 = _group_0_binding_3_cs[_e134];
                    uvec3 _e138 = bsh_grid_last(_e136, leaf.center, _e125);
                    uint _e140 = l;
                    GridFrame _e142 = _group_0_binding_3_cs[_e140];
                    uvec3 _e144 = bsh_grid_first(_e142, leaf.center, _e125);
                    uvec3 d = ((_e138 - _e144) + uvec3(1u));
                    uint n_2 = ((d.x * d.y) * d.z);
                    uint _e157 = l;
                    uint at = ((h_1 + 16u) + (2u * _e157));
                    uint _e162 = atomicAdd(_group_0_binding_4_cs[at], n_2);
                    if (((_e162 + n_2) < _e162)) {
                        uint _e170 = atomicAdd(_group_0_binding_4_cs[(at + 1u)], 1u);
                    }
                }
            }
            return;
        }
        case 1u: {
            if ((i_2 != 0u)) {
                return;
            }
            uint leaves_1 = atomicOr(_group_0_binding_4_cs[(h_1 + 13u)], 0u);
            uint _e183 = _group_0_binding_0_cs.levels;
            chosen = _e183;
            bool loop_init_4 = true;
            while(true) {
                if (!loop_init_4) {
                    uint _e246 = l_1;
                    l_1 = (_e246 + 1u);
                }
                loop_init_4 = false;
                uint _e187 = l_1;
                uint _e190 = _group_0_binding_0_cs.levels;
                if ((_e187 < _e190)) {
                } else {
                    break;
                }
                {
                    uint _e193 = l_1;
                    GridFrame f_4 = _group_0_binding_3_cs[_e193];
                    uint cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    uint _e201 = bsh_grid_budget(leaves_1, cells_2);
                    uint _e204 = _group_0_binding_0_cs.capacity;
                    uint budget = min(_e201, _e204);
                    uint _e209 = l_1;
                    uint at_1 = ((h_1 + 16u) + (2u * _e209));
                    uint _e212 = chosen;
                    uint _e215 = _group_0_binding_0_cs.levels;
                    if ((_e212 == _e215)) {
                        uint _e223 = atomicOr(_group_0_binding_4_cs[(at_1 + 1u)], 0u);
                        local = (_e223 == 0u);
                    } else {
                        local = false;
                    }
                    bool _e227 = local;
                    if (_e227) {
                        uint _e232 = atomicOr(_group_0_binding_4_cs[at_1], 0u);
                        local_1 = (_e232 <= budget);
                    } else {
                        local_1 = false;
                    }
                    bool _e235 = local_1;
                    if (_e235) {
                        uint _e236 = l_1;
                        chosen = _e236;
                    }
                    atomicExchange(_group_0_binding_4_cs[at_1], 0u);
                    atomicExchange(_group_0_binding_4_cs[(at_1 + 1u)], 0u);
                }
            }
            atomicExchange(_group_0_binding_4_cs[(h_1 + 13u)], 0u);
            uint _e254 = chosen;
            uint _e257 = _group_0_binding_0_cs.levels;
            if ((_e254 < _e257)) {
                uint _e260 = chosen;
                GridFrame _e262 = _group_0_binding_3_cs[_e260];
                f = _e262;
            }
            float _e267 = f.lo.x;
            atomicExchange(_group_0_binding_4_cs[h_1], floatBitsToUint(_e267));
            float _e275 = f.lo.y;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 1u)], floatBitsToUint(_e275));
            float _e283 = f.lo.z;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 2u)], floatBitsToUint(_e283));
            uint _e290 = f.nx;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 3u)], _e290);
            float _e297 = f.hi.x;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 4u)], floatBitsToUint(_e297));
            float _e305 = f.hi.y;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 5u)], floatBitsToUint(_e305));
            float _e313 = f.hi.z;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 6u)], floatBitsToUint(_e313));
            uint _e320 = f.ny;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 7u)], _e320);
            float _e327 = f.inv.x;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 8u)], floatBitsToUint(_e327));
            float _e335 = f.inv.y;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 9u)], floatBitsToUint(_e335));
            float _e343 = f.inv.z;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 10u)], floatBitsToUint(_e343));
            uint _e350 = f.nz;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 11u)], _e350);
            float _e357 = _group_0_binding_0_cs.reach;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 12u)], floatBitsToUint(_e357));
            return;
        }
        case 2u:
        case 4u: {
            uint _e361 = _group_0_binding_0_cs.count;
            if ((i_2 >= _e361)) {
                return;
            }
            GridFrame _e363 = grid_frame(h_1);
            uint _e364 = grid_leaf(i_2);
            if (!((_e363.nx == 0u))) {
                local_2 = (_e364 == BSH_NONE);
            } else {
                local_2 = true;
            }
            bool _e374 = local_2;
            if (_e374) {
                return;
            }
            BshNode leaf_1 = _group_0_binding_1_cs[_e364];
            float _e380 = _group_0_binding_0_cs.reach;
            float _e381 = bsh_grid_radius(leaf_1, _e380);
            uvec3 _e383 = bsh_grid_first(_e363, leaf_1.center, _e381);
            uvec3 _e385 = bsh_grid_last(_e363, leaf_1.center, _e381);
            z = _e383.z;
            bool loop_init_5 = true;
            while(true) {
                if (!loop_init_5) {
                    uint _e432 = z;
                    z = (_e432 + 1u);
                }
                loop_init_5 = false;
                uint _e388 = z;
                if ((_e388 <= _e385.z)) {
                } else {
                    break;
                }
                {
                    y = _e383.y;
                    bool loop_init_6 = true;
                    while(true) {
                        if (!loop_init_6) {
                            uint _e429 = y;
                            y = (_e429 + 1u);
                        }
                        loop_init_6 = false;
                        uint _e393 = y;
                        if ((_e393 <= _e385.y)) {
                        } else {
                            break;
                        }
                        {
                            x = _e383.x;
                            bool loop_init_7 = true;
                            while(true) {
                                if (!loop_init_7) {
                                    uint _e426 = x;
                                    x = (_e426 + 1u);
                                }
                                loop_init_7 = false;
                                uint _e398 = x;
                                if ((_e398 <= _e385.x)) {
                                } else {
                                    break;
                                }
                                {
                                    uint _e401 = z;
                                    uint _e404 = y;
                                    uint _e408 = x;
                                    uint c_5 = ((((_e401 * _e363.ny) + _e404) * _e363.nx) + _e408);
                                    uint _e413 = _group_0_binding_0_cs.fill;
                                    uint _e417 = atomicAdd(_group_0_binding_5_cs[(_e413 + c_5)], 1u);
                                    uint _e420 = _group_0_binding_0_cs.stage;
                                    if ((_e420 == 4u)) {
                                        _group_0_binding_6_cs[_e417] = i_2;
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
            GridFrame _e434 = grid_frame(h_1);
            if ((i_2 >= ((_e434.nx * _e434.ny) * _e434.nz))) {
                return;
            }
            uint _e444 = _group_0_binding_0_cs.fill;
            atomicExchange(_group_0_binding_5_cs[(_e444 + i_2)], 0u);
            uint a_2 = atomicOr(_group_0_binding_4_cs[(starts + i_2)], 0u);
            uint b_2 = atomicOr(_group_0_binding_4_cs[((starts + i_2) + 1u)], 0u);
            s = (a_2 + 1u);
            bool loop_init_8 = true;
            while(true) {
                if (!loop_init_8) {
                    uint _e498 = s;
                    s = (_e498 + 1u);
                }
                loop_init_8 = false;
                uint _e461 = s;
                if ((_e461 < b_2)) {
                } else {
                    break;
                }
                {
                    uint _e464 = s;
                    uint v_1 = _group_0_binding_6_cs[_e464];
                    uint _e467 = s;
                    c_2 = _e467;
                    while(true) {
                        uint _e469 = c_2;
                        if ((_e469 > a_2)) {
                            uint _e474 = c_2;
                            uint _e478 = _group_0_binding_6_cs[(_e474 - 1u)];
                            local_3 = (_e478 > v_1);
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
                            uint _e490 = _group_0_binding_6_cs[(_e486 - 1u)];
                            _group_0_binding_6_cs[_e483] = _e490;
                            uint _e491 = c_2;
                            c_2 = (_e491 - 1u);
                        }
                    }
                    uint _e495 = c_2;
                    _group_0_binding_6_cs[_e495] = v_1;
                }
            }
            s_1 = a_2;
            bool loop_init_9 = true;
            while(true) {
                if (!loop_init_9) {
                    uint _e514 = s_1;
                    s_1 = (_e514 + 1u);
                }
                loop_init_9 = false;
                uint _e501 = s_1;
                if ((_e501 < b_2)) {
                } else {
                    break;
                }
                {
                    uint _e504 = s_1;
                    uint _e508 = s_1;
                    uint _e510 = _group_0_binding_6_cs[_e508];
                    uint _e512 = _group_0_binding_2_cs[_e510];
                    _group_0_binding_6_cs[_e504] = _e512;
                }
            }
            return;
        }
    }
}

