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
    uint size7;
    uint size9;
    uint size10;
    uint size11;
    uint size12;
    uint size13;
    uint size14;
    uint size15;
    uint size16;
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
    uint material;
    metal::packed_float3 weight;
    float pad1_;
    metal::packed_float3 gnormal;
    float pad2_;
    metal::packed_float3 wo;
    float pad3_;
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
    metal::packed_float3 prev_r;
    uint pad3_;
    metal::float4 prev_lobe;
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
    float metallic;
    metal::packed_float3 emission;
    float alpha;
    metal::packed_float3 f0_;
    float f90_;
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
    float extent;
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
typedef GpuLightCone type_10[1];
typedef GpuLightBvhNode type_11[1];
typedef uint BvhNodes;
struct BvhPick {
    uint light;
    float pmf;
};
typedef GpuLight type_12[1];
typedef BshNode type_13[1];
typedef uint type_14[1];
typedef GpuMaterial type_15[1];
typedef GpuPathState type_16[1];
typedef GpuPathVertex type_17[1];
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
constant float GGX_ALPHA_MIN = 0.001;
constant float RANGE_SCALE_MAX = 64.0;
constant uint LIGHT_BVH_LEAF = 4294967295u;
constant float ONE_MINUS_EPSILON = 0.99999994;
constant float F32_MAX = 340282350000000000000000000000000000000.0;
constant float DEPTH_NONE = 1000000000000000000000000000000.0;
constant float DEPTH_SIGMA = 0.05;
constant float COVER_WEIGHT = 0.1;
constant uint NEAR_BLOCK = 64u;
constant uint ROULETTE_DEPTH = 2u;
constant uint K = 8u;
constant BvhNodes BVH = 0u;

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
    uint v_1 = {};
    v_1 = ((x_2 >> 16u) & 65535u) | ((x_2 & 65535u) << 16u);
    uint _e11 = v_1;
    uint _e16 = v_1;
    v_1 = ((_e11 >> 8u) & 16711935u) | ((_e16 & 16711935u) << 8u);
    uint _e22 = v_1;
    uint _e27 = v_1;
    v_1 = ((_e22 >> 4u) & 252645135u) | ((_e27 & 252645135u) << 4u);
    uint _e33 = v_1;
    uint _e38 = v_1;
    v_1 = ((_e33 >> 2u) & 858993459u) | ((_e38 & 858993459u) << 2u);
    uint _e44 = v_1;
    uint _e49 = v_1;
    v_1 = ((_e44 >> 1u) & 1431655765u) | ((_e49 & 1431655765u) << 1u);
    uint _e55 = v_1;
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
    float w_12 = metal::saturate(1.0 - (q_2 * q_2));
    return (w_12 * w_12) / metal::max(d2_4, 0.0001);
}

bool sphere_contains_point(
    metal::float3 c,
    float r,
    metal::float3 x_3
) {
    metal::float3 v_11 = x_3 - c;
    return metal::dot(v_11, v_11) <= (r * r);
}

bool sphere_overlaps_sphere(
    metal::float3 c1_,
    float r1_,
    metal::float3 c2_,
    float r2_2
) {
    metal::float3 v_12 = c2_ - c1_;
    float r_13 = r1_ + r2_2;
    return metal::dot(v_12, v_12) <= (r_13 * r_13);
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
    bool local_4 = {};
    metal::float3 v_13 = c2_1 - c1_1;
    float d_7 = metal::sqrt(metal::dot(v_13, v_13));
    float _e8 = sphere_pad(r1_1, c1_1);
    if (r1_1 >= ((d_7 + r2_3) + _e8)) {
        return metal::float4(c1_1.x, c1_1.y, c1_1.z, r1_1);
    }
    float _e16 = sphere_pad(r2_3, c2_1);
    if (r2_3 >= ((d_7 + r1_1) + _e16)) {
        return metal::float4(c2_1.x, c2_1.y, c2_1.z, r2_3);
    }
    if (!((d_7 >= SPHERE_HUGE))) {
        local_4 = (0.5 * ((d_7 + r1_1) + r2_3)) >= SPHERE_HUGE;
    } else {
        local_4 = true;
    }
    bool _e35 = local_4;
    if (_e35) {
        return metal::float4(c1_1.x, c1_1.y, c1_1.z, SPHERE_HUGE);
    }
    if (metal::abs(r1_1 - r2_3) >= d_7) {
        if (r1_1 >= r2_3) {
            float rn = metal::max(r1_1, d_7 + r2_3);
            float _e50 = sphere_pad(rn, c1_1);
            return metal::float4(c1_1.x, c1_1.y, c1_1.z, rn + _e50);
        }
        float rm = metal::max(r2_3, d_7 + r1_1);
        float _e58 = sphere_pad(rm, c2_1);
        return metal::float4(c2_1.x, c2_1.y, c2_1.z, rm + _e58);
    }
    float r0_ = 0.5 * ((d_7 + r1_1) + r2_3);
    metal::float3 c_10 = c1_1 + (v_13 * ((r0_ - r1_1) / d_7));
    metal::float3 e1_ = c_10 - c1_1;
    metal::float3 e2_ = c_10 - c2_1;
    float r_14 = metal::max(r0_, metal::max(metal::sqrt(metal::dot(e1_, e1_)) + r1_1, metal::sqrt(metal::dot(e2_, e2_)) + r2_3));
    float _e82 = sphere_pad(r_14, c_10);
    return metal::float4(c_10.x, c_10.y, c_10.z, r_14 + _e82);
}

bool sphere_overlaps_aabb(
    metal::float3 c_2,
    float r_2,
    metal::float3 bmin,
    metal::float3 bmax
) {
    metal::float3 q_3 = metal::clamp(c_2, bmin, bmax);
    metal::float3 v_14 = q_3 - c_2;
    return metal::dot(v_14, v_14) <= (r_2 * r_2);
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
    float w_1
) {
    float _e4 = inverse_square(d2_6);
    float _e6 = slc_weight(rt2_3, d2_6);
    return ((cos_x * _e4) * _e6) * w_1;
}

float connection_cosine(
    metal::float3 x_4,
    metal::float3 y,
    metal::float3 n,
    metal::float3 ng,
    float r2_5
) {
    bool local_5 = {};
    bool local_6 = {};
    metal::float3 v_15 = x_4 - y;
    float d2_12 = metal::dot(v_15, v_15);
    bool _e7 = slc_keep(r2_5, d2_12);
    if (!(!(_e7))) {
        local_5 = !((d2_12 > 0.0));
    } else {
        local_5 = true;
    }
    bool _e16 = local_5;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_13 = v_15 / metal::float3(metal::sqrt(d2_12));
    float cos_x_1 = -(metal::dot(n, w_13));
    if (!((cos_x_1 <= 0.0))) {
        local_6 = metal::dot(ng, w_13) >= 0.0;
    } else {
        local_6 = true;
    }
    bool _e32 = local_6;
    if (_e32) {
        return 0.0;
    }
    return cos_x_1;
}

float vpl_lobe(
    metal::float3 n_1,
    metal::float3 w_2
) {
    return metal::max(metal::dot(n_1, w_2), 0.0) * INV_PI;
}

float vpl_transfer(
    metal::float3 n_l,
    metal::float3 n_x,
    metal::float3 v_2,
    float min_d2_
) {
    float m = metal::max(metal::dot(v_2, v_2), min_d2_);
    return ((metal::max(metal::dot(n_l, v_2), 0.0) * metal::max(-(metal::dot(n_x, v_2)), 0.0)) * INV_PI) / (m * m);
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
    metal::float3 w_3
) {
    return area * metal::max(metal::dot(n_2, w_3), 0.0);
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
    float c_11 = metal::abs(cos_light);
    if (c_11 <= 0.0) {
        return 0.0;
    }
    return (pdf_area * d2_7) / c_11;
}

float atan_portable(
    float x_5
) {
    float base = 0.0;
    float t = {};
    float a_10 = metal::abs(x_5);
    t = a_10;
    if (a_10 > 2.4142137) {
        base = 1.5707964;
        t = -1.0 / a_10;
    } else {
        if (a_10 > 0.41421357) {
            base = 0.7853982;
            t = (a_10 - 1.0) / (a_10 + 1.0);
        }
    }
    float _e18 = t;
    float _e19 = t;
    float z_3 = _e18 * _e19;
    float _e21 = base;
    float _e33 = t;
    float _e35 = t;
    float r_15 = _e21 + (((((((((0.080537446 * z_3) - 0.13877685) * z_3) + 0.19977711) * z_3) - 0.3333295) * z_3) * _e33) + _e35);
    return (x_5 < 0.0) ? -(r_15) : r_15;
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
    bool local_7 = {};
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
        local_7 = gamma > _e22;
    } else {
        local_7 = true;
    }
    bool _e25 = local_7;
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
    float a_11 = (_e58 * (1.0 - _e49)) + (_e65 * _e49);
    float _e71 = at(tab_2, (c0_1 + (ih1_ * _e5)) + _e33, slc_table, _buffer_sizes);
    float _e78 = at(tab_2, (c0_1 + (ih1_ * _e5)) + iv1_, slc_table, _buffer_sizes);
    float b_8 = (_e71 * (1.0 - _e49)) + (_e78 * _e49);
    return (a_11 * (1.0 - _e54)) + (b_8 * _e54);
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
    float c_12 = on_axis ? 0.0 : ((_e16) * 57.295779513082322865);
    float _e20 = ies_candela(tab_3, base_2, gamma_1, c_12, slc_table, _buffer_sizes);
    return _e20;
}

float ies_light_candela(
    Table tab_4,
    uint base_3,
    metal::float3 nadir,
    metal::float3 reference,
    metal::float3 w_4,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 side = metal::cross(reference, nadir);
    float _e9 = ies_candela_dir(tab_4, base_3, metal::dot(w_4, nadir), metal::dot(w_4, reference), metal::dot(w_4, side), slc_table, _buffer_sizes);
    return _e9;
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
    float w_5,
    float w_sum,
    float u_1
) {
    return (u_1 * w_sum) < w_5;
}

float weighted_pick_weight(
    float w_sum_1,
    float w_6,
    uint k_2
) {
    float _e3 = to_f32_(k_2);
    return w_sum_1 / (_e3 * w_6);
}

float reservoir_select_pdf(
    uint seen,
    bool in_range,
    uint k_3
) {
    uint others = {};
    bool local_8 = {};
    others = seen;
    if (in_range) {
        local_8 = seen > 0u;
    } else {
        local_8 = false;
    }
    bool _e9 = local_8;
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

float mis_balance(
    float pdf_a,
    float pdf_b
) {
    float s = pdf_a + pdf_b;
    if (s <= 0.0) {
        return 0.0;
    }
    return pdf_a / s;
}

float mis_power(
    float pdf_a_1,
    float pdf_b_1
) {
    float a2_ = pdf_a_1 * pdf_a_1;
    float s_1 = a2_ + (pdf_b_1 * pdf_b_1);
    if (s_1 <= 0.0) {
        return 0.0;
    }
    return a2_ / s_1;
}

float light_strategy_pdf(
    float select,
    float rt2_4,
    float d2_8,
    float area_1,
    float cos_y
) {
    bool local_9 = {};
    bool local_10 = {};
    if (!((d2_8 <= 0.0))) {
        local_9 = area_1 <= 0.0;
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
    float _e22 = rr_probability(rt2_4, d2_8);
    float _e26 = area_to_solid_angle_pdf(1.0 / area_1, d2_8, cos_y);
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

metal::float3 onb_tangent(
    metal::float3 n_9
) {
    float s_2 = (n_9.z >= 0.0) ? 1.0 : -1.0;
    float a_12 = -1.0 / (s_2 + n_9.z);
    return metal::float3(1.0 + (((s_2 * n_9.x) * n_9.x) * a_12), ((s_2 * n_9.x) * n_9.y) * a_12, -(s_2) * n_9.x);
}

metal::float3 onb_bitangent(
    metal::float3 n_10
) {
    float s_3 = (n_10.z >= 0.0) ? 1.0 : -1.0;
    float a_13 = -1.0 / (s_3 + n_10.z);
    return metal::float3((n_10.x * n_10.y) * a_13, s_3 + ((n_10.y * n_10.y) * a_13), -(n_10.y));
}

metal::float3 onb_to_world(
    metal::float3 n_11,
    metal::float3 d
) {
    metal::float3 _e2 = onb_tangent(n_11);
    metal::float3 _e5 = onb_bitangent(n_11);
    return ((_e2 * d.x) + (_e5 * d.y)) + (n_11 * d.z);
}

metal::float3 onb_to_local(
    metal::float3 n_12,
    metal::float3 w_7
) {
    metal::float3 _e2 = onb_tangent(n_12);
    metal::float3 _e4 = onb_bitangent(n_12);
    return metal::float3(metal::dot(w_7, _e2), metal::dot(w_7, _e4), metal::dot(w_7, n_12));
}

metal::float3 cosine_direction(
    metal::float3 n_13,
    float u1_1,
    float u2_1
) {
    float r_16 = metal::sqrt(u1_1);
    float phi_5 = 6.2831855 * u2_1;
    metal::float3 _e16 = onb_to_world(n_13, metal::float3(r_16 * metal::cos(phi_5), r_16 * metal::sin(phi_5), metal::sqrt(metal::max(1.0 - u1_1, 0.0))));
    return metal::normalize(_e16);
}

float ggx_alpha(
    float roughness
) {
    return metal::max(roughness * roughness, GGX_ALPHA_MIN);
}

float ggx_d(
    float cos_h,
    float sin2_h,
    float alpha
) {
    if (cos_h <= 0.0) {
        return 0.0;
    }
    float a2_1 = alpha * alpha;
    float t_3 = ((cos_h * cos_h) * a2_1) + sin2_h;
    return (a2_1 * INV_PI) / (t_3 * t_3);
}

float smith_root(
    float cos,
    float alpha_1
) {
    float a2_2 = alpha_1 * alpha_1;
    return metal::sqrt(((cos * cos) * (1.0 - a2_2)) + a2_2);
}

float smith_visibility(
    float n_l_1,
    float n_v,
    float alpha_2
) {
    bool local_11 = {};
    if (!((n_l_1 <= 0.0))) {
        local_11 = n_v <= 0.0;
    } else {
        local_11 = true;
    }
    bool _e11 = local_11;
    if (_e11) {
        return 0.0;
    }
    float _e13 = smith_root(n_v, alpha_2);
    float _e15 = smith_root(n_l_1, alpha_2);
    return 0.5 / ((n_l_1 * _e13) + (n_v * _e15));
}

metal::float3 fresnel_schlick(
    metal::float3 f0_,
    float f90_,
    float v_h
) {
    float c_13 = metal::saturate(1.0 - v_h);
    float c2_2 = c_13 * c_13;
    return f0_ + ((metal::float3(f90_, f90_, f90_) - f0_) * ((c2_2 * c2_2) * c_13));
}

metal::float3 specular_fresnel(
    metal::float3 base_4,
    float metallic,
    metal::float3 f0_d,
    float f90_d,
    float v_h_1
) {
    metal::float3 _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    metal::float3 _e10 = fresnel_schlick(base_4, 1.0, v_h_1);
    return (_e5 * (1.0 - metallic)) + (_e10 * metallic);
}

metal::float3 diffuse_brdf(
    metal::float3 base_5,
    float metallic_1,
    metal::float3 f0_d_1,
    float f90_d_1,
    float v_h_2
) {
    metal::float3 _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return (((metal::float3(1.0, 1.0, 1.0) - _e9) * base_5) * (1.0 - metallic_1)) * INV_PI;
}

float half_cosine(
    metal::float3 v_3,
    metal::float3 l
) {
    metal::float3 h_2 = v_3 + l;
    float len2_ = metal::dot(h_2, h_2);
    if (len2_ <= 0.0) {
        return 0.0;
    }
    return metal::saturate(metal::dot(v_3, h_2) / metal::sqrt(len2_));
}

metal::float3 specular_brdf(
    metal::float3 base_6,
    float metallic_2,
    metal::float3 f0_d_2,
    float f90_d_2,
    float alpha_3,
    metal::float3 n_14,
    metal::float3 v_4,
    metal::float3 l_1
) {
    bool local_12 = {};
    float n_l_2 = metal::dot(n_14, l_1);
    float n_v_2 = metal::dot(n_14, v_4);
    if (!((n_l_2 <= 0.0))) {
        local_12 = n_v_2 <= 0.0;
    } else {
        local_12 = true;
    }
    bool _e18 = local_12;
    if (_e18) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    metal::float3 hs = v_4 + l_1;
    float inv = 1.0 / metal::sqrt(metal::dot(hs, hs));
    metal::float3 h_3 = hs * inv;
    metal::float3 c_14 = metal::cross(n_14, h_3);
    float _e32 = ggx_d(metal::dot(n_14, h_3), metal::dot(c_14, c_14), alpha_3);
    metal::float3 _e34 = specular_fresnel(base_6, metallic_2, f0_d_2, f90_d_2, metal::dot(v_4, h_3));
    float _e35 = smith_visibility(n_l_2, n_v_2, alpha_3);
    return _e34 * (_e32 * _e35);
}

metal::float3 brdf_eval(
    metal::float3 base_7,
    float metallic_3,
    metal::float3 f0_d_3,
    float f90_d_3,
    float alpha_4,
    metal::float3 n_15,
    metal::float3 v_5,
    metal::float3 l_2
) {
    if (metal::dot(n_15, l_2) <= 0.0) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    float _e15 = half_cosine(v_5, l_2);
    metal::float3 _e16 = diffuse_brdf(base_7, metallic_3, f0_d_3, f90_d_3, _e15);
    metal::float3 _e17 = specular_brdf(base_7, metallic_3, f0_d_3, f90_d_3, alpha_4, n_15, v_5, l_2);
    return _e16 + _e17;
}

bool has_specular(
    float metallic_4,
    metal::float3 f0_d_4,
    float f90_d_4
) {
    bool local_13 = {};
    bool local_14 = {};
    if (!((metallic_4 > 0.0))) {
        local_13 = f90_d_4 > 0.0;
    } else {
        local_13 = true;
    }
    bool _e11 = local_13;
    if (!(_e11)) {
        local_14 = metal::max(metal::max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0.0;
    } else {
        local_14 = true;
    }
    bool _e23 = local_14;
    return _e23;
}

float channel_mean(
    metal::float3 c_6
) {
    return ((c_6.x + c_6.y) + c_6.z) * 0.33333334;
}

metal::float4 receiver_lobe(
    metal::float3 base_8,
    float metallic_5,
    metal::float3 f0_d_5,
    float f90_d_5,
    float alpha_5,
    float n_v_1
) {
    bool local_15 = {};
    metal::float3 _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    float _e16 = channel_mean(((metal::float3(1.0, 1.0, 1.0) - _e10) * base_8) * (1.0 - metallic_5));
    if (!((n_v_1 <= 0.0))) {
        bool _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_15 = !(_e22);
    } else {
        local_15 = true;
    }
    bool _e25 = local_15;
    if (_e25) {
        return metal::float4(_e16, 0.0, alpha_5, n_v_1);
    }
    metal::float3 _e28 = specular_fresnel(base_8, metallic_5, f0_d_5, f90_d_5, n_v_1);
    float _e29 = channel_mean(_e28);
    return metal::float4(_e16, _e29, alpha_5, n_v_1);
}

float specular_probability(
    metal::float4 lobe
) {
    if (lobe.y <= 0.0) {
        return 0.0;
    }
    if (lobe.x <= 0.0) {
        return 1.0;
    }
    return metal::clamp(lobe.y / (lobe.y + lobe.x), 0.1, 0.9);
}

float receiver_peak(
    metal::float4 lobe_1
) {
    float _e10 = smith_root(lobe_1.w, lobe_1.z);
    return lobe_1.x + ((lobe_1.y * 0.25) / ((lobe_1.z * lobe_1.z) * _e10));
}

float range_scale(
    metal::float4 lobe_2
) {
    if (lobe_2.y <= 0.0) {
        return 1.0;
    }
    float _e5 = receiver_peak(lobe_2);
    return metal::clamp(_e5, 1.0, RANGE_SCALE_MAX);
}

metal::float3 mirror_dir(
    metal::float3 n_16,
    metal::float3 v_6
) {
    return (n_16 * (2.0 * metal::dot(n_16, v_6))) - v_6;
}

float bounded_vndf_k(
    metal::float3 wi,
    float alpha_6
) {
    float a_14 = metal::saturate(alpha_6);
    float s_4 = 1.0 + metal::sqrt((wi.x * wi.x) + (wi.y * wi.y));
    float a2_3 = a_14 * a_14;
    float s2_ = s_4 * s_4;
    return ((1.0 - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z));
}

metal::float3 ggx_vndf_sample(
    metal::float3 wi_1,
    float alpha_7,
    float u1_2,
    float u2_2
) {
    metal::float3 wi_std = metal::normalize(metal::float3(wi_1.x * alpha_7, wi_1.y * alpha_7, wi_1.z));
    float _e12 = bounded_vndf_k(wi_1, alpha_7);
    float b_9 = (wi_1.z > 0.0) ? (_e12 * wi_std.z) : wi_std.z;
    float phi_6 = 6.2831855 * u1_2;
    float z_4 = ((1.0 - u2_2) * (1.0 + b_9)) - b_9;
    float sin_t = metal::sqrt(metal::saturate(1.0 - (z_4 * z_4)));
    metal::float3 m_std = wi_std + metal::float3(sin_t * metal::cos(phi_6), sin_t * metal::sin(phi_6), z_4);
    metal::float3 m_1 = metal::normalize(metal::float3(m_std.x * alpha_7, m_std.y * alpha_7, m_std.z));
    return (m_1 * (2.0 * metal::dot(wi_1, m_1))) - wi_1;
}

float ggx_vndf_pdf(
    metal::float3 wi_2,
    metal::float3 wo,
    float alpha_8
) {
    bool local_16 = {};
    if (!((wi_2.z <= 0.0))) {
        local_16 = wo.z <= 0.0;
    } else {
        local_16 = true;
    }
    bool _e13 = local_16;
    if (_e13) {
        return 0.0;
    }
    metal::float3 hs_1 = wi_2 + wo;
    metal::float3 m_2 = hs_1 / metal::float3(metal::sqrt(metal::dot(hs_1, hs_1)));
    float _e28 = ggx_d(m_2.z, (m_2.x * m_2.x) + (m_2.y * m_2.y), alpha_8);
    float t_4 = metal::sqrt(((alpha_8 * alpha_8) * ((wi_2.x * wi_2.x) + (wi_2.y * wi_2.y))) + (wi_2.z * wi_2.z));
    float _e43 = bounded_vndf_k(wi_2, alpha_8);
    return _e28 / (2.0 * ((_e43 * wi_2.z) + t_4));
}

metal::float3 bsdf_sample(
    metal::float3 n_17,
    metal::float3 v_7,
    float alpha_9,
    float p_spec,
    float u1_3,
    float u2_3
) {
    if (u1_3 < p_spec) {
        if (metal::dot(n_17, v_7) <= 0.0) {
            return -(n_17);
        }
        metal::float3 _e11 = onb_to_local(n_17, v_7);
        metal::float3 _e13 = ggx_vndf_sample(_e11, alpha_9, u1_3 / p_spec, u2_3);
        metal::float3 _e14 = onb_to_world(n_17, _e13);
        return metal::normalize(_e14);
    }
    metal::float3 _e20 = cosine_direction(n_17, (u1_3 - p_spec) / (1.0 - p_spec), u2_3);
    return _e20;
}

float bsdf_pdf(
    metal::float3 n_18,
    metal::float3 v_8,
    metal::float3 l_3,
    float alpha_10,
    float p_spec_1
) {
    float _e6 = cosine_pdf(metal::dot(n_18, l_3));
    if (p_spec_1 <= 0.0) {
        return _e6;
    }
    metal::float3 _e9 = onb_to_local(n_18, v_8);
    metal::float3 _e10 = onb_to_local(n_18, l_3);
    float _e11 = ggx_vndf_pdf(_e9, _e10, alpha_10);
    return (p_spec_1 * _e11) + ((1.0 - p_spec_1) * _e6);
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

float subtended_cos(
    float dist2_,
    float r2_6
) {
    float _e5 = safe_sqrt(1.0 - (r2_6 / dist2_));
    return (dist2_ <= r2_6) ? -1.0 : _e5;
}

float emitter_importance(
    metal::float3 center,
    float radius,
    float phi,
    metal::float3 axis,
    float cos_o,
    float cos_e,
    metal::float3 p
) {
    metal::float3 v_16 = p - center;
    float dist2_1 = metal::dot(v_16, v_16);
    float r2_7 = radius * radius;
    float d2_13 = metal::max(metal::max(dist2_1, r2_7), MIN_D2_);
    metal::float3 wi_3 = (dist2_1 > 0.0) ? (v_16 / metal::float3(metal::sqrt(dist2_1))) : metal::float3(0.0, 0.0, 0.0);
    float cos_w = metal::dot(axis, wi_3);
    float _e27 = safe_sqrt(1.0 - (cos_w * cos_w));
    float _e28 = subtended_cos(dist2_1, r2_7);
    float _e32 = safe_sqrt(1.0 - (_e28 * _e28));
    float _e36 = safe_sqrt(1.0 - (cos_o * cos_o));
    float _e37 = cos_sub_clamped(_e27, cos_w, _e36, cos_o);
    float _e38 = sin_sub_clamped(_e27, cos_w, _e36, cos_o);
    float _e39 = cos_sub_clamped(_e38, _e37, _e32, _e28);
    if (_e39 <= cos_e) {
        return 0.0;
    }
    return (phi * _e39) / d2_13;
}

float cone_cos_toward(
    metal::float3 center_1,
    float radius_1,
    metal::float3 p_1,
    metal::float3 d_1
) {
    metal::float3 v_17 = center_1 - p_1;
    float dist2_2 = metal::dot(v_17, v_17);
    metal::float3 w_14 = (dist2_2 > 0.0) ? (v_17 / metal::float3(metal::sqrt(dist2_2))) : metal::float3(0.0, 0.0, 0.0);
    float _e17 = subtended_cos(dist2_2, radius_1 * radius_1);
    float cos_i = metal::dot(w_14, d_1);
    float _e22 = safe_sqrt(1.0 - (cos_i * cos_i));
    float _e26 = safe_sqrt(1.0 - (_e17 * _e17));
    float _e27 = cos_sub_clamped(_e22, cos_i, _e26, _e17);
    return _e27;
}

float light_importance(
    metal::float3 center_2,
    float radius_2,
    float phi_1,
    metal::float3 axis_1,
    float cos_o_1,
    float cos_e_1,
    metal::float3 p_2,
    metal::float3 n_19
) {
    float imp = {};
    float _e8 = emitter_importance(center_2, radius_2, phi_1, axis_1, cos_o_1, cos_e_1, p_2);
    imp = _e8;
    if (metal::dot(n_19, n_19) > 0.0) {
        float _e13 = imp;
        float _e14 = cone_cos_toward(center_2, radius_2, p_2, n_19);
        imp = _e13 * metal::max(_e14, 0.0);
    }
    float _e18 = imp;
    return metal::max(_e18, 0.0);
}

float glossy_importance(
    metal::float3 center_3,
    float radius_3,
    float phi_2,
    metal::float3 axis_2,
    float cos_o_2,
    float cos_e_2,
    metal::float3 p_3,
    metal::float3 n_20,
    metal::float3 r_3,
    metal::float4 lobe_3
) {
    bool local_17 = {};
    float _e10 = emitter_importance(center_3, radius_3, phi_2, axis_2, cos_o_2, cos_e_2, p_3);
    float _e11 = cone_cos_toward(center_3, radius_3, p_3, n_20);
    if (!((_e10 <= 0.0))) {
        local_17 = _e11 <= 0.0;
    } else {
        local_17 = true;
    }
    bool _e20 = local_17;
    if (_e20) {
        return 0.0;
    }
    float _e22 = cone_cos_toward(center_3, radius_3, p_3, r_3);
    float _e27 = safe_sqrt(0.5 + (0.5 * _e22));
    float _e33 = ggx_d(_e27, 1.0 - (_e27 * _e27), lobe_3.z);
    float _e39 = smith_root(lobe_3.w, lobe_3.z);
    float spec = ((lobe_3.y * _e33) * 0.25) / _e39;
    return _e10 * (((lobe_3.x * INV_PI) * _e11) + spec);
}

float receiver_importance(
    metal::float3 center_4,
    float radius_4,
    float phi_3,
    metal::float3 axis_3,
    float cos_o_3,
    float cos_e_3,
    metal::float3 p_4,
    metal::float3 n_21,
    metal::float3 r_4,
    metal::float4 lobe_4
) {
    if (lobe_4.y <= 0.0) {
        float _e13 = light_importance(center_4, radius_4, phi_3, axis_3, cos_o_3, cos_e_3, p_4, n_21);
        return _e13;
    }
    float _e14 = glossy_importance(center_4, radius_4, phi_3, axis_3, cos_o_3, cos_e_3, p_4, n_21, r_4, lobe_4);
    return _e14;
}

float candidate_weight(
    float importance,
    float rt2_5,
    float d2_9
) {
    float _e3 = slc_weight(rt2_5, d2_9);
    return importance * _e3;
}

float cone_weight(
    metal::float3 center_5,
    float radius_5,
    float phi_4,
    metal::float3 axis_4,
    float cos_o_4,
    float cos_e_4,
    float rt2_6,
    metal::float3 p_5,
    metal::float3 n_22,
    metal::float3 r_5,
    metal::float4 lobe_5
) {
    metal::float3 v_18 = p_5 - center_5;
    if (lobe_5.y <= 0.0) {
        float _e15 = light_importance(center_5, radius_5, phi_4, axis_4, cos_o_4, cos_e_4, p_5, n_22);
        float _e19 = candidate_weight(_e15 * INV_PI, rt2_6, metal::dot(v_18, v_18));
        return _e19;
    }
    float _e20 = glossy_importance(center_5, radius_5, phi_4, axis_4, cos_o_4, cos_e_4, p_5, n_22, r_5, lobe_5);
    float _e22 = candidate_weight(_e20, rt2_6, metal::dot(v_18, v_18));
    return _e22;
}

float weighted_select_pdf(
    float w_8,
    float w_sum_2,
    bool in_range_1,
    uint k_4
) {
    if (w_8 <= 0.0) {
        return 0.0;
    }
    float total = in_range_1 ? w_sum_2 : (w_sum_2 + w_8);
    float _e9 = to_f32_(k_4);
    return (_e9 * w_8) / total;
}

float bvh_first_prob(
    float c0_,
    float c1_2
) {
    float s_5 = c0_ + c1_2;
    if (s_5 > 0.0) {
        return c0_ / s_5;
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

metal::float3 triangle_normal(
    metal::float3 a_5,
    metal::float3 b_4,
    metal::float3 c_7
) {
    bool local_18 = {};
    metal::float3 n_35 = metal::cross(b_4 - a_5, c_7 - a_5);
    float l2_ = metal::dot(n_35, n_35);
    if (!(!((l2_ > 0.0)))) {
        local_18 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_18 = true;
    }
    bool _e17 = local_18;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_35 / metal::float3(metal::sqrt(l2_));
}

metal::float3 face_against(
    metal::float3 n_23,
    metal::float3 dir
) {
    return (metal::dot(n_23, dir) > 0.0) ? -(n_23) : n_23;
}

metal::float3 barycentric(
    metal::float3 p_6,
    metal::float3 a_6,
    metal::float3 b_5,
    metal::float3 c_8
) {
    metal::float3 e1_1 = b_5 - a_6;
    metal::float3 e2_1 = c_8 - a_6;
    metal::float3 q_4 = p_6 - a_6;
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
    metal::float3 w_9,
    metal::float3 facing
) {
    bool local_19 = {};
    metal::float3 s_6 = ((n0_ * w_9.x) + (n1_ * w_9.y)) + (n2_ * w_9.z);
    float l2_1 = metal::dot(s_6, s_6);
    if (!(!((l2_1 > 0.000000000001)))) {
        local_19 = !((l2_1 < 300000000000000000000000000000000000000.0));
    } else {
        local_19 = true;
    }
    bool _e24 = local_19;
    if (_e24) {
        return facing;
    }
    metal::float3 n_36 = s_6 / metal::float3(metal::sqrt(l2_1));
    return (metal::dot(n_36, facing) < 0.0) ? -(n_36) : n_36;
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_3,
    metal::float3 a_7,
    metal::float3 b_6,
    metal::float3 c_9,
    float t_min,
    float t_max_1
) {
    bool local_20 = {};
    bool local_21 = {};
    bool local_22 = {};
    metal::float3 e1_2 = b_6 - a_7;
    metal::float3 e2_2 = c_9 - a_7;
    metal::float3 p_7 = metal::cross(d_3, e2_2);
    float det = metal::dot(e1_2, p_7);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv_1 = 1.0 / det;
    metal::float3 s_7 = o_1 - a_7;
    float u_7 = metal::dot(s_7, p_7) * inv_1;
    if (!((u_7 < 0.0))) {
        local_20 = u_7 > 1.0;
    } else {
        local_20 = true;
    }
    bool _e28 = local_20;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q_5 = metal::cross(s_7, e1_2);
    float v_19 = metal::dot(d_3, q_5) * inv_1;
    if (!((v_19 < 0.0))) {
        local_21 = (u_7 + v_19) > 1.0;
    } else {
        local_21 = true;
    }
    bool _e42 = local_21;
    if (_e42) {
        return -1.0;
    }
    float t_5 = metal::dot(e2_2, q_5) * inv_1;
    if (t_5 > t_min) {
        local_22 = t_5 < t_max_1;
    } else {
        local_22 = false;
    }
    bool _e51 = local_22;
    if (_e51) {
        return t_5;
    }
    return -1.0;
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
    metal::float3 n_24,
    metal::float3 nj,
    float z_1,
    float zj,
    float inv_sz
) {
    float dn = metal::max(metal::dot(n_24, nj), 0.0);
    float dn2_ = dn * dn;
    float dn4_ = dn2_ * dn2_;
    float dn8_ = dn4_ * dn4_;
    float d_8 = (zj - z_1) * inv_sz;
    float t_6 = metal::max(1.0 - (d_8 * d_8), 0.0);
    return ((dn8_ * dn8_) * t_6) * t_6;
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
    float t_7 = metal::clamp((near_r2_ - d2_10) / (0.75 * near_r2_), 0.0, 1.0);
    return (t_7 * t_7) * (3.0 - (2.0 * t_7));
}

float vpl_far_weight(
    float d2_11,
    float near_r2_1
) {
    float _e2 = vpl_near_weight(d2_11, near_r2_1);
    return 1.0 - _e2;
}

metal::float3 camera_dir(
    metal::float3 forward,
    metal::float3 right,
    metal::float3 up,
    float px,
    float py,
    float w_10,
    float h_1
) {
    float sx = ((2.0 * px) / w_10) - 1.0;
    float sy = 1.0 - ((2.0 * py) / h_1);
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
    metal::float3 n_25,
    metal::float3 ng_1
) {
    bool local_23 = {};
    if (metal::dot(nd, n_25) > 0.0) {
        local_23 = metal::dot(nd, ng_1) > 0.0;
    } else {
        local_23 = false;
    }
    bool _e12 = local_23;
    return _e12;
}

bool finite3_(
    metal::float3 v_9
) {
    bool local_24 = {};
    bool local_25 = {};
    if (metal::abs(v_9.x) <= F32_MAX) {
        local_24 = metal::abs(v_9.y) <= F32_MAX;
    } else {
        local_24 = false;
    }
    bool _e12 = local_24;
    if (_e12) {
        local_25 = metal::abs(v_9.z) <= F32_MAX;
    } else {
        local_25 = false;
    }
    bool _e20 = local_25;
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
    metal::float3 axis_5,
    float extent_2,
    bool perspective
) {
    return metal::dot(rel, dir_2) / ((perspective ? metal::dot(rel, axis_5) : 1.0) * extent_2);
}

float display_encode(
    float x_14
) {
    float v_20 = metal::max(x_14, 0.0);
    float t_8 = (2.0 * v_20) / (1.0 + (2.0 * v_20));
    return (t_8 <= 0.0031308) ? (12.92 * t_8) : ((1.055 * metal::pow(t_8, 0.41666666)) - 0.055);
}

float light_map_depth(
    metal::float3 rel_1,
    metal::float3 axis_6,
    bool perspective_1
) {
    return perspective_1 ? metal::sqrt(metal::dot(rel_1, rel_1)) : metal::dot(rel_1, axis_6);
}

float rsm_texel_solid_angle(
    float texel_area,
    float cos_axis
) {
    return ((texel_area * cos_axis) * cos_axis) * cos_axis;
}

metal::float3 point_irradiance(
    metal::float3 intensity_1,
    metal::float3 n_26,
    metal::float3 v_10
) {
    float d2_14 = metal::dot(v_10, v_10);
    float cos_x_2 = metal::dot(n_26, v_10) / metal::sqrt(metal::max(d2_14, MIN_D2_));
    float _e11 = inverse_square(d2_14);
    return intensity_1 * (metal::max(cos_x_2, 0.0) * _e11);
}

metal::float3 directional_irradiance(
    metal::float3 e_1,
    metal::float3 n_27,
    metal::float3 to_light
) {
    return e_1 * metal::max(metal::dot(n_27, to_light), 0.0);
}

float perspective_texel_width(
    float extent_3,
    float d_4,
    float z_2,
    float size_8
) {
    return (((2.0 * extent_3) * d_4) * d_4) / (size_8 * z_2);
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
    float c_15 = metal::clamp(cos_light_1, 0.02, 1.0);
    return texel * (1.5 + (metal::sqrt(1.0 - (c_15 * c_15)) / c_15));
}

bool shadow_lit(
    float d_5,
    float d_map,
    float bias
) {
    bool local_26 = {};
    if (!((d_map <= 0.0))) {
        local_26 = d_5 <= (d_map + bias);
    } else {
        local_26 = true;
    }
    bool _e11 = local_26;
    return _e11;
}

metal::float3 diffuse_radiance(
    metal::float3 albedo,
    metal::float3 emission,
    metal::float3 e_2
) {
    return emission + ((albedo * INV_PI) * e_2);
}

metal::float3 light_intensity(
    GpuLight l_4,
    metal::float3 w_11
) {
    switch(l_4.kind) {
        case 0u: {
            return l_4.intensity;
        }
        case 3u: {
            metal::float3 _e8 = triangle_normal(l_4.p0_, l_4.p1_, l_4.p2_);
            float _e10 = triangle_lobe(_e8, l_4.a, w_11);
            return l_4.intensity * _e10;
        }
        default: {
            return metal::float3(0.0);
        }
    }
}

metal::float3 light_point(
    GpuLight l_5,
    float u1_4,
    float u2_4
) {
    if (l_5.kind == LIGHT_TRIANGLE) {
        metal::float3 _e9 = triangle_sample(l_5.p0_, l_5.p1_, l_5.p2_, u1_4, u2_4);
        return _e9;
    }
    return l_5.p0_;
}

float light_area(
    GpuLight l_6
) {
    if (l_6.kind == LIGHT_TRIANGLE) {
        return l_6.a;
    }
    return 0.0;
}

metal::float3 light_normal(
    GpuLight l_7
) {
    if (l_7.kind == LIGHT_TRIANGLE) {
        metal::float3 _e7 = triangle_normal(l_7.p0_, l_7.p1_, l_7.p2_);
        return _e7;
    }
    return metal::float3(0.0);
}

GeoHit trace(
    metal::float3 o_2,
    metal::float3 d_6,
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
    uint node_1 = 0u;
    uint i_2 = {};
    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((1 + (_buffer_sizes.size1 - 0 - 32) / 32) == 0u) {
        GeoHit _e13 = hit;
        return _e13;
    }
    metal::float3 _e14 = ray_inverse3_(d_6);
    uint2 loop_bound_1 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e21 = node_1;
        GpuGeoNode n_37 = geo_nodes[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_37.bmin, n_37.bmax, _e27);
        if (_e28 >= 0.0) {
            if (n_37.count > 0u) {
                i_2 = n_37.first;
                uint2 loop_bound_2 = uint2(4294967295u);
                bool loop_init = true;
                while(true) {
                    if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                    loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                    if (!loop_init) {
                        uint _e58 = i_2;
                        i_2 = _e58 + 1u;
                    }
                    loop_init = false;
                    uint _e36 = i_2;
                    if (_e36 < (n_37.first + n_37.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i_2;
                        GpuTriangle t_9 = geo_tris[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_6, t_9.v0_, t_9.v1_, t_9.v2_, t_min_1, _e49);
                        if (_e50 > 0.0) {
                            hit.t = _e50;
                            uint _e55 = i_2;
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
                    stack.inner[_e63] = n_37.first + 1u;
                    uint _e68 = sp;
                    sp = _e68 + 1u;
                }
                node_1 = n_37.first;
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
        node_1 = _e80;
    }
    GeoHit _e81 = hit;
    return _e81;
}

bool occluded(
    metal::float3 a_9,
    metal::float3 b_7,
    device type_6 const& geo_nodes,
    device type_7 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 dv = b_7 - a_9;
    float len_1 = metal::length(dv);
    if (len_1 <= 0.0) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    GeoHit _e12 = trace(a_9, dv / metal::float3(len_1), _e7, len_1 - _e7, true, geo_nodes, geo_tris, _buffer_sizes);
    return _e12.tri != NO_LIGHT;
}

float mis_weight(
    float pdf_a_2,
    float pdf_b_2
) {
    float _e2 = mis_power(pdf_a_2, pdf_b_2);
    return _e2;
}

float light_weight(
    uint li,
    metal::float3 x_15,
    metal::float3 n_28,
    metal::float3 r_6,
    metal::float4 lobe_6,
    device type_10 const& light_cones,
    device type_4 const& rt2_7,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_16 = light_cones[li];
    float _e14 = range_scale(lobe_6);
    float _e17 = rt2_7[li];
    float _e19 = cone_weight(c_16.center, c_16.radius, c_16.phi, c_16.axis, c_16.cos_o, c_16.cos_e, _e14 * _e17, x_15, n_28, r_6, lobe_6);
    return _e19;
}

GpuLightBvhNode light_bvh_node(
    BvhNodes nodes,
    uint i_3,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightBvhNode _e4 = light_bvh[i_3];
    return _e4;
}

uint light_bvh_count(
    BvhNodes nodes_1,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    return 1 + (_buffer_sizes.size5 - 0 - 48) / 48;
}

float bvh_importance(
    BvhNodes nodes_2,
    uint i_4,
    metal::float3 x_16,
    metal::float3 n_29,
    metal::float3 r_7,
    metal::float4 lobe_7,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightBvhNode _e6 = light_bvh_node(nodes_2, i_4, light_bvh, _buffer_sizes);
    float _e13 = receiver_importance(_e6.center, _e6.radius, _e6.phi, _e6.axis, _e6.cos_o, _e6.cos_e, x_16, n_29, r_7, lobe_7);
    return _e13;
}

float bvh_first(
    BvhNodes nodes_3,
    uint i_5,
    metal::float3 x_17,
    metal::float3 n_30,
    metal::float3 r_8,
    metal::float4 lobe_8,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_27 = {};
    GpuLightBvhNode _e6 = light_bvh_node(nodes_3, i_5, light_bvh, _buffer_sizes);
    uint j = _e6.second;
    if (!((j <= (i_5 + 1u)))) {
        uint _e14 = light_bvh_count(nodes_3, light_bvh, _buffer_sizes);
        local_27 = j >= _e14;
    } else {
        local_27 = true;
    }
    bool _e17 = local_27;
    if (_e17) {
        return -1.0;
    }
    float _e21 = bvh_importance(nodes_3, i_5 + 1u, x_17, n_30, r_8, lobe_8, light_bvh, _buffer_sizes);
    float _e22 = bvh_importance(nodes_3, j, x_17, n_30, r_8, lobe_8, light_bvh, _buffer_sizes);
    float _e23 = bvh_first_prob(_e21, _e22);
    return _e23;
}

BvhPick bvh_pick_none(
) {
    return BvhPick {0u, 0.0};
}

BvhPick light_bvh_sample(
    BvhNodes nodes_4,
    metal::float3 x_18,
    metal::float3 n_31,
    metal::float3 r_9,
    metal::float4 lobe_9,
    float u_in,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    BvhPick pick = {};
    float u_6 = {};
    uint i_6 = 0u;
    float pmf = 1.0;
    bool local_28 = {};
    BvhPick _e6 = bvh_pick_none();
    pick = _e6;
    u_6 = u_in;
    uint2 loop_bound_3 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e13 = i_6;
        uint _e14 = light_bvh_count(nodes_4, light_bvh, _buffer_sizes);
        if (_e13 < _e14) {
        } else {
            break;
        }
        {
            uint _e16 = i_6;
            GpuLightBvhNode _e17 = light_bvh_node(nodes_4, _e16, light_bvh, _buffer_sizes);
            if (_e17.second == LIGHT_BVH_LEAF) {
                uint _e21 = i_6;
                if (!((_e21 > 0u))) {
                    float _e28 = bvh_importance(nodes_4, 0u, x_18, n_31, r_9, lobe_9, light_bvh, _buffer_sizes);
                    local_28 = _e28 > 0.0;
                } else {
                    local_28 = true;
                }
                bool _e32 = local_28;
                if (_e32) {
                    pick.light = _e17.light;
                    float _e36 = pmf;
                    pick.pmf = _e36;
                }
                BvhPick _e37 = pick;
                return _e37;
            }
            uint _e38 = i_6;
            float _e39 = bvh_first(nodes_4, _e38, x_18, n_31, r_9, lobe_9, light_bvh, _buffer_sizes);
            if (_e39 < 0.0) {
                BvhPick _e42 = pick;
                return _e42;
            }
            float _e43 = u_6;
            bool first_1 = _e43 < _e39;
            float _e45 = pmf;
            pmf = _e45 * (first_1 ? _e39 : (1.0 - _e39));
            float _e50 = u_6;
            float _e51 = bvh_remap_u(_e50, _e39, first_1);
            u_6 = _e51;
            uint _e53 = i_6;
            i_6 = first_1 ? (_e53 + 1u) : _e17.second;
        }
    }
    BvhPick _e57 = pick;
    return _e57;
}

float light_bvh_pmf(
    BvhNodes nodes_5,
    uint leaf,
    metal::float3 x_19,
    metal::float3 n_32,
    metal::float3 r_10,
    metal::float4 lobe_10,
    device type_11 const& light_bvh,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_7 = 0u;
    float pmf_1 = 1.0;
    bool local_29 = {};
    bool local_30 = {};
    uint _e6 = light_bvh_count(nodes_5, light_bvh, _buffer_sizes);
    if (leaf >= _e6) {
        return 0.0;
    }
    uint2 loop_bound_4 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        uint _e13 = i_7;
        uint _e14 = light_bvh_count(nodes_5, light_bvh, _buffer_sizes);
        if (_e13 < _e14) {
        } else {
            break;
        }
        {
            uint _e16 = i_7;
            GpuLightBvhNode _e17 = light_bvh_node(nodes_5, _e16, light_bvh, _buffer_sizes);
            if (_e17.second == LIGHT_BVH_LEAF) {
                uint _e21 = i_7;
                if (_e21 == leaf) {
                    uint _e25 = i_7;
                    if (!((_e25 > 0u))) {
                        float _e32 = bvh_importance(nodes_5, 0u, x_19, n_32, r_10, lobe_10, light_bvh, _buffer_sizes);
                        local_30 = _e32 > 0.0;
                    } else {
                        local_30 = true;
                    }
                    bool _e36 = local_30;
                    local_29 = _e36;
                } else {
                    local_29 = false;
                }
                bool _e38 = local_29;
                if (_e38) {
                    float _e39 = pmf_1;
                    return _e39;
                }
                return 0.0;
            }
            uint _e41 = i_7;
            float _e42 = bvh_first(nodes_5, _e41, x_19, n_32, r_10, lobe_10, light_bvh, _buffer_sizes);
            if (_e42 < 0.0) {
                return 0.0;
            }
            bool first_2 = leaf < _e17.second;
            float _e48 = pmf_1;
            pmf_1 = _e48 * (first_2 ? _e42 : (1.0 - _e42));
            uint _e54 = i_7;
            i_7 = first_2 ? (_e54 + 1u) : _e17.second;
        }
    }
    return 0.0;
}

float select_pdf(
    uint li_1,
    metal::float3 x_20,
    metal::float3 n_33,
    metal::float3 r_11,
    metal::float4 lobe_11,
    uint nee,
    bool in_range_2
) {
    float _e8 = reservoir_select_pdf(nee, in_range_2, K);
    return _e8;
}

float light_pdf(
    uint li_2,
    metal::float3 x_21,
    metal::float3 n_34,
    metal::float3 r_12,
    metal::float4 lobe_12,
    metal::float3 y_3,
    uint nee_1,
    bool in_range_3,
    device type_4 const& rt2_7,
    device type_12 const& lights,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight l_8 = lights[li_2];
    metal::float3 v_21 = x_21 - y_3;
    float d2_15 = metal::dot(v_21, v_21);
    metal::float3 _e13 = light_normal(l_8);
    float cos_y_1 = (d2_15 > 0.0) ? metal::dot(_e13, v_21 / metal::float3(metal::sqrt(d2_15))) : 0.0;
    float _e22 = select_pdf(li_2, x_21, n_34, r_12, lobe_12, nee_1, in_range_3);
    float _e23 = range_scale(lobe_12);
    float _e26 = rt2_7[li_2];
    float _e28 = light_area(l_8);
    float _e29 = light_strategy_pdf(_e22, _e23 * _e26, d2_15, _e28, cos_y_1);
    return _e29;
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

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, device type_6 const& geo_nodes [[user(fake0)]]
, device type_7 const& geo_tris [[user(fake0)]]
, device type_4 const& rt2_7 [[user(fake0)]]
, device type_12 const& lights [[user(fake0)]]
, constant PtParams& params [[user(fake0)]]
, device type_13 const& bsh_nodes [[user(fake0)]]
, device type_14 const& light_leaf [[user(fake0)]]
, device type_15 const& materials [[user(fake0)]]
, device type_9 const& geo_normals [[user(fake0)]]
, device type_14 const& candidates [[user(fake0)]]
, device type_16& paths [[user(fake0)]]
, device type_17& vertices [[user(fake0)]]
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
    bool local_3 = {};
    uint i_8 = gid.x;
    uint _e4 = params.width;
    uint _e7 = params.height;
    if (i_8 >= (_e4 * _e7)) {
        return;
    }
    uint _e13 = params.depth;
    if (_e13 == 0u) {
        uint _e18 = params.seed;
        uint _e21 = params.pass_index;
        uint _e22 = path_stream(_e18, i_8, _e21);
        h = _e22;
        uint _e26 = params.width;
        float _e28 = next_uniform(h);
        float _e29 = jittered_pixel(naga_mod(i_8, _e26), _e28);
        uint _e32 = params.width;
        float _e34 = next_uniform(h);
        float _e35 = jittered_pixel(naga_div(i_8, _e32), _e34);
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
        GpuPathState _e74 = paths[i_8];
        st = _e74;
    }
    v.alive = 0u;
    uint _e79 = st.alive;
    if (_e79 == 0u) {
        GpuPathVertex _e84 = v;
        vertices[i_8] = _e84;
        return;
    }
    metal::float3 _e86 = st.origin;
    metal::float3 _e88 = st.dir;
    float _e91 = params.t_min;
    GeoHit _e94 = trace(_e86, _e88, _e91, F32_MAX, false, geo_nodes, geo_tris, _buffer_sizes);
    if (_e94.tri == NO_LIGHT) {
        st.alive = 0u;
        GpuPathState _e102 = st;
        paths[i_8] = _e102;
        GpuPathVertex _e105 = v;
        vertices[i_8] = _e105;
        return;
    }
    GpuTriangle tri = geo_tris[_e94.tri];
    metal::float3 _e111 = st.origin;
    metal::float3 _e113 = st.dir;
    metal::float3 x_22 = _e111 + (_e113 * _e94.t);
    metal::float3 _e120 = triangle_normal(tri.v0_, tri.v1_, tri.v2_);
    metal::float3 _e122 = st.dir;
    metal::float3 _e123 = face_against(_e120, _e122);
    uint b_10 = _e94.tri * 3u;
    metal::float4 _e129 = geo_normals[b_10];
    metal::float4 _e135 = geo_normals[b_10 + 1u];
    metal::float4 _e141 = geo_normals[b_10 + 2u];
    metal::float3 _e146 = barycentric(x_22, tri.v0_, tri.v1_, tri.v2_);
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
            BshNode leaf_1 = bsh_nodes[_e168];
            metal::float4 _e173 = st.prev_lobe;
            float _e174 = range_scale(_e173);
            float _e176 = bsh_scaled_radius(leaf_1, metal::sqrt(_e174));
            metal::float3 _e178 = st.prev;
            bool _e179 = sphere_contains_point(leaf_1.center, _e176, _e178);
            float _e181 = st.pdf_bsdf;
            metal::float3 _e184 = st.prev;
            metal::float3 _e186 = st.prev_normal;
            metal::float3 _e188 = st.prev_r;
            metal::float4 _e190 = st.prev_lobe;
            uint _e193 = candidates[i_8];
            float _e194 = light_pdf(tri.light, _e184, _e186, _e188, _e190, x_22, _e193, _e179, rt2_7, lights, _buffer_sizes);
            float _e195 = mis_weight(_e181, _e194);
            w = _e195;
        }
        metal::float3 _e197 = st.beta;
        metal::float3 _e202 = lights[tri.light].intensity;
        float _e204 = w;
        metal::float3 add = (_e197 * _e202) * _e204;
        bool _e206 = finite3_(add);
        if (_e206) {
            metal::float4 _e209 = radiance[i_8];
            radiance[i_8] = _e209 + metal::float4(add, 0.0);
        }
    }
    GpuMaterial m_3 = materials[tri.material];
    metal::float3 _e218 = st.dir;
    metal::float3 wo_1 = -(_e218);
    metal::float4 _e226 = receiver_lobe(m_3.albedo, m_3.metallic, m_3.f0_, m_3.f90_, m_3.alpha, metal::dot(_e147, wo_1));
    v.position = x_22;
    v.normal = _e147;
    v.material = tri.material;
    v.gnormal = _e123;
    metal::float3 _e234 = st.beta;
    v.weight = _e234;
    v.wo = wo_1;
    v.alive = 1u;
    GpuPathVertex _e240 = v;
    vertices[i_8] = _e240;
    uint _e242 = st.rng;
    rng = _e242;
    float _e244 = next_uniform(rng);
    float _e245 = next_uniform(rng);
    float _e246 = specular_probability(_e226);
    metal::float3 _e248 = bsdf_sample(_e147, wo_1, m_3.alpha, _e246, _e244, _e245);
    float _e250 = bsdf_pdf(_e147, wo_1, _e248, m_3.alpha, _e246);
    bool _e254 = has_specular(m_3.metallic, m_3.f0_, m_3.f90_);
    if (_e254) {
        metal::float3 _e256 = st.beta;
        metal::float3 _e262 = brdf_eval(m_3.albedo, m_3.metallic, m_3.f0_, m_3.f90_, m_3.alpha, _e147, wo_1, _e248);
        st.beta = _e256 * (_e262 * (metal::dot(_e248, _e147) / _e250));
    } else {
        metal::float3 _e268 = st.beta;
        st.beta = _e268 * m_3.albedo;
    }
    st.prev = x_22;
    st.prev_normal = _e147;
    metal::float3 _e274 = mirror_dir(_e147, wo_1);
    st.prev_r = _e274;
    st.prev_lobe = _e226;
    st.pdf_bsdf = _e250;
    float _e280 = params.eps;
    st.origin = x_22 + (_e123 * _e280);
    st.dir = _e248;
    bool _e284 = continues_path(_e248, _e147, _e123);
    if (!(!(_e284))) {
        local_1 = !((_e250 > 0.0));
    } else {
        local_1 = true;
    }
    bool _e293 = local_1;
    if (!(_e293)) {
        uint _e299 = params.depth;
        uint _e304 = params.max_depth;
        local_2 = (_e299 + 1u) >= _e304;
    } else {
        local_2 = true;
    }
    bool _e307 = local_2;
    if (_e307) {
        st.alive = 0u;
    }
    uint _e312 = params.depth;
    bool _e313 = plays_roulette(_e312);
    if (_e313) {
        uint _e317 = st.alive;
        local_3 = _e317 == 1u;
    } else {
        local_3 = false;
    }
    bool _e321 = local_3;
    if (_e321) {
        metal::float3 _e323 = st.beta;
        float _e324 = path_survival(_e323);
        float _e325 = next_uniform(rng);
        if (_e325 >= _e324) {
            st.alive = 0u;
        } else {
            metal::float3 _e330 = st.beta;
            st.beta = _e330 / metal::float3(_e324);
        }
    }
    uint _e334 = rng;
    st.rng = _e334;
    GpuPathState _e337 = st;
    paths[i_8] = _e337;
    return;
}
