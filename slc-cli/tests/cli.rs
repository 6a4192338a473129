//! Runs the `slc` binary the way README.md and docs/guide.md show it (at
//! small sizes where they use large ones), so their commands cannot rot.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use slc_tests::shared_data as shared;

fn slc(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_slc")).args(args).current_dir(dir).output().expect("run slc")
}

fn ok(dir: &Path, args: &[&str]) -> String {
    let out = slc(dir, args);
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "slc {args:?} failed:\n{}\n{}",
        text,
        String::from_utf8_lossy(&out.stderr)
    );
    text
}

/// A test's scratch directory (`slc-cli-NAME-…` in the system's temporary
/// directory), removed when the test is done with it, a failed one too.
struct Scratch(tempfile::TempDir);

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        self.0.path()
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        self.0.path()
    }
}

fn tempdir(name: &str) -> Scratch {
    Scratch(tempfile::Builder::new().prefix(&format!("slc-cli-{name}-")).tempdir().unwrap())
}

/// README: `cargo run --release -p slc-cli` (no arguments).
fn main_job_with_no_arguments() {
    let d = tempdir("main");
    let text = ok(&d, &[]);
    for key in ["65536 VPLs", "lights/px", "RMSE", "slc-out.exr"] {
        assert!(text.contains(key), "summary lacks {key}:\n{text}");
    }
    assert!(d.join("slc-out.exr").exists() && d.join("slc-out.png").exists());
}

/// README: `slc render` with each method, and with the shared Cornell OBJ.
fn render_commands() {
    let d = tempdir("render");
    let small = ["--width", "64", "--height", "48", "--vpls", "4096"];
    for (method, extra) in [
        ("slc", vec!["--error-bound", "0.008"]),
        ("clamp", vec!["--range", "0.1"]),
        ("none", vec![]),
        ("reference", vec![]),
    ] {
        let out = format!("{method}.exr");
        let mut args = vec!["render", "--method", method, "--out", &out];
        args.extend(small);
        args.extend(extra.iter().copied());
        ok(&d, &args);
        assert!(d.join(&out).exists() && d.join(format!("{method}.png")).exists());
    }
    {
        let obj = shared("scenes/cornell-box/CornellBox-Original.obj");
        let obj = obj.to_string_lossy().into_owned();
        let mut args = vec!["render", "--scene", &obj, "--out", "obj.exr"];
        args.extend(small);
        ok(&d, &args);
    }
}

/// README: `slc bench ... --json --csv`, plus `--plot` and `slc plot`.
fn bench_and_plot_commands() {
    let d = tempdir("bench");
    let text = ok(
        &d,
        &[
            "bench",
            "--width",
            "32",
            "--height",
            "32",
            "--vpls",
            "1024",
            "--repeat",
            "2",
            "--error-bounds",
            "0.004,0.016",
            "--ranges",
            "0.05,0.2",
            "--json",
            "b.json",
            "--csv",
            "b.csv",
            "--plot",
            "b.svg",
            "--cache-dir",
            "cache",
        ],
    );
    assert!(text.contains("slc") && text.contains("clamp") && text.contains("none"));
    assert!(text.contains("unculled loop:") && text.contains("light evaluations/s"), "{text}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("b.json")).unwrap()).unwrap();
    for key in ["app", "backend", "scene", "width", "height", "lights", "runs"] {
        assert!(json.get(key).is_some(), "JSON lacks {key}");
    }
    // The unculled loop's speed, without the near field: positive and finite.
    let speed = json["unculled_loop_evaluations_per_second"]
        .as_f64()
        .expect("JSON lacks the unculled loop's speed");
    assert!(speed.is_finite() && speed > 0.0, "{speed}");
    let runs = json["runs"].as_array().unwrap();
    assert_eq!(runs.len(), 5);
    for r in runs {
        for key in ["method", "param", "shading_ms", "total_ms", "rmse", "lights_per_pixel"] {
            assert!(r.get(key).is_some(), "run lacks {key}");
        }
        assert!(r["rmse"].as_f64().unwrap().is_finite());
        // Two frames, two ξ sets and two shifts of the interleaving's
        // subset map: the mean RMSE and its spread.
        let sd = r["rmse_sd"].as_f64().expect("run lacks rmse_sd");
        assert!(sd.is_finite() && sd >= 0.0, "{r}");
    }
    assert!(
        runs.iter().any(|r| r["method"] == "slc" && r["rmse_sd"].as_f64().unwrap() > 0.0),
        "SLC's frames differ"
    );
    assert_eq!(std::fs::read_to_string(d.join("b.csv")).unwrap().lines().count(), 6);
    let svg = std::fs::read_to_string(d.join("b.svg")).unwrap();
    assert!(svg.contains("<svg") && svg.contains("shading time") && svg.contains("RMSE"));
    // The second run reads the reference from the cache.
    // Without --json: the table only (JSON is optional).
    // --simd runs the loops on a lower instruction set (every CPU has the baseline).
    let text = ok(
        &d,
        &[
            "bench",
            "--width",
            "32",
            "--height",
            "32",
            "--vpls",
            "1024",
            "--repeat",
            "1",
            "--cache-dir",
            "cache",
            "--simd",
            "baseline",
        ],
    );
    assert!(
        text.contains("from cache")
            && text.contains("shading ms")
            && text.contains("baseline loops"),
        "{text}"
    );
    ok(&d, &["plot", "b.json", "--out", "p.png"]);
    assert!(std::fs::metadata(d.join("p.png")).unwrap().len() > 1000);
}

/// README: `slc ies FILE` (and `--plot`) on every shared IES file.
fn ies_command() {
    let d = tempdir("ies");
    for name in [
        "indoor-60w-120deg.ies",
        "outdoor-roadway-60w.ies",
        "absolute-led.ies",
        "floodlight-12w-54deg.ies",
        "tilt-include-synthetic.ies",
    ] {
        let p = shared(&format!("ies/{name}"));
        let text = ok(&d, &["ies", &p.to_string_lossy(), "--plot", "polar.png"]);
        for key in ["format", "photometric type", "peak candela", "total flux", "horizontal angles"]
        {
            assert!(text.contains(key), "{name}: no {key}");
        }
        assert!(std::fs::metadata(d.join("polar.png")).unwrap().len() > 1000);
    }
}

/// `slc diff`: statistics, heat map, and exit status 1 over --max-rmse.
fn diff_command() {
    let d = tempdir("diff");
    let small = ["--width", "32", "--height", "32", "--vpls", "1024"];
    let mut a = vec!["render", "--method", "slc", "--out", "a.exr"];
    a.extend(small);
    ok(&d, &a);
    let mut b = vec!["render", "--method", "clamp", "--range", "0.05", "--out", "b.exr"];
    b.extend(small);
    ok(&d, &b);
    let text = ok(&d, &["diff", "a.exr", "a.exr", "--max-rmse", "0"]);
    assert!(text.contains("RMSE            0.000000"), "{text}");
    let text = ok(&d, &["diff", "a.exr", "b.exr", "--heatmap", "h.png"]);
    assert!(text.contains("relative RMSE") && text.contains("NaN/inf values  0 in A, 0 in B"));
    assert!(d.join("h.png").exists());
    let out = slc(&d, &["diff", "a.exr", "b.exr", "--max-rmse", "0.000001"]);
    assert_eq!(out.status.code(), Some(1));
    // PNGs are previews: diff says it compares EXR images.
    let out = slc(&d, &["diff", "a.png", "b.exr"]);
    assert!(!out.status.success() && String::from_utf8_lossy(&out.stderr).contains("EXR"));
}

/// `--out x.png` writes `x.png` and the EXR beside it, and says so; an
/// extension that is neither is refused before rendering.
fn out_paths() {
    let d = tempdir("out");
    let text =
        ok(&d, &["render", "--width", "16", "--height", "16", "--vpls", "64", "--out", "x.png"]);
    assert!(d.join("x.png").exists() && d.join("x.exr").exists());
    assert!(text.contains("x.exr and x.png"), "{text}");
    let out =
        slc(&d, &["render", "--width", "16", "--height", "16", "--vpls", "64", "--out", "x.jpg"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && err.contains(".exr"), "{err}");
    // The name given is the name written; its twin takes a lowercase kind.
    ok(&d, &["render", "--width", "16", "--height", "16", "--vpls", "64", "--out", "Y.EXR"]);
    let names: Vec<String> = std::fs::read_dir(&*d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('Y'))
        .collect();
    assert!(
        names.len() == 2 && names.contains(&"Y.EXR".into()) && names.contains(&"Y.png".into()),
        "{names:?}"
    );
}

/// Bad input: a one-line error on stderr and a non-zero exit status.
fn bad_input_is_one_line_error() {
    let d = tempdir("bad");
    for args in [
        vec!["render", "--vpls", "1000"],
        vec!["render", "--error-bound=-1", "--width", "8", "--height", "8", "--vpls", "64"],
        vec!["render", "--app", "pt", "--error-bound", "auto:0", "--width", "8", "--height", "8"],
        vec!["render", "--app", "pt", "--error-bound", "auto:1e9", "--width", "8", "--height", "8"],
        vec!["render", "--scene", "missing.obj"],
        vec!["ies", "missing.ies"],
        vec!["diff", "missing-a.exr", "missing-b.exr"],
        vec!["render", "--width", "0"],
        vec!["render", "--app", "pt", "--spp", "0", "--width", "8", "--height", "8"],
        vec!["bench", "--repeat", "0", "--width", "8", "--height", "8", "--vpls", "64"],
        vec!["bench", "--app", "pt", "--noise", "seeds", "--pairs", "0", "--width", "8"],
        vec!["bench", "--app", "pt", "--noise", "seeds", "--pairs", "5000", "--width", "8"],
        vec!["bench", "--app", "pt", "--pairs", "2", "--width", "8", "--height", "8"],
        vec!["bench", "--pairs", "2", "--width", "8", "--height", "8", "--vpls", "64"],
        vec!["render", "--grid", "on", "--width", "8", "--height", "8", "--vpls", "64"],
        // An outside user's finds (2026-11-29): each was accepted, or failed
        // late or with a panic, or named a flag the user had not given.
        vec![
            "render",
            "--method",
            "clamp",
            "--exposure=nan",
            "--width",
            "8",
            "--height",
            "8",
            "--vpls",
            "64",
        ],
        vec![
            "render",
            "--method",
            "none",
            "--exposure=0",
            "--width",
            "8",
            "--height",
            "8",
            "--vpls",
            "64",
        ],
        vec![
            "render",
            "--app",
            "pt",
            "--method",
            "uniform",
            "--exposure=-1",
            "--width",
            "8",
            "--height",
            "8",
        ],
        vec!["diff", "missing-a.exr", "missing-b.exr", "--heatmap", "d.jpg"],
        vec!["diff", "missing-a.exr", "missing-b.exr", "--max-rmse", "nan"],
        vec!["view", "--frames", "1", "--width", "100000", "--height", "8", "--vpls", "64"],
        vec!["view", "--frames", "1", "--screenshot", "v.jpg"],
        vec!["bench", "--app", "pt", "--reference-spp", "0"],
        // Flags the chosen application would ignore.
        vec!["render", "--app", "pt", "--vpls", "4096", "--width", "8", "--height", "8"],
        vec!["render", "--app", "pt", "--no-denoise", "--width", "8", "--height", "8"],
        vec!["render", "--spp", "4", "--width", "8", "--height", "8", "--vpls", "64"],
        vec!["bench", "--suite", "scenes/suite", "--width", "8", "--height", "8", "--vpls", "64"],
        vec!["bench", "--app", "pt", "--tile", "2", "--width", "8", "--height", "8"],
        // ... also when the value given is the default one.
        vec!["bench", "--app", "pt", "--tile", "4", "--width", "8", "--height", "8"],
        vec!["render", "--app", "pt", "--shadow-size", "2048", "--width", "8", "--height", "8"],
        // ... or the backend would ignore, and `slc bench`'s for the other
        // application's bench.
        vec!["render", "--shadow-size", "64", "--width", "8", "--height", "8", "--vpls", "64"],
        vec!["render", "--backend", "gpu", "--tile", "4", "--width", "8", "--vpls", "64"],
        vec!["bench", "--seconds", "1", "--width", "8", "--height", "8", "--vpls", "64"],
        vec!["bench", "--noise", "seeds", "--width", "8", "--height", "8", "--vpls", "64"],
        vec!["bench", "--app", "pt", "--error-bounds", "0.1", "--width", "8", "--height", "8"],
        vec!["bench", "--app", "pt", "--repeat", "3", "--width", "8", "--height", "8"],
        vec!["bench", "--warmup", "1", "--width", "8", "--height", "8", "--vpls", "64"],
        vec!["bench", "--frames", "3", "--width", "8", "--height", "8", "--vpls", "64"],
        // A negative value reaches the value's own check (not clap's
        // "unexpected argument").
        vec!["render", "--app", "pt", "--seconds", "-1", "--width", "8", "--height", "8"],
        vec!["shaders", "--out", "no-kernels", "--lights", ""],
        // Output files whose folder is missing or whose plot kind is unknown
        // fail before the work, not after it.
        vec!["render", "--out", "no-folder/x.exr", "--width", "8", "--height", "8", "--vpls", "64"],
        vec![
            "bench",
            "--json",
            "no-folder/b.json",
            "--width",
            "8",
            "--height",
            "8",
            "--vpls",
            "64",
        ],
        vec!["bench", "--plot", "b.txt", "--width", "8", "--height", "8", "--vpls", "64"],
    ] {
        let out = slc(&d, &args);
        assert!(!out.status.success(), "{args:?} succeeded");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.trim().lines().count() == 1 && err.starts_with("error: "), "{args:?}: {err}");
        for flag in ["--repeat", "--timed-frames"] {
            assert!(args.contains(&flag) || !err.contains(flag), "{args:?} names {flag}: {err}");
        }
    }
    assert!(!d.join("no-kernels").exists(), "a refused light set wrote kernels");
}

/// Without a GPU adapter (no Vulkan driver for the child process), `--backend
/// gpu` fails with the library's typed error (which names no flag) and the
/// CLI's hint to the flag that helps.
fn no_adapter_error_names_the_flag() {
    let d = tempdir("noadapter");
    let out = Command::new(env!("CARGO_BIN_EXE_slc"))
        .args(["render", "--backend", "gpu", "--width", "8", "--height", "8", "--vpls", "64"])
        .env("VK_ICD_FILENAMES", "/nonexistent.json")
        .env("WGPU_BACKEND", "vulkan")
        .current_dir(&d)
        .output()
        .expect("run slc");
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    let last = err.trim().lines().last().unwrap_or("");
    assert!(
        last.starts_with("error: no GPU adapter found")
            && last.ends_with("(--backend cpu renders on the CPU)"),
        "{err}"
    );
}

/// A GPU render on a machine without a display prints no `error:` line
/// when nothing is wrong (Mesa's device-select layer used to make
/// libwayland print two).
fn gpu_start_up_is_quiet() {
    let d = tempdir("quiet");
    let out = Command::new(env!("CARGO_BIN_EXE_slc"))
        .args([
            "render",
            "--backend",
            "gpu",
            "--width",
            "16",
            "--height",
            "16",
            "--vpls",
            "256",
            "--out",
            "q.exr",
        ])
        .env_remove("XDG_RUNTIME_DIR")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("DISPLAY")
        .env_remove("MESA_VK_DEVICE_SELECT")
        .env_remove("NODEVICE_SELECT")
        .current_dir(&d)
        .output()
        .expect("run slc");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(!err.lines().any(|l| l.contains("error")), "stderr of a good GPU render:\n{err}");
}

/// Every example scene in `scenes/` loads and renders (small overrides on
/// the command line win over the file's `[render]`).
fn example_scene_files_render() {
    let d = tempdir("scenes");
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let p = entry.unwrap().path();
        if p.extension().is_some_and(|e| e == "toml" || e == "glb") {
            let text = std::fs::read(&p).unwrap();
            if String::from_utf8_lossy(&text).contains("shared/data") {
                shared("ies");
            }
            let out = ok(
                &d,
                &[
                    "render",
                    "--scene",
                    &p.to_string_lossy(),
                    "--width",
                    "32",
                    "--height",
                    "32",
                    "--vpls",
                    "1024",
                    "--out",
                    "s.exr",
                ],
            );
            assert!(out.contains("32x32"), "{}: {out}", p.display());
            n += 1;
        }
    }
    assert!(n >= 3, "expected the example scenes, found {n}");
}

/// README: a glTF file renders in both applications from the command line
/// (`scenes/glossy-spheres.glb`: its point, spot and emissive lights light
/// the path tracer; its spot is the VPL application's primary light), and
/// the built-in glossy box renders.
fn gltf_and_glossy_scenes_render() {
    let d = tempdir("gltf");
    let glb = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes/glossy-spheres.glb");
    let glb = glb.to_string_lossy();
    let out = ok(
        &d,
        &[
            "render", "--app", "pt", "--scene", &glb, "--width", "24", "--height", "24", "--spp",
            "4", "--out", "g.exr",
        ],
    );
    assert!(out.contains("24x24") && out.contains("4 lights"), "{out}");
    let img = slc_scene::image::Image::read_exr(&d.join("g.exr")).unwrap();
    assert!(img.is_finite() && img.mean() > 0.0);
    ok(
        &d,
        &[
            "render", "--scene", &glb, "--width", "24", "--height", "24", "--vpls", "1024",
            "--out", "v.exr",
        ],
    );
    ok(
        &d,
        &[
            "render",
            "--app",
            "pt",
            "--scene",
            "cornell-glossy",
            "--width",
            "16",
            "--height",
            "16",
            "--spp",
            "2",
            "--out",
            "c.exr",
        ],
    );
}

/// README: `slc shaders --out DIR [--lights ...]` writes every kernel in
/// every format.
fn shaders_command_exports_every_kernel() {
    let d = tempdir("shaders");
    let text = ok(&d, &["shaders", "--out", "k", "--lights", "point,triangle"]);
    assert!(text.contains("30 kernels"), "{text}");
    for entry in ["vs_main", "fs_gbuffer", "fs_rsm", "fs_shadow"] {
        let p = d.join("k").join(format!("scene_raster.{entry}.glsl"));
        assert!(
            std::fs::metadata(&p).map(|m| m.len() > 100).unwrap_or(false),
            "{} missing or empty",
            p.display()
        );
    }
    let names = [
        "light_update",
        "bsh_refit",
        "bsh_tail",
        "bsh_grid",
        "bsh_reservoir",
        "pt_connect",
        "pt_connect_grid",
        "pt_extend",
        "light_ranges",
        "direct_light",
    ];
    let names = names.into_iter().chain(["vpl_tiled_slc", "vpl_tiled_clamp", "vpl_tiled_none"]);
    let frame = [
        "vpl_denoise",
        "vpl_near",
        "vpl_pack",
        "vpl_clusters",
        "vpl_groups",
        "irradiance_export",
        "primary_direct",
        "frame_compose",
    ];
    let glossy = [
        "vpl_tiled_slc_glossy",
        "vpl_tiled_clamp_glossy",
        "vpl_tiled_none_glossy",
        "vpl_near_glossy",
        "irradiance_export_glossy",
    ];
    let frame = frame.into_iter().chain(glossy).chain([
        "frame_compose_glossy",
        "temporal",
        "temporal_motion",
    ]);
    for name in names.into_iter().chain(frame) {
        for ext in ["wgsl", "spv", "glsl", "hlsl", "metal"] {
            let p = d.join("k").join(format!("{name}.{ext}"));
            assert!(
                std::fs::metadata(&p).map(|m| m.len() > 100).unwrap_or(false),
                "{} missing or empty",
                p.display()
            );
        }
    }
    // slc-core's modules (brdf included), as naga_oil and as WESL modules.
    assert!(text.contains("19 naga_oil modules") && text.contains("19 WESL modules"), "{text}");
    let wesl = std::fs::read_to_string(d.join("k/wesl/slc/range.wesl")).unwrap();
    assert!(wesl.contains("public fn slc_keep("), "{wesl}");
    let range = std::fs::read_to_string(d.join("k/slc/range.wgsl")).unwrap();
    assert!(
        range.starts_with("#define_import_path slc::range") && range.contains("fn slc_keep("),
        "{range}"
    );
    let pt = std::fs::read_to_string(d.join("k/pt_connect.wgsl")).unwrap();
    assert!(pt.contains("LIGHT_TRIANGLE:") && !pt.contains("case LIGHT_SPOT:"));
    // The direct pass's kernel for the asked lights, reading depth (R32Float).
    let direct = std::fs::read_to_string(d.join("k/direct_light.wgsl")).unwrap();
    assert!(
        direct.contains("LIGHT_TRIANGLE:")
            && !direct.contains("case LIGHT_SPOT:")
            && direct.contains("depth_tex: texture_2d<f32>"),
        "{direct}"
    );
    let out = slc(&d, &["shaders", "--out", "k2", "--lights", "laser"]);
    assert!(!out.status.success());
}

/// `slc render --backend gpu` runs the whole frame on the GPU (rasterized
/// G-buffer, RSM and shadow map) and reports every stage; its image is the
/// CPU's ray-cast one up to silhouettes and shadow edges (RMSE bound 0.02,
/// the image mean is about 0.07), and so is its reference (`--method
/// reference`). `slc bench --backend gpu` writes the
/// stage times into its JSON. Declared `Gpu` (see the harness at the end).
fn gpu_backend_renders_like_cpu() {
    let d = tempdir("gpu");
    let small = ["--width", "48", "--height", "32", "--vpls", "4096", "--no-denoise"];
    let mut args = vec!["render", "--backend", "gpu", "--out", "g.exr", "--shadow-size", "512"];
    args.extend(small);
    let stdout = ok(&d, &args);
    assert!(stdout.contains("GPU ") && stdout.contains("whole frame on the GPU"), "{stdout}");
    for stage in [
        "G-buffer",
        "RSM",
        "shadow map",
        "VPL generation",
        "light update",
        "shading",
        "direct",
        "composition",
    ] {
        assert!(stdout.contains(stage), "no {stage} time in:\n{stdout}");
    }
    let mut args = vec!["render", "--backend", "cpu", "--out", "c.exr"];
    args.extend(small);
    ok(&d, &args);
    ok(&d, &["diff", "c.exr", "g.exr", "--max-rmse", "0.02"]);
    let out = slc(
        &d,
        &[
            "render",
            "--backend",
            "gpu",
            "--method",
            "reference",
            "--width",
            "8",
            "--height",
            "8",
            "--vpls",
            "64",
            "--out",
            "r.exr",
        ],
    );
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // The GPU's reference (every VPL at every pixel) is the CPU's, up to
    // the rasterized G-buffer's silhouettes and shadow edges.
    ok(
        &d,
        &[
            "render",
            "--backend",
            "cpu",
            "--method",
            "reference",
            "--width",
            "8",
            "--height",
            "8",
            "--vpls",
            "64",
            "--out",
            "rc.exr",
        ],
    );
    ok(&d, &["diff", "rc.exr", "r.exr", "--max-rmse", "0.02"]);
    let bench = [
        "bench",
        "--backend",
        "gpu",
        "--width",
        "16",
        "--height",
        "16",
        "--vpls",
        "1024",
        "--repeat",
        "1",
    ];
    ok(
        &d,
        &[
            &bench[..],
            &[
                "--error-bounds",
                "0.008",
                "--ranges",
                "0.1",
                "--shadow-size",
                "256",
                "--json",
                "b.json",
            ],
        ]
        .concat(),
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("b.json")).unwrap()).unwrap();
    assert!(json["backend"].as_str().unwrap().starts_with("gpu: "));
    let runs = json["runs"].as_array().unwrap();
    assert_eq!(runs.len(), 3);
    for r in runs {
        assert!(r["rmse"].as_f64().unwrap().is_finite());
        assert!(r["stages"].as_array().unwrap().iter().any(|s| s["name"] == "shading"), "{r}");
    }
}

/// `slc render --scene cornell-glossy --backend gpu` shades the glossy
/// surfaces with the glTF BRDF as the CPU does: RMSE(CPU, GPU) ≤ 0.01
/// (observed 0.0028 at 48×32, 4,096 VPLs, undenoised; the same frame
/// shaded matte on the GPU, as before the glossy pass, is 0.058 off the
/// CPU's, so the bound fails it). Declared `Gpu`.
fn gpu_glossy_render_is_glossy() {
    let d = tempdir("gpuglossy");
    let small = [
        "--scene",
        "cornell-glossy",
        "--width",
        "48",
        "--height",
        "32",
        "--vpls",
        "4096",
        "--no-denoise",
    ];
    ok(
        &d,
        &[&["render", "--backend", "gpu", "--out", "g.exr", "--shadow-size", "512"][..], &small]
            .concat(),
    );
    ok(&d, &[&["render", "--backend", "cpu", "--out", "c.exr"][..], &small].concat());
    ok(&d, &["diff", "c.exr", "g.exr", "--max-rmse", "0.01"]);
}

/// README: `slc render --app pt --backend gpu` and `slc bench --app pt
/// --backend gpu`. Declared `Gpu` (see the harness at the end).
fn gpu_path_tracer_renders_and_benches() {
    let d = tempdir("gpupt");
    let text = ok(
        &d,
        &[
            "render",
            "--app",
            "pt",
            "--backend",
            "gpu",
            "--width",
            "16",
            "--height",
            "16",
            "--spp",
            "4",
            "--out",
            "g.exr",
        ],
    );
    // The default method is slc on both backends, as --help says.
    assert!(
        text.contains("method slc\n")
            && text.contains("4 samples per pixel")
            && text.contains("GPU "),
        "{text}"
    );
    assert!(d.join("g.exr").exists() && d.join("g.png").exists());
    let args = [
        "bench",
        "--app",
        "pt",
        "--backend",
        "gpu",
        "--width",
        "16",
        "--height",
        "16",
        "--seconds",
        "0.2",
        "--reference-spp",
        "8",
    ];
    let text = ok(&d, &[&args[..], &["--json", "g.json", "--cache-dir", "cache"]].concat());
    assert!(text.contains("slc-reservoir") && text.contains("slc-weighted"), "{text}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("g.json")).unwrap()).unwrap();
    assert!(json["backend"].as_str().unwrap().starts_with("gpu: "));
    assert_eq!(json["runs"].as_array().unwrap().len(), 6);
    let text = ok(
        &d,
        &[
            "render",
            "--app",
            "pt",
            "--backend",
            "gpu",
            "--method",
            "lightbvh",
            "--width",
            "8",
            "--height",
            "8",
            "--out",
            "p.exr",
        ],
    );
    assert!(text.contains("method lightbvh") && d.join("p.exr").exists(), "{text}");
}

/// README: `slc render --app pt` with each method.
fn path_tracer_renders() {
    let d = tempdir("pt");
    for m in ["slc", "slc-reservoir", "slc-weighted", "uniform", "power", "lightbvh"] {
        let out = format!("pt-{m}.exr");
        let text = ok(
            &d,
            &[
                "render", "--app", "pt", "--method", m, "--width", "24", "--height", "24", "--spp",
                "2", "--out", &out,
            ],
        );
        assert!(
            text.contains("path tracing")
                && text.contains("2 samples per pixel")
                && text.contains("[primary]"),
            "{text}"
        );
        assert!(d.join(&out).exists());
        // The SLC methods say how their ε was set: from the scene by default.
        let culls = m.starts_with("slc");
        assert_eq!(
            text.contains("error bound ε")
                && text.contains("(automatic: 1.5 expected candidates per surface point)"),
            culls,
            "{text}"
        );
    }
    let text = ok(
        &d,
        &[
            "render",
            "--app",
            "pt",
            "--method",
            "slc-weighted",
            "--error-bound",
            "0.5",
            "--width",
            "8",
            "--height",
            "8",
            "--spp",
            "1",
        ],
    );
    assert!(text.contains("error bound ε = 0.5000 (given)"), "{text}");
    // A scene file's `[render] error_bound` is the VPL frame's (a VPL value
    // gives a path tracer tens of times the candidates): the path tracer
    // reads only `pt_error_bound`, a number or `auto:C`, and the flag
    // overrides it.
    let file_eps = |render: &str, extra: &[&str]| {
        std::fs::write(
            d.join("eps.toml"),
            format!("[[geometry]]\nbuiltin = \"cornell\"\n[render]\n{render}\n"),
        )
        .unwrap();
        let mut args = vec![
            "render",
            "--app",
            "pt",
            "--scene",
            "eps.toml",
            "--method",
            "slc-weighted",
            "--width",
            "8",
            "--height",
            "8",
            "--spp",
            "1",
        ];
        args.extend_from_slice(extra);
        slc(&d, &args)
    };
    let said = |o: Output| String::from_utf8_lossy(&o.stdout).into_owned();
    let vpl_eps = said(file_eps("error_bound = 0.008", &[]));
    assert!(
        vpl_eps.contains("(automatic: 1.5 expected candidates per surface point)"),
        "{vpl_eps}"
    );
    let pt_eps = said(file_eps("error_bound = 0.008\npt_error_bound = 0.25", &[]));
    assert!(pt_eps.contains("error bound ε = 0.2500 (the scene file's)"), "{pt_eps}");
    let pt_auto = said(file_eps("pt_error_bound = \"auto:6\"", &[]));
    assert!(pt_auto.contains("(automatic: 6 expected candidates per surface point)"), "{pt_auto}");
    let flag = said(file_eps("pt_error_bound = 0.25", &["--error-bound", "0.5"]));
    assert!(flag.contains("error bound ε = 0.5000 (given)"), "{flag}");
    let bad = file_eps("pt_error_bound = \"auto:0\"", &[]);
    let err = String::from_utf8_lossy(&bad.stderr);
    assert!(!bad.status.success() && err.contains("[render] pt_error_bound auto:0"), "{err}");
    // `--grid off` walks the light hierarchy at every vertex: the same
    // lights in the same order as the grids' lookups, so the same image.
    let grid = |g: &str| {
        let out = format!("pt-grid-{g}.exr");
        ok(
            &d,
            &[
                "render",
                "--app",
                "pt",
                "--method",
                "slc-weighted",
                "--width",
                "16",
                "--height",
                "16",
                "--spp",
                "2",
                "--grid",
                g,
                "--out",
                &out,
            ],
        );
        std::fs::read(d.join(&out)).unwrap()
    };
    assert!(grid("on") == grid("off"), "--grid off changed the image");
    // `auto:C` sets ε for C expected candidates (more candidates: a smaller
    // ε), on a scene with lights enough (2,048) that neither target is
    // capped at half the light count.
    let suite =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes/suite/points-clusters-2048.toml");
    let eps_of = |text: &str| -> f32 {
        let at = text.find("error bound ε = ").expect("ε printed") + "error bound ε = ".len();
        text[at..].split_whitespace().next().unwrap().parse().unwrap()
    };
    let auto = |c: &str| {
        ok(
            &d,
            &[
                "render",
                "--app",
                "pt",
                "--scene",
                suite.to_str().unwrap(),
                "--method",
                "slc-weighted",
                "--error-bound",
                c,
                "--width",
                "8",
                "--height",
                "8",
                "--spp",
                "1",
            ],
        )
    };
    let (default, six) = (auto("auto"), auto("auto:6"));
    assert!(six.contains("(automatic: 6 expected candidates per surface point)"), "{six}");
    assert!(eps_of(&six) < eps_of(&default), "{six}\n{default}");
    // `auto` is the path tracer's: the VPL application refuses it in one line.
    let out = slc(
        &d,
        &["render", "--error-bound", "auto", "--width", "8", "--height", "8", "--vpls", "64"],
    );
    assert!(
        !out.status.success()
            && String::from_utf8_lossy(&out.stderr).contains("applies to path tracing")
    );
    let out =
        slc(&d, &["render", "--app", "pt", "--method", "clamp", "--width", "8", "--height", "8"]);
    assert!(
        !out.status.success() && String::from_utf8_lossy(&out.stderr).contains("slc-reservoir")
    );
}

/// README: `slc suite` writes every family at every count, and `slc bench
/// --app pt --suite` runs every method on each, with one table, JSON
/// (a report per scene, summary rows), CSV and plot.
fn suite_commands() {
    let d = tempdir("suite");
    let ies = shared("ies/indoor-60w-120deg.ies");
    let text =
        ok(&d, &["suite", "--out", "s", "--counts", "16,32", "--ies", ies.to_str().unwrap()]);
    assert!(text.contains("wrote 20 scene files"), "{text}");
    assert_eq!(std::fs::read_dir(d.join("s")).unwrap().count(), 20);
    // Files that would not load are not written: a count no scene file
    // holds, and the default profile's path from another folder.
    for (args, needle) in [
        (
            vec!["suite", "--out", "big", "--counts", "10000000", "--ies", ies.to_str().unwrap()],
            "--counts",
        ),
        (vec!["suite", "--out", "elsewhere", "--counts", "16"], "--ies"),
    ] {
        let out = slc(&d, &args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success() && err.contains(needle), "{args:?}: {err}");
        assert!(!d.join(args[2]).join("dominant-16.toml").exists(), "{args:?} wrote files");
    }
    // Two families at one small count keep the run short.
    let two = d.join("two");
    std::fs::create_dir_all(&two).unwrap();
    for f in ["dominant-16.toml", "mixed-types-16.toml"] {
        std::fs::copy(d.join("s").join(f), two.join(f)).unwrap();
    }
    let args = [
        "bench",
        "--app",
        "pt",
        "--suite",
        "two",
        "--width",
        "8",
        "--height",
        "8",
        "--seconds",
        "0.05",
        "--reference-spp",
        "16",
    ];
    let text = ok(
        &d,
        &[
            &args[..],
            &["--json", "s.json", "--csv", "s.csv", "--plot", "s.svg", "--cache-dir", "cache"],
        ]
        .concat(),
    );
    assert!(
        text.contains("dominant-16")
            && text.contains("mixed-types-16")
            && text.contains("slc-weighted / best peer"),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("s.json")).unwrap()).unwrap();
    assert_eq!(json["scenes"].as_array().unwrap().len(), 2);
    let rows = json["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 12);
    for r in rows.iter().filter(|r| r["method"] == "uniform") {
        // Uniform's time per sample over its own is 1 (no NaN on the way).
        assert!((r["time_per_sample_vs_uniform"].as_f64().unwrap() - 1.0).abs() < 1e-9, "{r}");
    }
    assert_eq!(std::fs::read_to_string(d.join("s.csv")).unwrap().lines().count(), 13);
    assert!(std::fs::read_to_string(d.join("s.svg")).unwrap().contains("suite scene"));
    // `slc plot` draws a suite's report again, as `--plot` did.
    ok(&d, &["plot", "s.json", "--out", "s2.svg"]);
    assert_eq!(
        std::fs::read_to_string(d.join("s2.svg")).unwrap(),
        std::fs::read_to_string(d.join("s.svg")).unwrap()
    );
    // Seed pairs: every ratio gets a standard error, the median an interval.
    let text = ok(
        &d,
        &[
            "bench",
            "--app",
            "pt",
            "--suite",
            "two",
            "--width",
            "8",
            "--height",
            "8",
            "--seconds",
            "0.05",
            "--noise",
            "seeds",
            "--pairs",
            "3",
            "--json",
            "p.json",
        ],
    );
    assert!(text.contains("90% interval over the seed pairs"), "{text}");
    assert!(text.contains("beyond 2 standard errors"), "{text}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("p.json")).unwrap()).unwrap();
    let (lo, hi) = (
        json["median_interval"][0].as_f64().unwrap(),
        json["median_interval"][1].as_f64().unwrap(),
    );
    assert!(lo > 0.0 && lo <= hi, "{lo} {hi}");
    for b in json["against_best"].as_array().unwrap() {
        assert!(b["rmse_se"].as_f64().unwrap() >= 0.0, "{b}");
    }
    // A folder without scene files is a one-line error that says how to make one.
    std::fs::create_dir_all(d.join("empty")).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_slc"))
        .current_dir(&d)
        .args(["bench", "--app", "pt", "--suite", "empty"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && err.contains("slc suite --out"), "{err}");
}

/// `slc bench --app pt`: equal-time runs with RMSE-over-time series, JSON,
/// CSV and plot.
fn path_tracer_bench() {
    let d = tempdir("ptbench");
    let text = ok(
        &d,
        &[
            "bench",
            "--app",
            "pt",
            "--width",
            "16",
            "--height",
            "16",
            "--seconds",
            "0.2",
            "--reference-spp",
            "8",
            "--json",
            "p.json",
            "--csv",
            "p.csv",
            "--plot",
            "p.svg",
            "--cache-dir",
            "cache",
        ],
    );
    assert!(text.contains("uniform/method") && text.contains("rmse net"), "{text}");
    // An 8-spp reference is far too noisy for these runs: the output says so.
    assert!(
        text.contains("warning: the reference has 8 spp") && text.contains("exceeds a third of"),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("p.json")).unwrap()).unwrap();
    let runs = json["runs"].as_array().unwrap();
    assert_eq!(runs.len(), 6);
    let noise = json["reference_noise"].as_f64().unwrap();
    for r in runs {
        for key in ["method", "param", "time_ms", "spp", "rmse", "rmse_net", "series"] {
            assert!(r.get(key).is_some(), "run lacks {key}");
        }
        assert!(!r["series"].as_array().unwrap().is_empty());
        // The net RMSE is the measured one with the reference's noise taken out.
        let (rmse, net) = (r["rmse"].as_f64().unwrap(), r["rmse_net"].as_f64().unwrap());
        assert!(
            (net * net - (rmse * rmse - noise * noise).max(0.0)).abs() <= 1e-9 + 1e-6 * rmse * rmse,
            "{rmse} {net} {noise}"
        );
    }
    assert!(json["reference_noise"].as_f64().unwrap() >= 0.0);
    assert!(std::fs::read_to_string(d.join("p.svg")).unwrap().contains("RMSE"));
    assert!(
        text.contains("[primary]"),
        "the output says what the path tracer's lights are:\n{text}"
    );
    // `slc plot` re-plots a path-tracing report too (RMSE over time).
    ok(&d, &["plot", "p.json", "--out", "q.svg"]);
    assert!(std::fs::read_to_string(d.join("q.svg")).unwrap().contains("RMSE"));
}

/// `slc bench --app pt --noise seeds`: no reference is rendered (nothing
/// cached); each method's error is σ = RMSE(seed 1, seed 2)/√2 at equal
/// passes, finite and positive, its own net figure, and the report says
/// where it came from.
fn path_tracer_bench_noise_from_seeds() {
    let d = tempdir("ptseeds");
    let text = ok(
        &d,
        &[
            "bench",
            "--app",
            "pt",
            "--noise",
            "seeds",
            "--width",
            "12",
            "--height",
            "12",
            "--seconds",
            "0.1",
            "--json",
            "p.json",
            "--cache-dir",
            "cache",
        ],
    );
    assert!(text.contains("none: noise from seeds 1 and 2"), "{text}");
    assert!(!text.contains("warning: the reference"), "{text}");
    assert!(!d.join("cache").exists(), "a reference was rendered");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("p.json")).unwrap()).unwrap();
    assert_eq!(json["reference_noise"].as_f64(), Some(0.0));
    let runs = json["runs"].as_array().unwrap();
    assert_eq!(runs.len(), 6);
    for r in runs {
        let (rmse, net) = (r["rmse"].as_f64().unwrap(), r["rmse_net"].as_f64().unwrap());
        assert!(rmse.is_finite() && rmse > 0.0 && net == rmse, "{r}");
        assert!(r["spp"].as_u64().unwrap() >= 1, "{r}");
        assert_eq!(r["pair_variances"].as_array().unwrap().len(), 1, "{r}");
    }
    assert!(text.contains("one pair: --pairs K"), "{text}");
    // Three pairs: σ² is their mean, with a standard error from their spread.
    let text = ok(
        &d,
        &[
            "bench",
            "--app",
            "pt",
            "--noise",
            "seeds",
            "--pairs",
            "3",
            "--width",
            "12",
            "--height",
            "12",
            "--seconds",
            "0.05",
            "--json",
            "q.json",
        ],
    );
    assert!(text.contains("3 seed pairs, seeds 1 to 6") && text.contains("± se"), "{text}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("q.json")).unwrap()).unwrap();
    for r in json["runs"].as_array().unwrap() {
        let v: Vec<f64> =
            r["pair_variances"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
        assert_eq!(v.len(), 3, "{r}");
        let rmse = r["rmse"].as_f64().unwrap();
        assert!((rmse * rmse - v.iter().sum::<f64>() / 3.0).abs() <= 1e-9 * rmse * rmse, "{r}");
    }
}

/// MTL features slc does not model produce one warning line per material
/// (naming the features and the material), and the render still succeeds;
/// a matte material, and a glossy one (Ks/Ns are modelled), say nothing.
fn unmodelled_mtl_features_are_warned_about_once() {
    let d = tempdir("mtl");
    std::fs::write(
        d.join("ball.mtl"),
        "newmtl glossy\nKd 0.5 0.5 0.5\nKs 0.3 0.3 0.3\nNs 60\nmap_Kd wood.png\nd 0.5\nnewmtl matte\nKd 0.7 0.7 0.7\nKs 0 0 0\n",
    )
    .unwrap();
    let obj = "mtllib ball.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nusemtl glossy\nf 1//1 2//1 3//1\nusemtl matte\nf 1//1 3//1 4//1\n";
    std::fs::write(d.join("ball.obj"), obj).unwrap();
    let out = slc(
        &d,
        &[
            "render", "--scene", "ball.obj", "--width", "16", "--height", "16", "--vpls", "64",
            "--out", "ball.exr",
        ],
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    let warnings: Vec<&str> = err.lines().filter(|l| l.starts_with("warning:")).collect();
    assert_eq!(warnings.len(), 1, "{err}");
    assert!(warnings[0].contains("material 'glossy' has d, map_Kd"), "{err}");
}

// GPU tests show as ignored without an adapter, and fail under SLC_REQUIRE_GPU=1.
/// An 8-bit RGB PNG's size and bytes.
fn read_png(path: &Path) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(path).expect("the PNG exists"),
    ));
    let mut reader = decoder.read_info().expect("a PNG");
    let mut bytes = vec![0; reader.output_buffer_size().expect("a size")];
    let info = reader.next_frame(&mut bytes).expect("a frame");
    assert_eq!(info.color_type, png::ColorType::Rgb, "{}", path.display());
    bytes.truncate(info.buffer_size());
    (info.width, info.height, bytes)
}

/// README and CI: `slc view --frames 30 --screenshot FILE.png` opens the
/// window (under xvfb-run where no display is set), renders 30 frames with
/// the light animated and saves the last: the right size, the lit box (more
/// than half the pixels lit), its mean within 5% of the CPU backend's frame of the same
/// scene and size (the GPU frame is tested against the CPU's to 1% in
/// tests/tests/gpu_frame.rs; the light has moved a sixteenth of its circle,
/// about 4 cm, and 8-bit tone-mapped means are compared).
/// With no adapter for the window it fails with one line naming the ones
/// there are.
fn view_renders_frames_and_saves_a_screenshot() {
    let d = tempdir("view");
    let size = ["--width", "96", "--height", "72", "--vpls", "4096"];
    let out = slc_tests::windowed(Path::new(env!("CARGO_BIN_EXE_slc")))
        .args(["view", "--frames", "30", "--animate", "--screenshot", "view.png"])
        .args(size)
        .current_dir(&d)
        .output()
        .expect("run slc view");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "slc view failed:\n{text}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("30 frames on"), "{text}");
    let (w, h, view) = read_png(&d.join("view.png"));
    assert_eq!((w, h), (96, 72));
    let lit = view.chunks(3).filter(|p| p.iter().any(|&c| c > 16)).count();
    assert!(lit > (w * h) as usize / 2, "only {lit} of {} pixels lit", w * h);
    ok(&d, &["render", "--out", "cpu.exr"].into_iter().chain(size).collect::<Vec<_>>());
    let (_, _, cpu) = read_png(&d.join("cpu.png"));
    let mean = |b: &[u8]| b.iter().map(|&c| c as f64).sum::<f64>() / b.len() as f64;
    let (mv, mc) = (mean(&view), mean(&cpu));
    assert!((mv - mc).abs() <= 0.05 * mc, "screenshot mean {mv:.1} vs the CPU frame's {mc:.1}");
    // The camera swinging with temporal accumulation on (the default), and
    // off: both lit frames, the accumulation's not darker or brighter than
    // the plain one by more than the light's own change would make it.
    let mut means = Vec::new();
    for extra in [&[][..], &["--no-temporal"]] {
        let out = slc_tests::windowed(Path::new(env!("CARGO_BIN_EXE_slc")))
            .args(["view", "--frames", "20", "--orbit", "--screenshot", "orbit.png"])
            .args(extra)
            .args(size)
            .current_dir(&d)
            .output()
            .expect("run slc view");
        assert!(
            out.status.success(),
            "slc view --orbit {extra:?} failed:\n{}",
            String::from_utf8_lossy(&out.stderr)
        );
        means.push(mean(&read_png(&d.join("orbit.png")).2));
    }
    assert!(
        (means[0] - means[1]).abs() <= 0.02 * means[1],
        "orbiting: accumulated mean {:.1} vs plain {:.1}",
        means[0],
        means[1]
    );
    // No adapter for the window: one line naming the ones there are.
    let out = slc_tests::windowed(Path::new(env!("CARGO_BIN_EXE_slc")))
        .args(["view", "--frames", "1"])
        .env("WGPU_ADAPTER_NAME", "no-such-adapter")
        .current_dir(&d)
        .output()
        .expect("run slc view");
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> =
        err.lines().filter(|l| l.starts_with("error:") && !l.contains("XDG_RUNTIME_DIR")).collect();
    assert!(
        !out.status.success()
            && lines.len() == 1
            && lines[0].contains("no GPU adapter")
            && lines[0].contains("no-such-adapter"),
        "{err}"
    );
}

/// Without a display `slc view` fails with one line that says so and how
/// to get one, and bad options fail before any window opens.
fn view_without_a_display_is_a_clear_error() {
    let d = tempdir("view-headless");
    let out = Command::new(env!("CARGO_BIN_EXE_slc"))
        .args(["view", "--frames", "1"])
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .current_dir(&d)
        .output()
        .expect("run slc view");
    let err = String::from_utf8_lossy(&out.stderr);
    let line = err
        .lines()
        .filter(|l| l.starts_with("error:") && !l.contains("XDG_RUNTIME_DIR"))
        .collect::<Vec<_>>();
    assert!(!out.status.success() && line.len() == 1, "{err}");
    assert!(line[0].contains("no display") && line[0].contains("xvfb-run"), "{err}");
    for args in [
        &["view", "--screenshot", "x.png"][..],
        &["view", "--frames", "0"],
        &["view", "--method", "reference"],
        &["view", "--vpls", "1000"],
    ] {
        let out = slc(&d, args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            !out.status.success() && err.lines().filter(|l| l.starts_with("error:")).count() == 1,
            "{args:?}: {err}"
        );
    }
}

slc_tests::harness!(
    Cpu: main_job_with_no_arguments,
    Cpu: render_commands,
    Cpu: bench_and_plot_commands,
    Cpu: ies_command,
    Cpu: diff_command,
    Cpu: out_paths,
    Cpu: bad_input_is_one_line_error,
    Cpu: no_adapter_error_names_the_flag,
    Cpu: example_scene_files_render,
    Cpu: gltf_and_glossy_scenes_render,
    Cpu: shaders_command_exports_every_kernel,
    Gpu: gpu_backend_renders_like_cpu,
    Gpu: gpu_glossy_render_is_glossy,
    Gpu: gpu_start_up_is_quiet,
    Gpu: gpu_path_tracer_renders_and_benches,
    Cpu: path_tracer_renders,
    Cpu: path_tracer_bench,
    Cpu: path_tracer_bench_noise_from_seeds,
    Cpu: suite_commands,
    Cpu: unmodelled_mtl_features_are_warned_about_once,
    Display: view_renders_frames_and_saves_a_screenshot,
    Cpu: view_without_a_display_is_a_clear_error,
);
