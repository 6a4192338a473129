//! How many BSH nodes the path tracer's walk visits per shading point, and
//! how many it would visit with two cheaper walks (issue 48, item 2), at
//! the automatic ε, for Lambertian receivers (the plain sphere test):
//!
//! - `spheres`: the walk without a range tail (`slc_core::bsh::walk::bsh_next_leaf`
//!   over the light set's BSH);
//! - `+ boxes`: each inner node also tested against the bounding box of its
//!   lights' bounds `c ± R` padded by the largest range below it (every
//!   light's range sphere lies in it, so the walk finds the same leaves);
//! - `tail N`: the `N` largest range spheres left out of the tree (tested
//!   flat, `N` tests per point, not counted here), alone and with the boxes
//!   (the path tracers' tail, `Bsh::with_tail`, takes at most 16: whole
//!   histogram bins);
//! - `+ cones`: nodes whose emitter bounds (pbrt-v4's, unioned as the light
//!   BVH does) send nothing toward the point also rejected, and all three;
//!   `lit cand.` counts the candidates left (those of nonzero weight);
//! - `built tail`: how many lights the path tracers' tail (`PtScene::bsh`)
//!   takes for the same ranges; `built`: the visits of the path tracers'
//!   own tree (split by the sphere-area heuristic and 4 wide,
//!   `BshShape::WIDE`) with that tail, and `balanced`: the light set's balanced tree
//!   (`BshSplit::Median`, which the other columns walk) with the same
//!   tail, as the path tracers walked before (the tail's flat tests not
//!   counted; each checked to find the same leaves with them); `levels`:
//!   the built tree's (the GPU refits one level per dispatch; the balanced
//!   tree has `⌈log₂ n⌉ + 1`). A visit is a node tested: a 4-wide tree
//!   tests more nodes than a binary one, side by side (see `wide_walk`
//!   for times).
//!
//! One ξ set (seed 1, pass 0), 2,000 points uniform by area on the
//! non-emissive surfaces. Counts, not times: the same on every machine.
//!
//!     cargo run --release -p slc-scene --example walk_visits -- [--tail N] SCENE.toml [SCENE.toml ...]

use glam::Vec3;

mod common;
use slc_core::bsh::{BSH_NONE, BSH_TAIL, Bsh, BshNode};
use slc_core::importance::{LightCone, emitter_cone};
use slc_scene::light_bvh::LightBounds;
use slc_scene::pt::RANGE_TAIL;

/// Shading points per scene.
const POINTS: u32 = 2000;

/// Per node: the box of its lights' bounds and the largest range below it.
fn boxes(
    nodes: &[BshNode],
    bounds: &[slc_core::light::LightBound],
    r2: &[f32],
) -> Vec<(Vec3, Vec3, f32)> {
    let mut b = vec![(Vec3::ZERO, Vec3::ZERO, 0.0); nodes.len()];
    // Reverse pre-order: children before parents.
    for i in (0..nodes.len()).rev() {
        let n = nodes[i];
        b[i] = if n.child == BSH_NONE {
            let l = &bounds[n.light as usize];
            (l.center - l.extent, l.center + l.extent, r2[n.light as usize].sqrt())
        } else {
            let (l, r) = (b[n.child as usize], b[nodes[n.child as usize].next as usize]);
            (l.0.min(r.0), l.1.max(r.1), l.2.max(r.2))
        };
    }
    b
}

/// Nodes visited and leaves found by the stackless walk at `x`, in the
/// tree's first `tree` nodes (a range tail after them is not walked, and
/// its marked leaves in the tree are skipped, as the path tracers' walk
/// does).
fn walk(
    nodes: &[BshNode],
    tree: usize,
    boxes: Option<&[(Vec3, Vec3, f32)]>,
    cones: Option<&[LightCone]>,
    x: Vec3,
) -> (u32, u32) {
    let (mut visits, mut found, mut i) = (0, 0, if nodes.is_empty() { BSH_NONE } else { 0 });
    while i != BSH_NONE && (i as usize) < tree {
        let n = nodes[i as usize];
        visits += 1;
        let marked = n.child == BSH_NONE && n.light & BSH_TAIL != 0;
        let mut hit = !marked && (x - n.center).length_squared() <= n.radius * n.radius;
        if let Some(b) = boxes.filter(|_| hit && n.child != BSH_NONE) {
            let (lo, hi, r) = b[i as usize];
            hit = x.cmpge(lo - r).all() && x.cmple(hi + r).all();
        }
        if let Some(c) = cones.filter(|_| hit) {
            let c = c[i as usize];
            hit = emitter_cone(c.center, c.radius, c.axis, c.cos_o, x).x > c.cos_e;
        }
        i = match (hit, n.child == BSH_NONE) {
            (true, true) => {
                found += 1;
                n.next
            }
            (true, false) => n.child,
            (false, _) => n.next,
        };
    }
    (visits, found)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut tail = 16;
    if let Some(k) = args.iter().position(|a| a == "--tail") {
        tail = args.get(k + 1).ok_or("--tail N")?.parse()?;
        args.drain(k..k + 2);
    }
    println!(
        "{:<40} {:>7} {:>9} {:>10} {:>9} {:>9} {:>9} {:>13} {:>9} {:>13} {:>9} {:>10} {:>9} {:>9} {:>7}",
        "scene",
        "lights",
        "auto eps",
        "candidates",
        "spheres",
        "+ boxes",
        format!("tail {tail}"),
        "tail + boxes",
        "+ cones",
        "all three",
        "lit cand.",
        "built tail",
        "balanced",
        "built",
        "levels"
    );
    for path in args {
        let w = common::Walked::load(&path)?;
        let (pts, eps, r2) = (&w.pts, w.eps, w.r2.clone());
        let bounds = pts.light_set().bounds();
        let xs = w.points(POINTS)?;
        // The tail: the lights of the largest range spheres, ranges set to 0
        // in the tree (their leaves then hold only their own bound).
        let mut order: Vec<usize> = (0..r2.len()).collect();
        let radius = |l: usize| bounds[l].extent + r2[l].sqrt();
        order.sort_by(|&a, &b| radius(b).total_cmp(&radius(a)));
        let mut r2_tail = r2.clone();
        for &l in order.iter().take(tail) {
            r2_tail[l] = 0.0;
        }
        // Each node's emitter bounds (pbrt-v4's, as the light BVH unions them).
        let lb: Vec<LightBounds> = pts
            .lights()
            .iter()
            .zip(pts.light_set().cones())
            .map(|(l, c)| LightBounds::of_light(l, c))
            .collect();
        let nodes = pts.light_set().bsh().nodes();
        let mut nb = vec![lb[0]; nodes.len()];
        for i in (0..nodes.len()).rev() {
            let n = nodes[i];
            nb[i] = if n.child == BSH_NONE {
                lb[n.light as usize]
            } else {
                nb[n.child as usize].union(&nb[nodes[n.child as usize].next as usize])
            };
        }
        let cones: Vec<LightCone> = nb.iter().map(LightBounds::cone).collect();
        // The path tracers' tail for these ranges (whole histogram bins):
        // its length.
        let mut built = pts.bsh().clone();
        built.refit(&r2)?;
        let (mut built_tail, mut t) = (0, built.nodes()[0].next);
        while t != BSH_NONE {
            built_tail += 1;
            t = built.nodes()[t as usize].next;
        }
        let mut row = Vec::new();
        let mut found_by = Vec::new();
        let mut candidates = 0.0;
        for (ranges, with_boxes, with_cones) in [
            (&r2, false, false),
            (&r2, true, false),
            (&r2_tail, false, false),
            (&r2_tail, true, false),
            (&r2, false, true),
            (&r2_tail, true, true),
        ] {
            let mut bsh: Bsh = pts.light_set().bsh().clone();
            bsh.refit(ranges)?;
            let b = boxes(bsh.nodes(), bounds, ranges);
            let (mut visits, mut found) = (0u64, 0u64);
            for k in 0..POINTS {
                let x = xs[k as usize];
                let (v, c) = walk(
                    bsh.nodes(),
                    bsh.tree_len(),
                    with_boxes.then_some(&b[..]),
                    with_cones.then_some(&cones),
                    x,
                );
                visits += v as u64;
                found += c as u64;
            }
            if std::ptr::eq(ranges, &r2) && !with_boxes && !with_cones {
                candidates = found as f64 / POINTS as f64;
            }
            row.push(visits as f64 / POINTS as f64);
            found_by.push(found);
        }
        // The path tracers' own tree (sphere-area split) with its built
        // tail: its walk's visits, and the same leaves as the plain walk
        // once its tail's flat tests are added.
        // The same tail on the balanced tree: what the path tracers walked
        // before the sphere-area split.
        let mut balanced = pts.light_set().bsh().clone().with_tail(RANGE_TAIL)?;
        balanced.refit(&r2)?;
        let mut tree_visits = [0u64; 2];
        for (t, visits) in [&balanced, &built].into_iter().zip(&mut tree_visits) {
            let mut found = 0u64;
            for k in 0..POINTS {
                let x = xs[k as usize];
                let (v, c) = walk(t.nodes(), t.tree_len(), None, None, x);
                let tail = &t.nodes()[t.tree_len()..t.tree_len() + built_tail];
                let flat =
                    tail.iter().filter(|n| (x - n.center).length_squared() <= n.radius * n.radius);
                *visits += v as u64;
                found += c as u64 + flat.count() as u64;
            }
            assert_eq!(found, found_by[0], "{path}: a tree with its tail found other leaves");
        }
        // The boxes only prune: the same leaves with and without them.
        assert_eq!(
            (found_by[0], found_by[2]),
            (found_by[1], found_by[3]),
            "{path}: boxes changed the leaves"
        );
        let name = &w.name;
        println!(
            "{name:<40} {:>7} {eps:>9.4} {candidates:>10.2} {:>9.1} {:>9.1} {:>9.1} {:>13.1} {:>9.1} {:>13.1} {:>9.2} {built_tail:>10} {:>9.1} {:>9.1} {:>7}",
            pts.lights().len(),
            row[0],
            row[1],
            row[2],
            row[3],
            row[4],
            row[5],
            found_by[4] as f64 / POINTS as f64,
            tree_visits[0] as f64 / POINTS as f64,
            tree_visits[1] as f64 / POINTS as f64,
            built.depths().into_iter().max().unwrap_or(0) + 1
        );
    }
    Ok(())
}
