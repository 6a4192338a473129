//! [`GpuDirect`]: direct light from many lights at arbitrary shading points
//! on the GPU, a thin caller of slc-wgpu's [`DirectPass`] through its
//! public API: the points and normals are uploaded as a position G-buffer
//! (point `i` at texel `i`, row-major, so its random streams are the
//! pass's pixel `i`, the eye at the origin), the pass is recorded with the
//! selection asked for (uniform picks of `k =` [`DIRECT_K`] by default, the
//! CPU's reservoir) and, given occluders, shadowed, and the output is read
//! back: the counterpart of the CPU backend's `slc_cpu::direct::DirectLights`,
//! which draws the same random numbers.

use crate::engine;
use slc_core::range::RangeParams;
use slc_scene::lights::{DIRECT_K, Direct, DirectSelection, LightSet};
use slc_scene::occluders::Occluders;
use slc_wgpu::glam::Vec3;
use slc_wgpu::passes::{
    Culling, DirectInputs, DirectPass, DirectPassDesc, DirectSettings, DirectWalk, GBuffer,
    Shadows, Surface, SurfaceDesc,
};
use slc_wgpu::{GpuContext, GpuError, LightTypes};

/// Texels per row of the point textures.
const ROW: u32 = 256;

/// The lights of a [`LightSet`] and a [`DirectPass`] sized for the last
/// call's points.
pub struct GpuDirect {
    gpu: GpuContext,
    lights: LightSet,
    pass: Option<DirectPass>,
    /// The occluders and normal offset of [`GpuDirect::set_shadows`].
    shadows: Option<(Occluders, f32)>,
    /// How the pass finds each point's lights (tile walk by default).
    pub walk: DirectWalk,
    /// The light types the pass compiles: `None` (the default) for the
    /// lights' own; more let [`GpuDirect::set_lights`] keep the pass for
    /// lights of other types.
    pub light_types: Option<LightTypes>,
}

impl GpuDirect {
    /// Keeps the lights; the pass is built at the first [`GpuDirect::shade`]
    /// (and again when the number of rows of points changes), checking the
    /// device's limits for them then.
    pub fn new(gpu: &GpuContext, lights: &LightSet) -> Result<Self, GpuError> {
        Ok(GpuDirect {
            gpu: gpu.clone(),
            lights: lights.clone(),
            pass: None,
            shadows: None,
            walk: DirectWalk::default(),
            light_types: None,
        })
    }

    /// Replaces the lights. A built pass keeps its pipelines and takes
    /// them ([`DirectPass::set_lights`]) where it compiles their types;
    /// otherwise the next shade builds a new one.
    pub fn set_lights(&mut self, lights: &LightSet) -> Result<(), GpuError> {
        match self.pass.as_mut() {
            Some(pass) if LightTypes::of(lights.lights()).within(pass.desc().light_types) => {
                pass.set_lights(lights)?
            }
            _ => self.pass = None,
        }
        self.lights = lights.clone();
        Ok(())
    }

    /// Shadows every pick against `occluders` (a ray's origin offset along
    /// the normal by `normal_offset` × its distance to the origin, the
    /// G-buffer's eye), or turns shadows off (`None`).
    pub fn set_shadows(&mut self, shadows: Option<(&Occluders, f32)>) -> Result<(), GpuError> {
        self.shadows = shadows.map(|(o, f)| (o.clone(), f));
        if let Some(pass) = self.pass.as_mut() {
            let sh = self
                .shadows
                .as_ref()
                .map(|(o, f)| Shadows { normal_offset: *f, ..Shadows::new(o) });
            pass.set_shadows(sh)?;
        }
        Ok(())
    }

    /// Direct light at `points` (unit `normals`) for frame `frame` of
    /// `seed`, number for number as the CPU's `DirectLights::shade`.
    pub fn shade(
        &mut self,
        points: &[Vec3],
        normals: &[Vec3],
        params: &RangeParams,
        seed: u32,
        frame: u32,
    ) -> Result<Vec<Direct>, GpuError> {
        let uniform = DirectSelection::Uniform { k: DIRECT_K as u32 };
        self.shade_selected(points, normals, params, seed, frame, uniform)
    }

    /// [`GpuDirect::shade`] with the picks `selection` makes, number for
    /// number as the CPU's `DirectLights::shade_selected`.
    pub fn shade_selected(
        &mut self,
        points: &[Vec3],
        normals: &[Vec3],
        params: &RangeParams,
        seed: u32,
        frame: u32,
        selection: DirectSelection,
    ) -> Result<Vec<Direct>, GpuError> {
        if points.len() != normals.len() {
            return Err(GpuError::Setting(format!(
                "{} points but {} normals",
                points.len(),
                normals.len()
            )));
        }
        if points.is_empty() {
            return Ok(Vec::new());
        }
        let gpu = self.gpu.clone();
        let n = points.len();
        let (w, h) = (ROW.min(n as u32), (n as u32).div_ceil(ROW));
        gpu.require(
            "max_texture_dimension_2d (point rows)",
            h as u64,
            gpu.limits.max_texture_dimension_2d as u64,
        )?;
        if self.pass.as_ref().is_none_or(|p| {
            (p.desc().width, p.desc().height, p.desc().selection, p.desc().walk)
                != (w, h, selection, self.walk)
        }) {
            let desc = DirectPassDesc {
                surface: SurfaceDesc::Position,
                output_format: wgpu::TextureFormat::Rgba32Float,
                selection,
                light_types: self
                    .light_types
                    .unwrap_or_else(|| LightTypes::of(self.lights.lights())),
                walk: self.walk,
                ..DirectPassDesc::new(w, h)
            };
            let mut pass = DirectPass::new(&gpu, &self.lights, &desc)?;
            let sh = self
                .shadows
                .as_ref()
                .map(|(o, f)| Shadows { normal_offset: *f, ..Shadows::new(o) });
            pass.set_shadows(sh)?;
            self.pass = Some(pass);
        }
        let Some(pass) = self.pass.as_mut() else {
            return Err(GpuError::Setting("no pass".into()));
        };
        // w = 1 marks a valid point; NaN coordinates are shaded as nothing, as on the CPU.
        let texels = (w * h) as usize;
        let mut p4 = vec![[0.0f32; 4]; texels];
        let mut n4 = vec![[0.0f32; 4]; texels];
        for i in 0..n {
            let p = points[i];
            p4[i] = [p.x, p.y, p.z, if p.is_nan() { 0.0 } else { 1.0 }];
            n4[i] = normals[i].extend(0.0).to_array();
        }
        let (pv, nv) = (
            engine::upload(&gpu, "slc points", (w, h), &p4),
            engine::upload(&gpu, "slc normals", (w, h), &n4),
        );
        let output = engine::output(&gpu, (w, h));
        let ov = output.create_view(&Default::default());
        let inputs = DirectInputs::new(
            GBuffer { surface: Surface::Position(&pv), normal: &nv, eye: Vec3::ZERO },
            &ov,
        );
        let mut enc = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("slc direct") });
        pass.record(
            &mut enc,
            &inputs,
            &DirectSettings { culling: Culling::Stochastic(*params), seed, frame },
        )?;
        gpu.queue.submit([enc.finish()]);
        let data = engine::read(&gpu, &output)?;
        Ok(data[..n]
            .iter()
            .map(|d| Direct { irradiance: Vec3::new(d[0], d[1], d[2]), in_range: d[3] as u32 })
            .collect())
    }
}

/// A unit cube centred at the origin, 12 triangles (occluders for the
/// shadow tests).
pub fn unit_cube() -> Vec<[Vec3; 3]> {
    let mut v = Vec::new();
    for axis in [Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y, -Vec3::Z] {
        let q = slc_wgpu::glam::Quat::from_rotation_arc(Vec3::Z, axis);
        let c = |x: f32, y: f32| q * Vec3::new(x, y, 0.5);
        v.push([c(-0.5, -0.5), c(0.5, -0.5), c(0.5, 0.5)]);
        v.push([c(-0.5, -0.5), c(0.5, 0.5), c(-0.5, 0.5)]);
    }
    v
}
