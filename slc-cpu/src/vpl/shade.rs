//! The shading loop: irradiance at a receiver from a list of VPLs, in
//! structure-of-arrays form so the loop runs on SIMD lanes.
//!
//! Every formula comes from slc-core: the VPL transfer
//! ([`slc_core::light::vpl_transfer`]), the keep test
//! ([`slc_core::range::slc_keep`]), the `1/p` weight
//! ([`slc_core::range::slc_weight`]) and the near-field split
//! ([`slc_core::interleave::vpl_near_weight`]).

use glam::Vec3;
use slc_core::interleave::{vpl_far_weight, vpl_near_weight};
use slc_core::light::vpl_transfer;
use slc_core::range::{clamp_keep, cull_radius, slc_keep, slc_weight};
use slc_core::sphere::sphere_overlaps_aabb;

/// How a light list is evaluated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cull {
    /// Stochastic light culling: keep iff `d² < r²`, weight `1/p`.
    Slc,
    /// Clamped range: keep iff `d² < R²`, no reweighting (biased).
    Clamp,
    /// Every light counts.
    None,
    /// The near field of the split: each light weighted by its near share
    /// [`slc_core::interleave::vpl_near_weight`] (the other methods take
    /// the rest, `1 − w`).
    Near,
}

/// A list of VPLs in SoA layout (one entry per light, same index in every
/// array). `rt2`/`r2` hold `r_t²` and `r²` for [`Cull::Slc`] and `R²` in
/// `r2` for [`Cull::Clamp`].
#[derive(Clone, Debug, Default)]
pub struct LightList {
    pub(crate) px: Vec<f32>,
    pub(crate) py: Vec<f32>,
    pub(crate) pz: Vec<f32>,
    pub(crate) nx: Vec<f32>,
    pub(crate) ny: Vec<f32>,
    pub(crate) nz: Vec<f32>,
    pub(crate) fr: Vec<f32>,
    pub(crate) fg: Vec<f32>,
    pub(crate) fb: Vec<f32>,
    pub(crate) rt2: Vec<f32>,
    pub(crate) r2: Vec<f32>,
    pub(crate) radius: Vec<f32>,
    /// Per chunk of [`CHUNK`] consecutive lights: the box holding their
    /// range spheres (empty until [`LightList::build_chunks`]).
    chunks: Vec<(Vec3, Vec3)>,
    /// Real lights when the list was padded by culling (else `len()`).
    real: usize,
}

/// Lights per chunk in [`LightList::cull_chunked_into`].
pub const CHUNK: usize = 16;

impl LightList {
    /// Empties the list, keeping its memory.
    pub fn clear(&mut self) {
        for v in [
            &mut self.px,
            &mut self.py,
            &mut self.pz,
            &mut self.nx,
            &mut self.ny,
            &mut self.nz,
            &mut self.fr,
            &mut self.fg,
            &mut self.fb,
            &mut self.rt2,
            &mut self.r2,
            &mut self.radius,
        ] {
            v.clear();
        }
        self.chunks.clear();
    }

    /// Appends one light; its culling sphere has radius
    /// [`slc_core::range::cull_radius`]`(r²)`.
    pub fn push(&mut self, p: Vec3, n: Vec3, flux: Vec3, rt2: f32, r2: f32) {
        self.real = self.len() + 1;
        self.radius.push(cull_radius(r2));
        self.px.push(p.x);
        self.py.push(p.y);
        self.pz.push(p.z);
        self.nx.push(n.x);
        self.ny.push(n.y);
        self.nz.push(n.z);
        self.fr.push(flux.x);
        self.fg.push(flux.y);
        self.fb.push(flux.z);
        self.rt2.push(rt2);
        self.r2.push(r2);
    }

    /// Computes the box of every chunk of [`CHUNK`] consecutive lights'
    /// range spheres (`centre ± r` per light), for [`LightList::cull_chunked_into`].
    pub fn build_chunks(&mut self) {
        self.chunks.clear();
        for c in (0..self.len()).step_by(CHUNK) {
            let mut lo = Vec3::INFINITY;
            let mut hi = Vec3::NEG_INFINITY;
            for j in c..(c + CHUNK).min(self.len()) {
                let p = Vec3::new(self.px[j], self.py[j], self.pz[j]);
                lo = lo.min(p - self.radius[j]);
                hi = hi.max(p + self.radius[j]);
            }
            self.chunks.push((lo, hi));
        }
    }

    /// [`LightList::cull_into`] that first skips every chunk whose box misses
    /// `[lo, hi]`; the result is the same set (the chunk box contains its
    /// lights' spheres). Needs [`LightList::build_chunks`].
    pub fn cull_chunked_into(&self, lo: Vec3, hi: Vec3, hits: &mut Vec<u32>, out: &mut LightList) {
        hits.clear();
        for (c, &(clo, chi)) in self.chunks.iter().enumerate() {
            if clo.cmple(hi).all() && lo.cmple(chi).all() {
                for j in c * CHUNK..((c + 1) * CHUNK).min(self.len()) {
                    let p = Vec3::new(self.px[j], self.py[j], self.pz[j]);
                    if sphere_overlaps_aabb(p, self.radius[j], lo, hi) {
                        hits.push(j as u32);
                    }
                }
            }
        }
        self.gather_into(hits, out);
    }

    /// Tile culling: replaces `out` with the lights whose range sphere
    /// `(p, √r²)` overlaps the box `[lo, hi]`
    /// ([`slc_core::sphere::sphere_overlaps_aabb`]). The test runs
    /// branch-free over all lights, then each array is gathered in one pass.
    pub fn cull_into(&self, lo: Vec3, hi: Vec3, hits: &mut Vec<u32>, out: &mut LightList) {
        let n = self.len();
        let (px, py, pz, radius) = (&self.px[..n], &self.py[..n], &self.pz[..n], &self.radius[..n]);
        hits.clear();
        hits.resize(n + 1, 0);
        let mut k = 0;
        for (j, (((&x, &y), &z), &r)) in px.iter().zip(py).zip(pz).zip(radius).enumerate() {
            // Branch-free compaction: always write, advance only on a hit.
            hits[k.min(n)] = j as u32;
            k += sphere_overlaps_aabb(Vec3::new(x, y, z), r, lo, hi) as usize;
        }
        hits.truncate(k);
        self.gather_into(hits, out);
    }

    /// Replaces `out` with the entries `hits` of this list, padded to a
    /// multiple of the SIMD width with entries that are never kept and carry
    /// no flux (`r² = 0`, `Φ = 0`), so the shading loop has no scalar tail.
    /// [`LightList::len_unpadded`] still counts only real lights.
    fn gather_into(&self, hits: &[u32], out: &mut LightList) {
        out.chunks.clear();
        out.real = hits.len();
        let pad = hits.len().next_multiple_of(LANES) - hits.len();
        let gather = |dst: &mut Vec<f32>, src: &[f32]| {
            dst.clear();
            dst.extend(hits.iter().map(|&j| src[j as usize]));
        };
        gather(&mut out.px, &self.px);
        gather(&mut out.py, &self.py);
        gather(&mut out.pz, &self.pz);
        gather(&mut out.nx, &self.nx);
        gather(&mut out.ny, &self.ny);
        gather(&mut out.nz, &self.nz);
        gather(&mut out.fr, &self.fr);
        gather(&mut out.fg, &self.fg);
        gather(&mut out.fb, &self.fb);
        gather(&mut out.rt2, &self.rt2);
        gather(&mut out.r2, &self.r2);
        gather(&mut out.radius, &self.radius);
        for v in [
            &mut out.px,
            &mut out.py,
            &mut out.pz,
            &mut out.nx,
            &mut out.ny,
            &mut out.nz,
            &mut out.fr,
            &mut out.fg,
            &mut out.fb,
            &mut out.rt2,
            &mut out.r2,
            &mut out.radius,
        ] {
            v.extend(std::iter::repeat_n(0.0, pad));
        }
    }

    /// Real lights in the list (padding excluded).
    pub fn len_unpadded(&self) -> usize {
        self.real.min(self.len())
    }

    /// Number of lights.
    pub fn len(&self) -> usize {
        self.px.len()
    }

    /// `true` when empty.
    pub fn is_empty(&self) -> bool {
        self.px.is_empty()
    }
}

/// SIMD lanes of the shading loop.
const LANES: usize = 8;

/// Irradiance at `x` (unit normal `n`) from every light of `list` under
/// `cull`, and the number of lights that passed the keep test. With
/// `near_r2 > 0` each light's transfer is split by its near share `w`
/// ([`slc_core::interleave::vpl_near_weight`]): [`Cull::Near`] takes `w`,
/// the others `1 − w`.
#[inline(never)]
pub fn shade(list: &LightList, x: Vec3, n: Vec3, min_d2: f32, near_r2: f32, cull: Cull) -> (Vec3, u32) {
    match cull {
        Cull::Slc => shade_impl::<0>(list, x, n, min_d2, near_r2),
        Cull::Clamp => shade_impl::<1>(list, x, n, min_d2, near_r2),
        Cull::None => shade_impl::<2>(list, x, n, min_d2, near_r2),
        Cull::Near => shade_impl::<3>(list, x, n, min_d2, near_r2),
    }
}

/// One light's weighted transfer and keep flag (0 or 1) at `x`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn term<const MODE: u8>(p: Vec3, nl: Vec3, rt2: f32, r2: f32, x: Vec3, n: Vec3, min_d2: f32, near_r2: f32) -> (f32, f32) {
    let v = x - p;
    let t = vpl_transfer(nl, n, v, min_d2);
    let d2 = v.x * v.x + v.y * v.y + v.z * v.z;
    // Every test evaluated unconditionally so the loop stays branch-free
    // (the keep test is a coin flip per light: branches mispredict).
    let near = vpl_near_weight(d2, near_r2);
    let far = vpl_far_weight(d2, near_r2);
    let (keep, w) = match MODE {
        0 => (slc_keep(r2, d2) & (far > 0.0), t * slc_weight(rt2, d2) * far),
        1 => (clamp_keep(r2, d2) & (far > 0.0), t * far),
        2 => (far > 0.0, t * far),
        // r² = R_n² (0 for padding, which is never kept).
        _ => (clamp_keep(r2, d2) & (near > 0.0), t * near),
    };
    (if keep { w } else { 0.0 }, if keep { 1.0 } else { 0.0 })
}

/// `LANES` consecutive entries of one SoA array.
#[inline(always)]
fn lanes(a: &[f32], base: usize) -> &[f32; LANES] {
    a[base..base + LANES].try_into().expect("chunk of LANES")
}

#[inline(always)]
fn shade_impl<const MODE: u8>(list: &LightList, x: Vec3, n: Vec3, min_d2: f32, near_r2: f32) -> (Vec3, u32) {
    let len = list.len();
    let (mut r, mut g, mut b, mut k) = ([0.0f32; LANES], [0.0f32; LANES], [0.0f32; LANES], [0.0f32; LANES]);
    let full = len / LANES * LANES;
    let mut base = 0;
    while base < full {
        let (px, py, pz) = (lanes(&list.px, base), lanes(&list.py, base), lanes(&list.pz, base));
        let (nx, ny, nz) = (lanes(&list.nx, base), lanes(&list.ny, base), lanes(&list.nz, base));
        let (fr, fg, fb) = (lanes(&list.fr, base), lanes(&list.fg, base), lanes(&list.fb, base));
        let (rt2, r2) = (lanes(&list.rt2, base), lanes(&list.r2, base));
        for l in 0..LANES {
            let (w, kept) = term::<MODE>(Vec3::new(px[l], py[l], pz[l]), Vec3::new(nx[l], ny[l], nz[l]), rt2[l], r2[l], x, n, min_d2, near_r2);
            r[l] += fr[l] * w;
            g[l] += fg[l] * w;
            b[l] += fb[l] * w;
            k[l] += kept;
        }
        base += LANES;
    }
    for j in full..len {
        let p = Vec3::new(list.px[j], list.py[j], list.pz[j]);
        let nl = Vec3::new(list.nx[j], list.ny[j], list.nz[j]);
        let (w, kept) = term::<MODE>(p, nl, list.rt2[j], list.r2[j], x, n, min_d2, near_r2);
        r[0] += list.fr[j] * w;
        g[0] += list.fg[j] * w;
        b[0] += list.fb[j] * w;
        k[0] += kept;
    }
    let sum = |a: [f32; LANES]| a.iter().sum::<f32>();
    (Vec3::new(sum(r), sum(g), sum(b)), sum(k) as u32)
}
