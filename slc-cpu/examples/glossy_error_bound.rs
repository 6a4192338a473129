//! What SLC's error bound lets through on glossy receivers (issue 30, item
//! 5), measured in a rendered image.
//!
//! The glossy Cornell box (`Scene::cornell_box_glossy`) with its ceiling
//! light split into 16×16 quads (512 triangle lights), direct light only
//! (`max_depth` 1), `slc` with the given ε against the same estimator with
//! nothing culled (ε = 1e-30: every light kept, `1/p = 1`). Both draw the
//! same kinds of random numbers, so the difference of their per-pixel
//! variances over passes is the variance SLC's roulette adds. Pixels are
//! grouped by the material their camera ray sees; per group the example
//! prints the mean radiance, the added standard deviation per pass (absolute
//! and relative to the radiance), that deviation relative to the
//! Lambertian walls', and relative to what the roulette adds at the same
//! pixels when every surface is white Lambertian (the receiver the 2016
//! bound is stated for: the ratio says how the glossy range scale holds the
//! bound there).
//!
//!     cargo run --release -p slc-cpu --example glossy_error_bound -- [EPS] [PASSES] [SIZE]

use slc_core::ray::ray_t_min;
use slc_cpu::geometry::Geometry;
use slc_cpu::pt::CpuPathTracer;
use slc_scene::pt::{PtMethod, PtRender, PtScene, PtSettings};
use slc_scene::scene::{Material, Scene};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let eps: f32 = args.next().map_or(Ok(0.05), |a| a.parse())?;
    let passes: u32 = args.next().map_or(Ok(128), |a| a.parse())?;
    let size: u32 = args.next().map_or(Ok(48), |a| a.parse())?;
    let scene = Scene::cornell_box_glossy().split_light(16);
    let pts = PtScene::new(&scene, &[])?;
    let mut white = scene.clone();
    for m in white.materials.iter_mut().filter(|m| m.emission == glam::Vec3::ZERO) {
        *m = Material::lambertian(glam::Vec3::ONE, glam::Vec3::ZERO);
    }
    let white = PtScene::new(&white, &[])?;
    // Per-pass grey values per pixel for one error bound.
    let per_pass = |pts: &PtScene, eps: f32| -> Result<Vec<Vec<f64>>, Box<dyn std::error::Error>> {
        let mut tracer = CpuPathTracer::new(pts);
        let s = PtSettings {
            method: PtMethod::Slc,
            error_bound: eps,
            max_depth: 1,
            seed: 5,
            ..PtSettings::default()
        };
        let mut acc = PtRender::new(size, size);
        let mut prev = vec![0.0f64; (size * size) as usize];
        let mut out = Vec::new();
        for _ in 0..passes {
            tracer.render(&mut acc, &s, 1)?;
            let total: Vec<f64> = acc
                .image()
                .data
                .iter()
                .map(|v| (v.x + v.y + v.z) as f64 / 3.0 * acc.passes as f64)
                .collect();
            out.push(total.iter().zip(&prev).map(|(t, p)| t - p).collect());
            prev = total;
        }
        Ok(out)
    };
    let slc = per_pass(&pts, eps)?;
    let all = per_pass(&pts, 1e-30)?;
    let slc_white = per_pass(&white, eps)?;
    let all_white = per_pass(&white, 1e-30)?;
    let stats = |p: &[Vec<f64>], i: usize| {
        let n = p.len() as f64;
        let m = p.iter().map(|x| x[i]).sum::<f64>() / n;
        (m, p.iter().map(|x| (x[i] - m).powi(2)).sum::<f64>() / (n - 1.0))
    };
    // The material each pixel's centre ray sees.
    let geo = Geometry::new(&scene.triangles);
    let (f, r, u) = scene.camera.scaled_basis(size, size);
    let names = [
        "walls (Lambertian)",
        "floor (dielectric, r 0.3)",
        "tall block (metal, r 0.15)",
        "short block (gold, r 0.4)",
        "ball (plastic, r 0.2)",
    ];
    let group = |m: u32| match m {
        0..=3 => 0,
        4 => 1,
        5 => 2,
        6 => 3,
        _ => 4,
    };
    let mut acc = [(0.0f64, 0.0f64, 0usize, 0.0f64); 5];
    for i in 0..(size * size) as usize {
        let (x, y) = ((i as u32 % size) as f32 + 0.5, (i as u32 / size) as f32 + 0.5);
        let dir = slc_core::path::camera_dir(f, r, u, x, y, size as f32, size as f32);
        let Some(hit) =
            geo.intersect(scene.camera.position, dir, ray_t_min(scene.diagonal()), f32::INFINITY)
        else {
            continue;
        };
        let m = scene.material_of[hit.triangle as usize];
        if scene.materials[m as usize].emission.max_element() > 0.0 {
            continue;
        }
        let ((mean, v_slc), (_, v_all)) = (stats(&slc, i), stats(&all, i));
        let ((_, w_slc), (_, w_all)) = (stats(&slc_white, i), stats(&all_white, i));
        let g = &mut acc[group(m)];
        g.0 += mean;
        g.1 += (v_slc - v_all).max(0.0);
        g.2 += 1;
        g.3 += (w_slc - w_all).max(0.0);
    }
    println!(
        "glossy Cornell box, 512 lights, direct light, {size}x{size}, {passes} passes, slc ε = {eps} against nothing culled"
    );
    println!(
        "{:<28} {:>7} {:>10} {:>12} {:>10} {:>12} {:>14}",
        "seen material", "pixels", "radiance", "added σ", "σ/radiance", "σ / walls'", "σ / white's"
    );
    let walls = (acc[0].1 / acc[0].2.max(1) as f64).sqrt();
    for (name, (m, v, n, w)) in names.iter().zip(acc) {
        if n == 0 {
            continue;
        }
        let (mean, sd) = (m / n as f64, (v / n as f64).sqrt());
        println!(
            "{name:<28} {n:>7} {mean:>10.4} {sd:>12.5} {:>10.3} {:>12.2} {:>14.2}",
            sd / mean,
            sd / walls,
            sd / (w / n as f64).sqrt()
        );
    }
    Ok(())
}
