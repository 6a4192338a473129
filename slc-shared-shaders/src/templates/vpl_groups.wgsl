{% include "header.wgsl" %}
// The group boxes of the VPL frame's two box hierarchies
// (slc_core::cluster), after vpl_clusters: workgroup g reduces the boxes of
// its group's clusters (at most 64: one per invocation). Groups g <
// G_far are the far field's, subset by subset (group_count(far_grid) per
// subset, each subset's clusters lights_per_subset / 64 apart), into
// boxes[far_groups_at + g]; the near field's g' = g - G_far into
// boxes[near_groups_at + g'].

const BOX_THREADS: u32 = CLUSTER;
{% include "workgroup_box.wgsl" %}

{{ bindings }}

@compute @workgroup_size(CLUSTER)
fn main(
    @builtin(workgroup_id) wg: vec3u,
    @builtin(num_workgroups) nwg: vec3u,
    @builtin(local_invocation_index) li: u32,
) {
    let g = wg.y * nwg.x + wg.x;
    let far = params.near_clusters_at - params.far_groups_at;
    let near = params.box_count - params.near_groups_at;
    if g >= far + near {
        return;
    }
    var grid: vec4u;
    var k: u32;
    var clusters: u32;
    var out: u32;
    if g < far {
        grid = params.far_grid;
        let per = group_count(grid.x, grid.y, grid.z, grid.w);
        k = g % per;
        clusters = (g / per) * (params.lights_per_subset / CLUSTER);
        out = params.far_groups_at + g;
    } else {
        grid = params.near_grid;
        k = g - far;
        clusters = params.near_clusters_at;
        out = params.near_groups_at + k;
    }
    let n = group_clusters(k, grid.x, grid.y, grid.z, grid.w);
    var lo = vec3f(F32_MAX);
    var hi = vec3f(-F32_MAX);
    if li < n {
        let b = boxes[clusters + group_first(k, grid.x, grid.y, grid.z, grid.w) + li];
        lo = b.lo;
        hi = b.hi;
    }
    let b = workgroup_bounds(li, lo, hi);
    if li == 0u {
        boxes[out] = GpuBox(b.lo, 0.0, b.hi, 0.0);
    }
}
