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
//! With `--glossy ROUGHNESS,METALLIC`, every point is a glossy receiver of
//! that glTF material (`Material::gltf`, base colour 0.8) seen from a random
//! direction above its surface, and the grids are built for reaches `w` of 2, 4 and 8
//! (`BshGrid::build_reaching`; at 8 the path tracer's sharp grid,
//! `BshGrid::build_reaching_within` with `SHARP_GRID_ENTRIES`) against the lobe-scaled walk: `held` is the
//! share of receivers whose lobe the grid holds (`rl.w ≤ w`; the others
//! walk the tree, and are timed so); `list` is what a held receiver's cell
//! lists.
//!
//!     cargo run --release -p slc-scene --example grid_walk -- [--glossy R,M] SCENE.toml [SCENE.toml ...]

use glam::{Vec3, Vec4};
use slc_core::bsh::BshGrid;
use slc_core::bsh::grid::{SHARP_GRID_ENTRIES, SHARP_REACH};
use slc_scene::placement::Stream;
use slc_scene::scene::Material;
use std::time::Instant;

mod common;

/// Shading points per timed set.
const POINTS: u32 = 100_000;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let glossy = match args.iter().position(|a| a == "--glossy") {
        Some(i) if i + 1 < args.len() => {
            let v = args.remove(i + 1);
            args.remove(i);
            let (a, m) = v.split_once(',').ok_or("--glossy takes ROUGHNESS,METALLIC")?;
            Some((a.parse::<f32>()?, m.parse::<f32>()?))
        }
        Some(_) => return Err("--glossy takes ROUGHNESS,METALLIC".into()),
        None => None,
    };
    println!(
        "{:<24} {:>7} {:>6} {:>9} {:>5} {:>9} {:>10} {:>8} {:>9} {:>9} {:>14} {:>5}",
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
        "cells",
        if glossy.is_some() { "w" } else { "" },
    );
    for path in &args {
        let w = common::Walked::load(path)?;
        let mut built = w.pts.bsh().clone();
        built.refit(&w.r2)?;
        let points = w.points_with_normals(POINTS)?;
        // Each point's receiver: (x, mirror direction, range lobe).
        let rcs: Vec<(Vec3, Vec3, Vec4)> = points
            .iter()
            .enumerate()
            .map(|(k, &(x, n))| match glossy {
                None => (x, n, Vec4::new(1.0, 0.0, 1.0, 1.0)),
                Some((roughness, metallic)) => {
                    let mut s = Stream::new(0x5678, k as u32);
                    let d = Vec3::new(s.uniform(), s.uniform(), s.uniform()) * 2.0 - 1.0;
                    let v = (d.normalize_or_zero() + n * 1.01).normalize();
                    let rc =
                        Material::gltf(Vec3::splat(0.8), metallic, roughness).receiver(x, n, v);
                    (x, rc.r, rc.range_lobe())
                }
            })
            .collect();
        let (lo, hi) = w.pts.scene().bounds();
        let runs: Vec<(u32, f32)> = match glossy {
            None => [0u32, 16, 32, 64, 128].map(|r| (r, 1.0)).to_vec(),
            Some(_) => [2.0f32, 4.0, 8.0].map(|w| (0, w)).to_vec(),
        };
        for (res, reach) in runs {
            let t0 = Instant::now();
            let grid = if res == 0 && reach == SHARP_REACH {
                BshGrid::build_reaching_within(&built, lo, hi, reach, SHARP_GRID_ENTRIES)
            } else if res == 0 {
                BshGrid::build_reaching(&built, lo, hi, reach)
            } else {
                BshGrid::build_reaching_at(&built, lo, hi, res, reach)
            };
            let build = t0.elapsed().as_secs_f64();
            let Some(grid) = grid else {
                println!("{:<24} {res:>5} {reach:>5}: no grid (ranges too large)", w.name);
                continue;
            };
            // A receiver the grid does not hold walks the tree, as in the
            // path tracer.
            let by_grid = |&(x, r, rl): &(Vec3, Vec3, Vec4), visit: &mut dyn FnMut(u32)| {
                if !grid.for_each_reaching(x, r, rl, &mut *visit) {
                    built.for_each_reaching(x, r, rl, visit);
                }
            };
            let (mut found, mut listed, mut held) = (0u64, 0u64, 0u64);
            for rc @ &(x, r, rl) in &rcs {
                let (mut a, mut b) = (Vec::new(), Vec::new());
                built.for_each_reaching(x, r, rl, |l| a.push(l));
                by_grid(rc, &mut |l| b.push(l));
                assert_eq!(a, b, "{path}: the grid found other lights at {x}");
                found += a.len() as u64;
                if rl.w <= reach && grid.tested(x).is_some() {
                    held += 1;
                    listed += grid.tested(x).unwrap_or(0) as u64;
                }
            }
            let mut best = [f64::INFINITY; 2];
            let mut sink = 0u64;
            for _ in 0..5 {
                let t0 = Instant::now();
                for &(x, r, rl) in &rcs {
                    if glossy.is_none() {
                        built.for_each_containing(x, |l| sink += l as u64);
                    } else {
                        built.for_each_reaching(x, r, rl, |l| sink += l as u64);
                    }
                }
                best[0] = best[0].min(t0.elapsed().as_secs_f64());
                let t0 = Instant::now();
                for rc in &rcs {
                    by_grid(rc, &mut |l| sink += l as u64);
                }
                best[1] = best[1].min(t0.elapsed().as_secs_f64());
            }
            std::hint::black_box(sink);
            let ns = |s: f64| s * 1e9 / POINTS as f64;
            println!(
                "{:<24} {:>7} {:>6.2} {:>9.1} {:>5} {:>9.2} {:>10} {:>8.1} {:>9.1} {:>9.2} {:>14} {:>5}",
                w.name,
                w.pts.lights().len(),
                found as f64 / POINTS as f64,
                ns(best[0]),
                if res == 0 { "auto".to_string() } else { res.to_string() },
                build * 1e3,
                grid.entries(),
                listed as f64 / held.max(1) as f64,
                ns(best[1]),
                best[1] / best[0],
                format!("{}", grid.cells()),
                match glossy {
                    Some(_) => format!("{reach} held {:.2}", held as f64 / POINTS as f64),
                    None => String::new(),
                },
            );
        }
    }
    Ok(())
}
