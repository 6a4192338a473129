//! `slc suite`: the scene suite for judging light samplers on scenes nobody
//! tuned them on. Families of many-light scenes in the Cornell box (lights
//! near surfaces facing them, facing away or any way; spread through the
//! volume; clustered in a few fixtures; equal, log-normal or one dominant
//! power; point, spot and IES mixes; spots aimed out of the room; glossy
//! receivers), each at every light count asked for, written as scene files
//! (`scenes/suite/` holds the default set). Deterministic: the files are
//! a function of the family table and the counts alone; the lights in them
//! are placed by the scene file's seeded `[[scatter_lights]]` and
//! `[[light_cloud]]`.
//!
//! Every family keeps its total power fixed across light counts (each
//! light's emission or mean intensity is divided by the count), so two
//! counts of a family differ in how the power is split, not in brightness.

use std::path::{Path, PathBuf};

/// Light counts of the default suite (about 2k and 50k).
pub const DEFAULT_COUNTS: [u32; 2] = [2048, 49152];

/// Total emitted radiance × count of the triangle families: 10,000 lights
/// of radiance 10 (`scenes/many-small-lights.toml`).
const TRIANGLE_RADIANCE_TOTAL: f64 = 1.0e5;

/// Total intensity of the punctual families (W/sr, scene units).
const PUNCTUAL_TOTAL: f64 = 0.2;

/// The IES profile of the mixed family as written by default: relative to
/// a scene file in `scenes/suite/` (`slc suite --ies` gives another path,
/// written as given: a scene file's paths are relative to the file).
pub const DEFAULT_IES: &str = "../../../shared/data/ies/indoor-60w-120deg.ies";

/// One family: its name, what it tests, and its scene file's body for `n`
/// lights.
struct Family {
    name: &'static str,
    about: &'static str,
    /// The body for `n` lights, with the IES file's path as written.
    body: fn(u32, &str) -> String,
}

fn box_only(glossy: bool) -> String {
    format!(
        "[[geometry]]\nbuiltin = \"{}\"\nemission_scale = 0.0\n",
        if glossy { "cornell-glossy" } else { "cornell" }
    )
}

fn triangles(n: u32, face: &str, offset: f64, glossy: bool) -> String {
    let e = TRIANGLE_RADIANCE_TOTAL / n as f64;
    format!(
        "{}\n[[scatter_lights]]\ncount = {n}\nsize = 0.005\noffset = {offset}\nface = \"{face}\"\nemission = [{:.6}, {:.6}, {:.6}]\nseed = 1\n",
        box_only(glossy),
        e,
        0.9 * e,
        0.8 * e
    )
}

fn cloud(n: u32, keys: &str) -> String {
    let i = PUNCTUAL_TOTAL / n as f64;
    format!(
        "{}\n[[light_cloud]]\ncount = {n}\nintensity = [{i:.9}, {:.9}, {:.9}]\nseed = 1\n{keys}\n",
        box_only(false),
        0.9 * i,
        0.8 * i
    )
}

const FAMILIES: &[Family] = &[
    Family {
        name: "tri-facing",
        about: "small triangle lights 5 cm off every surface, facing it (pools of light; the camera sees their backs)",
        body: |n, _| triangles(n, "surface", 0.05, false),
    },
    Family {
        name: "tri-away",
        about: "small triangle lights just off every surface, facing the room (the camera sees them)",
        body: |n, _| triangles(n, "away", 0.002, false),
    },
    Family {
        name: "tri-random",
        about: "small triangle lights 5 cm off every surface, each facing any way",
        body: |n, _| triangles(n, "random", 0.05, false),
    },
    Family {
        name: "points-volume",
        about: "equal point lights spread through the room",
        body: |n, _| cloud(n, "placement = \"volume\""),
    },
    Family {
        name: "points-clusters",
        about: "equal point lights in four tight fixtures",
        body: |n, _| cloud(n, "placement = \"clusters\"\nclusters = 4\nspread = 0.02"),
    },
    Family {
        name: "points-lognormal",
        about: "point lights through the room with log-normal powers (σ = 2: a few carry most of the power)",
        body: |n, _| cloud(n, "placement = \"volume\"\npower = \"lognormal\"\nsigma = 2.0"),
    },
    Family {
        name: "dominant",
        about: "one point light with half the power among many small ones",
        body: |n, _| cloud(n, "placement = \"volume\"\npower = \"dominant\"\ndominant_share = 0.5"),
    },
    Family {
        name: "mixed-types",
        about: "point, spot and IES lights 5 cm off the surfaces, aimed any way, log-normal powers (σ = 1)",
        body: |n, ies| {
            cloud(
                n,
                &format!(
                    "placement = \"surface\"\noffset = 0.05\ntypes = [\"point\", \"spot\", \"ies\"]\nies = {ies:?}\naim = \"random\"\nouter = 45.0\npower = \"lognormal\"\nsigma = 1.0"
                ),
            )
        },
    },
    Family {
        name: "spots-at-camera",
        about: "30° spot lights through the room, each aimed at the camera outside it: most power leaves the room, only cone-aware importance tells which light reaches a point",
        body: |n, _| {
            cloud(n, "placement = \"volume\"\ntypes = [\"spot\"]\naim = \"camera\"\nouter = 30.0")
        },
    },
    Family {
        name: "glossy-facing",
        about: "tri-facing in the glossy box (glossy floor, metal blocks)",
        body: |n, _| triangles(n, "surface", 0.05, true),
    },
];

/// The suite's scene files: `(file name, text)` for every family and count,
/// family by family; `ies` is the IES profile's path as written.
pub fn scene_files(counts: &[u32], ies: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for f in FAMILIES {
        for &n in counts {
            let head = format!(
                "# Scene suite ({}): {}; {n} lights.\n# Written by `slc suite`; do not edit by hand.\n\n",
                f.name, f.about
            );
            out.push((format!("{}-{n}.toml", f.name), head + &(f.body)(n, ies)));
        }
    }
    out
}

/// Writes the suite's scene files into `dir` (created if missing); returns
/// their paths. Refuses counts a scene file cannot hold and an IES path
/// that does not name a file from `dir` (a scene file's paths are relative
/// to it), so that every file it writes loads.
pub fn write(dir: &Path, counts: &[u32], ies: &str) -> anyhow::Result<Vec<PathBuf>> {
    use slc_scene::light_cloud::MAX_CLOUD;
    if counts.is_empty() || counts.iter().any(|n| !(1..=MAX_CLOUD).contains(n)) {
        anyhow::bail!("--counts must list light counts in 1..={MAX_CLOUD}");
    }
    std::fs::create_dir_all(dir)
        .map_err(|e| anyhow::anyhow!("cannot create {}: {e}", dir.display()))?;
    if !dir.join(ies).is_file() {
        anyhow::bail!(
            "--ies {ies}: no such file from {} (the scene files' paths are relative to them): give the profile's path from there, or an absolute one",
            dir.display()
        );
    }
    let mut paths = Vec::new();
    for (name, text) in scene_files(counts, ies) {
        let p = dir.join(name);
        std::fs::write(&p, text)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", p.display()))?;
        paths.push(p);
    }
    Ok(paths)
}

#[cfg(test)]
mod tests {
    use super::*;
    use slc_scene::scene_file::SceneFile;

    /// `scenes/suite/` is what `slc suite --out scenes/suite` writes now.
    #[test]
    fn committed_suite_is_current() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/suite");
        for (name, text) in scene_files(&DEFAULT_COUNTS, DEFAULT_IES) {
            let have = std::fs::read_to_string(dir.join(&name)).unwrap_or_default();
            assert!(
                have == text,
                "scenes/suite/{name} is stale: run `cargo run --release -p slc-cli -- suite --out scenes/suite`"
            );
        }
        let listed = std::fs::read_dir(&dir)
            .unwrap()
            .filter(|e| e.as_ref().is_ok_and(|e| e.path().extension().is_some_and(|x| x == "toml")))
            .count();
        assert_eq!(
            listed,
            FAMILIES.len() * DEFAULT_COUNTS.len(),
            "scenes/suite holds files no family writes"
        );
    }

    /// Every family loads at a small count with that many lights (punctual
    /// lights, or emissive triangles), and at least 8 families exist.
    #[test]
    fn every_family_loads_with_its_light_count() {
        assert!(FAMILIES.len() >= 8);
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/suite");
        for (name, text) in scene_files(&[64], DEFAULT_IES) {
            let f = SceneFile::parse(&text, &dir, &name).unwrap_or_else(|e| panic!("{name}: {e}"));
            let emissive = f
                .scene
                .triangles
                .iter()
                .enumerate()
                .filter(|(t, _)| {
                    f.scene.materials[f.scene.material_of[*t] as usize].emission != glam::Vec3::ZERO
                })
                .count();
            assert_eq!(
                f.lights.len() + emissive,
                64,
                "{name}: {} lights, {emissive} emissive triangles",
                f.lights.len()
            );
        }
    }
}
