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
struct type_20 {
    metal::uint2 inner[8];
};
struct type_21 {
    bool inner[8];
};
struct type_23 {
    metal::float2 inner[8];
};
struct type_24 {
    float inner[8];
};
constant uint LIGHT_POINT = 0u;
constant uint LIGHT_SPOT = 1u;
constant uint LIGHT_IES = 2u;
constant uint LIGHT_TRIANGLE = 3u;
constant uint LIGHT_VPL = 4u;
constant uint NO_LIGHT = 4294967295u;
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
constant uint RESERVOIR_FULL = 4294967295u;
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

float to_f32_(
    uint u
) {
    return static_cast<float>(u);
}

uint mul_lo_u32_(
    uint a,
    uint b_1
) {
    return a * b_1;
}

uint add_wrap_u32_(
    uint a_1,
    uint b_2
) {
    return a_1 + b_2;
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
    metal::float3 n,
    metal::float3 ng,
    float r2_1
) {
    bool local_4 = {};
    bool local_5 = {};
    metal::float3 v_3 = x_2 - y;
    float d2_6 = metal::dot(v_3, v_3);
    bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local_4 = !((d2_6 > 0.0));
    } else {
        local_4 = true;
    }
    bool _e16 = local_4;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_6 = v_3 / metal::float3(metal::sqrt(d2_6));
    float cos_x_1 = -(metal::dot(n, w_6));
    if (!((cos_x_1 <= 0.0))) {
        local_5 = metal::dot(ng, w_6) >= 0.0;
    } else {
        local_5 = true;
    }
    bool _e32 = local_5;
    if (_e32) {
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
    float t_1 = metal::saturate((cos_theta - cos_outer) / (cos_inner - cos_outer));
    return (shape > 0.5) ? (t_1 * t_1) : ((t_1 * t_1) * (3.0 - (2.0 * t_1)));
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

float weighted_threshold(
    float w_sum,
    float u_2
) {
    return w_sum / (1.0 - u_2);
}

float resample_target(
    metal::float3 c_1
) {
    return ((c_1.x + c_1.y) + c_1.z) * 0.33333334;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

float slot_target(
    metal::float3 c_2,
    uint slot,
    uint k_2
) {
    if (k_2 < 3u) {
        float _e5 = resample_target(c_2);
        return _e5;
    }
    uint j_2 = naga_mod(slot, 3u);
    if (j_2 == 0u) {
        return c_2.x;
    }
    if (j_2 == 1u) {
        return c_2.y;
    }
    return c_2.z;
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
        float w_7 = 1.0 / _e4;
        return metal::float3(w_7, w_7, w_7);
    }
    uint j_3 = naga_mod(slot_1, 3u);
    float _e15 = to_f32_(naga_div((k_3 + 2u) - j_3, 3u));
    float w_8 = 1.0 / _e15;
    if (j_3 == 0u) {
        return metal::float3(w_8, 0.0, 0.0);
    }
    if (j_3 == 1u) {
        return metal::float3(0.0, w_8, 0.0);
    }
    return metal::float3(0.0, 0.0, w_8);
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
    bool local_6 = {};
    bool local_7 = {};
    float vd = metal::dot(v, d);
    float h2_ = d2_4 - (a_2 * a_2);
    if (!((h2_ <= 0.0))) {
        if (vd >= 0.0) {
            local_7 = (vd * vd) >= h2_;
        } else {
            local_7 = false;
        }
        bool _e19 = local_7;
        local_6 = _e19;
    } else {
        local_6 = true;
    }
    bool _e21 = local_6;
    if (_e21) {
        return 1.0;
    }
    metal::float3 c_6 = metal::cross(v, d);
    return metal::min(((vd * metal::sqrt(h2_)) + (metal::sqrt(metal::dot(c_6, c_6)) * a_2)) / d2_4, 1.0);
}

float cone_cos_toward(
    metal::float3 center,
    float radius,
    metal::float3 p,
    metal::float3 d_1
) {
    metal::float3 v_4 = center - p;
    float _e6 = cone_cos_of(v_4, metal::dot(v_4, v_4), radius, d_1);
    return _e6;
}

float range_scale_at(
    metal::float4 rl,
    float cos_t
) {
    float t_2 = ((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0;
    return metal::clamp(rl.x + ((rl.y * rl.z) / (t_2 * t_2)), 1.0, rl.w * rl.w);
}

float range_scale_toward(
    metal::float4 rl_1,
    metal::float3 center_1,
    float radius_1,
    metal::float3 p_1,
    metal::float3 r_2
) {
    if (rl_1.w <= 1.0) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_2);
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
    metal::float3 bmin,
    metal::float3 bmax,
    float t_max
) {
    metal::float3 t0_ = (bmin - o) * inv_d;
    metal::float3 t1_ = (bmax - o) * inv_d;
    metal::float3 lo = metal::min(t0_, t1_);
    metal::float3 hi = metal::max(t0_, t1_);
    float t_in = metal::max(metal::max(lo.x, lo.y), metal::max(lo.z, 0.0));
    float t_out = metal::min(metal::min(hi.x, hi.y), metal::min(hi.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1.0;
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_3,
    metal::float3 a_3,
    metal::float3 b_3,
    metal::float3 c_3,
    float t_min,
    float t_max_1
) {
    bool local_8 = {};
    bool local_9 = {};
    bool local_10 = {};
    metal::float3 e1_ = b_3 - a_3;
    metal::float3 e2_ = c_3 - a_3;
    metal::float3 p_2 = metal::cross(d_3, e2_);
    float det = metal::dot(e1_, p_2);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv = 1.0 / det;
    metal::float3 s_4 = o_1 - a_3;
    float u_3 = metal::dot(s_4, p_2) * inv;
    if (!((u_3 < 0.0))) {
        local_8 = u_3 > 1.0;
    } else {
        local_8 = true;
    }
    bool _e28 = local_8;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q_1 = metal::cross(s_4, e1_);
    float v_5 = metal::dot(d_3, q_1) * inv;
    if (!((v_5 < 0.0))) {
        local_9 = (u_3 + v_5) > 1.0;
    } else {
        local_9 = true;
    }
    bool _e42 = local_9;
    if (_e42) {
        return -1.0;
    }
    float t_3 = metal::dot(e2_, q_1) * inv;
    if (t_3 > t_min) {
        local_10 = t_3 < t_max_1;
    } else {
        local_10 = false;
    }
    bool _e51 = local_10;
    if (_e51) {
        return t_3;
    }
    return -1.0;
}

metal::float3 light_intensity(
    GpuLight l,
    metal::float3 w_2
) {
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            float _e11 = spot_falloff(metal::dot(l.p1_, w_2), l.a, l.b, l.p2_[0]);
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
    uint node_2 = 0u;
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
        uint _e21 = node_2;
        GpuGeoNode n_7 = geo_nodes[_e21];
        uint _e25 = nodes_visited;
        nodes_visited = _e25 + 1u;
        float _e31 = hit.t;
        float _e32 = ray_aabb(o_2, _e14, n_7.bmin, n_7.bmax, _e31);
        if (_e32 >= 0.0) {
            if (n_7.count > 0u) {
                i = n_7.first;
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
                    if (_e40 < (n_7.first + n_7.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e46 = i;
                        GpuTriangle t_4 = geo_tris[_e46];
                        float _e53 = hit.t;
                        float _e54 = ray_triangle(o_2, d_4, t_4.v0_, t_4.v1_, t_4.v2_, t_min_1, _e53);
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
                    stack.inner[_e67] = n_7.first + 1u;
                    uint _e72 = sp;
                    sp = _e72 + 1u;
                }
                node_2 = n_7.first;
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
        node_2 = _e84;
    }
    GeoHit _e85 = hit;
    return _e85;
}

bool occluded(
    metal::float3 a_4,
    metal::float3 b_4,
    thread uint& rays_cast,
    thread uint& nodes_visited,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 dv = b_4 - a_4;
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
    metal::float3 r_3,
    metal::float4 rl_2
) {
    float _e5 = cone_cos_of(v_1, d2_5, a_5, r_3);
    float _e8 = range_scale_at(rl_2, _e5 + 0.000002);
    return _e8;
}

bool bsh_reaches(
    BshNode node_3,
    metal::float3 x_4,
    metal::float3 r_4,
    metal::float4 rl_3
) {
    bool local_11 = {};
    bool local_12 = {};
    bool _e6 = sphere_contains_point(node_3.center, node_3.radius, x_4);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_3.center, node_3.radius * (rl_3.w * 1.0001), x_4);
        local_11 = !(_e20);
    } else {
        local_11 = true;
    }
    bool _e23 = local_11;
    if (_e23) {
        return false;
    }
    float _e25 = bsh_range_bound(node_3);
    metal::float3 v_6 = x_4 - node_3.center;
    float d2_7 = metal::dot(v_6, v_6);
    float reach_max = node_3.extent + ((rl_3.w * 1.001) * _e25);
    if (d2_7 > (reach_max * reach_max)) {
        return false;
    }
    if (node_3.child == BSH_NONE) {
        float _e43 = range_scale_toward(rl_3, node_3.center, node_3.extent, x_4, r_4);
        float _e46 = bsh_scaled_radius(node_3, metal::sqrt(_e43));
        bool _e47 = sphere_contains_point(node_3.center, _e46, x_4);
        return _e47;
    }
    float _e50 = bsh_inner_scale(node_3.extent, -(v_6), d2_7, r_4, rl_3);
    float s_c = _e50 * 1.001;
    float reach = node_3.extent + (metal::sqrt(s_c) * _e25);
    if (d2_7 <= ((node_3.radius * node_3.radius) * s_c)) {
        local_12 = d2_7 <= (reach * reach);
    } else {
        local_12 = false;
    }
    bool _e67 = local_12;
    return _e67;
}

uint bsh_next_leaf_lobe(
    BshNodes nodes_3,
    uint start,
    metal::float3 x_5,
    metal::float3 r_5,
    metal::float4 rl_4,
    device type_13 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_2 = {};
    i_2 = start;
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e6 = i_2;
        if (_e6 != BSH_NONE) {
        } else {
            break;
        }
        {
            uint _e9 = i_2;
            BshNode _e10 = bsh_node(nodes_3, _e9, bsh_nodes, _buffer_sizes);
            bool _e11 = bsh_reaches(_e10, x_5, r_5, rl_4);
            if (_e11) {
                if (_e10.child == BSH_NONE) {
                    uint _e15 = i_2;
                    return _e15;
                }
                i_2 = _e10.child;
            } else {
                i_2 = _e10.next;
            }
        }
    }
    return BSH_NONE;
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
    metal::float3 x_6,
    metal::float3 n_1,
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
    Connection c_4 = {};
    bool local_13 = {};
    bool local_14 = {};
    c_4.e = metal::float3(0.0);
    metal::float3 _e16 = light_point(l_2, u1_1, u2_1);
    c_4.y = _e16;
    metal::float3 _e19 = c_4.y;
    float _e20 = connection_cosine(x_6, _e19, n_1, ng_1, r2_2);
    c_4.cos_x = _e20;
    float _e22 = c_4.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            metal::float3 _e33 = c_4.y;
            bool _e34 = occluded(x_6 + (ng_1 * eps), _e33, rays_cast, nodes_visited, geo_nodes, geo_tris, _buffer_sizes);
            local_14 = _e34;
        } else {
            local_14 = false;
        }
        bool _e36 = local_14;
        local_13 = _e36;
    } else {
        local_13 = true;
    }
    bool _e38 = local_13;
    if (_e38) {
        Connection _e39 = c_4;
        return _e39;
    }
    metal::float3 _e41 = c_4.y;
    metal::float3 v_7 = x_6 - _e41;
    float d2_8 = metal::dot(v_7, v_7);
    metal::float3 _e48 = light_intensity(l_2, v_7 / metal::float3(metal::sqrt(d2_8)));
    float _e50 = c_4.cos_x;
    float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_4.e = _e48 * _e51;
    Connection _e53 = c_4;
    return _e53;
}

Connection connect_traced(
    uint li,
    metal::float3 x_7,
    metal::float3 n_2,
    metal::float3 ng_2,
    float s,
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
    Connection _e21 = connect_record(_e12, x_7, n_2, ng_2, s * _e15, s * _e19, w_res_1, u1_2, u2_2, eps_1, trace_2, rays_cast, nodes_visited, geo_nodes, geo_tris, _buffer_sizes);
    return _e21;
}

metal::float4 surface_at(
    metal::int2 texel,
    metal::texture2d<float, metal::access::sample> position_tex
) {
    metal::float4 p_3 = position_tex.read(metal::uint2(texel), 0);
    return (p_3.w > 0.0) ? metal::float4(p_3.xyz, 1.0) : metal::float4(0.0);
}

void counter_add(
    uint f,
    uint n_3,
    device type_15& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e6 = metal::atomic_fetch_add_explicit(&counters[2u * f], n_3, metal::memory_order_relaxed);
    if ((_e6 + n_3) < _e6) {
        uint _e16 = metal::atomic_fetch_add_explicit(&counters[(2u * f) + 1u], 1u, metal::memory_order_relaxed);
        return;
    } else {
        return;
    }
}

Shaded shade_connection(
    Connection c_5,
    metal::float3 x_8,
    metal::float3 n_4,
    Material m_1
) {
    Shaded s_1 = {};
    s_1.e = c_5.e;
    s_1.diffuse = metal::float3(0.0);
    s_1.specular = metal::float3(0.0);
    Shaded _e13 = s_1;
    return _e13;
}

Shaded shade_pick_traced(
    uint li_1,
    metal::float3 x_9,
    metal::float3 n_5,
    metal::float3 r_6,
    metal::float4 rl_5,
    Material m_2,
    float w_3,
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
    Connection _e12 = connect_traced(li_1, x_9, n_5, n_5, 1.0, w_3, u1_3, u2_3, eps_2, trace_3, rays_cast, nodes_visited, geo_nodes, geo_tris, lights, rt2_3, r2_3, _buffer_sizes);
    Shaded _e13 = shade_connection(_e12, x_9, n_5, m_2);
    return _e13;
}

Shaded shade_pick(
    uint li_2,
    metal::float3 x_10,
    metal::float3 n_6,
    metal::float3 r_7,
    metal::float4 rl_6,
    Material m_3,
    float w_4,
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
    Shaded _e11 = shade_pick_traced(li_2, x_10, n_6, r_7, rl_6, m_3, w_4, u1_4, u2_4, eps_3, true, rays_cast, nodes_visited, geo_nodes, geo_tris, lights, rt2_3, r2_3, _buffer_sizes);
    return _e11;
}

Shaded add(
    Shaded a_6,
    Shaded b_5
) {
    return Shaded {a_6.e + b_5.e, a_6.diffuse + b_5.diffuse, a_6.specular + b_5.specular};
}

Shaded scaled(
    Shaded s_2,
    metal::float3 w_5
) {
    return Shaded {s_2.e * w_5, s_2.diffuse * w_5, s_2.specular * w_5};
}

type_16 first_holders(
    type_20 keys_1,
    type_21 held_1
) {
    type_16 first = {};
    uint k_4 = 0u;
    uint j_1 = {};
    bool local_15 = {};
    bool local_16 = {};
    uint2 loop_bound_3 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e45 = k_4;
            k_4 = _e45 + 1u;
        }
        loop_init_1 = false;
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
            j_1 = 0u;
            uint2 loop_bound_4 = uint2(4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (metal::all(loop_bound_4 == uint2(0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e42 = j_1;
                    j_1 = _e42 + 1u;
                }
                loop_init_2 = false;
                uint _e17 = j_1;
                uint _e18 = k_4;
                if (_e17 < _e18) {
                    uint _e22 = k_4;
                    local_15 = held_1.inner[_e22];
                } else {
                    local_15 = false;
                }
                bool _e25 = local_15;
                if (_e25) {
                } else {
                    break;
                }
                {
                    uint _e26 = j_1;
                    if (held_1.inner[_e26]) {
                        uint _e30 = j_1;
                        uint _e32 = k_4;
                        local_16 = metal::all(keys_1.inner[_e30] == keys_1.inner[_e32]);
                    } else {
                        local_16 = false;
                    }
                    bool _e37 = local_16;
                    if (_e37) {
                        uint _e38 = k_4;
                        uint _e40 = j_1;
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
    Shaded s_3
) {
    return s_3.e;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
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
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint rays_cast = {};
    uint nodes_visited = {};
    uint evaluations = {};
    bool local = {};
    bool local_1 = {};
    Material m = {};
    metal::float4 lobe = metal::float4(1.0, 0.0, 1.0, 1.0);
    metal::float3 r = {};
    uint h = {};
    Shaded t = Shaded {metal::float3(0.0), metal::float3(0.0), metal::float3(0.0)};
    type_16 slot_light = {};
    type_23 slot_u = {};
    type_24 slot_p = {};
    metal::float3 total = metal::float3(0.0);
    uint count = 0u;
    uint hc = {};
    type_24 threshold = {};
    uint b = {};
    uint q = {};
    bool local_2 = {};
    type_20 keys = {};
    type_21 held = {};
    uint k = 0u;
    uint k_1 = 0u;
    metal::float3 w = {};
    uint j = {};
    bool local_3 = {};
    uint _e4 = view.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = view.height;
        local = gid.y >= _e12;
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    metal::int2 texel_1 = metal::int2(static_cast<int>(gid.x), static_cast<int>(gid.y));
    metal::float4 _e21 = surface_at(texel_1, position_tex);
    metal::float4 _e24 = normal_tex.read(metal::uint2(texel_1), 0);
    metal::float3 nn = _e24.xyz;
    float len2_ = metal::dot(nn, nn);
    if (!((_e21.w <= 0.0))) {
        local_1 = !((len2_ > 0.0));
    } else {
        local_1 = true;
    }
    bool _e37 = local_1;
    if (_e37) {
        out_tex.write(metal::float4(0.0), metal::uint2(texel_1));
        return;
    }
    metal::float3 x_11 = _e21.xyz;
    metal::float3 n_8 = nn / metal::float3(metal::sqrt(len2_));
    r = n_8;
    metal::float4 _e53 = lobe;
    metal::float4 _e54 = range_lobe(_e53);
    float _e57 = view.shadow_offset;
    metal::float3 _e60 = view.eye;
    float eps_4 = _e57 * metal::length(_e60 - x_11);
    uint _e66 = view.seed;
    uint _e70 = view.width;
    uint _e76 = view.frame;
    uint _e77 = point_stream(_e66, (gid.y * _e70) + gid.x, _e76);
    uint _e78 = pick_stream(_e77);
    h = _e78;
    hc = _e77;
    uint _e100 = bsh_first(BSH, bsh_nodes, _buffer_sizes);
    metal::float3 _e101 = r;
    uint _e102 = bsh_next_leaf_lobe(BSH, _e100, x_11, _e101, _e54, bsh_nodes, _buffer_sizes);
    b = _e102;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e177 = b;
            uint _e180 = bsh_nodes[_e177].next;
            metal::float3 _e181 = r;
            uint _e182 = bsh_next_leaf_lobe(BSH, _e180, x_11, _e181, _e54, bsh_nodes, _buffer_sizes);
            b = _e182;
        }
        loop_init_3 = false;
        uint _e104 = b;
        if (_e104 != BSH_NONE) {
        } else {
            break;
        }
        {
            uint _e107 = count;
            count = _e107 + 1u;
            uint _e111 = b;
            uint li_3 = bsh_nodes[_e111].light;
            uint _e115 = h;
            uint _e116 = pcg_hash(_e115);
            h = _e116;
            uint _e117 = h;
            float _e118 = xi_from_bits(_e117);
            uint _e119 = h;
            uint _e120 = pcg_hash(_e119);
            h = _e120;
            uint _e121 = h;
            float _e122 = xi_from_bits(_e121);
            metal::float2 u_4 = metal::float2(_e118, _e122);
            metal::float3 _e124 = r;
            Material _e125 = m;
            Shaded _e130 = shade_pick_traced(li_3, x_11, n_8, _e124, _e54, _e125, 1.0, u_4.x, u_4.y, eps_4, false, rays_cast, nodes_visited, geo_nodes, geo_tris, lights, rt2_3, r2_3, _buffer_sizes);
            metal::float3 _e131 = output_of(_e130);
            uint _e133 = evaluations;
            evaluations = _e133 + 1u;
            float _e136 = resample_target(_e131);
            if (_e136 > 0.0) {
                metal::float3 _e139 = total;
                total = _e139 + _e131;
                q = 0u;
                uint2 loop_bound_6 = uint2(4294967295u);
                bool loop_init_4 = true;
                while(true) {
                    if (metal::all(loop_bound_6 == uint2(0u))) { break; }
                    loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                    if (!loop_init_4) {
                        uint _e173 = q;
                        q = _e173 + 1u;
                    }
                    loop_init_4 = false;
                    uint _e143 = q;
                    if (_e143 < K) {
                    } else {
                        break;
                    }
                    {
                        uint _e146 = q;
                        float _e148 = slot_target(_e131, _e146, K);
                        metal::float3 _e149 = total;
                        uint _e150 = q;
                        float _e152 = slot_target(_e149, _e150, K);
                        if (_e148 > 0.0) {
                            uint _e157 = q;
                            float _e159 = threshold.inner[_e157];
                            local_2 = _e152 > _e159;
                        } else {
                            local_2 = false;
                        }
                        bool _e162 = local_2;
                        if (_e162) {
                            uint _e163 = q;
                            slot_light.inner[_e163] = li_3;
                            uint _e165 = q;
                            slot_u.inner[_e165] = u_4;
                            uint _e167 = q;
                            slot_p.inner[_e167] = _e148;
                            uint _e169 = q;
                            float _e171 = next_threshold(_e152, hc);
                            threshold.inner[_e169] = _e171;
                        }
                    }
                }
            }
        }
    }
    uint2 loop_bound_7 = uint2(4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (metal::all(loop_bound_7 == uint2(0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e205 = k;
            k = _e205 + 1u;
        }
        loop_init_5 = false;
        uint _e187 = k;
        if (_e187 < K) {
        } else {
            break;
        }
        {
            uint _e190 = k;
            uint _e192 = k;
            uint _e194 = slot_light.inner[_e192];
            keys.inner[_e190] = metal::uint2(_e194, 0u);
            uint _e197 = k;
            uint _e199 = k;
            float _e201 = slot_p.inner[_e199];
            held.inner[_e197] = _e201 > 0.0;
        }
    }
    type_20 _e207 = keys;
    type_21 _e208 = held;
    type_16 _e209 = first_holders(_e207, _e208);
    uint2 loop_bound_8 = uint2(4294967295u);
    bool loop_init_6 = true;
    while(true) {
        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_6) {
            uint _e272 = k_1;
            k_1 = _e272 + 1u;
        }
        loop_init_6 = false;
        uint _e212 = k_1;
        if (_e212 < K) {
        } else {
            break;
        }
        {
            w = metal::float3(0.0);
            uint _e218 = k_1;
            uint _e220 = k_1;
            bool first_1 = _e209.inner[_e218] == _e220;
            uint _e222 = k_1;
            j = _e222;
            uint2 loop_bound_9 = uint2(4294967295u);
            bool loop_init_7 = true;
            while(true) {
                if (metal::all(loop_bound_9 == uint2(0u))) { break; }
                loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                if (!loop_init_7) {
                    uint _e250 = j;
                    j = _e250 + 1u;
                }
                loop_init_7 = false;
                uint _e224 = j;
                if (_e224 < K) {
                    local_3 = first_1;
                } else {
                    local_3 = false;
                }
                bool _e230 = local_3;
                if (_e230) {
                } else {
                    break;
                }
                {
                    uint _e231 = j;
                    uint _e233 = k_1;
                    if (_e209.inner[_e231] == _e233) {
                        metal::float3 _e235 = w;
                        metal::float3 _e236 = total;
                        uint _e237 = j;
                        float _e239 = slot_target(_e236, _e237, K);
                        uint _e240 = j;
                        float _e242 = slot_p.inner[_e240];
                        uint _e244 = j;
                        metal::float3 _e246 = slot_share(_e244, K);
                        w = _e235 + ((_e239 / _e242) * _e246);
                    }
                }
            }
            if (first_1) {
                Shaded _e252 = t;
                uint _e253 = k_1;
                uint _e255 = slot_light.inner[_e253];
                metal::float3 _e256 = r;
                Material _e257 = m;
                uint _e259 = k_1;
                float _e262 = slot_u.inner[_e259].x;
                uint _e263 = k_1;
                float _e266 = slot_u.inner[_e263].y;
                Shaded _e267 = shade_pick(_e255, x_11, n_8, _e256, _e54, _e257, 1.0, _e262, _e266, eps_4, rays_cast, nodes_visited, geo_nodes, geo_tris, lights, rt2_3, r2_3, _buffer_sizes);
                metal::float3 _e268 = w;
                Shaded _e269 = scaled(_e267, _e268);
                Shaded _e270 = add(_e252, _e269);
                t = _e270;
            }
        }
    }
    metal::float3 _e276 = t.e;
    uint _e277 = count;
    out_tex.write(metal::float4(_e276, static_cast<float>(_e277)), metal::uint2(texel_1));
    counter_add(DIRECT_COUNT_PIXELS, 1u, counters, _buffer_sizes);
    uint _e283 = count;
    counter_add(DIRECT_COUNT_CANDIDATES, _e283, counters, _buffer_sizes);
    uint _e286 = evaluations;
    counter_add(DIRECT_COUNT_EVALUATIONS, _e286, counters, _buffer_sizes);
    uint _e289 = rays_cast;
    counter_add(DIRECT_COUNT_RAYS, _e289, counters, _buffer_sizes);
    uint _e292 = nodes_visited;
    counter_add(DIRECT_COUNT_NODES, _e292, counters, _buffer_sizes);
    return;
}
