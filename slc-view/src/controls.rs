//! What the viewer's user controls, and the keys that change it: the
//! method and its parameter, the denoise, frozen ξ, temporal
//! accumulation, the VPL count, the primary light (moved, aimed, or
//! animated on a circle) and the camera (orbited about its target, or
//! swinging).

use glam::{Quat, Vec3};
use slc_core::range::CullKind;
use slc_scene::culling::{DEFAULT_CLAMP_RANGE, DEFAULT_ERROR_BOUND};
use slc_scene::scene::{Camera, PrimaryLight};
use slc_scene::vpl::{Culling, VplSettings};
use winit::keyboard::{Key, NamedKey};

/// RSM edges the VPL count cycles through (`edge²` VPLs).
pub const VPL_EDGES: [u32; 4] = [64, 128, 256, 512];

/// Seconds per turn of the animated light.
const TURN_SECONDS: f32 = 8.0;

/// Seconds per swing of the orbiting camera (±[`SWING`] about its target).
const SWING_SECONDS: f32 = 6.0;

/// Half the orbiting camera's swing (radians).
const SWING: f32 = 0.25;

/// The camera's orbit per key press (radians).
const ORBIT_STEP: f32 = 0.05;

/// The viewer's settings and the light's pose.
#[derive(Clone, Debug, PartialEq)]
pub struct Controls {
    /// Seed, denoise and near field of the frame (its culling is
    /// [`Controls::kind`] with the knobs below: [`Controls::culling`]).
    pub settings: VplSettings,
    /// The culling the keys and the overlay choose (`1` `2` `3`).
    pub kind: CullKind,
    /// The error bound ε of stochastic culling (kept while another kind is
    /// shown).
    pub error_bound: f32,
    /// The clamp range `R` (kept while another kind is shown).
    pub range: f32,
    /// The exposure of the error bound and of the display.
    pub exposure: f32,
    /// Keep ξ of frame 0 on every frame (no temporal change of SLC's noise).
    pub freeze: bool,
    /// Move the light on a horizontal circle.
    pub animate: bool,
    /// Accumulate the indirect light over frames (reprojected, with the
    /// moving light a reported change).
    pub temporal: bool,
    /// Swing the camera about its target.
    pub orbit: bool,
    /// The scene's camera.
    camera: Camera,
    /// The camera's turn about the vertical through its target (radians).
    pub cam_yaw: f32,
    /// The camera's tilt about its right axis (radians).
    pub cam_pitch: f32,
    /// The swing's angle (radians).
    pub swing_phase: f32,
    /// RSM edge (`edge²` VPLs).
    pub rsm_edge: u32,
    /// The scene's primary light.
    base: PrimaryLight,
    /// Offset of the light's position from the scene's (spot).
    pub offset: Vec3,
    /// Rotation of the light's direction about the vertical axis (radians).
    pub yaw: f32,
    /// Tilt of the light's direction toward its right (radians).
    pub pitch: f32,
    /// The animation's angle (radians).
    pub phase: f32,
    /// A step of the keys, in scene units (2% of the scene's diagonal).
    step: f32,
}

impl Controls {
    /// Controls at `settings` (its culling sets the kind and its knob; the
    /// other knob starts at its default), exposure `exposure`, the scene's
    /// primary light `base` and camera `camera`, a scene of diagonal
    /// `diag`, `rsm_edge²` VPLs; temporal accumulation on.
    pub fn new(
        settings: VplSettings,
        exposure: f32,
        base: PrimaryLight,
        camera: Camera,
        diag: f32,
        rsm_edge: u32,
    ) -> Controls {
        let range = match settings.culling {
            Culling::Clamped(r) => r.get(),
            _ => DEFAULT_CLAMP_RANGE,
        };
        Controls {
            kind: settings.culling.kind(),
            error_bound: settings.culling.error_bound().unwrap_or(DEFAULT_ERROR_BOUND),
            range,
            exposure,
            settings,
            freeze: false,
            animate: false,
            temporal: true,
            orbit: false,
            camera,
            cam_yaw: 0.0,
            cam_pitch: 0.0,
            swing_phase: 0.0,
            rsm_edge,
            base,
            offset: Vec3::ZERO,
            yaw: 0.0,
            pitch: 0.0,
            phase: 0.0,
            step: 0.02 * diag,
        }
    }

    /// The camera now: the scene's, turned about the vertical through its
    /// target by `cam_yaw` plus the swing, and tilted by `cam_pitch`.
    pub fn camera(&self) -> Camera {
        let c = &self.camera;
        let yaw = Quat::from_rotation_y(self.cam_yaw + SWING * self.swing_phase.sin());
        let back = yaw * (c.position - c.target);
        let right = back.cross(Vec3::Y);
        let tilt = if right.length_squared() > 1e-12 {
            Quat::from_axis_angle(right.normalize(), self.cam_pitch)
        } else {
            Quat::IDENTITY
        };
        Camera { position: c.target + tilt * back, up: tilt * yaw * c.up, ..*c }
    }

    /// The primary light now: the scene's, moved by `offset` plus the
    /// animation's circle (radius five steps), its direction turned by
    /// `yaw` about +y and tilted by `pitch`.
    pub fn light(&self) -> PrimaryLight {
        // Zero at phase 0: the light starts, and resets, at the scene's.
        let circle = Vec3::new(self.phase.cos() - 1.0, 0.0, self.phase.sin()) * (5.0 * self.step);
        let turn = |d: Vec3| {
            let d = Quat::from_rotation_y(self.yaw) * d;
            let right = d.cross(Vec3::Y);
            if right.length_squared() > 1e-12 {
                Quat::from_axis_angle(right.normalize(), self.pitch) * d
            } else {
                d
            }
        };
        match self.base {
            PrimaryLight::Spot { position, direction, intensity, inner, outer } => {
                PrimaryLight::Spot {
                    position: position + self.offset + circle,
                    direction: turn(direction),
                    intensity,
                    inner,
                    outer,
                }
            }
            PrimaryLight::Directional { direction, irradiance } => PrimaryLight::Directional {
                direction: Quat::from_rotation_y(self.phase) * turn(direction),
                irradiance,
            },
        }
    }

    /// Advances the animation by `dt` seconds (when on).
    pub fn tick(&mut self, dt: f32) {
        if self.animate {
            self.phase =
                (self.phase + dt * std::f32::consts::TAU / TURN_SECONDS) % std::f32::consts::TAU;
        }
        if self.orbit {
            self.swing_phase = (self.swing_phase + dt * std::f32::consts::TAU / SWING_SECONDS)
                % std::f32::consts::TAU;
        }
    }

    /// The culling the controls show: [`Controls::kind`] with its knob.
    /// The knobs stay within bounds that make a valid culling; an exposure
    /// that does not falls back to 1.
    pub fn culling(&self) -> Culling {
        match self.kind {
            CullKind::Stochastic => Culling::stochastic(self.error_bound, self.exposure)
                .or_else(|_| Culling::stochastic(self.error_bound, 1.0))
                .unwrap_or_default(),
            CullKind::Clamped => Culling::clamped(self.range).unwrap_or(Culling::None),
            CullKind::None => Culling::None,
        }
    }

    /// The frame's settings for frame number `frame` (0 while ξ is frozen).
    pub fn frame_settings(&self, frame: u32) -> VplSettings {
        VplSettings {
            culling: self.culling(),
            frame: if self.freeze { 0 } else { frame },
            ..self.settings
        }
    }

    /// Applies a key; `true` when it changed something. Keys: `1` `2` `3`
    /// method slc / clamp / none; `+` `-` the error bound ×2 / ÷2 (slc) or
    /// the range ×1.25 / ÷1.25 (clamp); `d` denoise; `f` freeze ξ; `t`
    /// temporal accumulation; `v` the next VPL count; space animation;
    /// arrows move the light across, PageUp / PageDown up and down; `j` `l`
    /// orbit the camera left / right, `i` `k` tilt it, `o` swing it; `r`
    /// resets the light and the camera.
    pub fn key(&mut self, key: &Key) -> bool {
        let s = &mut self.settings;
        match key {
            Key::Character(c) => match c.as_str() {
                "1" => self.kind = CullKind::Stochastic,
                "2" => self.kind = CullKind::Clamped,
                "3" => self.kind = CullKind::None,
                "+" | "=" => self.scale_parameter(true),
                "-" => self.scale_parameter(false),
                "d" | "D" => s.denoise = !s.denoise,
                "f" | "F" => self.freeze = !self.freeze,
                "t" | "T" => self.temporal = !self.temporal,
                "v" | "V" => self.rsm_edge = next_edge(self.rsm_edge),
                "j" | "J" => self.cam_yaw -= ORBIT_STEP,
                "l" | "L" => self.cam_yaw += ORBIT_STEP,
                "i" | "I" => self.cam_pitch = (self.cam_pitch + ORBIT_STEP).clamp(-1.2, 1.2),
                "k" | "K" => self.cam_pitch = (self.cam_pitch - ORBIT_STEP).clamp(-1.2, 1.2),
                "o" | "O" => self.orbit = !self.orbit,
                "r" | "R" => {
                    (self.offset, self.yaw, self.pitch, self.phase) = (Vec3::ZERO, 0.0, 0.0, 0.0);
                    (self.cam_yaw, self.cam_pitch, self.swing_phase) = (0.0, 0.0, 0.0);
                }
                _ => return false,
            },
            Key::Named(NamedKey::Space) => self.animate = !self.animate,
            Key::Named(NamedKey::ArrowLeft) => self.offset.x -= self.step,
            Key::Named(NamedKey::ArrowRight) => self.offset.x += self.step,
            Key::Named(NamedKey::ArrowUp) => self.offset.z -= self.step,
            Key::Named(NamedKey::ArrowDown) => self.offset.z += self.step,
            Key::Named(NamedKey::PageUp) => self.offset.y += self.step,
            Key::Named(NamedKey::PageDown) => self.offset.y -= self.step,
            _ => return false,
        }
        true
    }

    /// Aims the light by a mouse drag of `(dx, dy)` pixels (a full window
    /// width turns it by about a quarter turn).
    pub fn drag(&mut self, (dx, dy): (f32, f32), width: f32) {
        let k = std::f32::consts::FRAC_PI_2 / width.max(1.0);
        self.yaw -= dx * k;
        self.pitch = (self.pitch - dy * k).clamp(-1.2, 1.2);
    }

    /// Doubles or halves the error bound (slc), or scales the clamp range
    /// by 1.25 (clamp); clamped to sane bounds.
    fn scale_parameter(&mut self, up: bool) {
        match self.kind {
            CullKind::Clamped => {
                let r = self.range;
                self.range = (if up { r * 1.25 } else { r / 1.25 }).clamp(1e-3, 1e3)
            }
            _ => {
                let e = self.error_bound;
                self.error_bound = (if up { e * 2.0 } else { e * 0.5 }).clamp(1e-5, 10.0)
            }
        }
    }
}

/// The VPL count after `edge²`: the next of [`VPL_EDGES`], round the list.
pub fn next_edge(edge: u32) -> u32 {
    let i = VPL_EDGES.iter().position(|&e| e == edge).map_or(0, |i| (i + 1) % VPL_EDGES.len());
    VPL_EDGES[i]
}

#[cfg(test)]
mod tests {
    use super::*;
    use slc_scene::scene::Scene;

    fn controls() -> Controls {
        let scene = Scene::cornell_box();
        Controls::new(
            VplSettings::default(),
            1.0,
            scene.primary,
            scene.camera,
            scene.diagonal(),
            256,
        )
    }

    /// Keys change what they say, and unknown keys nothing.
    #[test]
    fn keys_change_the_settings() {
        let mut c = controls();
        let eps = c.frame_settings(0).culling.error_bound().unwrap();
        assert!(c.key(&Key::Character("+".into())));
        assert_eq!(c.frame_settings(0).culling.error_bound(), Some(2.0 * eps));
        assert!(c.key(&Key::Character("2".into())));
        let Culling::Clamped(r) = c.frame_settings(0).culling else { panic!("clamped") };
        c.key(&Key::Character("-".into()));
        let Culling::Clamped(r2) = c.frame_settings(0).culling else { panic!("clamped") };
        assert!((r2.get() - r.get() / 1.25).abs() < 1e-6);
        c.key(&Key::Character("1".into()));
        assert_eq!(c.frame_settings(0).culling.error_bound(), Some(2.0 * eps), "ε kept");
        c.key(&Key::Character("d".into()));
        assert!(!c.settings.denoise);
        c.key(&Key::Character("f".into()));
        assert_eq!(c.frame_settings(7).frame, 0, "frozen ξ");
        c.key(&Key::Character("v".into()));
        assert_eq!(c.rsm_edge, 512);
        assert!(c.temporal, "accumulation starts on");
        c.key(&Key::Character("t".into()));
        assert!(!c.temporal);
        let before = c.clone();
        assert!(!c.key(&Key::Character("q".into())));
        assert_eq!(c, before);
    }

    /// The light at rest is the scene's; moved, aimed and animated lights
    /// stay valid and move; `r` puts the scene's light back.
    #[test]
    fn the_light_moves_and_stays_valid() {
        let mut c = controls();
        assert_eq!(c.light(), Scene::cornell_box().primary);
        c.key(&Key::Named(NamedKey::ArrowLeft));
        c.drag((40.0, -25.0), 512.0);
        c.key(&Key::Named(NamedKey::Space));
        for _ in 0..100 {
            c.tick(0.05);
            c.light().validate().expect("a valid light");
        }
        let PrimaryLight::Spot { position: p, .. } = c.light() else { unreachable!("a spot") };
        c.tick(TURN_SECONDS - 5.0);
        let PrimaryLight::Spot { position: q, .. } = c.light() else { unreachable!("a spot") };
        assert!((p - q).length() > 1e-3, "the light moved");
        c.tick(5.0);
        c.key(&Key::Character("r".into()));
        assert_eq!(c.light(), Scene::cornell_box().primary, "reset");
    }

    /// The camera at rest is the scene's; orbited, tilted and swinging it
    /// stays valid, keeps its distance to the target and moves; `r` resets it.
    #[test]
    fn the_camera_orbits_and_stays_valid() {
        let mut c = controls();
        let cam = Scene::cornell_box().camera;
        assert!((c.camera().position - cam.position).length() < 1e-4);
        for k in ["j", "j", "i", "o"] {
            c.key(&Key::Character(k.into()));
        }
        for _ in 0..50 {
            c.tick(0.05);
            let m = c.camera();
            m.validate().expect("a valid camera");
            assert!(
                ((m.position - m.target).length() - (cam.position - cam.target).length()).abs()
                    < 1e-3
            );
        }
        assert!((c.camera().position - cam.position).length() > 1e-3, "the camera moved");
        c.key(&Key::Character("r".into()));
        assert!((c.camera().position - cam.position).length() < 1e-4, "reset");
    }
}
