//! Random numbers ξ: one per light per frame (or per pass when progressive),
//! shared by every shading point (talk: "single random number for each
//! light"). Also the integer hash the GPU kernels use to draw them.

use crate::wgsl::*;
use rand_core::RngCore;

crate::shared! {
    /// `2⁻²⁴`, the spacing of the ξ lattice.
    pub const XI_STEP: f32 = 0.000000059604644775390625;

    /// Maps 32 random bits to `ξ = ⌊bits / 2⁸⌋ · 2⁻²⁴ ∈ [0, 1 − 2⁻²⁴]`: every
    /// value is exact in `f32`, uniform on the 2²⁴-point lattice, and never 1.
    pub fn xi_from_bits(bits: u32) -> f32 {
        return to_f32(bits >> 8) * XI_STEP;
    }

    /// PCG-RXS-M-XS 32-bit hash (Jarzynski & Olano, "Hash Functions for GPU
    /// Rendering", JCGT 2020): a stateless per-pixel/per-light random source.
    pub fn pcg_hash(x: u32) -> u32 {
        let state: u32 = add_wrap_u32(mul_lo_u32(x, 747796405), 2891336453);
        let word: u32 = mul_lo_u32((state >> ((state >> 28) + 4)) ^ state, 277803737);
        return (word >> 22) ^ word;
    }

    /// Burley's hash-based Laine–Karras permutation (B. Burley, "Practical
    /// Hash-based Owen Scrambling", JCGT 9(4), 2020): bit `k` of the result
    /// depends on bits `0..=k` of `x` and on `seed` only, and `x ↦ result` is
    /// a bijection. Applied to a bit-reversed index it is a nested uniform
    /// (Owen) shuffle of that index.
    pub fn laine_karras(x: u32, seed: u32) -> u32 {
        let mut v: u32 = add_wrap_u32(x, seed);
        v = v ^ mul_lo_u32(v, 1817228412);
        v = v ^ mul_lo_u32(v, 3090095698);
        v = v ^ mul_lo_u32(v, 3350193720);
        v = v ^ mul_lo_u32(v, 2367878886);
        return v;
    }

    /// ξ of light `light` in frame (or pass) `frame` for seed `seed`, from hashes
    /// alone, so every backend draws the same numbers without shared state,
    /// and stratified over frames:
    /// `xi_from_bits(o + (LK(rev(frame), s) ⊕ LK(0, s)) mod 2³²)` with the
    /// light's random offset `o = h(h(h(seed)) ⊕ light)`, its shuffle seed
    /// `s = h(o)`, `h` = [`pcg_hash`], `rev` the bit reversal and `LK`
    /// [`laine_karras`].
    ///
    /// `LK(rev(frame), s)` is the van der Corput point of the light's own
    /// Owen-shuffled frame index (Burley 2020, §4: shuffled, padded 1D
    /// sequences), xored with its frame-0 value (a digital shift, so frame 0
    /// is `xi_from_bits(o)`). In every frame each ξ is uniform and the
    /// lights' ξ are independent (the offsets are); over frames `0..2ᵐ` each
    /// light's ξ falls once in each of `2ᵐ` equal strata, so the image-wide
    /// error of a progressive average falls faster than `1/√frames`; and
    /// because each light visits its strata in its own nested random order,
    /// the lights' joint ξ over frames fill the unit cube as independent
    /// draws would. Without the shuffle (the rotation `o + rev(frame)` alone)
    /// every pair of lights kept the same ξ difference in every frame, and
    /// an estimate depending on several lights' ξ at once (slc-weighted's
    /// weighted pick, a reservoir with more candidates than slots, the
    /// direct pass's picks) converged, for a fixed seed, to the wrong value
    /// (2.5% seed-to-seed spread of the image mean at 512 and at 8,192
    /// passes on tools/mitsuba_compare.py's scene).
    pub fn xi_for(seed: u32, frame: u32, light: u32) -> f32 {
        let o: u32 = pcg_hash(pcg_hash(pcg_hash(seed)) ^ light);
        let s: u32 = pcg_hash(o);
        return xi_from_bits(add_wrap_u32(o, laine_karras(reverse_bits(frame), s) ^ laine_karras(0, s)));
    }

    /// The ξ a light takes in a frame: [`xi_for`]`(seed, frame, light)`,
    /// or `fixed` for every light where `fixed ≥ 0` (a fixed ξ in `[0, 1)`:
    /// not an estimator on its own, but averaging frames over a grid of
    /// fixed ξ is quadrature of the expectation over ξ, how the tests prove
    /// a pipeline unbiased; a negative `fixed` means none).
    pub fn frame_xi(seed: u32, frame: u32, light: u32, fixed: f32) -> f32 {
        if fixed >= 0.0 {
            return fixed;
        }
        return xi_for(seed, frame, light);
    }

    /// `⌊2³²/φ⌋`, the golden-ratio increment: xored into a point's stream it
    /// starts the independent stream that samples its picks, added to a pass
    /// index the one of its camera rays.
    pub const PICK_STREAM: u32 = 2654435769;

    /// Random stream of shading point `point` in frame (or pass, or path
    /// depth) `frame` for seed `seed`: `h(seed ⊕ h(point ⊕ h(frame)))`, `h` =
    /// [`pcg_hash`]. The traversal's reservoir draws from it.
    pub fn point_stream(seed: u32, point: u32, frame: u32) -> u32 {
        return pcg_hash(seed ^ pcg_hash(point ^ pcg_hash(frame)));
    }

    /// The stream that samples a point's picks (a position on each picked
    /// light), independent of the traversal's: `h(stream ⊕ PICK_STREAM)`
    /// for the point's [`point_stream`].
    pub fn pick_stream(stream: u32) -> u32 {
        return pcg_hash(stream ^ PICK_STREAM);
    }

    /// The stream that draws which previous-frame pixels a point's reuse
    /// reads (`which = 0`) and which reused pick each of its reservoirs
    /// keeps (`which = 1`), independent of its traversal's and picks':
    /// `h(h(stream ⊕ PICK_STREAM) + 1 + which)`.
    pub fn reuse_stream(stream: u32, which: u32) -> u32 {
        return pcg_hash(pick_stream(stream) + 1 + which);
    }

    /// Random stream of the path through pixel `pixel` in pass
    /// `pass_index`: its camera jitter, BSDF samples and roulette,
    /// `point_stream(seed, pixel, pass_index + PICK_STREAM)` (mod 2³²; apart
    /// from the connection streams, which take the path depth as frame).
    pub fn path_stream(seed: u32, pixel: u32, pass_index: u32) -> u32 {
        return point_stream(seed, pixel, add_wrap_u32(pass_index, PICK_STREAM));
    }

    /// Bit `k` of the result is bit `31 − k` of `x` (swaps of halves, bytes,
    /// nibbles, pairs and bits; WGSL's `reverseBits` has no MSL 1.x
    /// translation).
    pub fn reverse_bits(x: u32) -> u32 {
        let mut v: u32 = ((x >> 16) & 65535) | ((x & 65535) << 16);
        v = ((v >> 8) & 16711935) | ((v & 16711935) << 8);
        v = ((v >> 4) & 252645135) | ((v & 252645135) << 4);
        v = ((v >> 2) & 858993459) | ((v & 858993459) << 2);
        v = ((v >> 1) & 1431655765) | ((v & 1431655765) << 1);
        return v;
    }
}

/// Fills `out` with one ξ per light from `rng`, using [`xi_from_bits`].
pub fn fill_xi<R: RngCore + ?Sized>(rng: &mut R, out: &mut [f32]) {
    for x in out {
        *x = xi_from_bits(rng.next_u32());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Over frames `0..2ᵐ` a light's ξ falls once in each stratum; frame 0
    /// is the light's offset alone; within one frame the lights' ξ are
    /// uniform (16-bin histogram of 65,536 lights within 5σ of the binomial
    /// spread in every bin).
    #[test]
    fn xi_is_stratified_over_frames_and_uniform_within_one() {
        for light in [0u32, 1, 77, 65_535] {
            let mut hit = [false; 1024];
            for frame in 0..1024 {
                let s = (xi_for(9, frame, light) * 1024.0) as usize;
                assert!(!hit[s], "light {light} frame {frame}: stratum {s} twice");
                hit[s] = true;
            }
            assert_eq!(xi_for(9, 0, light), xi_from_bits(pcg_hash(pcg_hash(pcg_hash(9)) ^ light)));
        }
        for frame in [0u32, 1, 2, 1023, 0x8000_0000] {
            let mut bins = [0u32; 16];
            for light in 0..65_536 {
                bins[(xi_for(3, frame, light) * 16.0) as usize] += 1;
            }
            let (expect, sd) = (4096.0f64, (65_536.0f64 * (1.0 / 16.0) * (15.0 / 16.0)).sqrt());
            for b in bins {
                assert!((b as f64 - expect).abs() < 5.0 * sd, "frame {frame}: bins {bins:?}");
            }
        }
    }

    /// The lights' ξ over a seed's frames are jointly uniform, not tied to
    /// one another: for 32 pairs of lights the frame average of
    /// `[ξ_a < ξ_b]` over 4,096 frames is ½ within 5σ of independent draws
    /// (σ = ½/√4096), and the pairs fill an 8×8 grid (each cell within 5σ of
    /// its binomial count). The rotation `o + rev(frame)` alone kept
    /// `ξ_b − ξ_a` fixed, so the average was 0 or 1 and a quarter of the
    /// cells stayed empty.
    #[test]
    fn lights_xi_over_frames_are_jointly_uniform() {
        let frames = 4096u32;
        let sd = 0.5 / (frames as f64).sqrt();
        for pair in 0..32u32 {
            let (a, b) = (pair * 7919 % 65_536, pair * 104_729 % 65_536 + 1);
            let mut below = 0u32;
            let mut cells = [0u32; 64];
            for frame in 0..frames {
                let (xa, xb) = (xi_for(5, frame, a), xi_for(5, frame, b));
                below += (xa < xb) as u32;
                cells[(xa * 8.0) as usize * 8 + (xb * 8.0) as usize] += 1;
            }
            let mean = below as f64 / frames as f64;
            assert!(
                (mean - 0.5).abs() < 5.0 * sd,
                "lights {a}, {b}: P(xi_a < xi_b) over frames = {mean}"
            );
            let (expect, cell_sd) =
                (frames as f64 / 64.0, (frames as f64 / 64.0 * (63.0 / 64.0)).sqrt());
            for (i, &c) in cells.iter().enumerate() {
                assert!(
                    (c as f64 - expect).abs() < 5.0 * cell_sd,
                    "lights {a}, {b}: cell {i} holds {c}"
                );
            }
        }
    }

    /// Burley's reference: the permutation is a bijection whose bit `k`
    /// depends on bits `0..=k` only (so it nests: on the low `k` bits it is a
    /// permutation of `0..2ᵏ` for every seed).
    #[test]
    fn laine_karras_is_a_nested_permutation() {
        for seed in [0u32, 1, 0xdead_beef] {
            for k in [1u32, 4, 10] {
                let mask = (1u32 << k) - 1;
                let mut seen = [false; 1024];
                for x in 0..(1u32 << k) {
                    let low = laine_karras(x, seed) & mask;
                    assert!(!seen[low as usize], "seed {seed}, {k} bits: {low} twice");
                    seen[low as usize] = true;
                    assert_eq!(low, laine_karras(x | (x << k) | 0xf000_0000, seed) & mask);
                }
            }
        }
    }

    #[test]
    fn reverse_bits_matches_std() {
        for x in [0u32, 1, 2, 3, 0x8000_0000, 0x1234_5678, 0xdead_beef, u32::MAX] {
            assert_eq!(reverse_bits(x), x.reverse_bits(), "{x:#x}");
        }
    }

    #[test]
    fn lattice_ends() {
        assert_eq!(xi_from_bits(0), 0.0);
        assert_eq!(xi_from_bits(u32::MAX), 1.0 - XI_STEP);
        assert!(xi_from_bits(u32::MAX) < 1.0);
        assert_eq!(XI_STEP, 2f32.powi(-24));
    }

    #[test]
    fn pcg_hash_reference_values() {
        // Reference values computed with u64 arithmetic reduced mod 2^32.
        fn reference(x: u32) -> u32 {
            let state = ((x as u64 * 747796405 + 2891336453) & 0xffff_ffff) as u32;
            let word = ((((state >> ((state >> 28) + 4)) ^ state) as u64 * 277803737) & 0xffff_ffff)
                as u32;
            (word >> 22) ^ word
        }
        for x in [0u32, 1, 2, 12345, 0xdead_beef, u32::MAX] {
            assert_eq!(pcg_hash(x), reference(x));
        }
    }

    #[test]
    fn fill_xi_is_in_range_and_deterministic() {
        use rand_core::SeedableRng;
        let mut a = [0.0f32; 1000];
        let mut b = [0.0f32; 1000];
        fill_xi(&mut rand_pcg::Pcg32::seed_from_u64(7), &mut a);
        fill_xi(&mut rand_pcg::Pcg32::seed_from_u64(7), &mut b);
        assert_eq!(a, b);
        assert!(a.iter().all(|&x| (0.0..1.0).contains(&x)));
        let mean = a.iter().map(|&x| x as f64).sum::<f64>() / 1000.0;
        // σ of the mean of 1000 uniforms: sqrt(1/12/1000) ≈ 0.0091; 5σ.
        assert!((mean - 0.5).abs() < 0.046, "{mean}");
    }
}
