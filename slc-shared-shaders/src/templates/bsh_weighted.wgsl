// slc-weighted over the BSH: every in-range candidate gets the weight
// w = ĝ/p (slc-core's cone_weight through `light_weight`: its importance for
// the receiver over its roulette probability), and K independent one-slot
// weighted reservoirs (in the threshold form) pick among them (a pick of
// weight w is then weighted W/(K·w)). A zero weight (no light can arrive) is never picked.

/// The weighted picks at a point: each slot's light and weight, the
/// candidates' total weight, how many candidates the traversal found and
/// the random stream's state after the traversal.
struct WeightedPicks {
    light: array<u32, K>,
    w: array<f32, K>,
    w_sum: f32,
    n: u32,
    h: u32,
}

/// The lights whose range sphere, scaled for the receiver (range lobe `rl`;
/// slc-core's `bsh_reaches`), contains `x`, weighed for the receiver
/// `(x, n, r, lobe)` and streamed through K weighted one-slot reservoirs
/// driven by the stream `h`.
fn bsh_weighted_collect(x: vec3f, n: vec3f, r: vec3f, lobe: vec4f, rl: vec4f, h0: u32) -> WeightedPicks {
    var picks: WeightedPicks;
    picks.w_sum = 0.0;
    picks.n = 0u;
    var h = h0;
    // Each slot's threshold on the running sum (next_threshold; 0
    // while empty): one hash per take.
    var threshold: array<f32, K>;
    for (var b = bsh_next_leaf_lobe(BSH, bsh_first(BSH), x, r, rl); b != BSH_NONE; b = bsh_next_leaf_lobe(BSH, bsh_nodes[b].next, x, r, rl)) {
        picks.n += 1u;
        let li = bsh_nodes[b].light;
        let w = light_weight(li, x, n, r, lobe, rl);
        if w > 0.0 {
            picks.w_sum += w;
            for (var s = 0u; s < K; s++) {
                if picks.w_sum > threshold[s] {
                    picks.light[s] = li;
                    picks.w[s] = w;
                    threshold[s] = next_threshold(picks.w_sum, &h);
                }
            }
        }
    }
    picks.h = h;
    return picks;
}
