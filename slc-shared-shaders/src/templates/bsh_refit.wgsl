{% include "header.wgsl" %}
// BSH refit for new ranges, one dispatch per tree level, deepest first
// (`order` lists node indices level by level; RefitParams picks the level):
// leaves bsh_leaf_refitted (their light's centre, as lights move, radius
// R + √r² and extent R; a light in the range tail, which `bsh_tail` cut
// before: radius R and the BSH_TAIL mark), inner nodes bsh_family_refitted
// (the union of their children, the radius about it holding their light
// bounds and the largest range below them; a wide tree's nodes have up to
// eight): slc-core's steps, which the CPU's refit runs.

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
        bsh_nodes[i] = bsh_leaf_refitted(node, bounds[li], r2[li], tail[0]);
        return;
    }
    bsh_nodes[i] = bsh_family_refitted(BSH, node);
}
