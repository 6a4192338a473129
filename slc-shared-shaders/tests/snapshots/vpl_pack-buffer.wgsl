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

struct GpuNearBox {
    lo: vec3<f32>,
    pad0_: f32,
    hi: vec3<f32>,
    pad1_: f32,
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

struct WorkgroupBox {
    lo: vec3<f32>,
    hi: vec3<f32>,
}

const LIGHT_POINT: u32 = 0u;
const LIGHT_SPOT: u32 = 1u;
const LIGHT_IES: u32 = 2u;
const LIGHT_TRIANGLE: u32 = 3u;
const LIGHT_VPL: u32 = 4u;
const NO_LIGHT: u32 = 4294967295u;
const MAP_CAMERA: u32 = 0u;
const MAP_PERSPECTIVE: u32 = 1u;
const MAP_ORTHOGRAPHIC: u32 = 2u;
const XI_STEP: f32 = 0.000000059604645f;
const PICK_STREAM: u32 = 2654435769u;
const TWO_PI: f32 = 6.2831855f;
const CULL_RADIUS_SCALE: f32 = 1.000001f;
const SPHERE_PAD: f32 = 0.00000047683716f;
const SPHERE_HUGE: f32 = 340282350000000000000000000000000000000f;
const SPHERE_PAD_ABS: f32 = 0.000000000000000001f;
const INV_PI: f32 = 0.31830987f;
const MIN_D2_: f32 = 0.000000000001f;
const MAX_INTENSITY: f32 = 72057594000000000f;
const BSH_NONE: u32 = 4294967295u;
const RESERVOIR_FULL: u32 = 4294967295u;
const GGX_ALPHA_MIN: f32 = 0.001f;
const RANGE_SCALE_MAX: f32 = 64f;
const LIGHT_BVH_LEAF: u32 = 4294967295u;
const ONE_MINUS_EPSILON: f32 = 0.99999994f;
const F32_MAX: f32 = 340282350000000000000000000000000000000f;
const DEPTH_NONE: f32 = 1000000000000000000000000000000f;
const DEPTH_SIGMA: f32 = 0.05f;
const COVER_WEIGHT: f32 = 0.1f;
const NEAR_BLOCK: u32 = 64u;
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
const BOX_THREADS: u32 = 64u;

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
@group(0) @binding(9) 
var<storage, read_write> near_boxes: array<GpuNearBox>;
var<workgroup> wg_lo: array<vec3<f32>, 64>;
var<workgroup> wg_hi: array<vec3<f32>, 64>;

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
    var local_1: bool;
    var local_2: bool;

    if (abs(v.x) <= F32_MAX) {
        local_1 = (abs(v.y) <= F32_MAX);
    } else {
        local_1 = false;
    }
    let _e12 = local_1;
    if _e12 {
        local_2 = (abs(v.z) <= F32_MAX);
    } else {
        local_2 = false;
    }
    let _e20 = local_2;
    return _e20;
}

fn vpl_record_ok(position_1: vec3<f32>, normal_1: vec3<f32>, flux_2: vec3<f32>) -> bool {
    var local_3: bool;
    var local_4: bool;
    var local_5: bool;
    var local_6: bool;
    var local_7: bool;

    let _e3 = finite3_(position_1);
    if _e3 {
        let _e6 = finite3_(normal_1);
        local_3 = _e6;
    } else {
        local_3 = false;
    }
    let _e8 = local_3;
    if _e8 {
        let _e11 = finite3_(flux_2);
        local_4 = _e11;
    } else {
        local_4 = false;
    }
    let _e13 = local_4;
    if !(_e13) {
        return false;
    }
    if (flux_2.x >= 0f) {
        local_5 = (flux_2.y >= 0f);
    } else {
        local_5 = false;
    }
    let _e25 = local_5;
    if _e25 {
        local_6 = (flux_2.z >= 0f);
    } else {
        local_6 = false;
    }
    let _e32 = local_6;
    if _e32 {
        local_7 = ((max(max(flux_2.x, flux_2.y), flux_2.z) * INV_PI) <= MAX_INTENSITY);
    } else {
        local_7 = false;
    }
    let _e45 = local_7;
    return _e45;
}

fn interleave_slot_linear(i: u32, per_subset: u32, period: u32) -> u32 {
    let subsets = (period * period);
    return (((i % subsets) * per_subset) + (i / subsets));
}

fn workgroup_box(li_1: u32, p_1: vec3<f32>, has: bool) -> WorkgroupBox {
    var stride: u32 = 32u;

    wg_lo[li_1] = select(vec3(340282350000000000000000000000000000000f), p_1, has);
    wg_hi[li_1] = select(vec3(-340282350000000000000000000000000000000f), p_1, has);
    workgroupBarrier();
    loop {
        let _e15 = stride;
        if (_e15 > 0u) {
        } else {
            break;
        }
        {
            let _e18 = stride;
            if (li_1 < _e18) {
                let _e24 = wg_lo[li_1];
                let _e26 = stride;
                let _e29 = wg_lo[(li_1 + _e26)];
                wg_lo[li_1] = min(_e24, _e29);
                let _e35 = wg_hi[li_1];
                let _e37 = stride;
                let _e40 = wg_hi[(li_1 + _e37)];
                wg_hi[li_1] = max(_e35, _e40);
            }
            workgroupBarrier();
        }
        continuing {
            let _e42 = stride;
            stride = (_e42 / 2u);
        }
    }
    let _e47 = wg_lo[0];
    let _e50 = wg_hi[0];
    return WorkgroupBox(_e47, _e50);
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    var position: vec3<f32> = vec3(0f);
    var lit: bool = false;
    var p: vec3<f32>;
    var normal: vec3<f32>;
    var flux: vec3<f32>;
    var local: bool;

    let i_1 = gid.x;
    let _e6 = params.count;
    let inside = (i_1 < _e6);
    if inside {
        let r = records[i_1];
        p = r.position;
        normal = r.normal;
        flux = r.flux;
        let _e24 = params.per_subset;
        let _e26 = interleave_slot_linear(i_1, _e24, P);
        let _e27 = p;
        let _e28 = normal;
        let _e29 = flux;
        let _e30 = vpl_record_ok(_e27, _e28, _e29);
        if !(_e30) {
            p = vec3(0f);
            normal = vec3(0f);
            flux = vec3(0f);
        }
        let _e38 = p;
        position = _e38;
        let _e39 = flux;
        let _e42 = params.scale;
        flux = (_e39 * _e42);
        let _e46 = position;
        let _e48 = normal;
        let _e51 = flux;
        lights[_e26] = GpuLight(_e46, LIGHT_VPL, _e48, 0f, vec3(0f), 0f, _e51, 0u);
        ids[_e26] = i_1;
        let _e60 = params.slc;
        let slc = (_e60 != 0u);
        let _e65 = flux;
        let _e68 = params.exposure;
        let _e71 = params.error_bound;
        let _e74 = params.mode;
        let _e75 = vpl_rt2_(_e65, _e68, _e71, _e74);
        rt2_[_e26] = select(0f, _e75, slc);
        let _e82 = params.fixed_r2_;
        r2_[_e26] = select(_e82, 0f, slc);
        near_slots[i_1] = _e26;
        let _e87 = flux;
        lit = any((_e87 != vec3(0f)));
    }
    let _e92 = position;
    let _e93 = lit;
    let _e94 = workgroup_box(li, _e92, _e93);
    if (li == 0u) {
        local = inside;
    } else {
        local = false;
    }
    let _e100 = local;
    if _e100 {
        near_boxes[wg.x] = GpuNearBox(_e94.lo, 0f, _e94.hi, 0f);
        return;
    } else {
        return;
    }
}
