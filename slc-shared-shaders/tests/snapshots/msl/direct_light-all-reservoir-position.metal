// language: metal1.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
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
typedef GpuLight type_8[1];
typedef BshNode type_9[1];
struct type_10 {
    uint inner[8];
};
struct Picks {
    type_10 light;
    uint n;
};
typedef uint BshNodes;
struct Connection {
    metal::float3 e;
    metal::packed_float3 y;
    float cos_x;
};
struct type_14 {
    metal::float3 inner[64];
};
struct WorkgroupBox {
    metal::float3 lo;
    metal::float3 hi;
};
struct type_15 {
    uint inner[1024];
};
struct type_16 {
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
    float r_1,
    metal::float3 x_2
) {
    metal::float3 v_2 = x_2 - c;
    return metal::dot(v_2, v_2) <= (r_1 * r_1);
}

bool sphere_overlaps_aabb(
    metal::float3 c_1,
    float r_2,
    metal::float3 bmin,
    metal::float3 bmax
) {
    metal::float3 q = metal::clamp(c_1, bmin, bmax);
    metal::float3 v_3 = q - c_1;
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
    float w
) {
    float _e4 = inverse_square(d2_3);
    float _e6 = slc_weight(rt2_1, d2_3);
    return ((cos_x * _e4) * _e6) * w;
}

float connection_cosine(
    metal::float3 x_3,
    metal::float3 y,
    metal::float3 n_1,
    metal::float3 ng,
    float r2_1
) {
    bool local_5 = {};
    bool local_6 = {};
    metal::float3 v_4 = x_3 - y;
    float d2_6 = metal::dot(v_4, v_4);
    bool _e7 = slc_keep(r2_1, d2_6);
    if (!(!(_e7))) {
        local_5 = !((d2_6 > 0.0));
    } else {
        local_5 = true;
    }
    bool _e16 = local_5;
    if (_e16) {
        return 0.0;
    }
    metal::float3 w_10 = v_4 / metal::float3(metal::sqrt(d2_6));
    float cos_x_1 = -(metal::dot(n_1, w_10));
    if (!(!((cos_x_1 > 0.0)))) {
        local_6 = !((metal::dot(ng, w_10) < 0.0));
    } else {
        local_6 = true;
    }
    bool _e34 = local_6;
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
    float t_5 = metal::saturate((cos_theta - cos_outer) / (cos_inner - cos_outer));
    return (shape > 0.5) ? (t_5 * t_5) : ((t_5 * t_5) * (3.0 - (2.0 * t_5)));
}

float triangle_lobe(
    metal::float3 n_2,
    float area,
    metal::float3 w_1
) {
    return area * metal::max(metal::dot(n_2, w_1), 0.0);
}

metal::float3 triangle_sample(
    metal::float3 a_2,
    metal::float3 b_2,
    metal::float3 c_2,
    float u1_,
    float u2_
) {
    float su = metal::sqrt(u1_);
    float b0_ = 1.0 - su;
    float b1_ = u2_ * su;
    return ((a_2 * b0_) + (b_2 * b1_)) + (c_2 * ((1.0 - b0_) - b1_));
}

float atan_portable(
    float x_4
) {
    float base = 0.0;
    float t_1 = {};
    float a_10 = metal::abs(x_4);
    t_1 = a_10;
    if (a_10 > 2.4142137) {
        base = 1.5707964;
        t_1 = -1.0 / a_10;
    } else {
        if (a_10 > 0.41421357) {
            base = 0.7853982;
            t_1 = (a_10 - 1.0) / (a_10 + 1.0);
        }
    }
    float _e18 = t_1;
    float _e19 = t_1;
    float z = _e18 * _e19;
    float _e21 = base;
    float _e33 = t_1;
    float _e35 = t_1;
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
    float c_3,
    float h_first,
    float h_last
) {
    float a_3 = {};
    a_3 = c_3 - (360.0 * metal::floor(c_3 / 360.0));
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
    uint start_1,
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
            float _e23 = at(tab_1, start_1 + mid, slc_table, _buffer_sizes);
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
    float c_4,
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
    uint c0_ = h0_ + _e9;
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
    float _e32 = ies_fold_c(c_4, _e27, _e31);
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
    float b_9 = (_e71 * (1.0 - _e49)) + (_e78 * _e49);
    return (a_11 * (1.0 - _e54)) + (b_9 * _e54);
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
    float c_8 = on_axis ? 0.0 : ((_e16) * 57.295779513082322865);
    float _e20 = ies_candela(tab_3, base_2, gamma_1, c_8, slc_table, _buffer_sizes);
    return _e20;
}

float ies_light_candela(
    Table tab_4,
    uint base_3,
    metal::float3 nadir,
    metal::float3 reference,
    metal::float3 w_2,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 side = metal::cross(reference, nadir);
    float _e9 = ies_candela_dir(tab_4, base_3, metal::dot(w_2, nadir), metal::dot(w_2, reference), metal::dot(w_2, side), slc_table, _buffer_sizes);
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
    float w_3
) {
    float _e5 = bsh_range_bound(node_2);
    return node_2.extent + ((w_3 * 1.001) * _e5);
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
    uint k_1,
    uint hi_2,
    uint lo_2
) {
    if (n_5 <= k_1) {
        return n_5 - 1u;
    }
    uint _e7 = uniform_index(n_5, hi_2, lo_2);
    if (_e7 < k_1) {
        return _e7;
    }
    return k_1;
}

bool reservoir_takes(
    uint n_6
) {
    return n_6 < RESERVOIR_FULL;
}

float reservoir_weight(
    uint n_7,
    uint k_2
) {
    float _e2 = to_f32_(n_7);
    float _e3 = to_f32_(k_2);
    return metal::max(_e2 / _e3, 1.0);
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
    float a_5,
    metal::float3 d
) {
    bool local_8 = {};
    bool local_9 = {};
    float vd = metal::dot(v, d);
    float h2_ = d2_4 - (a_5 * a_5);
    if (!((h2_ <= 0.0))) {
        if (vd >= 0.0) {
            local_9 = (vd * vd) >= h2_;
        } else {
            local_9 = false;
        }
        bool _e19 = local_9;
        local_8 = _e19;
    } else {
        local_8 = true;
    }
    bool _e21 = local_8;
    if (_e21) {
        return 1.0;
    }
    metal::float3 c_9 = metal::cross(v, d);
    return metal::min(((vd * metal::sqrt(h2_)) + (metal::sqrt(metal::dot(c_9, c_9)) * a_5)) / d2_4, 1.0);
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
    float t_6 = ((0.5 + (0.5 * cos_t)) * (rl.z - 1.0)) + 1.0;
    return metal::clamp(rl.x + ((rl.y * rl.z) / (t_6 * t_6)), 1.0, rl.w * rl.w);
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

metal::float3 triangle_normal(
    metal::float3 a_6,
    metal::float3 b_4,
    metal::float3 c_5
) {
    bool local_10 = {};
    metal::float3 n_13 = metal::cross(b_4 - a_6, c_5 - a_6);
    float l2_ = metal::dot(n_13, n_13);
    if (!(!((l2_ > 0.0)))) {
        local_10 = !((l2_ < 300000000000000000000000000000000000000.0));
    } else {
        local_10 = true;
    }
    bool _e17 = local_10;
    if (_e17) {
        return metal::float3(0.0, 0.0, 0.0);
    }
    return n_13 / metal::float3(metal::sqrt(l2_));
}

metal::float3 light_intensity(
    GpuLight l,
    metal::float3 w_4,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    switch(l.kind) {
        case 0u: {
            return l.intensity;
        }
        case 1u: {
            float _e11 = spot_falloff(metal::dot(l.p1_, w_4), l.a, l.b, l.p2_[0]);
            return l.intensity * _e11;
        }
        case 2u: {
            float _e18 = ies_light_candela(0u, l.ies_base, l.p1_, l.p2_, w_4, slc_table, _buffer_sizes);
            return l.intensity * _e18;
        }
        case 3u: {
            metal::float3 _e24 = triangle_normal(l.p0_, l.p1_, l.p2_);
            float _e26 = triangle_lobe(_e24, l.a, w_4);
            return l.intensity * _e26;
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

bool occluded(
    metal::float3 a_7,
    metal::float3 b_5
) {
    return false;
}

BshNode bsh_node(
    BshNodes nodes,
    uint i_1,
    device type_9 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    BshNode _e4 = bsh_nodes[i_1];
    return _e4;
}

uint bsh_count(
    BshNodes nodes_1,
    device type_9 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    return 1 + (_buffer_sizes.size8 - 0 - 32) / 32;
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

float bsh_inner_scale(
    float a_8,
    metal::float3 v_1,
    float d2_5,
    metal::float3 r_4,
    metal::float4 rl_2
) {
    float _e5 = cone_cos_of(v_1, d2_5, a_8, r_4);
    float _e8 = range_scale_at(rl_2, _e5 + 0.000002);
    return _e8;
}

bool bsh_reaches(
    BshNode node_3,
    metal::float3 x_8,
    metal::float3 r_5,
    metal::float4 rl_3
) {
    bool local_11 = {};
    bool local_12 = {};
    bool _e6 = sphere_contains_point(node_3.center, node_3.radius, x_8);
    if (_e6) {
        return true;
    }
    if (!((rl_3.w <= 1.0))) {
        bool _e20 = sphere_contains_point(node_3.center, node_3.radius * (rl_3.w * 1.0001), x_8);
        local_11 = !(_e20);
    } else {
        local_11 = true;
    }
    bool _e23 = local_11;
    if (_e23) {
        return false;
    }
    metal::float3 v_6 = x_8 - node_3.center;
    float d2_7 = metal::dot(v_6, v_6);
    float _e29 = bsh_reach_bound(node_3, rl_3.w);
    if (d2_7 > (_e29 * _e29)) {
        return false;
    }
    if (node_3.child == BSH_NONE) {
        float _e38 = range_scale_toward(rl_3, node_3.center, node_3.extent, x_8, r_5);
        float _e41 = bsh_scaled_radius(node_3, metal::sqrt(_e38));
        bool _e42 = sphere_contains_point(node_3.center, _e41, x_8);
        return _e42;
    }
    float _e45 = bsh_inner_scale(node_3.extent, -(v_6), d2_7, r_5, rl_3);
    float s_c = _e45 * 1.001;
    float _e50 = bsh_range_bound(node_3);
    float reach = node_3.extent + (metal::sqrt(s_c) * _e50);
    if (d2_7 <= ((node_3.radius * node_3.radius) * s_c)) {
        local_12 = d2_7 <= (reach * reach);
    } else {
        local_12 = false;
    }
    bool _e63 = local_12;
    return _e63;
}

bool bsh_reaches_box(
    BshNode node_4,
    metal::float3 lo_3,
    metal::float3 hi_3,
    float w_5
) {
    bool _e13 = sphere_overlaps_aabb(node_4.center, node_4.radius * (metal::max(1.0, w_5 * 1.0001) * 1.0001), lo_3, hi_3);
    return _e13;
}

uint bsh_subtree(
    BshNodes nodes_3,
    uint s_1,
    uint depth,
    device type_9 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_2 = {};
    uint level = 0u;
    bool local_13 = {};
    uint _e3 = bsh_first(nodes_3, bsh_nodes, _buffer_sizes);
    i_2 = _e3;
    uint2 loop_bound_1 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e7 = level;
        if (_e7 < depth) {
            uint _e11 = i_2;
            local_13 = _e11 != BSH_NONE;
        } else {
            local_13 = false;
        }
        bool _e15 = local_13;
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
    uint start_2,
    uint end,
    metal::float3 lo_4,
    metal::float3 hi_4,
    float w_6,
    device type_9 const& bsh_nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i_3 = {};
    i_3 = start_2;
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e7 = i_3;
        if (_e7 != end) {
        } else {
            break;
        }
        {
            uint _e9 = i_3;
            BshNode _e10 = bsh_node(nodes_4, _e9, bsh_nodes, _buffer_sizes);
            bool _e11 = bsh_reaches_box(_e10, lo_4, hi_4, w_6);
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

void reservoir_offer(
    thread Picks& picks_1,
    thread uint& h_1,
    uint light
) {
    uint _e4 = picks_1.n;
    bool _e5 = reservoir_takes(_e4);
    if (_e5) {
        uint _e7 = picks_1.n;
        picks_1.n = _e7 + 1u;
        uint _e10 = h_1;
        uint _e11 = pcg_hash(_e10);
        h_1 = _e11;
        uint hi_6 = h_1;
        uint _e13 = h_1;
        uint _e14 = pcg_hash(_e13);
        h_1 = _e14;
        uint _e16 = picks_1.n;
        uint _e18 = h_1;
        uint _e19 = reservoir_slot(_e16, K, hi_6, _e18);
        if (_e19 < K) {
            picks_1.light.inner[_e19] = light;
            return;
        } else {
            return;
        }
    } else {
        return;
    }
}

Connection connect_record(
    GpuLight l_2,
    metal::float3 x_9,
    metal::float3 n_8,
    metal::float3 ng_1,
    float r2_2,
    float rt2_2,
    float w_res,
    float u1_2,
    float u2_2,
    float eps,
    bool trace,
    device type_4 const& slc_table,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection c_6 = {};
    bool local_14 = {};
    bool local_15 = {};
    c_6.e = metal::float3(0.0);
    metal::float3 _e16 = light_point(l_2, u1_2, u2_2);
    c_6.y = _e16;
    metal::float3 _e19 = c_6.y;
    float _e20 = connection_cosine(x_9, _e19, n_8, ng_1, r2_2);
    c_6.cos_x = _e20;
    float _e22 = c_6.cos_x;
    if (!((_e22 <= 0.0))) {
        if (trace) {
            metal::float3 _e33 = c_6.y;
            bool _e34 = occluded(x_9 + (ng_1 * eps), _e33);
            local_15 = _e34;
        } else {
            local_15 = false;
        }
        bool _e36 = local_15;
        local_14 = _e36;
    } else {
        local_14 = true;
    }
    bool _e38 = local_14;
    if (_e38) {
        Connection _e39 = c_6;
        return _e39;
    }
    metal::float3 _e41 = c_6.y;
    metal::float3 v_7 = x_9 - _e41;
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
    metal::float3 x_10,
    metal::float3 n_9,
    metal::float3 ng_2,
    float s_2,
    float w_res_1,
    float u1_3,
    float u2_3,
    float eps_1,
    bool trace_1,
    device type_4 const& slc_table,
    device type_8 const& lights,
    device type_4 const& rt2_3,
    device type_4 const& r2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuLight _e12 = lights[li];
    float _e15 = r2_3[li];
    float _e19 = rt2_3[li];
    Connection _e21 = connect_record(_e12, x_10, n_9, ng_2, s_2 * _e15, s_2 * _e19, w_res_1, u1_3, u2_3, eps_1, trace_1, slc_table, _buffer_sizes);
    return _e21;
}

metal::float4 surface_at(
    metal::int2 texel,
    metal::texture2d<float, metal::access::sample> position_tex
) {
    metal::float4 p_5 = position_tex.read(metal::uint2(texel), 0);
    return (p_5.w > 0.0) ? metal::float4(p_5.xyz, 1.0) : metal::float4(0.0);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

WorkgroupBox workgroup_bounds(
    uint li_1,
    metal::float3 lo_5,
    metal::float3 hi_5,
    threadgroup type_14& wg_lo,
    threadgroup type_14& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    uint stride = 32u;
    wg_lo.inner[li_1] = lo_5;
    wg_hi.inner[li_1] = hi_5;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint2 loop_bound_3 = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        if (!loop_init) {
            uint _e36 = stride;
            stride = naga_div(_e36, 2u);
        }
        loop_init = false;
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
    threadgroup type_14& wg_lo,
    threadgroup type_14& wg_hi,
    threadgroup WorkgroupBox& wg_box
) {
    WorkgroupBox _e3 = point_box(p_3, has_1);
    WorkgroupBox _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi, wg_lo, wg_hi, wg_box);
    return _e6;
}

bool box_is_empty(
    WorkgroupBox b_6
) {
    return b_6.lo.x > b_6.hi.x;
}

uint tile_subtree(
    uint s_3,
    TileWalk t_2,
    bool list,
    uint at_1,
    uint start_3,
    uint to,
    device type_9 const& bsh_nodes,
    threadgroup type_15& tile_list,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint p_4 = {};
    uint b_7 = {};
    bool local_16 = {};
    bool local_17 = {};
    bool local_18 = {};
    uint _e8 = bsh_subtree(BSH, s_3, BSH_TILE_DEPTH, bsh_nodes, _buffer_sizes);
    if (_e8 == BSH_NONE) {
        return 0u;
    }
    uint end_1 = bsh_nodes[_e8].next;
    p_4 = at_1;
    uint _e21 = bsh_next_leaf_box(BSH, _e8, end_1, t_2.lo, t_2.hi, t_2.w, bsh_nodes, _buffer_sizes);
    b_7 = _e21;
    uint2 loop_bound_4 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e53 = b_7;
            uint _e56 = bsh_nodes[_e53].next;
            uint _e60 = bsh_next_leaf_box(BSH, _e56, end_1, t_2.lo, t_2.hi, t_2.w, bsh_nodes, _buffer_sizes);
            b_7 = _e60;
        }
        loop_init_1 = false;
        uint _e23 = b_7;
        if (_e23 != end_1) {
            if (!(!(list))) {
                uint _e31 = p_4;
                local_17 = _e31 < to;
            } else {
                local_17 = true;
            }
            bool _e34 = local_17;
            local_16 = _e34;
        } else {
            local_16 = false;
        }
        bool _e36 = local_16;
        if (_e36) {
        } else {
            break;
        }
        {
            if (list) {
                uint _e39 = p_4;
                local_18 = _e39 >= start_3;
            } else {
                local_18 = false;
            }
            bool _e42 = local_18;
            if (_e42) {
                uint _e44 = p_4;
                uint _e47 = b_7;
                tile_list.inner[_e44 - start_3] = _e47;
            }
            uint _e48 = p_4;
            p_4 = _e48 + 1u;
        }
    }
    uint _e61 = p_4;
    return _e61 - at_1;
}

TileWalk tile_walk_begin(
    uint li_3,
    metal::float3 x_11,
    float w_7,
    bool has_2,
    device type_9 const& bsh_nodes,
    threadgroup type_14& wg_lo,
    threadgroup type_14& wg_hi,
    threadgroup WorkgroupBox& wg_box,
    threadgroup type_15& tile_list,
    threadgroup type_16& subtree_at,
    threadgroup metal::atomic_uint& tile_scale,
    threadgroup uint& tile_total,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_19 = {};
    TileWalk t_3 = {};
    uint s_4 = {};
    uint sum = 0u;
    uint s_5 = 0u;
    if (has_2) {
        local_19 = w_7 >= 0.0;
    } else {
        local_19 = false;
    }
    bool _e12 = local_19;
    uint _e14 = metal::atomic_fetch_max_explicit(&tile_scale, _e12 ? as_type<uint>(w_7) : 0u, metal::memory_order_relaxed);
    WorkgroupBox _e15 = workgroup_box(li_3, x_11, has_2, wg_lo, wg_hi, wg_box);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_1 = metal::atomic_load_explicit(&tile_scale, metal::memory_order_relaxed);
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    t_3 = TileWalk {_e15.lo, _e15.hi, as_type<float>(unnamed_1), 0u};
    bool _e24 = box_is_empty(_e15);
    if (_e24) {
        TileWalk _e25 = t_3;
        return _e25;
    }
    s_4 = li_3;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e40 = s_4;
            s_4 = _e40 + TILE_THREADS;
        }
        loop_init_2 = false;
        uint _e27 = s_4;
        if (_e27 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            uint _e31 = s_4;
            uint _e33 = s_4;
            TileWalk _e34 = t_3;
            uint _e39 = tile_subtree(_e33, _e34, false, 0u, 0u, 0u, bsh_nodes, tile_list, _buffer_sizes);
            subtree_at.inner[_e31] = _e39;
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    if (li_3 == 0u) {
        uint2 loop_bound_6 = uint2(4294967295u);
        bool loop_init_3 = true;
        while(true) {
            if (metal::all(loop_bound_6 == uint2(0u))) { break; }
            loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
            if (!loop_init_3) {
                uint _e63 = s_5;
                s_5 = _e63 + 1u;
            }
            loop_init_3 = false;
            uint _e49 = s_5;
            if (_e49 < BSH_TILE_SUBTREES) {
            } else {
                break;
            }
            {
                uint _e53 = s_5;
                uint c_10 = subtree_at.inner[_e53];
                uint _e57 = s_5;
                uint _e59 = sum;
                subtree_at.inner[_e57] = _e59;
                uint _e60 = sum;
                sum = _e60 + c_10;
            }
        }
        uint _e66 = sum;
        tile_total = _e66;
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    uint unnamed_2 = tile_total;
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    t_3.total = unnamed_2;
    TileWalk _e70 = t_3;
    return _e70;
}

uint tile_walk_fill(
    uint li_4,
    TileWalk t_4,
    uint start_4,
    device type_9 const& bsh_nodes,
    threadgroup type_15& tile_list,
    threadgroup type_16& subtree_at,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint s_6 = {};
    uint past = {};
    bool local_20 = {};
    uint to_1 = metal::min(t_4.total, start_4 + TILE_LIST);
    s_6 = li_4;
    uint2 loop_bound_7 = uint2(4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (metal::all(loop_bound_7 == uint2(0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e38 = s_6;
            s_6 = _e38 + TILE_THREADS;
        }
        loop_init_4 = false;
        uint _e8 = s_6;
        if (_e8 < BSH_TILE_SUBTREES) {
        } else {
            break;
        }
        {
            uint _e12 = s_6;
            uint at_2 = subtree_at.inner[_e12];
            past = t_4.total;
            uint _e17 = s_6;
            if ((_e17 + 1u) < BSH_TILE_SUBTREES) {
                uint _e23 = s_6;
                uint _e27 = subtree_at.inner[_e23 + 1u];
                past = _e27;
            }
            if (at_2 < to_1) {
                uint _e31 = past;
                local_20 = _e31 > start_4;
            } else {
                local_20 = false;
            }
            bool _e34 = local_20;
            if (_e34) {
                uint _e35 = s_6;
                uint _e37 = tile_subtree(_e35, t_4, true, at_2, start_4, to_1, bsh_nodes, tile_list, _buffer_sizes);
            }
        }
    }
    metal::threadgroup_barrier(metal::mem_flags::mem_threadgroup);
    return to_1 - start_4;
}

Shaded shade_connection(
    Connection c_7,
    metal::float3 x_12,
    metal::float3 n_10,
    Material m_1
) {
    Shaded s_7 = {};
    s_7.e = c_7.e;
    s_7.diffuse = metal::float3(0.0);
    s_7.specular = metal::float3(0.0);
    Shaded _e13 = s_7;
    return _e13;
}

Shaded shade_pick_traced(
    uint li_5,
    metal::float3 x_13,
    metal::float3 n_11,
    metal::float3 r_6,
    metal::float4 rl_4,
    Material m_2,
    float w_8,
    float u1_4,
    float u2_4,
    float eps_2,
    bool trace_2,
    device type_4 const& slc_table,
    device type_8 const& lights,
    device type_4 const& rt2_3,
    device type_4 const& r2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    Connection _e12 = connect_traced(li_5, x_13, n_11, n_11, 1.0, w_8, u1_4, u2_4, eps_2, trace_2, slc_table, lights, rt2_3, r2_3, _buffer_sizes);
    Shaded _e13 = shade_connection(_e12, x_13, n_11, m_2);
    return _e13;
}

Shaded shade_pick(
    uint li_6,
    metal::float3 x_14,
    metal::float3 n_12,
    metal::float3 r_7,
    metal::float4 rl_5,
    Material m_3,
    float w_9,
    float u1_5,
    float u2_5,
    float eps_3,
    device type_4 const& slc_table,
    device type_8 const& lights,
    device type_4 const& rt2_3,
    device type_4 const& r2_3,
    constant _mslBufferSizes& _buffer_sizes
) {
    Shaded _e11 = shade_pick_traced(li_6, x_14, n_12, r_7, rl_5, m_3, w_9, u1_5, u2_5, eps_3, true, slc_table, lights, rt2_3, r2_3, _buffer_sizes);
    return _e11;
}

Shaded add(
    Shaded a_9,
    Shaded b_8
) {
    return Shaded {a_9.e + b_8.e, a_9.diffuse + b_8.diffuse, a_9.specular + b_8.specular};
}

struct main_Input {
};
kernel void main_(
  metal::uint3 gid [[thread_position_in_grid]]
, uint lid [[thread_index_in_threadgroup]]
, device type_4 const& slc_table [[user(fake0)]]
, constant ViewParams& view [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> position_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::sample> normal_tex [[user(fake0)]]
, metal::texture2d<float, metal::access::write> out_tex [[user(fake0)]]
, device type_8 const& lights [[user(fake0)]]
, device type_4 const& rt2_3 [[user(fake0)]]
, device type_4 const& r2_3 [[user(fake0)]]
, device type_9 const& bsh_nodes [[user(fake0)]]
, threadgroup type_14& wg_lo
, threadgroup type_14& wg_hi
, threadgroup WorkgroupBox& wg_box
, threadgroup type_15& tile_list
, threadgroup type_16& subtree_at
, threadgroup metal::atomic_uint& tile_scale
, threadgroup uint& tile_total
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
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
    Picks picks = {};
    uint hr = {};
    uint start = 0u;
    uint j = {};
    bool local_4 = {};
    uint k = 0u;
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
    metal::float3 x_15 = _e35.xyz;
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
        local_3 = metal::all(metal::abs(x_15) <= metal::float3(340282350000000000000000000000000000000.0));
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
    float eps_4 = _e82 * metal::length(_e85 - x_15);
    uint _e91 = view.seed;
    uint _e95 = view.width;
    uint _e101 = view.frame;
    uint _e102 = point_stream(_e91, (gid.y * _e95) + gid.x, _e101);
    uint _e103 = pick_stream(_e102);
    h = _e103;
    picks.n = 0u;
    hr = _e102;
    TileWalk _e118 = tile_walk_begin(lid, x_15, _e79.w, has_3, bsh_nodes, wg_lo, wg_hi, wg_box, tile_list, subtree_at, tile_scale, tile_total, _buffer_sizes);
    uint2 loop_bound_8 = uint2(4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e153 = start;
            start = _e153 + TILE_LIST;
        }
        loop_init_5 = false;
        uint _e121 = start;
        if (_e121 < _e118.total) {
        } else {
            break;
        }
        {
            uint _e124 = start;
            uint _e125 = tile_walk_fill(lid, _e118, _e124, bsh_nodes, tile_list, subtree_at, _buffer_sizes);
            j = 0u;
            uint2 loop_bound_9 = uint2(4294967295u);
            bool loop_init_6 = true;
            while(true) {
                if (metal::all(loop_bound_9 == uint2(0u))) { break; }
                loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                if (!loop_init_6) {
                    uint _e151 = j;
                    j = _e151 + 1u;
                }
                loop_init_6 = false;
                uint _e128 = j;
                if (_e128 < _e125) {
                } else {
                    break;
                }
                {
                    uint _e131 = j;
                    uint b_10 = tile_list.inner[_e131];
                    if (!(!(has_3))) {
                        BshNode _e140 = bsh_nodes[b_10];
                        metal::float3 _e141 = r;
                        bool _e142 = bsh_reaches(_e140, x_15, _e141, _e79);
                        local_4 = !(_e142);
                    } else {
                        local_4 = true;
                    }
                    bool _e145 = local_4;
                    if (_e145) {
                        continue;
                    }
                    uint li_7 = bsh_nodes[b_10].light;
                    reservoir_offer(picks, hr, li_7);
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
    uint _e161 = picks.n;
    float _e163 = reservoir_weight(_e161, K);
    uint2 loop_bound_10 = uint2(4294967295u);
    bool loop_init_7 = true;
    while(true) {
        if (metal::all(loop_bound_10 == uint2(0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        if (!loop_init_7) {
            uint _e191 = k;
            k = _e191 + 1u;
        }
        loop_init_7 = false;
        uint _e166 = k;
        uint _e168 = picks.n;
        if (_e166 < metal::min(_e168, K)) {
        } else {
            break;
        }
        {
            uint _e172 = h;
            uint _e173 = pcg_hash(_e172);
            h = _e173;
            uint _e174 = h;
            float _e175 = xi_from_bits(_e174);
            uint _e176 = h;
            uint _e177 = pcg_hash(_e176);
            h = _e177;
            Shaded _e178 = t;
            uint _e180 = k;
            uint _e182 = picks.light.inner[_e180];
            metal::float3 _e183 = n;
            metal::float3 _e184 = r;
            Material _e185 = m;
            uint _e186 = h;
            float _e187 = xi_from_bits(_e186);
            Shaded _e188 = shade_pick(_e182, x_15, _e183, _e184, _e79, _e185, _e163, _e175, _e187, eps_4, slc_table, lights, rt2_3, r2_3, _buffer_sizes);
            Shaded _e189 = add(_e178, _e188);
            t = _e189;
        }
    }
    uint count = picks.n;
    metal::float3 _e197 = t.e;
    out_tex.write(metal::float4(_e197, static_cast<float>(count)), metal::uint2(texel_1));
    return;
}
