{% include "header.wgsl" %}
{% include "lights.wgsl" %}
{% include "geometry.wgsl" %}
const K: u32 = {{ k }}u;
{% include "pt_mis.wgsl" %}
// One bounce of the wavefront path tracer, per pixel: at depth 0 a jittered
// camera ray, later the ray `pt_extend` sampled at the previous vertex. The
// closest hit adds emission (MIS-weighted against the light strategy, whose
// pdf at the previous vertex uses the in-range count `pt_connect` left in
// `candidates`), writes the vertex for `pt_connect`, samples the BSDF
// (slc-core's glTF metallic-roughness: cosine or bounded-VNDF GGX lobe) for
// the next ray and plays Russian roulette on path length from the third
// bounce, as the CPU path tracer does.

{{ bindings }}
{% include "bsh_walk.wgsl" %}

/// Next uniform in [0, 1) of a path's random state.
fn next_uniform(state: ptr<function, u32>) -> f32 {
    *state = pcg_hash(*state);
    return xi_from_bits(*state);
}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let i = gid.x;
    if i >= params.width * params.height {
        return;
    }
    var st: GpuPathState;
    if params.depth == 0u {
        var h = path_stream(params.seed, i, params.pass_index);
        let px = jittered_pixel(i % params.width, next_uniform(&h));
        let py = jittered_pixel(i / params.width, next_uniform(&h));
        st.origin = params.cam_pos;
        st.dir = camera_dir(params.cam_forward, params.cam_right, params.cam_up, px, py, f32(params.width), f32(params.height));
        st.alive = 1u;
        st.rng = h;
        st.beta = vec3f(1.0);
        st.pdf_bsdf = 0.0;
        st.prev = params.cam_pos;
    } else {
        st = paths[i];
    }
    var v: GpuPathVertex;
    v.alive = 0u;
    if st.alive == 0u {
        vertices[i] = v;
        return;
    }
    let hit = trace(st.origin, st.dir, params.t_min, F32_MAX, false);
    if hit.tri == NO_LIGHT {
        st.alive = 0u;
        paths[i] = st;
        vertices[i] = v;
        return;
    }
    let tri = geo_tris[hit.tri];
    let x = st.origin + st.dir * hit.t;
    let gn = triangle_normal(tri.v0, tri.v1, tri.v2);
    let ng = face_against(gn, st.dir);
    let b = hit.tri * 3u;
    let n = shading_normal(geo_normals[b].xyz, geo_normals[b + 1u].xyz, geo_normals[b + 2u].xyz, barycentric(x, tri.v0, tri.v1, tri.v2), ng);
    // Emission, one-sided like the light, seen directly or by BSDF sampling.
    if tri.light != NO_LIGHT && sees_emission(gn, st.dir) {
        var w = 1.0;
        if st.pdf_bsdf > 0.0 {
            let leaf = bsh_range_leaf(BSH, light_leaf[tri.light]);
            let rl = range_lobe(st.prev_lobe);
            let in_range = bsh_reaches(leaf, st.prev, st.prev_r, rl);
            w = mis_weight(st.pdf_bsdf, light_pdf(tri.light, st.prev, st.prev_normal, st.prev_r, st.prev_lobe, rl, x, candidates[i], in_range));
        }
        let add = st.beta * lights[tri.light].intensity * w;
        if finite3(add) {
            radiance[i] += vec4f(add, 0.0);
        }
    }
    // Past the last vertex: only the emission found by its BSDF sample,
    // the other share of the last vertex's MIS (no vertex, no NEE).
    if params.depth >= params.max_depth {
        st.alive = 0u;
        paths[i] = st;
        vertices[i] = v;
        return;
    }
    let m = materials[tri.material];
    let wo = -st.dir;
    let lobe = receiver_lobe(m.albedo, m.metallic, m.f0, m.f90, m.alpha, dot(n, wo));
    v.position = x;
    v.normal = n;
    v.material = tri.material;
    v.gnormal = ng;
    v.weight = st.beta;
    v.wo = wo;
    v.alive = 1u;
    vertices[i] = v;
    // A BSDF sample about the shading normal (cosine, or the GGX lobe's
    // visible normals); f·cos/pdf is exactly ρ for a Lambertian surface.
    var rng = st.rng;
    let u1 = next_uniform(&rng);
    let u2 = next_uniform(&rng);
    let p_spec = specular_probability(lobe);
    let nd = bsdf_sample(n, wo, m.alpha, p_spec, u1, u2);
    let pdf = bsdf_pdf(n, wo, nd, m.alpha, p_spec);
    if has_specular(m.metallic, m.f0, m.f90) {
        st.beta *= brdf_eval(m.albedo, m.metallic, m.f0, m.f90, m.alpha, n, wo, nd) * (dot(nd, n) / pdf);
    } else {
        st.beta *= m.albedo;
    }
    st.prev = x;
    st.prev_normal = n;
    st.prev_r = mirror_dir(n, wo);
    st.prev_lobe = lobe;
    st.pdf_bsdf = pdf;
    st.origin = x + ng * params.eps;
    st.dir = nd;
    // A direction below the surface itself ends the path.
    if !continues_path(nd, n, ng) || !(pdf > 0.0) {
        st.alive = 0u;
    }
    // Russian roulette on path length from the third bounce.
    if plays_roulette(params.depth) && st.alive == 1u {
        let q = path_survival(st.beta);
        if next_uniform(&rng) >= q {
            st.alive = 0u;
        } else {
            st.beta /= q;
        }
    }
    st.rng = rng;
    paths[i] = st;
}
