//! Random kernel `Features` for every kernel: generation either returns
//! naga-validated WGSL or the typed `ShaderError::Unsupported` that
//! `check` gives. A template error or WGSL that naga rejects is a bug (a
//! combination `check` lets through but the templates cannot build).
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use slc_shared_shaders::{
    CullKind, DirectOutput, Features, Heuristic, Kernel, LightTypes, OutputFormat, Selection,
    ShaderError, SurfaceSource, VplSource, generate,
};

#[derive(Arbitrary, Debug)]
struct Input {
    kernel: u8,
    lights: u8,
    reservoir_k: u8,
    workgroup_size: u16,
    tile_size: u8,
    interleave: u8,
    max_tile_lights: u16,
    method: u8,
    heuristic: bool,
    selection: u8,
    rsm: bool,
    rgba32: bool,
    shadows: bool,
    surface: u8,
    direct_output: u8,
    glossy: bool,
    motion_vectors: bool,
    counters: bool,
    reuse_domains: u8,
    tile_walk: bool,
    ray_query: bool,
    bsh_grid: bool,
}

fuzz_target!(|i: Input| {
    let kernel = Kernel::ALL[i.kernel as usize % Kernel::ALL.len()];
    let features = Features {
        lights: LightTypes::from_bits(i.lights as u32),
        reservoir_k: i.reservoir_k as u32,
        workgroup_size: i.workgroup_size as u32,
        tile_size: i.tile_size as u32,
        interleave: i.interleave as u32,
        max_tile_lights: i.max_tile_lights as u32,
        method: CullKind::ALL[i.method as usize % 3],
        heuristic: if i.heuristic { Heuristic::Balance } else { Heuristic::Power },
        selection: [
            Selection::Reservoir,
            Selection::All,
            Selection::Uniform,
            Selection::Power,
            Selection::Weighted,
            Selection::LightBvh,
            Selection::Resampled,
        ][i.selection as usize % 7],
        vpl_source: if i.rsm { VplSource::Rsm } else { VplSource::Buffer },
        output_format: if i.rgba32 { OutputFormat::Rgba32Float } else { OutputFormat::Rgba16Float },
        shadows: i.shadows,
        surface: [SurfaceSource::Position, SurfaceSource::Depth, SurfaceSource::R32Depth]
            [i.surface as usize % 3],
        direct_output: [
            DirectOutput::Irradiance,
            DirectOutput::Radiance,
            DirectOutput::Split,
            DirectOutput::BevyRadiance,
        ][i.direct_output as usize % 4],
        glossy: i.glossy,
        motion_vectors: i.motion_vectors,
        counters: i.counters,
        // 0..=9: no reuse, every allowed count of reused pixels, one too many.
        reuse_domains: i.reuse_domains as u32 % 10,
        tile_walk: i.tile_walk,
        ray_query: i.ray_query,
        bsh_grid: i.bsh_grid,
    };
    match generate(kernel, &features) {
        Ok(wgsl) => assert!(wgsl.contains("fn "), "{kernel:?}: empty source"),
        Err(ShaderError::Unsupported(_)) => {}
        Err(e) => panic!("{kernel:?} {features:?}: {e}"),
    }
});
