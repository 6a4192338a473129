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
typedef metal::float4 type_16[1];
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
    metal::float3 x_2
) {
    metal::float3 v_2 = x_2 - c;
    return metal::dot(v_2, v_2) <= (r * r);
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
    metal::float3 x_3,
    metal::float3 y,
    metal::float3 n,
    metal::float3 ng,
    float r2_1
) {
    bool local = {};
    bool local_1 = {};
    metal::float3 v_3 = x_3 - y;
    float d2_6 = metal::dot(v_3, v_3);
    bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local = !((d2_6 > 0.0));
    } else {
        local = true;
    }
    bool _e16 = local;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_4 = v_3 / metal::float3(metal::sqrt(d2_6));
    float cos_x_1 = -(metal::dot(n, w_4));
    if (!(!((cos_x_1 > 0.0)))) {
        local_1 = !((metal::dot(ng, w_4) < 0.0));
    } else {
        local_1 = true;
    }
    bool _e34 = local_1;
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
    float t_1 = metal::saturate((cos_theta - cos_outer) / (cos_inner - cos_outer));
    return (shape > 0.5) ? (t_1 * t_1) : ((t_1 * t_1) * (3.0 - (2.0 * t_1)));
}

float atan_portable(
    float x_4
) {
    float base = 0.0;
    float t = {};
    float a_8 = metal::abs(x_4);
    t = a_8;
    if (a_8 > 2.4142137) {
        base = 1.5707964;
        t = -1.0 / a_8;
    } else {
        if (a_8 > 0.41421357) {
            base = 0.7853982;
            t = (a_8 - 1.0) / (a_8 + 1.0);
        }
    }
    float _e18 = t;
    float _e19 = t;
    float z = _e18 * _e19;
    float _e21 = base;
    float _e33 = t;
    float _e35 = t;
    float r_8 = _e21 + (((((((((0.080537446 * z) - 0.13877685) * z) + 0.19977711) * z) - 0.3333295) * z) * _e33) + _e35);
    return (x_4 < 0.0) ? -(r_8) : r_8;
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
    float c_1,
    float h_first,
    float h_last
) {
    float a_2 = {};
    a_2 = c_1 - (360.0 * metal::floor(c_1 / 360.0));
    if (h_last <= 0.0) {
        return 0.0;
    }
    if (h_last <= 90.0) {
        float _e15 = a_2;
        if (_e15 > 180.0) {
            float _e18 = a_2;
            a_2 = 360.0 - _e18;
        }
        float _e21 = a_2;
        if (_e21 > 90.0) {
            float _e24 = a_2;
            a_2 = 180.0 - _e24;
        }
        float _e27 = a_2;
        return _e27;
    }
    if (h_first >= 90.0) {
        float _e30 = a_2;
        if (_e30 < 90.0) {
            float _e33 = a_2;
            a_2 = 180.0 - _e33;
        } else {
            float _e36 = a_2;
            if (_e36 > 270.0) {
                float _e39 = a_2;
                a_2 = 540.0 - _e39;
            }
        }
        float _e42 = a_2;
        return _e42;
    }
    if (h_last <= 180.0) {
        float _e45 = a_2;
        if (_e45 > 180.0) {
            float _e48 = a_2;
            a_2 = 360.0 - _e48;
        }
        float _e51 = a_2;
        return _e51;
    }
    float _e52 = a_2;
    return _e52;
}

uint ies_segment(
    Table tab_1,
    uint start,
    uint n_1,
    float x_6,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint lo = 0u;
    uint hi = {};
    if (n_1 < 2u) {
        return 0u;
    }
    hi = n_1 - 1u;
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
    float c_2,
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
    float _e32 = ies_fold_c(c_2, _e27, _e31);
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
    float a_9 = (_e58 * (1.0 - _e49)) + (_e65 * _e49);
    float _e71 = at(tab_2, (c0_ + (ih1_ * _e5)) + _e33, slc_table, _buffer_sizes);
    float _e78 = at(tab_2, (c0_ + (ih1_ * _e5)) + iv1_, slc_table, _buffer_sizes);
    float b_5 = (_e71 * (1.0 - _e49)) + (_e78 * _e49);
    return (a_9 * (1.0 - _e54)) + (b_5 * _e54);
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
    float c_7 = on_axis ? 0.0 : ((_e16) * 57.295779513082322865);
    float _e20 = ies_candela(tab_3, base_2, gamma_1, c_7, slc_table, _buffer_sizes);
    return _e20;
}

float ies_light_candela(
    Table tab_4,
    uint base_3,
    metal::float3 nadir,
    metal::float3 reference,
    metal::float3 w_1,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 side = metal::cross(reference, nadir);
    float _e9 = ies_candela_dir(tab_4, base_3, metal::dot(w_1, nadir), metal::dot(w_1, reference), metal::dot(w_1, side), slc_table, _buffer_sizes);
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
    float w_2
) {
    float _e5 = bsh_range_bound(node_2);
    return node_2.extent + ((w_2 * 1.001) * _e5);
}

uint mul_hi_u32_(
    uint a_3,
    uint b_2
) {
    uint a_lo = a_3 & 65535u;
    uint a_hi = a_3 >> 16u;
    uint b_lo = b_2 & 65535u;
    uint b_hi = b_2 >> 16u;
    uint ll = a_lo * b_lo;
    uint lh = a_lo * b_hi;
    uint hl = a_hi * b_lo;
    uint hh = a_hi * b_hi;
    uint mid_1 = ((ll >> 16u) + (lh & 65535u)) + (hl & 65535u);
    return ((hh + (lh >> 16u)) + (hl >> 16u)) + (mid_1 >> 16u);
}

uint uniform_index(
    uint n_2,
    uint hi_1,
    uint lo_1
) {
    uint _e3 = mul_lo_u32_(hi_1, n_2);
    uint _e4 = mul_hi_u32_(hi_1, n_2);
    uint _e5 = mul_hi_u32_(lo_1, n_2);
    if (_e3 > (4294967295u - _e5)) {
        return _e4 + 1u;
    }
    return _e4;
}

uint reservoir_slot(
    uint n_3,
    uint k,
    uint hi_2,
    uint lo_2
) {
    if (n_3 <= k) {
        return n_3 - 1u;
    }
    uint _e7 = uniform_index(n_3, hi_2, lo_2);
    if (_e7 < k) {
        return _e7;
    }
    return k;
}

bool reservoir_takes(
    uint n_4
) {
    return n_4 < RESERVOIR_FULL;
}

float reservoir_weight(
    uint n_5,
    uint k_1
) {
    float _e2 = to_f32_(n_5);
    float _e3 = to_f32_(k_1);
    return metal::max(_e2 / _e3, 1.0);
}

float cone_cos_of(
    metal::float3 v,
    float d2_4,
    float a_4,
    metal::float3 d
) {
    bool local_3 = {};
    bool local_4 = {};
    float vd = metal::dot(v, d);
    float h2_ = d2_4 - (a_4 * a_4);
    if (!((h2_ <= 0.0))) {
        if (vd >= 0.0) {
            local_4 = (vd * vd) >= h2_;
        } else {
            local_4 = false;
        }
        bool _e19 = local_4;
        local_3 = _e19;
    } else {
        local_3 = true;
    }
    bool _e21 = local_3;
    if (_e21) {
        return 1.0;
    }
    metal::float3 c_8 = metal::cross(v, d);
    return metal::min(((vd * metal::sqrt(h2_)) + (metal::sqrt(metal::dot(c_8, c_8)) * a_4)) / d2_4, 1.0);
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
    metal::float3 r_1
) {
    if (rl_1.w <= 1.0) {
        return 1.0;
    }
    float _e9 = cone_cos_toward(center_1, radius_1, p_1, r_1);
    float _e10 = range_scale_at(rl_1, _e9);
    return _e10;
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

float ray_triangle(
    metal::float3 o_1,
    metal::float3 d_3,
    metal::float3 a_5,
    metal::float3 b_3,
    metal::float3 c_3,
    float t_min,
    float t_max_1
) {
    bool local_5 = {};
    bool local_6 = {};
    bool local_7 = {};
    metal::float3 e1_ = b_3 - a_5;
    metal::float3 e2_ = c_3 - a_5;
    metal::float3 p_2 = metal::cross(d_3, e2_);
    float det = metal::dot(e1_, p_2);
    if (metal::abs(det) <= 0.0) {
        return -1.0;
    }
    float inv = 1.0 / det;
    metal::float3 s_3 = o_1 - a_5;
    float u_2 = metal::dot(s_3, p_2) * inv;
    if (!((u_2 < 0.0))) {
        local_5 = u_2 > 1.0;
    } else {
        local_5 = true;
    }
    bool _e28 = local_5;
    if (_e28) {
        return -1.0;
    }
    metal::float3 q = metal::cross(s_3, e1_);
    float v_5 = metal::dot(d_3, q) * inv;
    if (!((v_5 < 0.0))) {
        local_6 = (u_2 + v_5) > 1.0;
    } else {
        local_6 = true;
    }
    bool _e42 = local_6;
    if (_e42) {
        return -1.0;
    }
    float t_3 = metal::dot(e2_, q) * inv;
    if (t_3 > t_min) {
        local_7 = t_3 < t_max_1;
    } else {
        local_7 = false;
    }
    bool _e51 = local_7;
    if (_e51) {
        return t_3;
    }
    return -1.0;
}

metal::float3 light_intensity(
    GpuLight l,
    metal::float3 w_3,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            float _e11 = spot_falloff(metal::dot(l.p1_, w_3), l.a, l.b, l.p2_[0]);
            return l.intensity * _e11;
        }
        case 2u: {
            float _e18 = ies_light_candela(0u, l.ies_base, l.p1_, l.p2_, w_3, slc_table, _buffer_sizes);
            return l.intensity * _e18;
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
        GpuGeoNode n_9 = geo_nodes[_e21];
        float _e27 = hit.t;
        float _e28 = ray_aabb(o_2, _e14, n_9.bmin, n_9.bmax, _e27);
        if (_e28 >= 0.0) {
            if (n_9.count > 0u) {
                i_1 = n_9.first;
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
                    if (_e36 < (n_9.first + n_9.count)) {
                    } else {
                        break;
                    }
                    {
                        uint _e42 = i_1;
                        GpuTriangle t_4 = geo_tris[_e42];
                        float _e49 = hit.t;
                        float _e50 = ray_triangle(o_2, d_4, t_4.v0_, t_4.v1_, t_4.v2_, t_min_1, _e49);
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
                    stack.inner[_e63] = n_9.first + 1u;
                    uint _e68 = sp;
                    sp = _e68 + 1u;
                }
                node_3 = n_9.first;
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
    metal::float3 a_6,
    metal::float3 b_4,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 dv = b_4 - a_6;
    float len_1 = metal::length(dv);
    if (len_1 <= 0.0) {
        return false;
    }
    float _e7 = shadow_margin(len_1);
    GeoHit _e12 = trace(a_6, dv / metal::float3(len_1), _e7, len_1 - _e7, true, geo_nodes, geo_tris, _buffer_sizes);
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
    float a_7,
    metal::float3 v_1,
    float d2_5,
    metal::float3 r_2,
    metal::float4 rl_2
) {
    float _e5 = cone_cos_of(v_1, d2_5, a_7, r_2);
    float _e8 = range_scale_at(rl_2, _e5 + 0.000002);
    return _e8;
}

bool bsh_reaches(
    BshNode node_4,
    metal::float3 x_9,
    metal::float3 r_3,
    metal::float4 rl_3
) {
    bool local_8 = {};
    bool local_9 = {};
    bool _e6 = sphere_contains_point(node_4.center, node_4.radius, x_9);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_4.center, node_4.radius * (rl_3.w * 1.0001), x_9);
        local_8 = !(_e20);
    } else {
        local_8 = true;
    }
    bool _e23 = local_8;
    if (_e23) {
        return false;
    }
    metal::float3 v_6 = x_9 - node_4.center;
    float d2_7 = metal::dot(v_6, v_6);
    float _e29 = bsh_reach_bound(node_4, rl_3.w);
    if (d2_7 > (_e29 * _e29)) {
        return false;
    }
    if (node_4.child == BSH_NONE) {
        float _e38 = range_scale_toward(rl_3, node_4.center, node_4.extent, x_9, r_3);
        float _e41 = bsh_scaled_radius(node_4, metal::sqrt(_e38));
        bool _e42 = sphere_contains_point(node_4.center, _e41, x_9);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_4.extent, -(v_6), d2_7, r_3, rl_3);
    float s_c = _e45 * 1.001;
    float _e50 = bsh_range_bound(node_4);
    float reach = node_4.extent + (metal::sqrt(s_c) * _e50);
    if (d2_7 <= ((node_4.radius * node_4.radius) * s_c)) {
        local_9 = d2_7 <= (reach * reach);
    } else {
        local_9 = false;
    }
    bool _e63 = local_9;
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
    BshCursor c_4 = {};
    c_4.i = 0u;
    c_4.end = 0u;
    uint _e10 = bsh_first(BSH, bsh_nodes, _buffer_sizes);
    c_4.next = _e10;
    c_4.cone = metal::float2(0.0);
    BshCursor _e14 = c_4;
    return _e14;
}

uint bsh_cursor_next(
    thread BshCursor& c_5,
    metal::float3 x_12,
    metal::float3 r_6,
    metal::float4 rl_6,
    device type_11 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e6 = c_5.next;
    uint _e7 = bsh_next_leaf_lobe(BSH, _e6, x_12, r_6, rl_6, bsh_nodes, _buffer_sizes);
    if (_e7 != BSH_NONE) {
        uint _e14 = bsh_nodes[_e7].next;
        c_5.next = _e14;
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
    GpuLight l_2,
    metal::float3 x_14,
    metal::float3 n_6,
    metal::float3 ng_1,
    float r2_2,
    float rt2_2,
    float w_res,
    float u1_1,
    float u2_1,
    float eps,
    bool trace_1,
    device type_4 const& slc_table,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection c_6 = {};
    bool local_10 = {};
    bool local_11 = {};
    c_6.e = metal::float3(0.0);
    metal::float3 _e16 = light_point(l_2, u1_1, u2_1);
    c_6.y = _e16;
    metal::float3 _e19 = c_6.y;
    float _e20 = connection_cosine(x_14, _e19, n_6, ng_1, r2_2);
    c_6.cos_x = _e20;
    float _e22 = c_6.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace_1) {
            metal::float3 _e33 = c_6.y;
            bool _e34 = occluded(x_14 + (ng_1 * eps), _e33, geo_nodes, geo_tris, _buffer_sizes);
            local_11 = _e34;
        } else {
            local_11 = false;
        }
        bool _e36 = local_11;
        local_10 = _e36;
    } else {
        local_10 = true;
    }
    bool _e38 = local_10;
    if (_e38) {
        Connection _e39 = c_6;
        return _e39;
    }
    metal::float3 _e41 = c_6.y;
    metal::float3 v_7 = x_14 - _e41;
    float d2_8 = metal::dot(v_7, v_7);
    metal::float3 _e48 = light_intensity(l_2, v_7 / metal::float3(metal::sqrt(d2_8)), slc_table, _buffer_sizes);
    float _e50 = c_6.cos_x;
    float _e51 = connection_factor(_e50, d2_8, rt2_2, w_res);
    c_6.e = _e48 * _e51;
    Connection _e53 = c_6;
    return _e53;
}

Connection connect_traced(
    uint li,
    metal::float3 x_15,
    metal::float3 n_7,
    metal::float3 ng_2,
    float s_1,
    float w_res_1,
    float u1_2,
    float u2_2,
    float eps_1,
    bool trace_2,
    device type_4 const& slc_table,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_15 const& lights,
    device type_4 const& r2_3,
    device type_4 const& rt2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight _e12 = lights[li];
    float _e15 = r2_3[li];
    float _e19 = rt2_3[li];
    Connection _e21 = connect_record(_e12, x_15, n_7, ng_2, s_1 * _e15, s_1 * _e19, w_res_1, u1_2, u2_2, eps_1, trace_2, slc_table, geo_nodes, geo_tris, _buffer_sizes);
    return _e21;
}

Connection connect(
    uint li_1,
    metal::float3 x_16,
    metal::float3 n_8,
    metal::float3 ng_3,
    float s_2,
    float w_res_2,
    float u1_3,
    float u2_3,
    float eps_2,
    device type_4 const& slc_table,
    device type_7 const& geo_nodes,
    device type_8 const& geo_tris,
    device type_15 const& lights,
    device type_4 const& r2_3,
    device type_4 const& rt2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection _e10 = connect_traced(li_1, x_16, n_8, ng_3, s_2, w_res_2, u1_3, u2_3, eps_2, true, slc_table, geo_nodes, geo_tris, lights, r2_3, rt2_3, _buffer_sizes);
    return _e10;
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
, device type_4 const& rt2_3 [[user(fake0)]]
, constant ShadeParams& params [[user(fake0)]]
, device type_16 const& points [[user(fake0)]]
, device type_16 const& normals [[user(fake0)]]
, device type_16& irradiance [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint h = {};
    metal::float3 e = metal::float3(0.0);
    uint s = 0u;
    uint i_5 = gid.x;
    uint _e4 = params.point_count;
    if (i_5 >= _e4) {
        return;
    }
    metal::float4 p_3 = points[i_5];
    if (p_3.w <= 0.0) {
        irradiance[i_5] = metal::float4(0.0);
        return;
    }
    metal::float3 x_17 = p_3.xyz;
    metal::float4 _e19 = normals[i_5];
    metal::float3 n_10 = _e19.xyz;
    uint _e23 = params.seed;
    uint _e26 = params.frame;
    uint _e27 = point_stream(_e23, i_5, _e26);
    Picks _e33 = bsh_collect(x_17, x_17, metal::float4(1.0, 0.0, 1.0, 1.0), _e27, bsh_nodes, _buffer_sizes);
    float _e36 = reservoir_weight(_e33.n, K);
    uint _e37 = pick_stream(_e27);
    h = _e37;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e69 = s;
            s = _e69 + 1u;
        }
        loop_init_2 = false;
        uint _e44 = s;
        if (_e44 < metal::min(_e33.n, K)) {
        } else {
            break;
        }
        {
            uint _e49 = h;
            uint _e50 = pcg_hash(_e49);
            h = _e50;
            uint _e51 = h;
            float _e52 = xi_from_bits(_e51);
            uint _e53 = h;
            uint _e54 = pcg_hash(_e53);
            h = _e54;
            metal::float3 _e55 = e;
            uint _e57 = s;
            uint _e60 = h;
            float _e61 = xi_from_bits(_e60);
            float _e64 = params.eps;
            Connection _e65 = connect(_e33.light.inner[_e57], x_17, n_10, n_10, 1.0, _e36, _e52, _e61, _e64, slc_table, geo_nodes, geo_tris, lights, r2_3, rt2_3, _buffer_sizes);
            e = _e55 + _e65.e;
        }
    }
    metal::float3 _e73 = e;
    irradiance[i_5] = metal::float4(_e73, static_cast<float>(_e33.n));
    return;
}
