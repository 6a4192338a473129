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

struct Window {
    sum: vec3<f32>,
    weight: f32,
    covered: u32,
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
const PERIOD: u32 = 8u;

@group(0) @binding(0) 
var<uniform> params: VplParams;
@group(0) @binding(1) 
var<storage> guide: array<vec4<f32>>;
@group(0) @binding(2) 
var<storage> irradiance: array<vec4<f32>>;
@group(0) @binding(3) 
var<storage, read_write> filtered: array<vec4<f32>>;

fn inv_sigma_z(z: f32) -> f32 {
    return (1f / (DEPTH_SIGMA * z));
}

fn window_start(x: u32, size: u32) -> u32 {
    let half = (size / 2u);
    return (max(x, half) - half);
}

fn window_end(x_1: u32, size_1: u32, extent: u32) -> u32 {
    return min(((x_1 + size_1) - (size_1 / 2u)), extent);
}

fn wide_window(period: u32) -> u32 {
    return (2u * period);
}

fn misses_subset(covered: u32, period_1: u32) -> bool {
    return (covered < (period_1 * period_1));
}

fn filtered_irradiance(e: vec3<f32>, sum: vec3<f32>, weight: f32) -> vec3<f32> {
    if (weight > 0f) {
        return (sum / vec3(weight));
    }
    return e;
}

fn bilateral_weight(n: vec3<f32>, nj: vec3<f32>, z_1: f32, zj: f32, inv_sz: f32) -> f32 {
    let dn = max(dot(n, nj), 0f);
    let dn2_ = (dn * dn);
    let dn4_ = (dn2_ * dn2_);
    let dn8_ = (dn4_ * dn4_);
    let d = ((zj - z_1) * inv_sz);
    let t = max((1f - (d * d)), 0f);
    return (((dn8_ * dn8_) * t) * t);
}

fn window_sum(x_2: u32, y: u32, size_2: u32, n_1: vec3<f32>, z_2: f32, inv: f32) -> Window {
    var win: Window;
    var yy: u32;
    var xx: u32;

    let w = params.width;
    let h = params.height;
    let _e12 = window_start(x_2, size_2);
    let _e13 = window_end(x_2, size_2, w);
    let _e14 = window_start(y, size_2);
    let _e15 = window_end(y, size_2, h);
    win.sum = vec3(0f);
    win.weight = 0f;
    win.covered = 0u;
    yy = _e14;
    loop {
        let _e25 = yy;
        if (_e25 < _e15) {
        } else {
            break;
        }
        {
            xx = _e12;
            loop {
                let _e28 = xx;
                if (_e28 < _e13) {
                } else {
                    break;
                }
                {
                    let _e30 = yy;
                    let _e32 = xx;
                    let j = ((_e30 * w) + _e32);
                    let g = guide[j];
                    let _e39 = bilateral_weight(n_1, g.xyz, z_2, g.w, inv);
                    let _e41 = win.sum;
                    let _e44 = irradiance[j];
                    win.sum = (_e41 + (_e44.xyz * _e39));
                    let _e49 = win.weight;
                    win.weight = (_e49 + _e39);
                    let _e52 = win.covered;
                    win.covered = (_e52 + select(0u, 1u, (_e39 > COVER_WEIGHT)));
                }
                continuing {
                    let _e60 = xx;
                    xx = (_e60 + 1u);
                }
            }
        }
        continuing {
            let _e63 = yy;
            yy = (_e63 + 1u);
        }
    }
    let _e65 = win;
    return _e65;
}

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var local: bool;
    var s: Window;

    let w_1 = params.width;
    let h_1 = params.height;
    if !((gid.x >= w_1)) {
        local = (gid.y >= h_1);
    } else {
        local = true;
    }
    let _e15 = local;
    if _e15 {
        return;
    }
    let i = ((gid.y * w_1) + gid.x);
    let e_1 = irradiance[i];
    let g_1 = guide[i];
    if all((g_1.xyz == vec3(0f))) {
        filtered[i] = vec4<f32>(0f, 0f, 0f, e_1.w);
        return;
    }
    let n_2 = g_1.xyz;
    let z_3 = g_1.w;
    let _e40 = inv_sigma_z(z_3);
    let _e44 = window_sum(gid.x, gid.y, PERIOD, n_2, z_3, _e40);
    s = _e44;
    let _e47 = s.covered;
    let _e49 = misses_subset(_e47, PERIOD);
    if _e49 {
        let _e53 = wide_window(PERIOD);
        let _e54 = window_sum(gid.x, gid.y, _e53, n_2, z_3, _e40);
        s = _e54;
    }
    let _e59 = s.sum;
    let _e61 = s.weight;
    let _e62 = filtered_irradiance(e_1.xyz, _e59, _e61);
    filtered[i] = vec4<f32>(_e62, e_1.w);
    return;
}
