#version 430 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

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
struct Window {
    vec3 sum;
    float weight;
    uint covered;
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
const uint PERIOD = 8u;

layout(std140) uniform VplParams_block_0Compute { VplParams _group_0_binding_0_cs; };

layout(std430) readonly buffer type_6_block_1Compute { vec4 _group_0_binding_1_cs[]; };

layout(std430) readonly buffer type_6_block_2Compute { vec4 _group_0_binding_2_cs[]; };

layout(std430) buffer type_6_block_3Compute { vec4 _group_0_binding_3_cs[]; };


float inv_sigma_z(float z) {
    return (1.0 / (DEPTH_SIGMA * z));
}

uint window_start(uint x, uint size) {
    uint half_ = (size / 2u);
    return (max(x, half_) - half_);
}

uint window_end(uint x_1, uint size_1, uint extent) {
    return min(((x_1 + size_1) - (size_1 / 2u)), extent);
}

uint wide_window(uint period) {
    return (2u * period);
}

bool misses_subset(uint covered, uint period_1) {
    return (covered < (period_1 * period_1));
}

vec3 filtered_irradiance(vec3 e, vec3 sum, float weight) {
    if ((weight > 0.0)) {
        return (sum / vec3(weight));
    }
    return e;
}

float bilateral_weight(vec3 n, vec3 nj, float z_1, float zj, float inv_sz) {
    float dn = max(dot(n, nj), 0.0);
    float dn2_ = (dn * dn);
    float dn4_ = (dn2_ * dn2_);
    float dn8_ = (dn4_ * dn4_);
    float d = ((zj - z_1) * inv_sz);
    float t = max((1.0 - (d * d)), 0.0);
    return (((dn8_ * dn8_) * t) * t);
}

Window window_sum(uint x_2, uint y, uint size_2, vec3 n_1, float z_2, float inv) {
    Window win = Window(vec3(0.0), 0.0, 0u);
    uint yy = 0u;
    uint xx = 0u;
    uint w = _group_0_binding_0_cs.width;
    uint h = _group_0_binding_0_cs.height;
    uint _e12 = window_start(x_2, size_2);
    uint _e13 = window_end(x_2, size_2, w);
    uint _e14 = window_start(y, size_2);
    uint _e15 = window_end(y, size_2, h);
    win.sum = vec3(0.0);
    win.weight = 0.0;
    win.covered = 0u;
    yy = _e14;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e63 = yy;
            yy = (_e63 + 1u);
        }
        loop_init = false;
        uint _e25 = yy;
        if ((_e25 < _e15)) {
        } else {
            break;
        }
        {
            xx = _e12;
            bool loop_init_1 = true;
            while(true) {
                if (!loop_init_1) {
                    uint _e60 = xx;
                    xx = (_e60 + 1u);
                }
                loop_init_1 = false;
                uint _e28 = xx;
                if ((_e28 < _e13)) {
                } else {
                    break;
                }
                {
                    uint _e30 = yy;
                    uint _e32 = xx;
                    uint j = ((_e30 * w) + _e32);
                    vec4 g = _group_0_binding_1_cs[j];
                    float _e39 = bilateral_weight(n_1, g.xyz, z_2, g.w, inv);
                    vec3 _e41 = win.sum;
                    vec4 _e44 = _group_0_binding_2_cs[j];
                    win.sum = (_e41 + (_e44.xyz * _e39));
                    float _e49 = win.weight;
                    win.weight = (_e49 + _e39);
                    uint _e52 = win.covered;
                    win.covered = (_e52 + ((_e39 > COVER_WEIGHT) ? 1u : 0u));
                }
            }
        }
    }
    Window _e65 = win;
    return _e65;
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    bool local = false;
    Window s = Window(vec3(0.0), 0.0, 0u);
    uint w_1 = _group_0_binding_0_cs.width;
    uint h_1 = _group_0_binding_0_cs.height;
    if (!((gid.x >= w_1))) {
        local = (gid.y >= h_1);
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    uint i = ((gid.y * w_1) + gid.x);
    vec4 e_1 = _group_0_binding_2_cs[i];
    vec4 g_1 = _group_0_binding_1_cs[i];
    if (all(equal(g_1.xyz, vec3(0.0)))) {
        _group_0_binding_3_cs[i] = vec4(0.0, 0.0, 0.0, e_1.w);
        return;
    }
    vec3 n_2 = g_1.xyz;
    float z_3 = g_1.w;
    float _e40 = inv_sigma_z(z_3);
    Window _e44 = window_sum(gid.x, gid.y, PERIOD, n_2, z_3, _e40);
    s = _e44;
    uint _e47 = s.covered;
    bool _e49 = misses_subset(_e47, PERIOD);
    if (_e49) {
        uint _e53 = wide_window(PERIOD);
        Window _e54 = window_sum(gid.x, gid.y, _e53, n_2, z_3, _e40);
        s = _e54;
    }
    vec3 _e59 = s.sum;
    float _e61 = s.weight;
    vec3 _e62 = filtered_irradiance(e_1.xyz, _e59, _e61);
    _group_0_binding_3_cs[i] = vec4(_e62, e_1.w);
    return;
}

