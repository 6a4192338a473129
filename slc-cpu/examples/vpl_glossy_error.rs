//! The VPL application on the glossy Cornell box: per material the camera
//! sees, the image mean and RMSE of a frame against the reference (every
//! VPL at every pixel, shaded with the glTF BRDF), for the frame shaded
//! with the BRDF and for the same frame composed as before (VPL and
//! direct light as `albedo/π · E`, the specular correction dropped).
//!
//! `cargo run --release -p slc-cpu --example vpl_glossy_error -- [SIZE] [RSM] [METHOD]`
//! (defaults 128, 256, slc; METHOD: slc, clamp or none).

use glam::DVec3;
use slc_cpu::vpl::VplContext;
use slc_scene::culling::{DEFAULT_CLAMP_RANGE, DEFAULT_ERROR_BOUND};
use slc_scene::scene::Scene;
use slc_scene::vpl::{Culling, Shaded, VplSettings};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let size: u32 = args.get(1).map_or(Ok(128), |s| s.parse())?;
    let rsm: u32 = args.get(2).map_or(Ok(256), |s| s.parse())?;
    let name = args.get(3).map_or("slc", String::as_str);
    let culling = Culling::named(name, DEFAULT_ERROR_BOUND, 1.0, DEFAULT_CLAMP_RANGE)?;
    let ctx = VplContext::new(&Scene::cornell_box_glossy(), size, size, rsm, None)?;
    let reference =
        ctx.render(&VplSettings { culling: Culling::Reference, ..VplSettings::default() })?.image;
    let settings = VplSettings { culling, ..VplSettings::default() };
    let shaded = ctx.shade(&settings)?;
    let lambert = Shaded { specular: Vec::new(), specular_near: Vec::new(), ..shaded.clone() };
    let (brdf, lambert) =
        (ctx.finish(shaded, &settings).image, ctx.finish(lambert, &settings).image);
    let gb = ctx.gbuffer();
    // The box's materials, told apart by their lobes (cornell_box_glossy).
    let class = |i: usize| match gb.specular_at(i) {
        None => "walls (Lambertian)",
        Some(s) if s.metallic == 1.0 && s.roughness < 0.2 => "tall block (metal, roughness 0.15)",
        Some(s) if s.metallic == 1.0 => "short block (gold, roughness 0.4)",
        Some(s) if s.roughness > 0.25 => "floor (dielectric, roughness 0.3)",
        Some(_) => "ball (plastic, roughness 0.2)",
    };
    println!(
        "{size}x{size}, {} VPLs, {}: per seen material, mean (rel. to reference) and RMSE",
        rsm * rsm,
        culling.name()
    );
    println!(
        "| seen material | reference mean | BRDF: mean | BRDF: RMSE | as before: mean | as before: RMSE |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    let names: Vec<&str> = (0..gb.position.len())
        .filter(|&i| gb.valid(i))
        .map(class)
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    for name in names {
        let px: Vec<usize> =
            (0..gb.position.len()).filter(|&i| gb.valid(i) && class(i) == name).collect();
        let n = px.len() as f64;
        let mean = |img: &[glam::Vec3]| {
            px.iter().map(|&i| img[i].as_dvec3()).sum::<DVec3>().element_sum() / (3.0 * n)
        };
        let rmse = |img: &[glam::Vec3]| {
            (px.iter()
                .map(|&i| (img[i] - reference.data[i]).as_dvec3().length_squared())
                .sum::<f64>()
                / (3.0 * n))
                .sqrt()
        };
        let r = mean(&reference.data);
        println!(
            "| {name} | {r:.4} | {:+.1}% | {:.4} | {:+.1}% | {:.4} |",
            100.0 * (mean(&brdf.data) / r - 1.0),
            rmse(&brdf.data),
            100.0 * (mean(&lambert.data) / r - 1.0),
            rmse(&lambert.data)
        );
    }
    Ok(())
}
