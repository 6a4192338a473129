{% include "header.wgsl" %}
{% include "lights.wgsl" %}
// Tiled deferred VPL shading with {{ method }} culling, for {{ period }}x{{ period }}
// interleaved sampling: workgroup (x, y, s) is tile (x, y) of sub-image s,
// which holds the pixels (s mod P + P·i, s / P + P·j) and shades them with
// VPL subset shifted_subset(s, subset_shift) (VPLs stored subset after
// subset, each subset's image in map order, flux already scaled by P²).
// The tile's box of G-buffer positions is reduced in workgroup memory;
{% if method == "none" %}
// unculled, every pixel loops over the subset's lit VPLs.
{% else %}
// the subset's box hierarchy (vpl_clusters, vpl_groups) is culled against
// it into a workgroup list (cluster_cull.wgsl), which each pixel loops over
// with the keep test and 1/p weight. A tile without a surface culls
// nothing.
{% endif %}
// Each light's transfer is weighted by its far share vpl_far_weight (the
// near share is vpl_near's): vpl_far_slc_share, vpl_far_fixed_share.
{% if glossy %}
// Glossy variant: each pixel's material from `materials`; where it has a
// specular lobe the same kept lights, transfer and shares also sum the
// specular correction S into `specular` (zero elsewhere).
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
{% if counters %}
{% include "work_counters.wgsl" %}
{% endif %}

{% include "vpl_receiver.wgsl" %}

/// Adds light `j`'s far share at this pixel.
fn shade_light(j: u32) {
    let l = lights[j];
    let v = pos - l.p0;
{% if method == "slc" %}
    let share = vpl_far_slc_share(rt2[j], r2[j], dot(v, v), params.near_r2);
{% elif method == "clamp" %}
    let share = vpl_far_fixed_share(r2[j], dot(v, v), params.near_r2);
{% else %}
    // Unculled: the far share alone.
    let share = vpl_far_weight(dot(v, v), params.near_r2);
{% endif %}
    if share > 0.0 {
        let t = vpl_transfer(l.p1, nrm, v, params.min_d2) * share;
        e += l.intensity * t;
{% if glossy %}
        s += glossy_term(g, l, nrm, v, t);
{% endif %}
        kept += 1u;
    }
}

{% if method != "none" %}
fn cluster_slot(c: u32, k: u32) -> u32 {
    return c * CLUSTER + k;
}

fn cull_r2_of(slot: u32) -> f32 {
    return r2[slot];
}

/// Every invocation shades every listed light.
fn shade_list(count: u32) {
    if valid {
        for (var k = 0u; k < count; k++) {
            shade_light(tile_lights[k]);
        }
{% if counters %}
        count_add(COUNT_TESTED, count);
{% endif %}
    }
}

{% include "tile_list.wgsl" %}
{% include "cluster_cull.wgsl" %}
{% endif %}

@compute @workgroup_size({{ tile }}, {{ tile }}, 1)
fn main(
    @builtin(workgroup_id) wg: vec3u,
    @builtin(local_invocation_id) lid: vec3u,
    @builtin(local_invocation_index) li: u32,
) {
    let sub = wg.z;
    let px = sub % P + (wg.x * TILE + lid.x) * P;
    let py = sub / P + (wg.y * TILE + lid.y) * P;
    let inside = px < params.width && py < params.height;
    let pix = py * params.width + px;
    let tile_box = load_receiver(li, pix, inside);
    // This frame's map: pixel class `sub` shades a shifted subset.
    let subset = shifted_subset(sub, params.subset_shift, P);
{% if method == "none" %}
    if valid {
        let base = subset * params.lights_per_subset;
        for (var j = base; j < base + params.lights_per_subset; j++) {
            if any(lights[j].intensity != vec3f(0.0)) {
                shade_light(j);
{% if counters %}
                count_one(COUNT_TESTED);
{% endif %}
            }
        }
    }
{% else %}
    if !box_is_empty(tile_box) {
{% if counters %}
        count_tests(li, COUNT_TILES, 1u);
{% endif %}
        let grid = params.far_grid;
        cull_tile(
            li,
            tile_box.lo,
            tile_box.hi,
            grid,
            subset * (params.lights_per_subset / CLUSTER),
            params.far_groups_at + subset * group_count(grid.x, grid.y, grid.z, grid.w),
        );
    }
{% endif %}
{% if counters %}
    count_receiver(li);
{% endif %}
    // Every pixel is written (zero where no surface is): nothing else
    // clears the irradiance of the last record. The guide is the G-buffer
    // as the denoise weighs its neighbours: each of its taps then reads one
    // texel instead of unprojecting depth and normalising a normal.
    if inside {
        irradiance[pix] = vec4f(e, f32(kept));
        guide[pix] = vec4f(nrm, eye_distance);
{% if glossy %}
        specular[pix] = vec4f(s, 0.0);
{% endif %}
    }
}
