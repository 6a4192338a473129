{% include "header.wgsl" %}
{% include "lights.wgsl" %}
// The near field of the VPL split (slc_core::interleave) with {{ method }}
// culling: every pixel adds the near share vpl_near_weight of every VPL
// closer than R_n, at the VPL's own flux (the light buffer holds flux x P^2),
// to the irradiance vpl_tiled wrote (after the denoise, which filters only
// the interleaved far field), culled as vpl_tiled culls the far field:
{% if method == "slc" %}
// stochastic light culling at the VPL's own ranges (vpl_near_range2 of the
// interleaved light's r_t^2, r^2: the same xi), vpl_near_slc_share (unbiased).
{% elif method == "clamp" %}
// at the clamp range R (r2 holds R^2), vpl_near_fixed_share.
{% else %}
// not at all (r2 holds a range beyond every distance), vpl_near_fixed_share.
{% endif %}
// Workgroup (x, y) is a {{ tile }}x{{ tile }} tile of full-resolution pixels: the
// box of its G-buffer positions is reduced in workgroup memory; then, a
// chunk of NEAR_CHUNK near blocks at a time, one thread per block tests the
// block's box (widened by R_n) and, where it meets the tile's box, puts
// the block's VPLs whose culling sphere (radius min(r, R_n),
// vpl_near_cull_range2) meets it into a list every pixel loops over.
{% if glossy %}
// Glossy variant: the near field's specular correction S is added to
// `specular` as its irradiance is to `irradiance` (vpl_tiled's glossy
// variant).
{% endif %}

const P: u32 = {{ period }}u;
const TILE: u32 = {{ tile }}u;
const THREADS: u32 = TILE * TILE;
const BOX_THREADS: u32 = THREADS;
{% include "workgroup_box.wgsl" %}
// Near blocks per chunk: one per thread, at most 32 (16 for 16x16 tiles,
// so the list fits WebGPU's 16 KiB of workgroup memory).
const NEAR_CHUNK: u32 = {% if tile * tile < 32 %}THREADS{% elif tile > 8 %}16u{% else %}32u{% endif %};

{{ bindings }}
{% include "gbuffer_read.wgsl" %}
{% if glossy %}
{% include "vpl_glossy.wgsl" %}
{% endif %}

/// The r^2 the near field keeps light `slot` by: its own range at the VPL's
/// flux (slc), or the interleaved light's fixed range (clamp, none).
fn near_r2_of(slot: u32) -> f32 {
{% if method == "slc" %}
    return vpl_near_range2(r2[slot], P);
{% else %}
    return r2[slot];
{% endif %}
}

var<workgroup> light_count: atomic<u32>;
var<workgroup> light_list: array<u32, NEAR_CHUNK * NEAR_BLOCK>;

@compute @workgroup_size({{ tile }}, {{ tile }}, 1)
fn main(
    @builtin(workgroup_id) wg: vec3u,
    @builtin(local_invocation_id) lid: vec3u,
    @builtin(local_invocation_index) li: u32,
) {
    let px = wg.x * TILE + lid.x;
    let py = wg.y * TILE + lid.y;
    let inside = px < params.width && py < params.height;
    let pix = py * params.width + px;
    var pos = vec4f(0.0);
    var nrm = vec3f(0.0);
    if inside {
        let g = gbuffer_at(pix);
        pos = g.position;
        nrm = g.normal.xyz;
    }
    let valid = inside && pos.w > 0.0;
    let tile_box = workgroup_box(li, pos.xyz, valid);
    let lo = tile_box.lo;
    let hi = tile_box.hi;
    let radius = cull_radius(params.near_r2);
    // The flux the light buffer holds is P^2 times the VPL's own.
    let unscale = 1.0 / interleave_flux_scale(P);
    var e = vec3f(0.0);
    var kept = 0u;
{% if glossy %}
    var s = vec3f(0.0);
    var g: Glossy;
    if valid {
        g = glossy_at(pix, pos.xyz);
    }
{% endif %}
    for (var first = 0u; first < params.near_blocks; first += NEAR_CHUNK) {
        if li == 0u {
            atomicStore(&light_count, 0u);
        }
        workgroupBarrier();
        let b = first + li;
        if li < NEAR_CHUNK && b < params.near_blocks {
            let nb = near_boxes[b];
            if all(nb.lo - vec3f(radius) <= hi) && all(lo <= nb.hi + vec3f(radius)) {
                for (var m = 0u; m < NEAR_BLOCK; m++) {
                    let slot = near_slots[b * NEAR_BLOCK + m];
                    let l = lights[slot];
                    let cull = cull_radius(vpl_near_cull_range2(near_r2_of(slot), params.near_r2));
                    if any(l.intensity != vec3f(0.0)) && sphere_overlaps_aabb(l.p0, cull, lo, hi) {
                        light_list[atomicAdd(&light_count, 1u)] = slot;
                    }
                }
            }
        }
        let count = workgroupUniformLoad(&light_count);
        if valid {
            for (var m = 0u; m < count; m++) {
                let slot = light_list[m];
                let l = lights[slot];
                let v = pos.xyz - l.p0;
{% if method == "slc" %}
                let share = vpl_near_slc_share(vpl_near_range2(rt2[slot], P), near_r2_of(slot), dot(v, v), params.near_r2);
{% else %}
                let share = vpl_near_fixed_share(r2[slot], dot(v, v), params.near_r2);
{% endif %}
                if share > 0.0 {
                    let t = vpl_transfer(l.p1, nrm, v, params.min_d2) * share * unscale;
                    e += l.intensity * t;
{% if glossy %}
                    s += glossy_term(g, l, nrm, v, t);
{% endif %}
                    kept += 1u;
                }
            }
        }
        // Every thread is done with the list before the next chunk refills it.
        workgroupBarrier();
    }
    if valid {
        let old = irradiance[pix];
        irradiance[pix] = vec4f(old.xyz + e, old.w + f32(kept));
{% if glossy %}
        specular[pix] = vec4f(specular[pix].xyz + s, 0.0);
{% endif %}
    }
}
