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
@group(1) @binding(2) var<storage, read> light_cones: array<GpuLightCone>;
@group(1) @binding(3) var<storage, read> light_bvh: array<GpuLightBvhNode>;

/// `slc-weighted`'s weight of light `li` at `x` with normal `n`
/// (slc-core's `cone_weight`).
fn light_weight(li: u32, x: vec3f, n: vec3f) -> f32 {
    let c = light_cones[li];
    return cone_weight(c.center, c.radius, c.phi, c.axis, c.cos_o, c.cos_e, rt2[li], x, n);
}

/// Importance of light-BVH node `i` at `x` (normal `n`).
fn bvh_importance(i: u32, x: vec3f, n: vec3f) -> f32 {
    let b = light_bvh[i];
    return light_importance(b.center, b.radius, b.phi, b.axis, b.cos_o, b.cos_e, x, n);
}

/// First-child probability at interior light-BVH node `i`, or −1 where
/// the walk ends (slc-core's `bvh_first_prob`; a malformed link ends it).
fn bvh_first(i: u32, x: vec3f, n: vec3f) -> f32 {
    let j = light_bvh[i].second;
    if j <= i + 1u || j >= arrayLength(&light_bvh) {
        return -1.0;
    }
    return bvh_first_prob(bvh_importance(i + 1u, x, n), bvh_importance(j, x, n));
}

/// A light drawn from the light BVH and its pmf (0: none).
struct BvhPick {
    light: u32,
    pmf: f32,
}

/// Walks the light BVH from the root for `x` (normal `n`) with uniform
/// `u`, choosing each child by its importance (slc-core's
/// `light_bvh_sample`).
fn light_bvh_sample(x: vec3f, n: vec3f, u_in: f32) -> BvhPick {
    var u = u_in;
    var i = 0u;
    var pmf = 1.0;
    loop {
        let node = light_bvh[i];
        if node.second == LIGHT_BVH_LEAF {
            let reaches = i > 0u || bvh_importance(0u, x, n) > 0.0;
            return BvhPick(node.light, select(0.0, pmf, reaches));
        }
        let p0 = bvh_first(i, x, n);
        if p0 < 0.0 {
            return BvhPick(0u, 0.0);
        }
        let first = u < p0;
        pmf *= select(1.0 - p0, p0, first);
        u = bvh_remap_u(u, p0, first);
        i = select(node.second, i + 1u, first);
    }
    return BvhPick(0u, 0.0);
}

/// Probability that `light_bvh_sample` at `x` (normal `n`) picks light
/// `li`: the same walk towards its leaf (slc-core's `light_bvh_pmf`).
fn light_bvh_pmf(li: u32, x: vec3f, n: vec3f) -> f32 {
    let leaf = light_cones[li].bvh_leaf;
    if leaf >= arrayLength(&light_bvh) {
        return 0.0;
    }
    var i = 0u;
    var pmf = 1.0;
    loop {
        let node = light_bvh[i];
        if node.second == LIGHT_BVH_LEAF {
            let reaches = i > 0u || bvh_importance(0u, x, n) > 0.0;
            return select(0.0, pmf, i == leaf && reaches);
        }
        let p0 = bvh_first(i, x, n);
        if p0 < 0.0 {
            return 0.0;
        }
        let first = leaf < node.second;
        pmf *= select(1.0 - p0, p0, first);
        i = select(node.second, i + 1u, first);
    }
    return 0.0;
}

/// Probability (expected count, for the weighted picks) that the light
/// strategy at `x` (normal `n`) selects light `li` ({{ selection }}
/// selection). `nee` is what the traversal at `x` left: the in-range count
/// (reservoir) or the bits of the candidates' total weight (weighted);
/// `in_range` says this pass's range of `li` reaches `x`, so that the
/// probability is the one of the *other* candidates, independent of the
/// light's own ξ.
fn select_pdf(li: u32, x: vec3f, n: vec3f, nee: u32, in_range: bool) -> f32 {
{% if selection == "reservoir" %}
    return reservoir_select_pdf(nee, in_range, K);
{% elif selection == "weighted" %}
    return weighted_select_pdf(light_weight(li, x, n), bitcast<f32>(nee), in_range, K);
{% elif selection == "all" %}
    return 1.0;
{% elif selection == "uniform" %}
    return 1.0 / f32(arrayLength(&lights));
{% elif selection == "lightbvh" %}
    return light_bvh_pmf(li, x, n);
{% else %}
    return power_table[li].z;
{% endif %}
}

/// Solid-angle pdf with which the light strategy at `x` (normal `n`)
/// produces the point `y` on area light `li` ([`select_pdf`]'s `nee` and
/// `in_range`): the selection probability, the RR probability at |x − y|
/// (1 for the baselines, whose ranges are +∞) and the area pdf converted
/// to solid angle (talk: "Multiple importance sampling"). It must not
/// depend on the light's own ξ (whether this pass's sphere contains `x`):
/// a pdf that is 0 when the sphere misses makes the two weights sum to more
/// than one in expectation and biases the image (the CPU path tracer's
/// test found +40%).
fn light_pdf(li: u32, x: vec3f, n: vec3f, y: vec3f, nee: u32, in_range: bool) -> f32 {
    let l = lights[li];
    let v = x - y;
    let d2 = dot(v, v);
    let cos_y = select(0.0, dot(light_normal(l), v / sqrt(d2)), d2 > 0.0);
    return light_strategy_pdf(select_pdf(li, x, n, nee, in_range), rt2[li], d2, light_area(l), cos_y);
}
