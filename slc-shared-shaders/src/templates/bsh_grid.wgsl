{% include "header.wgsl" %}
// A uniform grid over the refitted BSH's leaves for this pass (slc-core's
// BshGrid, which the CPU path tracer builds): every tree leaf the walk can
// find is listed in each cell its test can reach (slc-core's
// bsh_grid_reach, bsh_grid_pad, bsh_grid_axis), in the walk's order;
// `pt_connect` then tests its cell's leaves and the range tail instead of
// walking the tree, and finds the same lights in the same order. A
// counting sort in six stages over the leaves by their rank in the walk
// (`grid_leaves`: a wide tree's node order is not the walk's):
//   0 (per leaf) each frame's entries counted, 64-bit;
//   1 (one invocation) the first frame whose entries fit its budget
//     (slc-core's GridFrame::budget) is the pass's, or none (no cells along
//     x: the walks take the tree); the counts cleared;
//   2 (per leaf) each cell's entries counted;
//   3 (one workgroup) the cells' starts, an exclusive scan;
//   4 (per leaf) each leaf's rank scattered into its cells;
//   5 (per cell) each cell sorted by rank (by its own invocation where
//     it is almost in order, else by a bitonic sort of its workgroup), the
//     ranks turned into node indices, its count cleared.
// The path tracer builds up to three grids in the same buffers, one for
// Lambertian receivers and one for glossy lobes up to each of two reaches,
// all in the same six dispatches: workgroup row `workgroup_id.z = g`
// builds grid `g`, whose `grids[g]` says where its words, counts and
// entries start, and the entries it may take at least.

{{ bindings }}

{{ bsh_grid }}

/// Word `i` of `grid` (the reader `bsh_grid_frame.wgsl` expects).
fn grid_word(i: u32) -> u32 {
    return atomicLoad(&grid[i]);
}

{% include "bsh_grid_frame.wgsl" %}

/// The tree's `i`-th leaf in the walk's order when the walk can find it
/// (not in the range tail this pass), else `BSH_NONE`.
fn grid_leaf(i: u32) -> u32 {
    let node = grid_leaves[i];
    if (bsh_nodes[node].light & BSH_TAIL) != 0u {
        return BSH_NONE;
    }
    return node;
}

/// Each invocation's running sum in stage 3.
var<workgroup> wg_sums: array<u32, {{ wg }}>;

/// Stage 5's cells left to the whole workgroup (their spans), how many,
/// and the one being sorted: its ranks.
var<workgroup> wg_big: array<vec2u, {{ wg }}>;
var<workgroup> wg_bigs: atomic<u32>;
var<workgroup> wg_cell: array<u32, GRID_SORT_MAX>;

/// Key `j` of the cell stage 5 sorts from `a`: its copy in workgroup
/// memory, or for a cell too `big` for it its entry `a + j`.
fn cell_key(big: bool, a: u32, j: u32) -> u32 {
    if big {
        return grid_entries[a + j];
    }
    return wg_cell[j];
}

/// Sets key `j` of the cell stage 5 sorts ([`cell_key`]) to `v`.
fn set_cell_key(big: bool, a: u32, j: u32, v: u32) {
    if big {
        grid_entries[a + j] = v;
    } else {
        wg_cell[j] = v;
    }
}

/// The cell `wg_big[b]` (its entries in `grid_entries`) put in order by the
/// whole workgroup (`li` its invocation), its ranks then turned into the
/// leaves' node indices: a bitonic sort whose every exchange puts the
/// smaller key lower (Batcher 1968; each merge's first step compares
/// mirrored positions), padded to a power of two with keys above every
/// rank that never move, so a pair reaching past the cell is skipped; in
/// workgroup memory up to `GRID_SORT_MAX` entries, in place past it. `n ≤
/// 2^m` entries take `m(m + 1)/2` steps of `2^(m−1)` pairs.
fn sort_together(b: u32, li: u32) {
    let span = workgroupUniformLoad(&wg_big[b]);
    let a = span.x;
    let n = span.y - span.x;
    let big = n > GRID_SORT_MAX;
    if !big {
        for (var j = li; j < n; j += {{ wg }}u) {
            wg_cell[j] = grid_entries[a + j];
        }
    }
    // A cell's entries are within `grid_entries`'s binding (below 2³⁰).
    var p = 1u;
    while p < n {
        p <<= 1u;
    }
    workgroupBarrier();
    for (var k = 2u; k <= p; k <<= 1u) {
        for (var h = k >> 1u; h > 0u; h >>= 1u) {
            for (var t = li; t < (p >> 1u); t += {{ wg }}u) {
                let i = ((t & ~(h - 1u)) << 1u) | (t & (h - 1u));
                let o = select(i | h, i ^ (k - 1u), h == (k >> 1u));
                if o < n {
                    let x = cell_key(big, a, i);
                    let y = cell_key(big, a, o);
                    if y < x {
                        set_cell_key(big, a, i, y);
                        set_cell_key(big, a, o, x);
                    }
                }
            }
            workgroupBarrier();
            storageBarrier();
        }
    }
    for (var j = li; j < n; j += {{ wg }}u) {
        grid_entries[a + j] = grid_leaves[cell_key(big, a, j)];
    }
    workgroupBarrier();
}

/// Stage 5 for the cells `first..first + {{ wg }}` of grid `g`, by one
/// workgroup (`li` its invocation): each cell's ranks, appended by stage 4
/// in any order, put in order and turned into the leaves' node indices,
/// and its count cleared. Each cell is sorted by its own invocation, by
/// insertion, unless that takes `params.moves` moves (by default
/// `GRID_SORT_MOVES`, which a cell of up to 45 entries never takes): the
/// cells left are then sorted by the whole workgroup, one after another
/// ([`sort_together`]).
fn sort_cells(g: GridParams, first: u32, li: u32) {
    let starts = g.header + GRID_HEADER;
    let f = grid_frame(g.header);
    let cell = first + li;
    var span = vec2u(0u);
    if cell < f.nx * f.ny * f.nz {
        span = vec2u(atomicLoad(&grid[starts + cell]), atomicLoad(&grid[starts + cell + 1u]));
        atomicStore(&grid_fill[g.fill + cell], 0u);
    }
    if li == 0u {
        atomicStore(&wg_bigs, 0u);
    }
    workgroupBarrier();
    // By insertion while its moves stay within the budget: a cell stage 4
    // filled almost in order (neighbouring leaves fill it in turn) is done.
    var s = span.x + 1u;
    var moves = 0u;
    while s < span.y && moves < params.moves {
        let v = grid_entries[s];
        var c = s;
        while c > span.x && grid_entries[c - 1u] > v {
            grid_entries[c] = grid_entries[c - 1u];
            c -= 1u;
        }
        grid_entries[c] = v;
        moves += s - c;
        s += 1u;
    }
    if s < span.y {
        wg_big[atomicAdd(&wg_bigs, 1u)] = span;
    } else {
        for (var e = span.x; e < span.y; e++) {
            grid_entries[e] = grid_leaves[grid_entries[e]];
        }
    }
    // What an invocation's insertion moved before it stopped is read by the
    // others in `sort_together`.
    storageBarrier();
    let bigs = workgroupUniformLoad(&wg_bigs);
    for (var b = 0u; b < bigs; b++) {
        sort_together(b, li);
    }
}

/// Stage 0 for leaf `i` of grid `g`: its entries counted in each frame
/// tried (64-bit, low and high words from word 16), the tree's leaves the
/// walk can find in word 13.
fn count_levels(g: GridParams, i: u32) {
    if i >= params.count {
        return;
    }
    let h = g.header;
    let node = grid_leaf(i);
    if node == BSH_NONE {
        return;
    }
    atomicAdd(&grid[h + 13u], 1u);
    let leaf = bsh_nodes[node];
    let r = bsh_grid_radius(leaf, g.reach);
    for (var l = 0u; l < params.levels; l++) {
        let d = bsh_grid_last(grid_levels[l], leaf.center, r) - bsh_grid_first(grid_levels[l], leaf.center, r) + vec3u(1u);
        let n = d.x * d.y * d.z;
        let at = h + 16u + 2u * l;
        let old = atomicAdd(&grid[at], n);
        if old + n < old {
            atomicAdd(&grid[at + 1u], 1u);
        }
    }
}

/// Stage 1 of grid `g`, by one invocation: the first frame whose entries
/// fit its budget written as the pass's (words 0–11; none: no cells along
/// x) with the reach (word 12), and stage 0's counts cleared.
fn choose_level(g: GridParams) {
    let h = g.header;
    let leaves = atomicLoad(&grid[h + 13u]);
    var chosen = params.levels;
    for (var l = 0u; l < params.levels; l++) {
        let f = grid_levels[l];
        let cells = f.nx * f.ny * f.nz;
        let budget = min(bsh_grid_budget(leaves, cells, g.least), g.capacity);
        let at = h + 16u + 2u * l;
        if chosen == params.levels && atomicLoad(&grid[at + 1u]) == 0u && atomicLoad(&grid[at]) <= budget {
            chosen = l;
        }
        atomicStore(&grid[at], 0u);
        atomicStore(&grid[at + 1u], 0u);
    }
    atomicStore(&grid[h + 13u], 0u);
    var f: GridFrame;
    if chosen < params.levels {
        f = grid_levels[chosen];
    }
    atomicStore(&grid[h], bitcast<u32>(f.lo.x));
    atomicStore(&grid[h + 1u], bitcast<u32>(f.lo.y));
    atomicStore(&grid[h + 2u], bitcast<u32>(f.lo.z));
    atomicStore(&grid[h + 3u], f.nx);
    atomicStore(&grid[h + 4u], bitcast<u32>(f.hi.x));
    atomicStore(&grid[h + 5u], bitcast<u32>(f.hi.y));
    atomicStore(&grid[h + 6u], bitcast<u32>(f.hi.z));
    atomicStore(&grid[h + 7u], f.ny);
    atomicStore(&grid[h + 8u], bitcast<u32>(f.inv.x));
    atomicStore(&grid[h + 9u], bitcast<u32>(f.inv.y));
    atomicStore(&grid[h + 10u], bitcast<u32>(f.inv.z));
    atomicStore(&grid[h + 11u], f.nz);
    atomicStore(&grid[h + 12u], bitcast<u32>(g.reach));
}

/// Stages 2 (`scatter` false) and 4 for leaf `i` of grid `g`: each cell
/// its reach covers counted, or given the leaf's rank at the cell's next
/// free entry.
fn fill_cells(g: GridParams, i: u32, scatter: bool) {
    if i >= params.count {
        return;
    }
    let f = grid_frame(g.header);
    let node = grid_leaf(i);
    if f.nx == 0u || node == BSH_NONE {
        return;
    }
    let leaf = bsh_nodes[node];
    let r = bsh_grid_radius(leaf, g.reach);
    let a = bsh_grid_first(f, leaf.center, r);
    let b = bsh_grid_last(f, leaf.center, r);
    for (var z = a.z; z <= b.z; z++) {
        for (var y = a.y; y <= b.y; y++) {
            for (var x = a.x; x <= b.x; x++) {
                let c = (z * f.ny + y) * f.nx + x;
                let at = atomicAdd(&grid_fill[g.fill + c], 1u);
                if scatter {
                    grid_entries[at] = i;
                }
            }
        }
    }
}

/// Stage 3 of grid `g`, by one workgroup (`li` its invocation): each
/// invocation scans a run of cells, then adds the runs before it; the
/// starts are positions in `grid_entries`, written as the cells' first
/// entries and as stage 4's fill.
fn scan_starts(g: GridParams, li: u32) {
    let starts = g.header + GRID_HEADER;
    let f = grid_frame(g.header);
    let cells = f.nx * f.ny * f.nz;
    let run = (cells + {{ wg }}u - 1u) / {{ wg }}u;
    let a = min(li * run, cells);
    let b = min(a + run, cells);
    var sum = 0u;
    for (var c = a; c < b; c++) {
        sum += atomicLoad(&grid_fill[g.fill + c]);
    }
    wg_sums[li] = sum;
    workgroupBarrier();
    var start = g.entries;
    for (var j = 0u; j < li; j++) {
        start += wg_sums[j];
    }
    for (var c = a; c < b; c++) {
        let n = atomicLoad(&grid_fill[g.fill + c]);
        atomicStore(&grid[starts + c], start);
        atomicStore(&grid_fill[g.fill + c], start);
        start += n;
    }
    if li + 1u == {{ wg }}u {
        atomicStore(&grid[starts + cells], start);
    }
}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u, @builtin(workgroup_id) wid: vec3u, @builtin(num_workgroups) groups: vec3u, @builtin(local_invocation_index) li: u32) {
    let g = grids[wid.z];
    switch params.stage {
        case 0u: {
            count_levels(g, gid.x);
        }
        case 1u: {
            if li == 0u {
                choose_level(g);
            }
        }
        case 3u: {
            scan_starts(g, li);
        }
        case 5u: {
            sort_cells(g, (wid.y * groups.x + wid.x) * {{ wg }}u, li);
        }
        default: {
            fill_cells(g, gid.x, params.stage == 4u);
        }
    }
}
