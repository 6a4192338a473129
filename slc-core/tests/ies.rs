//! LM-63 parsing of the real files in `../shared/data/ies/`, the horizontal
//! symmetries, and hostile input.

#[macro_use]
mod common;

use slc_core::IesErrorKind;
use slc_core::ies::{IesFormat, IesProfile, PhotometricType, Tilt};

const FILES: [&str; 5] = [
    "absolute-led.ies",
    "floodlight-12w-54deg.ies",
    "indoor-60w-120deg.ies",
    "outdoor-roadway-60w.ies",
    "tilt-include-synthetic.ies",
];

fn load(name: &str) -> (Vec<u8>, IesProfile) {
    let path = common::shared_data(&format!("ies/{name}"));
    let bytes = std::fs::read(&path).unwrap();
    let p = IesProfile::parse_bytes(&bytes).unwrap_or_else(|e| panic!("{name}: {e}"));
    (bytes, p)
}

#[test]
fn every_shared_file_parses_and_evaluates_finite() {
    for name in FILES {
        let (_, p) = load(name);
        assert_eq!(p.candela.len(), p.vertical.len() * p.horizontal.len(), "{name}");
        assert!(p.max_candela() > 0.0 && p.max_candela().is_finite(), "{name}");
        for g in 0..=180 {
            for c in (-360..=720).step_by(7) {
                let v = p.candela_at(g as f32, c as f32);
                assert!(
                    v.is_finite() && v >= 0.0 && v <= p.max_candela() * 1.000_001,
                    "{name} γ{g} C{c}: {v}"
                );
            }
        }
        let flux = p.total_flux();
        assert!(flux.is_finite() && flux > 0.0, "{name}: {flux}");
    }
}

#[test]
fn header_facts() {
    let (_, abs) = load("absolute-led.ies");
    assert_eq!(abs.format, IesFormat::Lm63_2002);
    assert_eq!(abs.lumens_per_lamp, -1.0);
    assert_eq!(abs.photometric_type, PhotometricType::C);
    assert_eq!((abs.vertical.len(), abs.horizontal.len()), (19, 37));
    assert_eq!(abs.max_candela(), 3500.0);
    assert_eq!(abs.candela_at(0.0, 123.0), 3500.0);
    // Bilinear between 3500 (0°) and 3450 (5°).
    assert_approx_eq!(abs.candela_at(2.5, 0.0), 3475.0, 1e-3);
    assert_eq!(abs.candela_at(91.0, 0.0), 0.0, "outside the 0–90° vertical range");

    let (_, tilt) = load("tilt-include-synthetic.ies");
    assert_eq!(
        tilt.tilt,
        Tilt::Include {
            geometry: 1,
            angles: vec![0.0, 45.0, 90.0, 180.0],
            factors: vec![1.0, 0.9, 0.8, 1.0]
        }
    );
    assert_eq!(tilt.horizontal, [0.0]);
    assert_approx_eq!(tilt.candela_at(33.75, 77.0), 800.0, 1e-3);

    let (_, road) = load("outdoor-roadway-60w.ies");
    assert_eq!(road.format, IesFormat::Lm63_1995);
    assert_eq!(road.vertical.len(), 361);

    let (_, indoor) = load("indoor-60w-120deg.ies");
    assert_eq!(indoor.horizontal.len(), 1);
    // Multiplier 0.4597 applied: I_max = 0.4597 × max raw candela.
    let raw_max = indoor.candela.iter().cloned().fold(0.0f32, f32::max);
    assert_approx_eq!(indoor.max_candela(), raw_max * 0.4597, raw_max * 1e-6);
}

#[test]
fn truncated_real_files_give_errors_not_panics() {
    for name in FILES {
        let (bytes, _) = load(name);
        // Cut at many places: must be Ok or a typed error with a line number.
        let step = (bytes.len() / 200).max(1);
        for cut in (0..bytes.len()).step_by(step) {
            if let Err(e) = IesProfile::parse_bytes(&bytes[..cut]) {
                assert!(e.line >= 1 || cut == 0, "{name}@{cut}: {e}");
                assert!(!e.to_string().is_empty());
            }
        }
    }
}

/// Builds a type C file with the given angles and a candela function.
fn synth(v: &[f32], h: &[f32], cd: impl Fn(f32, f32) -> f32) -> String {
    let mut s = format!(
        "IESNA:LM-63-2002\n[TEST] synth\nTILT=NONE\n1 1000 1 {} {} 1 2 0 0 0\n1 1 10\n",
        v.len(),
        h.len()
    );
    for a in v {
        s += &format!("{a} ");
    }
    s += "\n";
    for a in h {
        s += &format!("{a} ");
    }
    s += "\n";
    for &hh in h {
        for &vv in v {
            s += &format!("{} ", cd(vv, hh));
        }
        s += "\n";
    }
    s
}

#[test]
fn horizontal_symmetries() {
    let v = [0.0, 90.0, 180.0];
    // Candela depends on C only: cd = 100 + C.
    let f = |_: f32, c: f32| 100.0 + c;
    // Rotational: one plane.
    let p = IesProfile::parse(&synth(&v, &[0.0], f)).unwrap();
    for c in [0.0, 45.0, 200.0, -30.0] {
        assert_eq!(p.candela_at(45.0, c), 100.0);
    }
    // Quadrant 0–90: I(C) = I(180 − C) = I(360 − C).
    let p = IesProfile::parse(&synth(&v, &[0.0, 45.0, 90.0], f)).unwrap();
    assert_approx_eq!(p.candela_at(45.0, 30.0), 130.0, 1e-3);
    assert_approx_eq!(p.candela_at(45.0, 150.0), 130.0, 1e-3);
    assert_approx_eq!(p.candela_at(45.0, 210.0), 130.0, 1e-3);
    assert_approx_eq!(p.candela_at(45.0, 330.0), 130.0, 1e-3);
    assert_approx_eq!(p.candela_at(45.0, -30.0), 130.0, 1e-3);
    // Bilateral 0–180: I(C) = I(360 − C).
    let p = IesProfile::parse(&synth(&v, &[0.0, 90.0, 180.0], f)).unwrap();
    assert_approx_eq!(p.candela_at(45.0, 120.0), 220.0, 1e-3);
    assert_approx_eq!(p.candela_at(45.0, 240.0), 220.0, 1e-3);
    // Bilateral 90–270: I(C) = I(180 − C).
    let p = IesProfile::parse(&synth(&v, &[90.0, 180.0, 270.0], f)).unwrap();
    assert_approx_eq!(p.candela_at(45.0, 60.0), 220.0, 1e-3);
    assert_approx_eq!(p.candela_at(45.0, 120.0), 220.0, 1e-3);
    assert_approx_eq!(p.candela_at(45.0, 330.0), 310.0, 1e-3);
    assert_approx_eq!(p.candela_at(45.0, 210.0), 310.0, 1e-3);
    // Full 0–360.
    let p = IesProfile::parse(&synth(&v, &[0.0, 90.0, 180.0, 270.0, 360.0], f)).unwrap();
    assert_approx_eq!(p.candela_at(45.0, 300.0), 400.0, 1e-3);
    assert_approx_eq!(p.candela_at(45.0, -60.0), 400.0, 1e-3);
    // Full table without a 360° column wraps to 0°: C = 315 is halfway
    // between 270 (370 cd) and 360 ≡ 0 (100 cd).
    let p = IesProfile::parse(&synth(&v, &[0.0, 90.0, 180.0, 270.0], f)).unwrap();
    assert_approx_eq!(p.candela_at(45.0, 315.0), 235.0, 1e-3);
}

#[test]
fn hard_tables() {
    // A single angle in each direction: constant over its one vertical angle.
    let p = IesProfile::parse(&synth(&[0.0], &[0.0], |_, _| 7.0)).unwrap();
    assert_eq!(p.candela_at(0.0, 0.0), 7.0);
    assert_eq!(p.candela_at(10.0, 0.0), 0.0);
    assert_eq!(p.max_candela(), 7.0);
    // Zero candela everywhere: a valid profile with I_max = 0.
    let p = IesProfile::parse(&synth(&[0.0, 90.0], &[0.0, 180.0], |_, _| 0.0)).unwrap();
    assert_eq!(p.max_candela(), 0.0);
    assert_eq!(p.total_flux(), 0.0);
    // Non-monotonic angles: an error naming the line.
    let e = IesProfile::parse(&synth(&[0.0, 60.0, 30.0, 90.0], &[0.0], |_, _| 1.0)).unwrap_err();
    assert_eq!(e.kind, IesErrorKind::NotIncreasing { field: "vertical angles" });
    assert_eq!(e.line, 6);
    let e = IesProfile::parse(&synth(&[0.0, 90.0], &[0.0, 90.0, 45.0], |_, _| 1.0)).unwrap_err();
    assert_eq!(e.kind, IesErrorKind::NotIncreasing { field: "horizontal angles" });
    // A symmetry LM-63 does not define.
    let e = IesProfile::parse(&synth(&[0.0, 90.0], &[10.0, 90.0], |_, _| 1.0)).unwrap_err();
    assert!(matches!(e.kind, IesErrorKind::HorizontalRange { .. }));
}

#[test]
fn hostile_input() {
    type Expect = fn(&IesErrorKind) -> bool;
    let cases: [(&str, Expect); 7] = [
        ("", |k| *k == IesErrorKind::MissingTilt),
        ("IESNA:LM-63-2002\n[TEST] x\n", |k| *k == IesErrorKind::MissingTilt),
        ("IESNA:LM-63-2002\nTILT=NONE\n1 1000 1 2", |k| {
            matches!(k, IesErrorKind::UnexpectedEnd { .. })
        }),
        ("TILT=NONE\n1 1000 1 nan 1 1 2 0 0 0\n1 1 1\n0\n0\n1\n", |k| {
            matches!(k, IesErrorKind::BadNumber { .. })
        }),
        ("TILT=NONE\n1 1000 1 99999999 99999999 1 2 0 0 0\n1 1 1\n", |k| {
            matches!(k, IesErrorKind::OutOfRange { .. })
        }),
        ("TILT=NONE\n1 1000 1 2000 2000 1 2 0 0 0\n1 1 1\n0\n", |k| {
            matches!(k, IesErrorKind::UnexpectedEnd { .. })
        }),
        ("TILT=NONE\n1 1000 1 1 1 1 2 0 0 0\n1 1 1\n0\n0\n-5\n", |k| {
            matches!(k, IesErrorKind::OutOfRange { .. })
        }),
    ];
    for (text, ok) in cases {
        let e = IesProfile::parse(text).unwrap_err();
        assert!(ok(&e.kind), "{text:?} gave {e}");
    }
    // Regression (fuzz/ies_parse): a finite ballast factor of 3e36 times
    // 1000 cd overflowed the table to infinity.
    let e = IesProfile::parse("TILT=NONE\n1 1000 1 1 1 1 2 0 0 0\n3e36 1 10\n0\n0\n1000\n")
        .unwrap_err();
    assert!(
        matches!(
            e.kind,
            IesErrorKind::OutOfRange { field: "candela values times multipliers", .. }
        ),
        "{e}"
    );
    // Regression (fuzz/ies_parse): ballast factors 3e31 × 3e36 overflow the
    // scale itself, and a zero candela value times it was NaN, which the
    // peak (a max) skipped.
    let e = IesProfile::parse("TILT=NONE\n1 1000 1 1 1 1 2 0 0 0\n3e31 3e36 10\n0\n0\n0\n")
        .unwrap_err();
    assert!(
        matches!(
            e.kind,
            IesErrorKind::OutOfRange { field: "candela multiplier times ballast factors", .. }
        ),
        "{e}"
    );
    // 1986 format (no header line) is accepted.
    let p =
        IesProfile::parse("some free text\nTILT=NONE\n1 1000 1 1 1 1 2 0 0 0\n1 1 1\n0\n0\n5\n")
            .unwrap();
    assert_eq!(p.format, IesFormat::Lm63_1986);
    assert_eq!(p.candela_at(0.0, 0.0), 5.0);
}
