{% include "header.wgsl" %}
// Per frame (or pass): the random squared range of every light from its own
// ξ = xi_for(seed, frame, id), the same numbers the CPU draws (or from a
// fixed ξ every light shares: frame_xi).

{{ bindings }}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let i = gid.x;
    if i >= params.light_count {
        return;
    }
    r2[i] = random_range2(rt2[i], frame_xi(params.seed, params.frame, ids[i], params.fixed_xi));
}
