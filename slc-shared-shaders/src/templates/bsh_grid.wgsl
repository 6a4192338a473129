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
//   5 (a workgroup per cell) each cell sorted by rank, the ranks turned
//     into node indices, its count cleared.
// The path tracer builds up to three grids in the same buffers, one for
// Lambertian receivers and one for glossy lobes up to each of two reaches:
// each dispatch's `params` say where its grid's words, counts and entries
// start, and the entries it may take at least.

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

/// Stage 5's cell: its ranks, then its first entry and end.
var<workgroup> wg_cell: array<u32, GRID_SORT_MAX>;
var<workgroup> wg_span: vec2u;

/// Stage 5 for cell `cell` of this dispatch's grid, by one workgroup
/// (`li` its invocation): the ranks stage 4 appended in any order are put
/// in order, each at the count of the cell's ranks below it (a leaf is
/// listed once a cell), as the leaf's node index; the cell's count is
/// cleared. A cell of more than `GRID_SORT_MAX` entries is sorted by
/// insertion by one invocation.
fn sort_cell(cell: u32, li: u32) {
    let starts = params.header + GRID_HEADER;
    if li == 0u {
        let f = grid_frame(params.header);
        var span = vec2u(0u);
        if cell < f.nx * f.ny * f.nz {
            span = vec2u(atomicLoad(&grid[starts + cell]), atomicLoad(&grid[starts + cell + 1u]));
            atomicStore(&grid_fill[params.fill + cell], 0u);
        }
        wg_span = span;
    }
    let span = workgroupUniformLoad(&wg_span);
    let a = span.x;
    let n = span.y - span.x;
    if n > GRID_SORT_MAX {
        if li == 0u {
            for (var s = a + 1u; s < a + n; s++) {
                let v = grid_entries[s];
                var c = s;
                while c > a && grid_entries[c - 1u] > v {
                    grid_entries[c] = grid_entries[c - 1u];
                    c -= 1u;
                }
                grid_entries[c] = v;
            }
            for (var s = a; s < a + n; s++) {
                grid_entries[s] = grid_leaves[grid_entries[s]];
            }
        }
        return;
    }
    for (var j = li; j < n; j += {{ wg }}u) {
        wg_cell[j] = grid_entries[a + j];
    }
    workgroupBarrier();
    for (var j = li; j < n; j += {{ wg }}u) {
        let v = wg_cell[j];
        var below = 0u;
        for (var m = 0u; m < n; m++) {
            below += select(0u, 1u, wg_cell[m] < v);
        }
        grid_entries[a + below] = grid_leaves[v];
    }
}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u, @builtin(workgroup_id) wid: vec3u, @builtin(num_workgroups) groups: vec3u, @builtin(local_invocation_index) li: u32) {
    if params.stage == 5u {
        sort_cell(wid.y * groups.x + wid.x, li);
        return;
    }
    let i = gid.x;
    // This grid's words in `grid`, its counts in `grid_fill`.
    let h = params.header;
    let starts = h + GRID_HEADER;
    if params.stage == 3u {
        // One workgroup: each invocation scans a run of cells, then adds
        // the runs before it; the starts are positions in `grid_entries`.
        let f = grid_frame(h);
        let cells = f.nx * f.ny * f.nz;
        let run = (cells + {{ wg }}u - 1u) / {{ wg }}u;
        let a = min(i * run, cells);
        let b = min(a + run, cells);
        var sum = 0u;
        for (var c = a; c < b; c++) {
            sum += atomicLoad(&grid_fill[params.fill + c]);
        }
        wg_sums[i] = sum;
        workgroupBarrier();
        var start = params.entries;
        for (var j = 0u; j < i; j++) {
            start += wg_sums[j];
        }
        for (var c = a; c < b; c++) {
            let n = atomicLoad(&grid_fill[params.fill + c]);
            atomicStore(&grid[starts + c], start);
            atomicStore(&grid_fill[params.fill + c], start);
            start += n;
        }
        if i + 1u == {{ wg }}u {
            atomicStore(&grid[starts + cells], start);
        }
        return;
    }
    switch params.stage {
        case 0u: {
            if i >= params.count {
                return;
            }
            let node = grid_leaf(i);
            if node == BSH_NONE {
                return;
            }
            atomicAdd(&grid[h + 13u], 1u);
            let leaf = bsh_nodes[node];
            let r = bsh_grid_radius(leaf, params.reach);
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
        case 1u: {
            if i != 0u {
                return;
            }
            let leaves = atomicLoad(&grid[h + 13u]);
            var chosen = params.levels;
            for (var l = 0u; l < params.levels; l++) {
                let f = grid_levels[l];
                let cells = f.nx * f.ny * f.nz;
                let budget = min(bsh_grid_budget(leaves, cells, params.least), params.capacity);
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
            atomicStore(&grid[h + 12u], bitcast<u32>(params.reach));
        }
        case 2u, 4u: {
            if i >= params.count {
                return;
            }
            let f = grid_frame(h);
            let node = grid_leaf(i);
            if f.nx == 0u || node == BSH_NONE {
                return;
            }
            let leaf = bsh_nodes[node];
            let r = bsh_grid_radius(leaf, params.reach);
            let a = bsh_grid_first(f, leaf.center, r);
            let b = bsh_grid_last(f, leaf.center, r);
            for (var z = a.z; z <= b.z; z++) {
                for (var y = a.y; y <= b.y; y++) {
                    for (var x = a.x; x <= b.x; x++) {
                        let c = (z * f.ny + y) * f.nx + x;
                        let at = atomicAdd(&grid_fill[params.fill + c], 1u);
                        if params.stage == 4u {
                            grid_entries[at] = i;
                        }
                    }
                }
            }
        }
        default: {}
    }
}
