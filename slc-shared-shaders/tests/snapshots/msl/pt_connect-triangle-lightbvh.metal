// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size1;
    uint size2;
    uint size3;
    uint size4;
    uint size5;
    uint size6;
    uint size8;
    uint size9;
    uint size10;
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
struct GpuLightCone {
    metal::packed_float3 center;
    float radius;
    metal::packed_float3 axis;
    float cos_o;
    float phi;
    float cos_e;
    uint bvh_leaf;
    uint pad;
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
struct GpuPathVertex {
    metal::packed_float3 position;
    uint alive;
    metal::packed_float3 normal;
    float pad;
    metal::packed_float3 weight;
    float pad1_;
    metal::packed_float3 gnormal;
    float pad2_;
};
struct ShadeParams {
    uint point_count;
    uint seed;
    uint frame;
    float eps;
};
typedef float type_4[1];
struct GpuLightBvhNode {
    metal::packed_float3 center;
    float radius;
    metal::packed_float3 axis;
    float cos_o;
    float phi;
    float cos_e;
    uint second;
    uint light;
};
struct GeoHit {
    float t;
    uint tri;
};
typedef GpuGeoNode type_6[1];
typedef GpuTriangle type_7[1];
struct type_8 {
    uint inner[64];
};
typedef uint BshNodes;
struct Connection {
    metal::float3 e;
    metal::packed_float3 y;
    float cos_x;
};
typedef GpuLight type_9[1];
typedef metal::float4 type_10[1];
typedef GpuLightCone type_11[1];
typedef GpuLightBvhNode type_12[1];
typedef uint BvhNodes;
struct BvhPick {
    uint light;
    float pmf;
};
typedef GpuPathVertex type_13[1];
typedef uint type_14[1];
constant uint LIGHT_POINT = 0u;
constant uint LIGHT_SPOT = 1u;
constant uint LIGHT_IES = 2u;
constant uint LIGHT_TRIANGLE = 3u;
constant uint LIGHT_VPL = 4u;
constant uint NO_LIGHT = 4294967295u;
constant uint MAP_CAMERA = 0u;
constant uint MAP_PERSPECTIVE = 1u;
constant uint MAP_ORTHOGRAPHIC = 2u;
constant float XI_STEP = 0.000000059604645;
constant uint PICK_STREAM = 2654435769u;
constant float TWO_PI = 6.2831855;
constant float CULL_RADIUS_SCALE = 1.000001;
constant float SPHERE_PAD = 0.00000047683716;
constant float SPHERE_HUGE = 340282350000000000000000000000000000000.0;
constant float SPHERE_PAD_ABS = 0.000000000000000001;
constant float INV_PI = 0.31830987;
constant float MIN_D2_ = 0.000000000001;
constant uint BSH_NONE = 4294967295u;
constant uint RESERVOIR_FULL = 4294967295u;
constant uint LIGHT_BVH_LEAF = 4294967295u;
constant float ONE_MINUS_EPSILON = 0.99999994;
constant float F32_MAX = 340282350000000000000000000000000000000.0;
constant float GGX_ALPHA_MIN = 0.001;
constant float DEPTH_NONE = 1000000000000000000000000000000.0;
constant float DEPTH_SIGMA = 0.05;
constant float COVER_WEIGHT = 0.1;
constant uint NEAR_BLOCK = 64u;
constant uint ROULETTE_DEPTH = 2u;
constant uint K = 8u;
constant BshNodes BSH = 0u;
constant BvhNodes BVH = 0u;

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

float rr_probability(
    float rt2_,
    float d2_
) {
    if (d2_ <= rt2_) {
        return 1.0;
    }
    return rt2_ / d2_;
}

float slc_weight(
    float rt2_1,
    float d2_1
) {
    if (d2_1 <= rt2_1) {
        return 1.0;
    }
    return d2_1 / rt2_1;
}

bool slc_keep(
    float r2_,
    float d2_2
) {
    return d2_2 < r2_;
}

float inverse_square(
    float d2_3
) {
    return 1.0 / metal::max(d2_3, MIN_D2_);
}

float connection_factor(
    float cos_x,
    float d2_4,
    float rt2_2,
    float w
) {
    float _e4 = inverse_square(d2_4);
    float _e6 = slc_weight(rt2_2, d2_4);
    return ((cos_x * _e4) * _e6) * w;
}

float connection_cosine(
    metal::float3 x_1,
    metal::float3 y,
    metal::float3 n,
    metal::float3 ng,
    float r2_1
) {
    bool local = {};
    bool local_1 = {};
    metal::float3 v_1 = x_1 - y;
    float d2_7 = metal::dot(v_1, v_1);
    bool _e7 = slc_keep(r2_1, d2_7);
    if (!(!(_e7))) {
        local = !((d2_7 > 0.0));
    } else {
        local = true;
    }
    bool _e16 = local;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_4 = v_1 / metal::float3(metal::sqrt(d2_7));
    float cos_x_1 = -(metal::dot(n, w_4));
    if (!((cos_x_1 <= 0.0))) {
        local_1 = metal::dot(ng, w_4) >= 0.0;
    } else {
        local_1 = true;
    }
    bool _e32 = local_1;
    if (_e32) {
        return 0.0;
    }
    return cos_x_1;
}

float triangle_lobe(
    metal::float3 n_1,
    float area,
    metal::float3 w_1
) {
    return area * metal::max(metal::dot(n_1, w_1), 0.0);
}

metal::float3 triangle_sample(
    metal::float3 a_2,
    metal::float3 b_2,
    metal::float3 c,
    float u1_,
    float u2_
) {
    float su = metal::sqrt(u1_);
    float b0_ = 1.0 - su;
    float b1_ = u2_ * su;
    return ((a_2 * b0_) + (b_2 * b1_)) + (c * ((1.0 - b0_) - b1_));
}

float area_to_solid_angle_pdf(
    float pdf_area,
    float d2_5,
    float cos_light
) {
    float c_4 = metal::abs(cos_light);
    if (c_4 <= 0.0) {
        return 0.0;
    }
    return (pdf_area * d2_5) / c_4;
}

float cos_sub_clamped(
    float sin_a,
    float cos_a,
    float sin_b,
    float cos_b
) {
    if (cos_a > cos_b) {
        return 1.0;
    }
    return (cos_a * cos_b) + (sin_a * sin_b);
}

float sin_sub_clamped(
    float sin_a_1,
    float cos_a_1,
    float sin_b_1,
    float cos_b_1
) {
    if (cos_a_1 > cos_b_1) {
        return 0.0;
    }
    return (sin_a_1 * cos_b_1) - (cos_a_1 * sin_b_1);
}

float safe_sqrt(
    float x_2
) {
    return metal::sqrt(metal::max(x_2, 0.0));
}

float light_importance(
    metal::float3 center,
    float radius,
    float phi,
    metal::float3 axis,
    float cos_o,
    float cos_e,
    metal::float3 p,
    metal::float3 n_2
) {
    float imp = {};
    metal::float3 v_2 = p - center;
    float dist2_ = metal::dot(v_2, v_2);
    float r2_3 = radius * radius;
    float d2_8 = metal::max(metal::max(dist2_, r2_3), MIN_D2_);
    metal::float3 wi = (dist2_ > 0.0) ? (v_2 / metal::float3(metal::sqrt(dist2_))) : metal::float3(0.0, 0.0, 0.0);
    float cos_w = metal::dot(axis, wi);
    float _e28 = safe_sqrt(1.0 - (cos_w * cos_w));
    float _e32 = safe_sqrt(1.0 - (r2_3 / dist2_));
    float cos_b_2 = (dist2_ <= r2_3) ? -1.0 : _e32;
    float _e39 = safe_sqrt(1.0 - (cos_b_2 * cos_b_2));
    float _e43 = safe_sqrt(1.0 - (cos_o * cos_o));
    float _e44 = cos_sub_clamped(_e28, cos_w, _e43, cos_o);
    float _e45 = sin_sub_clamped(_e28, cos_w, _e43, cos_o);
    float _e46 = cos_sub_clamped(_e45, _e44, _e39, cos_b_2);
    if (_e46 <= cos_e) {
        return 0.0;
    }
    imp = (phi * _e46) / d2_8;
    if (metal::dot(n_2, n_2) > 0.0) {
        float cos_i = -(metal::dot(wi, n_2));
        float _e60 = safe_sqrt(1.0 - (cos_i * cos_i));
        float _e61 = imp;
        float _e62 = cos_sub_clamped(_e60, cos_i, _e39, cos_b_2);
        imp = _e61 * metal::max(_e62, 0.0);
    }
    float _e66 = imp;
    return metal::max(_e66, 0.0);
}

float bvh_first_prob(
    float c0_,
    float c1_
) {
    float s = c0_ + c1_;
    if (s > 0.0) {
        return c0_ / s;
    }
    return -1.0;
}

float bvh_remap_u(
    float u_1,
    float p0_,
    bool first
) {
    if (first) {
        return metal::min(u_1 / p0_, ONE_MINUS_EPSILON);
    }
    return metal::clamp((u_1 - p0_) / (1.0 - p0_), 0.0, ONE_MINUS_EPSILON);
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
    metal::float3 d
) {
    float _e2 = ray_inverse(d.x);
    float _e4 = ray_inverse(d.y);
    float _e6 = ray_inverse(d.z);
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

metal::float3 triangle_normal(
    metal::float3 a_3,
    metal::float3 b_3,
    metal::float3 c_1
) {
    bool local_2 = {};
    metal::float3 n_11 = metal::cross(b_3 - a_3, c_1 - a_3);
    float l2_ = metal::dot(n_11, n_11);
    if (!(!((l2_ > 0.0)))) {
        local_2 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_2 = true;
    }
    bool _e17 = local_2;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_11 / metal::float3(metal::sqrt(l2_));
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_1,
    metal::float3 a_4,
    metal::float3 b_4,
    metal::float3 c_2,
    float t_min,
    float t_max_1
) {
    bool local_3 = {};
    bool local_4 = {};
    bool local_5 = {};
    metal::float3 e1_ = b_4 - a_4;
    metal::float3 e2_ = c_2 - a_4;
    metal::float3 p_1 = metal::cross(d_1, e2_);
    float det = metal::dot(e1_, p_1);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv = 1.0 / det;
    metal::float3 s_1 = o_1 - a_4;
    float u_3 = metal::dot(s_1, p_1) * inv;
    if (!((u_3 < 0.0))) {
        local_3 = u_3 > 1.0;
    } else {
        local_3 = true;
    }
    bool _e28 = local_3;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q = metal::cross(s_1, e1_);
    float v_3 = metal::dot(d_1, q) * inv;
    if (!((v_3 < 0.0))) {
        local_4 = (u_3 + v_3) > 1.0;
    } else {
        local_4 = true;
    }
    bool _e42 = local_4;
    if (_e42) {
        return -1.0;
    }
    float t = metal::dot(e2_, q) * inv;
    if (t > t_min) {
        local_5 = t < t_max_1;
    } else {
        local_5 = false;
    }
    bool _e51 = local_5;
    if (_e51) {
        return t;
    }
    return -1.0;
}

float mis_power(
    float pdf_a,
    float pdf_b
) {
    float a2_ = pdf_a * pdf_a;
    float s_2 = a2_ + (pdf_b * pdf_b);
    if (s_2 <= 0.0) {
        return 0.0;
    }
    return a2_ / s_2;
}

float light_strategy_pdf(
    float select,
    float rt2_3,
    float d2_6,
    float area_1,
    float cos_y
) {
    bool local_6 = {};
    bool local_7 = {};
    if (!((d2_6 <= 0.0))) {
        local_6 = area_1 <= 0.0;
    } else {
        local_6 = true;
    }
    bool _e13 = local_6;
    if (!(_e13)) {
        local_7 = cos_y <= 0.0;
    } else {
        local_7 = true;
    }
    bool _e20 = local_7;
    if (_e20) {
        return 0.0;
    }
    float _e22 = rr_probability(rt2_3, d2_6);
    float _e26 = area_to_solid_angle_pdf(1.0 / area_1, d2_6, cos_y);
    return (select * _e22) * _e26;
}

float cosine_pdf(
    float cos_theta
) {
    return metal::max(cos_theta, 0.0) * INV_PI;
}

bool finite3_(
    metal::float3 v
) {
    bool local_8 = {};
    bool local_9 = {};
    if (metal::abs(v.x) <= F32_MAX) {
        local_8 = metal::abs(v.y) <= F32_MAX;
    } else {
        local_8 = false;
    }
    bool _e12 = local_8;
    if (_e12) {
        local_9 = metal::abs(v.z) <= F32_MAX;
    } else {
        local_9 = false;
    }
    bool _e20 = local_9;
    return _e20;
}

metal::float3 light_intensity(
    GpuLight l,
    metal::float3 w_2
) {
    switch(l.kind) {
        case 3u: {
            metal::float3 _e7 = triangle_normal(l.p0_, l.p1_, l.p2_);
            float _e9 = triangle_lobe(_e7, l.a, w_2);
            return l.intensity * _e9;
        }
        default: {
            return metal::float3(0.0);
        }
    }
}

metal::float3 light_point(
    GpuLight l_1,
    float u1_1,
    float u2_1
) {
    if (l_1.kind == LIGHT_TRIANGLE) {
        metal::float3 _e9 = triangle_sample(l_1.p0_, l_1.p1_, l_1.p2_, u1_1, u2_1);
        return _e9;
    }
    return l_1.p0_;
}

float light_area(
    GpuLight l_2
) {
    if (l_2.kind == LIGHT_TRIANGLE) {
        return l_2.a;
    }
    return 0.0;
}

metal::float3 light_normal(
    GpuLight l_3
) {
    if (l_3.kind == LIGHT_TRIANGLE) {
        metal::float3 _e7 = triangle_normal(l_3.p0_, l_3.p1_, l_3.p2_);
        return _e7;
    }
    return metal::float3(0.0);
}

GeoHit trace(
    metal::float3 o_2,
    metal::float3 d_2,
    float t_min_1,
    float t_max_2,
    bool any_hit,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    GeoHit hit = {};
    type_8 stack = {};
    uint sp = 0u;
    uint node = 0u;
    uint i = {};
    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((1 + (_buffer_sizes.size0 - 0 - 32) / 32) == 0u) {
        GeoHit _e13 = hit;
        return _e13;
    }
    metal::float3 _e14 = ray_inverse3_(d_2);
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e21 = node;
        GpuGeoNode n_12 = geo_nodes[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_12.bmin, n_12.bmax, _e27);
        if (_e28 >= 0.0) {
            if (n_12.count > 0u) {
                i = n_12.first;
                uint2 loop_bound_1 = uint2(4294967295u);
                bool loop_init = true;
                while(true) {
                    if (metal::all(loop_bound_1 == uint2(0u))) { break; }
                    loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                    if (!loop_init) {
                        uint _e58 = i;
                        i = _e58 + 1u;
                    }
                    loop_init = false;
                    uint _e36 = i;
                    if (_e36 < (n_12.first + n_12.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_1 = geo_tris[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_2, t_1.v0_, t_1.v1_, t_1.v2_, t_min_1, _e49);
                        if (_e50 > 0.0) {
                            hit.t = _e50;
                            uint _e55 = i;
                            hit.tri = _e55;
                            if (any_hit) {
                                GeoHit _e56 = hit;
                                return _e56;
                            }
                        }
                    }
                }
            } else {
                uint _e60 = sp;
                if (_e60 < 64u) {
                    uint _e63 = sp;
                    stack.inner[_e63] = n_12.first + 1u;
                    uint _e68 = sp;
                    sp = _e68 + 1u;
                }
                node = n_12.first;
                continue;
            }
        }
        uint _e72 = sp;
        if (_e72 == 0u) {
            break;
        }
        uint _e75 = sp;
        sp = _e75 - 1u;
        uint _e78 = sp;
        uint _e80 = stack.inner[_e78];
        node = _e80;
    }
    GeoHit _e81 = hit;
    return _e81;
}

bool occluded(
    metal::float3 a_5,
    metal::float3 b_5,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 dv = b_5 - a_5;
    float len_1 = metal::length(dv);
    if (len_1 <= 0.0) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    GeoHit _e12 = trace(a_5, dv / metal::float3(len_1), _e7, len_1 - _e7, true, geo_nodes, geo_tris, _buffer_sizes);
    return _e12.tri != NO_LIGHT;
}

Connection connect(
    uint li,
    metal::float3 x_4,
    metal::float3 n_3,
    metal::float3 ng_1,
    float w_res,
    float u1_2,
    float u2_2,
    float eps,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    device type_9 const& lights,
    device type_4 const& r2_2,
    device type_4 const& rt2_4,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection c_3 = {};
    bool local_10 = {};
    c_3.e = metal::float3(0.0);
    GpuLight l_4 = lights[li];
    metal::float3 _e16 = light_point(l_4, u1_2, u2_2);
    c_3.y = _e16;
    metal::float3 _e19 = c_3.y;
    float _e22 = r2_2[li];
    float _e23 = connection_cosine(x_4, _e19, n_3, ng_1, _e22);
    c_3.cos_x = _e23;
    float _e25 = c_3.cos_x;
    if (!((_e25 <= 0.0))) {
        metal::float3 _e34 = c_3.y;
        bool _e35 = occluded(x_4 + (ng_1 * eps), _e34, geo_nodes, geo_tris, _buffer_sizes);
        local_10 = _e35;
    } else {
        local_10 = true;
    }
    bool _e37 = local_10;
    if (_e37) {
        Connection _e38 = c_3;
        return _e38;
    }
    metal::float3 _e40 = c_3.y;
    metal::float3 v_4 = x_4 - _e40;
    float d2_9 = metal::dot(v_4, v_4);
    metal::float3 _e47 = light_intensity(l_4, v_4 / metal::float3(metal::sqrt(d2_9)));
    float _e49 = c_3.cos_x;
    float _e52 = rt2_4[li];
    float _e53 = connection_factor(_e49, d2_9, _e52, w_res);
    c_3.e = _e47 * _e53;
    Connection _e55 = c_3;
    return _e55;
}

float mis_weight(
    float pdf_a_1,
    float pdf_b_1
) {
    float _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

GpuLightBvhNode light_bvh_node(
    BvhNodes nodes,
    uint i_1,
    device type_12 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightBvhNode _e4 = light_bvh[i_1];
    return _e4;
}

uint light_bvh_count(
    BvhNodes nodes_1,
    device type_12 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    return 1 + (_buffer_sizes.size6 - 0 - 48) / 48;
}

float bvh_importance(
    BvhNodes nodes_2,
    uint i_2,
    metal::float3 x_5,
    metal::float3 n_4,
    device type_12 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightBvhNode _e4 = light_bvh_node(nodes_2, i_2, light_bvh, _buffer_sizes);
    float _e11 = light_importance(_e4.center, _e4.radius, _e4.phi, _e4.axis, _e4.cos_o, _e4.cos_e, x_5, n_4);
    return _e11;
}

float bvh_first(
    BvhNodes nodes_3,
    uint i_3,
    metal::float3 x_6,
    metal::float3 n_5,
    device type_12 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_11 = {};
    GpuLightBvhNode _e4 = light_bvh_node(nodes_3, i_3, light_bvh, _buffer_sizes);
    uint j = _e4.second;
    if (!((j <= (i_3 + 1u)))) {
        uint _e12 = light_bvh_count(nodes_3, light_bvh, _buffer_sizes);
        local_11 = j >= _e12;
    } else {
        local_11 = true;
    }
    bool _e15 = local_11;
    if (_e15) {
        return -1.0;
    }
    float _e19 = bvh_importance(nodes_3, i_3 + 1u, x_6, n_5, light_bvh, _buffer_sizes);
    float _e20 = bvh_importance(nodes_3, j, x_6, n_5, light_bvh, _buffer_sizes);
    float _e21 = bvh_first_prob(_e19, _e20);
    return _e21;
}

BvhPick bvh_pick_none(
) {
    return BvhPick {0u, 0.0};
}

BvhPick light_bvh_sample(
    BvhNodes nodes_4,
    metal::float3 x_7,
    metal::float3 n_6,
    float u_in,
    device type_12 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    BvhPick pick = {};
    float u_2 = {};
    uint i_4 = 0u;
    float pmf = 1.0;
    bool local_12 = {};
    BvhPick _e4 = bvh_pick_none();
    pick = _e4;
    u_2 = u_in;
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e11 = i_4;
        uint _e12 = light_bvh_count(nodes_4, light_bvh, _buffer_sizes);
        if (_e11 < _e12) {
        } else {
            break;
        }
        {
            uint _e14 = i_4;
            GpuLightBvhNode _e15 = light_bvh_node(nodes_4, _e14, light_bvh, _buffer_sizes);
            if (_e15.second == LIGHT_BVH_LEAF) {
                uint _e19 = i_4;
                if (!((_e19 > 0u))) {
                    float _e26 = bvh_importance(nodes_4, 0u, x_7, n_6, light_bvh, _buffer_sizes);
                    local_12 = _e26 > 0.0;
                } else {
                    local_12 = true;
                }
                bool _e30 = local_12;
                if (_e30) {
                    pick.light = _e15.light;
                    float _e34 = pmf;
                    pick.pmf = _e34;
                }
                BvhPick _e35 = pick;
                return _e35;
            }
            uint _e36 = i_4;
            float _e37 = bvh_first(nodes_4, _e36, x_7, n_6, light_bvh, _buffer_sizes);
            if (_e37 < 0.0) {
                BvhPick _e40 = pick;
                return _e40;
            }
            float _e41 = u_2;
            bool first_1 = _e41 < _e37;
            float _e43 = pmf;
            pmf = _e43 * (first_1 ? _e37 : (1.0 - _e37));
            float _e48 = u_2;
            float _e49 = bvh_remap_u(_e48, _e37, first_1);
            u_2 = _e49;
            uint _e51 = i_4;
            i_4 = first_1 ? (_e51 + 1u) : _e15.second;
        }
    }
    BvhPick _e55 = pick;
    return _e55;
}

float light_bvh_pmf(
    BvhNodes nodes_5,
    uint leaf,
    metal::float3 x_8,
    metal::float3 n_7,
    device type_12 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_5 = 0u;
    float pmf_1 = 1.0;
    bool local_13 = {};
    bool local_14 = {};
    uint _e4 = light_bvh_count(nodes_5, light_bvh, _buffer_sizes);
    if (leaf >= _e4) {
        return 0.0;
    }
    uint2 loop_bound_3 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e11 = i_5;
        uint _e12 = light_bvh_count(nodes_5, light_bvh, _buffer_sizes);
        if (_e11 < _e12) {
        } else {
            break;
        }
        {
            uint _e14 = i_5;
            GpuLightBvhNode _e15 = light_bvh_node(nodes_5, _e14, light_bvh, _buffer_sizes);
            if (_e15.second == LIGHT_BVH_LEAF) {
                uint _e19 = i_5;
                if (_e19 == leaf) {
                    uint _e23 = i_5;
                    if (!((_e23 > 0u))) {
                        float _e30 = bvh_importance(nodes_5, 0u, x_8, n_7, light_bvh, _buffer_sizes);
                        local_14 = _e30 > 0.0;
                    } else {
                        local_14 = true;
                    }
                    bool _e34 = local_14;
                    local_13 = _e34;
                } else {
                    local_13 = false;
                }
                bool _e36 = local_13;
                if (_e36) {
                    float _e37 = pmf_1;
                    return _e37;
                }
                return 0.0;
            }
            uint _e39 = i_5;
            float _e40 = bvh_first(nodes_5, _e39, x_8, n_7, light_bvh, _buffer_sizes);
            if (_e40 < 0.0) {
                return 0.0;
            }
            bool first_2 = leaf < _e15.second;
            float _e46 = pmf_1;
            pmf_1 = _e46 * (first_2 ? _e40 : (1.0 - _e40));
            uint _e52 = i_5;
            i_5 = first_2 ? (_e52 + 1u) : _e15.second;
        }
    }
    return 0.0;
}

float select_pdf(
    uint li_1,
    metal::float3 x_9,
    metal::float3 n_8,
    uint nee,
    bool in_range,
    device type_11 const& light_cones,
    device type_12 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e9 = light_cones[li_1].bvh_leaf;
    float _e10 = light_bvh_pmf(BVH, _e9, x_9, n_8, light_bvh, _buffer_sizes);
    return _e10;
}

float light_pdf(
    uint li_2,
    metal::float3 x_10,
    metal::float3 n_9,
    metal::float3 y_1,
    uint nee_1,
    bool in_range_1,
    device type_9 const& lights,
    device type_4 const& rt2_4,
    device type_11 const& light_cones,
    device type_12 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight l_5 = lights[li_2];
    metal::float3 v_5 = x_10 - y_1;
    float d2_10 = metal::dot(v_5, v_5);
    metal::float3 _e11 = light_normal(l_5);
    float cos_y_1 = (d2_10 > 0.0) ? metal::dot(_e11, v_5 / metal::float3(metal::sqrt(d2_10))) : 0.0;
    float _e20 = select_pdf(li_2, x_10, n_9, nee_1, in_range_1, light_cones, light_bvh, _buffer_sizes);
    float _e23 = rt2_4[li_2];
    float _e24 = light_area(l_5);
    float _e25 = light_strategy_pdf(_e20, _e23, d2_10, _e24, cos_y_1);
    return _e25;
}

metal::float3 shade_pick(
    uint li_3,
    metal::float3 x_11,
    metal::float3 n_10,
    metal::float3 ng_2,
    float w_3,
    uint nee_2,
    float u1_3,
    float u2_3,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    device type_9 const& lights,
    device type_4 const& r2_2,
    device type_4 const& rt2_4,
    device type_11 const& light_cones,
    device type_12 const& light_bvh,
    constant ShadeParams& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    float mis = 1.0;
    bool local_15 = {};
    float _e10 = params.eps;
    Connection _e11 = connect(li_3, x_11, n_10, ng_2, w_3, u1_3, u2_3, _e10, geo_nodes, geo_tris, lights, r2_2, rt2_4, _buffer_sizes);
    GpuLight _e16 = lights[li_3];
    float _e17 = light_area(_e16);
    if (_e17 > 0.0) {
        local_15 = _e11.cos_x > 0.0;
    } else {
        local_15 = false;
    }
    bool _e26 = local_15;
    if (_e26) {
        float _e29 = light_pdf(li_3, x_11, n_10, _e11.y, nee_2, true, lights, rt2_4, light_cones, light_bvh, _buffer_sizes);
        float _e31 = cosine_pdf(_e11.cos_x);
        float _e32 = mis_weight(_e29, _e31);
        mis = _e32;
    }
    float _e34 = mis;
    return _e11.e * _e34;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, device type_6 const& geo_nodes [[user(fake0)]]
, device type_7 const& geo_tris [[user(fake0)]]
, device type_9 const& lights [[user(fake0)]]
, device type_4 const& r2_2 [[user(fake0)]]
, device type_4 const& rt2_4 [[user(fake0)]]
, device type_11 const& light_cones [[user(fake0)]]
, device type_12 const& light_bvh [[user(fake0)]]
, constant ShadeParams& params [[user(fake0)]]
, device type_13 const& vertices [[user(fake0)]]
, device type_10& radiance [[user(fake0)]]
, device type_14& candidates [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint h = {};
    metal::float3 sum = metal::float3(0.0);
    uint i_6 = gid.x;
    uint _e4 = params.point_count;
    if (i_6 >= _e4) {
        return;
    }
    GpuPathVertex vtx = vertices[i_6];
    if (vtx.alive == 0u) {
        candidates[i_6] = 0u;
        return;
    }
    metal::float3 x_12 = vtx.position;
    metal::float3 n_13 = vtx.normal;
    metal::float3 ng_3 = vtx.gnormal;
    uint _e20 = params.seed;
    uint _e23 = params.frame;
    uint _e24 = point_stream(_e20, i_6, _e23);
    uint _e25 = pick_stream(_e24);
    h = _e25;
    candidates[i_6] = 0u;
    uint _e33 = h;
    uint _e34 = pcg_hash(_e33);
    h = _e34;
    uint _e35 = h;
    float _e36 = xi_from_bits(_e35);
    BvhPick _e38 = light_bvh_sample(BVH, x_12, n_13, _e36, light_bvh, _buffer_sizes);
    uint li_4 = _e38.light;
    float pmf_2 = _e38.pmf;
    uint _e41 = h;
    uint _e42 = pcg_hash(_e41);
    h = _e42;
    uint _e43 = h;
    float _e44 = xi_from_bits(_e43);
    uint _e45 = h;
    uint _e46 = pcg_hash(_e45);
    h = _e46;
    uint _e47 = h;
    float _e48 = xi_from_bits(_e47);
    if (pmf_2 > 0.0) {
        metal::float3 _e54 = shade_pick(li_4, x_12, n_13, ng_3, 1.0 / pmf_2, 0u, _e44, _e48, geo_nodes, geo_tris, lights, r2_2, rt2_4, light_cones, light_bvh, params, _buffer_sizes);
        sum = _e54;
    }
    metal::float3 _e56 = sum;
    metal::float3 add = vtx.weight * _e56;
    bool _e58 = finite3_(add);
    if (_e58) {
        metal::float4 _e61 = radiance[i_6];
        radiance[i_6] = _e61 + metal::float4(add, 0.0);
        return;
    } else {
        return;
    }
}
