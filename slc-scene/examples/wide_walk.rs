//! What a 4-wide BSH would save the path tracers' walk (issue 48, item 2),
//! measured before building one: the walk's time per shading point on the
//! path tracers' own tree (`PtScene::bsh`, refit for one ξ set at the
//! automatic ε; Lambertian receivers, the plain sphere test) against the
//! same tree collapsed to four children per node, walked with a stack and
//! the four sphere tests side by side (what a 4-wide node in one 64-byte
//! line of structure-of-arrays spheres plus one of links would give both
//! backends). Each is checked to find the same lights at every point; the
//! range tail's flat tests are in both. The collapse is done once here (a
//! refit would redo it every pass: not timed).
//!
//! Times, not counts: machine-dependent; quote them with the machine.
//!
//!     cargo run --release -p slc-scene --example wide_walk -- SCENE.toml [SCENE.toml ...]

use glam::Vec3;
use slc_core::bsh::{BSH_NONE, BSH_TAIL, BshNode};
use slc_core::range::{RangeParams, random_range2};
use slc_core::xi::xi_for;
use slc_scene::error_bound::{TARGET_CANDIDATES, auto_error_bound};
use slc_scene::placement::{Stream, Surfaces};
use slc_scene::pt::PtScene;
use slc_scene::scene_file::SceneFile;
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

/// The lights whose sphere holds `x`, by the 4-wide walk.
fn wide_walk(wide: &[Wide], x: Vec3, mut visit: impl FnMut(u32)) {
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
        "{:<28} {:>7} {:>11} {:>12} {:>12} {:>11} {:>9} {:>10}",
        "scene",
        "lights",
        "candidates",
        "binary ns",
        "plain ns",
        "4-wide ns",
        "ratio",
        "wide nodes"
    );
    for path in std::env::args().skip(1) {
        let f = SceneFile::load(std::path::Path::new(&path))?;
        let pts = PtScene::new(&f.scene, &f.lights)?;
        let eps = auto_error_bound(&pts, 1.0, TARGET_CANDIDATES).ok_or("no automatic bound")?;
        let params = RangeParams::new(eps, 1.0)?;
        let r2: Vec<f32> = pts
            .lights()
            .iter()
            .enumerate()
            .map(|(i, l)| random_range2(params.threshold_range2(l.peak()), xi_for(1, 0, i as u32)))
            .collect();
        let mut bsh = pts.bsh().clone();
        bsh.refit(&r2)?;
        let nodes = bsh.nodes();
        let tree = bsh.tree_len();
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
        let surfaces = Surfaces::new(pts.scene())?;
        let xs: Vec<Vec3> =
            (0..POINTS).map(|k| surfaces.sample(&mut Stream::new(0x1234, k)).0).collect();
        // The same lights at every point.
        let mut found = 0u64;
        for &x in &xs {
            let (mut a, mut b) = (Vec::new(), Vec::new());
            bsh.for_each_containing(x, |l| a.push(l));
            wide_walk(&wide, x, |l| b.push(l));
            for n in &tail {
                if (x - n.center).length_squared() <= n.radius * n.radius {
                    b.push(n.light);
                }
            }
            a.sort();
            b.sort();
            assert_eq!(a, b, "{path}: the 4-wide walk found other lights at {x}");
            found += a.len() as u64;
        }
        // Fastest of 5 rounds each, alternated.
        let (mut binary, mut plain, mut four) = (f64::INFINITY, f64::INFINITY, f64::INFINITY);
        let mut sink = 0u64;
        for _ in 0..5 {
            let t0 = Instant::now();
            for &x in &xs {
                bsh.for_each_containing(x, |l| sink += l as u64);
            }
            binary = binary.min(t0.elapsed().as_secs_f64());
            let t0 = Instant::now();
            for &x in &xs {
                bsh.traverse(|c, r| (x - c).length_squared() <= r * r, |l| sink += l as u64);
            }
            plain = plain.min(t0.elapsed().as_secs_f64());
            let t0 = Instant::now();
            for &x in &xs {
                wide_walk(&wide, x, |l| sink += l as u64);
                for n in &tail {
                    if (x - n.center).length_squared() <= n.radius * n.radius {
                        sink += n.light as u64;
                    }
                }
            }
            four = four.min(t0.elapsed().as_secs_f64());
        }
        std::hint::black_box(sink);
        let name = std::path::Path::new(&path)
            .file_stem()
            .map_or(path.clone(), |s| s.to_string_lossy().into());
        let ns = |s: f64| s * 1e9 / POINTS as f64;
        println!(
            "{name:<28} {:>7} {:>11.2} {:>12.1} {:>12.1} {:>11.1} {:>9.2} {:>10}",
            pts.lights().len(),
            found as f64 / POINTS as f64,
            ns(binary),
            ns(plain),
            ns(four),
            four / binary,
            wide.len()
        );
    }
    Ok(())
}
