//! # slc-test-data
//!
//! The one place slc's tests (slc-core's, slc-cpu's, the cross-backend
//! tests and slc-cli's) find the team's shared data: the Cornell box, the
//! bunny and the IES files in `../shared/data/` beside the checkout, never
//! copied into the repository. No dependencies, so every crate can use it
//! as a dev-dependency without a cycle.
#![deny(missing_docs)]

use std::path::PathBuf;

/// `../shared/data/<rel>` beside the checkout.
///
/// # Panics
/// When it is missing: missing test data is a failure, never a silent
/// downgrade of what a test covers.
pub fn shared_data(rel: &str) -> PathBuf {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/data").join(rel);
    assert!(
        p.exists(),
        "test data {} is missing: the tests need ../shared (the team data) beside the checkout",
        p.display()
    );
    p
}
