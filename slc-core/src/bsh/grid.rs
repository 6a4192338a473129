//! A uniform grid over a refitted [`Bsh`]'s leaves: the CPU's shortcut for
//! the walk of a Lambertian receiver.
//!
//! The stackless walk's cost is one dependent load per visited node, about
//! a hundred of them for one or two lights found among 49,152 on surfaces
//! (docs/results/bsh-walk-visits.md). A grid built after each refit lists,
//! in every cell, the leaves whose range sphere's box overlaps it; a point
//! tests the spheres of its own cell, then the range tail's, in the walk's
//! own order, with the walk's own leaf test ([`sphere_contains_point`] on
//! the leaf's values). So it finds the same lights in the same order as
//! [`Bsh::for_each_containing`]: same candidates, same random numbers, the
//! same image.
//!
//! A glossy receiver scales each light's range toward it by up to its
//! range lobe's `rl.w` ([`crate::bsh::walk::bsh_reaches`]). A grid built
//! for a *reach* `w` ([`BshGrid::build_reaching`]) lists each leaf in every
//! cell its sphere so scaled at most can touch ([`bsh_reach_bound`], the
//! walk's own bound), and a receiver with `rl.w ≤ w` tests its cell's
//! leaves with the walk's leaf test: again the walk's lights in its order.
//! Points outside the grid's box, and receivers whose lobe reaches beyond
//! the grid's, take the tree. (A sharper lobe scales its ranges by more
//! than `w²` only in a narrow cone around its mirror direction; its
//! cell's lights below `w²` plus a walk that skips every node whose scale
//! bound is at most `w²` took 1.3–1.7 of the plain walk's time: tried,
//! not kept, docs/results/bsh-walk-visits.md.) The GPU keeps the
//! stackless walk (a grid per pass there is a counting sort the kernels
//! do not have yet).

use super::walk::bsh_reaches;
use super::{BSH_NONE, BSH_TAIL, Bsh, BshNode, bsh_reach_bound};
use crate::sphere::sphere_contains_point;
use alloc::vec;
use alloc::vec::Vec;
use glam::{UVec3, Vec3, Vec4};

/// Fewest cells along the grid's longest axis: [`BshGrid::build`] takes
/// `∛(n/2)` for `n` lights, within these bounds (32 for 49,152 lights, 16 for
/// 2,048: the fastest of 16–128 on the suite; `cargo run --release -p
/// slc-scene --example grid_walk`).
pub const GRID_RES_MIN: u32 = 4;
/// Most cells along the grid's longest axis [`BshGrid::build`] takes.
pub const GRID_RES_MAX: u32 = 64;

/// Most cells along the longest axis [`BshGrid::build_at`] takes (2²⁴
/// cells at most).
pub const GRID_RES_LIMIT: u32 = 256;

/// Most entries a grid may hold per light in the tree (plus one per cell;
/// 20 bytes each): past it the resolution halves, and below
/// [`GRID_RES_MIN`] there is no grid (ranges as large as the scene: the
/// tree is as good). The suite's scenes take 2–5 at their own resolution.
pub const GRID_ENTRIES_PER_LIGHT: u64 = 8;

/// A grid of one refit's leaf spheres (see the module docs).
#[derive(Clone, Debug)]
pub struct BshGrid {
    lo: Vec3,
    hi: Vec3,
    inv: Vec3,
    n: UVec3,
    /// The largest range lobe `rl.w` the cells hold (1: the plain spheres).
    reach: f32,
    /// Cell `c`'s entries are `start[c]..start[c + 1]`.
    start: Vec<u32>,
    /// Each entry's sphere `(centre, radius)`, light and light extent `R`
    /// (the extents only for a reach above 1: a glossy lobe's test reads
    /// them, the plain sphere test does not).
    spheres: Vec<Vec4>,
    lights: Vec<u32>,
    extents: Vec<f32>,
    /// The range tail's spheres, lights and extents, tested at every point.
    tail_spheres: Vec<Vec4>,
    tail_lights: Vec<u32>,
    tail_extents: Vec<f32>,
}

impl BshGrid {
    /// The grid of `bsh`'s leaves as its last refit left them, over the box
    /// `(lo, hi)` (the scene's: a point outside it takes the tree), at
    /// `∛(n/2)` cells along the box's longest axis for `n` lights in the
    /// tree, within [`GRID_RES_MIN`]`..=`[`GRID_RES_MAX`] ([`Self::build_at`]).
    pub fn build(bsh: &Bsh, lo: Vec3, hi: Vec3) -> Option<BshGrid> {
        Self::build_reaching(bsh, lo, hi, 1.0)
    }

    /// [`Self::build`] for receivers whose range lobe reaches up to `w`
    /// (`rl.w ≤ w`; [`Self::for_each_reaching`]): each leaf in every cell
    /// its sphere scaled by `w` can touch. `w ≤ 1` is [`Self::build`]'s
    /// grid; `None` also for a `w` that is not finite.
    pub fn build_reaching(bsh: &Bsh, lo: Vec3, hi: Vec3, w: f32) -> Option<BshGrid> {
        let res = libm::cbrtf(bsh.len() as f32 / 2.0) as u32;
        Self::build_reaching_at(bsh, lo, hi, res.clamp(GRID_RES_MIN, GRID_RES_MAX), w)
    }

    /// [`Self::build`] at `res` cells along the box's longest axis, halved
    /// while the entries pass [`GRID_ENTRIES_PER_LIGHT`]; `None` for an
    /// empty tree, a box that is not finite and positive, or ranges so
    /// large that even [`GRID_RES_MIN`] cells a side would pass it.
    pub fn build_at(bsh: &Bsh, lo: Vec3, hi: Vec3, res: u32) -> Option<BshGrid> {
        Self::build_reaching_at(bsh, lo, hi, res, 1.0)
    }

    /// [`Self::build_reaching`] at `res` cells along the box's longest
    /// axis, halved as [`Self::build_at`] halves it.
    pub fn build_reaching_at(bsh: &Bsh, lo: Vec3, hi: Vec3, res: u32, w: f32) -> Option<BshGrid> {
        let ext = hi - lo;
        if !(lo.is_finite() && ext.is_finite() && ext.min_element() > 0.0) || bsh.is_empty() {
            return None;
        }
        if !w.is_finite() {
            return None;
        }
        let w = w.max(1.0);
        // A flat box (a single wall) gets a thickness, so no axis's cells
        // are narrower than 10⁻³ of the longest; and every side a margin of
        // 10⁻⁴ of it, for points on the surfaces that rounding put outside.
        let pad = Vec3::splat(ext.max_element() * 1e-4);
        let lo = lo - pad;
        let ext = ext.max(Vec3::splat(ext.max_element() * 1e-3)) + 2.0 * pad;
        let hi = lo + ext;
        // The walk's leaves in its order: the tree's, then the tail's copies.
        let nodes = bsh.nodes();
        let tree = bsh.tree_len();
        let (mut inside, mut tail_spheres, mut tail_lights, mut tail_extents) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut i = 0u32;
        while i != BSH_NONE {
            let n = nodes[i as usize];
            if n.child != BSH_NONE {
                i = n.child;
                continue;
            }
            // The walk's own choice: a marked leaf is never found.
            if n.light & BSH_TAIL == 0 {
                if (i as usize) < tree {
                    inside.push(i);
                } else {
                    tail_spheres.push(n.center.extend(n.radius));
                    tail_lights.push(n.light);
                    if w > 1.0 {
                        tail_extents.push(n.extent);
                    }
                }
            }
            i = n.next;
        }
        let lights_in = inside.len() as u64;
        let mut res = res.clamp(GRID_RES_MIN, GRID_RES_LIMIT);
        loop {
            let cell = ext.max_element() / res as f32;
            let n = (ext / cell).ceil().as_uvec3().max(UVec3::ONE);
            let inv = n.as_vec3() / ext;
            if !inv.is_finite() {
                return None;
            }
            let cells = (n.x * n.y * n.z) as usize;
            let cover = |i: u32| {
                let s = nodes[i as usize];
                // The farthest the leaf test reaches: the sphere, or for a
                // lobe up to `w` the walk's own bound.
                let reach = if w > 1.0 { s.radius.max(bsh_reach_bound(s, w)) } else { s.radius };
                // A reach whose square overflows holds every point (the
                // leaf test's `d² ≤ ∞`): every cell.
                if reach * reach == f32::INFINITY {
                    return (UVec3::ZERO, n - 1);
                }
                // Padded: the leaf test rounds, the box must not; and
                // squares underflow, so a point within ~5e-23 of a centre
                // passes even a zero radius.
                let r = reach * (1.0 + 1e-5) + 1e-22;
                let a = ((s.center - r - lo) * inv).floor().max(Vec3::ZERO);
                let b = ((s.center + r - lo) * inv).floor().max(Vec3::ZERO);
                let top = (n - 1).as_vec3();
                // NaN spheres (never found) cover nothing.
                if a.is_nan() || b.is_nan() {
                    return (UVec3::ONE, UVec3::ZERO);
                }
                (a.min(top).as_uvec3(), b.min(top).as_uvec3())
            };
            // Each leaf's cells, once: counted, then filled.
            let covers: Vec<(UVec3, UVec3)> = inside.iter().map(|&i| cover(i)).collect();
            let mut total = 0u64;
            for &(a, b) in &covers {
                if a.x <= b.x && a.y <= b.y && a.z <= b.z {
                    let d = b - a + 1;
                    total += d.x as u64 * d.y as u64 * d.z as u64;
                }
            }
            if total > (GRID_ENTRIES_PER_LIGHT * lights_in + cells as u64).min(u32::MAX as u64) {
                if res / 2 < GRID_RES_MIN {
                    return None;
                }
                res /= 2;
                continue;
            }
            let each = |(a, b): (UVec3, UVec3), f: &mut dyn FnMut(usize)| {
                for z in a.z..=b.z {
                    for y in a.y..=b.y {
                        let row = ((z * n.y + y) * n.x) as usize;
                        for x in a.x..=b.x {
                            f(row + x as usize);
                        }
                    }
                }
            };
            let mut start = vec![0u32; cells + 1];
            for &c in &covers {
                each(c, &mut |c| start[c + 1] += 1);
            }
            for c in 0..cells {
                start[c + 1] += start[c];
            }
            let mut fill = start.clone();
            let mut spheres = vec![Vec4::ZERO; total as usize];
            let mut lights = vec![0u32; total as usize];
            let mut extents = vec![0f32; if w > 1.0 { total as usize } else { 0 }];
            for (&i, &c) in inside.iter().zip(&covers) {
                let s = nodes[i as usize];
                each(c, &mut |c| {
                    let at = fill[c] as usize;
                    spheres[at] = s.center.extend(s.radius);
                    lights[at] = s.light;
                    if let Some(e) = extents.get_mut(at) {
                        *e = s.extent;
                    }
                    fill[c] += 1;
                });
            }
            return Some(BshGrid {
                lo,
                hi,
                inv,
                n,
                reach: w,
                start,
                spheres,
                lights,
                extents,
                tail_spheres,
                tail_lights,
                tail_extents,
            });
        }
    }

    /// Calls `visit(light)` for each light whose range sphere contains `x`,
    /// in the walk's order, and returns `true`; `false` (nothing visited)
    /// where `x` lies outside the grid's box: the caller walks the tree.
    /// Nothing for a NaN point (as the walk).
    pub fn for_each_containing(&self, x: Vec3, mut visit: impl FnMut(u32)) -> bool {
        if x.is_nan() {
            return true;
        }
        let Some(c) = self.cell(x) else { return false };
        let (a, b) = (self.start[c] as usize, self.start[c + 1] as usize);
        for (s, &l) in self.spheres[a..b].iter().zip(&self.lights[a..b]) {
            if sphere_contains_point(s.truncate(), s.w, x) {
                visit(l);
            }
        }
        for (s, &l) in self.tail_spheres.iter().zip(&self.tail_lights) {
            if sphere_contains_point(s.truncate(), s.w, x) {
                visit(l);
            }
        }
        true
    }

    /// Calls `visit(light)` for each light whose range sphere, scaled for a
    /// receiver at `x` with mirror direction `r` and range lobe `rl`,
    /// reaches it ([`bsh_reaches`], the walk's own leaf test), in the
    /// walk's order ([`Bsh::for_each_reaching`]), and returns `true`;
    /// `false` (nothing visited) where `x` lies outside the grid's box or
    /// the lobe reaches beyond the grid's (`rl.w` above the `w` it was
    /// built for, or NaN): the caller walks the tree.
    pub fn for_each_reaching(
        &self,
        x: Vec3,
        r: Vec3,
        rl: Vec4,
        mut visit: impl FnMut(u32),
    ) -> bool {
        if rl.w <= 1.0 {
            return self.for_each_containing(x, visit);
        }
        if !(rl.w <= self.reach) {
            return false;
        }
        if x.is_nan() {
            return true;
        }
        let Some(c) = self.cell(x) else { return false };
        let (a, b) = (self.start[c] as usize, self.start[c + 1] as usize);
        let leaf = |s: &Vec4, light: u32, extent: f32| BshNode {
            center: s.truncate(),
            radius: s.w,
            child: BSH_NONE,
            next: BSH_NONE,
            light,
            extent,
        };
        let cell = self.spheres[a..b].iter().zip(&self.lights[a..b]).zip(&self.extents[a..b]);
        let tail = self.tail_spheres.iter().zip(&self.tail_lights).zip(&self.tail_extents);
        for ((s, &l), &e) in cell.chain(tail) {
            if bsh_reaches(leaf(s, l, e), x, r, rl) {
                visit(l);
            }
        }
        true
    }

    /// The largest range lobe `rl.w` the grid serves (1 for
    /// [`Self::build`]'s).
    pub fn reach(&self) -> f32 {
        self.reach
    }

    /// How many spheres a point at `x` tests (its cell's and the range
    /// tail's), or `None` outside the grid's box or for a NaN point.
    pub fn tested(&self, x: Vec3) -> Option<usize> {
        self.cell(x).map(|c| (self.start[c + 1] - self.start[c]) as usize + self.tail_lights.len())
    }

    /// The cell holding `x`, or `None` outside the grid's box (or NaN).
    fn cell(&self, x: Vec3) -> Option<usize> {
        if !(x.cmpge(self.lo).all() && x.cmple(self.hi).all()) {
            return None;
        }
        let c = ((x - self.lo) * self.inv).floor().min((self.n - 1).as_vec3()).as_uvec3();
        Some(((c.z * self.n.y + c.y) * self.n.x + c.x) as usize)
    }

    /// Entries in all cells (each light once per cell its box overlaps).
    pub fn entries(&self) -> usize {
        self.lights.len()
    }

    /// Cells along each axis.
    pub fn cells(&self) -> UVec3 {
        self.n
    }
}
