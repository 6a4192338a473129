//! naga validates every variant the generator can produce: all 31 non-empty
//! light-type subsets × reservoir sizes × heuristics for the BSH and path
//! tracing kernels,
//! tile sizes × periods × methods for the VPL kernel; a sample of them is
//! translated to every back end; unsupported combinations are typed errors.

use slc_shared_shaders::*;

fn vpl_only() -> LightTypes {
    LightTypes { vpl: true, ..LightTypes::default() }
}

#[test]
fn every_bsh_variant_validates() {
    let mut n = 0;
    for bits in 1..32 {
        let lights = LightTypes::from_bits(bits);
        for k in [1, 8, 32] {
            for heuristic in [Heuristic::Balance, Heuristic::Power] {
                for (kernel, selection) in [
                    (Kernel::BshReservoir, Selection::Reservoir),
                    (Kernel::PtConnect, Selection::Reservoir),
                    (Kernel::PtConnect, Selection::All),
                    (Kernel::PtConnect, Selection::Weighted),
                    (Kernel::PtConnect, Selection::Uniform),
                    (Kernel::PtConnect, Selection::Power),
                    (Kernel::PtConnect, Selection::LightBvh),
                    (Kernel::PtExtend, Selection::Reservoir),
                    (Kernel::PtExtend, Selection::Weighted),
                    (Kernel::PtExtend, Selection::Power),
                    (Kernel::PtExtend, Selection::LightBvh),
                ] {
                    let f = Features {
                        lights,
                        reservoir_k: k,
                        heuristic,
                        selection,
                        ..Features::default()
                    };
                    let g = generate_module(kernel, &f)
                        .unwrap_or_else(|e| panic!("{:?} {f:?}: {e}", kernel));
                    // Only the scene's light types are compiled in.
                    for (name, case) in [
                        ("point", "LIGHT_POINT:"),
                        ("spot", "LIGHT_SPOT:"),
                        ("ies", "LIGHT_IES:"),
                        ("triangle", "LIGHT_TRIANGLE:"),
                        ("vpl", "LIGHT_VPL:"),
                    ] {
                        let wanted = lights.names().contains(&name);
                        assert_eq!(
                            g.source.contains(&format!("case {case}")),
                            wanted,
                            "{name} in {:?} {f:?}",
                            kernel
                        );
                    }
                    n += 1;
                }
            }
        }
    }
    for wg in [1, 32, 64, 256] {
        for kernel in [Kernel::LightUpdate, Kernel::BshRefit, Kernel::BshTail, Kernel::BshGrid] {
            generate_module(kernel, &Features { workgroup_size: wg, ..Features::default() })
                .unwrap();
            n += 1;
        }
    }
    // pt_connect's grid variant, for the selections that walk the BSH.
    for selection in [Selection::Reservoir, Selection::All, Selection::Weighted] {
        for lights in [LightTypes::ALL, LightTypes::parse("triangle").unwrap()] {
            let f = Features { lights, selection, bsh_grid: true, ..Features::default() };
            let g = generate_module(Kernel::PtConnect, &f).unwrap();
            assert!(g.source.contains("grid_entries"), "{f:?}");
            n += 1;
        }
    }
    assert_eq!(n, 31 * 3 * 2 * 11 + 16 + 6);
}

#[test]
fn every_vpl_variant_validates() {
    for kernel in [Kernel::VplTiled, Kernel::VplNear] {
        for tile in [1, 2, 4, 8, 16] {
            for period in [1, 4, 8, 16] {
                for method in CullKind::ALL {
                    for max_tile_lights in [32, 64, 1024, 2048, 4000] {
                        for (glossy, counters) in
                            [(false, false), (true, false), (false, true), (true, true)]
                        {
                            let f = Features {
                                lights: vpl_only(),
                                tile_size: tile,
                                interleave: period,
                                method,
                                max_tile_lights,
                                glossy,
                                counters,
                                ..Features::default()
                            };
                            let r = generate_module(kernel, &f);
                            // One invocation per light of a cluster, a list
                            // that takes a cluster, within 16 KiB, and a
                            // Lambertian counting variant.
                            let supported = tile == 8
                                && max_tile_lights >= 64
                                && vpl_workgroup_bytes(kernel, &f) <= 16384
                                && !(glossy && counters);
                            if supported {
                                r.unwrap_or_else(|e| panic!("{kernel:?} {f:?}: {e}"));
                            } else {
                                assert!(
                                    matches!(r, Err(ShaderError::Unsupported(_))),
                                    "{kernel:?} {f:?} should be unsupported"
                                );
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(
        vpl_workgroup_bytes(
            Kernel::VplTiled,
            &Features { max_tile_lights: 4000, ..Features::default() }
        ) > 16384
    );
    for kernel in [Kernel::VplClusters, Kernel::VplGroups] {
        for period in [1, 4, 8, 16] {
            for method in CullKind::ALL {
                let f = Features {
                    lights: vpl_only(),
                    interleave: period,
                    method,
                    ..Features::default()
                };
                generate_module(kernel, &f).unwrap_or_else(|e| panic!("{kernel:?} {f:?}: {e}"));
            }
        }
    }
}

#[test]
fn every_kernel_translates_to_every_backend() {
    let sets = [
        LightTypes::ALL,
        LightTypes::parse("triangle").unwrap(),
        LightTypes::parse("point,ies").unwrap(),
        vpl_only(),
    ];
    for lights in sets {
        for g in all_kernels(&Features { lights, ..Features::default() }).unwrap() {
            let t = translate(&g).unwrap_or_else(|e| panic!("{e}"));
            assert!(t.spv.len() > 100 && t.spv[0] == 0x0723_0203, "SPIR-V magic");
            assert_eq!(t.glsl_entries.len(), g.kernel.entry_points().len());
            assert!(
                t.glsl_entries.iter().all(|(_, src)| src.contains("void main()")),
                "{}",
                g.kernel.name()
            );
            if g.kernel == Kernel::SceneRaster {
                assert!(t.msl.contains("vertex ") && t.msl.contains("fragment "), "{}", t.msl);
                assert!(t.hlsl.contains("vs_main") && t.hlsl.contains("fs_rsm"));
            } else {
                assert!(t.hlsl.contains("[numthreads("));
                assert!(t.msl.contains("kernel void"));
            }
        }
    }
    for method in CullKind::ALL {
        let g = generate_module(
            Kernel::VplTiled,
            &Features { lights: vpl_only(), method, ..Features::default() },
        )
        .unwrap();
        translate(&g).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn unsupported_combinations_are_typed_errors() {
    let unsupported = |k: Kernel, f: Features| {
        assert!(matches!(generate(k, &f), Err(ShaderError::Unsupported(_))), "{k:?} {f:?}")
    };
    unsupported(Kernel::VplTiled, Features::default());
    unsupported(
        Kernel::VplTiled,
        Features { lights: LightTypes::parse("vpl,point").unwrap(), ..Features::default() },
    );
    unsupported(
        Kernel::VplTiled,
        Features { lights: vpl_only(), tile_size: 3, ..Features::default() },
    );
    unsupported(
        Kernel::VplTiled,
        Features { lights: vpl_only(), tile_size: 32, ..Features::default() },
    );
    unsupported(
        Kernel::VplTiled,
        Features { lights: vpl_only(), interleave: 0, ..Features::default() },
    );
    unsupported(
        Kernel::BshReservoir,
        Features { lights: LightTypes::default(), ..Features::default() },
    );
    unsupported(Kernel::PtConnect, Features { reservoir_k: 0, ..Features::default() });
    unsupported(Kernel::LightUpdate, Features { workgroup_size: 512, ..Features::default() });
    assert!(matches!(LightTypes::parse("point,laser"), Err(ShaderError::Unsupported(_))));
}

#[test]
fn naga_errors_quote_the_source_line() {
    let e = validate("broken", "fn f() -> f32 {\n    return vec3f(1.0);\n}\n").unwrap_err();
    let ShaderError::Naga { message, .. } = e else { panic!("not a naga error") };
    assert!(message.contains("return vec3f(1.0)"), "{message}");
}

/// The direct pass's kernel for every light-type subset, selection, surface
/// source and a few k.
#[test]
fn every_direct_light_variant_validates() {
    let mut n = 0;
    for bits in 1..32 {
        for selection in [Selection::Reservoir, Selection::Weighted, Selection::All] {
            for surface in [SurfaceSource::Position, SurfaceSource::Depth, SurfaceSource::R32Depth]
            {
                for (k, direct_output) in [
                    (1, DirectOutput::Irradiance),
                    (8, DirectOutput::Radiance),
                    (8, DirectOutput::Split),
                    (8, DirectOutput::BevyRadiance),
                ] {
                    let f = Features {
                        lights: LightTypes::from_bits(bits),
                        selection,
                        surface,
                        reservoir_k: k,
                        direct_output,
                        ..Features::default()
                    };
                    generate_module(Kernel::DirectLight, &f)
                        .unwrap_or_else(|e| panic!("{f:?}: {e}"));
                    n += 1;
                }
            }
        }
    }
    assert_eq!(n, 31 * 3 * 3 * 4);
    let weighted = Features { selection: Selection::Weighted, ..Features::default() };
    // The tile walk: a power-of-two tile, a list of at least one entry that
    // fits WebGPU's 16 KiB of workgroup memory; without it, any list.
    for bad in [
        Features { selection: Selection::Power, ..Features::default() },
        Features { tile_size: 3, ..weighted },
        Features { tile_size: 32, ..weighted },
        Features { max_tile_lights: 0, ..weighted },
        Features { max_tile_lights: 4096, ..weighted },
    ] {
        let r = generate_module(Kernel::DirectLight, &bad);
        assert!(matches!(r, Err(ShaderError::Unsupported(_))), "{bad:?}");
    }
    for good in [
        Features { tile_size: 3, tile_walk: false, ..weighted },
        Features { max_tile_lights: 0, tile_walk: false, ..weighted },
        Features { max_tile_lights: 1, ..weighted },
    ] {
        generate_module(Kernel::DirectLight, &good).unwrap_or_else(|e| panic!("{good:?}: {e}"));
    }
}

/// Shadow rays as ray queries: `direct_light` with shadows and
/// `pt_connect` bind the acceleration structure instead of the BVH's
/// buffers and validate only with naga's ray-query capability; every other
/// combination is refused.
#[test]
fn ray_query_variant() {
    use slc_shared_shaders::bindings::{Resource, bindings};
    let rq = Features { ray_query: true, ..Features::default() };
    let pt = Features { reservoir_k: 8, ..rq };
    for (kernel, f, slot) in [
        (Kernel::DirectLight, rq, (1, 6)),
        (
            Kernel::DirectLight,
            Features { selection: Selection::Weighted, tile_walk: false, ..rq },
            (1, 6),
        ),
        (
            Kernel::DirectLight,
            Features { selection: Selection::Resampled, reuse_domains: 3, ..rq },
            (1, 6),
        ),
        (Kernel::PtConnect, pt, (0, 6)),
        (Kernel::PtConnect, Features { selection: Selection::Weighted, ..pt }, (0, 6)),
        (
            Kernel::PtConnect,
            Features { selection: Selection::Uniform, reservoir_k: 1, ..pt },
            (0, 6),
        ),
    ] {
        let g = generate_module(kernel, &f).unwrap_or_else(|e| panic!("{f:?}: {e}"));
        assert!(g.source.contains("rayQueryInitialize"));
        assert!(!g.source.contains("geo_nodes"));
        let t = bindings(kernel, &f);
        let tlas: Vec<_> =
            t.iter().filter(|b| b.resource == Resource::AccelerationStructure).collect();
        assert_eq!(tlas.len(), 1);
        assert_eq!((tlas[0].group, tlas[0].binding, tlas[0].name), (slot.0, slot.1, "geo_tlas"));
        // Without the capability naga refuses it: the module really holds a ray query.
        let r = naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::default(),
        )
        .validate(&g.module);
        assert!(r.is_err(), "{f:?} validated without RAY_QUERY");
        g.compacted().unwrap();
    }
    for bad in [
        (Kernel::DirectLight, Features { shadows: false, ..rq }),
        (Kernel::DirectLight, Features { counters: true, ..rq }),
        (Kernel::BshReservoir, rq),
        (Kernel::PtExtend, rq),
    ] {
        let r = generate_module(bad.0, &bad.1);
        assert!(matches!(r, Err(ShaderError::Unsupported(_))), "{bad:?}");
    }
}
