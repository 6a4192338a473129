//! The pixels a frame shades, grouped once per G-buffer for tile culling:
//! parts (the unit of parallel work: a sub-image of the interleaving, a
//! region of the image) hold tiles (the unit of culling, each with the box
//! of its receivers' positions), tiles hold receivers (the pixels that see
//! a surface, with position, normal and, where the material has one, the
//! specular lobe).
//!
//! A frame's shading reads this instead of walking the G-buffer again:
//! the boxes, receiver lists and lobes depend on the camera alone, so
//! [`super::VplContext`] builds its tilings with the G-buffer and times them
//! with it. Receivers are numbered in part, group, tile order, so one part's
//! results are a contiguous range of a receiver-ordered buffer
//! ([`Tiling::split`]); [`Tiling::receiver`] maps a pixel back to its
//! receiver.

use super::shade::Glossy;
use glam::Vec3;
use rayon::prelude::*;
use slc_scene::vpl::GBuffer;
use std::ops::Range;
use std::sync::atomic::{AtomicU32, Ordering};

/// Marks a pixel without a receiver in [`Tiling::receiver`].
pub(crate) const NO_RECEIVER: u32 = u32::MAX;

/// A tile: its box, receivers and glossy receivers (ranges of its part),
/// and, in the near field's tiling, its quarters (a range of
/// [`PartTiles::quarters`]; empty in the far field's).
#[derive(Clone, Debug)]
pub(crate) struct Tile {
    pub lo: Vec3,
    pub hi: Vec3,
    pub receivers: Range<usize>,
    pub glossy: Range<usize>,
    pub quarters: Range<usize>,
}

/// One part's tiles and receivers (indices local to the part).
#[derive(Clone, Debug, Default)]
pub(crate) struct PartTiles {
    pub tiles: Vec<Tile>,
    /// Pixel of each receiver.
    pub pixel: Vec<u32>,
    /// Position and unit normal of each receiver.
    pub points: Vec<(Vec3, Vec3)>,
    /// The receivers with a specular lobe: receiver index and lobe.
    pub glossy: Vec<(usize, Glossy)>,
    /// The near field's quarter tiles ([`Tiling::regions`]): each a
    /// [`Tile`] of its own receivers (those of its tile, in quarter order),
    /// its own `quarters` empty.
    pub quarters: Vec<Tile>,
}

/// See the module documentation.
#[derive(Debug, Default)]
pub(crate) struct Tiling {
    pub parts: Vec<PartTiles>,
    /// The first receiver of each part, and the number of receivers last.
    pub offsets: Vec<usize>,
    /// Receiver of each pixel, [`NO_RECEIVER`] where the pixel sees no
    /// surface ([`Tiling::receiver`]; atomic so that the parts write their
    /// own pixels in parallel).
    receivers: Vec<AtomicU32>,
}

impl Tiling {
    /// The interleaved far field's tiling: one part per pixel class of the
    /// `period × period` interleaving (class `sy·P + sx` holds pixels
    /// `(sx + P·i, sy + P·j)`, its sub-image), its sub-image cut into
    /// tiles of `tile²` sub-image pixels, row-major from the origin (the
    /// GPU's workgroups at the same tile size).
    pub fn interleaved(gb: &GBuffer, period: usize, tile: usize) -> Tiling {
        let mut t = Tiling::default();
        t.interleaved_into(gb, period, tile);
        t
    }

    /// [`Tiling::interleaved`] in place, reusing this tiling's memory.
    pub fn interleaved_into(&mut self, gb: &GBuffer, period: usize, tile: usize) {
        let (w, h) = (gb.width as usize, gb.height as usize);
        self.fill_parts(gb, period * period, |sub, t| {
            let (sx, sy) = (sub % period, sub / period);
            let (sw, sh) = ((w + period - 1 - sx) / period, (h + period - 1 - sy) / period);
            for ty in (0..sh).step_by(tile) {
                for tx in (0..sw).step_by(tile) {
                    let rows = (ty..(ty + tile).min(sh)).map(|j| (sy + j * period) * w + sx);
                    t.push_tile(gb, rows, tx..(tx + tile).min(sw), period);
                }
            }
        });
    }

    /// The near field's tiling: one part per `region²` pixels of the image
    /// (`region` a multiple of `tile`, so the tiles are the image's, from
    /// the origin: the GPU's workgroups at the same tile size), cut into
    /// tiles of `tile²` pixels, each cut into four quarters of `(tile/2)²`
    /// pixels (those that see a surface), the receivers numbered quarter by
    /// quarter: a tile culls the near field's lights to its box, each
    /// quarter that list to its own (the GPU's `vpl_near` masks).
    #[cfg(test)]
    pub fn regions(gb: &GBuffer, region: usize, tile: usize) -> Tiling {
        let mut t = Tiling::default();
        t.regions_into(gb, region, tile);
        t
    }

    /// [`Tiling::regions`] in place, reusing this tiling's memory.
    pub fn regions_into(&mut self, gb: &GBuffer, region: usize, tile: usize) {
        let (w, h) = (gb.width as usize, gb.height as usize);
        let across = w.div_ceil(region);
        self.fill_parts(gb, across * h.div_ceil(region), |k, t| {
            let (x0, y0) = ((k % across) * region, (k / across) * region);
            let (x1, y1) = ((x0 + region).min(w), (y0 + region).min(h));
            for ty in (y0..y1).step_by(tile) {
                for tx in (x0..x1).step_by(tile) {
                    t.push_quartered(gb, (tx, ty), tile, (x1, y1), |y| y * w, 1);
                }
            }
        });
    }

    /// Refills this tiling with `parts` parts, part `k` by `fill(k, part)`
    /// (in parallel, each part's memory reused), then numbers the
    /// receivers in part order.
    fn fill_parts(
        &mut self,
        gb: &GBuffer,
        parts: usize,
        fill: impl Fn(usize, &mut PartTiles) + Sync,
    ) {
        self.parts.resize_with(parts, PartTiles::default);
        self.parts.par_iter_mut().enumerate().for_each(|(k, t)| {
            t.clear();
            fill(k, t);
        });
        self.offsets.clear();
        self.offsets.push(0);
        for p in &self.parts {
            self.offsets.push(self.offsets.last().copied().unwrap_or(0) + p.pixel.len());
        }
        let n = gb.position.len();
        if self.receivers.len() != n {
            self.receivers = (0..n).map(|_| AtomicU32::new(NO_RECEIVER)).collect();
        } else {
            self.receivers.par_iter().for_each(|r| r.store(NO_RECEIVER, Ordering::Relaxed));
        }
        // Each pixel belongs to at most one part: the stores never race.
        self.parts.par_iter().zip(&self.offsets).for_each(|(p, &o)| {
            for (r, &i) in p.pixel.iter().enumerate() {
                self.receivers[i as usize].store((o + r) as u32, Ordering::Relaxed);
            }
        });
    }

    /// The receiver of pixel `i`, [`NO_RECEIVER`] where it sees no surface.
    pub fn receiver(&self, i: usize) -> u32 {
        self.receivers[i].load(Ordering::Relaxed)
    }

    /// Number of pixels.
    #[cfg(test)]
    pub fn pixels(&self) -> usize {
        self.receivers.len()
    }

    /// A per-receiver buffer split into each part's range.
    pub fn split<'a, T>(&self, mut out: &'a mut [T]) -> Vec<&'a mut [T]> {
        let mut parts = Vec::with_capacity(self.parts.len());
        for p in &self.parts {
            let (a, rest) = out.split_at_mut(p.pixel.len());
            parts.push(a);
            out = rest;
        }
        parts
    }

    /// [`Tiling::split`], or empty slices when `out` is empty (no glossy
    /// pixel).
    pub fn split_glossy<'a, T>(&self, out: &'a mut [T]) -> Vec<&'a mut [T]> {
        if out.is_empty() {
            self.parts.iter().map(|_| <&mut [T]>::default()).collect()
        } else {
            self.split(out)
        }
    }

    /// Number of receivers.
    pub fn len(&self) -> usize {
        self.offsets.last().copied().unwrap_or(0)
    }

    /// `true` when some receiver has a specular lobe.
    pub fn has_glossy(&self) -> bool {
        self.parts.iter().any(|p| !p.glossy.is_empty())
    }
}

impl PartTiles {
    fn clear(&mut self) {
        self.tiles.clear();
        self.pixel.clear();
        self.points.clear();
        self.glossy.clear();
        self.quarters.clear();
    }

    /// Appends the tile of `tile²` pixels from `(tx, ty)` (clipped to `(x1,
    /// y1)`) in four quarters of `⌈tile/2⌉²`, quarter by quarter (row-major);
    /// pixel `(x, y)` is `row_start(y) + x·step` (none seeing a surface: no
    /// tile, no quarter).
    fn push_quartered(
        &mut self,
        gb: &GBuffer,
        (tx, ty): (usize, usize),
        tile: usize,
        (x1, y1): (usize, usize),
        row_start: impl Fn(usize) -> usize,
        step: usize,
    ) {
        let half = tile.div_ceil(2);
        let (r0, s0, q0) = (self.pixel.len(), self.glossy.len(), self.quarters.len());
        for (qx, qy) in [(0, 0), (half, 0), (0, half), (half, half)] {
            let (qx0, qy0) = ((tx + qx).min(x1), (ty + qy).min(y1));
            let rows = (qy0..(qy0 + half).min(ty + tile).min(y1)).map(&row_start);
            let cols = qx0..(qx0 + half).min(tx + tile).min(x1);
            if let Some(q) = self.push_pixels(gb, rows, cols, step) {
                self.quarters.push(q);
            }
        }
        if let Some(&Tile { lo, hi, .. }) = self.quarters.get(q0) {
            let (lo, hi) = self.quarters[q0..]
                .iter()
                .fold((lo, hi), |(lo, hi), q| (lo.min(q.lo), hi.max(q.hi)));
            self.tiles.push(Tile {
                lo,
                hi,
                receivers: r0..self.pixel.len(),
                glossy: s0..self.glossy.len(),
                quarters: q0..self.quarters.len(),
            });
        }
    }

    /// Appends a tile of the pixels `row + i·step` (each `row` start of
    /// `rows`, each `i` of `cols`) that see a surface (none: no tile).
    fn push_tile(
        &mut self,
        gb: &GBuffer,
        rows: impl Iterator<Item = usize>,
        cols: Range<usize>,
        step: usize,
    ) {
        if let Some(t) = self.push_pixels(gb, rows, cols, step) {
            self.tiles.push(t);
        }
    }

    /// Appends the receivers of [`PartTiles::push_tile`]'s pixels and
    /// returns their tile (without quarters), or `None` where none sees a
    /// surface.
    fn push_pixels(
        &mut self,
        gb: &GBuffer,
        rows: impl Iterator<Item = usize>,
        cols: Range<usize>,
        step: usize,
    ) -> Option<Tile> {
        let (r0, s0) = (self.pixel.len(), self.glossy.len());
        let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
        let glossy = !gb.specular.is_empty();
        for row in rows {
            for i in (row + cols.start * step..row + cols.end * step).step_by(step) {
                if !gb.valid(i) {
                    continue;
                }
                let x = gb.position[i];
                (lo, hi) = (lo.min(x), hi.max(x));
                if let Some(g) = glossy.then(|| Glossy::at(gb, i)).flatten() {
                    self.glossy.push((self.pixel.len(), g));
                }
                self.pixel.push(i as u32);
                self.points.push((x, gb.normal[i]));
            }
        }
        (self.pixel.len() > r0).then_some(Tile {
            lo,
            hi,
            receivers: r0..self.pixel.len(),
            glossy: s0..self.glossy.len(),
            quarters: 0..0,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vpl::VplContext;
    use slc_scene::scene::Scene;

    /// Every pixel that sees a surface is exactly one receiver, each tile's
    /// box holds its receivers, and the ranges cover in order; the near
    /// field's tiles are cut into quarters that cover their receivers and
    /// glossy receivers in order, each quarter's box the box of its pixels,
    /// which lie in one `⌈tile/2⌉²` square of the tile (the GPU's
    /// `vpl_near` quarters), and the tile's box the quarters' union.
    #[test]
    fn tilings_cover_every_surface_pixel_once_with_boxes_that_hold_them() {
        let ctx = VplContext::new(&Scene::cornell_box_glossy(), 37, 29, 64, None).unwrap();
        let gb = ctx.gbuffer();
        let w = gb.width as usize;
        for (t, quarters) in [
            (Tiling::interleaved(gb, 8, 4), None),
            (Tiling::interleaved(gb, 8, 3), None),
            (Tiling::regions(gb, 32, 8), Some(8usize)),
            (Tiling::regions(gb, 9, 3), Some(3)),
        ] {
            let mut cut = 0;
            for p in &t.parts {
                for tile in &p.tiles {
                    let q = &p.quarters[tile.quarters.clone()];
                    let Some(size) = quarters else {
                        assert!(q.is_empty());
                        continue;
                    };
                    cut += (q.len() > 1) as usize;
                    assert_eq!(q.first().map(|q| q.receivers.start), Some(tile.receivers.start));
                    assert_eq!(q.last().map(|q| q.receivers.end), Some(tile.receivers.end));
                    assert_eq!(q.first().map(|q| q.glossy.start), Some(tile.glossy.start));
                    assert_eq!(q.last().map(|q| q.glossy.end), Some(tile.glossy.end));
                    let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
                    for (a, b) in q.iter().zip(q.iter().skip(1)) {
                        assert_eq!(
                            (a.receivers.end, a.glossy.end),
                            (b.receivers.start, b.glossy.start)
                        );
                    }
                    for quarter in q {
                        let (mut qlo, mut qhi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
                        let half = size.div_ceil(2);
                        let square = |i: u32| {
                            ((i as usize % w) % size / half, (i as usize / w) % size / half)
                        };
                        let first = square(p.pixel[quarter.receivers.start]);
                        for k in quarter.receivers.clone() {
                            assert_eq!(square(p.pixel[k]), first, "one quarter's pixels");
                            (qlo, qhi) = (qlo.min(p.points[k].0), qhi.max(p.points[k].0));
                        }
                        assert_eq!((qlo, qhi), (quarter.lo, quarter.hi));
                        (lo, hi) = (lo.min(qlo), hi.max(qhi));
                    }
                    assert_eq!((lo, hi), (tile.lo, tile.hi));
                }
            }
            assert!(quarters.is_none() || cut > 0, "some tile has several quarters");
            let valid = (0..gb.position.len()).filter(|&i| gb.valid(i)).count();
            assert_eq!(t.len(), valid);
            for (p, &o) in t.parts.iter().zip(&t.offsets) {
                let mut next = 0;
                for tile in &p.tiles {
                    assert_eq!(tile.receivers.start, next);
                    next = tile.receivers.end;
                    for &(x, _) in &p.points[tile.receivers.clone()] {
                        assert!(tile.lo.cmple(x).all() && x.cmple(tile.hi).all());
                    }
                    for &(k, _) in &p.glossy[tile.glossy.clone()] {
                        assert!(tile.receivers.contains(&k));
                    }
                }
                assert_eq!(next, p.pixel.len());
                for (r, &i) in p.pixel.iter().enumerate() {
                    assert_eq!(t.receiver(i as usize) as usize, o + r, "pixel {i}");
                }
            }
            for i in 0..gb.position.len() {
                assert_eq!(t.receiver(i) != NO_RECEIVER, gb.valid(i), "pixel {i}");
            }
            let glossy = (0..gb.position.len()).filter(|&i| gb.specular_at(i).is_some()).count();
            assert!(
                glossy > 0 && t.parts.iter().map(|p| p.glossy.len()).sum::<usize>() == glossy,
                "every glossy pixel has its lobe"
            );
        }
    }
}
