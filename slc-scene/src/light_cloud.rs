//! `[[light_cloud]]` in a scene file: many punctual lights (point, spot,
//! IES) placed and powered by a seed, for scenes nobody tuned a sampler on.
//!
//! ```toml
//! [[light_cloud]]
//! count = 2000
//! placement = "volume"       # or "surface" (`offset` above the surfaces, by area), "clusters"
//! types = ["point", "spot", "ies"]   # each light's type drawn uniformly from these
//! aim = "random"             # spots' and IES nadirs: "random", "down", "away"/"toward" (the surface), "camera"
//! intensity = [0.01, 0.01, 0.01]     # mean peak intensity per light
//! power = "lognormal"        # or "equal", "dominant"
//! sigma = 1.5                # lognormal: σ of ln(intensity)
//! dominant_share = 0.5       # dominant: light 0's share of the total
//! ies = "../../shared/data/ies/indoor-60w-120deg.ies"   # needed when types holds "ies"
//! outer = 60.0               # spots' cone, degrees
//! offset = 0.05              # surface: distance above the surface
//! clusters = 4               # clusters: fixtures, centres uniform in the volume
//! spread = 0.05              # clusters: σ of the lights around a centre, as a fraction of the diagonal
//! margin = 0.05              # volume and clusters: the bounds shrunk by this fraction per side
//! seed = 1
//! ```
//!
//! Powers keep their mean: `equal` gives every light `intensity`;
//! `lognormal` scales light `i` by `exp(σ zᵢ − σ²/2)` (`zᵢ` standard normal,
//! so `E[scale] = 1`); `dominant` gives light 0 `dominant_share` of the
//! total `count · intensity` and the others equal shares of the rest.
//! An IES light's tint is `intensity · scale / peak candela`, so its peak
//! intensity is the same as a point's.

use crate::placement::{Stream, Surfaces};
use crate::scene::Scene;
use glam::Vec3;
use serde::Deserialize;
use slc_core::ies::IesProfile;
use slc_core::light::{IesLight, Light, PointLight, SpotLight};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Most lights one `[[light_cloud]]` places.
pub const MAX_CLOUD: u32 = 1 << 20;

/// Where a cloud's lights are.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(rename_all = "lowercase")]
pub enum Placement {
    /// Uniform in the scene's bounds, shrunk by `margin` per side.
    Volume,
    /// `offset` above the non-emissive surfaces, uniform by area.
    Surface,
    /// Around `clusters` centres uniform in the shrunk bounds, normally
    /// distributed with σ = `spread` × the bounds' diagonal.
    Clusters,
}

/// Which way spots point and IES nadirs look.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq)]
#[serde(rename_all = "lowercase")]
pub enum Aim {
    /// Uniform on the sphere, per light.
    #[default]
    Random,
    /// Along −y.
    Down,
    /// Along the surface's normal (placement `surface` only).
    Away,
    /// Against the surface's normal, lighting a pool on it (placement
    /// `surface` only).
    Toward,
    /// At the scene's camera: the lights' bright side is in view.
    Camera,
}

/// How a cloud's intensities are distributed (their mean is `intensity`).
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq)]
#[serde(rename_all = "lowercase")]
pub enum Power {
    /// Every light `intensity`.
    #[default]
    Equal,
    /// Log-normal with σ = `sigma`, mean-preserving.
    Lognormal,
    /// Light 0 holds `dominant_share` of the total.
    Dominant,
}

/// One `[[light_cloud]]` table (see the module docs).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightCloudDef {
    count: u32,
    placement: Placement,
    #[serde(default = "point_only")]
    types: Vec<String>,
    #[serde(default)]
    aim: Aim,
    intensity: [f32; 3],
    #[serde(default)]
    power: Power,
    #[serde(default = "one")]
    sigma: f32,
    #[serde(default = "half")]
    dominant_share: f32,
    ies: Option<PathBuf>,
    #[serde(default = "sixty")]
    outer: f32,
    #[serde(default)]
    offset: f32,
    #[serde(default = "four")]
    clusters: u32,
    #[serde(default = "five_percent")]
    spread: f32,
    #[serde(default = "five_percent")]
    margin: f32,
    #[serde(default = "one_u32")]
    seed: u32,
}

fn point_only() -> Vec<String> {
    vec!["point".into()]
}
fn one() -> f32 {
    1.0
}
fn half() -> f32 {
    0.5
}
fn sixty() -> f32 {
    60.0
}
fn four() -> u32 {
    4
}
fn five_percent() -> f32 {
    0.05
}
fn one_u32() -> u32 {
    1
}

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Point,
    Spot,
    Ies,
}

impl LightCloudDef {
    /// The cloud's lights over `scene` (IES files relative to `dir`); an
    /// error names the key at fault.
    pub fn lights(&self, scene: &Scene, dir: &Path) -> Result<Vec<Light>, String> {
        let kinds = self.kinds()?;
        self.check()?;
        let profile = match (&self.ies, kinds.contains(&Kind::Ies)) {
            (Some(file), true) => {
                let p = dir.join(file);
                let bytes = std::fs::read(&p).map_err(|e| format!("ies: {}: {e}", p.display()))?;
                Some(Arc::new(
                    IesProfile::parse_bytes(&bytes)
                        .map_err(|e| format!("ies: {}: {e}", p.display()))?,
                ))
            }
            (None, true) => {
                return Err("types holds \"ies\": give the profile as `ies = \"file.ies\"`".into());
            }
            (Some(_), false) => return Err("`ies` is given but types holds no \"ies\"".into()),
            (None, false) => None,
        };
        let peak = profile.as_ref().map_or(1.0, |p| p.max_candela());
        if !(peak.is_finite() && peak > 0.0) {
            return Err(format!("ies: the profile's peak candela {peak} must be finite and > 0"));
        }
        let surfaces =
            if self.placement == Placement::Surface { Some(Surfaces::new(scene)?) } else { None };
        let (lo, hi) = scene.bounds();
        if !(lo.is_finite() && hi.is_finite()) {
            return Err(
                "the scene has no geometry to place the lights in (list [[geometry]] first)".into(),
            );
        }
        let inset = (hi - lo) * self.margin;
        let (lo, hi) = (lo + inset, hi - inset);
        let centres: Vec<Vec3> = (0..self.clusters)
            .map(|c| {
                let mut s = Stream::new(self.seed ^ 0x5bd1_e995, c);
                lo + (hi - lo) * Vec3::new(s.uniform(), s.uniform(), s.uniform())
            })
            .collect();
        let sigma_cluster = self.spread * (hi - lo).length();
        let camera = scene.camera.position;
        let base = Vec3::from(self.intensity);
        let n = self.count as f32;
        let mut lights = Vec::with_capacity(self.count as usize);
        for i in 0..self.count {
            let mut s = Stream::new(self.seed, i);
            let (position, normal) = match (self.placement, &surfaces) {
                (Placement::Surface, Some(sf)) => {
                    let (p, n) = sf.sample(&mut s);
                    (p + n * self.offset, n)
                }
                (Placement::Clusters, _) => {
                    let c = centres
                        [((s.uniform() * self.clusters as f32) as usize).min(centres.len() - 1)];
                    let offset = Vec3::new(s.normal(), s.normal(), s.normal()) * sigma_cluster;
                    ((c + offset).clamp(lo, hi), Vec3::Y)
                }
                _ => (lo + (hi - lo) * Vec3::new(s.uniform(), s.uniform(), s.uniform()), Vec3::Y),
            };
            let kind = kinds[((s.uniform() * kinds.len() as f32) as usize).min(kinds.len() - 1)];
            let random_dir = s.direction();
            let z = s.normal();
            let aim = match self.aim {
                Aim::Random => random_dir,
                Aim::Down => Vec3::NEG_Y,
                Aim::Away => normal,
                Aim::Toward => -normal,
                Aim::Camera => (camera - position).try_normalize().unwrap_or(Vec3::NEG_Y),
            };
            let scale = match self.power {
                Power::Equal => 1.0,
                Power::Lognormal => (self.sigma * z - 0.5 * self.sigma * self.sigma).exp(),
                Power::Dominant if i == 0 => self.dominant_share * n,
                Power::Dominant => (1.0 - self.dominant_share) * n / (n - 1.0).max(1.0),
            };
            let intensity = base * scale;
            let err = |e: slc_core::LightError| format!("light {i}: {e}");
            lights.push(match kind {
                Kind::Point => Light::Point(PointLight::new(position, intensity).map_err(err)?),
                Kind::Spot => Light::Spot(
                    SpotLight::new(position, aim, intensity, 0.0, self.outer.to_radians())
                        .map_err(err)?,
                ),
                Kind::Ies => {
                    let profile = profile.clone().ok_or("types holds \"ies\" without a profile")?;
                    let reference = aim.any_orthonormal_vector();
                    Light::Ies(
                        IesLight::new(position, aim, reference, intensity / peak, profile)
                            .map_err(err)?,
                    )
                }
            });
        }
        Ok(lights)
    }

    /// The light types, checked.
    fn kinds(&self) -> Result<Vec<Kind>, String> {
        if self.types.is_empty() {
            return Err("types must name at least one of \"point\", \"spot\", \"ies\"".into());
        }
        self.types
            .iter()
            .map(|t| match t.as_str() {
                "point" => Ok(Kind::Point),
                "spot" => Ok(Kind::Spot),
                "ies" => Ok(Kind::Ies),
                other => Err(format!("types: \"{other}\" is not \"point\", \"spot\" or \"ies\"")),
            })
            .collect()
    }

    /// The numeric keys, checked.
    fn check(&self) -> Result<(), String> {
        if !(1..=MAX_CLOUD).contains(&self.count) {
            return Err(format!("count {} must be in 1..={MAX_CLOUD}", self.count));
        }
        let intensity = Vec3::from(self.intensity);
        if !(intensity.is_finite() && intensity.min_element() >= 0.0) {
            return Err("intensity must be finite and >= 0".into());
        }
        let ok = |v: f32, lo: f32, hi: f32| v.is_finite() && lo <= v && v <= hi;
        for (key, v, lo, hi) in [
            ("sigma", self.sigma, 0.0, 8.0),
            ("dominant_share", self.dominant_share, 0.0, 1.0),
            ("outer", self.outer, 0.0, 180.0),
            ("offset", self.offset, 0.0, f32::MAX),
            ("spread", self.spread, 0.0, 1.0),
            ("margin", self.margin, 0.0, 0.49),
        ] {
            if !ok(v, lo, hi) {
                return Err(format!("{key} {v} must be finite and within [{lo}, {hi}]"));
            }
        }
        if self.clusters == 0 || self.clusters > MAX_CLOUD {
            return Err(format!("clusters {} must be in 1..={MAX_CLOUD}", self.clusters));
        }
        if matches!(self.aim, Aim::Away | Aim::Toward) && self.placement != Placement::Surface {
            return Err(
                "aim \"away\" and \"toward\" need placement = \"surface\" (a surface to face)"
                    .into(),
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::scene_file::SceneFile;
    use glam::Vec3;
    use slc_core::light::Light;
    use std::path::Path;

    fn cloud(keys: &str) -> Result<SceneFile, String> {
        let text = format!(
            "[[geometry]]\nbuiltin = \"cornell\"\nemission_scale = 0.0\n[[light_cloud]]\n{keys}\n"
        );
        SceneFile::parse(&text, Path::new(env!("CARGO_MANIFEST_DIR")), "t.toml")
            .map_err(|e| e.to_string())
    }

    fn intensity(l: &Light) -> f32 {
        // Along a spot's axis, any way for a point: the peak.
        let w = if let Light::Spot(s) = l { s.direction() } else { Vec3::Y };
        l.intensity(w).max_element()
    }

    /// Volume placement stays inside the shrunk bounds; the same seed
    /// places the same lights, another seed others.
    #[test]
    fn volume_lights_are_inside_and_deterministic() {
        let f =
            cloud("count = 3000\nplacement = \"volume\"\nintensity = [1, 1, 1]\nseed = 7").unwrap();
        assert_eq!(f.lights.len(), 3000);
        let (lo, hi) = f.scene.bounds();
        let inset = (hi - lo) * 0.05;
        for l in &f.lights {
            let Light::Point(p) = l else { panic!("a point light expected") };
            let q = p.position();
            assert!(
                q.cmpge(lo + inset - 1e-5).all() && q.cmple(hi - inset + 1e-5).all(),
                "{q} outside"
            );
        }
        let again =
            cloud("count = 3000\nplacement = \"volume\"\nintensity = [1, 1, 1]\nseed = 7").unwrap();
        assert_eq!(format!("{:?}", f.lights), format!("{:?}", again.lights));
        let other =
            cloud("count = 3000\nplacement = \"volume\"\nintensity = [1, 1, 1]\nseed = 8").unwrap();
        assert_ne!(format!("{:?}", f.lights), format!("{:?}", other.lights));
    }

    /// Each power law keeps the mean intensity: log-normal within 5σ of its
    /// sampling error (σ of the scale is √(e^{σ²} − 1)), dominant exactly,
    /// and the dominant light holds its share.
    #[test]
    fn powers_keep_their_mean() {
        let n = 20_000usize;
        for sigma in [0.5f32, 1.5] {
            let f = cloud(&format!("count = {n}\nplacement = \"volume\"\nintensity = [2, 2, 2]\npower = \"lognormal\"\nsigma = {sigma}")).unwrap();
            let mean = f.lights.iter().map(|l| intensity(l) as f64).sum::<f64>() / n as f64;
            let sd = 2.0 * (((sigma * sigma) as f64).exp() - 1.0).sqrt() / (n as f64).sqrt();
            assert!((mean - 2.0).abs() < 5.0 * sd, "σ = {sigma}: mean {mean}, sd {sd}");
        }
        let f = cloud("count = 1000\nplacement = \"volume\"\nintensity = [1, 1, 1]\npower = \"dominant\"\ndominant_share = 0.25").unwrap();
        let total: f64 = f.lights.iter().map(|l| intensity(l) as f64).sum();
        assert!((total - 1000.0).abs() < 1e-2, "{total}");
        assert!((intensity(&f.lights[0]) as f64 - 250.0).abs() < 1e-3);
    }

    /// Surface placement floats `offset` in front of a surface; aim
    /// `toward` points a spot back at it; clusters stay near their centres;
    /// IES lights peak at the cloud's intensity.
    #[test]
    fn surfaces_aims_clusters_and_ies() {
        let f = cloud("count = 500\nplacement = \"surface\"\noffset = 0.05\ntypes = [\"spot\"]\naim = \"toward\"\nintensity = [1, 1, 1]").unwrap();
        for l in &f.lights {
            let Light::Spot(s) = l else { panic!("a spot expected") };
            // Straight along the spot's axis the surface is 5 cm away.
            let hit = f.scene.triangles.iter().any(|t| {
                let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
                (s.position() - t[0]).dot(n).abs() > 0.049
                    && (s.position() - t[0]).dot(n).abs() < 0.051
                    && n.dot(s.direction()).abs() > 0.999
            });
            assert!(hit, "spot at {} aims at no surface 5 cm away", s.position());
        }
        let f = cloud("count = 2000\nplacement = \"clusters\"\nclusters = 3\nspread = 0.01\nintensity = [1, 1, 1]").unwrap();
        let positions: Vec<Vec3> = f
            .lights
            .iter()
            .map(|l| if let Light::Point(p) = l { p.position() } else { panic!() })
            .collect();
        // Three tight fixtures: every light is within 5σ of one of three
        // lights' positions (the first light of each cluster seen).
        let diag = f.scene.diagonal() * 0.9;
        let mut reps: Vec<Vec3> = Vec::new();
        for p in &positions {
            if !reps.iter().any(|r| r.distance(*p) < 10.0 * 0.01 * diag) {
                reps.push(*p);
            }
        }
        assert!(reps.len() <= 3, "{} fixtures", reps.len());
        // The IES file by absolute path (missing test data is a failure).
        let ies = slc_test_data::shared_data("ies/indoor-60w-120deg.ies");
        let f =
            cloud(&format!("count = 50\nplacement = \"volume\"\ntypes = [\"ies\"]\nies = {:?}\nintensity = [3, 3, 3]", ies.display().to_string()))
                .unwrap();
        for l in &f.lights {
            let Light::Ies(l) = l else { panic!("an IES light expected") };
            let peak = l.tint().max_element() * l.profile().max_candela();
            assert!((peak - 3.0).abs() < 1e-4, "peak {peak}");
        }
    }

    /// Bad keys are errors that name them.
    #[test]
    fn bad_clouds_name_the_key() {
        for (keys, word) in [
            ("count = 0\nplacement = \"volume\"\nintensity = [1, 1, 1]", "count"),
            ("count = 5\nplacement = \"volume\"\nintensity = [-1, 1, 1]", "intensity"),
            (
                "count = 5\nplacement = \"volume\"\nintensity = [1, 1, 1]\ntypes = [\"laser\"]",
                "laser",
            ),
            ("count = 5\nplacement = \"volume\"\nintensity = [1, 1, 1]\ntypes = [\"ies\"]", "ies"),
            (
                "count = 5\nplacement = \"volume\"\nintensity = [1, 1, 1]\naim = \"toward\"",
                "placement",
            ),
            ("count = 5\nplacement = \"volume\"\nintensity = [1, 1, 1]\nsigma = nan", "sigma"),
            ("count = 5\nplacement = \"volume\"\nintensity = [1, 1, 1]\nouter = 200", "outer"),
            ("count = 5\nplacement = \"moon\"\nintensity = [1, 1, 1]", "moon"),
        ] {
            let e = cloud(keys).err().unwrap_or_else(|| panic!("{keys:?} was accepted"));
            assert!(e.contains(word), "{keys:?}: {e}");
        }
    }
}
