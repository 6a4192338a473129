#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

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
const uint GRID_ENTRIES_PER_LIGHT = 8u;
const float LOBE_CONE_PAD = 1.001;

layout(std140) uniform GridStage_block_0Compute { GridStage _group_0_binding_0_cs; };

layout(std430) readonly buffer type_4_block_1Compute { BshNode _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_5_block_2Compute { uint _group_0_binding_2_cs[]; };

layout(std430) readonly buffer type_6_block_3Compute { GridFrame _group_0_binding_3_cs[]; };

layout(std430) buffer type_8_block_4Compute { uint _group_0_binding_4_cs[]; };

layout(std430) buffer type_8_block_5Compute { uint _group_0_binding_5_cs[]; };

layout(std430) buffer type_5_block_6Compute { uint _group_0_binding_6_cs[]; };

layout(std430) readonly buffer type_9_block_7Compute { GridParams _group_0_binding_7_cs[]; };

shared uint wg_sums[64];

shared uvec2 wg_big[64];

shared uint wg_bigs;

shared uint wg_cell[1024];


uint to_u32_(float x) {
    return uint(x);
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

uint bsh_grid_budget(uint leaves, uint cells, uint least) {
    if ((leaves > 536870911u)) {
        return 4294967295u;
    }
    uint e_1 = (leaves * GRID_ENTRIES_PER_LIGHT);
    uint _e8 = add_wrap_u32_(e_1, cells);
    return max(((_e8 < e_1) ? 4294967295u : _e8), least);
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

uvec3 bsh_grid_first(GridFrame f, vec3 c, float r) {
    uint _e10 = bsh_grid_axis((c.x - r), f.lo.x, f.inv.x, f.nx);
    uint _e18 = bsh_grid_axis((c.y - r), f.lo.y, f.inv.y, f.ny);
    uint _e26 = bsh_grid_axis((c.z - r), f.lo.z, f.inv.z, f.nz);
    return uvec3(_e10, _e18, _e26);
}

uvec3 bsh_grid_last(GridFrame f_1, vec3 c_1, float r_1) {
    uint _e10 = bsh_grid_axis((c_1.x + r_1), f_1.lo.x, f_1.inv.x, f_1.nx);
    uint _e18 = bsh_grid_axis((c_1.y + r_1), f_1.lo.y, f_1.inv.y, f_1.ny);
    uint _e26 = bsh_grid_axis((c_1.z + r_1), f_1.lo.z, f_1.inv.z, f_1.nz);
    return uvec3(_e10, _e18, _e26);
}

uint grid_word(uint i) {
    uint _e3 = atomicOr(_group_0_binding_4_cs[i], 0u);
    return _e3;
}

GridFrame grid_frame(uint h) {
    GridFrame f_2 = GridFrame(vec3(0.0), 0u, vec3(0.0), 0u, vec3(0.0), 0u);
    uint _e3 = grid_word(h);
    uint _e7 = grid_word((h + 1u));
    uint _e11 = grid_word((h + 2u));
    f_2.lo = vec3(uintBitsToFloat(_e3), uintBitsToFloat(_e7), uintBitsToFloat(_e11));
    uint _e17 = grid_word((h + 3u));
    f_2.nx = _e17;
    uint _e21 = grid_word((h + 4u));
    uint _e25 = grid_word((h + 5u));
    uint _e29 = grid_word((h + 6u));
    f_2.hi = vec3(uintBitsToFloat(_e21), uintBitsToFloat(_e25), uintBitsToFloat(_e29));
    uint _e35 = grid_word((h + 7u));
    f_2.ny = _e35;
    uint _e39 = grid_word((h + 8u));
    uint _e43 = grid_word((h + 9u));
    uint _e47 = grid_word((h + 10u));
    f_2.inv = vec3(uintBitsToFloat(_e39), uintBitsToFloat(_e43), uintBitsToFloat(_e47));
    uint _e53 = grid_word((h + 11u));
    f_2.nz = _e53;
    GridFrame _e54 = f_2;
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

uint cell_key(bool big, uint a_1, uint j) {
    if (big) {
        uint _e6 = _group_0_binding_6_cs[(a_1 + j)];
        return _e6;
    }
    uint _e9 = wg_cell[j];
    return _e9;
}

void set_cell_key(bool big_1, uint a_2, uint j_1, uint v_1) {
    if (big_1) {
        _group_0_binding_6_cs[(a_2 + j_1)] = v_1;
        return;
    } else {
        wg_cell[j_1] = v_1;
        return;
    }
}

void sort_together(uint b_1, uint li_1) {
    uint j_2 = 0u;
    uint p = 1u;
    uint k = 2u;
    uint h_1 = 0u;
    uint t = 0u;
    uint j_3 = 0u;
    memoryBarrierShared();
    barrier();
    uvec2 _e4 = wg_big[b_1];
    memoryBarrierShared();
    barrier();
    uint a_3 = _e4.x;
    uint n_1 = (_e4.y - _e4.x);
    bool big_2 = (n_1 > GRID_SORT_MAX);
    if (!(big_2)) {
        j_2 = li_1;
        bool loop_init = true;
        while(true) {
            if (!loop_init) {
                uint _e23 = j_2;
                j_2 = (_e23 + 64u);
            }
            loop_init = false;
            uint _e13 = j_2;
            if ((_e13 < n_1)) {
            } else {
                break;
            }
            {
                uint _e16 = j_2;
                uint _e19 = j_2;
                uint _e22 = _group_0_binding_6_cs[(a_3 + _e19)];
                wg_cell[_e16] = _e22;
            }
        }
    }
    while(true) {
        uint _e28 = p;
        if ((_e28 < n_1)) {
        } else {
            break;
        }
        {
            uint _e30 = p;
            p = (_e30 << 1u);
        }
    }
    memoryBarrierShared();
    barrier();
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e87 = k;
            k = (_e87 << 1u);
        }
        loop_init_1 = false;
        uint _e35 = k;
        uint _e36 = p;
        if ((_e35 <= _e36)) {
        } else {
            break;
        }
        {
            uint _e38 = k;
            h_1 = (_e38 >> 1u);
            bool loop_init_2 = true;
            while(true) {
                if (!loop_init_2) {
                    uint _e84 = h_1;
                    h_1 = (_e84 >> 1u);
                }
                loop_init_2 = false;
                uint _e42 = h_1;
                if ((_e42 > 0u)) {
                } else {
                    break;
                }
                {
                    t = li_1;
                    bool loop_init_3 = true;
                    while(true) {
                        if (!loop_init_3) {
                            uint _e81 = t;
                            t = (_e81 + 64u);
                        }
                        loop_init_3 = false;
                        uint _e46 = t;
                        uint _e47 = p;
                        if ((_e46 < (_e47 >> 1u))) {
                        } else {
                            break;
                        }
                        {
                            uint _e51 = t;
                            uint _e52 = h_1;
                            uint _e59 = t;
                            uint _e60 = h_1;
                            uint i_4 = (((_e51 & ~((_e52 - 1u))) << 1u) | (_e59 & (_e60 - 1u)));
                            uint _e65 = h_1;
                            uint _e67 = k;
                            uint _e71 = h_1;
                            uint _e72 = k;
                            uint o = ((_e71 == (_e72 >> 1u)) ? (i_4 ^ (_e67 - 1u)) : (i_4 | _e65));
                            if ((o < n_1)) {
                                uint _e78 = cell_key(big_2, a_3, i_4);
                                uint _e79 = cell_key(big_2, a_3, o);
                                if ((_e79 < _e78)) {
                                    set_cell_key(big_2, a_3, i_4, _e79);
                                    set_cell_key(big_2, a_3, o, _e78);
                                }
                            }
                        }
                    }
                    memoryBarrierShared();
                    barrier();
                    memoryBarrierBuffer();
                    barrier();
                }
            }
        }
    }
    j_3 = li_1;
    bool loop_init_4 = true;
    while(true) {
        if (!loop_init_4) {
            uint _e102 = j_3;
            j_3 = (_e102 + 64u);
        }
        loop_init_4 = false;
        uint _e91 = j_3;
        if ((_e91 < n_1)) {
        } else {
            break;
        }
        {
            uint _e94 = j_3;
            uint _e98 = j_3;
            uint _e99 = cell_key(big_2, a_3, _e98);
            uint _e101 = _group_0_binding_2_cs[_e99];
            _group_0_binding_6_cs[(a_3 + _e94)] = _e101;
        }
    }
    memoryBarrierShared();
    barrier();
    return;
}

void sort_cells(GridParams g, uint first, uint li_2) {
    uvec2 span = uvec2(0u);
    uint s = 0u;
    uint moves = 0u;
    bool local = false;
    uint c_2 = 0u;
    bool local_1 = false;
    uint e = 0u;
    uint b_2 = 0u;
    uint starts = (g.header + GRID_HEADER);
    GridFrame _e7 = grid_frame(g.header);
    uint cell = (first + li_2);
    if ((cell < ((_e7.nx * _e7.ny) * _e7.nz))) {
        uint _e21 = atomicOr(_group_0_binding_4_cs[(starts + cell)], 0u);
        uint _e27 = atomicOr(_group_0_binding_4_cs[((starts + cell) + 1u)], 0u);
        span = uvec2(_e21, _e27);
        atomicExchange(_group_0_binding_5_cs[(g.fill + cell)], 0u);
    }
    if ((li_2 == 0u)) {
        atomicExchange(wg_bigs, 0u);
    }
    memoryBarrierShared();
    barrier();
    uint _e39 = span.x;
    s = (_e39 + 1u);
    while(true) {
        uint _e45 = s;
        uint _e47 = span.y;
        if ((_e45 < _e47)) {
            uint _e51 = moves;
            uint _e54 = _group_0_binding_0_cs.moves;
            local = (_e51 < _e54);
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
            uint v_2 = _group_0_binding_6_cs[_e59];
            uint _e62 = s;
            c_2 = _e62;
            while(true) {
                uint _e64 = c_2;
                uint _e66 = span.x;
                if ((_e64 > _e66)) {
                    uint _e71 = c_2;
                    uint _e75 = _group_0_binding_6_cs[(_e71 - 1u)];
                    local_1 = (_e75 > v_2);
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
                    uint _e87 = _group_0_binding_6_cs[(_e83 - 1u)];
                    _group_0_binding_6_cs[_e80] = _e87;
                    uint _e88 = c_2;
                    c_2 = (_e88 - 1u);
                }
            }
            uint _e92 = c_2;
            _group_0_binding_6_cs[_e92] = v_2;
            uint _e94 = moves;
            uint _e95 = s;
            uint _e96 = c_2;
            moves = (_e94 + (_e95 - _e96));
            uint _e99 = s;
            s = (_e99 + 1u);
        }
    }
    uint _e102 = s;
    uint _e104 = span.y;
    if ((_e102 < _e104)) {
        uint _e109 = atomicAdd(wg_bigs, 1u);
        uvec2 _e111 = span;
        wg_big[_e109] = _e111;
    } else {
        uint _e113 = span.x;
        e = _e113;
        bool loop_init_5 = true;
        while(true) {
            if (!loop_init_5) {
                uint _e130 = e;
                e = (_e130 + 1u);
            }
            loop_init_5 = false;
            uint _e115 = e;
            uint _e117 = span.y;
            if ((_e115 < _e117)) {
            } else {
                break;
            }
            {
                uint _e120 = e;
                uint _e124 = e;
                uint _e126 = _group_0_binding_6_cs[_e124];
                uint _e128 = _group_0_binding_2_cs[_e126];
                _group_0_binding_6_cs[_e120] = _e128;
            }
        }
    }
    memoryBarrierBuffer();
    barrier();
    memoryBarrierShared();
    barrier();
    uint _e133 = wg_bigs;
    memoryBarrierShared();
    barrier();
    bool loop_init_6 = true;
    while(true) {
        if (!loop_init_6) {
            uint _e140 = b_2;
            b_2 = (_e140 + 1u);
        }
        loop_init_6 = false;
        uint _e136 = b_2;
        if ((_e136 < _e133)) {
        } else {
            break;
        }
        {
            uint _e138 = b_2;
            sort_together(_e138, li_2);
        }
    }
    return;
}

void count_levels(GridParams g_1, uint i_2) {
    uint l = 0u;
    uint _e4 = _group_0_binding_0_cs.count;
    if ((i_2 >= _e4)) {
        return;
    }
    uint h_2 = g_1.header;
    uint _e7 = grid_leaf(i_2);
    if ((_e7 == BSH_NONE)) {
        return;
    }
    uint _e15 = atomicAdd(_group_0_binding_4_cs[(h_2 + 13u)], 1u);
    BshNode leaf = _group_0_binding_1_cs[_e7];
    float _e20 = bsh_grid_radius(leaf, g_1.reach);
    bool loop_init_7 = true;
    while(true) {
        if (!loop_init_7) {
            uint _e67 = l;
            l = (_e67 + 1u);
        }
        loop_init_7 = false;
        uint _e23 = l;
        uint _e26 = _group_0_binding_0_cs.levels;
        if ((_e23 < _e26)) {
        } else {
            break;
        }
        {
            uint _e29 = l;
            GridFrame _e31 = _group_0_binding_3_cs[_e29];
            uvec3 _e33 = bsh_grid_last(_e31, leaf.center, _e20);
            uint _e35 = l;
            GridFrame _e37 = _group_0_binding_3_cs[_e35];
            uvec3 _e39 = bsh_grid_first(_e37, leaf.center, _e20);
            uvec3 d = ((_e33 - _e39) + uvec3(1u));
            uint n_2 = ((d.x * d.y) * d.z);
            uint _e52 = l;
            uint at = ((h_2 + 16u) + (2u * _e52));
            uint _e57 = atomicAdd(_group_0_binding_4_cs[at], n_2);
            if (((_e57 + n_2) < _e57)) {
                uint _e65 = atomicAdd(_group_0_binding_4_cs[(at + 1u)], 1u);
            }
        }
    }
    return;
}

void choose_level(GridParams g_2) {
    uint chosen = 0u;
    uint l_1 = 0u;
    bool local_2 = false;
    bool local_3 = false;
    GridFrame f_3 = GridFrame(vec3(0.0), 0u, vec3(0.0), 0u, vec3(0.0), 0u);
    uint h_3 = g_2.header;
    uint leaves_1 = atomicOr(_group_0_binding_4_cs[(h_3 + 13u)], 0u);
    uint _e9 = _group_0_binding_0_cs.levels;
    chosen = _e9;
    bool loop_init_8 = true;
    while(true) {
        if (!loop_init_8) {
            uint _e71 = l_1;
            l_1 = (_e71 + 1u);
        }
        loop_init_8 = false;
        uint _e13 = l_1;
        uint _e16 = _group_0_binding_0_cs.levels;
        if ((_e13 < _e16)) {
        } else {
            break;
        }
        {
            uint _e19 = l_1;
            GridFrame f_4 = _group_0_binding_3_cs[_e19];
            uint cells_1 = ((f_4.nx * f_4.ny) * f_4.nz);
            uint _e28 = bsh_grid_budget(leaves_1, cells_1, g_2.least);
            uint budget = min(_e28, g_2.capacity);
            uint _e34 = l_1;
            uint at_1 = ((h_3 + 16u) + (2u * _e34));
            uint _e37 = chosen;
            uint _e40 = _group_0_binding_0_cs.levels;
            if ((_e37 == _e40)) {
                uint _e48 = atomicOr(_group_0_binding_4_cs[(at_1 + 1u)], 0u);
                local_2 = (_e48 == 0u);
            } else {
                local_2 = false;
            }
            bool _e52 = local_2;
            if (_e52) {
                uint _e57 = atomicOr(_group_0_binding_4_cs[at_1], 0u);
                local_3 = (_e57 <= budget);
            } else {
                local_3 = false;
            }
            bool _e60 = local_3;
            if (_e60) {
                uint _e61 = l_1;
                chosen = _e61;
            }
            atomicExchange(_group_0_binding_4_cs[at_1], 0u);
            atomicExchange(_group_0_binding_4_cs[(at_1 + 1u)], 0u);
        }
    }
    atomicExchange(_group_0_binding_4_cs[(h_3 + 13u)], 0u);
    uint _e79 = chosen;
    uint _e82 = _group_0_binding_0_cs.levels;
    if ((_e79 < _e82)) {
        uint _e85 = chosen;
        GridFrame _e87 = _group_0_binding_3_cs[_e85];
        f_3 = _e87;
    }
    float _e92 = f_3.lo.x;
    atomicExchange(_group_0_binding_4_cs[h_3], floatBitsToUint(_e92));
    float _e100 = f_3.lo.y;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 1u)], floatBitsToUint(_e100));
    float _e108 = f_3.lo.z;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 2u)], floatBitsToUint(_e108));
    uint _e115 = f_3.nx;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 3u)], _e115);
    float _e122 = f_3.hi.x;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 4u)], floatBitsToUint(_e122));
    float _e130 = f_3.hi.y;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 5u)], floatBitsToUint(_e130));
    float _e138 = f_3.hi.z;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 6u)], floatBitsToUint(_e138));
    uint _e145 = f_3.ny;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 7u)], _e145);
    float _e152 = f_3.inv.x;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 8u)], floatBitsToUint(_e152));
    float _e160 = f_3.inv.y;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 9u)], floatBitsToUint(_e160));
    float _e168 = f_3.inv.z;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 10u)], floatBitsToUint(_e168));
    uint _e175 = f_3.nz;
    atomicExchange(_group_0_binding_4_cs[(h_3 + 11u)], _e175);
    atomicExchange(_group_0_binding_4_cs[(h_3 + 12u)], floatBitsToUint(g_2.reach));
    return;
}

void fill_cells(GridParams g_3, uint i_3, bool scatter) {
    bool local_4 = false;
    uint z = 0u;
    uint y = 0u;
    uint x_1 = 0u;
    uint _e5 = _group_0_binding_0_cs.count;
    if ((i_3 >= _e5)) {
        return;
    }
    GridFrame _e8 = grid_frame(g_3.header);
    uint _e9 = grid_leaf(i_3);
    if (!((_e8.nx == 0u))) {
        local_4 = (_e9 == BSH_NONE);
    } else {
        local_4 = true;
    }
    bool _e19 = local_4;
    if (_e19) {
        return;
    }
    BshNode leaf_1 = _group_0_binding_1_cs[_e9];
    float _e24 = bsh_grid_radius(leaf_1, g_3.reach);
    uvec3 _e26 = bsh_grid_first(_e8, leaf_1.center, _e24);
    uvec3 _e28 = bsh_grid_last(_e8, leaf_1.center, _e24);
    z = _e26.z;
    bool loop_init_9 = true;
    while(true) {
        if (!loop_init_9) {
            uint _e68 = z;
            z = (_e68 + 1u);
        }
        loop_init_9 = false;
        uint _e31 = z;
        if ((_e31 <= _e28.z)) {
        } else {
            break;
        }
        {
            y = _e26.y;
            bool loop_init_10 = true;
            while(true) {
                if (!loop_init_10) {
                    uint _e65 = y;
                    y = (_e65 + 1u);
                }
                loop_init_10 = false;
                uint _e36 = y;
                if ((_e36 <= _e28.y)) {
                } else {
                    break;
                }
                {
                    x_1 = _e26.x;
                    bool loop_init_11 = true;
                    while(true) {
                        if (!loop_init_11) {
                            uint _e62 = x_1;
                            x_1 = (_e62 + 1u);
                        }
                        loop_init_11 = false;
                        uint _e41 = x_1;
                        if ((_e41 <= _e28.x)) {
                        } else {
                            break;
                        }
                        {
                            uint _e44 = z;
                            uint _e47 = y;
                            uint _e51 = x_1;
                            uint c_5 = ((((_e44 * _e8.ny) + _e47) * _e8.nx) + _e51);
                            uint _e58 = atomicAdd(_group_0_binding_5_cs[(g_3.fill + c_5)], 1u);
                            if (scatter) {
                                _group_0_binding_6_cs[_e58] = i_3;
                            }
                        }
                    }
                }
            }
        }
    }
    return;
}

void scan_starts(GridParams g_4, uint li_3) {
    uint sum = 0u;
    uint c_3 = 0u;
    uint start = 0u;
    uint j_4 = 0u;
    uint c_4 = 0u;
    uint starts_1 = (g_4.header + GRID_HEADER);
    GridFrame _e6 = grid_frame(g_4.header);
    uint cells_2 = ((_e6.nx * _e6.ny) * _e6.nz);
    uint run = (((cells_2 + 64u) - 1u) / 64u);
    uint a_4 = min((li_3 * run), cells_2);
    uint b_3 = min((a_4 + run), cells_2);
    c_3 = a_4;
    bool loop_init_12 = true;
    while(true) {
        if (!loop_init_12) {
            uint _e36 = c_3;
            c_3 = (_e36 + 1u);
        }
        loop_init_12 = false;
        uint _e25 = c_3;
        if ((_e25 < b_3)) {
        } else {
            break;
        }
        {
            uint _e27 = sum;
            uint _e30 = c_3;
            uint _e33 = atomicOr(_group_0_binding_5_cs[(g_4.fill + _e30)], 0u);
            sum = (_e27 + _e33);
        }
    }
    uint _e40 = sum;
    wg_sums[li_3] = _e40;
    memoryBarrierShared();
    barrier();
    start = g_4.entries;
    bool loop_init_13 = true;
    while(true) {
        if (!loop_init_13) {
            uint _e54 = j_4;
            j_4 = (_e54 + 1u);
        }
        loop_init_13 = false;
        uint _e45 = j_4;
        if ((_e45 < li_3)) {
        } else {
            break;
        }
        {
            uint _e47 = start;
            uint _e49 = j_4;
            uint _e51 = wg_sums[_e49];
            start = (_e47 + _e51);
        }
    }
    c_4 = a_4;
    bool loop_init_14 = true;
    while(true) {
        if (!loop_init_14) {
            uint _e79 = c_4;
            c_4 = (_e79 + 1u);
        }
        loop_init_14 = false;
        uint _e57 = c_4;
        if ((_e57 < b_3)) {
        } else {
            break;
        }
        {
            uint _e61 = c_4;
            uint n_3 = atomicOr(_group_0_binding_5_cs[(g_4.fill + _e61)], 0u);
            uint _e66 = c_4;
            uint _e69 = start;
            atomicExchange(_group_0_binding_4_cs[(starts_1 + _e66)], _e69);
            uint _e72 = c_4;
            uint _e75 = start;
            atomicExchange(_group_0_binding_5_cs[(g_4.fill + _e72)], _e75);
            uint _e76 = start;
            start = (_e76 + n_3);
        }
    }
    if (((li_3 + 1u) == 64u)) {
        uint _e88 = start;
        atomicExchange(_group_0_binding_4_cs[(starts_1 + cells_2)], _e88);
        return;
    } else {
        return;
    }
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_sums = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
        wg_big = uvec2[64](uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u), uvec2(0u));
        wg_bigs = 0u;
        wg_cell = uint[1024](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    }
    memoryBarrierShared();
    barrier();
    uvec3 gid = gl_GlobalInvocationID;
    uvec3 wid = gl_WorkGroupID;
    uvec3 groups = gl_NumWorkGroups;
    uint li = gl_LocalInvocationIndex;
    GridParams g_5 = _group_0_binding_7_cs[wid.z];
    uint _e10 = _group_0_binding_0_cs.stage;
    switch(_e10) {
        case 0u: {
            count_levels(g_5, gid.x);
            return;
        }
        case 1u: {
            if ((li == 0u)) {
                choose_level(g_5);
                return;
            } else {
                return;
            }
            break;
        }
        case 3u: {
            scan_starts(g_5, li);
            return;
        }
        case 5u: {
            sort_cells(g_5, (((wid.y * groups.x) + wid.x) * 64u), li);
            return;
        }
        default: {
            uint _e24 = _group_0_binding_0_cs.stage;
            fill_cells(g_5, gid.x, (_e24 == 4u));
            return;
        }
    }
}

