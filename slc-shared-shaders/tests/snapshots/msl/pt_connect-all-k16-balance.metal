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
    uint inner[16];
};
struct Picks {
    type_10 light;
    uint n;
};
typedef uint BshNodes;
typedef BshNode type_11[1];
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
typedef GpuLight type_15[1];
typedef GpuLightCone type_16[1];
typedef uint BvhNodes;
typedef GpuPathVertex type_17[1];
typedef GpuMaterial type_18[1];
typedef metal::float4 type_19[1];
typedef uint type_20[1];
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
constant uint K = 16u;
constant BshNodes BSH = 0u;
constant uint BSH_TILE_DEPTH = 8u;
constant uint BSH_TILE_SUBTREES = 256u;
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
    metal::float3 v_8 = x_2 - c;
    return metal::dot(v_8, v_8) <= (r * r);
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
    metal::float3 v_9 = x_3 - y;
    float d2_9 = metal::dot(v_9, v_9);
    bool _e7 = slc_keep(r2_1, d2_9);
    if (!(!(_e7))) {
        local = !((d2_9 > 0.0));
    } else {
        local = true;
    }
    bool _e16 = local;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_8 = v_9 / metal::float3(metal::sqrt(d2_9));
    float cos_x_1 = -(metal::dot(n, w_8));
    if (!(!((cos_x_1 > 0.0)))) {
        local_1 = !((metal::dot(ng, w_8) < 0.0));
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
    float c_10 = metal::abs(cos_light);
    if (c_10 <= 0.0) {
        return 0.0;
    }
    return (pdf_area * d2_5) / c_10;
}

float atan_portable(
    float x_4
) {
    float base = 0.0;
    float t = {};
    float a_10 = metal::abs(x_4);
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
    float z = _e18 * _e19;
    float _e21 = base;
    float _e33 = t;
    float _e35 = t;
    float r_13 = _e21 + (((((((((0.080537446 * z) - 0.13877685) * z) + 0.19977711) * z) - 0.3333295) * z) * _e33) + _e35);
    return (x_4 < 0.0) ? -(r_13) : r_13;
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
    uint h0_ = v0_ + _e5;
    uint c0_ = h0_ + _e9;
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
    float _e27 = at(tab_2, h0_, slc_table, _buffer_sizes);
    float _e31 = at(tab_2, (h0_ + _e9) - 1u, slc_table, _buffer_sizes);
    float _e32 = ies_fold_c(c_3, _e27, _e31);
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
    float _e58 = at(tab_2, (c0_ + (_e34 * _e5)) + _e33, slc_table, _buffer_sizes);
    float _e65 = at(tab_2, (c0_ + (_e34 * _e5)) + iv1_, slc_table, _buffer_sizes);
    float a_11 = (_e58 * (1.0 - _e49)) + (_e65 * _e49);
    float _e71 = at(tab_2, (c0_ + (ih1_ * _e5)) + _e33, slc_table, _buffer_sizes);
    float _e78 = at(tab_2, (c0_ + (ih1_ * _e5)) + iv1_, slc_table, _buffer_sizes);
    float b_7 = (_e71 * (1.0 - _e49)) + (_e78 * _e49);
    return (a_11 * (1.0 - _e54)) + (b_7 * _e54);
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

float reservoir_select_pdf(
    uint seen,
    bool in_range,
    uint k_2
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
    float _e15 = reservoir_weight(_e12 + 1u, k_2);
    return 1.0 / _e15;
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

float light_strategy_pdf(
    float select,
    float rt2_3,
    float d2_6,
    float area_1,
    float cos_y
) {
    bool local_4 = {};
    bool local_5 = {};
    if (!((d2_6 <= 0.0))) {
        local_4 = area_1 <= 0.0;
    } else {
        local_4 = true;
    }
    bool _e13 = local_4;
    if (!(_e13)) {
        local_5 = cos_y <= 0.0;
    } else {
        local_5 = true;
    }
    bool _e20 = local_5;
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
    metal::float3 n_8
) {
    float s_4 = (n_8.z >= 0.0) ? 1.0 : -1.0;
    float a_12 = -1.0 / (s_4 + n_8.z);
    return metal::float3(1.0 + (((s_4 * n_8.x) * n_8.x) * a_12), ((s_4 * n_8.x) * n_8.y) * a_12, -(s_4) * n_8.x);
}

metal::float3 onb_bitangent(
    metal::float3 n_9
) {
    float s_5 = (n_9.z >= 0.0) ? 1.0 : -1.0;
    float a_13 = -1.0 / (s_5 + n_9.z);
    return metal::float3((n_9.x * n_9.y) * a_13, s_5 + ((n_9.y * n_9.y) * a_13), -(n_9.y));
}

metal::float3 onb_to_local(
    metal::float3 n_10,
    metal::float3 w_5
) {
    metal::float3 _e2 = onb_tangent(n_10);
    metal::float3 _e4 = onb_bitangent(n_10);
    return metal::float3(metal::dot(w_5, _e2), metal::dot(w_5, _e4), metal::dot(w_5, n_10));
}

float ggx_d(
    float cos_h,
    float sin2_h,
    float alpha
) {
    if (cos_h <= 0.0) {
        return 0.0;
    }
    float a2_ = alpha * alpha;
    float t_2 = ((cos_h * cos_h) * a2_) + sin2_h;
    return (a2_ * INV_PI) / (t_2 * t_2);
}

float smith_root(
    float cos,
    float alpha_1
) {
    float a2_1 = alpha_1 * alpha_1;
    return metal::sqrt(((cos * cos) * (1.0 - a2_1)) + a2_1);
}

float smith_visibility(
    float n_l,
    float n_v,
    float alpha_2
) {
    bool local_6 = {};
    if (!((n_l <= 0.0))) {
        local_6 = n_v <= 0.0;
    } else {
        local_6 = true;
    }
    bool _e11 = local_6;
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
    float c_12 = metal::saturate(1.0 - v_h);
    float c2_ = c_12 * c_12;
    return f0_ + ((metal::float3(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_12));
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
    metal::float3 h_3 = v + l;
    float len2_ = metal::dot(h_3, h_3);
    if (len2_ <= 0.0) {
        return 0.0;
    }
    return metal::saturate(metal::dot(v, h_3) / metal::sqrt(len2_));
}

metal::float3 specular_brdf(
    metal::float3 base_6,
    float metallic_2,
    metal::float3 f0_d_2,
    float f90_d_2,
    float alpha_3,
    metal::float3 n_11,
    metal::float3 v_1,
    metal::float3 l_1
) {
    bool local_7 = {};
    float n_l_1 = metal::dot(n_11, l_1);
    float n_v_2 = metal::dot(n_11, v_1);
    if (!((n_l_1 <= 0.0))) {
        local_7 = n_v_2 <= 0.0;
    } else {
        local_7 = true;
    }
    bool _e18 = local_7;
    if (_e18) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    metal::float3 hs = v_1 + l_1;
    float inv = 1.0 / metal::sqrt(metal::dot(hs, hs));
    metal::float3 h_4 = hs * inv;
    metal::float3 c_13 = metal::cross(n_11, h_4);
    float _e32 = ggx_d(metal::dot(n_11, h_4), metal::dot(c_13, c_13), alpha_3);
    metal::float3 _e34 = specular_fresnel(base_6, metallic_2, f0_d_2, f90_d_2, metal::dot(v_1, h_4));
    float _e35 = smith_visibility(n_l_1, n_v_2, alpha_3);
    return _e34 * (_e32 * _e35);
}

metal::float3 brdf_eval(
    metal::float3 base_7,
    float metallic_3,
    metal::float3 f0_d_3,
    float f90_d_3,
    float alpha_4,
    metal::float3 n_12,
    metal::float3 v_2,
    metal::float3 l_2
) {
    if (metal::dot(n_12, l_2) <= 0.0) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    float _e15 = half_cosine(v_2, l_2);
    metal::float3 _e16 = diffuse_brdf(base_7, metallic_3, f0_d_3, f90_d_3, _e15);
    metal::float3 _e17 = specular_brdf(base_7, metallic_3, f0_d_3, f90_d_3, alpha_4, n_12, v_2, l_2);
    return _e16 + _e17;
}

bool has_specular(
    float metallic_4,
    metal::float3 f0_d_4,
    float f90_d_4
) {
    bool local_8 = {};
    bool local_9 = {};
    if (!((metallic_4 > 0.0))) {
        local_8 = f90_d_4 > 0.0;
    } else {
        local_8 = true;
    }
    bool _e11 = local_8;
    if (!(_e11)) {
        local_9 = metal::max(metal::max(f0_d_4.x, f0_d_4.y), f0_d_4.z) > 0.0;
    } else {
        local_9 = true;
    }
    bool _e23 = local_9;
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
    bool local_10 = {};
    metal::float3 _e10 = fresnel_schlick(f0_d_5, f90_d_5, n_v_1);
    float _e16 = channel_mean(((metal::float3(1.0, 1.0, 1.0) - _e10) * base_8) * (1.0 - metallic_5));
    if (!((n_v_1 <= 0.0))) {
        bool _e22 = has_specular(metallic_5, f0_d_5, f90_d_5);
        local_10 = !(_e22);
    } else {
        local_10 = true;
    }
    bool _e25 = local_10;
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
    metal::float3 n_13,
    metal::float3 v_3
) {
    return (n_13 * (2.0 * metal::dot(n_13, v_3))) - v_3;
}

float bounded_vndf_k(
    metal::float3 wi,
    float alpha_6
) {
    float a_14 = metal::saturate(alpha_6);
    float s_6 = 1.0 + metal::sqrt((wi.x * wi.x) + (wi.y * wi.y));
    float a2_2 = a_14 * a_14;
    float s2_ = s_6 * s_6;
    return ((1.0 - a2_2) * s2_) / (s2_ + ((a2_2 * wi.z) * wi.z));
}

float ggx_vndf_pdf(
    metal::float3 wi_1,
    metal::float3 wo,
    float alpha_7
) {
    bool local_11 = {};
    if (!((wi_1.z <= 0.0))) {
        local_11 = wo.z <= 0.0;
    } else {
        local_11 = true;
    }
    bool _e13 = local_11;
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
    metal::float3 n_14,
    metal::float3 v_4,
    metal::float3 l_3,
    float alpha_8,
    float p_spec
) {
    float _e6 = cosine_pdf(metal::dot(n_14, l_3));
    if (p_spec <= 0.0) {
        return _e6;
    }
    metal::float3 _e9 = onb_to_local(n_14, v_4);
    metal::float3 _e10 = onb_to_local(n_14, l_3);
    float _e11 = ggx_vndf_pdf(_e9, _e10, alpha_8);
    return (p_spec * _e11) + ((1.0 - p_spec) * _e6);
}

float cone_cos_of(
    metal::float3 v_5,
    float d2_7,
    float a_5,
    metal::float3 d
) {
    bool local_12 = {};
    bool local_13 = {};
    float vd = metal::dot(v_5, d);
    float h2_ = d2_7 - (a_5 * a_5);
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
    metal::float3 c_14 = metal::cross(v_5, d);
    return metal::min(((vd * metal::sqrt(h2_)) + (metal::sqrt(metal::dot(c_14, c_14)) * a_5)) / d2_7, 1.0);
}

float cone_cos_toward(
    metal::float3 center,
    float radius,
    metal::float3 p,
    metal::float3 d_1
) {
    metal::float3 v_10 = center - p;
    float _e6 = cone_cos_of(v_10, metal::dot(v_10, v_10), radius, d_1);
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
    metal::float3 center_1,
    float radius_1,
    metal::float3 p_1,
    metal::float3 r_1
) {
    if (rl_1.w <= 1.0) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_1);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
}

bool finite3_(
    metal::float3 v_6
) {
    bool local_14 = {};
    bool local_15 = {};
    if (metal::abs(v_6.x) <= F32_MAX) {
        local_14 = metal::abs(v_6.y) <= F32_MAX;
    } else {
        local_14 = false;
    }
    bool _e12 = local_14;
    if (_e12) {
        local_15 = metal::abs(v_6.z) <= F32_MAX;
    } else {
        local_15 = false;
    }
    bool _e20 = local_15;
    return _e20;
}

float shadow_margin(
    float len
) {
    return 0.0001 * len;
}

float ray_inverse(
    float x_8
) {
    return 1.0 / ((metal::abs(x_8) < 0.000000000000000000000000000001) ? 0.000000000000000000000000000001 : x_8);
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
    metal::float3 a_6,
    metal::float3 b_4,
    metal::float3 c_5
) {
    bool local_16 = {};
    metal::float3 n_21 = metal::cross(b_4 - a_6, c_5 - a_6);
    float l2_ = metal::dot(n_21, n_21);
    if (!(!((l2_ > 0.0)))) {
        local_16 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_16 = true;
    }
    bool _e17 = local_16;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_21 / metal::float3(metal::sqrt(l2_));
}

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_3,
    metal::float3 a_7,
    metal::float3 b_5,
    metal::float3 c_6,
    float t_min,
    float t_max_1
) {
    bool local_17 = {};
    bool local_18 = {};
    bool local_19 = {};
    metal::float3 e1_ = b_5 - a_7;
    metal::float3 e2_ = c_6 - a_7;
    metal::float3 p_2 = metal::cross(d_3, e2_);
    float det = metal::dot(e1_, p_2);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv_1 = 1.0 / det;
    metal::float3 s_7 = o_1 - a_7;
    float u_2 = metal::dot(s_7, p_2) * inv_1;
    if (!((u_2 < 0.0))) {
        local_17 = u_2 > 1.0;
    } else {
        local_17 = true;
    }
    bool _e28 = local_17;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q = metal::cross(s_7, e1_);
    float v_11 = metal::dot(d_3, q) * inv_1;
    if (!((v_11 < 0.0))) {
        local_18 = (u_2 + v_11) > 1.0;
    } else {
        local_18 = true;
    }
    bool _e42 = local_18;
    if (_e42) {
        return -1.0;
    }
    float t_5 = metal::dot(e2_, q) * inv_1;
    if (t_5 > t_min) {
        local_19 = t_5 < t_max_1;
    } else {
        local_19 = false;
    }
    bool _e51 = local_19;
    if (_e51) {
        return t_5;
    }
    return -1.0;
}

metal::float3 light_intensity(
    GpuLight l_4,
    metal::float3 w_6,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    switch(l_4.kind) {
        case 0u: {
            return l_4.intensity;
        }
        case 1u: {
            float _e11 = spot_falloff(metal::dot(l_4.p1_, w_6), l_4.a, l_4.b, l_4.p2_[0]);
            return l_4.intensity * _e11;
        }
        case 2u: {
            float _e18 = ies_light_candela(0u, l_4.ies_base, l_4.p1_, l_4.p2_, w_6, slc_table, _buffer_sizes);
            return l_4.intensity * _e18;
        }
        case 3u: {
            metal::float3 _e24 = triangle_normal(l_4.p0_, l_4.p1_, l_4.p2_);
            float _e26 = triangle_lobe(_e24, l_4.a, w_6);
            return l_4.intensity * _e26;
        }
        case 4u: {
            float _e30 = vpl_lobe(l_4.p1_, w_6);
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
        GpuGeoNode n_22 = geo_nodes[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_22.bmin, n_22.bmax, _e27);
        if (_e28 >= 0.0) {
            if (n_22.count > 0u) {
                i_1 = n_22.first;
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
                    if (_e36 < (n_22.first + n_22.count)) {
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
                    stack.inner[_e63] = n_22.first + 1u;
                    uint _e68 = sp;
                    sp = _e68 + 1u;
                }
                node_3 = n_22.first;
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
    metal::float3 a_8,
    metal::float3 b_6,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 dv = b_6 - a_8;
    float len_1 = metal::length(dv);
    if (len_1 <= 0.0) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    GeoHit _e12 = trace(a_8, dv / metal::float3(len_1), _e7, len_1 - _e7, true, geo_nodes, geo_tris, _buffer_sizes);
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
    float a_9,
    metal::float3 v_7,
    float d2_8,
    metal::float3 r_2,
    metal::float4 rl_2
) {
    float _e5 = cone_cos_of(v_7, d2_8, a_9, r_2);
    float _e8 = range_scale_at(rl_2, _e5 + 0.000002);
    return _e8;
}

bool bsh_reaches(
    BshNode node_4,
    metal::float3 x_9,
    metal::float3 r_3,
    metal::float4 rl_3
) {
    bool local_20 = {};
    bool local_21 = {};
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_9);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, node_4.radius * (rl_3.w * 1.0001), x_9);
        local_20 = !(_e20);
    } else {
        local_20 = true;
    }
    bool _e23 = local_20;
    if (_e23) {
        return false;
    }
    metal::float3 v_12 = x_9 - node_4.center;
    float d2_10 = metal::dot(v_12, v_12);
    float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_10 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        float _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_9, r_3);
        float _e41 = bsh_scaled_radius(node_4, metal::sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_9);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_12), d2_10, r_3, rl_3);
    float s_c = _e45 * 1.001;
    float _e50 = bsh_range_bound(node_4);
    float reach = node_4.extent + (metal::sqrt(s_c) * _e50);
    if (d2_10 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_21 = d2_10 <= (reach * reach);
    } else {
        local_21 = false;
    }
    bool _e63 = local_21;
    return _e63;
}

uint bsh_next_leaf_lobe(
    BshNodes nodes_3,
    uint start_1,
    metal::float3 x_10,
    metal::float3 r_4,
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
            bool _e11 = bsh_reaches(_e10, x_10, r_4, rl_4);
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

BshCursor bsh_cursor(
    metal::float3 x_11,
    metal::float3 r_5,
    metal::float4 rl_5,
    device type_11 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshCursor c_7 = {};
    c_7.i = 0u;
    c_7.end = 0u;
    uint _e10 = bsh_first(BSH, bsh_nodes, _buffer_sizes);
    c_7.next = _e10;
    c_7.cone = metal::float2(0.0);
    BshCursor _e14 = c_7;
    return _e14;
}

uint bsh_cursor_next(
    thread BshCursor& c_8,
    metal::float3 x_12,
    metal::float3 r_6,
    metal::float4 rl_6,
    device type_11 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e6 = c_8.next;
    uint _e7 = bsh_next_leaf_lobe(BSH, _e6, x_12, r_6, rl_6, bsh_nodes, _buffer_sizes);
    if (_e7 != BSH_NONE) {
        uint _e14 = bsh_nodes[_e7].next;
        c_8.next = _e14;
    }
    return _e7;
}

void reservoir_offer(
    thread Picks& picks,
    thread uint& h_1,
    uint light
) {
    uint _e4 = picks.n;
    bool _e5 = reservoir_takes(_e4);
    if (_e5) {
        uint _e7 = picks.n;
        picks.n = _e7 + 1u;
        uint _e10 = h_1;
        uint _e11 = pcg_hash(_e10);
        h_1 = _e11;
        uint hi_4 = h_1;
        uint _e13 = h_1;
        uint _e14 = pcg_hash(_e13);
        h_1 = _e14;
        uint _e16 = picks.n;
        uint _e18 = h_1;
        uint _e19 = reservoir_slot(_e16, K, hi_4, _e18);
        if (_e19 < K) {
            picks.light.inner[_e19] = light;
            return;
        } else {
            return;
        }
    } else {
        return;
    }
}

Picks bsh_collect(
    metal::float3 x_13,
    metal::float3 r_7,
    metal::float4 rl_7,
    uint seed_1,
    device type_11 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Picks picks_1 = {};
    uint h_2 = {};
    BshCursor cur = {};
    uint i_4 = {};
    picks_1.n = 0u;
    h_2 = seed_1;
    BshCursor _e8 = bsh_cursor(x_13, r_7, rl_7, bsh_nodes, _buffer_sizes);
    cur = _e8;
    uint _e10 = bsh_cursor_next(cur, x_13, r_7, rl_7, bsh_nodes, _buffer_sizes);
    i_4 = _e10;
    uint2 loop_bound_4 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e20 = bsh_cursor_next(cur, x_13, r_7, rl_7, bsh_nodes, _buffer_sizes);
            i_4 = _e20;
        }
        loop_init_1 = false;
        uint _e12 = i_4;
        if (_e12 != BSH_NONE) {
        } else {
            break;
        }
        {
            uint _e16 = i_4;
            uint _e19 = bsh_nodes[_e16].light;
            reservoir_offer(picks_1, h_2, _e19);
        }
    }
    Picks _e21 = picks_1;
    return _e21;
}

Connection connect_record(
    GpuLight l_8,
    metal::float3 x_14,
    metal::float3 n_15,
    metal::float3 ng_1,
    float r2_2,
    float rt2_4,
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
    Connection c_9 = {};
    bool local_22 = {};
    bool local_23 = {};
    c_9.e = metal::float3(0.0);
    metal::float3 _e16 = light_point(l_8, u1_2, u2_2);
    c_9.y = _e16;
    metal::float3 _e19 = c_9.y;
    float _e20 = connection_cosine(x_14, _e19, n_15, ng_1, r2_2);
    c_9.cos_x = _e20;
    float _e22 = c_9.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            metal::float3 _e33 = c_9.y;
            bool _e34 = occluded(x_14 + (ng_1 * eps), _e33, geo_nodes, geo_tris, _buffer_sizes);
            local_23 = _e34;
        } else {
            local_23 = false;
        }
        bool _e36 = local_23;
        local_22 = _e36;
    } else {
        local_22 = true;
    }
    bool _e38 = local_22;
    if (_e38) {
        Connection _e39 = c_9;
        return _e39;
    }
    metal::float3 _e41 = c_9.y;
    metal::float3 v_13 = x_14 - _e41;
    float d2_11 = metal::dot(v_13, v_13);
    metal::float3 _e48 = light_intensity(l_8, v_13 / metal::float3(metal::sqrt(d2_11)), slc_table, _buffer_sizes);
    float _e50 = c_9.cos_x;
    float _e51 = connection_factor(_e50, d2_11, rt2_4, w_res);
    c_9.e = _e48 * _e51;
    Connection _e53 = c_9;
    return _e53;
}

Connection connect_traced(
    uint li,
    metal::float3 x_15,
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
    device type_15 const& lights,
    device type_4 const& r2_3,
    device type_4 const& rt2_5,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight _e12 = lights[li];
    float _e15 = r2_3[li];
    float _e19 = rt2_5[li];
    Connection _e21 = connect_record(_e12, x_15, n_16, ng_2, s_1 * _e15, s_1 * _e19, w_res_1, u1_3, u2_3, eps_1, trace_2, slc_table, geo_nodes, geo_tris, _buffer_sizes);
    return _e21;
}

Connection connect(
    uint li_1,
    metal::float3 x_16,
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
    device type_15 const& lights,
    device type_4 const& r2_3,
    device type_4 const& rt2_5,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection _e10 = connect_traced(li_1, x_16, n_17, ng_3, s_2, w_res_2, u1_4, u2_4, eps_2, true, slc_table, geo_nodes, geo_tris, lights, r2_3, rt2_5, _buffer_sizes);
    return _e10;
}

float mis_weight(
    float pdf_a_1,
    float pdf_b_1
) {
    float _e2 = mis_balance(pdf_a_1, pdf_b_1);
    return _e2;
}

float light_range_scale(
    uint li_2,
    metal::float3 x_17,
    metal::float3 r_8,
    metal::float4 rl_8,
    device type_16 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLightCone c_15 = light_cones[li_2];
    float _e9 = range_scale_toward(rl_8, c_15.center, c_15.radius, x_17, r_8);
    return _e9;
}

float select_pdf(
    uint li_3,
    metal::float3 x_18,
    metal::float3 n_18,
    metal::float3 r_9,
    metal::float4 lobe_5,
    metal::float4 rl_9,
    uint nee,
    bool in_range_1
) {
    float _e9 = reservoir_select_pdf(nee, in_range_1, K);
    return _e9;
}

float light_pdf_selected(
    uint li_4,
    metal::float3 x_19,
    metal::float3 r_10,
    metal::float4 rl_10,
    metal::float3 y_2,
    float sel,
    device type_15 const& lights,
    device type_4 const& rt2_5,
    device type_16 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight l_9 = lights[li_4];
    metal::float3 v_14 = x_19 - y_2;
    float d2_12 = metal::dot(v_14, v_14);
    metal::float3 _e11 = light_normal(l_9);
    float cos_y_1 = (d2_12 > 0.0) ? metal::dot(_e11, v_14 / metal::float3(metal::sqrt(d2_12))) : 0.0;
    float _e20 = light_range_scale(li_4, x_19, r_10, rl_10, light_cones, _buffer_sizes);
    float _e23 = rt2_5[li_4];
    float _e25 = light_area(l_9);
    float _e26 = light_strategy_pdf(sel, _e20 * _e23, d2_12, _e25, cos_y_1);
    return _e26;
}

float light_pdf(
    uint li_5,
    metal::float3 x_20,
    metal::float3 n_19,
    metal::float3 r_11,
    metal::float4 lobe_6,
    metal::float4 rl_11,
    metal::float3 y_3,
    uint nee_1,
    bool in_range_2,
    device type_15 const& lights,
    device type_4 const& rt2_5,
    device type_16 const& light_cones,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e9 = select_pdf(li_5, x_20, n_19, r_11, lobe_6, rl_11, nee_1, in_range_2);
    float _e10 = light_pdf_selected(li_5, x_20, r_11, rl_11, y_3, _e9, lights, rt2_5, light_cones, _buffer_sizes);
    return _e10;
}

metal::float3 shade_pick(
    uint li_6,
    metal::float3 x_21,
    metal::float3 n_20,
    metal::float3 ng_4,
    GpuMaterial m,
    metal::float3 wo_1,
    metal::float3 r_12,
    metal::float4 lobe_7,
    metal::float4 rl_12,
    float w_7,
    uint nee_2,
    float u1_5,
    float u2_5,
    device type_4 const& slc_table,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_15 const& lights,
    device type_4 const& r2_3,
    device type_4 const& rt2_5,
    device type_16 const& light_cones,
    constant ShadeParams& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    float mis = 1.0;
    float _e13 = light_range_scale(li_6, x_21, r_12, rl_12, light_cones, _buffer_sizes);
    float _e16 = params.eps;
    Connection _e17 = connect(li_6, x_21, n_20, ng_4, _e13, w_7, u1_5, u2_5, _e16, slc_table, geo_nodes, geo_tris, lights, r2_3, rt2_5, _buffer_sizes);
    if (_e17.cos_x <= 0.0) {
        return metal::float3(0.0);
    }
    metal::float3 l_10 = metal::normalize(_e17.y - x_21);
    GpuLight _e30 = lights[li_6];
    float _e31 = light_area(_e30);
    if (_e31 > 0.0) {
        float _e36 = light_pdf(li_6, x_21, n_20, r_12, lobe_7, rl_12, _e17.y, nee_2, true, lights, rt2_5, light_cones, _buffer_sizes);
        float _e38 = specular_probability(lobe_7);
        float _e39 = bsdf_pdf(n_20, wo_1, l_10, m.alpha, _e38);
        float _e40 = mis_weight(_e36, _e39);
        mis = _e40;
    }
    metal::float3 _e46 = brdf_eval(m.albedo, m.metallic, m.f0_, m.f90_, m.alpha, n_20, wo_1, l_10);
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
, device type_15 const& lights [[user(fake0)]]
, device type_4 const& r2_3 [[user(fake0)]]
, device type_4 const& rt2_5 [[user(fake0)]]
, device type_16 const& light_cones [[user(fake0)]]
, constant ShadeParams& params [[user(fake0)]]
, device type_17 const& vertices [[user(fake0)]]
, device type_18 const& materials [[user(fake0)]]
, device type_19& radiance [[user(fake0)]]
, device type_20& candidates [[user(fake0)]]
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
    metal::float3 x_22 = vtx.position;
    metal::float3 n_23 = vtx.normal;
    metal::float3 ng_5 = vtx.gnormal;
    GpuMaterial m_2 = materials[vtx.material];
    metal::float3 wo_2 = vtx.wo;
    metal::float3 _e23 = mirror_dir(n_23, wo_2);
    metal::float4 _e30 = receiver_lobe(m_2.albedo, m_2.metallic, m_2.f0_, m_2.f90_, m_2.alpha, metal::dot(n_23, wo_2));
    metal::float4 _e31 = range_lobe(_e30);
    uint _e34 = params.seed;
    uint _e37 = params.frame;
    uint _e38 = point_stream(_e34, i_5, _e37);
    uint _e39 = pick_stream(_e38);
    h = _e39;
    Picks _e44 = bsh_collect(x_22, _e23, _e31, _e38, bsh_nodes, _buffer_sizes);
    candidates[i_5] = _e44.n;
    float _e50 = reservoir_weight(_e44.n, K);
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e74 = s;
            s = _e74 + 1u;
        }
        loop_init_2 = false;
        uint _e53 = s;
        if (_e53 < metal::min(_e44.n, K)) {
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
            uint _e69 = h;
            float _e70 = xi_from_bits(_e69);
            metal::float3 _e71 = shade_pick(_e44.light.inner[_e66], x_22, n_23, ng_5, m_2, wo_2, _e23, _e30, _e31, _e50, _e44.n, _e61, _e70, slc_table, geo_nodes, geo_tris, lights, r2_3, rt2_5, light_cones, params, _buffer_sizes);
            sum = _e64 + _e71;
        }
    }
    metal::float3 _e77 = sum;
    metal::float3 add = vtx.weight * _e77;
    bool _e79 = finite3_(add);
    if (_e79) {
        metal::float4 _e82 = radiance[i_5];
        radiance[i_5] = _e82 + metal::float4(add, 0.0);
        return;
    } else {
        return;
    }
}
