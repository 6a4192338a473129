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
    near_blocks: u32,
    pad0_: u32,
    pad1_: u32,
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
const P: u32 = 8u;
const TILE: u32 = 8u;
const THREADS: u32 = 64u;
const BOX_THREADS: u32 = 64u;
const MAX_TILE_LIGHTS: u32 = 1024u;

var<workgroup> wg_lo: array<vec3<f32>, 64>;
var<workgroup> wg_hi: array<vec3<f32>, 64>;
@group(0) @binding(0) 
var<uniform> params: VplParams;
@group(0) @binding(1) 
var<storage> gb_position: array<vec4<f32>>;
@group(0) @binding(2) 
var<storage> gb_normal: array<vec4<f32>>;
@group(0) @binding(3) 
var<storage> lights: array<GpuLight>;
@group(0) @binding(4) 
var<storage> rt2_2: array<f32>;
@group(0) @binding(5) 
var<storage> r2_3: array<f32>;
@group(0) @binding(6) 
var<storage, read_write> irradiance: array<vec4<f32>>;
var<workgroup> tile_count: atomic<u32>;
var<workgroup> tile_lights: array<u32, 1024>;

fn slc_weight(rt2_: f32, d2_: f32) -> f32 {
    if (d2_ <= rt2_) {
        return 1f;
    }
    return (d2_ / rt2_);
}

fn slc_keep(r2_: f32, d2_1: f32) -> bool {
    return (d2_1 < r2_);
}

fn cull_radius(r2_1: f32) -> f32 {
    return (sqrt(r2_1) * CULL_RADIUS_SCALE);
}

fn sphere_overlaps_aabb(c: vec3<f32>, r: f32, bmin: vec3<f32>, bmax: vec3<f32>) -> bool {
    let q = clamp(c, bmin, bmax);
    let v_1 = (q - c);
    return (dot(v_1, v_1) <= (r * r));
}

fn vpl_transfer(n_l: vec3<f32>, n_x: vec3<f32>, v: vec3<f32>, min_d2_: f32) -> f32 {
    let m = max(dot(v, v), min_d2_);
    return (((max(dot(n_l, v), 0f) * max(-(dot(n_x, v)), 0f)) * INV_PI) / (m * m));
}

fn vpl_near_weight(d2_2: f32, near_r2_: f32) -> f32 {
    if (near_r2_ <= 0f) {
        return 0f;
    }
    let t = clamp(((near_r2_ - d2_2) / (0.75f * near_r2_)), 0f, 1f);
    return ((t * t) * (3f - (2f * t)));
}

fn vpl_far_weight(d2_3: f32, near_r2_1: f32) -> f32 {
    let _e2 = vpl_near_weight(d2_3, near_r2_1);
    return (1f - _e2);
}

fn vpl_far_slc_share(rt2_1: f32, r2_2: f32, d2_4: f32, near_r2_2: f32) -> f32 {
    let _e4 = vpl_far_weight(d2_4, near_r2_2);
    let _e5 = slc_weight(rt2_1, d2_4);
    let _e7 = slc_keep(r2_2, d2_4);
    return select(0f, (_e4 * _e5), (_e7 & (_e4 > 0f)));
}

fn workgroup_box(li_1: u32, p: vec3<f32>, has: bool) -> WorkgroupBox {
    var stride: u32 = 32u;

    wg_lo[li_1] = select(vec3(340282350000000000000000000000000000000f), p, has);
    wg_hi[li_1] = select(vec3(-340282350000000000000000000000000000000f), p, has);
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

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    var local: bool;
    var pos: vec4<f32> = vec4(0f);
    var nrm: vec3<f32> = vec3(0f);
    var local_1: bool;
    var e: vec3<f32> = vec3(0f);
    var kept: u32 = 0u;
    var first: u32 = 0u;
    var j: u32;
    var k: u32;

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
    let inside = local;
    let _e38 = params.width;
    let pix = ((py * _e38) + px);
    if inside {
        let _e49 = gb_position[pix];
        pos = _e49;
        let _e52 = gb_normal[pix];
        nrm = _e52.xyz;
    }
    if inside {
        let _e57 = pos.w;
        local_1 = (_e57 > 0f);
    } else {
        local_1 = false;
    }
    let valid = local_1;
    let _e62 = pos;
    let _e64 = workgroup_box(li, _e62.xyz, valid);
    let lo = _e64.lo;
    let hi = _e64.hi;
    let _e69 = params.lights_per_subset;
    let base = (sub * _e69);
    loop {
        let _e78 = first;
        let _e81 = params.lights_per_subset;
        if (_e78 < _e81) {
        } else {
            break;
        }
        {
            let _e83 = first;
            let _e88 = params.lights_per_subset;
            let end = min((_e83 + MAX_TILE_LIGHTS), _e88);
            if (li == 0u) {
                atomicStore((&tile_count), 0u);
            }
            workgroupBarrier();
            let _e94 = first;
            j = (_e94 + li);
            loop {
                let _e97 = j;
                if (_e97 < end) {
                } else {
                    break;
                }
                {
                    let _e100 = j;
                    let _e104 = lights[(base + _e100)].p0_;
                    let _e106 = j;
                    let _e109 = r2_3[(base + _e106)];
                    let _e110 = cull_radius(_e109);
                    let _e111 = sphere_overlaps_aabb(_e104, _e110, lo, hi);
                    if _e111 {
                        let _e114 = atomicAdd((&tile_count), 1u);
                        if (_e114 < MAX_TILE_LIGHTS) {
                            let _e119 = j;
                            tile_lights[_e114] = _e119;
                        }
                    }
                }
                continuing {
                    let _e120 = j;
                    j = (_e120 + THREADS);
                }
            }
            let _e124 = workgroupUniformLoad((&tile_count));
            let count = min(_e124, MAX_TILE_LIGHTS);
            if valid {
                k = 0u;
                loop {
                    let _e129 = k;
                    if (_e129 < count) {
                    } else {
                        break;
                    }
                    {
                        let _e132 = k;
                        let _e134 = tile_lights[_e132];
                        let j_1 = (base + _e134);
                        let l = lights[j_1];
                        let _e139 = pos;
                        let v_2 = (_e139.xyz - l.p0_);
                        let _e145 = rt2_2[j_1];
                        let _e148 = r2_3[j_1];
                        let _e152 = params.near_r2_;
                        let _e153 = vpl_far_slc_share(_e145, _e148, dot(v_2, v_2), _e152);
                        if (_e153 > 0f) {
                            let _e156 = e;
                            let _e159 = nrm;
                            let _e162 = params.min_d2_;
                            let _e163 = vpl_transfer(l.p1_, _e159, v_2, _e162);
                            e = (_e156 + (l.intensity * (_e163 * _e153)));
                            let _e167 = kept;
                            kept = (_e167 + 1u);
                        }
                    }
                    continuing {
                        let _e171 = k;
                        k = (_e171 + 1u);
                    }
                }
            }
            workgroupBarrier();
        }
        continuing {
            let _e173 = first;
            first = (_e173 + MAX_TILE_LIGHTS);
        }
    }
    if valid {
        let _e178 = e;
        let _e179 = kept;
        irradiance[pix] = vec4<f32>(_e178, f32(_e179));
        return;
    } else {
        return;
    }
}
