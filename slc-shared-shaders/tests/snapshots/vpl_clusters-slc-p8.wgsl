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

struct VplParams {
    width: u32,
    height: u32,
    lights_per_subset: u32,
    min_d2_: f32,
    near_r2_: f32,
    subset_shift: u32,
    far_groups_at: u32,
    near_clusters_at: u32,
    near_groups_at: u32,
    box_count: u32,
    pad0_: u32,
    pad1_: u32,
    far_grid: vec4<u32>,
    near_grid: vec4<u32>,
}

struct GpuBox {
    lo: vec3<f32>,
    pad0_: f32,
    hi: vec3<f32>,
    pad1_: f32,
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
const BOX_THREADS: u32 = 64u;

var<workgroup> wg_lo: array<vec3<f32>, 64>;
var<workgroup> wg_hi: array<vec3<f32>, 64>;
var<workgroup> wg_box: WorkgroupBox;
@group(0) @binding(0) 
var<uniform> params: VplParams;
@group(0) @binding(1) 
var<storage> lights: array<GpuLight>;
@group(0) @binding(2) 
var<storage> r2_3: array<f32>;
@group(0) @binding(3) 
var<storage> near_slots: array<u32>;
@group(0) @binding(4) 
var<storage, read_write> boxes: array<GpuBox>;

fn to_f32_(u: u32) -> f32 {
    return f32(u);
}

fn cull_radius(r2_: f32) -> f32 {
    return (sqrt(r2_) * CULL_RADIUS_SCALE);
}

fn interleave_flux_scale(period: u32) -> f32 {
    let _e2 = to_f32_((period * period));
    return _e2;
}

fn vpl_near_range2_(r2_1: f32, period_1: u32) -> f32 {
    let _e2 = interleave_flux_scale(period_1);
    return (r2_1 / _e2);
}

fn vpl_near_cull_range2_(r2_2: f32, near_r2_: f32) -> f32 {
    return min(r2_2, near_r2_);
}

fn workgroup_bounds(li_1: u32, lo: vec3<f32>, hi: vec3<f32>) -> WorkgroupBox {
    var stride: u32 = 32u;

    wg_lo[li_1] = lo;
    wg_hi[li_1] = hi;
    workgroupBarrier();
    loop {
        let _e9 = stride;
        if (_e9 > 0u) {
        } else {
            break;
        }
        {
            let _e12 = stride;
            if (li_1 < _e12) {
                let _e18 = wg_lo[li_1];
                let _e20 = stride;
                let _e23 = wg_lo[(li_1 + _e20)];
                wg_lo[li_1] = min(_e18, _e23);
                let _e29 = wg_hi[li_1];
                let _e31 = stride;
                let _e34 = wg_hi[(li_1 + _e31)];
                wg_hi[li_1] = max(_e29, _e34);
            }
            workgroupBarrier();
        }
        continuing {
            let _e36 = stride;
            stride = (_e36 / 2u);
        }
    }
    if (li_1 == 0u) {
        let _e44 = wg_lo[0];
        let _e47 = wg_hi[0];
        wg_box = WorkgroupBox(_e44, _e47);
    }
    let _e50 = workgroupUniformLoad((&wg_box));
    return _e50;
}

fn near_r2_of(slot_1: u32) -> f32 {
    let _e3 = r2_3[slot_1];
    let _e5 = vpl_near_range2_(_e3, P);
    return _e5;
}

fn near_cull_r2_of(slot_2: u32, near_r2_1: f32) -> f32 {
    let _e2 = near_r2_of(slot_2);
    let _e3 = vpl_near_cull_range2_(_e2, near_r2_1);
    return _e3;
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(workgroup_id) wg: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    var slot: u32;
    var out: u32;
    var r2_cull: f32;

    let c = ((wg.y * nwg.x) + wg.x);
    let far = params.far_groups_at;
    let _e13 = params.near_groups_at;
    let _e16 = params.near_clusters_at;
    let near = (_e13 - _e16);
    if (c >= (far + near)) {
        return;
    }
    if (c < far) {
        slot = ((c * CLUSTER) + li);
        out = c;
        let _e28 = slot;
        let _e30 = r2_3[_e28];
        r2_cull = _e30;
    } else {
        let _e37 = near_slots[(((c - far) * CLUSTER) + li)];
        slot = _e37;
        let _e40 = params.near_clusters_at;
        out = ((_e40 + c) - far);
        let _e43 = slot;
        let _e46 = params.near_r2_;
        let _e47 = near_cull_r2_of(_e43, _e46);
        r2_cull = _e47;
    }
    let _e49 = slot;
    let l = lights[_e49];
    let lit = any((l.intensity != vec3(0f)));
    let _e57 = r2_cull;
    let _e58 = cull_radius(_e57);
    let _e71 = workgroup_bounds(li, select(vec3(340282350000000000000000000000000000000f), (l.p0_ - vec3(_e58)), lit), select(vec3(-340282350000000000000000000000000000000f), (l.p0_ + vec3(_e58)), lit));
    if (li == 0u) {
        let _e75 = out;
        boxes[_e75] = GpuBox(_e71.lo, 0f, _e71.hi, 0f);
        return;
    } else {
        return;
    }
}
