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
// box of its G-buffer positions is reduced in workgroup memory, then the
// near field's box hierarchy over the whole RSM in map order (near_slots;
// vpl_clusters, vpl_groups) is culled against it (cluster_cull.wgsl), each
// VPL's culling sphere of radius min(r, R_n) (vpl_ranges.wgsl): a tile
// visits the clusters its box meets, not every VPL of the frame.
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
const MAX_TILE_LIGHTS: u32 = {{ max_tile_lights }}u;

{{ bindings }}
{% include "gbuffer_read.wgsl" %}
{% if glossy %}
{% include "vpl_glossy.wgsl" %}
{% endif %}
{% include "vpl_ranges.wgsl" %}
{% if counters %}
{% include "work_counters.wgsl" %}
{% endif %}

{% include "vpl_receiver.wgsl" %}

fn cluster_slot(c: u32, k: u32) -> u32 {
    return near_slots[(c - params.near_clusters_at) * CLUSTER + k];
}

fn cull_r2_of(slot: u32) -> f32 {
    return near_cull_r2_of(slot, params.near_r2);
}

fn shade_list(count: u32) {
    if !valid {
        return;
    }
    // The flux the light buffer holds is P^2 times the VPL's own.
    let unscale = 1.0 / interleave_flux_scale(P);
    for (var m = 0u; m < count; m++) {
        let slot = tile_lights[m];
        let l = lights[slot];
        let v = pos - l.p0;
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
{% if counters %}
    count_add(COUNT_TESTED, count);
{% endif %}
}

{% include "cluster_cull.wgsl" %}

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
    let tile_box = load_receiver(li, pix, inside);
    if !box_is_empty(tile_box) {
{% if counters %}
        count_tests(li, COUNT_TILES, 1u);
{% endif %}
        cull_tile(li, tile_box.lo, tile_box.hi, params.near_grid, params.near_clusters_at, params.near_groups_at);
    }
{% if counters %}
    count_receiver(li);
{% endif %}
    if valid {
        let old = irradiance[pix];
        irradiance[pix] = vec4f(old.xyz + e, old.w + f32(kept));
{% if glossy %}
        specular[pix] = vec4f(specular[pix].xyz + s, 0.0);
{% endif %}
    }
}
