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

struct ViewParams {
    c0_: vec4<f32>,
    c1_: vec4<f32>,
    c2_: vec4<f32>,
    c3_: vec4<f32>,
    eye: vec3<f32>,
    width: u32,
    height: u32,
    shadow_offset: f32,
    seed: u32,
    frame: u32,
    f0_d: vec3<f32>,
    f90_d: f32,
}

struct WorkgroupBox {
    lo: vec3<f32>,
    hi: vec3<f32>,
}

struct GbTexel {
    position: vec4<f32>,
    normal: vec4<f32>,
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
const TILE: u32 = 8u;
const THREADS: u32 = 64u;
const BOX_THREADS: u32 = 64u;
const MAX_TILE_LIGHTS: u32 = 1024u;

var<workgroup> wg_lo: array<vec3<f32>, 64>;
var<workgroup> wg_hi: array<vec3<f32>, 64>;
var<workgroup> wg_box: WorkgroupBox;
@group(0) @binding(0) 
var<uniform> params: VplParams;
@group(0) @binding(1) 
var<uniform> view: ViewParams;
@group(0) @binding(2) 
var position_tex: texture_2d<f32>;
@group(0) @binding(3) 
var normal_tex: texture_2d<f32>;
@group(0) @binding(4) 
var<storage> lights: array<GpuLight>;
@group(0) @binding(6) 
var<storage> r2_1: array<f32>;
@group(0) @binding(7) 
var<storage> boxes: array<GpuBox>;
@group(0) @binding(8) 
var<storage, read_write> irradiance: array<vec4<f32>>;
@group(0) @binding(9) 
var<storage, read_write> guide: array<vec4<f32>>;
var<private> pos: vec3<f32>;
var<private> nrm: vec3<f32>;
var<private> eye_distance: f32;
var<private> valid: bool;
var<private> e: vec3<f32>;
var<private> kept: u32;
var<workgroup> tile_lights: array<u32, 1024>;
var<workgroup> list_count: atomic<u32>;
var<workgroup> cluster_hits: array<u32, 64>;
var<workgroup> hit_count: atomic<u32>;

fn clamp_keep(range2_: f32, d2_: f32) -> bool {
    return (d2_ < range2_);
}

fn cull_radius(r2_: f32) -> f32 {
    return (sqrt(r2_) * CULL_RADIUS_SCALE);
}

fn sphere_overlaps_aabb(c: vec3<f32>, r: f32, bmin: vec3<f32>, bmax: vec3<f32>) -> bool {
    let q = clamp(c, bmin, bmax);
    let v_1 = (q - c);
    return (dot(v_1, v_1) <= (r * r));
}

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
    let h_1 = min(gh_1, (bh_1 - (gh_1 * gy)));
    return (((gy * gh_1) * bw_2) + ((gx * gw_2) * h_1));
}

fn group_clusters(g_1: u32, bw_3: u32, bh_2: u32, gw_3: u32, gh_2: u32) -> u32 {
    let _e5 = groups_across(bw_3, gw_3);
    let gx_1 = (g_1 % _e5);
    let gy_1 = (g_1 / _e5);
    return (min(gw_3, (bw_3 - (gw_3 * gx_1))) * min(gh_2, (bh_2 - (gh_2 * gy_1))));
}

fn box_overlaps_box(lo1_: vec3<f32>, hi1_: vec3<f32>, lo2_: vec3<f32>, hi2_: vec3<f32>) -> bool {
    var local_1: bool;
    var local_2: bool;
    var local_3: bool;
    var local_4: bool;
    var local_5: bool;

    if (lo1_.x <= hi2_.x) {
        local_1 = (lo2_.x <= hi1_.x);
    } else {
        local_1 = false;
    }
    let _e13 = local_1;
    if _e13 {
        local_2 = (lo1_.y <= hi2_.y);
    } else {
        local_2 = false;
    }
    let _e20 = local_2;
    if _e20 {
        local_3 = (lo2_.y <= hi1_.y);
    } else {
        local_3 = false;
    }
    let _e27 = local_3;
    if _e27 {
        local_4 = (lo1_.z <= hi2_.z);
    } else {
        local_4 = false;
    }
    let _e34 = local_4;
    if _e34 {
        local_5 = (lo2_.z <= hi1_.z);
    } else {
        local_5 = false;
    }
    let _e41 = local_5;
    return _e41;
}

fn vpl_transfer(n_l: vec3<f32>, n_x: vec3<f32>, v: vec3<f32>, min_d2_: f32) -> f32 {
    let m = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0f) * max(-(dot(n_x, v)), 0f)) * INV_PI) / (m * m));
}

fn shifted_subset(pixel_class: u32, shift: u32, period: u32) -> u32 {
    return ((pixel_class + shift) % (period * period));
}

fn vpl_near_weight(d2_1: f32, near_r2_: f32) -> f32 {
    if (near_r2_ <= 0f) {
        return 0f;
    }
    let t = clamp(((near_r2_ - d2_1) / (0.75f * near_r2_)), 0f, 1f);
    return ((t * t) * (3f - (2f * t)));
}

fn vpl_far_weight(d2_2: f32, near_r2_1: f32) -> f32 {
    let _e2 = vpl_near_weight(d2_2, near_r2_1);
    return (1f - _e2);
}

fn vpl_far_fixed_share(range2_1: f32, d2_3: f32, near_r2_2: f32) -> f32 {
    let _e3 = vpl_far_weight(d2_3, near_r2_2);
    let _e4 = clamp_keep(range2_1, d2_3);
    return select(0f, _e3, (_e4 & (_e3 > 0f)));
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

fn point_box(p: vec3<f32>, has: bool) -> WorkgroupBox {
    return WorkgroupBox(select(vec3(340282350000000000000000000000000000000f), p, has), select(vec3(-340282350000000000000000000000000000000f), p, has));
}

fn workgroup_box(li_2: u32, p_1: vec3<f32>, has_1: bool) -> WorkgroupBox {
    let _e3 = point_box(p_1, has_1);
    let _e6 = workgroup_bounds(li_2, _e3.lo, _e3.hi);
    return _e6;
}

fn box_is_empty(b: WorkgroupBox) -> bool {
    return (b.lo.x > b.hi.x);
}

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p_4 = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p_4.xyz, 1f), (p_4.w > 0f));
}

fn gbuffer_at(i: u32) -> GbTexel {
    var local_6: bool;

    let _e3 = view.width;
    let _e8 = view.width;
    let texel_1 = vec2<i32>(i32((i % _e3)), i32((i / _e8)));
    let _e12 = surface_at(texel_1);
    let _e15 = textureLoad(normal_tex, texel_1, 0i);
    let n = _e15.xyz;
    let len2_ = dot(n, n);
    if (_e12.w > 0f) {
        local_6 = (len2_ > 0f);
    } else {
        local_6 = false;
    }
    let valid_1 = local_6;
    let _e30 = view.eye;
    let v_2 = (_e12.xyz - _e30);
    let position = vec4<f32>(_e12.xyz, select(0f, 1f, valid_1));
    let normal = select(vec4<f32>(0f, 0f, 0f, 1000000000000000000000000000000f), vec4<f32>((n / vec3(sqrt(len2_))), sqrt(dot(v_2, v_2))), valid_1);
    return GbTexel(position, normal);
}

fn load_receiver(li_3: u32, pix: u32, inside: bool) -> WorkgroupBox {
    var p_2: vec4<f32> = vec4(0f);
    var local_7: bool;

    eye_distance = DEPTH_NONE;
    if inside {
        let _e8 = gbuffer_at(pix);
        p_2 = _e8.position;
        nrm = _e8.normal.xyz;
        eye_distance = _e8.normal.w;
    }
    let _e17 = p_2;
    pos = _e17.xyz;
    if inside {
        let _e23 = p_2.w;
        local_7 = (_e23 > 0f);
    } else {
        local_7 = false;
    }
    let _e27 = local_7;
    valid = _e27;
    let _e29 = pos;
    let _e31 = valid;
    let _e32 = workgroup_box(li_3, _e29, _e31);
    return _e32;
}

fn shade_light(j: u32) {
    let l = lights[j];
    let _e5 = pos;
    let v_3 = (_e5 - l.p0_);
    let _e10 = r2_1[j];
    let _e14 = params.near_r2_;
    let _e15 = vpl_far_fixed_share(_e10, dot(v_3, v_3), _e14);
    if (_e15 > 0f) {
        let _e20 = nrm;
        let _e23 = params.min_d2_;
        let _e24 = vpl_transfer(l.p1_, _e20, v_3, _e23);
        let t_1 = (_e24 * _e15);
        let _e27 = e;
        e = (_e27 + (l.intensity * t_1));
        let _e32 = kept;
        kept = (_e32 + 1u);
        return;
    } else {
        return;
    }
}

fn cluster_slot(c_1: u32, k: u32) -> u32 {
    return ((c_1 * CLUSTER) + k);
}

fn cull_r2_of(slot: u32) -> f32 {
    let _e3 = r2_1[slot];
    return _e3;
}

fn shade_list(count: u32) {
    var k_1: u32 = 0u;

    let _e2 = valid;
    if _e2 {
        loop {
            let _e5 = k_1;
            if (_e5 < count) {
            } else {
                break;
            }
            {
                let _e8 = k_1;
                let _e10 = tile_lights[_e8];
                shade_light(_e10);
            }
            continuing {
                let _e12 = k_1;
                k_1 = (_e12 + 1u);
            }
        }
        return;
    } else {
        return;
    }
}

fn list_clear(li_4: u32) {
    if (li_4 == 0u) {
        atomicStore((&list_count), 0u);
        return;
    } else {
        return;
    }
}

fn list_full() -> bool {
    let _e1 = workgroupUniformLoad((&list_count));
    return ((_e1 + CLUSTER) > MAX_TILE_LIGHTS);
}

fn list_add(slot_1: u32, p_3: vec3<f32>, radius: f32) {
    let _e6 = atomicAdd((&list_count), 1u);
    tile_lights[_e6] = slot_1;
    return;
}

fn list_shade() {
    let _e1 = workgroupUniformLoad((&list_count));
    shade_list(_e1);
    return;
}

fn cull_tile(li_5: u32, lo_1: vec3<f32>, hi_1: vec3<f32>, grid: vec4<u32>, clusters_at: u32, groups_at: u32) {
    var g_2: u32 = 0u;
    var h: u32;

    list_clear(li_5);
    let _e10 = group_count(grid.x, grid.y, grid.z, grid.w);
    loop {
        let _e13 = g_2;
        if (_e13 < _e10) {
        } else {
            break;
        }
        {
            let _e16 = g_2;
            let gb = boxes[(groups_at + _e16)];
            let _e22 = box_overlaps_box(gb.lo, gb.hi, lo_1, hi_1);
            if !(_e22) {
                continue;
            }
            let _e24 = g_2;
            let _e29 = group_first(_e24, grid.x, grid.y, grid.z, grid.w);
            let first = (clusters_at + _e29);
            let _e31 = g_2;
            let _e36 = group_clusters(_e31, grid.x, grid.y, grid.z, grid.w);
            if (li_5 == 0u) {
                atomicStore((&hit_count), 0u);
            }
            workgroupBarrier();
            if (li_5 < _e36) {
                let cb = boxes[(first + li_5)];
                let _e48 = box_overlaps_box(cb.lo, cb.hi, lo_1, hi_1);
                if _e48 {
                    let _e52 = atomicAdd((&hit_count), 1u);
                    cluster_hits[_e52] = (first + li_5);
                }
            }
            let _e56 = workgroupUniformLoad((&hit_count));
            h = 0u;
            loop {
                let _e59 = h;
                if (_e59 < _e56) {
                } else {
                    break;
                }
                {
                    let _e61 = list_full();
                    if _e61 {
                        list_shade();
                        workgroupBarrier();
                        list_clear(li_5);
                        workgroupBarrier();
                    }
                    let _e63 = h;
                    let _e65 = cluster_hits[_e63];
                    let _e66 = cluster_slot(_e65, li_5);
                    let l_1 = lights[_e66];
                    if any((l_1.intensity != vec3(0f))) {
                        let _e75 = cull_r2_of(_e66);
                        let _e76 = cull_radius(_e75);
                        let _e78 = sphere_overlaps_aabb(l_1.p0_, _e76, lo_1, hi_1);
                        if _e78 {
                            list_add(_e66, l_1.p0_, _e76);
                        }
                    }
                }
                continuing {
                    let _e81 = h;
                    h = (_e81 + 1u);
                }
            }
            workgroupBarrier();
        }
        continuing {
            let _e84 = g_2;
            g_2 = (_e84 + 1u);
        }
    }
    list_shade();
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    var local: bool;

    let sub = wg.z;
    let px = ((sub % P) + (((wg.x * TILE) + lid.x) * P));
    let py = ((sub / P) + (((wg.y * TILE) + lid.y) * P));
    let _e26 = params.width;
    if (px < _e26) {
        let _e32 = params.height;
        local = (py < _e32);
    } else {
        local = false;
    }
    let inside_1 = local;
    let _e38 = params.width;
    let pix_1 = ((py * _e38) + px);
    let _e41 = load_receiver(li, pix_1, inside_1);
    let _e44 = params.subset_shift;
    let _e46 = shifted_subset(sub, _e44, P);
    let _e47 = box_is_empty(_e41);
    if !(_e47) {
        let grid_1 = params.far_grid;
        let _e56 = params.lights_per_subset;
        let _e62 = params.far_groups_at;
        let _e67 = group_count(grid_1.x, grid_1.y, grid_1.z, grid_1.w);
        cull_tile(li, _e41.lo, _e41.hi, grid_1, (_e46 * (_e56 / CLUSTER)), (_e62 + (_e46 * _e67)));
    }
    if inside_1 {
        let _e73 = e;
        let _e75 = kept;
        irradiance[pix_1] = vec4<f32>(_e73, f32(_e75));
        let _e81 = nrm;
        let _e83 = eye_distance;
        guide[pix_1] = vec4<f32>(_e81, _e83);
        return;
    } else {
        return;
    }
}
