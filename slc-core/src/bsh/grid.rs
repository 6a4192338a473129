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
//! same image. A grid cannot hold a glossy receiver's scaled ranges (their
//! scale depends on the receiver); those, and points outside the grid's
//! box, take the tree. The GPU keeps the stackless walk (a grid per pass
//! there is a counting sort the kernels do not have yet).

use super::{BSH_NONE, BSH_TAIL, Bsh};
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
    /// Cell `c`'s entries are `start[c]..start[c + 1]`.
    start: Vec<u32>,
    /// Each entry's sphere `(centre, radius)` and light.
    spheres: Vec<Vec4>,
    lights: Vec<u32>,
    /// The range tail's spheres and lights, tested at every point.
    tail_spheres: Vec<Vec4>,
    tail_lights: Vec<u32>,
}

impl BshGrid {
    /// The grid of `bsh`'s leaves as its last refit left them, over the box
    /// `(lo, hi)` (the scene's: a point outside it takes the tree), at
    /// `∛(n/2)` cells along the box's longest axis for `n` lights in the
    /// tree, within [`GRID_RES_MIN`]`..=`[`GRID_RES_MAX`] ([`Self::build_at`]).
    pub fn build(bsh: &Bsh, lo: Vec3, hi: Vec3) -> Option<BshGrid> {
        let res = libm::cbrtf(bsh.len() as f32 / 2.0) as u32;
        Self::build_at(bsh, lo, hi, res.clamp(GRID_RES_MIN, GRID_RES_MAX))
    }

    /// [`Self::build`] at `res` cells along the box's longest axis, halved
    /// while the entries pass [`GRID_ENTRIES_PER_LIGHT`]; `None` for an
    /// empty tree, a box that is not finite and positive, or ranges so
    /// large that even [`GRID_RES_MIN`] cells a side would pass it.
    pub fn build_at(bsh: &Bsh, lo: Vec3, hi: Vec3, res: u32) -> Option<BshGrid> {
        let ext = hi - lo;
        if !(lo.is_finite() && ext.is_finite() && ext.min_element() > 0.0) || bsh.is_empty() {
            return None;
        }
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
        let (mut inside, mut tail_spheres, mut tail_lights) = (Vec::new(), Vec::new(), Vec::new());
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
                // A radius whose square overflows holds every point (the
                // leaf test's `d² ≤ ∞`): every cell.
                if s.radius * s.radius == f32::INFINITY {
                    return (UVec3::ZERO, n - 1);
                }
                // Padded: the leaf test rounds, the box must not; and
                // squares underflow, so a point within ~5e-23 of a centre
                // passes even a zero radius.
                let r = s.radius * (1.0 + 1e-5) + 1e-22;
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
            for (&i, &c) in inside.iter().zip(&covers) {
                let s = nodes[i as usize];
                each(c, &mut |c| {
                    let at = fill[c] as usize;
                    spheres[at] = s.center.extend(s.radius);
                    lights[at] = s.light;
                    fill[c] += 1;
                });
            }
            return Some(BshGrid {
                lo,
                hi,
                inv,
                n,
                start,
                spheres,
                lights,
                tail_spheres,
                tail_lights,
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
