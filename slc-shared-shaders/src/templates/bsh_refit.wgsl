{% include "header.wgsl" %}
// BSH refit for new ranges, one dispatch per tree level, deepest first
// (`order` lists node indices level by level; RefitParams picks the level):
// leaves get their light's centre (lights move), radius R + √r² and extent
// R (a light in the range tail, which `bsh_tail` cut before: radius R and
// the BSH_TAIL mark), inner nodes the union of their two children, the
// radius about it holding their light bounds and the largest range below
// them.

{{ bindings }}

{% include "bsh_walk.wgsl" %}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= params.count {
        return;
    }
    let i = order[params.first + gid.x];
    let node = bsh_nodes[i];
    if node.child == BSH_NONE {
        let li = node.light & (BSH_TAIL - 1u);
        let bound = bounds[li];
        let in_tail = bsh_in_tail(bound.w, r2[li], tail[0]);
        bsh_nodes[i].center = bound.xyz;
        bsh_nodes[i].radius = range_radius(bound.w, select(r2[li], 0.0, in_tail));
        bsh_nodes[i].extent = bound.w;
        bsh_nodes[i].light = li | select(0u, BSH_TAIL, in_tail);
        return;
    }
    let u = bsh_children_sphere(BSH, i);
    bsh_nodes[i].center = u.xyz;
    bsh_nodes[i].radius = u.w;
    bsh_nodes[i].extent = bsh_children_extent(BSH, i, u.xyz);
    bsh_nodes[i].light = f32_to_bits(bsh_children_range(BSH, i));
}
