//! `slc bench`'s reference images, cached on disk by a hash of the scene and
//! settings, so a bench does not recompute the (expensive) ground truth. The
//! cache is the bench's business: the CPU backend only renders.

use glam::Vec3;
use slc_cpu::pt::CpuPathTracer;
use slc_cpu::vpl::VplContext;
use slc_scene::image::Image;
use slc_scene::pt::{PtRender, PtSettings};
use slc_scene::vpl::{Culling, VplSettings};
use slc_scene::{OutputError, RenderError};
use std::path::{Path, PathBuf};

/// Bumped when the reference renderer changes meaning.
/// 2: vertex normals (smooth shading) and one emitted-power formula.
/// 3: the lights' ξ over passes shuffled per light (`slc_core::xi::xi_for`).
const VERSION: u64 = 3;

/// FNV-1a, 64 bit.
fn fnv(bytes: &[u8], mut h: u64) -> u64 {
    for &b in bytes {
        h ^= b as u64;
        h = h.wrapping_mul(0x100_0000_01b3);
    }
    h
}

/// Hash of everything the VPL reference depends on.
pub fn vpl_reference_key(ctx: &VplContext) -> u64 {
    let s = ctx.scene();
    let mut h = fnv(&VERSION.to_le_bytes(), 0xcbf2_9ce4_8422_2325);
    for t in &s.triangles {
        for v in t {
            h = fnv(bytemuck::cast_slice(&v.to_array()), h);
        }
    }
    h = fnv(bytemuck::cast_slice(&s.material_of), h);
    h = normals_hash(&s.normals, h);
    let text = format!("{:?}{:?}{:?}", s.materials, s.camera, s.primary);
    h = fnv(text.as_bytes(), h);
    let gb = ctx.gbuffer();
    for x in [gb.width, gb.height, ctx.vpls().size, ctx.min_d2().to_bits()] {
        h = fnv(&x.to_le_bytes(), h);
    }
    h
}

/// The VPL reference image of `ctx`: read from `cache_dir` when present,
/// else rendered and stored there (`cache_dir = None` disables caching).
/// Returns the image and whether it came from the cache.
pub fn vpl_reference(
    ctx: &VplContext,
    cache_dir: Option<&Path>,
) -> Result<(Image, bool), RenderError> {
    let path =
        cache_dir.map(|d| d.join(format!("vpl-reference-{:016x}.bin", vpl_reference_key(ctx))));
    if let Some(p) = &path
        && let Some(img) = read_raw(p)
        && (img.width, img.height) == (ctx.gbuffer().width, ctx.gbuffer().height)
    {
        return Ok((img, true));
    }
    let frame =
        ctx.render(&VplSettings { culling: Culling::Reference, ..VplSettings::default() })?;
    if let Some(p) = &path {
        write_raw(p, &frame.image).map_err(|e| RenderError::Setting(e.to_string()))?;
    }
    Ok((frame.image, false))
}

/// A path-tracing reference and an estimate of its own noise.
pub struct PtReference {
    /// The image.
    pub image: Image,
    /// Estimated RMSE of the reference against the truth: it is rendered as
    /// two independent halves, and `RMSE(half₁, half₂)/2` estimates the
    /// noise of their mean. A method's RMSE near this is limited by the
    /// reference, not by the method.
    pub noise: f64,
    /// Whether it came from the cache.
    pub cached: bool,
}

/// The path-tracing reference of `pts` at `width × height`: `spp` passes of
/// `settings` in two halves with different seeds, cached in `cache_dir` by
/// a hash of scene, lights, size and settings. `progress(done, spp)` is
/// called as passes complete (a cached reference calls it once, done).
pub fn pt_reference(
    pts: &mut CpuPathTracer,
    width: u32,
    height: u32,
    settings: &PtSettings,
    spp: u32,
    cache_dir: Option<&Path>,
    progress: &mut dyn FnMut(u32, u32),
) -> Result<PtReference, RenderError> {
    let s = pts.scene().scene();
    let mut h = fnv(&VERSION.to_le_bytes(), 0x5bd1_e995_0000_0001);
    for t in &s.triangles {
        for v in t {
            h = fnv(bytemuck::cast_slice(&v.to_array()), h);
        }
    }
    h = fnv(bytemuck::cast_slice(&s.material_of), h);
    h = normals_hash(&s.normals, h);
    h = fnv(
        format!(
            "{:?}{:?}{:?}{:?}{}x{}x{}",
            s.materials,
            s.camera,
            pts.scene().lights_debug(),
            settings,
            width,
            height,
            spp
        )
        .as_bytes(),
        h,
    );
    let paths = cache_dir.map(|d| {
        (
            d.join(format!("pt-reference-{h:016x}-a.bin")),
            d.join(format!("pt-reference-{h:016x}-b.bin")),
        )
    });
    let cached = paths.as_ref().and_then(|(a, b)| Some((read_raw(a)?, read_raw(b)?)));
    let (a, b, from_cache) = match cached {
        Some((a, b)) if (a.width, a.height) == (width, height) => {
            progress(spp, spp);
            (a, b, true)
        }
        _ => {
            let per_half = spp.div_ceil(2);
            // A render split over calls equals one call: chunks of 8 passes
            // report progress without changing the image.
            let mut half = |seed: u32, before: u32| -> Result<Image, RenderError> {
                let mut acc = PtRender::new(width, height);
                while acc.passes < per_half {
                    let n = (per_half - acc.passes).min(8);
                    pts.render(&mut acc, &PtSettings { seed, ..*settings }, n)?;
                    progress(before + acc.passes, 2 * per_half);
                }
                Ok(acc.image())
            };
            let a = half(settings.seed, 0)?;
            let b = half(settings.seed ^ 0x9E37_79B9, per_half)?;
            if let Some((pa, pb)) = &paths {
                write_raw(pa, &a).map_err(|e| RenderError::Setting(e.to_string()))?;
                write_raw(pb, &b).map_err(|e| RenderError::Setting(e.to_string()))?;
            }
            (a, b, false)
        }
    };
    let noise = a.rmse(&b) / 2.0;
    let image = Image {
        width,
        height,
        data: a.data.iter().zip(&b.data).map(|(x, y)| (*x + *y) * 0.5).collect(),
    };
    Ok(PtReference { image, noise, cached: from_cache })
}

fn normals_hash(normals: &[[Vec3; 3]], mut h: u64) -> u64 {
    for t in normals {
        for v in t {
            h = fnv(bytemuck::cast_slice(&v.to_array()), h);
        }
    }
    h
}

fn read_raw(path: &Path) -> Option<Image> {
    let bytes = std::fs::read(path).ok()?;
    let (head, body) = bytes.split_at_checked(8)?;
    let w = u32::from_le_bytes(head[0..4].try_into().ok()?);
    let h = u32::from_le_bytes(head[4..8].try_into().ok()?);
    if body.len() != w as usize * h as usize * 12 {
        return None;
    }
    let data = body.chunks_exact(12).map(|c| {
        let f = |k: usize| f32::from_le_bytes(c[k..k + 4].try_into().expect("4 bytes"));
        Vec3::new(f(0), f(4), f(8))
    });
    Some(Image { width: w, height: h, data: data.collect() })
}

fn write_raw(path: &Path, img: &Image) -> Result<(), OutputError> {
    let err = |e: std::io::Error| OutputError(path.display().to_string(), e.to_string());
    if let Some(d) = path.parent() {
        std::fs::create_dir_all(d).map_err(err)?;
    }
    let mut bytes = Vec::with_capacity(8 + img.data.len() * 12);
    bytes.extend(img.width.to_le_bytes());
    bytes.extend(img.height.to_le_bytes());
    for p in &img.data {
        for c in p.to_array() {
            bytes.extend(c.to_le_bytes());
        }
    }
    let tmp = PathBuf::from(format!("{}.tmp{}", path.display(), std::process::id()));
    std::fs::write(&tmp, bytes).map_err(err)?;
    std::fs::rename(&tmp, path).map_err(err)
}
