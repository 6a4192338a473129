{% include "header.wgsl" %}
// The BSH's range tail for this pass's ranges (slc-core's bsh::tail and
// Bsh::refit, which the CPU runs): stage 0 counts the lights' range-sphere
// radii into bins (`bsh_tail_key`), stage 1 cuts the histogram at the
// tail's length limit (`bsh_tail_cut`, over a copy in workgroup memory and
// its chunk sums), stage 2 appends the lights at or
// above the cut, stage 3 sorts them into light order, writes them as
// leaves after the tree, points the tree's rightmost path at the first and
// clears the histogram for the next pass. `bsh_refit` then leaves their
// ranges out of the tree.

{{ bindings }}

{% include "bsh_walk.wgsl" %}

/// Stage 1's copy of the histogram and its chunk sums, as slc-core's
/// `bsh_tail_cut` reads them.
var<workgroup> wg_bins: array<u32, BSH_TAIL_BINS>;
var<workgroup> wg_chunks: array<u32, 32>;
alias TailHist = u32;
const HIST: TailHist = 0u;
fn bsh_tail_bin(hist: TailHist, b: u32) -> u32 {
    return wg_bins[b];
}
fn bsh_tail_chunk(hist: TailHist, c: u32) -> u32 {
    return wg_chunks[c];
}
{{ bsh_tail }}

/// Light `tail[2 + s]`: the tail's `s`-th light.
fn tail_light(s: u32) -> u32 {
    return atomicLoad(&tail[2u + s]);
}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let i = gid.x;
    // Stage 1 runs as one workgroup: the histogram into workgroup memory,
    // each chunk summed by one invocation, then one invocation's cut.
    if params.stage == 1u {
        for (var b = i; b < BSH_TAIL_BINS; b += {{ wg }}u) {
            wg_bins[b] = atomicLoad(&tail_hist[b]);
        }
        workgroupBarrier();
        for (var c = i; c < BSH_TAIL_BINS / BSH_TAIL_CHUNK; c += {{ wg }}u) {
            var sum = 0u;
            for (var b = 0u; b < BSH_TAIL_CHUNK; b++) {
                sum += wg_bins[c * BSH_TAIL_CHUNK + b];
            }
            wg_chunks[c] = sum;
        }
        workgroupBarrier();
        if i == 0u {
            atomicStore(&tail[0], bsh_tail_cut(HIST, params.k));
            atomicStore(&tail[1], 0u);
        }
        return;
    }
    switch params.stage {
        case 0u: {
            if i < params.count {
                atomicAdd(&tail_hist[bsh_tail_key(range_radius(bounds[i].w, r2[i]))], 1u);
            }
        }
        case 2u: {
            if i < params.count && bsh_in_tail(bounds[i].w, r2[i], atomicLoad(&tail[0])) {
                atomicStore(&tail[2u + atomicAdd(&tail[1], 1u)], i);
            }
        }
        default: {
            for (var b = i; b < BSH_TAIL_BINS; b += {{ wg }}u) {
                atomicStore(&tail_hist[b], 0u);
            }
            if i != 0u {
                return;
            }
            // Appended in any order: insertion sort (at most k² steps).
            let count = atomicLoad(&tail[1]);
            for (var a = 1u; a < count; a++) {
                let v = tail_light(a);
                var c = a;
                while c > 0u && tail_light(c - 1u) > v {
                    atomicStore(&tail[2u + c], tail_light(c - 1u));
                    c -= 1u;
                }
                atomicStore(&tail[2u + c], v);
            }
            for (var s = 0u; s < count; s++) {
                let li = tail_light(s);
                let at = params.tree + s;
                let next = select(at + 1u, BSH_NONE, s + 1u == count);
                bsh_nodes[at] = bsh_tail_leaf(bsh_nodes[at], bounds[li], r2[li], li, next);
            }
            let first = select(params.tree, BSH_NONE, count == 0u);
            // Each node's last child is found before its `next` changes.
            var n = 0u;
            while n != BSH_NONE {
                let last = bsh_rightmost_next(BSH, n);
                bsh_nodes[n].next = first;
                n = last;
            }
        }
    }
}
