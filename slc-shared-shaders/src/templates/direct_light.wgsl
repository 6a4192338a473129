{% include "header.wgsl" %}
{% include "lights.wgsl" %}
/// Unshadowed: the engine owns visibility.
fn occluded(a: vec3f, b: vec3f) -> bool {
    return false;
}
{{ bindings }}
{% include "bsh_collect.wgsl" %}
{% if selection == "weighted" %}
{% include "bsh_weighted.wgsl" %}
{% endif %}
{% include "gbuffer_read.wgsl" %}
// The engine's direct pass: at every G-buffer pixel, the lights whose random
// range reaches it (BSH traversal), {% if selection == "weighted" %}{{ k }} importance-weighted picks among them{% elif selection == "all" %}every one of them (exact given ξ){% else %}{{ k }} uniform picks among them (Algorithm R){% endif %},
// each sampled (a point on a triangle), RR-tested at that point with its own
// range and weighted by 1/p and its selection weight. Output: irradiance
// (rgb) and the number of in-range lights (a); zero where no surface is.

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= view.width || gid.y >= view.height {
        return;
    }
    let texel = vec2i(i32(gid.x), i32(gid.y));
    let s = surface_at(texel);
    let nn = textureLoad(normal_tex, texel, 0).xyz;
    let len2 = dot(nn, nn);
    if s.w <= 0.0 || !(len2 > 0.0) {
        textureStore(out_tex, texel, vec4f(0.0));
        return;
    }
    let x = s.xyz;
    let n = nn / sqrt(len2);
    let seed = point_stream(view.seed, gid.y * view.width + gid.x, view.frame);
    var h = pick_stream(seed);
    var e = vec3f(0.0);
{% if selection == "weighted" %}
    let picks = bsh_weighted_collect(x, n, seed);
    if picks.w_sum > 0.0 {
        for (var k = 0u; k < K; k++) {
            h = pcg_hash(h);
            let u1 = xi_from_bits(h);
            h = pcg_hash(h);
            e += connect(picks.light[k], x, n, n, weighted_pick_weight(picks.w_sum, picks.w[k], K), u1, xi_from_bits(h), 0.0).e;
        }
    }
    let count = picks.n;
{% elif selection == "all" %}
    var count = 0u;
    for (var b = bsh_next_leaf(BSH, bsh_first(BSH), x); b != BSH_NONE; b = bsh_next_leaf(BSH, bsh_nodes[b].next, x)) {
        count += 1u;
        h = pcg_hash(h);
        let u1 = xi_from_bits(h);
        h = pcg_hash(h);
        e += connect(bsh_nodes[b].light, x, n, n, 1.0, u1, xi_from_bits(h), 0.0).e;
    }
{% else %}
    let picks = bsh_collect(x, seed);
    let w_res = reservoir_weight(picks.n, K);
    for (var k = 0u; k < min(picks.n, K); k++) {
        h = pcg_hash(h);
        let u1 = xi_from_bits(h);
        h = pcg_hash(h);
        e += connect(picks.light[k], x, n, n, w_res, u1, xi_from_bits(h), 0.0).e;
    }
    let count = picks.n;
{% endif %}
    textureStore(out_tex, texel, vec4f(e, f32(count)));
}
