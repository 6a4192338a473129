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
// visits the clusters its box meets, not every VPL of the frame. Each listed
// light goes to the lists of the tile's quarters (four (TILE/2)^2 squares)
// whose own box its sphere meets, and an invocation shades only its
// quarter's list (the CPU's near tiling culls the tile's list to each
// quarter's box).
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

/// Side of a quarter: the tile's four (TILE/2)^2 squares, quarter q at
/// columns from (q % 2) HALF and rows from (q / 2) HALF.
const HALF: u32 = (TILE + 1u) / 2u;
/// Capacity of each quarter's list (slc-shared-shaders'
/// near_quarter_lights: a quarter of the tile list, at least a cluster).
const QUARTER_LIGHTS: u32 = {{ quarter_lights }}u;
var<workgroup> quarter_lo: array<vec3f, 4>;
var<workgroup> quarter_hi: array<vec3f, 4>;
/// Quarter q's list: the light slots quarter_lights[q QUARTER_LIGHTS ..]
/// [..quarter_count[q]], in the order they were added.
var<workgroup> quarter_lights: array<u32, {{ quarter_list }}>;
var<workgroup> quarter_count: array<atomic<u32>, 4>;
/// The longest quarter list.
var<workgroup> fullest: atomic<u32>;
/// This invocation's quarter.
var<private> quarter: u32;

/// The box of each quarter's surfaces (empty where none), into
/// quarter_lo/hi, and this invocation's quarter. Every invocation calls it,
/// after load_receiver (it reuses workgroup_box.wgsl's arrays).
fn quarter_boxes(li: u32, lid: vec3u) {
    quarter = select(0u, 1u, lid.x >= HALF) + select(0u, 2u, lid.y >= HALF);
    let own = point_box(pos, valid);
    wg_lo[li] = own.lo;
    wg_hi[li] = own.hi;
    workgroupBarrier();
    if li < 4u {
        var lo = vec3f(F32_MAX);
        var hi = vec3f(-F32_MAX);
        let x0 = (li % 2u) * HALF;
        let y0 = (li / 2u) * HALF;
        for (var y = y0; y < min(y0 + HALF, TILE); y++) {
            for (var x = x0; x < min(x0 + HALF, TILE); x++) {
                lo = min(lo, wg_lo[y * TILE + x]);
                hi = max(hi, wg_hi[y * TILE + x]);
            }
        }
        quarter_lo[li] = lo;
        quarter_hi[li] = hi;
    }
    workgroupBarrier();
}

// The light lists of cluster_cull.wgsl: one per quarter, each light in the
// lists of the quarters whose own box its sphere meets (the CPU's near
// tiling culls the tile's list to each quarter's box). An invocation loops
// over its own quarter's list only, so the invocations of a warp that
// shades two quarters run the longer of their two lists, not their union.

fn list_clear(li: u32) {
    if li < 4u {
        atomicStore(&quarter_count[li], 0u);
    }
    if li == 0u {
        atomicStore(&fullest, 0u);
    }
}

fn list_full() -> bool {
    return workgroupUniformLoad(&fullest) + CLUSTER > QUARTER_LIGHTS;
}

/// Adds light `slot` to quarter q's list where the quarter has surfaces
/// and the sphere (p, radius) meets their box (a test, counted): the list's
/// new length, else 0. Called four times, not looped: lavapipe counts
/// every loop iteration against its limit.
fn quarter_add(q: u32, slot: u32, p: vec3f, radius: f32) -> u32 {
    let lo = quarter_lo[q];
    let hi = quarter_hi[q];
    if lo.x > hi.x {
        return 0u;
    }
{% if counters %}
    count_one(COUNT_SPHERE_TESTS);
{% endif %}
    if !sphere_overlaps_aabb(p, radius, lo, hi) {
        return 0u;
    }
    let n = atomicAdd(&quarter_count[q], 1u);
    quarter_lights[q * QUARTER_LIGHTS + n] = slot;
    return n + 1u;
}

fn list_add(slot: u32, p: vec3f, radius: f32) {
    let a = max(quarter_add(0u, slot, p, radius), quarter_add(1u, slot, p, radius));
    let b = max(quarter_add(2u, slot, p, radius), quarter_add(3u, slot, p, radius));
    atomicMax(&fullest, max(a, b));
}

fn list_shade() {
    workgroupBarrier();
    shade_list(atomicLoad(&quarter_count[quarter]), quarter * QUARTER_LIGHTS);
}

/// Shades this invocation's quarter's list, quarter_lights[first ..][..count].
fn shade_list(count: u32, first: u32) {
    if !valid {
        return;
    }
    // The flux the light buffer holds is P^2 times the VPL's own.
    let unscale = 1.0 / interleave_flux_scale(P);
    for (var m = 0u; m < count; m++) {
        let slot = quarter_lights[first + m];
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
        quarter_boxes(li, lid);
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
