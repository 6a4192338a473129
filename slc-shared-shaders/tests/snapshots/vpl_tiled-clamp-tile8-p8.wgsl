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
    subset_shift: u32,
    pad1_: u32,
}

struct ViewParams {
    c0_: vec4<f32>,
    c1_: vec4<f32>,
    c2_: vec4<f32>,
    c3_: vec4<f32>,
    eye: vec3<f32>,
    width: u32,
    height: u32,
    pad0_: u32,
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
const TILE: u32 = 8u;
const THREADS: u32 = 64u;
const BOX_THREADS: u32 = 64u;
const MAX_TILE_LIGHTS: u32 = 1024u;

var<workgroup> wg_lo: array<vec3<f32>, 64>;
var<workgroup> wg_hi: array<vec3<f32>, 64>;
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
var<storage, read_write> irradiance: array<vec4<f32>>;
var<workgroup> tile_count: atomic<u32>;
var<workgroup> tile_lights: array<u32, 1024>;

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

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p_1 = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p_1.xyz, 1f), (p_1.w > 0f));
}

fn gbuffer_at(i: u32) -> GbTexel {
    var local_2: bool;

    let _e3 = view.width;
    let _e8 = view.width;
    let texel_1 = vec2<i32>(i32((i % _e3)), i32((i / _e8)));
    let _e12 = surface_at(texel_1);
    let _e15 = textureLoad(normal_tex, texel_1, 0i);
    let n = _e15.xyz;
    let len2_ = dot(n, n);
    if (_e12.w > 0f) {
        local_2 = (len2_ > 0f);
    } else {
        local_2 = false;
    }
    let valid = local_2;
    let _e30 = view.eye;
    let v_2 = (_e12.xyz - _e30);
    let position = vec4<f32>(_e12.xyz, select(0f, 1f, valid));
    let normal = select(vec4<f32>(0f, 0f, 0f, 1000000000000000000000000000000f), vec4<f32>((n / vec3(sqrt(len2_))), sqrt(dot(v_2, v_2))), valid);
    return GbTexel(position, normal);
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
        let _e47 = gbuffer_at(pix);
        pos = _e47.position;
        nrm = _e47.normal.xyz;
    }
    if inside {
        let _e54 = pos.w;
        local_1 = (_e54 > 0f);
    } else {
        local_1 = false;
    }
    let valid_1 = local_1;
    let _e59 = pos;
    let _e61 = workgroup_box(li, _e59.xyz, valid_1);
    let lo = _e61.lo;
    let hi = _e61.hi;
    let _e66 = params.subset_shift;
    let _e68 = shifted_subset(sub, _e66, P);
    let _e71 = params.lights_per_subset;
    let base = (_e68 * _e71);
    loop {
        let _e80 = first;
        let _e83 = params.lights_per_subset;
        if (_e80 < _e83) {
        } else {
            break;
        }
        {
            let _e85 = first;
            let _e90 = params.lights_per_subset;
            let end = min((_e85 + MAX_TILE_LIGHTS), _e90);
            if (li == 0u) {
                atomicStore((&tile_count), 0u);
            }
            workgroupBarrier();
            let _e96 = first;
            j = (_e96 + li);
            loop {
                let _e99 = j;
                if (_e99 < end) {
                } else {
                    break;
                }
                {
                    let _e102 = j;
                    let _e106 = lights[(base + _e102)].p0_;
                    let _e108 = j;
                    let _e111 = r2_1[(base + _e108)];
                    let _e112 = cull_radius(_e111);
                    let _e113 = sphere_overlaps_aabb(_e106, _e112, lo, hi);
                    if _e113 {
                        let _e116 = atomicAdd((&tile_count), 1u);
                        if (_e116 < MAX_TILE_LIGHTS) {
                            let _e121 = j;
                            tile_lights[_e116] = _e121;
                        }
                    }
                }
                continuing {
                    let _e122 = j;
                    j = (_e122 + THREADS);
                }
            }
            let _e126 = workgroupUniformLoad((&tile_count));
            let count = min(_e126, MAX_TILE_LIGHTS);
            if valid_1 {
                k = 0u;
                loop {
                    let _e131 = k;
                    if (_e131 < count) {
                    } else {
                        break;
                    }
                    {
                        let _e134 = k;
                        let _e136 = tile_lights[_e134];
                        let j_1 = (base + _e136);
                        let l = lights[j_1];
                        let _e141 = pos;
                        let v_3 = (_e141.xyz - l.p0_);
                        let _e147 = r2_1[j_1];
                        let _e151 = params.near_r2_;
                        let _e152 = vpl_far_fixed_share(_e147, dot(v_3, v_3), _e151);
                        if (_e152 > 0f) {
                            let _e156 = nrm;
                            let _e159 = params.min_d2_;
                            let _e160 = vpl_transfer(l.p1_, _e156, v_3, _e159);
                            let t_1 = (_e160 * _e152);
                            let _e162 = e;
                            e = (_e162 + (l.intensity * t_1));
                            let _e166 = kept;
                            kept = (_e166 + 1u);
                        }
                    }
                    continuing {
                        let _e170 = k;
                        k = (_e170 + 1u);
                    }
                }
            }
            workgroupBarrier();
        }
        continuing {
            let _e172 = first;
            first = (_e172 + MAX_TILE_LIGHTS);
        }
    }
    if inside {
        let _e177 = e;
        let _e178 = kept;
        irradiance[pix] = vec4<f32>(_e177, f32(_e178));
        return;
    } else {
        return;
    }
}
