{% include "header.wgsl" %}
{% include "lights.wgsl" %}
{% if shadows %}
{% include "geometry.wgsl" %}
{% else %}
/// Unshadowed: the engine owns visibility.
fn occluded(a: vec3f, b: vec3f) -> bool {
    return false;
}
{% endif %}
{{ bindings }}
{% include "bsh_collect.wgsl" %}
{% if selection == "weighted" or pbr != "none" %}
{% include "light_weight.wgsl" %}
{% endif %}
{% if selection == "weighted" %}
{% include "bsh_weighted.wgsl" %}
{% endif %}
{% include "gbuffer_read.wgsl" %}
// The engine's direct pass: at every G-buffer pixel, the lights whose random
// range reaches it (BSH traversal), {% if selection == "weighted" %}{{ k }} importance-weighted picks among them{% elif selection == "resampled" %}{{ k }} picks resampled from them in proportion to their unshadowed contributions{% elif selection == "all" %}every one of them (exact given ξ){% else %}{{ k }} uniform picks among them (Algorithm R){% endif %},
// each sampled (a point on a triangle), RR-tested at that point with its own
// range, {% if shadows %}shadowed by one ray through the occluders' BVH (leaving the surface
// `view.shadow_offset` × the eye distance along the normal), {% endif %}and weighted by 1/p and its selection weight. Output: {% if pbr == "radiance" %}outgoing radiance
// under the G-buffer's glTF metallic-roughness material{% elif pbr == "bevy" %}outgoing radiance under
// Bevy StandardMaterial's BRDF of the G-buffer's material{% elif pbr == "split" %}irradiance, and the
// specular radiance of the G-buffer's material in specular_tex{% else %}irradiance{% endif %} (rgb) and the number of
// in-range lights (a); zero where no surface is.

/// What the picks add at a pixel: irradiance{% if pbr != "none" %}, and the material's diffuse and specular radiance{% endif %}.
struct Shaded {
    e: vec3f,
    diffuse: vec3f,
    specular: vec3f,
}

/// The surface's material (glTF metallic-roughness, or Bevy's with its
/// perceptual roughness and reflectance) and view.
struct Material {
    base: vec3f,
    metallic: f32,
    alpha: f32,
    v: vec3f,
    roughness: f32,
    reflectance: f32,
}

/// One pick of light `li` at `x` (normal `n`, mirror direction `r`) with
/// selection weight `w`, its ranges² scaled by the receiver's `s` toward it
/// (range lobe `rl`; slc-core's `range_scale_toward`; 1 for irradiance);
/// its shadow ray leaves from `x + eps·n`.
fn shade_pick(li: u32, x: vec3f, n: vec3f, r: vec3f, rl: vec4f, m: Material, w: f32, u1: f32, u2: f32, eps: f32) -> Shaded {
    return shade_pick_traced(li, x, n, r, rl, m, w, u1, u2, eps, true);
}

/// [`shade_pick`], shadowed only where `trace` says.
fn shade_pick_traced(li: u32, x: vec3f, n: vec3f, r: vec3f, rl: vec4f, m: Material, w: f32, u1: f32, u2: f32, eps: f32, trace: bool) -> Shaded {
    var s: Shaded;
{% if pbr != "none" %}
    let s2 = light_range_scale(li, x, r, rl);
{% else %}
    let s2 = 1.0;
{% endif %}
    let c = connect_traced(li, x, n, n, s2, w, u1, u2, eps, trace);
    s.e = c.e;
    s.diffuse = vec3f(0.0);
    s.specular = vec3f(0.0);
{% if pbr == "bevy" %}
    if c.cos_x > 0.0 {
        s.diffuse = bevy_brdf(m.base, m.metallic, m.roughness, m.reflectance, n, m.v, normalize(c.y - x)) * c.e;
    }
{% elif pbr != "none" %}
    if c.cos_x > 0.0 {
        let l = normalize(c.y - x);
        s.diffuse = diffuse_brdf(m.base, m.metallic, view.f0_d, view.f90_d, half_cosine(m.v, l)) * c.e;
        s.specular = specular_brdf(m.base, m.metallic, view.f0_d, view.f90_d, m.alpha, n, m.v, l) * c.e;
    }
{% endif %}
    return s;
}

fn add(a: Shaded, b: Shaded) -> Shaded {
    return Shaded(a.e + b.e, a.diffuse + b.diffuse, a.specular + b.specular);
}

/// How many of the picks `lights` hold light `lights[k]` when `k` is the
/// first of them, else 0: a pick held `m` times is shaded once, weighted
/// `m` times (one shadow ray instead of `m`).
fn pick_copies(lights: array<u32, K>, k: u32) -> u32 {
    var copies = 1u;
    for (var j = 0u; j < K; j++) {
        if j != k && lights[j] == lights[k] {
            if j < k {
                return 0u;
            }
            copies += 1u;
        }
    }
    return copies;
}

/// What a pick adds to the output: the irradiance{% if pbr == "radiance" or pbr == "bevy" %}, here the outgoing radiance{% elif pbr == "split" %} (the output) and the specular radiance{% endif %}.
fn output_of(s: Shaded) -> vec3f {
{% if pbr == "radiance" or pbr == "bevy" %}
    return s.diffuse + s.specular;
{% elif pbr == "split" %}
    return s.e + s.specular;
{% else %}
    return s.e;
{% endif %}
}

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= view.width || gid.y >= view.height {
        return;
    }
    let texel = vec2i(i32(gid.x), i32(gid.y));
    let s = surface_at(texel);
    let nn = textureLoad(normal_tex, texel, 0).xyz;
    let len2 = dot(nn, nn);
    if s.w <= 0.0 || !(len2 > 0.0) {
        textureStore(out_tex, texel, vec4f(0.0));
{% if pbr == "split" %}
        textureStore(specular_tex, texel, vec4f(0.0));
{% endif %}
        return;
    }
    let x = s.xyz;
    let n = nn / sqrt(len2);
    var m: Material;
    // The receiver as light selection sees it: Lambertian for irradiance;
    // with a material, its lobe, mirror direction and range scale s (a
    // glossy lobe reaches farther lights near its mirror direction;
    // slc-core's `range_lobe`).
    var lobe = vec4f(1.0, 0.0, 1.0, 1.0);
    var r = n;
{% if pbr != "none" %}
    let mr = textureLoad(metal_rough_tex, texel, 0);
{% if pbr == "bevy" %}
    // Selection sees Bevy's material through the glTF lobe of the same F0
    // (any importance keeps the estimate unbiased).
    let f0_d = bevy_f0(mr.w);
    m = Material(textureLoad(base_color_tex, texel, 0).xyz, saturate(mr.z), bevy_alpha(mr.y), normalize(view.eye - x), mr.y, mr.w);
    lobe = receiver_lobe(m.base, m.metallic, vec3f(f0_d), 1.0, m.alpha, dot(n, m.v));
{% else %}
    m = Material(textureLoad(base_color_tex, texel, 0).xyz, saturate(mr.z), ggx_alpha(saturate(mr.y)), normalize(view.eye - x), mr.y, 0.0);
    lobe = receiver_lobe(m.base, m.metallic, view.f0_d, view.f90_d, m.alpha, dot(n, m.v));
{% endif %}
    r = mirror_dir(n, m.v);
{% endif %}
    let rl = range_lobe(lobe);
    let eps = view.shadow_offset * length(view.eye - x);
    let seed = point_stream(view.seed, gid.y * view.width + gid.x, view.frame);
    var h = pick_stream(seed);
    var t = Shaded(vec3f(0.0), vec3f(0.0), vec3f(0.0));
{% if selection == "weighted" %}
    let picks = bsh_weighted_collect(x, n, r, lobe, rl, seed);
    if picks.w_sum > 0.0 {
        for (var k = 0u; k < K; k++) {
            h = pcg_hash(h);
            let u1 = xi_from_bits(h);
            h = pcg_hash(h);
            let u2 = xi_from_bits(h);
            let li = picks.light[k];
            // The picks are independent, so a light may be picked more than
            // once. A light without area (point, spot, IES, VPL) has no point
            // to sample: its `copies` picks are one ray and one term, shaded once
            // at its first pick with `copies` times a pick's weight (the same
            // sum, `copies − 1` fewer shadow rays). A triangle's picks each
            // sample a point of their own.
            let copies = select(1u, pick_copies(picks.light, k), lights[li].kind != LIGHT_TRIANGLE);
            if copies > 0u {
                t = add(t, shade_pick(li, x, n, r, rl, m, weighted_pick_weight(picks.w_sum, picks.w[k], K) * f32(copies), u1, u2, eps));
            }
        }
    }
    let count = picks.n;
{% elif selection == "resampled" %}
    // Resampled importance sampling over every light in range: each is
    // sampled (its point from the pick stream) and evaluated without a
    // shadow ray, and K independent one-slot weighted reservoirs (the
    // seed's stream) keep candidate j with probability p_j / P, p_j its
    // resample_target and P their sum. A kept candidate adds its
    // contribution shadowed, weighted P / (K p_j): the expectation is the
    // shadowed sum. The rays go only where light arrives unshadowed; a
    // candidate kept by m slots casts one ray, weighted m times.
    var slot_light: array<u32, K>;
    var slot_u: array<vec2f, K>;
    var slot_p: array<f32, K>;
    var total = 0.0;
    var count = 0u;
    var hc = seed;
    for (var b = bsh_next_leaf_lobe(BSH, bsh_first(BSH), x, r, rl); b != BSH_NONE; b = bsh_next_leaf_lobe(BSH, bsh_nodes[b].next, x, r, rl)) {
        count += 1u;
        let li = bsh_nodes[b].light;
        h = pcg_hash(h);
        let u1 = xi_from_bits(h);
        h = pcg_hash(h);
        let u = vec2f(u1, xi_from_bits(h));
        let p = resample_target(output_of(shade_pick_traced(li, x, n, r, rl, m, 1.0, u.x, u.y, eps, false)));
        if p > 0.0 {
            total += p;
            for (var q = 0u; q < K; q++) {
                hc = pcg_hash(hc);
                if weighted_replace(p, total, xi_from_bits(hc)) {
                    slot_light[q] = li;
                    slot_u[q] = u;
                    slot_p[q] = p;
                }
            }
        }
    }
    if total > 0.0 {
        for (var k = 0u; k < K; k++) {
            // A light is one candidate with one sampled point: the slots
            // holding it hold the same pick.
            let copies = pick_copies(slot_light, k);
            if copies > 0u {
                let w = total / (f32(K) * slot_p[k]) * f32(copies);
                t = add(t, shade_pick(slot_light[k], x, n, r, rl, m, w, slot_u[k].x, slot_u[k].y, eps));
            }
        }
    }
{% elif selection == "all" %}
    var count = 0u;
    for (var b = bsh_next_leaf_lobe(BSH, bsh_first(BSH), x, r, rl); b != BSH_NONE; b = bsh_next_leaf_lobe(BSH, bsh_nodes[b].next, x, r, rl)) {
        count += 1u;
        h = pcg_hash(h);
        let u1 = xi_from_bits(h);
        h = pcg_hash(h);
        t = add(t, shade_pick(bsh_nodes[b].light, x, n, r, rl, m, 1.0, u1, xi_from_bits(h), eps));
    }
{% else %}
    let picks = bsh_collect(x, r, rl, seed);
    let w_res = reservoir_weight(picks.n, K);
    for (var k = 0u; k < min(picks.n, K); k++) {
        h = pcg_hash(h);
        let u1 = xi_from_bits(h);
        h = pcg_hash(h);
        t = add(t, shade_pick(picks.light[k], x, n, r, rl, m, w_res, u1, xi_from_bits(h), eps));
    }
    let count = picks.n;
{% endif %}
{% if pbr == "radiance" or pbr == "bevy" %}
    textureStore(out_tex, texel, vec4f(t.diffuse + t.specular, f32(count)));
{% else %}
    textureStore(out_tex, texel, vec4f(t.e, f32(count)));
{% endif %}
{% if pbr == "split" %}
    textureStore(specular_tex, texel, vec4f(t.specular, 0.0));
{% endif %}
}
