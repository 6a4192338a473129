//! Application A wholly on the GPU: one command encoder per frame records
//! the camera's G-buffer and the primary light's reflective shadow map
//! and shadow map (wgpu render pipelines over the scene's triangles,
//! `scene_raster`), the
//! [`IndirectPass`] on them (VPLs from the RSM, light update with the CPU's
//! ξ, tiled SLC shading per 8×8 interleaved sub-image, cross-bilateral
//! denoise), the primary light's direct term shadowed by the shadow map
//! (`primary_direct`) and the composition `L_e + ρ/π·(E_direct +
//! E_indirect)` into an `Rgba32Float` HDR target (`frame_compose`). A
//! scene with glossy materials (a specular lobe: metals, dielectrics with
//! Fresnel reflectance) builds the pass glossy ([`IndirectPassDesc::glossy`],
//! the frame's material table and the G-buffer's material index): its
//! glossy pixels take `L_e + f(v, l)·E_direct + c_diff/π·E_indirect + S`,
//! the primary light reflected by the whole BRDF toward it and `S` the
//! VPLs' specular correction, as the CPU frame composes them. Pixels
//! come back only when asked for ([`GpuVplFrame::render`]; an engine or a
//! viewer records [`GpuVplFrame::record`] and samples
//! [`GpuVplFrame::output`]).
//!
//! Stage times come from GPU timestamps around each stage's pass where the
//! adapter has them; otherwise (and on software adapters such as lavapipe,
//! whose timestamps do not bracket the work) each stage is submitted alone
//! and timed by the host's clock ([`Timing::Wall`]).
//!
//! ```no_run
//! use slc_scene::scene::Scene;
//! use slc_scene::vpl::VplSettings;
//! use slc_wgpu::GpuContext;
//! use slc_wgpu::frame::{FrameDesc, GpuVplFrame, indirect_settings};
//! use slc_wgpu::passes::IndirectSettings;
//!
//! let gpu = GpuContext::new()?;
//! let mut frame = GpuVplFrame::new(&gpu, &Scene::cornell_box(), &FrameDesc { width: 512, height: 512, rsm_size: 256, shadow_size: 2048, min_distance: None })?;
//! // The indirect pass's own settings, at the frame's clamp distance ...
//! let out = frame.render(&IndirectSettings { min_distance: frame.min_distance(), ..IndirectSettings::default() })?;
//! // ... or converted from the CPU frame's (refused: its reference and fixed ξ).
//! let out = frame.render(&indirect_settings(&VplSettings::default(), frame.min_distance())?)?;
//! for s in &out.stages {
//!     println!("{:>18} {:.3} ms", s.name, s.ms);
//! }
//! out.image.write_png(std::path::Path::new("frame.png"), 1.0)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::kernel::{KernelLayout, check_kernels, read_back, storage, zeroed};
use crate::passes::{
    Culling, GBuffer, IndirectInputs, IndirectMaterials, IndirectPass, IndirectPassDesc,
    IndirectSettings, Surface, SurfaceDesc, TemporalInputs, TemporalPass, TemporalPassDesc,
    VplInput, VplSourceDesc,
};
use crate::record::{Dispatch, Recording, Uploads};
use crate::texture::{DEPTH, F16, F32, R32, Target, read_texture, target, tex};
pub use crate::timing::{Stage, StageTime};
use crate::timing::{TIMED_PASSES, Timer};
use crate::{GpuContext, GpuError};
use glam::{Mat4, Vec3, Vec4};
use slc_scene::backend::Timing;
use slc_scene::image::Image;
use slc_scene::scene::{Camera, LightMap, Material, PrimaryLight, Scene};
use slc_scene::temporal::{TemporalSettings, TemporalView};
use slc_scene::vpl::{PERIOD, Specular, VplInputs, VplSettings, VplStats, Vpls};
use slc_shared_shaders::layout::{
    GpuLight, GpuMaterial, GpuVertex, ImageParams, LIGHT_SPOT, MAP_CAMERA, MAP_ORTHOGRAPHIC,
    MAP_PERSPECTIVE, MapParams,
};
use slc_shared_shaders::{Features, Kernel, LightTypes, OutputFormat, generate};
use std::time::Instant;
use wgpu::util::DeviceExt;

/// Tile edge of the 2-D kernels.
const TILE: u32 = crate::vpl::TILE;

/// What a [`GpuVplFrame`] is built for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameDesc {
    /// Image width (1..=16384).
    pub width: u32,
    /// Image height (1..=16384).
    pub height: u32,
    /// RSM edge: a positive multiple of 8 up to 4096 (`rsm_size²` VPLs).
    pub rsm_size: u32,
    /// Shadow-map edge (the primary light's map again, depth only, for its
    /// direct term): 1 up to the device's texture limit. The RSM's own
    /// resolution is too coarse for a wide spot's shadows.
    pub shadow_size: u32,
    /// Clamp distance of the VPL fall-off (`None`: 1% of the scene's diagonal).
    pub min_distance: Option<f32>,
}

/// The indirect pass's settings for the CPU frame's VPL settings at clamp
/// distance `min_distance` ([`GpuVplFrame::min_distance`] for a frame):
/// the same culling, seed, frame, fixed ξ, denoise and near field; the
/// reference is refused here ([`crate::vpl::GpuVpl`] shades it), and the
/// CPU's `tile` (its tile size) has no GPU counterpart.
pub fn indirect_settings(
    settings: &VplSettings,
    min_distance: f32,
) -> Result<IndirectSettings, GpuError> {
    settings.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
    if settings.culling == Culling::Reference {
        return Err(GpuError::Setting(
            "the GPU frame runs slc, clamp or none (the reference is GpuVpl's)".into(),
        ));
    }
    Ok(IndirectSettings {
        culling: settings.culling,
        seed: settings.seed,
        frame: settings.frame,
        fixed_xi: settings.fixed_xi,
        denoise: settings.denoise,
        min_distance,
        near_radius: settings.near_radius,
    })
}

/// A rendered frame read back.
#[derive(Clone, Debug)]
pub struct FrameRender {
    /// Final linear radiance.
    pub image: Image,
    /// Every stage's time, in order.
    pub stages: Vec<StageTime>,
    /// How the stages were timed.
    pub timing: Timing,
    /// The stage times summed into the CPU frame's categories (G-buffer:
    /// raster; RSM: raster and VPL generation; direct: shadow
    /// map and direct; shading: light update and shading; denoise: denoise,
    /// export and composition), the kept lights per shaded pixel and the
    /// VPL count. The GPU does not count loop evaluations (`evaluations`
    /// and `lights_per_pixel` are 0).
    pub stats: VplStats,
}

fn columns(m: Mat4) -> [Vec4; 4] {
    [m.x_axis, m.y_axis, m.z_axis, m.w_axis]
}

/// Depth range of a raster view from `eye` over the scene's bounding sphere
/// (bounds `(lo, hi)`), the near plane no closer than 1/1000 of the far one
/// (a 32-bit depth buffer then resolves 0.05 mm at 2 m, enough for a light
/// quad under its ceiling).
fn depth_range((lo, hi): (Vec3, Vec3), eye: Vec3) -> std::ops::Range<f32> {
    let (centre, radius) = ((lo + hi) * 0.5, 0.5 * (hi - lo).length());
    let far = (eye - centre).length() + radius;
    (((eye - centre).length() - radius) * 0.9).max(far * 1e-3)..far * 1.01
}

/// The RSM's and the shadow map's raster uniforms for `primary` in a scene
/// with bounds `bounds`: the light's map ([`PrimaryLight::light_map`]) in
/// the Y-down convention (map row 0 toward −up, the CPU's texel order),
/// `rsm_size` and `shadow_size` texels per edge.
fn light_uniforms(
    primary: &PrimaryLight,
    bounds: (Vec3, Vec3),
    rsm_size: u32,
    shadow_size: u32,
) -> (MapParams, MapParams) {
    use glam::camera::rh::{proj, view::look_to_mat4};
    let light = match *primary {
        PrimaryLight::Spot { position, direction, intensity, .. } => {
            let (cos_outer, cos_inner) =
                primary.spot().map(|s| s.cone_cosines()).unwrap_or((0.0, 0.0));
            GpuLight {
                p0: position,
                kind: LIGHT_SPOT,
                p1: direction.normalize(),
                a: cos_outer,
                p2: Vec3::ZERO,
                b: cos_inner,
                intensity,
                ies_base: 0,
            }
        }
        PrimaryLight::Directional { irradiance, .. } => GpuLight {
            p0: Vec3::ZERO,
            kind: LIGHT_SPOT,
            p1: Vec3::ZERO,
            a: 0.0,
            p2: Vec3::ZERO,
            b: 0.0,
            intensity: irradiance,
            ies_base: 0,
        },
    };
    let (vp, origin, axis, right, up, extent, mode) = match primary.light_map(bounds) {
        LightMap::Perspective { origin, axis, right, up, tan } => {
            let r = depth_range(bounds, origin);
            let vp = proj::vulkan::perspective(2.0 * tan.atan(), 1.0, r.start, r.end)
                * look_to_mat4(origin, axis, up);
            (vp, origin, axis, right, up, tan, MAP_PERSPECTIVE)
        }
        LightMap::Orthographic { origin, axis, right, up, half } => {
            let vp = proj::vulkan::orthographic(-half, half, -half, half, 0.0, 4.0 * half)
                * look_to_mat4(origin, axis, up);
            (vp, origin, axis, right, up, half, MAP_ORTHOGRAPHIC)
        }
    };
    let texel = (2.0 * extent / rsm_size as f32).powi(2);
    let [c0, c1, c2, c3] = columns(vp);
    let rsm = MapParams {
        c0,
        c1,
        c2,
        c3,
        light,
        origin,
        mode,
        axis,
        size: rsm_size,
        right,
        extent,
        up,
        texel,
    };
    (rsm, MapParams { size: shadow_size, ..rsm })
}

/// The VPL frame of one scene at one size, wholly on the GPU.
pub struct GpuVplFrame {
    gpu: GpuContext,
    desc: FrameDesc,
    eye: Vec3,
    /// The clamp distance the frame was built with.
    min_distance: f32,
    /// The clamp distance of the last recorded frame ([`Self::read_inputs`]).
    recorded_min_distance: f32,
    materials: Vec<Material>,
    /// The materials as the kernels read them (raster, composition, the
    /// glossy indirect pass).
    material_table: wgpu::Buffer,
    vertices: wgpu::Buffer,
    vertex_count: u32,
    bounds: (Vec3, Vec3),
    light_params: wgpu::Buffer,
    shadow_params: wgpu::Buffer,
    camera_group: wgpu::BindGroup,
    light_group: wgpu::BindGroup,
    shadow_group: wgpu::BindGroup,
    gbuffer_pipeline: wgpu::RenderPipeline,
    rsm_pipeline: wgpu::RenderPipeline,
    shadow_pipeline: wgpu::RenderPipeline,
    gb: [Target; 3],
    rsm: [Target; 4],
    shadow_map: [Target; 2],
    indirect: IndirectPass,
    irradiance: Target,
    /// The VPLs' specular correction (a scene with glossy materials).
    specular: Option<Target>,
    direct: wgpu::Buffer,
    direct_pipeline: wgpu::ComputePipeline,
    direct_group: wgpu::BindGroup,
    compose_pipeline: wgpu::ComputePipeline,
    compose_layout: KernelLayout,
    compose_group: wgpu::BindGroup,
    output: Target,
    /// The camera's raster uniforms and the image's (eye), rewritten by
    /// [`GpuVplFrame::set_camera`].
    camera_params: wgpu::Buffer,
    camera_map: MapParams,
    image_params: wgpu::Buffer,
    camera: Camera,
    /// Temporal accumulation of the indirect light, when on.
    temporal: Option<FrameTemporal>,
    /// The primary light moved since the last recorded frame (a reported
    /// change for the temporal stage).
    lighting_changed: std::cell::Cell<bool>,
    /// The primary light the uniforms hold (the host-side composition's
    /// direction to it).
    primary: std::cell::Cell<PrimaryLight>,
    /// GPU timestamps around the stages, sized for every [`Stage`] (and
    /// the glossy frame's second denoise, [`TIMED_PASSES`]); `None`
    /// where the frame times by the host's clock.
    timer: Option<Timer>,
    /// The stages the last timestamped recording timed, in order.
    timed_stages: Vec<Stage>,
}

impl GpuVplFrame {
    /// Validates the scene and sizes as the CPU's frame does, checks every
    /// device limit, uploads the triangles and materials, and builds the
    /// pipelines and targets.
    pub fn new(gpu: &GpuContext, scene: &Scene, desc: &FrameDesc) -> Result<Self, GpuError> {
        let min_distance = slc_scene::vpl::check_frame(
            scene,
            desc.width,
            desc.height,
            desc.rsm_size,
            desc.min_distance,
        )
        .map_err(|e| GpuError::Setting(e.to_string()))?;
        let size = desc.rsm_size;
        let (w, h) = (desc.width, desc.height);
        let lim = &gpu.limits;
        let shadow = desc.shadow_size;
        if shadow == 0 {
            return Err(GpuError::Setting("shadow map size must be > 0".into()));
        }
        gpu.require(
            "max_texture_dimension_2d",
            w.max(h).max(size).max(shadow) as u64,
            lim.max_texture_dimension_2d as u64,
        )?;
        gpu.require("max_color_attachments", 3, lim.max_color_attachments as u64)?;
        // The RSM's targets: position and flux Rgba32Float, normal Rgba16Float.
        gpu.require(
            "max_color_attachment_bytes_per_sample (RSM)",
            16 + 8 + 16,
            lim.max_color_attachment_bytes_per_sample as u64,
        )?;
        gpu.require(
            "max_storage_buffers_per_shader_stage (fragment)",
            1,
            lim.max_storage_buffers_per_shader_stage as u64,
        )?;
        let vertex_bytes =
            scene.triangles.len() as u64 * 3 * std::mem::size_of::<GpuVertex>() as u64;
        gpu.require("max_buffer_size (vertices)", vertex_bytes, lim.max_buffer_size)?;
        let features = Features {
            lights: LightTypes { vpl: true, ..LightTypes::default() },
            tile_size: TILE,
            interleave: PERIOD,
            ..Features::default()
        };
        // Glossy materials: the indirect pass's and the composition's glossy kernels.
        let glossy = scene.materials.iter().any(Material::has_specular);
        let compose_features =
            Features { output_format: OutputFormat::Rgba32Float, glossy, ..features };
        check_kernels(
            gpu,
            &[
                (Kernel::SceneRaster, &features, 0),
                (Kernel::PrimaryDirect, &features, 0),
                (Kernel::FrameCompose, &compose_features, 0),
            ],
        )?;
        let indirect_desc = IndirectPassDesc {
            surface: SurfaceDesc::Position,
            output_format: F32,
            glossy,
            ..IndirectPassDesc::new(w, h, VplSourceDesc::Rsm { size })
        };
        // The indirect pass checks its own limits before it creates
        // anything; built first, so that no raster pipeline precedes them.
        let indirect = IndirectPass::new(gpu, &indirect_desc)?;

        // Triangles as vertices: position, material, vertex normal, geometric normal.
        let mut verts = Vec::with_capacity(scene.triangles.len() * 3);
        for (i, tri) in scene.triangles.iter().enumerate() {
            let (geo, normals) = (scene.geometric_normal(i), scene.vertex_normals(i));
            for k in 0..3 {
                verts.push(GpuVertex {
                    position: tri[k],
                    material: scene.material_of[i],
                    normal: normals[k],
                    pad0: 0,
                    geo_normal: geo,
                    pad1: 0,
                });
            }
        }
        let vertices = gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("slc frame vertices"),
            contents: bytemuck::cast_slice(&verts),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let mats: Vec<GpuMaterial> = scene.materials.iter().map(crate::pt::gpu_material).collect();
        let materials = storage(
            gpu,
            "slc frame materials",
            bytemuck::cast_slice(&mats),
            wgpu::BufferUsages::empty(),
        );

        // The camera's and the light's raster parameters.
        let (lo, hi) = scene.bounds();
        let cam = &scene.camera;
        // The camera's view-projection: right-handed, depth in [0, 1].
        let r = depth_range((lo, hi), cam.position);
        let camera_vp = cam.view_projection(w, h, r.start, r.end);
        let (light, shadow_light) = light_uniforms(&scene.primary, (lo, hi), size, shadow);
        let uniform = |label: &str, bytes: &[u8]| {
            gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytes,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            })
        };
        let [c0, c1, c2, c3] = columns(camera_vp);
        let camera_map =
            MapParams { c0, c1, c2, c3, origin: cam.position, mode: MAP_CAMERA, size: 0, ..light };
        let camera_params = uniform("slc camera params", bytemuck::bytes_of(&camera_map));
        let light_params = uniform("slc light params", bytemuck::bytes_of(&light));
        let shadow_params = uniform("slc shadow params", bytemuck::bytes_of(&shadow_light));
        let image_params = uniform(
            "slc frame image",
            bytemuck::bytes_of(&ImageParams {
                eye: cam.position,
                width: w,
                height: h,
                pad0: 0,
                pad1: 0,
                pad2: 0,
            }),
        );

        // Raster pipelines.
        let raster_layout = KernelLayout::with_visibility(
            gpu,
            Kernel::SceneRaster,
            &features,
            wgpu::ShaderStages::VERTEX_FRAGMENT,
        )?;
        let raster_group = |params: &wgpu::Buffer| {
            raster_layout.group(
                gpu,
                0,
                &[
                    ("params", params.as_entire_binding()),
                    ("materials", materials.as_entire_binding()),
                ],
            )
        };
        let (camera_group, light_group, shadow_group) = (
            raster_group(&camera_params),
            raster_group(&light_params),
            raster_group(&shadow_params),
        );
        let module = gpu.device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("scene_raster"),
            source: wgpu::ShaderSource::Wgsl(generate(Kernel::SceneRaster, &features)?.into()),
        });
        let pipeline_layout = gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("scene_raster"),
            bind_group_layouts: &[Some(raster_layout.group_layout(0))],
            immediate_size: 0,
        });
        // GpuVertex's offsets (its padding keeps the WGSL layout).
        let attribute = |shader_location, format, offset| wgpu::VertexAttribute {
            format,
            offset,
            shader_location,
        };
        let attributes = [
            attribute(0, wgpu::VertexFormat::Float32x3, 0),
            attribute(1, wgpu::VertexFormat::Uint32, 12),
            attribute(2, wgpu::VertexFormat::Float32x3, 16),
            attribute(3, wgpu::VertexFormat::Float32x3, 32),
        ];
        let buffers = [Some(wgpu::VertexBufferLayout {
            array_stride: std::mem::size_of::<GpuVertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &attributes,
        })];
        let raster = |entry: &str, formats: &[wgpu::TextureFormat]| {
            let targets: Vec<Option<wgpu::ColorTargetState>> =
                formats.iter().map(|&f| Some(f.into())).collect();
            gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(entry),
                layout: Some(&pipeline_layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_main"),
                    compilation_options: Default::default(),
                    buffers: &buffers,
                },
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(entry),
                    compilation_options: Default::default(),
                    targets: &targets,
                }),
                primitive: wgpu::PrimitiveState::default(),
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(wgpu::CompareFunction::Less),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: Default::default(),
                multiview_mask: None,
                cache: None,
            })
        };
        let gbuffer_pipeline = raster("fs_gbuffer", &[F32, F32]);
        // Flux in f32: a texel carries 1/size² of the light's flux, which half
        // floats flush to zero at 256² (28% of the lit texels of the default
        // box, 1% of the indirect light).
        let rsm_pipeline = raster("fs_rsm", &[F32, F16, F32]);
        let shadow_pipeline = raster("fs_shadow", &[R32]);

        // Targets.
        let rt = wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let gb = [
            target(gpu, "slc gb position", (w, h), F32, rt),
            target(gpu, "slc gb normal", (w, h), F32, rt),
            target(gpu, "slc gb depth", (w, h), DEPTH, wgpu::TextureUsages::RENDER_ATTACHMENT),
        ];
        let rsm = [
            target(gpu, "slc rsm position", (size, size), F32, rt),
            target(gpu, "slc rsm normal", (size, size), F16, rt),
            target(gpu, "slc rsm flux", (size, size), F32, rt),
            target(
                gpu,
                "slc rsm depth",
                (size, size),
                DEPTH,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            ),
        ];
        let shadow_map = [
            target(gpu, "slc shadow map", (shadow, shadow), R32, rt),
            target(
                gpu,
                "slc shadow depth",
                (shadow, shadow),
                DEPTH,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            ),
        ];
        let sampled_storage = wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let irradiance = target(gpu, "slc frame irradiance", (w, h), F32, sampled_storage);
        let output = target(gpu, "slc frame output", (w, h), F32, sampled_storage);
        let specular =
            glossy.then(|| target(gpu, "slc frame specular", (w, h), F32, sampled_storage));

        // Direct light and composition: fixed resources, bound once.
        let direct = zeroed(
            gpu,
            "slc frame direct",
            w as u64 * h as u64 * 16,
            wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        );
        let direct_layout = KernelLayout::new(gpu, Kernel::PrimaryDirect, &features)?;
        let direct_pipeline = direct_layout.pipeline(gpu, &features, None)?;
        let direct_group = direct_layout.group(
            gpu,
            0,
            &[
                ("params", shadow_params.as_entire_binding()),
                ("image", image_params.as_entire_binding()),
                ("position_tex", tex(&gb[0])),
                ("normal_tex", tex(&gb[1])),
                ("shadow_map", tex(&shadow_map[0])),
                ("direct", direct.as_entire_binding()),
            ],
        );
        let compose_layout = KernelLayout::new(gpu, Kernel::FrameCompose, &compose_features)?;
        let compose_pipeline = compose_layout.pipeline(gpu, &compose_features, None)?;
        let compose_group = ComposeInputs {
            gpu,
            layout: &compose_layout,
            image: &image_params,
            gb: &gb,
            direct: &direct,
            primary: &shadow_params,
            materials: &materials,
            output: &output,
        }
        .group(&irradiance, specular.as_ref());
        let s = GpuVplFrame {
            gpu: gpu.clone(),
            desc: *desc,
            eye: cam.position,
            min_distance,
            recorded_min_distance: min_distance,
            materials: scene.materials.clone(),
            material_table: materials,
            vertices,
            vertex_count: verts.len() as u32,
            bounds: (lo, hi),
            light_params,
            shadow_params,
            camera_group,
            light_group,
            shadow_group,
            gbuffer_pipeline,
            rsm_pipeline,
            shadow_pipeline,
            gb,
            rsm,
            shadow_map,
            indirect,
            irradiance,
            specular,
            direct,
            direct_pipeline,
            direct_group,
            compose_pipeline,
            compose_layout,
            compose_group,
            output,
            camera_params,
            camera_map,
            image_params,
            camera: *cam,
            temporal: None,
            lighting_changed: std::cell::Cell::new(false),
            primary: std::cell::Cell::new(scene.primary),
            // A software adapter's timestamps do not bracket the work its
            // worker threads do (lavapipe reports microseconds for
            // 10⁸-evaluation dispatches): time it by the clock instead.
            timer: if gpu.adapter.device_type == wgpu::DeviceType::Cpu {
                None
            } else {
                Timer::new(gpu, TIMED_PASSES)
            },
            timed_stages: Vec::new(),
        };
        gpu.take_errors()?;
        Ok(s)
    }

    /// The descriptor the frame was built for.
    pub fn desc(&self) -> &FrameDesc {
        &self.desc
    }

    /// The clamp distance of the VPL fall-off the frame was built with
    /// ([`FrameDesc::min_distance`], or 1% of the scene's diagonal): the
    /// CPU frame's, for [`IndirectSettings::min_distance`].
    pub fn min_distance(&self) -> f32 {
        self.min_distance
    }

    /// The HDR target (`Rgba32Float`, `TEXTURE_BINDING | STORAGE_BINDING |
    /// COPY_SRC`): radiance, alpha 1, after the recorded frame.
    pub fn output(&self) -> &wgpu::Texture {
        &self.output.texture
    }

    /// Moves or changes the primary light (a viewer animating it, an
    /// engine's sun): rewrites the RSM's and the shadow map's uniforms, so
    /// the next recorded frame renders with it. The light is checked as
    /// the scene's is ([`PrimaryLight::validate`]).
    pub fn set_primary(&self, primary: &PrimaryLight) -> Result<(), GpuError> {
        primary.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
        let (light, shadow) =
            light_uniforms(primary, self.bounds, self.desc.rsm_size, self.desc.shadow_size);
        self.gpu.queue.write_buffer(&self.light_params, 0, bytemuck::bytes_of(&light));
        self.gpu.queue.write_buffer(&self.shadow_params, 0, bytemuck::bytes_of(&shadow));
        self.lighting_changed.set(true);
        self.primary.set(*primary);
        Ok(())
    }

    /// Moves the camera (a viewer flying, an engine's view): rewrites the
    /// G-buffer's raster uniforms and the eye, so the next recorded frame
    /// renders from it. The camera is checked as the scene's is
    /// ([`Camera::validate`]).
    pub fn set_camera(&mut self, camera: &Camera) -> Result<(), GpuError> {
        camera.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
        let (w, h) = (self.desc.width, self.desc.height);
        let r = depth_range(self.bounds, camera.position);
        let [c0, c1, c2, c3] = columns(camera.view_projection(w, h, r.start, r.end));
        self.camera_map = MapParams { c0, c1, c2, c3, origin: camera.position, ..self.camera_map };
        let image =
            ImageParams { eye: camera.position, width: w, height: h, pad0: 0, pad1: 0, pad2: 0 };
        self.gpu.queue.write_buffer(&self.camera_params, 0, bytemuck::bytes_of(&self.camera_map));
        self.gpu.queue.write_buffer(&self.image_params, 0, bytemuck::bytes_of(&image));
        (self.camera, self.eye) = (*camera, camera.position);
        Ok(())
    }

    /// The camera the next frame renders from.
    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    /// Turns temporal accumulation of the indirect light on (with
    /// `settings`) or off (`None`): the filtered irradiance (and on glossy
    /// pixels the specular correction) goes through a [`TemporalPass`]
    /// before the composition, reprojected with the camera's motion
    /// ([`GpuVplFrame::set_camera`]); a moved primary light
    /// ([`GpuVplFrame::set_primary`]) is a reported change
    /// ([`TemporalSettings::after_change`]). Turning it on builds the
    /// passes and targets (once); the history starts empty.
    pub fn set_temporal(&mut self, settings: Option<TemporalSettings>) -> Result<(), GpuError> {
        let Some(settings) = settings else {
            self.temporal = None;
            return Ok(());
        };
        settings.validate().map_err(|e| GpuError::Setting(e.to_string()))?;
        if let Some(t) = &mut self.temporal {
            t.settings = settings;
            return Ok(());
        }
        let gpu = &self.gpu;
        let (w, h) = (self.desc.width, self.desc.height);
        let desc = TemporalPassDesc { output_format: F32, ..TemporalPassDesc::new(w, h) };
        let usage = wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let irradiance = (
            TemporalPass::new(gpu, &desc)?,
            target(gpu, "slc frame accumulated irradiance", (w, h), F32, usage),
        );
        let specular = match self.specular {
            Some(_) => Some((
                TemporalPass::new(gpu, &desc)?,
                target(gpu, "slc frame accumulated specular", (w, h), F32, usage),
            )),
            None => None,
        };
        let compose_group =
            self.compose_inputs().group(&irradiance.1, specular.as_ref().map(|s| &s.1));
        self.lighting_changed.set(false);
        self.temporal = Some(FrameTemporal { settings, irradiance, specular, compose_group });
        Ok(())
    }

    /// Forgets the temporal history (a cut); nothing when accumulation is off.
    pub fn reset_temporal(&mut self) {
        if let Some(t) = &mut self.temporal {
            t.irradiance.0.reset();
            if let Some(s) = &mut t.specular {
                s.0.reset();
            }
        }
    }

    /// What the composition binds besides the indirect light.
    fn compose_inputs(&self) -> ComposeInputs<'_> {
        ComposeInputs {
            gpu: &self.gpu,
            layout: &self.compose_layout,
            image: &self.image_params,
            gb: &self.gb,
            direct: &self.direct,
            primary: &self.shadow_params,
            materials: &self.material_table,
            output: &self.output,
        }
    }

    /// Whether stages are timed by GPU timestamps. A software adapter's
    /// timestamps do not bracket its worker threads' work, so the frame
    /// times it by the host's clock unless `on` asks for timestamps anyway
    /// (their values then mean little; the test of the timestamp path runs
    /// on lavapipe this way). Returns whether timestamps are now used:
    /// never without the device's `TIMESTAMP_QUERY`.
    pub fn use_timestamps(&mut self, on: bool) -> bool {
        self.timer = if on { Timer::new(&self.gpu, TIMED_PASSES) } else { None };
        self.timed_stages.clear();
        self.timer.is_some()
    }

    /// [`GpuVplFrame::record`] with a GPU timestamp around every stage
    /// where the adapter has usable ones (not on software adapters, unless
    /// [`GpuVplFrame::use_timestamps`]); read them with
    /// [`GpuVplFrame::stage_times`] once the encoder's commands are
    /// submitted. Returns whether the stages are timed.
    pub fn record_timed(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        settings: &IndirectSettings,
    ) -> Result<bool, GpuError> {
        let (uploads, steps) = self.steps(settings)?;
        uploads.record(&self.gpu, encoder);
        let mut timer = self.timer.take();
        match timer.as_mut() {
            Some(t) => self.record_with_timestamps(encoder, &steps, t),
            None => {
                for step in &steps {
                    self.record_step(encoder, step, None);
                }
            }
        }
        let timed = timer.is_some();
        self.timer = timer;
        Ok(timed)
    }

    /// Records `steps` with a timestamp pair around each, resolves the
    /// queries and remembers the stages for [`GpuVplFrame::stage_times`].
    fn record_with_timestamps(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        steps: &[Step],
        t: &mut Timer,
    ) {
        t.reset();
        for step in steps {
            self.record_step(encoder, step, Some(t));
        }
        t.resolve(encoder);
        self.timed_stages = steps.iter().map(Step::stage).collect();
    }

    /// Every stage's GPU time of the last frame recorded with timestamps
    /// (waits for it to finish), in order, each stage with its own
    /// duration; `None` where the frame does not use timestamps or no frame
    /// was timed yet.
    pub fn stage_times(&self) -> Result<Option<Vec<StageTime>>, GpuError> {
        let Some(t) = self.timer.as_ref().filter(|_| !self.timed_stages.is_empty()) else {
            return Ok(None);
        };
        let ms = t.durations_ms(&self.gpu)?;
        if ms.len() != self.timed_stages.len() {
            return Err(GpuError::Device(format!(
                "{} timestamp pairs for {} stages",
                ms.len(),
                self.timed_stages.len()
            )));
        }
        Ok(Some(
            self.timed_stages
                .iter()
                .zip(ms)
                .map(|(&stage, ms)| StageTime::new(stage, ms))
                .collect(),
        ))
    }

    /// The frame's uniforms (recorded first) and its steps for `st`, each
    /// recordable on its own.
    fn steps(&mut self, st: &IndirectSettings) -> Result<(Uploads, Vec<Step>), GpuError> {
        let inputs = IndirectInputs {
            gbuffer: GBuffer {
                surface: Surface::Position(&self.gb[0].view),
                normal: &self.gb[1].view,
                eye: self.eye,
            },
            vpls: VplInput::Rsm {
                position: &self.rsm[0].view,
                normal: &self.rsm[1].view,
                flux: &self.rsm[2].view,
            },
            output: &self.irradiance.view,
            materials: self
                .specular
                .as_ref()
                .map(|sp| IndirectMaterials { table: &self.material_table, specular: &sp.view }),
        };
        let Recording { mut uploads, dispatches: indirect } =
            self.indirect.dispatches(&inputs, st)?;
        self.recorded_min_distance = st.min_distance;
        let (gx, gy) = (self.desc.width.div_ceil(TILE), self.desc.height.div_ceil(TILE));
        let mut steps = vec![
            Step::Raster(Stage::GBuffer),
            Step::Raster(Stage::Rsm),
            Step::Raster(Stage::ShadowMap),
        ];
        steps.extend(indirect.into_iter().map(Step::Compute));
        let mut compose = self.compose_group.clone();
        if let Some(t) = &mut self.temporal {
            let view = TemporalView::of_camera(&self.camera, self.desc.width, self.desc.height);
            let ts =
                if self.lighting_changed.take() { t.settings.after_change() } else { t.settings };
            let (pass, out) = &mut t.irradiance;
            let signal = TemporalInputs::new(inputs.gbuffer, &self.irradiance.view, &out.view);
            let (up, d) = pass.dispatch(&signal, &view, &ts)?;
            uploads.append(up);
            steps.push(Step::Compute(d));
            if let (Some((pass, out)), Some(sp)) = (&mut t.specular, &self.specular) {
                let signal = TemporalInputs::new(inputs.gbuffer, &sp.view, &out.view);
                let (up, d) = pass.dispatch(&signal, &view, &ts)?;
                uploads.append(up);
                steps.push(Step::Compute(d));
            }
            compose = t.compose_group.clone();
        }
        steps.push(Step::Compute(Dispatch::new(
            Stage::Direct,
            &self.direct_pipeline,
            self.direct_group.clone(),
            None,
            [gx, gy, 1],
        )));
        steps.push(Step::Compute(Dispatch::new(
            Stage::Composition,
            &self.compose_pipeline,
            compose,
            None,
            [gx, gy, 1],
        )));
        Ok((uploads, steps))
    }

    fn record_step(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        step: &Step,
        timer: Option<&mut Timer>,
    ) {
        match step {
            Step::Compute(d) => {
                let timestamp_writes = timer.and_then(|t| t.next());
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some(d.stage.name()),
                    timestamp_writes,
                });
                d.record(&mut pass);
            }
            Step::Raster(stage) => {
                let (colors, depth, pipeline, group) = match stage {
                    Stage::GBuffer => {
                        (&self.gb[..2], &self.gb[2], &self.gbuffer_pipeline, &self.camera_group)
                    }
                    Stage::Rsm => {
                        (&self.rsm[..3], &self.rsm[3], &self.rsm_pipeline, &self.light_group)
                    }
                    _ => (
                        &self.shadow_map[..1],
                        &self.shadow_map[1],
                        &self.shadow_pipeline,
                        &self.shadow_group,
                    ),
                };
                let attachments: Vec<Option<wgpu::RenderPassColorAttachment>> = colors
                    .iter()
                    .map(|t| {
                        Some(wgpu::RenderPassColorAttachment {
                            view: &t.view,
                            depth_slice: None,
                            resolve_target: None,
                            ops: wgpu::Operations {
                                load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                                store: wgpu::StoreOp::Store,
                            },
                        })
                    })
                    .collect();
                let timestamp_writes = timer.and_then(|t| t.next_render());
                let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some(stage.name()),
                    color_attachments: &attachments,
                    depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                        view: &depth.view,
                        depth_ops: Some(wgpu::Operations {
                            load: wgpu::LoadOp::Clear(1.0),
                            store: wgpu::StoreOp::Discard,
                        }),
                        stencil_ops: None,
                    }),
                    timestamp_writes,
                    occlusion_query_set: None,
                    multiview_mask: None,
                });
                pass.set_pipeline(pipeline);
                pass.set_bind_group(0, group, &[]);
                pass.set_vertex_buffer(0, self.vertices.slice(..));
                pass.draw(0..self.vertex_count, 0..1);
            }
        }
    }

    /// Records the whole frame into `encoder` (render and compute passes;
    /// nothing is submitted or read back) with the indirect pass's
    /// `settings` (every one of them honoured).
    pub fn record(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        settings: &IndirectSettings,
    ) -> Result<(), GpuError> {
        let (uploads, steps) = self.steps(settings)?;
        uploads.record(&self.gpu, encoder);
        for step in &steps {
            self.record_step(encoder, step, None);
        }
        Ok(())
    }

    /// Renders one frame in one command encoder, reads the image back and
    /// times every stage (GPU timestamps, else each stage submitted alone
    /// under the host clock).
    pub fn render(&mut self, settings: &IndirectSettings) -> Result<FrameRender, GpuError> {
        let (uploads, steps) = self.steps(settings)?;
        let gpu = self.gpu.clone();
        let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("slc frame uniforms"),
        });
        uploads.record(&gpu, &mut encoder);
        gpu.queue.submit([encoder.finish()]);
        let mut times = Vec::with_capacity(steps.len());
        let mut timer = self.timer.take();
        let timing = match timer.as_mut() {
            Some(t) => {
                let mut encoder =
                    gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                        label: Some("slc frame"),
                    });
                self.record_with_timestamps(&mut encoder, &steps, t);
                gpu.queue.submit([encoder.finish()]);
                gpu.wait()?;
                let ms = t.durations_ms(&gpu)?;
                times.extend(
                    steps.iter().zip(ms).map(|(step, ms)| StageTime::new(step.stage(), ms)),
                );
                Timing::GpuTimestamps
            }
            None => {
                gpu.wait()?;
                for step in &steps {
                    let t0 = Instant::now();
                    let mut encoder =
                        gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                            label: Some(step.stage().name()),
                        });
                    self.record_step(&mut encoder, step, None);
                    gpu.queue.submit([encoder.finish()]);
                    gpu.wait()?;
                    times.push(StageTime::new(step.stage(), t0.elapsed().as_secs_f64() * 1e3));
                }
                Timing::Wall
            }
        };
        self.timer = timer;
        let (w, h) = (self.desc.width, self.desc.height);
        let radiance = read_texture(&gpu, &self.output.texture)?;
        let irradiance = read_texture(&gpu, &self.irradiance.texture)?;
        let positions = read_texture(&gpu, &self.gb[0].texture)?;
        let image = Image {
            width: w,
            height: h,
            data: radiance.iter().map(|p| Vec3::new(p[0], p[1], p[2])).collect(),
        };
        let shaded = positions.iter().filter(|p| p[3] > 0.0).count().max(1) as f64;
        let sum = |stages: &[Stage]| {
            times.iter().filter(|t| stages.contains(&t.stage)).map(|t| t.ms).sum::<f64>()
        };
        let stats = VplStats {
            gbuffer_ms: sum(&[Stage::GBuffer]),
            // The CPU's "direct" includes its shadow rays.
            direct_ms: sum(&[Stage::ShadowMap, Stage::Direct]),
            rsm_ms: sum(&[Stage::Rsm, Stage::VplGeneration]),
            shading_ms: sum(&[Stage::LightUpdate, Stage::Shading, Stage::NearField]),
            denoise_ms: sum(&[
                Stage::Denoise,
                Stage::IrradianceExport,
                Stage::Temporal,
                Stage::Composition,
            ]),
            total_ms: times.iter().map(|t| t.ms).sum(),
            vpls: (self.desc.rsm_size as usize).pow(2),
            lights_per_pixel: 0.0,
            kept_per_pixel: irradiance
                .iter()
                .zip(&positions)
                .filter(|(_, p)| p[3] > 0.0)
                .map(|(e, _)| e[3] as f64)
                .sum::<f64>()
                / shaded,
            evaluations: 0,
        };
        Ok(FrameRender { image, stages: times, timing, stats })
    }

    /// The G-buffer and VPLs the last frame rasterized, read back as the
    /// backend-neutral [`VplInputs`] (to shade them with another backend,
    /// or to compare with the CPU's ray-cast ones), with the last frame's
    /// clamp distance. Depth is the distance from the eye.
    pub fn read_inputs(&self) -> Result<VplInputs, GpuError> {
        let gpu = &self.gpu;
        let (position, normal) =
            (read_texture(gpu, &self.gb[0].texture)?, read_texture(gpu, &self.gb[1].texture)?);
        let n = position.len();
        let mut gb = slc_scene::vpl::GBuffer {
            width: self.desc.width,
            height: self.desc.height,
            position: vec![Vec3::ZERO; n],
            normal: vec![Vec3::ZERO; n],
            albedo: vec![Vec3::ZERO; n],
            emission: vec![Vec3::ZERO; n],
            depth: vec![f32::INFINITY; n],
            eye: self.eye,
            specular: vec![Specular::default(); n],
        };
        for i in 0..n {
            if position[i][3] > 0.0 {
                let p = Vec3::new(position[i][0], position[i][1], position[i][2]);
                let m = self
                    .materials
                    .get(normal[i][3] as usize)
                    .copied()
                    .unwrap_or(Material::lambertian(Vec3::ZERO, Vec3::ZERO));
                gb.position[i] = p;
                gb.normal[i] = Vec3::new(normal[i][0], normal[i][1], normal[i][2]);
                gb.albedo[i] = m.albedo;
                gb.emission[i] = m.emission;
                gb.specular[i] = Specular::of(&m);
                gb.depth[i] = (p - self.eye).length();
            }
        }
        let [p, nn, f] = [0, 1, 2].map(|k| read_texture(gpu, &self.rsm[k].texture));
        let (p, nn, f) = (p?, nn?, f?);
        let v3 = |t: &[[f32; 4]]| t.iter().map(|x| Vec3::new(x[0], x[1], x[2])).collect::<Vec<_>>();
        let vpls =
            Vpls { size: self.desc.rsm_size, position: v3(&p), normal: v3(&nn), flux: v3(&f) };
        Ok(VplInputs {
            gbuffer: gb,
            vpls,
            min_d2: self.recorded_min_distance * self.recorded_min_distance,
        })
    }

    /// The primary light's direct irradiance of the last frame, per pixel.
    pub fn read_direct(&self) -> Result<Vec<Vec3>, GpuError> {
        let staging = zeroed(
            &self.gpu,
            "slc direct readback",
            self.direct.size(),
            wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        );
        let d: Vec<[f32; 4]> = read_back(&self.gpu, &self.direct, &staging)?;
        Ok(d.iter().map(|x| Vec3::new(x[0], x[1], x[2])).collect())
    }

    /// The image this frame would show with indirect irradiance
    /// `indirect` and specular correction `specular` (e.g. the
    /// reference's [`Shaded`](slc_scene::vpl::Shaded), shaded from
    /// [`Self::read_inputs`]) instead of its own: `L_e + ρ/π·(E_direct +
    /// E)` on the host with the last frame's G-buffer and direct light, and
    /// at pixels with a specular lobe `L_e + f(v, l)·E_direct + c_diff/π·E
    /// + S` (as the frame composes them: [`GBuffer::radiance`](slc_scene::vpl::GBuffer::radiance);
    /// `specular` empty: every pixel Lambertian).
    pub fn compose_with(
        &self,
        inputs: &VplInputs,
        indirect: &[Vec3],
        specular: &[Vec3],
    ) -> Result<Image, GpuError> {
        let direct = self.read_direct()?;
        let gb = &inputs.gbuffer;
        if indirect.len() != direct.len()
            || gb.position.len() != direct.len()
            || !(specular.is_empty() || specular.len() == direct.len())
        {
            return Err(GpuError::Setting(format!(
                "{} irradiance and {} specular values for {} pixels",
                indirect.len(),
                specular.len(),
                direct.len()
            )));
        }
        let primary = self.primary.get();
        let data = (0..direct.len())
            .map(|i| gb.radiance(i, &primary, direct[i], indirect[i], specular.get(i).copied()))
            .collect();
        Ok(Image { width: gb.width, height: gb.height, data })
    }
}

/// The composition's fixed bindings: image uniforms, G-buffer, direct
/// light, materials and the HDR target.
struct ComposeInputs<'a> {
    gpu: &'a GpuContext,
    layout: &'a KernelLayout,
    image: &'a wgpu::Buffer,
    gb: &'a [Target; 3],
    direct: &'a wgpu::Buffer,
    /// The primary light's map uniforms (the glossy composition's
    /// direction to the light).
    primary: &'a wgpu::Buffer,
    materials: &'a wgpu::Buffer,
    output: &'a Target,
}

impl ComposeInputs<'_> {
    /// The composition's bind group reading the indirect irradiance from
    /// `indirect` and, glossy, the specular correction from `specular`.
    fn group(&self, indirect: &Target, specular: Option<&Target>) -> wgpu::BindGroup {
        let mut res = vec![
            ("image", self.image.as_entire_binding()),
            ("position_tex", tex(&self.gb[0])),
            ("normal_tex", tex(&self.gb[1])),
            ("indirect_tex", tex(indirect)),
            ("direct", self.direct.as_entire_binding()),
            ("materials", self.materials.as_entire_binding()),
            ("out_tex", tex(self.output)),
        ];
        if let Some(sp) = specular {
            res.push(("specular_tex", tex(sp)));
            res.push(("params", self.primary.as_entire_binding()));
        }
        self.layout.group(self.gpu, 0, &res)
    }
}

/// The frame's temporal stage: its settings, a pass and an output per
/// accumulated signal (irradiance; the glossy frame's specular
/// correction), and the composition's bind group reading the outputs.
struct FrameTemporal {
    settings: TemporalSettings,
    irradiance: (TemporalPass, Target),
    specular: Option<(TemporalPass, Target)>,
    compose_group: wgpu::BindGroup,
}

/// A step of the frame: a raster pass (G-buffer, RSM or shadow map) or a
/// compute dispatch.
enum Step {
    Raster(Stage),
    Compute(Dispatch),
}

impl Step {
    fn stage(&self) -> Stage {
        match self {
            Step::Raster(s) => *s,
            Step::Compute(d) => d.stage,
        }
    }
}
