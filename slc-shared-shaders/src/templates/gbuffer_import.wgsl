{% include "header.wgsl" %}
// An engine's G-buffer textures into the buffers vpl_tiled and vpl_denoise
// read: position (xyz, w > 0 where a surface is) and unit normal facing the
// camera; depth is the distance from the eye. Clears the irradiance of every
// pixel, since vpl_tiled writes only pixels that see a surface.

{{ bindings }}
{% include "gbuffer_read.wgsl" %}

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= view.width || gid.y >= view.height {
        return;
    }
    let i = gid.y * view.width + gid.x;
    let texel = vec2i(i32(gid.x), i32(gid.y));
    let p = surface_at(texel);
    let n = textureLoad(normal_tex, texel, 0).xyz;
    let len2 = dot(n, n);
    let valid = p.w > 0.0 && len2 > 0.0;
    let v = p.xyz - view.eye;
    gb_position[i] = vec4f(p.xyz, select(0.0, 1.0, valid));
    gb_normal[i] = select(vec4f(0.0, 0.0, 0.0, DEPTH_NONE), vec4f(n / sqrt(len2), sqrt(dot(v, v))), valid);
    irradiance[i] = vec4f(0.0);
}
