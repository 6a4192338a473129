//! Smooth shading from vertex normals, on both backends and in both
//! applications' inputs: a coarse UV sphere (12 × 24, 552 triangles) with
//! exact vertex normals, lit by one point light, against the analytic
//! Lambert shading of the true sphere `ρ/π · I · cos θ / d²`, away from the
//! silhouette and the terminator. The same mesh without normals (faceted)
//! must miss the analytic image by much more: that is what the test detects.

use glam::Vec3;
use slc_core::light::{Light, PointLight};
use slc_cpu::pt::CpuPathTracer;
use slc_cpu::vpl::VplContext;
use slc_scene::backend::PathTracer;
use slc_scene::pt::{PtMethod, PtRender, PtScene, PtSettings};
use slc_scene::scene::{Camera, Material, PrimaryLight, Scene};

const W: u32 = 40;
const RHO: f32 = 0.8;
const LIGHT: Vec3 = Vec3::new(2.0, 2.5, 3.0);
const INTENSITY: f32 = 10.0;

/// A unit UV sphere at the origin; `smooth` gives it exact vertex normals.
fn sphere(smooth: bool) -> Scene {
    let (stacks, slices) = (12, 24);
    let p = |i: u32, j: u32| {
        let (t, f) = (
            std::f32::consts::PI * i as f32 / stacks as f32,
            std::f32::consts::TAU * j as f32 / slices as f32,
        );
        Vec3::new(t.sin() * f.cos(), t.cos(), t.sin() * f.sin())
    };
    let mut triangles = Vec::new();
    for i in 0..stacks {
        for j in 0..slices {
            let (a, b, c, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
            if i != 0 {
                triangles.push([a, c, b]);
            }
            if i != stacks - 1 {
                triangles.push([a, d, c]);
            }
        }
    }
    let normals = if smooth {
        triangles.iter().map(|t| t.map(|v: Vec3| v.normalize())).collect()
    } else {
        Vec::new()
    };
    Scene {
        name: "sphere".into(),
        material_of: vec![0; triangles.len()],
        triangles,
        normals,
        materials: vec![Material::lambertian(Vec3::splat(RHO), Vec3::ZERO)],
        camera: Camera {
            position: Vec3::new(0.0, 0.0, 4.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            vfov_deg: 35.0,
        },
        primary: PrimaryLight::Spot {
            position: LIGHT,
            direction: -LIGHT.normalize(),
            intensity: Vec3::ONE,
            inner: 0.0,
            outer: 1.0,
        },
        unsupported: Vec::new(),
    }
}

/// The analytic radiance of the true sphere through pixel `(x, y)`'s centre,
/// or `None` outside the tested region (beyond 80% of the silhouette
/// radius, or where `cos θ < 0.3`).
fn analytic(scene: &Scene, x: u32, y: u32) -> Option<f32> {
    let o = scene.camera.position;
    let d = scene.camera.ray_dir(x as f32, y as f32, W, W);
    // |o + t d|² = 1, and the ray's closest approach to the centre.
    let b = o.dot(d);
    let closest = (o - d * b).length();
    if closest > 0.8 {
        return None;
    }
    let t = -b - (b * b - (o.length_squared() - 1.0)).sqrt();
    let p = o + d * t;
    let v = LIGHT - p;
    let cos = p.normalize().dot(v.normalize());
    (cos >= 0.3).then(|| RHO / std::f32::consts::PI * INTENSITY * cos / v.length_squared())
}

/// Mean relative error over the tested region of an image (row-major, one
/// channel suffices: the light is white).
fn error(scene: &Scene, image: &[Vec3]) -> f64 {
    let (mut sum, mut n) = (0.0f64, 0);
    for y in 0..W {
        for x in 0..W {
            if let Some(a) = analytic(scene, x, y) {
                sum += ((image[(y * W + x) as usize].x - a).abs() / a) as f64;
                n += 1;
            }
        }
    }
    assert!(n > 200, "{n} tested pixels");
    sum / n as f64
}

fn light() -> Vec<Light> {
    vec![Light::Point(PointLight::new(LIGHT, Vec3::splat(INTENSITY)).unwrap())]
}

/// Direct light only (max depth 1), power sampling (one light: pdf 1), 16
/// jittered passes.
fn settings() -> PtSettings {
    PtSettings { method: PtMethod::Power, max_depth: 1, ..PtSettings::default() }
}

fn render(tracer: &mut impl PathTracer) -> Vec<Vec3> {
    let mut acc = PtRender::new(W, W);
    tracer.render(&mut acc, &settings(), 16).unwrap();
    acc.image().data
}

/// Bounds: the inscribed mesh lies up to 1 − cos 7.5° = 0.9% inside the
/// sphere and the pixel jitter averages over the pixel, so the smooth mesh
/// stays within 3% on average; the faceted one's normals are up to ~10° off
/// (several % of cos θ) and it must be at least twice as far off.
fn check(what: &str, smooth: f64, faceted: f64) {
    eprintln!("{what}: mean relative error smooth {smooth:.4}, faceted {faceted:.4}");
    assert!(smooth < 0.03, "{what}: smooth sphere off the analytic shading by {smooth}");
    assert!(
        faceted > 2.0 * smooth && faceted > 0.03,
        "{what}: faceted {faceted} is not clearly worse than smooth {smooth}"
    );
}

fn cpu_path_tracer_shades_vertex_normals_smoothly() {
    let e = |smooth: bool| {
        let s = sphere(smooth);
        let img = render(&mut CpuPathTracer::new(&PtScene::new(&s, &light()).unwrap()));
        error(&s, &img)
    };
    check("cpu", e(true), e(false));
}

fn gpu_path_tracer_shades_vertex_normals_smoothly() {
    let Some(g) = slc_tests::gpu() else { return };
    let e = |smooth: bool| {
        let s = sphere(smooth);
        let img = render(
            &mut slc_wgpu::pt::GpuPt::new(g, &PtScene::new(&s, &light()).unwrap(), W, W).unwrap(),
        );
        error(&s, &img)
    };
    check("gpu", e(true), e(false));
}

/// The VPL application's G-buffer (what both backends shade) carries the
/// interpolated normal: within 1.5° of the true sphere's normal where the
/// faceted one is off by several degrees.
fn vpl_gbuffer_carries_smooth_normals() {
    let worst = |smooth: bool| {
        let s = sphere(smooth);
        let ctx = VplContext::new(&s, W, W, 8, None).unwrap();
        let gb = ctx.gbuffer();
        let mut worst = 0.0f32;
        for y in 0..W {
            for x in 0..W {
                let i = (y * W + x) as usize;
                if analytic(&s, x, y).is_some() && gb.valid(i) {
                    worst = worst.max(
                        gb.normal[i]
                            .dot(gb.position[i].normalize())
                            .clamp(-1.0, 1.0)
                            .acos()
                            .to_degrees(),
                    );
                }
            }
        }
        worst
    };
    let (smooth, faceted) = (worst(true), worst(false));
    assert!(
        smooth < 1.5 && faceted > 4.0,
        "worst normal error: smooth {smooth}°, faceted {faceted}°"
    );
}

slc_tests::harness!(
    Cpu: cpu_path_tracer_shades_vertex_normals_smoothly,
    Gpu: gpu_path_tracer_shades_vertex_normals_smoothly,
    Cpu: vpl_gbuffer_carries_smooth_normals,
);
