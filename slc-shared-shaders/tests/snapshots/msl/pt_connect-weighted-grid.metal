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
    uint size8;
    uint size9;
    uint size11;
    uint size12;
    uint size13;
    uint size14;
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
struct GpuMaterial {
    metal::packed_float3 albedo;
    float metallic;
    metal::packed_float3 emission;
    float alpha;
    metal::packed_float3 f0_;
    float f90_;
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
struct GeoHit {
    float t;
    uint tri;
};
typedef GpuGeoNode type_7[1];
typedef GpuTriangle type_8[1];
struct type_9 {
    uint inner[64];
};
struct type_10 {
    uint inner[8];
};
typedef uint BshNodes;
typedef BshNode type_11[1];
struct GridFrame {
    metal::packed_float3 lo;
    uint nx;
    metal::packed_float3 hi;
    uint ny;
    metal::packed_float3 inv;
    uint nz;
};
typedef uint type_13[1];
struct BshCursor {
    uint i;
    uint end;
    uint next;
    char _pad3[4];
    metal::float2 cone;
};
struct Connection {
    metal::float3 e;
    metal::packed_float3 y;
    float cos_x;
};
typedef GpuLight type_16[1];
typedef GpuLightCone type_17[1];
typedef uint BvhNodes;
struct type_18 {
    float inner[8];
};
struct WeightedPicks {
    type_10 light;
    type_18 w;
    type_18 threshold;
    float w_sum;
    uint n;
    uint h;
};
typedef GpuPathVertex type_20[1];
typedef GpuMaterial type_21[1];
typedef metal::float4 type_22[1];
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
constant uint GRID_ENTRIES_PER_LIGHT = 8u;
constant float LOBE_CONE_PAD = 1.001;
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
    uint x_1
) {
    uint _e2 = mul_lo_u32_(x_1, 747796405u);
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

bool sphere_contains_point(
    metal::float3 c,
    float r,
    metal::float3 x_2
) {
    metal::float3 v_10 = x_2 - c;
    return metal::dot(v_10, v_10) <= (r * r);
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
    metal::float3 x_3,
    metal::float3 y,
    metal::float3 n,
    metal::float3 ng,
    float r2_1
) {
    bool local = {};
    bool local_1 = {};
    metal::float3 v_11 = x_3 - y;
    float d2_11 = metal::dot(v_11, v_11);
    bool _e7 = slc_keep(r2_1, d2_11);
    if (!(!(_e7))) {
        local = !((d2_11 > 0.0));
    } else {
        local = true;
    }
    bool _e16 = local;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_12 = v_11 / metal::float3(metal::sqrt(d2_11));
    float cos_x_1 = -(metal::dot(n, w_12));
    if (!(!((cos_x_1 > 0.0)))) {
        local_1 = !((metal::dot(ng, w_12) < 0.0));
    } else {
        local_1 = true;
    }
    bool _e34 = local_1;
    if (_e34) {
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
    metal::float3 c_1,
    float u1_,
    float u2_
) {
    float su = metal::sqrt(u1_);
    float b0_ = 1.0 - su;
    float b1_ = u2_ * su;
    return ((a_2 * b0_) + (b_2 * b1_)) + (c_1 * ((1.0 - b0_) - b1_));
}

float area_to_solid_angle_pdf(
    float pdf_area,
    float d2_5,
    float cos_light
) {
    float c_12 = metal::abs(cos_light);
    if (c_12 <= 0.0) {
        return 0.0;
    }
    return (pdf_area * d2_5) / c_12;
}

float atan_portable(
    float x_4
) {
    float base = 0.0;
    float t = {};
    float a_9 = metal::abs(x_4);
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
    float z = _e18 * _e19;
    float _e21 = base;
    float _e33 = t;
    float _e35 = t;
    float r_17 = _e21 + (((((((((0.080537446 * z) - 0.13877685) * z) + 0.19977711) * z) - 0.3333295) * z) * _e33) + _e35);
    return (x_4 < 0.0) ? -(r_17) : r_17;
}

float atan2_portable(
    float y_1,
    float x_5
) {
    if (x_5 == 0.0) {
        if (y_1 > 0.0) {
            return 1.5707964;
        }
        if (y_1 < 0.0) {
            return -1.5707964;
        }
        return 0.0;
    }
    float _e12 = atan_portable(y_1 / x_5);
    if (x_5 > 0.0) {
        return _e12;
    }
    if (y_1 >= 0.0) {
        return _e12 + 3.1415927;
    }
    return _e12 - 3.1415927;
}

float ies_fold_c(
    float c_2,
    float h_first,
    float h_last
) {
    float a_3 = {};
    a_3 = c_2 - (360.0 * metal::floor(c_2 / 360.0));
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
    float x_6,
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
            if (_e23 <= x_6) {
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
    float x_7
) {
    if (a1_ <= a0_) {
        return 0.0;
    }
    return metal::saturate((x_7 - a0_) / (a1_ - a0_));
}

float ies_candela(
    Table tab_2,
    uint base_1,
    float gamma,
    float c_3,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_2 = {};
    float _e4 = at(tab_2, base_1, slc_table, _buffer_sizes);
    uint _e5 = to_u32_(_e4);
    float _e8 = at(tab_2, base_1 + 1u, slc_table, _buffer_sizes);
    uint _e9 = to_u32_(_e8);
    uint v0_ = base_1 + 2u;
    uint h0_1 = v0_ + _e5;
    uint c0_ = h0_1 + _e9;
    float _e14 = at(tab_2, v0_, slc_table, _buffer_sizes);
    if (!((gamma < _e14))) {
        float _e22 = at(tab_2, (v0_ + _e5) - 1u, slc_table, _buffer_sizes);
        local_2 = gamma > _e22;
    } else {
        local_2 = true;
    }
    bool _e25 = local_2;
    if (_e25) {
        return 0.0;
    }
    float _e27 = at(tab_2, h0_1, slc_table, _buffer_sizes);
    float _e31 = at(tab_2, (h0_1 + _e9) - 1u, slc_table, _buffer_sizes);
    float _e32 = ies_fold_c(c_3, _e27, _e31);
    uint _e33 = ies_segment(tab_2, v0_, _e5, gamma, slc_table, _buffer_sizes);
    uint _e34 = ies_segment(tab_2, h0_1, _e9, _e32, slc_table, _buffer_sizes);
    uint iv1_ = metal::min(_e33 + 1u, _e5 - 1u);
    uint ih1_ = metal::min(_e34 + 1u, _e9 - 1u);
    float _e46 = at(tab_2, v0_ + _e33, slc_table, _buffer_sizes);
    float _e48 = at(tab_2, v0_ + iv1_, slc_table, _buffer_sizes);
    float _e49 = ies_lerp_t(_e46, _e48, gamma);
    float _e51 = at(tab_2, h0_1 + _e34, slc_table, _buffer_sizes);
    float _e53 = at(tab_2, h0_1 + ih1_, slc_table, _buffer_sizes);
    float _e54 = ies_lerp_t(_e51, _e53, _e32);
    float _e58 = at(tab_2, (c0_ + (_e34 * _e5)) + _e33, slc_table, _buffer_sizes);
    float _e65 = at(tab_2, (c0_ + (_e34 * _e5)) + iv1_, slc_table, _buffer_sizes);
    float a_10 = (_e58 * (1.0 - _e49)) + (_e65 * _e49);
    float _e71 = at(tab_2, (c0_ + (ih1_ * _e5)) + _e33, slc_table, _buffer_sizes);
    float _e78 = at(tab_2, (c0_ + (ih1_ * _e5)) + iv1_, slc_table, _buffer_sizes);
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
    float c_13 = on_axis ? 0.0 : ((_e16) * 57.295779513082322865);
    float _e20 = ies_candela(tab_3, base_2, gamma_1, c_13, slc_table, _buffer_sizes);
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
    float w_4
) {
    float _e5 = bsh_range_bound(node_2);
    return node_2.extent + ((w_4 * 1.001) * _e5);
}

float weighted_threshold(
    float w_sum,
    float u_2
) {
    return w_sum / (1.0 - u_2);
}

float weighted_pick_weight(
    float w_sum_1,
    float w_5,
    uint k
) {
    float _e3 = to_f32_(k);
    return w_sum_1 / (_e3 * w_5);
}

float mis_power(
    float pdf_a,
    float pdf_b
) {
    float a2_ = pdf_a * pdf_a;
    float s_4 = a2_ + (pdf_b * pdf_b);
    if (s_4 <= 0.0) {
        return 0.0;
    }
    return a2_ / s_4;
}

float light_strategy_pdf(
    float select,
    float rt2_3,
    float d2_6,
    float area_1,
    float cos_y
) {
    bool local_3 = {};
    bool local_4 = {};
    if (!((d2_6 <= 0.0))) {
        local_3 = area_1 <= 0.0;
    } else {
        local_3 = true;
    }
    bool _e13 = local_3;
    if (!(_e13)) {
        local_4 = cos_y <= 0.0;
    } else {
        local_4 = true;
    }
    bool _e20 = local_4;
    if (_e20) {
        return 0.0;
    }
    float _e22 = rr_probability(rt2_3, d2_6);
    float _e26 = area_to_solid_angle_pdf(1.0 / area_1, d2_6, cos_y);
    return (select * _e22) * _e26;
}

float cosine_pdf(
    float cos_theta_1
) {
    return metal::max(cos_theta_1, 0.0) * INV_PI;
}

metal::float3 onb_tangent(
    metal::float3 n_4
) {
    float s_5 = (n_4.z >= 0.0) ? 1.0 : -1.0;
    float a_11 = -1.0 / (s_5 + n_4.z);
    return metal::float3(1.0 + (((s_5 * n_4.x) * n_4.x) * a_11), ((s_5 * n_4.x) * n_4.y) * a_11, -(s_5) * n_4.x);
}

metal::float3 onb_bitangent(
    metal::float3 n_5
) {
    float s_6 = (n_5.z >= 0.0) ? 1.0 : -1.0;
    float a_12 = -1.0 / (s_6 + n_5.z);
    return metal::float3((n_5.x * n_5.y) * a_12, s_6 + ((n_5.y * n_5.y) * a_12), -(n_5.y));
}

metal::float3 onb_to_local(
    metal::float3 n_6,
    metal::float3 w_6
) {
    metal::float3 _e2 = onb_tangent(n_6);
    metal::float3 _e4 = onb_bitangent(n_6);
    return metal::float3(metal::dot(w_6, _e2), metal::dot(w_6, _e4), metal::dot(w_6, n_6));
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
    float t_2 = ((cos_h * cos_h) * a2_1) + sin2_h;
    return (a2_1 * INV_PI) / (t_2 * t_2);
}

float smith_root(
    float cos,
    float alpha_1
) {
    float a2_2 = alpha_1 * alpha_1;
    return metal::sqrt(((cos * cos) * (1.0 - a2_2)) + a2_2);
}

float smith_visibility(
    float n_l,
    float n_v,
    float alpha_2
) {
    bool local_5 = {};
    if (!((n_l <= 0.0))) {
        local_5 = n_v <= 0.0;
    } else {
        local_5 = true;
    }
    bool _e11 = local_5;
    if (_e11) {
        return 0.0;
    }
    float _e13 = smith_root(n_v, alpha_2);
    float _e15 = smith_root(n_l, alpha_2);
    return 0.5 / ((n_l * _e13) + (n_v * _e15));
}

metal::float3 fresnel_schlick(
    metal::float3 f0_,
    float f90_,
    float v_h
) {
    float c_14 = metal::saturate(1.0 - v_h);
    float c2_ = c_14 * c_14;
    return f0_ + ((metal::float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_14));
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
    metal::float3 v,
    metal::float3 l
) {
    metal::float3 h_7 = v + l;
    float len2_ = metal::dot(h_7, h_7);
    if (len2_ <= 0.0) {
        return 0.0;
    }
    return metal::saturate(metal::dot(v, h_7) / metal::sqrt(len2_));
}

metal::float3 specular_brdf(
    metal::float3 base_6,
    float metallic_2,
    metal::float3 f0_d_2,
    float f90_d_2,
    float alpha_3,
    metal::float3 n_7,
    metal::float3 v_1,
    metal::float3 l_1
) {
    bool local_6 = {};
    float n_l_1 = metal::dot(n_7, l_1);
    float n_v_2 = metal::dot(n_7, v_1);
    if (!((n_l_1 <= 0.0))) {
        local_6 = n_v_2 <= 0.0;
    } else {
        local_6 = true;
    }
    bool _e18 = local_6;
    if (_e18) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    metal::float3 hs = v_1 + l_1;
    float inv_1 = 1.0 / metal::sqrt(metal::dot(hs, hs));
    metal::float3 h_8 = hs * inv_1;
    metal::float3 c_15 = metal::cross(n_7, h_8);
    float _e32 = ggx_d(metal::dot(n_7, h_8), metal::dot(c_15, c_15), alpha_3);
    metal::float3 _e34 = specular_fresnel(base_6, metallic_2, f0_d_2, f90_d_2, metal::dot(v_1, h_8));
    float _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return _e34 * (_e32 * _e35);
}

metal::float3 brdf_eval(
    metal::float3 base_7,
    float metallic_3,
    metal::float3 f0_d_3,
    float f90_d_3,
    float alpha_4,
    metal::float3 n_8,
    metal::float3 v_2,
    metal::float3 l_2
) {
    if (metal::dot(n_8, l_2) <= 0.0) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    float _e15 = half_cosine(v_2, l_2);
    metal::float3 _e16 = diffuse_brdf(base_7, metallic_3, f0_d_3, f90_d_3, _e15);
    metal::float3 _e17 = specular_brdf(base_7, metallic_3, f0_d_3, f90_d_3, alpha_4, n_8, v_2, l_2);
    return _e16 + _e17;
}

bool has_specular(
    float metallic_4,
    metal::float3 f0_d_4,
    float f90_d_4
) {
    bool local_7 = {};
    bool local_8 = {};
    if (!((metallic_4 > 0.0))) {
        local_7 = f90_d_4 > 0.0;
    } else {
        local_7 = true;
    }
    bool _e11 = local_7;
    if (!(_e11)) {
        local_8 = metal::max(metal::max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0.0;
    } else {
        local_8 = true;
    }
    bool _e23 = local_8;
    return _e23;
}

float channel_mean(
    metal::float3 c_4
) {
    return ((c_4.x + c_4.y) + c_4.z) * 0.33333334;
}

metal::float4 receiver_lobe(
    metal::float3 base_8,
    float metallic_5,
    metal::float3 f0_d_5,
    float f90_d_5,
    float alpha_5,
    float n_v_1
) {
    bool local_9 = {};
    metal::float3 _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    float _e16 = channel_mean(((metal::float3(1.0, 1.0, 1.0) - _e10) * base_8) * (1.0 - metallic_5));
    if (!((n_v_1 <= 0.0))) {
        bool _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_9 = !(_e22);
    } else {
        local_9 = true;
    }
    bool _e25 = local_9;
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

metal::float3 mirror_dir(
    metal::float3 n_9,
    metal::float3 v_3
) {
    return (n_9 * (2.0 * metal::dot(n_9, v_3))) - v_3;
}

float bounded_vndf_k(
    metal::float3 wi,
    float alpha_6
) {
    float a_13 = metal::saturate(alpha_6);
    float s_7 = 1.0 + metal::sqrt((wi.x * wi.x) + (wi.y * wi.y));
    float a2_3 = a_13 * a_13;
    float s2_ = s_7 * s_7;
    return ((1.0 - a2_3) * s2_) / (s2_ + ((a2_3 * wi.z) * wi.z));
}

float ggx_vndf_pdf(
    metal::float3 wi_1,
    metal::float3 wo,
    float alpha_7
) {
    bool local_10 = {};
    if (!((wi_1.z <= 0.0))) {
        local_10 = wo.z <= 0.0;
    } else {
        local_10 = true;
    }
    bool _e13 = local_10;
    if (_e13) {
        return 0.0;
    }
    metal::float3 hs_1 = wi_1 + wo;
    metal::float3 m_1 = hs_1 / metal::float3(metal::sqrt(metal::dot(hs_1, hs_1)));
    float _e28 = ggx_d(m_1.z, (m_1.x * m_1.x) + (m_1.y * m_1.y), alpha_7);
    float t_3 = metal::sqrt(((alpha_7 * alpha_7) * ((wi_1.x * wi_1.x) + (wi_1.y * wi_1.y))) + (wi_1.z * wi_1.z));
    float _e43 = bounded_vndf_k(wi_1, alpha_7);
    return _e28 / (2.0 * ((_e43 * wi_1.z) + t_3));
}

float bsdf_pdf(
    metal::float3 n_10,
    metal::float3 v_4,
    metal::float3 l_3,
    float alpha_8,
    float p_spec
) {
    float _e6 = cosine_pdf(metal::dot(n_10, l_3));
    if (p_spec <= 0.0) {
        return _e6;
    }
    metal::float3 _e9 = onb_to_local(n_10, v_4);
    metal::float3 _e10 = onb_to_local(n_10, l_3);
    float _e11 = ggx_vndf_pdf(_e9, _e10, alpha_8);
    return (p_spec * _e11) + ((1.0 - p_spec) * _e6);
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
    float x_8
) {
    return metal::sqrt(metal::max(x_8, 0.0));
}

float subtended_cos(
    float dist2_,
    float r2_2
) {
    float _e5 = safe_sqrt(1.0 - (r2_2 / dist2_));
    return (dist2_ <= r2_2) ? -1.0 : _e5;
}

metal::float4 emitter_cone(
    metal::float3 center,
    float radius,
    metal::float3 axis,
    float cos_o,
    metal::float3 p
) {
    bool local_11 = {};
    metal::float3 v_12 = p - center;
    float dist2_1 = metal::dot(v_12, v_12);
    float r2_5 = radius * radius;
    if (dist2_1 <= 0.0) {
        local_11 = r2_5 <= 0.0;
    } else {
        local_11 = false;
    }
    bool _e15 = local_11;
    if (_e15) {
        return metal::float4(-2.0, 0.000000000001, -1.0, 0.0);
    }
    float d2_12 = metal::max(metal::max(dist2_1, r2_5), MIN_D2_);
    metal::float3 wi_2 = (dist2_1 > 0.0) ? (v_12 / metal::float3(metal::sqrt(dist2_1))) : metal::float3(0.0, 0.0, 0.0);
    float cos_w = metal::dot(axis, wi_2);
    float _e38 = safe_sqrt(1.0 - (cos_w * cos_w));
    float _e39 = subtended_cos(dist2_1, r2_5);
    float _e43 = safe_sqrt(1.0 - (_e39 * _e39));
    float _e47 = safe_sqrt(1.0 - (cos_o * cos_o));
    float _e48 = cos_sub_clamped(_e38, cos_w, _e47, cos_o);
    float _e49 = sin_sub_clamped(_e38, cos_w, _e47, cos_o);
    float _e50 = cos_sub_clamped(_e49, _e48, _e43, _e39);
    return metal::float4(_e50, d2_12, _e39, _e43);
}

float emitter_importance(
    metal::float3 center_1,
    float radius_1,
    float phi,
    metal::float3 axis_1,
    float cos_o_1,
    float cos_e,
    metal::float3 p_1
) {
    metal::float4 _e7 = emitter_cone(center_1, radius_1, axis_1, cos_o_1, p_1);
    if (_e7.x <= cos_e) {
        return 0.0;
    }
    return (phi * _e7.x) / _e7.y;
}

float cone_cos_of(
    metal::float3 v_5,
    float d2_7,
    float a_4,
    metal::float3 d
) {
    bool local_12 = {};
    bool local_13 = {};
    float vd = metal::dot(v_5, d);
    float h2_ = d2_7 - (a_4 * a_4);
    if (!((h2_ <= 0.0))) {
        if (vd >= 0.0) {
            local_13 = (vd * vd) >= h2_;
        } else {
            local_13 = false;
        }
        bool _e19 = local_13;
        local_12 = _e19;
    } else {
        local_12 = true;
    }
    bool _e21 = local_12;
    if (_e21) {
        return 1.0;
    }
    metal::float3 c_16 = metal::cross(v_5, d);
    return metal::min(((vd * metal::sqrt(h2_)) + (metal::sqrt(metal::dot(c_16, c_16)) * a_4)) / d2_7, 1.0);
}

float cone_cos_toward(
    metal::float3 center_2,
    float radius_2,
    metal::float3 p_2,
    metal::float3 d_1
) {
    metal::float3 v_13 = center_2 - p_2;
    float _e6 = cone_cos_of(v_13, metal::dot(v_13, v_13), radius_2, d_1);
    return _e6;
}

float range_scale_at(
    metal::float4 rl,
    float cos_t
) {
    float t_4 = ((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0;
    return metal::clamp(rl.x + ((rl.y * rl.z) / (t_4 * t_4)), 1.0, rl.w * rl.w);
}

float range_scale_toward(
    metal::float4 rl_1,
    metal::float3 center_3,
    float radius_3,
    metal::float3 p_3,
    metal::float3 r_1
) {
    if (rl_1.w <= 1.0) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_3, radius_3, p_3, r_1);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

float light_importance(
    metal::float3 center_4,
    float radius_4,
    float phi_1,
    metal::float3 axis_2,
    float cos_o_2,
    float cos_e_1,
    metal::float3 p_4,
    metal::float3 n_11
) {
    float imp = {};
    metal::float4 _e8 = emitter_cone(center_4, radius_4, axis_2, cos_o_2, p_4);
    if (_e8.x <= cos_e_1) {
        return 0.0;
    }
    imp = (phi_1 * _e8.x) / _e8.y;
    if (metal::dot(n_11, n_11) > 0.0) {
        metal::float3 v_14 = center_4 - p_4;
        float dist2_2 = metal::dot(v_14, v_14);
        float cos_i = metal::dot((dist2_2 > 0.0) ? (v_14 / metal::float3(metal::sqrt(dist2_2))) : metal::float3(0.0, 0.0, 0.0), n_11);
        float _e33 = imp;
        float _e37 = safe_sqrt(1.0 - (cos_i * cos_i));
        float _e40 = cos_sub_clamped(_e37, cos_i, _e8.w, _e8.z);
        imp = _e33 * metal::max(_e40, 0.0);
    }
    float _e44 = imp;
    return metal::max(_e44, 0.0);
}

float glossy_importance(
    metal::float3 center_5,
    float radius_5,
    float phi_2,
    metal::float3 axis_3,
    float cos_o_3,
    float cos_e_2,
    metal::float3 p_5,
    metal::float3 n_12,
    metal::float3 r_2,
    metal::float4 lobe_5
) {
    bool local_14 = {};
    float _e10 = emitter_importance(center_5, radius_5, phi_2, axis_3, cos_o_3, cos_e_2, p_5);
    float _e11 = cone_cos_toward(center_5, radius_5, p_5, n_12);
    if (!((_e10 <= 0.0))) {
        local_14 = _e11 <= 0.0;
    } else {
        local_14 = true;
    }
    bool _e20 = local_14;
    if (_e20) {
        return 0.0;
    }
    float _e22 = cone_cos_toward(center_5, radius_5, p_5, r_2);
    float _e27 = safe_sqrt(0.5 + (0.5 * _e22));
    float _e33 = ggx_d(_e27, 1.0 - (_e27 * _e27), lobe_5.z);
    float _e39 = smith_root(lobe_5.w, lobe_5.z);
    float spec = ((lobe_5.y * _e33) * 0.25) / _e39;
    return _e10 * (((lobe_5.x * INV_PI) * _e11) + spec);
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
    metal::float3 center_6,
    float radius_6,
    float phi_3,
    metal::float3 axis_4,
    float cos_o_4,
    float cos_e_3,
    float rt2_5,
    metal::float3 p_6,
    metal::float3 n_13,
    metal::float3 r_3,
    metal::float4 lobe_6
) {
    metal::float3 v_15 = p_6 - center_6;
    if (lobe_6.y <= 0.0) {
        float _e15 = light_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_13);
        float _e19 = candidate_weight(_e15 * INV_PI, rt2_5, metal::dot(v_15, v_15));
        return _e19;
    }
    float _e20 = glossy_importance(center_6, radius_6, phi_3, axis_4, cos_o_4, cos_e_3, p_6, n_13, r_3, lobe_6);
    float _e22 = candidate_weight(_e20, rt2_5, metal::dot(v_15, v_15));
    return _e22;
}

float weighted_select_pdf(
    float w_7,
    float w_sum_2,
    bool in_range,
    uint k_1
) {
    if (w_7 <= 0.0) {
        return 0.0;
    }
    float total = in_range ? w_sum_2 : (w_sum_2 + w_7);
    float _e9 = to_f32_(k_1);
    return (_e9 * w_7) / total;
}

bool finite3_(
    metal::float3 v_6
) {
    bool local_15 = {};
    bool local_16 = {};
    if (metal::abs(v_6.x) <= F32_MAX) {
        local_15 = metal::abs(v_6.y) <= F32_MAX;
    } else {
        local_15 = false;
    }
    bool _e12 = local_15;
    if (_e12) {
        local_16 = metal::abs(v_6.z) <= F32_MAX;
    } else {
        local_16 = false;
    }
    bool _e20 = local_16;
    return _e20;
}

float shadow_margin(
    float len
) {
    return 0.0001 * len;
}

float ray_inverse(
    float x_9
) {
    return 1.0 / ((metal::abs(x_9) < 0.000000000000000000000000000001) ? 0.000000000000000000000000000001 : x_9);
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
    metal::float3 lo_2 = metal::min(t0_, t1_);
    metal::float3 hi_1 = metal::max(t0_, t1_);
    float t_in = metal::max(metal::max(lo_2.x, lo_2.y), metal::max(lo_2.z, 0.0));
    float t_out = metal::min(metal::min(hi_1.x, hi_1.y), metal::min(hi_1.z, t_max));
    if (t_in <= t_out) {
        return t_in;
    }
    return -1.0;
}

metal::float3 triangle_normal(
    metal::float3 a_5,
    metal::float3 b_3,
    metal::float3 c_5
) {
    bool local_17 = {};
    metal::float3 n_23 = metal::cross(b_3 - a_5, c_5 - a_5);
    float l2_ = metal::dot(n_23, n_23);
    if (!(!((l2_ > 0.0)))) {
        local_17 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_17 = true;
    }
    bool _e17 = local_17;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_23 / metal::float3(metal::sqrt(l2_));
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_3,
    metal::float3 a_6,
    metal::float3 b_4,
    metal::float3 c_6,
    float t_min,
    float t_max_1
) {
    bool local_18 = {};
    bool local_19 = {};
    bool local_20 = {};
    metal::float3 e1_ = b_4 - a_6;
    metal::float3 e2_ = c_6 - a_6;
    metal::float3 p_7 = metal::cross(d_3, e2_);
    float det = metal::dot(e1_, p_7);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv_2 = 1.0 / det;
    metal::float3 s_8 = o_1 - a_6;
    float u_3 = metal::dot(s_8, p_7) * inv_2;
    if (!((u_3 < 0.0))) {
        local_18 = u_3 > 1.0;
    } else {
        local_18 = true;
    }
    bool _e28 = local_18;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q = metal::cross(s_8, e1_);
    float v_16 = metal::dot(d_3, q) * inv_2;
    if (!((v_16 < 0.0))) {
        local_19 = (u_3 + v_16) > 1.0;
    } else {
        local_19 = true;
    }
    bool _e42 = local_19;
    if (_e42) {
        return -1.0;
    }
    float t_5 = metal::dot(e2_, q) * inv_2;
    if (t_5 > t_min) {
        local_20 = t_5 < t_max_1;
    } else {
        local_20 = false;
    }
    bool _e51 = local_20;
    if (_e51) {
        return t_5;
    }
    return -1.0;
}

metal::float3 light_intensity(
    GpuLight l_4,
    metal::float3 w_8,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    switch(l_4.kind) {
        case 0u: {
            return l_4.intensity;
        }
        case 1u: {
            float _e11 = spot_falloff(metal::dot(l_4.p1_, w_8), l_4.a, l_4.b, l_4.p2_[0]);
            return l_4.intensity * _e11;
        }
        case 2u: {
            float _e18 = ies_light_candela(0u, l_4.ies_base, l_4.p1_, l_4.p2_, w_8, slc_table, _buffer_sizes);
            return l_4.intensity * _e18;
        }
        case 3u: {
            metal::float3 _e24 = triangle_normal(l_4.p0_, l_4.p1_, l_4.p2_);
            float _e26 = triangle_lobe(_e24, l_4.a, w_8);
            return l_4.intensity * _e26;
        }
        case 4u: {
            float _e30 = vpl_lobe(l_4.p1_, w_8);
            return l_4.intensity * _e30;
        }
        default: {
            return metal::float3(0.0);
        }
    }
}

metal::float3 light_point(
    GpuLight l_5,
    float u1_1,
    float u2_1
) {
    if (l_5.kind == LIGHT_TRIANGLE) {
        metal::float3 _e9 = triangle_sample(l_5.p0_, l_5.p1_, l_5.p2_, u1_1, u2_1);
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
    metal::float3 d_4,
    float t_min_1,
    float t_max_2,
    bool any_hit,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    GeoHit hit = {};
    type_9 stack = {};
    uint sp = 0u;
    uint node_3 = 0u;
    uint i_1 = {};
    hit.t = t_max_2;
    hit.tri = NO_LIGHT;
    if ((1 + (_buffer_sizes.size1 - 0 - 32) / 32) == 0u) {
        GeoHit _e13 = hit;
        return _e13;
    }
    metal::float3 _e14 = ray_inverse3_(d_4);
    uint2 loop_bound_1 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e21 = node_3;
        GpuGeoNode n_24 = geo_nodes[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_24.bmin, n_24.bmax, _e27);
        if (_e28 >= 0.0) {
            if (n_24.count > 0u) {
                i_1 = n_24.first;
                uint2 loop_bound_2 = uint2(4294967295u);
                bool loop_init = true;
                while(true) {
                    if (metal::all(loop_bound_2 == uint2(0u))) { break; }
                    loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
                    if (!loop_init) {
                        uint _e58 = i_1;
                        i_1 = _e58 + 1u;
                    }
                    loop_init = false;
                    uint _e36 = i_1;
                    if (_e36 < (n_24.first + n_24.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i_1;
                        GpuTriangle t_6 = geo_tris[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_4, t_6.v0_, t_6.v1_, t_6.v2_, t_min_1, _e49);
                        if (_e50 > 0.0) {
                            hit.t = _e50;
                            uint _e55 = i_1;
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
                    stack.inner[_e63] = n_24.first + 1u;
                    uint _e68 = sp;
                    sp = _e68 + 1u;
                }
                node_3 = n_24.first;
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
        node_3 = _e80;
    }
    GeoHit _e81 = hit;
    return _e81;
}

bool occluded(
    metal::float3 a_7,
    metal::float3 b_5,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 dv = b_5 - a_7;
    float len_1 = metal::length(dv);
    if (len_1 <= 0.0) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    GeoHit _e12 = trace(a_7, dv / metal::float3(len_1), _e7, len_1 - _e7, true, geo_nodes, geo_tris, _buffer_sizes);
    return _e12.tri != NO_LIGHT;
}

BshNode bsh_node(
    BshNodes nodes,
    uint i_2,
    device type_11 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshNode _e4 = bsh_nodes[i_2];
    return _e4;
}

uint bsh_count(
    BshNodes nodes_1,
    device type_11 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    return 1 + (_buffer_sizes.size3 - 0 - 32) / 32;
}

uint bsh_first(
    BshNodes nodes_2,
    device type_11 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e1 = bsh_count(nodes_2, bsh_nodes, _buffer_sizes);
    if (_e1 > 0u) {
        return 0u;
    }
    return BSH_NONE;
}

float bsh_inner_scale(
    float a_8,
    metal::float3 v_7,
    float d2_9,
    metal::float3 r_4,
    metal::float4 rl_2
) {
    float _e5 = cone_cos_of(v_7, d2_9, a_8, r_4);
    float _e8 = range_scale_at(rl_2, _e5 + 0.000002);
    return _e8;
}

bool bsh_reaches(
    BshNode node_4,
    metal::float3 x_10,
    metal::float3 r_5,
    metal::float4 rl_3
) {
    bool local_21 = {};
    bool local_22 = {};
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_10);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, node_4.radius * (rl_3.w * 1.0001), x_10);
        local_21 = !(_e20);
    } else {
        local_21 = true;
    }
    bool _e23 = local_21;
    if (_e23) {
        return false;
    }
    metal::float3 v_17 = x_10 - node_4.center;
    float d2_13 = metal::dot(v_17, v_17);
    float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_13 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        float _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_10, r_5);
        float _e41 = bsh_scaled_radius(node_4, metal::sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_10);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_17), d2_13, r_5, rl_3);
    float s_c = _e45 * 1.001;
    float _e50 = bsh_range_bound(node_4);
    float reach = node_4.extent + (metal::sqrt(s_c) * _e50);
    if (d2_13 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_22 = d2_13 <= (reach * reach);
    } else {
        local_22 = false;
    }
    bool _e63 = local_22;
    return _e63;
}

uint bsh_next_leaf_lobe(
    BshNodes nodes_3,
    uint start_1,
    metal::float3 x_11,
    metal::float3 r_6,
    metal::float4 rl_4,
    device type_11 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_3 = {};
    i_3 = start_1;
    uint2 loop_bound_3 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e6 = i_3;
        if (_e6 != BSH_NONE) {
        } else {
            break;
        }
        {
            uint _e9 = i_3;
            BshNode _e10 = bsh_node(nodes_3, _e9, bsh_nodes, _buffer_sizes);
            bool _e11 = bsh_reaches(_e10, x_11, r_6, rl_4);
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
    return BSH_NONE;
}

uint bsh_grid_axis(
    float v_8,
    float lo_1,
    float inv,
    uint n_14
) {
    uint _e8 = to_u32_(metal::max((v_8 - lo_1) * inv, 0.0));
    return metal::min(_e8, n_14 - 1u);
}

uint bsh_grid_cell(
    GridFrame f,
    metal::float3 x_12
) {
    bool local_23 = {};
    bool local_24 = {};
    bool local_25 = {};
    bool local_26 = {};
    bool local_27 = {};
    if (x_12.x >= f.lo[0]) {
        local_23 = x_12.y >= f.lo[1];
    } else {
        local_23 = false;
    }
    bool _e13 = local_23;
    if (_e13) {
        local_24 = x_12.z >= f.lo[2];
    } else {
        local_24 = false;
    }
    bool _e21 = local_24;
    if (_e21) {
        local_25 = x_12.x <= f.hi[0];
    } else {
        local_25 = false;
    }
    bool _e29 = local_25;
    if (_e29) {
        local_26 = x_12.y <= f.hi[1];
    } else {
        local_26 = false;
    }
    bool _e37 = local_26;
    if (_e37) {
        local_27 = x_12.z <= f.hi[2];
    } else {
        local_27 = false;
    }
    bool inside = local_27;
    if (!(inside)) {
        return BSH_NONE;
    }
    uint _e54 = bsh_grid_axis(x_12.x, f.lo[0], f.inv[0], f.nx);
    uint _e61 = bsh_grid_axis(x_12.y, f.lo[1], f.inv[1], f.ny);
    uint _e68 = bsh_grid_axis(x_12.z, f.lo[2], f.inv[2], f.nz);
    return (((_e68 * f.ny) + _e61) * f.nx) + _e54;
}

metal::float2 lobe_cone(
    metal::float3 r_7,
    metal::float4 rl_5
) {
    bool local_28 = {};
    bool local_29 = {};
    bool local_30 = {};
    bool local_31 = {};
    float c_7 = {};
    uint tries = 0u;
    bool _e2 = finite3_(r_7);
    if (_e2) {
        local_28 = rl_5.x < 1.0;
    } else {
        local_28 = false;
    }
    bool _e9 = local_28;
    if (_e9) {
        local_29 = rl_5.y >= 0.0;
    } else {
        local_29 = false;
    }
    bool _e16 = local_29;
    if (_e16) {
        local_30 = rl_5.z > 0.0;
    } else {
        local_30 = false;
    }
    bool _e23 = local_30;
    if (_e23) {
        local_31 = rl_5.z < 1.0;
    } else {
        local_31 = false;
    }
    bool _e30 = local_31;
    if (!(_e30)) {
        return metal::float2(0.0, 0.0);
    }
    float t1_1 = metal::sqrt((rl_5.y * rl_5.z) / (1.0 - rl_5.x));
    c_7 = ((2.0 * (1.0 - t1_1)) / (1.0 - rl_5.z)) - 1.0;
    uint2 loop_bound_4 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        float _e56 = c_7;
        float _e57 = range_scale_at(rl_5, _e56);
        if (!((_e57 <= 1.0))) {
        } else {
            break;
        }
        {
            float _e61 = c_7;
            c_7 = _e61 - 0.0001;
            uint _e64 = tries;
            tries = _e64 + 1u;
            uint _e67 = tries;
            if (_e67 > 16u) {
                return metal::float2(0.0, 0.0);
            }
        }
    }
    float _e73 = c_7;
    float w_13 = metal::min(metal::min(_e73, 1.0) - 0.001, 0.9999);
    if (!((w_13 > 0.0))) {
        return metal::float2(0.0, 0.0);
    }
    return metal::float2(w_13 * w_13, 1.0 / metal::sqrt(1.0 - (w_13 * w_13)));
}

bool lobe_cone_meets(
    metal::float3 v_9,
    float d2_10,
    float extent,
    metal::float3 axis_5,
    metal::float2 cone
) {
    bool local_32 = {};
    float k_2 = ((extent * LOBE_CONE_PAD) + 0.000000000000000000000000000001) * cone.y;
    float vd_1 = -(metal::dot(v_9, axis_5));
    float a_14 = vd_1 + k_2;
    float b_8 = d2_10 + (k_2 * ((2.0 * vd_1) + k_2));
    if (a_14 >= 0.0) {
        local_32 = (a_14 * a_14) >= (b_8 * cone.x);
    } else {
        local_32 = false;
    }
    bool _e28 = local_32;
    return _e28;
}

bool bsh_lobe_admits(
    metal::float3 c_8,
    float radius_7,
    float extent_1,
    metal::float3 x_13,
    float w_9,
    metal::float3 axis_6,
    metal::float2 cone_1
) {
    bool local_33 = {};
    bool local_34 = {};
    bool local_35 = {};
    metal::float3 v_18 = x_13 - c_8;
    float d2_14 = metal::dot(v_18, v_18);
    float f_2 = radius_7 * (w_9 * 1.0001);
    if (d2_14 <= (f_2 * f_2)) {
        if (!((cone_1.y == 0.0))) {
            local_34 = d2_14 <= (radius_7 * radius_7);
        } else {
            local_34 = true;
        }
        bool _e25 = local_34;
        if (!(_e25)) {
            bool _e29 = lobe_cone_meets(v_18, d2_14, extent_1, axis_6, cone_1);
            local_35 = _e29;
        } else {
            local_35 = true;
        }
        bool _e31 = local_35;
        local_33 = _e31;
    } else {
        local_33 = false;
    }
    bool _e33 = local_33;
    return _e33;
}

uint grid_word(
    uint i_4,
    device type_13 const& grid,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = grid[i_4];
    return _e3;
}

GridFrame grid_frame(
    uint h_1,
    device type_13 const& grid,
    constant _mslBufferSizes& _buffer_sizes
) {
    GridFrame f_1 = {};
    uint _e3 = grid_word(h_1, grid, _buffer_sizes);
    uint _e7 = grid_word(h_1 + 1u, grid, _buffer_sizes);
    uint _e11 = grid_word(h_1 + 2u, grid, _buffer_sizes);
    f_1.lo = metal::float3(as_type<float>(_e3), as_type<float>(_e7), as_type<float>(_e11));
    uint _e17 = grid_word(h_1 + 3u, grid, _buffer_sizes);
    f_1.nx = _e17;
    uint _e21 = grid_word(h_1 + 4u, grid, _buffer_sizes);
    uint _e25 = grid_word(h_1 + 5u, grid, _buffer_sizes);
    uint _e29 = grid_word(h_1 + 6u, grid, _buffer_sizes);
    f_1.hi = metal::float3(as_type<float>(_e21), as_type<float>(_e25), as_type<float>(_e29));
    uint _e35 = grid_word(h_1 + 7u, grid, _buffer_sizes);
    f_1.ny = _e35;
    uint _e39 = grid_word(h_1 + 8u, grid, _buffer_sizes);
    uint _e43 = grid_word(h_1 + 9u, grid, _buffer_sizes);
    uint _e47 = grid_word(h_1 + 10u, grid, _buffer_sizes);
    f_1.inv = metal::float3(as_type<float>(_e39), as_type<float>(_e43), as_type<float>(_e47));
    uint _e53 = grid_word(h_1 + 11u, grid, _buffer_sizes);
    f_1.nz = _e53;
    GridFrame _e54 = f_1;
    return _e54;
}

float grid_reach(
    uint h_2,
    device type_13 const& grid,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = grid_word(h_2 + 12u, grid, _buffer_sizes);
    return as_type<float>(_e3);
}

BshCursor bsh_cursor(
    metal::float3 x_14,
    metal::float3 r_8,
    metal::float4 rl_6,
    device type_11 const& bsh_nodes,
    device type_13 const& grid,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshCursor c_9 = {};
    uint h_3 = 0u;
    uint g = 1u;
    bool local_36 = {};
    bool local_37 = {};
    bool local_38 = {};
    c_9.i = 0u;
    c_9.end = 0u;
    uint _e10 = bsh_first(BSH, bsh_nodes, _buffer_sizes);
    c_9.next = _e10;
    c_9.cone = metal::float2(0.0);
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e34 = g;
            g = _e34 + 1u;
        }
        loop_init_1 = false;
        uint _e18 = g;
        if (_e18 < GRIDS_MAX) {
            uint _e24 = h_3;
            float _e25 = grid_reach(_e24, grid, _buffer_sizes);
            local_36 = rl_6.w > _e25;
        } else {
            local_36 = false;
        }
        bool _e28 = local_36;
        if (_e28) {
        } else {
            break;
        }
        {
            uint _e29 = h_3;
            uint _e32 = grid_word(_e29 + 14u, grid, _buffer_sizes);
            h_3 = _e32;
        }
    }
    uint _e36 = h_3;
    GridFrame _e37 = grid_frame(_e36, grid, _buffer_sizes);
    uint _e39 = c_9.next;
    if (_e39 != BSH_NONE) {
        local_37 = _e37.nx > 0u;
    } else {
        local_37 = false;
    }
    bool _e48 = local_37;
    if (_e48) {
        uint _e52 = h_3;
        float _e53 = grid_reach(_e52, grid, _buffer_sizes);
        local_38 = rl_6.w <= _e53;
    } else {
        local_38 = false;
    }
    bool _e56 = local_38;
    if (_e56) {
        uint _e57 = bsh_grid_cell(_e37, x_14);
        if (_e57 != BSH_NONE) {
            uint _e62 = h_3;
            uint _e67 = grid[(_e62 + GRID_HEADER) + _e57];
            c_9.i = _e67;
            uint _e70 = h_3;
            uint _e77 = grid[((_e70 + GRID_HEADER) + _e57) + 1u];
            c_9.end = _e77;
            uint _e82 = bsh_nodes[0].next;
            c_9.next = _e82;
            metal::float2 _e84 = lobe_cone(r_8, rl_6);
            c_9.cone = _e84;
        }
    }
    BshCursor _e85 = c_9;
    return _e85;
}

uint bsh_cursor_next(
    thread BshCursor& c_10,
    metal::float3 x_15,
    metal::float3 r_9,
    metal::float4 rl_7,
    device type_11 const& bsh_nodes,
    device type_13 const& grid_entries,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_39 = {};
    bool local_40 = {};
    uint2 loop_bound_6 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        uint _e5 = c_10.i;
        uint _e7 = c_10.end;
        if (_e5 < _e7) {
        } else {
            break;
        }
        {
            uint _e11 = c_10.i;
            uint b_9 = grid_entries[_e11];
            uint _e15 = c_10.i;
            c_10.i = _e15 + 1u;
            BshNode n_25 = bsh_nodes[b_9];
            if (!((rl_7.w <= 1.0))) {
                metal::float2 _e32 = c_10.cone;
                bool _e33 = bsh_lobe_admits(n_25.center, n_25.radius, n_25.extent, x_15, rl_7.w, r_9, _e32);
                local_39 = _e33;
            } else {
                local_39 = true;
            }
            bool _e35 = local_39;
            if (_e35) {
                bool _e38 = bsh_reaches(n_25, x_15, r_9, rl_7);
                local_40 = _e38;
            } else {
                local_40 = false;
            }
            bool _e40 = local_40;
            if (_e40) {
                return b_9;
            }
        }
    }
    uint _e43 = c_10.next;
    uint _e44 = bsh_next_leaf_lobe(BSH, _e43, x_15, r_9, rl_7, bsh_nodes, _buffer_sizes);
    if (_e44 != BSH_NONE) {
        uint _e51 = bsh_nodes[_e44].next;
        c_10.next = _e51;
    }
    return _e44;
}

float next_threshold(
    float sum_1,
    thread uint& h_4
) {
    uint _e2 = h_4;
    uint _e3 = pcg_hash(_e2);
    h_4 = _e3;
    uint _e4 = h_4;
    float _e5 = xi_from_bits(_e4);
    float _e6 = weighted_threshold(sum_1, _e5);
    return _e6;
}

Connection connect_record(
    GpuLight l_8,
    metal::float3 x_16,
    metal::float3 n_15,
    metal::float3 ng_1,
    float r2_3,
    float rt2_6,
    float w_res,
    float u1_2,
    float u2_2,
    float eps,
    bool trace_1,
    device type_4 const& slc_table,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection c_11 = {};
    bool local_41 = {};
    bool local_42 = {};
    c_11.e = metal::float3(0.0);
    metal::float3 _e16 = light_point(l_8, u1_2, u2_2);
    c_11.y = _e16;
    metal::float3 _e19 = c_11.y;
    float _e20 = connection_cosine(x_16, _e19, n_15, ng_1, r2_3);
    c_11.cos_x = _e20;
    float _e22 = c_11.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            metal::float3 _e33 = c_11.y;
            bool _e34 = occluded(x_16 + (ng_1 * eps), _e33, geo_nodes, geo_tris, _buffer_sizes);
            local_42 = _e34;
        } else {
            local_42 = false;
        }
        bool _e36 = local_42;
        local_41 = _e36;
    } else {
        local_41 = true;
    }
    bool _e38 = local_41;
    if (_e38) {
        Connection _e39 = c_11;
        return _e39;
    }
    metal::float3 _e41 = c_11.y;
    metal::float3 v_19 = x_16 - _e41;
    float d2_15 = metal::dot(v_19, v_19);
    metal::float3 _e48 = light_intensity(l_8, v_19 / metal::float3(metal::sqrt(d2_15)), slc_table, _buffer_sizes);
    float _e50 = c_11.cos_x;
    float _e51 = connection_factor(_e50, d2_15, rt2_6, w_res);
    c_11.e = _e48 * _e51;
    Connection _e53 = c_11;
    return _e53;
}

Connection connect_traced(
    uint li,
    metal::float3 x_17,
    metal::float3 n_16,
    metal::float3 ng_2,
    float s_1,
    float w_res_1,
    float u1_3,
    float u2_3,
    float eps_1,
    bool trace_2,
    device type_4 const& slc_table,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_16 const& lights,
    device type_4 const& r2_4,
    device type_4 const& rt2_7,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight _e12 = lights[li];
    float _e15 = r2_4[li];
    float _e19 = rt2_7[li];
    Connection _e21 = connect_record(_e12, x_17, n_16, ng_2, s_1 * _e15, s_1 * _e19, w_res_1, u1_3, u2_3, eps_1, trace_2, slc_table, geo_nodes, geo_tris, _buffer_sizes);
    return _e21;
}

Connection connect(
    uint li_1,
    metal::float3 x_18,
    metal::float3 n_17,
    metal::float3 ng_3,
    float s_2,
    float w_res_2,
    float u1_4,
    float u2_4,
    float eps_2,
    device type_4 const& slc_table,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_16 const& lights,
    device type_4 const& r2_4,
    device type_4 const& rt2_7,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection _e10 = connect_traced(li_1, x_18, n_17, ng_3, s_2, w_res_2, u1_4, u2_4, eps_2, true, slc_table, geo_nodes, geo_tris, lights, r2_4, rt2_7, _buffer_sizes);
    return _e10;
}

float mis_weight(
    float pdf_a_1,
    float pdf_b_1
) {
    float _e2 = mis_power(pdf_a_1, pdf_b_1);
    return _e2;
}

float light_range_scale(
    uint li_2,
    metal::float3 x_19,
    metal::float3 r_10,
    metal::float4 rl_8,
    device type_17 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_17 = light_cones[li_2];
    float _e9 = range_scale_toward(rl_8, c_17.center, c_17.radius, x_19, r_10);
    return _e9;
}

float light_weight(
    uint li_3,
    metal::float3 x_20,
    metal::float3 n_18,
    metal::float3 r_11,
    metal::float4 lobe_7,
    metal::float4 rl_9,
    device type_4 const& rt2_7,
    device type_17 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_18 = light_cones[li_3];
    float _e15 = light_range_scale(li_3, x_20, r_11, rl_9, light_cones, _buffer_sizes);
    float _e18 = rt2_7[li_3];
    float _e20 = cone_weight(c_18.center, c_18.radius, c_18.phi, c_18.axis, c_18.cos_o, c_18.cos_e, _e15 * _e18, x_20, n_18, r_11, lobe_7);
    return _e20;
}

float select_pdf(
    uint li_4,
    metal::float3 x_21,
    metal::float3 n_19,
    metal::float3 r_12,
    metal::float4 lobe_8,
    metal::float4 rl_10,
    uint nee,
    bool in_range_1,
    device type_4 const& rt2_7,
    device type_17 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e8 = light_weight(li_4, x_21, n_19, r_12, lobe_8, rl_10, rt2_7, light_cones, _buffer_sizes);
    float _e11 = weighted_select_pdf(_e8, as_type<float>(nee), in_range_1, K);
    return _e11;
}

float light_pdf_selected(
    uint li_5,
    metal::float3 x_22,
    metal::float3 r_13,
    metal::float4 rl_11,
    metal::float3 y_2,
    float sel,
    device type_16 const& lights,
    device type_4 const& rt2_7,
    device type_17 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight l_9 = lights[li_5];
    metal::float3 v_20 = x_22 - y_2;
    float d2_16 = metal::dot(v_20, v_20);
    metal::float3 _e11 = light_normal(l_9);
    float cos_y_1 = (d2_16 > 0.0) ? metal::dot(_e11, v_20 / metal::float3(metal::sqrt(d2_16))) : 0.0;
    float _e20 = light_range_scale(li_5, x_22, r_13, rl_11, light_cones, _buffer_sizes);
    float _e23 = rt2_7[li_5];
    float _e25 = light_area(l_9);
    float _e26 = light_strategy_pdf(sel, _e20 * _e23, d2_16, _e25, cos_y_1);
    return _e26;
}

float light_pdf(
    uint li_6,
    metal::float3 x_23,
    metal::float3 n_20,
    metal::float3 r_14,
    metal::float4 lobe_9,
    metal::float4 rl_12,
    metal::float3 y_3,
    uint nee_1,
    bool in_range_2,
    device type_16 const& lights,
    device type_4 const& rt2_7,
    device type_17 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e9 = select_pdf(li_6, x_23, n_20, r_14, lobe_9, rl_12, nee_1, in_range_2, rt2_7, light_cones, _buffer_sizes);
    float _e10 = light_pdf_selected(li_6, x_23, r_14, rl_12, y_3, _e9, lights, rt2_7, light_cones, _buffer_sizes);
    return _e10;
}

WeightedPicks weighted_picks(
    uint h_5
) {
    WeightedPicks picks = {};
    picks.w_sum = 0.0;
    picks.n = 0u;
    picks.h = h_5;
    WeightedPicks _e7 = picks;
    return _e7;
}

void weighted_offer(
    thread WeightedPicks& picks_1,
    uint li_7,
    float w_10
) {
    uint h_6 = {};
    uint s_3 = 0u;
    uint _e4 = picks_1.n;
    picks_1.n = _e4 + 1u;
    if (w_10 > 0.0) {
        float _e10 = picks_1.w_sum;
        picks_1.w_sum = _e10 + w_10;
        uint _e13 = picks_1.h;
        h_6 = _e13;
        uint2 loop_bound_7 = uint2(4294967295u);
        bool loop_init_2 = true;
        while(true) {
            if (metal::all(loop_bound_7 == uint2(0u))) { break; }
            loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
            if (!loop_init_2) {
                uint _e40 = s_3;
                s_3 = _e40 + 1u;
            }
            loop_init_2 = false;
            uint _e17 = s_3;
            if (_e17 < K) {
            } else {
                break;
            }
            {
                float _e21 = picks_1.w_sum;
                uint _e23 = s_3;
                float _e25 = picks_1.threshold.inner[_e23];
                if (_e21 > _e25) {
                    uint _e28 = s_3;
                    picks_1.light.inner[_e28] = li_7;
                    uint _e31 = s_3;
                    picks_1.w.inner[_e31] = w_10;
                    uint _e34 = s_3;
                    float _e37 = picks_1.w_sum;
                    float _e38 = next_threshold(_e37, h_6);
                    picks_1.threshold.inner[_e34] = _e38;
                }
            }
        }
        uint _e43 = h_6;
        picks_1.h = _e43;
        return;
    } else {
        return;
    }
}

WeightedPicks bsh_weighted_collect(
    metal::float3 x_24,
    metal::float3 n_21,
    metal::float3 r_15,
    metal::float4 lobe_10,
    metal::float4 rl_13,
    uint h0_,
    device type_11 const& bsh_nodes,
    device type_13 const& grid,
    device type_13 const& grid_entries,
    device type_4 const& rt2_7,
    device type_17 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    WeightedPicks picks_2 = {};
    BshCursor cur = {};
    uint b_6 = {};
    WeightedPicks _e6 = weighted_picks(h0_);
    picks_2 = _e6;
    BshCursor _e8 = bsh_cursor(x_24, r_15, rl_13, bsh_nodes, grid, _buffer_sizes);
    cur = _e8;
    uint _e10 = bsh_cursor_next(cur, x_24, r_15, rl_13, bsh_nodes, grid_entries, _buffer_sizes);
    b_6 = _e10;
    uint2 loop_bound_8 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e21 = bsh_cursor_next(cur, x_24, r_15, rl_13, bsh_nodes, grid_entries, _buffer_sizes);
            b_6 = _e21;
        }
        loop_init_3 = false;
        uint _e12 = b_6;
        if (_e12 != BSH_NONE) {
        } else {
            break;
        }
        {
            uint _e16 = b_6;
            uint li_9 = bsh_nodes[_e16].light;
            float _e20 = light_weight(li_9, x_24, n_21, r_15, lobe_10, rl_13, rt2_7, light_cones, _buffer_sizes);
            weighted_offer(picks_2, li_9, _e20);
        }
    }
    WeightedPicks _e22 = picks_2;
    return _e22;
}

metal::float3 shade_pick(
    uint li_8,
    metal::float3 x_25,
    metal::float3 n_22,
    metal::float3 ng_4,
    GpuMaterial m,
    metal::float3 wo_1,
    metal::float3 r_16,
    metal::float4 lobe_11,
    metal::float4 rl_14,
    float w_11,
    uint nee_2,
    float u1_5,
    float u2_5,
    device type_4 const& slc_table,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_16 const& lights,
    device type_4 const& r2_4,
    device type_4 const& rt2_7,
    device type_17 const& light_cones,
    constant ShadeParams& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    float mis = 1.0;
    float _e13 = light_range_scale(li_8, x_25, r_16, rl_14, light_cones, _buffer_sizes);
    float _e16 = params.eps;
    Connection _e17 = connect(li_8, x_25, n_22, ng_4, _e13, w_11, u1_5, u2_5, _e16, slc_table, geo_nodes, geo_tris, lights, r2_4, rt2_7, _buffer_sizes);
    if (_e17.cos_x <= 0.0) {
        return metal::float3(0.0);
    }
    metal::float3 l_10 = metal::normalize(_e17.y - x_25);
    GpuLight _e30 = lights[li_8];
    float _e31 = light_area(_e30);
    if (_e31 > 0.0) {
        float _e36 = light_pdf(li_8, x_25, n_22, r_16, lobe_11, rl_14, _e17.y, nee_2, true, lights, rt2_7, light_cones, _buffer_sizes);
        float _e38 = specular_probability(lobe_11);
        float _e39 = bsdf_pdf(n_22, wo_1, l_10, m.alpha, _e38);
        float _e40 = mis_weight(_e36, _e39);
        mis = _e40;
    }
    metal::float3 _e46 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, n_22, wo_1, l_10);
    float _e49 = mis;
    return (_e46 * _e17.e) * _e49;
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, device type_4 const& slc_table [[user(fake0)]]
, device type_7 const& geo_nodes [[user(fake0)]]
, device type_8 const& geo_tris [[user(fake0)]]
, device type_11 const& bsh_nodes [[user(fake0)]]
, device type_13 const& grid [[user(fake0)]]
, device type_13 const& grid_entries [[user(fake0)]]
, device type_16 const& lights [[user(fake0)]]
, device type_4 const& r2_4 [[user(fake0)]]
, device type_4 const& rt2_7 [[user(fake0)]]
, device type_17 const& light_cones [[user(fake0)]]
, constant ShadeParams& params [[user(fake0)]]
, device type_20 const& vertices [[user(fake0)]]
, device type_21 const& materials [[user(fake0)]]
, device type_22& radiance [[user(fake0)]]
, device type_13& candidates [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint h = {};
    metal::float3 sum = metal::float3(0.0);
    uint s = 0u;
    uint i_5 = gid.x;
    uint _e4 = params.point_count;
    if (i_5 >= _e4) {
        return;
    }
    GpuPathVertex vtx = vertices[i_5];
    if (vtx.alive == 0u) {
        candidates[i_5] = 0u;
        return;
    }
    metal::float3 x_26 = vtx.position;
    metal::float3 n_26 = vtx.normal;
    metal::float3 ng_5 = vtx.gnormal;
    GpuMaterial m_2 = materials[vtx.material];
    metal::float3 wo_2 = vtx.wo;
    metal::float3 _e23 = mirror_dir(n_26, wo_2);
    metal::float4 _e30 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, metal::dot(n_26, wo_2));
    metal::float4 _e31 = range_lobe(_e30);
    uint _e34 = params.seed;
    uint _e37 = params.frame;
    uint _e38 = point_stream(_e34, i_5, _e37);
    uint _e39 = pick_stream(_e38);
    h = _e39;
    uint _e44 = h;
    WeightedPicks _e45 = bsh_weighted_collect(x_26, n_26, _e23, _e30, _e31, _e44, bsh_nodes, grid, grid_entries, rt2_7, light_cones, _buffer_sizes);
    h = _e45.h;
    float w_sum_3 = _e45.w_sum;
    candidates[i_5] = as_type<uint>(w_sum_3);
    if (w_sum_3 > 0.0) {
        uint2 loop_bound_9 = uint2(4294967295u);
        bool loop_init_4 = true;
        while(true) {
            if (metal::all(loop_bound_9 == uint2(0u))) { break; }
            loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
            if (!loop_init_4) {
                uint _e79 = s;
                s = _e79 + 1u;
            }
            loop_init_4 = false;
            uint _e55 = s;
            if (_e55 < K) {
            } else {
                break;
            }
            {
                uint _e58 = h;
                uint _e59 = pcg_hash(_e58);
                h = _e59;
                uint _e60 = h;
                float _e61 = xi_from_bits(_e60);
                uint _e62 = h;
                uint _e63 = pcg_hash(_e62);
                h = _e63;
                metal::float3 _e64 = sum;
                uint _e66 = s;
                uint _e69 = s;
                float _e72 = weighted_pick_weight(w_sum_3, _e45.w.inner[_e69], K);
                uint _e74 = h;
                float _e75 = xi_from_bits(_e74);
                metal::float3 _e76 = shade_pick(_e45.light.inner[_e66], x_26, n_26, ng_5, m_2, wo_2, _e23, _e30, _e31, _e72, as_type<uint>(w_sum_3), _e61, _e75, slc_table, geo_nodes, geo_tris, lights, r2_4, rt2_7, light_cones, params, _buffer_sizes);
                sum = _e64 + _e76;
            }
        }
    }
    metal::float3 _e82 = sum;
    metal::float3 add = vtx.weight * _e82;
    bool _e84 = finite3_(add);
    if (_e84) {
        metal::float4 _e87 = radiance[i_5];
        radiance[i_5] = _e87 + metal::float4(add, 0.0);
        return;
    } else {
        return;
    }
}
