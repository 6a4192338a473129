//! A battery of bad inputs to every public constructor and loader: each
//! must return a typed error, never panic (checked with catch_unwind), and
//! its message must name the bad field.

use slc_core::bsh::Bsh;
use slc_core::glam::Vec3;
use slc_core::ies::IesProfile;
use slc_core::light::{LightBound, PointLight, SpotLight, TriangleLight, Vpl};
use slc_core::range::{RangeParams, Xi};
use slc_cpu::vpl::VplContext;
use slc_scene::scene::Scene;
use slc_scene::scene_file::SceneFile;
use slc_scene::vpl::{VplMethod, VplSettings};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

/// Runs `f`, asserting it returns an error (not a panic) whose message
/// contains `needle`.
fn rejects<T: std::fmt::Debug, E: std::fmt::Display>(what: &str, needle: &str, f: impl FnOnce() -> Result<T, E> + std::panic::UnwindSafe) {
    match catch_unwind(f) {
        Err(_) => panic!("{what}: panicked instead of returning an error"),
        Ok(Ok(v)) => panic!("{what}: accepted ({v:?})"),
        Ok(Err(e)) => {
            let msg = e.to_string();
            assert!(msg.to_lowercase().contains(&needle.to_lowercase()), "{what}: error '{msg}' does not name '{needle}'");
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
        rejects("point intensity", "intensity", move || PointLight::new(Vec3::ZERO, Vec3::new(0.0, b, 0.0)));
        rejects("vpl flux", "flux", move || Vpl::new(Vec3::ZERO, Vec3::Y, Vec3::splat(b)));
        rejects("spot angle", "cone", move || SpotLight::new(Vec3::ZERO, Vec3::Y, Vec3::ONE, 0.1, b));
        rejects("triangle radiance", "radiance", move || TriangleLight::new(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::splat(b)));
        rejects("bsh extent", "extent", move || Bsh::build(&[LightBound { center: Vec3::ZERO, extent: b }]));
    }
    for b in NONFINITE {
        rejects("point position", "position", move || PointLight::new(Vec3::new(b, 0.0, 0.0), Vec3::ONE));
        rejects("triangle vertex", "vertex", move || TriangleLight::new(Vec3::splat(b), Vec3::X, Vec3::Y, Vec3::ONE));
        rejects("bsh centre", "centre", move || Bsh::build(&[LightBound { center: Vec3::new(0.0, b, 0.0), extent: 0.0 }]));
    }
    rejects("xi = 1", "xi", || Xi::new(1.0));
    rejects("vpl normal", "normal", || Vpl::new(Vec3::ZERO, Vec3::ZERO, Vec3::ONE));
    rejects("spot direction", "direction", || SpotLight::new(Vec3::ZERO, Vec3::ZERO, Vec3::ONE, 0.1, 0.2));
    rejects("zero-area triangle", "zero area", || TriangleLight::new(Vec3::ZERO, Vec3::X, Vec3::X * 2.0, Vec3::ONE));
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
        rejects(&format!("obj {:?}", String::from_utf8_lossy(obj)), needle, move || Scene::parse_obj(obj, "t.obj", |_| None));
    }
    // Regression (fuzz/scene_loaders): tobj panics on a short colour line.
    for line in ["Kd", "Kd 0.5", "Ke 1 2", "Ka", "Ks 0 0"] {
        let mtl = format!("newmtl a\n{line}\n").into_bytes();
        rejects(&format!("mtl {line:?}"), "material", move || {
            Scene::parse_obj(b"mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "t.obj", |_| Some(mtl.clone()))
        });
    }
    rejects("albedo > 1", "albedo", || {
        Scene::parse_obj(b"mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "t.obj", |_| Some(b"newmtl a\nKd 2 0 0\n".to_vec()))
    });
    for (text, needle) in [
        ("[[geometry]]\nbuiltin = \"cornell\"\nbogus = 1\n", "bogus"),
        ("[[geometry]]\nobj = \"missing.obj\"\n", "missing.obj"),
        ("[[geometry]]\nbuiltin = \"cornell\"\n[render]\nwidth = -3\n", "line 4"),
        ("[[geometry]]\nbuiltin = \"cornell\"\n[[light]]\ntype = \"ies\"\nposition = [0, 0, 0]\nfile = \"none.ies\"\n", "none.ies"),
    ] {
        rejects(&format!("scene file {text:?}"), needle, move || SceneFile::parse(text, Path::new("/nonexistent"), "t.toml").map(|_| ()));
    }
}

fn renderer_settings() {
    let scene = Scene::cornell_box();
    rejects("width 0", "size", || VplContext::new(&scene, 0, 8, 32, None).map(|_| ()));
    rejects("vpl count", "vpls", || VplContext::new(&scene, 8, 8, 12, None).map(|_| ()));
    rejects("min distance", "min distance", || VplContext::new(&scene, 8, 8, 32, Some(f32::NAN)).map(|_| ()));
    let ctx = VplContext::new(&scene, 8, 8, 16, None).unwrap();
    for b in BAD {
        rejects("render error bound", "error bound", || ctx.render(&VplSettings { error_bound: b, ..VplSettings::default() }).map(|_| ()));
        rejects("render range", "range", || ctx.render(&VplSettings { method: VplMethod::Clamp, range: b, ..VplSettings::default() }).map(|_| ()));
        rejects("render fixed xi", "xi", || ctx.render(&VplSettings { fixed_xi: Some(b), ..VplSettings::default() }).map(|_| ()));
    }
    rejects("shader lights", "laser", || slc_shared_shaders::LightSet::parse("laser"));
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
        LightSet::new(vec![l2]).and_then(|set| DirectLights::new(&set).shade(&[Vec3::ONE], &[], &params, 1, 0)).map(|_| ())
    });
    let scene = Scene::cornell_box();
    for b in BAD {
        rejects("pt error bound", "error bound", || {
            let mut pts = CpuPathTracer::new(&PtScene::new(&scene, &[]).unwrap());
            pts.render(&mut PtRender::new(4, 4), &PtSettings { error_bound: b, ..PtSettings::default() }, 1)
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
    rejects("gpu pt size", "size", AssertUnwindSafe(|| slc_wgpu::pt::GpuPt::new(g, &pts, 0, 8).map(|_| ())));
    let mut gpt = slc_wgpu::pt::GpuPt::new(g, &pts, 4, 4).unwrap();
    for b in BAD {
        let s = PtSettings { method: PtMethod::SlcReservoir, error_bound: b, ..PtSettings::default() };
        rejects("gpu pt error bound", "error bound", AssertUnwindSafe(|| gpt.render(&mut PtRender::new(4, 4), &s, 1)));
    }
    let d = LightSet::new(vec![light]).unwrap();
    let mut gd = slc_wgpu::direct::GpuDirect::new(g, &d).unwrap();
    rejects("gpu points vs normals", "normals", AssertUnwindSafe(|| gd.shade(&[Vec3::ONE, Vec3::ZERO], &[Vec3::Y], &params, 1, 0)));
}

slc_tests::harness!(
    Cpu: core_constructors,
    Cpu: ies_parser,
    Cpu: scene_loaders,
    Cpu: renderer_settings,
    Gpu: path_tracer_and_direct_light_settings,
);
