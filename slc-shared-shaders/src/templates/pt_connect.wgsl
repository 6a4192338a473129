{% if ray_query %}
enable wgpu_ray_query;
{% endif %}
{% include "header.wgsl" %}
{% include "lights.wgsl" %}
{% include "geometry.wgsl" %}
{% include "bsh_collect.wgsl" %}
{% include "pt_mis.wgsl" %}
{% if selection == "weighted" %}
{% include "bsh_weighted.wgsl" %}
{% endif %}
// Explicit light connection of a progressive path tracer: at every live path
// vertex, the BSH and a {{ k }}-slot reservoir pick lights ({{ selection }}
// selection; the uniform and power baselines pick one light); each pick is
// sampled, passes the RR test at the sampled point, casts a shadow ray, is
// shaded with the vertex's BRDF (slc-core's glTF metallic-roughness) and is
// weighted by MIS ({{ heuristic }} heuristic) against BSDF sampling.
// The light strategy's pdf includes the RR probability and the reservoir's
// selection probability (talk: "Multiple importance sampling").

{{ bindings }}

/// One pick connected to the vertex `x` (material `m` seen from `wo`,
/// mirror direction `r`, lobe `lobe`): its contribution through the BRDF
/// times the MIS weight (area lights) against BSDF sampling; `w` is the
/// selection weight (the reservoir's n/k, the weighted picks' W/(k·w), or
/// 1/pmf), `nee` what the traversal found (`select_pdf`; the pick is in
/// range).
fn shade_pick(li: u32, x: vec3f, n: vec3f, ng: vec3f, m: GpuMaterial, wo: vec3f, r: vec3f, lobe: vec4f, rl: vec4f, w: f32, nee: u32, u1: f32, u2: f32) -> vec3f {
    let c = connect(li, x, n, ng, light_range_scale(li, x, r, rl), w, u1, u2, params.eps);
    if c.cos_x <= 0.0 {
        return vec3f(0.0);
    }
    let l = normalize(c.y - x);
    var mis = 1.0;
    if light_area(lights[li]) > 0.0 {
{% if selection == "lightbvh" %}
        // The pick's pmf is 1/w: no second walk of the tree.
        let pdf_light = light_pdf_selected(li, x, r, rl, c.y, 1.0 / w);
{% else %}
        let pdf_light = light_pdf(li, x, n, r, lobe, rl, c.y, nee, true);
{% endif %}
        mis = mis_weight(pdf_light, bsdf_pdf(n, wo, l, m.alpha, specular_probability(lobe)));
    }
    return brdf_eval(m.albedo, m.metallic, m.f0, m.f90, m.alpha, n, wo, l) * c.e * mis;
}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let i = gid.x;
    if i >= params.point_count {
        return;
    }
    let vtx = vertices[i];
    if vtx.alive == 0u {
        candidates[i] = 0u;
        return;
    }
    let x = vtx.position;
    let n = vtx.normal;
    let ng = vtx.gnormal;
    let m = materials[vtx.material];
    let wo = vtx.wo;
    let r = mirror_dir(n, wo);
    let lobe = receiver_lobe(m.albedo, m.metallic, m.f0, m.f90, m.alpha, dot(n, wo));
    // What scales each light's range: a glossy lobe reaches farther lights
    // near its mirror direction.
    let rl = range_lobe(lobe);
    let seed = point_stream(params.seed, i, params.frame);
    var h = pick_stream(seed);
    var sum = vec3f(0.0);
{% if selection == "reservoir" %}
    let picks = bsh_collect(x, r, rl, seed);
    candidates[i] = picks.n;
    let w_res = reservoir_weight(picks.n, K);
    for (var s = 0u; s < min(picks.n, K); s++) {
        h = pcg_hash(h);
        let u1 = xi_from_bits(h);
        h = pcg_hash(h);
        sum += shade_pick(picks.light[s], x, n, ng, m, wo, r, lobe, rl, w_res, picks.n, u1, xi_from_bits(h));
    }
{% elif selection == "weighted" %}
    // K independent one-slot weighted reservoirs over the in-range lights.
    let picks = bsh_weighted_collect(x, n, r, lobe, rl, h);
    h = picks.h;
    let w_sum = picks.w_sum;
    candidates[i] = bitcast<u32>(w_sum);
    if w_sum > 0.0 {
        for (var s = 0u; s < K; s++) {
            h = pcg_hash(h);
            let u1 = xi_from_bits(h);
            h = pcg_hash(h);
            sum += shade_pick(picks.light[s], x, n, ng, m, wo, r, lobe, rl, weighted_pick_weight(w_sum, picks.w[s], K), bitcast<u32>(w_sum), u1, xi_from_bits(h));
        }
    }
{% elif selection == "all" %}
    // Every in-range light, each connected as the traversal finds it.
    var count = 0u;
    var cur = bsh_cursor(x, r, rl);
    for (var b = bsh_cursor_next(&cur, x, r, rl); b != BSH_NONE; b = bsh_cursor_next(&cur, x, r, rl)) {
        count += 1u;
        h = pcg_hash(h);
        let u1 = xi_from_bits(h);
        h = pcg_hash(h);
        sum += shade_pick(bsh_nodes[b].light, x, n, ng, m, wo, r, lobe, rl, 1.0, 0u, u1, xi_from_bits(h));
    }
    candidates[i] = count;
{% else %}
    // One light, {{ selection }}; its range is +∞ (p = 1).
    candidates[i] = 0u;
    h = pcg_hash(h);
    let us = xi_from_bits(h);
{% if selection == "lightbvh" %}
    let bp = light_bvh_sample(BVH, x, n, r, lobe, us);
    let li = bp.light;
    let pmf = bp.pmf;
{% else %}
    let nl = arrayLength(&lights);
    var li = uniform_light(us, nl);
{% if selection == "power" %}
    h = pcg_hash(h);
    let entry = power_table[li];
    li = alias_choice(li, bitcast<u32>(entry.y), entry.x, xi_from_bits(h));
{% endif %}
    let pmf = select_pdf(li, x, n, r, lobe, rl, 0u, true);
{% endif %}
    h = pcg_hash(h);
    let u1 = xi_from_bits(h);
    h = pcg_hash(h);
    let u2 = xi_from_bits(h);
    if pmf > 0.0 {
        sum = shade_pick(li, x, n, ng, m, wo, r, lobe, rl, 1.0 / pmf, 0u, u1, u2);
    }
{% endif %}
    let add = vtx.weight * sum;
    if finite3(add) {
        radiance[i] += vec4f(add, 0.0);
    }
}
