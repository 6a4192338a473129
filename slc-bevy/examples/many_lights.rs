//! Thousands of moving coloured point lights (every tenth a spot light)
//! over a city block of pillars, shaded by slc (every light shadowed by
//! the pillars, one ray per pick) or by Bevy's own clustered lighting
//! (unshadowed: thousands of shadow maps are out of its reach).
//!
//! ```text
//! cargo run --release --manifest-path slc-bevy/Cargo.toml --ignore-rust-version --example many_lights [LIGHTS]
//! ```
//!
//! Keys: `Space` cycles slc → Bevy with its default 20 m ranges → Bevy with
//! unbounded ranges (the ground truth, slow with thousands of lights);
//! `Up`/`Down` double or halve slc's error bound ε; `S` turns slc's shadows
//! off and on; `R` switches slc's picks between resampled (the default)
//! and weighted; `U` turns the resampled picks' reuse across frames off
//! and on. The window's title shows the mode, the light count, ε,
//! the shadows, the picks and the frame time (smoothed).
//!
//! For scripts: `SLC_BEVY_FRAMES=N` exits after N frames, first writing the
//! window to the PNG `SLC_BEVY_SCREENSHOT` names (if set); `SLC_BEVY_MODE`
//! (`slc`, `default`, `unbounded`) picks the starting mode; `SLC_BEVY_SIZE`
//! (`WxH`) the window's size; `SLC_BEVY_SHADOWS=off` starts without slc's
//! shadows; `SLC_BEVY_EPSILON` sets slc's error bound ε (default 0.01; the
//! bench too); `SLC_BEVY_WALK=pixel` walks the light hierarchy once per
//! pixel instead of once per tile (`SlcCamera::walk`; the bench too);
//! `SLC_BEVY_RAY_QUERY=1` casts slc's shadow rays as hardware ray queries
//! where the device has them (`SlcCamera::ray_query`; the bench too);
//! `SLC_BEVY_VISIBILITY=0` turns off the reuse's visibility reuse
//! (`SlcCamera::visibility_reuse`, on by default; the bench's default rows
//! too).
//!
//! **Frame-time bench** (no window, no display): `SLC_BEVY_BENCH=out.json`
//! renders into an image target at `SLC_BEVY_SIZE` (default 1920x1080)
//! under Bevy's `RenderDiagnosticsPlugin` (GPU timestamps where the adapter
//! has them), in seven configurations: slc shadowed (3 resampled picks with
//! visibility reuse across frames, its default; 8 picks with plain reuse,
//! its default until 2026-12-08; without reuse; weighted picks), slc
//! unshadowed, Bevy at its default 20 m ranges, Bevy at unbounded ranges. Each warms up for
//! at least 0.5 s and 3 frames, then times `SLC_BEVY_BENCH_FRAMES` frames
//! (default 64, at most 120) back to back (`SLC_BEVY_BENCH_MODES`, e.g.
//! `slc` or `slc,default`, limits it to those modes' configurations); it
//! reports per configuration
//! the median GPU time of each of Bevy's top-level passes and slc's
//! (`render/slc`), their sum (the GPU frame), the median wall time of a
//! frame, and for slc's configurations its work per shaded pixel (lights in
//! range, evaluated, shadow rays, BVH nodes: one counted frame after the
//! timed ones, the same on every adapter), as a table and as JSON. Every
//! frame waits for the GPU to finish (an image target paces nothing:
//! unwaited, the CPU ran ahead and the timestamps after a change were the
//! previous configuration's), so the wall time is the CPU's and the GPU's
//! work one after the other. Run it once per light count:
//!
//! ```text
//! SLC_BEVY_BENCH=bench-4000.json cargo run --release --manifest-path slc-bevy/Cargo.toml --ignore-rust-version --example many_lights 4000
//! ```

use bevy::camera::RenderTarget;
use bevy::core_pipeline::tonemapping::Tonemapping;
use bevy::pbr::DefaultOpaqueRendererMethod;
use bevy::prelude::*;
use bevy::render::view::screenshot::{Screenshot, ScreenshotCaptured};
use rand::{Rng, SeedableRng};
use slc_bevy::{Culling, DirectWalk, SlcCamera, SlcLight, SlcPlugin, SlcStatus};

fn main() {
    let lights = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(4000usize);
    if let Ok(out) = std::env::var("SLC_BEVY_BENCH") {
        if let Err(e) = bench(lights, &out) {
            eprintln!("many_lights bench: {e}");
            std::process::exit(1);
        }
        return;
    }
    let mode =
        std::env::var("SLC_BEVY_MODE").ok().and_then(|m| Mode::named(&m)).unwrap_or(Mode::Slc);
    let mut window = Window { title: "slc-bevy many_lights".into(), ..default() };
    if let Some((w, h)) = size() {
        window.resolution = (w, h).into();
    }
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin { primary_window: Some(window), ..default() }),
            SlcPlugin,
        ))
        .insert_resource(DefaultOpaqueRendererMethod::deferred())
        .insert_resource(GlobalAmbientLight { brightness: 0.0, ..default() })
        .insert_resource(ClearColor(Color::srgb(0.01, 0.01, 0.02)))
        .insert_resource(Settings { lights, mode, frame_ms: 0.0, apply: true })
        .add_systems(Startup, setup)
        .add_systems(Update, (move_lights, keys, title, scripted_exit))
        .run();
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum Mode {
    Slc,
    BevyDefaultRange,
    BevyUnbounded,
}

impl Mode {
    /// The mode `SLC_BEVY_MODE` and `SLC_BEVY_BENCH_MODES` call `name`
    /// (`slc`, `default`, `unbounded`).
    fn named(name: &str) -> Option<Mode> {
        match name.trim() {
            "slc" => Some(Mode::Slc),
            "default" => Some(Mode::BevyDefaultRange),
            "unbounded" => Some(Mode::BevyUnbounded),
            _ => None,
        }
    }
}

#[derive(Resource)]
struct Settings {
    lights: usize,
    mode: Mode,
    frame_ms: f32,
    /// Apply `mode` to the lights at the next update.
    apply: bool,
}

/// `SLC_BEVY_SIZE` (`WxH`), when set.
fn size() -> Option<(u32, u32)> {
    std::env::var("SLC_BEVY_SIZE").ok().and_then(|s| {
        s.split_once('x').and_then(|(w, h)| Some((w.parse::<u32>().ok()?, h.parse::<u32>().ok()?)))
    })
}

/// slc's culling: the default, its error bound set by `SLC_BEVY_EPSILON`
/// when given (a bad value exits with the reason).
fn culling() -> Culling {
    let default = SlcCamera::default().culling;
    let Ok(e) = std::env::var("SLC_BEVY_EPSILON") else { return default };
    let parsed = e.parse().map_err(|_| format!("{e} is not a number"));
    match parsed.and_then(|eps| default.with_error_bound(eps).map_err(|err| err.to_string())) {
        Ok(culling) => culling,
        Err(err) => {
            eprintln!("SLC_BEVY_EPSILON: {err}");
            std::process::exit(2);
        }
    }
}

/// Whether slc's shadow rays are ray queries: `SLC_BEVY_RAY_QUERY=1`.
fn ray_query() -> bool {
    std::env::var("SLC_BEVY_RAY_QUERY").as_deref() == Ok("1")
}

/// Whether the reuse is visibility reuse: yes (`SlcCamera`'s default)
/// unless `SLC_BEVY_VISIBILITY=0`.
fn visibility_reuse() -> bool {
    std::env::var("SLC_BEVY_VISIBILITY").as_deref() != Ok("0")
}

/// How slc finds each pixel's lights: `SLC_BEVY_WALK` (`tile`, the
/// default, or `pixel`; another value exits with the reason).
fn walk() -> DirectWalk {
    match std::env::var("SLC_BEVY_WALK").as_deref() {
        Err(_) | Ok("tile") => DirectWalk::Tile,
        Ok("pixel") => DirectWalk::Pixel,
        Ok(other) => {
            eprintln!("SLC_BEVY_WALK: {other:?} is neither tile nor pixel");
            std::process::exit(2);
        }
    }
}

/// The bench's image target: the camera renders into it instead of a window.
#[derive(Resource)]
struct BenchTarget(Handle<Image>);

/// A light's circle: centre, radius, angular speed, phase.
#[derive(Component)]
struct Orbit {
    centre: Vec3,
    radius: f32,
    speed: f32,
    phase: f32,
}

fn setup(
    mut commands: Commands,
    settings: Res<Settings>,
    target: Option<Res<BenchTarget>>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    let mut rng = rand::rngs::StdRng::seed_from_u64(1);
    let floor = materials.add(StandardMaterial {
        base_color: Color::srgb(0.5, 0.5, 0.5),
        perceptual_roughness: 0.7,
        ..default()
    });
    commands.spawn((
        Mesh3d(meshes.add(Plane3d::default().mesh().size(240.0, 240.0))),
        MeshMaterial3d(floor),
    ));
    let pillar = meshes.add(Cuboid::new(1.0, 1.0, 1.0));
    for i in -6..=6 {
        for j in -6..=6 {
            let h = rng.random_range(2.0..14.0);
            let m = materials.add(StandardMaterial {
                base_color: Color::hsl(rng.random_range(0.0..360.0), 0.3, 0.6),
                metallic: if rng.random_bool(0.3) { 1.0 } else { 0.0 },
                perceptual_roughness: rng.random_range(0.2..0.9),
                ..default()
            });
            commands.spawn((
                Mesh3d(pillar.clone()),
                MeshMaterial3d(m),
                Transform::from_xyz(i as f32 * 16.0, h / 2.0, j as f32 * 16.0)
                    .with_scale(Vec3::new(4.0, h, 4.0)),
            ));
        }
    }
    for i in 0..settings.lights {
        let centre = Vec3::new(
            rng.random_range(-110.0..110.0),
            rng.random_range(0.5..12.0),
            rng.random_range(-110.0..110.0),
        );
        let color = Color::hsl(rng.random_range(0.0..360.0), 0.9, 0.6);
        let orbit = Orbit {
            centre,
            radius: rng.random_range(1.0..8.0),
            speed: rng.random_range(-1.0..1.0),
            phase: rng.random_range(0.0..6.3),
        };
        if i % 10 == 0 {
            // Every tenth a spot light, looking down.
            let spot = SpotLight {
                color,
                intensity: rng.random_range(1e5..6e5),
                inner_angle: 0.2,
                outer_angle: 0.6,
                shadow_maps_enabled: false,
                ..default()
            };
            commands.spawn((
                spot,
                Transform::from_translation(centre).looking_to(Vec3::NEG_Y, Vec3::X),
                orbit,
            ));
        } else {
            let point = PointLight {
                color,
                intensity: rng.random_range(2e4..2e5),
                shadow_maps_enabled: false,
                ..default()
            };
            commands.spawn((point, Transform::from_translation(centre), orbit));
        }
    }
    let camera = commands
        .spawn((
            Camera3d::default(),
            SlcCamera {
                shadows: std::env::var("SLC_BEVY_SHADOWS").as_deref() != Ok("off"),
                culling: culling(),
                walk: walk(),
                ray_query: ray_query(),
                visibility_reuse: visibility_reuse(),
                ..default()
            },
            Tonemapping::AcesFitted,
            Transform::from_xyz(0.0, 60.0, 120.0).looking_at(Vec3::ZERO, Vec3::Y),
        ))
        .id();
    if let Some(t) = target {
        commands.entity(camera).insert(RenderTarget::Image(t.0.clone().into()));
    }
}

/// Moves the lights along their circles: by the clock, or in scripted
/// runs (`SLC_BEVY_FRAMES`) by 1/60 s per frame, as a 60 Hz display would
/// (a software renderer's seconds per frame would jump the lights).
fn move_lights(
    time: Res<Time>,
    frames: Res<bevy::diagnostic::FrameCount>,
    mut lights: Query<(&Orbit, &mut Transform)>,
) {
    let t = if std::env::var_os("SLC_BEVY_FRAMES").is_some()
        || std::env::var_os("SLC_BEVY_BENCH").is_some()
    {
        frames.0 as f32 / 60.0
    } else {
        time.elapsed_secs()
    };
    for (o, mut tr) in &mut lights {
        let a = o.phase + o.speed * t;
        tr.translation = o.centre + Vec3::new(a.cos(), 0.0, a.sin()) * o.radius;
    }
}

fn keys(
    input: Res<ButtonInput<KeyCode>>,
    mut settings: ResMut<Settings>,
    mut commands: Commands,
    mut points: Query<(Entity, &mut PointLight)>,
    mut spots: Query<(Entity, &mut SpotLight)>,
    mut cameras: Query<&mut SlcCamera>,
) {
    if input.just_pressed(KeyCode::Space) {
        settings.mode = match settings.mode {
            Mode::Slc => Mode::BevyDefaultRange,
            Mode::BevyDefaultRange => Mode::BevyUnbounded,
            Mode::BevyUnbounded => Mode::Slc,
        };
    }
    if input.just_pressed(KeyCode::Space) || settings.apply {
        settings.apply = false;
        let range =
            if settings.mode == Mode::BevyUnbounded { 1e4 } else { PointLight::default().range };
        let mut lights: Vec<Entity> = Vec::new();
        for (e, mut light) in &mut points {
            light.range = range;
            lights.push(e);
        }
        for (e, mut light) in &mut spots {
            light.range = range;
            lights.push(e);
        }
        for e in lights {
            if settings.mode == Mode::Slc {
                commands.entity(e).insert(SlcLight);
            } else {
                commands.entity(e).remove::<SlcLight>();
            }
        }
    }
    for mut camera in &mut cameras {
        if input.just_pressed(KeyCode::KeyS) {
            camera.shadows = !camera.shadows;
        }
        if input.just_pressed(KeyCode::KeyR) {
            camera.resample = !camera.resample;
        }
        if input.just_pressed(KeyCode::KeyU) {
            camera.reuse = !camera.reuse;
        }
        // ×2 or ÷2 on ε (a stochastic culling only; the others keep theirs).
        let scale = |c: Culling, k: f32| c.with_error_bound(c.error_bound().unwrap_or(1.0) * k);
        if input.just_pressed(KeyCode::ArrowUp)
            && let Ok(c) = scale(camera.culling, 2.0)
        {
            camera.culling = c;
        }
        if input.just_pressed(KeyCode::ArrowDown)
            && let Ok(c) = scale(camera.culling, 0.5)
        {
            camera.culling = c;
        }
    }
}

fn title(
    time: Res<Time>,
    mut settings: ResMut<Settings>,
    cameras: Query<&SlcCamera>,
    mut windows: Query<&mut Window>,
) {
    let ms = time.delta_secs() * 1000.0;
    settings.frame_ms =
        if settings.frame_ms == 0.0 { ms } else { 0.95 * settings.frame_ms + 0.05 * ms };
    let eps = cameras.iter().next().and_then(|c| c.culling.error_bound()).unwrap_or(0.0);
    let shadows = if cameras.iter().next().is_some_and(|c| c.shadows) { "on" } else { "off" };
    let picks = match cameras.iter().next().map(|c| (c.resample, c.reuse)) {
        Some((true, true)) => "reused resampled",
        Some((true, false)) => "resampled",
        _ => "weighted",
    };
    for mut w in &mut windows {
        w.title = format!(
            "slc-bevy many_lights: {:?}, {} lights, ε {eps}, shadows {shadows}, {picks} picks, {:.1} ms/frame (Space: mode, Up/Down: ε, S: shadows, R: picks, U: reuse)",
            settings.mode, settings.lights, settings.frame_ms
        );
    }
}

/// `SLC_BEVY_FRAMES`: exit after that many frames, writing the window to
/// `SLC_BEVY_SCREENSHOT` first; exits with an error when slc's mode is on
/// and slc reports the camera skipped or unshaded.
fn scripted_exit(
    mut frames: Local<u32>,
    mut commands: Commands,
    mut exit: MessageWriter<AppExit>,
    settings: Res<Settings>,
    status: Res<SlcStatus>,
    cameras: Query<Entity, With<SlcCamera>>,
) {
    let Some(n) = std::env::var("SLC_BEVY_FRAMES").ok().and_then(|s| s.parse::<u32>().ok()) else {
        return;
    };
    *frames += 1;
    if *frames == n && settings.mode == Mode::Slc {
        for camera in &cameras {
            match status.get(camera) {
                Some(Ok(shaded)) if shaded > 0 => {}
                other => {
                    eprintln!("slc did not shade the camera: {other:?}");
                    exit.write(AppExit::error());
                    return;
                }
            }
        }
    }
    if *frames == n {
        match std::env::var("SLC_BEVY_SCREENSHOT") {
            Ok(path) => {
                commands.spawn(Screenshot::primary_window()).observe(
                    move |ev: On<ScreenshotCaptured>, mut exit: MessageWriter<AppExit>| {
                        match ev.image.clone().try_into_dynamic() {
                            Ok(img) => {
                                let rgb = img.to_rgb8();
                                if let Err(e) =
                                    write_png(&path, rgb.width(), rgb.height(), rgb.as_raw())
                                {
                                    eprintln!("could not write {path}: {e}");
                                }
                            }
                            Err(e) => eprintln!("could not convert the screenshot: {e}"),
                        }
                        exit.write(AppExit::Success);
                    },
                );
            }
            Err(_) => {
                exit.write(AppExit::Success);
            }
        }
    }
    if *frames > n + 30 {
        exit.write(AppExit::error());
    }
}

/// One configuration of the bench: its name, the lights' mode, slc's
/// shadows, whether its picks are resampled (its default) or weighted,
/// whether resampled picks are reused across frames (its default), and the
/// picks and visibility reuse where they are not the run's
/// ([`SlcCamera`]'s default picks, [`visibility_reuse`]).
type BenchConfig = (&'static str, Mode, bool, bool, bool, Option<(u32, bool)>);

const CONFIGS: [BenchConfig; 7] = [
    ("slc, shadowed", Mode::Slc, true, true, true, None),
    ("slc, shadowed, 8 plain reused", Mode::Slc, true, true, true, Some((8, false))),
    ("slc, shadowed, no reuse", Mode::Slc, true, true, false, None),
    ("slc, shadowed, weighted picks", Mode::Slc, true, false, false, None),
    ("slc, unshadowed", Mode::Slc, false, true, true, None),
    ("Bevy, default 20 m ranges", Mode::BevyDefaultRange, false, true, true, None),
    ("Bevy, unbounded ranges", Mode::BevyUnbounded, false, true, true, None),
];

/// The median of `v` (slc-scene's, shared with `slc bench`), 0 for none.
fn median(v: Vec<f64>) -> f64 {
    slc_scene::stats::median(&v).unwrap_or(0.0)
}

/// One frame of the bench, then a wait until the GPU has run everything
/// submitted so far. Rendering into an image, nothing paces the CPU (no
/// swap chain): unthrottled, it ran frames far ahead of an NVIDIA H200, so
/// the timestamps read after a configuration change were the previous
/// configuration's. Waiting keeps each configuration's timestamps its own;
/// the wall time is then the CPU's and the GPU's work one after the other.
fn step(app: &mut App) {
    use bevy::render::renderer::RenderDevice;
    app.update();
    let device = app.world().resource::<RenderDevice>().clone();
    // An error here (a lost device) shows as missing timestamps.
    let _ = device.poll(wgpu::PollType::wait_indefinitely());
}

/// Changes every [`SlcCamera`] by `set`.
fn set_cameras(app: &mut App, set: impl Fn(&mut SlcCamera)) {
    let world = app.world_mut();
    let mut cameras = world.query::<&mut SlcCamera>();
    for mut c in cameras.iter_mut(world) {
        set(&mut c);
    }
}

/// slc's work in one frame with [`SlcCamera::count_work`] set (it counts
/// on the render thread, which runs a frame behind: three frames, then the
/// setting off again), or `None` where nothing was counted.
fn count_work(app: &mut App) -> Option<slc_bevy::DirectCounts> {
    set_cameras(app, |c| c.count_work = true);
    for _ in 0..3 {
        step(app);
    }
    set_cameras(app, |c| c.count_work = false);
    step(app);
    let world = app.world_mut();
    let camera = world.query_filtered::<Entity, With<SlcCamera>>().iter(world).next()?;
    world.resource::<slc_bevy::SlcWork>().get(camera)
}

/// The frame-time bench (see the module docs): every configuration of
/// [`CONFIGS`] with `lights` lights, written to `out` as JSON.
fn bench(lights: usize, out: &str) -> Result<(), String> {
    use bevy::app::PluginsState;
    use bevy::diagnostic::DiagnosticsStore;
    use bevy::render::RenderPlugin;
    use bevy::render::diagnostic::RenderDiagnosticsPlugin;
    use bevy::render::render_resource::TextureFormat;
    use bevy::render::renderer::RenderAdapterInfo;
    use bevy::window::ExitCondition;
    use bevy::winit::WinitPlugin;
    use std::time::{Duration, Instant};

    let (w, h) = size().unwrap_or((1920, 1080));
    // The modes benched (all by default): `SLC_BEVY_BENCH_MODES=slc` skips
    // Bevy's two (unbounded ranges take minutes at 20,000 lights).
    let modes: Vec<Mode> = match std::env::var("SLC_BEVY_BENCH_MODES") {
        Err(_) => vec![Mode::Slc, Mode::BevyDefaultRange, Mode::BevyUnbounded],
        Ok(list) => list
            .split(',')
            .map(|m| {
                Mode::named(m).ok_or(format!(
                    "SLC_BEVY_BENCH_MODES: unknown mode {m:?} (slc, default, unbounded)"
                ))
            })
            .collect::<Result<_, _>>()?,
    };
    let frames: usize = std::env::var("SLC_BEVY_BENCH_FRAMES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(64)
        .clamp(2, 120);
    let mut app = App::new();
    app.add_plugins((
        DefaultPlugins
            .set(WindowPlugin {
                primary_window: None,
                exit_condition: ExitCondition::DontExit,
                ..default()
            })
            .set(RenderPlugin { synchronous_pipeline_compilation: true, ..default() })
            .disable::<WinitPlugin>(),
        SlcPlugin,
        RenderDiagnosticsPlugin,
    ))
    .insert_resource(DefaultOpaqueRendererMethod::deferred())
    .insert_resource(GlobalAmbientLight { brightness: 0.0, ..default() })
    .insert_resource(ClearColor(Color::srgb(0.01, 0.01, 0.02)))
    .insert_resource(Settings { lights, mode: Mode::Slc, frame_ms: 0.0, apply: true })
    .add_systems(Startup, setup)
    .add_systems(Update, (move_lights, keys));
    while app.plugins_state() == PluginsState::Adding {
        bevy::tasks::tick_global_task_pools_on_main_thread();
    }
    app.finish();
    app.cleanup();
    let image = Image::new_target_texture(w, h, TextureFormat::Rgba16Float, None);
    let image = app.world_mut().resource_mut::<Assets<Image>>().add(image);
    app.insert_resource(BenchTarget(image));
    let adapter = app
        .sub_app(bevy::render::RenderApp)
        .world()
        .get_resource::<RenderAdapterInfo>()
        .map_or("unknown".to_string(), |a| format!("{} ({:?})", a.name, a.backend));
    let slc_walk = format!("{:?}", walk()).to_lowercase();
    // Bevy's device has every feature of the adapter's (its default settings).
    let device_rq =
        app.world().get_resource::<bevy::render::renderer::RenderDevice>().is_some_and(|d| {
            d.features().contains(bevy::render::settings::WgpuFeatures::EXPERIMENTAL_RAY_QUERY)
        });
    let slc_ray_query = ray_query() && device_rq;
    let rays = match (ray_query(), device_rq) {
        (true, true) => "ray queries",
        (true, false) => "a WGSL walk (the device has no ray queries)",
        _ => "a WGSL walk",
    };
    println!(
        "many_lights bench: {lights} lights, {w}x{h}, {frames} timed frames, slc's {slc_walk} walk, shadow rays by {rays}, visibility reuse {}, on {adapter}",
        if visibility_reuse() { "on" } else { "off" }
    );
    let mut results = Vec::new();
    let run_picks = (SlcCamera::default().picks, visibility_reuse());
    for (name, mode, shadows, resample, reuse, picks) in CONFIGS {
        if !modes.contains(&mode) {
            continue;
        }
        let mut settings = app.world_mut().resource_mut::<Settings>();
        (settings.mode, settings.apply) = (mode, true);
        let (k, visibility) = picks.unwrap_or(run_picks);
        set_cameras(&mut app, |c| {
            (c.shadows, c.resample, c.reuse) = (shadows, resample, reuse);
            (c.picks, c.visibility_reuse) = (k, visibility);
        });
        // Warm-up: the mode applied, pipelines built, the clock up.
        let start = Instant::now();
        let mut n = 0;
        while n < 3 || start.elapsed() < Duration::from_millis(500) {
            step(&mut app);
            n += 1;
        }
        // Timestamps arrive a few frames late: what is in flight is
        // dropped, then `frames` frames are timed back to back (and the
        // few after them let their timestamps arrive).
        let clear = |app: &mut App| {
            for d in app.world_mut().resource_mut::<DiagnosticsStore>().iter_mut() {
                d.clear_history();
            }
        };
        for _ in 0..2 {
            step(&mut app);
        }
        clear(&mut app);
        let mut wall = Vec::with_capacity(frames);
        for _ in 0..frames {
            let t = Instant::now();
            step(&mut app);
            wall.push(t.elapsed().as_secs_f64() * 1e3);
        }
        for _ in 0..4 {
            step(&mut app);
        }
        let store = app.world().resource::<DiagnosticsStore>();
        // Bevy's top-level spans: render/<pass>/elapsed_gpu (nested ones
        // are inside them).
        let mut passes: Vec<(String, f64, usize)> = store
            .iter()
            .filter_map(|d| {
                let c: Vec<&str> = d.path().components().collect();
                let v: Vec<f64> = d.values().copied().take(frames).collect();
                (c.len() == 3 && c[0] == "render" && c[2] == "elapsed_gpu" && !v.is_empty()).then(
                    || {
                        let n = v.len();
                        (c[1].to_string(), median(v), n)
                    },
                )
            })
            .collect();
        passes.sort_by(|a, b| a.0.cmp(&b.0));
        let gpu_total: f64 = passes.iter().map(|p| p.1).sum();
        let slc = passes.iter().find(|p| p.0 == "slc").map_or(0.0, |p| p.1);
        let samples = passes.iter().map(|p| p.2).min().unwrap_or(0);
        let cpu = median(wall);
        println!(
            "  {name:<28} GPU frame {gpu_total:8.3} ms (slc {slc:7.3} ms; {} passes, {samples} frames of timestamps); wall {cpu:8.2} ms/frame",
            passes.len()
        );
        // slc's work per shaded pixel, from one counted frame after the
        // timed ones (the same on every adapter).
        let work = (mode == Mode::Slc).then(|| count_work(&mut app)).flatten();
        if let Some(w) = &work {
            println!(
                "  {:<28} per shaded pixel: {:.1} lights in range, {:.1} evaluated, {:.2} shadow rays, {:.1} BVH nodes",
                "",
                w.per_pixel(w.candidates),
                w.per_pixel(w.evaluations),
                w.per_pixel(w.rays),
                w.per_pixel(w.nodes)
            );
        }
        results.push(serde_json::json!({
            "configuration": name,
            "gpu_frame_ms": gpu_total,
            "slc_ms": slc,
            "timestamped_frames": samples,
            "wall_ms": cpu,
            "work_per_pixel": work.map(|w| serde_json::json!({
                "pixels": w.pixels,
                "in_range": w.per_pixel(w.candidates),
                "evaluated": w.per_pixel(w.evaluations),
                "shadow_rays": w.per_pixel(w.rays),
                "bvh_nodes": w.per_pixel(w.nodes),
            })),
            "passes_ms": passes.iter().map(|p| (p.0.clone(), serde_json::json!(p.1))).collect::<serde_json::Map<_, _>>(),
        }));
    }
    let timestamps = results.iter().any(|r| r["timestamped_frames"].as_u64() > Some(0));
    if !timestamps {
        println!("  no GPU timestamps on this adapter: only the wall times mean anything");
    }
    let report = serde_json::json!({
        "adapter": adapter,
        "lights": lights,
        "width": w,
        "height": h,
        "timed_frames": frames,
        "slc_walk": slc_walk,
        "slc_ray_query": slc_ray_query,
        "timestamps": timestamps,
        "configurations": results,
    });
    let text = serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?;
    std::fs::write(out, text).map_err(|e| format!("{out}: {e}"))
}

fn write_png(
    path: &str,
    width: u32,
    height: u32,
    rgb: &[u8],
) -> Result<(), Box<dyn std::error::Error>> {
    let mut enc =
        png::Encoder::new(std::io::BufWriter::new(std::fs::File::create(path)?), width, height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.write_header()?.write_image_data(rgb)?;
    Ok(())
}
