//! Criterion benchmarks of slc-core: keep-test/weight throughput, and BSH
//! build, refit and point query at 1k, 65,536 and 1M lights, on the balanced
//! binary tree and the path tracers' 4-wide one.
//!
//! `cargo bench -p slc-core` (add `-- --quick` for a fast pass).

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use rand_core::{RngCore, SeedableRng};
use slc_core::bsh::{Bsh, BshShape};
use slc_core::glam::Vec3;
use slc_core::light::LightBound;
use slc_core::range::{random_range2, slc_keep, slc_weight};
use slc_core::xi::{fill_xi, xi_from_bits};
use std::hint::black_box;

fn uniform(rng: &mut impl RngCore) -> f32 {
    xi_from_bits(rng.next_u32())
}

/// Lights spread through a 100³ box with `r_t² ∝ 1/n` (as VPLs of flux Φ/n
/// have), so a query point finds about the same few dozen lights at every n:
/// E[hits] ≈ ρ·∫ min(r_t²/d², 1) dV ≈ 2π ρ r_t² L for density ρ = n/L³.
fn scene(n: usize) -> (Vec<LightBound>, Vec<f32>, Vec<Vec3>) {
    let mut rng = rand_pcg::Pcg32::seed_from_u64(1);
    let mut p = || Vec3::new(uniform(&mut rng), uniform(&mut rng), uniform(&mut rng)) * 100.0;
    let bounds: Vec<LightBound> = (0..n).map(|_| LightBound { center: p(), extent: 0.0 }).collect();
    let queries: Vec<Vec3> = (0..1024).map(|_| p()).collect();
    let rt2 = 32.0 * 100f32.powi(2) / (2.0 * std::f32::consts::PI * n as f32);
    let mut xi = vec![0.0f32; n];
    fill_xi(&mut rand_pcg::Pcg32::seed_from_u64(2), &mut xi);
    let r2 = xi.iter().map(|&x| random_range2(rt2, x)).collect();
    (bounds, r2, queries)
}

fn keep_and_weight(c: &mut Criterion) {
    let n = 1 << 16;
    let mut rng = rand_pcg::Pcg32::seed_from_u64(3);
    let d2: Vec<f32> = (0..n).map(|_| uniform(&mut rng) * 10.0).collect();
    let rt2: Vec<f32> = (0..n).map(|_| uniform(&mut rng)).collect();
    let r2: Vec<f32> = rt2.iter().map(|&r| random_range2(r, uniform(&mut rng))).collect();
    let mut g = c.benchmark_group("range");
    g.throughput(Throughput::Elements(n as u64));
    g.bench_function("keep_and_weight_65536", |b| {
        b.iter(|| {
            let mut s = 0.0f32;
            for i in 0..n {
                let w = slc_weight(rt2[i], d2[i]);
                s += if slc_keep(r2[i], d2[i]) { w } else { 0.0 };
            }
            black_box(s)
        })
    });
    g.finish();
}

fn bsh(c: &mut Criterion) {
    let mut g = c.benchmark_group("bsh");
    g.sample_size(10);
    for n in [1_000usize, 65_536, 1 << 20] {
        let (bounds, r2, queries) = scene(n);
        g.throughput(Throughput::Elements(n as u64));
        g.bench_with_input(BenchmarkId::new("build", n), &bounds, |b, bounds| {
            b.iter(|| Bsh::build(bounds).unwrap())
        });
        // The direct pass's balanced binary tree and the path tracers' 4-wide one.
        for (shape, name) in [(BshShape::BALANCED, ""), (BshShape::WIDE, "_wide")] {
            g.throughput(Throughput::Elements(n as u64));
            if shape == BshShape::WIDE {
                g.bench_with_input(BenchmarkId::new("build_wide", n), &bounds, |b, bounds| {
                    b.iter(|| Bsh::build_with(bounds, shape).unwrap())
                });
            }
            let mut t = Bsh::build_with(&bounds, shape).unwrap();
            g.bench_with_input(BenchmarkId::new(format!("refit{name}"), n), &r2, |b, r2| {
                b.iter(|| t.refit(r2).unwrap())
            });
            t.refit(&r2).unwrap();
            let mut hits = 0u64;
            for &x in &queries {
                t.for_each_containing(x, |_| hits += 1);
            }
            let per = hits as f64 / queries.len() as f64;
            eprintln!("bsh{name} n = {n}: {per:.1} lights per query point");
            g.throughput(Throughput::Elements(queries.len() as u64));
            let id = BenchmarkId::new(format!("query_1024_points{name}"), n);
            g.bench_with_input(id, &queries, |b, q| {
                b.iter(|| {
                    let mut hits = 0u32;
                    for &x in q {
                        t.for_each_containing(x, |_| hits += 1);
                    }
                    black_box(hits)
                })
            });
        }
    }
    g.finish();
}

criterion_group!(benches, keep_and_weight, bsh);
criterion_main!(benches);
