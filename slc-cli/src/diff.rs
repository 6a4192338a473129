//! `slc diff A.exr B.exr`: image difference statistics and a heat map.

use anyhow::anyhow;
use clap::Args;
use slc_scene::image::{Image, write_rgb8_png};
use std::path::PathBuf;

#[derive(Args)]
pub struct DiffArgs {
    /// First image (EXR).
    a: PathBuf,
    /// Second image (EXR), the reference for relative error.
    b: PathBuf,
    /// Write |A − B| (channel mean) as a colour heat map PNG.
    #[arg(long)]
    heatmap: Option<PathBuf>,
    /// Exit with status 1 when the RMSE exceeds this.
    #[arg(long)]
    max_rmse: Option<f64>,
}

/// Difference statistics over finite pixels.
#[derive(Debug, PartialEq)]
pub struct DiffStats {
    /// `sqrt(mean((a − b)²))` over pixels and channels.
    pub rmse: f64,
    /// `sqrt(mean((a − b)² / (b² + 0.01)))` (pbrt's relative MSE, rooted).
    pub rel_rmse: f64,
    /// Largest `|a − b|` over pixels and channels.
    pub max_abs: f64,
    /// Non-finite channel values in A and in B (excluded from the above).
    pub nonfinite: (usize, usize),
}

pub fn stats(a: &Image, b: &Image) -> DiffStats {
    let (mut se, mut rel, mut max_abs, mut n) = (0.0f64, 0.0f64, 0.0f64, 0usize);
    let (mut bad_a, mut bad_b) = (0, 0);
    for (pa, pb) in a.data.iter().zip(&b.data) {
        for c in 0..3 {
            let (x, y) = (pa[c] as f64, pb[c] as f64);
            bad_a += !x.is_finite() as usize;
            bad_b += !y.is_finite() as usize;
            if x.is_finite() && y.is_finite() {
                let d = x - y;
                se += d * d;
                rel += d * d / (y * y + 0.01);
                max_abs = max_abs.max(d.abs());
                n += 1;
            }
        }
    }
    let n = n.max(1) as f64;
    DiffStats {
        rmse: (se / n).sqrt(),
        rel_rmse: (rel / n).sqrt(),
        max_abs,
        nonfinite: (bad_a, bad_b),
    }
}

/// A perceptually ordered colour ramp (dark blue → teal → yellow), `t ∈ [0, 1]`.
fn ramp(t: f32) -> [u8; 3] {
    const STOPS: [[f32; 3]; 5] = [
        [0.05, 0.03, 0.25],
        [0.23, 0.32, 0.55],
        [0.13, 0.57, 0.55],
        [0.37, 0.79, 0.38],
        [0.99, 0.91, 0.14],
    ];
    let t = if t.is_finite() { t.clamp(0.0, 1.0) } else { 1.0 } * 4.0;
    let i = (t as usize).min(3);
    let f = t - i as f32;
    let c = |k: usize| STOPS[i][k] + (STOPS[i + 1][k] - STOPS[i][k]) * f;
    [c(0), c(1), c(2)].map(|x| (x * 255.0 + 0.5) as u8)
}

pub fn run(a: DiffArgs) -> anyhow::Result<()> {
    if let Some(out) = &a.heatmap {
        crate::png_only("--heatmap", out)?;
    }
    if let Some(limit) = a.max_rmse
        && !(limit >= 0.0 && limit.is_finite())
    {
        return Err(anyhow!("--max-rmse {limit} must be a finite RMSE of at least 0"));
    }
    let read = |p: &std::path::Path| {
        if p.extension().and_then(|e| e.to_str()).is_some_and(|e| e.eq_ignore_ascii_case("png")) {
            return Err(anyhow!(
                "{}: diff compares linear EXR images; a PNG is the tone-mapped 8-bit preview (compare the .exr written beside it)",
                p.display()
            ));
        }
        Image::read_exr(p).map_err(|e| anyhow!("{}: {e} (diff reads EXR images)", p.display()))
    };
    let (ia, ib) = (read(&a.a)?, read(&a.b)?);
    if (ia.width, ia.height) != (ib.width, ib.height) {
        return Err(anyhow!(
            "image sizes differ: {}x{} vs {}x{}",
            ia.width,
            ia.height,
            ib.width,
            ib.height
        ));
    }
    let s = stats(&ia, &ib);
    println!("{} vs {} ({}x{})", a.a.display(), a.b.display(), ia.width, ia.height);
    println!("  RMSE            {:.6}", s.rmse);
    println!("  relative RMSE   {:.6}", s.rel_rmse);
    println!("  max |a - b|     {:.6}", s.max_abs);
    println!("  NaN/inf values  {} in A, {} in B", s.nonfinite.0, s.nonfinite.1);
    if let Some(out) = &a.heatmap {
        let d: Vec<f32> = ia
            .data
            .iter()
            .zip(&ib.data)
            .map(|(x, y)| (*x - *y).abs().element_sum() / 3.0)
            .collect();
        let max = d.iter().cloned().filter(|v| v.is_finite()).fold(0.0f32, f32::max).max(1e-12);
        let bytes: Vec<u8> = d.iter().flat_map(|&v| ramp(v / max)).collect();
        write_rgb8_png(out, ia.width, ia.height, &bytes)?;
        println!("  heat map        {} (yellow = {:.6})", out.display(), max);
    }
    if let Some(limit) = a.max_rmse
        && (s.rmse.partial_cmp(&limit) != Some(std::cmp::Ordering::Less) && s.rmse != limit
            || s.nonfinite != (0, 0))
    {
        println!("  FAIL: RMSE {:.6} over --max-rmse {limit} (or non-finite values)", s.rmse);
        std::process::exit(1);
    }
    Ok(())
}
