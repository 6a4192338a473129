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
//   5 (per cell) each cell sorted by rank, the ranks turned into node
//     indices, its count cleared.

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

/// The first cells `(x, y, z)` of leaf `node` in frame `f`.
fn cover_first(f: GridFrame, node: BshNode, r: f32) -> vec3u {
    let c = node.center;
    return vec3u(bsh_grid_axis(c.x - r, f.lo.x, f.inv.x, f.nx), bsh_grid_axis(c.y - r, f.lo.y, f.inv.y, f.ny), bsh_grid_axis(c.z - r, f.lo.z, f.inv.z, f.nz));
}

/// The last cells `(x, y, z)` of leaf `node` in frame `f`.
fn cover_last(f: GridFrame, node: BshNode, r: f32) -> vec3u {
    let c = node.center;
    return vec3u(bsh_grid_axis(c.x + r, f.lo.x, f.inv.x, f.nx), bsh_grid_axis(c.y + r, f.lo.y, f.inv.y, f.ny), bsh_grid_axis(c.z + r, f.lo.z, f.inv.z, f.nz));
}

/// Each invocation's running sum in stage 3.
var<workgroup> wg_sums: array<u32, {{ wg }}>;

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let i = gid.x;
    if params.stage == 3u {
        // One workgroup: each invocation scans a run of cells, then adds
        // the runs before it.
        let f = grid_frame();
        let cells = f.nx * f.ny * f.nz;
        let run = (cells + {{ wg }}u - 1u) / {{ wg }}u;
        let a = min(i * run, cells);
        let b = min(a + run, cells);
        var sum = 0u;
        for (var c = a; c < b; c++) {
            sum += atomicLoad(&grid_fill[c]);
        }
        wg_sums[i] = sum;
        workgroupBarrier();
        var start = 0u;
        for (var j = 0u; j < i; j++) {
            start += wg_sums[j];
        }
        for (var c = a; c < b; c++) {
            let n = atomicLoad(&grid_fill[c]);
            atomicStore(&grid[GRID_HEADER + c], start);
            atomicStore(&grid_fill[c], start);
            start += n;
        }
        if i + 1u == {{ wg }}u {
            atomicStore(&grid[GRID_HEADER + cells], start);
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
            atomicAdd(&grid[13], 1u);
            let leaf = bsh_nodes[node];
            let r = bsh_grid_pad(bsh_grid_reach(leaf, params.reach));
            for (var l = 0u; l < params.levels; l++) {
                let d = cover_last(grid_levels[l], leaf, r) - cover_first(grid_levels[l], leaf, r) + vec3u(1u);
                let n = d.x * d.y * d.z;
                let at = 16u + 2u * l;
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
            let leaves = atomicLoad(&grid[13]);
            var chosen = params.levels;
            for (var l = 0u; l < params.levels; l++) {
                let f = grid_levels[l];
                let cells = f.nx * f.ny * f.nz;
                let budget = min(bsh_grid_budget(leaves, cells), params.capacity);
                if chosen == params.levels && atomicLoad(&grid[17u + 2u * l]) == 0u && atomicLoad(&grid[16u + 2u * l]) <= budget {
                    chosen = l;
                }
                atomicStore(&grid[16u + 2u * l], 0u);
                atomicStore(&grid[17u + 2u * l], 0u);
            }
            atomicStore(&grid[13], 0u);
            var f: GridFrame;
            if chosen < params.levels {
                f = grid_levels[chosen];
            }
            atomicStore(&grid[0], bitcast<u32>(f.lo.x));
            atomicStore(&grid[1], bitcast<u32>(f.lo.y));
            atomicStore(&grid[2], bitcast<u32>(f.lo.z));
            atomicStore(&grid[3], f.nx);
            atomicStore(&grid[4], bitcast<u32>(f.hi.x));
            atomicStore(&grid[5], bitcast<u32>(f.hi.y));
            atomicStore(&grid[6], bitcast<u32>(f.hi.z));
            atomicStore(&grid[7], f.ny);
            atomicStore(&grid[8], bitcast<u32>(f.inv.x));
            atomicStore(&grid[9], bitcast<u32>(f.inv.y));
            atomicStore(&grid[10], bitcast<u32>(f.inv.z));
            atomicStore(&grid[11], f.nz);
            atomicStore(&grid[12], bitcast<u32>(params.reach));
        }
        case 2u, 4u: {
            if i >= params.count {
                return;
            }
            let f = grid_frame();
            let node = grid_leaf(i);
            if f.nx == 0u || node == BSH_NONE {
                return;
            }
            let leaf = bsh_nodes[node];
            let r = bsh_grid_pad(bsh_grid_reach(leaf, params.reach));
            let a = cover_first(f, leaf, r);
            let b = cover_last(f, leaf, r);
            for (var z = a.z; z <= b.z; z++) {
                for (var y = a.y; y <= b.y; y++) {
                    for (var x = a.x; x <= b.x; x++) {
                        let c = (z * f.ny + y) * f.nx + x;
                        let at = atomicAdd(&grid_fill[c], 1u);
                        if params.stage == 4u {
                            grid_entries[at] = i;
                        }
                    }
                }
            }
        }
        default: {
            let f = grid_frame();
            if i >= f.nx * f.ny * f.nz {
                return;
            }
            atomicStore(&grid_fill[i], 0u);
            // Appended in any order: insertion sort by rank, then each
            // rank's node.
            let a = atomicLoad(&grid[GRID_HEADER + i]);
            let b = atomicLoad(&grid[GRID_HEADER + i + 1u]);
            for (var s = a + 1u; s < b; s++) {
                let v = grid_entries[s];
                var c = s;
                while c > a && grid_entries[c - 1u] > v {
                    grid_entries[c] = grid_entries[c - 1u];
                    c -= 1u;
                }
                grid_entries[c] = v;
            }
            for (var s = a; s < b; s++) {
                grid_entries[s] = grid_leaves[grid_entries[s]];
            }
        }
    }
}
