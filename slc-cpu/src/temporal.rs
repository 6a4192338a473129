//! Temporal accumulation of a per-pixel signal on the CPU (the indirect
//! irradiance after the spatial filter, or the direct pass's irradiance):
//! each frame reprojects the history with the previous camera, keeps the
//! taps of the same surface, responds to change from the luminance
//! moments and blends with the moving average, every step slc-core's
//! [`slc_core::temporal`] (the GPU's `temporal` kernel calls the same
//! functions).
//!
//! ```
//! use slc_cpu::vpl::{FrameHistory, VplContext};
//! use slc_scene::scene::Scene;
//! use slc_scene::temporal::TemporalSettings;
//! use slc_scene::vpl::VplSettings;
//!
//! let ctx = VplContext::new(&Scene::cornell_box(), 32, 32, 32, None).unwrap();
//! let mut history = FrameHistory::new(32, 32).unwrap();
//! for frame in 0..4 {
//!     let f = ctx.render_accumulated(&VplSettings { frame, ..Default::default() }, &mut history, &TemporalSettings::default()).unwrap();
//!     assert!(f.image.is_finite());
//! }
//! // Every lit pixel has accumulated all four frames.
//! assert!(history.irradiance.history_lengths().iter().all(|&n| n == 0.0 || n == 4.0));
//! ```

use glam::{Vec2, Vec3, Vec4};
use rayon::prelude::*;
use slc_core::temporal::{
    history_mean, history_tap, history_tap_weight, history_tap_weight_motion, reproject,
    reproject_motion, temporal_color, temporal_moments,
};
use slc_scene::RenderError;
use slc_scene::temporal::{TemporalSettings, TemporalView};
use slc_scene::vpl::GBuffer;

/// One pixel's history: the accumulated value and its length in frames,
/// the last frame's luminance and the noise variance, and the surface it
/// belongs to (normal and tangent-plane offset; length 0 where there was
/// none). The GPU keeps the same three `vec4`s in three textures.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Texel {
    /// Value (xyz) and length (w).
    value: Vec4,
    /// The last frame's luminance (x), the noise variance (y) and the
    /// distance from the eye (z).
    moments: Vec4,
    /// Unit normal `n` (xyz) and tangent-plane offset `n·p` (w).
    surface: Vec4,
}

/// The history of one image size and what it was last rendered with.
pub struct Temporal {
    width: u32,
    height: u32,
    history: Vec<Texel>,
    /// The buffer the next frame's history is written into.
    spare: Vec<Texel>,
    previous: Option<TemporalView>,
}

impl Temporal {
    /// An empty history for `width × height` images (each in `1..=16384`).
    pub fn new(width: u32, height: u32) -> Result<Temporal, RenderError> {
        slc_scene::check_size(width, height)?;
        let n = (width * height) as usize;
        Ok(Temporal {
            width,
            height,
            history: vec![Texel::default(); n],
            spare: vec![Texel::default(); n],
            previous: None,
        })
    }

    /// Forgets the history (a cut: the next frame starts afresh).
    pub fn reset(&mut self) {
        self.history.fill(Texel::default());
        self.previous = None;
    }

    /// Each pixel's history length in frames after the last
    /// [`Temporal::accumulate`] (0 where there was no surface).
    pub fn history_lengths(&self) -> Vec<f32> {
        self.history.iter().map(|t| t.value.w).collect()
    }

    /// Accumulates this frame's `signal` (one value per pixel, row-major)
    /// over the G-buffer `gb` seen from `view`, and returns the
    /// accumulated signal (the signal itself where the G-buffer has no
    /// surface or the history nothing to reuse). The history becomes this
    /// frame's.
    pub fn accumulate(
        &mut self,
        signal: &[Vec3],
        gb: &GBuffer,
        view: &TemporalView,
        settings: &TemporalSettings,
    ) -> Result<Vec<Vec3>, RenderError> {
        self.accumulate_with(signal, gb, view, None, settings)
    }

    /// [`Temporal::accumulate`] reprojecting by the engine's motion vectors
    /// (`motion`, one per pixel: current minus previous UV, x right, y
    /// down) instead of the previous view-projection, so moving objects
    /// keep their history; a tap then matches by its distance from its
    /// eye and its normal ([`slc_core::temporal::history_tap_weight_motion`]).
    pub fn accumulate_with_motion(
        &mut self,
        signal: &[Vec3],
        gb: &GBuffer,
        view: &TemporalView,
        motion: &[Vec2],
        settings: &TemporalSettings,
    ) -> Result<Vec<Vec3>, RenderError> {
        self.accumulate_with(signal, gb, view, Some(motion), settings)
    }

    fn accumulate_with(
        &mut self,
        signal: &[Vec3],
        gb: &GBuffer,
        view: &TemporalView,
        motion: Option<&[Vec2]>,
        settings: &TemporalSettings,
    ) -> Result<Vec<Vec3>, RenderError> {
        settings.validate()?;
        view.validate()?;
        let n = (self.width * self.height) as usize;
        if gb.width != self.width
            || gb.height != self.height
            || gb.position.len() != n
            || gb.normal.len() != n
        {
            return Err(RenderError::Setting(format!(
                "a {}x{} G-buffer for a {}x{} temporal history",
                gb.width, gb.height, self.width, self.height
            )));
        }
        if signal.len() != n {
            return Err(RenderError::Setting(format!(
                "{} signal values for {n} pixels",
                signal.len()
            )));
        }
        if let Some(m) = motion
            && (m.len() != n || !m.iter().all(|v| v.is_finite()))
        {
            return Err(RenderError::Setting(format!(
                "{} motion vectors for {n} pixels (each finite)",
                m.len()
            )));
        }
        // The next history goes into the spare buffer (no allocation per
        // frame), then the two swap.
        let mut next = std::mem::take(&mut self.spare);
        next.resize(n, Texel::default());
        let this = &*self;
        let mut out = vec![Vec3::ZERO; n];
        next.par_iter_mut().zip(out.par_iter_mut()).enumerate().for_each(|(i, (t, o))| {
            *t = if !gb.valid(i) {
                Texel { value: signal[i].extend(0.0), ..Texel::default() }
            } else {
                let (p, nrm) = (gb.position[i], gb.normal[i]);
                let h = match (this.previous, motion) {
                    (None, _) => Texel::default(),
                    (Some(prev), None) => this.reprojected(p, nrm, &prev),
                    (Some(_), Some(m)) => this.moved(i, p, nrm, m[i], view.eye),
                };
                let value = temporal_color(
                    signal[i],
                    h.value,
                    h.moments.y,
                    h.moments.x,
                    settings.max_history,
                );
                let moments = temporal_moments(
                    signal[i],
                    h.moments.x,
                    h.moments.y,
                    h.value.w,
                    value.w,
                    (p - view.eye).length(),
                );
                Texel { value, moments, surface: nrm.extend(nrm.dot(p)) }
            };
            *o = t.value.truncate();
        });
        self.spare = std::mem::replace(&mut self.history, next);
        self.previous = Some(*view);
        Ok(out)
    }

    /// The history at surface point `p` with normal `n`, read bilinearly
    /// where `previous` saw it, from the taps of the same surface
    /// (renormalised); length 0 where none is.
    fn reprojected(&self, p: Vec3, n: Vec3, previous: &TemporalView) -> Texel {
        let m = previous.view_projection;
        let q = reproject(
            m.x_axis,
            m.y_axis,
            m.z_axis,
            m.w_axis,
            p,
            self.width as f32,
            self.height as f32,
        );
        let d = (p - previous.eye).length();
        self.gathered(q, |w, t| {
            history_tap_weight(w, n, t.surface.truncate(), p, t.surface.w, d, t.value.w)
        })
    }

    /// The history of pixel `i` (point `p`, normal `n`, seen from `eye`)
    /// where its motion vector `m` says it was.
    fn moved(&self, i: usize, p: Vec3, n: Vec3, m: Vec2, eye: Vec3) -> Texel {
        let (w, h) = (self.width as f32, self.height as f32);
        let q = reproject_motion(
            (i % self.width as usize) as f32,
            (i / self.width as usize) as f32,
            m.x,
            m.y,
            w,
            h,
        );
        let d = (p - eye).length();
        self.gathered(q, |w, t| {
            history_tap_weight_motion(w, n, t.surface.truncate(), d, t.moments.z, t.value.w)
        })
    }

    /// The history at previous-frame pixel coordinates `q`: its four taps
    /// ([`history_tap`]), each weighted by `weight(bilinear weight, tap)`,
    /// renormalised ([`history_mean`]).
    fn gathered(&self, q: Vec3, weight: impl Fn(f32, &Texel) -> f32) -> Texel {
        let (mut value, mut moments, mut weight_sum) = (Vec4::ZERO, Vec4::ZERO, 0.0);
        for k in 0..4 {
            let tap = history_tap(q, k, self.width as f32, self.height as f32);
            if tap.w > 0.0 {
                let t = &self.history[tap.y as usize * self.width as usize + tap.x as usize];
                let w = weight(tap.z, t);
                value += t.value * w;
                moments += t.moments * w;
                weight_sum += w;
            }
        }
        Texel {
            value: history_mean(value, weight_sum),
            moments: history_mean(moments, weight_sum),
            surface: Vec4::ZERO,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vpl::VplContext;
    use slc_core::xi::{pcg_hash, xi_from_bits};
    use slc_scene::scene::Scene;

    fn context() -> VplContext {
        VplContext::new(&Scene::cornell_box(), 64, 64, 8, None).unwrap()
    }

    /// Uniform noise on `[0, 1)` per pixel and frame, fixed seed.
    fn noise(n: usize, frame: u32) -> Vec<Vec3> {
        (0..n as u32)
            .map(|i| {
                Vec3::splat(xi_from_bits(pcg_hash(pcg_hash(i) ^ frame.wrapping_mul(0x9e37_79b9))))
            })
            .collect()
    }

    /// A static view accumulates the plain mean of the frames: after 32
    /// frames of i.i.d. noise of variance 1/12 the per-pixel variance is
    /// 1/(12·32), which false change detections would raise.
    #[test]
    fn static_noise_averages_down() {
        let ctx = context();
        let gb = &ctx.inputs().gbuffer;
        let view = TemporalView::of_camera(&ctx.scene().camera, 64, 64);
        let mut t = Temporal::new(64, 64).unwrap();
        let mut out = Vec::new();
        for f in 0..32 {
            out =
                t.accumulate(&noise(64 * 64, f), gb, &view, &TemporalSettings::default()).unwrap();
        }
        let lit: Vec<f64> =
            (0..out.len()).filter(|&i| gb.valid(i)).map(|i| out[i].x as f64).collect();
        let m = lit.iter().sum::<f64>() / lit.len() as f64;
        let var = lit.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (lit.len() - 1) as f64;
        let expected = 1.0 / (12.0 * 32.0);
        // The sample variance of n values has relative sd √(2/n) (≈ 2.5%
        // here): 5σ.
        let tol = 5.0 * (2.0 / lit.len() as f64).sqrt();
        assert!(
            (var / expected - 1.0).abs() < tol,
            "variance {var} vs {expected} ({} pixels)",
            lit.len()
        );
        assert!((m - 0.5).abs() < 5.0 * (expected / lit.len() as f64).sqrt());
        let lens = t.history_lengths();
        assert!((0..lens.len()).all(|i| gb.valid(i) || lens[i] == 0.0));
        // The change test's σ is estimated from the pixel's own few frames,
        // so a 4σ alarm is rare but not impossible: 53 of 3,844 pixels
        // (1.4%) lost part of their history here.
        let short = (0..lens.len()).filter(|&i| gb.valid(i) && lens[i] < 32.0).count();
        assert!(
            short * 50 < lit.len(),
            "{short} of {} pixels lost history in a static scene",
            lit.len()
        );
    }

    /// When the camera moves, a pixel whose surface the previous frame saw
    /// at all four taps keeps its history; a pixel none of whose taps saw
    /// it (disoccluded, or outside the previous image) starts afresh with
    /// this frame's value.
    #[test]
    fn disocclusion_starts_afresh() {
        let mut ctx = context();
        let mut t = Temporal::new(64, 64).unwrap();
        let ts = TemporalSettings::default();
        let base = ctx.scene().camera;
        let before = ctx.inputs().gbuffer.clone();
        for f in 0..6 {
            t.accumulate(&noise(64 * 64, f), &before, &TemporalView::of_camera(&base, 64, 64), &ts)
                .unwrap();
        }
        // Sideways by a twentieth of the scene: the blocks uncover the wall
        // behind them, and the box's edge moves in the image.
        let step = Vec3::X * (0.1 * ctx.scene().diagonal());
        let moved = slc_scene::scene::Camera {
            position: base.position + step,
            target: base.target + step,
            ..base
        };
        ctx.set_camera(moved).unwrap();
        let gb = ctx.inputs().gbuffer.clone();
        let signal = noise(64 * 64, 99);
        let out =
            t.accumulate(&signal, &gb, &TemporalView::of_camera(&moved, 64, 64), &ts).unwrap();
        let lens = t.history_lengths();
        let prev = TemporalView::of_camera(&base, 64, 64).view_projection;
        let (mut kept, mut fresh) = (0, 0);
        for i in (0..lens.len()).filter(|&i| gb.valid(i)) {
            let (p, n) = (gb.position[i], gb.normal[i]);
            let q = reproject(prev.x_axis, prev.y_axis, prev.z_axis, prev.w_axis, p, 64.0, 64.0);
            let d = (p - base.position).length();
            let taps = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)].map(|(dx, dy)| {
                let (x, y) = (q.x.floor() + dx, q.y.floor() + dy);
                let inside = (0.0..64.0).contains(&x) && (0.0..64.0).contains(&y);
                let j = if inside { y as usize * 64 + x as usize } else { 0 };
                let nj = before.normal[j];
                inside
                    && before.valid(j)
                    && slc_core::temporal::history_matches(n, nj, p, nj.dot(before.position[j]), d)
            });
            if taps.iter().all(|&m| m) {
                assert!(lens[i] > 1.0, "pixel {i}: every tap saw its surface");
                kept += 1;
            } else if taps.iter().all(|&m| !m) {
                assert_eq!(
                    (lens[i], out[i]),
                    (1.0, signal[i]),
                    "pixel {i}: no tap saw its surface"
                );
                fresh += 1;
            }
        }
        assert!(fresh > 8, "the move uncovers surfaces ({fresh} pixels)");
        assert!(kept > 64 * 40, "most of the image keeps its history ({kept} pixels)");
    }

    /// A change far beyond the noise drops the history at once; a reported
    /// change caps it.
    #[test]
    fn change_resets_the_history() {
        let ctx = context();
        let gb = &ctx.inputs().gbuffer;
        let view = TemporalView::of_camera(&ctx.scene().camera, 64, 64);
        let mut t = Temporal::new(64, 64).unwrap();
        let ts = TemporalSettings::default();
        for f in 0..10 {
            let s: Vec<Vec3> =
                noise(64 * 64, f).iter().map(|v| Vec3::splat(1.0) + *v * 0.01).collect();
            t.accumulate(&s, gb, &view, &ts).unwrap();
        }
        // A jump far beyond the noise: its first frame could be a lone
        // outlier and enters the mean (history 11 frames); its second
        // frame makes it a change, and the history restarts from it.
        let jump = vec![Vec3::splat(2.0); 64 * 64];
        t.accumulate(&jump, gb, &view, &ts).unwrap();
        assert!(
            (0..jump.len()).filter(|&i| gb.valid(i)).all(|i| t.history_lengths()[i] == 11.0),
            "a lone outlier keeps the history"
        );
        let out = t.accumulate(&jump, gb, &view, &ts).unwrap();
        for i in (0..out.len()).filter(|&i| gb.valid(i)) {
            assert_eq!(t.history_lengths()[i], 1.0);
            assert_eq!(out[i], jump[i]);
        }
        for _ in 0..10 {
            t.accumulate(&jump, gb, &view, &ts).unwrap();
        }
        t.accumulate(&jump, gb, &view, &ts.after_change()).unwrap();
        assert!(
            t.history_lengths().iter().all(|&n| n <= 1.0),
            "a reported change drops the history"
        );
        t.reset();
        assert!(t.history_lengths().iter().all(|&n| n == 0.0));
    }

    /// Motion vectors that describe the camera's move reproject as the
    /// matrices do: the same accumulation wherever the two surface tests
    /// (tangent plane; distance from the eye) agree, all but a few edge
    /// pixels. Wrong-sized or non-finite motion is refused.
    #[test]
    fn motion_vectors_follow_the_camera_like_the_matrices() {
        let mut ctx = context();
        let base = ctx.scene().camera;
        let ts = TemporalSettings::default();
        let (mut by_matrix, mut by_motion) =
            (Temporal::new(64, 64).unwrap(), Temporal::new(64, 64).unwrap());
        let gb = ctx.inputs().gbuffer.clone();
        let view = TemporalView::of_camera(&base, 64, 64);
        let still = vec![Vec2::ZERO; 64 * 64];
        for f in 0..6 {
            by_matrix.accumulate(&noise(64 * 64, f), &gb, &view, &ts).unwrap();
            by_motion.accumulate_with_motion(&noise(64 * 64, f), &gb, &view, &still, &ts).unwrap();
        }
        let step = Vec3::X * (0.03 * ctx.scene().diagonal());
        let moved = slc_scene::scene::Camera {
            position: base.position + step,
            target: base.target + step,
            ..base
        };
        ctx.set_camera(moved).unwrap();
        let gb = ctx.inputs().gbuffer.clone();
        let m = view.view_projection;
        let motion: Vec<Vec2> = (0..64 * 64)
            .map(|i| {
                let q =
                    reproject(m.x_axis, m.y_axis, m.z_axis, m.w_axis, gb.position[i], 64.0, 64.0);
                if gb.valid(i) {
                    Vec2::new(((i % 64) as f32 - q.x) / 64.0, ((i / 64) as f32 - q.y) / 64.0)
                } else {
                    Vec2::ZERO
                }
            })
            .collect();
        let view = TemporalView::of_camera(&moved, 64, 64);
        let a = by_matrix.accumulate(&noise(64 * 64, 9), &gb, &view, &ts).unwrap();
        let b =
            by_motion.accumulate_with_motion(&noise(64 * 64, 9), &gb, &view, &motion, &ts).unwrap();
        let lit: Vec<usize> = (0..a.len()).filter(|&i| gb.valid(i)).collect();
        let same = lit
            .iter()
            .filter(|&&i| (a[i] - b[i]).abs().max_element() <= 1e-4 * a[i].max_element())
            .count();
        assert!(same * 50 >= lit.len() * 49, "{same} of {} pixels agree", lit.len());
        let kept = by_motion.history_lengths().iter().filter(|&&n| n > 1.0).count();
        assert!(
            kept * 10 > lit.len() * 8,
            "motion vectors keep the history ({kept} of {})",
            lit.len()
        );
        assert!(
            by_motion
                .accumulate_with_motion(&noise(64 * 64, 10), &gb, &view, &motion[1..], &ts)
                .is_err()
        );
        let mut bad = motion.clone();
        bad[7] = Vec2::NAN;
        assert!(
            by_motion.accumulate_with_motion(&noise(64 * 64, 10), &gb, &view, &bad, &ts).is_err()
        );
    }

    #[test]
    fn bad_input_is_refused() {
        let ctx = context();
        let gb = &ctx.inputs().gbuffer;
        let view = TemporalView::of_camera(&ctx.scene().camera, 64, 64);
        let ts = TemporalSettings::default();
        assert_eq!(Temporal::new(0, 4).err(), Some(RenderError::Size(0, 4)));
        let mut t = Temporal::new(32, 32).unwrap();
        assert!(
            t.accumulate(&vec![Vec3::ZERO; 32 * 32], gb, &view, &ts).is_err(),
            "G-buffer of another size"
        );
        let mut t = Temporal::new(64, 64).unwrap();
        assert!(t.accumulate(&[Vec3::ZERO; 3], gb, &view, &ts).is_err(), "signal of another size");
        assert!(
            t.accumulate(
                &vec![Vec3::ZERO; 64 * 64],
                gb,
                &TemporalView { eye: Vec3::NAN, ..view },
                &ts
            )
            .is_err()
        );
        assert!(
            t.accumulate(
                &vec![Vec3::ZERO; 64 * 64],
                gb,
                &view,
                &TemporalSettings { max_history: 0.0 }
            )
            .is_err()
        );
    }
}
