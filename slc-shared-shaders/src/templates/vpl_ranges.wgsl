// The near field's ranges of a VPL with {{ method }} culling, read by
// vpl_near (its shares) and vpl_clusters (its cluster boxes): the r^2 the
// near field keeps light `slot` by, its own range at the VPL's flux (slc:
// vpl_near_range2 of the interleaved light's r^2, the same xi) or the
// interleaved light's fixed range (clamp, none); and the squared radius of
// its culling sphere, that range cut at R_n (vpl_near_cull_range2).

fn near_r2_of(slot: u32) -> f32 {
{% if method == "slc" %}
    return vpl_near_range2(r2[slot], P);
{% else %}
    return r2[slot];
{% endif %}
}

fn near_cull_r2_of(slot: u32, near_r2: f32) -> f32 {
    return vpl_near_cull_range2(near_r2_of(slot), near_r2);
}
