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

struct GpuNearBox {
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
const NEAR_CHUNK: u32 = 32u;

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
@group(0) @binding(5) 
var<storage> near_slots: array<u32>;
@group(0) @binding(6) 
var<storage> near_boxes: array<GpuNearBox>;
@group(0) @binding(8) 
var<storage> r2_2: array<f32>;
@group(0) @binding(9) 
var<storage, read_write> irradiance: array<vec4<f32>>;
var<workgroup> light_count: atomic<u32>;
var<workgroup> light_list: array<u32, 2048>;

fn to_f32_(u: u32) -> f32 {
    return f32(u);
}

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
    let m_2 = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0f) * max(-(dot(n_x, v)), 0f)) * INV_PI) / (m_2 * m_2));
}

fn interleave_flux_scale(period: u32) -> f32 {
    let _e2 = to_f32_((period * period));
    return _e2;
}

fn vpl_near_weight(d2_1: f32, near_r2_: f32) -> f32 {
    if (near_r2_ <= 0f) {
        return 0f;
    }
    let t = clamp(((near_r2_ - d2_1) / (0.75f * near_r2_)), 0f, 1f);
    return ((t * t) * (3f - (2f * t)));
}

fn vpl_near_cull_range2_(r2_1: f32, near_r2_1: f32) -> f32 {
    return min(r2_1, near_r2_1);
}

fn vpl_near_fixed_share(range2_1: f32, d2_2: f32, near_r2_2: f32) -> f32 {
    let _e3 = vpl_near_weight(d2_2, near_r2_2);
    let _e4 = clamp_keep(range2_1, d2_2);
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
    var local_5: bool;

    let _e3 = view.width;
    let _e8 = view.width;
    let texel_1 = vec2<i32>(i32((i % _e3)), i32((i / _e8)));
    let _e12 = surface_at(texel_1);
    let _e15 = textureLoad(normal_tex, texel_1, 0i);
    let n = _e15.xyz;
    let len2_ = dot(n, n);
    if (_e12.w > 0f) {
        local_5 = (len2_ > 0f);
    } else {
        local_5 = false;
    }
    let valid = local_5;
    let _e30 = view.eye;
    let v_2 = (_e12.xyz - _e30);
    let position = vec4<f32>(_e12.xyz, select(0f, 1f, valid));
    let normal = select(vec4<f32>(0f, 0f, 0f, 1000000000000000000000000000000f), vec4<f32>((n / vec3(sqrt(len2_))), sqrt(dot(v_2, v_2))), valid);
    return GbTexel(position, normal);
}

fn near_r2_of(slot: u32) -> f32 {
    let _e3 = r2_2[slot];
    return _e3;
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
    var local_2: bool;
    var local_3: bool;
    var m: u32;
    var local_4: bool;
    var m_1: u32;

    let px = ((wg.x * TILE) + lid.x);
    let py = ((wg.y * TILE) + lid.y);
    let _e15 = params.width;
    if (px < _e15) {
        let _e21 = params.height;
        local = (py < _e21);
    } else {
        local = false;
    }
    let inside = local;
    let _e27 = params.width;
    let pix = ((py * _e27) + px);
    if inside {
        let _e36 = gbuffer_at(pix);
        pos = _e36.position;
        nrm = _e36.normal.xyz;
    }
    if inside {
        let _e43 = pos.w;
        local_1 = (_e43 > 0f);
    } else {
        local_1 = false;
    }
    let valid_1 = local_1;
    let _e48 = pos;
    let _e50 = workgroup_box(li, _e48.xyz, valid_1);
    let lo = _e50.lo;
    let hi = _e50.hi;
    let _e55 = params.near_r2_;
    let _e56 = cull_radius(_e55);
    let _e58 = interleave_flux_scale(P);
    let unscale = (1f / _e58);
    loop {
        let _e68 = first;
        let _e71 = params.near_blocks;
        if (_e68 < _e71) {
        } else {
            break;
        }
        {
            if (li == 0u) {
                atomicStore((&light_count), 0u);
            }
            workgroupBarrier();
            let _e77 = first;
            let b = (_e77 + li);
            if (li < NEAR_CHUNK) {
                let _e85 = params.near_blocks;
                local_2 = (b < _e85);
            } else {
                local_2 = false;
            }
            let _e88 = local_2;
            if _e88 {
                let nb = near_boxes[b];
                if all(((nb.lo - vec3(_e56)) <= hi)) {
                    local_3 = all((lo <= (nb.hi + vec3(_e56))));
                } else {
                    local_3 = false;
                }
                let _e105 = local_3;
                if _e105 {
                    m = 0u;
                    loop {
                        let _e108 = m;
                        if (_e108 < NEAR_BLOCK) {
                        } else {
                            break;
                        }
                        {
                            let _e114 = m;
                            let slot_1 = near_slots[((b * NEAR_BLOCK) + _e114)];
                            let l = lights[slot_1];
                            let _e121 = near_r2_of(slot_1);
                            let _e124 = params.near_r2_;
                            let _e125 = vpl_near_cull_range2_(_e121, _e124);
                            let _e126 = cull_radius(_e125);
                            if any((l.intensity != vec3(0f))) {
                                let _e135 = sphere_overlaps_aabb(l.p0_, _e126, lo, hi);
                                local_4 = _e135;
                            } else {
                                local_4 = false;
                            }
                            let _e137 = local_4;
                            if _e137 {
                                let _e141 = atomicAdd((&light_count), 1u);
                                light_list[_e141] = slot_1;
                            }
                        }
                        continuing {
                            let _e144 = m;
                            m = (_e144 + 1u);
                        }
                    }
                }
            }
            let _e147 = workgroupUniformLoad((&light_count));
            if valid_1 {
                m_1 = 0u;
                loop {
                    let _e150 = m_1;
                    if (_e150 < _e147) {
                    } else {
                        break;
                    }
                    {
                        let _e153 = m_1;
                        let slot_2 = light_list[_e153];
                        let l_1 = lights[slot_2];
                        let _e159 = pos;
                        let v_3 = (_e159.xyz - l_1.p0_);
                        let _e165 = r2_2[slot_2];
                        let _e169 = params.near_r2_;
                        let _e170 = vpl_near_fixed_share(_e165, dot(v_3, v_3), _e169);
                        if (_e170 > 0f) {
                            let _e174 = nrm;
                            let _e177 = params.min_d2_;
                            let _e178 = vpl_transfer(l_1.p1_, _e174, v_3, _e177);
                            let t_1 = ((_e178 * _e170) * unscale);
                            let _e181 = e;
                            e = (_e181 + (l_1.intensity * t_1));
                            let _e185 = kept;
                            kept = (_e185 + 1u);
                        }
                    }
                    continuing {
                        let _e189 = m_1;
                        m_1 = (_e189 + 1u);
                    }
                }
            }
            workgroupBarrier();
        }
        continuing {
            let _e191 = first;
            first = (_e191 + NEAR_CHUNK);
        }
    }
    if valid_1 {
        let old = irradiance[pix];
        let _e200 = e;
        let _e203 = kept;
        irradiance[pix] = vec4<f32>((old.xyz + _e200), (old.w + f32(_e203)));
        return;
    } else {
        return;
    }
}
