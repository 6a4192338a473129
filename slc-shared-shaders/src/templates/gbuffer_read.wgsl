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
    return unproject_pixel(view.c0, view.c1, view.c2, view.c3, f32(texel.x), f32(texel.y), f32(view.width), f32(view.height), d, view.background);
{% endif %}
}
