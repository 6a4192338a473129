// The talk's stackless BSH traversal ("Improving tree traversal & shading")
// feeding a k-slot reservoir (Algorithm R): no shading inside the loop, and
// storage and the later shading loop bounded by K.

const K: u32 = {{ k }}u;

/// Lights held by the reservoir and the number of in-range lights seen.
struct Picks {
    light: array<u32, K>,
    n: u32,
}

{% include "bsh_walk.wgsl" %}
{% if grid %}
{{ bsh_grid }}

/// Word `i` of the pass's grid (the reader `bsh_grid_frame.wgsl` expects).
fn grid_word(i: u32) -> u32 {
    return grid[i];
}

{% include "bsh_grid_frame.wgsl" %}
{% endif %}

/// Where a receiver's candidates come from: its cell's entries `i..end`
/// of the pass's grid, cut to its lobe's cone `cone` (slc-core's
/// `lobe_cone`), then the walk from node `next` (the range tail after a
/// cell; the root without one).
struct BshCursor {
    i: u32,
    end: u32,
    next: u32,
    cone: vec2f,
}

/// The candidates of a receiver at `x` (mirror direction `r`, range lobe
/// `rl`): {% if grid %}its cell's leaves and then the range tail (whose
/// first node is the root's `next`) where the pass has a grid whose reach
/// holds `rl.w` (the Lambertian one at word 0 of `grid`, then the glossy
/// ones in order, each grid's word 14 where the next one's words start, 0
/// after the last) and `x` lies in its box, else{% endif %} the walk of the
/// whole tree. [`bsh_cursor_next`] gives them in the walk's order.
fn bsh_cursor(x: vec3f, r: vec3f, rl: vec4f) -> BshCursor {
    var c: BshCursor;
    c.i = 0u;
    c.end = 0u;
    c.next = bsh_first(BSH);
    c.cone = vec2f(0.0);
{% if grid %}
    var h = 0u;
    for (var g = 1u; g < GRIDS_MAX && rl.w > grid_reach(h); g++) {
        h = grid_word(h + 14u);
    }
    let f = grid_frame(h);
    if c.next != BSH_NONE && f.nx > 0u && rl.w <= grid_reach(h) {
        let cell = bsh_grid_cell(f, x);
        if cell != BSH_NONE {
            c.i = grid[h + GRID_HEADER + cell];
            c.end = grid[h + GRID_HEADER + cell + 1u];
            c.next = bsh_nodes[0].next;
            c.cone = lobe_cone(r, rl);
        }
    }
{% endif %}
    return c;
}

/// The next leaf of cursor `c` whose test ([`bsh_reaches`]) the receiver
/// passes, or `BSH_NONE`{% if grid %}: a glossy receiver's cell entries
/// first through the grid's cut (slc-core's `bsh_lobe_admits`, which
/// rejects only what `bsh_reaches` rejects){% endif %}.
fn bsh_cursor_next(c: ptr<function, BshCursor>, x: vec3f, r: vec3f, rl: vec4f) -> u32 {
{% if grid %}
    while (*c).i < (*c).end {
        let b = grid_entries[(*c).i];
        (*c).i += 1u;
        let n = bsh_nodes[b];
        if (rl.w <= 1.0 || bsh_lobe_admits(n.center, n.radius, n.extent, x, rl.w, r, (*c).cone)) && bsh_reaches(n, x, r, rl) {
            return b;
        }
    }
{% endif %}
    let b = bsh_next_leaf_lobe(BSH, (*c).next, x, r, rl);
    if b != BSH_NONE {
        (*c).next = bsh_nodes[b].next;
    }
    return b;
}

/// Lights whose range sphere, scaled for the receiver at `x` (mirror
/// direction `r`, range lobe `rl`; slc-core's `bsh_reaches`), contains `x`,
/// streamed through the reservoir; `seed` drives its random choices.
fn bsh_collect(x: vec3f, r: vec3f, rl: vec4f, seed: u32) -> Picks {
    var picks: Picks;
    picks.n = 0u;
    var h = seed;
    var cur = bsh_cursor(x, r, rl);
    for (var i = bsh_cursor_next(&cur, x, r, rl); i != BSH_NONE; i = bsh_cursor_next(&cur, x, r, rl)) {
        reservoir_offer(&picks, &h, bsh_nodes[i].light);
    }
    return picks;
}

/// Streams the candidate `light` through the reservoir `picks`, its
/// random choices drawn from the stream `h`.
fn reservoir_offer(picks: ptr<function, Picks>, h: ptr<function, u32>, light: u32) {
    if reservoir_takes((*picks).n) {
        (*picks).n += 1u;
        *h = pcg_hash(*h);
        let hi = *h;
        *h = pcg_hash(*h);
        let slot = reservoir_slot((*picks).n, K, hi, *h);
        if slot < K {
            (*picks).light[slot] = light;
        }
    }
}

/// The next threshold of a weighted one-slot reservoir that has just taken
/// a candidate at running sum `sum` (slc-core's `weighted_threshold`; the
/// slot takes again where its sum passes it), from one hash of `*h`.
fn next_threshold(sum: f32, h: ptr<function, u32>) -> f32 {
    *h = pcg_hash(*h);
    return weighted_threshold(sum, xi_from_bits(*h));
}

/// One reservoir pick connected to the shading point `x` (normal `n`).
struct Connection {
    /// Irradiance the pick adds at `x`, with the 1/p and reservoir weights
    /// (zero when the RR test at the sampled point fails, the light is
    /// behind `x`, or the shadow ray is blocked).
    e: vec3f,
    /// The sampled point on the light.
    y: vec3f,
    /// Cosine at `x` toward `y`.
    cos_x: f32,
}

/// Samples pick `li` at `(u1, u2)`, applies the RR test with the light's own
/// range² (scaled by the receiver's `s` toward it, 1 for a Lambertian one) at the
/// sampled point's distance, casts the shadow ray (offset `eps` along `n`)
/// and weights by `1/p` and the reservoir weight `w_res`.
fn connect(li: u32, x: vec3f, n: vec3f, ng: vec3f, s: f32, w_res: f32, u1: f32, u2: f32, eps: f32) -> Connection {
    return connect_traced(li, x, n, ng, s, w_res, u1, u2, eps, true);
}

/// [`connect`], casting the shadow ray only where `trace` says (without
/// it, the unshadowed contribution: what a resampled pick is weighed by).
fn connect_traced(li: u32, x: vec3f, n: vec3f, ng: vec3f, s: f32, w_res: f32, u1: f32, u2: f32, eps: f32, trace: bool) -> Connection {
    return connect_record(lights[li], x, n, ng, s * r2[li], s * rt2[li], w_res, u1, u2, eps, trace);
}

/// [`connect_traced`] for the light record `l` with the ranges² `r2`
/// (the RR test) and `rt2` (its `1/p`) given: both slc-core's `UNRANGED`
/// for the light's whole contribution, no roulette.
fn connect_record(l: GpuLight, x: vec3f, n: vec3f, ng: vec3f, r2: f32, rt2: f32, w_res: f32, u1: f32, u2: f32, eps: f32, trace: bool) -> Connection {
    var c: Connection;
    c.e = vec3f(0.0);
    c.y = light_point(l, u1, u2);
    c.cos_x = connection_cosine(x, c.y, n, ng, r2);
    // The shadow ray leaves along the geometric normal `ng`.
    if c.cos_x <= 0.0 || (trace && occluded(x + ng * eps, c.y)) {
        return c;
    }
    let v = x - c.y;
    let d2 = dot(v, v);
    c.e = light_intensity(l, v / sqrt(d2)) * connection_factor(c.cos_x, d2, rt2, w_res);
    return c;
}
