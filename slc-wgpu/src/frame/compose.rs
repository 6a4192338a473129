//! The frame's last two stages: the primary light's direct term shadowed
//! by the shadow map (`primary_direct`, into a buffer) and the composition
//! of direct and indirect light into the HDR target (`frame_compose`).

use super::raster::Raster;
use crate::kernel::{KernelLayout, read_back, zeroed};
use crate::passes::indirect::TILE;
use crate::record::Dispatch;
use crate::texture::{F32, Target, target, tex};
use crate::timing::Stage;
use crate::{GpuContext, GpuError};
use glam::Vec3;
use slc_shared_shaders::{Features, Kernel};

/// `primary_direct` and `frame_compose`: their pipelines and bind groups,
/// the direct light and the HDR output.
pub(crate) struct Compose {
    /// The primary light's direct irradiance per pixel.
    direct: wgpu::Buffer,
    /// `primary_direct` and its bindings (fixed).
    direct_pipeline: wgpu::ComputePipeline,
    direct_group: wgpu::BindGroup,
    /// `frame_compose` and its layout (the temporal stage binds its own
    /// group).
    pipeline: wgpu::ComputePipeline,
    layout: KernelLayout,
    /// The composition reading the indirect pass's own targets.
    group: wgpu::BindGroup,
    /// The HDR target.
    pub(crate) output: Target,
    /// Workgroups of both kernels.
    groups: [u32; 3],
}

/// The composition's fixed bindings: image uniforms, G-buffer, direct
/// light, materials and the HDR target.
struct ComposeInputs<'a> {
    gpu: &'a GpuContext,
    /// `frame_compose`'s layout.
    layout: &'a KernelLayout,
    /// The image uniforms, the G-buffer, the materials and the primary
    /// light's map uniforms (the glossy composition's direction to the
    /// light).
    raster: &'a Raster,
    /// The direct light and the HDR target.
    direct: &'a wgpu::Buffer,
    output: &'a Target,
}

impl ComposeInputs<'_> {
    /// The composition's bind group reading the indirect irradiance from
    /// `indirect` and, glossy, the specular correction from `specular`.
    fn group(&self, indirect: &Target, specular: Option<&Target>) -> wgpu::BindGroup {
        let r = self.raster;
        let mut res = vec![
            ("image", r.image_params.as_entire_binding()),
            ("position_tex", tex(&r.gbuffer.colors[0])),
            ("normal_tex", tex(&r.gbuffer.colors[1])),
            ("indirect_tex", tex(indirect)),
            ("direct", self.direct.as_entire_binding()),
            ("materials", r.material_table.as_entire_binding()),
            ("out_tex", tex(self.output)),
        ];
        if let Some(sp) = specular {
            res.push(("specular_tex", tex(sp)));
            res.push(("params", r.shadow.params.as_entire_binding()));
        }
        self.layout.group(self.gpu, 0, &res)
    }
}

impl Compose {
    /// The direct term for `features` and the composition for
    /// `compose_features` (glossy or not) of `raster`'s image, reading the
    /// indirect irradiance from `irradiance` and, glossy, the specular
    /// correction from `specular`.
    pub(crate) fn new(
        gpu: &GpuContext,
        raster: &Raster,
        (features, compose_features): (&Features, &Features),
        irradiance: &Target,
        specular: Option<&Target>,
    ) -> Result<Compose, GpuError> {
        let size = raster.size();
        let (w, h) = size;
        let sampled_storage = wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let output = target(gpu, "slc frame output", size, F32, sampled_storage);
        // Direct light and composition: fixed resources, bound once.
        let direct = zeroed(
            gpu,
            "slc frame direct",
            w as u64 * h as u64 * 16,
            wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        );
        let direct_layout = KernelLayout::new(gpu, Kernel::PrimaryDirect, features)?;
        let direct_pipeline = direct_layout.pipeline(gpu, features, None)?;
        let direct_group = direct_layout.group(
            gpu,
            0,
            &[
                ("params", raster.shadow.params.as_entire_binding()),
                ("image", raster.image_params.as_entire_binding()),
                ("position_tex", tex(&raster.gbuffer.colors[0])),
                ("normal_tex", tex(&raster.gbuffer.colors[1])),
                ("shadow_map", tex(&raster.shadow.colors[0])),
                ("direct", direct.as_entire_binding()),
            ],
        );
        let layout = KernelLayout::new(gpu, Kernel::FrameCompose, compose_features)?;
        let pipeline = layout.pipeline(gpu, compose_features, None)?;
        let group =
            ComposeInputs { gpu, layout: &layout, raster, direct: &direct, output: &output }
                .group(irradiance, specular);
        Ok(Compose {
            direct,
            direct_pipeline,
            direct_group,
            pipeline,
            layout,
            group,
            output,
            groups: [w.div_ceil(TILE), h.div_ceil(TILE), 1],
        })
    }

    /// A composition bind group reading `indirect` and, glossy, `specular`
    /// instead of the indirect pass's targets (the temporal stage's
    /// outputs).
    pub(crate) fn group(
        &self,
        gpu: &GpuContext,
        raster: &Raster,
        indirect: &Target,
        specular: Option<&Target>,
    ) -> wgpu::BindGroup {
        let inputs = ComposeInputs {
            gpu,
            layout: &self.layout,
            raster,
            direct: &self.direct,
            output: &self.output,
        };
        inputs.group(indirect, specular)
    }

    /// The direct term's dispatch and the composition's, reading the
    /// indirect light through `group` ([`Compose::group`]; `None`: the
    /// indirect pass's targets).
    pub(crate) fn dispatches(&self, group: Option<wgpu::BindGroup>) -> [Dispatch; 2] {
        let group = group.unwrap_or_else(|| self.group.clone());
        [
            Dispatch::new(
                Stage::Direct,
                &self.direct_pipeline,
                self.direct_group.clone(),
                None,
                self.groups,
            ),
            Dispatch::new(Stage::Composition, &self.pipeline, group, None, self.groups),
        ]
    }

    /// The primary light's direct irradiance of the last frame, per pixel.
    pub(crate) fn read_direct(&self, gpu: &GpuContext) -> Result<Vec<Vec3>, GpuError> {
        let staging = zeroed(
            gpu,
            "slc direct readback",
            self.direct.size(),
            wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        );
        let d: Vec<[f32; 4]> = read_back(gpu, &self.direct, &staging)?;
        Ok(d.iter().map(|x| Vec3::new(x[0], x[1], x[2])).collect())
    }
}
