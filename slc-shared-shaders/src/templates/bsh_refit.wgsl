{% include "header.wgsl" %}
// BSH refit for new ranges, one dispatch per tree level, deepest first
// (`order` lists node indices level by level; RefitParams picks the level):
// leaves get radius R + √r², inner nodes the union of their two children.

@group(0) @binding(0) var<uniform> params: RefitParams;
@group(0) @binding(1) var<storage, read> order: array<u32>;
@group(0) @binding(2) var<storage, read> extent: array<f32>;
@group(0) @binding(3) var<storage, read> r2: array<f32>;
@group(0) @binding(4) var<storage, read_write> bsh_nodes: array<BshNode>;
@group(1) @binding(0) var<storage, read> slc_table: array<f32>;

{% include "bsh_walk.wgsl" %}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= params.count {
        return;
    }
    let i = order[params.first + gid.x];
    let node = bsh_nodes[i];
    if node.child == BSH_NONE {
        bsh_nodes[i].radius = range_radius(extent[node.light], r2[node.light]);
        return;
    }
    let u = bsh_children_sphere(BSH, i);
    bsh_nodes[i].center = u.xyz;
    bsh_nodes[i].radius = u.w;
}
