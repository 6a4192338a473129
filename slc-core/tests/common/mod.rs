//! Test helpers shared by slc-core's integration tests.
#![allow(dead_code)]

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

#[allow(unused_imports)]
pub use slc_test_data::shared_data;
