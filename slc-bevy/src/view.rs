//! Each slc camera's state in the render world: its direct and temporal
//! passes and textures, made or resized and given the frame's lights and
//! view in [`prepare_views`], and recorded into the view's encoder after
//! Bevy's opaque pass in [`shade_view`].

use crate::extract::{ExtractedLights, ExtractedOccluders, slc_lights};
use crate::gpu::{GBUFFER_FORMAT, Gpu, HDR_FORMAT, texture};
use crate::{DirectWalk, SlcCamera, SlcStatus, SlcWork};
use bevy::core_pipeline::prepass::{MotionVectorPrepass, ViewPrepassTextures};
use bevy::prelude::*;
use bevy::render::camera::ExtractedCamera;
use bevy::render::diagnostic::RecordDiagnostics;
use bevy::render::render_resource::{CachedPipelineState, PipelineCache};
use bevy::render::renderer::{RenderContext, ViewQuery};
use bevy::render::sync_world::MainEntity;
use bevy::render::view::{ExtractedView, Msaa, ViewTarget};
use slc_wgpu::passes::{
    DirectInputs, DirectOutputs, DirectPass, DirectPassDesc, DirectReuse, DirectSelection,
    DirectSettings, MaterialInputs, ShadowRays, Shadows, TemporalInputs, TemporalPass,
    TemporalPassDesc,
};
use slc_wgpu::{
    Culling, GBuffer, Light, LightSet, Surface, SurfaceDesc, TemporalSettings, TemporalView,
};
use std::collections::HashMap;

/// One camera's slc state.
struct View {
    pass: DirectPass,
    temporal: TemporalPass,
    /// The accumulation reprojects by Bevy's motion vectors (the camera has
    /// `MotionVectorPrepass`), else by the camera's motion.
    motion: bool,
    /// The unpack's bind group and the G-buffer view it binds.
    unpack_group: Option<(wgpu::TextureView, wgpu::BindGroup)>,
    /// The composite's bind groups: this frame's estimate, the accumulation.
    composite_groups: [wgpu::BindGroup; 2],
    /// The light set changed size this frame (the history is capped).
    changed: bool,
    /// The occluders' generation the pass shadows against and how its
    /// rays are cast, if shadowed.
    shadowed: Option<(u64, ShadowRays)>,
    accumulated: wgpu::TextureView,
    size: (u32, u32),
    lights: usize,
    normal: wgpu::TextureView,
    base: wgpu::TextureView,
    material: wgpu::TextureView,
    output: wgpu::TextureView,
    frame: u32,
    inv_view_proj: glam::Mat4,
    eye: glam::Vec3,
    settings: SlcCamera,
    main: Entity,
}

/// Per render-world camera entity.
#[derive(Resource, Default)]
pub(crate) struct Views(HashMap<Entity, View>);

/// The camera settings a view's direct pass is built for: a change of any
/// rebuilds the view.
fn pass_built_for(s: &SlcCamera) -> (u32, bool, bool, bool, DirectWalk) {
    (s.picks, s.resample, s.reuse, s.visibility_reuse, s.walk)
}

fn new_view(
    gpu: &Gpu,
    cache: &PipelineCache,
    size: (u32, u32),
    lights: &[Light],
    settings: &SlcCamera,
    main: Entity,
    motion: bool,
) -> Result<View, String> {
    let mut desc = DirectPassDesc::new(size.0, size.1);
    desc.surface = SurfaceDesc::Depth { format: wgpu::TextureFormat::Depth32Float };
    desc.selection = if settings.resample {
        DirectSelection::Resampled { k: settings.picks }
    } else {
        DirectSelection::Weighted { k: settings.picks }
    };
    desc.reuse = (settings.resample && settings.reuse)
        .then(|| DirectReuse { visibility: settings.visibility_reuse, ..DirectReuse::default() });
    desc.walk = settings.walk;
    desc.outputs = DirectOutputs::BevyRadiance;
    desc.light_types = slc_shared_lights();
    let set = LightSet::new(lights.to_vec()).map_err(|e| e.to_string())?;
    let pass = DirectPass::new(&gpu.ctx, &set, &desc).map_err(|e| e.to_string())?;
    let mut temporal_desc = TemporalPassDesc::new(size.0, size.1);
    temporal_desc.surface = desc.surface;
    temporal_desc.output_format = GBUFFER_FORMAT;
    temporal_desc.motion_vectors = motion;
    let temporal = TemporalPass::new(&gpu.ctx, &temporal_desc).map_err(|e| e.to_string())?;
    let d = &gpu.ctx.device;
    let inputs = wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::TEXTURE_BINDING;
    let output = texture(d, size, "slc-bevy radiance", inputs);
    let accumulated = texture(d, size, "slc-bevy accumulated radiance", inputs);
    let composite = |shown: &wgpu::TextureView| {
        d.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("slc-bevy composite"),
            layout: &cache.get_bind_group_layout(&gpu.composite_layout),
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(shown),
            }],
        })
    };
    Ok(View {
        unpack_group: None,
        composite_groups: [composite(&output), composite(&accumulated)],
        pass,
        temporal,
        motion,
        changed: false,
        shadowed: None,
        accumulated,
        size,
        lights: lights.len(),
        normal: texture(d, size, "slc-bevy normal", inputs),
        base: texture(d, size, "slc-bevy base colour", inputs),
        material: texture(d, size, "slc-bevy metallic-roughness", inputs),
        output,
        frame: 0,
        inv_view_proj: glam::Mat4::IDENTITY,
        eye: glam::Vec3::ZERO,
        settings: *settings,
        main,
    })
}

/// The light types the pass compiles: Bevy's point and spot lights, and
/// emissive meshes' triangles.
fn slc_shared_lights() -> slc_shared_shaders::LightTypes {
    slc_shared_shaders::LightTypes {
        point: true,
        spot: true,
        ies: false,
        triangle: true,
        vpl: false,
    }
}

fn to_glam(m: Mat4) -> glam::Mat4 {
    glam::Mat4::from_cols_array(&m.to_cols_array())
}

/// What [`prepare_views`] reads of a render-world camera.
type CameraItem = (
    Entity,
    &'static MainEntity,
    &'static SlcCamera,
    &'static ExtractedView,
    &'static ExtractedCamera,
    Option<&'static Msaa>,
    Has<MotionVectorPrepass>,
);

/// Makes or resizes each slc camera's state and gives it this frame's
/// lights and view.
pub(crate) fn prepare_views(
    gpu: Option<Res<Gpu>>,
    cache: Res<PipelineCache>,
    lights: Res<ExtractedLights>,
    occluders: Res<ExtractedOccluders>,
    mut views: ResMut<Views>,
    status: Res<SlcStatus>,
    cameras: Query<CameraItem>,
) {
    let Some(gpu) = gpu else { return };
    let mut report = status.0.lock().unwrap_or_else(|e| e.into_inner());
    let live: Vec<Entity> = cameras.iter().map(|c| c.0).collect();
    views.0.retain(|e, _| live.contains(e));
    for (entity, main, settings, view, camera, msaa, motion) in &cameras {
        let main = main.id();
        let skip =
            |views: &mut Views, why: String, report: &mut HashMap<Entity, Result<u64, String>>| {
                views.0.remove(&entity);
                report.insert(main, Err(why));
            };
        if !settings.enabled {
            views.0.remove(&entity);
            continue;
        }
        if msaa.is_some_and(|m| *m != Msaa::Off) {
            skip(
                &mut views,
                "slc needs Msaa::Off (a multisampled target is re-resolved over what slc adds)"
                    .into(),
                &mut report,
            );
            continue;
        }
        let Some(size) = camera.physical_viewport_size.map(|s| (s.x, s.y)) else { continue };
        if size.0 == 0 || size.1 == 0 {
            continue;
        }
        if settings.culling == Culling::Reference {
            let why = "Culling::Reference is the VPL frame's ground truth, not a real-time setting";
            skip(&mut views, why.into(), &mut report);
            continue;
        }
        let exposure = camera.exposure;
        let lights = slc_lights(&lights.0, exposure);
        if lights.is_empty() {
            views.0.remove(&entity);
            report.insert(main, Ok(0));
            continue;
        }
        let stale = views.0.get(&entity).is_none_or(|v| {
            v.size != size
                || pass_built_for(&v.settings) != pass_built_for(settings)
                || v.motion != motion
        });
        if stale {
            match new_view(&gpu, &cache, size, &lights, settings, main, motion) {
                Ok(v) => {
                    views.0.insert(entity, v);
                }
                Err(e) => {
                    skip(&mut views, e, &mut report);
                    continue;
                }
            }
        }
        let v = views.0.get_mut(&entity).expect("made above");
        let updated = if v.lights == lights.len() {
            v.pass.update_lights(&lights).map_err(|e| e.to_string())
        } else {
            LightSet::new(lights.clone())
                .map_err(|e| e.to_string())
                .and_then(|set| v.pass.set_lights(&set).map_err(|e| e.to_string()))
        };
        if let Err(e) = updated {
            skip(&mut views, e, &mut report);
            continue;
        }
        let rays = if settings.ray_query && gpu.ctx.ray_query {
            ShadowRays::RayQuery
        } else {
            ShadowRays::Software
        };
        let shadowed =
            (settings.shadows && occluders.error.is_none()).then_some((occluders.generation, rays));
        if v.shadowed != shadowed {
            let sh =
                shadowed.map(|(_, rays)| Shadows { rays, ..Shadows::new(&occluders.occluders) });
            if let Err(e) = v.pass.set_shadows(sh) {
                skip(&mut views, e.to_string(), &mut report);
                continue;
            }
            v.shadowed = shadowed;
        }
        v.changed = v.lights != lights.len();
        v.lights = lights.len();
        if !settings.accumulate {
            v.temporal.reset();
        }
        v.settings = *settings;
        let world_from_view = to_glam(view.world_from_view.to_matrix());
        v.inv_view_proj = world_from_view * to_glam(view.clip_from_view).inverse();
        v.eye = world_from_view.w_axis.truncate();
    }
}

/// Unpacks the G-buffer, shades slc's lights and adds them into the view
/// target, in the view's command encoder.
pub(crate) fn shade_view(
    view: ViewQuery<(Entity, &ViewTarget, &ViewPrepassTextures), With<SlcCamera>>,
    gpu: Option<Res<Gpu>>,
    cache: Res<PipelineCache>,
    mut views: ResMut<Views>,
    status: Res<SlcStatus>,
    work: Res<SlcWork>,
    mut ctx: RenderContext,
) {
    let Some(gpu) = gpu else { return };
    let (entity, target, prepass) = view.into_inner();
    let Some(v) = views.0.get_mut(&entity) else { return };
    let main = v.main;
    let report = |r: Result<u64, String>| {
        status.0.lock().unwrap_or_else(|e| e.into_inner()).insert(main, r);
    };
    // The plugin's kernels compile in Bevy's pipeline cache (in the
    // background unless the app asks for synchronous compilation).
    for state in [
        cache.get_compute_pipeline_state(gpu.unpack),
        cache.get_render_pipeline_state(gpu.composite),
    ] {
        if let CachedPipelineState::Err(e) = state {
            report(Err(format!("slc-bevy's shaders: {e}")));
            return;
        }
    }
    let (Some(unpack), Some(composite)) =
        (cache.get_compute_pipeline(gpu.unpack), cache.get_render_pipeline(gpu.composite))
    else {
        return;
    };
    let (Some(depth), Some(gbuffer)) = (prepass.depth_only_view(), prepass.deferred_view()) else {
        report(Err("the camera has no depth prepass or deferred G-buffer (add DepthPrepass and DeferredPrepass)".into()));
        return;
    };
    if target.main_texture_format() != HDR_FORMAT {
        report(Err("slc adds linear radiance before tonemapping: the camera must be Hdr".into()));
        return;
    }
    // Bevy's G-buffer comes from its texture cache: the same view most
    // frames, so the unpack's bind group is made again only when it changes.
    let gbuffer: &wgpu::TextureView = gbuffer;
    if v.unpack_group.as_ref().is_none_or(|(view, _)| view != gbuffer) {
        let group = gpu.ctx.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("slc-bevy unpack"),
            layout: &cache.get_bind_group_layout(&gpu.unpack_layout),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(gbuffer),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&v.normal),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: wgpu::BindingResource::TextureView(&v.base),
                },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: wgpu::BindingResource::TextureView(&v.material),
                },
            ],
        });
        v.unpack_group = Some((gbuffer.clone(), group));
    }
    let Some((_, unpack_group)) = &v.unpack_group else { return };
    let composite_group = &v.composite_groups[usize::from(v.settings.accumulate)];
    // One span over slc's work in the view (Bevy's RenderDiagnosticsPlugin,
    // where the app adds it: "render/slc/elapsed_gpu"; nothing otherwise).
    let diagnostics = ctx.diagnostic_recorder();
    let diagnostics = diagnostics.as_deref();
    let encoder = ctx.command_encoder();
    let span = diagnostics.time_span(encoder, "slc");
    let recorded = (|| -> Result<(), String> {
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("slc-bevy unpack"),
                timestamp_writes: None,
            });
            pass.set_pipeline(unpack);
            pass.set_bind_group(0, unpack_group, &[]);
            pass.dispatch_workgroups(v.size.0.div_ceil(8), v.size.1.div_ceil(8), 1);
        }
        let gbuf = GBuffer {
            surface: Surface::Depth { depth, inv_view_proj: v.inv_view_proj },
            normal: &v.normal,
            eye: v.eye,
        };
        let mut inputs = DirectInputs::new(gbuf, &v.output);
        inputs.material =
            Some(MaterialInputs { base_color: &v.base, metallic_roughness: &v.material });
        let settings =
            DirectSettings { culling: v.settings.culling, seed: v.settings.seed, frame: v.frame };
        v.pass.record(encoder, &inputs, &settings).map_err(|e| e.to_string())?;
        if v.settings.count_work {
            let counts = v.pass.count_work(&inputs, &settings).map_err(|e| e.to_string())?;
            work.0.lock().unwrap_or_else(|e| e.into_inner()).insert(main, counts);
        }
        if v.settings.accumulate {
            let history = TemporalSettings { max_history: v.settings.max_history };
            let history = if v.changed { history.after_change() } else { history };
            let view = TemporalView { view_projection: v.inv_view_proj.inverse(), eye: v.eye };
            let inputs = TemporalInputs {
                motion: if v.motion { prepass.motion_vectors_view().map(|t| &**t) } else { None },
                ..TemporalInputs::new(gbuf, &v.output, &v.accumulated)
            };
            v.temporal.record(encoder, &inputs, &view, &history).map_err(|e| e.to_string())?;
        }
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("slc-bevy composite"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: target.main_texture_view(),
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Load, store: wgpu::StoreOp::Store },
            })],
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(composite);
        pass.set_bind_group(0, composite_group, &[]);
        pass.draw(0..3, 0..1);
        Ok(())
    })();
    span.end(encoder);
    if let Err(e) = recorded {
        report(Err(e));
        return;
    }
    v.frame = v.frame.wrapping_add(1);
    report(Ok(u64::from(v.frame)));
}
