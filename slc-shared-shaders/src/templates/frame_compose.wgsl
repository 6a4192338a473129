{% include "header.wgsl" %}
// The VPL frame's composition into the HDR target ({{ out_format }}):
// `L_e + ρ/π · (E_direct + E_indirect)` per G-buffer pixel (material from
// the normal's w), zero where no surface; alpha 1.
{% if glossy %}
// Glossy variant: a material with a specular lobe takes
// `L_e + f(v, l) · E_direct + c_diff/π · E_indirect + S` (glossy_radiance),
// `f` the whole BRDF toward the primary light (primary_light_dir), S the
// VPLs' specular correction.
{% endif %}

{{ bindings }}

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= image.width || gid.y >= image.height {
        return;
    }
    let i = gid.y * image.width + gid.x;
    let texel = vec2i(i32(gid.x), i32(gid.y));
    var radiance = vec3f(0.0);
    let p = textureLoad(position_tex, texel, 0);
    if p.w > 0.0 {
        let nm = textureLoad(normal_tex, texel, 0);
        let m = materials[u32(nm.w)];
{% if glossy %}
        let e = textureLoad(indirect_tex, texel, 0).xyz;
        if has_specular(m.metallic, m.f0, m.f90) {
            let l = primary_light_dir(p.xyz, params.origin, params.axis, params.mode == MAP_PERSPECTIVE);
            let f = brdf_eval(m.albedo, m.metallic, m.f0, m.f90, m.alpha, normalize(nm.xyz), normalize(image.eye - p.xyz), l);
            radiance = glossy_radiance(m.albedo, m.emission, m.metallic, f, direct[i].xyz, e, textureLoad(specular_tex, texel, 0).xyz);
        } else {
            radiance = diffuse_radiance(m.albedo, m.emission, direct[i].xyz + e);
        }
{% else %}
        radiance = diffuse_radiance(m.albedo, m.emission, direct[i].xyz + textureLoad(indirect_tex, texel, 0).xyz);
{% endif %}
    }
    textureStore(out_tex, texel, vec4f(radiance, 1.0));
}
