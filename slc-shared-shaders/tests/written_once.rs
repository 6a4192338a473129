//! No template retypes a formula of slc-core: the kernels call the core's
//! generated functions instead. The patterns are fragments of the core's
//! formulas (range, weight, lobes, union, hashing, camera ray, roulette,
//! denoise weight).

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
    ];
    let mut n = 0;
    for (name, src) in slc_shared_shaders::templates() {
        for f in forbidden {
            assert!(!src.contains(f), "template {name} contains the core formula fragment `{f}`");
        }
        n += 1;
    }
    assert_eq!(n, 20);
}
