//! Interleaved sampling of the VPL application (Keller & Heidrich,
//! "Interleaved Sampling", EGWR 2001; Segovia et al. 2006): the VPLs of an
//! `s × s` reflective shadow map split into `P × P` subsets by texel
//! position mod `P`, pixel `(x, y)` shades with subset
//! `(y mod P)·P + x mod P` only, its flux scaled by `P²`. Where a VPL goes
//! in the subset-after-subset light buffer is written here once, for the
//! host upload and the GPU's VPL generation alike.

crate::shared! {
    /// Subset of pixel (or RSM texel) `(x, y)` for period `P > 0`:
    /// `(y mod P)·P + x mod P`.
    pub fn interleave_subset(x: u32, y: u32, period: u32) -> u32 {
        return (y % period) * period + x % period;
    }

    /// Index of RSM texel `(tx, ty)` of an `s × s` map (`s` a multiple of
    /// `P > 0`) in the light buffer that stores subset after subset, each
    /// subset row-major in `(tx / P, ty / P)`: `subset · (s/P)² +
    /// (ty/P)·(s/P) + tx/P`.
    pub fn interleave_slot(tx: u32, ty: u32, size: u32, period: u32) -> u32 {
        let side: u32 = size / period;
        return interleave_subset(tx, ty, period) * side * side + (ty / period) * side + tx / period;
    }

    /// Index of VPL `i` of a list (no RSM position) in the same buffer, for
    /// `P² · per_subset` VPLs: subset `i mod P²`, entry `i / P²` in it.
    pub fn interleave_slot_linear(i: u32, per_subset: u32, period: u32) -> u32 {
        let subsets: u32 = period * period;
        return (i % subsets) * per_subset + i / subsets;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    /// The slots of an `s × s` map are a permutation, and each subset holds
    /// exactly the texels congruent to it mod `P`.
    #[test]
    fn slots_are_a_permutation_grouped_by_subset() {
        let (s, p) = (32u32, 8u32);
        let per = (s / p) * (s / p);
        let mut seen = vec![false; (s * s) as usize];
        for ty in 0..s {
            for tx in 0..s {
                let slot = interleave_slot(tx, ty, s, p);
                assert!(!seen[slot as usize], "slot {slot} twice");
                seen[slot as usize] = true;
                assert_eq!(slot / per, interleave_subset(tx, ty, p));
            }
        }
        assert!(seen.iter().all(|&b| b));
    }
}
