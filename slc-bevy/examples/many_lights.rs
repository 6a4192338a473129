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
//! off and on. The window's title shows the mode, the light count, ε,
//! the shadows and the frame time (smoothed).
//!
//! For scripts: `SLC_BEVY_FRAMES=N` exits after N frames, first writing the
//! window to the PNG `SLC_BEVY_SCREENSHOT` names (if set); `SLC_BEVY_MODE`
//! (`slc`, `default`, `unbounded`) picks the starting mode; `SLC_BEVY_SIZE`
//! (`WxH`) the window's size; `SLC_BEVY_SHADOWS=off` starts without slc's
//! shadows.

use bevy::core_pipeline::tonemapping::Tonemapping;
use bevy::pbr::DefaultOpaqueRendererMethod;
use bevy::prelude::*;
use bevy::render::view::screenshot::{Screenshot, ScreenshotCaptured};
use rand::{Rng, SeedableRng};
use slc_bevy::{Culling, SlcCamera, SlcLight, SlcPlugin, SlcStatus};

fn main() {
    let lights = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(4000usize);
    let mode = match std::env::var("SLC_BEVY_MODE").as_deref() {
        Ok("default") => Mode::BevyDefaultRange,
        Ok("unbounded") => Mode::BevyUnbounded,
        _ => Mode::Slc,
    };
    let mut window = Window { title: "slc-bevy many_lights".into(), ..default() };
    if let Some((w, h)) = std::env::var("SLC_BEVY_SIZE").ok().and_then(|s| {
        s.split_once('x').and_then(|(w, h)| Some((w.parse::<u32>().ok()?, h.parse::<u32>().ok()?)))
    }) {
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
        .insert_resource(Settings { lights, mode, frame_ms: 0.0 })
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

#[derive(Resource)]
struct Settings {
    lights: usize,
    mode: Mode,
    frame_ms: f32,
}

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
    commands.spawn((
        Camera3d::default(),
        SlcCamera {
            shadows: std::env::var("SLC_BEVY_SHADOWS").as_deref() != Ok("off"),
            ..default()
        },
        Tonemapping::AcesFitted,
        Transform::from_xyz(0.0, 60.0, 120.0).looking_at(Vec3::ZERO, Vec3::Y),
    ));
}

/// Moves the lights along their circles: by the clock, or in scripted
/// runs (`SLC_BEVY_FRAMES`) by 1/60 s per frame, as a 60 Hz display would
/// (a software renderer's seconds per frame would jump the lights).
fn move_lights(
    time: Res<Time>,
    frames: Res<bevy::diagnostic::FrameCount>,
    mut lights: Query<(&Orbit, &mut Transform)>,
) {
    let t = if std::env::var_os("SLC_BEVY_FRAMES").is_some() {
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
    if input.just_pressed(KeyCode::Space) || settings.is_added() {
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
    for mut w in &mut windows {
        w.title = format!(
            "slc-bevy many_lights: {:?}, {} lights, ε {eps}, shadows {shadows}, {:.1} ms/frame (Space: mode, Up/Down: ε, S: shadows)",
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
