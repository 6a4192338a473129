//! Criterion benchmarks of the CPU VPL frame's stages that are not the
//! shading loop: the cross-bilateral denoise at 512×512 (the default
//! image), on the unculled interleaved irradiance of the Cornell box.
//!
//! `cargo bench -p slc-cpu --bench frame` (add `-- --quick` for a fast pass).

use criterion::{Criterion, criterion_group, criterion_main};
use slc_cpu::vpl::VplContext;
use slc_cpu::vpl::denoise::cross_bilateral;
use slc_scene::scene::Scene;
use slc_scene::vpl::{Culling, PERIOD, VplSettings};
use std::hint::black_box;

fn denoise(c: &mut Criterion) {
    let ctx = VplContext::new(&Scene::cornell_box(), 512, 512, 64, None).expect("context");
    let shaded = ctx
        .shade(&VplSettings { culling: Culling::None, denoise: false, ..VplSettings::default() })
        .expect("shade");
    c.bench_function("denoise 512x512 (8x8 window)", |b| {
        b.iter(|| black_box(cross_bilateral(&shaded.irradiance, ctx.gbuffer(), PERIOD)))
    });
}

criterion_group!(benches, denoise);
criterion_main!(benches);
