//! The shared WGSL library parses and validates with naga, contains every
//! shared item, and `BshNode`'s Rust layout equals naga's WGSL layout.

use naga::valid::{Capabilities, ValidationFlags, Validator};

/// A module that includes the library, as a kernel template would.
fn module_source() -> String {
    let mut s = String::from("@group(0) @binding(0) var<storage, read> slc_table: array<f32>;\n");
    s.push_str(&slc_core::wgsl::library());
    s
}

fn parse_and_validate(src: &str) -> (naga::Module, naga::valid::ModuleInfo) {
    let module = match naga::front::wgsl::parse_str(src) {
        Ok(m) => m,
        Err(e) => panic!("WGSL parse error:\n{}", e.emit_to_string(src)),
    };
    let info = match Validator::new(ValidationFlags::all(), Capabilities::all()).validate(&module) {
        Ok(i) => i,
        Err(e) => panic!("WGSL validation error:\n{}", e.emit_to_string(src)),
    };
    (module, info)
}

#[test]
fn library_validates_with_naga() {
    let src = module_source();
    let (module, _) = parse_and_validate(&src);
    let names: Vec<_> = module.functions.iter().filter_map(|(_, f)| f.name.clone()).collect();
    for f in [
        "rr_probability",
        "slc_weight",
        "random_range2",
        "slc_keep",
        "threshold_range2",
        "intensity_measure",
        "windowed_falloff",
        "xi_from_bits",
        "pcg_hash",
        "sphere_contains_point",
        "sphere_overlaps_sphere",
        "sphere_overlaps_aabb",
        "inverse_square",
        "vpl_lobe",
        "vpl_transfer",
        "spot_falloff",
        "triangle_lobe",
        "triangle_sample",
        "area_to_solid_angle_pdf",
        "ies_fold_c",
        "ies_segment",
        "ies_lerp_t",
        "ies_candela",
        "ies_candela_dir",
        "mul_hi_u32",
        "uniform_index",
        "reservoir_slot",
        "reservoir_weight",
        "weighted_replace",
        "weighted_threshold",
        "xi_for",
        "xi_rotated",
        "light_xi",
        "cull_radius",
        "range_radius",
        "sphere_union",
        "ray_aabb",
        "ray_triangle",
        "mis_balance",
        "mis_power",
        "cosine_pdf",
        "onb_to_world",
        "ggx_d",
        "smith_visibility",
        "brdf_eval",
        "ggx_vndf_sample",
        "bsdf_sample",
        "bsdf_pdf",
        "light_importance",
        "candidate_weight",
        "weighted_select_pdf",
    ] {
        assert!(names.iter().any(|n| n == f), "{f} missing from the WGSL library");
    }
}

#[test]
fn library_is_formatted_one_statement_per_line() {
    let lib = slc_core::wgsl::library();
    assert!(!lib.contains("let mut"), "let mut must become var");
    assert!(lib.contains("var lo: u32 = 0;"));
    assert!(lib.lines().all(|l| l.len() < 200), "a line is too long to review");
}

#[test]
fn bsh_node_layout_matches_wgsl() {
    let src = format!(
        "{}\n@group(0) @binding(1) var<storage, read> nodes: array<BshNode>;\n\
         @compute @workgroup_size(1) fn main() {{ let n = nodes[0]; }}",
        module_source()
    );
    let (module, _) = parse_and_validate(&src);
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).unwrap();
    let (handle, ty) =
        module.types.iter().find(|(_, t)| t.name.as_deref() == Some("BshNode")).unwrap();
    let naga::TypeInner::Struct { members, span } = &ty.inner else {
        panic!("BshNode is not a struct")
    };
    assert_eq!(*span as usize, std::mem::size_of::<slc_core::bsh::BshNode>());
    assert_eq!(layouter[handle].size as usize, std::mem::size_of::<slc_core::bsh::BshNode>());
    let rust = [
        ("center", std::mem::offset_of!(slc_core::bsh::BshNode, center)),
        ("radius", std::mem::offset_of!(slc_core::bsh::BshNode, radius)),
        ("child", std::mem::offset_of!(slc_core::bsh::BshNode, child)),
        ("next", std::mem::offset_of!(slc_core::bsh::BshNode, next)),
        ("light", std::mem::offset_of!(slc_core::bsh::BshNode, light)),
        ("extent", std::mem::offset_of!(slc_core::bsh::BshNode, extent)),
    ];
    assert_eq!(members.len(), rust.len());
    for (m, (name, off)) in members.iter().zip(rust) {
        assert_eq!(m.name.as_deref(), Some(name));
        assert_eq!(m.offset as usize, off, "offset of {name}");
    }
}

#[test]
#[ignore = "prints the library; run with --ignored --nocapture"]
fn print_library() {
    println!("{}", slc_core::wgsl::library());
}
