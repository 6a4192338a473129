// slc-core's shared BSH steps (bsh::walk: bsh_first, bsh_next_leaf(_lobe), bsh_reaches,
// bsh_leaf_refitted, bsh_family_refitted) over the including kernel's `bsh_nodes` buffer,
// read through the two readers the steps expect.

alias BshNodes = u32;
const BSH: BshNodes = 0u;
fn bsh_node(nodes: BshNodes, i: u32) -> BshNode {
    return bsh_nodes[i];
}
fn bsh_count(nodes: BshNodes) -> u32 {
    return arrayLength(&bsh_nodes);
}
{{ bsh_walk }}
