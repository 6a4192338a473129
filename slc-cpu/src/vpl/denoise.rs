//! Cross-bilateral (geometry-aware) filter over the interleaving period
//! (Segovia et al. 2006): each pixel averages the `P × P` window that holds
//! one pixel of every VPL subset, weighting neighbours by normal and depth
//! similarity so edges stay sharp. Filters irradiance, before albedo.
//!
//! Weights: slc-core's [`bilateral_weight`] (shared with the GPU's
//! `vpl_denoise` kernel). Where some neighbour of the `P × P` window
//! weighs no more than [`COVER_WEIGHT`], its VPL subset is missing from the
//! estimate (edges, corners, the image border), and the window doubles to
//! `2P × 2P`. Background pixels (depth ∞) get weight 0.
//!
//! Vectorization: the inputs are split once into SoA planes (irradiance,
//! normal, depth) and each pixel's `1/(σz)` is computed once. Interior
//! pixels are filtered 16 at a time along a row, one pixel per SIMD
//! lane: for every window offset the block's neighbours are consecutive in
//! memory, so each step is contiguous loads and branch-free lane math.
//! Pixels whose window the image border clips, and those that widen, take
//! the per-pixel path (window rows in chunks of 8 neighbours). Rows run in
//! parallel, each on the CPU's best [`SimdPath`]. The order of the
//! additions differs between the two paths and between instruction sets:
//! a few ulps of each weighted mean.

use crate::simd::SimdPath;
use glam::Vec3;
use rayon::prelude::*;
use slc_core::denoise::{
    COVER_WEIGHT, DEPTH_NONE, bilateral_weight, filtered_irradiance, inv_sigma_z, misses_subset,
    wide_window, window_end, window_start,
};
use slc_scene::vpl::GBuffer;

/// Neighbours per vectorized chunk of a window row in the per-pixel path:
/// a full row of the 8 × 8 window, and of the widened 16 × 16 one
/// ([`WIDE_LANES`]).
const LANES: usize = 8;
const WIDE_LANES: usize = 16;

/// Pixels filtered together in the interior path: one AVX-512 register of
/// f32, two AVX2 ones.
const BLOCK: usize = 16;

/// The filter's inputs as planes, one value per pixel.
#[derive(Default)]
struct Planes {
    /// The filtered signal.
    er: Vec<f32>,
    eg: Vec<f32>,
    eb: Vec<f32>,
    nx: Vec<f32>,
    ny: Vec<f32>,
    nz: Vec<f32>,
    /// Depth, [`DEPTH_NONE`] where no surface.
    z: Vec<f32>,
    /// `1/(σ z)` ([`inv_sigma_z`]) of each pixel as a window's centre.
    inv: Vec<f32>,
    w: usize,
    h: usize,
    period: u32,
}

/// The cross-bilateral filter with its planes kept between frames: the
/// G-buffer's (normals, depth, `1/(σz)`) split once per G-buffer
/// ([`Denoiser::set_gbuffer`]), the signal's written into the same memory
/// every call. [`crate::vpl::VplContext`] keeps one.
#[derive(Default)]
pub struct Denoiser {
    planes: Planes,
}

impl Denoiser {
    /// A filter for `gb`'s pixels.
    pub fn new(gb: &GBuffer) -> Denoiser {
        let mut d = Denoiser::default();
        d.set_gbuffer(gb);
        d
    }

    /// Splits a new G-buffer's normals and depths into the kept planes.
    pub fn set_gbuffer(&mut self, gb: &GBuffer) {
        let p = &mut self.planes;
        (p.w, p.h) = (gb.width as usize, gb.height as usize);
        for (plane, c) in [(&mut p.nx, 0), (&mut p.ny, 1), (&mut p.nz, 2)] {
            plane.resize(gb.normal.len(), 0.0);
            plane.par_iter_mut().zip(&gb.normal).for_each(|(o, n)| *o = n[c]);
        }
        // DEPTH_NONE stands for "no surface": every δ to it is huge, weight 0.
        p.z.resize(gb.depth.len(), 0.0);
        p.z.par_iter_mut()
            .zip(&gb.depth)
            .for_each(|(o, &d)| *o = if d.is_finite() { d } else { DEPTH_NONE });
        p.inv.resize(gb.depth.len(), 0.0);
        p.inv.par_iter_mut().zip(&p.z).for_each(|(o, &z)| *o = inv_sigma_z(z));
    }

    /// The far field of a split signal filtered, the near field added
    /// back: `filter(e − near) + near` (the filter of `e` when `near` is
    /// empty), with a `period × period` window on the CPU's best
    /// [`SimdPath`]. `gb` is the G-buffer of the last
    /// [`Denoiser::set_gbuffer`] (one of another size is split first).
    pub fn filter_far(
        &mut self,
        e: &[Vec3],
        near: &[Vec3],
        gb: &GBuffer,
        period: u32,
    ) -> Vec<Vec3> {
        self.filter_on(SimdPath::best(), e, near, gb, period)
    }

    /// [`Denoiser::filter_far`] on a chosen [`SimdPath`] (the baseline where
    /// the CPU lacks it).
    pub fn filter_on(
        &mut self,
        path: SimdPath,
        e: &[Vec3],
        near: &[Vec3],
        gb: &GBuffer,
        period: u32,
    ) -> Vec<Vec3> {
        let mut out = e.to_vec();
        self.filter_in_place_on(path, &mut out, near, gb, period);
        out
    }

    /// [`Denoiser::filter_far`] written over `e` (one value per pixel of
    /// `gb`): a frame's irradiance needs no second buffer.
    pub fn filter_far_in_place(
        &mut self,
        e: &mut [Vec3],
        near: &[Vec3],
        gb: &GBuffer,
        period: u32,
    ) {
        self.filter_in_place_on(SimdPath::best(), e, near, gb, period);
    }

    /// The filter on `path`: the signal is copied into the planes first,
    /// then every pixel of `e` is written from them.
    fn filter_in_place_on(
        &mut self,
        path: SimdPath,
        e: &mut [Vec3],
        near: &[Vec3],
        gb: &GBuffer,
        period: u32,
    ) {
        self.load(e, near, gb, period);
        let planes = &self.planes;
        let w = planes.w.max(1);
        e.par_chunks_mut(w).enumerate().for_each(|(y, row)| {
            path.run(FilterRow { p: planes, gb, y, row: &mut *row });
            if !near.is_empty() {
                for (o, &n) in row.iter_mut().zip(&near[y * w..]) {
                    *o += n;
                }
            }
        });
    }

    /// Writes `e − near` (`e` where `near` is empty) into the signal's
    /// planes, after splitting `gb` if its size is not the planes'.
    fn load(&mut self, e: &[Vec3], near: &[Vec3], gb: &GBuffer, period: u32) {
        if (self.planes.w, self.planes.h) != (gb.width as usize, gb.height as usize) {
            self.set_gbuffer(gb);
        }
        let planes = &mut self.planes;
        planes.period = period;
        for (plane, c) in [(&mut planes.er, 0), (&mut planes.eg, 1), (&mut planes.eb, 2)] {
            plane.resize(e.len(), 0.0);
            if near.is_empty() {
                plane.par_iter_mut().zip(e).for_each(|(o, v)| *o = v[c]);
            } else {
                plane.par_iter_mut().zip(e).zip(near).for_each(|((o, v), n)| *o = v[c] - n[c]);
            }
        }
    }
}

/// Filters `e` (one value per pixel) with a `period × period` window, on the
/// CPU's best [`SimdPath`] (a [`Denoiser`] for this call alone).
pub fn cross_bilateral(e: &[Vec3], gb: &GBuffer, period: u32) -> Vec<Vec3> {
    cross_bilateral_on(SimdPath::best(), e, gb, period)
}

/// [`cross_bilateral`] on a chosen [`SimdPath`].
pub fn cross_bilateral_on(path: SimdPath, e: &[Vec3], gb: &GBuffer, period: u32) -> Vec<Vec3> {
    Denoiser::new(gb).filter_on(path, e, &[], gb, period)
}

impl Planes {
    /// The planes of `e` and the G-buffer (tests).
    #[cfg(test)]
    fn new(e: &[Vec3], gb: &GBuffer, period: u32) -> Self {
        let mut d = Denoiser::new(gb);
        d.load(e, &[], gb, period);
        d.planes
    }

    /// The filtered signal at pixel `i`.
    fn own(&self, i: usize) -> Vec3 {
        Vec3::new(self.er[i], self.eg[i], self.eb[i])
    }
}

/// One output row as a pulp operation, so [`SimdPath::run`] compiles it per
/// instruction set.
struct FilterRow<'a> {
    p: &'a Planes,
    gb: &'a GBuffer,
    y: usize,
    row: &'a mut [Vec3],
}

impl pulp::WithSimd for FilterRow<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        let FilterRow { p, gb, y, row } = self;
        let (w, size) = (p.w, p.period);
        let half = (size / 2) as usize;
        // Block starts x whose every pixel's window is unclipped in x:
        // x ≥ ⌊P/2⌋ and x + BLOCK − 1 + P − ⌊P/2⌋ ≤ w.
        let interior = |x: usize| x >= half && x + BLOCK - 1 + size as usize - half <= w;
        let mut x = 0;
        while x < w {
            if interior(x) {
                filter_block(p, gb, y, x, &mut row[x..x + BLOCK]);
                x += BLOCK;
            } else {
                let i = y * w + x;
                row[x] = if gb.valid(i) { filter_pixel(p, x, y) } else { Vec3::ZERO };
                x += 1;
            }
        }
    }
}

/// Pixels `x..x + BLOCK` of row `y`, whose `P × P` windows the image border
/// does not clip in x: lane `l` is pixel `x + l`, and window offset
/// `(dx, yy)` reads the consecutive neighbours `yy·w + x − ⌊P/2⌋ + dx + l`.
#[inline(always)]
fn filter_block(p: &Planes, gb: &GBuffer, y: usize, x: usize, out: &mut [Vec3]) {
    let (w, size) = (p.w, p.period);
    let half = (size / 2) as usize;
    let lanes =
        |v: &[f32], a: usize| -> [f32; BLOCK] { v[a..a + BLOCK].try_into().expect("BLOCK") };
    let c = y * w + x;
    let (cx, cy, cz, czz, cinv) =
        (lanes(&p.nx, c), lanes(&p.ny, c), lanes(&p.nz, c), lanes(&p.z, c), lanes(&p.inv, c));
    let (mut sr, mut sg, mut sb, mut sw, mut cover) =
        ([0.0f32; BLOCK], [0.0f32; BLOCK], [0.0f32; BLOCK], [0.0f32; BLOCK], [0u32; BLOCK]);
    let (y0, y1) =
        (window_start(y as u32, size) as usize, window_end(y as u32, size, p.h as u32) as usize);
    for yy in y0..y1 {
        for dx in 0..size as usize {
            let a = yy * w + x - half + dx;
            let (njx, njy, njz, zj) =
                (lanes(&p.nx, a), lanes(&p.ny, a), lanes(&p.nz, a), lanes(&p.z, a));
            let (rr, gg, bb) = (lanes(&p.er, a), lanes(&p.eg, a), lanes(&p.eb, a));
            for l in 0..BLOCK {
                let wgt = bilateral_weight(
                    Vec3::new(cx[l], cy[l], cz[l]),
                    Vec3::new(njx[l], njy[l], njz[l]),
                    czz[l],
                    zj[l],
                    cinv[l],
                );
                sr[l] += rr[l] * wgt;
                sg[l] += gg[l] * wgt;
                sb[l] += bb[l] * wgt;
                sw[l] += wgt;
                cover[l] += (wgt > COVER_WEIGHT) as u32;
            }
        }
    }
    for l in 0..BLOCK {
        let i = c + l;
        out[l] = if !gb.valid(i) {
            Vec3::ZERO
        } else if misses_subset(cover[l], size) {
            // A VPL subset is missing (an edge, a corner): the doubled
            // window brings it in (the P × P window's cover is this one's:
            // the same weights).
            let (sum, sw, _) = window_sum(p, x + l, y, wide_window(size));
            filtered_irradiance(p.own(i), sum, sw)
        } else {
            filtered_irradiance(p.own(i), Vec3::new(sr[l], sg[l], sb[l]), sw[l])
        };
    }
}

/// One pixel (that sees a surface) on its own: the `P × P` window, clipped
/// by the border, widened to [`wide_window`] where it misses a subset.
#[inline(always)]
fn filter_pixel(p: &Planes, x: usize, y: usize) -> Vec3 {
    let i = y * p.w + x;
    let (mut sum, mut sw, covered) = window_sum(p, x, y, p.period);
    if misses_subset(covered, p.period) {
        (sum, sw, _) = window_sum(p, x, y, wide_window(p.period));
    }
    filtered_irradiance(p.own(i), sum, sw)
}

/// Weighted sum, total weight and covering neighbours of the `size × size`
/// window around pixel `(x, y)`, clipped by the border; window rows in
/// chunks of [`LANES`] neighbours with per-lane partial sums.
#[inline(always)]
fn window_sum(p: &Planes, x: usize, y: usize, size: u32) -> (Vec3, f32, u32) {
    // The widened window's rows fill one AVX-512 register of neighbours.
    if size as usize >= WIDE_LANES {
        window_sum_in::<WIDE_LANES>(p, x, y, size)
    } else {
        window_sum_in::<LANES>(p, x, y, size)
    }
}

/// [`window_sum`] in chunks of `L` neighbours.
#[inline(always)]
fn window_sum_in<const L: usize>(p: &Planes, x: usize, y: usize, size: u32) -> (Vec3, f32, u32) {
    let (w, h) = (p.w, p.h);
    let i = y * w + x;
    let n = Vec3::new(p.nx[i], p.ny[i], p.nz[i]);
    let (zi, inv) = (p.z[i], p.inv[i]);
    let (x0, x1) =
        (window_start(x as u32, size) as usize, window_end(x as u32, size, w as u32) as usize);
    let (y0, y1) =
        (window_start(y as u32, size) as usize, window_end(y as u32, size, h as u32) as usize);
    let (mut lr, mut lg, mut lb, mut lw, mut lc) =
        ([0.0f32; L], [0.0f32; L], [0.0f32; L], [0.0f32; L], [0u32; L]);
    let (mut sr, mut sg, mut sb, mut sw) = (0.0f32, 0.0f32, 0.0f32, 0.0f32);
    let mut covered = 0u32;
    for yy in y0..y1 {
        let row = yy * w;
        let (mut a, b) = (row + x0, row + x1);
        while b - a >= L {
            let lanes = |v: &[f32]| -> [f32; L] { v[a..a + L].try_into().expect("L lanes") };
            let (zj, njx, njy, njz) = (lanes(&p.z), lanes(&p.nx), lanes(&p.ny), lanes(&p.nz));
            let (rr, gg, bb) = (lanes(&p.er), lanes(&p.eg), lanes(&p.eb));
            for l in 0..L {
                let wgt = bilateral_weight(n, Vec3::new(njx[l], njy[l], njz[l]), zi, zj[l], inv);
                lr[l] += rr[l] * wgt;
                lg[l] += gg[l] * wgt;
                lb[l] += bb[l] * wgt;
                lw[l] += wgt;
                lc[l] += (wgt > COVER_WEIGHT) as u32;
            }
            a += L;
        }
        for j in a..b {
            let wgt = bilateral_weight(n, Vec3::new(p.nx[j], p.ny[j], p.nz[j]), zi, p.z[j], inv);
            sr += p.er[j] * wgt;
            sg += p.eg[j] * wgt;
            sb += p.eb[j] * wgt;
            sw += wgt;
            covered += (wgt > COVER_WEIGHT) as u32;
        }
    }
    for l in 0..L {
        sr += lr[l];
        sg += lg[l];
        sb += lb[l];
        sw += lw[l];
        covered += lc[l];
    }
    (Vec3::new(sr, sg, sb), sw, covered)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vpl::VplContext;
    use slc_scene::scene::Scene;
    use slc_scene::vpl::{Culling, PERIOD, VplSettings};

    /// On the Cornell box's interleaved (blocky) irradiance, every
    /// instruction set the CPU has gives the per-pixel filter's result (the
    /// straightforward form: each pixel's clipped window, widened where it
    /// misses a subset) within float-summation tolerance.
    #[test]
    fn every_simd_path_matches_the_per_pixel_filter() {
        // 72 × 40: interior blocks, border pixels and a partial block per row.
        let ctx = VplContext::new(&Scene::cornell_box(), 72, 40, 64, None).unwrap();
        let shaded = ctx
            .shade(&VplSettings {
                culling: Culling::None,
                near_radius: Some(0.0),
                ..VplSettings::default()
            })
            .unwrap();
        let gb = ctx.gbuffer();
        let e = &shaded.irradiance;
        let planes = Planes::new(e, gb, PERIOD);
        let expected: Vec<Vec3> = (0..e.len())
            .map(|i| if gb.valid(i) { filter_pixel(&planes, i % 72, i / 72) } else { Vec3::ZERO })
            .collect();
        let widened = (0..e.len())
            .filter(|&i| {
                gb.valid(i) && misses_subset(window_sum(&planes, i % 72, i / 72, PERIOD).2, PERIOD)
            })
            .count();
        assert!(
            widened > 0 && widened < e.len() / 2,
            "both window sizes occur ({widened} widened)"
        );
        for path in SimdPath::ALL {
            if !path.is_available() {
                eprintln!("SKIP {path}: this CPU lacks it");
                continue;
            }
            let got = cross_bilateral_on(path, e, gb, PERIOD);
            for i in 0..e.len() {
                assert!(
                    (got[i] - expected[i]).abs().max_element()
                        <= 1e-5 * expected[i].max_element().max(1e-6),
                    "{path}, pixel {i}: {} vs {}",
                    got[i],
                    expected[i]
                );
            }
        }
    }
}
