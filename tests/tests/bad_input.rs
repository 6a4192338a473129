//! A battery of bad inputs to every public constructor and loader: each
//! must return a typed error, never panic (checked with catch_unwind), and
//! its message must name the bad field; and an engine's misuses of the
//! passes ([`engine_misuse`]): a typed error or a documented, tested
//! behaviour each.

use slc_core::bsh::Bsh;
use slc_core::glam::Vec3;
use slc_core::ies::IesProfile;
use slc_core::light::{LightBound, PointLight, SpotLight, TriangleLight, Vpl};
use slc_core::range::{RangeParams, Xi};
use slc_cpu::vpl::VplContext;
use slc_scene::scene::Scene;
use slc_scene::scene_file::SceneFile;
use slc_scene::vpl::{Culling, VplSettings};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

/// Runs `f`, asserting it returns an error (not a panic) whose message
/// contains `needle`.
fn rejects<T: std::fmt::Debug, E: std::fmt::Display>(
    what: &str,
    needle: &str,
    f: impl FnOnce() -> Result<T, E> + std::panic::UnwindSafe,
) {
    match catch_unwind(f) {
        Err(_) => panic!("{what}: panicked instead of returning an error"),
        Ok(Ok(v)) => panic!("{what}: accepted ({v:?})"),
        Ok(Err(e)) => {
            let msg = e.to_string();
            assert!(
                msg.to_lowercase().contains(&needle.to_lowercase()),
                "{what}: error '{msg}' does not name '{needle}'"
            );
        }
    }
}

/// Bad for every scalar that must be finite and positive.
const BAD: [f32; 4] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -1.0];
/// Bad for coordinates (which may be negative).
const NONFINITE: [f32; 3] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY];

fn core_constructors() {
    for b in BAD {
        rejects("error bound", "error bound", move || RangeParams::new(b, 1.0));
        rejects("exposure", "exposure", move || RangeParams::new(0.1, b));
        rejects("alpha", "alpha", move || RangeParams::from_alpha(b));
        rejects("xi", "xi", move || Xi::new(b));
        rejects("point intensity", "intensity", move || {
            PointLight::new(Vec3::ZERO, Vec3::new(0.0, b, 0.0))
        });
        rejects("vpl flux", "flux", move || Vpl::new(Vec3::ZERO, Vec3::Y, Vec3::splat(b)));
        rejects("spot angle", "cone", move || {
            SpotLight::new(Vec3::ZERO, Vec3::Y, Vec3::ONE, 0.1, b)
        });
        rejects("triangle radiance", "radiance", move || {
            TriangleLight::new(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::splat(b))
        });
        rejects("bsh extent", "extent", move || {
            Bsh::build(&[LightBound { center: Vec3::ZERO, extent: b }])
        });
    }
    for b in NONFINITE {
        rejects("point position", "position", move || {
            PointLight::new(Vec3::new(b, 0.0, 0.0), Vec3::ONE)
        });
        rejects("triangle vertex", "vertex", move || {
            TriangleLight::new(Vec3::splat(b), Vec3::X, Vec3::Y, Vec3::ONE)
        });
        rejects("bsh centre", "centre", move || {
            Bsh::build(&[LightBound { center: Vec3::new(0.0, b, 0.0), extent: 0.0 }])
        });
    }
    rejects("xi = 1", "xi", || Xi::new(1.0));
    rejects("vpl normal", "normal", || Vpl::new(Vec3::ZERO, Vec3::ZERO, Vec3::ONE));
    rejects("spot direction", "direction", || {
        SpotLight::new(Vec3::ZERO, Vec3::ZERO, Vec3::ONE, 0.1, 0.2)
    });
    rejects("zero-area triangle", "zero area", || {
        TriangleLight::new(Vec3::ZERO, Vec3::X, Vec3::X * 2.0, Vec3::ONE)
    });
    rejects("bsh refit NaN", "range", || {
        let mut t = Bsh::build(&[LightBound { center: Vec3::ZERO, extent: 0.0 }]).unwrap();
        t.refit(&[f32::NAN]).map(|_| ())
    });
    rejects("bsh refit count", "ranges", || {
        let mut t = Bsh::build(&[LightBound { center: Vec3::ZERO, extent: 0.0 }]).unwrap();
        t.refit(&[1.0, 2.0]).map(|_| ())
    });
}

fn ies_parser() {
    for (text, needle) in [
        ("", "tilt"),
        ("TILT=NONE\n1 1000 1 x 1 1 2 0 0 0\n", "vertical"),
        ("TILT=NONE\n1 1000 1 2 1 9 2 0 0 0\n1 1 1\n0 90\n0\n1 1\n", "photometric type"),
        ("TILT=NONE\n1 1000 1 2 1 1 2 0 0 0\n1 1 1\n90 0\n0\n1 1\n", "vertical angles"),
        ("TILT=NONE\n1 1000 1 1 1 1 2 0 0 0\n1 1 1\n0\n0\nnan\n", "candela"),
        ("TILT=INCLUDE\n1\n99999999\n", "tilt angle count"),
    ] {
        rejects(&format!("ies {text:?}"), needle, move || IesProfile::parse(text));
    }
    // Every error carries a line number.
    let e = IesProfile::parse("TILT=NONE\n1 1000 1 1 1 1 2 0 0 0\n1 1 1\n0\n0\n-3\n").unwrap_err();
    assert_eq!(e.line, 6);
}

fn scene_loaders() {
    let bad_obj: [(&[u8], &str); 4] = [
        (b"", "no triangles"),
        (b"v inf 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "non-finite"),
        (b"v 0 0 0\nf 1 2 3\n", "index"),
        (b"mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "material"),
    ];
    for (obj, needle) in bad_obj {
        rejects(&format!("obj {:?}", String::from_utf8_lossy(obj)), needle, move || {
            Scene::parse_obj(obj, "t.obj", |_| None)
        });
    }
    // Regression (fuzz/scene_loaders): tobj panics on a short colour line.
    for line in ["Kd", "Kd 0.5", "Ke 1 2", "Ka", "Ks 0 0"] {
        let mtl = format!("newmtl a\n{line}\n").into_bytes();
        rejects(&format!("mtl {line:?}"), "material", move || {
            Scene::parse_obj(
                b"mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                "t.obj",
                |_| Some(mtl.clone()),
            )
        });
    }
    rejects("albedo > 1", "albedo", || {
        Scene::parse_obj(
            b"mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
            "t.obj",
            |_| Some(b"newmtl a\nKd 2 0 0\n".to_vec()),
        )
    });
    for (text, needle) in [
        ("[[geometry]]\nbuiltin = \"cornell\"\nbogus = 1\n", "bogus"),
        ("[[geometry]]\nobj = \"missing.obj\"\n", "missing.obj"),
        ("[[geometry]]\nbuiltin = \"cornell\"\n[render]\nwidth = -3\n", "line 4"),
        (
            "[[geometry]]\nbuiltin = \"cornell\"\n[[light]]\ntype = \"ies\"\nposition = [0, 0, 0]\nfile = \"none.ies\"\n",
            "none.ies",
        ),
    ] {
        rejects(&format!("scene file {text:?}"), needle, move || {
            SceneFile::parse(text, Path::new("/nonexistent"), "t.toml").map(|_| ())
        });
    }
}

fn renderer_settings() {
    let scene = Scene::cornell_box();
    rejects("width 0", "size", || VplContext::new(&scene, 0, 8, 32, None).map(|_| ()));
    rejects("vpl count", "vpls", || VplContext::new(&scene, 8, 8, 12, None).map(|_| ()));
    rejects("min distance", "min distance", || {
        VplContext::new(&scene, 8, 8, 32, Some(f32::NAN)).map(|_| ())
    });
    let ctx = VplContext::new(&scene, 8, 8, 16, None).unwrap();
    for b in BAD {
        rejects("culling error bound", "error bound", move || Culling::stochastic(b, 1.0));
        rejects("culling exposure", "exposure", move || Culling::stochastic(0.01, b));
        rejects("culling range", "range", move || Culling::clamped(b));
        rejects("render fixed xi", "xi", || {
            ctx.render(&VplSettings { fixed_xi: Some(b), ..VplSettings::default() }).map(|_| ())
        });
    }
    rejects("shader lights", "laser", || slc_shared_shaders::LightTypes::parse("laser"));
    rejects("shader k", "reservoir", || {
        let f = slc_shared_shaders::Features { reservoir_k: 0, ..Default::default() };
        slc_shared_shaders::generate(slc_shared_shaders::Kernel::BshReservoir, &f)
    });
}

/// The path tracer's and direct light's entry points, on both backends.
fn path_tracer_and_direct_light_settings() {
    use slc_cpu::direct::DirectLights;
    use slc_cpu::pt::CpuPathTracer;
    use slc_scene::lights::LightSet;
    use slc_scene::pt::{PtMethod, PtRender, PtScene, PtSettings};
    rejects("no direct lights", "no lights", || LightSet::new(Vec::new()).map(|_| ()));
    let light = slc_core::light::Light::Point(PointLight::new(Vec3::ZERO, Vec3::ONE).unwrap());
    let params = RangeParams::new(0.1, 1.0).unwrap();
    let l2 = light.clone();
    rejects("points vs normals", "normals", move || {
        LightSet::new(vec![l2])
            .and_then(|set| DirectLights::new(&set).shade(&[Vec3::ONE], &[], &params, 1, 0))
            .map(|_| ())
    });
    let scene = Scene::cornell_box();
    for b in BAD {
        rejects("pt error bound", "error bound", || {
            let mut pts = CpuPathTracer::new(&PtScene::new(&scene, &[]).unwrap());
            pts.render(
                &mut PtRender::new(4, 4),
                &PtSettings { error_bound: b, ..PtSettings::default() },
                1,
            )
        });
    }
    for (w, h) in [(0, 8), (8, 0), (0, 0)] {
        rejects("pt size", "size", || {
            CpuPathTracer::new(&PtScene::new(&scene, &[]).unwrap()).render(
                &mut PtRender::new(w, h),
                &PtSettings::default(),
                1,
            )
        });
    }
    rejects("pt depth", "depth", || {
        CpuPathTracer::new(&PtScene::new(&scene, &[]).unwrap()).render(
            &mut PtRender::new(4, 4),
            &PtSettings { max_depth: 0, ..PtSettings::default() },
            1,
        )
    });
    let Some(g) = slc_tests::gpu() else { return };
    let pts = PtScene::new(&scene, &[]).unwrap();
    rejects(
        "gpu pt size",
        "size",
        AssertUnwindSafe(|| slc_wgpu::pt::GpuPt::new(g, &pts, 0, 8).map(|_| ())),
    );
    let mut gpt = slc_wgpu::pt::GpuPt::new(g, &pts, 4, 4).unwrap();
    for b in BAD {
        let s =
            PtSettings { method: PtMethod::SlcReservoir, error_bound: b, ..PtSettings::default() };
        rejects(
            "gpu pt error bound",
            "error bound",
            AssertUnwindSafe(|| gpt.render(&mut PtRender::new(4, 4), &s, 1)),
        );
    }
    let d = LightSet::new(vec![light]).unwrap();
    let mut gd = slc_tests::direct::GpuDirect::new(g, &d).unwrap();
    rejects(
        "gpu points vs normals",
        "normals",
        AssertUnwindSafe(|| gd.shade(&[Vec3::ONE, Vec3::ZERO], &[Vec3::Y], &params, 1, 0)),
    );
}

/// Two shading points an outside program found (2026-11-29), on both
/// backends and for every selection: one with a NaN normal lights nothing
/// (as one with a NaN coordinate; it gave NaN), and one exactly at a point
/// light, which lights nothing there and so weighs nothing: the weighted
/// picks go to the other lights in range (they went to it, and the point
/// was black in nearly every frame). Over 256 frames the weighted picks'
/// mean there lies within 5 standard errors of every light's.
fn degenerate_direct_points() {
    use slc_core::light::Light;
    use slc_cpu::direct::DirectLights;
    use slc_scene::lights::{Direct, DirectSelection, LightSet};
    let at = |i: usize| Vec3::new(0.05 * i as f32, 0.3 + 0.01 * i as f32, 0.0);
    let lights: Vec<Light> =
        (0..20).map(|i| Light::Point(PointLight::new(at(i), Vec3::ONE).unwrap())).collect();
    let set = LightSet::new(lights).unwrap();
    let params = RangeParams::new(2.0, 1.0).unwrap();
    let (points, normals) = ([Vec3::new(0.5, 0.0, 0.0), at(0)], [Vec3::NAN, Vec3::Y]);
    let selections = [
        DirectSelection::All,
        DirectSelection::Uniform { k: 8 },
        DirectSelection::Weighted { k: 8 },
        DirectSelection::Resampled { k: 8 },
    ];
    let check = |backend: &str, shade: &mut dyn FnMut(u32, DirectSelection) -> Vec<Direct>| {
        let mut means = Vec::new();
        for sel in selections {
            let (mut sum, mut sum2, mut lit) = (0.0f64, 0.0f64, 0);
            for frame in 0..256 {
                let d = shade(frame, sel);
                assert_eq!(d[0].irradiance, Vec3::ZERO, "{backend} {sel:?}: a NaN normal");
                let e = d[1].irradiance.x as f64;
                assert!(e.is_finite(), "{backend} {sel:?}: at a light: {e}");
                (sum, sum2, lit) = (sum + e, sum2 + e * e, lit + (e > 0.0) as u32);
            }
            assert!(lit >= 192, "{backend} {sel:?}: at a light, lit in {lit} of 256 frames");
            let mean = sum / 256.0;
            means.push((mean, ((sum2 / 256.0 - mean * mean).max(0.0) / 256.0).sqrt()));
        }
        let ((all, se_all), (weighted, se_w)) = (means[0], means[2]);
        let se = (se_all * se_all + se_w * se_w).sqrt();
        eprintln!("{backend}: at a light, weighted {weighted} ± {se_w}, all {all} ± {se_all}");
        assert!(
            (weighted - all).abs() <= 5.0 * se + 1e-5 * all,
            "{backend}: at a light, weighted {weighted} vs all {all} (standard error {se})"
        );
    };
    let mut cpu = DirectLights::new(&set);
    check("cpu", &mut |frame, sel| {
        cpu.shade_selected(&points, &normals, &params, 3, frame, sel).unwrap()
    });
    let Some(g) = slc_tests::gpu() else { return };
    let mut gpu = slc_tests::direct::GpuDirect::new(g, &set).unwrap();
    check("gpu", &mut |frame, sel| {
        gpu.shade_selected(&points, &normals, &params, 3, frame, sel).unwrap()
    });
}

/// An engine's misuses of the passes, as an outside program made them
/// (issue 50's table), one per function below: each is a typed error or a
/// documented, tested behaviour, never a silent wrong image.
mod engine_misuse {
    use slc_core::glam::{Mat4, Vec3};
    use slc_core::light::{Light, MAX_INTENSITY, PointLight, SpotLight};
    use slc_core::range::RangeParams;
    use slc_scene::scene::Scene;
    use slc_shared_shaders::layout::GpuVplRecord;
    use slc_tests::engine::{self, texture, upload};
    use slc_wgpu::passes::{
        Culling, DirectInputs, DirectPass, DirectPassDesc, DirectReuse, DirectSelection,
        DirectSettings, GBuffer, IndirectInputs, IndirectPass, IndirectPassDesc, IndirectSettings,
        Surface, SurfaceDesc, VplInput, VplSourceDesc, vpl_buffer,
    };
    use slc_wgpu::{GpuContext, GpuError, LightSet};

    const W: u32 = 16;
    const H: u32 = 16;

    /// The Cornell box's ray-cast G-buffer (positions, normals) and its
    /// 8×8 RSM as textures, and the camera's eye.
    struct Inputs {
        position: wgpu::TextureView,
        normal: wgpu::TextureView,
        rsm: [wgpu::TextureView; 3],
        eye: Vec3,
        vpls: slc_scene::vpl::Vpls,
    }

    fn inputs(gpu: &GpuContext) -> Inputs {
        let ctx = slc_cpu::vpl::VplContext::new(&Scene::cornell_box(), W, H, 8, None).unwrap();
        let (gb, vp) = (&ctx.inputs().gbuffer, &ctx.inputs().vpls);
        let v4 = |v: Vec3, w: f32| [v.x, v.y, v.z, w];
        let pos: Vec<[f32; 4]> =
            (0..gb.position.len()).map(|i| v4(gb.position[i], gb.valid(i) as u32 as f32)).collect();
        Inputs {
            position: upload(gpu, "p", (W, H), &pos),
            normal: upload(
                gpu,
                "n",
                (W, H),
                &gb.normal.iter().map(|&n| v4(n, 0.0)).collect::<Vec<_>>(),
            ),
            rsm: [
                upload(
                    gpu,
                    "rp",
                    (8, 8),
                    &vp.position.iter().map(|&p| v4(p, 1.0)).collect::<Vec<_>>(),
                ),
                upload(
                    gpu,
                    "rn",
                    (8, 8),
                    &vp.normal.iter().map(|&n| v4(n, 0.0)).collect::<Vec<_>>(),
                ),
                upload(gpu, "rf", (8, 8), &vp.flux.iter().map(|&f| v4(f, 0.0)).collect::<Vec<_>>()),
            ],
            eye: gb.eye,
            vpls: vp.clone(),
        }
    }

    fn lights(n: usize) -> LightSet {
        let light = |i: usize| {
            Vec3::new(
                0.05 + 0.1 * (i % 5) as f32,
                0.3 + 0.04 * (i / 5 % 5) as f32,
                0.05 + 0.1 * (i / 25) as f32,
            )
        };
        LightSet::new(
            (0..n)
                .map(|i| Light::Point(PointLight::new(light(i), Vec3::splat(0.01)).unwrap()))
                .collect(),
        )
        .unwrap()
    }

    fn f32_desc() -> DirectPassDesc {
        DirectPassDesc {
            surface: SurfaceDesc::Position,
            output_format: wgpu::TextureFormat::Rgba32Float,
            ..DirectPassDesc::new(W, H)
        }
    }

    /// 17 records of each pass in one submission (once more than the 16
    /// uniform slots the passes had, where record 0 ran with record 16's
    /// settings), each with its own settings and output: every output
    /// equals the same record submitted alone, bit for bit.
    pub fn seventeen_records_in_one_submission() {
        let Some(gpu) = slc_tests::gpu() else { return };
        let inp = inputs(gpu);
        let outs: Vec<wgpu::Texture> = (0..17).map(|_| engine::output(gpu, (W, H))).collect();
        let views: Vec<wgpu::TextureView> =
            outs.iter().map(|t| t.create_view(&Default::default())).collect();
        let gb = GBuffer {
            surface: Surface::Position(&inp.position),
            normal: &inp.normal,
            eye: inp.eye,
        };
        let mut direct = DirectPass::new(gpu, &lights(125), &f32_desc()).unwrap();
        // Clamp ranges from 0.05 to 0.85: each record keeps other lights.
        let direct_settings = |r: usize| DirectSettings {
            culling: Culling::clamped(0.05 * (r + 1) as f32).unwrap(),
            seed: 1,
            frame: r as u32,
        };
        let idesc = IndirectPassDesc {
            surface: SurfaceDesc::Position,
            output_format: wgpu::TextureFormat::Rgba32Float,
            ..IndirectPassDesc::new(W, H, VplSourceDesc::Rsm { size: 8 })
        };
        let mut indirect = IndirectPass::new(gpu, &idesc).unwrap();
        let vpls = VplInput::Rsm { position: &inp.rsm[0], normal: &inp.rsm[1], flux: &inp.rsm[2] };
        let indirect_settings = |r: usize| IndirectSettings {
            culling: Culling::Stochastic(RangeParams::new(0.001 * (r + 1) as f32, 1.0).unwrap()),
            frame: r as u32,
            min_distance: 0.01,
            ..IndirectSettings::default()
        };
        let read = |k: usize| {
            engine::submit_and_read(
                gpu,
                gpu.device.create_command_encoder(&Default::default()),
                &outs[k],
            )
        };
        for (name, record) in [("direct", 0), ("indirect", 1)] {
            let mut rec = |enc: &mut wgpu::CommandEncoder, r: usize| {
                if record == 0 {
                    direct
                        .record(enc, &DirectInputs::new(gb, &views[r]), &direct_settings(r))
                        .unwrap()
                } else {
                    let inputs =
                        IndirectInputs { gbuffer: gb, vpls, output: &views[r], materials: None };
                    indirect.record(enc, &inputs, &indirect_settings(r)).unwrap()
                }
            };
            let mut enc = gpu.device.create_command_encoder(&Default::default());
            for r in 0..17 {
                rec(&mut enc, r);
            }
            gpu.queue.submit([enc.finish()]);
            let together: Vec<Vec<[f32; 4]>> = (0..17).map(read).collect();
            for r in 0..17 {
                let mut enc = gpu.device.create_command_encoder(&Default::default());
                rec(&mut enc, r);
                gpu.queue.submit([enc.finish()]);
                let alone = read(r);
                let differ = alone.iter().zip(&together[r]).filter(|(a, b)| a != b).count();
                assert!(
                    differ == 0,
                    "{name} record {r} of 17 in one submission differs from itself alone at {differ} pixels"
                );
            }
            assert!(
                together[0] != together[16],
                "{name}: records 0 and 16 must differ (their settings do)"
            );
        }
        gpu.take_errors().unwrap();
    }

    /// A finite but huge intensity (`f32::MAX` wrote 56,368 ∞ pixels) is a
    /// typed error at the light's constructor, and so no `update_lights`
    /// can carry one; VPLs from an engine's buffer that no constructor
    /// would accept (NaN, ∞, negative or too bright flux, a NaN position
    /// or normal) are skipped: the image is the one with those VPLs at
    /// zero flux, bit for bit, and finite.
    pub fn overflowing_lights() {
        for bright in [f32::MAX, 1e30, MAX_INTENSITY * 1.01] {
            let e = PointLight::new(Vec3::ZERO, Vec3::splat(bright)).unwrap_err();
            assert!(e.to_string().contains("peak intensity"), "{e}");
            assert!(
                SpotLight::new(Vec3::ZERO, -Vec3::Y, Vec3::new(1.0, bright, 1.0), 0.2, 0.4)
                    .is_err()
            );
        }
        let Some(gpu) = slc_tests::gpu() else { return };
        let inp = inputs(gpu);
        let good: Vec<GpuVplRecord> = (0..inp.vpls.len())
            .map(|i| GpuVplRecord {
                position: inp.vpls.position[i],
                normal: inp.vpls.normal[i],
                flux: inp.vpls.flux[i],
                pad0: 0.0,
                pad1: 0.0,
                pad2: 0.0,
            })
            .collect();
        let mut bad = good.clone();
        let mut skipped = good.clone();
        let nan = Vec3::new(f32::NAN, 0.0, 0.0);
        let cases = [
            (Vec3::ZERO, Vec3::ZERO, Vec3::splat(f32::MAX)),
            (Vec3::ZERO, Vec3::ZERO, Vec3::splat(f32::INFINITY)),
            (Vec3::ZERO, Vec3::ZERO, nan),
            (Vec3::ZERO, Vec3::ZERO, Vec3::new(-1.0, 1.0, 1.0)),
            (nan, Vec3::ZERO, Vec3::ZERO),
            (Vec3::ZERO, nan, Vec3::ZERO),
        ];
        let lit: Vec<usize> =
            (0..good.len()).filter(|&i| good[i].flux.min_element() > 0.0).collect();
        assert!(lit.len() > 2 * cases.len(), "the RSM must have lit texels");
        for (k, (dp, dn, flux)) in cases.into_iter().enumerate() {
            let i = lit[2 * k];
            let r = &mut bad[i];
            (r.position, r.normal) = (r.position + dp, r.normal + dn);
            if flux != Vec3::ZERO {
                r.flux = flux;
            }
            skipped[i] = GpuVplRecord {
                position: Vec3::ZERO,
                normal: Vec3::ZERO,
                flux: Vec3::ZERO,
                ..skipped[i]
            };
        }
        let out = engine::output(gpu, (W, H));
        let view = out.create_view(&Default::default());
        let gb = GBuffer {
            surface: Surface::Position(&inp.position),
            normal: &inp.normal,
            eye: inp.eye,
        };
        let desc = IndirectPassDesc {
            surface: SurfaceDesc::Position,
            output_format: wgpu::TextureFormat::Rgba32Float,
            ..IndirectPassDesc::new(W, H, VplSourceDesc::Buffer { count: good.len() as u32 })
        };
        let mut pass = IndirectPass::new(gpu, &desc).unwrap();
        for culling in [
            Culling::Stochastic(RangeParams::new(0.004, 1.0).unwrap()),
            Culling::clamped(0.3).unwrap(),
            Culling::None,
        ] {
            let mut image = |records: &[GpuVplRecord]| {
                let buf = vpl_buffer(gpu, records);
                let inputs = IndirectInputs {
                    gbuffer: gb,
                    vpls: VplInput::Buffer(&buf),
                    output: &view,
                    materials: None,
                };
                let mut enc = gpu.device.create_command_encoder(&Default::default());
                pass.record(
                    &mut enc,
                    &inputs,
                    &IndirectSettings { culling, min_distance: 0.0, ..IndirectSettings::default() },
                )
                .unwrap();
                engine::submit_and_read(gpu, enc, &out)
            };
            let (got, want) = (image(&bad), image(&skipped));
            assert!(got.iter().flatten().all(|v| v.is_finite()), "{culling:?}: a non-finite pixel");
            assert!(got == want, "{culling:?}: bad VPLs are not skipped");
            assert!(want != image(&good), "{culling:?}: the skipped VPLs must matter");
        }
        gpu.take_errors().unwrap();
    }

    /// A camera over the box: its view-projection (wgpu's clip space, depth
    /// in [0, 1]) and eye.
    fn camera(reversed: bool) -> (Mat4, Vec3) {
        use slc_core::glam::camera::rh::{proj, view::look_to_mat4};
        let eye = Vec3::new(0.28, 0.27, 0.8);
        let (near, far) = if reversed { (10.0, 0.1) } else { (0.1, 10.0) };
        (
            proj::directx::perspective(0.8, 1.0, near, far) * look_to_mat4(eye, -Vec3::Z, Vec3::Y),
            eye,
        )
    }

    /// An `R32Float` depth texture holding `depth`.
    fn depth_texture(gpu: &GpuContext, depth: &[f32]) -> wgpu::TextureView {
        let t = texture(
            gpu,
            "depth",
            (W, H),
            wgpu::TextureFormat::R32Float,
            wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        );
        gpu.queue.write_texture(
            t.as_image_copy(),
            bytemuck::cast_slice(depth),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(W * 4),
                rows_per_image: None,
            },
            t.size(),
        );
        t.create_view(&Default::default())
    }

    /// Depth conventions: the reversed flag that did not match the depth
    /// buffer shaded 165,902 background pixels; now a depth of exactly 0 or
    /// 1 is background whatever the convention (there is no flag), so a
    /// standard buffer cleared to 1 and a reversed one cleared to 0 both
    /// leave their background black, under one descriptor, while their
    /// surfaces are shaded. The forward view-projection passed where its
    /// inverse belongs (a plausible, wrong image), or an eye that is not
    /// the matrix's, is a typed error; an orthographic inverse is taken.
    pub fn depth_conventions_and_the_view() {
        let Some(gpu) = slc_tests::gpu() else { return };
        let out = engine::output(gpu, (W, H));
        let view = out.create_view(&Default::default());
        let desc = DirectPassDesc {
            surface: SurfaceDesc::Depth { format: wgpu::TextureFormat::R32Float },
            ..f32_desc()
        };
        let up = upload(gpu, "up", (W, H), &vec![[0.0, 1.0, 0.0, 0.0]; (W * H) as usize]);
        let mut pass = DirectPass::new(gpu, &lights(125), &desc).unwrap();
        let settings = DirectSettings { culling: Culling::None, seed: 1, frame: 0 };
        for reversed in [false, true] {
            let (vp, eye) = camera(reversed);
            // The floor of the box (y = 0) from row FLOOR down, background above.
            const FLOOR: u32 = 11;
            let depth: Vec<f32> = (0..W * H)
                .map(|i| {
                    let (x, y) = (i % W, i / W);
                    if y < FLOOR {
                        return if reversed { 0.0 } else { 1.0 };
                    }
                    let ndc = slc_core::glam::Vec2::new(
                        2.0 * (x as f32 + 0.5) / W as f32 - 1.0,
                        1.0 - 2.0 * (y as f32 + 0.5) / H as f32,
                    );
                    let inv = vp.inverse();
                    let (a, b) =
                        (inv.project_point3(ndc.extend(0.0)), inv.project_point3(ndc.extend(1.0)));
                    let t = -a.y / (b.y - a.y);
                    let hit = a + (b - a) * t;
                    let d = vp.project_point3(hit).z;
                    assert!(
                        d > 0.0 && d < 1.0,
                        "the floor at pixel {i} must be within the depth range: {d}"
                    );
                    d
                })
                .collect();
            let tex = depth_texture(gpu, &depth);
            let gbuffer = |inv_view_proj, eye| GBuffer {
                surface: Surface::Depth { depth: &tex, inv_view_proj },
                normal: &up,
                eye,
            };
            let mut enc = gpu.device.create_command_encoder(&Default::default());
            pass.record(&mut enc, &DirectInputs::new(gbuffer(vp.inverse(), eye), &view), &settings)
                .unwrap();
            let got = engine::submit_and_read(gpu, enc, &out);
            for (i, p) in got.iter().enumerate() {
                let background = (i as u32 / W) < FLOOR;
                // Unculled: every light is in range (a) on the floor.
                let want = if background { 0.0 } else { 125.0 };
                assert_eq!(p[3], want, "reversed {reversed}, pixel {i}: {p:?}");
                assert!(background == (*p == [0.0; 4]), "reversed {reversed}, pixel {i}: {p:?}");
            }
            let mut enc = gpu.device.create_command_encoder(&Default::default());
            let e = pass
                .record(&mut enc, &DirectInputs::new(gbuffer(vp, eye), &view), &settings)
                .unwrap_err();
            assert!(
                matches!(&e, GpuError::Setting(m) if m.contains("inv_view_proj")),
                "forward matrix: {e}"
            );
            let e = pass
                .record(
                    &mut enc,
                    &DirectInputs::new(gbuffer(vp.inverse(), eye + Vec3::X), &view),
                    &settings,
                )
                .unwrap_err();
            assert!(matches!(&e, GpuError::Setting(m) if m.contains("eye")), "wrong eye: {e}");
        }
        let ortho = slc_core::glam::camera::rh::proj::directx::orthographic(
            -1.0, 1.0, -1.0, 1.0, 0.1, 10.0,
        );
        let tex = depth_texture(gpu, &vec![0.5; (W * H) as usize]);
        let g = GBuffer {
            surface: Surface::Depth { depth: &tex, inv_view_proj: ortho.inverse() },
            normal: &up,
            eye: Vec3::new(5.0, 5.0, 5.0),
        };
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        pass.record(&mut enc, &DirectInputs::new(g, &view), &settings).unwrap();
        gpu.queue.submit([enc.finish()]);
        gpu.take_errors().unwrap();
    }

    /// The direct pass's reuse: refused (before the device is touched)
    /// for picks other than resampled ones, 8 neighbours, a NaN radius, a
    /// confidence cap below 1 or visibility reuse from neighbours; a record of a position surface without its
    /// view-projection is refused and records nothing; with it, two frames
    /// come out finite.
    pub fn direct_reuse_settings() {
        let Some(gpu) = slc_tests::gpu() else { return };
        let reuse = DirectReuse { visibility: false, ..DirectReuse::default() };
        let resampled = DirectSelection::Resampled { k: 4 };
        let desc =
            |selection, reuse| DirectPassDesc { selection, reuse: Some(reuse), ..f32_desc() };
        let refused = |d: DirectPassDesc, what: &str| {
            let e = DirectPass::new(gpu, &lights(25), &d).err().expect("refused");
            assert!(matches!(&e, GpuError::Setting(m) if m.contains(what)), "{e}");
        };
        refused(desc(DirectSelection::Weighted { k: 4 }, reuse), "Resampled");
        refused(desc(resampled, DirectReuse { neighbours: 8, ..reuse }), "neighbours");
        refused(desc(resampled, DirectReuse { radius: f32::NAN, ..reuse }), "radius");
        refused(desc(resampled, DirectReuse { max_confidence: 0.5, ..reuse }), "confidence");
        let spread = DirectReuse { visibility: true, neighbours: 2, ..reuse };
        refused(desc(resampled, spread), "visibility");
        let mut pass = DirectPass::new(gpu, &lights(25), &desc(resampled, reuse)).unwrap();
        let inp = inputs(gpu);
        let out = engine::output(gpu, (W, H));
        let view = out.create_view(&Default::default());
        let g = GBuffer {
            surface: Surface::Position(&inp.position),
            normal: &inp.normal,
            eye: inp.eye,
        };
        let settings = DirectSettings {
            culling: Culling::Stochastic(RangeParams::new(0.01, 1.0).unwrap()),
            seed: 1,
            frame: 0,
        };
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        let e = pass.record(&mut enc, &DirectInputs::new(g, &view), &settings).unwrap_err();
        assert!(matches!(e, GpuError::Binding { name: "view_projection", .. }), "{e}");
        let vp = Scene::cornell_box().camera.view_projection(W, H, 0.01, 100.0);
        let inputs = DirectInputs { view_projection: Some(vp), ..DirectInputs::new(g, &view) };
        for frame in 0..2 {
            let mut enc = gpu.device.create_command_encoder(&Default::default());
            pass.record(&mut enc, &inputs, &DirectSettings { frame, ..settings }).unwrap();
            let img = engine::submit_and_read(gpu, enc, &out);
            assert!(img.iter().flatten().all(|v| v.is_finite()), "frame {frame} not finite");
            assert!(img.iter().any(|p| p[0] > 0.0), "frame {frame} dark");
        }
        gpu.take_errors().unwrap();
    }
}

use engine_misuse::*;

slc_tests::harness!(
    Cpu: core_constructors,
    Cpu: ies_parser,
    Cpu: scene_loaders,
    Cpu: renderer_settings,
    Gpu: path_tracer_and_direct_light_settings,
    Gpu: degenerate_direct_points,
    Gpu: seventeen_records_in_one_submission,
    Gpu: overflowing_lights,
    Gpu: depth_conventions_and_the_view,
    Gpu: direct_reuse_settings,
);
