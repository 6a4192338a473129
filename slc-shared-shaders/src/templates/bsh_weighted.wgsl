// slc-weighted over the BSH: every in-range candidate gets the weight
// w = ĝ/p (slc-core's cone_weight through `light_weight`: its importance for
// the receiver over its roulette probability), and K independent one-slot
// weighted reservoirs (in the threshold form) pick among them (a pick of
// weight w is then weighted W/(K·w)). A zero weight (no light can arrive) is never picked.

/// The weighted picks at a point: each slot's light, weight and threshold
/// on the running sum (next_threshold; 0 while empty: one hash per take),
/// the candidates' total weight, how many candidates were offered and the
/// random stream's state.
struct WeightedPicks {
    light: array<u32, K>,
    w: array<f32, K>,
    threshold: array<f32, K>,
    w_sum: f32,
    n: u32,
    h: u32,
}

/// K empty slots whose random choices the stream `h` drives.
fn weighted_picks(h: u32) -> WeightedPicks {
    var picks: WeightedPicks;
    picks.w_sum = 0.0;
    picks.n = 0u;
    picks.h = h;
    return picks;
}

/// Offers candidate light `li` of weight `w` to the K slots of `picks`
/// (counted; a zero weight is never kept).
fn weighted_offer(picks: ptr<function, WeightedPicks>, li: u32, w: f32) {
    (*picks).n += 1u;
    if w > 0.0 {
        (*picks).w_sum += w;
        var h = (*picks).h;
        for (var s = 0u; s < K; s++) {
            if (*picks).w_sum > (*picks).threshold[s] {
                (*picks).light[s] = li;
                (*picks).w[s] = w;
                (*picks).threshold[s] = next_threshold((*picks).w_sum, &h);
            }
        }
        (*picks).h = h;
    }
}

/// The lights whose range sphere, scaled for the receiver (range lobe `rl`;
/// slc-core's `bsh_reaches`), contains `x`, weighed for the receiver
/// `(x, n, r, lobe)` and streamed through K weighted one-slot reservoirs
/// driven by the stream `h0`.
fn bsh_weighted_collect(x: vec3f, n: vec3f, r: vec3f, lobe: vec4f, rl: vec4f, h0: u32) -> WeightedPicks {
    var picks = weighted_picks(h0);
    var cur = bsh_cursor(x, r, rl);
    for (var b = bsh_cursor_next(&cur, x, r, rl); b != BSH_NONE; b = bsh_cursor_next(&cur, x, r, rl)) {
        let li = bsh_nodes[b].light;
        weighted_offer(&picks, li, light_weight(li, x, n, r, lobe, rl));
    }
    return picks;
}
