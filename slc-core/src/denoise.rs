//! The cross-bilateral (geometry-aware) filter weight of the VPL
//! application's denoise over the interleaving period (Segovia et al.,
//! "Non-interleaved Deferred Shading of Interleaved Sample Patterns",
//! Graphics Hardware 2006): neighbours count by normal and depth similarity,
//! so edges stay sharp. Both backends' filters call this one function.

use crate::wgsl::*;

crate::shared! {
    /// Depth given to a pixel without a surface: far beyond any scene, so
    /// its neighbours' relative depth test gives it weight 0.
    pub const DEPTH_NONE: f32 = 1e30;

    /// Relative depth tolerance σ of [`bilateral_weight`].
    pub const DEPTH_SIGMA: f32 = 0.05;

    /// Weight above which a neighbour counts as covering its VPL subset. A
    /// `P × P` window holds each subset once; where some are not covered
    /// (edges, corners, the image border) the filter widens to `2P × 2P`,
    /// else the mix of the covered subsets leaves a P-periodic pattern.
    pub const COVER_WEIGHT: f32 = 0.1;

    /// `1/(σ z)` for a pixel at depth `z`: the `inv_sz` of
    /// [`bilateral_weight`].
    pub fn inv_sigma_z(z: f32) -> f32 {
        return 1.0 / (DEPTH_SIGMA * z);
    }

    /// First column (or row) of the `size`-wide window around pixel
    /// coordinate `x`: `max(x − ⌊size/2⌋, 0)`.
    pub fn window_start(x: u32, size: u32) -> u32 {
        let half: u32 = size / 2;
        return max(x, half) - half;
    }

    /// One past the last column (or row) of that window in an image
    /// `extent` pixels wide: `min(x + size − ⌊size/2⌋, extent)`.
    pub fn window_end(x: u32, size: u32, extent: u32) -> u32 {
        return min(x + size - size / 2, extent);
    }

    /// The window the filter uses where the `P × P` one misses a VPL
    /// subset: `2P × 2P`.
    pub fn wide_window(period: u32) -> u32 {
        return 2 * period;
    }

    /// `true` when a `P × P` window with `covered` neighbours heavier than
    /// [`COVER_WEIGHT`] misses a VPL subset (fewer than `P²`), so the filter
    /// widens to [`wide_window`].
    pub fn misses_subset(covered: u32, period: u32) -> bool {
        return covered < period * period;
    }

    /// The filtered irradiance: the weighted mean `sum/weight`, or the
    /// pixel's own `e` where no neighbour weighs anything.
    pub fn filtered_irradiance(e: vec3f, sum: vec3f, weight: f32) -> vec3f {
        if weight > 0.0 {
            return sum / weight;
        }
        return e;
    }

    /// Weight of a neighbour with normal `nj` at depth `zj` for a pixel with
    /// normal `n` at depth `z`: `max(n·nj, 0)^16 · max(1 − δ², 0)²`,
    /// `δ = (zj − z)·inv_sz` with `inv_sz = 1/(σ z)` (a compact-support
    /// Tukey kernel in relative depth). A neighbour without a surface (depth
    /// [`DEPTH_NONE`], zero normal) gets weight 0.
    pub fn bilateral_weight(n: vec3f, nj: vec3f, z: f32, zj: f32, inv_sz: f32) -> f32 {
        let dn: f32 = max(dot(n, nj), 0.0);
        let dn2: f32 = dn * dn;
        let dn4: f32 = dn2 * dn2;
        let dn8: f32 = dn4 * dn4;
        let d: f32 = (zj - z) * inv_sz;
        let t: f32 = max(1.0 - d * d, 0.0);
        return dn8 * dn8 * t * t;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weight_is_one_for_equal_geometry_and_falls_off() {
        let n = vec3f(0.0, 1.0, 0.0);
        let inv = 1.0 / (DEPTH_SIGMA * 2.0);
        assert_eq!(bilateral_weight(n, n, 2.0, 2.0, inv), 1.0);
        // δ = 0.5: (1 − 0.25)² = 0.5625.
        assert!((bilateral_weight(n, n, 2.0, 2.05, inv) - 0.5625).abs() < 1e-5);
        // Beyond σ z, and for opposite or missing normals: nothing.
        assert_eq!(bilateral_weight(n, n, 2.0, 2.2, inv), 0.0);
        assert_eq!(bilateral_weight(n, vec3f(0.0, -1.0, 0.0), 2.0, 2.0, inv), 0.0);
        assert_eq!(bilateral_weight(n, vec3f(0.0, 0.0, 0.0), 2.0, 1e30, inv), 0.0);
        // cos 60° = 0.5: 0.5^16.
        let tilted = vec3f(0.0, 0.5, 0.75f32.sqrt());
        assert!((bilateral_weight(n, tilted, 2.0, 2.0, inv) - 0.5f32.powi(16)).abs() < 1e-9);
    }
}
