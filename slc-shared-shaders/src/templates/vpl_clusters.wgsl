{% include "header.wgsl" %}
// The cluster boxes of the VPL frame's two box hierarchies
// (slc_core::cluster), every frame once the ranges are drawn: workgroup c
// reduces the box of the culling spheres of cluster c's lit lights (empty
// where none is lit) into boxes[c] for c < far_groups_at, the far field's
// clusters (light k of cluster c in slot 64c + k; sphere radius
// cull_radius(r^2)); then the near field's, cluster c' = c - far_groups_at
// into boxes[near_clusters_at + c'] (light k in near_slots[64c' + k];
// radius of the range cut at R_n, with {{ method }} culling). The workgroups
// are numbered row-major over a 2-D dispatch (any count fits).

const P: u32 = {{ period }}u;
const BOX_THREADS: u32 = CLUSTER;
{% include "workgroup_box.wgsl" %}

{{ bindings }}
{% include "vpl_ranges.wgsl" %}

@compute @workgroup_size(CLUSTER)
fn main(
    @builtin(workgroup_id) wg: vec3u,
    @builtin(num_workgroups) nwg: vec3u,
    @builtin(local_invocation_index) li: u32,
) {
    let c = wg.y * nwg.x + wg.x;
    let far = params.far_groups_at;
    let near = params.near_groups_at - params.near_clusters_at;
    if c >= far + near {
        return;
    }
    var slot: u32;
    var out: u32;
    var r2_cull: f32;
    if c < far {
        slot = c * CLUSTER + li;
        out = c;
        r2_cull = r2[slot];
    } else {
        slot = near_slots[(c - far) * CLUSTER + li];
        out = params.near_clusters_at + c - far;
        r2_cull = near_cull_r2_of(slot, params.near_r2);
    }
    let l = lights[slot];
    let lit = any(l.intensity != vec3f(0.0));
    let r = cull_radius(r2_cull);
    let b = workgroup_bounds(
        li,
        select(vec3f(F32_MAX), l.p0 - vec3f(r), lit),
        select(vec3f(-F32_MAX), l.p0 + vec3f(r), lit),
    );
    if li == 0u {
        boxes[out] = GpuBox(b.lo, 0.0, b.hi, 0.0);
    }
}
