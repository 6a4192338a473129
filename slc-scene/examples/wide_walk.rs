//! What the path tracers' 4-wide tree saves their walk (issue 48, item
//! 2): the walk's time per shading point (Lambertian receivers, the plain
//! sphere test; one ξ set at the automatic ε; the range tail's flat tests
//! included) on
//!
//! - `binary`: the sphere-area tree, binary (`BshShape { split:
//!   SphereArea, width: 2 }`), with the same range tail;
//! - `built`: the path tracers' own tree (`PtScene::bsh`: the same split
//!   regrouped 4 wide, `BshShape::WIDE`), the same stackless walk;
//! - `stack`: the binary tree collapsed here to four children per node
//!   whose spheres sit side by side (x, y, z, r² as four lanes each, then
//!   four links: 80 bytes, aligned to 64), walked with a stack and the four
//!   sphere tests at once: a layout the shared stackless walk cannot take
//!   (it needs a stack in WGSL), timed to show what is left.
//!
//! Each is checked to find the same lights at every point. The collapse is
//! done once here (a refit would redo it every pass: not timed). Times, not
//! counts: machine-dependent; quote them with the machine.
//!
//!     cargo run --release -p slc-scene --example wide_walk -- SCENE.toml [SCENE.toml ...]

use glam::Vec3;

mod common;
use slc_core::bsh::{BSH_NONE, BSH_TAIL, Bsh, BshNode, BshShape, BshSplit};
use slc_scene::pt::RANGE_TAIL;
use std::time::Instant;

/// Shading points per timed walk set.
const POINTS: u32 = 100_000;

/// A child slot that is a leaf: the light index in the low bits.
const LEAF: u32 = 1 << 31;

/// Four children: their spheres side by side (squared radius; −1 for an
/// empty slot or a leaf in the range tail, which no point is in) and their
/// links (a wide node, or `LEAF | light`).
#[derive(Clone, Copy)]
#[repr(C, align(64))]
struct Wide {
    x: [f32; 4],
    y: [f32; 4],
    z: [f32; 4],
    r2: [f32; 4],
    link: [u32; 4],
}

/// Collapses the binary subtree at inner node `i` into wide nodes (the
/// slots: `i`'s children, the largest inner one opened while fewer than
/// four), appended to `out`; returns its index.
fn collapse(nodes: &[BshNode], i: u32, out: &mut Vec<Wide>) -> u32 {
    let children = |j: u32| {
        let c = nodes[j as usize].child;
        [c, nodes[c as usize].next]
    };
    let mut slots: Vec<u32> = children(i).to_vec();
    while slots.len() < 4 {
        let open = slots
            .iter()
            .enumerate()
            .filter(|(_, j)| nodes[**j as usize].child != BSH_NONE)
            .max_by(|a, b| nodes[*a.1 as usize].radius.total_cmp(&nodes[*b.1 as usize].radius));
        let Some((k, &j)) = open else { break };
        slots.splice(k..k + 1, children(j));
    }
    let me = out.len();
    out.push(Wide { x: [0.0; 4], y: [0.0; 4], z: [0.0; 4], r2: [-1.0; 4], link: [0; 4] });
    for (k, &j) in slots.iter().enumerate() {
        let n = nodes[j as usize];
        let link = if n.child == BSH_NONE { LEAF | n.light } else { collapse(nodes, j, out) };
        let w = &mut out[me];
        (w.x[k], w.y[k], w.z[k]) = (n.center.x, n.center.y, n.center.z);
        let marked = n.child == BSH_NONE && n.light & BSH_TAIL != 0;
        w.r2[k] = if marked { -1.0 } else { n.radius * n.radius };
        w.link[k] = link;
    }
    me as u32
}

/// The lights whose sphere holds `x`, by the 4-wide walk with a stack.
fn wide_walk(wide: &[Wide], x: Vec3, visit: &mut dyn FnMut(u32)) {
    let mut stack = [0u32; 256];
    let mut sp = 1;
    while sp > 0 {
        sp -= 1;
        let w = &wide[stack[sp] as usize];
        let mut hit = [false; 4];
        for k in 0..4 {
            let (dx, dy, dz) = (x.x - w.x[k], x.y - w.y[k], x.z - w.z[k]);
            hit[k] = dx * dx + dy * dy + dz * dz <= w.r2[k];
        }
        for k in 0..4 {
            if hit[k] {
                let l = w.link[k];
                if l & LEAF != 0 {
                    visit(l & !LEAF);
                } else {
                    stack[sp] = l;
                    sp += 1;
                }
            }
        }
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!(
        "{:<28} {:>7} {:>11} {:>10} {:>10} {:>10} {:>12} {:>12}",
        "scene",
        "lights",
        "candidates",
        "binary ns",
        "built ns",
        "stack ns",
        "built/binary",
        "stack/binary"
    );
    for path in std::env::args().skip(1) {
        let w = common::Walked::load(&path)?;
        let (pts, r2) = (&w.pts, &w.r2);
        // The same split, binary, with the same tail; and the built tree.
        let shape = BshShape { split: BshSplit::SphereArea, width: 2 };
        let mut binary = Bsh::build_with(pts.light_set().bounds(), shape)?.with_tail(RANGE_TAIL)?;
        binary.refit(r2)?;
        let mut built = pts.bsh().clone();
        built.refit(r2)?;
        let nodes = binary.nodes();
        let tree = binary.tree_len();
        if nodes[0].child == BSH_NONE {
            continue;
        }
        let mut wide = Vec::new();
        collapse(&nodes[..tree], 0, &mut wide);
        let mut tail = Vec::new();
        let mut t = nodes[0].next;
        while t != BSH_NONE {
            tail.push(nodes[t as usize]);
            t = nodes[t as usize].next;
        }
        let stack_walk = |x: Vec3, visit: &mut dyn FnMut(u32)| {
            wide_walk(&wide, x, &mut *visit);
            for n in &tail {
                if (x - n.center).length_squared() <= n.radius * n.radius {
                    visit(n.light);
                }
            }
        };
        let xs = w.points(POINTS)?;
        // The same lights at every point.
        let mut found = 0u64;
        for &x in &xs {
            let (mut a, mut b, mut c) = (Vec::new(), Vec::new(), Vec::new());
            binary.for_each_containing(x, |l| a.push(l));
            built.for_each_containing(x, |l| b.push(l));
            stack_walk(x, &mut |l| c.push(l));
            for v in [&mut a, &mut b, &mut c] {
                v.sort();
            }
            assert_eq!(a, b, "{path}: the built tree found other lights at {x}");
            assert_eq!(a, c, "{path}: the stack walk found other lights at {x}");
            found += a.len() as u64;
        }
        // Fastest of 5 rounds each, alternated.
        let mut best = [f64::INFINITY; 3];
        let mut sink = 0u64;
        for _ in 0..5 {
            let t0 = Instant::now();
            for &x in &xs {
                binary.for_each_containing(x, |l| sink += l as u64);
            }
            best[0] = best[0].min(t0.elapsed().as_secs_f64());
            let t0 = Instant::now();
            for &x in &xs {
                built.for_each_containing(x, |l| sink += l as u64);
            }
            best[1] = best[1].min(t0.elapsed().as_secs_f64());
            let t0 = Instant::now();
            for &x in &xs {
                stack_walk(x, &mut |l| sink += l as u64);
            }
            best[2] = best[2].min(t0.elapsed().as_secs_f64());
        }
        std::hint::black_box(sink);
        let name = &w.name;
        let ns = |s: f64| s * 1e9 / POINTS as f64;
        println!(
            "{name:<28} {:>7} {:>11.2} {:>10.1} {:>10.1} {:>10.1} {:>12.2} {:>12.2}",
            pts.lights().len(),
            found as f64 / POINTS as f64,
            ns(best[0]),
            ns(best[1]),
            ns(best[2]),
            best[1] / best[0],
            best[2] / best[0]
        );
    }
    Ok(())
}
