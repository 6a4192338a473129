{% include "header.wgsl" %}
// Per frame (or pass): the random squared range of every light from its ξ,
// light_xi(seed, frame, key) with the light's key in `ids` (a VPL's id; a
// path-tracer light's xi_keys entry), the same numbers the CPU draws (or
// from a fixed ξ every light shares: frame_xi).

{{ bindings }}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let i = gid.x;
    if i >= params.light_count {
        return;
    }
    r2[i] = random_range2(rt2[i], frame_xi(params.seed, params.frame, ids[i], params.fixed_xi));
}
