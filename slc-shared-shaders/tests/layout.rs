//! Every buffer struct shared with the host has the same size and field
//! offsets in Rust (`#[repr(C)]`) as naga's layout of its WGSL declaration.

use naga::proc::Layouter;
use slc_shared_shaders::layout::*;
use std::mem::{offset_of, size_of};

macro_rules! fields {
    ($t:ty, $($f:ident),+) => {
        (stringify!($t), size_of::<$t>(), vec![$((stringify!($f), offset_of!($t, $f))),+])
    };
}

#[test]
fn rust_twins_match_naga_layout() {
    let src = format!(
        "{}\n{}\n@group(0) @binding(0) var<storage, read> slc_table: array<f32>;",
        slc_core::wgsl::translate(WGSL),
        slc_core::wgsl::library()
    );
    let (module, _) = slc_shared_shaders::validate("layout", &src).unwrap();
    let mut layouter = Layouter::default();
    layouter.update(module.to_ctx()).unwrap();
    let structs = [
        fields!(GpuLight, p0, kind, p1, a, p2, b, intensity, ies_base),
        fields!(GpuGeoNode, bmin, first, bmax, count),
        fields!(GpuTriangle, v0, material, v1, light, v2, pad),
        fields!(
            GpuPathState,
            origin,
            alive,
            dir,
            rng,
            beta,
            pdf_bsdf,
            prev,
            pad,
            prev_normal,
            pad2,
            prev_r,
            pad3,
            prev_lobe
        ),
        fields!(
            PtParams,
            cam_pos,
            width,
            cam_right,
            height,
            cam_up,
            depth,
            cam_forward,
            seed,
            pass_index,
            max_depth,
            eps,
            t_min
        ),
        fields!(GpuLightCone, center, radius, axis, cos_o, phi, cos_e, bvh_leaf, pad),
        fields!(GpuLightBvhNode, center, radius, axis, cos_o, phi, cos_e, second, light),
        fields!(
            GpuPathVertex,
            position,
            alive,
            normal,
            material,
            weight,
            pad1,
            gnormal,
            pad2,
            wo,
            pad3
        ),
        fields!(FrameParams, light_count, seed, frame, fixed_xi),
        fields!(RefitParams, first, count, pad0, pad1),
        fields!(
            VplParams,
            width,
            height,
            lights_per_subset,
            min_d2,
            near_r2,
            subset_shift,
            far_groups_at,
            near_clusters_at,
            near_groups_at,
            box_count,
            pad0,
            pad1,
            far_grid,
            near_grid
        ),
        fields!(GpuBox, lo, pad0, hi, pad1),
        fields!(ShadeParams, point_count, seed, frame, eps),
        fields!(GpuVplRecord, position, pad0, normal, pad1, flux, pad2),
        fields!(
            PackParams,
            count,
            size,
            per_subset,
            mode,
            exposure,
            error_bound,
            scale,
            slc,
            fixed_r2,
            pad0,
            pad1,
            pad2
        ),
        fields!(ImageParams, eye, width, height, pad0, pad1, pad2),
        fields!(
            ViewParams,
            c0,
            c1,
            c2,
            c3,
            eye,
            width,
            height,
            shadow_offset,
            seed,
            frame,
            f0_d,
            f90_d
        ),
        fields!(
            CullParams,
            light_count,
            seed,
            frame,
            slc,
            mode,
            exposure,
            error_bound,
            fixed_r2,
            unculled,
            pad0,
            pad1,
            pad2
        ),
        fields!(GpuVertex, position, material, normal, pad0, geo_normal, pad1),
        fields!(GpuMaterial, albedo, metallic, emission, alpha, f0, f90),
        fields!(
            MapParams, c0, c1, c2, c3, light, origin, mode, axis, size, right, extent, up, texel
        ),
        fields!(slc_core::bsh::BshNode, center, radius, child, next, light, extent),
    ];
    for (name, size, offsets) in structs {
        let name = name.rsplit("::").next().unwrap().trim();
        let (handle, ty) = module
            .types
            .iter()
            .find(|(_, t)| t.name.as_deref() == Some(name))
            .unwrap_or_else(|| panic!("{name} not in WGSL"));
        let naga::TypeInner::Struct { members, span } = &ty.inner else {
            panic!("{name} is not a struct")
        };
        assert_eq!(*span as usize, size, "{name}: WGSL size {span} vs Rust {size}");
        assert_eq!(layouter[handle].size as usize, size, "{name} size");
        assert_eq!(members.len(), offsets.len(), "{name} field count");
        for (m, (field, off)) in members.iter().zip(offsets) {
            assert_eq!(m.name.as_deref(), Some(field), "{name} field order");
            assert_eq!(
                m.offset as usize, off,
                "{name}.{field}: WGSL offset {} vs Rust {off}",
                m.offset
            );
        }
        // Uniform buffers need 16-byte multiples.
        assert_eq!(size % 16, 0, "{name} size {size}");
    }
}

/// `vpl_workgroup_bytes`, which the host checks against the adapter's
/// `max_compute_workgroup_storage_size`, is the size naga lays out for the
/// generated `vpl_tiled`'s and `vpl_near`'s workgroup variables, for every
/// culling kind, with and without counters, and a few list capacities.
#[test]
fn vpl_workgroup_bytes_match_naga() {
    use slc_shared_shaders::{
        CullKind, Features, Kernel, LightTypes, generate_module, vpl_workgroup_bytes,
    };
    for kernel in [Kernel::VplTiled, Kernel::VplNear] {
        for method in CullKind::ALL {
            for counters in [false, true] {
                for list in [64u32, 100, 2048] {
                    let f = Features {
                        lights: LightTypes { vpl: true, ..LightTypes::default() },
                        max_tile_lights: list,
                        method,
                        counters,
                        ..Features::default()
                    };
                    let g = generate_module(kernel, &f).unwrap();
                    let mut layouter = Layouter::default();
                    layouter.update(g.module.to_ctx()).unwrap();
                    let naga_bytes: u64 = g
                        .module
                        .global_variables
                        .iter()
                        .filter(|(_, v)| v.space == naga::AddressSpace::WorkGroup)
                        .map(|(_, v)| layouter[v.ty].size as u64)
                        .sum();
                    assert_eq!(
                        vpl_workgroup_bytes(kernel, &f),
                        naga_bytes,
                        "{kernel:?} {method:?} counters {counters} list {list}"
                    );
                }
            }
        }
    }
}

/// `direct_workgroup_bytes` is the size naga lays out for the generated
/// `direct_light`'s workgroup variables (its tile walk), for each tile
/// size and a few list capacities, with and without counters, and none
/// with the walk per pixel.
#[test]
fn direct_workgroup_bytes_match_naga() {
    use slc_shared_shaders::{
        Features, Kernel, LightTypes, Selection, direct_workgroup_bytes, generate_module,
    };
    for tile in [1u32, 4, 8, 16] {
        for list in [16u32, 1024] {
            for (counters, tile_walk) in [(false, true), (true, true), (false, false)] {
                let f = Features {
                    lights: LightTypes { point: true, ..LightTypes::default() },
                    selection: Selection::Weighted,
                    tile_size: tile,
                    max_tile_lights: list,
                    counters,
                    tile_walk,
                    ..Features::default()
                };
                let g = generate_module(Kernel::DirectLight, &f).unwrap();
                let mut layouter = Layouter::default();
                layouter.update(g.module.to_ctx()).unwrap();
                let naga_bytes: u64 = g
                    .module
                    .global_variables
                    .iter()
                    .filter(|(_, v)| v.space == naga::AddressSpace::WorkGroup)
                    .map(|(_, v)| layouter[v.ty].size as u64)
                    .sum();
                assert_eq!(
                    direct_workgroup_bytes(&f),
                    naga_bytes,
                    "tile {tile} list {list} counters {counters} tile walk {tile_walk}"
                );
            }
        }
    }
}
