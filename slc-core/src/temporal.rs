//! Temporal accumulation of the real-time passes' stochastic outputs
//! (indirect irradiance after the spatial filter, the direct pass's
//! irradiance), written once for both backends. Per pixel, each frame:
//!
//! 1. **Reproject** the pixel's surface point into the previous frame
//!    ([`reproject`]: the previous view-projection, the inverse of the
//!    engine pass's `unproject_pixel`; or the engine's motion vector,
//!    [`reproject_motion`], which also follows moving objects) and read the history there
//!    bilinearly ([`bilinear_weight`]), keeping only taps that saw the same
//!    surface ([`history_matches`]: the point on the tap's tangent plane,
//!    and the normals alike), renormalised; no matching tap is a
//!    disocclusion.
//! 2. **Respond to change**, two ways. (a) Reported: a caller that knows
//!    the lighting changed this frame (the primary light moved, a light
//!    was added) caps the history at [`TEMPORAL_CHANGED_HISTORY`] frame:
//!    the history is dropped, and accumulation starts again from the
//!    first frame after the change stops. (b) Detected, per pixel: the history
//!    keeps the luminance of the last frame's value and a moving average
//!    of half the squared difference between consecutive frames, the
//!    frame-to-frame noise variance σ² (differences of consecutive frames,
//!    unlike SVGF's moments `E[l²] − E[l]²`, hardly grow while the signal
//!    drifts, so drift cannot hide behind its own variance); a current
//!    value further from the history's mean than the noise explains
//!    shortens the history in proportion ([`temporal_change`]), when the
//!    last frame's value deviated to the same side too
//!    ([`persistent_change`]): a change persists, while a single outlier of
//!    a heavy-tailed estimate (a rare bright pick) does not, and dropping
//!    the history for it would bias the mean upward. This
//!    stands in for A-SVGF's temporal gradients (Schied et al., "Gradient
//!    Estimation for Real-Time Adaptive Temporal Filtering", HPG 2018),
//!    which re-shade last frame's samples with this frame's scene and need
//!    the shading kernels' cooperation; the test here needs none, and
//!    catches only changes larger than a few σ (which is why (a) exists).
//! 3. **Accumulate**: an exponential moving average whose weight is
//!    `1/n` for a history of `n` frames, capped at [`TEMPORAL_MAX_HISTORY`]
//!    ([`temporal_alpha`]): the plain mean while the history grows, then a
//!    moving average.
//!
//! The signals are irradiance, not radiance: albedo (and a glossy lobe's
//! reflectance) is applied after accumulation, so texture and material
//! detail never blur over frames ("demodulation", SVGF §4).

// Shared (WGSL) functions take their inputs as scalars and vectors.
#![allow(clippy::too_many_arguments)]

use crate::wgsl::*;

crate::shared! {
    /// The longest history `N`: the moving average never weighs the current
    /// frame below `1/N`.
    pub const TEMPORAL_MAX_HISTORY: f32 = 32.0;

    /// The current surface point may lie this fraction of its distance
    /// from the eye off a history tap's tangent plane and still be the
    /// same surface.
    pub const TEMPORAL_DEPTH_TOLERANCE: f32 = 0.01;

    /// With motion vectors (objects move, so a world plane does not
    /// persist): a tap's distance from its frame's eye may differ from the
    /// current point's distance from this frame's eye by this fraction.
    pub const TEMPORAL_MOTION_DEPTH_TOLERANCE: f32 = 0.05;

    /// A history tap's normal must be within this cosine of the current one.
    pub const TEMPORAL_NORMAL_COS: f32 = 0.9;

    /// Frames of history before its noise estimate is trusted to judge a
    /// change ([`temporal_change`] keeps the history until then).
    pub const TEMPORAL_MIN_MOMENTS: f32 = 8.0;

    /// The history cap of a frame whose caller reports that the lighting
    /// changed: 1, the history is dropped. Measured (`slc bench --flicker`,
    /// a spot moving 1.6% of the scene's diagonal per frame): the image
    /// changes per frame by six times the spatially filtered frame's
    /// error, so any weight above ~0.1 on a past frame lags by more than
    /// the noise it removes (a cap of 4 gave 1.8× the spatial-only error).
    /// Keeping history under motion needs A-SVGF's per-pixel gradients.
    pub const TEMPORAL_CHANGED_HISTORY: f32 = 1.0;

    /// Below this many standard deviations between the current value and
    /// the history's mean, the difference is noise: the history is kept.
    pub const TEMPORAL_CHANGE_LOW: f32 = 4.0;

    /// At this many standard deviations or more the history is dropped
    /// entirely; between the two, in proportion.
    pub const TEMPORAL_CHANGE_HIGH: f32 = 8.0;

    /// Bilinear weight below which a reprojection counts as a disocclusion.
    pub const TEMPORAL_MIN_WEIGHT: f32 = 0.01;

    /// Relative luminance of linear Rec. 709 RGB (ITU-R BT.709):
    /// `0.2126 R + 0.7152 G + 0.0722 B`.
    pub fn luminance(c: vec3f) -> f32 {
        return dot(c, vec3f(0.2126, 0.7152, 0.0722));
    }

    /// Where world point `p` was in the previous frame: its pixel
    /// coordinates (x, y; pixel centres at integers, row 0 at the top) in a
    /// `width × height` image under the previous view-projection with
    /// columns `c0..c3` (wgpu conventions: clip `M·(p, 1)`, normalised
    /// device `x, y = clip.xy/clip.w`, y up), and in z the clip `w` (≤ 0:
    /// behind the previous camera, nothing to reuse). The inverse of the
    /// engine pass's `unproject_pixel`.
    pub fn reproject(c0: vec4f, c1: vec4f, c2: vec4f, c3: vec4f, p: vec3f, width: f32, height: f32) -> vec3f {
        let clip: vec4f = c0 * p.x + c1 * p.y + c2 * p.z + c3;
        if clip.w <= 0.0 {
            return vec3f(-1.0, -1.0, 0.0);
        }
        let x: f32 = (clip.x / clip.w + 1.0) * 0.5 * width - 0.5;
        let y: f32 = (1.0 - clip.y / clip.w) * 0.5 * height - 0.5;
        return vec3f(x, y, clip.w);
    }

    /// Where pixel `(px, py)` of a `width × height` image was in the
    /// previous frame by the engine's motion vector `(mx, my)`, the
    /// current minus the previous position in UV units (x right, y down,
    /// `[0, 1]` across the image: Bevy's and most engines' convention):
    /// `(px − mx·width, py − my·height)`, and z = 1 (always in front).
    pub fn reproject_motion(px: f32, py: f32, mx: f32, my: f32, width: f32, height: f32) -> vec3f {
        return vec3f(px - mx * width, py - my * height, 1.0);
    }

    /// Bilinear weight of tap `(x0 + dx, y0 + dy)`, `dx, dy ∈ {0, 1}`, for a
    /// point at fractional offsets `(fx, fy)` from `(x0, y0) = ⌊(x, y)⌋`.
    pub fn bilinear_weight(fx: f32, fy: f32, dx: u32, dy: u32) -> f32 {
        let wx: f32 = select(1.0 - fx, fx, dx == 1);
        let wy: f32 = select(1.0 - fy, fy, dy == 1);
        return wx * wy;
    }

    /// Tap `k ∈ 0..4` of the bilinear read of the history at previous-frame
    /// pixel coordinates `q` (z ≤ 0: nothing to read) in a `width × height`
    /// image: the tap's pixel (x, y), its [`bilinear_weight`] (z), and 1 in
    /// w where the tap lies inside the image (else 0: skip it). Both
    /// backends' gathers loop over these four.
    pub fn history_tap(q: vec3f, k: u32, width: f32, height: f32) -> vec4f {
        let x0: f32 = floor(q.x);
        let y0: f32 = floor(q.y);
        let dx: u32 = k % 2;
        let dy: u32 = k / 2;
        let tx: f32 = x0 + to_f32(dx);
        let ty: f32 = y0 + to_f32(dy);
        let inside: bool = q.z > 0.0 && tx >= 0.0 && ty >= 0.0 && tx < width && ty < height;
        return vec4f(tx, ty, bilinear_weight(q.x - x0, q.y - y0, dx, dy), select(0.0, 1.0, inside));
    }

    /// The gathered history `sum` of taps weighing `weight` in all,
    /// renormalised, or zero (length 0: no history, a disocclusion) where
    /// they weigh less than [`TEMPORAL_MIN_WEIGHT`].
    pub fn history_mean(sum: vec4f, weight: f32) -> vec4f {
        if weight < TEMPORAL_MIN_WEIGHT {
            return vec4f(0.0, 0.0, 0.0, 0.0);
        }
        return sum / weight;
    }

    /// Whether a history tap that saw a surface with unit normal `nh` and
    /// tangent plane `nh·x = oh` is the surface now seen at point `p` with
    /// unit normal `n`, at distance `d` from the eye: `p` within
    /// [`TEMPORAL_DEPTH_TOLERANCE`]`·d` of the tap's plane (a plane test,
    /// not a depth test, so a grazing floor matches its neighbours at any
    /// resolution) and the normals within [`TEMPORAL_NORMAL_COS`].
    pub fn history_matches(n: vec3f, nh: vec3f, p: vec3f, oh: f32, d: f32) -> bool {
        return abs(dot(nh, p) - oh) <= TEMPORAL_DEPTH_TOLERANCE * d && dot(n, nh) >= TEMPORAL_NORMAL_COS;
    }

    /// How much of a history of `n` frames to drop (0: keep, 1: drop all)
    /// for a current luminance `l` against the history's mean luminance
    /// `m1`, with frame-to-frame noise variance `noise` (the history's
    /// moving average of half the squared consecutive differences): the
    /// difference of a new draw from the history's mean has standard
    /// deviation `σ·√(1 + 1/n)`; at `t` such
    /// deviations, `λ = clamp((t − LOW)/(HIGH − LOW), 0, 1)`
    /// ([`TEMPORAL_CHANGE_LOW`], [`TEMPORAL_CHANGE_HIGH`]). A history
    /// shorter than [`TEMPORAL_MIN_MOMENTS`] has no trusted σ and is kept
    /// (its weight is high anyway). The `1e-3` relative floor keeps a
    /// noise-free signal (σ = 0) from resetting on rounding.
    pub fn temporal_change(l: f32, m1: f32, noise: f32, n: f32) -> f32 {
        if n < TEMPORAL_MIN_MOMENTS {
            return 0.0;
        }
        let sigma: f32 = sqrt(max(noise, 0.0) * (1.0 + 1.0 / n));
        let t: f32 = abs(l - m1) / (sigma + 1e-3 * max(abs(l), abs(m1)) + 1e-20);
        return clamp((t - TEMPORAL_CHANGE_LOW) / (TEMPORAL_CHANGE_HIGH - TEMPORAL_CHANGE_LOW), 0.0, 1.0);
    }

    /// The history length after this frame: the `(1 − λ)` share of the
    /// `n` frames kept ([`temporal_change`]) plus the current one, capped
    /// at `max_history` (≥ 1).
    pub fn next_history_length(n: f32, lambda: f32, max_history: f32) -> f32 {
        return min((1.0 - lambda) * n + 1.0, max(max_history, 1.0));
    }

    /// The moving average's weight of the current frame for a history of
    /// `n ≥ 1` frames including it: `1/n` (for `n` below the cap this is
    /// the plain mean of the frames so far).
    pub fn temporal_alpha(n: f32) -> f32 {
        return 1.0 / max(n, 1.0);
    }

    /// Weight of a history tap of bilinear weight `w` ([`history_tap`]'s
    /// z) holding `len` frames (0: no surface) of a surface with normal
    /// `nh` and plane offset `oh`, for the current surface (point `p`,
    /// normal `n`, distance `d` from the eye): `w` where the tap has
    /// history of the same surface ([`history_matches`]), else 0.
    pub fn history_tap_weight(w: f32, n: vec3f, nh: vec3f, p: vec3f, oh: f32, d: f32, len: f32) -> f32 {
        return select(0.0, w, len > 0.0 && history_matches(n, nh, p, oh, d));
    }

    /// [`history_tap_weight`] for reprojection by motion vectors: the tap
    /// matches where its distance `dh` from its frame's eye is within
    /// [`TEMPORAL_MOTION_DEPTH_TOLERANCE`] of the current point's distance
    /// `d` from this frame's eye and the normals are within
    /// [`TEMPORAL_NORMAL_COS`].
    pub fn history_tap_weight_motion(w: f32, n: vec3f, nh: vec3f, d: f32, dh: f32, len: f32) -> f32 {
        return select(0.0, w, len > 0.0 && abs(dh - d) <= TEMPORAL_MOTION_DEPTH_TOLERANCE * d && dot(n, nh) >= TEMPORAL_NORMAL_COS);
    }

    /// The share `λ` of the history a detected change drops, for this
    /// frame's luminance `l` and the last frame's `last` against the
    /// history's mean `m1` (noise variance `noise`, `n` frames): the smaller
    /// of the two frames' [`temporal_change`], and 0 unless both deviate to
    /// the same side. A lone outlier keeps the history (it enters the mean
    /// with weight `1/n`, unbiased); a real change drops it one frame
    /// later. Measured (slc-bevy's headless test, bright spot lights with
    /// hard edges, 40 frames): a change test on one frame alone biased the
    /// accumulated image mean by +6.9%.
    pub fn persistent_change(l: f32, last: f32, m1: f32, noise: f32, n: f32) -> f32 {
        if (l - m1) * (last - m1) <= 0.0 {
            return 0.0;
        }
        return min(temporal_change(l, m1, noise, n), temporal_change(last, m1, noise, n));
    }

    /// This frame's accumulated value (xyz) and history length (w) from the
    /// current value `c`, the reprojected history `h` (value in xyz, length
    /// in w; length 0: none) with noise variance `noise` and last frame's
    /// luminance `last`, and the cap `max_history`: `λ` from
    /// [`persistent_change`] against the history's luminance, the length
    /// from [`next_history_length`], then `h·(1 − α) + c·α` with `α = `
    /// [`temporal_alpha`] (written so that `α = 1`, a dropped history,
    /// gives `c` exactly: `h + (c − h)·α` would round at `h`'s scale).
    pub fn temporal_color(c: vec3f, h: vec4f, noise: f32, last: f32, max_history: f32) -> vec4f {
        let hc: vec3f = vec3f(h.x, h.y, h.z);
        let lambda: f32 = persistent_change(luminance(c), last, luminance(hc), noise, h.w);
        let len: f32 = next_history_length(h.w, lambda, max_history);
        let alpha: f32 = temporal_alpha(len);
        let v: vec3f = hc * (1.0 - alpha) + c * alpha;
        return vec4f(v.x, v.y, v.z, len);
    }

    /// The noise statistics after this frame (x: this frame's luminance,
    /// y: the noise variance, z: `depth`, the point's distance from this
    /// frame's eye, for reprojection by motion vectors; w zero) from the
    /// current value `c`, the
    /// history's last luminance `last` and variance `var` over `prev_len`
    /// frames (0: no history, the variance starts at 0), and the new
    /// history length `len` ([`temporal_color`]'s w): the variance's moving
    /// average takes `(l − last)²/2` with weight `1/(len − 1)` (one
    /// difference fewer than frames), at most `LOW²` times the variance
    /// so far once that is trusted ([`TEMPORAL_MIN_MOMENTS`] frames).
    pub fn temporal_moments(c: vec3f, last: f32, noise: f32, prev_len: f32, len: f32, depth: f32) -> vec4f {
        let l: f32 = luminance(c);
        if prev_len <= 0.0 {
            return vec4f(l, 0.0, depth, 0.0);
        }
        let d: f32 = l - last;
        // Once the estimate is trusted, one difference counts as at most
        // LOW² times it: a step's first frame must not inflate σ so far
        // that its second frame passes for noise ([`persistent_change`]
        // needs both); heavy tails still raise σ, more slowly.
        let d2: f32 = 0.5 * d * d;
        let cap: f32 = TEMPORAL_CHANGE_LOW * TEMPORAL_CHANGE_LOW * noise;
        let sample: f32 = select(d2, min(d2, cap), prev_len >= TEMPORAL_MIN_MOMENTS && noise > 0.0);
        return vec4f(l, noise + (sample - noise) * temporal_alpha(len - 1.0), depth, 0.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Mat4, Vec3};

    #[test]
    fn reprojection_inverts_the_pixel_rays() {
        use glam::camera::rh::{proj, view::look_to_mat4};
        let (w, h) = (64.0, 48.0);
        let vp = proj::directx::perspective(1.0, w / h, 0.1, 50.0)
            * look_to_mat4(Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.2, -0.3, -1.0), Vec3::Y);
        let inv = vp.inverse();
        // The centre of pixel (10, 37) at NDC depth 0.9, unprojected.
        let (px, py) = (10.0f32, 37.0f32);
        let ndc = glam::Vec4::new((px + 0.5) / w * 2.0 - 1.0, 1.0 - (py + 0.5) / h * 2.0, 0.9, 1.0);
        let p = inv * ndc;
        let p = p.truncate() / p.w;
        let q = reproject(vp.x_axis, vp.y_axis, vp.z_axis, vp.w_axis, p, w, h);
        assert!((q.x - px).abs() < 1e-3 && (q.y - py).abs() < 1e-3 && q.z > 0.0, "{q}");
        // Behind the camera: nothing.
        let behind = Vec3::new(1.0, 2.0, 3.0) - Vec3::new(0.2, -0.3, -1.0);
        assert!(reproject(vp.x_axis, vp.y_axis, vp.z_axis, vp.w_axis, behind, w, h).z <= 0.0);
        let z = Mat4::ZERO;
        assert_eq!(reproject(z.x_axis, z.y_axis, z.z_axis, z.w_axis, p, w, h).z, 0.0);
    }

    #[test]
    fn motion_vectors_point_back() {
        // Half a pixel right and a pixel down since last frame, in UV.
        let q = reproject_motion(10.0, 20.0, 0.5 / 64.0, 1.0 / 48.0, 64.0, 48.0);
        assert_eq!((q.x, q.y), (9.5, 19.0));
        assert!(q.z > 0.0);
    }

    #[test]
    fn bilinear_weights_sum_to_one() {
        for (fx, fy) in [(0.0, 0.0), (0.25, 0.75), (0.5, 0.5), (0.99, 0.01)] {
            let s: f32 = (0..4).map(|k| bilinear_weight(fx, fy, k & 1, k >> 1)).sum();
            assert!((s - 1.0).abs() < 1e-6);
        }
        assert_eq!(bilinear_weight(0.0, 0.0, 0, 0), 1.0);
        assert_eq!(bilinear_weight(0.25, 0.5, 1, 1), 0.125);
    }

    #[test]
    fn history_matching() {
        let n = Vec3::Y;
        // The floor y = 0 seen from 2 m.
        assert!(
            history_matches(n, n, Vec3::new(5.0, 0.01, 1.0), 0.0, 2.0),
            "on the plane anywhere"
        );
        assert!(
            !history_matches(n, n, Vec3::new(0.0, 0.05, 0.0), 0.0, 2.0),
            "5 cm above it at 2 m is another surface"
        );
        assert!(!history_matches(n, Vec3::X, Vec3::ZERO, 0.0, 2.0), "a crease");
    }

    #[test]
    fn change_response() {
        // σ = 1, n = 16: σ_Δ = √(17/16).
        let (m1, noise, n) = (10.0, 1.0, 16.0);
        let s = (17.0f32 / 16.0).sqrt();
        assert_eq!(temporal_change(10.0 + 3.9 * s, m1, noise, n), 0.0, "within the noise");
        let half = temporal_change(10.0 + 6.0 * s, m1, noise, n);
        assert!((half - 0.5).abs() < 0.03, "{half}");
        assert_eq!(temporal_change(10.0 - 9.0 * s, m1, noise, n), 1.0, "a change, either way");
        assert_eq!(temporal_change(1e6, m1, noise, 7.0), 0.0, "too short to judge");
        // A noise-free history responds to a 1% change, not to rounding.
        assert_eq!(temporal_change(1.000_001, 1.0, 0.0, 32.0), 0.0);
        assert_eq!(temporal_change(1.01, 1.0, 0.0, 32.0), 1.0);
        assert!(temporal_change(0.0, 0.0, 0.0, 32.0) == 0.0);
    }

    /// The noise estimate of i.i.d. frames is their variance, and a steady
    /// drift hardly raises it.
    #[test]
    fn noise_estimate_of_consecutive_differences() {
        let mut h = (0.0f32, 0.0f32, 0.0f32); // last, noise, len
        let mut state = 12345u32;
        for k in 0..4000 {
            state = crate::xi::pcg_hash(state);
            // Uniform noise of variance 1/12 on a drift of 1e-3 per frame.
            let x = crate::xi::xi_from_bits(state) + 1e-3 * k as f32;
            let len = (h.2 + 1.0).min(32.0);
            let m = temporal_moments(Vec3::splat(x), h.0, h.1, h.2, len, 1.0);
            h = (m.x, m.y, len);
        }
        // 32-frame moving average: relative spread about 1/√16.
        assert!((h.1 * 12.0 - 1.0).abs() < 0.6, "{}", h.1 * 12.0);
        assert_eq!(
            temporal_moments(Vec3::ONE, 0.0, 0.0, 0.0, 1.0, 2.0),
            glam::Vec4::new(1.0, 0.0, 2.0, 0.0)
        );
    }

    #[test]
    fn history_length_and_weight() {
        assert_eq!(next_history_length(0.0, 0.0, 32.0), 1.0);
        assert_eq!(next_history_length(7.0, 0.0, 32.0), 8.0);
        assert_eq!(next_history_length(32.0, 0.0, 32.0), 32.0);
        assert_eq!(next_history_length(20.0, 1.0, 32.0), 1.0);
        assert_eq!(next_history_length(20.0, 0.5, 32.0), 11.0);
        assert_eq!(next_history_length(5.0, 0.0, 0.0), 1.0, "a cap below 1 means no history");
        // The running mean: after frames 1..=4 the weights 1, 1/2, 1/3, 1/4
        // give the plain mean.
        let mut m = 0.0;
        for (k, x) in [3.0f32, 5.0, 10.0, 2.0].iter().enumerate() {
            m += (x - m) * temporal_alpha(k as f32 + 1.0);
        }
        assert!((m - 5.0).abs() < 1e-6);
    }

    #[test]
    fn accumulation_step() {
        use glam::Vec4;
        // No history: the current value, length 1, moments of it alone.
        let c = Vec3::new(2.0, 1.0, 0.5);
        let first = temporal_color(c, Vec4::ZERO, 0.0, 0.0, 32.0);
        assert_eq!(first, c.extend(1.0));
        let l = luminance(c);
        assert_eq!(temporal_moments(c, 0.0, 0.0, 0.0, 1.0, 3.0), Vec4::new(l, 0.0, 3.0, 0.0));
        // Three frames of history: the mean of four.
        let h = Vec3::splat(1.0).extend(3.0);
        let v = temporal_color(Vec3::splat(5.0), h, 1.0, 1.0, 32.0);
        assert_eq!(v, Vec4::new(2.0, 2.0, 2.0, 4.0));
        // A long history (σ = 1 about a mean of 1): a lone outlier at 20σ
        // enters the mean with weight 1/n; when last frame was high too,
        // the history is dropped.
        let h = Vec3::splat(1.0).extend(31.0);
        assert_eq!(
            temporal_color(Vec3::splat(21.0), h, 1.0, 1.0, 32.0),
            Vec4::new(1.625, 1.625, 1.625, 32.0)
        );
        assert_eq!(
            temporal_color(Vec3::splat(21.0), h, 1.0, 21.0, 32.0),
            Vec4::new(21.0, 21.0, 21.0, 1.0)
        );
        assert_eq!(
            persistent_change(21.0, -19.0, 1.0, 1.0, 31.0),
            0.0,
            "deviations to opposite sides are noise"
        );
        // A tap without history or of another surface weighs nothing.
        let (n, p) = (Vec3::Z, Vec3::Z);
        assert_eq!(history_tap_weight(0.25, n, n, p, 1.0, 1.0, 0.0), 0.0);
        assert_eq!(history_tap_weight(0.25, n, -n, p, 1.0, 1.0, 3.0), 0.0);
        assert_eq!(history_tap_weight(0.25, n, n, p, 1.0, 1.0, 3.0), 0.25);
        // By motion vectors: distances from each frame's eye within 5%.
        assert_eq!(history_tap_weight_motion(0.25, n, n, 2.0, 2.08, 3.0), 0.25);
        assert_eq!(history_tap_weight_motion(0.25, n, n, 2.0, 2.2, 3.0), 0.0);
        // The four taps of (9.25, 3.5): pixels, weights, inside the image;
        // none behind the camera, none past the edge.
        let q = Vec3::new(9.25, 3.5, 1.0);
        let taps: alloc::vec::Vec<Vec4> = (0..4).map(|k| history_tap(q, k, 10.0, 8.0)).collect();
        assert_eq!(taps[0], Vec4::new(9.0, 3.0, 0.375, 1.0));
        assert_eq!(taps[3], Vec4::new(10.0, 4.0, 0.125, 0.0), "x = 10 is past the edge");
        assert!((0..4).all(|k| history_tap(Vec3::new(2.0, 2.0, -1.0), k, 10.0, 8.0).w == 0.0));
        assert_eq!(history_mean(Vec4::splat(2.0), 0.5), Vec4::splat(4.0));
        assert_eq!(history_mean(Vec4::splat(2.0), 0.001), Vec4::ZERO);
    }
}
