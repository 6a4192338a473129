//! Tests of [`super`]: its properties against brute force and closed forms.

use super::*;

fn pt(x: f32, y: f32, z: f32) -> LightBound {
    LightBound { center: Vec3::new(x, y, z), extent: 0.0 }
}

/// Either split rule and a width of 2, 3, 4 or 8, from two uniform
/// numbers.
fn shape_of(u: f32, v: f32) -> BshShape {
    let split = if u < 0.5 { BshSplit::Median } else { BshSplit::SphereArea };
    BshShape { split, width: [2, 3, 4, 8][(v * 4.0) as usize] }
}

/// The depth of the deepest leaf (the root's is 0).
fn depth(t: &Bsh) -> u32 {
    t.depths().into_iter().max().unwrap_or(0)
}

#[test]
fn links_form_preorder() {
    let b: Vec<_> = (0..7).map(|i| pt(i as f32, 0.0, 0.0)).collect();
    let t = Bsh::build(&b).unwrap();
    let n = t.nodes();
    assert_eq!(n.len(), 13);
    assert_eq!(n[0].next, BSH_NONE);
    for (i, node) in n.iter().enumerate() {
        if node.child != BSH_NONE {
            assert_eq!(node.child, i as u32 + 1);
            assert_eq!(bsh_range_bound(*node), 0.0, "no range before the first refit");
        } else {
            assert!(node.light < 7);
        }
    }
    // Every light appears in exactly one leaf.
    let mut seen = [0; 7];
    for node in n.iter().filter(|n| n.child == BSH_NONE) {
        seen[node.light as usize] += 1;
    }
    assert_eq!(seen, [1; 7]);
}

/// The split refit (subtrees above the grain refitted through `join`,
/// here the second before the first, which their independence allows)
/// leaves the same nodes as the serial one, bit for bit, over 300
/// lights with heavy-tailed ranges, an unbalanced count and extents, at
/// every grain, on balanced, sphere-area and 4-wide trees (which refit
/// serially); every light's leaf is its own.
#[test]
fn split_refit_equals_serial_refit() {
    let mut u = uniforms(5);
    let b: Vec<_> = (0..300)
        .map(|_| LightBound { center: Vec3::new(u(), u(), u()) * 10.0, extent: u() * 0.1 })
        .collect();
    let r2: Vec<f32> = (0..300).map(|_| 0.01 / (1.0 - u()).max(1e-6)).collect();
    let reversed: &Join = &|a, b| {
        b();
        a();
    };
    let sah = BshShape { split: BshSplit::SphereArea, width: 2 };
    for (tail, shape) in
        [(0, BshShape::BALANCED), (16, BshShape::BALANCED), (16, sah), (16, BshShape::WIDE)]
    {
        let mut serial = Bsh::build_with(&b, shape).unwrap().with_tail(tail).unwrap();
        serial.refit(&r2).unwrap();
        for grain in [0, 1, 2, 7, 64, 1000] {
            let mut split = Bsh::build_with(&b, shape).unwrap().with_tail(tail).unwrap();
            split.refit_split(&r2, grain, reversed).unwrap();
            assert!(serial.nodes() == split.nodes(), "grain {grain}, tail {tail}");
        }
        for l in 0..300 {
            let leaf = serial.leaf(l);
            assert!(leaf.child == BSH_NONE && leaf.light == l as u32);
            assert_eq!(leaf.radius, b[l].range_sphere(r2[l]).radius);
        }
        assert!(serial.refit_split(&[1.0], 8, reversed).is_err());
    }
}

/// The range tail holds the lights of the largest range spheres, at most
/// `k` and no fewer than the histogram's top bins that fit allow; their
/// tree leaves are marked and shrunk to their bounds; the root's sphere
/// no longer holds their ranges; a refit with a smaller tail, and
/// `with_tail(0)`, take them back. On a binary and a 4-wide tree.
#[test]
fn range_tail_takes_the_largest_spheres() {
    let mut u = uniforms(29);
    let n = 2000;
    let b: Vec<_> = (0..n)
        .map(|_| LightBound { center: Vec3::new(u(), u(), u()) * 10.0, extent: u() * 0.01 })
        .collect();
    let r2: Vec<f32> = (0..n).map(|_| 0.01 / (1.0 - u()).max(1e-9)).collect();
    let radius: Vec<f32> = b.iter().zip(&r2).map(|(b, &r)| b.range_sphere(r).radius).collect();
    for (shape, k) in
        [1, 4, 16, 64].into_iter().map(|k| (BshShape::BALANCED, k)).chain([(BshShape::WIDE, 16)])
    {
        let mut plain = Bsh::build_with(&b, shape).unwrap();
        plain.refit(&r2).unwrap();
        let mut t = Bsh::build_with(&b, shape).unwrap().with_tail(k).unwrap();
        t.refit(&r2).unwrap();
        assert_eq!((t.tail_capacity(), t.nodes().len()), (k, t.tree_len() + k));
        let tail: Vec<u32> = (0..n as u32)
            .filter(|&l| t.nodes()[t.leaves[l as usize] as usize].light & BSH_TAIL != 0)
            .collect();
        assert!(tail.len() <= k, "tail of {} for k = {k}", tail.len());
        // The tail is a top set: every light outside it is no larger.
        let smallest_in = tail.iter().map(|&l| radius[l as usize]).fold(f32::INFINITY, f32::min);
        let largest_out =
            (0..n).filter(|l| !tail.contains(&(*l as u32))).map(|l| radius[l]).fold(0.0, f32::max);
        assert!(tail.is_empty() || largest_out <= smallest_in);
        // With the next bin in, the tail would exceed k.
        let cut = bsh_tail_key(smallest_in.min(largest_out * 2.0)).min(bsh_tail_key(largest_out));
        let next_bin = (0..n).filter(|&l| bsh_tail_key(radius[l]) >= cut).count();
        assert!(next_bin > k || next_bin == tail.len(), "k = {k}: {next_bin} in the next bin");
        // The chain after the tree holds them in light order, with ranges.
        let mut chain = Vec::new();
        let mut i = t.nodes()[0].next;
        while i != BSH_NONE {
            let c = t.nodes()[i as usize];
            assert_eq!(c.radius, radius[c.light as usize]);
            chain.push(c.light);
            i = c.next;
        }
        assert_eq!(chain, tail);
        for &l in &tail {
            let leaf = t.nodes()[t.leaves[l as usize] as usize];
            assert_eq!(leaf.radius, b[l as usize].extent);
        }
        if k >= 16 {
            assert!(!tail.is_empty());
            assert!(t.nodes()[0].radius < plain.nodes()[0].radius);
        }
        let mut none = t.clone().with_tail(0).unwrap();
        none.refit(&r2).unwrap();
        assert!(none.nodes() == plain.nodes());
    }
    let plain = Bsh::build(&b).unwrap();
    assert!(matches!(plain.with_tail(65), Err(crate::BshError::TailTooLong(65))));
}

#[test]
fn empty_and_single() {
    let t = Bsh::build(&[]).unwrap();
    assert_eq!(t, Bsh::default());
    assert_eq!(Bsh::build_with(&[], BshShape::WIDE).unwrap().tree_len(), 0);
    let mut hits = 0;
    t.for_each_containing(Vec3::ZERO, |_| hits += 1);
    assert_eq!(hits, 0);
    let mut t = Bsh::build(&[pt(1.0, 2.0, 3.0)]).unwrap();
    t.refit(&[4.0]).unwrap();
    let mut got = Vec::new();
    t.for_each_containing(Vec3::new(1.0, 2.0, 4.5), |i| got.push(i));
    assert_eq!(got, [0]);
    got.clear();
    t.for_each_containing(Vec3::new(1.0, 2.0, 5.5), |i| got.push(i));
    assert!(got.is_empty());
}

#[test]
fn rejects_bad_input() {
    assert_eq!(Bsh::build(&[pt(f32::NAN, 0.0, 0.0)]), Err(BshError::NonFiniteCenter(0)));
    assert_eq!(
        Bsh::build(&[pt(0.0, 0.0, 0.0), pt(f32::INFINITY, 0.0, 0.0)]),
        Err(BshError::NonFiniteCenter(1))
    );
    // Queries with NaN or a negative radius match nothing (regression:
    // fuzz/bsh_vs_brute found a negative query radius answered
    // inconsistently by leaves and their parents).
    let mut t2 = Bsh::build(&[pt(0.0, 0.0, 0.0), pt(1.0, 0.0, 0.0)]).unwrap();
    t2.refit(&[1.0, 1.0]).unwrap();
    let mut hits = 0;
    t2.for_each_overlapping_sphere(Sphere::new(Vec3::ZERO, -5.0), |_| hits += 1);
    t2.for_each_overlapping_sphere(Sphere::new(Vec3::ZERO, f32::NAN), |_| hits += 1);
    t2.for_each_containing(Vec3::NAN, |_| hits += 1);
    t2.for_each_overlapping_aabb(Aabb { min: Vec3::NAN, max: Vec3::ONE }, |_| hits += 1);
    assert_eq!(hits, 0);
    let neg = LightBound { center: Vec3::ZERO, extent: -1.0 };
    assert!(matches!(Bsh::build(&[neg]), Err(BshError::BadExtent(0, _))));
    let mut t = Bsh::build(&[pt(0.0, 0.0, 0.0)]).unwrap();
    assert!(t.refit(&[]).is_err());
    assert!(t.refit(&[f32::NAN]).is_err());
    assert!(t.refit(&[-1.0]).is_err());
    assert!(t.refit(&[f32::INFINITY]).is_ok());
}

/// A stream of uniform numbers in `[0, 1]` from a fixed seed (PCG32's
/// draw over 2³², rounded to f32: one near 2³² reads 1): what the
/// randomized tests draw.
fn uniforms(seed: u64) -> impl FnMut() -> f32 {
    use rand_core::{RngCore, SeedableRng};
    let mut rng = rand_pcg::Pcg32::seed_from_u64(seed);
    move || rng.next_u32() as f32 / 4294967296.0
}

/// Queries equal brute force at every scale from 10³⁸ down to
/// subnormal spacings (regression: fuzz/bsh_vs_brute found lights
/// 10⁻²³ apart where squares underflow and a parent missed a point its
/// child held; before the absolute padding floor, ~1% of these failed).
/// The lights a query visits, sorted.
fn sorted(query: impl FnOnce(&mut dyn FnMut(u32))) -> Vec<u32> {
    let mut got = Vec::new();
    query(&mut |i| got.push(i));
    got.sort_unstable();
    got
}

#[test]
fn queries_match_brute_force_at_every_scale() {
    let mut u = uniforms(19);
    let mut mismatches = 0;
    for _ in 0..20_000 {
        let scale = 10f32.powf(38.0 - 83.0 * u());
        let n = 2 + (u() * 6.0) as usize;
        let b: Vec<LightBound> = (0..n)
            .map(|_| LightBound {
                center: (Vec3::new(u(), u(), u()) - 0.5) * scale,
                extent: if u() < 0.5 { 0.0 } else { u() * scale },
            })
            .collect();
        let r2: Vec<f32> = (0..n).map(|_| (u() * scale).powi(2)).collect();
        let tail = (u() * 4.0) as usize;
        let mut t = Bsh::build_with(&b, shape_of(u(), u())).unwrap().with_tail(tail).unwrap();
        t.refit(&r2).unwrap();
        let spheres: Vec<Sphere> = b.iter().zip(&r2).map(|(b, &r)| b.range_sphere(r)).collect();
        let brute = |test: &dyn Fn(&Sphere) -> bool| -> Vec<u32> {
            (0..n as u32).filter(|&i| test(&spheres[i as usize])).collect()
        };
        let x = (Vec3::new(u(), u(), u()) - 0.5) * scale;
        let q = Sphere::new(x, u() * scale);
        let bx = Aabb { min: x, max: x + Vec3::new(u(), u(), u()) * scale * 0.1 };
        mismatches += (sorted(|f| t.for_each_containing(x, f)) != brute(&|s| s.contains(x))) as u32;
        mismatches += (sorted(|f| t.for_each_overlapping_sphere(q, f))
            != brute(&|s| s.overlaps_sphere(&q))) as u32;
        mismatches += (sorted(|f| t.for_each_overlapping_aabb(bx, f))
            != brute(&|s| s.overlaps_aabb(&bx))) as u32;
    }
    assert_eq!(mismatches, 0);
}
/// An inner node's scale ([`walk::bsh_inner_scale`]) is never below
/// [`crate::importance::range_scale_toward`] of the same sphere (which
/// the leaves below take), and exceeds it by little (at most 10%, where
/// a mirror-like lobe's scale is steepest): receivers from
/// mirror-like (roughness 0.05) to rough, spheres from points to ones
/// holding the receiver, mirror directions grazing the sphere's cone.
#[test]
fn inner_scale_bounds_the_exact_scale_tightly() {
    use crate::brdf::{mirror_dir, range_lobe, receiver_lobe};
    use crate::importance::range_scale_toward;
    let mut u = uniforms(29);
    let (mut below, mut worst, mut tested) = (0, 1.0f32, 0);
    for k in 0..200_000 {
        let nrm = (Vec3::new(u(), u(), u()) - 0.5).normalize();
        let view = (Vec3::new(u(), u(), u()) - 0.5 + nrm).normalize();
        let alpha = (0.05 + 0.95 * u() * u()).powi(2);
        let lobe = receiver_lobe(
            Vec3::splat(0.8),
            if u() < 0.5 { 1.0 } else { 0.0 },
            Vec3::splat(0.04),
            1.0,
            alpha,
            nrm.dot(view),
        );
        let (r, rl) = (mirror_dir(nrm, view), range_lobe(lobe));
        if rl.w <= 1.0 {
            continue;
        }
        let x = Vec3::new(u(), u(), u()) - 0.5;
        // Every fourth centre lies near the mirror direction's cone edge.
        let dist = 0.01 + 2.0 * u();
        let radius = dist * [0.0, 0.01, 0.3, 1.2][k % 4] * u();
        let c = if k % 4 == 0 {
            x + (r + (Vec3::new(u(), u(), u()) - 0.5) * 0.02).normalize() * dist
        } else {
            x + (Vec3::new(u(), u(), u()) - 0.5).normalize() * dist
        };
        let v = c - x;
        let exact = range_scale_toward(rl, c, radius, x, r);
        let inner = walk::bsh_inner_scale(radius, v, v.dot(v), r, rl);
        below += (inner < exact) as u32;
        worst = worst.max(inner / exact);
        tested += 1;
    }
    assert!(tested > 50_000, "{tested}");
    assert_eq!(below, 0);
    // 2e-6 in the cosine near a mirror-like lobe's peak, where the
    // scale changes fastest (`∂ ln s/∂ cos θ` up to about `1/t`).
    assert!(worst < 1.1, "inner scale up to {worst}× the exact one");
}

/// A glossy receiver's walk ([`Bsh::for_each_reaching`]) finds exactly
/// the lights whose own sphere, scaled by the receiver's scale toward
/// that light ([`crate::importance::range_scale_toward`]), holds the
/// point: every light tested by brute force, for random receivers
/// (roughness 0.05 to 1, metallic and dielectric, any view) among
/// clustered lights whose heavy-tailed ranges inflate the inner spheres.
/// Some lights get less than the receiver's peak scale, some the peak.
#[test]
fn glossy_walk_matches_brute_force() {
    use crate::brdf::{range_lobe, range_scale, receiver_lobe};
    use crate::importance::range_scale_toward;
    let mut u = uniforms(23);
    let (mut mismatches, mut found, mut below_peak, mut at_peak) = (0, 0, 0, 0);
    for _ in 0..2_000 {
        let n = 2 + (u() * 60.0) as usize;
        let b: Vec<LightBound> = (0..n)
            .map(|_| LightBound {
                center: Vec3::new(u(), u(), u()) - 0.5,
                extent: if u() < 0.5 { 0.0 } else { 0.02 * u() },
            })
            .collect();
        let r2: Vec<f32> = (0..n).map(|_| (0.05 / (1.0 - u()).sqrt()).powi(2)).collect();
        let tail = [0, 1, 8][(u() * 3.0) as usize];
        let mut t = Bsh::build_with(&b, shape_of(u(), u())).unwrap().with_tail(tail).unwrap();
        t.refit(&r2).unwrap();
        let x = Vec3::new(u(), u(), u()) - 0.5;
        let nrm = (Vec3::new(u(), u(), u()) - 0.5).normalize();
        let v = (Vec3::new(u(), u(), u()) - 0.5 + nrm).normalize();
        let alpha = (0.05 + 0.95 * u()).powi(2);
        let lobe = receiver_lobe(
            Vec3::splat(0.8),
            if u() < 0.5 { 1.0 } else { 0.0 },
            Vec3::splat(0.04),
            1.0,
            alpha,
            nrm.dot(v),
        );
        let r = crate::brdf::mirror_dir(nrm, v);
        let rl = range_lobe(lobe);
        let peak = range_scale(lobe);
        let leaves: Vec<BshNode> = (0..n).map(|i| t.leaf(i)).collect();
        let mut brute = Vec::new();
        for i in 0..n {
            let s = range_scale_toward(rl, b[i].center, b[i].extent, x, r);
            if s < 0.9 * peak {
                below_peak += 1;
            } else if peak > 1.0 {
                at_peak += 1;
            }
            // The leaf's test is the scaled sphere's, up to rounding.
            let (d, radius) = ((x - b[i].center).length(), b[i].extent + s.sqrt() * r2[i].sqrt());
            let reaches = walk::bsh_reaches(leaves[i], x, r, rl);
            if (d - radius).abs() > 1e-5 * radius {
                mismatches += (reaches != (d <= radius)) as u32;
            }
            if reaches {
                brute.push(i as u32);
            }
        }
        // The walk misses no leaf that reaches the point.
        let got = sorted(|f| t.for_each_reaching(x, r, rl, f));
        mismatches += (got != brute) as u32;
        found += got.len();
    }
    assert_eq!(mismatches, 0);
    assert!(
        found > 500 && below_peak > 1_000 && at_peak > 100,
        "{found} found, {below_peak} below the peak, {at_peak} at it"
    );
}

/// The direct pass's tile walk: the subtrees at any depth, walked in index
/// order against a box, list the leaves that reach the box's points in
/// traversal order, and each point's exact test over that list finds the
/// same lights in the same order as its own walk (glossy receivers
/// included: the box test bounds every range lobe up to the largest).
#[test]
fn tile_walk_lists_every_point_walk_in_order() {
    use crate::brdf::{range_lobe, receiver_lobe};
    let mut u = uniforms(47);
    let (mut listed, mut found, mut pruned) = (0usize, 0usize, 0usize);
    for case in 0..400 {
        let n = 1 + (u() * 300.0) as usize;
        let b: Vec<LightBound> = (0..n)
            .map(|_| LightBound {
                center: Vec3::new(u(), u(), u()) * 4.0 - 2.0,
                extent: if u() < 0.5 { 0.0 } else { 0.02 * u() },
            })
            .collect();
        let r2: Vec<f32> = (0..n).map(|_| (0.15 / (1.0 - u()).sqrt()).powi(2)).collect();
        let mut t = Bsh::build(&b).unwrap();
        t.refit(&r2).unwrap();
        let nodes = t.nodes();
        let depth = case % 10;
        // Every leaf once, in traversal order, through an unbounded box.
        let all = |lo: Vec3, hi: Vec3, w: f32| {
            let mut out = Vec::new();
            for s in 0..(1u32 << depth) {
                let root = walk::bsh_subtree(nodes, s, depth);
                if root == BSH_NONE {
                    continue;
                }
                let end = nodes[root as usize].next;
                let mut i = walk::bsh_next_leaf_box(nodes, root, end, lo, hi, w);
                while i != end {
                    out.push(i);
                    i = walk::bsh_next_leaf_box(nodes, nodes[i as usize].next, end, lo, hi, w);
                }
            }
            out
        };
        // The flat array is in pre-order: its leaves are the traversal's.
        let leaves: Vec<u32> =
            (0..nodes.len() as u32).filter(|&i| nodes[i as usize].child == BSH_NONE).collect();
        assert_eq!(
            all(Vec3::splat(-1e30), Vec3::splat(1e30), 1.0),
            leaves,
            "{n} lights, depth {depth}"
        );
        // A small box of receivers, each with its own lobe.
        let lo = Vec3::new(u(), u(), u()) * 4.0 - 2.0;
        let hi = lo + Vec3::new(u(), u(), u()) * 0.3;
        let receivers: Vec<_> = (0..16)
            .map(|_| {
                let x = lo + (hi - lo) * Vec3::new(u(), u(), u());
                let nrm = (Vec3::new(u(), u(), u()) - 0.5).normalize();
                let v = (Vec3::new(u(), u(), u()) - 0.5 + nrm).normalize();
                let lobe = receiver_lobe(
                    Vec3::splat(0.8),
                    if u() < 0.5 { 1.0 } else { 0.0 },
                    Vec3::splat(0.04),
                    1.0,
                    (0.05 + 0.95 * u()).powi(2),
                    nrm.dot(v),
                );
                let lambertian = u() < 0.3;
                let rl =
                    if lambertian { glam::Vec4::new(1.0, 0.0, 1.0, 1.0) } else { range_lobe(lobe) };
                (x, if lambertian { x } else { crate::brdf::mirror_dir(nrm, v) }, rl)
            })
            .collect();
        let w = receivers.iter().map(|r| r.2.w).fold(0.0, f32::max);
        let list = all(lo, hi, w);
        listed += list.len();
        pruned += n - list.len();
        for (x, r, rl) in receivers {
            let mut own = Vec::new();
            t.for_each_reaching(x, r, rl, |l| own.push(l));
            let from_list: Vec<u32> = list
                .iter()
                .map(|&i| nodes[i as usize])
                .filter(|node| walk::bsh_reaches(*node, x, r, rl))
                .map(|node| node.light)
                .collect();
            assert_eq!(from_list, own, "{n} lights, depth {depth}, receiver at {x}");
            found += own.len();
        }
    }
    assert!(
        found > 2_000 && pruned > 10_000 && listed > 1_000,
        "{found} found, {listed} listed, {pruned} pruned"
    );
}

/// The two-level cut (whole chunks, then bins) is the lowest bin whose
/// suffix holds at most `k` lights, as a bin-by-bin scan from the top finds
/// it: sparse, dense, empty and all-fitting histograms.
#[test]
fn tail_cut_is_the_lowest_bin_that_fits() {
    use rand_core::{RngCore, SeedableRng};
    let mut rng = rand_pcg::Pcg32::seed_from_u64(31);
    let naive = |h: &[u32], k: u32| {
        let (mut b, mut sum) = (h.len(), 0);
        while b > 0 && sum + h[b - 1] <= k {
            sum += h[b - 1];
            b -= 1;
        }
        b as u32
    };
    for case in 0..2000 {
        let mut h = alloc::vec![0u32; BSH_TAIL_BINS as usize];
        let (fill, max) = [(0, 0), (3, 5), (40, 3), (1024, 2), (200, 40)][case % 5];
        for _ in 0..fill {
            let b = rng.next_u32() as usize % h.len();
            h[b] += rng.next_u32() % (max + 1);
        }
        let k = rng.next_u32() % 70;
        assert_eq!(tail::bsh_tail_cut(&h, k), naive(&h, k), "case {case}, k {k}");
    }
}

/// The sphere-area split keeps clusters whole where the median cuts
/// through one: 3 lights about x = 0 and 13 about x = 10 (the median
/// takes 8 and 8); the root's children are the two clusters. The
/// balanced tree is `⌈log₂ n⌉` deep.
#[test]
fn sphere_area_split_keeps_clusters_whole() {
    let b: Vec<_> =
        (0..16)
            .map(|i| {
                if i < 3 {
                    pt(i as f32 * 0.1, 0.0, 0.0)
                } else {
                    pt(10.0 + i as f32 * 0.1, 0.0, 0.0)
                }
            })
            .collect();
    let lights_under = |t: &Bsh, root: u32| -> Vec<u32> {
        let n = t.nodes();
        let end = n[root as usize].next;
        let mut l: Vec<u32> = (root..end.min(t.tree_len() as u32))
            .filter(|&i| n[i as usize].child == BSH_NONE)
            .map(|i| n[i as usize].light)
            .collect();
        l.sort();
        l
    };
    let area = Bsh::build_with(&b, BshShape { split: BshSplit::SphereArea, width: 2 }).unwrap();
    assert_eq!(lights_under(&area, 1), [0, 1, 2]);
    let median = Bsh::build(&b).unwrap();
    assert_eq!(lights_under(&median, 1).len(), 8);
    assert_eq!(depth(&median), 4);
}

/// A sphere-area tree stays within [`BSH_MAX_DEPTH`] where the heuristic
/// would peel a few lights off per level (900 lights on six arms along
/// the axes at `±2⁻ᵏ`, k < 150: each split cuts off an arm's far bins;
/// without the bound, 107 levels), and still answers as brute force does.
#[test]
fn sphere_area_depth_is_bounded() {
    let n = 6 * 150;
    let b: Vec<_> = (0..n)
        .map(|i| {
            let x = 2f32.powi(-(i as i32 / 6)) * if i % 2 == 0 { 1.0 } else { -1.0 };
            [pt(x, 0.0, 0.0), pt(0.0, x, 0.0), pt(0.0, 0.0, x)][i % 3]
        })
        .collect();
    let mut t = Bsh::build_with(&b, BshShape { split: BshSplit::SphereArea, width: 2 }).unwrap();
    let d = depth(&t);
    assert!(d > 20 && d <= BSH_MAX_DEPTH, "depth {d}");
    let r2: Vec<f32> = (0..n).map(|k| (1e-3 * (k % 7) as f32).powi(2)).collect();
    t.refit(&r2).unwrap();
    for x in [0.0, 1e-30, 1e-5, 0.01, -0.5, 0.9, 1.0] {
        for x in [Vec3::new(x, 0.0, 0.0), Vec3::new(0.0, x, 1e-3)] {
            let brute: Vec<u32> = (0..n as u32)
                .filter(|&i| b[i as usize].range_sphere(r2[i as usize]).contains(x))
                .collect();
            assert_eq!(sorted(|f| t.for_each_containing(x, f)), brute);
        }
    }
}

/// A wide tree's links: every inner node has 2..=width children side by
/// side after it (each one's `next` the following one, the last one's its
/// parent's), every light sits in one leaf, the depth is at most the
/// binary tree's, and a refit's every sphere holds its children's; too
/// wide or too narrow a shape is a typed error.
#[test]
fn wide_tree_links() {
    let mut u = uniforms(29);
    for (n, width) in [(2, 4), (3, 4), (5, 3), (100, 4), (1000, 4), (777, 8)] {
        let b: Vec<_> = (0..n)
            .map(|_| LightBound { center: Vec3::new(u(), u(), u()), extent: 0.01 * u() })
            .collect();
        let binary =
            Bsh::build_with(&b, BshShape { split: BshSplit::SphereArea, width: 2 }).unwrap();
        let mut t = Bsh::build_with(&b, BshShape { split: BshSplit::SphereArea, width }).unwrap();
        assert_eq!(t.width(), width);
        assert!(depth(&t) <= depth(&binary), "{n} lights, {width} wide");
        let r2: Vec<f32> = (0..n).map(|_| 0.001 / (1.0 - u()).max(1e-3)).collect();
        t.refit(&r2).unwrap();
        let nodes = t.nodes();
        assert_eq!(nodes.len(), t.tree_len());
        let mut seen = alloc::vec![0; n];
        for (i, node) in nodes.iter().enumerate() {
            if node.child == BSH_NONE {
                seen[node.light as usize] += 1;
                assert_eq!(t.leaf(node.light as usize), *node);
                continue;
            }
            let (mut c, mut count) = (node.child, 0);
            assert!(c as usize > i);
            loop {
                let child = nodes[c as usize];
                count += 1;
                let d = (child.center - node.center).length();
                assert!(d + child.radius <= node.radius * 1.0001 + 1e-6, "node {i}, child {c}");
                if child.next == node.next {
                    break;
                }
                assert_eq!(child.next, c + 1, "node {i}: children side by side");
                c = child.next;
            }
            assert!((2..=width).contains(&count), "node {i}: {count} children");
        }
        assert_eq!(seen, alloc::vec![1; n]);
    }
    for width in [0, 1, 9] {
        let b = [pt(0.0, 0.0, 0.0), pt(1.0, 0.0, 0.0)];
        let shape = BshShape { split: BshSplit::Median, width };
        assert_eq!(Bsh::build_with(&b, shape), Err(BshError::BadWidth(width)));
    }
}

/// The sharp grid's scan cuts a glossy receiver's cell to the lights whose
/// bound meets its lobe's cone (outside it the lobe scales no range) and
/// still finds what the walk finds, in its order, where that cut is
/// tightest: lights just inside the cone, whose scale toward them is barely
/// above 1, each at a distance between its plain sphere's radius and its
/// scaled one's (so only the scale brings it in), points and spheres, for
/// metal and dielectric lobes of GGX α from 0.0025 to 0.25, among lights
/// anywhere in the box.
#[test]
fn the_sharp_grid_finds_the_lights_at_its_cones_edge() {
    use crate::brdf::{mirror_dir, range_lobe, receiver_lobe};
    use crate::importance::{range_scale_at, range_scale_toward};
    use grid::{SHARP_GRID_ENTRIES, SHARP_REACH};
    let mut u = uniforms(31);
    let (mut edge, mut edge_found, mut receivers) = (0, 0, 0);
    for _ in 0..300 {
        let x = Vec3::new(0.3 + 0.4 * u(), 0.3 + 0.4 * u(), 0.3 + 0.4 * u());
        let nrm = (Vec3::new(u(), u(), u()) - 0.5).normalize();
        let v = (Vec3::new(u(), u(), u()) - 0.5 + nrm * 1.5).normalize();
        let alpha = (0.05 + 0.45 * u()).powi(2);
        let metal = if u() < 0.5 { 1.0 } else { 0.0 };
        let lobe =
            receiver_lobe(Vec3::splat(0.8), metal, Vec3::splat(0.04), 1.0, alpha, nrm.dot(v));
        let (r, rl) = (mirror_dir(nrm, v), range_lobe(lobe));
        if rl.w <= 1.0 {
            continue;
        }
        receivers += 1;
        // The smallest cosine whose scale exceeds 1 (bisection: the scale
        // is monotone in the cosine).
        let (mut lo, mut hi) = (-1.0f32, 1.0f32);
        for _ in 0..40 {
            let mid = 0.5 * (lo + hi);
            if range_scale_at(rl, mid) > 1.0 { hi = mid } else { lo = mid }
        }
        let p = r.any_orthonormal_vector();
        let q = r.cross(p);
        let (mut b, mut r2, mut at_edge) = (Vec::new(), Vec::new(), Vec::new());
        for k in 0..48 {
            // Just inside the cone: a cosine a little above `hi`.
            let c = (hi + (1.0 - hi) * 0.02 * u() * u()).min(1.0);
            let phi = core::f32::consts::TAU * u();
            let d = 0.05 + 0.25 * u();
            let extent = if k % 2 == 0 { 0.0 } else { 0.2 * d * u() };
            // The centre farther off the axis by the sphere's own angle.
            let t = c.acos() + (extent / d).asin();
            let side = p * phi.cos() + q * phi.sin();
            let center = x + (r * t.cos() + side * t.sin()) * d;
            let s = range_scale_toward(rl, center, extent, x, r);
            if !(s > 1.0) {
                continue;
            }
            // Between the plain radius and the scaled one.
            let range = (d - extent) / (0.5 + 0.5 * s.sqrt());
            b.push(LightBound { center, extent });
            r2.push(range * range);
            at_edge.push(b.len() as u32 - 1);
        }
        for _ in 0..200 {
            b.push(LightBound { center: Vec3::new(u(), u(), u()), extent: 0.01 * u() });
            r2.push((0.03 * u()).powi(2));
        }
        let mut t = Bsh::build_with(&b, shape_of(u(), u())).unwrap();
        t.refit(&r2).unwrap();
        let g = BshGrid::build_reaching_within(
            &t,
            Vec3::ZERO,
            Vec3::ONE,
            SHARP_REACH,
            SHARP_GRID_ENTRIES,
        )
        .expect("a sharp grid");
        let mut walk = Vec::new();
        t.for_each_reaching(x, r, rl, |l| walk.push(l));
        let mut got = Vec::new();
        assert!(g.for_each_reaching(x, r, rl, |l| got.push(l)), "held: {rl}");
        assert_eq!(got, walk, "at {x}, lobe {rl}");
        edge += at_edge.len();
        edge_found += at_edge.iter().filter(|l| walk.contains(l)).count();
    }
    assert!(receivers > 200 && edge > 5_000, "{receivers} receivers, {edge} lights at the edge");
    // The edge lights reach the point by their scale alone (up to rounding).
    assert!(edge_found as f32 > 0.95 * edge as f32, "{edge_found} of {edge} found");
}

/// The grid finds what the walk finds, in the walk's order (the same
/// candidates and random numbers for the CPU's shortcut): every shape, the
/// range tail, zero, huge and infinite ranges, points in and outside its
/// box, scales from 10⁻⁶ to 10⁶; and so does a grid built for glossy
/// receivers' lobes up to a reach `w`, for every receiver whose lobe it
/// holds (the others, `rl.w > w`, are refused). A box that is not finite,
/// inverted or a point, an empty tree, or ranges as large as the scene give
/// no grid; a flat box (a floor) gets one.
#[test]
fn grid_finds_what_the_walk_finds_in_its_order() {
    use crate::brdf::{mirror_dir, range_lobe, receiver_lobe};
    let mut u = uniforms(23);
    let (mut grids, mut inside, mut found) = (0, 0, 0usize);
    let (mut glossy, mut glossy_found, mut refused) = (0, 0usize, 0);
    for _ in 0..400 {
        let scale = 10f32.powf(6.0 - 12.0 * u());
        let n = 1 + (u() * 400.0) as usize;
        let b: Vec<LightBound> = (0..n)
            .map(|_| LightBound {
                center: Vec3::new(u(), u(), u()) * scale,
                extent: if u() < 0.5 { 0.0 } else { u() * 0.01 * scale },
            })
            .collect();
        let r2: Vec<f32> = (0..n)
            .map(|_| match (u() * 20.0) as u32 {
                0 => 0.0,
                1 => f32::INFINITY,
                2 => (u() * scale).powi(2),
                _ => (u() * 0.05 * scale).powi(2),
            })
            .collect();
        let mut t = Bsh::build_with(&b, shape_of(u(), u()))
            .unwrap()
            .with_tail((u() * 20.0) as usize)
            .unwrap();
        t.refit(&r2).unwrap();
        let w = 1.0 + 7.0 * u();
        let gw = BshGrid::build_reaching(&t, Vec3::ZERO, Vec3::splat(scale), w);
        let Some(g) = BshGrid::build(&t, Vec3::ZERO, Vec3::splat(scale)) else { continue };
        grids += 1;
        for _ in 0..200 {
            let x = (Vec3::new(u(), u(), u()) * 1.2 - 0.1) * scale;
            let in_box = x.cmpge(Vec3::ZERO).all() && x.cmple(Vec3::splat(scale)).all();
            if let Some(gw) = &gw {
                let nrm = (Vec3::new(u(), u(), u()) - 0.5).normalize();
                let v = (Vec3::new(u(), u(), u()) - 0.5 + nrm).normalize();
                let metal = if u() < 0.5 { 1.0 } else { 0.0 };
                let alpha = (0.05 + 0.95 * u()).powi(2);
                let lobe = receiver_lobe(
                    Vec3::splat(0.8),
                    metal,
                    Vec3::splat(0.04),
                    1.0,
                    alpha,
                    nrm.dot(v),
                );
                let (r, rl) = (mirror_dir(nrm, v), range_lobe(lobe));
                let mut walk = Vec::new();
                t.for_each_reaching(x, r, rl, |l| walk.push(l));
                let mut grid = Vec::new();
                if gw.for_each_reaching(x, r, rl, |l| grid.push(l)) {
                    assert_eq!(grid, walk, "at {x} of scale {scale}, lobe {rl} in a grid for {w}");
                    glossy += (rl.w > 1.0) as u32;
                    glossy_found += walk.len();
                } else {
                    assert!(grid.is_empty() && (rl.w > w || !in_box), "{rl} refused by {w}");
                    refused += (rl.w > w) as u32;
                }
            }
            let mut walk = Vec::new();
            t.for_each_containing(x, |l| walk.push(l));
            let mut grid = Vec::new();
            if g.for_each_containing(x, |l| grid.push(l)) {
                assert_eq!(grid, walk, "at {x} of scale {scale}");
                assert!(g.tested(x).unwrap() >= walk.len());
                inside += 1;
                found += walk.len();
            } else {
                assert!(grid.is_empty() && !in_box);
            }
        }
    }
    assert!(grids > 250 && inside > 30_000 && found > 30_000, "{grids} {inside} {found}");
    assert!(
        glossy > 4_000 && glossy_found > 50_000 && refused > 4_000,
        "{glossy} glossy receivers found {glossy_found}, {refused} refused"
    );
    // No grid: bad boxes, an empty tree, every range covering the box.
    let mut t = Bsh::build(&[pt(0.5, 0.5, 0.5); 64]).unwrap();
    t.refit(&[0.0; 64]).unwrap();
    for (lo, hi) in [
        (Vec3::ONE, Vec3::ZERO),
        (Vec3::ONE, Vec3::ONE),
        (Vec3::ZERO, Vec3::INFINITY),
        (Vec3::NAN, Vec3::ONE),
    ] {
        assert!(BshGrid::build(&t, lo, hi).is_none());
    }
    // A flat box (a floor) gets a thickness: its points, and those a
    // little off it, find the walk's lights (64 above it, ranges 0.1).
    let above: Vec<LightBound> = (0..64)
        .map(|i| pt((i % 8) as f32 / 8.0 + 0.0625, 0.05, (i / 8) as f32 / 8.0 + 0.0625))
        .collect();
    let mut lit = Bsh::build(&above).unwrap();
    lit.refit(&[0.01; 64]).unwrap();
    let floor = BshGrid::build(&lit, Vec3::ZERO, Vec3::new(1.0, 0.0, 1.0)).unwrap();
    let mut floor_found = 0;
    for k in 0..400 {
        let x = Vec3::new(
            (k % 20) as f32 / 20.0,
            if k % 3 == 0 { 1e-5 } else { 0.0 },
            (k / 20) as f32 / 20.0,
        );
        let (mut walk, mut grid) = (Vec::new(), Vec::new());
        lit.for_each_containing(x, |l| walk.push(l));
        assert!(floor.for_each_containing(x, |l| grid.push(l)), "{x} outside the floor's grid");
        assert_eq!(grid, walk, "at {x}");
        floor_found += walk.len();
    }
    assert!(floor_found > 100, "{floor_found} lights found on the floor");
    assert!(BshGrid::build(&t, Vec3::ZERO, Vec3::ONE).is_some());
    assert!(BshGrid::build(&Bsh::build(&[]).unwrap(), Vec3::ZERO, Vec3::ONE).is_none());
    t.refit(&[4.0; 64]).unwrap();
    assert!(BshGrid::build(&t, Vec3::ZERO, Vec3::ONE).is_none());
    // A NaN point finds nothing, as the walk.
    t.refit(&[0.01; 64]).unwrap();
    let g = BshGrid::build(&t, Vec3::ZERO, Vec3::ONE).unwrap();
    assert!(g.for_each_containing(Vec3::NAN, |_| panic!("found at NaN")));
}
