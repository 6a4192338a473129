// Glossy receivers of the VPL kernels: a pixel's glTF material from the
// material table (its index in the normal texture's w) and its view
// direction; at a pixel whose material has a specular lobe, every kept VPL
// adds its term of the specular correction S (slc-core's
// specular_correction, f - c_diff/pi) with the transfer and share its
// irradiance takes.

struct Glossy {
    m: GpuMaterial,
    // Unit direction toward the eye.
    v: vec3f,
    // The material has a specular lobe (else S stays 0).
    on: bool,
}

fn glossy_at(i: u32, x: vec3f) -> Glossy {
    let texel = vec2i(i32(i % view.width), i32(i / view.width));
    let m = materials[u32(textureLoad(normal_tex, texel, 0).w)];
    return Glossy(m, normalize(view.eye - x), has_specular(m.metallic, m.f0, m.f90));
}

// S's term of light l at offset v (receiver - light) for a receiver with
// normal n taking the light's transfer t (already weighted by its share,
// as the irradiance takes it): flux * (f - c_diff/pi) * t; 0 without a
// lobe or a transfer.
fn glossy_term(g: Glossy, l: GpuLight, n: vec3f, v: vec3f, t: f32) -> vec3f {
    if !g.on || t <= 0.0 {
        return vec3f(0.0);
    }
    return l.intensity * specular_correction(g.m.albedo, g.m.metallic, g.m.f0, g.m.f90, g.m.alpha, n, g.v, normalize(-v)) * t;
}
