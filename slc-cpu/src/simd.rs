//! Runtime CPU-feature dispatch of the hot loops (the VPL shading loop and
//! the denoise): each is compiled three times, for AVX-512 (x86-64-v4),
//! AVX2 + FMA (x86-64-v3) and the baseline of the build target, and the
//! best path the CPU has is chosen once, at first use. The target-feature
//! wrappers are pulp's ([`pulp::x86::V4`], [`pulp::x86::V3`]), so a shipped
//! binary needs no global `-C target-cpu` and no `unsafe` here.
//!
//! The paths compute the same formulas; their results differ only by the
//! order of float additions (lane counts), a few ulps per sum.

use std::sync::OnceLock;

/// The path [`SimdPath::best`] returns, chosen once.
static BEST: OnceLock<SimdPath> = OnceLock::new();

/// An instruction set a hot loop runs on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SimdPath {
    /// AVX-512 F/VL/BW/DQ/CD (x86-64-v4).
    Avx512,
    /// AVX2 with FMA (x86-64-v3).
    Avx2,
    /// The build target's baseline (SSE2 on x86-64).
    Baseline,
}

impl SimdPath {
    /// Every path, best first.
    pub const ALL: [SimdPath; 3] = [SimdPath::Avx512, SimdPath::Avx2, SimdPath::Baseline];

    /// `true` when this CPU can run the path.
    pub fn is_available(self) -> bool {
        match self {
            #[cfg(target_arch = "x86_64")]
            SimdPath::Avx512 => pulp::x86::V4::is_available(),
            #[cfg(target_arch = "x86_64")]
            SimdPath::Avx2 => pulp::x86::V3::is_available(),
            SimdPath::Baseline => true,
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }

    /// The paths this CPU can run, best first.
    pub fn available() -> Vec<SimdPath> {
        Self::ALL.into_iter().filter(|p| p.is_available()).collect()
    }

    /// The best path this CPU has, detected once (or the one
    /// [`SimdPath::prefer`] chose first).
    pub fn best() -> SimdPath {
        *BEST.get_or_init(Self::detect)
    }

    /// The best path this CPU has.
    fn detect() -> SimdPath {
        Self::ALL.into_iter().find(|p| p.is_available()).unwrap_or(SimdPath::Baseline)
    }

    /// Makes `path` the one [`SimdPath::best`] returns for the rest of the
    /// process, where the CPU has it and no hot loop has run yet (to
    /// measure a lower instruction set on a machine that has a higher
    /// one: `slc bench --simd avx2`). Returns the path in effect, which is
    /// `path` only when both hold.
    pub fn prefer(path: SimdPath) -> SimdPath {
        *BEST.get_or_init(|| if path.is_available() { path } else { Self::detect() })
    }

    /// The path named `name` ([`SimdPath::name`]).
    pub fn from_name(name: &str) -> Option<SimdPath> {
        Self::ALL.into_iter().find(|p| p.name() == name)
    }

    /// Short name: `avx512`, `avx2` or `baseline`.
    pub fn name(self) -> &'static str {
        match self {
            SimdPath::Avx512 => "avx512",
            SimdPath::Avx2 => "avx2",
            SimdPath::Baseline => "baseline",
        }
    }

    /// Runs `op` compiled for this path (the baseline where the CPU lacks
    /// it). `op`'s `with_simd` must be `#[inline(always)]` and inline its
    /// loop, so the loop is compiled with the path's target features.
    #[inline(always)]
    pub(crate) fn run<Op: pulp::WithSimd>(self, op: Op) -> Op::Output {
        #[cfg(target_arch = "x86_64")]
        match self {
            SimdPath::Avx512 => {
                if let Some(simd) = pulp::x86::V4::try_new() {
                    return pulp::Simd::vectorize(simd, op);
                }
            }
            SimdPath::Avx2 => {
                if let Some(simd) = pulp::x86::V3::try_new() {
                    return pulp::Simd::vectorize(simd, op);
                }
            }
            SimdPath::Baseline => {}
        }
        pulp::Simd::vectorize(pulp::Scalar::new(), op)
    }
}

impl std::fmt::Display for SimdPath {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}
