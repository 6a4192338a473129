//! # slc-tests
//!
//! Cross-backend tests of slc: the GPU (wgpu, kernels from
//! slc-shared-shaders) against the CPU (rayon), on the same inputs with the
//! same ξ. Each test file runs through [`harness!`] (libtest-mimic, as
//! wgpu's own test crate does), which declares what every test needs:
//! without a GPU adapter the GPU tests show as **ignored**, with the reason
//! printed once, and `cargo test -- --ignored` fails them with that reason
//! rather than passing them empty; under `SLC_REQUIRE_GPU=1` (CI, on Mesa's
//! lavapipe) they fail instead.
//!
//! ```
//! // The property the parity tests check on both backends, shown on the CPU:
//! // a light at d² = 1.5 with r_t² = 1 survives for ξ = 0.5 (r² = 2).
//! use slc_core::range::{random_range2, slc_keep};
//! assert!(slc_keep(random_range2(1.0, 0.5), 1.5));
//! ```
#![deny(missing_docs)]

use std::sync::OnceLock;

pub mod direct;
pub mod engine;
pub mod vpl;

/// The shared GPU context once made, or why there is none.
static CTX: OnceLock<Result<slc_wgpu::GpuContext, String>> = OnceLock::new();

/// The shared GPU context, or why there is none.
fn context() -> &'static Result<slc_wgpu::GpuContext, String> {
    CTX.get_or_init(|| {
        let r = slc_wgpu::GpuContext::new().map_err(|e| e.to_string());
        if let Ok(c) = &r {
            eprintln!("GPU tests run on: {}", c.describe());
        }
        r
    })
}

/// The shared context opened with wgpu's ray queries, or why there is
/// none (no adapter, or one without `EXPERIMENTAL_RAY_QUERY`).
static RQ_CTX: OnceLock<Result<slc_wgpu::GpuContext, String>> = OnceLock::new();

fn ray_query_context() -> &'static Result<slc_wgpu::GpuContext, String> {
    RQ_CTX.get_or_init(|| {
        let options = slc_wgpu::GpuOptions { ray_query: true };
        match slc_wgpu::GpuContext::with_options(&options) {
            Ok(c) if c.ray_query => {
                eprintln!("ray-query tests run on: {}", c.describe());
                Ok(c)
            }
            Ok(c) => Err(format!(
                "{} has no ray queries (wgpu's EXPERIMENTAL_RAY_QUERY; Mesa 25's lavapipe has: tools/lavapipe-ray-query.sh)",
                c.describe()
            )),
            Err(e) => Err(e.to_string()),
        }
    })
}

/// The shared context with ray queries, for tests declared
/// [`Needs::RayQuery`] (which [`run`] starts only when it exists).
///
/// # Panics
/// Without one: the calling test is not declared [`Needs::RayQuery`].
pub fn ray_query_gpu() -> Option<&'static slc_wgpu::GpuContext> {
    match ray_query_context() {
        Ok(c) => Some(c),
        Err(e) => panic!("this test uses ray queries but is not declared Needs::RayQuery ({e})"),
    }
}

/// The shared GPU context, for tests declared [`Needs::Gpu`] (which
/// [`run`] starts only when an adapter exists). Always `Some`: the
/// `Option` keeps call sites short.
///
/// # Panics
/// Without an adapter: the calling test uses the GPU but is not declared
/// [`Needs::Gpu`], and must not pass without running.
pub fn gpu() -> Option<&'static slc_wgpu::GpuContext> {
    match context() {
        Ok(c) => Some(c),
        Err(e) => panic!("this test uses the GPU but is not declared Needs::Gpu (no adapter: {e})"),
    }
}

/// What a test needs to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Needs {
    /// Nothing but the CPU.
    Cpu,
    /// A GPU adapter (a real GPU or lavapipe).
    Gpu,
    /// A GPU adapter and a display to open a window on: `DISPLAY` or
    /// `WAYLAND_DISPLAY`, else `xvfb-run` on the `PATH` ([`windowed`] runs
    /// the program under it). Without one the test shows as ignored;
    /// under `SLC_REQUIRE_DISPLAY=1` (CI, which installs Xvfb) it fails.
    Display,
    /// A GPU adapter with wgpu's experimental ray queries
    /// ([`ray_query_gpu`]). Without one the test shows as ignored; under
    /// `SLC_REQUIRE_RAY_QUERY=1` (CI's run on Mesa 25's lavapipe,
    /// `tools/lavapipe-ray-query.sh`) it fails.
    RayQuery,
}

/// Why no window can be opened here, or `None` when a display exists or
/// `xvfb-run` can make one.
fn display_missing() -> Option<String> {
    if display_set() || xvfb_run().is_some() {
        return None;
    }
    Some("no DISPLAY or WAYLAND_DISPLAY, and no xvfb-run on the PATH (apt-get install xvfb)".into())
}

/// `true` when `DISPLAY` or `WAYLAND_DISPLAY` names a display.
fn display_set() -> bool {
    ["DISPLAY", "WAYLAND_DISPLAY"]
        .iter()
        .any(|k| std::env::var_os(k).is_some_and(|v| !v.is_empty()))
}

/// `xvfb-run` on the `PATH`, if any.
fn xvfb_run() -> Option<std::path::PathBuf> {
    std::env::split_paths(&std::env::var_os("PATH")?)
        .map(|d| d.join("xvfb-run"))
        .find(|p| p.is_file())
}

/// A command running `program` with a window: directly where a display is
/// set, else under `xvfb-run -a` (a 1024×768 virtual screen).
pub fn windowed(program: &std::path::Path) -> std::process::Command {
    match xvfb_run().filter(|_| !display_set()) {
        Some(xvfb) => {
            let mut c = std::process::Command::new(xvfb);
            c.args(["-a", "-s", "-screen 0 1024x768x24"]).arg(program);
            c
        }
        None => std::process::Command::new(program),
    }
}

/// Why no GPU test can run here, or `None` when an adapter exists.
fn gpu_missing() -> Option<String> {
    context().as_ref().err().cloned()
}

/// Runs a test file's tests as libtest would (filters, `--list`,
/// `--ignored`, threads), each `(name, needs, test)`. GPU tests without an
/// adapter are ignored with the reason printed once; run anyway
/// (`--ignored`) they fail with it; under `SLC_REQUIRE_GPU=1` they fail.
/// Window tests ([`Needs::Display`]) need a display too: without one they
/// are ignored the same way, and fail under `SLC_REQUIRE_DISPLAY=1`.
pub fn run(tests: &[(&'static str, Needs, fn())]) -> std::process::ExitCode {
    let args = libtest_mimic::Arguments::from_args();
    let on_gpu = |n: Needs| matches!(n, Needs::Gpu | Needs::Display);
    let missing = if tests.iter().any(|t| on_gpu(t.1)) { gpu_missing() } else { None };
    let required = std::env::var("SLC_REQUIRE_GPU").as_deref() == Ok("1");
    if let Some(reason) = &missing {
        if required {
            eprintln!("SLC_REQUIRE_GPU=1, so the GPU tests fail: {reason}");
        } else {
            let n = tests.iter().filter(|t| on_gpu(t.1)).count();
            eprintln!("{n} GPU test(s) ignored: {reason}");
        }
    }
    let no_display =
        if tests.iter().any(|t| t.1 == Needs::Display) { display_missing() } else { None };
    let no_ray_query = if tests.iter().any(|t| t.1 == Needs::RayQuery) {
        ray_query_context().as_ref().err().cloned()
    } else {
        None
    };
    let ray_query_required = std::env::var("SLC_REQUIRE_RAY_QUERY").as_deref() == Ok("1");
    if let Some(reason) = &no_ray_query {
        let n = tests.iter().filter(|t| t.1 == Needs::RayQuery).count();
        let verb = if ray_query_required { "fail (SLC_REQUIRE_RAY_QUERY=1)" } else { "ignored" };
        eprintln!("{n} ray-query test(s) {verb}: {reason}");
    }
    let display_required = std::env::var("SLC_REQUIRE_DISPLAY").as_deref() == Ok("1");
    if let Some(reason) = &no_display {
        let n = tests.iter().filter(|t| t.1 == Needs::Display).count();
        let verb = if display_required { "fail (SLC_REQUIRE_DISPLAY=1)" } else { "ignored" };
        eprintln!("{n} window test(s) {verb}: {reason}");
    }
    let trials = tests
        .iter()
        .map(|&(name, needs, test)| {
            // The test's kind, and why it cannot run here with whether
            // that fails it (else it shows as ignored).
            let skip = |reason: &Option<String>, what: &str, fails: bool| {
                reason.as_ref().map(|r| (format!("needs {what}: {r}"), fails))
            };
            let (kind, skip) = match needs {
                Needs::Cpu => (None, None),
                Needs::RayQuery => {
                    (Some("ray query"), skip(&no_ray_query, "ray queries", ray_query_required))
                }
                Needs::Gpu | Needs::Display if missing.is_some() => {
                    (Some("gpu"), skip(&missing, "a GPU adapter", required))
                }
                Needs::Gpu => (Some("gpu"), None),
                Needs::Display => {
                    (Some("window"), skip(&no_display, "a display", display_required))
                }
            };
            let trial = match skip {
                Some((why, fails)) => libtest_mimic::Trial::test(name, move || Err(why.into()))
                    .with_ignored_flag(!fails),
                None => libtest_mimic::Trial::test(name, move || {
                    test();
                    Ok(())
                }),
            };
            match kind {
                Some(k) => trial.with_kind(k),
                None => trial,
            }
        })
        .collect();
    let conclusion = libtest_mimic::run(&args, trials);
    // Exit with no GPU work in flight: a short test binary leaving
    // lavapipe busy crashed in the process's exit handlers about 1 run in
    // 30 after every test had passed.
    for ctx in [CTX.get(), RQ_CTX.get()] {
        if let Some(Ok(gpu)) = ctx {
            gpu.wait().ok();
        }
    }
    conclusion.exit_code()
}

/// The `main` of a test file: `harness!(Cpu: parses, Gpu: shades_like_cpu);`
/// runs the named functions through [`run`].
#[macro_export]
macro_rules! harness {
    ($($needs:ident: $test:ident),* $(,)?) => {
        fn main() -> std::process::ExitCode {
            $crate::run(&[$((stringify!($test), $crate::Needs::$needs, $test as fn())),*])
        }
    };
}

/// A file under `../shared/data` beside the checkout (panics when it is
/// missing; see [`slc_test_data::shared_data`]).
pub use slc_test_data::shared_data;
