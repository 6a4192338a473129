{% include "header.wgsl" %}
// Per frame (or pass): the random squared range of every light from its own
// ξ = xi_for(seed, frame, id), the same numbers the CPU draws.

@group(0) @binding(0) var<uniform> params: FrameParams;
@group(0) @binding(1) var<storage, read> ids: array<u32>;
@group(0) @binding(2) var<storage, read> rt2: array<f32>;
@group(0) @binding(3) var<storage, read_write> r2: array<f32>;
@group(1) @binding(0) var<storage, read> slc_table: array<f32>;

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let i = gid.x;
    if i >= params.light_count {
        return;
    }
    r2[i] = random_range2(rt2[i], xi_for(params.seed, params.frame, ids[i]));
}
