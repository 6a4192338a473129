//! Rust definitions of the WGSL built-ins (and the few helpers that stand in
//! for casts and wrapping arithmetic) that shared code calls, with WGSL's
//! semantics: shared code written against these compiles as Rust and, token
//! for token, as WGSL.

use glam::Vec3;

/// Rust spelling of WGSL's `vec2f`.
#[allow(non_camel_case_types)]
pub type vec2f = glam::Vec2;

/// WGSL's `vec2f(x, y)` constructor.
#[inline]
pub fn vec2f(x: f32, y: f32) -> glam::Vec2 {
    glam::Vec2::new(x, y)
}

/// Rust spelling of WGSL's `vec3f`.
#[allow(non_camel_case_types)]
pub type vec3f = Vec3;

/// WGSL's `vec3f(x, y, z)` constructor.
#[inline]
pub fn vec3f(x: f32, y: f32, z: f32) -> Vec3 {
    Vec3::new(x, y, z)
}

/// Rust spelling of WGSL's `vec4f`.
#[allow(non_camel_case_types)]
pub type vec4f = glam::Vec4;

/// WGSL's `vec4f(x, y, z, w)` constructor.
#[inline]
pub fn vec4f(x: f32, y: f32, z: f32, w: f32) -> glam::Vec4 {
    glam::Vec4::new(x, y, z, w)
}

/// Rust spelling of WGSL's `vec3u`.
#[allow(non_camel_case_types)]
pub type vec3u = glam::UVec3;

/// WGSL's `vec3u(x, y, z)` constructor.
#[inline]
pub fn vec3u(x: u32, y: u32, z: u32) -> glam::UVec3 {
    glam::UVec3::new(x, y, z)
}

/// Rust spelling of WGSL's `vec4u`.
#[allow(non_camel_case_types)]
pub type vec4u = glam::UVec4;

/// A read-only table of `f32` indexed with `u32`: a slice on the CPU. In WGSL
/// the same parameter is a dummy `u32` and [`at`] reads the module-scope
/// storage buffer `slc_table` (see [`PRELUDE`](super::PRELUDE)).
pub type Table<'a> = &'a [f32];

/// `tab[i]`, or `0.0` outside the table (WGSL's robust-access behaviour is
/// also a clamped or zero read, never a fault).
#[inline]
pub fn at(tab: Table, i: u32) -> f32 {
    match tab.get(i as usize) {
        Some(v) => *v,
        None => 0.0,
    }
}

/// WGSL's `f32(u)`.
#[inline]
pub fn to_f32(u: u32) -> f32 {
    u as f32
}

/// WGSL's `u32(x)` for `x` in `[0, 2³²)`; saturates outside (Rust `as` and
/// WGSL's conversion agree on that range, which is all shared code uses).
#[inline]
pub fn to_u32(x: f32) -> u32 {
    x as u32
}

/// WGSL's `bitcast<f32>(u)`.
#[inline]
pub fn f32_from_bits(u: u32) -> f32 {
    f32::from_bits(u)
}

/// WGSL's `bitcast<u32>(x)`.
#[inline]
pub fn f32_to_bits(x: f32) -> u32 {
    x.to_bits()
}

/// Low 32 bits of `a · b` (WGSL's `u32` multiply wraps).
#[inline]
pub fn mul_lo_u32(a: u32, b: u32) -> u32 {
    a.wrapping_mul(b)
}

/// `a + b` modulo 2³² (WGSL's `u32` add wraps).
#[inline]
pub fn add_wrap_u32(a: u32, b: u32) -> u32 {
    a.wrapping_add(b)
}

/// Types WGSL's `min`/`max`/`clamp`/`select` accept in shared code.
pub trait WgslScalar: Copy {
    /// WGSL `min`.
    fn wmin(self, o: Self) -> Self;
    /// WGSL `max`.
    fn wmax(self, o: Self) -> Self;
}
impl WgslScalar for f32 {
    #[inline]
    fn wmin(self, o: Self) -> Self {
        f32::min(self, o)
    }
    #[inline]
    fn wmax(self, o: Self) -> Self {
        f32::max(self, o)
    }
}
impl WgslScalar for u32 {
    #[inline]
    fn wmin(self, o: Self) -> Self {
        if self < o { self } else { o }
    }
    #[inline]
    fn wmax(self, o: Self) -> Self {
        if self > o { self } else { o }
    }
}
impl WgslScalar for Vec3 {
    #[inline]
    fn wmin(self, o: Self) -> Self {
        vec3f(self.x.wmin(o.x), self.y.wmin(o.y), self.z.wmin(o.z))
    }
    #[inline]
    fn wmax(self, o: Self) -> Self {
        vec3f(self.x.wmax(o.x), self.y.wmax(o.y), self.z.wmax(o.z))
    }
}

/// WGSL `min` (component-wise on vectors).
#[inline]
pub fn min<T: WgslScalar>(a: T, b: T) -> T {
    a.wmin(b)
}
/// WGSL `max` (component-wise on vectors).
#[inline]
pub fn max<T: WgslScalar>(a: T, b: T) -> T {
    a.wmax(b)
}
/// WGSL `clamp(e, lo, hi) = min(max(e, lo), hi)`; never panics for `lo > hi`.
#[inline]
pub fn clamp<T: WgslScalar>(e: T, lo: T, hi: T) -> T {
    e.wmax(lo).wmin(hi)
}
/// WGSL `select(f, t, cond)`.
#[inline]
pub fn select<T>(f: T, t: T, cond: bool) -> T {
    if cond { t } else { f }
}
/// WGSL `dot`.
#[inline]
pub fn dot(a: Vec3, b: Vec3) -> f32 {
    a.x * b.x + a.y * b.y + a.z * b.z
}
/// WGSL `cross`.
#[inline]
pub fn cross(a: Vec3, b: Vec3) -> Vec3 {
    a.cross(b)
}
/// WGSL `normalize`.
#[inline]
pub fn normalize(v: Vec3) -> Vec3 {
    v / sqrt(dot(v, v))
}
/// WGSL `sqrt`.
#[inline]
pub fn sqrt(x: f32) -> f32 {
    libm::sqrtf(x)
}
/// WGSL `pow` (`x ≥ 0`).
#[inline]
pub fn pow(x: f32, y: f32) -> f32 {
    libm::powf(x, y)
}
/// WGSL `exp2`.
#[inline]
pub fn exp2(x: f32) -> f32 {
    libm::exp2f(x)
}
/// WGSL `floor`.
#[inline]
pub fn floor(x: f32) -> f32 {
    libm::floorf(x)
}
/// WGSL `abs`.
#[inline]
pub fn abs(x: f32) -> f32 {
    libm::fabsf(x)
}
/// WGSL `acos`.
#[inline]
pub fn acos(x: f32) -> f32 {
    libm::acosf(x)
}
/// WGSL `atan2(y, x)`.
#[inline]
pub fn atan2(y: f32, x: f32) -> f32 {
    libm::atan2f(y, x)
}
/// WGSL `cos`.
#[inline]
pub fn cos(x: f32) -> f32 {
    libm::cosf(x)
}
/// WGSL `sin`.
#[inline]
pub fn sin(x: f32) -> f32 {
    libm::sinf(x)
}
/// WGSL `degrees`.
#[inline]
pub fn degrees(rad: f32) -> f32 {
    rad * (180.0 / core::f32::consts::PI)
}
/// WGSL `saturate`.
#[inline]
pub fn saturate(x: f32) -> f32 {
    clamp(x, 0.0, 1.0)
}
