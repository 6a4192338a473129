// The box of the points of a workgroup's invocations, reduced in workgroup
// memory: vpl_tiled and vpl_near (a tile's G-buffer positions), vpl_pack (a
// near block's VPL positions). The including kernel defines BOX_THREADS, its
// invocation count (a power of two).

var<workgroup> wg_lo: array<vec3f, BOX_THREADS>;
var<workgroup> wg_hi: array<vec3f, BOX_THREADS>;

/// A box `lo ≤ hi`, or empty (`lo = F32_MAX > hi = -F32_MAX`).
struct WorkgroupBox {
    lo: vec3f,
    hi: vec3f,
}

/// The box holding every invocation's `p` where `has` (empty if none).
/// Every invocation must call it (it has barriers); `li` is its
/// local_invocation_index.
fn workgroup_box(li: u32, p: vec3f, has: bool) -> WorkgroupBox {
    wg_lo[li] = select(vec3f(F32_MAX), p, has);
    wg_hi[li] = select(vec3f(-F32_MAX), p, has);
    workgroupBarrier();
    for (var stride = BOX_THREADS / 2u; stride > 0u; stride = stride / 2u) {
        if li < stride {
            wg_lo[li] = min(wg_lo[li], wg_lo[li + stride]);
            wg_hi[li] = max(wg_hi[li], wg_hi[li + stride]);
        }
        workgroupBarrier();
    }
    return WorkgroupBox(wg_lo[0], wg_hi[0]);
}
