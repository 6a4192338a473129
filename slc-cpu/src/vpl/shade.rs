//! The shading loop: irradiance at a receiver from a list of VPLs, in
//! structure-of-arrays form so the loop runs on SIMD lanes.
//!
//! Every formula comes from slc-core: the VPL transfer
//! ([`slc_core::light::vpl_transfer`]), the keep test
//! ([`slc_core::range::slc_keep`]), the `1/p` weight
//! ([`slc_core::range::slc_weight`]) and the near-field split
//! ([`slc_core::interleave::vpl_near_weight`]).
//!
//! A receiver with a specular lobe also takes [`shade_specular`]: the same
//! lights, keep tests and weights, each term times the glTF BRDF
//! ([`slc_core::brdf::brdf_eval`]) less the receiver's diffuse albedo over
//! π, in a scalar loop (the SIMD loop of Lambertian receivers is
//! untouched).

use glam::Vec3;
use slc_core::brdf::{ggx_alpha, specular_correction};
use slc_core::cluster::{CLUSTER, ClusterGrid, box_overlaps_box};
use slc_core::interleave::{
    vpl_far_fixed_share, vpl_far_slc_share, vpl_far_weight, vpl_near_cull_range2,
    vpl_near_fixed_share, vpl_near_slc_share,
};
use slc_core::light::vpl_transfer;
use slc_core::range::{CullKind, cull_radius};
use slc_core::ray::F32_MAX;
use slc_core::sphere::sphere_overlaps_aabb;
use slc_scene::vpl::GBuffer;
use slc_scene::vpl::WorkCounts;

pub use crate::simd::SimdPath;

/// How a light list is evaluated: the culling kind of its ranges (the
/// frame's [`slc_scene::culling::Culling`]), for the far field of the
/// near-field split or for its near field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cull {
    /// The keep test and weight: stochastic (keep iff `d² < r²`, weight
    /// `1/p`), clamped (keep iff `d² < R²`, no reweighting: biased), or
    /// none (every light counts).
    pub kind: CullKind,
    /// The near field of the split: each light weighted by its near share
    /// [`slc_core::interleave::vpl_near_weight`] (the far field takes the
    /// rest, `1 − w`), under a fixed range (`r²` holds `R²`, or `∞`), or,
    /// stochastic, at each VPL's own flux (`rt2`, `r2` hold its own
    /// ranges, [`slc_core::interleave::vpl_near_range2`]:
    /// [`slc_core::interleave::vpl_near_slc_share`]).
    pub near: bool,
}

impl Cull {
    /// The far field (or an unsplit list) under `kind`.
    pub const fn far(kind: CullKind) -> Cull {
        Cull { kind, near: false }
    }

    /// The near field under `kind`.
    pub const fn near(kind: CullKind) -> Cull {
        Cull { kind, near: true }
    }

    /// The loop's const parameter (one monomorphised loop per value).
    const fn mode(self) -> u8 {
        match (self.near, self.kind) {
            (false, CullKind::Stochastic) => SLC,
            (false, CullKind::Clamped) => CLAMP,
            (false, CullKind::None) => NONE,
            (true, CullKind::Stochastic) => NEAR_SLC,
            (true, _) => NEAR,
        }
    }
}

/// [`Cull::mode`]'s values.
const SLC: u8 = 0;
const CLAMP: u8 = 1;
const NONE: u8 = 2;
const NEAR: u8 = 3;
const NEAR_SLC: u8 = 4;

/// A list of VPLs in SoA layout (one entry per light, same index in every
/// array). `rt2`/`r2` hold `r_t²` and `r²` under stochastic culling and
/// `R²` in `r2` under a clamped range.
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
    /// The box hierarchy over the list, when it was built as one
    /// ([`LightList::begin_tree`]).
    tree: Tree,
    /// Real lights when the list was padded by culling (else `len()`).
    real: usize,
}

/// The two-level box hierarchy over a list ([`slc_core::cluster`]):
/// clusters of the grid's numbering, the lights of cluster `c` at
/// `starts[c]..starts[c + 1]` (its lit lights only: a cluster may hold none),
/// each cluster's and each group's box of its lights' culling spheres
/// (empty, `[F32_MAX, −F32_MAX]`, where it holds none).
#[derive(Clone, Debug, Default)]
struct Tree {
    grid: Option<ClusterGrid>,
    starts: Vec<u32>,
    clusters: Vec<(Vec3, Vec3)>,
    groups: Vec<(Vec3, Vec3)>,
}

/// The empty box of a reduction over no point.
const EMPTY: (Vec3, Vec3) = (Vec3::splat(F32_MAX), Vec3::splat(-F32_MAX));

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
        self.tree.grid = None;
        self.tree.starts.clear();
    }

    /// Starts a list culled as a box hierarchy over `grid` (emptied first):
    /// push the lit lights of cluster 0, [`LightList::close_cluster`], and
    /// so on for every cluster of the grid's numbering in turn; then
    /// [`LightList::build_tree`].
    pub fn begin_tree(&mut self, grid: ClusterGrid) {
        self.clear();
        self.tree.grid = Some(grid);
        self.tree.starts.push(0);
    }

    /// Ends the current cluster: the lights pushed since the last call
    /// (or [`LightList::begin_tree`]) are its lights.
    pub fn close_cluster(&mut self) {
        self.tree.starts.push(self.len() as u32);
    }

    /// Computes the boxes of every cluster (its lights' culling spheres,
    /// `centre ± radius`) and of every group (its clusters' boxes), for
    /// [`LightList::cull_tree_into`].
    ///
    /// # Panics
    /// When the list was not begun as a tree, or not every cluster of its
    /// grid was closed (a bug of the caller, never input).
    pub fn build_tree(&mut self) {
        let t = &mut self.tree;
        let grid = t.grid.expect("a list begun with begin_tree");
        assert_eq!(t.starts.len() as u32, grid.clusters() + 1, "every cluster closed");
        t.clusters.clear();
        for c in 0..grid.clusters() as usize {
            let mut b = EMPTY;
            for j in t.starts[c] as usize..t.starts[c + 1] as usize {
                let (p, r) = (Vec3::new(self.px[j], self.py[j], self.pz[j]), self.radius[j]);
                b = (b.0.min(p - r), b.1.max(p + r));
            }
            t.clusters.push(b);
        }
        t.groups.clear();
        for g in 0..grid.groups() {
            let b = grid.group_range(g).fold(EMPTY, |b, c| {
                let (lo, hi) = t.clusters[c as usize];
                (b.0.min(lo), b.1.max(hi))
            });
            t.groups.push(b);
        }
    }

    /// Tile culling through the box hierarchy ([`LightList::build_tree`]):
    /// replaces `out` with the lights whose culling sphere overlaps the box
    /// `[lo, hi]`, testing every group box, the cluster boxes of the groups
    /// that meet it and the spheres of the clusters that meet it, as the
    /// GPU's kernels do; returns those tests. `hits` is scratch memory.
    pub fn cull_tree_into(
        &self,
        lo: Vec3,
        hi: Vec3,
        hits: &mut Vec<u32>,
        out: &mut LightList,
    ) -> WorkCounts {
        let (k, counts) = SimdPath::best().run(TreeCullOp { list: self, lo, hi, hits: &mut *hits });
        self.gather_into(&hits[..k], out);
        counts
    }

    /// Replaces `out` with the lights of this flat list (a tile's, culled
    /// by [`LightList::cull_tree_into`]) whose culling sphere overlaps the
    /// box `[lo, hi]`, in the list's order; returns the sphere tests (one
    /// a light). `hits` is scratch memory.
    pub fn cull_into(
        &self,
        lo: Vec3,
        hi: Vec3,
        hits: &mut Vec<u32>,
        out: &mut LightList,
    ) -> WorkCounts {
        let n = self.len_unpadded();
        if hits.len() <= n {
            hits.resize(n + 1, 0);
        }
        let k = SimdPath::best().run(FlatCullOp { list: self, lo, hi, hits: &mut *hits });
        self.gather_into(&hits[..k], out);
        WorkCounts { sphere_tests: n as u64, ..WorkCounts::default() }
    }

    /// Appends one light; its culling sphere has radius
    /// [`slc_core::range::cull_radius`]`(r²)`.
    pub fn push(&mut self, p: Vec3, n: Vec3, flux: Vec3, rt2: f32, r2: f32) {
        self.push_culled(p, n, flux, rt2, r2, r2);
    }

    /// Appends one light of the near field: its culling sphere has the
    /// radius of its range cut at the near radius,
    /// [`slc_core::interleave::vpl_near_cull_range2`]`(r², R_n²)`.
    pub fn push_near(&mut self, p: Vec3, n: Vec3, flux: Vec3, rt2: f32, r2: f32, near_r2: f32) {
        self.push_culled(p, n, flux, rt2, r2, vpl_near_cull_range2(r2, near_r2));
    }

    /// Appends one light whose culling sphere has squared radius `cull_r2`.
    fn push_culled(&mut self, p: Vec3, n: Vec3, flux: Vec3, rt2: f32, r2: f32, cull_r2: f32) {
        self.real = self.len() + 1;
        self.radius.push(cull_radius(cull_r2));
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

    /// Replaces `out` with the entries `hits` of this list, padded to a
    /// multiple of the SIMD width with entries that are never kept and carry
    /// no flux (`r² = 0`, `Φ = 0`), so the shading loop has no scalar tail.
    /// [`LightList::len_unpadded`] still counts only real lights.
    fn gather_into(&self, hits: &[u32], out: &mut LightList) {
        out.tree.grid = None;
        out.tree.starts.clear();
        out.real = hits.len();
        let len = hits.len().next_multiple_of(LANES);
        SimdPath::best().run(GatherOp { from: self, hits, to: out, len });
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

    /// Lights the list holds without allocating.
    pub fn capacity(&self) -> usize {
        self.px.capacity()
    }
}

/// Lights per pass of [`cull_range`]'s flag loop: a cluster.
const FLAGS: usize = CLUSTER as usize;

/// The lights of `range` whose culling sphere overlaps `[lo, hi]`, their
/// indices appended to `hits` from `k` on; returns the new `k`. Plain
/// loops over runs of [`FLAGS`] (a closure would not be compiled with the
/// caller's target features).
#[inline(always)]
fn cull_range(
    l: &LightList,
    range: std::ops::Range<usize>,
    lo: Vec3,
    hi: Vec3,
    hits: &mut [u32],
    mut k: usize,
) -> usize {
    let mut flags = [0u8; FLAGS];
    for a in range.clone().step_by(FLAGS) {
        let b = (a + FLAGS).min(range.end);
        let (px, py, pz, r) = (&l.px[a..b], &l.py[a..b], &l.pz[a..b], &l.radius[a..b]);
        for ((((f, &x), &y), &z), &r) in flags.iter_mut().zip(px).zip(py).zip(pz).zip(r) {
            *f = sphere_overlaps_aabb(Vec3::new(x, y, z), r, lo, hi) as u8;
        }
        for (j, &f) in (a..b).zip(&flags) {
            // Branch-free compaction: always write, advance on a hit.
            hits[k] = j as u32;
            k += f as usize;
        }
    }
    k
}

/// [`LightList::cull_tree_into`]'s traversal as a pulp operation: every
/// group box, then the cluster boxes of the groups that meet the tile,
/// then [`cull_range`] over the lights of the clusters that meet it.
struct TreeCullOp<'a> {
    list: &'a LightList,
    lo: Vec3,
    hi: Vec3,
    hits: &'a mut Vec<u32>,
}

impl pulp::WithSimd for TreeCullOp<'_> {
    type Output = (usize, WorkCounts);

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) -> (usize, WorkCounts) {
        let (l, lo, hi) = (self.list, self.lo, self.hi);
        let t = &l.tree;
        let grid = t.grid.expect("a list built with build_tree");
        if self.hits.len() <= l.len() {
            self.hits.resize(l.len() + 1, 0);
        }
        let mut counts = WorkCounts { tiles: 1, ..WorkCounts::default() };
        let mut k = 0;
        for (g, &(glo, ghi)) in t.groups.iter().enumerate() {
            counts.group_tests += 1;
            if !box_overlaps_box(glo, ghi, lo, hi) {
                continue;
            }
            for c in grid.group_range(g as u32) {
                counts.cluster_tests += 1;
                let (clo, chi) = t.clusters[c as usize];
                if !box_overlaps_box(clo, chi, lo, hi) {
                    continue;
                }
                let range = t.starts[c as usize] as usize..t.starts[c as usize + 1] as usize;
                counts.sphere_tests += range.len() as u64;
                k = cull_range(l, range, lo, hi, self.hits, k);
            }
        }
        (k, counts)
    }
}

/// [`LightList::cull_into`]'s [`cull_range`] over a flat list's real
/// lights as a pulp operation.
struct FlatCullOp<'a> {
    list: &'a LightList,
    lo: Vec3,
    hi: Vec3,
    hits: &'a mut Vec<u32>,
}

impl pulp::WithSimd for FlatCullOp<'_> {
    type Output = usize;

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) -> usize {
        cull_range(self.list, 0..self.list.len_unpadded(), self.lo, self.hi, self.hits, 0)
    }
}

/// [`LightList::gather_into`]'s copies as a pulp operation: each array's
/// entries `hits` (a vectorized gather where the path has one), then zeros
/// up to `len`.
struct GatherOp<'a> {
    from: &'a LightList,
    hits: &'a [u32],
    to: &'a mut LightList,
    len: usize,
}

impl pulp::WithSimd for GatherOp<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        let (f, t) = (self.from, self.to);
        let pairs: [(&mut Vec<f32>, &[f32]); 12] = [
            (&mut t.px, &f.px),
            (&mut t.py, &f.py),
            (&mut t.pz, &f.pz),
            (&mut t.nx, &f.nx),
            (&mut t.ny, &f.ny),
            (&mut t.nz, &f.nz),
            (&mut t.fr, &f.fr),
            (&mut t.fg, &f.fg),
            (&mut t.fb, &f.fb),
            (&mut t.rt2, &f.rt2),
            (&mut t.r2, &f.r2),
            (&mut t.radius, &f.radius),
        ];
        for (dst, src) in pairs {
            dst.clear();
            if let Some(last) = src.len().checked_sub(1) {
                // `min` proves the index in bounds, so the loop has no
                // branch; written once, without zeroing the hits' part first.
                dst.extend(self.hits.iter().map(|&j| src[(j as usize).min(last)]));
            }
            dst.resize(self.len, 0.0);
        }
    }
}

/// Lanes of the shading loop and padding of the tile lists: one AVX2
/// register of f32. Sixteen (one AVX-512 register) runs the unculled loop
/// 1.3× faster but SLC's short tile lists (about 24 lights) 1.2× slower,
/// from padding and per-pixel sums.
const LANES: usize = 8;

/// Irradiance at `x` (unit normal `n`) from every light of `list` under
/// `cull`, and the number of lights that passed the keep test. With
/// `near_r2 > 0` each light's transfer is split by its near share `w`
/// ([`slc_core::interleave::vpl_near_weight`]): the near field
/// ([`Cull::near`]) takes `w`, the far field `1 − w`. Runs on the CPU's best [`SimdPath`].
pub fn shade(
    list: &LightList,
    x: Vec3,
    n: Vec3,
    min_d2: f32,
    near_r2: f32,
    cull: Cull,
) -> (Vec3, u32) {
    shade_on(SimdPath::best(), list, x, n, min_d2, near_r2, cull)
}

/// [`shade`] on a chosen [`SimdPath`] (the baseline where the CPU lacks it).
pub fn shade_on(
    path: SimdPath,
    list: &LightList,
    x: Vec3,
    n: Vec3,
    min_d2: f32,
    near_r2: f32,
    cull: Cull,
) -> (Vec3, u32) {
    let mut out = Vec::with_capacity(1);
    shade_all_on(path, list, &[(x, n)], min_d2, near_r2, cull, &mut out);
    out[0]
}

/// [`shade`] at every receiver `(x, n)` of `receivers` (one tile's pixels),
/// appending `(irradiance, kept)` to `out` in receiver order: one dispatch
/// to the CPU's best [`SimdPath`] for the whole tile.
pub fn shade_all(
    list: &LightList,
    receivers: &[(Vec3, Vec3)],
    min_d2: f32,
    near_r2: f32,
    cull: Cull,
    out: &mut Vec<(Vec3, u32)>,
) {
    shade_all_on(SimdPath::best(), list, receivers, min_d2, near_r2, cull, out);
}

/// [`shade_all`] on a chosen [`SimdPath`].
#[inline(never)]
pub fn shade_all_on(
    path: SimdPath,
    list: &LightList,
    receivers: &[(Vec3, Vec3)],
    min_d2: f32,
    near_r2: f32,
    cull: Cull,
    out: &mut Vec<(Vec3, u32)>,
) {
    let at = At { list, receivers, min_d2, near_r2, out };
    match cull.mode() {
        SLC => path.run(ShadeOp::<SLC>(at)),
        CLAMP => path.run(ShadeOp::<CLAMP>(at)),
        NONE => path.run(ShadeOp::<NONE>(at)),
        NEAR => path.run(ShadeOp::<NEAR>(at)),
        _ => path.run(ShadeOp::<NEAR_SLC>(at)),
    }
}

/// The arguments of one [`shade_all`] call.
struct At<'a> {
    list: &'a LightList,
    receivers: &'a [(Vec3, Vec3)],
    min_d2: f32,
    near_r2: f32,
    out: &'a mut Vec<(Vec3, u32)>,
}

/// [`shade_impl`] over a tile's receivers as a pulp operation, so
/// [`SimdPath::run`] compiles it per instruction set.
struct ShadeOp<'a, const MODE: u8>(At<'a>);

impl<const MODE: u8> pulp::WithSimd for ShadeOp<'_, MODE> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        let a = self.0;
        // A plain loop: a closure would not be compiled with the path's
        // target features.
        a.out.reserve(a.receivers.len());
        // Two receivers per pass over the lights (AVX-512's 32 registers
        // hold both; the far field's loop −14% there, the same on AVX2).
        let mut pairs = a.receivers.chunks_exact(2);
        for pair in &mut pairs {
            a.out.extend(shade_impl::<MODE, 2>(a.list, [pair[0], pair[1]], a.min_d2, a.near_r2));
        }
        for &at in pairs.remainder() {
            a.out.extend(shade_impl::<MODE, 1>(a.list, [at], a.min_d2, a.near_r2));
        }
    }
}

/// The per-VPL term: irradiance per unit flux at the receiver `(x, n)`
/// from the VPL at `p` with normal `nl`, the Lambertian transfer
/// [`slc_core::light::vpl_transfer`]: irradiance, so the receiver's
/// diffuse albedo is applied after the denoise and a specular lobe's rest
/// of the BRDF by [`shade_specular`] over the same terms; culling and the
/// near/far partition are [`cull_share`]'s.
#[inline(always)]
fn transfer(p: Vec3, nl: Vec3, x: Vec3, n: Vec3, min_d2: f32) -> f32 {
    vpl_transfer(nl, n, x - p, min_d2)
}

/// What the loop multiplies a light's transfer by under culling mode
/// `MODE` ([`Cull::mode`]), from slc-core's shared functions: the keep
/// test, the `1/p` weight and the near or far share of the split; 0 where
/// the light is culled (padding entries, `r² = 0`, always are).
#[inline(always)]
fn cull_share<const MODE: u8>(rt2: f32, r2: f32, d2: f32, near_r2: f32) -> f32 {
    match MODE {
        SLC => vpl_far_slc_share(rt2, r2, d2, near_r2),
        // Clamp: r² = R².
        CLAMP => vpl_far_fixed_share(r2, d2, near_r2),
        // Unculled: the far share alone (no range to load or test).
        NONE => vpl_far_weight(d2, near_r2),
        // The near field at the VPL's own flux: r_t², r² its own ranges.
        NEAR_SLC => vpl_near_slc_share(rt2, r2, d2, near_r2),
        // The near field under a fixed range (clamp R², or ∞).
        _ => vpl_near_fixed_share(r2, d2, near_r2),
    }
}

/// One light's weighted transfer and keep flag (0 or 1) at `x`. Every
/// test is evaluated unconditionally so the loop stays branch-free (the
/// keep test is a coin flip per light: branches mispredict).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn term<const MODE: u8>(
    p: Vec3,
    nl: Vec3,
    rt2: f32,
    r2: f32,
    x: Vec3,
    n: Vec3,
    min_d2: f32,
    near_r2: f32,
) -> (f32, f32) {
    let v = x - p;
    let d2 = v.x * v.x + v.y * v.y + v.z * v.z;
    let share = cull_share::<MODE>(rt2, r2, d2, near_r2);
    let kept = share > 0.0;
    (if kept { transfer(p, nl, x, n, min_d2) * share } else { 0.0 }, if kept { 1.0 } else { 0.0 })
}

/// `L` consecutive entries of one SoA array.
#[inline(always)]
fn lanes<const L: usize>(a: &[f32], base: usize) -> &[f32; L] {
    a[base..base + L].try_into().expect("chunk of L lanes")
}

/// Sums over lights `start..end` (a multiple of `L` long) in chunks of `L`
/// lanes at each of `R` receivers `(x, n)`: the weighted flux and the kept
/// count. Each chunk is loaded once for all `R` (the loop is bound by its
/// loads); each receiver's sums are the same, term by term and in the same
/// order, for any `R`.
#[inline(always)]
fn lane_sums<const MODE: u8, const L: usize, const R: usize>(
    list: &LightList,
    start: usize,
    end: usize,
    at: [(Vec3, Vec3); R],
    min_d2: f32,
    near_r2: f32,
) -> [(Vec3, f32); R] {
    let mut acc = [([0.0f32; L], [0.0f32; L], [0.0f32; L], [0.0f32; L]); R];
    let mut base = start;
    while base < end {
        let (px, py, pz) =
            (lanes::<L>(&list.px, base), lanes::<L>(&list.py, base), lanes::<L>(&list.pz, base));
        let (nx, ny, nz) =
            (lanes::<L>(&list.nx, base), lanes::<L>(&list.ny, base), lanes::<L>(&list.nz, base));
        let (fr, fg, fb) =
            (lanes::<L>(&list.fr, base), lanes::<L>(&list.fg, base), lanes::<L>(&list.fb, base));
        let (rt2, r2) = (lanes::<L>(&list.rt2, base), lanes::<L>(&list.r2, base));
        for l in 0..L {
            let (p, nl) = (Vec3::new(px[l], py[l], pz[l]), Vec3::new(nx[l], ny[l], nz[l]));
            for ((x, n), (r, g, b, k)) in at.iter().zip(acc.iter_mut()) {
                let (w, kept) = term::<MODE>(p, nl, rt2[l], r2[l], *x, *n, min_d2, near_r2);
                r[l] += fr[l] * w;
                g[l] += fg[l] * w;
                b[l] += fb[l] * w;
                k[l] += kept;
            }
        }
        base += L;
    }
    let sum = |a: &[f32; L]| a.iter().sum::<f32>();
    acc.map(|(r, g, b, k)| (Vec3::new(sum(&r), sum(&g), sum(&b)), sum(&k)))
}

/// The light loop at `R` receivers at once: chunks of [`LANES`] lanes (the
/// lists' padding), then single lights (unpadded lists).
#[inline(always)]
fn shade_impl<const MODE: u8, const R: usize>(
    list: &LightList,
    at: [(Vec3, Vec3); R],
    min_d2: f32,
    near_r2: f32,
) -> [(Vec3, u32); R] {
    let len = list.len();
    let full = len / LANES * LANES;
    let chunks = lane_sums::<MODE, LANES, R>(list, 0, full, at, min_d2, near_r2);
    let tail = lane_sums::<MODE, 1, R>(list, full, len, at, min_d2, near_r2);
    core::array::from_fn(|j| (chunks[j].0 + tail[j].0, (chunks[j].1 + tail[j].1) as u32))
}

/// A receiver with a specular lobe as [`shade_specular`] sees it: its
/// position, unit shading normal, unit view direction (toward the eye) and
/// glTF material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Glossy {
    /// Position.
    pub x: Vec3,
    /// Unit shading normal.
    pub n: Vec3,
    /// Unit direction toward the eye.
    pub v: Vec3,
    /// Base colour.
    pub base: Vec3,
    /// Metallic factor.
    pub metallic: f32,
    /// GGX `α`.
    pub alpha: f32,
    /// The dielectric's `F0`.
    pub f0: Vec3,
    /// The dielectric's `F90`.
    pub f90: f32,
}

impl Glossy {
    /// G-buffer pixel `i` where it has a specular lobe
    /// ([`GBuffer::specular_at`]), else `None`.
    pub fn at(gb: &GBuffer, i: usize) -> Option<Glossy> {
        let s = gb.specular_at(i)?;
        let (x, base) = (gb.position[i], gb.albedo[i]);
        Some(Glossy {
            x,
            n: gb.normal[i],
            v: (gb.eye - x).normalize_or_zero(),
            base,
            metallic: s.metallic,
            alpha: ggx_alpha(s.roughness),
            f0: s.f0,
            f90: s.f90,
        })
    }

    /// `f(l, v) − c_diff/π` toward the unit direction `l`
    /// ([`slc_core::brdf::specular_correction`]).
    #[inline(always)]
    pub fn correction(&self, l: Vec3) -> Vec3 {
        specular_correction(
            self.base,
            self.metallic,
            self.f0,
            self.f90,
            self.alpha,
            self.n,
            self.v,
            l,
        )
    }
}

/// The specular correction at a receiver `g` from every light of `list`
/// under `cull`: `Σ Φ ⊙ (f(l, v) − c_diff/π) · T · share`, with each
/// light's transfer `T` and culling share exactly as [`shade`] weighs its
/// irradiance (the same lights kept), so `c_diff/π · E + S` is the BRDF's
/// outgoing radiance. A scalar loop.
pub fn shade_specular(list: &LightList, g: &Glossy, min_d2: f32, near_r2: f32, cull: Cull) -> Vec3 {
    match cull.mode() {
        SLC => specular_impl::<SLC>(list, g, min_d2, near_r2),
        CLAMP => specular_impl::<CLAMP>(list, g, min_d2, near_r2),
        NONE => specular_impl::<NONE>(list, g, min_d2, near_r2),
        NEAR => specular_impl::<NEAR>(list, g, min_d2, near_r2),
        _ => specular_impl::<NEAR_SLC>(list, g, min_d2, near_r2),
    }
}

fn specular_impl<const MODE: u8>(list: &LightList, g: &Glossy, min_d2: f32, near_r2: f32) -> Vec3 {
    let mut s = Vec3::ZERO;
    for j in 0..list.len() {
        let p = Vec3::new(list.px[j], list.py[j], list.pz[j]);
        // The irradiance loop's own term: the same keep test, share and
        // transfer; skipped where it is 0 (culled, or facing away).
        let (wt, _) = term::<MODE>(
            p,
            Vec3::new(list.nx[j], list.ny[j], list.nz[j]),
            list.rt2[j],
            list.r2[j],
            g.x,
            g.n,
            min_d2,
            near_r2,
        );
        if wt <= 0.0 {
            continue;
        }
        let flux = Vec3::new(list.fr[j], list.fg[j], list.fb[j]);
        s += flux * g.correction((p - g.x).normalize()) * wt;
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand_core::{RngCore, SeedableRng};

    /// Every instruction set the CPU has gives the baseline's irradiance
    /// within float-summation tolerance and the same kept counts, for every
    /// culling mode, with and without the near split.
    #[test]
    fn every_simd_path_matches_the_baseline() {
        let mut rng = rand_pcg::Pcg32::seed_from_u64(7);
        let mut u = || rng.next_u32() as f32 / 4294967296.0;
        let mut all = LightList::default();
        for _ in 0..1000 {
            let p = Vec3::new(u(), u(), u());
            let n = Vec3::new(u() - 0.5, u() - 0.5, 1.0).normalize();
            let rt2 = 0.01 * u();
            all.push(p, n, Vec3::new(u(), u(), u()), rt2, rt2 / (1.0 - u()).max(1e-3));
        }
        // Padded to whole SIMD chunks, as the frame's tile lists are.
        let mut list = LightList::default();
        all.gather_into(&(0..all.len() as u32).collect::<Vec<_>>(), &mut list);
        for path in SimdPath::ALL {
            if !path.is_available() {
                eprintln!("SKIP {path}: this CPU lacks it");
                continue;
            }
            for cull in [
                Cull::far(CullKind::Stochastic),
                Cull::far(CullKind::Clamped),
                Cull::far(CullKind::None),
                Cull::near(CullKind::None),
            ] {
                for near_r2 in [0.0, 0.04] {
                    let mut kept = 0;
                    for i in 0..64 {
                        // Above the lights, facing down at them.
                        let x = Vec3::new(u(), u(), 1.05 + 0.01 * i as f32);
                        let (e, k) = shade_on(path, &list, x, Vec3::NEG_Z, 1e-4, near_r2, cull);
                        let (e0, k0) = shade_on(
                            SimdPath::Baseline,
                            &list,
                            x,
                            Vec3::NEG_Z,
                            1e-4,
                            near_r2,
                            cull,
                        );
                        assert_eq!(k, k0, "{path} {cull:?}: kept");
                        kept += k;
                        assert!(
                            (e - e0).abs().max_element() <= 1e-5 * e0.max_element().max(1e-6),
                            "{path} {cull:?}: {e} vs {e0}"
                        );
                    }
                    // Without a split the near field holds nothing.
                    assert!(
                        kept > 0 || (cull == Cull::near(CullKind::None) && near_r2 == 0.0),
                        "{path} {cull:?} R_n² {near_r2}: nothing kept"
                    );
                }
            }
        }
    }
}
