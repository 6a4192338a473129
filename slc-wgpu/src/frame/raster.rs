//! The frame's raster stages: the scene's triangles and materials uploaded
//! once, the camera's G-buffer, the primary light's reflective shadow map
//! and its shadow map, each a render pipeline of `scene_raster` with its
//! uniforms and targets, and the rewrites of those uniforms when the
//! camera or the light moves.

use crate::kernel::{KernelLayout, storage};
use crate::texture::{DEPTH, F16, F32, R32, Target, read_texture, target};
use crate::timing::Stage;
use crate::{GpuContext, GpuError};
use glam::{Mat4, Vec3, Vec4};
use slc_scene::scene::{Camera, LightMap, Material, PrimaryLight, Scene};
use slc_scene::vpl::{Specular, VplInputs, Vpls};
use slc_shared_shaders::layout::{
    GpuLight, GpuMaterial, GpuVertex, ImageParams, LIGHT_SPOT, MAP_CAMERA, MAP_ORTHOGRAPHIC,
    MAP_PERSPECTIVE, MapParams,
};
use slc_shared_shaders::{Features, Kernel, generate};
use wgpu::util::DeviceExt;

/// One raster view (the G-buffer, the RSM or the shadow map): its uniforms,
/// their bind group, its pipeline and its color and depth targets.
pub(crate) struct RasterView {
    /// The view's [`MapParams`].
    pub(crate) params: wgpu::Buffer,
    /// The uniforms and the materials, bound.
    group: wgpu::BindGroup,
    /// `scene_raster` with the view's fragment entry point.
    pipeline: wgpu::RenderPipeline,
    /// The color targets, in the fragment entry point's order.
    pub(crate) colors: Vec<Target>,
    /// The depth attachment (not stored).
    depth: Target,
}

/// The scene's triangles and materials on the device and the frame's three
/// raster views, with the camera and light they are rendered from.
pub(crate) struct Raster {
    /// The scene's materials (the read-back G-buffer's).
    materials: Vec<Material>,
    /// The materials as the kernels read them (raster, composition, the
    /// glossy indirect pass).
    pub(crate) material_table: wgpu::Buffer,
    /// The triangles, three vertices each ([`GpuVertex`]).
    vertices: wgpu::Buffer,
    vertex_count: u32,
    /// The scene's bounds (the views' depth ranges and the light's map).
    bounds: (Vec3, Vec3),
    /// Image width and height.
    size: (u32, u32),
    /// The RSM's and the shadow map's edges.
    rsm_size: u32,
    shadow_size: u32,
    /// The camera the next frame renders from, and its raster uniforms.
    camera: Camera,
    camera_map: MapParams,
    /// The image's uniforms (the eye), rewritten with the camera.
    pub(crate) image_params: wgpu::Buffer,
    /// The camera's G-buffer: position (`w > 0` where a surface is) and
    /// normal (`w`: the material index).
    pub(crate) gbuffer: RasterView,
    /// The primary light's reflective shadow map: position, normal, flux.
    pub(crate) rsm: RasterView,
    /// The primary light's shadow map (its uniforms: the light's, which
    /// the direct term and the glossy composition read too).
    pub(crate) shadow: RasterView,
}

impl Raster {
    /// Checks the device limits the raster stages need for `scene` at
    /// image `size`, `rsm_size` and `shadow_size` (before anything is
    /// created).
    pub(crate) fn check(
        gpu: &GpuContext,
        scene: &Scene,
        (w, h): (u32, u32),
        rsm_size: u32,
        shadow_size: u32,
    ) -> Result<(), GpuError> {
        let lim = &gpu.limits;
        if shadow_size == 0 {
            return Err(GpuError::Setting("shadow map size must be > 0".into()));
        }
        gpu.require(
            "max_texture_dimension_2d",
            w.max(h).max(rsm_size).max(shadow_size) as u64,
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
        gpu.require("max_buffer_size (vertices)", vertex_bytes, lim.max_buffer_size)
    }

    /// Uploads the scene's triangles and materials and builds the three
    /// views' uniforms, pipelines (`scene_raster` for `features`) and
    /// targets ([`Raster::check`] first).
    pub(crate) fn new(
        gpu: &GpuContext,
        scene: &Scene,
        (w, h): (u32, u32),
        rsm_size: u32,
        shadow_size: u32,
        features: &Features,
    ) -> Result<Raster, GpuError> {
        let (size, shadow) = (rsm_size, shadow_size);
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
            features,
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
        let module = gpu.device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("scene_raster"),
            source: wgpu::ShaderSource::Wgsl(generate(Kernel::SceneRaster, features)?.into()),
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
        // Targets: color targets are sampled by the compute stages and read back.
        let rt = wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let depth = |label: &str, edge: (u32, u32)| {
            target(gpu, label, edge, DEPTH, wgpu::TextureUsages::RENDER_ATTACHMENT)
        };
        let gbuffer = RasterView {
            group: raster_group(&camera_params),
            pipeline: raster("fs_gbuffer", &[F32, F32]),
            colors: vec![
                target(gpu, "slc gb position", (w, h), F32, rt),
                target(gpu, "slc gb normal", (w, h), F32, rt),
            ],
            depth: depth("slc gb depth", (w, h)),
            params: camera_params,
        };
        // Flux in f32: a texel carries 1/size² of the light's flux, which half
        // floats flush to zero at 256² (28% of the lit texels of the default
        // box, 1% of the indirect light).
        let rsm = RasterView {
            group: raster_group(&light_params),
            pipeline: raster("fs_rsm", &[F32, F16, F32]),
            colors: vec![
                target(gpu, "slc rsm position", (size, size), F32, rt),
                target(gpu, "slc rsm normal", (size, size), F16, rt),
                target(gpu, "slc rsm flux", (size, size), F32, rt),
            ],
            depth: depth("slc rsm depth", (size, size)),
            params: light_params,
        };
        let shadow = RasterView {
            group: raster_group(&shadow_params),
            pipeline: raster("fs_shadow", &[R32]),
            colors: vec![target(gpu, "slc shadow map", (shadow, shadow), R32, rt)],
            depth: depth("slc shadow depth", (shadow, shadow)),
            params: shadow_params,
        };
        Ok(Raster {
            materials: scene.materials.clone(),
            material_table: materials,
            vertices,
            vertex_count: verts.len() as u32,
            bounds: (lo, hi),
            size: (w, h),
            rsm_size,
            shadow_size,
            camera: *cam,
            camera_map,
            image_params,
            gbuffer,
            rsm,
            shadow,
        })
    }

    /// Image width and height.
    pub(crate) fn size(&self) -> (u32, u32) {
        self.size
    }

    /// The camera the next frame renders from.
    pub(crate) fn camera(&self) -> &Camera {
        &self.camera
    }

    /// Rewrites the RSM's and the shadow map's uniforms for `primary`
    /// (checked by the caller).
    pub(crate) fn set_primary(&self, gpu: &GpuContext, primary: &PrimaryLight) {
        let (light, shadow) = light_uniforms(primary, self.bounds, self.rsm_size, self.shadow_size);
        gpu.queue.write_buffer(&self.rsm.params, 0, bytemuck::bytes_of(&light));
        gpu.queue.write_buffer(&self.shadow.params, 0, bytemuck::bytes_of(&shadow));
    }

    /// Rewrites the G-buffer's raster uniforms and the image's eye for
    /// `camera` (checked by the caller).
    pub(crate) fn set_camera(&mut self, gpu: &GpuContext, camera: &Camera) {
        let (w, h) = self.size;
        let r = depth_range(self.bounds, camera.position);
        let [c0, c1, c2, c3] = columns(camera.view_projection(w, h, r.start, r.end));
        self.camera_map = MapParams { c0, c1, c2, c3, origin: camera.position, ..self.camera_map };
        let image =
            ImageParams { eye: camera.position, width: w, height: h, pad0: 0, pad1: 0, pad2: 0 };
        gpu.queue.write_buffer(&self.gbuffer.params, 0, bytemuck::bytes_of(&self.camera_map));
        gpu.queue.write_buffer(&self.image_params, 0, bytemuck::bytes_of(&image));
        self.camera = *camera;
    }

    /// Records the render pass of `stage` ([`Stage::GBuffer`],
    /// [`Stage::Rsm`], else the shadow map) into `encoder`, with
    /// `timestamp_writes` around it.
    pub(crate) fn record(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        stage: Stage,
        timestamp_writes: Option<wgpu::RenderPassTimestampWrites>,
    ) {
        let view = match stage {
            Stage::GBuffer => &self.gbuffer,
            Stage::Rsm => &self.rsm,
            _ => &self.shadow,
        };
        let attachments: Vec<Option<wgpu::RenderPassColorAttachment>> = view
            .colors
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
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some(stage.name()),
            color_attachments: &attachments,
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &view.depth.view,
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
        pass.set_pipeline(&view.pipeline);
        pass.set_bind_group(0, &view.group, &[]);
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.draw(0..self.vertex_count, 0..1);
    }

    /// The G-buffer and VPLs last rasterized, read back as the
    /// backend-neutral [`VplInputs`] with clamp distance `min_distance`.
    /// Depth is the distance from the eye.
    pub(crate) fn read_inputs(
        &self,
        gpu: &GpuContext,
        min_distance: f32,
    ) -> Result<VplInputs, GpuError> {
        let gb = &self.gbuffer.colors;
        let (position, normal) =
            (read_texture(gpu, &gb[0].texture)?, read_texture(gpu, &gb[1].texture)?);
        let n = position.len();
        let eye = self.camera.position;
        let mut gb = slc_scene::vpl::GBuffer {
            width: self.size.0,
            height: self.size.1,
            position: vec![Vec3::ZERO; n],
            normal: vec![Vec3::ZERO; n],
            albedo: vec![Vec3::ZERO; n],
            emission: vec![Vec3::ZERO; n],
            depth: vec![f32::INFINITY; n],
            eye,
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
                gb.depth[i] = (p - eye).length();
            }
        }
        let [p, nn, f] = [0, 1, 2].map(|k| read_texture(gpu, &self.rsm.colors[k].texture));
        let (p, nn, f) = (p?, nn?, f?);
        let v3 = |t: &[[f32; 4]]| t.iter().map(|x| Vec3::new(x[0], x[1], x[2])).collect::<Vec<_>>();
        let vpls = Vpls { size: self.rsm_size, position: v3(&p), normal: v3(&nn), flux: v3(&f) };
        Ok(VplInputs { gbuffer: gb, vpls, min_d2: min_distance * min_distance })
    }
}

/// The columns of `m`, as the uniforms hold a matrix.
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
