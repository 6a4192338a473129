// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size2;
    uint size3;
    uint size8;
    uint size9;
    uint size10;
    uint size11;
    uint size12;
};

struct GpuLight {
    metal::packed_float3 p0_;
    uint kind;
    metal::packed_float3 p1_;
    float a;
    metal::packed_float3 p2_;
    float b;
    metal::packed_float3 intensity;
    uint ies_base;
};
struct GpuGeoNode {
    metal::packed_float3 bmin;
    uint first;
    metal::packed_float3 bmax;
    uint count;
};
struct GpuTriangle {
    metal::packed_float3 v0_;
    uint material;
    metal::packed_float3 v1_;
    uint light;
    metal::packed_float3 v2_;
    uint pad;
};
struct ViewParams {
    metal::float4 c0_;
    metal::float4 c1_;
    metal::float4 c2_;
    metal::float4 c3_;
    metal::packed_float3 eye;
    uint width;
    uint height;
    float shadow_offset;
    uint seed;
    uint frame;
    metal::packed_float3 f0_d;
    float f90_d;
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
struct GeoHit {
    float t;
    uint tri;
};
typedef GpuGeoNode type_7[1];
typedef GpuTriangle type_8[1];
struct type_9 {
    uint inner[64];
};
typedef GpuLight type_12[1];
typedef BshNode type_13[1];
typedef metal::atomic_uint type_15[1];
struct type_16 {
    uint inner[8];
};
typedef uint BshNodes;
struct Connection {
    metal::float3 e;
    metal::packed_float3 y;
    float cos_x;
};
struct type_19 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
};
struct type_20 {
    uint inner[1024];
};
struct type_21 {
    uint inner[256];
};
struct TileWalk {
    metal::float3 lo;
    metal::packed_float3 hi;
    float w;
    uint total;
    char _pad4[12];
};
struct Shaded {
    metal::float3 e;
    metal::float3 diffuse;
    metal::float3 specular;
};
struct Material {
    metal::packed_float3 base;
    float metallic;
    float alpha;
    char _pad3[12];
    metal::packed_float3 v;
    float roughness;
    float reflectance;
    char _pad6[12];
};
struct type_23 {
    metal::uint2 inner[8];
};
struct type_24 {
    bool inner[8];
};
struct type_26 {
    metal::float2 inner[8];
};
struct type_27 {
    float inner[8];
};
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
constant uint K = 8u;
constant BshNodes BSH = 0u;
constant uint BSH_TILE_DEPTH = 8u;
constant uint BSH_TILE_SUBTREES = 256u;
constant uint TILE_THREADS = 64u;
constant uint BOX_THREADS = 64u;
constant uint TILE_LIST = 1024u;

float to_f32_(
    uint u
) {
    return static_cast<float>(u);
}

uint mul_lo_u32_(
    uint a,
    uint b
) {
    return a * b;
}

uint add_wrap_u32_(
    uint a_1,
    uint b_1
) {
    return a_1 + b_1;
}

float f32_from_bits(
    uint u_1
) {
    return as_type<float>(u_1);
}

float xi_from_bits(
    uint bits
) {
    float _e3 = to_f32_(bits >> 8u);
    return _e3 * XI_STEP;
}

uint pcg_hash(
    uint x
) {
    uint _e2 = mul_lo_u32_(x, 747796405u);
    uint _e4 = add_wrap_u32_(_e2, 2891336453u);
    uint _e12 = mul_lo_u32_((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4, 277803737u);
    return (_e12 >> 22u) ^ _e12;
}

uint point_stream(
    uint seed,
    uint point,
    uint frame
) {
    uint _e3 = pcg_hash(frame);
    uint _e5 = pcg_hash(point ^ _e3);
    uint _e7 = pcg_hash(seed ^ _e5);
    return _e7;
}

uint pick_stream(
    uint stream
) {
    uint _e3 = pcg_hash(stream ^ PICK_STREAM);
    return _e3;
}

float slc_weight(
    float rt2_,
    float d2_
) {
    if (d2_ <= rt2_) {
        return 1.0;
    }
    return d2_ / rt2_;
}

bool slc_keep(
    float r2_,
    float d2_1
) {
    return d2_1 < r2_;
}

bool sphere_contains_point(
    metal::float3 c,
    float r_1,
    metal::float3 x_1
) {
    metal::float3 v_2 = x_1 - c;
    return metal::dot(v_2, v_2) <= (r_1 * r_1);
}

bool sphere_overlaps_aabb(
    metal::float3 c_1,
    float r_2,
    metal::float3 bmin,
    metal::float3 bmax
) {
    metal::float3 q_1 = metal::clamp(c_1, bmin, bmax);
    metal::float3 v_3 = q_1 - c_1;
    return metal::dot(v_3, v_3) <= (r_2 * r_2);
}

float inverse_square(
    float d2_2
) {
    return 1.0 / metal::max(d2_2, MIN_D2_);
}

float connection_factor(
    float cos_x,
    float d2_3,
    float rt2_1,
    float w_1
) {
    float _e4 = inverse_square(d2_3);
    float _e6 = slc_weight(rt2_1, d2_3);
    return ((cos_x * _e4) * _e6) * w_1;
}

float connection_cosine(
    metal::float3 x_2,
    metal::float3 y,
    metal::float3 n_1,
    metal::float3 ng,
    float r2_1
) {
    bool local_7 = {};
    bool local_8 = {};
    metal::float3 v_4 = x_2 - y;
    float d2_6 = metal::dot(v_4, v_4);
    bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local_7 = !((d2_6 > 0.0));
    } else {
        local_7 = true;
    }
    bool _e16 = local_7;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_10 = v_4 / metal::float3(metal::sqrt(d2_6));
    float cos_x_1 = -(metal::dot(n_1, w_10));
    if (!(!((cos_x_1 > 0.0)))) {
        local_8 = !((metal::dot(ng, w_10) < 0.0));
    } else {
        local_8 = true;
    }
    bool _e34 = local_8;
    if (_e34) {
        return 0.0;
    }
    return cos_x_1;
}

float spot_falloff(
    float cos_theta,
    float cos_outer,
    float cos_inner,
    float shape
) {
    if (cos_inner <= cos_outer) {
        return (cos_theta >= cos_outer) ? 1.0 : 0.0;
    }
    float t_4 = metal::saturate((cos_theta - cos_outer) / (cos_inner - cos_outer));
    return (shape > 0.5) ? (t_4 * t_4) : ((t_4 * t_4) * (3.0 - (2.0 * t_4)));
}

float bsh_scaled_radius(
    BshNode node,
    float scale
) {
    if (scale == 1.0) {
        return node.radius;
    }
    if (node.child == BSH_NONE) {
        return node.extent + (scale * (node.radius - node.extent));
    }
    return node.radius * scale;
}

float bsh_range_bound(
    BshNode node_1
) {
    if (node_1.child == BSH_NONE) {
        return node_1.radius - node_1.extent;
    }
    float _e8 = f32_from_bits(node_1.light);
    return _e8;
}

float bsh_reach_bound(
    BshNode node_2,
    float w_2
) {
    float _e5 = bsh_range_bound(node_2);
    return node_2.extent + ((w_2 * 1.001) * _e5);
}

float weighted_threshold(
    float w_sum,
    float u_2
) {
    return w_sum / (1.0 - u_2);
}

float resample_target(
    metal::float3 c_2
) {
    return ((c_2.x + c_2.y) + c_2.z) * 0.33333334;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

float slot_target(
    metal::float3 c_3,
    uint slot,
    uint k_2
) {
    if (k_2 < 3u) {
        float _e5 = resample_target(c_3);
        return _e5;
    }
    uint j_3 = naga_mod(slot, 3u);
    if (j_3 == 0u) {
        return c_3.x;
    }
    if (j_3 == 1u) {
        return c_3.y;
    }
    return c_3.z;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

metal::float3 slot_share(
    uint slot_1,
    uint k_3
) {
    if (k_3 < 3u) {
        float _e4 = to_f32_(k_3);
        float w_11 = 1.0 / _e4;
        return metal::float3(w_11, w_11, w_11);
    }
    uint j_4 = naga_mod(slot_1, 3u);
    float _e15 = to_f32_(naga_div((k_3 + 2u) - j_4, 3u));
    float w_12 = 1.0 / _e15;
    if (j_4 == 0u) {
        return metal::float3(w_12, 0.0, 0.0);
    }
    if (j_4 == 1u) {
        return metal::float3(0.0, w_12, 0.0);
    }
    return metal::float3(0.0, 0.0, w_12);
}

float smith_root(
    float cos,
    float alpha
) {
    float a2_ = alpha * alpha;
    return metal::sqrt(((cos * cos) * (1.0 - a2_)) + a2_);
}

float specular_peak_factor(
    metal::float4 lobe_1
) {
    float _e6 = smith_root(lobe_1.w, lobe_1.z);
    return (lobe_1.y * 0.5) / (_e6 + metal::max(lobe_1.w, 0.0));
}

float receiver_peak(
    metal::float4 lobe_2
) {
    float _e2 = specular_peak_factor(lobe_2);
    return lobe_2.x + (_e2 / (lobe_2.z * lobe_2.z));
}

float range_scale(
    metal::float4 lobe_3
) {
    if (lobe_3.y <= 0.0) {
        return 1.0;
    }
    float _e5 = receiver_peak(lobe_3);
    return metal::clamp(_e5, 1.0, RANGE_SCALE_MAX);
}

metal::float4 range_lobe(
    metal::float4 lobe_4
) {
    if (lobe_4.y <= 0.0) {
        return metal::float4(1.0, 0.0, 1.0, 1.0);
    }
    float _e10 = specular_peak_factor(lobe_4);
    float _e14 = range_scale(lobe_4);
    return metal::float4(lobe_4.x, _e10, lobe_4.z * lobe_4.z, metal::sqrt(_e14));
}

float cone_cos_of(
    metal::float3 v,
    float d2_4,
    float a_2,
    metal::float3 d
) {
    bool local_9 = {};
    bool local_10 = {};
    float vd = metal::dot(v, d);
    float h2_ = d2_4 - (a_2 * a_2);
    if (!((h2_ <= 0.0))) {
        if (vd >= 0.0) {
            local_10 = (vd * vd) >= h2_;
        } else {
            local_10 = false;
        }
        bool _e19 = local_10;
        local_9 = _e19;
    } else {
        local_9 = true;
    }
    bool _e21 = local_9;
    if (_e21) {
        return 1.0;
    }
    metal::float3 c_7 = metal::cross(v, d);
    return metal::min(((vd * metal::sqrt(h2_)) + (metal::sqrt(metal::dot(c_7, c_7)) * a_2)) / d2_4, 1.0);
}

float cone_cos_toward(
    metal::float3 center,
    float radius,
    metal::float3 p,
    metal::float3 d_1
) {
    metal::float3 v_5 = center - p;
    float _e6 = cone_cos_of(v_5, metal::dot(v_5, v_5), radius, d_1);
    return _e6;
}

float range_scale_at(
    metal::float4 rl,
    float cos_t
) {
    float t_5 = ((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0;
    return metal::clamp(rl.x + ((rl.y * rl.z) / (t_5 * t_5)), 1.0, rl.w * rl.w);
}

float range_scale_toward(
    metal::float4 rl_1,
    metal::float3 center_1,
    float radius_1,
    metal::float3 p_1,
    metal::float3 r_3
) {
    if (rl_1.w <= 1.0) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_3);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

float shadow_margin(
    float len
) {
    return 0.0001 * len;
}

float ray_inverse(
    float x_3
) {
    return 1.0 / ((metal::abs(x_3) < 0.000000000000000000000000000001) ? 0.000000000000000000000000000001 : x_3);
}

metal::float3 ray_inverse3_(
    metal::float3 d_2
) {
    float _e2 = ray_inverse(d_2.x);
    float _e4 = ray_inverse(d_2.y);
    float _e6 = ray_inverse(d_2.z);
    return metal::float3(_e2, _e4, _e6);
}

float ray_aabb(
    metal::float3 o,
    metal::float3 inv_d,
    metal::float3 bmin_1,
    metal::float3 bmax_1,
    float t_max
) {
    metal::float3 t0_ = (bmin_1 - o) * inv_d;
    metal::float3 t1_ = (bmax_1 - o) * inv_d;
    metal::float3 lo_3 = metal::min(t0_, t1_);
    metal::float3 hi_3 = metal::max(t0_, t1_);
    float t_in = metal::max(metal::max(lo_3.x, lo_3.y), metal::max(lo_3.z, 0.0));
    float t_out = metal::min(metal::min(hi_3.x, hi_3.y), metal::min(hi_3.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1.0;
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_3,
    metal::float3 a_3,
    metal::float3 b_2,
    metal::float3 c_4,
    float t_min,
    float t_max_1
) {
    bool local_11 = {};
    bool local_12 = {};
    bool local_13 = {};
    metal::float3 e1_ = b_2 - a_3;
    metal::float3 e2_ = c_4 - a_3;
    metal::float3 p_5 = metal::cross(d_3, e2_);
    float det = metal::dot(e1_, p_5);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv = 1.0 / det;
    metal::float3 s_10 = o_1 - a_3;
    float u_3 = metal::dot(s_10, p_5) * inv;
    if (!((u_3 < 0.0))) {
        local_11 = u_3 > 1.0;
    } else {
        local_11 = true;
    }
    bool _e28 = local_11;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q_2 = metal::cross(s_10, e1_);
    float v_6 = metal::dot(d_3, q_2) * inv;
    if (!((v_6 < 0.0))) {
        local_12 = (u_3 + v_6) > 1.0;
    } else {
        local_12 = true;
    }
    bool _e42 = local_12;
    if (_e42) {
        return -1.0;
    }
    float t_6 = metal::dot(e2_, q_2) * inv;
    if (t_6 > t_min) {
        local_13 = t_6 < t_max_1;
    } else {
        local_13 = false;
    }
    bool _e51 = local_13;
    if (_e51) {
        return t_6;
    }
    return -1.0;
}

metal::float3 light_intensity(
    GpuLight l,
    metal::float3 w_3
) {
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            float _e11 = spot_falloff(metal::dot(l.p1_, w_3), l.a, l.b, l.p2_[0]);
            return l.intensity * _e11;
        }
        default: {
            return metal::float3(0.0);
        }
    }
}

metal::float3 light_point(
    GpuLight l_1,
    float u1_,
    float u2_
) {
    return l_1.p0_;
}

GeoHit trace(
    metal::float3 o_2,
    metal::float3 d_4,
    float t_min_1,
    float t_max_2,
    bool any_hit,
    thread uint& nodes_visited,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    GeoHit hit = {};
    type_9 stack = {};
    uint sp = 0u;
    uint node_3 = 0u;
    uint i = {};
    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((1 + (_buffer_sizes.size2 - 0 - 32) / 32) == 0u) {
        GeoHit _e13 = hit;
        return _e13;
    }
    metal::float3 _e14 = ray_inverse3_(d_4);
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e21 = node_3;
        GpuGeoNode n_8 = geo_nodes[_e21];
        uint _e25 = nodes_visited;
        nodes_visited = _e25 + 1u;
        float _e31 = hit.t;
        float _e32 = ray_aabb(o_2, _e14, n_8.bmin, n_8.bmax, _e31);
        if (_e32 >= 0.0) {
            if (n_8.count > 0u) {
                i = n_8.first;
                uint2 loop_bound_1 = uint2(4294967295u);
                bool loop_init = true;
                while(true) {
                    if (metal::all(loop_bound_1 == uint2(0u))) { break; }
                    loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                    if (!loop_init) {
                        uint _e62 = i;
                        i = _e62 + 1u;
                    }
                    loop_init = false;
                    uint _e40 = i;
                    if (_e40 < (n_8.first + n_8.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e46 = i;
                        GpuTriangle t_7 = geo_tris[_e46];
                        float _e53 = hit.t;
                        float _e54 = ray_triangle(o_2, d_4, t_7.v0_, t_7.v1_, t_7.v2_, t_min_1, _e53);
                        if (_e54 > 0.0) {
                            hit.t = _e54;
                            uint _e59 = i;
                            hit.tri = _e59;
                            if (any_hit) {
                                GeoHit _e60 = hit;
                                return _e60;
                            }
                        }
                    }
                }
            } else {
                uint _e64 = sp;
                if (_e64 < 64u) {
                    uint _e67 = sp;
                    stack.inner[_e67] = n_8.first + 1u;
                    uint _e72 = sp;
                    sp = _e72 + 1u;
                }
                node_3 = n_8.first;
                continue;
            }
        }
        uint _e76 = sp;
        if (_e76 == 0u) {
            break;
        }
        uint _e79 = sp;
        sp = _e79 - 1u;
        uint _e82 = sp;
        uint _e84 = stack.inner[_e82];
        node_3 = _e84;
    }
    GeoHit _e85 = hit;
    return _e85;
}

bool occluded(
    metal::float3 a_4,
    metal::float3 b_3,
    thread uint& rays_cast,
    thread uint& nodes_visited,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 dv = b_3 - a_4;
    float len_1 = metal::length(dv);
    if (len_1 <= 0.0) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    uint _e9 = rays_cast;
    rays_cast = _e9 + 1u;
    GeoHit _e16 = trace(a_4, dv / metal::float3(len_1), _e7, len_1 - _e7, true, nodes_visited, geo_nodes, geo_tris, _buffer_sizes);
    return _e16.tri != NO_LIGHT;
}

BshNode bsh_node(
    BshNodes nodes,
    uint i_1,
    device type_13 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshNode _e4 = bsh_nodes[i_1];
    return _e4;
}

uint bsh_count(
    BshNodes nodes_1,
    device type_13 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    return 1 + (_buffer_sizes.size11 - 0 - 32) / 32;
}

uint bsh_first(
    BshNodes nodes_2,
    device type_13 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e1 = bsh_count(nodes_2, bsh_nodes, _buffer_sizes);
    if (_e1 > 0u) {
        return 0u;
    }
    return BSH_NONE;
}

float bsh_inner_scale(
    float a_5,
    metal::float3 v_1,
    float d2_5,
    metal::float3 r_4,
    metal::float4 rl_2
) {
    float _e5 = cone_cos_of(v_1, d2_5, a_5, r_4);
    float _e8 = range_scale_at(rl_2, _e5 + 0.000002);
    return _e8;
}

bool bsh_reaches(
    BshNode node_4,
    metal::float3 x_4,
    metal::float3 r_5,
    metal::float4 rl_3
) {
    bool local_14 = {};
    bool local_15 = {};
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_4);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, node_4.radius * (rl_3.w * 1.0001), x_4);
        local_14 = !(_e20);
    } else {
        local_14 = true;
    }
    bool _e23 = local_14;
    if (_e23) {
        return false;
    }
    metal::float3 v_7 = x_4 - node_4.center;
    float d2_7 = metal::dot(v_7, v_7);
    float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_7 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        float _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_4, r_5);
        float _e41 = bsh_scaled_radius(node_4, metal::sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_4);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_7), d2_7, r_5, rl_3);
    float s_c = _e45 * 1.001;
    float _e50 = bsh_range_bound(node_4);
    float reach = node_4.extent + (metal::sqrt(s_c) * _e50);
    if (d2_7 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_15 = d2_7 <= (reach * reach);
    } else {
        local_15 = false;
    }
    bool _e63 = local_15;
    return _e63;
}

bool bsh_reaches_box(
    BshNode node_5,
    metal::float3 lo,
    metal::float3 hi,
    float w_4
) {
    bool _e13 = sphere_overlaps_aabb(node_5.center, node_5.radius * (metal::max(1.0, w_4 * 1.0001) * 1.0001), lo, hi);
    return _e13;
}

uint bsh_subtree(
    BshNodes nodes_3,
    uint s_1,
    uint depth,
    device type_13 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_2 = {};
    uint level = 0u;
    bool local_16 = {};
    uint _e3 = bsh_first(nodes_3, bsh_nodes, _buffer_sizes);
    i_2 = _e3;
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e7 = level;
        if (_e7 < depth) {
            uint _e11 = i_2;
            local_16 = _e11 != BSH_NONE;
        } else {
            local_16 = false;
        }
        bool _e15 = local_16;
        if (_e15) {
        } else {
            break;
        }
        {
            uint _e16 = i_2;
            BshNode _e17 = bsh_node(nodes_3, _e16, bsh_nodes, _buffer_sizes);
            uint _e18 = level;
            uint below = depth - _e18;
            if (_e17.child == BSH_NONE) {
                if ((s_1 << (32u - below)) != 0u) {
                    return BSH_NONE;
                }
                uint _e29 = i_2;
                return _e29;
            }
            if (((s_1 >> (below - 1u)) & 1u) == 0u) {
                i_2 = _e17.child;
            } else {
                BshNode _e39 = bsh_node(nodes_3, _e17.child, bsh_nodes, _buffer_sizes);
                i_2 = _e39.next;
            }
            uint _e41 = level;
            level = _e41 + 1u;
        }
    }
    uint _e44 = i_2;
    return _e44;
}

uint bsh_next_leaf_box(
    BshNodes nodes_4,
    uint start_1,
    uint end,
    metal::float3 lo_1,
    metal::float3 hi_1,
    float w_5,
    device type_13 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_3 = {};
    i_3 = start_1;
    uint2 loop_bound_3 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e7 = i_3;
        if (_e7 != end) {
        } else {
            break;
        }
        {
            uint _e9 = i_3;
            BshNode _e10 = bsh_node(nodes_4, _e9, bsh_nodes, _buffer_sizes);
            bool _e11 = bsh_reaches_box(_e10, lo_1, hi_1, w_5);
            if (_e11) {
                if (_e10.child == BSH_NONE) {
                    if ((_e10.light & BSH_TAIL) == 0u) {
                        uint _e20 = i_3;
                        return _e20;
                    }
                    i_3 = _e10.next;
                } else {
                    i_3 = _e10.child;
                }
            } else {
                i_3 = _e10.next;
            }
        }
    }
    return end;
}

float next_threshold(
    float sum,
    thread uint& h_1
) {
    uint _e2 = h_1;
    uint _e3 = pcg_hash(_e2);
    h_1 = _e3;
    uint _e4 = h_1;
    float _e5 = xi_from_bits(_e4);
    float _e6 = weighted_threshold(sum, _e5);
    return _e6;
}

Connection connect_record(
    GpuLight l_2,
    metal::float3 x_5,
    metal::float3 n_2,
    metal::float3 ng_1,
    float r2_2,
    float rt2_2,
    float w_res,
    float u1_1,
    float u2_1,
    float eps,
    bool trace_1,
    thread uint& rays_cast,
    thread uint& nodes_visited,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection c_5 = {};
    bool local_17 = {};
    bool local_18 = {};
    c_5.e = metal::float3(0.0);
    metal::float3 _e16 = light_point(l_2, u1_1, u2_1);
    c_5.y = _e16;
    metal::float3 _e19 = c_5.y;
    float _e20 = connection_cosine(x_5, _e19, n_2, ng_1, r2_2);
    c_5.cos_x = _e20;
    float _e22 = c_5.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            metal::float3 _e33 = c_5.y;
            bool _e34 = occluded(x_5 + (ng_1 * eps), _e33, rays_cast, nodes_visited, geo_nodes, geo_tris, _buffer_sizes);
            local_18 = _e34;
        } else {
            local_18 = false;
        }
        bool _e36 = local_18;
        local_17 = _e36;
    } else {
        local_17 = true;
    }
    bool _e38 = local_17;
    if (_e38) {
        Connection _e39 = c_5;
        return _e39;
    }
    metal::float3 _e41 = c_5.y;
    metal::float3 v_8 = x_5 - _e41;
    float d2_8 = metal::dot(v_8, v_8);
    metal::float3 _e48 = light_intensity(l_2, v_8 / metal::float3(metal::sqrt(d2_8)));
    float _e50 = c_5.cos_x;
    float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_5.e = _e48 * _e51;
    Connection _e53 = c_5;
    return _e53;
}

Connection connect_traced(
    uint li,
    metal::float3 x_6,
    metal::float3 n_3,
    metal::float3 ng_2,
    float s_2,
    float w_res_1,
    float u1_2,
    float u2_2,
    float eps_1,
    bool trace_2,
    thread uint& rays_cast,
    thread uint& nodes_visited,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_12 const& lights,
    device type_4 const& rt2_3,
    device type_4 const& r2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight _e12 = lights[li];
    float _e15 = r2_3[li];
    float _e19 = rt2_3[li];
    Connection _e21 = connect_record(_e12, x_6, n_3, ng_2, s_2 * _e15, s_2 * _e19, w_res_1, u1_2, u2_2, eps_1, trace_2, rays_cast, nodes_visited, geo_nodes, geo_tris, _buffer_sizes);
    return _e21;
}

metal::float4 surface_at(
    metal::int2 texel,
    metal::texture2d<float, metal::access::sample> position_tex
) {
    metal::float4 p_6 = position_tex.read(metal::uint2(texel), 0);
    return (p_6.w > 0.0) ? metal::float4(p_6.xyz, 1.0) : metal::float4(0.0);
}

WorkgroupBox workgroup_bounds(
    uint li_1,
    metal::float3 lo_2,
    metal::float3 hi_2,
    threadgroup type_19& wg_lo,
    threadgroup type_19& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    uint stride = 32u;
    wg_lo.inner[li_1] = lo_2;
    wg_hi.inner[li_1] = hi_2;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint2 loop_bound_4 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e36 = stride;
            stride = naga_div(_e36, 2u);
        }
        loop_init_1 = false;
        uint _e9 = stride;
        if (_e9 > 0u) {
        } else {
            break;
        }
        {
            uint _e12 = stride;
            if (li_1 < _e12) {
                metal::float3 _e18 = wg_lo.inner[li_1];
                uint _e20 = stride;
                metal::float3 _e23 = wg_lo.inner[li_1 + _e20];
                wg_lo.inner[li_1] = metal::min(_e18, _e23);
                metal::float3 _e29 = wg_hi.inner[li_1];
                uint _e31 = stride;
                metal::float3 _e34 = wg_hi.inner[li_1 + _e31];
                wg_hi.inner[li_1] = metal::max(_e29, _e34);
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (li_1 == 0u) {
        metal::float3 _e44 = wg_lo.inner[0];
        metal::float3 _e47 = wg_hi.inner[0];
        wg_box = WorkgroupBox {_e44, _e47};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    WorkgroupBox unnamed = wg_box;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return unnamed;
}

WorkgroupBox point_box(
    metal::float3 p_2,
    bool has
) {
    return WorkgroupBox {has ? p_2 : metal::float3(340282350000000000000000000000000000000.0), has ? p_2 : metal::float3(-340282350000000000000000000000000000000.0)};
}

WorkgroupBox workgroup_box(
    uint li_2,
    metal::float3 p_3,
    bool has_1,
    threadgroup type_19& wg_lo,
    threadgroup type_19& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    WorkgroupBox _e3 = point_box(p_3, has_1);
    WorkgroupBox _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi, wg_lo, wg_hi, wg_box);
    return _e6;
}

bool box_is_empty(
    WorkgroupBox b_4
) {
    return b_4.lo.x > b_4.hi.x;
}

uint tile_subtree(
    uint s_3,
    TileWalk t_1,
    bool list,
    uint at,
    uint start_2,
    uint to,
    device type_13 const& bsh_nodes,
    threadgroup type_20& tile_list,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint p_4 = {};
    uint b_5 = {};
    bool local_19 = {};
    bool local_20 = {};
    bool local_21 = {};
    uint _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH, bsh_nodes, _buffer_sizes);
    if (_e8 == BSH_NONE) {
        return 0u;
    }
    uint end_1 = bsh_nodes[_e8].next;
    p_4 = at;
    uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_1.lo, t_1.hi, t_1.w, bsh_nodes, _buffer_sizes);
    b_5 = _e21;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e53 = b_5;
            uint _e56 = bsh_nodes[_e53].next;
            uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_1.lo, t_1.hi, t_1.w, bsh_nodes, _buffer_sizes);
            b_5 = _e60;
        }
        loop_init_2 = false;
        uint _e23 = b_5;
        if (_e23 != end_1) {
            if (!(!(list))) {
                uint _e31 = p_4;
                local_20 = _e31 < to;
            } else {
                local_20 = true;
            }
            bool _e34 = local_20;
            local_19 = _e34;
        } else {
            local_19 = false;
        }
        bool _e36 = local_19;
        if (_e36) {
        } else {
            break;
        }
        {
            if (list) {
                uint _e39 = p_4;
                local_21 = _e39 >= start_2;
            } else {
                local_21 = false;
            }
            bool _e42 = local_21;
            if (_e42) {
                uint _e44 = p_4;
                uint _e47 = b_5;
                tile_list.inner[_e44 - start_2] = _e47;
            }
            uint _e48 = p_4;
            p_4 = _e48 + 1u;
        }
    }
    uint _e61 = p_4;
    return _e61 - at;
}

TileWalk tile_walk_begin(
    uint li_3,
    metal::float3 x_7,
    float w_6,
    bool has_2,
    device type_13 const& bsh_nodes,
    threadgroup type_19& wg_lo,
    threadgroup type_19& wg_hi,
    threadgroup WorkgroupBox& wg_box,
    threadgroup type_20& tile_list,
    threadgroup type_21& subtree_at,
    threadgroup metal::atomic_uint& tile_scale,
    threadgroup uint& tile_total,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_22 = {};
    TileWalk t_2 = {};
    uint s_4 = {};
    uint sum_1 = 0u;
    uint s_5 = 0u;
    if (has_2) {
        local_22 = w_6 >= 0.0;
    } else {
        local_22 = false;
    }
    bool _e12 = local_22;
    uint _e14 = metal::atomic_fetch_max_explicit(&tile_scale, _e12 ? as_type<uint>(w_6) : 0u, metal::memory_order_relaxed);
    WorkgroupBox _e15 = workgroup_box(li_3, x_7, has_2, wg_lo, wg_hi, wg_box);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_1 = metal::atomic_load_explicit(&tile_scale, metal::memory_order_relaxed);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    t_2 = TileWalk {_e15.lo, _e15.hi, as_type<float>(unnamed_1), 0u};
    bool _e24 = box_is_empty(_e15);
    if (_e24) {
        TileWalk _e25 = t_2;
        return _e25;
    }
    s_4 = li_3;
    uint2 loop_bound_6 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e40 = s_4;
            s_4 = _e40 + TILE_THREADS;
        }
        loop_init_3 = false;
        uint _e27 = s_4;
        if (_e27 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            uint _e31 = s_4;
            uint _e33 = s_4;
            TileWalk _e34 = t_2;
            uint _e39 = tile_subtree(_e33, _e34, false, 0u, 0u, 0u, bsh_nodes, tile_list, _buffer_sizes);
            subtree_at.inner[_e31] = _e39;
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    if (li_3 == 0u) {
        uint2 loop_bound_7 = uint2(4294967295u);
        bool loop_init_4 = true;
        while(true) {
            if (metal::all(loop_bound_7 == uint2(0u))) { break; }
            loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
            if (!loop_init_4) {
                uint _e63 = s_5;
                s_5 = _e63 + 1u;
            }
            loop_init_4 = false;
            uint _e49 = s_5;
            if (_e49 < BSH_TILE_SUBTREES) {
            } else {
                break;
            }
            {
                uint _e53 = s_5;
                uint c_8 = subtree_at.inner[_e53];
                uint _e57 = s_5;
                uint _e59 = sum_1;
                subtree_at.inner[_e57] = _e59;
                uint _e60 = sum_1;
                sum_1 = _e60 + c_8;
            }
        }
        uint _e66 = sum_1;
        tile_total = _e66;
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_2 = tile_total;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    t_2.total = unnamed_2;
    TileWalk _e70 = t_2;
    return _e70;
}

uint tile_walk_fill(
    uint li_4,
    TileWalk t_3,
    uint start_3,
    device type_13 const& bsh_nodes,
    threadgroup type_20& tile_list,
    threadgroup type_21& subtree_at,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint s_6 = {};
    uint past = {};
    bool local_23 = {};
    uint to_1 = metal::min(t_3.total, start_3 + TILE_LIST);
    s_6 = li_4;
    uint2 loop_bound_8 = uint2(4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e38 = s_6;
            s_6 = _e38 + TILE_THREADS;
        }
        loop_init_5 = false;
        uint _e8 = s_6;
        if (_e8 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            uint _e12 = s_6;
            uint at_1 = subtree_at.inner[_e12];
            past = t_3.total;
            uint _e17 = s_6;
            if ((_e17 + 1u) < BSH_TILE_SUBTREES) {
                uint _e23 = s_6;
                uint _e27 = subtree_at.inner[_e23 + 1u];
                past = _e27;
            }
            if (at_1 < to_1) {
                uint _e31 = past;
                local_23 = _e31 > start_3;
            } else {
                local_23 = false;
            }
            bool _e34 = local_23;
            if (_e34) {
                uint _e35 = s_6;
                uint _e37 = tile_subtree(_e35, t_3, true, at_1, start_3, to_1, bsh_nodes, tile_list, _buffer_sizes);
            }
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return to_1 - start_3;
}

void counter_add(
    uint f,
    uint n_4,
    device type_15& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e6 = metal::atomic_fetch_add_explicit(&counters[2u * f], n_4, metal::memory_order_relaxed);
    if ((_e6 + n_4) < _e6) {
        uint _e16 = metal::atomic_fetch_add_explicit(&counters[(2u * f) + 1u], 1u, metal::memory_order_relaxed);
        return;
    } else {
        return;
    }
}

Shaded shade_connection(
    Connection c_6,
    metal::float3 x_8,
    metal::float3 n_5,
    Material m_1
) {
    Shaded s_7 = {};
    s_7.e = c_6.e;
    s_7.diffuse = metal::float3(0.0);
    s_7.specular = metal::float3(0.0);
    Shaded _e13 = s_7;
    return _e13;
}

Shaded shade_pick_traced(
    uint li_5,
    metal::float3 x_9,
    metal::float3 n_6,
    metal::float3 r_6,
    metal::float4 rl_4,
    Material m_2,
    float w_7,
    float u1_3,
    float u2_3,
    float eps_2,
    bool trace_3,
    thread uint& rays_cast,
    thread uint& nodes_visited,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_12 const& lights,
    device type_4 const& rt2_3,
    device type_4 const& r2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection _e12 = connect_traced(li_5, x_9, n_6, n_6, 1.0, w_7, u1_3, u2_3, eps_2, trace_3, rays_cast, nodes_visited, geo_nodes, geo_tris, lights, rt2_3, r2_3, _buffer_sizes);
    Shaded _e13 = shade_connection(_e12, x_9, n_6, m_2);
    return _e13;
}

Shaded shade_pick(
    uint li_6,
    metal::float3 x_10,
    metal::float3 n_7,
    metal::float3 r_7,
    metal::float4 rl_5,
    Material m_3,
    float w_8,
    float u1_4,
    float u2_4,
    float eps_3,
    thread uint& rays_cast,
    thread uint& nodes_visited,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_12 const& lights,
    device type_4 const& rt2_3,
    device type_4 const& r2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    Shaded _e11 = shade_pick_traced(li_6, x_10, n_7, r_7, rl_5, m_3, w_8, u1_4, u2_4, eps_3, true, rays_cast, nodes_visited, geo_nodes, geo_tris, lights, rt2_3, r2_3, _buffer_sizes);
    return _e11;
}

Shaded add(
    Shaded a_6,
    Shaded b_6
) {
    return Shaded {a_6.e + b_6.e, a_6.diffuse + b_6.diffuse, a_6.specular + b_6.specular};
}

Shaded scaled(
    Shaded s_8,
    metal::float3 w_9
) {
    return Shaded {s_8.e * w_9, s_8.diffuse * w_9, s_8.specular * w_9};
}

type_16 first_holders(
    type_23 keys_1,
    type_24 held_1
) {
    type_16 first = {};
    uint k_4 = 0u;
    uint j_2 = {};
    bool local_24 = {};
    bool local_25 = {};
    uint2 loop_bound_9 = uint2(4294967295u);
    bool loop_init_6 = true;
    while(true) {
        if (metal::all(loop_bound_9 == uint2(0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_6) {
            uint _e45 = k_4;
            k_4 = _e45 + 1u;
        }
        loop_init_6 = false;
        uint _e5 = k_4;
        if (_e5 < K) {
        } else {
            break;
        }
        {
            uint _e8 = k_4;
            uint _e11 = k_4;
            uint _e12 = k_4;
            first.inner[_e8] = held_1.inner[_e12] ? _e11 : K;
            j_2 = 0u;
            uint2 loop_bound_10 = uint2(4294967295u);
            bool loop_init_7 = true;
            while(true) {
                if (metal::all(loop_bound_10 == uint2(0u))) { break; }
                loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
                if (!loop_init_7) {
                    uint _e42 = j_2;
                    j_2 = _e42 + 1u;
                }
                loop_init_7 = false;
                uint _e17 = j_2;
                uint _e18 = k_4;
                if (_e17 < _e18) {
                    uint _e22 = k_4;
                    local_24 = held_1.inner[_e22];
                } else {
                    local_24 = false;
                }
                bool _e25 = local_24;
                if (_e25) {
                } else {
                    break;
                }
                {
                    uint _e26 = j_2;
                    if (held_1.inner[_e26]) {
                        uint _e30 = j_2;
                        uint _e32 = k_4;
                        local_25 = metal::all(keys_1.inner[_e30] == keys_1.inner[_e32]);
                    } else {
                        local_25 = false;
                    }
                    bool _e37 = local_25;
                    if (_e37) {
                        uint _e38 = k_4;
                        uint _e40 = j_2;
                        first.inner[_e38] = _e40;
                        break;
                    }
                }
            }
        }
    }
    type_16 _e47 = first;
    return _e47;
}

metal::float3 output_of(
    Shaded s_9
) {
    return s_9.e;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, uint lid [[thread_index_in_threadgroup]]
, device type_7 const& geo_nodes [[user(fake0)]]
, device type_8 const& geo_tris [[user(fake0)]]
, constant ViewParams& view [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::write> out_tex [[user(fake0)]]
, device type_12 const& lights [[user(fake0)]]
, device type_4 const& rt2_3 [[user(fake0)]]
, device type_4 const& r2_3 [[user(fake0)]]
, device type_13 const& bsh_nodes [[user(fake0)]]
, device type_15& counters [[user(fake0)]]
, threadgroup type_19& wg_lo
, threadgroup type_19& wg_hi
, threadgroup WorkgroupBox& wg_box
, threadgroup type_20& tile_list
, threadgroup type_21& subtree_at
, threadgroup metal::atomic_uint& tile_scale
, threadgroup uint& tile_total
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint rays_cast = {};
    uint nodes_visited = {};
    uint evaluations = {};
    if (lid == 0u) {
        wg_lo = {};
        wg_hi = {};
        wg_box = {};
        tile_list = {};
        subtree_at = {};
        metal::atomic_store_explicit(&tile_scale, 0, metal::memory_order_relaxed);
        tile_total = {};
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    bool local = {};
    metal::float4 s = metal::float4(0.0);
    metal::float3 nn = metal::float3(0.0);
    bool local_1 = {};
    bool local_2 = {};
    bool local_3 = {};
    metal::float3 n = metal::float3(0.0, 0.0, 1.0);
    Material m = {};
    metal::float4 lobe = metal::float4(1.0, 0.0, 1.0, 1.0);
    metal::float3 r = {};
    uint h = {};
    Shaded t = Shaded {metal::float3(0.0), metal::float3(0.0), metal::float3(0.0)};
    type_16 slot_light = {};
    type_26 slot_u = {};
    type_27 slot_p = {};
    metal::float3 total = metal::float3(0.0);
    uint count = 0u;
    uint hc = {};
    type_27 threshold = {};
    uint start = 0u;
    uint j = {};
    bool local_4 = {};
    uint q = {};
    bool local_5 = {};
    type_23 keys = {};
    type_24 held = {};
    uint k = 0u;
    uint k_1 = 0u;
    metal::float3 w = {};
    uint j_1 = {};
    bool local_6 = {};
    uint _e5 = view.width;
    if (gid.x < _e5) {
        uint _e12 = view.height;
        local = gid.y < _e12;
    } else {
        local = false;
    }
    bool inside = local;
    metal::int2 texel_1 = metal::int2(static_cast<int>(gid.x), static_cast<int>(gid.y));
    if (inside) {
        metal::float4 _e27 = surface_at(texel_1, position_tex);
        s = _e27;
        metal::float4 _e30 = normal_tex.read(metal::uint2(texel_1), 0);
        nn = _e30.xyz;
    }
    metal::float3 _e32 = nn;
    metal::float3 _e33 = nn;
    float len2_ = metal::dot(_e32, _e33);
    metal::float4 _e35 = s;
    metal::float3 x_11 = _e35.xyz;
    if (inside) {
        float _e40 = s.w;
        local_1 = _e40 > 0.0;
    } else {
        local_1 = false;
    }
    bool _e44 = local_1;
    if (_e44) {
        local_2 = len2_ > 0.0;
    } else {
        local_2 = false;
    }
    bool _e50 = local_2;
    if (_e50) {
        local_3 = metal::all(metal::abs(x_11) <= metal::float3(340282350000000000000000000000000000000.0));
    } else {
        local_3 = false;
    }
    bool has_3 = local_3;
    if (has_3) {
        metal::float3 _e65 = nn;
        n = _e65 / metal::float3(metal::sqrt(len2_));
    }
    metal::float3 _e76 = n;
    r = _e76;
    metal::float4 _e78 = lobe;
    metal::float4 _e79 = range_lobe(_e78);
    float _e82 = view.shadow_offset;
    metal::float3 _e85 = view.eye;
    float eps_4 = _e82 * metal::length(_e85 - x_11);
    uint _e91 = view.seed;
    uint _e95 = view.width;
    uint _e101 = view.frame;
    uint _e102 = point_stream(_e91, (gid.y * _e95) + gid.x, _e101);
    uint _e103 = pick_stream(_e102);
    h = _e103;
    hc = _e102;
    TileWalk _e124 = tile_walk_begin(lid, x_11, _e79.w, has_3, bsh_nodes, wg_lo, wg_hi, wg_box, tile_list, subtree_at, tile_scale, tile_total, _buffer_sizes);
    uint2 loop_bound_11 = uint2(4294967295u);
    bool loop_init_8 = true;
    while(true) {
        if (metal::all(loop_bound_11 == uint2(0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_8) {
            uint _e223 = start;
            start = _e223 + TILE_LIST;
        }
        loop_init_8 = false;
        uint _e127 = start;
        if (_e127 < _e124.total) {
        } else {
            break;
        }
        {
            uint _e130 = start;
            uint _e131 = tile_walk_fill(lid, _e124, _e130, bsh_nodes, tile_list, subtree_at, _buffer_sizes);
            j = 0u;
            uint2 loop_bound_12 = uint2(4294967295u);
            bool loop_init_9 = true;
            while(true) {
                if (metal::all(loop_bound_12 == uint2(0u))) { break; }
                loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
                if (!loop_init_9) {
                    uint _e221 = j;
                    j = _e221 + 1u;
                }
                loop_init_9 = false;
                uint _e134 = j;
                if (_e134 < _e131) {
                } else {
                    break;
                }
                {
                    uint _e137 = j;
                    uint b_7 = tile_list.inner[_e137];
                    if (!(!(has_3))) {
                        BshNode _e146 = bsh_nodes[b_7];
                        metal::float3 _e147 = r;
                        bool _e148 = bsh_reaches(_e146, x_11, _e147, _e79);
                        local_4 = !(_e148);
                    } else {
                        local_4 = true;
                    }
                    bool _e151 = local_4;
                    if (_e151) {
                        continue;
                    }
                    uint li_7 = bsh_nodes[b_7].light;
                    uint _e156 = count;
                    count = _e156 + 1u;
                    uint _e159 = h;
                    uint _e160 = pcg_hash(_e159);
                    h = _e160;
                    uint _e161 = h;
                    float _e162 = xi_from_bits(_e161);
                    uint _e163 = h;
                    uint _e164 = pcg_hash(_e163);
                    h = _e164;
                    uint _e165 = h;
                    float _e166 = xi_from_bits(_e165);
                    metal::float2 u_4 = metal::float2(_e162, _e166);
                    metal::float3 _e168 = n;
                    metal::float3 _e169 = r;
                    Material _e170 = m;
                    Shaded _e175 = shade_pick_traced(li_7, x_11, _e168, _e169, _e79, _e170, 1.0, u_4.x, u_4.y, eps_4, false, rays_cast, nodes_visited, geo_nodes, geo_tris, lights, rt2_3, r2_3, _buffer_sizes);
                    metal::float3 _e176 = output_of(_e175);
                    uint _e178 = evaluations;
                    evaluations = _e178 + 1u;
                    float _e181 = resample_target(_e176);
                    if (_e181 > 0.0) {
                        metal::float3 _e184 = total;
                        total = _e184 + _e176;
                        q = 0u;
                        uint2 loop_bound_13 = uint2(4294967295u);
                        bool loop_init_10 = true;
                        while(true) {
                            if (metal::all(loop_bound_13 == uint2(0u))) { break; }
                            loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
                            if (!loop_init_10) {
                                uint _e218 = q;
                                q = _e218 + 1u;
                            }
                            loop_init_10 = false;
                            uint _e188 = q;
                            if (_e188 < K) {
                            } else {
                                break;
                            }
                            {
                                uint _e191 = q;
                                float _e193 = slot_target(_e176, _e191, K);
                                metal::float3 _e194 = total;
                                uint _e195 = q;
                                float _e197 = slot_target(_e194, _e195, K);
                                if (_e193 > 0.0) {
                                    uint _e202 = q;
                                    float _e204 = threshold.inner[_e202];
                                    local_5 = _e197 > _e204;
                                } else {
                                    local_5 = false;
                                }
                                bool _e207 = local_5;
                                if (_e207) {
                                    uint _e208 = q;
                                    slot_light.inner[_e208] = li_7;
                                    uint _e210 = q;
                                    slot_u.inner[_e210] = u_4;
                                    uint _e212 = q;
                                    slot_p.inner[_e212] = _e193;
                                    uint _e214 = q;
                                    float _e216 = next_threshold(_e197, hc);
                                    threshold.inner[_e214] = _e216;
                                }
                            }
                        }
                    }
                }
            }
            metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
        }
    }
    if (!(has_3)) {
        if (inside) {
            out_tex.write(metal::float4(0.0), metal::uint2(texel_1));
        }
        return;
    }
    uint2 loop_bound_14 = uint2(4294967295u);
    bool loop_init_11 = true;
    while(true) {
        if (metal::all(loop_bound_14 == uint2(0u))) { break; }
        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
        if (!loop_init_11) {
            uint _e252 = k;
            k = _e252 + 1u;
        }
        loop_init_11 = false;
        uint _e234 = k;
        if (_e234 < K) {
        } else {
            break;
        }
        {
            uint _e237 = k;
            uint _e239 = k;
            uint _e241 = slot_light.inner[_e239];
            keys.inner[_e237] = metal::uint2(_e241, 0u);
            uint _e244 = k;
            uint _e246 = k;
            float _e248 = slot_p.inner[_e246];
            held.inner[_e244] = _e248 > 0.0;
        }
    }
    type_23 _e254 = keys;
    type_24 _e255 = held;
    type_16 _e256 = first_holders(_e254, _e255);
    uint2 loop_bound_15 = uint2(4294967295u);
    bool loop_init_12 = true;
    while(true) {
        if (metal::all(loop_bound_15 == uint2(0u))) { break; }
        loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
        if (!loop_init_12) {
            uint _e320 = k_1;
            k_1 = _e320 + 1u;
        }
        loop_init_12 = false;
        uint _e259 = k_1;
        if (_e259 < K) {
        } else {
            break;
        }
        {
            w = metal::float3(0.0);
            uint _e265 = k_1;
            uint _e267 = k_1;
            bool first_1 = _e256.inner[_e265] == _e267;
            uint _e269 = k_1;
            j_1 = _e269;
            uint2 loop_bound_16 = uint2(4294967295u);
            bool loop_init_13 = true;
            while(true) {
                if (metal::all(loop_bound_16 == uint2(0u))) { break; }
                loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
                if (!loop_init_13) {
                    uint _e297 = j_1;
                    j_1 = _e297 + 1u;
                }
                loop_init_13 = false;
                uint _e271 = j_1;
                if (_e271 < K) {
                    local_6 = first_1;
                } else {
                    local_6 = false;
                }
                bool _e277 = local_6;
                if (_e277) {
                } else {
                    break;
                }
                {
                    uint _e278 = j_1;
                    uint _e280 = k_1;
                    if (_e256.inner[_e278] == _e280) {
                        metal::float3 _e282 = w;
                        metal::float3 _e283 = total;
                        uint _e284 = j_1;
                        float _e286 = slot_target(_e283, _e284, K);
                        uint _e287 = j_1;
                        float _e289 = slot_p.inner[_e287];
                        uint _e291 = j_1;
                        metal::float3 _e293 = slot_share(_e291, K);
                        w = _e282 + ((_e286 / _e289) * _e293);
                    }
                }
            }
            if (first_1) {
                Shaded _e299 = t;
                uint _e300 = k_1;
                uint _e302 = slot_light.inner[_e300];
                metal::float3 _e303 = n;
                metal::float3 _e304 = r;
                Material _e305 = m;
                uint _e307 = k_1;
                float _e310 = slot_u.inner[_e307].x;
                uint _e311 = k_1;
                float _e314 = slot_u.inner[_e311].y;
                Shaded _e315 = shade_pick(_e302, x_11, _e303, _e304, _e79, _e305, 1.0, _e310, _e314, eps_4, rays_cast, nodes_visited, geo_nodes, geo_tris, lights, rt2_3, r2_3, _buffer_sizes);
                metal::float3 _e316 = w;
                Shaded _e317 = scaled(_e315, _e316);
                Shaded _e318 = add(_e299, _e317);
                t = _e318;
            }
        }
    }
    metal::float3 _e324 = t.e;
    uint _e325 = count;
    out_tex.write(metal::float4(_e324, static_cast<float>(_e325)), metal::uint2(texel_1));
    counter_add(DIRECT_COUNT_PIXELS, 1u, counters, _buffer_sizes);
    uint _e331 = count;
    counter_add(DIRECT_COUNT_CANDIDATES, _e331, counters, _buffer_sizes);
    uint _e334 = evaluations;
    counter_add(DIRECT_COUNT_EVALUATIONS, _e334, counters, _buffer_sizes);
    uint _e337 = rays_cast;
    counter_add(DIRECT_COUNT_RAYS, _e337, counters, _buffer_sizes);
    uint _e340 = nodes_visited;
    counter_add(DIRECT_COUNT_NODES, _e340, counters, _buffer_sizes);
    return;
}
