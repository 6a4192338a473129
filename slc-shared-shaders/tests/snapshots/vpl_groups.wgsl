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
const BOX_THREADS: u32 = 64u;

var<workgroup> wg_lo: array<vec3<f32>, 64>;
var<workgroup> wg_hi: array<vec3<f32>, 64>;
var<workgroup> wg_box: WorkgroupBox;
@group(0) @binding(0) 
var<uniform> params: VplParams;
@group(0) @binding(1) 
var<storage, read_write> boxes: array<GpuBox>;

fn groups_across(bw: u32, gw: u32) -> u32 {
    return (((bw + gw) - 1u) / gw);
}

fn group_count(bw_1: u32, bh: u32, gw_1: u32, gh: u32) -> u32 {
    let _e4 = groups_across(bw_1, gw_1);
    let _e5 = groups_across(bh, gh);
    return (_e4 * _e5);
}

fn group_first(g: u32, bw_2: u32, bh_1: u32, gw_2: u32, gh_1: u32) -> u32 {
    let _e5 = groups_across(bw_2, gw_2);
    let gx = (g % _e5);
    let gy = (g / _e5);
    let h = min(gh_1, (bh_1 - (gh_1 * gy)));
    return (((gy * gh_1) * bw_2) + ((gx * gw_2) * h));
}

fn group_clusters(g_1: u32, bw_3: u32, bh_2: u32, gw_3: u32, gh_2: u32) -> u32 {
    let _e5 = groups_across(bw_3, gw_3);
    let gx_1 = (g_1 % _e5);
    let gy_1 = (g_1 / _e5);
    return (min(gw_3, (bw_3 - (gw_3 * gx_1))) * min(gh_2, (bh_2 - (gh_2 * gy_1))));
}

fn workgroup_bounds(li_1: u32, lo_1: vec3<f32>, hi_1: vec3<f32>) -> WorkgroupBox {
    var stride: u32 = 32u;

    wg_lo[li_1] = lo_1;
    wg_hi[li_1] = hi_1;
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

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(workgroup_id) wg: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    var grid: vec4<u32>;
    var k: u32;
    var clusters: u32;
    var out: u32;
    var lo: vec3<f32> = vec3(340282350000000000000000000000000000000f);
    var hi: vec3<f32> = vec3(-340282350000000000000000000000000000000f);

    let g_2 = ((wg.y * nwg.x) + wg.x);
    let _e10 = params.near_clusters_at;
    let _e13 = params.far_groups_at;
    let far = (_e10 - _e13);
    let _e17 = params.box_count;
    let _e20 = params.near_groups_at;
    let near = (_e17 - _e20);
    if (g_2 >= (far + near)) {
        return;
    }
    if (g_2 < far) {
        let _e31 = params.far_grid;
        grid = _e31;
        let _e33 = grid.x;
        let _e35 = grid.y;
        let _e37 = grid.z;
        let _e39 = grid.w;
        let _e40 = group_count(_e33, _e35, _e37, _e39);
        k = (g_2 % _e40);
        let _e45 = params.lights_per_subset;
        clusters = ((g_2 / _e40) * (_e45 / CLUSTER));
        let _e51 = params.far_groups_at;
        out = (_e51 + g_2);
    } else {
        let _e55 = params.near_grid;
        grid = _e55;
        k = (g_2 - far);
        let _e59 = params.near_clusters_at;
        clusters = _e59;
        let _e62 = params.near_groups_at;
        let _e63 = k;
        out = (_e62 + _e63);
    }
    let _e65 = k;
    let _e67 = grid.x;
    let _e69 = grid.y;
    let _e71 = grid.z;
    let _e73 = grid.w;
    let _e74 = group_clusters(_e65, _e67, _e69, _e71, _e73);
    if (li < _e74) {
        let _e83 = clusters;
        let _e84 = k;
        let _e86 = grid.x;
        let _e88 = grid.y;
        let _e90 = grid.z;
        let _e92 = grid.w;
        let _e93 = group_first(_e84, _e86, _e88, _e90, _e92);
        let b = boxes[((_e83 + _e93) + li)];
        lo = b.lo;
        hi = b.hi;
    }
    let _e100 = lo;
    let _e101 = hi;
    let _e102 = workgroup_bounds(li, _e100, _e101);
    if (li == 0u) {
        let _e106 = out;
        boxes[_e106] = GpuBox(_e102.lo, 0f, _e102.hi, 0f);
        return;
    } else {
        return;
    }
}
