/// `slc-weighted`'s weight of light `li` for the receiver `(x, n, r, lobe)`
/// (slc-core's `cone_weight`, with the receiver's range scale). Needs the
/// bindings `light_cones` and `rt2`.
fn light_weight(li: u32, x: vec3f, n: vec3f, r: vec3f, lobe: vec4f) -> f32 {
    let c = light_cones[li];
    return cone_weight(c.center, c.radius, c.phi, c.axis, c.cos_o, c.cos_e, range_scale(lobe) * rt2[li], x, n, r, lobe);
}
