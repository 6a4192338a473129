struct CullParams {
    light_count: u32,
    seed: u32,
    frame: u32,
    slc: u32,
    mode: u32,
    exposure: f32,
    error_bound: f32,
    fixed_r2_: f32,
    unculled: f32,
    pad0_: u32,
    pad1_: u32,
    pad2_: u32,
}

const LIGHT_POINT: u32 = 0u;
const LIGHT_SPOT: u32 = 1u;
const LIGHT_IES: u32 = 2u;
const LIGHT_TRIANGLE: u32 = 3u;
const LIGHT_VPL: u32 = 4u;
const NO_LIGHT: u32 = 4294967295u;
const GRID_HEADER: u32 = 32u;
const GRID_LEVELS_MAX: u32 = 8u;
const GRIDS_MAX: u32 = 3u;
const GRID_SORT_MOVES: u32 = 1024u;
const GRID_SORT_MAX: u32 = 1024u;
const COUNT_TILES: u32 = 0u;
const COUNT_GROUP_TESTS: u32 = 1u;
const COUNT_CLUSTER_TESTS: u32 = 2u;
const COUNT_SPHERE_TESTS: u32 = 3u;
const COUNT_TESTED: u32 = 4u;
const COUNT_KEPT: u32 = 5u;
const COUNT_PIXELS: u32 = 6u;
const COUNT_FIELDS: u32 = 7u;
const DIRECT_COUNT_PIXELS: u32 = 0u;
const DIRECT_COUNT_CANDIDATES: u32 = 1u;
const DIRECT_COUNT_EVALUATIONS: u32 = 2u;
const DIRECT_COUNT_RAYS: u32 = 3u;
const DIRECT_COUNT_NODES: u32 = 4u;
const DIRECT_COUNT_FIELDS: u32 = 5u;
const MAP_CAMERA: u32 = 0u;
const MAP_PERSPECTIVE: u32 = 1u;
const MAP_ORTHOGRAPHIC: u32 = 2u;
const XI_STEP: f32 = 0.000000059604645f;
const XI_ROTATED: u32 = 2147483648u;
const XI_BITS_SHIFT: u32 = 26u;
const XI_INDEX_MASK: u32 = 67108863u;
const PICK_STREAM: u32 = 2654435769u;
const TWO_PI: f32 = 6.2831855f;
const UNRANGED: f32 = 100000000000000000000000000000000000000f;
const CULL_RADIUS_SCALE: f32 = 1.000001f;
const SPHERE_PAD: f32 = 0.00000047683716f;
const SPHERE_HUGE: f32 = 340282350000000000000000000000000000000f;
const SPHERE_PAD_ABS: f32 = 0.000000000000000001f;
const CLUSTER: u32 = 64u;
const GROUP_SIDE: u32 = 8u;
const INV_PI: f32 = 0.31830987f;
const MIN_D2_: f32 = 0.000000000001f;
const MAX_INTENSITY: f32 = 72057594000000000f;
const BSH_NONE: u32 = 4294967295u;
const BSH_TAIL: u32 = 2147483648u;
const BSH_TAIL_BINS: u32 = 1024u;
const BSH_TAIL_MAX: u32 = 64u;
const RESERVOIR_FULL: u32 = 4294967295u;
const REUSE_TRUST_SCALE: f32 = 64f;
const GGX_ALPHA_MIN: f32 = 0.001f;
const RANGE_SCALE_MAX: f32 = 64f;
const LIGHT_BVH_LEAF: u32 = 4294967295u;
const ONE_MINUS_EPSILON: f32 = 0.99999994f;
const F32_MAX: f32 = 340282350000000000000000000000000000000f;
const DEPTH_NONE: f32 = 1000000000000000000000000000000f;
const DEPTH_SIGMA: f32 = 0.05f;
const COVER_WEIGHT: f32 = 0.1f;
const ROULETTE_DEPTH: u32 = 2u;
const TEMPORAL_MAX_HISTORY: f32 = 32f;
const TEMPORAL_DEPTH_TOLERANCE: f32 = 0.01f;
const TEMPORAL_MOTION_DEPTH_TOLERANCE: f32 = 0.05f;
const TEMPORAL_NORMAL_COS: f32 = 0.9f;
const TEMPORAL_MIN_MOMENTS: f32 = 8f;
const TEMPORAL_CHANGED_HISTORY: f32 = 1f;
const TEMPORAL_CHANGE_LOW: f32 = 4f;
const TEMPORAL_CHANGE_HIGH: f32 = 8f;
const TEMPORAL_MIN_WEIGHT: f32 = 0.01f;

@group(0) @binding(0) 
var<uniform> params: CullParams;
@group(0) @binding(1) 
var<storage> peaks: array<vec4<f32>>;
@group(0) @binding(2) 
var<storage, read_write> rt2_2: array<f32>;
@group(0) @binding(3) 
var<storage, read_write> r2_: array<f32>;

fn to_f32_(u: u32) -> f32 {
    return f32(u);
}

fn mul_lo_u32_(a: u32, b: u32) -> u32 {
    return (a * b);
}

fn add_wrap_u32_(a_1: u32, b_1: u32) -> u32 {
    return (a_1 + b_1);
}

fn xi_from_bits(bits: u32) -> f32 {
    let _e3 = to_f32_((bits >> 8u));
    return (_e3 * XI_STEP);
}

fn pcg_hash(x: u32) -> u32 {
    let _e2 = mul_lo_u32_(x, 747796405u);
    let _e4 = add_wrap_u32_(_e2, 2891336453u);
    let _e12 = mul_lo_u32_(((_e4 >> ((_e4 >> 28u) + 4u)) ^ _e4), 277803737u);
    return ((_e12 >> 22u) ^ _e12);
}

fn laine_karras(x_1: u32, seed: u32) -> u32 {
    var v: u32;

    let _e2 = add_wrap_u32_(x_1, seed);
    v = _e2;
    let _e4 = v;
    let _e5 = v;
    let _e7 = mul_lo_u32_(_e5, 1817228412u);
    v = (_e4 ^ _e7);
    let _e9 = v;
    let _e10 = v;
    let _e12 = mul_lo_u32_(_e10, 3090095698u);
    v = (_e9 ^ _e12);
    let _e14 = v;
    let _e15 = v;
    let _e17 = mul_lo_u32_(_e15, 3350193720u);
    v = (_e14 ^ _e17);
    let _e19 = v;
    let _e20 = v;
    let _e22 = mul_lo_u32_(_e20, 2367878886u);
    v = (_e19 ^ _e22);
    let _e24 = v;
    return _e24;
}

fn reverse_bits(x_2: u32) -> u32 {
    var v_1: u32;

    v_1 = (((x_2 >> 16u) & 65535u) | ((x_2 & 65535u) << 16u));
    let _e11 = v_1;
    let _e16 = v_1;
    v_1 = (((_e11 >> 8u) & 16711935u) | ((_e16 & 16711935u) << 8u));
    let _e22 = v_1;
    let _e27 = v_1;
    v_1 = (((_e22 >> 4u) & 252645135u) | ((_e27 & 252645135u) << 4u));
    let _e33 = v_1;
    let _e38 = v_1;
    v_1 = (((_e33 >> 2u) & 858993459u) | ((_e38 & 858993459u) << 2u));
    let _e44 = v_1;
    let _e49 = v_1;
    v_1 = (((_e44 >> 1u) & 1431655765u) | ((_e49 & 1431655765u) << 1u));
    let _e55 = v_1;
    return _e55;
}

fn xi_for(seed_1: u32, frame: u32, light: u32) -> f32 {
    let _e3 = pcg_hash(seed_1);
    let _e4 = pcg_hash(_e3);
    let _e6 = pcg_hash((_e4 ^ light));
    let _e7 = pcg_hash(_e6);
    let _e8 = reverse_bits(frame);
    let _e9 = laine_karras(_e8, _e7);
    let _e11 = laine_karras(0u, _e7);
    let _e13 = add_wrap_u32_(_e6, (_e9 ^ _e11));
    let _e14 = xi_from_bits(_e13);
    return _e14;
}

fn random_range2_(rt2_: f32, xi: f32) -> f32 {
    return (rt2_ / (1f - xi));
}

fn threshold_range2_(intensity: f32, exposure: f32, error_bound: f32) -> f32 {
    if (intensity <= 0f) {
        return 0f;
    }
    return (((exposure / error_bound) * intensity) / TWO_PI);
}

fn intensity_measure(rgb: vec3<f32>, mode: u32) -> f32 {
    if (mode == 1u) {
        return (((rgb.x + rgb.y) + rgb.z) / 3f);
    }
    return max(rgb.x, max(rgb.y, rgb.z));
}

fn record_rt2_(peak: vec3<f32>, slc: u32, mode_1: u32, exposure_1: f32, error_bound_1: f32, unculled: f32) -> f32 {
    if (slc == 1u) {
        let _e8 = intensity_measure(peak, mode_1);
        let _e9 = threshold_range2_(_e8, exposure_1, error_bound_1);
        return _e9;
    }
    return unculled;
}

fn record_r2_(rt2_1: f32, slc_1: u32, fixed_r2_: f32, xi_1: f32) -> f32 {
    if (slc_1 == 1u) {
        let _e6 = random_range2_(rt2_1, xi_1);
        return _e6;
    }
    return fixed_r2_;
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    let _e4 = params.light_count;
    if (i >= _e4) {
        return;
    }
    let _e8 = peaks[i];
    let _e12 = params.slc;
    let _e15 = params.mode;
    let _e18 = params.exposure;
    let _e21 = params.error_bound;
    let _e24 = params.unculled;
    let _e25 = record_rt2_(_e8.xyz, _e12, _e15, _e18, _e21, _e24);
    rt2_2[i] = _e25;
    let _e32 = params.slc;
    let _e35 = params.fixed_r2_;
    let _e38 = params.seed;
    let _e41 = params.frame;
    let _e42 = xi_for(_e38, _e41, i);
    let _e43 = record_r2_(_e25, _e32, _e35, _e42);
    r2_[i] = _e43;
    return;
}
