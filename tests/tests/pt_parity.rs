//! CPU/GPU parity of the path tracer (application B).
//!
//! The two backends run the same estimator (`slc-reservoir`, k = 8, power
//! heuristic, the same ξ per light and pass) but draw their per-path random
//! numbers from different generators, so their images agree in
//! expectation, not pixel by pixel. Every bound below is therefore derived
//! from the variance measured over independent passes (fixed seeds):
//! - **Image mean.** The per-pass image means of the two backends agree
//!   within 5σ of the difference (σ² = σ²_cpu/n + σ²_gpu/n), and the GPU's
//!   agrees with the CPU's unculled `uniform` estimator within 5σ: the GPU
//!   estimator is unbiased.
//! - **Images.** RMSE(mean CPU image, mean GPU image) ≤ 1.5 × the RMSE that
//!   the per-pixel variances predict for two independent unbiased images,
//!   `√(mean_px (s²_cpu + s²_gpu)/n)` (observed 0.71 ×), so a per-pixel bias
//!   beyond about 1.3 × the predicted noise fails.
//! - **Hard cases.** Error bounds of 1e-30 (nothing culled) and 1e30
//!   (everything culled), intensities near slc's limit (`MAX_INTENSITY`,
//!   2⁵⁶) and subnormal: every
//!   pixel finite and non-negative, means as above.

use glam::Vec3;
use slc_core::ies::IesProfile;
use slc_core::light::{IesLight, Light, PointLight, SpotLight};
use slc_cpu::pt::CpuPathTracer;
use slc_scene::pt::{PtMethod, PtRender, PtScene, PtSettings};
use slc_scene::scene::Scene;
use slc_tests::{gpu, shared_data};
use slc_wgpu::passes::ShadowRays;
use slc_wgpu::pt::GpuPt;
use std::sync::Arc;

const W: u32 = 16;
const H: u32 = 16;

/// Bounces of the parity tests' paths: every depth runs the same kernels,
/// and on lavapipe each depth is two dispatches of about a millisecond per
/// pass whatever the image size (the default, 8, made this file a quarter
/// of CI's test time).
const DEPTH: u32 = 5;

/// Independent passes per method in the full-scene tests: about 40 ms each
/// on lavapipe at 16×16 and depth 5 (one submission, eleven dispatches and
/// the BSH's refit), so the two tests were 95 s of CI at 200 each. The
/// bounds follow the variance of the mean whatever the count. Diffuse: 120
/// (RMSE over its prediction 0.62–0.83 of the bound's 1.5). Glossy: 200, as
/// GGX's heavy-tailed passes make the variance estimate itself noisy (at
/// 120, slc-reservoir's ratio rose from 1.21 to 1.30).
const PASSES: [u32; 2] = [120, 200];

/// The Cornell box with its ceiling light split into 4×4 quads (32
/// triangle lights), plus a point, a spot and an IES light: every light
/// type of the path tracer, with more lights in range than reservoir slots.
/// Diffuse, or with [`Scene::cornell_box_glossy`]'s GGX floor, blocks and
/// ball.
fn scene(extra_intensity: f32, glossy: bool) -> (Scene, Vec<Light>) {
    let s = if glossy {
        Scene::cornell_box_glossy().split_light(4)
    } else {
        Scene::cornell_box_split_light(4)
    };
    let mut lights = vec![
        Light::Point(
            PointLight::new(Vec3::new(0.15, 0.45, 0.2), Vec3::splat(0.01 * extra_intensity))
                .unwrap(),
        ),
        Light::Spot(
            SpotLight::new(
                Vec3::new(0.4, 0.5, 0.4),
                Vec3::NEG_Y,
                Vec3::new(0.05, 0.03, 0.01) * extra_intensity,
                0.3,
                0.6,
            )
            .unwrap(),
        ),
    ];
    let profile = Arc::new(
        IesProfile::parse_bytes(&std::fs::read(shared_data("ies/indoor-60w-120deg.ies")).unwrap())
            .unwrap(),
    );
    lights.push(Light::Ies(
        IesLight::new(
            Vec3::new(0.3, 0.54, 0.15),
            Vec3::NEG_Y,
            Vec3::X,
            Vec3::splat(1e-4 * extra_intensity),
            profile,
        )
        .unwrap(),
    ));
    (s, lights)
}

/// Per-pass images (RGB per pixel, `3·pixel + channel`) from one pass at a
/// time, as differences of the accumulated sums. Asserts every accumulated
/// pixel is finite and non-negative.
fn passes(mut one: impl FnMut(&mut PtRender), n: u32, (w, h): (u32, u32)) -> Vec<Vec<f64>> {
    let mut acc = PtRender::new(w, h);
    let mut prev = vec![0.0f64; 3 * (w * h) as usize];
    (0..n)
        .map(|_| {
            one(&mut acc);
            let img = acc.image();
            assert!(
                img.data.iter().all(|v| v.is_finite() && v.min_element() >= 0.0),
                "a pixel is NaN, infinite or negative"
            );
            let total: Vec<f64> = img
                .data
                .iter()
                .flat_map(|v| v.to_array())
                .map(|c| c as f64 * acc.passes as f64)
                .collect();
            let pass: Vec<f64> = total.iter().zip(&prev).map(|(t, p)| t - p).collect();
            prev = total;
            pass
        })
        .collect()
}

/// Per-pixel mean (of the channels) and variance of that mean, and per
/// channel the image mean's mean and σ.
struct Stats {
    mean: Vec<f64>,
    var_of_mean: Vec<f64>,
    image_mean: [f64; 3],
    image_sigma: [f64; 3],
}

fn stats(p: &[Vec<f64>]) -> Stats {
    let n = p.len() as f64;
    let px = p[0].len() / 3;
    let grey = |x: &[f64], i: usize| (x[3 * i] + x[3 * i + 1] + x[3 * i + 2]) / 3.0;
    let mean: Vec<f64> = (0..px).map(|i| p.iter().map(|x| grey(x, i)).sum::<f64>() / n).collect();
    let var_of_mean = (0..px)
        .map(|i| p.iter().map(|x| (grey(x, i) - mean[i]).powi(2)).sum::<f64>() / (n - 1.0) / n)
        .collect();
    let (mut image_mean, mut image_sigma) = ([0.0; 3], [0.0; 3]);
    for c in 0..3 {
        let means: Vec<f64> =
            p.iter().map(|x| x.iter().skip(c).step_by(3).sum::<f64>() / px as f64).collect();
        image_mean[c] = means.iter().sum::<f64>() / n;
        let var = means.iter().map(|m| (m - image_mean[c]).powi(2)).sum::<f64>() / (n - 1.0);
        image_sigma[c] = (var / n).sqrt();
    }
    Stats { mean, var_of_mean, image_mean, image_sigma }
}

/// Each channel's image mean agrees within 5σ of the difference.
fn assert_means_agree(what: &str, a: &Stats, b: &Stats) {
    for c in 0..3 {
        let (ma, mb) = (a.image_mean[c], b.image_mean[c]);
        let bound = 5.0 * (a.image_sigma[c].powi(2) + b.image_sigma[c].powi(2)).sqrt();
        eprintln!(
            "{what} channel {c}: image means {ma:.5} vs {mb:.5}, |Δ| = {:.5}, 5σ = {bound:.5}",
            (ma - mb).abs()
        );
        assert!(
            (ma - mb).abs() <= bound,
            "{what} channel {c}: image means {ma} vs {mb} (5σ = {bound})"
        );
    }
}

fn all_finite(p: &[Vec<f64>]) -> bool {
    p.iter().flatten().all(|v| v.is_finite())
}

/// One scene's GPU and CPU path tracers, made once and shared by every
/// method the test runs on it (a `GpuPt` compiles its pipelines: on
/// lavapipe most of a small test's time; a baseline after an SLC method
/// renders as on a fresh one, `gpu_baselines_after_an_slc_method_are_unchanged`).
struct Parity {
    gpt: GpuPt,
    cpu: CpuPathTracer,
    passes: u32,
    size: (u32, u32),
    max_depth: u32,
}

impl Parity {
    /// `passes` independent passes per run at `size` pixels, paths of up to
    /// `max_depth` bounces; `None` without a GPU.
    fn new(scene: &PtScene, passes: u32, size: (u32, u32), max_depth: u32) -> Option<Self> {
        let gpt = GpuPt::new(gpu()?, scene, size.0, size.1).unwrap();
        Some(Parity { gpt, cpu: CpuPathTracer::new(scene), passes, size, max_depth })
    }

    fn settings(&self, method: PtMethod, eps: f32, seed: u32) -> PtSettings {
        PtSettings {
            method,
            error_bound: eps,
            seed,
            max_depth: self.max_depth,
            ..PtSettings::default()
        }
    }

    /// Per-pass statistics of `method` on the GPU and on the CPU (same seed).
    fn run(&mut self, method: PtMethod, eps: f32) -> (Stats, Stats) {
        let set = self.settings(method, eps, 3);
        let (n, size) = (self.passes, self.size);
        let gp = passes(|acc| _ = self.gpt.render(acc, &set, 1).unwrap(), n, size);
        let cp = passes(|acc| self.cpu.render(acc, &set, 1).unwrap(), n, size);
        assert!(
            all_finite(&gp) && all_finite(&cp),
            "{} at ε = {eps}: a pass is NaN or infinite",
            method.name()
        );
        (stats(&gp), stats(&cp))
    }

    /// Per-pass statistics of the CPU's unculled `uniform` estimator (its
    /// own seed), the reference every method's mean must match.
    fn unculled(&mut self) -> Stats {
        let set = self.settings(PtMethod::Uniform, 0.05, 77);
        let cpu = &mut self.cpu;
        stats(&passes(|acc| cpu.render(acc, &set, 1).unwrap(), self.passes, self.size))
    }
}

/// The test scene ([`scene`]) prepared for the path tracers.
fn pt_scene(intensity: f32, glossy: bool) -> PtScene {
    let (s, lights) = scene(intensity, glossy);
    PtScene::new(&s, &lights).unwrap()
}

/// Every method (slc, slc-reservoir, slc-weighted, uniform, power,
/// lightbvh) runs on the GPU as the CPU's estimator: same image mean,
/// images within the variance bound, and the same mean as the CPU's
/// unculled estimator.
fn gpu_path_tracer_matches_cpu_and_unculled_in_expectation() {
    matches_cpu_and_unculled(false);
}

/// The same on glossy surfaces (GGX BRDF, bounded-VNDF sampling, lobe-aware
/// light weights): every method.
fn gpu_path_tracer_matches_cpu_on_glossy_surfaces() {
    matches_cpu_and_unculled(true);
}

fn matches_cpu_and_unculled(glossy: bool) {
    let scene = pt_scene(1.0, glossy);
    let Some(mut parity) = Parity::new(&scene, PASSES[glossy as usize], (W, H), DEPTH) else {
        return;
    };
    let u = parity.unculled();
    for method in PtMethod::ALL {
        let (g, c) = parity.run(method, 0.05);
        let name = method.name();
        assert!(g.image_mean.iter().all(|&m| m > 0.0));
        assert_means_agree(&format!("GPU vs CPU {name}"), &g, &c);
        assert_means_agree(&format!("GPU {name} vs CPU uniform (unculled)"), &g, &u);
        let px = g.mean.len() as f64;
        let rmse =
            (g.mean.iter().zip(&c.mean).map(|(a, b)| (a - b).powi(2)).sum::<f64>() / px).sqrt();
        let predicted =
            (g.var_of_mean.iter().zip(&c.var_of_mean).map(|(a, b)| a + b).sum::<f64>() / px).sqrt();
        eprintln!(
            "{name}: RMSE(CPU, GPU) = {rmse:.5}, predicted by the variances {predicted:.5}, ratio {:.3}",
            rmse / predicted
        );
        assert!(
            rmse <= 1.5 * predicted,
            "{name}: RMSE(CPU, GPU) = {rmse} exceeds 1.5 × {predicted}"
        );
    }
}

/// The scene suite (`scenes/suite/`, the 2,048-light files: triangles
/// facing, away and any way; points in the volume, in clusters, log-normal
/// or one dominant; point/spot/IES mixes; spots aimed out; glossy
/// receivers) at its automatic ε: every method on the GPU has the CPU's
/// image mean and the CPU's unculled mean (5σ); 6×6 pixels, 32 passes, so
/// the ten families cost CI about what one scene of the tests above does.
fn gpu_path_tracer_matches_cpu_on_the_scene_suite() {
    if gpu().is_none() {
        return;
    }
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/suite");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.to_string_lossy().ends_with("-2048.toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 8, "the suite has {} families", files.len());
    for file in files {
        let f = slc_scene::scene_file::SceneFile::load(&file).unwrap();
        let scene = PtScene::new(&f.scene, &f.lights).unwrap();
        let eps = slc_scene::error_bound::auto_error_bound(
            &scene,
            1.0,
            slc_scene::error_bound::TARGET_CANDIDATES,
        )
        .unwrap();
        let name = file.file_stem().unwrap().to_string_lossy().into_owned();
        let mut parity = Parity::new(&scene, 32, (6, 6), 3).unwrap();
        let u = parity.unculled();
        for method in PtMethod::ALL {
            let (g, c) = parity.run(method, eps);
            let what = format!("{name} {}", method.name());
            assert_means_agree(&format!("{what}: GPU vs CPU"), &g, &c);
            assert_means_agree(&format!("{what}: GPU vs CPU uniform (unculled)"), &g, &u);
        }
    }
}

/// Hard cases on the GPU: nothing culled, everything culled, huge and
/// subnormal intensities: finite, non-negative, and the same mean as the CPU.
fn gpu_path_tracer_hard_cases() {
    for (eps, intensity) in [(1e-30f32, 1.0f32), (1e30, 1.0), (0.05, 1e17), (0.05, 1e-40)] {
        let scene = pt_scene(intensity, false);
        let Some(mut parity) = Parity::new(&scene, 40, (W, H), DEPTH) else { return };
        let (g, c) = parity.run(PtMethod::SlcReservoir, eps);
        assert!(g.image_mean.iter().all(|m| m.is_finite()));
        assert_means_agree(&format!("ε = {eps:e}, intensity ×{intensity:e}"), &g, &c);
    }
}

/// The baselines skip the SLC methods' per-pass BSH refit and write their
/// +∞ ranges once per `render` call: a baseline rendered after an SLC
/// method on the same `GpuPt` (whose ranges and tree that method left
/// behind) gives, pass by pass, exactly the image a fresh `GpuPt` gives,
/// over several calls (every pass of a call after its first reads the
/// ranges its first wrote).
fn gpu_baselines_after_an_slc_method_are_unchanged() {
    let Some(g) = gpu() else { return };
    let (s, lights) = scene(1.0, true);
    let pts = PtScene::new(&s, &lights).unwrap();
    for method in [PtMethod::Uniform, PtMethod::Power, PtMethod::LightBvh] {
        let set = PtSettings { method, error_bound: 0.05, seed: 3, ..PtSettings::default() };
        let render = |gpt: &mut GpuPt| {
            let mut acc = PtRender::new(W, H);
            for _ in 0..3 {
                gpt.render(&mut acc, &set, 2).unwrap();
            }
            acc.image().data
        };
        let fresh = render(&mut GpuPt::new(g, &pts, W, H).unwrap());
        let mut used = GpuPt::new(g, &pts, W, H).unwrap();
        let slc = PtSettings { method: PtMethod::SlcWeighted, ..set };
        used.render(&mut PtRender::new(W, H), &slc, 2).unwrap();
        assert!(
            render(&mut used) == fresh,
            "{}: the image depends on the method rendered before",
            method.name()
        );
    }
}

/// A mismatched accumulation, a zero depth and a NaN error bound are
/// typed errors on the GPU.
fn gpu_path_tracer_rejects_bad_settings() {
    let Some(g) = gpu() else { return };
    let (s, lights) = scene(1.0, false);
    let pts = PtScene::new(&s, &lights).unwrap();
    let mut gpt = GpuPt::new(g, &pts, W, H).unwrap();
    let ok = PtSettings { method: PtMethod::SlcReservoir, ..PtSettings::default() };
    assert!(gpt.render(&mut PtRender::new(W + 1, H), &ok, 1).is_err());
    assert!(gpt.render(&mut PtRender::new(W, H), &PtSettings { max_depth: 0, ..ok }, 1).is_err());
    assert!(
        gpt.render(&mut PtRender::new(W, H), &PtSettings { error_bound: f32::NAN, ..ok }, 1)
            .is_err()
    );
}

/// The light connections' shadow rays as ray queries
/// ([`GpuPt::with_shadow_rays`]) give the software walk's image: the same
/// random numbers, the same segments. Point, spot and IES lights (the
/// scene's split ceiling light dimmed to nothing): the same pixels to the
/// last bit. With the ceiling's 32 triangle lights: at most 1 pixel in 50
/// differs (lavapipe's ray queries report a hit the WGSL walk and the CPU
/// do not for a few segments that end on an emitter, always darker: 0.7%
/// of tri-facing-2048's pixels at 1 spp; docs/results/pt-ray-queries.md).
fn ray_query_path_tracer_equals_the_software_walk() {
    let Some(g) = slc_tests::ray_query_gpu() else { return };
    let (s, lights) = scene(1.0, false);
    let mut dark = s.clone();
    for m in dark.materials.iter_mut() {
        m.emission = Vec3::ZERO;
    }
    for (what, scene, exact) in [("point lights", &dark, true), ("with triangle lights", &s, false)]
    {
        let pts = PtScene::new(scene, &lights).unwrap();
        // One path tracer per kind of shadow ray, both rendering the same
        // methods in the same order.
        let mut hw_pt = GpuPt::with_shadow_rays(g, &pts, W, H, ShadowRays::RayQuery).unwrap();
        let mut sw_pt = GpuPt::with_shadow_rays(g, &pts, W, H, ShadowRays::Software).unwrap();
        for method in [PtMethod::SlcWeighted, PtMethod::Uniform, PtMethod::LightBvh] {
            let set = PtSettings {
                method,
                error_bound: 0.05,
                seed: 3,
                max_depth: DEPTH,
                ..PtSettings::default()
            };
            let render = |gpt: &mut GpuPt| {
                let mut acc = PtRender::new(W, H);
                gpt.render(&mut acc, &set, 4).unwrap();
                acc.image().data
            };
            let (hw, sw) = (render(&mut hw_pt), render(&mut sw_pt));
            let differ = hw.iter().zip(&sw).filter(|(a, b)| a != b).count();
            let lit = sw.iter().filter(|p| p.max_element() > 0.0).count();
            eprintln!("{what}, {}: {differ} of {} pixels differ", method.name(), sw.len());
            assert!(lit * 2 > sw.len(), "{what}: only {lit} lit pixels");
            if exact {
                assert_eq!(differ, 0, "{what}, {}: ray queries differ", method.name());
            } else {
                assert!(
                    differ * 50 <= sw.len(),
                    "{what}, {}: {differ} pixels differ",
                    method.name()
                );
            }
        }
    }
    g.take_errors().unwrap();
}

/// On a device opened without ray queries, asking for them is a typed
/// error, not a panic or a validation error.
fn ray_query_path_tracer_without_the_feature() {
    let Some(g) = gpu() else { return };
    if g.ray_query {
        return;
    }
    let (s, lights) = scene(1.0, false);
    let pts = PtScene::new(&s, &lights).unwrap();
    let r = GpuPt::with_shadow_rays(g, &pts, W, H, ShadowRays::RayQuery);
    assert!(matches!(r, Err(slc_wgpu::GpuError::Setting(_))), "{:?}", r.err());
    g.take_errors().unwrap();
}

/// The GPU's range tail (`bsh_tail`) takes the lights the CPU's refit
/// takes for the same pass, chains them after the tree in light order and
/// marks the same tree leaves; every sphere of the tree and of the tail in
/// use agrees within 1e-5 (the ranges are computed apart, a few ulps; the
/// points' ξ rotate together, the triangles' are their own). Over the scene suite's 2,048-light
/// points (volume, clusters) and triangles, and passes 0..3.
fn gpu_range_tail_matches_the_cpu_refit() {
    use slc_core::bsh::{BSH_NONE, BSH_TAIL, BshNode};
    use slc_core::range::{RangeParams, random_range2};
    use slc_core::xi::{light_xi, xi_keys};
    let Some(g) = gpu() else { return };
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/suite");
    for name in ["points-volume-2048", "points-clusters-2048", "tri-away-2048"] {
        let f = slc_scene::scene_file::SceneFile::load(&dir.join(format!("{name}.toml"))).unwrap();
        let pts = PtScene::new(&f.scene, &f.lights).unwrap();
        let eps = 0.5;
        let mut gpt = GpuPt::new(g, &pts, 4, 4).unwrap();
        let set = PtSettings {
            method: PtMethod::SlcWeighted,
            error_bound: eps,
            seed: 5,
            max_depth: 1,
            ..PtSettings::default()
        };
        let params = RangeParams::new(eps, set.exposure).unwrap();
        let mut acc = PtRender::new(4, 4);
        for pass in 0..3 {
            gpt.render(&mut acc, &set, 1).unwrap();
            let gn = gpt.read_bsh(g).unwrap();
            let keys = xi_keys(pts.lights());
            let r2: Vec<f32> = pts
                .lights()
                .iter()
                .zip(&keys)
                .map(|(l, &k)| {
                    random_range2(params.threshold_range2(l.peak()), light_xi(5, pass, k))
                })
                .collect();
            let mut cpu = pts.bsh().clone();
            cpu.refit(&r2).unwrap();
            let cn = cpu.nodes();
            assert_eq!(gn.len(), cn.len());
            let chain = |n: &[BshNode]| {
                let (mut v, mut i) = (Vec::new(), n[0].next);
                while i != BSH_NONE {
                    v.push(n[i as usize].light);
                    i = n[i as usize].next;
                }
                v
            };
            let tail = chain(cn);
            assert!(!tail.is_empty() && tail.len() <= 16, "{name}: a tail of {}", tail.len());
            assert_eq!(chain(&gn), tail, "{name}, pass {pass}");
            // The tree and the tail's slots in use (the others are stale).
            let used = cpu.tree_len() + tail.len();
            for (i, (a, b)) in gn[..used].iter().zip(&cn[..used]).enumerate() {
                let close = |x: f32, y: f32| (x - y).abs() <= 1e-5 * x.abs().max(y.abs());
                assert!(
                    close(a.radius, b.radius) && (a.center - b.center).length() <= 1e-5 * b.radius,
                    "{name}, pass {pass}, node {i}: {a:?} against {b:?}"
                );
                assert_eq!((a.child, a.next), (b.child, b.next), "{name}, node {i}");
                if b.child == BSH_NONE {
                    assert_eq!(a.light, b.light, "{name}, pass {pass}, leaf {i}");
                }
            }
            let marked = cn.iter().filter(|n| n.child == BSH_NONE && n.light & BSH_TAIL != 0);
            assert_eq!(marked.count(), tail.len());
        }
    }
    g.take_errors().unwrap();
}

/// The GPU's grids (`bsh_grid`) list, in every cell, in the walk's order,
/// each tree leaf the walk can find (not in the range tail) that reaches a
/// point of the cell: at 2,000 points drawn in the scene's box, against
/// every leaf, the Lambertian grid for the plain sphere test and the
/// glossy and sharp ones for a GGX receiver drawn at each point whose
/// range lobe they hold (the walk's leaf test, `bsh_reaches`), where the
/// cells' cut to the lobe's cone (`bsh_lobe_admits`) keeps every leaf
/// that reaches the point. And `slc-weighted`,
/// `slc-reservoir` and `slc` render the same image bit for bit with and
/// without them (the walk's lights in its order). Over the scene suite's
/// 2,048-light points (volume, clusters), triangles and glossy box, two
/// passes at depth 3 and the ε `slc render` sets for each.
fn gpu_grid_gives_the_walks_image() {
    use slc_core::bsh::grid::{
        GLOSSY_REACH, SHARP_REACH, bsh_grid_cell, bsh_lobe_admits, lobe_cone, walk_leaves,
    };
    use slc_core::bsh::walk::bsh_reaches;
    use slc_core::bsh::{BSH_NONE, BSH_TAIL};
    use slc_scene::error_bound::{TARGET_CANDIDATES, auto_error_bound};
    use slc_scene::scene::Material;
    let Some(g) = gpu() else { return };
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/suite");
    let mut glossy_held = [0; 3];
    for name in
        ["points-volume-2048", "points-clusters-2048", "tri-away-2048", "glossy-facing-2048"]
    {
        let f = slc_scene::scene_file::SceneFile::load(&dir.join(format!("{name}.toml"))).unwrap();
        let pts = PtScene::new(&f.scene, &f.lights).unwrap();
        let mut gpt = GpuPt::new(g, &pts, W, H).unwrap();
        let tree = pts.bsh().tree_len();
        let mut rank = vec![u32::MAX; pts.bsh().nodes().len()];
        for (r, &i) in walk_leaves(pts.bsh()).iter().enumerate() {
            rank[i as usize] = r as u32;
        }
        // The ε `slc render` takes for the scene.
        let eps = auto_error_bound(&pts, 1.0, TARGET_CANDIDATES).unwrap();
        for method in [PtMethod::SlcWeighted, PtMethod::SlcReservoir, PtMethod::Slc] {
            let set = PtSettings {
                method,
                seed: 3,
                max_depth: 3,
                error_bound: eps,
                ..PtSettings::default()
            };
            let mut images = Vec::new();
            for on in [true, false] {
                gpt.set_grid(on);
                let mut acc = PtRender::new(W, H);
                gpt.render(&mut acc, &set, 2).unwrap();
                images.push(acc.image().data);
                if !on || method != PtMethod::SlcWeighted {
                    continue;
                }
                let nodes = gpt.read_bsh(g).unwrap();
                let glossy = name.starts_with("glossy");
                assert_eq!(gpt.read_grid(g, 1).unwrap().is_some(), glossy, "{name}");
                assert_eq!(gpt.read_grid(g, 2).unwrap().is_some(), glossy, "{name}");
                for grid in 0..if glossy { 3 } else { 1 } {
                    let (frame, cells) = gpt.read_grid(g, grid).unwrap().unwrap();
                    assert!(
                        frame.nx > 0 && cells.len() as u64 == frame.cells(),
                        "{name}: no grid {grid}"
                    );
                    for cell in &cells {
                        let ranks: Vec<u32> = cell.iter().map(|&b| rank[b as usize]).collect();
                        assert!(
                            ranks.windows(2).all(|w| w[0] < w[1]),
                            "{name}: a cell out of order"
                        );
                        for &b in cell {
                            let n = nodes[b as usize];
                            assert!(
                                (b as usize) < tree
                                    && n.child == BSH_NONE
                                    && n.light & BSH_TAIL == 0
                            );
                        }
                    }
                    let (lo, hi) = pts.scene().bounds();
                    let mut h = 7u32;
                    let mut u = || {
                        h = slc_core::xi::pcg_hash(h);
                        slc_core::xi::xi_from_bits(h)
                    };
                    let mut held = 0;
                    for _ in 0..2000 {
                        let p = lo + (hi - lo) * Vec3::new(u(), u(), u());
                        // A GGX receiver for the glossy grid; none (the
                        // plain sphere test) for the Lambertian one.
                        let (mut r, mut rl) = (Vec3::Z, glam::Vec4::new(1.0, 0.0, 1.0, 1.0));
                        if grid > 0 {
                            let nrm = (Vec3::new(u(), u(), u()) - 0.5).normalize();
                            let v = (Vec3::new(u(), u(), u()) - 0.5 + nrm).normalize();
                            let metal = if u() < 0.5 { 1.0 } else { 0.0 };
                            let roughness = 0.05 + 0.95 * u();
                            let rc = Material::gltf(Vec3::splat(0.8), metal, roughness)
                                .receiver(p, nrm, v);
                            (r, rl) = (rc.r, rc.range_lobe());
                            let (a, b) =
                                [(1.0, GLOSSY_REACH), (GLOSSY_REACH, SHARP_REACH)][grid - 1];
                            if !(rl.w > a && rl.w <= b) {
                                continue;
                            }
                            glossy_held[grid] += 1;
                        }
                        let c = bsh_grid_cell(frame, p);
                        assert_ne!(c, BSH_NONE, "{name}: {p} outside the grid");
                        let cone = lobe_cone(r, rl);
                        let reaches = |b: usize| bsh_reaches(nodes[b], p, r, rl);
                        let admits = |b: usize| {
                            let n = nodes[b];
                            rl.w <= 1.0
                                || bsh_lobe_admits(n.center, n.radius, n.extent, p, rl.w, r, cone)
                        };
                        let walk = (0..tree)
                            .filter(|&i| {
                                nodes[i].child == BSH_NONE && nodes[i].light & BSH_TAIL == 0
                            })
                            .filter(|&i| reaches(i))
                            .count();
                        let listed = cells[c as usize]
                            .iter()
                            .filter(|&&b| admits(b as usize) && reaches(b as usize))
                            .count();
                        assert_eq!(
                            listed, walk,
                            "{name}, grid {grid}: the cell of {p} misses a leaf"
                        );
                        held += listed;
                    }
                    assert!(held > 0, "{name}, grid {grid}: no light found");
                }
            }
            assert!(
                images[0] == images[1],
                "{name}, {method:?}: the grid's image differs from the walk's"
            );
        }
    }
    assert!(
        glossy_held[1] > 500 && glossy_held[2] > 100,
        "{glossy_held:?} glossy and sharp receivers held"
    );
    g.take_errors().unwrap();
}

/// `bsh_grid` lists every cell exactly as the CPU would from the GPU's
/// refit: each leaf the walk can find in every cell its sphere covers, in
/// the walk's order, with both of stage 5's sorts: by insertion in one
/// invocation (the default budget: lavapipe's stage 4 fills cells almost
/// in order), and by the workgroup's bitonic sort (no budget), where some
/// cells hold more entries than it sorts in workgroup memory
/// (`GRID_SORT_MAX`) and are sorted in place (points-clusters-49152's
/// Lambertian grid: clusters of thousands of lights).
fn gpu_grid_cells_past_workgroup_memory() {
    use slc_core::bsh::grid::{bsh_grid_radius, walk_leaves};
    use slc_core::bsh::{BSH_NONE, BSH_TAIL};
    use slc_shared_shaders::layout::{GRID_SORT_MAX, GRID_SORT_MOVES};
    let Some(g) = gpu() else { return };
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/suite");
    let f =
        slc_scene::scene_file::SceneFile::load(&dir.join("points-clusters-49152.toml")).unwrap();
    let pts = PtScene::new(&f.scene, &f.lights).unwrap();
    let mut gpt = GpuPt::new(g, &pts, 8, 8).unwrap();
    gpt.set_grid(true);
    let set = PtSettings {
        method: PtMethod::SlcWeighted,
        seed: 5,
        max_depth: 1,
        ..PtSettings::default()
    };
    for moves in [GRID_SORT_MOVES, 0] {
        gpt.set_grid_sort_moves(moves);
        gpt.render(&mut PtRender::new(8, 8), &set, 1).unwrap();
        let nodes = gpt.read_bsh(g).unwrap();
        let (frame, cells) = gpt.read_grid(g, 0).unwrap().unwrap();
        assert!(frame.nx > 0, "no grid");
        let d = frame.dims();
        let mut expected = vec![Vec::new(); cells.len()];
        for b in walk_leaves(pts.bsh()) {
            let n = nodes[b as usize];
            if n.child != BSH_NONE || n.light & BSH_TAIL != 0 {
                continue;
            }
            let (lo, hi) = frame.cover(n.center, bsh_grid_radius(n, 1.0));
            for z in lo.z..=hi.z {
                for y in lo.y..=hi.y {
                    for x in lo.x..=hi.x {
                        expected[((z * d.y + y) * d.x + x) as usize].push(b);
                    }
                }
            }
        }
        let most = cells.iter().map(Vec::len).max().unwrap_or(0);
        assert!(most > GRID_SORT_MAX as usize, "the largest cell holds {most} entries");
        for (c, (got, want)) in cells.iter().zip(&expected).enumerate() {
            assert!(
                got == want,
                "moves {moves}, cell {c}: {} entries, {} expected",
                got.len(),
                want.len()
            );
        }
    }
    g.take_errors().unwrap();
}

slc_tests::harness!(
    Gpu: gpu_range_tail_matches_the_cpu_refit,
    Gpu: gpu_grid_gives_the_walks_image,
    Gpu: gpu_grid_cells_past_workgroup_memory,
    RayQuery: ray_query_path_tracer_equals_the_software_walk,
    Gpu: ray_query_path_tracer_without_the_feature,
    Gpu: gpu_path_tracer_matches_cpu_and_unculled_in_expectation,
    Gpu: gpu_path_tracer_matches_cpu_on_glossy_surfaces,
    Gpu: gpu_path_tracer_matches_cpu_on_the_scene_suite,
    Gpu: gpu_path_tracer_hard_cases,
    Gpu: gpu_path_tracer_rejects_bad_settings,
    Gpu: gpu_baselines_after_an_slc_method_are_unchanged,
);
