{% include "header.wgsl" %}
{% include "lights.wgsl" %}
{% if shadows %}
{% include "geometry.wgsl" %}
{% else %}
/// The unshadowed variant (the caller owns visibility): nothing occludes.
fn occluded(a: vec3f, b: vec3f) -> bool {
    return false;
}
{% endif %}
{% include "bsh_collect.wgsl" %}
// Direct light from many lights at shading points: BSH traversal into a
// {{ k }}-slot reservoir, then shading of the picks with the RR test (at the
// sampled point for area lights), the 1/p and n/k weights and a shadow ray
// ({% if shadows %}through geo_nodes/geo_tris{% else %}none in this variant: the caller owns visibility{% endif %}).
// Output: irradiance (rgb) and the number of in-range lights (w).

{{ bindings }}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let i = gid.x;
    if i >= params.point_count {
        return;
    }
    let p = points[i];
    if p.w <= 0.0 {
        irradiance[i] = vec4f(0.0);
        return;
    }
    let x = p.xyz;
    let n = normals[i].xyz;
    let seed = point_stream(params.seed, i, params.frame);
    let picks = bsh_collect(x, x, vec4f(1.0, 0.0, 1.0, 1.0), seed);
    let w_res = reservoir_weight(picks.n, K);
    var h = pick_stream(seed);
    var e = vec3f(0.0);
    for (var s = 0u; s < min(picks.n, K); s++) {
        h = pcg_hash(h);
        let u1 = xi_from_bits(h);
        h = pcg_hash(h);
        e += connect(picks.light[s], x, n, n, 1.0, w_res, u1, xi_from_bits(h), params.eps).e;
    }
    irradiance[i] = vec4f(e, f32(picks.n));
}
