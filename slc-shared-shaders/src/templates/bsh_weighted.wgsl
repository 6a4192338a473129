// slc-weighted over the BSH: every in-range candidate gets the weight
// w = ĝ/p (slc-core's cone_weight: its importance over its roulette
// probability), and K independent one-slot weighted reservoirs pick among
// them (a pick of weight w is then weighted W/(K·w)). A zero weight (no
// light can arrive) is never picked.

/// `slc-weighted`'s weight of light `li` at `x` with normal `n`.
fn light_weight(li: u32, x: vec3f, n: vec3f) -> f32 {
    let c = light_cones[li];
    return cone_weight(c.center, c.radius, c.phi, c.axis, c.cos_o, c.cos_e, rt2[li], x, n);
}

/// The weighted picks at a point: each slot's light and weight, the
/// candidates' total weight and how many candidates the traversal found.
struct WeightedPicks {
    light: array<u32, K>,
    w: array<f32, K>,
    w_sum: f32,
    n: u32,
}

/// The lights whose range sphere contains `x` (normal `n`), streamed
/// through K weighted one-slot reservoirs driven by `seed`.
fn bsh_weighted_collect(x: vec3f, n: vec3f, seed: u32) -> WeightedPicks {
    var picks: WeightedPicks;
    picks.w_sum = 0.0;
    picks.n = 0u;
    var h = seed;
    for (var b = bsh_next_leaf(BSH, bsh_first(BSH), x); b != BSH_NONE; b = bsh_next_leaf(BSH, bsh_nodes[b].next, x)) {
        picks.n += 1u;
        let li = bsh_nodes[b].light;
        let w = light_weight(li, x, n);
        if w > 0.0 {
            picks.w_sum += w;
            for (var s = 0u; s < K; s++) {
                h = pcg_hash(h);
                if weighted_replace(w, picks.w_sum, xi_from_bits(h)) {
                    picks.light[s] = li;
                    picks.w[s] = w;
                }
            }
        }
    }
    return picks;
}
