//! Path-tracing steps both backends take the same way: the camera ray
//! through a pixel, and Russian roulette on path length.

use crate::wgsl::*;

crate::shared! {
    /// Unit direction of the pinhole camera ray through image point
    /// `(px, py)` (pixel units, y down; pixel centres at `+0.5`) of a
    /// `w × h` image: `normalize(f + sx·r + sy·u)` with
    /// `sx = 2px/w − 1`, `sy = 1 − 2py/h`, where `r` and `u` are the right
    /// and up vectors already scaled by `tan(fov/2)·aspect` and `tan(fov/2)`.
    pub fn camera_dir(forward: vec3f, right: vec3f, up: vec3f, px: f32, py: f32, w: f32, h: f32) -> vec3f {
        let sx: f32 = 2.0 * px / w - 1.0;
        let sy: f32 = 1.0 - 2.0 * py / h;
        return normalize(forward + right * sx + up * sy);
    }

    /// Image coordinate of a pixel sample: pixel `coord` (row or column)
    /// plus a uniform `u ∈ [0, 1)` across it (`u = ½` is its centre).
    pub fn jittered_pixel(coord: u32, u: f32) -> f32 {
        return to_f32(coord) + u;
    }

    /// Russian roulette on path length starts at this depth (the third
    /// bounce; depth 0 is the camera ray's hit).
    pub const ROULETTE_DEPTH: u32 = 2;

    /// `true` when the path plays Russian roulette after the bounce at
    /// `depth`.
    pub fn plays_roulette(depth: u32) -> bool {
        return depth >= ROULETTE_DEPTH;
    }

    /// `true` when a ray along `dir` sees the emission of a surface with
    /// geometric normal `gn`: emitters are one-sided, like the triangle
    /// lights, and shine to the side `gn` points to.
    pub fn sees_emission(gn: vec3f, dir: vec3f) -> bool {
        return dot(gn, dir) < 0.0;
    }

    /// `true` when a sampled direction `nd` continues the path: above the
    /// shading normal `n` and above the surface itself (`ng`, facing the
    /// incoming ray); a direction below either ends it.
    pub fn continues_path(nd: vec3f, n: vec3f, ng: vec3f) -> bool {
        return dot(nd, n) > 0.0 && dot(nd, ng) > 0.0;
    }

    /// Survival probability of Russian roulette on path length for
    /// throughput `beta`: its largest channel, clamped to `[0.05, 0.95]`
    /// (a survivor's throughput is divided by it).
    pub fn path_survival(beta: vec3f) -> f32 {
        return clamp(max(max(beta.x, beta.y), beta.z), 0.05, 0.95);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centre_pixel_looks_forward_and_survival_is_clamped() {
        let f = vec3f(0.0, 0.0, 1.0);
        let d = camera_dir(f, vec3f(0.5, 0.0, 0.0), vec3f(0.0, 0.5, 0.0), 32.0, 16.0, 64.0, 32.0);
        assert!((d - f).length() < 1e-6);
        // The left edge of the image: sx = −1, the direction leans by atan(0.5).
        let e = camera_dir(f, vec3f(0.5, 0.0, 0.0), vec3f(0.0, 0.5, 0.0), 0.0, 16.0, 64.0, 32.0);
        assert!((e.x / e.z + 0.5).abs() < 1e-6);
        assert_eq!(path_survival(vec3f(0.0, 0.0, 0.0)), 0.05);
        assert_eq!(path_survival(vec3f(0.3, 2.0, 0.1)), 0.95);
        assert_eq!(path_survival(vec3f(0.3, 0.5, 0.1)), 0.5);
    }
}
