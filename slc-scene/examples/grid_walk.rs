//! What the CPU path tracer's per-pass grid of the lights' range spheres
//! (`slc_core::bsh::BshGrid`) costs and saves against the 4-wide BSH walk
//! (issue 48, item 2): for one ξ set at the automatic ε, per grid
//! resolution (`auto`: what `BshGrid::build` takes), the build time (what
//! a pass pays), the entries, the spheres a point tests (its cell's and
//! the range tail's) and the time per point, against the built tree's
//! walk (Lambertian receivers, the plain sphere test). Each grid is checked
//! to find the same lights in the same order at every point. Times:
//! machine-dependent.
//!
//!     cargo run --release -p slc-scene --example grid_walk -- SCENE.toml [SCENE.toml ...]

use slc_core::bsh::BshGrid;
use std::time::Instant;

mod common;

/// Shading points per timed set.
const POINTS: u32 = 100_000;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!(
        "{:<24} {:>7} {:>6} {:>9} {:>5} {:>9} {:>10} {:>8} {:>9} {:>9} {:>14}",
        "scene",
        "lights",
        "cand",
        "tree ns",
        "res",
        "build ms",
        "entries",
        "list",
        "grid ns",
        "grid/tree",
        "cells"
    );
    for path in std::env::args().skip(1) {
        let w = common::Walked::load(&path)?;
        let mut built = w.pts.bsh().clone();
        built.refit(&w.r2)?;
        let xs = w.points(POINTS)?;
        let (lo, hi) = w.pts.scene().bounds();
        for res in [0u32, 16, 32, 64, 128] {
            let t0 = Instant::now();
            let grid = if res == 0 {
                BshGrid::build(&built, lo, hi)
            } else {
                BshGrid::build_at(&built, lo, hi, res)
            };
            let build = t0.elapsed().as_secs_f64();
            let Some(grid) = grid else {
                println!("{:<24} {res:>5}: no grid (ranges too large)", w.name);
                continue;
            };
            let (mut found, mut listed) = (0u64, 0u64);
            for &x in &xs {
                let (mut a, mut b) = (Vec::new(), Vec::new());
                built.for_each_containing(x, |l| a.push(l));
                assert!(grid.for_each_containing(x, |l| b.push(l)), "{path}: {x} outside");
                assert_eq!(a, b, "{path}: the grid found other lights at {x}");
                found += a.len() as u64;
                listed += grid.tested(x).unwrap_or(0) as u64;
            }
            let mut best = [f64::INFINITY; 2];
            let mut sink = 0u64;
            for _ in 0..5 {
                let t0 = Instant::now();
                for &x in &xs {
                    built.for_each_containing(x, |l| sink += l as u64);
                }
                best[0] = best[0].min(t0.elapsed().as_secs_f64());
                let t0 = Instant::now();
                for &x in &xs {
                    grid.for_each_containing(x, |l| sink += l as u64);
                }
                best[1] = best[1].min(t0.elapsed().as_secs_f64());
            }
            std::hint::black_box(sink);
            let ns = |s: f64| s * 1e9 / POINTS as f64;
            println!(
                "{:<24} {:>7} {:>6.2} {:>9.1} {:>5} {:>9.2} {:>10} {:>8.1} {:>9.1} {:>9.2} {:>14}",
                w.name,
                w.pts.lights().len(),
                found as f64 / POINTS as f64,
                ns(best[0]),
                if res == 0 { "auto".to_string() } else { res.to_string() },
                build * 1e3,
                grid.entries(),
                listed as f64 / POINTS as f64,
                ns(best[1]),
                best[1] / best[0],
                format!("{}", grid.cells())
            );
        }
    }
    Ok(())
}
