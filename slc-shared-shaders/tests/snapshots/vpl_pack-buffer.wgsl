struct GpuLight {
    p0_: vec3<f32>,
    kind: u32,
    p1_: vec3<f32>,
    a: f32,
    p2_: vec3<f32>,
    b: f32,
    intensity: vec3<f32>,
    ies_base: u32,
}

struct GpuVplRecord {
    position: vec3<f32>,
    pad0_: f32,
    normal: vec3<f32>,
    pad1_: f32,
    flux: vec3<f32>,
    pad2_: f32,
}

struct PackParams {
    count: u32,
    size: u32,
    per_subset: u32,
    mode: u32,
    exposure: f32,
    error_bound: f32,
    scale: f32,
    slc: u32,
    fixed_r2_: f32,
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
const P: u32 = 8u;

@group(0) @binding(0) 
var<uniform> params: PackParams;
@group(0) @binding(1) 
var<storage> records: array<GpuVplRecord>;
@group(0) @binding(4) 
var<storage, read_write> lights: array<GpuLight>;
@group(0) @binding(5) 
var<storage, read_write> ids: array<u32>;
@group(0) @binding(6) 
var<storage, read_write> rt2_: array<f32>;
@group(0) @binding(7) 
var<storage, read_write> r2_: array<f32>;
@group(0) @binding(8) 
var<storage, read_write> near_slots: array<u32>;

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

fn vpl_rt2_(flux_1: vec3<f32>, exposure_1: f32, error_bound_1: f32, mode_1: u32) -> f32 {
    let _e6 = intensity_measure((flux_1 * INV_PI), mode_1);
    let _e7 = threshold_range2_(_e6, exposure_1, error_bound_1);
    return _e7;
}

fn finite3_(v: vec3<f32>) -> bool {
    var local: bool;
    var local_1: bool;

    if (abs(v.x) <= F32_MAX) {
        local = (abs(v.y) <= F32_MAX);
    } else {
        local = false;
    }
    let _e12 = local;
    if _e12 {
        local_1 = (abs(v.z) <= F32_MAX);
    } else {
        local_1 = false;
    }
    let _e20 = local_1;
    return _e20;
}

fn vpl_record_ok(position: vec3<f32>, normal_1: vec3<f32>, flux_2: vec3<f32>) -> bool {
    var local_2: bool;
    var local_3: bool;
    var local_4: bool;
    var local_5: bool;
    var local_6: bool;

    let _e3 = finite3_(position);
    if _e3 {
        let _e6 = finite3_(normal_1);
        local_2 = _e6;
    } else {
        local_2 = false;
    }
    let _e8 = local_2;
    if _e8 {
        let _e11 = finite3_(flux_2);
        local_3 = _e11;
    } else {
        local_3 = false;
    }
    let _e13 = local_3;
    if !(_e13) {
        return false;
    }
    if (flux_2.x >= 0f) {
        local_4 = (flux_2.y >= 0f);
    } else {
        local_4 = false;
    }
    let _e25 = local_4;
    if _e25 {
        local_5 = (flux_2.z >= 0f);
    } else {
        local_5 = false;
    }
    let _e32 = local_5;
    if _e32 {
        local_6 = ((max(max(flux_2.x, flux_2.y), flux_2.z) * INV_PI) <= MAX_INTENSITY);
    } else {
        local_6 = false;
    }
    let _e45 = local_6;
    return _e45;
}

fn interleave_slot_linear(i: u32, per_subset: u32, period: u32) -> u32 {
    let subsets = (period * period);
    return (((i % subsets) * per_subset) + (i / subsets));
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var p: vec3<f32>;
    var normal: vec3<f32>;
    var flux: vec3<f32>;

    let i_1 = gid.x;
    let _e4 = params.count;
    if (i_1 >= _e4) {
        return;
    }
    let r = records[i_1];
    p = r.position;
    normal = r.normal;
    flux = r.flux;
    let _e17 = params.per_subset;
    let _e19 = interleave_slot_linear(i_1, _e17, P);
    let _e20 = p;
    let _e21 = normal;
    let _e22 = flux;
    let _e23 = vpl_record_ok(_e20, _e21, _e22);
    if !(_e23) {
        p = vec3(0f);
        normal = vec3(0f);
        flux = vec3(0f);
    }
    let _e31 = flux;
    let _e34 = params.scale;
    flux = (_e31 * _e34);
    let _e38 = p;
    let _e40 = normal;
    let _e43 = flux;
    lights[_e19] = GpuLight(_e38, LIGHT_VPL, _e40, 0f, vec3(0f), 0f, _e43, 0u);
    ids[_e19] = i_1;
    let _e52 = params.slc;
    let slc = (_e52 != 0u);
    let _e57 = flux;
    let _e60 = params.exposure;
    let _e63 = params.error_bound;
    let _e66 = params.mode;
    let _e67 = vpl_rt2_(_e57, _e60, _e63, _e66);
    rt2_[_e19] = select(0f, _e67, slc);
    let _e74 = params.fixed_r2_;
    r2_[_e19] = select(_e74, 0f, slc);
    near_slots[i_1] = _e19;
    return;
}
