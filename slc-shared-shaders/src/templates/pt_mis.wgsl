// MIS of the path tracer's two strategies ({{ heuristic }} heuristic): the
// light strategy (BSH + {{ k }}-slot reservoir + RR) against BSDF sampling.
// Needs bindings `lights`, `rt2`, `power_table`, `light_cones` and
// `light_bvh` (the including kernel declares them from its binding table). A receiver is `x`, its shading normal
// `n`, the view's mirror direction `r` and its BRDF lobe `lobe`
// (slc-core's `receiver_lobe`), which weigh the lights of slc-weighted and
// the light BVH.

/// MIS weight of strategy `a` against strategy `b`.
fn mis_weight(pdf_a: f32, pdf_b: f32) -> f32 {
{% if heuristic == "power" %}
    return mis_power(pdf_a, pdf_b);
{% else %}
    return mis_balance(pdf_a, pdf_b);
{% endif %}
}

{% include "light_weight.wgsl" %}

/// The kernel's `light_bvh` buffer as slc-core's shared walks
/// (`light_bvh_sample`, `light_bvh_pmf`, below) read it.
alias BvhNodes = u32;
const BVH: BvhNodes = 0u;
fn light_bvh_node(nodes: BvhNodes, i: u32) -> GpuLightBvhNode {
    return light_bvh[i];
}
fn light_bvh_count(nodes: BvhNodes) -> u32 {
    return arrayLength(&light_bvh);
}
{{ bvh_walk }}

/// Probability (expected count, for the weighted picks) that the light
/// strategy for the receiver `(x, n, r, lobe)` (range lobe `rl`: slc-core's `range_lobe`) selects light `li` ({{ selection }}
/// selection). `nee` is what the traversal at `x` left: the in-range count
/// (reservoir) or the bits of the candidates' total weight (weighted);
/// `in_range` says this pass's range of `li` reaches `x`, so that the
/// probability is the one of the *other* candidates, independent of the
/// light's own ξ.
fn select_pdf(li: u32, x: vec3f, n: vec3f, r: vec3f, lobe: vec4f, rl: vec4f, nee: u32, in_range: bool) -> f32 {
{% if selection == "reservoir" %}
    return reservoir_select_pdf(nee, in_range, K);
{% elif selection == "weighted" %}
    return weighted_select_pdf(light_weight(li, x, n, r, lobe, rl), bitcast<f32>(nee), in_range, K);
{% elif selection == "all" %}
    return 1.0;
{% elif selection == "uniform" %}
    return 1.0 / f32(arrayLength(&lights));
{% elif selection == "lightbvh" %}
    return light_bvh_pmf(BVH, light_cones[li].bvh_leaf, x, n, r, lobe);
{% else %}
    return power_table[li].z;
{% endif %}
}

/// Solid-angle pdf with which the light strategy for the receiver `(x, n,
/// r, lobe)` produces the point `y` on area light `li` ([`select_pdf`]'s `nee` and
/// `in_range`): the selection probability, the RR probability at |x − y|
/// (1 for the baselines, whose ranges are +∞) and the area pdf converted
/// to solid angle (talk: "Multiple importance sampling"). It must not
/// depend on the light's own ξ (whether this pass's sphere contains `x`):
/// a pdf that is 0 when the sphere misses makes the two weights sum to more
/// than one in expectation and biases the image (the CPU path tracer's
/// test found +40%).
fn light_pdf(li: u32, x: vec3f, n: vec3f, r: vec3f, lobe: vec4f, rl: vec4f, y: vec3f, nee: u32, in_range: bool) -> f32 {
    return light_pdf_selected(li, x, r, rl, y, select_pdf(li, x, n, r, lobe, rl, nee, in_range));
}

/// [`light_pdf`] for a known selection probability `sel`: what the
/// one-light selection's pick already carries (its pmf), so that the light
/// BVH's MIS weight needs no second walk (pbrt-v4's `SampleLd` takes
/// `sampledLight->p`).
fn light_pdf_selected(li: u32, x: vec3f, r: vec3f, rl: vec4f, y: vec3f, sel: f32) -> f32 {
    let l = lights[li];
    let v = x - y;
    let d2 = dot(v, v);
    let cos_y = select(0.0, dot(light_normal(l), v / sqrt(d2)), d2 > 0.0);
    return light_strategy_pdf(sel, light_range_scale(li, x, r, rl) * rt2[li], d2, light_area(l), cos_y);
}
