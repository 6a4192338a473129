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

@group(0) @binding(0) var<uniform> params: ShadeParams;
@group(0) @binding(1) var<storage, read> points: array<vec4f>;
@group(0) @binding(2) var<storage, read> normals: array<vec4f>;
@group(0) @binding(3) var<storage, read> lights: array<GpuLight>;
@group(0) @binding(4) var<storage, read> rt2: array<f32>;
@group(0) @binding(5) var<storage, read> r2: array<f32>;
@group(0) @binding(6) var<storage, read> bsh_nodes: array<BshNode>;
{% if shadows %}
@group(0) @binding(7) var<storage, read> geo_nodes: array<GpuGeoNode>;
@group(0) @binding(8) var<storage, read> geo_tris: array<GpuTriangle>;
{% endif %}
@group(0) @binding(9) var<storage, read_write> irradiance: array<vec4f>;
@group(1) @binding(0) var<storage, read> slc_table: array<f32>;

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
    let picks = bsh_collect(x, 1.0, seed);
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
