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
    uint _e9 = to_u32_(max(floor(((v - lo) * inv)), 0.0));
    return min(_e9, (n - 1u));
}

uint grid_word(uint i) {
    uint _e3 = atomicOr(_group_0_binding_4_cs[i], 0u);
    return _e3;
}

GridFrame grid_frame() {
    GridFrame f_1 = GridFrame(vec3(0.0), 0u, vec3(0.0), 0u, vec3(0.0), 0u);
    uint _e3 = grid_word(0u);
    uint _e6 = grid_word(1u);
    uint _e9 = grid_word(2u);
    f_1.lo = vec3(uintBitsToFloat(_e3), uintBitsToFloat(_e6), uintBitsToFloat(_e9));
    uint _e14 = grid_word(3u);
    f_1.nx = _e14;
    uint _e17 = grid_word(4u);
    uint _e20 = grid_word(5u);
    uint _e23 = grid_word(6u);
    f_1.hi = vec3(uintBitsToFloat(_e17), uintBitsToFloat(_e20), uintBitsToFloat(_e23));
    uint _e28 = grid_word(7u);
    f_1.ny = _e28;
    uint _e31 = grid_word(8u);
    uint _e34 = grid_word(9u);
    uint _e37 = grid_word(10u);
    f_1.inv = vec3(uintBitsToFloat(_e31), uintBitsToFloat(_e34), uintBitsToFloat(_e37));
    uint _e42 = grid_word(11u);
    f_1.nz = _e42;
    GridFrame _e43 = f_1;
    return _e43;
}

uint grid_leaf(uint i_1) {
    uint node_5 = _group_0_binding_2_cs[i_1];
    uint _e7 = _group_0_binding_1_cs[node_5].light;
    if (((_e7 & BSH_TAIL) != 0u)) {
        return BSH_NONE;
    }
    return node_5;
}

uvec3 cover_first(GridFrame f_2, BshNode node_3, float r) {
    vec3 c_3 = node_3.center;
    uint _e11 = bsh_grid_axis((c_3.x - r), f_2.lo.x, f_2.inv.x, f_2.nx);
    uint _e19 = bsh_grid_axis((c_3.y - r), f_2.lo.y, f_2.inv.y, f_2.ny);
    uint _e27 = bsh_grid_axis((c_3.z - r), f_2.lo.z, f_2.inv.z, f_2.nz);
    return uvec3(_e11, _e19, _e27);
}

uvec3 cover_last(GridFrame f_3, BshNode node_4, float r_1) {
    vec3 c_4 = node_4.center;
    uint _e11 = bsh_grid_axis((c_4.x + r_1), f_3.lo.x, f_3.inv.x, f_3.nx);
    uint _e19 = bsh_grid_axis((c_4.y + r_1), f_3.lo.y, f_3.inv.y, f_3.ny);
    uint _e27 = bsh_grid_axis((c_4.z + r_1), f_3.lo.z, f_3.inv.z, f_3.nz);
    return uvec3(_e11, _e19, _e27);
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
    uint _e4 = _group_0_binding_0_cs.stage;
    if ((_e4 == 3u)) {
        GridFrame _e7 = grid_frame();
        uint cells_1 = ((_e7.nx * _e7.ny) * _e7.nz);
        uint run = (((cells_1 + 64u) - 1u) / 64u);
        uint a_1 = min((i_2 * run), cells_1);
        uint b_1 = min((a_1 + run), cells_1);
        c = a_1;
        bool loop_init = true;
        while(true) {
            if (!loop_init) {
                uint _e35 = c;
                c = (_e35 + 1u);
            }
            loop_init = false;
            uint _e26 = c;
            if ((_e26 < b_1)) {
            } else {
                break;
            }
            {
                uint _e28 = sum;
                uint _e30 = c;
                uint _e32 = atomicOr(_group_0_binding_5_cs[_e30], 0u);
                sum = (_e28 + _e32);
            }
        }
        uint _e39 = sum;
        wg_sums[i_2] = _e39;
        memoryBarrierShared();
        barrier();
        bool loop_init_1 = true;
        while(true) {
            if (!loop_init_1) {
                uint _e53 = j;
                j = (_e53 + 1u);
            }
            loop_init_1 = false;
            uint _e44 = j;
            if ((_e44 < i_2)) {
            } else {
                break;
            }
            {
                uint _e46 = start;
                uint _e48 = j;
                uint _e50 = wg_sums[_e48];
                start = (_e46 + _e50);
            }
        }
        c_1 = a_1;
        bool loop_init_2 = true;
        while(true) {
            if (!loop_init_2) {
                uint _e75 = c_1;
                c_1 = (_e75 + 1u);
            }
            loop_init_2 = false;
            uint _e56 = c_1;
            if ((_e56 < b_1)) {
            } else {
                break;
            }
            {
                uint _e59 = c_1;
                uint n_1 = atomicOr(_group_0_binding_5_cs[_e59], 0u);
                uint _e64 = c_1;
                uint _e67 = start;
                atomicExchange(_group_0_binding_4_cs[(GRID_HEADER + _e64)], _e67);
                uint _e69 = c_1;
                uint _e71 = start;
                atomicExchange(_group_0_binding_5_cs[_e69], _e71);
                uint _e72 = start;
                start = (_e72 + n_1);
            }
        }
        if (((i_2 + 1u) == 64u)) {
            uint _e85 = start;
            atomicExchange(_group_0_binding_4_cs[(GRID_HEADER + cells_1)], _e85);
        }
        return;
    }
    uint _e88 = _group_0_binding_0_cs.stage;
    switch(_e88) {
        case 0u: {
            uint _e91 = _group_0_binding_0_cs.count;
            if ((i_2 >= _e91)) {
                return;
            }
            uint _e93 = grid_leaf(i_2);
            if ((_e93 == BSH_NONE)) {
                return;
            }
            uint _e99 = atomicAdd(_group_0_binding_4_cs[13], 1u);
            BshNode leaf = _group_0_binding_1_cs[_e93];
            float _e105 = _group_0_binding_0_cs.reach;
            float _e106 = bsh_grid_reach(leaf, _e105);
            float _e107 = bsh_grid_pad(_e106);
            bool loop_init_3 = true;
            while(true) {
                if (!loop_init_3) {
                    uint _e151 = l;
                    l = (_e151 + 1u);
                }
                loop_init_3 = false;
                uint _e110 = l;
                uint _e113 = _group_0_binding_0_cs.levels;
                if ((_e110 < _e113)) {
                } else {
                    break;
                }
                {
                    uint _e116 = l;
                    GridFrame _e118 = _group_0_binding_3_cs[_e116];
                    uvec3 _e119 = cover_last(_e118, leaf, _e107);
                    uint _e121 = l;
                    GridFrame _e123 = _group_0_binding_3_cs[_e121];
                    uvec3 _e124 = cover_first(_e123, leaf, _e107);
                    uvec3 d = ((_e119 - _e124) + uvec3(1u));
                    uint n_2 = ((d.x * d.y) * d.z);
                    uint _e136 = l;
                    uint at = (16u + (2u * _e136));
                    uint _e141 = atomicAdd(_group_0_binding_4_cs[at], n_2);
                    if (((_e141 + n_2) < _e141)) {
                        uint _e149 = atomicAdd(_group_0_binding_4_cs[(at + 1u)], 1u);
                    }
                }
            }
            return;
        }
        case 1u: {
            if ((i_2 != 0u)) {
                return;
            }
            uint leaves_1 = atomicOr(_group_0_binding_4_cs[13], 0u);
            uint _e160 = _group_0_binding_0_cs.levels;
            chosen = _e160;
            bool loop_init_4 = true;
            while(true) {
                if (!loop_init_4) {
                    uint _e233 = l_1;
                    l_1 = (_e233 + 1u);
                }
                loop_init_4 = false;
                uint _e164 = l_1;
                uint _e167 = _group_0_binding_0_cs.levels;
                if ((_e164 < _e167)) {
                } else {
                    break;
                }
                {
                    uint _e170 = l_1;
                    GridFrame f_4 = _group_0_binding_3_cs[_e170];
                    uint cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    uint _e178 = bsh_grid_budget(leaves_1, cells_2);
                    uint _e181 = _group_0_binding_0_cs.capacity;
                    uint budget = min(_e178, _e181);
                    uint _e183 = chosen;
                    uint _e186 = _group_0_binding_0_cs.levels;
                    if ((_e183 == _e186)) {
                        uint _e193 = l_1;
                        uint _e197 = atomicOr(_group_0_binding_4_cs[(17u + (2u * _e193))], 0u);
                        local = (_e197 == 0u);
                    } else {
                        local = false;
                    }
                    bool _e201 = local;
                    if (_e201) {
                        uint _e207 = l_1;
                        uint _e211 = atomicOr(_group_0_binding_4_cs[(16u + (2u * _e207))], 0u);
                        local_1 = (_e211 <= budget);
                    } else {
                        local_1 = false;
                    }
                    bool _e214 = local_1;
                    if (_e214) {
                        uint _e215 = l_1;
                        chosen = _e215;
                    }
                    uint _e219 = l_1;
                    atomicExchange(_group_0_binding_4_cs[(16u + (2u * _e219))], 0u);
                    uint _e227 = l_1;
                    atomicExchange(_group_0_binding_4_cs[(17u + (2u * _e227))], 0u);
                }
            }
            atomicExchange(_group_0_binding_4_cs[13], 0u);
            uint _e239 = chosen;
            uint _e242 = _group_0_binding_0_cs.levels;
            if ((_e239 < _e242)) {
                uint _e245 = chosen;
                GridFrame _e247 = _group_0_binding_3_cs[_e245];
                f = _e247;
            }
            float _e252 = f.lo.x;
            atomicExchange(_group_0_binding_4_cs[0], floatBitsToUint(_e252));
            float _e258 = f.lo.y;
            atomicExchange(_group_0_binding_4_cs[1], floatBitsToUint(_e258));
            float _e264 = f.lo.z;
            atomicExchange(_group_0_binding_4_cs[2], floatBitsToUint(_e264));
            uint _e269 = f.nx;
            atomicExchange(_group_0_binding_4_cs[3], _e269);
            float _e274 = f.hi.x;
            atomicExchange(_group_0_binding_4_cs[4], floatBitsToUint(_e274));
            float _e280 = f.hi.y;
            atomicExchange(_group_0_binding_4_cs[5], floatBitsToUint(_e280));
            float _e286 = f.hi.z;
            atomicExchange(_group_0_binding_4_cs[6], floatBitsToUint(_e286));
            uint _e291 = f.ny;
            atomicExchange(_group_0_binding_4_cs[7], _e291);
            float _e296 = f.inv.x;
            atomicExchange(_group_0_binding_4_cs[8], floatBitsToUint(_e296));
            float _e302 = f.inv.y;
            atomicExchange(_group_0_binding_4_cs[9], floatBitsToUint(_e302));
            float _e308 = f.inv.z;
            atomicExchange(_group_0_binding_4_cs[10], floatBitsToUint(_e308));
            uint _e313 = f.nz;
            atomicExchange(_group_0_binding_4_cs[11], _e313);
            float _e318 = _group_0_binding_0_cs.reach;
            atomicExchange(_group_0_binding_4_cs[12], floatBitsToUint(_e318));
            return;
        }
        case 2u:
        case 4u: {
            uint _e322 = _group_0_binding_0_cs.count;
            if ((i_2 >= _e322)) {
                return;
            }
            GridFrame _e324 = grid_frame();
            uint _e325 = grid_leaf(i_2);
            if (!((_e324.nx == 0u))) {
                local_2 = (_e325 == BSH_NONE);
            } else {
                local_2 = true;
            }
            bool _e335 = local_2;
            if (_e335) {
                return;
            }
            BshNode leaf_1 = _group_0_binding_1_cs[_e325];
            float _e341 = _group_0_binding_0_cs.reach;
            float _e342 = bsh_grid_reach(leaf_1, _e341);
            float _e343 = bsh_grid_pad(_e342);
            uvec3 _e344 = cover_first(_e324, leaf_1, _e343);
            uvec3 _e345 = cover_last(_e324, leaf_1, _e343);
            z = _e344.z;
            bool loop_init_5 = true;
            while(true) {
                if (!loop_init_5) {
                    uint _e388 = z;
                    z = (_e388 + 1u);
                }
                loop_init_5 = false;
                uint _e348 = z;
                if ((_e348 <= _e345.z)) {
                } else {
                    break;
                }
                {
                    y = _e344.y;
                    bool loop_init_6 = true;
                    while(true) {
                        if (!loop_init_6) {
                            uint _e385 = y;
                            y = (_e385 + 1u);
                        }
                        loop_init_6 = false;
                        uint _e353 = y;
                        if ((_e353 <= _e345.y)) {
                        } else {
                            break;
                        }
                        {
                            x = _e344.x;
                            bool loop_init_7 = true;
                            while(true) {
                                if (!loop_init_7) {
                                    uint _e382 = x;
                                    x = (_e382 + 1u);
                                }
                                loop_init_7 = false;
                                uint _e358 = x;
                                if ((_e358 <= _e345.x)) {
                                } else {
                                    break;
                                }
                                {
                                    uint _e361 = z;
                                    uint _e364 = y;
                                    uint _e368 = x;
                                    uint c_5 = ((((_e361 * _e324.ny) + _e364) * _e324.nx) + _e368);
                                    uint _e373 = atomicAdd(_group_0_binding_5_cs[c_5], 1u);
                                    uint _e376 = _group_0_binding_0_cs.stage;
                                    if ((_e376 == 4u)) {
                                        _group_0_binding_6_cs[_e373] = i_2;
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
            GridFrame _e390 = grid_frame();
            if ((i_2 >= ((_e390.nx * _e390.ny) * _e390.nz))) {
                return;
            }
            atomicExchange(_group_0_binding_5_cs[i_2], 0u);
            uint a_2 = atomicOr(_group_0_binding_4_cs[(GRID_HEADER + i_2)], 0u);
            uint b_2 = atomicOr(_group_0_binding_4_cs[((GRID_HEADER + i_2) + 1u)], 0u);
            s = (a_2 + 1u);
            bool loop_init_8 = true;
            while(true) {
                if (!loop_init_8) {
                    uint _e452 = s;
                    s = (_e452 + 1u);
                }
                loop_init_8 = false;
                uint _e415 = s;
                if ((_e415 < b_2)) {
                } else {
                    break;
                }
                {
                    uint _e418 = s;
                    uint v_1 = _group_0_binding_6_cs[_e418];
                    uint _e421 = s;
                    c_2 = _e421;
                    while(true) {
                        uint _e423 = c_2;
                        if ((_e423 > a_2)) {
                            uint _e428 = c_2;
                            uint _e432 = _group_0_binding_6_cs[(_e428 - 1u)];
                            local_3 = (_e432 > v_1);
                        } else {
                            local_3 = false;
                        }
                        bool _e435 = local_3;
                        if (_e435) {
                        } else {
                            break;
                        }
                        {
                            uint _e437 = c_2;
                            uint _e440 = c_2;
                            uint _e444 = _group_0_binding_6_cs[(_e440 - 1u)];
                            _group_0_binding_6_cs[_e437] = _e444;
                            uint _e445 = c_2;
                            c_2 = (_e445 - 1u);
                        }
                    }
                    uint _e449 = c_2;
                    _group_0_binding_6_cs[_e449] = v_1;
                }
            }
            s_1 = a_2;
            bool loop_init_9 = true;
            while(true) {
                if (!loop_init_9) {
                    uint _e468 = s_1;
                    s_1 = (_e468 + 1u);
                }
                loop_init_9 = false;
                uint _e455 = s_1;
                if ((_e455 < b_2)) {
                } else {
                    break;
                }
                {
                    uint _e458 = s_1;
                    uint _e462 = s_1;
                    uint _e464 = _group_0_binding_6_cs[_e462];
                    uint _e466 = _group_0_binding_2_cs[_e464];
                    _group_0_binding_6_cs[_e458] = _e466;
                }
            }
            return;
        }
    }
}

