// The counting variant's work counters (slc_scene::vpl::WorkCounts): each
// field summed over the workgroup in workgroup memory, then added by one
// invocation to `counters` as a 64-bit count (counter64.wgsl). Never in a
// timed frame.

{% include "counter64.wgsl" %}

// The fields (COUNT_TILES … COUNT_FIELDS) are the layout's constants.

var<workgroup> wg_counts: array<atomic<u32>, COUNT_FIELDS>;

/// Clears the workgroup's counts; every invocation calls it first.
fn counts_begin(li: u32) {
    if li < COUNT_FIELDS {
        atomicStore(&wg_counts[li], 0u);
    }
    workgroupBarrier();
}

/// Adds `n` to field `f` (any invocation).
fn count_add(f: u32, n: u32) {
    atomicAdd(&wg_counts[f], n);
}

/// Adds 1 to field `f`.
fn count_one(f: u32) {
    atomicAdd(&wg_counts[f], 1u);
}

/// Adds `n` tests the whole workgroup made together (counted once).
fn count_tests(li: u32, f: u32, n: u32) {
    if li == 0u {
        atomicAdd(&wg_counts[f], n);
    }
}

/// Adds the workgroup's counts to `counters`; every invocation calls it
/// last.
fn counts_end(li: u32) {
    workgroupBarrier();
    if li < COUNT_FIELDS {
        counter_add(li, atomicLoad(&wg_counts[li]));
    }
}
