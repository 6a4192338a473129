//! The LM-63 parser on arbitrary bytes: never panics or hangs; what it
//! accepts evaluates to finite, non-negative candela no larger than its peak.
#![no_main]

use libfuzzer_sys::fuzz_target;
use slc_core::ies::IesProfile;

fuzz_target!(|data: &[u8]| {
    let Ok(p) = IesProfile::parse_bytes(data) else { return };
    let peak = p.max_candela();
    assert!(peak.is_finite() && peak >= 0.0, "peak {peak}");
    for g in (-10..=190).step_by(5) {
        for c in (-400..=800).step_by(37) {
            let v = p.candela_at(g as f32, c as f32);
            assert!(
                v.is_finite() && v >= 0.0 && v <= peak * (1.0 + 1e-6) + 1e-30,
                "γ {g} C {c}: {v} (peak {peak})"
            );
        }
    }
    for x in [f32::NAN, f32::INFINITY, -f32::INFINITY, f32::MAX, -0.0] {
        let v = p.candela_at(x, x);
        assert!(!(v < 0.0) && !v.is_infinite(), "{v}");
    }
});
