// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size5;
    uint size6;
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
struct FrameParams {
    uint light_count;
    uint seed;
    uint frame;
    uint pad;
};
struct RefitParams {
    uint first;
    uint count;
    uint pad0_;
    uint pad1_;
};
struct VplParams {
    uint width;
    uint height;
    uint lights_per_subset;
    float min_d2_;
    float near_r2_;
    uint near_blocks;
    uint pad0_;
    uint pad1_;
};
struct GpuNearBox {
    metal::packed_float3 lo;
    float pad0_;
    metal::packed_float3 hi;
    float pad1_;
};
struct GpuVplRecord {
    metal::packed_float3 position;
    float pad0_;
    metal::packed_float3 normal;
    float pad1_;
    metal::packed_float3 flux;
    float pad2_;
};
struct PackParams {
    uint count;
    uint size;
    uint per_subset;
    uint mode;
    float exposure;
    float error_bound;
    float scale;
    uint slc;
    float fixed_r2_;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};
struct ImageParams {
    metal::packed_float3 eye;
    uint width;
    uint height;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};
struct GpuVertex {
    metal::packed_float3 position;
    uint material;
    metal::packed_float3 normal;
    uint pad0_;
    metal::packed_float3 geo_normal;
    uint pad1_;
};
struct GpuMaterial {
    metal::packed_float3 albedo;
    uint pad0_;
    metal::packed_float3 emission;
    uint pad1_;
};
struct MapParams {
    metal::float4 c0_;
    metal::float4 c1_;
    metal::float4 c2_;
    metal::float4 c3_;
    GpuLight light;
    metal::packed_float3 origin;
    uint mode;
    metal::packed_float3 axis;
    uint size;
    metal::packed_float3 right;
    float extent;
    metal::packed_float3 up;
    float texel;
};
struct ShadeParams {
    uint point_count;
    uint seed;
    uint frame;
    float eps;
};
typedef uint Table;
typedef float type_4[1];
struct BshNode {
    metal::packed_float3 center;
    float radius;
    uint child;
    uint next;
    uint light;
    uint pad;
};
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
typedef metal::float4 type_7[1];
typedef GpuMaterial type_8[1];
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
constant float DEPTH_NONE = 1000000000000000000000000000000.0;
constant float DEPTH_SIGMA = 0.05;
constant float COVER_WEIGHT = 0.1;
constant uint NEAR_BLOCK = 64u;
constant uint ROULETTE_DEPTH = 2u;

float at(
    Table tab,
    uint i,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e4 = slc_table[i];
    return _e4;
}

float to_f32_(
    uint u
) {
    return static_cast<float>(u);
}

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

uint to_u32_(
    float x
) {
    return naga_f2u32(x);
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
    uint x_1
) {
    uint _e2 = mul_lo_u32_(x_1, 747796405u);
    uint _e4 = add_wrap_u32_(_e2, 2891336453u);
    uint _e12 = mul_lo_u32_((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4, 277803737u);
    return (_e12 >> 22u) ^ _e12;
}

uint reverse_bits(
    uint x_2
) {
    uint v = {};
    v = ((x_2 >> 16u) & 65535u) | ((x_2 & 65535u) << 16u);
    uint _e11 = v;
    uint _e16 = v;
    v = ((_e11 >> 8u) & 16711935u) | ((_e16 & 16711935u) << 8u);
    uint _e22 = v;
    uint _e27 = v;
    v = ((_e22 >> 4u) & 252645135u) | ((_e27 & 252645135u) << 4u);
    uint _e33 = v;
    uint _e38 = v;
    v = ((_e33 >> 2u) & 858993459u) | ((_e38 & 858993459u) << 2u);
    uint _e44 = v;
    uint _e49 = v;
    v = ((_e44 >> 1u) & 1431655765u) | ((_e49 & 1431655765u) << 1u);
    uint _e55 = v;
    return _e55;
}

float xi_for(
    uint seed,
    uint frame,
    uint light
) {
    uint _e3 = pcg_hash(seed);
    uint _e4 = pcg_hash(_e3);
    uint _e6 = pcg_hash(_e4 ^ light);
    uint _e7 = reverse_bits(frame);
    uint _e8 = add_wrap_u32_(_e6, _e7);
    float _e9 = xi_from_bits(_e8);
    return _e9;
}

uint point_stream(
    uint seed_1,
    uint point,
    uint frame_1
) {
    uint _e3 = pcg_hash(frame_1);
    uint _e5 = pcg_hash(point ^ _e3);
    uint _e7 = pcg_hash(seed_1 ^ _e5);
    return _e7;
}

uint pick_stream(
    uint stream
) {
    uint _e3 = pcg_hash(stream ^ PICK_STREAM);
    return _e3;
}

uint path_stream(
    uint seed_2,
    uint pixel,
    uint pass_index
) {
    uint _e4 = add_wrap_u32_(pass_index, PICK_STREAM);
    uint _e5 = point_stream(seed_2, pixel, _e4);
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

float slc_weight(
    float rt2_1,
    float d2_1
) {
    if (d2_1 <= rt2_1) {
        return 1.0;
    }
    return d2_1 / rt2_1;
}

float random_range2_(
    float rt2_2,
    float xi
) {
    return rt2_2 / (1.0 - xi);
}

bool slc_keep(
    float r2_,
    float d2_2
) {
    return d2_2 < r2_;
}

bool clamp_keep(
    float range2_,
    float d2_3
) {
    return d2_3 < range2_;
}

float threshold_range2_(
    float intensity,
    float exposure,
    float error_bound
) {
    if (intensity <= 0.0) {
        return 0.0;
    }
    return ((exposure / error_bound) * intensity) / TWO_PI;
}

float intensity_measure(
    metal::float3 rgb,
    uint mode
) {
    if (mode == 1u) {
        return ((rgb.x + rgb.y) + rgb.z) / 3.0;
    }
    return metal::max(rgb.x, metal::max(rgb.y, rgb.z));
}

float cull_radius(
    float r2_1
) {
    return metal::sqrt(r2_1) * CULL_RADIUS_SCALE;
}

float windowed_falloff(
    float d2_4,
    float range2_1
) {
    float q_2 = d2_4 / range2_1;
    float w_9 = metal::saturate(1.0 - (q_2 * q_2));
    return (w_9 * w_9) / metal::max(d2_4, 0.0001);
}

bool sphere_contains_point(
    metal::float3 c,
    float r,
    metal::float3 x_3
) {
    metal::float3 v_4 = x_3 - c;
    return metal::dot(v_4, v_4) <= (r * r);
}

bool sphere_overlaps_sphere(
    metal::float3 c1_,
    float r1_,
    metal::float3 c2_,
    float r2_2
) {
    metal::float3 v_5 = c2_ - c1_;
    float r_3 = r1_ + r2_2;
    return metal::dot(v_5, v_5) <= (r_3 * r_3);
}

float sphere_pad(
    float r_1,
    metal::float3 c_1
) {
    return ((r_1 + metal::max(metal::abs(c_1.x), metal::max(metal::abs(c_1.y), metal::abs(c_1.z)))) * SPHERE_PAD) + SPHERE_PAD_ABS;
}

metal::float4 sphere_union(
    metal::float3 c1_1,
    float r1_1,
    metal::float3 c2_1,
    float r2_3
) {
    bool local_1 = {};
    metal::float3 v_6 = c2_1 - c1_1;
    float d_4 = metal::sqrt(metal::dot(v_6, v_6));
    float _e8 = sphere_pad(r1_1, c1_1);
    if (r1_1 >= ((d_4 + r2_3) + _e8)) {
        return metal::float4(c1_1.x, c1_1.y, c1_1.z, r1_1);
    }
    float _e16 = sphere_pad(r2_3, c2_1);
    if (r2_3 >= ((d_4 + r1_1) + _e16)) {
        return metal::float4(c2_1.x, c2_1.y, c2_1.z, r2_3);
    }
    if (!((d_4 >= SPHERE_HUGE))) {
        local_1 = (0.5 * ((d_4 + r1_1) + r2_3)) >= SPHERE_HUGE;
    } else {
        local_1 = true;
    }
    bool _e35 = local_1;
    if (_e35) {
        return metal::float4(c1_1.x, c1_1.y, c1_1.z, SPHERE_HUGE);
    }
    if (metal::abs(r1_1 - r2_3) >= d_4) {
        if (r1_1 >= r2_3) {
            float rn = metal::max(r1_1, d_4 + r2_3);
            float _e50 = sphere_pad(rn, c1_1);
            return metal::float4(c1_1.x, c1_1.y, c1_1.z, rn + _e50);
        }
        float rm = metal::max(r2_3, d_4 + r1_1);
        float _e58 = sphere_pad(rm, c2_1);
        return metal::float4(c2_1.x, c2_1.y, c2_1.z, rm + _e58);
    }
    float r0_ = 0.5 * ((d_4 + r1_1) + r2_3);
    metal::float3 c_9 = c1_1 + (v_6 * ((r0_ - r1_1) / d_4));
    metal::float3 e1_ = c_9 - c1_1;
    metal::float3 e2_ = c_9 - c2_1;
    float r_4 = metal::max(r0_, metal::max(metal::sqrt(metal::dot(e1_, e1_)) + r1_1, metal::sqrt(metal::dot(e2_, e2_)) + r2_3));
    float _e82 = sphere_pad(r_4, c_9);
    return metal::float4(c_9.x, c_9.y, c_9.z, r_4 + _e82);
}

bool sphere_overlaps_aabb(
    metal::float3 c_2,
    float r_2,
    metal::float3 bmin,
    metal::float3 bmax
) {
    metal::float3 q_3 = metal::clamp(c_2, bmin, bmax);
    metal::float3 v_7 = q_3 - c_2;
    return metal::dot(v_7, v_7) <= (r_2 * r_2);
}

float vpl_rt2_(
    metal::float3 flux,
    float exposure_1,
    float error_bound_1,
    uint mode_1
) {
    float _e6 = intensity_measure(flux * INV_PI, mode_1);
    float _e7 = threshold_range2_(_e6, exposure_1, error_bound_1);
    return _e7;
}

float range_radius(
    float extent,
    float r2_4
) {
    return extent + metal::sqrt(r2_4);
}

float inverse_square(
    float d2_5
) {
    return 1.0 / metal::max(d2_5, MIN_D2_);
}

float connection_factor(
    float cos_x,
    float d2_6,
    float rt2_3,
    float w
) {
    float _e4 = inverse_square(d2_6);
    float _e6 = slc_weight(rt2_3, d2_6);
    return ((cos_x * _e4) * _e6) * w;
}

float connection_cosine(
    metal::float3 x_4,
    metal::float3 y,
    metal::float3 n,
    metal::float3 ng,
    float r2_5
) {
    bool local_2 = {};
    bool local_3 = {};
    metal::float3 v_8 = x_4 - y;
    float d2_16 = metal::dot(v_8, v_8);
    bool _e7 = slc_keep(r2_5, d2_16);
    if (!(!(_e7))) {
        local_2 = !((d2_16 > 0.0));
    } else {
        local_2 = true;
    }
    bool _e16 = local_2;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_10 = v_8 / metal::float3(metal::sqrt(d2_16));
    float cos_x_1 = -(metal::dot(n, w_10));
    if (!((cos_x_1 <= 0.0))) {
        local_3 = metal::dot(ng, w_10) >= 0.0;
    } else {
        local_3 = true;
    }
    bool _e32 = local_3;
    if (_e32) {
        return 0.0;
    }
    return cos_x_1;
}

float vpl_lobe(
    metal::float3 n_1,
    metal::float3 w_1
) {
    return metal::max(metal::dot(n_1, w_1), 0.0) * INV_PI;
}

float vpl_transfer(
    metal::float3 n_l,
    metal::float3 n_x,
    metal::float3 v_1,
    float min_d2_
) {
    float m = metal::max(metal::dot(v_1, v_1), min_d2_);
    return ((metal::max(metal::dot(n_l, v_1), 0.0) * metal::max(-(metal::dot(n_x, v_1)), 0.0)) * INV_PI) / (m * m);
}

float spot_falloff(
    float cos_theta,
    float cos_outer,
    float cos_inner
) {
    if (cos_inner <= cos_outer) {
        return (cos_theta >= cos_outer) ? 1.0 : 0.0;
    }
    float t_2 = metal::saturate((cos_theta - cos_outer) / (cos_inner - cos_outer));
    return (t_2 * t_2) * (3.0 - (2.0 * t_2));
}

float triangle_lobe(
    metal::float3 n_2,
    float area,
    metal::float3 w_2
) {
    return area * metal::max(metal::dot(n_2, w_2), 0.0);
}

metal::float3 triangle_sample(
    metal::float3 a_2,
    metal::float3 b_2,
    metal::float3 c_3,
    float u1_,
    float u2_
) {
    float su = metal::sqrt(u1_);
    float b0_ = 1.0 - su;
    float b1_ = u2_ * su;
    return ((a_2 * b0_) + (b_2 * b1_)) + (c_3 * ((1.0 - b0_) - b1_));
}

float area_to_solid_angle_pdf(
    float pdf_area,
    float d2_7,
    float cos_light
) {
    float c_10 = metal::abs(cos_light);
    if (c_10 <= 0.0) {
        return 0.0;
    }
    return (pdf_area * d2_7) / c_10;
}

float atan_portable(
    float x_5
) {
    float base = 0.0;
    float t = {};
    float a_9 = metal::abs(x_5);
    t = a_9;
    if (a_9 > 2.4142137) {
        base = 1.5707964;
        t = -1.0 / a_9;
    } else {
        if (a_9 > 0.41421357) {
            base = 0.7853982;
            t = (a_9 - 1.0) / (a_9 + 1.0);
        }
    }
    float _e18 = t;
    float _e19 = t;
    float z_3 = _e18 * _e19;
    float _e21 = base;
    float _e33 = t;
    float _e35 = t;
    float r_5 = _e21 + (((((((((0.080537446 * z_3) - 0.13877685) * z_3) + 0.19977711) * z_3) - 0.3333295) * z_3) * _e33) + _e35);
    return (x_5 < 0.0) ? -(r_5) : r_5;
}

float atan2_portable(
    float y_1,
    float x_6
) {
    if (x_6 == 0.0) {
        if (y_1 > 0.0) {
            return 1.5707964;
        }
        if (y_1 < 0.0) {
            return -1.5707964;
        }
        return 0.0;
    }
    float _e12 = atan_portable(y_1 / x_6);
    if (x_6 > 0.0) {
        return _e12;
    }
    if (y_1 >= 0.0) {
        return _e12 + 3.1415927;
    }
    return _e12 - 3.1415927;
}

float ies_fold_c(
    float c_4,
    float h_first,
    float h_last
) {
    float a_3 = {};
    a_3 = c_4 - (360.0 * metal::floor(c_4 / 360.0));
    if (h_last <= 0.0) {
        return 0.0;
    }
    if (h_last <= 90.0) {
        float _e15 = a_3;
        if (_e15 > 180.0) {
            float _e18 = a_3;
            a_3 = 360.0 - _e18;
        }
        float _e21 = a_3;
        if (_e21 > 90.0) {
            float _e24 = a_3;
            a_3 = 180.0 - _e24;
        }
        float _e27 = a_3;
        return _e27;
    }
    if (h_first >= 90.0) {
        float _e30 = a_3;
        if (_e30 < 90.0) {
            float _e33 = a_3;
            a_3 = 180.0 - _e33;
        } else {
            float _e36 = a_3;
            if (_e36 > 270.0) {
                float _e39 = a_3;
                a_3 = 540.0 - _e39;
            }
        }
        float _e42 = a_3;
        return _e42;
    }
    if (h_last <= 180.0) {
        float _e45 = a_3;
        if (_e45 > 180.0) {
            float _e48 = a_3;
            a_3 = 360.0 - _e48;
        }
        float _e51 = a_3;
        return _e51;
    }
    float _e52 = a_3;
    return _e52;
}

uint ies_segment(
    Table tab_1,
    uint start,
    uint n_3,
    float x_7,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint lo = 0u;
    uint hi = {};
    if (n_3 < 2u) {
        return 0u;
    }
    hi = n_3 - 1u;
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e12 = hi;
        uint _e13 = lo;
        if ((_e12 - _e13) > 1u) {
        } else {
            break;
        }
        {
            uint _e17 = lo;
            uint _e18 = hi;
            uint mid = (_e17 + _e18) >> 1u;
            float _e23 = at(tab_1, start + mid, slc_table, _buffer_sizes);
            if (_e23 <= x_7) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
    uint _e25 = lo;
    return _e25;
}

float ies_lerp_t(
    float a0_,
    float a1_,
    float x_8
) {
    if (a1_ <= a0_) {
        return 0.0;
    }
    return metal::saturate((x_8 - a0_) / (a1_ - a0_));
}

float ies_candela(
    Table tab_2,
    uint base_1,
    float gamma,
    float c_5,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_4 = {};
    float _e4 = at(tab_2, base_1, slc_table, _buffer_sizes);
    uint _e5 = to_u32_(_e4);
    float _e8 = at(tab_2, base_1 + 1u, slc_table, _buffer_sizes);
    uint _e9 = to_u32_(_e8);
    uint v0_ = base_1 + 2u;
    uint h0_ = v0_ + _e5;
    uint c0_1 = h0_ + _e9;
    float _e14 = at(tab_2, v0_, slc_table, _buffer_sizes);
    if (!((gamma < _e14))) {
        float _e22 = at(tab_2, (v0_ + _e5) - 1u, slc_table, _buffer_sizes);
        local_4 = gamma > _e22;
    } else {
        local_4 = true;
    }
    bool _e25 = local_4;
    if (_e25) {
        return 0.0;
    }
    float _e27 = at(tab_2, h0_, slc_table, _buffer_sizes);
    float _e31 = at(tab_2, (h0_ + _e9) - 1u, slc_table, _buffer_sizes);
    float _e32 = ies_fold_c(c_5, _e27, _e31);
    uint _e33 = ies_segment(tab_2, v0_, _e5, gamma, slc_table, _buffer_sizes);
    uint _e34 = ies_segment(tab_2, h0_, _e9, _e32, slc_table, _buffer_sizes);
    uint iv1_ = metal::min(_e33 + 1u, _e5 - 1u);
    uint ih1_ = metal::min(_e34 + 1u, _e9 - 1u);
    float _e46 = at(tab_2, v0_ + _e33, slc_table, _buffer_sizes);
    float _e48 = at(tab_2, v0_ + iv1_, slc_table, _buffer_sizes);
    float _e49 = ies_lerp_t(_e46, _e48, gamma);
    float _e51 = at(tab_2, h0_ + _e34, slc_table, _buffer_sizes);
    float _e53 = at(tab_2, h0_ + ih1_, slc_table, _buffer_sizes);
    float _e54 = ies_lerp_t(_e51, _e53, _e32);
    float _e58 = at(tab_2, (c0_1 + (_e34 * _e5)) + _e33, slc_table, _buffer_sizes);
    float _e65 = at(tab_2, (c0_1 + (_e34 * _e5)) + iv1_, slc_table, _buffer_sizes);
    float a_10 = (_e58 * (1.0 - _e49)) + (_e65 * _e49);
    float _e71 = at(tab_2, (c0_1 + (ih1_ * _e5)) + _e33, slc_table, _buffer_sizes);
    float _e78 = at(tab_2, (c0_1 + (ih1_ * _e5)) + iv1_, slc_table, _buffer_sizes);
    float b_7 = (_e71 * (1.0 - _e49)) + (_e78 * _e49);
    return (a_10 * (1.0 - _e54)) + (b_7 * _e54);
}

float ies_candela_dir(
    Table tab_3,
    uint base_2,
    float wn,
    float wr,
    float ws,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e9 = atan2_portable(metal::sqrt((wr * wr) + (ws * ws)), wn);
    float gamma_1 = ((_e9) * 57.295779513082322865);
    bool on_axis = (metal::abs(wr) + metal::abs(ws)) <= 0.0;
    float _e16 = atan2_portable(ws, wr);
    float c_11 = on_axis ? 0.0 : ((_e16) * 57.295779513082322865);
    float _e20 = ies_candela(tab_3, base_2, gamma_1, c_11, slc_table, _buffer_sizes);
    return _e20;
}

float ies_light_candela(
    Table tab_4,
    uint base_3,
    metal::float3 nadir,
    metal::float3 reference,
    metal::float3 w_3,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 side = metal::cross(reference, nadir);
    float _e9 = ies_candela_dir(tab_4, base_3, metal::dot(w_3, nadir), metal::dot(w_3, reference), metal::dot(w_3, side), slc_table, _buffer_sizes);
    return _e9;
}

uint mul_hi_u32_(
    uint a_4,
    uint b_3
) {
    uint a_lo = a_4 & 65535u;
    uint a_hi = a_4 >> 16u;
    uint b_lo = b_3 & 65535u;
    uint b_hi = b_3 >> 16u;
    uint ll = a_lo * b_lo;
    uint lh = a_lo * b_hi;
    uint hl = a_hi * b_lo;
    uint hh = a_hi * b_hi;
    uint mid_1 = ((ll >> 16u) + (lh & 65535u)) + (hl & 65535u);
    return ((hh + (lh >> 16u)) + (hl >> 16u)) + (mid_1 >> 16u);
}

uint uniform_index(
    uint n_4,
    uint hi_1,
    uint lo_1
) {
    uint _e3 = mul_lo_u32_(hi_1, n_4);
    uint _e4 = mul_hi_u32_(hi_1, n_4);
    uint _e5 = mul_hi_u32_(lo_1, n_4);
    if (_e3 > (4294967295u - _e5)) {
        return _e4 + 1u;
    }
    return _e4;
}

uint reservoir_slot(
    uint n_5,
    uint k,
    uint hi_2,
    uint lo_2
) {
    if (n_5 <= k) {
        return n_5 - 1u;
    }
    uint _e7 = uniform_index(n_5, hi_2, lo_2);
    if (_e7 < k) {
        return _e7;
    }
    return k;
}

bool reservoir_takes(
    uint n_6
) {
    return n_6 < RESERVOIR_FULL;
}

float reservoir_weight(
    uint n_7,
    uint k_1
) {
    float _e2 = to_f32_(n_7);
    float _e3 = to_f32_(k_1);
    return metal::max(_e2 / _e3, 1.0);
}

bool weighted_replace(
    float w_4,
    float w_sum,
    float u_1
) {
    return (u_1 * w_sum) < w_4;
}

float weighted_pick_weight(
    float w_sum_1,
    float w_5,
    uint k_2
) {
    float _e3 = to_f32_(k_2);
    return w_sum_1 / (_e3 * w_5);
}

float reservoir_select_pdf(
    uint seen,
    bool in_range,
    uint k_3
) {
    uint others = {};
    bool local_5 = {};
    others = seen;
    if (in_range) {
        local_5 = seen > 0u;
    } else {
        local_5 = false;
    }
    bool _e9 = local_5;
    if (_e9) {
        others = seen - 1u;
    }
    uint _e12 = others;
    float _e15 = reservoir_weight(_e12 + 1u, k_3);
    return 1.0 / _e15;
}

uint alias_choice(
    uint column,
    uint other,
    float keep,
    float u_2
) {
    return (u_2 < keep) ? column : other;
}

uint uniform_light(
    float u_3,
    uint n_8
) {
    float _e2 = to_f32_(n_8);
    uint _e4 = to_u32_(u_3 * _e2);
    return metal::min(_e4, n_8 - 1u);
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
    float x_9
) {
    return metal::sqrt(metal::max(x_9, 0.0));
}

float light_importance(
    metal::float3 center,
    float radius,
    float phi,
    metal::float3 axis,
    float cos_o,
    float cos_e,
    metal::float3 p,
    metal::float3 n_9
) {
    float imp = {};
    metal::float3 v_9 = p - center;
    float dist2_ = metal::dot(v_9, v_9);
    float r2_10 = radius * radius;
    float d2_17 = metal::max(metal::max(dist2_, r2_10), MIN_D2_);
    metal::float3 wi = (dist2_ > 0.0) ? (v_9 / metal::float3(metal::sqrt(dist2_))) : metal::float3(0.0, 0.0, 0.0);
    float cos_w = metal::dot(axis, wi);
    float _e28 = safe_sqrt(1.0 - (cos_w * cos_w));
    float _e32 = safe_sqrt(1.0 - (r2_10 / dist2_));
    float cos_b_2 = (dist2_ <= r2_10) ? -1.0 : _e32;
    float _e39 = safe_sqrt(1.0 - (cos_b_2 * cos_b_2));
    float _e43 = safe_sqrt(1.0 - (cos_o * cos_o));
    float _e44 = cos_sub_clamped(_e28, cos_w, _e43, cos_o);
    float _e45 = sin_sub_clamped(_e28, cos_w, _e43, cos_o);
    float _e46 = cos_sub_clamped(_e45, _e44, _e39, cos_b_2);
    if (_e46 <= cos_e) {
        return 0.0;
    }
    imp = (phi * _e46) / d2_17;
    if (metal::dot(n_9, n_9) > 0.0) {
        float cos_i = -(metal::dot(wi, n_9));
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
    float rt2_4,
    float d2_8
) {
    float _e3 = slc_weight(rt2_4, d2_8);
    return importance * _e3;
}

float cone_weight(
    metal::float3 center_1,
    float radius_1,
    float phi_1,
    metal::float3 axis_1,
    float cos_o_1,
    float cos_e_1,
    float rt2_5,
    metal::float3 p_1,
    metal::float3 n_10
) {
    metal::float3 v_10 = p_1 - center_1;
    float _e10 = light_importance(center_1, radius_1, phi_1, axis_1, cos_o_1, cos_e_1, p_1, n_10);
    float _e14 = candidate_weight(_e10 * INV_PI, rt2_5, metal::dot(v_10, v_10));
    return _e14;
}

float weighted_select_pdf(
    float w_6,
    float w_sum_2,
    bool in_range_1,
    uint k_4
) {
    if (w_6 <= 0.0) {
        return 0.0;
    }
    float total = in_range_1 ? w_sum_2 : (w_sum_2 + w_6);
    float _e9 = to_f32_(k_4);
    return (_e9 * w_6) / total;
}

float bvh_first_prob(
    float c0_,
    float c1_2
) {
    float s = c0_ + c1_2;
    if (s > 0.0) {
        return c0_ / s;
    }
    return -1.0;
}

float bvh_remap_u(
    float u_4,
    float p0_,
    bool first
) {
    if (first) {
        return metal::min(u_4 / p0_, ONE_MINUS_EPSILON);
    }
    return metal::clamp((u_4 - p0_) / (1.0 - p0_), 0.0, ONE_MINUS_EPSILON);
}

float surface_offset(
    float diag
) {
    return 0.00001 * diag;
}

float ray_t_min(
    float diag_1
) {
    return 0.000001 * diag_1;
}

float shadow_margin(
    float len
) {
    return 0.0001 * len;
}

float ray_inverse(
    float x_10
) {
    return 1.0 / ((metal::abs(x_10) < 0.000000000000000000000000000001) ? 0.000000000000000000000000000001 : x_10);
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

metal::float3 triangle_normal(
    metal::float3 a_5,
    metal::float3 b_4,
    metal::float3 c_6
) {
    bool local_6 = {};
    metal::float3 n_17 = metal::cross(b_4 - a_5, c_6 - a_5);
    float l2_ = metal::dot(n_17, n_17);
    if (!(!((l2_ > 0.0)))) {
        local_6 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_6 = true;
    }
    bool _e17 = local_6;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_17 / metal::float3(metal::sqrt(l2_));
}

metal::float3 face_against(
    metal::float3 n_11,
    metal::float3 dir
) {
    return (metal::dot(n_11, dir) > 0.0) ? -(n_11) : n_11;
}

metal::float3 barycentric(
    metal::float3 p_2,
    metal::float3 a_6,
    metal::float3 b_5,
    metal::float3 c_7
) {
    metal::float3 e1_1 = b_5 - a_6;
    metal::float3 e2_1 = c_7 - a_6;
    metal::float3 q_4 = p_2 - a_6;
    float d11_ = metal::dot(e1_1, e1_1);
    float d12_ = metal::dot(e1_1, e2_1);
    float d22_ = metal::dot(e2_1, e2_1);
    float den = (d11_ * d22_) - (d12_ * d12_);
    if (!((metal::abs(den) > 0.0))) {
        return metal::float3(1.0, 0.0, 0.0);
    }
    float w1_ = ((d22_ * metal::dot(q_4, e1_1)) - (d12_ * metal::dot(q_4, e2_1))) / den;
    float w2_ = ((d11_ * metal::dot(q_4, e2_1)) - (d12_ * metal::dot(q_4, e1_1))) / den;
    return metal::float3((1.0 - w1_) - w2_, w1_, w2_);
}

metal::float3 shading_normal(
    metal::float3 n0_,
    metal::float3 n1_,
    metal::float3 n2_,
    metal::float3 w_7,
    metal::float3 facing
) {
    bool local_7 = {};
    metal::float3 s_1 = ((n0_ * w_7.x) + (n1_ * w_7.y)) + (n2_ * w_7.z);
    float l2_1 = metal::dot(s_1, s_1);
    if (!(!((l2_1 > 0.000000000001)))) {
        local_7 = !((l2_1 < 300000000000000000000000000000000000000.0));
    } else {
        local_7 = true;
    }
    bool _e24 = local_7;
    if (_e24) {
        return facing;
    }
    metal::float3 n_18 = s_1 / metal::float3(metal::sqrt(l2_1));
    return (metal::dot(n_18, facing) < 0.0) ? -(n_18) : n_18;
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_1,
    metal::float3 a_7,
    metal::float3 b_6,
    metal::float3 c_8,
    float t_min,
    float t_max_1
) {
    bool local_8 = {};
    bool local_9 = {};
    bool local_10 = {};
    metal::float3 e1_2 = b_6 - a_7;
    metal::float3 e2_2 = c_8 - a_7;
    metal::float3 p_3 = metal::cross(d_1, e2_2);
    float det = metal::dot(e1_2, p_3);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv = 1.0 / det;
    metal::float3 s_2 = o_1 - a_7;
    float u_6 = metal::dot(s_2, p_3) * inv;
    if (!((u_6 < 0.0))) {
        local_8 = u_6 > 1.0;
    } else {
        local_8 = true;
    }
    bool _e28 = local_8;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q_5 = metal::cross(s_2, e1_2);
    float v_11 = metal::dot(d_1, q_5) * inv;
    if (!((v_11 < 0.0))) {
        local_9 = (u_6 + v_11) > 1.0;
    } else {
        local_9 = true;
    }
    bool _e42 = local_9;
    if (_e42) {
        return -1.0;
    }
    float t_3 = metal::dot(e2_2, q_5) * inv;
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

float mis_balance(
    float pdf_a,
    float pdf_b
) {
    float s_3 = pdf_a + pdf_b;
    if (s_3 <= 0.0) {
        return 0.0;
    }
    return pdf_a / s_3;
}

float mis_power(
    float pdf_a_1,
    float pdf_b_1
) {
    float a2_ = pdf_a_1 * pdf_a_1;
    float s_4 = a2_ + (pdf_b_1 * pdf_b_1);
    if (s_4 <= 0.0) {
        return 0.0;
    }
    return a2_ / s_4;
}

float light_strategy_pdf(
    float select,
    float rt2_6,
    float d2_9,
    float area_1,
    float cos_y
) {
    bool local_11 = {};
    bool local_12 = {};
    if (!((d2_9 <= 0.0))) {
        local_11 = area_1 <= 0.0;
    } else {
        local_11 = true;
    }
    bool _e13 = local_11;
    if (!(_e13)) {
        local_12 = cos_y <= 0.0;
    } else {
        local_12 = true;
    }
    bool _e20 = local_12;
    if (_e20) {
        return 0.0;
    }
    float _e22 = rr_probability(rt2_6, d2_9);
    float _e26 = area_to_solid_angle_pdf(1.0 / area_1, d2_9, cos_y);
    return (select * _e22) * _e26;
}

metal::float3 lambert_brdf(
    metal::float3 rho
) {
    return rho * INV_PI;
}

float cosine_pdf(
    float cos_theta_1
) {
    return metal::max(cos_theta_1, 0.0) * INV_PI;
}

metal::float3 cosine_direction(
    metal::float3 n_12,
    float u1_1,
    float u2_1
) {
    float s_5 = (n_12.z >= 0.0) ? 1.0 : -1.0;
    float a_11 = -1.0 / (s_5 + n_12.z);
    float b_8 = (n_12.x * n_12.y) * a_11;
    metal::float3 t_4 = metal::float3(1.0 + (((s_5 * n_12.x) * n_12.x) * a_11), s_5 * b_8, -(s_5) * n_12.x);
    metal::float3 bt = metal::float3(b_8, s_5 + ((n_12.y * n_12.y) * a_11), -(n_12.y));
    float r_6 = metal::sqrt(u1_1);
    float phi_2 = 6.2831855 * u2_1;
    return metal::normalize(((t_4 * (r_6 * metal::cos(phi_2))) + (bt * (r_6 * metal::sin(phi_2)))) + (n_12 * metal::sqrt(metal::max(1.0 - u1_1, 0.0))));
}

float inv_sigma_z(
    float z
) {
    return 1.0 / (DEPTH_SIGMA * z);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

uint window_start(
    uint x_11,
    uint size
) {
    uint half_ = naga_div(size, 2u);
    return metal::max(x_11, half_) - half_;
}

uint window_end(
    uint x_12,
    uint size_1,
    uint extent_1
) {
    return metal::min((x_12 + size_1) - naga_div(size_1, 2u), extent_1);
}

uint wide_window(
    uint period
) {
    return 2u * period;
}

bool misses_subset(
    uint covered,
    uint period_1
) {
    return covered < (period_1 * period_1);
}

metal::float3 filtered_irradiance(
    metal::float3 e,
    metal::float3 sum,
    float weight
) {
    if (weight > 0.0) {
        return sum / metal::float3(weight);
    }
    return e;
}

float bilateral_weight(
    metal::float3 n_13,
    metal::float3 nj,
    float z_1,
    float zj,
    float inv_sz
) {
    float dn = metal::max(metal::dot(n_13, nj), 0.0);
    float dn2_ = dn * dn;
    float dn4_ = dn2_ * dn2_;
    float dn8_ = dn4_ * dn4_;
    float d_5 = (zj - z_1) * inv_sz;
    float t_5 = metal::max(1.0 - (d_5 * d_5), 0.0);
    return ((dn8_ * dn8_) * t_5) * t_5;
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint interleave_subset(
    uint x_13,
    uint y_2,
    uint period_2
) {
    return (naga_mod(y_2, period_2) * period_2) + naga_mod(x_13, period_2);
}

uint interleave_slot(
    uint tx,
    uint ty,
    uint size_2,
    uint period_3
) {
    uint side_1 = naga_div(size_2, period_3);
    uint _e5 = interleave_subset(tx, ty, period_3);
    return (((_e5 * side_1) * side_1) + (naga_div(ty, period_3) * side_1)) + naga_div(tx, period_3);
}

uint interleave_slot_linear(
    uint i_1,
    uint per_subset,
    uint period_4
) {
    uint subsets = period_4 * period_4;
    return (naga_mod(i_1, subsets) * per_subset) + naga_div(i_1, subsets);
}

float interleave_flux_scale(
    uint period_5
) {
    float _e2 = to_f32_(period_5 * period_5);
    return _e2;
}

uint near_block_index(
    uint tx_1,
    uint ty_1,
    uint size_3
) {
    uint side_2 = naga_div(size_3, 8u);
    return ((((naga_div(ty_1, 8u) * side_2) + naga_div(tx_1, 8u)) * NEAR_BLOCK) + (naga_mod(ty_1, 8u) * 8u)) + naga_mod(tx_1, 8u);
}

uint near_block_tx(
    uint q,
    uint size_4
) {
    return (naga_mod(naga_div(q, NEAR_BLOCK), naga_div(size_4, 8u)) * 8u) + naga_mod(q, 8u);
}

uint near_block_ty(
    uint q_1,
    uint size_5
) {
    return (naga_div(naga_div(q_1, NEAR_BLOCK), naga_div(size_5, 8u)) * 8u) + naga_div(naga_mod(q_1, NEAR_BLOCK), 8u);
}

float vpl_near_weight(
    float d2_10,
    float near_r2_
) {
    if (near_r2_ <= 0.0) {
        return 0.0;
    }
    float t_6 = metal::clamp((near_r2_ - d2_10) / (0.75 * near_r2_), 0.0, 1.0);
    return (t_6 * t_6) * (3.0 - (2.0 * t_6));
}

float vpl_far_weight(
    float d2_11,
    float near_r2_1
) {
    float _e2 = vpl_near_weight(d2_11, near_r2_1);
    return 1.0 - _e2;
}

float vpl_far_slc_share(
    float rt2_7,
    float r2_6,
    float d2_12,
    float near_r2_2
) {
    float _e4 = vpl_far_weight(d2_12, near_r2_2);
    float _e5 = slc_weight(rt2_7, d2_12);
    bool _e7 = slc_keep(r2_6, d2_12);
    return (_e7 & (_e4 > 0.0)) ? (_e4 * _e5) : 0.0;
}

float vpl_far_fixed_share(
    float range2_2,
    float d2_13,
    float near_r2_3
) {
    float _e3 = vpl_far_weight(d2_13, near_r2_3);
    bool _e4 = clamp_keep(range2_2, d2_13);
    return (_e4 & (_e3 > 0.0)) ? _e3 : 0.0;
}

float vpl_near_range2_(
    float r2_7,
    uint period_6
) {
    float _e2 = interleave_flux_scale(period_6);
    return r2_7 / _e2;
}

float vpl_near_cull_range2_(
    float r2_8,
    float near_r2_4
) {
    return metal::min(r2_8, near_r2_4);
}

float vpl_near_slc_share(
    float rt2_8,
    float r2_9,
    float d2_14,
    float near_r2_5
) {
    float _e4 = vpl_near_weight(d2_14, near_r2_5);
    float _e5 = slc_weight(rt2_8, d2_14);
    bool _e7 = slc_keep(r2_9, d2_14);
    return (_e7 & (_e4 > 0.0)) ? (_e4 * _e5) : 0.0;
}

float vpl_near_fixed_share(
    float range2_3,
    float d2_15,
    float near_r2_6
) {
    float _e3 = vpl_near_weight(d2_15, near_r2_6);
    bool _e4 = clamp_keep(range2_3, d2_15);
    return (_e4 & (_e3 > 0.0)) ? _e3 : 0.0;
}

metal::float3 camera_dir(
    metal::float3 forward,
    metal::float3 right,
    metal::float3 up,
    float px,
    float py,
    float w_8,
    float h
) {
    float sx = ((2.0 * px) / w_8) - 1.0;
    float sy = 1.0 - ((2.0 * py) / h);
    return metal::normalize((forward + (right * sx)) + (up * sy));
}

float jittered_pixel(
    uint coord,
    float u_5
) {
    float _e2 = to_f32_(coord);
    return _e2 + u_5;
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
    metal::float3 n_14,
    metal::float3 ng_1
) {
    bool local_13 = {};
    if (metal::dot(nd, n_14) > 0.0) {
        local_13 = metal::dot(nd, ng_1) > 0.0;
    } else {
        local_13 = false;
    }
    bool _e12 = local_13;
    return _e12;
}

bool finite3_(
    metal::float3 v_2
) {
    bool local_14 = {};
    bool local_15 = {};
    if (metal::abs(v_2.x) <= F32_MAX) {
        local_14 = metal::abs(v_2.y) <= F32_MAX;
    } else {
        local_14 = false;
    }
    bool _e12 = local_14;
    if (_e12) {
        local_15 = metal::abs(v_2.z) <= F32_MAX;
    } else {
        local_15 = false;
    }
    bool _e20 = local_15;
    return _e20;
}

float path_survival(
    metal::float3 beta
) {
    return metal::clamp(metal::max(metal::max(beta.x, beta.y), beta.z), 0.05, 0.95);
}

float light_map_coord(
    uint t_1,
    uint size_6
) {
    float _e2 = to_f32_(t_1);
    float _e7 = to_f32_(size_6);
    return ((2.0 * (_e2 + 0.5)) / _e7) - 1.0;
}

uint light_map_texel(
    float a_8,
    uint size_7
) {
    float _e6 = to_f32_(size_7);
    float _e9 = to_f32_(size_7);
    uint _e14 = to_u32_(metal::clamp(metal::floor(((a_8 + 1.0) * 0.5) * _e6), 0.0, _e9 - 1.0));
    return _e14;
}

float light_map_coord_at(
    metal::float3 rel,
    metal::float3 dir_2,
    metal::float3 axis_2,
    float extent_2,
    bool perspective
) {
    return metal::dot(rel, dir_2) / ((perspective ? metal::dot(rel, axis_2) : 1.0) * extent_2);
}

float display_encode(
    float x_14
) {
    float v_12 = metal::max(x_14, 0.0);
    float t_7 = (2.0 * v_12) / (1.0 + (2.0 * v_12));
    return (t_7 <= 0.0031308) ? (12.92 * t_7) : ((1.055 * metal::pow(t_7, 0.41666666)) - 0.055);
}

float light_map_depth(
    metal::float3 rel_1,
    metal::float3 axis_3,
    bool perspective_1
) {
    return perspective_1 ? metal::sqrt(metal::dot(rel_1, rel_1)) : metal::dot(rel_1, axis_3);
}

float rsm_texel_solid_angle(
    float texel_area,
    float cos_axis
) {
    return ((texel_area * cos_axis) * cos_axis) * cos_axis;
}

metal::float3 point_irradiance(
    metal::float3 intensity_1,
    metal::float3 n_15,
    metal::float3 v_3
) {
    float d2_18 = metal::dot(v_3, v_3);
    float cos_x_2 = metal::dot(n_15, v_3) / metal::sqrt(metal::max(d2_18, MIN_D2_));
    float _e11 = inverse_square(d2_18);
    return intensity_1 * (metal::max(cos_x_2, 0.0) * _e11);
}

metal::float3 directional_irradiance(
    metal::float3 e_1,
    metal::float3 n_16,
    metal::float3 to_light
) {
    return e_1 * metal::max(metal::dot(n_16, to_light), 0.0);
}

float perspective_texel_width(
    float extent_3,
    float d_2,
    float z_2,
    float size_8
) {
    return (((2.0 * extent_3) * d_2) * d_2) / (size_8 * z_2);
}

float ortho_texel_width(
    float extent_4,
    float size_9
) {
    return (2.0 * extent_4) / size_9;
}

float shadow_bias(
    float texel,
    float cos_light_1
) {
    float c_12 = metal::clamp(cos_light_1, 0.02, 1.0);
    return texel * (1.5 + (metal::sqrt(1.0 - (c_12 * c_12)) / c_12));
}

bool shadow_lit(
    float d_3,
    float d_map,
    float bias
) {
    bool local_16 = {};
    if (!((d_map <= 0.0))) {
        local_16 = d_3 <= (d_map + bias);
    } else {
        local_16 = true;
    }
    bool _e11 = local_16;
    return _e11;
}

metal::float3 diffuse_radiance(
    metal::float3 albedo,
    metal::float3 emission,
    metal::float3 e_2
) {
    return emission + ((albedo * INV_PI) * e_2);
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, constant ImageParams& image [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> indirect_tex [[user(fake0)]]
, device type_7 const& direct [[user(fake0)]]
, device type_8 const& materials [[user(fake0)]]
, metal::texture2d<float, metal::access::write> out_tex [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    bool local = {};
    metal::float3 radiance = metal::float3(0.0);
    uint _e4 = image.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = image.height;
        local = gid.y >= _e12;
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    uint _e19 = image.width;
    uint i_2 = (gid.y * _e19) + gid.x;
    metal::int2 texel_1 = metal::int2(static_cast<int>(gid.x), static_cast<int>(gid.y));
    metal::float4 _e33 = position_tex.read(metal::uint2(texel_1), 0);
    if (_e33.w > 0.0) {
        metal::float4 _e40 = normal_tex.read(metal::uint2(texel_1), 0);
        GpuMaterial m_1 = materials[naga_f2u32(_e40.w)];
        metal::float4 _e49 = direct[i_2];
        metal::float4 _e53 = indirect_tex.read(metal::uint2(texel_1), 0);
        metal::float3 _e56 = diffuse_radiance(m_1.albedo, m_1.emission, _e49.xyz + _e53.xyz);
        radiance = _e56;
    }
    metal::float3 _e58 = radiance;
    out_tex.write(metal::float4(_e58, 1.0), metal::uint2(texel_1));
    return;
}
