//! Reservoir sampling of in-range lights (talk: "Reservoir sampling
//! \[Vitter85\]"; docs/architecture.md §1.5). The GPU cannot store every light a traversal
//! finds, so it streams them through `k` slots.
//!
//! - [`Reservoir`]: Vitter's Algorithm R. After `n` candidates every one is
//!   held with probability `min(k/n, 1)`, so weighting each held light by
//!   `max(n/k, 1)` keeps the sum unbiased.
//! - [`WeightedReservoir`]: `k` independent one-slot weighted reservoirs
//!   (Chao 1982). Each slot holds candidate `i` with probability `wᵢ/W`;
//!   a held light's weight is `W/(k·wᵢ)` (beyond the paper). Each slot
//!   keeps a threshold on the running sum ([`weighted_threshold`]), so it
//!   draws a random number only when it takes a candidate.
//!
//! Random input is two 32-bit words per candidate; the index draw uses 64
//! bits so its bias is below `n/2⁶⁴` even for `n` near `u32::MAX`.

use crate::range::TWO_PI;
use crate::wgsl::*;

crate::shared! {
    /// High 32 bits of the 64-bit product `a · b`, from 16-bit halves (no
    /// 64-bit integers in WGSL; no intermediate overflows).
    pub fn mul_hi_u32(a: u32, b: u32) -> u32 {
        let a_lo: u32 = a & 65535;
        let a_hi: u32 = a >> 16;
        let b_lo: u32 = b & 65535;
        let b_hi: u32 = b >> 16;
        let ll: u32 = a_lo * b_lo;
        let lh: u32 = a_lo * b_hi;
        let hl: u32 = a_hi * b_lo;
        let hh: u32 = a_hi * b_hi;
        let mid: u32 = (ll >> 16) + (lh & 65535) + (hl & 65535);
        return hh + (lh >> 16) + (hl >> 16) + (mid >> 16);
    }

    /// `⌊(hi·2³² + lo) · n / 2⁶⁴⌋`: a uniform index in `[0, n)` from 64
    /// random bits, with bias below `n/2⁶⁴`.
    pub fn uniform_index(n: u32, hi: u32, lo: u32) -> u32 {
        let p_lo: u32 = mul_lo_u32(hi, n);
        let p_hi: u32 = mul_hi_u32(hi, n);
        let carry_in: u32 = mul_hi_u32(lo, n);
        if p_lo > 4294967295 - carry_in {
            return p_hi + 1;
        }
        return p_hi;
    }

    /// Algorithm R: where the `n`-th candidate (counting from 1) goes in a
    /// `k`-slot reservoir: slot `n − 1` while filling, then a uniform
    /// `j ∈ [0, n)` replaces slot `j` if `j < k`; returns `k` to discard.
    pub fn reservoir_slot(n: u32, k: u32, hi: u32, lo: u32) -> u32 {
        if n <= k {
            return n - 1;
        }
        let j: u32 = uniform_index(n, hi, lo);
        if j < k {
            return j;
        }
        return k;
    }

    /// Candidates a reservoir counts at most (`u32::MAX`); later ones are
    /// ignored, so the count never wraps.
    pub const RESERVOIR_FULL: u32 = 4294967295;

    /// `true` while a reservoir that has seen `n` candidates takes another.
    pub fn reservoir_takes(n: u32) -> bool {
        return n < RESERVOIR_FULL;
    }

    /// Weight of each held light after `n` candidates: `max(n/k, 1)`.
    pub fn reservoir_weight(n: u32, k: u32) -> f32 {
        return max(to_f32(n) / to_f32(k), 1.0);
    }

    /// Weighted one-slot reservoir: the candidate with weight `w` replaces the
    /// held one iff `u · W < w`, `W` the running weight sum including `w`,
    /// `u ∈ [0, 1)`; so it is held at the end with probability `w/W_final`.
    pub fn weighted_replace(w: f32, w_sum: f32, u: f32) -> bool {
        return u * w_sum < w;
    }

    /// The same one-slot reservoir as a threshold on its running sum (the
    /// jump form of [`weighted_replace`], after Efraimidis & Spirakis 2006
    /// and Li's Algorithm L): after taking a candidate at running sum `W_j`,
    /// the slot keeps it through candidate `m` with probability
    /// `Π (1 − w_i/W_i) = W_j/W_m`, so with `u ∈ [0, 1)` drawn at the take
    /// it is replaced first by the candidate whose running sum exceeds
    /// `W_j/(1 − u)` (this threshold; an empty slot's is 0). The same
    /// distribution with one random number per take instead of one per
    /// candidate: a slot takes about `ln n` of `n` equal candidates.
    pub fn weighted_threshold(w_sum: f32, u: f32) -> f32 {
        return w_sum / (1.0 - u);
    }

    /// Estimator weight of a pick of weight `w` among `k` independent
    /// weighted slots over candidates weighing `w_sum`: `W/(k·w)`, the
    /// inverse of its expected count.
    pub fn weighted_pick_weight(w_sum: f32, w: f32, k: u32) -> f32 {
        return w_sum / (to_f32(k) * w);
    }

    /// Probability that a `k`-slot reservoir at a point where the traversal
    /// counted `seen` in-range lights selects a given light, independent of
    /// that light's own ξ (what MIS needs): `1/max((others + 1)/k, 1)`, with
    /// `others = seen − 1` when `in_range` says the light was one of the
    /// `seen` (never below 0), else `others = seen`.
    pub fn reservoir_select_pdf(seen: u32, in_range: bool, k: u32) -> f32 {
        let mut others: u32 = seen;
        if in_range && seen > 0 {
            others = seen - 1;
        }
        return 1.0 / reservoir_weight(others + 1, k);
    }

    /// The target a resampled pick is drawn in proportion to: the channel
    /// mean of its unshadowed contribution `c` (any function positive
    /// wherever `c` is keeps the estimate unbiased).
    pub fn resample_target(c: vec3f) -> f32 {
        return (c.x + c.y + c.z) * 0.33333334;
    }

    /// The target slot `slot` of `k` resampled picks draws in proportion
    /// to: with `k ≥ 3`, one colour channel of the unshadowed contribution
    /// `c`, channel `slot mod 3`, so that every channel is estimated by
    /// picks drawn in proportion to that channel (a target shared by the
    /// channels, such as their mean, picks a red light as often for the
    /// blue channel as for the red one: colour noise wherever the lights
    /// differ in colour); with fewer slots, the channel mean
    /// ([`resample_target`]).
    pub fn slot_target(c: vec3f, slot: u32, k: u32) -> f32 {
        if k < 3 {
            return resample_target(c);
        }
        let j: u32 = slot % 3;
        if j == 0 {
            return c.x;
        }
        if j == 1 {
            return c.y;
        }
        return c.z;
    }

    /// What slot `slot` of `k` adds to each channel's estimate per unit of
    /// its pick's contribution `f(y)·W`: with `k ≥ 3`, `1/n_j` in its own
    /// channel `j = slot mod 3` (`n_j = ⌊(k + 2 − j)/3⌋` slots estimate
    /// channel `j`) and 0 in the others, whose targets it was not drawn
    /// for ([`slot_target`]); with fewer slots `1/k` in every channel.
    pub fn slot_share(slot: u32, k: u32) -> vec3f {
        if k < 3 {
            let w: f32 = 1.0 / to_f32(k);
            return vec3f(w, w, w);
        }
        let j: u32 = slot % 3;
        let w: f32 = 1.0 / to_f32((k + 2 - j) / 3);
        if j == 0 {
            return vec3f(w, 0.0, 0.0);
        }
        if j == 1 {
            return vec3f(0.0, w, 0.0);
        }
        return vec3f(0.0, 0.0, w);
    }

    /// A coordinate of a reused pick's point, on the 16-bit grid the
    /// candidates draw it on: the midpoint `(k + ½)/2¹⁶` of cell `k`, the
    /// high 16 bits of `bits` (a hash, or a stored pick's cells). A pick is
    /// kept as its two cells, so the point a later frame shades is the one
    /// drawn; the midpoint rule's error is `O(2⁻³²)`.
    pub fn grid_coordinate(bits: u32) -> f32 {
        return (to_f32(bits >> 16) + 0.5) / 65536.0;
    }

    /// A reused pick's two grid cells (see [`grid_coordinate`]) from two
    /// hashes: `h1`'s high 16 bits high, `h2`'s high 16 bits low.
    pub fn grid_cells(h1: u32, h2: u32) -> u32 {
        return (h1 & 4294901760) | (h2 >> 16);
    }

    /// The offset of a neighbour drawn uniformly in a disk of radius `r`
    /// by `u1, u2 ∈ [0, 1)`: `r √u1 (cos 2πu2, sin 2πu2)`.
    pub fn disk_offset(r: f32, u1: f32, u2: f32) -> vec2f {
        let a: f32 = TWO_PI * u2;
        return vec2f(cos(a), sin(a)) * (r * sqrt(u1));
    }

    /// The weight a reused pick enters a combined reservoir with
    /// (generalized RIS, Lin et al. 2022, eq. 9, with the generalized
    /// balance heuristic): its domain's share `own / all` of the targets
    /// `all = Σₖ cₖ p̂ₖ(y)` of every domain combined, at `y` (`own` its own
    /// domain's term `c p̂(y)`), times the target here `p_hat` = `p̂(y)` and its
    /// unbiased contribution weight `w`. 0 where `all` is 0 (no domain
    /// could have drawn `y`). The shares sum to 1 over the domains that
    /// can draw `y`, so the combination is unbiased whatever each domain's
    /// confidence `c`.
    pub fn gris_weight(own: f32, all: f32, p_hat: f32, w: f32) -> f32 {
        if !(all > 0.0) {
            return 0.0;
        }
        return own / all * p_hat * w;
    }

    /// How strongly a reused sample's domain term counts is the domain's
    /// confidence times this: `|h|² / (|h|² + s·|h − t|²)` with `s` =
    /// [`REUSE_TRUST_SCALE`], `h = y − x` the sample's connection from this
    /// surface to its light point and `t = y − x₋` the same from the
    /// domain's surface: 1 where the surfaces are one, ½ where the surface
    /// moved an eighth of the light's distance. Reuse shifts a pick to this
    /// pixel unchanged (the identity shift); where the camera moved, the
    /// domain's surface is another pixel's, and its target differs most
    /// from this pixel's for the nearest lights, which its picks then
    /// stand for badly. Any confidence keeps generalized RIS unbiased, a
    /// sample's too (the balance heuristic's shares still sum to 1,
    /// [`gris_weight`]); this one gives the record's own candidates the
    /// share of the picks whose connection changed. (Counting a light's own
    /// motion the same way raised the error where lights jitter: 0.132 to
    /// 0.165 in slc's shadow test, plain reuse.) 1 for a connection of no
    /// length.
    pub fn reuse_trust(h: vec3f, t: vec3f) -> f32 {
        let d2: f32 = dot(h, h);
        if !(d2 > 0.0) {
            return 1.0;
        }
        let c: vec3f = h - t;
        return d2 / (d2 + REUSE_TRUST_SCALE * dot(c, c));
    }

    /// [`reuse_trust`]'s scale: measured in slc's Cornell shadow test with
    /// the camera panning a pixel a frame at 64×48 (one frame's relative
    /// RMSE, 3 picks with visibility reuse: 0.281 with no trust, 0.226 at
    /// 16, 0.217 at 64, 0.213 at 256, 0.207 at 1,024), the middle of the
    /// curve.
    pub const REUSE_TRUST_SCALE: f32 = 64.0;

    /// The unbiased contribution weight of a combined reservoir's pick of
    /// target `p_hat`: `Σw / p̂(y)`, 0 without a pick.
    pub fn gris_contribution_weight(w_sum: f32, p_hat: f32) -> f32 {
        if !(p_hat > 0.0) {
            return 0.0;
        }
        return w_sum / p_hat;
    }

    /// Walker's alias method's second choice: the table column `column`
    /// (drawn by [`uniform_light`]) keeps its own index when `u < keep`
    /// (its probability of staying) and gives its alias `other` otherwise;
    /// `u` uniform in `[0, 1)`.
    pub fn alias_choice(column: u32, other: u32, keep: f32, u: f32) -> u32 {
        return select(other, column, u < keep);
    }

    /// Light `⌊u·n⌋` (at most `n − 1`) of `n > 0`, for uniform `u ∈ [0, 1)`:
    /// the uniform one-light pick, each light with probability `1/n`.
    pub fn uniform_light(u: f32, n: u32) -> u32 {
        return min(to_u32(u * to_f32(n)), n - 1);
    }
}

/// Algorithm R with `K` slots.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Reservoir<const K: usize> {
    slots: [u32; K],
    n: u32,
}

impl<const K: usize> Default for Reservoir<K> {
    fn default() -> Self {
        Self { slots: [0; K], n: 0 }
    }
}

impl<const K: usize> Reservoir<K> {
    const K32: u32 = {
        assert!(K > 0 && K < u32::MAX as usize);
        K as u32
    };

    /// An empty reservoir.
    pub fn new() -> Self {
        Self::default()
    }

    /// Offers `item` with 64 random bits `(hi, lo)`. After `u32::MAX`
    /// candidates the count saturates and further items are ignored.
    pub fn push(&mut self, item: u32, hi: u32, lo: u32) {
        if !reservoir_takes(self.n) {
            return;
        }
        self.n += 1;
        let s = reservoir_slot(self.n, Self::K32, hi, lo);
        if s < Self::K32 {
            self.slots[s as usize] = item;
        }
    }

    /// Candidates seen.
    pub fn seen(&self) -> u32 {
        self.n
    }

    /// The held items (`min(n, K)` of them).
    pub fn picks(&self) -> &[u32] {
        &self.slots[..(self.n as usize).min(K)]
    }

    /// Weight of each held item, `max(n/K, 1)`.
    pub fn weight(&self) -> f32 {
        reservoir_weight(self.n, Self::K32)
    }
}

/// One weighted one-slot reservoir's step in the threshold form
/// ([`weighted_threshold`]), for the CPU's reservoirs: `true` when the
/// running sum `sum` (this candidate's weight included) passes
/// `*threshold`, the slot taking the candidate; then `u()` draws the next
/// threshold's uniform. (WGSL's `next_threshold` is the kernels' twin.)
#[inline]
pub fn threshold_takes(sum: f32, threshold: &mut f32, u: impl FnOnce() -> f32) -> bool {
    if sum <= *threshold {
        return false;
    }
    *threshold = weighted_threshold(sum, u());
    true
}

/// `K` independent one-slot weighted reservoirs, in the threshold form
/// ([`weighted_threshold`]: a slot draws a number only when it takes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WeightedReservoir<const K: usize> {
    slots: [(u32, f32); K],
    /// Each slot's threshold on the running sum (0 while empty).
    thresholds: [f32; K],
    w_sum: f32,
}

impl<const K: usize> Default for WeightedReservoir<K> {
    fn default() -> Self {
        Self { slots: [(0, 0.0); K], thresholds: [0.0; K], w_sum: 0.0 }
    }
}

impl<const K: usize> WeightedReservoir<K> {
    /// An empty reservoir.
    pub fn new() -> Self {
        Self::default()
    }

    /// Offers `item` with importance `w` (finite, `> 0`; others are
    /// ignored); a slot that takes it calls `u` for its next threshold's
    /// uniform in `[0, 1)`.
    pub fn push(&mut self, item: u32, w: f32, mut u: impl FnMut() -> f32) {
        if !(w > 0.0 && w.is_finite()) {
            return;
        }
        self.w_sum += w;
        for (slot, threshold) in self.slots.iter_mut().zip(&mut self.thresholds) {
            if threshold_takes(self.w_sum, threshold, &mut u) {
                *slot = (item, w);
            }
        }
    }

    /// Sum of offered weights `W`.
    pub fn total_weight(&self) -> f32 {
        self.w_sum
    }

    /// Each slot's item and its weight `W/(K·wᵢ)`; empty before any push.
    pub fn picks(&self) -> impl Iterator<Item = (u32, f32)> + '_ {
        let w = self.w_sum;
        self.slots
            .iter()
            .filter(move |_| w > 0.0)
            .map(move |&(i, wi)| (i, weighted_pick_weight(w, wi, K as u32)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every channel's shares sum to 1 over the slots, and a slot's share
    /// lies in the channel its target is.
    #[test]
    fn slot_shares_cover_every_channel_once() {
        let c = vec3f(1.0, 2.0, 3.0);
        for k in 1..=9u32 {
            let mut sum = vec3f(0.0, 0.0, 0.0);
            for q in 0..k {
                let share = slot_share(q, k);
                sum += share;
                let t = slot_target(c, q, k);
                if k >= 3 {
                    assert_eq!(share.dot(c) / share.max_element(), t, "k {k}, slot {q}");
                } else {
                    assert_eq!(t, resample_target(c));
                }
            }
            assert!((sum - vec3f(1.0, 1.0, 1.0)).abs().max_element() < 1e-6, "k {k}: {sum}");
        }
    }

    /// The threshold form of the one-slot reservoir ([`WeightedReservoir`])
    /// keeps candidate `i` with probability `w_i/W` (zero weights never),
    /// as [`weighted_replace`] does, and takes `Σ w_i/W_i` candidates on
    /// average, drawing one number per take: 200,000 fixed-seed one-slot
    /// reservoirs over ten weights, each frequency within 5 standard
    /// deviations of its probability.
    #[test]
    fn threshold_slot_keeps_each_candidate_by_its_weight() {
        use crate::xi::{pcg_hash, xi_from_bits};
        let w = [0.5f32, 0.0, 3.0, 1.0, 0.25, 0.0, 2.0, 8.0, 0.125, 1.5];
        let total: f32 = w.iter().sum();
        let trials = 200_000u32;
        let (mut kept, mut takes) = ([0u32; 10], 0u64);
        let mut h = 0x5eed;
        for _ in 0..trials {
            let mut r = WeightedReservoir::<1>::new();
            for (i, &wi) in w.iter().enumerate() {
                r.push(i as u32, wi, || {
                    takes += 1;
                    h = pcg_hash(h);
                    xi_from_bits(h)
                });
            }
            for (i, _) in r.picks() {
                kept[i as usize] += 1;
            }
        }
        for (i, &wi) in w.iter().enumerate() {
            let p = (wi / total) as f64;
            let f = kept[i] as f64 / trials as f64;
            let sd = (p * (1.0 - p) / trials as f64).sqrt();
            assert!((f - p).abs() <= 5.0 * sd + 1e-12, "candidate {i}: {f} against {p}");
        }
        // Expected takes: Σ w_i/W_i over the positive weights (the first 1).
        let mut sum = 0.0f64;
        let expected: f64 = w
            .iter()
            .filter(|&&wi| wi > 0.0)
            .map(|&wi| {
                sum += wi as f64;
                wi as f64 / sum
            })
            .sum();
        let mean = takes as f64 / trials as f64;
        assert!((mean - expected).abs() < 0.02, "takes per slot {mean} against {expected}");
    }

    #[test]
    fn reuse_grid_and_weights() {
        // The grid's cells are midpoints inside (0, 1), kept bit for bit
        // through a stored pick's two cells.
        assert_eq!(grid_coordinate(0), 0.5 / 65536.0);
        assert_eq!(grid_coordinate(u32::MAX), 1.0 - 0.5 / 65536.0);
        let cells = grid_cells(0xabcd_1234, 0x5678_9999);
        assert_eq!(cells, 0xabcd_5678);
        assert_eq!(grid_coordinate(cells), grid_coordinate(0xabcd_1234));
        assert_eq!(grid_coordinate(cells << 16), grid_coordinate(0x5678_9999));
        // The balance heuristic's shares sum to 1 over the domains.
        let terms = [0.3f32, 1.2, 0.5];
        let all: f32 = terms.iter().sum();
        let shares: f32 = terms.iter().map(|&t| gris_weight(t, all, 1.0, 1.0)).sum();
        assert!((shares - 1.0).abs() < 1e-6);
        assert_eq!(gris_weight(1.0, 0.0, 1.0, 1.0), 0.0, "no domain can draw it");
        assert_eq!(gris_contribution_weight(3.0, 0.0), 0.0);
        assert_eq!(gris_contribution_weight(3.0, 2.0), 1.5);
        // A connection the same at both surfaces keeps its confidence; one
        // changed by an eighth of its length keeps half; none of no length
        // loses it.
        let h = vec3f(0.0, 2.0, 0.0);
        assert_eq!(reuse_trust(h, h), 1.0);
        assert!((reuse_trust(h, h + vec3f(0.25, 0.0, 0.0)) - 0.5).abs() < 1e-6);
        assert!(reuse_trust(h, h * 2.0) < reuse_trust(h, h * 1.5));
        assert_eq!(reuse_trust(vec3f(0.0, 0.0, 0.0), h), 1.0);
        // Disk offsets stay inside the radius and reach its edge.
        let edge = disk_offset(4.0, 0.999_999, 0.25);
        assert!(edge.length() <= 4.0 && edge.length() > 3.99 && edge.y > 3.99);
    }

    #[test]
    fn mul_hi_matches_u64() {
        let vals = [0u32, 1, 2, 65535, 65536, 0x1234_5678, 0xdead_beef, u32::MAX - 1, u32::MAX];
        for &a in &vals {
            for &b in &vals {
                assert_eq!(mul_hi_u32(a, b), ((a as u64 * b as u64) >> 32) as u32, "{a} {b}");
            }
        }
    }

    #[test]
    fn uniform_index_matches_u128_reference() {
        let ns = [1u32, 2, 3, 1000, 1 << 24, u32::MAX - 1, u32::MAX];
        let bits = [
            (0u32, 0u32),
            (u32::MAX, u32::MAX),
            (0x8000_0000, 0),
            (0x1234_5678, 0x9abc_def0),
            (u32::MAX, 0),
        ];
        for &n in &ns {
            for &(hi, lo) in &bits {
                let r = ((((hi as u128) << 32 | lo as u128) * n as u128) >> 64) as u32;
                let j = uniform_index(n, hi, lo);
                assert_eq!(j, r, "n {n} hi {hi} lo {lo}");
                assert!(j < n);
            }
        }
    }

    #[test]
    fn n_near_u32_max() {
        // The slot draw stays in range and the weight is finite.
        let n = u32::MAX;
        assert_eq!(reservoir_slot(n, 8, u32::MAX, u32::MAX), 8);
        assert_eq!(reservoir_slot(n, 8, 0, 0), 0);
        let w = reservoir_weight(n, 8);
        assert!((w as f64 - n as f64 / 8.0).abs() / (n as f64 / 8.0) < 1e-7);
        // P(j < k) = k/n to within 2^-64·n relative.
        let k = 8u32;
        let threshold_hi = ((k as u128) << 64).div_ceil(n as u128) >> 32;
        assert!(uniform_index(n, threshold_hi as u32 - 1, u32::MAX) < k);
        assert!(uniform_index(n, threshold_hi as u32 + 1, 0) >= k);
        let mut r = Reservoir::<2>::new();
        r.n = u32::MAX - 1;
        r.push(7, 0, 0);
        assert_eq!(r.seen(), u32::MAX);
        r.push(9, 0, 0);
        assert_eq!(r.seen(), u32::MAX);
        assert_eq!(r.picks(), &[7, 0]);
    }
}
