// The engine's G-buffer as the engine passes read it: the surface from
// {% if surface == "position" %}a world-position texture{% else %}a depth texture and the view's inverse view-projection{% endif %}, and its normal.
{{ engine }}

/// The surface at `texel`: world position (xyz) and 1, or 0 where there is none.
fn surface_at(texel: vec2i) -> vec4f {
{% if surface == "position" %}
    let p = textureLoad(position_tex, texel, 0);
    return select(vec4f(0.0), vec4f(p.xyz, 1.0), p.w > 0.0);
{% else %}
    let d = textureLoad(depth_tex, texel, 0){% if surface == "r32" %}.x{% endif %};
    return unproject_pixel(view.c0, view.c1, view.c2, view.c3, f32(texel.x), f32(texel.y), f32(view.width), f32(view.height), d);
{% endif %}
}

/// Pixel `i` (row-major) of the G-buffer as the VPL kernels read it, in
/// place: world position and w = 1 where a surface with a normal is (else
/// 0); unit normal and, in w, the distance from the eye (the denoise's
/// depth; DEPTH_NONE where there is no surface).
struct GbTexel {
    position: vec4f,
    normal: vec4f,
}

fn gbuffer_at(i: u32) -> GbTexel {
    let texel = vec2i(i32(i % view.width), i32(i / view.width));
    let p = surface_at(texel);
    let n = textureLoad(normal_tex, texel, 0).xyz;
    let len2 = dot(n, n);
    let valid = p.w > 0.0 && len2 > 0.0;
    let v = p.xyz - view.eye;
    let position = vec4f(p.xyz, select(0.0, 1.0, valid));
    let normal = select(vec4f(0.0, 0.0, 0.0, DEPTH_NONE), vec4f(n / sqrt(len2), sqrt(dot(v, v))), valid);
    return GbTexel(position, normal);
}
