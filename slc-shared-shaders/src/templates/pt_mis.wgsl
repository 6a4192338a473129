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

/// Solid-angle pdf with which the light strategy at `x` produces the point
/// `y` on area light `li`, when `others` other lights are in range at `x`:
/// the reservoir's selection probability min(k/(others + 1), 1), the RR
/// probability at |x − y| and the area pdf converted to solid angle (talk:
/// "Multiple importance sampling"). It must not depend on the light's own ξ
/// (whether this pass's sphere contains `x`): a pdf that is 0 when the
/// sphere misses makes the two weights sum to more than one in expectation
/// and biases the image (the CPU path tracer's test found +40%).
fn light_pdf(li: u32, x: vec3f, y: vec3f, others: u32) -> f32 {
    let l = lights[li];
    let area = light_area(l);
    let v = x - y;
    let d2 = dot(v, v);
    if area <= 0.0 || d2 <= 0.0 {
        return 0.0;
    }
    let cos_y = dot(light_normal(l), v / sqrt(d2));
    let select_p = 1.0 / reservoir_weight(others + 1u, K);
    return select_p * rr_probability(rt2[li], d2) * area_to_solid_angle_pdf(1.0 / area, d2, cos_y);
}

/// `true` when every component of `v` is finite (NaN compares false).
fn finite3(v: vec3f) -> bool {
    return all(abs(v) <= vec3f(3.4028235e38));
}
