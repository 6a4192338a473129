struct FrameParams {
    light_count: u32,
    seed: u32,
    frame: u32,
    fixed_xi: f32,
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
var<uniform> params: FrameParams;
@group(0) @binding(1) 
var<storage> ids: array<u32>;
@group(0) @binding(2) 
var<storage> rt2_1: array<f32>;
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

fn xi_rotated(seed_2: u32, frame_1: u32, light_1: u32, bits_1: u32) -> f32 {
    let _e4 = pcg_hash(seed_2);
    let _e7 = pcg_hash((_e4 ^ 1013904223u));
    let _e8 = laine_karras(light_1, _e7);
    let _e13 = pcg_hash((_e7 ^ light_1));
    let o = ((_e8 << (32u - bits_1)) | (_e13 >> bits_1));
    let _e16 = pcg_hash(_e7);
    let _e17 = reverse_bits(frame_1);
    let _e18 = laine_karras(_e17, _e16);
    let _e20 = laine_karras(0u, _e16);
    let t = (_e18 ^ _e20);
    let _e22 = add_wrap_u32_(o, t);
    let _e23 = xi_from_bits(_e22);
    return _e23;
}

fn light_xi(seed_3: u32, frame_2: u32, key: u32) -> f32 {
    if (key >= XI_ROTATED) {
        let _e13 = xi_rotated(seed_3, frame_2, (key & XI_INDEX_MASK), max(((key >> XI_BITS_SHIFT) & 31u), 1u));
        return _e13;
    }
    let _e14 = xi_for(seed_3, frame_2, key);
    return _e14;
}

fn frame_xi(seed_4: u32, frame_3: u32, key_1: u32, fixed: f32) -> f32 {
    if (fixed >= 0f) {
        return fixed;
    }
    let _e6 = light_xi(seed_4, frame_3, key_1);
    return _e6;
}

fn random_range2_(rt2_: f32, xi: f32) -> f32 {
    return (rt2_ / (1f - xi));
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    let _e4 = params.light_count;
    if (i >= _e4) {
        return;
    }
    let _e10 = rt2_1[i];
    let _e13 = params.seed;
    let _e16 = params.frame;
    let _e19 = ids[i];
    let _e22 = params.fixed_xi;
    let _e23 = frame_xi(_e13, _e16, _e19, _e22);
    let _e24 = random_range2_(_e10, _e23);
    r2_[i] = _e24;
    return;
}
