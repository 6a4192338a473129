// Tile culling through a two-level box hierarchy (slc_core::cluster), the
// loop of vpl_tiled (a subset's clusters) and vpl_near (the RSM's), as the
// CPU's LightList::cull_tree_into walks it: every group box of the grid is
// tested against the tile's box; the cluster boxes of a group that meets
// it, one per invocation; then, cluster by cluster, the lit lights' culling
// spheres, one per invocation, the hits added to the workgroup's list(s).
// Lists that could not take one more cluster are shaded and emptied first,
// and the rest at the end (the paper's tile loop, culled by all the tile's
// threads at once).
//
// The including kernel has CLUSTER invocations (an 8x8 tile) and defines
// the binding `boxes`, and
//   fn cluster_slot(c: u32, k: u32) -> u32   slot of light k of the cluster
//                                            whose box is boxes[c]
//   fn cull_r2_of(slot: u32) -> f32          its culling sphere's radius^2
// and its light list(s) (vpl_tiled: tile_list.wgsl, one list every
// invocation shades; vpl_near: one list per quarter of the tile):
//   fn list_clear(li: u32)                   empties them (before a barrier)
//   fn list_full() -> bool                   uniform: one more cluster might
//                                            not fit (every invocation calls it)
//   fn list_add(slot: u32, p: vec3f, radius: f32)
//                                            adds a light whose sphere
//                                            (p, radius) meets the tile
//   fn list_shade()                          shades what they hold (every
//                                            invocation calls it)
{% if counters %}
// Counting variant: every test is counted (work_counters.wgsl).
{% endif %}

var<workgroup> cluster_hits: array<u32, CLUSTER>;
var<workgroup> hit_count: atomic<u32>;

/// Culls the hierarchy `grid` (bw, bh, gw, gh) whose cluster boxes start at
/// boxes[clusters_at] and group boxes at boxes[groups_at] against the
/// tile's box `[lo, hi]` (uniform), shading the lights that meet it. Every
/// invocation calls it; `li` is its local_invocation_index.
fn cull_tile(li: u32, lo: vec3f, hi: vec3f, grid: vec4u, clusters_at: u32, groups_at: u32) {
    list_clear(li);
    let groups = group_count(grid.x, grid.y, grid.z, grid.w);
{% if counters %}
    count_tests(li, COUNT_GROUP_TESTS, groups);
{% endif %}
    for (var g = 0u; g < groups; g++) {
        let gb = boxes[groups_at + g];
        if !box_overlaps_box(gb.lo, gb.hi, lo, hi) {
            continue;
        }
        let first = clusters_at + group_first(g, grid.x, grid.y, grid.z, grid.w);
        let n = group_clusters(g, grid.x, grid.y, grid.z, grid.w);
{% if counters %}
        count_tests(li, COUNT_CLUSTER_TESTS, n);
{% endif %}
        if li == 0u {
            atomicStore(&hit_count, 0u);
        }
        workgroupBarrier();
        if li < n {
            let cb = boxes[first + li];
            if box_overlaps_box(cb.lo, cb.hi, lo, hi) {
                cluster_hits[atomicAdd(&hit_count, 1u)] = first + li;
            }
        }
        let hits = workgroupUniformLoad(&hit_count);
        for (var h = 0u; h < hits; h++) {
            if list_full() {
                list_shade();
                workgroupBarrier();
                list_clear(li);
                workgroupBarrier();
            }
            let slot = cluster_slot(cluster_hits[h], li);
            let l = lights[slot];
            if any(l.intensity != vec3f(0.0)) {
{% if counters %}
                count_one(COUNT_SPHERE_TESTS);
{% endif %}
                let radius = cull_radius(cull_r2_of(slot));
                if sphere_overlaps_aabb(l.p0, radius, lo, hi) {
                    list_add(slot, l.p0, radius);
                }
            }
        }
        // The next group refills cluster_hits.
        workgroupBarrier();
    }
    list_shade();
}
