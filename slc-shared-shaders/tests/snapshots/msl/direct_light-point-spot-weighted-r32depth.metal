// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size4;
    uint size5;
    uint size6;
    uint size7;
    uint size8;
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
struct ViewParams {
    metal::float4 c0_;
    metal::float4 c1_;
    metal::float4 c2_;
    metal::float4 c3_;
    metal::packed_float3 eye;
    uint width;
    uint height;
    float background;
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
    uint pad;
};
typedef GpuLight type_8[1];
typedef BshNode type_9[1];
typedef GpuLightCone type_10[1];
struct type_11 {
    uint inner[8];
};
typedef uint BshNodes;
struct Connection {
    metal::float3 e;
    metal::packed_float3 y;
    float cos_x;
};
struct type_12 {
    float inner[8];
};
struct WeightedPicks {
    type_11 light;
    type_12 w;
    float w_sum;
    uint n;
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
    metal::float3 v;
};
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
    float r,
    metal::float3 x_1
) {
    metal::float3 v = x_1 - c;
    return metal::dot(v, v) <= (r * r);
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
    float w
) {
    float _e4 = inverse_square(d2_3);
    float _e6 = slc_weight(rt2_1, d2_3);
    return ((cos_x * _e4) * _e6) * w;
}

float connection_cosine(
    metal::float3 x_2,
    metal::float3 y,
    metal::float3 n,
    metal::float3 ng,
    float r2_1
) {
    bool local_2 = {};
    bool local_3 = {};
    metal::float3 v_1 = x_2 - y;
    float d2_5 = metal::dot(v_1, v_1);
    bool _e7 = slc_keep(r2_1, d2_5);
    if (!(!(_e7))) {
        local_2 = !((d2_5 > 0.0));
    } else {
        local_2 = true;
    }
    bool _e16 = local_2;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_5 = v_1 / metal::float3(metal::sqrt(d2_5));
    float cos_x_1 = -(metal::dot(n, w_5));
    if (!((cos_x_1 <= 0.0))) {
        local_3 = metal::dot(ng, w_5) >= 0.0;
    } else {
        local_3 = true;
    }
    bool _e32 = local_3;
    if (_e32) {
        return 0.0;
    }
    return cos_x_1;
}

float spot_falloff(
    float cos_theta,
    float cos_outer,
    float cos_inner
) {
    if (cos_inner <= cos_outer) {
        return (cos_theta >= cos_outer) ? 1.0 : 0.0;
    }
    float t_1 = metal::saturate((cos_theta - cos_outer) / (cos_inner - cos_outer));
    return (t_1 * t_1) * (3.0 - (2.0 * t_1));
}

bool weighted_replace(
    float w_1,
    float w_sum,
    float u_1
) {
    return (u_1 * w_sum) < w_1;
}

float weighted_pick_weight(
    float w_sum_1,
    float w_2,
    uint k_1
) {
    float _e3 = to_f32_(k_1);
    return w_sum_1 / (_e3 * w_2);
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
    float x_3
) {
    return metal::sqrt(metal::max(x_3, 0.0));
}

float light_importance(
    metal::float3 center,
    float radius,
    float phi,
    metal::float3 axis,
    float cos_o,
    float cos_e,
    metal::float3 p,
    metal::float3 n_1
) {
    float imp = {};
    metal::float3 v_2 = p - center;
    float dist2_ = metal::dot(v_2, v_2);
    float r2_3 = radius * radius;
    float d2_6 = metal::max(metal::max(dist2_, r2_3), MIN_D2_);
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
    imp = (phi * _e46) / d2_6;
    if (metal::dot(n_1, n_1) > 0.0) {
        float cos_i = -(metal::dot(wi, n_1));
        float _e60 = safe_sqrt(1.0 - (cos_i * cos_i));
        float _e61 = imp;
        float _e62 = cos_sub_clamped(_e60, cos_i, _e39, cos_b_2);
        imp = _e61 * metal::max(_e62, 0.0);
    }
    float _e66 = imp;
    return metal::max(_e66, 0.0);
}

float candidate_weight(
    float importance,
    float rt2_2,
    float d2_4
) {
    float _e3 = slc_weight(rt2_2, d2_4);
    return importance * _e3;
}

float cone_weight(
    metal::float3 center_1,
    float radius_1,
    float phi_1,
    metal::float3 axis_1,
    float cos_o_1,
    float cos_e_1,
    float rt2_3,
    metal::float3 p_1,
    metal::float3 n_2
) {
    metal::float3 v_3 = p_1 - center_1;
    float _e10 = light_importance(center_1, radius_1, phi_1, axis_1, cos_o_1, cos_e_1, p_1, n_2);
    float _e14 = candidate_weight(_e10 * INV_PI, rt2_3, metal::dot(v_3, v_3));
    return _e14;
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
            float _e9 = spot_falloff(metal::dot(l.p1_, w_3), l.a, l.b);
            return l.intensity * _e9;
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

bool occluded(
    metal::float3 a_2,
    metal::float3 b_2
) {
    return false;
}

BshNode bsh_node(
    BshNodes nodes,
    uint i,
    device type_9 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshNode _e4 = bsh_nodes[i];
    return _e4;
}

uint bsh_count(
    BshNodes nodes_1,
    device type_9 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    return 1 + (_buffer_sizes.size7 - 0 - 32) / 32;
}

uint bsh_first(
    BshNodes nodes_2,
    device type_9 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e1 = bsh_count(nodes_2, bsh_nodes, _buffer_sizes);
    if (_e1 > 0u) {
        return 0u;
    }
    return BSH_NONE;
}

uint bsh_next_leaf(
    BshNodes nodes_3,
    uint start,
    metal::float3 x_4,
    device type_9 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_1 = {};
    i_1 = start;
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e4 = i_1;
        if (_e4 != BSH_NONE) {
        } else {
            break;
        }
        {
            uint _e7 = i_1;
            BshNode _e8 = bsh_node(nodes_3, _e7, bsh_nodes, _buffer_sizes);
            bool _e11 = sphere_contains_point(_e8.center, _e8.radius, x_4);
            if (_e11) {
                if (_e8.child == BSH_NONE) {
                    uint _e15 = i_1;
                    return _e15;
                }
                i_1 = _e8.child;
            } else {
                i_1 = _e8.next;
            }
        }
    }
    return BSH_NONE;
}

Connection connect(
    uint li,
    metal::float3 x_5,
    metal::float3 n_3,
    metal::float3 ng_1,
    float w_res,
    float u1_1,
    float u2_1,
    float eps,
    device type_8 const& lights,
    device type_4 const& rt2_4,
    device type_4 const& r2_2,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection c_1 = {};
    bool local_4 = {};
    c_1.e = metal::float3(0.0);
    GpuLight l_2 = lights[li];
    metal::float3 _e16 = light_point(l_2, u1_1, u2_1);
    c_1.y = _e16;
    metal::float3 _e19 = c_1.y;
    float _e22 = r2_2[li];
    float _e23 = connection_cosine(x_5, _e19, n_3, ng_1, _e22);
    c_1.cos_x = _e23;
    float _e25 = c_1.cos_x;
    if (!((_e25 <= 0.0))) {
        metal::float3 _e34 = c_1.y;
        bool _e35 = occluded(x_5 + (ng_1 * eps), _e34);
        local_4 = _e35;
    } else {
        local_4 = true;
    }
    bool _e37 = local_4;
    if (_e37) {
        Connection _e38 = c_1;
        return _e38;
    }
    metal::float3 _e40 = c_1.y;
    metal::float3 v_4 = x_5 - _e40;
    float d2_7 = metal::dot(v_4, v_4);
    metal::float3 _e47 = light_intensity(l_2, v_4 / metal::float3(metal::sqrt(d2_7)));
    float _e49 = c_1.cos_x;
    float _e52 = rt2_4[li];
    float _e53 = connection_factor(_e49, d2_7, _e52, w_res);
    c_1.e = _e47 * _e53;
    Connection _e55 = c_1;
    return _e55;
}

float light_weight(
    uint li_1,
    metal::float3 x_6,
    metal::float3 n_4,
    device type_4 const& rt2_4,
    device type_10 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_2 = light_cones[li_1];
    float _e14 = rt2_4[li_1];
    float _e15 = cone_weight(c_2.center, c_2.radius, c_2.phi, c_2.axis, c_2.cos_o, c_2.cos_e, _e14, x_6, n_4);
    return _e15;
}

WeightedPicks bsh_weighted_collect(
    metal::float3 x_7,
    metal::float3 n_5,
    uint seed_1,
    device type_4 const& rt2_4,
    device type_9 const& bsh_nodes,
    device type_10 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    WeightedPicks picks = {};
    uint h_1 = {};
    uint b_3 = {};
    uint s = {};
    picks.w_sum = 0.0;
    picks.n = 0u;
    h_1 = seed_1;
    uint _e11 = bsh_first(BSH, bsh_nodes, _buffer_sizes);
    uint _e12 = bsh_next_leaf(BSH, _e11, x_7, bsh_nodes, _buffer_sizes);
    b_3 = _e12;
    uint2 loop_bound_1 = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init) {
            uint _e55 = b_3;
            uint _e58 = bsh_nodes[_e55].next;
            uint _e59 = bsh_next_leaf(BSH, _e58, x_7, bsh_nodes, _buffer_sizes);
            b_3 = _e59;
        }
        loop_init = false;
        uint _e14 = b_3;
        if (_e14 != BSH_NONE) {
        } else {
            break;
        }
        {
            uint _e18 = picks.n;
            picks.n = _e18 + 1u;
            uint _e22 = b_3;
            uint li_3 = bsh_nodes[_e22].light;
            float _e26 = light_weight(li_3, x_7, n_5, rt2_4, light_cones, _buffer_sizes);
            if (_e26 > 0.0) {
                float _e30 = picks.w_sum;
                picks.w_sum = _e30 + _e26;
                s = 0u;
                uint2 loop_bound_2 = uint2(4294967295u);
                bool loop_init_1 = true;
                while(true) {
                    if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                    loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                    if (!loop_init_1) {
                        uint _e51 = s;
                        s = _e51 + 1u;
                    }
                    loop_init_1 = false;
                    uint _e34 = s;
                    if (_e34 < K) {
                    } else {
                        break;
                    }
                    {
                        uint _e37 = h_1;
                        uint _e38 = pcg_hash(_e37);
                        h_1 = _e38;
                        float _e40 = picks.w_sum;
                        uint _e41 = h_1;
                        float _e42 = xi_from_bits(_e41);
                        bool _e43 = weighted_replace(_e26, _e40, _e42);
                        if (_e43) {
                            uint _e45 = s;
                            picks.light.inner[_e45] = li_3;
                            uint _e48 = s;
                            picks.w.inner[_e48] = _e26;
                        }
                    }
                }
            }
        }
    }
    WeightedPicks _e60 = picks;
    return _e60;
}

metal::float4 unproject_pixel(
    metal::float4 c0_,
    metal::float4 c1_,
    metal::float4 c2_,
    metal::float4 c3_,
    float px,
    float py,
    float width,
    float height,
    float depth,
    float background
) {
    if (depth == background) {
        return metal::float4(0.0, 0.0, 0.0, 0.0);
    }
    float x_9 = (((px + 0.5) / width) * 2.0) - 1.0;
    float y_1 = 1.0 - (((py + 0.5) / height) * 2.0);
    metal::float4 p_2 = (((c0_ * x_9) + (c1_ * y_1)) + (c2_ * depth)) + c3_;
    if (metal::abs(p_2.w) > 0.0) {
        return metal::float4(p_2.x / p_2.w, p_2.y / p_2.w, p_2.z / p_2.w, 1.0);
    }
    return metal::float4(0.0, 0.0, 0.0, 0.0);
}

metal::float4 surface_at(
    metal::int2 texel,
    constant ViewParams& view,
    metal::texture2d<float, metal::access::sample> depth_tex
) {
    metal::float4 _e3 = depth_tex.read(metal::uint2(texel), 0);
    float d = _e3.x;
    metal::float4 _e7 = view.c0_;
    metal::float4 _e10 = view.c1_;
    metal::float4 _e13 = view.c2_;
    metal::float4 _e16 = view.c3_;
    uint _e23 = view.width;
    uint _e27 = view.height;
    float _e31 = view.background;
    metal::float4 _e32 = unproject_pixel(_e7, _e10, _e13, _e16, static_cast<float>(texel.x), static_cast<float>(texel.y), static_cast<float>(_e23), static_cast<float>(_e27), d, _e31);
    return _e32;
}

Shaded shade_pick(
    uint li_2,
    metal::float3 x_8,
    metal::float3 n_6,
    Material m_1,
    float w_4,
    float u1_2,
    float u2_2,
    device type_8 const& lights,
    device type_4 const& rt2_4,
    device type_4 const& r2_2,
    constant _mslBufferSizes& _buffer_sizes
) {
    Shaded s_1 = {};
    Connection _e9 = connect(li_2, x_8, n_6, n_6, w_4, u1_2, u2_2, 0.0, lights, rt2_4, r2_2, _buffer_sizes);
    s_1.e = _e9.e;
    s_1.diffuse = metal::float3(0.0);
    s_1.specular = metal::float3(0.0);
    Shaded _e18 = s_1;
    return _e18;
}

Shaded add(
    Shaded a_3,
    Shaded b_4
) {
    return Shaded {a_3.e + b_4.e, a_3.diffuse + b_4.diffuse, a_3.specular + b_4.specular};
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, constant ViewParams& view [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> depth_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::write> out_tex [[user(fake0)]]
, device type_8 const& lights [[user(fake0)]]
, device type_4 const& rt2_4 [[user(fake0)]]
, device type_4 const& r2_2 [[user(fake0)]]
, device type_9 const& bsh_nodes [[user(fake0)]]
, device type_10 const& light_cones [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    bool local = {};
    bool local_1 = {};
    Material m = {};
    uint h = {};
    Shaded t = Shaded {metal::float3(0.0), metal::float3(0.0), metal::float3(0.0)};
    uint k = 0u;
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
    metal::float4 _e21 = surface_at(texel_1, view, depth_tex);
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
    metal::float3 x_10 = _e21.xyz;
    metal::float3 n_7 = nn / metal::float3(metal::sqrt(len2_));
    uint _e48 = view.seed;
    uint _e52 = view.width;
    uint _e58 = view.frame;
    uint _e59 = point_stream(_e48, (gid.y * _e52) + gid.x, _e58);
    uint _e60 = pick_stream(_e59);
    h = _e60;
    WeightedPicks _e70 = bsh_weighted_collect(x_10, n_7, _e59, rt2_4, bsh_nodes, light_cones, _buffer_sizes);
    if (_e70.w_sum > 0.0) {
        uint2 loop_bound_3 = uint2(4294967295u);
        bool loop_init_2 = true;
        while(true) {
            if (metal::all(loop_bound_3 == uint2(0u))) { break; }
            loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
            if (!loop_init_2) {
                uint _e101 = k;
                k = _e101 + 1u;
            }
            loop_init_2 = false;
            uint _e76 = k;
            if (_e76 < K) {
            } else {
                break;
            }
            {
                uint _e79 = h;
                uint _e80 = pcg_hash(_e79);
                h = _e80;
                uint _e81 = h;
                float _e82 = xi_from_bits(_e81);
                uint _e83 = h;
                uint _e84 = pcg_hash(_e83);
                h = _e84;
                Shaded _e85 = t;
                uint _e87 = k;
                Material _e89 = m;
                uint _e92 = k;
                float _e95 = weighted_pick_weight(_e70.w_sum, _e70.w.inner[_e92], K);
                uint _e96 = h;
                float _e97 = xi_from_bits(_e96);
                Shaded _e98 = shade_pick(_e70.light.inner[_e87], x_10, n_7, _e89, _e95, _e82, _e97, lights, rt2_4, r2_2, _buffer_sizes);
                Shaded _e99 = add(_e85, _e98);
                t = _e99;
            }
        }
    }
    uint count = _e70.n;
    metal::float3 _e106 = t.e;
    out_tex.write(metal::float4(_e106, static_cast<float>(count)), metal::uint2(texel_1));
    return;
}
