/// The factor by which a receiver at `x` (mirror direction `r`, range lobe
/// `rl`: slc-core's `range_lobe`) scales light `li`'s ranges² (slc-core's
/// `range_scale_toward` over the light's bounding sphere, as the BSH's
/// `bsh_reaches` takes it over the light's leaf). Needs the binding
/// `light_cones`.
fn light_range_scale(li: u32, x: vec3f, r: vec3f, rl: vec4f) -> f32 {
    let c = light_cones[li];
    return range_scale_toward(rl, c.center, c.radius, x, r);
}

/// `slc-weighted`'s weight of light `li` for the receiver `(x, n, r, lobe)`
/// with range lobe `rl` (slc-core's `cone_weight`, with the receiver's range
/// scale toward the light). Needs the bindings `light_cones` and `rt2`.
fn light_weight(li: u32, x: vec3f, n: vec3f, r: vec3f, lobe: vec4f, rl: vec4f) -> f32 {
    let c = light_cones[li];
    return cone_weight(c.center, c.radius, c.phi, c.axis, c.cos_o, c.cos_e, light_range_scale(li, x, r, rl) * rt2[li], x, n, r, lobe);
}
