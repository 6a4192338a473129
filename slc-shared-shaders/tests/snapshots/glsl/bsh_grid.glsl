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
    uint least;
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
const uint GRID_SORT_MAX = 1536u;
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
const float LOBE_CONE_PAD = 1.001;

layout(std140) uniform GridParams_block_0Compute { GridParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_4_block_1Compute { BshNode _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_5_block_2Compute { uint _group_0_binding_2_cs[]; };

layout(std430) readonly buffer type_6_block_3Compute { GridFrame _group_0_binding_3_cs[]; };

layout(std430) buffer type_8_block_4Compute { uint _group_0_binding_4_cs[]; };

layout(std430) buffer type_8_block_5Compute { uint _group_0_binding_5_cs[]; };

layout(std430) buffer type_5_block_6Compute { uint _group_0_binding_6_cs[]; };

shared uint wg_sums[64];

shared uint wg_cell[1536];

shared uvec2 wg_span;


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

uint bsh_grid_budget(uint leaves, uint cells, uint least) {
    if ((leaves > 536870911u)) {
        return 4294967295u;
    }
    uint e = (leaves * GRID_ENTRIES_PER_LIGHT);
    uint _e8 = add_wrap_u32_(e, cells);
    return max(((_e8 < e) ? 4294967295u : _e8), least);
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

uvec3 bsh_grid_first(GridFrame f_1, vec3 c_2, float r) {
    uint _e10 = bsh_grid_axis((c_2.x - r), f_1.lo.x, f_1.inv.x, f_1.nx);
    uint _e18 = bsh_grid_axis((c_2.y - r), f_1.lo.y, f_1.inv.y, f_1.ny);
    uint _e26 = bsh_grid_axis((c_2.z - r), f_1.lo.z, f_1.inv.z, f_1.nz);
    return uvec3(_e10, _e18, _e26);
}

uvec3 bsh_grid_last(GridFrame f_2, vec3 c_3, float r_1) {
    uint _e10 = bsh_grid_axis((c_3.x + r_1), f_2.lo.x, f_2.inv.x, f_2.nx);
    uint _e18 = bsh_grid_axis((c_3.y + r_1), f_2.lo.y, f_2.inv.y, f_2.ny);
    uint _e26 = bsh_grid_axis((c_3.z + r_1), f_2.lo.z, f_2.inv.z, f_2.nz);
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

void sort_cell(uint cell, uint li_1) {
    uvec2 span = uvec2(0u);
    uint s = 0u;
    uint c_4 = 0u;
    bool local_3 = false;
    uint s_1 = 0u;
    uint j_1 = 0u;
    uint j_2 = 0u;
    uint below = 0u;
    uint m = 0u;
    uint _e4 = _group_0_binding_0_cs.header;
    uint starts = (_e4 + GRID_HEADER);
    if ((li_1 == 0u)) {
        uint _e11 = _group_0_binding_0_cs.header;
        GridFrame _e12 = grid_frame(_e11);
        if ((cell < ((_e12.nx * _e12.ny) * _e12.nz))) {
            uint _e25 = atomicOr(_group_0_binding_4_cs[(starts + cell)], 0u);
            uint _e31 = atomicOr(_group_0_binding_4_cs[((starts + cell) + 1u)], 0u);
            span = uvec2(_e25, _e31);
            uint _e36 = _group_0_binding_0_cs.fill;
            atomicExchange(_group_0_binding_5_cs[(_e36 + cell)], 0u);
        }
        uvec2 _e41 = span;
        wg_span = _e41;
    }
    memoryBarrierShared();
    barrier();
    uvec2 _e43 = wg_span;
    memoryBarrierShared();
    barrier();
    uint a_1 = _e43.x;
    uint n_1 = (_e43.y - _e43.x);
    if ((n_1 > GRID_SORT_MAX)) {
        if ((li_1 == 0u)) {
            s = (a_1 + 1u);
            bool loop_init = true;
            while(true) {
                if (!loop_init) {
                    uint _e93 = s;
                    s = (_e93 + 1u);
                }
                loop_init = false;
                uint _e55 = s;
                if ((_e55 < (a_1 + n_1))) {
                } else {
                    break;
                }
                {
                    uint _e59 = s;
                    uint v_1 = _group_0_binding_6_cs[_e59];
                    uint _e62 = s;
                    c_4 = _e62;
                    while(true) {
                        uint _e64 = c_4;
                        if ((_e64 > a_1)) {
                            uint _e69 = c_4;
                            uint _e73 = _group_0_binding_6_cs[(_e69 - 1u)];
                            local_3 = (_e73 > v_1);
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
                            uint _e85 = _group_0_binding_6_cs[(_e81 - 1u)];
                            _group_0_binding_6_cs[_e78] = _e85;
                            uint _e86 = c_4;
                            c_4 = (_e86 - 1u);
                        }
                    }
                    uint _e90 = c_4;
                    _group_0_binding_6_cs[_e90] = v_1;
                }
            }
            s_1 = a_1;
            bool loop_init_1 = true;
            while(true) {
                if (!loop_init_1) {
                    uint _e110 = s_1;
                    s_1 = (_e110 + 1u);
                }
                loop_init_1 = false;
                uint _e96 = s_1;
                if ((_e96 < (a_1 + n_1))) {
                } else {
                    break;
                }
                {
                    uint _e100 = s_1;
                    uint _e104 = s_1;
                    uint _e106 = _group_0_binding_6_cs[_e104];
                    uint _e108 = _group_0_binding_2_cs[_e106];
                    _group_0_binding_6_cs[_e100] = _e108;
                }
            }
        }
        return;
    }
    j_1 = li_1;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e123 = j_1;
            j_1 = (_e123 + 64u);
        }
        loop_init_2 = false;
        uint _e113 = j_1;
        if ((_e113 < n_1)) {
        } else {
            break;
        }
        {
            uint _e116 = j_1;
            uint _e119 = j_1;
            uint _e122 = _group_0_binding_6_cs[(a_1 + _e119)];
            wg_cell[_e116] = _e122;
        }
    }
    memoryBarrierShared();
    barrier();
    j_2 = li_1;
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            uint _e159 = j_2;
            j_2 = (_e159 + 64u);
        }
        loop_init_3 = false;
        uint _e127 = j_2;
        if ((_e127 < n_1)) {
        } else {
            break;
        }
        {
            uint _e130 = j_2;
            uint v_2 = wg_cell[_e130];
            below = 0u;
            m = 0u;
            bool loop_init_4 = true;
            while(true) {
                if (!loop_init_4) {
                    uint _e150 = m;
                    m = (_e150 + 1u);
                }
                loop_init_4 = false;
                uint _e137 = m;
                if ((_e137 < n_1)) {
                } else {
                    break;
                }
                {
                    uint _e139 = below;
                    uint _e143 = m;
                    uint _e145 = wg_cell[_e143];
                    below = (_e139 + ((_e145 < v_2) ? 1u : 0u));
                }
            }
            uint _e153 = below;
            uint _e158 = _group_0_binding_2_cs[v_2];
            _group_0_binding_6_cs[(a_1 + _e153)] = _e158;
        }
    }
    return;
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_sums = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
        wg_cell = uint[1536](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
        wg_span = uvec2(0u);
    }
    memoryBarrierShared();
    barrier();
    uvec3 gid = gl_GlobalInvocationID;
    uvec3 wid = gl_WorkGroupID;
    uvec3 groups = gl_NumWorkGroups;
    uint li = gl_LocalInvocationIndex;
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
    uint _e6 = _group_0_binding_0_cs.stage;
    if ((_e6 == 5u)) {
        sort_cell(((wid.y * groups.x) + wid.x), li);
        return;
    }
    uint i_2 = gid.x;
    uint h_1 = _group_0_binding_0_cs.header;
    uint starts_1 = (h_1 + GRID_HEADER);
    uint _e22 = _group_0_binding_0_cs.stage;
    if ((_e22 == 3u)) {
        GridFrame _e25 = grid_frame(h_1);
        uint cells_1 = ((_e25.nx * _e25.ny) * _e25.nz);
        uint run = (((cells_1 + 64u) - 1u) / 64u);
        uint a_2 = min((i_2 * run), cells_1);
        uint b_1 = min((a_2 + run), cells_1);
        c = a_2;
        bool loop_init_5 = true;
        while(true) {
            if (!loop_init_5) {
                uint _e57 = c;
                c = (_e57 + 1u);
            }
            loop_init_5 = false;
            uint _e44 = c;
            if ((_e44 < b_1)) {
            } else {
                break;
            }
            {
                uint _e46 = sum;
                uint _e50 = _group_0_binding_0_cs.fill;
                uint _e51 = c;
                uint _e54 = atomicOr(_group_0_binding_5_cs[(_e50 + _e51)], 0u);
                sum = (_e46 + _e54);
            }
        }
        uint _e61 = sum;
        wg_sums[i_2] = _e61;
        memoryBarrierShared();
        barrier();
        uint _e64 = _group_0_binding_0_cs.entries;
        start = _e64;
        bool loop_init_6 = true;
        while(true) {
            if (!loop_init_6) {
                uint _e77 = j;
                j = (_e77 + 1u);
            }
            loop_init_6 = false;
            uint _e68 = j;
            if ((_e68 < i_2)) {
            } else {
                break;
            }
            {
                uint _e70 = start;
                uint _e72 = j;
                uint _e74 = wg_sums[_e72];
                start = (_e70 + _e74);
            }
        }
        c_1 = a_2;
        bool loop_init_7 = true;
        while(true) {
            if (!loop_init_7) {
                uint _e106 = c_1;
                c_1 = (_e106 + 1u);
            }
            loop_init_7 = false;
            uint _e80 = c_1;
            if ((_e80 < b_1)) {
            } else {
                break;
            }
            {
                uint _e85 = _group_0_binding_0_cs.fill;
                uint _e86 = c_1;
                uint n_2 = atomicOr(_group_0_binding_5_cs[(_e85 + _e86)], 0u);
                uint _e91 = c_1;
                uint _e94 = start;
                atomicExchange(_group_0_binding_4_cs[(starts_1 + _e91)], _e94);
                uint _e98 = _group_0_binding_0_cs.fill;
                uint _e99 = c_1;
                uint _e102 = start;
                atomicExchange(_group_0_binding_5_cs[(_e98 + _e99)], _e102);
                uint _e103 = start;
                start = (_e103 + n_2);
            }
        }
        if (((i_2 + 1u) == 64u)) {
            uint _e115 = start;
            atomicExchange(_group_0_binding_4_cs[(starts_1 + cells_1)], _e115);
        }
        return;
    }
    uint _e118 = _group_0_binding_0_cs.stage;
    switch(_e118) {
        case 0u: {
            uint _e121 = _group_0_binding_0_cs.count;
            if ((i_2 >= _e121)) {
                return;
            }
            uint _e123 = grid_leaf(i_2);
            if ((_e123 == BSH_NONE)) {
                return;
            }
            uint _e131 = atomicAdd(_group_0_binding_4_cs[(h_1 + 13u)], 1u);
            BshNode leaf = _group_0_binding_1_cs[_e123];
            float _e137 = _group_0_binding_0_cs.reach;
            float _e138 = bsh_grid_radius(leaf, _e137);
            bool loop_init_8 = true;
            while(true) {
                if (!loop_init_8) {
                    uint _e185 = l;
                    l = (_e185 + 1u);
                }
                loop_init_8 = false;
                uint _e141 = l;
                uint _e144 = _group_0_binding_0_cs.levels;
                if ((_e141 < _e144)) {
                } else {
                    break;
                }
                {
                    uint _e147 = l;
                    GridFrame _e149 = _group_0_binding_3_cs[_e147];
                    uvec3 _e151 = bsh_grid_last(_e149, leaf.center, _e138);
                    uint _e153 = l;
                    GridFrame _e155 = _group_0_binding_3_cs[_e153];
                    uvec3 _e157 = bsh_grid_first(_e155, leaf.center, _e138);
                    uvec3 d = ((_e151 - _e157) + uvec3(1u));
                    uint n_3 = ((d.x * d.y) * d.z);
                    uint _e170 = l;
                    uint at = ((h_1 + 16u) + (2u * _e170));
                    uint _e175 = atomicAdd(_group_0_binding_4_cs[at], n_3);
                    if (((_e175 + n_3) < _e175)) {
                        uint _e183 = atomicAdd(_group_0_binding_4_cs[(at + 1u)], 1u);
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
            uint _e196 = _group_0_binding_0_cs.levels;
            chosen = _e196;
            bool loop_init_9 = true;
            while(true) {
                if (!loop_init_9) {
                    uint _e262 = l_1;
                    l_1 = (_e262 + 1u);
                }
                loop_init_9 = false;
                uint _e200 = l_1;
                uint _e203 = _group_0_binding_0_cs.levels;
                if ((_e200 < _e203)) {
                } else {
                    break;
                }
                {
                    uint _e206 = l_1;
                    GridFrame f_4 = _group_0_binding_3_cs[_e206];
                    uint cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    uint _e216 = _group_0_binding_0_cs.least;
                    uint _e217 = bsh_grid_budget(leaves_1, cells_2, _e216);
                    uint _e220 = _group_0_binding_0_cs.capacity;
                    uint budget = min(_e217, _e220);
                    uint _e225 = l_1;
                    uint at_1 = ((h_1 + 16u) + (2u * _e225));
                    uint _e228 = chosen;
                    uint _e231 = _group_0_binding_0_cs.levels;
                    if ((_e228 == _e231)) {
                        uint _e239 = atomicOr(_group_0_binding_4_cs[(at_1 + 1u)], 0u);
                        local = (_e239 == 0u);
                    } else {
                        local = false;
                    }
                    bool _e243 = local;
                    if (_e243) {
                        uint _e248 = atomicOr(_group_0_binding_4_cs[at_1], 0u);
                        local_1 = (_e248 <= budget);
                    } else {
                        local_1 = false;
                    }
                    bool _e251 = local_1;
                    if (_e251) {
                        uint _e252 = l_1;
                        chosen = _e252;
                    }
                    atomicExchange(_group_0_binding_4_cs[at_1], 0u);
                    atomicExchange(_group_0_binding_4_cs[(at_1 + 1u)], 0u);
                }
            }
            atomicExchange(_group_0_binding_4_cs[(h_1 + 13u)], 0u);
            uint _e270 = chosen;
            uint _e273 = _group_0_binding_0_cs.levels;
            if ((_e270 < _e273)) {
                uint _e276 = chosen;
                GridFrame _e278 = _group_0_binding_3_cs[_e276];
                f = _e278;
            }
            float _e283 = f.lo.x;
            atomicExchange(_group_0_binding_4_cs[h_1], floatBitsToUint(_e283));
            float _e291 = f.lo.y;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 1u)], floatBitsToUint(_e291));
            float _e299 = f.lo.z;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 2u)], floatBitsToUint(_e299));
            uint _e306 = f.nx;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 3u)], _e306);
            float _e313 = f.hi.x;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 4u)], floatBitsToUint(_e313));
            float _e321 = f.hi.y;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 5u)], floatBitsToUint(_e321));
            float _e329 = f.hi.z;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 6u)], floatBitsToUint(_e329));
            uint _e336 = f.ny;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 7u)], _e336);
            float _e343 = f.inv.x;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 8u)], floatBitsToUint(_e343));
            float _e351 = f.inv.y;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 9u)], floatBitsToUint(_e351));
            float _e359 = f.inv.z;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 10u)], floatBitsToUint(_e359));
            uint _e366 = f.nz;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 11u)], _e366);
            float _e373 = _group_0_binding_0_cs.reach;
            atomicExchange(_group_0_binding_4_cs[(h_1 + 12u)], floatBitsToUint(_e373));
            return;
        }
        case 2u:
        case 4u: {
            uint _e377 = _group_0_binding_0_cs.count;
            if ((i_2 >= _e377)) {
                return;
            }
            GridFrame _e379 = grid_frame(h_1);
            uint _e380 = grid_leaf(i_2);
            if (!((_e379.nx == 0u))) {
                local_2 = (_e380 == BSH_NONE);
            } else {
                local_2 = true;
            }
            bool _e390 = local_2;
            if (_e390) {
                return;
            }
            BshNode leaf_1 = _group_0_binding_1_cs[_e380];
            float _e396 = _group_0_binding_0_cs.reach;
            float _e397 = bsh_grid_radius(leaf_1, _e396);
            uvec3 _e399 = bsh_grid_first(_e379, leaf_1.center, _e397);
            uvec3 _e401 = bsh_grid_last(_e379, leaf_1.center, _e397);
            z = _e399.z;
            bool loop_init_10 = true;
            while(true) {
                if (!loop_init_10) {
                    uint _e448 = z;
                    z = (_e448 + 1u);
                }
                loop_init_10 = false;
                uint _e404 = z;
                if ((_e404 <= _e401.z)) {
                } else {
                    break;
                }
                {
                    y = _e399.y;
                    bool loop_init_11 = true;
                    while(true) {
                        if (!loop_init_11) {
                            uint _e445 = y;
                            y = (_e445 + 1u);
                        }
                        loop_init_11 = false;
                        uint _e409 = y;
                        if ((_e409 <= _e401.y)) {
                        } else {
                            break;
                        }
                        {
                            x = _e399.x;
                            bool loop_init_12 = true;
                            while(true) {
                                if (!loop_init_12) {
                                    uint _e442 = x;
                                    x = (_e442 + 1u);
                                }
                                loop_init_12 = false;
                                uint _e414 = x;
                                if ((_e414 <= _e401.x)) {
                                } else {
                                    break;
                                }
                                {
                                    uint _e417 = z;
                                    uint _e420 = y;
                                    uint _e424 = x;
                                    uint c_5 = ((((_e417 * _e379.ny) + _e420) * _e379.nx) + _e424);
                                    uint _e429 = _group_0_binding_0_cs.fill;
                                    uint _e433 = atomicAdd(_group_0_binding_5_cs[(_e429 + c_5)], 1u);
                                    uint _e436 = _group_0_binding_0_cs.stage;
                                    if ((_e436 == 4u)) {
                                        _group_0_binding_6_cs[_e433] = i_2;
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

