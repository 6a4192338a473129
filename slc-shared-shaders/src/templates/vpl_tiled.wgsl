{% include "header.wgsl" %}
{% include "lights.wgsl" %}
// Tiled deferred VPL shading with {{ method }} culling, for {{ period }}x{{ period }}
// interleaved sampling: workgroup (x, y, s) is tile (x, y) of sub-image s,
// which holds the pixels (s mod P + P·i, s / P + P·j) and shades them with
// VPL subset shifted_subset(s, subset_shift) (VPLs stored subset after
// subset, flux already scaled by P²).
// The tile's box of G-buffer positions is reduced in workgroup memory, the
// subset's range spheres are culled against it into a workgroup list (a
// chunk of the subset at a time), then each pixel loops over the list with
// the keep test and 1/p weight. Each light's transfer is weighted by its far
// share vpl_far_weight (the near share is vpl_near's): vpl_far_slc_share,
// vpl_far_fixed_share.
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

var<workgroup> tile_count: atomic<u32>;
var<workgroup> tile_lights: array<u32, MAX_TILE_LIGHTS>;

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
    // This frame's map: pixel class `sub` shades a shifted subset.
    let base = shifted_subset(sub, params.subset_shift, P) * params.lights_per_subset;
    var e = vec3f(0.0);
    var kept = 0u;
{% if glossy %}
    var s = vec3f(0.0);
    var g: Glossy;
    if valid {
        g = glossy_at(pix, pos.xyz);
    }
{% endif %}
{% if method == "none" %}
    if valid {
        for (var j = base; j < base + params.lights_per_subset; j++) {
            let l = lights[j];
            let v = pos.xyz - l.p0;
            // Unculled: the far share alone.
            let share = vpl_far_weight(dot(v, v), params.near_r2);
            if share > 0.0 {
                let t = vpl_transfer(l.p1, nrm, v, params.min_d2) * share;
                e += l.intensity * t;
{% if glossy %}
                s += glossy_term(g, l, nrm, v, t);
{% endif %}
                kept += 1u;
            }
        }
    }
{% else %}
    // The subset streams through the list MAX_TILE_LIGHTS lights at a time,
    // so any subset size fits the workgroup memory.
    for (var first = 0u; first < params.lights_per_subset; first += MAX_TILE_LIGHTS) {
        let end = min(first + MAX_TILE_LIGHTS, params.lights_per_subset);
        if li == 0u {
            atomicStore(&tile_count, 0u);
        }
        workgroupBarrier();
        for (var j = first + li; j < end; j += THREADS) {
            if sphere_overlaps_aabb(lights[base + j].p0, cull_radius(r2[base + j]), lo, hi) {
                let slot = atomicAdd(&tile_count, 1u);
                if slot < MAX_TILE_LIGHTS {
                    tile_lights[slot] = j;
                }
            }
        }
        let count = min(workgroupUniformLoad(&tile_count), MAX_TILE_LIGHTS);
        if valid {
            for (var k = 0u; k < count; k++) {
                let j = base + tile_lights[k];
                let l = lights[j];
                let v = pos.xyz - l.p0;
{% if method == "slc" %}
                let share = vpl_far_slc_share(rt2[j], r2[j], dot(v, v), params.near_r2);
{% else %}
                let share = vpl_far_fixed_share(r2[j], dot(v, v), params.near_r2);
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
        }
        // Every thread is done with the list before the next chunk refills it.
        workgroupBarrier();
    }
{% endif %}
    // Every pixel is written (zero where no surface is): nothing else
    // clears the irradiance of the last record.
    if inside {
        irradiance[pix] = vec4f(e, f32(kept));
{% if glossy %}
        specular[pix] = vec4f(s, 0.0);
{% endif %}
    }
}
