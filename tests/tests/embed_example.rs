//! The embed example (`slc-wgpu/examples/embed.rs`: an engine's own
//! device, pipelines and G-buffer, slc's passes recorded into its encoder)
//! run as a GPU test through the harness, so that without an adapter it
//! shows as ignored with the reason, and under `SLC_REQUIRE_GPU=1` fails,
//! instead of passing without running.

#[path = "../../slc-wgpu/examples/embed.rs"]
#[allow(dead_code)]
mod embed;

use embed::{H, RSM, W, render, settings, small_lights_at};
use glam::{DVec3, Vec3};
use slc_cpu::vpl::VplContext;
use slc_scene::scene::Scene;
use slc_scene::vpl::{Culling, VplSettings};

slc_tests::harness!(Gpu: embed_matches_the_cpu_frame);

/// The engine's rasterized frame against the CPU backend's ray-cast
/// frame (same scene, size, RSM and settings, method `none`, so no ξ
/// and no roulette): rasterization and ray casting differ at
/// silhouettes and half floats round the RSM's normal and flux, so the
/// bounds are on the image: each channel's mean within 1%, median pixel within 1%,
/// at most 2% of the pixels with a different surface (valid mask).
fn embed_matches_the_cpu_frame() {
    let scene = Scene::cornell_box();
    let s = VplSettings { culling: Culling::None, denoise: false, ..settings() };
    let frame = render(&scene, &s, 0.05, 1).expect("the embed example renders");
    let ctx = VplContext::new(&scene, W, H, RSM, Some(0.05)).unwrap();
    let cpu = ctx.shade(&s).unwrap();
    let gb = ctx.gbuffer();
    let (mut mask_differs, mut rel, mut sum_gpu, mut sum_cpu) =
        (0usize, Vec::new(), DVec3::ZERO, DVec3::ZERO);
    for i in 0..cpu.irradiance.len() {
        let g = &frame.irradiance[i];
        let gpu_valid = g[3] > 0.0 || (g[0], g[1], g[2]) != (0.0, 0.0, 0.0);
        let (a, b) = (Vec3::new(g[0], g[1], g[2]), cpu.irradiance[i]);
        sum_gpu += a.as_dvec3();
        sum_cpu += b.as_dvec3();
        if gpu_valid != gb.valid(i) {
            mask_differs += 1;
        } else if gb.valid(i) {
            rel.push(((a - b).abs().element_sum() / b.element_sum().max(1e-12)) as f64);
        }
    }
    rel.sort_by(f64::total_cmp);
    let median = rel[rel.len() / 2];
    // The worst channel's image-mean difference.
    let mean_rel = ((sum_gpu - sum_cpu).abs() / sum_cpu).max_element();
    let share = mask_differs as f64 / cpu.irradiance.len() as f64;
    eprintln!(
        "embed vs CPU: mean {mean_rel:.2e} relative, median pixel {median:.2e}, {:.2}% of pixels see another surface",
        100.0 * share
    );
    assert!(mean_rel <= 0.01, "image mean differs by {mean_rel:.3e}");
    assert!(median <= 0.01, "median pixel differs by {median:.3e}");
    assert!(share <= 0.02, "{:.2}% of the pixels see another surface", 100.0 * share);
    assert!(frame.image.is_finite() && frame.image.mean() > 0.0);

    // The small lights' direct light at frame 3, where the example has
    // moved and brightened them with update_lights (the pass was built with
    // frame 0's), against the CPU's (slc_cpu::direct, the same lights, seed
    // and frame, the CPU's ray-cast G-buffer): the image means within 2%
    // (rasterized points differ at silhouettes). Frame 0's lights at frame
    // 3 light the image ~20% less: a pass that kept them fails.
    let s = VplSettings { frame: 3, ..settings() };
    let frame = render(&scene, &s, 0.05, 1).unwrap();
    let points: Vec<Vec3> = (0..gb.position.len())
        .map(|i| if gb.valid(i) { gb.position[i] } else { Vec3::NAN })
        .collect();
    let params = s.culling.range_params().expect("the example's culling is stochastic");
    let cpu_sum = |f: u32| -> DVec3 {
        let mut lights = slc_cpu::direct::DirectLights::new(
            &slc_scene::lights::LightSet::new(small_lights_at(f)).unwrap(),
        );
        lights
            .shade(&points, &gb.normal, &params, s.seed, s.frame)
            .unwrap()
            .iter()
            .map(|d| d.irradiance.as_dvec3())
            .sum()
    };
    let (sum_cpu, unmoved) = (cpu_sum(s.frame), cpu_sum(0));
    let sum_gpu: DVec3 = frame.direct.iter().map(|d| Vec3::new(d[0], d[1], d[2]).as_dvec3()).sum();
    let rel = ((sum_gpu - sum_cpu).abs() / sum_cpu).max_element();
    let moved = ((unmoved - sum_cpu).abs() / sum_cpu).min_element();
    eprintln!(
        "small lights' direct light at frame {}: GPU pass {sum_gpu:.4}, CPU {sum_cpu:.4}, worst channel {rel:.2e} relative (unmoved lights: {moved:.2e} off)",
        s.frame
    );
    assert!(
        moved > 0.1,
        "the lights barely changed between frames 0 and {} ({moved:.3e}): the test cannot see update_lights",
        s.frame
    );
    assert!(frame.direct.iter().all(|d| d.iter().all(|v| v.is_finite() && *v >= 0.0)));
    assert!(rel <= 0.02, "direct light means differ by {rel:.3e}");
}
