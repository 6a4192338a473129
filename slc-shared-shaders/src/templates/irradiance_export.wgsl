{% include "header.wgsl" %}
// The indirect irradiance (rgb, lights kept in w) into an engine's storage
// texture ({{ out_format }}); zero where the G-buffer has no surface.
{% if glossy %}
// Glossy variant: the specular correction S (rgb) into `specular_tex` too.
{% endif %}

{{ bindings }}
{% include "gbuffer_read.wgsl" %}

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= view.width || gid.y >= view.height {
        return;
    }
    let i = gid.y * view.width + gid.x;
    let valid = gbuffer_at(i).position.w > 0.0;
    let e = select(vec4f(0.0), irradiance[i], valid);
    textureStore(out_tex, vec2i(i32(gid.x), i32(gid.y)), e);
{% if glossy %}
    let s = select(vec4f(0.0), specular[i], valid);
    textureStore(specular_tex, vec2i(i32(gid.x), i32(gid.y)), vec4f(s.xyz, 0.0));
{% endif %}
}
