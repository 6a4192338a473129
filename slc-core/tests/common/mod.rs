//! Test helpers shared by slc-core's integration tests.
#![allow(dead_code)]

use std::path::PathBuf;

/// `assert_approx_eq!(a, b, tol)`: `|a − b| ≤ tol`, with both values in the
/// message.
#[macro_export]
macro_rules! assert_approx_eq {
    ($a:expr, $b:expr, $tol:expr) => {{
        let (a, b, tol) = ($a as f64, $b as f64, $tol as f64);
        assert!((a - b).abs() <= tol, "assert_approx_eq failed: {} vs {} (|diff| {} > tol {})", a, b, (a - b).abs(), tol);
    }};
    ($a:expr, $b:expr, $tol:expr, $($msg:tt)+) => {{
        let (a, b, tol) = ($a as f64, $b as f64, $tol as f64);
        assert!((a - b).abs() <= tol, "{}: {} vs {} (|diff| {} > tol {})", format!($($msg)+), a, b, (a - b).abs(), tol);
    }};
}

/// `../shared/data/<rel>` from the workspace root. Returns `None` (and says
/// so) when the data is absent on a developer machine; fails under `CI`.
pub fn shared_data(rel: &str) -> Option<PathBuf> {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/data").join(rel);
    if p.exists() {
        return Some(p);
    }
    if std::env::var_os("CI").is_some() {
        panic!("test data {} is missing (CI must have ../shared beside the checkout)", p.display());
    }
    eprintln!("skipping: test data {} not found", p.display());
    None
}
