//! Bevy 0.20 plugin: Bevy's point lights shaded by stochastic light culling
//! (Tokuyoshi & Harada, JCGT 2016), with no range cut-off, and shadowed by
//! the scene's meshes.
//!
//! Bevy's clustered renderer gives every [`PointLight`] a hard `range`
//! (20 m by default): beyond it the light adds nothing, so a scene lit by
//! many lights darkens. slc gives each light a *random* range every frame,
//! scaled so that the expectation over frames is the unbounded
//! inverse-square light, and shades only the lights whose range reaches a
//! pixel (slc-wgpu's [`DirectPass`](slc_wgpu::passes::DirectPass) on Bevy's own device and
//! G-buffer).
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
//! [`Occluders`](slc_wgpu::Occluders) (one BVH per mesh asset, built when the asset is first
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
mod extract;
mod gpu;
mod view;

use bevy::camera::Hdr;
use bevy::camera::visibility::RenderLayers;
use bevy::core_pipeline::Core3d;
use bevy::core_pipeline::core_3d::{main_opaque_pass_3d, main_transparent_pass_3d};
use bevy::core_pipeline::prepass::{DeferredPrepass, DepthPrepass};
use bevy::prelude::*;
use bevy::render::extract_component::{ExtractComponent, ExtractComponentPlugin};
use bevy::render::view::Msaa;
use bevy::render::{ExtractSchedule, Render, RenderApp, RenderStartup, RenderSystems};
/// How an [`SlcCamera`]'s lights are culled (slc's one culling vocabulary).
pub use slc_wgpu::Culling;
pub use slc_wgpu::passes::DirectCounts;
/// How an [`SlcCamera`]'s direct pass finds each pixel's lights in range.
pub use slc_wgpu::passes::{DirectWalk, ShadowRays};
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
    /// many shadow rays (two or three times as many with
    /// [`Self::visibility_reuse`]). 3 by default: resampled picks draw one
    /// colour channel each, and with visibility reuse 3 picks cast fewer
    /// rays than 8 plain reused picks in a still view (5.3 against 7.3 per
    /// pixel in slc's shadow test) and about as many while the camera
    /// moves (7.1 against 7.2), at 0.58 of their error still.
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
    /// `2 × (48 + 12·picks)` bytes per pixel (3 picks at 1080p: 348 MB).
    pub reuse: bool,
    /// With [`Self::reuse`], visibility reuse (slc-wgpu's
    /// `DirectReuse::visibility`, ReSTIR DI's): each frame's picks are
    /// shadowed before they meet the last frame's, so a pixel's reservoirs
    /// keep only lights that reach it, and where shadows are the noise a
    /// still view's frames get far cleaner (the engine-pass scene of
    /// slc's tests: 4 picks a quarter of 8 weighted picks' error after 32
    /// frames at the same rays, where plain reuse barely helps). Up to two
    /// rays a pick (its own and, where the last frame's wins, that one's),
    /// and one more for a pick that reaches the pixel where the camera or
    /// its light moved (did it reach the last frame's surface?). Unbiased
    /// where the camera, the lights and the meshes move too: a moving
    /// mesh costs the pixels whose rays cross the box it moved in their
    /// history, not their mean. On by default (with 3 picks: issue 47's
    /// noise target at fewer rays than the 8 plain reused picks it
    /// replaced; docs/results/reused-picks.md); its GPU time is pending.
    pub visibility_reuse: bool,
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
    /// On, ε = 0.01, 3 resampled picks with visibility reuse across
    /// frames, seed 1, accumulated over up to 32 frames, shadowed.
    fn default() -> Self {
        SlcCamera {
            enabled: true,
            culling: Culling::stochastic(0.01, 1.0).expect("a valid default"),
            picks: 3,
            resample: true,
            reuse: true,
            visibility_reuse: true,
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

/// Keeps an emissive mesh from lighting the scene through slc: it is
/// only shown, as Bevy shows emissive surfaces (a glowing sign or a
/// decoration of many triangles that should not become lights).
#[derive(Component, Clone, Copy, Debug, Default)]
pub struct NotSlcLight;

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
        let shaders = gpu::add_shaders(app);
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
            .init_resource::<extract::ExtractedLights>()
            .init_resource::<extract::ExtractedOccluders>()
            .init_resource::<view::Views>()
            .add_systems(RenderStartup, gpu::init_gpu)
            .add_systems(ExtractSchedule, (extract::extract_lights, extract::extract_occluders))
            .add_systems(Render, view::prepare_views.in_set(RenderSystems::PrepareResources))
            .add_systems(
                Core3d,
                view::shade_view.after(main_opaque_pass_3d).before(main_transparent_pass_3d),
            );
    }
}
