//! What the temporal stage of both backends takes besides the signal:
//! each frame's camera ([`TemporalView`]) and the accumulation's settings
//! ([`TemporalSettings`]). The per-pixel math is slc-core's
//! [`slc_core::temporal`].

use crate::RenderError;
use crate::scene::Camera;
use glam::{Mat4, Vec3};

/// A frame's camera as the temporal stage reprojects with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TemporalView {
    /// View-projection (wgpu clip space: depth in `[0, 1]`, y up; pixel
    /// rays as the G-buffer's).
    pub view_projection: Mat4,
    /// Eye position (the history's depths are distances from it).
    pub eye: Vec3,
}

impl TemporalView {
    /// The view of `camera` for a `w × h` image ([`Camera::view_projection`];
    /// the depth range does not change the reprojected pixel, so a fixed
    /// one serves every scene).
    pub fn of_camera(camera: &Camera, w: u32, h: u32) -> TemporalView {
        TemporalView {
            view_projection: camera.view_projection(w, h, 1e-3, 1e3),
            eye: camera.position,
        }
    }

    /// Checks that every entry is finite.
    pub fn validate(&self) -> Result<(), RenderError> {
        if self.view_projection.is_finite() && self.eye.is_finite() {
            Ok(())
        } else {
            Err(RenderError::Setting(
                "temporal view: the view-projection and the eye must be finite".into(),
            ))
        }
    }
}

/// The temporal accumulation's settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TemporalSettings {
    /// The longest history in frames `N ≥ 1` (the moving average's weight
    /// never falls below `1/N`; 1 turns accumulation off).
    pub max_history: f32,
}

impl Default for TemporalSettings {
    fn default() -> Self {
        TemporalSettings { max_history: slc_core::temporal::TEMPORAL_MAX_HISTORY }
    }
}

impl TemporalSettings {
    /// These settings for a frame whose lighting changed (a light moved or
    /// was added or removed): the history capped at
    /// [`slc_core::temporal::TEMPORAL_CHANGED_HISTORY`] (1: dropped).
    pub fn after_change(self) -> TemporalSettings {
        TemporalSettings {
            max_history: self.max_history.min(slc_core::temporal::TEMPORAL_CHANGED_HISTORY),
        }
    }

    /// Checks `max_history` (finite, `≥ 1`).
    pub fn validate(&self) -> Result<(), RenderError> {
        if self.max_history.is_finite() && self.max_history >= 1.0 {
            Ok(())
        } else {
            Err(RenderError::Setting(format!(
                "temporal max history {} must be finite and >= 1",
                self.max_history
            )))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;
    use slc_core::temporal::reproject;

    /// The reprojection of a point on a camera ray lands on that ray's pixel.
    #[test]
    fn camera_rays_reproject_to_their_pixels() {
        let cam = Scene::cornell_box().camera;
        let (w, h) = (96, 64);
        let v = TemporalView::of_camera(&cam, w, h);
        let m = v.view_projection;
        for (x, y) in [(0u32, 0u32), (95, 63), (40, 17), (3, 60)] {
            let p = cam.position + cam.ray_dir(x as f32, y as f32, w, h) * 2.7;
            let q = reproject(m.x_axis, m.y_axis, m.z_axis, m.w_axis, p, w as f32, h as f32);
            assert!(
                (q.x - x as f32).abs() < 1e-3 && (q.y - y as f32).abs() < 1e-3,
                "({x}, {y}) → {q}"
            );
        }
        assert!(v.validate().is_ok());
        assert!(TemporalView { eye: Vec3::NAN, ..v }.validate().is_err());
        assert!(TemporalSettings { max_history: 0.5 }.validate().is_err());
        assert!(TemporalSettings { max_history: f32::NAN }.validate().is_err());
        assert!(TemporalSettings::default().validate().is_ok());
    }
}
