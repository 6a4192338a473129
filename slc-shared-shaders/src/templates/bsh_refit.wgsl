{% include "header.wgsl" %}
// BSH refit for new ranges, one dispatch per tree level, deepest first
// (`order` lists node indices level by level; RefitParams picks the level):
// leaves get their light's centre (lights move), radius R + √r² and extent
// R, inner nodes the union of their two children, the radius about it
// holding their light bounds and the largest range below them.

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
        let bound = bounds[node.light];
        bsh_nodes[i].center = bound.xyz;
        bsh_nodes[i].radius = range_radius(bound.w, r2[node.light]);
        bsh_nodes[i].extent = bound.w;
        return;
    }
    let u = bsh_children_sphere(BSH, i);
    bsh_nodes[i].center = u.xyz;
    bsh_nodes[i].radius = u.w;
    bsh_nodes[i].extent = bsh_children_extent(BSH, i, u.xyz);
    bsh_nodes[i].light = f32_to_bits(bsh_children_range(BSH, i));
}
