struct TemporalParams {
    float4 c0_;
    float4 c1_;
    float4 c2_;
    float4 c3_;
    float3 prev_eye;
    float max_history;
    uint has_history;
    uint pad0_;
    uint pad1_;
    uint pad2_;
};

struct ViewParams {
    float4 c0_;
    float4 c1_;
    float4 c2_;
    float4 c3_;
    float3 eye;
    uint width;
    uint height;
    float shadow_offset;
    uint seed;
    uint frame;
    float3 f0_d;
    float f90_d;
};

struct GbTexel {
    float4 position;
    float4 normal;
};

static const uint LIGHT_POINT = 0u;
static const uint LIGHT_SPOT = 1u;
static const uint LIGHT_IES = 2u;
static const uint LIGHT_TRIANGLE = 3u;
static const uint LIGHT_VPL = 4u;
static const uint NO_LIGHT = 4294967295u;
static const uint GRID_HEADER = 32u;
static const uint GRID_LEVELS_MAX = 8u;
static const uint GRIDS_MAX = 3u;
static const uint GRID_SORT_MOVES = 1024u;
static const uint GRID_SORT_MAX = 1024u;
static const uint COUNT_TILES = 0u;
static const uint COUNT_GROUP_TESTS = 1u;
static const uint COUNT_CLUSTER_TESTS = 2u;
static const uint COUNT_SPHERE_TESTS = 3u;
static const uint COUNT_TESTED = 4u;
static const uint COUNT_KEPT = 5u;
static const uint COUNT_PIXELS = 6u;
static const uint COUNT_FIELDS = 7u;
static const uint DIRECT_COUNT_PIXELS = 0u;
static const uint DIRECT_COUNT_CANDIDATES = 1u;
static const uint DIRECT_COUNT_EVALUATIONS = 2u;
static const uint DIRECT_COUNT_RAYS = 3u;
static const uint DIRECT_COUNT_NODES = 4u;
static const uint DIRECT_COUNT_FIELDS = 5u;
static const uint MAP_CAMERA = 0u;
static const uint MAP_PERSPECTIVE = 1u;
static const uint MAP_ORTHOGRAPHIC = 2u;
static const float XI_STEP = 5.9604645e-8;
static const uint XI_ROTATED = 2147483648u;
static const uint XI_BITS_SHIFT = 26u;
static const uint XI_INDEX_MASK = 67108863u;
static const uint PICK_STREAM = 2654435769u;
static const float TWO_PI = 6.2831855;
static const float UNRANGED = 1e38;
static const float CULL_RADIUS_SCALE = 1.000001;
static const float SPHERE_PAD = 4.7683716e-7;
static const float SPHERE_HUGE = 3.4028235e38;
static const float SPHERE_PAD_ABS = 1e-18;
static const uint CLUSTER = 64u;
static const uint GROUP_SIDE = 8u;
static const float INV_PI = 0.31830987;
static const float MIN_D2_ = 1e-12;
static const float MAX_INTENSITY = 7.2057594e16;
static const uint BSH_NONE = 4294967295u;
static const uint BSH_TAIL = 2147483648u;
static const uint BSH_TAIL_BINS = 1024u;
static const uint BSH_TAIL_MAX = 64u;
static const uint RESERVOIR_FULL = 4294967295u;
static const float REUSE_TRUST_SCALE = 64.0;
static const float GGX_ALPHA_MIN = 0.001;
static const float RANGE_SCALE_MAX = 64.0;
static const uint LIGHT_BVH_LEAF = 4294967295u;
static const float ONE_MINUS_EPSILON = 0.99999994;
static const float F32_MAX = 3.4028235e38;
static const float DEPTH_NONE = 1e30;
static const float DEPTH_SIGMA = 0.05;
static const float COVER_WEIGHT = 0.1;
static const uint ROULETTE_DEPTH = 2u;
static const float TEMPORAL_MAX_HISTORY = 32.0;
static const float TEMPORAL_DEPTH_TOLERANCE = 0.01;
static const float TEMPORAL_MOTION_DEPTH_TOLERANCE = 0.05;
static const float TEMPORAL_NORMAL_COS = 0.9;
static const float TEMPORAL_MIN_MOMENTS = 8.0;
static const float TEMPORAL_CHANGED_HISTORY = 1.0;
static const float TEMPORAL_CHANGE_LOW = 4.0;
static const float TEMPORAL_CHANGE_HIGH = 8.0;
static const float TEMPORAL_MIN_WEIGHT = 0.01;

cbuffer view : register(b0) { ViewParams view; }
Texture2D<float4> position_tex : register(t1);
Texture2D<float4> normal_tex : register(t2);
cbuffer params : register(b3) { TemporalParams params; }
Texture2D<float4> signal_tex : register(t4);
Texture2D<float4> hist_value : register(t5);
Texture2D<float4> hist_noise : register(t6);
Texture2D<float4> hist_surface : register(t7);
RWTexture2D<float4> out_tex : register(u8);
RWTexture2D<float4> next_value : register(u9);
RWTexture2D<float4> next_noise : register(u10);
RWTexture2D<float4> next_surface : register(u11);

float to_f32_(uint u)
{
    return float(u);
}

float luminance(float3 c)
{
    return dot(c, float3(0.2126, 0.7152, 0.0722));
}

float3 reproject(float4 c0_, float4 c1_, float4 c2_, float4 c3_, float3 p, float width, float height)
{
    float4 clip_ = ((((c0_ * p.x) + (c1_ * p.y)) + (c2_ * p.z)) + c3_);
    if ((clip_.w <= 0.0)) {
        return float3(-1.0, -1.0, 0.0);
    }
    float x = (((((clip_.x / clip_.w) + 1.0) * 0.5) * width) - 0.5);
    float y = ((((1.0 - (clip_.y / clip_.w)) * 0.5) * height) - 0.5);
    return float3(x, y, clip_.w);
}

float bilinear_weight(float fx, float fy, uint dx, uint dy)
{
    float wx = ((dx == 1u) ? fx : (1.0 - fx));
    float wy = ((dy == 1u) ? fy : (1.0 - fy));
    return (wx * wy);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

float4 history_tap(float3 q, uint k_1, float width_1, float height_1)
{
    bool local_1 = (bool)0;
    bool local_2 = (bool)0;
    bool local_3 = (bool)0;
    bool local_4 = (bool)0;

    float x0_ = floor(q.x);
    float y0_ = floor(q.y);
    uint dx_1 = naga_mod(k_1, 2u);
    uint dy_1 = naga_div(k_1, 2u);
    const float _e12 = to_f32_(dx_1);
    float tx = (x0_ + _e12);
    const float _e14 = to_f32_(dy_1);
    float ty = (y0_ + _e14);
    if ((q.z > 0.0)) {
        local_1 = (tx >= 0.0);
    } else {
        local_1 = false;
    }
    bool _e24 = local_1;
    if (_e24) {
        local_2 = (ty >= 0.0);
    } else {
        local_2 = false;
    }
    bool _e30 = local_2;
    if (_e30) {
        local_3 = (tx < width_1);
    } else {
        local_3 = false;
    }
    bool _e35 = local_3;
    if (_e35) {
        local_4 = (ty < height_1);
    } else {
        local_4 = false;
    }
    bool inside = local_4;
    const float _e45 = bilinear_weight((q.x - x0_), (q.y - y0_), dx_1, dy_1);
    return float4(tx, ty, _e45, (inside ? 1.0 : 0.0));
}

float4 history_mean(float4 sum, float weight_1)
{
    if ((weight_1 < TEMPORAL_MIN_WEIGHT)) {
        return float4(0.0, 0.0, 0.0, 0.0);
    }
    return (sum / (weight_1).xxxx);
}

bool history_matches(float3 n, float3 nh, float3 p_1, float oh, float d)
{
    bool local_5 = (bool)0;

    if ((abs((dot(nh, p_1) - oh)) <= (TEMPORAL_DEPTH_TOLERANCE * d))) {
        local_5 = (dot(n, nh) >= TEMPORAL_NORMAL_COS);
    } else {
        local_5 = false;
    }
    bool _e17 = local_5;
    return _e17;
}

float temporal_change(float l, float m1_, float noise_, float n_1)
{
    if ((n_1 < TEMPORAL_MIN_MOMENTS)) {
        return 0.0;
    }
    float sigma = sqrt((max(noise_, 0.0) * (1.0 + (1.0 / n_1))));
    float t = (abs((l - m1_)) / ((sigma + (0.001 * max(abs(l), abs(m1_)))) + 1e-20));
    return clamp(((t - TEMPORAL_CHANGE_LOW) / 4.0), 0.0, 1.0);
}

float next_history_length(float n_2, float lambda, float max_history)
{
    return min((((1.0 - lambda) * n_2) + 1.0), max(max_history, 1.0));
}

float temporal_alpha(float n_3)
{
    return (1.0 / max(n_3, 1.0));
}

float history_tap_weight(float w, float3 n_4, float3 nh_1, float3 p_2, float oh_1, float d_1, float len)
{
    bool local_6 = (bool)0;

    if ((len > 0.0)) {
        const bool _e11 = history_matches(n_4, nh_1, p_2, oh_1, d_1);
        local_6 = _e11;
    } else {
        local_6 = false;
    }
    bool _e13 = local_6;
    return (_e13 ? w : 0.0);
}

float persistent_change(float l_1, float last, float m1_1, float noise_1, float n_5)
{
    if ((((l_1 - m1_1) * (last - m1_1)) <= 0.0)) {
        return 0.0;
    }
    const float _e11 = temporal_change(l_1, m1_1, noise_1, n_5);
    const float _e12 = temporal_change(last, m1_1, noise_1, n_5);
    return min(_e11, _e12);
}

float4 temporal_color(float3 c_1, float4 h, float noise_2, float last_1, float max_history_1)
{
    float3 hc = float3(h.x, h.y, h.z);
    const float _e9 = luminance(c_1);
    const float _e10 = luminance(hc);
    const float _e12 = persistent_change(_e9, last_1, _e10, noise_2, h.w);
    const float _e14 = next_history_length(h.w, _e12, max_history_1);
    const float _e15 = temporal_alpha(_e14);
    float3 v_1 = ((hc * (1.0 - _e15)) + (c_1 * _e15));
    return float4(v_1.x, v_1.y, v_1.z, _e14);
}

float4 temporal_moments(float3 c_2, float last_2, float noise_3, float prev_len, float len_1, float depth)
{
    bool local_7 = (bool)0;

    const float _e6 = luminance(c_2);
    if ((prev_len <= 0.0)) {
        return float4(_e6, 0.0, depth, 0.0);
    }
    float d_2 = (_e6 - last_2);
    float d2_ = ((0.5 * d_2) * d_2);
    float cap = (16.0 * noise_3);
    if ((prev_len >= TEMPORAL_MIN_MOMENTS)) {
        local_7 = (noise_3 > 0.0);
    } else {
        local_7 = false;
    }
    bool _e26 = local_7;
    float sample_ = (_e26 ? min(d2_, cap) : d2_);
    const float _e31 = temporal_alpha((len_1 - 1.0));
    return float4(_e6, (noise_3 + ((sample_ - noise_3) * _e31)), depth, 0.0);
}

float4 surface_at(int2 texel)
{
    float4 p_3 = position_tex.Load(int3(texel, int(0)));
    return ((p_3.w > 0.0) ? float4(p_3.xyz, 1.0) : (0.0).xxxx);
}

GbTexel ConstructGbTexel(float4 arg0, float4 arg1) {
    GbTexel ret = (GbTexel)0;
    ret.position = arg0;
    ret.normal = arg1;
    return ret;
}

GbTexel gbuffer_at(uint i)
{
    bool local_8 = (bool)0;

    uint _e3 = view.width;
    uint _e8 = view.width;
    int2 texel_1 = int2(int(naga_mod(i, _e3)), int(naga_div(i, _e8)));
    const float4 _e12 = surface_at(texel_1);
    float4 _e15 = normal_tex.Load(int3(texel_1, int(0)));
    float3 n_6 = _e15.xyz;
    float len2_ = dot(n_6, n_6);
    if ((_e12.w > 0.0)) {
        local_8 = (len2_ > 0.0);
    } else {
        local_8 = false;
    }
    bool valid = local_8;
    float3 _e30 = view.eye;
    float3 v_2 = (_e12.xyz - _e30);
    float4 position = float4(_e12.xyz, (valid ? 1.0 : 0.0));
    float4 normal = (valid ? float4((n_6 / (sqrt(len2_)).xxx), sqrt(dot(v_2, v_2))) : float4(0.0, 0.0, 0.0, 1e30));
    const GbTexel gbtexel = ConstructGbTexel(position, normal);
    return gbtexel;
}

int naga_f2i32(float value) {
    return int(clamp(value, -2147483600.0, 2147483500.0));
}

[numthreads(8, 8, 1)]
void main(uint3 gid : SV_DispatchThreadID)
{
    bool local = (bool)0;
    float4 hv = (0.0).xxxx;
    float4 hn = (0.0).xxxx;
    float4 v = (0.0).xxxx;
    float4 m = (0.0).xxxx;
    float weight = 0.0;
    uint k = 0u;

    uint _e4 = view.width;
    if (!((gid.x >= _e4))) {
        uint _e12 = view.height;
        local = (gid.y >= _e12);
    } else {
        local = true;
    }
    bool _e15 = local;
    if (_e15) {
        return;
    }
    int2 texel_2 = int2(int(gid.x), int(gid.y));
    uint _e24 = view.width;
    const GbTexel _e28 = gbuffer_at(((gid.y * _e24) + gid.x));
    float4 _e31 = signal_tex.Load(int3(texel_2, int(0)));
    float3 c_3 = _e31.xyz;
    if ((_e28.position.w <= 0.0)) {
        out_tex[texel_2] = float4(c_3, 0.0);
        next_value[texel_2] = float4(c_3, 0.0);
        next_noise[texel_2] = (0.0).xxxx;
        next_surface[texel_2] = (0.0).xxxx;
        return;
    }
    float3 p_4 = _e28.position.xyz;
    float3 n_7 = _e28.normal.xyz;
    float4 _e61 = params.c0_;
    float4 _e64 = params.c1_;
    float4 _e67 = params.c2_;
    float4 _e70 = params.c3_;
    uint _e73 = view.width;
    uint _e77 = view.height;
    const float3 _e79 = reproject(_e61, _e64, _e67, _e70, p_4, float(_e73), float(_e77));
    uint _e82 = params.has_history;
    if ((_e82 == 1u)) {
        float3 _e87 = params.prev_eye;
        float d_3 = length((p_4 - _e87));
        uint2 loop_bound = uint2(4294967295u, 4294967295u);
        bool loop_init = true;
        while(true) {
            if (all(loop_bound == uint2(0u, 0u))) { break; }
            loop_bound -= uint2(loop_bound.y == 0u, 1u);
            if (!loop_init) {
                uint _e144 = k;
                k = (_e144 + 1u);
            }
            loop_init = false;
            uint _e100 = k;
            if ((_e100 < 4u)) {
            } else {
                break;
            }
            {
                uint _e103 = k;
                uint _e106 = view.width;
                uint _e110 = view.height;
                const float4 _e112 = history_tap(_e79, _e103, float(_e106), float(_e110));
                if ((_e112.w > 0.0)) {
                    int2 t_1 = int2(naga_f2i32(_e112.x), naga_f2i32(_e112.y));
                    float4 tv = hist_value.Load(int3(t_1, int(0)));
                    float4 ts = hist_surface.Load(int3(t_1, int(0)));
                    float4 tn = hist_noise.Load(int3(t_1, int(0)));
                    const float _e134 = history_tap_weight(_e112.z, n_7, ts.xyz, p_4, ts.w, d_3, tv.w);
                    float4 _e135 = v;
                    v = (_e135 + (tv * _e134));
                    float4 _e138 = m;
                    m = (_e138 + (tn * _e134));
                    float _e141 = weight;
                    weight = (_e141 + _e134);
                }
            }
        }
        float4 _e146 = v;
        float _e147 = weight;
        const float4 _e148 = history_mean(_e146, _e147);
        hv = _e148;
        float4 _e149 = m;
        float _e150 = weight;
        const float4 _e151 = history_mean(_e149, _e150);
        hn = _e151;
    }
    float4 _e152 = hv;
    float _e154 = hn.y;
    float _e156 = hn.x;
    float _e159 = params.max_history;
    const float4 _e160 = temporal_color(c_3, _e152, _e154, _e156, _e159);
    out_tex[texel_2] = _e160;
    next_value[texel_2] = _e160;
    float _e165 = hn.x;
    float _e167 = hn.y;
    float _e169 = hv.w;
    float3 _e173 = view.eye;
    const float4 _e176 = temporal_moments(c_3, _e165, _e167, _e169, _e160.w, length((p_4 - _e173)));
    next_noise[texel_2] = _e176;
    next_surface[texel_2] = float4(n_7, dot(n_7, p_4));
    return;
}
