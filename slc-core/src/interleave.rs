//! Interleaved sampling of the VPL application (Keller & Heidrich,
//! "Interleaved Sampling", EGWR 2001; Segovia et al. 2006): the VPLs of an
//! `s × s` reflective shadow map split into `P × P` subsets by texel
//! position mod `P`, pixel `(x, y)` shades with subset
//! `(y mod P)·P + x mod P` only, its flux scaled by `P²`. Where a VPL goes
//! in the subset-after-subset light buffer is written here once, for the
//! host upload and the GPU's VPL generation alike.
//!
//! **Near-field split.** A VPL a few centimetres from a receiver carries a
//! transfer so large that giving it to one pixel in `P²` (×`P²`) leaves a
//! `P × P` blotch the denoise cannot average where the surface is only a
//! few pixels wide (the floor's VPLs at the base of a wall). So every pixel
//! shades the VPLs closer than a near radius `R_n` itself, from every subset
//! at their own flux, and its interleaved subset skips them, with a smooth
//! partition of unity between ([`vpl_near_weight`]): each VPL's transfer is
//! still counted exactly once per pixel (near) or once per `P × P` window
//! at `P²` times its flux (far), so the split changes no expectation.
//!
//! **Culling order.** Both fields are culled through the box hierarchy of
//! [`crate::cluster`]: the far field's light buffer holds each subset's
//! image in map order ([`interleave_slot`]), the near field's index lists
//! the whole map in map order ([`crate::cluster::map_index`] on the RSM),
//! so every cluster is an 8×8 patch of texels and every group 64×64.
//!
//! **A shifted map per frame.** A fixed pixel-to-subset map is a
//! structured subsampling: the RSM's texel grid and the screen's pixel
//! grid line up on flat surfaces, so a subset's VPLs sit nearer to the
//! pixels of their own class than to the others, and the image keeps an
//! offset no number of frames removes (−0.30% of the Cornell box's mean
//! irradiance at 256², 65,536 VPLs, unculled). So each frame shifts the
//! map: pixel class `c` shades subset `(c + k) mod P²`
//! ([`shifted_subset`]), `k` = [`interleave_shift`]`(seed, frame)`,
//! uniform and stratified over frames (frames `0..P²` take every shift
//! once). Over frames each pixel shades every subset equally often: the
//! interleaved estimator is unbiased per pixel, as the culling is, and its
//! residual pattern changes every frame. The slots, the clusters and
//! the denoise's window (one pixel of every class, so of every subset)
//! are unchanged.

use crate::cluster::{CLUSTER, map_index};
use crate::light::{INV_PI, MAX_INTENSITY};
use crate::range::{clamp_keep, slc_keep, slc_weight};
use crate::ray::finite3;
use crate::wgsl::builtins::{clamp, max, min, select, to_f32};
use crate::wgsl::vec3f;
use crate::xi::{laine_karras, pcg_hash};

crate::shared! {
    /// Subset of pixel (or RSM texel) `(x, y)` for period `P > 0`:
    /// `(y mod P)·P + x mod P`.
    pub fn interleave_subset(x: u32, y: u32, period: u32) -> u32 {
        return (y % period) * period + x % period;
    }

    /// The VPL subset that pixels of class `pixel_class`
    /// ([`interleave_subset`]) shade in a frame whose map is shifted by
    /// `shift` ([`interleave_shift`]): `(pixel_class + shift) mod P²`.
    pub fn shifted_subset(pixel_class: u32, shift: u32, period: u32) -> u32 {
        return (pixel_class + shift) % (period * period);
    }

    /// `true` when a VPL handed over as raw numbers (an engine's RSM texel
    /// or VPL record) is one [`Vpl::new`](crate::light::Vpl::new) would accept: finite position and
    /// normal, and a flux whose channels are finite, ≥ 0 and give a peak
    /// `Φ/π` of at most [`MAX_INTENSITY`]. The GPU's packing gives any
    /// other VPL zero flux at the origin (skipped: never a NaN or ∞ pixel).
    pub fn vpl_record_ok(position: vec3f, normal: vec3f, flux: vec3f) -> bool {
        if !(finite3(position) && finite3(normal) && finite3(flux)) {
            return false;
        }
        return flux.x >= 0.0 && flux.y >= 0.0 && flux.z >= 0.0 && max(max(flux.x, flux.y), flux.z) * INV_PI <= MAX_INTENSITY;
    }

    /// The side of one interleaved subset's image of an `s × s` map
    /// (`s` a multiple of `P`) in the light buffer: `s/P` padded to a
    /// multiple of 8, so its map order ([`crate::cluster::map_index`]) has
    /// whole 8×8 clusters; the padding holds no VPL.
    pub fn subset_side(size: u32, period: u32) -> u32 {
        return (size / period + 7) / 8 * 8;
    }

    /// Index of RSM texel `(tx, ty)` of an `s × s` map (`s` a multiple of
    /// `P > 0`) in the light buffer that stores subset after subset, each
    /// subset's image `(tx / P, ty / P)` in map order on its padded side
    /// `m` ([`subset_side`]): `subset · m² + map_index(tx/P, ty/P, m)`.
    /// A subset's clusters and groups ([`crate::cluster`]) are then runs of
    /// consecutive slots.
    pub fn interleave_slot(tx: u32, ty: u32, size: u32, period: u32) -> u32 {
        let side: u32 = subset_side(size, period);
        return interleave_subset(tx, ty, period) * side * side + map_index(tx / period, ty / period, side);
    }

    /// Slots per subset of a list of `count` VPLs (a multiple of `P²`, no
    /// RSM position): `count / P²` padded to whole clusters of
    /// [`CLUSTER`]; the padding holds no VPL.
    pub fn subset_slots_linear(count: u32, period: u32) -> u32 {
        let per: u32 = count / (period * period);
        return (per + CLUSTER - 1) / CLUSTER * CLUSTER;
    }

    /// Index of VPL `i` of a list (no RSM position) in the same buffer,
    /// `per_subset` slots per subset ([`subset_slots_linear`]): subset
    /// `i mod P²`, entry `i / P²` in it.
    pub fn interleave_slot_linear(i: u32, per_subset: u32, period: u32) -> u32 {
        let subsets: u32 = period * period;
        return (i % subsets) * per_subset + i / subsets;
    }

    /// Flux scale of an interleaved VPL, `P²` for period `P`: a pixel
    /// shades one subset of `P²`, so each of its VPLs stands for `P²`
    /// (the near field, shaded by every pixel, undoes it).
    pub fn interleave_flux_scale(period: u32) -> f32 {
        return to_f32(period * period);
    }

    /// The near-field split's share of a VPL at squared distance `d²` from
    /// the receiver: `w = smoothstep(t)`, `t = clamp((R_n² − d²)/(¾R_n²),
    /// 0, 1)`, so 1 within `R_n/2`, 0 from `R_n` on. The pixel shades `w·T`
    /// itself at the VPL's own flux and its interleaved subset `(1 − w)·T`
    /// at `P²` times it: the two parts sum to `T` at every pixel, and each is
    /// smooth in the receiver's position, so the denoise that averages
    /// neighbours' far parts meets no edge at `R_n`. `R_n = 0`: `w = 0`.
    pub fn vpl_near_weight(d2: f32, near_r2: f32) -> f32 {
        if near_r2 <= 0.0 {
            return 0.0;
        }
        let t: f32 = clamp((near_r2 - d2) / (0.75 * near_r2), 0.0, 1.0);
        return t * t * (3.0 - 2.0 * t);
    }

    /// The interleaved (far) field's share `1 − w` of the same VPL
    /// ([`vpl_near_weight`]); 1 without a split.
    pub fn vpl_far_weight(d2: f32, near_r2: f32) -> f32 {
        return 1.0 - vpl_near_weight(d2, near_r2);
    }

    /// The interleaved (far) field's weight of one VPL under stochastic
    /// light culling (its light's `r_t²`, `r²` at `P²` times the flux): the
    /// far share `1 − w` ([`vpl_far_weight`]) over the roulette
    /// probability, `(1 − w) · max(d²/r_t², 1)`, where `d² < r²` and
    /// `1 − w > 0`, else 0 (culled).
    pub fn vpl_far_slc_share(rt2: f32, r2: f32, d2: f32, near_r2: f32) -> f32 {
        let f: f32 = vpl_far_weight(d2, near_r2);
        return select(0.0, f * slc_weight(rt2, d2), slc_keep(r2, d2) & (f > 0.0));
    }

    /// The far field's weight of one VPL under a fixed range (the clamp
    /// method's `R²`, or `∞` unculled): its far share `1 − w` where
    /// `d² < R²` and `1 − w > 0`, else 0.
    pub fn vpl_far_fixed_share(range2: f32, d2: f32, near_r2: f32) -> f32 {
        let f: f32 = vpl_far_weight(d2, near_r2);
        return select(0.0, f, clamp_keep(range2, d2) & (f > 0.0));
    }

    /// A VPL's squared range (`r²` or `r_t²`) at its own flux, for the near
    /// field, from its interleaved light's (flux × `P²`): `r²/P²`. `r_t²`
    /// is linear in the flux ([`crate::light::vpl_rt2`]) and `r² = r_t²/(1 − ξ)`,
    /// so this is the range of the VPL's own flux with the *same* ξ; for a
    /// power-of-two `P` the division is exact, so it equals the range
    /// computed from the unscaled flux bit for bit.
    pub fn vpl_near_range2(r2: f32, period: u32) -> f32 {
        return r2 / interleave_flux_scale(period);
    }

    /// Squared radius of a near-field light's culling sphere: `min(r², R_n²)`,
    /// the light's own range `r²` ([`vpl_near_range2`], or a clamp range)
    /// cut at the near radius, beyond which its near share is 0.
    pub fn vpl_near_cull_range2(r2: f32, near_r2: f32) -> f32 {
        return min(r2, near_r2);
    }

    /// The culled near field's weight of one VPL (stochastic light culling
    /// at the VPL's own flux): its near share `w` ([`vpl_near_weight`])
    /// over the roulette probability, `w · max(d²/r_t², 1)`, where the
    /// keep test `d² < r²` passes and `w > 0`, else 0 (a light it culls).
    /// `r_t²`, `r²` are the VPL's own ([`vpl_near_range2`]). Over ξ its
    /// expectation is `w` (`P(d² < r²) = min(r_t²/d², 1)`), so the culled
    /// near field is unbiased, and the partition `w + (1 − w)` stays smooth.
    pub fn vpl_near_slc_share(rt2: f32, r2: f32, d2: f32, near_r2: f32) -> f32 {
        let w: f32 = vpl_near_weight(d2, near_r2);
        return select(0.0, w * slc_weight(rt2, d2), slc_keep(r2, d2) & (w > 0.0));
    }

    /// The near field's weight of one VPL under a fixed range (the clamp
    /// method's `R²`, or `∞` unculled): its near share `w` where
    /// `d² < R²` and `w > 0`, else 0.
    pub fn vpl_near_fixed_share(range2: f32, d2: f32, near_r2: f32) -> f32 {
        let w: f32 = vpl_near_weight(d2, near_r2);
        return select(0.0, w, clamp_keep(range2, d2) & (w > 0.0));
    }
}

/// Random stream of [`interleave_shift`] (xored into the seed).
const SHIFT_STREAM: u32 = 0x5bd1_e995;

/// The shift `k ∈ 0..P²` of frame `frame`'s pixel-to-subset map
/// ([`shifted_subset`]) for seed `seed`: the top bits of an Owen-scrambled
/// van der Corput point of the frame index, as [`crate::xi::xi_for`]
/// draws ξ, `LK(rev(frame), s) ⊕ LK(0, s) ⊕ h(s)` with `s = h(seed ⊕
/// c)` (`LK` [`laine_karras`], `h` [`pcg_hash`]), times `P²`. Uniform in
/// every frame; frames `0..P²` (and every later run of `P²` frames from
/// a multiple of `P²`) take each shift once. Both backends' hosts call it.
pub fn interleave_shift(seed: u32, frame: u32, period: u32) -> u32 {
    let s = pcg_hash(seed ^ SHIFT_STREAM);
    let v = laine_karras(frame.reverse_bits(), s) ^ laine_karras(0, s) ^ pcg_hash(s);
    ((v as u64 * (period * period) as u64) >> 32) as u32
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    /// Frames `0..P²`, and `P²..2P²`, take each shift once, for any seed;
    /// seeds give frame 0 different shifts.
    #[test]
    fn shifts_are_stratified_over_frames() {
        for seed in [0u32, 1, 7, 0xdead_beef] {
            for block in 0..2u32 {
                let mut seen = [false; 64];
                for f in 0..64 {
                    let k = interleave_shift(seed, block * 64 + f, 8) as usize;
                    assert!(!seen[k], "seed {seed}: shift {k} twice in frames {}..", block * 64);
                    seen[k] = true;
                }
            }
        }
        let first: alloc::collections::BTreeSet<u32> =
            (0..32).map(|seed| interleave_shift(seed, 0, 8)).collect();
        assert!(first.len() > 10, "frame 0's shift must depend on the seed: {first:?}");
        assert_eq!(interleave_shift(3, 5, 1), 0);
        assert_eq!(shifted_subset(60, 7, 8), 3);
    }

    /// The slots of an `s × s` map are distinct, each subset holds
    /// exactly the texels congruent to it mod `P`, and each cluster of
    /// slots is an 8×8 patch of its subset's image; padded sides (`s/P`
    /// not a multiple of 8) leave slots free.
    #[test]
    fn slots_are_distinct_grouped_by_subset_in_patches() {
        for (s, p) in [(128u32, 8u32), (72, 8), (64, 1), (16, 2)] {
            let m = subset_side(s, p);
            let per = m * m;
            let mut seen = vec![false; (per * p * p) as usize];
            for ty in 0..s {
                for tx in 0..s {
                    let slot = interleave_slot(tx, ty, s, p);
                    assert!(!seen[slot as usize], "slot {slot} twice");
                    seen[slot as usize] = true;
                    assert_eq!(slot / per, interleave_subset(tx, ty, p));
                    let q = slot % per;
                    assert_eq!(
                        (crate::cluster::map_x(q, m), crate::cluster::map_y(q, m)),
                        (tx / p, ty / p)
                    );
                }
            }
            let used = seen.iter().filter(|&&b| b).count() as u32;
            assert_eq!(used, s * s);
        }
        assert_eq!(subset_side(72, 8), 16);
        assert_eq!(subset_slots_linear(64 * 65, 8), 128);
        assert_eq!(interleave_slot_linear(64 + 3, 128, 8), 3 * 128 + 1);
    }

    /// The near field's split weight.
    #[test]
    fn near_weight_is_a_smooth_partition() {
        assert_eq!(vpl_near_weight(0.25, 1.0), 1.0);
        assert_eq!(vpl_near_weight(0.0, 1.0), 1.0);
        assert_eq!(vpl_near_weight(1.0, 1.0), 0.0);
        assert_eq!(vpl_near_weight(0.0, 0.0), 0.0);
        let mid = vpl_near_weight(0.625, 1.0);
        assert!((mid - 0.5).abs() < 1e-6, "{mid}");
    }
}
