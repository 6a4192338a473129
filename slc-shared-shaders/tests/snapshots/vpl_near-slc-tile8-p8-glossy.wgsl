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

struct GpuMaterial {
    albedo: vec3<f32>,
    metallic: f32,
    emission: vec3<f32>,
    alpha: f32,
    f0_: vec3<f32>,
    f90_: f32,
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

struct Glossy {
    m: GpuMaterial,
    v: vec3<f32>,
    on: bool,
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
@group(0) @binding(7) 
var<storage> rt2_2: array<f32>;
@group(0) @binding(8) 
var<storage> r2_5: array<f32>;
@group(0) @binding(9) 
var<storage, read_write> irradiance: array<vec4<f32>>;
@group(0) @binding(10) 
var<storage> materials: array<GpuMaterial>;
@group(0) @binding(11) 
var<storage, read_write> specular: array<vec4<f32>>;
var<workgroup> light_count: atomic<u32>;
var<workgroup> light_list: array<u32, 2048>;

fn to_f32_(u: u32) -> f32 {
    return f32(u);
}

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
    let v_6 = (q - c);
    return (dot(v_6, v_6) <= (r * r));
}

fn vpl_transfer(n_l: vec3<f32>, n_x: vec3<f32>, v: vec3<f32>, min_d2_: f32) -> f32 {
    let m_2 = max(dot(v, v), max(min_d2_, MIN_D2_));
    return (((max(dot(n_l, v), 0f) * max(-(dot(n_x, v)), 0f)) * INV_PI) / (m_2 * m_2));
}

fn ggx_d(cos_h: f32, sin2_h: f32, alpha: f32) -> f32 {
    if (cos_h <= 0f) {
        return 0f;
    }
    let a2_ = (alpha * alpha);
    let t_1 = (((cos_h * cos_h) * a2_) + sin2_h);
    return ((a2_ * INV_PI) / (t_1 * t_1));
}

fn smith_root(cos_: f32, alpha_1: f32) -> f32 {
    let a2_1 = (alpha_1 * alpha_1);
    return sqrt((((cos_ * cos_) * (1f - a2_1)) + a2_1));
}

fn smith_visibility(n_l_1: f32, n_v: f32, alpha_2: f32) -> f32 {
    var local_5: bool;

    if !((n_l_1 <= 0f)) {
        local_5 = (n_v <= 0f);
    } else {
        local_5 = true;
    }
    let _e11 = local_5;
    if _e11 {
        return 0f;
    }
    let _e13 = smith_root(n_v, alpha_2);
    let _e15 = smith_root(n_l_1, alpha_2);
    return (0.5f / ((n_l_1 * _e13) + (n_v * _e15)));
}

fn fresnel_schlick(f0_: vec3<f32>, f90_: f32, v_h: f32) -> vec3<f32> {
    let c_1 = saturate((1f - v_h));
    let c2_ = (c_1 * c_1);
    return (f0_ + ((vec3<f32>(f90_, f90_, f90_) - f0_) * ((c2_ * c2_) * c_1)));
}

fn specular_fresnel(base: vec3<f32>, metallic: f32, f0_d: vec3<f32>, f90_d: f32, v_h_1: f32) -> vec3<f32> {
    let _e5 = fresnel_schlick(f0_d, f90_d, v_h_1);
    let _e10 = fresnel_schlick(base, 1f, v_h_1);
    return ((_e5 * (1f - metallic)) + (_e10 * metallic));
}

fn diffuse_brdf(base_1: vec3<f32>, metallic_1: f32, f0_d_1: vec3<f32>, f90_d_1: f32, v_h_2: f32) -> vec3<f32> {
    let _e9 = fresnel_schlick(f0_d_1, f90_d_1, v_h_2);
    return ((((vec3<f32>(1f, 1f, 1f) - _e9) * base_1) * (1f - metallic_1)) * INV_PI);
}

fn half_cosine(v_1: vec3<f32>, l: vec3<f32>) -> f32 {
    let h = (v_1 + l);
    let len2_ = dot(h, h);
    if (len2_ <= 0f) {
        return 0f;
    }
    return saturate((dot(v_1, h) / sqrt(len2_)));
}

fn specular_brdf(base_2: vec3<f32>, metallic_2: f32, f0_d_2: vec3<f32>, f90_d_2: f32, alpha_3: f32, n: vec3<f32>, v_2: vec3<f32>, l_1: vec3<f32>) -> vec3<f32> {
    var local_6: bool;

    let n_l_2 = dot(n, l_1);
    let n_v_1 = dot(n, v_2);
    if !((n_l_2 <= 0f)) {
        local_6 = (n_v_1 <= 0f);
    } else {
        local_6 = true;
    }
    let _e18 = local_6;
    if _e18 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let hs = (v_2 + l_1);
    let inv = (1f / sqrt(dot(hs, hs)));
    let h_1 = (hs * inv);
    let c_2 = cross(n, h_1);
    let _e32 = ggx_d(dot(n, h_1), dot(c_2, c_2), alpha_3);
    let _e34 = specular_fresnel(base_2, metallic_2, f0_d_2, f90_d_2, dot(v_2, h_1));
    let _e35 = smith_visibility(n_l_2, n_v_1, alpha_3);
    return (_e34 * (_e32 * _e35));
}

fn brdf_eval(base_3: vec3<f32>, metallic_3: f32, f0_d_3: vec3<f32>, f90_d_3: f32, alpha_4: f32, n_1: vec3<f32>, v_3: vec3<f32>, l_2: vec3<f32>) -> vec3<f32> {
    if (dot(n_1, l_2) <= 0f) {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e15 = half_cosine(v_3, l_2);
    let _e16 = diffuse_brdf(base_3, metallic_3, f0_d_3, f90_d_3, _e15);
    let _e17 = specular_brdf(base_3, metallic_3, f0_d_3, f90_d_3, alpha_4, n_1, v_3, l_2);
    return (_e16 + _e17);
}

fn diffuse_albedo(base_4: vec3<f32>, metallic_4: f32) -> vec3<f32> {
    return (base_4 * (1f - metallic_4));
}

fn specular_correction(base_5: vec3<f32>, metallic_5: f32, f0_d_4: vec3<f32>, f90_d_4: f32, alpha_5: f32, n_2: vec3<f32>, v_4: vec3<f32>, l_3: vec3<f32>) -> vec3<f32> {
    let _e8 = brdf_eval(base_5, metallic_5, f0_d_4, f90_d_4, alpha_5, n_2, v_4, l_3);
    let _e9 = diffuse_albedo(base_5, metallic_5);
    return (_e8 - (_e9 * INV_PI));
}

fn has_specular(metallic_6: f32, f0_d_5: vec3<f32>, f90_d_5: f32) -> bool {
    var local_7: bool;
    var local_8: bool;

    if !((metallic_6 > 0f)) {
        local_7 = (f90_d_5 > 0f);
    } else {
        local_7 = true;
    }
    let _e11 = local_7;
    if !(_e11) {
        local_8 = (max(max(f0_d_5.x, f0_d_5.y), f0_d_5.z) > 0f);
    } else {
        local_8 = true;
    }
    let _e23 = local_8;
    return _e23;
}

fn interleave_flux_scale(period: u32) -> f32 {
    let _e2 = to_f32_((period * period));
    return _e2;
}

fn vpl_near_weight(d2_2: f32, near_r2_: f32) -> f32 {
    if (near_r2_ <= 0f) {
        return 0f;
    }
    let t_2 = clamp(((near_r2_ - d2_2) / (0.75f * near_r2_)), 0f, 1f);
    return ((t_2 * t_2) * (3f - (2f * t_2)));
}

fn vpl_near_range2_(r2_2: f32, period_1: u32) -> f32 {
    let _e2 = interleave_flux_scale(period_1);
    return (r2_2 / _e2);
}

fn vpl_near_cull_range2_(r2_3: f32, near_r2_1: f32) -> f32 {
    return min(r2_3, near_r2_1);
}

fn vpl_near_slc_share(rt2_1: f32, r2_4: f32, d2_3: f32, near_r2_2: f32) -> f32 {
    let _e4 = vpl_near_weight(d2_3, near_r2_2);
    let _e5 = slc_weight(rt2_1, d2_3);
    let _e7 = slc_keep(r2_4, d2_3);
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

fn surface_at(texel: vec2<i32>) -> vec4<f32> {
    let p_1 = textureLoad(position_tex, texel, 0i);
    return select(vec4(0f), vec4<f32>(p_1.xyz, 1f), (p_1.w > 0f));
}

fn gbuffer_at(i: u32) -> GbTexel {
    var local_9: bool;

    let _e3 = view.width;
    let _e8 = view.width;
    let texel_1 = vec2<i32>(i32((i % _e3)), i32((i / _e8)));
    let _e12 = surface_at(texel_1);
    let _e15 = textureLoad(normal_tex, texel_1, 0i);
    let n_4 = _e15.xyz;
    let len2_1 = dot(n_4, n_4);
    if (_e12.w > 0f) {
        local_9 = (len2_1 > 0f);
    } else {
        local_9 = false;
    }
    let valid = local_9;
    let _e30 = view.eye;
    let v_7 = (_e12.xyz - _e30);
    let position = vec4<f32>(_e12.xyz, select(0f, 1f, valid));
    let normal = select(vec4<f32>(0f, 0f, 0f, 1000000000000000000000000000000f), vec4<f32>((n_4 / vec3(sqrt(len2_1))), sqrt(dot(v_7, v_7))), valid);
    return GbTexel(position, normal);
}

fn glossy_at(i_1: u32, x: vec3<f32>) -> Glossy {
    let _e4 = view.width;
    let _e9 = view.width;
    let texel_2 = vec2<i32>(i32((i_1 % _e4)), i32((i_1 / _e9)));
    let _e16 = textureLoad(normal_tex, texel_2, 0i);
    let m_3 = materials[u32(_e16.w)];
    let _e23 = view.eye;
    let _e29 = has_specular(m_3.metallic, m_3.f0_, m_3.f90_);
    return Glossy(m_3, normalize((_e23 - x)), _e29);
}

fn glossy_term(g_1: Glossy, l_4: GpuLight, n_3: vec3<f32>, v_5: vec3<f32>, t: f32) -> vec3<f32> {
    var local_10: bool;

    if !(!(g_1.on)) {
        local_10 = (t <= 0f);
    } else {
        local_10 = true;
    }
    let _e13 = local_10;
    if _e13 {
        return vec3(0f);
    }
    let _e30 = specular_correction(g_1.m.albedo, g_1.m.metallic, g_1.m.f0_, g_1.m.f90_, g_1.m.alpha, n_3, g_1.v, normalize(-(v_5)));
    return ((l_4.intensity * _e30) * t);
}

fn near_r2_of(slot: u32) -> f32 {
    let _e3 = r2_5[slot];
    let _e5 = vpl_near_range2_(_e3, P);
    return _e5;
}

@compute @workgroup_size(8, 8, 1) 
fn main(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    var local: bool;
    var pos: vec4<f32> = vec4(0f);
    var nrm: vec3<f32> = vec3(0f);
    var local_1: bool;
    var e: vec3<f32> = vec3(0f);
    var kept: u32 = 0u;
    var s: vec3<f32> = vec3(0f);
    var g: Glossy;
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
    if valid_1 {
        let _e70 = pos;
        let _e72 = glossy_at(pix, _e70.xyz);
        g = _e72;
    }
    loop {
        let _e75 = first;
        let _e78 = params.near_blocks;
        if (_e75 < _e78) {
        } else {
            break;
        }
        {
            if (li == 0u) {
                atomicStore((&light_count), 0u);
            }
            workgroupBarrier();
            let _e84 = first;
            let b = (_e84 + li);
            if (li < NEAR_CHUNK) {
                let _e92 = params.near_blocks;
                local_2 = (b < _e92);
            } else {
                local_2 = false;
            }
            let _e95 = local_2;
            if _e95 {
                let nb = near_boxes[b];
                if all(((nb.lo - vec3(_e56)) <= hi)) {
                    local_3 = all((lo <= (nb.hi + vec3(_e56))));
                } else {
                    local_3 = false;
                }
                let _e112 = local_3;
                if _e112 {
                    m = 0u;
                    loop {
                        let _e115 = m;
                        if (_e115 < NEAR_BLOCK) {
                        } else {
                            break;
                        }
                        {
                            let _e121 = m;
                            let slot_1 = near_slots[((b * NEAR_BLOCK) + _e121)];
                            let l_5 = lights[slot_1];
                            let _e128 = near_r2_of(slot_1);
                            let _e131 = params.near_r2_;
                            let _e132 = vpl_near_cull_range2_(_e128, _e131);
                            let _e133 = cull_radius(_e132);
                            if any((l_5.intensity != vec3(0f))) {
                                let _e142 = sphere_overlaps_aabb(l_5.p0_, _e133, lo, hi);
                                local_4 = _e142;
                            } else {
                                local_4 = false;
                            }
                            let _e144 = local_4;
                            if _e144 {
                                let _e148 = atomicAdd((&light_count), 1u);
                                light_list[_e148] = slot_1;
                            }
                        }
                        continuing {
                            let _e151 = m;
                            m = (_e151 + 1u);
                        }
                    }
                }
            }
            let _e154 = workgroupUniformLoad((&light_count));
            if valid_1 {
                m_1 = 0u;
                loop {
                    let _e157 = m_1;
                    if (_e157 < _e154) {
                    } else {
                        break;
                    }
                    {
                        let _e160 = m_1;
                        let slot_2 = light_list[_e160];
                        let l_6 = lights[slot_2];
                        let _e166 = pos;
                        let v_8 = (_e166.xyz - l_6.p0_);
                        let _e172 = rt2_2[slot_2];
                        let _e174 = vpl_near_range2_(_e172, P);
                        let _e175 = near_r2_of(slot_2);
                        let _e179 = params.near_r2_;
                        let _e180 = vpl_near_slc_share(_e174, _e175, dot(v_8, v_8), _e179);
                        if (_e180 > 0f) {
                            let _e184 = nrm;
                            let _e187 = params.min_d2_;
                            let _e188 = vpl_transfer(l_6.p1_, _e184, v_8, _e187);
                            let t_3 = ((_e188 * _e180) * unscale);
                            let _e191 = e;
                            e = (_e191 + (l_6.intensity * t_3));
                            let _e195 = s;
                            let _e196 = g;
                            let _e197 = nrm;
                            let _e198 = glossy_term(_e196, l_6, _e197, v_8, t_3);
                            s = (_e195 + _e198);
                            let _e200 = kept;
                            kept = (_e200 + 1u);
                        }
                    }
                    continuing {
                        let _e204 = m_1;
                        m_1 = (_e204 + 1u);
                    }
                }
            }
            workgroupBarrier();
        }
        continuing {
            let _e206 = first;
            first = (_e206 + NEAR_CHUNK);
        }
    }
    if valid_1 {
        let old = irradiance[pix];
        let _e215 = e;
        let _e218 = kept;
        irradiance[pix] = vec4<f32>((old.xyz + _e215), (old.w + f32(_e218)));
        let _e226 = specular[pix];
        let _e228 = s;
        specular[pix] = vec4<f32>((_e226.xyz + _e228), 0f);
        return;
    } else {
        return;
    }
}
