#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

struct GpuLight {
    vec3 p0_;
    uint kind;
    vec3 p1_;
    float a;
    vec3 p2_;
    float b;
    vec3 intensity;
    uint ies_base;
};
struct VplParams {
    uint width;
    uint height;
    uint lights_per_subset;
    float min_d2_;
    float near_r2_;
    uint subset_shift;
    uint far_groups_at;
    uint near_clusters_at;
    uint near_groups_at;
    uint box_count;
    uint pad0_;
    uint pad1_;
    uvec4 far_grid;
    uvec4 near_grid;
};
struct GpuBox {
    vec3 lo;
    float pad0_;
    vec3 hi;
    float pad1_;
};
struct ViewParams {
    vec4 c0_;
    vec4 c1_;
    vec4 c2_;
    vec4 c3_;
    vec3 eye;
    uint width;
    uint height;
    float shadow_offset;
    uint seed;
    uint frame;
    vec3 f0_d;
    float f90_d;
};
struct WorkgroupBox {
    vec3 lo;
    vec3 hi;
};
struct GbTexel {
    vec4 position;
    vec4 normal;
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
const uint P = 8u;
const uint TILE = 8u;
const uint THREADS = 64u;
const uint BOX_THREADS = 64u;
const uint MAX_TILE_LIGHTS = 1024u;

shared vec3 wg_lo[64];

shared vec3 wg_hi[64];

shared WorkgroupBox wg_box;

layout(std140) uniform VplParams_block_0Compute { VplParams _group_0_binding_0_cs; };

layout(std140) uniform ViewParams_block_1Compute { ViewParams _group_0_binding_1_cs; };

uniform sampler2D _group_0_binding_2_cs;

uniform sampler2D _group_0_binding_3_cs;

layout(std430) readonly buffer type_9_block_2Compute { GpuLight _group_0_binding_4_cs[]; };

layout(std430) readonly buffer type_5_block_3Compute { float _group_0_binding_5_cs[]; };

layout(std430) readonly buffer type_5_block_4Compute { float _group_0_binding_6_cs[]; };

layout(std430) readonly buffer type_10_block_5Compute { GpuBox _group_0_binding_7_cs[]; };

layout(std430) buffer type_11_block_6Compute { vec4 _group_0_binding_8_cs[]; };

layout(std430) buffer type_11_block_7Compute { vec4 _group_0_binding_9_cs[]; };

layout(std430) buffer type_13_block_8Compute { uint _group_0_binding_12_cs[]; };

shared uint wg_counts[7];

vec3 pos = vec3(0.0);

vec3 nrm = vec3(0.0);

float eye_distance = 0.0;

bool valid = false;

vec3 e = vec3(0.0);

uint kept = 0u;

shared uint tile_lights[1024];

shared uint list_count;

shared uint cluster_hits[64];

shared uint hit_count;


float slc_weight(float rt2_, float d2_) {
    if ((d2_ <= rt2_)) {
        return 1.0;
    }
    return (d2_ / rt2_);
}

bool slc_keep(float r2_, float d2_1) {
    return (d2_1 < r2_);
}

float cull_radius(float r2_1) {
    return (sqrt(r2_1) * CULL_RADIUS_SCALE);
}

bool sphere_overlaps_aabb(vec3 c, float r, vec3 bmin, vec3 bmax) {
    vec3 q = clamp(c, bmin, bmax);
    vec3 v_1 = (q - c);
    return (dot(v_1, v_1) <= (r * r));
}

uint groups_across(uint bw, uint gw) {
    return (((bw + gw) - 1u) / gw);
}

uint group_count(uint bw_1, uint bh, uint gw_1, uint gh) {
    uint _e4 = groups_across(bw_1, gw_1);
    uint _e5 = groups_across(bh, gh);
    return (_e4 * _e5);
}

uint group_first(uint g, uint bw_2, uint bh_1, uint gw_2, uint gh_1) {
    uint _e5 = groups_across(bw_2, gw_2);
    uint gx = (g % _e5);
    uint gy = (g / _e5);
    uint h_1 = min(gh_1, (bh_1 - (gh_1 * gy)));
    return (((gy * gh_1) * bw_2) + ((gx * gw_2) * h_1));
}

uint group_clusters(uint g_1, uint bw_3, uint bh_2, uint gw_3, uint gh_2) {
    uint _e5 = groups_across(bw_3, gw_3);
    uint gx_1 = (g_1 % _e5);
    uint gy_1 = (g_1 / _e5);
    return (min(gw_3, (bw_3 - (gw_3 * gx_1))) * min(gh_2, (bh_2 - (gh_2 * gy_1))));
}

bool box_overlaps_box(vec3 lo1_, vec3 hi1_, vec3 lo2_, vec3 hi2_) {
    bool local_1 = false;
    bool local_2 = false;
    bool local_3 = false;
    bool local_4 = false;
    bool local_5 = false;
    if ((lo1_.x <= hi2_.x)) {
        local_1 = (lo2_.x <= hi1_.x);
    } else {
        local_1 = false;
    }
    bool _e13 = local_1;
    if (_e13) {
        local_2 = (lo1_.y <= hi2_.y);
    } else {
        local_2 = false;
    }
    bool _e20 = local_2;
    if (_e20) {
        local_3 = (lo2_.y <= hi1_.y);
    } else {
        local_3 = false;
    }
    bool _e27 = local_3;
    if (_e27) {
        local_4 = (lo1_.z <= hi2_.z);
    } else {
        local_4 = false;
    }
    bool _e34 = local_4;
    if (_e34) {
        local_5 = (lo2_.z <= hi1_.z);
    } else {
        local_5 = false;
    }
    bool _e41 = local_5;
    return _e41;
}

float vpl_transfer(vec3 n_l, vec3 n_x, vec3 v, float min_d2_) {
    float m = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0.0) * max(-(dot(n_x, v)), 0.0)) * INV_PI) / (m * m));
}

uint shifted_subset(uint pixel_class, uint shift, uint period) {
    return ((pixel_class + shift) % (period * period));
}

float vpl_near_weight(float d2_2, float near_r2_) {
    if ((near_r2_ <= 0.0)) {
        return 0.0;
    }
    float t = clamp(((near_r2_ - d2_2) / (0.75 * near_r2_)), 0.0, 1.0);
    return ((t * t) * (3.0 - (2.0 * t)));
}

float vpl_far_weight(float d2_3, float near_r2_1) {
    float _e2 = vpl_near_weight(d2_3, near_r2_1);
    return (1.0 - _e2);
}

float vpl_far_slc_share(float rt2_1, float r2_2, float d2_4, float near_r2_2) {
    float _e4 = vpl_far_weight(d2_4, near_r2_2);
    float _e5 = slc_weight(rt2_1, d2_4);
    bool _e7 = slc_keep(r2_2, d2_4);
    return ((_e7 && (_e4 > 0.0)) ? (_e4 * _e5) : 0.0);
}

WorkgroupBox workgroup_bounds(uint li_1, vec3 lo, vec3 hi) {
    uint stride = 32u;
    wg_lo[li_1] = lo;
    wg_hi[li_1] = hi;
    memoryBarrierShared();
    barrier();
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e36 = stride;
            stride = (_e36 / 2u);
        }
        loop_init = false;
        uint _e9 = stride;
        if ((_e9 > 0u)) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if ((li_1 < _e12)) {
                vec3 _e18 = wg_lo[li_1];
                uint _e20 = stride;
                vec3 _e23 = wg_lo[(li_1 + _e20)];
                wg_lo[li_1] = min(_e18, _e23);
                vec3 _e29 = wg_hi[li_1];
                uint _e31 = stride;
                vec3 _e34 = wg_hi[(li_1 + _e31)];
                wg_hi[li_1] = max(_e29, _e34);
            }
            memoryBarrierShared();
            barrier();
        }
    }
    if ((li_1 == 0u)) {
        vec3 _e44 = wg_lo[0];
        vec3 _e47 = wg_hi[0];
        wg_box = WorkgroupBox(_e44, _e47);
    }
    memoryBarrierShared();
    barrier();
    WorkgroupBox _e50 = wg_box;
    memoryBarrierShared();
    barrier();
    return _e50;
}

WorkgroupBox point_box(vec3 p, bool has) {
    return WorkgroupBox((has ? p : vec3(3.4028235e38)), (has ? p : vec3(-3.4028235e38)));
}

WorkgroupBox workgroup_box(uint li_2, vec3 p_1, bool has_1) {
    WorkgroupBox _e3 = point_box(p_1, has_1);
    WorkgroupBox _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi);
    return _e6;
}

bool box_is_empty(WorkgroupBox b) {
    return (b.lo.x > b.hi.x);
}

vec4 surface_at(ivec2 texel) {
    vec4 p_4 = texelFetch(_group_0_binding_2_cs, texel, 0);
    return ((p_4.w > 0.0) ? vec4(p_4.xyz, 1.0) : vec4(0.0));
}

GbTexel gbuffer_at(uint i) {
    bool local_6 = false;
    uint _e3 = _group_0_binding_1_cs.width;
    uint _e8 = _group_0_binding_1_cs.width;
    ivec2 texel_1 = ivec2(int((i % _e3)), int((i / _e8)));
    vec4 _e12 = surface_at(texel_1);
    vec4 _e15 = texelFetch(_group_0_binding_3_cs, texel_1, 0);
    vec3 n_3 = _e15.xyz;
    float len2_ = dot(n_3, n_3);
    if ((_e12.w > 0.0)) {
        local_6 = (len2_ > 0.0);
    } else {
        local_6 = false;
    }
    bool valid_1 = local_6;
    vec3 _e30 = _group_0_binding_1_cs.eye;
    vec3 v_2 = (_e12.xyz - _e30);
    vec4 position = vec4(_e12.xyz, (valid_1 ? 1.0 : 0.0));
    vec4 normal = (valid_1 ? vec4((n_3 / vec3(sqrt(len2_))), sqrt(dot(v_2, v_2))) : vec4(0.0, 0.0, 0.0, 1e30));
    return GbTexel(position, normal);
}

void counter_add(uint f, uint n) {
    uint _e6 = atomicAdd(_group_0_binding_12_cs[(2u * f)], n);
    if (((_e6 + n) < _e6)) {
        uint _e16 = atomicAdd(_group_0_binding_12_cs[((2u * f) + 1u)], 1u);
        return;
    } else {
        return;
    }
}

void counts_begin(uint li_3) {
    if ((li_3 < COUNT_FIELDS)) {
        atomicExchange(wg_counts[li_3], 0u);
    }
    memoryBarrierShared();
    barrier();
    return;
}

void count_add(uint f_1, uint n_1) {
    uint _e4 = atomicAdd(wg_counts[f_1], n_1);
    return;
}

void count_one(uint f_2) {
    uint _e4 = atomicAdd(wg_counts[f_2], 1u);
    return;
}

void count_tests(uint li_4, uint f_3, uint n_2) {
    if ((li_4 == 0u)) {
        uint _e7 = atomicAdd(wg_counts[f_3], n_2);
        return;
    } else {
        return;
    }
}

void counts_end(uint li_5) {
    memoryBarrierShared();
    barrier();
    if ((li_5 < COUNT_FIELDS)) {
        uint _e5 = atomicOr(wg_counts[li_5], 0u);
        counter_add(li_5, _e5);
        return;
    } else {
        return;
    }
}

WorkgroupBox load_receiver(uint li_6, uint pix, bool inside) {
    vec4 p_2 = vec4(0.0);
    bool local_7 = false;
    eye_distance = DEPTH_NONE;
    if (inside) {
        GbTexel _e8 = gbuffer_at(pix);
        p_2 = _e8.position;
        nrm = _e8.normal.xyz;
        eye_distance = _e8.normal.w;
    }
    vec4 _e17 = p_2;
    pos = _e17.xyz;
    if (inside) {
        float _e23 = p_2.w;
        local_7 = (_e23 > 0.0);
    } else {
        local_7 = false;
    }
    bool _e27 = local_7;
    valid = _e27;
    counts_begin(li_6);
    bool _e29 = valid;
    if (_e29) {
        count_one(COUNT_PIXELS);
    }
    vec3 _e32 = pos;
    bool _e34 = valid;
    WorkgroupBox _e35 = workgroup_box(li_6, _e32, _e34);
    return _e35;
}

void count_receiver(uint li_7) {
    bool _e2 = valid;
    if (_e2) {
        uint _e5 = kept;
        count_add(COUNT_KEPT, _e5);
    }
    counts_end(li_7);
    return;
}

void shade_light(uint j) {
    GpuLight l = _group_0_binding_4_cs[j];
    vec3 _e5 = pos;
    vec3 v_3 = (_e5 - l.p0_);
    float _e10 = _group_0_binding_5_cs[j];
    float _e13 = _group_0_binding_6_cs[j];
    float _e17 = _group_0_binding_0_cs.near_r2_;
    float _e18 = vpl_far_slc_share(_e10, _e13, dot(v_3, v_3), _e17);
    if ((_e18 > 0.0)) {
        vec3 _e23 = nrm;
        float _e26 = _group_0_binding_0_cs.min_d2_;
        float _e27 = vpl_transfer(l.p1_, _e23, v_3, _e26);
        float t_1 = (_e27 * _e18);
        vec3 _e30 = e;
        e = (_e30 + (l.intensity * t_1));
        uint _e35 = kept;
        kept = (_e35 + 1u);
        return;
    } else {
        return;
    }
}

uint cluster_slot(uint c_1, uint k) {
    return ((c_1 * CLUSTER) + k);
}

float cull_r2_of(uint slot) {
    float _e3 = _group_0_binding_6_cs[slot];
    return _e3;
}

void shade_list(uint count) {
    uint k_1 = 0u;
    bool _e2 = valid;
    if (_e2) {
        bool loop_init_1 = true;
        while(true) {
            if (!loop_init_1) {
                uint _e12 = k_1;
                k_1 = (_e12 + 1u);
            }
            loop_init_1 = false;
            uint _e5 = k_1;
            if ((_e5 < count)) {
            } else {
                break;
            }
            {
                uint _e8 = k_1;
                uint _e10 = tile_lights[_e8];
                shade_light(_e10);
            }
        }
        count_add(COUNT_TESTED, count);
        return;
    } else {
        return;
    }
}

void list_clear(uint li_8) {
    if ((li_8 == 0u)) {
        atomicExchange(list_count, 0u);
        return;
    } else {
        return;
    }
}

bool list_full() {
    memoryBarrierShared();
    barrier();
    uint _e1 = list_count;
    memoryBarrierShared();
    barrier();
    return ((_e1 + CLUSTER) > MAX_TILE_LIGHTS);
}

void list_add(uint slot_1, vec3 p_3, float radius) {
    uint _e6 = atomicAdd(list_count, 1u);
    tile_lights[_e6] = slot_1;
    return;
}

void list_shade() {
    memoryBarrierShared();
    barrier();
    uint _e1 = list_count;
    memoryBarrierShared();
    barrier();
    shade_list(_e1);
    return;
}

void cull_tile(uint li_9, vec3 lo_1, vec3 hi_1, uvec4 grid, uint clusters_at, uint groups_at) {
    uint g_2 = 0u;
    uint h = 0u;
    list_clear(li_9);
    uint _e10 = group_count(grid.x, grid.y, grid.z, grid.w);
    count_tests(li_9, COUNT_GROUP_TESTS, _e10);
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e87 = g_2;
            g_2 = (_e87 + 1u);
        }
        loop_init_2 = false;
        uint _e14 = g_2;
        if ((_e14 < _e10)) {
        } else {
            break;
        }
        {
            uint _e17 = g_2;
            GpuBox gb = _group_0_binding_7_cs[(groups_at + _e17)];
            bool _e23 = box_overlaps_box(gb.lo, gb.hi, lo_1, hi_1);
            if (!(_e23)) {
                continue;
            }
            uint _e25 = g_2;
            uint _e30 = group_first(_e25, grid.x, grid.y, grid.z, grid.w);
            uint first = (clusters_at + _e30);
            uint _e32 = g_2;
            uint _e37 = group_clusters(_e32, grid.x, grid.y, grid.z, grid.w);
            count_tests(li_9, COUNT_CLUSTER_TESTS, _e37);
            if ((li_9 == 0u)) {
                atomicExchange(hit_count, 0u);
            }
            memoryBarrierShared();
            barrier();
            if ((li_9 < _e37)) {
                GpuBox cb = _group_0_binding_7_cs[(first + li_9)];
                bool _e50 = box_overlaps_box(cb.lo, cb.hi, lo_1, hi_1);
                if (_e50) {
                    uint _e54 = atomicAdd(hit_count, 1u);
                    cluster_hits[_e54] = (first + li_9);
                }
            }
            memoryBarrierShared();
            barrier();
            uint _e58 = hit_count;
            memoryBarrierShared();
            barrier();
            h = 0u;
            bool loop_init_3 = true;
            while(true) {
                if (!loop_init_3) {
                    uint _e84 = h;
                    h = (_e84 + 1u);
                }
                loop_init_3 = false;
                uint _e61 = h;
                if ((_e61 < _e58)) {
                } else {
                    break;
                }
                {
                    bool _e63 = list_full();
                    if (_e63) {
                        list_shade();
                        memoryBarrierShared();
                        barrier();
                        list_clear(li_9);
                        memoryBarrierShared();
                        barrier();
                    }
                    uint _e65 = h;
                    uint _e67 = cluster_hits[_e65];
                    uint _e68 = cluster_slot(_e67, li_9);
                    GpuLight l_1 = _group_0_binding_4_cs[_e68];
                    if (any(notEqual(l_1.intensity, vec3(0.0)))) {
                        count_one(COUNT_SPHERE_TESTS);
                        float _e78 = cull_r2_of(_e68);
                        float _e79 = cull_radius(_e78);
                        bool _e81 = sphere_overlaps_aabb(l_1.p0_, _e79, lo_1, hi_1);
                        if (_e81) {
                            list_add(_e68, l_1.p0_, _e79);
                        }
                    }
                }
            }
            memoryBarrierShared();
            barrier();
        }
    }
    list_shade();
    return;
}

void main() {
    if (gl_LocalInvocationID == uvec3(0u)) {
        wg_lo = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_hi = vec3[64](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
        wg_box = WorkgroupBox(vec3(0.0), vec3(0.0));
        wg_counts = uint[7](0u, 0u, 0u, 0u, 0u, 0u, 0u);
        tile_lights = uint[1024](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
        list_count = 0u;
        cluster_hits = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
        hit_count = 0u;
    }
    memoryBarrierShared();
    barrier();
    uvec3 wg = gl_WorkGroupID;
    uvec3 lid = gl_LocalInvocationID;
    uint li = gl_LocalInvocationIndex;
    bool local = false;
    uint sub = wg.z;
    uint px = ((sub % P) + (((wg.x * TILE) + lid.x) * P));
    uint py = ((sub / P) + (((wg.y * TILE) + lid.y) * P));
    uint _e26 = _group_0_binding_0_cs.width;
    if ((px < _e26)) {
        uint _e32 = _group_0_binding_0_cs.height;
        local = (py < _e32);
    } else {
        local = false;
    }
    bool inside_1 = local;
    uint _e38 = _group_0_binding_0_cs.width;
    uint pix_1 = ((py * _e38) + px);
    WorkgroupBox _e41 = load_receiver(li, pix_1, inside_1);
    uint _e44 = _group_0_binding_0_cs.subset_shift;
    uint _e46 = shifted_subset(sub, _e44, P);
    bool _e47 = box_is_empty(_e41);
    if (!(_e47)) {
        count_tests(li, COUNT_TILES, 1u);
        uvec4 grid_1 = _group_0_binding_0_cs.far_grid;
        uint _e58 = _group_0_binding_0_cs.lights_per_subset;
        uint _e64 = _group_0_binding_0_cs.far_groups_at;
        uint _e69 = group_count(grid_1.x, grid_1.y, grid_1.z, grid_1.w);
        cull_tile(li, _e41.lo, _e41.hi, grid_1, (_e46 * (_e58 / CLUSTER)), (_e64 + (_e46 * _e69)));
    }
    count_receiver(li);
    if (inside_1) {
        vec3 _e75 = e;
        uint _e77 = kept;
        _group_0_binding_8_cs[pix_1] = vec4(_e75, float(_e77));
        vec3 _e83 = nrm;
        float _e85 = eye_distance;
        _group_0_binding_9_cs[pix_1] = vec4(_e83, _e85);
        return;
    } else {
        return;
    }
}

