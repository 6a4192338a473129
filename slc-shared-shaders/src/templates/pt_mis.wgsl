// MIS of the path tracer's two strategies ({{ heuristic }} heuristic): the
// light strategy (BSH + {{ k }}-slot reservoir + RR) against cosine BSDF
// sampling. Needs bindings `lights` and `rt2`.

/// MIS weight of strategy `a` against strategy `b`.
fn mis_weight(pdf_a: f32, pdf_b: f32) -> f32 {
{% if heuristic == "power" %}
    return mis_power(pdf_a, pdf_b);
{% else %}
    return mis_balance(pdf_a, pdf_b);
{% endif %}
}

@group(1) @binding(1) var<storage, read> power_table: array<vec4f>;

/// Probability that the light strategy selects light `li` at a point with
/// `others` other lights in range ({{ selection }} selection).
fn select_pdf(li: u32, others: u32) -> f32 {
{% if selection == "reservoir" %}
    return 1.0 / reservoir_weight(others + 1u, K);
{% elif selection == "all" %}
    return 1.0;
{% elif selection == "uniform" %}
    return 1.0 / f32(arrayLength(&lights));
{% else %}
    return power_table[li].z;
{% endif %}
}

/// Solid-angle pdf with which the light strategy at `x` produces the point
/// `y` on area light `li`, when `others` other lights are in range at `x`:
/// the selection probability (the reservoir's min(k/(others + 1), 1), or
/// the baselines' 1/N or pmf), the RR probability at |x − y| (1 for the
/// baselines, whose ranges are +∞) and the area pdf converted to solid
/// angle (talk:
/// "Multiple importance sampling"). It must not depend on the light's own ξ
/// (whether this pass's sphere contains `x`): a pdf that is 0 when the
/// sphere misses makes the two weights sum to more than one in expectation
/// and biases the image (the CPU path tracer's test found +40%).
fn light_pdf(li: u32, x: vec3f, y: vec3f, others: u32) -> f32 {
    let l = lights[li];
    let v = x - y;
    let d2 = dot(v, v);
    let cos_y = select(0.0, dot(light_normal(l), v / sqrt(d2)), d2 > 0.0);
    return light_strategy_pdf(select_pdf(li, others), rt2[li], d2, light_area(l), cos_y);
}

/// `true` when every component of `v` is finite (NaN compares false).
fn finite3(v: vec3f) -> bool {
    return all(abs(v) <= vec3f(3.4028235e38));
}
