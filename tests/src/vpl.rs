//! [`GpuVpl`]: application A's shading on the GPU for the G-buffer and VPLs
//! of a [`VplInputs`] (whoever made them: the CPU backend ray casts them),
//! a thin caller of slc-wgpu's [`IndirectPass`] through its public API, as
//! an engine would call it: the G-buffer and the VPLs are uploaded once as
//! a position G-buffer and an RSM, each shade records the pass, submits it
//! and reads its output back. The composition is the caller's.
//!
//! [`Culling::Reference`] records a second pass built without
//! interleaving ([`IndirectPassDesc::interleaved`]`: false`, unculled,
//! neither denoised nor split into near and far fields; built at the first
//! reference shade); a fixed ξ ([`VplSettings::fixed_xi`]) is the pass's
//! own. The CPU's `tile` (its tile size) has no GPU counterpart.
//!
//! A G-buffer with specular lobes ([`slc_scene::vpl::GBuffer::has_specular`])
//! builds the pass glossy ([`IndirectPassDesc::glossy`]): the pixels'
//! materials are uploaded as a material table (one entry per distinct
//! material, its index in the normal texture's `w`), and
//! [`Shaded::specular`] comes back as the CPU's does (the specular
//! correction at the pixels with a specular lobe, zero elsewhere; denoised
//! on the GPU when the irradiance is). Nothing is timed: `shading_ms` is 0,
//! and `denoised_ms` is `Some(0.0)` when the GPU denoised.

use crate::engine;
use slc_scene::vpl::{Shaded, Specular, VplInputs, VplSettings, WorkCounts};
use slc_wgpu::glam::Vec3;
use slc_wgpu::passes::indirect::TILE_LIST;
use slc_wgpu::passes::{
    Culling, GBuffer, GpuMaterial, IndirectInputs, IndirectMaterials, IndirectPass,
    IndirectPassDesc, IndirectSettings, Surface, SurfaceDesc, VplInput, VplSourceDesc,
};
use slc_wgpu::{GpuContext, GpuError};

/// The [`IndirectPass`] over one [`VplInputs`] (one G-buffer and VPL set),
/// with the inputs uploaded once.
pub struct GpuVpl {
    gpu: GpuContext,
    /// Interleaved, the pass every method but the reference records.
    pass: IndirectPass,
    /// Not interleaved (the reference), built at its first use.
    reference: Option<IndirectPass>,
    /// The uploaded inputs and the outputs.
    io: Io,
    min_distance: f32,
    /// Pixels that see a surface.
    valid: Vec<bool>,
}

/// What a record of the pass binds: the uploaded G-buffer and RSM, the
/// outputs.
struct Io {
    position: wgpu::TextureView,
    normal: wgpu::TextureView,
    rsm: [wgpu::TextureView; 3],
    /// The irradiance and its read-back buffer.
    output: Readable,
    /// A glossy G-buffer's material table and specular output.
    glossy: Option<(wgpu::Buffer, Readable)>,
    eye: Vec3,
}

impl Io {
    /// The pass's inputs (with the material table and specular target
    /// where the G-buffer is glossy).
    fn inputs(&self) -> IndirectInputs<'_> {
        IndirectInputs {
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
            output: &self.output.view,
            materials: self
                .glossy
                .as_ref()
                .map(|(table, sp)| IndirectMaterials { table, specular: &sp.view }),
        }
    }
}

/// An `Rgba32Float` output texture, its view and its read-back buffer
/// (kept: shades allocate nothing).
struct Readable {
    texture: wgpu::Texture,
    view: wgpu::TextureView,
    staging: wgpu::Buffer,
}

impl Readable {
    /// An output of `size` and its read-back buffer.
    fn new(gpu: &GpuContext, size: (u32, u32)) -> Readable {
        let texture = engine::output(gpu, size);
        let staging = engine::staging(gpu, &texture);
        Readable { view: texture.create_view(&Default::default()), texture, staging }
    }

    /// The texels, masked to zero where no surface is.
    fn read(&self, gpu: &GpuContext, valid: &[bool]) -> Result<Vec<[f32; 4]>, GpuError> {
        let data = engine::read_via(gpu, &self.texture, &self.staging)?;
        Ok(data.iter().zip(valid).map(|(&d, &v)| if v { d } else { [0.0; 4] }).collect())
    }
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
    /// Builds the pass for `inputs` (the pass checks every device limit
    /// before it creates anything) and uploads the G-buffer and VPLs. The
    /// tile light list holds up to [`TILE_LIST`] lights; larger subsets
    /// stream through it in chunks.
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
            engine::upload(gpu, label, size, &texels)
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
        let glossy = glossy.then(|| (engine::materials(gpu, &table), Readable::new(gpu, (w, h))));
        let g = GpuVpl {
            gpu: gpu.clone(),
            pass,
            reference: None,
            io: Io {
                position,
                normal,
                rsm,
                output: Readable::new(gpu, (w, h)),
                glossy,
                eye: gb.eye,
            },
            min_distance,
            valid,
        };
        gpu.wait()?;
        Ok(g)
    }

    /// The culling work of [`GpuVpl::shade`]`(settings)`, far field then
    /// near field, from the pass's counting kernels
    /// ([`IndirectPass::count_work`]); not for the reference.
    pub fn count_work(
        &mut self,
        settings: &VplSettings,
    ) -> Result<(WorkCounts, WorkCounts), GpuError> {
        let st = slc_wgpu::frame::indirect_settings(settings, self.min_distance)?;
        self.pass.count_work(&self.io.inputs(), &st)
    }

    /// Indirect irradiance on the GPU for `settings` (the same ξ as the
    /// CPU: `xi_for(seed, frame, VPL index)`), denoised on the GPU when
    /// `settings.denoise` (the same filter as the CPU's).
    pub fn shade(&mut self, settings: &VplSettings) -> Result<Shaded, GpuError> {
        let reference = settings.culling == Culling::Reference;
        let st = if reference {
            settings.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
            IndirectSettings {
                seed: settings.seed,
                frame: settings.frame,
                min_distance: self.min_distance,
                ..IndirectSettings::default()
            }
            .reference()
        } else {
            slc_wgpu::frame::indirect_settings(settings, self.min_distance)?
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
        let inputs = self.io.inputs();
        let mut enc = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("slc vpl") });
        pass.record(&mut enc, &inputs, &st)?;
        gpu.queue.submit([enc.finish()]);
        let data = self.io.output.read(&gpu, &self.valid)?;
        let irradiance = data.iter().map(|d| Vec3::new(d[0], d[1], d[2])).collect();
        let kept: Vec<u32> = data.iter().map(|d| d[3] as u32).collect();
        let evaluations = kept.iter().map(|&k| k as u64).sum();
        let specular = match &self.io.glossy {
            Some((_, sp)) => {
                sp.read(&gpu, &self.valid)?.iter().map(|d| Vec3::new(d[0], d[1], d[2])).collect()
            }
            None => Vec::new(),
        };
        Ok(Shaded {
            irradiance,
            near: Vec::new(),
            specular,
            specular_near: Vec::new(),
            kept,
            evaluations,
            far_work: Default::default(),
            near_work: Default::default(),
            shading_ms: 0.0,
            denoised_ms: st.denoise.then_some(0.0),
        })
    }
}
