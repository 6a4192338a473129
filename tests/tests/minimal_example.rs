//! The minimal embedding example (`slc-wgpu/examples/minimal.rs`: an
//! engine's own device and compute shader with slc's roulette pasted in as
//! plain WGSL) run as a GPU test through the harness.

#[path = "../../slc-wgpu/examples/minimal.rs"]
#[allow(dead_code)]
mod minimal;

slc_tests::harness!(Gpu: minimal_example_matches_the_cpu);

/// The shader's sums against the CPU's, computed with the Rust functions
/// its WGSL was generated from: every kept count equal (the keep test
/// `d² < r²` sits on an f32 boundary only with probability ~2⁻²⁴ per pair;
/// 2M pairs allow a few flips, so up to 4 points may differ) and, where
/// the counts agree, the irradiance within 1e-4 relative (512-term f32
/// sums, `d²` possibly fused on the GPU).
fn minimal_example_matches_the_cpu() {
    let g = minimal::gpu().expect("the minimal example runs");
    let c = minimal::cpu();
    let (worst, counts) = minimal::compare(&g, &c);
    let kept = c.iter().map(|p| p[3]).sum::<f32>() / c.len() as f32;
    eprintln!(
        "minimal example: {kept:.1} lights kept per point, worst relative difference {worst:.2e}, {counts} kept counts differ"
    );
    assert!(
        kept > 5.0 && kept < minimal::LIGHTS as f32 * 0.9,
        "the roulette must keep some lights and cull others: {kept}"
    );
    assert!(counts <= 4, "{counts} points keep other lights than the CPU");
    assert!(worst <= 1e-4, "irradiance differs by {worst:.2e}");
}
