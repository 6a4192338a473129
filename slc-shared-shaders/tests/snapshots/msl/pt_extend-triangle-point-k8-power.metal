// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size1;
    uint size2;
    uint size3;
    uint size5;
    uint size6;
    uint size7;
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
struct GpuPathState {
    metal::packed_float3 origin;
    uint alive;
    metal::packed_float3 dir;
    uint rng;
    metal::packed_float3 beta;
    float pdf_bsdf;
    metal::packed_float3 prev;
    uint pad;
    metal::packed_float3 prev_normal;
    uint pad2_;
};
struct PtParams {
    metal::packed_float3 cam_pos;
    uint width;
    metal::packed_float3 cam_right;
    uint height;
    metal::packed_float3 cam_up;
    uint depth;
    metal::packed_float3 cam_forward;
    uint seed;
    uint pass_index;
    uint max_depth;
    float eps;
    float t_min;
};
typedef float type_4[1];
struct BshNode {
    metal::packed_float3 center;
    float radius;
    uint child;
    uint next;
    uint light;
    uint pad;
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
typedef metal::float4 type_9[1];
typedef uint BvhNodes;
typedef GpuLight type_10[1];
typedef BshNode type_11[1];
typedef uint type_12[1];
typedef GpuPathState type_13[1];
typedef GpuPathVertex type_14[1];
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

uint path_stream(
    uint seed_1,
    uint pixel,
    uint pass_index
) {
    uint _e4 = add_wrap_u32_(pass_index, PICK_STREAM);
    uint _e5 = point_stream(seed_1, pixel, _e4);
    return _e5;
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

bool sphere_contains_point(
    metal::float3 c,
    float r,
    metal::float3 x_1
) {
    metal::float3 v_2 = x_1 - c;
    return metal::dot(v_2, v_2) <= (r * r);
}

float area_to_solid_angle_pdf(
    float pdf_area,
    float d2_1,
    float cos_light
) {
    float c_4 = metal::abs(cos_light);
    if (c_4 <= 0.0) {
        return 0.0;
    }
    return (pdf_area * d2_1) / c_4;
}

float reservoir_weight(
    uint n,
    uint k
) {
    float _e2 = to_f32_(n);
    float _e3 = to_f32_(k);
    return metal::max(_e2 / _e3, 1.0);
}

float reservoir_select_pdf(
    uint seen,
    bool in_range,
    uint k_1
) {
    uint others = {};
    bool local_3 = {};
    others = seen;
    if (in_range) {
        local_3 = seen > 0u;
    } else {
        local_3 = false;
    }
    bool _e9 = local_3;
    if (_e9) {
        others = seen - 1u;
    }
    uint _e12 = others;
    float _e15 = reservoir_weight(_e12 + 1u, k_1);
    return 1.0 / _e15;
}

float ray_inverse(
    float x_2
) {
    return 1.0 / ((metal::abs(x_2) < 0.000000000000000000000000000001) ? 0.000000000000000000000000000001 : x_2);
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
    metal::float3 a_2,
    metal::float3 b_2,
    metal::float3 c_1
) {
    bool local_4 = {};
    metal::float3 n_9 = metal::cross(b_2 - a_2, c_1 - a_2);
    float l2_ = metal::dot(n_9, n_9);
    if (!(!((l2_ > 0.0)))) {
        local_4 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_4 = true;
    }
    bool _e17 = local_4;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_9 / metal::float3(metal::sqrt(l2_));
}

metal::float3 face_against(
    metal::float3 n_1,
    metal::float3 dir
) {
    return (metal::dot(n_1, dir) > 0.0) ? -(n_1) : n_1;
}

metal::float3 barycentric(
    metal::float3 p,
    metal::float3 a_3,
    metal::float3 b_3,
    metal::float3 c_2
) {
    metal::float3 e1_ = b_3 - a_3;
    metal::float3 e2_ = c_2 - a_3;
    metal::float3 q = p - a_3;
    float d11_ = metal::dot(e1_, e1_);
    float d12_ = metal::dot(e1_, e2_);
    float d22_ = metal::dot(e2_, e2_);
    float den = (d11_ * d22_) - (d12_ * d12_);
    if (!((metal::abs(den) > 0.0))) {
        return metal::float3(1.0, 0.0, 0.0);
    }
    float w1_ = ((d22_ * metal::dot(q, e1_)) - (d12_ * metal::dot(q, e2_))) / den;
    float w2_ = ((d11_ * metal::dot(q, e2_)) - (d12_ * metal::dot(q, e1_))) / den;
    return metal::float3((1.0 - w1_) - w2_, w1_, w2_);
}

metal::float3 shading_normal(
    metal::float3 n0_,
    metal::float3 n1_,
    metal::float3 n2_,
    metal::float3 w_1,
    metal::float3 facing
) {
    bool local_5 = {};
    metal::float3 s = ((n0_ * w_1.x) + (n1_ * w_1.y)) + (n2_ * w_1.z);
    float l2_1 = metal::dot(s, s);
    if (!(!((l2_1 > 0.000000000001)))) {
        local_5 = !((l2_1 < 300000000000000000000000000000000000000.0));
    } else {
        local_5 = true;
    }
    bool _e24 = local_5;
    if (_e24) {
        return facing;
    }
    metal::float3 n_10 = s / metal::float3(metal::sqrt(l2_1));
    return (metal::dot(n_10, facing) < 0.0) ? -(n_10) : n_10;
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_1,
    metal::float3 a_4,
    metal::float3 b_4,
    metal::float3 c_3,
    float t_min,
    float t_max_1
) {
    bool local_6 = {};
    bool local_7 = {};
    bool local_8 = {};
    metal::float3 e1_1 = b_4 - a_4;
    metal::float3 e2_1 = c_3 - a_4;
    metal::float3 p_1 = metal::cross(d_1, e2_1);
    float det = metal::dot(e1_1, p_1);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv = 1.0 / det;
    metal::float3 s_1 = o_1 - a_4;
    float u_2 = metal::dot(s_1, p_1) * inv;
    if (!((u_2 < 0.0))) {
        local_6 = u_2 > 1.0;
    } else {
        local_6 = true;
    }
    bool _e28 = local_6;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q_1 = metal::cross(s_1, e1_1);
    float v_3 = metal::dot(d_1, q_1) * inv;
    if (!((v_3 < 0.0))) {
        local_7 = (u_2 + v_3) > 1.0;
    } else {
        local_7 = true;
    }
    bool _e42 = local_7;
    if (_e42) {
        return -1.0;
    }
    float t = metal::dot(e2_1, q_1) * inv;
    if (t > t_min) {
        local_8 = t < t_max_1;
    } else {
        local_8 = false;
    }
    bool _e51 = local_8;
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
    float rt2_1,
    float d2_2,
    float area,
    float cos_y
) {
    bool local_9 = {};
    bool local_10 = {};
    if (!((d2_2 <= 0.0))) {
        local_9 = area <= 0.0;
    } else {
        local_9 = true;
    }
    bool _e13 = local_9;
    if (!(_e13)) {
        local_10 = cos_y <= 0.0;
    } else {
        local_10 = true;
    }
    bool _e20 = local_10;
    if (_e20) {
        return 0.0;
    }
    float _e22 = rr_probability(rt2_1, d2_2);
    float _e26 = area_to_solid_angle_pdf(1.0 / area, d2_2, cos_y);
    return (select * _e22) * _e26;
}

metal::float3 lambert_brdf(
    metal::float3 rho
) {
    return rho * INV_PI;
}

float cosine_pdf(
    float cos_theta
) {
    return metal::max(cos_theta, 0.0) * INV_PI;
}

metal::float3 onb_tangent(
    metal::float3 n_2
) {
    float s_3 = (n_2.z >= 0.0) ? 1.0 : -1.0;
    float a_5 = -1.0 / (s_3 + n_2.z);
    return metal::float3(1.0 + (((s_3 * n_2.x) * n_2.x) * a_5), ((s_3 * n_2.x) * n_2.y) * a_5, -(s_3) * n_2.x);
}

metal::float3 onb_bitangent(
    metal::float3 n_3
) {
    float s_4 = (n_3.z >= 0.0) ? 1.0 : -1.0;
    float a_6 = -1.0 / (s_4 + n_3.z);
    return metal::float3((n_3.x * n_3.y) * a_6, s_4 + ((n_3.y * n_3.y) * a_6), -(n_3.y));
}

metal::float3 onb_to_world(
    metal::float3 n_4,
    metal::float3 d_2
) {
    metal::float3 _e2 = onb_tangent(n_4);
    metal::float3 _e5 = onb_bitangent(n_4);
    return ((_e2 * d_2.x) + (_e5 * d_2.y)) + (n_4 * d_2.z);
}

metal::float3 cosine_direction(
    metal::float3 n_5,
    float u1_,
    float u2_
) {
    float r_1 = metal::sqrt(u1_);
    float phi = 6.2831855 * u2_;
    metal::float3 _e16 = onb_to_world(n_5, metal::float3(r_1 * metal::cos(phi), r_1 * metal::sin(phi), metal::sqrt(metal::max(1.0 - u1_, 0.0))));
    return metal::normalize(_e16);
}

metal::float3 camera_dir(
    metal::float3 forward,
    metal::float3 right,
    metal::float3 up,
    float px,
    float py,
    float w_2,
    float h_1
) {
    float sx = ((2.0 * px) / w_2) - 1.0;
    float sy = 1.0 - ((2.0 * py) / h_1);
    return metal::normalize((forward + (right * sx)) + (up * sy));
}

float jittered_pixel(
    uint coord,
    float u_1
) {
    float _e2 = to_f32_(coord);
    return _e2 + u_1;
}

bool plays_roulette(
    uint depth
) {
    return depth >= ROULETTE_DEPTH;
}

bool sees_emission(
    metal::float3 gn,
    metal::float3 dir_1
) {
    return metal::dot(gn, dir_1) < 0.0;
}

bool continues_path(
    metal::float3 nd,
    metal::float3 n_6,
    metal::float3 ng
) {
    bool local_11 = {};
    if (metal::dot(nd, n_6) > 0.0) {
        local_11 = metal::dot(nd, ng) > 0.0;
    } else {
        local_11 = false;
    }
    bool _e12 = local_11;
    return _e12;
}

bool finite3_(
    metal::float3 v_1
) {
    bool local_12 = {};
    bool local_13 = {};
    if (metal::abs(v_1.x) <= F32_MAX) {
        local_12 = metal::abs(v_1.y) <= F32_MAX;
    } else {
        local_12 = false;
    }
    bool _e12 = local_12;
    if (_e12) {
        local_13 = metal::abs(v_1.z) <= F32_MAX;
    } else {
        local_13 = false;
    }
    bool _e20 = local_13;
    return _e20;
}

float path_survival(
    metal::float3 beta
) {
    return metal::clamp(metal::max(metal::max(beta.x, beta.y), beta.z), 0.05, 0.95);
}

float light_area(
    GpuLight l
) {
    if (l.kind == LIGHT_TRIANGLE) {
        return l.a;
    }
    return 0.0;
}

metal::float3 light_normal(
    GpuLight l_1
) {
    if (l_1.kind == LIGHT_TRIANGLE) {
        metal::float3 _e7 = triangle_normal(l_1.p0_, l_1.p1_, l_1.p2_);
        return _e7;
    }
    return metal::float3(0.0);
}

GeoHit trace(
    metal::float3 o_2,
    metal::float3 d_3,
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
    metal::float3 _e14 = ray_inverse3_(d_3);
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e21 = node;
        GpuGeoNode n_11 = geo_nodes[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_11.bmin, n_11.bmax, _e27);
        if (_e28 >= 0.0) {
            if (n_11.count > 0u) {
                i = n_11.first;
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
                    if (_e36 < (n_11.first + n_11.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i;
                        GpuTriangle t_1 = geo_tris[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_3, t_1.v0_, t_1.v1_, t_1.v2_, t_min_1, _e49);
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
                    stack.inner[_e63] = n_11.first + 1u;
                    uint _e68 = sp;
                    sp = _e68 + 1u;
                }
                node = n_11.first;
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

float mis_weight(
    float pdf_a_1,
    float pdf_b_1
) {
    float _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

float select_pdf(
    uint li,
    metal::float3 x_3,
    metal::float3 n_7,
    uint nee,
    bool in_range_1
) {
    float _e6 = reservoir_select_pdf(nee, in_range_1, K);
    return _e6;
}

float light_pdf(
    uint li_1,
    metal::float3 x_4,
    metal::float3 n_8,
    metal::float3 y,
    uint nee_1,
    bool in_range_2,
    device type_4 const& rt2_2,
    device type_10 const& lights,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight l_2 = lights[li_1];
    metal::float3 v_4 = x_4 - y;
    float d2_3 = metal::dot(v_4, v_4);
    metal::float3 _e11 = light_normal(l_2);
    float cos_y_1 = (d2_3 > 0.0) ? metal::dot(_e11, v_4 / metal::float3(metal::sqrt(d2_3))) : 0.0;
    float _e20 = select_pdf(li_1, x_4, n_8, nee_1, in_range_2);
    float _e23 = rt2_2[li_1];
    float _e24 = light_area(l_2);
    float _e25 = light_strategy_pdf(_e20, _e23, d2_3, _e24, cos_y_1);
    return _e25;
}

float next_uniform(
    thread uint& state
) {
    uint _e1 = state;
    uint _e2 = pcg_hash(_e1);
    state = _e2;
    uint _e3 = state;
    float _e4 = xi_from_bits(_e3);
    return _e4;
}
uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}


struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, device type_6 const& geo_nodes [[user(fake0)]]
, device type_7 const& geo_tris [[user(fake0)]]
, device type_4 const& rt2_2 [[user(fake0)]]
, device type_10 const& lights [[user(fake0)]]
, constant PtParams& params [[user(fake0)]]
, device type_11 const& bsh_nodes [[user(fake0)]]
, device type_12 const& light_leaf [[user(fake0)]]
, device type_9 const& albedo [[user(fake0)]]
, device type_9 const& geo_normals [[user(fake0)]]
, device type_12 const& candidates [[user(fake0)]]
, device type_13& paths [[user(fake0)]]
, device type_14& vertices [[user(fake0)]]
, device type_9& radiance [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    GpuPathState st = {};
    uint h = {};
    GpuPathVertex v = {};
    bool local = {};
    float w = 1.0;
    uint rng = {};
    bool local_1 = {};
    bool local_2 = {};
    uint i_1 = gid.x;
    uint _e4 = params.width;
    uint _e7 = params.height;
    if (i_1 >= (_e4 * _e7)) {
        return;
    }
    uint _e13 = params.depth;
    if (_e13 == 0u) {
        uint _e18 = params.seed;
        uint _e21 = params.pass_index;
        uint _e22 = path_stream(_e18, i_1, _e21);
        h = _e22;
        uint _e26 = params.width;
        float _e28 = next_uniform(h);
        float _e29 = jittered_pixel(naga_mod(i_1, _e26), _e28);
        uint _e32 = params.width;
        float _e34 = next_uniform(h);
        float _e35 = jittered_pixel(naga_div(i_1, _e32), _e34);
        metal::float3 _e39 = params.cam_pos;
        st.origin = _e39;
        metal::float3 _e43 = params.cam_forward;
        metal::float3 _e46 = params.cam_right;
        metal::float3 _e49 = params.cam_up;
        uint _e52 = params.width;
        uint _e56 = params.height;
        metal::float3 _e58 = camera_dir(_e43, _e46, _e49, _e29, _e35, static_cast<float>(_e52), static_cast<float>(_e56));
        st.dir = _e58;
        st.alive = 1u;
        uint _e62 = h;
        st.rng = _e62;
        st.beta = metal::float3(1.0);
        st.pdf_bsdf = 0.0;
        metal::float3 _e71 = params.cam_pos;
        st.prev = _e71;
    } else {
        GpuPathState _e74 = paths[i_1];
        st = _e74;
    }
    v.alive = 0u;
    uint _e79 = st.alive;
    if (_e79 == 0u) {
        GpuPathVertex _e84 = v;
        vertices[i_1] = _e84;
        return;
    }
    metal::float3 _e86 = st.origin;
    metal::float3 _e88 = st.dir;
    float _e91 = params.t_min;
    GeoHit _e94 = trace(_e86, _e88, _e91, F32_MAX, false, geo_nodes, geo_tris, _buffer_sizes);
    if (_e94.tri == NO_LIGHT) {
        st.alive = 0u;
        GpuPathState _e102 = st;
        paths[i_1] = _e102;
        GpuPathVertex _e105 = v;
        vertices[i_1] = _e105;
        return;
    }
    GpuTriangle tri = geo_tris[_e94.tri];
    metal::float3 _e111 = st.origin;
    metal::float3 _e113 = st.dir;
    metal::float3 x_5 = _e111 + (_e113 * _e94.t);
    metal::float3 _e120 = triangle_normal(tri.v0_, tri.v1_, tri.v2_);
    metal::float3 _e122 = st.dir;
    metal::float3 _e123 = face_against(_e120, _e122);
    uint b_5 = _e94.tri * 3u;
    metal::float4 _e129 = geo_normals[b_5];
    metal::float4 _e135 = geo_normals[b_5 + 1u];
    metal::float4 _e141 = geo_normals[b_5 + 2u];
    metal::float3 _e146 = barycentric(x_5, tri.v0_, tri.v1_, tri.v2_);
    metal::float3 _e147 = shading_normal(_e129.xyz, _e135.xyz, _e141.xyz, _e146, _e123);
    if (tri.light != NO_LIGHT) {
        metal::float3 _e154 = st.dir;
        bool _e155 = sees_emission(_e120, _e154);
        local = _e155;
    } else {
        local = false;
    }
    bool _e157 = local;
    if (_e157) {
        float _e161 = st.pdf_bsdf;
        if (_e161 > 0.0) {
            uint _e168 = light_leaf[tri.light];
            BshNode leaf = bsh_nodes[_e168];
            metal::float3 _e174 = st.prev;
            bool _e175 = sphere_contains_point(leaf.center, leaf.radius, _e174);
            float _e177 = st.pdf_bsdf;
            metal::float3 _e180 = st.prev;
            metal::float3 _e182 = st.prev_normal;
            uint _e185 = candidates[i_1];
            float _e186 = light_pdf(tri.light, _e180, _e182, x_5, _e185, _e175, rt2_2, lights, _buffer_sizes);
            float _e187 = mis_weight(_e177, _e186);
            w = _e187;
        }
        metal::float3 _e189 = st.beta;
        metal::float3 _e194 = lights[tri.light].intensity;
        float _e196 = w;
        metal::float3 add = (_e189 * _e194) * _e196;
        bool _e198 = finite3_(add);
        if (_e198) {
            metal::float4 _e201 = radiance[i_1];
            radiance[i_1] = _e201 + metal::float4(add, 0.0);
        }
    }
    metal::float4 _e208 = albedo[tri.material];
    metal::float3 rho_1 = _e208.xyz;
    v.position = x_5;
    v.normal = _e147;
    v.gnormal = _e123;
    metal::float3 _e215 = st.beta;
    metal::float3 _e216 = lambert_brdf(rho_1);
    v.weight = _e215 * _e216;
    v.alive = 1u;
    GpuPathVertex _e222 = v;
    vertices[i_1] = _e222;
    uint _e224 = st.rng;
    rng = _e224;
    float _e226 = next_uniform(rng);
    float _e227 = next_uniform(rng);
    metal::float3 _e228 = cosine_direction(_e147, _e226, _e227);
    float cos_o = metal::dot(_e228, _e147);
    metal::float3 _e231 = st.beta;
    st.beta = _e231 * rho_1;
    st.prev = x_5;
    st.prev_normal = _e147;
    float _e236 = cosine_pdf(cos_o);
    st.pdf_bsdf = _e236;
    float _e240 = params.eps;
    st.origin = x_5 + (_e123 * _e240);
    st.dir = _e228;
    bool _e244 = continues_path(_e228, _e147, _e123);
    if (!(!(_e244))) {
        uint _e251 = params.depth;
        uint _e256 = params.max_depth;
        local_1 = (_e251 + 1u) >= _e256;
    } else {
        local_1 = true;
    }
    bool _e259 = local_1;
    if (_e259) {
        st.alive = 0u;
    }
    uint _e264 = params.depth;
    bool _e265 = plays_roulette(_e264);
    if (_e265) {
        uint _e269 = st.alive;
        local_2 = _e269 == 1u;
    } else {
        local_2 = false;
    }
    bool _e273 = local_2;
    if (_e273) {
        metal::float3 _e275 = st.beta;
        float _e276 = path_survival(_e275);
        float _e277 = next_uniform(rng);
        if (_e277 >= _e276) {
            st.alive = 0u;
        } else {
            metal::float3 _e282 = st.beta;
            st.beta = _e282 / metal::float3(_e276);
        }
    }
    uint _e286 = rng;
    st.rng = _e286;
    GpuPathState _e289 = st;
    paths[i_1] = _e289;
    return;
}
