//! Application A on the GPU for the G-buffer and VPLs of a
//! [`slc_scene::vpl::VplInputs`] (whoever made them: the CPU backend ray
//! casts them), a thin caller of the engine's [`IndirectPass`], as
//! [`crate::direct::GpuDirect`] is of the direct pass: the G-buffer and the
//! VPLs are uploaded once as a position G-buffer and an RSM, each shade
//! records the pass (its uniforms, its cached bind groups),
//! submits it and reads its output back. [`GpuVpl`] is an
//! [`IndirectShader`]; the frame's composition is the caller's.
//!
//! [`Culling::Reference`] records a second pass built without
//! interleaving ([`IndirectPassDesc::interleaved`]`: false`, unculled,
//! neither denoised nor split into near and far fields; built at the first
//! reference shade); a fixed ξ ([`VplSettings::fixed_xi`]) is the pass's
//! own. The CPU's `tile` (its tile size) has no GPU counterpart: the
//! kernels' tiles are [`TILE`] pixels.
//!
//! A G-buffer with specular lobes ([`slc_scene::vpl::GBuffer::has_specular`])
//! builds the pass glossy ([`IndirectPassDesc::glossy`]): the pixels' glTF
//! materials are uploaded as a material table (one entry per distinct
//! material, its index in the normal texture's `w`), and
//! [`Shaded::specular`] comes back as the CPU's does (the specular
//! correction at the pixels with a specular lobe, zero elsewhere; denoised
//! on the GPU when the irradiance is).

use crate::kernel::storage;
use crate::passes::{
    Culling, GBuffer, IndirectInputs, IndirectMaterials, IndirectPass, IndirectPassDesc,
    IndirectSettings, Surface, SurfaceDesc, VplInput, VplSourceDesc,
};
use crate::timing::Timer;
use crate::{GpuContext, GpuError};
use glam::Vec3;
use slc_scene::backend::IndirectShader;
use slc_scene::vpl::{Shaded, Specular, VplInputs, VplSettings};
use slc_shared_shaders::layout::GpuMaterial;
use std::time::Instant;

pub use crate::passes::indirect::{TILE, TILE_LIST};

/// Which of a shade's submissions a stage of the pass belongs to: each is
/// submitted (and timed) on its own.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Part {
    /// VPL packing (untimed).
    Setup,
    /// Light update and tiled shading.
    Shading,
    /// The cross-bilateral filter.
    Denoise,
    /// The near field (shading time).
    Near,
    /// The irradiance into the output texture (untimed).
    Export,
}

impl Part {
    const ALL: [Part; 5] = [Part::Setup, Part::Shading, Part::Denoise, Part::Near, Part::Export];

    fn of(stage: crate::timing::Stage) -> Part {
        use crate::timing::Stage;
        match stage {
            Stage::LightUpdate | Stage::Shading => Part::Shading,
            Stage::Denoise => Part::Denoise,
            Stage::NearField => Part::Near,
            Stage::IrradianceExport => Part::Export,
            _ => Part::Setup,
        }
    }

    fn timed(self) -> bool {
        matches!(self, Part::Shading | Part::Denoise | Part::Near)
    }
}

/// The [`IndirectPass`] over one [`VplInputs`] (one G-buffer and VPL set),
/// with the inputs uploaded once.
pub struct GpuVpl {
    gpu: GpuContext,
    /// Interleaved, the pass every method but the reference records.
    pass: IndirectPass,
    /// Not interleaved (the reference), built at its first use.
    reference: Option<IndirectPass>,
    position: wgpu::TextureView,
    normal: wgpu::TextureView,
    rsm: [wgpu::TextureView; 3],
    output: wgpu::Texture,
    output_view: wgpu::TextureView,
    /// The output's read-back buffer (rows padded to the copy alignment).
    staging: wgpu::Buffer,
    /// A glossy G-buffer's material table and specular output.
    glossy: Option<GlossyTargets>,
    eye: Vec3,
    min_distance: f32,
    /// Pixels that see a surface.
    valid: Vec<bool>,
    /// Timestamps around the timed parts; `None` where the adapter has none
    /// or is a software one, whose timestamps do not bracket the work.
    timer: Option<Timer>,
}

/// The material input of a glossy [`GpuVpl`]: the pixels' materials and
/// the specular correction's target and read-back buffer.
struct GlossyTargets {
    table: wgpu::Buffer,
    output: wgpu::Texture,
    view: wgpu::TextureView,
    staging: wgpu::Buffer,
}

/// The distinct materials of a G-buffer's pixels (base colour and specular
/// lobe; emission plays no part in VPL shading) as a table, and each
/// pixel's index into it (0 where no surface is).
fn material_table(gb: &slc_scene::vpl::GBuffer) -> (Vec<GpuMaterial>, Vec<u32>) {
    let mut table: Vec<GpuMaterial> = Vec::new();
    let mut seen = std::collections::HashMap::new();
    let index = (0..gb.position.len())
        .map(|i| {
            let s = if gb.valid(i) {
                gb.specular.get(i).copied().unwrap_or_default()
            } else {
                Specular::default()
            };
            let b = if gb.valid(i) { gb.albedo[i] } else { Vec3::ZERO };
            let key = [b.x, b.y, b.z, s.metallic, s.roughness, s.f0.x, s.f0.y, s.f0.z, s.f90]
                .map(f32::to_bits);
            *seen.entry(key).or_insert_with(|| {
                table.push(GpuMaterial::new(b, Vec3::ZERO, s.metallic, s.roughness, s.f0, s.f90));
                table.len() as u32 - 1
            })
        })
        .collect();
    (table, index)
}

impl GpuVpl {
    /// Builds the pass for `inputs` (checking every device limit before it
    /// creates anything) and uploads the G-buffer and VPLs. The tile light
    /// list holds up to [`TILE_LIST`] lights; larger subsets stream through
    /// it in chunks.
    pub fn new(gpu: &GpuContext, inputs: &VplInputs) -> Result<Self, GpuError> {
        Self::with_tile_list(gpu, inputs, TILE_LIST)
    }

    /// [`GpuVpl::new`] with a tile light list of `capacity` lights (at
    /// least 1): smaller lists take less workgroup memory and more chunks.
    pub fn with_tile_list(
        gpu: &GpuContext,
        inputs: &VplInputs,
        capacity: u32,
    ) -> Result<Self, GpuError> {
        let gb = &inputs.gbuffer;
        let v = &inputs.vpls;
        let (w, h) = (gb.width, gb.height);
        let n = (w as usize) * (h as usize);
        if [gb.position.len(), gb.normal.len(), gb.depth.len()].iter().any(|&l| l != n) {
            return Err(GpuError::Setting(format!(
                "G-buffer of {w}x{h} holds {} positions, {} normals",
                gb.position.len(),
                gb.normal.len()
            )));
        }
        let texels = v.size as usize * v.size as usize;
        if [v.position.len(), v.normal.len(), v.flux.len()].iter().any(|&l| l != texels) {
            return Err(GpuError::Setting(format!("{} VPLs for an RSM of {0}x{0} texels", v.size)));
        }
        let min_distance = inputs.min_d2.sqrt();
        if !min_distance.is_finite() || !gb.eye.is_finite() {
            return Err(GpuError::Setting(format!(
                "clamp distance² {} and eye {} must be finite",
                inputs.min_d2, gb.eye
            )));
        }
        let glossy = gb.has_specular();
        let desc = IndirectPassDesc {
            surface: SurfaceDesc::Position,
            output_format: wgpu::TextureFormat::Rgba32Float,
            tile_list: capacity,
            glossy,
            ..IndirectPassDesc::new(w, h, VplSourceDesc::Rsm { size: v.size })
        };
        // The pass checks the sizes and every limit before it creates anything.
        let pass = IndirectPass::new(gpu, &desc)?;
        gpu.require(
            "max_texture_dimension_2d (RSM)",
            v.size as u64,
            gpu.limits.max_texture_dimension_2d as u64,
        )?;
        let v4 = |v: Vec3, w: f32| [v.x, v.y, v.z, w];
        let upload = |label: &str, size: (u32, u32), texels: Vec<[f32; 4]>| {
            crate::texture::upload_rgba32(gpu, label, size, &texels)
                .create_view(&Default::default())
        };
        let valid: Vec<bool> = (0..n).map(|i| gb.valid(i)).collect();
        let position = upload(
            "slc vpl gb position",
            (w, h),
            (0..n).map(|i| v4(gb.position[i], valid[i] as u32 as f32)).collect(),
        );
        // A glossy G-buffer: each pixel's material index in the normal's w.
        let (table, index) = if glossy { material_table(gb) } else { (Vec::new(), vec![0; n]) };
        let normal = upload(
            "slc vpl gb normal",
            (w, h),
            gb.normal.iter().zip(&index).map(|(&x, &m)| v4(x, m as f32)).collect(),
        );
        let s = (v.size, v.size);
        let rsm = [
            upload("slc vpl rsm position", s, v.position.iter().map(|&x| v4(x, 1.0)).collect()),
            upload("slc vpl rsm normal", s, v.normal.iter().map(|&x| v4(x, 0.0)).collect()),
            upload("slc vpl rsm flux", s, v.flux.iter().map(|&x| v4(x, 0.0)).collect()),
        ];
        let output = crate::texture::rgba32_target(
            gpu,
            "slc vpl irradiance",
            (w, h),
            wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
        );
        let staging = crate::texture::texture_staging(gpu, &output);
        let glossy = glossy.then(|| {
            let output = crate::texture::rgba32_target(
                gpu,
                "slc vpl specular",
                (w, h),
                wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
            );
            GlossyTargets {
                table: storage(
                    gpu,
                    "slc vpl materials",
                    bytemuck::cast_slice(&table),
                    wgpu::BufferUsages::empty(),
                ),
                view: output.create_view(&Default::default()),
                staging: crate::texture::texture_staging(gpu, &output),
                output,
            }
        });
        let g = GpuVpl {
            gpu: gpu.clone(),
            pass,
            reference: None,
            position,
            normal,
            rsm,
            output_view: output.create_view(&Default::default()),
            output,
            staging,
            glossy,
            eye: gb.eye,
            min_distance,
            valid,
            timer: if gpu.adapter.device_type == wgpu::DeviceType::Cpu {
                None
            } else {
                Timer::new(gpu, 3)
            },
        };
        gpu.wait()?;
        Ok(g)
    }

    /// Indirect irradiance on the GPU for `settings` (the same ξ as the
    /// CPU: `xi_for(seed, frame, VPL index)`), denoised on the GPU when
    /// `settings.denoise` (the same filter as the CPU's). `shading_ms` and
    /// `denoised_ms` are GPU time from timestamps where the adapter has
    /// usable ones, else the wall time of each part submitted alone.
    pub fn shade(&mut self, settings: &VplSettings) -> Result<Shaded, GpuError> {
        let reference = settings.culling == Culling::Reference;
        let st = if reference {
            settings.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
            IndirectSettings {
                culling: Culling::None,
                seed: settings.seed,
                frame: settings.frame,
                fixed_xi: None,
                denoise: false,
                min_distance: self.min_distance,
                near_radius: Some(0.0),
            }
        } else {
            crate::frame::indirect_settings(settings, self.min_distance)?
        };
        if reference && self.reference.is_none() {
            let desc = IndirectPassDesc { interleaved: false, ..*self.pass.desc() };
            self.reference = Some(IndirectPass::new(&self.gpu, &desc)?);
        }
        let gpu = self.gpu.clone();
        let pass = match (reference, self.reference.as_mut()) {
            (true, Some(r)) => r,
            _ => &mut self.pass,
        };
        let inputs = IndirectInputs {
            gbuffer: GBuffer {
                surface: Surface::Position(&self.position),
                normal: &self.normal,
                eye: self.eye,
            },
            vpls: VplInput::Rsm {
                position: &self.rsm[0],
                normal: &self.rsm[1],
                flux: &self.rsm[2],
            },
            output: &self.output_view,
            materials: self
                .glossy
                .as_ref()
                .map(|g| IndirectMaterials { table: &g.table, specular: &g.view }),
        };
        let recording = pass.dispatches(&inputs, &st)?;
        let mut enc = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("slc vpl uniforms"),
        });
        recording.uploads.record(&gpu, &mut enc);
        gpu.queue.submit([enc.finish()]);
        let dispatches = recording.dispatches;
        let mut timer = self.timer.as_mut();
        if let Some(t) = timer.as_mut() {
            t.reset();
        }
        let (mut shading_ms, mut denoise_ms) = (0.0, None);
        let mut timed = Vec::new();
        gpu.wait()?;
        for part in Part::ALL {
            let mut ds = dispatches.iter().filter(|d| Part::of(d.stage) == part).peekable();
            if ds.peek().is_none() {
                continue;
            }
            let mut enc = gpu
                .device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("slc vpl") });
            {
                let timestamp_writes =
                    if part.timed() { timer.as_mut().and_then(|t| t.next()) } else { None };
                let mut cp = enc.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("slc vpl"),
                    timestamp_writes,
                });
                for d in ds {
                    d.record(&mut cp);
                }
            }
            if part == Part::Export
                && let Some(t) = timer.as_ref()
            {
                t.resolve(&mut enc);
            }
            let t0 = Instant::now();
            gpu.queue.submit([enc.finish()]);
            gpu.wait()?;
            let ms = t0.elapsed().as_secs_f64() * 1e3;
            match part {
                Part::Shading | Part::Near => shading_ms += ms,
                Part::Denoise => denoise_ms = Some(ms),
                _ => {}
            }
            if part.timed() {
                timed.push(part);
            }
        }
        if let Some(t) = timer {
            let d = t.durations_ms(&gpu)?;
            shading_ms =
                timed.iter().zip(&d).filter(|(p, _)| **p != Part::Denoise).map(|(_, ms)| ms).sum();
            denoise_ms =
                timed.iter().zip(&d).find(|(p, _)| **p == Part::Denoise).map(|(_, &ms)| ms);
        }
        let data = crate::texture::read_texture_via(&gpu, &self.output, &self.staging)?;
        let mut irradiance = Vec::with_capacity(data.len());
        let mut kept = Vec::with_capacity(data.len());
        let mut evaluations = 0u64;
        for (d, &valid) in data.iter().zip(&self.valid) {
            irradiance.push(if valid { Vec3::new(d[0], d[1], d[2]) } else { Vec3::ZERO });
            kept.push(if valid { d[3] as u32 } else { 0 });
            evaluations += valid as u64 * d[3] as u64;
        }
        let specular = match &self.glossy {
            Some(g) => crate::texture::read_texture_via(&gpu, &g.output, &g.staging)?
                .iter()
                .zip(&self.valid)
                .map(|(d, &valid)| if valid { Vec3::new(d[0], d[1], d[2]) } else { Vec3::ZERO })
                .collect(),
            None => Vec::new(),
        };
        Ok(Shaded {
            irradiance,
            near: Vec::new(),
            specular,
            specular_near: Vec::new(),
            kept,
            evaluations,
            shading_ms,
            denoised_ms: denoise_ms,
        })
    }
}

impl IndirectShader for GpuVpl {
    type Error = GpuError;

    fn describe(&self) -> String {
        self.gpu.describe()
    }

    fn shade(&mut self, settings: &VplSettings) -> Result<Shaded, GpuError> {
        GpuVpl::shade(self, settings)
    }
}
