// The box of a workgroup's invocations' boxes, reduced in workgroup memory:
// vpl_tiled and vpl_near (a tile's G-buffer positions), vpl_clusters (a
// cluster's culling spheres) and vpl_groups (a group's cluster boxes). The
// including kernel defines BOX_THREADS, its invocation count (a power of
// two).

var<workgroup> wg_lo: array<vec3f, BOX_THREADS>;
var<workgroup> wg_hi: array<vec3f, BOX_THREADS>;
var<workgroup> wg_box: WorkgroupBox;

/// A box `lo ≤ hi`, or empty (`lo = F32_MAX > hi = -F32_MAX`).
struct WorkgroupBox {
    lo: vec3f,
    hi: vec3f,
}

/// The box holding every invocation's box `[lo, hi]` (an empty one adds
/// nothing), the same value in every invocation (a uniform value: it may
/// decide a branch with barriers). Every invocation must call it (it has
/// barriers); `li` is its local_invocation_index.
fn workgroup_bounds(li: u32, lo: vec3f, hi: vec3f) -> WorkgroupBox {
    wg_lo[li] = lo;
    wg_hi[li] = hi;
    workgroupBarrier();
    for (var stride = BOX_THREADS / 2u; stride > 0u; stride = stride / 2u) {
        if li < stride {
            wg_lo[li] = min(wg_lo[li], wg_lo[li + stride]);
            wg_hi[li] = max(wg_hi[li], wg_hi[li + stride]);
        }
        workgroupBarrier();
    }
    if li == 0u {
        wg_box = WorkgroupBox(wg_lo[0], wg_hi[0]);
    }
    return workgroupUniformLoad(&wg_box);
}

/// The box of the point `p` where `has`, else the empty box.
fn point_box(p: vec3f, has: bool) -> WorkgroupBox {
    return WorkgroupBox(select(vec3f(F32_MAX), p, has), select(vec3f(-F32_MAX), p, has));
}

/// The box holding every invocation's `p` where `has` (empty if none).
fn workgroup_box(li: u32, p: vec3f, has: bool) -> WorkgroupBox {
    let b = point_box(p, has);
    return workgroup_bounds(li, b.lo, b.hi);
}

/// `true` for the empty box of a reduction over no point.
fn box_is_empty(b: WorkgroupBox) -> bool {
    return b.lo.x > b.hi.x;
}
