//! No template retypes a formula of slc-core: the kernels call the core's
//! generated functions instead. Two guards: templates spell no numeric
//! constant of their own (only `0.0`, `1.0` and small integers), which
//! catches a copied formula by its constants; and a list of fragments of
//! the core's formulas made of those alone (range, weight, lobes, union,
//! hashing, camera ray, roulette, denoise weight).

#[test]
fn templates_do_not_contain_core_formulas() {
    let forbidden = [
        "1.0 - xi",
        "(1.0 - xi)",
        "/ (PI * alpha)",
        "PI * alpha",
        "rt2 / d2",
        "d2 / rt2",
        "/ (1.0 -",
        "TWO_PI",
        "0.3183",
        "6.2831",
        "3.1415",
        "INV_PI",
        "exposure *",
        "747796405",
        "r1 + r2",
        "smoothstep",
        "t * t * (3.0",
        "sqrt(u1)",
        "* 0.5 * (d",
        "n / k",
        "0.05, 0.95",
        "* inverse_square(d2) *",
        "area_to_solid_angle_pdf(1.0 / ",
        "2.0 * px",
        "2.0 * py",
        "pow(dn",
        "* dn8",
        "normalize(cross(",
        "dot(gn, st.dir) > 0.0",
        "1.0 - vpl_near_weight",
        // Orchestration moved into slc-core (issue 18): random streams, the
        // denoise window and widening, the interleaved flux scale.
        "^ pcg_hash(",
        "DEPTH_SIGMA *",
        "PERIOD * PERIOD",
        "P * P",
        "size / 2u",
        "cross(l.p2",
        "d2 < r2",
        // The VPL frame's glossy composition (c_diff = (1 - m) b).
        "1.0 - m.metallic",
        "(1.0 - metallic)",
        // Temporal accumulation: the moving average, the change test, the
        // luminance, the bilinear weights.
        "(1.0 - lambda)",
        "0.5 * d * d",
        "0.2126",
        "(c - hc)",
        "1.0 - fx",
    ];
    let mut n = 0;
    for (name, src) in slc_shared_shaders::templates() {
        for f in forbidden {
            assert!(!src.contains(f), "template {name} contains the core formula fragment `{f}`");
        }
        n += 1;
    }
    assert_eq!(n, 39);
}

/// The guard that catches the next copy: a template composes the core's
/// functions and constants, so the only numbers it may spell are the
/// identities `0.0` and `1.0` and small integers (binding numbers, indices,
/// fixed array sizes, at most 64). Any other literal (a `0.5`, a `1e-4`,
/// a hash constant) is a formula's constant and lives in slc-core's shared
/// code, where both backends read it.
#[test]
fn templates_spell_no_constants_of_their_own() {
    let mut found = Vec::new();
    for (name, src) in slc_shared_shaders::templates() {
        for lit in numeric_literals(&strip(src)) {
            if !allowed(&lit) {
                found.push(format!("{name}: {lit}"));
            }
        }
    }
    assert!(
        found.is_empty(),
        "constants typed in templates (move them to slc-core's shared code):\n{}",
        found.join("\n")
    );
    // The lexer itself: it finds what it must.
    let probe = "let a = 0.5 * x; let b = vec3f(1e-4); let c = h ^ 0x9E3779B9u; let d = 2654435769u; let e = arr[3u] + 1.0; // 7.0";
    let lits: Vec<String> =
        numeric_literals(&strip(probe)).into_iter().filter(|l| !allowed(l)).collect();
    assert_eq!(lits, ["0.5", "1e-4", "0x9E3779B9u", "2654435769u"]);
}

/// `src` without `//` comments and minijinja tags (`{% … %}`, `{{ … }}`).
fn strip(src: &str) -> String {
    let mut out = String::new();
    for line in src.lines() {
        let line = line.split("//").next().unwrap_or("");
        let mut rest = line;
        while let Some(start) = rest.find(['{']) {
            let tail = &rest[start..];
            let close = if tail.starts_with("{%") {
                "%}"
            } else if tail.starts_with("{{") {
                "}}"
            } else {
                out.push_str(&rest[..=start]);
                rest = &rest[start + 1..];
                continue;
            };
            out.push_str(&rest[..start]);
            out.push(' ');
            rest = tail.find(close).map_or("", |e| &tail[e + 2..]);
        }
        out.push_str(rest);
        out.push('\n');
    }
    out
}

/// Every numeric literal token of WGSL text (identifiers such as `vec3f`
/// or `atan2` are skipped whole).
fn numeric_literals(src: &str) -> Vec<String> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c.is_ascii_alphabetic() || c == b'_' {
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
        } else if c.is_ascii_digit() || (c == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit))
        {
            let start = i;
            while i < b.len() {
                let d = b[i];
                let exp_sign = (d == b'-' || d == b'+')
                    && matches!(b[i - 1], b'e' | b'E')
                    && !src[start..i].starts_with("0x");
                if d.is_ascii_alphanumeric() || d == b'.' || d == b'_' || exp_sign {
                    i += 1;
                } else {
                    break;
                }
            }
            out.push(src[start..i].to_string());
        } else {
            i += 1;
        }
    }
    out
}

/// `0.0`, `1.0` (with or without an `f` suffix) and decimal integers up to 64.
fn allowed(lit: &str) -> bool {
    if lit.starts_with("0x") || lit.starts_with("0X") {
        return false;
    }
    let is_float = lit.contains('.') || lit.contains(['e', 'E']);
    if is_float {
        let v: f64 = lit.trim_end_matches(['f', 'h']).parse().unwrap_or(f64::NAN);
        return v == 0.0 || v == 1.0;
    }
    lit.trim_end_matches(['u', 'i']).parse::<u64>().is_ok_and(|v| v <= 64)
}
