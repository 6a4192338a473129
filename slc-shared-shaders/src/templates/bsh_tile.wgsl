// The direct pass's tile walk: one walk of the light hierarchy per tile
// lists, in traversal order, the leaves that may reach some pixel of the
// tile (slc-core's bsh_reaches_box: the tile's box of positions at its
// pixels' largest range-lobe scale); each pixel then tests the listed
// leaves exactly (bsh_reaches) and finds the lights its own walk would, in
// the same order, so its random draws are unchanged. The walk is shared by
// the tile's invocations: the BSH_TILE_SUBTREES subtrees at depth
// BSH_TILE_DEPTH (slc-core's bsh_subtree) are dealt out interleaved (a
// tile's lights sit in few neighbouring subtrees), a counting walk sizes
// each subtree's run, a prefix sum places it, and the list is filled
// TILE_LIST entries at a time: a longer one is shaded in several rounds.
//
// The including kernel has TILE_THREADS invocations (a power of two:
// BOX_THREADS of workgroup_box.wgsl) and includes bsh_walk.wgsl.

const TILE_LIST: u32 = {{ max_tile_lights }}u;

{% include "workgroup_box.wgsl" %}

/// This round's slice of the tile's list: node indices of leaves.
var<workgroup> tile_list: array<u32, TILE_LIST>;
/// Each subtree's first position in the tile's list.
var<workgroup> subtree_at: array<u32, BSH_TILE_SUBTREES>;
/// The pixels' largest range-lobe scale (f32 bits; 0 before any).
var<workgroup> tile_scale: atomic<u32>;
/// The length of the tile's list.
var<workgroup> tile_total: u32;

/// A tile's walk: its box, scale and list length (uniform values).
struct TileWalk {
    lo: vec3f,
    hi: vec3f,
    w: f32,
    total: u32,
}

/// The number of leaves of subtree `s` that reach the tile `t`; with
/// `list`, the ones at list positions `start..to` (the subtree's run
/// starting at `at`) are written to `tile_list`, relative to `start`, and
/// the walk stops at `to`.
fn tile_subtree(s: u32, t: TileWalk, list: bool, at: u32, start: u32, to: u32) -> u32 {
    let root = bsh_subtree(BSH, s, BSH_TILE_DEPTH);
    if root == BSH_NONE {
        return 0u;
    }
    let end = bsh_nodes[root].next;
    var p = at;
    for (var b = bsh_next_leaf_box(BSH, root, end, t.lo, t.hi, t.w); b != end && (!list || p < to); b = bsh_next_leaf_box(BSH, bsh_nodes[b].next, end, t.lo, t.hi, t.w)) {
        if list && p >= start {
            tile_list[p - start] = b;
        }
        p += 1u;
    }
    return p - at;
}

/// Starts the tile's walk for the pixel at `x` with range-lobe scale `w`
/// (`has`: whether it has a surface) and sizes its list. Every invocation
/// calls it (barriers); `li` is its local_invocation_index. A NaN scale
/// is left out of the tile's (that pixel's `bsh_reaches` accepts only the
/// plain spheres that hold it), its position is not.
fn tile_walk_begin(li: u32, x: vec3f, w: f32, has: bool) -> TileWalk {
    atomicMax(&tile_scale, select(0u, bitcast<u32>(w), has && w >= 0.0));
    let box = workgroup_box(li, x, has);
    var t = TileWalk(box.lo, box.hi, bitcast<f32>(workgroupUniformLoad(&tile_scale)), 0u);
    if box_is_empty(box) {
        return t;
    }
    for (var s = li; s < BSH_TILE_SUBTREES; s += TILE_THREADS) {
        subtree_at[s] = tile_subtree(s, t, false, 0u, 0u, 0u);
    }
    workgroupBarrier();
    if li == 0u {
        var sum = 0u;
        for (var s = 0u; s < BSH_TILE_SUBTREES; s++) {
            let c = subtree_at[s];
            subtree_at[s] = sum;
            sum += c;
        }
        tile_total = sum;
    }
    t.total = workgroupUniformLoad(&tile_total);
    return t;
}

/// Fills `tile_list` with the tile's list from position `start` on, at
/// most TILE_LIST entries, and returns how many. Every invocation calls it
/// (barriers), after every invocation is done with the previous round's.
fn tile_walk_fill(li: u32, t: TileWalk, start: u32) -> u32 {
    let to = min(t.total, start + TILE_LIST);
    for (var s = li; s < BSH_TILE_SUBTREES; s += TILE_THREADS) {
        let at = subtree_at[s];
        var past = t.total;
        if s + 1u < BSH_TILE_SUBTREES {
            past = subtree_at[s + 1u];
        }
        if at < to && past > start {
            tile_subtree(s, t, true, at, start, to);
        }
    }
    workgroupBarrier();
    return to - start;
}
