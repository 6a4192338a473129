//! The VPL frame's image-mean offset against the all-VPL reference, stage
//! by stage: interleaving alone, with the near field, and with the
//! denoise, for the unculled interleaved estimator (one frame: it is
//! deterministic) and for SLC (the mean over `frames` frames, a new ξ set
//! each), on the built-in Cornell box.
//!
//! ```sh
//! cargo run --release -p slc-cpu --example indirect_offset -- [size] [rsm] [frames]
//! ```
//! Prints, per configuration, the offset of the mean irradiance over the
//! shaded pixels (and of the albedo-weighted mean, what a composed image
//! shows) relative to the reference's, and for SLC one frame's standard
//! deviation of that offset and the standard error of the mean over frames.

use glam::Vec3;
use slc_cpu::vpl::VplContext;
use slc_cpu::vpl::denoise::Denoiser;
use slc_scene::scene::Scene;
use slc_scene::vpl::{Culling, GBuffer, PERIOD, VplSettings};

/// Mean irradiance (channel average) over the shaded pixels, and the
/// albedo-weighted mean.
fn means(e: &[Vec3], gb: &GBuffer) -> (f64, f64) {
    let (mut plain, mut albedo, mut n) = (0.0f64, 0.0f64, 0usize);
    for i in (0..e.len()).filter(|&i| gb.valid(i)) {
        let v = e[i].as_dvec3();
        plain += v.element_sum() / 3.0;
        albedo += (v * gb.albedo[i].as_dvec3()).element_sum() / 3.0;
        n += 1;
    }
    (plain / n as f64, albedo / n as f64)
}

fn main() {
    let args: Vec<u32> =
        std::env::args().skip(1).map(|a| a.parse().expect("numbers: size rsm frames")).collect();
    let size = args.first().copied().unwrap_or(256);
    let rsm = args.get(1).copied().unwrap_or(256);
    let frames = args.get(2).copied().unwrap_or(64);
    let ctx = VplContext::new(&Scene::cornell_box(), size, size, rsm, None).expect("context");
    let gb = ctx.gbuffer();
    let base = VplSettings::default();
    let reference = ctx
        .shade(&VplSettings { culling: Culling::Reference, ..base })
        .expect("reference")
        .irradiance;
    let (ref_plain, ref_albedo) = means(&reference, gb);
    println!(
        "Cornell box {size}x{size}, {} VPLs; reference mean irradiance {ref_plain:.6}, albedo-weighted {ref_albedo:.6}",
        rsm * rsm
    );
    println!(
        "{:<10} {:<28} {:>10} {:>10} {:>12} {:>10}",
        "method", "stages", "offset", "albedo-w.", "frame sd", "sem"
    );
    let mut denoiser = Denoiser::new(gb);
    // The filter on the true signal: what it does to the image mean where
    // its input is unbiased at every pixel.
    let (fp, fa) = means(&denoiser.filter_far(&reference, &[], gb, PERIOD), gb);
    println!(
        "{:<10} {:<28} {:>+9.3}% {:>+9.3}%",
        "reference",
        "denoise",
        100.0 * (fp / ref_plain - 1.0),
        100.0 * (fa / ref_albedo - 1.0)
    );
    // What the frame's expectation is with the near field: the filter of
    // the true far field, the (exact) near field added back.
    let near = ctx.shade(&VplSettings { culling: Culling::None, ..base }).expect("near field").near;
    let (fp, fa) = means(&denoiser.filter_far(&reference, &near, gb, PERIOD), gb);
    println!(
        "{:<10} {:<28} {:>+9.3}% {:>+9.3}%",
        "reference",
        "denoise of the far field",
        100.0 * (fp / ref_plain - 1.0),
        100.0 * (fa / ref_albedo - 1.0)
    );
    for culling in [Culling::None, base.culling] {
        let n = frames;
        for (stages, near_radius, denoise) in [
            ("interleave", Some(0.0), false),
            ("interleave + near", None, false),
            ("interleave + near + denoise", None, true),
        ] {
            let mut offsets = Vec::new();
            let mut albedo_offsets = Vec::new();
            for frame in 0..n {
                let st = VplSettings { culling, frame, near_radius, denoise, ..base };
                let shaded = ctx.shade(&st).expect("shade");
                let e = if denoise {
                    denoiser.filter_far(&shaded.irradiance, &shaded.near, gb, PERIOD)
                } else {
                    shaded.irradiance
                };
                let (plain, albedo) = means(&e, gb);
                offsets.push(plain / ref_plain - 1.0);
                albedo_offsets.push(albedo / ref_albedo - 1.0);
            }
            let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
            let (m, ma) = (mean(&offsets), mean(&albedo_offsets));
            let sd = (offsets.iter().map(|o| (o - m).powi(2)).sum::<f64>() / (n.max(2) - 1) as f64)
                .sqrt();
            let sem = sd / (n as f64).sqrt();
            println!(
                "{:<10} {:<28} {:>+9.3}% {:>+9.3}% {:>11.3}% {:>9.3}%",
                culling.name(),
                stages,
                100.0 * m,
                100.0 * ma,
                100.0 * if n > 1 { sd } else { 0.0 },
                100.0 * if n > 1 { sem } else { 0.0 }
            );
        }
    }
}
