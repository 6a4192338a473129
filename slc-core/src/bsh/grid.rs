//! A uniform grid over a refitted [`Bsh`]'s leaves: the CPU's shortcut for
//! the walk of a Lambertian receiver.
//!
//! The stackless walk's cost is one dependent load per visited node, about
//! a hundred of them for one or two lights found among 49,152 on surfaces
//! (docs/results/bsh-walk-visits.md). A grid built after each refit lists,
//! in every cell, the leaves whose range sphere's box overlaps it; a point
//! tests the spheres of its own cell, then the range tail's, in the walk's
//! own order, with the walk's own leaf test ([`crate::sphere::sphere_contains_point`] on
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
//! the grid's, take the tree.
//!
//! A lobe scales no light's range outside a cone around its mirror
//! direction (its scale's lower clamp, 1): the scan of a glossy
//! receiver's cell keeps only the spheres that hold the point or whose
//! light's bound meets that cone ([`bsh_lobe_admits`], a test without
//! roots or divisions), and the walk's leaf test runs on those alone. So a grid
//! for the sharpest lobes ([`SHARP_REACH`]), whose cells list hundreds of
//! spheres, takes 0.27–0.38 of their walk's time
//! (docs/results/pt-suite-pairs.md).
//!
//! The GPU path tracer builds the same grids each pass with a counting sort
//! (slc-shared-shaders' `bsh_grid`), from the same frames
//! ([`GridFrame::levels`]), the same leaf order ([`walk_leaves`]) and the
//! same budget, cover and cell steps ([`WGSL`]: [`bsh_grid_budget`],
//! [`bsh_grid_reach`], [`bsh_grid_pad`], [`bsh_grid_radius`], [`bsh_grid_axis`],
//! [`bsh_grid_first`], [`bsh_grid_last`], [`bsh_grid_cell`]), and cuts a
//! glossy receiver's cell with the same cone ([`lobe_cone`],
//! [`bsh_lobe_admits`]).

use super::walk::bsh_reaches;
use super::{BSH_NONE, BSH_TAIL, Bsh, BshNode, bsh_reach_bound};
use crate::importance::range_scale_at;
use crate::ray::finite3;
use crate::wgsl::*;
use alloc::vec;
use alloc::vec::Vec;
use glam::{UVec3, Vec2, Vec3, Vec4};

crate::shared! {
    /// Most entries a grid may hold per light in the tree (plus one per cell;
    /// 20 bytes each): past it the resolution halves, and below
    /// [`GRID_RES_MIN`] there is no grid (ranges as large as the scene: the
    /// tree is as good). The suite's scenes take 2–5 at their own resolution.
    pub const GRID_ENTRIES_PER_LIGHT: u32 = 8;

    /// The most entries a grid of `cells` cells may hold for `leaves`
    /// leaves in the tree: [`GRID_ENTRIES_PER_LIGHT`] per leaf plus one
    /// per cell, at most `2³² − 1`, and at least `least` (the sharp grid's
    /// [`SHARP_GRID_ENTRIES`], 0 for the others).
    pub fn bsh_grid_budget(leaves: u32, cells: u32, least: u32) -> u32 {
        if leaves > 536870911 {
            return 4294967295;
        }
        let e: u32 = leaves * GRID_ENTRIES_PER_LIGHT;
        let t: u32 = add_wrap_u32(e, cells);
        return max(select(t, 4294967295, t < e), least);
    }

    /// A grid's cells: the box `(lo, hi)`, `inv` cells per unit length
    /// along each axis and `(nx, ny, nz)` cells (cell `(x, y, z)` is
    /// `(z·ny + y)·nx + x`); 48 bytes, the same layout in Rust and WGSL.
    pub struct GridFrame {
        /// The box's lower corner.
        pub lo: vec3f,
        /// Cells along x.
        pub nx: u32,
        /// The box's upper corner.
        pub hi: vec3f,
        /// Cells along y.
        pub ny: u32,
        /// Cells per unit length along each axis.
        pub inv: vec3f,
        /// Cells along z.
        pub nz: u32,
    }

    /// The farthest from its centre that leaf `node`'s test reaches for a
    /// receiver whose range lobe is at most `w` ([`crate::bsh::walk::bsh_reaches`]):
    /// its sphere, and for `w > 1` also the walk's own glossy bound
    /// [`bsh_reach_bound`].
    pub fn bsh_grid_reach(node: BshNode, w: f32) -> f32 {
        if w > 1.0 {
            return max(node.radius, bsh_reach_bound(node, w));
        }
        return node.radius;
    }

    /// A leaf's reach padded for its box of cells: the leaf test rounds,
    /// the box must not (a relative 1e-5), and squares underflow, so a
    /// point within ~5e-23 of a centre passes even a zero radius. A reach
    /// above 1e19 (its square may overflow, and the test then holds
    /// everywhere) becomes the largest f32: every cell.
    pub fn bsh_grid_pad(reach: f32) -> f32 {
        if reach > 1e19 {
            return 3.4028235e38;
        }
        return reach * (1.0 + 1e-5) + 1e-22;
    }

    /// The cell along one axis (from `lo`, `inv` cells per unit, `n`
    /// cells) holding the coordinate `v`: `⌊(v − lo)·inv⌋` kept in
    /// `[0, n − 1]` (a NaN coordinate lands in the range too). The
    /// conversion's truncation is the floor: the value is first kept at or
    /// above 0 (a software `floor` cost the CPU's grid lookup 1.6% of a
    /// path tracer's time).
    pub fn bsh_grid_axis(v: f32, lo: f32, inv: f32, n: u32) -> u32 {
        return min(to_u32(max((v - lo) * inv, 0.0)), n - 1);
    }

    /// The radius about leaf `node`'s centre whose box of cells a grid for
    /// range lobes up to `w` lists it in: [`bsh_grid_reach`] padded by
    /// [`bsh_grid_pad`].
    pub fn bsh_grid_radius(node: BshNode, w: f32) -> f32 {
        return bsh_grid_pad(bsh_grid_reach(node, w));
    }

    /// The first cell along each axis of frame `f` that a leaf centred at
    /// `c` reaching `r` ([`bsh_grid_radius`]) covers.
    pub fn bsh_grid_first(f: GridFrame, c: vec3f, r: f32) -> vec3u {
        return vec3u(bsh_grid_axis(c.x - r, f.lo.x, f.inv.x, f.nx), bsh_grid_axis(c.y - r, f.lo.y, f.inv.y, f.ny), bsh_grid_axis(c.z - r, f.lo.z, f.inv.z, f.nz));
    }

    /// The last cell along each axis of frame `f` that a leaf centred at
    /// `c` reaching `r` covers.
    pub fn bsh_grid_last(f: GridFrame, c: vec3f, r: f32) -> vec3u {
        return vec3u(bsh_grid_axis(c.x + r, f.lo.x, f.inv.x, f.nx), bsh_grid_axis(c.y + r, f.lo.y, f.inv.y, f.ny), bsh_grid_axis(c.z + r, f.lo.z, f.inv.z, f.nz));
    }

    /// The cell of frame `f` holding the point `x`, or `BSH_NONE` outside
    /// its box (or for a NaN point).
    pub fn bsh_grid_cell(f: GridFrame, x: vec3f) -> u32 {
        let inside: bool = x.x >= f.lo.x && x.y >= f.lo.y && x.z >= f.lo.z && x.x <= f.hi.x && x.y <= f.hi.y && x.z <= f.hi.z;
        if !inside {
            return BSH_NONE;
        }
        let cx: u32 = bsh_grid_axis(x.x, f.lo.x, f.inv.x, f.nx);
        let cy: u32 = bsh_grid_axis(x.y, f.lo.y, f.inv.y, f.ny);
        let cz: u32 = bsh_grid_axis(x.z, f.lo.z, f.inv.z, f.nz);
        return (cz * f.ny + cy) * f.nx + cx;
    }

    /// The relative padding of a light's extent in [`lobe_cone_meets`]
    /// (against rounding).
    pub const LOBE_CONE_PAD: f32 = 1.001;

    /// The cone around a glossy receiver's mirror direction outside which
    /// its range lobe `rl` ([`crate::brdf::range_lobe`]) scales no light's
    /// range, as `(cos² θ, 1/sin θ)`, or `(0, 0)` where it would be no
    /// narrower than a half-space (`k_d` near 1, a wide lobe), or the lobe
    /// or the mirror direction `r` (the cone's axis) is not finite (no cut). [`range_scale_at`] is exactly 1 (its lower
    /// clamp) for every direction at an angle beyond `θ₁` from the mirror
    /// direction, where `k_d + c_s·α²/t² = 1`, i.e.
    /// `t₁ = √(c_s·α²/(1 − k_d))` and `cos θ₁ = 2(1 − t₁)/(1 − α²) − 1`
    /// (`t = (1 + cos θ)/2·(α² − 1) + 1`), lowered until
    /// `range_scale_at(rl, cos θ₁)` reads 1 in f32 (the function is
    /// monotone, and so is its rounded value), then widened by 10⁻³ in its
    /// cosine for the rounding of [`crate::importance::cone_cos_of`] and of
    /// [`lobe_cone_meets`]. A light's bound sphere that misses it gets
    /// scale 1.
    pub fn lobe_cone(r: vec3f, rl: vec4f) -> vec2f {
        if !(finite3(r) && rl.x < 1.0 && rl.y >= 0.0 && rl.z > 0.0 && rl.z < 1.0) {
            return vec2f(0.0, 0.0);
        }
        let t1: f32 = sqrt(rl.y * rl.z / (1.0 - rl.x));
        let mut c: f32 = 2.0 * (1.0 - t1) / (1.0 - rl.z) - 1.0;
        let mut tries: u32 = 0;
        while !(range_scale_at(rl, c) <= 1.0) {
            c -= 1e-4;
            tries += 1;
            if tries > 16 {
                return vec2f(0.0, 0.0);
            }
        }
        let w: f32 = min(min(c, 1.0) - 1e-3, 0.9999);
        if !(w > 0.0) {
            return vec2f(0.0, 0.0);
        }
        return vec2f(w * w, 1.0 / sqrt(1.0 - w * w));
    }

    #[inline(always)]
    /// Whether a light's bound sphere `(c, extent)`, seen from a receiver
    /// at `x` with `v = x − c` (`d2 = |v|²`), meets the cone
    /// `cone` ([`lobe_cone`]) around the mirror direction `axis` (unit)
    /// with its apex at `x`: the test of the centre against the cone with
    /// its apex moved back along the axis by the padded extent over sin θ
    /// (no square root, no division).
    pub fn lobe_cone_meets(v: vec3f, d2: f32, extent: f32, axis: vec3f, cone: vec2f) -> bool {
        let k: f32 = (extent * LOBE_CONE_PAD + 1e-30) * cone.y;
        let vd: f32 = -dot(v, axis);
        let a: f32 = vd + k;
        let b: f32 = d2 + k * (2.0 * vd + k);
        return a >= 0.0 && a * a >= b * cone.x;
    }

    #[inline(always)]
    /// A grid's cut of a glossy receiver's cell: whether the leaf sphere
    /// `(c, radius)` of a light bounded by `(c, extent)` may reach the
    /// receiver at `x` (mirror direction `axis`, range lobe's `rl.w` `w`,
    /// cone `cone` of [`lobe_cone`]): the sphere scaled by `w·1.0001`
    /// holds `x` (the walk's own first test, bit for bit),
    /// and the sphere itself holds `x` or the light's bound meets the cone
    /// ([`lobe_cone_meets`]; any, for `cone.y = 0`). What it rejects,
    /// [`bsh_reaches`] rejects: outside the cone the lobe scales the
    /// light's range by exactly 1, and the plain sphere misses `x`.
    pub fn bsh_lobe_admits(c: vec3f, radius: f32, extent: f32, x: vec3f, w: f32, axis: vec3f, cone: vec2f) -> bool {
        let v: vec3f = x - c;
        let d2: f32 = dot(v, v);
        let f: f32 = radius * (w * 1.0001);
        return d2 <= f * f && (cone.y == 0.0 || d2 <= radius * radius || lobe_cone_meets(v, d2, extent, axis, cone));
    }
}

impl GridFrame {
    /// The frames a grid over the box `(lo, hi)` (the scene's) tries for
    /// `n` lights in the tree: `∛(n/2)` cells along the box's longest axis
    /// within [`GRID_RES_MIN`]`..=`[`GRID_RES_MAX`], then halved down to
    /// [`GRID_RES_MIN`] ([`BshGrid::build`] takes the first whose entries
    /// fit [`GridFrame::budget`]). Empty for a box that is not finite, is
    /// inverted or is a single point (a flat one, a floor, gets a
    /// thickness).
    pub fn levels(lo: Vec3, hi: Vec3, n: usize) -> Vec<GridFrame> {
        let res = libm::cbrtf(n as f32 / 2.0) as u32;
        Self::levels_at(lo, hi, res.clamp(GRID_RES_MIN, GRID_RES_MAX))
    }

    /// [`GridFrame::levels`] from `res` cells along the longest axis
    /// (within [`GRID_RES_MIN`]`..=`[`GRID_RES_LIMIT`]). The box is padded:
    /// a flat one (a single wall or floor) gets a thickness, so no axis's
    /// cells are narrower than 10⁻³ of the longest, and every side a margin of 10⁻⁴
    /// of it, for points on the surfaces that rounding put outside.
    pub fn levels_at(lo: Vec3, hi: Vec3, res: u32) -> Vec<GridFrame> {
        let ext = hi - lo;
        if !(lo.is_finite()
            && ext.is_finite()
            && ext.min_element() >= 0.0
            && ext.max_element() > 0.0)
        {
            return Vec::new();
        }
        let pad = Vec3::splat(ext.max_element() * 1e-4);
        let lo = lo - pad;
        let ext = ext.max(Vec3::splat(ext.max_element() * 1e-3)) + 2.0 * pad;
        let hi = lo + ext;
        let mut res = res.clamp(GRID_RES_MIN, GRID_RES_LIMIT);
        let mut levels = Vec::new();
        loop {
            let cell = ext.max_element() / res as f32;
            let n = (ext / cell).ceil().as_uvec3().max(UVec3::ONE);
            let inv = n.as_vec3() / ext;
            if !inv.is_finite() {
                return levels;
            }
            levels.push(GridFrame { lo, nx: n.x, hi, ny: n.y, inv, nz: n.z });
            if res / 2 < GRID_RES_MIN {
                return levels;
            }
            res /= 2;
        }
    }

    /// Cells along each axis.
    pub fn dims(&self) -> UVec3 {
        UVec3::new(self.nx, self.ny, self.nz)
    }

    /// Cells in all.
    pub fn cells(&self) -> u64 {
        self.nx as u64 * self.ny as u64 * self.nz as u64
    }

    /// The most entries the frame may hold for `lights` leaves in the
    /// tree, at least `least` ([`bsh_grid_budget`]).
    pub fn budget(&self, lights: u64, least: u64) -> u64 {
        let (l, c) = (lights.min(u32::MAX as u64) as u32, self.cells().min(u32::MAX as u64) as u32);
        bsh_grid_budget(l, c, least.min(u32::MAX as u64) as u32) as u64
    }

    /// The cells `(first, last)` along each axis that a leaf centred at
    /// `c` reaching `r` (its [`bsh_grid_radius`]) covers
    /// ([`bsh_grid_first`], [`bsh_grid_last`]).
    pub fn cover(&self, c: Vec3, r: f32) -> (UVec3, UVec3) {
        (bsh_grid_first(*self, c, r), bsh_grid_last(*self, c, r))
    }
}

/// Fewest cells along the grid's longest axis: [`BshGrid::build`] takes
/// `∛(n/2)` for `n` lights, within these bounds (32 for 49,152 lights, 16 for
/// 2,048: the fastest of 16–128 on the suite; `cargo run --release -p
/// slc-scene --example grid_walk`).
pub const GRID_RES_MIN: u32 = 4;
/// Most cells along the grid's longest axis [`BshGrid::build`] takes.
pub const GRID_RES_MAX: u32 = 64;

/// The largest range lobe `rl.w` (the square root of a receiver's range
/// scale) a path tracer's glossy grid holds; sharper lobes take the sharp
/// grid ([`SHARP_REACH`]).
/// At 4, glossy-facing-49152's floor (GGX α 0.09) holds 92% of its
/// receivers (0.41 of the walk's time), its gold (α 0.16) 75% (0.41); at
/// 2 the floor's share falls to 68%, and at 8 a cell lists 758 spheres
/// (0.91 of the walk's time for the floor) (`cargo run --release -p
/// slc-scene --example grid_walk -- --glossy 0.3,0
/// scenes/suite/glossy-facing-49152.toml`).
pub const GLOSSY_REACH: f32 = 4.0;

/// The range lobe a path tracer's third grid holds: every receiver's,
/// `√`[`crate::brdf::RANGE_SCALE_MAX`] (GGX α below ~0.05 scales a
/// light's range by up to 8 toward its mirror direction). Its cells list
/// hundreds of spheres, which the scan's cone test
/// ([`BshGrid::for_each_reaching`]) cuts to the few near that direction.
pub const SHARP_REACH: f32 = 8.0;

/// The entries [`BshGrid::build_reaching_within`] allows the sharp grid at
/// least (2¹⁸, 6 MiB), above [`GRID_ENTRIES_PER_LIGHT`] per light: with a
/// few thousand lights, spheres 8× their range leave no frame within the
/// plain budget.
pub const SHARP_GRID_ENTRIES: u64 = 1 << 18;

/// Most cells along the longest axis [`BshGrid::build_at`] takes (2²⁴
/// cells at most).
pub const GRID_RES_LIMIT: u32 = 256;

/// The tree's leaves (node indices) in the order the stackless walk
/// visits them, the range tail's copies left out: a wide tree's node order
/// is not the walk's (its families sit side by side). What a grid lists in
/// each cell, in this order, on both backends.
pub fn walk_leaves(bsh: &Bsh) -> Vec<u32> {
    let (nodes, tree) = (bsh.nodes(), bsh.tree_len());
    let mut leaves = Vec::with_capacity(bsh.len());
    let mut i = if tree > 0 { 0u32 } else { BSH_NONE };
    while i != BSH_NONE && (i as usize) < tree {
        let n = nodes[i as usize];
        if n.child != BSH_NONE {
            i = n.child;
        } else {
            leaves.push(i);
            i = n.next;
        }
    }
    leaves
}

/// Spheres as four arrays, so that [`Spheres::scan`]'s test of a run of
/// them compiles to vector instructions.
#[derive(Clone, Debug, Default)]
struct Spheres {
    x: Vec<f32>,
    y: Vec<f32>,
    z: Vec<f32>,
    r: Vec<f32>,
}

/// Spheres [`Spheres::scan`] tests at once.
const SCAN_CHUNK: usize = 64;

impl Spheres {
    /// `n` spheres at the origin of radius 0 (filled by [`Spheres::set`]).
    fn zeroed(n: usize) -> Spheres {
        Spheres { x: vec![0.0; n], y: vec![0.0; n], z: vec![0.0; n], r: vec![0.0; n] }
    }

    fn push(&mut self, c: Vec3, r: f32) {
        self.x.push(c.x);
        self.y.push(c.y);
        self.z.push(c.z);
        self.r.push(r);
    }

    fn set(&mut self, at: usize, c: Vec3, r: f32) {
        (self.x[at], self.y[at], self.z[at], self.r[at]) = (c.x, c.y, c.z, r);
    }

    /// Sphere `k`: its centre and radius.
    fn get(&self, k: usize) -> (Vec3, f32) {
        (Vec3::new(self.x[k], self.y[k], self.z[k]), self.r[k])
    }

    fn len(&self) -> usize {
        self.x.len()
    }

    /// Calls `hit(k)`, in order, for each sphere `k` of `range` whose
    /// radius times `scale` holds `p`: [`crate::sphere::sphere_contains_point`]'s test,
    /// `(p − c)·(p − c) ≤ (scale·r)²` with the same operations in the same
    /// order (so the same answer, bit for bit), on [`SCAN_CHUNK`] spheres
    /// at a time: one loop of plain arithmetic over the four arrays, which
    /// the compiler turns into vector instructions, then the hits in order.
    #[inline]
    fn scan(
        &self,
        range: core::ops::Range<usize>,
        p: Vec3,
        scale: f32,
        mut hit: impl FnMut(usize),
    ) {
        let mut at = range.start;
        while at < range.end {
            let n = (range.end - at).min(SCAN_CHUNK);
            let (x, y, z, r) = (
                &self.x[at..at + n],
                &self.y[at..at + n],
                &self.z[at..at + n],
                &self.r[at..at + n],
            );
            let mut inside = [0u8; SCAN_CHUNK];
            for j in 0..n {
                let (dx, dy, dz) = (p.x - x[j], p.y - y[j], p.z - z[j]);
                let rj = r[j] * scale;
                inside[j] = (dx * dx + dy * dy + dz * dz <= rj * rj) as u8;
            }
            hits(&inside[..n.next_multiple_of(8)], at, &mut hit);
            at += n;
        }
    }

    /// [`Spheres::scan`] for a glossy receiver at `p` with mirror
    /// direction `axis` and cone `cone` ([`lobe_cone`]): calls `hit(k)`, in
    /// order, for each sphere `k` of `range` that [`bsh_lobe_admits`] (the
    /// light's extent `extents[k]`), in the same chunks and with the hits
    /// in order as [`Spheres::scan`].
    #[inline]
    fn scan_lobe(
        &self,
        range: core::ops::Range<usize>,
        extents: &[f32],
        p: Vec3,
        w: f32,
        (axis, cone): (Vec3, Vec2),
        mut hit: impl FnMut(usize),
    ) {
        let mut at = range.start;
        while at < range.end {
            let n = (range.end - at).min(SCAN_CHUNK);
            let (x, y, z, r, e) = (
                &self.x[at..at + n],
                &self.y[at..at + n],
                &self.z[at..at + n],
                &self.r[at..at + n],
                &extents[at..at + n],
            );
            let mut inside = [0u8; SCAN_CHUNK];
            for j in 0..n {
                let c = Vec3::new(x[j], y[j], z[j]);
                inside[j] = bsh_lobe_admits(c, r[j], e[j], p, w, axis, cone) as u8;
            }
            hits(&inside[..n.next_multiple_of(8)], at, &mut hit);
            at += n;
        }
    }

    /// [`bsh_lobe_admits`] for each sphere `k` of `range` (the light's
    /// extent `extents[k]`), calling `hit(k)` in order for those it admits:
    /// [`Spheres::scan_lobe`] where the lobe has a cone (`cone.1.y > 0`),
    /// else [`Spheres::scan`] of the spheres scaled by `w·1.0001`, the
    /// same test without the cone's terms.
    #[inline]
    fn scan_reaching(
        &self,
        range: core::ops::Range<usize>,
        extents: &[f32],
        p: Vec3,
        w: f32,
        cone: (Vec3, Vec2),
        hit: impl FnMut(usize),
    ) {
        if cone.1.y > 0.0 {
            self.scan_lobe(range, extents, p, w, cone, hit);
        } else {
            self.scan(range, p, w * 1.0001, hit);
        }
    }
}

/// Calls `hit(at + j)`, in order, for each `j` whose flag `inside[j]` is
/// set ([`Spheres::scan`]'s and [`Spheres::scan_lobe`]'s flags, one byte
/// each, a whole number of words: zeros past the chunk): eight flags a
/// word, since most words of a chunk hold no hit.
#[inline]
fn hits(inside: &[u8], at: usize, hit: &mut impl FnMut(usize)) {
    for (w, word) in inside.chunks_exact(8).enumerate() {
        let mut bits = u64::from_le_bytes(word.try_into().unwrap_or([0; 8]));
        while bits != 0 {
            hit(at + 8 * w + (bits.trailing_zeros() / 8) as usize);
            bits &= bits - 1;
        }
    }
}

/// A grid of one refit's leaf spheres (see the module docs).
#[derive(Clone, Debug)]
pub struct BshGrid {
    frame: GridFrame,
    /// The largest range lobe `rl.w` the cells hold (1: the plain spheres).
    reach: f32,
    /// Cell `c`'s entries are `start[c]..start[c + 1]`.
    start: Vec<u32>,
    /// Each entry's sphere `(centre, radius)`, light and light extent `R`
    /// (the extents only for a reach above 1: a glossy lobe's test reads
    /// them, the plain sphere test does not).
    spheres: Spheres,
    lights: Vec<u32>,
    extents: Vec<f32>,
    /// The range tail's spheres, lights and extents, tested at every point.
    tail_spheres: Spheres,
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
        Self::build_in(bsh, GridFrame::levels(lo, hi, bsh.len()), w, 0)
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
        Self::build_in(bsh, GridFrame::levels_at(lo, hi, res), w, 0)
    }

    /// [`Self::build_reaching`] allowed at least `entries` entries (a
    /// frame fits within the larger of them and its
    /// [`GridFrame::budget`]): the CPU's sharp-lobe grid
    /// ([`SHARP_GRID_ENTRIES`]; the GPU's third grid takes the same).
    pub fn build_reaching_within(
        bsh: &Bsh,
        lo: Vec3,
        hi: Vec3,
        w: f32,
        entries: u64,
    ) -> Option<BshGrid> {
        Self::build_in(bsh, GridFrame::levels(lo, hi, bsh.len()), w, entries)
    }

    /// The grid in the first of `levels` whose entries fit the larger of
    /// its [`GridFrame::budget`] and `entries`.
    fn build_in(bsh: &Bsh, levels: Vec<GridFrame>, w: f32, entries: u64) -> Option<BshGrid> {
        if bsh.is_empty() || !w.is_finite() {
            return None;
        }
        let w = w.max(1.0);
        // The walk's leaves in its order: the tree's (a marked leaf is
        // never found), then the tail's copies, chained from the root's
        // `next`.
        let nodes = bsh.nodes();
        let inside: Vec<u32> = walk_leaves(bsh)
            .into_iter()
            .filter(|&i| nodes[i as usize].light & BSH_TAIL == 0)
            .collect();
        let (mut tail_spheres, mut tail_lights, mut tail_extents) =
            (Spheres::default(), Vec::new(), Vec::new());
        let mut i = nodes[0].next;
        while i != BSH_NONE {
            let n = nodes[i as usize];
            tail_spheres.push(n.center, n.radius);
            tail_lights.push(n.light);
            if w > 1.0 {
                tail_extents.push(n.extent);
            }
            i = n.next;
        }
        let lights_in = inside.len() as u64;
        // Each leaf's centre and padded reach ([`bsh_grid_radius`]), the
        // same at every level.
        let reach: Vec<(Vec3, f32)> = inside
            .iter()
            .map(|&i| (nodes[i as usize].center, bsh_grid_radius(nodes[i as usize], w)))
            .collect();
        for frame in levels {
            let n = frame.dims();
            let cells = frame.cells() as usize;
            // The entries this level needs, counted before any is listed.
            let mut total = 0u64;
            for &(c, r) in &reach {
                let (a, b) = frame.cover(c, r);
                let d = b - a + 1;
                total += d.x as u64 * d.y as u64 * d.z as u64;
            }
            if total > frame.budget(lights_in, entries) {
                continue;
            }
            let covers: Vec<(UVec3, UVec3)> =
                reach.iter().map(|&(c, r)| frame.cover(c, r)).collect();
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
            // Each entry's leaf (its rank in the walk's order) scattered to
            // its cell, then the entries written in order from it: one
            // scattered write an entry instead of six.
            let mut fill = start.clone();
            let mut order = vec![0u32; total as usize];
            for (rank, &c) in covers.iter().enumerate() {
                each(c, &mut |c| {
                    order[fill[c] as usize] = rank as u32;
                    fill[c] += 1;
                });
            }
            let mut spheres = Spheres::zeroed(total as usize);
            let mut lights = vec![0u32; total as usize];
            let mut extents = vec![0f32; if w > 1.0 { total as usize } else { 0 }];
            for (at, &rank) in order.iter().enumerate() {
                let s = nodes[inside[rank as usize] as usize];
                spheres.set(at, s.center, s.radius);
                lights[at] = s.light;
                if let Some(e) = extents.get_mut(at) {
                    *e = s.extent;
                }
            }
            return Some(BshGrid {
                frame,
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
        None
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
        self.spheres.scan(a..b, x, 1.0, |k| visit(self.lights[k]));
        self.tail_spheres.scan(0..self.tail_spheres.len(), x, 1.0, |k| visit(self.tail_lights[k]));
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
        // `bsh_reaches` rejects a leaf whose sphere scaled by `rl.w·1.0001`
        // misses `x` before its lobe's scale: the scan runs that test (and
        // the cone's) on the whole cell, and only its hits take the full one.
        let cone = (r, lobe_cone(r, rl));
        let mut reaches = |spheres: &Spheres, lights: &[u32], extents: &[f32], k: usize| {
            let (center, radius) = spheres.get(k);
            let leaf = BshNode {
                center,
                radius,
                child: BSH_NONE,
                next: BSH_NONE,
                light: lights[k],
                extent: extents[k],
            };
            if bsh_reaches(leaf, x, r, rl) {
                visit(lights[k]);
            }
        };
        let (cell, tail) = (&self.spheres, &self.tail_spheres);
        cell.scan_reaching(a..b, &self.extents, x, rl.w, cone, |k| {
            reaches(cell, &self.lights, &self.extents, k)
        });
        tail.scan_reaching(0..tail.len(), &self.tail_extents, x, rl.w, cone, |k| {
            reaches(tail, &self.tail_lights, &self.tail_extents, k)
        });
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
        let c = bsh_grid_cell(self.frame, x);
        (c != BSH_NONE).then_some(c as usize)
    }

    /// Entries in all cells (each light once per cell its box overlaps).
    pub fn entries(&self) -> usize {
        self.lights.len()
    }

    /// Cells along each axis.
    pub fn cells(&self) -> UVec3 {
        self.frame.dims()
    }

    /// The grid's frame (its box and cells).
    pub fn frame(&self) -> GridFrame {
        self.frame
    }
}
