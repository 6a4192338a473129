//! The shading of a frame's pixels: the reference (every VPL at every
//! pixel) and the interleaved far field with the near field of the split,
//! each culled per tile.

use super::VplContext;
use super::shade::{self, Cull, Glossy, LightList};
use super::tiling::{NO_RECEIVER, PartTiles, Tile, Tiling};
use glam::Vec3;
use rayon::prelude::*;
use slc_core::cluster::{CLUSTER, ClusterGrid, map_x, map_y};
use slc_core::interleave::{
    interleave_flux_scale, interleave_shift, shifted_subset, subset_side, vpl_near_range2,
};
use slc_core::light::vpl_threshold_range2;
use slc_core::range::{CullKind, random_range2};
use slc_core::xi::frame_xi;
use slc_scene::vpl::{Culling, PERIOD, VplSettings, WorkCounts};

/// What the shading of a frame's pixels returns (fields of [`Shaded`]):
/// irradiance (the near field included) and the near field alone, the
/// same two of the specular correction (empty without glossy pixels), the
/// kept counts and the loop evaluations.
#[derive(Default)]
pub(super) struct Fields {
    pub(super) irradiance: Vec<Vec3>,
    pub(super) near: Vec<Vec3>,
    pub(super) specular: Vec<Vec3>,
    pub(super) specular_near: Vec<Vec3>,
    pub(super) kept: Vec<u32>,
    pub(super) evaluations: u64,
    pub(super) far_work: WorkCounts,
    pub(super) near_work: WorkCounts,
}

impl VplContext {
    /// Every lit VPL at every pixel (an unlit one adds nothing; neither
    /// backend loops over it).
    pub(super) fn shade_reference(&self) -> Fields {
        let v = &self.inputs.vpls;
        let mut list = LightList::default();
        for i in (0..v.len()).filter(|&i| v.flux[i] != Vec3::ZERO) {
            list.push(v.position[i], v.normal[i], v.flux[i], f32::INFINITY, f32::INFINITY);
        }
        let gb = &self.inputs.gbuffer;
        let out: Vec<(Vec3, u32)> = (0..gb.position.len())
            .into_par_iter()
            .map(|i| {
                if gb.valid(i) {
                    shade::shade(
                        &list,
                        gb.position[i],
                        gb.normal[i],
                        self.inputs.min_d2,
                        0.0,
                        Cull::far(CullKind::None),
                    )
                } else {
                    (Vec3::ZERO, 0)
                }
            })
            .collect();
        let shaded = (0..out.len()).filter(|&i| gb.valid(i)).count() as u64;
        let specular = self.specular_at_every_glossy_pixel(|g| {
            shade::shade_specular(&list, g, self.inputs.min_d2, 0.0, Cull::far(CullKind::None))
        });
        Fields {
            irradiance: out.iter().map(|o| o.0).collect(),
            near: Vec::new(),
            specular,
            specular_near: Vec::new(),
            kept: out.iter().map(|o| o.1).collect(),
            evaluations: shaded * list.len_unpadded() as u64,
            ..Fields::default()
        }
    }

    /// `shade(g)` at every pixel with a specular lobe, zero elsewhere;
    /// empty when no pixel has one.
    pub(super) fn specular_at_every_glossy_pixel(
        &self,
        shade: impl Fn(&Glossy) -> Vec3 + Sync,
    ) -> Vec<Vec3> {
        let gb = &self.inputs.gbuffer;
        if !gb.has_specular() {
            return Vec::new();
        }
        (0..gb.position.len())
            .into_par_iter()
            .map(|i| Glossy::at(gb, i).map_or(Vec3::ZERO, |g| shade(&g)))
            .collect()
    }

    /// Interleaved sampling with tiled culling per sub-image: the far field
    /// plus the near field ([`VplContext::shade_near_in`]), the near field
    /// alone, the same two of the specular correction at the pixels with a
    /// specular lobe, the kept counts and evaluations of both. The tiles are
    /// the context's [`Tiling::interleaved`] (built with the G-buffer) for
    /// the default tile size, built here for another.
    pub(super) fn shade_interleaved(&self, s: &VplSettings) -> Fields {
        let gb = &self.inputs.gbuffer;
        let p = PERIOD as usize;
        let cull = Cull::far(s.culling.kind());
        let (w, h) = (gb.width as usize, gb.height as usize);
        let near_r2 = s.near_r2(self.inputs.min_d2);
        let owned;
        let tiling = if s.tile as usize == self.from_gbuffer.far_tile {
            &self.from_gbuffer.far
        } else {
            owned = Tiling::interleaved(gb, p, s.tile as usize);
            &owned
        };
        let min_d2 = self.inputs.min_d2;
        let mut reused = self.take_reused();
        let ranges = self.ranges(s);
        let shift = interleave_shift(s.seed, s.frame, PERIOD);
        let (mut far, mut near_lights) =
            (std::mem::take(&mut reused.far), std::mem::take(&mut reused.near_lights));
        // The near field's light list is built (one thread) while the far
        // field is shaded (the other, and both once it is built).
        rayon::join(
            || {
                far.shade_parts(tiling, |class, part, out, spec, scratch| {
                    self.subset_lights_into(
                        &mut scratch.all,
                        shifted_subset(class as u32, shift, PERIOD) as usize,
                        &ranges,
                    );
                    shade_part(
                        part,
                        &scratch.all,
                        cull.kind != CullKind::None,
                        cull,
                        min_d2,
                        near_r2,
                        out,
                        spec,
                        &mut scratch.lists,
                    )
                })
            },
            || self.near_lights_into(&mut near_lights, &ranges, near_r2, cull),
        );
        let mut near = std::mem::take(&mut reused.near);
        self.shade_near_in(&mut near, &self.from_gbuffer.near, &near_lights, near_r2, cull);
        // Each pixel adds its far field to its near field, in parallel, in
        // one pass that also writes the near field alone.
        let nt = &self.from_gbuffer.near;
        let (mut irradiance, mut kept, mut near_field) =
            (reused.vec3(), reused.counts(), reused.vec3());
        let sum = |i: usize| {
            let ((f, kf), (n, kn)) = (far.at(tiling, i), near.at(nt, i));
            ((f + n, kf + kn), n)
        };
        if near.out.is_empty() {
            (0..w * h)
                .into_par_iter()
                .map(|i| sum(i).0)
                .unzip_into_vecs(&mut irradiance, &mut kept);
        } else {
            let mut all = ((irradiance, kept), near_field);
            all.par_extend((0..w * h).into_par_iter().map(sum));
            ((irradiance, kept), near_field) = all;
        }
        // A field per pixel, empty where `present` is false.
        let mut pixels = |present: bool, value: &(dyn Fn(usize) -> Vec3 + Sync)| -> Vec<Vec3> {
            let mut out = reused.vec3();
            if present {
                out.par_extend((0..w * h).into_par_iter().map(value));
            }
            out
        };
        let specular =
            pixels(!far.spec.is_empty(), &|i| far.specular_at(tiling, i) + near.specular_at(nt, i));
        let specular_near = pixels(!near.spec.is_empty(), &|i| near.specular_at(nt, i));
        let (far_work, near_work) = (far.work, near.work);
        let evaluations = far_work.tested + near_work.tested;
        (reused.far, reused.near, reused.near_lights) = (far, near, near_lights);
        self.keep_reused(reused);
        Fields {
            irradiance,
            near: near_field,
            specular,
            specular_near,
            kept,
            evaluations,
            far_work,
            near_work,
        }
    }

    /// Each VPL's interleaved ranges `(r_t², r²)` under the frame's
    /// culling ([`light_ranges`], flux × `P²`), computed once per frame for
    /// the far and the near field.
    pub(super) fn ranges(&self, s: &VplSettings) -> Vec<(f32, f32)> {
        let v = &self.inputs.vpls;
        let scale = interleave_flux_scale(PERIOD);
        (0..v.len()).into_par_iter().map(|i| light_ranges(s, i, v.flux[i] * scale)).collect()
    }

    /// The far field's lights of VPL subset `sub` (`sy·P + sx`) into `all`
    /// (emptied first): its lit VPLs at the interleaved flux (each pixel
    /// sees 1/P² of the VPLs, so each counts P²×) with their interleaved
    /// `ranges`, as a box hierarchy over the subset's image in map order
    /// ([`slc_core::cluster`]: clusters of 8×8 subset texels, groups of
    /// 8×8 clusters; the image padded to a multiple of 8 texels, its
    /// padding and unlit texels left out), the GPU's order.
    pub(super) fn subset_lights_into(
        &self,
        all: &mut LightList,
        sub: usize,
        ranges: &[(f32, f32)],
    ) {
        let v = &self.inputs.vpls;
        let (p, size) = (PERIOD as usize, v.size as usize);
        let (sx, sy, m) = (sub % p, sub / p, size / p);
        let side = subset_side(v.size, PERIOD);
        let scale = interleave_flux_scale(PERIOD);
        map_order_tree(all, side, |all, u, w| {
            if u >= m || w >= m {
                return;
            }
            let i = (sy + w * p) * size + sx + u * p;
            if v.flux[i] != Vec3::ZERO {
                let (rt2, r2) = ranges[i];
                all.push(v.position[i], v.normal[i], v.flux[i] * scale, rt2, r2);
            }
        });
    }

    /// The near field's lights into `all` (emptied first): the lit VPLs of
    /// every subset at their own flux, as a box hierarchy over the RSM in
    /// map order ([`slc_core::cluster`]: clusters of 8×8 texels, groups of
    /// 8×8 clusters), the GPU's order, with the ranges `cull` gives them
    /// (from the interleaved `ranges`: SLC with each VPL's own ranges and
    /// the far field's ξ, [`slc_core::interleave::vpl_near_range2`]; clamp
    /// at its range; none not at all) and culling spheres of radius
    /// `min(r, R_n)`. Empty when `near_r2 = 0`.
    pub(super) fn near_lights_into(
        &self,
        all: &mut LightList,
        ranges: &[(f32, f32)],
        near_r2: f32,
        cull: Cull,
    ) {
        all.clear();
        if near_r2 <= 0.0 {
            return;
        }
        let v = &self.inputs.vpls;
        let size = v.size as usize;
        map_order_tree(all, v.size, |all, tx, ty| {
            let i = ty * size + tx;
            if v.flux[i] != Vec3::ZERO {
                // The interleaved light's ranges, then the VPL's own.
                let (rt2, r2) = ranges[i];
                let (rt2, r2) = if cull.kind == CullKind::Stochastic {
                    (vpl_near_range2(rt2, PERIOD), vpl_near_range2(r2, PERIOD))
                } else {
                    (rt2, r2)
                };
                all.push_near(v.position[i], v.normal[i], v.flux[i], rt2, r2, near_r2);
            }
        });
    }

    /// The near field of the split ([`slc_core::interleave::vpl_near_weight`]):
    /// at every receiver of `tiling` (a [`Tiling::regions`]), the near share
    /// of the lights `all` ([`VplContext::near_lights_into`]) closer than
    /// `R_n = √near_r2`, culled as the method culls the far field (`cull`),
    /// into `r`: SLC at each VPL's own ranges
    /// ([`slc_core::interleave::vpl_near_slc_share`]: unbiased), clamp at
    /// its range, none not at all; with the kept counts and loop
    /// evaluations. Empty when `near_r2 = 0`. Each tile of full-resolution
    /// pixels culls `all`'s box hierarchy once (groups, clusters, then each
    /// light's sphere of radius `min(r, R_n)`,
    /// [`slc_core::interleave::vpl_near_cull_range2`]) against the box of
    /// its G-buffer positions.
    pub(super) fn shade_near_in(
        &self,
        r: &mut PerReceiver,
        tiling: &Tiling,
        all: &LightList,
        near_r2: f32,
        cull: Cull,
    ) {
        if near_r2 <= 0.0 {
            r.clear();
            return;
        }
        let near_cull = Cull::near(cull.kind);
        let min_d2 = self.inputs.min_d2;
        r.shade_parts(tiling, |_, part, out, spec, scratch| {
            shade_part(part, all, true, near_cull, min_d2, near_r2, out, spec, &mut scratch.lists)
        });
    }
}

/// Shades the receivers of one part of a tiling with the lights of `all`
/// under `cull` into `out` (`(irradiance, kept)`) and, at its glossy
/// receivers, the specular correction into `spec` (both the part's range
/// of a per-receiver buffer); returns the work. With `cull_lists`, each
/// tile culls `all` to its box through the list's box hierarchy
/// ([`LightList::cull_tree_into`], counted); without, every tile takes
/// every light.
#[allow(clippy::too_many_arguments)]
fn shade_part(
    part: &PartTiles,
    all: &LightList,
    cull_lists: bool,
    cull: Cull,
    min_d2: f32,
    near_r2: f32,
    out: &mut [(Vec3, u32)],
    spec: &mut [Vec3],
    lists: &mut CullLists,
) -> WorkCounts {
    let CullLists { fine, quarter, hits, shaded } = lists;
    let mut work = WorkCounts::default();
    for tile in &part.tiles {
        let lights = if cull_lists {
            work = work + all.cull_tree_into(tile.lo, tile.hi, hits, fine);
            &*fine
        } else {
            all
        };
        if tile.quarters.is_empty() {
            work = work + shade_tile(part, tile, lights, cull, min_d2, near_r2, out, spec, shaded);
            continue;
        }
        // The near field's quarters: each shades the tile's lights whose
        // sphere meets its own box.
        for q in &part.quarters[tile.quarters.clone()] {
            work = work + lights.cull_into(q.lo, q.hi, hits, quarter);
            work = work + shade_tile(part, q, quarter, cull, min_d2, near_r2, out, spec, shaded);
        }
    }
    work
}

/// Shades the receivers of `tile` (of `part`) with `lights` into `out` and
/// `spec` (as [`shade_part`]); returns the loops' work.
#[allow(clippy::too_many_arguments)]
fn shade_tile(
    part: &PartTiles,
    tile: &Tile,
    lights: &LightList,
    cull: Cull,
    min_d2: f32,
    near_r2: f32,
    out: &mut [(Vec3, u32)],
    spec: &mut [Vec3],
    shaded: &mut Vec<(Vec3, u32)>,
) -> WorkCounts {
    let r = tile.receivers.clone();
    shaded.clear();
    shade::shade_all(lights, &part.points[r.clone()], min_d2, near_r2, cull, shaded);
    out[r.clone()].copy_from_slice(shaded);
    for (k, g) in &part.glossy[tile.glossy.clone()] {
        spec[*k] = shade::shade_specular(lights, g, min_d2, near_r2, cull);
    }
    WorkCounts {
        tested: (lights.len_unpadded() * r.len()) as u64,
        kept: shaded.iter().map(|s| s.1 as u64).sum::<u64>(),
        pixels: r.len() as u64,
        ..WorkCounts::default()
    }
}

/// Builds `all` (emptied first) as a box hierarchy over a `side × side`
/// map in map order ([`slc_core::cluster::map_index`]): for every cluster
/// of [`ClusterGrid::map`] in turn, `push(all, tx, ty)` for its 8×8
/// texels row-major (pushing the texel's light where it has one), then the
/// cluster is closed; the boxes last.
fn map_order_tree(
    all: &mut LightList,
    side: u32,
    mut push: impl FnMut(&mut LightList, usize, usize),
) {
    let grid = ClusterGrid::map(side);
    all.begin_tree(grid);
    for c in 0..grid.clusters() {
        for q in c * CLUSTER..(c + 1) * CLUSTER {
            push(all, map_x(q, side) as usize, map_y(q, side) as usize);
        }
        all.close_cluster();
    }
    all.build_tree();
}

/// One worker's reused memory: a part's own light list (the far field's
/// subset) and [`shade_part`]'s lists.
#[derive(Default)]
pub(super) struct Scratch {
    all: LightList,
    lists: CullLists,
}

/// [`shade_part`]'s culled lists (a tile's, a quarter's), hit indices
/// and loop results, reused.
#[derive(Default)]
struct CullLists {
    fine: LightList,
    quarter: LightList,
    hits: Vec<u32>,
    shaded: Vec<(Vec3, u32)>,
}

/// A tiling's results per receiver ([`Tiling`]'s order): `(irradiance,
/// kept)`, the specular correction (empty without glossy pixels) and the
/// loop evaluations. Empty: nothing shaded (no near field).
#[derive(Default)]
pub(super) struct PerReceiver {
    pub(super) out: Vec<(Vec3, u32)>,
    pub(super) spec: Vec<Vec3>,
    pub(super) work: WorkCounts,
}

impl PerReceiver {
    /// Nothing shaded.
    pub(super) fn clear(&mut self) {
        self.out.clear();
        self.spec.clear();
        self.work = WorkCounts::default();
    }

    /// Every part `k` of `tiling` shaded by `shade(k, part, out, spec,
    /// scratch)` in parallel (into its range of the per-receiver buffers,
    /// with a worker's reused lists; returning its work), into
    /// this one's memory. Every receiver's `out` is written by its part;
    /// `spec` starts at zero where the tiling has glossy receivers and is
    /// empty where it has none.
    pub(super) fn shade_parts(
        &mut self,
        tiling: &Tiling,
        shade: impl Fn(usize, &PartTiles, &mut [(Vec3, u32)], &mut [Vec3], &mut Scratch) -> WorkCounts
        + Sync
        + Send,
    ) {
        // Every receiver's `out` is written below: its old values need no
        // clearing (only a new size is filled).
        let n = tiling.len();
        self.out.resize(n, (Vec3::ZERO, 0));
        self.spec.clear();
        if tiling.has_glossy() {
            self.spec.resize(n, Vec3::ZERO);
        }
        self.work = tiling
            .parts
            .par_iter()
            .zip(tiling.split(&mut self.out))
            .zip(tiling.split_glossy(&mut self.spec))
            .enumerate()
            .map_init(Scratch::default, |scratch, (k, ((part, out), spec))| {
                shade(k, part, out, spec, scratch)
            })
            .sum();
    }

    /// Pixel `i`'s `(irradiance, kept)`; zero where it has no receiver or
    /// nothing was shaded.
    pub(super) fn at(&self, tiling: &Tiling, i: usize) -> (Vec3, u32) {
        match tiling.receiver(i) {
            r if r != NO_RECEIVER && !self.out.is_empty() => self.out[r as usize],
            _ => (Vec3::ZERO, 0),
        }
    }

    /// Irradiance and kept count of each of the tiling's pixels (tests).
    #[cfg(test)]
    pub(super) fn per_pixel(&self, tiling: &Tiling) -> (Vec<Vec3>, Vec<u32>) {
        (0..tiling.pixels()).map(|i| self.at(tiling, i)).unzip()
    }

    /// Pixel `i`'s specular correction, zero as [`PerReceiver::at`].
    pub(super) fn specular_at(&self, tiling: &Tiling, i: usize) -> Vec3 {
        match tiling.receiver(i) {
            r if r != NO_RECEIVER && !self.spec.is_empty() => self.spec[r as usize],
            _ => Vec3::ZERO,
        }
    }
}

/// The ranges `(r_t², r²)` of VPL `i`'s interleaved light (flux `flux`,
/// already × `P²`) under `s.culling`: stochastic ranges from the error
/// bound and the VPL's ξ (`xi_for(seed, frame, i)`, or `fixed_xi`), the
/// clamp range `(0, R²)`, or `(∞, ∞)` unculled.
pub(super) fn light_ranges(s: &VplSettings, i: usize, flux: Vec3) -> (f32, f32) {
    match s.culling {
        Culling::Stochastic(params) => {
            let rt2 = vpl_threshold_range2(&params, flux);
            let xi = frame_xi(s.seed, s.frame, i as u32, s.fixed_xi.unwrap_or(-1.0));
            (rt2, random_range2(rt2, xi))
        }
        Culling::Clamped(r) => (0.0, r.get() * r.get()),
        Culling::None | Culling::Reference => (f32::INFINITY, f32::INFINITY),
    }
}
