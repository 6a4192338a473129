{% include "header.wgsl" %}
{% include "lights.wgsl" %}
// The primary light's direct irradiance at every G-buffer pixel, shadowed
// by its shadow map (`fs_shadow`: per texel the distance along the light's
// ray to the first surface, 0 where none): the receiver is lit when that
// surface lies no nearer to the light (less the slope-scaled bias).

{{ bindings }}

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= image.width || gid.y >= image.height {
        return;
    }
    let i = gid.y * image.width + gid.x;
    let texel = vec2i(i32(gid.x), i32(gid.y));
    let p = textureLoad(position_tex, texel, 0);
    let nn = textureLoad(normal_tex, texel, 0).xyz;
    if !(p.w > 0.0) || dot(nn, nn) <= 0.0 {
        direct[i] = vec4f(0.0);
        return;
    }
    let x = p.xyz;
    let n = normalize(nn);
    let size = f32(params.size);
    var e = vec3f(0.0);
    var a = 0.0;
    var b = 0.0;
    // Depth along the map's ray (what the shadow map holds), the texel's
    // width there, the light's cosine.
    let rel = x - params.origin;
    let d = light_map_depth(rel, params.axis, params.mode == MAP_PERSPECTIVE);
    var width = 0.0;
    var cos_light = 0.0;
    if params.mode == MAP_PERSPECTIVE {
        let v = -rel;
        let z = dot(rel, params.axis);
        if z <= 0.0 || d <= 0.0 {
            direct[i] = vec4f(0.0);
            return;
        }
        a = light_map_coord_at(rel, params.right, params.axis, params.extent, true);
        b = light_map_coord_at(rel, params.up, params.axis, params.extent, true);
        width = perspective_texel_width(params.extent, d, z, size);
        cos_light = dot(n, v) / d;
        e = point_irradiance(light_intensity(params.light, rel / d), n, v);
    } else {
        a = light_map_coord_at(rel, params.right, params.axis, params.extent, false);
        b = light_map_coord_at(rel, params.up, params.axis, params.extent, false);
        width = ortho_texel_width(params.extent, size);
        cos_light = -dot(n, params.axis);
        e = directional_irradiance(params.light.intensity, n, -params.axis);
    }
    if abs(a) <= 1.0 && abs(b) <= 1.0 {
        let d_map = textureLoad(shadow_map, vec2i(i32(light_map_texel(a, params.size)), i32(light_map_texel(b, params.size))), 0).x;
        if !shadow_lit(d, d_map, shadow_bias(width, cos_light)) {
            e = vec3f(0.0);
        }
    }
    direct[i] = vec4f(e, 0.0);
}
