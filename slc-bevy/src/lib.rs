//! Bevy 0.20 plugin: Bevy's point lights shaded by stochastic light culling
//! (Tokuyoshi & Harada, JCGT 2016), with no range cut-off, and shadowed by
//! the scene's meshes.
//!
//! Bevy's clustered renderer gives every [`PointLight`] a hard `range`
//! (20 m by default): beyond it the light adds nothing, so a scene lit by
//! many lights darkens. slc gives each light a *random* range every frame,
//! scaled so that the expectation over frames is the unbounded
//! inverse-square light, and shades only the lights whose range reaches a
//! pixel (slc-wgpu's [`DirectPass`] on Bevy's own device and G-buffer).
//!
//! ```no_run
//! use bevy::prelude::*;
//! use slc_bevy::{SlcCamera, SlcLight, SlcPlugin};
//!
//! fn setup(mut commands: Commands) {
//!     // The camera: HDR, deferred G-buffer and depth prepass, no MSAA (required by SlcCamera).
//!     commands.spawn((Camera3d::default(), SlcCamera::default(), Transform::from_xyz(0.0, 8.0, 20.0)));
//!     // A light slc takes over: Bevy's clustered pass no longer sees it.
//!     commands.spawn((PointLight { intensity: 2e5, ..default() }, SlcLight, Transform::from_xyz(0.0, 3.0, 0.0)));
//! }
//!
//! App::new()
//!     .add_plugins((DefaultPlugins, SlcPlugin))
//!     // slc shades Bevy's deferred G-buffer: opaque materials render deferred.
//!     .insert_resource(bevy::pbr::DefaultOpaqueRendererMethod::deferred())
//!     .add_systems(Startup, setup)
//!     .run();
//! ```
//!
//! **What slc takes over**: every entity with [`PointLight`] or [`SpotLight`]
//! and [`SlcLight`]
//! (the marker puts the light on no render layer, `RenderLayers::none()`,
//! so Bevy's own lighting, clustering and shadow maps skip it; its `range`
//! is ignored). Lights move, spawn and despawn freely: they are read every
//! frame, the light hierarchy refitted when their number is unchanged and
//! rebuilt when it changes (`O(n)` CPU per frame).
//!
//! **How it shades**: at every pixel of a camera with [`SlcCamera`], after
//! Bevy's opaque (deferred lighting) pass and before transparents and
//! tonemapping: (1) Bevy's deferred G-buffer is unpacked into normal, base
//! colour and metallic-roughness-reflectance textures (`unpack.wesl`, which
//! imports Bevy's own unpacking functions from `bevy_pbr::deferred::types`
//! and `bevy_render::utils`); (2) slc's direct pass
//! picks [`SlcCamera::picks`] lights among those whose random range reaches
//! the pixel, in proportion to their unshadowed light
//! ([`SlcCamera::resample`]), each pick reused by the next frame at the
//! pixel the point reprojects to ([`SlcCamera::reuse`], unbiased), and
//! shades them with Bevy
//! `StandardMaterial`'s BRDF (`slc_core::brdf::bevy_brdf`: Burley diffuse,
//! GGX with Bevy's Fresnel and multiple-scattering compensation) times
//! Bevy's light units (`intensity` in lumens, `/4π` to candela, times the
//! camera's exposure), each pick shadowed by one ray against the scene's
//! meshes ([`SlcCamera::shadows`], below); (3) by default the result is accumulated over frames
//! ([`SlcCamera::accumulate`]: slc-wgpu's temporal pass, reprojected by the
//! camera's motion, history dropped where the surface or the light
//! changed); (4) it is added into the view target.
//!
//! **Shadows** (on by default, [`SlcCamera::shadows`]): every entity with a
//! [`Mesh3d`] that is visible in the hierarchy (`InheritedVisibility`) and
//! has no `NotShadowCaster` occludes slc's lights, through slc-wgpu's
//! [`Occluders`] (one BVH per mesh asset, built when the asset is first
//! seen, again when it is edited; a top level over the entities, refitted
//! every frame for the entities that moved and laid out anew when entities
//! appear or go) and
//! one shadow ray per pick in slc's direct kernel: plain WGSL, so every
//! adapter shadows, no ray-tracing hardware needed. Costs: a mesh's BVH
//! once (`O(n log n)` in its triangles), a moved entity's triangles every
//! frame it moves (`O(n)` on the CPU, during extraction), the buffers
//! re-uploaded when anything moved (48 B per triangle), `picks` rays per
//! pixel. An edited mesh asset, or most of the built meshes falling out of
//! use, starts the occluders over (every used mesh's BVH built again).
//! Not followed: a
//! mesh that is not a triangle list or strip, has no index or position
//! data, or was extracted to the render world only (its
//! `RenderAssetUsages` without `MAIN_WORLD`) casts no slc shadow, with one
//! warning in the log.
//!
//! **Emissive meshes** light the scene: every visible entity with a
//! [`Mesh3d`] and a `StandardMaterial` whose `emissive` is not black
//! becomes triangle lights, one per triangle, in world space, emitting
//! from Bevy's front face (both faces for a `double_sided` material) with
//! radiance `emissive` in cd/m² (Bevy's units) times the camera's
//! exposure, placed every frame (moved, spawned or recoloured emitters
//! follow; `O(triangles)` per frame; each mesh asset's triangles are read
//! once and again only when the asset changes); [`NotSlcLight`] keeps an emissive
//! mesh from becoming lights (it is only shown). An `emissive_texture`
//! scales each triangle by the texture's mean over its UVs (the material's
//! UV channel and `uv_transform`, the image's address modes; a pattern
//! finer than the triangles is averaged over each; `emissive.rs`); a
//! texture that cannot be read (a compressed format) is left out with one
//! warning. `emissive_exposure_weight` (a display setting) is not applied. Bevy
//! itself only shows an emissive surface; slc lets it light the others,
//! as Bevy's Solari does with hardware ray tracing.
//!
//! **Bad input**: a light slc cannot shade (NaN, infinite or negative
//! intensity or colour, a NaN position or cone angle, a zero-area emissive
//! triangle) is left out, with
//! one warning in the log; a mesh that cannot occlude casts no slc shadow,
//! with one warning per mesh asset. Neither stops the camera.
//!
//! **Not applied**: the light's `radius` (a point light), clearcoat,
//! anisotropy and transmission, light textures, forward-rendered materials
//! (only the deferred G-buffer is read). A single frame is noisy by design
//! (SLC's random ranges and the picks), and unbiased: the mean over frames
//! is Bevy's own shading with unbounded ranges (the headless test checks
//! it). The accumulation reprojects by Bevy's motion vectors when the camera
//! has `MotionVectorPrepass` (moving objects keep their history), else by the
//! camera's motion alone; it treats the view-dependent specular lobe as if
//! it were fixed to the surface.
//!
//! **WESL**: the plugin's kernels (`unpack.wesl`, `composite.wesl`) are
//! WESL compiled by Bevy's pipeline cache, importing Bevy's modules as
//! Bevy's own shaders do; and the plugin registers slc's WESL package
//! (`slc_shared_shaders::wesl`) with Bevy's shader assets, so any Bevy
//! shader can `import slc::range::{random_range2, slc_keep, slc_weight};`
//! (the headless test runs one). slc's shading itself is slc-wgpu's direct
//! kernel, generated from the same functions.
//!
//! **Requirements** (checked; a camera that lacks them is skipped and
//! reported in [`SlcStatus`]): the camera is `Hdr` with `Msaa::Off`,
//! `DepthPrepass` and `DeferredPrepass` ([`SlcCamera`] requires them).

mod emissive;

use bevy::camera::Hdr;
use bevy::camera::visibility::RenderLayers;
use bevy::core_pipeline::Core3d;
use bevy::core_pipeline::FullscreenShader;
use bevy::core_pipeline::core_3d::{main_opaque_pass_3d, main_transparent_pass_3d};
use bevy::core_pipeline::prepass::{
    DeferredPrepass, DepthPrepass, MotionVectorPrepass, ViewPrepassTextures,
};
use bevy::light::NotShadowCaster;
use bevy::mesh::UvChannel;
use bevy::prelude::*;
use bevy::render::camera::ExtractedCamera;
use bevy::render::diagnostic::RecordDiagnostics;
use bevy::render::extract_component::{ExtractComponent, ExtractComponentPlugin};
use bevy::render::render_resource::binding_types::{texture_2d, texture_storage_2d};
use bevy::render::render_resource::{
    BindGroupLayoutDescriptor, BindGroupLayoutEntries, BlendComponent, BlendFactor, BlendOperation,
    BlendState, CachedComputePipelineId, CachedPipelineState, CachedRenderPipelineId,
    ColorTargetState, ColorWrites, ComputePipelineDescriptor, FragmentState, PipelineCache,
    RenderPipelineDescriptor, ShaderStages, StorageTextureAccess, TextureSampleType,
};
use bevy::render::renderer::{RenderContext, RenderDevice, RenderQueue, ViewQuery};
use bevy::render::sync_world::MainEntity;
use bevy::render::view::{ExtractedView, Msaa, ViewTarget};
use bevy::render::{Extract, ExtractSchedule, Render, RenderApp, RenderStartup, RenderSystems};
/// How an [`SlcCamera`]'s lights are culled (slc's one culling vocabulary).
pub use slc_wgpu::Culling;
pub use slc_wgpu::passes::DirectCounts;
use slc_wgpu::passes::{
    DirectInputs, DirectOutputs, DirectPass, DirectPassDesc, DirectReuse, DirectSelection,
    DirectSettings, MaterialInputs, Shadows, TemporalInputs, TemporalPass, TemporalPassDesc,
};
/// How an [`SlcCamera`]'s direct pass finds each pixel's lights in range.
pub use slc_wgpu::passes::{DirectWalk, ShadowRays};
use slc_wgpu::{
    GBuffer, GpuContext, Instance, Light, LightSet, Occluders, PointLight as SlcPoint,
    SpotLight as SlcSpot, Surface, SurfaceDesc, TemporalSettings, TemporalView, TriangleLight,
};
use std::collections::HashMap;
use std::sync::{Arc, Mutex};

/// Adds slc's light culling to every camera with [`SlcCamera`].
pub struct SlcPlugin;

/// slc's settings on a 3-D camera: the lights with [`SlcLight`] are shaded
/// for it by stochastic light culling.
#[derive(Component, Clone, Copy, Debug, PartialEq, ExtractComponent)]
#[extract_app(RenderApp)]
#[require(Hdr, DepthPrepass, DeferredPrepass, Msaa::Off)]
pub struct SlcCamera {
    /// Shade slc's lights (off: they add nothing, Bevy's own lights stay).
    pub enabled: bool,
    /// How the lights are culled: stochastic culling by default, its error
    /// bound ε in the camera's exposed radiance (how much one light's random
    /// range may add to a Lambertian pixel's standard deviation, JCGT 2016,
    /// eq. 7; smaller: larger ranges, more lights per pixel, less noise).
    /// slc's time follows the lights in range per pixel: where many lights
    /// crowd a view, a larger ε (0.03 took 0.55× the time of 0.01 with
    /// 4,000 lights on lavapipe) costs little noise while [`Self::reuse`]
    /// is on (docs/bevy.md, "Choosing ε").
    /// Keep the culling's own exposure at 1: the camera's exposure is
    /// applied to the lights. [`Culling::Clamped`] and [`Culling::None`]
    /// are the baselines; [`Culling::Reference`] is not a real-time setting
    /// (the camera is skipped with the reason).
    pub culling: Culling,
    /// Picks per pixel among the lights in range (`1..=64`): at most this
    /// many shadow rays.
    pub picks: u32,
    /// Draw the picks in proportion to each light's unshadowed light at
    /// the pixel, every light in range evaluated without a ray
    /// (`DirectSelection::Resampled`: the rays go where light arrives, each
    /// pick drawn for one colour channel, and only shadows add noise); off:
    /// in proportion to an importance bound
    /// (`DirectSelection::Weighted`, cheaper per light, noisier).
    pub resample: bool,
    /// Reuse the resampled picks across frames (`resample` only; slc-wgpu's
    /// `DirectReuse`, ReSTIR DI's temporal reuse, unbiased): each pick is
    /// a reservoir combined with the last frame's at the pixel the point
    /// was seen in, so a still view's picks improve frame after frame. Costs
    /// `2 × (48 + 12·picks)` bytes per pixel (8 picks at 1080p: 597 MB).
    pub reuse: bool,
    /// Seed of the random ranges and picks (the frame number varies them
    /// every frame).
    pub seed: u32,
    /// Accumulate slc's light over frames (slc-wgpu's temporal pass:
    /// reprojection by the camera's motion, disocclusion, a change test
    /// against the frame-to-frame noise, a moving average); off: every
    /// frame is a fresh, noisy, unbiased estimate. A moving light's light
    /// trails behind it by up to `max_history` frames (the change test
    /// only catches changes well beyond the noise): lower `max_history`
    /// for fast lights.
    pub accumulate: bool,
    /// The longest history of the accumulation, in frames (`≥ 1`).
    pub max_history: f32,
    /// Shadow every pick against the scene's meshes (see the crate docs);
    /// off: light passes through everything, as with no shadow maps.
    pub shadows: bool,
    /// Count the direct pass's work every frame while set, into
    /// [`SlcWork`]: lights in range, lights evaluated, shadow rays and
    /// occluder BVH nodes per shaded pixel (slc-wgpu's
    /// `DirectPass::count_work`, the same on every adapter). The counting
    /// variant of the kernel is submitted and read back on the render
    /// thread, which waits for it: never in timed frames. It counts the
    /// view's G-buffer as the previous frame left it (its record runs before
    /// this frame's unpack); the image is unchanged.
    pub count_work: bool,
    /// How each pixel's lights in range are found: one walk of the light
    /// hierarchy per 8×8 tile, shared (the default), or one per pixel.
    /// The same lights either way, so the same image; which is faster
    /// depends on the adapter (many_lights' bench compares them:
    /// `SLC_BEVY_WALK`).
    pub walk: DirectWalk,
    /// Cast the shadow rays as the render device's hardware ray queries
    /// where it has them (slc-wgpu's `ShadowRays::RayQuery`; Bevy's default
    /// `WgpuSettings` ask for every feature the adapter has, wgpu's
    /// experimental ray queries included), else the WGSL walk: the same
    /// rays, the same image. Off by default until a real GPU has timed
    /// both (many_lights: `SLC_BEVY_RAY_QUERY=1`).
    pub ray_query: bool,
}

impl Default for SlcCamera {
    /// On, ε = 0.01, 8 resampled picks reused across frames, seed 1,
    /// accumulated over up to 32 frames, shadowed.
    fn default() -> Self {
        SlcCamera {
            enabled: true,
            culling: Culling::stochastic(0.01, 1.0).expect("a valid default"),
            picks: 8,
            resample: true,
            reuse: true,
            seed: 1,
            accumulate: true,
            max_history: 32.0,
            shadows: true,
            count_work: false,
            walk: DirectWalk::Tile,
            ray_query: false,
        }
    }
}

/// Marks a [`PointLight`] or [`SpotLight`] (Bevy's cone and fall-off,
/// `slc_core::light::spot_falloff`'s quadratic shape) that slc shades
/// instead of Bevy: it is put on no
/// render layer (`RenderLayers::none()`, replacing any it had), so Bevy's
/// clustered lighting and shadows skip it, and its `range` is ignored
/// (slc's ranges are random and unbiased). Removing the marker removes the
/// light's `RenderLayers`: Bevy lights it again.
#[derive(Component, Clone, Copy, Debug, Default)]
pub struct SlcLight;

/// What the render world last reported, per camera (main-world entity):
/// `Ok(frames shaded)` or why a camera was skipped. Shared with the render
/// world; read it from the main world.
#[derive(Resource, Clone, Default)]
pub struct SlcStatus(pub Arc<Mutex<HashMap<Entity, Result<u64, String>>>>);

impl SlcStatus {
    /// The report for the main-world camera `camera`.
    pub fn get(&self, camera: Entity) -> Option<Result<u64, String>> {
        self.0.lock().ok()?.get(&camera).cloned()
    }
}

/// The direct pass's work in the last counted frame, per camera
/// (main-world entity), for cameras with [`SlcCamera::count_work`] set.
/// Shared with the render world; read it from the main world.
#[derive(Resource, Clone, Default)]
pub struct SlcWork(pub Arc<Mutex<HashMap<Entity, DirectCounts>>>);

impl SlcWork {
    /// The last counts for the main-world camera `camera`.
    pub fn get(&self, camera: Entity) -> Option<DirectCounts> {
        self.0.lock().ok()?.get(&camera).copied()
    }
}

impl Plugin for SlcPlugin {
    fn build(&self, app: &mut App) {
        let status = SlcStatus::default();
        app.insert_resource(status.clone());
        let work = SlcWork::default();
        app.insert_resource(work.clone());
        let shaders = add_shaders(app);
        app.insert_resource(shaders.clone());
        app.add_plugins(ExtractComponentPlugin::<SlcCamera>::default());
        app.add_observer(|ev: On<Add<SlcLight>>, mut commands: Commands| {
            commands.entity(ev.entity).insert(RenderLayers::none());
        });
        app.add_observer(|ev: On<Remove<SlcLight>>, mut commands: Commands| {
            // A despawn also removes the marker: nothing to do then.
            commands.entity(ev.entity).try_remove::<RenderLayers>();
        });
        let Some(render_app) = app.get_sub_app_mut(RenderApp) else { return };
        render_app
            .insert_resource(status)
            .insert_resource(work)
            .insert_resource(shaders)
            .init_resource::<ExtractedLights>()
            .init_resource::<ExtractedOccluders>()
            .init_resource::<Views>()
            .add_systems(RenderStartup, init_gpu)
            .add_systems(ExtractSchedule, (extract_lights, extract_occluders))
            .add_systems(Render, prepare_views.in_set(RenderSystems::PrepareResources))
            .add_systems(
                Core3d,
                shade_view.after(main_opaque_pass_3d).before(main_transparent_pass_3d),
            );
    }
}

/// The lights slc shades this frame, in Bevy's terms: RGB luminous
/// intensity in candela (Bevy's lumens / 4π, for spots too, as Bevy does),
/// before the camera's exposure.
#[derive(Resource, Default)]
struct ExtractedLights(Vec<BevyLight>);

#[derive(Clone, Copy, Debug)]
enum BevyLight {
    Point {
        position: glam::Vec3,
        candela: glam::Vec3,
    },
    /// Bevy's spot: axis the transform's forward (−Z); the cone angles as
    /// Bevy's extraction clamps them (outer below π/2, inner at most outer).
    Spot {
        position: glam::Vec3,
        axis: glam::Vec3,
        candela: glam::Vec3,
        inner: f32,
        outer: f32,
    },
    /// A triangle of an emissive mesh in world space, counter-clockwise
    /// from its emitting side (Bevy's front face), and its radiance in
    /// cd/m² (the material's `emissive`).
    Triangle {
        vertices: [glam::Vec3; 3],
        nits: glam::Vec3,
    },
}

fn candela(color: Color, lumens: f32) -> glam::Vec3 {
    let c = LinearRgba::from(color);
    glam::Vec3::new(c.red, c.green, c.blue) * (lumens / (4.0 * std::f32::consts::PI))
}

fn to_vec3(v: Vec3) -> glam::Vec3 {
    glam::Vec3::new(v.x, v.y, v.z)
}

/// Keeps an emissive mesh from lighting the scene through slc: it is
/// only shown, as Bevy shows emissive surfaces (a glowing sign or a
/// decoration of many triangles that should not become lights).
#[derive(Component, Clone, Copy, Debug, Default)]
pub struct NotSlcLight;

/// What [`extract_lights`] reads of an emissive mesh.
type EmitterItem = (
    &'static Mesh3d,
    &'static MeshMaterial3d<StandardMaterial>,
    &'static GlobalTransform,
    &'static InheritedVisibility,
);

/// Each emissive mesh asset's triangles in object space (or why it
/// lights nothing), read once and kept until the asset changes.
type EmitterCache = HashMap<AssetId<Mesh>, Result<Vec<[glam::Vec3; 3]>, String>>;

/// Each textured emitter's per-triangle texture means
/// ([`emissive::triangle_means`]) by mesh, image, UV channel and
/// `uv_transform` (its bits), kept until the mesh or image changes.
type TextureCache =
    HashMap<(AssetId<Mesh>, AssetId<Image>, bool, [u32; 6]), Result<Vec<glam::Vec3>, String>>;

#[allow(clippy::too_many_arguments)] // A system's parameters.
fn extract_lights(
    mut out: ResMut<ExtractedLights>,
    mut cache: Local<EmitterCache>,
    mut textured: Local<TextureCache>,
    points: Extract<Query<(&PointLight, &GlobalTransform), With<SlcLight>>>,
    spots: Extract<Query<(&SpotLight, &GlobalTransform), With<SlcLight>>>,
    emitters: Extract<Query<EmitterItem, Without<NotSlcLight>>>,
    meshes: Extract<Res<Assets<Mesh>>>,
    images: Extract<Res<Assets<Image>>>,
    materials: Extract<Res<Assets<StandardMaterial>>>,
    mut events: Extract<MessageReader<AssetEvent<Mesh>>>,
    mut image_events: Extract<MessageReader<AssetEvent<Image>>>,
) {
    out.0.clear();
    for e in events.read() {
        if let AssetEvent::Modified { id } | AssetEvent::Removed { id } = e {
            cache.remove(id);
            textured.retain(|k, _| k.0 != *id);
        }
    }
    for e in image_events.read() {
        if let AssetEvent::Modified { id } | AssetEvent::Removed { id } = e {
            textured.retain(|k, _| k.1 != *id);
        }
    }
    let mut emitting = 0;
    for (mesh, material, transform, visible) in &emitters {
        let Some(m) = materials.get(material.id()) else { continue };
        let e = m.emissive;
        let nits = glam::Vec3::new(e.red, e.green, e.blue);
        if !visible.get() || nits.max_element() <= 0.0 {
            continue;
        }
        emitting += 1;
        let tris = match cache.get(&mesh.id()) {
            Some(t) => t,
            None => {
                // Not loaded yet: looked at again next frame.
                let Some(asset) = meshes.get(mesh.id()) else { continue };
                cache.entry(mesh.id()).or_insert(mesh_triangles(asset))
            }
        };
        let tris = match tris {
            Ok(t) => t,
            Err(e) => {
                warn_once!("slc: an emissive mesh lights nothing: {e}");
                continue;
            }
        };
        // A textured emitter: each triangle's texture mean, read once per
        // mesh, image and mapping (not loaded yet: next frame).
        let means = match &m.emissive_texture {
            None => None,
            Some(texture) => {
                let uv = m.uv_transform.to_cols_array().map(f32::to_bits);
                let key = (mesh.id(), texture.id(), m.emissive_channel == UvChannel::Uv1, uv);
                use std::collections::hash_map::Entry;
                let means = match textured.entry(key) {
                    Entry::Occupied(kept) => kept.into_mut(),
                    Entry::Vacant(slot) => {
                        let (Some(asset), Some(image)) =
                            (meshes.get(mesh.id()), images.get(texture))
                        else {
                            continue;
                        };
                        slot.insert(emissive::triangle_means(
                            asset,
                            image,
                            m.emissive_channel.clone(),
                            m.uv_transform,
                        ))
                    }
                };
                match &*means {
                    Ok(means) if means.len() == tris.len() => Some(means),
                    Ok(_) => {
                        warn_once!(
                            "slc: an emissive mesh's texture means do not match its triangles: its texture is not applied"
                        );
                        None
                    }
                    Err(e) => {
                        warn_once!("slc: {e}: the emissive mesh lights without its texture");
                        None
                    }
                }
            }
        };
        let a = glam::Affine3A::from_cols_array(&transform.affine().to_cols_array());
        for (i, t) in tris.iter().enumerate() {
            let nits = means.map_or(nits, |m| nits * m[i]);
            // A black part of the texture lights nothing: no light.
            if nits.max_element() <= 0.0 {
                continue;
            }
            let v = t.map(|p| a.transform_point3(p));
            out.0.push(BevyLight::Triangle { vertices: v, nits });
            if m.double_sided {
                out.0.push(BevyLight::Triangle { vertices: [v[0], v[2], v[1]], nits });
            }
        }
    }
    // Meshes made and dropped as the app runs: read again when most of
    // the cache is no longer in use.
    if cache.len() > 64 + 2 * emitting {
        cache.clear();
    }
    if textured.len() > 64 + 2 * emitting {
        textured.clear();
    }
    for (light, transform) in &points {
        out.0.push(BevyLight::Point {
            position: to_vec3(transform.translation()),
            candela: candela(light.color, light.intensity),
        });
    }
    for (light, transform) in &spots {
        let outer = light.outer_angle.min(std::f32::consts::FRAC_PI_2 - 1e-4);
        out.0.push(BevyLight::Spot {
            position: to_vec3(transform.translation()),
            axis: to_vec3(*transform.forward()),
            candela: candela(light.color, light.intensity),
            inner: light.inner_angle.clamp(0.0, outer.max(0.0)),
            outer: outer.max(0.0),
        });
    }
}

/// The scene's meshes as slc's occluders (render world).
#[derive(Resource, Default)]
struct ExtractedOccluders {
    occluders: Occluders,
    /// Each mesh asset's mesh in `occluders`, or `None` where it cannot
    /// occlude (warned once).
    mesh_of: HashMap<AssetId<Mesh>, Option<u32>>,
    /// The instances by entity, in order: a changed list is laid out anew.
    entities: Vec<(Entity, u32)>,
    /// Bumped whenever the occluders change.
    generation: u64,
    /// Why the occluders cannot be used (shadows are off until it clears).
    error: Option<String>,
}

/// A mesh asset's triangles in object space, or why it cannot occlude.
fn mesh_triangles(mesh: &Mesh) -> Result<Vec<[glam::Vec3; 3]>, String> {
    Ok(mesh.triangles().map_err(|e| e.to_string())?.map(|t| t.vertices.map(to_vec3)).collect())
}

/// What [`extract_occluders`] reads of a shadow caster.
type CasterItem = (Entity, &'static Mesh3d, &'static GlobalTransform, &'static InheritedVisibility);

/// Reads the shadow casters: new mesh assets get their BVH, moved
/// entities are refitted, a changed set of entities is laid out anew.
fn extract_occluders(
    mut out: ResMut<ExtractedOccluders>,
    meshes: Extract<Res<Assets<Mesh>>>,
    mut events: Extract<MessageReader<AssetEvent<Mesh>>>,
    casters: Extract<Query<CasterItem, Without<NotShadowCaster>>>,
) {
    let out = &mut *out;
    // Start over (every used mesh's BVH built again) when a mesh asset in
    // use was edited, or when most of the meshes built are no longer used
    // (assets made and dropped as the app runs).
    let edited = events
        .read()
        .any(|e| matches!(e, AssetEvent::Modified { id } if out.mesh_of.contains_key(id)));
    let used: std::collections::HashSet<u32> = out.entities.iter().map(|e| e.1).collect();
    if edited || out.occluders.mesh_count() > 64 + 2 * used.len() {
        out.occluders = Occluders::default();
        out.mesh_of.clear();
        out.entities.clear();
    }
    let (mut entities, mut transforms) = (Vec::new(), Vec::new());
    for (entity, mesh, transform, visible) in &casters {
        if !visible.get() {
            continue;
        }
        let id = mesh.id();
        let index = match out.mesh_of.get(&id) {
            Some(&i) => i,
            // Not loaded yet: looked at again next frame.
            None if meshes.get(id).is_none() => continue,
            None => {
                let i = meshes
                    .get(id)
                    .map_or(Err("not loaded".into()), mesh_triangles)
                    .and_then(|t| out.occluders.add_mesh(&t).map_err(|e| e.to_string()))
                    .map_err(|e| warn!("slc: mesh {id:?} casts no slc shadow: {e}"))
                    .ok();
                out.mesh_of.insert(id, i);
                i
            }
        };
        let t = glam::Affine3A::from_cols_array(&transform.affine().to_cols_array());
        if let Some(i) = index
            && slc_wgpu::occluders::placeable(&t)
        {
            entities.push((entity, i));
            transforms.push(t);
        }
    }
    let result = if entities == out.entities {
        out.occluders.set_transforms(&transforms).map(|moved| moved.then_some(()))
    } else {
        let instances: Vec<Instance> = entities
            .iter()
            .zip(&transforms)
            .map(|(&(_, mesh), &transform)| Instance { mesh, transform })
            .collect();
        out.entities = entities;
        out.occluders.set_instances(&instances).map(Some)
    };
    match result {
        Ok(None) => {}
        Ok(Some(())) => {
            out.generation += 1;
            out.error = None;
        }
        Err(e) => {
            if out.error.is_none() {
                warn!("slc: shadows are off: {e}");
            }
            out.error = Some(e.to_string());
            out.generation += 1;
        }
    }
}

/// The textures a view's G-buffer is unpacked into, and slc's output.
const GBUFFER_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// The main texture of an `Hdr` camera.
const HDR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// Device objects shared by every view: slc's context on Bevy's device,
/// and the plugin's two kernels, WESL through Bevy's pipeline cache.
#[derive(Resource)]
struct Gpu {
    ctx: GpuContext,
    unpack_layout: BindGroupLayoutDescriptor,
    unpack: CachedComputePipelineId,
    composite_layout: BindGroupLayoutDescriptor,
    composite: CachedRenderPipelineId,
}

/// The plugin's WESL shaders and slc's WESL package, held so they stay
/// loaded.
#[derive(Resource, Clone)]
struct Shaders {
    unpack: Handle<Shader>,
    composite: Handle<Shader>,
    /// slc's package: held, never read.
    _slc: Vec<Handle<Shader>>,
}

/// Adds slc's WESL package (`slc_shared_shaders::wesl::modules()`, the
/// module path `slc::{name}`: e.g. `import slc::range::{random_range2,
/// slc_keep, slc_weight};`) and the plugin's own shaders to Bevy's shader
/// assets, so that any Bevy shader can import slc's functions.
fn add_shaders(app: &mut App) -> Shaders {
    let mut shaders = app.world_mut().resource_mut::<Assets<Shader>>();
    let slc = slc_shared_shaders::wesl::modules()
        .into_iter()
        .map(|m| {
            shaders.add(Shader::from_wesl(m.source, format!("embedded://slc/{}.wesl", m.name)))
        })
        .collect();
    let unpack = shaders
        .add(Shader::from_wesl(include_str!("unpack.wesl"), "embedded://slc_bevy/unpack.wesl"));
    let composite = shaders.add(Shader::from_wesl(
        include_str!("composite.wesl"),
        "embedded://slc_bevy/composite.wesl",
    ));
    Shaders { unpack, composite, _slc: slc }
}

fn init_gpu(
    mut commands: Commands,
    device: Res<RenderDevice>,
    queue: Res<RenderQueue>,
    cache: Res<PipelineCache>,
    shaders: Res<Shaders>,
    fullscreen: Res<FullscreenShader>,
) {
    let device: wgpu::Device = device.wgpu_device().clone();
    let queue: wgpu::Queue = (**queue).clone();
    let storage = || texture_storage_2d(GBUFFER_FORMAT, StorageTextureAccess::WriteOnly);
    let unpack_layout = BindGroupLayoutDescriptor::new(
        "slc-bevy unpack",
        &BindGroupLayoutEntries::sequential(
            ShaderStages::COMPUTE,
            (texture_2d(TextureSampleType::Uint), storage(), storage(), storage()),
        ),
    );
    let unpack = cache.queue_compute_pipeline(ComputePipelineDescriptor {
        label: Some("slc-bevy unpack".into()),
        layout: vec![unpack_layout.clone()],
        shader: shaders.unpack.clone(),
        entry_point: Some("unpack".into()),
        ..default()
    });
    let composite_layout = BindGroupLayoutDescriptor::new(
        "slc-bevy composite",
        &BindGroupLayoutEntries::single(
            ShaderStages::FRAGMENT,
            texture_2d(TextureSampleType::Float { filterable: false }),
        ),
    );
    let add = BlendComponent {
        src_factor: BlendFactor::One,
        dst_factor: BlendFactor::One,
        operation: BlendOperation::Add,
    };
    let keep = BlendComponent {
        src_factor: BlendFactor::Zero,
        dst_factor: BlendFactor::One,
        operation: BlendOperation::Add,
    };
    let composite = cache.queue_render_pipeline(RenderPipelineDescriptor {
        label: Some("slc-bevy composite".into()),
        layout: vec![composite_layout.clone()],
        vertex: fullscreen.to_vertex_state(),
        fragment: Some(FragmentState {
            shader: shaders.composite.clone(),
            entry_point: Some("composite".into()),
            targets: vec![Some(ColorTargetState {
                format: HDR_FORMAT,
                blend: Some(BlendState { color: add, alpha: keep }),
                write_mask: ColorWrites::ALL,
            })],
            ..default()
        }),
        ..default()
    });
    commands.insert_resource(Gpu {
        ctx: GpuContext::from_device(device, queue),
        unpack_layout,
        unpack,
        composite_layout,
        composite,
    });
}

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
struct Views(HashMap<Entity, View>);

fn texture(
    device: &wgpu::Device,
    (w, h): (u32, u32),
    label: &str,
    usage: wgpu::TextureUsages,
) -> wgpu::TextureView {
    device
        .create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: GBUFFER_FORMAT,
            usage,
            view_formats: &[],
        })
        .create_view(&Default::default())
}

/// The view's lights in slc's form: candela times the camera's exposure.
/// A light slc cannot shade (NaN, infinite or negative intensity, a NaN
/// position or angle) is left out, with one warning in the log for the
/// first such light.
fn slc_lights(lights: &[BevyLight], exposure: f32) -> Vec<Light> {
    lights
        .iter()
        .filter_map(|l| {
            match *l {
                BevyLight::Point { position, candela } => {
                    SlcPoint::new(position, candela * exposure)
                        .map(Light::Point)
                        .map_err(|e| format!("point light at {position}: {e}"))
                }
                // Bevy's spot fall-off is the quadratic one.
                BevyLight::Spot { position, axis, candela, inner, outer } => {
                    SlcSpot::new(position, axis, candela * exposure, inner, outer)
                        .map(|s| Light::Spot(s.with_quadratic_falloff()))
                        .map_err(|e| format!("spot light at {position}: {e}"))
                }
                BevyLight::Triangle { vertices: [a, b, c], nits } => {
                    TriangleLight::new(a, b, c, nits * exposure)
                        .map(Light::Triangle)
                        .map_err(|e| format!("emissive triangle at {a}: {e}"))
                }
            }
            .map_err(|e| {
                warn_once!("slc: a light is left out (and any other it cannot shade): {e}")
            })
            .ok()
        })
        .collect()
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
    desc.reuse = (settings.resample && settings.reuse).then(DirectReuse::default);
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
fn prepare_views(
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
                || (v.settings.picks, v.settings.resample, v.settings.reuse, v.settings.walk)
                    != (settings.picks, settings.resample, settings.reuse, settings.walk)
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
fn shade_view(
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
