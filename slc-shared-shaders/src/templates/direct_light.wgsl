{% if ray_query %}
enable wgpu_ray_query;
{% endif %}
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
{% if tile_walk %}
const TILE_THREADS: u32 = {{ tile }}u * {{ tile }}u;
const BOX_THREADS: u32 = TILE_THREADS;
{% include "bsh_tile.wgsl" %}
{% endif %}
// The engine's direct pass: at every G-buffer pixel, the lights whose random
// range reaches it (BSH traversal), {% if selection == "weighted" %}{{ k }} importance-weighted picks among them{% elif selection == "resampled" %}{{ k }} picks resampled from them in proportion to their unshadowed contributions{% if reuse %} and reused across frames and pixels{% endif %}{% elif selection == "all" %}every one of them (exact given ξ){% else %}{{ k }} uniform picks among them (Algorithm R){% endif %},
// each sampled (a point on a triangle), RR-tested at that point with its own
// range, {% if shadows %}shadowed by one ray through the occluders' BVH (leaving the surface
// `view.shadow_offset` × the eye distance along the normal), {% endif %}and weighted by 1/p and its selection weight. Output: {% if pbr == "radiance" %}outgoing radiance
// under the G-buffer's glTF metallic-roughness material{% elif pbr == "bevy" %}outgoing radiance under
// Bevy StandardMaterial's BRDF of the G-buffer's material{% elif pbr == "split" %}irradiance, and the
// specular radiance of the G-buffer's material in specular_tex{% else %}irradiance{% endif %} (rgb) and the number of
// in-range lights (a); zero where no surface is.

{% if counters %}
// The counting variant: every shaded pixel adds its work to `counters`
// (slc-wgpu's DirectCounts, 64-bit per field: counter64.wgsl; never in a
// timed frame).

/// Lights this invocation evaluated without a ray.
var<private> evaluations: u32;

{% include "counter64.wgsl" %}

{% endif %}
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
{% if pbr != "none" %}
    let s2 = light_range_scale(li, x, r, rl);
{% else %}
    let s2 = 1.0;
{% endif %}
    return shade_connection(connect_traced(li, x, n, n, s2, w, u1, u2, eps, trace), x, n, m);
}

/// What connection `c` adds at `x` (normal `n`) under material `m`.
fn shade_connection(c: Connection, x: vec3f, n: vec3f, m: Material) -> Shaded {
    var s: Shaded;
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

/// The material at a G-buffer texel: base colour, metallic, perceptual
/// roughness and (Bevy) reflectance as the textures give them, seen from
/// direction `v`.
fn material_of(base: vec3f, metallic: f32, roughness: f32, reflectance: f32, v: vec3f) -> Material {
{% if pbr == "bevy" %}
    return Material(base, saturate(metallic), bevy_alpha(roughness), v, roughness, reflectance);
{% else %}
    return Material(base, saturate(metallic), ggx_alpha(saturate(roughness)), v, roughness, 0.0);
{% endif %}
}

fn add(a: Shaded, b: Shaded) -> Shaded {
    return Shaded(a.e + b.e, a.diffuse + b.diffuse, a.specular + b.specular);
}

/// `s` weighted per channel by `w`.
fn scaled(s: Shaded, w: vec3f) -> Shaded {
    return Shaded(s.e * w, s.diffuse * w, s.specular * w);
}

/// Per slot, the first slot holding the same sample, or K where the slot
/// holds none (`held[k]` false): slots whose `keys` are equal hold one
/// sample (a light, and for a light with area the point on it), shaded
/// once with the slots' weights summed in slot order (one shadow ray
/// instead of several). Every selection's picks are merged by it.
fn first_holders(keys: array<vec2u, K>, held: array<bool, K>) -> array<u32, K> {
    var first: array<u32, K>;
    for (var k = 0u; k < K; k++) {
        first[k] = select(K, k, held[k]);
        for (var j = 0u; j < k && held[k]; j++) {
            if held[j] && all(keys[j] == keys[k]) {
                first[k] = j;
                break;
            }
        }
    }
    return first;
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

{% if reuse %}
// ---- Reuse (ReSTIR DI's temporal and spatial reuse, Bitterli et al.
// 2020, as generalized RIS, Lin et al. 2022): each of the K slots is a
// reservoir whose pick carries an unbiased contribution weight W. This
// frame's candidates are combined with the slots of previous-frame pixels
// (the reprojected one and DOMAINS − 1 around it) under the
// generalized balance heuristic: a pick's share is its domain's confidence
// (times slc-core's `reuse_trust` in the pick: less where that surface is
// not this one, the more so the nearer the pick's light) times its target
// at that domain's surface (previous lights), over the sum for every
// domain. Every target is the pick's whole unshadowed
// contribution (no range, no roulette), so each domain can draw every
// light: the combination is unbiased, and the culling's noise averages
// over the reused frames.

/// A pixel's reservoirs as the next frame reads them.
struct ReusePixel {
    surface: ReuseSurface,
    slots: array<ReuseSlot, K>,
}

/// Where pixel `i`'s reservoirs of the previous frame are in
/// `reuse_pixels` (the half this frame does not write).
fn previous_index(i: u32) -> u32 {
    return (1u - reuse.parity) * view.width * view.height + i;
}

/// Where this frame writes pixel `i`'s reservoirs.
fn next_index(i: u32) -> u32 {
    return reuse.parity * view.width * view.height + i;
}

/// The previous-frame pixels one pixel reuses: the reprojected one and
/// its neighbours.
const DOMAINS: u32 = {{ reuse_domains }}u;

/// A previous-frame pixel whose reservoirs are reused: where in
/// `reuse_pixels`, its surface and material, its confidence.
struct Domain {
    pixel: u32,
    x: vec3f,
    n: vec3f,
    m: Material,
    c: f32,
    temporal: bool,
}

/// Slot `q`'s target of the pick of light record `l` at grid cells
/// `cells` for the surface `x` (normal `n`, material `m`): slc-core's
/// `slot_target` of its whole unshadowed contribution.
fn reuse_target(q: u32, l: GpuLight, cells: u32, x: vec3f, n: vec3f, m: Material) -> f32 {
{% if counters %}
    evaluations += 1u;
{% endif %}
    let c = sample_connection(l, cells, x, n, 0.0, false);
    return slot_target(output_of(shade_connection(c, x, n, m)), q, K);
}

/// The surface record of `x` (normal `n`, material `m`) with confidence `c`.
fn reuse_surface(x: vec3f, n: vec3f, m: Material, c: f32) -> ReuseSurface {
    return ReuseSurface(x, c, n, pack4x8unorm(vec4f(m.base, m.metallic)), pack2x16unorm(vec2f(saturate(m.roughness), saturate(m.reflectance))), 0u, 0u, 0u);
}

/// The material a surface record keeps, seen from `eye`.
fn reuse_material(s: ReuseSurface, eye: vec3f) -> Material {
    let b = unpack4x8unorm(s.base);
    let r = unpack2x16unorm(s.rough);
    return material_of(b.xyz, b.w, r.x, r.y, normalize(eye - s.x));
}

/// The sample a reused pick of light `li` at grid cells `cells` stands
/// for: the light, and for a triangle its point (a light without area has
/// one point for every cell).
fn sample_key(li: u32, cells: u32) -> vec2u {
    return vec2u(li, select(0u, cells, lights[li].kind == LIGHT_TRIANGLE));
}

/// The reused pick of light record `l` at grid cells `cells` connected
/// to `x` (normal `n`), unranged, weight 1; shadowed (its ray leaving
/// `x + eps·n`) where `trace`.
fn sample_connection(l: GpuLight, cells: u32, x: vec3f, n: vec3f, eps: f32, trace: bool) -> Connection {
    return connect_record(l, x, n, n, UNRANGED, UNRANGED, 1.0, grid_coordinate(cells), grid_coordinate(cells << 16u), eps, trace);
}

/// Whether a pick whose unshadowed target is positive reaches `x`: its
/// shadow ray is not blocked (its connection keeps light).
fn sample_reaches(l: GpuLight, cells: u32, x: vec3f, n: vec3f, eps: f32) -> bool {
    return any(sample_connection(l, cells, x, n, eps, true).e > vec3f(0.0));
}

/// The normal offset of a shadow ray from domain `d`'s surface, as its
/// record cast them (`view.shadow_offset` × its eye distance).
fn domain_offset(d: Domain) -> f32 {
    return view.shadow_offset * length(reuse.prev_eye - d.x);
}

/// Whether this record can tell what the previous one's shadow ray saw
/// for the pick of light `li` at grid cells `cells` at domain `d`'s
/// surface (from it to the light where it stood then, `lights_prev`): not
/// where that ray crosses the space the occluders moved in since
/// (`reuse.moved`). Visibility reuse gives the history no share of such a
/// pick, its own or this record's (the shares still sum to 1: this
/// record's pick takes all of it).
fn history_vouches(li: u32, cells: u32, d: Domain) -> bool {
    if reuse.moved == 0u {
        return true;
    }
    if reuse.moved == 2u {
        return false;
    }
    let a = d.x + d.n * domain_offset(d);
    let b = light_point(lights_prev[li], grid_coordinate(cells), grid_coordinate(cells << 16u));
    return ray_aabb(a, ray_inverse3(b - a), reuse.moved_min, reuse.moved_max, 1.0) < 0.0;
}

/// Whether the pick of light `li` at grid cells `cells`, which reaches
/// `x` (normal `n`) in this record, reached the surface of domain `d` in
/// the previous one, as far as this record can tell (`history_vouches`):
/// its ray from there to the light where it stood then. Visibility
/// reuse's history holds only picks that reached its pixel, so the pick's
/// share against that history counts the history's target only where it
/// did (ReSTIR DI's unbiased visibility reuse). Known without a ray where
/// the surface is this one and the light has not moved, or where the
/// history holds the same sample (it kept only picks that reached it).
fn reached_before(li: u32, cells: u32, d: Domain, x: vec3f, n: vec3f) -> bool {
    if !history_vouches(li, cells, d) {
        return false;
    }
    let l = lights[li];
    let lp = lights_prev[li];
    if all(d.x == x) && all(d.n == n) && all(l.p0 == lp.p0) && all(l.p1 == lp.p1) && all(l.p2 == lp.p2) {
        return true;
    }
    let key = sample_key(li, cells);
    for (var q = 0u; q < K; q++) {
        let h = reuse_pixels[previous_index(d.pixel)].slots[q];
        if h.w > 0.0 && h.light < arrayLength(&lights) && all(sample_key(h.light, h.u) == key) {
            return true;
        }
    }
    return sample_reaches(lp, cells, d.x, d.n, domain_offset(d));
}

/// The previous-frame pixels pixel `x` (normal `n`, distance `d` from the
/// eye) reuses, drawn from stream `h`: the one it reprojects to, then
/// `DOMAINS − 1` in a disk of `reuse.radius` pixels around it, each
/// kept where it saw the same surface, once.
fn reuse_domains(x: vec3f, n: vec3f, d: f32, h: u32, doms: ptr<function, array<Domain, DOMAINS>>) -> u32 {
    var nd = 0u;
    if reuse.has_history != 1u {
        return 0u;
    }
    let q = reproject(reuse.c0, reuse.c1, reuse.c2, reuse.c3, x, f32(view.width), f32(view.height));
    if q.z <= 0.0 {
        return 0u;
    }
    var hr = h;
    for (var j = 0u; j < DOMAINS; j++) {
        var p = q.xy;
        if j > 0u {
            hr = pcg_hash(hr);
            let u1 = xi_from_bits(hr);
            hr = pcg_hash(hr);
            p += disk_offset(reuse.radius, u1, xi_from_bits(hr));
        }
        let t = vec2i(round(p));
        if t.x < 0 || t.y < 0 || t.x >= i32(view.width) || t.y >= i32(view.height) {
            continue;
        }
        let pixel = u32(t.y) * view.width + u32(t.x);
        var seen = false;
        for (var k = 0u; k < nd; k++) {
            seen = seen || (*doms)[k].pixel == pixel;
        }
        let s = reuse_pixels[previous_index(pixel)].surface;
        if seen || !(s.m > 0.0) || !history_matches(n, s.n, x, dot(s.n, s.x), d) {
            continue;
        }
        (*doms)[nd] = Domain(pixel, s.x, s.n, reuse_material(s, reuse.prev_eye), min(s.m, reuse.max_confidence), j == 0u);
        nd += 1u;
    }
    return nd;
}

/// Slot `q`'s reservoir combined by generalized RIS (slc-core's
/// `gris_weight`, balance heuristic) from a pick `cur` of this pixel
/// (confidence `cur_c`; its weight `cur.w` the unbiased contribution
/// weight, or with `cur_ris` the sum `P` of this frame's candidate targets,
/// so `W = P / p̂(y)`) and slot `q` of the histories of domains
/// `k0..k1` of `doms`. Each input's share is its domain's target over
/// all of theirs: this pixel's whole unranged target here, the previous
/// record's light at each domain's stored surface; with `cur_reached`
/// false the domains could not hold `cur`'s pick (visibility reuse: it
/// did not reach their surface), and their targets for it are 0. One
/// pick is kept with probability proportional to its weight (stream
/// `hs`).
fn gris_combine(q: u32, cur: ReuseSlot, cur_ris: bool, cur_c: f32, cur_reached: bool, k0: u32, k1: u32, x: vec3f, n: vec3f, m: Material, doms: ptr<function, array<Domain, DOMAINS>>, hs: ptr<function, u32>) -> ReuseSlot {
    var w_sum = 0.0;
    var out = ReuseSlot(0u, 0u, 0.0);
    var out_target = 0.0;
    for (var j = k0; j <= k1; j++) {
        // Input k0 is this pixel's pick, input j > k0 domain j − 1's history.
        var s = cur;
        if j > k0 {
            s = reuse_pixels[previous_index((*doms)[j - 1u].pixel)].slots[q];
        }
        if !(s.w > 0.0) || s.light >= arrayLength(&lights) {
            continue;
        }
        if j > k0 && reuse.visibility == 1u && !history_vouches(s.light, s.u, (*doms)[j - 1u]) {
            continue;
        }
        let here = reuse_target(q, lights[s.light], s.u, x, n, m);
        if !(here > 0.0) {
            continue;
        }
        var w_in = s.w;
        if j == k0 && cur_ris {
            w_in = s.w / here;
        }
        var own = cur_c * here;
        var all = own;
        // The sample's light, for each domain's trust in it.
        let y = light_point(lights[s.light], grid_coordinate(s.u), grid_coordinate(s.u << 16u));
        for (var k = k0; k < k1; k++) {
            var t = 0.0;
            if j > k0 || cur_reached {
                let d = (*doms)[k];
                t = d.c * reuse_trust(y - x, y - d.x) * reuse_target(q, lights_prev[s.light], s.u, d.x, d.n, d.m);
            }
            all += t;
            if k + 1u == j {
                own = t;
            }
        }
        let w = gris_weight(own, all, here, w_in);
        w_sum += w;
        *hs = pcg_hash(*hs);
        if w > 0.0 && weighted_replace(w, w_sum, xi_from_bits(*hs)) {
            out = s;
            out_target = here;
        }
    }
    out.w = gris_contribution_weight(w_sum, out_target);
    return out;
}
{% endif %}

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u, @builtin(local_invocation_index) lid: u32) {
    // Every invocation takes part in its tile's walk (barriers); one
    // outside the image, or without a surface (or a finite position),
    // finds no light and writes zeros where its texel is.
    let inside = gid.x < view.width && gid.y < view.height;
    let texel = vec2i(i32(gid.x), i32(gid.y));
    var s = vec4f(0.0);
    var nn = vec3f(0.0);
    if inside {
        s = surface_at(texel);
        nn = textureLoad(normal_tex, texel, 0).xyz;
    }
    let len2 = dot(nn, nn);
    let x = s.xyz;
    let has = inside && s.w > 0.0 && len2 > 0.0 && all(abs(x) <= vec3f(F32_MAX));
    var n = vec3f(0.0, 0.0, 1.0);
    if has {
        n = nn / sqrt(len2);
    }
    var m: Material;
    // The receiver as light selection sees it: Lambertian for irradiance;
    // with a material, its lobe, mirror direction and range scale s (a
    // glossy lobe reaches farther lights near its mirror direction;
    // slc-core's `range_lobe`).
    var lobe = vec4f(1.0, 0.0, 1.0, 1.0);
    var r = n;
{% if pbr != "none" %}
    if has {
        let mr = textureLoad(metal_rough_tex, texel, 0);
        m = material_of(textureLoad(base_color_tex, texel, 0).xyz, mr.z, mr.y, mr.w, normalize(view.eye - x));
{% if pbr == "bevy" %}
        // Selection sees Bevy's material through the glTF lobe of the same
        // F0 (any importance keeps the estimate unbiased).
        lobe = receiver_lobe(m.base, m.metallic, vec3f(bevy_f0(mr.w)), 1.0, m.alpha, dot(n, m.v));
{% else %}
        lobe = receiver_lobe(m.base, m.metallic, view.f0_d, view.f90_d, m.alpha, dot(n, m.v));
{% endif %}
        r = mirror_dir(n, m.v);
    }
{% endif %}
    let rl = range_lobe(lobe);
    let eps = view.shadow_offset * length(view.eye - x);
    let seed = point_stream(view.seed, gid.y * view.width + gid.x, view.frame);
    var h = pick_stream(seed);
    var t = Shaded(vec3f(0.0), vec3f(0.0), vec3f(0.0));
{% if selection == "weighted" %}
    var picks = weighted_picks(seed);
{% elif selection == "resampled" %}
    // Resampled importance sampling over every light in range: each is
    // sampled (its point from the pick stream{% if reuse %}, on the 16-bit grid{% endif %}) and evaluated without a
    // shadow ray, and K independent one-slot weighted reservoirs (the
    // seed's stream, one hash per take: the threshold form) keep candidate
    // j with probability p_j / P, p_j the slot's target (slc-core's
    // slot_target: one colour channel per slot, the channel mean below 3
    // slots) and P their sum. {% if reuse %}Slot k's pick then has the unbiased
    // contribution weight P / p̂(y), p̂ its whole unranged target (p_j is
    // p̂ times the roulette's 1/p), and enters the reuse.{% else %}A kept candidate adds its
    // contribution shadowed, weighted P / p_j times the slot's share of
    // each channel (slot_share): the expectation is the shadowed sum. The
    // rays go only where light arrives unshadowed; a candidate kept by
    // several slots casts one ray, weighted by all their shares.{% endif %}

    var slot_light: array<u32, K>;
    var slot_u: array<vec2f, K>;
    var slot_p: array<f32, K>;
{% if reuse %}
    var slot_cells: array<u32, K>;
{% endif %}
    var total = vec3f(0.0);
    var count = 0u;
    var hc = seed;
    // Each slot's threshold on its running sum (next_threshold; 0
    // while empty): one hash per take.
    var threshold: array<f32, K>;
{% elif selection == "all" %}
    var count = 0u;
{% else %}
    var picks: Picks;
    picks.n = 0u;
    var hr = seed;
{% endif %}
{% if tile_walk %}
    // The lights in range, from the tile's list (bsh_tile.wgsl): the ones
    // this pixel's own walk of the hierarchy finds, in its order.
    let walk = tile_walk_begin(lid, x, rl.w, has);
    for (var start = 0u; start < walk.total; start += TILE_LIST) {
        let listed = tile_walk_fill(lid, walk, start);
        for (var j = 0u; j < listed; j++) {
            let b = tile_list[j];
            if !has || !bsh_reaches(bsh_nodes[b], x, r, rl) {
                continue;
            }
{% else %}
    // The lights in range, from this pixel's own walk of the hierarchy.
    if has {
        for (var b = bsh_next_leaf_lobe(BSH, bsh_first(BSH), x, r, rl); b != BSH_NONE; b = bsh_next_leaf_lobe(BSH, bsh_nodes[b].next, x, r, rl)) {
{% endif %}
            let li = bsh_nodes[b].light;
{% if selection == "weighted" %}
            weighted_offer(&picks, li, light_weight(li, x, n, r, lobe, rl));
{% elif selection == "resampled" %}
            count += 1u;
            h = pcg_hash(h);
{% if reuse %}
            let h1 = h;
            h = pcg_hash(h);
            let cells = grid_cells(h1, h);
            let u = vec2f(grid_coordinate(h1), grid_coordinate(h));
{% else %}
            let u1 = xi_from_bits(h);
            h = pcg_hash(h);
            let u = vec2f(u1, xi_from_bits(h));
{% endif %}
            let c = output_of(shade_pick_traced(li, x, n, r, rl, m, 1.0, u.x, u.y, eps, false));
{% if counters %}
            evaluations += 1u;
{% endif %}
            if resample_target(c) > 0.0 {
                total += c;
                for (var q = 0u; q < K; q++) {
                    let p = slot_target(c, q, K);
                    let sum = slot_target(total, q, K);
                    if p > 0.0 && sum > threshold[q] {
                        slot_light[q] = li;
                        slot_u[q] = u;
                        slot_p[q] = p;
{% if reuse %}
                        slot_cells[q] = cells;
{% endif %}
                        threshold[q] = next_threshold(sum, &hc);
                    }
                }
            }
{% elif selection == "all" %}
            count += 1u;
            h = pcg_hash(h);
            let u1 = xi_from_bits(h);
            h = pcg_hash(h);
            t = add(t, shade_pick(li, x, n, r, rl, m, 1.0, u1, xi_from_bits(h), eps));
{% else %}
            reservoir_offer(&picks, &hr, li);
{% endif %}
        }
{% if tile_walk %}
        // The next round refills the list.
        workgroupBarrier();
{% endif %}
    }
    if !has {
        if inside {
            textureStore(out_tex, texel, vec4f(0.0));
{% if pbr == "split" %}
            textureStore(specular_tex, texel, vec4f(0.0));
{% endif %}
{% if reuse %}
            reuse_pixels[next_index(gid.y * view.width + gid.x)].surface.m = 0.0;
{% endif %}
        }
        return;
    }
{% if selection == "weighted" %}
    if picks.w_sum > 0.0 {
        // The picks are independent, so a light may be picked more than
        // once. A light without area (point, spot, IES, VPL) has no point
        // to sample: its `copies` picks are one ray and one term, shaded
        // once at its first pick with `copies` times a pick's weight (the
        // same sum, `copies − 1` fewer shadow rays). A triangle's picks
        // each sample a point of their own (keys of their own).
        var keys: array<vec2u, K>;
        var held: array<bool, K>;
        for (var k = 0u; k < K; k++) {
            let own = select(0u, k + 1u, lights[picks.light[k]].kind == LIGHT_TRIANGLE);
            keys[k] = vec2u(picks.light[k], own);
            held[k] = true;
        }
        let firsts = first_holders(keys, held);
        for (var k = 0u; k < K; k++) {
            h = pcg_hash(h);
            let u1 = xi_from_bits(h);
            h = pcg_hash(h);
            let u2 = xi_from_bits(h);
            let li = picks.light[k];
            var copies = 0u;
            for (var j = k; j < K; j++) {
                copies += select(0u, 1u, firsts[j] == k);
            }
            if copies > 0u {
                t = add(t, shade_pick(li, x, n, r, rl, m, weighted_pick_weight(picks.w_sum, picks.w[k], K) * f32(copies), u1, u2, eps));
            }
        }
    }
    let count = picks.n;
{% elif selection == "resampled" %}
    // The resampled slots' picks (their candidates taken in the tile loop).
{% if reuse %}
    // Each slot first combines this frame's pick (confidence 1) with the
    // same slot of the pixel's own history (the reprojected pixel, where it
    // saw this surface): that reservoir is the next frame's history. The
    // neighbours' histories then join it for this frame's shading only, so
    // no reservoir feeds back through its neighbours.
    let pixel = gid.y * view.width + gid.x;
    var doms: array<Domain, DOMAINS>;
    let nd = reuse_domains(x, n, length(view.eye - x), reuse_stream(seed, 0u), &doms);
    let own_history = nd > 0u && doms[0].temporal;
    let first = select(0u, 1u, own_history);
    let confidence = 1.0 + select(0.0, doms[0].c, own_history);
    var hs = reuse_stream(seed, 1u);
    // With visibility reuse (ReSTIR DI's), this frame's picks are shadowed
    // before they meet the history: an occluded one enters with no weight,
    // so a reservoir holds only picks that reached its pixel, and its
    // weight averages over the frames it stands for how much of the light
    // arrives (not only whether its last pick did). Slots holding the same
    // sample cast one ray, and a final pick that is one of these samples
    // is not traced again.
    var fresh_keys: array<vec2u, K>;
    var fresh_held: array<bool, K>;
    for (var q = 0u; q < K; q++) {
        fresh_keys[q] = sample_key(slot_light[q], slot_cells[q]);
        fresh_held[q] = reuse.visibility == 1u && slot_p[q] > 0.0;
    }
    let fresh_firsts = first_holders(fresh_keys, fresh_held);
    var fresh_visible: array<bool, K>;
    for (var q = 0u; q < K; q++) {
        if fresh_firsts[q] == q {
            fresh_visible[q] = sample_reaches(lights[slot_light[q]], slot_cells[q], x, n, eps);
        } else if fresh_firsts[q] < K {
            fresh_visible[q] = fresh_visible[fresh_firsts[q]];
        }
    }
    // And whether a visible one could be in the history: it reached the
    // reprojected surface in the previous record (a second ray, only where
    // the camera or its light moved). Without it a light that came out of
    // a shadow would be shared with a history that cannot hold it, and
    // the image would come out dark where things move.
    var fresh_before: array<bool, K>;
    for (var q = 0u; q < K; q++) {
        fresh_before[q] = true;
        if fresh_firsts[q] == q && fresh_visible[q] && own_history {
            fresh_before[q] = reached_before(slot_light[q], slot_cells[q], doms[0], x, n);
        } else if fresh_firsts[q] < K {
            fresh_before[q] = fresh_before[fresh_firsts[q]];
        }
    }
    var kept: array<ReuseSlot, K>;
    var fin: array<ReuseSlot, K>;
    for (var q = 0u; q < K; q++) {
        // This frame's pick (its weight the candidates' sum; none where
        // visibility reuse found it occluded) and the pixel's own history.
        let fresh = slot_p[q] > 0.0 && (reuse.visibility == 0u || fresh_visible[q]);
        kept[q] = gris_combine(q, ReuseSlot(slot_light[q], slot_cells[q], select(0.0, slot_target(total, q, K), fresh)), true, 1.0, fresh_before[q], 0u, first, x, n, m, &doms, &hs);
        // The neighbours' histories join it (confidence: the inputs each
        // stands for).
        fin[q] = kept[q];
        if nd > first {
            fin[q] = gris_combine(q, kept[q], false, confidence, true, first, nd, x, n, m, &doms, &hs);
        }
    }
    // The K picks, shadowed, each weighted W / K; the slots holding the
    // same sample cast one ray with their weights summed. With visibility
    // reuse a slot whose pick is occluded here keeps no pick for the next
    // frame.
    var keys: array<vec2u, K>;
    var held: array<bool, K>;
    for (var k = 0u; k < K; k++) {
        keys[k] = sample_key(fin[k].light, fin[k].u);
        held[k] = fin[k].w > 0.0;
    }
    let firsts = first_holders(keys, held);
    var visible: array<bool, K>;
    for (var k = 0u; k < K; k++) {
        if firsts[k] != k {
            continue;
        }
        var w = vec3f(0.0);
        for (var j = k; j < K; j++) {
            if firsts[j] == k {
                w += fin[j].w * slot_share(j, K);
            }
        }
        // A sample this frame's picks already traced.
        var known = false;
        var seen = false;
        for (var j = 0u; j < K && !known; j++) {
            if fresh_held[j] && all(fresh_keys[j] == keys[k]) {
                known = true;
                seen = fresh_visible[j];
            }
        }
        // A known occluded sample adds nothing and is not evaluated.
        var shaded = Shaded(vec3f(0.0), vec3f(0.0), vec3f(0.0));
        if !known || seen {
            shaded = shade_connection(sample_connection(lights[fin[k].light], fin[k].u, x, n, eps, !known), x, n, m);
        }
        t = add(t, scaled(shaded, w));
        for (var j = k; j < K; j++) {
            if firsts[j] == k {
                visible[j] = resample_target(output_of(shaded)) > 0.0;
            }
        }
    }
    for (var q = 0u; q < K; q++) {
        // Visibility reuse comes without neighbours: the kept pick is the
        // shaded one.
        let keep = reuse.visibility == 0u || visible[q];
        reuse_pixels[next_index(pixel)].slots[q] = ReuseSlot(kept[q].light, kept[q].u, select(0.0, kept[q].w, keep));
    }
    reuse_pixels[next_index(pixel)].surface = reuse_surface(x, n, m, min(confidence, reuse.max_confidence));
{% else %}
    // A light is one candidate with one sampled point: the slots holding
    // it hold the same pick, shaded once with their weights.
    var keys: array<vec2u, K>;
    var held: array<bool, K>;
    for (var k = 0u; k < K; k++) {
        keys[k] = vec2u(slot_light[k], 0u);
        held[k] = slot_p[k] > 0.0;
    }
    let firsts = first_holders(keys, held);
    for (var k = 0u; k < K; k++) {
        var w = vec3f(0.0);
        let first = firsts[k] == k;
        for (var j = k; j < K && first; j++) {
            if firsts[j] == k {
                w += slot_target(total, j, K) / slot_p[j] * slot_share(j, K);
            }
        }
        if first {
            t = add(t, scaled(shade_pick(slot_light[k], x, n, r, rl, m, 1.0, slot_u[k].x, slot_u[k].y, eps), w));
        }
    }
{% endif %}
{% elif selection == "all" %}
    // Every light in range is shaded in the tile loop above.
{% else %}
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
{% if counters %}
    counter_add(DIRECT_COUNT_PIXELS, 1u);
    counter_add(DIRECT_COUNT_CANDIDATES, count);
    counter_add(DIRECT_COUNT_EVALUATIONS, evaluations);
{% if shadows %}
    counter_add(DIRECT_COUNT_RAYS, rays_cast);
    counter_add(DIRECT_COUNT_NODES, nodes_visited);
{% endif %}
{% endif %}
}
