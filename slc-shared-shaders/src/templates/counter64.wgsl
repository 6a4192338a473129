/// Adds `n` to the 64-bit work counter of field `f` in the kernel's
/// `counters` buffer (low word at 2f, high at 2f + 1, the carry added where
/// the low word wraps): the counting variants' one writer.
fn counter_add(f: u32, n: u32) {
    let old = atomicAdd(&counters[2u * f], n);
    if old + n < old {
        atomicAdd(&counters[2u * f + 1u], 1u);
    }
}
